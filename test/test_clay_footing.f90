!> Circular footing on clay, the reduced-order method of [AD11] chapter 3 (doc/winkler.md,
!> (W.60)-(W.79)): the bearing identity, k/k_el = 1 below chi = 0.1, the Gaussian correction's
!> limits and peak, theta_up against the Winkler uplift angle, the pushover against the
!> constant-k Winkler circle written here in closed form (parametrised by the contact width
!> b: theta(b) and M(b), no root finding) with G = 1 and with a Gaussian, the overturning
!> angle by bisection here, k_el = 1.28 vs 1.14 (scale only), the moment capacities, the
!> weak-zone flag, and bad input. Every expected value is computed here independently.
module test_clay_footing
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_SOLUTION
    use seispulse_clay_footing, only: degradation_coeffs_t, inelastic_pushover_t, &
                                      clay_bearing, initial_stiffness_ratio, &
                                      gaussian_correction, theta_uplift, inelastic_pushover, &
                                      moment_capacity_circle, IP_THETA, IP_K_R, IP_M_FOUND, &
                                      IP_M_IMPOSED, IP_FORCE, IP_X, IP_G, IP_NCOL, &
                                      CAPACITY_TC00_PEAK, CAPACITY_EFFECTIVE_WIDTH
    use seispulse_winkler, only: winkler_pushover, winkler_pushover_t, WP_NCOL, WP_M_FOUND, &
                                 WP_M_IMPOSED, WP_FORCE
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_clay_footing

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    ! the example: r = 1 m, h = 3 m, S_u = 100 kPa, E = 30 MPa, nu = 0.3
    real(dp), parameter :: r0 = 1.0_dp, h0 = 3.0_dp, su0 = 1.0e5_dp, nu0 = 0.3_dp
    real(dp), parameter :: g0 = 30.0e6_dp / (2.0_dp * (1.0_dp + nu0))
    integer, parameter :: nb = 40

contains

    subroutine collect_clay_footing(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('N_ult = (pi + 3) S_u pi r^2, SF, chi; a given n_c', &
                              test_bearing), &
                 new_unittest('k/k_el = 1 for chi <= 0.1 exactly; the user law above; jump', &
                              test_stiffness_ratio), &
                 new_unittest('G: 1 at theta = 0 and far out, 1 + a at log_B x = b, a value', &
                              test_gaussian), &
                 new_unittest('theta_up = Winkler uplift angle with k = 4 K_R/(pi r^4)', &
                              test_uplift), &
                 new_unittest('G = 1, k_el = 1: the constant-k Winkler pushover (closed form)', &
                              test_pushover_winkler), &
                 new_unittest('G = 1, k_el = 1: = winkler_pushover (columns, peaks, overturn)', &
                              test_vs_winkler_pushover), &
                 new_unittest('a Gaussian: M_found = M_Winkler/G; chi > 0.1 scales K_R0', &
                              test_pushover_gauss), &
                 new_unittest('k_el = 1.28 vs 1.14: the same normalised curve, scale only', &
                              test_k_el_scale), &
                 new_unittest('moment capacity: 0.8 A D S_u; (pi+3)/2 chi (1-chi), 0.768', &
                              test_capacity), &
                 new_unittest('flags: weak zone SF < 1.25 near 0.1 theta_up; K_R0 <= W h', &
                              test_flags), &
                 new_unittest('bad input names the parameter', test_bad_input)]
    end subroutine collect_clay_footing

    ! ------------------------------------------------------------------------------
    ! Independent closed forms: the constant-k Winkler circle (radius r, modulus k, load W)
    ! at the contact width b: theta(b) = 1/2 asin(2 W/(k Phi(b))),
    ! M(b) = k sin(theta) cos^2(theta) (J2 - c J1), c = r - b.
    ! ------------------------------------------------------------------------------

    subroutine winkler_at_b(r, k, w, b, theta, m)
        real(dp), intent(in) :: r, k, w, b
        real(dp), intent(out) :: theta, m
        real(dp) :: c, s, a0, j1, j2, phi
        c = r - b
        s = sqrt(2.0_dp * r * b - b * b)
        a0 = r * r * acos(c / r) - c * s
        j1 = 2.0_dp / 3.0_dp * s**3
        j2 = r**4 / 4.0_dp * (0.5_dp * pi - asin(c / r)) - c / 4.0_dp * (2.0_dp * c * c - r * r) * s
        phi = j1 - c * a0
        theta = 0.5_dp * asin(2.0_dp * w / (k * phi))
        m = k * sin(theta) * cos(theta)**2 * (j2 - c * j1)
    end subroutine winkler_at_b

    !> Contact widths b(i) from 2 r down to the smallest admissible (2 W/(k Phi) < 1),
    !> geometrically spaced in 2 r - b near full contact and in b near the end.
    subroutine b_grid(r, k, w, b)
        real(dp), intent(in) :: r, k, w
        real(dp), intent(out) :: b(:)
        real(dp) :: lo, hi, mid
        integer :: i, n
        ! smallest admissible b by bisection (theta(b) defined)
        lo = 1.0e-12_dp * r
        hi = 2.0_dp * r
        do i = 1, 200
            mid = 0.5_dp * (lo + hi)
            if (admissible(mid)) then
                hi = mid
            else
                lo = mid
            end if
        end do
        n = size(b)
        do i = 1, n
            b(i) = 2.0_dp * r - (2.0_dp * r - 1.001_dp * hi) * (real(i - 1, dp) / (n - 1))**2
        end do
    contains
        logical function admissible(bb)
            real(dp), intent(in) :: bb
            real(dp) :: c, s, a0, j1, phi
            c = r - bb
            s = sqrt(2.0_dp * r * bb - bb * bb)
            a0 = r * r * acos(c / r) - c * s
            j1 = 2.0_dp / 3.0_dp * s**3
            phi = j1 - c * a0
            admissible = 2.0_dp * w / (k * phi) < 1.0_dp
        end function admissible
    end subroutine b_grid

    real(dp) function nan()
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
    end function nan

    !> Coefficients with every lost value given: k/k_el = 1.1 - chi, a(chi) = 0.5 chi +
    !> 5.11 chi^4, b = -0.3 ln(chi) + 0.2, c = 0.4 chi + 0.3 (an example, not [AD11]'s).
    function example_coeffs() result(co)
        type(degradation_coeffs_t) :: co
        co%kr_c1 = 1.1_dp
        co%kr_c2 = 1.0_dp
        co%a_poly = [0.0_dp, 0.5_dp, 0.0_dp, 0.0_dp, 5.11_dp]
        co%b1 = -0.3_dp
        co%b2 = 0.2_dp
        co%c1 = 0.4_dp
        co%c2 = 0.3_dp
    end function example_coeffs

    ! ------------------------------------------------------------------------------

    subroutine test_bearing(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: n_ult, sf, chi
        integer :: stat
        call clay_bearing(su0, 1.5_dp, 1.0e6_dp, n_ult, sf, chi, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'clay_bearing failed')
        if (allocated(error)) return
        call check(error, n_ult, (pi + 3.0_dp) * su0 * pi * 1.5_dp**2, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, sf, (pi + 3.0_dp) * su0 * pi * 2.25_dp / 1.0e6_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, chi, 1.0e6_dp / ((pi + 3.0_dp) * su0 * pi * 2.25_dp), &
                   rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, sf * chi, 1.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call clay_bearing(su0, 1.5_dp, 1.0e6_dp, n_ult, sf, chi, stat, nc=5.14_dp)
        call check(error, n_ult, 5.14_dp * su0 * pi * 2.25_dp, rtol=1.0e-15_dp)
    end subroutine test_bearing

    subroutine test_stiffness_ratio(error)
        type(test_error), allocatable, intent(out) :: error
        type(degradation_coeffs_t) :: co
        real(dp) :: kr, kappa, jump
        logical :: disc
        integer :: stat, i
        real(dp), parameter :: chis(4) = [0.0_dp, 1.0e-3_dp, 0.05_dp, 0.1_dp]
        ! no coefficients given: chi <= 0.1 needs none and gives exactly 1
        co%k_el = 1.28_dp
        do i = 1, size(chis)
            call initial_stiffness_ratio(chis(i), co, kr, stat, kappa=kappa, &
                                         discontinuous=disc)
            call check(error, stat == SEISPULSE_SUCCESS .and. .not. disc, 'chi <= 0.1 failed')
            if (allocated(error)) return
            call check(error, kr, 1.0_dp, rtol=0.0_dp)
            if (allocated(error)) return
            call check(error, kappa, 1.28_dp, rtol=0.0_dp)
            if (allocated(error)) return
        end do
        ! the user's law above 0.1: 1.2 - 2 chi (jumps at 0.1: 1.0 -> 1.0 ... continuous)
        co%kr_c1 = 1.2_dp
        co%kr_c2 = 2.0_dp
        call initial_stiffness_ratio(0.3_dp, co, kr, stat, kappa=kappa, discontinuous=disc, &
                                     jump=jump)
        call check(error, kr, 1.2_dp - 2.0_dp * 0.3_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, kappa, 1.28_dp * (1.2_dp - 0.6_dp), rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, .not. disc, 'continuous law flagged')
        if (allocated(error)) return
        call check(error, jump, 0.0_dp, atol=1.0e-15_dp)
        if (allocated(error)) return
        ! a law that jumps at 0.1: flagged (also when chi <= 0.1), the jump reported
        co%kr_c1 = 1.0_dp
        co%kr_c2 = 1.0_dp
        call initial_stiffness_ratio(0.05_dp, co, kr, stat, discontinuous=disc, jump=jump)
        call check(error, stat == SEISPULSE_SUCCESS .and. disc, 'jump not flagged')
        if (allocated(error)) return
        call check(error, kr, 1.0_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, jump, -0.1_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call initial_stiffness_ratio(0.5_dp, co, kr, stat, discontinuous=disc)
        call check(error, kr, 0.5_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, disc, 'jump not flagged above 0.1')
    end subroutine test_stiffness_ratio

    subroutine test_gaussian(error)
        type(test_error), allocatable, intent(out) :: error
        type(degradation_coeffs_t) :: co
        real(dp) :: g, a, b, c, chi, x, expect
        integer :: stat
        co = example_coeffs()
        chi = 0.6_dp
        call gaussian_correction(chi, 0.0_dp, co, g, stat, a=a, b=b, c=c)
        call check(error, stat == SEISPULSE_SUCCESS, 'G(0) failed')
        if (allocated(error)) return
        call check(error, g, 1.0_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, a, 0.5_dp * chi + 5.11_dp * chi**4, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, b, -0.3_dp * log(chi) + 0.2_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, c, 0.4_dp * chi + 0.3_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! theta -> 0: G -> 1 (and far out)
        call gaussian_correction(chi, 1.0e-30_dp, co, g, stat)
        call check(error, g, 1.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call gaussian_correction(chi, 1.0e-300_dp, co, g, stat)
        call check(error, g, 1.0_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call gaussian_correction(chi, 1.0e30_dp, co, g, stat)
        call check(error, g, 1.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! the peak 1 + a at log10(x) = b, and lower on either side
        call gaussian_correction(chi, 10.0_dp**b, co, g, stat)
        call check(error, g, 1.0_dp + a, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call gaussian_correction(chi, 1.01_dp * 10.0_dp**b, co, expect, stat)
        call check(error, expect < g, 'G above its peak to the right')
        if (allocated(error)) return
        call gaussian_correction(chi, 0.99_dp * 10.0_dp**b, co, expect, stat)
        call check(error, expect < g, 'G above its peak to the left')
        if (allocated(error)) return
        ! one value, base 10 and base e
        x = 7.0_dp
        expect = 1.0_dp + a * exp(-(log10(x) - b)**2 / (2.0_dp * c**2))
        call gaussian_correction(chi, x, co, g, stat)
        call check(error, g, expect, rtol=1.0e-14_dp)
        if (allocated(error)) return
        co%log_base = exp(1.0_dp)
        expect = 1.0_dp + a * exp(-(log(x) - b)**2 / (2.0_dp * c**2))
        call gaussian_correction(chi, x, co, g, stat)
        call check(error, g, expect, rtol=1.0e-14_dp)
        if (allocated(error)) return
        ! a(chi) = 0: G = 1 everywhere, b and c not needed
        co = degradation_coeffs_t()
        co%a_poly = 0.0_dp
        call gaussian_correction(chi, x, co, g, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'a = 0 needs no b, c')
        if (allocated(error)) return
        call check(error, g, 1.0_dp, rtol=0.0_dp)
    end subroutine test_gaussian

    subroutine test_uplift(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: th, k_r, k, w
        integer :: stat
        logical :: none
        k_r = 8.0_dp * g0 * r0**3 / (3.0_dp * (1.0_dp - nu0))
        w = 2.0e5_dp
        call theta_uplift(w, r0, k_r, th, stat, no_uplift=none)
        call check(error, stat == SEISPULSE_SUCCESS .and. .not. none, 'theta_uplift failed')
        if (allocated(error)) return
        call check(error, th, 0.5_dp * asin(w * r0 / (2.0_dp * k_r)), rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! the constant-k Winkler uplift angle 1/2 asin(2 W/(k pi r^3)), k = 4 K_R/(pi r^4)
        k = 4.0_dp * k_r / (pi * r0**4)
        call check(error, th, 0.5_dp * asin(2.0_dp * w / (k * pi * r0**3)), rtol=1.0e-14_dp)
        if (allocated(error)) return
        ! no uplift: NaN and the flag
        call theta_uplift(3.0_dp * k_r, r0, k_r, th, stat, no_uplift=none)
        call check(error, stat == SEISPULSE_SUCCESS .and. none .and. ieee_is_nan(th), &
                   'no uplift: NaN and flag expected')
    end subroutine test_uplift

    !> With a(chi) = 0 (G = 1), k_el = 1 and chi < 0.1 the method is the constant-k Winkler
    !> pushover with k = 4 HK_R/(pi r^4) = 32 G/(3 pi (1 - nu) r).
    subroutine test_pushover_winkler(error)
        type(test_error), allocatable, intent(out) :: error
        type(degradation_coeffs_t) :: co
        type(inelastic_pushover_t) :: res
        real(dp) :: b(nb), th(nb + 4), mw(nb + 4), curve(nb + 4, IP_NCOL), w, k, k_r0, m
        real(dp) :: lo, hi, mid, t_lo, t_hi, th_up, fm, m_max, f_max, t_mmax
        integer :: stat, i
        co%a_poly = 0.0_dp
        w = (pi + 3.0_dp) * su0 * pi * r0**2 / 20.0_dp        ! SF = 20, chi = 0.05
        k_r0 = 8.0_dp * g0 * r0**3 / (3.0_dp * (1.0_dp - nu0))
        k = 4.0_dp * k_r0 / (pi * r0**4)
        th_up = 0.5_dp * asin(2.0_dp * w / (k * pi * r0**3))
        ! full contact (M = K_R0 cos^2 sin), then the uplift branch from b, then beyond pi/4
        th(1) = 0.0_dp
        th(2) = 0.3_dp * th_up
        th(3) = 0.9_dp * th_up
        mw(1:3) = k_r0 * cos(th(1:3))**2 * sin(th(1:3))
        call b_grid(r0, k, w, b)
        do i = 1, nb
            call winkler_at_b(r0, k, w, b(i), th(3 + i), mw(3 + i))
        end do
        th(nb + 4) = 0.8_dp
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, th, curve, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'inelastic_pushover failed')
        if (allocated(error)) return
        call check(error, res%theta_up, th_up, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, res%k_r0, k_r0, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, res%chi, 0.05_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, .not. (res%weak_zone .or. res%kr_discontinuous .or. res%no_uplift), &
                   'no flag expected')
        if (allocated(error)) return
        do i = 1, nb + 3
            call check(error, curve(i, IP_M_FOUND), mw(i), rtol=1.0e-10_dp, &
                       atol=1.0e-12_dp * w * r0)
            if (allocated(error)) return
            call check(error, curve(i, IP_M_IMPOSED), mw(i) - w * h0 * sin(th(i)), &
                       rtol=1.0e-9_dp, atol=1.0e-10_dp * w * r0)
            if (allocated(error)) return
            call check(error, curve(i, IP_FORCE), curve(i, IP_M_IMPOSED) / (h0 * cos(th(i))), &
                       rtol=1.0e-15_dp)
            if (allocated(error)) return
            call check(error, curve(i, IP_X), th(i) / th_up, rtol=1.0e-14_dp)
            if (allocated(error)) return
            call check(error, curve(i, IP_G), 1.0_dp, rtol=0.0_dp)
            if (allocated(error)) return
            if (i > 1) then
                call check(error, curve(i, IP_K_R), mw(i) / th(i), rtol=1.0e-10_dp)
                if (allocated(error)) return
            end if
        end do
        call check(error, curve(1, IP_K_R), k_r0, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, ieee_is_nan(curve(nb + 4, IP_M_FOUND)) .and. &
                   ieee_is_nan(curve(nb + 4, IP_K_R)), 'beyond pi/4: NaN expected')
        if (allocated(error)) return
        ! the peaks: at least the grid's, and those of a dense scan of b here
        call check(error, res%max_moment >= maxval(curve(1:nb + 3, IP_M_IMPOSED)) .and. &
                   res%max_force_over_weight >= maxval(curve(1:nb + 3, IP_FORCE)) / w, &
                   'peaks below the grid values')
        if (allocated(error)) return
        m_max = -huge(1.0_dp)
        f_max = -huge(1.0_dp)
        do i = 0, 200000
            mid = 2.0_dp * r0 - (2.0_dp * r0 - b(nb)) * real(i, dp) / 200000.0_dp
            call winkler_at_b(r0, k, w, mid, t_lo, m)
            if (m - w * h0 * sin(t_lo) > m_max) then
                m_max = m - w * h0 * sin(t_lo)
                t_mmax = t_lo
            end if
            f_max = max(f_max, (m - w * h0 * sin(t_lo)) / (h0 * cos(t_lo) * w))
        end do
        call check(error, res%max_moment, m_max, rtol=1.0e-9_dp)
        if (allocated(error)) return
        call check(error, res%max_force_over_weight, f_max, rtol=1.0e-9_dp)
        if (allocated(error)) return
        call check(error, res%theta_at_max_moment, t_mmax, rtol=1.0e-3_dp)
        if (allocated(error)) return
        ! overturning: M(b) = W h sin(theta(b)) by bisection on b here
        lo = b(nb)
        hi = 2.0_dp * r0
        do i = 1, 200
            mid = 0.5_dp * (lo + hi)
            call winkler_at_b(r0, k, w, mid, t_lo, m)
            fm = m - w * h0 * sin(t_lo)
            if (fm > 0.0_dp) then
                hi = mid
            else
                lo = mid
            end if
        end do
        call winkler_at_b(r0, k, w, hi, t_hi, m)
        call check(error, res%theta_overturn, t_hi, rtol=1.0e-9_dp)
        if (allocated(error)) return
        ! near the rigid tan(theta) = r/h (stiff soil), below it
        call check(error, res%theta_overturn < atan(r0 / h0) .and. &
                   res%theta_overturn > 0.9_dp * atan(r0 / h0), 'overturning angle off')
    end subroutine test_pushover_winkler

    !> The same with seispulse_winkler's winkler_pushover (another implementation: its own
    !> inversion theta -> contact): every column, theta_up, the peaks and theta_overturn.
    subroutine test_vs_winkler_pushover(error)
        type(test_error), allocatable, intent(out) :: error
        type(degradation_coeffs_t) :: co
        type(inelastic_pushover_t) :: res
        type(winkler_pushover_t) :: wres
        integer, parameter :: n = 400
        real(dp) :: th(n), curve(n, IP_NCOL), cw(n, WP_NCOL), w, k
        integer :: stat, i
        co%a_poly = 0.0_dp
        w = (pi + 3.0_dp) * su0 * pi * r0**2 / 12.0_dp        ! SF = 12, chi < 0.1
        k = 32.0_dp * g0 / (3.0_dp * pi * (1.0_dp - nu0) * r0)
        do i = 1, n
            th(i) = 0.9_dp * real(i - 1, dp) / (n - 1)        ! up to 0.9 rad: past pi/4
        end do
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, th, curve, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'inelastic_pushover failed')
        if (allocated(error)) return
        call winkler_pushover(r0, h0, w, k, th, cw, wres, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'winkler_pushover failed')
        if (allocated(error)) return
        call check(error, res%theta_up, wres%theta_up, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, res%theta_overturn, wres%theta_overturn, rtol=1.0e-9_dp)
        if (allocated(error)) return
        call check(error, res%max_moment, wres%max_moment, rtol=1.0e-9_dp)
        if (allocated(error)) return
        call check(error, res%max_force_over_weight, wres%max_force_over_weight, &
                   rtol=1.0e-9_dp)
        if (allocated(error)) return
        do i = 1, n
            call check(error, ieee_is_nan(curve(i, IP_M_FOUND)) .eqv. &
                       ieee_is_nan(cw(i, WP_M_FOUND)), 'NaN points differ')
            if (allocated(error)) return
            if (ieee_is_nan(cw(i, WP_M_FOUND))) cycle
            call check(error, curve(i, IP_M_FOUND), cw(i, WP_M_FOUND), rtol=1.0e-10_dp, &
                       atol=1.0e-12_dp * w * r0)
            if (allocated(error)) return
            call check(error, curve(i, IP_M_IMPOSED), cw(i, WP_M_IMPOSED), rtol=1.0e-9_dp, &
                       atol=1.0e-10_dp * w * r0)
            if (allocated(error)) return
            call check(error, curve(i, IP_FORCE), cw(i, WP_FORCE), rtol=1.0e-9_dp, &
                       atol=1.0e-10_dp * w)
            if (allocated(error)) return
        end do
    end subroutine test_vs_winkler_pushover

    !> The full method: chi = 0.4 > 0.1 (K_R0 = HK_R k_el (1.1 - chi)) and a Gaussian:
    !> M_found(theta) = M_Winkler(theta; k = 4 K_R0/(pi r^4))/G(chi; theta/theta_up).
    subroutine test_pushover_gauss(error)
        type(test_error), allocatable, intent(out) :: error
        type(degradation_coeffs_t) :: co
        type(inelastic_pushover_t) :: res
        real(dp) :: b(nb), th(nb), mw(nb), curve(nb, IP_NCOL), w, k, k_r0, chi, a, bb, c
        real(dp) :: th_up, g, x
        integer :: stat, i
        co = example_coeffs()
        co%k_el = 1.14_dp
        chi = 0.4_dp
        w = chi * (pi + 3.0_dp) * su0 * pi * r0**2
        k_r0 = 8.0_dp * g0 * r0**3 / (3.0_dp * (1.0_dp - nu0)) * 1.14_dp * (1.1_dp - chi)
        k = 4.0_dp * k_r0 / (pi * r0**4)
        th_up = 0.5_dp * asin(w * r0 / (2.0_dp * k_r0))
        a = 0.5_dp * chi + 5.11_dp * chi**4
        bb = -0.3_dp * log(chi) + 0.2_dp
        c = 0.4_dp * chi + 0.3_dp
        call b_grid(r0, k, w, b)
        do i = 1, nb
            call winkler_at_b(r0, k, w, b(i), th(i), mw(i))
        end do
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, th, curve, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'inelastic_pushover failed')
        if (allocated(error)) return
        call check(error, res%k_r0, k_r0, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, res%sf, 2.5_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, res%a, a, rtol=1.0e-14_dp)
        if (allocated(error)) return
        do i = 1, nb
            x = th(i) / th_up
            g = 1.0_dp + a * exp(-(log10(x) - bb)**2 / (2.0_dp * c**2))
            call check(error, curve(i, IP_G), g, rtol=1.0e-13_dp)
            if (allocated(error)) return
            call check(error, curve(i, IP_M_FOUND), mw(i) / g, rtol=1.0e-10_dp)
            if (allocated(error)) return
            call check(error, curve(i, IP_K_R), mw(i) / (g * th(i)), rtol=1.0e-10_dp)
            if (allocated(error)) return
        end do
        ! the Gaussian lowers the moment (a > 0)
        call check(error, curve(nb / 2, IP_M_FOUND) < mw(nb / 2), 'G > 1 must soften')
    end subroutine test_pushover_gauss

    !> [AD11]: k_el = 1.28 or 1.14 changes only the scale: K_R0 in their ratio, sin(2
    !> theta_up) in the inverse ratio, and the normalised curve K_R/K_R0 against
    !> theta/theta_up the same (up to the O(theta^2) of the large-angle geometry).
    subroutine test_k_el_scale(error)
        type(test_error), allocatable, intent(out) :: error
        type(degradation_coeffs_t) :: co
        type(inelastic_pushover_t) :: r1, r2
        integer, parameter :: n = 30
        real(dp) :: xg(n), c1(n, IP_NCOL), c2(n, IP_NCOL), w, tol
        integer :: stat, i
        co = example_coeffs()
        w = 0.3_dp * (pi + 3.0_dp) * su0 * pi * r0**2
        do i = 1, n
            xg(i) = 10.0_dp**(-2.0_dp + 3.5_dp * real(i - 1, dp) / (n - 1))
        end do
        call run_normalised(1.28_dp, c1, r1)
        if (allocated(error)) return
        call run_normalised(1.14_dp, c2, r2)
        if (allocated(error)) return
        call check(error, r1%k_r0 / r2%k_r0, 1.28_dp / 1.14_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, sin(2.0_dp * r1%theta_up) / sin(2.0_dp * r2%theta_up), &
                   1.14_dp / 1.28_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        tol = 4.0_dp * (xg(n) * max(r1%theta_up, r2%theta_up))**2
        call check(error, tol < 1.0e-3_dp, 'test problem not stiff enough')
        if (allocated(error)) return
        do i = 1, n
            call check(error, c1(i, IP_K_R) / r1%k_r0, c2(i, IP_K_R) / r2%k_r0, rtol=tol)
            if (allocated(error)) return
            call check(error, c1(i, IP_G), c2(i, IP_G), rtol=1.0e-14_dp)
            if (allocated(error)) return
        end do
        ! but the scale differs: the same x is a different theta
        call check(error, abs(c1(n, IP_THETA) / c2(n, IP_THETA) - 1.0_dp) > 0.1_dp, &
                   'theta scale should differ')
    contains
        !> The pushover at theta = x theta_up (theta_up from a first run at theta = 0).
        subroutine run_normalised(k_el, c, res)
            real(dp), intent(in) :: k_el
            real(dp), intent(out) :: c(:, :)
            type(inelastic_pushover_t), intent(out) :: res
            co%k_el = k_el
            call inelastic_pushover(r0, h0, w, 10.0_dp * g0, nu0, su0, co, [0.0_dp], &
                                    c(1:1, :), res, stat)
            call inelastic_pushover(r0, h0, w, 10.0_dp * g0, nu0, su0, co, xg * res%theta_up, &
                                    c, res, stat)
            call check(error, stat == SEISPULSE_SUCCESS, 'k_el run failed')
        end subroutine run_normalised
    end subroutine test_k_el_scale

    subroutine test_capacity(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: m, m_lo, m_hi, adsu
        integer :: stat
        adsu = pi * 1.5_dp**2 * 3.0_dp * su0
        call moment_capacity_circle(su0, 1.5_dp, 0.3_dp, CAPACITY_TC00_PEAK, m, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'TC00 failed')
        if (allocated(error)) return
        call check(error, m, 0.8_dp * adsu, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call moment_capacity_circle(su0, 1.5_dp, 0.5_dp, CAPACITY_EFFECTIVE_WIDTH, m, stat)
        call check(error, m / adsu, (pi + 3.0_dp) / 8.0_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, m / adsu, 0.768_dp, atol=5.0e-4_dp)
        if (allocated(error)) return
        ! N D (1 - chi)/2 with N = chi N_ult
        call moment_capacity_circle(su0, 1.5_dp, 0.2_dp, CAPACITY_EFFECTIVE_WIDTH, m, stat)
        call check(error, m, 0.2_dp * (pi + 3.0_dp) * su0 * pi * 2.25_dp * 3.0_dp * 0.8_dp &
                   / 2.0_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call moment_capacity_circle(su0, 1.5_dp, 0.49_dp, CAPACITY_EFFECTIVE_WIDTH, m_lo, stat)
        call moment_capacity_circle(su0, 1.5_dp, 0.51_dp, CAPACITY_EFFECTIVE_WIDTH, m_hi, stat)
        call moment_capacity_circle(su0, 1.5_dp, 0.5_dp, CAPACITY_EFFECTIVE_WIDTH, m, stat)
        call check(error, m > m_lo .and. m > m_hi, 'the maximum is at chi = 0.5')
        if (allocated(error)) return
        call moment_capacity_circle(su0, 1.5_dp, 1.0_dp, CAPACITY_EFFECTIVE_WIDTH, m, stat)
        call check(error, m, 0.0_dp, atol=0.0_dp)
    end subroutine test_capacity

    subroutine test_flags(error)
        type(test_error), allocatable, intent(out) :: error
        type(degradation_coeffs_t) :: co
        type(inelastic_pushover_t) :: res
        real(dp) :: curve(3, IP_NCOL), c1(1, IP_NCOL), w, th_up, g_soft, k_r0
        integer :: stat
        co = example_coeffs()
        ! SF = 1.2: a grid through 0.1 theta_up is flagged, one from theta_up on is not
        w = (pi + 3.0_dp) * su0 * pi * r0**2 / 1.2_dp
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, [0.0_dp], c1, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. .not. res%weak_zone, &
                   'theta = 0 only: no weak zone')
        if (allocated(error)) return
        th_up = res%theta_up
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, [0.0_dp, 0.1_dp, 1.0_dp] * th_up, &
                                curve, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. res%weak_zone, 'weak zone expected')
        if (allocated(error)) return
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, [1.0_dp, 2.0_dp, 5.0_dp] * th_up, &
                                curve, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. .not. res%weak_zone, &
                   'grid beyond the weak zone flagged')
        if (allocated(error)) return
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, [0.3_dp, 1.0_dp, 2.0_dp] * th_up, &
                                curve, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. .not. res%weak_zone, &
                   'grid from 0.3 theta_up flagged')
        if (allocated(error)) return
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, [0.15_dp, 1.0_dp, 2.0_dp] * th_up, &
                                curve, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. res%weak_zone, &
                   'grid from 0.15 theta_up not flagged')
        if (allocated(error)) return
        ! SF = 2: never flagged
        w = (pi + 3.0_dp) * su0 * pi * r0**2 / 2.0_dp
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, [0.0_dp], c1, res, stat)
        th_up = res%theta_up
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, co, [0.0_dp, 0.1_dp, 1.0_dp] * th_up, &
                                curve, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. .not. res%weak_zone, &
                   'SF = 2 flagged')
        if (allocated(error)) return
        ! K_R0 = 2 W r (uplift exists: W r/(2 K_R0) = 1/4) but <= W h: overturning angle 0
        co%a_poly = 0.0_dp
        k_r0 = 2.0_dp * w * r0
        g_soft = k_r0 * 3.0_dp * (1.0_dp - nu0) / (8.0_dp * r0**3 * (1.1_dp - 0.5_dp))
        call inelastic_pushover(r0, h0, w, g_soft, nu0, su0, co, [0.0_dp, 0.01_dp, 0.1_dp], &
                                curve, res, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'soft soil failed')
        if (allocated(error)) return
        call check(error, res%k_r0, k_r0, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, res%theta_overturn, 0.0_dp, atol=0.0_dp)
        if (allocated(error)) return
        call check(error, res%theta_up, 0.5_dp * asin(0.25_dp), rtol=1.0e-14_dp)
        if (allocated(error)) return
        ! softer still: no uplift is an error with the flag set
        call inelastic_pushover(r0, h0, w, g_soft / 8.0_dp, nu0, su0, co, [0.0_dp], c1, res, &
                                stat)
        call check(error, stat == SEISPULSE_NO_SOLUTION .and. res%no_uplift .and. &
                   ieee_is_nan(res%theta_up), 'no uplift expected')
    end subroutine test_flags

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(degradation_coeffs_t) :: co, full
        type(inelastic_pushover_t) :: res
        real(dp) :: curve(2, IP_NCOL), wrong(2, 3), v1, v2, v3, w
        integer :: stat
        character(len=400) :: msg
        full = example_coeffs()
        w = (pi + 3.0_dp) * su0 * pi * r0**2 / 3.0_dp
        call clay_bearing(0.0_dp, r0, w, v1, v2, v3, stat, msg)
        call expect('su', stat, msg)
        if (allocated(error)) return
        call clay_bearing(su0, -1.0_dp, w, v1, v2, v3, stat, msg)
        call expect('r', stat, msg)
        if (allocated(error)) return
        call clay_bearing(su0, r0, nan(), v1, v2, v3, stat, msg)
        call expect('weight', stat, msg)
        if (allocated(error)) return
        ! SF <= 1 names weight and su
        call clay_bearing(su0, r0, 3.0_dp * w, v1, v2, v3, stat, msg)
        call expect('weight', stat, msg)
        if (allocated(error)) return
        call check(error, index(msg, 'su') > 0 .and. index(msg, 'SF') > 0, trim(msg))
        if (allocated(error)) return
        call bad_push(r0, h0, 10.0_dp * w, g0, nu0, su0, full, [0.0_dp, 0.1_dp], 'weight')
        if (allocated(error)) return
        call bad_push(r0, h0, w, 0.0_dp, nu0, su0, full, [0.0_dp, 0.1_dp], 'g_mod')
        if (allocated(error)) return
        call bad_push(r0, h0, w, g0, 0.5_dp, su0, full, [0.0_dp, 0.1_dp], 'nu')
        if (allocated(error)) return
        call bad_push(r0, h0, w, g0, 0.0_dp, su0, full, [0.0_dp, 0.1_dp], 'nu')
        if (allocated(error)) return
        call bad_push(r0, -h0, w, g0, nu0, su0, full, [0.0_dp, 0.1_dp], 'h')
        if (allocated(error)) return
        call bad_push(0.0_dp, h0, w, g0, nu0, su0, full, [0.0_dp, 0.1_dp], 'r')
        if (allocated(error)) return
        call bad_push(r0, h0, w, g0, nu0, -su0, full, [0.0_dp, 0.1_dp], 'su')
        if (allocated(error)) return
        call bad_push(r0, h0, w, g0, nu0, su0, full, [0.1_dp, 0.0_dp], 'theta(2)')
        if (allocated(error)) return
        call bad_push(r0, h0, w, g0, nu0, su0, full, [-0.1_dp, 0.0_dp], 'theta(1)')
        if (allocated(error)) return
        call inelastic_pushover(r0, h0, w, g0, nu0, su0, full, [0.0_dp, 0.1_dp], wrong, res, &
                                stat, msg)
        call expect('curve', stat, msg)
        if (allocated(error)) return
        ! missing coefficients (chi = 1/3 > 0.1): each named
        co = full
        co%kr_c2 = nan()
        call bad_push(r0, h0, w, g0, nu0, su0, co, [0.0_dp, 0.1_dp], 'kr_c1')
        if (allocated(error)) return
        call check(error, index(msg, 'kr_c2') > 0, trim(msg))
        if (allocated(error)) return
        co = full
        co%a_poly(2) = nan()
        call bad_push(r0, h0, w, g0, nu0, su0, co, [0.0_dp, 0.1_dp], 'a_poly(2)')
        if (allocated(error)) return
        co = full
        co%b1 = nan()
        call bad_push(r0, h0, w, g0, nu0, su0, co, [0.0_dp, 0.1_dp], 'b1')
        if (allocated(error)) return
        co = full
        co%b2 = nan()
        call bad_gauss('b2')
        if (allocated(error)) return
        co = full
        co%c1 = nan()
        call bad_gauss('c1')
        if (allocated(error)) return
        co = full
        co%c2 = nan()
        call bad_gauss('c2')
        if (allocated(error)) return
        co = full
        co%c1 = 1.0_dp
        co%c2 = -0.3_dp                   ! c(0.3) = 0
        call bad_gauss('c1')
        if (allocated(error)) return
        co = full
        co%log_base = 1.0_dp
        call bad_gauss('log_base')
        if (allocated(error)) return
        co = full
        co%a_poly = [-2.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
        call bad_gauss('a_poly')
        if (allocated(error)) return
        co = full
        co%k_el = 0.0_dp
        call initial_stiffness_ratio(0.3_dp, co, v1, stat, msg)
        call expect('k_el', stat, msg)
        if (allocated(error)) return
        co = full
        co%kr_c1 = 0.1_dp                 ! k/k_el < 0 at chi = 0.3
        call initial_stiffness_ratio(0.3_dp, co, v1, stat, msg)
        call expect('kr_c1', stat, msg)
        if (allocated(error)) return
        call initial_stiffness_ratio(1.0_dp, full, v1, stat, msg)
        call expect('chi', stat, msg)
        if (allocated(error)) return
        call theta_uplift(w, r0, 0.0_dp, v1, stat, msg)
        call expect('k_r', stat, msg)
        if (allocated(error)) return
        call moment_capacity_circle(su0, r0, 0.5_dp, 3, v1, stat, msg)
        call expect('model', stat, msg)
        if (allocated(error)) return
        call moment_capacity_circle(su0, r0, 1.5_dp, CAPACITY_TC00_PEAK, v1, stat, msg)
        call expect('chi', stat, msg)
    contains
        subroutine bad_push(rr, hh, ww, gg, nn, ss, cc, th, name)
            real(dp), intent(in) :: rr, hh, ww, gg, nn, ss, th(:)
            type(degradation_coeffs_t), intent(in) :: cc
            character(len=*), intent(in) :: name
            call inelastic_pushover(rr, hh, ww, gg, nn, ss, cc, th, curve, res, stat, msg)
            call expect(name, stat, msg)
        end subroutine bad_push

        subroutine bad_gauss(name)
            character(len=*), intent(in) :: name
            call gaussian_correction(0.3_dp, 1.0_dp, co, v1, stat, msg)
            call expect(name, stat, msg)
        end subroutine bad_gauss

        subroutine expect(name, st, m)
            character(len=*), intent(in) :: name, m
            integer, intent(in) :: st
                logical :: named
            named = .false.
            if (index(m, name) == 1 .and. len(m) > len(name)) &
                named = scan(m(len(name) + 1:len(name) + 1), ' :,') == 1
            call check(error, st == SEISPULSE_INVALID_INPUT .and. named, &
                       'expected an error naming '//name//', got: '//trim(m))
        end subroutine expect
    end subroutine test_bad_input

end module test_clay_footing
