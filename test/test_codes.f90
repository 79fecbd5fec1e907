!> EN 1998 code checks (seispulse_codes) against independent computations: the published
!> Mononobe-Okabe check (xc / eurocodeapplied.com: theta = 0.2110933332227465 rad,
!> K = 0.4856177257638489, K_pd = 2.6); Coulomb/Rankine closed forms at kh = kv = 0;
!> the rotation identity of Mononobe-Okabe (Arango); a brute-force planar-wedge search
!> written here (golden section over the failure-plane angle) for active and passive
!> coefficients on inclined walls with sloping backfill and wall friction, and the
!> transcribed E.4 numerator that it rejects; every NO_SOLUTION branch; thrusts of the
!> three water cases from hand formulas; Westergaard's resultant 7/12 kh gamma_w H^2 at
!> 0.4 H by Gauss quadrature of the returned pressures; the rigid-wall rules; the EN 1998-1
!> tables transcribed here, each spectral branch at and between the corner periods,
!> continuity at TB, TC, TD, eta, the design floor; the Greek National Annex zones
!> Z1..Z3 = 0.16/0.24/0.36 g (the 2003 map the Greek NA adopted: 0.16-0.36 g in [PRDA24],
!> 0.24 g and the names from press reports); bad input (messages name the parameter).
module test_codes
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_NO_SOLUTION
    use seispulse_codes, only: ec8_seismic_coefficients, ec8_vertical_ratio, ec8_r_factor, &
                               mononobe_okabe, ec8_thrust_t, ec8_thrust, westergaard_pressure, &
                               ec8_rigid_thrust, seed_whitman_increment, wood_thrust, &
                               ec8_ground_parameters, ec8_damping_correction, ec8_check_damping, &
                               ec8_elastic_spectrum, ec8_design_spectrum, EC8_WALL_GRAVITY_300, &
                               EC8_WALL_GRAVITY_200, EC8_WALL_RESTRAINED, WATER_DRY, &
                               WATER_IMPERVIOUS, WATER_PERMEABLE, EC8_SPECTRUM_TYPE_1, &
                               EC8_SPECTRUM_TYPE_2, EC8_GROUND_A, EC8_GROUND_B, EC8_GROUND_C, &
                               EC8_GROUND_D, EC8_GROUND_E, EC8_ANNEX_RECOMMENDED, EC8_ANNEX_GR, &
                               ec8_reference_pga, ec8_design_ag
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_codes

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: rad = pi/180.0_dp

contains

    subroutine collect_codes(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('kh = alpha S/r, kv 0.5/0.33 kh, Table 7.1 r, bad input', &
                              test_coefficients), &
                 new_unittest('M-O published check: theta, K (1e-12), K_pd = 2.6', &
                              test_mo_published), &
                 new_unittest('M-O at kh = kv = 0: Coulomb 1/3, 3; Rankine sloping backfill', &
                              test_mo_coulomb), &
                 new_unittest('M-O = rotated Coulomb (Arango), kv sign, gamma_phi', &
                              test_mo_rotation), &
                 new_unittest('M-O = planar-wedge search; transcribed E.4 numerator rejected', &
                              test_mo_wedge), &
                 new_unittest('M-O no solution: E.3 branch, k_e3, each passive/active limit', &
                              test_mo_no_solution), &
                 new_unittest('M-O bad input: each parameter named', test_mo_bad_input), &
                 new_unittest('thrust, dry: E.1 with the published K, H/3, H/2, moment', &
                              test_thrust_dry), &
                 new_unittest('thrust, impervious and permeable: theta, gamma*, E_ws, E_wd', &
                              test_thrust_water), &
                 new_unittest('thrust: bad input and no-solution messages', test_thrust_bad), &
                 new_unittest('Westergaard: 7/8 kh gamma_w sqrt(h z); resultant 7/12 at 0.4 H', &
                              test_westergaard), &
                 new_unittest('rigid wall, Seed-Whitman, Wood: values, NaN without stat', &
                              test_rigid_rules), &
                 new_unittest('EN 1998-1 Tables 3.2/3.3 and bad type/ground', &
                              test_ground_parameters), &
                 new_unittest('eta = sqrt(10/(5 + xi)) >= 0.55', test_damping), &
                 new_unittest('elastic spectrum: branches, corners, continuity, eta', &
                              test_elastic_spectrum), &
                 new_unittest('design spectrum: branches, plateau 2.5/q, floor beta ag', &
                              test_design_spectrum), &
                 new_unittest('spectra: bad input', test_spectra_bad), &
                 new_unittest('Greek NA zones Z1..Z3 = 0.16/0.24/0.36 g; no zones otherwise', &
                              test_reference_pga), &
                 new_unittest('ec8_design_ag: one of ag and zone, importance 1 with ag', &
                              test_design_ag)]
    end subroutine collect_codes

    ! ------------------------------------------------------------------ helpers

    !> errmsg must start with `prefix` and stat must be `code`.
    subroutine check_message(error, stat, code, errmsg, prefix)
        type(test_error), allocatable, intent(inout) :: error
        integer, intent(in) :: stat, code
        character(len=*), intent(in) :: errmsg, prefix
        call check(error, stat, code, 'status for '//prefix)
        if (allocated(error)) return
        call check(error, index(errmsg, prefix) == 1, 'message "'//trim(errmsg)// &
                   '" should start with "'//prefix//'"')
    end subroutine check_message

    !> x is exactly zero (not NaN); an ordered test, free of -Wcompare-reals.
    logical function zero(x)
        real(dp), intent(in) :: x
        zero = abs(x) <= 0.0_dp
    end function zero

    real(dp) function nan()
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
    end function nan

    !> E.2 transcribed here (radians, design angles).
    real(dp) function k_e2(phi, delta, psi, beta, theta)
        real(dp), intent(in) :: phi, delta, psi, beta, theta
        k_e2 = sin(psi + phi - theta)**2/(cos(theta)*sin(psi)**2*sin(psi - theta - delta)* &
               (1.0_dp + sqrt(sin(phi + delta)*sin(phi - beta - theta)/ &
                              (sin(psi - theta - delta)*sin(psi + beta))))**2)
    end function k_e2

    !> Thrust / (gamma H^2) of a planar wedge whose failure plane makes the angle rho with
    !> the horizontal. Wedge frame: backfill on the +x side, heel at the origin, back face
    !> at a = 180 - psi from +x (psi of EN measured on the other side), top at height 1.
    !> Forces on the wedge: wall reaction P at delta to the wall normal (friction up the
    !> wall when active, down when passive), soil reaction R at phi to the plane normal
    !> (resisting the sliding), weight W (1 - kv) down and kh W towards the wall (active)
    !> or away from it (passive). valid = P > 0 and R > 0.
    subroutine wedge_force(rho, a, beta, phi, delta, kh, kv, passive, p, valid)
        real(dp), intent(in) :: rho, a, beta, phi, delta, kh, kv
        logical, intent(in) :: passive
        real(dp), intent(out) :: p
        logical, intent(out) :: valid
        real(dp) :: w, sg, t(2), n(2), pw(2), qs(2), f(2), u(2), m(2), pq, r
        w = 0.5_dp*sin(a - beta)*sin(a - rho)/(sin(a)**2*sin(rho - beta))
        sg = 1.0_dp
        if (passive) sg = -1.0_dp
        t = [cos(a), sin(a)]
        n = [t(2), -t(1)]
        pw = cos(delta)*n + sg*sin(delta)*t
        u = [cos(rho), sin(rho)]
        m = [-sin(rho), cos(rho)]
        qs = cos(phi)*m + sg*sin(phi)*u
        if (passive) then
            f = [kh, -(1.0_dp - kv)]*w
        else
            f = [-kh, -(1.0_dp - kv)]*w
        end if
        pq = cross(pw, qs)
        p = -cross(f, qs)/pq
        r = -cross(pw, f)/pq
        valid = p > 0.0_dp .and. r > 0.0_dp
    end subroutine wedge_force

    pure real(dp) function cross(x, y)
        real(dp), intent(in) :: x(2), y(2)
        cross = x(1)*y(2) - x(2)*y(1)
    end function cross

    !> K of the wedge search: max (active) or min (passive) of P over rho in (beta, a),
    !> K = 2 P/(1 - kv). A coarse scan, then golden section around the best point.
    !> found = .false. when the extremum is not interior.
    subroutine wedge_k(phi_deg, delta_deg, psi_deg, beta_deg, kh, kv, passive, k, found)
        real(dp), intent(in) :: phi_deg, delta_deg, psi_deg, beta_deg, kh, kv
        logical, intent(in) :: passive
        real(dp), intent(out) :: k
        logical, intent(out) :: found
        integer, parameter :: n = 2000
        real(dp), parameter :: g = (sqrt(5.0_dp) - 1.0_dp)/2.0_dp
        real(dp) :: a, beta, phi, delta, lo, hi, h, rho, p, best, sg, x1, x2, f1, f2
        integer :: i, ibest, it
        logical :: valid
        a = (180.0_dp - psi_deg)*rad
        beta = beta_deg*rad
        phi = phi_deg*rad
        delta = delta_deg*rad
        sg = -1.0_dp                 ! minimise sg P: maximise P (active)
        if (passive) sg = 1.0_dp
        h = (a - beta)/real(n + 1, dp)
        ibest = 0
        best = huge(1.0_dp)
        do i = 1, n
            rho = beta + i*h
            call wedge_force(rho, a, beta, phi, delta, kh, kv, passive, p, valid)
            if (valid .and. sg*p < best) then
                best = sg*p
                ibest = i
            end if
        end do
        found = ibest > 1 .and. ibest < n
        k = 0.0_dp
        if (.not. found) return
        lo = beta + (ibest - 1)*h
        hi = beta + (ibest + 1)*h
        x1 = hi - g*(hi - lo)
        x2 = lo + g*(hi - lo)
        call wedge_force(x1, a, beta, phi, delta, kh, kv, passive, f1, valid)
        call wedge_force(x2, a, beta, phi, delta, kh, kv, passive, f2, valid)
        do it = 1, 200
            if (hi - lo < 1.0e-13_dp) exit
            if (sg*f1 < sg*f2) then
                hi = x2
                x2 = x1
                f2 = f1
                x1 = hi - g*(hi - lo)
                call wedge_force(x1, a, beta, phi, delta, kh, kv, passive, f1, valid)
            else
                lo = x1
                x1 = x2
                f1 = f2
                x2 = lo + g*(hi - lo)
                call wedge_force(x2, a, beta, phi, delta, kh, kv, passive, f2, valid)
            end if
        end do
        k = 2.0_dp*(0.5_dp*(f1 + f2))/(1.0_dp - kv)
    end subroutine wedge_k

    ! ------------------------------------------------------------------ §7.3.2.2

    subroutine test_coefficients(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: kh, kv, r
        integer :: stat
        character(len=256) :: msg
        call ec8_seismic_coefficients(0.24_dp, 1.2_dp, 2.0_dp, 0.9_dp, kh, kv, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, kh, 0.144_dp, rtol=1.0e-15_dp, message='kh = 0.24*1.2/2')
        if (allocated(error)) return
        call check(error, kv, 0.072_dp, rtol=1.0e-15_dp, message='kv = kh/2 (avg/ag > 0.6)')
        if (allocated(error)) return
        call ec8_seismic_coefficients(0.24_dp, 1.2_dp, 2.0_dp, 0.45_dp, kh, kv, stat, msg)
        call check(error, kv, 0.33_dp*0.144_dp, rtol=1.0e-15_dp, message='kv = 0.33 kh')
        if (allocated(error)) return
        ! (7.2) needs avg/ag > 0.6 strictly
        call ec8_seismic_coefficients(0.3_dp, 1.0_dp, 1.0_dp, 0.6_dp, kh, kv, stat, msg)
        call check(error, kv, 0.099_dp, rtol=1.0e-14_dp, message='avg/ag = 0.6 -> 0.33 kh')
        if (allocated(error)) return
        call ec8_seismic_coefficients(0.3_dp, 1.0_dp, 1.0_dp, 0.6000001_dp, kh, kv, stat, msg)
        call check(error, kv, 0.15_dp, rtol=1.0e-14_dp, message='avg/ag > 0.6 -> 0.5 kh')
        if (allocated(error)) return
        call ec8_seismic_coefficients(0.0_dp, 1.0_dp, 1.5_dp, ec8_vertical_ratio(1), kh, kv, &
                                      stat, msg)
        call check(error, stat == SEISPULSE_SUCCESS .and. zero(kh) .and. zero(kv), &
                   'alpha = 0 gives zero coefficients')
        if (allocated(error)) return
        call check(error, ec8_vertical_ratio(EC8_SPECTRUM_TYPE_1), 0.9_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, ec8_vertical_ratio(EC8_SPECTRUM_TYPE_2), 0.45_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, ieee_is_nan(ec8_vertical_ratio(3)), 'type 3 -> NaN')
        if (allocated(error)) return
        call ec8_r_factor(EC8_WALL_GRAVITY_300, r, stat, msg)
        call check(error, r, 2.0_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call ec8_r_factor(EC8_WALL_GRAVITY_200, r, stat, msg)
        call check(error, r, 1.5_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call ec8_r_factor(EC8_WALL_RESTRAINED, r, stat, msg)
        call check(error, r, 1.0_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call ec8_r_factor(4, r, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'wall_type = 4')
        if (allocated(error)) return
        call ec8_seismic_coefficients(-0.1_dp, 1.0_dp, 1.0_dp, 0.9_dp, kh, kv, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'alpha = -0.1')
        if (allocated(error)) return
        call ec8_seismic_coefficients(nan(), 1.0_dp, 1.0_dp, 0.9_dp, kh, kv, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'alpha = NaN')
        if (allocated(error)) return
        call ec8_seismic_coefficients(0.1_dp, 0.0_dp, 1.0_dp, 0.9_dp, kh, kv, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 's = 0')
        if (allocated(error)) return
        call ec8_seismic_coefficients(0.1_dp, 1.0_dp, 0.9_dp, 0.9_dp, kh, kv, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'r = 0.9')
        if (allocated(error)) return
        call ec8_seismic_coefficients(0.1_dp, 1.0_dp, 2.5_dp, 0.9_dp, kh, kv, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'r = 2.5')
        if (allocated(error)) return
        call ec8_seismic_coefficients(0.1_dp, 1.0_dp, 1.0_dp, ec8_vertical_ratio(7), kh, kv, &
                                      stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'vertical_ratio = NaN')
    end subroutine test_coefficients

    ! ------------------------------------------------------------------ Mononobe-Okabe

    subroutine test_mo_published(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, theta, kpd, ke3
        integer :: stat
        character(len=256) :: msg
        call mononobe_okabe(30.0_dp, 0.24_dp, -0.12_dp, 0.0_dp, 90.0_dp, 0.0_dp, .false., &
                            1.0_dp, k, theta, stat, msg, ke3)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, theta, 0.2110933332227465_dp, rtol=1.0e-12_dp, message='theta')
        if (allocated(error)) return
        call check(error, k, 0.4856177257638489_dp, rtol=1.0e-12_dp, message='K_ad')
        if (allocated(error)) return
        call check(error, ke3, 0.0_dp, atol=0.0_dp, message='k_e3 unset below the limit')
        if (allocated(error)) return
        call mononobe_okabe(30.0_dp, 0.24_dp, -0.12_dp, 0.0_dp, 90.0_dp, 0.0_dp, .true., &
                            1.0_dp, kpd, theta, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, kpd, 2.6_dp, rtol=1.0e-3_dp, message='K_pd (xc: 2.6 +- 0.1 %)')
        if (allocated(error)) return
        ! passive at psi = 90, delta = beta = 0: cos^2(phi - theta)/(cos^2 theta
        ! [1 - sqrt(sin phi sin(phi - theta)/cos theta)]^2), written here
        call check(error, kpd, cos(30*rad - theta)**2/(cos(theta)**2*(1.0_dp - &
                   sqrt(sin(30*rad)*sin(30*rad - theta)/cos(theta)))**2), rtol=1.0e-13_dp, &
                   message='K_pd closed form')
    end subroutine test_mo_published

    subroutine test_mo_coulomb(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, theta, cb, cf, r, kc, phi, psi, beta, delta
        integer :: stat, i
        character(len=256) :: msg
        real(dp), parameter :: cases(4, 4) = reshape([ &   ! phi, delta, psi, beta
            30.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 35.0_dp, 20.0_dp, 80.0_dp, 10.0_dp, &
            28.0_dp, 15.0_dp, 100.0_dp, -10.0_dp, 40.0_dp, 26.0_dp, 95.0_dp, 15.0_dp], [4, 4])
        call mononobe_okabe(30.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, .false., 1.0_dp, &
                            k, theta, stat, msg)
        call check(error, k, 1.0_dp/3.0_dp, rtol=1.0e-14_dp, message='Rankine active 1/3')
        if (allocated(error)) return
        call check(error, theta, 0.0_dp, atol=0.0_dp, message='theta = 0')
        if (allocated(error)) return
        call mononobe_okabe(30.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, .true., 1.0_dp, &
                            k, theta, stat, msg)
        call check(error, k, 3.0_dp, rtol=1.0e-14_dp, message='Rankine passive 3')
        if (allocated(error)) return
        ! Rankine, backfill at beta = 20: active thrust parallel to the slope (delta = beta);
        ! passive with the ground falling at 20 deg in front (delta = 20, beta = -20)
        cb = cos(20*rad)
        cf = cos(30*rad)
        r = sqrt(cb**2 - cf**2)
        call mononobe_okabe(30.0_dp, 0.0_dp, 0.0_dp, 20.0_dp, 90.0_dp, 20.0_dp, .false., 1.0_dp, &
                            k, theta, stat, msg)
        call check(error, k, cb*(cb - r)/(cb + r), rtol=1.0e-13_dp, message='Rankine sloping')
        if (allocated(error)) return
        call mononobe_okabe(30.0_dp, 0.0_dp, 0.0_dp, 20.0_dp, 90.0_dp, -20.0_dp, .true., 1.0_dp, &
                            k, theta, stat, msg)
        call check(error, k, cb*(cb + r)/(cb - r), rtol=1.0e-13_dp, &
                   message='Rankine passive sloping')
        if (allocated(error)) return
        ! Coulomb (Das, Principles of Foundation Engineering, with the back face at
        ! alpha = 90 - psi from the vertical): active
        ! cos^2(phi - alpha)/(cos^2 alpha cos(delta + alpha) [1 + sqrt(sin(delta + phi)
        ! sin(phi - beta)/(cos(delta + alpha) cos(alpha - beta)))]^2)
        do i = 1, 4
            phi = cases(1, i)*rad
            delta = cases(2, i)*rad
            psi = (90.0_dp - cases(3, i))*rad     ! alpha
            beta = cases(4, i)*rad
            kc = cos(phi - psi)**2/(cos(psi)**2*cos(delta + psi)*(1.0_dp + sqrt(sin(delta + &
                 phi)*sin(phi - beta)/(cos(delta + psi)*cos(psi - beta))))**2)
            call mononobe_okabe(cases(1, i), 0.0_dp, 0.0_dp, cases(2, i), cases(3, i), &
                                cases(4, i), .false., 1.0_dp, k, theta, stat, msg)
            call check(error, k, kc, rtol=1.0e-13_dp, message='Coulomb active, case')
            if (allocated(error)) return
            ! passive: cos^2(phi + alpha)/(cos^2 alpha cos(delta - alpha) [1 - sqrt(
            ! sin(phi + delta) sin(phi + beta)/(cos(delta - alpha) cos(beta - alpha)))]^2)
            kc = cos(phi + psi)**2/(cos(psi)**2*cos(delta - psi)*(1.0_dp - sqrt(sin(phi + &
                 delta)*sin(phi + beta)/(cos(delta - psi)*cos(beta - psi))))**2)
            call mononobe_okabe(cases(1, i), 0.0_dp, 0.0_dp, cases(2, i), cases(3, i), &
                                cases(4, i), .true., 1.0_dp, k, theta, stat, msg)
            call check(error, k, kc, rtol=1.0e-13_dp, message='Coulomb passive, case')
            if (allocated(error)) return
        end do
    end subroutine test_mo_coulomb

    subroutine test_mo_rotation(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, theta, k0, t0, thd, phid
        integer :: stat
        character(len=256) :: msg
        ! active: K(psi, beta; theta) = K_C(psi - theta, beta + theta) sin^2(psi - theta)/
        ! (cos theta sin^2 psi), K_C the static Coulomb value (Arango's rotation)
        call mononobe_okabe(34.0_dp, 0.2_dp, 0.1_dp, 17.0_dp, 84.0_dp, 8.0_dp, .false., &
                            1.0_dp, k, theta, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, theta, atan(0.2_dp/0.9_dp), rtol=1.0e-15_dp, message='theta')
        if (allocated(error)) return
        thd = theta/rad
        call mononobe_okabe(34.0_dp, 0.0_dp, 0.0_dp, 17.0_dp, 84.0_dp - thd, 8.0_dp + thd, &
                            .false., 1.0_dp, k0, t0, stat, msg)
        call check(error, k, k0*sin((84.0_dp - thd)*rad)**2/(cos(theta)*sin(84*rad)**2), &
                   rtol=1.0e-12_dp, message='active rotation')
        if (allocated(error)) return
        ! passive: K(psi, beta; theta) = K_C(psi + theta, beta - theta) sin^2(psi + theta)/
        ! (cos theta sin^2 psi)
        call mononobe_okabe(34.0_dp, 0.2_dp, 0.1_dp, 17.0_dp, 84.0_dp, 8.0_dp, .true., &
                            1.0_dp, k, theta, stat, msg)
        call mononobe_okabe(34.0_dp, 0.0_dp, 0.0_dp, 17.0_dp, 84.0_dp + thd, 8.0_dp - thd, &
                            .true., 1.0_dp, k0, t0, stat, msg)
        call check(error, k, k0*sin((84.0_dp + thd)*rad)**2/(cos(theta)*sin(84*rad)**2), &
                   rtol=1.0e-12_dp, message='passive rotation')
        if (allocated(error)) return
        ! the other sign of kv (independent values: theta = 0.2662520, K = 0.5407058 for kv = +0.12)
        call mononobe_okabe(30.0_dp, 0.24_dp, 0.12_dp, 0.0_dp, 90.0_dp, 0.0_dp, .false., &
                            1.0_dp, k, theta, stat, msg)
        call check(error, theta, atan(0.24_dp/0.88_dp), rtol=1.0e-15_dp, message='theta, kv > 0')
        if (allocated(error)) return
        call check(error, k, k_e2(30*rad, 0.0_dp, 90*rad, 0.0_dp, theta), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, k, 0.5407058_dp, rtol=1.0e-6_dp, message='independent value, kv = +0.12')
        if (allocated(error)) return
        ! gamma_phi = 1.25: the same as the characteristic call with phi_d, delta_d
        phid = atan(tan(32*rad)/1.25_dp)/rad
        call mononobe_okabe(32.0_dp, 0.15_dp, -0.05_dp, 20.0_dp, 95.0_dp, 5.0_dp, .false., &
                            1.25_dp, k, theta, stat, msg)
        call mononobe_okabe(phid, 0.15_dp, -0.05_dp, atan(tan(20*rad)/1.25_dp)/rad, 95.0_dp, &
                            5.0_dp, .false., 1.0_dp, k0, t0, stat, msg)
        call check(error, k, k0, rtol=1.0e-13_dp, message='gamma_phi = 1.25')
        if (allocated(error)) return
        call check(error, k > 0.4_dp, 'gamma_phi raises K_a')
    end subroutine test_mo_rotation

    subroutine test_mo_wedge(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, theta, kw, e4
        integer :: stat, i
        logical :: found, passive
        character(len=256) :: msg
        ! phi, delta, psi, beta, kh, kv
        real(dp), parameter :: cases(6, 5) = reshape([ &
            30.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 0.24_dp, -0.12_dp, &
            30.0_dp, 20.0_dp, 80.0_dp, 10.0_dp, 0.2_dp, -0.1_dp, &
            35.0_dp, 15.0_dp, 100.0_dp, -10.0_dp, 0.3_dp, 0.15_dp, &
            25.0_dp, 25.0_dp, 85.0_dp, 5.0_dp, 0.1_dp, 0.05_dp, &
            40.0_dp, 10.0_dp, 110.0_dp, 12.0_dp, 0.25_dp, -0.2_dp], [6, 5])
        real(dp), parameter :: flat_backs(3) = [30.0_dp, 39.9_dp, 40.0_dp]   ! psi, deg
        do i = 1, 10
            passive = i > 5
            associate (c => cases(:, mod(i - 1, 5) + 1))
                call mononobe_okabe(c(1), c(5), c(6), c(2), c(3), c(4), passive, 1.0_dp, k, &
                                    theta, stat, msg)
                call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
                if (allocated(error)) return
                call wedge_k(c(1), c(2), c(3), c(4), c(5), c(6), passive, kw, found)
                call check(error, found, 'wedge extremum not interior')
                if (allocated(error)) return
                call check(error, k, kw, rtol=1.0e-10_dp, message='M-O vs wedge search')
                if (allocated(error)) return
            end associate
        end do
        ! the transcribed E.4 numerator sin^2(psi + phi - theta) misses the wedge at psi = 80
        call wedge_k(30.0_dp, 0.0_dp, 80.0_dp, 0.0_dp, 0.2_dp, 0.0_dp, .true., kw, found)
        theta = atan(0.2_dp)
        e4 = sin(80*rad + 30*rad - theta)**2/(cos(theta)*sin(80*rad)**2*sin(80*rad + theta)* &
             (1.0_dp - sqrt(sin(30*rad)*sin(30*rad - theta)/(sin(80*rad)* &
                                                             sin(80*rad + theta))))**2)
        call check(error, abs(e4/kw - 1.0_dp) > 0.1_dp, 'transcribed E.4 should miss the wedge')
        if (allocated(error)) return
        call mononobe_okabe(30.0_dp, 0.2_dp, 0.0_dp, 0.0_dp, 80.0_dp, 0.0_dp, .true., 1.0_dp, &
                            k, theta, stat, msg)
        call check(error, k, kw, rtol=1.0e-10_dp, message='implemented passive vs wedge, psi 80')
        if (allocated(error)) return
        ! a back flatter than phi (psi + theta <= phi: the square root reaches 1): K finite
        do i = 1, 3
            theta = flat_backs(i)
            call wedge_k(40.0_dp, 0.0_dp, theta, 0.0_dp, 0.0_dp, 0.0_dp, .true., kw, found)
            call check(error, found, 'wedge extremum not interior (flat back)')
            if (allocated(error)) return
            call mononobe_okabe(40.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, theta, 0.0_dp, .true., 1.0_dp, &
                                k, e4, stat, msg)
            call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
            if (allocated(error)) return
            call check(error, k, kw, rtol=1.0e-9_dp, message='passive, psi <= phi vs wedge')
            if (allocated(error)) return
        end do
    end subroutine test_mo_wedge

    subroutine test_mo_no_solution(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, theta, ke3, limit, k2, e3
        integer :: stat
        character(len=256) :: msg
        ! active, beta > phi - theta: NO_SOLUTION, k = 0, k_e3 = E.3 (written here)
        call mononobe_okabe(30.0_dp, 0.24_dp, -0.12_dp, 10.0_dp, 95.0_dp, 25.0_dp, .false., &
                            1.0_dp, k, theta, stat, msg, ke3)
        call check_message(error, stat, SEISPULSE_NO_SOLUTION, msg, 'beta_deg = 25')
        if (allocated(error)) return
        call check(error, k, 0.0_dp, atol=0.0_dp, message='k = 0 (not NaN)')
        if (allocated(error)) return
        e3 = sin(95*rad + 30*rad - theta)**2/(cos(theta)*sin(95*rad)**2* &
                                              sin(95*rad - theta - 10*rad))
        call check(error, ke3, e3, rtol=1.0e-14_dp, message='k_e3 = E.3')
        if (allocated(error)) return
        call check(error, index(msg, 'no finite active thrust') > 0, trim(msg))
        if (allocated(error)) return
        ! continuity of E.2 into E.3 just below the limit beta = phi - theta
        limit = (30*rad - theta)/rad
        call mononobe_okabe(30.0_dp, 0.24_dp, -0.12_dp, 10.0_dp, 95.0_dp, limit - 1.0e-9_dp, &
                            .false., 1.0_dp, k2, theta, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, k2, sin(95*rad + 30*rad - theta)**2/(cos(theta)*sin(95*rad)**2* &
                   sin(95*rad - theta - 10*rad)), rtol=2.0e-5_dp, message='E.2 -> E.3 at the limit')
        if (allocated(error)) return
        ! active, psi - theta - delta <= 0
        call mononobe_okabe(30.0_dp, 0.1_dp, 0.0_dp, 15.0_dp, 20.0_dp, 0.0_dp, .false., &
                            1.0_dp, k, theta, stat, msg, ke3)
        call check_message(error, stat, SEISPULSE_NO_SOLUTION, msg, 'psi_deg = 20')
        if (allocated(error)) return
        call check(error, zero(k) .and. zero(ke3), 'k and k_e3 = 0')
        if (allocated(error)) return
        ! active, overhang: psi + phi - theta >= 180
        call mononobe_okabe(30.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 160.0_dp, 0.0_dp, .false., &
                            1.0_dp, k, theta, stat, msg)
        call check_message(error, stat, SEISPULSE_NO_SOLUTION, msg, 'psi_deg = 160')
        if (allocated(error)) return
        ! passive, ground in front sliding: phi + beta - theta < 0
        call mononobe_okabe(25.0_dp, 0.3_dp, 0.0_dp, 0.0_dp, 90.0_dp, -20.0_dp, .true., &
                            1.0_dp, k, theta, stat, msg)
        call check_message(error, stat, SEISPULSE_NO_SOLUTION, msg, 'beta_deg = -20')
        if (allocated(error)) return
        ! passive, psi + phi + beta + delta = 180 (phi = delta = 45, vertical, flat): unbounded
        call mononobe_okabe(45.0_dp, 0.0_dp, 0.0_dp, 45.0_dp, 90.0_dp, 0.0_dp, .true., &
                            1.0_dp, k, theta, stat, msg)
        call check_message(error, stat, SEISPULSE_NO_SOLUTION, msg, 'psi_deg = 90')
        if (allocated(error)) return
        ! passive, psi + theta + delta >= 180
        call mononobe_okabe(30.0_dp, 0.0_dp, 0.0_dp, 15.0_dp, 170.0_dp, 0.0_dp, .true., &
                            1.0_dp, k, theta, stat, msg)
        call check_message(error, stat, SEISPULSE_NO_SOLUTION, msg, 'psi_deg = 170')
        if (allocated(error)) return
        call check(error, k, 0.0_dp, atol=0.0_dp)
    end subroutine test_mo_no_solution

    subroutine test_mo_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k, theta, inf
        integer :: stat
        character(len=256) :: msg
        inf = ieee_value(1.0_dp, ieee_positive_inf)
        call mo(0.0_dp, 0.1_dp, 0.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 1.0_dp, 'phi_deg = 0')
        if (allocated(error)) return
        call mo(90.0_dp, 0.1_dp, 0.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 1.0_dp, 'phi_deg = 90')
        if (allocated(error)) return
        call mo(nan(), 0.1_dp, 0.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 1.0_dp, 'phi_deg = NaN')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 0.0_dp, -1.0_dp, 90.0_dp, 0.0_dp, 1.0_dp, 'delta_deg = -1')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 0.0_dp, 31.0_dp, 90.0_dp, 0.0_dp, 1.0_dp, 'delta_deg = 31')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 'psi_deg = 0')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 0.0_dp, 0.0_dp, 180.0_dp, 0.0_dp, 1.0_dp, 'psi_deg = 180')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 0.0_dp, 0.0_dp, 90.0_dp, 90.0_dp, 1.0_dp, 'beta_deg = 90')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 0.0_dp, 0.0_dp, 90.0_dp, -90.0_dp, 1.0_dp, 'beta_deg = -90')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 0.0_dp, 0.0_dp, 40.0_dp, -50.0_dp, 1.0_dp, 'beta_deg = -50')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 0.0_dp, 0.0_dp, 120.0_dp, 60.0_dp, 1.0_dp, 'beta_deg = 60')
        if (allocated(error)) return
        call mo(30.0_dp, -0.1_dp, 0.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 1.0_dp, 'kh = -0.1')
        if (allocated(error)) return
        call mo(30.0_dp, inf, 0.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 1.0_dp, 'kh = ')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 1.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 1.0_dp, 'kv = 1')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, nan(), 0.0_dp, 90.0_dp, 0.0_dp, 1.0_dp, 'kv = NaN')
        if (allocated(error)) return
        call mo(30.0_dp, 0.1_dp, 0.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 0.9_dp, 'gamma_phi = 0.9')
    contains
        subroutine mo(phi, kh, kv, delta, psi, beta, gphi, prefix)
            real(dp), intent(in) :: phi, kh, kv, delta, psi, beta, gphi
            character(len=*), intent(in) :: prefix
            call mononobe_okabe(phi, kh, kv, delta, psi, beta, .false., gphi, k, theta, stat, msg)
            call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, prefix)
            if (allocated(error)) return
            call check(error, zero(k) .and. zero(theta), 'outputs zeroed: '//prefix)
        end subroutine mo
    end subroutine test_mo_bad_input

    ! ------------------------------------------------------------------ thrust

    subroutine test_thrust_dry(error)
        type(test_error), allocatable, intent(out) :: error
        type(ec8_thrust_t) :: res
        integer :: stat
        character(len=256) :: msg
        real(dp), parameter :: h = 6.0_dp, g = 20.0_dp, kpub = 0.4856177257638489_dp
        real(dp) :: es, est, m
        call ec8_thrust(h, g, 30.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 0.24_dp, -0.12_dp, WATER_DRY, &
                        0.0_dp, 0.0_dp, 1.0_dp, res, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        es = 0.5_dp*g*1.12_dp*kpub*h**2
        est = 0.5_dp*g*h**2/3.0_dp
        call check(error, res%k, kpub, rtol=1.0e-12_dp, message='k')
        if (allocated(error)) return
        call check(error, res%theta, 0.2110933332227465_dp, rtol=1.0e-12_dp, message='theta')
        if (allocated(error)) return
        call check(error, res%e_soil, es, rtol=1.0e-12_dp, message='E.1 soil, (1 - kv) = 1.12')
        if (allocated(error)) return
        call check(error, res%k_static, 1.0_dp/3.0_dp, rtol=1.0e-14_dp, message='K static')
        if (allocated(error)) return
        call check(error, res%e_static, est, rtol=1.0e-14_dp, message='static 1/2 gamma K H^2')
        if (allocated(error)) return
        call check(error, res%e_dynamic, es - est, rtol=1.0e-12_dp, message='increment')
        if (allocated(error)) return
        call check(error, zero(res%e_ws) .and. zero(res%e_wd), 'no water terms dry')
        if (allocated(error)) return
        call check(error, res%total, es, rtol=1.0e-12_dp, message='total')
        if (allocated(error)) return
        call check(error, [res%z_static, res%z_dynamic, res%z_ws, res%z_wd], &
                   [2.0_dp, 3.0_dp, 2.0_dp, 2.4_dp], rtol=1.0e-15_dp, message='heights')
        if (allocated(error)) return
        m = est*2.0_dp + (es - est)*3.0_dp
        call check(error, res%m_base, m, rtol=1.0e-12_dp, message='moment')
        if (allocated(error)) return
        call check(error, res%z_total, m/es, rtol=1.0e-12_dp, message='z_total')
        if (allocated(error)) return
        ! kh = 0, kv > 0: K static, the soil only lighter: increment -kv E_st
        call ec8_thrust(h, g, 30.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 0.0_dp, 0.1_dp, WATER_DRY, &
                        0.0_dp, 0.0_dp, 1.0_dp, res, stat, msg)
        call check(error, res%e_dynamic, -0.1_dp*est, rtol=1.0e-13_dp, message='kh = 0, kv > 0')
    end subroutine test_thrust_dry

    subroutine test_thrust_water(error)
        type(test_error), allocatable, intent(out) :: error
        type(ec8_thrust_t) :: res
        integer :: stat
        character(len=256) :: msg
        real(dp), parameter :: h = 5.0_dp, g = 20.0_dp, gw = 9.81_dp, gd = 16.5_dp, &
                               kh = 0.2_dp, kv = 0.1_dp, phi = 32.0_dp*rad
        real(dp) :: theta, kk, es, est, ews, ewd, ks
        ks = (1.0_dp - sin(phi))/(1.0_dp + sin(phi))       ! Rankine static
        ! impervious: tan theta = gamma/(gamma - gamma_w) kh/(1 - kv); vertical-wall M-O
        ! cos^2(phi - theta)/(cos^2 theta [1 + sqrt(sin phi sin(phi - theta)/cos theta)]^2)
        call ec8_thrust(h, g, 32.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, kh, kv, WATER_IMPERVIOUS, gw, &
                        0.0_dp, 1.0_dp, res, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        theta = atan(g/(g - gw)*kh/(1.0_dp - kv))
        kk = cos(phi - theta)**2/(cos(theta)**2*(1.0_dp + sqrt(sin(phi)*sin(phi - theta)/ &
                                                              cos(theta)))**2)
        es = 0.5_dp*(g - gw)*(1.0_dp - kv)*kk*h**2
        est = 0.5_dp*(g - gw)*ks*h**2
        ews = 0.5_dp*gw*h**2
        call check(error, res%theta, theta, rtol=1.0e-14_dp, message='impervious theta')
        if (allocated(error)) return
        call check(error, res%k, kk, rtol=1.0e-13_dp, message='impervious K')
        if (allocated(error)) return
        call check(error, res%e_soil, es, rtol=1.0e-13_dp, message='impervious soil')
        if (allocated(error)) return
        call check(error, res%e_static, est, rtol=1.0e-13_dp, message='impervious static')
        if (allocated(error)) return
        call check(error, res%e_ws, ews, rtol=1.0e-15_dp, message='hydrostatic')
        if (allocated(error)) return
        call check(error, res%e_wd, 0.0_dp, atol=0.0_dp, message='no hydrodynamic term')
        if (allocated(error)) return
        call check(error, res%total, es + ews, rtol=1.0e-13_dp, message='impervious total')
        if (allocated(error)) return
        call check(error, res%m_base, est*h/3 + (es - est)*h/2 + ews*h/3, rtol=1.0e-13_dp, &
                   message='impervious moment')
        if (allocated(error)) return
        ! permeable: tan theta = gamma_d/(gamma - gamma_w) kh/(1 - kv), + 7/12 kh gamma_w H^2
        call ec8_thrust(h, g, 32.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, kh, kv, WATER_PERMEABLE, gw, gd, &
                        1.0_dp, res, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        theta = atan(gd/(g - gw)*kh/(1.0_dp - kv))
        kk = cos(phi - theta)**2/(cos(theta)**2*(1.0_dp + sqrt(sin(phi)*sin(phi - theta)/ &
                                                              cos(theta)))**2)
        es = 0.5_dp*(g - gw)*(1.0_dp - kv)*kk*h**2
        ewd = 7.0_dp/12.0_dp*kh*gw*h**2
        call check(error, res%theta, theta, rtol=1.0e-14_dp, message='permeable theta')
        if (allocated(error)) return
        call check(error, res%e_soil, es, rtol=1.0e-13_dp, message='permeable soil')
        if (allocated(error)) return
        call check(error, res%e_wd, ewd, rtol=1.0e-15_dp, message='E.13')
        if (allocated(error)) return
        call check(error, res%total, es + ews + ewd, rtol=1.0e-13_dp, message='permeable total')
        if (allocated(error)) return
        call check(error, res%m_base, est*h/3 + (es - est)*h/2 + ews*h/3 + ewd*0.4_dp*h, &
                   rtol=1.0e-13_dp, message='permeable moment')
        if (allocated(error)) return
        call check(error, res%z_total, res%m_base/res%total, rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! the water cases ignore gamma_w/gamma_d where unused: dry with junk values
        call ec8_thrust(h, g, 32.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, kh, kv, WATER_DRY, -1.0_dp, &
                        nan(), 1.0_dp, res, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'dry ignores gamma_w, gamma_d')
    end subroutine test_thrust_water

    subroutine test_thrust_bad(error)
        type(test_error), allocatable, intent(out) :: error
        type(ec8_thrust_t) :: res
        integer :: stat
        character(len=256) :: msg
        call th(0.0_dp, 20.0_dp, 30.0_dp, 90.0_dp, 0.0_dp, 0.1_dp, WATER_DRY, 9.81_dp, 0.0_dp, &
                SEISPULSE_INVALID_INPUT, 'height = 0')
        if (allocated(error)) return
        call th(5.0_dp, -1.0_dp, 30.0_dp, 90.0_dp, 0.0_dp, 0.1_dp, WATER_DRY, 9.81_dp, 0.0_dp, &
                SEISPULSE_INVALID_INPUT, 'gamma = -1')
        if (allocated(error)) return
        call th(5.0_dp, 20.0_dp, 30.0_dp, 90.0_dp, 0.0_dp, 0.1_dp, 4, 9.81_dp, 0.0_dp, &
                SEISPULSE_INVALID_INPUT, 'water_case = 4')
        if (allocated(error)) return
        call th(5.0_dp, 9.0_dp, 30.0_dp, 90.0_dp, 0.0_dp, 0.1_dp, WATER_IMPERVIOUS, 9.81_dp, &
                0.0_dp, SEISPULSE_INVALID_INPUT, 'gamma_w = 9.81')
        if (allocated(error)) return
        call th(5.0_dp, 20.0_dp, 30.0_dp, 90.0_dp, 0.0_dp, 0.1_dp, WATER_PERMEABLE, 0.0_dp, &
                17.0_dp, SEISPULSE_INVALID_INPUT, 'gamma_w = 0')
        if (allocated(error)) return
        call th(5.0_dp, 20.0_dp, 30.0_dp, 90.0_dp, 0.0_dp, 0.1_dp, WATER_PERMEABLE, 9.81_dp, &
                0.0_dp, SEISPULSE_INVALID_INPUT, 'gamma_d = 0')
        if (allocated(error)) return
        call th(5.0_dp, 20.0_dp, 95.0_dp, 90.0_dp, 0.0_dp, 0.1_dp, WATER_DRY, 9.81_dp, 0.0_dp, &
                SEISPULSE_INVALID_INPUT, 'phi_deg = 95')
        if (allocated(error)) return
        ! impervious soil raises theta: beta = 15 is fine dry, beyond the limit when wet
        call th(5.0_dp, 20.0_dp, 30.0_dp, 90.0_dp, 15.0_dp, 0.2_dp, WATER_DRY, 9.81_dp, 0.0_dp, &
                SEISPULSE_SUCCESS, '')
        if (allocated(error)) return
        call th(5.0_dp, 20.0_dp, 30.0_dp, 90.0_dp, 15.0_dp, 0.2_dp, WATER_IMPERVIOUS, 9.81_dp, &
                0.0_dp, SEISPULSE_NO_SOLUTION, 'beta_deg = 15')
        if (allocated(error)) return
        call check(error, index(msg, 'impervious soil') > 0, trim(msg))
        if (allocated(error)) return
        call check(error, zero(res%k) .and. zero(res%total), 'zero result on failure')
        if (allocated(error)) return
        ! the seismic wedge exists, the static one (psi + phi >= 180) does not
        call th(5.0_dp, 20.0_dp, 30.0_dp, 155.0_dp, 0.0_dp, 0.2_dp, WATER_DRY, 9.81_dp, 0.0_dp, &
                SEISPULSE_NO_SOLUTION, 'psi_deg = 155')
        if (allocated(error)) return
        call check(error, index(msg, 'static part') > 0, trim(msg))
    contains
        subroutine th(h, g, phi, psi, beta, kh, wc, gw, gd, code, prefix)
            real(dp), intent(in) :: h, g, phi, psi, beta, kh, gw, gd
            integer, intent(in) :: wc, code
            character(len=*), intent(in) :: prefix
            msg = ''
            call ec8_thrust(h, g, phi, 0.0_dp, psi, beta, kh, 0.0_dp, wc, gw, gd, 1.0_dp, res, &
                            stat, msg)
            call check_message(error, stat, code, msg, prefix)
        end subroutine th
    end subroutine test_thrust_bad

    subroutine test_westergaard(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: h = 4.0_dp, kh = 0.15_dp, gw = 9.81_dp
        real(dp) :: s(3), w(3), z(3), q(3), force, moment, qa(3), z3(3)
        integer :: stat
        character(len=256) :: msg
        call westergaard_pressure(kh, gw, h, [0.0_dp, 1.0_dp, h], qa, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, qa, [0.0_dp, 0.875_dp*kh*gw*2.0_dp, 0.875_dp*kh*gw*h], &
                   rtol=1.0e-15_dp, message='q = 7/8 kh gamma_w sqrt(h z)')
        if (allocated(error)) return
        ! z = h s^2, dz = 2 h s ds: the integrands become polynomials in s of degree <= 4,
        ! exact with 3-point Gauss-Legendre on [0, 1]
        s = 0.5_dp*(1.0_dp + [-sqrt(0.6_dp), 0.0_dp, sqrt(0.6_dp)])
        w = 0.5_dp*[5.0_dp, 8.0_dp, 5.0_dp]/9.0_dp
        z = h*s**2
        call westergaard_pressure(kh, gw, h, z, q, stat, msg)
        force = sum(w*q*2.0_dp*h*s)
        moment = sum(w*q*(h - z)*2.0_dp*h*s)
        call check(error, force, 7.0_dp/12.0_dp*kh*gw*h**2, rtol=1.0e-14_dp, &
                   message='resultant 7/12 kh gamma_w H^2 (E.13)')
        if (allocated(error)) return
        call check(error, moment/force, 0.4_dp*h, rtol=1.0e-14_dp, message='at 0.4 H')
        if (allocated(error)) return
        z3 = [0.0_dp, 4.5_dp, 1.0_dp]
        call westergaard_pressure(kh, gw, h, z3, qa, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'z(2) = 4.5')
        if (allocated(error)) return
        call check(error, all(ieee_is_nan(qa)), 'q = NaN on error')
        if (allocated(error)) return
        call westergaard_pressure(kh, gw, h, [-0.1_dp], qa(1:1), stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'z(1) = -0.1')
        if (allocated(error)) return
        call westergaard_pressure(-kh, gw, h, [0.1_dp], qa(1:1), stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'kh = -0.15')
        if (allocated(error)) return
        call westergaard_pressure(kh, 0.0_dp, h, [0.1_dp], qa(1:1), stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'gamma_w = 0')
        if (allocated(error)) return
        call westergaard_pressure(kh, gw, 0.0_dp, [0.0_dp], qa(1:1), stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'h_water = 0')
        if (allocated(error)) return
        call westergaard_pressure(kh, gw, h, [0.1_dp, 0.2_dp], qa, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'q: must have the size')
        if (allocated(error)) return
        call westergaard_pressure(kh, gw, h, [5.0_dp], qa(1:1), stat)
        call check(error, ieee_is_nan(qa(1)), 'NaN on error')
    end subroutine test_westergaard

    subroutine test_rigid_rules(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: p, z
        integer :: stat
        character(len=256) :: msg
        call ec8_rigid_thrust(0.3_dp, 19.0_dp, 7.0_dp, p, z, stat, msg)
        call check(error, [p, z], [0.3_dp*19*49, 3.5_dp], rtol=1.0e-15_dp, message='EC8 rigid')
        if (allocated(error)) return
        call seed_whitman_increment(0.2_dp, 19.0_dp, 7.0_dp, p, z, stat, msg)
        call check(error, [p, z], [3.0_dp/8*0.2_dp*19*49, 4.2_dp], rtol=1.0e-15_dp, &
                   message='Seed-Whitman')
        if (allocated(error)) return
        ! Seed-Whitman's increment is 1/2 gamma H^2 (3/4 kh)
        call check(error, p, 0.5_dp*19*49*0.75_dp*0.2_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call wood_thrust(0.2_dp, 19.0_dp, 7.0_dp, p, z, stat, msg)
        call check(error, [p, z], [0.2_dp*19*49, 4.2_dp], rtol=1.0e-15_dp, message='Wood')
        if (allocated(error)) return
        call ec8_rigid_thrust(-0.1_dp, 19.0_dp, 7.0_dp, p, z, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'alpha_s = -0.1')
        if (allocated(error)) return
        call seed_whitman_increment(0.2_dp, 0.0_dp, 7.0_dp, p, z, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'gamma = 0')
        if (allocated(error)) return
        call wood_thrust(0.2_dp, 19.0_dp, -7.0_dp, p, z, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'height = -7')
        if (allocated(error)) return
        call wood_thrust(nan(), 19.0_dp, 7.0_dp, p, z, stat)
        call check(error, ieee_is_nan(p) .and. ieee_is_nan(z), 'NaN on error')
    end subroutine test_rigid_rules

    ! ------------------------------------------------------------------ spectra

    subroutine test_ground_parameters(error)
        type(test_error), allocatable, intent(out) :: error
        ! EN 1998-1 Table 3.2 (Type 1) and 3.3 (Type 2), typed again from EN 1998-1
        real(dp), parameter :: t1(4, 5) = reshape([1.00_dp, 0.15_dp, 0.40_dp, 2.0_dp, &
            1.20_dp, 0.15_dp, 0.50_dp, 2.0_dp, 1.15_dp, 0.20_dp, 0.60_dp, 2.0_dp, &
            1.35_dp, 0.20_dp, 0.80_dp, 2.0_dp, 1.40_dp, 0.15_dp, 0.50_dp, 2.0_dp], [4, 5])
        real(dp), parameter :: t2(4, 5) = reshape([1.00_dp, 0.05_dp, 0.25_dp, 1.2_dp, &
            1.35_dp, 0.05_dp, 0.25_dp, 1.2_dp, 1.50_dp, 0.10_dp, 0.25_dp, 1.2_dp, &
            1.80_dp, 0.10_dp, 0.30_dp, 1.2_dp, 1.60_dp, 0.05_dp, 0.25_dp, 1.2_dp], [4, 5])
        integer, parameter :: grounds(5) = [EC8_GROUND_A, EC8_GROUND_B, EC8_GROUND_C, &
                                            EC8_GROUND_D, EC8_GROUND_E]
        real(dp) :: s, tb, tc, td
        integer :: g, stat
        character(len=256) :: msg
        do g = 1, 5
            call ec8_ground_parameters(EC8_SPECTRUM_TYPE_1, grounds(g), s, tb, tc, td, stat, msg)
            call check(error, [s, tb, tc, td], t1(:, g), rtol=0.0_dp, message='Type 1')
            if (allocated(error)) return
            call ec8_ground_parameters(EC8_SPECTRUM_TYPE_2, grounds(g), s, tb, tc, td, stat, msg)
            call check(error, [s, tb, tc, td], t2(:, g), rtol=0.0_dp, message='Type 2')
            if (allocated(error)) return
        end do
        call ec8_ground_parameters(3, 1, s, tb, tc, td, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'spectrum_type = 3')
        if (allocated(error)) return
        call ec8_ground_parameters(1, 6, s, tb, tc, td, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'ground = 6')
        if (allocated(error)) return
        call ec8_ground_parameters(1, 0, s, tb, tc, td, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'ground = 0')
    end subroutine test_ground_parameters

    subroutine test_damping(error)
        type(test_error), allocatable, intent(out) :: error
        integer :: stat
        character(len=256) :: msg
        call check(error, ec8_damping_correction(5.0_dp), 1.0_dp, rtol=0.0_dp, message='eta(5)')
        if (allocated(error)) return
        call check(error, ec8_damping_correction(0.0_dp), sqrt(2.0_dp), rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, ec8_damping_correction(10.0_dp), sqrt(2.0_dp/3.0_dp), rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! floor: sqrt(10/(5 + xi)) = 0.55 at xi = 10/0.3025 - 5 = 28.0579
        call check(error, ec8_damping_correction(28.0_dp), sqrt(10.0_dp/33.0_dp), &
                   rtol=1.0e-15_dp, message='just above the floor')
        if (allocated(error)) return
        call check(error, ec8_damping_correction(28.06_dp), 0.55_dp, rtol=0.0_dp, &
                   message='floor at 28.06 %')
        if (allocated(error)) return
        call check(error, ec8_damping_correction(100.0_dp), 0.55_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, ieee_is_nan(ec8_damping_correction(-1.0_dp)), 'eta(-1) = NaN')
        if (allocated(error)) return
        call ec8_check_damping(-1.0_dp, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'xi_percent = -1')
        if (allocated(error)) return
        call ec8_check_damping(7.0_dp, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS)
    end subroutine test_damping

    subroutine test_elastic_spectrum(error)
        type(test_error), allocatable, intent(out) :: error
        ! ground C, Type 1: S = 1.15, TB = 0.2, TC = 0.6, TD = 2.0; ag = 0.25 g (m/s^2)
        real(dp), parameter :: ag = 0.25_dp*9.81_dp, s = 1.15_dp, tb = 0.2_dp, tc = 0.6_dp, &
                               td = 2.0_dp, e = 1.0e-12_dp
        real(dp) :: t(10), se(10), ex(10), eta, sl(6), sr(6)
        integer :: stat
        character(len=256) :: msg
        t = [0.0_dp, 0.1_dp, tb, 0.4_dp, tc, 1.0_dp, td, 3.0_dp, 4.0_dp, 6.0_dp]
        eta = sqrt(10.0_dp/(5.0_dp + 3.0_dp))      ! xi = 3 %
        ex(1) = ag*s
        ex(2) = ag*s*(1.0_dp + 0.5_dp*(2.5_dp*eta - 1.0_dp))
        ex(3:5) = 2.5_dp*eta*ag*s
        ex(6) = 2.5_dp*eta*ag*s*0.6_dp
        ex(7) = 2.5_dp*eta*ag*s*0.3_dp
        ex(8) = 2.5_dp*eta*ag*s*0.6_dp*2.0_dp/9.0_dp
        ex(9) = 2.5_dp*eta*ag*s*1.2_dp/16.0_dp
        ex(10) = 2.5_dp*eta*ag*s*1.2_dp/36.0_dp
        call ec8_elastic_spectrum(t, ag, EC8_SPECTRUM_TYPE_1, EC8_GROUND_C, 3.0_dp, se, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, se, ex, rtol=1.0e-14_dp, message='Se, ground C Type 1, xi = 3 %')
        if (allocated(error)) return
        ! continuity at TB, TC, TD
        call ec8_elastic_spectrum([tb - e, tc - e, td - e], ag, 1, EC8_GROUND_C, 3.0_dp, &
                                  sl(1:3), stat, msg)
        call ec8_elastic_spectrum([tb + e, tc + e, td + e], ag, 1, EC8_GROUND_C, 3.0_dp, &
                                  sr(1:3), stat, msg)
        call check(error, sl(1:3), sr(1:3), rtol=1.0e-10_dp, message='continuity')
        if (allocated(error)) return
        ! 5 %: plateau 2.5 ag S, ground E Type 2 (S = 1.6, TB = 0.05, TC = 0.25, TD = 1.2)
        call ec8_elastic_spectrum([0.05_dp, 0.1_dp, 0.25_dp, 0.5_dp, 1.2_dp, 2.0_dp], 1.0_dp, &
                                  EC8_SPECTRUM_TYPE_2, EC8_GROUND_E, 5.0_dp, sl, stat, msg)
        call check(error, sl, 4.0_dp*[1.0_dp, 1.0_dp, 1.0_dp, 0.5_dp, 0.25_dp/1.2_dp, &
                                      0.25_dp*1.2_dp/4.0_dp], rtol=1.0e-14_dp, &
                   message='Type 2 ground E, 5 %')
    end subroutine test_elastic_spectrum

    subroutine test_design_spectrum(error)
        type(test_error), allocatable, intent(out) :: error
        ! ground B, Type 1: S = 1.2, TB = 0.15, TC = 0.5, TD = 2.0; ag = 0.16 (g), q = 3.5
        real(dp), parameter :: ag = 0.16_dp, s = 1.2_dp, q = 3.5_dp, e = 1.0e-12_dp
        real(dp) :: t(9), sd(9), ex(9), plateau, sl(3), sr(3)
        integer :: stat
        character(len=256) :: msg
        plateau = ag*s*2.5_dp/q
        t = [0.0_dp, 0.075_dp, 0.15_dp, 0.3_dp, 0.5_dp, 1.0_dp, 2.0_dp, 2.5_dp, 4.0_dp]
        ex(1) = ag*s*2.0_dp/3.0_dp
        ex(2) = ag*s*(2.0_dp/3.0_dp + 0.5_dp*(2.5_dp/q - 2.0_dp/3.0_dp))
        ex(3:5) = plateau
        ex(6) = plateau*0.5_dp                       ! 0.0686 > 0.2 ag = 0.032
        ex(7) = max(plateau*0.25_dp, 0.2_dp*ag)      ! 0.0343
        ex(8) = max(plateau*0.5_dp*2.0_dp/6.25_dp, 0.2_dp*ag)   ! 0.02194 -> floor 0.032
        ex(9) = 0.2_dp*ag
        call ec8_design_spectrum(t, ag, 1, EC8_GROUND_B, q, 0.2_dp, sd, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, sd, ex, rtol=1.0e-14_dp, message='Sd ground B, q = 3.5')
        if (allocated(error)) return
        call check(error, sd(8), 0.2_dp*ag, rtol=0.0_dp, message='floor active at 2.5 s')
        if (allocated(error)) return
        call ec8_design_spectrum([0.15_dp - e, 0.5_dp - e, 2.0_dp - e], ag, 1, EC8_GROUND_B, q, &
                                 0.2_dp, sl, stat, msg)
        call ec8_design_spectrum([0.15_dp + e, 0.5_dp + e, 2.0_dp + e], ag, 1, EC8_GROUND_B, q, &
                                 0.2_dp, sr, stat, msg)
        call check(error, sl, sr, rtol=1.0e-10_dp, message='continuity')
        if (allocated(error)) return
        ! q = 1, beta = 0: no floor, plateau 2.5 ag S
        call ec8_design_spectrum([0.3_dp, 10.0_dp], ag, 1, EC8_GROUND_B, 1.0_dp, 0.0_dp, &
                                 sl(1:2), stat, msg)
        call check(error, sl(1:2), [2.5_dp*ag*s, 2.5_dp*ag*s*0.5_dp*2.0_dp/100.0_dp], &
                   rtol=1.0e-14_dp, message='q = 1, beta = 0')
    end subroutine test_design_spectrum

    subroutine test_spectra_bad(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: out(2)
        integer :: stat
        character(len=256) :: msg
        call ec8_elastic_spectrum([0.1_dp, -0.5_dp], 1.0_dp, 1, 1, 5.0_dp, out, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'periods(2) = -0.5')
        if (allocated(error)) return
        call ec8_elastic_spectrum([0.1_dp, nan()], 1.0_dp, 1, 1, 5.0_dp, out, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'periods(2) = NaN')
        if (allocated(error)) return
        call ec8_elastic_spectrum([0.1_dp, 0.2_dp], -1.0_dp, 1, 1, 5.0_dp, out, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'ag = -1')
        if (allocated(error)) return
        call ec8_elastic_spectrum([0.1_dp, 0.2_dp], 1.0_dp, 2, 1, -5.0_dp, out, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'xi_percent = -5')
        if (allocated(error)) return
        call ec8_elastic_spectrum([0.1_dp, 0.2_dp], 1.0_dp, 0, 1, 5.0_dp, out, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'spectrum_type = 0')
        if (allocated(error)) return
        call ec8_elastic_spectrum([0.1_dp], 1.0_dp, 1, 1, 5.0_dp, out, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'se: must have the size')
        if (allocated(error)) return
        call ec8_design_spectrum([0.1_dp, 0.2_dp], 1.0_dp, 1, 1, 0.9_dp, 0.2_dp, out, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'q = 0.9')
        if (allocated(error)) return
        call ec8_design_spectrum([0.1_dp, 0.2_dp], 1.0_dp, 1, 1, 2.0_dp, -0.2_dp, out, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'beta = -0.2')
        if (allocated(error)) return
        call ec8_design_spectrum([0.1_dp, 0.2_dp], 1.0_dp, 1, 9, 2.0_dp, 0.2_dp, out, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'ground = 9')
    end subroutine test_spectra_bad

    subroutine test_reference_pga(error)
        type(test_error), allocatable, intent(out) :: error
        ! zone values of the 2003 map adopted by the Greek NA, g ([PRDA24]: three zones,
        ! 0.16-0.36 g; 0.24 g and the names Z1-Z3 from press reports, SECONDARY)
        real(dp), parameter :: zones_2003(3) = [0.16_dp, 0.24_dp, 0.36_dp]
        real(dp) :: agr, se(3), ex(3)
        integer :: stat, zone
        character(len=256) :: msg
        call check(error, EC8_ANNEX_RECOMMENDED == 0 .and. EC8_ANNEX_GR == 1, 'annex codes')
        if (allocated(error)) return
        do zone = 1, 3
            call ec8_reference_pga(EC8_ANNEX_GR, zone, agr, stat, msg)
            call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
            if (allocated(error)) return
            call check(error, agr, zones_2003(zone), rtol=0.0_dp, message='a_gR of zone')
            if (allocated(error)) return
        end do
        ! a zone's spectrum is the spectrum of ag = gamma_I a_gR: Z2, gamma_I = 1.2, ground B
        ! Type 1 (S = 1.2, TB = 0.15, TC = 0.5): plateau 2.5 ag S, ag S at T = 0
        call ec8_reference_pga(EC8_ANNEX_GR, 2, agr, stat, msg)
        call ec8_elastic_spectrum([0.0_dp, 0.3_dp, 1.0_dp], 1.2_dp*agr, EC8_SPECTRUM_TYPE_1, &
                                  EC8_GROUND_B, 5.0_dp, se, stat, msg)
        ex = 1.2_dp*0.24_dp*1.2_dp*[1.0_dp, 2.5_dp, 2.5_dp*0.5_dp]
        call check(error, se, ex, rtol=1.0e-14_dp, message='Se of Z2, gamma_I = 1.2, ground B')
        if (allocated(error)) return
        ! refusals: a_gR = 0 (as the spectra's outputs), message naming the parameter and
        ! the allowed values
        call ec8_reference_pga(EC8_ANNEX_GR, 4, agr, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'zone = 4: must be 1, 2 or 3')
        if (allocated(error)) return
        call check(error, agr, 0.0_dp, rtol=0.0_dp, message='a_gR = 0 on error')
        if (allocated(error)) return
        call ec8_reference_pga(EC8_ANNEX_GR, 0, agr, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'zone = 0')
        if (allocated(error)) return
        call ec8_reference_pga(EC8_ANNEX_RECOMMENDED, 1, agr, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'annex = 0')
        if (allocated(error)) return
        call check(error, index(msg, 'give ag') > 0, 'recommended: "give ag" in '//trim(msg))
        if (allocated(error)) return
        call check(error, agr, 0.0_dp, rtol=0.0_dp, &
                   message='a_gR = 0 for the recommended values')
        if (allocated(error)) return
        call ec8_reference_pga(7, 1, agr, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'annex = 7: must be 1')
        if (allocated(error)) return
        ! without errmsg
        call ec8_reference_pga(EC8_ANNEX_GR, 5, agr, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'stat without errmsg')
    end subroutine test_reference_pga

    !> The one rule of ag = gamma_I a_gR (written out: Z3 0.36 g x 1.2 = 0.432 g) and each
    !> refusal with the parameter it names.
    subroutine test_design_ag(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: nan, ag
        integer :: stat
        character(len=256) :: msg
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        msg = ''
        call ec8_design_ag(nan, EC8_ANNEX_GR, 3, 1.2_dp, ag, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, ag, 1.2_dp*0.36_dp, rtol=0.0_dp, message='Z3, gamma_I = 1.2')
        if (allocated(error)) return
        ! ag given: returned as is, importance 1 and either annex accepted (only checked)
        call ec8_design_ag(0.25_dp, EC8_ANNEX_GR, 0, 1.0_dp, ag, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, ag, 0.25_dp, rtol=0.0_dp, message='ag with annex GR')
        if (allocated(error)) return
        call ec8_design_ag(0.0_dp, EC8_ANNEX_RECOMMENDED, 0, 1.0_dp, ag, stat, msg)
        call check(error, stat == SEISPULSE_SUCCESS .and. zero(ag), 'ag = 0, recommended')
        if (allocated(error)) return
        call ec8_design_ag(nan, EC8_ANNEX_GR, 0, 1.0_dp, ag, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'ag: give the design')
        if (allocated(error)) return
        call ec8_design_ag(0.2_dp, EC8_ANNEX_GR, 2, 1.0_dp, ag, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'ag and zone: give one')
        if (allocated(error)) return
        call ec8_design_ag(0.2_dp, EC8_ANNEX_GR, 0, 1.2_dp, ag, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'importance = 1.2')
        if (allocated(error)) return
        call check(error, index(msg, 'ag is already the design ground acceleration') > 0, &
                   'importance with ag: '//trim(msg))
        if (allocated(error)) return
        call ec8_design_ag(nan, EC8_ANNEX_GR, 2, 0.0_dp, ag, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, &
                           'importance = 0.0: must be a finite number > 0')
        if (allocated(error)) return
        call ec8_design_ag(nan, EC8_ANNEX_GR, 2, nan, ag, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'importance = ')
        if (allocated(error)) return
        call ec8_design_ag(-0.1_dp, EC8_ANNEX_GR, 0, 1.0_dp, ag, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'ag = -0.1: must be')
        if (allocated(error)) return
        call ec8_design_ag(0.2_dp, 7, 0, 1.0_dp, ag, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'annex = 7')
        if (allocated(error)) return
        call ec8_design_ag(nan, EC8_ANNEX_RECOMMENDED, 1, 1.0_dp, ag, stat, msg)
        call check_message(error, stat, SEISPULSE_INVALID_INPUT, msg, 'annex = 0')
        if (allocated(error)) return
        call check(error, ag, 0.0_dp, rtol=0.0_dp, message='ag = 0 on error')
    end subroutine test_design_ag

end module test_codes
