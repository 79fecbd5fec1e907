!> Analysis 'sdof' of the linear oscillator (doc/oscillator.md), on accelerogram files:
!> response spectra (SD, SV, SA and the pseudo-spectra PSV, PSA, optionally PSA/PGA),
!> their envelope over the records with the short-period plateau of the design curve,
!> and response histories.
!>
!> Groups: &records (driver_records: the files and how to read and scale each one, as
!> in analysis 'newmark'), &sdof (the spectrum periods, the damping ratios, g, how
!> peaks are taken, the envelope and the spectral shape) and &sdof_history (the
!> periods of the response histories). Tables <output>_sdof (spectra, when &sdof gives
!> periods), <output>_sdof_envelope (envelope = .true.) and <output>_sdof_history
!> (with &sdof_history). Everything is checked before any record is read, and every
!> table is computed before the first is written. A record that cannot be read,
!> scaled or analysed fails its rows (NaN results, status failed; the message goes to
!> stderr and into the headers) and the other records are still computed; run_sdof
!> then returns ROWS_FAILED and the driver exits with status 1 after writing the
!> tables. The numbers come from seispulse_records and seispulse_sdof_sim; the driver only
!> reads, checks and writes.
!>
!> Analyses 'sdof_beta' and 'sdof_shock': driver_sdof_beta, driver_sdof_shock.
module driver_sdof
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite
    use seispulse, only: dp, shortest_str, SEISPULSE_SUCCESS, outside, int_str, sdof_spectrum, &
                         pseudo_spectra, &
                         sdof_response, design_envelope, spectral_shape, SDOF_PEAKS_EXACT, &
                         SDOF_PEAKS_SAMPLES
    use driver_namelist_scan, only: nml_group
    use driver_input, only: find_group, located, join, read_optional, given, list_item, &
                            name_index, ROWS_FAILED
    use driver_input, only: missing_group
    use driver_input, only: output_located
    use driver_tables, only: table_t, table_open, table_comment, table_row, table_close, &
                             table_drop, say_written, category_kind, status_names
    use driver_records, only: records_keys, record_in_t, record_out_t, records_defaults, &
                              read_records, check_records, echo_records, load_record, report, &
                              records_missing, record_line, add_failed_record
    use driver_sdof_common, only: max_periods, max_dampings, check_dampings
    use driver_axis, only: axis_values
    use driver_echo, only: echo_unit
    use driver_unit_result, only: unit_result_t
    use driver_batch, only: batch_run, record_keys, pack_record, unpack_record, RECORD_VALUES
    use driver_records, only: record_place
    implicit none
    private

    public :: run_sdof, sdof_groups, sdof_tables

    !> Groups this analysis reads (besides &run).
    character(len=12), parameter :: sdof_groups(3) = [character(len=12) :: 'records', &
        'sdof', 'sdof_history']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=13), parameter :: sdof_tables(3) = [character(len=13) :: 'sdof', &
        'sdof_envelope', 'sdof_history']

    character(len=13), parameter :: sdof_keys(11) = [character(len=13) :: 'periods', &
        'period_range', 'period_count', 'spacing', 'damping', 'g', 'peaks', 'threads', &
        'envelope', 'plateau_below', 'shape']
    character(len=8), parameter :: history_keys(2) = [character(len=8) :: 'periods', &
        'damping']
    character(len=7), parameter :: peaks_names(2) = [character(len=7) :: 'exact', 'samples']

    !> Most rows of the spectra table (records x damping ratios x periods) and of the
    !> history table (their samples x damping ratios x periods).
    integer, parameter :: max_rows = 5000000, max_history_rows = 5000000

    ! namelist variables of &sdof (defaults are set in set_defaults; &records:
    ! driver_records; &sdof_history: read_history, into hist_periods, hist_damping)
    real(dp) :: periods(max_periods), period_range(2), damping(max_dampings), g, plateau_below
    integer :: period_count, threads
    character(len=32) :: spacing, peaks
    logical :: envelope, shape
    namelist /sdof/ periods, period_range, period_count, spacing, damping, g, peaks, threads, &
        envelope, plateau_below, shape

    real(dp) :: hist_periods(max_periods), hist_damping(max_dampings)

    !> The validated input.
    type :: config_t
        type(record_in_t), allocatable :: recs(:)
        logical :: slammer_rounding = .false.
        logical :: spectra = .false.                !! spectrum periods given
        real(dp), allocatable :: periods(:)         !! spectrum periods (s), as given
        character(len=:), allocatable :: grid       !! how they were given (for the header)
        real(dp), allocatable :: dampings(:)        !! damping ratios of the spectra
        real(dp) :: g = 9.80665_dp                  !! m/s2
        integer :: peaks = SDOF_PEAKS_EXACT
        integer :: threads = 0
        logical :: envelope = .false.
        real(dp) :: plateau_below = 0.0_dp          !! s
        logical :: shape = .false.
        logical :: history = .false.                !! &sdof_history given
        real(dp), allocatable :: h_periods(:)       !! history periods (s)
        real(dp), allocatable :: h_dampings(:)      !! history damping ratios
    end type config_t

    !> Results of one record.
    type :: record_res_t
        real(dp), allocatable :: sd(:, :), sv(:, :), sa(:, :), psv(:, :), psa(:, :)
        real(dp), allocatable :: shp(:, :)          !! PSA/PGA (shape = .true.)
        real(dp), allocatable :: t_peak(:), peak(:) !! per damping: peak of PSA/PGA
        real(dp), allocatable :: hist(:, :)         !! history rows (numeric columns)
    end type record_res_t

    ! --- the batch being computed (set by compute before batch_run, read-only while the
    ! units run concurrently in sdof_unit)
    type(config_t) :: run_cfg
    character(len=:), allocatable :: run_where          !! "file:line: &records: "
    ! --- the tables being written (on the root, by sdof_take: one record at a time, in
    ! record order)
    type(table_t) :: out_spectra, out_envelope, out_history
    integer :: out_failed = 0                    !! records failed
    integer :: out_named = 0                     !! records in out_names
    character(len=:), allocatable :: out_names   !! the failed records (failed_records)
    integer :: out_nok = 0                       !! records computed (in the envelope)
    integer :: out_hrows = 0                     !! rows of the history table so far
    character(len=:), allocatable :: out_error   !! why the history table was dropped
    !> the envelope: per period, damping and curve (SA, PSA, PSA/PGA) the largest ordinate
    !> of the records so far, and whether one was not finite
    real(dp), allocatable :: env_max(:, :, :)
    logical, allocatable :: env_bad(:, :, :)

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        call records_defaults()
        periods = nan
        period_range = nan
        period_count = 0
        spacing = 'linear'
        damping = nan
        g = 9.80665_dp
        peaks = 'exact'
        threads = 0
        envelope = .false.
        plateau_below = 0.0_dp
        shape = .false.
        hist_periods = nan
        hist_damping = nan
    end subroutine set_defaults

    subroutine read_sdof(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=sdof, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=sdof, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_sdof

    !> &sdof_history has keys named like those of &sdof: its own namelist, on local
    !> variables copied to hist_periods, hist_damping.
    subroutine read_history(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        real(dp) :: periods(max_periods), damping(max_dampings)
        namelist /sdof_history/ periods, damping
        periods = hist_periods
        damping = hist_damping
        if (len(text) > 0) then
            read(text, nml=sdof_history, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=sdof_history, iostat=ios, iomsg=iomsg)
        end if
        if (ios == 0) then
            hist_periods = periods
            hist_damping = damping
        end if
    end subroutine read_history

    !> Read and check the groups, compute every table, write them; print where they
    !> went. stat: 0, ROWS_FAILED (tables written, errmsg says which records
    !> failed), or > 0 for an input or output error (nothing written).
    subroutine run_sdof(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(nml_group) :: gr, gs, gh
        type(config_t) :: cfg

        call set_defaults()
        call read_optional(path, groups, 'records', records_keys, read_records, gr, stat, &
                           errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'sdof', sdof_keys, read_sdof, gs, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'sdof_history', history_keys, read_history, gh, &
                           stat, errmsg)
        if (stat /= 0) return
        stat = 1
        if (find_group(groups, 'records') == 0) then
            errmsg = missing_group(path, 'records')//records_missing
            return
        end if
        if (find_group(groups, 'sdof') == 0 .and. find_group(groups, 'sdof_history') == 0) &
            then
            errmsg = missing_group(path, 'sdof')//' (it gives the spectrum periods: periods ' &
                     //'= a list, or period_range = min, max with period_count; and the ' &
                     //'damping ratios)'
            return
        end if
        call check_records(path, gr, cfg%recs, cfg%slammer_rounding, errmsg)
        if (len(errmsg) > 0) return
        call check_sdof(path, gs, find_group(groups, 'sdof_history') > 0, cfg, errmsg)
        if (len(errmsg) > 0) return
        cfg%history = find_group(groups, 'sdof_history') > 0
        if (cfg%history) then
            call check_history(path, gh, cfg, errmsg)
            if (len(errmsg) > 0) return
        end if
        if (size(cfg%periods) * size(cfg%dampings) > max_rows / size(cfg%recs)) then
            errmsg = located(path, gs)//'periods, damping: '//int_str(size(cfg%recs)) &
                     //' records x '//int_str(size(cfg%dampings))//' damping ratios x ' &
                     //int_str(size(cfg%periods))//' periods: more than ' &
                     //int_str(max_rows)//' rows'
            return
        end if

        ! --- echo the effective input
        call echo_records(cfg%recs, cfg%slammer_rounding)
        call echo_sdof(cfg)

        ! --- compute every record, writing its rows as it comes (the tables are renamed
        !     from <file>.part when the run ends)
        call compute(path, gr, prefix, cfg, stat, errmsg)
        if (stat /= 0) return
        if (cfg%spectra) call say_written('sdof spectra', out_spectra%files)
        if (cfg%envelope) call say_written('sdof envelope', out_envelope%files)
        if (cfg%history) call say_written('sdof history', out_history%files)
        stat = 0
        if (out_failed > 0) then
            stat = ROWS_FAILED
            errmsg = int_str(out_failed)//' of '//int_str(size(cfg%recs))//' records failed (' &
                     //out_names//'): their rows hold NaN and status failed'
        end if
    end subroutine run_sdof

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> Check &sdof (possibly absent: then only the defaults) and fill cfg.
    subroutine check_sdof(path, gs, with_history, cfg, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gs
        logical, intent(in) :: with_history               !! &sdof_history is given
        type(config_t), intent(inout) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=13), parameter :: spectrum_keys(5) = [character(len=13) :: 'peaks', &
            'threads', 'envelope', 'plateau_below', 'shape']
        character(len=:), allocatable :: where
        integer :: i

        where = located(path, gs)
        errmsg = ''
        if (outside(g, 0.0_dp, huge(g), .true., .false.)) then
            errmsg = where//'g = '//shortest_str(g)//': must be a finite number > 0 (m/s2)'
            return
        end if
        cfg%g = g
        call check_dampings(gs, damping, cfg%dampings, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if

        ! --- spectrum periods
        call axis_values(gs, 'periods', 'period', periods, period_range, period_count, &
                         spacing, .false., .false., max_periods, cfg%periods, cfg%grid, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        cfg%spectra = size(cfg%periods) > 0
        if (.not. cfg%spectra) then
            if (.not. with_history) then
                errmsg = where//'periods: missing (give periods = a list, or period_range ' &
                         //'= min, max with period_count; or only &sdof_history for ' &
                         //'response histories)'
                return
            end if
            do i = 1, size(spectrum_keys)
                if (given(gs, trim(spectrum_keys(i)))) then
                    errmsg = where//trim(spectrum_keys(i))//': only with spectra (give ' &
                             //'periods or period_range)'
                    return
                end if
            end do
        end if

        ! --- how the spectra are computed
        cfg%peaks = name_index(peaks, peaks_names)
        if (cfg%peaks == 0) then
            errmsg = where//'peaks = '''//trim(peaks)//''': unknown peaks (allowed: ' &
                     //join(peaks_names)//')'
            return
        end if
        cfg%peaks = merge(SDOF_PEAKS_EXACT, SDOF_PEAKS_SAMPLES, cfg%peaks == 1)
        if (threads < 0) then
            errmsg = where//'threads = '//int_str(threads)//': must be >= 0 (0: the ' &
                     //'OpenMP default)'
            return
        end if
        cfg%threads = threads
        cfg%envelope = envelope
        cfg%shape = shape
        if (given(gs, 'plateau_below') .and. .not. envelope) then
            errmsg = where//'plateau_below: only with envelope = .true.'
            return
        end if
        if (outside(plateau_below, 0.0_dp, huge(g), .false., .false.)) then
            errmsg = where//'plateau_below = '//shortest_str(plateau_below)//': must be a finite ' &
                     //'period >= 0 (s; 0: no plateau)'
            return
        end if
        cfg%plateau_below = plateau_below
    end subroutine check_sdof

    !> Check &sdof_history and fill cfg%h_periods, cfg%h_dampings (default: the damping
    !> ratios of &sdof).
    subroutine check_history(path, gh, cfg, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gh
        type(config_t), intent(inout) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, grid
        real(dp) :: no_range(2)
        integer :: nrow

        where = located(path, gh)
        errmsg = ''
        no_range = ieee_value(no_range, ieee_quiet_nan)
        if (.not. given(gh, 'periods')) then
            errmsg = where//'periods: missing (the periods of the response histories, s)'
            return
        end if
        call axis_values(gh, 'periods', 'period', hist_periods, no_range, 0, 'linear', &
                         .false., .false., max_periods, cfg%h_periods, grid, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        if (given(gh, 'damping')) then
            call check_dampings(gh, hist_damping, cfg%h_dampings, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
        else
            cfg%h_dampings = cfg%dampings
        end if
        nrow = size(cfg%h_periods) * size(cfg%h_dampings)
        if (nrow > max_history_rows / max(1, size(cfg%recs))) then
            errmsg = where//'periods: too many histories ('//int_str(nrow)//' per record)'
            return
        end if
    end subroutine check_history

    ! ------------------------------------------------------------------------------
    ! Echo
    ! ------------------------------------------------------------------------------

    !> &sdof (and &sdof_history) with the values in use; the periods as a list.
    subroutine echo_sdof(cfg)
        type(config_t), intent(in) :: cfg
        if (cfg%spectra) then
            call echo_spectra(size(cfg%periods), size(cfg%dampings))
        else
            call echo_plain(size(cfg%dampings))
        end if
        if (cfg%history) call echo_history(size(cfg%h_periods), size(cfg%h_dampings))

    contains

        subroutine echo_spectra(np, nd)
            integer, intent(in) :: np, nd
            real(dp) :: periods(np), damping(nd), g, plateau_below
            character(len=7) :: peaks
            integer :: threads
            logical :: envelope, shape
            namelist /sdof/ periods, damping, g, peaks, threads, envelope, plateau_below, &
                shape
            periods = cfg%periods
            damping = cfg%dampings
            g = cfg%g
            peaks = merge('exact  ', 'samples', cfg%peaks == SDOF_PEAKS_EXACT)
            threads = cfg%threads
            envelope = cfg%envelope
            plateau_below = cfg%plateau_below
            shape = cfg%shape
            if (cfg%envelope) then
                write(echo_unit(), nml=sdof)
            else
                call echo_no_envelope()
            end if
        end subroutine echo_spectra

        subroutine echo_no_envelope()
            real(dp) :: periods(size(cfg%periods)), damping(size(cfg%dampings)), g
            character(len=7) :: peaks
            integer :: threads
            logical :: envelope, shape
            namelist /sdof/ periods, damping, g, peaks, threads, envelope, shape
            periods = cfg%periods
            damping = cfg%dampings
            g = cfg%g
            peaks = merge('exact  ', 'samples', cfg%peaks == SDOF_PEAKS_EXACT)
            threads = cfg%threads
            envelope = .false.
            shape = cfg%shape
            write(echo_unit(), nml=sdof)
        end subroutine echo_no_envelope

        subroutine echo_plain(nd)
            integer, intent(in) :: nd
            real(dp) :: damping(nd), g
            namelist /sdof/ damping, g
            damping = cfg%dampings
            g = cfg%g
            write(echo_unit(), nml=sdof)
        end subroutine echo_plain

        subroutine echo_history(np, nd)
            integer, intent(in) :: np, nd
            real(dp) :: periods(np), damping(nd)
            namelist /sdof_history/ periods, damping
            periods = cfg%h_periods
            damping = cfg%h_dampings
            write(echo_unit(), nml=sdof_history)
        end subroutine echo_history

    end subroutine echo_sdof

    ! ------------------------------------------------------------------------------
    ! Computation
    ! ------------------------------------------------------------------------------

    !> Every record (read, polarity, scale), its spectra and histories: one unit of a
    !> batch per record (driver_batch: threads, ranks, the restart journal). The tables
    !> are opened first; each record's header line and rows go into them as soon as every
    !> record before it is done (sdof_take), so memory does not grow with the number of
    !> records; the envelope keeps the running maxima. A record that fails (reading,
    !> scaling or a library check) keeps o%ok = .false. and its message, reported on
    !> stderr (in record order). stat /= 0: the journal was refused, or an output or the
    !> envelope failed (errmsg); no table is left.
    subroutine compute(path, gr, prefix, cfg, stat, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gr
        character(len=*), intent(in) :: prefix            !! output prefix (the journal)
        type(config_t), intent(inout) :: cfg              !! its records are lent to run_cfg
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(record_in_t), allocatable :: recs(:)
        integer :: np, nd

        ! --- the batch's read-only state (the records moved there, not copied: a long
        !     list is held once) and the tables
        call move_alloc(cfg%recs, recs)
        run_cfg = cfg
        call move_alloc(recs, run_cfg%recs)
        run_where = located(path, gr)
        out_failed = 0
        out_named = 0
        out_names = ''
        out_nok = 0
        out_hrows = 0
        out_error = ''
        np = size(cfg%periods)
        nd = size(cfg%dampings)
        if (allocated(env_max)) deallocate(env_max, env_bad)
        if (cfg%envelope) allocate(env_max(np, nd, 3), env_bad(np, nd, 3))
        call open_tables(prefix, cfg, stat, errmsg)
        if (stat == 0) then
            call batch_run(path, prefix, 'sdof', record_keys(run_cfg%recs, &
                           cfg%slammer_rounding), sdof_unit, sdof_take, stat, errmsg)
            if (stat == 0) then
                call close_tables(path, run_cfg, stat, errmsg)
                if (stat /= 0) errmsg = output_located(path)//errmsg
            end if
        else
            errmsg = output_located(path)//errmsg
        end if
        if (stat /= 0) then
            ! the journal was refused (its message as it is), or an output failed
            call drop_tables()
            stat = 1
        end if
        call move_alloc(run_cfg%recs, cfg%recs)
    end subroutine compute

    !> On the root, record ir's unit, in record order (driver_batch): its header line in
    !> every table, its spectra rows, its history rows, its spectra into the envelope's
    !> maxima; a failed record is counted and named.
    subroutine sdof_take(ir, res)
        integer, intent(in) :: ir
        type(unit_result_t), intent(in) :: res
        type(record_out_t) :: o
        type(record_res_t) :: q
        character(len=:), allocatable :: line

        associate (cfg => run_cfg)
            call unpack_record(res, o)
            if (o%ok) call unpack_results(cfg, o%dt, res%values, q)
            line = record_comment(cfg, ir, o, q)
            if (cfg%spectra) then
                call table_comment(out_spectra, line)
                call spectra_rows(cfg, o, q)
            end if
            if (cfg%envelope) then
                call table_comment(out_envelope, line)
                if (o%ok) call envelope_add(q)
            end if
            if (cfg%history) then
                call table_comment(out_history, line)
                call history_rows(cfg, o, q)
            end if
            if (.not. o%ok) then
                out_failed = out_failed + 1
                call add_failed_record(out_names, out_named, ir, o%name)
            end if
        end associate
    end subroutine sdof_take

    !> One unit: record ir read and analysed, packed into res: the record (pack_record),
    !> then, if it was computed, its results (pack_results); stderr lines into res%log.
    !> Runs concurrently: it reads run_cfg and run_where only. Texts are built in the
    !> critical section seispulse_text (see driver_newmark's record_rows: gfortran 12 and
    !> deferred-length character function results); the oscillators run outside it.
    subroutine sdof_unit(ir, res)
        integer, intent(in) :: ir
        type(unit_result_t), intent(out) :: res
        type(record_out_t) :: o
        type(record_res_t) :: q
        real(dp), allocatable :: accel(:), packed(:)
        character(len=4096) :: msg
        integer :: st

        associate (cfg => run_cfg, r => run_cfg%recs(ir))
            call load_record(run_where, r, ir, size(cfg%recs), 'sdof', cfg%slammer_rounding, &
                             o, accel, res)
            if (o%ok) then
                msg = ''
                call analyse(cfg, accel, o%dt, o%pga, q, st, msg)
                if (st /= SEISPULSE_SUCCESS) then
                    ! a failure of the oscillator itself: this record's rows
                    o%ok = .false.
                    o%message = trim(msg)
                    !$omp critical (seispulse_text)
                    call report(run_where//record_place(ir, r)//': ' &
                                //o%message, res)
                    !$omp end critical (seispulse_text)
                end if
            end if
            if (o%ok) then
                call pack_results(cfg, q, accel, packed)
            else
                allocate(packed(0))
            end if
        end associate
        allocate(res%values(RECORD_VALUES + size(packed)))
        call pack_record(o, res)
        res%values(RECORD_VALUES + 1:) = packed
    end subroutine sdof_unit

    !> The results of a computed record as one list: SD, SV, SA, PSV, PSA (periods x
    !> dampings each), with shape PSA/PGA, t_peak, peak; with histories the number of
    !> samples n, the record (n) and per oscillator (damping, then period) z, z', a_abs
    !> (n each): the other history columns follow from cfg and the record's dt.
    subroutine pack_results(cfg, q, accel, v)
        type(config_t), intent(in) :: cfg
        type(record_res_t), intent(in) :: q
        real(dp), intent(in) :: accel(:)                  !! the record as scaled (g)
        real(dp), allocatable, intent(out) :: v(:)
        integer :: nspec, nhist, npd, n, nosc, k, pos
        npd = size(cfg%periods) * size(cfg%dampings)
        nspec = 0
        if (cfg%spectra) nspec = 5 * npd
        if (cfg%spectra .and. cfg%shape) nspec = nspec + npd + 2 * size(cfg%dampings)
        nhist = 0
        n = size(accel)
        nosc = 0
        if (cfg%history) then
            ! (the history periods and dampings are allocated only with &sdof_history)
            nosc = size(cfg%h_periods) * size(cfg%h_dampings)
            nhist = 1 + n + 3 * n * nosc
        end if
        allocate(v(nspec + nhist))
        pos = 0
        if (cfg%spectra) then
            call put(reshape(q%sd, [npd]))
            call put(reshape(q%sv, [npd]))
            call put(reshape(q%sa, [npd]))
            call put(reshape(q%psv, [npd]))
            call put(reshape(q%psa, [npd]))
            if (cfg%shape) then
                call put(reshape(q%shp, [npd]))
                call put(q%t_peak)
                call put(q%peak)
            end if
        end if
        if (cfg%history) then
            call put([real(n, dp)])
            call put(accel)
            do k = 0, nosc - 1
                call put(q%hist(k * n + 1:(k + 1) * n, 5))
                call put(q%hist(k * n + 1:(k + 1) * n, 6))
                call put(q%hist(k * n + 1:(k + 1) * n, 7))
            end do
        end if
    contains
        subroutine put(x)
            real(dp), intent(in) :: x(:)
            v(pos + 1:pos + size(x)) = x
            pos = pos + size(x)
        end subroutine put
    end subroutine pack_results

    !> The record_res_t of a computed record from the values of its unit (after
    !> RECORD_VALUES): what analyse computed, bit for bit (the history columns damping, T,
    !> t = (i-1) dt and status as analyse builds them).
    subroutine unpack_results(cfg, dt, values, q)
        type(config_t), intent(in) :: cfg
        real(dp), intent(in) :: dt                        !! the record's time step (s)
        real(dp), intent(in) :: values(:)                 !! the unit's values
        type(record_res_t), intent(out) :: q
        real(dp), allocatable :: accel(:), t(:)
        integer :: np, nd, npd, n, i, j, k, row, pos
        np = size(cfg%periods)
        nd = size(cfg%dampings)
        npd = np * nd
        pos = RECORD_VALUES
        if (cfg%spectra) then
            q%sd = reshape(take(npd), [np, nd])
            q%sv = reshape(take(npd), [np, nd])
            q%sa = reshape(take(npd), [np, nd])
            q%psv = reshape(take(npd), [np, nd])
            q%psa = reshape(take(npd), [np, nd])
            if (cfg%shape) then
                q%shp = reshape(take(npd), [np, nd])
                q%t_peak = take(nd)
                q%peak = take(nd)
            end if
        end if
        if (.not. cfg%history) return
        n = nint(values(pos + 1))
        pos = pos + 1
        accel = take(n)
        allocate(q%hist(n * size(cfg%h_periods) * size(cfg%h_dampings), 8))
        t = dt * [(real(i - 1, dp), i = 1, n)]
        row = 0
        do j = 1, size(cfg%h_dampings)
            do k = 1, size(cfg%h_periods)
                q%hist(row + 1:row + n, 1) = cfg%h_dampings(j)
                q%hist(row + 1:row + n, 2) = cfg%h_periods(k)
                q%hist(row + 1:row + n, 3) = t
                q%hist(row + 1:row + n, 4) = accel
                q%hist(row + 1:row + n, 5) = take(n)
                q%hist(row + 1:row + n, 6) = take(n)
                q%hist(row + 1:row + n, 7) = take(n)
                q%hist(row + 1:row + n, 8) = 0.0_dp
                row = row + n
            end do
        end do
    contains
        function take(m) result(x)
            integer, intent(in) :: m
            real(dp) :: x(m)
            x = values(pos + 1:pos + m)
            pos = pos + m
        end function take
    end subroutine unpack_results

    !> Spectra (and PSA/PGA) and histories of one record (accel in g).
    subroutine analyse(cfg, accel, dt, pga, q, stat, msg)
        type(config_t), intent(in) :: cfg
        real(dp), intent(in) :: accel(:), dt, pga
        type(record_res_t), intent(out) :: q
        integer, intent(out) :: stat
        character(len=*), intent(inout) :: msg
        real(dp), allocatable :: disp(:), vel(:), acc(:), t(:)
        integer :: np, nd, j, k, i, n, row

        stat = SEISPULSE_SUCCESS
        np = size(cfg%periods)
        nd = size(cfg%dampings)
        if (cfg%spectra) then
            allocate(q%sd(np, nd), q%sv(np, nd), q%sa(np, nd), q%psv(np, nd), q%psa(np, nd))
            call sdof_spectrum(accel, dt, cfg%periods, cfg%dampings, cfg%g, q%sd, q%sv, q%sa, &
                               stat, msg, peaks=cfg%peaks, threads=cfg%threads)
            if (stat /= SEISPULSE_SUCCESS) return
            call pseudo_spectra(cfg%periods, q%sd, cfg%g, pga, q%psv, q%psa)
            if (cfg%shape) then
                allocate(q%shp(np, nd), q%t_peak(nd), q%peak(nd))
                do j = 1, nd
                    call spectral_shape(cfg%periods, q%psa(:, j), pga, q%shp(:, j), &
                                        q%t_peak(j), q%peak(j), stat, msg)
                    if (stat /= SEISPULSE_SUCCESS) then
                        msg = 'PSA/PGA (shape = .true.): '//trim(msg)
                        return
                    end if
                end do
            end if
        end if
        if (.not. cfg%history) return
        n = size(accel)
        if (n > max_history_rows / (size(cfg%h_periods) * size(cfg%h_dampings))) then
            stat = 1
            !$omp critical (seispulse_text)
            msg = 'the response histories ('//int_str(n)//' samples x ' &
                  //int_str(size(cfg%h_periods) * size(cfg%h_dampings))//' oscillators) ' &
                  //'would have more than '//int_str(max_history_rows)//' rows'
            !$omp end critical (seispulse_text)
            return
        end if
        allocate(q%hist(n * size(cfg%h_periods) * size(cfg%h_dampings), 8))
        allocate(disp(n), vel(n), acc(n), t(n))
        t = dt * [(real(i - 1, dp), i = 1, n)]
        row = 0
        do j = 1, size(cfg%h_dampings)
            do k = 1, size(cfg%h_periods)
                call sdof_response(accel, dt, cfg%h_periods(k), cfg%h_dampings(j), cfg%g, &
                                   disp, vel, acc, stat, msg)
                if (stat /= SEISPULSE_SUCCESS) return
                q%hist(row + 1:row + n, 1) = cfg%h_dampings(j)
                q%hist(row + 1:row + n, 2) = cfg%h_periods(k)
                q%hist(row + 1:row + n, 3) = t
                q%hist(row + 1:row + n, 4) = accel
                q%hist(row + 1:row + n, 5) = disp
                q%hist(row + 1:row + n, 6) = vel
                q%hist(row + 1:row + n, 7) = acc
                q%hist(row + 1:row + n, 8) = 0.0_dp
                row = row + n
            end do
        end do
    end subroutine analyse

    ! ------------------------------------------------------------------------------
    ! Output
    ! ------------------------------------------------------------------------------

    !> The first header lines of every table of this analysis: what, the input, then
    !> `head`, then the title of the records' lines (record_comment gives each).
    function lead_comments(path, what, head) result(lines)
        character(len=*), intent(in) :: path, what
        character(len=*), intent(in) :: head(:)
        character(len=max(len(head), 4096)) :: lines(3 + size(head))
        integer :: nh
        nh = size(head)
        lines(1) = 'seispulse analysis sdof: '//what
        lines(2) = 'input: '//trim(path)
        lines(3:2 + nh) = head
        lines(3 + nh) = 'records (index, file, format read, npts, dt (s), PGA as read ' &
                        //'(g), scale factor, PGA after scaling (g)):'
    end function lead_comments

    !> The header line of record ir (the same in every table): how it was read, its PGA
    !> after scaling and, with shape = .true., the peak of PSA/PGA per damping.
    function record_comment(cfg, ir, o, q) result(line)
        type(config_t), intent(in) :: cfg
        integer, intent(in) :: ir
        type(record_out_t), intent(in) :: o
        type(record_res_t), intent(in) :: q
        character(len=:), allocatable :: line
        integer :: j
        line = record_line(ir, cfg%recs(ir), o)
        if (.not. o%ok) return
        line = line//', PGA '//shortest_str(o%pga)
        if (cfg%spectra .and. cfg%shape) then
            do j = 1, size(cfg%dampings)
                line = line//'; damping '//shortest_str(cfg%dampings(j))//': PSA/PGA ' &
                       //'peak '//shortest_str(q%peak(j))//' at T = ' &
                       //shortest_str(q%t_peak(j))//' s'
            end do
        end if
    end function record_comment

    !> "periods: ...; g = ... m/s2; peaks = ..." of the spectrum tables.
    function spectra_line(cfg) result(s)
        type(config_t), intent(in) :: cfg
        character(len=:), allocatable :: s
        s = 'periods: '//cfg%grid//'; g = '//shortest_str(cfg%g)//' m/s2; peaks = '
        if (cfg%peaks == SDOF_PEAKS_EXACT) then
            s = s//'exact (true maxima, between samples too)'
        else
            s = s//'samples (maxima over the samples)'
        end if
    end function spectra_line

    !> Open the tables of the run (spectra: one row per record, damping ratio and period;
    !> envelope: one row per damping ratio and period; histories: per record, damping
    !> and period the samples of the response). stat /= 0: none is left.
    subroutine open_tables(prefix, cfg, stat, errmsg)
        character(len=*), intent(in) :: prefix
        type(config_t), intent(in) :: cfg
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=8), allocatable :: names(:), col_units(:)
        character(len=16), allocatable :: kinds(:)
        integer :: ncol

        stat = 0
        errmsg = ''
        if (cfg%spectra) then
            ncol = spectra_columns(cfg)
            allocate(names(ncol + 1), col_units(ncol + 1))
            names(1:8) = [character(len=8) :: 'record', 'damping', 'T', 'SD', 'SV', 'SA', &
                          'PSV', 'PSA']
            col_units(1:8) = [character(len=8) :: '-', '-', 's', 'm', 'm/s', 'g', 'm/s', 'g']
            if (cfg%shape) then
                names(9) = 'PSA/PGA'
                col_units(9) = '-'
            end if
            names(ncol + 1) = 'status'
            col_units(ncol + 1) = '-'
            allocate(kinds(ncol + 1))
            kinds = ''
            kinds(ncol + 1) = category_kind(status_names)
            call table_open(out_spectra, prefix, 'sdof', names, col_units, stat, errmsg, &
                            kinds=kinds, labelled=.true.)
            if (stat /= 0) return
            deallocate(names, col_units)
        end if
        if (cfg%envelope) then
            ncol = merge(5, 4, cfg%shape)
            allocate(names(ncol), col_units(ncol))
            names(1:4) = [character(len=8) :: 'damping', 'T', 'SA', 'PSA']
            col_units(1:4) = [character(len=8) :: '-', 's', 'g', 'g']
            if (cfg%shape) then
                names(5) = 'PSA/PGA'
                col_units(5) = '-'
            end if
            call table_open(out_envelope, prefix, 'sdof_envelope', names, col_units, stat, &
                            errmsg)
            if (stat /= 0) then
                call drop_tables()
                return
            end if
        end if
        if (cfg%history) then
            call table_open(out_history, prefix, 'sdof_history', &
                [character(len=8) :: 'record', 'damping', 'T', 't', 'a_g', 'z', 'z''', &
                 'a_abs', 'status'], &
                [character(len=8) :: '-', '-', 's', 's', 'g', 'm', 'm/s', 'g', '-'], stat, &
                errmsg, labelled=.true., kinds=[character(len=16) :: '', '', '', '', '', '', &
                '', '', category_kind(status_names)])
            if (stat /= 0) call drop_tables()
        end if
    end subroutine open_tables

    !> The numeric columns of a spectra row: damping, T, SD, SV, SA, PSV, PSA (, PSA/PGA),
    !> status.
    pure integer function spectra_columns(cfg) result(ncol)
        type(config_t), intent(in) :: cfg
        ncol = merge(9, 8, cfg%shape)
    end function spectra_columns

    !> The spectra rows of one record (NaN results and status failed if it failed).
    subroutine spectra_rows(cfg, o, q)
        type(config_t), intent(in) :: cfg
        type(record_out_t), intent(in) :: o
        type(record_res_t), intent(in) :: q
        real(dp) :: row(spectra_columns(cfg)), nan
        integer :: i, j, ncol
        nan = ieee_value(nan, ieee_quiet_nan)
        ncol = size(row)
        do j = 1, size(cfg%dampings)
            do i = 1, size(cfg%periods)
                row = nan
                row(1) = cfg%dampings(j)
                row(2) = cfg%periods(i)
                row(ncol) = 1.0_dp
                if (o%ok) then
                    row(3:7) = [q%sd(i, j), q%sv(i, j), q%sa(i, j), q%psv(i, j), q%psa(i, j)]
                    if (cfg%shape) row(8) = q%shp(i, j)
                    row(ncol) = 0.0_dp
                end if
                call table_row(out_spectra, row, o%name)
            end do
        end do
    end subroutine spectra_rows

    !> The history rows of one record (one row of NaN per damping and period, status
    !> failed, if it failed). Past max_history_rows in all the history table is dropped
    !> and out_error says why.
    subroutine history_rows(cfg, o, q)
        type(config_t), intent(in) :: cfg
        type(record_out_t), intent(in) :: o
        type(record_res_t), intent(in) :: q
        real(dp) :: row(8), nan
        integer :: i, j, k, n
        nan = ieee_value(nan, ieee_quiet_nan)
        if (o%ok) then
            n = size(q%hist, 1)
        else
            n = size(cfg%h_periods) * size(cfg%h_dampings)
        end if
        if (out_hrows > max_history_rows - n) then
            if (len(out_error) == 0) out_error = 'the history table would have more than ' &
                //int_str(max_history_rows)//' rows (give fewer records, or fewer periods ' &
                //'or damping ratios in &sdof_history)'
            call table_drop(out_history)
            return
        end if
        out_hrows = out_hrows + n
        if (o%ok) then
            do i = 1, n
                call table_row(out_history, q%hist(i, :), o%name)
            end do
        else
            do j = 1, size(cfg%h_dampings)
                do k = 1, size(cfg%h_periods)
                    row = nan
                    row(1:2) = [cfg%h_dampings(j), cfg%h_periods(k)]
                    row(8) = 1.0_dp
                    call table_row(out_history, row, o%name)
                end do
            end do
        end if
    end subroutine history_rows

    !> A computed record's SA, PSA (and PSA/PGA) into the envelope's running maxima
    !> (env_max; env_bad marks an ordinate that was not finite, which design_envelope
    !> refuses).
    subroutine envelope_add(q)
        type(record_res_t), intent(in) :: q
        out_nok = out_nok + 1
        call take(1, q%sa)
        call take(2, q%psa)
        if (run_cfg%shape) call take(3, q%shp)
    contains
        subroutine take(k, x)
            integer, intent(in) :: k
            real(dp), intent(in) :: x(:, :)
            if (out_nok == 1) then
                env_max(:, :, k) = x
                env_bad(:, :, k) = .false.
            else
                env_max(:, :, k) = max(env_max(:, :, k), x)
            end if
            env_bad(:, :, k) = env_bad(:, :, k) .or. .not. ieee_is_finite(x)
        end subroutine take
    end subroutine envelope_add

    !> Write the envelope's rows (design_envelope of the maxima over the records
    !> computed) and close every table, each with its first header lines, in the order
    !> spectra, envelope, histories (the first that fails gives stat and errmsg; a
    !> history table past max_history_rows fails with out_error).
    subroutine close_tables(path, cfg, stat, errmsg)
        character(len=*), intent(in) :: path
        type(config_t), intent(in) :: cfg
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=4096) :: head(4)

        stat = 0
        errmsg = ''
        if (cfg%spectra) then
            head(1) = spectra_line(cfg)
            head(2) = 'SD, SV: largest |z|, |z''| (displacement and velocity of the mass ' &
                      //'relative to the ground); SA: largest |a_g + z''''| (absolute ' &
                      //'acceleration); PSV = omega SD, PSA = omega^2 SD / g (Eq. 2.33); ' &
                      //'maxima over the record (no free vibration after it)'
            head(3) = 'T = 0: the ground itself (SD = SV = PSV = 0, SA = PSA = the PGA after ' &
                      //'scaling)'
            if (cfg%shape) head(3) = trim(head(3))//'; PSA/PGA: the normalized spectral shape'
            head(4) = 'status: ok, or failed (nan results; the reason is below and on ' &
                      //'stderr); exit status 1 when a record failed (2: an input error, no ' &
                      //'table)'
            call table_close(out_spectra, stat, errmsg, lead=lead_comments(path, &
                'response spectra of the linear oscillator on accelerograms, one row per ' &
                //'record, damping ratio and period', head))
            if (stat /= 0) return
        end if
        if (cfg%envelope) then
            call envelope_rows(cfg, stat, errmsg)
            if (stat /= 0) return
            head(1) = spectra_line(cfg)
            head(2) = 'the largest SA, PSA'
            if (cfg%shape) head(2) = trim(head(2))//', PSA/PGA'
            head(2) = trim(head(2))//' at each period over the '//int_str(out_nok) &
                      //' records computed (of '//int_str(size(cfg%recs))//'; NaN: none was)'
            if (cfg%plateau_below > 0.0_dp) then
                head(3) = 'plateau: below T = '//shortest_str(cfg%plateau_below) &
                          //' s each curve is held at its largest value at that or any ' &
                          //'longer period'
            else
                head(3) = 'no plateau (plateau_below = 0)'
            end if
            call table_close(out_envelope, stat, errmsg, lead=lead_comments(path, &
                'envelope of the response spectra over the records (the design curve), ' &
                //'one row per damping ratio and period', head(1:3)))
            if (stat /= 0) return
        end if
        if (cfg%history) then
            if (len(out_error) > 0) then
                ! the history table was dropped: it would have had too many rows
                stat = 1
                errmsg = out_error
                return
            end if
            head(1) = 'g = '//shortest_str(cfg%g)//' m/s2; the oscillator starts from rest; ' &
                      //'t = (i-1) dt at the samples of the record'
            head(2) = 'a_g: the ground acceleration (the record as scaled); z, z'': ' &
                      //'displacement and velocity of the mass relative to the ground; ' &
                      //'a_abs = a_g + z'''': absolute acceleration of the mass; T = 0: the ' &
                      //'ground (z = z'' = 0, a_abs = a_g)'
            head(3) = 'status: ok, or failed (one row of nan per damping and period; the ' &
                      //'reason is below and on stderr)'
            call table_close(out_history, stat, errmsg, lead=lead_comments(path, &
                'response histories of the linear oscillator on accelerograms, one block ' &
                //'of rows per record, damping ratio and period', head(1:3)))
        end if
    end subroutine close_tables

    !> The envelope's rows: per damping ratio and period, design_envelope of the maxima
    !> over the records computed (NaN if none was). stat /= 0: design_envelope refused.
    subroutine envelope_rows(cfg, stat, errmsg)
        type(config_t), intent(in) :: cfg
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=4096) :: msg
        real(dp) :: row(merge(5, 4, cfg%shape)), env(size(cfg%periods), 3), nan
        integer :: np, j, i, k, nk

        nan = ieee_value(nan, ieee_quiet_nan)
        np = size(cfg%periods)
        nk = size(row) - 2
        stat = 0
        errmsg = ''
        do j = 1, size(cfg%dampings)
            env = nan
            if (out_nok > 0) then
                do k = 1, nk
                    ! the maxima over the records are the envelope's peaks exactly; a
                    ! column with a non-finite ordinate is refused as the records were
                    msg = ''
                    call design_envelope(cfg%periods, reshape(merge(nan, env_max(:, j, k), &
                        env_bad(:, j, k)), [np, 1]), cfg%plateau_below, env(:, k), stat, msg)
                    if (stat /= SEISPULSE_SUCCESS) then
                        stat = 1
                        errmsg = 'envelope: '//trim(msg)
                        return
                    end if
                end do
            end if
            do i = 1, np
                row(1:2) = [cfg%dampings(j), cfg%periods(i)]
                row(3:) = env(i, 1:nk)
                call table_row(out_envelope, row)
            end do
        end do
    end subroutine envelope_rows

    !> Give up every table of the run (an error elsewhere): their files are dropped, the
    !> ones already closed too.
    subroutine drop_tables()
        call table_drop(out_spectra)
        call table_drop(out_envelope)
        call table_drop(out_history)
    end subroutine drop_tables

end module driver_sdof
