!> Stick-slip integrator: closed forms of doc/sliding.md (rectangle, triangle), published
!> values (Sections 8.2, 10.1, 7.4), records against pulses, convergence of sampled
!> pulses, grid output, degenerate cases and bad input.
module test_sliding_sim
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_negative_inf, ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_pulses, only: pulse_t, pulse_at, exponential_pulse, half_sine_pulse, &
                                sine_cycle_pulse, cosine_cycle_pulse, rectangular_pulse, &
                                triangular_pulse, ricker_pulse, mp_pulse
    use seispulse_sliding_sim, only: friction_t, slide_t, stickslip_result_t, &
                                   friction_validate, stickslip_pulse, stickslip_record
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_sliding_sim

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    !> stickslip_record takes accel and ay in g with g in m/s^2; the records here are
    !> samples of pulses in the pulse's own units, so g = 1 (u in those units times s^2)
    real(dp), parameter :: g_unit = 1.0_dp
    real(dp), parameter :: g0 = 9.80665_dp
    !> a g for which the floating-point product (huge/g) g overflows
    real(dp), parameter :: g_edge = 11.527021957185141_dp

contains

    subroutine collect_sliding_sim(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('rectangular full cycle: stop, slip, ((1-eta)/(1+eta))^2', &
                              test_rect_full), &
                 new_unittest('rectangular half cycle: 1/eta, (1-eta)/(2 eta), SI', &
                              test_rect_half), &
                 new_unittest('triangle half cycle: free and forced regimes', &
                              test_triangle_half), &
                 new_unittest('exponential half cycle, static friction (8.2)', &
                              test_exp_half_static), &
                 new_unittest('full cycle beta = -pi, eta = 0.5 (Example 1.9.1)', &
                              test_full_cycle_example), &
                 new_unittest('asymmetric friction: stuck, forced reverse stop (7.3-7.4)', &
                              test_asymmetric), &
                 new_unittest('triangle full cycle: stick, mirror slide, static_all', &
                              test_stick_static_all), &
                 new_unittest('sampled triangle and rectangle equal the pulses', &
                              test_record_equals_pulse), &
                 new_unittest('sampled exponential pulse converges at second order', &
                              test_record_convergence), &
                 new_unittest('slide sums, grid output and its derivative', &
                              test_consistency_grid), &
                 new_unittest('half-sine stop against bisection; other pulses run', &
                              test_other_pulses), &
                 new_unittest('M&P and Ricker agree with fine records at order dt^2', &
                              test_mp_ricker_records), &
                 new_unittest('spike, eta >= 1, one-way friction, short records', &
                              test_degenerate), &
                 new_unittest('bad input is a status naming the parameter', test_bad_input), &
                 new_unittest('record in g with g: m and m/s, the products accel g, ay g', &
                              test_record_in_g), &
                 new_unittest('2 sine/cosine cycles = a record of sin, cos at order dt^2', &
                              test_cycles_record)]
    end subroutine collect_sliding_sim

    ! ---------------------------------------------------------------- helpers

    pure function fric(ay_fwd, ay_rev, static_factor, static_all) result(fr)
        real(dp), intent(in) :: ay_fwd, ay_rev
        real(dp), intent(in), optional :: static_factor
        logical, intent(in), optional :: static_all
        type(friction_t) :: fr
        fr%ay_fwd = ay_fwd
        fr%ay_rev = ay_rev
        if (present(static_factor)) fr%static_factor = static_factor
        if (present(static_all)) fr%static_all = static_all
    end function fric

    !> Run a pulse and check the status and the number of slides (unless nslides < 0).
    subroutine run_pulse(error, p, fr, nslides, res, label)
        type(test_error), allocatable, intent(inout) :: error
        type(pulse_t), intent(in) :: p
        type(friction_t), intent(in) :: fr
        integer, intent(in) :: nslides
        type(stickslip_result_t), intent(out) :: res
        character(len=*), intent(in) :: label
        integer :: stat
        character(len=200) :: msg
        msg = ''
        call stickslip_pulse(p, fr, res, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, label//': status ('//trim(msg)//')')
        if (allocated(error)) return
        if (nslides >= 0) call check(error, size(res%slides), nslides, label//': number of slides')
    end subroutine run_pulse

    !> Sum of the signed slide lengths.
    pure function slide_sum(res) result(s)
        type(stickslip_result_t), intent(in) :: res
        real(dp) :: s
        integer :: k
        s = 0.0_dp
        do k = 1, size(res%slides)
            s = s + (res%slides(k)%u_stop - res%slides(k)%u_start)
        end do
    end function slide_sum

    !> Onset time of the exponential pulse, Eqs. 1.12 / 1.34 (threshold thr in A_g).
    pure function exp_onset(beta, thr) result(tau)
        real(dp), intent(in) :: beta, thr
        real(dp) :: tau
        tau = log(1.0_dp - thr * (1.0_dp - exp(beta))) / (2.0_dp * beta)
    end function exp_onset

    !> Slides of two runs agree (times, displacements, peaks, directions).
    subroutine check_same_slides(error, a, b, rtol, label)
        type(test_error), allocatable, intent(inout) :: error
        type(stickslip_result_t), intent(in) :: a, b
        real(dp), intent(in) :: rtol
        character(len=*), intent(in) :: label
        integer :: k
        call check(error, size(a%slides), size(b%slides), label//': number of slides')
        if (allocated(error)) return
        do k = 1, size(a%slides)
            call check(error, a%slides(k)%direction, b%slides(k)%direction, label//': direction')
            if (allocated(error)) return
            call check(error, a%slides(k)%t_start, b%slides(k)%t_start, rtol=rtol, &
                       atol=rtol, message=label//': t_start')
            if (allocated(error)) return
            call check(error, a%slides(k)%t_stop, b%slides(k)%t_stop, rtol=rtol, &
                       message=label//': t_stop')
            if (allocated(error)) return
            call check(error, a%slides(k)%u_stop, b%slides(k)%u_stop, rtol=rtol, &
                       message=label//': u_stop')
            if (allocated(error)) return
            call check(error, a%slides(k)%w_peak, b%slides(k)%w_peak, rtol=rtol, &
                       message=label//': w_peak')
            if (allocated(error)) return
            call check(error, a%slides(k)%t_peak, b%slides(k)%t_peak, rtol=rtol, &
                       message=label//': t_peak')
            if (allocated(error)) return
        end do
        call check(error, a%u_final, b%u_final, rtol=rtol, message=label//': u_final')
    end subroutine check_same_slides

    !> Samples of a pulse at t = (i - 1) dt, i = 1..n.
    subroutine sample_pulse(p, dt, n, acc)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: dt
        integer, intent(in) :: n
        real(dp), allocatable, intent(out) :: acc(:)
        real(dp) :: v, d
        integer :: i
        allocate(acc(n))
        do i = 1, n
            call pulse_at(p, real(i - 1, dp) * dt, acc(i), v, d)
        end do
    end subroutine sample_pulse

    ! ---------------------------------------------------------------- tests

    !> doc/sliding.md sections 4, 5: t_m1 = 2/(1+eta), u_m1 = (1-eta)/(1+eta), always slip,
    !> t_m2 = 4/(1+eta), u_m2 = 2 eta (1-eta)/(1+eta)^2, u_res = ((1-eta)/(1+eta))^2.
    subroutine test_rect_full(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: etas(3) = [0.1_dp, 0.3_dp, 0.7_dp], tol = 1.0e-13_dp
        type(stickslip_result_t) :: res
        real(dp) :: eta, box
        integer :: i
        box = ieee_value(box, ieee_negative_inf)
        do i = 1, size(etas)
            eta = etas(i)
            call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, box, .true.), &
                           fric(eta, eta), 2, res, 'box full')
            if (allocated(error)) return
            associate(s1 => res%slides(1), s2 => res%slides(2))
                call check(error, s1%direction == 1 .and. .not. s1%from_slip, 'first slide forward')
                if (allocated(error)) return
                call check(error, s1%t_start, 0.0_dp, atol=0.0_dp, message='onset at the jump')
                if (allocated(error)) return
                call check(error, s1%t_stop, 2.0_dp / (1.0_dp + eta), rtol=tol, message='t_m1')
                if (allocated(error)) return
                call check(error, s1%u_stop, (1.0_dp - eta) / (1.0_dp + eta), rtol=tol, &
                           message='u_m1')
                if (allocated(error)) return
                ! the sliding velocity peaks at the end of the first lobe
                call check(error, s1%w_peak, 1.0_dp - eta, rtol=tol, message='V_m = 1 - eta')
                if (allocated(error)) return
                call check(error, s1%t_peak, 1.0_dp, rtol=tol, message='t_vm = 1')
                if (allocated(error)) return
                call check(error, s2%direction == -1 .and. s2%from_slip, 'immediate reversal')
                if (allocated(error)) return
                call check(error, s2%t_start, s1%t_stop, rtol=0.0_dp, message='slip at the stop')
                if (allocated(error)) return
                call check(error, s2%t_stop, 4.0_dp / (1.0_dp + eta), rtol=tol, message='t_m2')
                if (allocated(error)) return
                call check(error, s2%u_start - s2%u_stop, &
                           2.0_dp * eta * (1.0_dp - eta) / (1.0_dp + eta)**2, rtol=tol, &
                           message='u_m2')
                if (allocated(error)) return
                ! reverse velocity is largest when the pulse ends at t = 2
                call check(error, s2%w_peak, 2.0_dp * eta * (1.0_dp - eta) / (1.0_dp + eta), &
                           rtol=tol, message='reverse peak velocity')
                if (allocated(error)) return
            end associate
            call check(error, res%u_final, ((1.0_dp - eta) / (1.0_dp + eta))**2, rtol=tol, &
                       message='u_res')
            if (allocated(error)) return
            call check(error, res%t_end, 4.0_dp / (1.0_dp + eta), rtol=tol, message='t_end')
            if (allocated(error)) return
        end do
    end subroutine test_rect_full

    !> doc/sliding.md section 3 (1.10a): t_m = 1/eta, u_m = (1 - eta)/(2 eta); the rectangular
    !> pulse kind in SI units scales as amp T^2.
    subroutine test_rect_half(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: etas(3) = [0.1_dp, 0.5_dp, 0.9_dp], tol = 1.0e-13_dp
        real(dp), parameter :: amp = 2.5_dp, td = 0.8_dp
        type(stickslip_result_t) :: res
        real(dp) :: eta, box
        integer :: i
        box = ieee_value(box, ieee_negative_inf)
        do i = 1, size(etas)
            eta = etas(i)
            call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, box, .false.), &
                           fric(eta, eta), 1, res, 'box half')
            if (allocated(error)) return
            call check(error, res%slides(1)%t_stop, 1.0_dp / eta, rtol=tol, message='t_m')
            if (allocated(error)) return
            call check(error, res%u_final, (1.0_dp - eta) / (2.0_dp * eta), rtol=tol, &
                       message='u_m')
            if (allocated(error)) return
            call check(error, res%u_max, res%u_final, rtol=0.0_dp, message='u_max')
            if (allocated(error)) return
            call check(error, res%u_min, 0.0_dp, atol=0.0_dp, message='u_min')
            if (allocated(error)) return
            ! SI: a = 2.5 m/s^2 for 0.8 s, ay = eta amp
            call run_pulse(error, rectangular_pulse(amp, td), fric(eta * amp, eta * amp), 1, &
                           res, 'rectangular SI')
            if (allocated(error)) return
            call check(error, res%slides(1)%t_stop, td / eta, rtol=tol, message='SI t_m')
            if (allocated(error)) return
            call check(error, res%u_final, amp * td**2 * (1.0_dp - eta) / (2.0_dp * eta), &
                       rtol=tol, message='SI u_m')
            if (allocated(error)) return
        end do
    end subroutine test_rect_half

    !> doc/sliding.md section 3 triangle table: onset eta/2; free (eta <= 2 - sqrt 2):
    !> t_m = (eta^2 + 2)/(4 eta), u = (12 - 24 eta + 12 eta^2 - eta^4)/(96 eta);
    !> forced: t_m = 1 - eta/2 + (1 - eta)/sqrt 2, u = (3 + 2 sqrt 2)(1 - eta)^3/12;
    !> V_m/V_g = (1 - eta)^2 with V_g = 1/2, at 1 - eta/2.
    subroutine test_triangle_half(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: etas(5) = [0.2_dp, 0.5_dp, 0.55_dp, 0.7_dp, 0.9_dp]
        real(dp), parameter :: tol = 1.0e-12_dp
        type(stickslip_result_t) :: res, res2
        real(dp) :: eta, tm, um, r2
        integer :: i
        r2 = sqrt(2.0_dp)
        do i = 1, size(etas)
            eta = etas(i)
            if (eta <= 2.0_dp - r2) then
                tm = (eta**2 + 2.0_dp) / (4.0_dp * eta)
                um = (12.0_dp - 24.0_dp * eta + 12.0_dp * eta**2 - eta**4) / (96.0_dp * eta)
            else
                tm = 1.0_dp - 0.5_dp * eta + (1.0_dp - eta) / r2
                um = (3.0_dp + 2.0_dp * r2) * (1.0_dp - eta)**3 / 12.0_dp
            end if
            call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, 0.0_dp, .false.), &
                           fric(eta, eta), 1, res, 'triangle')
            if (allocated(error)) return
            call check(error, res%slides(1)%t_start, 0.5_dp * eta, rtol=tol, message='onset')
            if (allocated(error)) return
            call check(error, res%slides(1)%t_stop, tm, rtol=tol, message='t_m')
            if (allocated(error)) return
            call check(error, res%u_final, um, rtol=tol, message='u_m')
            if (allocated(error)) return
            call check(error, res%slides(1)%w_peak, 0.5_dp * (1.0_dp - eta)**2, rtol=tol, &
                       message='V_m')
            if (allocated(error)) return
            call check(error, res%slides(1)%t_peak, 1.0_dp - 0.5_dp * eta, rtol=tol, &
                       message='t_vm')
            if (allocated(error)) return
            ! the triangular kind with r = 1/2 is the same pulse
            call run_pulse(error, triangular_pulse(1.0_dp, 1.0_dp, 0.5_dp), fric(eta, eta), 1, &
                           res2, 'triangular kind')
            if (allocated(error)) return
            call check_same_slides(error, res2, res, 1.0e-13_dp, 'triangular kind')
            if (allocated(error)) return
        end do
        ! r = 1: a = t rising to a jump at t = 1 (left limit 1, then 0): onset eta,
        ! w(1) = (1 - eta)^2/2, stop 1 + (1 - eta)^2/(2 eta),
        ! u = (1 - eta)^3/6 + (1 - eta)^4/(8 eta)
        eta = 0.5_dp
        call run_pulse(error, triangular_pulse(1.0_dp, 1.0_dp, 1.0_dp), fric(eta, eta), 1, res, &
                       'triangle r = 1')
        if (allocated(error)) return
        call check(error, res%slides(1)%t_start, eta, rtol=1.0e-14_dp, message='r = 1: onset')
        if (allocated(error)) return
        call check(error, res%slides(1)%t_stop, 1.0_dp + (1.0_dp - eta)**2 / (2.0_dp * eta), &
                   rtol=1.0e-14_dp, message='r = 1: stop')
        if (allocated(error)) return
        call check(error, res%slides(1)%w_peak, 0.5_dp * (1.0_dp - eta)**2, rtol=1.0e-14_dp, &
                   message='r = 1: peak at the jump')
        if (allocated(error)) return
        call check(error, res%u_final, (1.0_dp - eta)**3 / 6.0_dp &
                   + (1.0_dp - eta)**4 / (8.0_dp * eta), rtol=1.0e-13_dp, message='r = 1: u')
        if (allocated(error)) return
        ! eta = 1/2: 47/768 exactly
        call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, 0.0_dp, .false.), &
                       fric(0.5_dp, 0.5_dp), 1, res, 'triangle 1/2')
        if (allocated(error)) return
        call check(error, res%u_final, 47.0_dp / 768.0_dp, rtol=1.0e-14_dp, message='47/768')
        if (allocated(error)) return
        ! the peak only touches eta = 1: no slide; just below it, a tiny forced slide
        call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, 0.0_dp, .false.), &
                       fric(1.0_dp, 1.0_dp), 0, res, 'eta = 1')
        if (allocated(error)) return
        call check(error, res%u_final, 0.0_dp, atol=0.0_dp, message='eta = 1: no motion')
        if (allocated(error)) return
        eta = 1.0_dp - 1.0e-4_dp
        call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, 0.0_dp, .false.), &
                       fric(eta, eta), 1, res, 'eta -> 1')
        if (allocated(error)) return
        call check(error, res%u_final, (3.0_dp + 2.0_dp * r2) * (1.0_dp - eta)**3 / 12.0_dp, &
                   atol=1.0e-16_dp, message='continuous as eta -> 1')
    end subroutine test_triangle_half

    !> doc/sliding.md section 8: u_m for a = 1 and 1.2 (5 digits), onsets from Eqs. 1.12 and
    !> 1.34, V_m from Eqs. 1.13 and 1.35 at tau = 1 - tau_y.
    subroutine test_exp_half_static(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: betas(2) = [-pi, 0.5_dp], etas(2) = [0.3_dp, 0.6_dp]
        real(dp), parameter :: um1(2) = [0.53554_dp, 0.022812_dp]
        real(dp), parameter :: um12(2) = [0.53457_dp, 0.020987_dp]
        real(dp), parameter :: atols(2) = [5.0e-6_dp, 5.0e-7_dp]
        type(stickslip_result_t) :: res
        real(dp) :: b, eta, ty, ts, vg, vm, eb
        integer :: i
        do i = 1, 2
            b = betas(i)
            eta = etas(i)
            eb = exp(b)
            vg = 1.0_dp / (1.0_dp - eb) + 1.0_dp / b
            ty = exp_onset(b, eta)
            call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, b, .false.), &
                           fric(eta, eta), 1, res, 'kinetic')
            if (allocated(error)) return
            call check(error, res%u_final, um1(i), atol=atols(i), message='u_m (published)')
            if (allocated(error)) return
            call check(error, res%slides(1)%t_start, ty, rtol=1.0e-12_dp, message='Eq. 1.12')
            if (allocated(error)) return
            vm = vg * ((1.0_dp - eta) * (eb - 1.0_dp) - b * (1.0_dp + eta * (eb - 1.0_dp)) &
                       * (1.0_dp - 2.0_dp * ty)) / (eb - b - 1.0_dp)
            call check(error, res%slides(1)%w_peak, vm, rtol=1.0e-12_dp, message='Eq. 1.13')
            if (allocated(error)) return
            call check(error, res%slides(1)%t_peak, 1.0_dp - ty, rtol=1.0e-12_dp, &
                       message='t_vm = 1 - tau_y')
            if (allocated(error)) return
            ! static friction a = 1.2: onset at the static threshold, kinetic sliding
            ts = exp_onset(b, 1.2_dp * eta)
            call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, b, .false.), &
                           fric(eta, eta, 1.2_dp), 1, res, 'static')
            if (allocated(error)) return
            call check(error, res%u_final, um12(i), atol=atols(i), &
                       message='u_m, a = 1.2 (published)')
            if (allocated(error)) return
            call check(error, res%slides(1)%t_start, ts, rtol=1.0e-12_dp, message='Eq. 1.34')
            if (allocated(error)) return
            vm = vg / (eb - b - 1.0_dp) * (-0.5_dp * (exp(2.0_dp * b * ts) + exp(2.0_dp * b * ty)) &
                 + b * (eta - 1.0_dp) * (1.0_dp - ts - ty) &
                 + eb * (1.0_dp - b * eta + b * eta * ts + b * eta * ty))
            call check(error, res%slides(1)%w_peak, vm, rtol=1.0e-12_dp, message='Eq. 1.35')
            if (allocated(error)) return
            call check(error, res%slides(1)%t_peak, 1.0_dp - ty, rtol=1.0e-12_dp, &
                       message='static: t_vm = 1 - tau_y (kinetic)')
            if (allocated(error)) return
        end do
    end subroutine test_exp_half_static

    !> doc/sliding.md section 10 (exact column): onset 0.1035846, t_m1 = 1.2465561,
    !> u_m1 = 0.1706088, slip, reverse stop at 1 + 1.4468988, u_m2 = 0.1643832; the
    !> first stop also solves the corrected Eq. 1.19 (doc/sliding.md section 4).
    subroutine test_full_cycle_example(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: b = -pi, eta = 0.5_dp, tol7 = 5.0e-8_dp
        type(stickslip_result_t) :: res
        real(dp) :: ty, tm, eb, f
        call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, b, .true.), fric(eta, eta), &
                       2, res, 'example 1.9.1')
        if (allocated(error)) return
        associate(s1 => res%slides(1), s2 => res%slides(2))
            call check(error, s1%t_start, 0.1035846_dp, atol=tol7, message='tau_y')
            if (allocated(error)) return
            ty = exp_onset(b, eta)
            call check(error, s1%t_start, ty, rtol=1.0e-12_dp, message='tau_y, Eq. 1.12')
            if (allocated(error)) return
            call check(error, s1%t_stop, 1.2465561_dp, atol=tol7, message='tau_m1')
            if (allocated(error)) return
            call check(error, s1%u_stop, 0.1706088_dp, atol=tol7, message='u_m1')
            if (allocated(error)) return
            call check(error, s2%direction == -1 .and. s2%from_slip, 'slip (1.21b)')
            if (allocated(error)) return
            call check(error, s2%t_start, s1%t_stop, rtol=0.0_dp, message='tau_y2 = tau_m1')
            if (allocated(error)) return
            call check(error, s2%t_stop, 2.4468988_dp, atol=tol7, message='tau_m2')
            if (allocated(error)) return
            call check(error, s2%u_start - s2%u_stop, 0.1643832_dp, atol=tol7, message='u_m2')
            if (allocated(error)) return
            ! corrected (1.19): continuous, its root is the first stop
            tm = s1%t_stop
            eb = exp(b)
            f = (tm - ty) * (1.0_dp - eta * (1.0_dp - eb)) &
                + (exp(2.0_dp * b * (1.0_dp - tm)) + exp(2.0_dp * b * ty) - 2.0_dp * eb) &
                  / (2.0_dp * b) &
                + 2.0_dp * (1.0_dp - tm) &
                + (exp(-2.0_dp * b * (1.0_dp - tm)) - exp(2.0_dp * b * (1.0_dp - tm))) &
                  / (2.0_dp * b)
            call check(error, f, 0.0_dp, atol=1.0e-13_dp, message='corrected Eq. 1.19 residual')
            if (allocated(error)) return
        end associate
        call check(error, res%u_final, 0.1706088_dp - 0.1643832_dp, atol=1.0e-7_dp, &
                   message='u_res')
    end subroutine test_full_cycle_example

    !> doc/sliding.md section 7: beta = 0.4, eta = (0.05, 0.7): no reverse slide at all;
    !> beta = -pi: the reverse slide starts by slip in the second half of the second
    !> lobe, stops before t = 2 (forced, the derived equation of 7.4 holds),
    !> u_m2 = 1.72069e-5; with eta_rev = +inf the first slide is unchanged and alone.
    subroutine test_asymmetric(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: e1 = 0.05_dp, e2 = 0.7_dp
        type(stickslip_result_t) :: res, res_inf
        real(dp) :: b, ty, tm, f
        call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, 0.4_dp, .true.), &
                       fric(e1, e2), 1, res, 'beta 0.4')
        if (allocated(error)) return
        call check(error, res%slides(1)%direction, 1, 'forward only')
        if (allocated(error)) return
        call check(error, res%u_final, res%slides(1)%u_stop, rtol=0.0_dp, message='u_res = u_m1')
        if (allocated(error)) return
        b = -pi
        call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, b, .true.), fric(e1, e2), 2, &
                       res, 'beta -pi')
        if (allocated(error)) return
        associate(s2 => res%slides(2))
            call check(error, s2%direction == -1 .and. s2%from_slip, 'reverse by slip')
            if (allocated(error)) return
            call check(error, s2%t_start > 1.5_dp .and. s2%t_stop < 2.0_dp, &
                       'slip after 3/2, forced stop before 2')
            if (allocated(error)) return
            call check(error, s2%u_start - s2%u_stop, 1.72069e-5_dp, rtol=5.0e-6_dp, &
                       message='u_m2')
            if (allocated(error)) return
            ty = s2%t_start - 1.0_dp
            tm = s2%t_stop - 1.0_dp
            f = (tm - ty) * (1.0_dp - e2 * (1.0_dp - exp(b))) &
                + (exp(2.0_dp * b * (1.0_dp - tm)) - exp(2.0_dp * b * (1.0_dp - ty))) / (2.0_dp * b)
            call check(error, f, 0.0_dp, atol=1.0e-14_dp, message='forced-phase equation')
            if (allocated(error)) return
        end associate
        call run_pulse(error, exponential_pulse(1.0_dp, 1.0_dp, b, .true.), &
                       fric(e1, ieee_value(b, ieee_positive_inf)), 1, res_inf, 'eta_rev = inf')
        if (allocated(error)) return
        call check(error, res_inf%slides(1)%t_stop, res%slides(1)%t_stop, rtol=1.0e-15_dp, &
                   message='first slide independent of eta_rev')
        if (allocated(error)) return
        call check(error, res_inf%u_final, res%slides(1)%u_stop, rtol=1.0e-15_dp, &
                   message='u_final = u_m1')
    end subroutine test_asymmetric

    !> Triangle full cycle, eta = 0.6 > eta_cr = sqrt 2 - 1: forced first stop before
    !> 1 + tau_y, so the block sticks; the reverse slide is the mirror image of the
    !> first (onset 1 + eta/2, stop 1 + tau_m1) and u_res = 0 (doc/sliding.md section 5).
    !> Static friction a = 1.2: the first onset at a eta/2; the second at 1 + eta/2
    !> (kinetic), or 1 + a eta/2 with static_all, which restores the mirror.
    subroutine test_stick_static_all(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: eta = 0.6_dp
        type(stickslip_result_t) :: res
        type(pulse_t) :: p
        real(dp) :: tm
        p = exponential_pulse(1.0_dp, 1.0_dp, 0.0_dp, .true.)
        tm = 1.0_dp - 0.5_dp * eta + (1.0_dp - eta) / sqrt(2.0_dp)
        call run_pulse(error, p, fric(eta, eta), 2, res, 'stick')
        if (allocated(error)) return
        associate(s1 => res%slides(1), s2 => res%slides(2))
            call check(error, s1%t_stop, tm, rtol=1.0e-12_dp, message='forced tau_m1')
            if (allocated(error)) return
            call check(error, s2%direction == -1 .and. .not. s2%from_slip, 'stick, then reverse')
            if (allocated(error)) return
            call check(error, s2%t_start, 1.0_dp + 0.5_dp * eta, rtol=1.0e-12_dp, &
                       message='tau_y2 = 1 + tau_y1')
            if (allocated(error)) return
            call check(error, s2%t_stop, 1.0_dp + tm, rtol=1.0e-12_dp, message='mirror stop')
            if (allocated(error)) return
        end associate
        call check(error, res%u_final, 0.0_dp, atol=1.0e-14_dp, message='u_res = 0')
        if (allocated(error)) return
        call run_pulse(error, p, fric(eta, eta, 1.2_dp, .false.), 2, res, 'static first')
        if (allocated(error)) return
        call check(error, res%slides(1)%t_start, 0.6_dp * eta, rtol=1.0e-12_dp, &
                   message='static first onset')
        if (allocated(error)) return
        call check(error, res%slides(2)%t_start, 1.0_dp + 0.5_dp * eta, rtol=1.0e-12_dp, &
                   message='kinetic second onset')
        if (allocated(error)) return
        call check(error, res%u_final < -1.0e-4_dp, 'reverse slide longer: u_res < 0')
        if (allocated(error)) return
        call run_pulse(error, p, fric(eta, eta, 1.2_dp, .true.), 2, res, 'static all')
        if (allocated(error)) return
        call check(error, res%slides(2)%t_start, 1.0_dp + 0.6_dp * eta, rtol=1.0e-12_dp, &
                   message='static second onset')
        if (allocated(error)) return
        call check(error, res%u_final, 0.0_dp, atol=1.0e-14_dp, message='mirror again: u_res = 0')
    end subroutine test_stick_static_all

    !> Samples of the triangle at dt = 2^-k hit its kinks, and a constant record ends
    !> with a_g = 0 after the last sample: both records ARE the pulses.
    subroutine test_record_equals_pulse(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: etas(2) = [0.3_dp, 0.7_dp]
        type(stickslip_result_t) :: rp, rr
        real(dp), allocatable :: acc(:)
        real(dp) :: dt
        integer :: i, k, n, stat
        type(pulse_t) :: p
        p = triangular_pulse(1.0_dp, 1.0_dp, 0.5_dp)
        do k = 3, 7, 2
            dt = 1.0_dp / real(2**k, dp)
            n = 2**k + 1
            call sample_pulse(p, dt, n, acc)
            do i = 1, size(etas)
                call run_pulse(error, p, fric(etas(i), etas(i)), 1, rp, 'triangle pulse')
                if (allocated(error)) return
                call stickslip_record(acc, dt, fric(etas(i), etas(i)), g_unit, rr, stat)
                call check(error, stat, SEISPULSE_SUCCESS, 'record status')
                if (allocated(error)) return
                call check_same_slides(error, rr, rp, 1.0e-12_dp, 'triangle record')
                if (allocated(error)) return
            end do
            ! rectangle of length 1: n samples of 1
            acc(:) = 1.0_dp
            call stickslip_record(acc, dt, fric(0.4_dp, 0.4_dp), g_unit, rr, stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'record status')
            if (allocated(error)) return
            call check(error, size(rr%slides), 1, 'one slide')
            if (allocated(error)) return
            call check(error, rr%slides(1)%t_stop, 1.0_dp / 0.4_dp, rtol=1.0e-12_dp, &
                       message='rectangle record t_m')
            if (allocated(error)) return
            call check(error, rr%u_final, 0.6_dp / 0.8_dp, rtol=1.0e-12_dp, &
                       message='rectangle record u_m')
            if (allocated(error)) return
        end do
    end subroutine test_record_equals_pulse

    !> Piecewise-linear sampling of a smooth pulse: error ~ dt^2 (ratio ~4 per halving),
    !> for a half cycle (one slide) and a full cycle with a slip.
    subroutine test_record_convergence(error)
        type(test_error), allocatable, intent(out) :: error
        type(stickslip_result_t) :: rp, rr
        real(dp), allocatable :: acc(:)
        real(dp) :: err(3), dt
        integer :: k, stat, c
        type(pulse_t) :: p
        do c = 1, 2
            p = exponential_pulse(1.0_dp, 1.0_dp, -pi, c == 2)
            call run_pulse(error, p, fric(0.3_dp, 0.3_dp), c, rp, 'exp pulse')
            if (allocated(error)) return
            do k = 1, 3
                dt = 1.0_dp / real(2**(k + 4), dp)
                call sample_pulse(p, dt, c * 2**(k + 4) + 1, acc)
                call stickslip_record(acc, dt, fric(0.3_dp, 0.3_dp), g_unit, rr, stat)
                call check(error, stat, SEISPULSE_SUCCESS, 'record status')
                if (allocated(error)) return
                call check(error, size(rr%slides), c, 'record: number of slides')
                if (allocated(error)) return
                err(k) = abs(rr%u_final - rp%u_final)
            end do
            call check(error, err(1) < 1.0e-2_dp .and. err(3) > 0.0_dp, 'errors small, not zero')
            if (allocated(error)) return
            call check(error, err(1) / err(2), 4.0_dp, rtol=0.1_dp, message='ratio dt/32 : dt/64')
            if (allocated(error)) return
            call check(error, err(2) / err(3), 4.0_dp, rtol=0.1_dp, message='ratio dt/64 : dt/128')
            if (allocated(error)) return
        end do
    end subroutine test_record_convergence

    !> u_final = sum of signed slides, u continuous between slides, u_max/u_min/t_end;
    !> grid output: rest before onset and after t_end, w = 0 at the stops, closed forms
    !> of the rectangle inside both slides; for a smooth pulse, w = du/dt on the grid.
    subroutine test_consistency_grid(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: eta = 0.3_dp, h = 1.0e-4_dp
        real(dp), parameter :: probes(5) = [0.3_dp, 0.8_dp, 1.1_dp, 1.7_dp, 2.2_dp]
        type(stickslip_result_t) :: res
        real(dp) :: tg(8), ug(8), wg(8), t1, t2, w2, u2, box, tp(15), up(15), wp(15)
        integer :: stat, k
        box = ieee_value(box, ieee_negative_inf)
        t1 = 2.0_dp / (1.0_dp + eta)
        t2 = 4.0_dp / (1.0_dp + eta)
        tg = [-0.5_dp, 0.0_dp, 0.5_dp, 1.2_dp, t1, 2.5_dp, t2, 10.0_dp]
        call stickslip_pulse(exponential_pulse(1.0_dp, 1.0_dp, box, .true.), fric(eta, eta), &
                             res, stat, t_grid=tg, u_grid=ug, w_grid=wg)
        call check(error, stat, SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, size(res%slides), 2, 'two slides')
        if (allocated(error)) return
        call check(error, res%u_final, slide_sum(res), rtol=1.0e-14_dp, message='sum of slides')
        if (allocated(error)) return
        call check(error, res%slides(2)%u_start, res%slides(1)%u_stop, rtol=0.0_dp, &
                   message='u continuous')
        if (allocated(error)) return
        call check(error, res%u_max, res%slides(1)%u_stop, rtol=0.0_dp, message='u_max')
        if (allocated(error)) return
        call check(error, res%u_min, 0.0_dp, atol=0.0_dp, message='u_min')
        if (allocated(error)) return
        call check(error, res%t_end, res%slides(2)%t_stop, rtol=0.0_dp, message='t_end')
        if (allocated(error)) return
        call check(error, ug(1:2), [0.0_dp, 0.0_dp], atol=0.0_dp, message='at rest before')
        if (allocated(error)) return
        call check(error, wg(1:2), [0.0_dp, 0.0_dp], atol=0.0_dp, message='at rest before')
        if (allocated(error)) return
        ! forced phase: w = (1 - eta) t, u = (1 - eta) t^2/2
        call check(error, wg(3), (1.0_dp - eta) * 0.5_dp, rtol=1.0e-14_dp, message='w(0.5)')
        if (allocated(error)) return
        call check(error, ug(3), (1.0_dp - eta) * 0.125_dp, rtol=1.0e-14_dp, message='u(0.5)')
        if (allocated(error)) return
        ! second lobe (a = -1): w = (1 - eta) - (1 + eta)(t - 1)
        call check(error, wg(4), (1.0_dp - eta) - (1.0_dp + eta) * 0.2_dp, rtol=1.0e-14_dp, &
                   message='w(1.2)')
        if (allocated(error)) return
        call check(error, ug(4), 0.5_dp * (1.0_dp - eta) + (1.0_dp - eta) * 0.2_dp &
                   - 0.5_dp * (1.0_dp + eta) * 0.04_dp, rtol=1.0e-14_dp, message='u(1.2)')
        if (allocated(error)) return
        call check(error, wg(5), 0.0_dp, atol=1.0e-14_dp, message='w = 0 at the first stop')
        if (allocated(error)) return
        call check(error, ug(5), res%slides(1)%u_stop, rtol=1.0e-14_dp, message='u(t_m1)')
        if (allocated(error)) return
        ! reverse slide: a = -1 until 2, then a = 0 (deceleration at eta)
        w2 = -(1.0_dp - eta) * (2.0_dp - t1)
        u2 = res%slides(1)%u_stop - 0.5_dp * (1.0_dp - eta) * (2.0_dp - t1)**2
        call check(error, wg(6), w2 + eta * 0.5_dp, rtol=1.0e-13_dp, message='w(2.5)')
        if (allocated(error)) return
        call check(error, ug(6), u2 + w2 * 0.5_dp + 0.5_dp * eta * 0.25_dp, rtol=1.0e-13_dp, &
                   message='u(2.5)')
        if (allocated(error)) return
        call check(error, wg(7), 0.0_dp, atol=1.0e-14_dp, message='w = 0 at the last stop')
        if (allocated(error)) return
        call check(error, ug(7:8), [res%u_final, res%u_final], rtol=1.0e-14_dp, &
                   message='at rest after')
        if (allocated(error)) return
        call check(error, wg(8), 0.0_dp, atol=0.0_dp, message='w = 0 after t_end')
        if (allocated(error)) return
        ! smooth pulse (Example 1.9.1): central differences of u_grid give w_grid
        do k = 1, size(probes)
            tp(3 * k - 2:3 * k) = probes(k) + [-h, 0.0_dp, h]
        end do
        call stickslip_pulse(exponential_pulse(1.0_dp, 1.0_dp, -pi, .true.), fric(0.5_dp, 0.5_dp), &
                             res, stat, t_grid=tp, u_grid=up, w_grid=wp)
        call check(error, stat, SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        do k = 1, size(probes)
            call check(error, (up(3 * k) - up(3 * k - 2)) / (2.0_dp * h), wp(3 * k - 1), &
                       rtol=1.0e-6_dp, atol=1.0e-9_dp, message='du/dt = w')
            if (allocated(error)) return
        end do
        call check(error, res%u_final, slide_sum(res), rtol=1.0e-14_dp, message='sum of slides')
    end subroutine test_consistency_grid

    !> Half-sine, eta = 0.3: the stop from a bisection on the analytic relative velocity
    !> w(t) = [cos(pi t_y) - cos(pi t)]/pi - eta (t - t_y) (t <= 1), w(1) - eta (t - 1)
    !> after; then sine cycle, cosine cycle (jumps at 0 and T), Ricker and M&P run
    !> with finite, ordered, consistent results.
    subroutine test_other_pulses(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: eta = 0.3_dp
        type(stickslip_result_t) :: res
        type(pulse_t) :: pulses(4)
        real(dp) :: ty, lo, hi, mid, w1, u1, um, ts, ays(4)
        integer :: i, k
        ty = asin(eta) / pi
        call run_pulse(error, half_sine_pulse(1.0_dp, 1.0_dp), fric(eta, eta), 1, res, 'half-sine')
        if (allocated(error)) return
        call check(error, res%slides(1)%t_start, ty, rtol=1.0e-13_dp, message='onset asin(eta)/pi')
        if (allocated(error)) return
        w1 = (cos(pi * ty) + 1.0_dp) / pi - eta * (1.0_dp - ty)
        lo = 0.5_dp
        hi = 1.0_dp + w1 / eta + 1.0_dp
        do k = 1, 200
            mid = 0.5_dp * (lo + hi)
            if (hs_velocity(mid) > 0.0_dp) then
                lo = mid
            else
                hi = mid
            end if
        end do
        ts = 0.5_dp * (lo + hi)
        call check(error, res%slides(1)%t_stop, ts, rtol=1.0e-13_dp, message='stop vs bisection')
        if (allocated(error)) return
        ! u: integral of w (free regime here: ts > 1)
        u1 = (cos(pi * ty) * (1.0_dp - ty) + sin(pi * ty) / pi) / pi &
             - 0.5_dp * eta * (1.0_dp - ty)**2
        um = u1 + w1 * (ts - 1.0_dp) - 0.5_dp * eta * (ts - 1.0_dp)**2
        call check(error, ts > 1.0_dp, 'free regime')
        if (allocated(error)) return
        call check(error, res%u_final, um, rtol=1.0e-12_dp, message='u_m half-sine')
        if (allocated(error)) return

        pulses = [sine_cycle_pulse(1.0_dp, 1.0_dp), cosine_cycle_pulse(1.0_dp, 1.0_dp), &
                  ricker_pulse(1.0_dp, 1.0_dp, 1.0_dp), &
                  mp_pulse(1.0_dp, 1.0_dp, 2.0_dp, 30.0_dp, 1.5_dp)]
        ays = [0.3_dp, 0.3_dp, 0.3_dp, 2.0_dp]
        do i = 1, size(pulses)
            call run_pulse(error, pulses(i), fric(ays(i), ays(i)), -1, res, 'other pulse')
            if (allocated(error)) return
            call check(error, size(res%slides) >= 2, 'two-sided pulses slide both ways')
            if (allocated(error)) return
            do k = 1, size(res%slides)
                associate(s => res%slides(k))
                    call check(error, ieee_is_finite(s%u_stop) .and. ieee_is_finite(s%w_peak) &
                               .and. s%t_stop > s%t_start .and. s%w_peak > 0.0_dp &
                               .and. s%t_peak > s%t_start .and. s%t_peak < s%t_stop, &
                               'finite slide with its peak inside')
                    if (allocated(error)) return
                    call check(error, s%direction * (s%u_stop - s%u_start) > 0.0_dp, &
                               'u moves in the slide direction')
                    if (allocated(error)) return
                    if (k > 1) then
                        call check(error, s%t_start >= res%slides(k - 1)%t_stop, 'slides ordered')
                        if (allocated(error)) return
                    end if
                end associate
            end do
            call check(error, res%u_final, slide_sum(res), rtol=1.0e-13_dp, atol=1.0e-15_dp, &
                       message='sum of slides')
            if (allocated(error)) return
        end do
        ! cosine cycle: the onset is the jump at t = 0
        call run_pulse(error, cosine_cycle_pulse(1.0_dp, 1.0_dp), fric(eta, eta), -1, res, 'cos')
        if (allocated(error)) return
        call check(error, res%slides(1)%t_start, 0.0_dp, atol=0.0_dp, message='cosine onset at 0')

    contains

        pure function hs_velocity(t) result(w)
            real(dp), intent(in) :: t
            real(dp) :: w
            if (t <= 1.0_dp) then
                w = (cos(pi * ty) - cos(pi * t)) / pi - eta * (t - ty)
            else
                w = w1 - eta * (t - 1.0_dp)
            end if
        end function hs_velocity

    end subroutine test_other_pulses

    !> M&P (jerk-split pieces) and Ricker (extrema pieces, cut at x = 10) against their
    !> finely sampled records: same slides, u_final and t_end errors ~ dt^2; a slide
    !> that only the exact extrema of a_g can reveal is found.
    subroutine test_mp_ricker_records(error)
        type(test_error), allocatable, intent(out) :: error
        type(stickslip_result_t) :: rp, rr
        type(pulse_t) :: p
        real(dp), allocatable :: acc(:)
        real(dp) :: eu(2), et(2), dt, tend, ay, t_pk, a_pk
        integer :: c, k, stat
        do c = 1, 2
            if (c == 1) then
                p = mp_pulse(1.0_dp, 1.0_dp, 2.0_dp, 30.0_dp, 1.5_dp)
                tend = 3.0_dp
                ay = 2.0_dp
            else
                p = ricker_pulse(1.0_dp, 1.0_dp, 1.0_dp)
                tend = 5.0_dp
                ay = 0.3_dp
            end if
            call run_pulse(error, p, fric(ay, ay), 3, rp, 'pulse')
            if (allocated(error)) return
            do k = 1, 2
                dt = 1.0_dp / real(2**(8 + k), dp)
                call sample_pulse(p, dt, nint(tend / dt) + 1, acc)
                call stickslip_record(acc, dt, fric(ay, ay), g_unit, rr, stat)
                call check(error, stat, SEISPULSE_SUCCESS, 'record status')
                if (allocated(error)) return
                call check(error, size(rr%slides), 3, 'record: same number of slides')
                if (allocated(error)) return
                eu(k) = abs(rr%u_final - rp%u_final)
                et(k) = abs(rr%t_end - rp%t_end)
            end do
            call check(error, eu(1) < 1.0e-5_dp .and. et(1) < 1.0e-4_dp, 'close at dt = 2^-9')
            if (allocated(error)) return
            call check(error, eu(1) / eu(2), 4.0_dp, rtol=0.1_dp, message='u_final error ratio')
            if (allocated(error)) return
            call check(error, et(1) / et(2), 4.0_dp, rtol=0.1_dp, message='t_end error ratio')
            if (allocated(error)) return
            ! a threshold a hair below the largest a_g (located here by sampling and a
            ! golden-section search): a slide must start there, although a_g stays
            ! below it at every sample and every 1/(64 f_p) node
            call peak_accel(p, tend, t_pk, a_pk)
            call run_pulse(error, p, fric(a_pk * (1.0_dp - 1.0e-7_dp), &
                           ieee_value(a_pk, ieee_positive_inf)), 1, rp, 'just below the peak')
            if (allocated(error)) return
            call check(error, rp%slides(1)%t_start, t_pk, atol=1.0e-3_dp, &
                       message='onset at the peak of a_g')
            if (allocated(error)) return
            call check(error, rp%slides(1)%t_stop - rp%slides(1)%t_start < 1.0e-3_dp, &
                       'short slide')
            if (allocated(error)) return
        end do

    contains

        !> Largest a_g on [0, tend]: best of 4001 samples, then golden section.
        subroutine peak_accel(pp, t_max, tp, ap)
            type(pulse_t), intent(in) :: pp
            real(dp), intent(in) :: t_max
            real(dp), intent(out) :: tp, ap
            real(dp), parameter :: gr = 0.6180339887498949_dp
            real(dp) :: a, v, d, lo, hi, x1, x2, f1, f2, step
            integer :: i
            step = t_max / 4000.0_dp
            ap = -huge(ap)
            tp = 0.0_dp
            do i = 0, 4000
                call pulse_at(pp, real(i, dp) * step, a, v, d)
                if (a > ap) then
                    ap = a
                    tp = real(i, dp) * step
                end if
            end do
            lo = tp - step
            hi = tp + step
            do i = 1, 100
                x1 = hi - gr * (hi - lo)
                x2 = lo + gr * (hi - lo)
                call pulse_at(pp, x1, f1, v, d)
                call pulse_at(pp, x2, f2, v, d)
                if (f1 > f2) then
                    hi = x2
                else
                    lo = x1
                end if
            end do
            tp = 0.5_dp * (lo + hi)
            call pulse_at(pp, tp, ap, v, d)
        end subroutine peak_accel

    end subroutine test_mp_ricker_records

    !> Spike (beta = +inf): no sliding, no NaN; one-way friction; records of one and two
    !> samples (the two-sample record [1, 1] with dt = 1 is the unit rectangle).
    subroutine test_degenerate(error)
        type(test_error), allocatable, intent(out) :: error
        type(stickslip_result_t) :: res
        real(dp) :: inf, tg(3), ug(3), wg(3)
        integer :: k, stat
        logical :: full
        inf = ieee_value(inf, ieee_positive_inf)
        do k = 1, 2
            full = k == 2
            tg = [0.25_dp, 0.5_dp, 3.0_dp]
            call stickslip_pulse(exponential_pulse(1.0_dp, 1.0_dp, inf, full), &
                                 fric(0.3_dp, 0.3_dp), res, stat, t_grid=tg, u_grid=ug, w_grid=wg)
            call check(error, stat, SEISPULSE_SUCCESS, 'spike status')
            if (allocated(error)) return
            call check(error, size(res%slides), 0, 'spike: no slide')
            if (allocated(error)) return
            call check(error, res%u_final, 0.0_dp, atol=0.0_dp, message='spike: u = 0')
            if (allocated(error)) return
            call check(error, ug, [0.0_dp, 0.0_dp, 0.0_dp], atol=0.0_dp, message='spike grid')
            if (allocated(error)) return
        end do
        ! sine cycle with no reverse sliding
        call run_pulse(error, sine_cycle_pulse(1.0_dp, 1.0_dp), fric(0.3_dp, inf), 1, res, &
                       'one-way')
        if (allocated(error)) return
        call check(error, res%slides(1)%direction, 1, 'forward only')
        if (allocated(error)) return
        call check(error, res%u_min, 0.0_dp, atol=0.0_dp, message='never negative')
        if (allocated(error)) return
        ! and no sliding at all
        call run_pulse(error, sine_cycle_pulse(1.0_dp, 1.0_dp), fric(inf, inf), 0, res, 'locked')
        if (allocated(error)) return
        call stickslip_record([5.0_dp], 0.01_dp, fric(0.1_dp, 0.1_dp), g_unit, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. size(res%slides) == 0, &
                   'one sample: an instant, no slide')
        if (allocated(error)) return
        call stickslip_record([1.0_dp, 1.0_dp], 1.0_dp, fric(0.5_dp, 0.5_dp), g_unit, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. size(res%slides) == 1, 'two samples')
        if (allocated(error)) return
        call check(error, res%slides(1)%t_stop, 2.0_dp, rtol=1.0e-15_dp, message='t_m = 1/eta')
        if (allocated(error)) return
        call check(error, res%u_final, 0.5_dp, rtol=1.0e-15_dp, message='u = (1-eta)/(2 eta)')
    end subroutine test_degenerate

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(stickslip_result_t) :: res
        type(pulse_t) :: p
        real(dp) :: nan, tg(3), ug(3), wg(2), wg3(3)
        integer :: stat
        character(len=200) :: msg
        nan = ieee_value(nan, ieee_quiet_nan)
        p = half_sine_pulse(1.0_dp, 1.0_dp)
        call expect(fric(-1.0_dp, 0.1_dp), 'ay_fwd = -1')
        if (allocated(error)) return
        call check(error, index(msg, 'must be > 0 (or +inf') > 0, 'range in message: '//trim(msg))
        if (allocated(error)) return
        call expect(fric(0.0_dp, 0.1_dp), 'ay_fwd')
        if (allocated(error)) return
        call expect(fric(0.1_dp, nan), 'ay_rev = NaN')
        if (allocated(error)) return
        call expect(fric(0.1_dp, -ieee_value(nan, ieee_positive_inf)), 'ay_rev')
        if (allocated(error)) return
        call expect(fric(0.1_dp, 0.1_dp, 0.5_dp), 'static_factor = 0.5')
        if (allocated(error)) return
        call expect(fric(0.1_dp, 0.1_dp, nan), 'static_factor')
        if (allocated(error)) return
        call expect(fric(0.1_dp, 0.1_dp, ieee_value(nan, ieee_positive_inf)), 'static_factor')
        if (allocated(error)) return
        call friction_validate(fric(0.1_dp, ieee_value(nan, ieee_positive_inf), 1.5_dp), stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'ay_rev = +inf is valid')
        if (allocated(error)) return
        ! pulse errors come from pulse_validate
        msg = ''
        call stickslip_pulse(half_sine_pulse(1.0_dp, -1.0_dp), fric(0.1_dp, 0.1_dp), res, stat, msg)
        call expect_status('duration')
        if (allocated(error)) return
        ! records
        msg = ''
        call stickslip_record([1.0_dp, 2.0_dp], 0.0_dp, fric(0.1_dp, 0.1_dp), &
                              g_unit, res, stat, msg)
        call expect_status('dt = 0')
        if (allocated(error)) return
        msg = ''
        call stickslip_record([1.0_dp, 2.0_dp], nan, fric(0.1_dp, 0.1_dp), g_unit, res, stat, msg)
        call expect_status('dt = NaN')
        if (allocated(error)) return
        msg = ''
        call stickslip_record([real(dp) ::], 0.01_dp, fric(0.1_dp, 0.1_dp), g_unit, res, stat, msg)
        call expect_status('accel')
        if (allocated(error)) return
        msg = ''
        call stickslip_record([1.0_dp, nan, 2.0_dp], 0.01_dp, fric(0.1_dp, 0.1_dp), &
                              g_unit, res, stat, msg)
        call expect_status('accel(2) = NaN')
        if (allocated(error)) return
        msg = ''
        call stickslip_record([1.0_dp, 2.0_dp], 0.01_dp, fric(-0.1_dp, 0.1_dp), &
                              g_unit, res, stat, msg)
        call expect_status('ay_fwd')
        if (allocated(error)) return
        msg = ''
        call stickslip_record([1.0_dp, 2.0_dp], 0.01_dp, fric(0.1_dp, 0.1_dp), 0.0_dp, res, stat, &
                              msg)
        call expect_status('g = 0.0')
        if (allocated(error)) return
        msg = ''
        call stickslip_record([1.0_dp, 2.0_dp], 0.01_dp, fric(0.1_dp, 0.1_dp), nan, res, stat, msg)
        call expect_status('g = NaN')
        if (allocated(error)) return
        msg = ''
        call stickslip_record([1.0_dp, -huge(1.0_dp)], 0.01_dp, fric(0.1_dp, 0.1_dp), g0, res, &
                              stat, msg)
        call expect_status('accel(2) = ')
        if (allocated(error)) return
        call check(error, index(msg, 'overflows') > 0, 'overflow in message: '//trim(msg))
        if (allocated(error)) return
        ! grids
        tg = [0.0_dp, 1.0_dp, 2.0_dp]
        msg = ''
        call stickslip_pulse(p, fric(0.1_dp, 0.1_dp), res, stat, msg, t_grid=tg, u_grid=ug, &
                             w_grid=wg)
        call expect_status('w_grid')
        if (allocated(error)) return
        msg = ''
        call stickslip_pulse(p, fric(0.1_dp, 0.1_dp), res, stat, msg, t_grid=tg, u_grid=ug)
        call expect_status('w_grid')
        if (allocated(error)) return
        msg = ''
        call stickslip_pulse(p, fric(0.1_dp, 0.1_dp), res, stat, msg, u_grid=ug, w_grid=wg)
        call expect_status('t_grid')
        if (allocated(error)) return
        tg = [0.0_dp, 2.0_dp, 1.0_dp]
        msg = ''
        call stickslip_record([1.0_dp, 2.0_dp], 0.01_dp, fric(0.1_dp, 0.1_dp), &
                              g_unit, res, stat, msg, &
                              t_grid=tg, u_grid=ug, w_grid=wg3)
        call expect_status('t_grid(3)')
        if (allocated(error)) return
        tg = [0.0_dp, nan, 1.0_dp]
        msg = ''
        call stickslip_record([1.0_dp, 2.0_dp], 0.01_dp, fric(0.1_dp, 0.1_dp), &
                              g_unit, res, stat, msg, &
                              t_grid=tg, u_grid=ug, w_grid=wg3)
        call expect_status('t_grid(2) = NaN')
        if (allocated(error)) return
        call check(error, size(res%slides) == 0 .and. .not. (abs(res%u_final) > 0.0_dp), &
                   'empty result on error')

    contains

        !> A pulse run and friction_validate both fail with a message starting with `head`.
        subroutine expect(fr, head)
            type(friction_t), intent(in) :: fr
            character(len=*), intent(in) :: head
            msg = ''
            call friction_validate(fr, stat, msg)
            call expect_status(head)
            if (allocated(error)) return
            msg = ''
            call stickslip_pulse(p, fr, res, stat, msg)
            call expect_status(head)
        end subroutine expect

        subroutine expect_status(head)
            character(len=*), intent(in) :: head
            call check(error, stat, SEISPULSE_INVALID_INPUT, 'status for '//head)
            if (allocated(error)) return
            call check(error, index(msg, head) == 1, 'message "'//trim(msg) &
                       //'" should start with "'//head//'"')
        end subroutine expect_status

    end subroutine test_bad_input

    !> A record in g and its g: the run on accel g, ay g (bit for bit the run on the
    !> caller's products with g = 1), u in m; the closed form of a constant record.
    subroutine test_record_in_g(error)
        type(test_error), allocatable, intent(out) :: error
        type(stickslip_result_t) :: rg, r1
        real(dp), allocatable :: acc(:)
        real(dp) :: dt
        integer :: stat
        type(pulse_t) :: p
        ! 1 g during 1 s, ay = 0.5 g: slides to t = 2 s, u = (1 - eta)/(2 eta) g s^2 = g/2 m
        call stickslip_record([1.0_dp, 1.0_dp], 1.0_dp, fric(0.5_dp, 0.5_dp), g0, rg, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'constant record status')
        if (allocated(error)) return
        call check(error, size(rg%slides), 1, 'constant record: one slide')
        if (allocated(error)) return
        call check(error, rg%slides(1)%t_stop, 2.0_dp, rtol=1.0e-15_dp, message='t_stop (s)')
        if (allocated(error)) return
        call check(error, rg%u_final, 0.5_dp * g0, rtol=1.0e-15_dp, message='u_final (m)')
        if (allocated(error)) return
        call check(error, rg%slides(1)%w_peak, 0.5_dp * g0, rtol=1.0e-15_dp, &
                   message='w_peak (m/s)')
        if (allocated(error)) return
        ! a full exponential cycle, two slides: identical to the run on the products
        p = exponential_pulse(1.0_dp, 1.0_dp, -pi, .true.)
        dt = 1.0_dp / 64.0_dp
        call sample_pulse(p, dt, 129, acc)
        call stickslip_record(acc, dt, fric(0.3_dp, 0.2_dp, 1.2_dp), g0, rg, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'record in g status')
        if (allocated(error)) return
        call stickslip_record(acc * g0, dt, fric(0.3_dp * g0, 0.2_dp * g0, 1.2_dp), g_unit, r1, &
                              stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'record in m/s^2 status')
        if (allocated(error)) return
        call check(error, size(rg%slides) >= 2, 'two slides at least')
        if (allocated(error)) return
        call check_same_slides(error, rg, r1, 0.0_dp, 'g0 against the products')
        if (allocated(error)) return
        call check(error, rg%u_max, r1%u_max, rtol=0.0_dp, message='u_max')
        if (allocated(error)) return
        call check(error, rg%u_min, r1%u_min, rtol=0.0_dp, message='u_min')
        if (allocated(error)) return
        ! at g = 11.527021957185141, (huge/g) g rounds up to +inf: a sample of huge/g must be
        ! refused by name, not turned into an infinite acceleration
        call stickslip_record([1.0_dp, huge(dt) / g_edge], 0.01_dp, fric(0.1_dp, 0.1_dp), &
                              g_edge, rg, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'sample huge/g: refused')
    end subroutine test_record_in_g

    !> Two sine and two cosine cycles (A = 1, T = 1, ay = 0.3: two-way slides in each cycle)
    !> against records of A sin(2 pi t/T), A cos(2 pi t/T) sampled here with the intrinsic
    !> functions (not through seispulse_pulses) and zero after 2 T: same slides, and the
    !> u_final and t_end errors fall as dt^2 (ratio 4 when dt halves; the linear
    !> interpolation error of a_g is <= A (2 pi/T)^2 dt^2/8, about 1.9e-5 A at dt = 2^-9 s).
    !> The cosine jumps from A to 0 at 2 T, which a record can only ramp over its last step
    !> (an impulse error of A dt/2): its errors fall as dt (ratio 2 when dt halves).
    subroutine test_cycles_record(error)
        type(test_error), allocatable, intent(out) :: error
        type(stickslip_result_t) :: rp, rr, r1
        type(pulse_t) :: p
        real(dp), allocatable :: acc(:)
        real(dp) :: eu(2), et(2), dt
        integer :: c, k, i, n, stat
        do c = 1, 2
            if (c == 1) then
                p = sine_cycle_pulse(1.0_dp, 1.0_dp, 2)
                call run_pulse(error, sine_cycle_pulse(1.0_dp, 1.0_dp), fric(0.3_dp, 0.3_dp), &
                               -1, r1, 'one sine cycle')
            else
                p = cosine_cycle_pulse(1.0_dp, 1.0_dp, 2)
                call run_pulse(error, cosine_cycle_pulse(1.0_dp, 1.0_dp), fric(0.3_dp, 0.3_dp), &
                               -1, r1, 'one cosine cycle')
            end if
            if (allocated(error)) return
            call run_pulse(error, p, fric(0.3_dp, 0.3_dp), -1, rp, 'two cycles')
            if (allocated(error)) return
            call check(error, size(rp%slides) > size(r1%slides) .and. rp%t_end > 1.0_dp, &
                       'two cycles slide more than one and end after T')
            if (allocated(error)) return
            do k = 1, 2
                dt = 1.0_dp / real(2**(8 + k), dp)
                n = nint(4.0_dp / dt) + 1
                allocate(acc(n))
                do i = 1, n
                    if (i - 1 < nint(2.0_dp / dt)) then
                        if (c == 1) then
                            acc(i) = sin(2.0_dp * pi * real(i - 1, dp) * dt)
                        else
                            acc(i) = cos(2.0_dp * pi * real(i - 1, dp) * dt)
                        end if
                    else
                        acc(i) = 0.0_dp
                    end if
                end do
                call stickslip_record(acc, dt, fric(0.3_dp, 0.3_dp), g_unit, rr, stat)
                deallocate(acc)
                call check(error, stat, SEISPULSE_SUCCESS, 'record status')
                if (allocated(error)) return
                call check(error, size(rr%slides), size(rp%slides), 'record: same slides')
                if (allocated(error)) return
                eu(k) = abs(rr%u_final - rp%u_final)
                et(k) = abs(rr%t_end - rp%t_end)
            end do
            if (c == 1) then
                call check(error, eu(1) < 1.0e-5_dp .and. et(1) < 1.0e-4_dp, &
                           'sine: close at dt = 2^-9')
                if (allocated(error)) return
                call check(error, eu(1) / eu(2), 4.0_dp, rtol=0.15_dp, &
                           message='sine: u_final error ratio')
                if (allocated(error)) return
                call check(error, et(1) / et(2), 4.0_dp, rtol=0.15_dp, &
                           message='sine: t_end error ratio')
            else
                call check(error, eu(1) < 1.0e-3_dp .and. et(1) < 1.0e-2_dp, &
                           'cosine: close at dt = 2^-9')
                if (allocated(error)) return
                call check(error, eu(1) / eu(2), 2.0_dp, rtol=0.1_dp, &
                           message='cosine: u_final error ratio')
                if (allocated(error)) return
                call check(error, et(1) / et(2), 2.0_dp, rtol=0.1_dp, &
                           message='cosine: t_end error ratio')
            end if
            if (allocated(error)) return
        end do
    end subroutine test_cycles_record

end module test_sliding_sim
