!> Analysis 'walls': seismic thrusts on one retaining wall, side by side (yielding-wall
!> rules, EN 1998-5 rigid wall, Veletsos-Younan and the one-term solution), with points
!> of application and base moments, and the pressure distributions against depth.
!>
!> Groups: &wall (geometry, rotational base spring, second wall), &backfill (soil) and
!> &seismic (EN 1998 input, or kh, kv and ag S/g given directly). Writes the tables
!> walls (one row per method: thrust kN/m, height of application m, z/H, base moment
!> kNm/m) and walls_pressure (depth m, pressures kPa); file names by table_path.
!> The driver only reads, checks and writes; every number comes from
!> seispulse_wall_table and seispulse_codes.
module driver_walls
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
    use seispulse, only: dp, shortest_str, SEISPULSE_SUCCESS, real_str, int_str, STANDARD_GRAVITY, &
                         ec8_ground_parameters, ec8_r_factor, ec8_seismic_coefficients, &
                         ec8_vertical_ratio, WATER_DRY, WATER_IMPERVIOUS, WATER_PERMEABLE, &
                         EC8_WALL_GRAVITY_300, EC8_WALL_GRAVITY_200, EC8_WALL_RESTRAINED, pi, &
                         WALL_SHAPE_LINEAR, WALL_SHAPE_SINE, WALL_SHAPE_PARABOLIC, &
                         WALL_SHAPE_POWER, wall_case_t, wall_case_default, wall_comparison, &
                         wall_pressure_profile, wall_row_label, WALL_ROWS, WALL_PROFILE_COLUMNS
    use driver_namelist_scan, only: nml_group
    use driver_input, only: find_group, located, join, read_optional, given, name_index
    use driver_input, only: missing_group, located_key
    use driver_input, only: output_located
    use driver_tables, only: write_tables, delete_files
    use driver_echo, only: echo_unit
    implicit none
    private

    public :: run_walls, walls_groups, walls_tables

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: walls_groups(3) = [character(len=8) :: 'wall', 'backfill', &
        'seismic']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=14), parameter :: walls_tables(2) = [character(len=14) :: 'walls', &
        'walls_pressure']

    character(len=17), parameter :: wall_keys(6) = [character(len=17) :: 'height', 'psi_deg', &
        'wall_friction_deg', 'k_rotation', 'd_theta', 'spacing']
    character(len=18), parameter :: backfill_keys(15) = [character(len=18) :: 'gamma', 'phi_deg', &
        'beta_deg', 'gamma_phi', 'nu', 'damping_ratio', 'loss_factor', 'vs', 'g_modulus', &
        'stiffness_exponent', 'shape', 'water', 'gamma_w', 'gamma_d', 'frequency']
    character(len=13), parameter :: seismic_keys(12) = [character(len=13) :: 'code', 'agr', &
        'importance', 'ground', 'spectrum_type', 'soil_factor', 'r', 'wall_type', 'kh', 'kv', &
        'alpha_s', 'npoints']

    character(len=10), parameter :: code_names(3) = [character(len=10) :: 'ec8', 'direct', 'eak']
    character(len=10), parameter :: water_names(3) = [character(len=10) :: 'dry', 'impervious', &
        'permeable']
    character(len=10), parameter :: shape_names(4) = [character(len=10) :: 'linear', 'sine', &
        'parabolic', 'power']
    character(len=11), parameter :: wall_type_names(3) = [character(len=11) :: 'gravity_300', &
        'gravity_200', 'restrained']
    character(len=1), parameter :: ground_names(5) = ['a', 'b', 'c', 'd', 'e']

    ! &wall
    real(dp) :: height, psi_deg, wall_friction_deg, k_rotation, d_theta, spacing
    namelist /wall/ height, psi_deg, wall_friction_deg, k_rotation, d_theta, spacing
    ! &backfill
    real(dp) :: gamma, phi_deg, beta_deg, gamma_phi, nu, damping_ratio, loss_factor, vs, &
                g_modulus, stiffness_exponent, gamma_w, gamma_d, frequency
    character(len=16) :: shape, water
    namelist /backfill/ gamma, phi_deg, beta_deg, gamma_phi, nu, damping_ratio, loss_factor, vs, &
        g_modulus, stiffness_exponent, shape, water, gamma_w, gamma_d, frequency
    ! &seismic
    character(len=16) :: code, ground, wall_type
    real(dp) :: agr, importance, soil_factor, r, kh, kv, alpha_s
    integer :: spectrum_type, npoints
    namelist /seismic/ code, agr, importance, ground, spectrum_type, soil_factor, r, wall_type, &
        kh, kv, alpha_s, npoints

    integer, parameter :: max_points = 100000

    !> What the tables show: per method (WALL_ROWS) and per depth.
    type :: result_t
        real(dp) :: thrust(WALL_ROWS), z(WALL_ROWS), moment(WALL_ROWS)  !! kN/m, m, kNm/m
        real(dp) :: kv_used                          !! kv of the yielding rows
        real(dp), allocatable :: depth(:)            !! m
        real(dp), allocatable :: p(:, :)             !! kPa, WALL_PROFILE_COLUMNS per depth
    end type result_t

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        height = nan
        psi_deg = 90.0_dp
        wall_friction_deg = 0.0_dp
        k_rotation = nan        ! none: a fixed base (d_theta = 0)
        d_theta = nan
        spacing = nan           ! none: a single wall (L = infinity)
        gamma = nan
        phi_deg = nan
        beta_deg = 0.0_dp
        gamma_phi = 1.0_dp
        nu = 0.3_dp
        damping_ratio = nan     ! neither: 5 %, loss factor 0.1
        loss_factor = nan
        vs = nan
        g_modulus = nan
        stiffness_exponent = 0.0_dp
        shape = ''              ! sine for homogeneous soil, power law otherwise
        water = 'dry'
        gamma_w = 9.81_dp
        gamma_d = nan
        frequency = 0.0_dp      ! pseudo-static elastic rows
        code = ''
        agr = nan
        importance = 1.0_dp
        ground = ''
        spectrum_type = 1
        soil_factor = nan       ! none: S of EN 1998-1 Table 3.2/3.3
        r = nan                 ! none: from wall_type
        wall_type = 'restrained'
        kh = nan
        kv = nan
        alpha_s = nan
        npoints = 21
    end subroutine set_defaults

    subroutine read_wall(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=wall, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=wall, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_wall

    subroutine read_backfill(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=backfill, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=backfill, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_backfill

    subroutine read_seismic(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=seismic, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=seismic, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_seismic

    !> Read and check the three groups, build the case, compute, write both tables; print
    !> where they went. stat > 0 with errmsg on an input or output error.
    subroutine run_walls(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(nml_group) :: gw, gb, gs
        type(wall_case_t) :: c
        type(result_t) :: res
        character(len=512) :: files(2), files2(2)

        call set_defaults()
        call read_optional(path, groups, 'wall', wall_keys, read_wall, gw, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'backfill', backfill_keys, read_backfill, gb, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'seismic', seismic_keys, read_seismic, gs, stat, errmsg)
        if (stat /= 0) return
        stat = 1
        if (find_group(groups, 'wall') == 0) then
            errmsg = missing_group(path, 'wall')//' (it gives the wall height, m)'
            return
        end if
        if (find_group(groups, 'backfill') == 0) then
            errmsg = missing_group(path, 'backfill')//' (it gives gamma, kN/m3, and phi_deg)'
            return
        end if
        if (find_group(groups, 'seismic') == 0) then
            errmsg = missing_group(path, 'seismic')//' (code = ''EC8'' with agr and ground, ' &
                     //'or code = ''direct'' with kh)'
            return
        end if

        ! --- check the input and build the case
        c = wall_case_default()
        call check_wall(path, gw, c, errmsg)
        if (len(errmsg) > 0) return
        call check_backfill(path, gw, gb, c, errmsg)
        if (len(errmsg) > 0) return
        call check_seismic(path, gs, c, errmsg)
        if (len(errmsg) > 0) return

        ! --- echo the effective input
        write(echo_unit(), nml=wall)
        write(echo_unit(), nml=backfill)
        write(echo_unit(), nml=seismic)

        ! --- compute (no output is written before both tables are computed)
        call compute(path, [gb, gw, gs], c, res, errmsg)
        if (len(errmsg) > 0) return

        ! --- write
        call write_result(path, prefix, c, res, files, files2, stat, errmsg)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        write(output_unit, '(a)') 'walls tables written to '//trim(files(1))//', ' &
            //trim(files(2))//', '//trim(files2(1))//' and '//trim(files2(2))
    end subroutine run_walls

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> Check &wall: the height, the second wall. errmsg is empty on success.
    subroutine check_wall(path, gw, c, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gw
        type(wall_case_t), intent(inout) :: c
        character(len=:), allocatable, intent(out) :: errmsg

        errmsg = ''
        if (ieee_is_nan(height)) then
            errmsg = located(path, gw)//'height: missing (the wall height, m, > 0)'
            return
        end if
        c%height = height
        c%psi_deg = psi_deg
        c%wall_friction_deg = wall_friction_deg
        if (given(gw, 'k_rotation') .and. given(gw, 'd_theta')) then
            errmsg = located(path, gw)//'k_rotation, d_theta: give one of them, not both'
            return
        end if
        if (given(gw, 'spacing')) then
            if (.not. (spacing > 0.0_dp)) then
                errmsg = located(path, gw)//'spacing = '//real_str(spacing)//': the distance ' &
                         //'to the second wall must be > 0 (m)'
                return
            end if
            c%l_over_h = spacing/height
        end if
    end subroutine check_wall

    !> Check &backfill: the soil, the water, the stiffness at the base and with it the
    !> rotational spring of &wall. errmsg is empty on success.
    subroutine check_backfill(path, gw, gb, c, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gw, gb
        type(wall_case_t), intent(inout) :: c
        character(len=:), allocatable, intent(out) :: errmsg
        real(dp) :: vs_base, g_base, omega_ref
        integer :: iwater, ishape

        errmsg = ''
        if (ieee_is_nan(gamma)) then
            errmsg = located(path, gb)//'gamma: missing (unit weight of the backfill, kN/m3)'
            return
        end if
        if (ieee_is_nan(phi_deg)) then
            errmsg = located(path, gb)//'phi_deg: missing (friction angle, degrees, in (0, 90))'
            return
        end if
        c%gamma = gamma
        c%phi_deg = phi_deg
        c%beta_deg = beta_deg
        c%gamma_phi = gamma_phi
        c%nu = nu
        c%n = stiffness_exponent
        c%gamma_w = gamma_w
        if (given(gb, 'damping_ratio') .and. given(gb, 'loss_factor')) then
            errmsg = located(path, gb)//'damping_ratio, loss_factor: give one of them, not both'
            return
        end if
        if (given(gb, 'loss_factor')) then
            c%delta = loss_factor
        else if (given(gb, 'damping_ratio')) then
            if (.not. (damping_ratio >= 0.0_dp .and. damping_ratio < 1.0_dp)) then
                errmsg = located(path, gb)//'damping_ratio = '//real_str(damping_ratio)// &
                         ': must lie in [0, 1) (fraction; loss factor = 2 x damping_ratio)'
                return
            end if
            c%delta = 2.0_dp*damping_ratio
        else
            c%delta = 0.1_dp
        end if
        iwater = name_index(water, water_names)
        select case (iwater)
        case (1)
            c%water = WATER_DRY
        case (2)
            c%water = WATER_IMPERVIOUS
        case (3)
            c%water = WATER_PERMEABLE
        case default
            errmsg = located(path, gb)//'water = '''//trim(water)//''': unknown case (allowed: ' &
                     //join(water_names)//')'
            return
        end select
        if (iwater == 3) then
            if (ieee_is_nan(gamma_d)) then
                errmsg = located(path, gb)//'gamma_d: missing (dry unit weight, kN/m3; needed ' &
                         //'by water = ''permeable'')'
                return
            end if
            c%gamma_d = gamma_d
        end if
        if (len_trim(shape) > 0) then
            ishape = name_index(shape, shape_names)
            select case (ishape)
            case (1)
                c%shape = WALL_SHAPE_LINEAR
            case (2)
                c%shape = WALL_SHAPE_SINE
            case (3)
                c%shape = WALL_SHAPE_PARABOLIC
            case (4)
                c%shape = WALL_SHAPE_POWER
            case default
                errmsg = located(path, gb)//'shape = '''//trim(shape)//''': unknown shape ' &
                         //'(allowed: '//join(shape_names)//')'
                return
            end select
        end if

        ! stiffness at the base: needed for a frequency or a rotational spring
        if (given(gb, 'vs') .and. given(gb, 'g_modulus')) then
            errmsg = located(path, gb)//'vs, g_modulus: give one of them, not both'
            return
        end if
        vs_base = ieee_value(vs_base, ieee_quiet_nan)
        g_base = vs_base
        if (given(gb, 'vs')) then
            if (.not. (vs > 0.0_dp .and. vs < huge(vs))) then
                errmsg = located(path, gb)//'vs = '//real_str(vs)//': the shear-wave velocity ' &
                         //'at the base must be > 0 (m/s)'
                return
            end if
            vs_base = vs
            g_base = gamma/STANDARD_GRAVITY*vs**2      ! kPa: (kN/m3)/(m/s2) (m/s)^2
        else if (given(gb, 'g_modulus')) then
            if (.not. (g_modulus > 0.0_dp .and. g_modulus < huge(g_modulus))) then
                errmsg = located(path, gb)//'g_modulus = '//real_str(g_modulus)//': the ' &
                         //'shear modulus at the base must be > 0 (kPa)'
                return
            end if
            g_base = g_modulus
            if (gamma > 0.0_dp) vs_base = sqrt(g_modulus*STANDARD_GRAVITY/gamma)
        end if
        if (.not. (frequency >= 0.0_dp .and. frequency < huge(frequency))) then
            errmsg = located(path, gb)//'frequency = '//real_str(frequency)//': must be >= 0 ' &
                     //'(Hz; 0 = pseudo-static)'
            return
        end if
        if (frequency > 0.0_dp) then
            if (ieee_is_nan(vs_base)) then
                errmsg = located(path, gb)//'vs: missing (a frequency > 0 needs vs, m/s, or ' &
                         //'g_modulus, kPa, at the base)'
                return
            end if
            if (height > 0.0_dp) then
                omega_ref = pi*vs_base/(2.0_dp*height)     ! omega_1 of the layer, rad/s
                c%omega_ratio = 2.0_dp*pi*frequency/omega_ref
            end if
        end if
        if (given(gw, 'd_theta')) then
            c%d_theta = d_theta
        else if (given(gw, 'k_rotation')) then
            if (ieee_is_nan(g_base)) then
                errmsg = located(path, gb)//'g_modulus: missing (k_rotation needs g_modulus, ' &
                         //'kPa, or vs, m/s, at the base)'
                return
            end if
            if (.not. (k_rotation > 0.0_dp)) then
                errmsg = located(path, gw)//'k_rotation = '//real_str(k_rotation)//': the ' &
                         //'rotational base stiffness must be > 0 (kNm/m/rad)'
                return
            end if
            c%d_theta = height**2*g_base/k_rotation           ! d_theta = H^2 G_H/K_R
        end if
    end subroutine check_backfill

    !> Check &seismic: kh, kv and ag S/g from EN 1998 or as given, the profile depths.
    !> errmsg is empty on success.
    subroutine check_seismic(path, gs, c, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gs
        type(wall_case_t), intent(inout) :: c
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=256) :: msg
        real(dp) :: s_eff, r_eff, kv_mag, tb, tc, td
        integer :: st, icode, iground, iwall

        errmsg = ''
        msg = ''
        icode = name_index(code, code_names)
        select case (icode)
        case (1)    ! EN 1998-1 / EN 1998-5
            if (ieee_is_nan(agr)) then
                errmsg = located(path, gs)//'agr: missing (reference peak ground acceleration ' &
                         //'on rock, in g)'
                return
            end if
            if (.not. (agr >= 0.0_dp .and. importance > 0.0_dp)) then
                errmsg = located(path, gs)//'agr, importance: agr must be >= 0 (g) and the ' &
                         //'importance factor > 0'
                return
            end if
            if (given(gs, 'kh') .or. given(gs, 'kv') .or. given(gs, 'alpha_s')) then
                errmsg = located(path, gs)//'kh, kv, alpha_s: come from agr, ground and r with ' &
                         //'code = ''EC8''; give them only with code = ''direct'''
                return
            end if
            if (given(gs, 'soil_factor')) then
                s_eff = soil_factor
            else
                iground = name_index(ground, ground_names)
                if (iground == 0) then
                    errmsg = located(path, gs)//'ground = '''//trim(ground)//''': must be one ' &
                             //'of A, B, C, D, E (EN 1998-1 Table 3.1), or give soil_factor'
                    return
                end if
                call ec8_ground_parameters(spectrum_type, iground, s_eff, tb, tc, td, st, msg)
                if (st /= SEISPULSE_SUCCESS) then
                    errmsg = located(path, gs)//trim(msg)
                    return
                end if
            end if
            if (given(gs, 'r')) then
                r_eff = r
            else
                iwall = name_index(wall_type, wall_type_names)
                select case (iwall)
                case (1)
                    iwall = EC8_WALL_GRAVITY_300
                case (2)
                    iwall = EC8_WALL_GRAVITY_200
                case (3)
                    iwall = EC8_WALL_RESTRAINED
                case default
                    errmsg = located(path, gs)//'wall_type = '''//trim(wall_type)//''': ' &
                             //'unknown (allowed: '//join(wall_type_names)//'), or give r'
                    return
                end select
                call ec8_r_factor(iwall, r_eff, st, msg)
                if (st /= SEISPULSE_SUCCESS) then
                    errmsg = located(path, gs)//trim(msg)
                    return
                end if
            end if
            call ec8_seismic_coefficients(importance*agr, s_eff, r_eff, &
                                          ec8_vertical_ratio(spectrum_type), c%kh, kv_mag, st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = located(path, gs)//trim(msg)
                return
            end if
            c%kv = kv_mag
            c%alpha_s = importance*agr*s_eff
        case (2)    ! kh, kv and ag S/g given
            if (ieee_is_nan(kh)) then
                errmsg = located(path, gs)//'kh: missing (horizontal seismic coefficient, >= 0)'
                return
            end if
            c%kh = kh
            c%kv = 0.0_dp
            if (given(gs, 'kv')) c%kv = kv
            if (abs(c%kv) >= 1.0_dp) then
                errmsg = located(path, gs)//'kv = '//real_str(kv)//': |kv| must be < 1'
                return
            end if
            c%alpha_s = kh                 ! r = 1 unless ag S/g is given
            if (given(gs, 'alpha_s')) c%alpha_s = alpha_s
        case (3)
            errmsg = located(path, gs)//'code = ''EAK'': not available: the retaining-wall ' &
                     //'clause of EAK 2000 could not be found (its spectra are available, see ' &
                     //'README); use code = ''direct'' with kh, kv (and alpha_s), or ' &
                     //'code = ''EC8'''
            return
        case default
            errmsg = located(path, gs)//'code = '''//trim(code)//''': unknown code (allowed: ' &
                     //'EC8, direct, EAK)'
            return
        end select
        if (npoints < 2 .or. npoints > max_points) then
            errmsg = located(path, gs)//'npoints = '//int_str(npoints)//': the pressure ' &
                     //'profile needs 2 .. '//int_str(max_points)//' depths'
            return
        end if
    end subroutine check_seismic

    ! ------------------------------------------------------------------------------
    ! Computation
    ! ------------------------------------------------------------------------------

    !> The thrusts of every method and the pressure profile. errmsg is empty on success.
    subroutine compute(path, gbws, c, res, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gbws(3)            !! &backfill, &wall, &seismic
        type(wall_case_t), intent(in) :: c
        type(result_t), intent(out) :: res
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=256) :: msg
        integer :: i, st

        errmsg = ''
        msg = ''
        call wall_comparison(c, res%thrust, res%z, res%moment, res%kv_used, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            ! the group of the key the message starts with (a missing active wedge:
            ! beta_deg of &backfill); a resonance comes from &backfill frequency
            errmsg = located_key(path, gbws, trim(msg))
            if (index(msg, 'omega_ratio') == 1) errmsg = located(path, gbws(1))//'frequency = ' &
                //real_str(frequency)//' Hz: '//trim(msg)
            return
        end if
        allocate(res%depth(npoints), res%p(npoints, WALL_PROFILE_COLUMNS))
        res%depth = height*[(real(i, dp), i = 0, npoints - 1)]/real(npoints - 1, dp)
        call wall_pressure_profile(c, res%depth, res%p, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = located_key(path, gbws, trim(msg))
            return
        end if
    end subroutine compute

    ! ------------------------------------------------------------------------------
    ! Output
    ! ------------------------------------------------------------------------------

    !> Both tables, or neither: <prefix>_walls (files) and <prefix>_walls_pressure
    !> (files2).
    subroutine write_result(path, prefix, c, res, files, files2, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(wall_case_t), intent(in) :: c
        type(result_t), intent(in) :: res
        character(len=*), intent(out) :: files(2), files2(2)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=300) :: comments(8)
        character(len=40) :: labels(WALL_ROWS)
        real(dp) :: table(WALL_ROWS, 4)
        real(dp), allocatable :: ptab(:, :)
        integer :: i

        do i = 1, WALL_ROWS
            labels(i) = wall_row_label(i)
            table(i, :) = [res%thrust(i), res%z(i), res%z(i)/height, res%moment(i)]
        end do
        comments(1) = 'seispulse analysis walls: seismic thrust on a retaining wall, per method'
        comments(2) = 'input: '//trim(path)
        comments(3) = 'H = '//shortest_str(height)//' m, gamma = '//shortest_str(gamma) &
                      //' kN/m3, phi = '//shortest_str(phi_deg)//' deg, wall friction = ' &
                      //shortest_str(wall_friction_deg)//' deg, psi = ' &
                      //shortest_str(psi_deg)//' deg, beta = '//shortest_str(beta_deg) &
                      //' deg, gamma_phi = '//shortest_str(gamma_phi)//', water = '//trim(water)
        comments(4) = 'yielding rows: kh = '//shortest_str(c%kh)//', kv = ' &
                      //shortest_str(res%kv_used) &
                      //' (the sign of kv with the larger total; kv > 0 upward)'
        comments(5) = 'non-yielding rows: ag S/g = '//shortest_str(c%alpha_s)//'; elastic rows: ' &
                      //'nu = '//shortest_str(c%nu)//', loss factor = '//shortest_str(c%delta) &
                      //', omega/omega_ref = '//shortest_str(c%omega_ratio)//', n = ' &
                      //shortest_str(c%n)//', d_theta = '//shortest_str(c%d_theta)//', L/H = ' &
                      //shortest_str(c%l_over_h)
        comments(6) = 'thrust: total (static + dynamic) for the static and M-O total rows, the ' &
                      //'dynamic increment for the others; z: height of the resultant above ' &
                      //'the base'
        comments(7) = 'Veletsos-Younan and one-term: |Q| gamma (ag S/g) H^2 at h = |M|/|Q| ' &
                      //'(dry backfill, harmonic ground motion)'
        comments(8) = 'EAK 2000: no wall rows (its retaining-wall clause could not be found; ' &
                      //'see README)'
        call write_tables(prefix, 'walls', comments, &
            [character(len=8) :: 'method', 'thrust', 'z', 'z/H', 'moment'], &
            [character(len=8) :: '-', 'kN/m', 'm', '-', 'kNm/m'], table, files, stat, errmsg, &
            labels=labels)
        if (stat /= 0) return
        allocate(ptab(npoints, WALL_PROFILE_COLUMNS + 1))
        ptab(:, 1) = res%depth
        ptab(:, 2:) = res%p
        comments(1) = 'seispulse analysis walls: pressures on the wall against depth below ' &
                      //'the top'
        comments(6) = 'static: K gamma* z (Coulomb); mo_dyn: the M-O increment spread ' &
                      //'uniformly (resultant at H/2); ec8_rigid: ag S/g gamma H'
        comments(7) = 'vy, one_term: |p| of the elastic solutions, gamma (ag S/g) H units ' &
                      //'converted to kPa; water pressures not included'
        call write_tables(prefix, 'walls_pressure', comments(1:7), &
            [character(len=9) :: 'depth', 'static', 'mo_dyn', 'ec8_rigid', 'vy', 'one_term'], &
            [character(len=9) :: 'm', 'kPa', 'kPa', 'kPa', 'kPa', 'kPa'], ptab, files2, stat, &
            errmsg)
        if (stat /= 0) call delete_files(files)     ! both tables or neither
    end subroutine write_result

end module driver_walls
