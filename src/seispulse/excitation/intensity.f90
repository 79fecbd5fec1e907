!> Ground-motion intensity measures of a record (doc/intensity.md): peak ground
!> acceleration, velocity and displacement, Arias intensity [A70], cumulative absolute
!> velocity [EPRI88], the significant durations D5-75 and D5-95 of the Husid curve [TB75],
!> the mean period Tm [RAB98], [RFRB04] and the spectral acceleration at a period.
!>
!> The record is linear between samples (the convention of the whole library,
!> doc/records.md), accel(i) at t = (i-1) dt: the first sample is the time origin. Every
!> integral is taken in closed form on each step (doc/intensity.md (I.1)-(I.12)): PGV and
!> PGD are the true maxima of the piecewise quadratic velocity and piecewise cubic
!> displacement of seispulse_records `ground_motion` (between samples too); the Husid
!> times are located inside their step by Brent's method on the cubic cumulative
!> integral, on a bracket that holds by construction.
!>
!> A record without energy (every sample 0, or a single sample) has no Husid curve: its
!> durations, times and Tm are NaN, as is Tm when no frequency of 0.25-20 Hz carries
!> energy; this is no error (doc/intensity.md section 4).
module seispulse_intensity
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_format, only: int_str, real_str
    use seispulse_special, only: pi
    use seispulse_roots, only: scalar_function, find_root
    use seispulse_fft, only: fft, next_power_of_two
    use seispulse_pieces, only: record_step_check
    use seispulse_optval, only: optval
    use seispulse_records, only: record_pga, ground_motion, STANDARD_GRAVITY
    use seispulse_sdof_sim, only: sdof_validate, sdof_spectrum, pseudo_spectra
    implicit none
    private

    public :: intensity_t, record_intensity, spectral_acceleration, mean_period
    public :: TM_F_LOW, TM_F_HIGH, TM_DF_MAX, TM_MAX_POINTS

    real(dp), parameter :: TM_F_LOW = 0.25_dp   !! lower end of the Tm band (Hz) [RAB98]
    real(dp), parameter :: TM_F_HIGH = 20.0_dp  !! upper end of the Tm band (Hz) [RAB98]
    real(dp), parameter :: TM_DF_MAX = 0.05_dp  !! largest frequency step of the Tm FFT (Hz)
    !> Largest padded FFT length for Tm (2^23 points, 134 MB of complex numbers): a record
    !> needs 20/dt points or more, so dt must be > 20/2^23 = 2.4e-6 s.
    integer, parameter :: TM_MAX_POINTS = 2**23

    !> Intensity measures of one record.
    type :: intensity_t
        real(dp) :: pga = 0.0_dp    !! peak ground acceleration max |a| (g)
        real(dp) :: pgv = 0.0_dp    !! peak ground velocity max |v| (m/s), between samples too
        real(dp) :: pgd = 0.0_dp    !! peak ground displacement max |d| (m), between samples too
        real(dp) :: arias = 0.0_dp  !! Arias intensity pi/(2g) int a^2 dt, a in m/s^2 (m/s)
        real(dp) :: cav = 0.0_dp    !! cumulative absolute velocity int |a| dt (m/s)
        real(dp) :: d5_75 = 0.0_dp  !! significant duration t75 - t5 (s)
        real(dp) :: d5_95 = 0.0_dp  !! significant duration t95 - t5 (s)
        real(dp) :: t5 = 0.0_dp     !! time the Husid curve reaches 5 % (s from the first sample)
        real(dp) :: t75 = 0.0_dp    !! time the Husid curve reaches 75 % (s)
        real(dp) :: t95 = 0.0_dp    !! time the Husid curve reaches 95 % (s)
        real(dp) :: tm = 0.0_dp     !! mean period (s) [RAB98]: 0.25-20 Hz, df <= 0.05 Hz
    end type intensity_t

    !> The Husid crossing inside one step: F(u) - delta, with F(u) the integral of the
    !> squared (scaled) acceleration from the start of the step to u dt, over dt
    !> (doc/intensity.md (I.10)).
    type, extends(scalar_function) :: husid_step_t
        real(dp) :: bi = 0.0_dp     !! scaled acceleration at the start of the step
        real(dp) :: bj = 0.0_dp     !! scaled acceleration at its end
        real(dp) :: delta = 0.0_dp  !! the part of the target left for this step
    contains
        procedure :: eval => husid_step_eval
    end type husid_step_t

contains

    ! ------------------------------------------------------------------------------
    ! Public API
    ! ------------------------------------------------------------------------------

    !> Intensity measures of a record (doc/intensity.md): accel in g at t = (i-1) dt,
    !> linear between samples. `husid` (optional, size(accel)) returns the normalized
    !> Husid curve at the samples (0 .. 1; all 0 for a record without energy).
    !>
    !> stat = SEISPULSE_INVALID_INPUT for an empty record, a non-finite sample, dt or
    !> g not finite and > 0, a result that overflows, or a dt so small that the Tm FFT
    !> would exceed TM_MAX_POINTS points.
    subroutine record_intensity(accel, dt, g, im, stat, errmsg, husid)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (g)
        real(dp), intent(in) :: dt                            !! time step (s), > 0
        real(dp), intent(in) :: g                             !! gravity (m/s^2), > 0
        type(intensity_t), intent(out) :: im                  !! the measures
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(out), optional :: husid(:)           !! normalized Husid curve (-)
        real(dp), allocatable :: vel(:), disp(:), cum(:), scaled(:)  !! scaled: accel / PGA
        real(dp) :: nan, e_tot, s_cav, scale
        integer :: n

        call record_step_check(accel, dt, g, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        n = size(accel)
        if (present(husid)) then
            if (size(husid) /= n) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'husid: size ' &
                               //int_str(size(husid))//', must be the size of accel (' &
                               //int_str(n)//')')
                return
            end if
            husid(:) = 0.0_dp
        end if
        nan = ieee_value(1.0_dp, ieee_quiet_nan)

        ! peaks (I.1)-(I.4): velocity and displacement from seispulse_records
        im%pga = record_pga(accel)
        allocate(vel(n), disp(n))
        call ground_motion(accel, dt, g, vel, disp, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call motion_peaks(accel, dt, g, vel, disp, im%pgv, im%pgd)

        ! the integrals on the record scaled by its PGA (no overflow of a^2)
        scale = im%pga
        if (.not. scale > 0.0_dp) scale = 1.0_dp
        allocate(cum(n))
        scaled = accel / scale
        call scaled_integrals(scaled, cum, s_cav)
        e_tot = cum(n)
        im%arias = safe_product([pi / 2.0_dp, g, dt, e_tot, scale, scale])  ! (I.5), (I.6)
        im%cav = safe_product([g, dt, s_cav, scale])                         ! (I.7), (I.8)
        if (im%arias < 0.0_dp .or. im%cav < 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel, dt, g: the Arias ' &
                           //'intensity or the CAV overflows')
            return
        end if

        ! Husid times (I.9), (I.10) and durations (I.11), (I.12)
        if (e_tot > 0.0_dp) then
            if (present(husid)) husid(:) = cum / e_tot
            call husid_time(scaled, dt, cum, 0.05_dp, im%t5, stat, errmsg)
            if (stat == SEISPULSE_SUCCESS) &
                call husid_time(scaled, dt, cum, 0.75_dp, im%t75, stat, errmsg)
            if (stat == SEISPULSE_SUCCESS) &
                call husid_time(scaled, dt, cum, 0.95_dp, im%t95, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            im%d5_75 = im%t75 - im%t5
            im%d5_95 = im%t95 - im%t5
        else
            im%t5 = nan
            im%t75 = nan
            im%t95 = nan
            im%d5_75 = nan
            im%d5_95 = nan
        end if

        call mean_period(accel, dt, im%tm, stat, errmsg)
    end subroutine record_intensity

    !> Mean period Tm (s) of a record [RAB98] (doc/intensity.md (I.13)-(I.16)):
    !>     Tm = sum(C_k^2 / f_k) / sum(C_k^2)   over 0.25 Hz <= f_k <= 20 Hz,
    !> C_k = |X_k| the amplitudes of the DFT of the samples zero-padded to
    !> N = next power of two >= max(n, 20/dt) points (df = 1/(N dt) <= 0.05 Hz),
    !> f_k = k / (N dt). NaN for a record without energy (every sample 0, or a single
    !> sample: no step, no motion) and when no frequency of the band carries energy.
    subroutine mean_period(accel, dt, tm, stat, errmsg)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (any units)
        real(dp), intent(in) :: dt                            !! time step (s), > 0
        real(dp), intent(out) :: tm                           !! mean period (s)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        complex(dp), allocatable :: x(:)
        real(dp) :: pga, need, df, f, c2, s0, s1
        integer :: n, npad, k

        tm = ieee_value(1.0_dp, ieee_quiet_nan)
        call record_step_check(accel, dt, 1.0_dp, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        n = size(accel)
        need = 1.0_dp / (TM_DF_MAX * dt)                     ! points for df <= 0.05 Hz (I.14)
        if (need > real(TM_MAX_POINTS, dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dt = '//real_str(dt) &
                           //': Tm needs df <= 0.05 Hz, i.e. 1/(0.05 dt) FFT points, more than ' &
                           //int_str(TM_MAX_POINTS)//' (dt must be > '//real_str( &
                           1.0_dp / (TM_DF_MAX * real(TM_MAX_POINTS, dp)))//' s)')
            return
        end if
        npad = next_power_of_two(max(n, ceiling(need)))
        if (npad < 0 .or. npad > TM_MAX_POINTS) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel: '//int_str(n) &
                           //' samples, Tm needs an FFT of more than '//int_str(TM_MAX_POINTS) &
                           //' points')
            return
        end if
        pga = record_pga(accel)
        if (.not. pga > 0.0_dp .or. n < 2) return
        allocate(x(npad))
        x(:) = (0.0_dp, 0.0_dp)
        x(1:n) = cmplx(accel / pga, 0.0_dp, kind=dp)
        call fft(x, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        df = 1.0_dp / (real(npad, dp) * dt)
        s0 = 0.0_dp
        s1 = 0.0_dp
        do k = 1, npad / 2
            f = real(k, dp) * df                              ! (I.15)
            if (f > TM_F_HIGH) exit
            if (f < TM_F_LOW) cycle
            c2 = real(x(k + 1), dp)**2 + aimag(x(k + 1))**2
            s0 = s0 + c2
            s1 = s1 + c2 / f
        end do
        if (s0 > 0.0_dp) tm = s1 / s0                         ! (I.13)
    end subroutine mean_period

    !> Spectral (pseudo-)acceleration PSA = omega^2 SD / g (g) of the oscillator of
    !> period `period` (s) and damping ratio `damping` under the record
    !> (doc/intensity.md (I.17)), from the exact response of seispulse_sdof_sim with the
    !> true peak between samples; period 0 gives the PGA.
    !> damping and g are optional (defaults 0.05 and STANDARD_GRAVITY, as Python's
    !> `records.spectral_acceleration`); when one is omitted, pass sa and stat by keyword.
    subroutine spectral_acceleration(accel, dt, period, damping, g, sa, stat, errmsg)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (g)
        real(dp), intent(in) :: dt                            !! time step (s), > 0
        real(dp), intent(in) :: period                        !! natural period (s), >= 0
        !> damping ratio, in [0, 1); default 0.05
        real(dp), intent(in), optional :: damping
        !> gravity (m/s^2), > 0; default STANDARD_GRAVITY (9.80665 m/s^2)
        real(dp), intent(in), optional :: g
        real(dp), intent(out) :: sa                           !! PSA (g)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: sd(1, 1), sv(1, 1), sa_abs(1, 1), psv(1, 1), psa(1, 1)
        real(dp) :: damping_in, g_in
        damping_in = optval(damping, 0.05_dp)
        g_in = optval(g, STANDARD_GRAVITY)
        sa = 0.0_dp
        call record_step_check(accel, dt, g_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call sdof_validate(period, damping_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call sdof_spectrum(accel, dt, [period], [damping_in], g_in, sd, sv, sa_abs, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call pseudo_spectra([period], sd, g_in, record_pga(accel), psv, psa)
        sa = psa(1, 1)
        if (.not. ieee_is_finite(sa)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel, period: the ' &
                           //'spectral acceleration overflows')
            sa = 0.0_dp
        end if
    end subroutine spectral_acceleration

    ! ------------------------------------------------------------------------------
    ! Internals
    ! ------------------------------------------------------------------------------

    !> PGV and PGD: the largest |v| and |d| at the samples and inside the steps
    !> (doc/intensity.md (I.3), (I.4)). On a step u = tau/dt in [0, 1]:
    !>     v(u) = v_i + g dt (a_i u + (a_j - a_i) u^2 / 2),
    !>     d(u) = d_i + v_i dt u + g dt^2 (a_i u^2 / 2 + (a_j - a_i) u^3 / 6);
    !> v has its interior extremum where a changes sign, d where v does.
    pure subroutine motion_peaks(a, dt, g, vel, disp, pgv, pgd)
        real(dp), intent(in) :: a(:), dt, g, vel(:), disp(:)
        real(dp), intent(out) :: pgv, pgd
        integer :: i
        real(dp) :: us, vs, vlo, vhi, c0, c1, c2, q, disc, roots(2)
        pgv = 0.0_dp
        pgd = 0.0_dp
        do i = 1, size(a)
            pgv = max(pgv, abs(vel(i)))
            pgd = max(pgd, abs(disp(i)))
        end do
        do i = 1, size(a) - 1
            vlo = min(vel(i), vel(i + 1))
            vhi = max(vel(i), vel(i + 1))
            if ((a(i) > 0.0_dp .and. a(i + 1) < 0.0_dp) .or. &
                (a(i) < 0.0_dp .and. a(i + 1) > 0.0_dp)) then
                us = a(i) / (a(i) - a(i + 1))                            ! a(us) = 0
                vs = vel(i) + 0.5_dp * g * dt * a(i) * us                ! (I.3)
                pgv = max(pgv, abs(vs))
                vlo = min(vlo, vs)
                vhi = max(vhi, vs)
            end if
            if (vlo >= 0.0_dp .or. vhi <= 0.0_dp) cycle
            ! v changes sign inside the step: roots of c0 + c1 u + c2 u^2 in (0, 1)
            c0 = vel(i)
            c1 = g * dt * a(i)
            c2 = 0.5_dp * g * dt * (a(i + 1) - a(i))
            q = max(abs(c0), abs(c1), abs(c2))        ! > 0: v changes sign; no overflow below
            c0 = c0 / q
            c1 = c1 / q
            c2 = c2 / q
            roots = -1.0_dp
            if (.not. abs(c2) > 0.0_dp) then
                if (abs(c1) > 0.0_dp) roots(1) = -c0 / c1
            else
                disc = c1 * c1 - 4.0_dp * c2 * c0
                if (disc >= 0.0_dp) then
                    q = -0.5_dp * (c1 + sign(sqrt(disc), c1))
                    roots(1) = q / c2
                    if (abs(q) > 0.0_dp) roots(2) = c0 / q
                end if
            end if
            if (roots(1) > 0.0_dp .and. roots(1) < 1.0_dp) pgd = max(pgd, abs(d_at(roots(1))))
            if (roots(2) > 0.0_dp .and. roots(2) < 1.0_dp) pgd = max(pgd, abs(d_at(roots(2))))
        end do
    contains
        pure real(dp) function d_at(u)                                  ! (I.4)
            real(dp), intent(in) :: u
            d_at = disp(i) + vel(i) * dt * u + g * dt * dt * u * u &
                   * (a(i) / 2.0_dp + (a(i + 1) - a(i)) * u / 6.0_dp)
        end function d_at
    end subroutine motion_peaks

    !> The product of non-negative finite factors, -1 when it would overflow (formed as
    !> the product of their fractions scaled by the sum of their exponents, so no
    !> intermediate product overflows either).
    pure real(dp) function safe_product(f) result(p)
        real(dp), intent(in) :: f(:)
        integer :: e
        p = 0.0_dp
        if (.not. all(f > 0.0_dp)) return
        e = sum(exponent(f))
        if (e > maxexponent(1.0_dp)) then
            p = -1.0_dp
        else
            p = scale(product(fraction(f)), e)
        end if
    end function safe_product

    !> The cumulative integral of b^2 over t/dt at the samples, cum(1) = 0 (I.6), and the
    !> integral of |b| over t/dt (I.8), for b linear between samples.
    pure subroutine scaled_integrals(b, cum, s_abs)
        real(dp), intent(in) :: b(:)
        real(dp), intent(out) :: cum(:)
        real(dp), intent(out) :: s_abs
        integer :: i
        real(dp) :: x, y
        cum(1) = 0.0_dp
        s_abs = 0.0_dp
        do i = 1, size(b) - 1
            x = b(i)
            y = b(i + 1)
            cum(i + 1) = cum(i) + (x * x + x * y + y * y) / 3.0_dp           ! (I.6)
            if ((x >= 0.0_dp .and. y >= 0.0_dp) .or. (x <= 0.0_dp .and. y <= 0.0_dp)) then
                s_abs = s_abs + 0.5_dp * (abs(x) + abs(y))                   ! (I.8)
            else
                s_abs = s_abs + 0.5_dp * (x * x + y * y) / (abs(x) + abs(y))
            end if
        end do
    end subroutine scaled_integrals

    !> The first time (s from the first sample) the Husid curve reaches the fraction p:
    !> the first step whose end value reaches p cum(n), then the root of (I.10) in it.
    subroutine husid_time(b, dt, cum, p, t, stat, errmsg)
        real(dp), intent(in) :: b(:), dt, cum(:), p
        real(dp), intent(out) :: t
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(husid_step_t) :: f
        real(dp) :: target, step_int, u
        integer :: k, n
        stat = SEISPULSE_SUCCESS
        n = size(b)
        target = p * cum(n)
        k = n - 1
        do while (k > 1)
            if (cum(k) < target) exit
            k = k - 1
        end do
        ! now cum(k) < target <= cum(k + 1) (cum(1) = 0 < target); first such k
        f%bi = b(k)
        f%bj = b(k + 1)
        f%delta = target - cum(k)
        step_int = (b(k)**2 + b(k) * b(k + 1) + b(k + 1)**2) / 3.0_dp
        if (.not. f%delta > 0.0_dp) then
            u = 0.0_dp
        else if (step_int - f%delta <= 0.0_dp) then
            u = 1.0_dp
        else
            call find_root(f, 0.0_dp, 1.0_dp, u, stat, errmsg, fa_known=-f%delta, &
                           fb_known=step_int - f%delta)
            if (stat /= SEISPULSE_SUCCESS) return
        end if
        t = (real(k - 1, dp) + u) * dt
    end subroutine husid_time

    !> F(u) - delta, F(u) = b_i^2 (1 - (1-u)^3)/3 + b_i b_j (u^2 - 2u^3/3) + b_j^2 u^3/3
    !> (doc/intensity.md (I.10)), nondecreasing in u.
    function husid_step_eval(self, x) result(y)
        class(husid_step_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        y = self%bi**2 * x * (3.0_dp + x * (x - 3.0_dp)) / 3.0_dp &
            + self%bi * self%bj * x * x * (1.0_dp - 2.0_dp * x / 3.0_dp) &
            + self%bj**2 * x**3 / 3.0_dp - self%delta
    end function husid_step_eval

end module seispulse_intensity
