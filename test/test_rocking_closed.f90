!> Rocking closed forms (seispulse_rocking_closed): the whole first excursion and every derived
!> quantity against an independent reference (the Duhamel integral of the linearized
!> equation of motion by adaptive Gauss-Legendre quadrature, roots and boundaries found on
!> it by safeguarded Newton and bisection), the oracle values of doc/rocking.md, the limit
!> equations, each corrected equation at a point where the printed form differs, the
!> monotonicity claims of section 5.3 and the input checks.
module test_rocking_closed
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_negative_inf, ieee_is_nan, ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_format, only: real_str
    use seispulse_special, only: pi
    use seispulse_rocking_closed
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_rocking_closed

    !> Reference problem psi'' - f^2 psi = f^2 (s(tau)/eta - 1) from rest at tau_up.
    type :: ref_t
        real(dp) :: f = 1.0_dp, eta = 0.5_dp, beta = 0.0_dp
        real(dp) :: tup = 0.0_dp
        logical :: rocks = .false.
    end type ref_t

    !> Reference values of everything the library computes for one case.
    type :: ref_result_t
        integer :: region = ROCK_NONE
        real(dp) :: p_half = 0.0_dp, q_half = 0.0_dp, p_one = 0.0_dp, q_one = 0.0_dp
        real(dp) :: a = 0.0_dp
        real(dp) :: tau_c = 0.0_dp, tau_m = 0.0_dp, psi_max = 0.0_dp, tau_i = 0.0_dp
    end type ref_result_t

    integer, parameter :: ngl = 20
    real(dp), save :: gl_x(ngl) = 0.0_dp, gl_w(ngl) = 0.0_dp
    logical, save :: gl_ready = .false.

    !> Tolerance of every comparison with the reference (relative; values passing through
    !> zero also get 1e-14 of the scale of their round-off, f int cosh(f(tau - s))
    !> (s/eta + 1) ds, as a floor). Reached on the grid (gfortran 12, x86-64): psi 3e-13,
    !> psi' 1.5e-13, tau_c 1e-14, tau_m 2e-14, psi_max 8e-14, tau_i 2e-14, eta_w and the
    !> boundaries 4e-15.
    real(dp), parameter :: rtol_ref = 1.0e-12_dp

contains

    subroutine collect_rocking_closed(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('uplift time Eq. 2.4 and its limits', test_uplift), &
                 new_unittest('region names and no-rocking cases', test_names_none), &
                 new_unittest('oracles: stability wall at f = 2|beta| (5.3)', test_wall_oracles), &
                 new_unittest('oracles: tau_c in O3 at beta = pi, f = 1 (5.4)', &
                              test_tau_c_oracles), &
                 new_unittest('corrected 2.16a vs printed', test_216a), &
                 new_unittest('corrected 2.18a vs printed; 2.17, 2.18b', test_218), &
                 new_unittest('corrected 2.30 vs printed; 2.29, 2.31', test_230), &
                 new_unittest('corrected 2.32b/e vs printed: y3 and root branch', test_232), &
                 new_unittest('corrected 2.34b vs printed; 2.34a', test_234), &
                 new_unittest('corrected 2.35, 2.36a vs printed; 2.33, 2.36b', test_235), &
                 new_unittest('limits 2.21, 2.22 and slow rectangle convergence', &
                              test_wall_limits), &
                 new_unittest('limits 2.25, 2.26, 2.27, 2.28', test_tau_m_limits), &
                 new_unittest('printed 2.10-2.15 where they are stable', test_printed_response), &
                 new_unittest('monotonicity claims of 5.3', test_monotone), &
                 new_unittest('f = 2|beta|, beta ~ 0 and large |beta|: no NaN, continuity', &
                              test_singular), &
                 new_unittest('inverse boundaries round trip', test_inverses), &
                 new_unittest('summary = single routines; response NaN after impact', &
                              test_summary), &
                 new_unittest('bad input names the parameter', test_bad_input), &
                 new_unittest('response and derived quantities = reference on the grid', &
                              test_grid), &
                 new_unittest('boundaries = reference bisection', test_boundaries_ref)]
    end subroutine collect_rocking_closed

    ! ------------------------------------------------------------------------------
    ! Oracles and corrected equations
    ! ------------------------------------------------------------------------------

    subroutine test_uplift(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: tau, inf
        integer :: stat
        inf = ieee_value(inf, ieee_positive_inf)
        call uplift_time(0.3_dp, pi, tau, stat)
        call check(error, tau, log(1.0_dp - 0.3_dp * (1.0_dp - exp(pi))) / (2.0_dp * pi), &
                   rtol=1.0e-15_dp, message='Eq. 2.4 at beta = pi')
        if (allocated(error)) return
        call uplift_time(0.3_dp, 0.0_dp, tau, stat)
        call check(error, tau, 0.15_dp, message='triangle eta/2')
        if (allocated(error)) return
        ! tiny beta: eta/2 + beta eta (1 - eta)/4 + O(beta^2), no loss of digits
        call uplift_time(0.3_dp, 1.0e-9_dp, tau, stat)
        call check(error, tau, 0.15_dp + 1.0e-9_dp * 0.3_dp * 0.7_dp / 4.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call uplift_time(0.3_dp, -inf, tau, stat)
        call check(error, tau, 0.0_dp, message='rectangle')
        if (allocated(error)) return
        call uplift_time(0.3_dp, inf, tau, stat)
        call check(error, tau, 0.5_dp, message='spike')
        if (allocated(error)) return
        ! beyond the overflow of e^beta: 1/2 + ln(eta + (1 - eta) e^-beta)/(2 beta)
        call uplift_time(0.3_dp, 1.0e4_dp, tau, stat)
        call check(error, tau, 0.5_dp + log(0.3_dp) / 2.0e4_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! small eta, beta = -2 pi: ln(1 - eta (1 - e^beta))/(2 beta) = eta (1 - e^beta)/(-2 beta)...
        call uplift_time(1.0e-10_dp, -2.0_dp * pi, tau, stat)
        call check(error, tau, 1.0e-10_dp * (1.0_dp - exp(-2.0_dp * pi)) / (4.0_dp * pi), &
                   rtol=1.0e-9_dp)
        if (allocated(error)) return
        call uplift_time(1.0_dp, 1.0_dp, tau, stat)
        call check(error, ieee_is_nan(tau) .and. stat == SEISPULSE_SUCCESS, 'eta = 1: NaN')
    end subroutine test_uplift

    subroutine test_names_none(error)
        type(test_error), allocatable, intent(out) :: error
        integer :: region, stat
        real(dp) :: psi, dpsi, inf, tu, tc, tm, pm, ti, x
        inf = ieee_value(inf, ieee_positive_inf)
        call check(error, rocking_region_name(ROCK_NONE) == 'no_rocking' .and. &
                   rocking_region_name(ROCK_O1) == 'O1' .and. rocking_region_name(ROCK_O2) == 'O2' &
                   .and. rocking_region_name(ROCK_O3) == 'O3' .and. &
                   rocking_region_name(ROCK_S1) == 'S1' .and. rocking_region_name(ROCK_S2) == 'S2' &
                   .and. rocking_region_name(17) == 'unknown', 'region names')
        if (allocated(error)) return
        ! eta >= 1: no rocking, zero response, no error
        call rocking_classify(2.0_dp, 1.0_dp, 0.5_dp, region, stat)
        call check(error, region == ROCK_NONE .and. stat == SEISPULSE_SUCCESS, 'eta = 1')
        if (allocated(error)) return
        call rocking_summary(2.0_dp, 3.0_dp, 0.5_dp, region, tu, tc, tm, pm, ti, stat)
        call check(error, region == ROCK_NONE .and. ieee_is_nan(tu) .and. ieee_is_nan(tc) .and. &
                   ieee_is_nan(tm) .and. ieee_is_nan(ti) .and. .not. abs(pm) > 0.0_dp, 'eta = 3')
        if (allocated(error)) return
        call rocking_response(0.7_dp, 2.0_dp, inf, 0.5_dp, psi, dpsi, stat)
        call check(error, .not. (abs(psi) > 0.0_dp .or. abs(dpsi) > 0.0_dp) .and. &
                   stat == SEISPULSE_SUCCESS, 'eta = inf: at rest')
        if (allocated(error)) return
        ! the spike has zero area: no rocking, uplift at 1/2
        call rocking_summary(2.0_dp, 0.2_dp, inf, region, tu, tc, tm, pm, ti, stat)
        call check(error, region == ROCK_NONE .and. abs(tu - 0.5_dp) < 1.0e-15_dp .and. &
                   .not. abs(pm) > 0.0_dp, 'spike')
        if (allocated(error)) return
        call stability_wall(2.0_dp, inf, x, stat)
        call check(error, x, 0.0_dp, message='spike wall')
        if (allocated(error)) return
        call stability_wall_inverse(0.3_dp, inf, x, stat)
        call check(error, x > huge(x), 'spike: no f overturns')
        if (allocated(error)) return
        call stability_wall_inverse(1.0_dp, 1.0_dp, x, stat)
        call check(error, x > huge(x), 'eta = 1: no f overturns')
        if (allocated(error)) return
        call s1_s2_boundary(2.0_dp, -inf, x, stat)
        call check(error, ieee_is_nan(x) .and. stat == SEISPULSE_SUCCESS, 'rectangle: no S1')
        if (allocated(error)) return
        ! before uplift: at rest
        call rocking_response(0.01_dp, 2.0_dp, 0.5_dp, 1.0_dp, psi, dpsi, stat)
        call check(error, .not. (abs(psi) > 0.0_dp .or. abs(dpsi) > 0.0_dp), 'before uplift')
    end subroutine test_names_none

    !> doc/rocking.md section 3: removable singularities of Eq. 2.20 at f = 2|beta|.
    subroutine test_wall_oracles(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: betas(6) = [0.5_dp, 1.0_dp, pi, -0.5_dp, -1.0_dp, -pi]
        real(dp), parameter :: walls(6) = [0.3112945075_dp, 0.4447161183_dp, 0.5893515252_dp, &
                                           0.3614922447_dp, 0.5739634818_dp, 0.9232753124_dp]
        real(dp) :: x, q, expected
        integer :: i, stat
        do i = 1, 6
            call stability_wall(2.0_dp * abs(betas(i)), betas(i), x, stat)
            call check(error, x, walls(i), atol=5.0e-11_dp, message='wall at beta = ' &
                       //real_str(betas(i)))
            if (allocated(error)) return
            ! the closed limits of 5.3: Q = exp(beta - 1/2 + e^(-2 beta)/2) (beta > 0),
            ! Q = sqrt((1 + f) e^-f) (beta < 0); eta_w = (1 - Q)/(1 - e^beta)
            if (betas(i) > 0.0_dp) then
                q = exp(betas(i) - 0.5_dp + 0.5_dp * exp(-2.0_dp * betas(i)))
            else
                q = sqrt((1.0_dp - 2.0_dp * betas(i)) * exp(2.0_dp * betas(i)))
            end if
            expected = (1.0_dp - q) / (1.0_dp - exp(betas(i)))
            call check(error, x, expected, rtol=1.0e-13_dp, message='5.3 limit form')
            if (allocated(error)) return
        end do
    end subroutine test_wall_oracles

    subroutine test_tau_c_oracles(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: etas(3) = [0.15_dp, 0.19_dp, 0.198_dp]
        real(dp), parameter :: taus(3) = [1.4103182142_dp, 2.3430539314_dp, 4.2505629625_dp]
        real(dp) :: tau_c
        integer :: i, stat, region
        do i = 1, 3
            call rocking_classify(1.0_dp, etas(i), pi, region, stat)
            call check(error, region == ROCK_O3, 'O3 at eta = '//real_str(etas(i)))
            if (allocated(error)) return
            call critical_time(1.0_dp, etas(i), pi, tau_c, stat)
            call check(error, tau_c, taus(i), atol=5.0e-11_dp * taus(i), &
                       message='tau_c at eta = '//real_str(etas(i)))
            if (allocated(error)) return
        end do
    end subroutine test_tau_c_oracles

    !> Corrected 2.16a (no -f^2 on the right): 0.1011941262 at beta = pi, f = 1 and
    !> 0.8221237806 at beta = -pi, f = 4; the printed form gives 0.100324 and 0.90096.
    subroutine test_216a(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: betas(2) = [pi, -pi], fs(2) = [1.0_dp, 4.0_dp]
        real(dp), parameter :: good(2) = [0.1011941262_dp, 0.8221237806_dp]
        real(dp), parameter :: printed(2) = [0.100324_dp, 0.90096_dp]
        real(dp) :: eta_b, eta_p
        integer :: i, stat
        do i = 1, 2
            call overturn_boundary(fs(i), betas(i), .true., eta_b, stat)
            call check(error, eta_b, good(i), atol=5.0e-11_dp, message='corrected 2.16a')
            if (allocated(error)) return
            eta_p = bisect_printed_216a(fs(i), betas(i))
            call check(error, eta_p, printed(i), atol=5.0e-6_dp, message='printed 2.16a')
            if (allocated(error)) return
            call check(error, abs(eta_p - eta_b) > 5.0e-4_dp, 'printed 2.16a should differ')
            if (allocated(error)) return
        end do
    end subroutine test_216a

    !> Root in eta of the printed 2.16a: beta[(f + 2b)Q^(1-f/2b) e^f - (f - 2b)Q^(1+f/2b) e^-f]
    !> = 4b^2 - f^2 + 2 b f e^b (e^(f/2) - e^(-f/2)), by bisection.
    function bisect_printed_216a(f, b) result(eta)
        real(dp), intent(in) :: f, b
        real(dp) :: eta, lo, hi, vlo
        integer :: it
        lo = 1.0e-6_dp
        hi = 1.0_dp - 1.0e-9_dp
        vlo = printed_216a(lo)
        do it = 1, 200
            eta = 0.5_dp * (lo + hi)
            if (printed_216a(eta) * vlo > 0.0_dp) then
                lo = eta
            else
                hi = eta
            end if
        end do
    contains
        function printed_216a(e) result(v)
            real(dp), intent(in) :: e
            real(dp) :: v, q
            q = 1.0_dp - e * (1.0_dp - exp(b))
            v = b * ((f + 2 * b) * q**(1 - f / (2 * b)) * exp(f) &
                     - (f - 2 * b) * q**(1 + f / (2 * b)) * exp(-f)) &
                - (4 * b**2 - f**2 + 2 * b * f * exp(b) * (exp(f / 2) - exp(-f / 2)))
        end function printed_216a
    end function bisect_printed_216a

    subroutine test_218(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: eta_b, printed, f, inf
        integer :: i, stat
        inf = ieee_value(inf, ieee_positive_inf)
        ! corrected 2.18a: 0.1782111419 at f = 1 (printed 0.23725), 0.6603102060 at f = 4
        call overturn_boundary(1.0_dp, 0.0_dp, .true., eta_b, stat)
        call check(error, eta_b, 0.1782111419_dp, atol=5.0e-11_dp, message='corrected 2.18a')
        if (allocated(error)) return
        printed = 2.0_dp + log(1.0_dp + 2.0_dp * (1.0_dp - sqrt(2.0_dp)))
        call check(error, printed, 0.23725_dp, atol=5.0e-6_dp, message='printed 2.18a')
        if (allocated(error)) return
        call check(error, abs(printed - eta_b) > 0.05_dp, 'printed 2.18a should differ')
        if (allocated(error)) return
        call overturn_boundary(4.0_dp, 0.0_dp, .true., eta_b, stat)
        call check(error, eta_b, 0.6603102060_dp, atol=5.0e-11_dp, message='corrected 2.18a, f=4')
        if (allocated(error)) return
        do i = 1, 16
            f = 0.5_dp * i
            ! corrected 2.18a in its printed shape with x = 2 sinh(f/2)
            call overturn_boundary(f, 0.0_dp, .true., eta_b, stat)
            printed = 2.0_dp + log(1.0_dp + 2.0_dp * (2 * sinh(f / 2)) * (2 * sinh(f / 2) &
                      - sqrt((2 * sinh(f / 2))**2 + 1.0_dp))) / f
            ! (the printed shape cancels in x - sqrt(x^2 + 1) for large f: 1e-7)
            call check(error, eta_b, printed, rtol=1.0e-7_dp, message='2.18a f='//real_str(f))
            if (allocated(error)) return
            ! Eq. 2.18b
            call overturn_boundary(f, 0.0_dp, .false., eta_b, stat)
            printed = 1.0_dp + log(1.0_dp + f / 2 * (f - sqrt(f * f + 4.0_dp))) / f
            call check(error, eta_b, printed, rtol=1.0e-11_dp, message='2.18b f='//real_str(f))
            if (allocated(error)) return
            ! Eq. 2.17a/b
            call overturn_boundary(f, -inf, .true., eta_b, stat)
            call check(error, eta_b, 1.0_dp - 1.0_dp / cosh(f), rtol=1.0e-13_dp, message='2.17a')
            if (allocated(error)) return
            call overturn_boundary(f, -inf, .false., eta_b, stat)
            call check(error, eta_b, 1.0_dp - 1.0_dp / cosh(f / 2), rtol=1.0e-13_dp, &
                       message='2.17b')
            if (allocated(error)) return
        end do
        ! small f: eta ~ f^2/4 (2.18a) and f^2/24 (2.18b) with all digits
        call overturn_boundary(1.0e-5_dp, 0.0_dp, .true., eta_b, stat)
        call check(error, eta_b, 0.25e-10_dp, rtol=1.0e-9_dp, message='2.18a, f -> 0')
        if (allocated(error)) return
        call overturn_boundary(1.0e-5_dp, 0.0_dp, .false., eta_b, stat)
        call check(error, eta_b, 1.0e-10_dp / 24.0_dp, rtol=1.0e-9_dp, message='2.18b, f -> 0')
    end subroutine test_218

    subroutine test_230(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: fbar, eta, el, r, printed, corrected, psi_max, f, tm, inf
        integer :: i, stat
        inf = ieee_value(inf, ieee_negative_inf)
        fbar = 0.5_dp
        eta = 0.3_dp
        el = log(1.0_dp / (1.0_dp - eta))
        r = ((1 - eta)**(-fbar) - 1 + eta) / ((1 - eta)**fbar - 1 + eta)
        printed = (eta + (1 - eta) * cosh(log(r)) - cosh(log(r) - fbar * el)) / eta
        corrected = (eta + (1 - eta) * cosh(0.5_dp * log(r)) - cosh(0.5_dp * log(r) - fbar * el)) &
                    / eta
        call check(error, printed, -0.053_dp, atol=5.0e-4_dp, message='printed 2.30')
        if (allocated(error)) return
        call check(error, rect_max_rotation_normalized(fbar, eta), 0.1328337665_dp, &
                   atol=5.0e-11_dp, message='corrected 2.30')
        if (allocated(error)) return
        call check(error, rect_max_rotation_normalized(fbar, eta), corrected, rtol=1.0e-12_dp)
        if (allocated(error)) return
        ! Eq. 2.29 with tau_m of 2.25, on a range; = max_rotation for the rectangle
        do i = 1, 9
            eta = 0.1_dp * i
            f = 0.9_dp * log(1.0_dp / (1.0_dp - eta))
            tm = log((1 - eta - exp(f)) / (1 - eta - exp(-f))) / (2 * f)
            printed = (eta + (1 - eta) * cosh(f * tm) - cosh(f * (tm - 1))) / eta
            call max_rotation(f, eta, inf, psi_max, stat)
            call check(error, psi_max, printed, rtol=1.0e-10_dp, message='2.29 eta='//real_str(eta))
            if (allocated(error)) return
            call check(error, rect_max_rotation_normalized(0.9_dp, eta), psi_max, rtol=1.0e-13_dp)
            if (allocated(error)) return
        end do
        ! Eq. 2.31a (eta -> 0): 1 - sqrt(1 - fbar^2); 2.31b (eta -> 1): 0
        do i = 1, 9
            fbar = 0.1_dp * i
            r = log(sqrt((1 + fbar) / (1 - fbar)))
            printed = 1 - cosh(r) + fbar * sinh(r)
            call check(error, printed, 1 - sqrt(1 - fbar**2), rtol=1.0e-12_dp)
            if (allocated(error)) return
            call check(error, rect_max_rotation_normalized(fbar, 1.0e-8_dp), printed, &
                       rtol=1.0e-6_dp, message='2.31a fbar='//real_str(fbar))
            if (allocated(error)) return
        end do
        ! 2.31b (eta -> 1): psi_max -> 0, algebraically, ~ (1 - eta)^(1 - fbar)
        do i = 1, 4
            fbar = 0.2_dp * i
            call check(error, approaches(2, fbar, 0.0_dp), &
                       '2.31b fbar='//real_str(fbar))
            if (allocated(error)) return
        end do
    end subroutine test_230

    !> 2.32: with the printed y3 (-2f e^(f/2 + beta)) the impact time at beta = pi, f = 0.5,
    !> eta = 0.379 comes out 2.888; the corrected y3 (-2f e^(beta - f/2)) gives 1.3391439583
    !> (doc/rocking.md rounds it to 1.338; 30-digit quadrature and the reference below agree on
    !> 1.33914). The printed "+ sqrt" root is the physical one only for f < 2|beta|.
    subroutine test_232(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: tau_i, y1, y2, y3p, y3c, plus, minus
        type(ref_t) :: r
        type(ref_result_t) :: rr
        integer :: stat, i
        real(dp), parameter :: etas(2) = [0.5772_dp, 0.6195_dp]
        call impact_time(0.5_dp, 0.379_dp, pi, tau_i, stat)
        call check(error, tau_i, 1.3391439583_dp, atol=5.0e-11_dp, message='corrected 2.32e')
        if (allocated(error)) return
        call check(error, abs(tau_i - 1.338_dp) < 2.0e-3_dp, 'doc/rocking.md example 1.338')
        if (allocated(error)) return
        call y_coefs(0.5_dp, 0.379_dp, pi, y1, y2, y3p, y3c)
        plus = log((sqrt(y2 * y3p + y1**2) - y1) / y3p) / 0.5_dp
        call check(error, plus, 2.8877_dp, atol=1.0e-4_dp, message='printed y3')
        if (allocated(error)) return
        plus = log((sqrt(y2 * y3c + y1**2) - y1) / y3c) / 0.5_dp
        call check(error, tau_i, plus, rtol=1.0e-12_dp, message='corrected 2.32b-e')
        if (allocated(error)) return
        call ref_setup(r, 0.5_dp, 0.379_dp, pi)
        call ref_derive(r, rr)
        call check(error, tau_i, rr%tau_i, rtol=rtol_ref, message='reference')
        if (allocated(error)) return
        ! f = 2.5 > 2|beta| = 1 (S2 and S1 with impact after the pulse): the "-" root
        do i = 1, 2
            call impact_time(2.5_dp, etas(i), 0.5_dp, tau_i, stat)
            call y_coefs(2.5_dp, etas(i), 0.5_dp, y1, y2, y3p, y3c)
            plus = log((sqrt(y2 * y3c + y1**2) - y1) / y3c) / 2.5_dp
            minus = log((-sqrt(y2 * y3c + y1**2) - y1) / y3c) / 2.5_dp
            call check(error, plus < 1.0_dp .and. tau_i > 1.0_dp, 'printed + root spurious')
            if (allocated(error)) return
            call check(error, tau_i, minus, rtol=1.0e-11_dp, message='- root, f > 2|beta|')
            if (allocated(error)) return
            call ref_setup(r, 2.5_dp, etas(i), 0.5_dp)
            call ref_derive(r, rr)
            call check(error, tau_i, rr%tau_i, rtol=rtol_ref, message='reference, f > 2|beta|')
            if (allocated(error)) return
        end do
    contains
        subroutine y_coefs(f, eta, b, y1, y2, y3p, y3c)
            real(dp), intent(in) :: f, eta, b
            real(dp), intent(out) :: y1, y2, y3p, y3c
            real(dp) :: q
            q = 1.0_dp - eta * (1.0_dp - exp(b))
            y1 = -eta / (2 * b) * (1 - exp(b)) * (f**2 - 4 * b**2)
            y2 = -2 * f * exp(f / 2 + b) + exp(f) * (f + 2 * b) + (f - 2 * b) * q**(1 + f / (2 * b))
            y3p = -2 * f * exp(f / 2 + b) + exp(-f) * (f - 2 * b) &
                  + (f + 2 * b) * q**(1 - f / (2 * b))
            y3c = -2 * f * exp(b - f / 2) + exp(-f) * (f - 2 * b) &
                  + (f + 2 * b) * q**(1 - f / (2 * b))
        end subroutine y_coefs
    end subroutine test_232

    !> Triangle impact: 2.34a during the pulse, corrected 2.34b after it; the printed 2.34b
    !> takes the square root of ab < 0.
    subroutine test_234(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: etas(4) = [0.4312_dp, 0.5260_dp, 0.6208_dp, 0.7156_dp]
        real(dp) :: tau_i, a, b, f, eta, corrected, psi, dpsi
        type(ref_t) :: r
        type(ref_result_t) :: rr
        integer :: i, stat
        f = 1.0_dp
        do i = 1, 4
            eta = etas(i)
            call impact_time(f, eta, 0.0_dp, tau_i, stat)
            a = exp(-f) - 2 * exp(-f / 2) + exp(-f * eta / 2)
            b = exp(f) - 2 * exp(f / 2) + exp(f * eta / 2)
            call check(error, a * b < 0.0_dp, 'printed 2.34b: sqrt(ab) of a negative number')
            if (allocated(error)) return
            corrected = log((-sqrt(a * b + (f * eta / 2)**2) - f * eta / 2) / a) / f
            call check(error, tau_i, corrected, rtol=1.0e-11_dp, message='corrected 2.34b')
            if (allocated(error)) return
            call ref_setup(r, f, eta, 0.0_dp)
            call ref_derive(r, rr)
            call check(error, tau_i, rr%tau_i, rtol=rtol_ref, message='2.34b reference')
            if (allocated(error)) return
        end do
        ! impact during the pulse (psi(1) < 0): 2.34a root
        eta = 0.9052_dp
        call rocking_response(1.0_dp, f, eta, 0.0_dp, psi, dpsi, stat)
        call check(error, ieee_is_nan(psi), 'impact before the end of the pulse')
        if (allocated(error)) return
        call impact_time(f, eta, 0.0_dp, tau_i, stat)
        call check(error, tau_i < 1.0_dp, '2.34a: tau_i < 1')
        if (allocated(error)) return
        call check(error, sinh(f * (tau_i - eta / 2)) - 2 * sinh(f * (tau_i - 0.5_dp)) &
                   + f * (tau_i + eta / 2 - 1), 0.0_dp, atol=1.0e-15_dp, message='2.34a residual')
        if (allocated(error)) return
        call ref_setup(r, f, eta, 0.0_dp)
        call ref_derive(r, rr)
        call check(error, tau_i, rr%tau_i, rtol=rtol_ref, message='2.34a reference')
    end subroutine test_234

    !> Rectangle impact time: 2.33, the corrected normalized 2.35 (prefactor 1/fbar, log
    !> argument without the sign error) and its limits 2.36 (fbar, not f, in 2.36a).
    subroutine test_235(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: fbar, eta, el, f, tau_i, printed, arg, inf, limit
        integer :: i, j, stat
        inf = ieee_value(inf, ieee_negative_inf)
        do i = 1, 9
            eta = 0.1_dp * i
            el = log(1.0_dp / (1.0_dp - eta))
            do j = 1, 4
                fbar = 0.2_dp * j
                f = fbar * el
                call impact_time(f, eta, inf, tau_i, stat)
                printed = log(((exp(-f) - 1) * sqrt(exp(f) * (1 - eta)) - eta) &
                              / (1 - eta - exp(-f))) / f
                call check(error, tau_i, printed, rtol=1.0e-10_dp, message='2.33')
                if (allocated(error)) return
                call check(error, rect_impact_time_normalized(fbar, eta), &
                           eta * tau_i / (1 + sqrt(1 - eta)), rtol=1.0e-13_dp, &
                           message='corrected 2.35 = 2.33')
                if (allocated(error)) return
                ! printed 2.35: the log argument is negative
                arg = (1 - (1 - eta)**(-fbar)) * sqrt((1 - eta)**(-fbar + 1) + eta) &
                      / ((1 - eta)**fbar - 1 + eta)
                call check(error, arg < 0.0_dp, 'printed 2.35 argument should be negative')
                if (allocated(error)) return
            end do
        end do
        ! 2.36a corrected: (1/(2 fbar)) ln[(1 + fbar)/(1 - fbar)] as eta -> 0; the printed
        ! f (-> 0 with eta) would give 1
        do j = 1, 4
            fbar = 0.2_dp * j
            limit = log((1 + fbar) / (1 - fbar)) / (2 * fbar)
            eta = 1.0e-8_dp
            f = fbar * log(1.0_dp / (1.0_dp - eta))
            printed = log((1 + f) / (1 - f)) / (2 * f)
            call check(error, rect_impact_time_normalized(fbar, eta), limit, rtol=1.0e-6_dp, &
                       message='2.36a')
            if (allocated(error)) return
            call check(error, abs(printed - limit) > 1.0e-3_dp, 'printed 2.36a should differ')
            if (allocated(error)) return
            ! 2.36b: -> 1 as eta -> 1 (algebraically in 1 - eta)
            call check(error, approaches(3, fbar, 1.0_dp), '2.36b')
            if (allocated(error)) return
        end do
        ! f -> 0: tau_i -> (1 + sqrt(1 - eta))/eta (text before 2.35)
        call impact_time(1.0e-6_dp, 0.4_dp, inf, tau_i, stat)
        call check(error, tau_i, (1 + sqrt(0.6_dp)) / 0.4_dp, rtol=1.0e-5_dp, message='f -> 0')
    end subroutine test_235

    subroutine test_wall_limits(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: f, x, y, inf, prev
        real(dp), parameter :: bs(4) = [-30.0_dp, -60.0_dp, -200.0_dp, -1.0e4_dp]
        real(dp), parameter :: vals(4) = [0.70771_dp, 0.71766_dp, 0.72454_dp, -1.0_dp]  ! 4: unused
        integer :: i, stat
        inf = ieee_value(inf, ieee_negative_inf)
        do i = 1, 16
            f = 0.5_dp * i
            call stability_wall(f, inf, x, stat)
            call check(error, x, 1.0_dp - exp(-f), rtol=1.0e-15_dp, message='2.21')
            if (allocated(error)) return
            call stability_wall(f, 0.0_dp, x, stat)
            call check(error, x, 2.0_dp - 2.0_dp / f * log(2 * exp(f / 2) - 1), rtol=1.0e-13_dp, &
                       message='2.22 f='//real_str(f))
            if (allocated(error)) return
            ! tiny beta joins the triangle smoothly: d eta_w/d beta = O(1)
            call stability_wall(f, 1.0e-9_dp, y, stat)
            call check(error, y, x, rtol=1.0e-8_dp, message='beta = 1e-9')
            if (allocated(error)) return
            call stability_wall(f, -1.0e-9_dp, y, stat)
            call check(error, y, x, rtol=1.0e-8_dp, message='beta = -1e-9')
            if (allocated(error)) return
        end do
        ! small f: 2.22 ~ f/2, without the cancellation of its printed form
        call stability_wall(1.0e-7_dp, 0.0_dp, x, stat)
        call check(error, x, 0.5e-7_dp, rtol=1.0e-6_dp, message='2.22, f -> 0')
        if (allocated(error)) return
        ! doc/rocking.md section 2, item 4: O(1/|beta|) convergence to the rectangle at f = 1.3
        prev = 1.0_dp
        do i = 1, 4
            call stability_wall(1.3_dp, bs(i), x, stat)
            if (i <= 3) then
                call check(error, x, vals(i), atol=5.0e-6_dp, message='beta = '//real_str(bs(i)))
                if (allocated(error)) return
            end if
            call check(error, abs(x - (1 - exp(-1.3_dp))) < prev, 'closer to 2.21')
            if (allocated(error)) return
            prev = abs(x - (1 - exp(-1.3_dp)))
        end do
        call check(error, prev < 1.0e-3_dp .and. prev > 1.0e-6_dp, 'beta = -1e4: O(1/|beta|)')
    end subroutine test_wall_limits

    subroutine test_tau_m_limits(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: eta, f, tau_m, printed, fbar, el, num, den, inf, limit
        integer :: i, j, stat, region
        inf = ieee_value(inf, ieee_negative_inf)
        do i = 1, 9
            eta = 0.1_dp * i
            el = log(1.0_dp / (1.0_dp - eta))
            do j = 1, 4
                fbar = 0.22_dp * j
                f = fbar * el
                call time_of_max(f, eta, inf, tau_m, stat)
                printed = log((1 - eta - exp(f)) / (1 - eta - exp(-f))) / (2 * f)
                call check(error, tau_m, printed, rtol=1.0e-11_dp, message='2.25')
                if (allocated(error)) return
                printed = -1 / (2 * fbar) * eta / log(1 - eta) &
                          * log(((1 - eta)**(-fbar) - 1 + eta) / ((1 - eta)**fbar - 1 + eta))
                call check(error, rect_time_of_max_normalized(fbar, eta), printed, &
                           rtol=1.0e-11_dp, message='2.27')
                if (allocated(error)) return
                call check(error, rect_time_of_max_normalized(fbar, eta), eta * tau_m, &
                           rtol=1.0e-13_dp)
                if (allocated(error)) return
            end do
        end do
        do j = 1, 4
            fbar = 0.22_dp * j
            limit = log((1 + fbar) / (1 - fbar)) / (2 * fbar)
            call check(error, rect_time_of_max_normalized(fbar, 1.0e-8_dp), limit, rtol=1.0e-6_dp, &
                       message='2.28a')
            if (allocated(error)) return
            call check(error, approaches(1, fbar, 1.0_dp), '2.28b')
            if (allocated(error)) return
        end do
        ! f -> 0: tau_m -> 1/eta
        call time_of_max(1.0e-6_dp, 0.4_dp, inf, tau_m, stat)
        call check(error, tau_m, 2.5_dp, rtol=1.0e-6_dp, message='f -> 0')
        if (allocated(error)) return
        ! triangle 2.26a (S1) and 2.26b (S2) in their printed forms
        do i = 1, 12
            eta = 0.08_dp * i
            f = 1.0_dp
            call rocking_classify(f, eta, 0.0_dp, region, stat)
            if (region /= ROCK_S1 .and. region /= ROCK_S2) cycle
            call time_of_max(f, eta, 0.0_dp, tau_m, stat)
            if (region == ROCK_S1) then
                num = 1 + 2 * sqrt(cosh(f / 2 * (1 - eta)) - 1)
                den = 2 * exp(-f / 2) - exp(-f * eta / 2)
                printed = log(num / den) / f
                call check(error, printed <= 1.0_dp, '2.26a valid in S1')
            else
                printed = log(-(2 * exp(f / 2) - exp(f * eta / 2) - exp(f)) &
                              / (2 * exp(-f / 2) - exp(-f * eta / 2) - exp(-f))) / (2 * f)
                call check(error, printed > 1.0_dp, '2.26b > 1 in S2')
            end if
            if (allocated(error)) return
            call check(error, tau_m, printed, rtol=1.0e-12_dp, message='2.26 eta='//real_str(eta))
            if (allocated(error)) return
        end do
    end subroutine test_tau_m_limits

    !> The printed 2.10-2.15 are right (only unstable near f = 2|beta|, beta = 0 and large
    !> |beta|): where they are well conditioned they agree with the library.
    subroutine test_printed_response(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: betas(5) = [pi, -pi, 1.0_dp, -1.0_dp, 0.3_dp]
        real(dp), parameter :: taus(7) = [0.35_dp, 0.45_dp, 0.5_dp, 0.62_dp, 0.8_dp, 1.0_dp, &
                                          1.3_dp]
        real(dp) :: psi, dpsi, pp, pq, f, eta, inf, b, q, x1, x2, x3, dx1, dx2, dx3, den, t
        integer :: i, j, stat
        inf = ieee_value(inf, ieee_negative_inf)
        f = 1.7_dp
        eta = 0.3_dp
        do i = 1, 5
            b = betas(i)
            q = 1 - eta * (1 - exp(b))
            do j = 1, 7
                t = taus(j)
                call rocking_response(t, f, eta, b, psi, dpsi, stat)
                x1 = b * (f + 2 * b) * q**(1 - f / (2 * b)) * exp(f * t) &
                     - b * (f - 2 * b) * q**(1 + f / (2 * b)) * exp(-f * t) &
                     + f**2 * (1 - exp(2 * b * t)) - 4 * b**2
                dx1 = f * b * (f + 2 * b) * q**(1 - f / (2 * b)) * exp(f * t) &
                      + f * b * (f - 2 * b) * q**(1 + f / (2 * b)) * exp(-f * t) &
                      - 2 * b * f**2 * exp(2 * b * t)
                x2 = 0.0_dp
                dx2 = 0.0_dp
                x3 = 0.0_dp
                dx3 = 0.0_dp
                if (t > 0.5_dp) then
                    x2 = f**2 * (exp(2 * b * t) - exp(2 * b * (1 - t))) &
                         - 2 * b * f * exp(b) * (exp(f * (t - 0.5_dp)) - exp(-f * (t - 0.5_dp)))
                    dx2 = 2 * b * f**2 * (exp(2 * b * t) + exp(2 * b * (1 - t))) &
                          - 2 * b * f**2 * exp(b) * (exp(f * (t - 0.5_dp)) + exp(-f * (t - 0.5_dp)))
                end if
                if (t > 1.0_dp) then
                    x3 = f**2 * exp(2 * b * (1 - t)) - (f**2 - 4 * b**2) &
                         + b * ((f - 2 * b) * exp(f * (t - 1)) - (f + 2 * b) * exp(-f * (t - 1)))
                    dx3 = -2 * b * f**2 * exp(2 * b * (1 - t)) &
                          + b * f * ((f - 2 * b) * exp(f * (t - 1)) &
                                     + (f + 2 * b) * exp(-f * (t - 1)))
                end if
                den = eta * (1 - exp(b)) * (f**2 - 4 * b**2)
                pp = 1 - (x1 + x2 + x3) / den
                pq = -(dx1 + dx2 + dx3) / (f * den)
                call check(error, psi, pp, rtol=1.0e-10_dp, atol=1.0e-12_dp, &
                           message='2.10a beta='//real_str(b)//' tau='//real_str(t))
                if (allocated(error)) return
                call check(error, dpsi, pq, rtol=1.0e-10_dp, atol=1.0e-12_dp, &
                           message='2.10b beta='//real_str(b)//' tau='//real_str(t))
                if (allocated(error)) return
            end do
        end do
        do j = 1, 7
            t = taus(j)
            ! rectangle 2.12, 2.13
            call rocking_response(t, f, eta, inf, psi, dpsi, stat)
            pp = (1 / eta - 1) * (cosh(f * t) - 1)
            pq = (1 / eta - 1) * sinh(f * t)
            if (t > 1.0_dp) then
                pp = pp - (cosh(f * (t - 1)) - 1) / eta
                pq = pq - sinh(f * (t - 1)) / eta
            end if
            call check(error, psi, pp, rtol=1.0e-12_dp, message='2.12')
            if (allocated(error)) return
            call check(error, dpsi, pq, rtol=1.0e-12_dp, message='2.13')
            if (allocated(error)) return
            ! triangle 2.14, 2.15
            call rocking_response(t, f, eta, 0.0_dp, psi, dpsi, stat)
            pp = 1 - (2 * t - 2 / f * sinh(f * (t - eta / 2))) / eta
            pq = -2 / (eta * f) * (1 - cosh(f * (t - eta / 2)))
            if (t > 0.5_dp) then
                pp = pp - (2 - 4 * t + 4 / f * sinh(f * (t - 0.5_dp))) / eta
                pq = pq - 4 / (eta * f) * (-1 + cosh(f * (t - 0.5_dp)))
            end if
            if (t > 1.0_dp) then
                pp = pp - (2 * (t - 1) - 2 / f * sinh(f * (t - 1))) / eta
                pq = pq - 2 / (eta * f) * (1 - cosh(f * (t - 1)))
            end if
            call check(error, psi, pp, rtol=1.0e-11_dp, atol=1.0e-13_dp, message='2.14')
            if (allocated(error)) return
            call check(error, dpsi, pq, rtol=1.0e-11_dp, atol=1.0e-13_dp, message='2.15')
            if (allocated(error)) return
        end do
    end subroutine test_printed_response

    !> Section 5.3: eta_w increases in f and decreases in beta; -> 0 as f -> 0, -> 1 as
    !> f -> inf.
    subroutine test_monotone(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: betas(6), bseq(14), fs(4), prev, x, f, inf
        integer :: i, j, stat
        inf = ieee_value(inf, ieee_positive_inf)
        betas = [-inf, -2 * pi, -pi, 0.0_dp, pi, 2 * pi]
        do i = 1, 6
            prev = 0.0_dp
            do j = 0, 199
                f = 0.05_dp + j * (10.0_dp - 0.05_dp) / 199
                call stability_wall(f, betas(i), x, stat)
                call check(error, x > prev .and. x < 1.0_dp, 'eta_w increasing in f, beta = ' &
                           //real_str(betas(i))//', f = '//real_str(f))
                if (allocated(error)) return
                prev = x
            end do
            call stability_wall(1.0e-6_dp, betas(i), x, stat)
            call check(error, x < 1.0e-5_dp, 'eta_w -> 0 as f -> 0')
            if (allocated(error)) return
            ! slowly, 1 - O(1/f) (triangle: 1 - 2 ln 2/f)
            call stability_wall(1.0e4_dp, betas(i), x, stat)
            call check(error, x > 0.999_dp .and. x <= 1.0_dp, 'eta_w -> 1 as f -> inf')
            if (allocated(error)) return
        end do
        bseq = [-inf, -1.0e4_dp, -100.0_dp, -20.0_dp, -2 * pi, -pi, -1.0_dp, -1.0e-9_dp, 0.0_dp, &
                1.0e-9_dp, 1.0_dp, pi, 2 * pi, 20.0_dp]
        fs = [0.3_dp, 1.0_dp, 3.0_dp, 8.0_dp]
        do i = 1, 4
            prev = 2.0_dp
            do j = 1, 14
                call stability_wall(fs(i), bseq(j), x, stat)
                call check(error, x < prev, 'eta_w decreasing in beta, f = '//real_str(fs(i)) &
                           //', beta = '//real_str(bseq(j)))
                if (allocated(error)) return
                prev = x
            end do
        end do
    end subroutine test_monotone

    !> Section 4.1 items 1-4: f = 2|beta| exactly and nearby, tiny beta, huge |beta|.
    subroutine test_singular(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: bs(6) = [0.5_dp, 1.0_dp, pi, -0.5_dp, -1.0_dp, -pi]
        real(dp), parameter :: rel(5) = [-1.0e-6_dp, -1.0e-12_dp, 0.0_dp, 1.0e-12_dp, 1.0e-6_dp]
        real(dp), parameter :: big(8) = [50.0_dp, 300.0_dp, 1.0e3_dp, 1.0e5_dp, -50.0_dp, &
                                         -300.0_dp, -1.0e3_dp, -1.0e5_dp]
        real(dp) :: f, eta, x0, vals(5, 6), tu, tc, tm, pm, ti, psi, dpsi, inf, rpm, rtm
        integer :: i, j, k, region, stat, r0
        inf = ieee_value(inf, ieee_negative_inf)
        do i = 1, 6
            call stability_wall(2 * abs(bs(i)), bs(i), x0, stat)
            do k = 1, 3
                eta = x0 + (1.0_dp - x0) * 0.25_dp * k
                if (k == 3) eta = 0.5_dp * x0
                r0 = -1
                do j = 1, 5
                    f = 2 * abs(bs(i)) * (1 + rel(j))
                    call rocking_summary(f, eta, bs(i), region, tu, tc, tm, pm, ti, stat)
                    call rocking_response(0.77_dp, f, eta, bs(i), psi, dpsi, stat)
                    vals(j, :) = [tc, tm, pm, ti, psi, dpsi]
                    if (r0 < 0) r0 = region
                    call check(error, region == r0, 'region constant across f = 2|beta|')
                    if (allocated(error)) return
                    call check(error, stat == SEISPULSE_SUCCESS, 'stat')
                    if (allocated(error)) return
                end do
                ! values at f(1 +- 1e-12) and exactly 2|beta| agree (no 0/0 noise) and the
                ! +-1e-6 neighbours differ by O(1e-6)
                do j = 1, 6
                    if (ieee_is_nan(vals(3, j))) cycle
                    if (vals(3, j) > huge(x0)) cycle
                    ! (a relative change of 1e-12 in f moves an O(1) quantity by ~1e-12)
                    call check(error, vals(2, j), vals(3, j), rtol=1.0e-10_dp, atol=1.0e-11_dp, &
                               message='f = 2|beta|(1 - 1e-12)')
                    if (allocated(error)) return
                    call check(error, vals(4, j), vals(3, j), rtol=1.0e-10_dp, atol=1.0e-11_dp, &
                               message='f = 2|beta|(1 + 1e-12)')
                    if (allocated(error)) return
                    call check(error, vals(1, j), vals(3, j), rtol=1.0e-4_dp, atol=1.0e-8_dp, &
                               message='f = 2|beta|(1 - 1e-6)')
                    if (allocated(error)) return
                    call check(error, vals(5, j), vals(3, j), rtol=1.0e-4_dp, atol=1.0e-8_dp, &
                               message='f = 2|beta|(1 + 1e-6)')
                    if (allocated(error)) return
                end do
            end do
        end do
        ! large |beta|: finite, no overflow; beta -> -inf tends to the rectangle at O(1/|beta|),
        ! beta -> +inf to no motion
        do i = 1, 8
            call rocking_summary(1.5_dp, 0.6_dp, big(i), region, tu, tc, tm, pm, ti, stat)
            call check(error, stat == SEISPULSE_SUCCESS .and. ieee_is_finite(tu) .and. &
                       region /= ROCK_NONE, 'large beta = '//real_str(big(i)))
            if (allocated(error)) return
            call check(error, ieee_is_finite(pm) .eqv. (region == ROCK_S1 .or. region == ROCK_S2), &
                       'finite psi_max in S')
            if (allocated(error)) return
            call rocking_response(0.9_dp, 1.5_dp, 0.6_dp, big(i), psi, dpsi, stat)
            if (ieee_is_finite(ti)) then
                if (ti > 0.9_dp) then
                    call check(error, ieee_is_finite(psi) .and. ieee_is_finite(dpsi), &
                               'response finite before impact')
                else
                    call check(error, ieee_is_nan(psi), 'response NaN after impact')
                end if
            else
                call check(error, ieee_is_finite(psi) .and. ieee_is_finite(dpsi), &
                           'response finite while overturning')
            end if
            if (allocated(error)) return
        end do
        ! (inf is -inf here; eta = 0.85 is above the rectangle's wall 1 - e^-1.5: S2)
        call rocking_summary(1.5_dp, 0.85_dp, inf, region, tu, tc, rtm, rpm, ti, stat)
        call check(error, region == ROCK_S2, 'rectangle S2')
        if (allocated(error)) return
        call rocking_summary(1.5_dp, 0.85_dp, -1.0e5_dp, region, tu, tc, tm, pm, ti, stat)
        call check(error, pm, rpm, rtol=1.0e-4_dp, message='beta = -1e5 ~ rectangle')
        if (allocated(error)) return
        call check(error, tm, rtm, rtol=1.0e-4_dp, message='beta = -1e5 ~ rectangle tau_m')
        if (allocated(error)) return
        call rocking_summary(1.5_dp, 0.6_dp, 1.0e5_dp, region, tu, tc, tm, pm, ti, stat)
        call check(error, pm < 1.0e-8_dp .and. pm > 0.0_dp, 'beta = 1e5: tiny rocking')
        if (allocated(error)) return
        ! beta ~ 0 joins the triangle: derivatives in beta are O(1)
        call rocking_summary(2.0_dp, 0.7_dp, 0.0_dp, region, tu, tc, rtm, rpm, ti, stat)
        call check(error, region == ROCK_S1 .or. region == ROCK_S2, 'triangle case in S')
        if (allocated(error)) return
        do i = -1, 1, 2
            call rocking_summary(2.0_dp, 0.7_dp, i * 1.0e-9_dp, region, tu, tc, tm, pm, ti, stat)
            call check(error, pm, rpm, rtol=1.0e-8_dp, message='beta = +-1e-9 psi_max')
            if (allocated(error)) return
            call check(error, tm, rtm, rtol=1.0e-8_dp, message='beta = +-1e-9 tau_m')
            if (allocated(error)) return
        end do
    end subroutine test_singular

    subroutine test_inverses(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: betas(6), inf, f, x, y, eta
        integer :: i, j, stat
        logical :: at_end
        inf = ieee_value(inf, ieee_positive_inf)
        betas = [-inf, -pi, -1.0e-9_dp, 0.0_dp, 1.0_dp, 3 * pi]
        do i = 1, 6
            do j = 1, 5
                f = 0.3_dp * j**1.5_dp
                call stability_wall(f, betas(i), eta, stat)
                call stability_wall_inverse(eta, betas(i), x, stat)
                call check(error, x, f, rtol=1.0e-9_dp, message='wall inverse')
                if (allocated(error)) return
                at_end = mod(j, 2) == 0
                call overturn_boundary(f, betas(i), at_end, eta, stat)
                call overturn_boundary_inverse(eta, betas(i), at_end, x, stat)
                call check(error, x, f, rtol=1.0e-9_dp, message='overturn inverse beta=' &
                           //real_str(betas(i)))
                if (allocated(error)) return
                call overturn_boundary(x, betas(i), at_end, y, stat)
                call check(error, y, eta, rtol=1.0e-12_dp)
                if (allocated(error)) return
            end do
        end do
    end subroutine test_inverses

    subroutine test_summary(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: etas(5) = [0.05_dp, 0.2_dp, 0.45_dp, 0.7_dp, 0.93_dp]
        real(dp) :: betas(4), tu, tc, tm, pm, ti, x, psi, dpsi, inf
        integer :: i, j, region, r2, stat
        inf = ieee_value(inf, ieee_negative_inf)
        betas = [-inf, -1.3_dp, 0.0_dp, 2.2_dp]
        do i = 1, 4
            do j = 1, 5
                call rocking_summary(2.0_dp, etas(j), betas(i), region, tu, tc, tm, pm, ti, stat)
                call rocking_classify(2.0_dp, etas(j), betas(i), r2, stat)
                call check(error, region == r2, 'classify')
                if (allocated(error)) return
                call uplift_time(etas(j), betas(i), x, stat)
                call check(error, same(x, tu), 'uplift')
                if (allocated(error)) return
                call critical_time(2.0_dp, etas(j), betas(i), x, stat)
                call check(error, same(x, tc), 'tau_c')
                if (allocated(error)) return
                call time_of_max(2.0_dp, etas(j), betas(i), x, stat)
                call check(error, same(x, tm), 'tau_m')
                if (allocated(error)) return
                call max_rotation(2.0_dp, etas(j), betas(i), x, stat)
                call check(error, same(x, pm), 'psi_max')
                if (allocated(error)) return
                call impact_time(2.0_dp, etas(j), betas(i), x, stat)
                call check(error, same(x, ti), 'tau_i')
                if (allocated(error)) return
                ! response: psi(tau_c) = 1, psi'(tau_m) = 0, psi(tau_m) = psi_max, NaN after
                ! tau_i, the formula kept past psi = 1
                select case (region)
                case (ROCK_O1, ROCK_O2, ROCK_O3)
                    call rocking_response(tc, 2.0_dp, etas(j), betas(i), psi, dpsi, stat)
                    call check(error, psi, 1.0_dp, rtol=1.0e-12_dp, message='psi(tau_c)')
                    if (allocated(error)) return
                    call rocking_response(tc + 0.5_dp, 2.0_dp, etas(j), betas(i), psi, dpsi, stat)
                    call check(error, psi > 1.0_dp .and. dpsi > 0.0_dp, 'past overturning')
                case (ROCK_S1, ROCK_S2)
                    call rocking_response(tm, 2.0_dp, etas(j), betas(i), psi, dpsi, stat)
                    call check(error, psi, pm, rtol=1.0e-12_dp, message='psi(tau_m)')
                    if (allocated(error)) return
                    call check(error, dpsi, 0.0_dp, atol=1.0e-13_dp, message='psi''(tau_m)')
                    if (allocated(error)) return
                    call rocking_response(0.999_dp * ti, 2.0_dp, etas(j), betas(i), psi, dpsi, stat)
                    call check(error, psi > 0.0_dp, 'before impact')
                    if (allocated(error)) return
                    call rocking_response(1.001_dp * ti, 2.0_dp, etas(j), betas(i), psi, dpsi, stat)
                    call check(error, ieee_is_nan(psi) .and. ieee_is_nan(dpsi), 'after impact')
                end select
                if (allocated(error)) return
            end do
        end do
    contains
        !> a = b exactly, both NaN or both +inf (no ordered comparison on NaN).
        logical function same(a, b)
            real(dp), intent(in) :: a, b
            if (ieee_is_nan(a) .or. ieee_is_nan(b)) then
                same = ieee_is_nan(a) .and. ieee_is_nan(b)
            else if (abs(a) > huge(a) .or. abs(b) > huge(b)) then
                same = a > huge(a) .and. b > huge(b)
            else
                same = .not. abs(a - b) > 0.0_dp
            end if
        end function same
    end subroutine test_summary

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: nan, inf, x, y
        character(len=256) :: msg
        integer :: stat, region
        nan = ieee_value(nan, ieee_quiet_nan)
        inf = ieee_value(inf, ieee_positive_inf)
        msg = ''
        call rocking_classify(0.0_dp, 0.5_dp, 1.0_dp, region, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'f = 0') == 1, trim(msg))
        if (allocated(error)) return
        call time_of_max(-1.0_dp, 0.5_dp, 1.0_dp, x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'f =') == 1, trim(msg))
        if (allocated(error)) return
        call max_rotation(nan, 0.5_dp, 1.0_dp, x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'f = NaN') == 1, &
                   trim(msg))
        if (allocated(error)) return
        call stability_wall(inf, 1.0_dp, x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'f =') == 1, trim(msg))
        if (allocated(error)) return
        call impact_time(1.0_dp, 0.0_dp, 1.0_dp, x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'eta =') == 1, trim(msg))
        if (allocated(error)) return
        call critical_time(1.0_dp, nan, 1.0_dp, x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'eta = NaN') == 1, &
                   trim(msg))
        if (allocated(error)) return
        call uplift_time(-0.1_dp, 1.0_dp, x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'eta =') == 1, trim(msg))
        if (allocated(error)) return
        call stability_wall_inverse(nan, 1.0_dp, x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'eta =') == 1, trim(msg))
        if (allocated(error)) return
        call overturn_boundary(1.0_dp, nan, .true., x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'beta') == 1, trim(msg))
        if (allocated(error)) return
        call s1_s2_boundary(1.0_dp, nan, x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'beta') == 1, trim(msg))
        if (allocated(error)) return
        call overturn_boundary_inverse(-2.0_dp, 1.0_dp, .false., x, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'eta =') == 1, trim(msg))
        if (allocated(error)) return
        call rocking_response(nan, 1.0_dp, 0.5_dp, 1.0_dp, x, y, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'tau = NaN') == 1 .and. &
                   ieee_is_nan(x), trim(msg))
        if (allocated(error)) return
        call rocking_response(inf, 1.0_dp, 0.5_dp, 1.0_dp, x, y, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'tau =') == 1, trim(msg))
        if (allocated(error)) return
        call rocking_response(0.5_dp, 1.0_dp, 0.5_dp, nan, x, y, stat)
        call check(error, stat == SEISPULSE_INVALID_INPUT, 'no errmsg: stat only')
    end subroutine test_bad_input

    !> g(fbar, eta) -> limit as eta -> 1 for the normalized rectangle form `which` (1 eta tau_m,
    !> 2 theta_max/alpha, 3 eta tau_i/(1 + sqrt(1 - eta))): |g - limit| at eta = 1 - 10^-k,
    !> k = 2, 4, .., 14, decreases strictly and ends below a tenth of its first value.
    logical function approaches(which, fbar, limit)
        integer, intent(in) :: which
        real(dp), intent(in) :: fbar, limit
        real(dp) :: d, d0, prev
        integer :: k
        approaches = .true.
        d0 = abs(g(1.0_dp - 1.0e-2_dp) - limit)
        prev = d0
        do k = 4, 14, 2
            d = abs(g(1.0_dp - 10.0_dp**(-k)) - limit)
            approaches = approaches .and. d < prev
            prev = d
        end do
        approaches = approaches .and. prev < 0.1_dp * d0
    contains
        real(dp) function g(eta)
            real(dp), intent(in) :: eta
            select case (which)
            case (1)
                g = rect_time_of_max_normalized(fbar, eta)
            case (2)
                g = rect_max_rotation_normalized(fbar, eta)
            case default
                g = rect_impact_time_normalized(fbar, eta)
            end select
        end function g
    end function approaches

    ! ------------------------------------------------------------------------------
    ! The grid against the reference (doc/rocking.md: closed form vs integration)
    ! ------------------------------------------------------------------------------

    subroutine test_grid(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: fs(9) = [0.2_dp, 0.45_dp, 0.8_dp, 1.3_dp, 2.0_dp, 3.1_dp, 4.7_dp, &
                                        6.5_dp, 8.0_dp]
        real(dp), parameter :: etas(10) = [0.03_dp, 0.1_dp, 0.2_dp, 0.33_dp, 0.47_dp, 0.6_dp, &
                                           0.72_dp, 0.85_dp, 0.93_dp, 0.98_dp]
        real(dp) :: betas(18), inf, f
        integer :: ib, ie, jf, nf
        inf = ieee_value(inf, ieee_negative_inf)
        betas = [inf, -3 * pi, -2 * pi, -5.0_dp, -pi, -2.0_dp, -1.0_dp, -0.37_dp, -1.0e-9_dp, &
                 0.0_dp, 1.0e-9_dp, 0.37_dp, 1.0_dp, 2.0_dp, pi, 5.0_dp, 2 * pi, 3 * pi]
        do ib = 1, size(betas)
            nf = size(fs)
            ! f = 2|beta| exactly, where 2|beta| is in [0.2, 8]
            if (abs(betas(ib)) >= 0.1_dp .and. abs(betas(ib)) <= 4.0_dp) nf = nf + 1
            do jf = 1, nf
                if (jf <= size(fs)) then
                    f = fs(jf)
                else
                    f = 2.0_dp * abs(betas(ib))
                end if
                do ie = 1, size(etas)
                    call compare_case(error, f, etas(ie), betas(ib))
                    if (allocated(error)) return
                end do
            end do
        end do
    end subroutine test_grid

    !> One case: region, uplift, psi and psi'/f along the excursion, tau_c, tau_m, psi_max,
    !> tau_i against the reference.
    subroutine compare_case(error, f, eta, beta)
        type(test_error), allocatable, intent(inout) :: error
        real(dp), intent(in) :: f, eta, beta
        type(ref_t) :: r
        type(ref_result_t) :: rr
        real(dp) :: tu, tc, tm, pm, ti, tau, tend, psi, dpsi, rpsi, rq, rabs
        integer :: region, stat, k
        character(len=:), allocatable :: where
        where = 'f='//real_str(f)//' eta='//real_str(eta)//' beta='//real_str(beta)
        call ref_setup(r, f, eta, beta)
        call ref_derive(r, rr)
        call rocking_summary(f, eta, beta, region, tu, tc, tm, pm, ti, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'stat '//where)
        if (allocated(error)) return
        call check(error, region, rr%region, 'region '//where)
        if (allocated(error)) return
        call check(error, tu, r%tup, rtol=1.0e-13_dp, atol=1.0e-16_dp, message='tau_up '//where)
        if (allocated(error)) return
        ! the excursion: before the impact or, overturning, up to tau_c + 1/2
        select case (region)
        case (ROCK_S1, ROCK_S2)
            tend = rr%tau_i - 1.0e-3_dp * (rr%tau_i - r%tup)
        case default
            tend = max(1.0_dp, rr%tau_c) + 0.5_dp
        end select
        do k = 1, 9
            tau = r%tup + (tend - r%tup) * k / 9.0_dp
            call rocking_response(tau, f, eta, beta, psi, dpsi, stat)
            call ref_eval(r, tau, rpsi, rq, rabs)
            call check(error, psi, rpsi, rtol=rtol_ref, atol=1.0e-14_dp * rabs, &
                       message='psi '//where//' tau='//real_str(tau))
            if (allocated(error)) return
            call check(error, dpsi, rq, rtol=rtol_ref, atol=1.0e-14_dp * rabs, &
                       message='dpsi '//where//' tau='//real_str(tau))
            if (allocated(error)) return
        end do
        select case (region)
        case (ROCK_O1, ROCK_O2, ROCK_O3)
            call check(error, tc, rr%tau_c, rtol=rtol_ref, message='tau_c '//where)
        case (ROCK_S1, ROCK_S2)
            call check(error, tm, rr%tau_m, rtol=rtol_ref, message='tau_m '//where)
            if (allocated(error)) return
            call check(error, pm, rr%psi_max, rtol=rtol_ref, message='psi_max '//where)
            if (allocated(error)) return
            call check(error, ti, rr%tau_i, rtol=rtol_ref, message='tau_i '//where)
        end select
    end subroutine compare_case

    !> The boundaries against bisection on the reference: eta_w on the sign of A (5.3),
    !> 2.16a/b on psi(1) - 1, psi(1/2) - 1, and the S1/S2 boundary on psi'(1).
    subroutine test_boundaries_ref(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: fs(5) = [0.2_dp, 0.7_dp, 1.5_dp, 3.0_dp, 8.0_dp]
        real(dp) :: betas(9), inf, f, x, ref, lo
        integer :: ib, jf, stat, nf
        inf = ieee_value(inf, ieee_negative_inf)
        betas = [inf, -3 * pi, -pi, -1.0_dp, -1.0e-9_dp, 0.0_dp, 0.5_dp, pi, 3 * pi]
        do ib = 1, size(betas)
            nf = 5
            if (abs(betas(ib)) >= 0.1_dp .and. abs(betas(ib)) <= 4.0_dp) nf = 6
            do jf = 1, nf
                if (jf <= 5) then
                    f = fs(jf)
                else
                    f = 2.0_dp * abs(betas(ib))
                end if
                call stability_wall(f, betas(ib), x, stat)
                ref = ref_bisect_eta(f, betas(ib), 4, 0.0_dp)
                call check(error, x, ref, rtol=rtol_ref, message='eta_w f='//real_str(f) &
                           //' beta='//real_str(betas(ib)))
                if (allocated(error)) return
                call overturn_boundary(f, betas(ib), .true., x, stat)
                ref = ref_bisect_eta(f, betas(ib), 2, 0.0_dp)
                call check(error, x, ref, rtol=rtol_ref, message='2.16a f='//real_str(f) &
                           //' beta='//real_str(betas(ib)))
                if (allocated(error)) return
                call overturn_boundary(f, betas(ib), .false., x, stat)
                ref = ref_bisect_eta(f, betas(ib), 1, 0.0_dp)
                call check(error, x, ref, rtol=rtol_ref, message='2.16b f='//real_str(f) &
                           //' beta='//real_str(betas(ib)))
                if (allocated(error)) return
                if (betas(ib) < -huge(f)) cycle
                call stability_wall(f, betas(ib), lo, stat)
                call s1_s2_boundary(f, betas(ib), x, stat)
                ref = ref_bisect_eta(f, betas(ib), 3, lo)
                call check(error, x, ref, rtol=rtol_ref, message='S1/S2 f='//real_str(f) &
                           //' beta='//real_str(betas(ib)))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_boundaries_ref

    !> Bisection in eta on the sign of a reference quantity: 1 psi(1/2) - 1, 2 psi(1) - 1,
    !> 3 psi'(1) (on (lo, 1)), 4 A (the wall). Each is positive at the small-eta end.
    function ref_bisect_eta(f, beta, what, lo_in) result(eta)
        real(dp), intent(in) :: f, beta, lo_in
        integer, intent(in) :: what
        real(dp) :: eta, lo, hi, v
        integer :: it
        type(ref_t) :: r
        type(ref_result_t) :: rr
        lo = lo_in
        hi = 1.0_dp
        if (what == 3) then
            ! the S1 strip of a near-rectangular pulse can hug eta = 1: start where psi'(1) < 0
            hi = 1.0_dp - 1.0e-12_dp
        end if
        do it = 1, 64
            eta = 0.5_dp * (lo + hi)
            if (.not. (eta > lo .and. eta < hi)) exit
            call ref_setup(r, f, eta, beta)
            call ref_state(r, rr)
            select case (what)
            case (1)
                v = rr%p_half - 1.0_dp
            case (2)
                v = rr%p_one - 1.0_dp
            case (3)
                v = rr%q_one
            case default
                v = rr%a
            end select
            if (v > 0.0_dp) then
                lo = eta
            else
                hi = eta
            end if
        end do
        eta = 0.5_dp * (lo + hi)
    end function ref_bisect_eta

    ! ------------------------------------------------------------------------------
    ! The reference: pulse of Eq. 2.1, uplift by bisection, Duhamel integral
    ! psi(tau) = f int sinh(f (tau - s)) g(s) ds, psi'/f = f int cosh(f (tau - s)) g(s) ds
    ! (doc/rocking.md section 2) by adaptive 20-point Gauss-Legendre quadrature
    ! ------------------------------------------------------------------------------

    !> s(tau) = a_g/A_g of Eq. 2.1 (half cycle), evaluated as expm1(2 beta u)/expm1(beta),
    !> u = min(tau, 1 - tau) (scaled by e^-beta for large beta).
    pure function pulse_s(tau, beta) result(s)
        real(dp), intent(in) :: tau, beta
        real(dp) :: s, u
        s = 0.0_dp
        if (tau <= 0.0_dp .or. tau >= 1.0_dp) return
        if (beta < -huge(beta)) then
            s = 1.0_dp
            return
        end if
        u = min(tau, 1.0_dp - tau)
        if (.not. abs(beta) > 0.0_dp) then
            s = 2.0_dp * u
        else if (beta > 300.0_dp) then
            s = exp(2.0_dp * beta * u - beta) * (expm1_t(-2.0_dp * beta * u) / expm1_t(-beta))
        else
            s = expm1_t(2.0_dp * beta * u) / expm1_t(beta)
        end if
    end function pulse_s

    !> e^x - 1 for the reference (series near 0, independent of the library's).
    elemental function expm1_t(x) result(y)
        real(dp), intent(in) :: x
        real(dp) :: y, term
        integer :: k
        if (abs(x) < 0.5_dp) then
            term = x
            y = x
            do k = 2, 30
                term = term * x / k
                y = y + term
                if (abs(term) < 1.0e-18_dp * abs(y)) exit
            end do
        else
            y = exp(x) - 1.0_dp
        end if
    end function expm1_t

    subroutine ref_setup(r, f, eta, beta)
        type(ref_t), intent(out) :: r
        real(dp), intent(in) :: f, eta, beta
        real(dp) :: lo, hi, mid
        integer :: it
        r%f = f
        r%eta = eta
        r%beta = beta
        r%rocks = eta < 1.0_dp .and. .not. beta > huge(beta)
        r%tup = 0.0_dp
        if (.not. r%rocks .or. beta < -huge(beta)) return
        ! uplift: s(tau) = eta on the rising branch, by bisection
        lo = 0.0_dp
        hi = 0.5_dp
        do it = 1, 200
            mid = 0.5_dp * (lo + hi)
            if (.not. (mid > lo .and. mid < hi)) exit
            if (pulse_s(mid, beta) < eta) then
                lo = mid
            else
                hi = mid
            end if
        end do
        r%tup = 0.5_dp * (lo + hi)
    end subroutine ref_setup

    !> psi, psi'/f and the absolute integral at tau.
    subroutine ref_eval(r, tau, psi, q, absint)
        type(ref_t), intent(in) :: r
        real(dp), intent(in) :: tau
        real(dp), intent(out) :: psi, q, absint
        real(dp) :: breaks(3), a, b, s, c, ab
        integer :: i
        psi = 0.0_dp
        q = 0.0_dp
        absint = 0.0_dp
        if (.not. r%rocks .or. tau <= r%tup) return
        breaks = [0.5_dp, 1.0_dp, tau]
        a = r%tup
        do i = 1, 3
            b = min(breaks(i), tau)
            if (b > a) then
                call gl_integrate(r, a, b, tau, s, c, ab)
                psi = psi + s
                q = q + c
                absint = absint + ab
                a = b
            end if
        end do
        psi = r%f * psi
        q = r%f * q
        absint = r%f * absint
    end subroutine ref_eval

    !> g(s) = s(tau)/eta - 1 (after uplift).
    pure function ref_g(r, sig) result(g)
        type(ref_t), intent(in) :: r
        real(dp), intent(in) :: sig
        real(dp) :: g
        g = pulse_s(sig, r%beta) / r%eta - 1.0_dp
    end function ref_g

    subroutine gl_integrate(r, a, b, tau, s, c, ab)
        type(ref_t), intent(in) :: r
        real(dp), intent(in) :: a, b, tau
        real(dp), intent(out) :: s, c, ab
        real(dp) :: ws, wc, wa
        if (.not. gl_ready) call gl_init()
        call gl_panel(r, a, b, tau, ws, wc, wa)
        call gl_adapt(r, a, b, tau, ws, wc, s, c, ab, 0)
    end subroutine gl_integrate

    recursive subroutine gl_adapt(r, a, b, tau, ws, wc, s, c, ab, depth)
        type(ref_t), intent(in) :: r
        real(dp), intent(in) :: a, b, tau, ws, wc
        real(dp), intent(out) :: s, c, ab
        integer, intent(in) :: depth
        real(dp) :: m, s1, c1, a1, s2, c2, a2, t1, t2, u1, u2, b1, b2
        m = 0.5_dp * (a + b)
        call gl_panel(r, a, m, tau, s1, c1, a1)
        call gl_panel(r, m, b, tau, s2, c2, a2)
        ! the halves are far more accurate than the whole panel: accept them once the two
        ! agree to 1e-13 of the scale of the round-off (a tighter test would chase it)
        if (abs(s1 + s2 - ws) + abs(c1 + c2 - wc) <= 1.0e-13_dp * (a1 + a2) .or. depth >= 14) then
            s = s1 + s2
            c = c1 + c2
            ab = a1 + a2
        else
            call gl_adapt(r, a, m, tau, s1, c1, t1, u1, b1, depth + 1)
            call gl_adapt(r, m, b, tau, s2, c2, t2, u2, b2, depth + 1)
            s = t1 + t2
            c = u1 + u2
            ab = b1 + b2
        end if
    end subroutine gl_adapt

    !> One 20-point panel of int sinh(f(tau - s)) g(s), int cosh(f(tau - s)) g(s) and
    !> int cosh(f(tau - s)) (s/eta + 1) over [a, b]: the scale of the round-off, both of the
    !> cancellation in g = s/eta - 1 near uplift and of positive against negative g.
    subroutine gl_panel(r, a, b, tau, s, c, ab)
        type(ref_t), intent(in) :: r
        real(dp), intent(in) :: a, b, tau
        real(dp), intent(out) :: s, c, ab
        real(dp) :: h, m, x, g, e, ep, em
        integer :: i
        h = 0.5_dp * (b - a)
        m = 0.5_dp * (a + b)
        s = 0.0_dp
        c = 0.0_dp
        ab = 0.0_dp
        do i = 1, ngl
            x = m + h * gl_x(i)
            g = ref_g(r, x)
            e = r%f * (tau - x)
            ep = exp(e)
            em = 1.0_dp / ep
            if (abs(e) < 0.1_dp) then
                s = s + gl_w(i) * g * sinh(e)
            else
                s = s + gl_w(i) * g * 0.5_dp * (ep - em)
            end if
            c = c + gl_w(i) * g * 0.5_dp * (ep + em)
            ab = ab + gl_w(i) * (pulse_s(x, r%beta) / r%eta + 1.0_dp) * 0.5_dp * (ep + em)
        end do
        s = h * s
        c = h * c
        ab = h * ab
    end subroutine gl_panel

    !> Gauss-Legendre nodes and weights (Newton on P_n).
    subroutine gl_init()
        integer :: i, k, it
        real(dp) :: z, z1, p1, p2, p3, pp
        do i = 1, ngl / 2   ! ngl is even
            z = cos(pi * (i - 0.25_dp) / (ngl + 0.5_dp))
            pp = 1.0_dp
            do it = 1, 100
                p1 = 1.0_dp
                p2 = 0.0_dp
                do k = 1, ngl
                    p3 = p2
                    p2 = p1
                    p1 = ((2 * k - 1) * z * p2 - (k - 1) * p3) / k
                end do
                pp = ngl * (z * p1 - p2) / (z * z - 1.0_dp)
                z1 = z
                z = z1 - p1 / pp
                if (abs(z - z1) < 1.0e-16_dp) exit
            end do
            gl_x(i) = -z
            gl_x(ngl + 1 - i) = z
            gl_w(i) = 2.0_dp / ((1.0_dp - z * z) * pp * pp)
            gl_w(ngl + 1 - i) = gl_w(i)
        end do
        gl_ready = .true.
    end subroutine gl_init

    !> Reference state at 1/2 and 1, A and the region (doc/rocking.md section 3).
    subroutine ref_state(r, rr)
        type(ref_t), intent(in) :: r
        type(ref_result_t), intent(out) :: rr
        real(dp) :: ab
        rr%region = ROCK_NONE
        if (.not. r%rocks) return
        call ref_eval(r, 0.5_dp, rr%p_half, rr%q_half, ab)
        call ref_eval(r, 1.0_dp, rr%p_one, rr%q_one, ab)
        rr%a = 0.5_dp * ((rr%p_one - 1.0_dp) + rr%q_one)
        if (rr%p_half >= 1.0_dp) then
            rr%region = ROCK_O1
        else if (rr%p_one >= 1.0_dp) then
            rr%region = ROCK_O2
        else if (rr%a > 0.0_dp) then
            rr%region = ROCK_O3
        else if (rr%q_one <= 0.0_dp) then
            rr%region = ROCK_S1
        else
            rr%region = ROCK_S2
        end if
    end subroutine ref_state

    !> Reference tau_c, tau_m, psi_max, tau_i: roots of the integrated psi - 1, psi', psi.
    subroutine ref_derive(r, rr)
        type(ref_t), intent(in) :: r
        type(ref_result_t), intent(out) :: rr
        real(dp) :: t, psi, q, ab, lo
        integer :: k
        call ref_state(r, rr)
        select case (rr%region)
        case (ROCK_O1)
            rr%tau_c = ref_root(r, 1, 1.0_dp, r%tup, 0.5_dp)
        case (ROCK_O2)
            rr%tau_c = ref_root(r, 1, 1.0_dp, 0.5_dp, 1.0_dp)
        case (ROCK_O3)
            lo = 1.0_dp
            t = 1.0_dp + 1.0_dp / r%f
            do k = 1, 60
                call ref_eval(r, t, psi, q, ab)
                if (psi > 1.0_dp) exit
                lo = t
                t = 1.0_dp + 1.5_dp * (t - 1.0_dp)
            end do
            rr%tau_c = ref_root(r, 1, 1.0_dp, lo, t)
        case (ROCK_S1, ROCK_S2)
            if (rr%region == ROCK_S1) then
                rr%tau_m = ref_root(r, 2, 0.0_dp, 1.0_dp - r%tup, 1.0_dp)
            else
                lo = 1.0_dp
                t = 1.0_dp + 1.0_dp / r%f
                do k = 1, 60
                    call ref_eval(r, t, psi, q, ab)
                    if (q < 0.0_dp) exit
                    lo = t
                    t = 1.0_dp + 1.5_dp * (t - 1.0_dp)
                end do
                rr%tau_m = ref_root(r, 2, 0.0_dp, lo, t)
            end if
            call ref_eval(r, rr%tau_m, rr%psi_max, q, ab)
            if (rr%p_one <= 0.0_dp) then
                rr%tau_i = ref_root(r, 1, 0.0_dp, rr%tau_m, 1.0_dp)
            else
                lo = max(1.0_dp, rr%tau_m)
                t = lo + 1.0_dp / r%f
                do k = 1, 60
                    call ref_eval(r, t, psi, q, ab)
                    if (psi < 0.0_dp) exit
                    lo = t
                    t = lo + 1.0_dp / r%f
                end do
                rr%tau_i = ref_root(r, 1, 0.0_dp, lo, t)
            end if
        end select
    end subroutine ref_derive

    !> Root on [a, b] (a sign change) of psi - level (kind 1, slope f psi'/f) or of psi'/f
    !> (kind 2, slope f (psi + g)): Newton steps kept in the bracket, else bisection.
    function ref_root(r, kind, level, a, b) result(x)
        type(ref_t), intent(in) :: r
        integer, intent(in) :: kind
        real(dp), intent(in) :: level, a, b
        real(dp) :: x, xl, xh, fa, fx, dfx, dx, dxold, psi, q, ab
        integer :: it
        call value(a, fa, dfx)
        if (fa < 0.0_dp) then
            xl = a
            xh = b
        else
            xl = b
            xh = a
        end if
        x = 0.5_dp * (a + b)
        dxold = abs(b - a)
        dx = dxold
        call value(x, fx, dfx)
        do it = 1, 200
            if (((x - xh) * dfx - fx) * ((x - xl) * dfx - fx) > 0.0_dp &
                .or. abs(2.0_dp * fx) > abs(dxold * dfx)) then
                dxold = dx
                dx = 0.5_dp * (xh - xl)
                x = xl + dx
            else
                dxold = dx
                dx = fx / dfx
                x = x - dx
            end if
            if (abs(dx) <= 2.0_dp * epsilon(x) * abs(x)) exit
            call value(x, fx, dfx)
            if (fx < 0.0_dp) then
                xl = x
            else
                xh = x
            end if
        end do
    contains
        subroutine value(t, v, dv)
            real(dp), intent(in) :: t
            real(dp), intent(out) :: v, dv
            call ref_eval(r, t, psi, q, ab)
            if (kind == 1) then
                v = psi - level
                dv = r%f * q
            else
                v = q
                if (t > 1.0_dp) then
                    dv = r%f * (psi - 1.0_dp)
                else
                    dv = r%f * (psi + ref_g(r, t))
                end if
            end if
        end subroutine value
    end function ref_root

end module test_rocking_closed
