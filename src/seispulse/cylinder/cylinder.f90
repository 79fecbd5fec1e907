!> Rigid circular cylinder (solid, hollow, or any body of revolution with a given J_o) and
!> uniform rectangular block rocking on a rigid base in one vertical plane, after [AD11]
!> chapter 1 (doc/cylinder.md): geometry and inertia (Y.1)-(Y.5), frequency parameter p
!> (Y.6, rad/s) and Housner's restitution (Y.7), the static rigid pushover (Y.10)-(Y.12), the
!> equivalent cylinder of a block and the equivalent block of a cylinder (same p, same
!> M_max, a stated slenderness: Y.13-Y.15), overturning maps on dimensionless or g-Hz axes
!> (Y.16) and the overturning PGA of a pulse of given frequency.
!>
!> The planar rocking itself is that of seispulse_rocking_sim: a body is the symmetric
!> block symmetric_block(R, theta_c, J_o/(m R^2), g) (doc/rocking.md section 1), run by
!> rock_pulse / rock_record, and its maps are overturning_map with alpha = theta_c.
!> Units: m, kg, m/s^2, rad, rad/s, N, N m; `_hz` names are Hz, `_g` names in units of g.
module seispulse_cylinder
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_checks, only: finite_positive, finite_at_least, in_open, in_closed, outside
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_CONVERGENCE, set_error
    use seispulse_format, only: real_str, int_str
    use seispulse_optval, only: optval
    use seispulse_records, only: STANDARD_GRAVITY
    use seispulse_special, only: pi
    use seispulse_pulses, only: pulse_t
    use seispulse_rocking_sim, only: rocking_block_t, symmetric_block, overturning_map
    implicit none
    private

    public :: rocking_body_t
    public :: cylinder_props, block_props, body_rocking_block
    public :: equivalent_cylinder, equivalent_block
    public :: rigid_pushover, normalized_pushover
    public :: body_overturning_map, map_difference, overturning_threshold
    public :: BODY_SOLID_CYLINDER, BODY_HOLLOW_CYLINDER, BODY_CUSTOM, BODY_BLOCK
    public :: MAP_AXES_DIMENSIONLESS, MAP_AXES_DIMENSIONAL
    public :: MAP_DIFF_SAME, MAP_DIFF_ONLY_FIRST, MAP_DIFF_ONLY_SECOND, MAP_DIFF_OTHER_MODE

    integer, parameter :: BODY_SOLID_CYLINDER = 1   !! solid circular cylinder
    integer, parameter :: BODY_HOLLOW_CYLINDER = 2  !! hollow circular cylinder (inner radius)
    integer, parameter :: BODY_CUSTOM = 3           !! body of revolution with a user-given J_o
    integer, parameter :: BODY_BLOCK = 4            !! uniform rectangular block (half-width b)
    integer, parameter :: MAP_AXES_DIMENSIONLESS = 1 !! x = omega_p/p, y = a_p/(g tan theta_c)
    integer, parameter :: MAP_AXES_DIMENSIONAL = 2   !! x = f_p (Hz), y = PGA (g)
    integer, parameter :: MAP_DIFF_SAME = 0          !! same class in both maps
    integer, parameter :: MAP_DIFF_ONLY_FIRST = 1    !! only the first body (cylinder) overturns
    integer, parameter :: MAP_DIFF_ONLY_SECOND = 2   !! only the second body (block) overturns
    integer, parameter :: MAP_DIFF_OTHER_MODE = 3    !! both overturn, by different classes

    !> A rigid body on a rigid base, rocking in a vertical plane about a point of its base
    !> edge (doc/cylinder.md section 1). Build it with cylinder_props or block_props: the
    !> derived components must agree with the geometry.
    type :: rocking_body_t
        integer  :: shape = BODY_SOLID_CYLINDER  !! one of the BODY_* codes
        real(dp) :: r = 1.0_dp        !! base radius (cylinder) or half-width b (block) (m)
        real(dp) :: r_inner = 0.0_dp  !! inner radius of a hollow cylinder (m), else 0
        real(dp) :: h = 1.0_dp        !! height of the centre of mass above the base (m)
        real(dp) :: mass = 1.0_dp     !! kg
        real(dp) :: g = 9.80665_dp    !! m/s^2
        real(dp) :: theta_c           !! atan(r/h) (rad): overturning angle, slenderness
        real(dp) :: big_r             !! sqrt(r^2 + h^2) (m): pivot to centre of mass
        real(dp) :: j_o               !! about the pivot, transverse axis (kg m^2)
        real(dp) :: j_g               !! about the centre of mass, transverse axis (kg m^2)
        real(dp) :: j_axis            !! about the axis of symmetry (kg m^2); NaN if unknown
        real(dp) :: p                 !! sqrt(m g R/J_o) (rad/s)
        real(dp) :: e                 !! Housner: max(0, 1 - (2 m R^2/J_o) sin^2 theta_c)
        real(dp) :: weight            !! m g (N)
        real(dp) :: m_max             !! m g r (N m): pushover moment at theta = 0
        real(dp) :: f_uplift          !! W r/h (N): force at the CoM that starts the uplift
    end type rocking_body_t

    real(dp), parameter :: two_pi = 2.0_dp * pi
    real(dp), parameter :: half_pi = 0.5_dp * pi
    !> Threshold search: default scan size, its bounds, the default top of the scan in units
    !> of tan(theta_c), the relative width of the final bracket and the bisection budget.
    integer, parameter :: n_scan_default = 200, n_scan_min = 2, n_scan_max = 100000
    real(dp), parameter :: pga_max_factor = 20.0_dp
    real(dp), parameter :: bisect_rtol = 1.0e-6_dp
    integer, parameter :: max_bisect = 200
    !> Accepted range of r, h, mass and g (in their units), and of J_o/(m R^2): every derived
    !> quantity (J_o, p, W, M_max, the map axes) is then representable without overflow.
    real(dp), parameter :: scale_min = 1.0e-30_dp, scale_max = 1.0e30_dp

contains

    ! ------------------------------------------------------------------------------
    ! Bodies
    ! ------------------------------------------------------------------------------

    !> A circular cylinder of base radius r whose centre of mass is at height h (the
    !> half-height of a uniform cylinder), doc/cylinder.md section 2:
    !> - solid (default): J_G = m (3 r^2 + 4 h^2)/12 (Y.2), J_o = J_G + m R^2
    !>   = (5/4) m r^2 + (4/3) m h^2 (Y.3), J_axis = m r^2/2;
    !> - hollow (r_inner > 0): J_G = m (3 (r^2 + r_inner^2) + 4 h^2)/12,
    !>   J_axis = m (r^2 + r_inner^2)/2 (Y.4); r_inner = 0 is the solid cylinder;
    !> - custom (j_o given): any body of revolution with J_o about the pivot (finite,
    !>   >= m R^2), J_G = J_o - m R^2; j_axis given (finite, > 0) or NaN (unknown).
    !> Then theta_c = atan(r/h), R = sqrt(r^2 + h^2) (Y.1), p = sqrt(m g R/J_o) in rad/s
    !> (Y.6), Housner's e = max(0, 1 - (2 m R^2/J_o) sin^2 theta_c) (Y.7), W = m g,
    !> M_max = m g r and F_uplift = W r/h (Y.11). A NaN j_axis counts as not given;
    !> j_axis is only taken with j_o (solid and hollow cylinders compute theirs).
    !> mass and g are optional (defaults 1 kg and STANDARD_GRAVITY, as Python's
    !> `cylinder.props`); when one is omitted, pass body and stat by keyword.
    subroutine cylinder_props(r, h, mass, g, body, stat, errmsg, r_inner, j_o, j_axis)
        real(dp), intent(in) :: r                             !! base radius (m), > 0
        real(dp), intent(in) :: h                             !! CoM height (m), > 0
        !> mass (kg), > 0; default 1.0
        real(dp), intent(in), optional :: mass
        !> gravity (m/s^2), > 0; default STANDARD_GRAVITY (9.80665 m/s^2)
        real(dp), intent(in), optional :: g
        type(rocking_body_t), intent(out) :: body             !! the body
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> inner radius (m), in [0, r); default 0 (solid cylinder)
        real(dp), intent(in), optional :: r_inner
        !> J_o (kg m^2), >= m R^2 (custom body); default that of the solid or hollow cylinder
        real(dp), intent(in), optional :: j_o
        !> J about the axis (kg m^2), > 0; default (absent or NaN) that of the cylinder
        real(dp), intent(in), optional :: j_axis
        real(dp) :: ri, mr2
        logical :: has_axis

        real(dp) :: mass_in, g_in
        mass_in = optval(mass, 1.0_dp)
        g_in = optval(g, STANDARD_GRAVITY)
        call check_geometry(r, 'r', 'the base radius', h, mass_in, g_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        ri = 0.0_dp
        if (present(r_inner)) then
            if (outside(r_inner, 0.0_dp, r, .false., .true.)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'r_inner = ' &
                               //real_str(r_inner)//': the inner radius must be in [0, r) = [0, ' &
                               //real_str(r)//') (m)')
                return
            end if
            ri = r_inner
        end if
        has_axis = .false.
        if (present(j_axis)) has_axis = .not. ieee_is_nan(j_axis)
        body%r = r
        body%h = h
        body%mass = mass_in
        body%g = g_in
        body%big_r = hypot(r, h)                                            ! (Y.1)
        body%theta_c = atan2(r, h)                                          ! (Y.1)
        mr2 = mass_in * body%big_r**2
        if (present(j_o)) then
            if (ri > 0.0_dp) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'r_inner = ' &
                               //real_str(ri)//', j_o = '//real_str(j_o)//': give either' &
                               //' r_inner (hollow cylinder) or j_o (custom body), not both')
                return
            end if
            if (.not. in_closed(j_o, mr2, scale_max * mr2)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'j_o = '//real_str(j_o) &
                               //': must be a finite number >= m R^2 = '//real_str(mr2) &
                               //' (kg m^2; J_o = J_G + m R^2), at most 1e30 m R^2')
                return
            end if
            if (has_axis) then
                if (.not. finite_positive(j_axis)) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'j_axis = ' &
                                   //real_str(j_axis)//': must be a finite number > 0' &
                                   //' (kg m^2), or NaN if unknown')
                    return
                end if
            end if
            body%shape = BODY_CUSTOM
            body%r_inner = 0.0_dp
            body%j_o = j_o
            body%j_g = j_o - mr2
            body%j_axis = ieee_value(1.0_dp, ieee_quiet_nan)
            if (has_axis) body%j_axis = j_axis
        else
            if (has_axis) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'j_axis = ' &
                               //real_str(j_axis)//': only with j_o (custom body); solid' &
                               //' and hollow cylinders compute their own')
                return
            end if
            if (ri > 0.0_dp) then
                body%shape = BODY_HOLLOW_CYLINDER
            else
                body%shape = BODY_SOLID_CYLINDER
            end if
            body%r_inner = ri
            ! (Y.2), (Y.4): transverse diameter axis through the centre of mass
            body%j_g = mass_in * (3.0_dp * (r * r + ri * ri) + 4.0_dp * h * h) / 12.0_dp
            body%j_o = body%j_g + mr2                         ! parallel axes (Y.3)
            body%j_axis = 0.5_dp * mass_in * (r * r + ri * ri)
        end if
        call finish_body(body, body%j_o / mr2, stat, errmsg)
    end subroutine cylinder_props

    !> Uniform rectangular block of half-width b and half-height h (doc/cylinder.md (Y.5),
    !> doc/rocking.md section 1): J_o = (4/3) m R^2, J_G = m (b^2 + h^2)/3, j_axis NaN (the
    !> depth is unknown), p = sqrt(3 g/(4 R)), e = max(0, 1 - 1.5 sin^2 theta_c); the same
    !> p and e as rectangular_block(b, h, g).
    !> mass and g are optional (defaults 1 kg and STANDARD_GRAVITY, as Python's
    !> `cylinder.block_props`); when one is omitted, pass body and stat by keyword.
    subroutine block_props(b, h, mass, g, body, stat, errmsg)
        real(dp), intent(in) :: b                             !! half-width (m), > 0
        real(dp), intent(in) :: h                             !! half-height (m), > 0
        !> mass (kg), > 0; default 1.0
        real(dp), intent(in), optional :: mass
        !> gravity (m/s^2), > 0; default STANDARD_GRAVITY (9.80665 m/s^2)
        real(dp), intent(in), optional :: g
        type(rocking_body_t), intent(out) :: body             !! the block
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0

        real(dp) :: mass_in, g_in
        mass_in = optval(mass, 1.0_dp)
        g_in = optval(g, STANDARD_GRAVITY)
        call check_geometry(b, 'b', 'the half-width', h, mass_in, g_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        body%shape = BODY_BLOCK
        body%r = b
        body%r_inner = 0.0_dp
        body%h = h
        body%mass = mass_in
        body%g = g_in
        body%big_r = hypot(b, h)
        body%theta_c = atan2(b, h)
        body%j_g = mass_in * (b * b + h * h) / 3.0_dp                       ! (Y.5)
        body%j_o = (4.0_dp / 3.0_dp) * mass_in * body%big_r**2              ! (Y.5)
        body%j_axis = ieee_value(1.0_dp, ieee_quiet_nan)
        call finish_body(body, 4.0_dp / 3.0_dp, stat, errmsg)
    end subroutine block_props

    !> The rocking_block_t of seispulse_rocking_sim for the body: symmetric_block(R,
    !> theta_c, J_o/(m R^2), g), so p and e are those of the body (doc/cylinder.md section
    !> 3); `e` overrides the restitution ([0, 1]) and `linearized` selects doc/rocking.md
    !> (2.7). Run it with rock_pulse or rock_record.
    subroutine body_rocking_block(body, blk, stat, errmsg, e, linearized)
        type(rocking_body_t), intent(in) :: body              !! the body
        type(rocking_block_t), intent(out) :: blk             !! its rocking block
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(in), optional :: e                   !! restitution, [0, 1]; default body%e
        logical, intent(in), optional :: linearized           !! Eq. 2.7 (default .false.)
        call check_body(body, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_e(e, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call symmetric_block(body%big_r, body%theta_c, body%j_o / (body%mass * body%big_r**2), &
                             body%g, blk, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (present(e)) blk%e = e
        if (present(linearized)) blk%linearized = linearized
    end subroutine body_rocking_block

    ! ------------------------------------------------------------------------------
    ! Equivalence (doc/cylinder.md section 5)
    ! ------------------------------------------------------------------------------

    !> The solid cylinder equivalent to a body (usually a BODY_BLOCK) on a rigid base: the
    !> same p and the same static M_max = m g r (m_c r_c = m_b b), plus the slenderness
    !> theta_c (default: the block's own), which fixes the second unknown (Y.14):
    !> R_c = g/(p^2 j(theta_c)), j = J_o/(m R^2) = 4/3 - sin^2(theta_c)/12 (Y.13),
    !> r_c = R_c sin theta_c, h_c = R_c cos theta_c, m_c = M_max/(g r_c). Same g.
    subroutine equivalent_cylinder(block, cyl, stat, errmsg, theta_c)
        type(rocking_body_t), intent(in) :: block             !! the given body
        type(rocking_body_t), intent(out) :: cyl              !! its solid cylinder
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> slenderness (rad), (0, pi/2); default the block's own
        real(dp), intent(in), optional :: theta_c
        real(dp) :: th, s, big_r, r, jr
        call check_body(block, stat, errmsg, 'block')
        if (stat /= SEISPULSE_SUCCESS) return
        th = block%theta_c
        if (present(theta_c)) then
            if (.not. in_open(theta_c, 0.0_dp, half_pi)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'theta_c = ' &
                               //real_str(theta_c)//': must be a number in (0, pi/2) (rad)')
                return
            end if
            th = theta_c
        end if
        s = sin(th)
        jr = 4.0_dp / 3.0_dp - s * s / 12.0_dp                              ! (Y.13)
        big_r = block%g / (block%p**2 * jr)                                 ! (Y.14)
        r = big_r * s
        call cylinder_props(r, big_r * cos(th), block%m_max / (block%g * r), block%g, cyl, &
                            stat, errmsg)
    end subroutine equivalent_cylinder

    !> The uniform block equivalent to a body (usually a cylinder): the same p, so
    !> R_b = 3 g/(4 p^2), the slenderness alpha (default: the body's theta_c), b = R_b
    !> sin(alpha), h = R_b cos(alpha), and the same M_max: m_b = M_max/(g b) (Y.15). Same g.
    subroutine equivalent_block(cyl, block, stat, errmsg, alpha)
        type(rocking_body_t), intent(in) :: cyl               !! the given body
        type(rocking_body_t), intent(out) :: block            !! its uniform block
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> slenderness (rad), (0, pi/2); default the body's theta_c
        real(dp), intent(in), optional :: alpha
        real(dp) :: al, big_r, b
        call check_body(cyl, stat, errmsg, 'cyl')
        if (stat /= SEISPULSE_SUCCESS) return
        al = cyl%theta_c
        if (present(alpha)) then
            if (.not. in_open(alpha, 0.0_dp, half_pi)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'alpha = ' &
                               //real_str(alpha)//': must be a number in (0, pi/2) (rad)')
                return
            end if
            al = alpha
        end if
        big_r = 0.75_dp * cyl%g / cyl%p**2                                  ! (Y.15)
        b = big_r * sin(al)
        call block_props(b, big_r * cos(al), cyl%m_max / (cyl%g * b), cyl%g, block, stat, &
                         errmsg)
    end subroutine equivalent_block

    ! ------------------------------------------------------------------------------
    ! Static pushover (doc/cylinder.md section 4)
    ! ------------------------------------------------------------------------------

    !> Static pushover on a rigid base at the tilt theta (rad, |theta| <= pi/2; theta < 0
    !> is the mirror image, rotation about the other edge, with F and M of opposite sign):
    !> the horizontal force at the centre of mass that holds the body, F = W tan(theta_c -
    !> |theta|) (N), and the moment about the pivot M = W R sin(theta_c - |theta|) = W (r cos
    !> theta - h sin theta) (N m) (Y.10). stable = |theta| <= theta_c; beyond theta_c, F and
    !> M have the opposite sign: the body falls on its own (not an equilibrium).
    subroutine rigid_pushover(body, theta, force, moment, stable, stat, errmsg)
        type(rocking_body_t), intent(in) :: body              !! the body
        real(dp), intent(in) :: theta                         !! tilt (rad), |theta| <= pi/2
        real(dp), intent(out) :: force                        !! F (N), at the CoM
        real(dp), intent(out) :: moment                       !! M (N m), about the pivot
        logical, intent(out) :: stable                        !! |theta| <= theta_c
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: t, s
        force = ieee_value(1.0_dp, ieee_quiet_nan)
        moment = force
        stable = .false.
        call check_body(body, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. in_closed(theta, -half_pi, half_pi)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'theta = '//real_str(theta) &
                           //': the tilt must be a number in [-pi/2, pi/2] (rad)')
            return
        end if
        t = abs(theta)
        s = 1.0_dp
        if (theta < 0.0_dp) s = -1.0_dp
        force = s * body%weight * tan(body%theta_c - t)                     ! (Y.10)
        moment = s * body%weight * body%big_r * sin(body%theta_c - t)       ! (Y.10)
        stable = t <= body%theta_c
    end subroutine rigid_pushover

    !> Normalized rigid pushover M/(m g r) = sin(theta_c (1 - u))/sin(theta_c) at
    !> u = theta/theta_c (Y.12): 1 at u = 0, 0 at u = 1, 1/(2 cos(theta_c/2)) at u = 1/2.
    !> NaN unless theta_c is in (0, pi/2) and u is finite.
    elemental function normalized_pushover(theta_c, u) result(m_ratio)
        real(dp), intent(in) :: theta_c  !! overturning angle atan(r/h) (rad), in (0, pi/2)
        real(dp), intent(in) :: u        !! theta/theta_c
        real(dp) :: m_ratio              !! M/(m g r)
        if (in_open(theta_c, 0.0_dp, half_pi) .and. in_open(u, -huge(u), huge(u))) then
            m_ratio = sin(theta_c * (1.0_dp - u)) / sin(theta_c)
        else
            m_ratio = ieee_value(1.0_dp, ieee_quiet_nan)
        end if
    end function normalized_pushover

    ! ------------------------------------------------------------------------------
    ! Overturning (doc/cylinder.md section 6)
    ! ------------------------------------------------------------------------------

    !> Overturning map of the body under a pulse family: classes(i, j) for y(i) and x(j)
    !> (0 safe, 1 overturns without impact, 2 after one impact, 3 after more, -1 undecided),
    !> from overturning_map of seispulse_rocking_sim with alpha = theta_c and e = body%e (or
    !> `e`). Axes (Y.16): MAP_AXES_DIMENSIONLESS: x = omega_p/p, y = a_p/(g tan theta_c);
    !> MAP_AXES_DIMENSIONAL: x = f_p (Hz), y = PGA (g), taken to omega_p/p = 2 pi f_p/p and
    !> a_p/(g tan theta_c) = PGA/tan(theta_c). f_p = omega_p/(2 pi) as overturning_map
    !> defines omega_p: 1/T_p of the pulse duration (the period of the cycle pulses, the
    !> length of the others, t_d of the exponential) and f_p of the Ricker wavelet. The PGA
    !> is the pulse's amp: every kind the map takes peaks at |a_g| = amp (the exponential at
    !> its lobe centre, the Ricker wavelet at t0; checked in test/test_cylinder.f90).
    !> template, linearized, rtol and the vertical acceleration a_v = kv a_g (doc/rocking.md
    !> section 7): as overturning_map.
    subroutine body_overturning_map(body, kind, x, y, axes, classes, stat, errmsg, template, &
                                    linearized, e, rtol, kv)
        type(rocking_body_t), intent(in) :: body              !! the body
        integer, intent(in) :: kind                           !! PULSE_* code (not PULSE_MP)
        real(dp), intent(in) :: x(:)                          !! frequencies (axes), > 0
        real(dp), intent(in) :: y(:)                          !! amplitudes (axes), >= 0
        integer, intent(in) :: axes                           !! MAP_AXES_* code
        integer, intent(out) :: classes(:, :)                 !! size(y) x size(x)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> shape parameters of the kind; absent: pulse_t defaults (as overturning_map)
        type(pulse_t), intent(in), optional :: template
        logical, intent(in), optional :: linearized           !! Eq. 2.7 (default .false.)
        real(dp), intent(in), optional :: e                   !! restitution, [0, 1]; default body%e
        real(dp), intent(in), optional :: rtol                !! step tolerance (default 1e-12)
        real(dp), intent(in), optional :: kv                  !! a_v/a_g, vertical (default 0)
        real(dp) :: fr(size(x)), ar(size(y)), ee, tan_c
        integer :: i, j

        classes = -1
        call check_body(body, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_e(e, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (axes /= MAP_AXES_DIMENSIONLESS .and. axes /= MAP_AXES_DIMENSIONAL) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'axes = '//int_str(axes) &
                           //': must be 1 (MAP_AXES_DIMENSIONLESS) or 2 (MAP_AXES_DIMENSIONAL)')
            return
        end if
        ee = body%e
        if (present(e)) ee = e
        tan_c = tan(body%theta_c)
        do j = 1, size(x)
            fr(j) = 0.0_dp
            if (finite_positive(x(j))) then
                fr(j) = x(j)
                if (axes == MAP_AXES_DIMENSIONAL) then
                    fr(j) = 0.0_dp
                    if (quotient_fits(x(j), body%p / 8.0_dp)) fr(j) = two_pi * x(j) / body%p
                end if                                                      ! (Y.16)
            end if
            if (.not. finite_positive(fr(j))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'x('//int_str(j) &
                               //') = '//real_str(x(j))//': must be a finite number > 0 (' &
                               //axis_unit(axes, 'x')//')')
                return
            end if
        end do
        do i = 1, size(y)
            ar(i) = -1.0_dp
            if (finite_at_least(y(i), 0.0_dp)) then
                ar(i) = y(i)
                if (axes == MAP_AXES_DIMENSIONAL) then
                    ar(i) = -1.0_dp
                    if (quotient_fits(y(i), tan_c)) ar(i) = y(i) / tan_c    ! (Y.16)
                end if
            end if
            if (.not. finite_at_least(ar(i), 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'y('//int_str(i) &
                               //') = '//real_str(y(i))//': must be a finite number >= 0 (' &
                               //axis_unit(axes, 'y')//')')
                return
            end if
        end do
        call overturning_map(body%theta_c, ee, kind, fr, ar, classes, stat, errmsg, &
                             linearized=linearized, template=template, rtol=rtol, kv=kv)
    end subroutine body_overturning_map

    !> Cell-by-cell comparison of two class maps of equal shape (classes of
    !> body_overturning_map, -1..3): MAP_DIFF_SAME where the classes agree,
    !> MAP_DIFF_ONLY_FIRST where only classes_a overturns (> 0), MAP_DIFF_ONLY_SECOND where
    !> only classes_b does, MAP_DIFF_OTHER_MODE where both overturn by different classes;
    !> -1 where either cell is undecided (-1).
    subroutine map_difference(classes_a, classes_b, diff, stat, errmsg)
        integer, intent(in) :: classes_a(:, :)                !! first map (cylinder)
        integer, intent(in) :: classes_b(:, :)                !! second map (block)
        integer, intent(out) :: diff(:, :)                    !! MAP_DIFF_* codes, same shape
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: i, j, a, b
        diff = -1
        stat = SEISPULSE_SUCCESS
        if (any(shape(classes_b) /= shape(classes_a)) &
            .or. any(shape(diff) /= shape(classes_a))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'classes_b, diff: must have' &
                           //' the shape of classes_a, '//int_str(size(classes_a, 1))//' x ' &
                           //int_str(size(classes_a, 2)))
            return
        end if
        do j = 1, size(classes_a, 2)
            do i = 1, size(classes_a, 1)
                a = classes_a(i, j)
                b = classes_b(i, j)
                if (a < -1 .or. a > 3 .or. b < -1 .or. b > 3) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'classes_a(' &
                                   //int_str(i)//', '//int_str(j)//') = '//int_str(a) &
                                   //', classes_b(...) = '//int_str(b)//': classes are' &
                                   //' -1 (undecided), 0 (safe) or 1..3 (overturns)')
                    diff = -1
                    return
                end if
                if (a < 0 .or. b < 0) then
                    diff(i, j) = -1
                else if (a == b) then
                    diff(i, j) = MAP_DIFF_SAME
                else if (b == 0) then
                    diff(i, j) = MAP_DIFF_ONLY_FIRST
                else if (a == 0) then
                    diff(i, j) = MAP_DIFF_ONLY_SECOND
                else
                    diff(i, j) = MAP_DIFF_OTHER_MODE
                end if
            end do
        end do
    end subroutine map_difference

    !> Smallest PGA (g) that overturns the body under a pulse of the kind with frequency
    !> freq_hz(k) (Hz; f_p as in body_overturning_map; template as in overturning_map):
    !> a geometric scan of n_scan amplitudes (default 200, at least 2) from the uplift
    !> threshold, PGA = tan(theta_c) (theta_c in the linearized model: no uplift, safe), up
    !> to pga_max_g (default 20 tan(theta_c)), stopped at the first amplitude that overturns;
    !> then bisection of that safe -> overturn bracket to a relative width of 1e-6, returning
    !> its upper end (a PGA that overturns). +inf when nothing up to pga_max_g overturns.
    !> Safe islands above the first overturning amplitude are not reported; an overturning
    !> interval narrower than the scan step may be missed. Each amplitude is one cell of
    !> overturning_map (e: body%e unless given; linearized, rtol as there). An undecided
    !> cell stops the search with SEISPULSE_NO_CONVERGENCE (pga_g(k) NaN from there on).
    subroutine overturning_threshold(body, kind, freq_hz, pga_g, stat, errmsg, template, &
                                     pga_max_g, n_scan, e, linearized, rtol)
        type(rocking_body_t), intent(in) :: body              !! the body
        integer, intent(in) :: kind                           !! PULSE_* code (not PULSE_MP)
        real(dp), intent(in) :: freq_hz(:)                    !! pulse frequencies f_p (Hz), > 0
        real(dp), intent(out) :: pga_g(:)                     !! overturning PGA (g), size(freq_hz)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> shape parameters of the kind; absent: pulse_t defaults (as overturning_map)
        type(pulse_t), intent(in), optional :: template
        !> top of the scan (g); default 20 tan(theta_c)
        real(dp), intent(in), optional :: pga_max_g
        integer, intent(in), optional :: n_scan               !! scan size, default 200
        real(dp), intent(in), optional :: e                   !! restitution, [0, 1]; default body%e
        logical, intent(in), optional :: linearized           !! Eq. 2.7 (default .false.)
        real(dp), intent(in), optional :: rtol                !! step tolerance (default 1e-12)
        real(dp) :: ee, tan_c, lo0, top, ratio, fr, lo, hi, mid
        integer :: n, k, i, it, cls
        logical :: lin, found

        pga_g = ieee_value(1.0_dp, ieee_quiet_nan)
        call check_body(body, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_e(e, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (size(pga_g) /= size(freq_hz)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pga_g: must have the size' &
                           //' of freq_hz, '//int_str(size(freq_hz)))
            return
        end if
        ee = body%e
        if (present(e)) ee = e
        lin = .false.
        if (present(linearized)) lin = linearized
        tan_c = tan(body%theta_c)
        ! uplift threshold in g (doc/rocking.md (2.3); alpha in the linearized model)
        lo0 = tan_c
        if (lin) lo0 = body%theta_c
        top = pga_max_factor * tan_c
        if (present(pga_max_g)) then
            if (.not. in_open(pga_max_g, lo0, scale_max)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pga_max_g = ' &
                               //real_str(pga_max_g)//': must be in (uplift threshold, 1e30)' &
                               //' = ('//real_str(lo0)//', 1e30) (g)')
                return
            end if
            top = pga_max_g
        end if
        n = n_scan_default
        if (present(n_scan)) then
            if (n_scan < n_scan_min .or. n_scan > n_scan_max) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'n_scan = ' &
                               //int_str(n_scan)//': must be in [2, 100000]')
                return
            end if
            n = n_scan
        end if
        do k = 1, size(freq_hz)
            found = finite_positive(freq_hz(k))
            if (found) found = quotient_fits(freq_hz(k), body%p / 8.0_dp)
            if (found) found = finite_positive(two_pi * freq_hz(k) / body%p)
            if (.not. found) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'freq_hz(' &
                               //int_str(k)//') = '//real_str(freq_hz(k)) &
                               //': must be a finite number > 0 (Hz)')
                return
            end if
        end do
        ratio = log(top / lo0)
        do k = 1, size(freq_hz)
            fr = two_pi * freq_hz(k) / body%p                               ! (Y.16)
            found = .false.
            lo = lo0
            hi = lo0
            do i = 1, n
                if (i == n) then
                    hi = top
                else
                    hi = lo0 * exp(ratio * real(i - 1, dp) / real(n - 1, dp))
                end if
                call one_cell(hi, cls)
                if (stat /= SEISPULSE_SUCCESS) return
                if (cls > 0) then
                    found = .true.
                    exit
                end if
                lo = hi
            end do
            if (.not. found) then
                pga_g(k) = ieee_value(1.0_dp, ieee_positive_inf)
                cycle
            end if
            if (i == 1) then
                ! cannot happen (no uplift at the threshold); report the amplitude itself
                pga_g(k) = hi
                cycle
            end if
            do it = 1, max_bisect
                if (hi - lo <= bisect_rtol * hi) exit
                mid = 0.5_dp * (lo + hi)
                if (.not. (mid > lo .and. mid < hi)) exit
                call one_cell(mid, cls)
                if (stat /= SEISPULSE_SUCCESS) return
                if (cls > 0) then
                    hi = mid
                else
                    lo = mid
                end if
            end do
            pga_g(k) = hi
        end do

    contains

        !> Class of the amplitude a (g) at the frequency ratio fr; -1 is an error.
        subroutine one_cell(a, c)
            real(dp), intent(in) :: a
            integer, intent(out) :: c
            integer :: cl(1, 1)
            call overturning_map(body%theta_c, ee, kind, [fr], [a / tan_c], cl, stat, errmsg, &
                                 linearized=linearized, template=template, rtol=rtol)
            c = cl(1, 1)
            if (stat /= SEISPULSE_SUCCESS) return
            if (c < 0) then
                call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, 'freq_hz(' &
                               //int_str(k)//') = '//real_str(freq_hz(k))//', PGA = ' &
                               //real_str(a)//' g: the run stayed undecided within its' &
                               //' step budget; no proven bracket')
            end if
        end subroutine one_cell

    end subroutine overturning_threshold

    ! ------------------------------------------------------------------------------
    ! Private
    ! ------------------------------------------------------------------------------

    !> Check the half-size, h, mass and g of a body.
    subroutine check_geometry(r, r_name, r_what, h, mass, g, stat, errmsg)
        real(dp), intent(in) :: r, h, mass, g
        character(len=*), intent(in) :: r_name, r_what
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. in_scale(r)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, r_name//' = '//real_str(r) &
                           //': '//r_what//' must be a finite number > 0, in [1e-30, 1e30] (m)')
        else if (.not. in_scale(h)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'h = '//real_str(h) &
                           //': the height of the centre of mass must be a finite number > 0,' &
                           //' in [1e-30, 1e30] (m)')
        else if (.not. in_scale(mass)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'mass = '//real_str(mass) &
                           //': must be a finite number > 0, in [1e-30, 1e30] (kg)')
        else if (.not. in_scale(g)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//real_str(g) &
                           //': must be a finite number > 0, in [1e-30, 1e30] (m/s^2)')
        end if
    end subroutine check_geometry

    !> p and e from symmetric_block with I_o/(m R^2) = io (Y.6, Y.7), then W, M_max,
    !> F_uplift (Y.11); an overflow of the derived values is reported.
    subroutine finish_body(body, io, stat, errmsg)
        type(rocking_body_t), intent(inout) :: body
        real(dp), intent(in) :: io
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(rocking_block_t) :: blk
        call symmetric_block(body%big_r, body%theta_c, io, body%g, blk, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        body%p = blk%p                                                      ! (Y.6)
        body%e = blk%e                                                      ! (Y.7)
        body%weight = body%mass * body%g
        body%m_max = body%weight * body%r                                   ! (Y.11)
        body%f_uplift = body%weight * (body%r / body%h)                     ! (Y.11)
        call check_body(body, stat, errmsg)
    end subroutine finish_body

    !> A body's components must be usable (built by cylinder_props or block_props and
    !> representable: no overflow); the message names the component.
    subroutine check_body(body, stat, errmsg, name)
        type(rocking_body_t), intent(in) :: body
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        character(len=*), intent(in), optional :: name
        character(len=:), allocatable :: nm, bad, range
        stat = SEISPULSE_SUCCESS
        nm = 'body'
        if (present(name)) nm = name
        bad = ''
        range = 'a finite number > 0'
        if (body%shape < BODY_SOLID_CYLINDER .or. body%shape > BODY_BLOCK) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, nm//'%shape = ' &
                           //int_str(body%shape)//': must be a BODY_* code, 1..4')
            return
        end if
        if (.not. in_scale(body%r)) then
            bad = 'r'
            range = 'in [1e-30, 1e30]'
        else if (.not. in_scale(body%h)) then
            bad = 'h'
            range = 'in [1e-30, 1e30]'
        else if (.not. in_scale(body%mass)) then
            bad = 'mass'
            range = 'in [1e-30, 1e30]'
        else if (.not. in_scale(body%g)) then
            bad = 'g'
            range = 'in [1e-30, 1e30]'
        else if (.not. in_open(body%theta_c, 0.0_dp, half_pi)) then
            bad = 'theta_c'
            range = 'in (0, pi/2)'
        else if (.not. in_closed(body%big_r, scale_min, 2.0_dp * scale_max)) then
            bad = 'big_r'
            range = 'in [1e-30, 2e30]'
        else if (.not. in_closed(body%j_o, body%mass * body%big_r**2, &
                                 scale_max * body%mass * body%big_r**2)) then
            bad = 'j_o'
            range = 'in [m R^2, 1e30 m R^2]'
        else if (.not. finite_positive(body%p)) then
            bad = 'p'
        else if (.not. in_closed(body%e, 0.0_dp, 1.0_dp)) then
            bad = 'e'
            range = 'in [0, 1]'
        else if (.not. finite_positive(body%weight)) then
            bad = 'weight'
        else if (.not. finite_positive(body%m_max)) then
            bad = 'm_max'
        end if
        if (len(bad) > 0) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, nm//'%'//bad//': must be ' &
                           //range//' (build the body with cylinder_props or block_props;' &
                           //' the values must not overflow)')
        end if
    end subroutine check_body

    !> x is finite and in [1e-30, 1e30].
    elemental logical function in_scale(x)
        real(dp), intent(in) :: x
        in_scale = in_closed(x, scale_min, scale_max)
    end function in_scale

    !> a/b (a >= 0, b > 0 finite) is representable: its binary exponent stays below the
    !> largest (no overflow; the quotient itself is not formed).
    elemental logical function quotient_fits(a, b)
        real(dp), intent(in) :: a, b
        quotient_fits = exponent(a) - exponent(b) < maxexponent(a) - 2
    end function quotient_fits

    !> An optional restitution must be in [0, 1].
    subroutine check_e(e, stat, errmsg)
        real(dp), intent(in), optional :: e
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. present(e)) return
        if (.not. in_closed(e, 0.0_dp, 1.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'e = '//real_str(e) &
                           //': the coefficient of restitution must be in [0, 1]')
        end if
    end subroutine check_e

    !> Unit of a map axis for messages.
    pure function axis_unit(axes, which) result(u)
        integer, intent(in) :: axes
        character(len=*), intent(in) :: which
        character(len=len_trim(axis_unit_text(axes, which))) :: u
        u = axis_unit_text(axes, which)
    end function axis_unit

    !> axis_unit(axes, which) padded with blanks.
    pure function axis_unit_text(axes, which) result(u)
        integer, intent(in) :: axes
        character(len=*), intent(in) :: which
        character(len=64) :: u
        if (axes == MAP_AXES_DIMENSIONAL) then
            if (which == 'x') then
                u = 'f_p, Hz'
            else
                u = 'PGA, g'
            end if
        else
            if (which == 'x') then
                u = 'omega_p/p'
            else
                u = 'a_p/(g tan theta_c)'
            end if
        end if
    end function axis_unit_text

end module seispulse_cylinder
