!> Rocking of a slender rigid block on a rigid base under the half-cycle exponential pulse
!> of Jacobsen & Ayre: the linearized closed forms of chapter 2 of Ref. [GR], corrected and in
!> numerically stable form (theory and corrections: doc/rocking.md; equation numbers below
!> are the chapter's, sections are those of doc/rocking.md).
!>
!> Dimensionless throughout (doc/rocking.md section 1): f = p t_d (the printed f = p/t_d is an
!> erratum: doc/rocking.md Corrections 1), eta = alpha/alpha_g, tau = t/t_d, psi = theta/alpha and
!> dpsi = (dtheta/dt)/(alpha p) = psi'/f (' = d/dtau). The pulse is Eq. 2.1 = 1.1b with shape
!> beta: -inf the rectangle, 0 the triangle, +inf the spike of zero area (no rocking).
!> First excursion: psi'' - f^2 psi = f^2 g, g = s(tau)/eta - 1, psi = psi' = 0 at tau_up.
!>
!> Stable core (section 2 in divided-difference form). After uplift the forcing is, on
!> each half of the pulse, a multiple of expm1 of a linear function of tau:
!>   g = K expm1(2 beta (tau - tau_up))/(2 beta)          on [tau_up, 1/2],
!>   g = K expm1(-2 beta (tau - 1 + tau_up))/(2 beta)     on [1/2, 1],
!> with K = 2 beta Q/(eta (e^beta - 1)) > 0, Q = e^(2 beta tau_up) (Eq. 2.4; K -> 2/eta as
!> beta -> 0). The Duhamel integrals of section 2 are then divided differences of exp at
!> the nodes 2 beta h, 0, +-f h (h the time into the phase): phase 1 gives
!>   psi = K f^2 h^3 exp[2 beta h, 0, f h, -f h],
!>   psi'/f = K f h^2 (exp[2 beta h, 0, f h] + exp[2 beta h, 0, -f h])/2,
!> and phase 2 the same with shifted nodes plus the free response from tau = 1/2. These
!> have no f^2 - 4 beta^2 denominator (f = 2|beta| is merely a double node: doc/rocking.md section
!> 2, item 1), no 1/(1 - e^beta) (doc/rocking.md section 2, item 2), and all nodes but the decaying
!> -2 beta h stay below |ln eta| + |ln(1 - eta)| for any beta (doc/rocking.md section 2, item 3).
!> Divided differences are evaluated without cancellation (seispulse_divided_differences): Taylor
!> series of the complete symmetric polynomials for clustered nodes, the recurrence on sorted nodes
!> otherwise (a few ulps either way). After the pulse
!> the state transition psi - 1 = A e^(f(tau-1)) + B e^(-f(tau-1)) (section 2, phase 3).
!> beta = 0 and -inf use the triangle (2.14, 2.15) and rectangle (2.12, 2.13) forms and
!> their limit equations; a large negative beta is never substituted for the rectangle
!> (doc/rocking.md section 2, item 4).
!>
!> Roots in time (tau_c in O1/O2, tau_m in S1, tau_i during the pulse) lie on proven
!> brackets inside one phase, whose end states are known; a sixth-order Newton method on
!> Taylor models built from the equation of motion (phase_root) needs about two
!> evaluations, with find_root_newton as the guaranteed fallback. Boundaries in eta or f
!> (2.16, S1/S2, inverses) use find_root (Brent) on brackets found by halving/doubling.
!> rocking_summary computes the state psi(1/2), psi(1), psi'(1), A, B once for everything.
module seispulse_rocking_closed
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
                                             ieee_quiet_nan, ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_checks, only: outside
    use seispulse_format, only: real_str
    use seispulse_special, only: expm1, log1p, phi1, phi1_from_exp, log1p_over_x, sinh_minus_x, &
                                 x_minus_asinh
    use seispulse_divided_differences, only: exp_dd_pack
    use seispulse_pulses, only: check_beta, exp_rise_time
    use seispulse_roots, only: scalar_function, find_root, smooth_function, find_root_newton
    implicit none
    private

    public :: ROCK_NONE, ROCK_O1, ROCK_O2, ROCK_O3, ROCK_S1, ROCK_S2
    public :: rocking_region_name, uplift_time, rocking_response, stability_wall, &
              rocking_extremes, &
              stability_wall_inverse, overturn_boundary, overturn_boundary_inverse, &
              rocking_classify, critical_time, time_of_max, max_rotation, impact_time, &
              s1_s2_boundary, rocking_summary
    public :: rect_time_of_max_normalized, rect_max_rotation_normalized, &
              rect_impact_time_normalized

    integer, parameter :: ROCK_NONE = 0  !! no rocking: eta >= 1 or the spike (beta = +inf)
    integer, parameter :: ROCK_O1 = 1    !! overturns on the rising branch, tau_c <= 1/2
    integer, parameter :: ROCK_O2 = 2    !! overturns on the decaying branch, 1/2 < tau_c <= 1
    integer, parameter :: ROCK_O3 = 3    !! overturns after the pulse, tau_c > 1
    integer, parameter :: ROCK_S1 = 4    !! stable, maximum during the pulse, tau_m <= 1
    integer, parameter :: ROCK_S2 = 5    !! stable, maximum after the pulse, tau_m > 1

    character(len=*), parameter :: region_names(0:5) = [character(len=10) :: &
        'no_rocking', 'O1', 'O2', 'O3', 'S1', 'S2']

    integer, parameter :: SHAPE_GENERAL = 0    ! finite beta /= 0
    integer, parameter :: SHAPE_TRIANGLE = 1   ! beta = 0
    integer, parameter :: SHAPE_RECTANGLE = 2  ! beta = -inf
    integer, parameter :: SHAPE_SPIKE = 3      ! beta = +inf

    ! what a boundary root finder zeroes
    integer, parameter :: WHAT_MID = 1    ! psi(1/2) - 1 (Eq. 2.16b, O1/O2)
    integer, parameter :: WHAT_END = 2    ! psi(1) - 1 (corrected Eq. 2.16a, O2/O3)
    integer, parameter :: WHAT_S1S2 = 3   ! psi'(1)/f (S1/S2)
    integer, parameter :: WHAT_WALL = 4   ! eta_w(f) - eta (Eq. 2.20)

    !> 1/((j+1)(j+2)) and 1/j for the Taylor recurrences.
    real(dp), parameter :: inv_pair(0:18) = [ &
        1.0_dp / 2.0_dp, 1.0_dp / 6.0_dp, 1.0_dp / 12.0_dp, 1.0_dp / 20.0_dp, 1.0_dp / 30.0_dp, &
        1.0_dp / 42.0_dp, 1.0_dp / 56.0_dp, 1.0_dp / 72.0_dp, 1.0_dp / 90.0_dp, &
        1.0_dp / 110.0_dp, 1.0_dp / 132.0_dp, 1.0_dp / 156.0_dp, 1.0_dp / 182.0_dp, &
        1.0_dp / 210.0_dp, 1.0_dp / 240.0_dp, 1.0_dp / 272.0_dp, 1.0_dp / 306.0_dp, &
        1.0_dp / 342.0_dp, 1.0_dp / 380.0_dp]
    real(dp), parameter :: inv_int(1:6) = [1.0_dp, 0.5_dp, 1.0_dp / 3.0_dp, 0.25_dp, 0.2_dp, &
                                           1.0_dp / 6.0_dp]
    !> Everything the first excursion needs, computed once per (f, eta, beta).
    type :: rock_state
        real(dp) :: f = 1.0_dp        ! p t_d
        real(dp) :: eta = 1.0_dp      ! alpha/alpha_g
        real(dp) :: beta = 0.0_dp     ! pulse shape
        integer :: shape = SHAPE_GENERAL
        logical :: rocks = .false.    ! eta < 1 and not the spike
        real(dp) :: tup = 0.0_dp      ! tau_up, Eq. 2.4
        real(dp) :: k = 0.0_dp        ! K = 2 beta Q/(eta (e^beta - 1))
        real(dp) :: d0 = 0.0_dp       ! 2 beta (1/2 - tau_up) = beta - ln Q
        real(dp) :: ed0 = 1.0_dp      ! e^d0
        real(dp) :: en1 = 1.0_dp      ! e^(d0 - beta) = 1/Q, the phase-2 node at tau = 1
        real(dp) :: c0 = 0.0_dp       ! 1/eta - 1 = g(1/2)
        real(dp) :: p_half = 0.0_dp   ! psi(1/2)
        real(dp) :: q_half = 0.0_dp   ! psi'(1/2)/f
        real(dp) :: p_one = 0.0_dp    ! psi(1)
        real(dp) :: q_one = 0.0_dp    ! psi'(1)/f
        real(dp) :: a = 0.0_dp        ! A = (psi(1) - 1 + psi'(1)/f)/2
        real(dp) :: b = 0.0_dp        ! B = (psi(1) - 1 - psi'(1)/f)/2
    end type rock_state

    !> psi(tau) - level, slope psi' = f dpsi: critical time (level 1), impact (level 0).
    type, extends(smooth_function) :: psi_level_fn
        type(rock_state) :: st
        real(dp) :: level = 0.0_dp
    contains
        procedure :: eval => psi_level_value
        procedure :: eval_slope => psi_level_slope
    end type psi_level_fn

    !> dpsi(tau) = psi'/f, slope f (psi + g) = f (psi - 1 + s/eta): Eq. 2.24a.
    type, extends(smooth_function) :: dpsi_fn
        type(rock_state) :: st
    contains
        procedure :: eval => dpsi_value
        procedure :: eval_slope => dpsi_slope
    end type dpsi_fn

    !> Triangle, impact during the pulse, Eq. 2.34a:
    !> sinh f(tau - eta/2) - 2 sinh f(tau - 1/2) + f (tau + eta/2 - 1) (= eta f psi/2).
    type, extends(smooth_function) :: tri_impact_fn
        real(dp) :: f = 1.0_dp, eta = 0.5_dp
    contains
        procedure :: eval => tri_impact_value
        procedure :: eval_slope => tri_impact_slope
    end type tri_impact_fn

    !> A boundary as a function of eta at fixed f, beta (WHAT_MID, WHAT_END, WHAT_S1S2).
    type, extends(scalar_function) :: eta_boundary_fn
        real(dp) :: f = 1.0_dp, beta = 0.0_dp
        integer :: what = WHAT_END
    contains
        procedure :: eval => eta_boundary_value
    end type eta_boundary_fn

    !> A boundary as a function of f at fixed eta, beta (WHAT_MID, WHAT_END, WHAT_WALL).
    type, extends(scalar_function) :: f_boundary_fn
        real(dp) :: eta = 0.5_dp, beta = 0.0_dp
        integer :: what = WHAT_WALL
    contains
        procedure :: eval => f_boundary_value
    end type f_boundary_fn

contains

    ! ------------------------------------------------------------------------------
    ! Names, uplift, time history
    ! ------------------------------------------------------------------------------

    !> 'no_rocking', 'O1', 'O2', 'O3', 'S1' or 'S2' (doc/rocking.md section 3); 'unknown' otherwise.
    pure function rocking_region_name(code) result(name)
        integer, intent(in) :: code  !! ROCK_*
        character(len=len_trim(rocking_region_name_text(code))) :: name
        name = rocking_region_name_text(code)
    end function rocking_region_name

    !> rocking_region_name(code) padded with blanks.
    pure function rocking_region_name_text(code) result(name)
        integer, intent(in) :: code
        character(len=64) :: name
        if (code >= 0 .and. code <= 5) then
            name = trim(region_names(code))
        else
            name = 'unknown'
        end if
    end function rocking_region_name_text

    !> Uplift time tau_up = ln[1 - eta (1 - e^beta)]/(2 beta) (Eq. 2.4), in [0, 1/2];
    !> limits 0 (rectangle), eta/2 (triangle), 1/2 (spike). NaN when eta >= 1 (no uplift).
    subroutine uplift_time(eta, beta, tau_up, stat, errmsg)
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: tau_up                       !! t_up/t_d, or NaN
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        tau_up = ieee_value(tau_up, ieee_quiet_nan)
        call check_eta(eta, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_beta(beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (eta < 1.0_dp) tau_up = exp_rise_time(eta, beta)
    end subroutine uplift_time

    !> Rotation psi = theta/alpha and angular velocity dpsi = (dtheta/dt)/(alpha p) of the
    !> first excursion (2.10-2.15 in the stable form of section 2): 0 before uplift (and
    !> without rocking); the linearized motion past psi = 1 for overturning blocks (it is the
    !> model's, not the real block's, once psi >= 1); NaN after the first impact.
    subroutine rocking_response(tau, f, eta, beta, psi, dpsi, stat, errmsg)
        real(dp), intent(in) :: tau                           !! t/t_d, finite
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: psi                          !! theta/alpha
        real(dp), intent(out) :: dpsi                         !! (dtheta/dt)/(alpha p) = psi'/f
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(rock_state) :: st
        psi = ieee_value(psi, ieee_quiet_nan)
        dpsi = psi
        stat = SEISPULSE_SUCCESS
        if (.not. ieee_is_finite(tau)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'tau = '//real_str(tau) &
                           //': must be a finite number (t/t_d)')
            return
        end if
        call check_common(f, eta, beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call state_init(st, f, eta, beta)
        psi = 0.0_dp
        dpsi = 0.0_dp
        if (.not. st%rocks) return
        if (.not. (tau > st%tup)) return
        call state_eval(st, tau, psi, dpsi)
        ! psi < 0 only after the impact: once psi < 0 with psi' < 0 and g < 0 (after
        ! tau_m >= 1 - tau_up), psi'' = f^2 (psi + g) < 0 keeps it there (section 3)
        if (psi < 0.0_dp .or. (tau > 1.0_dp .and. st%p_one < 0.0_dp)) then
            psi = ieee_value(psi, ieee_quiet_nan)
            dpsi = psi
        end if
    end subroutine rocking_response

    ! ------------------------------------------------------------------------------
    ! Boundaries of the region map (doc/rocking.md section 3)
    ! ------------------------------------------------------------------------------

    !> The stability wall eta_w(f, beta) (Eq. 2.20; boundary O3/S: overturn iff eta < eta_w),
    !> in a form with the removable singularities at f = 2|beta| and beta = 0 removed
    !> (section 3); limits 1 - e^-f (rectangle, Eq. 2.21), 2 - (2/f) ln(2 e^(f/2) - 1)
    !> (triangle, Eq. 2.22), 0 for the spike.
    subroutine stability_wall(f, beta, eta_w, stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: eta_w                        !! wall, in (0, 1)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        eta_w = ieee_value(eta_w, ieee_quiet_nan)
        call check_f(f, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_beta(beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        eta_w = wall_eta(f, beta)
    end subroutine stability_wall

    !> Pulse duration f_w on the stability wall for a given eta: eta_w(f_w, beta) = eta
    !> (eta_w increases in f, section 3). Rectangle: f = ln[1/(1 - eta)]; otherwise a root.
    !> +inf when eta >= 1 or for the spike (no pulse duration overturns).
    subroutine stability_wall_inverse(eta, beta, f_w, stat, errmsg)
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: f_w                          !! p t_d on the wall
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        f_w = ieee_value(f_w, ieee_quiet_nan)
        call check_eta(eta, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_beta(beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. (eta < 1.0_dp) .or. beta > huge(beta)) then
            f_w = ieee_value(f_w, ieee_positive_inf)
        else if (beta < -huge(beta)) then
            f_w = -log1p(-eta)        ! Eq. 2.21 inverted
        else
            call f_boundary(eta, beta, WHAT_WALL, f_w, stat, errmsg)
        end if
    end subroutine stability_wall_inverse

    !> Overturning boundaries of section 3: at_end, theta = alpha at the end of the
    !> pulse (corrected Eq. 2.16a, tau_c = 1, boundary O2/O3); otherwise at mid-pulse
    !> (Eq. 2.16b, tau_c = 1/2, boundary O1/O2). Rectangle: Eq. 2.17a/b; triangle: corrected
    !> Eq. 2.18a / Eq. 2.18b; other shapes: the root in eta of psi(tau_c) = 1 (decreasing in
    !> eta). 0 for the spike.
    subroutine overturn_boundary(f, beta, at_end, eta_b, stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        logical, intent(in) :: at_end                         !! tau_c = 1 (else tau_c = 1/2)
        real(dp), intent(out) :: eta_b                        !! boundary eta in (0, 1)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: u, w
        eta_b = ieee_value(eta_b, ieee_quiet_nan)
        call check_f(f, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_beta(beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (beta > huge(beta)) then
            eta_b = 0.0_dp
        else if (beta < -huge(beta)) then
            ! Eq. 2.17a/b: eta = 1 - 1/cosh(x) = 2 sinh^2(x/2)/cosh(x), x = f or f/2
            u = f
            if (.not. at_end) u = 0.5_dp * f
            if (u < 1.0_dp) then
                eta_b = 2.0_dp * sinh(0.5_dp * u)**2 / cosh(u)
            else
                eta_b = 1.0_dp - 1.0_dp / cosh(u)
            end if
        else if (.not. abs(beta) > 0.0_dp) then
            u = 0.5_dp * f
            if (at_end) then
                ! corrected Eq. 2.18a: eta = 2 - (2/f) asinh(w), w = 2 sinh(f/2), written
                ! [(w - asinh w) - 2 (sinh u - u)]/u without cancellation (u = f/2)
                w = 2.0_dp * sinh(u)
                eta_b = (x_minus_asinh(w) - 2.0_dp * sinh_minus_x(u)) / u
            else
                ! Eq. 2.18b: eta = 1 - (2/f) asinh(f/2) = (u - asinh u)/u
                eta_b = x_minus_asinh(u) / u
            end if
        else if (at_end) then
            call eta_boundary(f, beta, WHAT_END, eta_b, stat, errmsg)
        else
            call eta_boundary(f, beta, WHAT_MID, eta_b, stat, errmsg)
        end if
    end subroutine overturn_boundary

    !> Pulse duration f_b on an overturning boundary of section 3 for a given eta
    !> (psi(tau_c; f) = 1 with tau_c = 1 when at_end, else 1/2). Rectangle: inverse of
    !> Eq. 2.17a/b in closed form; otherwise a root in f. +inf when eta >= 1 or for the spike.
    subroutine overturn_boundary_inverse(eta, beta, at_end, f_b, stat, errmsg)
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        logical, intent(in) :: at_end                         !! tau_c = 1 (else tau_c = 1/2)
        real(dp), intent(out) :: f_b                          !! p t_d on the boundary
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        f_b = ieee_value(f_b, ieee_quiet_nan)
        call check_eta(eta, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_beta(beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. (eta < 1.0_dp) .or. beta > huge(beta)) then
            f_b = ieee_value(f_b, ieee_positive_inf)
        else if (beta < -huge(beta)) then
            ! cosh(x) = 1/(1 - eta): x = 2 asinh(sqrt(eta/(2 (1 - eta)))), x = f or f/2
            f_b = 2.0_dp * asinh(sqrt(eta / (2.0_dp * (1.0_dp - eta))))
            if (.not. at_end) f_b = 2.0_dp * f_b
        else if (at_end) then
            call f_boundary(eta, beta, WHAT_END, f_b, stat, errmsg)
        else
            call f_boundary(eta, beta, WHAT_MID, f_b, stat, errmsg)
        end if
    end subroutine overturn_boundary_inverse

    !> The S1/S2 boundary: eta in (eta_w, 1) with psi'(1) = 0, i.e. tau_m = 1 (section 3,
    !> "(2.10b) / (2.24a) at tau = 1"). Triangle: cosh f(1 - eta/2) - 2 cosh(f/2) + 1 = 0,
    !> eta = 2 - (4/f) asinh(sqrt(2) sinh(f/4)); other shapes: a root in eta. NaN for the
    !> rectangle (no S1: tau_m > 1 always) and the spike (no rocking).
    subroutine s1_s2_boundary(f, beta, eta_b, stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: eta_b                        !! boundary eta, or NaN
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: u, x
        eta_b = ieee_value(eta_b, ieee_quiet_nan)
        call check_f(f, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_beta(beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (beta > huge(beta) .or. beta < -huge(beta)) return
        if (.not. abs(beta) > 0.0_dp) then
            ! cosh(f (1 - eta/2)) = 2 cosh(f/2) - 1 = 1 + 4 sinh^2(f/4)
            u = 0.25_dp * f
            if (u < 20.0_dp) then
                x = asinh(sqrt(2.0_dp) * sinh(u))
            else
                x = u + 0.5_dp * log(2.0_dp)   ! asinh(sqrt 2 sinh u), e^(-2u) < 1e-17
            end if
            eta_b = 2.0_dp - x / u
        else
            call eta_boundary(f, beta, WHAT_S1S2, eta_b, stat, errmsg)
        end if
    end subroutine s1_s2_boundary

    ! ------------------------------------------------------------------------------
    ! Region and response quantities (doc/rocking.md sections 3, 4, 5)
    ! ------------------------------------------------------------------------------

    !> Region of the map (doc/rocking.md section 3): psi(1/2) >= 1 -> O1; psi(1) >= 1 -> O2;
    !> A > 0 -> O3; psi'(1) <= 0 -> S1; else S2; ROCK_NONE when eta >= 1 or beta = +inf.
    subroutine rocking_classify(f, eta, beta, region, stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        integer, intent(out) :: region                        !! ROCK_*
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(rock_state) :: st
        region = ROCK_NONE
        call check_common(f, eta, beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call state_init(st, f, eta, beta)
        region = region_of(st)
    end subroutine rocking_classify

    !> Critical time tau_c (theta = alpha) in the O regions: the root of psi = 1 on
    !> [tau_up, 1/2] (O1) or [1/2, 1] (O2) (rectangle: cosh(f tau_c) = 1/(1 - eta)), and
    !> 1 + ln(-B/A)/(2f) in O3 (section 3). NaN otherwise.
    subroutine critical_time(f, eta, beta, tau_c, stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: tau_c                        !! t_c/t_d, or NaN
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(rock_state) :: st
        tau_c = ieee_value(tau_c, ieee_quiet_nan)
        call check_common(f, eta, beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call state_init(st, f, eta, beta)
        call get_tau_c(st, region_of(st), tau_c, stat, errmsg)
    end subroutine critical_time

    !> Time of the maximum rotation tau_m (section 4): S1, the root of Eq. 2.24a on
    !> [1 - tau_up, 1]; S2, 1 + ln(B/A)/(2f) (= Eq. 2.24b); rectangle Eq. 2.25; triangle
    !> Eq. 2.26a where valid (<= 1, positive denominator), else Eq. 2.26b. NaN for the O
    !> regions and without rocking.
    subroutine time_of_max(f, eta, beta, tau_m, stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: tau_m                        !! t_m/t_d, or NaN
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(rock_state) :: st
        real(dp) :: psi_m
        tau_m = ieee_value(tau_m, ieee_quiet_nan)
        call check_common(f, eta, beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call state_init(st, f, eta, beta)
        call get_tau_m(st, region_of(st), tau_m, psi_m, stat, errmsg)
    end subroutine time_of_max

    !> Maximum rotation theta_max/alpha (section 4): 0 without rocking, +inf in the O regions
    !> (overturning), 1 - 2 sqrt(AB) in S2 (rectangle: Eq. 2.29), psi(tau_m) in S1.
    subroutine max_rotation(f, eta, beta, psi_max, stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: psi_max                      !! theta_max/alpha
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: region
        call rocking_extremes(f, eta, beta, region, psi_max, stat, errmsg)
    end subroutine max_rotation

    !> Region and theta_max/alpha from one evaluation of the shared state: the cheap path
    !> for classifying many cases (`rocking_summary` adds the times).
    subroutine rocking_extremes(f, eta, beta, region, psi_max, stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        integer, intent(out) :: region                        !! ROCK_*
        real(dp), intent(out) :: psi_max                      !! theta_max/alpha
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(rock_state) :: st
        real(dp) :: tau_m, psi_m
        region = ROCK_NONE
        psi_max = ieee_value(psi_max, ieee_quiet_nan)
        call check_common(f, eta, beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call state_init(st, f, eta, beta)
        region = region_of(st)
        tau_m = ieee_value(tau_m, ieee_quiet_nan)
        psi_m = tau_m
        ! S1 needs its maximum inside the pulse; every other region has a closed form
        if (region == ROCK_S1) call get_tau_m(st, region, tau_m, psi_m, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        psi_max = psi_max_of(st, region, tau_m, psi_m)
    end subroutine rocking_extremes

    !> Time of the first impact tau_i (section 5): during the pulse (psi(1) <= 0) the root
    !> of Eq. 2.32a on [tau_m, 1] (triangle: Eq. 2.34a); after it the larger root of the
    !> corrected Eq. 2.32b-e, 1 + ln(z)/f with z = (1 + sqrt(1 - 4AB))/(-2A); rectangle
    !> Eq. 2.33; triangle corrected Eq. 2.34b. NaN unless the region is S1 or S2.
    subroutine impact_time(f, eta, beta, tau_i, stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: tau_i                        !! t_i/t_d, or NaN
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(rock_state) :: st
        real(dp) :: tau_m, psi_m
        integer :: region
        tau_i = ieee_value(tau_i, ieee_quiet_nan)
        call check_common(f, eta, beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call state_init(st, f, eta, beta)
        region = region_of(st)
        tau_m = ieee_value(tau_m, ieee_quiet_nan)
        if (region == ROCK_S1 .and. st%p_one <= 0.0_dp) &
            call get_tau_m(st, region, tau_m, psi_m, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call get_tau_i(st, region, tau_m, psi_m, tau_i, stat, errmsg)
    end subroutine impact_time

    !> Everything at once from one evaluation of the state psi(1/2), psi(1), psi'(1), A, B:
    !> region, uplift, critical time, time of the maximum, maximum rotation and impact time
    !> (each NaN where it does not apply, as in the single routines). The fast path for
    !> arrays of cases.
    subroutine rocking_summary(f, eta, beta, region, tau_up, tau_c, tau_m, psi_max, tau_i, &
                               stat, errmsg)
        real(dp), intent(in) :: f                             !! p t_d > 0
        real(dp), intent(in) :: eta                           !! alpha/alpha_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        integer, intent(out) :: region                        !! ROCK_*
        real(dp), intent(out) :: tau_up                       !! uplift t_up/t_d (NaN: eta >= 1)
        real(dp), intent(out) :: tau_c                        !! critical time (O regions)
        real(dp), intent(out) :: tau_m                        !! time of the maximum (S)
        real(dp), intent(out) :: psi_max                      !! theta_max/alpha
        real(dp), intent(out) :: tau_i                        !! first impact (S)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(rock_state) :: st
        real(dp) :: nan, psi_m
        nan = ieee_value(nan, ieee_quiet_nan)
        psi_m = nan
        region = ROCK_NONE
        tau_up = nan
        tau_c = nan
        tau_m = nan
        psi_max = nan
        tau_i = nan
        call check_common(f, eta, beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call state_init(st, f, eta, beta)
        region = region_of(st)
        if (st%rocks) then
            tau_up = st%tup
        else if (eta < 1.0_dp) then
            tau_up = 0.5_dp                   ! the spike
        end if
        select case (region)
        case (ROCK_O1, ROCK_O2, ROCK_O3)
            call get_tau_c(st, region, tau_c, stat, errmsg)
        case (ROCK_S1, ROCK_S2)
            call get_tau_m(st, region, tau_m, psi_m, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            call get_tau_i(st, region, tau_m, psi_m, tau_i, stat, errmsg)
        end select
        psi_max = psi_max_of(st, region, tau_m, psi_m)
    end subroutine rocking_summary

    ! ------------------------------------------------------------------------------
    ! Normalized rectangle forms (sections 4, 5)
    ! ------------------------------------------------------------------------------

    !> eta tau_m for the rectangle in the normalized variables fbar = f/ln[1/(1 - eta)]
    !> (Eq. 2.27): eta ln[((1-eta)^-fbar - 1 + eta)/((1-eta)^fbar - 1 + eta)]/(2 fbar L),
    !> L = ln[1/(1 - eta)]. Unchecked: 0 < eta < 1, 0 < fbar < 1 (fbar >= 1 overturns).
    elemental function rect_time_of_max_normalized(fbar, eta) result(eta_tau_m)
        real(dp), intent(in) :: fbar  !! f/ln[1/(1 - eta)] in (0, 1)
        real(dp), intent(in) :: eta   !! alpha/alpha_g in (0, 1)
        real(dp) :: eta_tau_m
        real(dp) :: el
        el = -log1p(-eta)
        eta_tau_m = eta * rect_tau_m(fbar * el, eta, el)
    end function rect_time_of_max_normalized

    !> theta_max/alpha for the rectangle in the normalized variables (corrected Eq. 2.30:
    !> f tau_m = (1/2) ln[.], the 1/2 the printed cosh arguments lack): with f = fbar L,
    !> (1/eta)[eta + (1 - eta) cosh(f tau_m) - cosh(f tau_m - f)], evaluated as
    !> 4 (1 - eta) sinh^2(f/2)/(eta (eta + X)), X = sqrt(expm1((fbar-1)L) expm1(-(fbar+1)L)).
    !> Unchecked: 0 < eta < 1, 0 < fbar < 1.
    elemental function rect_max_rotation_normalized(fbar, eta) result(psi_max)
        real(dp), intent(in) :: fbar  !! f/ln[1/(1 - eta)] in (0, 1)
        real(dp), intent(in) :: eta   !! alpha/alpha_g in (0, 1)
        real(dp) :: psi_max
        real(dp) :: el
        el = -log1p(-eta)
        psi_max = rect_psi_max(fbar * el, eta, el)
    end function rect_max_rotation_normalized

    !> eta tau_i/(1 + sqrt(1 - eta)) for the rectangle in the normalized variables
    !> (corrected Eq. 2.35: prefactor 1/fbar, log argument
    !> [eta + sqrt(1-eta) ((1-eta)^(-fbar/2) - (1-eta)^(fbar/2))]/[(1-eta)^fbar - 1 + eta]).
    !> Unchecked: 0 < eta < 1, 0 < fbar < 1.
    elemental function rect_impact_time_normalized(fbar, eta) result(tau_norm)
        real(dp), intent(in) :: fbar  !! f/ln[1/(1 - eta)] in (0, 1)
        real(dp), intent(in) :: eta   !! alpha/alpha_g in (0, 1)
        real(dp) :: tau_norm
        real(dp) :: el
        el = -log1p(-eta)
        tau_norm = eta * rect_tau_i(fbar * el, eta, el) / (1.0_dp + sqrt(1.0_dp - eta))
    end function rect_impact_time_normalized

    ! ------------------------------------------------------------------------------
    ! Rectangle closed forms in stable form (L = ln[1/(1 - eta)], (1 - eta) e^L = 1)
    ! ------------------------------------------------------------------------------

    !> Eq. 2.25: tau_m = ln[(e^f - 1 + eta)/(e^-f - 1 + eta)]/(2f)
    !> = ln[1 + 2 sinh f/((1 - eta) expm1(L - f))]/(2f).
    elemental function rect_tau_m(f, eta, el) result(tau_m)
        real(dp), intent(in) :: f, eta, el
        real(dp) :: tau_m
        tau_m = log1p(2.0_dp * sinh(f) / ((1.0_dp - eta) * expm1(el - f))) / (2.0_dp * f)
    end function rect_tau_m

    !> Eq. 2.29 (= corrected 2.30): 1 - 2 sqrt(AB) written without cancellation,
    !> 4 (1 - eta) sinh^2(f/2)/(eta (eta + X)), X^2 = (1 - (1-eta) e^f)(1 - (1-eta) e^-f).
    elemental function rect_psi_max(f, eta, el) result(psi_max)
        real(dp), intent(in) :: f, eta, el
        real(dp) :: psi_max
        real(dp) :: x
        x = sqrt(expm1(f - el) * expm1(-f - el))
        psi_max = 4.0_dp * (1.0_dp - eta) * sinh(0.5_dp * f)**2 / (eta * (eta + x))
    end function rect_psi_max

    !> Eq. 2.33: e^(f tau_i) = [eta + 2 sqrt(1 - eta) sinh(f/2)]/[e^-f - (1 - eta)], the
    !> denominator (1 - eta) expm1(L - f), the ratio 1 + (2 sqrt(1-eta) sinh(f/2) - expm1(-f))
    !> /((1 - eta) expm1(L - f)).
    elemental function rect_tau_i(f, eta, el) result(tau_i)
        real(dp), intent(in) :: f, eta, el
        real(dp) :: tau_i
        tau_i = log1p((2.0_dp * sqrt(1.0_dp - eta) * sinh(0.5_dp * f) - expm1(-f)) &
                      / ((1.0_dp - eta) * expm1(el - f))) / f
    end function rect_tau_i

    ! ------------------------------------------------------------------------------
    ! The state of the first excursion (section 2)
    ! ------------------------------------------------------------------------------

    !> tau_up (Eq. 2.4), d0 = 2 beta (1/2 - tau_up) = beta - ln Q and
    !> K = 2 beta Q/(eta (e^beta - 1)) = 2 Q/(eta phi_1(beta)) for finite beta /= 0,
    !> 0 < eta < 1, each without cancellation and from one expm1(beta):
    !> Q = 1 + eta expm1(beta) = (1 - eta) + eta e^beta, Q e^-beta = 1 + (1 - eta) expm1(-beta),
    !> expm1(-beta) = -expm1(beta)/(1 + expm1(beta)). tau_up equals exp_rise_time(eta, beta)
    !> (the public uplift_time); it is formed here from the same logarithm as d0, which
    !> needs its absolute accuracy even for huge beta.
    pure subroutine uplift_consts(eta, beta, tup, d0, k)
        real(dp), intent(in) :: eta, beta
        real(dp), intent(out) :: tup, d0, k
        real(dp) :: e, x, lnq, q
        if (abs(beta) < 1.0_dp) then
            ! ln(1 + x)/(2 beta) = (eta/2) phi_1(beta) ln(1 + x)/x, x = eta expm1(beta)
            e = expm1(beta)
            x = eta * e
            tup = 0.5_dp * eta * (e / beta) * log1p_over_x(x)
            d0 = beta * (1.0_dp - 2.0_dp * tup)
            k = 2.0_dp * (1.0_dp + x) / (eta * (e / beta))
        else if (beta > 0.0_dp) then
            if (beta < 700.0_dp) then
                ! (d0 = beta - ln Q has the absolute accuracy its uses need: it is a node)
                e = expm1(beta)
                lnq = log1p(eta * e)
                tup = lnq / (2.0_dp * beta)
                d0 = beta - lnq
                k = 2.0_dp * beta + 2.0_dp * beta / (eta * e)
            else
                d0 = -log1p((1.0_dp - eta) * expm1(-beta))
                tup = 0.5_dp - d0 / (2.0_dp * beta)
                k = 2.0_dp * beta + 2.0_dp * beta * exp(-beta) / eta
            end if
        else
            e = expm1(beta)
            q = (1.0_dp - eta) + eta * (1.0_dp + e)
            if (q < 0.5_dp) then
                lnq = log(q)
            else
                lnq = log1p(eta * e)
            end if
            tup = lnq / (2.0_dp * beta)
            d0 = beta - lnq
            k = 2.0_dp * q * (beta / e) / eta
        end if
    end subroutine uplift_consts

    !> The state at tau = 1/2 and 1 and the after-pulse coefficients A, B.
    pure subroutine state_init(st, f, eta, beta)
        type(rock_state), intent(out) :: st
        real(dp), intent(in) :: f, eta, beta
        real(dp) :: h, n0
        st%f = f
        st%eta = eta
        st%beta = beta
        if (beta < -huge(beta)) then
            st%shape = SHAPE_RECTANGLE
        else if (beta > huge(beta)) then
            st%shape = SHAPE_SPIKE
        else if (.not. abs(beta) > 0.0_dp) then
            st%shape = SHAPE_TRIANGLE
        else
            st%shape = SHAPE_GENERAL
        end if
        st%rocks = eta < 1.0_dp .and. st%shape /= SHAPE_SPIKE
        if (.not. st%rocks) return
        st%c0 = (1.0_dp - eta) / eta
        select case (st%shape)
        case (SHAPE_RECTANGLE)
            st%tup = 0.0_dp
            st%k = 0.0_dp
            st%d0 = 0.0_dp
        case (SHAPE_TRIANGLE)
            st%tup = 0.5_dp * eta
            st%k = 2.0_dp / eta
            st%d0 = 0.0_dp
        case default
            call uplift_consts(eta, beta, st%tup, st%d0, st%k)
            st%ed0 = exp(st%d0)
        end select
        if (st%shape == SHAPE_GENERAL) then
            ! tau = 1/2: h = 1/2 - tau_up = d0/(2 beta), 2 beta h = d0;
            ! tau = 1: h = 1/2, n0 = d0 - beta = -ln Q
            if (beta > 0.0_dp) then
                h = st%d0 / (2.0_dp * beta)
            else
                h = 0.5_dp - st%tup
            end if
            call phase1(st, h, st%d0, st%ed0, f * h, st%p_half, st%q_half)
            n0 = st%d0 - beta
            st%en1 = exp(n0)
            call phase2(st, 0.5_dp, n0, st%en1, st%p_one, st%q_one)
        else
            call state_eval(st, 0.5_dp, st%p_half, st%q_half)
            call state_eval(st, 1.0_dp, st%p_one, st%q_one)
        end if
        st%a = 0.5_dp * ((st%p_one - 1.0_dp) + st%q_one)
        st%b = 0.5_dp * ((st%p_one - 1.0_dp) - st%q_one)
    end subroutine state_init

    !> psi and q = psi'/f at tau >= tau_up of the one-sided motion (theta > 0 branch);
    !> phases 1 and 2 need st%p_half, st%q_half only for tau > 1/2, phase 3 needs A, B.
    pure subroutine state_eval(st, tau, psi, q)
        type(rock_state), intent(in) :: st
        real(dp), intent(in) :: tau
        real(dp), intent(out) :: psi, q
        real(dp) :: h, x, y, c, y1, y2, t, e
        if (tau <= 1.0_dp) then
            select case (st%shape)
            case (SHAPE_RECTANGLE)
                ! Eq. 2.12, 2.13 (cosh x - 1 = 2 sinh^2(x/2))
                y = st%f * tau
                psi = 2.0_dp * st%c0 * sinh(0.5_dp * y)**2
                q = st%c0 * sinh(y)
            case (SHAPE_TRIANGLE)
                ! Eq. 2.14, 2.15 as (2/(eta f))[(sinh y1 - y1) - 2 (sinh y2 - y2) H(tau-1/2)]
                c = 2.0_dp / (st%eta * st%f)
                y1 = st%f * (tau - st%tup)
                psi = c * sinh_minus_x(y1)
                q = 2.0_dp * c * sinh(0.5_dp * y1)**2
                if (tau > 0.5_dp) then
                    y2 = st%f * (tau - 0.5_dp)
                    psi = psi - 2.0_dp * c * sinh_minus_x(y2)
                    q = q - 4.0_dp * c * sinh(0.5_dp * y2)**2
                end if
            case default
                if (tau <= 0.5_dp) then
                    h = tau - st%tup
                    x = 2.0_dp * st%beta * h
                    call phase1(st, h, x, exp(x), st%f * h, psi, q)
                else
                    h = tau - 0.5_dp
                    x = st%d0 - 2.0_dp * st%beta * h
                    call phase2(st, h, x, exp(x), psi, q)
                end if
            end select
        else
            ! phase 3: psi - 1 = A e^t + B e^-t, t = f (tau - 1)
            t = st%f * (tau - 1.0_dp)
            e = exp(t)
            psi = 1.0_dp + st%b / e
            q = -st%b / e
            if (abs(st%a) > 0.0_dp) then
                psi = psi + st%a * e
                q = q + st%a * e
            end if
        end if
    end subroutine state_eval

    !> Phase 1 (tau_up <= tau <= 1/2, h = tau - tau_up), section 2 in divided differences:
    !> psi = K f^2 h^3 exp[x, 0, y, -y], psi'/f = K f h^2 (exp[x, 0, y] + exp[x, 0, -y])/2
    !> with x = 2 beta h (ex = e^x) and y = f h.
    pure subroutine phase1(st, h, x, ex, y, psi, q)
        type(rock_state), intent(in) :: st
        real(dp), intent(in) :: h, x, ex, y
        real(dp), intent(out) :: psi, q
        real(dp) :: ey, dplus, dminus, d3
        ey = exp(y)
        call exp_dd_pack(x, ex, 0.0_dp, 1.0_dp, y, ey, dplus, dminus, d3)
        psi = st%k * y * y * h * d3
        q = 0.5_dp * st%k * y * h * (dplus + dminus)
    end subroutine phase1

    !> Phase 2 (1/2 <= tau <= 1, h = tau - 1/2): the free response from tau = 1/2 plus the
    !> Duhamel integral of g = c0 + K (expm1(n) - expm1(d0))/(2 beta), n = d0 - 2 beta h
    !> (en0 = e^n0), the nodes shifted by d0 absorbing e^(2 beta (1/2 - tau_up)):
    !> psi = psi(1/2) cosh y + psi'(1/2)/f sinh y + c0 (cosh y - 1)
    !>       - K y^2 h exp[n0, d0, d0 + y, d0 - y], y = f h, and its derivative.
    pure subroutine phase2(st, h, n0, en0, psi, q)
        type(rock_state), intent(in) :: st
        real(dp), intent(in) :: h, n0, en0
        real(dp), intent(out) :: psi, q
        real(dp) :: y, y2, ey, sh, ch, cm1, dplus, dminus, d3
        integer :: j
        y = st%f * h
        if (y < 1.0_dp) then
            ! Taylor polynomials of sinh y and cosh y - 1 (to y^19/19!, y^20/20!)
            y2 = y * y
            sh = 1.0_dp
            cm1 = 1.0_dp
            do j = 9, 1, -1
                sh = 1.0_dp + sh * y2 * inv_pair(2 * j - 1)
                cm1 = 1.0_dp + cm1 * y2 * inv_pair(2 * j)
            end do
            sh = y * sh
            cm1 = 0.5_dp * y2 * cm1
            ey = 1.0_dp + sh + cm1
        else
            ey = exp(y)
            sh = 0.5_dp * (ey - 1.0_dp / ey)
            cm1 = 0.5_dp * (ey + 1.0_dp / ey) - 1.0_dp
        end if
        ch = 1.0_dp + cm1
        call exp_dd_pack(n0, en0, st%d0, st%ed0, y, ey, dplus, dminus, d3)
        psi = st%p_half * ch + st%q_half * sh + st%c0 * cm1 - st%k * y * y * h * d3
        q = st%p_half * sh + st%q_half * ch + st%c0 * sh - 0.5_dp * st%k * y * h * (dplus + dminus)
    end subroutine phase2

    !> g = s(tau)/eta - 1 for tau >= tau_up (psi'' = f^2 (psi + g)).
    pure function state_forcing(st, tau) result(g)
        type(rock_state), intent(in) :: st
        real(dp), intent(in) :: tau
        real(dp) :: g, h
        if (tau > 1.0_dp) then
            g = -1.0_dp
        else if (st%shape == SHAPE_RECTANGLE) then
            g = st%c0
        else if (tau <= 0.5_dp) then
            h = tau - st%tup
            g = st%k * h * phi1(2.0_dp * st%beta * h)
        else
            h = tau - (1.0_dp - st%tup)
            g = -st%k * h * phi1(-2.0_dp * st%beta * h)
        end if
    end function state_forcing

    !> The region from the state (doc/rocking.md section 3).
    pure function region_of(st) result(region)
        type(rock_state), intent(in) :: st
        integer :: region
        if (.not. st%rocks) then
            region = ROCK_NONE
        else if (st%p_half >= 1.0_dp) then
            region = ROCK_O1
        else if (st%p_one >= 1.0_dp) then
            region = ROCK_O2
        else if (st%a > 0.0_dp) then
            region = ROCK_O3
        else if (st%q_one <= 0.0_dp) then
            region = ROCK_S1
        else
            region = ROCK_S2
        end if
    end function region_of

    !> tau_c for the O regions (section 3), NaN otherwise.
    subroutine get_tau_c(st, region, tau_c, stat, errmsg)
        type(rock_state), intent(in) :: st
        integer, intent(in) :: region
        real(dp), intent(out) :: tau_c
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: psi
        stat = SEISPULSE_SUCCESS
        tau_c = ieee_value(tau_c, ieee_quiet_nan)
        select case (region)
        case (ROCK_O1, ROCK_O2)
            if (st%shape == SHAPE_RECTANGLE) then
                ! Eq. 2.12: cosh(f tau_c) = 1/(1 - eta)
                tau_c = 2.0_dp * asinh(sqrt(st%eta / (2.0_dp * (1.0_dp - st%eta)))) / st%f
            else
                ! psi increases through 1 (psi' > 0 until 1 - tau_up, and beyond once psi
                ! >= 1, section 3): one root in the phase
                if (region == ROCK_O1) then
                    call phase_root(st, 1, 1, 1.0_dp, st%tup, [0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], &
                                    0.5_dp, [st%p_half, st%q_half, st%d0, st%ed0], tau_c, psi, &
                                    stat, errmsg)
                else
                    call phase_root(st, 2, 1, 1.0_dp, 0.5_dp, &
                                    [st%p_half, st%q_half, st%d0, st%ed0], 1.0_dp, &
                                    [st%p_one, st%q_one, st%d0 - st%beta, st%en1], tau_c, psi, &
                                    stat, errmsg)
                end if
            end if
        case (ROCK_O3)
            tau_c = 1.0_dp + log(-st%b / st%a) / (2.0_dp * st%f)
        end select
    end subroutine get_tau_c

    !> tau_m for the S regions (section 4), NaN otherwise.
    subroutine get_tau_m(st, region, tau_m, psi_m, stat, errmsg)
        type(rock_state), intent(in) :: st
        integer, intent(in) :: region
        real(dp), intent(out) :: tau_m
        real(dp), intent(out) :: psi_m       ! psi(tau_m) in S1 (the root finder has it)
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: f, eta, num, den, a, b, lo, psi, q, e, ee
        stat = SEISPULSE_SUCCESS
        tau_m = ieee_value(tau_m, ieee_quiet_nan)
        psi_m = tau_m
        if (region /= ROCK_S1 .and. region /= ROCK_S2) return
        f = st%f
        eta = st%eta
        select case (st%shape)
        case (SHAPE_RECTANGLE)
            tau_m = rect_tau_m(f, eta, -log1p(-eta))          ! Eq. 2.25
        case (SHAPE_TRIANGLE)
            ! Eq. 2.26a, the "+" root (sqrt(cosh x - 1) = sqrt 2 sinh(x/2)), if valid
            num = 1.0_dp + 2.0_dp * sqrt(2.0_dp) * sinh(0.25_dp * f * (1.0_dp - eta))
            den = 2.0_dp * exp(-0.5_dp * f) - exp(-0.5_dp * f * eta)
            tau_m = 2.0_dp                    ! invalid unless 2.26a applies
            if (den > 0.0_dp) tau_m = log(num / den) / f
            if (tau_m > 1.0_dp) then
                ! Eq. 2.26b: ln(b/(-a))/(2f), b = e^f - 2 e^(f/2) + e^(f eta/2),
                ! a = e^-f - 2 e^(-f/2) + e^(-f eta/2), in expm1 form
                b = expm1(0.5_dp * f)**2 + expm1(0.5_dp * f * eta)
                a = expm1(-0.5_dp * f)**2 + expm1(-0.5_dp * f * eta)
                tau_m = log(-b / a) / (2.0_dp * f)
            end if
        case default
            if (region == ROCK_S1) then
                ! Eq. 2.24a on [1 - tau_up, 1]: psi' > 0 at the left end (Eq. 2.23), <= 0 at 1
                ! (S1); searching from tau_up would meet round-off roots (section 4)
                lo = 1.0_dp - st%tup
                call eval_node(st, 2, lo, psi, q, e, ee)
                if (q > 0.0_dp) then
                    call phase_root(st, 2, 2, 0.0_dp, lo, [psi, q, e, ee], 1.0_dp, &
                                    [st%p_one, st%q_one, st%d0 - st%beta, st%en1], tau_m, &
                                    psi_m, stat, errmsg)
                else
                    tau_m = lo                        ! a motion below round-off
                    psi_m = psi
                end if
            else
                tau_m = 1.0_dp + log(st%b / st%a) / (2.0_dp * f)   ! Eq. 2.24b
            end if
        end select
    end subroutine get_tau_m

    !> theta_max/alpha (section 4) given tau_m and psi(tau_m) if known (S1 only; NaN: not).
    pure function psi_max_of(st, region, tau_m, psi_m) result(psi_max)
        type(rock_state), intent(in) :: st
        integer, intent(in) :: region
        real(dp), intent(in) :: tau_m, psi_m
        real(dp) :: psi_max, q
        select case (region)
        case (ROCK_NONE)
            psi_max = 0.0_dp
        case (ROCK_O1, ROCK_O2, ROCK_O3)
            psi_max = ieee_value(psi_max, ieee_positive_inf)
        case (ROCK_S1)
            if (ieee_is_nan(psi_m)) then
                call state_eval(st, tau_m, psi_max, q)
            else
                psi_max = psi_m
            end if
        case default
            if (st%shape == SHAPE_RECTANGLE) then
                psi_max = rect_psi_max(st%f, st%eta, -log1p(-st%eta))   ! Eq. 2.29
            else
                ! 1 - 2 sqrt(AB) = (1 - 4AB)/(1 + 2 sqrt(AB)), 1 - 4AB = psi1 (2 - psi1)
                ! + q1^2: positive terms (0 < psi1 < 1 in S2)
                psi_max = (st%p_one * (2.0_dp - st%p_one) + st%q_one**2) &
                          / (1.0_dp + 2.0_dp * sqrt(st%a * st%b))
            end if
        end select
    end function psi_max_of

    !> tau_i for the S regions (section 5), NaN otherwise; tau_m needed when psi(1) <= 0.
    subroutine get_tau_i(st, region, tau_m, psi_m, tau_i, stat, errmsg)
        type(rock_state), intent(in) :: st
        integer, intent(in) :: region
        real(dp), intent(in) :: tau_m
        real(dp), intent(in) :: psi_m         ! psi(tau_m), or NaN
        real(dp), intent(out) :: tau_i
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(tri_impact_fn) :: tri
        real(dp) :: psi, q, f, eta, a, b, hfe, z, e, ee
        stat = SEISPULSE_SUCCESS
        tau_i = ieee_value(tau_i, ieee_quiet_nan)
        if (region /= ROCK_S1 .and. region /= ROCK_S2) return
        f = st%f
        eta = st%eta
        if (st%p_one <= 0.0_dp) then
            ! impact during the pulse: psi(tau_m) > 0 >= psi(1), psi falls on [tau_m, 1]
            if (st%shape == SHAPE_TRIANGLE) then
                tri%f = f
                tri%eta = eta
                call tri%eval_slope(tau_m, psi, q)
                call tri%eval_slope(1.0_dp, a, b)
                call solve_hermite(tri, tau_m, psi, q, 1.0_dp, a, b, tau_i, stat, errmsg) ! 2.34a
            else
                if (ieee_is_nan(psi_m)) then
                    call eval_node(st, 2, tau_m, psi, q, e, ee)
                else
                    ! psi'(tau_m) = 0: only the node is new
                    psi = psi_m
                    q = 0.0_dp
                    e = st%d0 - 2.0_dp * st%beta * (tau_m - 0.5_dp)
                    ee = exp(e)
                end if
                call phase_root(st, 2, 1, 0.0_dp, tau_m, [psi, q, e, ee], 1.0_dp, &
                                [st%p_one, st%q_one, st%d0 - st%beta, st%en1], tau_i, q, stat, &
                                errmsg)                                       ! Eq. 2.32a
            end if
            return
        end if
        select case (st%shape)
        case (SHAPE_RECTANGLE)
            tau_i = rect_tau_i(f, eta, -log1p(-eta))          ! Eq. 2.33
        case (SHAPE_TRIANGLE)
            ! corrected Eq. 2.34b: ln[(sqrt(ab + (f eta/2)^2) + f eta/2)/(-a)]/f
            b = expm1(0.5_dp * f)**2 + expm1(0.5_dp * f * eta)
            a = expm1(-0.5_dp * f)**2 + expm1(-0.5_dp * f * eta)
            hfe = 0.5_dp * f * eta
            tau_i = log((sqrt(a * b + hfe * hfe) + hfe) / (-a)) / f
        case default
            ! corrected Eq. 2.32b-e: 1 + A z + B/z = 0, z = e^(f(tau-1)), the larger root
            ! z = (1 + sqrt(1 - 4AB))/(-2A) (A < 0 in S), 1 - 4AB = psi1 (2 - psi1) + q1^2
            z = (1.0_dp + sqrt(st%p_one * (2.0_dp - st%p_one) + st%q_one**2)) / (-2.0_dp * st%a)
            tau_i = 1.0_dp + log(z) / f
        end select
    end subroutine get_tau_i

    !> Root on [lo, hi] (inside phase 1 or 2 of the pulse, a sign change) of F = psi - level
    !> (what 1) or F = psi'/f (what 2), given the exact state at both ends,
    !> sl = [psi, psi'/f, e, e^e] with e the node of the phase there (the exponent of the
    !> pulse term of g); psi_x = psi at the root.
    !> Higher-order Newton: steps to the root of the degree-5 Taylor model of F at the last
    !> point with an exact state, the coefficients from the equation of motion,
    !> psi_(j+2) = f^2 (psi_j + g_j)/((j+1)(j+2)), g_j = g^(j)/j! in closed form (order 6).
    !> The first model is built at the end nearer the root of the cubic Hermite interpolant
    !> (no evaluation); each step stays in the bracket, which every exact evaluation
    !> shrinks, and within 1.5/max(f, 2|beta|) of its point. Converged when the step is below
    !> 4 eps |x| (that point), or below 1e-3/max(f, 2|beta|) (the model point: the model is
    !> then exact to 1e-18 relative). Otherwise, after 10 steps, find_root_newton finishes
    !> on the bracket (guaranteed termination).
    subroutine phase_root(st, phase, what, level, lo, sl, hi, sh, x, psi_x, stat, errmsg)
        type(rock_state), intent(in) :: st
        integer, intent(in) :: phase, what
        real(dp), intent(in) :: level, lo, sl(4), hi, sh(4)
        real(dp), intent(out) :: x, psi_x
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(psi_level_fn) :: fl
        type(dpsi_fn) :: fd
        real(dp) :: a, fa, b, fb, xk, psi, q, e, ee, fk, c(0:6), m(0:5), d, r, q2
        real(dp) :: mlo(0:5), mhi(0:5), clo(0:6), chi(0:6)
        integer :: it, j
        stat = SEISPULSE_SUCCESS
        call taylor_model(st, phase, what, level, lo, sl(1), sl(2), sl(3), sl(4), clo, mlo)
        call taylor_model(st, phase, what, level, hi, sh(1), sh(2), sh(3), sh(4), chi, mhi)
        a = lo
        fa = mlo(0)
        b = hi
        fb = mhi(0)
        r = max(st%f, 2.0_dp * abs(st%beta))
        ! start at the end whose model step is the shorter (none where F' = 0)
        d = huge(d)
        if (abs(mlo(1)) > 0.0_dp) d = abs(series_step(mlo))
        q2 = huge(q2)
        if (abs(mhi(1)) > 0.0_dp) q2 = abs(series_step(mhi))
        if (d <= q2) then
            xk = lo
            psi = sl(1)
            c = clo
            m = mlo
        else
            xk = hi
            psi = sh(1)
            c = chi
            m = mhi
        end if
        do it = 1, 10
            if (it > 1) then
                call eval_node(st, phase, xk, psi, q, e, ee)
                call taylor_model(st, phase, what, level, xk, psi, q, e, ee, c, m)
                fk = m(0)
                x = xk
                psi_x = psi
                if (.not. abs(fk) > 0.0_dp) return
                if (.not. ieee_is_finite(fk)) exit
                if ((fk > 0.0_dp .and. fa > 0.0_dp) .or. (fk < 0.0_dp .and. fa < 0.0_dp)) then
                    a = xk
                    fa = fk
                else
                    b = xk
                    fb = fk
                end if
            end if
            d = min(max(series_step(m), max(a - xk, -1.5_dp / r)), min(b - xk, 1.5_dp / r))
            if (it > 1 .and. abs(d) <= 4.0_dp * epsilon(x) * abs(xk)) return
            if (small_step(m, r) .and. xk + d > a .and. xk + d < b) then
                x = xk + d
                psi_x = c(6)
                do j = 5, 0, -1
                    psi_x = psi_x * d + c(j)
                end do
                return
            end if
            xk = xk + d
            if (.not. (xk > a .and. xk < b)) xk = 0.5_dp * (a + b)
        end do
        if (what == 1) then
            fl%st = st
            fl%level = level
            call find_root_newton(fl, a, b, x, stat, errmsg, fa_known=fa, fb_known=fb)
        else
            fd%st = st
            call find_root_newton(fd, a, b, x, stat, errmsg, fa_known=fa, fb_known=fb)
        end if
        call eval_node(st, phase, x, psi_x, q2, e, ee)
    end subroutine phase_root

    !> psi, q = psi'/f at x in the given phase (1 or 2) and the node e of that phase with
    !> ee = e^e (e = 2 beta (x - tau_up) in phase 1, d0 - 2 beta (x - 1/2) in phase 2).
    pure subroutine eval_node(st, phase, x, psi, q, e, ee)
        type(rock_state), intent(in) :: st
        integer, intent(in) :: phase
        real(dp), intent(in) :: x
        real(dp), intent(out) :: psi, q, e, ee
        real(dp) :: h
        if (st%shape /= SHAPE_GENERAL) then
            call state_eval(st, x, psi, q)
            e = 0.0_dp
            ee = 1.0_dp
        else if (phase == 1) then
            h = x - st%tup
            e = 2.0_dp * st%beta * h
            ee = exp(e)
            call phase1(st, h, e, ee, st%f * h, psi, q)
        else
            h = x - 0.5_dp
            e = st%d0 - 2.0_dp * st%beta * h
            ee = exp(e)
            call phase2(st, h, e, ee, psi, q)
        end if
    end subroutine eval_node

    !> The Taylor coefficients c(0:6) of psi at x (exact psi, q = psi'/f there, node e,
    !> ee = e^e of the phase) and the degree-5 model m(0:5) of F (what 1: psi - level,
    !> what 2: psi'/f). g = C (e^e - 1) with g^(j) = C kappa^j e^e (kappa = +-2 beta).
    pure subroutine taylor_model(st, phase, what, level, x, psi, q, e, ee, c, m)
        type(rock_state), intent(in) :: st
        integer, intent(in) :: phase, what
        real(dp), intent(in) :: level, x, psi, q, e, ee
        real(dp), intent(out) :: c(0:6), m(0:5)
        real(dp) :: g, ge, kap, pw, f2, h
        integer :: j
        if (phase == 1) then
            h = x - st%tup
            kap = 2.0_dp * st%beta
            ge = st%k * ee                    ! C kappa e^e
            g = st%k * h * phi1_from_exp(e, ee)
        else
            h = x - (1.0_dp - st%tup)
            kap = -2.0_dp * st%beta
            ge = -st%k * ee
            g = -st%k * h * phi1_from_exp(e, ee)
        end if
        if (st%shape == SHAPE_RECTANGLE) then
            g = st%c0
            ge = 0.0_dp
        end if
        f2 = st%f * st%f
        c(0) = psi
        c(1) = st%f * q
        pw = 1.0_dp                           ! kappa^(j-1)/j! for the g_j of the next step
        do j = 0, 4
            c(j + 2) = f2 * (c(j) + g) * inv_pair(j)
            g = ge * pw
            pw = pw * kap * inv_int(j + 2)
        end do
        if (what == 1) then
            m = c(0:5)
            m(0) = m(0) - level
        else
            h = 1.0_dp / st%f
            do j = 0, 5
                m(j) = real(j + 1, dp) * c(j + 1) * h
            end do
        end if
    end subroutine taylor_model

    !> Root d near 0 of the polynomial m(0:5) by series reversion: with y = -m0/m1 and
    !> b_j = m_j/m1, d = y - b2 y^2 + (2 b2^2 - b3) y^3 + (5 b2 b3 - 5 b2^3 - b4) y^4
    !> + (14 b2^4 - 21 b2^2 b3 + 6 b2 b4 + 3 b3^2 - b5) y^5 (error O(y^6): the step of a
    !> sixth-order method; the caller clamps it to the bracket and the trust radius).
    pure function series_step(m) result(d)
        real(dp), intent(in) :: m(0:5)
        real(dp) :: d, r1, y, b2, b3, b4, b5
        if (.not. abs(m(1)) > 0.0_dp) then
            d = 0.0_dp
            return
        end if
        r1 = 1.0_dp / m(1)
        y = -m(0) * r1
        b2 = m(2) * r1
        b3 = m(3) * r1
        b4 = m(4) * r1
        b5 = m(5) * r1
        d = y * (1.0_dp + y * (-b2 + y * ((2.0_dp * b2 * b2 - b3) &
            + y * ((5.0_dp * b2 * b3 - 5.0_dp * b2**3 - b4) &
            + y * (14.0_dp * b2**4 - 21.0_dp * b2 * b2 * b3 + 6.0_dp * b2 * b4 &
                   + 3.0_dp * b3 * b3 - b5)))))
        if (.not. abs(d) <= huge(d)) d = y
    end function series_step

    !> Whether the model step of series_step is exact to rounding: y = -m0/m1 with
    !> |y b2|, |y^2 b3|^(1/2), ... and |y| r (r bounds the neglected Taylor terms) below
    !> 1e-3, so the neglected terms of the reversion and of the model are below 1e-18 |y|.
    pure logical function small_step(m, r) result(ok)
        real(dp), intent(in) :: m(0:5), r
        real(dp) :: y, t
        ok = abs(m(1)) > 0.0_dp
        if (.not. ok) return
        y = abs(m(0) / m(1))
        t = y / abs(m(1))
        ok = y * r <= 1.0e-3_dp .and. t * abs(m(2)) <= 1.0e-3_dp &
             .and. t * y * abs(m(3)) <= 1.0e-6_dp .and. t * y * y * abs(m(4)) <= 1.0e-9_dp &
             .and. t * y**3 * abs(m(5)) <= 1.0e-12_dp
    end function small_step

    !> Root of fn on [lo, hi] (a sign change) given its values and slopes at both ends:
    !> up to two evaluations at the root of the cubic Hermite interpolant (which shrink the
    !> bracket to a sliver for these smooth functions), then find_root_newton on what is
    !> left (safeguarded Newton, guaranteed termination).
    subroutine solve_hermite(fn, lo, flo, dlo, hi, fhi, dhi, x, stat, errmsg)
        class(smooth_function), intent(inout) :: fn
        real(dp), intent(in) :: lo, flo, dlo, hi, fhi, dhi
        real(dp), intent(out) :: x
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: a, fa, da, b, fb, db, xg, fg, dg
        integer :: i
        a = lo
        fa = flo
        da = dlo
        b = hi
        fb = fhi
        db = dhi
        do i = 1, 2
            if (.not. (abs(fa) > 0.0_dp .and. abs(fb) > 0.0_dp)) exit
            xg = hermite_root(a, fa, da, b, fb, db)
            if (.not. (xg > a .and. xg < b)) exit
            call fn%eval_slope(xg, fg, dg)
            if (.not. ieee_is_finite(fg)) exit
            if ((fg > 0.0_dp .and. fa > 0.0_dp) .or. (fg < 0.0_dp .and. fa < 0.0_dp)) then
                a = xg
                fa = fg
                da = dg
            else
                b = xg
                fb = fg
                db = dg
            end if
        end do
        call find_root_newton(fn, a, b, x, stat, errmsg, fa_known=fa, fb_known=fb)
    end subroutine solve_hermite

    !> Root in (a, b) of the cubic Hermite interpolant of (fa, da) at a and (fb, db) at b,
    !> fa fb < 0: Newton on the cubic kept in its bracket (a few flops; only a first guess).
    pure function hermite_root(a, fa, da, b, fb, db) result(x)
        real(dp), intent(in) :: a, fa, da, b, fb, db
        real(dp) :: x, w, c1, c2, c3, t, tl, th, h, dh, dt
        integer :: it
        w = b - a
        c1 = w * da
        c2 = 3.0_dp * (fb - fa) - 2.0_dp * w * da - w * db
        c3 = 2.0_dp * (fa - fb) + w * da + w * db
        ! H(0) = fa, H(1) = fb; keep tl on the side of fa
        tl = 0.0_dp
        th = 1.0_dp
        t = fa / (fa - fb)
        do it = 1, 8
            h = fa + t * (c1 + t * (c2 + t * c3))
            dh = c1 + t * (2.0_dp * c2 + 3.0_dp * t * c3)
            if ((h > 0.0_dp .and. fa > 0.0_dp) .or. (h < 0.0_dp .and. fa < 0.0_dp)) then
                tl = t
            else
                th = t
            end if
            if (abs(dh) > 0.0_dp) then
                dt = h / dh
            else
                dt = 2.0_dp
            end if
            if (.not. (t - dt > min(tl, th) .and. t - dt < max(tl, th))) then
                dt = t - 0.5_dp * (tl + th)
            end if
            t = t - dt
            if (abs(dt) < 1.0e-12_dp) exit
        end do
        x = a + t * w
    end function hermite_root

    ! ------------------------------------------------------------------------------
    ! Boundaries by root finding (table 8: R2, R3, R4 inverse, R6)
    ! ------------------------------------------------------------------------------

    !> eta_w(f, beta), Eq. 2.20 with Q = R^(2 beta/(2 beta - f)) and
    !> R = [2f e^(beta - f/2) - (f - 2 beta) e^-f]/(f + 2 beta) = e^-f (1 + f phi_1(beta + f/2))
    !> (no 0/0 at f = -2 beta); eta_w = expm1(beta lambda)/expm1(beta), lambda = ln Q/beta
    !> = 2 ln R/(2 beta - f). Near f = 2 beta (0/0 in lambda): R - 1 = d W/(f + 2 beta),
    !> d = 2 beta - f, W = f phi_1(d/2) + expm1(-f), so lambda = 2 W/(f + 2 beta)
    !> ln(1 + x)/x, x = d W/(f + 2 beta). For beta > 0, lambda - 1 = 2 ln(e^-y + f q_1(y))/d
    !> (y = beta + f/2, q_1 = e^-y phi_1) scales out e^beta (no overflow).
    pure function wall_eta(f, beta) result(eta_w)
        real(dp), intent(in) :: f, beta
        real(dp) :: eta_w, d, s, w, lam, lm1, y, lnr
        if (beta < -huge(beta)) then
            eta_w = -expm1(-f)                                  ! Eq. 2.21
        else if (beta > huge(beta)) then
            eta_w = 0.0_dp
        else if (.not. abs(beta) > 0.0_dp) then
            ! Eq. 2.22, 2 - (2/f) ln(2 e^(f/2) - 1) = -(2/f) ln(1 - (1 - e^(-f/2))^2)
            ! = 1 - (2/f) ln(2 - e^(-f/2)) (the first form for small f, the second for large)
            if (f < 1.0_dp) then
                eta_w = -(2.0_dp / f) * log1p(-expm1(-0.5_dp * f)**2)
            else
                eta_w = 1.0_dp - (2.0_dp / f) * log(2.0_dp - exp(-0.5_dp * f))
            end if
        else
            d = 2.0_dp * beta - f
            s = f + 2.0_dp * beta
            y = beta + 0.5_dp * f
            if (beta > 0.0_dp) then
                if (abs(d) < 0.5_dp * s) then
                    w = f * phi1(0.5_dp * d) + expm1(-f)
                    lam = 2.0_dp * w / s * log1p_over_x(d * w / s)
                    lm1 = lam - 1.0_dp
                else
                    lm1 = 2.0_dp * log(exp(-y) + f * (-expm1(-y)) / y) / d
                    lam = 1.0_dp + lm1
                end if
                eta_w = exp(beta * lm1) * expm1(-beta * lam) / expm1(-beta)
            else
                if (y > 1.0_dp) then
                    lnr = (beta - 0.5_dp * f) + log(exp(-y) + f * (-expm1(-y)) / y)
                else
                    lnr = -f + log1p(f * phi1(y))
                end if
                lam = 2.0_dp * lnr / d
                eta_w = expm1(beta * lam) / expm1(beta)
            end if
        end if
    end function wall_eta

    !> Root in eta of a boundary function at fixed f, beta: WHAT_MID/WHAT_END on (0, 1)
    !> (the value is -1 at eta = 1 and grows without bound as eta -> 0), WHAT_S1S2 on
    !> (eta_w, 1) (psi'(1) > 0 on the wall, < 0 as eta -> 1).
    subroutine eta_boundary(f, beta, what, eta_b, stat, errmsg)
        real(dp), intent(in) :: f, beta
        integer, intent(in) :: what
        real(dp), intent(out) :: eta_b
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(eta_boundary_fn) :: fn
        real(dp) :: lo, hi, flo, fhi, gap
        integer :: i
        stat = SEISPULSE_SUCCESS
        fn%f = f
        fn%beta = beta
        fn%what = what
        if (what == WHAT_S1S2) then
            lo = wall_eta(f, beta)
            flo = fn%eval(lo)
            gap = 1.0_dp - lo
            hi = lo
            fhi = flo
            do i = 1, 60
                hi = 1.0_dp - gap * 0.5_dp**i
                fhi = fn%eval(hi)
                if (fhi < 0.0_dp) exit
                lo = hi
                flo = fhi
            end do
            if (.not. (fhi < 0.0_dp)) then
                eta_b = hi            ! the S1 strip is narrower than rounding near 1
                return
            end if
            if (.not. (flo > 0.0_dp)) then
                eta_b = lo            ! on the wall up to rounding
                return
            end if
        else
            hi = 1.0_dp
            fhi = -1.0_dp             ! no rocking at eta = 1
            lo = 0.5_dp
            flo = fn%eval(lo)
            do i = 1, 1100
                if (flo > 0.0_dp) exit
                hi = lo
                fhi = flo
                lo = 0.5_dp * lo
                if (.not. lo > 0.0_dp) then
                    eta_b = 0.0_dp    ! below the smallest number
                    return
                end if
                flo = fn%eval(lo)
            end do
        end if
        call find_root(fn, lo, hi, eta_b, stat, errmsg, fa_known=flo, fb_known=fhi)
    end subroutine eta_boundary

    !> Root in f of a boundary function at fixed eta < 1, beta (WHAT_MID, WHAT_END, WHAT_WALL):
    !> each increases in f from a negative value at f -> 0 to a positive one.
    subroutine f_boundary(eta, beta, what, f_b, stat, errmsg)
        real(dp), intent(in) :: eta, beta
        integer, intent(in) :: what
        real(dp), intent(out) :: f_b
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(f_boundary_fn) :: fn
        real(dp) :: lo, hi, flo, fhi
        integer :: i
        stat = SEISPULSE_SUCCESS
        fn%eta = eta
        fn%beta = beta
        fn%what = what
        lo = 1.0_dp
        flo = fn%eval(lo)
        hi = lo
        fhi = flo
        if (flo < 0.0_dp) then
            do i = 1, 12
                hi = 2.0_dp * lo
                fhi = fn%eval(hi)
                if (fhi >= 0.0_dp) exit
                lo = hi
                flo = fhi
            end do
            if (.not. (fhi >= 0.0_dp)) then
                f_b = ieee_value(f_b, ieee_positive_inf)   ! beyond f = 4096: eta ~ 1
                return
            end if
        else
            do i = 1, 1100
                lo = 0.5_dp * hi
                if (.not. lo > 0.0_dp) then
                    f_b = 0.0_dp
                    return
                end if
                flo = fn%eval(lo)
                if (flo < 0.0_dp) exit
                hi = lo
                fhi = flo
            end do
        end if
        call find_root(fn, lo, hi, f_b, stat, errmsg, fa_known=flo, fb_known=fhi)
    end subroutine f_boundary

    function eta_boundary_value(self, x) result(y)
        class(eta_boundary_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        type(rock_state) :: st
        call state_init(st, self%f, x, self%beta)
        if (.not. st%rocks) then
            y = -1.0_dp
        else if (self%what == WHAT_MID) then
            y = st%p_half - 1.0_dp
        else if (self%what == WHAT_END) then
            y = st%p_one - 1.0_dp
        else
            y = st%q_one
        end if
    end function eta_boundary_value

    function f_boundary_value(self, x) result(y)
        class(f_boundary_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        type(rock_state) :: st
        if (self%what == WHAT_WALL) then
            y = wall_eta(x, self%beta) - self%eta
        else
            call state_init(st, x, self%eta, self%beta)
            if (self%what == WHAT_MID) then
                y = st%p_half - 1.0_dp
            else
                y = st%p_one - 1.0_dp
            end if
        end if
    end function f_boundary_value

    function psi_level_value(self, x) result(y)
        class(psi_level_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y, dy
        call self%eval_slope(x, y, dy)
    end function psi_level_value

    subroutine psi_level_slope(self, x, y, dy)
        class(psi_level_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), intent(out) :: y, dy
        real(dp) :: q
        call state_eval(self%st, x, y, q)
        y = y - self%level
        dy = self%st%f * q
    end subroutine psi_level_slope

    function dpsi_value(self, x) result(y)
        class(dpsi_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y, dy
        call self%eval_slope(x, y, dy)
    end function dpsi_value

    subroutine dpsi_slope(self, x, y, dy)
        class(dpsi_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), intent(out) :: y, dy
        real(dp) :: psi
        call state_eval(self%st, x, psi, y)
        dy = self%st%f * (psi + state_forcing(self%st, x))
    end subroutine dpsi_slope

    function tri_impact_value(self, x) result(y)
        class(tri_impact_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y, dy
        call self%eval_slope(x, y, dy)
    end function tri_impact_value

    subroutine tri_impact_slope(self, x, y, dy)
        class(tri_impact_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), intent(out) :: y, dy
        real(dp) :: y1, y2
        y1 = self%f * (x - 0.5_dp * self%eta)
        y2 = self%f * (x - 0.5_dp)
        ! Eq. 2.34a = (sinh y1 - y1) - 2 (sinh y2 - y2)
        y = sinh_minus_x(y1) - 2.0_dp * sinh_minus_x(y2)
        dy = self%f * (2.0_dp * sinh(0.5_dp * y1)**2 - 4.0_dp * sinh(0.5_dp * y2)**2)
    end subroutine tri_impact_slope

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    subroutine check_common(f, eta, beta, stat, errmsg)
        real(dp), intent(in) :: f, eta, beta
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call check_f(f, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_eta(eta, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_beta(beta, stat, errmsg)
    end subroutine check_common

    subroutine check_f(f, stat, errmsg)
        real(dp), intent(in) :: f
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (outside(f, 0.0_dp, huge(f), .true., .false.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'f = '//real_str(f) &
                           //': must be a finite number > 0 (f = p t_d)')
    end subroutine check_f

    subroutine check_eta(eta, stat, errmsg)
        real(dp), intent(in) :: eta
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        ! +inf is allowed: no rocking
        if (outside(eta, 0.0_dp, ieee_value(eta, ieee_positive_inf), .true., .false.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'eta = '//real_str(eta) &
                           //': must be > 0 (alpha/alpha_g; eta >= 1 means no rocking)')
    end subroutine check_eta


end module seispulse_rocking_closed
