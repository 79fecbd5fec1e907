!> LAPACK interfaces (all of them, in one place) and the mapping of `info`.
module seispulse_lapack
    use seispulse_kinds, only: dp, ik
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_SINGULAR, &
                                SEISPULSE_INTERNAL, set_error
    implicit none
    private

    public :: solve_linear, solve_linear_inplace

    interface
        !> LU factorisation and solution of A X = B (LAPACK).
        pure subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
            import :: dp, ik
            integer(ik), intent(in) :: n, nrhs, lda, ldb
            real(dp), intent(inout) :: a(lda, *)
            integer(ik), intent(out) :: ipiv(*)
            real(dp), intent(inout) :: b(ldb, *)
            integer(ik), intent(out) :: info
        end subroutine dgesv
    end interface

contains

    !> Solve A x = b by LU factorisation with partial pivoting (LAPACK dgesv).
    subroutine solve_linear(a, b, x, stat, errmsg)
        real(dp), intent(in) :: a(:, :)                       !! coefficient matrix, n x n
        real(dp), intent(in) :: b(:)                          !! right-hand side, n
        real(dp), intent(out) :: x(:)                         !! solution, n
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), allocatable :: lu(:, :), rhs(:, :)
        integer(ik), allocatable :: ipiv(:)
        integer(ik) :: n, info
        n = int(size(b), ik)
        if (size(a, 1) /= n .or. size(a, 2) /= n .or. size(x) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'a: must be square with the length of b and x')
            return
        end if
        allocate(lu, source=a)
        allocate(rhs(n, 1))
        rhs(:, 1) = b
        allocate(ipiv(n))
        call dgesv(n, 1_ik, lu, max(1_ik, n), ipiv, rhs, max(1_ik, n), info)
        call handle_gesv_info(info, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) x = rhs(:, 1)
    end subroutine solve_linear

    !> Solve A x = b in place on arrays the caller owns (LAPACK dgesv; no allocation: for
    !> small systems solved many times, e.g. once per right-hand-side evaluation of an ODE).
    !> On return `a` holds the LU factors and `b` the solution x (undefined if stat /= 0).
    subroutine solve_linear_inplace(a, b, ipiv, stat, errmsg)
        real(dp), contiguous, intent(inout) :: a(:, :)        !! n x n in, LU factors out
        real(dp), contiguous, intent(inout) :: b(:)           !! right-hand side in (n), x out
        integer(ik), contiguous, intent(out) :: ipiv(:)       !! pivot indices, n
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer(ik) :: n, info
        n = int(size(b), ik)
        if (size(a, 1) /= n .or. size(a, 2) /= n .or. size(ipiv) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'a: must be square with the length of b and ipiv')
            return
        end if
        call dgesv(n, 1_ik, a, max(1_ik, n), ipiv, b, max(1_ik, n), info)
        call handle_gesv_info(info, stat, errmsg)
    end subroutine solve_linear_inplace

    !> dgesv: info < 0 is our bug (bad argument), info > 0 a singular matrix.
    subroutine handle_gesv_info(info, stat, errmsg)
        integer(ik), intent(in) :: info
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        character(len=12) :: num
        write(num, '(i0)') abs(info)
        if (info == 0) then
            stat = SEISPULSE_SUCCESS
        else if (info < 0) then
            call set_error(stat, errmsg, SEISPULSE_INTERNAL, &
                           'dgesv: illegal value in argument '//trim(num))
        else
            call set_error(stat, errmsg, SEISPULSE_SINGULAR, &
                           'a: matrix is singular (zero pivot U('//trim(num)//','//trim(num)//'))')
        end if
    end subroutine handle_gesv_info

end module seispulse_lapack
