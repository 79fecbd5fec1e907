!> Analysis 'newmark': rigid-block (Newmark) sliding on accelerogram files, one row per
!> record and yield acceleration, for the record as read ("normal") and turned over
!> ("inverse", the record times -1).
!>
!> Groups: &records (the files and how to read and scale each one) and &newmark (the
!> yield accelerations ky, or friction values mu on one incline, the mode and the
!> integration rule). Table <output>_newmark. Everything is checked before any record
!> is read. A record that cannot be read or scaled fails its rows (NaN results, status
!> 1; the message goes to stderr and into the table's header) and the other records
!> are still computed; run_newmark then returns NEWMARK_ROWS_FAILED and the driver
!> exits with status 1 after writing the table. The numbers come from seispulse_records
!> (reading, PGA scaling) and seispulse_newmark (the sliding block); the driver only
!> reads, checks, converts units and writes.
module driver_newmark
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
                                             ieee_quiet_nan, ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, real_str, int_str
    use seispulse_records, only: record_t, read_record, record_pga, pga_scale_factor, &
                                 record_format_name, record_units_name, RECORD_AUTO, RECORD_COLUMN, &
                                 RECORD_TIME_ACCEL, UNITS_G, UNITS_M_S2, UNITS_CM_S2
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid, &
                                 newmark_incline, newmark_block_validate, newmark_mode_code, &
                                 newmark_method_code, newmark_mode_name, &
                                 newmark_method_name, NEWMARK_DOWN, NEWMARK_BOTH, NEWMARK_ASYM
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: find_group, located, join, read_optional, given, &
                            list_length, list_item
    use driver_tables, only: write_tables
    implicit none
    private

    public :: run_newmark, newmark_groups, NEWMARK_ROWS_FAILED

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: newmark_groups(2) = [character(len=8) :: 'records', &
        'newmark']

    !> stat of run_newmark when the table is written but some rows failed (exit 1).
    integer, parameter :: NEWMARK_ROWS_FAILED = -1

    character(len=12), parameter :: records_keys(8) = [character(len=12) :: 'files', &
        'format', 'units', 'dt', 'scale', 'target_pga', 'pga_rounding', 'polarity']
    character(len=12), parameter :: newmark_keys(11) = [character(len=12) :: 'ky', 'mode', &
        'ky_up', 'k_down', 'k_up', 'mu', 'slope_deg', 'xi_deg', 'along_plane', 'method', 'g']
    character(len=10), parameter :: format_names(5) = [character(len=10) :: 'auto', 'at2', &
        'slammer', 'column', 'time_accel']
    character(len=6), parameter :: units_names(7) = [character(len=6) :: 'auto', 'g', &
        'm/s2', 'cm/s2', 'm/s^2', 'cm/s^2', 'gal']
    character(len=7), parameter :: rounding_names(2) = [character(len=7) :: 'exact', 'slammer']
    character(len=4), parameter :: mode_names(3) = [character(len=4) :: 'down', 'both', 'asym']
    character(len=7), parameter :: method_names(2) = [character(len=7) :: 'exact', 'slammer']

    !> Most record files, most ky (or mu) values.
    integer, parameter :: max_files = 500, max_ky = 1000
    !> Length of a file name in &records.
    integer, parameter :: path_len = 1024
    !> Unset entries of the integer list polarity.
    integer, parameter :: unset_int = -huge(0)
    !> Most failed records named in the final message.
    integer, parameter :: max_named = 20

    ! namelist variables (defaults are set in set_defaults)
    character(len=path_len) :: files(max_files)
    character(len=32) :: format(max_files), units(max_files)
    real(dp) :: dt(max_files), scale(max_files), target_pga(max_files)
    character(len=32) :: pga_rounding
    integer :: polarity(max_files)
    namelist /records/ files, format, units, dt, scale, target_pga, pga_rounding, polarity

    real(dp) :: ky(max_ky), ky_up(max_ky), k_down, k_up, mu(max_ky), slope_deg, xi_deg, g
    character(len=32) :: mode, method
    logical :: along_plane
    namelist /newmark/ ky, mode, ky_up, k_down, k_up, mu, slope_deg, xi_deg, along_plane, &
        method, g

    !> One record file and how to read and scale it.
    type :: record_in_t
        character(len=:), allocatable :: file   !! as written in &records
        character(len=:), allocatable :: path   !! the path opened (relative to the input)
        integer :: fmt = RECORD_AUTO            !! RECORD_*
        integer :: units = 0                    !! UNITS_*, 0: auto (AT2 header, else g)
        real(dp) :: dt = 0.0_dp                 !! s, 0: from the file
        real(dp) :: scale = 1.0_dp              !! factor (without the polarity)
        real(dp) :: target = 0.0_dp             !! target PGA (g), 0: use scale
        integer :: polarity = 1                 !! +1 or -1
    end type record_in_t

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
        integer :: method = 0
        real(dp) :: g = 9.80665_dp
    end type config_t

    !> What happened to one record.
    type :: record_out_t
        logical :: ok = .false.
        character(len=:), allocatable :: name      !! file stem (the table's label)
        character(len=:), allocatable :: message   !! why it failed ('' if it did not)
        integer :: fmt = RECORD_AUTO               !! format read
        integer :: npts = 0
        real(dp) :: dt = 0.0_dp
        real(dp) :: pga_read = 0.0_dp              !! PGA as read (g)
        real(dp) :: factor = 0.0_dp                !! scale factor applied, signed
        real(dp) :: pga = 0.0_dp                   !! PGA after scaling (g)
    end type record_out_t

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        files = ''
        format = ''
        units = ''
        dt = nan
        scale = nan
        target_pga = nan
        pga_rounding = 'exact'
        polarity = unset_int
        ky = nan
        mode = ''
        ky_up = nan
        k_down = 1.0_dp
        k_up = 1.0_dp
        mu = nan
        slope_deg = 0.0_dp
        xi_deg = 0.0_dp
        along_plane = .true.
        method = 'exact'
        g = 9.80665_dp
    end subroutine set_defaults

    subroutine read_records(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=records, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=records, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_records

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
    !> went. stat: 0, NEWMARK_ROWS_FAILED (table written, errmsg says how many rows
    !> failed), or > 0 for an input or output error (nothing written).
    subroutine run_newmark(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(nml_group) :: gr, gn
        type(config_t) :: cfg
        type(record_out_t), allocatable :: outs(:)
        real(dp), allocatable :: table(:, :)
        character(len=512) :: files_out(2)
        integer :: nfailed, nrows

        call set_defaults()
        call read_optional(path, groups, 'records', records_keys, read_records, gr, stat, &
                           errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'newmark', newmark_keys, read_newmark, gn, stat, &
                           errmsg)
        if (stat /= 0) return
        stat = 1
        if (find_group(groups, 'records') == 0) then
            errmsg = path//': &records: missing group (it lists the record files: files = ' &
                     //'''a.AT2'', ...)'
            return
        end if
        if (find_group(groups, 'newmark') == 0) then
            errmsg = path//': &newmark: missing group (it gives the yield accelerations ky ' &
                     //'or the friction mu of an incline)'
            return
        end if
        call check_records(path, gr, cfg, errmsg)
        if (len(errmsg) > 0) return
        call check_newmark(path, gn, cfg, errmsg)
        if (len(errmsg) > 0) return

        ! --- echo the effective input
        call echo_records(cfg)
        call echo_newmark(cfg)

        ! --- compute every row (nothing is written before all of them are done)
        call compute(path, gr, cfg, outs, table, nfailed)

        ! --- write
        call write_result(path, prefix, cfg, outs, table, files_out, stat, errmsg)
        if (stat /= 0) then
            stat = 1
            errmsg = path//': &run: output: '//errmsg
            return
        end if
        write(output_unit, '(a)') 'newmark table written to '//trim(files_out(1))//' and ' &
            //trim(files_out(2))
        stat = 0
        if (nfailed > 0) then
            nrows = size(table, 1)
            stat = NEWMARK_ROWS_FAILED
            errmsg = int_str(nfailed)//' of '//int_str(nrows)//' rows failed (records: ' &
                     //failed_list(outs, table, size(cfg%blocks))//')'
        end if
    end subroutine run_newmark

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> Check &records and fill cfg%recs. errmsg is empty on success.
    subroutine check_records(path, gr, cfg, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gr
        type(config_t), intent(inout) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, item
        integer :: n, i, k, n_fmt, n_units, n_dt, n_scale, n_target, n_pol, code
        real(dp) :: x

        where = located(path, gr)
        errmsg = ''
        if (.not. given(gr, 'files')) then
            errmsg = where//'files: missing (the record files: files = ''a.AT2'', ''b.csv'')'
            return
        end if
        call count_strings(files, 'files', n, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        allocate(cfg%recs(n))
        do i = 1, n
            cfg%recs(i)%file = trim(adjustl(files(i)))
            cfg%recs(i)%path = resolve(path, cfg%recs(i)%file)
        end do

        ! --- how many values each per-file key has: 1 (all files) or n (one each)
        call per_file_strings(format, 'format', n_fmt)
        if (len(errmsg) > 0) return
        call per_file_strings(units, 'units', n_units)
        if (len(errmsg) > 0) return
        call per_file_reals(dt, 'dt', n_dt)
        if (len(errmsg) > 0) return
        call per_file_reals(scale, 'scale', n_scale)
        if (len(errmsg) > 0) return
        call per_file_reals(target_pga, 'target_pga', n_target)
        if (len(errmsg) > 0) return
        n_pol = 0
        do i = size(polarity), 1, -1
            if (polarity(i) /= unset_int) then
                n_pol = i
                exit
            end if
        end do
        do i = 1, n_pol
            if (polarity(i) == unset_int) then
                errmsg = where//list_item('polarity', i)//': missing (give every value, ' &
                         //'without gaps)'
                return
            end if
        end do
        call check_count('polarity', n_pol)
        if (len(errmsg) > 0) return

        ! --- the values
        do i = 1, n
            associate (r => cfg%recs(i))
                if (n_fmt > 0) then
                    k = min(i, n_fmt)
                    item = value_name('format', k, n_fmt)
                    code = name_index(format(k), format_names)
                    if (code == 0) then
                        errmsg = where//item//' = '''//trim(format(k))//''': unknown format ' &
                                 //'(allowed: '//join(format_names)//')'
                        return
                    end if
                    ! format_names are in the order of the RECORD_* codes
                    r%fmt = RECORD_AUTO + code - 1
                    if (record_format_name(r%fmt) /= trim(format_names(code))) then
                        errmsg = where//item//': internal error: format codes changed'
                        return
                    end if
                end if
                if (n_units > 0) then
                    k = min(i, n_units)
                    item = value_name('units', k, n_units)
                    select case (name_index(units(k), units_names))
                    case (1)
                        r%units = 0
                    case (2)
                        r%units = UNITS_G
                    case (3, 5)
                        r%units = UNITS_M_S2
                    case (4, 6, 7)
                        r%units = UNITS_CM_S2
                    case default
                        errmsg = where//item//' = '''//trim(units(k))//''': unknown units ' &
                                 //'(allowed: '//join(units_names)//')'
                        return
                    end select
                end if
                if (n_dt > 0) then
                    k = min(i, n_dt)
                    x = dt(k)
                    if (.not. (ieee_is_finite(x) .and. x >= 0.0_dp)) then
                        errmsg = where//value_name('dt', k, n_dt)//' = '//num(x) &
                                 //': must be a finite time step >= 0 (s; 0: from the file)'
                        return
                    end if
                    r%dt = x
                end if
                if (r%fmt == RECORD_COLUMN .and. .not. r%dt > 0.0_dp) then
                    errmsg = where//'dt: '//list_item('files', i)//' = '''//r%file &
                             //''' has format ''column'', which has no time step: give ' &
                             //'dt > 0 (s) for it'
                    return
                end if
                if (n_scale > 0) then
                    k = min(i, n_scale)
                    x = scale(k)
                    if (.not. (ieee_is_finite(x) .and. x > 0.0_dp)) then
                        errmsg = where//value_name('scale', k, n_scale)//' = '//num(x) &
                                 //': must be a finite factor > 0 (polarity = -1 turns the ' &
                                 //'record over)'
                        return
                    end if
                    r%scale = x
                end if
                if (n_target > 0) then
                    k = min(i, n_target)
                    x = target_pga(k)
                    if (.not. (ieee_is_finite(x) .and. x >= 0.0_dp)) then
                        errmsg = where//value_name('target_pga', k, n_target)//' = ' &
                                 //num(x)//': must be a finite PGA > 0 (g; 0: use scale)'
                        return
                    end if
                    r%target = x
                end if
                if (r%target > 0.0_dp .and. abs(r%scale - 1.0_dp) > 0.0_dp) then
                    errmsg = where//'scale, target_pga: '//list_item('files', i)//' = ''' &
                             //r%file//''' has both (target_pga > 0 scales the record to ' &
                             //'that PGA; give scale = 1 or leave it out for that file)'
                    return
                end if
                if (n_pol > 0) then
                    k = min(i, n_pol)
                    if (abs(polarity(k)) /= 1) then
                        errmsg = where//value_name('polarity', k, n_pol)//' = ' &
                                 //int_str(polarity(k))//': must be 1 or -1 (-1 turns the ' &
                                 //'record over before anything else)'
                        return
                    end if
                    r%polarity = polarity(k)
                end if
            end associate
        end do

        select case (name_index(pga_rounding, rounding_names))
        case (1)
            cfg%slammer_rounding = .false.
        case (2)
            cfg%slammer_rounding = .true.
        case default
            errmsg = where//'pga_rounding = '''//trim(pga_rounding)//''': unknown rounding ' &
                     //'(allowed: '//join(rounding_names)//')'
            return
        end select
        if (given(gr, 'pga_rounding') .and. .not. any(cfg%recs%target > 0.0_dp)) &
            write(error_unit, '(a)') 'warning: '//where//'pga_rounding: not used without ' &
            //'target_pga'

    contains

        !> Number of values of a per-file text key (0: not given).
        subroutine per_file_strings(list, name, m)
            character(len=*), intent(in) :: list(:)
            character(len=*), intent(in) :: name
            integer, intent(out) :: m
            m = 0
            if (.not. given(gr, name)) return
            call count_strings(list, name, m, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
            call check_count(name, m)
        end subroutine per_file_strings

        !> Number of values of a per-file real key (0: not given).
        subroutine per_file_reals(list, name, m)
            real(dp), intent(in) :: list(:)
            character(len=*), intent(in) :: name
            integer, intent(out) :: m
            m = 0
            if (.not. given(gr, name)) return
            call list_length(list, name, m, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
            call check_count(name, m)
        end subroutine per_file_reals

        subroutine check_count(name, m)
            character(len=*), intent(in) :: name
            integer, intent(in) :: m
            if (m > 1 .and. m /= n) errmsg = where//name//': '//int_str(m)//' values for ' &
                //int_str(n)//' files (give one value for all files, or one per file)'
        end subroutine check_count

    end subroutine check_records

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
        integer :: n, i, k, n_up, st
        real(dp) :: nan

        nan = ieee_value(nan, ieee_quiet_nan)
        where = located(path, gn)
        errmsg = ''

        ! --- method and g
        cfg%method = newmark_method_code(trim(lower(adjustl(method))))
        if (cfg%method == 0) then
            errmsg = where//'method = '''//trim(method)//''': unknown method (allowed: ' &
                     //join(method_names)//')'
            return
        end if
        if (.not. (ieee_is_finite(g) .and. g > 0.0_dp)) then
            errmsg = where//'g = '//num(g)//': must be a finite number > 0 (m/s2)'
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
                    errmsg = where//value_name('mu', i, n)//' = '//num(mu(i))//': '//trim(msg)
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
                errmsg = where//item//' = '//num(ky(i))//': must be > 0 (g; inf: no ' &
                         //'sliding)'
                return
            end if
            cfg%blocks(i)%mode = cfg%mode
            cfg%blocks(i)%ky = ky(i)
            cfg%blocks(i)%ky_up = ky(i)
            if (cfg%mode == NEWMARK_ASYM) then
                k = min(i, n_up)
                if (.not. positive(ky_up(k))) then
                    errmsg = where//value_name('ky_up', k, n_up)//' = '//num(ky_up(k)) &
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

    ! ------------------------------------------------------------------------------
    ! Echo
    ! ------------------------------------------------------------------------------

    !> &records with one value per file (a namelist that reads back to the same input).
    subroutine echo_records(cfg)
        type(config_t), intent(in) :: cfg
        integer :: i, flen
        flen = 1
        do i = 1, size(cfg%recs)
            flen = max(flen, len(cfg%recs(i)%file))
        end do
        call echo_records_n(cfg, size(cfg%recs), flen)
    end subroutine echo_records

    subroutine echo_records_n(cfg, n, flen)
        type(config_t), intent(in) :: cfg
        integer, intent(in) :: n, flen
        character(len=flen) :: files(n)
        character(len=10) :: format(n)
        character(len=6) :: units(n)
        real(dp) :: dt(n), scale(n), target_pga(n)
        character(len=7) :: pga_rounding
        integer :: polarity(n), i
        namelist /records/ files, format, units, dt, scale, target_pga, pga_rounding, polarity
        do i = 1, n
            files(i) = cfg%recs(i)%file
            format(i) = record_format_name(cfg%recs(i)%fmt)
            units(i) = units_name(cfg%recs(i)%units)
            dt(i) = cfg%recs(i)%dt
            scale(i) = cfg%recs(i)%scale
            target_pga(i) = cfg%recs(i)%target
            polarity(i) = cfg%recs(i)%polarity
        end do
        pga_rounding = merge('slammer', 'exact  ', cfg%slammer_rounding)
        write(output_unit, nml=records)
    end subroutine echo_records_n

    !> &newmark with the keys in use.
    subroutine echo_newmark(cfg)
        type(config_t), intent(in) :: cfg
        if (cfg%with_mu) then
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
            write(output_unit, nml=newmark)
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
            write(output_unit, nml=newmark)
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
            write(output_unit, nml=newmark)
        end subroutine echo_mu

    end subroutine echo_newmark

    ! ------------------------------------------------------------------------------
    ! Computation
    ! ------------------------------------------------------------------------------

    !> Every record (read, polarity, scale), every block, normal and inverse. A record
    !> that fails leaves NaN results and status 1 in its rows; the message goes to
    !> stderr at once. Progress: one line per record on stderr.
    subroutine compute(path, gr, cfg, outs, table, nfailed)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gr
        type(config_t), intent(in) :: cfg
        type(record_out_t), allocatable, intent(out) :: outs(:)
        real(dp), allocatable, intent(out) :: table(:, :)   !! the numeric columns
        integer, intent(out) :: nfailed
        type(record_t) :: rec
        type(newmark_result_t) :: rn, ri
        real(dp), allocatable :: accel(:)
        character(len=:), allocatable :: where, errmsg
        character(len=4096) :: msg
        real(dp) :: nan, factor, ky_up_col
        integer :: nrec, nblk, ir, ib, row, st, st2, c0, i

        nan = ieee_value(nan, ieee_quiet_nan)
        where = located(path, gr)
        nrec = size(cfg%recs)
        nblk = size(cfg%blocks)
        c0 = 2                       ! columns before ky: pga, scale (and mu)
        if (cfg%with_mu) c0 = 3
        allocate(outs(nrec))
        allocate(table(nrec * nblk, c0 + 11))
        table = nan
        nfailed = 0
        do ir = 1, nrec
            associate (r => cfg%recs(ir), o => outs(ir))
                ! --- read, turn over, scale
                msg = ''
                if (r%units > 0) then
                    call read_record(r%path, rec, st, msg, fmt=r%fmt, units=r%units, dt=r%dt)
                else
                    call read_record(r%path, rec, st, msg, fmt=r%fmt, dt=r%dt)
                end if
                o%name = record_label(rec, r%path, ir)
                o%message = ''
                if (st == SEISPULSE_SUCCESS) then
                    o%fmt = rec%fmt
                    o%npts = rec%npts
                    o%dt = rec%dt
                    o%pga_read = rec%pga
                    factor = r%scale
                    if (r%target > 0.0_dp) then
                        call pga_scale_factor(rec%pga, r%target, cfg%slammer_rounding, factor, &
                                              st, msg)
                        if (st /= SEISPULSE_SUCCESS) msg = r%path//': cannot scale to ' &
                            //'target_pga = '//num(r%target)//' g: '//trim(msg)
                    end if
                end if
                if (st == SEISPULSE_SUCCESS) then
                    o%factor = real(r%polarity, dp) * factor
                    accel = rec%accel * o%factor
                    if (.not. all(ieee_is_finite(accel))) then
                        st = 1
                        msg = r%path//': scale = '//num(factor)//': the scaled record ' &
                              //'overflows'
                    end if
                end if
                if (st == SEISPULSE_SUCCESS) then
                    o%ok = .true.
                    o%pga = record_pga(accel)
                    call progress(ir, nrec, o%name//' (npts '//int_str(o%npts)//', dt ' &
                                  //num(o%dt)//' s, PGA '//short(o%pga_read)//' g' &
                                  //scaled_text(o)//')')
                else
                    o%ok = .false.
                    o%message = trim(msg)
                    call progress(ir, nrec, o%name//' (failed)')
                    call report(where//list_item('files', ir)//' = '''//r%file//''': ' &
                                //o%message)
                end if

                ! --- the rows of this record
                do ib = 1, nblk
                    row = (ir - 1) * nblk + ib
                    associate (b => cfg%blocks(ib))
                        ky_up_col = b%ky_up
                        if (b%mode == NEWMARK_DOWN) ky_up_col = ieee_value(nan, &
                                                                           ieee_positive_inf)
                        if (b%mode == NEWMARK_BOTH) ky_up_col = b%ky
                        if (cfg%with_mu) table(row, 3) = cfg%mu(ib)
                        table(row, c0 + 1) = b%ky
                        table(row, c0 + 2) = ky_up_col
                        table(row, c0 + 11) = 1.0_dp
                        if (.not. o%ok) cycle
                        table(row, 1) = o%pga
                        table(row, 2) = o%factor
                        msg = ''
                        st2 = SEISPULSE_SUCCESS
                        call newmark_rigid(accel, o%dt, b, cfg%method, cfg%g, rn, st, msg)
                        if (st == SEISPULSE_SUCCESS) &
                            call newmark_rigid(-accel, o%dt, b, cfg%method, cfg%g, ri, st2, msg)
                        if (st /= SEISPULSE_SUCCESS .or. st2 /= SEISPULSE_SUCCESS) then
                            ! a failure of the sliding analysis itself: this row only
                            errmsg = where//list_item('files', ir)//' = '''//r%file//''', ' &
                                     //row_name(cfg, ib)//': '//trim(msg)
                            call report(errmsg)
                            if (len(o%message) > 0) o%message = o%message//'; '
                            o%message = o%message//row_name(cfg, ib)//': '//trim(msg)
                            cycle
                        end if
                        table(row, c0 + 3:c0 + 10) = [rn%max_disp, 100.0_dp * rn%max_disp, &
                            rn%final_disp, 100.0_dp * rn%final_disp, ri%max_disp, &
                            100.0_dp * ri%max_disp, ri%final_disp, 100.0_dp * ri%final_disp]
                        table(row, c0 + 11) = 0.0_dp
                    end associate
                end do
            end associate
        end do
        nfailed = 0
        do i = 1, size(table, 1)
            if (table(i, c0 + 11) > 0.5_dp) nfailed = nfailed + 1
        end do
    end subroutine compute

    !> " -> 0.4 g" (or with the polarity) when the record is scaled or turned over.
    function scaled_text(o) result(s)
        type(record_out_t), intent(in) :: o
        character(len=:), allocatable :: s
        s = ''
        if (abs(abs(o%factor) - 1.0_dp) > 0.0_dp) s = ' -> '//short(o%pga)//' g'
        if (o%factor < 0.0_dp) s = s//', turned over (polarity -1)'
    end function scaled_text

    !> "ky(2) = 0.1" or "mu(2) = 0.3" (without the index for a single value).
    function row_name(cfg, ib) result(s)
        type(config_t), intent(in) :: cfg
        integer, intent(in) :: ib
        character(len=:), allocatable :: s
        if (cfg%with_mu) then
            s = value_name('mu', ib, size(cfg%blocks))//' = '//num(cfg%mu(ib))
        else
            s = value_name('ky', ib, size(cfg%blocks))//' = '//num(cfg%blocks(ib)%ky)
        end if
    end function row_name

    !> The table's label of a record: the file stem (the file name if it has none).
    function record_label(rec, path, i) result(s)
        type(record_t), intent(in) :: rec
        character(len=*), intent(in) :: path
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        integer :: k
        s = ''
        if (allocated(rec%name)) s = trim(rec%name)
        if (len(s) == 0) then
            k = index(path, '/', back=.true.)
            s = trim(path(k + 1:))
        end if
        if (len(s) == 0) s = 'record_'//int_str(i)
    end function record_label

    subroutine progress(i, n, text)
        integer, intent(in) :: i, n
        character(len=*), intent(in) :: text
        write(error_unit, '(a)') 'newmark: record '//int_str(i)//'/'//int_str(n)//': '//text
        flush(error_unit)
    end subroutine progress

    !> An error of one record or row: reported at once, the run goes on.
    subroutine report(text)
        character(len=*), intent(in) :: text
        write(error_unit, '(a)') 'seispulse: error: '//text
        flush(error_unit)
    end subroutine report

    !> "2 'name', 5 'other'" of the records with a failed row (at most max_named).
    function failed_list(outs, table, nblk) result(s)
        type(record_out_t), intent(in) :: outs(:)
        real(dp), intent(in) :: table(:, :)
        integer, intent(in) :: nblk
        character(len=:), allocatable :: s
        integer :: ir, named, ncol
        ncol = size(table, 2)
        s = ''
        named = 0
        do ir = 1, size(outs)
            if (.not. any(table((ir - 1) * nblk + 1:ir * nblk, ncol) > 0.5_dp)) cycle
            named = named + 1
            if (named > max_named) then
                s = s//', ...'
                exit
            end if
            if (named > 1) s = s//', '
            s = s//int_str(ir)//' '''//outs(ir)%name//''''
        end do
    end function failed_list

    ! ------------------------------------------------------------------------------
    ! Output
    ! ------------------------------------------------------------------------------

    subroutine write_result(path, prefix, cfg, outs, table, files_out, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(config_t), intent(in) :: cfg
        type(record_out_t), intent(in) :: outs(:)
        real(dp), intent(in) :: table(:, :)
        character(len=*), intent(out) :: files_out(2)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=4096), allocatable :: comments(:)
        character(len=16), allocatable :: names(:), col_units(:)
        character(len=path_len), allocatable :: labels(:)
        character(len=:), allocatable :: line
        integer :: nblk, ir, k

        nblk = size(cfg%blocks)
        allocate(comments(7 + size(outs)))
        comments(1) = 'seispulse analysis newmark: rigid-block (Newmark) sliding on ' &
                      //'accelerograms, one row per record and '//merge('mu', 'ky', cfg%with_mu)
        comments(2) = 'input: '//trim(path)
        line = 'mode = '//newmark_mode_name(cfg%mode)//', method = ' &
               //newmark_method_name(cfg%method)//', g = '//num(cfg%g)//' m/s2'
        if (cfg%with_mu) line = line//'; incline: slope_deg = '//num(cfg%slope_deg) &
            //', xi_deg = '//num(cfg%xi_deg)//', along_plane = ' &
            //trim(merge('true ', 'false', cfg%along_plane))//' (ky, ky_up from Eq. 1.31)'
        comments(3) = line
        comments(4) = 'sign convention: positive slip = downslope, driven by positive ' &
                      //'ground acceleration; normal = the record times scale (scale < 0: ' &
                      //'polarity -1), inverse = the normal record x -1'
        comments(5) = 'max: largest |u| over time; final: u when the block is at rest at ' &
                      //'the end (signed); ky_up = inf: no upslope sliding (mode ''down''); ' &
                      //'pga: after scaling'
        comments(6) = 'status: 0 ok, 1 failed (NaN results; the reason is below and on ' &
                      //'stderr); exit status 1 when a row failed (2: an input error, no table)'
        comments(7) = 'records (index, file, format read, npts, dt (s), PGA as read (g), ' &
                      //'scale factor):'
        do ir = 1, size(outs)
            associate (o => outs(ir), r => cfg%recs(ir))
                line = 'record '//int_str(ir)//': '//r%file//': '
                if (o%ok) then
                    line = line//'format '//record_format_name(o%fmt)//', npts ' &
                           //int_str(o%npts)//', dt '//num(o%dt)//', PGA ' &
                           //num(o%pga_read)//', scale factor '//num(o%factor)
                    if (len(o%message) > 0) line = line//'; FAILED rows: '//o%message
                else
                    line = line//'FAILED: '//o%message
                end if
                comments(7 + ir) = line
            end associate
        end do

        allocate(names(size(table, 2) + 1), col_units(size(table, 2) + 1))
        if (cfg%with_mu) then
            names(1:5) = [character(len=16) :: 'record', 'pga', 'scale', 'mu', 'ky']
            col_units(1:5) = [character(len=16) :: '-', 'g', '-', '-', 'g']
            k = 5
        else
            names(1:4) = [character(len=16) :: 'record', 'pga', 'scale', 'ky']
            col_units(1:4) = [character(len=16) :: '-', 'g', '-', 'g']
            k = 4
        end if
        names(k + 1:) = [character(len=16) :: 'ky_up', 'max_normal', 'max_normal', &
            'final_normal', 'final_normal', 'max_inverse', 'max_inverse', 'final_inverse', &
            'final_inverse', 'status']
        col_units(k + 1:) = [character(len=16) :: 'g', 'm', 'cm', 'm', 'cm', 'm', 'cm', 'm', &
            'cm', '-']
        allocate(labels(size(table, 1)))
        do ir = 1, size(outs)
            labels((ir - 1) * nblk + 1:ir * nblk) = outs(ir)%name
        end do
        call write_tables(prefix, 'newmark', comments, names, col_units, table, files_out, &
                          stat, errmsg, labels=labels)
    end subroutine write_result

    ! ------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------

    !> A record file relative to the directory of the input file (absolute: as is).
    function resolve(nml_path, file) result(p)
        character(len=*), intent(in) :: nml_path, file
        character(len=:), allocatable :: p
        integer :: k
        k = index(nml_path, '/', back=.true.)
        p = file
        if (k == 0) return
        if (file(1:1) == '/') return
        p = nml_path(1:k)//file
    end function resolve

    !> Number of values in a text list (the last one not blank); a blank before it is an
    !> error.
    subroutine count_strings(list, name, n, errmsg)
        character(len=*), intent(in) :: list(:)
        character(len=*), intent(in) :: name
        integer, intent(out) :: n
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: i
        errmsg = ''
        n = 0
        do i = size(list), 1, -1
            if (len_trim(list(i)) > 0) then
                n = i
                exit
            end if
        end do
        if (n == 0) then
            errmsg = name//': empty (no value given)'
            return
        end if
        do i = 1, n
            if (len_trim(list(i)) == 0) then
                errmsg = list_item(name, i)//': missing or empty (give every value, ' &
                         //'without gaps)'
                return
            end if
        end do
    end subroutine count_strings

    !> Index of a name (case and leading blanks ignored) in `names`, 0 if absent.
    pure integer function name_index(text, names)
        character(len=*), intent(in) :: text
        character(len=*), intent(in) :: names(:)
        integer :: i
        name_index = 0
        do i = 1, size(names)
            if (trim(lower(adjustl(text))) == trim(names(i))) then
                name_index = i
                return
            end if
        end do
    end function name_index

    !> Name of a UNITS_* code, 'auto' for 0 (the AT2 header's units, else g).
    pure function units_name(code) result(s)
        integer, intent(in) :: code
        character(len=:), allocatable :: s
        if (code == 0) then
            s = 'auto'
        else
            s = record_units_name(code)
        end if
    end function units_name

    !> "name" for a single value, "name(i)" in a list of n.
    pure function value_name(name, i, n) result(item)
        character(len=*), intent(in) :: name
        integer, intent(in) :: i, n
        character(len=:), allocatable :: item
        if (n > 1) then
            item = list_item(name, i)
        else
            item = name
        end if
    end function value_name

    !> x to 4 significant digits, for progress lines.
    function short(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        real(dp) :: p
        if (.not. (ieee_is_finite(x) .and. abs(x) > 0.0_dp)) then
            s = num(x)
            return
        end if
        p = 10.0_dp**(3 - floor(log10(abs(x))))
        s = num(anint(x * p) / p)
    end function short

    !> The shortest decimal that reads back as x: plain for 1e-4 <= |x| < 1e7
    !> ("0.01", "9.80665"), else with an exponent ("1.5E-007").
    function num(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=40) :: buf, fm
        real(dp) :: y
        integer :: d, e, k
        if (.not. ieee_is_finite(x)) then
            s = real_str(x)
            return
        else if (.not. abs(x) > 0.0_dp) then
            s = '0.0'
            return
        end if
        do d = 2, 17
            write(fm, '(a, i0, a)') '(es30.', d - 1, 'e3)'
            write(buf, fm) x
            read(buf, *) y
            if (.not. abs(y - x) > 0.0_dp) exit
        end do
        k = scan(buf, 'E')
        read(buf(k + 1:), *) e
        s = trim(adjustl(buf))
        if (e >= -4 .and. e < 7) then
            write(fm, '(a, i0, a)') '(f0.', max(min(d, 17) - 1 - e, 1), ')'
            write(buf, fm) x
            s = trim(adjustl(buf))
            if (s(1:1) == '.') s = '0'//s
            if (s(1:2) == '-.') s = '-0'//s(2:)
            ! "0.010" -> "0.01", "2.0" stays
            k = len(s)
            do while (s(k:k) == '0' .and. s(k - 1:k - 1) /= '.')
                k = k - 1
            end do
            s = s(1:k)
        end if
    end function num

    !> x > 0 (+inf allowed), not NaN.
    elemental logical function positive(x)
        real(dp), intent(in) :: x
        positive = .false.
        if (.not. ieee_is_nan(x)) positive = x > 0.0_dp
    end function positive

end module driver_newmark
