!> Defaults of optional arguments: `optval(x, default)` is `x` when the caller passed it,
!> else `default` (the idiom of the Fortran stdlib's stdlib_optval). Public routines whose
!> optional arguments take the defaults of the Python layer read them through it, so that
!> the body works on plain values.
module seispulse_optval
    use seispulse_kinds, only: dp
    implicit none
    private

    public :: optval

    !> `x` if present, else `default`.
    interface optval
        module procedure optval_real, optval_int, optval_logical
    end interface optval

contains

    !> Real `x` if present, else `default`.
    pure function optval_real(x, default) result(y)
        real(dp), intent(in), optional :: x  !! the optional argument (any unit); absent: default
        real(dp), intent(in) :: default      !! value used when x is absent (unit of x)
        real(dp) :: y
        if (present(x)) then
            y = x
        else
            y = default
        end if
    end function optval_real

    !> Integer `x` if present, else `default`.
    pure function optval_int(x, default) result(y)
        integer, intent(in), optional :: x  !! the optional argument; absent: default
        integer, intent(in) :: default      !! value used when x is absent
        integer :: y
        if (present(x)) then
            y = x
        else
            y = default
        end if
    end function optval_int

    !> Logical `x` if present, else `default`.
    pure function optval_logical(x, default) result(y)
        logical, intent(in), optional :: x  !! the optional argument; absent: default
        logical, intent(in) :: default      !! value used when x is absent
        logical :: y
        if (present(x)) then
            y = x
        else
            y = default
        end if
    end function optval_logical

end module seispulse_optval
