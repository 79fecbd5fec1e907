!> Status codes and the one helper that reports them (argument checks live in
!> seispulse_checks, number formatting for messages in seispulse_format).
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
    public :: set_error, status_name

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
        character(len=len_trim(status_name_text(code))) :: name
        name = status_name_text(code)
    end function status_name

    !> status_name(code) padded with blanks.
    pure function status_name_text(code) result(name)
        integer, intent(in) :: code
        character(len=64) :: name
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
    end function status_name_text

end module seispulse_errors
