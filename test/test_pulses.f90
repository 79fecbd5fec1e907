!> Pulses: closed forms against quad-precision printed formulas, published values,
!> exact limits, and adaptive Gauss-Legendre quadrature of a and v.
module test_pulses
    use, intrinsic :: iso_fortran_env, only: qp => real128
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_negative_inf, ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_pulses, only: exp_pulse, exp_pulse_point, exp_pulse_peaks, &
        exp_pulse_impulse_amplitude, pulse_t, pulse_validate, pulse_eval, pulse_at, &
        pulse_breaks, pulse_end_time, pulse_kind_from_name, pulse_kind_name, &
        exponential_pulse, half_sine_pulse, sine_cycle_pulse, cosine_cycle_pulse, &
        rectangular_pulse, triangular_pulse, ricker_pulse, mp_pulse, PULSE_NKINDS, &
        PULSE_EXPONENTIAL, PULSE_MP, pulse_accel, pulse_peak_accel, ricker_accel, &
        ricker_window, ricker_x_cut, mp_terms, mp_jerk_t, mp_jerk_of, mp_jerk, mp_jerk_slope, &
        exp_consts_t, exp_consts, pulse_from_params, PULSE_NPARAM, PULSE_PARAM_AMP, &
        PULSE_PARAM_DURATION, PULSE_PARAM_CYCLES, PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE
    use seispulse_special, only: sin_pi, tau_minus_sinpi
    use seispulse_pieces, only: piece_t, piece_iter_t, pulse_pieces_init, next_piece
    use testing, only: test_error, unit_test, new_unittest, check, same_bits
    implicit none
    private

    public :: collect_pulses

    real(qp), parameter :: piq = 3.14159265358979323846264338327950288_qp

    !> Betas of the cross-check grid, including the awkward corners.
    real(dp), parameter :: betas(*) = [-1.0e6_dp, -2000.0_dp, -709.0_dp, -40.0_dp, &
        -6.283185307179586_dp, -3.141592653589793_dp, -1.0_dp, -1.0e-3_dp, -1.0e-7_dp, &
        -1.0e-12_dp, 0.0_dp, 1.0e-12_dp, 1.0e-7_dp, 1.0e-3_dp, 1.0_dp, 3.141592653589793_dp, &
        6.283185307179586_dp, 40.0_dp, 699.9_dp, 700.1_dp, 709.5_dp, 2000.0_dp, 1.0e6_dp]

    ! integrand of the adaptive quadrature (test code: module state is fine here)
    type(pulse_t) :: quad_pulse
    integer :: quad_which = 1

contains

    subroutine collect_pulses(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('V_g published values (doc/pulses.md 1)', test_vg_published), &
                 new_unittest('V_g(beta) + V_g(-beta) = 1', test_vg_symmetry), &
                 new_unittest('exp pulse vs quad-precision Eq. 1.1b forms', test_exp_vs_quad), &
                 new_unittest('tiny |beta| to 1e-13 relative', test_exp_tiny_beta), &
                 new_unittest('beta = 0 is the triangle', test_exp_triangle), &
                 new_unittest('beta = -inf is the box', test_exp_box), &
                 new_unittest('beta = +inf is the spike', test_exp_spike), &
                 new_unittest('huge |beta|: finite, converging to the limits', test_exp_huge), &
                 new_unittest('full cycle: odd lobe, rest after 2 t_d', test_exp_full_cycle), &
                 new_unittest('peaks D_g and impulse normalization', test_exp_peaks), &
                 new_unittest('continuity at phase boundaries', test_continuity), &
                 new_unittest('v = int a, d = int v for every pulse', test_quadrature), &
                 new_unittest('classic pulses: closed-form values', test_classic_values), &
                 new_unittest('SI scaling and equivalent forms', test_si_equivalences), &
                 new_unittest('breaks and end times', test_breaks), &
                 new_unittest('names and kinds', test_names), &
                 new_unittest('bad input is a status naming the parameter', test_bad_input), &
                 new_unittest('pulse_accel = pulse_at acceleration', test_pulse_accel), &
                 new_unittest('Ricker: one underflow rule, window', test_ricker_cutoff), &
                 new_unittest('M&P jerk vs product-form derivatives', test_mp_jerk), &
                 new_unittest('peak acceleration vs a dense sample', test_peak_accel), &
                 new_unittest('cycles = 1: the single-cycle formulas, bit for bit', &
                              test_cycles_one_bits), &
                 new_unittest('n cycles: v, d vs composite Simpson, continuity at cycle ends', &
                              test_cycles_simpson), &
                 new_unittest('n cycles: monotone pieces at every extremum', test_cycles_pieces), &
                 new_unittest('n cycles: bad cycles refused naming cycles', test_cycles_bad)]
    end subroutine collect_pulses

    ! ---------------------------------------------------------------- references

    !> Printed half-lobe forms of doc/pulses.md section 1 (Eq. 1.1b convention) in quad precision:
    !> a = (1 - e^(2 b s))/(1 - e^b), v = c[s - (e^(2 b s) - 1)/(2 b)],
    !> u = c[s^2/2 - (e^(2 b s) - 1 - 2 b s)/(4 b^2)], for 0 <= s <= 1/2;
    !> the falling half by V - v(1 - s), V (s - 1/2) + u(1 - s).
    subroutine ref_exp_half(tau, beta, a, v, d)
        real(dp), intent(in) :: tau, beta
        real(qp), intent(out) :: a, v, d
        real(qp) :: b, c, s, e, vg
        b = real(beta, qp)
        c = 1 / (1 - exp(b))
        vg = c + 1 / b
        if (tau <= 0.5_dp) then
            s = real(tau, qp)
        else
            s = 1 - real(tau, qp)
        end if
        e = exp(2 * b * s)
        a = (1 - e) * c
        v = c * (s - (e - 1) / (2 * b))
        d = c * (s * s / 2 - (e - 1 - 2 * b * s) / (4 * b * b))
        if (tau > 0.5_dp) then
            v = vg - v
            d = vg * (real(tau, qp) - 0.5_qp) + d
        end if
    end subroutine ref_exp_half

    ! ---------------------------------------------------------------- tests

    subroutine test_vg_published(error)
        type(test_error), allocatable, intent(out) :: error
        ! doc/pulses.md section 1, table of V_g/(A_g t_d) (10 digits)
        real(dp), parameter :: b(6) = [-6.283185307179586_dp, -3.141592653589793_dp, -1.0_dp, &
                                       1.0_dp, 3.141592653589793_dp, 6.283185307179586_dp]
        real(dp), parameter :: vref(6) = [0.8427159935_dp, 0.7268558192_dp, 0.5819767069_dp, &
                                          0.4180232931_dp, 0.2731441808_dp, 0.1572840065_dp]
        real(dp) :: vg, dg
        integer :: i, stat
        do i = 1, 6
            call exp_pulse_peaks(b(i), .false., vg, dg, stat)
            call check(error, vg, vref(i), atol=6.0e-11_dp, message='V_g')
            if (allocated(error)) return
        end do
    end subroutine test_vg_published

    subroutine test_vg_symmetry(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: v1, v2, dg
        integer :: i, stat
        do i = 1, size(betas)
            call exp_pulse_peaks(betas(i), .false., v1, dg, stat)
            call exp_pulse_peaks(-betas(i), .false., v2, dg, stat)
            call check(error, v1 + v2, 1.0_dp, rtol=2.0e-15_dp, message='beta = '//num(betas(i)))
            if (allocated(error)) return
        end do
    end subroutine test_vg_symmetry

    subroutine test_exp_vs_quad(error)
        type(test_error), allocatable, intent(out) :: error
        ! betas where quad precision evaluates the printed forms to >= 18 digits
        real(dp), parameter :: bq(*) = [-2000.0_dp, -709.0_dp, -40.0_dp, -6.283185307179586_dp, &
            -1.0_dp, -1.0e-3_dp, 1.0e-3_dp, 1.0_dp, 3.141592653589793_dp, 40.0_dp, 699.9_dp, &
            700.1_dp, 2000.0_dp]
        real(dp) :: tau, a, v, d, rt
        real(qp) :: ar, vr, dr
        integer :: i, j
        do i = 1, size(bq)
            ! the values have condition number ~ 2 |beta| with respect to tau and beta:
            ! rounding the inputs alone moves them by that many ulps
            rt = 1.0e-14_dp + 2.0_dp * abs(bq(i)) * epsilon(1.0_dp)
            do j = 0, 40
                tau = j / 40.0_dp
                call exp_pulse_point(tau, bq(i), .false., a, v, d)
                call ref_exp_half(tau, bq(i), ar, vr, dr)
                call check(error, a, real(ar, dp), rtol=rt, atol=1.0e-300_dp, &
                           message='a, beta = '//num(bq(i))//', tau = '//num(tau))
                if (allocated(error)) return
                call check(error, v, real(vr, dp), rtol=rt, atol=1.0e-300_dp, &
                           message='v, beta = '//num(bq(i))//', tau = '//num(tau))
                if (allocated(error)) return
                call check(error, d, real(dr, dp), rtol=rt, atol=1.0e-300_dp, &
                           message='d, beta = '//num(bq(i))//', tau = '//num(tau))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_exp_vs_quad

    !> Reference for tiny |beta|: the printed v and d cancel even in quad precision
    !> (c ~ 1/beta times a difference of nearly equal terms), but the printed a keeps
    !> >= 25 digits, and v = int_0^tau a, d = int_0^tau (tau - s) a(s) ds are smooth
    !> integrals that 8-point Gauss-Legendre per half-lobe gets to ~1e-16.
    subroutine ref_exp_by_quadrature(tau, beta, a, v, d)
        real(dp), intent(in) :: tau, beta
        real(qp), intent(out) :: a, v, d
        real(qp), parameter :: xg(4) = [0.1834346424956498049394761_qp, &
            0.5255324099163289858177390_qp, 0.7966664774136267395915539_qp, &
            0.9602898564975362316835609_qp]
        real(qp), parameter :: wg(4) = [0.3626837833783619829651504_qp, &
            0.3137066458778872873379622_qp, 0.2223810344533744705443560_qp, &
            0.1012285362903762591525314_qp]
        real(qp) :: t, x0, x1, c, h, sg, ag
        integer :: piece, k, side
        t = real(tau, qp)
        a = acc(t)
        v = 0
        d = 0
        do piece = 1, 2
            x0 = (piece - 1) * 0.5_qp
            x1 = min(t, piece * 0.5_qp)
            if (x1 <= x0) cycle
            c = (x0 + x1) / 2
            h = (x1 - x0) / 2
            do k = 1, 4
                do side = -1, 1, 2
                    sg = c + side * h * xg(k)
                    ag = acc(sg)
                    v = v + h * wg(k) * ag
                    d = d + h * wg(k) * (t - sg) * ag
                end do
            end do
        end do

    contains

        real(qp) function acc(s)
            real(qp), intent(in) :: s
            real(qp) :: b
            b = real(beta, qp)
            acc = (1 - exp(2 * b * min(s, 1 - s))) / (1 - exp(b))
        end function acc

    end subroutine ref_exp_by_quadrature

    subroutine test_exp_tiny_beta(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: bt(*) = [-9.9e-7_dp, -1.0e-7_dp, 1.0e-7_dp, 9.9e-7_dp]
        real(dp) :: tau, a, v, d
        real(qp) :: ar, vr, dr
        integer :: i, j
        do i = 1, size(bt)
            do j = 1, 20
                tau = j / 20.0_dp - 0.013_dp
                call exp_pulse_point(tau, bt(i), .false., a, v, d)
                call ref_exp_by_quadrature(tau, bt(i), ar, vr, dr)
                call check(error, a, real(ar, dp), rtol=1.0e-13_dp, message='a')
                if (allocated(error)) return
                call check(error, v, real(vr, dp), rtol=1.0e-13_dp, message='v')
                if (allocated(error)) return
                call check(error, d, real(dr, dp), rtol=1.0e-13_dp, message='d')
                if (allocated(error)) return
            end do
        end do
        ! and beta so small that it underflows in any printed form
        call exp_pulse_point(0.3_dp, 1.0e-300_dp, .false., a, v, d)
        call check(error, [a, v, d], [0.6_dp, 0.09_dp, 0.009_dp], rtol=1.0e-15_dp)
    end subroutine test_exp_tiny_beta

    subroutine test_exp_triangle(error)
        type(test_error), allocatable, intent(out) :: error
        ! beta = 0 (doc/pulses.md section 1): a = 2 tau, v = tau^2, u = tau^3/3 on [0, 1/2];
        ! mirror on [1/2, 1]: v = 1/2 - (1 - tau)^2, u = (tau - 1/2)/2 + (1 - tau)^3/3
        real(dp) :: tau, a, v, d, s
        integer :: j
        do j = 0, 20
            tau = j / 20.0_dp
            call exp_pulse_point(tau, 0.0_dp, .false., a, v, d)
            if (tau <= 0.5_dp) then
                call check(error, [a, v, d], [2 * tau, tau**2, tau**3 / 3], rtol=2.0e-16_dp)
            else
                s = 1 - tau
                call check(error, [a, v, d], [2 * s, 0.5_dp - s**2, (tau - 0.5_dp) / 2 + s**3 / 3], &
                           rtol=4.0e-16_dp)
            end if
            if (allocated(error)) return
        end do
    end subroutine test_exp_triangle

    subroutine test_exp_box(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: ninf, a, v, d
        ninf = ieee_value(ninf, ieee_negative_inf)
        call exp_pulse_point(0.0_dp, ninf, .false., a, v, d)
        call check(error, [a, v, d], [1.0_dp, 0.0_dp, 0.0_dp], message='tau = 0 (right-continuous)')
        if (allocated(error)) return
        call exp_pulse_point(0.6_dp, ninf, .false., a, v, d)
        call check(error, [a, v, d], [1.0_dp, 0.6_dp, 0.18_dp], rtol=1.0e-15_dp)
        if (allocated(error)) return
        call exp_pulse_point(3.0_dp, ninf, .false., a, v, d)
        call check(error, [a, v, d], [0.0_dp, 1.0_dp, 2.5_dp], rtol=1.0e-15_dp)
        if (allocated(error)) return
        call exp_pulse_point(1.5_dp, ninf, .true., a, v, d)
        call check(error, [a, v, d], [-1.0_dp, 0.5_dp, 0.875_dp], rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! the limit of finite beta: beta = -1e6 is the box to 1e-6 in v and d
        call exp_pulse_point(0.6_dp, -1.0e6_dp, .false., a, v, d)
        call check(error, [a, v, d], [1.0_dp, 0.6_dp, 0.18_dp], rtol=3.0e-6_dp)
    end subroutine test_exp_box

    subroutine test_exp_spike(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: pinf, a, v, d
        pinf = ieee_value(pinf, ieee_positive_inf)
        call exp_pulse_point(0.5_dp, pinf, .false., a, v, d)
        call check(error, [a, v, d], [1.0_dp, 0.0_dp, 0.0_dp], atol=0.0_dp)
        if (allocated(error)) return
        call exp_pulse_point(0.49_dp, pinf, .false., a, v, d)
        call check(error, [a, v, d], [0.0_dp, 0.0_dp, 0.0_dp], atol=0.0_dp)
        if (allocated(error)) return
        call exp_pulse_point(1.5_dp, pinf, .true., a, v, d)
        call check(error, [a, v, d], [-1.0_dp, 0.0_dp, 0.0_dp], atol=0.0_dp)
        if (allocated(error)) return
        ! beta = 1e6: the peak is still exactly 1 at the centre, the area ~ 1/beta
        call exp_pulse_point(0.5_dp, 1.0e6_dp, .false., a, v, d)
        call check(error, a, 1.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call exp_pulse_point(1.0_dp, 1.0e6_dp, .false., a, v, d)
        call check(error, v, 1.0e-6_dp, rtol=1.0e-15_dp, message='V_g ~ 1/beta')
    end subroutine test_exp_spike

    subroutine test_exp_huge(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: tau, a, v, d
        integer :: i, j
        logical :: full
        do i = 1, size(betas)
            do j = -2, 50
                tau = j / 20.0_dp + 1.0e-3_dp
                full = mod(j, 2) == 0
                call exp_pulse_point(tau, betas(i), full, a, v, d)
                call check(error, ieee_is_finite(a) .and. ieee_is_finite(v) .and. &
                           ieee_is_finite(d), 'finite at beta = '//num(betas(i)))
                if (allocated(error)) return
                call check(error, abs(a) <= 1.0_dp .and. v >= 0.0_dp .and. v <= 1.0_dp &
                           .and. d >= 0.0_dp, 'bounds at beta = '//num(betas(i)))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_exp_huge

    subroutine test_exp_full_cycle(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: tau, a1, v1, d1, a2, v2, d2, vg, dg
        integer :: i, j, stat
        do i = 1, size(betas)
            call exp_pulse_peaks(betas(i), .true., vg, dg, stat)
            do j = 1, 19
                tau = j / 20.0_dp
                call exp_pulse_point(tau, betas(i), .true., a1, v1, d1)
                call exp_pulse_point(2 - tau, betas(i), .true., a2, v2, d2)
                ! a odd about tau = 1, v even, d(tau) + d(2 - tau) = V_g
                ! 2 - tau is rounded: allow the condition number ~ |beta|
                call check(error, [a2, v2, d1 + d2], [-a1, v1, vg], &
                           rtol=4.0e-15_dp + 4.0_dp * abs(betas(i)) * epsilon(1.0_dp), &
                           atol=1.0e-300_dp, message='beta = '//num(betas(i)))
                if (allocated(error)) return
            end do
            call exp_pulse_point(2.7_dp, betas(i), .true., a1, v1, d1)
            call check(error, [a1, v1, d1], [0.0_dp, 0.0_dp, dg], rtol=1.0e-15_dp, &
                       message='at rest after 2 t_d, beta = '//num(betas(i)))
            if (allocated(error)) return
        end do
    end subroutine test_exp_full_cycle

    subroutine test_exp_peaks(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: vg, dg, a, v, d, amp, ninf, pinf
        integer :: stat
        call exp_pulse_peaks(-2.0_dp, .false., vg, dg, stat)
        call exp_pulse_point(1.0_dp, -2.0_dp, .false., a, v, d)
        call check(error, [vg, dg], [v, d], rtol=1.0e-15_dp, message='half: D_g = u_g(t_d)')
        if (allocated(error)) return
        call exp_pulse_peaks(-2.0_dp, .true., vg, dg, stat)
        call exp_pulse_point(2.0_dp, -2.0_dp, .true., a, v, d)
        call check(error, dg, d, rtol=1.0e-15_dp, message='full: D_g = u_g(2 t_d)')
        if (allocated(error)) return
        ! k(beta) = 1/(1 - e^beta) + 1/beta at beta = -2 in quad precision
        call check(error, vg, real(1 / (1 - exp(-2.0_qp)) - 0.5_qp, dp), rtol=1.0e-15_dp)
        if (allocated(error)) return
        call exp_pulse_impulse_amplitude(-2.0_dp, amp, stat)
        call check(error, amp * vg, 1.0_dp, rtol=1.0e-15_dp, message='unit impulse')
        if (allocated(error)) return
        ninf = ieee_value(ninf, ieee_negative_inf)
        pinf = ieee_value(pinf, ieee_positive_inf)
        call exp_pulse_impulse_amplitude(ninf, amp, stat)
        call check(error, amp, 1.0_dp, message='box: area t_d')
        if (allocated(error)) return
        call exp_pulse_impulse_amplitude(0.0_dp, amp, stat)
        call check(error, amp, 2.0_dp, message='triangle: area t_d/2')
        if (allocated(error)) return
        call exp_pulse_impulse_amplitude(pinf, amp, stat)
        call check(error, amp, pinf, message='spike: delta function')
    end subroutine test_exp_peaks

    subroutine test_continuity(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: bounds(*) = [0.5_dp, 1.0_dp, 1.5_dp, 2.0_dp]
        real(dp) :: al, vl, dl, ar, vr, dr, h, b
        integer :: i, j
        do i = 1, size(betas)
            b = betas(i)
            if (abs(b) > 1.0e3_dp) cycle   ! steeper than any step h below
            do j = 1, size(bounds)
                h = 1.0e-9_dp
                call exp_pulse_point(bounds(j) - h, b, .true., al, vl, dl)
                call exp_pulse_point(bounds(j) + h, b, .true., ar, vr, dr)
                ! |da/dtau| <= 2 |beta| + 2 on each side (a jumps by exactly 4h at tau = 1
                ! when beta -> 0), |dv/dtau| <= 1, |dd/dtau| <= 1
                call check(error, ar, al, atol=(4.0_dp * abs(b) + 5.0_dp) * h, &
                           message='a at tau = '//num(bounds(j))//', beta = '//num(b))
                if (allocated(error)) return
                call check(error, [vr, dr], [vl, dl], atol=3.0_dp * h, &
                           message='v, d at tau = '//num(bounds(j))//', beta = '//num(b))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_continuity

    !> All pulse kinds used by the SI tests.
    function sample_pulses() result(ps)
        type(pulse_t), allocatable :: ps(:)
        ps = [exponential_pulse(3.0_dp, 0.4_dp, -3.0_dp, .false.), &
              exponential_pulse(3.0_dp, 0.4_dp, -3.0_dp, .true.), &
              exponential_pulse(-2.0_dp, 0.7_dp, 5.0_dp, .true.), &
              exponential_pulse(2.0_dp, 0.7_dp, 1.0e-9_dp, .false.), &
              exponential_pulse(2.0_dp, 0.5_dp, -400.0_dp, .true.), &
              exponential_pulse(2.0_dp, 0.5_dp, 900.0_dp, .false.), &
              half_sine_pulse(4.0_dp, 0.6_dp), &
              sine_cycle_pulse(2.5_dp, 1.2_dp), &
              cosine_cycle_pulse(-1.5_dp, 0.8_dp), &
              sine_cycle_pulse(2.5_dp, 1.2_dp, 3), &
              cosine_cycle_pulse(-1.5_dp, 0.8_dp, 3), &
              rectangular_pulse(1.0_dp, 0.3_dp), &
              triangular_pulse(2.0_dp, 0.9_dp, 0.25_dp), &
              triangular_pulse(2.0_dp, 0.9_dp, 0.0_dp), &
              triangular_pulse(2.0_dp, 0.9_dp, 1.0_dp), &
              ricker_pulse(5.0_dp, 2.0_dp, 0.75_dp), &
              ricker_pulse(5.0_dp, 2.0_dp, 0.1_dp), &
              mp_pulse(0.8_dp, 1.5_dp, 2.3_dp, 70.0_dp, 1.0_dp), &
              mp_pulse(0.5_dp, 0.4_dp, 1.0000001_dp, -90.0_dp, 1.25_dp)]
    end function sample_pulses

    function integrand(t) result(y)
        real(dp), intent(in) :: t
        real(dp) :: y
        real(dp) :: a, v, d
        call pulse_at(quad_pulse, t, a, v, d)
        if (quad_which == 1) then
            y = a
        else
            y = v
        end if
    end function integrand

    !> 8-point Gauss-Legendre on [x0, x1].
    function gauss8(x0, x1) result(s)
        real(dp), intent(in) :: x0, x1
        real(dp) :: s
        real(dp), parameter :: xg(4) = [0.1834346424956498049394761_dp, &
            0.5255324099163289858177390_dp, 0.7966664774136267395915539_dp, &
            0.9602898564975362316835609_dp]
        real(dp), parameter :: wg(4) = [0.3626837833783619829651504_dp, &
            0.3137066458778872873379622_dp, 0.2223810344533744705443560_dp, &
            0.1012285362903762591525314_dp]
        real(dp) :: c, h
        integer :: k
        c = 0.5_dp * (x0 + x1)
        h = 0.5_dp * (x1 - x0)
        s = 0.0_dp
        do k = 1, 4
            s = s + wg(k) * (integrand(c - h * xg(k)) + integrand(c + h * xg(k)))
        end do
        s = s * h
    end function gauss8

    recursive function adapt(x0, x1, whole, tol, depth) result(s)
        real(dp), intent(in) :: x0, x1, whole, tol
        integer, intent(in) :: depth
        real(dp) :: s, xm, left, right
        xm = 0.5_dp * (x0 + x1)
        left = gauss8(x0, xm)
        right = gauss8(xm, x1)
        ! per-panel tolerance, not halved: the panels are few and the floor is rounding
        if (abs(left + right - whole) <= tol .or. depth >= 30) then
            s = left + right
        else
            s = adapt(x0, xm, left, tol, depth + 1) + adapt(xm, x1, right, tol, depth + 1)
        end if
    end function adapt

    !> Integral of a (which = 1) or v (which = 2) from 0 to t, piecewise between breaks.
    function integral_to(p, which, t, tol) result(s)
        type(pulse_t), intent(in) :: p
        integer, intent(in) :: which
        real(dp), intent(in) :: t, tol
        real(dp) :: s, breaks(5), x0, x1
        integer :: nb, k
        quad_pulse = p
        quad_which = which
        call pulse_breaks(p, breaks, nb)
        s = 0.0_dp
        x0 = 0.0_dp
        do k = 1, nb + 1
            if (k <= nb) then
                x1 = min(max(breaks(k), 0.0_dp), t)
            else
                x1 = t
            end if
            if (x1 > x0) then
                s = s + adapt(x0, x1, gauss8(x0, x1), tol, 0)
                x0 = x1
            end if
        end do
    end function integral_to

    subroutine test_quadrature(error)
        type(test_error), allocatable, intent(out) :: error
        type(pulse_t), allocatable :: ps(:)
        real(dp) :: t, tend, a, v, d, vscale, dscale, iv, id
        integer :: i, j
        allocate(ps, source=sample_pulses())
        do i = 1, size(ps)
            tend = pulse_end_time(ps(i))
            if (.not. ieee_is_finite(tend)) tend = ps(i)%t0 + 2.0_dp / ps(i)%freq
            vscale = 0.0_dp
            dscale = 0.0_dp
            do j = 0, 100
                call pulse_at(ps(i), 1.2_dp * tend * j / 100.0_dp, a, v, d)
                vscale = max(vscale, abs(v))
                dscale = max(dscale, abs(d))
            end do
            do j = 1, 12
                t = 1.2_dp * tend * j / 12.0_dp - 0.0137_dp * tend
                call pulse_at(ps(i), t, a, v, d)
                iv = integral_to(ps(i), 1, t, 1.0e-16_dp * vscale)
                id = integral_to(ps(i), 2, t, 1.0e-16_dp * dscale)
                call check(error, v, iv, atol=1.0e-13_dp * vscale, &
                           message='v = int a, pulse '//pulse_kind_name(ps(i)%kind)//' #' &
                           //num(real(i, dp))//', t = '//num(t))
                if (allocated(error)) return
                call check(error, d, id, atol=1.0e-13_dp * dscale, &
                           message='d = int v, pulse '//pulse_kind_name(ps(i)%kind)//' #' &
                           //num(real(i, dp))//', t = '//num(t))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_quadrature

    subroutine test_classic_values(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a, v, d, pi_
        pi_ = real(piq, dp)
        ! half-sine, A = 4, T = 0.6: v(T) = 2 A T/pi, d(T) = A T^2/pi
        call pulse_at(half_sine_pulse(4.0_dp, 0.6_dp), 0.6_dp, a, v, d)
        call check(error, [v, d], [4.8_dp / pi_, 1.44_dp / pi_], rtol=1.0e-15_dp, message='half-sine')
        if (allocated(error)) return
        ! one-cycle sine: v returns to 0, residual d = A T^2/(2 pi) (fling step)
        call pulse_at(sine_cycle_pulse(2.5_dp, 1.2_dp), 5.0_dp, a, v, d)
        call check(error, [a, v, d], [0.0_dp, 0.0_dp, 2.5_dp * 1.44_dp / (2 * pi_)], &
                   rtol=1.0e-15_dp, message='sine cycle')
        if (allocated(error)) return
        ! one-cycle cosine: v and d return to 0; peak d = A T^2/(2 pi^2) at T/2
        call pulse_at(cosine_cycle_pulse(-1.5_dp, 0.8_dp), 0.4_dp, a, v, d)
        call check(error, [a, v, d], [1.5_dp, 0.0_dp, -1.5_dp * 0.64_dp / (2 * pi_**2)], &
                   rtol=1.0e-15_dp, atol=1.0e-16_dp, message='cosine cycle')
        if (allocated(error)) return
        ! triangle: v(T) = A T/2, d(T) = A T^2 (2 - r)/6
        call pulse_at(triangular_pulse(2.0_dp, 0.9_dp, 0.25_dp), 0.9_dp, a, v, d)
        call check(error, [v, d], [0.9_dp, 2.0_dp * 0.81_dp * 1.75_dp / 6], rtol=1.0e-15_dp, &
                   message='triangle')
        if (allocated(error)) return
        ! Ricker: peak a_p at t0; v(t0) = (a_p/f) tau0 e^(-pi^2 tau0^2) (truncation)
        call pulse_at(ricker_pulse(5.0_dp, 2.0_dp, 0.75_dp), 0.75_dp, a, v, d)
        call check(error, [a, v], [5.0_dp, 2.5_dp * real(1.5_qp * exp(-piq**2 * 2.25_qp), dp)], &
                   rtol=1.0e-14_dp, message='Ricker')
        if (allocated(error)) return
        ! M&P with nu = 0: v(t0) = A (envelope 1, carrier 1), a(t0) = 0
        call pulse_at(mp_pulse(0.8_dp, 1.5_dp, 2.3_dp, 0.0_dp, 1.0_dp), 1.0_dp, a, v, d)
        call check(error, [a, v], [0.0_dp, 0.8_dp], rtol=1.0e-15_dp, atol=1.0e-15_dp, &
                   message='M&P peak')
        if (allocated(error)) return
        ! M&P nu = 0: int of v over the window = A/(2 pi f) * sin(pi gamma) * gamma^2
        !   / (gamma^2 - 1)... evaluated here in quad precision from the three cosines
        call pulse_at(mp_pulse(0.8_dp, 1.5_dp, 2.3_dp, 0.0_dp, 1.0_dp), 9.0_dp, a, v, d)
        call check(error, d, real(mp_final_disp(0.8_qp, 1.5_qp, 2.3_qp), dp), rtol=1.0e-14_dp, &
                   message='M&P residual displacement')
    end subroutine test_classic_values

    !> Residual displacement of the M&P pulse with nu = 0, integrated in closed form
    !> in quad precision: int_{-g/2}^{g/2} (1 + cos(2 pi x/g)) cos(2 pi x)/2 dx, in A/f.
    function mp_final_disp(amp, f, g) result(dfin)
        real(qp), intent(in) :: amp, f, g
        real(qp) :: dfin, k1, k2, k3
        k1 = 2 * piq
        k2 = 2 * piq * (1 + 1 / g)
        k3 = 2 * piq * (1 - 1 / g)
        dfin = sin(k1 * g / 2) / k1 + 0.5_qp * (sin(k2 * g / 2) / k2 + sin(k3 * g / 2) / k3)
        dfin = amp / f * dfin
    end function mp_final_disp

    subroutine test_si_equivalences(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: t(7), a1(7), v1(7), d1(7), a2(7), v2(7), d2(7), tau(7)
        integer :: stat
        t = [-0.1_dp, 0.0_dp, 0.05_dp, 0.2_dp, 0.3_dp, 0.55_dp, 1.0_dp]
        ! rectangular pulse = exponential with beta = -inf
        call pulse_eval(rectangular_pulse(2.0_dp, 0.4_dp), t, a1, v1, d1, stat)
        call pulse_eval(exponential_pulse(2.0_dp, 0.4_dp, ieee_value(1.0_dp, ieee_negative_inf), &
                        .false.), t, a2, v2, d2, stat)
        call check(error, [a1, v1, d1], [a2, v2, d2], rtol=1.0e-15_dp, message='box')
        if (allocated(error)) return
        ! symmetric triangle (different code path) = exponential with beta = 0
        call pulse_eval(triangular_pulse(2.0_dp, 0.4_dp, 0.5_dp), t, a1, v1, d1, stat)
        call pulse_eval(exponential_pulse(2.0_dp, 0.4_dp, 0.0_dp, .false.), t, a2, v2, d2, stat)
        call check(error, [a1, v1, d1], [a2, v2, d2], rtol=1.0e-15_dp, atol=1.0e-17_dp, &
                   message='triangle')
        if (allocated(error)) return
        ! SI = A (a~, t_d v~, t_d^2 d~) of the dimensionless core
        call pulse_eval(exponential_pulse(9.81_dp * 0.3_dp, 0.4_dp, -2.0_dp, .true.), t, &
                        a1, v1, d1, stat)
        tau = t / 0.4_dp
        call exp_pulse(tau, [-2.0_dp], .true., a2, v2, d2, stat)
        call check(error, [a1, v1, d1], 9.81_dp * 0.3_dp * [a2, 0.4_dp * v2, 0.16_dp * d2], &
                   rtol=1.0e-15_dp, message='exponential SI')
    end subroutine test_si_equivalences

    subroutine test_breaks(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: b(5)
        integer :: nb
        call pulse_breaks(exponential_pulse(1.0_dp, 0.4_dp, 1.0_dp, .true.), b, nb)
        call check(error, b(1:nb), [0.0_dp, 0.2_dp, 0.4_dp, 0.6_dp, 0.8_dp], rtol=1.0e-15_dp)
        if (allocated(error)) return
        call pulse_breaks(mp_pulse(1.0_dp, 2.0_dp, 3.0_dp, 0.0_dp, 1.0_dp), b, nb)
        call check(error, b(1:nb), [0.25_dp, 1.75_dp], rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, pulse_end_time(triangular_pulse(1.0_dp, 0.9_dp, 0.3_dp)), 0.9_dp)
        if (allocated(error)) return
        call check(error, .not. ieee_is_finite(pulse_end_time(ricker_pulse(1.0_dp, 1.0_dp, &
                   1.5_dp))), 'Ricker never ends')
    end subroutine test_breaks

    subroutine test_names(error)
        type(test_error), allocatable, intent(out) :: error
        integer :: k, kind, stat
        character(len=200) :: msg
        do k = 1, PULSE_NKINDS
            call pulse_kind_from_name(pulse_kind_name(k), kind, stat)
            call check(error, kind, k, 'round trip '//pulse_kind_name(k))
            if (allocated(error)) return
        end do
        call pulse_kind_from_name('  MP', kind, stat)
        call check(error, kind, PULSE_MP, 'alias, case and blanks')
        if (allocated(error)) return
        call pulse_kind_from_name('Exp', kind, stat)
        call check(error, kind, PULSE_EXPONENTIAL, 'alias exp')
        if (allocated(error)) return
        msg = ''
        call pulse_kind_from_name('gabor', kind, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'ricker') > 0, &
                   'unknown name lists the allowed ones: '//trim(msg))
    end subroutine test_names

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: nan, pinf, a(2), v(2), d(2), vg, dg
        integer :: stat
        character(len=200) :: msg
        nan = ieee_value(nan, ieee_quiet_nan)
        pinf = ieee_value(pinf, ieee_positive_inf)
        call expect(exponential_pulse(1.0_dp, 1.0_dp, nan, .false.), 'beta')
        if (allocated(error)) return
        call expect(exponential_pulse(1.0_dp, -1.0_dp, 0.0_dp, .false.), 'duration')
        if (allocated(error)) return
        call expect(exponential_pulse(pinf, 1.0_dp, 0.0_dp, .false.), 'amp')
        if (allocated(error)) return
        call expect(triangular_pulse(1.0_dp, 1.0_dp, 1.5_dp), 'peak_frac')
        if (allocated(error)) return
        call expect(ricker_pulse(1.0_dp, 0.0_dp, 1.0_dp), 'freq')
        if (allocated(error)) return
        call expect(ricker_pulse(1.0_dp, 1.0_dp, -1.0_dp), 't0')
        if (allocated(error)) return
        call expect(mp_pulse(1.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 1.0_dp), 'gamma')
        if (allocated(error)) return
        call expect(mp_pulse(1.0_dp, 1.0_dp, 2.0_dp, nan, 1.0_dp), 'nu_deg')
        if (allocated(error)) return
        call expect(mp_pulse(1.0_dp, 1.0_dp, 2.0_dp, 0.0_dp, 0.5_dp), 't0')
        if (allocated(error)) return
        msg = ''
        call exp_pulse([0.1_dp, nan], [0.0_dp], .false., a, v, d, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:3) == 'tau', trim(msg))
        if (allocated(error)) return
        call exp_pulse([0.1_dp, 0.2_dp], [0.0_dp, 1.0_dp, 2.0_dp], .false., a, v, d, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:4) == 'beta', trim(msg))
        if (allocated(error)) return
        call pulse_eval(half_sine_pulse(1.0_dp, 1.0_dp), [0.0_dp, pinf], a, v, d, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:1) == 't', trim(msg))
        if (allocated(error)) return
        call exp_pulse_peaks(nan, .false., vg, dg, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:4) == 'beta', trim(msg))

    contains

        subroutine expect(p, name)
            type(pulse_t), intent(in) :: p
            character(len=*), intent(in) :: name
            msg = ''
            call pulse_validate(p, stat, msg)
            call check(error, stat == SEISPULSE_INVALID_INPUT .and. &
                       msg(1:len(name) + 1) == name//' ', 'expected "'//name//' ...", got "' &
                       //trim(msg)//'"')
        end subroutine expect

    end subroutine test_bad_input

    ! ---------------------------------------------------------------- acceleration only

    !> pulse_accel agrees with pulse_at to rounding inside every pulse (the fast forms use
    !> sin(2 pi t/T) and x = pi f (t - t0)), and is pulse_at's value before t = 0 and
    !> from the end of a timed pulse on.
    subroutine test_pulse_accel(error)
        type(test_error), allocatable, intent(out) :: error
        type(pulse_t) :: ps(10)
        type(exp_consts_t) :: c
        real(dp) :: t, a, v, d, a1, a2, t_end
        integer :: k, i
        ps = [exponential_pulse(2.0_dp, 0.8_dp, 1.5_dp, .true.), half_sine_pulse(3.0_dp, 0.6_dp), &
              sine_cycle_pulse(-2.0_dp, 0.7_dp), cosine_cycle_pulse(1.5_dp, 0.9_dp), &
              rectangular_pulse(2.5_dp, 0.4_dp), triangular_pulse(1.0_dp, 1.1_dp, 0.3_dp), &
              ricker_pulse(4.0_dp, 1.7_dp, 1.1_dp), ricker_pulse(-1.0_dp, 0.3_dp, 0.0_dp), &
              mp_pulse(0.6_dp, 1.2_dp, 2.4_dp, 40.0_dp, 1.5_dp), &
              exponential_pulse(1.0_dp, 0.5_dp, -3.0_dp, .false.)]
        do k = 1, size(ps)
            c = exp_consts(ps(k)%beta)
            t_end = pulse_end_time(ps(k))
            do i = -20, 400
                t = 0.00731_dp * real(i, dp)
                call pulse_at(ps(k), t, a, v, d)
                a1 = pulse_accel(ps(k), t)
                a2 = pulse_accel(ps(k), t, c)
                call check(error, same_bits(a2, a1), 'consts changes pulse_accel, kind ' &
                           //pulse_kind_name(ps(k)%kind)//' t = '//num(t))
                if (allocated(error)) return
                if (t < 0.0_dp .or. t >= t_end) then
                    call check(error, same_bits(a1, a), 'pulse_accel /= pulse_at outside the ' &
                               //'pulse, '//pulse_kind_name(ps(k)%kind)//' t = '//num(t))
                else
                    call check(error, a1, a, rtol=1.0e-14_dp, atol=1.0e-14_dp * abs(ps(k)%amp), &
                               message=pulse_kind_name(ps(k)%kind)//' t = '//num(t))
                end if
                if (allocated(error)) return
            end do
            ! exactly at the end of a timed pulse: the ground is at rest
            if (t_end < huge(t_end)) then
                call check(error, .not. abs(pulse_accel(ps(k), t_end)) > 0.0_dp, &
                           'a(t_end) /= 0, '//pulse_kind_name(ps(k)%kind))
                if (allocated(error)) return
            end if
        end do
    end subroutine test_pulse_accel

    !> The Ricker cut-off is the underflow of e^(-w), w = (pi f (t - t0))^2: e^(-745.2) is
    !> already 0 in double precision, so the formula itself is 0 for every w >= 750 (the
    !> branch only makes it +0 and keeps w = +inf from giving NaN), and the |x| < 30 cut of
    !> the former quadrature copy (w < 900) changed nothing but the sign of a zero.
    !> Values against quad precision; the window ends where |a| < 1e-40 a_p.
    subroutine test_ricker_cutoff(error)
        type(test_error), allocatable, intent(out) :: error
        type(pulse_t) :: p
        real(dp) :: t, w, a, x, ts, te, v, d, big
        real(qp) :: xq, aq
        integer :: i
        p = ricker_pulse(3.0_dp, 1.3_dp, 2.0_dp)
        w = 745.2_dp
        call check(error, .not. exp(-w) > 0.0_dp, 'exp(-745.2) should underflow to 0')
        if (allocated(error)) return
        w = 745.0_dp
        call check(error, exp(-w) > 0.0_dp, 'exp(-745) should be subnormal, not 0')
        if (allocated(error)) return
        do i = 0, 300
            ! w from 700 to 1000: the formula and ricker_accel agree as numbers
            w = 700.0_dp + real(i, dp)
            t = p%t0 + sqrt(w) / (piq_dp() * p%freq)
            x = piq_dp() * p%freq * (t - p%t0)
            a = ricker_accel(p, t)
            call check(error, a, p%amp * (1.0_dp - 2.0_dp * x * x) * exp(-x * x), rtol=0.0_dp, &
                       message='ricker_accel /= formula at w = '//num(w))
            if (allocated(error)) return
            if (x * x >= 750.0_dp) then
                call check(error, same_bits(a, 0.0_dp), 'expected +0 at w = '//num(w))
                if (allocated(error)) return
            end if
        end do
        big = 1.0e150_dp   ! w ~ 1e300: finite (an infinite w is caught by the same branch)
        a = ricker_accel(p, big)
        call check(error, same_bits(a, 0.0_dp), 'a(1e150) should be +0')
        if (allocated(error)) return
        call pulse_at(p, big, a, v, d)
        call check(error, .not. abs(a) > 0.0_dp .and. ieee_is_finite(v) .and. ieee_is_finite(d), &
                   'pulse_at(1e150) should be a = 0, v and d finite')
        if (allocated(error)) return
        ! against quad precision inside the wavelet
        do i = -40, 40
            t = p%t0 + 0.05_dp * real(i, dp) / p%freq
            xq = piq * real(p%freq, qp) * (real(t, qp) - real(p%t0, qp))
            aq = real(p%amp, qp) * (1 - 2 * xq * xq) * exp(-xq * xq)
            call check(error, ricker_accel(p, t), real(aq, dp), rtol=1.0e-13_dp, &
                       atol=1.0e-15_dp, message='Ricker vs quad, t = '//num(t))
            if (allocated(error)) return
        end do
        ! the window: |x| <= ricker_x_cut, clipped at t = 0
        p = ricker_pulse(3.0_dp, 1.3_dp, 5.0_dp)
        call ricker_window(p, ts, te)
        call check(error, te, p%t0 + ricker_x_cut / (piq_dp() * p%freq), rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, ts, p%t0 - ricker_x_cut / (piq_dp() * p%freq), rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, abs(ricker_accel(p, te)) < 1.0e-40_dp * p%amp .and. &
                   abs(ricker_accel(p, te)) > 0.0_dp, '|a(te)| should be in (0, 1e-40 a_p)')
        if (allocated(error)) return
        call ricker_window(ricker_pulse(1.0_dp, 1.0_dp, 0.5_dp), ts, te)
        call check(error, same_bits(ts, 0.0_dp), 'window should start at t = 0')
    end subroutine test_ricker_cutoff

    !> mp_terms, and mp_jerk, mp_jerk_slope against the second and third derivatives of the
    !> printed product form v/A = (1 + cos(2 pi x/gamma)) cos(2 pi x + nu)/2, in quad precision.
    subroutine test_mp_jerk(error)
        type(test_error), allocatable, intent(out) :: error
        type(mp_jerk_t) :: f
        type(pulse_t) :: p
        real(dp) :: k(3), w(3), x, gam
        real(qp) :: u, e0, e1, e2, e3, c0, c1, c2, c3, j2, j3, tp, xq, nuq
        integer :: i, m
        real(dp), parameter :: gammas(3) = [1.05_dp, 2.3_dp, 17.0_dp]
        call mp_terms(2.0_dp, k, w)
        call check(error, k, [1.0_dp, 1.5_dp, 0.5_dp] * real(2 * piq, dp), rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, w, [0.5_dp, 0.25_dp, 0.25_dp], rtol=0.0_dp)
        if (allocated(error)) return
        do m = 1, size(gammas)
            gam = gammas(m)
            p = mp_pulse(0.7_dp, 1.3_dp, gam, -65.0_dp + 50.0_dp * m, gam)
            f = mp_jerk_of(p)
            nuq = real(p%nu_deg, qp) * piq / 180
            tp = 2 * piq
            u = tp / real(gam, qp)
            do i = -50, 50
                x = 0.5_dp * gam * real(i, dp) / 50.0_dp
                xq = real(x, qp)
                e0 = 1 + cos(u * xq)
                e1 = -u * sin(u * xq)
                e2 = -u * u * cos(u * xq)
                e3 = u**3 * sin(u * xq)
                c0 = cos(tp * xq + nuq)
                c1 = -tp * sin(tp * xq + nuq)
                c2 = -tp * tp * cos(tp * xq + nuq)
                c3 = tp**3 * sin(tp * xq + nuq)
                j2 = (e2 * c0 + 2 * e1 * c1 + e0 * c2) / 2
                j3 = (e3 * c0 + 3 * e2 * c1 + 3 * e1 * c2 + e0 * c3) / 2
                call check(error, mp_jerk(f, x), real(j2, dp), rtol=1.0e-12_dp, &
                           atol=1.0e-14_dp * 160.0_dp * (1.0_dp + abs(x)), &
                           message='jerk, gamma = '//num(gam)//' x = '//num(x))
                if (allocated(error)) return
                call check(error, mp_jerk_slope(f, x), real(j3, dp), rtol=1.0e-12_dp, &
                           atol=1.0e-14_dp * 1000.0_dp * (1.0_dp + abs(x)), &
                           message='jerk slope, gamma = '//num(gam)//' x = '//num(x))
                if (allocated(error)) return
                call check(error, same_bits(f%eval(x), mp_jerk(f, x)), 'eval /= mp_jerk')
                if (allocated(error)) return
            end do
        end do
    end subroutine test_mp_jerk

    !> pulse_peak_accel is at least the largest |a| of a dense sample of pulse_at and
    !> exceeds it by no more than the curvature allows; its time gives that value.
    subroutine test_peak_accel(error)
        type(test_error), allocatable, intent(out) :: error
        type(pulse_t) :: ps(5)
        real(dp) :: amax, tmax, t, a, v, d, best, t0, t1
        integer :: k, i, stat
        integer, parameter :: n = 200000
        ps = [mp_pulse(0.6_dp, 1.2_dp, 2.4_dp, 40.0_dp, 1.5_dp), &
              mp_pulse(0.3_dp, 0.5_dp, 1.2_dp, -120.0_dp, 1.3_dp), &
              mp_pulse(1.0_dp, 2.0_dp, 9.0_dp, 75.0_dp, 2.5_dp), &
              half_sine_pulse(-2.0_dp, 0.6_dp), ricker_pulse(2.0_dp, 1.0_dp, 1.0_dp)]
        do k = 1, size(ps)
            call pulse_peak_accel(ps(k), amax, tmax, stat)
            call check(error, stat == SEISPULSE_SUCCESS, 'pulse_peak_accel failed')
            if (allocated(error)) return
            call pulse_at(ps(k), tmax, a, v, d)
            call check(error, abs(a), amax, rtol=1.0e-13_dp, &
                       message='|a(t_max)| /= a_max, '//pulse_kind_name(ps(k)%kind))
            if (allocated(error)) return
            t0 = 0.0_dp
            t1 = 3.0_dp * max(ps(k)%t0, ps(k)%duration)
            if (ps(k)%kind == PULSE_MP) t1 = ps(k)%t0 + 0.5_dp * ps(k)%gamma / ps(k)%freq
            best = 0.0_dp
            do i = 0, n
                t = t0 + (t1 - t0) * real(i, dp) / real(n, dp)
                call pulse_at(ps(k), t, a, v, d)
                best = max(best, abs(a))
            end do
            call check(error, amax >= best * (1.0_dp - 1.0e-14_dp) .and. &
                       amax <= best * (1.0_dp + 5.0e-8_dp), 'a_max = '//num(amax) &
                       //' vs sample max '//num(best)//', '//pulse_kind_name(ps(k)%kind))
            if (allocated(error)) return
        end do
    end subroutine test_peak_accel

    !> pi (quad precision) rounded to double.
    pure function piq_dp() result(y)
        real(dp) :: y
        y = real(piq, dp)
    end function piq_dp

    function num(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: buf
        write(buf, '(g0.6)') x
        s = trim(adjustl(buf))
    end function num

    ! ---------------------------------------------------------------- n cycles

    !> cycles = 1 (the default, given, or packed) gives the formulas of the single cycle
    !> written out here as they were before cycles existed, bit for bit, inside the pulse
    !> and after it (sine: rest at d = A T^2/(2 pi); cosine: rest at 0).
    subroutine test_cycles_one_bits(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: amp = 2.5_dp, tp = 1.2_dp, pi_ = acos(-1.0_dp)
        type(pulse_t) :: ps(3), pc(3)
        real(dp) :: params(PULSE_NPARAM), t, tau, a, v, d, ea, ev, ed
        integer :: i, j
        params = 0.0_dp
        params(PULSE_PARAM_AMP) = amp
        params(PULSE_PARAM_DURATION) = tp
        params(PULSE_PARAM_CYCLES) = 1.0_dp
        ps = [sine_cycle_pulse(amp, tp), sine_cycle_pulse(amp, tp, 1), &
              pulse_from_params(PULSE_SINE_CYCLE, params)]
        pc = [cosine_cycle_pulse(amp, tp), cosine_cycle_pulse(amp, tp, 1), &
              pulse_from_params(PULSE_COSINE_CYCLE, params)]
        do j = 0, 300
            t = 1.5_dp * tp * real(j, dp) / 300.0_dp
            tau = t / tp
            do i = 1, 3
                call pulse_at(ps(i), t, a, v, d)
                if (tau < 1.0_dp) then
                    ea = amp * sin_pi(2.0_dp * tau)
                    ev = amp * (tp * (sin_pi(tau)**2 / pi_))
                    ed = amp * (tp * (tp * (tau_minus_sinpi(2.0_dp * tau) / (4.0_dp * pi_))))
                else
                    ea = 0.0_dp
                    ev = 0.0_dp
                    ed = amp * (tp * (tp * (0.5_dp / pi_)))
                end if
                call check(error, same_bits(a, ea) .and. same_bits(v, ev) .and. &
                           same_bits(d, ed), 'sine cycle #'//num(real(i, dp))//', t = '//num(t))
                if (allocated(error)) return
                call pulse_at(pc(i), t, a, v, d)
                if (tau < 1.0_dp) then
                    ea = amp * cos_pi_ref(2.0_dp * tau)
                    ev = amp * (tp * (sin_pi(2.0_dp * tau) / (2.0_dp * pi_)))
                    ed = amp * (tp * (tp * (sin_pi(tau)**2 / (2.0_dp * pi_ * pi_))))
                else
                    ea = 0.0_dp
                    ev = 0.0_dp
                    ed = 0.0_dp
                end if
                call check(error, same_bits(a, ea) .and. same_bits(v, ev) .and. &
                           same_bits(d, ed), 'cosine cycle #'//num(real(i, dp))//', t = '//num(t))
                if (allocated(error)) return
            end do
            call check(error, same_bits(pulse_end_time(ps(1)), tp), 'end time of one cycle')
            if (allocated(error)) return
        end do
    contains
        real(dp) function cos_pi_ref(x)
            use seispulse_special, only: cos_pi
            real(dp), intent(in) :: x
            cos_pi_ref = cos_pi(x)
        end function cos_pi_ref
    end subroutine test_cycles_one_bits

    !> n = 3 cycles: v and d against composite Simpson integration of a and v (2^14 panels
    !> per cycle, error ~ (2 pi)^4 h^4/180 ~ 1e-15 relative, each integrand smooth on
    !> [0, n T]); at every cycle end v(kT-) = v(kT) = 0 (sine and cosine) and d(kT) = k A T^2
    !> /(2 pi) (sine) or 0 (cosine), continuous; after the end v = 0 and d constant.
    subroutine test_cycles_simpson(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 3, m = 2**14
        real(dp), parameter :: amp = 1.7_dp, tp = 0.9_dp, pi_ = acos(-1.0_dp)
        type(pulse_t) :: p
        real(dp) :: h, t, a, v, d, sv, sd, a0, v0, vm, dm, a1, v1, d1, vscale, dscale, dk
        integer :: kind, j, k
        do kind = 1, 2
            if (kind == 1) then
                p = sine_cycle_pulse(amp, tp, n)
                vscale = amp * tp / pi_
                dscale = n * amp * tp * tp / (2.0_dp * pi_)
            else
                p = cosine_cycle_pulse(amp, tp, n)
                vscale = amp * tp / (2.0_dp * pi_)
                dscale = amp * tp * tp / (2.0_dp * pi_**2)
            end if
            call check(error, pulse_end_time(p), n * tp, rtol=1.0e-15_dp, message='end time')
            if (allocated(error)) return
            ! Simpson on 2 panels of h at a time, checked at every k T/4
            h = tp / real(m, dp)
            sv = 0.0_dp
            sd = 0.0_dp
            call pulse_at(p, 0.0_dp, a0, v0, d1)
            do j = 1, n * m / 2
                t = 2.0_dp * real(j - 1, dp) * h
                call pulse_at(p, t + h, vm, dm, d1)      ! vm = a, dm = v at the midpoint
                if (j < n * m / 2) then
                    call pulse_at(p, t + 2.0_dp * h, a1, v1, d1)
                else
                    ! the cosine jumps to 0 at n T: the left limit closes the integral
                    call pulse_at(p, n * tp * (1.0_dp - 4.0_dp * epsilon(t)), a1, v1, d1)
                end if
                sv = sv + h / 3.0_dp * (a0 + 4.0_dp * vm + a1)
                sd = sd + h / 3.0_dp * (v0 + 4.0_dp * dm + v1)
                a0 = a1
                v0 = v1
                if (mod(2 * j, m / 4) == 0) then
                    call check(error, v1, sv, atol=1.0e-12_dp * vscale, message=trim( &
                               pulse_kind_name(p%kind))//': v = int a at t = '//num(t + 2 * h))
                    if (allocated(error)) return
                    call check(error, d1, sd, atol=1.0e-12_dp * dscale, message=trim( &
                               pulse_kind_name(p%kind))//': d = int v at t = '//num(t + 2 * h))
                    if (allocated(error)) return
                end if
            end do
            do k = 1, n
                t = real(k, dp) * tp
                call pulse_at(p, t * (1.0_dp - 4.0_dp * epsilon(t)), a, vm, dm)
                call pulse_at(p, t, a, v, d)
                ! the left sample is 4 k eps T before k T: |v| there ~ 2 pi 4 k eps vscale
                call check(error, abs(vm) <= 1.0e-13_dp * vscale .and. &
                           abs(v) <= 1.0e-14_dp * vscale, 'v at the end of cycle ' &
                           //num(real(k, dp))//': '//num(vm)//', '//num(v))
                if (allocated(error)) return
                dk = 0.0_dp
                if (kind == 1) dk = k * amp * tp * tp / (2.0_dp * pi_)
                call check(error, d, dk, atol=1.0e-14_dp * dscale, &
                           message='d at the end of cycle '//num(real(k, dp)))
                if (allocated(error)) return
                call check(error, dm, d, atol=1.0e-14_dp * dscale, &
                           message='d continuous at the end of cycle '//num(real(k, dp)))
                if (allocated(error)) return
            end do
            call pulse_at(p, 7.3_dp * tp, a, v, d)
            call check(error, .not. (abs(a) > 0.0_dp .or. abs(v) > 0.0_dp), &
                       'rest after n cycles')
            if (allocated(error)) return
            call check(error, d, dk, atol=1.0e-14_dp * dscale, message='d after n cycles')
            if (allocated(error)) return
        end do
    end subroutine test_cycles_simpson

    !> The pieces of 3 sine cycles: 0, T/4, 3T/4, ..., 11T/4, 3T (7 pieces); of 3 cosine
    !> cycles 0, T/2, ..., 3T (6 pieces); a_g monotone on each (dense sample), the ends
    !> at the extrema +-A, the last piece ending at n T.
    subroutine test_cycles_pieces(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: amp = 1.3_dp, tp = 0.7_dp
        type(pulse_t) :: p
        type(piece_iter_t) :: it
        type(piece_t) :: pc
        logical :: found
        real(dp) :: no_record(0), texp, a, v, d, prev, sgn
        integer :: kind, npieces, stat, j, nexp
        do kind = 1, 2
            if (kind == 1) then
                p = sine_cycle_pulse(amp, tp, 3)
                nexp = 7
            else
                p = cosine_cycle_pulse(amp, tp, 3)
                nexp = 6
            end if
            call pulse_pieces_init(it, p)
            npieces = 0
            do
                call next_piece(it, no_record, 'test', pc, found, stat)
                call check(error, stat == SEISPULSE_SUCCESS, 'next_piece status')
                if (allocated(error)) return
                if (.not. found) exit
                npieces = npieces + 1
                if (kind == 1) then
                    if (npieces == 1) then
                        texp = 0.25_dp * tp
                    else if (npieces == nexp) then
                        texp = 3.0_dp * tp
                    else
                        texp = (0.25_dp + 0.5_dp * (npieces - 1)) * tp
                    end if
                else
                    texp = 0.5_dp * npieces * tp
                end if
                call check(error, pc%tb, texp, rtol=1.0e-15_dp, &
                           message='piece '//num(real(npieces, dp))//' end')
                if (allocated(error)) return
                ! monotone: a_g - aa keeps the sign of ab - aa, values in between
                sgn = sign(1.0_dp, pc%ab - pc%aa)
                prev = pc%aa
                do j = 1, 200
                    call pulse_at(p, pc%ta + (pc%tb - pc%ta) * j / 201.0_dp, a, v, d)
                    call check(error, sgn * (a - prev) >= -1.0e-15_dp * amp, &
                               'monotone on piece '//num(real(npieces, dp)))
                    if (allocated(error)) return
                    prev = a
                end do
                call check(error, sgn * (pc%ab - prev) >= -1.0e-15_dp * amp, &
                           'monotone to the end of piece '//num(real(npieces, dp)))
                if (allocated(error)) return
                if (npieces < nexp) then
                    call check(error, abs(pc%ab), amp, rtol=1.0e-14_dp, &
                               message='piece ends at an extremum')
                    if (allocated(error)) return
                end if
            end do
            call check(error, npieces == nexp, trim(pulse_kind_name(p%kind))//': ' &
                       //num(real(npieces, dp))//' pieces, expected '//num(real(nexp, dp)))
            if (allocated(error)) return
        end do
    end subroutine test_cycles_pieces

    !> cycles must be a whole number in [1, 1e6]: 0, 2.5, NaN, 1e7, -3, +inf are refused
    !> with a message starting with "cycles "; 1e6 and 20 are accepted.
    subroutine test_cycles_bad(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: bad(6), good(3)
        type(pulse_t) :: p
        integer :: i, kind, stat
        character(len=200) :: msg
        bad = [0.0_dp, 2.5_dp, ieee_value(1.0_dp, ieee_quiet_nan), 1.0e7_dp, -3.0_dp, &
               ieee_value(1.0_dp, ieee_positive_inf)]
        good = [1.0_dp, 20.0_dp, 1.0e6_dp]
        do kind = PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE
            p = sine_cycle_pulse(1.0_dp, 1.0_dp)
            p%kind = kind
            do i = 1, size(bad)
                p%cycles = bad(i)
                msg = ''
                call pulse_validate(p, stat, msg)
                call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:7) == 'cycles ', &
                           'cycles = '//num(bad(i))//': got "'//trim(msg)//'"')
                if (allocated(error)) return
            end do
            do i = 1, size(good)
                p%cycles = good(i)
                call pulse_validate(p, stat, msg)
                call check(error, stat == SEISPULSE_SUCCESS, 'cycles = '//num(good(i)))
                if (allocated(error)) return
            end do
        end do
        ! not a parameter of the other kinds: ignored there
        p = half_sine_pulse(1.0_dp, 1.0_dp)
        p%cycles = 2.5_dp
        call pulse_validate(p, stat, msg)
        call check(error, stat == SEISPULSE_SUCCESS, 'half_sine ignores cycles')
    end subroutine test_cycles_bad

end module test_pulses
