!> Decimal numbers in text files: a strict, correctly rounded reader and the
!> "<path>:<n>: " prefix of the messages that point into a file.
!>
!> Numbers with at most 15 significant digits and a decimal exponent within +-22 are
!> converted exactly (one correctly rounded product or quotient of exact doubles,
!> Clinger's fast path); others go through the compiler's conversion (a correctly
!> rounded strtod in gfortran). Either way the result is the correctly rounded double,
!> bitwise equal to what numpy or C would read. Every token is validated as a decimal
!> number before it is converted (`nan`, `inf`, `1.0.0`, `1/2` are refused).
module seispulse_number_reader
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_format, only: quote, int_str, int_str_len
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    implicit none
    private

    public :: parse_real, value_at, at_line
    public :: NUM_OK, NUM_INVALID, NUM_RANGE

    !> Exact powers of ten (10**22 is the largest exactly representable one).
    real(dp), parameter :: P10(0:22) = [1.0e0_dp, 1.0e1_dp, 1.0e2_dp, 1.0e3_dp, 1.0e4_dp, &
        1.0e5_dp, 1.0e6_dp, 1.0e7_dp, 1.0e8_dp, 1.0e9_dp, 1.0e10_dp, 1.0e11_dp, 1.0e12_dp, &
        1.0e13_dp, 1.0e14_dp, 1.0e15_dp, 1.0e16_dp, 1.0e17_dp, 1.0e18_dp, 1.0e19_dp, &
        1.0e20_dp, 1.0e21_dp, 1.0e22_dp]

    !> Results of parse_real.
    integer, parameter :: NUM_OK = 0       !! a number, converted
    integer, parameter :: NUM_INVALID = 1  !! not a decimal number
    integer, parameter :: NUM_RANGE = 2    !! a number out of the range of double precision

contains

    !> A decimal number token [+-]digits[.digits][(e|E|d|D)[+-]digits] (also .5 and 5.)
    !> to double precision, correctly rounded. code: NUM_OK, NUM_INVALID (not of that
    !> form), NUM_RANGE (|x| >= 1e308: out of the range of double precision).
    subroutine parse_real(tok, x, code)
        character(len=*), intent(in) :: tok  !! the token, without blanks
        real(dp), intent(out) :: x           !! its value (0 unless code = NUM_OK)
        integer, intent(out) :: code         !! NUM_OK, NUM_INVALID or NUM_RANGE
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

    !> The value of a decimal digit character, -1 for any other character.
    pure integer function digit(c)
        character, intent(in) :: c  !! one character
        digit = iachar(c) - iachar('0')
        if (digit < 0 .or. digit > 9) digit = -1
    end function digit

    !> Parse one value of a data line (parse_real); on failure set the error: the file,
    !> the line, the token quoted and what was expected.
    subroutine value_at(path, lnum, tok, x, stat, errmsg)
        character(len=*), intent(in) :: path                  !! the file (for the message)
        integer, intent(in) :: lnum                           !! the line (for the message)
        character(len=*), intent(in) :: tok                   !! the token, without blanks
        real(dp), intent(out) :: x                            !! its value
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
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

    !> The prefix of a message about line `lnum` of file `path`: "<path>:<n>: ".
    pure function at_line(path, lnum) result(s)
        character(len=*), intent(in) :: path  !! the file
        integer, intent(in) :: lnum           !! the line number
        character(len=len(path) + int_str_len(lnum) + 3) :: s
        s = path//':'//int_str(lnum)//': '
    end function at_line

end module seispulse_number_reader
