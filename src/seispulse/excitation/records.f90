!> Accelerogram files: reading, PGA scaling and ground velocity/displacement.
!>
!> Formats (`read_record`):
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
!> converted (`nan`, `inf`, `1.0.0`, `1/2` are errors), every row must have the
!> number of values of its format, nothing is truncated. Messages start with
!> `<path>, line <n>: ` (or `<path>: ` for the whole file) and say what was expected
!> and what was found. A UTF-8 byte-order mark, CRLF line ends, a last line without
!> a newline and trailing commas on comment lines are accepted.
!>
!> The file is read in one piece (stream access) and parsed in memory. Numbers with
!> at most 15 significant digits and a decimal exponent within +-22 are converted
!> exactly (one correctly rounded product or quotient of exact doubles, Clinger's
!> fast path); others go through the compiler's conversion (a correctly rounded
!> strtod in gfortran). Either way the result is the correctly rounded double,
!> bitwise equal to what numpy or C would read.
!>
!> Accelerations are stored in g: values in m/s^2 are divided by STANDARD_GRAVITY,
!> values in cm/s^2 by 100 STANDARD_GRAVITY.
module seispulse_records
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_checks, only: finite_positive
    use seispulse_format, only: num_str, quote, upper, real_str, int_str
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_IO, set_error
    implicit none
    private

    public :: record_t, read_record, record_pga, pga_scale_factor, ground_motion, &
              record_format_name, record_units_name
    public :: RECORD_AUTO, RECORD_AT2, RECORD_SLAMMER, RECORD_COLUMN, RECORD_TIME_ACCEL
    public :: UNITS_G, UNITS_M_S2, UNITS_CM_S2, STANDARD_GRAVITY

    integer, parameter :: RECORD_AUTO = 0        !! detect the format (see the module notes)
    integer, parameter :: RECORD_AT2 = 1         !! PEER NGA .AT2
    integer, parameter :: RECORD_SLAMMER = 2     !! SLAMMER CSV: 2 comment lines, time, accel
    integer, parameter :: RECORD_COLUMN = 3      !! one value per line, dt from the caller
    integer, parameter :: RECORD_TIME_ACCEL = 4  !! two columns, time (s) and acceleration

    integer, parameter :: UNITS_G = 1            !! acceleration in g
    integer, parameter :: UNITS_M_S2 = 2         !! acceleration in m/s^2
    integer, parameter :: UNITS_CM_S2 = 3        !! acceleration in cm/s^2 (gal)

    real(dp), parameter :: STANDARD_GRAVITY = 9.80665_dp  !! m/s^2, for unit conversion

    !> An accelerogram sampled at a constant time step, in g.
    type :: record_t
        real(dp), allocatable :: accel(:)      !! ground acceleration (g), accel(i) at t = (i-1) dt
        real(dp) :: dt = 0.0_dp                !! time step (s)
        integer :: npts = 0                    !! number of samples = size(accel)
        real(dp) :: pga = 0.0_dp               !! max |accel| (g)
        real(dp) :: t0 = 0.0_dp                !! time of the first sample in the file (s; 0
                                               !! unless a time column says otherwise)
        integer :: fmt = RECORD_AUTO           !! the format actually read (never AUTO after a read)
        character(len=:), allocatable :: name  !! file name without directory and extension
        character(len=:), allocatable :: title !! AT2: line 2 of the header; text formats: the
                                               !! first comment line without '#'; else ''
    end type record_t

    character(len=*), parameter :: LF = achar(10), CR = achar(13), TAB = achar(9)

    !> Exact powers of ten (10**22 is the largest exactly representable one).
    real(dp), parameter :: P10(0:22) = [1.0e0_dp, 1.0e1_dp, 1.0e2_dp, 1.0e3_dp, 1.0e4_dp, &
        1.0e5_dp, 1.0e6_dp, 1.0e7_dp, 1.0e8_dp, 1.0e9_dp, 1.0e10_dp, 1.0e11_dp, 1.0e12_dp, &
        1.0e13_dp, 1.0e14_dp, 1.0e15_dp, 1.0e16_dp, 1.0e17_dp, 1.0e18_dp, 1.0e19_dp, &
        1.0e20_dp, 1.0e21_dp, 1.0e22_dp]

    !> Results of parse_real.
    integer, parameter :: NUM_OK = 0, NUM_INVALID = 1, NUM_RANGE = 2

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

    !> Read an accelerogram file (formats in the module notes) into `rec`, in g.
    !>
    !> stat = SEISPULSE_IO when the file cannot be opened or read
    !> ("<path>: cannot open: <system message>"), SEISPULSE_INVALID_INPUT for a
    !> malformed file or a bad argument (the message names the file and the line, what
    !> was expected and what was found). On error `rec` holds no samples (npts = 0).
    subroutine read_record(path, rec, stat, errmsg, fmt, units, dt)
        character(len=*), intent(in) :: path                  !! the file
        type(record_t), intent(out) :: rec                    !! the record read
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(in), optional :: fmt     !! RECORD_*, default RECORD_AUTO
        integer, intent(in), optional :: units   !! UNITS_* of the values in the file, default
                                                 !! UNITS_G (AT2: the units of header line 3)
        real(dp), intent(in), optional :: dt     !! time step (s); required for RECORD_COLUMN;
                                                 !! <= 0 or absent = not given
        type(text_t) :: txt
        integer :: want, units_in
        real(dp) :: dt_in

        stat = SEISPULSE_SUCCESS
        allocate(rec%accel(0))
        rec%name = base_name(path)
        rec%title = ''

        want = RECORD_AUTO
        if (present(fmt)) want = fmt
        if (want < RECORD_AUTO .or. want > RECORD_TIME_ACCEL) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'fmt = '//int_str(want) &
                           //': must be RECORD_AUTO (0), RECORD_AT2 (1), RECORD_SLAMMER (2), ' &
                           //'RECORD_COLUMN (3) or RECORD_TIME_ACCEL (4)')
            return
        end if
        units_in = 0
        if (present(units)) then
            if (units < UNITS_G .or. units > UNITS_CM_S2) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'units = ' &
                               //int_str(units)//': must be UNITS_G (1), UNITS_M_S2 (2) or ' &
                               //'UNITS_CM_S2 (3)')
                return
            end if
            units_in = units
        end if
        dt_in = 0.0_dp
        if (present(dt)) then
            if (.not. ieee_is_finite(dt)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dt = '//num_str(dt) &
                               //': must be a finite time step > 0 (s), or <= 0 for none')
                return
            end if
            dt_in = max(dt, 0.0_dp)
        end if

        call load_file(path, txt%buf, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        ! UTF-8 byte-order mark EF BB BF
        if (len(txt%buf) >= 3) then
            if (iachar(txt%buf(1:1)) == 239 .and. iachar(txt%buf(2:2)) == 187 .and. &
                iachar(txt%buf(3:3)) == 191) txt%pos = 4
        end if
        if (want == RECORD_AUTO) then
            call detect_format(path, txt, want, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end if

        select case (want)
        case (RECORD_AT2)
            call read_at2(path, txt, units_in, dt_in, rec, stat, errmsg)
        case (RECORD_COLUMN)
            call read_columns(path, txt, 1, .false., units_in, dt_in, rec, stat, errmsg)
        case (RECORD_SLAMMER)
            call read_columns(path, txt, 2, .true., units_in, dt_in, rec, stat, errmsg)
        case default
            call read_columns(path, txt, 2, .false., units_in, dt_in, rec, stat, errmsg)
        end select
        if (stat /= SEISPULSE_SUCCESS) then
            rec%npts = 0
            rec%dt = 0.0_dp
            rec%t0 = 0.0_dp
            rec%fmt = RECORD_AUTO
            if (allocated(rec%accel)) deallocate(rec%accel)
            allocate(rec%accel(0))
            return
        end if
        rec%fmt = want
        rec%npts = size(rec%accel)
        rec%pga = record_pga(rec%accel)
    end subroutine read_record

    !> Peak ground acceleration: max |accel| (0 for an empty array), in the units of accel.
    pure real(dp) function record_pga(accel)
        real(dp), intent(in) :: accel(:)  !! the samples
        integer :: i
        record_pga = 0.0_dp
        do i = 1, size(accel)
            record_pga = max(record_pga, abs(accel(i)))
        end do
    end function record_pga

    !> Scale factor that brings a record of PGA `pga` to `target_pga`.
    !>
    !> factor = target_pga / pga, or with `slammer_rounding` SLAMMER's convention
    !> target_pga / (nint(1000 pga) / 1000): the record's PGA rounded to 3 decimals
    !> (half away from zero), as SLAMMER displays and uses it.
    subroutine pga_scale_factor(pga, target_pga, slammer_rounding, factor, stat, errmsg)
        real(dp), intent(in) :: pga                           !! PGA of the record (g), > 0
        real(dp), intent(in) :: target_pga                    !! wanted PGA (g), > 0
        logical, intent(in) :: slammer_rounding               !! round pga to 0.001 first
        real(dp), intent(out) :: factor                       !! the scale factor
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: p
        factor = 0.0_dp
        stat = SEISPULSE_SUCCESS
        if (.not. finite_positive(pga)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pga = '//num_str(pga) &
                           //': must be a finite number > 0 (g)')
            return
        end if
        if (.not. finite_positive(target_pga)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'target_pga = ' &
                           //num_str(target_pga)//': must be a finite number > 0 (g)')
            return
        end if
        p = pga
        if (slammer_rounding) then
            ! anint, not nint: no integer overflow for a huge pga
            p = anint(pga * 1000.0_dp) / 1000.0_dp
            if (.not. p > 0.0_dp) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pga = '//num_str(pga) &
                               //': rounds to 0.000 g, SLAMMER scaling impossible')
                return
            end if
        end if
        factor = target_pga / p
        if (.not. ieee_is_finite(factor)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'target_pga = ' &
                           //num_str(target_pga)//': target_pga / pga overflows')
            factor = 0.0_dp
        end if
    end subroutine pga_scale_factor

    !> Ground velocity and displacement of a record, exact for an acceleration that is
    !> linear between samples and at rest at the first sample (v = d = 0 there):
    !>     vel(i+1) = vel(i) + g dt (a_i + a_{i+1}) / 2
    !>     disp(i+1) = disp(i) + vel(i) dt + g dt^2 (2 a_i + a_{i+1}) / 6
    !> With accel in g and g in m/s^2, vel is in m/s and disp in m.
    subroutine ground_motion(accel, dt, g, vel, disp, stat, errmsg)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (g)
        real(dp), intent(in) :: dt                            !! time step (s), > 0
        real(dp), intent(in) :: g                             !! gravity (m/s^2), > 0
        real(dp), intent(out) :: vel(:)                       !! velocity (m/s), size(accel)
        real(dp), intent(out) :: disp(:)                      !! displacement (m), size(accel)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: i, n
        real(dp) :: h1, h2
        stat = SEISPULSE_SUCCESS
        n = size(accel)
        if (size(vel) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'vel: size '//int_str(size(vel)) &
                           //', must be the size of accel ('//int_str(n)//')')
            return
        end if
        if (size(disp) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'disp: size ' &
                           //int_str(size(disp))//', must be the size of accel (' &
                           //int_str(n)//')')
            return
        end if
        vel(:) = 0.0_dp
        disp(:) = 0.0_dp
        if (.not. finite_positive(dt)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dt = '//num_str(dt) &
                           //': must be a finite time step > 0 (s)')
            return
        end if
        if (.not. finite_positive(g)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//num_str(g) &
                           //': must be a finite number > 0 (m/s^2)')
            return
        end if
        do i = 1, n
            if (.not. ieee_is_finite(accel(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel('//int_str(i) &
                               //') = '//num_str(accel(i))//': must be a finite number')
                return
            end if
        end do
        h1 = g * dt / 2.0_dp
        h2 = g * dt * dt / 6.0_dp
        do i = 1, n - 1
            vel(i + 1) = vel(i) + h1 * (accel(i) + accel(i + 1))
            disp(i + 1) = disp(i) + vel(i) * dt + h2 * (2.0_dp * accel(i) + accel(i + 1))
        end do
        if (n > 0) then
            if (.not. (ieee_is_finite(vel(n)) .and. ieee_is_finite(disp(n)))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel, dt, g: the ' &
                               //'velocity or displacement overflows')
            end if
        end if
    end subroutine ground_motion

    !> Name of a RECORD_* code: 'auto', 'at2', 'slammer', 'column', 'time_accel'
    !> ('unknown' otherwise).
    pure function record_format_name(code) result(name)
        integer, intent(in) :: code  !! a RECORD_* code
        character(len=:), allocatable :: name
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
    end function record_format_name

    !> Name of a UNITS_* code: 'g', 'm/s2', 'cm/s2' ('unknown' otherwise).
    pure function record_units_name(code) result(name)
        integer, intent(in) :: code  !! a UNITS_* code
        character(len=:), allocatable :: name
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
    end function record_units_name

    ! ------------------------------------------------------------------------------
    ! The file and its lines
    ! ------------------------------------------------------------------------------

    !> The whole file as one string (stream access: any line length, any line end).
    subroutine load_file(path, buf, stat, errmsg)
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
        if (nbytes < 0 .or. nbytes > int(huge(1), int64)) then
            close(u)
            call set_error(stat, errmsg, SEISPULSE_IO, path//': cannot read: the size of ' &
                           //'the file is unknown or above 2 GiB')
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
    end subroutine load_file

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
        character(len=:), allocatable :: text
        integer :: a, b
        a = verify(line, ' '//TAB//'#')
        if (a == 0) then
            text = ''
            return
        end if
        b = verify(line, ' '//TAB//',', back=.true.)
        if (b < a) then
            text = ''
        else
            text = line(a:b)
        end if
    end function comment_text

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
    ! Numbers
    ! ------------------------------------------------------------------------------

    !> A decimal number token [+-]digits[.digits][(e|E|d|D)[+-]digits] (also .5 and 5.)
    !> to double precision, correctly rounded. code: NUM_OK, NUM_INVALID (not of that
    !> form), NUM_RANGE (|x| >= 1e308: out of the range of double precision).
    subroutine parse_real(tok, x, code)
        character(len=*), intent(in) :: tok
        real(dp), intent(out) :: x
        integer, intent(out) :: code
        integer :: i, n, d, nint_d, nfrac_d, nsig, expo, e10, lead
        integer(int64) :: m
        logical :: neg, eneg
        integer :: ios
        x = 0.0_dp
        code = NUM_INVALID
        n = len(tok)
        if (n == 0) return
        i = 1
        neg = .false.
        if (tok(1:1) == '+' .or. tok(1:1) == '-') then
            neg = tok(1:1) == '-'
            i = 2
        end if
        m = 0_int64
        nsig = 0
        nint_d = 0
        nfrac_d = 0
        do while (i <= n)
            d = digit(tok(i:i))
            if (d < 0) exit
            call add_digit(d)
            nint_d = nint_d + 1
            i = i + 1
        end do
        if (i <= n) then
            if (tok(i:i) == '.') then
                i = i + 1
                do while (i <= n)
                    d = digit(tok(i:i))
                    if (d < 0) exit
                    call add_digit(d)
                    nfrac_d = nfrac_d + 1
                    i = i + 1
                end do
            end if
        end if
        if (nint_d + nfrac_d == 0) return
        expo = 0
        if (i <= n) then
            if (scan(tok(i:i), 'eEdD') == 0) return
            i = i + 1
            eneg = .false.
            if (i <= n) then
                if (tok(i:i) == '+' .or. tok(i:i) == '-') then
                    eneg = tok(i:i) == '-'
                    i = i + 1
                end if
            end if
            if (i > n) return
            do while (i <= n)
                d = digit(tok(i:i))
                if (d < 0) return
                if (expo < 100000) expo = 10 * expo + d
                i = i + 1
            end do
            if (eneg) expo = -expo
        end if
        code = NUM_OK
        if (nsig == 0) then
            ! all digits zero
            if (neg) x = -x
            return
        end if
        ! value = (digits as an integer) 10^e10; leading digit at 10^lead
        e10 = expo - nfrac_d
        lead = e10 + nsig - 1
        if (lead >= 308) then
            code = NUM_RANGE
            return
        end if
        if (lead < -400) then
            ! far below the smallest subnormal: rounds to zero
            if (neg) x = -x
            return
        end if
        if (nsig <= 15 .and. abs(e10) <= 22) then
            ! m < 10^15 < 2^53 and 10^|e10| are exact: one correctly rounded operation
            if (e10 >= 0) then
                x = real(m, dp) * P10(e10)
            else
                x = real(m, dp) / P10(-e10)
            end if
        else
            read(tok, *, iostat=ios) x
            if (ios /= 0) then
                code = NUM_RANGE
                x = 0.0_dp
                return
            end if
            if (.not. ieee_is_finite(x)) then
                code = NUM_RANGE
                x = 0.0_dp
                return
            end if
            x = abs(x)
        end if
        if (neg) x = -x

    contains

        subroutine add_digit(dd)
            integer, intent(in) :: dd
            if (nsig == 0 .and. dd == 0) return
            nsig = nsig + 1
            if (nsig <= 15) m = 10_int64 * m + int(dd, int64)
        end subroutine add_digit

    end subroutine parse_real

    pure integer function digit(c)
        character, intent(in) :: c
        digit = iachar(c) - iachar('0')
        if (digit < 0 .or. digit > 9) digit = -1
    end function digit

    !> Parse one value of a data line; on failure set the error (file, line, token).
    subroutine value_at(path, lnum, tok, x, stat, errmsg)
        character(len=*), intent(in) :: path, tok
        integer, intent(in) :: lnum
        real(dp), intent(out) :: x
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: code
        stat = SEISPULSE_SUCCESS
        call parse_real(tok, x, code)
        if (code == NUM_INVALID) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, lnum) &
                           //'non-numeric value '//quote(tok)//' (expected a number such ' &
                           //'as -1.25E-03)')
        else if (code == NUM_RANGE) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, lnum) &
                           //'value '//quote(tok)//' is out of the range of double ' &
                           //'precision (|x| < 1e308 expected)')
        end if
    end subroutine value_at

    ! ------------------------------------------------------------------------------
    ! Formats
    ! ------------------------------------------------------------------------------

    !> RECORD_AUTO: the format of the file (see the module notes). The cursor of
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
                                   //'found '//quote(line))
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
    subroutine read_at2(path, txt, units_in, dt_in, rec, stat, errmsg)
        character(len=*), intent(in) :: path
        type(text_t), intent(inout) :: txt
        integer, intent(in) :: units_in    !! 0: not given
        real(dp), intent(in) :: dt_in      !! 0: not given
        type(record_t), intent(inout) :: rec
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
                    rec%title = trim(adjustl(line))
                case (3)
                    call at2_units(upper(line), units_hdr, ok3)
                    if (ok3 < 0) then
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                       at_line(path, 3)//'not an acceleration record (' &
                                       //'expected '//LINE3//', found '//quote(line)//')')
                        return
                    else if (ok3 == 0) then
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                       at_line(path, 3)//'expected the quantity and units ' &
                                       //'as '//LINE3//', found '//quote(line))
                        return
                    end if
                case (4)
                    call at2_npts_dt(line, npts, dt_hdr, stat, errmsg, path)
                    if (stat /= SEISPULSE_SUCCESS) return
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
        allocate(vals(cap))
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
                                       //'here ('//quote(line(ts:te))//')')
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
        call to_g(vals, units_use, path, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call move_alloc(vals, rec%accel)
        rec%dt = dt_hdr
        rec%t0 = 0.0_dp
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
                           //AT2_LINE4_FORMS//', found '//quote(line))
        end subroutine bad4

        logical function set_npts(tok)
            character(len=*), intent(in) :: tok
            integer :: i
            set_npts = .false.
            if (verify(tok, '0123456789') /= 0 .or. len(tok) > 9) then
                call bad4('NPTS = '//quote(tok)//' is not a positive integer')
                return
            end if
            npts = 0
            do i = 1, len(tok)
                npts = 10 * npts + digit(tok(i:i))
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
                call bad4('DT = '//quote(tok)//' is not a number')
                dt = 0.0_dp
            else if (.not. dt > 0.0_dp) then
                call bad4('DT = '//quote(tok)//' must be > 0')
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
    subroutine read_columns(path, txt, ncol, slammer, units_in, dt_in, rec, stat, errmsg)
        character(len=*), intent(in) :: path
        type(text_t), intent(inout) :: txt
        integer, intent(in) :: ncol
        logical, intent(in) :: slammer
        integer, intent(in) :: units_in
        real(dp), intent(in) :: dt_in
        type(record_t), intent(inout) :: rec
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), allocatable :: vals(:), times(:)
        integer, allocatable :: lines(:)
        integer :: cap, n, nf, p, ts, te, i, units_use
        logical :: after_comma, empty, titled
        real(dp) :: x, t, dt, expect

        stat = SEISPULSE_SUCCESS
        if (ncol == 1 .and. .not. dt_in > 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': dt: a single-column ' &
                           //'file has no time step; give dt')
            return
        end if
        cap = count_lines(txt%buf)
        allocate(vals(cap))
        if (ncol == 2) allocate(times(cap), lines(cap))
        n = 0
        titled = .false.
        do while (next_line(txt))
            associate (line => txt%buf(txt%ls:txt%le))
                if (slammer .and. txt%line <= 2 .and. .not. is_comment(line)) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, txt%line) &
                                   //"expected a '#' comment line (a SLAMMER file starts " &
                                   //'with two), found '//quote(line))
                    return
                end if
                if (is_comment(line)) then
                    if (.not. titled) rec%title = comment_text(line)
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
                                       //quote(line))
                    else
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                       at_line(path, txt%line)//'expected 2 values (time, ' &
                                       //'acceleration), found '//int_str(nf)//': '//quote(line))
                    end if
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
            rec%t0 = times(1)
        else
            dt = dt_in
            rec%t0 = 0.0_dp
        end if

        units_use = UNITS_G
        if (units_in /= 0) units_use = units_in
        call to_g(vals(1:n), units_use, path, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        deallocate(rec%accel)
        if (n == cap) then
            call move_alloc(vals, rec%accel)
        else
            allocate(rec%accel(n), source=vals(1:n))
        end if
        rec%dt = dt
    end subroutine read_columns

    !> Values in `units` to g (in place); a non-finite result is an error.
    subroutine to_g(a, units, path, stat, errmsg)
        real(dp), intent(inout) :: a(:)
        integer, intent(in) :: units
        character(len=*), intent(in) :: path
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: i
        stat = SEISPULSE_SUCCESS
        select case (units)
        case (UNITS_M_S2)
            a(:) = a(:) / STANDARD_GRAVITY
        case (UNITS_CM_S2)
            a(:) = a(:) / (100.0_dp * STANDARD_GRAVITY)
        end select
        do i = 1, size(a)
            if (.not. ieee_is_finite(a(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': value number ' &
                               //int_str(i)//' is not finite after conversion to g')
                return
            end if
        end do
    end subroutine to_g

    subroutine empty_value(path, lnum, line, stat, errmsg)
        character(len=*), intent(in) :: path, line
        integer, intent(in) :: lnum
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, at_line(path, lnum)//'empty ' &
                       //'value (a leading or trailing comma, or two commas in a row): ' &
                       //quote(line))
    end subroutine empty_value

    ! ------------------------------------------------------------------------------
    ! Small helpers
    ! ------------------------------------------------------------------------------

    !> "line a" or "lines a-b".
    pure function line_range(a, b) result(s)
        integer, intent(in) :: a, b
        character(len=:), allocatable :: s
        if (b > a) then
            s = 'lines '//int_str(a)//'-'//int_str(b)
        else
            s = 'line '//int_str(a)
        end if
    end function line_range

    pure function at_line(path, lnum) result(s)
        character(len=*), intent(in) :: path
        integer, intent(in) :: lnum
        character(len=:), allocatable :: s
        s = path//', line '//int_str(lnum)//': '
    end function at_line

    !> The file name of a path, without the directory.
    pure function base_with_ext(path) result(b)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: b
        integer :: k
        k = scan(path, '/\', back=.true.)
        b = path(k + 1:len_trim(path))
    end function base_with_ext

    !> The file name without the directory and the last extension (a leading dot is
    !> part of the name: '.hidden' stays).
    pure function base_name(path) result(b)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: b
        integer :: k
        b = base_with_ext(path)
        k = index(b, '.', back=.true.)
        if (k > 1) b = b(1:k - 1)
    end function base_name

end module seispulse_records
