!> Accelerogram files as text: the format codes, the file and its lines, the
!> values of a line, and the readers of each format (used by `read_record` of
!> seispulse_records, which converts the values to g and fills the record).
!>
!> Formats:
!>
!> - `RECORD_AT2`: PEER NGA `.AT2`. Four header lines (1: database, 2: title,
!>   3: quantity and units, 4: `NPTS=  5590, DT=   .0050 SEC` (NGA-West2) or
!>   `  3999    .0100    NPTS, DT` (old NGA)), then exactly NPTS values, any number
!>   per line.
!> - `RECORD_SLAMMER`: SLAMMER / pySLAMMER CSV: two `#` comment lines, then
!>   `time_s, accel_g` rows.
!> - `RECORD_TIME_ACCEL`: two columns, time (s) and acceleration; comment lines
!>   (`#`) anywhere, blank lines ignored, values separated by a comma and/or blanks.
!>   The time step is (t_last - t_first)/(n - 1) and every time must lie on that
!>   uniform grid within 1 % of dt.
!> - `RECORD_COLUMN`: one value per line (comments and blank lines ignored); the
!>   caller gives dt.
!>
!> `RECORD_AUTO` takes AT2 for an `.at2` extension (any case), a first line that is
!> not a comment and mentions PEER, or a fourth line that is not a comment and
!> mentions NPTS; otherwise the first data line decides: two numbers give
!> `RECORD_TIME_ACCEL` (reported as `RECORD_SLAMMER` when the file starts with
!> exactly two comment lines), one number `RECORD_COLUMN`.
!>
!> The reader is strict: every value is validated as a decimal number before it is
!> converted (seispulse_number_reader: `nan`, `inf`, `1.0.0`, `1/2` are errors), every
!> row must have the number of values of its format, nothing is truncated. Messages
!> start with `<path>:<n>: ` (or `<path>: ` for the whole file) and say what was
!> expected and what was found. A UTF-8 byte-order mark, CRLF line ends, a last line
!> without a newline and trailing commas on comment lines are accepted.
!>
!> The file is read in one piece (stream access) and parsed in memory; numbers are
!> converted to the correctly rounded double (seispulse_number_reader).
!>
!> Limits (hostile or mistaken input: a binary file, a huge NPTS, a file of 1e8 samples
!> or of 1 GB): memory and time stay bounded and the error names the file and the line.
!>
!> - `MAX_RECORD_SAMPLES` = 10 000 000 samples. The longest accelerograms in use hold
!>   about 1e5 samples (NGA-West2: up to some 1e4 - 1e5; a 10 min subduction record at
!>   200 Hz: 1.2e5); 1e7 samples is 27.8 h at 100 Hz or 2.8 h at 1 kHz, and keeps the
!>   reader's arrays (values, and for two columns times and line numbers: 20 bytes a
!>   sample) under 200 MB. An AT2 header with a larger NPTS is refused at line 4, a text
!>   file at the row of sample MAX_RECORD_SAMPLES + 1.
!> - `MAX_RECORD_BYTES` = 536 870 912 bytes (512 MiB): the file is held in memory while
!>   it is parsed; 512 MiB leaves some 50 characters for each of MAX_RECORD_SAMPLES
!>   samples (an AT2 value takes about 15, a SLAMMER row about 20). A larger file is
!>   refused before it is read, from its size.
!> - a NUL byte anywhere: a record is a text file; the error gives its line and column.
!>
!> The reader therefore takes at most about 0.7 GB and time linear in the size of the
!> file (messages quote at most 40 characters of a line, control bytes shown as \xNN).
module seispulse_record_reader
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_format, only: num_str, quote, upper, int_str, int_str_len, quote_len
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_IO, set_error
    use seispulse_number_reader, only: parse_real, value_at, at_line, NUM_OK
    implicit none
    private

    public :: read_record_file, base_name, record_format_name, record_units_name
    public :: RECORD_AUTO, RECORD_AT2, RECORD_SLAMMER, RECORD_COLUMN, RECORD_TIME_ACCEL
    public :: UNITS_G, UNITS_M_S2, UNITS_CM_S2
    public :: MAX_RECORD_SAMPLES, MAX_RECORD_BYTES

    integer, parameter :: RECORD_AUTO = 0        !! detect the format (see the module notes)
    integer, parameter :: RECORD_AT2 = 1         !! PEER NGA .AT2
    integer, parameter :: RECORD_SLAMMER = 2     !! SLAMMER CSV: 2 comment lines, time, accel
    integer, parameter :: RECORD_COLUMN = 3      !! one value per line, dt from the caller
    integer, parameter :: RECORD_TIME_ACCEL = 4  !! two columns, time (s) and acceleration

    integer, parameter :: UNITS_G = 1            !! acceleration in g
    integer, parameter :: UNITS_M_S2 = 2         !! acceleration in m/s^2
    integer, parameter :: UNITS_CM_S2 = 3        !! acceleration in cm/s^2 (gal)

    !> The most samples a record may have (the module notes give the reasoning): a
    !> larger AT2 NPTS, or more rows of data, is an error naming the line.
    integer, parameter :: MAX_RECORD_SAMPLES = 10000000
    !> The largest record file, in bytes (512 MiB; the module notes give the reasoning):
    !> a larger file is refused from its size, before it is read.
    integer, parameter :: MAX_RECORD_BYTES = 536870912

    character(len=*), parameter :: LF = achar(10), CR = achar(13), TAB = achar(9)

    character(len=*), parameter :: AT2_LINE4_FORMS = "expected 'NPTS=  5590, DT=   .0050 SEC' " &
                                                      //"(NGA-West2) or '  3999    .0100    " &
                                                      //"NPTS, DT' (NGA)"

    !> The text of a file and a cursor over its lines.
    type :: text_t
        character(len=:), allocatable :: buf  !! the whole file
        integer :: pos = 1                    !! first byte of the next line
        integer :: line = 0                   !! number of the line last returned
        integer :: ls = 1                     !! bounds of that line in buf (CR removed)
        integer :: le = 0
    end type text_t

contains

    ! ------------------------------------------------------------------------------
    ! Public API
    ! ------------------------------------------------------------------------------

    !> Read an accelerogram file (formats in the module notes): the values as they are
    !> in the file, and their units. Arguments as for `read_record` of
    !> seispulse_records, which checks them first; `fmt_in`, `units_in` and `dt_in` are
    !> a RECORD_* code, 0 or a UNITS_* code, and 0 or the time step.
    !>
    !> stat = SEISPULSE_IO when the file cannot be opened or read, else
    !> SEISPULSE_INVALID_INPUT for a malformed file (the message names the file and the
    !> line, what was expected and what was found), a file above MAX_RECORD_BYTES or
    !> more samples than `max_samples`.
    subroutine read_record_file(path, fmt_in, units_in, dt_in, accel, units, dt, t0, title, &
                                fmt, stat, errmsg, max_samples)
        character(len=*), intent(in) :: path                  !! the file
        integer, intent(in) :: fmt_in            !! RECORD_*: the format asked for (AUTO: detect)
        integer, intent(in) :: units_in          !! UNITS_* of the values, 0: not given
        real(dp), intent(in) :: dt_in            !! time step (s), 0: not given
        real(dp), allocatable, intent(out) :: accel(:)  !! the acceleration values as read
        integer, intent(out) :: units            !! UNITS_* of `accel`
        real(dp), intent(out) :: dt              !! time step (s)
        real(dp), intent(out) :: t0              !! time of the first sample (s)
        character(len=:), allocatable, intent(out) :: title  !! line 2 of the header (AT2);
                                                 !! text formats: the first comment line
                                                 !! without '#'; else ''
        integer, intent(out) :: fmt              !! the format read (RECORD_AUTO on error)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(in), optional :: max_samples  !! the most samples accepted, 1 to
                                                      !! MAX_RECORD_SAMPLES (the default)
        type(text_t) :: txt
        integer :: want, nmax

        stat = SEISPULSE_SUCCESS
        units = UNITS_G
        dt = 0.0_dp
        t0 = 0.0_dp
        title = ''
        fmt = RECORD_AUTO
        nmax = MAX_RECORD_SAMPLES
        if (present(max_samples)) nmax = max_samples
        if (nmax < 1 .or. nmax > MAX_RECORD_SAMPLES) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'max_samples = ' &
                           //int_str(nmax)//': must be 1 to MAX_RECORD_SAMPLES = ' &
                           //int_str(MAX_RECORD_SAMPLES))
            return
        end if
        call load_file(path, txt%buf, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_no_nul(path, txt%buf, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        ! UTF-8 byte-order mark EF BB BF
        if (len(txt%buf) >= 3) then
            if (iachar(txt%buf(1:1)) == 239 .and. iachar(txt%buf(2:2)) == 187 .and. &
                iachar(txt%buf(3:3)) == 191) txt%pos = 4
        end if
        want = fmt_in
        if (want == RECORD_AUTO) then
            call detect_format(path, txt, want, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end if

        select case (want)
        case (RECORD_AT2)
            call read_at2(path, txt, units_in, dt_in, nmax, accel, units, dt, t0, title, stat, &
                          errmsg)
        case (RECORD_COLUMN)
            call read_columns(path, txt, 1, .false., units_in, dt_in, nmax, accel, units, dt, &
                              t0, title, stat, errmsg)
        case (RECORD_SLAMMER)
            call read_columns(path, txt, 2, .true., units_in, dt_in, nmax, accel, units, dt, &
                              t0, title, stat, errmsg)
        case default
            call read_columns(path, txt, 2, .false., units_in, dt_in, nmax, accel, units, dt, &
                              t0, title, stat, errmsg)
        end select
        if (stat == SEISPULSE_SUCCESS) fmt = want
    end subroutine read_record_file

    !> Name of a RECORD_* code: 'auto', 'at2', 'slammer', 'column', 'time_accel'
    !> ('unknown' otherwise).
    pure function record_format_name(code) result(name)
        integer, intent(in) :: code  !! a RECORD_* code
        ! a length by specification expression, not deferred: reentrant (gfortran 12)
        character(len=len_trim(format_text(code))) :: name
        name = format_text(code)
    end function record_format_name

    !> record_format_name, blank-padded.
    pure function format_text(code) result(name)
        integer, intent(in) :: code
        character(len=16) :: name
        select case (code)
        case (RECORD_AUTO)
            name = 'auto'
        case (RECORD_AT2)
            name = 'at2'
        case (RECORD_SLAMMER)
            name = 'slammer'
        case (RECORD_COLUMN)
            name = 'column'
        case (RECORD_TIME_ACCEL)
            name = 'time_accel'
        case default
            name = 'unknown'
        end select
    end function format_text

    !> Name of a UNITS_* code: 'g', 'm/s2', 'cm/s2' ('unknown' otherwise).
    pure function record_units_name(code) result(name)
        integer, intent(in) :: code  !! a UNITS_* code
        character(len=len_trim(units_text(code))) :: name
        name = units_text(code)
    end function record_units_name

    !> record_units_name, blank-padded.
    pure function units_text(code) result(name)
        integer, intent(in) :: code
        character(len=8) :: name
        select case (code)
        case (UNITS_G)
            name = 'g'
        case (UNITS_M_S2)
            name = 'm/s2'
        case (UNITS_CM_S2)
            name = 'cm/s2'
        case default
            name = 'unknown'
        end select
    end function units_text

    ! ------------------------------------------------------------------------------
    ! The file and its lines
    ! ------------------------------------------------------------------------------

    !> The whole file as one string (stream access: any line length, any line end).
    subroutine load_file(path, buf, stat, errmsg)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: buf
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        ! one thread at a time: a Fortran file is connected to one unit only, and threads
        ! may read the same record file ("File already opened in another unit"); the
        ! parsing that follows runs in parallel
        !$omp critical (seispulse_record_file)
        call read_whole_file(path, buf, stat, errmsg)
        !$omp end critical (seispulse_record_file)
    end subroutine load_file

    !> load_file's reading.
    subroutine read_whole_file(path, buf, stat, errmsg)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: buf
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: u, ios
        integer(int64) :: nbytes
        character(len=512) :: msg
        stat = SEISPULSE_SUCCESS
        msg = ''
        open(newunit=u, file=path, access='stream', form='unformatted', status='old', &
             action='read', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, errmsg, SEISPULSE_IO, path//': cannot open: '//trim(msg))
            return
        end if
        inquire(unit=u, size=nbytes)
        if (nbytes < 0) then
            close(u)
            call set_error(stat, errmsg, SEISPULSE_IO, path//': cannot read: the size of ' &
                           //'the file is unknown (not a regular file?)')
            return
        end if
        if (nbytes > int(MAX_RECORD_BYTES, int64)) then
            close(u)
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': the file has ' &
                           //int64_str(nbytes)//' bytes, more than a record file may have ' &
                           //'(MAX_RECORD_BYTES = '//int_str(MAX_RECORD_BYTES)//' bytes, 512 ' &
                           //'MiB): not an accelerogram, or too long to read')
            return
        end if
        allocate(character(len=int(nbytes)) :: buf, stat=ios)
        if (ios /= 0) then
            close(u)
            call set_error(stat, errmsg, SEISPULSE_IO, path//': cannot read: out of memory')
            return
        end if
        if (nbytes > 0) then
            read(u, iostat=ios, iomsg=msg) buf
            if (ios /= 0) then
                close(u)
                call set_error(stat, errmsg, SEISPULSE_IO, path//': cannot read: '//trim(msg))
                return
            end if
        end if
        close(u)
    end subroutine read_whole_file

    !> A NUL byte is an error naming its line and column: a record is a text file.
    subroutine check_no_nul(path, buf, stat, errmsg)
        character(len=*), intent(in) :: path
        character(len=*), intent(in) :: buf
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: k, i, lnum, lstart
        stat = SEISPULSE_SUCCESS
        k = index(buf, achar(0))
        if (k == 0) return
        lnum = 1
        lstart = 1
        do i = 1, k - 1
            if (buf(i:i) == LF) then
                lnum = lnum + 1
                lstart = i + 1
            end if
        end do
        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, lnum)//'a NUL ' &
                       //'byte (column '//int_str(k - lstart + 1)//'): a record is a text ' &
                       //'file, this one holds binary data')
    end subroutine check_no_nul

    !> An integer(int64) as text.
    pure function int64_str(n) result(s)
        integer(int64), intent(in) :: n
        character(len=int64_str_len(n)) :: s
        write(s, '(i0)') n
    end function int64_str

    !> The length of int64_str(n).
    pure integer function int64_str_len(n)
        integer(int64), intent(in) :: n
        character(len=24) :: b
        write(b, '(i0)') n
        int64_str_len = len_trim(b)
    end function int64_str_len

    !> A quoted excerpt of a line for a message: quote() (at most 40 characters) with
    !> control bytes shown as \xNN, so that a message stays one printable line.
    pure function shown(text) result(s)
        character(len=*), intent(in) :: text
        ! lengths by specification expressions, not deferred: reentrant (gfortran 12)
        character(len=quote_len(controls_shown(text))) :: s
        s = quote(controls_shown(text))
    end function shown

    !> The first 160 characters of text with control bytes (but tab) written as \xNN.
    pure function controls_shown(text) result(t)
        character(len=*), intent(in) :: text
        character(len=controls_shown_len(text)) :: t
        character(len=*), parameter :: HEX = '0123456789ABCDEF'
        integer :: i, c, p
        p = 0
        do i = 1, min(len(text), 160)
            c = iachar(text(i:i))
            if (is_control(c)) then
                t(p + 1:p + 4) = '\x'//HEX(c / 16 + 1:c / 16 + 1) &
                                 //HEX(mod(c, 16) + 1:mod(c, 16) + 1)
                p = p + 4
            else
                t(p + 1:p + 1) = text(i:i)
                p = p + 1
            end if
        end do
    end function controls_shown

    !> The length of controls_shown(text).
    pure integer function controls_shown_len(text)
        character(len=*), intent(in) :: text
        integer :: i
        controls_shown_len = min(len(text), 160)
        do i = 1, min(len(text), 160)
            if (is_control(iachar(text(i:i)))) controls_shown_len = controls_shown_len + 3
        end do
    end function controls_shown_len

    !> Whether character code c is a control byte shown as \xNN (not a tab).
    pure logical function is_control(c)
        integer, intent(in) :: c
        is_control = (c < 32 .and. c /= 9) .or. c == 127
    end function is_control

    !> Advance to the next line; false at the end of the text. The line is
    !> txt%buf(txt%ls:txt%le), without its LF or CRLF.
    logical function next_line(txt)
        type(text_t), intent(inout) :: txt
        integer :: k
        next_line = txt%pos <= len(txt%buf)
        if (.not. next_line) return
        txt%line = txt%line + 1
        txt%ls = txt%pos
        ! a plain loop: faster than index() through the library for short lines
        txt%le = len(txt%buf)
        txt%pos = len(txt%buf) + 1
        do k = txt%ls, len(txt%buf)
            if (txt%buf(k:k) == LF) then
                txt%le = k - 1
                txt%pos = k + 1
                exit
            end if
        end do
        if (txt%le >= txt%ls) then
            if (txt%buf(txt%le:txt%le) == CR) txt%le = txt%le - 1
        end if
    end function next_line

    !> Number of lines of the text (an upper bound on the rows of data).
    pure integer function count_lines(buf)
        character(len=*), intent(in) :: buf
        integer :: i
        count_lines = 1
        do i = 1, len(buf)
            if (buf(i:i) == LF) count_lines = count_lines + 1
        end do
    end function count_lines

    !> A blank or a tab. (iachar, not c == ' ': gfortran turns a comparison with a
    !> blank into a len_trim library call, the hot spot of the reader.)
    elemental logical function is_space(c)
        character, intent(in) :: c
        is_space = iachar(c) == 32 .or. iachar(c) == 9
    end function is_space

    !> Position of the first character that is not a blank or tab (0: none).
    pure integer function first_nonblank(line)
        character(len=*), intent(in) :: line
        integer :: i
        first_nonblank = 0
        do i = 1, len(line)
            if (.not. is_space(line(i:i))) then
                first_nonblank = i
                return
            end if
        end do
    end function first_nonblank

    pure logical function is_blank(line)
        character(len=*), intent(in) :: line
        is_blank = first_nonblank(line) == 0
    end function is_blank

    !> First non-blank character is '#'.
    pure logical function is_comment(line)
        character(len=*), intent(in) :: line
        integer :: k
        k = first_nonblank(line)
        is_comment = .false.
        if (k > 0) is_comment = line(k:k) == '#'
    end function is_comment

    !> A comment line as a title: without the leading '#'s, blanks and trailing commas.
    pure function comment_text(line) result(text)
        character(len=*), intent(in) :: line
        character(len=comment_len(line)) :: text
        integer :: a
        a = verify(line, ' '//TAB//'#')
        if (len(text) > 0) text = line(a:a + len(text) - 1)
    end function comment_text

    !> The length of comment_text(line): from its first character that is not a blank, a
    !> tab or '#' to its last that is not a blank, a tab or a comma (0: none).
    pure integer function comment_len(line)
        character(len=*), intent(in) :: line
        integer :: a, b
        comment_len = 0
        a = verify(line, ' '//TAB//'#')
        if (a == 0) return
        b = verify(line, ' '//TAB//',', back=.true.)
        comment_len = max(0, b - a + 1)
    end function comment_len

    !> The next value of a line: bounds ts:te (ts = 0 at the end of the line). Values
    !> are separated by blanks and/or one comma; `empty` flags an empty value (a
    !> leading or trailing comma, two commas in a row). Start with p = 1,
    !> after_comma = .false.
    pure subroutine next_field(line, p, after_comma, ts, te, empty)
        character(len=*), intent(in) :: line
        integer, intent(inout) :: p
        logical, intent(inout) :: after_comma
        integer, intent(out) :: ts, te
        logical, intent(out) :: empty
        integer :: n, k
        n = len(line)
        ts = 0
        te = 0
        empty = .false.
        do while (p <= n)
            if (.not. is_space(line(p:p))) exit
            p = p + 1
        end do
        if (p > n) then
            empty = after_comma
            return
        end if
        if (line(p:p) == ',') then
            empty = .true.
            return
        end if
        ts = p
        ! a plain loop: scan() goes through a slow library call here (a hot spot)
        te = n
        do k = p + 1, n
            if (is_space(line(k:k)) .or. line(k:k) == ',') then
                te = k - 1
                exit
            end if
        end do
        p = te + 1
        do while (p <= n)
            if (.not. is_space(line(p:p))) exit
            p = p + 1
        end do
        after_comma = .false.
        if (p <= n) then
            if (line(p:p) == ',') then
                after_comma = .true.
                p = p + 1
            end if
        end if
    end subroutine next_field

    !> Number of values on a line; -1 if one of them is empty.
    pure integer function count_fields(line)
        character(len=*), intent(in) :: line
        integer :: p, ts, te
        logical :: after_comma, empty
        p = 1
        after_comma = .false.
        count_fields = 0
        do
            call next_field(line, p, after_comma, ts, te, empty)
            if (empty) then
                count_fields = -1
                return
            end if
            if (ts == 0) return
            count_fields = count_fields + 1
        end do
    end function count_fields

    ! ------------------------------------------------------------------------------
    ! Formats
    ! ------------------------------------------------------------------------------

    !> The format of the file for RECORD_AUTO (see the module notes). The cursor of
    !> `txt` is left where it was.
    subroutine detect_format(path, txt, fmt, stat, errmsg)
        character(len=*), intent(in) :: path
        type(text_t), intent(inout) :: txt
        integer, intent(out) :: fmt
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        character(len=:), allocatable :: bname
        integer :: k, nf, ncomment_lead, code, p, ts, te, pos0, line0
        logical :: leading, after_comma, empty, numeric
        real(dp) :: x
        stat = SEISPULSE_SUCCESS
        fmt = RECORD_AUTO
        bname = base_with_ext(path)
        k = index(bname, '.', back=.true.)
        if (k > 1) then
            if (upper(bname(k + 1:)) == 'AT2') then
                fmt = RECORD_AT2
                return
            end if
        end if
        pos0 = txt%pos
        line0 = txt%line
        ! a PEER header: line 1 mentions PEER or line 4 NPTS (neither a comment)
        do while (next_line(txt))
            if (txt%line > 4) exit
            associate (line => txt%buf(txt%ls:txt%le))
                if (txt%line == 1 .or. txt%line == 4) then
                    if (.not. is_comment(line)) then
                        if ((txt%line == 1 .and. index(upper(line), 'PEER') > 0) .or. &
                            (txt%line == 4 .and. index(upper(line), 'NPTS') > 0)) then
                            fmt = RECORD_AT2
                            exit
                        end if
                    end if
                end if
            end associate
        end do
        txt%pos = pos0
        txt%line = line0
        if (fmt == RECORD_AT2) return
        ! otherwise the first data line decides
        ncomment_lead = 0
        leading = .true.
        do while (next_line(txt))
            associate (line => txt%buf(txt%ls:txt%le))
                if (is_comment(line)) then
                    if (leading) ncomment_lead = ncomment_lead + 1
                    cycle
                end if
                leading = .false.
                if (is_blank(line)) cycle
                nf = count_fields(line)
                numeric = nf == 1 .or. nf == 2
                if (numeric) then
                    p = 1
                    after_comma = .false.
                    do
                        call next_field(line, p, after_comma, ts, te, empty)
                        if (ts == 0) exit
                        call parse_real(line(ts:te), x, code)
                        if (code /= NUM_OK) numeric = .false.
                    end do
                end if
                if (.not. numeric) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                   at_line(path, txt%line)//'expected 1 or 2 numbers (one ' &
                                   //'column of accelerations, or time and acceleration), ' &
                                   //'found '//shown(line))
                    exit
                end if
                if (nf == 1) then
                    fmt = RECORD_COLUMN
                else if (ncomment_lead == 2 .and. txt%line == 3) then
                    fmt = RECORD_SLAMMER
                else
                    fmt = RECORD_TIME_ACCEL
                end if
                exit
            end associate
        end do
        if (fmt == RECORD_AUTO .and. stat == SEISPULSE_SUCCESS) then
            call no_data(path, txt, stat, errmsg)
        end if
        txt%pos = pos0
        txt%line = line0
    end subroutine detect_format

    !> The error of a file without data.
    subroutine no_data(path, txt, stat, errmsg)
        character(len=*), intent(in) :: path
        type(text_t), intent(in) :: txt
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        if (len(txt%buf) == 0) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': empty file (no data)')
        else
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': no data (only ' &
                           //'comments and blank lines)')
        end if
    end subroutine no_data

    !> PEER NGA .AT2.
    subroutine read_at2(path, txt, units_in, dt_in, nmax, accel, units, dt_out, t0, title, stat, &
                        errmsg)
        character(len=*), intent(in) :: path
        type(text_t), intent(inout) :: txt
        integer, intent(in) :: units_in    !! 0: not given
        real(dp), intent(in) :: dt_in      !! 0: not given
        integer, intent(in) :: nmax        !! the most samples accepted
        real(dp), allocatable, intent(inout) :: accel(:)  !! the values read
        integer, intent(out) :: units      !! their UNITS_*
        real(dp), intent(inout) :: dt_out  !! time step (s)
        real(dp), intent(inout) :: t0      !! time of the first sample (s)
        character(len=:), allocatable, intent(inout) :: title
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        character(len=*), parameter :: LINE3 = "'ACCELERATION TIME SERIES IN UNITS OF G'"
        integer :: k, ok3, units_hdr, units_use, npts, n, cap, p, ts, te, first_line
        real(dp) :: dt_hdr, x
        real(dp), allocatable :: vals(:)
        logical :: after_comma, empty

        stat = SEISPULSE_SUCCESS
        do k = 1, 4
            if (.not. next_line(txt)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, k) &
                               //'the AT2 header has 4 lines (database, title, ' &
                               //'quantity and units, NPTS and DT); found the end of the file')
                return
            end if
            associate (line => txt%buf(txt%ls:txt%le))
                select case (k)
                case (2)
                    title = trim(adjustl(line))
                case (3)
                    call at2_units(upper(line), units_hdr, ok3)
                    if (ok3 < 0) then
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                       at_line(path, 3)//'not an acceleration record (' &
                                       //'expected '//LINE3//', found '//shown(line)//')')
                        return
                    else if (ok3 == 0) then
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                       at_line(path, 3)//'expected the quantity and units ' &
                                       //'as '//LINE3//', found '//shown(line))
                        return
                    end if
                case (4)
                    call at2_npts_dt(line, npts, dt_hdr, stat, errmsg, path)
                    if (stat /= SEISPULSE_SUCCESS) return
                    if (npts > nmax) then
                        call too_many(path, 4, 'NPTS = '//int_str(npts), nmax, stat, errmsg)
                        return
                    end if
                end select
            end associate
        end do

        units_use = UNITS_G
        if (units_hdr /= 0) then
            if (units_in /= 0 .and. units_in /= units_hdr) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, 3) &
                               //'the header gives the units as '//record_units_name(units_hdr) &
                               //' but units = '//record_units_name(units_in)//' was passed')
                return
            end if
            units_use = units_hdr
        else if (units_in /= 0) then
            units_use = units_in
        end if
        if (dt_in > 0.0_dp) then
            if (abs(dt_in - dt_hdr) > 1.0e-6_dp * dt_hdr) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, 4) &
                               //'DT = '//num_str(dt_hdr)//' s, but dt = '//num_str(dt_in) &
                               //' s was given (they differ by more than 1e-6 relative)')
                return
            end if
        end if

        ! at most one value per two bytes of text
        cap = max(1, min(npts, len(txt%buf) / 2 + 1))
        allocate(vals(cap), stat=k)
        if (k /= 0) then
            call out_of_memory(path, cap, stat, errmsg)
            return
        end if
        n = 0
        first_line = 0
        do while (next_line(txt))
            associate (line => txt%buf(txt%ls:txt%le))
                if (is_blank(line)) cycle
                if (first_line == 0) first_line = txt%line
                p = 1
                after_comma = .false.
                do
                    call next_field(line, p, after_comma, ts, te, empty)
                    if (empty) then
                        call empty_value(path, txt%line, line, stat, errmsg)
                        return
                    end if
                    if (ts == 0) exit
                    if (n == npts) then
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                       at_line(path, txt%line)//'more values than NPTS = ' &
                                       //int_str(npts)//' (line 4): the extra values start ' &
                                       //'here ('//shown(line(ts:te))//')')
                        return
                    end if
                    call value_at(path, txt%line, line(ts:te), x, stat, errmsg)
                    if (stat /= SEISPULSE_SUCCESS) return
                    n = n + 1
                    vals(n) = x
                end do
            end associate
        end do
        if (n < npts) then
            if (n == 0) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': no data: NPTS ' &
                               //'= '//int_str(npts)//' (line 4) but the file has no values')
            else
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': NPTS = ' &
                               //int_str(npts)//' (line 4) but the file has only ' &
                               //int_str(n)//' values ('//line_range(first_line, txt%line)//')')
            end if
            return
        end if
        units = units_use
        call move_alloc(vals, accel)
        dt_out = dt_hdr
        t0 = 0.0_dp
    end subroutine read_at2

    !> Units of AT2 header line 3 (upper case): units = UNITS_* or 0 (none recognised,
    !> g assumed); ok = 1, 0 if the line does not say ACCELERATION, -1 if it says
    !> VELOCITY or DISPLACEMENT.
    pure subroutine at2_units(u3, units, ok)
        character(len=*), intent(in) :: u3
        integer, intent(out) :: units, ok
        integer :: p, a, b
        character(len=*), parameter :: SEPS = ' ,;:=()[]'//TAB
        units = 0
        if (index(u3, 'VELOCITY') > 0 .or. index(u3, 'DISPLACEMENT') > 0) then
            ok = -1
            return
        end if
        ok = 0
        if (index(u3, 'ACCEL') == 0) return
        ok = 1
        ! words of the line: the first that names units decides
        p = 1
        do while (p <= len(u3))
            a = verify(u3(p:), SEPS)
            if (a == 0) exit
            a = p + a - 1
            b = scan(u3(a:), SEPS)
            if (b == 0) then
                b = len(u3)
            else
                b = a + b - 2
            end if
            p = b + 1
            associate (w => u3(a:b))
                if (starts(w, 'CM/S') .or. w == 'GAL' .or. w == 'GALS' .or. w == 'CM/SEC2' &
                    .or. starts(w, 'CM/SEC')) then
                    units = UNITS_CM_S2
                    return
                else if (starts(w, 'M/S')) then
                    units = UNITS_M_S2
                    return
                else if (w == 'G' .or. w == 'G.' .or. w == "G'S" .or. w == 'GS') then
                    units = UNITS_G
                    return
                end if
            end associate
        end do
    end subroutine at2_units

    pure logical function starts(word, prefix)
        character(len=*), intent(in) :: word, prefix
        starts = .false.
        if (len(word) >= len(prefix)) starts = word(1:len(prefix)) == prefix
    end function starts

    !> NPTS and DT of AT2 header line 4, in either form.
    subroutine at2_npts_dt(line, npts, dt, stat, errmsg, path)
        character(len=*), intent(in) :: line
        integer, intent(out) :: npts
        real(dp), intent(out) :: dt
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: u4
        integer :: k, kd, p, ts, te, code
        logical :: after_comma, empty
        stat = SEISPULSE_SUCCESS
        npts = 0
        dt = 0.0_dp
        u4 = upper(line)
        k = index(u4, 'NPTS')
        if (k == 0) then
            call bad4('NPTS missing')
            return
        end if
        p = skip_blanks(u4, k + 4)
        if (p <= len(u4)) then
            if (u4(p:p) == '=') then
                ! NGA-West2: NPTS= n, DT= dt SEC
                call token_after(u4, p + 1, ts, te)
                if (ts == 0) then
                    call bad4('no value after NPTS=')
                    return
                end if
                if (.not. set_npts(line(ts:te))) return
                kd = index(u4(te + 1:), 'DT')
                if (kd == 0) then
                    call bad4('DT missing')
                    return
                end if
                p = skip_blanks(u4, te + kd + 2)
                if (p > len(u4)) then
                    call bad4("no '=' after DT")
                    return
                end if
                if (u4(p:p) /= '=') then
                    call bad4("no '=' after DT")
                    return
                end if
                call token_after(u4, p + 1, ts, te)
                if (ts == 0) then
                    call bad4('no value after DT=')
                    return
                end if
                ! a unit glued to the number: .0050SEC
                if (te - ts >= 3) then
                    if (u4(te - 2:te) == 'SEC') te = te - 3
                end if
                if (te > ts) then
                    if (u4(te:te) == 'S' .and. u4(te - 1:te - 1) /= 'E') te = te - 1
                end if
                call set_dt(line(ts:te))
                return
            end if
        end if
        ! old NGA: n dt NPTS, DT
        if (index(u4(k + 4:), 'DT') == 0) then
            call bad4('DT missing')
            return
        end if
        if (k == 1) then
            call bad4('no values before NPTS, DT')
            return
        end if
        if (count_fields(line(1:k - 1)) /= 2) then
            call bad4('two values expected before NPTS, DT')
            return
        end if
        p = 1
        after_comma = .false.
        call next_field(line(1:k - 1), p, after_comma, ts, te, empty)
        if (.not. set_npts(line(ts:te))) return
        call next_field(line(1:k - 1), p, after_comma, ts, te, empty)
        call set_dt(line(ts:te))

    contains

        subroutine bad4(what)
            character(len=*), intent(in) :: what
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, 4)//what//'; ' &
                           //AT2_LINE4_FORMS//', found '//shown(line))
        end subroutine bad4

        logical function set_npts(tok)
            character(len=*), intent(in) :: tok
            integer :: i, i0
            set_npts = .false.
            if (verify(tok, '0123456789') /= 0) then
                call bad4('NPTS = '//shown(tok)//' is not a positive integer')
                return
            end if
            i0 = verify(tok, '0')
            if (i0 == 0) i0 = len(tok)
            if (len(tok) - i0 + 1 > 9) then
                call too_many(path, 4, 'NPTS = '//shown(tok), MAX_RECORD_SAMPLES, stat, errmsg)
                return
            end if
            npts = 0
            do i = i0, len(tok)
                npts = 10 * npts + (iachar(tok(i:i)) - iachar('0'))
            end do
            if (npts == 0) then
                call bad4('NPTS = 0: the record has no samples')
                return
            end if
            set_npts = .true.
        end function set_npts

        subroutine set_dt(tok)
            character(len=*), intent(in) :: tok
            call parse_real(tok, dt, code)
            if (code /= NUM_OK) then
                call bad4('DT = '//shown(tok)//' is not a number')
                dt = 0.0_dp
            else if (.not. dt > 0.0_dp) then
                call bad4('DT = '//shown(tok)//' must be > 0')
                dt = 0.0_dp
            end if
        end subroutine set_dt

    end subroutine at2_npts_dt

    pure integer function skip_blanks(s, p0)
        character(len=*), intent(in) :: s
        integer, intent(in) :: p0
        skip_blanks = p0
        do while (skip_blanks <= len(s))
            if (.not. is_space(s(skip_blanks:skip_blanks))) exit
            skip_blanks = skip_blanks + 1
        end do
    end function skip_blanks

    !> The word starting after blanks at p0, up to a blank or comma (ts = 0: none).
    pure subroutine token_after(s, p0, ts, te)
        character(len=*), intent(in) :: s
        integer, intent(in) :: p0
        integer, intent(out) :: ts, te
        integer :: k
        ts = skip_blanks(s, p0)
        te = 0
        if (ts > len(s)) then
            ts = 0
            return
        end if
        k = scan(s(ts:), ' ,;'//TAB)
        if (k == 0) then
            te = len(s)
        else if (k == 1) then
            ts = 0
        else
            te = ts + k - 2
        end if
    end subroutine token_after

    !> One or two columns: RECORD_COLUMN (ncol = 1), RECORD_TIME_ACCEL and
    !> RECORD_SLAMMER (ncol = 2; `slammer` requires the two comment lines).
    subroutine read_columns(path, txt, ncol, slammer, units_in, dt_in, nmax, accel, units, &
                            dt_out, t0, title, stat, errmsg)
        character(len=*), intent(in) :: path
        type(text_t), intent(inout) :: txt
        integer, intent(in) :: ncol
        logical, intent(in) :: slammer
        integer, intent(in) :: units_in
        real(dp), intent(in) :: dt_in
        integer, intent(in) :: nmax        !! the most samples accepted
        real(dp), allocatable, intent(inout) :: accel(:)  !! the values read
        integer, intent(out) :: units      !! their UNITS_*
        real(dp), intent(inout) :: dt_out  !! time step (s)
        real(dp), intent(inout) :: t0      !! time of the first sample (s)
        character(len=:), allocatable, intent(inout) :: title
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), allocatable :: vals(:), times(:)
        integer, allocatable :: lines(:)
        integer :: cap, n, nf, p, ts, te, i
        logical :: after_comma, empty, titled
        real(dp) :: x, t, dt, expect

        stat = SEISPULSE_SUCCESS
        if (ncol == 1 .and. .not. dt_in > 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': dt: a single-column ' &
                           //'file has no time step; give dt')
            return
        end if
        cap = min(count_lines(txt%buf), nmax)
        allocate(vals(cap), stat=i)
        if (i == 0 .and. ncol == 2) allocate(times(cap), lines(cap), stat=i)
        if (i /= 0) then
            call out_of_memory(path, cap, stat, errmsg)
            return
        end if
        n = 0
        titled = .false.
        do while (next_line(txt))
            associate (line => txt%buf(txt%ls:txt%le))
                if (slammer .and. txt%line <= 2 .and. .not. is_comment(line)) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, txt%line) &
                                   //"expected a '#' comment line (a SLAMMER file starts " &
                                   //'with two), found '//shown(line))
                    return
                end if
                if (is_comment(line)) then
                    if (.not. titled) title = comment_text(line)
                    titled = .true.
                    cycle
                end if
                if (is_blank(line)) cycle
                nf = count_fields(line)
                if (nf < 0) then
                    call empty_value(path, txt%line, line, stat, errmsg)
                    return
                end if
                if (nf /= ncol) then
                    if (ncol == 1) then
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                       at_line(path, txt%line)//'expected 1 value (a single ' &
                                       //'column of accelerations), found '//int_str(nf)//': ' &
                                       //shown(line))
                    else
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                       at_line(path, txt%line)//'expected 2 values (time, ' &
                                       //'acceleration), found '//int_str(nf)//': '//shown(line))
                    end if
                    return
                end if
                if (n == nmax) then
                    call too_many(path, txt%line, 'a row of data', nmax, stat, errmsg)
                    return
                end if
                p = 1
                after_comma = .false.
                call next_field(line, p, after_comma, ts, te, empty)
                call value_at(path, txt%line, line(ts:te), x, stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                n = n + 1
                if (ncol == 2) then
                    t = x
                    call next_field(line, p, after_comma, ts, te, empty)
                    call value_at(path, txt%line, line(ts:te), x, stat, errmsg)
                    if (stat /= SEISPULSE_SUCCESS) return
                    if (n > 1) then
                        if (.not. t > times(n - 1)) then
                            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                           at_line(path, txt%line)//'time '//num_str(t) &
                                           //' is not after the previous time ' &
                                           //num_str(times(n - 1))//' (line ' &
                                           //int_str(lines(n - 1))//'): the times must increase')
                            return
                        end if
                    end if
                    times(n) = t
                    lines(n) = txt%line
                end if
                vals(n) = x
            end associate
        end do
        if (n == 0) then
            call no_data(path, txt, stat, errmsg)
            return
        end if

        if (ncol == 2) then
            if (n < 2) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': a time/' &
                               //'acceleration file needs at least 2 rows to give a time ' &
                               //'step, found 1 (line '//int_str(lines(1))//')')
                return
            end if
            dt = (times(n) - times(1)) / real(n - 1, dp)
            if (.not. (ieee_is_finite(dt) .and. dt > 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': the times ' &
                               //num_str(times(1))//' to '//num_str(times(n)) &
                               //' give no finite time step')
                return
            end if
            do i = 2, n - 1
                expect = times(1) + real(i - 1, dp) * dt
                if (abs(times(i) - expect) > 0.01_dp * dt) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                   at_line(path, lines(i))//'time '//num_str(times(i)) &
                                   //' is off the uniform time grid: expected ' &
                                   //num_str(expect)//' (dt = '//num_str(dt)//' s from ' &
                                   //'the first and last times, tolerance 0.01 dt)')
                    return
                end if
            end do
            if (dt_in > 0.0_dp) then
                if (abs(dt_in - dt) > 1.0e-6_dp * dt) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': the ' &
                                   //'times give dt = '//num_str(dt)//' s, but dt = ' &
                                   //num_str(dt_in)//' s was given (they differ by more ' &
                                   //'than 1e-6 relative)')
                    return
                end if
            end if
            t0 = times(1)
        else
            dt = dt_in
            t0 = 0.0_dp
        end if

        units = UNITS_G
        if (units_in /= 0) units = units_in
        if (allocated(accel)) deallocate(accel)
        if (n == cap) then
            call move_alloc(vals, accel)
        else
            allocate(accel(n), source=vals(1:n))
        end if
        dt_out = dt
    end subroutine read_columns

    !> The error of a record above the sample limit, at line lnum: `what` would make
    !> more than nmax samples.
    subroutine too_many(path, lnum, what, nmax, stat, errmsg)
        character(len=*), intent(in) :: path, what
        integer, intent(in) :: lnum, nmax
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        character(len=:), allocatable :: limit
        if (nmax == MAX_RECORD_SAMPLES) then
            limit = 'MAX_RECORD_SAMPLES = '//int_str(nmax)//' samples, the limit of the reader'
        else
            limit = 'max_samples = '//int_str(nmax)//' samples'
        end if
        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, lnum)//what &
                       //': more samples than a record may have ('//limit//')')
    end subroutine too_many

    subroutine out_of_memory(path, n, stat, errmsg)
        character(len=*), intent(in) :: path
        integer, intent(in) :: n
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call set_error(stat, errmsg, SEISPULSE_IO, path//': cannot read: out of memory for ' &
                       //int_str(n)//' samples')
    end subroutine out_of_memory

    subroutine empty_value(path, lnum, line, stat, errmsg)
        character(len=*), intent(in) :: path, line
        integer, intent(in) :: lnum
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, lnum)//'empty ' &
                       //'value (a leading or trailing comma, or two commas in a row): ' &
                       //shown(line))
    end subroutine empty_value

    ! ------------------------------------------------------------------------------
    ! Small helpers
    ! ------------------------------------------------------------------------------

    !> "line a" or "lines a-b".
    pure function line_range(a, b) result(s)
        integer, intent(in) :: a, b
        character(len=merge(7 + int_str_len(a) + int_str_len(b), 5 + int_str_len(a), &
                            b > a)) :: s
        if (b > a) then
            s = 'lines '//int_str(a)//'-'//int_str(b)
        else
            s = 'line '//int_str(a)
        end if
    end function line_range

    !> The file name of a path, without the directory.
    pure function base_with_ext(path) result(b)
        character(len=*), intent(in) :: path
        character(len=max(0, len_trim(path) - scan(path, '/\', back=.true.))) :: b
        integer :: k
        k = scan(path, '/\', back=.true.)
        b = path(k + 1:k + len(b))
    end function base_with_ext

    !> The file name without the directory and the last extension (a leading dot is
    !> part of the name: '.hidden' stays).
    pure function base_name(path) result(b)
        character(len=*), intent(in) :: path  !! a file path
        character(len=base_name_len(path)) :: b
        integer :: k
        k = scan(path, '/\', back=.true.)
        b = path(k + 1:k + len(b))
    end function base_name

    !> The length of base_name(path).
    pure integer function base_name_len(path)
        character(len=*), intent(in) :: path
        integer :: k, n, d
        k = scan(path, '/\', back=.true.)
        n = max(0, len_trim(path) - k)
        d = index(path(k + 1:k + n), '.', back=.true.)
        base_name_len = n
        if (d > 1) base_name_len = d - 1
    end function base_name_len

end module seispulse_record_reader
