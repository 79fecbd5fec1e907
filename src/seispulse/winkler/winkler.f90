!> Rigid cylinders and blocks on tensionless elastic Winkler soil, statics ([AD11] chapter
!> 2, doc/winkler.md sections 3-6): the Winkler modulus from the halfspace rocking stiffness of
!> the circle (W.24) and from [G91]'s rectangle formulas (W.25), the shape factor of the
!> varying-k method (W.26)-(W.27), the static pushover of a circular base (W.7)-(W.19) and of a
!> rectangular base (W.20)-(W.23) with the modulus constant or varying with the contact, the
!> universal small-angle curve (W.28) and the cylinder equivalent to a block on the same soil
!> (W.29).
!>
!> Conventions: theta >= 0 tilts the base so that the edge s = +r is pressed; s runs along the
!> rocking diameter from the base centre (m); the contact is the strip from the zero-pressure
!> line s = c to the compressed edge, of width b (m); the pressure k delta acts on the
!> horizontal projection of the base. Units: m, N, N m, rad, Pa (G), N/m^3 (k).
module seispulse_winkler
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_checks, only: in_open, in_closed, finite_at_least, outside
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_SOLUTION, set_error
    use seispulse_format, only: real_str, int_str
    use seispulse_special, only: pi, x_minus_sin
    use seispulse_roots, only: scalar_function, find_root, find_minimum
    use seispulse_cylinder, only: rocking_body_t, cylinder_props, equivalent_cylinder, &
                                  BODY_BLOCK
    use seispulse_winkler_contact, only: FOOTING_CIRCLE, FOOTING_RECTANGLE
    implicit none
    private

    public :: K_CONSTANT, K_VARYING, AXIS_LONG, AXIS_SHORT
    public :: WP_THETA, WP_B, WP_POLE, WP_AREA, WP_SETTLEMENT, WP_K, WP_M_FOUND, &
              WP_M_IMPOSED, WP_FORCE, WP_NCOL
    public :: winkler_pushover_t
    public :: halfspace_rocking_stiffness, winkler_modulus_circle, rect_rocking_stiffness, &
              winkler_modulus_rect, shape_factor, varying_modulus
    public :: winkler_pushover, block_winkler_pushover, winkler_master_curve, &
              winkler_equivalent_cylinder
    !> the scale check of a length, weight, modulus ... (in [1e-30, 1e30]), for the sibling
    !> module seispulse_clay_footing (not re-exported by the facade)
    public :: check_scale

    integer, parameter :: K_CONSTANT = 1   !! k fixed at its full-contact value
    integer, parameter :: K_VARYING = 2    !! [AD11] varying k: equivalent rectangle of the contact
    integer, parameter :: AXIS_LONG = 1    !! [G91] K_rx, rotation about the long axis
    integer, parameter :: AXIS_SHORT = 2   !! [G91] K_ry, rotation about the short axis

    integer, parameter :: WP_THETA = 1       !! tilt theta (rad)
    integer, parameter :: WP_B = 2           !! contact width from the compressed edge (m)
    integer, parameter :: WP_POLE = 3        !! pole a from the base centre towards the
                                             !! compressed edge (m)
    integer, parameter :: WP_AREA = 4        !! projected contact area (m^2)
    integer, parameter :: WP_SETTLEMENT = 5  !! settlement of the base centre (m, + down)
    integer, parameter :: WP_K = 6           !! current Winkler modulus (N/m^3)
    integer, parameter :: WP_M_FOUND = 7     !! foundation moment about the base centre (N m)
    integer, parameter :: WP_M_IMPOSED = 8   !! M_found - W h sin(theta) (N m)
    integer, parameter :: WP_FORCE = 9       !! F = M_imp/(h cos theta) at the CoM (N)
    integer, parameter :: WP_NCOL = 9        !! number of columns

    !> Scalars of a Winkler pushover (doc/winkler.md (W.18)-(W.19)).
    type :: winkler_pushover_t
        real(dp) :: theta_up               !! uplift angle (rad); NaN: no uplift on the branch
        real(dp) :: k0                     !! full-contact modulus (N/m^3)
        real(dp) :: max_force_over_weight  !! peak F/W on the branch (-)
        real(dp) :: theta_at_max           !! its theta (rad)
        real(dp) :: max_moment             !! peak imposed moment (N m)
        real(dp) :: theta_at_max_moment    !! its theta (rad)
        real(dp) :: theta_overturn         !! first zero of the imposed moment (rad); NaN if none
        real(dp) :: theta_end              !! largest admissible theta (end of the branch) (rad)
    end type winkler_pushover_t

    !> Accepted range of r, h, weight, k, G, alpha (in their units): every product formed
    !> (k r^4, W h, ...) is then representable.
    real(dp), parameter :: scale_min = 1.0e-30_dp, scale_max = 1.0e30_dp
    real(dp), parameter :: quarter_pi = 0.25_dp * pi, half_pi = 0.5_dp * pi
    !> [G91] rectangle formulas: K_rx = G/(1 - nu) I^0.75 (L/B)^0.25 (2.4 + 0.5 B/L),
    !> K_ry = 3 G/(1 - nu) I^0.75 (L/B)^0.15 (W.25).
    real(dp), parameter :: grx_a = 2.4_dp, grx_b = 0.5_dp, grx_e = 0.25_dp
    real(dp), parameter :: gry_a = 3.0_dp, gry_e = 0.15_dp
    !> Scan of the contact variable (varying k, peaks): uniform points, geometric tail.
    integer, parameter :: n_scan = 400, n_tail = 60, n_peak = 256
    !> Relative residual accepted for the inversion theta -> contact (a larger one: theta in
    !> the gap of a jump of the varying modulus, no equilibrium point).
    real(dp), parameter :: jump_rtol = 1.0e-8_dp

    !> One footing on one soil under one weight: the pushover branch (doc/winkler.md
    !> section 3). The contact variable t is u = acos(c/r) in (0, pi] (circle) or the width
    !> b' in (0, 2 r] (rectangle); t_max is full contact.
    type :: branch_t
        integer :: footing = FOOTING_CIRCLE
        real(dp) :: r = 1.0_dp, alpha = 1.0_dp, h = 1.0_dp, w = 1.0_dp, k = 1.0_dp
        logical :: varying = .false.
        integer :: reading = AXIS_LONG
        real(dp) :: t_max = pi
        real(dp) :: i_full = 1.0_dp     ! second moment of the full base (m^4)
        real(dp) :: a_full = 1.0_dp     ! area of the full base (m^2)
        real(dp) :: phi_full = 1.0_dp   ! Phi at full contact (m^3)
        real(dp) :: kr_full = 1.0_dp    ! (K_R/I)(1 - nu)/G of the full equivalent rectangle
    end type branch_t

    !> What a branch function returns at the contact variable t.
    integer, parameter :: fn_phi = 1       ! k(t) Phi(t) - target
    integer, parameter :: fn_overturn = 2  ! k(t) cos^2(theta) (J2 - c J1) - W h
    integer, parameter :: fn_force = 3     ! -F/W
    integer, parameter :: fn_moment = 4    ! -M_imp/(W r)

    type, extends(scalar_function) :: branch_fn
        type(branch_t) :: br
        integer :: what = fn_phi
        real(dp) :: target = 0.0_dp
    contains
        procedure :: eval => branch_eval
    end type branch_fn

    !> Peak imposed moment of a cylinder of given weight on the soil (equivalent cylinder).
    type, extends(scalar_function) :: cyl_peak_fn
        type(branch_t) :: br
        real(dp) :: target = 0.0_dp
    contains
        procedure :: eval => cyl_peak_eval
    end type cyl_peak_fn

contains

    ! ------------------------------------------------------------------------------
    ! Stiffness (doc/winkler.md section 5)
    ! ------------------------------------------------------------------------------

    !> Rocking stiffness of a rigid circular footing on a homogeneous elastic halfspace,
    !> K_R = 8 G r^3/(3 (1 - nu)) (N m/rad) (W.24).
    subroutine halfspace_rocking_stiffness(g_mod, nu, r, k_r, stat, errmsg)
        real(dp), intent(in) :: g_mod                         !! shear modulus G (Pa)
        real(dp), intent(in) :: nu                            !! Poisson's ratio, (0, 0.5)
        real(dp), intent(in) :: r                             !! footing radius (m)
        real(dp), intent(out) :: k_r                          !! K_R (N m/rad)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        k_r = nan()
        call check_soil(g_mod, nu, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(r, 'r', 'the footing radius', 'm', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        k_r = 8.0_dp * g_mod * r**3 / (3.0_dp * (1.0_dp - nu))             ! (W.24)
    end subroutine halfspace_rocking_stiffness

    !> Winkler modulus of a circular footing, k = K_R/I = 32 G/(3 pi (1 - nu) r) (N/m^3),
    !> I = pi r^4/4 (W.24).
    subroutine winkler_modulus_circle(g_mod, nu, r, k, stat, errmsg)
        real(dp), intent(in) :: g_mod                         !! shear modulus G (Pa)
        real(dp), intent(in) :: nu                            !! Poisson's ratio, (0, 0.5)
        real(dp), intent(in) :: r                             !! footing radius (m)
        real(dp), intent(out) :: k                            !! k (N/m^3)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        k = nan()
        call check_soil(g_mod, nu, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(r, 'r', 'the footing radius', 'm', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        k = 32.0_dp * (g_mod / r) / (3.0_dp * pi * (1.0_dp - nu))          ! (W.24)
    end subroutine winkler_modulus_circle

    !> [G91] rocking stiffness (N m/rad) of a rigid rectangular footing width x length (m) on
    !> a homogeneous halfspace, `width` along the rocking direction, rotation about the axis
    !> parallel to `length`, I = length width^3/12 about that axis (W.25): if length >= width
    !> the rotation is about the long axis, K_rx = G/(1 - nu) I^0.75 (L/B)^0.25 (2.4 + 0.5
    !> B/L) (axis = AXIS_LONG); else about the short axis, K_ry = 3 G/(1 - nu) I^0.75
    !> (L/B)^0.15 (axis = AXIS_SHORT); B <= L are the half-sides. At the square the two
    !> formulas differ (2.9 and 3.0 G/(1 - nu) I^0.75): the long-axis one is used.
    subroutine rect_rocking_stiffness(g_mod, nu, width, length, k_r, stat, errmsg, axis)
        real(dp), intent(in) :: g_mod                         !! shear modulus G (Pa)
        real(dp), intent(in) :: nu                            !! Poisson's ratio, (0, 0.5)
        real(dp), intent(in) :: width                         !! side along the rocking (m)
        real(dp), intent(in) :: length                        !! side along the axis (m)
        real(dp), intent(out) :: k_r                          !! K_R (N m/rad)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(out), optional :: axis                !! AXIS_LONG or AXIS_SHORT used
        integer :: ax
        k_r = nan()
        if (present(axis)) axis = AXIS_LONG
        call check_rect(g_mod, nu, width, length, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        ax = rect_axis(width, length)
        ! K_R = (K_R/I) I; I = length width^3/12 (W.25)
        k_r = g_mod / (1.0_dp - nu) * kr_over_i(width, length, ax) &
              * (length * width**3 / 12.0_dp)
        if (present(axis)) axis = ax
    end subroutine rect_rocking_stiffness

    !> Winkler modulus of a rectangular footing, k = K_R/I (N/m^3) with [G91]'s K_R of
    !> rect_rocking_stiffness and I = length width^3/12 (W.25).
    subroutine winkler_modulus_rect(g_mod, nu, width, length, k, stat, errmsg)
        real(dp), intent(in) :: g_mod                         !! shear modulus G (Pa)
        real(dp), intent(in) :: nu                            !! Poisson's ratio, (0, 0.5)
        real(dp), intent(in) :: width                         !! side along the rocking (m)
        real(dp), intent(in) :: length                        !! side along the axis (m)
        real(dp), intent(out) :: k                            !! k (N/m^3)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        k = nan()
        call check_rect(g_mod, nu, width, length, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        k = g_mod / (1.0_dp - nu) * kr_over_i(width, length, rect_axis(width, length))
    end subroutine winkler_modulus_rect

    !> Shape factor of the varying-k method by its definition, k_circle/k_square for the
    !> square 2r x 2r circumscribing the circle (W.26): 32 (4/3)^(1/4)/(3 pi C) with C = 2.9
    !> (reading AXIS_LONG, [G91] K_rx at L = B: 1.2581) or C = 3 (AXIS_SHORT, K_ry: 1.2162).
    !> Independent of G, nu and r. The value [AD11] used is lost; both readings are offered.
    subroutine shape_factor(reading, factor, stat, errmsg)
        integer, intent(in) :: reading                        !! AXIS_LONG or AXIS_SHORT
        real(dp), intent(out) :: factor                       !! k_circle/k_square (-)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        factor = nan()
        call check_reading(reading, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        ! k_circle (1 - nu) r/G = 32/(3 pi); k_square (1 - nu) r/G = kr_over_i(2, 2) (W.26)
        factor = 32.0_dp / (3.0_dp * pi) / kr_over_i(2.0_dp, 2.0_dp, reading)
    end subroutine shape_factor

    !> Winkler modulus of the varying-k method at contact width b (m), from the full-contact
    !> k (N/m^3) (W.27). Circle: the equivalent rectangle b x 2 sqrt(r^2 - a^2), a the pole
    !> (centroid of the contact segment), k_b = k (K_R/I)(b x L)/(K_R/I)(2r x 2r), both by
    !> the [G91] formula of `reading` (default AXIS_LONG, whose shape factor is 1.258): that
    !> is the shape factor of the reading times the rectangle's K_R/I, scaled to the given k,
    !> so k_b = k at full contact. Rectangle (half-width r, half-length alpha): b x 2 alpha,
    !> k_b = k (K_R/I)(b x 2 alpha)/(K_R/I)(2r x 2 alpha), each by the formula its sides select
    !> (rect_rocking_stiffness), no shape factor. b in (0, 2 r]. The dynamics uses it too.
    subroutine varying_modulus(footing, r, alpha, k, b, k_b, stat, errmsg, reading)
        integer, intent(in) :: footing                        !! FOOTING_CIRCLE / _RECTANGLE
        real(dp), intent(in) :: r                             !! radius or half-width (m)
        real(dp), intent(in) :: alpha                         !! half-length (m), rectangle
        real(dp), intent(in) :: k                             !! full-contact k (N/m^3)
        real(dp), intent(in) :: b                             !! contact width (m), (0, 2 r]
        real(dp), intent(out) :: k_b                          !! modulus at b (N/m^3)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(in), optional :: reading              !! AXIS_LONG (default)/AXIS_SHORT
        type(branch_t) :: br
        real(dp) :: t
        k_b = nan()
        call make_branch(footing, r, alpha, 1.0_dp, 1.0_dp, k, K_VARYING, br, stat, errmsg, &
                         reading)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(b, 0.0_dp, 2.0_dp * r, .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'b = '//real_str(b) &
                           //': the contact width must be a number in (0, 2 r] = (0, ' &
                           //real_str(2.0_dp * r)//'] (m)')
            return
        end if
        if (footing == FOOTING_CIRCLE) then
            t = 2.0_dp * atan2(sqrt(b), sqrt(2.0_dp * r - b))   ! u: sin^2(u/2) = b/(2r)
        else
            t = b
        end if
        k_b = modulus(br, t)
    end subroutine varying_modulus

    ! ------------------------------------------------------------------------------
    ! Pushover (doc/winkler.md sections 3 and 4)
    ! ------------------------------------------------------------------------------

    !> Static pushover of a rigid cylinder (base radius r, CoM height h, weight W) on
    !> tensionless Winkler soil of full-contact modulus k, on the user's grid of tilts theta
    !> (rad, finite, >= 0; any order): curve(i, WP_*) (W.7)-(W.19). Full contact up to
    !> theta_up = asin(2 W/(k pi r^3))/2 (W.10); then uplift, theta(b) = asin(2 W/(k(b)
    !> Phi(b)))/2 on the branch theta <= pi/4 (W.12), inverted on a proven bracket for
    !> constant k (Phi increases with b) and by a scan and bracket for varying k (the
    !> largest contact with that theta). Past the end of the branch (theta > pi/4: 2 W/(k
    !> Phi) > 1 for every admissible contact), or inside the gap of a jump of the varying
    !> modulus, a point has no equilibrium: NaN in columns 2..9. If 2 W/(k pi r^3) > 1 there
    !> is no uplift before pi/4: full contact up to pi/2, theta_up = NaN, theta_end = pi/2.
    !> res: the peaks of F/W and of M_imp (bounded maximiser), the first zero of M_imp
    !> (overturning; 0 if M_imp < 0 from the start, NaN if none on the branch) (W.19).
    !> k_method K_CONSTANT (default) or K_VARYING (W.27) with `reading` (default AXIS_LONG).
    subroutine winkler_pushover(r, h, weight, k, theta, curve, res, stat, errmsg, k_method, &
                                reading)
        real(dp), intent(in) :: r                             !! base radius (m)
        real(dp), intent(in) :: h                             !! CoM height (m)
        real(dp), intent(in) :: weight                        !! W (N)
        real(dp), intent(in) :: k                             !! full-contact k (N/m^3)
        real(dp), intent(in) :: theta(:)                      !! tilts (rad), >= 0
        real(dp), intent(out) :: curve(:, :)                  !! (size(theta), WP_NCOL)
        type(winkler_pushover_t), intent(out) :: res          !! scalars
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(in), optional :: k_method             !! K_CONSTANT (default)/K_VARYING
        integer, intent(in), optional :: reading              !! AXIS_LONG (default)/AXIS_SHORT
        call run_pushover(FOOTING_CIRCLE, r, 1.0_dp, h, weight, k, theta, curve, res, stat, &
                          errmsg, k_method, reading)
    end subroutine winkler_pushover

    !> Static pushover of a rigid block (half-width b in the rocking direction, half-length
    !> alpha out of plane, CoM height h, weight W) on Winkler soil (W.20)-(W.23): full contact
    !> up to theta_up = asin(W/(2 alpha b^2 k))/2 (W.21), then the contact width b' =
    !> sqrt(2 W/(alpha k sin 2 theta)) in closed form for constant k (W.22), by a scan and
    !> bracket for varying k (b' x 2 alpha rectangle, W.27). Columns, branch rules and res as
    !> winkler_pushover.
    subroutine block_winkler_pushover(b, alpha, h, weight, k, theta, curve, res, stat, errmsg, &
                                      k_method)
        real(dp), intent(in) :: b                             !! half-width (m)
        real(dp), intent(in) :: alpha                         !! half-length (m)
        real(dp), intent(in) :: h                             !! CoM height (m)
        real(dp), intent(in) :: weight                        !! W (N)
        real(dp), intent(in) :: k                             !! full-contact k (N/m^3)
        real(dp), intent(in) :: theta(:)                      !! tilts (rad), >= 0
        real(dp), intent(out) :: curve(:, :)                  !! (size(theta), WP_NCOL)
        type(winkler_pushover_t), intent(out) :: res          !! scalars
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(in), optional :: k_method             !! K_CONSTANT (default)/K_VARYING
        call run_pushover(FOOTING_RECTANGLE, b, alpha, h, weight, k, theta, curve, res, stat, &
                          errmsg, k_method)
    end subroutine block_winkler_pushover

    !> Universal small-angle curve of the constant-k footing (W.28) at x = theta/theta_up >= 0
    !> (theta_up = W r/(4 K_0) for the circle, W b/(3 K_0) for the rectangle, K_0 = k I):
    !> k_ratio = K_sec/K_0, m_ratio = M/(W r) (r the radius or the half-width b), b_ratio =
    !> b/(2 r), a_ratio = a/r. Full contact for x <= 1: (1, x/4 or x/3, 1, 0). Circle beyond:
    !> x = pi/f(u), K_sec/K_0 = g(u)/(pi/4), M/(W r) = g(u)/f(u), b/(2 r) = sin^2(u/2); rectangle:
    !> beta = b'/(2 b) = x^(-1/2), K_sec/K_0 = beta^2 (3 - 2 beta), M/(W b) = 1 - 2 beta/3,
    !> a/b = 1 - beta. x = +inf gives the limits (0, 1, 0, 1); NaN for x < 0, NaN or an unknown
    !> footing.
    elemental subroutine winkler_master_curve(footing, x, k_ratio, m_ratio, b_ratio, a_ratio)
        integer, intent(in) :: footing      !! FOOTING_CIRCLE or FOOTING_RECTANGLE
        real(dp), intent(in) :: x           !! theta/theta_up (-), >= 0
        real(dp), intent(out) :: k_ratio    !! K_sec/K_0 (-)
        real(dp), intent(out) :: m_ratio    !! M/(W r) (-)
        real(dp), intent(out) :: b_ratio    !! b/(2 r) (-)
        real(dp), intent(out) :: a_ratio    !! a/r (-)
        real(dp) :: u, beta
        k_ratio = nan()
        m_ratio = k_ratio
        b_ratio = k_ratio
        a_ratio = k_ratio
        if (ieee_is_nan(x)) return
        if (x < 0.0_dp) return
        if (footing /= FOOTING_CIRCLE .and. footing /= FOOTING_RECTANGLE) return
        if (x <= 1.0_dp) then
            k_ratio = 1.0_dp
            b_ratio = 1.0_dp
            a_ratio = 0.0_dp
            if (footing == FOOTING_CIRCLE) then
                m_ratio = 0.25_dp * x                                       ! (W.28)
            else
                m_ratio = x / 3.0_dp                                        ! (W.28)
            end if
        else if (x > huge(x)) then
            k_ratio = 0.0_dp
            m_ratio = 1.0_dp
            b_ratio = 0.0_dp
            a_ratio = 1.0_dp
        else if (footing == FOOTING_CIRCLE) then
            u = u_of_phi(pi / x)                                            ! (W.28)
            k_ratio = seg_g(u) / quarter_pi
            m_ratio = seg_g(u) / seg_f(u)
            b_ratio = sin(0.5_dp * u)**2
            a_ratio = seg_pole(u)
        else
            beta = 1.0_dp / sqrt(x)                                         ! (W.28)
            k_ratio = beta * beta * (3.0_dp - 2.0_dp * beta)
            m_ratio = 1.0_dp - 2.0_dp * beta / 3.0_dp
            b_ratio = beta
            a_ratio = 1.0_dp - beta
        end if
    end subroutine winkler_master_curve

    !> The solid cylinder equivalent to a block on the same Winkler soil ([AD11] p.43,
    !> doc/winkler.md (W.29)): three conditions, (1) the same rigid p and (2) the slenderness
    !> theta_c (default: the block's own) fix r_c and h_c as equivalent_cylinder does (Y.13,
    !> Y.14); (3) the mass makes the peak imposed moment of the cylinder's Winkler pushover
    !> equal to the block's, on the same k with the same k_method (varying: the cylinder with
    !> the reading AXIS_LONG). The root in the cylinder's weight lies on a proven bracket: the
    !> peak is below W r_c (M_found <= W r cos theta), so W = M_peak/r_c is a lower end; the
    !> upper end is found by doubling (at most 60 times; the lightest cylinder found).
    subroutine winkler_equivalent_cylinder(block, alpha, k, cyl, stat, errmsg, theta_c, &
                                           k_method)
        type(rocking_body_t), intent(in) :: block             !! the block (block_props)
        real(dp), intent(in) :: alpha                         !! block half-length (m)
        real(dp), intent(in) :: k                             !! full-contact k (N/m^3)
        type(rocking_body_t), intent(out) :: cyl              !! its solid cylinder
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> slenderness (rad), (0, pi/2); default the block's own
        real(dp), intent(in), optional :: theta_c
        integer, intent(in), optional :: k_method             !! K_CONSTANT (default)/K_VARYING
        type(branch_t) :: bb
        type(rocking_body_t) :: geom
        type(winkler_pushover_t) :: rb
        type(cyl_peak_fn) :: fn
        real(dp) :: target, w_lo, w_hi, p_lo, p_hi, w_c
        integer :: km, i
        km = K_CONSTANT
        if (present(k_method)) km = k_method
        if (block%shape /= BODY_BLOCK) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'block: shape = ' &
                           //int_str(block%shape)//': must be a block (block_props)')
            return
        end if
        call make_branch(FOOTING_RECTANGLE, block%r, alpha, block%h, block%weight, k, km, bb, &
                         stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call equivalent_cylinder(block, geom, stat, errmsg, theta_c)        ! (W.29) 1, 2
        if (stat /= SEISPULSE_SUCCESS) return
        call branch_scalars(bb, rb, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        target = rb%max_moment
        if (.not. (target > 0.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'block: the imposed moment' &
                           //' has no positive peak on this soil (W h >= k I): no equivalent')
            return
        end if
        call make_branch(FOOTING_CIRCLE, geom%r, 1.0_dp, geom%h, block%weight, k, km, &
                         fn%br, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        fn%target = target
        ! (W.29) 3: the peak is below W r_c, so W = target/r_c undershoots
        w_lo = target / geom%r
        p_lo = fn%eval(w_lo)
        w_hi = w_lo
        p_hi = p_lo
        do i = 1, 60
            w_hi = 2.0_dp * w_lo
            p_hi = fn%eval(w_hi)
            if (p_hi >= 0.0_dp .or. p_hi < p_lo .or. w_hi > scale_max) exit
            w_lo = w_hi
            p_lo = p_hi
        end do
        if (.not. (p_hi >= 0.0_dp) .or. .not. (p_lo < 0.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'block: no cylinder of radius ' &
                           //real_str(geom%r)//' m and height '//real_str(geom%h) &
                           //' m reaches the block''s peak imposed moment '//real_str(target) &
                           //' N m on this soil')
            return
        end if
        call find_root(fn, w_lo, w_hi, w_c, stat, errmsg, fa_known=p_lo, fb_known=p_hi)
        if (stat /= SEISPULSE_SUCCESS) return
        call cylinder_props(geom%r, geom%h, w_c / block%g, block%g, cyl, stat, errmsg)
    end subroutine winkler_equivalent_cylinder

    ! ------------------------------------------------------------------------------
    ! The branch engine
    ! ------------------------------------------------------------------------------

    !> Validate and set up a branch. The weight and h of varying_modulus are dummies (1).
    subroutine make_branch(footing, r, alpha, h, weight, k, k_method, br, stat, errmsg, &
                           reading)
        integer, intent(in) :: footing, k_method
        real(dp), intent(in) :: r, alpha, h, weight, k
        type(branch_t), intent(out) :: br
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer, intent(in), optional :: reading
        if (footing /= FOOTING_CIRCLE .and. footing /= FOOTING_RECTANGLE) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'footing = ' &
                           //int_str(footing)//': must be FOOTING_CIRCLE (1) or' &
                           //' FOOTING_RECTANGLE (2)')
            return
        end if
        if (footing == FOOTING_CIRCLE) then
            call check_scale(r, 'r', 'the base radius', 'm', stat, errmsg)
        else
            call check_scale(r, 'b', 'the half-width', 'm', stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            call check_scale(alpha, 'alpha', 'the half-length', 'm', stat, errmsg)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(h, 'h', 'the height of the centre of mass', 'm', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(weight, 'weight', 'the weight', 'N', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(k, 'k', 'the Winkler modulus', 'N/m^3', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (k_method /= K_CONSTANT .and. k_method /= K_VARYING) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'k_method = ' &
                           //int_str(k_method)//': must be K_CONSTANT (1) or K_VARYING (2)')
            return
        end if
        br%reading = AXIS_LONG
        if (present(reading)) then
            call check_reading(reading, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            br%reading = reading
        end if
        br%footing = footing
        br%r = r
        br%alpha = alpha
        br%h = h
        br%w = weight
        br%k = k
        br%varying = k_method == K_VARYING
        if (footing == FOOTING_CIRCLE) then
            br%t_max = pi
            br%i_full = quarter_pi * r**4                                   ! (W.8)
            br%a_full = pi * r * r
            br%phi_full = pi * r**3                                         ! (W.12)
            br%kr_full = kr_over_i(2.0_dp * r, 2.0_dp * r, br%reading)
        else
            br%t_max = 2.0_dp * r
            br%i_full = 4.0_dp * alpha * r**3 / 3.0_dp                      ! (W.20)
            br%a_full = 4.0_dp * alpha * r
            br%phi_full = 4.0_dp * alpha * r * r                            ! (W.22)
            br%kr_full = kr_over_i(2.0_dp * r, 2.0_dp * alpha, &
                                   rect_axis(2.0_dp * r, 2.0_dp * alpha))
        end if
        stat = SEISPULSE_SUCCESS
    end subroutine make_branch

    !> Phi (m^3) at the contact variable t: W = k sin(theta) cos(theta) Phi (W.12), (W.22).
    pure real(dp) function phi_of(br, t)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: t
        if (br%footing == FOOTING_CIRCLE) then
            phi_of = br%r**3 * seg_f(t)
        else
            phi_of = br%alpha * t * t
        end if
    end function phi_of

    !> J2 - c J1 (m^4) at t: M_found = k sin(theta) cos^2(theta) (J2 - c J1) (W.14), (W.23).
    pure real(dp) function mom_of(br, t)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: t
        if (br%footing == FOOTING_CIRCLE) then
            mom_of = br%r**4 * seg_g(t)
        else
            ! 2 alpha [(b^3 - c^3)/3 - c (b^2 - c^2)/2] = alpha b'^2 (3 b - b')/3
            mom_of = br%alpha * t * t * (3.0_dp * br%r - t) / 3.0_dp
        end if
    end function mom_of

    !> Winkler modulus (N/m^3) at the contact variable t (W.27).
    pure real(dp) function modulus(br, t)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: t
        real(dp) :: a, chord
        modulus = br%k
        if (.not. br%varying) return
        if (t >= br%t_max) return
        if (br%footing == FOOTING_CIRCLE) then
            ! chord through the pole, 2 sqrt(r^2 - a^2) = 2 r sqrt(q (2 - q)), q = 1 - a/r
            a = seg_one_minus_pole(t)
            chord = 2.0_dp * br%r * sqrt(a * (2.0_dp - a))
            modulus = br%k * kr_over_i(2.0_dp * br%r * sin(0.5_dp * t)**2, chord, br%reading) &
                      / br%kr_full
        else
            modulus = br%k * kr_over_i(t, 2.0_dp * br%alpha, rect_axis(t, 2.0_dp * br%alpha)) &
                      / br%kr_full
        end if
    end function modulus

    !> Tilt at the contact variable t (W.12), (W.22); ok = .false. where 2 W/(k Phi) > 1.
    pure subroutine theta_at(br, t, theta, ok)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: t
        real(dp), intent(out) :: theta
        logical, intent(out) :: ok
        real(dp) :: s
        s = 2.0_dp * br%w / (modulus(br, t) * phi_of(br, t))
        ok = s <= 1.0_dp
        theta = quarter_pi
        if (ok) theta = 0.5_dp * asin(s)
    end subroutine theta_at

    !> One curve row at full contact (W.7)-(W.9), (W.20).
    pure subroutine full_row(br, theta, row)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: theta
        real(dp), intent(out) :: row(WP_NCOL)
        real(dp) :: s, c
        s = sin(theta)
        c = cos(theta)
        row(WP_THETA) = theta
        row(WP_B) = 2.0_dp * br%r
        row(WP_POLE) = 0.0_dp
        row(WP_AREA) = br%a_full * c
        row(WP_SETTLEMENT) = br%w / (br%k * br%a_full * c)                 ! (W.7)
        row(WP_K) = br%k
        row(WP_M_FOUND) = br%k * br%i_full * c * c * s                     ! (W.8), (W.20)
        row(WP_M_IMPOSED) = row(WP_M_FOUND) - br%w * br%h * s              ! (W.9)
        row(WP_FORCE) = row(WP_M_IMPOSED) / (br%h * c)                     ! (W.9)
    end subroutine full_row

    !> One curve row after uplift at contact variable t and tilt theta (W.11)-(W.16), (W.23).
    pure subroutine uplift_row(br, t, theta, row)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: t, theta
        real(dp), intent(out) :: row(WP_NCOL)
        real(dp) :: s, c, kt
        s = sin(theta)
        c = cos(theta)
        kt = modulus(br, t)
        row(WP_THETA) = theta
        if (br%footing == FOOTING_CIRCLE) then
            row(WP_B) = 2.0_dp * br%r * sin(0.5_dp * t)**2                 ! (W.11)
            row(WP_POLE) = br%r * seg_pole(t)                              ! (W.16)
            row(WP_AREA) = br%r * br%r * 0.5_dp * x_minus_sin(2.0_dp * t) * c   ! (W.16)
            row(WP_SETTLEMENT) = -br%r * cos(t) * s                        ! (W.16)
        else
            row(WP_B) = t
            row(WP_POLE) = br%r - 0.5_dp * t                               ! (W.23)
            row(WP_AREA) = 2.0_dp * br%alpha * t * c                       ! (W.23)
            row(WP_SETTLEMENT) = -(br%r - t) * s
        end if
        row(WP_K) = kt
        row(WP_M_FOUND) = kt * s * c * c * mom_of(br, t)                   ! (W.14), (W.23)
        row(WP_M_IMPOSED) = row(WP_M_FOUND) - br%w * br%h * s              ! (W.9)
        row(WP_FORCE) = row(WP_M_IMPOSED) / (br%h * c)                     ! (W.9)
    end subroutine uplift_row

    !> The branch function at t (see fn_*).
    function branch_eval(self, x) result(y)
        class(branch_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        real(dp) :: th, row(WP_NCOL)
        logical :: ok
        select case (self%what)
        case (fn_phi)
            y = modulus(self%br, x) * phi_of(self%br, x) - self%target
        case (fn_overturn)
            call theta_at(self%br, x, th, ok)
            y = modulus(self%br, x) * cos(th)**2 * mom_of(self%br, x) - self%br%w * self%br%h
        case default
            call theta_at(self%br, x, th, ok)
            call uplift_row(self%br, x, th, row)
            if (self%what == fn_force) then
                y = -row(WP_FORCE) / self%br%w
            else
                y = -row(WP_M_IMPOSED) / (self%br%w * self%br%r)
            end if
        end select
    end function branch_eval

    !> Peak imposed moment (N m) of a cylinder of weight x (N) minus the target.
    function cyl_peak_eval(self, x) result(y)
        class(cyl_peak_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        type(winkler_pushover_t) :: rb
        integer :: st
        self%br%w = x
        call branch_scalars(self%br, rb, st)
        y = rb%max_moment - self%target
        if (st /= SEISPULSE_SUCCESS) y = nan()
    end function cyl_peak_eval

    !> The scan of the contact variable from full contact down (descending t): n_scan
    !> uniform points, then a geometric tail towards 0.
    pure subroutine scan_points(t_max, ts)
        real(dp), intent(in) :: t_max
        real(dp), intent(out) :: ts(n_scan + n_tail)
        integer :: i
        do i = 1, n_scan
            ts(i) = t_max * real(n_scan + 1 - i, dp) / real(n_scan, dp)
        end do
        do i = 1, n_tail
            ts(n_scan + i) = ts(n_scan) * 0.5_dp**i
        end do
    end subroutine scan_points

    !> Contact variable t with k(t) Phi(t) = target (N/m^3 m^3 = N), target in
    !> [2 W, k Phi_full] (W.18): closed form (rectangle) or a root on the proven bracket
    !> (0, pi] (circle) for constant k; for varying k the largest t of the scan below
    !> which k Phi drops under the target, refined by find_root; found = .false. when no
    !> such t exists (t: the smallest of the scan) or the root is the jump of a
    !> discontinuous modulus (t: the jump).
    subroutine invert_phi(br, ts, ps, target, t, found, stat, errmsg)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: ts(:), ps(:)
        real(dp), intent(in) :: target
        real(dp), intent(out) :: t
        logical, intent(out) :: found
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(branch_fn) :: fn
        integer :: i
        stat = SEISPULSE_SUCCESS
        found = .true.
        t = br%t_max
        if (.not. br%varying) then
            if (br%footing == FOOTING_CIRCLE) then
                t = u_of_phi(target / (br%k * br%r**3))                     ! (W.18)
            else
                t = min(sqrt(target / (br%k * br%alpha)), br%t_max)         ! (W.22)
            end if
            return
        end if
        found = .false.
        if (ps(1) <= target) then
            found = ps(1) >= target
            return
        end if
        t = ts(size(ts))        ! no sign change on the scan: its smallest contact
        fn%br = br
        fn%what = fn_phi
        fn%target = target
        do i = 2, size(ts)
            if (ps(i) < target) then
                call find_root(fn, ts(i), ts(i - 1), t, stat, errmsg, &
                               fa_known=ps(i) - target, fb_known=ps(i - 1) - target)
                if (stat /= SEISPULSE_SUCCESS) return
                found = abs(fn%eval(t)) <= jump_rtol * target
                return
            end if
        end do
    end subroutine invert_phi

    !> Move t to the admissible side of a jump of k(t) Phi(t) across the target: the
    !> smallest t' >= t with k Phi >= target, by bisection against the nearest admissible
    !> scan point above t (to the last ulp; at most 200 halvings).
    subroutine admissible_end(br, ts, ps, target, t)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: ts(:), ps(:), target
        real(dp), intent(inout) :: t
        real(dp) :: lo, hi, mid
        integer :: i
        if (modulus(br, t) * phi_of(br, t) >= target) return
        hi = -1.0_dp
        do i = 1, size(ts)
            if (.not. (ts(i) > t)) exit
            if (ps(i) >= target) hi = ts(i)
        end do
        if (hi < 0.0_dp) return
        lo = t
        do i = 1, 200
            mid = lo + 0.5_dp * (hi - lo)
            if (.not. (mid > lo .and. mid < hi)) exit
            if (modulus(br, mid) * phi_of(br, mid) >= target) then
                hi = mid
            else
                lo = mid
            end if
        end do
        t = hi
    end subroutine admissible_end

    !> Scalars of the branch (W.18)-(W.19): theta_up, the end of the branch, the peaks of
    !> F/W and of M_imp, the overturning angle.
    subroutine branch_scalars(br, res, stat, errmsg, t_end_out)
        type(branch_t), intent(in) :: br
        type(winkler_pushover_t), intent(out) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(out), optional :: t_end_out
        real(dp) :: ts(n_scan + n_tail), ps(n_scan + n_tail), s_up, t_end, q
        logical :: found
        call clear_result(res)
        res%k0 = br%k
        stat = SEISPULSE_SUCCESS
        s_up = 2.0_dp * br%w / (br%k * br%phi_full)                         ! (W.10)
        if (present(t_end_out)) t_end_out = br%t_max
        if (s_up > 1.0_dp) then
            ! no uplift before pi/4: full contact up to pi/2
            res%theta_end = half_pi
            call full_peaks(br, half_pi, res)
            q = br%w * br%h / (br%k * br%i_full)
            res%theta_overturn = 0.0_dp
            if (q < 1.0_dp) res%theta_overturn = acos(sqrt(q))              ! (W.19)
            return
        end if
        res%theta_up = 0.5_dp * asin(s_up)                                  ! (W.10)
        res%theta_end = quarter_pi                                          ! (W.18)
        call scan_points(br%t_max, ts)
        call scan_values(br, ts, ps)
        ! the end of the branch, k Phi = 2 W (theta = pi/4); without an exact root (a jump of
        ! the varying modulus across 2 W) the jump itself
        call invert_phi(br, ts, ps, 2.0_dp * br%w, t_end, found, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. found) then
            ! the branch ends at a jump of the modulus (or at the smallest contact of the
            ! scan): its last admissible point, k Phi >= 2 W, is the end, below pi/4
            call admissible_end(br, ts, ps, 2.0_dp * br%w, t_end)
            call theta_at(br, t_end, q, found)
            if (found) res%theta_end = q
        end if
        if (present(t_end_out)) t_end_out = t_end
        call full_peaks(br, res%theta_up, res)
        call uplift_peak(br, t_end, fn_force, res%max_force_over_weight, res%theta_at_max, &
                         stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call uplift_peak(br, t_end, fn_moment, res%max_moment, res%theta_at_max_moment, &
                         stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        ! overturning (W.19): in full contact when M_imp <= 0 at theta_up
        q = br%w * br%h / (br%k * br%i_full)
        if (q >= cos(res%theta_up)**2) then
            res%theta_overturn = 0.0_dp
            if (q < 1.0_dp) res%theta_overturn = acos(sqrt(q))
            return
        end if
        call overturn_root(br, ts, t_end, res%theta_overturn, stat, errmsg)
    end subroutine branch_scalars

    !> k(t) Phi(t) on the scan (N).
    pure subroutine scan_values(br, ts, ps)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: ts(:)
        real(dp), intent(out) :: ps(:)
        integer :: i
        do i = 1, size(ts)
            ps(i) = modulus(br, ts(i)) * phi_of(br, ts(i))
        end do
    end subroutine scan_values

    !> Peaks of F/W and M_imp at full contact, theta in [0, theta_hi] (closed forms, W.19):
    !> F' = 0 at cos(2 theta) cos^2(theta) = q, q = h W/(k I); M_imp' = 0 at sin^2(theta) =
    !> (1 - q)/3. Sets the peaks of res (values at theta = 0 are 0).
    pure subroutine full_peaks(br, theta_hi, res)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: theta_hi
        type(winkler_pushover_t), intent(inout) :: res
        real(dp) :: q, one_minus_c, th, row(WP_NCOL)
        q = br%h * br%w / (br%k * br%i_full)
        res%max_force_over_weight = 0.0_dp
        res%theta_at_max = 0.0_dp
        res%max_moment = 0.0_dp
        res%theta_at_max_moment = 0.0_dp
        if (q >= 1.0_dp) return
        ! c = cos 2 theta = (sqrt(1 + 8 q) - 1)/2: 1 - c = 4 (1 - q)/(3 + sqrt(1 + 8 q))
        one_minus_c = 4.0_dp * (1.0_dp - q) / (3.0_dp + sqrt(1.0_dp + 8.0_dp * q))
        th = min(asin(sqrt(0.5_dp * one_minus_c)), theta_hi)
        call full_row(br, th, row)
        res%max_force_over_weight = row(WP_FORCE) / br%w
        res%theta_at_max = th
        th = min(asin(sqrt((1.0_dp - q) / 3.0_dp)), theta_hi)
        call full_row(br, th, row)
        res%max_moment = row(WP_M_IMPOSED)
        res%theta_at_max_moment = th
    end subroutine full_peaks

    !> Peak of F/W (what = fn_force) or of M_imp (fn_moment) after uplift, t in [t_end,
    !> t_max]: n_peak samples, then the bounded maximiser around the best one; kept if above
    !> the full-contact value already in (value, theta_peak).
    subroutine uplift_peak(br, t_end, what, value, theta_peak, stat, errmsg)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: t_end
        integer, intent(in) :: what
        real(dp), intent(inout) :: value, theta_peak
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(branch_fn) :: fn
        real(dp) :: t, y, best, t_best, lo, hi, tx, fx, th, scale
        integer :: i, i_best
        logical :: ok
        fn%br = br
        fn%what = what
        scale = br%w
        if (what == fn_moment) scale = br%w * br%r
        best = huge(1.0_dp)
        i_best = 0
        t_best = br%t_max
        do i = 0, n_peak
            t = t_end + (br%t_max - t_end) * real(i, dp) / real(n_peak, dp)
            y = fn%eval(t)
            if (y < best) then
                best = y
                i_best = i
                t_best = t
            end if
        end do
        lo = t_end + (br%t_max - t_end) * real(max(i_best - 1, 0), dp) / real(n_peak, dp)
        hi = t_end + (br%t_max - t_end) * real(min(i_best + 1, n_peak), dp) / real(n_peak, dp)
        call find_minimum(fn, lo, hi, tx, fx, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (fx < best) then
            best = fx
            t_best = tx
        end if
        y = -best
        if (what == fn_moment) y = y * scale
        if (y > value) then
            value = y
            call theta_at(br, t_best, th, ok)
            theta_peak = th
        end if
    end subroutine uplift_peak

    !> First zero of M_imp after uplift (W.19), scanning from full contact towards t_end:
    !> a proven bracket for constant k (Z increases with t), the first sign change of the
    !> scan for varying k; NaN if M_imp stays positive to the end of the branch.
    subroutine overturn_root(br, ts, t_end, theta, stat, errmsg)
        type(branch_t), intent(in) :: br
        real(dp), intent(in) :: ts(:), t_end
        real(dp), intent(out) :: theta
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(branch_fn) :: fn
        real(dp) :: t_hi, z_hi, t_lo, z_lo, t
        logical :: ok
        integer :: i
        stat = SEISPULSE_SUCCESS
        theta = nan()
        fn%br = br
        fn%what = fn_overturn
        t_hi = br%t_max
        z_hi = fn%eval(t_hi)
        do i = 2, size(ts) + 1
            if (i <= size(ts)) then
                t_lo = ts(i)
                if (.not. br%varying) t_lo = t_end
                if (t_lo < t_end) t_lo = t_end
            else
                t_lo = t_end
            end if
            z_lo = fn%eval(t_lo)
            if (z_lo <= 0.0_dp) then
                call find_root(fn, t_lo, t_hi, t, stat, errmsg, fa_known=z_lo, fb_known=z_hi)
                if (stat /= SEISPULSE_SUCCESS) return
                call theta_at(br, t, theta, ok)
                return
            end if
            if (t_lo <= t_end) return
            t_hi = t_lo
            z_hi = z_lo
        end do
    end subroutine overturn_root

    !> The pushover of a footing on the theta grid and its scalars (both public pushovers).
    subroutine run_pushover(footing, r, alpha, h, weight, k, theta, curve, res, stat, errmsg, &
                            k_method, reading)
        integer, intent(in) :: footing
        real(dp), intent(in) :: r, alpha, h, weight, k
        real(dp), intent(in) :: theta(:)
        real(dp), intent(out) :: curve(:, :)
        type(winkler_pushover_t), intent(out) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer, intent(in), optional :: k_method, reading
        type(branch_t) :: br
        real(dp) :: ts(n_scan + n_tail), ps(n_scan + n_tail), t, row(WP_NCOL), t_end
        integer :: i, km
        logical :: found
        call clear_result(res)
        curve = nan()
        km = K_CONSTANT
        if (present(k_method)) km = k_method
        call make_branch(footing, r, alpha, h, weight, k, km, br, stat, errmsg, reading)
        if (stat /= SEISPULSE_SUCCESS) return
        if (size(curve, 1) /= size(theta) .or. size(curve, 2) /= WP_NCOL) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'curve: shape (' &
                           //int_str(size(curve, 1))//', '//int_str(size(curve, 2)) &
                           //') must be (size(theta), WP_NCOL) = ('//int_str(size(theta)) &
                           //', '//int_str(WP_NCOL)//')')
            return
        end if
        do i = 1, size(theta)
            if (.not. finite_at_least(theta(i), 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'theta('//int_str(i) &
                               //') = '//real_str(theta(i))//': must be a finite number' &
                               //' >= 0 (rad)')
                return
            end if
        end do
        call branch_scalars(br, res, stat, errmsg, t_end)
        if (stat /= SEISPULSE_SUCCESS) return
        call scan_points(br%t_max, ts)
        call scan_values(br, ts, ps)
        curve(:, WP_THETA) = theta
        do i = 1, size(theta)
            if (ieee_is_nan(res%theta_up)) then
                if (theta(i) < half_pi) then
                    call full_row(br, theta(i), row)
                    curve(i, :) = row
                end if
            else if (theta(i) <= res%theta_up) then
                call full_row(br, theta(i), row)
                curve(i, :) = row
            else if (theta(i) <= quarter_pi) then
                ! (W.18): k(t) Phi(t) = 2 W/sin(2 theta)
                call invert_phi(br, ts, ps, 2.0_dp * br%w / sin(2.0_dp * theta(i)), t, found, &
                                stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                if (found) then
                    call uplift_row(br, t, theta(i), row)
                    curve(i, :) = row
                end if
            end if
        end do
    end subroutine run_pushover

    ! ------------------------------------------------------------------------------
    ! Segment of the circle (doc/winkler.md (W.11)-(W.17))
    ! ------------------------------------------------------------------------------

    !> Phi/r^3 = sin u - u cos u - sin^3(u)/3 for the segment of half-angle u (W.17):
    !> the series sum_{n>=2} (-1)^n c_n u^(2n+1), c_n = ((9^n - 1)/4 - 2n)/(2n+1)!, for
    !> u < 1 (the closed form cancels to u^5 (2/15)), else the closed form.
    elemental real(dp) function seg_f(u)
        real(dp), intent(in) :: u
        real(dp) :: c(2:22), p9, fac
        integer :: n
        if (u < 1.0_dp) then
            p9 = 9.0_dp
            fac = 6.0_dp
            do n = 2, 22
                p9 = p9 * 9.0_dp
                fac = fac * real((2 * n) * (2 * n + 1), dp)
                c(n) = (0.25_dp * (p9 - 1.0_dp) - real(2 * n, dp)) / fac
            end do
            seg_f = alternating_odd(c, u)
        else
            seg_f = sin(u) - u * cos(u) - sin(u)**3 / 3.0_dp
        end if
    end function seg_f

    !> (J2 - c J1)/r^4 = u/4 - sin(2u)/6 + sin(4u)/48 (W.17): the series sum_{n>=2} (-1)^n
    !> d_n u^(2n+1), d_n = 4^n (4^(n-1) - 1)/(3 (2n+1)!), for u < 1, else the closed form.
    elemental real(dp) function seg_g(u)
        real(dp), intent(in) :: u
        real(dp) :: d(2:24), p4, fac
        integer :: n
        if (u < 1.0_dp) then
            p4 = 4.0_dp
            fac = 6.0_dp
            do n = 2, 24
                p4 = p4 * 4.0_dp
                fac = fac * real((2 * n) * (2 * n + 1), dp)
                d(n) = p4 * (0.25_dp * p4 - 1.0_dp) / (3.0_dp * fac)
            end do
            seg_g = alternating_odd(d, u)
        else
            seg_g = 0.25_dp * u - sin(2.0_dp * u) / 6.0_dp + sin(4.0_dp * u) / 48.0_dp
        end if
    end function seg_g

    !> sum_{n=2}^{N} (-1)^n cf(n) u^(2n+1) by Horner's rule in u^2 (the series of (W.17)).
    pure real(dp) function alternating_odd(cf, u)
        real(dp), intent(in) :: cf(2:)
        real(dp), intent(in) :: u
        real(dp) :: x, s
        integer :: n, top
        top = ubound(cf, 1)
        x = u * u
        s = cf(top)
        do n = top - 1, 2, -1
            s = cf(n) - x * s
        end do
        alternating_odd = s * x * x * u
    end function alternating_odd

    !> Pole a/r = J1/(A0 r) = (4/3) sin^3(u)/(2u - sin 2u) (W.16); 1 at u = 0.
    elemental real(dp) function seg_pole(u)
        real(dp), intent(in) :: u
        if (u > 0.0_dp) then
            seg_pole = 4.0_dp * sin(u)**3 / (3.0_dp * x_minus_sin(2.0_dp * u))
        else
            seg_pole = 1.0_dp
        end if
    end function seg_pole

    !> 1 - a/r = (2u - sin 2u - (4/3) sin^3 u)/(2u - sin 2u) (W.16): the numerator by its
    !> series sum_{n>=2} (-1)^n e_n u^(2n+1), e_n = (9^n - 2 4^n - 1)/(2n+1)!, for u < 1
    !> (it cancels to 0.4 u^5), else the closed form 2u - sin 2u - sin u + sin(3u)/3.
    elemental real(dp) function seg_one_minus_pole(u)
        real(dp), intent(in) :: u
        real(dp) :: s, e(2:22), p9, p4, fac
        integer :: n
        if (u < 1.0_dp) then
            p9 = 9.0_dp
            p4 = 4.0_dp
            fac = 6.0_dp
            do n = 2, 22
                p9 = p9 * 9.0_dp
                p4 = p4 * 4.0_dp
                fac = fac * real((2 * n) * (2 * n + 1), dp)
                e(n) = (p9 - 2.0_dp * p4 - 1.0_dp) / fac
            end do
            s = alternating_odd(e, u)
        else
            s = 2.0_dp * u - sin(2.0_dp * u) - sin(u) + sin(3.0_dp * u) / 3.0_dp
        end if
        if (u > 0.0_dp) then
            seg_one_minus_pole = s / x_minus_sin(2.0_dp * u)
        else
            seg_one_minus_pole = 0.0_dp
        end if
    end function seg_one_minus_pole

    !> u in [0, pi] with Phi(u)/r^3 = t (W.18): safeguarded Newton on the proven bracket
    !> [0, pi] (seg_f increases: seg_f' = sin(u) (2u - sin 2u)/2 >= 0), bisection where a
    !> step leaves the bracket or does not halve; at most 200 steps. t >= pi gives pi.
    elemental real(dp) function u_of_phi(t)
        real(dp), intent(in) :: t
        real(dp) :: lo, hi, u, f, df, step, step_old
        integer :: it
        u_of_phi = pi
        if (t >= pi) return
        u_of_phi = 0.0_dp
        if (.not. (t > 0.0_dp)) return
        lo = 0.0_dp
        hi = pi
        u = min((7.5_dp * t)**0.2_dp, 0.5_dp * pi)       ! seg_f ~ (2/15) u^5
        step_old = hi - lo
        step = step_old
        do it = 1, 200
            f = seg_f(u) - t
            if (f < 0.0_dp) then
                lo = u
            else if (f > 0.0_dp) then
                hi = u
            else
                exit
            end if
            df = sin(u) * 0.5_dp * x_minus_sin(2.0_dp * u)
            step_old = step
            if (df > 0.0_dp .and. abs(2.0_dp * f) < abs(step_old * df)) then
                step = f / df
                if (u - step <= lo .or. u - step >= hi) then
                    step = u - 0.5_dp * (lo + hi)
                end if
            else
                step = u - 0.5_dp * (lo + hi)
            end if
            u = u - step
            if (abs(step) <= 2.0_dp * epsilon(1.0_dp) * u .or. &
                hi - lo <= 4.0_dp * epsilon(1.0_dp) * hi) exit
        end do
        u_of_phi = u
    end function u_of_phi

    ! ------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------

    !> (K_R/I) (1 - nu)/G (1/m) of a rectangle width x length, rotation about the axis
    !> parallel to length, by the [G91] formula of `axis` (W.25).
    pure real(dp) function kr_over_i(width, length, axis)
        real(dp), intent(in) :: width, length
        integer, intent(in) :: axis
        real(dp) :: bh, lh, i_q
        bh = 0.5_dp * min(width, length)
        lh = 0.5_dp * max(width, length)
        ! I^(-1/4), I = length width^3/12, without forming width^3 (no underflow)
        i_q = (length / 12.0_dp)**(-0.25_dp) * width**(-0.75_dp)
        if (axis == AXIS_LONG) then
            kr_over_i = i_q * (lh / bh)**grx_e * (grx_a + grx_b * bh / lh)
        else
            kr_over_i = gry_a * i_q * (lh / bh)**gry_e
        end if
    end function kr_over_i

    !> The [G91] formula a rectangle's sides select: rotation about the long axis when
    !> length >= width.
    pure integer function rect_axis(width, length)
        real(dp), intent(in) :: width, length
        rect_axis = AXIS_LONG
        if (length < width) rect_axis = AXIS_SHORT
    end function rect_axis


    !> x in [1e-30, 1e30] (scale_min, scale_max), else an error "name = x: <what> must be a
    !> finite number > 0 (<unit>), in [1e-30, 1e30]".
    subroutine check_scale(x, name, what, unit, stat, errmsg)
        real(dp), intent(in) :: x             !! the value (in `unit`)
        character(len=*), intent(in) :: name  !! the argument's name, for the message
        character(len=*), intent(in) :: what  !! what it is, for the message
        character(len=*), intent(in) :: unit  !! its unit, for the message
        integer, intent(out) :: stat          !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        if (.not. in_closed(x, scale_min, scale_max)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name//' = '//real_str(x) &
                           //': '//what//' must be a finite number > 0 ('//unit &
                           //'), in [1e-30, 1e30]')
        end if
    end subroutine check_scale

    subroutine check_soil(g_mod, nu, stat, errmsg)
        real(dp), intent(in) :: g_mod, nu
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call check_scale(g_mod, 'g_mod', 'the shear modulus G', 'Pa', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. in_open(nu, 0.0_dp, 0.5_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'nu = '//real_str(nu) &
                           //": Poisson's ratio must be a number in (0, 0.5)")
        end if
    end subroutine check_soil

    subroutine check_rect(g_mod, nu, width, length, stat, errmsg)
        real(dp), intent(in) :: g_mod, nu, width, length
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call check_soil(g_mod, nu, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(width, 'width', 'the side along the rocking direction', 'm', stat, &
                         errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(length, 'length', 'the side along the rotation axis', 'm', stat, &
                         errmsg)
    end subroutine check_rect

    subroutine check_reading(reading, stat, errmsg)
        integer, intent(in) :: reading
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (reading /= AXIS_LONG .and. reading /= AXIS_SHORT) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'reading = ' &
                           //int_str(reading)//': must be AXIS_LONG (1) or AXIS_SHORT (2)')
        end if
    end subroutine check_reading

    pure subroutine clear_result(res)
        type(winkler_pushover_t), intent(out) :: res
        res%theta_up = nan()
        res%k0 = res%theta_up
        res%max_force_over_weight = res%theta_up
        res%theta_at_max = res%theta_up
        res%max_moment = res%theta_up
        res%theta_at_max_moment = res%theta_up
        res%theta_overturn = res%theta_up
        res%theta_end = res%theta_up
    end subroutine clear_result

    elemental real(dp) function nan()
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
    end function nan

end module seispulse_winkler
