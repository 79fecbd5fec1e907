!> Sliding-block closed forms (seispulse_sliding_closed, seispulse_sliding_norm): published
!> values, the limit shapes in closed form, the corrected equations at points where the
!> printed ones differ, and the whole grid against the event-driven integrator.
module test_sliding_closed
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_negative_inf, ieee_is_nan, ieee_is_finite
    use, intrinsic :: iso_fortran_env, only: int64
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_format, only: real_str
    use seispulse_special, only: pi
    use seispulse_pulses, only: exp_pulse_peaks, exp_consts_t, exp_consts, exp_eval, &
                                exp_rise_time
    use seispulse_sliding_closed
    use seispulse_sliding_norm
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_sliding_closed

contains

    subroutine collect_sliding_closed(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('onset 1.12/1.34 and its limits', test_onset), &
                 new_unittest('half cycle: published values', test_half_published), &
                 new_unittest('half cycle: printed 1.9 cancels, 1.5 does not', test_half_cancel), &
                 new_unittest('half cycle: rectangle and triangle closed forms', &
                              test_half_limits), &
                 new_unittest('half cycle: regime threshold and spike', test_half_threshold), &
                 new_unittest('full cycle: example 1.9.1, corrected 1.19', test_full_example), &
                 new_unittest('full cycle: rectangle closed forms', test_full_rectangle), &
                 new_unittest('full cycle: stick, stuck, forced reverse, reverse only', &
                              test_full_modes), &
                 new_unittest('critical strength: exact and Eq. 1.22', test_eta_critical), &
                 new_unittest('incline: Eq. 1.31 special cases, K, unstable slope', test_incline), &
                 new_unittest('block in SI scales the dimensionless answer', test_block), &
                 new_unittest('normalization: 1.25-1.29, Tables 1.2 and 1.3', test_norm), &
                 new_unittest('bad input names the parameter', test_bad_input), &
                 new_unittest('closed forms = event-driven integrator on the grid', test_grid), &
                 new_unittest('full cycle: eta from 1e-13 to subnormal against references', &
                              test_small_eta)]
    end subroutine collect_sliding_closed

    !> eta = 10^-k (k = 13..40, 100, 200, 300, 307) and two subnormals. The forward slide
    !> stops at tau_m1 = 2 - sigma, sigma ~ sqrt(2 eta/g(beta)) with g = beta/expm1(beta),
    !> and the block slides back at once with v_g(tau_m1) = O(eta) of ground velocity to come
    !> (doc/sliding.md section 5). Taken as V_g - v_g(tau_m1 - 1) that velocity was lost
    !> below the rounding of V_g: no bracket from eta = 1e-17 on, tau_m2 wrong before (by
    !> 2e-5 at 1e-13, 0.2 at 1e-16; by 2 for subnormals). References: the rectangle in
    !> closed form (section 5); the triangle in closed form, tau_m1 = 2 - sqrt(2 eta) + eta/2,
    !> tau_m2 = 4 - 2 sqrt(2 eta) + 3 eta/4 (the sqrt(eta) approach to the limits 2 and 4);
    !> any finite beta: ref_small_eta; the integrator where it is usable: the forward slide
    !> for eta >= 1e-14 (its reverse slide and, at beta = 50, its stop time lose digits as
    !> the old closed form did), and the half cycle for normal eta (at a subnormal eta its
    !> stop time overflows: no reference). The spike sticks, with no slip. The check build
    !> runs this with overflow trapped: at a subnormal eta the free-stop time (V_g - v)/eta
    !> is +inf without an overflow.
    subroutine test_small_eta(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: betas(9), etas(34), inf, eta, beta, tau_m1, um1, tau_m2, um2, ures, vm2
        type(full_cycle_t) :: f, g
        integer :: ib, ie, k, stat
        character(len=:), allocatable :: at
        inf = ieee_value(inf, ieee_positive_inf)
        betas = [-inf, -50.0_dp, -1.0_dp, 0.0_dp, 1.0e-9_dp, 1.0_dp, 5.0_dp, 50.0_dp, inf]
        do k = 13, 40
            etas(k - 12) = 10.0_dp**(-k)
        end do
        etas(29:32) = [1.0e-100_dp, 1.0e-200_dp, 1.0e-300_dp, 1.0e-307_dp]
        etas(33) = transfer(20240225330731_int64, 1.0_dp)   ! 1e-310
        etas(34) = transfer(1_int64, 1.0_dp)                ! 4.9e-324, the smallest
        do ib = 1, size(betas)
            beta = betas(ib)
            do ie = 1, size(etas)
                eta = etas(ie)
                at = ' at eta = '//real_str(eta)//', beta = '//real_str(beta)
                call full_cycle(eta, eta, beta, 1.0_dp, .false., f, stat)
                call check(error, stat == SEISPULSE_SUCCESS, 'full cycle: stat'//at)
                if (allocated(error)) return
                call check(error, all(ieee_is_finite([f%tau_y1, f%tau_m1, f%um1, f%tau_y2, &
                           f%tau_m2, f%um2, f%ures, f%vm1, f%vm2])), 'full cycle: finite'//at)
                if (allocated(error)) return
                if (beta > huge(beta)) then
                    call check(error, f%mode == SLIDING_MODE_STICK .and. same(f%um1, 0.0_dp) &
                               .and. same(f%um2, 0.0_dp), 'spike: stick, no slip'//at)
                    if (allocated(error)) return
                    ! V_m/V_g = 1 - eta (1 - ln eta) -> 1 (section 3)
                    call check(error, f%vm1, 1.0_dp, rtol=1.0e-9_dp, message='spike vm1'//at)
                    if (allocated(error)) return
                else
                    call check(error, f%mode == SLIDING_MODE_SLIP, 'mode slip, not ' &
                               //sliding_mode_name(f%mode)//at)
                    if (allocated(error)) return
                    call agree(error, f%tau_m1, f%tau_y2, 'tau_y2 = tau_m1', eta, eta, beta, &
                               1.0_dp)
                    if (allocated(error)) return
                    if (beta < -huge(beta)) then
                        call rectangle_full(eta, tau_m1, um1, tau_m2, um2, ures)
                        vm2 = 2.0_dp * eta * (1.0_dp - eta) / (1.0_dp + eta)
                    else
                        call ref_small_eta(eta, beta, tau_m1, um1, tau_m2, um2, vm2)
                        ures = um1 - um2
                    end if
                    call agree(error, tau_m1, f%tau_m1, 'tau_m1', eta, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                    call agree(error, um1, f%um1, 'um1', eta, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                    call agree(error, tau_m2, f%tau_m2, 'tau_m2', eta, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                    call agree(error, um2, f%um2, 'um2', eta, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                    call agree(error, ures, f%ures, 'ures', eta, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                    call agree(error, vm2, f%vm2, 'vm2', eta, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                end if
                if (same(beta, 0.0_dp)) then
                    call check(error, f%tau_m1, 2.0_dp - sqrt(2.0_dp * eta) + 0.5_dp * eta, &
                               rtol=2.0e-15_dp, message='triangle tau_m1'//at)
                    if (allocated(error)) return
                    call check(error, f%tau_m2, 4.0_dp - 2.0_dp * sqrt(2.0_dp * eta) &
                               + 0.75_dp * eta, rtol=2.0e-15_dp, message='triangle tau_m2'//at)
                    if (allocated(error)) return
                end if
                if (eta >= 1.0e-14_dp .and. beta < huge(beta)) then
                    call full_cycle_integrated(eta, eta, beta, 1.0_dp, .false., .true., g, stat)
                    call check(error, stat == SEISPULSE_SUCCESS .and. g%mode == f%mode, &
                               'integrator: stat and mode'//at)
                    if (allocated(error)) return
                    call agree(error, f%tau_y1, g%tau_y1, 'tau_y1', eta, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                    call agree(error, f%um1, g%um1, 'um1', eta, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                    call agree(error, f%vm1, g%vm1, 'vm1', eta, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                end if
                if (eta >= tiny(eta)) then
                    call compare_half(error, eta, beta, 1.0_dp)
                    if (allocated(error)) return
                end if
            end do
        end do
    end subroutine test_small_eta

    !> Reference of test_small_eta for a finite beta: the symmetric full cycle whose forward
    !> slide stops in the last quarter, tau_m1 = 2 - sigma with sigma < 1/2, and whose block
    !> slides back at once and stops after the pulse (doc/sliding.md section 5), written in
    !> sigma, where the full-cycle ground velocity and displacement are those of the rising
    !> branch, v(sigma) and V_g - d(sigma), without cancellation. The stop: v(sigma) =
    !> v(tau_y) + eta (2 - sigma - tau_y) (Eq. 1.6), by bisection on the logarithm of sigma;
    !> u_m1 by Eq. 1.5. The reverse slide starts at 2 - sigma with v(sigma) to come, is
    !> v(sigma) - eta sigma fast at tau = 2 and stops v(sigma)/eta after its start; it slips
    !> v sigma - d(sigma) - eta sigma^2/2 (up to tau = 2) + (v - eta sigma)^2/(2 eta) (after).
    subroutine ref_small_eta(eta, beta, tau_m1, um1, tau_m2, um2, vm2)
        real(dp), intent(in) :: eta, beta
        real(dp), intent(out) :: tau_m1, um1, tau_m2, um2, vm2
        type(exp_consts_t) :: c
        real(dp) :: ty, a, v0, d0, lo, hi, sig, vs, ds, h, w2
        integer :: i
        c = exp_consts(beta)
        ty = exp_rise_time(eta, beta)
        call exp_eval(c, ty, .false., a, v0, d0)
        ! v(sigma) - v0 - eta (2 - sigma - ty): < 0 at tiny (v ~ sigma^2 underflows), > 0 at 1/2
        lo = tiny(1.0_dp)
        hi = 0.5_dp
        do i = 1, 200
            sig = sqrt(lo) * sqrt(hi)
            if (.not. (sig > lo .and. sig < hi)) exit
            call exp_eval(c, sig, .false., a, vs, ds)
            if (vs - v0 < eta * (2.0_dp - sig - ty)) then
                lo = sig
            else
                hi = sig
            end if
        end do
        sig = hi
        call exp_eval(c, sig, .false., a, vs, ds)
        tau_m1 = 2.0_dp - sig
        h = tau_m1 - ty
        um1 = ((c%vg - ds) - d0) - h * v0 - 0.5_dp * eta * h * h
        w2 = vs - eta * sig
        tau_m2 = tau_m1 + vs / eta
        um2 = (vs * sig - ds - 0.5_dp * eta * sig * sig) + w2 * w2 / (2.0_dp * eta)
        ! peak reverse velocity, where the mirrored lobe falls to eta: tbar = 1 - tau_y
        vm2 = ((vs - v0) - eta * (sig - ty)) / c%vg
    end subroutine ref_small_eta

    subroutine test_onset(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: tau, inf
        integer :: stat
        inf = ieee_value(inf, ieee_positive_inf)
        call yield_time(0.5_dp, -pi, 1.0_dp, tau, stat)
        call check(error, tau, 0.1035846_dp, atol=5.0e-8_dp, message='example 1.9.1')
        if (allocated(error)) return
        call yield_time(0.3_dp, 0.0_dp, 1.0_dp, tau, stat)
        call check(error, tau, 0.15_dp, message='beta = 0: eta/2')
        if (allocated(error)) return
        ! tiny beta: eta/2 + beta eta (1 - eta)/4 + O(beta^2)
        call yield_time(0.3_dp, 1.0e-9_dp, 1.0_dp, tau, stat)
        call check(error, tau, 0.15_dp + 1.0e-9_dp * 0.3_dp * 0.7_dp / 4.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call yield_time(0.3_dp, -inf, 1.0_dp, tau, stat)
        call check(error, tau, 0.0_dp, message='box')
        if (allocated(error)) return
        call yield_time(0.3_dp, inf, 1.0_dp, tau, stat)
        call check(error, tau, 0.5_dp, message='spike')
        if (allocated(error)) return
        ! beyond overflow of e^beta: 1/2 + ln(eta + (1 - eta) e^-beta)/(2 beta)
        call yield_time(0.3_dp, 1.0e4_dp, 1.0_dp, tau, stat)
        call check(error, tau, 0.5_dp + log(0.3_dp) / 2.0e4_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! Eq. 1.34 = 1.12 at a*eta; NaN when a*eta >= 1
        call yield_time(0.5_dp, 1.0_dp, 1.2_dp, tau, stat)
        call check(error, tau, log(1.0_dp + 0.6_dp * (exp(1.0_dp) - 1.0_dp)) / 2.0_dp, &
                   rtol=1.0e-15_dp)
        if (allocated(error)) return
        call yield_time(0.9_dp, 1.0_dp, 1.2_dp, tau, stat)
        call check(error, ieee_is_nan(tau) .and. stat == SEISPULSE_SUCCESS, 'a eta >= 1: NaN')
    end subroutine test_onset

    !> doc/sliding.md section 8 (a = 1 and 1.2) and 3.5 (beta = -2 pi and -pi at eta = 0.1).
    subroutine test_half_published(error)
        type(test_error), allocatable, intent(out) :: error
        type(half_cycle_t) :: r
        integer :: stat
        call half_cycle(0.3_dp, -pi, 1.0_dp, r, stat)
        call check(error, r%um, 0.53554_dp, atol=5.0e-6_dp)
        if (allocated(error)) return
        call half_cycle(0.3_dp, -pi, 1.2_dp, r, stat)
        call check(error, r%um, 0.53457_dp, atol=5.0e-6_dp)
        if (allocated(error)) return
        call half_cycle(0.6_dp, 0.5_dp, 1.0_dp, r, stat)
        call check(error, r%um, 0.022812_dp, atol=5.0e-7_dp)
        if (allocated(error)) return
        call half_cycle(0.6_dp, 0.5_dp, 1.2_dp, r, stat)
        call check(error, r%um, 0.020987_dp, atol=5.0e-7_dp)
        if (allocated(error)) return
        call half_cycle(0.1_dp, -2.0_dp * pi, 1.0_dp, r, stat)
        call check(error, r%tau_m, 8.43_dp, atol=5.0e-3_dp)
        if (allocated(error)) return
        call check(error, r%um, 3.133_dp, atol=5.0e-4_dp)
        if (allocated(error)) return
        call half_cycle(0.1_dp, -pi, 1.0_dp, r, stat)
        call check(error, r%um, 2.284_dp, atol=5.0e-4_dp)
        if (allocated(error)) return
        ! spike-like pulse: V_m/V_g -> 1 - eta (1 - ln eta) (section 3.6, beta = 20)
        call half_cycle(0.2_dp, 20.0_dp, 1.0_dp, r, stat)
        call check(error, r%vm, 0.478112_dp, atol=5.0e-7_dp)
        if (allocated(error)) return
        ! u_m/du_gm -> 1/2 as eta -> 0 (section 3.8): 0.49997, 0.49995, 0.49991 at 1e-4
        call half_cycle(1.0e-4_dp, -pi, 1.0_dp, r, stat)
        call check(error, r%um / r%dugm, 0.49997_dp, atol=5.0e-6_dp)
        if (allocated(error)) return
        call half_cycle(1.0e-4_dp, 0.0_dp, 1.0_dp, r, stat)
        call check(error, r%um / r%dugm, 0.49995_dp, atol=5.0e-6_dp)
        if (allocated(error)) return
        call half_cycle(1.0e-4_dp, pi, 1.0_dp, r, stat)
        call check(error, r%um / r%dugm, 0.49991_dp, atol=5.0e-6_dp)
    end subroutine test_half_published

    !> The printed Eq. 1.9 at beta = -2 pi, eta = 0.1: e^(2 beta (1 - tau_m)) ~ 3e40 appears
    !> with both signs and the sum loses every digit; the library's 1.5 route gives 3.133.
    subroutine test_half_cancel(error)
        type(test_error), allocatable, intent(out) :: error
        type(half_cycle_t) :: r
        real(dp) :: b, ty, tm, eta, x1, printed
        integer :: stat
        b = -2.0_dp * pi
        eta = 0.1_dp
        call half_cycle(eta, b, 1.0_dp, r, stat)
        ty = r%tau_y
        tm = r%tau_m
        x1 = -exp(2 * b * (1 - tm)) + exp(2 * b * ty) + 2 * b * (exp(b) * (1 - 2 * tm) &
             + exp(2 * b * ty) * (tm - ty)) + 2 * b**2 * (tm - ty)**2 * (1 - eta * (1 - exp(b)))
        printed = (x1 + (-2 * b * (1 - tm) * (1 + b * (1 - tm)) - 1 + exp(2 * b * (1 - tm)))) &
                  / (4 * b**2 * (1 - exp(b)))
        call check(error, abs(printed - r%um) > 0.1_dp, 'the printed 1.9 should lose its digits')
        if (allocated(error)) return
        call check(error, r%um, 3.132957_dp, atol=5.0e-7_dp)
    end subroutine test_half_cancel

    !> beta = -inf and 0 against their own closed forms (1.10a, corrected 1.10b).
    subroutine test_half_limits(error)
        type(test_error), allocatable, intent(out) :: error
        type(half_cycle_t) :: r
        real(dp) :: eta, tau_m, um, ratio, vm, tau_y, inf, printed
        integer :: i, stat, regime
        inf = ieee_value(inf, ieee_negative_inf)
        do i = 1, 19
            eta = 0.05_dp * i
            call half_cycle(eta, inf, 1.0_dp, r, stat)
            call rectangle_half(eta, tau_m, um, ratio, vm)
            call check(error, r%tau_m, tau_m, rtol=1.0e-14_dp, &
                       message='rect tau_m eta='//real_str(eta))
            if (allocated(error)) return
            call check(error, r%um, um, rtol=1.0e-13_dp, message='rect um eta='//real_str(eta))
            if (allocated(error)) return
            call check(error, r%um / r%dugm, ratio, rtol=1.0e-13_dp)
            if (allocated(error)) return
            call check(error, r%vm, vm, rtol=1.0e-14_dp)
            if (allocated(error)) return
            call half_cycle(eta, 0.0_dp, 1.0_dp, r, stat)
            call triangle_half(eta, tau_y, tau_m, um, vm, regime)
            call check(error, r%tau_y, tau_y, rtol=1.0e-15_dp)
            if (allocated(error)) return
            call check(error, r%tau_m, tau_m, rtol=1.0e-13_dp, &
                       message='tri tau_m eta='//real_str(eta))
            if (allocated(error)) return
            call check(error, r%um, um, rtol=1.0e-11_dp, message='tri um eta='//real_str(eta))
            if (allocated(error)) return
            call check(error, r%vm, vm, rtol=1.0e-12_dp, message='tri vm eta='//real_str(eta))
            if (allocated(error)) return
            call check(error, r%regime == regime, 'triangle regime at eta = '//real_str(eta))
            if (allocated(error)) return
        end do
        ! doc/sliding.md Corrections 3: the printed 1.10b has +(1/3)(1 - tau_m)^3 H(tau_m - 1); at
        ! eta = 0.3 it gives -0.068 where the slip is +0.2039
        eta = 0.3_dp
        call half_cycle(eta, 0.0_dp, 1.0_dp, r, stat)
        tau_y = r%tau_y
        tau_m = r%tau_m
        printed = -eta / 2 * (tau_m - tau_y)**2 + tau_m**2 * (1 - tau_m / 3) + (1 - 6 * tau_m) / 12 &
                  - tau_y**2 * (tau_m - 2 * tau_y / 3) + (1 - tau_m)**3 / 3
        call check(error, printed, -0.068_dp, atol=1.0e-3_dp, message='printed 1.10b')
        if (allocated(error)) return
        call check(error, r%um, 0.20388542_dp, atol=5.0e-9_dp, message='corrected 1.10b')
    end subroutine test_half_limits

    !> tau_m = 1 at eta*(beta) (section 3.4): 2 - sqrt 2 for the triangle; the published
    !> thresholds 0.8949, 0.7969, 0.3559, 0.2266 at beta = -2 pi, -pi, pi, 2 pi.
    subroutine test_half_threshold(error)
        type(test_error), allocatable, intent(out) :: error
        type(half_cycle_t) :: lo, hi
        real(dp), parameter :: betas(5) = [-2.0_dp * pi, -pi, 0.0_dp, pi, 2.0_dp * pi]
        real(dp), parameter :: thresholds(5) = [0.8949_dp, 0.7969_dp, 0.5858_dp, 0.3559_dp, &
                                                0.2266_dp]
        real(dp) :: inf
        type(half_cycle_t) :: r
        integer :: i, stat
        do i = 1, 5
            call half_cycle(thresholds(i) - 1.0e-4_dp, betas(i), 1.0_dp, lo, stat)
            call half_cycle(thresholds(i) + 1.0e-4_dp, betas(i), 1.0_dp, hi, stat)
            call check(error, &
                       lo%regime == SLIDING_REGIME_FREE .and. hi%regime == SLIDING_REGIME_FORCED, &
                       'regime change at eta* for beta = '//real_str(betas(i)))
            if (allocated(error)) return
            call check(error, lo%tau_m, 1.0_dp, atol=1.0e-3_dp)
            if (allocated(error)) return
        end do
        call half_cycle(2.0_dp - sqrt(2.0_dp), 0.0_dp, 1.0_dp, r, stat)
        call check(error, r%tau_m, 1.0_dp, rtol=1.0e-13_dp, message='triangle eta* = 2 - sqrt 2')
        if (allocated(error)) return
        ! the spike: onset 1/2, no slip, V_m/V_g at its limit
        inf = ieee_value(inf, ieee_positive_inf)
        call half_cycle(0.2_dp, inf, 1.0_dp, r, stat)
        call check(error, r%tau_y, 0.5_dp)
        if (allocated(error)) return
        call check(error, r%um, 0.0_dp)
        if (allocated(error)) return
        call check(error, r%vm, spike_velocity_ratio(0.2_dp))
        if (allocated(error)) return
        call check(error, spike_velocity_ratio(0.2_dp), 1.0_dp - 0.2_dp * (1.0_dp - log(0.2_dp)))
        if (allocated(error)) return
        ! eta >= 1: no sliding, not an error
        call half_cycle(1.0_dp, 0.0_dp, 1.0_dp, r, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. r%regime == SLIDING_REGIME_NONE .and. &
                   ieee_is_nan(r%tau_y), 'eta = 1: none')
    end subroutine test_half_threshold

    !> doc/sliding.md section 10, exact column; the printed 1.19a has the spurious root tau_m = 1.
    subroutine test_full_example(error)
        type(test_error), allocatable, intent(out) :: error
        type(full_cycle_t) :: r
        real(dp) :: b, eta, x3
        integer :: stat
        call full_cycle(0.5_dp, 0.5_dp, -pi, 1.0_dp, .false., r, stat)
        call check(error, r%mode == SLIDING_MODE_SLIP, 'mode slip')
        if (allocated(error)) return
        call check(error, r%tau_y1, 0.1035846_dp, atol=5.0e-8_dp)
        if (allocated(error)) return
        call check(error, r%tau_m1, 1.2465561_dp, atol=5.0e-8_dp)
        if (allocated(error)) return
        call check(error, r%um1, 0.1706088_dp, atol=5.0e-8_dp)
        if (allocated(error)) return
        call check(error, r%tau_y2, r%tau_m1, message='slip: reverse onset at the stop')
        if (allocated(error)) return
        call check(error, r%tau_m2, 2.4468988_dp, atol=5.0e-8_dp)
        if (allocated(error)) return
        call check(error, r%um2, 0.1643832_dp, atol=5.0e-8_dp)
        if (allocated(error)) return
        call check(error, r%ures, 0.0062257_dp, atol=5.0e-8_dp)
        if (allocated(error)) return
        ! the printed 1.19a is X3 (> 0 up to tau = 1) minus 2 tau_m + O(tau_m - 1) above 1: it
        ! jumps by -2 at tau = 1 and changes sign there, a spurious root where the
        ! corrected form (continuous) has none
        b = -pi
        eta = 0.5_dp
        x3 = (1.0_dp - r%tau_y1) * (1 - eta * (1 - exp(b))) + (1.0_dp + exp(2 * b * r%tau_y1) &
             - 2 * exp(b)) / (2 * b)
        call check(error, x3 > 0.0_dp .and. x3 - 2.0_dp < 0.0_dp, 'printed 1.19a: root at 1')
        if (allocated(error)) return
        call check(error, abs(r%tau_m1 - 1.0_dp) > 0.2_dp, 'the corrected root is not 1')
    end subroutine test_full_example

    subroutine test_full_rectangle(error)
        type(test_error), allocatable, intent(out) :: error
        type(full_cycle_t) :: r
        real(dp) :: eta, tau_m1, um1, tau_m2, um2, ures, inf
        integer :: i, stat
        inf = ieee_value(inf, ieee_negative_inf)
        do i = 1, 19
            eta = 0.05_dp * i
            call full_cycle(eta, eta, inf, 1.0_dp, .false., r, stat)
            call rectangle_full(eta, tau_m1, um1, tau_m2, um2, ures)
            call check(error, r%mode == SLIDING_MODE_SLIP, 'rectangle always slips')
            if (allocated(error)) return
            call check(error, r%tau_m1, tau_m1, rtol=1.0e-14_dp)
            if (allocated(error)) return
            call check(error, r%um1, um1, rtol=1.0e-13_dp)
            if (allocated(error)) return
            call check(error, r%tau_m2, tau_m2, rtol=1.0e-14_dp)
            if (allocated(error)) return
            call check(error, r%um2, um2, rtol=1.0e-12_dp, message='um2 eta='//real_str(eta))
            if (allocated(error)) return
            call check(error, r%ures, ures, rtol=1.0e-12_dp, atol=1.0e-15_dp)
            if (allocated(error)) return
        end do
    end subroutine test_full_rectangle

    subroutine test_full_modes(error)
        type(test_error), allocatable, intent(out) :: error
        type(full_cycle_t) :: r
        type(half_cycle_t) :: h
        integer :: stat
        ! stick with a forced reverse stop: the reverse slide mirrors the forward one
        call full_cycle(0.7_dp, 0.7_dp, 0.0_dp, 1.0_dp, .false., r, stat)
        call check(error, r%mode == SLIDING_MODE_STICK, 'stick')
        if (allocated(error)) return
        call check(error, r%ures, 0.0_dp, atol=1.0e-16_dp, message='forced stick: no residual')
        if (allocated(error)) return
        ! stick with a free reverse stop: u_m2 is the half-cycle slip (section 5.5)
        call full_cycle(0.5_dp, 0.5_dp, pi, 1.0_dp, .false., r, stat)
        call half_cycle(0.5_dp, pi, 1.0_dp, h, stat)
        call check(error, r%mode == SLIDING_MODE_STICK, 'stick at beta = pi, eta = 0.5')
        if (allocated(error)) return
        call check(error, r%um2, h%um, rtol=1.0e-13_dp)
        if (allocated(error)) return
        call check(error, r%tau_m2, 1.0_dp + h%tau_m, rtol=1.0e-14_dp)
        if (allocated(error)) return
        ! stuck (section 7.3): beta = 0.4, eta1 = 0.05, eta2 = 0.7
        call full_cycle(0.05_dp, 0.7_dp, 0.4_dp, 1.0_dp, .false., r, stat)
        call check(error, r%mode == SLIDING_MODE_STUCK .and. same(r%um2, 0.0_dp) &
                   .and. same(r%ures, r%um1), 'stuck')
        if (allocated(error)) return
        ! late slip with a forced reverse stop (section 7.4)
        call full_cycle(0.05_dp, 0.7_dp, -pi, 1.0_dp, .false., r, stat)
        call check(error, r%mode == SLIDING_MODE_SLIP, 'slip')
        if (allocated(error)) return
        call check(error, r%tau_m2 - 1.0_dp, 0.84597_dp, atol=5.0e-6_dp)
        if (allocated(error)) return
        call check(error, r%um2, 1.72069e-5_dp, rtol=5.0e-6_dp)
        if (allocated(error)) return
        ! unilateral and reverse only
        call full_cycle(0.3_dp, 1.2_dp, -pi, 1.0_dp, .false., r, stat)
        call check(error, r%mode == SLIDING_MODE_UNILATERAL .and. ieee_is_nan(r%tau_y2) .and. &
                   same(r%ures, r%um1), 'unilateral')
        if (allocated(error)) return
        call full_cycle(1.5_dp, 0.3_dp, -pi, 1.0_dp, .false., r, stat)
        call half_cycle(0.3_dp, -pi, 1.0_dp, h, stat)
        call check(error, r%mode == SLIDING_MODE_REVERSE_ONLY .and. ieee_is_nan(r%tau_y1), &
                   'reverse only')
        if (allocated(error)) return
        call check(error, r%um2, h%um, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, r%ures, -h%um, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, r%tau_y2, 1.0_dp + h%tau_y, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call full_cycle(1.5_dp, 1.1_dp, -pi, 1.0_dp, .false., r, stat)
        call check(error, r%mode == SLIDING_MODE_NO_SLIDING .and. same(r%ures, 0.0_dp), &
                   'no sliding')
        if (allocated(error)) return
        ! static friction at the reverse onset delays it (stick case)
        call full_cycle(0.7_dp, 0.7_dp, 0.0_dp, 1.2_dp, .true., r, stat)
        call check(error, r%tau_y2, 1.0_dp + 0.5_dp * 0.84_dp, rtol=1.0e-15_dp)
    end subroutine test_full_modes

    !> doc/sliding.md section 5: exact eta_cr and the fit 1.22.
    subroutine test_eta_critical(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: exact(9) = [0.8410_dp, 0.8057_dp, 0.7445_dp, 0.6234_dp, &
            0.4142_dp, 0.2268_dp, 0.1368_dp, 0.0959_dp, 0.0737_dp]
        real(dp), parameter :: fit(9) = [0.8708_dp, 0.8373_dp, 0.7689_dp, 0.6403_dp, &
            0.4383_dp, 0.2211_dp, 0.1127_dp, 0.1001_dp, 0.1000_dp]
        real(dp) :: beta, eta_cr
        type(full_cycle_t) :: lo, hi
        integer :: i, stat
        do i = 1, 9
            beta = (i - 5) * pi
            call eta_critical(beta, eta_cr, stat)
            call check(error, eta_cr, exact(i), atol=5.0e-5_dp, message='exact at '//real_str(beta))
            if (allocated(error)) return
            call check(error, eta_critical_regression(beta), fit(i), atol=5.0e-5_dp)
            if (allocated(error)) return
            ! slip just below, stick just above
            call full_cycle(eta_cr * (1 - 1.0e-6_dp), eta_cr * (1 - 1.0e-6_dp), beta, 1.0_dp, &
                            .false., lo, stat)
            call full_cycle(eta_cr * (1 + 1.0e-6_dp), eta_cr * (1 + 1.0e-6_dp), beta, 1.0_dp, &
                            .false., hi, stat)
            call check(error, lo%mode == SLIDING_MODE_SLIP .and. hi%mode == SLIDING_MODE_STICK, &
                       'slip/stick on each side at beta = '//real_str(beta))
            if (allocated(error)) return
        end do
        call eta_critical(0.0_dp, eta_cr, stat)
        call check(error, eta_cr, sqrt(2.0_dp) - 1.0_dp, rtol=1.0e-13_dp, message='sqrt 2 - 1')
    end subroutine test_eta_critical

    subroutine test_incline(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: eta1, eta2, k1, k2, lam, mu, eta
        integer :: stat
        character(len=256) :: msg
        mu = 0.6_dp
        eta = mu / 0.4_dp
        lam = 20.0_dp * pi / 180.0_dp
        ! xi = lambda: eta (cos lambda -+ sin lambda / mu), K = 1
        call inclined_resistances(mu, 0.4_dp, 20.0_dp, 20.0_dp, eta1, eta2, k1, k2, stat)
        call check(error, eta1, eta * (cos(lam) - sin(lam) / mu), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, eta2, eta * (cos(lam) + sin(lam) / mu), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, k1, 1.0_dp)
        if (allocated(error)) return
        ! xi = 0: eta (1 -+ tan(lambda)/mu)/(1 +- mu tan lambda), K = cos lambda (1 +- mu tan
        ! lambda)
        call inclined_resistances(mu, 0.4_dp, 20.0_dp, 0.0_dp, eta1, eta2, k1, k2, stat)
        call check(error, eta1, eta * (1 - tan(lam) / mu) / (1 + mu * tan(lam)), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, eta2, eta * (1 + tan(lam) / mu) / (1 - mu * tan(lam)), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, k1, cos(lam) * (1 + mu * tan(lam)), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, k2, cos(lam) * (1 - mu * tan(lam)), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call inclined_resistances(mu, 0.4_dp, 0.0_dp, 0.0_dp, eta1, eta2, k1, k2, stat)
        call check(error, same(eta1, eta) .and. same(eta2, eta) .and. same(k1, 1.0_dp), &
                   'flat: eta both ways')
        if (allocated(error)) return
        ! a pulse steep enough that it cannot push the block uphill: eta2 = +inf
        call inclined_resistances(mu, 0.4_dp, 20.0_dp, -80.0_dp, eta1, eta2, k1, k2, stat)
        call check(error, eta2 > huge(eta2) .and. same(k2, 0.0_dp) &
                   .and. stat == SEISPULSE_SUCCESS, 'no uphill sliding')
        if (allocated(error)) return
        ! example 1.9.2: tan 30 > 0.33, statically unstable
        msg = ''
        call inclined_resistances(0.33_dp, 0.66_dp, 30.0_dp, 0.0_dp, eta1, eta2, k1, k2, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'slope_deg') == 1 &
                   .and. index(msg, 'statically unstable') > 0, 'unstable: '//trim(msg))
    end subroutine test_incline

    subroutine test_block(error)
        type(test_error), allocatable, intent(out) :: error
        type(sliding_block_t) :: b
        type(full_cycle_t) :: f
        real(dp) :: eta1, eta2, k1, k2, ag, vg, dg
        integer :: stat
        call block_response(0.3_dp, 0.5_dp, 0.4_dp, -1.0_dp, .true., 8.0_dp, 3.0_dp, 1.1_dp, &
                            .false., .true., 9.81_dp, b, stat)
        call inclined_resistances(0.3_dp, 0.5_dp, 8.0_dp, 3.0_dp, eta1, eta2, k1, k2, stat)
        call full_cycle(eta1, eta2, -1.0_dp, 1.1_dp, .false., f, stat)
        call exp_pulse_peaks(-1.0_dp, .true., vg, dg, stat)
        ag = 0.5_dp * 9.81_dp
        call check(error, b%mode == f%mode, 'mode')
        if (allocated(error)) return
        call check(error, b%t_m1, f%tau_m1 * 0.4_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, b%u_m1, k1 * f%um1 * ag * 0.16_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, b%u_m2, k2 * f%um2 * ag * 0.16_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, b%v_m1, k1 * f%vm1 * vg * ag * 0.4_dp, rtol=1.0e-14_dp)
    end subroutine test_block

    subroutine test_norm(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: len6(6), dc, a, b, c, d, ratios(6), vg, dg, k
        real(dp), parameter :: expo(4, 6) = reshape([1, 0, 0, 2, -1, 2, 0, 0, 0, 0, 1, 0, &
            0, 1, 0, 1, -1, 1, 1, -1, 1, -1, 1, 1], [4, 6]) * 1.0_dp
        character(len=1), parameter :: tables(6) = ['a', 'b', 'c', 'd', 'e', 'f']
        integer :: i, j, m, stat
        call basic_lengths(3.0_dp, 0.7_dp, 0.2_dp, 0.9_dp, len6, stat)
        do i = 1, 6
            call characteristic_length(expo(1, i), expo(2, i), expo(3, i), expo(4, i), 3.0_dp, &
                                       0.7_dp, 0.2_dp, 0.9_dp, dc, stat)
            call check(error, dc, len6(i), rtol=1.0e-14_dp, message='1.28 vs 1.25')
            if (allocated(error)) return
        end do
        call characteristic_length(1.0_dp, 1.0_dp, 0.0_dp, 3.0_dp, 1.0_dp, 1.0_dp, 1.0_dp, &
                                   1.0_dp, dc, stat)
        call check(error, stat == SEISPULSE_INVALID_INPUT, 'a + b + c /= 1 rejected')
        if (allocated(error)) return
        ! every cell of Tables 1.2 a-f satisfies 1.26 and keeps its two free exponents
        do m = 1, 6
            do i = -4, 4
                do j = -4, 4
                    call table_1_2_exponents(tables(m), real(i, dp), real(j, dp), a, b, c, d, stat)
                    call check(error, abs(a + b + c - 1) < 1.0e-15_dp .and. &
                               abs(2 * a + b - d) < 1.0e-15_dp, 'Table 1.2'//tables(m))
                    if (allocated(error)) return
                end do
            end do
        end do
        ! Table 1.2e at (d, b) = (2, 0) is A_g t^2 (a = 1, c = 0)
        call table_1_2_exponents('e', 2.0_dp, 0.0_dp, a, b, c, d, stat)
        call check(error, same(a, 1.0_dp) .and. same(c, 0.0_dp), 'Table 1.2e cell')
        if (allocated(error)) return
        ! Table 1.3 and the relations 1.29 (n = 2 half cycle)
        call table_1_3(-pi, .false., ratios, stat)
        call exp_pulse_peaks(-pi, .false., vg, dg, stat)
        k = vg
        call check(error, ratios(1), 1.0_dp)
        if (allocated(error)) return
        call check(error, ratios(2), k * k, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, ratios(3), dg, rtol=1.0e-15_dp, message='D_g = u_g(t_d)')
        if (allocated(error)) return
        call check(error, ratios(4), 2.0_dp * ratios(3), rtol=1.0e-15_dp, message='1.29a')
        if (allocated(error)) return
        call check(error, ratios(1), 2.0_dp * ratios(6), rtol=1.0e-15_dp, message='1.29b')
        if (allocated(error)) return
        call check(error, ratios(2), 2.0_dp * ratios(5), rtol=1.0e-15_dp, message='1.29c')
    end subroutine test_norm

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(half_cycle_t) :: h
        type(full_cycle_t) :: f
        real(dp) :: nan, tau
        character(len=256) :: msg
        integer :: stat
        nan = ieee_value(nan, ieee_quiet_nan)
        msg = ''
        call half_cycle(0.0_dp, 0.0_dp, 1.0_dp, h, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'eta =') == 1, trim(msg))
        if (allocated(error)) return
        call half_cycle(nan, 0.0_dp, 1.0_dp, h, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'eta = NaN') == 1, &
                   trim(msg))
        if (allocated(error)) return
        call half_cycle(0.3_dp, nan, 1.0_dp, h, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'beta') == 1, trim(msg))
        if (allocated(error)) return
        call full_cycle(0.3_dp, -0.1_dp, 0.0_dp, 1.0_dp, .false., f, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'eta2') == 1, trim(msg))
        if (allocated(error)) return
        call yield_time(0.3_dp, 0.0_dp, 0.9_dp, tau, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'static_factor') == 1, &
                   trim(msg))
    end subroutine test_bad_input

    ! ------------------------------------------------------------------------------
    ! The grid against the integrator (doc/sliding.md section 9)
    ! ------------------------------------------------------------------------------

    subroutine test_grid(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: betas(18), inf
        real(dp), parameter :: etas(9) = [1.0e-3_dp, 0.05_dp, 0.2_dp, 0.4_dp, 0.6_dp, 0.8_dp, &
                                          0.95_dp, 0.99_dp, 0.999_dp]
        real(dp), parameter :: factors(3) = [1.0_dp, 1.1_dp, 1.3_dp]
        real(dp), parameter :: second(4) = [0.05_dp, 0.4_dp, 0.7_dp, 1.2_dp]
        integer :: ib, ie, ia, i2
        inf = ieee_value(inf, ieee_positive_inf)
        betas = [-inf, -1.0e3_dp, -4 * pi, -3 * pi, -2 * pi, -pi, -1.0_dp, -1.0e-9_dp, 0.0_dp, &
                 1.0e-9_dp, 1.0_dp, pi, 2 * pi, 3 * pi, 4 * pi, 30.0_dp, 200.0_dp, 1.0e3_dp]
        do ib = 1, size(betas)
            do ie = 1, size(etas)
                do ia = 1, size(factors)
                    call compare_half(error, etas(ie), betas(ib), factors(ia))
                    if (allocated(error)) return
                    call compare_full(error, etas(ie), etas(ie), betas(ib), factors(ia), .false.)
                    if (allocated(error)) return
                    call compare_full(error, etas(ie), etas(ie), betas(ib), factors(ia), .true.)
                    if (allocated(error)) return
                    do i2 = 1, size(second)
                        call compare_full(error, etas(ie), second(i2), betas(ib), factors(ia), &
                                          .false.)
                        if (allocated(error)) return
                        call compare_full(error, second(i2), etas(ie), betas(ib), factors(ia), &
                                          .true.)
                        if (allocated(error)) return
                    end do
                end do
            end do
        end do
    end subroutine test_grid

    !> Agreement: relative 1e-9, with an absolute floor of 1e-13 A_g t_d^2 for slips that
    !> vanish (eta -> 1) and 1e-12 t_d for times.
    subroutine agree(error, closed, integ, what, eta1, eta2, beta, a)
        type(test_error), allocatable, intent(inout) :: error
        real(dp), intent(in) :: closed, integ, eta1, eta2, beta, a
        character(len=*), intent(in) :: what
        if (ieee_is_nan(closed) .and. ieee_is_nan(integ)) return
        call check(error, integ, closed, rtol=1.0e-9_dp, atol=1.0e-13_dp, message=what// &
                   ' at eta1 = '//real_str(eta1)//', eta2 = '//real_str(eta2)//', beta = ' &
                   //real_str(beta)//', a = '//real_str(a))
    end subroutine agree

    subroutine compare_half(error, eta, beta, a)
        type(test_error), allocatable, intent(inout) :: error
        real(dp), intent(in) :: eta, beta, a
        type(half_cycle_t) :: h, g
        integer :: stat
        call half_cycle(eta, beta, a, h, stat)
        call half_cycle_integrated(eta, beta, a, g, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'integrator status')
        if (allocated(error)) return
        if (.not. (beta < huge(beta))) then
            ! the spike has no area: the integrator sees no slide, the closed form one of
            ! zero length (the limit beta -> +inf)
            call check(error, same(h%um, 0.0_dp) .and. same(g%um, 0.0_dp), 'spike: no slip')
            return
        end if
        call check(error, g%regime == h%regime, 'regime '//sliding_regime_name(h%regime)//' vs ' &
                   //sliding_regime_name(g%regime)//' at eta = '//real_str(eta)//', beta = ' &
                   //real_str(beta)//', a = '//real_str(a))
        if (allocated(error)) return
        call agree(error, h%tau_y, g%tau_y, 'tau_y', eta, eta, beta, a)
        if (allocated(error)) return
        call agree(error, h%tau_m, g%tau_m, 'tau_m', eta, eta, beta, a)
        if (allocated(error)) return
        call agree(error, h%um, g%um, 'um', eta, eta, beta, a)
        if (allocated(error)) return
        call agree(error, h%dugm, g%dugm, 'dugm', eta, eta, beta, a)
        if (allocated(error)) return
        call agree(error, h%vm, g%vm, 'vm', eta, eta, beta, a)
    end subroutine compare_half

    subroutine compare_full(error, eta1, eta2, beta, a, srev)
        type(test_error), allocatable, intent(inout) :: error
        real(dp), intent(in) :: eta1, eta2, beta, a
        logical, intent(in) :: srev
        type(full_cycle_t) :: f, g
        integer :: stat
        call full_cycle(eta1, eta2, beta, a, srev, f, stat)
        call full_cycle_integrated(eta1, eta2, beta, a, srev, .true., g, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'integrator status')
        if (allocated(error)) return
        if (.not. (beta < huge(beta))) then
            call check(error, same(f%um1, 0.0_dp) .and. same(f%um2, 0.0_dp) .and. &
                       same(g%ures, 0.0_dp), 'spike: no slip')
            return
        end if
        call check(error, g%mode == f%mode, 'mode '//sliding_mode_name(f%mode)//' vs ' &
                   //sliding_mode_name(g%mode)//' at eta1 = '//real_str(eta1)//', eta2 = ' &
                   //real_str(eta2)//', beta = '//real_str(beta)//', a = '//real_str(a))
        if (allocated(error)) return
        call agree(error, f%tau_y1, g%tau_y1, 'tau_y1', eta1, eta2, beta, a)
        if (allocated(error)) return
        call agree(error, f%tau_m1, g%tau_m1, 'tau_m1', eta1, eta2, beta, a)
        if (allocated(error)) return
        call agree(error, f%um1, g%um1, 'um1', eta1, eta2, beta, a)
        if (allocated(error)) return
        call agree(error, f%vm1, g%vm1, 'vm1', eta1, eta2, beta, a)
        if (allocated(error)) return
        call agree(error, f%tau_y2, g%tau_y2, 'tau_y2', eta1, eta2, beta, a)
        if (allocated(error)) return
        call agree(error, f%tau_m2, g%tau_m2, 'tau_m2', eta1, eta2, beta, a)
        if (allocated(error)) return
        call agree(error, f%um2, g%um2, 'um2', eta1, eta2, beta, a)
        if (allocated(error)) return
        call agree(error, f%vm2, g%vm2, 'vm2', eta1, eta2, beta, a)
        if (allocated(error)) return
        call agree(error, f%ures, g%ures, 'ures', eta1, eta2, beta, a)
    end subroutine compare_full

    !> Exact equality, without the -Wcompare-reals warning; NaN equals nothing.
    elemental logical function same(x, y)
        real(dp), intent(in) :: x, y
        if (ieee_is_nan(x) .or. ieee_is_nan(y)) then
            same = .false.
        else
            same = .not. (abs(x - y) > 0.0_dp)
        end if
    end function same

end module test_sliding_closed
