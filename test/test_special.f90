!> Special functions against quad-precision (real128) evaluations of the printed
!> formulas: 113-bit arithmetic leaves >= 20 correct digits where the double
!> forms would cancel.
module test_special
    use, intrinsic :: iso_fortran_env, only: qp => real128
    use seispulse_kinds, only: dp
    use seispulse_special, only: expm1, log1p, exp_phis, exp_phis_scaled, phi2, phi3, exp_expm1, &
                                 sin_pi, cos_pi, tau_minus_sinpi, phi1, phi1_taylor, &
                                 phi1_from_exp, inv_factorial, complex_phis, log1p_over_x, &
                                 sinh_minus_x, x_minus_asinh
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_special

    real(dp), parameter :: grid(*) = [0.0_dp, 1.0e-300_dp, 1.0e-12_dp, 1.0e-6_dp, 1.0e-3_dp, &
        0.1_dp, 0.124_dp, 0.126_dp, 0.49_dp, 0.51_dp, 1.0_dp, 1.99_dp, 2.0_dp, 2.01_dp, &
        5.0_dp, 10.0_dp, 37.0_dp, 100.0_dp, 699.0_dp]

contains

    subroutine collect_special(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('phi_k against quad precision', test_phis), &
                 new_unittest('phi_k at zero and far left', test_phis_limits), &
                 new_unittest('scaled phi_k, no overflow', test_phis_scaled), &
                 new_unittest('phi2 and phi3 wrappers', test_phi2_phi3), &
                 new_unittest('expm1 and log1p', test_expm1_log1p), &
                 new_unittest('sin_pi and cos_pi exact zeros', test_sincos_pi), &
                 new_unittest('tau - sin(pi tau)/pi near 0', test_tau_minus_sinpi), &
                 new_unittest('complex exp and expm1 near 2 pi i and 0', test_exp_expm1), &
                 new_unittest('phi_1 forms: real, Taylor, from e^x, complex', test_phi1_forms), &
                 new_unittest('1/m! table', test_inv_factorial), &
                 new_unittest('log1p(x)/x, sinh x - x, x - asinh x', test_elementary)]
    end subroutine collect_special

    !> phi_k(x) in quad precision: printed form, or the series where even 113 bits cancel.
    elemental function ref_phi(k, x) result(y)
        integer, intent(in) :: k
        real(dp), intent(in) :: x
        real(qp) :: y, xq, term, tay
        integer :: j
        xq = real(x, qp)
        if (abs(xq) < 1.0e-4_qp) then
            y = 0
            term = 1
            do j = 1, k
                term = term / j
            end do
            do j = 0, 30
                y = y + term
                term = term * xq / (j + k + 1)
            end do
        else
            tay = 0
            term = 1
            do j = 0, k - 1
                tay = tay + term
                term = term * xq / (j + 1)
            end do
            y = (exp(xq) - tay) / xq**k
        end if
    end function ref_phi

    subroutine test_phis(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: p(3), x, s
        integer :: i, k, sgn
        do i = 1, size(grid)
            do sgn = -1, 1, 2
                x = sgn * grid(i)
                call exp_phis(x, p(1), p(2), p(3))
                do k = 1, 3
                    call check(error, p(k), real(ref_phi(k, x), dp), rtol=4.0e-15_dp, &
                               message='phi_k at x = '//num(x))
                    if (allocated(error)) return
                end do
            end do
        end do
        ! random-ish points across the series/recurrence switch
        do i = 1, 200
            s = -3.0_dp + 6.0_dp * i / 200.0_dp
            call exp_phis(s, p(1), p(2), p(3))
            do k = 1, 3
                call check(error, p(k), real(ref_phi(k, s), dp), rtol=4.0e-15_dp, &
                           message='phi_k at x = '//num(s))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_phis

    subroutine test_phis_limits(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: p1, p2, p3
        call exp_phis(0.0_dp, p1, p2, p3)
        call check(error, p1, 1.0_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, p2, 0.5_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, p3, 1.0_dp / 6.0_dp, rtol=0.0_dp)
        if (allocated(error)) return
        ! x = -1e6: phi_1 = (1 - e^x)/|x|, phi_2 = (|x| - 1)/x^2, phi_3 = (x^2/2 - |x| + 1)/|x|^3
        call exp_phis(-1.0e6_dp, p1, p2, p3)
        call check(error, p1, 1.0e-6_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, p2, (1.0e6_dp - 1.0_dp) / 1.0e12_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, p3, (0.5e12_dp - 1.0e6_dp + 1.0_dp) / 1.0e18_dp, rtol=1.0e-15_dp)
    end subroutine test_phis_limits

    subroutine test_phis_scaled(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: xs(*) = [0.0_dp, 1.0e-9_dp, 0.3_dp, 1.5_dp, 3.0_dp, 50.0_dp, &
                                        699.9_dp, 700.1_dp, 800.0_dp, 5000.0_dp]
        real(dp) :: q(3)
        integer :: i, k
        do i = 1, size(xs)
            call exp_phis_scaled(xs(i), q(1), q(2), q(3))
            do k = 1, 3
                call check(error, q(k), real(exp(-real(xs(i), qp)) * ref_phi(k, xs(i)), dp), &
                           rtol=4.0e-15_dp, message='scaled phi_k at x = '//num(xs(i)))
                if (allocated(error)) return
            end do
        end do
        ! far beyond exp's range: q_k -> 1/x^k
        call exp_phis_scaled(1.0e6_dp, q(1), q(2), q(3))
        call check(error, q(1), 1.0e-6_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, q(2), 1.0e-12_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, q(3), 1.0e-18_dp, rtol=1.0e-15_dp)
    end subroutine test_phis_scaled

    subroutine test_phi2_phi3(error)
        type(test_error), allocatable, intent(out) :: error
        ! doc/pulses.md section 1: the naive V_g = 1/(1 - e^b) + 1/b gives 28.3 at b = 1e-9;
        ! V_g = phi2(b) * b/expm1(b) must give 0.5 - b/12.
        real(dp) :: b
        b = 1.0e-9_dp
        call check(error, phi2(b) * b / expm1(b), 0.5_dp - b / 12.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, phi3(-0.7_dp), real(ref_phi(3, -0.7_dp), dp), rtol=4.0e-15_dp)
        if (allocated(error)) return
        call check(error, phi2(3.3_dp), real(ref_phi(2, 3.3_dp), dp), rtol=4.0e-15_dp)
    end subroutine test_phi2_phi3

    !> e^z and e^z - 1 against mpmath (40 digits) at the exact double z: near 2 pi i, where
    !> exp(z) - 1 would lose 9 digits of the real part, near 0 and at a plain point.
    subroutine test_exp_expm1(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: z(3), e(3), em1(3)
        complex(dp), parameter :: e_ref(3) = [ &
            (0.9999999999_dp, 9.99999837711011e-10_dp), &
            (0.04369226300728118_dp, 0.02386919206778745_dp), &
            (0.999999999999_dp, -9.99999999999e-13_dp)]
        complex(dp), parameter :: em1_ref(3) = [ &
            (-1.0000000049499984e-10_dp, 9.99999837711011e-10_dp), &
            (-0.9563077369927189_dp, 0.02386919206778745_dp), &
            (-1e-12_dp, -9.99999999999e-13_dp)]
        integer :: i
        z = [(-1e-10_dp, 6.283185308179586_dp), (-3.0_dp, 0.5_dp), (-1e-12_dp, -1e-12_dp)]
        call exp_expm1(z, e, em1)
        do i = 1, 3
            call check(error, [real(e(i), dp), aimag(e(i))], &
                       [real(e_ref(i), dp), aimag(e_ref(i))], rtol=1.0e-14_dp, message='e^z')
            if (allocated(error)) return
            call check(error, [real(em1(i), dp), aimag(em1(i))], &
                       [real(em1_ref(i), dp), aimag(em1_ref(i))], rtol=1.0e-14_dp, &
                       message='e^z - 1')
            if (allocated(error)) return
        end do
    end subroutine test_exp_expm1

    subroutine test_expm1_log1p(error)
        type(test_error), allocatable, intent(out) :: error
        call check(error, expm1(1.0e-10_dp), 1.00000000005e-10_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, log1p(1.0e-10_dp), 0.99999999995e-10_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, expm1(-1.0_dp), real(exp(-1.0_qp) - 1, dp), rtol=1.0e-15_dp)
    end subroutine test_expm1_log1p

    subroutine test_sincos_pi(error)
        type(test_error), allocatable, intent(out) :: error
        real(qp), parameter :: piq = 3.14159265358979323846264338327950288_qp
        real(dp) :: x
        integer :: i
        do i = -8, 8
            call check(error, sin_pi(real(i, dp)), 0.0_dp, atol=0.0_dp, message='sin_pi(int)')
            if (allocated(error)) return
            call check(error, cos_pi(i + 0.5_dp), 0.0_dp, atol=0.0_dp, message='cos_pi(half)')
            if (allocated(error)) return
        end do
        do i = 0, 100
            x = -3.1_dp + 0.0617_dp * i
            call check(error, sin_pi(x), real(sin(piq * x), dp), rtol=1.0e-14_dp, &
                       atol=1.0e-16_dp, message='sin_pi')
            if (allocated(error)) return
            call check(error, cos_pi(x), real(cos(piq * x), dp), rtol=1.0e-14_dp, &
                       atol=1.0e-16_dp, message='cos_pi')
            if (allocated(error)) return
        end do
    end subroutine test_sincos_pi

    subroutine test_tau_minus_sinpi(error)
        type(test_error), allocatable, intent(out) :: error
        real(qp), parameter :: piq = 3.14159265358979323846264338327950288_qp
        real(dp), parameter :: ts(*) = [1.0e-7_dp, 1.0e-3_dp, 0.1_dp, 0.49_dp, 0.51_dp, &
                                        0.9_dp, 1.7_dp, -0.3_dp]
        integer :: i
        do i = 1, size(ts)
            call check(error, tau_minus_sinpi(ts(i)), &
                       real(ts(i) - sin(piq * ts(i)) / piq, dp), rtol=2.0e-15_dp, &
                       message='t = '//num(ts(i)))
            if (allocated(error)) return
        end do
    end subroutine test_tau_minus_sinpi

    !> The phi_1 forms against phi_1 in quad precision (ref_phi): phi1 (expm1/x) on the whole
    !> grid and its mirror, phi1_taylor for |x| <= 1/2, phi1_from_exp from exp(x); the
    !> complex phi1 against the quad-precision quotient (e^z - 1)/z away from 0 and the
    !> real values on the real axis.
    subroutine test_phi1_forms(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: x, ref
        complex(dp) :: z, p0, p1, p2
        complex(qp) :: zq
        integer :: i, sgn, k
        do i = 1, size(grid)
            do sgn = -1, 1, 2
                x = real(sgn, dp) * grid(i)
                ref = real(ref_phi(1, x), dp)
                call check(error, phi1(x), ref, rtol=4.0e-16_dp, message='phi1('//num(x)//')')
                if (allocated(error)) return
                call check(error, phi1_from_exp(x, exp(x)), ref, rtol=2.0e-15_dp, &
                           message='phi1_from_exp('//num(x)//')')
                if (allocated(error)) return
                if (abs(x) <= 0.5_dp) then
                    call check(error, phi1_taylor(x), ref, rtol=4.0e-16_dp, &
                               message='phi1_taylor('//num(x)//')')
                    if (allocated(error)) return
                end if
                call check(error, real(phi1(cmplx(x, 0.0_dp, dp)), dp), ref, rtol=2.0e-15_dp, &
                           message='complex phi1('//num(x)//')')
                if (allocated(error)) return
            end do
        end do
        do k = 0, 40
            z = cmplx(-3.0_dp + 0.15_dp * real(k, dp), 1.7_dp - 0.09_dp * real(k, dp), dp)
            zq = cmplx(real(z, qp), aimag(z), qp)
            call complex_phis(z, p0, p1, p2)
            call check(error, abs(phi1(z) - cmplx((exp(zq) - 1) / zq, kind=dp)) &
                       <= 2.0e-15_dp * abs(phi1(z)), 'complex phi1 at '//num(real(z, dp)) &
                       //' + i '//num(aimag(z)))
            if (allocated(error)) return
        end do
    end subroutine test_phi1_forms

    !> inv_factorial(m) = 1/m! to rounding (m! exact in quad precision up to 26!).
    subroutine test_inv_factorial(error)
        type(test_error), allocatable, intent(out) :: error
        real(qp) :: f
        integer :: m
        f = 1
        do m = 0, 26
            if (m > 0) f = f * m
            call check(error, inv_factorial(m), real(1 / f, dp), rtol=2.0e-16_dp, &
                       message='1/'//num(real(m, dp))//'!')
            if (allocated(error)) return
        end do
    end subroutine test_inv_factorial

    !> ln(1 + x)/x, sinh(x) - x and x - asinh(x) against quad precision (the printed forms,
    !> or their series where even 113 bits cancel), on the grid and its mirror, both sides of
    !> the series switches (1 and 1/4). Above a switch the printed form cancels a little:
    !> sinh x - x keeps ~1 - log10(6) digits less at |x| = 1, x - asinh x about 2 digits less
    !> at |x| = 1/4 (the tolerances say so).
    subroutine test_elementary(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: xs(*) = [1.0e-300_dp, 1.0e-12_dp, 1.0e-6_dp, 1.0e-3_dp, 0.1_dp, &
            0.2499_dp, 0.25_dp, 0.2501_dp, 0.5_dp, 0.9999_dp, 1.0_dp, 1.0001_dp, 3.0_dp, 40.0_dp, &
            700.0_dp]
        real(dp) :: x
        real(qp) :: xq, ref
        integer :: i, sgn
        call check(error, log1p_over_x(0.0_dp), 1.0_dp, rtol=0.0_dp, message='log1p(x)/x at 0')
        if (allocated(error)) return
        call check(error, sinh_minus_x(0.0_dp), 0.0_dp, rtol=0.0_dp, message='sinh x - x at 0')
        if (allocated(error)) return
        call check(error, x_minus_asinh(0.0_dp), 0.0_dp, rtol=0.0_dp, message='x - asinh x at 0')
        if (allocated(error)) return
        do i = 1, size(xs)
            do sgn = -1, 1, 2
                x = real(sgn, dp) * xs(i)
                xq = real(x, qp)
                if (x > -1.0_dp) then
                    if (abs(xq) < 1.0e-6_qp) then
                        ref = 1 - xq / 2 + xq * xq / 3 - xq**3 / 4
                    else
                        ref = log(1 + xq) / xq
                    end if
                    call check(error, log1p_over_x(x), real(ref, dp), rtol=4.0e-16_dp, &
                               message='log1p(x)/x at '//num(x))
                    if (allocated(error)) return
                end if
                if (abs(xq) < 1.0e-6_qp) then
                    ref = xq**3 / 6 + xq**5 / 120
                else
                    ref = sinh(xq) - xq
                end if
                call check(error, sinh_minus_x(x), real(ref, dp), rtol=3.0e-15_dp, &
                           message='sinh x - x at '//num(x))
                if (allocated(error)) return
                if (abs(xq) < 1.0e-6_qp) then
                    ref = xq**3 / 6 - 3 * xq**5 / 40
                else
                    ref = xq - asinh(xq)
                end if
                call check(error, x_minus_asinh(x), real(ref, dp), rtol=tol_asinh(x), &
                           message='x - asinh x at '//num(x))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_elementary

    !> x - asinh x: series below |x| = 1/4 (a few ulps); the printed form above it loses
    !> log10(x/(x - asinh x)) digits, at most about 2 at |x| = 1/4.
    pure function tol_asinh(x) result(tol)
        real(dp), intent(in) :: x
        real(dp) :: tol
        if (abs(x) < 0.25_dp) then
            tol = 1.0e-15_dp
        else
            tol = 4.0_dp * epsilon(x) * abs(x) / abs(x - asinh(x))
        end if
    end function tol_asinh

    function num(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: buf
        write(buf, '(es12.4)') x
        s = trim(adjustl(buf))
    end function num

end module test_special
