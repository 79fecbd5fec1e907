!> LAPACK interfaces (all of them, in one place) and the mapping of `info`.
module seispulse_lapack
    use seispulse_kinds, only: dp, ik
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_SINGULAR, &
                                SEISPULSE_INTERNAL, set_error
    implicit none
    private

    public :: solve_linear, solve_linear_inplace, lu_factor, lu_solve

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
        !> LU factorisation with partial pivoting, real (LAPACK).
        pure subroutine dgetrf(m, n, a, lda, ipiv, info)
            import :: dp, ik
            integer(ik), intent(in) :: m, n, lda
            real(dp), intent(inout) :: a(lda, *)
            integer(ik), intent(out) :: ipiv(*)
            integer(ik), intent(out) :: info
        end subroutine dgetrf
        !> Solution of A X = B from the factors of dgetrf (LAPACK).
        pure subroutine dgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
            import :: dp, ik
            character(len=1), intent(in) :: trans
            integer(ik), intent(in) :: n, nrhs, lda, ldb
            real(dp), intent(in) :: a(lda, *)
            integer(ik), intent(in) :: ipiv(*)
            real(dp), intent(inout) :: b(ldb, *)
            integer(ik), intent(out) :: info
        end subroutine dgetrs
        !> LU factorisation with partial pivoting, complex (LAPACK).
        pure subroutine zgetrf(m, n, a, lda, ipiv, info)
            import :: dp, ik
            integer(ik), intent(in) :: m, n, lda
            complex(dp), intent(inout) :: a(lda, *)
            integer(ik), intent(out) :: ipiv(*)
            integer(ik), intent(out) :: info
        end subroutine zgetrf
        !> Solution of A X = B from the factors of zgetrf (LAPACK).
        pure subroutine zgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
            import :: dp, ik
            character(len=1), intent(in) :: trans
            integer(ik), intent(in) :: n, nrhs, lda, ldb
            complex(dp), intent(in) :: a(lda, *)
            integer(ik), intent(in) :: ipiv(*)
            complex(dp), intent(inout) :: b(ldb, *)
            integer(ik), intent(out) :: info
        end subroutine zgetrs
    end interface

    !> In-place LU factorisation of a square matrix the caller owns, real or complex
    !> (LAPACK dgetrf/zgetrf; no allocation, for small systems factored many times).
    interface lu_factor
        module procedure lu_factor_real, lu_factor_complex
    end interface lu_factor

    !> Solution of A x = b in place from the factors of `lu_factor` (LAPACK dgetrs/zgetrs;
    !> no allocation).
    interface lu_solve
        module procedure lu_solve_real, lu_solve_complex
    end interface lu_solve

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

    !> LU factors of a real n x n matrix in place (dgetrf): a = P L U. stat is
    !> SEISPULSE_SINGULAR for an exactly zero pivot (the factors are complete but U is
    !> singular: do not solve with them).
    subroutine lu_factor_real(a, ipiv, stat, errmsg)
        real(dp), contiguous, intent(inout) :: a(:, :)        !! n x n in, LU factors out
        integer(ik), contiguous, intent(out) :: ipiv(:)       !! pivot indices, n
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer(ik) :: n, info
        n = int(size(a, 1), ik)
        if (size(a, 2) /= n .or. size(ipiv) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'a: must be square with the length of ipiv')
            return
        end if
        call dgetrf(n, n, a, max(1_ik, n), ipiv, info)
        call handle_getrf_info('dgetrf', info, stat, errmsg)
    end subroutine lu_factor_real

    !> LU factors of a complex n x n matrix in place (zgetrf); stat as `lu_factor_real`.
    subroutine lu_factor_complex(a, ipiv, stat, errmsg)
        complex(dp), contiguous, intent(inout) :: a(:, :)     !! n x n in, LU factors out
        integer(ik), contiguous, intent(out) :: ipiv(:)       !! pivot indices, n
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer(ik) :: n, info
        n = int(size(a, 1), ik)
        if (size(a, 2) /= n .or. size(ipiv) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'a: must be square with the length of ipiv')
            return
        end if
        call zgetrf(n, n, a, max(1_ik, n), ipiv, info)
        call handle_getrf_info('zgetrf', info, stat, errmsg)
    end subroutine lu_factor_complex

    !> x = A^-1 b in place from the factors of `lu_factor_real` (dgetrs). The sizes are
    !> the caller's to match (n x n, n, n): no check on this path, for speed.
    pure subroutine lu_solve_real(lu, ipiv, b)
        real(dp), contiguous, intent(in) :: lu(:, :)          !! LU factors, n x n
        integer(ik), contiguous, intent(in) :: ipiv(:)        !! pivot indices, n
        real(dp), contiguous, intent(inout) :: b(:)           !! right-hand side in (n), x out
        integer(ik) :: n, info
        n = int(size(b), ik)
        call dgetrs('N', n, 1_ik, lu, max(1_ik, n), ipiv, b, max(1_ik, n), info)
    end subroutine lu_solve_real

    !> x = A^-1 b in place from the factors of `lu_factor_complex` (zgetrs); as
    !> `lu_solve_real`.
    pure subroutine lu_solve_complex(lu, ipiv, b)
        complex(dp), contiguous, intent(in) :: lu(:, :)       !! LU factors, n x n
        integer(ik), contiguous, intent(in) :: ipiv(:)        !! pivot indices, n
        complex(dp), contiguous, intent(inout) :: b(:)        !! right-hand side in (n), x out
        integer(ik) :: n, info
        n = int(size(b), ik)
        call zgetrs('N', n, 1_ik, lu, max(1_ik, n), ipiv, b, max(1_ik, n), info)
    end subroutine lu_solve_complex

    !> d/zgetrf: info < 0 is our bug (bad argument), info > 0 an exactly zero pivot. The
    !> message is formatted only on an error (the success path stays cheap).
    subroutine handle_getrf_info(name, info, stat, errmsg)
        character(len=*), intent(in) :: name
        integer(ik), intent(in) :: info
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        character(len=12) :: num
        stat = SEISPULSE_SUCCESS
        if (info == 0) return
        write(num, '(i0)') abs(info)
        if (info < 0) then
            call set_error(stat, errmsg, SEISPULSE_INTERNAL, &
                           name//': illegal value in argument '//trim(num))
        else
            call set_error(stat, errmsg, SEISPULSE_SINGULAR, &
                           'a: matrix is singular (zero pivot U('//trim(num)//','//trim(num)//'))')
        end if
    end subroutine handle_getrf_info

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
