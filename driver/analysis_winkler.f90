!> Analysis 'winkler': a rigid cylinder (circular footing) or block (rectangular footing) on
!> tensionless elastic Winkler soil, and a circular footing on undrained clay
!> (doc/winkler.md; [AD11] chapters 2 and 3, [KH91], [KSR86], [G91], [TC00]).
!>
!> Groups: &winkler (the body, the soil, what to compute and its grid), &pulse
!> (driver_pulse_group) or &records (driver_records) for a history, &map (the pulse family
!> and the grids of an overturning map). Six modes (`what`):
!>   * 'pushover': <output>_winkler_pushover (the static curve against theta) and
!>     <output>_winkler_pushover_summary (uplift, peaks, overturning);
!>   * 'master': <output>_winkler_master, the universal small-angle curve against
!>     theta/theta_up;
!>   * 'history': <output>_winkler (summary) and <output>_winkler_history, the planar
!>     rocking with settlement under one pulse or each record;
!>   * 'map': <output>_winkler_map, an overturning map on either axis system, with the
!>     rigid map of the same body and the difference on request;
!>   * 'inelastic': <output>_winkler_inelastic and <output>_winkler_inelastic_summary, the
!>     pushover on clay by the stiffness-degradation method;
!>   * 'capacity': <output>_winkler_capacity, the bearing capacity, the factor of safety
!>     and the moment capacities of a circular footing on clay.
!> File names by table_path (out/winkler_map + winkler_map: out/winkler_map.txt).
!> The numbers come from seispulse_winkler, seispulse_winkler_rock and
!> seispulse_clay_footing; the driver only reads, checks, converts units and writes. Every
!> table is computed before the first is written.
module driver_winkler
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan, &
                                             ieee_positive_inf
    use seispulse, only: dp, shortest_str, pi, pulse_t, pulse_kind_name, SEISPULSE_SUCCESS, &
                         real_str, &
                         int_str, finite_positive, rocking_body_t, cylinder_props, block_props, &
                         body_overturning_map, map_difference, FOOTING_CIRCLE, &
                         FOOTING_RECTANGLE, K_CONSTANT, K_VARYING, AXIS_LONG, AXIS_SHORT, &
                         winkler_modulus_circle, winkler_modulus_rect, winkler_pushover, &
                         block_winkler_pushover, winkler_pushover_t, winkler_master_curve, &
                         WP_THETA, WP_FORCE, WP_NCOL, DAMP_ROCKING, DAMP_VERTICAL, &
                         winkler_model_t, winkler_model, winkler_run_t, winkler_rock, &
                         winkler_overturning_map, winkler_output_name, &
                         WR_NOUT, WR_RUN_TIME_LIMIT, clay_bearing, degradation_coeffs_t, &
                         inelastic_pushover, inelastic_pushover_t, IP_NCOL, IP_FORCE, &
                         moment_capacity_circle, CAPACITY_TC00_PEAK, CAPACITY_EFFECTIVE_WIDTH
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
    use driver_tables, only: write_tables, say_written, stack, write_table_pair, category_kind
    use driver_axis, only: axis_values
    use driver_rocking_common, only: check_run_options, locate_run_message, map_kind, &
                                     map_template, progress_t, axes_names, map_axes_code, &
                                     map_grids, map_axes_header, map_table, run_summary_kinds, &
                                     map_class_names, winkler_outcome_names, map_class_line
    use driver_echo, only: echo_unit
    use driver_records, only: record_place
    implicit none
    private

    public :: run_winkler, winkler_groups, winkler_tables

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: winkler_groups(4) = [character(len=8) :: 'winkler', &
        'pulse', 'records', 'map']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=25), parameter :: winkler_tables(9) = [character(len=25) :: 'winkler_pushover', &
        'winkler_pushover_summary', 'winkler_master', 'winkler_inelastic', &
        'winkler_inelastic_summary', 'winkler_capacity', 'winkler', 'winkler_history', &
        'winkler_map']

    !> Every key of &winkler, and the modes that use it (letters of mode_letters).
    character(len=17), parameter :: winkler_keys(43) = [character(len=17) :: 'what', &
        'footing', 'r', 'b', 'alpha', 'h', 'mass', 'weight', 'g', 'k', 'g_mod', 'nu', &
        'k_method', 'reading', 'xi', 'damping_ref', 'c', 'su', 'nc', 'k_el', 'kr_c1', &
        'kr_c2', 'a_poly', 'b1', 'b2', 'c1', 'c2', 'log_base', 'theta', 'theta_range', &
        'theta_count', 'theta_max', 'spacing', 'theta_ratio', 'theta_ratio_range', &
        'theta_ratio_count', 't_max', 'rtol', 't_end', 'npts', 'dt', 'theta0', 'theta_rate0']
    character(len=6), parameter :: key_modes(43) = [character(len=6) :: 'PMHAIC', &
        'PMHAIC', 'PHAIC', 'PHA', 'PHA', 'PHAI', 'PHAIC', 'PHAIC', 'PHAIC', 'PHA', 'PHAI', &
        'PHAI', 'PHA', 'PHA', 'HA', 'HA', 'HA', 'IC', 'IC', 'I', 'I', &
        'I', 'I', 'I', 'I', 'I', 'I', 'I', 'PI', 'PI', &
        'PI', 'PI', 'PIM', 'M', 'M', &
        'M', 'H', 'HA', 'H', 'H', 'H', 'H', 'H']
    !> The modes, and their letters in key_modes.
    character(len=9), parameter :: what_names(6) = [character(len=9) :: 'pushover', &
        'master', 'history', 'map', 'inelastic', 'capacity']
    character(len=6), parameter :: mode_letters = 'PMHAIC'
    character(len=13), parameter :: map_keys(20) = [character(len=13) :: 'axes', 'kind', &
        'beta', 'full', 'peak_frac', 't0_periods', 'cycles', 'freq_ratio', 'freq_range', &
        'freq_count', 'amp_ratio', 'amp_range', 'amp_count', 'freq_hz', 'freq_hz_range', &
        'freq_hz_count', 'pga', 'pga_range', 'pga_count', 'compare_rigid']
    !> In the order of the FOOTING_*, K_*, AXIS_* and DAMP_* codes.
    character(len=6), parameter :: footing_names(2) = [character(len=6) :: 'circle', 'block']
    character(len=8), parameter :: k_method_names(2) = [character(len=8) :: 'constant', &
        'varying']
    character(len=5), parameter :: reading_names(2) = [character(len=5) :: 'long', 'short']
    character(len=8), parameter :: damping_names(2) = [character(len=8) :: 'rocking', &
        'vertical']
    !> Units of the WR_OUT_* columns of winkler_rock.
    character(len=5), parameter :: history_units(11) = [character(len=5) :: 'm', 'rad', &
        'm/s', 'rad/s', 'm', 'N', 'N m', 'm/s2', 'J', 'J', 'J']
    character(len=16), parameter :: diff_names(0:3) = [character(len=16) :: 'same', &
        'only_winkler', 'only_rigid', 'other_mode']

    !> Most values of a list (the theta grids, the map axes).
    integer, parameter :: max_list = 1000
    !> Points of the default grids: theta = 0 .. theta_c (pushover, inelastic),
    !> theta/theta_up = 0 .. master_default_top (master).
    integer, parameter :: grid_default_count = 101
    real(dp), parameter :: master_default_top = 10.0_dp

    ! namelist variables (defaults are set in set_defaults)
    character(len=32) :: what, footing, k_method, reading, damping_ref, spacing
    real(dp) :: r, b, alpha, h, mass, weight, g, k, g_mod, nu, xi, c
    real(dp) :: su, nc, k_el, kr_c1, kr_c2, a_poly(0:4), b1, b2, c1, c2, log_base
    real(dp) :: theta(max_list), theta_range(2), theta_max, theta_ratio(max_list), &
                theta_ratio_range(2)
    integer :: theta_count, theta_ratio_count, npts
    real(dp) :: t_max, rtol, t_end, dt, theta0, theta_rate0
    character(len=32) :: axes, kind
    real(dp) :: beta, peak_frac, t0_periods
    real(dp) :: cycles   !! sine_cycle, cosine_cycle: whole number of cycles (read as a real)
    logical :: full, compare_rigid
    real(dp) :: freq_ratio(max_list), freq_range(2), amp_ratio(max_list), amp_range(2)
    real(dp) :: freq_hz(max_list), freq_hz_range(2), pga(max_list), pga_range(2)
    integer :: freq_count, amp_count, freq_hz_count, pga_count
    namelist /winkler/ what, footing, r, b, alpha, h, mass, weight, g, k, g_mod, nu, &
        k_method, reading, xi, damping_ref, c, su, nc, k_el, kr_c1, kr_c2, a_poly, b1, b2, &
        c1, c2, log_base, theta, theta_range, theta_count, theta_max, spacing, theta_ratio, &
        theta_ratio_range, theta_ratio_count, t_max, rtol, t_end, npts, dt, theta0, &
        theta_rate0
    namelist /map/ axes, kind, beta, full, peak_frac, t0_periods, cycles, freq_ratio, &
        freq_range, freq_count, amp_ratio, amp_range, amp_count, freq_hz, freq_hz_range, &
        freq_hz_count, pga, pga_range, pga_count, compare_rigid

    !> The checked input of a run.
    type :: setup_t
        character(len=:), allocatable :: task     !! one of what_names
        integer :: footing = FOOTING_CIRCLE       !! FOOTING_*
        integer :: k_method = K_CONSTANT          !! K_*
        integer :: reading = AXIS_LONG            !! AXIS_*
        real(dp) :: weight = 0.0_dp               !! W = m g (N)
        real(dp) :: k = 0.0_dp                    !! full-contact Winkler modulus (N/m3)
        type(rocking_body_t) :: body              !! the body (SI), rigid theta_c and p
        type(winkler_model_t) :: model            !! the dynamic model (history, map)
        logical :: use_records = .false.          !! a history on &records
        type(pulse_input_t) :: pin                !! the pulse of a history
        type(record_in_t), allocatable :: recs(:) !! the records of a history
        logical :: slammer_rounding = .false.
        type(nml_group) :: gw, gm, gr             !! &winkler, &map, &records
    end type setup_t

contains

    !> The defaults of &winkler and &map, set before they are read.
    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        what = 'pushover'
        footing = 'circle'
        r = nan
        b = nan
        alpha = nan
        h = nan
        mass = nan
        weight = nan
        g = 9.80665_dp
        k = nan
        g_mod = nan
        nu = nan
        k_method = 'constant'
        reading = 'long'
        xi = 0.003_dp          ! [AD11]: 0.2 to 0.3 % for rocking
        damping_ref = 'rocking'
        c = nan
        su = nan
        nc = pi + 3.0_dp
        k_el = 1.0_dp
        kr_c1 = nan            ! the lost coefficients: no defaults
        kr_c2 = nan
        a_poly = nan
        b1 = nan
        b2 = nan
        c1 = nan
        c2 = nan
        log_base = nan         ! lost too: needed only when a(chi) /= 0
        theta = nan
        theta_range = nan
        theta_count = grid_default_count
        theta_max = nan
        spacing = 'linear'
        theta_ratio = nan
        theta_ratio_range = nan
        theta_ratio_count = grid_default_count
        t_max = ieee_value(t_max, ieee_positive_inf)
        rtol = 1.0e-10_dp
        t_end = nan            ! NaN: 1.25 x the end of the motion, at least the excitation's
        npts = 0               ! neither dt nor npts: 1001 points
        dt = 0.0_dp
        theta0 = 0.0_dp
        theta_rate0 = 0.0_dp
        axes = 'dimensionless'
        kind = 'sine_cycle'
        beta = 0.0_dp
        full = .false.
        peak_frac = 0.5_dp
        t0_periods = 1.5_dp
        cycles = 1.0_dp
        compare_rigid = .false.
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
    end subroutine set_defaults

    subroutine read_winkler(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=winkler, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=winkler, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_winkler

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

    !> Read the groups, compute, write the tables; print where they went. stat: 0,
    !> ROWS_FAILED (a history on records: the tables are written, some records failed;
    !> errmsg says which), or > 0 for an input or output error (nothing written).
    subroutine run_winkler(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(setup_t) :: s
        integer :: i, j, m

        call set_defaults()
        call records_defaults()
        call read_pulse_group(path, groups, s%pin, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'winkler', winkler_keys, read_winkler, s%gw, stat, &
                           errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'map', map_keys, read_map, s%gm, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'records', records_keys, read_records, s%gr, stat, &
                           errmsg)
        if (stat /= 0) return
        stat = 1

        ! --- what to compute, which groups and keys go with it
        if (find_group(groups, 'winkler') == 0) then
            errmsg = missing_group(path, 'winkler')//' (it gives the body and the soil: ' &
                     //'footing, r (or b and alpha), h, mass, k ...)'
            return
        end if
        s%task = trim(lower(adjustl(what)))
        m = name_index(what, what_names)
        if (m == 0) then
            errmsg = located(path, s%gw)//'what = '''//trim(what)//''': unknown (allowed: ' &
                     //join(what_names)//')'
            return
        end if
        what = s%task
        do i = 1, size(s%gw%items)
            j = name_index(s%gw%items(i)%key, winkler_keys)     ! > 0: check_keys passed
            if (index(key_modes(j), mode_letters(m:m)) == 0) then
                errmsg = located(path, s%gw)//s%gw%items(i)%key//': only with what = ' &
                         //modes_text(key_modes(j))//' (now what = '''//s%task//''')'
                return
            end if
        end do
        call check_groups(path, groups, s, errmsg)
        if (len(errmsg) > 0) return

        ! --- the excitation of a history (its g is the body's), then the body and soil
        if (s%task == 'history') then
            if (s%use_records) then
                call check_records(path, s%gr, s%recs, s%slammer_rounding, errmsg)
                if (len(errmsg) > 0) return
            else
                call build_pulse(path, s%pin, stat, errmsg, g_used=.true.)
                if (stat /= 0) return
                stat = 1
                if (given(s%gw, 'g') .and. .not. abs(g - s%pin%g) <= 0.0_dp) then
                    errmsg = located(path, s%gw)//'g = '//real_str(g)//': not the g of ' &
                             //'&pulse ('//real_str(s%pin%g)//' m/s2): with a pulse give g ' &
                             //'in &pulse'
                    return
                end if
                g = s%pin%g
            end if
        end if
        call check_winkler(path, s, errmsg)
        if (len(errmsg) > 0) return

        select case (s%task)
        case ('pushover')
            call do_pushover(path, prefix, s, stat, errmsg)
        case ('master')
            call do_master(path, prefix, s, stat, errmsg)
        case ('history')
            if (s%use_records) then
                call do_history_records(path, prefix, s, stat, errmsg)
            else
                call do_history_pulse(path, prefix, s, stat, errmsg)
            end if
        case ('map')
            call do_map(path, prefix, s, stat, errmsg)
        case ('inelastic')
            call do_inelastic(path, prefix, s, stat, errmsg)
        case default
            call do_capacity(path, prefix, s, stat, errmsg)
        end select
    end subroutine run_winkler

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> "'pushover', 'history' or 'map'" of the mode letters of a key.
    pure function modes_text(letters) result(text)
        character(len=*), intent(in) :: letters
        character(len=:), allocatable :: text
        integer :: i, n, j
        text = ''
        n = len_trim(letters)
        do i = 1, n
            j = index(mode_letters, letters(i:i))
            if (i > 1 .and. i == n) then
                text = text//' or '
            else if (i > 1) then
                text = text//', '
            end if
            text = text//''''//trim(what_names(j))//''''
        end do
    end function modes_text

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
        if (s%task /= 'map' .and. find_group(groups, 'map') > 0) then
            errmsg = located(path, s%gm)//'only with what = ''map'' (&winkler; now what = ''' &
                     //s%task//''')'
        else if (s%task == 'history') then
            if (has_pulse .and. has_records) then
                errmsg = located(path, s%gr)//'not with &pulse (a history runs under one ' &
                         //'pulse or under records: give one of the two groups)'
            else if (.not. (has_pulse .or. has_records)) then
                errmsg = missing_group(path, 'pulse')//' (what = ''history'' needs the ' &
                         //'excitation: &pulse, or &records with the record files)'
            end if
            s%use_records = has_records
        else if (has_pulse) then
            errmsg = located(path, s%pin%group)//'only with what = ''history'''
            if (s%task == 'map') errmsg = located(path, s%pin%group)//'not used by ' &
                //'what = ''map'' (the pulse family and shape of a map are in &map)'
        else if (has_records) then
            errmsg = located(path, s%gr)//'only with what = ''history'''
        else if (s%task == 'map' .and. find_group(groups, 'map') == 0) then
            errmsg = missing_group(path, 'map')//' (what = ''map'' needs the grids: ' &
                     //'freq_ratio or freq_range, amp_ratio or amp_range, or on axes = ' &
                     //'''dimensional'' freq_hz or freq_hz_range, pga or pga_range)'
        end if
    end subroutine check_groups

    !> Check &winkler for the task and build what it needs: the weight, the body, the
    !> Winkler modulus, the dynamic model. errmsg is empty on success.
    subroutine check_winkler(path, s, errmsg)
        character(len=*), intent(in) :: path
        type(setup_t), intent(inout) :: s
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=512) :: msg
        integer :: st
        logical :: dynamic, clay

        where = located(path, s%gw)
        errmsg = ''
        msg = ''
        dynamic = s%task == 'history' .or. s%task == 'map'
        clay = s%task == 'inelastic' .or. s%task == 'capacity'
        ! --- the footing and its size
        s%footing = name_index(footing, footing_names)
        if (s%footing == 0) then
            errmsg = where//'footing = '''//trim(footing)//''': unknown footing (allowed: ' &
                     //join(footing_names)//')'
            return
        end if
        footing = footing_names(s%footing)
        if (clay .and. s%footing /= FOOTING_CIRCLE) then
            errmsg = where//'footing = ''block'': what = '''//s%task//''' is for a ' &
                     //'circular footing on clay (footing = ''circle'')'
            return
        end if
        if (s%task == 'master') return
        if (s%footing == FOOTING_CIRCLE) then
            call refuse('b', 'footing = ''block'' (a circle takes the radius r)')
            call refuse('alpha', 'footing = ''block''')
            call required('r', 'the radius of the circular base, m')
        else
            call refuse('r', 'footing = ''circle'' (a block takes the half-width b)')
            call required('b', 'the half-width of the base in the rocking direction, m')
            call required('alpha', 'the half-length of the base out of the plane, m')
            if (len(errmsg) == 0 .and. .not. finite_positive(alpha)) errmsg = where &
                //'alpha = '//real_str(alpha)//': must be a finite number > 0 (m; the ' &
                //'half-length out of the plane)'
        end if
        if (s%task /= 'capacity') call required('h', 'the height of the centre of mass ' &
                                                //'above the base, m')
        if (len(errmsg) > 0) return
        ! --- gravity and the weight
        if (.not. finite_positive(g)) then
            errmsg = where//'g = '//real_str(g)//': must be a finite number > 0 (m/s2)'
            return
        end if
        if (given(s%gw, 'mass') .and. given(s%gw, 'weight')) then
            errmsg = where//'mass, weight: give one of them (kg, or N)'
            return
        else if (given(s%gw, 'mass')) then
            if (.not. finite_positive(mass)) then
                errmsg = where//'mass = '//real_str(mass)//': must be a finite number > 0 (kg)'
                return
            end if
            s%weight = mass * g
        else if (given(s%gw, 'weight')) then
            if (.not. finite_positive(weight)) then
                errmsg = where//'weight = '//real_str(weight)//': must be a finite number > 0 (N)'
                return
            end if
            s%weight = weight
            mass = weight / g
        else
            errmsg = where//'mass: missing (kg, or the weight in N)'
            return
        end if
        weight = s%weight
        ! --- the body (rigid theta_c and p, inertia)
        if (s%task /= 'capacity') then
            if (s%footing == FOOTING_CIRCLE) then
                call cylinder_props(r, h, mass, g, s%body, st, msg)
            else
                call block_props(b, h, mass, g, s%body, st, msg)
            end if
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = where//trim(msg)
                return
            end if
        end if
        if (clay) then
            call required('su', 'the undrained shear strength of the clay, Pa')
            if (s%task == 'inelastic') then
                call required('g_mod', 'the shear modulus of the soil, Pa')
                call required('nu', 'the Poisson ratio of the soil, in (0, 0.5)')
            end if
            return
        end if
        ! --- the Winkler modulus
        if (given(s%gw, 'k') .and. (given(s%gw, 'g_mod') .or. given(s%gw, 'nu'))) then
            errmsg = where//'k, g_mod: give k, or g_mod and nu to compute it (not both)'
            return
        else if (given(s%gw, 'k')) then
            if (.not. finite_positive(k)) then
                errmsg = where//'k = '//real_str(k)//': must be a finite number > 0 (N/m3, ' &
                         //'pressure per settlement)'
                return
            end if
            s%k = k
        else if (given(s%gw, 'g_mod') .or. given(s%gw, 'nu')) then
            call required('g_mod', 'the shear modulus of the soil, Pa; with nu it gives k')
            call required('nu', 'the Poisson ratio of the soil, in (0, 0.5); with g_mod it ' &
                          //'gives k')
            if (len(errmsg) > 0) return
            if (s%footing == FOOTING_CIRCLE) then
                call winkler_modulus_circle(g_mod, nu, r, s%k, st, msg)
            else
                call winkler_modulus_rect(g_mod, nu, 2.0_dp * b, 2.0_dp * alpha, s%k, st, msg)
            end if
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = where//trim(msg)
                return
            end if
        else
            errmsg = where//'k: missing (the Winkler modulus, N/m3; or g_mod and nu to ' &
                     //'compute it from the halfspace rocking stiffness)'
            return
        end if
        ! --- the method of k
        s%k_method = name_index(k_method, k_method_names)
        if (s%k_method == 0) then
            errmsg = where//'k_method = '''//trim(k_method)//''': unknown (allowed: ' &
                     //join(k_method_names)//')'
            return
        end if
        k_method = k_method_names(s%k_method)
        s%reading = name_index(reading, reading_names)
        if (s%reading == 0) then
            errmsg = where//'reading = '''//trim(reading)//''': unknown (allowed: ' &
                     //join(reading_names)//')'
            return
        end if
        reading = reading_names(s%reading)
        if (given(s%gw, 'reading') .and. .not. (s%footing == FOOTING_CIRCLE .and. &
                                                 s%k_method == K_VARYING)) then
            errmsg = where//'reading: only with footing = ''circle'' and k_method = ' &
                     //'''varying'' (the Gazetas formula of the equivalent rectangle)'
            return
        end if
        if (.not. dynamic) return
        ! --- the dynamic model: damping from c, or from xi with damping_ref
        if (given(s%gw, 'c') .and. (given(s%gw, 'xi') .or. given(s%gw, 'damping_ref'))) then
            errmsg = where//'c, xi: give the dashpot c, or the damping ratio xi (with ' &
                     //'damping_ref), not both'
            return
        end if
        if (name_index(damping_ref, damping_names) == 0) then
            errmsg = where//'damping_ref = '''//trim(damping_ref)//''': unknown (allowed: ' &
                     //join(damping_names)//')'
            return
        end if
        damping_ref = damping_names(name_index(damping_ref, damping_names))
        if (given(s%gw, 'c')) then
            if (s%footing == FOOTING_CIRCLE) then
                call winkler_model(s%body, s%k, s%model, st, msg, k_method=s%k_method, c=c, &
                                   reading=s%reading)
            else
                call winkler_model(s%body, s%k, s%model, st, msg, alpha=alpha, &
                                   k_method=s%k_method, c=c)
            end if
        else
            if (s%footing == FOOTING_CIRCLE) then
                call winkler_model(s%body, s%k, s%model, st, msg, k_method=s%k_method, xi=xi, &
                                   damping_ref=name_index(damping_ref, damping_names), &
                                   reading=s%reading)
            else
                call winkler_model(s%body, s%k, s%model, st, msg, alpha=alpha, &
                                   k_method=s%k_method, xi=xi, &
                                   damping_ref=name_index(damping_ref, damping_names))
            end if
        end if
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = where//trim(msg)
            return
        end if
        c = s%model%c
        call check_run_options(where, t_max, rtol, errmsg)
        if (len(errmsg) == 0 .and. s%task == 'history') call check_time_grid(where, s%gw, &
            t_end, dt, npts, errmsg)

    contains

        subroutine required(key, meaning)
            character(len=*), intent(in) :: key, meaning
            if (len(errmsg) > 0) return
            if (.not. given(s%gw, key)) errmsg = where//key//': missing ('//meaning//')'
        end subroutine required

        subroutine refuse(key, what_for)
            character(len=*), intent(in) :: key, what_for
            if (len(errmsg) > 0) return
            if (given(s%gw, key)) errmsg = where//key//': only with '//what_for//' (now ' &
                                           //'footing = '''//trim(footing)//''')'
        end subroutine refuse

    end subroutine check_winkler

    !> The grid of tilts of a pushover (rad): a list `theta`, a range `theta_range` with
    !> `theta_count` (and `spacing`), or 0 .. theta_max (default: the rigid theta_c) in
    !> theta_count values. grid says how (header). errmsg (located) on failure.
    subroutine theta_grid(where, s, th, grid, errmsg)
        character(len=*), intent(in) :: where
        type(setup_t), intent(in) :: s
        real(dp), allocatable, intent(out) :: th(:)
        character(len=:), allocatable, intent(out) :: grid
        character(len=:), allocatable, intent(out) :: errmsg
        real(dp) :: top
        integer :: i
        errmsg = ''
        if (given(s%gw, 'theta') .or. given(s%gw, 'theta_range')) then
            if (given(s%gw, 'theta_max')) then
                errmsg = where//'theta_max: not with '//trim(merge('theta      ', &
                         'theta_range', given(s%gw, 'theta')))//' (give the grid one way)'
                return
            end if
            call axis_values(s%gw, 'theta', 'theta', theta, theta_range, theta_count, &
                             spacing, .false., .true., max_list, th, grid, errmsg, &
                             count_optional=.true.)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
        else
            if (given(s%gw, 'spacing')) then
                errmsg = where//'spacing: only with theta_range'
                return
            end if
            top = s%body%theta_c
            grid = 'theta = 0 .. theta_c (rigid) = '//shortest_str(top)//' rad'
            if (given(s%gw, 'theta_max')) then
                if (.not. (finite_positive(theta_max) .and. theta_max <= 0.5_dp * pi)) then
                    errmsg = where//'theta_max = '//real_str(theta_max)//': must be in ' &
                             //'(0, pi/2] (rad)'
                    return
                end if
                top = theta_max
                grid = 'theta = 0 .. theta_max = '//shortest_str(top)//' rad'
            end if
            if (theta_count < 2 .or. theta_count > max_list) then
                errmsg = where//'theta_count = '//int_str(theta_count)//': must be in 2 .. ' &
                         //int_str(max_list)
                return
            end if
            allocate(th(theta_count))
            th = [(top * (real(i, dp) / real(theta_count - 1, dp)), i = 0, theta_count - 1)]
            th(theta_count) = top
            grid = grid//', '//int_str(theta_count)//' values'
        end if
        do i = 1, size(th)
            if (th(i) > 0.5_dp * pi) then
                errmsg = where//list_item('theta', i)//' = '//real_str(th(i))//': must be ' &
                         //'<= pi/2 (rad)'
                return
            end if
        end do
    end subroutine theta_grid

    !> Header line of the body and soil.
    function body_line(s) result(line)
        type(setup_t), intent(in) :: s
        character(len=:), allocatable :: line
        if (s%footing == FOOTING_CIRCLE) then
            line = 'circular footing r = '//shortest_str(r)//' m'
        else
            line = 'rectangular footing b = '//shortest_str(b) &
                //' m (rocking direction) x alpha = ' &
                   //shortest_str(alpha)//' m (half-lengths)'
        end if
        line = line//', h = '//shortest_str(h)//' m, W = '//shortest_str(s%weight)//' N, g = ' &
               //shortest_str(g)//' m/s2'
    end function body_line

    !> Header line of the soil: k and how it was chosen.
    function soil_line(s) result(line)
        type(setup_t), intent(in) :: s
        character(len=:), allocatable :: line
        line = 'Winkler modulus k = '//shortest_str(s%k)//' N/m3'
        if (given(s%gw, 'g_mod')) line = line//' (K_R/I of the halfspace, G = ' &
                                         //shortest_str(g_mod)//' Pa, nu = '//shortest_str(nu)//')'
        line = line//', k_method = '''//trim(k_method)//''''
        if (s%k_method == K_VARYING) then
            if (s%footing == FOOTING_CIRCLE) then
                line = line//' (equivalent rectangle of the contact, reading = ''' &
                       //trim(reading)//''')'
            else
                line = line//' (rectangle of the contact width x 2 alpha)'
            end if
        end if
    end function soil_line

    ! ------------------------------------------------------------------------------
    ! Pushover and master curve
    ! ------------------------------------------------------------------------------

    !> 'pushover': the static curve over the grid of tilts and its summary.
    subroutine do_pushover(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, grid
        character(len=512) :: msg, comments(7), sums(6)
        real(dp), allocatable :: th(:), curve(:, :), table(:, :)
        type(winkler_pushover_t) :: res
        real(dp) :: row(11)
        integer :: n

        where = located(path, s%gw)
        stat = 1
        msg = ''
        call theta_grid(where, s, th, grid, errmsg)
        if (len(errmsg) > 0) return
        n = size(th)
        allocate(curve(n, WP_NCOL), table(n, WP_NCOL + 2))
        if (s%footing == FOOTING_CIRCLE) then
            call winkler_pushover(r, h, s%weight, s%k, th, curve, res, stat, msg, &
                                  k_method=s%k_method, reading=s%reading)
        else
            call block_winkler_pushover(b, alpha, h, s%weight, s%k, th, curve, res, stat, &
                                        msg, k_method=s%k_method)
        end if
        if (stat /= SEISPULSE_SUCCESS) then
            stat = 1
            errmsg = where//trim(msg)
            return
        end if
        table(:, 1:WP_NCOL) = curve
        table(:, WP_NCOL + 1) = curve(:, WP_FORCE) / s%weight
        ! the same body on a rigid base: W tan(theta_c - theta) at the centre of mass
        table(:, WP_NCOL + 2) = s%weight * tan(s%body%theta_c - curve(:, WP_THETA))
        row = [s%weight, res%k0, s%body%theta_c, res%theta_up, res%max_force_over_weight, &
               res%theta_at_max, res%max_moment, res%theta_at_max_moment, &
               res%theta_overturn, res%theta_end, r_of(s) / h]

        call echo(s)
        comments(1) = 'seispulse analysis winkler: static pushover of a rigid body on ' &
                      //'tensionless Winkler springs (seispulse_winkler, doc/winkler.md)'
        comments(2) = body_line(s)
        comments(3) = soil_line(s)
        comments(4) = 'b: contact width from the compressed edge, pole: from the base ' &
                      //'centre towards the compressed edge, area: projected contact area, ' &
                      //'settlement: of the base centre (+ down), k: current modulus'
        comments(5) = 'm_found: foundation moment about the base centre, m_imposed = m_found ' &
                      //'- W h sin(theta) = F h cos(theta); force F at the centre of mass, ' &
                      //'force_rigid = W tan(theta_c - theta) on a rigid base; NaN: no ' &
                      //'equilibrium (beyond theta_end)'
        comments(6) = 'grid: '//grid
        comments(7) = 'input: '//trim(path)
        sums(1:3) = comments(1:3)
        sums(4) = 'theta_up: first loss of contact at the edge; max_force_ratio: peak F/W ' &
                  //'and theta_at_max; max_moment: peak imposed moment and its theta'
        sums(5) = 'theta_overturn: first zero of the imposed moment (NaN: none on the ' &
                  //'branch); theta_end: largest tilt with an equilibrium; ' &
                  //'force_ratio_rigid = r/h (F/W at theta = 0 on a rigid base)'
        sums(6) = comments(7)
        call write_table_pair(path, prefix, 'winkler_pushover', comments, &
            [character(len=12) :: 'theta', 'b', 'pole', 'area', 'settlement', 'k', 'm_found', &
             'm_imposed', 'force', 'force_ratio', 'force_rigid'], &
            [character(len=4) :: 'rad', 'm', 'm', 'm2', 'm', 'N/m3', 'N m', 'N m', 'N', '-', &
             'N'], table, 'winkler pushover', 'winkler_pushover_summary', sums, &
            [character(len=20) :: 'weight', 'k0', 'theta_c', 'theta_up', 'max_force_ratio', &
             'theta_at_max', 'max_moment', 'theta_at_max_moment', 'theta_overturn', &
             'theta_end', 'force_ratio_rigid'], &
            [character(len=4) :: 'N', 'N/m3', 'rad', 'rad', '-', 'rad', 'N m', 'rad', 'rad', &
             'rad', '-'], reshape(row, [1, size(row)]), 'winkler pushover summary', stat, &
            errmsg, summary2=.true.)
    end subroutine do_pushover

    !> The radius or the half-width b (m).
    pure real(dp) function r_of(s)
        type(setup_t), intent(in) :: s
        if (s%footing == FOOTING_CIRCLE) then
            r_of = r
        else
            r_of = b
        end if
    end function r_of

    !> 'master': the universal small-angle curve of the constant-k footing against
    !> x = theta/theta_up.
    subroutine do_master(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, grid
        character(len=512) :: files(2), comments(5)
        real(dp), allocatable :: x(:), table(:, :)
        integer :: i, n

        where = located(path, s%gw)
        stat = 1
        if (given(s%gw, 'theta_ratio') .or. given(s%gw, 'theta_ratio_range')) then
            call axis_values(s%gw, 'theta_ratio', 'theta_ratio', theta_ratio, &
                             theta_ratio_range, theta_ratio_count, spacing, .false., .true., &
                             max_list, x, grid, errmsg, count_optional=.true.)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
        else
            if (given(s%gw, 'spacing')) then
                errmsg = where//'spacing: only with theta_ratio_range'
                return
            end if
            if (theta_ratio_count < 2 .or. theta_ratio_count > max_list) then
                errmsg = where//'theta_ratio_count = '//int_str(theta_ratio_count)//': must ' &
                         //'be in 2 .. '//int_str(max_list)
                return
            end if
            n = theta_ratio_count
            x = [(master_default_top * (real(i, dp) / real(n - 1, dp)), i = 0, n - 1)]
            x(n) = master_default_top
            grid = 'theta_ratio = 0 .. '//shortest_str(master_default_top)//', '//int_str(n) &
                   //' values (default)'
        end if
        n = size(x)
        allocate(table(n, 5))
        table(:, 1) = x
        call winkler_master_curve(s%footing, x, table(:, 2), table(:, 3), table(:, 4), &
                                  table(:, 5))

        call echo(s)
        comments(1) = 'seispulse analysis winkler: universal small-angle pushover of the ' &
                      //trim(merge('circular   ', 'rectangular', s%footing == FOOTING_CIRCLE)) &
                      //' footing on constant-k Winkler springs (seispulse_winkler, ' &
                      //'doc/winkler.md)'
        comments(2) = 'theta_ratio = theta/theta_up; k_ratio = K_sec/K_0 (secant rocking ' &
                      //'stiffness over k I); m_ratio = M/(W r) (foundation moment)'
        comments(3) = 'b_ratio = b/(2 r) (contact width), a_ratio = a/r (pole); r: the ' &
                      //'radius, or the half-width b of a rectangle'
        comments(4) = 'grid: '//grid
        comments(5) = 'input: '//trim(path)
        call write_tables(prefix, 'winkler_master', comments, &
            [character(len=12) :: 'theta_ratio', 'k_ratio', 'm_ratio', 'b_ratio', 'a_ratio'], &
            [character(len=1) :: '-', '-', '-', '-', '-'], table, files, stat, errmsg)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('winkler master curve', files)
    end subroutine do_master

    ! ------------------------------------------------------------------------------
    ! Clay: inelastic pushover and capacities
    ! ------------------------------------------------------------------------------

    !> 'inelastic': the pushover on undrained clay by the stiffness-degradation method
    !> ([AD11] chapter 3) with the user's coefficients.
    subroutine do_inelastic(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, grid
        character(len=512) :: msg, comments(7), sums(6)
        real(dp), allocatable :: th(:), curve(:, :), table(:, :)
        type(degradation_coeffs_t) :: coeffs
        type(inelastic_pushover_t) :: res
        real(dp) :: row(12)
        integer :: n

        where = located(path, s%gw)
        stat = 1
        msg = ''
        call theta_grid(where, s, th, grid, errmsg)
        if (len(errmsg) > 0) return
        n = size(th)
        coeffs = coefficients()
        allocate(curve(n, IP_NCOL), table(n, IP_NCOL + 1))
        if (given(s%gw, 'nc')) then
            call inelastic_pushover(r, h, s%weight, g_mod, nu, su, coeffs, th, curve, res, &
                                    stat, msg, nc=nc)
        else
            call inelastic_pushover(r, h, s%weight, g_mod, nu, su, coeffs, th, curve, res, &
                                    stat, msg)
        end if
        if (stat /= SEISPULSE_SUCCESS) then
            stat = 1
            errmsg = where//trim(msg)
            return
        end if
        table(:, 1:IP_NCOL) = curve
        table(:, IP_NCOL + 1) = curve(:, IP_FORCE) / s%weight
        row = [s%weight, res%n_ult, res%sf, res%chi, res%hk_r, res%k_r0, res%theta_up, &
               res%max_moment, res%theta_at_max_moment, res%max_force_over_weight, &
               res%theta_at_max, res%theta_overturn]
        if (res%weak_zone) write(error_unit, '(a)') 'warning: '//where//'su = ' &
            //real_str(su)//': factor of safety '//real_str(res%sf)//' < 1.25, where the ' &
            //'degradation method deviates most near theta = 0.1 theta_up ([AD11] p.109)'
        if (res%kr_discontinuous) write(error_unit, '(a)') 'warning: '//where//'kr_c1, ' &
            //'kr_c2: k/k_el = kr_c1 - kr_c2 chi jumps at chi = 0.1 by '//real_str(res%kr_jump) &
            //' (1 below; continuous when kr_c1 - 0.1 kr_c2 = 1)'

        call echo(s)
        comments(1) = 'seispulse analysis winkler: inelastic pushover of a circular footing ' &
                      //'on undrained clay, stiffness-degradation method ([AD11] chapter 3; ' &
                      //'seispulse_clay_footing, doc/winkler.md)'
        comments(2) = body_line(s)
        comments(3) = 'clay: G = '//shortest_str(g_mod)//' Pa, nu = '//shortest_str(nu) &
            //', S_u = ' &
                      //shortest_str(su)//' Pa, N_c = '//shortest_str(nc)//'; '//coeffs_text(coeffs)
        comments(4) = 'USER-SUPPLIED coefficients: the thesis''s fitted values are lost; the ' &
                      //'curve is only as good as the coefficients given'
        comments(5) = 'k_r: secant rocking stiffness K_R(theta) (N m/rad), m_found = K_R ' &
                      //'theta, m_imposed = m_found - W h sin(theta) = F h cos(theta), ' &
                      //'force F at the centre of mass; theta_ratio = theta/theta_up, g_corr: ' &
                      //'the Gaussian correction G; NaN past pi/4'
        comments(6) = 'grid: '//grid
        comments(7) = 'input: '//trim(path)
        sums(1:4) = comments(1:4)
        sums(5) = 'n_ult = N_c S_u pi r^2, sf = n_ult/W, chi = 1/sf; hk_r = 8 G r^3/(3 ' &
                  //'(1 - nu)), k_r0 = hk_r k_el (k/k_el)(chi); theta_up = asin(W r/(2 ' &
                  //'k_r0))/2; theta_overturn: first zero of the imposed moment (NaN: ' &
                  //'none up to pi/4)'
        sums(6) = comments(7)
        call write_table_pair(path, prefix, 'winkler_inelastic', comments, &
            [character(len=12) :: 'theta', 'k_r', 'm_found', 'm_imposed', 'force', &
             'theta_ratio', 'g_corr', 'force_ratio'], &
            [character(len=7) :: 'rad', 'N m/rad', 'N m', 'N m', 'N', '-', '-', '-'], table, &
            'winkler inelastic pushover', 'winkler_inelastic_summary', sums, &
            [character(len=19) :: 'weight', 'n_ult', 'sf', 'chi', 'hk_r', 'k_r0', 'theta_up', &
             'max_moment', 'theta_at_max_moment', 'max_force_ratio', 'theta_at_max', &
             'theta_overturn'], &
            [character(len=7) :: 'N', 'N', '-', '-', 'N m/rad', 'N m/rad', 'rad', 'N m', 'rad', &
             '-', 'rad', 'rad'], reshape(row, [1, size(row)]), 'winkler inelastic summary', &
            stat, errmsg, summary2=.true.)
    end subroutine do_inelastic

    !> The degradation coefficients of &winkler.
    function coefficients() result(cf)
        type(degradation_coeffs_t) :: cf
        cf%k_el = k_el
        cf%kr_c1 = kr_c1
        cf%kr_c2 = kr_c2
        cf%a_poly = a_poly
        cf%b1 = b1
        cf%b2 = b2
        cf%c1 = c1
        cf%c2 = c2
        cf%log_base = log_base
    end function coefficients

    !> The coefficients for the header.
    function coeffs_text(cf) result(text)
        type(degradation_coeffs_t), intent(in) :: cf
        character(len=:), allocatable :: text
        integer :: i
        text = 'k_el = '//shortest_str(cf%k_el)//', kr_c1 = '//shortest_str(cf%kr_c1) &
            //', kr_c2 = ' &
               //shortest_str(cf%kr_c2)//', a_poly ='
        do i = 0, 4
            text = text//' '//shortest_str(cf%a_poly(i))
        end do
        text = text//', b1 = '//shortest_str(cf%b1)//', b2 = '//shortest_str(cf%b2)//', c1 = ' &
               //shortest_str(cf%c1)//', c2 = '//shortest_str(cf%c2)//', log_base = ' &
               //shortest_str(cf%log_base)
    end function coeffs_text

    !> 'capacity': bearing capacity, factor of safety and moment capacities of a circular
    !> footing on clay.
    subroutine do_capacity(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=512) :: msg, files(2), comments(5)
        real(dp) :: n_ult, sf, chi, m_tc, m_ew, adsu

        where = located(path, s%gw)
        msg = ''
        if (given(s%gw, 'nc')) then
            call clay_bearing(su, r, s%weight, n_ult, sf, chi, stat, msg, nc=nc)
        else
            call clay_bearing(su, r, s%weight, n_ult, sf, chi, stat, msg)
        end if
        if (stat == SEISPULSE_SUCCESS) call moment_capacity_circle(su, r, chi, &
            CAPACITY_TC00_PEAK, m_tc, stat, msg, nc=nc)
        if (stat == SEISPULSE_SUCCESS) call moment_capacity_circle(su, r, chi, &
            CAPACITY_EFFECTIVE_WIDTH, m_ew, stat, msg, nc=nc)
        if (stat /= SEISPULSE_SUCCESS) then
            stat = 1
            errmsg = where//trim(msg)
            return
        end if
        adsu = pi * r**2 * (2.0_dp * r) * su
        call echo(s)
        comments(1) = 'seispulse analysis winkler: capacities of a circular footing on ' &
                      //'undrained clay (seispulse_clay_footing, doc/winkler.md)'
        comments(2) = 'circular footing r = '//shortest_str(r)//' m, W = '//shortest_str(s%weight) &
                      //' N, S_u = '//shortest_str(su)//' Pa'
        comments(3) = 'n_ult = N_c S_u pi r^2 (N_c = pi + 3 by default, [SLSY04]), sf = ' &
                      //'n_ult/W, chi = 1/sf'
        comments(4) = 'm_ult_tc = 0.8 A D S_u ([TC00] peak), m_ult_width = W D (1 - chi)/2 ' &
                      //'(effective width); *_norm = M/(A D S_u), A = pi r^2, D = 2 r'
        comments(5) = 'input: '//trim(path)
        call write_tables(prefix, 'winkler_capacity', comments, &
            [character(len=15) :: 'su', 'r', 'weight', 'nc', 'n_ult', 'sf', 'chi', 'm_ult_tc', &
             'm_ult_width', 'm_tc_norm', 'm_width_norm'], &
            [character(len=3) :: 'Pa', 'm', 'N', '-', 'N', '-', '-', 'N m', 'N m', '-', '-'], &
            reshape([su, r, s%weight, n_ult / (su * pi * r**2), n_ult, sf, chi, m_tc, m_ew, &
                     m_tc / adsu, m_ew / adsu], [1, 11]), files, stat, errmsg, summary=.true.)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('winkler capacity', files)
    end subroutine do_capacity

    ! ------------------------------------------------------------------------------
    ! History
    ! ------------------------------------------------------------------------------

    !> The summary columns of a run (after any label and pga).
    function summary_row(s, run) result(row)
        type(setup_t), intent(in) :: s
        type(winkler_run_t), intent(in) :: run
        real(dp) :: row(14)
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        row = nan
        row(1:4) = [s%model%k, s%model%c, s%body%theta_c, s%model%theta_overturn]
        row(5:8) = [real(run%outcome, dp), run%t_uplift, run%t_lift_off, &
                    real(run%n_impacts, dp)]
        if (run%n_impacts > 0) row(9) = run%t_impacts(1)
        row(10:14) = [run%t_overturn, run%theta_max, run%normal_max, run%energy_error, &
                      run%t_end]
    end function summary_row

    !> Names of the summary table (with the record and pga columns for records).
    function summary_names(records) result(names)
        logical, intent(in) :: records
        character(len=14), allocatable :: names(:)
        character(len=14), parameter :: base(14) = [character(len=14) :: 'k', 'c', &
            'theta_c', 'theta_overturn', 'outcome', 't_uplift', 't_lift_off', 'n_impacts', &
            't_impact1', 't_overturn', 'theta_max', 'normal_max', 'energy_error', 't_end']
        if (records) then
            names = [character(len=14) :: 'record', 'pga', base]
        else
            names = base
        end if
    end function summary_names

    !> Units of the summary table (with the record and pga columns for records).
    function summary_units(records) result(units)
        logical, intent(in) :: records
        character(len=6), allocatable :: units(:)
        character(len=6), parameter :: base(14) = [character(len=6) :: 'N/m3', 'N s/m3', &
            'rad', 'rad', '-', 's', 's', '-', 's', 's', 'rad', 'N', '-', 's']
        if (records) then
            units = [character(len=6) :: '-', 'g', base]
        else
            units = base
        end if
    end function summary_units

    !> Names and units of the history table: t, then the WR_OUT_* outputs.
    subroutine history_header(records, names, units)
        logical, intent(in) :: records
        character(len=16), allocatable, intent(out) :: names(:)
        character(len=6), allocatable, intent(out) :: units(:)
        integer :: j
        allocate(names(1 + WR_NOUT), units(1 + WR_NOUT))
        names(1) = 't'
        units(1) = 's'
        do j = 1, WR_NOUT
            names(1 + j) = winkler_output_name(j)
            units(1 + j) = history_units(j)
        end do
        if (records) then
            names = [character(len=16) :: 'record', names]
            units = [character(len=6) :: '-', units]
        end if
    end subroutine history_header

    !> Kinds of the summary columns (with the record and pga columns for records):
    !> outcome by name, n_impacts an integer.
    function summary_kinds(records) result(kinds)
        logical, intent(in) :: records
        character(len=:), allocatable :: kinds(:)
        integer :: k0
        k0 = merge(2, 0, records)
        kinds = run_summary_kinds(k0 + 14, k0 + 5, winkler_outcome_names, k0 + 8)
    end function summary_kinds

    !> Header lines shared by the tables of a history.
    subroutine history_comments(s, excitation, lines)
        type(setup_t), intent(in) :: s
        character(len=*), intent(in) :: excitation
        character(len=*), intent(out) :: lines(5)
        lines(1) = 'seispulse analysis winkler: planar rocking with settlement on ' &
                   //'tensionless Winkler springs and dashpots ([KH91], [KSR86]; ' &
                   //'seispulse_winkler_rock) under '//excitation
        lines(2) = body_line(s)
        lines(3) = soil_line(s)//', c = '//shortest_str(s%model%c)//' N s/m3'
        if (given(s%gw, 'c')) then
            lines(3) = trim(lines(3))//' (given)'
        else
            lines(3) = trim(lines(3))//' (xi = '//shortest_str(xi)//', damping_ref = ''' &
                       //trim(damping_ref)//''')'
        end if
        lines(4) = 'theta_c, theta_overturn: rigid and static Winkler overturning angles'
        lines(5) = 'v: settlement of the base centre (+ down), theta > 0 lifts the s > 0 ' &
                   //'side, contact_width: contact width, normal_force: N, moment: foundation ' &
                   //'moment about the base centre in the sense of theta (restoring: opposite ' &
                   //'sign to theta and to the pushover''s m_found), ground_accel: ground a_g ' &
                   //'(> 0 drives theta > 0); energy: kinetic + potential + spring, ' &
                   //'input_work: input work, ' &
                   //'dissipated: contact work - spring energy; energy_error: largest ' &
                   //'relative energy balance error'
    end subroutine history_comments

    !> The end of the history grid: t_end, else past the end of the motion (at least the
    !> excitation's end t_exc), or the time limit.
    function last_time(run, t_exc) result(t_last)
        type(winkler_run_t), intent(in) :: run
        real(dp), intent(in) :: t_exc
        real(dp) :: t_last
        t_last = t_end
        if (ieee_is_nan(t_end)) then
            if (run%outcome == WR_RUN_TIME_LIMIT .and. run%t_end > 0.0_dp) then
                t_last = run%t_end
            else
                t_last = max(1.25_dp * run%t_end, t_exc)
            end if
            if (.not. t_last > 0.0_dp) t_last = 1.0_dp
        end if
    end function last_time

    !> The end of a run (s): t_max if given, else t_end if given, else the end of the
    !> excitation t_exc plus 20 periods 2 pi/p of the rigid body (a run the energy
    !> criterion cannot decide, as with varying k, ends there as a time limit).
    real(dp) function run_end(s, t_exc)
        type(setup_t), intent(in) :: s
        real(dp), intent(in) :: t_exc                     !! end of the excitation (s)
        if (given(s%gw, 't_max')) then
            run_end = t_max
        else if (given(s%gw, 't_end')) then
            run_end = t_end
        else
            run_end = t_exc + 20.0_dp * (2.0_dp * pi / s%body%p)
        end if
    end function run_end

    !> 'history' under the pulse of &pulse: the summary and the history tables.
    subroutine do_history_pulse(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(winkler_run_t) :: run
        character(len=512) :: msg, comments(7), lines(7)
        character(len=16), allocatable :: names(:)
        character(len=6), allocatable :: units(:)
        real(dp), allocatable :: t(:), hist(:, :), table(:, :)
        real(dp) :: one_hist(WR_NOUT, 1), t_run
        integer :: n, st

        call echo(s)
        stat = 1
        msg = ''
        t_run = run_end(s, pulse_end(s%pin))
        call winkler_rock(s%model, [0.0_dp], one_hist, run, st, msg, pulse=s%pin%p, &
                          theta0=theta0, theta_rate0=theta_rate0, t_max=t_run, rtol=rtol)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = locate_message(path, trim(msg), s)
            return
        end if
        call time_grid(last_time(run, pulse_end(s%pin)), dt, npts, t, errmsg)
        if (len(errmsg) > 0) then
            errmsg = located(path, s%gw)//errmsg
            return
        end if
        n = size(t)
        allocate(hist(WR_NOUT, n), table(n, 1 + WR_NOUT))
        call winkler_rock(s%model, t, hist, run, st, msg, pulse=s%pin%p, theta0=theta0, &
                          theta_rate0=theta_rate0, t_max=max(t_run, t(n)), rtol=rtol)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = locate_message(path, trim(msg), s)
            return
        end if
        table(:, 1) = t
        table(:, 2:) = transpose(hist)

        call history_comments(s, pulse_kind_name(s%pin%code)//' pulse', comments(1:5))
        comments(6) = 'NaN: no such event; overturned or a time limit: NaN after t_end'
        comments(7) = 'input: '//trim(path)
        lines = comments
        lines(6) = 'outcome: '//trim(winkler_outcome_names(run%outcome))//', impacts: ' &
                   //int_str(run%n_impacts)//', theta_max = '//shortest_str(run%theta_max) &
                   //' rad, t_end = '//shortest_str(run%t_end)//' s'
        call history_header(.false., names, units)
        call write_table_pair(path, prefix, 'winkler', comments, summary_names(.false.), &
            summary_units(.false.), reshape(summary_row(s, run), [1, 14]), 'winkler summary', &
            'winkler_history', lines, names, units, table, 'winkler history', stat, errmsg, &
            note='winkler: '//trim(winkler_outcome_names(run%outcome)), &
            kinds1=summary_kinds(.false.), summary1=.true.)
    end subroutine do_history_pulse

    !> Rocking under each record of &records: a summary row and the history rows of each
    !> (a record that cannot be read or run: NaN, the others go on).
    subroutine do_history_records(path, prefix, s, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(setup_t), intent(in) :: s
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(winkler_run_t) :: run
        type(record_out_t), allocatable :: outs(:)
        character(len=:), allocatable :: where
        character(len=512) :: msg
        character(len=1024), allocatable :: comments(:), lines(:)
        character(len=256), allocatable :: labels(:), hlabels(:)
        character(len=16), allocatable :: names(:)
        character(len=6), allocatable :: units(:)
        real(dp), allocatable :: accel(:), t(:), summary(:, :), hist(:, :), part(:, :), &
                                 h1(:, :)
        real(dp) :: one_hist(WR_NOUT, 1), nan, t_exc, t_run
        integer :: nrec, ir, i, st, nfailed
        logical, allocatable :: failed(:)

        nan = ieee_value(nan, ieee_quiet_nan)
        where = located(path, s%gr)
        call echo(s)
        nrec = size(s%recs)
        allocate(outs(nrec), labels(nrec), summary(nrec, 15), failed(nrec))
        allocate(hlabels(0), hist(0, 1 + WR_NOUT))
        summary = nan
        failed = .false.
        do ir = 1, nrec
            call load_record(where, s%recs(ir), ir, nrec, 'winkler', s%slammer_rounding, &
                             outs(ir), accel)
            labels(ir) = outs(ir)%name
            failed(ir) = .not. outs(ir)%ok
            if (outs(ir)%ok) then
                msg = ''
                t_exc = outs(ir)%dt * real(size(accel) - 1, dp)
                t_run = run_end(s, t_exc)
                call winkler_rock(s%model, [0.0_dp], one_hist, run, st, msg, accel=accel, &
                                  dt=outs(ir)%dt, g_rec=g, theta0=theta0, &
                                  theta_rate0=theta_rate0, t_max=t_run, rtol=rtol)
                if (st == SEISPULSE_SUCCESS) then
                    call time_grid(last_time(run, t_exc), dt, npts, t, errmsg)
                    if (len(errmsg) > 0) then
                        stat = 1
                        errmsg = located(path, s%gw)//list_item('files', ir)//': '//errmsg
                        return
                    end if
                    allocate(h1(WR_NOUT, size(t)), part(size(t), 1 + WR_NOUT))
                    call winkler_rock(s%model, t, h1, run, st, msg, accel=accel, &
                                      dt=outs(ir)%dt, g_rec=g, theta0=theta0, &
                                      theta_rate0=theta_rate0, t_max=max(t_run, t(size(t))), &
                                      rtol=rtol)
                    part(:, 1) = t
                    part(:, 2:) = transpose(h1)
                    deallocate(h1)
                end if
                if (st /= SEISPULSE_SUCCESS) then
                    failed(ir) = .true.
                    outs(ir)%message = trim(msg)
                    write(error_unit, '(a)') 'seispulse: error: '//where &
                        //record_place(ir, s%recs(ir))//': '//trim(msg)
                    if (allocated(part)) deallocate(part)
                else
                    summary(ir, 1) = outs(ir)%pga
                    summary(ir, 2:15) = summary_row(s, run)
                    hist = stack(hist, part)
                    hlabels = [character(len=256) :: hlabels, &
                               (labels(ir), i = 1, size(part, 1))]
                    deallocate(part)
                    cycle
                end if
            end if
            ! a failed record: one row of NaN in each table
            hist = stack(hist, reshape([(nan, i = 1, 1 + WR_NOUT)], [1, 1 + WR_NOUT]))
            hlabels = [character(len=256) :: hlabels, labels(ir)]
        end do

        allocate(comments(7 + nrec))
        call history_comments(s, 'records (&records; the samples in g, linear in between, ' &
                              //'0 after the last)', comments(1:5))
        comments(6) = 'pga: after scaling (g); NaN: no such event, or a record that failed'
        do ir = 1, nrec
            comments(6 + ir) = record_line(ir, s%recs(ir), outs(ir))
            if (outs(ir)%ok .and. failed(ir)) comments(6 + ir) = trim(comments(6 + ir)) &
                //'; FAILED: '//outs(ir)%message
        end do
        comments(7 + nrec) = 'input: '//trim(path)
        lines = comments
        lines(6) = 'rows: each record from t = 0; NaN: a record that failed'
        call history_header(.true., names, units)
        call write_table_pair(path, prefix, 'winkler', comments, summary_names(.true.), &
            summary_units(.true.), summary, 'winkler summary', 'winkler_history', lines, names, &
            units, hist, 'winkler history', stat, errmsg, labels1=labels, labels2=hlabels, &
            kinds1=summary_kinds(.true.))
        if (stat /= 0) return
        nfailed = count(failed)
        if (nfailed > 0) then
            stat = ROWS_FAILED
            errmsg = int_str(nfailed)//' of '//int_str(nrec)//' records failed (' &
                     //failed_records(outs, failed)//'): their rows hold NaN'
        end if
    end subroutine do_history_records

    !> Where a library message about a run belongs: &pulse or &winkler.
    function locate_message(path, msg, s) result(full_msg)
        character(len=*), intent(in) :: path, msg
        type(setup_t), intent(in) :: s
        character(len=:), allocatable :: full_msg
        full_msg = locate_run_message(path, msg, s%pin%group, pulse_keys, s%gw, &
                                      winkler_keys, s%gw)
    end function locate_message

    ! ------------------------------------------------------------------------------
    ! Overturning map
    ! ------------------------------------------------------------------------------

    !> 'map': the overturning map on the chosen axes (rigid p and theta_c of the body), with
    !> the rigid map of the same body and the difference on request.
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
        integer, allocatable :: classes(:, :), classes_r(:, :), diff(:, :)
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
        call map_grids(where, s%gm, axes_code, freq_ratio, freq_range, freq_count, amp_ratio, &
                       amp_range, amp_count, freq_hz, freq_hz_range, freq_hz_count, pga, &
                       pga_range, pga_count, max_list, xs, ys, grid_x, grid, ykey, errmsg)
        if (len(errmsg) > 0) return
        ! the shape at a unit time scale (the map checks every time scale)
        call map_template(where, code, beta, full, peak_frac, t0_periods, cycles, tpl, errmsg)
        if (len(errmsg) > 0) return
        call warn_unused_template(path, s%gm, code)

        call echo(s)
        allocate(classes(size(ys), size(xs)), classes_r(size(ys), size(xs)), &
                 diff(size(ys), size(xs)))
        call progress%start(timing=.true.)
        do i = 1, size(ys)
            call winkler_overturning_map(s%model, code, xs, ys(i:i), axes_code, &
                                         classes(i:i, :), st, msg, template=tpl, rtol=rtol)
            if (st == SEISPULSE_SUCCESS .and. compare_rigid) &
                call body_overturning_map(s%body, code, xs, ys(i:i), axes_code, &
                                          classes_r(i:i, :), st, msg, template=tpl, &
                                          rtol=rtol)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = locate_run_message(path, trim(msg), s%gm, map_keys, s%gw, &
                                            winkler_keys, s%gm)
                return
            end if
            call progress%row(i, size(ys))
        end do
        call progress%done(size(ys))
        if (compare_rigid) then
            call map_difference(classes, classes_r, diff, st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = where//'compare_rigid: '//trim(msg)
                return
            end if
        end if

        ! --- the table: both axis systems, the chosen one first
        if (compare_rigid) then
            call map_table(axes_code, xs, ys, s%body%p, s%body%theta_c, classes, table, &
                           classes_r, diff)
            call map_axes_header(axes_code, names, units, 'class_rigid')
        else
            call map_table(axes_code, xs, ys, s%body%p, s%body%theta_c, classes, table)
            call map_axes_header(axes_code, names, units)
        end if
        ! the classes of both maps by the same names
        kinds = [character(len=128) :: '', '', '', '', category_kind(map_class_names)]
        if (compare_rigid) kinds = [character(len=128) :: kinds, category_kind(map_class_names), &
                                    category_kind(diff_names)]
        comments(1) = 'seispulse analysis winkler: overturning map on Winkler soil, ' &
                      //pulse_kind_name(code)//' pulse family (seispulse_winkler_rock)'
        comments(2) = body_line(s)//'; rigid theta_c = '//shortest_str(s%body%theta_c) &
                      //' rad, p = '//shortest_str(s%body%p)//' rad/s'
        comments(3) = trim(soil_line(s))//', c = '//shortest_str(s%model%c)//' N s/m3'
        comments(4) = map_class_line
        comments(5) = 'freq_ratio = omega_p/p = 2 pi freq_hz/p (T_p: t_d of the ' &
                      //'exponential pulse, the period of sine/cosine cycles, the length ' &
                      //'of the others; Ricker: the dominant f_p); amp_ratio = a_p/(g tan ' &
                      //'theta_c) = pga/tan theta_c; p, theta_c of the rigid body'
        comments(6) = 'axes = '''//trim(axes)//''' (the first two columns); rows: '// &
                      trim(names(2))//' outer, '//trim(names(1))//' inner; '//template_text(tpl)
        if (compare_rigid) then
            comments(7) = 'class_rigid: the same body on a rigid base (Housner e = ' &
                          //shortest_str(s%body%e)//'), same cells'
            comments(8) = 'diff: only_winkler, only_rigid: only one of the two overturns, ' &
                          //'other_mode: both, in different classes; grid: '//grid_x//', '//grid
        else
            comments(7) = 'compare_rigid = .false.: no rigid map'
            comments(8) = 'grid: '//grid_x//', '//grid
        end if
        comments(9) = 'input: '//trim(path)
        call write_tables(prefix, 'winkler_map', comments, names, units, table, files, &
                          stat, errmsg, kinds=kinds)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('winkler map', files)
    end subroutine do_map

    ! ------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------

    !> Echo the effective input: &pulse or &records for a history, &winkler, &map for a
    !> map.
    subroutine echo(s)
        type(setup_t), intent(in) :: s
        if (s%task == 'history') then
            if (s%use_records) then
                call echo_records(s%recs, s%slammer_rounding)
            else
                call write_pulse_group(echo_unit())
            end if
        end if
        if (s%task /= 'master' .and. s%task /= 'inelastic' .and. s%task /= 'capacity') &
            k = s%k
        write(echo_unit(), nml=winkler)
        if (s%task == 'map') write(echo_unit(), nml=map)
    end subroutine echo

end module driver_winkler
