!> LAPACK wrapper: a solve checked against a hand-computed solution, and info mapping;
!> the LU factor/solve pair, real and complex.
module test_lapack
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_SINGULAR, SEISPULSE_INVALID_INPUT
    use seispulse_lapack, only: solve_linear, solve_linear_inplace, lu_factor, lu_solve
    use seispulse_kinds, only: ik
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_lapack

contains

    subroutine collect_lapack(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('solve 3x3', test_solve), &
                 new_unittest('singular matrix is a status', test_singular), &
                 new_unittest('shape mismatch is a status', test_shapes), &
                 new_unittest('in-place solve 3x3', test_inplace), &
                 new_unittest('in-place: singular and shape mismatch', test_inplace_errors), &
                 new_unittest('LU factors reused: real and complex', test_lu), &
                 new_unittest('LU: singular and shape mismatch', test_lu_errors)]
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

    !> The caller-owned variant: same system, solution in b, LU factors in a (L U = P A).
    subroutine test_inplace(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(3, 3), a0(3, 3), b(3), l(3, 3), u(3, 3), pa(3, 3), row(3)
        integer(ik) :: ipiv(3)
        integer :: stat, i
        a0 = reshape([4.0_dp, 2.0_dp, 1.0_dp, 1.0_dp, 5.0_dp, 2.0_dp, 0.0_dp, 1.0_dp, 3.0_dp], &
                     [3, 3])
        a = a0
        b = [2.0_dp, -5.0_dp, 6.0_dp]
        call solve_linear_inplace(a, b, ipiv, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, b, [1.0_dp, -2.0_dp, 3.0_dp], rtol=1.0e-14_dp, atol=1.0e-14_dp)
        if (allocated(error)) return
        ! the factors: unit lower L and upper U with L U = A with rows swapped as ipiv says
        l = 0.0_dp
        u = 0.0_dp
        do i = 1, 3
            l(i, i) = 1.0_dp
            l(i + 1:, i) = a(i + 1:, i)
            u(i, i:) = a(i, i:)
        end do
        pa = a0
        do i = 1, 3
            row = pa(i, :)
            pa(i, :) = pa(ipiv(i), :)
            pa(ipiv(i), :) = row
        end do
        call check(error, reshape(matmul(l, u), [9]), reshape(pa, [9]), rtol=1.0e-14_dp, &
                   atol=1.0e-14_dp)
    end subroutine test_inplace

    subroutine test_inplace_errors(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(2, 2), b(2), a3(3, 3)
        integer(ik) :: ipiv(2)
        integer :: stat
        character(len=100) :: msg
        a = reshape([1.0_dp, 2.0_dp, 2.0_dp, 4.0_dp], [2, 2])
        b = 1.0_dp
        msg = ''
        call solve_linear_inplace(a, b, ipiv, stat, msg)
        call check(error, stat, SEISPULSE_SINGULAR, 'singular status')
        if (allocated(error)) return
        call check(error, index(msg, 'singular') > 0, 'message names the problem: '//trim(msg))
        if (allocated(error)) return
        a3 = 1.0_dp
        call solve_linear_inplace(a3, b, ipiv, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'shape status')
    end subroutine test_inplace_errors

    !> Factor once, solve two right-hand sides built from chosen solutions (b = A x by
    !> matmul), real and complex.
    subroutine test_lu(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(3, 3), lu(3, 3), x(3), b(3)
        complex(dp) :: ac(3, 3), luc(3, 3), xc(3), bc(3)
        integer(ik) :: ipiv(3)
        integer :: stat, k
        a = reshape([4.0_dp, 2.0_dp, 1.0_dp, 1.0_dp, 5.0_dp, 2.0_dp, 0.0_dp, 1.0_dp, 3.0_dp], &
                    [3, 3])
        lu = a
        call lu_factor(lu, ipiv, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'real factor')
        if (allocated(error)) return
        do k = 1, 2
            x = [1.0_dp, -2.0_dp, 3.0_dp] * real(k, dp) + [0.0_dp, 0.0_dp, 0.5_dp] * real(k - 1, dp)
            b = matmul(a, x)
            call lu_solve(lu, ipiv, b)
            call check(error, b, x, rtol=1.0e-14_dp, atol=1.0e-14_dp, message='real solve')
            if (allocated(error)) return
        end do
        ac = cmplx(a, transpose(a) - 1.0_dp, kind=dp)
        luc = ac
        call lu_factor(luc, ipiv, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'complex factor')
        if (allocated(error)) return
        do k = 1, 2
            xc = cmplx([1.0_dp, -2.0_dp, 3.0_dp], [0.5_dp, 0.0_dp, -1.0_dp] * real(k, dp), kind=dp)
            bc = matmul(ac, xc)
            call lu_solve(luc, ipiv, bc)
            call check(error, real(bc, dp), real(xc, dp), rtol=1.0e-14_dp, atol=1.0e-14_dp, &
                       message='complex solve, real part')
            if (allocated(error)) return
            call check(error, aimag(bc), aimag(xc), rtol=1.0e-14_dp, atol=1.0e-14_dp, &
                       message='complex solve, imaginary part')
            if (allocated(error)) return
        end do
    end subroutine test_lu

    subroutine test_lu_errors(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(2, 2), r(2, 3)
        complex(dp) :: ac(2, 2)
        integer(ik) :: ipiv(2)
        integer :: stat
        character(len=100) :: msg
        a = reshape([1.0_dp, 2.0_dp, 2.0_dp, 4.0_dp], [2, 2])
        call lu_factor(a, ipiv, stat, msg)
        call check(error, stat, SEISPULSE_SINGULAR, 'real singular')
        if (allocated(error)) return
        call check(error, index(msg, 'singular') > 0, 'message says singular')
        if (allocated(error)) return
        ac = cmplx(reshape([1.0_dp, 2.0_dp, 2.0_dp, 4.0_dp], [2, 2]), &
                   reshape([1.0_dp, 2.0_dp, 2.0_dp, 4.0_dp], [2, 2]), kind=dp)
        call lu_factor(ac, ipiv, stat)
        call check(error, stat, SEISPULSE_SINGULAR, 'complex singular')
        if (allocated(error)) return
        r = 1.0_dp
        call lu_factor(r, ipiv, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'not square')
    end subroutine test_lu_errors

end module test_lapack
