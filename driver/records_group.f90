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
                         finite_positive, accel_unit_code, parse_real, NUM_OK, NUM_RANGE
    use driver_namelist_scan, only: nml_group, lower, read_line, control_char, char_name, &
                                    text_buffer, append, contents, max_line_len, open_text
    use driver_paths, only: glob_files, has_glob_chars, string_t
    use driver_input, only: located, join, given, list_length, list_item, name_index, &
                            value_name
    use driver_echo, only: echo_unit, echo_path
    use driver_unit_result, only: unit_result_t, add_log
    implicit none
    private

    public :: records_keys, record_in_t, record_out_t, records_defaults, read_records
    public :: check_records, echo_records, load_record, progress, report
    public :: path_len, short, records_missing, record_line, failed_records, resolve, &
              record_place, add_failed_record, &
              count_strings, label_len

    character(len=12), parameter :: records_keys(9) = [character(len=12) :: 'files', &
        'format', 'units', 'dt', 'scale', 'target_pga', 'pga_rounding', 'polarity', 'list']
    character(len=10), parameter :: format_names(5) = [character(len=10) :: 'auto', 'at2', &
        'slammer', 'column', 'time_accel']
    character(len=7), parameter :: rounding_names(2) = [character(len=7) :: 'exact', 'slammer']
    !> Columns of a list file (`list`): path first, the others optional.
    character(len=10), parameter :: list_columns(8) = [character(len=10) :: 'path', 'name', &
        'scale', 'target_pga', 'units', 'format', 'dt', 'polarity']

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

    ! the problems of a value (after "key = value"), the same in &records and in a list
    character(len=*), parameter :: bad_dt = ': must be a finite time step >= 0 (s; 0: from ' &
        //'the file)'
    character(len=*), parameter :: bad_scale = ': must be a finite factor > 0 (polarity = ' &
        //'-1 turns the record over)'
    character(len=*), parameter :: bad_target = ': must be a finite PGA > 0 (g; 0: use scale)'
    character(len=*), parameter :: bad_polarity = ': must be 1 or -1 (-1 turns the record ' &
        //'over before anything else)'
    character(len=*), parameter :: auto_units = '; or auto (the AT2 header''s units, else g)'

    ! namelist variables (defaults are set in records_defaults)
    character(len=path_len) :: files(max_files), list
    character(len=32) :: format(max_files), units(max_files)
    real(dp) :: dt(max_files), scale(max_files), target_pga(max_files)
    character(len=32) :: pga_rounding
    integer :: polarity(max_files)
    namelist /records/ files, format, units, dt, scale, target_pga, pga_rounding, polarity, list

    !> One record file and how to read and scale it.
    type :: record_in_t
        character(len=:), allocatable :: file   !! as written in &records (a file a pattern
                                                !! matched: as if written there), or in the
                                                !! path column of the list
        character(len=:), allocatable :: path   !! the path opened (relative to the input)
        character(len=:), allocatable :: name   !! its label in the tables (the list's name
                                                !! column); unset or '': the file stem
        integer :: line = 0                     !! its line in the list file, 0: from files
        integer :: fmt = RECORD_AUTO            !! RECORD_*
        integer :: units = 0                    !! UNITS_*, 0: auto (AT2 header, else g)
        real(dp) :: dt = 0.0_dp                 !! s, 0: from the file
        real(dp) :: scale = 1.0_dp              !! factor (without the polarity)
        real(dp) :: target = 0.0_dp             !! target PGA (g), 0: use scale
        integer :: polarity = 1                 !! +1 or -1
    end type record_in_t

    !> The &records group of the last check_records as given, for echo_records: its files
    !> entries (patterns as written, path = the entry as opened), the value of each per-file
    !> key for every record (one value given, else the default), how many values each was
    !> given (format, units, dt, scale, target_pga, polarity) and the list file as opened
    !> ('' without one).
    type :: records_given_t
        type(record_in_t), allocatable :: entries(:)
        type(record_in_t) :: shared
        integer :: counts(6) = 0
        character(len=:), allocatable :: list
    end type records_given_t
    type(records_given_t), save :: last_given

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
        list = ''
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

    !> Check &records (read by read_records) and fill recs: the files of `files` in order
    !> (a pattern: the files it matches, sorted), then the rows of the list file `list`.
    !> errmsg is empty on success.
    subroutine check_records(path, gr, recs, slammer_rounding, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gr
        type(record_in_t), allocatable, intent(out) :: recs(:)  !! one per file
        logical, intent(out) :: slammer_rounding                 !! pga_rounding = 'slammer'
        character(len=:), allocatable, intent(out) :: errmsg
        type(record_in_t), allocatable :: entries(:), found(:)
        type(record_in_t) :: shared
        character(len=:), allocatable :: where, item, list_opened
        integer :: n, i, k, n_fmt, n_units, n_dt, n_scale, n_target, n_pol, nrec
        real(dp) :: x
        character(len=256) :: msg

        where = located(path, gr)
        errmsg = ''
        slammer_rounding = .false.
        if (.not. (given(gr, 'files') .or. given(gr, 'list'))) then
            errmsg = where//'files: missing (the record files: files = ''a.AT2'', ''b.csv'', ' &
                     //'or a list of them: list = ''suite.csv'')'
            return
        end if
        n = 0
        if (given(gr, 'files')) then
            call count_strings(files, 'files', n, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
        end if
        list_opened = ''
        if (given(gr, 'list')) then
            if (len_trim(list) == 0) then
                errmsg = where//'list: empty (the list file of the records: list = ' &
                         //'''suite.csv'')'
                return
            end if
            list_opened = resolve(path, trim(adjustl(list)))
        end if
        allocate(entries(n))
        do i = 1, n
            entries(i)%file = trim(adjustl(files(i)))
            entries(i)%path = resolve(path, entries(i)%file)
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

        ! --- the values: i = 0 the value for every record (of the list too) when one is
        ! given, else the default; i = 1..n those of the files entries
        do i = 0, n
            if (i == 0) then
                call set_values(shared, i)
            else
                call set_values(entries(i), i)
            end if
            if (len(errmsg) > 0) return
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

        ! --- the records: the files entries (patterns expanded), then the list
        allocate(found(max(1, n)))
        nrec = 0
        do i = 1, n
            call expand_entry(path, entries(i), found, nrec, msg)
            if (len_trim(msg) > 0) then
                errmsg = where//list_item('files', i)//' = '''//entries(i)%file//''': ' &
                         //trim(msg)
                return
            end if
        end do
        if (len(list_opened) > 0) then
            call read_list(list_opened, shared, found, nrec, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//'list = '''//trim(adjustl(list))//''': '//errmsg
                return
            end if
        end if
        allocate(recs(nrec))
        do i = 1, nrec
            recs(i) = found(i)
        end do
        if (given(gr, 'pga_rounding') .and. .not. any(recs%target > 0.0_dp)) &
            write(error_unit, '(a)') 'warning: '//where//'pga_rounding: not used without ' &
            //'target_pga'

        call move_alloc(entries, last_given%entries)
        last_given%shared = shared
        last_given%counts = [n_fmt, n_units, n_dt, n_scale, n_target, n_pol]
        last_given%list = list_opened

    contains

        !> The values of entry i of files (i = 0: the value for all records) into r.
        subroutine set_values(r, i)
            type(record_in_t), intent(inout) :: r
            integer, intent(in) :: i
            if (n_fmt > 0 .and. (i > 0 .or. n_fmt == 1)) then
                k = max(1, min(i, n_fmt))
                item = value_name('format', k, n_fmt)
                call format_code(format(k), r%fmt, msg)
                if (len_trim(msg) > 0) then
                    errmsg = where//item//' = '''//trim(format(k))//''': '//trim(msg)
                    return
                end if
            end if
            if (n_units > 0 .and. (i > 0 .or. n_units == 1)) then
                k = max(1, min(i, n_units))
                item = value_name('units', k, n_units)
                call units_code(units(k), r%units, msg)
                if (len_trim(msg) > 0) then
                    errmsg = where//item//' = '//trim(msg)//auto_units
                    return
                end if
            end if
            if (n_dt > 0 .and. (i > 0 .or. n_dt == 1)) then
                k = max(1, min(i, n_dt))
                x = dt(k)
                if (.not. finite_at_least(x, 0.0_dp)) then
                    errmsg = where//value_name('dt', k, n_dt)//' = '//shortest_str(x)//bad_dt
                    return
                end if
                r%dt = x
            end if
            if (i > 0 .and. r%fmt == RECORD_COLUMN .and. .not. r%dt > 0.0_dp) then
                errmsg = where//'dt: '//list_item('files', i)//' = '''//r%file &
                         //''' has format ''column'', which has no time step: give ' &
                         //'dt > 0 (s) for it'
                return
            end if
            if (n_scale > 0 .and. (i > 0 .or. n_scale == 1)) then
                k = max(1, min(i, n_scale))
                x = scale(k)
                if (.not. finite_positive(x)) then
                    errmsg = where//value_name('scale', k, n_scale)//' = '//shortest_str(x) &
                             //bad_scale
                    return
                end if
                r%scale = x
            end if
            if (n_target > 0 .and. (i > 0 .or. n_target == 1)) then
                k = max(1, min(i, n_target))
                x = target_pga(k)
                if (.not. finite_at_least(x, 0.0_dp)) then
                    errmsg = where//value_name('target_pga', k, n_target)//' = ' &
                             //shortest_str(x)//bad_target
                    return
                end if
                r%target = x
            end if
            if (i > 0 .and. r%target > 0.0_dp .and. abs(r%scale - 1.0_dp) > 0.0_dp) then
                errmsg = where//'scale, target_pga: '//list_item('files', i)//' = ''' &
                         //r%file//''' has both (target_pga > 0 scales the record to ' &
                         //'that PGA; give scale = 1 or leave it out for that file)'
                return
            end if
            if (n_pol > 0 .and. (i > 0 .or. n_pol == 1)) then
                k = max(1, min(i, n_pol))
                if (abs(polarity(k)) /= 1) then
                    errmsg = where//value_name('polarity', k, n_pol)//' = ' &
                             //int_str(polarity(k))//bad_polarity
                    return
                end if
                r%polarity = polarity(k)
            end if
        end subroutine set_values

        !> Number of values of a per-file text key (0: not given).
        subroutine per_file_strings(values, name, m)
            character(len=*), intent(in) :: values(:)
            character(len=*), intent(in) :: name
            integer, intent(out) :: m
            m = 0
            if (.not. given(gr, name)) return
            call count_strings(values, name, m, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
            call check_count(name, m)
        end subroutine per_file_strings

        !> Number of values of a per-file real key (0: not given).
        subroutine per_file_reals(values, name, m)
            real(dp), intent(in) :: values(:)
            character(len=*), intent(in) :: name
            integer, intent(out) :: m
            m = 0
            if (.not. given(gr, name)) return
            call list_length(values, name, m, errmsg)
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

    !> RECORD_* code of a format name; problem: '' or why it is refused.
    subroutine format_code(text, code, problem)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: code
        character(len=*), intent(out) :: problem
        integer :: k
        problem = ''
        k = name_index(text, format_names)
        if (k == 0) then
            problem = 'unknown format (allowed: '//join(format_names)//')'
            return
        end if
        ! format_names are in the order of the RECORD_* codes
        code = RECORD_AUTO + k - 1
        if (record_format_name(code) /= trim(format_names(k))) &
            problem = 'internal error: format codes changed'
    end subroutine format_code

    !> UNITS_* code of a unit name, 0 for 'auto'; problem: '' or the library's message
    !> ("'x': unknown acceleration unit (allowed: ...)").
    subroutine units_code(text, code, problem)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: code
        character(len=*), intent(out) :: problem
        integer :: st
        problem = ''
        if (trim(lower(adjustl(text))) == 'auto') then
            code = 0
            return
        end if
        ! the one vocabulary of acceleration units (seispulse_records)
        call accel_unit_code(text, code, st, problem)
        if (st == SEISPULSE_SUCCESS) problem = ''
    end subroutine units_code

    !> Append to found(1:nrec) the records of one files entry: the entry itself, or the
    !> files its pattern matches (sorted; directories it matches are left out). msg: ''
    !> or why the entry is refused (a pattern that matches no file).
    subroutine expand_entry(nml_path, entry, found, nrec, msg)
        character(len=*), intent(in) :: nml_path        !! the input file
        type(record_in_t), intent(in) :: entry
        type(record_in_t), allocatable, intent(inout) :: found(:)
        integer, intent(inout) :: nrec
        character(len=*), intent(out) :: msg
        type(string_t), allocatable :: matches(:)
        integer :: j, n_dirs, st, k
        msg = ''
        if (.not. has_glob_chars(entry%file)) then
            call add_record(found, nrec, entry)
            return
        end if
        call glob_files(entry%path, matches, n_dirs, st)
        if (st /= 0) then
            msg = 'the pattern cannot be expanded (a directory cannot be read, or out of ' &
                  //'memory)'
            return
        end if
        if (size(matches) == 0) then
            msg = 'the pattern matches no file'
            if (n_dirs > 0) msg = trim(msg)//' (only '//int_str(n_dirs)//' directories, ' &
                //'which are left out)'
            return
        end if
        ! a match as if written in &records: without the directory of the input
        k = index(nml_path, '/', back=.true.)
        if (entry%file(1:1) == '/') k = 0
        do j = 1, size(matches)
            call add_record(found, nrec, entry)
            found(nrec)%path = matches(j)%s
            found(nrec)%file = matches(j)%s
            if (k > 0 .and. len(matches(j)%s) > k) then
                if (matches(j)%s(1:k) == nml_path(1:k)) found(nrec)%file = matches(j)%s(k + 1:)
            end if
        end do
    end subroutine expand_entry

    !> found(nrec + 1) = r (found doubled when full).
    subroutine add_record(found, nrec, r)
        type(record_in_t), allocatable, intent(inout) :: found(:)
        integer, intent(inout) :: nrec
        type(record_in_t), intent(in) :: r
        type(record_in_t), allocatable :: more(:)
        if (nrec == size(found)) then
            allocate(more(2 * size(found)))
            more(1:nrec) = found(1:nrec)
            call move_alloc(more, found)
        end if
        nrec = nrec + 1
        found(nrec) = r
    end subroutine add_record

    ! ------------------------------------------------------------------------------
    ! The list file (list = 'suite.csv')
    ! ------------------------------------------------------------------------------

    !> Append the records of the list file `opened` (CSV: a header row naming the columns,
    !> then one row per record; blank lines and lines starting with # skipped) to
    !> found(1:nrec). Every record starts from `shared` (the &records values for all
    !> records); a cell that is not empty replaces its value. errmsg: '' or
    !> "<opened>:<line>: <column> = '<cell>': problem".
    subroutine read_list(opened, shared, found, nrec, errmsg)
        character(len=*), intent(in) :: opened              !! the list file as opened
        type(record_in_t), intent(in) :: shared
        type(record_in_t), allocatable, intent(inout) :: found(:)
        integer, intent(inout) :: nrec
        character(len=:), allocatable, intent(out) :: errmsg
        type(string_t), allocatable :: cells(:)
        character(len=:), allocatable :: line, at
        integer, allocatable :: col(:)
        integer :: u, ios, lineno, ncell, ncol, j, k, bad, nrows
        logical :: too_long

        call open_text(opened, 'list file', u, errmsg)
        if (len(errmsg) > 0) return
        lineno = 0
        ncol = 0
        nrows = 0
        allocate(col(0))
        do
            call read_line(u, line, ios, max_line_len, too_long)
            if (ios /= 0) exit
            lineno = lineno + 1
            at = opened//':'//int_str(lineno)//': '
            if (too_long) then
                errmsg = at//'line longer than '//int_str(max_line_len)//' characters (not ' &
                         //'a list file?)'
                exit
            end if
            bad = control_char(line)
            if (bad > 0) then
                errmsg = at//char_name(line(bad:bad))//' at column '//int_str(bad) &
                         //': not a text file (a list file is CSV text)'
                exit
            end if
            k = verify(line, ' '//achar(9)//achar(13))
            if (k == 0) cycle
            if (line(k:k) == '#') cycle
            call split_csv(line, cells, ncell, errmsg)
            if (len(errmsg) > 0) then
                errmsg = at//errmsg
                exit
            end if
            if (ncol == 0) then
                ! the header
                ncol = ncell
                deallocate(col)
                allocate(col(ncol))
                do j = 1, ncol
                    col(j) = name_index(cells(j)%s, list_columns)
                    if (col(j) == 0) then
                        errmsg = at//'column '''//cells(j)%s//''': unknown column (allowed: ' &
                                 //join(list_columns)//')'
                        exit
                    end if
                    if (any(col(1:j - 1) == col(j))) then
                        errmsg = at//'column '''//cells(j)%s//''': given twice'
                        exit
                    end if
                end do
                if (len(errmsg) > 0) exit
                if (.not. any(col == 1)) then
                    errmsg = at//'no column ''path'' in the header (the first row names ' &
                             //'the columns: path, and any of '//join(list_columns(2:))//')'
                    exit
                end if
                cycle
            end if
            if (ncell /= ncol) then
                errmsg = at//int_str(ncell)//' fields, the header has '//int_str(ncol) &
                         //' (a field with a comma is quoted: "a,b")'
                exit
            end if
            nrows = nrows + 1
            call add_record(found, nrec, shared)
            found(nrec)%line = lineno
            call list_row(opened, cells, col, found(nrec), errmsg)
            if (len(errmsg) > 0) then
                errmsg = at//errmsg
                exit
            end if
        end do
        close(u)
        if (len(errmsg) > 0) return
        if (ncol == 0) then
            errmsg = opened//': no header row (the first row names the columns: path, and ' &
                     //'any of '//join(list_columns(2:))//')'
        else if (nrows == 0) then
            errmsg = opened//': no record (one row per record after the header)'
        end if
    end subroutine read_list

    !> The values of one row of the list into r (its cells by column code col: the index
    !> in list_columns). errmsg: '' or "<column> = '<cell>': problem".
    subroutine list_row(opened, cells, col, r, errmsg)
        character(len=*), intent(in) :: opened
        type(string_t), intent(in) :: cells(:)
        integer, intent(in) :: col(:)
        type(record_in_t), intent(inout) :: r
        character(len=:), allocatable, intent(inout) :: errmsg
        character(len=256) :: msg
        character(len=:), allocatable :: c, item
        real(dp) :: x
        integer :: j
        do j = 1, size(col)
            c = cells(j)%s
            item = trim(list_columns(col(j)))//' = '''//c//''''
            if (len(c) == 0) then
                if (col(j) == 1) then
                    errmsg = 'path: empty (the record file of this row)'
                    return
                end if
                cycle
            end if
            msg = ''
            select case (col(j))
            case (1)
                r%file = c
                r%path = resolve(opened, c)
            case (2)
                r%name = c
            case (3)
                call cell_real(c, x, msg)
                if (len_trim(msg) == 0 .and. .not. finite_positive(x)) msg = bad_scale(3:)
                r%scale = x
            case (4)
                call cell_real(c, x, msg)
                if (len_trim(msg) == 0 .and. .not. finite_at_least(x, 0.0_dp)) &
                    msg = bad_target(3:)
                r%target = x
            case (5)
                call units_code(c, r%units, msg)
                if (len_trim(msg) > 0) then
                    errmsg = 'units = '//trim(msg)//auto_units
                    return
                end if
            case (6)
                call format_code(c, r%fmt, msg)
            case (7)
                call cell_real(c, x, msg)
                if (len_trim(msg) == 0 .and. .not. finite_at_least(x, 0.0_dp)) msg = bad_dt(3:)
                r%dt = x
            case (8)
                if (c == '1' .or. c == '+1') then
                    r%polarity = 1
                else if (c == '-1') then
                    r%polarity = -1
                else
                    msg = bad_polarity(3:)
                end if
            end select
            if (len_trim(msg) > 0) then
                errmsg = item//': '//trim(msg)
                return
            end if
        end do
        if (r%fmt == RECORD_COLUMN .and. .not. r%dt > 0.0_dp) then
            errmsg = 'dt: the record '''//r%file//''' has format ''column'', which has no ' &
                     //'time step: give dt > 0 (s) for it'
        else if (r%target > 0.0_dp .and. abs(r%scale - 1.0_dp) > 0.0_dp) then
            errmsg = 'scale = '//shortest_str(r%scale)//', target_pga = ' &
                     //shortest_str(r%target)//': both (target_pga > 0 scales the record to ' &
                     //'that PGA; give scale = 1 in this row, or leave target_pga empty)'
        end if
    end subroutine list_row

    !> A decimal number in a cell (the library's strict reader); problem: '' or why not.
    subroutine cell_real(c, x, problem)
        character(len=*), intent(in) :: c
        real(dp), intent(out) :: x
        character(len=*), intent(out) :: problem
        integer :: code
        problem = ''
        call parse_real(c, x, code)
        if (code == NUM_RANGE) then
            problem = 'out of the range of double precision'
        else if (code /= NUM_OK) then
            problem = 'not a number'
        end if
    end subroutine cell_real

    !> The fields of a CSV line: separated by commas, blanks around them dropped; a field
    !> in double quotes may hold commas, and "" stands for one quote. errmsg: '' or why the
    !> line cannot be split.
    subroutine split_csv(line, cells, ncell, errmsg)
        character(len=*), intent(in) :: line
        type(string_t), allocatable, intent(out) :: cells(:)
        integer, intent(out) :: ncell
        character(len=:), allocatable, intent(inout) :: errmsg
        type(text_buffer) :: cell
        character(len=*), parameter :: blanks = ' '//achar(9)//achar(13)
        integer :: i, n, k
        logical :: quoted
        n = len(line)
        allocate(cells(count_commas() + 1))
        ncell = 0
        i = 1
        do
            ! one field, starting at i
            cell%n = 0
            do while (i <= n)
                if (index(blanks, line(i:i)) == 0) exit
                i = i + 1
            end do
            quoted = .false.
            if (i <= n) quoted = line(i:i) == '"'     ! (.and. need not short-circuit)
            if (quoted) then
                i = i + 1
                do
                    if (i > n) then
                        errmsg = 'field '//int_str(ncell + 1)//': no closing quote (")'
                        return
                    end if
                    if (line(i:i) == '"') then
                        if (i < n) then
                            if (line(i + 1:i + 1) == '"') then
                                call append(cell, '"')
                                i = i + 2
                                cycle
                            end if
                        end if
                        i = i + 1
                        exit
                    end if
                    call append(cell, line(i:i))
                    i = i + 1
                end do
                k = i
                do while (i <= n)
                    if (line(i:i) == ',') exit
                    if (index(blanks, line(i:i)) == 0) then
                        errmsg = 'field '//int_str(ncell + 1)//': text after the closing ' &
                                 //'quote'
                        return
                    end if
                    i = i + 1
                end do
                ncell = ncell + 1
                cells(ncell)%s = contents(cell)
            else
                k = i
                do while (i <= n)
                    if (line(i:i) == ',') exit
                    i = i + 1
                end do
                ncell = ncell + 1
                cells(ncell)%s = trim_blanks(line(k:i - 1))
            end if
            if (i > n) exit
            i = i + 1
        end do
    contains
        !> Commas in the line: the most fields it can have, less one.
        integer function count_commas()
            integer :: j
            count_commas = 0
            do j = 1, n
                if (line(j:j) == ',') count_commas = count_commas + 1
            end do
        end function count_commas
        function trim_blanks(s) result(t)
            character(len=*), intent(in) :: s
            character(len=:), allocatable :: t
            integer :: e
            e = verify(s, blanks, back=.true.)
            t = s(1:e)
        end function trim_blanks
    end subroutine split_csv

    ! ------------------------------------------------------------------------------
    ! Echo
    ! ------------------------------------------------------------------------------

    !> &records as given, completed (a namelist that reads back to the same input): the
    !> files entries as written (a pattern stays a pattern), the list file, and per-file
    !> keys with one value per files entry (one value for all records when there is a list
    !> and the input gave one). The group is that of the last check_records (recs: its
    !> records, whose files are the entries if check_records was not called).
    subroutine echo_records(recs, slammer_rounding)
        type(record_in_t), intent(in) :: recs(:)
        logical, intent(in) :: slammer_rounding
        type(records_given_t) :: gv
        integer :: i, flen, sizes(6)
        if (allocated(last_given%entries)) then
            gv = last_given
        else
            gv%entries = recs
            gv%list = ''
        end if
        flen = 1
        do i = 1, size(gv%entries)
            flen = max(flen, len(echo_path(gv%entries(i)%path)))
        end do
        ! with a list, a key given one value keeps one value (for the list's rows too)
        sizes = max(1, size(gv%entries))
        if (len(gv%list) > 0) then
            where (gv%counts <= 1) sizes = 1
        end if
        call echo_records_n(gv, slammer_rounding, max(1, size(gv%entries)), flen, sizes, &
                            max(1, len(echo_path(gv%list))))
    end subroutine echo_records

    subroutine echo_records_n(gv, slammer_rounding, n, flen, sizes, llen)
        type(records_given_t), intent(in) :: gv
        logical, intent(in) :: slammer_rounding
        integer, intent(in) :: n, flen, sizes(6), llen
        character(len=flen) :: files(n)
        character(len=10) :: format(sizes(1))
        character(len=6) :: units(sizes(2))
        real(dp) :: dt(sizes(3)), scale(sizes(4)), target_pga(sizes(5))
        character(len=7) :: pga_rounding
        character(len=llen) :: list
        integer :: polarity(sizes(6)), i
        type(record_in_t) :: r
        namelist /records/ files, format, units, dt, scale, target_pga, pga_rounding, polarity, &
                           list
        files = ''
        do i = 1, size(gv%entries)
            files(i) = echo_path(gv%entries(i)%path)
        end do
        do i = 1, maxval(sizes)
            r = value_of(i)
            if (i <= size(format)) format(i) = record_format_name(r%fmt)
            if (i <= size(units)) units(i) = units_name(r%units)
            if (i <= size(dt)) dt(i) = r%dt
            if (i <= size(scale)) scale(i) = r%scale
            if (i <= size(target_pga)) target_pga(i) = r%target
            if (i <= size(polarity)) polarity(i) = r%polarity
        end do
        pga_rounding = merge('slammer', 'exact  ', slammer_rounding)
        list = echo_path(gv%list)
        write(echo_unit(), nml=records)
    contains
        !> The values of entry i (those for all records when there is no entry; a key
        !> given one value has it in every entry).
        function value_of(i) result(r)
            integer, intent(in) :: i
            type(record_in_t) :: r
            if (size(gv%entries) == 0) then
                r = gv%shared
            else
                r = gv%entries(min(i, size(gv%entries)))
            end if
        end function value_of
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
        integer :: st

        ! --- read, turn over, scale (numbers only: threads run this side by side)
        call read_scaled(r, slammer_rounding, rec, o, accel, st, msg)
        ! --- the label and the lines, one thread at a time: gfortran 12 keeps the length
        ! of a deferred-length function result (record_label, short, list_item, ...) in
        ! one static variable per call site
        !$omp critical (seispulse_text)
        o%name = record_label(rec, r, ir)
        if (st == SEISPULSE_SUCCESS) then
            call progress(tag, ir, nrec, o%name//' (npts '//int_str(o%npts)//', dt ' &
                          //shortest_str(o%dt)//' s, PGA '//short(o%pga_read)//' g' &
                          //scaled_text(o)//')', log)
        else
            call progress(tag, ir, nrec, o%name//' (failed)', log)
            call report(where//record_place(ir, r)//': ' &
                        //o%message, log)
        end if
        !$omp end critical (seispulse_text)
    end subroutine load_record

    !> The numbers of load_record: read record r, turn it over and scale it into accel
    !> (g); o gets everything but the name (o%ok, o%message on failure). st is
    !> SEISPULSE_SUCCESS or not, msg the reason. Only library calls and intrinsic string
    !> operations: safe to run in several threads at once.
    subroutine read_scaled(r, slammer_rounding, rec, o, accel, st, msg)
        type(record_in_t), intent(in) :: r                !! the record's input
        logical, intent(in) :: slammer_rounding           !! pga_rounding = 'slammer'
        type(record_t), intent(out) :: rec                !! the record as read
        type(record_out_t), intent(inout) :: o            !! what happened
        real(dp), allocatable, intent(out) :: accel(:)    !! the scaled record (g), if ok
        integer, intent(out) :: st
        character(len=*), intent(out) :: msg
        real(dp) :: factor
        msg = ''
        if (r%units > 0) then
            call read_record(r%path, rec, st, msg, fmt=r%fmt, units=r%units, dt=r%dt)
        else
            call read_record(r%path, rec, st, msg, fmt=r%fmt, dt=r%dt)
        end if
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
        o%ok = st == SEISPULSE_SUCCESS
        if (o%ok) then
            o%pga = record_pga(accel)
        else
            o%message = trim(msg)
        end if
    end subroutine read_scaled

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
        if (r%line > 0) line = 'record '//int_str(ir)//': '//r%file//' (list line ' &
                               //int_str(r%line)//'): '
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
            if (failed(ir)) call add_failed_record(s, named, ir, outs(ir)%name)
        end do
    end function failed_records

    !> Add record ir, `name`, to s, the list of failed_records built one record at a time
    !> (`named`: records added so far, 0 at first).
    subroutine add_failed_record(s, named, ir, name)
        character(len=:), allocatable, intent(inout) :: s
        integer, intent(inout) :: named
        integer, intent(in) :: ir
        character(len=*), intent(in) :: name
        named = named + 1
        if (named > max_named + 1) return
        if (named > max_named) then
            s = s//', ...'
        else
            if (named > 1) s = s//', '
            s = s//int_str(ir)//' '''//name//''''
        end if
    end subroutine add_failed_record

    !> " -> 0.4 g" (or with the polarity) when the record is scaled or turned over.
    function scaled_text(o) result(s)
        type(record_out_t), intent(in) :: o
        character(len=:), allocatable :: s
        s = ''
        if (abs(abs(o%factor) - 1.0_dp) > 0.0_dp) s = ' -> '//short(o%pga)//' g'
        if (o%factor < 0.0_dp) s = s//', turned over (polarity -1)'
    end function scaled_text

    !> Where record ir comes from, for messages: "files(3) = 'a.AT2'", or for a record of
    !> the list "list line 7 = 'a.AT2'" (its line in the list file).
    function record_place(ir, r) result(s)
        integer, intent(in) :: ir                         !! its index among the records
        type(record_in_t), intent(in) :: r
        character(len=:), allocatable :: s
        if (r%line > 0) then
            s = 'list line '//int_str(r%line)//' = '''//r%file//''''
        else
            s = list_item('files', ir)//' = '''//r%file//''''
        end if
    end function record_place

    !> The table's label of a record: its name in the list, else the file stem (the file
    !> name if it has none).
    function record_label(rec, r, i) result(s)
        type(record_t), intent(in) :: rec
        type(record_in_t), intent(in) :: r
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        integer :: k
        s = ''
        if (allocated(r%name)) s = r%name
        if (len(s) == 0 .and. allocated(rec%name)) s = trim(rec%name)
        if (len(s) == 0) then
            k = index(r%path, '/', back=.true.)
            s = trim(r%path(k + 1:))
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
