!> Numbers and text for messages: one place that decides how a value reads in an
!> error message or a table note.
module seispulse_format
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use, intrinsic :: iso_fortran_env, only: int64
    use seispulse_kinds, only: dp
    implicit none
    private

    public :: real_str, int_str, num_str, quote, upper, name_of, code_of
    public :: g_str, shortest_str

    !> longest quoted text in a message, in bytes (longer text is cut, with '...')
    integer, parameter :: QUOTE_MAX = 40

contains

    !> A real number as short text for messages: 15 significant digits without
    !> trailing zeros ("-1.0", "0.6", "1.0E+300", "NaN", "Infinity").
    pure function real_str(x) result(text)
        real(dp), intent(in) :: x  !! the number
        character(len=:), allocatable :: text
        character(len=40) :: buf
        integer :: e, k
        write(buf, '(g0.15)') x
        buf = adjustl(buf)
        e = scan(buf, 'Ee')
        if (e == 0) e = len_trim(buf) + 1
        if (index(buf(1:e - 1), '.') > 0) then
            k = e - 1
            do while (k > 1)
                if (buf(k:k) /= '0' .or. buf(k - 1:k - 1) == '.') exit
                k = k - 1
            end do
            text = buf(1:k)//trim(buf(e:))
        else
            text = trim(buf)
        end if
    end function real_str

    !> An integer as text for messages ("42", "-1").
    pure function int_str(i) result(text)
        integer, intent(in) :: i  !! the number
        character(len=:), allocatable :: text
        character(len=16) :: buf
        write(buf, '(i0)') i
        text = trim(buf)
    end function int_str

    !> A number for messages: fixed notation with up to 15 significant digits for
    !> 1e-5 <= |x| < 1e15 ("0.01", "133.895", "-0.35"), real_str's form otherwise.
    pure function num_str(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=64) :: buf
        integer :: nd, k
        if (.not. ieee_is_finite(x)) then
            s = real_str(x)
            return
        end if
        if (.not. abs(x) > 0.0_dp) then
            s = '0.0'
            return
        end if
        if (abs(x) < 1.0e-5_dp .or. abs(x) >= 1.0e15_dp) then
            s = real_str(x)
            return
        end if
        nd = max(1, 14 - floor(log10(abs(x))))
        write(buf, '(f0.'//int_str(nd)//')') x
        buf = adjustl(buf)
        k = len_trim(buf)
        do while (k > 2)
            if (buf(k:k) /= '0' .or. buf(k - 1:k - 1) == '.') exit
            k = k - 1
        end do
        s = buf(1:k)
        if (s(1:1) == '.') then
            s = '0'//s
        else if (len(s) > 1) then
            if (s(1:2) == '-.') s = '-0'//s(2:)
        end if
    end function num_str

    !> x with `digits` significant digits as C's printf("%.<digits>g") writes it: the
    !> decimal exponent X of the rounded value gives fixed notation for -4 <= X < digits
    !> ("0.05", "123457", "0.000123"), else E notation ("1.5e-05", "1.23457e+08");
    !> trailing zeros and a trailing point dropped ("3", "-0"); "nan", "inf", "-inf".
    pure function g_str(x, digits) result(s)
        real(dp), intent(in) :: x        !! the number
        integer, intent(in) :: digits    !! significant digits, 1..17 (clamped to that)
        character(len=:), allocatable :: s
        character(len=17) :: d
        integer :: p, ex
        logical :: neg, is_special
        call special(x, s, is_special)
        if (is_special) return
        p = min(max(digits, 1), 17)
        call decimal_digits(x, p, d, ex, neg)
        if (ex >= -4 .and. ex < p) then
            s = fixed_text(d(1:p), ex, neg, .false.)
        else
            s = sci_text(d(1:p), ex, neg)
        end if
    end function g_str

    !> The shortest decimal text that reads back to exactly x (at most 17 significant
    !> digits), laid out as Python's repr(float): fixed notation for decimal exponents
    !> -4..15 with at least one digit after the point ("0.1", "100.0", "-0.0",
    !> "123456.5"), else E notation ("1e-05", "5e-324", "1.7976931348623157e+308");
    !> "nan", "inf", "-inf". The digits: x rounded to 15, 16, then 17 significant digits,
    !> the first that reads back to x (15 digits with trailing zeros dropped is the
    !> shortest text whenever one of at most 15 digits exists).
    function shortest_str(x) result(s)
        real(dp), intent(in) :: x        !! the number
        character(len=:), allocatable :: s
        character(len=17) :: d
        integer :: p, ex, k
        logical :: neg, is_special
        call special(x, s, is_special)
        if (is_special) return
        do p = 15, 17
            call decimal_digits(x, p, d, ex, neg)
            if (p == 17) exit
            if (reads_back(d(1:p), ex, neg, x)) exit
        end do
        k = p
        do while (k > 1)
            if (d(k:k) /= '0') exit
            k = k - 1
        end do
        if (ex >= -4 .and. ex < 16) then
            s = fixed_text(d(1:k), ex, neg, .true.)
        else
            s = sci_text(d(1:k), ex, neg)
        end if
    end function shortest_str

    !> "nan", "inf" or "-inf" for a number that is not finite (then is_special).
    pure subroutine special(x, s, is_special)
        real(dp), intent(in) :: x
        character(len=:), allocatable, intent(inout) :: s
        logical, intent(out) :: is_special
        is_special = .not. ieee_is_finite(x)
        if (.not. is_special) return
        if (ieee_is_nan(x)) then
            s = 'nan'
        else if (x > 0.0_dp) then
            s = 'inf'
        else
            s = '-inf'
        end if
    end subroutine special

    !> x (finite) rounded to p significant digits (round to nearest): the digits d(1:p)
    !> and the decimal exponent ex, x = +-d(1).d(2:p) 10^ex (0 for a zero), and the sign.
    pure subroutine decimal_digits(x, p, d, ex, neg)
        real(dp), intent(in) :: x
        integer, intent(in) :: p              !! 1..17
        character(len=17), intent(out) :: d
        integer, intent(out) :: ex
        logical, intent(out) :: neg
        character(len=12), parameter :: fmts(17) = [character(len=12) :: '(es26.0e3)', &
            '(es26.1e3)', '(es26.2e3)', '(es26.3e3)', '(es26.4e3)', '(es26.5e3)', &
            '(es26.6e3)', '(es26.7e3)', '(es26.8e3)', '(es26.9e3)', '(es26.10e3)', &
            '(es26.11e3)', '(es26.12e3)', '(es26.13e3)', '(es26.14e3)', '(es26.15e3)', &
            '(es26.16e3)']
        character(len=26) :: buf
        integer :: i, n, e
        write(buf, fmts(p)) x
        ! buf: blanks, optional '-', digit, '.', p - 1 digits, 'E', sign, 3 digits
        e = 26 - 4
        neg = .false.
        d = ' '
        n = 0
        do i = 1, e - 1
            select case (buf(i:i))
            case ('-')
                neg = .true.
            case ('0':'9')
                n = n + 1
                d(n:n) = buf(i:i)
            end select
        end do
        ex = 100 * (iachar(buf(e + 2:e + 2)) - 48) + 10 * (iachar(buf(e + 3:e + 3)) - 48) &
             + iachar(buf(e + 4:e + 4)) - 48
        if (buf(e + 1:e + 1) == '-') ex = -ex
        if (verify(d(1:p), '0') == 0) ex = 0
    end subroutine decimal_digits

    !> Whether +-0.d 10^(ex+1) reads back (as a Fortran read does) to exactly x.
    logical function reads_back(d, ex, neg, x)
        character(len=*), intent(in) :: d
        integer, intent(in) :: ex
        logical, intent(in) :: neg
        real(dp), intent(in) :: x
        character(len=32) :: buf
        real(dp) :: y
        integer :: ios
        write(buf, '(a, "0.", a, "E", i0)') merge('-', ' ', neg), d, ex + 1
        read(buf, '(f32.0)', iostat=ios) y
        ! the same bits (a zero keeps its sign)
        reads_back = ios == 0 .and. transfer(y, 0_int64) == transfer(x, 0_int64)
    end function reads_back

    !> Fixed notation of +-d(1).d(2:) 10^ex (-4 <= ex): trailing zeros of the fraction
    !> dropped, then the point too unless `point_zero` (then ".0" stays, as in "100.0").
    pure function fixed_text(d, ex, neg, point_zero) result(s)
        character(len=*), intent(in) :: d
        integer, intent(in) :: ex
        logical, intent(in) :: neg, point_zero
        character(len=:), allocatable :: s
        character(len=:), allocatable :: ip, fp
        integer :: k
        if (ex >= 0) then
            if (ex + 1 >= len(d)) then
                ip = d//repeat('0', ex + 1 - len(d))
                fp = ''
            else
                ip = d(1:ex + 1)
                fp = d(ex + 2:)
            end if
        else
            ip = '0'
            fp = repeat('0', -ex - 1)//d
        end if
        k = len(fp)
        do while (k > 0)
            if (fp(k:k) /= '0') exit
            k = k - 1
        end do
        if (k > 0) then
            s = ip//'.'//fp(1:k)
        else if (point_zero) then
            s = ip//'.0'
        else
            s = ip
        end if
        if (neg) s = '-'//s
    end function fixed_text

    !> E notation of +-d(1).d(2:) 10^ex: trailing zeros dropped, at least two exponent
    !> digits ("1.5e-05", "5e-324").
    pure function sci_text(d, ex, neg) result(s)
        character(len=*), intent(in) :: d
        integer, intent(in) :: ex
        logical, intent(in) :: neg
        character(len=:), allocatable :: s
        character(len=8) :: eb
        integer :: k
        k = len(d)
        do while (k > 1)
            if (d(k:k) /= '0') exit
            k = k - 1
        end do
        if (k > 1) then
            s = d(1:1)//'.'//d(2:k)
        else
            s = d(1:1)
        end if
        write(eb, '(i2.2)') abs(ex)
        if (abs(ex) >= 100) write(eb, '(i3)') abs(ex)
        s = s//'e'//merge('-', '+', ex < 0)//trim(adjustl(eb))
        if (neg) s = '-'//s
    end function sci_text

    !> 'text' for a message, cut to QUOTE_MAX bytes (at a UTF-8 character boundary)
    !> with '...' when longer.
    pure function quote(text) result(s)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: s
        integer :: k
        if (len(text) <= QUOTE_MAX) then
            s = "'"//text//"'"
            return
        end if
        ! cut at a UTF-8 character boundary: not before a continuation byte 10xxxxxx
        k = QUOTE_MAX
        do while (k > 1)
            if (iachar(text(k + 1:k + 1)) < 128 .or. iachar(text(k + 1:k + 1)) >= 192) exit
            k = k - 1
        end do
        s = "'"//text(1:k)//"...'"
    end function quote

    !> s in upper case (ASCII letters only).
    pure function upper(s) result(u)
        character(len=*), intent(in) :: s
        character(len=len(s)) :: u
        integer :: i, c
        do i = 1, len(s)
            c = iachar(s(i:i))
            if (c >= iachar('a') .and. c <= iachar('z')) then
                u(i:i) = achar(c - 32)
            else
                u(i:i) = s(i:i)
            end if
        end do
    end function upper

    !> The name of a code in a table of names: table(code), '?' outside the table.
    pure function name_of(code, table) result(name)
        integer, intent(in) :: code                !! 1-based index
        character(len=*), intent(in) :: table(:)   !! the names
        character(len=:), allocatable :: name
        if (code >= 1 .and. code <= size(table)) then
            name = trim(table(code))
        else
            name = '?'
        end if
    end function name_of

    !> The code of a name in a table of names: its index, 0 if absent.
    pure integer function code_of(name, table)
        character(len=*), intent(in) :: name       !! the name (trailing blanks ignored)
        character(len=*), intent(in) :: table(:)   !! the names
        integer :: k
        code_of = 0
        do k = 1, size(table)
            if (trim(table(k)) == trim(name)) code_of = k
        end do
    end function code_of

end module seispulse_format
