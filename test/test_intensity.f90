!> Intensity measures of records: closed forms of piecewise-linear records (constant,
!> triangle, sampled sine, in-step sign changes), Tm against a direct DFT, spectral
!> acceleration limits, records without energy, argument errors.
module test_intensity
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_intensity, only: intensity_t, record_intensity, spectral_acceleration, &
                                   mean_period
    use seispulse_sdof_sim, only: sdof_spectrum
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_intensity

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: g0 = 9.80665_dp

contains

    subroutine collect_intensity(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('constant record: every measure in closed form', test_constant), &
                 new_unittest('triangle record: Husid times by cube roots', test_triangle), &
                 new_unittest('sampled sine: Arias and CAV by trigonometric sums', test_sine), &
                 new_unittest('sign change inside a step: CAV, PGV, PGD', test_sign_change), &
                 new_unittest('Husid curve output', test_husid_curve), &
                 new_unittest('Tm equals the direct DFT sum', test_tm_direct), &
                 new_unittest('Tm of a sine of frequency f is 1/f', test_tm_sine), &
                 new_unittest('spectral acceleration: T = 0, long T, the spectrum', test_sa), &
                 new_unittest('records without energy: NaN durations', test_no_energy), &
                 new_unittest('bad arguments are errors naming them', test_errors)]
    end subroutine collect_intensity

    !> a = c on [0, T], T = (n-1) dt.
    subroutine test_constant(error)
        type(test_error), allocatable, intent(out) :: error
        type(intensity_t) :: im
        real(dp) :: a(101), dt, c, t
        integer :: stat
        c = -0.3_dp
        dt = 0.02_dp
        a = c
        t = 100.0_dp * dt
        call record_intensity(a, dt, g0, im, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, im%pga, 0.3_dp, message='pga')
        if (allocated(error)) return
        call check(error, im%pgv, g0 * 0.3_dp * t, rtol=1.0e-13_dp, message='pgv')
        if (allocated(error)) return
        call check(error, im%pgd, g0 * 0.3_dp * t * t / 2.0_dp, rtol=1.0e-13_dp, message='pgd')
        if (allocated(error)) return
        call check(error, im%arias, pi * g0 / 2.0_dp * c * c * t, rtol=1.0e-13_dp, &
                   message='arias')
        if (allocated(error)) return
        call check(error, im%cav, g0 * 0.3_dp * t, rtol=1.0e-13_dp, message='cav')
        if (allocated(error)) return
        call check(error, im%t5, 0.05_dp * t, rtol=1.0e-13_dp, message='t5')
        if (allocated(error)) return
        call check(error, im%t75, 0.75_dp * t, rtol=1.0e-13_dp, message='t75')
        if (allocated(error)) return
        call check(error, im%t95, 0.95_dp * t, rtol=1.0e-13_dp, message='t95')
        if (allocated(error)) return
        call check(error, im%d5_75, 0.70_dp * t, rtol=1.0e-13_dp, message='d5_75')
        if (allocated(error)) return
        call check(error, im%d5_95, 0.90_dp * t, rtol=1.0e-13_dp, message='d5_95')
    end subroutine test_constant

    !> Samples 0, A, 0: H(t) = t^3 / (2 dt^3) on the first step, symmetric on the second.
    subroutine test_triangle(error)
        type(test_error), allocatable, intent(out) :: error
        type(intensity_t) :: im
        real(dp) :: a(3), dt, amp
        integer :: stat
        amp = 0.8_dp
        dt = 0.5_dp
        a = [0.0_dp, amp, 0.0_dp]
        call record_intensity(a, dt, g0, im, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, im%arias, pi * g0 / 2.0_dp * amp**2 * 2.0_dp * dt / 3.0_dp, &
                   message='arias')
        if (allocated(error)) return
        call check(error, im%cav, g0 * amp * dt, message='cav')
        if (allocated(error)) return
        call check(error, im%pgv, g0 * amp * dt, message='pgv')
        if (allocated(error)) return
        call check(error, im%pgd, g0 * amp * dt * dt, rtol=1.0e-14_dp, message='pgd')
        if (allocated(error)) return
        call check(error, im%t5, 0.1_dp**(1.0_dp / 3.0_dp) * dt, rtol=1.0e-14_dp, message='t5')
        if (allocated(error)) return
        call check(error, im%t75, (2.0_dp - 0.5_dp**(1.0_dp / 3.0_dp)) * dt, rtol=1.0e-14_dp, &
                   message='t75')
        if (allocated(error)) return
        call check(error, im%t95, (2.0_dp - 0.1_dp**(1.0_dp / 3.0_dp)) * dt, rtol=1.0e-14_dp, &
                   message='t95')
    end subroutine test_triangle

    !> a_i = A sin(theta i), m steps spanning whole cycles, M = 20 steps per half cycle:
    !> sum of a_i^2 + a_i a_j + a_j^2 over the steps = m (1 + cos(theta) / 2); CAV per
    !> half cycle = g A dt sum_{i=0}^{M} sin(pi i / M) = g A dt cot(pi / (2M)).
    subroutine test_sine(error)
        type(test_error), allocatable, intent(out) :: error
        type(intensity_t) :: im
        integer, parameter :: m_half = 20, cycles = 3, m = 2 * m_half * cycles
        real(dp) :: a(m + 1), dt, amp, theta
        integer :: i, stat
        amp = 0.25_dp
        dt = 0.01_dp
        theta = pi / real(m_half, dp)
        do i = 0, m
            a(i + 1) = amp * sin(theta * real(i, dp))
        end do
        call record_intensity(a, dt, g0, im, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, im%arias, pi * g0 / 2.0_dp * amp**2 * dt / 3.0_dp * real(m, dp) &
                   * (1.0_dp + cos(theta) / 2.0_dp), rtol=1.0e-13_dp, message='arias')
        if (allocated(error)) return
        call check(error, im%cav, real(2 * cycles, dp) * g0 * amp * dt &
                   / tan(pi / real(2 * m_half, dp)), rtol=1.0e-13_dp, message='cav')
    end subroutine test_sine

    !> Samples 1, -2 (g): a = 0 at u = 1/3, v = g dt (u - 3u^2/2) is 0 again at u = 2/3,
    !> where d = g dt^2 (u^2/2 - u^3/2) peaks at 2/27 g dt^2; |v| peaks at the end,
    !> g dt / 2; CAV = g dt (1 + 4) / (2 * 3). Samples 1, -1: PGV g dt / 4 mid-step.
    subroutine test_sign_change(error)
        type(test_error), allocatable, intent(out) :: error
        type(intensity_t) :: im
        real(dp) :: dt
        integer :: stat
        dt = 0.1_dp
        call record_intensity([1.0_dp, -2.0_dp], dt, g0, im, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, im%cav, g0 * dt * 5.0_dp / 6.0_dp, message='cav')
        if (allocated(error)) return
        call check(error, im%pgv, g0 * dt / 2.0_dp, message='pgv')
        if (allocated(error)) return
        call check(error, im%pgd, 2.0_dp / 27.0_dp * g0 * dt * dt, message='pgd')
        if (allocated(error)) return
        call record_intensity([1.0_dp, -1.0_dp], dt, g0, im, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, im%pgv, g0 * dt / 4.0_dp, message='pgv mid-step')
        if (allocated(error)) return
        call check(error, im%cav, g0 * dt / 2.0_dp, message='cav symmetric')
        if (allocated(error)) return
        call check(error, im%pgd, g0 * dt * dt / 6.0_dp, message='pgd at the end')
    end subroutine test_sign_change

    subroutine test_husid_curve(error)
        type(test_error), allocatable, intent(out) :: error
        type(intensity_t) :: im
        real(dp) :: h(4)
        integer :: stat
        ! steps of energy dt/3 (1 + 2 + 4) = 7/3, dt/3 (4 - 4 + 4) = 4/3, dt/3 (4) = 4/3
        call record_intensity([1.0_dp, 2.0_dp, -2.0_dp, 0.0_dp], 1.0_dp, g0, im, stat, &
                              husid=h)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, h, [0.0_dp, 7.0_dp / 15.0_dp, 11.0_dp / 15.0_dp, 1.0_dp], &
                   rtol=1.0e-15_dp)
    end subroutine test_husid_curve

    !> Tm from a DFT summed directly at f_k = k / (N dt), N = 2048 >= max(300, 20/0.01).
    subroutine test_tm_direct(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 300, npad = 2048
        real(dp) :: a(n), dt, tm, f, re, im_, c2, s0, s1, arg
        integer :: i, k, stat
        dt = 0.01_dp
        do i = 1, n
            a(i) = sin(0.37_dp * real(i, dp)) * exp(-0.01_dp * real(i, dp)) &
                   + 0.3_dp * cos(2.9_dp * real(i, dp) + 0.4_dp)
        end do
        call mean_period(a, dt, tm, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        s0 = 0.0_dp
        s1 = 0.0_dp
        do k = 1, npad / 2
            f = real(k, dp) / (real(npad, dp) * dt)
            if (f < 0.25_dp .or. f > 20.0_dp) cycle
            re = 0.0_dp
            im_ = 0.0_dp
            do i = 0, n - 1
                arg = 2.0_dp * pi * real(mod(i * k, npad), dp) / real(npad, dp)
                re = re + a(i + 1) * cos(arg)
                im_ = im_ - a(i + 1) * sin(arg)
            end do
            c2 = re * re + im_ * im_
            s0 = s0 + c2
            s1 = s1 + c2 / f
        end do
        call check(error, tm, s1 / s0, rtol=1.0e-12_dp)
    end subroutine test_tm_direct

    !> A sine filling the padded window (2048 samples, dt = 0.01 s) at the bin frequency
    !> f = 41 / (2048 dt): one line, Tm = 1/f to rounding. Sines of 2 Hz and 0.8 Hz over
    !> 60 s: the leakage of the finite sine biases Tm by O(1/(f T)), here < 0.4 %.
    subroutine test_tm_sine(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(2048), b(6001), dt, tm, f, freqs(2)
        integer :: i, j, stat
        dt = 0.01_dp
        f = 41.0_dp / (2048.0_dp * dt)
        do i = 1, size(a)
            a(i) = sin(2.0_dp * pi * 41.0_dp * real(i - 1, dp) / 2048.0_dp)
        end do
        call mean_period(a, dt, tm, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, tm, 1.0_dp / f, rtol=1.0e-12_dp, message='bin frequency')
        if (allocated(error)) return
        freqs = [2.0_dp, 0.8_dp]
        do j = 1, 2
            do i = 1, size(b)
                b(i) = sin(2.0_dp * pi * freqs(j) * real(i - 1, dp) * dt)
            end do
            call mean_period(b, dt, tm, stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call check(error, tm, 1.0_dp / freqs(j), rtol=5.0e-3_dp, message='60 s sine')
            if (allocated(error)) return
        end do
    end subroutine test_tm_sine

    subroutine test_sa(error)
        type(test_error), allocatable, intent(out) :: error
        type(intensity_t) :: im
        real(dp) :: a(501), dt, sa, omega, sd(1, 1), sv(1, 1), sab(1, 1)
        integer :: i, stat
        dt = 0.01_dp
        do i = 1, size(a)
            a(i) = 0.4_dp * sin(7.0_dp * real(i - 1, dp) * dt) * exp(-0.5_dp * real(i - 1, dp) &
                   * dt) - 0.1_dp * cos(19.0_dp * real(i - 1, dp) * dt)
        end do
        call record_intensity(a, dt, g0, im, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        ! T = 0: the PGA
        call spectral_acceleration(a, dt, 0.0_dp, 0.05_dp, g0, sa, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, sa, im%pga, message='T = 0')
        if (allocated(error)) return
        ! T = 1e5 s, no damping, over 5 s: the mass stays put, z = -d_g to a relative
        ! (omega t)^2 ~ 1e-7, so SD = PGD (both true peaks between samples)
        call spectral_acceleration(a, dt, 1.0e5_dp, 0.0_dp, g0, sa, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        omega = 2.0_dp * pi / 1.0e5_dp
        call check(error, sa * g0 / omega**2, im%pgd, rtol=1.0e-7_dp, message='long period')
        if (allocated(error)) return
        ! T = 0.7 s: omega^2 SD / g of the spectrum
        call spectral_acceleration(a, dt, 0.7_dp, 0.02_dp, g0, sa, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call sdof_spectrum(a, dt, [0.7_dp], [0.02_dp], g0, sd, sv, sab, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        omega = 2.0_dp * pi / 0.7_dp
        call check(error, sa, omega**2 * sd(1, 1) / g0, message='T = 0.7 s')
    end subroutine test_sa

    subroutine test_no_energy(error)
        type(test_error), allocatable, intent(out) :: error
        type(intensity_t) :: im
        real(dp) :: z(50), tm1
        integer :: stat
        z = 0.0_dp
        call record_intensity(z, 0.01_dp, g0, im, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, .not. any([im%pga, im%pgv, im%pgd, im%arias, im%cav] > 0.0_dp), &
                   'zero measures')
        if (allocated(error)) return
        call check(error, ieee_is_nan(im%t5) .and. ieee_is_nan(im%t75) .and. ieee_is_nan(im%t95) &
                   .and. ieee_is_nan(im%d5_75) .and. ieee_is_nan(im%d5_95) &
                   .and. ieee_is_nan(im%tm), 'NaN durations and Tm')
        if (allocated(error)) return
        ! one sample: no step, no motion, no energy: no Tm either (doc/intensity.md section 4)
        call record_intensity([0.2_dp], 0.01_dp, g0, im, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, im%pga, 0.2_dp)
        if (allocated(error)) return
        call check(error, .not. im%arias > 0.0_dp .and. ieee_is_nan(im%d5_95), 'one sample')
        if (allocated(error)) return
        call check(error, ieee_is_nan(im%tm), 'one sample: Tm NaN')
        if (allocated(error)) return
        call mean_period([0.2_dp], 0.01_dp, tm1, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, ieee_is_nan(tm1), 'mean_period of one sample: NaN')
    end subroutine test_no_energy

    subroutine test_errors(error)
        type(test_error), allocatable, intent(out) :: error
        type(intensity_t) :: im
        real(dp) :: e(0), sa, h(2), nan
        integer :: stat
        character(len=300) :: msg
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        msg = ''
        call record_intensity(e, 0.01_dp, g0, im, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'accel') == 1, &
                   trim(msg))
        if (allocated(error)) return
        call record_intensity([1.0_dp, 2.0_dp], 0.0_dp, g0, im, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'dt') == 1, trim(msg))
        if (allocated(error)) return
        call record_intensity([1.0_dp, 2.0_dp], 0.01_dp, -1.0_dp, im, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'g') == 1, trim(msg))
        if (allocated(error)) return
        call record_intensity([1.0_dp, nan], 0.01_dp, g0, im, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'accel(2)') == 1, &
                   trim(msg))
        if (allocated(error)) return
        call record_intensity([1.0_dp, 2.0_dp, 3.0_dp], 0.01_dp, g0, im, stat, msg, husid=h)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'husid') == 1, &
                   trim(msg))
        if (allocated(error)) return
        call record_intensity([1.0_dp, 2.0_dp], 1.0e-7_dp, g0, im, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'dt') == 1, trim(msg))
        if (allocated(error)) return
        ! a^2 overflows, the velocity and displacement do not
        call record_intensity([1.0e160_dp, 1.0e160_dp], 1.0_dp, g0, im, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'overflows') > 0, &
                   'overflow: '//trim(msg))
        if (allocated(error)) return
        call spectral_acceleration([1.0_dp, 2.0_dp], 0.01_dp, -1.0_dp, 0.05_dp, g0, sa, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'period') == 1, &
                   trim(msg))
        if (allocated(error)) return
        call spectral_acceleration([1.0_dp, 2.0_dp], 0.01_dp, 1.0_dp, 1.0_dp, g0, sa, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'damping') == 1, &
                   trim(msg))
    end subroutine test_errors

end module test_intensity
