!> Flexible sliding masses integrated exactly (doc/flexible.md sections 5-7, Eqs. F.30-F.50):
!> the one-mode shear beam's response to the piecewise-linear record by the exact
!> recurrence, and the coupled stick-slip model of Rathje & Bray [RB99] (after Chopra &
!> Zhang [CZ91]) with its phases integrated in closed form and its onsets and stops
!> located on brackets that are proven.
!>
!> Model (doc/flexible.md (F.30)-(F.33); SLAMMER's [SL13] equations with the record's
!> polarity as given: positive a drives downslope sliding). u is the modal coordinate of
!> the decoupled response (omega = pi Vs/(2H), L/M = 4/pi, L/Mtot = 2/pi, d1 = 1 - 8/pi^2):
!>     stick:  u'' + 2 xi omega u' + omega^2 u = -(4/pi) g a(t)                   (F.30)
!>     g HEA = g a + (2/pi) u''   (the base force per unit mass)                 (F.31)
!>     slide:  d1 u'' + 2 xi omega u' + omega^2 u = -(4/pi) g ky,                 (F.32)
!>             s'' = g a - g ky + (2/pi) u''  (= (HEA_stick form - g ky)/d1)      (F.33)
!> Sliding starts when HEA exceeds g ky and stops when s' returns to 0 (one way).
!>
!> Each phase is a linear oscillator x' = A x + e l(tau), x = (u, u'), A = [0 1; -w2 -c],
!> with a load l linear on a step, solved by
!>     x(tau) = x0 + tau phi_1(tau A) x0' + tau^2 phi_2(tau A) e l'                 (F.38)
!> where f(tau A) = alpha I + beta tau A (Cayley-Hamilton) and beta = f[mu1, mu2], the divided
!> difference at the eigenvalues mu = tau lambda (complex, or real when the sliding
!> oscillator is over-damped: one formula for every damping, from
!> seispulse_divided_differences). The sliding displacement follows without quadrature
!> from (F.33): s(tau) = s0 + s0' tau + g int int (a - ky) + (2/pi)(u - u0 - tau u0').
!>
!> Events. `first_zero` returns the first zero in (0, h] of a smooth function f given
!> f, f', f'' at points and a bound M3 >= |f'''| on the step (F.44)-(F.47): the Taylor
!> bounds f(xa + d) >= f(xa) + f'(xa) d + (f''(xa) - M3 L/3) d^2/2 from both ends exclude a
!> zero from a sub-interval of length L, a sign change with f' < 0 proven on the
!> sub-interval brackets exactly one zero (Brent), otherwise the sub-interval is halved.
!> For both phases the bound comes from the energy norm of the oscillator,
!> N^2 = w2 z1^2 + z2^2 with N(tau) <= N(0) e^(max(0, -c) tau) (F.45).
module seispulse_flexible_exact
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_INTERNAL, &
                                set_error
    use seispulse_format, only: real_str, int_str
    use seispulse_checks, only: finite_positive, positive, check_history_sizes
    use seispulse_special, only: pi, complex_phis
    use seispulse_divided_differences, only: cexp_dd1, cexp_dd2, cexp_dd3
    use seispulse_sdof_sim, only: sdof_step_t, sdof_step
    use seispulse_pieces, only: record_step_check
    use seispulse_roots, only: scalar_function, find_root
    use seispulse_ode, only: ode_system, ode_dop853_t, ode_dop853_factor
    use seispulse_flexible_model, only: ky_table_validate, ky_table_at
    implicit none
    private

    public :: modal_response_exact, modal_hea_extended, coupled_exact
    public :: zero_function, first_zero, prop_t, propagator

    real(dp), parameter :: lm = 4.0_dp / pi          !! L/M of the first mode
    real(dp), parameter :: lmt = 2.0_dp / pi         !! L/Mtot
    real(dp), parameter :: d1 = 1.0_dp - 8.0_dp / pi**2  !! 1 - L^2/(M Mtot)

    !> Events (onsets, stops) allowed in one step before it is reported as chatter.
    integer, parameter :: max_events = 16
    !> Sub-pieces of a step of a stiff phase (omega tau > stiff_len; lengths doubling
    !> from stiff_len/omega, restarted after each event): enough for omega dt < 2^60.
    integer, parameter :: max_sub = 64
    real(dp), parameter :: stiff_len = 8.0_dp
    !> Depth of the interval stack of `first_zero` (intervals down to h 2^-62).
    integer, parameter :: max_depth = 62
    !> Steps of the run-out after the record before it is reported as an error.
    integer, parameter :: max_runout = 10000000

    !> A smooth function for `first_zero`: f, f', f'' at x (`taylor`); `eval` gives f.
    type, abstract, extends(scalar_function) :: zero_function
    contains
        procedure(taylor_iface), deferred :: taylor
        procedure :: eval => zero_eval
    end type zero_function

    abstract interface
        !> f(x), f'(x), f''(x).
        subroutine taylor_iface(self, x, f)
            import :: zero_function, dp
            class(zero_function), intent(inout) :: self  !! the function
            real(dp), intent(in) :: x                    !! abscissa
            real(dp), intent(out) :: f(0:2)              !! f, f', f''
        end subroutine taylor_iface
    end interface

    !> exp(tau A), tau phi_1(tau A), tau^2 phi_2(tau A) of A = [0 1; -w2 -c] (F.38).
    type :: prop_t
        real(dp) :: e(2, 2) = 0.0_dp    !! e^(tau A)
        real(dp) :: p1(2, 2) = 0.0_dp   !! tau phi_1(tau A) (s)
        real(dp) :: p2(2, 2) = 0.0_dp   !! tau^2 phi_2(tau A) (s^2)
    end type prop_t

    !> One phase on (part of) a step: the oscillator, its state at the start and the
    !> record; f is the onset function g ky - HEA (stick) or the sliding speed s' (slide).
    type, extends(zero_function) :: phase_t
        logical :: slide = .false.
        real(dp) :: c = 0.0_dp, w2 = 0.0_dp  !! damping 2 xi omega (/d1) and stiffness (1/s, 1/s^2)
        real(dp) :: u0 = 0.0_dp, v0 = 0.0_dp !! u (m), u' (m/s) at the start
        real(dp) :: s0 = 0.0_dp, sd0 = 0.0_dp !! s (m), s' (m/s) at the start
        real(dp) :: ga0 = 0.0_dp, gas = 0.0_dp !! g a at the start (m/s^2), its slope (m/s^3)
        real(dp) :: gky = 0.0_dp             !! g ky (m/s^2)
        real(dp) :: l0 = 0.0_dp, l1 = 0.0_dp !! load of the modal equation and its slope
        real(dp) :: acc0 = 0.0_dp, jrk0 = 0.0_dp !! u'', u''' at the start
    contains
        procedure :: taylor => phase_taylor
    end type phase_t

    !> The slide with ky(s) linear on a table segment (F.49): y = (u, u', s, s'),
    !> time from the start of the piece; ky continued linearly past the segment's end.
    type, extends(ode_system) :: table_slide_sys_t
        real(dp) :: c = 0.0_dp, w2 = 0.0_dp     !! stick damping (1/s) and stiffness (1/s^2)
        real(dp) :: gk0 = 0.0_dp, gk1 = 0.0_dp  !! g ky at s_j (m/s^2), g dky/ds (1/s^2)
        real(dp) :: sj = 0.0_dp                 !! segment start (m)
        real(dp) :: ga0 = 0.0_dp, gas = 0.0_dp  !! g a at the piece start, its slope
    contains
        procedure :: rhs => table_slide_rhs
    end type table_slide_sys_t

    !> A polynomial of degree 7 on [0, 1] (the dense output of one component), minus level.
    type, extends(zero_function) :: poly_fn_t
        real(dp) :: c(0:7) = 0.0_dp
    contains
        procedure :: taylor => poly_taylor
    end type poly_fn_t

    !> DOP853 tolerance for sliding with a yield table.
    real(dp), parameter :: table_rtol = 1.0e-12_dp
    !> DOP853 steps allowed in one piece of a record step.
    integer, parameter :: max_ode_steps = 100000

contains

    ! ------------------------------------------------------------------------------
    ! Modal response
    ! ------------------------------------------------------------------------------

    !> Exact one-mode response to the piecewise-linear record (the record as given):
    !> u'' + 2 xi omega u' + omega^2 u = -(4/pi) g a(t) from rest (F.30), at the samples,
    !> by the exact recurrence of seispulse_sdof_sim (F.34) (|xi| < 1; over-damped: the
    !> propagator of (F.38)); HEA = a + (2/pi) u''/g (F.31).
    subroutine modal_response_exact(accel, dt, g, omega, xi, u, hea, stat, errmsg, udot, uddot)
        real(dp), intent(in) :: accel(:)                      !! record (g) at (i-1) dt
        real(dp), intent(in) :: dt                            !! time step (s) > 0
        real(dp), intent(in) :: g                             !! gravity (m/s^2) > 0
        real(dp), intent(in) :: omega                         !! circular frequency (rad/s) > 0
        real(dp), intent(in) :: xi                            !! damping ratio > -1
        !> modal displacement (m) relative to the base, the sign of (F.30): a > 0 drives u < 0
        real(dp), intent(out) :: u(:)
        real(dp), intent(out) :: hea(:)                       !! HEA (g)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(out), optional :: udot(:)            !! u' (m/s)
        real(dp), intent(out), optional :: uddot(:)           !! u'' (m/s^2)
        real(dp), parameter :: big = 1.0e150_dp  !! |u| + |u'|/omega (m) beyond which it fails
        type(sdof_step_t) :: st
        type(prop_t) :: pr
        real(dp) :: z, v, zn, acc, w2, c, gl
        integer :: i, n
        logical :: over
        call check_modal(accel, dt, g, omega, xi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        n = size(accel)
        call check_history_sizes(n, [character(len=5) :: 'u', 'hea', 'udot', 'uddot'], stat, &
                                 errmsg, u, hea, udot, uddot)
        if (stat /= SEISPULSE_SUCCESS) return
        ! sdof_step solves z'' + 2 xi omega z' + omega^2 z = -a_g: a_g = (4/pi) g a;
        ! over-damped (xi >= 1): the propagator of (F.38)
        gl = lm * g
        call modal_setup(dt, omega, xi, over, w2, c, st, pr)
        z = 0.0_dp
        v = 0.0_dp
        do i = 1, n
            if (i > 1) call step(i)
            if (.not. (abs(z) + abs(v) / omega < big)) then
                ! a negative damping grows the response beyond range: refuse before overflow
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'xi = '//real_str(xi) &
                               //': the modal response overflows near t = ' &
                               //real_str(real(i - 1, dp) * dt)//' s (omega = ' &
                               //real_str(omega)//' rad/s)')
                return
            end if
            acc = -gl * accel(i) - c * v - w2 * z
            u(i) = z
            hea(i) = accel(i) + lmt * acc / g
            if (present(udot)) udot(i) = v
            if (present(uddot)) uddot(i) = acc
        end do
    contains
        subroutine step(j)
            integer, intent(in) :: j
            real(dp) :: ap, ac, x1, x2, l1
            ap = accel(j - 1)
            ac = accel(j)
            if (over) then
                ! x(h) = x0 + P1 x0' + P2 (0, l'), x0' = (v, -gl a_n - c v - w2 z) (F.38)
                x1 = v
                x2 = -gl * ap - c * v - w2 * z
                l1 = -gl * (ac - ap) / dt
                zn = z + pr%p1(1, 1) * x1 + pr%p1(1, 2) * x2 + pr%p2(1, 2) * l1
                v = v + pr%p1(2, 1) * x1 + pr%p1(2, 2) * x2 + pr%p2(2, 2) * l1
                z = zn
                return
            end if
            zn = st%e11 * z + st%e12 * v + gl * (st%b1 * ap + st%c1 * ac)
            v = st%e21 * z + st%e22 * v + gl * (st%b2 * ap + st%c2 * ac)
            z = zn
        end subroutine step
    end subroutine modal_response_exact

    !> HEA (g) of the record followed by the beam's free vibration after it (a = 0 from the
    !> last sample on, the recurrence of modal_response_exact), sampled at dt (F.48): at least
    !> min_tail samples after the record, then until the stuck beam's energy bound
    !> (2/pi) sqrt(omega^2 u'^2 + u''^2)/g is below ky_min (g) and no slide on HEA alone can
    !> start again. hea(1:n) is modal_response_exact's HEA bit for bit.
    subroutine modal_hea_extended(accel, dt, g, omega, xi, ky_min, min_tail, hea, stat, errmsg)
        real(dp), intent(in) :: accel(:)                      !! record (g) at (i-1) dt
        real(dp), intent(in) :: dt                            !! time step (s) > 0
        real(dp), intent(in) :: g                             !! gravity (m/s^2) > 0
        real(dp), intent(in) :: omega                         !! circular frequency (rad/s) > 0
        real(dp), intent(in) :: xi                            !! damping ratio >= 0
        real(dp), intent(in) :: ky_min                        !! smallest yield (g) > 0
        integer, intent(in) :: min_tail                       !! samples after the record >= 0
        real(dp), allocatable, intent(out) :: hea(:)          !! HEA (g), n + tail samples
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), allocatable :: u(:), ud(:)
        type(sdof_step_t) :: st
        type(prop_t) :: pr
        real(dp) :: z, v, zn, acc, w2, c
        integer :: n, ntail, pass, j
        logical :: over
        call check_modal(accel, dt, g, omega, xi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_damping(xi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. positive(ky_min)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky = '//real_str(ky_min) &
                           //': must be > 0 (g)')
            return
        end if
        n = size(accel)
        allocate(u(n), ud(n), hea(n))
        call modal_response_exact(accel, dt, g, omega, xi, u, hea, stat, errmsg, udot=ud)
        if (stat /= SEISPULSE_SUCCESS) return
        call modal_setup(dt, omega, xi, over, w2, c, st, pr)
        ! pass 1 counts the tail, pass 2 stores it (the same arithmetic)
        ntail = 0
        do pass = 1, 2
            z = u(n)
            v = ud(n)
            do j = 1, max_runout + 1
                if (pass == 2 .and. j > ntail) exit
                acc = -c * v - w2 * z
                if (pass == 1 .and. j > min_tail) then
                    if (lmt * sqrt(w2 * v * v + acc * acc) * (1.0_dp + 1.0e-10_dp) < g * ky_min) &
                        exit
                end if
                if (j > max_runout) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky = ' &
                                   //real_str(ky_min)//': the free vibration after the ' &
                                   //'record stays above the yield for '//int_str(max_runout) &
                                   //' steps')
                    return
                end if
                call free_step()
                if (pass == 1) then
                    ntail = j
                else
                    hea(n + j) = lmt * (-c * v - w2 * z) / g
                end if
            end do
            if (pass == 1) then
                if (ntail == 0) return
                call grow()
            end if
        end do
    contains
        !> One step of the recurrence of modal_response_exact with a = 0.
        subroutine free_step()
            real(dp) :: x1, x2
            if (over) then
                x1 = v
                x2 = -c * v - w2 * z
                zn = z + pr%p1(1, 1) * x1 + pr%p1(1, 2) * x2
                v = v + pr%p1(2, 1) * x1 + pr%p1(2, 2) * x2
                z = zn
                return
            end if
            zn = st%e11 * z + st%e12 * v
            v = st%e21 * z + st%e22 * v
            z = zn
        end subroutine free_step
        subroutine grow()
            real(dp), allocatable :: tmp(:)
            allocate(tmp(n + ntail))
            tmp(1:n) = hea
            call move_alloc(tmp, hea)
        end subroutine grow
    end subroutine modal_hea_extended

    !> The one-step recurrence of the modal response: sdof_step (|xi| < 1) or, over-damped
    !> (xi >= 1), the propagator of (F.38); w2 = omega^2, c = 2 xi omega.
    subroutine modal_setup(dt, omega, xi, over, w2, c, st, pr)
        real(dp), intent(in) :: dt, omega, xi
        logical, intent(out) :: over
        real(dp), intent(out) :: w2, c
        type(sdof_step_t), intent(out) :: st
        type(prop_t), intent(out) :: pr
        over = xi >= 1.0_dp
        w2 = omega**2
        c = 2.0_dp * xi * omega
        if (over) then
            call propagator(c, w2, dt, pr)
        else
            st = sdof_step(2.0_dp * pi / omega, xi, dt)
        end if
    end subroutine modal_setup

    !> The analyses that run on after the record need xi >= 0 (F.48).
    subroutine check_damping(xi, stat, errmsg)
        real(dp), intent(in) :: xi
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (xi < 0.0_dp) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'xi = ' &
                                        //real_str(xi)//': the total damping ratio must be ' &
                                        //'>= 0 (the free vibration after the record would ' &
                                        //'grow and the sliding never end)')
    end subroutine check_damping

    !> Checks shared by the two public routines.
    subroutine check_modal(accel, dt, g, omega, xi, stat, errmsg)
        real(dp), intent(in) :: accel(:), dt, g, omega, xi
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call record_step_check(accel, dt, g, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. finite_positive(omega)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'omega = '//real_str(omega) &
                           //': must be a finite number > 0 (rad/s)')
        else if (.not. (xi > -1.0_dp .and. ieee_is_finite(xi))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'xi = '//real_str(xi) &
                           //': the damping ratio must be finite and > -1')
        end if
    end subroutine check_modal

    ! ------------------------------------------------------------------------------
    ! Coupled sliding
    ! ------------------------------------------------------------------------------

    !> Coupled stick-slip of the flexible mass (F.30)-(F.33), exact: downslope sliding s
    !> (m, >= 0) under the record as given. After the last sample the record is 0 and the
    !> analysis goes on until the mass is at rest and the beam's free vibration can no longer
    !> start a slide, (2/pi) sqrt(omega^2 u'^2 + u''^2) < g ky (F.48) (final_disp includes
    !> it, t_end says when the last slide ended): zero samples appended change nothing.
    !> xi < 0 is refused (the free vibration would grow without end).
    !> Histories at the samples: s (m), s' (m/s), u (m, the sign of (F.30)) and
    !> hea = a + (2/pi) u''/g (g) with u'' of the phase the mass is in ((F.30) or (F.32)).
    !> ky = +inf: never slides. With ky_disp, ky_values (m, g): ky(s) interpolated
    !> linearly, constant beyond the last row; then ky is ignored.
    subroutine coupled_exact(accel, dt, g, omega, xi, ky, max_disp, final_disp, t_end, stat, &
                             errmsg, ky_disp, ky_values, s_hist, sdot_hist, u_modal, hea)
        real(dp), intent(in) :: accel(:)                      !! record (g) at (i-1) dt
        real(dp), intent(in) :: dt                            !! time step (s) > 0
        real(dp), intent(in) :: g                             !! gravity (m/s^2) > 0
        real(dp), intent(in) :: omega                         !! circular frequency (rad/s) > 0
        real(dp), intent(in) :: xi                            !! total damping ratio >= 0
        real(dp), intent(in) :: ky                            !! yield acceleration (g) > 0
        real(dp), intent(out) :: max_disp                     !! largest s (m)
        real(dp), intent(out) :: final_disp                   !! s at rest at the end (m)
        real(dp), intent(out) :: t_end                        !! end of the last slide (s)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> yield table: displacements (m); with ky_values, or absent (ky used)
        real(dp), intent(in), optional :: ky_disp(:)
        !> yield table: yields (g); with ky_disp, or absent (ky used)
        real(dp), intent(in), optional :: ky_values(:)
        real(dp), intent(out), optional :: s_hist(:)          !! s at the samples (m)
        real(dp), intent(out), optional :: sdot_hist(:)       !! s' at the samples (m/s)
        real(dp), intent(out), optional :: u_modal(:)         !! u at the samples (m), (F.30) sign
        real(dp), intent(out), optional :: hea(:)             !! HEA at the samples (g)

        type(phase_t) :: ph
        type(prop_t) :: p_stick, p_slide, pr
        type(ode_dop853_t) :: ode
        type(table_slide_sys_t) :: sys
        type(poly_fn_t) :: pf
        real(dp), allocatable :: tab_d(:), tab_k(:)
        real(dp) :: hguess, yv(4), yn(4), fv(4), fn(4), sc(4)
        integer :: nt
        logical :: tab
        real(dp) :: cst, w2t, csl, w2s, x, h, t0, as, a0, a1, fa(0:2), fb(0:2), m3, xs
        real(dp) :: u, v, s, sd, gky, tol, ue, ve, se, sde, d2e
        real(dp) :: hp, lsub, om
        integer :: n, i, nev, k, it
        logical :: sliding, found, done

        max_disp = 0.0_dp
        final_disp = 0.0_dp
        t_end = 0.0_dp
        call check_modal(accel, dt, g, omega, xi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_damping(xi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. (positive(ky) .or. present(ky_disp) .or. present(ky_values))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky = '//real_str(ky) &
                           //': must be > 0 (g; +inf: no sliding)')
            return
        end if
        tab = .false.
        gky = g * ky
        if (present(ky_disp) .or. present(ky_values)) then
            if (.not. (present(ky_disp) .and. present(ky_values))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_disp, ky_values: ' &
                               //'give both or neither')
                return
            end if
            call ky_table_validate(ky_disp, ky_values, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            ! one row: the constant yield (the same arithmetic, bit for bit)
            gky = g * ky_values(1)
            tab = size(ky_disp) > 1
            if (tab) then
                allocate(tab_d, source=ky_disp)
                allocate(tab_k, source=ky_values)
                nt = size(tab_d)
            end if
        end if
        n = size(accel)
        call check_history_sizes(n, [character(len=9) :: 's_hist', 'sdot_hist', 'u_modal', 'hea'], &
                                 stat, errmsg, s_hist, sdot_hist, u_modal, hea)
        if (stat /= SEISPULSE_SUCCESS) return

        cst = 2.0_dp * xi * omega
        w2t = omega**2
        csl = cst / d1
        w2s = w2t / d1
        call propagator(cst, w2t, dt, p_stick)
        call propagator(csl, w2s, dt, p_slide)
        if (tab) then
            ! tolerances: rtol on the state, atol at 1e-12 of the scales of a slide
            sc(1) = lm * g * maxval(tab_k) / w2t
            sc(2) = g * maxval(tab_k) / omega
            sc(3) = g * maxval(tab_k) * dt * dt
            sc(4) = g * maxval(tab_k) * dt
            call ode%init(4, table_rtol, table_rtol * sc, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            sys%c = cst
            sys%w2 = w2t
            hguess = dt
        end if
        u = 0.0_dp
        v = 0.0_dp
        s = 0.0_dp
        sd = 0.0_dp
        sliding = .false.
        ! the mass starts at rest: it slides at once if HEA(0) = d1 g a(0) exceeds g ky
        call set_phase(0, 0.0_dp, accel(1), accel(1))
        call phase_f(ph, 0.0_dp, u, v, sd, fa)
        if (onset_now(fa)) call start_slide()
        call record(1, accel(1))

        done = .false.
        i = 0
        do k = 1, n - 1 + max_runout
            i = i + 1
            if (i <= n - 1) then
                a0 = accel(i)
                a1 = accel(i + 1)
            else
                ! after the record: a = 0 until the mass is at rest and no onset can follow
                ! (F.48)
                if (.not. sliding .and. quiet()) then
                    done = .true.
                    exit
                end if
                a0 = 0.0_dp
                a1 = 0.0_dp
            end if
            t0 = real(i - 1, dp) * dt
            x = 0.0_dp
            as = a0
            nev = 0
            lsub = 0.0_dp
            events: do it = 1, (max_events + 1) * max_sub
                if (nev > max_events .or. it == (max_events + 1) * max_sub) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'coupled_exact: more ' &
                                   //'than '//int_str(max_events)//' onsets and stops in one ' &
                                   //'step near t = '//real_str(t0)//' s (the stick-slip ' &
                                   //'chatters: a smaller dt or another ky)')
                    return
                end if
                h = dt - x
                if (.not. (h > 0.0_dp)) exit events
                if (tab .and. sliding) then
                    call table_piece(h, as, a1, found, xs)
                    if (stat /= SEISPULSE_SUCCESS) return
                    if (.not. found) exit events
                    as = as + (a1 - as) * (xs / h)
                    x = x + xs
                    sd = 0.0_dp
                    sliding = .false.
                    t_end = t0 + x
                    gky = g * table_ky(s)
                    cycle events
                end if
                call set_phase(merge(1, 0, sliding), x, as, a1)
                call phase_f(ph, 0.0_dp, u, v, sd, fa)
                if (.not. sliding) then
                    if (onset_now(fa)) then
                        call start_slide()
                        cycle events
                    end if
                end if
                fa(0) = max(fa(0), 0.0_dp)
                if (sliding .and. zero(fa(0))) fa(1) = max(fa(1), 0.0_dp)
                ! a stiff phase (omega h > stiff_len): pieces from stiff_len/omega on, doubling,
                ! with the bound renewed at each piece's start (the transient decays)
                hp = h
                om = sqrt(ph%w2)
                if (om * h > stiff_len) then
                    if (.not. (lsub > 0.0_dp)) lsub = stiff_len / om
                    hp = min(h, lsub)
                    lsub = 2.0_dp * lsub
                end if
                ! the end of the piece (the full-step propagators computed once)
                if (x > 0.0_dp .or. hp < h) then
                    call propagator(ph%c, ph%w2, hp, pr)
                    call phase_state(ph, pr, hp, ue, ve, se, sde, d2e)
                else if (sliding) then
                    call phase_state(ph, p_slide, hp, ue, ve, se, sde, d2e)
                else
                    call phase_state(ph, p_stick, hp, ue, ve, se, sde, d2e)
                end if
                call phase_f(ph, hp, ue, ve, sde, fb)
                m3 = phase_bound(hp)
                ! most steps: no event, proven by the first test of first_zero
                found = .false.
                if (.not. excluded(fa, fb, hp, m3)) then
                    call first_zero(ph, hp, fa, fb, m3, found, xs, stat, errmsg)
                    if (stat /= SEISPULSE_SUCCESS) then
                        call stiff_message()
                        return
                    end if
                end if
                if (.not. found) then
                    u = ue
                    v = ve
                    if (sliding) then
                        s = se
                        sd = sde
                    end if
                    if (hp < h) then
                        ! the next piece of a stiff phase
                        as = as + (a1 - as) * (hp / h)
                        x = x + hp
                        cycle events
                    end if
                    exit events
                end if
                ! the event at xs: advance the state there
                nev = nev + 1
                lsub = 0.0_dp
                call propagator(ph%c, ph%w2, xs, pr)
                call advance(pr, xs)
                as = as + (a1 - as) * (xs / h)
                x = x + xs
                if (sliding) then
                    sd = 0.0_dp
                    sliding = .false.
                    t_end = t0 + x
                else
                    call start_slide()
                end if
            end do events
            if (.not. (ieee_is_finite(u) .and. ieee_is_finite(v) .and. ieee_is_finite(s) &
                       .and. ieee_is_finite(sd))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'coupled_exact: the ' &
                               //'response overflows near t = '//real_str(t0)//' s (omega = ' &
                               //real_str(omega)//' rad/s, xi = '//real_str(xi)//')')
                return
            end if
            if (i <= n - 1) call record(i + 1, a1)
        end do
        if (.not. done) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky = '//real_str(ky) &
                           //': the mass still slides or the beam can still start a slide ' &
                           //int_str(max_runout)//' steps after the record (the run-out ' &
                           //'does not end)')
            return
        end if
        final_disp = s
        max_disp = s

    contains

        !> At rest after the record (a = 0): the stuck beam's (u', u'') has the energy
        !> N^2 = omega^2 u'^2 + u''^2, not increasing for xi >= 0, and |u''| <= N; no onset
        !> can follow once (2/pi) N < g ky (F.48).
        logical function quiet()
            real(dp) :: acc, nn
            acc = -cst * v - w2t * u
            nn = sqrt(w2t * v * v + acc * acc)
            quiet = lmt * nn * (1.0_dp + 1.0e-10_dp) < gky
            if (.not. ieee_is_finite(gky)) quiet = .true.
        end function quiet

        !> A first_zero that does not decide: the mass is too stiff for dt (or the bound
        !> is not finite); the message names omega.
        subroutine stiff_message()
            stat = SEISPULSE_INVALID_INPUT
            if (present(errmsg)) errmsg = 'omega = '//real_str(omega)//' rad/s, dt = ' &
                //real_str(dt)//' s: the onsets and stops of this stiff mass cannot be ' &
                //'decided within the bounds of the exact rule (a larger height or a lower vs)'
        end subroutine stiff_message

        !> The phase (0 stick, 1 slide) from the current state at x with g a = as .. a1.
        subroutine set_phase(mode, xx, aa, ae)
            integer, intent(in) :: mode
            real(dp), intent(in) :: xx, aa, ae
            ph%slide = mode == 1
            ph%u0 = u
            ph%v0 = v
            ph%s0 = s
            ph%sd0 = sd
            ph%ga0 = g * aa
            if (dt - xx > 0.0_dp) then
                ph%gas = g * (ae - aa) / (dt - xx)
            else
                ph%gas = 0.0_dp
            end if
            ph%gky = gky
            if (ph%slide) then
                ph%c = csl
                ph%w2 = w2s
                ph%l0 = -lm * gky / d1
                ph%l1 = 0.0_dp
            else
                ph%c = cst
                ph%w2 = w2t
                ph%l0 = -lm * ph%ga0
                ph%l1 = -lm * ph%gas
            end if
            ph%acc0 = ph%l0 - ph%c * v - ph%w2 * u
            ph%jrk0 = ph%l1 - ph%c * ph%acc0 - ph%w2 * v
        end subroutine set_phase

        !> At rest, HEA exceeds g ky at the start of the phase (more than rounding), or
        !> reaches it there and grows.
        logical function onset_now(f)
            real(dp), intent(in) :: f(0:2)
            if (.not. ieee_is_finite(gky)) then
                onset_now = .false.
                return
            end if
            tol = 8.0_dp * epsilon(1.0_dp) * (gky + abs(ph%ga0) + lmt * abs(ph%acc0))
            if (f(0) < -tol) then
                onset_now = .true.
            else if (f(0) <= tol) then
                ! a double zero (f = f' = 0): the slide's s'''' decides (s'' = -f/d1,
                ! s''' = -f'/d1 at an onset; s'''' = (2/pi) u'''' of (F.32), a'' = 0)
                onset_now = f(1) < 0.0_dp .or. (zero(f(1)) .and. slide_s4() > 0.0_dp)
            else
                onset_now = .false.
            end if
        end function onset_now

        !> s'''' at the start of a slide from the current state (F.32)-(F.33).
        real(dp) function slide_s4()
            real(dp) :: acc, jrk
            acc = (-lm * gky - cst * v - w2t * u) / d1
            jrk = (-cst * acc - w2t * v) / d1
            slide_s4 = lmt * (-cst * jrk - w2t * acc) / d1
        end function slide_s4

        subroutine start_slide()
            sliding = .true.
            sd = 0.0_dp
        end subroutine start_slide

        !> Move the state by the phase over hh (propagator p).
        subroutine advance(p, hh)
            type(prop_t), intent(in) :: p
            real(dp), intent(in) :: hh
            real(dp) :: uu, vv, ss, ssd, dd2
            call phase_state(ph, p, hh, uu, vv, ss, ssd, dd2)
            u = uu
            v = vv
            if (ph%slide) then
                s = ss
                sd = ssd
            end if
        end subroutine advance

        !> Bound on |f'''| over the phase of length hh (F.45).
        real(dp) function phase_bound(hh)
            real(dp), intent(in) :: hh
            real(dp) :: snp, crk, grow
            snp = -ph%c * ph%jrk0 - ph%w2 * ph%acc0
            crk = -ph%c * snp - ph%w2 * ph%jrk0
            grow = 1.0_dp
            if (ph%c < 0.0_dp) grow = exp(-ph%c * hh)
            if (ph%slide) then
                ! f''' = (2/pi) u'''' and (u''', u'''') solves the free oscillator
                phase_bound = lmt * sqrt(ph%w2 * ph%jrk0**2 + snp**2) * grow
            else
                ! f''' = -(2/pi) u^(5) and (u'''', u^(5)) solves the free oscillator
                phase_bound = lmt * sqrt(ph%w2 * snp**2 + crk**2) * grow
            end if
            phase_bound = phase_bound * (1.0_dp + 1.0e-10_dp)
        end function phase_bound

        !> ky (g) at s (m): linear on the table's segments, constant beyond the last row.
        pure real(dp) function table_ky(ss)
            real(dp), intent(in) :: ss
            table_ky = ky_table_at(ss, tab_d(1:nt), tab_k(1:nt))
        end function table_ky

        !> The segment of s: its start, g ky there and g dky/ds into sys.
        subroutine set_segment(ss)
            real(dp), intent(in) :: ss
            integer :: j
            sys%sj = tab_d(nt)
            sys%gk0 = g * tab_k(nt)
            sys%gk1 = 0.0_dp
            do j = 1, nt - 1
                if (ss < tab_d(j + 1)) then
                    sys%sj = tab_d(j)
                    sys%gk0 = g * tab_k(j)
                    sys%gk1 = g * (tab_k(j + 1) - tab_k(j)) / (tab_d(j + 1) - tab_d(j))
                    exit
                end if
            end do
        end subroutine set_segment

        !> Slide with the table over hp (a from aa to ae) by DOP853 (F.49)-(F.49): on each
        !> accepted step the stop is the first zero of the dense output's polynomial of s'
        !> (first_zero, a proven bracket on that polynomial), a segment end the crossing of
        !> its polynomial of s (increasing until the stop: one crossing, Brent); the
        !> integration restarts there with the next segment's law.
        subroutine table_piece(hp, aa, ae, found_stop, x_stop)
            real(dp), intent(in) :: hp, aa, ae
            logical, intent(out) :: found_stop
            real(dp), intent(out) :: x_stop
            real(dp) :: t, hh, err, fa2(0:2), fb2(0:2), xz, xe, xb2, mm, dnext
            integer :: it
            logical :: fnd
            found_stop = .false.
            x_stop = hp
            sys%ga0 = g * aa
            sys%gas = g * (ae - aa) / hp
            call set_segment(s)
            t = 0.0_dp
            yv = [u, v, s, sd]
            call sys%rhs(t, yv, fv)
            do it = 1, max_ode_steps
                if (.not. (hp - t > 4.0_dp * epsilon(1.0_dp) * hp)) exit
                hh = min(hguess, hp - t)
                if (hp - t - hh < 1.0e-3_dp * hh) hh = hp - t
                call ode%step(sys, t, yv, fv, hh, t + hh, yn, fn, err)
                if (.not. err <= 1.0_dp) then
                    hguess = hh * ode_dop853_factor(err)
                    cycle
                end if
                call ode%dense_setup(sys, t, yv, fv, hh, yn, fn)
                ! the stop: first zero of s'(x) on (0, 1]
                call dense_poly(4, pf%c)
                call pf%taylor(0.0_dp, fa2)
                fa2(0) = max(fa2(0), 0.0_dp)
                if (.not. (fa2(0) > 0.0_dp)) fa2(1) = max(fa2(1), 0.0_dp)
                call pf%taylor(1.0_dp, fb2)
                mm = poly_bound3(pf%c)
                call first_zero(pf, 1.0_dp, fa2, fb2, mm, fnd, xz, stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                xe = 1.0_dp
                if (fnd) xe = xz
                ! a segment end before the stop: s rises to it once
                if (sys%sj < tab_d(nt)) then
                    dnext = next_break(s)
                    if (ode%dense%component(3, xe) >= dnext) then
                        call dense_poly(3, pf%c)
                        pf%c(0) = pf%c(0) - dnext
                        call find_root(pf, 0.0_dp, xe, xb2, stat, errmsg, &
                                       fa_known=pf%c(0), fb_known=ode%dense%component(3, xe) &
                                       - dnext)
                        if (stat /= SEISPULSE_SUCCESS) return
                        call ode%dense%value(xb2, yv)
                        yv(3) = dnext
                        t = t + xb2 * hh
                        call take(yv)
                        call set_segment(s)
                        call sys%rhs(t, yv, fv)
                        cycle
                    end if
                end if
                if (fnd) then
                    call ode%dense%value(xz, yv)
                    yv(4) = 0.0_dp
                    call take(yv)
                    found_stop = .true.
                    x_stop = t + xz * hh
                    return
                end if
                t = t + hh
                yv = yn
                fv = fn
                call take(yv)
                hguess = hh * ode_dop853_factor(err)
            end do
            if (it > max_ode_steps) then
                call set_error(stat, errmsg, SEISPULSE_INTERNAL, 'coupled_exact: too many ' &
                               //'integrator steps in one record step (a bug)')
            end if
        end subroutine table_piece

        !> The table row after s (m).
        pure real(dp) function next_break(ss)
            real(dp), intent(in) :: ss
            integer :: j
            next_break = huge(1.0_dp)
            do j = 2, nt
                if (tab_d(j) > ss) then
                    next_break = tab_d(j)
                    return
                end if
            end do
        end function next_break

        subroutine take(y)
            real(dp), intent(in) :: y(4)
            u = y(1)
            v = y(2)
            s = y(3)
            sd = y(4)
        end subroutine take

        !> Monomial coefficients in x of component m of the last step's dense output.
        subroutine dense_poly(m, c)
            integer, intent(in) :: m
            real(dp), intent(out) :: c(0:7)
            c = 0.0_dp
            c(1) = ode%dense%r(m, 7)
            c(0) = c(0) + ode%dense%r(m, 6)
            call times_one_minus_x(c)
            c(0) = c(0) + ode%dense%r(m, 5)
            call times_x(c)
            c(0) = c(0) + ode%dense%r(m, 4)
            call times_one_minus_x(c)
            c(0) = c(0) + ode%dense%r(m, 3)
            call times_x(c)
            c(0) = c(0) + ode%dense%r(m, 2)
            call times_one_minus_x(c)
            c(0) = c(0) + ode%dense%r(m, 1)
            call times_x(c)
            c(0) = c(0) + ode%dense%y0(m)
        end subroutine dense_poly

        !> Histories at sample j (a = record value there).
        subroutine record(j, aj)
            integer, intent(in) :: j
            real(dp), intent(in) :: aj
            real(dp) :: acc
            if (present(s_hist)) s_hist(j) = s
            if (present(sdot_hist)) sdot_hist(j) = sd
            if (present(u_modal)) u_modal(j) = u
            if (present(hea)) then
                if (sliding .and. tab) then
                    acc = (-lm * g * table_ky(s) - cst * v - w2t * u) / d1
                else if (sliding) then
                    acc = (-lm * gky - cst * v - w2t * u) / d1
                else
                    acc = -lm * g * aj - cst * v - w2t * u
                end if
                hea(j) = aj + lmt * acc / g
            end if
        end subroutine record

    end subroutine coupled_exact

    !> State of phase ph after tau (propagator p of length tau): u, u' (m, m/s), s, s'
    !> (m, m/s; the start values when sticking) and d2 = u - u0 - tau u0' (m).
    pure subroutine phase_state(ph, p, tau, u, v, s, sd, d2)
        type(phase_t), intent(in) :: ph
        type(prop_t), intent(in) :: p
        real(dp), intent(in) :: tau
        real(dp), intent(out) :: u, v, s, sd, d2
        real(dp) :: x1(2), x2(2), du, dv
        ! x0' = (v0, acc0), x0'' = (acc0, jrk0); (F.38)
        x1 = [ph%v0, ph%acc0]
        x2 = [ph%acc0, ph%jrk0]
        du = p%p1(1, 1) * x1(1) + p%p1(1, 2) * x1(2) + p%p2(1, 2) * ph%l1
        dv = p%p1(2, 1) * x1(1) + p%p1(2, 2) * x1(2) + p%p2(2, 2) * ph%l1
        u = ph%u0 + du
        v = ph%v0 + dv
        d2 = p%p2(1, 1) * x2(1) + p%p2(1, 2) * x2(2)
        if (ph%slide) then
            ! (F.41): s' and s from the record and the modal increments
            sd = ph%sd0 + tau * (ph%ga0 - ph%gky + 0.5_dp * ph%gas * tau) + lmt * dv
            s = ph%s0 + tau * (ph%sd0 + tau * (0.5_dp * (ph%ga0 - ph%gky) &
                + ph%gas * tau / 6.0_dp)) + lmt * d2
        else
            sd = ph%sd0
            s = ph%s0
        end if
    end subroutine phase_state

    !> f, f', f'' of the phase at tau from the state there.
    pure subroutine phase_f(ph, tau, u, v, sd, f)
        type(phase_t), intent(in) :: ph
        real(dp), intent(in) :: tau, u, v, sd
        real(dp), intent(out) :: f(0:2)
        real(dp) :: acc, jrk, snp, ga
        ga = ph%ga0 + ph%gas * tau
        acc = ph%l0 + ph%l1 * tau - ph%c * v - ph%w2 * u
        jrk = ph%l1 - ph%c * acc - ph%w2 * v
        if (ph%slide) then
            ! f = s' (F.33)
            f(0) = sd
            f(1) = ga - ph%gky + lmt * acc
            f(2) = ph%gas + lmt * jrk
        else
            ! f = g ky - HEA (F.31)
            snp = -ph%c * jrk - ph%w2 * acc
            f(0) = ph%gky - ga - lmt * acc
            f(1) = -ph%gas - lmt * jrk
            f(2) = -lmt * snp
        end if
    end subroutine phase_f

    !> The phase function at x: the propagator of length x, the state, f.
    subroutine phase_taylor(self, x, f)
        class(phase_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), intent(out) :: f(0:2)
        type(prop_t) :: p
        real(dp) :: u, v, s, sd, d2
        call propagator(self%c, self%w2, x, p)
        call phase_state(self, p, x, u, v, s, sd, d2)
        call phase_f(self, x, u, v, sd, f)
    end subroutine phase_taylor

    !> The slide with a linear ky(s) (F.49): d1 u'' + c u' + w2 u = -(4/pi) g ky(s),
    !> s'' = g a - g ky(s) + (2/pi) u''.
    subroutine table_slide_rhs(self, t, y, dydt)
        class(table_slide_sys_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        real(dp) :: gk, acc
        gk = self%gk0 + self%gk1 * (y(3) - self%sj)
        acc = (-lm * gk - self%c * y(2) - self%w2 * y(1)) / d1
        dydt(1:4) = [y(2), acc, y(4), self%ga0 + self%gas * t - gk + lmt * acc]
    end subroutine table_slide_rhs

    !> p, p', p'' of the polynomial at x.
    subroutine poly_taylor(self, x, f)
        class(poly_fn_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), intent(out) :: f(0:2)
        integer :: k
        f = 0.0_dp
        do k = 7, 0, -1
            f(2) = f(2) * x + 2.0_dp * f(1)
            f(1) = f(1) * x + f(0)
            f(0) = f(0) * x + self%c(k)
        end do
    end subroutine poly_taylor

    !> max |p'''| on [0, 1] <= sum k(k-1)(k-2) |c_k|.
    pure real(dp) function poly_bound3(c) result(m)
        real(dp), intent(in) :: c(0:7)
        integer :: k
        m = 0.0_dp
        do k = 3, 7
            m = m + real(k * (k - 1) * (k - 2), dp) * abs(c(k))
        end do
        m = m * (1.0_dp + 1.0e-10_dp)
    end function poly_bound3

    !> c times (1 - x), degree kept within 7 (explicit shifts: no temporary).
    pure subroutine times_one_minus_x(c)
        real(dp), intent(inout) :: c(0:7)
        integer :: k
        do k = 7, 1, -1
            c(k) = c(k) - c(k - 1)
        end do
    end subroutine times_one_minus_x

    !> c times x, degree kept within 7.
    pure subroutine times_x(c)
        real(dp), intent(inout) :: c(0:7)
        integer :: k
        do k = 7, 1, -1
            c(k) = c(k - 1)
        end do
        c(0) = 0.0_dp
    end subroutine times_x

    ! ------------------------------------------------------------------------------
    ! The oscillator's matrix functions
    ! ------------------------------------------------------------------------------

    !> e^(tau A), tau phi_1(tau A), tau^2 phi_2(tau A) for A = [0 1; -w2 -c], any real c
    !> and w2 > 0 (under-, critically or over-damped, negative damping): f(tau A) =
    !> alpha I + beta tau A with beta = f[mu1, mu2], alpha = f(mu2) - mu2 beta at the
    !> eigenvalues mu of tau A (F.39).
    pure subroutine propagator(c, w2, tau, p)
        real(dp), intent(in) :: c    !! damping coefficient (1/s)
        real(dp), intent(in) :: w2   !! stiffness (1/s^2)
        real(dp), intent(in) :: tau  !! step (s) >= 0
        type(prop_t), intent(out) :: p  !! the propagator of the step (SI: s, 1/s)
        complex(dp) :: q, mu1, mu2, b0, e2, b1, b2, p0, ph1, ph2
        real(dp) :: al0, al1, al2, be0, be1, be2, ta(2, 2)
        integer :: k
        if (.not. (tau > 0.0_dp)) then
            p%e = reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
            p%p1 = 0.0_dp
            p%p2 = 0.0_dp
            return
        end if
        ! eigenvalues -c/2 +- sqrt(c^2/4 - w2), times tau
        q = sqrt(cmplx(0.25_dp * c * c - w2, 0.0_dp, dp))
        if (c >= 0.0_dp) then
            mu1 = tau * (-0.5_dp * c - q)
            ! the product of the roots is w2: the smaller one without cancellation
            mu2 = tau * w2 / (-0.5_dp * c - q)
        else
            mu1 = tau * (-0.5_dp * c + q)
            mu2 = tau * w2 / (-0.5_dp * c + q)
        end if
        call cexp_dd1(mu1, mu2, b0, e2)
        b1 = cexp_dd2(mu1, mu2, (0.0_dp, 0.0_dp))
        b2 = cexp_dd3(mu1, mu2, (0.0_dp, 0.0_dp), (0.0_dp, 0.0_dp))
        call complex_phis(mu2, p0, ph1, ph2)
        be0 = real(b0, dp)
        be1 = real(b1, dp)
        be2 = real(b2, dp)
        al0 = real(e2 - mu2 * b0, dp)
        al1 = real(ph1 - mu2 * b1, dp)
        al2 = real(ph2 - mu2 * b2, dp)
        ta = reshape([0.0_dp, -w2 * tau, tau, -c * tau], [2, 2])
        p%e = be0 * ta
        p%p1 = (tau * be1) * ta
        p%p2 = (tau * tau * be2) * ta
        do k = 1, 2
            p%e(k, k) = p%e(k, k) + al0
            p%p1(k, k) = p%p1(k, k) + tau * al1
            p%p2(k, k) = p%p2(k, k) + tau * tau * al2
        end do
    end subroutine propagator

    ! ------------------------------------------------------------------------------
    ! First zero on a proven bracket
    ! ------------------------------------------------------------------------------

    !> f(x), the first member of `taylor`, for the root finder.
    function zero_eval(self, x) result(y)
        class(zero_function), intent(inout) :: self  !! the function
        real(dp), intent(in) :: x  !! the argument (unit of the function's variable)
        real(dp) :: y
        real(dp) :: f(0:2)
        call self%taylor(x, f)
        y = f(0)
    end function zero_eval

    !> The first zero of f in (0, h] (F.44)-(F.47). Given f >= 0 at 0 with f > 0 just
    !> after 0 (f(0) > 0, or f(0) = 0 and f'(0) > 0, or f(0) = f'(0) = 0 < f''(0)), fa =
    !> (f, f', f'') at 0, fb at h, and m3 >= |f'''| on [0, h]. found = .false.: f > 0 on
    !> (0, h] (up to a dip below 0 of at most m3 h^3 eps^3 in a sub-interval of width
    !> 4 eps h, which is rounding). Sub-intervals are excluded by the Taylor bounds from
    !> both ends; a sub-interval with f(b) <= 0 on which f' < 0 is proven holds exactly
    !> one zero, found by Brent's method; anything else is halved (at most max_depth
    !> levels).
    subroutine first_zero(fn, h, fa, fb, m3, found, x, stat, errmsg)
        class(zero_function), intent(inout) :: fn             !! the function
        real(dp), intent(in) :: h                             !! interval end (> 0)
        real(dp), intent(in) :: fa(0:2)                       !! f, f', f'' at 0
        real(dp), intent(in) :: fb(0:2)                       !! f, f', f'' at h
        real(dp), intent(in) :: m3                            !! bound on |f'''| on [0, h]
        logical, intent(out) :: found                         !! a zero in (0, h]
        real(dp), intent(out) :: x                            !! the first zero
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: xs(max_depth + 1), fs(0:2, max_depth + 1), xa, fl(0:2), xb, fr(0:2)
        real(dp) :: el, width, xm, fm(0:2)
        integer :: top, iter
        stat = SEISPULSE_SUCCESS
        found = .false.
        x = h
        if (.not. (ieee_is_finite(m3) .and. all(ieee_is_finite(fa)) &
                   .and. all(ieee_is_finite(fb)))) then
            ! a bound that is not finite proves nothing
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'first_zero: f or the ' &
                           //'bound on its third derivative is not finite (overflow)')
            return
        end if
        width = 4.0_dp * epsilon(1.0_dp) * h
        xa = 0.0_dp
        fl = fa
        top = 1
        xs(1) = h
        fs(:, 1) = fb
        do iter = 1, 64 * (max_depth + 2)
            xb = xs(top)
            fr = fs(:, top)
            el = xb - xa
            if (excluded(fl, fr, el, m3)) then
                call pop()
                if (top == 0) return
                cycle
            end if
            if (fr(0) <= 0.0_dp .and. (decreasing(fl, fr, el, m3) .or. el <= width &
                                       .or. top > max_depth)) then
                found = .true.
                if (zero(fr(0)) .or. .not. (fl(0) > 0.0_dp)) then
                    x = xb
                    if (.not. (fl(0) > 0.0_dp)) x = xa
                else
                    call find_root(fn, xa, xb, x, stat, errmsg, fa_known=fl(0), fb_known=fr(0))
                end if
                x = min(max(x, xa), xb)
                return
            end if
            if (el <= width .or. top > max_depth) then
                ! f > 0 at both ends of a sub-interval at rounding width: no stop here
                call pop()
                if (top == 0) return
                cycle
            end if
            xm = xa + 0.5_dp * el
            call fn%taylor(xm, fm)
            top = top + 1
            xs(top) = xm
            fs(:, top) = fm
        end do
        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'first_zero: no decision in ' &
                       //int_str(64 * (max_depth + 2))//' sub-intervals (the bound on the ' &
                       //'third derivative is too large for the interval)')

    contains

        subroutine pop()
            xa = xs(top)
            fl = fs(:, top)
            top = top - 1
        end subroutine pop

    end subroutine first_zero

    !> No zero of f in (xa, xa + el]: the Taylor lower bounds from the two ends
    !> (F.46) are positive on pieces that cover the interval.
    pure logical function excluded(fl, fr, el, m3)
        real(dp), intent(in) :: fl(0:2), fr(0:2), el, m3
        real(dp) :: dl, dr
        excluded = .false.
        if (.not. (fr(0) > 0.0_dp)) return
        ! a bound or a value that is not finite proves nothing
        if (.not. (ieee_is_finite(m3) .and. all(ieee_is_finite(fl)) &
                   .and. all(ieee_is_finite(fr)))) return
        ! the crude bound f >= f(xa) - |f'(xa)| L - max(0, M3 L/3 - f''(xa)) L^2/2 first
        excluded = fl(0) - abs(fl(1)) * el - max(0.0_dp, m3 * el / 3.0_dp - fl(2)) * el * el &
                   * 0.5_dp > 0.0_dp
        if (excluded) return
        dl = first_positive_root(fl(0), fl(1), 0.5_dp * (fl(2) - m3 * el / 3.0_dp))
        dr = first_positive_root(fr(0), -fr(1), 0.5_dp * (fr(2) - m3 * el / 3.0_dp))
        if (dl >= el .or. dr >= el) then
            excluded = .true.
        else
            excluded = dl + dr > el
        end if
    end function excluded

    !> f' < 0 on (xa, xa + el) from the Taylor upper bounds of f' (F.47).
    pure logical function decreasing(fl, fr, el, m3)
        real(dp), intent(in) :: fl(0:2), fr(0:2), el, m3
        real(dp) :: bl, br
        bl = fl(1) + max(fl(2), 0.0_dp) * el + 0.5_dp * m3 * el * el
        br = fr(1) + max(-fr(2), 0.0_dp) * el + 0.5_dp * m3 * el * el
        decreasing = bl < 0.0_dp .or. br < 0.0_dp
    end function decreasing

    !> x is zero (no -Wcompare-reals).
    elemental logical function zero(x)
        real(dp), intent(in) :: x
        zero = abs(x) <= 0.0_dp
    end function zero

    !> The first d > 0 where c0 + c1 d + c2 d^2 (c0 >= 0) reaches 0; huge if never; 0 if it
    !> is not positive just after 0.
    pure real(dp) function first_positive_root(c0, c1, c2) result(d)
        real(dp), intent(in) :: c0, c1, c2
        real(dp) :: disc, qq, r1, r2
        d = huge(1.0_dp)
        if (c0 < 0.0_dp) then
            d = 0.0_dp
        else if (zero(c0)) then
            if (c1 > 0.0_dp) then
                if (c2 < 0.0_dp) d = -c1 / c2
            else if (.not. (zero(c1) .and. c2 > 0.0_dp)) then
                d = 0.0_dp
            end if
        else if (zero(c2)) then
            if (c1 < 0.0_dp) d = -c0 / c1
        else
            disc = c1 * c1 - 4.0_dp * c2 * c0
            if (disc < 0.0_dp) return   ! c2 > 0: no real root
            qq = -0.5_dp * (c1 + sign(sqrt(disc), c1))
            r1 = huge(1.0_dp)
            r2 = huge(1.0_dp)
            if (.not. zero(qq)) then
                r1 = qq / c2
                r2 = c0 / qq
            end if
            if (r1 > 0.0_dp) d = min(d, r1)
            if (r2 > 0.0_dp) d = min(d, r2)
        end if
    end function first_positive_root

end module seispulse_flexible_exact
