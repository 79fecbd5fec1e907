!> Analysis 'rocking': a free-standing rigid block rocking on a rigid base (Housner 1963)
!> under one pulse or under accelerograms: the classification and extreme values of the
!> response, its time history, or an overturning map of a pulse family.
!>
!> Groups: &block (geometry, restitution, model; g with records), &pulse
!> (driver_pulse_group) or &records (driver_records: the record files and how to read and
!> scale each one, as for 'newmark' and 'sdof'; the excitation), &rocking (what to
!> compute, run limits, the history grid) and &map (the pulse family and the grids of an
!> overturning map).
!> Tables <output>_rocking (what = 'summary'; one row per record with &records),
!> <output>_rocking_history ('history'; the records stacked, the record's name first) or
!> <output>_rocking_map ('map'). A record that cannot be read or run fails its row (NaN,
!> status failed), the others are written and run_rocking returns ROWS_FAILED (exit status 1).
!> The numbers come from seispulse_rocking_sim (the
!> integrator, any pulse) and seispulse_rocking_closed (the linearized closed forms of the
!> half-cycle exponential pulse, shown side by side); the driver only reads, checks,
!> converts units and writes.
module driver_rocking
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan, &
                                             ieee_positive_inf, ieee_is_finite
    use seispulse, only: dp, shortest_str, pulse_t, pulse_validate, pulse_eval, pulse_kind_name, &
                         SEISPULSE_SUCCESS, PULSE_EXPONENTIAL, PULSE_RECTANGULAR, &
                         PULSE_TRIANGULAR, PULSE_RICKER, real_str, &
                         int_str, rocking_summary, rocking_region_name, rocking_block_t, &
                         rocking_run_t, rectangular_block, symmetric_block, &
                         rocking_block_validate, rock_pulse, overturning_map, ROCK_RUN_TIME_LIMIT, &
                         pi, in_open
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: find_group, located, join, read_optional, given, list_item, &
                            ROWS_FAILED
    use driver_records, only: records_keys, record_in_t, record_out_t, records_defaults, &
                              read_records, check_records, echo_records, record_line, &
                              failed_records
    use driver_input, only: missing_group
    use driver_input, only: output_located
    use driver_pulse_group, only: pulse_input_t, pulse_keys, read_pulse_group, build_pulse, &
                                  write_pulse_group, pulse_end, check_time_grid, time_grid, &
                                  warn_unused_template, template_text, not_one
    use driver_tables, only: write_tables, say_written, category_kind, status_names
    use driver_axis, only: axis_values
    use driver_rocking_common, only: check_run_options, restitution_and_model, &
                                     locate_run_message, map_kind, map_template, progress_t, &
                                     map_class_names, rock_records, run_outcome_names, &
                                     map_class_line
    use driver_echo, only: echo_unit
    implicit none
    private

    public :: run_rocking, rocking_groups, rocking_tables

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: rocking_groups(5) = [character(len=8) :: 'block', &
        'pulse', 'records', 'rocking', 'map']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=15), parameter :: rocking_tables(3) = [character(len=15) :: 'rocking', &
        'rocking_history', 'rocking_map']

    character(len=12), parameter :: block_keys(9) = [character(len=12) :: 'b', 'h', &
        'alpha', 'alpha_deg', 'r', 'io_over_mr2', 'e', 'model', 'g']
    character(len=8), parameter :: rocking_keys(7) = [character(len=8) :: 'what', 't_max', &
        'rtol', 't_end', 'npts', 'dt', 'kv']
    character(len=12), parameter :: map_keys(12) = [character(len=12) :: 'kind', 'beta', &
        'full', 'peak_frac', 't0_periods', 'freq_ratio', 'freq_range', 'freq_count', &
        'amp_ratio', 'amp_range', 'amp_count', 'cycles']
    character(len=8), parameter :: what_names(3) = [character(len=8) :: 'summary', &
        'history', 'map']

    !> Most values on one axis of a map (freq_ratio, amp_ratio).
    integer, parameter :: max_list = 1000

    !> The summary table on records: the record's name, then these columns.
    integer, parameter :: n_rec_cols = 17
    character(len=13), parameter :: rec_names(n_rec_cols + 1) = [character(len=13) :: &
        'record', 'pga', 'alpha', 'p', 'e', 'outcome', 't_uplift', 't_overturn', 'n_impacts', &
        't_impact1', 'theta_max', 'theta_min', 'psi_max', 'psi_min', 't_end', 'theta_abs_max', &
        't_abs_max', 'status']
    character(len=6), parameter :: rec_units(n_rec_cols + 1) = [character(len=6) :: '-', 'g', &
        'rad', 'rad/s', '-', '-', 's', 's', '-', 's', 'rad', 'rad', '-', '-', 's', 'rad', 's', &
        '-']

    ! namelist variables (defaults are set in set_defaults)
    real(dp) :: b, h, alpha, alpha_deg, r, io_over_mr2, e
    real(dp) :: g        !! gravity (m/s2) with &records, also the unit g of the records
    character(len=32) :: model
    character(len=32) :: what
    real(dp) :: t_max, rtol, t_end, dt
    real(dp) :: kv       !! vertical ground acceleration a_v = kv a_g (doc/rocking.md section 7)
    integer :: npts
    character(len=32) :: kind
    real(dp) :: beta, peak_frac, t0_periods
    real(dp) :: cycles   !! sine_cycle, cosine_cycle: whole number of cycles (read as a real)
    logical :: full
    real(dp) :: freq_ratio(max_list), freq_range(2), amp_ratio(max_list), amp_range(2)
    integer :: freq_count, amp_count
    namelist /block/ b, h, alpha, alpha_deg, r, io_over_mr2, e, model
    ! &block is read (with g) in read_block and echoed with g in echo_records_mode
    ! &rocking is read (with kv) in read_rocking and echoed in echo_rocking
    namelist /map/ kind, beta, full, peak_frac, t0_periods, freq_ratio, freq_range, &
        freq_count, amp_ratio, amp_range, amp_count, cycles

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        b = nan
        h = nan
        alpha = nan
        alpha_deg = nan
        r = nan
        io_over_mr2 = 4.0_dp / 3.0_dp
        e = nan           ! NaN: Housner's value from the geometry
        g = 9.80665_dp    ! with &records
        model = 'nonlinear'
        what = 'summary'
        t_max = ieee_value(t_max, ieee_positive_inf)
        rtol = 1.0e-12_dp
        kv = 0.0_dp       ! no vertical ground acceleration
        t_end = nan       ! NaN: 1.25 x the end of the motion, at least the end of the pulse
        npts = 0          ! neither dt nor npts: 1001 points
        dt = 0.0_dp
        kind = 'exponential'
        beta = 0.0_dp
        full = .false.
        peak_frac = 0.5_dp
        t0_periods = 1.5_dp
        cycles = 1.0_dp
        freq_ratio = nan
        freq_range = nan
        freq_count = 21
        amp_ratio = nan
        amp_range = nan
        amp_count = 21
    end subroutine set_defaults

    subroutine read_block(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        namelist /block/ b, h, alpha, alpha_deg, r, io_over_mr2, e, model, g
        if (len(text) > 0) then
            read(text, nml=block, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=block, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_block

    subroutine read_rocking(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        namelist /rocking/ what, t_max, rtol, t_end, npts, dt, kv
        if (len(text) > 0) then
            read(text, nml=rocking, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=rocking, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_rocking

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

    !> Read the groups, compute, write the table; print where it went.
    subroutine run_rocking(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(pulse_input_t) :: pin
        type(nml_group) :: gb, gr, gm, grec
        type(rocking_block_t) :: blk
        type(record_in_t), allocatable :: recs(:)
        character(len=:), allocatable :: task
        real(dp) :: g_block
        logical :: use_records, slammer_rounding

        call set_defaults()
        call records_defaults()
        call read_pulse_group(path, groups, pin, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'records', records_keys, read_records, grec, stat, &
                           errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'block', block_keys, read_block, gb, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'rocking', rocking_keys, read_rocking, gr, stat, &
                           errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'map', map_keys, read_map, gm, stat, errmsg)
        if (stat /= 0) return
        stat = 1

        ! --- what to compute, and which groups go with it
        task = trim(lower(adjustl(what)))
        if (.not. any(what_names == task)) then
            errmsg = located(path, gr)//'what = '''//trim(what)//''': unknown (allowed: ' &
                     //join(what_names)//')'
            return
        end if
        call check_rocking(path, gr, task, errmsg)
        if (len(errmsg) > 0) return
        if (find_group(groups, 'block') == 0) then
            errmsg = missing_group(path, 'block')//' (it gives the block: b and h, or alpha ' &
                     //'or alpha_deg with r)'
            return
        end if
        if (task == 'map') then
            if (find_group(groups, 'pulse') > 0) then
                errmsg = located(path, pin%group)//'not used by what = ''map'' (the pulse ' &
                         //'family and shape of a map are in &map)'
                return
            end if
            if (find_group(groups, 'map') == 0) then
                errmsg = missing_group(path, 'map')//' (what = ''map'' needs the grids: ' &
                         //'freq_ratio or freq_range, amp_ratio or amp_range)'
                return
            end if
        else if (find_group(groups, 'map') > 0) then
            errmsg = located(path, gm)//'only with what = ''map'' (&rocking; now what = ''' &
                     //task//''')'
            return
        end if

        ! --- &records instead of &pulse (summary, history): records_setup
        use_records = find_group(groups, 'records') > 0
        call records_setup(path, groups, task, use_records, pin, grec, gb, errmsg)
        if (len(errmsg) > 0) return

        ! --- the excitation, then the block (which uses its g)
        g_block = 9.80665_dp
        if (use_records) then
            g_block = g
            call check_records(path, grec, recs, slammer_rounding, errmsg)
            if (len(errmsg) > 0) return
        else if (task /= 'map') then
            call build_pulse(path, pin, stat, errmsg, g_used=.true.)
            if (stat /= 0) return
            stat = 1
            g_block = pin%g
        end if
        call check_block(path, gb, g_block, task == 'map', blk, errmsg)
        if (len(errmsg) > 0) return

        if (use_records) then
            call do_records(path, prefix, grec, gr, blk, recs, slammer_rounding, &
                            task == 'history', stat, errmsg)
            return
        end if
        select case (task)
        case ('summary')
            call do_summary(path, prefix, pin, gb, gr, blk, stat, errmsg)
        case ('history')
            call do_history(path, prefix, pin, gb, gr, blk, stat, errmsg)
        case default
            call do_map(path, prefix, gb, gr, gm, blk, stat, errmsg)
        end select
    end subroutine run_rocking

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> Check &rocking for the task. errmsg is empty on success.
    subroutine check_rocking(path, gr, task, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gr
        character(len=*), intent(in) :: task
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=8), parameter :: grid_keys(3) = [character(len=8) :: 't_end', 'npts', &
            'dt']
        integer :: i
        where = located(path, gr)
        errmsg = ''
        if (task /= 'history') then
            do i = 1, size(grid_keys)
                if (given(gr, trim(grid_keys(i)))) then
                    errmsg = where//trim(grid_keys(i))//': only with what = ''history'' ' &
                             //'(the grid of the history table)'
                    return
                end if
            end do
        end if
        if (task == 'map' .and. given(gr, 't_max')) then
            errmsg = where//'t_max: not with what = ''map'' (each cell runs until its ' &
                     //'class is known)'
            return
        end if
        call check_run_options(where, t_max, rtol, errmsg)
        if (len(errmsg) > 0) return
        if (.not. ieee_is_finite(kv)) then
            errmsg = where//'kv = '//real_str(kv)//': must be a finite number (vertical ' &
                     //'ground acceleration a_v = kv a_g)'
            return
        end if
        if (task /= 'history') return
        call check_time_grid(where, gr, t_end, dt, npts, errmsg)
    end subroutine check_rocking

    !> Check &block and build the block (g: gravity of the excitation; for a map any
    !> value, the map being dimensionless). errmsg is empty on success.
    subroutine check_block(path, gb, g, for_map, blk, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gb
        real(dp), intent(in) :: g
        logical, intent(in) :: for_map
        type(rocking_block_t), intent(out) :: blk
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=512) :: msg
        real(dp) :: a, radius
        integer :: stat
        logical :: has_bh, has_alpha

        where = located(path, gb)
        errmsg = ''
        msg = ''
        has_bh = given(gb, 'b') .or. given(gb, 'h')
        has_alpha = given(gb, 'alpha') .or. given(gb, 'alpha_deg')
        if (given(gb, 'alpha') .and. given(gb, 'alpha_deg')) then
            errmsg = where//'alpha, alpha_deg: give only one of them'
            return
        end if
        if (has_bh .and. has_alpha) then
            errmsg = where//'b, h: not with alpha or alpha_deg (give b and h, or the ' &
                     //'slenderness with r)'
            return
        end if
        if (has_bh) then
            if (.not. given(gb, 'b')) then
                errmsg = where//'b: missing (b and h go together: half-width and ' &
                         //'half-height, m)'
            else if (.not. given(gb, 'h')) then
                errmsg = where//'h: missing (b and h go together: half-width and ' &
                         //'half-height, m)'
            else if (given(gb, 'r')) then
                errmsg = where//'r: not with b and h (R = sqrt(b^2 + h^2))'
            end if
            if (len(errmsg) > 0) return
            if (given(gb, 'io_over_mr2')) then
                ! b, h and a non-uniform mass: symmetric_block, after the checks of b, h
                call rectangular_block(b, h, g, blk, stat, msg)
                if (stat == SEISPULSE_SUCCESS) call symmetric_block(hypot(b, h), &
                    atan2(b, h), io_over_mr2, g, blk, stat, msg)
            else
                call rectangular_block(b, h, g, blk, stat, msg)
            end if
        else if (has_alpha) then
            if (given(gb, 'alpha_deg')) then
                if (.not. in_open(alpha_deg, 0.0_dp, 90.0_dp)) then
                    errmsg = where//'alpha_deg = '//real_str(alpha_deg)//': must be a ' &
                             //'number in (0, 90) (degrees)'
                    return
                end if
                a = alpha_deg * (pi / 180.0_dp)
            else
                a = alpha
            end if
            radius = r
            if (.not. given(gb, 'r')) then
                if (.not. for_map) then
                    errmsg = where//'r: missing (the distance from the pivot corner to the ' &
                             //'centre of mass, m; with alpha or alpha_deg)'
                    return
                end if
                radius = 1.0_dp          ! a map is dimensionless: p drops out
            end if
            call symmetric_block(radius, a, io_over_mr2, g, blk, stat, msg)
        else
            errmsg = where//'b, h: missing (give b and h, or alpha or alpha_deg with r)'
            return
        end if
        if (stat /= SEISPULSE_SUCCESS) then
            errmsg = where//trim(msg)
            return
        end if
        if (for_map .and. given(gb, 'r')) write(error_unit, '(a)') 'warning: '//where &
            //'r: not used by what = ''map'' (the map is dimensionless)'
        call restitution_and_model(where, gb, e, model, blk%e, blk%linearized, errmsg)
        if (len(errmsg) > 0) return
        call rocking_block_validate(blk, stat, msg)
        if (stat /= SEISPULSE_SUCCESS) then
            errmsg = where//trim(msg)
            return
        end if
        ! the effective value, for the echo
        e = blk%e
    end subroutine check_block

    !> Where a library message about a run belongs: &pulse, &rocking or &block.
    function locate_message(path, msg, pin, gb, gr) result(full_msg)
        character(len=*), intent(in) :: path, msg
        type(pulse_input_t), intent(in) :: pin
        type(nml_group), intent(in) :: gb, gr
        character(len=:), allocatable :: full_msg
        full_msg = locate_run_message(path, msg, pin%group, pulse_keys, gr, rocking_keys, gb)
    end function locate_message

    ! ------------------------------------------------------------------------------
    ! Summary
    ! ------------------------------------------------------------------------------

    !> The closed forms apply: the half-cycle exponential pulse or one of its limits
    !> (rectangular: beta = -inf; symmetric triangular: beta = 0), amp > 0. beta_cf
    !> receives the shape.
    logical function closed_form_pulse(p, beta_cf)
        type(pulse_t), intent(in) :: p
        real(dp), intent(out) :: beta_cf
        closed_form_pulse = .false.
        beta_cf = 0.0_dp
        if (.not. p%amp > 0.0_dp) return
        select case (p%kind)
        case (PULSE_EXPONENTIAL)
            closed_form_pulse = .not. p%full
            beta_cf = p%beta
        case (PULSE_RECTANGULAR)
            closed_form_pulse = .true.
            beta_cf = -ieee_value(beta_cf, ieee_positive_inf)
        case (PULSE_TRIANGULAR)
            closed_form_pulse = .not. abs(p%peak_frac - 0.5_dp) > 0.0_dp
        end select
    end function closed_form_pulse

    subroutine do_summary(path, prefix, pin, gb, gr, blk, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(pulse_input_t), intent(in) :: pin
        type(nml_group), intent(in) :: gb, gr
        type(rocking_block_t), intent(in) :: blk
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(rocking_run_t) :: run
        character(len=512) :: msg, files(2), comments(8)
        real(dp) :: row(21), nan, f, eta, beta_cf, tau_up, tau_c, tau_m, psi_max, tau_i, td
        character(len=32) :: names(0:5)
        integer :: region, i, k
        logical :: cf

        nan = ieee_value(nan, ieee_quiet_nan)
        call echo()
        stat = 1
        msg = ''
        call rock_pulse(blk, pin%p, run, i, msg, t_max=t_max, rtol=rtol, kv=kv)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = locate_message(path, trim(msg), pin, gb, gr)
            return
        end if
        ! the closed forms have no vertical acceleration
        cf = closed_form_pulse(pin%p, beta_cf) .and. .not. abs(kv) > 0.0_dp
        f = nan
        eta = nan
        region = -1
        tau_up = nan
        tau_c = nan
        tau_m = nan
        psi_max = nan
        tau_i = nan
        td = pin%p%duration
        if (cf) then
            f = blk%p * td
            eta = blk%alpha / pin%amp_g
            call rocking_summary(f, eta, beta_cf, region, tau_up, tau_c, tau_m, psi_max, &
                                 tau_i, i, msg)
            if (i /= SEISPULSE_SUCCESS) then
                errmsg = located(path, gb)//'closed forms: '//trim(msg)
                return
            end if
        end if
        row = nan
        row(1:6) = [blk%alpha, blk%p, blk%e, f, eta, real(run%outcome, dp)]
        row(7:8) = [run%t_uplift, run%t_overturn]
        row(9) = real(run%n_impacts, dp)
        if (run%n_impacts > 0) row(10) = run%t_impacts(1)
        row(11:15) = [run%theta_max, run%theta_min, run%theta_max / blk%alpha, &
                      run%theta_min / blk%alpha, run%t_end]
        if (cf) row(16:21) = [real(region, dp), tau_up * td, tau_c * td, tau_m * td, &
                              psi_max, tau_i * td]

        call block_comments(pin, blk, comments(1:3))
        comments(4) = 't_overturn: last outward crossing of |theta| = alpha before ' &
                      //'overturning (theta_max = pi/2 then); t_impact1: first impact; ' &
                      //'t_end: rest, overturned (|theta| = pi/2) or the time limit'
        comments(5) = 'psi = theta/alpha; nan: no such event'
        do k = 0, 5
            names(k) = rocking_region_name(k)
        end do
        comments(6) = 'region: the closed forms'' response region (nan without them)'
        if (cf) then
            comments(7) = 'closed forms (_cf): linearized model (doc/rocking.md (2.4)-(2.35), ' &
                          //'seispulse_rocking_closed), half-cycle exponential pulse, beta = ' &
                          //shortest_str(beta_cf)//', f = p t_d, eta = alpha/(A_g/g)'
        else
            comments(7) = 'closed forms (_cf): nan, they exist for the half-cycle ' &
                          //'exponential pulse (also rectangular, symmetric triangular) ' &
                          //'with amp > 0 only'
            if (abs(kv) > 0.0_dp) comments(7) = 'closed forms (_cf): nan, they have no ' &
                                               //'vertical ground acceleration (kv = 0 only)'
        end if
        comments(8) = 'input: '//trim(path)
        call write_tables(prefix, 'rocking', comments, &
            [character(len=12) :: 'alpha', 'p', 'e', 'f', 'eta', 'outcome', 't_uplift', &
             't_overturn', 'n_impacts', 't_impact1', 'theta_max', 'theta_min', 'psi_max', &
             'psi_min', 't_end', 'region', 't_up_cf', 't_c_cf', 't_m_cf', 'psi_max_cf', &
             't_i_cf'], &
            [character(len=6) :: 'rad', 'rad/s', '-', '-', '-', '-', 's', 's', '-', 's', &
             'rad', 'rad', '-', '-', 's', '-', 's', 's', 's', '-', 's'], &
            reshape(row, [1, size(row)]), files, stat, errmsg, &
            kinds=[character(len=256) :: '', '', '', '', '', category_kind(run_outcome_names), &
                   '', '', 'int', '', '', '', '', '', '', category_kind(names)], summary=.true.)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        write(output_unit, '(a)') 'rocking: '//trim(run_outcome_names(run%outcome))
        call say_written('rocking table', files)
    end subroutine do_summary

    !> Header lines describing the excitation and the block.
    subroutine block_comments(pin, blk, lines)
        type(pulse_input_t), intent(in) :: pin
        type(rocking_block_t), intent(in) :: blk
        character(len=*), intent(out) :: lines(3)
        lines(1) = 'seispulse analysis rocking: '//pulse_kind_name(pin%code)//' pulse, ' &
                   //trim(model)//' model (seispulse_rocking_sim)'
        call block_lines(blk, lines(2:3))
    end subroutine block_comments

    !> Header lines describing the block and its uplift (with kv).
    subroutine block_lines(blk, lines)
        type(rocking_block_t), intent(in) :: blk
        character(len=*), intent(out) :: lines(2)
        lines(1) = 'block: alpha = '//shortest_str(blk%alpha)//' rad, p = '//shortest_str(blk%p) &
                   //' rad/s, e = '//shortest_str(blk%e)//', g = '//shortest_str(blk%g)//' m/s2'
        lines(2) = 'uplift at |a_g| > g tan(alpha) (nonlinear) or g alpha (linearized); ' &
                   //'a_g > 0 drives theta > 0'
        if (abs(kv) > 0.0_dp) lines(2) = 'vertical ground acceleration a_v = kv a_g, kv = ' &
            //shortest_str(kv)//' (doc/rocking.md section 7): uplift at a_g > g t/(1 - kv t) or ' &
            //'a_g < -g t/(1 + kv t), t = tan(alpha) (nonlinear) or alpha (linearized); ' &
            //'a_g > 0 drives theta > 0'
    end subroutine block_lines

    ! ------------------------------------------------------------------------------
    ! History
    ! ------------------------------------------------------------------------------

    subroutine do_history(path, prefix, pin, gb, gr, blk, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(pulse_input_t), intent(in) :: pin
        type(nml_group), intent(in) :: gb, gr
        type(rocking_block_t), intent(in) :: blk
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(rocking_run_t) :: run
        character(len=512) :: msg, files(2), comments(7)
        real(dp), allocatable :: t(:), table(:, :), v(:), d(:)
        real(dp) :: t_last
        integer :: n, i

        call echo()
        stat = 1
        msg = ''
        ! --- the grid: up to t_end, or past the end of the motion
        t_last = t_end
        if (ieee_is_nan(t_end)) then
            call rock_pulse(blk, pin%p, run, i, msg, t_max=t_max, rtol=rtol, kv=kv)
            if (i /= SEISPULSE_SUCCESS) then
                errmsg = locate_message(path, trim(msg), pin, gb, gr)
                return
            end if
            if (run%outcome == ROCK_RUN_TIME_LIMIT .and. run%t_end > 0.0_dp) then
                t_last = run%t_end               ! no solution beyond it
            else
                t_last = max(1.25_dp * run%t_end, pulse_end(pin))
            end if
        end if
        call time_grid(t_last, dt, npts, t, errmsg)
        if (len(errmsg) > 0) then
            errmsg = located(path, gr)//errmsg
            return
        end if
        n = size(t)
        allocate(table(n, 4), v(n), d(n))
        call rock_pulse(blk, pin%p, run, i, msg, t_grid=t, theta_grid=table(:, 3), &
                        omega_grid=table(:, 4), t_max=t_max, rtol=rtol, kv=kv)
        if (i == SEISPULSE_SUCCESS) call pulse_eval(pin%p, t, table(:, 2), v, d, i, msg)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = locate_message(path, trim(msg), pin, gb, gr)
            return
        end if
        table(:, 1) = t

        call block_comments(pin, blk, comments(1:3))
        comments(4) = 'outcome: '//trim(run_outcome_names(run%outcome))//', t_uplift = ' &
                      //shortest_str(run%t_uplift)//' s, impacts: '//int_str(run%n_impacts) &
                      //', theta_max = '//shortest_str(run%theta_max)//' rad, theta_min = ' &
                      //shortest_str(run%theta_min)//' rad, t_end = '//shortest_str(run%t_end)//' s'
        comments(5) = 'theta: rotation (rad; > 0 about one corner, < 0 about the other), ' &
                      //'omega = dtheta/dt (rad/s)'
        comments(6) = 'overturned: theta = +-pi/2 and omega = 0 after t_end; nan after a ' &
                      //'time limit'
        comments(7) = 'input: '//trim(path)
        call write_tables(prefix, 'rocking_history', comments, &
            [character(len=8) :: 't', 'a_g', 'theta', 'omega'], &
            [character(len=8) :: 's', 'm/s2', 'rad', 'rad/s'], table, files, stat, errmsg)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        write(output_unit, '(a)') 'rocking: '//trim(run_outcome_names(run%outcome))
        call say_written('rocking history', files)
    end subroutine do_history

    ! ------------------------------------------------------------------------------
    ! Overturning map
    ! ------------------------------------------------------------------------------

    subroutine do_map(path, prefix, gb, gr, gm, blk, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(nml_group), intent(in) :: gb, gr, gm
        type(rocking_block_t), intent(in) :: blk
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=512) :: msg, files(2), comments(7)
        real(dp), allocatable :: freqs(:), amps(:), table(:, :)
        integer, allocatable :: classes(:, :)
        type(pulse_t) :: tpl, pl
        integer :: code, i, j, row, st
        type(progress_t) :: progress

        where = located(path, gm)
        stat = 1
        msg = ''
        call map_kind(where, kind, code, errmsg)
        if (len(errmsg) > 0) return
        call map_axis(gm, 'freq', freq_ratio, freq_range, freq_count, .true., freqs, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        call map_axis(gm, 'amp', amp_ratio, amp_range, amp_count, .false., amps, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        ! the shape first (at a unit time scale), then every time scale of the map
        call map_template(where, code, beta, full, peak_frac, t0_periods, cycles, tpl, errmsg)
        if (len(errmsg) > 0) return
        do j = 1, size(freqs)
            pl = tpl
            pl%amp = tan(blk%alpha)
            if (code == PULSE_RICKER) then
                pl%freq = freqs(j) / (2.0_dp * pi)
                pl%t0 = t0_periods / pl%freq
            else
                pl%duration = 2.0_dp * pi / freqs(j)
            end if
            call pulse_validate(pl, st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                if (given(gm, 'freq_ratio')) then
                    errmsg = where//'freq_ratio('//int_str(j)//') = '//real_str(freqs(j))
                else
                    errmsg = where//'freq_range: the value '//real_str(freqs(j))
                end if
                errmsg = errmsg//': no valid pulse at this time scale ('//trim(msg)//')'
                return
            end if
        end do
        call warn_unused_template(path, gm, code)

        call echo()
        allocate(classes(size(amps), size(freqs)))
        call progress%start()
        do i = 1, size(amps)
            call overturning_map(blk%alpha, blk%e, code, freqs, amps(i:i), &
                                 classes(i:i, :), st, msg, linearized=blk%linearized, &
                                 template=tpl, rtol=rtol, kv=kv)
            if (st /= SEISPULSE_SUCCESS) then
                if (index(msg, 'kv ') == 1) then
                    ! one row at a time: name the amplitude, not the library's amp_ratio(1)
                    errmsg = located(path, gr)//'kv = '//real_str(kv)//': at amp_ratio = ' &
                             //real_str(amps(i))//' the vertical acceleration kv a_g goes ' &
                             //'below -g (the block would leave the ground)'
                else if (index(msg, 'rtol') == 1) then
                    errmsg = located(path, gr)//trim(msg)
                else if (index(msg, 'alpha') == 1 .or. msg(1:2) == 'e ') then
                    errmsg = located(path, gb)//trim(msg)
                else
                    errmsg = where//trim(msg)
                end if
                return
            end if
            call progress%row(i, size(amps))
        end do
        call progress%done(size(amps))

        allocate(table(size(amps) * size(freqs), 3))
        row = 0
        do i = 1, size(amps)
            do j = 1, size(freqs)
                row = row + 1
                table(row, :) = [freqs(j), amps(i), real(classes(i, j), dp)]
            end do
        end do
        comments(1) = 'seispulse analysis rocking: overturning map, '//pulse_kind_name(code) &
                      //' pulse family, '//trim(model)//' model (seispulse_rocking_sim)'
        comments(2) = map_class_line
        comments(3) = 'freq_ratio = omega_p/p, omega_p = 2 pi/T_p (T_p: t_d of the ' &
                      //'exponential pulse, the period of sine/cosine cycles, the length ' &
                      //'of the others; Ricker: omega_p = 2 pi f_p)'
        comments(4) = 'amp_ratio = a_p/(g tan alpha) (both models); rows: amp_ratio ' &
                      //'outer, freq_ratio inner'
        comments(5) = 'block: alpha = '//shortest_str(blk%alpha)//' rad, e = '//shortest_str(blk%e)
        if (abs(kv) > 0.0_dp) comments(5) = trim(comments(5))//'; vertical ground ' &
            //'acceleration a_v = kv a_g, kv = '//shortest_str(kv)//' (doc/rocking.md section 7)'
        comments(6) = template_text(tpl)
        comments(7) = 'input: '//trim(path)
        call write_tables(prefix, 'rocking_map', comments, &
            [character(len=12) :: 'freq_ratio', 'amp_ratio', 'class'], &
            [character(len=4) :: '-', '-', '-'], table, files, stat, errmsg, &
            kinds=[character(len=256) :: '', '', category_kind(map_class_names)])
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('rocking map', files)
    end subroutine do_map

    !> One axis of the map from a list (`<axis>_ratio`) or a range with a count.
    subroutine map_axis(gm, axis, list, range, count, positive, values, errmsg)
        type(nml_group), intent(in) :: gm
        character(len=*), intent(in) :: axis              !! 'freq' or 'amp'
        real(dp), intent(in) :: list(:), range(2)
        integer, intent(in) :: count
        logical, intent(in) :: positive                   !! > 0 (else >= 0)
        real(dp), allocatable, intent(out) :: values(:)
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: grid
        call axis_values(gm, axis//'_ratio', axis, list, range, count, 'linear', positive, &
                         .false., max_list, values, grid, errmsg, required=.true., &
                         count_optional=.true., hint=.false., real_numbers=.true.)
    end subroutine map_axis

    ! ------------------------------------------------------------------------------
    ! Records
    ! ------------------------------------------------------------------------------

    !> The groups that go with &records (use_records) or without it. errmsg is empty on
    !> success.
    subroutine records_setup(path, groups, task, use_records, pin, grec, gb, errmsg)
        character(len=*), intent(in) :: path, task
        type(nml_group), intent(in) :: groups(:)
        logical, intent(in) :: use_records                !! &records is given
        type(pulse_input_t), intent(in) :: pin
        type(nml_group), intent(in) :: grec, gb
        character(len=:), allocatable, intent(out) :: errmsg
        errmsg = ''
        if (.not. use_records) then
            if (given(gb, 'g')) errmsg = located(path, gb)//'g: only with &records (the ' &
                //'gravity and unit g of the records; with &pulse it is &pulse''s g)'
            return
        end if
        if (task == 'map') then
            errmsg = located(path, grec)//'not used by what = ''map'' (the pulse family ' &
                     //'and shape of a map are in &map)'
        else if (find_group(groups, 'pulse') > 0) then
            errmsg = located(path, pin%group)//'not with &records (the base moves under ' &
                     //'one pulse or under records: give one of the two groups)'
        end if
    end subroutine records_setup

    !> Summary row of one record after the label: pga (g, after scaling), the block, the
    !> run (outcome code, times, impacts, extremes, max |theta| and its time), status 0
    !> (ok).
    function record_row(pga, blk, run) result(row)
        real(dp), intent(in) :: pga
        type(rocking_block_t), intent(in) :: blk
        type(rocking_run_t), intent(in) :: run
        real(dp) :: row(n_rec_cols)
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        row = nan
        row(1:5) = [pga, blk%alpha, blk%p, blk%e, real(run%outcome, dp)]
        row(6:8) = [run%t_uplift, run%t_overturn, real(run%n_impacts, dp)]
        if (run%n_impacts > 0) row(9) = run%t_impacts(1)
        row(10:14) = [run%theta_max, run%theta_min, run%theta_max / blk%alpha, &
                      run%theta_min / blk%alpha, run%t_end]
        ! the largest |theta| and the first time it is reached (either side)
        if (run%theta_max > -run%theta_min) then
            row(15:16) = [run%theta_max, run%t_theta_max]
        else if (run%theta_max < -run%theta_min) then
            row(15:16) = [-run%theta_min, run%t_theta_min]
        else
            row(15:16) = [run%theta_max, min(run%t_theta_max, run%t_theta_min)]
        end if
        row(17) = 0.0_dp
    end function record_row

    !> 'summary' or 'history' under each record of &records: a record that cannot be
    !> read or run gives a row of NaN (status failed) and the others go on; stat ROWS_FAILED
    !> then (the table is written).
    subroutine do_records(path, prefix, grec, gr, blk, recs, slammer_rounding, history, &
                          stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(nml_group), intent(in) :: grec, gr
        type(rocking_block_t), intent(in) :: blk
        type(record_in_t), intent(in) :: recs(:)
        logical, intent(in) :: slammer_rounding, history
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(rocking_run_t), allocatable :: runs(:)
        type(record_out_t), allocatable :: outs(:)
        character(len=:), allocatable :: grid_msg
        character(len=512) :: files(2)
        character(len=1024), allocatable :: comments(:)
        character(len=256), allocatable :: labels(:), hlabels(:)
        real(dp), allocatable :: summary(:, :), hist(:, :)
        real(dp) :: nan
        integer :: nrec, ir, nfailed
        logical, allocatable :: failed(:)

        nan = ieee_value(nan, ieee_quiet_nan)
        call echo_records_mode(recs, slammer_rounding)
        call rock_records(located(path, grec), 'rocking', recs, slammer_rounding, blk, blk%g, &
                          kv, t_max, rtol, history, t_end, dt, npts, outs, failed, runs, &
                          hist, hlabels, grid_msg, ir)
        if (len(grid_msg) > 0) then
            stat = 1
            errmsg = located(path, gr)//list_item('files', ir)//': '//grid_msg
            return
        end if
        nrec = size(recs)
        allocate(labels(nrec), summary(nrec, n_rec_cols))
        do ir = 1, nrec
            labels(ir) = outs(ir)%name
            if (failed(ir)) then
                ! a failed row: the block, NaN results, status failed
                summary(ir, :) = nan
                summary(ir, 2:4) = [blk%alpha, blk%p, blk%e]
                summary(ir, n_rec_cols) = 1.0_dp
            else
                summary(ir, :) = record_row(outs(ir)%pga, blk, runs(ir))
            end if
        end do

        call record_comments(path, blk, recs, outs, failed, summary, history, comments)
        if (history) then
            call write_tables(prefix, 'rocking_history', comments, &
                [character(len=8) :: 'record', 't', 'a_g', 'theta', 'omega'], &
                [character(len=8) :: '-', 's', 'm/s2', 'rad', 'rad/s'], hist, files, stat, &
                errmsg, labels=hlabels)
        else
            call write_tables(prefix, 'rocking', comments, rec_names, rec_units, summary, &
                              files, stat, errmsg, labels=labels, kinds=record_kinds())
        end if
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        if (history) then
            call say_written('rocking history', files)
        else
            call say_written('rocking table', files)
        end if
        stat = 0
        nfailed = count(failed)
        if (nfailed > 0) then
            stat = ROWS_FAILED
            errmsg = int_str(nfailed)//' of '//int_str(nrec)//' records failed (' &
                     //failed_records(outs, failed)//'): their rows hold NaN'
            if (.not. history) errmsg = errmsg//' and status failed'
        end if
    end subroutine do_records

    !> Header lines of the tables on records: the model, the block, the columns, then
    !> one line per record (with its outcome in a history), then the input file.
    subroutine record_comments(path, blk, recs, outs, failed, summary, history, comments)
        character(len=*), intent(in) :: path
        type(rocking_block_t), intent(in) :: blk
        type(record_in_t), intent(in) :: recs(:)
        type(record_out_t), intent(in) :: outs(:)
        logical, intent(in) :: failed(:)
        real(dp), intent(in) :: summary(:, :)             !! the summary rows
        logical, intent(in) :: history
        character(len=1024), allocatable, intent(out) :: comments(:)
        integer, parameter :: nh = 6
        integer :: ir, nrec

        nrec = size(recs)
        allocate(comments(nh + nrec + 1))
        comments(1) = 'seispulse analysis rocking: records (&records; the samples in g, ' &
                      //'linear in between, 0 after the last), '//trim(model) &
                      //' model (seispulse_rocking_sim)'
        call block_lines(blk, comments(2:3))
        if (history) then
            comments(4) = 'rows: each record from t = 0; theta: rotation (rad; > 0 about one ' &
                          //'corner, < 0 about the other), omega = dtheta/dt (rad/s), a_g = ' &
                          //'g x the record (m/s2)'
            comments(5) = 'overturned: theta = +-pi/2 and omega = 0 after t_end; NaN after a ' &
                          //'time limit, and one row of NaN for a record that failed (exit ' &
                          //'status 1)'
            comments(6) = 'records (index, file, format read, npts, dt (s), PGA as read (g), ' &
                          //'scale factor; outcome):'
        else
            comments(4) = 'pga: after scaling (g); t_overturn: last outward crossing of ' &
                          //'|theta| = alpha before overturning (theta_max = pi/2 then); ' &
                          //'t_impact1: first impact; t_end: rest, overturned (|theta| = ' &
                          //'pi/2) or the time limit'
            comments(5) = 'psi = theta/alpha; theta_abs_max: the largest |theta|, t_abs_max: ' &
                          //'the first time it is reached; NaN: no such event'
            comments(6) = 'status: ok, or failed (NaN results; the reason is below and on ' &
                          //'stderr; exit status 1); records (index, file, format read, npts, ' &
                          //'dt (s), PGA as read (g), scale factor):'
        end if
        do ir = 1, nrec
            comments(nh + ir) = record_line(ir, recs(ir), outs(ir))
            if (outs(ir)%ok .and. failed(ir)) then
                comments(nh + ir) = trim(comments(nh + ir))//'; FAILED: '//outs(ir)%message
            else if (history .and. .not. failed(ir)) then
                comments(nh + ir) = trim(comments(nh + ir))//'; outcome: ' &
                    //trim(run_outcome_names(nint(summary(ir, 5))))//', impacts: ' &
                    //int_str(nint(summary(ir, 8)))//', theta_max = ' &
                    //shortest_str(summary(ir, 10))//' rad, theta_min = ' &
                    //shortest_str(summary(ir, 11))//' rad, t_end = ' &
                        //shortest_str(summary(ir, 14)) &
                    //' s'
            end if
        end do
        comments(nh + nrec + 1) = 'input: '//trim(path)
    end subroutine record_comments

    !> Column kinds of the summary table on records (outcome and status by name, the
    !> impacts as an integer).
    function record_kinds() result(kinds)
        character(len=160) :: kinds(n_rec_cols + 1)
        kinds = ''
        kinds(6) = category_kind(run_outcome_names)
        kinds(9) = 'int'
        kinds(n_rec_cols + 1) = category_kind(status_names)
    end function record_kinds

    !> Echo the effective input with &records: &records, &block (with g), &rocking.
    subroutine echo_records_mode(recs, slammer_rounding)
        type(record_in_t), intent(in) :: recs(:)
        logical, intent(in) :: slammer_rounding
        namelist /block/ b, h, alpha, alpha_deg, r, io_over_mr2, e, model, g
        what = trim(lower(adjustl(what)))
        call echo_records(recs, slammer_rounding)
        write(echo_unit(), nml=block)
        if (abs(kv) > 0.0_dp) then
            call echo_rocking_kv()
        else
            call echo_rocking()
        end if
    end subroutine echo_records_mode

    ! ------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------

    !> Echo the effective input (&pulse unless a map, &block, &rocking, &map if a map).
    subroutine echo()
        character(len=:), allocatable :: task
        task = trim(lower(adjustl(what)))
        what = task
        if (task /= 'map') call write_pulse_group(echo_unit())
        write(echo_unit(), nml=block)
        if (abs(kv) > 0.0_dp) then
            call echo_rocking_kv()
        else
            call echo_rocking()
        end if
        if (task == 'map') then
            if (not_one(cycles)) then
                write(echo_unit(), nml=map)
            else
                call echo_map_without_cycles()
            end if
        end if
    end subroutine echo

    !> Echo &rocking as before kv existed (kv = 0: the same output as without it).
    subroutine echo_rocking()
        namelist /rocking/ what, t_max, rtol, t_end, npts, dt
        write(echo_unit(), nml=rocking)
    end subroutine echo_rocking

    !> Echo &rocking with kv.
    subroutine echo_rocking_kv()
        namelist /rocking/ what, t_max, rtol, t_end, npts, dt, kv
        write(echo_unit(), nml=rocking)
    end subroutine echo_rocking_kv

    !> The echo of &map without `cycles` when it is 1 (the default), so that the echo of
    !> an input without it stays as it was: a local namelist of the same name hides the
    !> module's one here.
    subroutine echo_map_without_cycles()
        namelist /map/ kind, beta, full, peak_frac, t0_periods, freq_ratio, freq_range, &
            freq_count, amp_ratio, amp_range, amp_count
        write(echo_unit(), nml=map)
    end subroutine echo_map_without_cycles

end module driver_rocking
