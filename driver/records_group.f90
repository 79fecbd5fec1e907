!> The &records group, shared by the analyses that run on accelerogram files
!> ('newmark', 'sdof', 'spectra', ...): its keys, defaults, reading, checks and echo, and
!> reading one record (format, units, time step, polarity, scale or target PGA). One code
!> path, so that a record means the same in every analysis.
!>
!> A record that cannot be read or scaled is not an input error: load_record reports
!> it on stderr at once and returns ok = .false.; the analysis fails that record's
!> rows (NaN results, status failed) and goes on with the others.
module driver_records
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
    use seispulse, only: dp, shortest_str, SEISPULSE_SUCCESS, int_str, record_t, read_record, &
                         record_pga, &
                         pga_scale_factor, record_format_name, record_units_name, RECORD_AUTO, &
                         RECORD_COLUMN, UNITS_G, UNITS_M_S2, UNITS_CM_S2, finite_at_least, &
                         finite_positive, accel_unit_code
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: located, join, given, list_length, list_item, name_index, &
                            value_name
    use driver_echo, only: echo_unit, echo_path
    use driver_unit_result, only: unit_result_t, add_log
    implicit none
    private

    public :: records_keys, record_in_t, record_out_t, records_defaults, read_records
    public :: check_records, echo_records, load_record, progress, report
    public :: path_len, short, records_missing, record_line, failed_records, resolve, &
              count_strings, label_len

    character(len=12), parameter :: records_keys(8) = [character(len=12) :: 'files', &
        'format', 'units', 'dt', 'scale', 'target_pga', 'pga_rounding', 'polarity']
    character(len=10), parameter :: format_names(5) = [character(len=10) :: 'auto', 'at2', &
        'slammer', 'column', 'time_accel']
    character(len=7), parameter :: rounding_names(2) = [character(len=7) :: 'exact', 'slammer']

    !> Most record files.
    integer, parameter :: max_files = 500
    !> Length of a file name in &records.
    integer, parameter :: path_len = 1024
    !> Unset entries of the integer list polarity.
    integer, parameter :: unset_int = -huge(0)
    !> Most failed records named in a final message.
    integer, parameter :: max_named = 20

    !> After missing_group(path, 'records'): what the group is for.
    character(len=*), parameter :: records_missing = ' (it lists the record files: ' &
        //'files = ''a.AT2'', ...)'

    ! namelist variables (defaults are set in records_defaults)
    character(len=path_len) :: files(max_files)
    character(len=32) :: format(max_files), units(max_files)
    real(dp) :: dt(max_files), scale(max_files), target_pga(max_files)
    character(len=32) :: pga_rounding
    integer :: polarity(max_files)
    namelist /records/ files, format, units, dt, scale, target_pga, pga_rounding, polarity

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

    !> The defaults of &records, set before it is read.
    subroutine records_defaults()
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
    end subroutine records_defaults

    !> Reader of &records for driver_input's read_group.
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

    !> Check &records (read by read_records) and fill recs. errmsg is empty on success.
    subroutine check_records(path, gr, recs, slammer_rounding, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gr
        type(record_in_t), allocatable, intent(out) :: recs(:)  !! one per file
        logical, intent(out) :: slammer_rounding                 !! pga_rounding = 'slammer'
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, item
        integer :: n, i, k, n_fmt, n_units, n_dt, n_scale, n_target, n_pol, code
        real(dp) :: x
        character(len=256) :: msg

        where = located(path, gr)
        errmsg = ''
        slammer_rounding = .false.
        if (.not. given(gr, 'files')) then
            errmsg = where//'files: missing (the record files: files = ''a.AT2'', ''b.csv'')'
            return
        end if
        call count_strings(files, 'files', n, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        allocate(recs(n))
        do i = 1, n
            recs(i)%file = trim(adjustl(files(i)))
            recs(i)%path = resolve(path, recs(i)%file)
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
            associate (r => recs(i))
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
                    if (trim(lower(adjustl(units(k)))) == 'auto') then
                        r%units = 0
                    else
                        ! the one vocabulary of acceleration units (seispulse_records)
                        call accel_unit_code(units(k), r%units, code, msg)
                        if (code /= SEISPULSE_SUCCESS) then
                            errmsg = where//item//' = '//trim(msg)//'; or auto (the AT2 ' &
                                     //'header''s units, else g)'
                            return
                        end if
                    end if
                end if
                if (n_dt > 0) then
                    k = min(i, n_dt)
                    x = dt(k)
                    if (.not. finite_at_least(x, 0.0_dp)) then
                        errmsg = where//value_name('dt', k, n_dt)//' = '//shortest_str(x) &
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
                    if (.not. finite_positive(x)) then
                        errmsg = where//value_name('scale', k, n_scale)//' = '//shortest_str(x) &
                                 //': must be a finite factor > 0 (polarity = -1 turns the ' &
                                 //'record over)'
                        return
                    end if
                    r%scale = x
                end if
                if (n_target > 0) then
                    k = min(i, n_target)
                    x = target_pga(k)
                    if (.not. finite_at_least(x, 0.0_dp)) then
                        errmsg = where//value_name('target_pga', k, n_target)//' = ' &
                                 //shortest_str(x)//': must be a finite PGA > 0 (g; 0: use scale)'
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
            slammer_rounding = .false.
        case (2)
            slammer_rounding = .true.
        case default
            errmsg = where//'pga_rounding = '''//trim(pga_rounding)//''': unknown rounding ' &
                     //'(allowed: '//join(rounding_names)//')'
            return
        end select
        if (given(gr, 'pga_rounding') .and. .not. any(recs%target > 0.0_dp)) &
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

    ! ------------------------------------------------------------------------------
    ! Echo
    ! ------------------------------------------------------------------------------

    !> &records with one value per file (a namelist that reads back to the same input).
    subroutine echo_records(recs, slammer_rounding)
        type(record_in_t), intent(in) :: recs(:)
        logical, intent(in) :: slammer_rounding
        integer :: i, flen
        flen = 1
        do i = 1, size(recs)
            flen = max(flen, len(echo_path(recs(i)%path)))
        end do
        call echo_records_n(recs, slammer_rounding, size(recs), flen)
    end subroutine echo_records

    subroutine echo_records_n(recs, slammer_rounding, n, flen)
        type(record_in_t), intent(in) :: recs(:)
        logical, intent(in) :: slammer_rounding
        integer, intent(in) :: n, flen
        character(len=flen) :: files(n)
        character(len=10) :: format(n)
        character(len=6) :: units(n)
        real(dp) :: dt(n), scale(n), target_pga(n)
        character(len=7) :: pga_rounding
        integer :: polarity(n), i
        namelist /records/ files, format, units, dt, scale, target_pga, pga_rounding, polarity
        do i = 1, n
            files(i) = echo_path(recs(i)%path)
            format(i) = record_format_name(recs(i)%fmt)
            units(i) = units_name(recs(i)%units)
            dt(i) = recs(i)%dt
            scale(i) = recs(i)%scale
            target_pga(i) = recs(i)%target
            polarity(i) = recs(i)%polarity
        end do
        pga_rounding = merge('slammer', 'exact  ', slammer_rounding)
        write(echo_unit(), nml=records)
    end subroutine echo_records_n

    ! ------------------------------------------------------------------------------
    ! Reading one record
    ! ------------------------------------------------------------------------------

    !> Read record ir of nrec, turn it over (polarity) and scale it (scale, or target
    !> PGA): accel in g and o. Progress on stderr ("<tag>: record ir/nrec: ..."); a
    !> record that cannot be read or scaled gives o%ok = .false. with o%message, also
    !> reported on stderr at once ("<where>files(ir) = '...': message"). With `log` (a unit
    !> of a batch, which never prints) those lines go to log%log instead of stderr.
    subroutine load_record(where, r, ir, nrec, tag, slammer_rounding, o, accel, log)
        character(len=*), intent(in) :: where             !! "file:line: &records: "
        type(record_in_t), intent(in) :: r                !! the record's input
        integer, intent(in) :: ir, nrec                   !! its index, the number of records
        character(len=*), intent(in) :: tag               !! analysis name (progress lines)
        logical, intent(in) :: slammer_rounding           !! pga_rounding = 'slammer'
        type(record_out_t), intent(out) :: o              !! what happened
        real(dp), allocatable, intent(out) :: accel(:)    !! the scaled record (g), if ok
        type(unit_result_t), intent(inout), optional :: log  !! collects the stderr lines
        type(record_t) :: rec
        character(len=4096) :: msg
        real(dp) :: factor
        integer :: st

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
                call pga_scale_factor(rec%pga, r%target, slammer_rounding, factor, &
                                      st, msg)
                if (st /= SEISPULSE_SUCCESS) msg = r%path//': cannot scale to ' &
                    //'target_pga = '//shortest_str(r%target)//' g: '//trim(msg)
            end if
        end if
        if (st == SEISPULSE_SUCCESS) then
            o%factor = real(r%polarity, dp) * factor
            accel = rec%accel * o%factor
            if (.not. all(ieee_is_finite(accel))) then
                st = 1
                msg = r%path//': scale = '//shortest_str(factor)//': the scaled record ' &
                      //'overflows'
            end if
        end if
        if (st == SEISPULSE_SUCCESS) then
            o%ok = .true.
            o%pga = record_pga(accel)
            call progress(tag, ir, nrec, o%name//' (npts '//int_str(o%npts)//', dt ' &
                          //shortest_str(o%dt)//' s, PGA '//short(o%pga_read)//' g' &
                          //scaled_text(o)//')', log)
        else
            o%ok = .false.
            o%message = trim(msg)
            call progress(tag, ir, nrec, o%name//' (failed)', log)
            call report(where//list_item('files', ir)//' = '''//r%file//''': ' &
                        //o%message, log)
        end if
    end subroutine load_record

    ! ------------------------------------------------------------------------------
    ! Labels and messages
    ! ------------------------------------------------------------------------------

    !> The header line of record ir: "record 2: a.AT2: format at2, npts 240, dt 0.01,
    !> PGA 0.39, scale factor 1.5", or "record 2: a.AT2: FAILED: why".
    function record_line(ir, r, o) result(line)
        integer, intent(in) :: ir                         !! its index
        type(record_in_t), intent(in) :: r                !! its input
        type(record_out_t), intent(in) :: o               !! what happened
        character(len=:), allocatable :: line
        line = 'record '//int_str(ir)//': '//r%file//': '
        if (o%ok) then
            line = line//'format '//record_format_name(o%fmt)//', npts '//int_str(o%npts) &
                   //', dt '//shortest_str(o%dt)//', PGA '//shortest_str(o%pga_read) &
                       //', scale factor ' &
                   //shortest_str(o%factor)
        else
            line = line//'FAILED: '//o%message
        end if
    end function record_line

    !> Length of the longest record name (the label column of a table; at least 1).
    pure integer function label_len(outs)
        type(record_out_t), intent(in) :: outs(:)
        integer :: i
        label_len = 1
        do i = 1, size(outs)
            label_len = max(label_len, len(outs(i)%name))
        end do
    end function label_len

    !> "2 'name', 5 'other'" of the records with failed(ir), at most max_named of them
    !> (then ", ...").
    function failed_records(outs, failed) result(s)
        type(record_out_t), intent(in) :: outs(:)
        logical, intent(in) :: failed(:)                  !! per record
        character(len=:), allocatable :: s
        integer :: ir, named
        s = ''
        named = 0
        do ir = 1, size(outs)
            if (.not. failed(ir)) cycle
            named = named + 1
            if (named > max_named) then
                s = s//', ...'
                exit
            end if
            if (named > 1) s = s//', '
            s = s//int_str(ir)//' '''//outs(ir)%name//''''
        end do
    end function failed_records

    !> " -> 0.4 g" (or with the polarity) when the record is scaled or turned over.
    function scaled_text(o) result(s)
        type(record_out_t), intent(in) :: o
        character(len=:), allocatable :: s
        s = ''
        if (abs(abs(o%factor) - 1.0_dp) > 0.0_dp) s = ' -> '//short(o%pga)//' g'
        if (o%factor < 0.0_dp) s = s//', turned over (polarity -1)'
    end function scaled_text

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

    !> "<tag>: record i/n: text" on stderr (tag: the analysis), or into log%log.
    subroutine progress(tag, i, n, text, log)
        character(len=*), intent(in) :: tag
        integer, intent(in) :: i, n
        character(len=*), intent(in) :: text
        type(unit_result_t), intent(inout), optional :: log  !! collects the line instead
        if (present(log)) then
            call add_log(log, tag//': record '//int_str(i)//'/'//int_str(n)//': '//text)
            return
        end if
        write(error_unit, '(a)') tag//': record '//int_str(i)//'/'//int_str(n)//': '//text
        flush(error_unit)
    end subroutine progress

    !> An error of one record or row: reported at once (or into log%log), the run goes on.
    subroutine report(text, log)
        character(len=*), intent(in) :: text
        type(unit_result_t), intent(inout), optional :: log  !! collects the line instead
        if (present(log)) then
            call add_log(log, 'seispulse: error: '//text)
            return
        end if
        write(error_unit, '(a)') 'seispulse: error: '//text
        flush(error_unit)
    end subroutine report

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

    !> x to 4 significant digits, for progress lines.
    function short(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        real(dp) :: p
        if (.not. (ieee_is_finite(x) .and. abs(x) > 0.0_dp)) then
            s = shortest_str(x)
            return
        end if
        p = 10.0_dp**(3 - floor(log10(abs(x))))
        s = shortest_str(anint(x * p) / p)
    end function short

end module driver_records
