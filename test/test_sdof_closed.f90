!> Linear oscillator closed forms (seispulse_sdof_closed) against independent computations:
!> adaptive Gauss-Kronrod (G7/K15) quadrature of Duhamel's integral written here, using
!> pulse_at for a_g; the book's numbers and each corrected equation of doc/oscillator.md (2.17
!> steady state vs 1.299 from rest, 2.20 square root, 2.21 cos omega t, 2.23 sign, beta_pulse);
!> limits (beta -> 0, -inf, +inf, huge; zeta -> 0 and -> 1; resonance and 1 +- 1e-9; t1 -> 0;
!> T -> inf, where z = -d_g, and T -> 0, where z = -a_g/omega^2; the step overshoot);
!> peaks against dense sampling and the half sine's residual closed form; spectra; the
!> peak-scan limit; bad input.
module test_sdof_closed
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_negative_inf
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_SINGULAR
    use seispulse_sdof_sim, only: min_period
    use seispulse_pulses, only: pulse_t, pulse_at, pulse_breaks, exp_consts_t, exp_consts, &
                                exponential_pulse, half_sine_pulse, sine_cycle_pulse, &
                                cosine_cycle_pulse, rectangular_pulse, triangular_pulse, &
                                ricker_pulse, mp_pulse, PULSE_RICKER, PULSE_EXPONENTIAL, &
                                pulse_peak_accel
    use seispulse_sdof_closed, only: dynamic_coefficient, harmonic_response, &
                                    rect_pulse_response, beta_pulse, impulse_max, &
                                    impulse_response, sdof_pulse_response, sdof_pulse_peaks, &
                                    sdof_pulse_spectrum, BETA_HYSTERETIC, &
                                    BETA_VISCOUS, HARMONIC_SINE, HARMONIC_COSINE, &
                                    BETA_PULSE_TEXTBOOK, BETA_PULSE_EXACT
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_sdof_closed

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp

    !> Forcing of the reference quadrature: a pulse, or harmonic -W0 sin / -W0 cos.
    integer, parameter :: SRC_PULSE = 1, SRC_SINE = 2, SRC_COSINE = 3

    type :: duhamel_t
        integer :: src = SRC_PULSE
        type(pulse_t) :: p
        type(exp_consts_t) :: c
        real(dp) :: omega = 1.0_dp, zeta = 0.0_dp, wd = 1.0_dp
        real(dp) :: w0 = 1.0_dp, theta = 1.0_dp
        real(dp) :: t = 0.0_dp           !! evaluation time
        real(dp) :: scale(2) = 1.0_dp    !! z, v scales for the error test
        integer :: nevals = 0
    end type duhamel_t

    ! Gauss-Kronrod 7/15 (QUADPACK qk15)
    real(dp), parameter :: xgk(8) = [0.991455371120812639206854697526329_dp, &
        0.949107912342758524526189684047851_dp, 0.864864423359769072789712788640926_dp, &
        0.741531185599394439863864773280788_dp, 0.586087235467691130294144845693013_dp, &
        0.405845151377397166906606412076961_dp, 0.207784955007898467600689403773245_dp, 0.0_dp]
    real(dp), parameter :: wgk(8) = [0.022935322010529224963732008058970_dp, &
        0.063092092629978553290700663189204_dp, 0.104790010322250183839876322541518_dp, &
        0.140653259715525918745189590510238_dp, 0.169004726639267902826583426598550_dp, &
        0.190350578064785409913256402421014_dp, 0.204432940075298892414161999234649_dp, &
        0.209482141084727828012999174891714_dp]
    real(dp), parameter :: wg(4) = [0.129484966168869693270611432679082_dp, &
        0.279705391489276667901467771423780_dp, 0.381830050505118944950369775488975_dp, &
        0.417959183673469387755102040816327_dp]

contains

    subroutine collect_sdof_closed(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('dynamic coefficient: Eq. 2.17, 2.20 (sqrt), viscous, 2|beta|', &
                              test_dynamic_coefficient), &
                 new_unittest('harmonic from rest = Duhamel quadrature (sine, cosine, damped)', &
                              test_harmonic_quadrature), &
                 new_unittest('Eq. 2.17 is steady state: from rest max 1.299 at r = 0.5', &
                              test_mononobe_transient), &
                 new_unittest('Eq. 2.21 with cos(omega t) (erratum), 2|beta| reached', &
                              test_cosine_law), &
                 new_unittest('resonance r = 1 and 1 +- 1e-9: exact, no lost digits', &
                              test_resonance), &
                 new_unittest('rectangle: Eq. 2.22/2.23 sign, any t1, = quadrature', &
                              test_rect_book), &
                 new_unittest('beta_pulse: exact 2 sin(pi t1/T) vs textbook 1 + 2 pi t1/T', &
                              test_beta_pulse), &
                 new_unittest('impulse: Eq. 2.24/2.25, damped max, rectangle t1 -> 0', &
                              test_impulse), &
                 new_unittest('every pulse = Duhamel quadrature (1e-8 of the max)', &
                              test_pulses_quadrature), &
                 new_unittest('n cycles = superposition of n shifted single cycles, = quadrature', &
                              test_cycles_superposition), &
                 new_unittest('exponential limits: beta -> 0, +-1, -inf, +inf, huge', &
                              test_exp_limits), &
                 new_unittest('zeta -> 0 is continuous', test_zeta_limit), &
                 new_unittest('very long periods: z -> -d_g, z'' -> -v_g; tiny t', &
                              test_long_periods), &
                 new_unittest('peaks >= dense samples, value at the reported time', &
                              test_peaks_dense), &
                 new_unittest('spectrum: residual closed form, period 0, T -> 0+ (jumps)', &
                              test_spectrum), &
                 new_unittest('damped steady state (transient = false) = closed form', &
                              test_damped_steady_state), &
                 new_unittest('rectangle at T = 1e160, 1e200: finite, z = -d_g', &
                              test_rect_huge_period), &
                 new_unittest('zeta -> 1 (1 - 2^-53, 1 - 1e-12): no digits lost', &
                              test_zeta_one), &
                 new_unittest('peak scan: aliasing periods refused, exact just above', &
                              test_scan_limit), &
                 new_unittest('M&P peak |a_g| for gamma = 1e5, 1e8 (no overflow)', &
                              test_mp_huge_gamma), &
                 new_unittest('tiny periods: 1e-308 refused, 2e-60 quasi-static', &
                              test_tiny_periods), &
                 new_unittest('bad input is a status naming the parameter', test_bad_input)]
    end subroutine collect_sdof_closed

    ! ---------------------------------------------------------------- reference quadrature

    !> Ground acceleration of the reference problem.
    function ground(d, tau) result(a)
        type(duhamel_t), intent(in) :: d
        real(dp), intent(in) :: tau
        real(dp) :: a, v, u
        select case (d%src)
        case (SRC_SINE)
            a = -d%w0 * sin(d%theta * tau)
        case (SRC_COSINE)
            a = -d%w0 * cos(d%theta * tau)
        case default
            call pulse_at(d%p, tau, a, v, u, d%c)
        end select
    end function ground

    !> Integrands of z(t) = -int h(t - tau) a dtau and z'(t) = -int h'(t - tau) a dtau.
    subroutine integrand(d, tau, f)
        type(duhamel_t), intent(inout) :: d
        real(dp), intent(in) :: tau
        real(dp), intent(out) :: f(2)
        real(dp) :: s, e, a
        s = d%t - tau
        e = exp(-d%zeta * d%omega * s)
        a = ground(d, tau)
        f(1) = -e * sin(d%wd * s) / d%wd * a
        f(2) = -e * (cos(d%wd * s) - d%zeta * d%omega / d%wd * sin(d%wd * s)) * a
        d%nevals = d%nevals + 1
    end subroutine integrand

    subroutine gk15(d, a, b, res, err)
        type(duhamel_t), intent(inout) :: d
        real(dp), intent(in) :: a, b
        real(dp), intent(out) :: res(2), err
        real(dp) :: c, h, f0(2), f1(2), f2(2), fs(2, 7), rg(2), rk(2)
        integer :: j
        c = 0.5_dp * (a + b)
        h = 0.5_dp * (b - a)
        call integrand(d, c, f0)
        rk = wgk(8) * f0
        do j = 1, 7
            call integrand(d, c - h * xgk(j), f1)
            call integrand(d, c + h * xgk(j), f2)
            fs(:, j) = f1 + f2
            rk = rk + wgk(j) * fs(:, j)
        end do
        ! the Gauss nodes are the even Kronrod nodes
        rg = wg(1) * fs(:, 2) + wg(2) * fs(:, 4) + wg(3) * fs(:, 6) + wg(4) * f0
        res = h * rk
        err = maxval(abs(h * (rk - rg)) / d%scale)
    end subroutine gk15

    !> Adaptive bisection of [a, b] until the G7/K15 difference is below tol per unit length.
    recursive subroutine adapt(d, a, b, tol, depth, res)
        type(duhamel_t), intent(inout) :: d
        real(dp), intent(in) :: a, b, tol
        integer, intent(in) :: depth
        real(dp), intent(out) :: res(2)
        real(dp) :: err, r1(2), r2(2), c
        call gk15(d, a, b, res, err)
        if (err <= tol * (b - a) .or. depth >= 60) return
        c = 0.5_dp * (a + b)
        call adapt(d, a, c, tol, depth + 1, r1)
        call adapt(d, c, b, tol, depth + 1, r2)
        res = r1 + r2
    end subroutine adapt

    !> z, z', a_abs at time t by quadrature of Duhamel's integral, split at the pulse breaks.
    subroutine duhamel(d, t, z, v, a)
        type(duhamel_t), intent(inout) :: d
        real(dp), intent(in) :: t
        real(dp), intent(out) :: z, v, a
        real(dp) :: pts(12), res(2), r(2), tend, tol
        integer :: np, nb, j
        real(dp) :: br(5)
        z = 0.0_dp
        v = 0.0_dp
        a = 0.0_dp
        if (.not. (t > 0.0_dp)) return
        d%t = t
        tend = t
        np = 1
        pts(1) = 0.0_dp
        if (d%src == SRC_PULSE) then
            call pulse_breaks(d%p, br, nb)
            do j = 1, nb
                if (br(j) > 0.0_dp .and. br(j) < t) then
                    np = np + 1
                    pts(np) = br(j)
                end if
            end do
            if (d%p%kind == PULSE_RICKER) then
                ! split at the wavelet's extrema; beyond x = 12 it is below 1e-60
                do j = -1, 1
                    if (d%p%t0 + j * 0.39_dp / d%p%freq > pts(np) .and. &
                        d%p%t0 + j * 0.39_dp / d%p%freq < t) then
                        np = np + 1
                        pts(np) = d%p%t0 + j * 0.39_dp / d%p%freq
                    end if
                end do
                tend = min(t, d%p%t0 + 12.0_dp / (pi * d%p%freq))
            end if
        end if
        np = np + 1
        pts(np) = tend
        tol = 1.0e-13_dp
        res = 0.0_dp
        do j = 1, np - 1
            if (pts(j + 1) > pts(j)) then
                call adapt(d, pts(j), pts(j + 1), tol, 0, r)
                res = res + r
            end if
        end do
        z = res(1)
        v = res(2)
        a = -(2.0_dp * d%zeta * d%omega * v + d%omega**2 * z)
    end subroutine duhamel

    function make_duhamel(p, period, zeta) result(d)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: period, zeta
        type(duhamel_t) :: d
        d%p = p
        if (p%kind == PULSE_EXPONENTIAL) d%c = exp_consts(p%beta)
        d%omega = 2.0_dp * pi / period
        d%zeta = zeta
        d%wd = d%omega * sqrt(1.0_dp - zeta**2)
        d%scale = [1.0_dp / d%omega**2, 1.0_dp / d%omega] * max(abs(p%amp), 1.0e-300_dp)
        if (p%kind == 8) d%scale = d%scale * 2.0_dp * pi * p%freq
    end function make_duhamel

    ! ---------------------------------------------------------------- helpers

    function linspace(a, b, n) result(x)
        real(dp), intent(in) :: a, b
        integer, intent(in) :: n
        real(dp) :: x(n)
        integer :: i
        do i = 1, n
            x(i) = a + (b - a) * real(i - 1, dp) / real(n - 1, dp)
        end do
    end function linspace

    !> Compare the closed form with quadrature at times t, to rtol of the largest |value|.
    subroutine check_against_quadrature(error, p, period, zeta, t, rtol, label)
        type(test_error), allocatable, intent(inout) :: error
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: period, zeta, t(:), rtol
        character(len=*), intent(in) :: label
        real(dp) :: z(size(t)), v(size(t)), a(size(t)), zr(size(t)), vr(size(t)), ar(size(t))
        type(duhamel_t) :: d
        integer :: stat, i
        character(len=200) :: msg
        call sdof_pulse_response(p, period, zeta, t, z, v, a, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, label//': '//trim(msg))
        if (allocated(error)) return
        d = make_duhamel(p, period, zeta)
        do i = 1, size(t)
            call duhamel(d, t(i), zr(i), vr(i), ar(i))
        end do
        call check(error, z, zr, atol=rtol * maxval(abs(zr)), message=label//' z')
        if (allocated(error)) return
        call check(error, v, vr, atol=rtol * maxval(abs(vr)), message=label//' v')
        if (allocated(error)) return
        call check(error, a, ar, atol=rtol * maxval(abs(ar)), message=label//' a_abs')
    end subroutine check_against_quadrature

    ! ---------------------------------------------------------------- book forms

    subroutine test_dynamic_coefficient(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: beta, bcos, bv, r
        integer :: stat
        character(len=256) :: msg
        ! Eq. 2.17: undamped, signed
        call dynamic_coefficient(0.5_dp, 0.0_dp, BETA_HYSTERETIC, beta, stat, beta_cos=bcos)
        call check(error, beta, 4.0_dp / 3.0_dp)
        if (allocated(error)) return
        call check(error, bcos, 8.0_dp / 3.0_dp, message='cosine law 2|beta|')
        if (allocated(error)) return
        call dynamic_coefficient(2.0_dp, 0.0_dp, BETA_HYSTERETIC, beta, stat, beta_cos=bcos)
        call check(error, beta, -1.0_dp / 3.0_dp, message='negative above resonance')
        if (allocated(error)) return
        call check(error, bcos, 2.0_dp / 3.0_dp)
        if (allocated(error)) return
        call dynamic_coefficient(0.3_dp, 0.0_dp, BETA_VISCOUS, beta, stat, beta_cos=bcos)
        call check(error, bcos, 2.1978_dp, atol=1.0e-4_dp, message='doc/oscillator.md 3: 0.3')
        if (allocated(error)) return
        ! Eq. 2.20 with the square root: beta(r = 1) = 1/gamma, both models
        call dynamic_coefficient(1.0_dp, 0.1_dp, BETA_HYSTERETIC, beta, stat)
        call check(error, beta, 10.0_dp, message='Eq. 2.20 at resonance')
        if (allocated(error)) return
        call dynamic_coefficient(1.0_dp, 0.1_dp, BETA_VISCOUS, beta, stat)
        call check(error, beta, 10.0_dp, message='viscous at resonance')
        if (allocated(error)) return
        ! without the square root 1/((1 - r^2)^2 + gamma^2) would give 100 there
        call dynamic_coefficient(0.6_dp, 0.2_dp, BETA_HYSTERETIC, beta, stat)
        call check(error, beta, 1.0_dp / sqrt(0.64_dp**2 + 0.04_dp), message='hysteretic r = 0.6')
        if (allocated(error)) return
        call dynamic_coefficient(0.6_dp, 0.2_dp, BETA_VISCOUS, bv, stat)
        call check(error, bv, 1.0_dp / sqrt(0.64_dp**2 + 0.04_dp * 0.36_dp), &
                   message='viscous r = 0.6')
        if (allocated(error)) return
        call check(error, bv > beta, 'viscous damping term is smaller below resonance')
        if (allocated(error)) return
        ! near resonance, (1 - r)(1 + r) keeps every digit: r = 1 - d gives 1/(d (2 - d))
        r = 1.0_dp - 2.0_dp**(-30)
        call dynamic_coefficient(r, 0.0_dp, BETA_HYSTERETIC, beta, stat)
        call check(error, beta, 1.0_dp / (2.0_dp**(-30) * (2.0_dp - 2.0_dp**(-30))), &
                   rtol=4.0e-16_dp, &
                   message='near resonance')
        if (allocated(error)) return
        ! singular: r = 1, gamma = 0
        msg = ''
        call dynamic_coefficient(1.0_dp, 0.0_dp, BETA_HYSTERETIC, beta, stat, msg)
        call check(error, stat, SEISPULSE_SINGULAR, 'r = 1, gamma = 0')
        if (allocated(error)) return
        call check(error, index(msg, 'ratio') > 0 .and. index(msg, 'gamma') > 0, trim(msg))
    end subroutine test_dynamic_coefficient

    subroutine test_harmonic_quadrature(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: period = 0.8_dp, w0 = 2.5_dp
        real(dp), parameter :: ratios(4) = [0.3_dp, 0.97_dp, 1.0_dp, 2.2_dp]
        real(dp), parameter :: zetas(2) = [0.0_dp, 0.07_dp]
        real(dp) :: t(7), z(7), v(7), a(7), zr, vr, ar, sc
        type(duhamel_t) :: d
        integer :: law, ir, iz, i, stat
        t = [0.0_dp, 0.013_dp, 0.31_dp, 0.77_dp, 1.9_dp, 4.45_dp, 7.3_dp]
        do law = HARMONIC_SINE, HARMONIC_COSINE
            do ir = 1, size(ratios)
                do iz = 1, size(zetas)
                    call harmonic_response(t, w0, period, ratios(ir), zetas(iz), law, .true., &
                                           z, v, a, stat)
                    call check(error, stat, SEISPULSE_SUCCESS, 'harmonic')
                    if (allocated(error)) return
                    d%src = merge(SRC_SINE, SRC_COSINE, law == HARMONIC_SINE)
                    d%omega = 2.0_dp * pi / period
                    d%zeta = zetas(iz)
                    d%wd = d%omega * sqrt(1.0_dp - zetas(iz)**2)
                    d%w0 = w0
                    d%theta = ratios(ir) * d%omega
                    d%scale = [w0 / d%omega**2, w0 / d%omega]
                    sc = w0 / d%omega**2 * 20.0_dp
                    do i = 1, size(t)
                        call duhamel(d, t(i), zr, vr, ar)
                        call check(error, z(i), zr, atol=1.0e-10_dp * sc, message='harmonic z')
                        if (allocated(error)) return
                        call check(error, v(i), vr, atol=1.0e-10_dp * sc * d%omega, &
                                   message='harmonic v')
                        if (allocated(error)) return
                        call check(error, a(i), ar, atol=1.0e-10_dp * sc * d%omega**2, &
                                   message='harmonic a_abs')
                        if (allocated(error)) return
                    end do
                end do
            end do
        end do
        ! t < 0 is rest
        call harmonic_response([-1.0_dp], w0, period, 0.5_dp, 0.0_dp, HARMONIC_COSINE, .true., &
                               z(1:1), v(1:1), a(1:1), stat)
        call check(error, abs(z(1)) + abs(v(1)) + abs(a(1)), 0.0_dp, message='t < 0')
    end subroutine test_harmonic_quadrature

    subroutine test_mononobe_transient(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 40001
        real(dp), parameter :: period = 1.0_dp, w0 = 3.0_dp, r = 0.5_dp
        real(dp) :: t(n), z(n), v(n), a(n), om, beta, zmax
        integer :: stat, i
        om = 2.0_dp * pi / period
        beta = 1.0_dp / (1.0_dp - r * r)
        t = linspace(0.0_dp, 4.0_dp * period / r, n)
        ! Eq. 2.17 is the steady state: z = W0 beta sin(theta t)/omega^2, S = m W0 beta sin
        call harmonic_response(t, w0, period, r, 0.0_dp, HARMONIC_SINE, .false., z, v, a, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        do i = 1, n, 997
            call check(error, z(i), w0 * beta * sin(r * om * t(i)) / om**2, &
                       atol=1.0e-15_dp * w0 / om**2, message='Eq. 2.17')
            if (allocated(error)) return
            ! Eq. 2.18: S = -m (a_g + z'') = -m a_abs = m W0 beta sin(theta t)
            call check(error, -a(i), w0 * beta * sin(r * om * t(i)), atol=1.0e-14_dp * w0, &
                       message='Eq. 2.18')
            if (allocated(error)) return
        end do
        ! from rest: steady state plus -(theta/omega)(W0 beta/omega^2) sin(omega t)
        call harmonic_response(t, w0, period, r, 0.0_dp, HARMONIC_SINE, .true., z, v, a, stat)
        do i = 1, n, 997
            call check(error, z(i), w0 * beta / om**2 * (sin(r * om * t(i)) &
                       - r * sin(om * t(i))), atol=1.0e-14_dp * w0 / om**2, message='from rest')
            if (allocated(error)) return
        end do
        zmax = maxval(abs(z)) * om**2 / (w0 * beta)
        call check(error, zmax, 1.299_dp, atol=5.0e-4_dp, message='max|z| omega^2/(W0 beta)')
        if (allocated(error)) return
        call check(error, zmax, 0.75_dp * sqrt(3.0_dp), rtol=1.0e-6_dp, message='3 sqrt(3)/4')
        if (allocated(error)) return
        ! undamped steady state at resonance does not exist
        call harmonic_response(t(1:2), w0, period, 1.0_dp, 0.0_dp, HARMONIC_SINE, .false., &
                               z(1:2), v(1:2), a(1:2), stat)
        call check(error, stat, SEISPULSE_SINGULAR, 'steady state at resonance')
    end subroutine test_mononobe_transient

    subroutine test_cosine_law(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: period = 0.7_dp, w0 = 1.7_dp
        real(dp) :: om, th, beta, t(3), z(3), v(3), a(3), printed, corrected
        integer :: stat
        om = 2.0_dp * pi / period
        ! r = 0.5 at t = 0.3 T: cos(omega t) = -0.309, sin(omega t) = 0.951
        th = 0.5_dp * om
        beta = 1.0_dp / (1.0_dp - 0.25_dp)
        t = [0.3_dp * period, 1.0e-9_dp, period]
        call harmonic_response(t, w0, period, 0.5_dp, 0.0_dp, HARMONIC_COSINE, .true., z, v, a, &
                               stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        corrected = w0 * beta / om**2 * (cos(th * t(1)) - cos(om * t(1)))
        printed = w0 * beta / om**2 * (cos(th * t(1)) - sin(om * t(1)))
        call check(error, z(1), corrected, rtol=1.0e-14_dp, message='Eq. 2.21 with cos(omega t)')
        if (allocated(error)) return
        call check(error, abs(z(1) - printed) > 0.5_dp * abs(printed), &
                   'the printed sin(omega t) form must differ')
        if (allocated(error)) return
        ! z(0) = 0 holds only with cos(omega t)
        call check(error, abs(z(2)) < 1.0e-15_dp * w0 / om**2, 'z(0+) = 0')
        if (allocated(error)) return
        ! the bracket reaches -2 at t = T: max|z| omega^2/W0 = 2|beta| = 2.6667
        call check(error, abs(z(3)) * om**2 / w0, 2.0_dp * beta, rtol=1.0e-13_dp, message='2|beta|')
        if (allocated(error)) return
        ! r = 0.3 reaches 2|beta| = 2.1978 at t = 5 T; r = 2 gives 0.6667 at T/2
        call harmonic_response([5.0_dp * period], w0, period, 0.3_dp, 0.0_dp, HARMONIC_COSINE, &
                               .true., z(1:1), v(1:1), a(1:1), stat)
        call check(error, abs(z(1)) * om**2 / w0, 2.1978_dp, atol=1.0e-4_dp, message='r = 0.3')
        if (allocated(error)) return
        call harmonic_response([0.5_dp * period], w0, period, 2.0_dp, 0.0_dp, HARMONIC_COSINE, &
                               .true., z(1:1), v(1:1), a(1:1), stat)
        call check(error, abs(z(1)) * om**2 / w0, 2.0_dp / 3.0_dp, rtol=1.0e-13_dp, message='r = 2')
    end subroutine test_cosine_law

    subroutine test_resonance(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: period = 1.0_dp, w0 = 2.0_dp
        real(dp) :: t(4), z(4), v(4), a(4), om, zr, vr, ar, eps(2)
        type(duhamel_t) :: d
        integer :: stat, i, k, law
        om = 2.0_dp * pi / period
        t = [0.3_dp, 1.7_dp, 5.25_dp, 20.1_dp]
        ! exact resonance: secular forms
        call harmonic_response(t, w0, period, 1.0_dp, 0.0_dp, HARMONIC_SINE, .true., z, v, a, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, z, w0 / (2.0_dp * om**2) * (sin(om * t) - om * t * cos(om * t)), &
                   atol=1.0e-14_dp * w0 * 20.0_dp / om, message='sine at resonance')
        if (allocated(error)) return
        call harmonic_response(t, w0, period, 1.0_dp, 0.0_dp, HARMONIC_COSINE, .true., z, v, a, &
                               stat)
        call check(error, z, w0 / (2.0_dp * om) * t * sin(om * t), &
                   atol=1.0e-14_dp * w0 * 20.0_dp / om, message='cosine at resonance')
        if (allocated(error)) return
        ! r = 1 +- 1e-9 against quadrature (no (sin a - sin b)/(omega^2 - theta^2) cancellation)
        eps = [-1.0e-9_dp, 1.0e-9_dp]
        do law = HARMONIC_SINE, HARMONIC_COSINE
            do k = 1, 2
                call harmonic_response(t, w0, period, 1.0_dp + eps(k), 0.0_dp, law, .true., &
                                       z, v, a, stat)
                d%src = merge(SRC_SINE, SRC_COSINE, law == HARMONIC_SINE)
                d%omega = om
                d%zeta = 0.0_dp
                d%wd = om
                d%w0 = w0
                d%theta = (1.0_dp + eps(k)) * om
                d%scale = [w0 / om**2, w0 / om]
                do i = 1, size(t)
                    call duhamel(d, t(i), zr, vr, ar)
                    call check(error, z(i), zr, rtol=1.0e-11_dp, atol=1.0e-14_dp * w0 / om**2, &
                               message='near resonance z')
                    if (allocated(error)) return
                    call check(error, v(i), vr, rtol=1.0e-11_dp, atol=1.0e-14_dp * w0 / om, &
                               message='near resonance v')
                    if (allocated(error)) return
                end do
            end do
        end do
    end subroutine test_resonance

    subroutine test_rect_book(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: period = 0.9_dp, w0 = 1.3_dp
        real(dp), parameter :: t1s(3) = [0.27_dp, 0.45_dp, 1.6_dp]   ! t1 < T/2, = T/2, > T/2
        real(dp) :: t(9), z(9), v(9), a(9), zp(9), vp(9), ap(9), om, t1, expect
        type(duhamel_t) :: d
        real(dp) :: zr, vr, ar
        integer :: stat, k, i
        om = 2.0_dp * pi / period
        do k = 1, 3
            t1 = t1s(k)
            t = [-0.2_dp, 0.0_dp, 0.3_dp * t1, t1 - 1.0e-12_dp, t1, 1.3_dp * t1, t1 + 0.37_dp, &
                 3.0_dp, 7.77_dp]
            call rect_pulse_response(t, w0, t1, period, z, v, a, stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            ! the general pulse response agrees (damping 0)
            call sdof_pulse_response(rectangular_pulse(w0, t1), period, 0.0_dp, t, zp, vp, ap, stat)
            call check(error, z, zp, atol=1.0e-13_dp * w0 / om**2, message='rect vs pulse z')
            if (allocated(error)) return
            call check(error, v, vp, atol=1.0e-13_dp * w0 / om, message='rect vs pulse v')
            if (allocated(error)) return
            d = make_duhamel(rectangular_pulse(w0, t1), period, 0.0_dp)
            do i = 1, size(t)
                call duhamel(d, t(i), zr, vr, ar)
                call check(error, z(i), zr, atol=1.0e-11_dp * w0 / om**2, message='rect quadrature')
                if (allocated(error)) return
                call check(error, a(i), ar, atol=1.0e-11_dp * w0, message='rect a_abs')
                if (allocated(error)) return
            end do
            ! during: -(W0/omega^2)(1 - cos omega t)
            call check(error, z(3), -w0 / om**2 * (1.0_dp - cos(om * t(3))), rtol=1.0e-13_dp, &
                       message='during the pulse')
            if (allocated(error)) return
            ! Eq. 2.23 with its minus sign restored
            expect = -2.0_dp * w0 / om**2 * sin(om * t1 / 2.0_dp) * sin(om * (t(7) - t1 / 2.0_dp))
            call check(error, z(7), expect, rtol=1.0e-12_dp, message='Eq. 2.23')
            if (allocated(error)) return
        end do
        ! the sign: right after a short positive pulse the mass lags behind (z < 0)
        call rect_pulse_response([0.3_dp], w0, 0.1_dp, period, z(1:1), v(1:1), a(1:1), stat)
        call check(error, z(1) < 0.0_dp, 'Eq. 2.23: z < 0 after a positive pulse')
    end subroutine test_rect_book

    subroutine test_beta_pulse(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: x(4) = [0.05_dp, 0.1_dp, 0.25_dp, 0.4_dp]
        real(dp), parameter :: ode(4) = [0.3128_dp, 0.6180_dp, 1.4143_dp, 1.9021_dp]
        real(dp), parameter :: book(4) = [1.3142_dp, 1.6283_dp, 2.5708_dp, 3.5133_dp]
        ! 2 sin(pi x) by mpmath (30 digits)
        real(dp), parameter :: mpm(4) = [0.31286893008046173802_dp, 0.6180339887498948482_dp, &
                                         1.4142135623730950488_dp, 1.9021130325903071442_dp]
        real(dp) :: be, bt, zm, tz, vm, tv, am, ta
        integer :: i, stat
        do i = 1, 4
            call beta_pulse(x(i), BETA_PULSE_EXACT, be, stat)
            call check(error, be, ode(i), atol=1.0e-4_dp, message='exact vs ODE check')
            if (allocated(error)) return
            call check(error, be, mpm(i), rtol=2.0e-16_dp, message='exact vs mpmath')
            if (allocated(error)) return
            call beta_pulse(x(i), BETA_PULSE_TEXTBOOK, bt, stat)
            call check(error, bt, book(i), atol=1.0e-4_dp, message='textbook')
            if (allocated(error)) return
            call check(error, bt - be > 0.9_dp, 'the textbook bound differs')
            if (allocated(error)) return
            ! independent: the largest |a_abs|/W0 of the undamped rectangle (peak finder)
            call sdof_pulse_peaks(rectangular_pulse(1.0_dp, x(i)), 1.0_dp, 0.0_dp, zm, tz, vm, &
                                  tv, am, ta, stat)
            call check(error, am, be, rtol=1.0e-12_dp, message='peak of the rectangle')
            if (allocated(error)) return
        end do
        call beta_pulse(0.7_dp, BETA_PULSE_EXACT, be, stat)
        call check(error, be, 2.0_dp, message='t1 >= T/2')
        if (allocated(error)) return
        call sdof_pulse_peaks(rectangular_pulse(1.0_dp, 0.7_dp), 1.0_dp, 0.0_dp, zm, tz, vm, tv, &
                              am, ta, stat)
        call check(error, am, 2.0_dp, rtol=1.0e-12_dp, message='rectangle t1 = 0.7 T')
        if (allocated(error)) return
        call check(error, ta, 0.5_dp, rtol=1.0e-9_dp, message='peak at T/2 during the pulse')
        if (allocated(error)) return
        ! t1 -> 0: textbook -> 1 (the printed "beta -> 0" is a typo), exact -> 0
        call beta_pulse(0.0_dp, BETA_PULSE_TEXTBOOK, bt, stat)
        call check(error, bt, 1.0_dp)
    end subroutine test_beta_pulse

    subroutine test_impulse(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: period = 0.6_dp, jw = 0.8_dp
        real(dp), parameter :: zetas(3) = [0.0_dp, 0.05_dp, 0.4_dp]
        integer, parameter :: n = 20001
        real(dp) :: zmax, tmax, om, t(n), z(n), v(n), a(n), t1, zm, tz, vm, tv, am, ta, tt(3), &
                    zz(3), vv(3), aa(3), zi(3), vi(3), ai(3)
        integer :: stat, k, i
        om = 2.0_dp * pi / period
        ! Eq. 2.25
        call impulse_max(jw, period, 0.0_dp, zmax, tmax, stat)
        call check(error, zmax, jw / om, message='Eq. 2.25')
        if (allocated(error)) return
        call check(error, tmax, period / 4.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        t = linspace(0.0_dp, period, n)
        do k = 1, 3
            call impulse_max(jw, period, zetas(k), zmax, tmax, stat)
            call impulse_response(t, jw, period, zetas(k), z, v, a, stat)
            ! Eq. 2.24 form, damped
            i = 1234
            call check(error, z(i), -jw * exp(-zetas(k) * om * t(i)) * sin(om * sqrt(1.0_dp &
                       - zetas(k)**2) * t(i)) / (om * sqrt(1.0_dp - zetas(k)**2)), &
                       rtol=1.0e-14_dp, message='impulse response')
            if (allocated(error)) return
            call check(error, zmax >= maxval(abs(z)) .and. &
                       zmax < maxval(abs(z)) * (1.0_dp + 1.0e-7_dp), &
                       'impulse_max vs dense samples')
            if (allocated(error)) return
            ! the rectangle with t1 -> 0 at fixed J_W = W0 t1 tends to the impulse
            t1 = 1.0e-7_dp * period
            call sdof_pulse_peaks(rectangular_pulse(jw / t1, t1), period, zetas(k), zm, tz, vm, &
                                  tv, am, ta, stat)
            call check(error, zm, zmax, rtol=1.0e-6_dp, message='rectangle t1 -> 0: max z')
            if (allocated(error)) return
            call check(error, tz, tmax + 0.5_dp * t1, rtol=1.0e-6_dp, message='its time')
            if (allocated(error)) return
            tt = [0.1_dp, 0.37_dp, 2.9_dp]
            call sdof_pulse_response(rectangular_pulse(jw / t1, t1), period, zetas(k), tt, zz, &
                                     vv, aa, stat)
            call impulse_response(tt - 0.5_dp * t1, jw, period, zetas(k), zi, vi, ai, stat)
            call check(error, zz, zi, atol=1.0e-10_dp * jw / om, message='rectangle -> impulse')
            if (allocated(error)) return
        end do
        ! Eq. 2.24: small t1, t >> t1, undamped book form
        t1 = 1.0e-5_dp
        call rect_pulse_response([0.4_dp], jw / t1, t1, period, z(1:1), v(1:1), a(1:1), stat)
        call check(error, z(1), -jw / om * sin(om * 0.4_dp), rtol=1.0e-4_dp, message='Eq. 2.24')
    end subroutine test_impulse

    ! ---------------------------------------------------------------- all pulses

    subroutine test_pulses_quadrature(error)
        type(test_error), allocatable, intent(out) :: error
        type(pulse_t) :: pulses(22)
        real(dp), parameter :: periods(3) = [0.23_dp, 0.9_dp, 3.1_dp]
        real(dp), parameter :: zetas(3) = [0.0_dp, 0.05_dp, 0.35_dp]
        real(dp) :: t(12), tend
        integer :: k, j
        character(len=64) :: label
        pulses = [exponential_pulse(2.0_dp, 0.7_dp, 0.0_dp, .false.), &
                  exponential_pulse(2.0_dp, 0.7_dp, 0.6_dp, .true.), &
                  exponential_pulse(2.0_dp, 0.7_dp, -0.6_dp, .false.), &
                  exponential_pulse(2.0_dp, 0.7_dp, 1.0_dp, .true.), &
                  exponential_pulse(2.0_dp, 0.7_dp, 2.5_dp, .false.), &
                  exponential_pulse(-2.0_dp, 0.7_dp, -2.5_dp, .true.), &
                  exponential_pulse(2.0_dp, 0.7_dp, 30.0_dp, .true.), &
                  exponential_pulse(2.0_dp, 0.7_dp, -30.0_dp, .false.), &
                  exponential_pulse(2.0_dp, 0.7_dp, ieee_value(1.0_dp, ieee_negative_inf), &
                                    .true.), &
                  half_sine_pulse(1.5_dp, 0.45_dp), &
                  half_sine_pulse(-0.8_dp, 1.15_dp), &
                  sine_cycle_pulse(-1.1_dp, 0.8_dp), &
                  sine_cycle_pulse(1.1_dp, 0.9_dp), &
                  cosine_cycle_pulse(0.9_dp, 0.8_dp), &
                  rectangular_pulse(1.2_dp, 0.35_dp), &
                  triangular_pulse(1.2_dp, 0.6_dp, 0.3_dp), &
                  triangular_pulse(1.2_dp, 0.6_dp, 0.0_dp), &
                  triangular_pulse(1.2_dp, 0.6_dp, 1.0_dp), &
                  ricker_pulse(2.0_dp, 1.3_dp, 1.1_dp), &
                  ricker_pulse(2.0_dp, 1.3_dp, 0.15_dp), &
                  mp_pulse(0.4_dp, 0.9_dp, 2.3_dp, 40.0_dp, 1.5_dp), &
                  mp_pulse(0.4_dp, 1.7_dp, 1.2_dp, -100.0_dp, 0.6_dp)]
        do k = 1, size(pulses)
            do j = 1, 3
                tend = 1.6_dp
                if (pulses(k)%kind == PULSE_RICKER) tend = pulses(k)%t0 + 2.0_dp / pulses(k)%freq
                if (pulses(k)%kind == 8) tend = pulses(k)%t0 + pulses(k)%gamma / pulses(k)%freq
                t = [-0.1_dp, 0.01_dp, 0.11_dp, 0.2_dp, 0.349_dp, 0.35_dp, 0.5_dp, 0.71_dp, &
                     0.93_dp, tend, tend + 0.37_dp * periods(j), tend + 2.2_dp * periods(j)]
                write(label, '(a, i0, a, i0)') 'pulse ', k, ' case ', j
                call check_against_quadrature(error, pulses(k), periods(j), zetas(j), t, &
                                              1.0e-9_dp, trim(label))
                if (allocated(error)) return
            end do
        end do
        ! exact resonance of a sinusoidal pulse (sine cycle with T_p = T), undamped
        t = linspace(0.05_dp, 3.0_dp, 12)
        call check_against_quadrature(error, sine_cycle_pulse(1.0_dp, 0.9_dp), 0.9_dp, 0.0_dp, t, &
                                      1.0e-9_dp, 'resonant sine cycle')
        if (allocated(error)) return
        ! very long and very short periods, heavy damping
        call check_against_quadrature(error, half_sine_pulse(1.0_dp, 0.45_dp), 1.0e3_dp, 0.05_dp, &
                                      t, 1.0e-9_dp, 'T = 1000 s')
        if (allocated(error)) return
        call check_against_quadrature(error, exponential_pulse(1.0_dp, 0.45_dp, 4.0_dp, .true.), &
                                      0.02_dp, 0.02_dp, t, 1.0e-9_dp, 'T = 20 ms')
        if (allocated(error)) return
        call check_against_quadrature(error, exponential_pulse(1.0_dp, 0.45_dp, -0.4_dp, .true.), &
                                      0.5_dp, 0.9_dp, t, 1.0e-9_dp, 'zeta = 0.9')
    end subroutine test_pulses_quadrature

    subroutine test_exp_limits(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: period = 0.6_dp, zeta = 0.05_dp, a0 = 2.0_dp, td = 0.7_dp
        real(dp) :: t(10), z(10), v(10), a(10), zr(10), vr(10), ar(10), om, wd, area, s
        real(dp) :: zm, tz, vm, tv, am, ta, b, sc
        type(duhamel_t) :: d
        real(dp), parameter :: huge_betas(3) = [1.0e6_dp, 1.0e12_dp, 1.0e300_dp]
        integer :: stat, k, i
        om = 2.0_dp * pi / period
        wd = om * sqrt(1.0_dp - zeta**2)
        t = [0.05_dp, 0.2_dp, 0.35_dp, 0.5_dp, 0.7_dp, 0.9_dp, 1.05_dp, 1.3_dp, 2.0_dp, 3.7_dp]
        ! beta = 0 is the triangle, tiny beta too: against the quadrature of the triangular
        ! pulse's a_g (pulse_at of the triangle, not the exponential's segments)
        d = make_duhamel(triangular_pulse(a0, td, 0.5_dp), period, zeta)
        do i = 1, size(t)
            call duhamel(d, t(i), zr(i), vr(i), ar(i))
        end do
        sc = maxval(abs(zr))
        call sdof_pulse_response(exponential_pulse(a0, td, 0.0_dp, .false.), period, zeta, t, z, &
                                 v, a, stat)
        call check(error, z, zr, atol=1.0e-12_dp * sc, message='beta = 0: triangle')
        if (allocated(error)) return
        call sdof_pulse_response(exponential_pulse(a0, td, 1.0e-300_dp, .false.), period, zeta, &
                                 t, z, v, a, stat)
        call check(error, z, zr, atol=1.0e-12_dp * sc, message='beta = 1e-300')
        if (allocated(error)) return
        call sdof_pulse_response(exponential_pulse(a0, td, -1.0e-9_dp, .false.), period, zeta, &
                                 t, z, v, a, stat)
        call check(error, z, zr, atol=1.0e-9_dp * sc, message='beta = -1e-9')
        if (allocated(error)) return
        ! continuity across the switch of forms at |beta| = 1
        do k = -1, 1, 2
            call sdof_pulse_response(exponential_pulse(a0, td, real(k, dp), .true.), period, &
                                     zeta, t, zr, vr, ar, stat)
            b = real(k, dp) * (1.0_dp + 4.0_dp * epsilon(1.0_dp))
            call sdof_pulse_response(exponential_pulse(a0, td, b, .true.), period, zeta, t, z, v, &
                                     a, stat)
            call check(error, z, zr, atol=1.0e-14_dp * maxval(abs(zr)), message='|beta| = 1+')
            if (allocated(error)) return
            call check(error, a, ar, atol=1.0e-14_dp * maxval(abs(ar)), message='|beta| = 1+ a')
            if (allocated(error)) return
        end do
        ! beta -> -inf: the box, against the quadrature of the rectangular pulse's a_g
        d = make_duhamel(rectangular_pulse(a0, td), period, zeta)
        do i = 1, size(t)
            call duhamel(d, t(i), zr(i), vr(i), ar(i))
        end do
        sc = maxval(abs(zr))
        call sdof_pulse_response(exponential_pulse(a0, td, ieee_value(1.0_dp, ieee_negative_inf), &
                                 .false.), period, zeta, t, z, v, a, stat)
        call check(error, z, zr, atol=1.0e-12_dp * sc, message='beta = -inf')
        if (allocated(error)) return
        call sdof_pulse_response(exponential_pulse(a0, td, -1.0e300_dp, .false.), period, zeta, &
                                 t, z, v, a, stat)
        call check(error, z, zr, atol=1.0e-12_dp * sc, message='beta = -1e300')
        if (allocated(error)) return
        call sdof_pulse_response(exponential_pulse(a0, td, -1.0e6_dp, .false.), period, zeta, &
                                 t, z, v, a, stat)
        call check(error, z, zr, atol=1.0e-5_dp * sc, message='beta = -1e6')
        if (allocated(error)) return
        ! beta = +inf: the spike has no area, the response is zero
        call sdof_pulse_response(exponential_pulse(a0, td, ieee_value(1.0_dp, ieee_positive_inf), &
                                 .true.), period, zeta, t, z, v, a, stat)
        call check(error, maxval(abs(z)) + maxval(abs(v)) + maxval(abs(a)), 0.0_dp, message='spike')
        if (allocated(error)) return
        call sdof_pulse_peaks(exponential_pulse(a0, td, ieee_value(1.0_dp, ieee_positive_inf), &
                              .false.), period, zeta, zm, tz, vm, tv, am, ta, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. .not. (zm + vm + am > 0.0_dp), &
                   'spike peaks')
        if (allocated(error)) return
        ! huge finite beta: the lobe is an impulse of area A t_d/beta (two halves of
        ! A t_d/(2 beta), 1/beta corrections) at t_d/2, negated at 3 t_d/2
        do k = 1, size(huge_betas)
            b = huge_betas(k)
            area = a0 * td / b
            call sdof_pulse_response(exponential_pulse(a0, td, b, .true.), period, zeta, t, z, &
                                     v, a, stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'huge beta')
            if (allocated(error)) return
            do i = 1, size(t)
                zr(i) = 0.0_dp
                s = t(i) - 0.5_dp * td
                if (s > 0.0_dp) zr(i) = -area * exp(-zeta * om * s) * sin(wd * s) / wd
                s = t(i) - 1.5_dp * td
                if (s > 0.0_dp) zr(i) = zr(i) + area * exp(-zeta * om * s) * sin(wd * s) / wd
            end do
            ! (t = 0.35 and 1.05 are the spikes themselves: half of an impulse is in)
            call check(error, maxval(abs(z)) < huge(1.0_dp) .and. maxval(abs(a)) < huge(1.0_dp), &
                       'huge beta: finite')
            if (allocated(error)) return
            call check(error, [z(1:2), z(4:6), z(8:)], [zr(1:2), zr(4:6), zr(8:)], &
                       atol=max(1.0e-5_dp, 1.0e2_dp / b) * maxval(abs(zr)), message='impulse limit')
            if (allocated(error)) return
            call sdof_pulse_peaks(exponential_pulse(a0, td, b, .true.), period, zeta, zm, tz, &
                                  vm, tv, am, ta, stat)
            call check(error, stat == SEISPULSE_SUCCESS .and. zm > 0.0_dp .and. vm > 0.0_dp .and. &
                       am > 0.0_dp .and. zm < huge(zm), 'huge beta peaks finite')
            if (allocated(error)) return
        end do
    end subroutine test_exp_limits

    subroutine test_zeta_limit(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: t(6), z0(6), v0(6), a0(6), z(6), v(6), a(6)
        integer :: stat
        t = [0.1_dp, 0.4_dp, 0.8_dp, 1.5_dp, 3.0_dp, 9.0_dp]
        call sdof_pulse_response(half_sine_pulse(1.0_dp, 0.5_dp), 0.7_dp, 0.0_dp, t, z0, v0, a0, &
                                 stat)
        call sdof_pulse_response(half_sine_pulse(1.0_dp, 0.5_dp), 0.7_dp, 1.0e-12_dp, t, z, v, a, &
                                 stat)
        call check(error, z, z0, atol=1.0e-10_dp * maxval(abs(z0)), message='zeta = 1e-12')
        if (allocated(error)) return
        call check(error, a, a0, atol=1.0e-10_dp * maxval(abs(a0)), message='zeta = 1e-12 a_abs')
    end subroutine test_zeta_limit

    subroutine test_long_periods(error)
        type(test_error), allocatable, intent(out) :: error
        type(pulse_t) :: pulses(6)
        real(dp), parameter :: periods(2) = [1.0e100_dp, 1.0e8_dp]
        real(dp) :: t(9), z(9), v(9), a(9), ag(9), vg(9), dg(9), om, h(1), zz(1), vv(1), aa(1)
        integer :: k, j, i, stat
        pulses = [half_sine_pulse(1.5_dp, 0.45_dp), &
                  exponential_pulse(2.0_dp, 0.7_dp, 3.0_dp, .true.), &
                  exponential_pulse(2.0_dp, 0.7_dp, 0.4_dp, .false.), &
                  triangular_pulse(1.2_dp, 0.6_dp, 0.3_dp), &
                  ricker_pulse(2.0_dp, 1.3_dp, 1.1_dp), &
                  mp_pulse(0.4_dp, 0.9_dp, 2.3_dp, 40.0_dp, 1.5_dp)]
        t = [0.01_dp, 0.1_dp, 0.3_dp, 0.5_dp, 0.9_dp, 1.3_dp, 1.9_dp, 2.6_dp, 3.1_dp]
        ! the mass stays where it was: z = -d_g, z' = -v_g (to (omega t)^2, and to
        ! zeta omega t with damping: undamped at T = 1e8 s)
        do j = 1, 2
            do k = 1, size(pulses)
                call sdof_pulse_response(pulses(k), periods(j), merge(0.05_dp, 0.0_dp, j == 1), &
                                         t, z, v, a, stat)
                call check(error, stat, SEISPULSE_SUCCESS, 'long period')
                if (allocated(error)) return
                do i = 1, size(t)
                    call pulse_at(pulses(k), t(i), ag(i), vg(i), dg(i))
                end do
                call check(error, z, -dg, atol=1.0e-12_dp * maxval(abs(dg)), message='z = -d_g')
                if (allocated(error)) return
                call check(error, v, -vg, atol=1.0e-12_dp * maxval(abs(vg)), message='v = -v_g')
                if (allocated(error)) return
            end do
        end do
        ! early in a pulse: the harmonic sine law from rest, z = -W0 theta t^3/6 (1 + O(t^2))
        om = 2.0_dp * pi
        h = 1.0e-7_dp
        call harmonic_response(h, 1.0_dp, 1.0_dp, 0.5_dp, 0.0_dp, HARMONIC_SINE, .true., zz, vv, &
                               aa, stat)
        call check(error, zz(1), 0.5_dp * om * h(1)**3 / 6.0_dp, rtol=1.0e-12_dp, &
                   message='z at t = 1e-7 T')
        if (allocated(error)) return
        call check(error, vv(1), 0.5_dp * om * h(1)**2 / 2.0_dp, rtol=1.0e-12_dp, &
                   message='v at t = 1e-7 T')
    end subroutine test_long_periods

    subroutine test_peaks_dense(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 30001
        type(pulse_t) :: pulses(11)
        real(dp), parameter :: periods(2) = [0.31_dp, 1.7_dp]
        real(dp), parameter :: zetas(2) = [0.0_dp, 0.08_dp]
        real(dp) :: t(n), z(n), v(n), a(n), pk(6), q(1), zz(1), vv(1), aa(1), tend, smax(3), &
                    vals(3), up
        integer :: k, j, stat, i
        character(len=64) :: label
        pulses = [exponential_pulse(2.0_dp, 0.7_dp, 0.3_dp, .true.), &
                  exponential_pulse(2.0_dp, 0.7_dp, 60.0_dp, .false.), &
                  exponential_pulse(2.0_dp, 0.7_dp, -8.0_dp, .true.), &
                  half_sine_pulse(1.5_dp, 0.45_dp), sine_cycle_pulse(1.1_dp, 0.8_dp), &
                  cosine_cycle_pulse(0.9_dp, 0.8_dp), rectangular_pulse(1.2_dp, 0.35_dp), &
                  triangular_pulse(1.2_dp, 0.6_dp, 0.3_dp), ricker_pulse(2.0_dp, 1.3_dp, 1.1_dp), &
                  mp_pulse(0.4_dp, 0.9_dp, 2.3_dp, 40.0_dp, 1.5_dp), &
                  exponential_pulse(2.0_dp, 0.7_dp, 1.0e6_dp, .false.)]
        do k = 1, size(pulses)
            do j = 1, 2
                write(label, '(a, i0, a, i0)') 'peaks pulse ', k, ' case ', j
                call sdof_pulse_peaks(pulses(k), periods(j), zetas(j), pk(1), pk(2), pk(3), &
                                      pk(4), pk(5), pk(6), stat)
                call check(error, stat, SEISPULSE_SUCCESS, trim(label))
                if (allocated(error)) return
                tend = 1.4_dp
                if (pulses(k)%kind == PULSE_RICKER) tend = 3.0_dp
                if (pulses(k)%kind == 8) tend = 4.5_dp
                t = linspace(0.0_dp, tend + 2.0_dp * periods(j), n)
                call sdof_pulse_response(pulses(k), periods(j), zetas(j), t, z, v, a, stat)
                smax = [maxval(abs(z)), maxval(abs(v)), maxval(abs(a))]
                do i = 1, 3
                    ! never below a sample; the dense grid comes within (2 pi dt/T)^2 of it
                    call check(error, pk(2 * i - 1) >= smax(i) * (1.0_dp - 1.0e-14_dp), &
                               trim(label)//': peak below a sample')
                    if (allocated(error)) return
                    ! beta = 1e6: z', a_abs change within t_d/1e6, below the grid
                    up = 1.0e-5_dp
                    if (k == 2) up = 1.0e-3_dp
                    if (k /= 11 .or. i == 1) then
                        call check(error, pk(2 * i - 1) <= smax(i) * (1.0_dp + up), &
                                   trim(label)//': peak far above the samples')
                        if (allocated(error)) return
                    end if
                    ! the value at the reported time is the peak
                    q = pk(2 * i)
                    call sdof_pulse_response(pulses(k), periods(j), zetas(j), q, zz, vv, aa, stat)
                    vals = [abs(zz(1)), abs(vv(1)), abs(aa(1))]
                    call check(error, vals(i), pk(2 * i - 1), rtol=1.0e-13_dp, &
                               message=trim(label)//': value at the time')
                    if (allocated(error)) return
                end do
            end do
        end do
    end subroutine test_peaks_dense

    subroutine test_spectrum(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: periods(5), sd(5), sv(5), sa(5), tsd(5), tsv(5), tsa(5), apk, tpk, om(2), &
                    tau(2), zs, wd, xs, step
        real(dp), parameter :: res_mpmath(2) = [0.94280904158206336587_dp, &
                                                0.39627354845631398838_dp]
        type(pulse_t) :: p
        integer :: stat, i, k
        p = half_sine_pulse(3.0_dp, 0.5_dp)
        periods = [0.0_dp, 1.0e-4_dp, 0.2_dp, 0.5_dp, 2.0_dp]
        call sdof_pulse_spectrum(p, periods, 0.05_dp, sd, sv, sa, stat, t_sd=tsd, t_sv=tsv, &
                                 t_sa=tsa)
        call check(error, stat, SEISPULSE_SUCCESS, 'spectrum')
        if (allocated(error)) return
        call check(error, [sd(1), sv(1)], [0.0_dp, 0.0_dp], message='period 0')
        if (allocated(error)) return
        call check(error, sa(1), 3.0_dp, message='period 0: PGA')
        if (allocated(error)) return
        call check(error, tsa(1), 0.25_dp, message='period 0: time of PGA')
        if (allocated(error)) return
        ! a smooth pulse: T -> 0 follows the ground (z -> -a_g/omega^2)
        call check(error, sa(2), 3.0_dp, rtol=1.0e-3_dp, message='T -> 0: PGA')
        if (allocated(error)) return
        ! undamped half sine with t_d/T = tau < 1/2: the maximum is residual, after the pulse,
        ! z = -(2 A Omega/(omega (Omega^2 - omega^2))) cos(omega t_d/2) sin(omega (t - t_d/2)),
        ! Omega = pi/t_d: omega^2 sd/A = 4 tau |cos(pi tau)|/(1 - 4 tau^2) at t = t_d/2 + T/4
        ! (mpmath: tau = 0.25 gives 0.94280904158206336587, 0.1 gives 0.39627354845631398838)
        call sdof_pulse_spectrum(p, [2.0_dp, 5.0_dp], 0.0_dp, sd(1:2), sv(1:2), sa(1:2), stat, &
                                 t_sd=tsd(1:2), t_sa=tsa(1:2))
        call check(error, stat, SEISPULSE_SUCCESS, 'undamped spectrum')
        if (allocated(error)) return
        om = 2.0_dp * pi / [2.0_dp, 5.0_dp]
        tau = 0.5_dp / [2.0_dp, 5.0_dp]
        do k = 1, 2
            call check(error, om(k)**2 * sd(k) / 3.0_dp, 4.0_dp * tau(k) * cos(pi * tau(k)) &
                       / (1.0_dp - 4.0_dp * tau(k)**2), rtol=1.0e-13_dp, message='residual sd')
            if (allocated(error)) return
            call check(error, om(k)**2 * sd(k) / 3.0_dp, res_mpmath(k), rtol=1.0e-13_dp, &
                       message='residual sd (mpmath)')
            if (allocated(error)) return
            call check(error, sa(k), om(k)**2 * sd(k), rtol=1.0e-13_dp, &
                       message='undamped: a_abs = -omega^2 z')
            if (allocated(error)) return
            call check(error, tsd(k), 0.25_dp + 0.25_dp * 2.0_dp * pi / om(k), rtol=1.0e-12_dp, &
                       message='time of the residual maximum')
            if (allocated(error)) return
        end do
        ! pulses whose a_g jumps: the limit T -> 0+ is the step overshoot, not the PGA:
        ! 2 undamped; damped max of 1 - e^(-zeta x)(cos(wd x) - (zeta/wd) sin(wd x)) at
        ! wd x = pi - atan(2 zeta wd/(1 - 2 zeta^2)) (1.8587581017750918274 by mpmath)
        zs = 0.05_dp
        wd = sqrt(1.0_dp - zs**2)
        xs = (pi - atan(2.0_dp * zs * wd / (1.0_dp - 2.0_dp * zs**2))) / wd
        step = 1.0_dp - exp(-zs * xs) * (cos(wd * xs) - zs / wd * sin(wd * xs))
        call check(error, step, 1.8587581017750918274_dp, rtol=1.0e-14_dp, message='mpmath')
        if (allocated(error)) return
        do i = 1, 2
            call sdof_pulse_spectrum(rectangular_pulse(2.0_dp, 0.5_dp), [0.0_dp, 1.0e-4_dp], &
                                     merge(0.0_dp, zs, i == 1), sd(1:2), sv(1:2), sa(1:2), stat)
            call check(error, sa(1), 2.0_dp, message='rectangle, period 0: PGA')
            if (allocated(error)) return
            call check(error, sa(2) / 2.0_dp, merge(2.0_dp, step, i == 1), rtol=1.0e-9_dp, &
                       message='rectangle, T = 1e-4 s: step overshoot')
            if (allocated(error)) return
        end do
        ! peak acceleration of M&P against dense samples of pulse_at
        p = mp_pulse(0.4_dp, 0.9_dp, 2.3_dp, 40.0_dp, 1.5_dp)
        call pulse_peak_accel(p, apk, tpk, stat)
        call check(error, apk, dense_pga(p), rtol=1.0e-6_dp, message='M&P peak |a_g|')
    contains
        function dense_pga(pp) result(m)
            type(pulse_t), intent(in) :: pp
            real(dp) :: m, a, v, d
            integer :: j
            m = 0.0_dp
            do j = 0, 200000
                call pulse_at(pp, 4.0_dp * real(j, dp) / 200000.0_dp, a, v, d)
                m = max(m, abs(a))
            end do
        end function dense_pga
    end subroutine test_spectrum

    subroutine test_damped_steady_state(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: period = 0.8_dp, w0 = 2.5_dp, zeta = 0.07_dp
        real(dp), parameter :: ratios(3) = [0.5_dp, 1.0_dp, 2.0_dp]
        real(dp) :: t(5), z(5), v(5), a(5), om, th, dd, den, zr(5), vr(5), ar(5), beta
        integer :: law, k, stat
        om = 2.0_dp * pi / period
        t = [0.0_dp, 0.13_dp, 0.9_dp, 3.7_dp, 12.2_dp]
        do law = HARMONIC_SINE, HARMONIC_COSINE
            do k = 1, size(ratios)
                call harmonic_response(t, w0, period, ratios(k), zeta, law, .false., z, v, a, &
                                       stat)
                call check(error, stat, SEISPULSE_SUCCESS, 'damped steady state')
                if (allocated(error)) return
                ! z'' + 2 zeta omega z' + omega^2 z = W0 sin(theta t) (or cos): the particular
                ! solution (W0/omega^2)[(1 - r^2) sin - 2 zeta r cos]/D (cosine law:
                ! [(1 - r^2) cos + 2 zeta r sin]/D), D = (1 - r^2)^2 + (2 zeta r)^2
                th = ratios(k) * om
                dd = 1.0_dp - ratios(k)**2
                den = dd**2 + (2.0_dp * zeta * ratios(k))**2
                if (law == HARMONIC_SINE) then
                    zr = w0 / om**2 * (dd * sin(th * t) - 2.0_dp * zeta * ratios(k) &
                                       * cos(th * t)) / den
                    vr = w0 / om**2 * th * (dd * cos(th * t) + 2.0_dp * zeta * ratios(k) &
                                            * sin(th * t)) / den
                else
                    zr = w0 / om**2 * (dd * cos(th * t) + 2.0_dp * zeta * ratios(k) &
                                       * sin(th * t)) / den
                    vr = w0 / om**2 * th * (-dd * sin(th * t) + 2.0_dp * zeta * ratios(k) &
                                            * cos(th * t)) / den
                end if
                ar = -(2.0_dp * zeta * om * vr + om**2 * zr)
                call check(error, z, zr, atol=1.0e-14_dp * w0 / om**2 / sqrt(den), &
                           message='steady z')
                if (allocated(error)) return
                call check(error, v, vr, atol=1.0e-14_dp * w0 * th / om**2 / sqrt(den), &
                           message='steady v')
                if (allocated(error)) return
                call check(error, a, ar, atol=1.0e-13_dp * w0 / sqrt(den), message='steady a')
                if (allocated(error)) return
                ! the amplitude is (W0/omega^2) beta of the viscous model with gamma = 2 zeta
                call dynamic_coefficient(ratios(k), 2.0_dp * zeta, BETA_VISCOUS, beta, stat)
                call check(error, beta, 1.0_dp / sqrt(den), rtol=1.0e-14_dp, message='viscous beta')
                if (allocated(error)) return
            end do
        end do
    end subroutine test_damped_steady_state

    subroutine test_rect_huge_period(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: periods(2) = [1.0e160_dp, 1.0e200_dp]
        real(dp) :: t(3), z(3), v(3), a(3)
        integer :: k, stat
        ! t1 = 1 s, W0 = 1: for omega t -> 0 the mass stays put, z = -d_g, z' = -v_g:
        ! d_g = t^2/2 during the pulse, t1 (t - t1/2) after it (corrections (omega t)^2 < 1e-300)
        t = [0.5_dp, 2.0_dp, 7.0_dp]
        do k = 1, 2
            call rect_pulse_response(t, 1.0_dp, 1.0_dp, periods(k), z, v, a, stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'huge period')
            if (allocated(error)) return
            call check(error, z, [-0.125_dp, -1.5_dp, -6.5_dp], rtol=1.0e-15_dp, &
                       message='z = -d_g')
            if (allocated(error)) return
            call check(error, v, [-0.5_dp, -1.0_dp, -1.0_dp], rtol=1.0e-15_dp, &
                       message='v = -v_g')
            if (allocated(error)) return
            ! a_abs = omega^2 d_g: below the smallest subnormal or tiny, never NaN or Inf
            call check(error, all(abs(a) < 1.0e-300_dp) .and. all(a >= 0.0_dp), &
                       'a_abs finite and ~0')
            if (allocated(error)) return
        end do
    end subroutine test_rect_huge_period

    subroutine test_zeta_one(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: npan = 64
        real(dp) :: zetas(2), t(5), z(5), v(5), a(5), zr, vr, res(2), err, te
        type(duhamel_t) :: d
        type(pulse_t) :: p
        integer :: k, i, j, stat
        ! Re V = -Im K/sqrt(1 - zeta^2) lost ~ eps/sqrt(1 - zeta^2) (2e-8 at 1 - 2^-53); the
        ! reference is Duhamel's integral of the (accurately evaluated) kernel
        ! e^(-zeta omega s) sin(omega_d s)/omega_d over the pulse by composite G7/K15 on 64
        ! equal panels (the integrand is entire: rounding-level)
        zetas = [1.0_dp - 2.0_dp**(-53), 1.0_dp - 1.0e-12_dp]
        p = half_sine_pulse(1.0_dp, 0.5_dp)
        t = [0.05_dp, 0.2_dp, 0.35_dp, 0.5_dp, 0.9_dp]
        do k = 1, 2
            call sdof_pulse_response(p, 1.0_dp, zetas(k), t, z, v, a, stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'zeta -> 1')
            if (allocated(error)) return
            d = make_duhamel(p, 1.0_dp, zetas(k))
            d%wd = d%omega * sqrt((1.0_dp - zetas(k)) * (1.0_dp + zetas(k)))
            do i = 1, size(t)
                d%t = t(i)
                te = min(t(i), 0.5_dp)
                zr = 0.0_dp
                vr = 0.0_dp
                do j = 1, npan
                    call gk15(d, te * real(j - 1, dp) / npan, te * real(j, dp) / npan, res, err)
                    zr = zr + res(1)
                    vr = vr + res(2)
                end do
                call check(error, z(i), zr, rtol=1.0e-12_dp, message='zeta -> 1: z')
                if (allocated(error)) return
                call check(error, v(i), vr, rtol=1.0e-12_dp, message='zeta -> 1: v')
                if (allocated(error)) return
            end do
        end do
    end subroutine test_zeta_one

    subroutine test_scan_limit(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: pk(6), sd(2), sv(2), sa(2), om, zeta, wd, tmin
        type(pulse_t) :: p
        integer :: stat, k
        character(len=300) :: msg
        ! a 2 s rectangle: the scan of 2^20 steps of <= T/32 needs T >= 2/32768 s
        p = rectangular_pulse(1.0_dp, 2.0_dp)
        tmin = 2.0_dp / 32768.0_dp
        msg = ''
        call sdof_pulse_peaks(p, 2.0_dp**(-19), 0.0_dp, pk(1), pk(2), pk(3), pk(4), pk(5), &
                              pk(6), stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call check(error, index(msg, '0.6103515625E-4') > 0, 'names the shortest period: ' &
                   //trim(msg))
        if (allocated(error)) return
        call sdof_pulse_spectrum(p, [1.0_dp, 2.0_dp**(-19)], 0.02_dp, sd, sv, sa, stat, msg)
        call expect_error(error, stat, msg, 'periods(2)')
        if (allocated(error)) return
        ! just above the limit: the step response from rest, undamped 2 W0/omega^2, damped
        ! (W0/omega^2)(1 + exp(-zeta pi/sqrt(1 - zeta^2))) (first overshoot, long before 2 s)
        do k = 1, 2
            zeta = merge(0.0_dp, 0.02_dp, k == 1)
            call sdof_pulse_peaks(p, 2.0_dp * tmin, zeta, pk(1), pk(2), pk(3), pk(4), pk(5), &
                                  pk(6), stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'T = 2 tmin')
            if (allocated(error)) return
            om = 2.0_dp * pi / (2.0_dp * tmin)
            wd = sqrt(1.0_dp - zeta**2)
            call check(error, pk(1) * om**2, 1.0_dp + exp(-zeta * pi / wd), rtol=1.0e-12_dp, &
                       message='step overshoot')
            if (allocated(error)) return
        end do
        ! M&P: more than 32767 cycles cannot be scanned at 32 steps each
        call sdof_pulse_peaks(mp_pulse(0.4_dp, 1.0_dp, 40000.0_dp, 0.0_dp, 20000.0_dp), 1.0_dp, &
                              0.05_dp, pk(1), pk(2), pk(3), pk(4), pk(5), pk(6), stat, msg)
        call expect_error(error, stat, msg, 'gamma')
    end subroutine test_scan_limit

    subroutine test_mp_huge_gamma(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: gammas(2) = [1.0e5_dp, 1.0e8_dp]
        real(dp) :: apk, tpk, b
        integer :: k, stat
        ! a = (A f/2)[env' cos(phi) - 2 pi env sin(phi)] with env = 1 + cos(2 pi x/gamma):
        ! for gamma -> inf the peak is 2 pi f |A| (1 + O(1/gamma^2)), within a cycle of t0
        ! (before the fix, 64 gamma overflowed the integer step count at gamma > 3.4e7)
        do k = 1, 2
            call pulse_peak_accel(mp_pulse(0.4_dp, 0.9_dp, gammas(k), 30.0_dp, &
                                           gammas(k) / 1.8_dp), apk, tpk, stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'M&P huge gamma')
            if (allocated(error)) return
            b = 2.0_dp * pi * 0.9_dp * 0.4_dp
            call check(error, apk, b, rtol=1.0e-13_dp + 10.0_dp / gammas(k)**2, &
                       message='peak 2 pi f A')
            if (allocated(error)) return
            call check(error, abs(tpk - gammas(k) / 1.8_dp) <= 1.0_dp / 0.9_dp, &
                       'peak within a cycle of t0')
            if (allocated(error)) return
        end do
    end subroutine test_mp_huge_gamma

    subroutine test_tiny_periods(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: t(2), z(2), v(2), a(2), x, y, om, ag, vg, dg, pk(6)
        type(pulse_t) :: p
        integer :: stat, i
        character(len=256) :: msg
        p = half_sine_pulse(1.0_dp, 0.5_dp)
        t = [0.1_dp, 0.2_dp]
        ! omega = 2 pi/1e-308 overflows: refused, as seispulse_sdof_sim refuses it
        call sdof_pulse_response(p, 1.0e-308_dp, 0.05_dp, t, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call sdof_pulse_peaks(p, 1.0e-308_dp, 0.05_dp, pk(1), pk(2), pk(3), pk(4), pk(5), &
                              pk(6), stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call harmonic_response(t, 1.0_dp, 1.0e-308_dp, 0.5_dp, 0.0_dp, HARMONIC_SINE, .true., &
                               z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call impulse_max(1.0_dp, 1.0e-308_dp, 0.0_dp, x, y, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call rect_pulse_response(t, 1.0_dp, 0.5_dp, 0.5_dp * min_period, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call sdof_pulse_spectrum(p, [1.0_dp, 1.0e-308_dp], 0.05_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'periods(2)')
        if (allocated(error)) return
        ! T = 2e-60 (>= min_period) is accepted: quasi-static, z = -a_g/omega^2 (1 + O(1e-60))
        om = 2.0_dp * pi / 2.0e-60_dp
        call sdof_pulse_response(p, 2.0e-60_dp, 0.05_dp, t, z, v, a, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'T = 2e-60')
        if (allocated(error)) return
        do i = 1, 2
            call pulse_at(p, t(i), ag, vg, dg)
            call check(error, z(i) * om**2, -ag, rtol=1.0e-12_dp, message='z = -a_g/omega^2')
            if (allocated(error)) return
            call check(error, a(i), ag, rtol=1.0e-12_dp, message='a_abs = a_g')
            if (allocated(error)) return
        end do
    end subroutine test_tiny_periods

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: nan, inf, t(2), z(2), v(2), a(2), x, y, pk(6)
        type(pulse_t) :: p
        integer :: stat
        character(len=256) :: msg
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        inf = ieee_value(1.0_dp, ieee_positive_inf)
        t = [0.1_dp, 0.2_dp]
        p = half_sine_pulse(1.0_dp, 0.5_dp)
        call sdof_pulse_response(p, -1.0_dp, 0.05_dp, t, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call sdof_pulse_response(p, nan, 0.05_dp, t, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call sdof_pulse_response(p, 1.0_dp, -0.01_dp, t, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'damping')
        if (allocated(error)) return
        call sdof_pulse_response(p, 1.0_dp, 1.0_dp, t, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'damping')
        if (allocated(error)) return
        call sdof_pulse_peaks(p, 1.0_dp, nan, pk(1), pk(2), pk(3), pk(4), pk(5), pk(6), stat, msg)
        call expect_error(error, stat, msg, 'damping')
        if (allocated(error)) return
        call sdof_pulse_response(half_sine_pulse(1.0_dp, -0.5_dp), 1.0_dp, 0.05_dp, t, z, v, a, &
                                 stat, msg)
        call expect_error(error, stat, msg, 'duration')
        if (allocated(error)) return
        p%kind = 99
        call sdof_pulse_peaks(p, 1.0_dp, 0.05_dp, pk(1), pk(2), pk(3), pk(4), pk(5), pk(6), stat, &
                              msg)
        call expect_error(error, stat, msg, 'kind')
        if (allocated(error)) return
        p = half_sine_pulse(1.0_dp, 0.5_dp)
        call sdof_pulse_response(p, 1.0_dp, 0.05_dp, [0.1_dp, nan], z, v, a, stat, msg)
        call expect_error(error, stat, msg, 't(2)')
        if (allocated(error)) return
        call check(error, trim(msg) == 't(2) = NaN: must be a finite number (s)', trim(msg))
        if (allocated(error)) return
        call sdof_pulse_response(p, 1.0_dp, 0.05_dp, [inf, 0.1_dp], z, v, a, stat, msg)
        call expect_error(error, stat, msg, 't(1) = ')
        if (allocated(error)) return
        call check(error, index(msg, ': must be a finite number (s)') > 0, trim(msg))
        if (allocated(error)) return
        call sdof_pulse_spectrum(p, [0.5_dp, -0.5_dp], 0.05_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'periods(2)')
        if (allocated(error)) return
        call sdof_pulse_response(ricker_pulse(1.0_dp, 1.0_dp, 1.0_dp), 1.0e-6_dp, 0.05_dp, t, z, &
                                 v, a, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call dynamic_coefficient(-0.5_dp, 0.1_dp, BETA_HYSTERETIC, x, stat, msg)
        call expect_error(error, stat, msg, 'ratio')
        if (allocated(error)) return
        call dynamic_coefficient(0.5_dp, -0.1_dp, BETA_HYSTERETIC, x, stat, msg)
        call expect_error(error, stat, msg, 'gamma')
        if (allocated(error)) return
        call dynamic_coefficient(0.5_dp, 0.1_dp, 3, x, stat, msg)
        call expect_error(error, stat, msg, 'model')
        if (allocated(error)) return
        call harmonic_response(t, 1.0_dp, 1.0_dp, 0.5_dp, 0.0_dp, 3, .true., z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'law')
        if (allocated(error)) return
        call harmonic_response(t, nan, 1.0_dp, 0.5_dp, 0.0_dp, HARMONIC_SINE, .true., z, v, a, &
                               stat, msg)
        call expect_error(error, stat, msg, 'w0')
        if (allocated(error)) return
        call rect_pulse_response(t, 1.0_dp, 0.0_dp, 1.0_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 't1')
        if (allocated(error)) return
        call beta_pulse(-0.1_dp, BETA_PULSE_EXACT, x, stat, msg)
        call expect_error(error, stat, msg, 't1_over_period')
        if (allocated(error)) return
        call beta_pulse(0.1_dp, 7, x, stat, msg)
        call expect_error(error, stat, msg, 'variant')
        if (allocated(error)) return
        call impulse_max(1.0_dp, 0.0_dp, 0.0_dp, x, y, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call sdof_pulse_response(p, 1.0_dp, 0.05_dp, t, z(1:1), v, a, stat, msg)
        call expect_error(error, stat, msg, 'z, v, a_abs')
        if (allocated(error)) return
        ! impulse_response
        call impulse_response(t, nan, 1.0_dp, 0.0_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'jw')
        if (allocated(error)) return
        call impulse_response(t, 1.0_dp, -2.0_dp, 0.0_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        call impulse_response(t, 1.0_dp, 1.0_dp, 1.0_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'damping')
        if (allocated(error)) return
        call impulse_response([0.1_dp, inf], 1.0_dp, 1.0_dp, 0.0_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 't(2)')
        if (allocated(error)) return
        call impulse_response(t, 1.0_dp, 1.0_dp, 0.0_dp, z, v(1:1), a, stat, msg)
        call expect_error(error, stat, msg, 'z, v, a_abs')
        if (allocated(error)) return
        ! NaN and Inf ratio and times: harmonic, rectangle
        call harmonic_response(t, 1.0_dp, 1.0_dp, nan, 0.0_dp, HARMONIC_SINE, .true., z, v, a, &
                               stat, msg)
        call expect_error(error, stat, msg, 'ratio')
        if (allocated(error)) return
        call harmonic_response(t, 1.0_dp, 1.0_dp, inf, 0.05_dp, HARMONIC_COSINE, .false., z, v, &
                               a, stat, msg)
        call expect_error(error, stat, msg, 'ratio')
        if (allocated(error)) return
        call dynamic_coefficient(inf, 0.1_dp, BETA_VISCOUS, x, stat, msg)
        call expect_error(error, stat, msg, 'ratio')
        if (allocated(error)) return
        call harmonic_response([nan, 0.1_dp], 1.0_dp, 1.0_dp, 0.5_dp, 0.0_dp, HARMONIC_SINE, &
                               .true., z, v, a, stat, msg)
        call expect_error(error, stat, msg, 't(1)')
        if (allocated(error)) return
        call harmonic_response([0.1_dp, -inf], 1.0_dp, 1.0_dp, 0.5_dp, 0.05_dp, HARMONIC_SINE, &
                               .false., z, v, a, stat, msg)
        call expect_error(error, stat, msg, 't(2)')
        if (allocated(error)) return
        call rect_pulse_response([0.1_dp, inf], 1.0_dp, 0.5_dp, 1.0_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 't(2)')
        if (allocated(error)) return
        call rect_pulse_response([nan, 0.1_dp], 1.0_dp, 0.5_dp, 1.0_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 't(1)')
        if (allocated(error)) return
        call rect_pulse_response(t, 1.0_dp, inf, 1.0_dp, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 't1')
        if (allocated(error)) return
        call rect_pulse_response(t, 1.0_dp, 0.5_dp, inf, z, v, a, stat, msg)
        call expect_error(error, stat, msg, 'period')
        if (allocated(error)) return
        ! pulse_peak_accel of an invalid pulse
        call pulse_peak_accel(half_sine_pulse(1.0_dp, -0.5_dp), x, y, stat, msg)
        call expect_error(error, stat, msg, 'duration')
        if (allocated(error)) return
        call pulse_peak_accel(mp_pulse(0.4_dp, 1.0_dp, 0.5_dp, 0.0_dp, 2.0_dp), x, y, stat, msg)
        call expect_error(error, stat, msg, 'gamma')
        if (allocated(error)) return
        ! optional time arrays of the spectrum must have the length of periods
        call sdof_pulse_spectrum(p, t, 0.05_dp, z, v, a, stat, msg, t_sd=pk(1:3))
        call expect_error(error, stat, msg, 't_sd')
        if (allocated(error)) return
        call sdof_pulse_spectrum(p, t, 0.05_dp, z, v, a, stat, msg, t_sa=pk(1:1))
        call expect_error(error, stat, msg, 't_sa')
    end subroutine test_bad_input

    subroutine expect_error(error, stat, msg, name)
        type(test_error), allocatable, intent(inout) :: error
        integer, intent(in) :: stat
        character(len=*), intent(in) :: msg, name
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'expected an error naming '//name)
        if (allocated(error)) return
        call check(error, index(msg, name) == 1, 'message must start with '//name//': '//trim(msg))
    end subroutine expect_error

    !> n sine or cosine cycles: the response is the sum of the responses to the single cycle
    !> shifted by k T_p, k = 0 .. n - 1 (linearity; the single cycle's own closed form is
    !> tested against quadrature above), at times inside, at and after the pulse; also
    !> against the Duhamel quadrature directly; peaks >= a dense sample of the superposition
    !> and equal to its maximum to 1e-6; more than 32768 cycles refused by the peak search.
    subroutine test_cycles_superposition(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: nt = 241
        real(dp) :: periods(3), zetas(3), tp, t(nt), z(nt), v(nt), a(nt), zs(nt), vs(nt), &
                    as(nt), z1(nt), v1(nt), a1(nt), zm, tz, vm, tv, am, ta
        type(pulse_t) :: pn, p1
        integer :: kind, j, k, n, stat
        character(len=200) :: msg
        character(len=64) :: label
        tp = 0.8_dp
        periods = [0.8_dp, 0.33_dp, 2.1_dp]    ! resonant, short, long
        zetas = [0.0_dp, 0.05_dp, 0.2_dp]
        do kind = 1, 2
            do j = 1, 3
                n = merge(3, 20, j /= 1)
                if (kind == 1) then
                    pn = sine_cycle_pulse(1.3_dp, tp, n)
                    p1 = sine_cycle_pulse(1.3_dp, tp)
                else
                    pn = cosine_cycle_pulse(1.3_dp, tp, n)
                    p1 = cosine_cycle_pulse(1.3_dp, tp)
                end if
                t = linspace(-0.1_dp, (n + 2.5_dp) * tp, nt)
                call sdof_pulse_response(pn, periods(j), zetas(j), t, z, v, a, stat, msg)
                call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
                if (allocated(error)) return
                zs = 0.0_dp
                vs = 0.0_dp
                as = 0.0_dp
                do k = 0, n - 1
                    call sdof_pulse_response(p1, periods(j), zetas(j), t - k * tp, z1, v1, a1, &
                                             stat, msg)
                    zs = zs + z1
                    vs = vs + v1
                    as = as + a1
                end do
                write(label, '(a, i0, a, i0, a, i0)') 'kind ', kind, ' n = ', n, ' case ', j
                call check(error, z, zs, atol=1.0e-11_dp * maxval(abs(zs)), &
                           message=trim(label)//' z')
                if (allocated(error)) return
                call check(error, v, vs, atol=1.0e-11_dp * maxval(abs(vs)), &
                           message=trim(label)//' v')
                if (allocated(error)) return
                call check(error, a, as, atol=1.0e-11_dp * maxval(abs(as)), &
                           message=trim(label)//' a_abs')
                if (allocated(error)) return
                call check_against_quadrature(error, pn, periods(j), zetas(j), t(1:nt:20), &
                                              1.0e-9_dp, trim(label)//' quadrature')
                if (allocated(error)) return
                call sdof_pulse_peaks(pn, periods(j), zetas(j), zm, tz, vm, tv, am, ta, stat, msg)
                call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
                if (allocated(error)) return
                call check(error, zm >= maxval(abs(zs)) * (1.0_dp - 1.0e-12_dp) .and. &
                           zm <= maxval(abs(zs)) * (1.0_dp + 2.0e-3_dp), trim(label) &
                           //' peak |z| vs the superposition''s sample')
                if (allocated(error)) return
            end do
        end do
        pn = sine_cycle_pulse(1.0_dp, 1.0_dp, 32769)
        call sdof_pulse_peaks(pn, 1.0_dp, 0.05_dp, zm, tz, vm, tv, am, ta, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:7) == 'cycles ', trim(msg))
        if (allocated(error)) return
        pn = sine_cycle_pulse(1.0_dp, 1.0_dp, 32768)
        call sdof_pulse_peaks(pn, 100.0_dp, 0.05_dp, zm, tz, vm, tv, am, ta, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
    end subroutine test_cycles_superposition

end module test_sdof_closed
