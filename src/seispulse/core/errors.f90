!> Status codes and the one helper that reports them.
!>
!> Library routines never stop and never print: a fallible routine ends with
!> `stat` (one of the codes below) and an optional `errmsg`. Messages name the
!> parameter first ("beta: ..."), so that the driver can prefix file and group
!> and the Python layer can raise an exception that names the argument.
module seispulse_errors
    implicit none
    private

    public :: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_SINGULAR, &
              SEISPULSE_NO_CONVERGENCE, SEISPULSE_NO_BRACKET, SEISPULSE_INTERNAL, SEISPULSE_IO, &
              SEISPULSE_NO_SOLUTION
    public :: set_error, status_name, real_str, int_str, outside, check_ascending_times, &
              check_output_grid

    integer, parameter :: SEISPULSE_SUCCESS = 0        !! no error
    integer, parameter :: SEISPULSE_INVALID_INPUT = 1  !! an argument is out of its domain
    integer, parameter :: SEISPULSE_SINGULAR = 2       !! singular matrix or degenerate system
    integer, parameter :: SEISPULSE_NO_CONVERGENCE = 3 !! iteration limit reached
    integer, parameter :: SEISPULSE_NO_BRACKET = 4     !! root finder: f(a), f(b) of one sign
    integer, parameter :: SEISPULSE_INTERNAL = 5       !! a bug: please report it
    integer, parameter :: SEISPULSE_IO = 6             !! a file cannot be opened or read
    !> the problem has no solution for these (valid) data, e.g. a Mononobe-Okabe backfill
    !> slope steeper than phi - theta: the wedge cannot be in equilibrium
    integer, parameter :: SEISPULSE_NO_SOLUTION = 7

contains

    !> Set `stat` to `code` and, when the caller passed one, `errmsg` to `message`.
    pure subroutine set_error(stat, errmsg, code, message)
        integer, intent(out) :: stat                          !! receives `code`
        character(len=*), intent(inout), optional :: errmsg  !! receives `message` (truncated)
        integer, intent(in) :: code                           !! one of the SEISPULSE_* codes
        character(len=*), intent(in) :: message               !! "parameter: what is wrong"
        stat = code
        if (present(errmsg)) errmsg = message
    end subroutine set_error

    !> Short name of a status code, for logs.
    pure function status_name(code) result(name)
        integer, intent(in) :: code  !! a SEISPULSE_* code
        character(len=:), allocatable :: name
        select case (code)
        case (SEISPULSE_SUCCESS)
            name = 'success'
        case (SEISPULSE_INVALID_INPUT)
            name = 'invalid input'
        case (SEISPULSE_SINGULAR)
            name = 'singular'
        case (SEISPULSE_NO_CONVERGENCE)
            name = 'no convergence'
        case (SEISPULSE_NO_BRACKET)
            name = 'no bracket'
        case (SEISPULSE_INTERNAL)
            name = 'internal error'
        case (SEISPULSE_IO)
            name = 'file error'
        case (SEISPULSE_NO_SOLUTION)
            name = 'no solution'
        case default
            name = 'unknown status'
        end select
    end function status_name

    !> A real number as short text for messages: 15 significant digits without
    !> trailing zeros ("-1.0", "0.6", "1.0E+300", "NaN", "Infinity").
    pure function real_str(x) result(text)
        use seispulse_kinds, only: dp
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

    !> x is NaN or outside [lo, hi] (an end excluded when open): the range check of every
    !> input. NaN is tested first: an ordered comparison on NaN raises the invalid flag
    !> (and traps in checked builds).
    elemental logical function outside(x, lo, hi, open_lo, open_hi)
        use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
        use seispulse_kinds, only: dp
        real(dp), intent(in) :: x        !! the value
        real(dp), intent(in) :: lo, hi   !! the range
        logical, intent(in) :: open_lo   !! lo itself is outside
        logical, intent(in) :: open_hi   !! hi itself is outside
        if (ieee_is_nan(x)) then
            outside = .true.
        else if (open_lo) then
            outside = .not. (x > lo)
        else
            outside = x < lo
        end if
        if (outside) return
        if (open_hi) then
            outside = .not. (x < hi)
        else
            outside = x > hi
        end if
    end function outside

    !> Output times of an integrator: finite and ascending (a message naming t(i)).
    subroutine check_ascending_times(t, name, stat, errmsg)
        use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
        use seispulse_kinds, only: dp
        real(dp), intent(in) :: t(:)                          !! the times
        character(len=*), intent(in) :: name                  !! their name in messages
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: i
        character(len=24) :: idx
        stat = SEISPULSE_SUCCESS
        do i = 1, size(t)
            if (.not. ieee_is_finite(t(i))) then
                write(idx, '(i0)') i
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name//'('//trim(idx) &
                               //') = '//real_str(t(i))//': must be a finite number')
                return
            end if
        end do
        do i = 2, size(t)
            if (t(i) < t(i - 1)) then
                write(idx, '(i0)') i
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name//'('//trim(idx) &
                               //') = '//real_str(t(i))//': the times must be ascending')
                return
            end if
        end do
    end subroutine check_ascending_times

    !> Optional output histories of an integrator: the times t_grid and the two grids
    !> x_grid, y_grid all present or all absent, of one size, t_grid finite and ascending.
    subroutine check_output_grid(x_name, y_name, stat, errmsg, t_grid, x_grid, y_grid)
        use seispulse_kinds, only: dp
        character(len=*), intent(in) :: x_name, y_name        !! names of the grids in messages
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(in), optional :: t_grid(:)           !! output times
        real(dp), intent(in), optional :: x_grid(:)           !! first output grid
        real(dp), intent(in), optional :: y_grid(:)           !! second output grid
        character(len=:), allocatable :: together
        stat = SEISPULSE_SUCCESS
        if (.not. (present(t_grid) .or. present(x_grid) .or. present(y_grid))) return
        together = ': missing (t_grid, '//x_name//' and '//y_name//' go together)'
        if (.not. present(t_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't_grid: missing (' &
                           //x_name//' and '//y_name//' need the output times)')
        else if (.not. present(x_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, x_name//together)
        else if (.not. present(y_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, y_name//together)
        else if (size(x_grid) /= size(t_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, x_name &
                           //': must have the size of t_grid')
        else if (size(y_grid) /= size(t_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, y_name &
                           //': must have the size of t_grid')
        else
            call check_ascending_times(t_grid, 't_grid', stat, errmsg)
        end if
    end subroutine check_output_grid

end module seispulse_errors
