!> The side-by-side table of seismic thrusts on one retaining wall that a design report
!> needs: yielding-wall rules (Coulomb static, Mononobe-Okabe per EN 1998-5 Annex E,
!> Seed-Whitman) next to non-yielding-wall rules (Wood, EN 1998-5 rigid wall) and the
!> elastodynamic solutions (Veletsos-Younan series, one-term solution), each with its
!> point of application and base moment; and the pressure distributions against depth.
!>
!> Accelerations: the yielding-wall rows use kh, kv (EN 1998-5: kh = alpha S/r); the
!> non-yielding rows use the ground acceleration alpha_s = ag S/g (no r), with
!> rho Xg = gamma alpha_s, so an elastic thrust q (in rho Xg H^2) is q gamma alpha_s H^2.
!> The elastic solutions give the dynamic increment only, for a dry (total-stress)
!> backfill; the water case enters the EN 1998-5 rows only.
module seispulse_wall_table
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_checks, only: outside
    use seispulse_format, only: real_str, int_str
    use seispulse_walls_vy, only: vy_rigid, vy_pressure
    use seispulse_walls_one_term, only: one_term, one_term_t, one_term_pressure, WALL_SHAPE_SINE, &
                                        WALL_SHAPE_POWER
    use seispulse_codes, only: ec8_thrust, ec8_thrust_t, ec8_rigid_thrust, &
                               seed_whitman_increment, wood_thrust, WATER_DRY
    implicit none
    private

    public :: wall_case_t, wall_case_default, wall_comparison, wall_pressure_profile, &
              wall_row_label, WALL_ROWS, WALL_PROFILE_COLUMNS, ROW_STATIC, ROW_MO_TOTAL, &
              ROW_MO_INCREMENT, ROW_SEED_WHITMAN, ROW_WOOD, ROW_EC8_RIGID, ROW_VY, ROW_ONE_TERM

    !> Rows of the comparison, in this order.
    integer, parameter :: ROW_STATIC = 1        !! static active thrust (Coulomb, kh = kv = 0)
    integer, parameter :: ROW_MO_TOTAL = 2      !! EN 1998-5 E.1 total (soil + water), critical kv
    integer, parameter :: ROW_MO_INCREMENT = 3  !! its dynamic soil increment
    integer, parameter :: ROW_SEED_WHITMAN = 4  !! Seed & Whitman (1970) increment, 3/8 kh gamma H^2
    integer, parameter :: ROW_WOOD = 5          !! Wood (1973) rigid wall, alpha_s gamma H^2
    integer, parameter :: ROW_EC8_RIGID = 6     !! EN 1998-5 rigid wall, alpha S gamma H^2 at H/2
    integer, parameter :: ROW_VY = 7            !! Veletsos & Younan (1994a) series
    integer, parameter :: ROW_ONE_TERM = 8      !! one-term solution (shape, n, d_theta, L/H)
    integer, parameter :: WALL_ROWS = 8
    !> Columns of the pressure profile: static active, M-O increment, EN 1998-5 rigid,
    !> Veletsos-Younan |p|, one-term |p| (kPa).
    integer, parameter :: WALL_PROFILE_COLUMNS = 5

    real(dp), parameter :: vy_table_tol = 1.0e-14_dp   ! tables print 16 digits

    !> One wall and its seismic input (SI: m, kN/m3, degrees).
    type :: wall_case_t
        real(dp) :: height = 0.0_dp            !! wall height H, m (> 0)
        real(dp) :: gamma = 0.0_dp             !! unit weight of the backfill, kN/m3 (> 0)
        real(dp) :: phi_deg = 0.0_dp           !! friction angle phi', degrees, (0, 90)
        real(dp) :: wall_friction_deg = 0.0_dp !! soil-wall friction angle delta, degrees
        real(dp) :: psi_deg = 90.0_dp          !! back face to the horizontal, deg (90 = vertical)
        real(dp) :: beta_deg = 0.0_dp          !! backfill slope, degrees
        real(dp) :: gamma_phi = 1.0_dp         !! partial factor on tan(phi') and tan(delta)
        integer :: water = WATER_DRY           !! EN 1998-5 water case (seispulse_codes WATER_*)
        real(dp) :: gamma_w = 9.81_dp          !! unit weight of water, kN/m3
        real(dp) :: gamma_d = 0.0_dp           !! dry unit weight (permeable case), kN/m3
        real(dp) :: kh = 0.0_dp                !! horizontal seismic coefficient (yielding rows)
        real(dp) :: kv = 0.0_dp                !! |kv|, vertical coefficient; both signs checked
        real(dp) :: alpha_s = 0.0_dp           !! ag S/g, acceleration of the non-yielding rows
        real(dp) :: nu = 0.3_dp                !! Poisson's ratio of the soil, [0, 0.5)
        real(dp) :: delta = 0.1_dp             !! loss factor of the soil, G* = G(1 + i delta)
        real(dp) :: omega_ratio = 0.0_dp       !! omega/omega_ref, elastic rows (0: pseudo-static)
        integer :: shape = 0                   !! SHAPE_*; 0: sine if n = 0, else power
        real(dp) :: n = 0.0_dp                 !! stiffness exponent, G = G_H (depth/H)^n
        real(dp) :: d_theta = 0.0_dp           !! base flexibility H^2 G_H/K_R (one-term row)
        !> distance to a second wall over H (one-term row); a single wall is +Infinity, which
        !> a default initializer cannot write: start from wall_case_default()
        real(dp) :: l_over_h = huge(1.0_dp)
    end type wall_case_t

contains

    !> A case with the defaults above and L/H = +Infinity (a single wall).
    pure function wall_case_default() result(c)
        type(wall_case_t) :: c
        c%l_over_h = ieee_value(1.0_dp, ieee_positive_inf)
    end function wall_case_default

    !> Label of comparison row `row` (1..WALL_ROWS), for tables.
    pure function wall_row_label(row) result(label)
        integer, intent(in) :: row  !! ROW_*
        character(len=len_trim(wall_row_label_text(row))) :: label
        label = wall_row_label_text(row)
    end function wall_row_label

    !> wall_row_label(row) padded with blanks.
    pure function wall_row_label_text(row) result(label)
        integer, intent(in) :: row
        character(len=64) :: label
        select case (row)
        case (ROW_STATIC)
            label = 'static active (Coulomb)'
        case (ROW_MO_TOTAL)
            label = 'Mononobe-Okabe total, EN 1998-5 E.1'
        case (ROW_MO_INCREMENT)
            label = 'Mononobe-Okabe dynamic increment'
        case (ROW_SEED_WHITMAN)
            label = 'Seed-Whitman increment (3/4 kh)'
        case (ROW_WOOD)
            label = 'Wood (1973) rigid wall'
        case (ROW_EC8_RIGID)
            label = 'EN 1998-5 rigid wall'
        case (ROW_VY)
            label = 'Veletsos-Younan rigid wall'
        case (ROW_ONE_TERM)
            label = 'one-term solution'
        case default
            label = 'row '//int_str(row)
        end select
    end function wall_row_label_text

    !> The comparison table: thrust (kN/m), height of its point of application above
    !> the base (m) and base moment (kNm/m) for every row ROW_*.
    !>
    !> The Mononobe-Okabe rows take the sign of kv that gives the larger total thrust
    !> (`kv_used`). The elastic rows report |Q| and h = |M|/|Q| H.
    subroutine wall_comparison(c, thrust, z, moment, kv_used, stat, errmsg)
        type(wall_case_t), intent(in) :: c                  !! the wall
        real(dp), intent(out) :: thrust(WALL_ROWS)          !! kN/m per row
        real(dp), intent(out) :: z(WALL_ROWS)               !! m above the base per row
        real(dp), intent(out) :: moment(WALL_ROWS)          !! kNm/m about the base per row
        real(dp), intent(out) :: kv_used                    !! signed kv of the M-O rows
        integer, intent(out) :: stat                        !! SEISPULSE_* status
        character(len=*), intent(inout), optional :: errmsg !! message naming the parameter
        type(ec8_thrust_t) :: mo
        type(one_term_t) :: ot
        complex(dp) :: q, m
        real(dp) :: h_ratio, scale
        thrust = 0.0_dp
        z = 0.0_dp
        moment = 0.0_dp
        kv_used = 0.0_dp
        call check_case(c, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return

        call critical_mo(c, mo, kv_used, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        thrust(ROW_STATIC) = mo%e_static
        z(ROW_STATIC) = mo%z_static
        thrust(ROW_MO_TOTAL) = mo%total
        z(ROW_MO_TOTAL) = mo%z_total
        thrust(ROW_MO_INCREMENT) = mo%e_dynamic
        z(ROW_MO_INCREMENT) = mo%z_dynamic
        call seed_whitman_increment(c%kh, c%gamma, c%height, thrust(ROW_SEED_WHITMAN), &
                                    z(ROW_SEED_WHITMAN), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call wood_thrust(c%alpha_s, c%gamma, c%height, thrust(ROW_WOOD), z(ROW_WOOD), stat, &
                         errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call ec8_rigid_thrust(c%alpha_s, c%gamma, c%height, thrust(ROW_EC8_RIGID), &
                              z(ROW_EC8_RIGID), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return

        ! elastic rows: q in rho Xg H^2 with rho Xg = gamma alpha_s
        scale = c%gamma*c%alpha_s*c%height**2
        call vy_rigid(c%omega_ratio, c%delta, c%nu, vy_table_tol, q, m, h_ratio, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        thrust(ROW_VY) = abs(q)*scale
        z(ROW_VY) = h_ratio*c%height
        call one_term(c%omega_ratio, c%delta, c%nu, one_term_shape_of(c), c%n, c%d_theta, &
                      c%l_over_h, ot, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        thrust(ROW_ONE_TERM) = abs(ot%q)*scale
        z(ROW_ONE_TERM) = ot%h_ratio*c%height
        moment = thrust*z
    end subroutine wall_comparison

    !> Pressures against depth (kPa), columns: static active earth pressure K gamma* z;
    !> the M-O dynamic increment spread uniformly (resultant at H/2); EN 1998-5 rigid
    !> wall alpha S gamma H (uniform); |p| of Veletsos-Younan and of the one-term
    !> solution. Water pressures are not included.
    subroutine wall_pressure_profile(c, depth, p, stat, errmsg)
        type(wall_case_t), intent(in) :: c                  !! the wall
        real(dp), intent(in) :: depth(:)                    !! depth below the top, m, in [0, H]
        real(dp), intent(out) :: p(:, :)                    !! size(depth) x 5, kPa
        integer, intent(out) :: stat                        !! SEISPULSE_* status
        character(len=*), intent(inout), optional :: errmsg !! message naming the parameter
        type(ec8_thrust_t) :: mo
        complex(dp), allocatable :: pc(:)
        real(dp), allocatable :: y(:)
        real(dp) :: kv_used, scale
        integer :: i
        p = 0.0_dp
        call check_case(c, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (size(p, 1) /= size(depth) .or. size(p, 2) /= WALL_PROFILE_COLUMNS) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'p: must be size(depth) x '// &
                           int_str(WALL_PROFILE_COLUMNS))
            return
        end if
        do i = 1, size(depth)
            if (outside(depth(i), 0.0_dp, c%height, .false., .false.)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'depth('//int_str(i)// &
                               ') = '//real_str(depth(i))//': must lie in [0, H] (m)')
                return
            end if
        end do
        call critical_mo(c, mo, kv_used, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        ! static: the Coulomb thrust 1/2 K gamma* H^2 is the resultant of K gamma* z
        p(:, 1) = 2.0_dp*mo%e_static/c%height**2*depth
        p(:, 2) = mo%e_dynamic/c%height
        p(:, 3) = c%alpha_s*c%gamma*c%height
        scale = c%gamma*c%alpha_s*c%height
        allocate(y(size(depth)), pc(size(depth)))
        ! the solutions measure y up from the base
        y = min(max(1.0_dp - depth/c%height, 0.0_dp), 1.0_dp)
        call vy_pressure(c%omega_ratio, c%delta, c%nu, y, vy_table_tol, pc, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        p(:, 4) = abs(pc)*scale
        call one_term_pressure(c%omega_ratio, c%delta, c%nu, one_term_shape_of(c), c%n, &
                               c%d_theta, c%l_over_h, y, pc, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        p(:, 5) = abs(pc)*scale
    end subroutine wall_pressure_profile

    !> The EN 1998-5 thrust for +kv and -kv; the one with the larger total.
    subroutine critical_mo(c, mo, kv_used, stat, errmsg)
        type(wall_case_t), intent(in) :: c
        type(ec8_thrust_t), intent(out) :: mo
        real(dp), intent(out) :: kv_used
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(ec8_thrust_t) :: other
        kv_used = abs(c%kv)
        call ec8_thrust(c%height, c%gamma, c%phi_deg, c%wall_friction_deg, c%psi_deg, c%beta_deg, &
                        c%kh, kv_used, c%water, c%gamma_w, c%gamma_d, c%gamma_phi, mo, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. (abs(c%kv) > 0.0_dp)) return
        call ec8_thrust(c%height, c%gamma, c%phi_deg, c%wall_friction_deg, c%psi_deg, c%beta_deg, &
                        c%kh, -abs(c%kv), c%water, c%gamma_w, c%gamma_d, c%gamma_phi, other, stat, &
                        errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (other%total > mo%total) then
            mo = other
            kv_used = -abs(c%kv)
        end if
    end subroutine critical_mo

    !> Checks of the fields only this module uses (the called routines check the rest).
    pure subroutine check_case(c, stat, errmsg)
        type(wall_case_t), intent(in) :: c
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (outside(c%height, 0.0_dp, huge(1.0_dp), .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'height = '// &
                           real_str(c%height)//': the wall height H (m) must be finite and > 0')
        else if (outside(c%gamma, 0.0_dp, huge(1.0_dp), .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'gamma = '//real_str(c%gamma)// &
                           ': the unit weight (kN/m3) must be finite and > 0')
        else if (outside(c%alpha_s, 0.0_dp, huge(1.0_dp), .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'alpha_s = '// &
                           real_str(c%alpha_s)//': ag S/g must be finite and >= 0')
        else if (outside(c%kh, 0.0_dp, huge(1.0_dp), .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kh = '//real_str(c%kh)// &
                           ': must be finite and >= 0')
        else if (.not. ieee_is_finite(c%kv)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kv = '//real_str(c%kv)// &
                           ': must be finite (|kv| < 1; both signs are checked)')
        end if
    end subroutine check_case

    !> The one-term shape of the case: as given, or sine for homogeneous soil and the
    !> static power-law shape (2.68) otherwise.
    pure integer function one_term_shape_of(c) result(shape)
        type(wall_case_t), intent(in) :: c
        shape = c%shape
        if (shape /= 0) return
        if (abs(c%n) > 0.0_dp) then
            shape = WALL_SHAPE_POWER
        else
            shape = WALL_SHAPE_SINE
        end if
    end function one_term_shape_of

end module seispulse_wall_table
