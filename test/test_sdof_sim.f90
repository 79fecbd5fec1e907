!> The linear oscillator on records (seispulse_sdof_sim): the exact step against Gauss-
!> Legendre quadrature of Duhamel's integral over T/dt from 0.05 to 1e5 and damping
!> 0 to 0.95; the limits T -> 0 (PSA -> PGA) and T -> inf (SD -> peak ground
!> displacement); the true maxima between samples against a 256x linear upsampling
!> (which leaves the problem unchanged) and never below the sample maxima; identical
!> results with 1 and 2 OpenMP threads; the envelope, the shape and bad input.
module test_sdof_sim
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_sdof_sim, only: sdof_response, sdof_spectrum, pseudo_spectra, design_envelope, &
                              spectral_shape, SDOF_PEAKS_EXACT, SDOF_PEAKS_SAMPLES
    use seispulse_records, only: ground_motion
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_sdof_sim

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: g0 = 9.80665_dp
    integer, parameter :: ngl = 20

contains

    subroutine collect_sdof_sim(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('exact step = Duhamel quadrature (T/dt 0.05..1e5)', &
                              test_duhamel), &
                 new_unittest('T = 0 is the ground; PSA -> PGA as T -> 0', test_short_period), &
                 new_unittest('SD -> peak ground displacement as T -> inf', test_long_period), &
                 new_unittest('true maxima: >= samples, = 256x upsampled, sub-steps', &
                              test_true_maxima), &
                 new_unittest('maxima of a free vibration: closed form', test_free_vibration), &
                 new_unittest('1 and 2 threads, grouped and alone: identical spectra', &
                              test_threads), &
                 new_unittest('envelope with plateau; normalized shape', test_envelope), &
                 new_unittest('bad input names the parameter', test_bad_input)]
    end subroutine collect_sdof_sim

    ! ---------------------------------------------------------------- helpers

    !> A deterministic strong-motion-like record (g).
    function synthetic(n, dt) result(a)
        integer, intent(in) :: n
        real(dp), intent(in) :: dt
        real(dp) :: a(n), t
        integer :: i
        do i = 1, n
            t = (i - 1) * dt
            a(i) = 0.3_dp * sin(2.0_dp * pi * 1.3_dp * t) * exp(-0.4_dp * t) &
                   + 0.2_dp * sin(2.0_dp * pi * 4.7_dp * t + 0.3_dp) * t * exp(-0.9_dp * t) &
                   + 0.05_dp * cos(2.0_dp * pi * 11.0_dp * t) * exp(-1.5_dp * t)
        end do
        a(1) = 0.0_dp
    end function synthetic

    !> Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n).
    subroutine gauss_legendre(x, w)
        real(dp), intent(out) :: x(ngl), w(ngl)
        integer :: i, j, it
        real(dp) :: z, p0, p1, p2, dp1
        do i = 1, ngl
            z = cos(pi * (i - 0.25_dp) / (ngl + 0.5_dp))
            do it = 1, 100
                p0 = 1.0_dp
                p1 = z
                do j = 2, ngl
                    p2 = ((2 * j - 1) * z * p1 - (j - 1) * p0) / j
                    p0 = p1
                    p1 = p2
                end do
                dp1 = ngl * (z * p1 - p0) / (z * z - 1.0_dp)
                if (abs(p1 / dp1) < 1.0e-16_dp) exit
                z = z - p1 / dp1
            end do
            x(i) = z
            w(i) = 2.0_dp / ((1.0_dp - z * z) * dp1 * dp1)
        end do
    end subroutine gauss_legendre

    !> z(t) and z'(t) at t = (k-1) dt by Duhamel's integral, z = -int a(s) h(t - s) ds,
    !> h = e^(-zeta w u) sin(wd u)/wd, with ngl-point Gauss-Legendre on each step (the
    !> integrand is smooth there) split further so that no panel exceeds T/8.
    subroutine duhamel(a, dt, period, zeta, k, z, v)
        real(dp), intent(in) :: a(:), dt, period, zeta
        integer, intent(in) :: k
        real(dp), intent(out) :: z, v
        real(dp) :: x(ngl), w(ngl), om, wd, t, s, u, as, hp, lo, hi, e
        integer :: i, j, p, npan
        call gauss_legendre(x, w)
        om = 2.0_dp * pi / period
        wd = om * sqrt(1.0_dp - zeta * zeta)
        t = (k - 1) * dt
        z = 0.0_dp
        v = 0.0_dp
        npan = max(1, ceiling(8.0_dp * dt / period))
        do i = 1, k - 1
            do p = 1, npan
                lo = (i - 1) * dt + (p - 1) * dt / npan
                hi = (i - 1) * dt + p * dt / npan
                do j = 1, ngl
                    s = 0.5_dp * (lo + hi) + 0.5_dp * (hi - lo) * x(j)
                    as = g0 * (a(i) + (a(i + 1) - a(i)) * (s - (i - 1) * dt) / dt)
                    u = t - s
                    e = exp(-zeta * om * u)
                    hp = 0.5_dp * (hi - lo) * w(j)
                    z = z - hp * as * e * sin(wd * u) / wd
                    v = v - hp * as * e * (cos(wd * u) - zeta * om / wd * sin(wd * u))
                end do
            end do
        end do
    end subroutine duhamel

    ! ---------------------------------------------------------------- tests

    subroutine test_duhamel(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 41
        real(dp) :: a(n), dt, disp(n), vel(n), acc(n), z, v, scale_z, scale_v, om
        real(dp), parameter :: ratios(7) = [0.05_dp, 0.5_dp, 1.0_dp, 2.0_dp, 7.0_dp, &
                                            100.0_dp, 1.0e5_dp]
        real(dp), parameter :: zetas(4) = [0.0_dp, 0.05_dp, 0.3_dp, 0.95_dp]
        integer :: ir, iz, k, stat
        character(len=80) :: label
        dt = 0.02_dp
        a = synthetic(n, dt)
        do ir = 1, size(ratios)
            do iz = 1, size(zetas)
                call sdof_response(a, dt, ratios(ir) * dt, zetas(iz), g0, disp, vel, acc, stat)
                call check(error, stat == SEISPULSE_SUCCESS, 'sdof_response status')
                if (allocated(error)) return
                om = 2.0_dp * pi / (ratios(ir) * dt)
                ! natural scales: a period that divides dt can leave z' = 0 at every sample
                scale_z = max(maxval(abs(disp)), g0 * maxval(abs(a)) / om**2)
                scale_v = max(maxval(abs(vel)), g0 * maxval(abs(a)) / om)
                do k = 2, n, 3
                    call duhamel(a, dt, ratios(ir) * dt, zetas(iz), k, z, v)
                    write(label, '(a, es9.2, a, f5.2, a, i0)') 'T/dt = ', ratios(ir), &
                        ' zeta = ', zetas(iz), ' k = ', k
                    call check(error, disp(k), z, rtol=0.0_dp, atol=1.0e-11_dp * scale_z, &
                               message='z, '//trim(label))
                    if (allocated(error)) return
                    call check(error, vel(k), v, rtol=0.0_dp, atol=1.0e-11_dp * scale_v, &
                               message="z', "//trim(label))
                    if (allocated(error)) return
                    ! a_abs = -(2 zeta omega z' + omega^2 z) (g)
                    call check(error, acc(k), -(2.0_dp * zetas(iz) * om * vel(k) &
                               + om * om * disp(k)) / g0, rtol=1.0e-13_dp, &
                               atol=1.0e-13_dp * maxval(abs(acc)), message='a_abs, '//trim(label))
                    if (allocated(error)) return
                end do
            end do
        end do
    end subroutine test_duhamel

    subroutine test_short_period(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 501
        real(dp) :: a(n), dt, sd(3, 1), sv(3, 1), sa(3, 1), psv(3, 1), psa(3, 1), pga
        real(dp) :: disp(n), vel(n), acc(n)
        integer :: stat
        dt = 0.01_dp
        a = synthetic(n, dt)
        pga = maxval(abs(a))
        call sdof_spectrum(a, dt, [0.0_dp, 1.0e-4_dp, 1.0e-6_dp], [0.05_dp], g0, sd, sv, sa, &
                           stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call pseudo_spectra([0.0_dp, 1.0e-4_dp, 1.0e-6_dp], sd, g0, pga, psv, psa)
        call check(error, abs(sd(1, 1)) + abs(sv(1, 1)) < tiny(1.0_dp), 'T = 0: SD = SV = 0')
        if (allocated(error)) return
        call check(error, sa(1, 1), pga, message='T = 0: SA = PGA')
        if (allocated(error)) return
        call check(error, psa(1, 1), pga, message='T = 0: PSA = PGA')
        if (allocated(error)) return
        ! the oscillator follows the ground: omega^2 z = -a_g + O(T a_g'), PSA -> PGA
        call check(error, psa(2, 1), pga, rtol=1.0e-4_dp, message='T = 1e-4 s: PSA -> PGA')
        if (allocated(error)) return
        call check(error, sa(2, 1), pga, rtol=1.0e-4_dp, message='T = 1e-4 s: SA -> PGA')
        if (allocated(error)) return
        call check(error, psa(3, 1), pga, rtol=1.0e-6_dp, message='T = 1e-6 s: PSA -> PGA')
        if (allocated(error)) return
        call sdof_response(a, dt, 0.0_dp, 0.05_dp, g0, disp, vel, acc, stat)
        call check(error, maxval(abs(acc - a)) + maxval(abs(disp)) + maxval(abs(vel)) &
                   < tiny(1.0_dp), 'T = 0 response is the ground motion')
    end subroutine test_short_period

    subroutine test_long_period(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1001
        real(dp) :: a(n), dt, vg(n), dg(n), pgd, sd(3, 1), sv(3, 1), sa(3, 1), t
        integer :: i, stat
        ! one full sine cycle of acceleration then rest: the ground ends displaced and still,
        ! a record with a known baseline (d_g grows to 0.2 g T_p^2/(2 pi) and stays)
        dt = 0.01_dp
        a = 0.0_dp
        do i = 1, 201
            t = (i - 1) * dt
            a(i) = 0.2_dp * sin(2.0_dp * pi * t / 2.0_dp)
        end do
        a(201) = 0.0_dp
        call ground_motion(a, dt, g0, vg, dg, stat)
        pgd = maxval(abs(dg))
        ! undamped: z = -d_g + O((omega t)^2), t <= 10 s
        call sdof_spectrum(a, dt, [1.0e4_dp, 1.0e6_dp, 1.0e8_dp], [0.0_dp], g0, sd, sv, sa, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, sd(1, 1), pgd, rtol=1.0e-4_dp, message='T = 1e4 s: SD -> PGD')
        if (allocated(error)) return
        call check(error, sd(2, 1), pgd, rtol=1.0e-8_dp, message='T = 1e6 s: SD -> PGD')
        if (allocated(error)) return
        ! T/dt = 1e10: the step coefficients lose no digits (printed forms would lose all)
        call check(error, sd(3, 1), pgd, rtol=1.0e-11_dp, message='T = 1e8 s: SD -> PGD')
        if (allocated(error)) return
        call check(error, sv(3, 1), maxval(abs(vg)), rtol=1.0e-11_dp, &
                   message='T = 1e8 s: SV -> PGV')
        if (allocated(error)) return
        ! damped: the correction is first order, 2 zeta omega t
        call sdof_spectrum(a, dt, [1.0e6_dp], [0.05_dp], g0, sd(1:1, :), sv(1:1, :), &
                           sa(1:1, :), stat)
        call check(error, sd(1, 1), pgd, rtol=1.0e-5_dp, message='T = 1e6 s, 5 %: SD -> PGD')
    end subroutine test_long_period

    subroutine test_true_maxima(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 201, up = 256, nu = (n - 1) * up + 1
        real(dp), parameter :: periods(6) = [0.004_dp, 0.013_dp, 0.02_dp, 0.05_dp, 0.3_dp, &
                                             2.0_dp]
        real(dp), parameter :: zetas(2) = [0.0_dp, 0.2_dp]
        real(dp) :: a(n), au(nu), dt, sd(6, 2), sv(6, 2), sa(6, 2), sds(6, 2), svs(6, 2), &
                    sas(6, 2), ud(6, 2), uv(6, 2), ua(6, 2), tz(6, 2), disp(nu), vel(nu), &
                    acc(nu), q
        integer :: i, k, stat, ip, iz
        character(len=60) :: label
        dt = 0.01_dp
        a = synthetic(n, dt)
        do i = 1, n - 1
            do k = 0, up - 1
                q = real(k, dp) / up
                au((i - 1) * up + k + 1) = (1.0_dp - q) * a(i) + q * a(i + 1)
            end do
        end do
        au(nu) = a(n)
        call sdof_spectrum(a, dt, periods, zetas, g0, sd, sv, sa, stat, t_sd=tz)
        call check(error, stat == SEISPULSE_SUCCESS, 'exact status')
        if (allocated(error)) return
        call sdof_spectrum(a, dt, periods, zetas, g0, sds, svs, sas, stat, &
                           peaks=SDOF_PEAKS_SAMPLES)
        call check(error, stat == SEISPULSE_SUCCESS, 'samples status')
        if (allocated(error)) return
        do iz = 1, 2
            do ip = 1, size(periods)
                call sdof_response(au, dt / up, periods(ip), zetas(iz), g0, disp, vel, acc, stat)
                ud(ip, iz) = maxval(abs(disp))
                uv(ip, iz) = maxval(abs(vel))
                ua(ip, iz) = maxval(abs(acc))
            end do
        end do
        do iz = 1, 2
            do ip = 1, size(periods)
                write(label, '(a, f6.3, a, f4.1)') 'T = ', periods(ip), ' zeta = ', zetas(iz)
                ! (to rounding: sub-steps reach the samples by another sequence of operations)
                call check(error, sd(ip, iz) >= sds(ip, iz) * (1.0_dp - 1.0e-12_dp) &
                           .and. sv(ip, iz) >= svs(ip, iz) * (1.0_dp - 1.0e-12_dp) &
                           .and. sa(ip, iz) >= sas(ip, iz) * (1.0_dp - 1.0e-12_dp), &
                           'exact >= samples, '//trim(label))
                if (allocated(error)) return
                ! the upsampled maximum is below the true one by O((omega h/256)^2) at most
                call check(error, sd(ip, iz) >= ud(ip, iz) * (1.0_dp - 1.0e-13_dp), &
                           'SD >= upsampled, '//trim(label))
                if (allocated(error)) return
                call check(error, sd(ip, iz), ud(ip, iz), rtol=2.0e-3_dp, &
                           message='SD = upsampled, '//trim(label))
                if (allocated(error)) return
                call check(error, sv(ip, iz), uv(ip, iz), rtol=2.0e-3_dp, &
                           message='SV = upsampled, '//trim(label))
                if (allocated(error)) return
                call check(error, sa(ip, iz), ua(ip, iz), rtol=2.0e-3_dp, &
                           message='SA = upsampled, '//trim(label))
                if (allocated(error)) return
                call check(error, tz(ip, iz) >= 0.0_dp .and. tz(ip, iz) <= (n - 1) * dt, &
                           'time of max in the record, '//trim(label))
                if (allocated(error)) return
            end do
        end do
        ! long periods: the samples miss little, the exact maxima agree to O((omega dt)^2)
        call check(error, sd(6, 1), sds(6, 1), rtol=1.0e-3_dp, message='T = 2 s: SD ~ samples')
        if (allocated(error)) return
        ! T = 0.004 s < dt: the sample maximum misses the peaks, the exact one does not
        call check(error, sa(1, 1) > 1.01_dp * sas(1, 1) .or. sd(1, 1) > 1.01_dp * sds(1, 1), &
                   'T < dt: the exact maxima exceed the sample ones')
    end subroutine test_true_maxima

    !> A record that ends at once after a constant acceleration: the oscillator is in free
    !> vibration from a known state; its maxima between samples are closed form.
    subroutine test_free_vibration(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(2), sd(1, 1), sv(1, 1), sa(1, 1), tz(1, 1), om, per, dt, a0, zmax, tmax
        integer :: stat
        ! constant a_g = a0 over one long step, undamped: z = -(a0/om^2)(1 - cos om t),
        ! largest |z| = 2 a0/om^2 at t = T/2 (the step is 0.7 T, so no sample is there)
        per = 1.0_dp
        dt = 0.7_dp * per
        a0 = 0.3_dp
        a = [a0, a0]
        om = 2.0_dp * pi / per
        zmax = 2.0_dp * a0 * g0 / om**2
        tmax = 0.5_dp * per
        call sdof_spectrum(a, dt, [per], [0.0_dp], g0, sd, sv, sa, stat, t_sd=tz)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, sd(1, 1), zmax, rtol=1.0e-13_dp, message='undamped step: SD')
        if (allocated(error)) return
        call check(error, tz(1, 1), tmax, rtol=1.0e-8_dp, message='undamped step: time of SD')
        if (allocated(error)) return
        ! largest |z'| = a0/om at t = T/4
        call check(error, sv(1, 1), a0 * g0 / om, rtol=1.0e-13_dp, message='undamped step: SV')
        if (allocated(error)) return
        call check(error, sa(1, 1), 2.0_dp * a0, rtol=1.0e-13_dp, message='undamped step: SA')
    end subroutine test_free_vibration

    subroutine test_threads(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 2001, np = 40
        real(dp) :: a(n), per(np), sd1(np, 3), sv1(np, 3), sa1(np, 3), sd2(np, 3), &
                    sv2(np, 3), sa2(np, 3), t1(np, 3), t2(np, 3)
        real(dp), parameter :: dampings(3) = [0.0_dp, 0.05_dp, 0.2_dp]
        integer :: i, j, stat
        a = synthetic(n, 0.01_dp)
        do i = 1, np
            per(i) = 0.005_dp * 1.2_dp**(i - 1)
        end do
        call sdof_spectrum(a, 0.01_dp, per, [0.0_dp, 0.05_dp, 0.2_dp], g0, sd1, sv1, sa1, stat, &
                           threads=1, t_sa=t1)
        call sdof_spectrum(a, 0.01_dp, per, [0.0_dp, 0.05_dp, 0.2_dp], g0, sd2, sv2, sa2, stat, &
                           threads=2, t_sa=t2)
        ! bitwise: no difference at all, not even in the last bit
        call check(error, maxval(abs(sd1 - sd2)) + maxval(abs(sv1 - sv2)) &
                   + maxval(abs(sa1 - sa2)) + maxval(abs(t1 - t2)) < tiny(1.0_dp), &
                   '1 and 2 threads: bitwise identical')
        if (allocated(error)) return
        ! Groups of oscillators run side by side (mixed sub-step counts, a period 0 in the
        ! middle, several dampings): each must equal the same oscillator run alone.
        per(7) = 0.0_dp
        call sdof_spectrum(a, 0.01_dp, per, [0.0_dp, 0.05_dp, 0.2_dp], g0, sd1, sv1, sa1, stat, &
                           threads=1, t_sa=t1)
        do j = 1, 3
            do i = 1, np
                call sdof_spectrum(a, 0.01_dp, per(i:i), [dampings(j)], g0, sd2(i:i, j:j), &
                                   sv2(i:i, j:j), sa2(i:i, j:j), stat, threads=1, &
                                   t_sa=t2(i:i, j:j))
            end do
        end do
        call check(error, maxval(abs(sd1 - sd2)) + maxval(abs(sv1 - sv2)) &
                   + maxval(abs(sa1 - sa2)) + maxval(abs(t1 - t2)) < tiny(1.0_dp), &
                   'grouped = alone: bitwise identical')
    end subroutine test_threads

    subroutine test_envelope(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: env(4), env3(3), shp(4), tp, pk
        integer :: stat
        call design_envelope([0.1_dp, 0.2_dp, 0.4_dp, 1.0_dp], &
                             reshape([1.0_dp, 2.0_dp, 3.0_dp, 1.0_dp, &
                                      2.5_dp, 1.0_dp, 2.0_dp, 1.5_dp], [4, 2]), 0.3_dp, env, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'envelope status')
        if (allocated(error)) return
        ! maxima 2.5, 2, 3, 1.5; below 0.3 s held at the largest ordinate from there on (3)
        call check(error, maxval(abs(env - [3.0_dp, 3.0_dp, 3.0_dp, 1.5_dp])) < tiny(1.0_dp), &
                   'envelope values')
        if (allocated(error)) return
        call design_envelope([0.1_dp, 0.2_dp, 0.4_dp, 1.0_dp], &
                             reshape([1.0_dp, 2.0_dp, 3.0_dp, 1.0_dp, &
                                      2.5_dp, 1.0_dp, 2.0_dp, 1.5_dp], [4, 2]), 0.0_dp, env, stat)
        call check(error, maxval(abs(env - [2.5_dp, 2.0_dp, 3.0_dp, 1.5_dp])) < tiny(1.0_dp), &
                   'no plateau')
        if (allocated(error)) return
        ! any order: the same plateau, by period (peaks 2.5, 2, 3, 1.5 at 0.1, 0.2, 0.4, 1 s;
        ! below 0.3 s held at the largest at that or any longer period: 3), and a period
        ! given twice
        call design_envelope([0.4_dp, 1.0_dp, 0.1_dp, 0.2_dp], &
                             reshape([3.0_dp, 1.0_dp, 1.0_dp, 2.0_dp, &
                                      2.0_dp, 1.5_dp, 2.5_dp, 1.0_dp], [4, 2]), 0.3_dp, env, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. maxval(abs(env - [3.0_dp, 1.5_dp, &
                   3.0_dp, 3.0_dp])) < tiny(1.0_dp), 'periods in any order')
        if (allocated(error)) return
        call design_envelope([1.0_dp, 0.1_dp, 0.1_dp], reshape([1.0_dp, 2.0_dp, 2.0_dp], &
                             [3, 1]), 0.5_dp, env3, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. maxval(abs(env3 - [1.0_dp, 2.0_dp, &
                   2.0_dp])) < tiny(1.0_dp), 'a period twice')
        if (allocated(error)) return
        call spectral_shape([0.1_dp, 0.3_dp, 0.5_dp, 1.0_dp], [0.5_dp, 1.25_dp, 0.75_dp, &
                            0.2_dp], 0.5_dp, shp, tp, pk, stat)
        call check(error, maxval(abs(shp - [1.0_dp, 2.5_dp, 1.5_dp, 0.4_dp])) < 1.0e-15_dp &
                   .and. abs(tp - 0.3_dp) < tiny(1.0_dp) .and. abs(pk - 2.5_dp) < 1.0e-15_dp, &
                   'shape, its peak and the peak period')
    end subroutine test_envelope

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(5), d(5), v(5), c(5), sd(1, 1), sv(1, 1), sa(1, 1), nan, empty(0)
        real(dp) :: sd2(2, 1), sv2(2, 1), sa2(2, 1)
        integer :: stat
        character(len=256) :: msg
        nan = ieee_value(nan, ieee_quiet_nan)
        a = [0.0_dp, 0.1_dp, -0.2_dp, 0.05_dp, 0.0_dp]
        call sdof_response(a, 0.01_dp, -1.0_dp, 0.05_dp, g0, d, v, c, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'period') == 1, &
                   'negative period: '//trim(msg))
        if (allocated(error)) return
        call sdof_response(a, 0.01_dp, nan, 0.05_dp, g0, d, v, c, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'period') == 1, &
                   'NaN period: '//trim(msg))
        if (allocated(error)) return
        ! a subnormal period would make omega infinite (the answer is T = 0's, the ground)
        call sdof_response(a, 0.01_dp, 1.0e-308_dp, 0.05_dp, g0, d, v, c, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'period') == 1 &
                   .and. index(msg, '>=') > 0, 'period 1e-308: '//trim(msg))
        if (allocated(error)) return
        call sdof_response(a, 0.01_dp, 1.0_dp, 1.0_dp, g0, d, v, c, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'damping') == 1 &
                   .and. index(msg, '[0, 1)') > 0, 'damping = 1: '//trim(msg))
        if (allocated(error)) return
        call sdof_response(a, 0.01_dp, 1.0_dp, -0.01_dp, g0, d, v, c, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'damping') == 1, &
                   'negative damping: '//trim(msg))
        if (allocated(error)) return
        call sdof_response(a, 0.0_dp, 1.0_dp, 0.05_dp, g0, d, v, c, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'dt') == 1, &
                   'dt = 0: '//trim(msg))
        if (allocated(error)) return
        call sdof_response(a, -0.01_dp, 1.0_dp, 0.05_dp, g0, d, v, c, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'dt') == 1, &
                   'dt < 0: '//trim(msg))
        if (allocated(error)) return
        call sdof_spectrum(empty, 0.01_dp, [1.0_dp], [0.05_dp], g0, sd, sv, sa, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'accel') == 1 &
                   .and. index(msg, 'empty') > 0, 'empty record: '//trim(msg))
        if (allocated(error)) return
        a(3) = nan
        call sdof_spectrum(a, 0.01_dp, [1.0_dp], [0.05_dp], g0, sd, sv, sa, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'accel(3)') == 1, &
                   'NaN sample: '//trim(msg))
        if (allocated(error)) return
        a(3) = 0.2_dp
        call sdof_spectrum(a, 0.01_dp, [1.0_dp, -2.0_dp], [0.05_dp], g0, sd2, sv2, sa2, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'periods(2)') == 1, &
                   'negative period in a list: '//trim(msg))
        if (allocated(error)) return
        call sdof_spectrum(a, 0.01_dp, [1.0_dp], [0.05_dp], g0, sd2, sv2, sa2, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'sd') == 1, &
                   'output shape: '//trim(msg))
        if (allocated(error)) return
        call sdof_spectrum(a, 0.01_dp, [1.0_dp], [0.05_dp], -g0, sd, sv, sa, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'g =') == 1, &
                   'negative g: '//trim(msg))
        if (allocated(error)) return
        call sdof_spectrum(a, 0.01_dp, [1.0_dp], [0.05_dp], g0, sd, sv, sa, stat, msg, peaks=3)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'peaks') == 1, &
                   'peaks code: '//trim(msg))
        if (allocated(error)) return
        call sdof_spectrum(a, 0.01_dp, [ieee_value(nan, ieee_positive_inf)], [0.05_dp], g0, &
                           sd, sv, sa, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'periods(1)') == 1, &
                   'infinite period: '//trim(msg))
    end subroutine test_bad_input

end module test_sdof_sim
