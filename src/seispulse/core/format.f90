!> Numbers and text for messages: one place that decides how a value reads in an
!> error message or a table note.
module seispulse_format
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    implicit none
    private

    public :: real_str, int_str, num_str, quote, upper, name_of, code_of

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
        real(dp), intent(in) :: x  !! the number (any unit; the caller writes the unit)
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

    !> 'text' for a message, cut to QUOTE_MAX bytes (at a UTF-8 character boundary)
    !> with '...' when longer.
    pure function quote(text) result(s)
        character(len=*), intent(in) :: text  !! the text to quote (any length)
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
