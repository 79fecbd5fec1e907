!> EAK 2000 spectra (seispulse_eak2000) against values computed independently: the check
!> table of doc/eak2000.md (soils A-D, T = 0 .. 3 s, alpha 0.24, q 3.5, 4 digits); the
!> closed forms (K.1)-(K.3) written out here; Phi_d(0) = gamma_I A; the plateau; left and
!> right limits at T1 and T2 (neighbouring doubles); eta = sqrt(7/(2 + xi)) at 2..20 %
!> and its optional lower limit; the elastic spectrum (= Phi_d with q = theta = 1 at the
!> exponent 2/3, (T2/T)^1 at exponent 1); the optional floor and where it acts (the
!> crossing period T2 (plateau/floor)^(3/2)); the zones of both maps, the importance
!> factors, the ground table; optional arguments omitted = their defaults; every bad
!> input (messages name the parameter).
module test_eak2000
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_next_after, ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_eak2000, only: eak2000_ground_parameters, eak2000_zone_acceleration, &
                                 eak2000_importance_factor, eak2000_damping_correction, &
                                 eak2000_check_damping, eak2000_design_spectrum, &
                                 eak2000_elastic_spectrum, EAK_GROUND_A, EAK_GROUND_B, &
                                 EAK_GROUND_C, EAK_GROUND_D, EAK_GROUND_X, EAK_MAP_2003, &
                                 EAK_MAP_2000, EAK_BETA0
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_eak2000

    !> The check table of doc/eak2000.md section 6 (alpha 0.24, gamma_I = eta = theta = 1,
    !> q = 3.5; g, 4 digits), rows A..D, columns T = 0, 0.1, 0.2, 0.5, 1, 2, 3 s.
    real(dp), parameter :: table_t(7) = [0.0_dp, 0.1_dp, 0.2_dp, 0.5_dp, 1.0_dp, 2.0_dp, 3.0_dp]
    real(dp), parameter :: table(7, 4) = reshape([ &
        0.2400_dp, 0.1714_dp, 0.1714_dp, 0.1477_dp, 0.0931_dp, 0.0586_dp, 0.0447_dp, &
        0.2400_dp, 0.1943_dp, 0.1714_dp, 0.1714_dp, 0.1220_dp, 0.0768_dp, 0.0586_dp, &
        0.2400_dp, 0.2057_dp, 0.1714_dp, 0.1714_dp, 0.1477_dp, 0.0931_dp, 0.0710_dp, &
        0.2400_dp, 0.2057_dp, 0.1714_dp, 0.1714_dp, 0.1714_dp, 0.1220_dp, 0.0931_dp], [7, 4])
    !> T1, T2 (s) of soils A..D, transcribed here from doc/eak2000.md section 4.
    real(dp), parameter :: t1_ref(4) = [0.10_dp, 0.15_dp, 0.20_dp, 0.20_dp]
    real(dp), parameter :: t2_ref(4) = [0.40_dp, 0.60_dp, 0.80_dp, 1.20_dp]

contains

    subroutine collect_eak2000(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('check table: soils A-D, T = 0..3 s, alpha 0.24, q 3.5 (4 digits)', &
                              test_check_table), &
                 new_unittest('closed forms (K.1)-(K.3) written out, gamma_I, q, theta, xi', &
                              test_closed_forms), &
                 new_unittest('Phi_d(0) = gamma_I A; plateau gamma_I A eta theta beta0/q', &
                              test_zero_and_plateau), &
                 new_unittest('continuity at T1 and T2: left/right neighbouring doubles', &
                              test_continuity), &
                 new_unittest('eta = sqrt(7/(2 + xi)) at 2..20 %; eta_min where it acts', &
                              test_eta), &
                 new_unittest('elastic: = design at q = theta = 1 (2/3); exponent 1 beyond T2', &
                              test_elastic), &
                 new_unittest('lower_bound: only beyond T2 (plateau/floor)^(3/2)', &
                              test_lower_bound), &
                 new_unittest('zones of the 2003 and 2000 maps, importance, ground table', &
                              test_tables), &
                 new_unittest('optional arguments omitted = their defaults', test_defaults), &
                 new_unittest('bad input: each parameter named, output zeroed', test_bad_input)]
    end subroutine collect_eak2000

    ! ------------------------------------------------------------------ helpers

    !> errmsg must start with `prefix` and stat must be SEISPULSE_INVALID_INPUT.
    subroutine check_invalid(error, stat, errmsg, prefix)
        type(test_error), allocatable, intent(inout) :: error
        integer, intent(in) :: stat
        character(len=*), intent(in) :: errmsg, prefix
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'status for '//prefix)
        if (allocated(error)) return
        call check(error, index(errmsg, prefix) == 1, 'message "'//trim(errmsg)// &
                   '" should start with "'//prefix//'"')
    end subroutine check_invalid

    !> (K.1)-(K.3) written out here, with the floor lb gamma_I A and the exponent p.
    pure real(dp) function phi_ref(t, alpha, t1, t2, gi, q, theta, eta, lb, p) result(phi)
        real(dp), intent(in) :: t, alpha, t1, t2, gi, q, theta, eta, lb, p
        real(dp) :: a, pl
        a = gi*alpha
        pl = a*eta*theta*2.5_dp/q
        if (t <= t1) then
            phi = a + (pl - a)*t/t1
        else if (t <= t2) then
            phi = pl
        else
            phi = pl*exp(p*log(t2/t))
        end if
        phi = max(phi, lb*a)
    end function phi_ref

    real(dp) function nan()
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
    end function nan

    ! ------------------------------------------------------------------ tests

    subroutine test_check_table(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: phi(7)
        integer :: stat, g, i
        character(len=64) :: label
        do g = 1, 4
            call eak2000_design_spectrum(table_t, 0.24_dp, g, q=3.5_dp, phi_d=phi, stat=stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            do i = 1, 7
                write(label, '(a, i0, a, f4.1, a)') 'soil ', g, ', T = ', table_t(i), ' s'
                ! compared at the table's 4-digit rounding
                call check(error, nint(phi(i)*1.0e4_dp), nint(table(i, g)*1.0e4_dp), &
                           trim(label))
                if (allocated(error)) return
            end do
        end do
    end subroutine test_check_table

    subroutine test_closed_forms(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: ts(9) = [0.0_dp, 0.03_dp, 0.1_dp, 0.17_dp, 0.35_dp, 0.7_dp, &
                                        1.3_dp, 4.0_dp, 10.0_dp]
        real(dp), parameter :: gis(3) = [0.85_dp, 1.15_dp, 1.3_dp]
        real(dp), parameter :: qs(3) = [1.0_dp, 2.0_dp, 4.5_dp]
        real(dp), parameter :: thetas(3) = [1.0_dp, 0.9_dp, 0.8_dp]
        real(dp), parameter :: xis(3) = [5.0_dp, 2.0_dp, 12.0_dp]
        real(dp) :: phi(size(ts)), eta
        integer :: stat, g, k, i
        do g = 1, 4
            do k = 1, 3
                eta = sqrt(7.0_dp/(2.0_dp + xis(k)))
                call eak2000_design_spectrum(ts, 0.36_dp, g, gis(k), qs(k), thetas(k), xis(k), &
                                             0.0_dp, 0.0_dp, phi, stat)
                call check(error, stat, SEISPULSE_SUCCESS)
                if (allocated(error)) return
                do i = 1, size(ts)
                    call check(error, phi(i), phi_ref(ts(i), 0.36_dp, t1_ref(g), t2_ref(g), &
                               gis(k), qs(k), thetas(k), eta, 0.0_dp, 2.0_dp/3.0_dp), &
                               rtol=4.0e-15_dp, message='closed form')
                    if (allocated(error)) return
                end do
            end do
        end do
        ! q > eta theta beta0: (K.1) slopes down from gamma_I A to the plateau
        call eak2000_design_spectrum([0.0_dp, 0.05_dp, 0.1_dp], 0.24_dp, EAK_GROUND_A, &
                                     q=5.0_dp, phi_d=phi(1:3), stat=stat)
        call check(error, phi(1) > phi(2) .and. phi(2) > phi(3), 'slopes down for q = 5')
        if (allocated(error)) return
        call check(error, phi(3), 0.24_dp*0.5_dp, rtol=1.0e-15_dp, message='plateau q = 5')
    end subroutine test_closed_forms

    subroutine test_zero_and_plateau(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: phi(3), t1, t2, plateau
        integer :: stat, g
        do g = 1, 4
            call eak2000_ground_parameters(g, t1, t2, stat)
            call eak2000_design_spectrum([0.0_dp, 0.5_dp*(t1 + t2), t2], 0.16_dp, g, 1.3_dp, &
                                         3.0_dp, 0.8_dp, 10.0_dp, phi_d=phi, stat=stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call check(error, phi(1), 1.3_dp*0.16_dp, rtol=1.0e-15_dp, message='Phi_d(0)')
            if (allocated(error)) return
            plateau = 1.3_dp*0.16_dp*sqrt(7.0_dp/12.0_dp)*0.8_dp*2.5_dp/3.0_dp
            call check(error, phi(2), plateau, rtol=2.0e-15_dp, message='plateau')
            if (allocated(error)) return
            call check(error, phi(3), plateau, rtol=2.0e-15_dp, message='plateau at T2')
            if (allocated(error)) return
        end do
        call check(error, abs(EAK_BETA0 - 2.5_dp) <= 0.0_dp, 'beta0 = 2.5')
    end subroutine test_zero_and_plateau

    subroutine test_continuity(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: t(6), phi(6), t1, t2, e(6)
        integer :: stat, g, i
        do g = 1, 4
            call eak2000_ground_parameters(g, t1, t2, stat)
            t = [ieee_next_after(t1, 0.0_dp), t1, ieee_next_after(t1, 1.0_dp), &
                 ieee_next_after(t2, 0.0_dp), t2, ieee_next_after(t2, 10.0_dp)]
            call eak2000_design_spectrum(t, 0.24_dp, g, q=2.0_dp, theta=0.9_dp, &
                                         xi_percent=3.0_dp, phi_d=phi, stat=stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            do i = 1, 2
                call check(error, phi(3*i - 2), phi(3*i - 1), rtol=1.0e-14_dp, &
                           message='left limit')
                if (allocated(error)) return
                call check(error, phi(3*i), phi(3*i - 1), rtol=1.0e-14_dp, &
                           message='right limit')
                if (allocated(error)) return
            end do
            call eak2000_elastic_spectrum(t, 0.24_dp, g, exponent=1.0_dp, phi_e=e, stat=stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'Phi_e at the corners')
            if (allocated(error)) return
            do i = 1, 2
                call check(error, e(3*i - 2), e(3*i - 1), rtol=1.0e-14_dp, message='Phi_e left')
                if (allocated(error)) return
                call check(error, e(3*i), e(3*i - 1), rtol=1.0e-14_dp, message='Phi_e right')
                if (allocated(error)) return
            end do
        end do
    end subroutine test_continuity

    subroutine test_eta(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: xi(5) = [2.0_dp, 5.0_dp, 10.0_dp, 15.0_dp, 20.0_dp]
        ! doc/eak2000.md section 4, 4 digits
        integer, parameter :: eta4(5) = [13229, 10000, 7638, 6417, 5641]
        real(dp) :: eta(5), phi(2), phi_none(2)
        integer :: i, stat
        eta = eak2000_damping_correction(xi)
        do i = 1, 5
            call check(error, nint(eta(i)*1.0e4_dp), eta4(i), 'eta at the table''s 4 digits')
            if (allocated(error)) return
            call check(error, eta(i), sqrt(7.0_dp/(2.0_dp + xi(i))), rtol=1.0e-15_dp)
            if (allocated(error)) return
        end do
        call check(error, eta(2), 1.0_dp, rtol=0.0_dp, message='eta(5 %) = 1 exactly')
        if (allocated(error)) return
        ! eta_min: acts only where sqrt(7/(2 + xi)) is below it
        eta = eak2000_damping_correction(xi, 0.7_dp)
        call check(error, eta(1:3), [sqrt(7.0_dp/4.0_dp), 1.0_dp, sqrt(7.0_dp/12.0_dp)], &
                   rtol=1.0e-15_dp, message='eta_min not acting')
        if (allocated(error)) return
        call check(error, eta(4:5), [0.7_dp, 0.7_dp], rtol=0.0_dp, message='eta_min acting')
        if (allocated(error)) return
        ! NaN for bad input, and the check says why
        call check(error, ieee_is_nan(eak2000_damping_correction(-1.0_dp)), 'NaN for xi < 0')
        if (allocated(error)) return
        call check(error, ieee_is_nan(eak2000_damping_correction(5.0_dp, 1.5_dp)), &
                   'NaN for eta_min > 1')
        if (allocated(error)) return
        ! in the spectrum: eta_min = 0.7 leaves 5 % alone, lifts 20 % to 0.7
        call eak2000_design_spectrum([0.0_dp, 0.3_dp], 0.24_dp, EAK_GROUND_A, xi_percent=5.0_dp, &
                                     eta_min=0.7_dp, phi_d=phi, stat=stat)
        call eak2000_design_spectrum([0.0_dp, 0.3_dp], 0.24_dp, EAK_GROUND_A, phi_d=phi_none, &
                                     stat=stat)
        call check(error, phi, phi_none, rtol=0.0_dp, message='eta_min at 5 %')
        if (allocated(error)) return
        call eak2000_design_spectrum([0.0_dp, 0.3_dp], 0.24_dp, EAK_GROUND_A, xi_percent=20.0_dp, &
                                     eta_min=0.7_dp, phi_d=phi, stat=stat)
        call check(error, phi, [0.24_dp, 0.24_dp*0.7_dp*2.5_dp], rtol=1.0e-15_dp, &
                   message='eta_min at 20 %')
        if (allocated(error)) return
        call eak2000_design_spectrum([0.3_dp], 0.24_dp, EAK_GROUND_A, xi_percent=20.0_dp, &
                                     phi_d=phi(1:1), stat=stat)
        call check(error, phi(1), 0.24_dp*sqrt(7.0_dp/22.0_dp)*2.5_dp, rtol=1.0e-15_dp, &
                   message='no eta_min at 20 %')
        if (allocated(error)) return
        call eak2000_check_damping(5.0_dp, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
    end subroutine test_eta

    subroutine test_elastic(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: ts(8) = [0.0_dp, 0.05_dp, 0.15_dp, 0.4_dp, 0.6_dp, 0.9_dp, &
                                        2.0_dp, 5.0_dp]
        real(dp) :: d(8), e(8), e1(8), t1, t2, pl
        integer :: stat, g, i
        do g = 1, 4
            call eak2000_design_spectrum(ts, 0.36_dp, g, 1.15_dp, 1.0_dp, 1.0_dp, 7.0_dp, &
                                         phi_d=d, stat=stat)
            call eak2000_elastic_spectrum(ts, 0.36_dp, g, 1.15_dp, 7.0_dp, phi_e=e, stat=stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call check(error, e, d, rtol=0.0_dp, message='elastic = design, q = theta = 1')
            if (allocated(error)) return
            call eak2000_elastic_spectrum(ts, 0.36_dp, g, 1.15_dp, 7.0_dp, exponent=2.0_dp/3.0_dp, &
                                          phi_e=e, stat=stat)
            call check(error, e, d, rtol=0.0_dp, message='exponent 2/3 given')
            if (allocated(error)) return
            call eak2000_elastic_spectrum(ts, 0.36_dp, g, 1.15_dp, 7.0_dp, exponent=1.0_dp, &
                                          phi_e=e1, stat=stat)
            call eak2000_ground_parameters(g, t1, t2, stat)
            pl = 1.15_dp*0.36_dp*sqrt(7.0_dp/9.0_dp)*2.5_dp
            do i = 1, size(ts)
                if (ts(i) > t2) then
                    call check(error, e1(i), pl*t2/ts(i), rtol=2.0e-15_dp, message='(T2/T)^1')
                else
                    call check(error, e1(i), d(i), rtol=0.0_dp, message='exponent 1, T <= T2')
                end if
                if (allocated(error)) return
            end do
        end do
    end subroutine test_elastic

    subroutine test_lower_bound(error)
        type(test_error), allocatable, intent(out) :: error
        !> the crossing periods quoted in doc/eak2000.md section 5, soils A and B (s)
        real(dp), parameter :: tc_doc(2) = [1.9318_dp, 2.8977_dp]
        real(dp) :: phi(7), phi0(7), tc, t(2), pb(2)
        integer :: stat, g, i
        do g = 1, 4
            call eak2000_design_spectrum(table_t, 0.24_dp, g, q=3.5_dp, phi_d=phi0, stat=stat)
            call eak2000_design_spectrum(table_t, 0.24_dp, g, q=3.5_dp, lower_bound=0.25_dp, &
                                         phi_d=phi, stat=stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            do i = 1, 7
                ! the floor 0.25 x 0.24 = 0.06 g acts only where Phi_d would be below it
                if (phi0(i) < 0.06_dp) then
                    call check(error, phi(i), 0.06_dp, rtol=1.0e-15_dp, message='floored')
                else
                    call check(error, phi(i), phi0(i), rtol=0.0_dp, message='not floored')
                end if
                if (allocated(error)) return
            end do
        end do
        ! soil A: floored at 2 and 3 s, not at 1 s; soil B: at 3 s only (check table)
        call eak2000_design_spectrum([1.0_dp, 2.0_dp, 3.0_dp], 0.24_dp, EAK_GROUND_A, q=3.5_dp, &
                                     lower_bound=0.25_dp, phi_d=phi(1:3), stat=stat)
        call check(error, phi(1:3), [0.24_dp*2.5_dp/3.5_dp*(0.4_dp)**(2.0_dp/3.0_dp), 0.06_dp, &
                                     0.06_dp], rtol=1.0e-15_dp, message='soil A')
        if (allocated(error)) return
        ! the crossing period T2 (plateau/floor)^(3/2) (1.93 s for soil A, 2.90 s for B)
        do g = 1, 2
            tc = t2_ref(g)*(2.5_dp/3.5_dp/0.25_dp)**1.5_dp
            t = [tc*(1.0_dp - 1.0e-9_dp), tc*(1.0_dp + 1.0e-9_dp)]
            call eak2000_design_spectrum(t, 0.24_dp, g, q=3.5_dp, lower_bound=0.25_dp, &
                                         phi_d=pb, stat=stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call eak2000_design_spectrum(t, 0.24_dp, g, q=3.5_dp, phi_d=phi(1:2), stat=stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call check(error, pb(1) > 0.06_dp .and. abs(pb(1) - phi(1)) <= 0.0_dp, &
                       'just before the crossing: not floored')
            if (allocated(error)) return
            call check(error, abs(pb(2) - 0.06_dp) <= 0.0_dp .and. phi(2) < 0.06_dp, &
                       'just after the crossing: floored')
            if (allocated(error)) return
        end do
        ! the crossings quoted in doc/eak2000.md section 5 (1.9318 s for A, 2.8977 s for B)
        ! bracketed by the library: plateau branch just below, floor just above
        do g = 1, 2
            tc = tc_doc(g)
            call eak2000_design_spectrum([tc - 1.0e-4_dp, tc + 1.0e-4_dp], 0.24_dp, g, &
                                         q=3.5_dp, lower_bound=0.25_dp, phi_d=pb, stat=stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call check(error, pb(1) > 0.06_dp, 'below the quoted crossing: (K.3) governs')
            if (allocated(error)) return
            call check(error, pb(2), 0.06_dp, rtol=0.0_dp, &
                       message='above the quoted crossing: the floor governs')
            if (allocated(error)) return
        end do
    end subroutine test_lower_bound

    subroutine test_tables(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: z03(3) = [0.16_dp, 0.24_dp, 0.36_dp]
        real(dp), parameter :: z00(4) = [0.12_dp, 0.16_dp, 0.24_dp, 0.36_dp]
        real(dp), parameter :: gam(4) = [0.85_dp, 1.0_dp, 1.15_dp, 1.3_dp]
        real(dp) :: a, t1, t2
        integer :: stat, k
        character(len=200) :: msg
        do k = 1, 3
            call eak2000_zone_acceleration(k, alpha=a, stat=stat)
            call check(error, a, z03(k), rtol=0.0_dp, message='2003 map (default)')
            if (allocated(error)) return
            call eak2000_zone_acceleration(k, EAK_MAP_2003, a, stat)
            call check(error, a, z03(k), rtol=0.0_dp, message='2003 map')
            if (allocated(error)) return
        end do
        do k = 1, 4
            call eak2000_zone_acceleration(k, EAK_MAP_2000, a, stat)
            call check(error, a, z00(k), rtol=0.0_dp, message='2000 map')
            if (allocated(error)) return
            call eak2000_importance_factor(k, a, stat)
            call check(error, a, gam(k), rtol=0.0_dp, message='gamma_I')
            if (allocated(error)) return
            call eak2000_ground_parameters(k, t1, t2, stat)
            call check(error, [t1, t2], [t1_ref(k), t2_ref(k)], rtol=0.0_dp, message='T1, T2')
            if (allocated(error)) return
        end do
        call check(error, all([EAK_GROUND_A, EAK_GROUND_B, EAK_GROUND_C, EAK_GROUND_D, &
                               EAK_GROUND_X] == [1, 2, 3, 4, 5]) .and. EAK_MAP_2003 == 1 &
                   .and. EAK_MAP_2000 == 2, 'codes')
        if (allocated(error)) return
        msg = ''
        call eak2000_zone_acceleration(4, EAK_MAP_2003, a, stat, msg)
        call check_invalid(error, stat, msg, 'zone = 4: must be 1..3')
        if (allocated(error)) return
        call check(error, abs(a) <= 0.0_dp, 'alpha = 0 on error')
        if (allocated(error)) return
        call eak2000_zone_acceleration(0, EAK_MAP_2000, a, stat, msg)
        call check_invalid(error, stat, msg, 'zone = 0: must be 1..4')
        if (allocated(error)) return
        call eak2000_zone_acceleration(1, 3, a, stat, msg)
        call check_invalid(error, stat, msg, 'zone_map = 3')
        if (allocated(error)) return
        call eak2000_importance_factor(5, a, stat, msg)
        call check_invalid(error, stat, msg, 'category = 5')
        if (allocated(error)) return
        call eak2000_ground_parameters(EAK_GROUND_X, t1, t2, stat, msg)
        call check_invalid(error, stat, msg, 'ground = 5 (X): ground category X calls for a '// &
                           'site-specific study (unverified); give ground A-D')
        if (allocated(error)) return
        call eak2000_ground_parameters(0, t1, t2, stat, msg)
        call check_invalid(error, stat, msg, 'ground = 0: must be 1..4')
    end subroutine test_tables

    subroutine test_defaults(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(7), b(7)
        integer :: stat
        call eak2000_design_spectrum(table_t, 0.24_dp, EAK_GROUND_C, phi_d=a, stat=stat)
        call eak2000_design_spectrum(table_t, 0.24_dp, EAK_GROUND_C, 1.0_dp, 1.0_dp, 1.0_dp, &
                                     5.0_dp, 0.0_dp, 0.0_dp, b, stat)
        call check(error, a, b, rtol=0.0_dp, message='design defaults')
        if (allocated(error)) return
        call eak2000_elastic_spectrum(table_t, 0.24_dp, EAK_GROUND_C, phi_e=a, stat=stat)
        call eak2000_elastic_spectrum(table_t, 0.24_dp, EAK_GROUND_C, 1.0_dp, 5.0_dp, 0.0_dp, &
                                      2.0_dp/3.0_dp, b, stat)
        call check(error, a, b, rtol=0.0_dp, message='elastic defaults')
        if (allocated(error)) return
        call check(error, eak2000_damping_correction(12.0_dp), &
                   eak2000_damping_correction(12.0_dp, 0.0_dp), rtol=0.0_dp, &
                   message='eta_min default')
    end subroutine test_defaults

    !> The design spectrum at periods [t1, t2] with these arguments (the others valid)
    !> must fail with a message starting with `prefix`, its output zeroed.
    subroutine bad_design(error, prefix, t1, t2, alpha, ground, importance, q, theta, &
                          xi_percent, eta_min, lower_bound)
        type(test_error), allocatable, intent(inout) :: error
        character(len=*), intent(in) :: prefix
        real(dp), intent(in) :: t1, t2, alpha, importance, q, theta, xi_percent, eta_min, &
                                lower_bound
        integer, intent(in) :: ground
        real(dp) :: out(2)
        integer :: stat
        character(len=200) :: msg
        out = 1.0_dp
        msg = ''
        call eak2000_design_spectrum([t1, t2], alpha, ground, importance, q, theta, xi_percent, &
                                     eta_min, lower_bound, out, stat, msg)
        call check_invalid(error, stat, msg, prefix)
        if (allocated(error)) return
        call check(error, all(abs(out) <= 0.0_dp), 'output zeroed on error ('//prefix//')')
    end subroutine bad_design

    !> As bad_design, for the elastic spectrum.
    subroutine bad_elastic(error, prefix, t2, ground, xi_percent, exponent)
        type(test_error), allocatable, intent(inout) :: error
        character(len=*), intent(in) :: prefix
        real(dp), intent(in) :: t2, xi_percent, exponent
        integer, intent(in) :: ground
        real(dp) :: out(2)
        integer :: stat
        character(len=200) :: msg
        msg = ''
        call eak2000_elastic_spectrum([0.1_dp, t2], 0.24_dp, ground, 1.0_dp, xi_percent, 0.0_dp, &
                                      exponent, out, stat, msg)
        call check_invalid(error, stat, msg, prefix)
    end subroutine bad_elastic

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: out(2), out3(3)
        integer, parameter :: b = EAK_GROUND_B
        integer :: stat
        character(len=200) :: msg
        !                            t1      t2      alpha    ground importance q    theta
        !                            xi      eta_min lower_bound
        call bad_design(error, 'q = 0.99', 0.1_dp, 0.2_dp, 0.24_dp, b, 1.0_dp, 0.99_dp, 1.0_dp, &
                        5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'q = NaN', 0.1_dp, 0.2_dp, 0.24_dp, b, 1.0_dp, nan(), 1.0_dp, &
                        5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'theta = 0.0: the foundation factor must lie in (0, 1]', 0.1_dp, &
                        0.2_dp, 0.24_dp, b, 1.0_dp, 1.0_dp, 0.0_dp, 5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'theta = 1.01', 0.1_dp, 0.2_dp, 0.24_dp, b, 1.0_dp, 1.0_dp, &
                        1.01_dp, 5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'alpha = -0.01', 0.1_dp, 0.2_dp, -0.01_dp, b, 1.0_dp, 1.0_dp, &
                        1.0_dp, 5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'alpha = NaN', 0.1_dp, 0.2_dp, nan(), b, 1.0_dp, 1.0_dp, 1.0_dp, &
                        5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'periods(2) = -0.2', 0.1_dp, -0.2_dp, 0.24_dp, b, 1.0_dp, 1.0_dp, &
                        1.0_dp, 5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'periods(1) = NaN', nan(), 0.2_dp, 0.24_dp, b, 1.0_dp, 1.0_dp, &
                        1.0_dp, 5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'ground = 5 (X): ground category X calls for', 0.1_dp, 0.2_dp, &
                        0.24_dp, EAK_GROUND_X, 1.0_dp, 1.0_dp, 1.0_dp, 5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'importance = 0', 0.1_dp, 0.2_dp, 0.24_dp, b, 0.0_dp, 1.0_dp, &
                        1.0_dp, 5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'xi_percent = -1', 0.1_dp, 0.2_dp, 0.24_dp, b, 1.0_dp, 1.0_dp, &
                        1.0_dp, -1.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'eta_min = 1.5', 0.1_dp, 0.2_dp, 0.24_dp, b, 1.0_dp, 1.0_dp, &
                        1.0_dp, 5.0_dp, 1.5_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'lower_bound = -0.1', 0.1_dp, 0.2_dp, 0.24_dp, b, 1.0_dp, 1.0_dp, &
                        1.0_dp, 5.0_dp, 0.0_dp, -0.1_dp)
        if (allocated(error)) return
        ! overflow is refused, not NaN/Inf with success: gamma_I A, and the floor
        call bad_design(error, 'alpha = ', 0.1_dp, 0.2_dp, 10.0_dp, b, huge(1.0_dp), 1.0_dp, &
                        1.0_dp, 5.0_dp, 0.0_dp, 0.0_dp)
        if (allocated(error)) return
        call bad_design(error, 'alpha = ', 0.1_dp, 0.2_dp, 1.0e300_dp, b, 1.0_dp, 1.0_dp, &
                        1.0_dp, 5.0_dp, 0.0_dp, 1.0e10_dp)
        if (allocated(error)) return
        call bad_elastic(error, 'periods(2) = ', ieee_value(1.0_dp, ieee_positive_inf), b, &
                         5.0_dp, 2.0_dp/3.0_dp)
        if (allocated(error)) return
        call bad_elastic(error, 'ground = 6: must be 1..4', 0.2_dp, 6, 5.0_dp, 2.0_dp/3.0_dp)
        if (allocated(error)) return
        call bad_elastic(error, 'xi_percent = -1', 0.2_dp, b, -1.0_dp, 2.0_dp/3.0_dp)
        if (allocated(error)) return
        call bad_elastic(error, 'exponent = 0', 0.2_dp, b, 5.0_dp, 0.0_dp)
        if (allocated(error)) return
        msg = ''
        call eak2000_design_spectrum([0.1_dp, 0.2_dp], 0.24_dp, b, phi_d=out3, stat=stat, &
                                     errmsg=msg)
        call check_invalid(error, stat, msg, 'phi_d: must have the size of periods (2)')
        if (allocated(error)) return
        call eak2000_elastic_spectrum([0.1_dp, 0.2_dp], 0.24_dp, b, phi_e=out3, stat=stat, &
                                      errmsg=msg)
        call check_invalid(error, stat, msg, 'phi_e: must have the size of periods (2)')
        if (allocated(error)) return
        call eak2000_elastic_spectrum([0.1_dp, 0.2_dp], 0.24_dp, b, phi_e=out, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'valid elastic call')
        if (allocated(error)) return
        call eak2000_check_damping(nan(), stat=stat, errmsg=msg)
        call check_invalid(error, stat, msg, 'xi_percent = NaN')
        if (allocated(error)) return
        call eak2000_check_damping(5.0_dp, -0.1_dp, stat, msg)
        call check_invalid(error, stat, msg, 'eta_min = -0.1')
    end subroutine test_bad_input

end module test_eak2000
