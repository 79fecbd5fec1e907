!> Rigid footings on Winkler soil (doc/winkler.md): the contact integrals against Gauss-Legendre
!> quadrature in quad precision written here (slivers at an edge and in the interior, wide
!> strips, the full circle and rectangle), x - sin x against quad precision. Every expected
!> value is computed here independently.
module test_winkler
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_special, only: x_minus_sin
    use seispulse_winkler_contact, only: FOOTING_CIRCLE, FOOTING_RECTANGLE, strip_moments
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_winkler

    integer, parameter :: qp = selected_real_kind(30)
    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(qp), parameter :: pi_q = 3.141592653589793238462643383279502884_qp
    integer, parameter :: n_gl = 40

contains

    subroutine collect_winkler(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('x - sin x: series and direct form against quad precision', &
                              test_x_minus_sin), &
                 new_unittest('strip moments, circle: full circle, slivers, wide strips vs' &
                              //' quad Gauss-Legendre', test_strip_circle), &
                 new_unittest('strip moments, rectangle: exact polynomials, slivers', &
                              test_strip_rectangle)]
    end subroutine collect_winkler

    subroutine test_x_minus_sin(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: xs(9) = [1.0e-8_dp, 1.0e-3_dp, 0.1_dp, 0.5_dp, 0.99_dp, &
                                        1.0_dp, 2.0_dp, 3.0_dp, 6.0_dp]
        real(qp) :: xq
        integer :: i
        call check(error, x_minus_sin(0.0_dp), 0.0_dp, rtol=0.0_dp, message='x - sin x at 0')
        if (allocated(error)) return
        do i = 1, size(xs)
            xq = real(xs(i), qp)
            call check(error, x_minus_sin(xs(i)), real(xq - sin(xq), dp), rtol=4.0e-16_dp, &
                       message='x - sin x')
            if (allocated(error)) return
            call check(error, x_minus_sin(-xs(i)), -real(xq - sin(xq), dp), rtol=4.0e-16_dp, &
                       message='x - sin x, odd')
            if (allocated(error)) return
        end do
    end subroutine test_x_minus_sin

    !> Reference moments of the circle strip [s_a, s_b] (quad): s = r cos u, 2 w ds =
    !> 2 r^2 sin^2 u du, Gauss-Legendre on [u_b, u_a] with u = acos(s/r).
    function circle_ref(r, sa, sb) result(m)
        real(qp), intent(in) :: r, sa, sb
        real(qp) :: m(0:2)
        real(qp) :: x(n_gl), wt(n_gl), ua, ub, u, f
        integer :: i
        call gauss_legendre(x, wt)
        ua = acos(sa / r)
        ub = acos(sb / r)
        m = 0.0_qp
        do i = 1, n_gl
            u = 0.5_qp * (ua + ub) + 0.5_qp * (ua - ub) * x(i)
            f = 2.0_qp * r * r * sin(u)**2 * 0.5_qp * (ua - ub) * wt(i)
            m(0) = m(0) + f
            m(1) = m(1) + f * r * cos(u)
            m(2) = m(2) + f * (r * cos(u))**2
        end do
    end function circle_ref

    !> Gauss-Legendre nodes and weights on [-1, 1] (quad; Newton on the three-term recurrence).
    subroutine gauss_legendre(x, wt)
        real(qp), intent(out) :: x(:), wt(:)
        real(qp) :: z, p0, p1, p2, dp_
        integer :: n, i, j, it
        n = size(x)
        do i = 1, n
            z = cos(pi_q * (real(i, qp) - 0.25_qp) / (real(n, qp) + 0.5_qp))
            do it = 1, 100
                p0 = 1.0_qp
                p1 = z
                do j = 2, n
                    p2 = ((2 * j - 1) * z * p1 - (j - 1) * p0) / real(j, qp)
                    p0 = p1
                    p1 = p2
                end do
                dp_ = real(n, qp) * (z * p1 - p0) / (z * z - 1.0_qp)
                z = z - p1 / dp_
                if (abs(p1 / dp_) < 1.0e-32_qp) exit
            end do
            x(i) = z
            wt(i) = 2.0_qp / ((1.0_qp - z * z) * dp_ * dp_)
        end do
    end subroutine gauss_legendre

    subroutine test_strip_circle(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: r = 1.75_dp
        real(dp) :: m(0:2), dla, dha, dlb, dhb
        real(qp) :: rq, ref(0:2)
        integer :: c, j
        character(len=*), parameter :: names(8) = [character(len=24) :: 'edge sliver at -r', &
            'edge sliver at +r', 'interior sliver', 'general strip', 'wide strip', &
            'contact strip b = 0.3r', 'contact strip b = 1.9r', 'near-full strip']
        rq = real(r, qp)
        ! full circle: m0 = pi r^2, m1 = 0, m2 = pi r^4/4
        call strip_moments(FOOTING_CIRCLE, r, 0.0_dp, 0.0_dp, 2.0_dp * r, 2.0_dp * r, 0.0_dp, m)
        call check(error, m(0), pi * r * r, rtol=2.0e-16_dp, message='full circle m0')
        if (allocated(error)) return
        call check(error, m(1), 0.0_dp, atol=0.0_dp, message='full circle m1')
        if (allocated(error)) return
        call check(error, m(2), pi * r**4 / 4.0_dp, rtol=4.0e-16_dp, message='full circle m2')
        if (allocated(error)) return
        ! empty and reversed strips
        call strip_moments(FOOTING_CIRCLE, r, 0.0_dp, r, r, r, r, m)
        call check(error, maxval(abs(m)), 0.0_dp, atol=0.0_dp, message='empty strip')
        if (allocated(error)) return
        call strip_moments(FOOTING_CIRCLE, r, 0.0_dp, 1.5_dp * r, 0.5_dp * r, r, r, m)
        call check(error, maxval(abs(m)), 0.0_dp, atol=0.0_dp, message='reversed strip')
        if (allocated(error)) return
        do c = 1, size(names)
            ! every case: distances exact in binary, the reference from the same numbers
            select case (c)
            case (1)
                dla = 0.0_dp
                dlb = 1.0e-12_dp * r
                ref = circle_ref(rq, -rq, real(dlb, qp) - rq)
            case (2)
                dha = 1.0e-12_dp * r
                dhb = 0.0_dp
                ref = circle_ref(rq, rq - real(dha, qp), rq)
            case (3)
                dla = 1.25_dp * r
                dlb = dla + 2.0_dp**(-30) * r
                ref = circle_ref(rq, real(dla, qp) - rq, real(dlb, qp) - rq)
            case (4)
                dla = 0.5_dp * r
                dlb = 1.875_dp * r
                ref = circle_ref(rq, real(dla, qp) - rq, real(dlb, qp) - rq)
            case (5)
                dla = 0.03125_dp * r
                dlb = 1.96875_dp * r
                ref = circle_ref(rq, real(dla, qp) - rq, real(dlb, qp) - rq)
            case (6)
                dha = 0.3_dp * r
                dhb = 0.0_dp
                ref = circle_ref(rq, rq - real(dha, qp), rq)
            case (7)
                dha = 1.9_dp * r
                dhb = 0.0_dp
                ref = circle_ref(rq, rq - real(dha, qp), rq)
            case default
                dla = 1.0e-9_dp * r
                dlb = 2.0_dp * r
                ref = circle_ref(rq, real(dla, qp) - rq, rq)
            end select
            select case (c)
            case (2, 6, 7)
                dla = 2.0_dp * r - dha
                dlb = 2.0_dp * r
            case default
                dha = 2.0_dp * r - dla
                dhb = 2.0_dp * r - dlb
            end select
            call strip_moments(FOOTING_CIRCLE, r, 0.0_dp, dla, dha, dlb, dhb, m)
            do j = 0, 2
                call check(error, m(j), real(ref(j), dp), rtol=2.0e-15_dp, &
                           atol=1.0e-15_dp * real(abs(ref(0)) * rq**j, dp), &
                           message=trim(names(c))//': m'//achar(48 + j))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_strip_circle

    subroutine test_strip_rectangle(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: b = 1.5_dp, al = 0.75_dp
        real(dp) :: m(0:2), w
        ! full rectangle 2b x 2 al: m0 = 4 al b, m1 = 0, m2 = 4 al b^3/3
        call strip_moments(FOOTING_RECTANGLE, b, al, 0.0_dp, 2.0_dp * b, 2.0_dp * b, 0.0_dp, m)
        call check(error, m(0), 4.0_dp * al * b, rtol=1.0e-16_dp, message='rect m0')
        if (allocated(error)) return
        call check(error, m(1), 0.0_dp, atol=0.0_dp, message='rect m1')
        if (allocated(error)) return
        call check(error, m(2), 4.0_dp * al * b**3 / 3.0_dp, rtol=3.0e-16_dp, message='rect m2')
        if (allocated(error)) return
        ! contact width w at the +b edge: strip [b - w, b]
        w = 1.0e-12_dp * b
        call strip_moments(FOOTING_RECTANGLE, b, al, 2.0_dp * b - w, w, 2.0_dp * b, 0.0_dp, m)
        call check(error, m(0), 2.0_dp * al * w, rtol=1.0e-16_dp, message='rect sliver m0')
        if (allocated(error)) return
        call check(error, m(1), al * w * (2.0_dp * b - w), rtol=3.0e-16_dp, &
                   message='rect sliver m1')
        if (allocated(error)) return
        call check(error, m(2), 2.0_dp * al * w * (b * b - b * w + w * w / 3.0_dp), &
                   rtol=4.0e-16_dp, message='rect sliver m2')
        if (allocated(error)) return
        ! interior strip [-0.25 b, 0.5 b]
        call strip_moments(FOOTING_RECTANGLE, b, al, 0.75_dp * b, 1.25_dp * b, 1.5_dp * b, &
                           0.5_dp * b, m)
        call check(error, m(0), 2.0_dp * al * 0.75_dp * b, rtol=1.0e-16_dp, message='rect m0 mid')
        if (allocated(error)) return
        call check(error, m(1), al * (0.25_dp - 0.0625_dp) * b * b, rtol=3.0e-16_dp, &
                   message='rect m1 mid')
        if (allocated(error)) return
        call check(error, m(2), 2.0_dp * al * (0.125_dp + 0.015625_dp) * b**3 / 3.0_dp, &
                   rtol=4.0e-16_dp, message='rect m2 mid')
        if (allocated(error)) return
    end subroutine test_strip_rectangle

end module test_winkler
