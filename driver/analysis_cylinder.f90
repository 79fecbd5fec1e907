!> Analysis 'cylinder': a rigid body of revolution (solid or hollow circular cylinder, or
!> a body with a given J_o) or a uniform block on a rigid base, statically pushed over or
!> rocking in a vertical plane (doc/cylinder.md; [AD11], [SK84], [H63]).
!>
!> Groups: &body (the body, its restitution and model), &cylinder (what to compute, run
!> limits, the pushover grid, the history grid), &pulse (driver_pulse_group) or &records
!> (driver_records) for a history, &map (the pulse family and the grids of an
!> overturning map), &roll (the initial state and the pulse direction of 'roll'). Five
!> modes (`what`):
!>   * 'props': <output>_cylinder_props, the body and its equivalent body;
!>   * 'pushover': <output>_cylinder_pushover, F, M, M/(m g r) against theta;
!>   * 'history': <output>_cylinder (summary) and <output>_cylinder_history, planar
!>     rocking under one pulse or each record;
!>   * 'map': <output>_cylinder_map, an overturning map on either axis system, with the
!>     equivalent block's map and the difference map on request;
!>   * 'roll': <output>_cylinder_roll (summary) and <output>_cylinder_roll_history, the
!>     3-D rocking with rolling of a circular cylinder on its rim ([KM90]) under a pulse
!>     along a direction, one or two records (x, y), or free from an initial state
!>     (&roll).
!> File names by table_path (out/cylinder_map + cylinder_map: out/cylinder_map.txt).
!> The numbers come from seispulse_cylinder (properties, pushover, maps),
!> seispulse_rocking_sim (the planar integrator) and seispulse_cylinder_roll (rolling); the
!> driver only reads, checks, converts units and writes. Every table is computed before the
!> first is written.
module driver_cylinder
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan, &
                                             ieee_positive_inf, ieee_is_finite
    use seispulse, only: dp, shortest_str, pi, pulse_t, pulse_eval, pulse_kind_name, &
                         SEISPULSE_SUCCESS, &
                         real_str, int_str, rocking_block_t, rocking_run_t, rock_pulse, &
                         ROCK_RUN_TIME_LIMIT, in_open, positive, rocking_body_t, &
                         cylinder_props, block_props, body_rocking_block, equivalent_cylinder, &
                         equivalent_block, rigid_pushover, normalized_pushover, &
                         body_overturning_map, map_difference, BODY_SOLID_CYLINDER, &
                         BODY_HOLLOW_CYLINDER, BODY_CUSTOM, BODY_BLOCK, MAP_AXES_DIMENSIONLESS, &
                         cylinder_roll, roll_run_t, roll_output_name, roll_outcome_name, &
                         ROLL_NOUT, ROLL_RUN_TIME_LIMIT
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: find_group, located, join, read_optional, given, list_item, &
                            name_index, ROWS_FAILED
    use driver_input, only: missing_group
    use driver_input, only: output_located
    use driver_pulse_group, only: pulse_input_t, pulse_keys, read_pulse_group, build_pulse, &
                                  write_pulse_group, pulse_end, check_time_grid, time_grid, &
                                  warn_unused_template, template_text
    use driver_records, only: records_keys, record_in_t, record_out_t, records_defaults, &
                              read_records, check_records, echo_records, load_record, &
                              record_line, failed_records
    use driver_tables, only: write_tables, say_written, delete_files, stack, category_kind
    use driver_axis, only: axis_values
    use driver_rocking_common, only: check_run_options, restitution_and_model, &
                                     locate_run_message, map_kind, map_template, progress_t, &
                                     axes_names, map_axes_code, map_grids, map_axes_header, &
                                     map_table, rock_records, record_at, run_summary_kinds, &
                                     map_class_names, run_outcome_names, map_class_line
    use driver_echo, only: echo_unit
    use driver_records, only: record_place
    implicit none
    private

    public :: run_cylinder, cylinder_groups, cylinder_tables

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: cylinder_groups(6) = [character(len=8) :: 'body', &
        'cylinder', 'pulse', 'records', 'map', 'roll']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=21), parameter :: cylinder_tables(7) = [character(len=21) :: 'cylinder_props', &
        'cylinder_pushover', 'cylinder', 'cylinder_history', 'cylinder_map', 'cylinder_roll', &
        'cylinder_roll_history']

    character(len=16), parameter :: body_keys(12) = [character(len=16) :: 'shape', 'r', &
        'b', 'r_inner', 'h', 'mass', 'j_o', 'j_axis', 'g', 'e', 'model', 'equivalent_angle']
    character(len=17), parameter :: cylinder_keys(13) = [character(len=17) :: 'what', &
        't_max', 'rtol', 't_end', 'npts', 'dt', 'kv', 'theta', 'theta_range', 'theta_count', &
        'theta_ratio', 'theta_ratio_range', 'theta_ratio_count']
    character(len=13), parameter :: map_keys(20) = [character(len=13) :: 'axes', 'kind', &
        'beta', 'full', 'peak_frac', 't0_periods', 'cycles', 'freq_ratio', 'freq_range', &
        'freq_count', 'amp_ratio', 'amp_range', 'amp_count', 'freq_hz', 'freq_hz_range', &
        'freq_hz_count', 'pga', 'pga_range', 'pga_count', 'compare_block']
    character(len=8), parameter :: what_names(5) = [character(len=8) :: 'props', &
        'pushover', 'history', 'map', 'roll']
    character(len=12), parameter :: roll_keys(7) = [character(len=12) :: 'theta0', 'psi0', &
        'spin0', 'theta_rate0', 'psi_rate0', 'spin_rate0', 'direction']
    !> Units of the ROLL_OUT_* columns of cylinder_roll.
    character(len=5), parameter :: roll_units(13) = [character(len=5) :: 'rad', 'rad', &
        'rad', 'rad/s', 'rad/s', 'rad/s', 'm', 'm', 'm', 'm', 'N', '-', 'J']
    !> In the order of the BODY_* codes.
    character(len=6), parameter :: shape_names(4) = [character(len=6) :: 'solid', 'hollow', &
        'custom', 'block']
    character(len=16), parameter :: diff_names(0:3) = [character(len=16) :: 'same', &
        'only_cylinder', 'only_block', 'other_mode']

    !> Most values of a list (pushover grid, map axes).
    integer, parameter :: max_list = 1000
    !> Points of the default pushover grid (theta/theta_c = 0 .. 1).
    integer, parameter :: pushover_default_count = 21

    ! namelist variables (defaults are set in set_defaults)
    character(len=32) :: shape, model
    real(dp) :: r, b, r_inner, h, mass, j_o, j_axis, g, e, equivalent_angle
    character(len=32) :: what
    real(dp) :: t_max, rtol, t_end, dt
    real(dp) :: kv       !! vertical ground acceleration a_v = kv a_g (doc/rocking.md section 7)
    integer :: npts
    real(dp) :: theta(max_list), theta_range(2), theta_ratio(max_list), theta_ratio_range(2)
    integer :: theta_count, theta_ratio_count
    character(len=32) :: axes, kind
    real(dp) :: beta, peak_frac, t0_periods
    real(dp) :: cycles   !! sine_cycle, cosine_cycle: whole number of cycles (read as a real)
    logical :: full, compare_block
    real(dp) :: theta0, psi0, spin0, theta_rate0, psi_rate0, spin_rate0, direction
    real(dp) :: freq_ratio(max_list), freq_range(2), amp_ratio(max_list), amp_range(2)
    real(dp) :: freq_hz(max_list), freq_hz_range(2), pga(max_list), pga_range(2)
    integer :: freq_count, amp_count, freq_hz_count, pga_count
    namelist /body/ shape, r, b, r_inner, h, mass, j_o, j_axis, g, e, model, equivalent_angle
    namelist /cylinder/ what, t_max, rtol, t_end, npts, dt, kv, theta, theta_range, &
        theta_count, theta_ratio, theta_ratio_range, theta_ratio_count
    namelist /map/ axes, kind, beta, full, peak_frac, t0_periods, cycles, freq_ratio, &
        freq_range, freq_count, amp_ratio, amp_range, amp_count, freq_hz, freq_hz_range, &
        freq_hz_count, pga, pga_range, pga_count, compare_block
    namelist /roll/ theta0, psi0, spin0, theta_rate0, psi_rate0, spin_rate0, direction

    !> The checked input of a run.
    type :: setup_t
        character(len=:), allocatable :: task     !! 'props', 'pushover', 'history', 'map'
        type(rocking_body_t) :: body              !! the body (SI)
        type(rocking_block_t) :: blk              !! its planar rocking model
        real(dp) :: e_run = 0.0_dp                !! restitution of the runs (given or Housner)
        logical :: e_given = .false.              !! e given in &body
        logical :: linearized = .false.           !! model = 'linearized'
        logical :: use_records = .false.          !! a history on &records
        type(pulse_input_t) :: pin                !! the pulse of a history
        type(record_in_t), allocatable :: recs(:) !! the records of a history
        logical :: slammer_rounding = .false.
        type(nml_group) :: gb, gc, gm, gr, gl     !! &body, &cylinder, &map, &records, &roll
    end type setup_t

contains

    !> The defaults of &body, &cylinder, &map and &roll, set before they are read.
    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        shape = 'solid'
        r = nan
        b = nan
        r_inner = nan
        h = nan
        mass = nan        ! NaN: required by 'props' and 'pushover', else 1 kg (not used)
        j_o = nan
        j_axis = nan
        g = 9.80665_dp
        e = nan           ! NaN: Housner's value from the geometry
        model = 'nonlinear'
        equivalent_angle = nan   ! NaN: the body's own slenderness
        what = 'props'
        t_max = ieee_value(t_max, ieee_positive_inf)
        rtol = 1.0e-12_dp
        kv = 0.0_dp       ! no vertical ground acceleration
        t_end = nan       ! NaN: 1.25 x the end of the motion, at least the excitation's
        npts = 0          ! neither dt nor npts: 1001 points
        dt = 0.0_dp
        theta = nan
        theta_range = nan
        theta_count = pushover_default_count
        theta_ratio = nan
        theta_ratio_range = nan
        theta_ratio_count = pushover_default_count
        axes = 'dimensionless'
        kind = 'sine_cycle'
        beta = 0.0_dp
        full = .false.
        peak_frac = 0.5_dp
        t0_periods = 1.5_dp
        cycles = 1.0_dp
        compare_block = .false.
        freq_ratio = nan
        freq_range = nan
        freq_count = 21
        amp_ratio = nan
        amp_range = nan
        amp_count = 21
        freq_hz = nan
        freq_hz_range = nan
        freq_hz_count = 21
        pga = nan
        pga_range = nan
        pga_count = 21
        theta0 = 0.0_dp
        psi0 = 0.0_dp
        spin0 = 0.0_dp
        theta_rate0 = 0.0_dp
        psi_rate0 = 0.0_dp
        spin_rate0 = 0.0_dp
        direction = 0.0_dp
    end subroutine set_defaults

    subroutine read_body(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=body, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=body, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_body

    subroutine read_cylinder(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=cylinder, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=cylinder, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_cylinder

    subroutine read_map(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=map, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=map, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_map

    subroutine read_roll(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=roll, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=roll, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_roll

    !> Read the groups, compute, write the tables; print where they went. stat: 0,
    !> ROWS_FAILED (a history on records: the tables are written, some records failed;
    !> errmsg says which), or > 0 for an input or output error (nothing written).
    subroutine run_cylinder(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(setup_t) :: s
        real(dp) :: g_pulse
        logical :: g_from_pulse

        call set_defaults()
        call records_defaults()
        call read_pulse_group(path, groups, s%pin, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'body', body_keys, read_body, s%gb, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'cylinder', cylinder_keys, read_cylinder, s%gc, &
                           stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'map', map_keys, read_map, s%gm, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'records', records_keys, read_records, s%gr, stat, &
                           errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'roll', roll_keys, read_roll, s%gl, stat, errmsg)
        if (stat /= 0) return
        stat = 1

        ! --- what to compute, and which groups go with it
        s%task = trim(lower(adjustl(what)))
        if (.not. any(what_names == s%task)) then
            errmsg = located(path, s%gc)//'what = '''//trim(what)//''': unknown (allowed: ' &
                     //join(what_names)//')'
            return
        end if
        call check_groups(path, groups, s, errmsg)
        if (len(errmsg) > 0) return
        call check_cylinder(path, s%gc, s%task, errmsg)
        if (len(errmsg) > 0) return

        ! --- the excitation of a history, then the body (which uses its g)
        g_from_pulse = .false.
        g_pulse = 9.80665_dp
        if (s%task == 'history' .or. s%task == 'roll') then
            if (s%use_records) then
                call check_records(path, s%gr, s%recs, s%slammer_rounding, errmsg)
                if (len(errmsg) > 0) return
            else if (find_group(groups, 'pulse') > 0) then
                call build_pulse(path, s%pin, stat, errmsg, g_used=.true.)
                if (stat /= 0) return
                stat = 1
                g_from_pulse = .true.
                g_pulse = s%pin%g
            end if
        end if
        call check_body(path, s, g_from_pulse, g_pulse, errmsg)
        if (len(errmsg) > 0) return

        select case (s%task)
        case ('props')
            call do_props(path, prefix, s, stat, errmsg)
        case ('pushover')
            call do_pushover(path, prefix, s, stat, errmsg)
        case ('history')
            if (s%use_records) then
                call do_history_records(path, prefix, s, stat, errmsg)
            else
                call do_history_pulse(path, prefix, s, stat, errmsg)
            end if
        case ('map')
            call do_map(path, prefix, s, stat, errmsg)
        case default
            call do_roll(path, prefix, s, stat, errmsg)
        end select
    end subroutine run_cylinder

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> Which groups the task needs and allows. errmsg is empty on success.
    subroutine check_groups(path, groups, s, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: groups(:)
        type(setup_t), intent(inout) :: s
        character(len=:), allocatable, intent(out) :: errmsg
        logical :: has_pulse, has_records

        errmsg = ''
        has_pulse = find_group(groups, 'pulse') > 0
        has_records = find_group(groups, 'records') > 0
        if (find_group(groups, 'body') == 0) then
            errmsg = missing_group(path, 'body')//' (it gives the body: shape, r and h, ' &
                     //'or b and h for a block)'
            return
        end if
        if (s%task /= 'map' .and. find_group(groups, 'map') > 0) then
            errmsg = located(path, s%gm)//'only with what = ''map'' (&cylinder; now what = ''' &
                     //s%task//''')'
            return
        end if
        if (s%task /= 'roll' .and. find_group(groups, 'roll') > 0) then
            errmsg = located(path, s%gl)//'only with what = ''roll'' (&cylinder; now what = ''' &
                     //s%task//''')'
            return
        end if
        select case (s%task)
        case ('roll')
            if (has_pulse .and. has_records) errmsg = located(path, s%gr)//'not with ' &
                //'&pulse (the base moves under one pulse or under records: give one of ' &
                //'the two groups, or neither for free rocking from &roll)'
            s%use_records = has_records
        case ('history')
            if (has_pulse .and. has_records) then
                errmsg = located(path, s%gr)//'not with &pulse (a history runs under one ' &
                         //'pulse or under records: give one of the two groups)'
            else if (.not. (has_pulse .or. has_records)) then
                errmsg = missing_group(path, 'pulse')//' (what = ''history'' needs the ' &
                         //'excitation: &pulse, or &records with the record files)'
            end if
            s%use_records = has_records
        case default
            if (has_pulse) then
                errmsg = located(path, s%pin%group)//'only with what = ''history'' or ''roll'''
                if (s%task == 'map') errmsg = located(path, s%pin%group)//'not used by ' &
                    //'what = ''map'' (the pulse family and shape of a map are in &map)'
            else if (has_records) then
                errmsg = located(path, s%gr)//'only with what = ''history'' or ''roll'''
            else if (s%task == 'map' .and. find_group(groups, 'map') == 0) then
                errmsg = missing_group(path, 'map')//' (what = ''map'' needs the grids: ' &
                         //'freq_ratio or freq_range, amp_ratio or amp_range, or on axes = ' &
                         //'''dimensional'' freq_hz or freq_hz_range, pga or pga_range)'
            end if
        end select
    end subroutine check_groups

    !> Check &cylinder for the task. errmsg is empty on success.
    subroutine check_cylinder(path, gc, task, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gc
        character(len=*), intent(in) :: task
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=8), parameter :: grid_keys(3) = [character(len=8) :: 't_end', 'npts', &
            'dt']
        character(len=17), parameter :: push_keys(6) = [character(len=17) :: 'theta', &
            'theta_range', 'theta_count', 'theta_ratio', 'theta_ratio_range', &
            'theta_ratio_count']
        integer :: i

        where = located(path, gc)
        errmsg = ''
        if (task /= 'history' .and. task /= 'roll') then
            do i = 1, size(grid_keys)
                if (given(gc, trim(grid_keys(i)))) then
                    errmsg = where//trim(grid_keys(i))//': only with what = ''history'' or ' &
                             //'''roll'' (the grid of the history table)'
                    return
                end if
            end do
        end if
        if (task /= 'pushover') then
            do i = 1, size(push_keys)
                if (given(gc, trim(push_keys(i)))) then
                    errmsg = where//trim(push_keys(i))//': only with what = ''pushover'' ' &
                             //'(the grid of the pushover table)'
                    return
                end if
            end do
        end if
        if (task /= 'history' .and. task /= 'roll' .and. given(gc, 't_max')) then
            errmsg = where//'t_max: only with what = ''history'' or ''roll'''
            if (task == 'map') errmsg = where//'t_max: not with what = ''map'' (each cell ' &
                                        //'runs until its class is known)'
            return
        end if
        if ((task == 'props' .or. task == 'pushover') .and. given(gc, 'rtol')) then
            errmsg = where//'rtol: only with what = ''history'', ''map'' or ''roll'' (the ' &
                     //'tolerance of the integration)'
            return
        end if
        call check_run_options(where, t_max, rtol, errmsg)
        if (len(errmsg) > 0) return
        if (task /= 'history' .and. task /= 'map' .and. given(gc, 'kv')) then
            errmsg = where//'kv: only with what = ''history'' or ''map'' (a vertical ground ' &
                     //'acceleration a_v = kv a_g during the motion)'
            return
        end if
        if (.not. ieee_is_finite(kv)) then
            errmsg = where//'kv = '//real_str(kv)//': must be a finite number (vertical ' &
                     //'ground acceleration a_v = kv a_g)'
            return
        end if
        if (task == 'history' .or. task == 'roll') call check_time_grid(where, gc, t_end, &
                                                                        dt, npts, errmsg)
    end subroutine check_cylinder

    !> Check &body and build the body (and its planar rocking model); g_pulse is the
    !> gravity of the pulse when g_from_pulse. errmsg is empty on success.
    subroutine check_body(path, s, g_from_pulse, g_pulse, errmsg)
        character(len=*), intent(in) :: path
        type(setup_t), intent(inout) :: s
        logical, intent(in) :: g_from_pulse
        real(dp), intent(in) :: g_pulse
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, name
        character(len=512) :: msg
        real(dp) :: m_used
        integer :: code, stat

        where = located(path, s%gb)
        errmsg = ''
        msg = ''
        name = trim(lower(adjustl(shape)))
        code = 0
        ! name_index, not findloc: gfortran 12 returned 0 here for a name in the list
        code = name_index(name, shape_names)
        if (code == 0) then
            errmsg = where//'shape = '''//trim(shape)//''': unknown shape (allowed: ' &
                     //join(shape_names)//')'
            return
        end if
        shape = name
        ! --- the keys of this shape
        if (code == BODY_BLOCK) then
            call only_with('r', 'shape = ''block'' takes the half-width b')
            call only_with('r_inner', 'a hollow cylinder (shape = ''hollow'')')
            call only_with('j_o', 'a custom body (shape = ''custom'')')
            call only_with('j_axis', 'a custom body (shape = ''custom'')')
            call required('b', 'the half-width of the block, m')
        else
            call only_with('b', 'a block (shape = ''block''); a cylinder takes the radius r')
            call required('r', 'the base radius, m')
            if (code == BODY_HOLLOW_CYLINDER) then
                call required('r_inner', 'the inner radius of the hollow cylinder, m')
                if (len(errmsg) == 0 .and. .not. positive(r_inner)) errmsg = where &
                    //'r_inner = '//real_str(r_inner)//': the inner radius of a hollow ' &
                    //'cylinder must be > 0 (m; shape = ''solid'' for none)'
            else
                call only_with('r_inner', 'a hollow cylinder (shape = ''hollow'')')
            end if
            if (code == BODY_CUSTOM) then
                call required('j_o', 'the moment of inertia about the pivot, kg m2')
            else
                call only_with('j_o', 'a custom body (shape = ''custom'')')
                call only_with('j_axis', 'a custom body (shape = ''custom'')')
            end if
        end if
        if (len(errmsg) > 0) return
        call required('h', 'the height of the centre of mass above the base, m')
        if (len(errmsg) > 0) return
        if (s%task == 'props' .or. s%task == 'pushover' .or. s%task == 'roll') then
            call required('mass', 'kg; the forces and moments scale with it')
            if (len(errmsg) > 0) return
        end if
        if (s%task == 'roll') then
            if (code == BODY_BLOCK) then
                errmsg = where//'shape = ''block'': what = ''roll'' is for a body of ' &
                         //'revolution rolling on its rim (solid, hollow, custom)'
            else if (code == BODY_CUSTOM) then
                call required('j_axis', 'the rolling needs J about the axis of symmetry, ' &
                              //'kg m2')
            end if
            if (len(errmsg) > 0) return
        end if
        m_used = mass
        if (.not. given(s%gb, 'mass')) m_used = 1.0_dp     ! dynamics do not depend on it
        ! --- gravity: the pulse's, or &body's; not two different values
        if (g_from_pulse) then
            ! the pulse's amplitude in g was converted with its own g (default 9.80665)
            if (given(s%gb, 'g') .and. .not. abs(g - g_pulse) <= 0.0_dp) then
                errmsg = where//'g = '//real_str(g)//': not the g of &pulse (' &
                         //real_str(g_pulse)//' m/s2): with a pulse give g in &pulse'
                return
            end if
            g = g_pulse
        end if
        ! --- the body
        select case (code)
        case (BODY_SOLID_CYLINDER)
            call cylinder_props(r, h, m_used, g, s%body, stat, msg)
        case (BODY_HOLLOW_CYLINDER)
            call cylinder_props(r, h, m_used, g, s%body, stat, msg, r_inner=r_inner)
        case (BODY_CUSTOM)
            if (given(s%gb, 'j_axis')) then
                call cylinder_props(r, h, m_used, g, s%body, stat, msg, j_o=j_o, &
                                    j_axis=j_axis)
            else
                call cylinder_props(r, h, m_used, g, s%body, stat, msg, j_o=j_o)
            end if
        case default
            call block_props(b, h, m_used, g, s%body, stat, msg)
        end select
        if (stat /= SEISPULSE_SUCCESS) then
            errmsg = where//trim(msg)
            return
        end if
        ! --- restitution, model, the equivalent body's slenderness
        s%e_given = given(s%gb, 'e')
        s%e_run = s%body%e
        call restitution_and_model(where, s%gb, e, model, s%e_run, s%linearized, errmsg)
        if (len(errmsg) > 0) return
        if (s%task == 'roll' .and. s%linearized) then
            errmsg = where//'model = ''linearized'': what = ''roll'' has the nonlinear ' &
                     //'model only'
            return
        end if
        ! keys that would be echoed but change nothing in this mode
        if (s%task == 'props' .or. s%task == 'pushover') then
            if (given(s%gb, 'e')) errmsg = where//'e: only with what = ''history'', ''map'' ' &
                //'or ''roll'' (the restitution at the impacts; the table shows Housner''s)'
            if (len(errmsg) == 0 .and. given(s%gb, 'model')) errmsg = where//'model: only ' &
                //'with what = ''history'' or ''map'' (the equation of motion)'
        end if
        if (len(errmsg) == 0 .and. given(s%gb, 'equivalent_angle') .and. &
            (s%task == 'pushover' .or. s%task == 'history' .or. s%task == 'roll')) &
            errmsg = where//'equivalent_angle: only with what = ''props'' or ''map'' (the ' &
                     //'slenderness of the equivalent body)'
        if (len(errmsg) > 0) return
        if (given(s%gb, 'equivalent_angle')) then
            if (.not. in_open(equivalent_angle, 0.0_dp, 0.5_dp * pi)) then
                errmsg = where//'equivalent_angle = '//real_str(equivalent_angle) &
                         //': must be a number in (0, pi/2) (rad)'
                return
            end if
        end if
        call body_rocking_block(s%body, s%blk, stat, msg, e=s%e_run, &
                                linearized=s%linearized)
        if (stat /= SEISPULSE_SUCCESS) then
            errmsg = where//trim(msg)
            return
        end if
        ! the effective values, for the echo
        e = s%e_run
        if (.not. given(s%gb, 'mass')) mass = m_used

    contains

        subroutine required(key, meaning)
            character(len=*), intent(in) :: key, meaning
            if (len(errmsg) > 0) return
            if (.not. given(s%gb, key)) errmsg = where//key//': missing ('//meaning//')'
        end subroutine required

        subroutine only_with(key, what_for)
            character(len=*), intent(in) :: key, what_for
            if (len(errmsg) > 0) return
            if (given(s%gb, key)) errmsg = where//key//': only with '//what_for//' (now ' &
                                           //'shape = '''//name//''')'
        end subroutine only_with

    end subroutine check_body

    !> The body's equivalent (same p, same M_max): a block for a cylinder, a solid
    !> cylinder for a block; with the slenderness equivalent_angle when given.
    subroutine equivalent_body(s, eq, stat, msg)
        type(setup_t), intent(in) :: s
        type(rocking_body_t), intent(out) :: eq
        integer, intent(out) :: stat
        character(len=*), intent(inout) :: msg
        if (s%body%shape == BODY_BLOCK) then
            if (given(s%gb, 'equivalent_angle')) then
                call equivalent_cylinder(s%body, eq, stat, msg, theta_c=equivalent_angle)
            else
                call equivalent_cylinder(s%body, eq, stat, msg)
            end if
        else
            if (given(s%gb, 'equivalent_angle')) then
                call equivalent_block(s%body, eq, stat, msg, alpha=equivalent_angle)
            else
                call equivalent_block(s%body, eq, stat, msg)
            end if
        end if
    end subroutine equivalent_body

    !> "solid cylinder", "block", ... of a BODY_* code.
    pure function shape_text(code) result(text)
        integer, intent(in) :: code
        character(len=:), allocatable :: text
        select case (code)
        case (BODY_SOLID_CYLINDER)
            text = 'solid cylinder'
        case (BODY_HOLLOW_CYLINDER)
            text = 'hollow cylinder'
        case (BODY_CUSTOM)
            text = 'body of revolution with a given J_o'
        case default
            text = 'uniform block'
        end select
    end function shape_text

    !> Header line of the body.
    function body_line(s) result(line)
        type(setup_t), intent(in) :: s
        character(len=:), allocatable :: line
        line = 'body: '//shape_text(s%body%shape)//', theta_c = '//shortest_str(s%body%theta_c) &
               //' rad, p = '//shortest_str(s%body%p)//' rad/s, e = '//shortest_str(s%e_run)
        if (s%e_given) then
            line = line//' (given; Housner: '//shortest_str(s%body%e)//')'
        else
            line = line//' (Housner)'
        end if
        line = line//', g = '//shortest_str(s%body%g)//' m/s2'
    end function body_line

    ! ------------------------------------------------------------------------------
    ! Properties
    ! ------------------------------------------------------------------------------

    !> 'props': the table of the body and of its equivalent body.
    subroutine do_props(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        integer, parameter :: nrow = 20
        type(rocking_body_t) :: eq
        character(len=512) :: msg, files(2), comments(6)
        character(len=20) :: labels(nrow)
        real(dp) :: table(nrow, 2)

        call echo(s)
        msg = ''
        call equivalent_body(s, eq, stat, msg)
        if (stat /= SEISPULSE_SUCCESS) then
            stat = 1
            errmsg = located(path, s%gb)//'equivalent body: '//trim(msg)
            return
        end if
        labels = [character(len=20) :: 'shape (-)', 'r (m)', 'r_inner (m)', 'h (m)', &
                  'mass (kg)', 'g (m/s2)', 'theta_c (rad)', 'theta_c (deg)', 'h/r (-)', &
                  'R (m)', 'J_o (kg m2)', 'J_G (kg m2)', 'J_axis (kg m2)', 'J_o/(m R2) (-)', &
                  'p (rad/s)', 'e (-)', 'W (N)', 'M_max (N m)', 'F_uplift (N)', &
                  'tan(theta_c) (g)']
        table(:, 1) = props_column(s%body)
        table(:, 2) = props_column(eq)
        comments(1) = 'seispulse analysis cylinder: properties of the body and of its ' &
                      //'equivalent '//trim(merge('solid cylinder', 'block         ', &
                      s%body%shape == BODY_BLOCK))//' (seispulse_cylinder)'
        comments(2) = 'shape: body '//trim(shape_names(s%body%shape))//', equivalent ' &
                      //trim(shape_names(eq%shape))//' (the row holds the code of each: 1 ' &
                      //'solid, 2 hollow, 3 custom, 4 block); r: base radius, or the ' &
                      //'half-width b of a block; h: height of the centre of mass'
        comments(3) = 'equivalent: the same p and the same M_max = m g r, slenderness ' &
                      //merge('equivalent_angle (given)', 'theta_c of the body     ', &
                      given(s%gb, 'equivalent_angle'))
        comments(4) = 'R = sqrt(r^2 + h^2), p = sqrt(m g R/J_o), e = max(0, 1 - (2 m R^2/' &
                      //'J_o) sin^2 theta_c) (Housner), uplift at |a_g| > g tan(theta_c)'
        comments(5) = 'M_max: pushover moment at theta = 0; F_uplift = W r/h at the centre ' &
                      //'of mass; J_axis NaN: unknown (a block''s depth)'
        comments(6) = 'input: '//trim(path)
        call write_tables(prefix, 'cylinder_props', comments, &
            [character(len=10) :: 'quantity', 'body', 'equivalent'], &
            [character(len=8) :: 'in name', 'as named', 'as named'], table, files, stat, &
            errmsg, labels=labels)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('cylinder properties', files)
    end subroutine do_props

    !> The rows of the properties table for one body.
    function props_column(bd) result(col)
        type(rocking_body_t), intent(in) :: bd
        real(dp) :: col(20)
        col = [real(bd%shape, dp), bd%r, bd%r_inner, bd%h, bd%mass, bd%g, bd%theta_c, &
               bd%theta_c * (180.0_dp / pi), bd%h / bd%r, bd%big_r, bd%j_o, bd%j_g, &
               bd%j_axis, bd%j_o / (bd%mass * bd%big_r**2), bd%p, bd%e, bd%weight, &
               bd%m_max, bd%f_uplift, tan(bd%theta_c)]
    end function props_column

    ! ------------------------------------------------------------------------------
    ! Pushover
    ! ------------------------------------------------------------------------------

    !> 'pushover': F, M, M/(m g r) and the stable flag over the grid of tilts
    !> (doc/cylinder.md section 4).
    subroutine do_pushover(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, grid, key
        character(len=512) :: msg, files(2), comments(6)
        real(dp), allocatable :: th(:), u(:), table(:, :)
        real(dp) :: force, moment
        logical :: stable, by_ratio
        integer :: i, n

        where = located(path, s%gc)
        stat = 1
        msg = ''
        if ((given(s%gc, 'theta') .or. given(s%gc, 'theta_range') .or. &
             given(s%gc, 'theta_count')) .and. (given(s%gc, 'theta_ratio') .or. &
             given(s%gc, 'theta_ratio_range') .or. given(s%gc, 'theta_ratio_count'))) then
            errmsg = where//'theta, theta_ratio: give the grid in one of them (theta in ' &
                     //'rad, or theta_ratio = theta/theta_c)'
            return
        end if
        by_ratio = .not. (given(s%gc, 'theta') .or. given(s%gc, 'theta_range') .or. &
                          given(s%gc, 'theta_count'))
        if (by_ratio) then
            key = 'theta_ratio'
            if (given(s%gc, 'theta_ratio') .or. given(s%gc, 'theta_ratio_range') .or. &
                given(s%gc, 'theta_ratio_count')) then
                call axis_values(s%gc, 'theta_ratio', 'theta_ratio', theta_ratio, &
                                 theta_ratio_range, theta_ratio_count, 'linear', .false., &
                                 .true., max_list, th, grid, errmsg, required=.true., &
                                 count_optional=.true.)
            else
                ! the default grid: theta/theta_c = 0, 0.05, .., 1
                th = [(real(i, dp) / real(pushover_default_count - 1, dp), &
                       i = 0, pushover_default_count - 1)]
                grid = 'theta_ratio = 0 .. 1, '//int_str(pushover_default_count)//' values ' &
                       //'(default)'
            end if
        else
            key = 'theta'
            call axis_values(s%gc, 'theta', 'theta', theta, theta_range, theta_count, &
                             'linear', .false., .true., max_list, th, grid, errmsg, &
                             required=.true., count_optional=.true.)
        end if
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        n = size(th)
        allocate(u(n))
        if (by_ratio) then
            u = th
            th = u * s%body%theta_c
        else
            u = th / s%body%theta_c
        end if
        do i = 1, n
            if (th(i) > 0.5_dp * pi) then
                errmsg = where//list_item(key, i)//': theta = '//real_str(th(i))//' rad: ' &
                         //'must be <= pi/2 (the body lies on its side)'
                return
            end if
        end do
        allocate(table(n, 6))
        do i = 1, n
            call rigid_pushover(s%body, th(i), force, moment, stable, stat, msg)
            if (stat /= SEISPULSE_SUCCESS) then
                stat = 1
                errmsg = where//list_item(key, i)//': '//trim(msg)
                return
            end if
            table(i, :) = [th(i), u(i), force, moment, &
                           normalized_pushover(s%body%theta_c, u(i)), &
                           merge(1.0_dp, 0.0_dp, stable)]
        end do

        call echo(s)
        comments(1) = 'seispulse analysis cylinder: static pushover on a rigid base ' &
                      //'(seispulse_cylinder, doc/cylinder.md)'
        comments(2) = body_line(s)//', W = '//shortest_str(s%body%weight)//' N, M_max = ' &
                      //shortest_str(s%body%m_max)//' N m'
        comments(3) = 'force: horizontal force at the centre of mass (N) that holds the ' &
                      //'body at theta, W tan(theta_c - theta); moment about the pivot ' &
                      //'(N m), W R sin(theta_c - theta)'
        comments(4) = 'm_ratio = M/(m g r) (r: the half-width of a block); stable: a flag, ' &
                      //'1 (true) for theta <= theta_c, else 0 (F < 0: the body falls on its own)'
        comments(5) = 'grid: '//grid
        comments(6) = 'input: '//trim(path)
        call write_tables(prefix, 'cylinder_pushover', comments, &
            [character(len=12) :: 'theta', 'theta_ratio', 'force', 'moment', 'm_ratio', &
             'stable'], &
            [character(len=4) :: 'rad', '-', 'N', 'N m', '-', '-'], table, files, stat, errmsg, &
            kinds=[character(len=3) :: '', '', '', '', '', 'int'])
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('cylinder pushover', files)
    end subroutine do_pushover

    ! ------------------------------------------------------------------------------
    ! History
    ! ------------------------------------------------------------------------------

    !> The summary columns of a run (after any label and pga).
    function summary_row(s, run) result(row)
        type(setup_t), intent(in) :: s
        type(rocking_run_t), intent(in) :: run
        real(dp) :: row(13)
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        row = nan
        row(1:4) = [s%body%theta_c, s%body%p, s%e_run, real(run%outcome, dp)]
        row(5:6) = [run%t_uplift, run%t_overturn]
        row(7) = real(run%n_impacts, dp)
        if (run%n_impacts > 0) row(8) = run%t_impacts(1)
        row(9:13) = [run%theta_max, run%theta_min, run%theta_max / s%body%theta_c, &
                     run%theta_min / s%body%theta_c, run%t_end]
    end function summary_row

    !> Header lines shared by the two tables of a history.
    subroutine history_comments(s, excitation, lines)
        type(setup_t), intent(in) :: s
        character(len=*), intent(in) :: excitation
        character(len=*), intent(out) :: lines(3)
        lines(1) = 'seispulse analysis cylinder: planar rocking on a rigid base under ' &
                   //excitation//', '//trim(model)//' model (seispulse_rocking_sim)'
        lines(2) = body_line(s)
        lines(3) = 'uplift at |a_g| > g tan(theta_c) (nonlinear) or g theta_c ' &
                   //'(linearized); a_g > 0 drives theta > 0'
        if (abs(kv) > 0.0_dp) lines(3) = 'vertical ground acceleration a_v = kv a_g, kv = ' &
            //shortest_str(kv)//' (doc/rocking.md section 7): uplift at a_g > g t/(1 - kv t) or ' &
            //'a_g < -g t/(1 + kv t), t = tan(theta_c) (nonlinear) or theta_c ' &
            //'(linearized); a_g > 0 drives theta > 0'
    end subroutine history_comments

    !> 'history' under the pulse of &pulse: the summary and the history tables.
    subroutine do_history_pulse(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(rocking_run_t) :: run
        character(len=512) :: msg, files(2), files2(2), comments(6)
        real(dp), allocatable :: t(:), table(:, :), v(:), d(:)
        real(dp) :: t_last
        integer :: n, i

        call echo(s)
        stat = 1
        msg = ''
        call rock_pulse(s%blk, s%pin%p, run, i, msg, t_max=t_max, rtol=rtol, kv=kv)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = locate_message(path, trim(msg), s)
            return
        end if
        ! --- the grid: up to t_end, or past the end of the motion
        t_last = t_end
        if (ieee_is_nan(t_end)) then
            if (run%outcome == ROCK_RUN_TIME_LIMIT .and. run%t_end > 0.0_dp) then
                t_last = run%t_end               ! no solution beyond it
            else
                t_last = max(1.25_dp * run%t_end, pulse_end(s%pin))
            end if
        end if
        call time_grid(t_last, dt, npts, t, errmsg)
        if (len(errmsg) > 0) then
            errmsg = located(path, s%gc)//errmsg
            return
        end if
        n = size(t)
        allocate(table(n, 4), v(n), d(n))
        call rock_pulse(s%blk, s%pin%p, run, i, msg, t_grid=t, theta_grid=table(:, 3), &
                        omega_grid=table(:, 4), t_max=t_max, rtol=rtol, kv=kv)
        if (i == SEISPULSE_SUCCESS) call pulse_eval(s%pin%p, t, table(:, 2), v, d, i, msg)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = locate_message(path, trim(msg), s)
            return
        end if
        table(:, 1) = t

        call history_comments(s, pulse_kind_name(s%pin%code)//' pulse', comments(1:3))
        comments(4) = 't_overturn: last outward crossing of |theta| = theta_c before ' &
                      //'overturning; t_impact1: first impact; t_end: rest, overturned ' &
                      //'(|theta| = pi/2) or the time limit; 0 without uplift'
        comments(5) = 'psi = theta/theta_c; NaN: no such event'
        comments(6) = 'input: '//trim(path)
        call write_tables(prefix, 'cylinder', comments, summary_names(.false.), &
            summary_units(.false.), reshape(summary_row(s, run), [1, 13]), files, stat, &
            errmsg, kinds=run_summary_kinds(13, 4, run_outcome_names, 7), summary=.true.)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        comments(4) = 'outcome: '//trim(run_outcome_names(run%outcome))//', t_uplift = ' &
                      //shortest_str(run%t_uplift)//' s, impacts: '//int_str(run%n_impacts) &
                      //', theta_max = '//shortest_str(run%theta_max)//' rad, theta_min = ' &
                      //shortest_str(run%theta_min)//' rad, t_end = '//shortest_str(run%t_end)//' s'
        comments(5) = 'theta: rotation (rad; > 0 about one edge, < 0 about the other), ' &
                      //'omega = dtheta/dt (rad/s); overturned: theta = +-pi/2, omega = 0 ' &
                      //'after t_end; NaN after a time limit'
        call write_tables(prefix, 'cylinder_history', comments, &
            [character(len=8) :: 't', 'a_g', 'theta', 'omega'], &
            [character(len=8) :: 's', 'm/s2', 'rad', 'rad/s'], table, files2, stat, errmsg)
        if (stat /= 0) then
            call delete_files(files)
            errmsg = output_located(path)//errmsg
            return
        end if
        write(output_unit, '(a)') 'cylinder: '//trim(run_outcome_names(run%outcome))
        call say_written('cylinder summary', files)
        call say_written('cylinder history', files2)
    end subroutine do_history_pulse

    !> Names of the summary table (with the record and pga columns for records).
    function summary_names(records) result(names)
        logical, intent(in) :: records
        character(len=12), allocatable :: names(:)
        character(len=12), parameter :: base(13) = [character(len=12) :: 'theta_c', 'p', &
            'e', 'outcome', 't_uplift', 't_overturn', 'n_impacts', 't_impact1', 'theta_max', &
            'theta_min', 'psi_max', 'psi_min', 't_end']
        if (records) then
            names = [character(len=12) :: 'record', 'pga', base]
        else
            names = base
        end if
    end function summary_names

    !> Units of the summary table (with the record and pga columns for records).
    function summary_units(records) result(units)
        logical, intent(in) :: records
        character(len=6), allocatable :: units(:)
        character(len=6), parameter :: base(13) = [character(len=6) :: 'rad', 'rad/s', '-', &
            '-', 's', 's', '-', 's', 'rad', 'rad', '-', '-', 's']
        if (records) then
            units = [character(len=6) :: '-', 'g', base]
        else
            units = base
        end if
    end function summary_units

    !> Planar rocking under each record of &records: a summary row and the history rows
    !> of each (a record that cannot be read or run: NaN, the others go on).
    subroutine do_history_records(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(rocking_run_t), allocatable :: runs(:)
        type(record_out_t), allocatable :: outs(:)
        character(len=:), allocatable :: grid_msg
        character(len=512) :: files(2), files2(2)
        character(len=1024), allocatable :: comments(:)
        character(len=256), allocatable :: labels(:), hlabels(:)
        real(dp), allocatable :: summary(:, :), hist(:, :)
        real(dp) :: nan
        integer :: nrec, ir, nfailed
        logical, allocatable :: failed(:)

        nan = ieee_value(nan, ieee_quiet_nan)
        call echo(s)
        call rock_records(located(path, s%gr), 'cylinder', s%recs, s%slammer_rounding, s%blk, &
                          s%body%g, kv, t_max, rtol, .true., t_end, dt, npts, outs, failed, &
                          runs, hist, hlabels, grid_msg, ir)
        if (len(grid_msg) > 0) then
            stat = 1
            errmsg = located(path, s%gc)//list_item('files', ir)//': '//grid_msg
            return
        end if
        nrec = size(s%recs)
        allocate(labels(nrec), summary(nrec, 14))
        summary = nan
        do ir = 1, nrec
            labels(ir) = outs(ir)%name
            if (failed(ir)) cycle
            summary(ir, 1) = outs(ir)%pga
            summary(ir, 2:14) = summary_row(s, runs(ir))
        end do

        allocate(comments(5 + nrec))
        call history_comments(s, 'records (&records; the samples in g, linear in between, ' &
                              //'0 after the last)', comments(1:3))
        comments(4) = 'pga: after scaling (g); psi = theta/theta_c; NaN: no such event, or ' &
                      //'a record that failed; t_end: rest, overturned or the time limit'
        do ir = 1, nrec
            comments(4 + ir) = record_line(ir, s%recs(ir), outs(ir))
            if (outs(ir)%ok .and. failed(ir)) comments(4 + ir) = trim(comments(4 + ir)) &
                //'; FAILED: '//outs(ir)%message
        end do
        comments(5 + nrec) = 'input: '//trim(path)
        call write_tables(prefix, 'cylinder', comments, summary_names(.true.), &
            summary_units(.true.), summary, files, stat, errmsg, labels=labels, &
            kinds=run_summary_kinds(15, 6, run_outcome_names, 9))
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        comments(4) = 'rows: each record from t = 0; theta (rad), omega = dtheta/dt ' &
                      //'(rad/s), a_g = g x the record (m/s2); NaN: a record that failed'
        call write_tables(prefix, 'cylinder_history', comments, &
            [character(len=8) :: 'record', 't', 'a_g', 'theta', 'omega'], &
            [character(len=8) :: '-', 's', 'm/s2', 'rad', 'rad/s'], hist, files2, stat, &
            errmsg, labels=hlabels)
        if (stat /= 0) then
            call delete_files(files)
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('cylinder summary', files)
        call say_written('cylinder history', files2)
        stat = 0
        nfailed = count(failed)
        if (nfailed > 0) then
            stat = ROWS_FAILED
            errmsg = int_str(nfailed)//' of '//int_str(nrec)//' records failed (' &
                     //failed_records(outs, failed)//'): their rows hold NaN'
        end if
    end subroutine do_history_records

    !> Where a library message about a run belongs: &pulse, &cylinder or &body.
    function locate_message(path, msg, s) result(full_msg)
        character(len=*), intent(in) :: path, msg
        type(setup_t), intent(in) :: s
        character(len=:), allocatable :: full_msg
        full_msg = locate_run_message(path, msg, s%pin%group, pulse_keys, s%gc, cylinder_keys, &
                                      s%gb)
    end function locate_message

    ! ------------------------------------------------------------------------------
    ! Overturning map
    ! ------------------------------------------------------------------------------

    !> 'map': the overturning map on the chosen axes (doc/cylinder.md section 6), with the
    !> equivalent block's map and the difference on request.
    subroutine do_map(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, grid, grid_x, ykey
        character(len=512) :: msg, files(2), comments(9)
        character(len=12), allocatable :: names(:)
        character(len=4), allocatable :: units(:)
        character(len=128), allocatable :: kinds(:)
        real(dp), allocatable :: xs(:), ys(:), table(:, :)
        integer, allocatable :: classes(:, :), classes_b(:, :), diff(:, :)
        type(rocking_body_t) :: eq
        type(pulse_t) :: tpl
        integer :: code, i, st, axes_code
        type(progress_t) :: progress

        where = located(path, s%gm)
        stat = 1
        msg = ''
        call map_axes_code(where, axes, axes_code, errmsg)
        if (len(errmsg) > 0) return
        axes = axes_names(axes_code)
        call map_kind(where, kind, code, errmsg)
        if (len(errmsg) > 0) return
        if (compare_block .and. s%body%shape == BODY_BLOCK) then
            errmsg = where//'compare_block: the body is a block already (shape = ''block'')'
            return
        end if
        ! --- the two axes, on the chosen system only
        call map_grids(where, s%gm, axes_code, freq_ratio, freq_range, freq_count, amp_ratio, &
                       amp_range, amp_count, freq_hz, freq_hz_range, freq_hz_count, pga, &
                       pga_range, pga_count, max_list, xs, ys, grid_x, grid, ykey, errmsg)
        if (len(errmsg) > 0) return
        ! the shape at a unit time scale (the map checks every time scale)
        call map_template(where, code, beta, full, peak_frac, t0_periods, cycles, tpl, errmsg)
        if (len(errmsg) > 0) return
        if (compare_block) then
            call equivalent_body(s, eq, st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = located(path, s%gb)//'equivalent block: '//trim(msg)
                return
            end if
        end if
        call warn_unused_template(path, s%gm, code)

        call echo(s)
        allocate(classes(size(ys), size(xs)), classes_b(size(ys), size(xs)), &
                 diff(size(ys), size(xs)))
        call progress%start()
        do i = 1, size(ys)
            call body_overturning_map(s%body, code, xs, ys(i:i), axes_code, &
                                      classes(i:i, :), st, msg, template=tpl, &
                                      linearized=s%linearized, e=s%e_run, rtol=rtol, kv=kv)
            if (st == SEISPULSE_SUCCESS .and. compare_block) &
                call body_overturning_map(eq, code, xs, ys(i:i), axes_code, &
                                          classes_b(i:i, :), st, msg, template=tpl, &
                                          linearized=s%linearized, rtol=rtol, kv=kv)
            if (st /= SEISPULSE_SUCCESS) then
                if (index(msg, 'kv') == 1) then
                    ! each row runs alone: name the user's amplitude, not the library's
                    errmsg = located(path, s%gc)//'kv = '//real_str(kv)//': a_v = kv a_g ' &
                             //'falls below -g at '//list_item(trim(ykey), i)//' = ' &
                             //real_str(ys(i))//' (the body would leave the ground)'
                else if (index(msg, 'rtol') == 1) then
                    errmsg = located(path, s%gc)//trim(msg)
                else
                    errmsg = where//trim(msg)
                end if
                return
            end if
            call progress%row(i, size(ys))
        end do
        call progress%done(size(ys))
        if (compare_block) then
            call map_difference(classes, classes_b, diff, st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = where//'compare_block: '//trim(msg)
                return
            end if
        end if

        ! --- the table: both axis systems, the chosen one first
        if (compare_block) then
            call map_table(axes_code, xs, ys, s%body%p, s%body%theta_c, classes, table, &
                           classes_b, diff)
            call map_axes_header(axes_code, names, units, 'class_block')
            kinds = [character(len=128) :: '', '', '', '', category_kind(map_class_names), &
                     category_kind(map_class_names), category_kind(diff_names)]
        else
            call map_table(axes_code, xs, ys, s%body%p, s%body%theta_c, classes, table)
            call map_axes_header(axes_code, names, units)
            kinds = [character(len=128) :: '', '', '', '', category_kind(map_class_names)]
        end if
        comments(1) = 'seispulse analysis cylinder: overturning map, '//pulse_kind_name(code) &
                      //' pulse family, '//trim(model)//' model (seispulse_cylinder)'
        comments(2) = body_line(s)
        comments(3) = map_class_line
        comments(4) = 'freq_ratio = omega_p/p = 2 pi freq_hz/p (T_p: t_d of the ' &
                      //'exponential pulse, the period of sine/cosine cycles, the length ' &
                      //'of the others; Ricker: f_p); amp_ratio = a_p/(g tan theta_c) = ' &
                      //'pga/tan theta_c'
        comments(5) = 'axes = '''//trim(axes)//''' (the first two columns); rows: '// &
                      trim(names(2))//' outer, '//trim(names(1))//' inner'
        comments(6) = template_text(tpl)
        if (abs(kv) > 0.0_dp) comments(6) = trim(comments(6))//'; vertical ground acceleration ' &
            //'a_v = kv a_g in every cell, kv = '//shortest_str(kv)//' (doc/rocking.md section 7)'
        if (compare_block) then
            comments(7) = 'class_block: the equivalent block (same p, same M_max, alpha = ' &
                          //shortest_str(eq%theta_c)//' rad, Housner e = '//shortest_str(eq%e) &
                          //') on the same '//trim(names(1))//', '//trim(names(2))
            comments(8) = 'diff: only_cylinder, only_block: only one of the two overturns, ' &
                          //'other_mode: both, in different classes; grid: '//grid_x//', '//grid
        else
            comments(7) = 'compare_block = .false.: no block map'
            comments(8) = 'grid: '//grid_x//', '//grid
        end if
        comments(9) = 'input: '//trim(path)
        call write_tables(prefix, 'cylinder_map', comments, names, units, table, files, &
                          stat, errmsg, kinds=kinds)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('cylinder map', files)

    end subroutine do_map

    ! ------------------------------------------------------------------------------
    ! Rocking with rolling (3-D)
    ! ------------------------------------------------------------------------------

    !> The 3-D motion of a circular cylinder rocking and rolling on its rim without slip
    !> (seispulse_cylinder_roll, [KM90]): under the pulse of &pulse along `direction`,
    !> under one record (x) or two (x, y) of &records, or free from the state of &roll.
    subroutine do_roll(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        integer, parameter :: nsum = 14
        type(roll_run_t) :: run
        type(record_out_t) :: outs(2)
        type(pulse_t), allocatable :: pl
        character(len=:), allocatable :: where, excitation
        character(len=512) :: msg, files(2), files2(2), comments(8)
        character(len=16) :: names(3 + ROLL_NOUT)
        character(len=6) :: units(3 + ROLL_NOUT)
        character(len=24) :: onames(0:3)
        real(dp), allocatable :: ax(:), ay(:), accel(:), t(:), hist(:, :), table(:, :), &
                                 v(:), d(:), a(:), rt
        real(dp) :: one_time(1), one_hist(ROLL_NOUT, 1), t_last, t_exc, rec_dt, row(nsum), nan, &
                    t_run
        integer :: nrec, ir, k, st, n
        logical :: echoed

        nan = ieee_value(nan, ieee_quiet_nan)
        echoed = .false.
        where = located(path, s%gc)
        stat = 1
        msg = ''
        rec_dt = 1.0_dp
        t_exc = 0.0_dp
        ! --- the excitation
        if (s%use_records) then
            nrec = size(s%recs)
            if (nrec > 2) then
                errmsg = located(path, s%gr)//'files: what = ''roll'' takes one record (the ' &
                         //'x component) or two (x, y), not '//int_str(nrec)
                return
            end if
            do ir = 1, nrec
                call load_record(located(path, s%gr), s%recs(ir), ir, nrec, 'cylinder', &
                                 s%slammer_rounding, outs(ir), accel)
                if (.not. outs(ir)%ok) then
                    errmsg = located(path, s%gr)//record_place(ir, s%recs(ir))//': ' &
                             //outs(ir)%message
                    return
                end if
                if (ir == 1) then
                    ax = accel
                    rec_dt = outs(1)%dt
                else
                    ay = accel
                end if
            end do
            if (nrec == 2) then
                if (abs(outs(2)%dt - outs(1)%dt) > 0.0_dp) then
                    errmsg = located(path, s%gr)//'files: the two components have different ' &
                             //'time steps ('//real_str(outs(1)%dt)//' s, ' &
                             //real_str(outs(2)%dt)//' s)'
                    return
                end if
                ! the shorter one is 0 after its last sample
                n = max(size(ax), size(ay))
                ax = [ax, spread(0.0_dp, 1, n - size(ax))]
                ay = [ay, spread(0.0_dp, 1, n - size(ay))]
            else
                allocate(ay(size(ax)))
                ay = 0.0_dp
            end if
            t_exc = rec_dt * real(size(ax) - 1, dp)
            excitation = 'records (x: '//outs(1)%name
            if (nrec == 2) excitation = excitation//', y: '//outs(2)%name
            excitation = excitation//'; in g, linear in between, 0 after the last sample)'
        else if (s%pin%group%line > 0) then
            pl = s%pin%p
            t_exc = pulse_end(s%pin)
            excitation = pulse_kind_name(s%pin%code)//' pulse along direction = ' &
                         //shortest_str(direction)//' rad from the x axis'
        else
            if (.not. (abs(theta0) > 0.0_dp .or. abs(theta_rate0) > 0.0_dp)) then
                if (s%gl%line > 0) then
                    errmsg = located(path, s%gl)//'theta0, theta_rate0: the body starts ' &
                             //'upright at rest and nothing moves the base (give &pulse, ' &
                             //'&records, or an initial tilt or rate)'
                else
                    errmsg = missing_group(path, 'pulse')//' (what = ''roll'' needs an ' &
                             //'excitation, &pulse or &records, or an initial state in &roll)'
                end if
                return
            end if
            excitation = 'no ground motion (free rocking from the initial state)'
        end if
        if (given(s%gl, 'direction') .and. .not. allocated(pl)) write(error_unit, '(a)') &
            'warning: '//located(path, s%gl)//'direction: not used without &pulse (records ' &
            //'give x and y)'
        if (given(s%gc, 'rtol')) rt = rtol
        ! the end of the run: t_max, else t_end, else the excitation and 20 periods 2 pi/p
        ! (with spin the body may roll round its rim for ever without an impact)
        t_run = t_max
        if (.not. given(s%gc, 't_max')) then
            if (ieee_is_nan(t_end)) then
                t_run = t_exc + 20.0_dp * (2.0_dp * pi / s%body%p)
            else
                t_run = t_end
            end if
        end if

        ! --- the grid: up to t_end, or past the end of the motion
        t_last = t_end
        if (ieee_is_nan(t_end)) then
            one_time = 0.0_dp
            call roll_once(one_time, one_hist)
            if (st /= SEISPULSE_SUCCESS) return
            if (run%outcome == ROLL_RUN_TIME_LIMIT .and. run%t_end > 0.0_dp) then
                t_last = run%t_end
            else
                t_last = max(1.25_dp * run%t_end, t_exc)
            end if
            if (.not. t_last > 0.0_dp) t_last = 1.0_dp       ! nothing moves: a short grid
        end if
        call time_grid(t_last, dt, npts, t, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        n = size(t)
        allocate(hist(ROLL_NOUT, n), table(n, 3 + ROLL_NOUT), a(n))
        call roll_once(t, hist)
        if (st /= SEISPULSE_SUCCESS) return
        table(:, 1) = t
        table(:, 2:3) = 0.0_dp
        if (allocated(pl)) then
            allocate(v(n), d(n))
            call pulse_eval(pl, t, a, v, d, st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = located(path, s%pin%group)//trim(msg)
                return
            end if
            table(:, 2) = a * cos(direction)
            table(:, 3) = a * sin(direction)
        else if (s%use_records) then
            table(:, 2) = s%body%g * record_at(ax, rec_dt, t)
            table(:, 3) = s%body%g * record_at(ay, rec_dt, t)
        end if
        table(:, 4:) = transpose(hist)

        ! --- the summary
        row = nan
        row(1:4) = [s%body%theta_c, s%body%p, s%e_run, real(run%outcome, dp)]
        row(5:7) = [run%t_uplift, real(run%n_impacts, dp), real(run%n_floor, dp)]
        if (run%n_impacts > 0) row(8) = run%t_impacts(1)
        row(9:14) = [run%theta_max, run%theta_max / s%body%theta_c, run%friction_max, &
                     run%t_lift_off, run%energy_drift, run%t_end]
        do k = 0, 3
            onames(k) = roll_outcome_name(k)
        end do
        comments(1) = 'seispulse analysis cylinder: rocking with rolling on the base rim ' &
                      //'without slip ([KM90]; seispulse_cylinder_roll) under '//excitation
        comments(2) = body_line(s)//', J_G = '//shortest_str(s%body%j_g)//' kg m2, J_axis = ' &
                      //shortest_str(s%body%j_axis)//' kg m2, m = '//shortest_str(s%body%mass) &
                          //' kg'
        comments(3) = 'initial state: theta0 = '//shortest_str(theta0)//' rad, psi0 = ' &
                      //shortest_str(psi0)//' rad, spin0 = '//shortest_str(spin0)//' rad, rates ' &
                      //shortest_str(theta_rate0)//', '//shortest_str(psi_rate0)//', ' &
                      //shortest_str(spin_rate0)//' rad/s'
        comments(4) = 'theta: tilt (>= 0), psi: heading of the rocking plane (jumps by pi at ' &
                      //'an impact), spin: about the axis of symmetry; contact point and ' &
                      //'centre of mass in the ground frame (m), from the centre of mass at (0, 0)'
        comments(5) = 'friction_demand = |F_t|/N (no slip needs mu >= it); energy: kinetic + ' &
                      //'potential (J); n_floor: impacts counted by the floor rule; ' &
                      //'energy_drift: largest |E - E0|/(E0 - m g h) in free flight'
        comments(6) = 'overturned: theta = pi/2 and the rates 0 after t_end (N, friction, ' &
                      //'energy NaN); NaN after a time limit; t_lift_off: first N <= 0 (NaN: never)'
        comments(7) = 'input: '//trim(path)
        call write_tables(prefix, 'cylinder_roll', comments(1:7), &
            [character(len=16) :: 'theta_c', 'p', 'e', 'outcome', 't_uplift', 'n_impacts', &
             'n_floor', 't_impact1', 'theta_max', 'theta_ratio_max', 'friction_max', &
             't_lift_off', 'energy_drift', 't_end'], &
            [character(len=6) :: 'rad', 'rad/s', '-', '-', 's', '-', '-', 's', 'rad', '-', &
             '-', 's', '-', 's'], reshape(row, [1, nsum]), files, stat, errmsg, &
            kinds=[character(len=64) :: '', '', '', category_kind(onames), '', 'int', 'int', &
                   '', '', '', '', '', '', ''], summary=.true.)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        names(1:3) = [character(len=16) :: 't', 'a_x', 'a_y']
        units(1:3) = [character(len=6) :: 's', 'm/s2', 'm/s2']
        do k = 1, ROLL_NOUT
            names(3 + k) = roll_output_name(k)
            units(3 + k) = roll_units(k)
        end do
        comments(8) = 'outcome: '//roll_outcome_name(run%outcome)//', impacts: ' &
                      //int_str(run%n_impacts)//', theta_max = '//shortest_str(run%theta_max) &
                      //' rad, t_end = '//shortest_str(run%t_end)//' s'
        call write_tables(prefix, 'cylinder_roll_history', [comments(1:6), comments(8), &
            comments(7)], names, units, table, files2, stat, errmsg)
        if (stat /= 0) then
            call delete_files(files)
            errmsg = output_located(path)//errmsg
            return
        end if
        write(output_unit, '(a)') 'cylinder: '//roll_outcome_name(run%outcome)
        call say_written('cylinder roll summary', files)
        call say_written('cylinder roll history', files2)

    contains

        !> One run on the grid tg; st and errmsg (located) on failure.
        subroutine roll_once(tg, hg)
            real(dp), intent(in) :: tg(:)
            real(dp), intent(out) :: hg(:, :)
            character(len=:), allocatable :: key
            call echo_once()
            call cylinder_roll(s%body, tg, hg, run, st, msg, theta0=theta0, psi0=psi0, &
                               spin0=spin0, theta_rate0=theta_rate0, psi_rate0=psi_rate0, &
                               spin_rate0=spin_rate0, pulse=pl, direction=direction, &
                               accel_x=ax, accel_y=ay, dt=rec_dt, g_rec=s%body%g, e=s%e_run, &
                               t_max=t_run, rtol=rt)
            if (st == SEISPULSE_SUCCESS) return
            k = scan(msg, ' =:(,')
            key = ''
            if (k > 1) key = msg(1:k - 1)
            if (any(roll_keys == key)) then
                errmsg = located(path, s%gl)//trim(msg)
            else if (any(cylinder_keys == key)) then
                errmsg = located(path, s%gc)//trim(msg)
            else if (any(pulse_keys == key) .or. key == 'pulse') then
                errmsg = located(path, s%pin%group)//trim(msg)
            else if (index(key, 'accel') == 1) then
                errmsg = located(path, s%gr)//trim(msg)
            else
                errmsg = located(path, s%gb)//trim(msg)
            end if
        end subroutine roll_once

        subroutine echo_once()
            if (echoed) return
            echoed = .true.
            call echo(s)
        end subroutine echo_once

    end subroutine do_roll

    ! ------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------

    !> Echo the effective input: &pulse or &records for a history, &body, &cylinder, &map
    !> for a map.
    subroutine echo(s)
        type(setup_t), intent(in) :: s
        what = s%task
        if (s%task == 'history' .or. s%task == 'roll') then
            if (s%use_records) then
                call echo_records(s%recs, s%slammer_rounding)
            else if (s%pin%group%line > 0) then
                call write_pulse_group(echo_unit())
            end if
        end if
        write(echo_unit(), nml=body)
        write(echo_unit(), nml=cylinder)
        if (s%task == 'map') write(echo_unit(), nml=map)
        if (s%task == 'roll') write(echo_unit(), nml=roll)
    end subroutine echo

end module driver_cylinder
