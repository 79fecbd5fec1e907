!> Numbers and text for messages: one place that decides how a value reads in an
!> error message or a table note.
module seispulse_format
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: iso_c_binding, only: c_char, c_ptr, c_double, c_null_char, c_null_ptr
    use seispulse_kinds, only: dp
    implicit none
    private

    public :: real_str, int_str, num_str, quote, upper, name_of, code_of
    public :: g_str, shortest_str, format_reals, NUM_LEN
    public :: real_str_len, int_str_len, num_str_len, quote_len, name_len

    ! Every function here that returns text gives its length by a specification
    ! expression (a pure *_len function of the same arguments), never a deferred length:
    ! gfortran keeps the length of a deferred-length result in a static variable of the
    ! caller, which two threads at the same call site would share.

    !> longest text of a number from g_str, shortest_str, format_reals
    !> ("-1.2345678901234567e-308")
    integer, parameter :: NUM_LEN = 24

    interface
        ! C's strtod: text to double, correctly rounded (declared pure: its only side
        ! effect, errno on overflow or underflow, is not read here)
        pure function c_strtod(text, endptr) bind(c, name='strtod') result(x)
            import :: c_char, c_ptr, c_double
            character(kind=c_char), intent(in) :: text(*)
            type(c_ptr), value, intent(in) :: endptr
            real(c_double) :: x
        end function c_strtod
    end interface

    !> longest quoted text in a message, in bytes (longer text is cut, with '...')
    integer, parameter :: QUOTE_MAX = 40

contains

    !> A real number as short text for messages: 15 significant digits without
    !> trailing zeros ("-1.0", "0.6", "1.0E+300", "NaN", "Infinity").
    pure function real_str(x) result(text)
        real(dp), intent(in) :: x  !! the number
        character(len=real_str_len(x)) :: text
        text = real_text(x)
    end function real_str

    !> The length of real_str(x).
    pure integer function real_str_len(x)
        real(dp), intent(in) :: x  !! the number
        real_str_len = len_trim(real_text(x))
    end function real_str_len

    !> real_str(x) padded with blanks.
    pure function real_text(x) result(text)
        real(dp), intent(in) :: x
        character(len=40) :: text
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
    end function real_text

    !> An integer as text for messages ("42", "-1").
    pure function int_str(i) result(text)
        integer, intent(in) :: i  !! the number
        character(len=int_str_len(i)) :: text
        character(len=16) :: buf
        write(buf, '(i0)') i
        text = buf
    end function int_str

    !> The length of int_str(i).
    pure integer function int_str_len(i)
        integer, intent(in) :: i  !! the number
        character(len=16) :: buf
        write(buf, '(i0)') i
        int_str_len = len_trim(buf)
    end function int_str_len

    !> A number for messages: fixed notation with up to 15 significant digits for
    !> 1e-5 <= |x| < 1e15 ("0.01", "133.895", "-0.35"), real_str's form otherwise.
    pure function num_str(x) result(s)
        real(dp), intent(in) :: x  !! the number (any unit; the caller writes the unit)
        character(len=num_str_len(x)) :: s
        s = num_text(x)
    end function num_str

    !> The length of num_str(x).
    pure integer function num_str_len(x)
        real(dp), intent(in) :: x  !! the number
        num_str_len = len_trim(num_text(x))
    end function num_str_len

    !> num_str(x) padded with blanks.
    pure function num_text(x) result(s)
        real(dp), intent(in) :: x
        character(len=64) :: s
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
        if (buf(1:1) == '.') then
            s = '0'//buf(1:k)
        else if (k > 1 .and. buf(1:2) == '-.') then
            s = '-0'//buf(2:k)
        else
            s = buf(1:k)
        end if
    end function num_text

    !> x with `digits` significant digits as C's printf("%.<digits>g") writes it: the
    !> decimal exponent X of the correctly rounded value gives fixed notation for
    !> -4 <= X < digits ("0.05", "123457", "0.000123"), else E notation ("1.5e-05",
    !> "1.23457e+08"); trailing zeros and a trailing point dropped ("3", "-0"); an exact
    !> tie rounds to even digits, as C does ("0.12" for 0.125 and 2 digits); "nan",
    !> "inf", "-inf". format_reals does the same for many numbers at a time.
    pure function g_str(x, digits) result(s)
        real(dp), intent(in) :: x        !! the number
        integer, intent(in) :: digits    !! significant digits, 1..17 (clamped to that)
        character(len=len_trim(g_text(x, min(max(digits, 1), 17)))) :: s
        s = g_text(x, min(max(digits, 1), 17))
    end function g_str

    !> The text of x by format_reals with `digits` (0 or 1..17), padded with blanks.
    pure function g_text(x, digits) result(s)
        real(dp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=NUM_LEN) :: s
        character(len=NUM_LEN) :: t(1)
        call format_reals([x], digits, t)
        s = t(1)
    end function g_text

    !> The shortest decimal text that reads back to exactly x (at most 17 significant
    !> digits; of the shortest, the nearest to x), laid out as Python's repr(float):
    !> fixed notation for decimal exponents -4..15 with at least one digit after the point
    !> ("0.1", "100.0", "-0.0", "123456.5"), else E notation ("1e-05", "5e-324",
    !> "1.7976931348623157e+308"); "nan", "inf", "-inf". format_reals does the same for
    !> many numbers at a time.
    pure function shortest_str(x) result(s)
        real(dp), intent(in) :: x        !! the number
        character(len=len_trim(g_text(x, 0))) :: s
        s = g_text(x, 0)
    end function shortest_str

    !> The texts of x(:) as g_str (digits 1..17) or shortest_str (digits 0) writes them,
    !> left-adjusted in texts(:) (at least NUM_LEN = 24 characters each); with digits2
    !> and texts2, also in the second setting (one decimal conversion serves both).
    !> Each number is converted once to 24 significant digits (one formatted write per
    !> CHUNK numbers); that is rounded to the digits asked for (exact unless the digits
    !> dropped read 5000..., then the number is converted again at those digits), and a
    !> shortest text is the first of 15, 16 (also the next 16-digit value up for a
    !> power of two) and 17 digits that reads back to x (strtod, correctly rounded).
    !> With 15 digits, trailing zeros dropped give the shortest text whenever one of at
    !> most 15 digits exists (a decimal of <= 15 digits survives the round trip to a
    !> normal double; a subnormal x tries 1, 2, ... digits).
    pure subroutine format_reals(x, digits, texts, digits2, texts2)
        real(dp), intent(in) :: x(:)                        !! the numbers
        integer, intent(in) :: digits                       !! 0 (shortest) or 1..17
        character(len=*), intent(out) :: texts(:)           !! size(x) texts
        integer, intent(in), optional :: digits2   !! a second setting, 0 or 1..17 (absent: none)
        character(len=*), intent(out), optional :: texts2(:)  !! its texts (with digits2 only)
        integer, parameter :: CHUNK = 64, FW = 32
        character(len=CHUNK * FW) :: buf
        integer :: i0, n, k, i
        do i0 = 1, size(x), CHUNK
            n = min(CHUNK, size(x) - i0 + 1)
            ! 24 significant digits: " -d.ddd...dE-eee" in FW characters per number
            write(buf, '(64es32.23e3)') x(i0:i0 + n - 1)
            do k = 1, n
                i = i0 + k - 1
                texts(i) = one_text(x(i), buf((k - 1) * FW + 1:k * FW), digits)
                if (present(texts2) .and. present(digits2)) texts2(i) = one_text(x(i), &
                    buf((k - 1) * FW + 1:k * FW), digits2)
            end do
        end do
    end subroutine format_reals

    !> The text of x from its 24-digit field f (es32.23e3): %g with p digits, or the
    !> shortest round-trip text (p = 0).
    pure function one_text(x, f, p) result(s)
        real(dp), intent(in) :: x
        character(len=32), intent(in) :: f
        integer, intent(in) :: p
        character(len=NUM_LEN) :: s
        character(len=24) :: d24
        character(len=17) :: d
        integer :: e24, ex, q, q0, k
        logical :: neg
        if (.not. ieee_is_finite(x)) then
            if (ieee_is_nan(x)) then
                s = 'nan'
            else if (x > 0.0_dp) then
                s = 'inf'
            else
                s = '-inf'
            end if
            return
        end if
        neg = f(2:2) == '-'
        d24 = f(3:3)//f(5:27)
        e24 = 100 * (iachar(f(30:30)) - 48) + 10 * (iachar(f(31:31)) - 48) &
              + iachar(f(32:32)) - 48
        if (f(29:29) == '-') e24 = -e24
        if (verify(d24, '0') == 0) e24 = 0
        if (p > 0) then
            q = min(p, 17)
            call round_digits(x, d24, e24, q, d, ex)
            if (ex >= -4 .and. ex < q) then
                s = fixed_text(d(1:q), ex, neg, .false.)
            else
                s = sci_text(d(1:q), ex, neg)
            end if
            return
        end if
        ! a subnormal number has fewer significant bits: its shortest text may be
        ! shorter than its 15 digits with trailing zeros dropped
        q0 = 15
        if (abs(x) < tiny(x)) q0 = 1
        do q = q0, 17
            call round_digits(x, d24, e24, q, d, ex)
            if (q == 17) exit
            if (reads_back(d(1:q), ex, neg, x)) exit
            if (q == 16 .and. is_power_of_two(x)) then
                ! the rounding interval reaches twice as far up as down: the next
                ! 16-digit value up may read back when the nearest (below) does not
                call next_up(d(1:q), ex)
                if (reads_back(d(1:q), ex, neg, x)) exit
            end if
        end do
        k = significant_len(d(1:q))
        if (ex >= -4 .and. ex < 16) then
            s = fixed_text(d(1:k), ex, neg, .true.)
        else
            s = sci_text(d(1:k), ex, neg)
        end if
    end function one_text

    !> |x| (finite) correctly rounded to p significant digits, d(1:p) and the decimal
    !> exponent ex (|x| = d(1).d(2:p) 10^ex; 0 for a zero), from its 24 digits d24 and
    !> exponent e24. The dropped digits d24(p+1:) decide, unless they read 5000...: the
    !> 24-digit value is itself rounded, so x is converted again at p digits (the
    !> compiler's conversion rounds correctly, an exact tie to even).
    pure subroutine round_digits(x, d24, e24, p, d, ex)
        real(dp), intent(in) :: x
        character(len=24), intent(in) :: d24
        integer, intent(in) :: e24
        integer, intent(in) :: p                  !! 1..17
        character(len=17), intent(out) :: d
        integer, intent(out) :: ex
        character(len=12), parameter :: fmts(17) = [character(len=12) :: '(es32.0e3)', &
            '(es32.1e3)', '(es32.2e3)', '(es32.3e3)', '(es32.4e3)', '(es32.5e3)', &
            '(es32.6e3)', '(es32.7e3)', '(es32.8e3)', '(es32.9e3)', '(es32.10e3)', &
            '(es32.11e3)', '(es32.12e3)', '(es32.13e3)', '(es32.14e3)', '(es32.15e3)', &
            '(es32.16e3)']
        character(len=32) :: f
        integer :: i, n
        d = d24(1:p)
        ex = e24
        if (d24(p + 1:p + 1) == '5' .and. verify(d24(p + 2:), '0') == 0) then
            write(f, fmts(p)) x
            ! f: blanks, optional '-', digit, '.', p - 1 digits, 'E', sign, 3 digits
            n = 0
            do i = 1, 27
                if (f(i:i) >= '0' .and. f(i:i) <= '9') then
                    n = n + 1
                    d(n:n) = f(i:i)
                end if
            end do
            ex = 100 * (iachar(f(30:30)) - 48) + 10 * (iachar(f(31:31)) - 48) &
                 + iachar(f(32:32)) - 48
            if (f(29:29) == '-') ex = -ex
        else if (d24(p + 1:p + 1) >= '5') then
            call next_up(d(1:p), ex)
        end if
        if (verify(d(1:p), '0') == 0) ex = 0
    end subroutine round_digits

    !> d(1).d(2:) 10^ex plus one unit in the last digit (9.99 -> 1.00 and ex + 1).
    pure subroutine next_up(d, ex)
        character(len=*), intent(inout) :: d
        integer, intent(inout) :: ex
        integer :: k
        do k = len(d), 1, -1
            if (d(k:k) /= '9') then
                d(k:k) = achar(iachar(d(k:k)) + 1)
                return
            end if
            d(k:k) = '0'
        end do
        d(1:1) = '1'
        ex = ex + 1
    end subroutine next_up

    !> Whether x is +-2^k (a normal number with a zero fraction): its rounding interval
    !> is narrower below than above.
    pure logical function is_power_of_two(x)
        real(dp), intent(in) :: x
        integer :: e
        is_power_of_two = .false.
        if (.not. abs(x) >= tiny(x)) return
        e = exponent(x)
        is_power_of_two = .not. abs(abs(x) - scale(0.5_dp, e)) > 0.0_dp
    end function is_power_of_two

    !> Whether +-d(1).d(2:) 10^ex reads back (C's strtod, correctly rounded) to x.
    pure logical function reads_back(d, ex, neg, x)
        character(len=*), intent(in) :: d
        integer, intent(in) :: ex
        logical, intent(in) :: neg
        real(dp), intent(in) :: x
        character(len=32) :: t
        real(dp) :: y
        integer :: n
        character(len=17) :: padded
        ! from the largest double plus half its spacing, 1.797693134862315807...e308, a
        ! text reads as an overflow: not x (and strtod would raise the overflow flag)
        reads_back = .false.
        padded = d//repeat('0', 17 - len(d))
        if (ex > 308 .or. (ex == 308 .and. lge(padded, '17976931348623159'))) return
        n = 0
        if (neg) then
            t(1:1) = '-'
            n = 1
        end if
        t(n + 1:n + len(d) + 3) = d(1:1)//'.'//d(2:)//'e'//merge('-', '+', ex < 0)
        n = n + len(d) + 3
        call put_exponent(t, n, ex, 1)
        t(n + 1:n + 1) = c_null_char
        y = c_strtod(t, c_null_ptr)
        ! the same bits (a zero keeps its sign)
        reads_back = transfer(y, 0_int64) == transfer(x, 0_int64)
    end function reads_back

    !> Append the digits of |ex| (< 1000), at least `least` of them ("05" for 5 and 2),
    !> to s(1:n).
    pure subroutine put_exponent(s, n, ex, least)
        character(len=*), intent(inout) :: s
        integer, intent(inout) :: n
        integer, intent(in) :: ex, least
        integer :: e
        e = abs(ex)
        if (e >= 100) then
            s(n + 1:n + 1) = achar(48 + e / 100)
            n = n + 1
        end if
        if (e >= 10 .or. least >= 2) then
            s(n + 1:n + 1) = achar(48 + mod(e / 10, 10))
            n = n + 1
        end if
        s(n + 1:n + 1) = achar(48 + mod(e, 10))
        n = n + 1
    end subroutine put_exponent

    !> The digits d without trailing zeros: their number (at least 1).
    pure integer function significant_len(d)
        character(len=*), intent(in) :: d
        significant_len = len(d)
        do while (significant_len > 1)
            if (d(significant_len:significant_len) /= '0') exit
            significant_len = significant_len - 1
        end do
    end function significant_len

    !> Fixed notation of +-d(1).d(2:) 10^ex (-4 <= ex <= 16): trailing zeros of the
    !> fraction dropped, then the point too unless `point_zero` (then ".0" stays, as in
    !> "100.0").
    pure function fixed_text(d, ex, neg, point_zero) result(s)
        character(len=*), intent(in) :: d
        integer, intent(in) :: ex
        logical, intent(in) :: neg, point_zero
        character(len=NUM_LEN) :: s
        integer :: n, k, nd
        nd = significant_len(d)
        s = merge('-', ' ', neg)
        n = merge(1, 0, neg)
        if (ex >= 0) then
            ! integer part: d(1:ex+1), zero-filled; then the fraction d(ex+2:nd)
            do k = 1, ex + 1
                if (k <= nd) then
                    s(n + k:n + k) = d(k:k)
                else
                    s(n + k:n + k) = '0'
                end if
            end do
            n = n + ex + 1
            if (nd > ex + 1) then
                s(n + 1:n + 1 + nd - ex - 1) = '.'//d(ex + 2:nd)
                n = n + 1 + nd - ex - 1
            else if (point_zero) then
                s(n + 1:n + 2) = '.0'
            end if
        else
            s(n + 1:n + 2) = '0.'
            n = n + 2
            s(n + 1:n - ex - 1) = repeat('0', -ex - 1)
            n = n - ex - 1
            s(n + 1:n + nd) = d(1:nd)
        end if
    end function fixed_text

    !> E notation of +-d(1).d(2:) 10^ex: trailing zeros dropped, at least two exponent
    !> digits ("1.5e-05", "5e-324").
    pure function sci_text(d, ex, neg) result(s)
        character(len=*), intent(in) :: d
        integer, intent(in) :: ex
        logical, intent(in) :: neg
        character(len=NUM_LEN) :: s
        integer :: k, n
        k = significant_len(d)
        s = merge('-', ' ', neg)
        n = merge(1, 0, neg)
        s(n + 1:n + 1) = d(1:1)
        n = n + 1
        if (k > 1) then
            s(n + 1:n + k) = '.'//d(2:k)
            n = n + k
        end if
        s(n + 1:n + 2) = 'e'//merge('-', '+', ex < 0)
        n = n + 2
        call put_exponent(s, n, ex, 2)
    end function sci_text

    !> 'text' for a message, cut to QUOTE_MAX bytes (at a UTF-8 character boundary)
    !> with '...' when longer.
    pure function quote(text) result(s)
        character(len=*), intent(in) :: text  !! the text to quote (any length)
        character(len=quote_len(text)) :: s
        integer :: k
        if (len(text) <= QUOTE_MAX) then
            s = "'"//text//"'"
            return
        end if
        k = quote_cut(text)
        s = "'"//text(1:k)//"...'"
    end function quote

    !> The length of quote(text).
    pure integer function quote_len(text)
        character(len=*), intent(in) :: text  !! the text to quote (any length)
        if (len(text) <= QUOTE_MAX) then
            quote_len = len(text) + 2
        else
            quote_len = quote_cut(text) + 5
        end if
    end function quote_len

    !> The bytes of text (longer than QUOTE_MAX) that quote keeps: at most QUOTE_MAX, cut
    !> at a UTF-8 character boundary (not before a continuation byte 10xxxxxx).
    pure integer function quote_cut(text)
        character(len=*), intent(in) :: text
        integer :: k
        k = QUOTE_MAX
        do while (k > 1)
            if (iachar(text(k + 1:k + 1)) < 128 .or. iachar(text(k + 1:k + 1)) >= 192) exit
            k = k - 1
        end do
        quote_cut = k
    end function quote_cut

    !> s in upper case (ASCII letters only).
    pure function upper(s) result(u)
        character(len=*), intent(in) :: s  !! the text (ASCII or UTF-8)
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
        character(len=name_len(code, table)) :: name
        if (code >= 1 .and. code <= size(table)) then
            name = table(code)
        else
            name = '?'
        end if
    end function name_of

    !> The length of name_of(code, table).
    pure integer function name_len(code, table)
        integer, intent(in) :: code                !! 1-based index
        character(len=*), intent(in) :: table(:)   !! the names
        if (code >= 1 .and. code <= size(table)) then
            name_len = len_trim(table(code))
        else
            name_len = 1
        end if
    end function name_len

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
