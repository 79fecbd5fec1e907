!> LAPACK wrapper: a solve checked against a hand-computed solution, and info mapping.
module test_lapack
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_SINGULAR, SEISPULSE_INVALID_INPUT
    use seispulse_lapack, only: solve_linear
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_lapack

contains

    subroutine collect_lapack(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('solve 3x3', test_solve), &
                 new_unittest('singular matrix is a status', test_singular), &
                 new_unittest('shape mismatch is a status', test_shapes)]
    end subroutine collect_lapack

    subroutine test_solve(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(3, 3), x(3)
        integer :: stat
        ! A x = b with x = (1, -2, 3) chosen first
        a = reshape([4.0_dp, 2.0_dp, 1.0_dp, 1.0_dp, 5.0_dp, 2.0_dp, 0.0_dp, 1.0_dp, 3.0_dp], [3, 3])
        call solve_linear(a, [2.0_dp, -5.0_dp, 6.0_dp], x, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, x, [1.0_dp, -2.0_dp, 3.0_dp], rtol=1.0e-14_dp, atol=1.0e-14_dp)
    end subroutine test_solve

    subroutine test_singular(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(2, 2), x(2)
        integer :: stat
        character(len=100) :: msg
        a = reshape([1.0_dp, 2.0_dp, 2.0_dp, 4.0_dp], [2, 2])
        call solve_linear(a, [1.0_dp, 1.0_dp], x, stat, msg)
        call check(error, stat, SEISPULSE_SINGULAR, 'status')
        if (allocated(error)) return
        call check(error, index(msg, 'singular') > 0, trim(msg))
    end subroutine test_singular

    subroutine test_shapes(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(2, 3), x(2)
        integer :: stat
        a = 1.0_dp
        call solve_linear(a, [1.0_dp, 1.0_dp], x, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'status')
    end subroutine test_shapes

end module test_lapack
