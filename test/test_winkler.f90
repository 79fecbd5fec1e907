!> Rigid footings on Winkler soil (doc/winkler.md): the contact integrals against Gauss-Legendre
!> quadrature in quad precision written here (slivers at an edge and in the interior, wide
!> strips, the full circle and rectangle), x - sin x against quad precision; the stiffness
!> formulas and shape factors; the pushover rows against 2-D quadrature of the pressure field
!> over the projected contact, the printed (long) and compact moment forms, the corrected
!> theta(b), continuity at the uplift, the small-angle table, the derived example, the block
!> closed forms, the rigid limit, the equivalent cylinder and bad input. Every expected value
!> is computed here independently.
module test_winkler
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_special, only: x_minus_sin
    use seispulse_roots, only: scalar_function, find_minimum
    use seispulse_winkler_contact, only: FOOTING_CIRCLE, FOOTING_RECTANGLE, strip_moments
    use seispulse_winkler, only: K_CONSTANT, K_VARYING, AXIS_LONG, AXIS_SHORT, WP_THETA, WP_B, &
                                 WP_POLE, WP_AREA, WP_SETTLEMENT, WP_K, WP_M_FOUND, WP_M_IMPOSED, &
                                 WP_FORCE, WP_NCOL, winkler_pushover_t, &
                                 halfspace_rocking_stiffness, winkler_modulus_circle, &
                                 rect_rocking_stiffness, winkler_modulus_rect, shape_factor, &
                                 varying_modulus, winkler_pushover, block_winkler_pushover, &
                                 winkler_master_curve, winkler_equivalent_cylinder
    use seispulse_cylinder, only: rocking_body_t, cylinder_props, block_props, rigid_pushover, &
                                  equivalent_cylinder
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_winkler

    integer, parameter :: qp = selected_real_kind(30)
    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(qp), parameter :: pi_q = 3.141592653589793238462643383279502884_qp
    integer, parameter :: n_gl = 40
    !> The derived example: R = 1 m, h = 3 m (half-height), E = 100 MPa, nu = 0.3,
    !> rho = 2.5 t/m^3, g = 9.81 m/s^2.
    real(dp), parameter :: ex_r = 1.0_dp, ex_h = 3.0_dp, ex_e = 100.0e6_dp, ex_nu = 0.3_dp
    real(dp), parameter :: ex_g = ex_e / (2.0_dp * (1.0_dp + ex_nu))
    real(dp), parameter :: ex_w = 2500.0_dp * pi * ex_r**2 * 2.0_dp * ex_h * 9.81_dp

    !> A parabola with its minimum at 0.3, value -2 (for the bounded minimiser).
    type, extends(scalar_function) :: parabola_fn
        integer :: calls = 0
    contains
        procedure :: eval => parabola_eval
    end type parabola_fn

contains

    subroutine collect_winkler(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('x - sin x: series and direct form against quad precision', &
                              test_x_minus_sin), &
                 new_unittest('strip moments, circle: full circle, slivers, wide strips vs' &
                              //' quad Gauss-Legendre', test_strip_circle), &
                 new_unittest('strip moments, rectangle: exact polynomials, slivers', &
                              test_strip_rectangle), &
                 new_unittest('bounded minimiser: interior minimum to full precision', &
                              test_minimiser), &
                 new_unittest('stiffness: K_R, k of circle and rectangles, shape factors' &
                              //' 1.258/1.216, varying k', test_stiffness), &
                 new_unittest('circle pushover rows = 2-D quadrature of the pressure field', &
                              test_circle_quadrature), &
                 new_unittest('circle: printed long moment form = compact form; A projected,' &
                              //' a centroid', test_circle_moment_forms), &
                 new_unittest('circle: corrected theta(b) with f(b), Phi(2R), continuity at' &
                              //' theta_up', test_circle_theta_b), &
                 new_unittest('small-angle curve: table to 4 digits, pushover at small angles', &
                              test_master_curve), &
                 new_unittest('derived example: 0.245/0.300 constant k, 0.283/0.317 varying k', &
                              test_derived_example), &
                 new_unittest('peaks and overturning: maxima and zero to full precision', &
                              test_peaks), &
                 new_unittest('block: uplift angle, theta(b''), both moment forms, quadrature', &
                              test_block), &
                 new_unittest('large k: the rigid pushover F = W tan(theta_c - theta)', &
                              test_rigid_limit), &
                 new_unittest('soft soil: no uplift before pi/4, full contact to pi/2', &
                              test_no_uplift), &
                 new_unittest('equivalent cylinder: same p, same peak imposed moment', &
                              test_equivalent_cylinder), &
                 new_unittest('bad input: messages name the parameter', test_bad_input)]
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

    function parabola_eval(self, x) result(y)
        class(parabola_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        self%calls = self%calls + 1
        y = 3.0_dp * (x - 0.3_dp)**2 - 2.0_dp
    end function parabola_eval

    subroutine test_minimiser(error)
        type(test_error), allocatable, intent(out) :: error
        type(parabola_fn) :: f
        real(dp) :: x, fx
        integer :: stat
        call find_minimum(f, -1.0_dp, 2.0_dp, x, fx, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'stat')
        if (allocated(error)) return
        call check(error, fx, -2.0_dp, rtol=2.0e-16_dp, message='minimum value')
        if (allocated(error)) return
        call check(error, x, 0.3_dp, atol=1.0e-7_dp, message='minimiser')
        if (allocated(error)) return
        call check(error, f%calls < 100, 'a few evaluations')
    end subroutine test_minimiser

    !> [G91] K_rx of a rectangle, written here: G/(1 - nu) I^0.75 (L/B)^0.25 (2.4 + 0.5 B/L).
    pure real(dp) function krx(g, nu, width, length)
        real(dp), intent(in) :: g, nu, width, length
        real(dp) :: bb, ll
        bb = width / 2
        ll = length / 2
        krx = g / (1 - nu) * (length * width**3 / 12)**0.75_dp * (ll / bb)**0.25_dp &
              * (2.4_dp + 0.5_dp * bb / ll)
    end function krx

    subroutine test_stiffness(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: g = 3.0e7_dp, nu = 0.3_dp, r = 1.3_dp
        real(dp) :: kr, k, ksq, f, kb, kb2, expect, a, u, chord, b
        integer :: stat, ax
        call halfspace_rocking_stiffness(g, nu, r, kr, stat)
        call check(error, kr, 8 * g * r**3 / (3 * (1 - nu)), rtol=4.0e-16_dp, message='K_R')
        if (allocated(error)) return
        call winkler_modulus_circle(g, nu, r, k, stat)
        call check(error, k, kr / (pi * r**4 / 4), rtol=4.0e-16_dp, message='k = K_R/I')
        if (allocated(error)) return
        ! rectangle rotating about its long axis (length > width)
        call rect_rocking_stiffness(g, nu, 1.0_dp, 3.0_dp, kr, stat, axis=ax)
        call check(error, ax, AXIS_LONG, 'axis of 1 x 3')
        if (allocated(error)) return
        call check(error, kr, krx(g, nu, 1.0_dp, 3.0_dp), rtol=1.0e-15_dp, message='K_rx')
        if (allocated(error)) return
        ! about its short axis: K_ry = 3 G/(1 - nu) I^0.75 (L/B)^0.15, I = 1 3^3/12
        call rect_rocking_stiffness(g, nu, 3.0_dp, 1.0_dp, kr, stat, axis=ax)
        call check(error, ax, AXIS_SHORT, 'axis of 3 x 1')
        if (allocated(error)) return
        call check(error, kr, 3 * g / (1 - nu) * 2.25_dp**0.75_dp * 3.0_dp**0.15_dp, &
                   rtol=1.0e-15_dp, message='K_ry')
        if (allocated(error)) return
        call winkler_modulus_rect(g, nu, 3.0_dp, 1.0_dp, k, stat)
        call check(error, k, kr / 2.25_dp, rtol=1.0e-15_dp, message='k rect = K_R/I')
        if (allocated(error)) return
        ! shape factors by definition, to 4 digits and to rounding
        call shape_factor(AXIS_LONG, f, stat)
        call check(error, nint(f * 1.0e4_dp), 12581, 'shape factor K_rx 1.2581')
        if (allocated(error)) return
        call winkler_modulus_circle(g, nu, r, k, stat)
        call winkler_modulus_rect(g, nu, 2 * r, 2 * r, ksq, stat)
        call check(error, f, k / ksq, rtol=1.0e-15_dp, message='shape factor = k_c/k_sq')
        if (allocated(error)) return
        call shape_factor(AXIS_SHORT, f, stat)
        call check(error, nint(f * 1.0e4_dp), 12162, 'shape factor K_ry 1.2162')
        if (allocated(error)) return
        call check(error, f, 32 * (4.0_dp / 3)**0.25_dp / (9 * pi), rtol=1.0e-15_dp, &
                   message='shape factor K_ry closed form')
        if (allocated(error)) return
        ! varying k equals k at full contact, both readings and the rectangle
        call varying_modulus(FOOTING_CIRCLE, r, 0.0_dp, k, 2 * r, kb, stat)
        call check(error, kb, k, rtol=0.0_dp, message='varying k at full contact')
        if (allocated(error)) return
        call varying_modulus(FOOTING_CIRCLE, r, 0.0_dp, k, 2 * r, kb, stat, reading=AXIS_SHORT)
        call check(error, kb, k, rtol=0.0_dp, message='varying k at full contact, short')
        if (allocated(error)) return
        call varying_modulus(FOOTING_RECTANGLE, r, 0.4_dp, k, 2 * r, kb, stat)
        call check(error, kb, k, rtol=0.0_dp, message='varying k rect at full contact')
        if (allocated(error)) return
        ! circle at b = 0.6 r: shape factor x K_rx/I of b x chord through the centroid,
        ! with k the halfspace value (so the result is the thesis's recipe)
        b = 0.6_dp * r
        u = acos((r - b) / r)
        a = (2.0_dp / 3) * (r * sin(u))**3 / (r * r * (u - sin(u) * cos(u)))
        chord = 2 * sqrt(r * r - a * a)
        call shape_factor(AXIS_LONG, f, stat)
        expect = f * krx(g, nu, b, chord) / (chord * b**3 / 12)
        call varying_modulus(FOOTING_CIRCLE, r, 0.0_dp, k, b, kb, stat)
        call check(error, kb, expect, rtol=1.0e-13_dp, message='varying k circle b = 0.6 r')
        if (allocated(error)) return
        call check(error, chord >= b, 'chord through the pole >= b')
        if (allocated(error)) return
        ! rectangle b' x 2 alpha with alpha = 0.4 r < b' = 1.2 r: K_ry side, no shape factor
        call varying_modulus(FOOTING_RECTANGLE, r, 0.4_dp, k, 1.2_dp * r, kb, stat)
        call winkler_modulus_rect(g, nu, 1.2_dp * r, 0.8_dp, kb2, stat)
        call winkler_modulus_rect(g, nu, 2 * r, 0.8_dp, ksq, stat)
        call check(error, kb, k * kb2 / ksq, rtol=1.0e-14_dp, message='varying k rectangle')
    end subroutine test_stiffness

    !> Quadrature over the projected contact of a circle of radius r tilted by theta: the
    !> strip s in [c, r] (x = s cos theta), p = k (v + x tan theta). Returns the integrals of
    !> p, x p and 1 and of x (qp), with x = r cos(theta) cos(phi), phi in [0, acos(c/r)],
    !> Gauss-Legendre in phi and in y.
    subroutine circle_contact_quad(r, c, theta, k, v, q)
        real(qp), intent(in) :: r, c, theta, k, v
        real(qp), intent(out) :: q(4)
        real(qp) :: xg(n_gl), wg(n_gl), yg(4), wy(4), phi0, phi, x, ymax, dxw, p, y
        integer :: i, j
        call gauss_legendre(xg, wg)
        call gauss_legendre(yg, wy)
        phi0 = acos(c / r)
        q = 0.0_qp
        do i = 1, n_gl
            phi = 0.5_qp * phi0 * (1.0_qp + xg(i))
            x = r * cos(theta) * cos(phi)
            ymax = r * sin(phi)
            dxw = 0.5_qp * phi0 * wg(i) * r * cos(theta) * sin(phi)
            do j = 1, 4
                y = ymax * yg(j)
                p = k * (v + x * tan(theta)) + 0.0_qp * y
                q(1) = q(1) + dxw * ymax * wy(j) * p
                q(2) = q(2) + dxw * ymax * wy(j) * x * p
                q(3) = q(3) + dxw * ymax * wy(j)
                q(4) = q(4) + dxw * ymax * wy(j) * x
            end do
        end do
    end subroutine circle_contact_quad

    subroutine test_circle_quadrature(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, th(5), curve(5, WP_NCOL), c
        type(winkler_pushover_t) :: res
        real(qp) :: q(4)
        integer :: stat, i, m, km
        call winkler_modulus_circle(ex_g, ex_nu, ex_r, k, stat)
        th = [0.0005_dp, 0.002_dp, 0.02_dp, 0.1_dp, 0.28_dp]
        do m = 1, 2
            km = K_CONSTANT
            if (m == 2) km = K_VARYING
            call winkler_pushover(ex_r, ex_h, ex_w, k, th, curve, res, stat, k_method=km)
            call check(error, stat, SEISPULSE_SUCCESS, 'stat')
            if (allocated(error)) return
            do i = 1, size(th)
                c = ex_r - curve(i, WP_B)
                if (i == 1) c = -ex_r
                call circle_contact_quad(real(ex_r, qp), real(c, qp), real(th(i), qp), &
                                         real(curve(i, WP_K), qp), &
                                         real(curve(i, WP_SETTLEMENT), qp), q)
                call check(error, curve(i, WP_THETA), th(i), rtol=0.0_dp, message='theta')
                if (allocated(error)) return
                call check(error, real(q(1), dp), ex_w, rtol=1.0e-12_dp, &
                           message='vertical equilibrium, row '//achar(48 + i))
                if (allocated(error)) return
                call check(error, curve(i, WP_M_FOUND), real(q(2), dp), rtol=1.0e-12_dp, &
                           message='foundation moment, row '//achar(48 + i))
                if (allocated(error)) return
                call check(error, curve(i, WP_AREA), real(q(3), dp), rtol=1.0e-12_dp, &
                           message='projected area, row '//achar(48 + i))
                if (allocated(error)) return
                call check(error, curve(i, WP_POLE), real(q(4) / q(3) / cos(th(i)), dp), &
                           rtol=1.0e-12_dp, atol=1.0e-15_dp, message='pole = centroid, row ' &
                           //achar(48 + i))
                if (allocated(error)) return
                ! no tension: zero pressure at the contact edge after uplift
                if (i > 1) then
                    call check(error, curve(i, WP_SETTLEMENT) + c * sin(th(i)), 0.0_dp, &
                               atol=1.0e-15_dp, message='zero pressure at the contact edge')
                    if (allocated(error)) return
                end if
                call check(error, curve(i, WP_M_IMPOSED), &
                           curve(i, WP_M_FOUND) - ex_w * ex_h * sin(th(i)), rtol=1.0e-14_dp, &
                           message='imposed moment')
                if (allocated(error)) return
                call check(error, curve(i, WP_FORCE), &
                           curve(i, WP_M_IMPOSED) / (ex_h * cos(th(i))), rtol=1.0e-14_dp, &
                           message='force')
                if (allocated(error)) return
            end do
        end do
    end subroutine test_circle_quadrature

    subroutine test_circle_moment_forms(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, th(3), curve(3, WP_NCOL), r, b, c, s3, j2, a0, area, long, wrong
        type(winkler_pushover_t) :: res
        integer :: stat, i
        r = ex_r
        call winkler_modulus_circle(ex_g, ex_nu, r, k, stat)
        th = [0.005_dp, 0.05_dp, 0.3_dp]
        call winkler_pushover(r, ex_h, ex_w, k, th, curve, res, stat)
        do i = 1, 3
            b = curve(i, WP_B)
            c = r - b
            s3 = (2 * r * b - b * b)**1.5_dp
            ! the printed bracket: J2 = (R^2 - 2 (R - b)^2)(R - b) S/4 + R^4/4 (pi/2 - asin)
            j2 = (r * r - 2 * c * c) * c * sqrt(2 * r * b - b * b) / 4 &
                 + r**4 / 4 * (pi / 2 - asin(c / r))
            area = curve(i, WP_AREA)
            long = k * cos(th(i))**2 * sin(th(i)) * j2 + (ex_w / area - curve(i, WP_POLE) * k &
                   * sin(th(i))) * (2.0_dp / 3) * cos(th(i))**2 * s3
            call check(error, curve(i, WP_M_FOUND), long, rtol=1.0e-11_dp, &
                       message='printed long form = compact form')
            if (allocated(error)) return
            ! A must be the projected area: the unprojected segment area gives another M
            a0 = r * r * acos(c / r) - c * sqrt(2 * r * b - b * b)
            call check(error, area, a0 * cos(th(i)), rtol=1.0e-13_dp, message='A = A0 cos')
            if (allocated(error)) return
            wrong = k * cos(th(i))**2 * sin(th(i)) * j2 + (ex_w / a0 - curve(i, WP_POLE) * k &
                    * sin(th(i))) * (2.0_dp / 3) * cos(th(i))**2 * s3
            if (i == 3) then
                call check(error, abs(wrong - long) > 1.0e-3_dp * abs(long), &
                           'the unprojected area A0 changes the moment (meaning of A)')
                if (allocated(error)) return
            end if
            ! a is the centroid of the segment, not the middle of the strip
            call check(error, curve(i, WP_POLE), (2.0_dp / 3) * sqrt(2 * r * b - b * b)**3 / a0, &
                       rtol=1.0e-12_dp, message='a = J1/A0')
            if (allocated(error)) return
            call check(error, abs(curve(i, WP_POLE) - (r - b / 2)) > 1.0e-3_dp * r, &
                       'the pole is not the middle of the contact strip')
            if (allocated(error)) return
        end do
    end subroutine test_circle_moment_forms

    subroutine test_circle_theta_b(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: bs(3) = [0.2_dp, 0.5_dp, 1.5_dp]
        real(dp) :: k, r, b, c, sq, f_b, theta_b, theta_garbled, th(3), curve(3, WP_NCOL)
        type(winkler_pushover_t) :: res
        integer :: stat, i
        r = ex_r
        call winkler_modulus_circle(ex_g, ex_nu, r, k, stat)
        do i = 1, 3
            b = bs(i) * r
            c = r - b
            sq = sqrt(2 * r * b - b * b)
            ! the corrected printed form: theta = asin(6 W/(2 k S^3 - 3 R^2 k (R - b) f(b)))/2,
            ! f(b) = acos((R - b)/R) - (R - b) S/R^2 (f(b) recovered)
            f_b = acos(c / r) - c * sq / r**2
            theta_b = 0.5_dp * asin(6 * ex_w / (2 * k * sq**3 - 3 * r * r * k * c * f_b))
            ! f(b) = acos((R - b)/R) alone (the garbled transcript) gives another theta
            theta_garbled = 6 * ex_w / (2 * k * sq**3 - 3 * r * r * k * c * acos(c / r))
            if (theta_garbled > 0.0_dp .and. theta_garbled < 1.0_dp) then
                theta_garbled = 0.5_dp * asin(theta_garbled)
            else
                theta_garbled = pi / 2    ! no equilibrium at all by the garbled form
            end if
            th = [theta_b, theta_b, theta_garbled]
            call winkler_pushover(r, ex_h, ex_w, k, th, curve, res, stat)
            call check(error, curve(1, WP_B), b, rtol=1.0e-11_dp, message='b(theta(b))')
            if (allocated(error)) return
            if (.not. ieee_is_nan(curve(3, WP_B))) then
                call check(error, abs(curve(3, WP_B) - b) > 1.0e-4_dp * b, &
                           'the garbled f(b) gives another contact width')
                if (allocated(error)) return
            end if
        end do
        ! Phi(2R) = pi R^3: theta(2R) = theta_up, and continuity across theta_up
        call check(error, res%theta_up, 0.5_dp * asin(2 * ex_w / (k * pi * r**3)), &
                   rtol=1.0e-15_dp, message='theta_up')
        if (allocated(error)) return
        th = [res%theta_up, res%theta_up * (1 + 1.0e-9_dp), res%theta_up * (1 + 1.0e-6_dp)]
        call winkler_pushover(r, ex_h, ex_w, k, th, curve, res, stat)
        call check(error, curve(2, WP_B), 2 * r, rtol=1.0e-5_dp, message='b just past theta_up')
        if (allocated(error)) return
        do i = WP_AREA, WP_FORCE
            call check(error, curve(2, i), curve(1, i), rtol=1.0e-7_dp, &
                       atol=1.0e-9_dp * abs(curve(3, i)), message='continuity at theta_up')
            if (allocated(error)) return
        end do
        ! M = W R/4 at theta_up (the kern of the circle), to O(theta_up^2)
        call check(error, curve(1, WP_M_FOUND), ex_w * r / 4, rtol=1.0e-5_dp, &
                   message='M(theta_up) = W R/4')
    end subroutine test_circle_theta_b

    subroutine test_master_curve(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: xs(6) = [1.0_dp, 2.0_dp, 3.0_dp, 5.0_dp, 10.0_dp, 100.0_dp]
        real(dp), parameter :: tb(6, 4) = reshape([ &
            1.0_dp, 0.7246_dp, 0.6067_dp, 0.4876_dp, 0.3646_dp, 0.1420_dp, &
            0.0_dp, 0.1950_dp, 0.3117_dp, 0.4378_dp, 0.5741_dp, 0.8311_dp, &
            1.0_dp, 0.8441_dp, 0.6770_dp, 0.4790_dp, 0.2785_dp, 0.0352_dp, &
            0.25_dp, 0.4220_dp, 0.5078_dp, 0.5987_dp, 0.6962_dp, 0.8795_dp], [6, 4])
        real(dp) :: kr(6), mr(6), br(6), ar(6), k, th(1), curve(1, WP_NCOL), beta
        real(dp) :: kr1, mr1, br1, ar1
        type(winkler_pushover_t) :: res
        integer :: i, stat
        call winkler_master_curve(FOOTING_CIRCLE, xs, kr, mr, br, ar)
        do i = 1, 6
            call check(error, br(i), tb(i, 1), atol=5.0e-5_dp, message='b/2R')
            if (allocated(error)) return
            call check(error, ar(i), tb(i, 2), atol=5.0e-5_dp, message='a/R')
            if (allocated(error)) return
            call check(error, kr(i), tb(i, 3), atol=5.0e-5_dp, message='K_sec/K_0')
            if (allocated(error)) return
            call check(error, mr(i), tb(i, 4), atol=5.0e-5_dp, message='M/(W R)')
            if (allocated(error)) return
        end do
        ! the same from a pushover at small angles (stiff soil): theta/theta_up = 10
        k = 1.0e12_dp
        th(1) = 10 * 0.5_dp * asin(2 * ex_w / (k * pi))
        call winkler_pushover(1.0_dp, ex_h, ex_w, k, th, curve, res, stat)
        call check(error, curve(1, WP_B) / 2, br(5), rtol=1.0e-5_dp, message='pushover b/2R')
        if (allocated(error)) return
        call check(error, curve(1, WP_M_FOUND) / ex_w, mr(5), rtol=1.0e-5_dp, &
                   message='pushover M/(W R)')
        if (allocated(error)) return
        ! limits: asymptote K/K_0 -> 4/x at large x, M -> W R; infinity; bad x
        call winkler_master_curve(FOOTING_CIRCLE, 1.0e8_dp, kr1, mr1, br1, ar1)
        call check(error, kr1 * 1.0e8_dp / 4, 1.0_dp, rtol=1.0e-2_dp, message='4/x asymptote')
        if (allocated(error)) return
        call winkler_master_curve(FOOTING_CIRCLE, ieee_value(1.0_dp, ieee_positive_inf), kr1, &
                                  mr1, br1, ar1)
        call check(error, mr1, 1.0_dp, rtol=0.0_dp, message='M/(W R) at x = inf')
        if (allocated(error)) return
        call winkler_master_curve(FOOTING_CIRCLE, -1.0_dp, kr1, mr1, br1, ar1)
        call check(error, ieee_is_nan(kr1) .and. ieee_is_nan(mr1), 'x < 0 gives NaN')
        if (allocated(error)) return
        ! rectangle: kern b/3 at x = 1; beta = x^(-1/2)
        call winkler_master_curve(FOOTING_RECTANGLE, 1.0_dp, kr1, mr1, br1, ar1)
        call check(error, mr1, 1.0_dp / 3, rtol=1.0e-15_dp, message='rect M/(W b) at x = 1')
        if (allocated(error)) return
        call winkler_master_curve(FOOTING_RECTANGLE, 4.0_dp, kr1, mr1, br1, ar1)
        beta = 0.5_dp
        call check(error, kr1, beta**2 * (3 - 2 * beta), rtol=1.0e-15_dp, message='rect K/K0')
        if (allocated(error)) return
        call check(error, mr1, kr1 * 4 / 3, rtol=1.0e-15_dp, message='rect M/(W b)')
        if (allocated(error)) return
        call check(error, ar1, 1 - beta, rtol=1.0e-15_dp, message='rect a/b')
    end subroutine test_master_curve

    subroutine test_derived_example(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, th(1), curve(1, WP_NCOL)
        type(winkler_pushover_t) :: res
        integer :: stat, m
        call winkler_modulus_circle(ex_g, ex_nu, ex_r, k, stat)
        th(1) = 0.1_dp
        call winkler_pushover(ex_r, ex_h, ex_w, k, th, curve, res, stat)
        call check(error, nint(res%max_force_over_weight * 1000), 245, 'constant k: max F/W')
        if (allocated(error)) return
        call check(error, nint(res%theta_overturn * 1000), 300, 'constant k: overturning')
        if (allocated(error)) return
        th(1) = res%theta_overturn
        call winkler_pushover(ex_r, ex_h, ex_w, k, th, curve, res, stat)
        call check(error, nint(curve(1, WP_B) / (2 * ex_r) * 1000), 85, 'b/2R at overturning')
        if (allocated(error)) return
        call check(error, nint(curve(1, WP_POLE) / ex_r * 100), 90, 'a/R at overturning')
        if (allocated(error)) return
        ! varying k: both readings of the shape factor reproduce the digits given
        do m = AXIS_LONG, AXIS_SHORT
            th(1) = 0.1_dp
            call winkler_pushover(ex_r, ex_h, ex_w, k, th, curve, res, stat, &
                                  k_method=K_VARYING, reading=m)
            call check(error, nint(res%max_force_over_weight * 1000), 283, 'varying: max F/W')
            if (allocated(error)) return
            call check(error, nint(res%theta_overturn * 1000), 317, 'varying: overturning')
            if (allocated(error)) return
            th(1) = res%theta_overturn
            call winkler_pushover(ex_r, ex_h, ex_w, k, th, curve, res, stat, &
                                  k_method=K_VARYING, reading=m)
            call check(error, nint(curve(1, WP_B) / (2 * ex_r) * 1000), 18, &
                       'varying: b/2R at overturning')
            if (allocated(error)) return
            call check(error, nint(curve(1, WP_POLE) / ex_r * 100), 98, &
                       'varying: a/R at overturning')
            if (allocated(error)) return
        end do
    end subroutine test_derived_example

    subroutine test_peaks(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, th(5), curve(5, WP_NCOL), d
        type(winkler_pushover_t) :: res, res2
        integer :: stat, m, i
        call winkler_modulus_circle(ex_g, ex_nu, ex_r, k, stat)
        do m = K_CONSTANT, K_VARYING
            th(1) = 0.1_dp
            call winkler_pushover(ex_r, ex_h, ex_w, k, th(1:1), curve(1:1, :), res, stat, &
                                  k_method=m)
            ! the curve at the peak angles gives the peak values
            th(1:2) = [res%theta_at_max, res%theta_at_max_moment]
            th(3) = res%theta_overturn
            call winkler_pushover(ex_r, ex_h, ex_w, k, th(1:3), curve(1:3, :), res2, stat, &
                                  k_method=m)
            call check(error, curve(1, WP_FORCE) / ex_w, res%max_force_over_weight, &
                       rtol=1.0e-12_dp, message='F/W at theta_at_max')
            if (allocated(error)) return
            call check(error, curve(2, WP_M_IMPOSED), res%max_moment, rtol=1.0e-12_dp, &
                       message='M_imp at theta_at_max_moment')
            if (allocated(error)) return
            call check(error, curve(3, WP_M_IMPOSED), 0.0_dp, atol=1.0e-9_dp * ex_w * ex_r, &
                       message='M_imp at theta_overturn')
            if (allocated(error)) return
            ! neighbours are lower (a maximum), and a sample grid never exceeds it
            d = 1.0e-3_dp * res%theta_at_max
            th = [res%theta_at_max - d, res%theta_at_max + d, (0.002_dp * i, i = 1, 3)]
            call winkler_pushover(ex_r, ex_h, ex_w, k, th, curve, res2, stat, k_method=m)
            call check(error, maxval(curve(:, WP_FORCE)) / ex_w <= res%max_force_over_weight, &
                       'F/W below its peak')
            if (allocated(error)) return
            ! past the end of the branch: NaN
            th(1) = 0.8_dp
            call winkler_pushover(ex_r, ex_h, ex_w, k, th(1:1), curve(1:1, :), res2, stat, &
                                  k_method=m)
            call check(error, ieee_is_nan(curve(1, WP_B)) .and. ieee_is_nan(curve(1, WP_FORCE)), &
                       'theta > pi/4: no equilibrium (NaN)')
            if (allocated(error)) return
            call check(error, res2%theta_end, pi / 4, rtol=0.0_dp, message='theta_end')
            if (allocated(error)) return
            ! a squat body (theta_c = atan(10) > pi/4) on stiff soil: M_imp > 0 to the end
            ! of the branch, no overturning on it
            call winkler_pushover(1.0_dp, 0.1_dp, ex_w, 1.0e12_dp, th(1:1), curve(1:1, :), &
                                  res2, stat, k_method=m)
            call check(error, ieee_is_nan(res2%theta_overturn), 'no overturning: NaN')
            if (allocated(error)) return
        end do
    end subroutine test_peaks

    subroutine test_block(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: b = 0.8_dp, al = 1.1_dp, h = 2.5_dp, w = 3.0e5_dp, k = 5.0e7_dp
        real(dp) :: th(4), curve(4, WP_NCOL), bp, c, tup, long, compact, s, co, area, a
        type(winkler_pushover_t) :: res
        integer :: stat, i
        tup = 0.5_dp * asin(w / (2 * al * b * b * k))
        bp = 0.7_dp * b
        th = [0.5_dp * tup, tup, 0.5_dp * asin(2 * w / (al * bp * bp * k)), 0.3_dp]
        call block_winkler_pushover(b, al, h, w, k, th, curve, res, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'stat')
        if (allocated(error)) return
        call check(error, res%theta_up, tup, rtol=1.0e-15_dp, message='uplift angle')
        if (allocated(error)) return
        ! full contact: M = 4/3 alpha b^3 k cos^2 sin, F = 2 alpha b^3 k sin 2t/(3h) - W tan
        call check(error, curve(1, WP_M_FOUND), 4 * al * b**3 * k * cos(th(1))**2 &
                   * sin(th(1)) / 3, rtol=1.0e-14_dp, message='block full-contact M')
        if (allocated(error)) return
        call check(error, curve(1, WP_FORCE), 2 * al * b**3 * k * sin(2 * th(1)) / (3 * h) &
                   - w * tan(th(1)), rtol=1.0e-13_dp, message='block full-contact F')
        if (allocated(error)) return
        ! theta(b') = asin(2 W/(alpha b'^2 k))/2
        call check(error, curve(3, WP_B), bp, rtol=1.0e-14_dp, message='b''(theta(b''))')
        if (allocated(error)) return
        do i = 3, 4
            bp = curve(i, WP_B)
            c = b - bp
            s = sin(th(i))
            co = cos(th(i))
            area = 2 * al * bp * co
            a = b - bp / 2
            call check(error, curve(i, WP_AREA), area, rtol=1.0e-14_dp, message='A projected')
            if (allocated(error)) return
            call check(error, curve(i, WP_POLE), a, rtol=1.0e-14_dp, message='pole')
            if (allocated(error)) return
            ! printed long form with W/A and a, and the compact form
            long = al * k * sin(2 * th(i)) * co * (b**3 - c**3) / 3 &
                   + al * (w / area - a * k * s) * bp * (2 * b - bp) * co * co
            compact = 2 * al * k * s * co * co * ((b**3 - c**3) / 3 - c * (b * b - c * c) / 2)
            call check(error, curve(i, WP_M_FOUND), long, rtol=1.0e-11_dp, &
                       message='block printed long form')
            if (allocated(error)) return
            call check(error, curve(i, WP_M_FOUND), compact, rtol=1.0e-11_dp, &
                       message='block compact form')
            if (allocated(error)) return
            ! vertical equilibrium: k cos(theta) int (s - c) sin(theta) 2 alpha ds = W
            call check(error, k * co * s * al * bp * bp, w, rtol=1.0e-13_dp, &
                       message='block vertical equilibrium')
            if (allocated(error)) return
        end do
        ! varying k: the modulus of the contact rectangle b' x 2 alpha; equilibrium holds
        call block_winkler_pushover(b, al, h, w, k, th, curve, res, stat, k_method=K_VARYING)
        do i = 3, 4
            bp = curve(i, WP_B)
            call check(error, curve(i, WP_K) * cos(th(i)) * sin(th(i)) * al * bp * bp, w, &
                       rtol=1.0e-12_dp, message='block varying: vertical equilibrium')
            if (allocated(error)) return
        end do
        call check(error, res%theta_overturn > 0.0_dp .and. res%theta_overturn < atan(b / h), &
                   'block varying: overturning below theta_c')
        if (allocated(error)) return
        call block_jump(error)
    end subroutine test_block

    !> A block longer in the rocking direction (alpha < b): its contact rectangle b' x 2 alpha
    !> passes through the square, where [G91]'s K_ry (3.0) and K_rx (2.9) differ; the tilts in
    !> the gap between theta(b' = 2 alpha) on either side have no equilibrium (NaN), every
    !> other point is in equilibrium.
    subroutine block_jump(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1000
        real(dp), parameter :: b = 1.0_dp, al = 0.3_dp, h = 2.5_dp, w = 2.0e5_dp, k = 5.0e7_dp
        real(dp) :: th(n), curve(n, WP_NCOL), kry_full, k_hi, k_lo, th_lo, th_hi, sq
        type(winkler_pushover_t) :: res
        integer :: stat, i, nnan
        do i = 1, n
            th(i) = 0.04_dp * i / n
        end do
        call block_winkler_pushover(b, al, h, w, k, th, curve, res, stat, k_method=K_VARYING)
        call check(error, stat, SEISPULSE_SUCCESS, 'stat')
        if (allocated(error)) return
        ! K_R/I up to G/(1 - nu): full 2b x 2 alpha by K_ry, the square 2 alpha by K_ry/K_rx
        kry_full = 3 * (2 * al * (2 * b)**3 / 12)**(-0.25_dp) * (b / al)**0.15_dp
        sq = (2 * al * (2 * al)**3 / 12)**(-0.25_dp)
        k_hi = k * 3 * sq / kry_full
        k_lo = k * 2.9_dp * sq / kry_full
        th_lo = 0.5_dp * asin(2 * w / (al * (2 * al)**2 * k_hi))
        th_hi = 0.5_dp * asin(2 * w / (al * (2 * al)**2 * k_lo))
        nnan = 0
        do i = 1, n
            if (ieee_is_nan(curve(i, WP_B))) then
                nnan = nnan + 1
                call check(error, th(i) > th_lo .and. th(i) < th_hi, 'NaN only inside the gap')
                if (allocated(error)) return
            else if (th(i) > res%theta_up) then
                call check(error, curve(i, WP_K) * cos(th(i)) * sin(th(i)) * al &
                           * curve(i, WP_B)**2, w, rtol=1.0e-10_dp, &
                           message='equilibrium outside the gap')
                if (allocated(error)) return
            else
                call check(error, curve(i, WP_K) * curve(i, WP_SETTLEMENT) * 4 * al * b &
                           * cos(th(i)), w, rtol=1.0e-14_dp, message='full-contact equilibrium')
                if (allocated(error)) return
            end if
        end do
        call check(error, nnan > 0, 'the gap has grid points')
    end subroutine block_jump

    subroutine test_rigid_limit(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: th(3), curve(3, WP_NCOL), f, mo
        type(rocking_body_t) :: body
        type(winkler_pushover_t) :: res
        logical :: stable
        integer :: stat, i
        ! the imposed moment tends to the rigid moment about the pivot, W R sin(theta_c -
        ! theta); the force, carried by the base, to M/(h cos theta) = W tan(theta_c - theta)
        ! (1 + (r/h) tan theta) (the rigid F acts through the pivot)
        call cylinder_props(1.0_dp, 3.0_dp, 5.0e4_dp, 9.81_dp, body, stat)
        th = [0.05_dp, 0.1_dp, 0.2_dp]
        call winkler_pushover(1.0_dp, 3.0_dp, body%weight, 1.0e18_dp, th, curve, res, stat)
        do i = 1, 3
            call rigid_pushover(body, th(i), f, mo, stable, stat)
            call check(error, curve(i, WP_M_IMPOSED), mo, rtol=1.0e-4_dp, &
                       message='M_imp rigid limit')
            if (allocated(error)) return
            call check(error, curve(i, WP_FORCE), f * (1 + tan(th(i)) / 3), rtol=1.0e-4_dp, &
                       message='F rigid limit')
            if (allocated(error)) return
        end do
        call check(error, res%theta_overturn, body%theta_c, rtol=1.0e-4_dp, &
                   message='overturning angle -> theta_c')
        if (allocated(error)) return
        call check(error, res%max_force_over_weight, tan(body%theta_c), rtol=1.0e-3_dp, &
                   message='peak F/W -> tan theta_c')
        if (allocated(error)) return
        call block_props(0.6_dp, 2.0_dp, 5.0e4_dp, 9.81_dp, body, stat)
        call block_winkler_pushover(0.6_dp, 0.5_dp, 2.0_dp, body%weight, 1.0e18_dp, th, curve, &
                                    res, stat)
        do i = 1, 3
            call rigid_pushover(body, th(i), f, mo, stable, stat)
            call check(error, curve(i, WP_M_IMPOSED), mo, rtol=1.0e-4_dp, &
                       message='block M_imp rigid limit')
            if (allocated(error)) return
        end do
        call check(error, res%theta_overturn, body%theta_c, rtol=1.0e-4_dp, &
                   message='block overturning angle -> theta_c')
    end subroutine test_rigid_limit

    subroutine test_no_uplift(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: th(3), curve(3, WP_NCOL), k
        type(winkler_pushover_t) :: res
        integer :: stat
        ! 2 W/(k pi R^3) = 1.5 > 1
        k = 2 * ex_w / (1.5_dp * pi)
        th = [0.3_dp, 1.0_dp, 1.6_dp]
        call winkler_pushover(ex_r, ex_h, ex_w, k, th, curve, res, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'stat')
        if (allocated(error)) return
        call check(error, ieee_is_nan(res%theta_up), 'theta_up NaN')
        if (allocated(error)) return
        call check(error, res%theta_end, pi / 2, rtol=0.0_dp, message='theta_end = pi/2')
        if (allocated(error)) return
        call check(error, curve(2, WP_M_FOUND), pi * k * cos(1.0_dp)**2 * sin(1.0_dp) / 4, &
                   rtol=1.0e-14_dp, message='full contact at 1 rad')
        if (allocated(error)) return
        call check(error, curve(2, WP_SETTLEMENT), ex_w / (k * pi * cos(1.0_dp)), &
                   rtol=1.0e-14_dp, message='settlement W/(k pi R^2 cos)')
        if (allocated(error)) return
        call check(error, ieee_is_nan(curve(3, WP_FORCE)), 'theta >= pi/2: NaN')
        if (allocated(error)) return
        ! W h > K_R: unstable from the start
        call check(error, res%theta_overturn, 0.0_dp, atol=0.0_dp, message='overturn at 0')
        if (allocated(error)) return
        call check(error, res%max_moment, 0.0_dp, atol=0.0_dp, message='no positive peak')
    end subroutine test_no_uplift

    subroutine test_equivalent_cylinder(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: al = 0.75_dp, k = 8.0e7_dp
        type(rocking_body_t) :: blk, cyl, rig
        type(winkler_pushover_t) :: rb, rc
        real(dp) :: th(1), curve(1, WP_NCOL)
        integer :: stat, m
        call block_props(0.5_dp, 2.0_dp, 1.2e4_dp, 9.81_dp, blk, stat)
        th(1) = 0.05_dp
        do m = K_CONSTANT, K_VARYING
            call winkler_equivalent_cylinder(blk, al, k, cyl, stat, k_method=m)
            call check(error, stat, SEISPULSE_SUCCESS, 'stat')
            if (allocated(error)) return
            call block_winkler_pushover(blk%r, al, blk%h, blk%weight, k, th, curve, rb, stat, &
                                        k_method=m)
            call winkler_pushover(cyl%r, cyl%h, cyl%weight, k, th, curve, rc, stat, k_method=m)
            call check(error, rc%max_moment, rb%max_moment, rtol=1.0e-10_dp, &
                       message='same peak imposed moment')
            if (allocated(error)) return
            call check(error, cyl%p, blk%p, rtol=1.0e-13_dp, message='same p')
            if (allocated(error)) return
            call check(error, cyl%theta_c, blk%theta_c, rtol=1.0e-13_dp, message='slenderness')
            if (allocated(error)) return
        end do
        ! stiff soil: the rigid equivalent (m_c r_c = m_b b)
        call winkler_equivalent_cylinder(blk, al, 1.0e22_dp, cyl, stat)
        call equivalent_cylinder(blk, rig, stat)
        call check(error, cyl%mass, rig%mass, rtol=1.0e-4_dp, message='rigid limit mass')
    end subroutine test_equivalent_cylinder

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: th(2), curve(2, WP_NCOL), bad_curve(2, 3), v, nan_, inf_
        type(winkler_pushover_t) :: res
        type(rocking_body_t) :: cyl, blk
        character(len=200) :: msg
        integer :: stat
        nan_ = ieee_value(1.0_dp, ieee_quiet_nan)
        inf_ = ieee_value(1.0_dp, ieee_positive_inf)
        th = [0.1_dp, 0.2_dp]
        call expect_bad('g_mod')
        call winkler_modulus_circle(-1.0_dp, 0.3_dp, 1.0_dp, v, stat, msg)
        call expect_stat('g_mod')
        if (allocated(error)) return
        call halfspace_rocking_stiffness(1.0e7_dp, 0.5_dp, 1.0_dp, v, stat, msg)
        call expect_stat('nu')
        if (allocated(error)) return
        call rect_rocking_stiffness(1.0e7_dp, 0.3_dp, nan_, 1.0_dp, v, stat, msg)
        call expect_stat('width')
        if (allocated(error)) return
        call shape_factor(3, v, stat, msg)
        call expect_stat('reading')
        if (allocated(error)) return
        call varying_modulus(FOOTING_CIRCLE, 1.0_dp, 0.0_dp, 1.0e8_dp, 2.5_dp, v, stat, msg)
        call expect_stat('b')
        if (allocated(error)) return
        call winkler_pushover(inf_, 3.0_dp, 1.0e5_dp, 1.0e8_dp, th, curve, res, stat, msg)
        call expect_stat('r')
        if (allocated(error)) return
        call winkler_pushover(1.0_dp, 0.0_dp, 1.0e5_dp, 1.0e8_dp, th, curve, res, stat, msg)
        call expect_stat('h')
        if (allocated(error)) return
        call winkler_pushover(1.0_dp, 3.0_dp, -1.0e5_dp, 1.0e8_dp, th, curve, res, stat, msg)
        call expect_stat('weight')
        if (allocated(error)) return
        call winkler_pushover(1.0_dp, 3.0_dp, 1.0e5_dp, nan_, th, curve, res, stat, msg)
        call expect_stat('k')
        if (allocated(error)) return
        call winkler_pushover(1.0_dp, 3.0_dp, 1.0e5_dp, 1.0e8_dp, [0.1_dp, -0.1_dp], curve, &
                              res, stat, msg)
        call expect_stat('theta(2)')
        if (allocated(error)) return
        call winkler_pushover(1.0_dp, 3.0_dp, 1.0e5_dp, 1.0e8_dp, th, bad_curve, res, stat, msg)
        call expect_stat('curve')
        if (allocated(error)) return
        call winkler_pushover(1.0_dp, 3.0_dp, 1.0e5_dp, 1.0e8_dp, th, curve, res, stat, msg, &
                              k_method=3)
        call expect_stat('k_method')
        if (allocated(error)) return
        call block_winkler_pushover(1.0_dp, -1.0_dp, 3.0_dp, 1.0e5_dp, 1.0e8_dp, th, curve, &
                                    res, stat, msg)
        call expect_stat('alpha')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 2.0_dp, 1.0e3_dp, 9.81_dp, cyl, stat)
        call winkler_equivalent_cylinder(cyl, 1.0_dp, 1.0e8_dp, blk, stat, msg)
        call expect_stat('block')
        if (allocated(error)) return

    contains

        subroutine expect_bad(name)
            character(len=*), intent(in) :: name
            msg = name
        end subroutine expect_bad

        subroutine expect_stat(name)
            character(len=*), intent(in) :: name
            call check(error, stat, SEISPULSE_INVALID_INPUT, 'stat for '//name)
            if (allocated(error)) return
            call check(error, index(msg, name//' ') == 1 .or. index(msg, name//':') == 1, &
                       'message names '//name//': '//trim(msg))
        end subroutine expect_stat

    end subroutine test_bad_input

end module test_winkler
