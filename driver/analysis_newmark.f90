!> Analysis 'newmark': rigid-block (Newmark) sliding, or a flexible sliding mass
!> (decoupled or coupled, doc/flexible.md section 9), on accelerogram files, one row per
!> record and yield acceleration, for the record as read ("normal") and turned over
!> ("inverse", the record times -1).
!>
!> Groups: &records (driver_records, shared with analysis 'sdof': the files and how to
!> read and scale each one), &newmark (the method, the yield accelerations ky, a yield
!> table, or friction values mu on one incline, the mode and the integration rule) and,
!> for the flexible methods, &slope (driver_slope: the sliding mass). Table
!> <output>_newmark. A flexible case whose equivalent-linear iteration does not
!> converge keeps the results of its last iteration with converged = 0: a warning on
!> stderr and in the header, not a failure.
!> Everything is checked before any record is read. A record that cannot be read or
!> scaled fails its rows (NaN results, status failed; the message goes to stderr and into the
!> table's header) and the other records are still computed; run_newmark then returns
!> ROWS_FAILED and the driver exits with status 1 after writing the table. The
!> numbers come from seispulse_records (reading, PGA scaling) and seispulse_newmark (the
!> sliding block); the driver only reads, checks, converts units and writes.
module driver_newmark
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    use seispulse, only: dp, shortest_str, SEISPULSE_SUCCESS, int_str, newmark_block_t, &
                         newmark_result_t, &
                         newmark_rigid, newmark_incline, newmark_block_validate, &
                         newmark_mode_code, newmark_method_code, newmark_mode_name, &
                         newmark_method_name, NEWMARK_DOWN, NEWMARK_BOTH, NEWMARK_ASYM, positive, &
                         finite_positive, NEWMARK_EXACT, SEISPULSE_NO_CONVERGENCE, &
                         flexible_mass_t, flexible_result_t, flexible_decoupled, flexible_coupled, &
                         ky_table_validate
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: find_group, located, join, read_optional, given, &
                            list_length, list_item, value_name, name_index, ROWS_FAILED
    use driver_input, only: missing_group
    use driver_input, only: output_located
    use driver_tables, only: table_t, table_open, table_comment, table_row, table_close, &
                             table_drop, say_written, category_kind, status_names
    use driver_slope, only: slope_keys, slope_defaults, read_slope, check_slope, echo_slope, &
                            slope_line
    use driver_records, only: records_keys, record_in_t, record_out_t, records_defaults, &
                              read_records, check_records, echo_records, load_record, report, &
                              records_missing, record_line, add_failed_record
    use driver_intensity_table, only: intensity_table_t, intensity_check, intensity_echo, &
                                      intensity_start, intensity_record, intensity_open, &
                                      intensity_add
    use driver_echo, only: echo_unit
    use driver_unit_result, only: unit_result_t, add_field, get_field, add_log
    use driver_batch, only: batch_run, record_keys, pack_record, unpack_record, RECORD_VALUES, &
                            RECORD_FIELDS
    use driver_records, only: record_place
    implicit none
    private

    public :: run_newmark, newmark_groups, newmark_tables

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: newmark_groups(3) = [character(len=8) :: 'records', &
        'newmark', 'slope']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=9), parameter :: newmark_tables(2) = [character(len=9) :: 'newmark', 'intensity']

    character(len=12), parameter :: newmark_keys(16) = [character(len=12) :: 'ky', 'mode', &
        'ky_up', 'k_down', 'k_up', 'mu', 'slope_deg', 'xi_deg', 'along_plane', 'method', 'g', &
        'intensity', 'sa_periods', 'rule', 'ky_disp', 'ky_table']
    character(len=4), parameter :: mode_names(3) = [character(len=4) :: 'down', 'both', 'asym']
    character(len=7), parameter :: method_names(2) = [character(len=7) :: 'exact', 'slammer']
    !> The analyses of `method` (KIND_* in this order); 'exact', 'slammer': the old form of
    !> method = 'rigid' with that rule.
    character(len=9), parameter :: kind_names(3) = [character(len=9) :: 'rigid', &
        'decoupled', 'coupled']
    integer, parameter :: KIND_RIGID = 1, KIND_DECOUPLED = 2, KIND_COUPLED = 3

    !> Most ky (or mu) values.
    integer, parameter :: max_ky = 1000

    ! namelist variables (defaults are set in set_defaults; &records: driver_records)
    real(dp) :: ky(max_ky), ky_up(max_ky), k_down, k_up, mu(max_ky), slope_deg, xi_deg, g
    character(len=32) :: mode, method
    logical :: along_plane
    ! the intensity table (driver_intensity_table): on/off and the Sa periods (s)
    logical :: intensity
    real(dp) :: sa_periods(max_ky)
    character(len=32) :: rule
    real(dp) :: ky_disp(max_ky), ky_table(max_ky)
    namelist /newmark/ ky, mode, ky_up, k_down, k_up, mu, slope_deg, xi_deg, along_plane, &
        method, g, intensity, sa_periods, rule, ky_disp, ky_table

    !> The validated input.
    type :: config_t
        type(record_in_t), allocatable :: recs(:)
        logical :: slammer_rounding = .false.
        type(newmark_block_t), allocatable :: blocks(:)  !! one per ky (or mu)
        real(dp), allocatable :: mu(:)                   !! friction per block (mu input)
        logical :: with_mu = .false.
        real(dp) :: slope_deg = 0.0_dp                   !! incline (mu input)
        real(dp) :: xi_deg = 0.0_dp
        logical :: along_plane = .true.
        integer :: mode = NEWMARK_DOWN
        integer :: method = 0                            !! the rule: NEWMARK_EXACT, _SLAMMER
        real(dp) :: g = 9.80665_dp
        integer :: kind = KIND_RIGID                     !! KIND_*
        type(flexible_mass_t) :: mass                    !! &slope (flexible methods)
        real(dp), allocatable :: ky_disp(:), ky_values(:) !! yield table (m, g), if given
    end type config_t

    ! --- the batch being computed (set by compute before batch_run, read-only while the
    ! units run concurrently in newmark_unit)
    type(config_t) :: run_cfg
    character(len=:), allocatable :: run_where          !! "file:line: &records: "
    logical :: run_itab_on = .false.                    !! the intensity table is on
    real(dp), allocatable :: run_periods(:)             !! its Sa periods (s)
    ! --- the tables being written (on the root, by newmark_take: one record at a time,
    ! in record order)
    type(table_t) :: out_table                          !! <output>_newmark
    type(table_t) :: out_itable                         !! <output>_intensity (if on)
    integer :: out_failed = 0                           !! rows of out_table failed
    integer :: out_ifailed = 0                          !! rows of out_itable failed
    integer :: out_named = 0                            !! records in out_names
    character(len=:), allocatable :: out_names          !! records with a failed row

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        call records_defaults()
        ky = nan
        mode = ''
        ky_up = nan
        k_down = 1.0_dp
        k_up = 1.0_dp
        mu = nan
        slope_deg = 0.0_dp
        xi_deg = 0.0_dp
        along_plane = .true.
        method = 'rigid'
        g = 9.80665_dp
        intensity = .false.
        sa_periods = nan
        rule = 'exact'
        ky_disp = nan
        ky_table = nan
        call slope_defaults()
    end subroutine set_defaults

    subroutine read_newmark(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=newmark, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=newmark, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_newmark

    !> Read and check the groups, compute every row, write the table; print where it
    !> went. stat: 0, ROWS_FAILED (table written, errmsg says how many rows
    !> failed), or > 0 for an input or output error (nothing written).
    subroutine run_newmark(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(nml_group) :: gr, gn, gs
        type(config_t) :: cfg
        type(intensity_table_t) :: itab
        character(len=512) :: files_out(2), files_int(2)

        call set_defaults()
        call read_optional(path, groups, 'records', records_keys, read_records, gr, stat, &
                           errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'newmark', newmark_keys, read_newmark, gn, stat, &
                           errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'slope', slope_keys, read_slope, gs, stat, errmsg)
        if (stat /= 0) return
        stat = 1
        if (find_group(groups, 'records') == 0) then
            errmsg = missing_group(path, 'records')//records_missing
            return
        end if
        if (find_group(groups, 'newmark') == 0) then
            errmsg = missing_group(path, 'newmark')//' (it gives the yield accelerations ky ' &
                     //'or the friction mu of an incline)'
            return
        end if
        call check_records(path, gr, cfg%recs, cfg%slammer_rounding, errmsg)
        if (len(errmsg) > 0) return
        call check_newmark(path, gn, cfg, errmsg)
        if (len(errmsg) > 0) return
        call check_method_slope(path, gn, gs, cfg, errmsg)
        if (len(errmsg) > 0) return
        call intensity_check(located(path, gn), intensity, given(gn, 'sa_periods'), sa_periods, &
                             itab, errmsg)
        if (len(errmsg) > 0) return

        ! --- echo the effective input
        call echo_records(cfg%recs, cfg%slammer_rounding)
        call echo_newmark(cfg)
        call intensity_echo(itab)
        if (cfg%kind /= KIND_RIGID) call echo_slope(cfg%mass)

        ! --- compute every record, writing its rows as it comes (the tables are renamed
        !     from <file>.part when the run ends)
        call compute(path, gr, prefix, cfg, itab, files_out, files_int, stat, errmsg)
        if (stat /= 0) return
        call say_written('newmark table', files_out)
        if (itab%on) call say_written('intensity table', files_int)
        stat = 0
        if (out_failed > 0) then
            stat = ROWS_FAILED
            errmsg = int_str(out_failed)//' of '//int_str(size(cfg%recs) * size(cfg%blocks)) &
                     //' rows failed (records: '//out_names//')'
        else if (out_ifailed > 0) then
            stat = ROWS_FAILED
            errmsg = int_str(out_ifailed)//' of '//int_str(size(cfg%recs)) &
                     //' rows of the intensity table failed'
        end if
    end subroutine run_newmark

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> Check &newmark and fill the blocks of cfg. errmsg is empty on success.
    subroutine check_newmark(path, gn, cfg, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gn
        type(config_t), intent(inout) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, item
        character(len=1024) :: msg
        character(len=12), parameter :: incline_keys(3) = [character(len=12) :: 'slope_deg', &
            'xi_deg', 'along_plane']
        character(len=12), parameter :: asym_keys(3) = [character(len=12) :: 'ky_up', &
            'k_down', 'k_up']
        character(len=12), parameter :: rigid_keys(6) = [character(len=12) :: 'mu', &
            'slope_deg', 'xi_deg', 'along_plane', 'k_down', 'k_up']
        integer :: n, i, k, n_up, st
        real(dp) :: nan

        nan = ieee_value(nan, ieee_quiet_nan)
        where = located(path, gn)
        errmsg = ''

        ! --- method (the analysis), rule and g
        cfg%kind = name_index(method, kind_names)
        if (cfg%kind > 0) then
            cfg%method = newmark_method_code(trim(lower(adjustl(rule))))
            if (cfg%method == 0) then
                errmsg = where//'rule = '''//trim(rule)//''': unknown rule (allowed: ' &
                         //join(method_names)//')'
                return
            end if
        else
            ! the old form: method = 'exact' | 'slammer' is a rigid block with that rule
            cfg%kind = KIND_RIGID
            cfg%method = newmark_method_code(trim(lower(adjustl(method))))
            if (cfg%method == 0) then
                errmsg = where//'method = '''//trim(method)//''': unknown method (allowed: ' &
                         //join(kind_names)//'; the old '//join(method_names)//' = rigid ' &
                         //'with that rule)'
                return
            end if
            if (given(gn, 'rule')) then
                errmsg = where//'rule: not with method = '''//trim(adjustl(method)) &
                         //''' (the old form of method = ''rigid'', rule = ''' &
                         //trim(adjustl(method))//'''): give method = ''rigid'' and the rule'
                return
            end if
        end if
        if (.not. finite_positive(g)) then
            errmsg = where//'g = '//shortest_str(g)//': must be a finite number > 0 (m/s2)'
            return
        end if
        cfg%g = g

        ! --- mode
        if (given(gn, 'mode')) then
            cfg%mode = newmark_mode_code(trim(lower(adjustl(mode))))
            if (cfg%mode == 0) then
                errmsg = where//'mode = '''//trim(mode)//''': unknown mode (allowed: ' &
                         //join(mode_names)//')'
                return
            end if
            if (cfg%mode /= NEWMARK_DOWN .and. cfg%kind /= KIND_RIGID .and. &
                (cfg%kind /= KIND_DECOUPLED .or. cfg%method /= NEWMARK_EXACT)) then
                errmsg = where//'mode = '''//trim(mode)//''': a flexible mass slides both ' &
                         //'ways only with method = ''decoupled'' and rule = ''exact'' ' &
                         //'(method is '''//trim(kind_names(cfg%kind))//''', rule ''' &
                         //newmark_method_name(cfg%method)//''')'
                return
            end if
        end if

        ! --- keys of the rigid block only
        if (cfg%kind /= KIND_RIGID) then
            do i = 1, size(rigid_keys)
                if (given(gn, trim(rigid_keys(i)))) then
                    errmsg = where//trim(rigid_keys(i))//': only with method = ''rigid'' ' &
                             //'(method is '''//trim(kind_names(cfg%kind))//''')'
                    return
                end if
            end do
        end if

        ! --- a yield table instead of ky
        if (given(gn, 'ky_disp') .or. given(gn, 'ky_table')) then
            call check_table(where, gn, cfg, errmsg)
            return
        end if

        ! --- ky or mu
        if (given(gn, 'ky') .and. given(gn, 'mu')) then
            errmsg = where//'ky, mu: give one of them (ky: yield accelerations in g; mu: ' &
                     //'friction coefficients of a block on an incline)'
            return
        else if (.not. (given(gn, 'ky') .or. given(gn, 'mu'))) then
            errmsg = where//'ky: missing (give ky, the yield accelerations in g, or mu, ' &
                     //'the friction of a block on an incline)'
            return
        end if

        if (given(gn, 'mu')) then
            cfg%with_mu = .true.
            if (given(gn, 'mode') .and. cfg%mode /= NEWMARK_ASYM) then
                errmsg = where//'mode = '''//trim(mode)//''': a block on an incline (mu) ' &
                         //'slides both ways with its own yields: leave mode out or give ' &
                         //'''asym'''
                return
            end if
            cfg%mode = NEWMARK_ASYM
            cfg%slope_deg = slope_deg
            cfg%xi_deg = xi_deg
            cfg%along_plane = along_plane
            do i = 1, size(asym_keys)
                if (given(gn, trim(asym_keys(i)))) then
                    errmsg = where//trim(asym_keys(i))//': not with mu (the incline gives ' &
                             //'the yields and the along-plane factors)'
                    return
                end if
            end do
            call list_length(mu, 'mu', n, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
            allocate(cfg%blocks(n), cfg%mu(n))
            cfg%mu = mu(1:n)
            do i = 1, n
                msg = ''
                call newmark_incline(mu(i), slope_deg, xi_deg, along_plane, cfg%blocks(i), &
                                     st, msg)
                if (st /= SEISPULSE_SUCCESS) then
                    errmsg = where//value_name('mu', i, n)//' = '//shortest_str(mu(i))//': ' &
                        //trim(msg)
                    return
                end if
            end do
            return
        end if

        ! --- ky
        do i = 1, size(incline_keys)
            if (given(gn, trim(incline_keys(i)))) then
                errmsg = where//trim(incline_keys(i))//': only with mu (a block on an ' &
                         //'incline); with ky the slope is in the yields already'
                return
            end if
        end do
        call list_length(ky, 'ky', n, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        allocate(cfg%blocks(n), cfg%mu(n))
        cfg%mu = nan
        n_up = 0
        if (cfg%mode == NEWMARK_ASYM) then
            if (.not. given(gn, 'ky_up')) then
                errmsg = where//'ky_up: missing (mode ''asym'' needs the upslope yields: ' &
                         //'one value for all ky, or one per ky; g, > 0, inf: none)'
                return
            end if
            call list_length(ky_up, 'ky_up', n_up, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
            if (n_up > 1 .and. n_up /= n) then
                errmsg = where//'ky_up: '//int_str(n_up)//' values for '//int_str(n) &
                         //' ky (give one value for all ky, or one per ky)'
                return
            end if
        else
            do i = 1, size(asym_keys)
                if (given(gn, trim(asym_keys(i)))) then
                    errmsg = where//trim(asym_keys(i))//': only for mode ''asym'' (mode is ''' &
                             //newmark_mode_name(cfg%mode)//''')'
                    return
                end if
            end do
        end if
        do i = 1, n
            item = value_name('ky', i, n)
            if (.not. positive(ky(i))) then
                errmsg = where//item//' = '//shortest_str(ky(i))//': must be > 0 (g; inf: no ' &
                         //'sliding)'
                return
            end if
            cfg%blocks(i)%mode = cfg%mode
            cfg%blocks(i)%ky = ky(i)
            cfg%blocks(i)%ky_up = ky(i)
            if (cfg%mode == NEWMARK_ASYM) then
                k = min(i, n_up)
                if (.not. positive(ky_up(k))) then
                    errmsg = where//value_name('ky_up', k, n_up)//' = '//shortest_str(ky_up(k)) &
                             //': must be > 0 (g; inf: no upslope sliding)'
                    return
                end if
                cfg%blocks(i)%ky_up = ky_up(k)
                cfg%blocks(i)%k_down = k_down
                cfg%blocks(i)%k_up = k_up
            end if
            msg = ''
            call newmark_block_validate(cfg%blocks(i), st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = where//trim(msg)
                return
            end if
        end do
    end subroutine check_newmark

    !> &newmark with ky_disp and ky_table: one block with the yield table (mode down).
    subroutine check_table(where, gn, cfg, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &newmark: "
        type(nml_group), intent(in) :: gn
        type(config_t), intent(inout) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=1024) :: msg
        integer :: n, n2, st

        errmsg = ''
        if (given(gn, 'ky') .or. given(gn, 'mu')) then
            errmsg = where//merge('ky', 'mu', given(gn, 'ky'))//', ky_table: give one of ' &
                     //'them (ky_disp and ky_table: a yield table ky(u) instead of ky)'
            return
        end if
        if (.not. given(gn, 'ky_disp') .or. .not. given(gn, 'ky_table')) then
            errmsg = where//merge('ky_table', 'ky_disp ', given(gn, 'ky_disp')) &
                     //': missing (a yield table needs both: ky_disp, the displacements ' &
                     //'(m), and ky_table, the yield accelerations (g))'
            errmsg = trim(errmsg)
            return
        end if
        if (cfg%mode /= NEWMARK_DOWN) then
            errmsg = where//'mode = '''//trim(mode)//''': a yield table slides one way ' &
                     //'(mode ''down'')'
            return
        end if
        if (given(gn, 'ky_up')) then
            errmsg = where//'ky_up: only for mode ''asym'' (with a yield table the mode is ' &
                     //'''down'')'
            return
        end if
        call list_length(ky_disp, 'ky_disp', n, errmsg)
        if (len(errmsg) == 0) call list_length(ky_table, 'ky_table', n2, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        if (n /= n2) then
            errmsg = where//'ky_table: '//int_str(n2)//' values for '//int_str(n) &
                     //' ky_disp (one yield acceleration per displacement)'
            return
        end if
        msg = ''
        call ky_table_validate(ky_disp(1:n), ky_table(1:n), st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = where//table_message(trim(msg))
            return
        end if
        cfg%ky_disp = ky_disp(1:n)
        cfg%ky_values = ky_table(1:n)
        allocate(cfg%blocks(1), cfg%mu(1))
        cfg%mu = ieee_value(0.0_dp, ieee_quiet_nan)
        cfg%blocks(1)%mode = NEWMARK_DOWN
        cfg%blocks(1)%ky = ky_table(1)
        cfg%blocks(1)%ky_up = ky_table(1)
        if (cfg%kind == KIND_RIGID) then
            cfg%blocks(1)%ky_disp = cfg%ky_disp
            cfg%blocks(1)%ky_values = cfg%ky_values
            msg = ''
            call newmark_block_validate(cfg%blocks(1), st, msg)
            if (st /= SEISPULSE_SUCCESS) errmsg = where//table_message(trim(msg))
        end if
    end subroutine check_table

    !> The library names the table's values ky_values; the key is ky_table.
    function table_message(msg) result(s)
        character(len=*), intent(in) :: msg
        character(len=:), allocatable :: s
        integer :: k
        s = msg
        k = index(s, 'ky_values')
        do while (k > 0)
            s = s(1:k - 1)//'ky_table'//s(k + 9:)
            k = index(s, 'ky_values')
        end do
    end function table_message

    !> &slope: required for 'decoupled' and 'coupled', refused for 'rigid'.
    subroutine check_method_slope(path, gn, gs, cfg, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gn, gs
        type(config_t), intent(inout) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        errmsg = ''
        if (cfg%kind == KIND_RIGID) then
            if (gs%line > 0) errmsg = located(path, gs)//'method = ''rigid'' (&newmark) has ' &
                //'no sliding mass: give method = ''decoupled'' or ''coupled'', or leave ' &
                //'&slope out'
            return
        end if
        if (gs%line == 0) then
            errmsg = located(path, gn)//'method = '''//trim(kind_names(cfg%kind)) &
                     //''': needs the group &slope (height, vs, vs_base of the sliding mass)'
            return
        end if
        call check_slope(path, gs, cfg%mass, errmsg)
    end subroutine check_method_slope

    ! ------------------------------------------------------------------------------
    ! Echo
    ! ------------------------------------------------------------------------------

    !> &newmark with the keys in use.
    subroutine echo_newmark(cfg)
        type(config_t), intent(in) :: cfg
        if (allocated(cfg%ky_disp)) then
            call echo_table(size(cfg%ky_disp))
        else if (cfg%kind /= KIND_RIGID .and. cfg%mode == NEWMARK_ASYM) then
            call echo_flexible_asym(size(cfg%blocks))
        else if (cfg%kind /= KIND_RIGID) then
            call echo_flexible(size(cfg%blocks))
        else if (cfg%with_mu) then
            call echo_mu(size(cfg%mu))
        else if (cfg%mode == NEWMARK_ASYM) then
            call echo_asym(size(cfg%blocks))
        else
            call echo_ky(size(cfg%blocks))
        end if

    contains

        subroutine echo_ky(n)
            integer, intent(in) :: n
            real(dp) :: ky(n), g
            character(len=4) :: mode
            character(len=7) :: method
            namelist /newmark/ ky, mode, method, g
            ky = cfg%blocks%ky
            mode = newmark_mode_name(cfg%mode)
            method = newmark_method_name(cfg%method)
            g = cfg%g
            write(echo_unit(), nml=newmark)
        end subroutine echo_ky

        subroutine echo_asym(n)
            integer, intent(in) :: n
            real(dp) :: ky(n), ky_up(n), k_down, k_up, g
            character(len=4) :: mode
            character(len=7) :: method
            namelist /newmark/ ky, mode, ky_up, k_down, k_up, method, g
            ky = cfg%blocks%ky
            ky_up = cfg%blocks%ky_up
            k_down = cfg%blocks(1)%k_down
            k_up = cfg%blocks(1)%k_up
            mode = newmark_mode_name(cfg%mode)
            method = newmark_method_name(cfg%method)
            g = cfg%g
            write(echo_unit(), nml=newmark)
        end subroutine echo_asym

        subroutine echo_mu(n)
            integer, intent(in) :: n
            real(dp) :: mu(n), slope_deg, xi_deg, g
            logical :: along_plane
            character(len=4) :: mode
            character(len=7) :: method
            namelist /newmark/ mu, slope_deg, xi_deg, along_plane, mode, method, g
            mu = cfg%mu
            slope_deg = cfg%slope_deg
            xi_deg = cfg%xi_deg
            along_plane = cfg%along_plane
            mode = newmark_mode_name(cfg%mode)
            method = newmark_method_name(cfg%method)
            g = cfg%g
            write(echo_unit(), nml=newmark)
        end subroutine echo_mu

        subroutine echo_table(n)
            integer, intent(in) :: n
            real(dp) :: ky_disp(n), ky_table(n), g
            character(len=9) :: method
            character(len=7) :: rule
            namelist /newmark/ ky_disp, ky_table, method, rule, g
            ky_disp = cfg%ky_disp
            ky_table = cfg%ky_values
            method = kind_names(cfg%kind)
            rule = newmark_method_name(cfg%method)
            g = cfg%g
            write(echo_unit(), nml=newmark)
        end subroutine echo_table

        subroutine echo_flexible(n)
            integer, intent(in) :: n
            real(dp) :: ky(n), g
            character(len=4) :: mode
            character(len=9) :: method
            character(len=7) :: rule
            namelist /newmark/ ky, mode, method, rule, g
            ky = cfg%blocks%ky
            mode = newmark_mode_name(cfg%mode)
            method = kind_names(cfg%kind)
            rule = newmark_method_name(cfg%method)
            g = cfg%g
            write(echo_unit(), nml=newmark)
        end subroutine echo_flexible

        subroutine echo_flexible_asym(n)
            integer, intent(in) :: n
            real(dp) :: ky(n), ky_up(n), g
            character(len=4) :: mode
            character(len=9) :: method
            character(len=7) :: rule
            namelist /newmark/ ky, mode, ky_up, method, rule, g
            ky = cfg%blocks%ky
            ky_up = cfg%blocks%ky_up
            mode = newmark_mode_name(cfg%mode)
            method = kind_names(cfg%kind)
            rule = newmark_method_name(cfg%method)
            g = cfg%g
            write(echo_unit(), nml=newmark)
        end subroutine echo_flexible_asym

    end subroutine echo_newmark

    ! ------------------------------------------------------------------------------
    ! Computation
    ! ------------------------------------------------------------------------------

    !> Every record (read, polarity, scale), every block, normal and inverse: one unit
    !> of a batch per record (driver_batch: threads, ranks, the restart journal). The
    !> tables are opened first; each record's header line and rows go into them as soon
    !> as every record before it is done (newmark_take), so memory does not grow with the
    !> number of records. A record that fails leaves NaN results and status failed in its
    !> rows; the message goes to stderr. An unconverged flexible case keeps its results
    !> (converged = 0) with a warning on stderr and a note in the header. Progress: one
    !> line per record on stderr, in record order. stat /= 0: the journal was refused or
    !> an output failed (errmsg); no table is left.
    subroutine compute(path, gr, prefix, cfg, itab, files_out, files_int, stat, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gr
        character(len=*), intent(in) :: prefix             !! output prefix (the journal)
        type(config_t), intent(inout) :: cfg               !! its records are lent to run_cfg
        type(intensity_table_t), intent(in) :: itab        !! on/off, Sa periods
        character(len=*), intent(out) :: files_out(2), files_int(2)  !! tables written
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(record_in_t), allocatable :: recs(:)

        ! --- the batch's read-only state (the records moved there, not copied: a long
        !     list is held once) and the tables
        call move_alloc(cfg%recs, recs)
        run_cfg = cfg
        call move_alloc(recs, run_cfg%recs)
        run_where = located(path, gr)
        run_itab_on = itab%on
        allocate(run_periods, source=itab%periods)
        out_failed = 0
        out_ifailed = 0
        out_named = 0
        out_names = ''
        call open_table(path, prefix, cfg, stat, errmsg)
        if (stat == 0) call intensity_open(out_itable, path, prefix, cfg%g, itab, stat, errmsg)
        if (stat == 0) then
            ! --- every record as one unit
            call batch_run(path, prefix, 'newmark', record_keys(run_cfg%recs, &
                           cfg%slammer_rounding), newmark_unit, newmark_take, stat, errmsg)
            if (stat == 0) then
                call table_close(out_table, stat, errmsg)
                if (stat == 0) call table_close(out_itable, stat, errmsg)
                if (stat /= 0) errmsg = output_located(path)//errmsg
            end if
        else
            errmsg = output_located(path)//errmsg
        end if
        if (stat /= 0) then
            ! the journal was refused (its message as it is), or an output failed
            call table_drop(out_table)
            call table_drop(out_itable)
            stat = 1
        end if
        files_out = out_table%files
        files_int = out_itable%files
        deallocate(run_periods)
        call move_alloc(run_cfg%recs, cfg%recs)
    end subroutine compute

    !> On the root, record ir's unit, in record order (driver_batch): its header line and
    !> its rows into the table, its intensity row; the failed rows are counted.
    subroutine newmark_take(ir, res)
        integer, intent(in) :: ir
        type(unit_result_t), intent(in) :: res
        type(record_out_t) :: o
        real(dp), allocatable :: rows(:, :)
        character(len=:), allocatable :: line, note
        integer :: nblk, ncol, nv, ib, nbad
        logical :: failed

        nblk = size(run_cfg%blocks)
        ncol = row_columns(run_cfg)
        call unpack_record(res, o)
        nv = RECORD_VALUES + nblk * ncol
        rows = reshape(res%values(RECORD_VALUES + 1:nv), [nblk, ncol])
        note = get_field(res, RECORD_FIELDS + 1)
        line = record_line(ir, run_cfg%recs(ir), o)
        if (o%ok .and. len(o%message) > 0) line = line//'; FAILED rows: '//o%message
        if (len(note) > 0) line = line//'; NOT CONVERGED: '//note
        call table_comment(out_table, line)
        do ib = 1, nblk
            call table_row(out_table, rows(ib, :), o%name)
        end do
        nbad = count(rows(:, ncol) > 0.5_dp)
        out_failed = out_failed + nbad
        if (nbad > 0) call add_failed_record(out_names, out_named, ir, o%name)
        if (run_itab_on) then
            call intensity_add(out_itable, ir, run_cfg%recs(ir), o, res%values(nv + 1:), &
                               get_field(res, RECORD_FIELDS + 2), failed)
            if (failed) out_ifailed = out_ifailed + 1
        end if
    end subroutine newmark_take

    !> The numeric columns of a row: pga, scale (, mu), ky, ky_up, the results, status.
    pure integer function row_columns(cfg) result(ncol)
        type(config_t), intent(in) :: cfg
        integer :: c0
        c0 = 2                       ! columns before ky: pga, scale (and mu)
        if (cfg%with_mu) c0 = 3
        ncol = c0 + 11               ! ... status
        if (cfg%kind /= KIND_RIGID) ncol = c0 + 17   ! ... kmax .. converged, status
    end function row_columns

    !> One unit: record ir read, its rows and its intensity row, packed into res (the
    !> record (pack_record), the rows (nblk x ncol, column-major), the intensity row;
    !> fields: the record's, the note, the intensity note); stderr lines into res%log.
    !> Runs concurrently: it reads run_cfg, run_where, run_itab_on, run_periods only.
    subroutine newmark_unit(ir, res)
        integer, intent(in) :: ir
        type(unit_result_t), intent(out) :: res
        type(record_out_t) :: o
        type(intensity_table_t) :: it1
        real(dp), allocatable :: rows(:, :)
        character(len=:), allocatable :: note
        integer :: nv, ni

        it1%on = run_itab_on
        allocate(it1%periods, source=run_periods)
        call intensity_start(it1, 1)
        call record_rows(ir, o, note, rows, it1, res)
        nv = RECORD_VALUES + size(rows)
        ni = 0
        if (it1%on) ni = size(it1%table, 2)
        allocate(res%values(nv + ni))
        call pack_record(o, res)
        res%values(RECORD_VALUES + 1:nv) = reshape(rows, [size(rows)])
        call add_field(res, note)
        if (it1%on) then
            res%values(nv + 1:nv + ni) = it1%table(1, :)
            call add_field(res, trim(it1%notes(1)))
        end if
    end subroutine newmark_unit

    !> Record ir (read, polarity, scale), its intensity row (it1, row 1) and its rows
    !> (nblk x ncol); stderr lines go to log%log. Texts are built in the critical section
    !> seispulse_text: gfortran 12 keeps the length of a deferred-length character function
    !> result (int_str, shortest_str, list_item, ...) in one static variable per call site,
    !> so two threads at one call site could swap lengths; the sliding analyses themselves
    !> run outside it, concurrently.
    subroutine record_rows(ir, o, note, rows, it1, log)
        integer, intent(in) :: ir
        type(record_out_t), intent(out) :: o
        character(len=:), allocatable, intent(out) :: note   !! '' or the unconverged rows
        real(dp), allocatable, intent(out) :: rows(:, :)
        type(intensity_table_t), intent(inout) :: it1
        type(unit_result_t), intent(inout) :: log
        type(newmark_result_t) :: rn, ri
        type(flexible_result_t) :: fn, fi
        real(dp), allocatable :: accel(:)
        character(len=:), allocatable :: errmsg, what
        character(len=4096) :: msg
        real(dp) :: nan, ky_up_col
        integer :: nrec, nblk, ib, st, st2, c0, ncol
        logical :: unconverged

        nan = ieee_value(nan, ieee_quiet_nan)
        nrec = size(run_cfg%recs)
        nblk = size(run_cfg%blocks)
        c0 = 2
        if (run_cfg%with_mu) c0 = 3
        ncol = row_columns(run_cfg)
        allocate(rows(nblk, ncol))
        rows = nan
        note = ''
        associate (cfg => run_cfg, where => run_where, r => run_cfg%recs(ir))
            ! --- read, turn over, scale
            call load_record(where, r, ir, nrec, 'newmark', cfg%slammer_rounding, o, accel, &
                             log)
            !$omp critical (seispulse_text)
            what = where//record_place(ir, r)
            !$omp end critical (seispulse_text)
            if (o%ok) call intensity_record(it1, 1, accel, o%dt, cfg%g, what, log)

            ! --- the rows of this record
            do ib = 1, nblk
                associate (b => cfg%blocks(ib))
                    ky_up_col = b%ky_up
                    if (b%mode == NEWMARK_DOWN) ky_up_col = ieee_value(nan, ieee_positive_inf)
                    if (b%mode == NEWMARK_BOTH) ky_up_col = b%ky
                    if (cfg%with_mu) rows(ib, 3) = cfg%mu(ib)
                    rows(ib, c0 + 1) = b%ky
                    rows(ib, c0 + 2) = ky_up_col
                    rows(ib, ncol) = 1.0_dp
                    if (.not. o%ok) cycle
                    rows(ib, 1) = o%pga
                    rows(ib, 2) = o%factor
                    msg = ''
                    st2 = SEISPULSE_SUCCESS
                    unconverged = .false.
                    if (cfg%kind == KIND_RIGID) then
                        call newmark_rigid(accel, o%dt, b, cfg%method, cfg%g, rn, st, msg)
                        if (st == SEISPULSE_SUCCESS) call newmark_rigid(-accel, o%dt, b, &
                            cfg%method, cfg%g, ri, st2, msg)
                    else
                        call flexible_row(cfg, b, accel, o%dt, fn, st, msg)
                        if (st == SEISPULSE_SUCCESS .or. st == SEISPULSE_NO_CONVERGENCE) &
                            call flexible_row(cfg, b, -accel, o%dt, fi, st2, msg)
                        ! not converged: the last iteration's results, with a warning
                        unconverged = st == SEISPULSE_NO_CONVERGENCE .or. &
                                      st2 == SEISPULSE_NO_CONVERGENCE
                        if (st == SEISPULSE_NO_CONVERGENCE) st = SEISPULSE_SUCCESS
                        if (st2 == SEISPULSE_NO_CONVERGENCE) st2 = SEISPULSE_SUCCESS
                    end if
                    if (st /= SEISPULSE_SUCCESS .or. st2 /= SEISPULSE_SUCCESS) then
                        ! a failure of the sliding analysis itself: this row only
                        !$omp critical (seispulse_text)
                        errmsg = what//', '//row_name(cfg, ib)//': '//trim(msg)
                        call report(errmsg, log)
                        if (len(o%message) > 0) o%message = o%message//'; '
                        o%message = o%message//row_name(cfg, ib)//': '//trim(msg)
                        !$omp end critical (seispulse_text)
                        cycle
                    end if
                    if (cfg%kind == KIND_RIGID) then
                        rows(ib, c0 + 3:c0 + 10) = [rn%max_disp, 100.0_dp * rn%max_disp, &
                            rn%final_disp, 100.0_dp * rn%final_disp, ri%max_disp, &
                            100.0_dp * ri%max_disp, ri%final_disp, 100.0_dp * ri%final_disp]
                    else
                        rows(ib, c0 + 3:c0 + 16) = [fn%max_disp, 100.0_dp * fn%max_disp, &
                            fn%final_disp, 100.0_dp * fn%final_disp, fi%max_disp, &
                            100.0_dp * fi%max_disp, fi%final_disp, &
                            100.0_dp * fi%final_disp, fn%kmax, fn%vs_final, &
                            fn%damping_final, fn%period, real(fn%iterations, dp), &
                            merge(1.0_dp, 0.0_dp, fn%converged .and. fi%converged)]
                        if (unconverged) then
                            !$omp critical (seispulse_text)
                            call add_log(log, 'warning: '//what//', '//row_name(cfg, ib)//': ' &
                                         //trim(msg))
                            if (len(note) > 0) note = note//'; '
                            note = note//row_name(cfg, ib)//': '//trim(msg)
                            !$omp end critical (seispulse_text)
                        end if
                    end if
                    rows(ib, ncol) = 0.0_dp
                end associate
            end do
        end associate
    end subroutine record_rows

    !> One flexible case (decoupled or coupled) on accel (g): the library's stat
    !> (SEISPULSE_NO_CONVERGENCE: res holds the last iteration) and message.
    subroutine flexible_row(cfg, b, accel, dt, res, stat, errmsg)
        type(config_t), intent(in) :: cfg
        type(newmark_block_t), intent(in) :: b           !! ky (g), mode, ky_up (g)
        real(dp), intent(in) :: accel(:)                 !! g
        real(dp), intent(in) :: dt                       !! s
        type(flexible_result_t), intent(out) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout) :: errmsg
        ! an unallocated ky_disp/ky_values (no table) is passed on as absent
        if (cfg%kind == KIND_DECOUPLED) then
            if (b%mode == NEWMARK_ASYM) then
                call flexible_decoupled(accel, dt, b%ky, cfg%mass, cfg%method, cfg%g, res, &
                                        stat, errmsg, mode=b%mode, ky_up=b%ky_up)
            else
                call flexible_decoupled(accel, dt, b%ky, cfg%mass, cfg%method, cfg%g, res, &
                                        stat, errmsg, mode=b%mode, ky_disp=cfg%ky_disp, &
                                        ky_values=cfg%ky_values)
            end if
        else
            call flexible_coupled(accel, dt, b%ky, cfg%mass, cfg%method, cfg%g, res, stat, &
                                  errmsg, ky_disp=cfg%ky_disp, ky_values=cfg%ky_values)
        end if
    end subroutine flexible_row

    !> "ky(2) = 0.1" or "mu(2) = 0.3" (without the index for a single value).
    function row_name(cfg, ib) result(s)
        type(config_t), intent(in) :: cfg
        integer, intent(in) :: ib
        character(len=:), allocatable :: s
        if (cfg%with_mu) then
            s = value_name('mu', ib, size(cfg%blocks))//' = '//shortest_str(cfg%mu(ib))
        else if (allocated(cfg%ky_disp)) then
            s = 'ky_table'
        else
            s = value_name('ky', ib, size(cfg%blocks))//' = '//shortest_str(cfg%blocks(ib)%ky)
        end if
    end function row_name

    ! ------------------------------------------------------------------------------
    ! Output
    ! ------------------------------------------------------------------------------

    !> Open the table <output>_newmark (out_table): its columns (the rigid block's, with
    !> mu, or with the flexible mass's six before status) and the header lines before
    !> the records' (newmark_take writes a line per record).
    subroutine open_table(path, prefix, cfg, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(config_t), intent(in) :: cfg
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=16), allocatable :: names(:), col_units(:)
        character(len=64), allocatable :: kinds(:)
        character(len=:), allocatable :: line
        !> the names of the column converged: 0 no, 1 yes
        character(len=3), parameter :: converged_names(0:1) = [character(len=3) :: 'no', 'yes']
        integer :: k, i, ncol
        logical :: flexible, with_table

        ! --- the columns
        ncol = row_columns(cfg)
        allocate(names(ncol + 1), col_units(ncol + 1))
        names(1:3) = [character(len=16) :: 'record', 'pga', 'scale']
        col_units(1:3) = [character(len=16) :: '-', 'g', '-']
        k = 4
        if (cfg%with_mu) then
            names(4) = 'mu'
            col_units(4) = '-'
            k = 5
        end if
        names(k) = 'ky'
        col_units(k) = 'g'
        names(k + 1:k + 10) = [character(len=16) :: 'ky_up', 'max_normal', 'max_normal_cm', &
            'final_normal', 'final_normal_cm', 'max_inverse', 'max_inverse_cm', &
            'final_inverse', 'final_inverse_cm', 'status']
        col_units(k + 1:k + 10) = [character(len=16) :: 'g', 'm', 'cm', 'm', 'cm', 'm', &
            'cm', 'm', 'cm', '-']
        if (cfg%kind /= KIND_RIGID) then
            names(k + 10:k + 16) = [character(len=16) :: 'kmax', 'vs_final', &
                'damping_final', 'period', 'iterations', 'converged', 'status']
            col_units(k + 10:k + 16) = [character(len=16) :: 'g', 'm/s', '-', 's', '-', &
                '-', '-']
        end if
        allocate(kinds(size(names)))
        kinds = ''
        kinds(size(names)) = category_kind(status_names)
        if (cfg%kind /= KIND_RIGID) then
            kinds(k + 14) = 'int'                            ! iterations
            kinds(k + 15) = category_kind(converged_names)  ! converged
        end if
        call table_open(out_table, prefix, 'newmark', names, col_units, stat, errmsg, &
                        kinds=kinds, labelled=.true.)
        if (stat /= 0) return

        ! --- the header lines
        flexible = cfg%kind /= KIND_RIGID
        with_table = allocated(cfg%ky_disp)
        if (flexible) then
            call add('seispulse analysis newmark: '//trim(kind_names(cfg%kind)) &
                     //' flexible sliding mass on accelerograms (doc/flexible.md), one ' &
                     //'row per record and ky')
        else if (with_table) then
            call add('seispulse analysis newmark: rigid-block (Newmark) sliding on ' &
                     //'accelerograms with a yield table, one row per record')
        else
            call add('seispulse analysis newmark: rigid-block (Newmark) sliding on ' &
                     //'accelerograms, one row per record and '//merge('mu', 'ky', cfg%with_mu))
        end if
        call add('input: '//trim(path))
        if (flexible .or. with_table) then
            call add('method = '//trim(kind_names(cfg%kind))//', rule = ' &
                     //newmark_method_name(cfg%method)//', mode = ' &
                     //newmark_mode_name(cfg%mode)//', g = '//shortest_str(cfg%g)//' m/s2')
        else
            line = 'mode = '//newmark_mode_name(cfg%mode)//', method = ' &
                   //newmark_method_name(cfg%method)//', g = '//shortest_str(cfg%g)//' m/s2'
            if (cfg%with_mu) line = line//'; incline: slope_deg = ' &
                //shortest_str(cfg%slope_deg)//', xi_deg = '//shortest_str(cfg%xi_deg) &
                //', along_plane = '//trim(merge('true ', 'false', cfg%along_plane)) &
                //' (ky, ky_up from Eq. 1.31)'
            call add(line)
        end if
        if (flexible) call add(slope_line(cfg%mass))
        if (with_table) then
            line = 'yield table (ky_disp m: ky_table g):'
            do i = 1, size(cfg%ky_disp)
                line = line//' '//shortest_str(cfg%ky_disp(i))//': ' &
                    //shortest_str(cfg%ky_values(i))
                if (i < size(cfg%ky_disp)) line = line//','
            end do
            call add(line//'; the column ky is ky_table(1)')
        end if
        call add('sign convention: positive slip = downslope, driven by positive ' &
                 //'ground acceleration; normal = the record times scale (scale < 0: ' &
                 //'polarity -1), inverse = the normal record x -1')
        if (flexible .or. with_table) then
            call add('max: largest |u| over time; final: u when the mass is at rest at ' &
                     //'the end (signed); ky_up = inf: no upslope sliding (mode ''down''); ' &
                     //'pga: after scaling')
        else
            call add('max: largest |u| over time; final: u when the block is at rest at ' &
                     //'the end (signed); ky_up = inf: no upslope sliding (mode ''down''); ' &
                     //'pga: after scaling')
        end if
        if (flexible) then
            call add('kmax: the peak of the average acceleration of the mass (HEA, g), ' &
                     //'signed, of the normal record (the inverse''s is -kmax); ' &
                     //'vs_final (m/s), damping_final (user or material, plus ' &
                     //'radiation) and period = 4 height / vs_final (s) of the final ' &
                     //'response, iterations (equivalent-linear; 0 for linear): the ' &
                     //'same for normal and inverse')
            call add('converged: yes, or no when the equivalent-linear iteration stopped ' &
                     //'at max_iter: the results of its last iteration, a warning below ' &
                     //'and on stderr, status ok')
        end if
        call add('status: ok, or failed (nan results; the reason is below and on ' &
                 //'stderr); exit status 1 when a row failed (2: an input error, no table)')
        call add('records (index, file, format read, npts, dt (s), PGA as read (g), ' &
                 //'scale factor):')

    contains

        subroutine add(text)
            character(len=*), intent(in) :: text
            call table_comment(out_table, text)
        end subroutine add

    end subroutine open_table

end module driver_newmark
