!> The linear oscillator on accelerograms: exact response histories and response
!> spectra (doc/oscillator.md section 6, Eqs. 2.27-2.33), the design envelope and the
!> normalized spectral shape of the spectral theory (СНиП II-7-81).
!>
!> The oscillator (natural period T, omega = 2 pi/T, viscous damping ratio zeta; the
!> book's gamma = 2 zeta) starts from rest under the ground acceleration a_g:
!>     z'' + 2 zeta omega z' + omega^2 z = -a_g(t),   z(0) = z'(0) = 0,
!> with z the displacement relative to the ground and a_abs = a_g + z'' =
!> -(2 zeta omega z' + omega^2 z) the absolute acceleration of the mass.
!>
!> Exact recurrence. The record is linear between samples (as everywhere in
!> seispulse), so each step is solved exactly (Nigam & Jennings 1968): with the state
!> x = (z, z'), x' = A x - e a_g, A = [0 1; -omega^2 -2 zeta omega], e = (0, 1),
!>     x(h) = e^(hA) x(0) - h phi_1(hA) e a_n - h phi_2(hA) e (a_(n+1) - a_n),
!> where phi_k are the exponential phi functions. A function f of the 2x2 matrix hA is
!> f(hA) = alpha I + beta hA with beta = Im f(mu)/Im mu, alpha = Re f(mu) - beta Re mu
!> at the eigenvalue mu = h(-zeta omega + i omega_d) (Cayley-Hamilton), and f(mu)
!> comes from `complex_phis`: a series near 0, so no coefficient loses digits when
!> h << T (the printed Nigam-Jennings coefficients lose ~ eps/(omega h)^2 there).
!>
!> True maxima between samples (SDOF_PEAKS_EXACT, the default). Within a step
!> each response q in {z, z', a_abs} is a line plus a damped sinusoid, and q'' is a
!> damped sinusoid e^(-zeta omega tau) (E cos omega_d tau + F sin omega_d tau), whose
!> zeros are pi/omega_d apart. On a step shorter than T_d/2 (longer steps are split
!> into equal sub-steps, still exact) q'' therefore has at most one zero, found from
!> its phase, and q' is monotone on each side of it: every interior extremum of q is
!> bracketed by a sign change of q' and found by safeguarded Newton (the bracket
!> shrinks at every step, at most 100 steps). A step is examined only when the bound
!> |q| <= max(|q_n|, |q_(n+1)|) + h^2 max|q''|/8 can beat the running maximum, so the
!> cost is that of the recurrence except near peaks. Above max_sub_steps sub-steps per
!> record step only the first and the last damped period of each record step are
!> searched (`cycles_run`, where the proof is): the cost is bounded whatever T/dt.
!> SDOF_PEAKS_SAMPLES takes the
!> maxima over the samples only (what eqsig, OpenSees and most programs report).
!> Maxima are taken over the duration of the record (no free vibration after it);
!> T = 0 is the ground itself: SD = SV = 0, SA = PGA.
!>
!> Spectra run up to four (period, damping) pairs side by side in one loop (independent
!> recurrences fill the vector units and hide each other's latency), one such group per
!> OpenMP thread when the library is built with OpenMP. Each pair's arithmetic is the
!> same whatever its neighbours and the groups are formed before the threads start,
!> so the results are identical to a serial run, bit for bit.
module seispulse_sdof_sim
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_format, only: real_str, int_str
    use seispulse_optval, only: optval
    use seispulse_records, only: STANDARD_GRAVITY
    use seispulse_special, only: complex_phis, pi
    use seispulse_pieces, only: record_step_check, record_in_si
    !$ use omp_lib, only: omp_set_num_threads, omp_get_max_threads
    implicit none
    private

    public :: sdof_step_t, sdof_step, sdof_validate, sdof_response, sdof_spectrum
    public :: pseudo_spectra, design_envelope, spectral_shape, sdof_threads
    public :: SDOF_PEAKS_EXACT, SDOF_PEAKS_SAMPLES

    integer, parameter :: SDOF_PEAKS_EXACT = 1    !! true maxima, between samples too
    integer, parameter :: SDOF_PEAKS_SAMPLES = 2  !! maxima over the samples only

    !> Safeguarded Newton: iteration limit (each step at least halves the bracket or
    !> converges quadratically, so 100 is never reached in double precision).
    integer, parameter :: max_newton = 100

    !> The shortest positive period accepted (s): omega^2 and its powers stay finite.
    real(dp), parameter, public :: min_period = 1.0e-60_dp

    !> Oscillators run side by side in one spectrum loop (see oscillator_peaks).
    integer, parameter :: lanes = 4

    !> Exact peaks: above this many sub-steps per record step, only the first and the
    !> last damped cycle of each record step are searched (`cycles_run`).
    integer, parameter :: max_sub_steps = 64

    !> Sub-steps of 0.4 T_d in each searched window: the windows span 1.2 T_d > T_d.
    integer, parameter :: window_steps = 3

    !> One exact step of length h for a given oscillator: the state after the step is
    !>     z+ = e11 z + e12 v + b1 a_n + c1 a_(n+1)
    !>     v+ = e21 z + e22 v + b2 a_n + c2 a_(n+1)      (a in the units the b, c expect).
    type :: sdof_step_t
        real(dp) :: omega = 0.0_dp  !! natural circular frequency (rad/s)
        real(dp) :: zeta = 0.0_dp   !! damping ratio
        real(dp) :: wd = 0.0_dp     !! damped circular frequency omega sqrt(1 - zeta^2) (rad/s)
        real(dp) :: h = 0.0_dp      !! step (s)
        real(dp) :: e11 = 1.0_dp, e12 = 0.0_dp, e21 = 0.0_dp, e22 = 1.0_dp
        real(dp) :: b1 = 0.0_dp, b2 = 0.0_dp, c1 = 0.0_dp, c2 = 0.0_dp
        real(dp) :: inv_h = 0.0_dp   !! 1/h (1/s)
        real(dp) :: inv_wd = 0.0_dp  !! 1/omega_d (s)
        real(dp) :: h4_64 = 0.0_dp   !! h^4/64 (s^4): the interior-peak filter of exact_step
    end type sdof_step_t

    !> The running maximum of one response quantity.
    type :: peak_t
        real(dp) :: value = 0.0_dp  !! largest |q| so far
        real(dp) :: time = 0.0_dp   !! where it occurs (s): within the step `step`, or absolute
        integer :: step = 0         !! exact runs: the (sub-)step the time is counted in, 0: absolute
    end type peak_t

contains

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> Check a period and a damping ratio: T = 0 or min_period <= T finite, 0 <= zeta < 1.
    !> `period_name`, `damping_name` name them in the message (e.g. 'periods(3)').
    subroutine sdof_validate(period, damping, stat, errmsg, period_name, damping_name)
        real(dp), intent(in) :: period                        !! natural period (s)
        real(dp), intent(in) :: damping                       !! damping ratio
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> name in messages; default 'period'
        character(len=*), intent(in), optional :: period_name
        !> name in messages; default 'damping'
        character(len=*), intent(in), optional :: damping_name
        character(len=:), allocatable :: pname, dname
        stat = SEISPULSE_SUCCESS
        pname = 'period'
        if (present(period_name)) pname = period_name
        dname = 'damping'
        if (present(damping_name)) dname = damping_name
        if (.not. ieee_is_finite(period)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, pname//' = ' &
                           //real_str(period)//': the period must be finite and >= 0 (s)')
        else if (period < 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, pname//' = ' &
                           //real_str(period)//': the period must be finite and >= 0 (s)')
        else if (period > 0.0_dp .and. period < min_period) then
            ! omega^2 must stay finite; T = 0 is the rigid limit
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, pname//' = ' &
                           //real_str(period)//': a positive period must be >= ' &
                           //real_str(min_period)//' s (0 for the rigid oscillator)')
        else if (.not. ieee_is_finite(damping)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, dname//' = ' &
                           //real_str(damping)//': the damping ratio must be in [0, 1)')
        else if (damping < 0.0_dp .or. damping >= 1.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, dname//' = ' &
                           //real_str(damping)//': the damping ratio must be in [0, 1)')
        end if
    end subroutine sdof_validate


    ! ------------------------------------------------------------------------------
    ! The exact step
    ! ------------------------------------------------------------------------------

    !> Coefficients of one exact step of length h (s) for period T > 0 (s) and damping
    !> 0 <= zeta < 1, for a_g in m/s^2 (multiply b, c by g for a_g in g). Unchecked. The
    !> same formulas hold for negative damping -1 < zeta < 0 (a growing response;
    !> seispulse_flexible_exact uses them for the total damping of a sliding mass).
    pure function sdof_step(period, zeta, h) result(st)
        real(dp), intent(in) :: period  !! natural period (s), > 0
        real(dp), intent(in) :: zeta    !! damping ratio, in (-1, 1)
        real(dp), intent(in) :: h       !! step (s), > 0
        type(sdof_step_t) :: st
        st%omega = 2.0_dp * pi / period
        st%zeta = zeta
        st%wd = st%omega * sqrt((1.0_dp - zeta) * (1.0_dp + zeta))
        st%h = h
        st%inv_h = 1.0_dp / h
        st%inv_wd = 1.0_dp / st%wd
        st%h4_64 = h**4 / 64.0_dp
        call set_coefficients(st, h)
    end function sdof_step

    !> The coefficients e, b, c of st for a step of length tau (the oscillator fields of
    !> st already set).
    pure subroutine set_coefficients(st, tau)
        type(sdof_step_t), intent(inout) :: st
        real(dp), intent(in) :: tau
        real(dp) :: a0, bt0, a1, bt1, a2, bt2, aq, bq, zwh
        zwh = st%zeta * st%omega * tau
        call matrix_functions(st, tau, a0, bt0, a1, bt1, a2, bt2)
        ! e^(tau A) = a0 I + bt0 tau A
        st%e11 = a0 + zwh * bt0
        st%e12 = bt0 * tau
        st%e21 = -bt0 * st%omega**2 * tau
        st%e22 = a0 - zwh * bt0
        ! forcing -a_g: -tau (phi_1 - phi_2)(tau A) e a_n - tau phi_2(tau A) e a_(n+1);
        ! F e = (b tau, a - b zwh)
        aq = a1 - a2
        bq = bt1 - bt2
        st%b1 = -tau * (bq * tau)
        st%b2 = -tau * (aq - zwh * bq)
        st%c1 = -tau * (bt2 * tau)
        st%c2 = -tau * (a2 - zwh * bt2)
    end subroutine set_coefficients

    !> Re f(mu) and beta = Im f(mu)/Im mu for f = exp, phi_1, phi_2 at mu = tau lambda,
    !> lambda = -zeta omega + i omega_d: f(tau A) = (Re f + beta zeta omega tau) I
    !> + beta tau A. Returned as (a_k, b_k) with a_k = Re f(mu) (the zeta terms are
    !> added by the callers, where they belong).
    pure subroutine matrix_functions(st, tau, a0, b0, a1, b1, a2, b2)
        type(sdof_step_t), intent(in) :: st
        real(dp), intent(in) :: tau
        real(dp), intent(out) :: a0, b0, a1, b1, a2, b2
        complex(dp) :: mu, p0, p1, p2
        real(dp) :: im_mu
        mu = cmplx(-st%zeta * st%omega * tau, st%wd * tau, dp)
        call complex_phis(mu, p0, p1, p2)
        im_mu = st%wd * tau
        if (im_mu > 0.0_dp) then
            b0 = aimag(p0) / im_mu
            b1 = aimag(p1) / im_mu
            b2 = aimag(p2) / im_mu
        else
            ! tau = 0: f'(0)
            b0 = 1.0_dp
            b1 = 0.5_dp
            b2 = 1.0_dp / 6.0_dp
        end if
        a0 = real(p0, dp)
        a1 = real(p1, dp)
        a2 = real(p2, dp)
    end subroutine matrix_functions

    !> The state (z, v) at tau inside a step that starts at (z0, v0) with a_g = a0 + s tau
    !> (m/s^2): the exact step of length tau, ending at a_g = a0 + s tau.
    pure subroutine state_at(st, z0, v0, a0, s, tau, z, v)
        type(sdof_step_t), intent(in) :: st
        real(dp), intent(in) :: z0, v0, a0, s, tau
        real(dp), intent(out) :: z, v
        type(sdof_step_t) :: part
        real(dp) :: a1
        part = st
        call set_coefficients(part, tau)
        a1 = a0 + s * tau
        z = part%e11 * z0 + part%e12 * v0 + part%b1 * a0 + part%c1 * a1
        v = part%e21 * z0 + part%e22 * v0 + part%b2 * a0 + part%c2 * a1
    end subroutine state_at

    ! ------------------------------------------------------------------------------
    ! Response history
    ! ------------------------------------------------------------------------------

    !> Response of the oscillator to a record, at the samples: relative displacement (m),
    !> relative velocity (m/s) and absolute acceleration (g). T = 0 gives the ground
    !> motion itself (z = z' = 0, a_abs = a_g).
    !> damping and g are optional (defaults 0.05 and STANDARD_GRAVITY, as Python's
    !> `sdof.response`); when one is omitted, pass disp, vel, acc and stat by keyword.
    subroutine sdof_response(accel, dt, period, damping, g, disp, vel, acc, stat, errmsg)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (g), at t = (i-1) dt
        real(dp), intent(in) :: dt                            !! time step (s), > 0
        real(dp), intent(in) :: period                        !! natural period (s), >= 0
        !> damping ratio, in [0, 1); default 0.05
        real(dp), intent(in), optional :: damping
        !> gravity (m/s^2), > 0; default STANDARD_GRAVITY (9.80665 m/s^2)
        real(dp), intent(in), optional :: g
        real(dp), intent(out) :: disp(:)                      !! relative displacement (m), size(accel)
        real(dp), intent(out) :: vel(:)                       !! relative velocity (m/s), size(accel)
        real(dp), intent(out) :: acc(:)                       !! absolute acceleration (g), size(accel)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(sdof_step_t) :: st
        integer :: i, n
        real(dp) :: z, v, zn, w2, zw2
        real(dp) :: damping_in, g_in
        damping_in = optval(damping, 0.05_dp)
        g_in = optval(g, STANDARD_GRAVITY)
        call record_step_check(accel, dt, g_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call sdof_validate(period, damping_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        n = size(accel)
        if (size(disp) /= n .or. size(vel) /= n .or. size(acc) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'disp, vel, acc: need ' &
                           //int_str(n)//' elements each (the record length)')
            return
        end if
        if (period <= 0.0_dp) then
            disp = 0.0_dp
            vel = 0.0_dp
            acc = accel
            return
        end if
        st = sdof_step(period, damping_in, dt)
        w2 = st%omega**2
        zw2 = 2.0_dp * damping_in * st%omega
        z = 0.0_dp
        v = 0.0_dp
        disp(1) = 0.0_dp
        vel(1) = 0.0_dp
        acc(1) = 0.0_dp
        do i = 1, n - 1
            zn = st%e11 * z + st%e12 * v + g_in * (st%b1 * accel(i) + st%c1 * accel(i + 1))
            v = st%e21 * z + st%e22 * v + g_in * (st%b2 * accel(i) + st%c2 * accel(i + 1))
            z = zn
            disp(i + 1) = z
            vel(i + 1) = v
            acc(i + 1) = -(zw2 * v + w2 * z) / g_in
        end do
    end subroutine sdof_response

    ! ------------------------------------------------------------------------------
    ! Spectra
    ! ------------------------------------------------------------------------------

    !> Response spectra of a record: for every period T_i and damping zeta_j the largest
    !> |z| (sd, m), |z'| (sv, m/s) and |a_abs| (sa, g) over the record, optionally with
    !> the times (s from the first sample) where they occur. Pseudo-spectra follow from
    !> `pseudo_spectra`. `peaks` = SDOF_PEAKS_EXACT (default: true maxima between
    !> samples too) or SDOF_PEAKS_SAMPLES. `threads` > 0 sets the OpenMP thread count
    !> for this call (0 or absent: the OpenMP default); the results do not depend on it.
    subroutine sdof_spectrum(accel, dt, periods, dampings, g, sd, sv, sa, stat, errmsg, &
                             peaks, threads, t_sd, t_sv, t_sa)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (g)
        real(dp), intent(in) :: dt                            !! time step (s), > 0
        real(dp), intent(in) :: periods(:)                    !! natural periods (s), >= 0
        real(dp), intent(in) :: dampings(:)                   !! damping ratios, in [0, 1)
        real(dp), intent(in) :: g                             !! gravity (m/s^2), > 0
        real(dp), intent(out) :: sd(:, :)                     !! max |z| (m), (period, damping)
        real(dp), intent(out) :: sv(:, :)                     !! max |z'| (m/s)
        real(dp), intent(out) :: sa(:, :)                     !! max |a_abs| (g)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> SDOF_PEAKS_EXACT or _SAMPLES; default SDOF_PEAKS_EXACT
        integer, intent(in), optional :: peaks
        integer, intent(in), optional :: threads              !! OpenMP threads (0: default)
        real(dp), intent(out), optional :: t_sd(:, :)         !! time of max |z| (s)
        real(dp), intent(out), optional :: t_sv(:, :)         !! time of max |z'| (s)
        real(dp), intent(out), optional :: t_sa(:, :)         !! time of max |a_abs| (s)
        integer :: np, nd, k, i, j, mode
        real(dp), allocatable :: ga(:)                        ! the record (m/s^2)
        real(dp) :: tz(size(periods), size(dampings)), tv(size(periods), size(dampings)), &
                    ta(size(periods), size(dampings))
        call record_step_check(accel, dt, g, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        np = size(periods)
        nd = size(dampings)
        do i = 1, np
            call sdof_validate(periods(i), 0.0_dp, stat, errmsg, period_name='periods(' &
                            //int_str(i)//')')
            if (stat /= SEISPULSE_SUCCESS) return
        end do
        do j = 1, nd
            call sdof_validate(0.0_dp, dampings(j), stat, errmsg, damping_name='dampings(' &
                            //int_str(j)//')')
            if (stat /= SEISPULSE_SUCCESS) return
        end do
        if (any(shape(sd) /= [np, nd]) .or. any(shape(sv) /= [np, nd]) &
            .or. any(shape(sa) /= [np, nd])) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'sd, sv, sa: need shape (' &
                           //int_str(np)//', '//int_str(nd)//') (periods, dampings)')
            return
        end if
        if (.not. times_fit(t_sd) .or. .not. times_fit(t_sv) .or. .not. times_fit(t_sa)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't_sd, t_sv, t_sa: need ' &
                           //'shape ('//int_str(np)//', '//int_str(nd)//') (periods, dampings)')
            return
        end if
        mode = SDOF_PEAKS_EXACT
        if (present(peaks)) mode = peaks
        if (mode /= SDOF_PEAKS_EXACT .and. mode /= SDOF_PEAKS_SAMPLES) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'peaks = '//int_str(mode) &
                           //': must be SDOF_PEAKS_EXACT (1) or SDOF_PEAKS_SAMPLES (2)')
            return
        end if
        if (present(threads)) then
            if (threads < 0) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'threads = ' &
                               //int_str(threads)//': must be >= 0 (0: the OpenMP default)')
                return
            end if
        end if
        ! m/s^2 once for all oscillators; a sample whose product with g overflows is an
        ! error naming it (found by fuzzing: it gave infinite or meaningless spectra)
        call record_in_si(accel, g, ga, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call run_spectrum()
    contains
        logical function times_fit(t)
            real(dp), intent(in), optional :: t(:, :)
            times_fit = .true.
            if (present(t)) times_fit = all(shape(t) == [np, nd])
        end function times_fit

        subroutine run_spectrum()
            integer :: nthreads, ngroups, g1, g2, nl, ip(lanes), id(lanes)
            integer, allocatable :: first(:), key(:)
            type(peak_t) :: pz(lanes), pv(lanes), pa(lanes)
            ! groups of up to `lanes` consecutive (period, damping) pairs that share a
            ! run (run_key); fixed before the threads start, so results do not depend
            ! on them
            allocate(key(np * nd), first(np * nd + 1))
            do k = 1, np * nd
                key(k) = run_key(periods(mod(k - 1, np) + 1), dampings((k - 1) / np + 1), &
                                 dt, mode)
            end do
            ngroups = min(np * nd, 1)
            first(1) = 1
            do k = 2, np * nd
                if (key(k) == 0 .or. key(k) /= key(k - 1) .or. k - first(ngroups) == lanes) then
                    ngroups = ngroups + 1
                    first(ngroups) = k
                end if
            end do
            first(ngroups + 1) = np * nd + 1
            nthreads = 0
            if (present(threads)) nthreads = threads
            !$ if (nthreads == 0) nthreads = omp_get_max_threads()
            ! one group per iteration; dynamic: short periods cost more
            !$omp parallel do schedule(dynamic, 1) num_threads(max(nthreads, 1)) &
            !$omp default(shared) private(k, i, j, g1, g2, nl, ip, id, pz, pv, pa)
            do k = 1, ngroups
                g1 = first(k)
                g2 = first(k + 1) - 1
                nl = g2 - g1 + 1
                ip(:nl) = mod([(i, i = g1, g2)] - 1, np) + 1
                id(:nl) = ([(i, i = g1, g2)] - 1) / np + 1
                call oscillator_peaks(ga, dt, periods(ip(:nl)), dampings(id(:nl)), mode, &
                                      pz(:nl), pv(:nl), pa(:nl))
                do j = 1, nl
                    sd(ip(j), id(j)) = pz(j)%value
                    sv(ip(j), id(j)) = pv(j)%value
                    sa(ip(j), id(j)) = pa(j)%value / g
                    tz(ip(j), id(j)) = pz(j)%time
                    tv(ip(j), id(j)) = pv(j)%time
                    ta(ip(j), id(j)) = pa(j)%time
                end do
            end do
            !$omp end parallel do
            if (present(t_sd)) t_sd = tz
            if (present(t_sv)) t_sv = tv
            if (present(t_sa)) t_sa = ta
        end subroutine run_spectrum
    end subroutine sdof_spectrum

    !> Number of OpenMP threads a spectrum uses by default (1 without OpenMP).
    function sdof_threads() result(n)
        integer :: n
        n = 1
        !$ n = omp_get_max_threads()
    end function sdof_threads

    !> Maxima of |z| (m), |z'| (m/s) and |a_abs| (m/s^2) for up to `lanes` oscillators
    !> on a valid record ga (m/s^2), run side by side (independent recurrences keep the
    !> processor busy where a single one waits on its own latency). In exact mode all
    !> of them take the same number of sub-steps (`run_key`); a period 0 runs alone.
    !> Each oscillator's arithmetic is the same whatever its neighbours, so spectra do
    !> not depend on the grouping or on the threads.
    subroutine oscillator_peaks(ga, dt, periods, zetas, mode, pz, pv, pa)
        real(dp), intent(in) :: ga(:), dt
        real(dp), intent(in) :: periods(:)  !! 1 to `lanes` periods (s)
        real(dp), intent(in) :: zetas(:)    !! their damping ratios
        integer, intent(in) :: mode
        type(peak_t), intent(out) :: pz(:), pv(:), pa(:)
        type(sdof_step_t) :: st(lanes)
        integer :: i, l, nl, m
        nl = size(periods)
        if (periods(1) <= 0.0_dp) then
            ! the ground itself: a_abs = a_g, linear between samples
            pz(1) = peak_t(0.0_dp, 0.0_dp)
            pv(1) = peak_t(0.0_dp, 0.0_dp)
            pa(1) = peak_t(abs(ga(1)), 0.0_dp)
            do i = 2, size(ga)
                if (abs(ga(i)) > pa(1)%value) pa(1) = peak_t(abs(ga(i)), (i - 1) * dt)
            end do
            return
        end if
        ! unused lanes repeat the first oscillator; their results are dropped
        m = run_key(periods(1), zetas(1), dt, mode)
        if (mode == SDOF_PEAKS_EXACT .and. m > max_sub_steps) then
            ! many damped cycles per record step: cost independent of T/dt
            do l = 1, nl
                call cycles_run(periods(l), zetas(l), ga, dt, pz(l), pv(l), pa(l))
            end do
            return
        end if
        do l = 1, lanes
            i = min(l, nl)
            st(l) = sdof_step(periods(i), zetas(i), dt / m)
        end do
        if (mode == SDOF_PEAKS_SAMPLES) then
            call samples_run(st, ga, pz(:nl), pv(:nl), pa(:nl))
        else
            call exact_run(st, ga, m, pz(:nl), pv(:nl), pa(:nl))
        end if
    end subroutine oscillator_peaks

    !> Which oscillators may share a run: 0 for a period 0 (the ground), else the number
    !> of sub-steps per record step (1 for sample maxima).
    pure function run_key(period, zeta, dt, mode) result(key)
        real(dp), intent(in) :: period, zeta, dt
        integer, intent(in) :: mode
        integer :: key
        if (period <= 0.0_dp) then
            key = 0
        else if (mode == SDOF_PEAKS_SAMPLES) then
            key = 1
        else
            key = sub_steps(period, zeta, dt)
        end if
    end function run_key

    !> Sub-steps per record step so that each is shorter than half a damped period.
    pure function sub_steps(period, zeta, dt) result(m)
        real(dp), intent(in) :: period, zeta, dt
        integer :: m
        real(dp) :: td, r
        td = period / sqrt((1.0_dp - zeta) * (1.0_dp + zeta))
        r = 2.0_dp * dt / td
        if (r < 1.0_dp) then
            m = 1
        else if (r < 1.0e6_dp) then
            m = int(r) + 1
        else
            m = 1000001  ! T below a millionth of dt: the response is the ground's
        end if
    end function sub_steps

    !> Maxima over the samples only (at t = 0 everything is zero).
    subroutine samples_run(st, ga, pz, pv, pa)
        type(sdof_step_t), intent(in) :: st(lanes)
        real(dp), intent(in) :: ga(:)  !! ground acceleration (m/s^2)
        type(peak_t), intent(out) :: pz(:), pv(:), pa(:)
        real(dp), dimension(lanes) :: e11, e12, e21, e22, b1, b2, c1, c2, w2, zw2, z, v, zn, &
                                      az, av, aa, mz, mv, ma, rise
        integer :: i, l
        call unpack_steps(st, e11, e12, e21, e22, b1, b2, c1, c2, w2, zw2)
        z = 0.0_dp
        v = 0.0_dp
        mz = 0.0_dp
        mv = 0.0_dp
        ma = 0.0_dp
        pz = peak_t(0.0_dp, 0.0_dp)
        pv = peak_t(0.0_dp, 0.0_dp)
        pa = peak_t(0.0_dp, 0.0_dp)
        ! the unused lanes never rise
        mz(size(pz) + 1:) = huge(1.0_dp)
        mv(size(pz) + 1:) = huge(1.0_dp)
        ma(size(pz) + 1:) = huge(1.0_dp)
        do i = 1, size(ga) - 1
            do l = 1, lanes
                zn(l) = e11(l) * z(l) + e12(l) * v(l) + b1(l) * ga(i) + c1(l) * ga(i + 1)
                v(l) = e21(l) * z(l) + e22(l) * v(l) + b2(l) * ga(i) + c2(l) * ga(i + 1)
                z(l) = zn(l)
                az(l) = abs(z(l))
                av(l) = abs(v(l))
                aa(l) = abs(zw2(l) * v(l) + w2(l) * z(l))
                rise(l) = max(az(l) - mz(l), av(l) - mv(l), aa(l) - ma(l))
            end do
            if (maxval(rise) > 0.0_dp) then
                do l = 1, size(pz)
                    if (az(l) > mz(l)) then
                        mz(l) = az(l)
                        pz(l) = peak_t(az(l), i * st(l)%h)
                    end if
                    if (av(l) > mv(l)) then
                        mv(l) = av(l)
                        pv(l) = peak_t(av(l), i * st(l)%h)
                    end if
                    if (aa(l) > ma(l)) then
                        ma(l) = aa(l)
                        pa(l) = peak_t(aa(l), i * st(l)%h)
                    end if
                end do
            end if
        end do
    end subroutine samples_run

    !> The step coefficients of the lanes as arrays (the hot loops work lane by lane).
    pure subroutine unpack_steps(st, e11, e12, e21, e22, b1, b2, c1, c2, w2, zw2)
        type(sdof_step_t), intent(in) :: st(lanes)
        real(dp), dimension(lanes), intent(out) :: e11, e12, e21, e22, b1, b2, c1, c2, w2, zw2
        e11 = st%e11
        e12 = st%e12
        e21 = st%e21
        e22 = st%e22
        b1 = st%b1
        b2 = st%b2
        c1 = st%c1
        c2 = st%c2
        w2 = st%omega**2
        zw2 = 2.0_dp * st%zeta * st%omega
    end subroutine unpack_steps

    !> The exact run with maxima between the samples (module header): m exact sub-steps
    !> per record step (a_g is linear in the step, so sub-samples are exact). Maxima
    !> of a_abs in m/s^2. The lanes advance together; a step is looked at lane by lane
    !> (`step_peaks`) only where a maximum can rise: this is the hot loop of every
    !> spectrum.
    subroutine exact_run(st, ga, m, pz, pv, pa)
        type(sdof_step_t), intent(in) :: st(lanes)
        real(dp), intent(in) :: ga(:)  !! ground acceleration (m/s^2)
        integer, intent(in) :: m
        type(peak_t), intent(out) :: pz(:), pv(:), pa(:)
        real(dp), dimension(lanes) :: e11, e12, e21, e22, b1, b2, c1, c2, w2, zw2, zw, inv_w, &
                                      inv_w2, inv_wd, z, v, z1, v1, q1, d2_0, d2_1, f, bound2, &
                                      mz, mv, ma, az0, av0, aq0, az1, av1, aq1, gap, low
        real(dp) :: a0, a1, qa, qb, s, inv_h, h4
        integer :: i, j, k, l, n
        call unpack_steps(st, e11, e12, e21, e22, b1, b2, c1, c2, w2, zw2)
        zw = 0.5_dp * zw2
        inv_w = 1.0_dp / st%omega
        inv_w2 = inv_w * inv_w
        inv_wd = st%inv_wd
        ! the lanes share the step (same sub-steps)
        inv_h = st(1)%inv_h
        h4 = st(1)%h4_64
        n = size(ga)
        ! at t = 0 everything is zero (a_abs = -(2 zeta omega z' + omega^2 z) = 0)
        pz = peak_t(0.0_dp, 0.0_dp)
        pv = peak_t(0.0_dp, 0.0_dp)
        pa = peak_t(0.0_dp, 0.0_dp)
        mz = 0.0_dp
        mv = 0.0_dp
        ma = 0.0_dp
        z = 0.0_dp
        v = 0.0_dp
        az0 = 0.0_dp
        av0 = 0.0_dp
        aq0 = 0.0_dp
        d2_1 = -ga(1)
        j = 0
        do i = 1, n - 1
            do k = 1, m
                j = j + 1
                if (m == 1) then
                    a0 = ga(i)
                    a1 = ga(i + 1)
                else
                    qa = real(k - 1, dp) / m
                    qb = real(k, dp) / m
                    a0 = (1.0_dp - qa) * ga(i) + qa * ga(i + 1)
                    a1 = (1.0_dp - qb) * ga(i) + qb * ga(i + 1)
                    if (k == 1) a0 = ga(i)
                    if (k == m) a1 = ga(i + 1)
                end if
                s = (a1 - a0) * inv_h
                do l = 1, lanes
                    z1(l) = e11(l) * z(l) + e12(l) * v(l) + b1(l) * a0 + c1(l) * a1
                    v1(l) = e21(l) * z(l) + e22(l) * v(l) + b2(l) * a0 + c2(l) * a1
                    q1(l) = -(zw2(l) * v1(l) + w2(l) * z1(l))
                    ! z'' at both ends (continuous: carried over)
                    d2_0(l) = d2_1(l)
                    d2_1(l) = q1(l) - a1
                    ! Inside the step z'' = e^(-zeta omega tau) (e cos(wd tau) + f sin(wd tau))
                    ! with e = z''(0) and f = (z'''(0) + zeta omega e)/wd, z''' = -(s +
                    ! 2 zeta omega z'' + omega^2 z'), so |z''| <= R = sqrt(e^2 + f^2). The
                    ! second derivatives of z' and of a_abs = a_g + z'' (a_g'' = 0) are the
                    ! same damped sinusoid differentiated once and twice, of amplitudes
                    ! omega R and omega^2 R. An interior |q| can exceed max(|q0|, |q1|) by
                    ! h^2 max|q''|/8 at most: a step needs a look only when a sample beats
                    ! the running maximum (gap < 0) or that bound can (gap^2 < bound^2),
                    ! tested at once on the gaps scaled to z (gap_v/omega, gap_a/omega^2).
                    f(l) = -(s + zw(l) * d2_0(l) + w2(l) * v(l)) * inv_wd(l)
                    bound2(l) = (d2_0(l) * d2_0(l) + f(l) * f(l)) * h4
                    az1(l) = abs(z1(l))
                    av1(l) = abs(v1(l))
                    aq1(l) = abs(q1(l))
                    gap(l) = min(mz(l) - max(az0(l), az1(l)), &
                                 (mv(l) - max(av0(l), av1(l))) * inv_w(l), &
                                 (ma(l) - max(aq0(l), aq1(l))) * inv_w2(l))
                    low(l) = min(gap(l), gap(l) * gap(l) - bound2(l))
                end do
                if (minval(low(:size(pz))) < 0.0_dp) then
                    do l = 1, size(pz)
                        if (low(l) < 0.0_dp) call step_peaks(st(l), j, z(l), v(l), z1(l), &
                            v1(l), a0, a1, s, d2_0(l), d2_1(l), f(l), bound2(l), mz(l), &
                            mv(l), ma(l), pz(l), pv(l), pa(l))
                    end do
                end if
                z = z1
                v = v1
                az0 = az1
                av0 = av1
                aq0 = aq1
            end do
        end do
        ! times from (sub-)step numbers: t = (j - 1) h + offset
        do l = 1, size(pz)
            call absolute_time(pz(l), st(l)%h)
            call absolute_time(pv(l), st(l)%h)
            call absolute_time(pa(l), st(l)%h)
        end do
    end subroutine exact_run

    !> Exact peaks when a record step spans many damped periods T_d (more than
    !> max_sub_steps sub-steps). Within a record step (length dt) every response q
    !> in {z, z', a_abs} is q(t) = c + d t + y(t), a line plus a damped sinusoid with
    !> y(t + T_d) = e^(-zeta omega T_d) y(t). Let t* be the first point of the step
    !> where q is largest and suppose T_d <= t* <= dt - T_d. If y(t*) >= 0, then
    !> q(t* - T_d) + q(t* + T_d) - 2 q(t*) = y(t*) (2 cosh(zeta omega T_d) - 2) >= 0, so
    !> q(t* - T_d) = q(t*): t* was not the first. If y(t*) < 0, the mean of
    !> q(t* -/+ T_d/2) is c + d t* + |y(t*)| cosh(zeta omega T_d/2) > q(t*). Either way
    !> a contradiction: the largest q (and, with -q, the largest -q) lies in the first
    !> or the last T_d of the step. Those two windows of 1.2 T_d are searched exactly
    !> by `step_peaks` on sub-steps of 0.4 T_d; the state jumps between them by one
    !> exact step. Cost: 8 steps per record step, whatever T/dt.
    subroutine cycles_run(period, zeta, ga, dt, pz, pv, pa)
        real(dp), intent(in) :: period  !! natural period (s), > 0
        real(dp), intent(in) :: zeta    !! damping ratio
        real(dp), intent(in) :: ga(:)   !! ground acceleration (m/s^2)
        real(dp), intent(in) :: dt      !! record step (s), > 2.4 T_d
        type(peak_t), intent(out) :: pz, pv, pa
        type(sdof_step_t) :: sw, sj
        real(dp) :: hw, tj, z, v, zj, vj, mz, mv, ma, s, t0, aj
        integer :: i
        hw = 0.4_dp * period / sqrt((1.0_dp - zeta) * (1.0_dp + zeta))
        tj = dt - 2 * window_steps * hw
        sw = sdof_step(period, zeta, hw)
        sj = sdof_step(period, zeta, tj)
        pz = peak_t(0.0_dp, 0.0_dp)
        pv = peak_t(0.0_dp, 0.0_dp)
        pa = peak_t(0.0_dp, 0.0_dp)
        mz = 0.0_dp
        mv = 0.0_dp
        ma = 0.0_dp
        z = 0.0_dp
        v = 0.0_dp
        do i = 1, size(ga) - 1
            s = (ga(i + 1) - ga(i)) / dt
            t0 = (i - 1) * dt
            ! the first window [0, 1.2 T_d]
            call window_peaks(sw, ga(i), s, 0.0_dp, t0, .false., ga(i + 1), z, v, &
                              mz, mv, ma, pz, pv, pa)
            ! one exact step to dt - 1.2 T_d, then the last window
            aj = ga(i) + s * (window_steps * hw)
            zj = sj%e11 * z + sj%e12 * v + sj%b1 * aj + sj%c1 * (aj + s * tj)
            vj = sj%e21 * z + sj%e22 * v + sj%b2 * aj + sj%c2 * (aj + s * tj)
            z = zj
            v = vj
            call window_peaks(sw, ga(i), s, dt - window_steps * hw, t0, .true., ga(i + 1), &
                              z, v, mz, mv, ma, pz, pv, pa)
        end do
    end subroutine cycles_run

    !> window_steps exact sub-steps of sw%h from the state (z, v) at tau0 (s) inside the
    !> record step that starts at t0 (s) with a_g = a_start + s tau (m/s^2); the state
    !> is advanced, the peaks updated (absolute times). `last`: the window ends the
    !> record step, its end sample is a_end.
    subroutine window_peaks(sw, a_start, s, tau0, t0, last, a_end, z, v, mz, mv, ma, &
                            pz, pv, pa)
        type(sdof_step_t), intent(in) :: sw
        real(dp), intent(in) :: a_start, s, tau0, t0, a_end
        logical, intent(in) :: last
        real(dp), intent(inout) :: z, v, mz, mv, ma
        type(peak_t), intent(inout) :: pz, pv, pa
        real(dp) :: a0, a1, z1, v1, w2, zw2, d2_0, d2_1, f, bound2, sk, tk
        integer :: k
        w2 = sw%omega**2
        zw2 = 2.0_dp * sw%zeta * sw%omega
        a1 = a_start + s * tau0
        do k = 1, window_steps
            a0 = a1
            a1 = a_start + s * (tau0 + k * sw%h)
            if (last .and. k == window_steps) a1 = a_end
            sk = (a1 - a0) * sw%inv_h
            z1 = sw%e11 * z + sw%e12 * v + sw%b1 * a0 + sw%c1 * a1
            v1 = sw%e21 * z + sw%e22 * v + sw%b2 * a0 + sw%c2 * a1
            d2_0 = -(a0 + zw2 * v + w2 * z)
            d2_1 = -(a1 + zw2 * v1 + w2 * z1)
            ! the bound of exact_run
            f = -(sk + 0.5_dp * zw2 * d2_0 + w2 * v) * sw%inv_wd
            bound2 = (d2_0 * d2_0 + f * f) * sw%h4_64
            call step_peaks(sw, 1, z, v, z1, v1, a0, a1, sk, d2_0, d2_1, f, bound2, &
                            mz, mv, ma, pz, pv, pa)
            tk = t0 + tau0 + (k - 1) * sw%h
            if (pz%step > 0) pz = peak_t(pz%value, tk + pz%time, 0)
            if (pv%step > 0) pv = peak_t(pv%value, tk + pv%time, 0)
            if (pa%step > 0) pa = peak_t(pa%value, tk + pa%time, 0)
            z = z1
            v = v1
        end do
    end subroutine window_peaks

    !> A peak's time counted from the first sample (s) instead of within its sub-step.
    pure subroutine absolute_time(p, h)
        type(peak_t), intent(inout) :: p
        real(dp), intent(in) :: h
        if (p%step > 0) p = peak_t(p%value, (p%step - 1) * h + p%time, 0)
    end subroutine absolute_time

    !> One step of one oscillator where a maximum can rise: the new samples against the
    !> running maxima (mz, mv, ma), then the interior of the step for each quantity
    !> whose bound h^2 max|q''|/8 can beat its maximum (see exact_run).
    subroutine step_peaks(st, j, z, v, z1, v1, a0, a1, s, d2_0, d2_1, f_z, bound2, &
                          mz, mv, ma, pz, pv, pa)
        type(sdof_step_t), intent(in) :: st
        integer, intent(in) :: j
        real(dp), intent(in) :: z, v, z1, v1, a0, a1, s, d2_0, d2_1, f_z, bound2
        real(dp), intent(inout) :: mz, mv, ma
        type(peak_t), intent(inout) :: pz, pv, pa
        real(dp) :: w2, zw, zw2, gap, d3_0, d3_1, d4_0, f, q0, q1, dq0, dq1, ddq0, ddq1
        w2 = st%omega**2
        zw = st%zeta * st%omega
        zw2 = 2.0_dp * zw
        d3_0 = -(s + zw2 * d2_0 + w2 * v)
        ! q = z
        if (abs(z1) > mz) then
            mz = abs(z1)
            pz = peak_t(mz, st%h, j)
        end if
        gap = mz - max(abs(z), abs(z1))
        if (gap * gap < bound2) then
            call search_step(st, z, v, a0, s, j, 1, z, z1, v, v1, d2_0, d2_1, f_z, pz)
            mz = pz%value
        end if
        ! q = z'
        if (abs(v1) > mv) then
            mv = abs(v1)
            pv = peak_t(mv, st%h, j)
        end if
        gap = mv - max(abs(v), abs(v1))
        if (gap * gap < w2 * bound2) then
            d3_1 = -(s + zw2 * d2_1 + w2 * v1)
            d4_0 = -(zw2 * d3_0 + w2 * d2_0)
            f = (d4_0 + zw * d3_0) * st%inv_wd
            call search_step(st, z, v, a0, s, j, 2, v, v1, d2_0, d2_1, d3_0, d3_1, f, pv)
            mv = pv%value
        end if
        ! q = a_abs = -(2 zeta omega z' + omega^2 z) = a_g + z''
        q0 = a0 + d2_0
        q1 = a1 + d2_1
        if (abs(q1) > ma) then
            ma = abs(q1)
            pa = peak_t(ma, st%h, j)
        end if
        gap = ma - max(abs(q0), abs(q1))
        if (gap * gap < w2 * w2 * bound2) then
            d3_1 = -(s + zw2 * d2_1 + w2 * v1)
            d4_0 = -(zw2 * d3_0 + w2 * d2_0)
            dq0 = s + d3_0
            dq1 = s + d3_1
            ddq0 = d4_0
            ddq1 = -(zw2 * d3_1 + w2 * d2_1)
            f = (-(zw2 * d4_0 + w2 * d3_0) + zw * d4_0) * st%inv_wd
            call search_step(st, z, v, a0, s, j, 3, q0, q1, dq0, dq1, ddq0, ddq1, f, pa)
            ma = pa%value
        end if
    end subroutine step_peaks

    !> The interior maximum of quantity kq (1 z, 2 z', 3 a_abs) on a step that starts at
    !> (z0, v0) with a_g = a0 + s tau, given q, q', q'' at both ends and f of q''
    !> (see exact_step): split at the zero of q'' if there is one, then look for a sign
    !> change of q' on each monotone side.
    subroutine search_step(st, z0, v0, a0, s, j, kq, qa, qb, dqa, dqb, ddqa, ddqb, f, p)
        type(sdof_step_t), intent(in) :: st
        real(dp), intent(in) :: z0, v0, a0, s
        integer, intent(in) :: j
        integer, intent(in) :: kq
        real(dp), intent(in) :: qa, qb, dqa, dqb, ddqa, ddqb, f
        type(peak_t), intent(inout) :: p
        real(dp) :: h, phase, tau_s, q_s, dq_s, ddq_s
        h = st%h
        if (ddqa * ddqb < 0.0_dp) then
            ! one zero of q'' inside, where wd tau + atan2(f, e) = pi/2 (mod pi)
            phase = modulo(atan2(f, ddqa) + 0.5_dp * pi, pi)
            tau_s = min(max(phase * st%inv_wd, 0.0_dp), h)
            call q_at(st, z0, v0, a0, s, kq, tau_s, q_s, dq_s, ddq_s)
            call piece_peak(st, z0, v0, a0, s, j, kq, 0.0_dp, tau_s, qa, dqa, q_s, dq_s, p)
            call piece_peak(st, z0, v0, a0, s, j, kq, tau_s, h, q_s, dq_s, qb, dqb, p)
        else
            call piece_peak(st, z0, v0, a0, s, j, kq, 0.0_dp, h, qa, dqa, qb, dqb, p)
        end if
    end subroutine search_step

    !> On [ta, tb] where q' is monotone: the interior extremum, if q' changes sign and
    !> the extremum can beat the running maximum, by Newton steps kept in the bracket.
    subroutine piece_peak(st, z0, v0, a0, s, j, kq, ta, tb, qa, dqa, qb, dqb, p)
        type(sdof_step_t), intent(in) :: st
        real(dp), intent(in) :: z0, v0, a0, s
        integer, intent(in) :: j
        integer, intent(in) :: kq
        real(dp), intent(in) :: ta, tb, qa, dqa, qb, dqb
        type(peak_t), intent(inout) :: p
        real(dp) :: lo, hi, x, dx, q, dq, ddq, dqlo, xi, tangents
        integer :: it
        logical :: newton
        if (.not. (dqa * dqb < 0.0_dp)) return
        ! q' monotone: q is convex or concave on the piece, so it lies between its chord
        ! and its two tangents; the extremum is between the ends' values and the value
        ! where the tangents meet
        xi = min(max((qb - qa + dqa * ta - dqb * tb) / (dqa - dqb), ta), tb)
        tangents = qa + dqa * (xi - ta)
        if (max(abs(tangents), abs(qa), abs(qb)) <= p%value) return
        lo = ta
        hi = tb
        dqlo = dqa
        ! start at the root of the chord of q' (exact when q is a parabola), which
        ! lies in the bracket as q' changes sign
        x = min(max(ta - dqa * (tb - ta) / (dqb - dqa), ta), tb)
        do it = 1, max_newton
            call q_at(st, z0, v0, a0, s, kq, x, q, dq, ddq)
            if (.not. (abs(dq) > 0.0_dp)) exit
            if ((dq < 0.0_dp) .eqv. (dqlo < 0.0_dp)) then
                lo = x
                dqlo = dq
            else
                hi = x
            end if
            ! Newton inside the bracket, else bisection
            dx = 0.5_dp * (lo + hi) - x
            newton = .false.
            if (abs(ddq) > 0.0_dp) then
                if (x - dq / ddq > lo .and. x - dq / ddq < hi) then
                    dx = -dq / ddq
                    newton = .true.
                end if
            end if
            ! q is flat at its extremum: once the Newton step is below 1e-7 h, the
            ! quadratic model q + dq dx/2 is the extremum to O(dx^3), far below rounding
            if (newton .and. abs(dx) <= 1.0e-7_dp * st%h) then
                q = q + 0.5_dp * dq * dx
                x = x + dx
                exit
            end if
            x = x + dx
            if (hi - lo <= 4.0_dp * epsilon(x) * st%h) exit
        end do
        if (abs(q) > p%value) p = peak_t(abs(q), x, j)
    end subroutine piece_peak

    !> q, q', q'' of quantity kq at tau inside a step that starts at (z0, v0), a_g = a0 + s tau.
    pure subroutine q_at(st, z0, v0, a0, s, kq, tau, q, dq, ddq)
        type(sdof_step_t), intent(in) :: st
        real(dp), intent(in) :: z0, v0, a0, s, tau
        integer, intent(in) :: kq
        real(dp), intent(out) :: q, dq, ddq
        real(dp) :: zt, vt, d2, d3, w2, zw2
        w2 = st%omega**2
        zw2 = 2.0_dp * st%zeta * st%omega
        call state_at(st, z0, v0, a0, s, tau, zt, vt)
        d2 = -(a0 + s * tau + zw2 * vt + w2 * zt)
        d3 = -(s + zw2 * d2 + w2 * vt)
        select case (kq)
        case (1)
            q = zt
            dq = vt
            ddq = d2
        case (2)
            q = vt
            dq = d2
            ddq = d3
        case default
            q = -(zw2 * vt + w2 * zt)
            dq = -(zw2 * d2 + w2 * vt)
            ddq = -(zw2 * d3 + w2 * d2)
        end select
    end subroutine q_at

    ! ------------------------------------------------------------------------------
    ! Derived spectra
    ! ------------------------------------------------------------------------------

    !> Pseudo-spectra (Eq. 2.33): PSV = omega SD (m/s), PSA = omega^2 SD / g (g).
    !> T = 0: PSV = 0 and PSA = the given PGA (the limit of omega^2 SD as T -> 0).
    pure subroutine pseudo_spectra(periods, sd, g, pga, psv, psa)
        real(dp), intent(in) :: periods(:)   !! periods (s), >= 0
        real(dp), intent(in) :: sd(:, :)     !! spectral displacement (m), (period, damping)
        real(dp), intent(in) :: g            !! gravity (m/s^2)
        real(dp), intent(in) :: pga          !! peak ground acceleration (g), for T = 0
        real(dp), intent(out) :: psv(:, :)   !! pseudo-velocity (m/s)
        real(dp), intent(out) :: psa(:, :)   !! pseudo-acceleration (g)
        integer :: i
        real(dp) :: omega
        do i = 1, size(periods)
            if (periods(i) > 0.0_dp) then
                omega = 2.0_dp * pi / periods(i)
                psv(i, :) = omega * sd(i, :)
                psa(i, :) = omega * omega * sd(i, :) / g
            else
                psv(i, :) = 0.0_dp
                psa(i, :) = pga
            end if
        end do
    end subroutine pseudo_spectra

    !> Design envelope of several spectra on one period grid (doc/oscillator.md section 6): the
    !> largest ordinate at each period; below `plateau_below` (s) the curve is held at
    !> the largest ordinate at that or any longer period (the book's short-period
    !> plateau, "peak values kept, not a decreasing branch"; 0 = no plateau). The periods
    !> may come in any order (a period twice gives the same value twice); env(i) belongs
    !> to periods(i).
    subroutine design_envelope(periods, spectra, plateau_below, env, stat, errmsg)
        real(dp), intent(in) :: periods(:)                    !! periods (s), any order
        real(dp), intent(in) :: spectra(:, :)                 !! ordinates, (period, spectrum)
        real(dp), intent(in) :: plateau_below                 !! plateau limit (s), >= 0
        real(dp), intent(out) :: env(:)                       !! envelope, size(periods)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: i, j, np
        real(dp), allocatable :: peak(:)
        stat = SEISPULSE_SUCCESS
        np = size(periods)
        if (np < 1 .or. size(spectra, 2) < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'spectra: at least one period and one spectrum are needed')
            return
        end if
        if (size(spectra, 1) /= np .or. size(env) /= np) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'spectra, env: need ' &
                           //int_str(np)//' periods (rows)')
            return
        end if
        do i = 1, np
            if (.not. ieee_is_finite(periods(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'periods('//int_str(i) &
                               //') = '//real_str(periods(i))//': must be finite and >= 0 (s)')
                return
            else if (periods(i) < 0.0_dp) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'periods('//int_str(i) &
                               //') = '//real_str(periods(i))//': must be finite and >= 0 (s)')
                return
            end if
            if (.not. all(ieee_is_finite(spectra(i, :)))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'spectra(' &
                               //int_str(i)//', :): every ordinate must be finite')
                return
            end if
        end do
        if (.not. ieee_is_finite(plateau_below)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'plateau_below = ' &
                           //real_str(plateau_below)//': must be finite and >= 0 (s)')
            return
        else if (plateau_below < 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'plateau_below = ' &
                           //real_str(plateau_below)//': must be finite and >= 0 (s)')
            return
        end if
        allocate(peak(np))
        do i = 1, np
            peak(i) = maxval(spectra(i, :))
        end do
        env(:) = peak
        ! the plateau: the largest ordinate at this or any longer period (by value, so that
        ! the order of the periods does not matter)
        do i = 1, np
            if (.not. periods(i) < plateau_below) cycle
            do j = 1, np
                if (periods(j) >= periods(i)) env(i) = max(env(i), peak(j))
            end do
        end do
    end subroutine design_envelope

    !> Normalized spectral shape of the spectral theory: beta(T) = C_W(T)/PGA (PSA over
    !> the peak ground acceleration, same units), the period of its peak and the peak.
    subroutine spectral_shape(periods, psa, pga, shape, t_peak, peak, stat, errmsg)
        real(dp), intent(in) :: periods(:)                    !! periods (s)
        real(dp), intent(in) :: psa(:)                        !! pseudo-acceleration (g)
        real(dp), intent(in) :: pga                           !! peak ground acceleration (g), > 0
        real(dp), intent(out) :: shape(:)                     !! PSA/PGA, size(periods)
        real(dp), intent(out) :: t_peak                       !! period of the largest PSA/PGA (s)
        real(dp), intent(out) :: peak                         !! largest PSA/PGA
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: k
        stat = SEISPULSE_SUCCESS
        t_peak = 0.0_dp
        peak = 0.0_dp
        if (size(psa) /= size(periods) .or. size(shape) /= size(periods) &
            .or. size(periods) < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'psa, shape: need one ' &
                           //'value per period (at least one)')
            return
        end if
        if (.not. ieee_is_finite(pga)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pga = '//real_str(pga) &
                           //': must be finite and > 0 (g)')
            return
        else if (pga <= 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pga = '//real_str(pga) &
                           //': must be finite and > 0 (g)')
            return
        end if
        shape = psa / pga
        k = maxloc(shape, dim=1)
        t_peak = periods(k)
        peak = shape(k)
    end subroutine spectral_shape

end module seispulse_sdof_sim


