!> EN 1998 code checks for retaining walls: seismic coefficients (EN 1998-5
!> §7.3.2.2), Mononobe-Okabe earth-pressure coefficients and thrusts with the three water
!> cases (EN 1998-5 Annex E), the rigid-wall rules (EN 1998-5, Seed & Whitman 1970,
!> Wood 1973) and the elastic and design response spectra of EN 1998-1 §3.2.2.
!>
!> Sources (doc/codes.md). The EN texts themselves could not be read here:
!> every formula and table value below agrees with at least two independent secondary
!> transcriptions (MIDAS design-guide components, GEO5 help, the xc project, eurocodepy,
!> TCVN 9386:2012 for EN 1998-1, UFC 3-220-20 for the Westergaard, Seed-Whitman and Wood
!> terms). Equation numbers that rest on recollection only are marked "(not verified)".
!> Table values are the RECOMMENDED values of EN; a National Annex may change them
!> (S, TB, TC, TD, beta, gamma_phi, r); of the Greek National Annex only the seismic
!> zones are implemented (ec8_reference_pga). The EAK 2000 spectra are in seispulse_eak2000
!> (doc/eak2000.md); EAK 2000 has no wall rules here (its clause could not be found).
!>
!> Conventions. Angles in DEGREES at the interface (theta is returned in radians); SI:
!> unit weights kN/m3, lengths m, thrusts kN/m, moments kNm/m; alpha = ag/g.
!> kv is SIGNED: kv > 0 is an upward inertia force (the soil is lighter), so the effective
!> gravity is g (1 - kv) and tan(theta) = kh/(1 - kv); EN's "1 -+ kv" pairs are both
!> covered by calling with +kv and -kv. psi is the inclination of the back face of the
!> wall to the horizontal, 90 = vertical; psi < 90 means that the top of the back face is
!> set back from its heel, away from the backfill, so that soil rests on the back face;
!> psi > 90 means that the back face overhangs the backfill. beta is the slope of the
!> backfill surface, > 0 rising away from the wall. H is the vertical height of the back
!> face. Thrusts act on the back face, inclined at delta to its normal.
!>
!> Mononobe-Okabe (planar wedge). Design angles phi_d = atan(tan(phi)/gamma_phi),
!> delta_d = atan(tan(delta)/gamma_phi) (Annex E(4)). The thrust is
!> E = 1/2 gamma* (1 - kv) K H^2 (E.1) with
!>   active (E.2, beta <= phi_d - theta):
!>     K = sin^2(psi + phi_d - theta) / { cos(theta) sin^2(psi) sin(psi - theta - delta_d)
!>         [1 + sqrt(sin(phi_d + delta_d) sin(phi_d - beta - theta)
!>                   / (sin(psi - theta - delta_d) sin(psi + beta)))]^2 },
!>   active beyond the limit (E.3, beta > phi_d - theta): EN prints
!>     K = sin^2(psi + phi_d - theta) / (cos(theta) sin^2(psi) sin(psi - theta - delta_d));
!>     no wedge behind the wall is in equilibrium there (the backfill slope itself fails
!>     under the seismic load), so this module reports SEISPULSE_NO_SOLUTION and hands
!>     the E.3 number over separately (`k_e3`) for users who need EN's value;
!>   passive (inertia directed away from the wall), with wall friction:
!>     K = sin^2(psi + theta - phi_d) / { cos(theta) sin^2(psi) sin(psi + theta + delta_d)
!>         [1 - sqrt(sin(phi_d + delta_d) sin(phi_d + beta - theta)
!>                   / (sin(psi + beta) sin(psi + theta + delta_d)))]^2 }.
!> [TEXT ERROR?] EN 1998-5 E.4 (delta_d = 0) as transcribed by two sources has the
!> numerator sin^2(psi + phi_d - theta). A brute-force planar-wedge search (limit
!> equilibrium over the angle of the failure plane, wall reaction at delta_d to the wall
!> normal, gravity g (1 - kv), inertia kh g) gives sin^2(psi + theta - phi_d): the two
!> agree for psi = 90 only (and only the latter reduces to Coulomb at kh = kv = 0 for an
!> inclined wall). test/python/test_codes.py runs that search over psi = 80..110,
!> beta = -25..25, delta = 0 and 2/3 phi, phi = 30 and 38, kh = 0 and 0.2, kv = +-0.1
!> (test/test_codes.f90 repeats it on 5 cases): E.2 and the passive form above match it
!> to 1e-9 (relative) wherever they are defined, and where a condition below fails the
!> wedge has no critical (interior, P > 0) wedge either; the tests also cover backs
!> flatter than phi_d (psi = 25..40 deg, where the square root exceeds 1).
!> Conditions (each failure is SEISPULSE_NO_SOLUTION with a message saying why):
!>   active: psi - theta - delta_d > 0; beta <= phi_d - theta (else E.3, above);
!>     psi + phi_d - theta < 180 (else the wedge maximum lies on the overhanging back
!>     face itself, not inside the soil, and E.2 does not apply);
!>   passive: psi + theta + delta_d < 180; phi_d + beta - theta >= 0 (else the slope in
!>     front of the wall fails under the inertia); psi + phi_d + beta + delta_d < 180
!>     (else no planar wedge limits the resistance: K unbounded). The passive K is
!>     evaluated in the equivalent form (1 + root)^2 sin^2(psi + beta) sin(psi + theta +
!>     delta_d)/(cos theta sin^2 psi sin^2(psi + phi_d + beta + delta_d)), which stays
!>     finite where the square root reaches 1 (psi + theta = phi_d).
!> The planar passive wedge is the classical Coulomb one: with wall friction delta_d
!> above about phi_d/3 it overestimates the passive resistance (log-spiral surfaces give
!> less); this is EN's model, not a correction of it.
module seispulse_codes
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_NO_SOLUTION, &
                                set_error
    use seispulse_checks, only: outside, check_spectrum_periods
    use seispulse_optval, only: optval
    use seispulse_format, only: real_str, real_str_len, int_str
    use seispulse_special, only: pi
    use seispulse_eak2000, only: EAK_ZONES_2003
    implicit none
    private

    public :: ec8_seismic_coefficients, ec8_vertical_ratio, ec8_r_factor
    public :: mononobe_okabe, ec8_thrust_t, ec8_thrust, westergaard_pressure
    public :: ec8_rigid_thrust, seed_whitman_increment, wood_thrust
    public :: ec8_ground_parameters, ec8_damping_correction, ec8_check_damping, &
              ec8_elastic_spectrum, ec8_design_spectrum, ec8_reference_pga, ec8_design_ag
    public :: EC8_WALL_GRAVITY_300, EC8_WALL_GRAVITY_200, EC8_WALL_RESTRAINED
    public :: WATER_DRY, WATER_IMPERVIOUS, WATER_PERMEABLE
    public :: EC8_SPECTRUM_TYPE_1, EC8_SPECTRUM_TYPE_2
    public :: EC8_GROUND_A, EC8_GROUND_B, EC8_GROUND_C, EC8_GROUND_D, EC8_GROUND_E
    public :: EC8_ANNEX_RECOMMENDED, EC8_ANNEX_GR

    !> EN 1998-5 Table 7.1, wall types and their r.
    integer, parameter :: EC8_WALL_GRAVITY_300 = 1 !! free gravity wall, dr <= 300 alpha S mm: 2
    integer, parameter :: EC8_WALL_GRAVITY_200 = 2 !! free gravity wall, dr <= 200 alpha S mm: 1.5
    !> flexural RC walls, anchored or braced walls, RC walls on vertical piles, restrained
    !> basement walls, bridge abutments: r = 1
    integer, parameter :: EC8_WALL_RESTRAINED = 3

    !> EN 1998-5 Annex E(5)-(7): where the water table is.
    integer, parameter :: WATER_DRY = 1         !! dry backfill, or water table below the wall
    integer, parameter :: WATER_IMPERVIOUS = 2  !! dynamically impervious soil below the water table
    integer, parameter :: WATER_PERMEABLE = 3   !! highly permeable soil below the water table

    !> EN 1998-1 §3.2.2.2: Type 1 (surface-wave magnitude Ms > 5.5), Type 2 (Ms <= 5.5).
    integer, parameter :: EC8_SPECTRUM_TYPE_1 = 1
    integer, parameter :: EC8_SPECTRUM_TYPE_2 = 2
    !> EN 1998-1 Table 3.1 ground types A..E.
    integer, parameter :: EC8_GROUND_A = 1, EC8_GROUND_B = 2, EC8_GROUND_C = 3, &
                          EC8_GROUND_D = 4, EC8_GROUND_E = 5
    !> National Annexes to EN 1998-1 (doc/codes.md section 1): EN's recommended values
    !> (no seismic zones: the user gives ag) or the Greek National Annex (zones Z1..Z3).
    integer, parameter :: EC8_ANNEX_RECOMMENDED = 0
    integer, parameter :: EC8_ANNEX_GR = 1

    real(dp), parameter :: deg = pi/180.0_dp  !! radians per degree
    real(dp), parameter :: big = huge(1.0_dp)

    !> EN 1998-1 Tables 3.2 (Type 1) and 3.3 (Type 2), recommended values, ground A..E.
    real(dp), parameter :: tab_s(5, 2) = reshape([1.00_dp, 1.20_dp, 1.15_dp, 1.35_dp, 1.40_dp, &
        1.00_dp, 1.35_dp, 1.50_dp, 1.80_dp, 1.60_dp], [5, 2])
    real(dp), parameter :: tab_tb(5, 2) = reshape([0.15_dp, 0.15_dp, 0.20_dp, 0.20_dp, 0.15_dp, &
        0.05_dp, 0.05_dp, 0.10_dp, 0.10_dp, 0.05_dp], [5, 2])
    real(dp), parameter :: tab_tc(5, 2) = reshape([0.40_dp, 0.50_dp, 0.60_dp, 0.80_dp, 0.50_dp, &
        0.25_dp, 0.25_dp, 0.25_dp, 0.30_dp, 0.25_dp], [5, 2])
    real(dp), parameter :: tab_td(5, 2) = reshape([2.0_dp, 2.0_dp, 2.0_dp, 2.0_dp, 2.0_dp, &
        1.2_dp, 1.2_dp, 1.2_dp, 1.2_dp, 1.2_dp], [5, 2])

    !> Outcome of the Mononobe-Okabe core (private).
    integer, parameter :: MO_OK = 0, MO_BEYOND_LIMIT = 1, MO_WALL_TOO_FLAT = 2, &
                          MO_OVERHANG = 3, MO_SLOPE_UNSTABLE = 4, MO_UNBOUNDED = 5, &
                          MO_PASSIVE_GEOMETRY = 6

    !> Thrust on a yielding wall, EN 1998-5 Annex E (E.1 with the water terms). Heights
    !> are measured vertically above the base of the wall (m).
    type :: ec8_thrust_t
        real(dp) :: k = 0.0_dp          !! active K (E.2) with the theta of the water case
        real(dp) :: theta = 0.0_dp      !! seismic angle theta, radians
        real(dp) :: e_soil = 0.0_dp     !! soil thrust 1/2 gamma* (1 - kv) K H^2, kN/m (E.1)
        real(dp) :: e_static = 0.0_dp   !! static part 1/2 gamma* K_static H^2, kN/m
        real(dp) :: e_dynamic = 0.0_dp  !! e_soil - e_static, kN/m (< 0 possible when kv > 0)
        real(dp) :: e_ws = 0.0_dp       !! hydrostatic 1/2 gamma_w H^2 (water cases 2, 3), kN/m
        real(dp) :: e_wd = 0.0_dp       !! hydrodynamic thrust 7/12 kh gamma_w H^2 (case 3), kN/m
        real(dp) :: total = 0.0_dp      !! e_soil + e_ws + e_wd, kN/m
        real(dp) :: z_static = 0.0_dp   !! H/3, m
        real(dp) :: z_dynamic = 0.0_dp  !! H/2, m
        real(dp) :: z_ws = 0.0_dp       !! H/3, m
        real(dp) :: z_wd = 0.0_dp       !! 0.4 H, m
        real(dp) :: z_total = 0.0_dp    !! m_base/total (0 when total = 0), m
        real(dp) :: m_base = 0.0_dp     !! sum of thrust x height, kNm/m (thrusts taken horizontal)
        real(dp) :: k_static = 0.0_dp   !! static (Coulomb, kh = kv = 0) active K, same gamma_phi
    end type ec8_thrust_t

contains

    ! ------------------------------------------------------------- seismic coefficients

    !> EN 1998-5 §7.3.2.2: kh = alpha S/r (7.1); kv = 0.5 kh if avg/ag > 0.6 (7.2), else
    !> 0.33 kh (7.3). kv is returned as a positive magnitude: check both signs (call the
    !> thrust routines with +kv and -kv). r may be any value in [1, 2]: Table 7.1 has
    !> 1, 1.5 and 2 (ec8_r_factor); values in between are accepted for National Annexes
    !> and interpolation, which EN itself does not provide.
    !> r and vertical_ratio are optional (defaults as Python's `codes.seismic_coefficients`);
    !> when omitted, pass kh, kv and stat by keyword.
    pure subroutine ec8_seismic_coefficients(alpha, s, r, vertical_ratio, kh, kv, stat, errmsg)
        real(dp), intent(in) :: alpha           !! ag/g (ag = gamma_I agR, on ground type A), >= 0
        real(dp), intent(in) :: s               !! soil factor S (EN 1998-1 Tables 3.2/3.3), > 0
        !> wall factor r (Table 7.1), in [1, 2]; default 1 (as Python's
        !> `codes.seismic_coefficients`)
        real(dp), intent(in), optional :: r
        !> avg/ag (EN 1998-1 Table 3.4), >= 0; default 0.90 (Type 1 spectrum,
        !> ec8_vertical_ratio(EC8_SPECTRUM_TYPE_1))
        real(dp), intent(in), optional :: vertical_ratio
        real(dp), intent(out) :: kh             !! horizontal seismic coefficient (dimensionless)
        real(dp), intent(out) :: kv             !! vertical coefficient, magnitude (dimensionless)
        integer, intent(out) :: stat            !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: r_in, ratio_in
        r_in = optval(r, 1.0_dp)
        ratio_in = optval(vertical_ratio, ec8_vertical_ratio(EC8_SPECTRUM_TYPE_1))
        kh = 0.0_dp
        kv = 0.0_dp
        stat = SEISPULSE_SUCCESS
        if (outside(alpha, 0.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'alpha = '//real_str(alpha)// &
                           ': ag/g must be finite and >= 0')
        else if (outside(s, 0.0_dp, big, .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 's = '//real_str(s)// &
                           ': the soil factor S must be finite and > 0')
        else if (outside(r_in, 1.0_dp, 2.0_dp, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'r = '//real_str(r_in)// &
                           ': must lie in [1, 2] (EN 1998-5 Table 7.1: 1, 1.5, 2)')
        else if (outside(ratio_in, 0.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'vertical_ratio = '// &
                           real_str(ratio_in)//': avg/ag must be finite and >= 0 '// &
                           '(ec8_vertical_ratio gives NaN for an unknown spectrum type)')
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        kh = alpha*s/r_in                                ! (7.1)
        if (ratio_in > 0.6_dp) then
            kv = 0.5_dp*kh                               ! (7.2)
        else
            kv = 0.33_dp*kh                              ! (7.3)
        end if
    end subroutine ec8_seismic_coefficients

    !> avg/ag of EN 1998-1 Table 3.4 (recommended): 0.90 for Type 1, 0.45 for Type 2.
    !> NaN for any other spectrum type (ec8_seismic_coefficients then refuses it).
    elemental real(dp) function ec8_vertical_ratio(spectrum_type) result(ratio)
        integer, intent(in) :: spectrum_type  !! EC8_SPECTRUM_TYPE_1 or EC8_SPECTRUM_TYPE_2
        select case (spectrum_type)
        case (EC8_SPECTRUM_TYPE_1)
            ratio = 0.90_dp
        case (EC8_SPECTRUM_TYPE_2)
            ratio = 0.45_dp
        case default
            ratio = ieee_value(1.0_dp, ieee_quiet_nan)
        end select
    end function ec8_vertical_ratio

    !> r of EN 1998-5 Table 7.1 for a wall type EC8_WALL_*.
    pure subroutine ec8_r_factor(wall_type, r, stat, errmsg)
        integer, intent(in) :: wall_type  !! EC8_WALL_GRAVITY_300, _GRAVITY_200, _RESTRAINED
        real(dp), intent(out) :: r        !! the factor r (dimensionless); 0 on error
        integer, intent(out) :: stat      !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming wall_type
        stat = SEISPULSE_SUCCESS
        select case (wall_type)
        case (EC8_WALL_GRAVITY_300)
            r = 2.0_dp
        case (EC8_WALL_GRAVITY_200)
            r = 1.5_dp
        case (EC8_WALL_RESTRAINED)
            r = 1.0_dp
        case default
            r = 0.0_dp
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'wall_type = '// &
                           int_str(wall_type)//': must be 1 (free gravity wall, dr <= 300 '// &
                           'alpha S mm), 2 (dr <= 200 alpha S mm) or 3 (restrained wall)')
        end select
    end subroutine ec8_r_factor

    ! ------------------------------------------------------------- Mononobe-Okabe

    !> Mononobe-Okabe earth-pressure coefficient K and seismic angle theta (EN 1998-5
    !> Annex E, E.2 active, the passive form with wall friction; see the module notes).
    !> tan(theta) = kh/(1 - kv) with kv signed (dry backfill; ec8_thrust handles water).
    !> SEISPULSE_NO_SOLUTION when no planar wedge is in equilibrium (then k = 0, theta is
    !> set, and for an active backfill steeper than phi_d - theta `k_e3` holds EN's E.3).
    !> The five arguments after kv are optional with the defaults of Python's
    !> `codes.mononobe_okabe` (a vertical wall, smooth, level dry backfill, active,
    !> characteristic values); when one is omitted, pass k, theta and stat by keyword:
    !> `call mononobe_okabe(30.0_dp, 0.1_dp, 0.0_dp, k=k, theta=theta, stat=stat)`.
    pure subroutine mononobe_okabe(phi_deg, kh, kv, delta_deg, psi_deg, beta_deg, passive, &
                                   gamma_phi, k, theta, stat, errmsg, k_e3)
        real(dp), intent(in) :: phi_deg    !! soil friction angle phi', degrees, in (0, 90)
        real(dp), intent(in) :: kh         !! horizontal seismic coefficient, finite, >= 0
        real(dp), intent(in) :: kv         !! vertical seismic coefficient, signed (> 0 upward), < 1
        !> soil-wall friction angle, degrees, in [0, phi_deg]; default 0
        real(dp), intent(in), optional :: delta_deg
        !> back face to horizontal, degrees, (0, 180); default 90 (vertical)
        real(dp), intent(in), optional :: psi_deg
        !> backfill slope, degrees, in (-90, 90), > 0 rising; default 0 (level)
        real(dp), intent(in), optional :: beta_deg
        !> .true.: passive coefficient; .false.: active; default .false.
        logical, intent(in), optional :: passive
        !> partial factor on tan(phi') and tan(delta), >= 1; default 1 (characteristic)
        real(dp), intent(in), optional :: gamma_phi
        real(dp), intent(out) :: k         !! K (dimensionless): thrust = 1/2 gamma (1 - kv) K H^2
        real(dp), intent(out) :: theta     !! seismic angle theta = atan(kh/(1 - kv)), radians
        integer, intent(out) :: stat       !! SEISPULSE_SUCCESS, _INVALID_INPUT or _NO_SOLUTION
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp), intent(out), optional :: k_e3  !! E.3 when beta > phi_d - theta (active), else 0
        real(dp) :: phi, delta, psi, beta, ke3, delta_in, psi_in, beta_in, gphi_in
        integer :: code
        k = 0.0_dp
        theta = 0.0_dp
        if (present(k_e3)) k_e3 = 0.0_dp
        delta_in = optval(delta_deg, 0.0_dp)
        psi_in = optval(psi_deg, 90.0_dp)
        beta_in = optval(beta_deg, 0.0_dp)
        gphi_in = optval(gamma_phi, 1.0_dp)
        call mo_check(phi_deg, kh, kv, delta_in, psi_in, beta_in, gphi_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call design_angles(phi_deg, delta_in, psi_in, beta_in, gphi_in, phi, delta, psi, beta)
        theta = atan2(kh, 1.0_dp - kv)                   ! Annex E(5): tan theta = kh/(1 - kv)
        call mo_core(phi, delta, psi, beta, theta, optval(passive, .false.), k, ke3, code)
        if (code /= MO_OK) then
            call mo_fail(code, phi, delta, psi, beta, theta, ke3, '', stat, errmsg)
            if (present(k_e3) .and. code == MO_BEYOND_LIMIT) k_e3 = ke3
        end if
    end subroutine mononobe_okabe

    !> Argument checks shared by mononobe_okabe and ec8_thrust.
    pure subroutine mo_check(phi_deg, kh, kv, delta_deg, psi_deg, beta_deg, gamma_phi, stat, &
                             errmsg)
        real(dp), intent(in) :: phi_deg, kh, kv, delta_deg, psi_deg, beta_deg, gamma_phi
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (outside(phi_deg, 0.0_dp, 90.0_dp, .true., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'phi_deg = '// &
                           real_str(phi_deg)//': the friction angle must lie in (0, 90) degrees')
        else if (outside(delta_deg, 0.0_dp, phi_deg, .false., .false.)) then
            ! EN: delta_d <= phi_d; the same gamma_phi reduces both, so delta <= phi
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'delta_deg = '// &
                           real_str(delta_deg)//': the wall friction angle must lie in [0, '// &
                           'phi_deg] = [0, '//real_str(phi_deg)//'] degrees')
        else if (outside(psi_deg, 0.0_dp, 180.0_dp, .true., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'psi_deg = '// &
                           real_str(psi_deg)//': the inclination of the back face must lie in '// &
                           '(0, 180) degrees (90 = vertical)')
        else if (outside(beta_deg, -90.0_dp, 90.0_dp, .true., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'beta_deg = '// &
                           real_str(beta_deg)//': the backfill slope must lie in (-90, 90) degrees')
        else if (outside(psi_deg + beta_deg, 0.0_dp, 180.0_dp, .true., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'beta_deg = '// &
                           real_str(beta_deg)//': psi_deg + beta_deg = '// &
                           real_str(psi_deg + beta_deg)//' must lie in (0, 180) degrees (else '// &
                           'the ground surface passes below the heel or above the top of the wall)')
        else if (outside(kh, 0.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kh = '//real_str(kh)// &
                           ': must be finite and >= 0')
        else if (outside(kv, -big, 1.0_dp, .false., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kv = '//real_str(kv)// &
                           ': must be finite and < 1 (signed, > 0 upward; the effective '// &
                           'gravity g (1 - kv) must stay > 0)')
        else if (outside(gamma_phi, 1.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'gamma_phi = '// &
                           real_str(gamma_phi)//': the partial factor on tan(phi) must be '// &
                           'finite and >= 1 (1 = characteristic; EN 1998-5 recommends 1.25, '// &
                           'not verified: check the National Annex)')
        end if
    end subroutine mo_check

    !> Radians, with phi and delta reduced by gamma_phi (Annex E(4)).
    pure subroutine design_angles(phi_deg, delta_deg, psi_deg, beta_deg, gamma_phi, phi, delta, &
                                  psi, beta)
        real(dp), intent(in) :: phi_deg, delta_deg, psi_deg, beta_deg, gamma_phi
        real(dp), intent(out) :: phi, delta, psi, beta
        phi = phi_deg*deg
        delta = delta_deg*deg
        if (gamma_phi > 1.0_dp) then     ! gamma_phi = 1 keeps the angles exactly
            phi = atan(tan(phi)/gamma_phi)
            delta = atan(tan(delta)/gamma_phi)
        end if
        psi = psi_deg*deg
        beta = beta_deg*deg
    end subroutine design_angles

    !> K for design angles in radians; code MO_OK or the reason there is none. ke3 is
    !> EN's E.3 whenever psi - theta - delta > 0 (active), else 0.
    pure subroutine mo_core(phi, delta, psi, beta, theta, passive, k, ke3, code)
        real(dp), intent(in) :: phi, delta, psi, beta, theta
        logical, intent(in) :: passive
        real(dp), intent(out) :: k, ke3
        integer, intent(out) :: code
        real(dp) :: s1, a, root
        k = 0.0_dp
        ke3 = 0.0_dp
        code = MO_OK
        if (.not. passive) then
            s1 = psi - theta - delta
            if (.not. (s1 > 0.0_dp)) then
                code = MO_WALL_TOO_FLAT
                return
            end if
            ke3 = sin(psi + phi - theta)**2/(cos(theta)*sin(psi)**2*sin(s1))   ! E.3
            a = phi - beta - theta
            if (a < 0.0_dp) then
                code = MO_BEYOND_LIMIT
            else if (.not. (psi + phi - theta < pi)) then
                code = MO_OVERHANG
            else
                root = sqrt(sin(phi + delta)*sin(a)/(sin(s1)*sin(psi + beta)))
                k = ke3/(1.0_dp + root)**2                                   ! E.2
            end if
        else
            s1 = psi + theta + delta
            a = phi + beta - theta
            if (.not. (s1 < pi)) then
                code = MO_PASSIVE_GEOMETRY
            else if (a < 0.0_dp) then
                code = MO_SLOPE_UNSTABLE
            else
                if (.not. (psi + phi + beta + delta < pi)) then
                    code = MO_UNBOUNDED
                else
                    ! E.4 generalised: sin^2(psi + theta - phi)/(cos theta sin^2 psi sin(s1)
                    ! (1 - root)^2). Since 1 - root^2 = sin(psi + theta - phi)
                    ! sin(psi + phi + beta + delta)/(sin(psi + beta) sin(s1)), the factor
                    ! sin(psi + theta - phi) cancels: the form below has no 0/0 at
                    ! psi + theta = phi (root = 1 there, K finite) and no cancellation in
                    ! 1 - root; its only pole, psi + phi + beta + delta = 180, is the
                    ! geometric limit of the passive wedge.
                    root = sqrt(sin(phi + delta)*sin(a)/(sin(psi + beta)*sin(s1)))
                    k = (1.0_dp + root)**2*sin(psi + beta)**2*sin(s1)/ &
                        (cos(theta)*sin(psi)**2*sin(psi + phi + beta + delta)**2)
                end if
            end if
        end if
    end subroutine mo_core

    !> The SEISPULSE_NO_SOLUTION message of a failed mo_core (angles in degrees, rounded to
    !> 1e-4 deg; messages stay under the 256 characters of the f2py layer).
    pure subroutine mo_fail(code, phi, delta, psi, beta, theta, ke3, context, stat, errmsg)
        integer, intent(in) :: code
        real(dp), intent(in) :: phi, delta, psi, beta, theta, ke3
        character(len=*), intent(in) :: context  !! e.g. ' (impervious soil)'
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        character(len=:), allocatable :: th
        th = 'theta = '//ang(theta)//' deg'//context
        select case (code)
        case (MO_BEYOND_LIMIT)
            if (phi - theta < 0.0_dp .and. .not. (beta > 0.0_dp)) then
                ! the inertia alone, not the slope, leaves no wedge in equilibrium
                call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'kh: '//th// &
                               ' exceeds phi_d = '//ang(phi)//' deg: no soil wedge is in '// &
                               'equilibrium even behind a level backfill, no finite active '// &
                               'thrust (EN 1998-5 E.3 gives K = '// &
                               real_str(anint(ke3*1.0e6_dp)/1.0e6_dp)//')')
                return
            end if
            call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'beta_deg = '//ang(beta)// &
                           ': the backfill slope exceeds phi_d - theta = '//ang(phi - theta)// &
                           ' deg ('//th//'): no soil wedge is in equilibrium, no finite active '// &
                           'thrust (EN 1998-5 E.3 gives K = '// &
                           real_str(anint(ke3*1.0e6_dp)/1.0e6_dp)//')')
        case (MO_WALL_TOO_FLAT)
            call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'psi_deg = '//ang(psi)// &
                           ': psi - theta - delta_d = '//ang(psi - theta - delta)//' deg <= 0 ('// &
                           th//'): the back face is too flat for an active Coulomb wedge')
        case (MO_OVERHANG)
            call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'psi_deg = '//ang(psi)// &
                           ': psi + phi_d - theta = '//ang(psi + phi - theta)//' deg >= 180 ('// &
                           th//'): the wedge maximum lies on the overhanging back face, '// &
                           'not in the soil; E.2 does not apply')
        case (MO_SLOPE_UNSTABLE)
            call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'beta_deg = '//ang(beta)// &
                           ': phi_d + beta - theta = '//ang(phi + beta - theta)//' deg < 0 ('// &
                           th//'): the ground in front of the wall slides, no passive wedge '// &
                           'is in equilibrium')
        case (MO_UNBOUNDED)
            call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'psi_deg = '//ang(psi)// &
                           ': psi + phi_d + beta + delta_d = '// &
                           ang(psi + phi + beta + delta)//' deg >= 180 ('//th// &
                           '): no planar wedge limits the passive resistance (K unbounded)')
        case default
            call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'psi_deg = '//ang(psi)// &
                           ': psi + theta + delta_d = '//ang(psi + theta + delta)// &
                           ' deg >= 180 ('// &
                           th//'): no passive Coulomb wedge exists for this geometry')
        end select
    end subroutine mo_fail

    !> An angle in radians as degrees for messages, rounded to 1e-4.
    pure function ang(x) result(text)
        real(dp), intent(in) :: x
        character(len=real_str_len(anint(x/deg*1.0e4_dp)/1.0e4_dp)) :: text
        text = real_str(anint(x/deg*1.0e4_dp)/1.0e4_dp)
    end function ang

    ! ------------------------------------------------------------- thrust on yielding walls

    !> Active seismic thrust on a yielding wall, EN 1998-5 Annex E: E.1 with the water
    !> cases of Annex E(5)-(7) (equation numbers E.5-E.13 not verified):
    !>  WATER_DRY:        gamma* = gamma,           tan theta = kh/(1 - kv);
    !>  WATER_IMPERVIOUS: gamma* = gamma - gamma_w, tan theta = gamma/(gamma - gamma_w) kh/(1 - kv),
    !>                    plus the hydrostatic thrust E_ws = 1/2 gamma_w H^2 at H/3;
    !>  WATER_PERMEABLE:  gamma* = gamma - gamma_w,
    !>                    tan theta = gamma_d/(gamma - gamma_w) kh/(1 - kv),
    !>                    plus E_ws and the hydrodynamic E_wd = 7/12 kh gamma_w H^2 (E.13) at
    !>                    0.4 H (the resultant of Westergaard's 7/8 kh gamma_w sqrt(H z)).
    !> The water table is at the ground surface (water height H) in cases 2 and 3.
    !> E_soil = 1/2 gamma* (1 - kv) K H^2 (the same effective gravity as theta). It is split
    !> into the static Coulomb thrust E_st = 1/2 gamma* K_static H^2 (kh = kv = 0, same
    !> gamma_phi) at H/3 and the dynamic increment E_soil - E_st at H/2 (the usual EN 1998-5
    !> reading, §7.3.2.3(?), clause not verified; for walls rotating about the toe EN puts
    !> the increment at the static point instead - not done here). Active thrust only; for
    !> passive thrusts call mononobe_okabe. m_base sums thrust x height with every thrust
    !> taken as a horizontal force (exact for a vertical back and delta = 0; resolve the
    !> inclined thrust yourself otherwise).
    !> delta_deg, psi_deg, beta_deg and the four arguments after kv are optional with the
    !> defaults of Python's `codes.earth_thrust`; when one is omitted, pass the arguments
    !> after it by keyword: `call ec8_thrust(6.0_dp, 20.0_dp, 30.0_dp, kh=0.1_dp, kv=0.05_dp,
    !> res=res, stat=stat)` is a dry backfill behind a smooth vertical wall.
    pure subroutine ec8_thrust(height, gamma, phi_deg, delta_deg, psi_deg, beta_deg, kh, kv, &
                               water_case, gamma_w, gamma_d, gamma_phi, res, stat, errmsg)
        real(dp), intent(in) :: height     !! vertical height H of the back face, m, > 0
        real(dp), intent(in) :: gamma      !! soil unit weight (saturated below water), kN/m3, > 0
        real(dp), intent(in) :: phi_deg    !! friction angle phi', degrees, (0, 90)
        !> soil-wall friction angle, degrees, [0, phi_deg]; default 0
        real(dp), intent(in), optional :: delta_deg
        !> back face to the horizontal, degrees, (0, 180); default 90 (vertical)
        real(dp), intent(in), optional :: psi_deg
        !> backfill slope, degrees, (-90, 90), > 0 rising; default 0 (level)
        real(dp), intent(in), optional :: beta_deg
        real(dp), intent(in) :: kh         !! horizontal seismic coefficient, >= 0
        real(dp), intent(in) :: kv         !! vertical seismic coefficient, signed (> 0 upward), < 1
        !> WATER_DRY, WATER_IMPERVIOUS or WATER_PERMEABLE; default WATER_DRY
        integer, intent(in), optional :: water_case
        !> water unit weight, kN/m3, (0, gamma) (cases 2, 3); default 9.81
        real(dp), intent(in), optional :: gamma_w
        !> dry unit weight of the soil, kN/m3, > 0; required for WATER_PERMEABLE, unused
        !> otherwise (default 0)
        real(dp), intent(in), optional :: gamma_d
        !> partial factor on tan(phi') and tan(delta), >= 1; default 1 (characteristic)
        real(dp), intent(in), optional :: gamma_phi
        type(ec8_thrust_t), intent(out) :: res  !! thrusts kN/m, heights m, moment kNm/m
        integer, intent(out) :: stat       !! SEISPULSE_SUCCESS, _INVALID_INPUT or _NO_SOLUTION
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: phi, delta, psi, beta, gstar, ratio, ke3, theta
        integer :: code
        character(len=:), allocatable :: context
        real(dp) :: delta_in, psi_in, beta_in, gamma_w_in, gamma_d_in, gphi_in
        integer :: water
        stat = SEISPULSE_SUCCESS
        delta_in = optval(delta_deg, 0.0_dp)
        psi_in = optval(psi_deg, 90.0_dp)
        beta_in = optval(beta_deg, 0.0_dp)
        water = optval(water_case, WATER_DRY)
        gamma_w_in = optval(gamma_w, 9.81_dp)
        gamma_d_in = optval(gamma_d, 0.0_dp)
        gphi_in = optval(gamma_phi, 1.0_dp)
        if (outside(height, 0.0_dp, big, .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'height = '//real_str(height)// &
                           ': the wall height H (m) must be finite and > 0')
        else if (outside(gamma, 0.0_dp, big, .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'gamma = '//real_str(gamma)// &
                           ': the unit weight (kN/m3) must be finite and > 0')
        else if (water < WATER_DRY .or. water > WATER_PERMEABLE) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'water_case = '// &
                           int_str(water)//': must be 1 (dry), 2 (impervious, below '// &
                           'the water table) or 3 (permeable, below the water table)')
        else if (water /= WATER_DRY .and. outside(gamma_w_in, 0.0_dp, gamma, .true., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'gamma_w = '// &
                           real_str(gamma_w_in)//': the unit weight of water (kN/m3) must '// &
                           'lie in (0, gamma) = (0, '//real_str(gamma)//') below the water table')
        else if (water == WATER_PERMEABLE .and. &
                 outside(gamma_d_in, 0.0_dp, big, .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'gamma_d = '// &
                           real_str(gamma_d_in)//': the dry unit weight (kN/m3) must be finite '// &
                           'and > 0 for permeable soil')
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        call mo_check(phi_deg, kh, kv, delta_in, psi_in, beta_in, gphi_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call design_angles(phi_deg, delta_in, psi_in, beta_in, gphi_in, phi, delta, psi, beta)

        select case (water)
        case (WATER_DRY)
            gstar = gamma
            ratio = 1.0_dp
            context = ''
        case (WATER_IMPERVIOUS)
            gstar = gamma - gamma_w_in
            ratio = gamma/gstar                          ! E.9? (not verified)
            context = ', impervious soil'
        case default
            gstar = gamma - gamma_w_in
            ratio = gamma_d_in/gstar                     ! E.12? (not verified)
            context = ', permeable soil'
        end select
        theta = atan2(ratio*kh, 1.0_dp - kv)
        res%theta = theta
        call mo_core(phi, delta, psi, beta, theta, .false., res%k, ke3, code)
        if (code /= MO_OK) then
            res%k = 0.0_dp
            call mo_fail(code, phi, delta, psi, beta, theta, ke3, context, stat, errmsg)
            return
        end if
        call mo_core(phi, delta, psi, beta, 0.0_dp, .false., res%k_static, ke3, code)
        if (code /= MO_OK) then
            res%k = 0.0_dp
            res%k_static = 0.0_dp
            call mo_fail(code, phi, delta, psi, beta, 0.0_dp, ke3, ', static part', &
                         stat, errmsg)
            return
        end if

        res%e_soil = 0.5_dp*gstar*(1.0_dp - kv)*res%k*height**2      ! E.1, soil term
        res%e_static = 0.5_dp*gstar*res%k_static*height**2
        res%e_dynamic = res%e_soil - res%e_static
        if (water /= WATER_DRY) res%e_ws = 0.5_dp*gamma_w_in*height**2
        if (water == WATER_PERMEABLE) res%e_wd = 7.0_dp/12.0_dp*kh*gamma_w_in*height**2   ! E.13
        res%total = res%e_soil + res%e_ws + res%e_wd
        res%z_static = height/3.0_dp
        res%z_dynamic = 0.5_dp*height
        res%z_ws = height/3.0_dp
        res%z_wd = 0.4_dp*height
        res%m_base = res%e_static*res%z_static + res%e_dynamic*res%z_dynamic + &
                     res%e_ws*res%z_ws + res%e_wd*res%z_wd
        if (res%total > 0.0_dp) res%z_total = res%m_base/res%total
    end subroutine ec8_thrust

    !> Hydrodynamic pressure of free water on the outer face of a wall, Westergaard as in
    !> EN 1998-5 Annex E (E.14, equation number not verified; UFC 3-220-20 eq. 4-19):
    !> q(z) = 7/8 kh gamma_w sqrt(h_water z), z the depth below the free water surface.
    !> Its resultant is 7/12 kh gamma_w h_water^2 at 0.4 h_water above the base. q acts
    !> in either direction (EN's +-); the magnitude is returned. Invalid input: q = NaN, and
    !> stat says why.
    pure subroutine westergaard_pressure(kh, gamma_w, h_water, z, q, stat, errmsg)
        real(dp), intent(in) :: kh        !! horizontal seismic coefficient, >= 0
        real(dp), intent(in) :: gamma_w   !! unit weight of water, kN/m3, > 0
        real(dp), intent(in) :: h_water   !! depth of the free water at the wall, m, > 0
        real(dp), intent(in) :: z(:)      !! depths below the free water surface, m, in [0, h_water]
        real(dp), intent(out) :: q(:)     !! pressures, kPa (size of z)
        integer, intent(out) :: stat  !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        integer :: st, i
        st = SEISPULSE_SUCCESS
        if (outside(kh, 0.0_dp, big, .false., .false.)) then
            call set_error(st, errmsg, SEISPULSE_INVALID_INPUT, 'kh = '//real_str(kh)// &
                           ': must be finite and >= 0')
        else if (outside(gamma_w, 0.0_dp, big, .true., .false.)) then
            call set_error(st, errmsg, SEISPULSE_INVALID_INPUT, 'gamma_w = '//real_str(gamma_w)// &
                           ': the unit weight of water (kN/m3) must be finite and > 0')
        else if (outside(h_water, 0.0_dp, big, .true., .false.)) then
            call set_error(st, errmsg, SEISPULSE_INVALID_INPUT, 'h_water = '//real_str(h_water)// &
                           ': the water depth (m) must be finite and > 0')
        else if (size(q) /= size(z)) then
            call set_error(st, errmsg, SEISPULSE_INVALID_INPUT, 'q: must have the size of z ('// &
                           int_str(size(z))//')')
        else
            do i = 1, size(z)
                if (outside(z(i), 0.0_dp, h_water, .false., .false.)) then
                    call set_error(st, errmsg, SEISPULSE_INVALID_INPUT, 'z('//int_str(i)// &
                                   ') = '//real_str(z(i))//': the depth must lie in [0, '// &
                                   'h_water] = [0, '//real_str(h_water)//'] m')
                    exit
                end if
            end do
        end if
        stat = st
        if (st /= SEISPULSE_SUCCESS) then
            q = ieee_value(1.0_dp, ieee_quiet_nan)
            return
        end if
        q = 0.875_dp*kh*gamma_w*sqrt(h_water*z)          ! E.14
    end subroutine westergaard_pressure

    ! ------------------------------------------------------------- non-yielding walls

    !> Rigid (completely restrained, non-yielding) wall, EN 1998-5 Annex E (rigid
    !> structures; clause/equation number, E.17?, not verified): dynamic increment
    !> thrust dP = alpha S gamma H^2 at H/2, for a vertical wall with horizontal backfill.
    !> Invalid input: thrust = z = NaN, and stat says why.
    pure subroutine ec8_rigid_thrust(alpha_s, gamma, height, thrust, z, stat, errmsg)
        real(dp), intent(in) :: alpha_s  !! alpha S = ag S/g (no r), >= 0
        real(dp), intent(in) :: gamma    !! unit weight of the soil, kN/m3, > 0
        real(dp), intent(in) :: height   !! wall height H, m, > 0
        real(dp), intent(out) :: thrust  !! dynamic thrust increment, kN/m
        real(dp), intent(out) :: z       !! its height above the base, m
        integer, intent(out) :: stat  !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        call simple_thrust('alpha_s', alpha_s, gamma, height, 1.0_dp, 0.5_dp, thrust, z, stat, &
                           errmsg)
    end subroutine ec8_rigid_thrust

    !> Seed & Whitman (1970) dynamic increment on a yielding wall, as quoted by UFC
    !> 3-220-20 eq. 4-17: dK = 3/4 kh, dP = 3/8 kh gamma H^2 at 0.6 H (vertical wall,
    !> horizontal backfill, delta = 0; proposed for kh up to about 0.4, not enforced).
    !> Seed & Whitman's kh is the peak ground acceleration over g; in an EN 1998-5 check
    !> it is the code's kh = alpha S/r of the yielding wall (seispulse_wall_table does so).
    !> Invalid input: thrust = z = NaN, and stat says why.
    pure subroutine seed_whitman_increment(kh, gamma, height, thrust, z, stat, errmsg)
        real(dp), intent(in) :: kh       !! horizontal seismic coefficient, >= 0
        real(dp), intent(in) :: gamma    !! unit weight of the soil, kN/m3, > 0
        real(dp), intent(in) :: height   !! wall height H, m, > 0
        real(dp), intent(out) :: thrust  !! dynamic thrust increment, kN/m
        real(dp), intent(out) :: z       !! its height above the base, m
        integer, intent(out) :: stat  !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        call simple_thrust('kh', kh, gamma, height, 0.375_dp, 0.6_dp, thrust, z, stat, errmsg)
    end subroutine seed_whitman_increment

    !> Wood (1973) non-yielding wall, as commonly quoted (UFC 3-220-20 eq. 4-18):
    !> dP = (ag S/g) gamma H^2 at 0.6 H, i.e. Wood's factor F_p taken as 1. Wood's own F_p
    !> depends on Poisson's ratio and on L/H (the distance to the next wall); the elastic
    !> solutions (seispulse_walls_vy, seispulse_walls_one_term) give it. Invalid input:
    !> thrust = z = NaN, and stat says why.
    pure subroutine wood_thrust(alpha_s, gamma, height, thrust, z, stat, errmsg)
        real(dp), intent(in) :: alpha_s  !! ground acceleration ag S/g (no r), >= 0
        real(dp), intent(in) :: gamma    !! unit weight of the soil, kN/m3, > 0
        real(dp), intent(in) :: height   !! wall height H, m, > 0
        real(dp), intent(out) :: thrust  !! dynamic thrust, kN/m
        real(dp), intent(out) :: z       !! its height above the base, m
        integer, intent(out) :: stat  !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        call simple_thrust('alpha_s', alpha_s, gamma, height, 1.0_dp, 0.6_dp, thrust, z, stat, &
                           errmsg)
    end subroutine wood_thrust

    !> thrust = factor a gamma H^2 at zfrac H, with the checks of the three rules above.
    pure subroutine simple_thrust(name, a, gamma, height, factor, zfrac, thrust, z, stat, errmsg)
        character(len=*), intent(in) :: name
        real(dp), intent(in) :: a, gamma, height, factor, zfrac
        real(dp), intent(out) :: thrust, z
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: st
        st = SEISPULSE_SUCCESS
        if (outside(a, 0.0_dp, big, .false., .false.)) then
            call set_error(st, errmsg, SEISPULSE_INVALID_INPUT, name//' = '//real_str(a)// &
                           ': must be finite and >= 0')
        else if (outside(gamma, 0.0_dp, big, .true., .false.)) then
            call set_error(st, errmsg, SEISPULSE_INVALID_INPUT, 'gamma = '//real_str(gamma)// &
                           ': the unit weight (kN/m3) must be finite and > 0')
        else if (outside(height, 0.0_dp, big, .true., .false.)) then
            call set_error(st, errmsg, SEISPULSE_INVALID_INPUT, 'height = '//real_str(height)// &
                           ': the wall height H (m) must be finite and > 0')
        end if
        stat = st
        if (st /= SEISPULSE_SUCCESS) then
            thrust = ieee_value(1.0_dp, ieee_quiet_nan)
            z = thrust
            return
        end if
        thrust = factor*a*gamma*height**2
        z = zfrac*height
    end subroutine simple_thrust

    ! ------------------------------------------------------------- EN 1998-1 spectra

    !> Reference peak ground acceleration a_gR on type A ground of a seismic zone of a
    !> National Annex to EN 1998-1 (doc/codes.md section 1). EC8_ANNEX_GR: zones 1, 2, 3
    !> (Z1, Z2, Z3) -> 0.16, 0.24, 0.36 g. [PRDA24] states that the Greek National Annex
    !> adopted the 2003 zonation map, three zones spanning 0.16-0.36 g; the middle value
    !> 0.24 g and the names Z1-Z3 are from press reports of the 2003 amendment (SECONDARY,
    !> doc/eak2000.md section 3). Only the zones are taken from the annex: the spectra keep
    !> EN's recommended S, TB, TC, TD, beta and eta. EC8_ANNEX_RECOMMENDED has no zones
    !> (EN leaves the map to the annexes) and is refused: give ag directly. The design
    !> ground acceleration is ag = gamma_I a_gR (EN 1998-1 3.2.1(3), not verified).
    !> agr is 0 on error (as the outputs of the spectra and ec8_ground_parameters).
    pure subroutine ec8_reference_pga(annex, zone, agr, stat, errmsg)
        integer, intent(in) :: annex          !! EC8_ANNEX_GR (EC8_ANNEX_RECOMMENDED is refused)
        integer, intent(in) :: zone           !! seismic zone, 1..3 for EC8_ANNEX_GR (Z1..Z3)
        real(dp), intent(out) :: agr          !! reference PGA a_gR on type A ground, g
        integer, intent(out) :: stat          !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        !> Greek National Annex zones Z1, Z2, Z3, g: the 2003 map of EAK 2000 ([PRDA24]:
        !> 0.16-0.36 g; 0.24 g and the names from press reports, SECONDARY)
        real(dp), parameter :: gr_agr(3) = EAK_ZONES_2003
        agr = 0.0_dp
        stat = SEISPULSE_SUCCESS
        select case (annex)
        case (EC8_ANNEX_GR)
            if (zone < 1 .or. zone > size(gr_agr)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'zone = '// &
                               int_str(zone)//': must be 1, 2 or 3 (Greek National Annex '// &
                               'zones Z1, Z2, Z3: 0.16, 0.24, 0.36 g)')
                return
            end if
            agr = gr_agr(zone)
        case (EC8_ANNEX_RECOMMENDED)
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'annex = '//int_str(annex)// &
                           ': the recommended values of EN 1998-1 have no seismic zones; '// &
                           'give ag, or annex = 1 (Greek National Annex)')
        case default
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'annex = '//int_str(annex)// &
                           ': must be 1 (Greek National Annex; 0, EN recommended, has no '// &
                           'zones: give ag)')
        end select
    end subroutine ec8_reference_pga

    !> The design ground acceleration ag = gamma_I a_gR on type A ground (g) of a spectrum,
    !> from ag given directly or from a seismic zone (EN 1998-1 3.2.1(3)); the one rule of
    !> every front end. "Not given": ag NaN, zone 0. Exactly one of ag and zone must be
    !> given. With ag: ag is already gamma_I a_gR, so importance must be 1 (any other value
    !> is refused: multiply ag yourself); annex is only checked (EC8_ANNEX_RECOMMENDED or
    !> EC8_ANNEX_GR); ag must be finite and >= 0. With zone: ag_out = importance a_gR
    !> (ec8_reference_pga of annex and zone), importance finite and > 0.
    pure subroutine ec8_design_ag(ag, annex, zone, importance, ag_out, stat, errmsg)
        real(dp), intent(in) :: ag            !! design ground acceleration, g (NaN: not given)
        integer, intent(in) :: annex          !! EC8_ANNEX_GR or EC8_ANNEX_RECOMMENDED
        integer, intent(in) :: zone           !! seismic zone 1..3 of annex (0: not given)
        real(dp), intent(in) :: importance    !! importance factor gamma_I (> 0; 1 with ag)
        real(dp), intent(out) :: ag_out       !! ag = gamma_I a_gR, g
        integer, intent(out) :: stat          !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: agr
        ag_out = 0.0_dp
        stat = SEISPULSE_SUCCESS
        if (zone == 0 .and. ieee_is_nan(ag)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ag: give the design '// &
                           'ground acceleration ag, or a seismic zone (Z1, Z2 or Z3 of the '// &
                           'Greek National Annex)')
        else if (zone /= 0 .and. .not. ieee_is_nan(ag)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ag and zone: give one of '// &
                           'them (a zone gives ag = importance x a_gR)')
        else if (outside(importance, 0.0_dp, big, .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'importance = '// &
                           real_str(importance)//': must be a finite number > 0')
        else if (zone /= 0) then
            call ec8_reference_pga(annex, zone, agr, stat, errmsg)
            if (stat == SEISPULSE_SUCCESS) ag_out = importance*agr
        else if (.not. (importance >= 1.0_dp .and. importance <= 1.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'importance = '// &
                           real_str(importance)//': ag is already the design ground '// &
                           'acceleration gamma_I a_gR; importance applies to the a_gR of a '// &
                           'zone only (give a zone, or multiply ag yourself)')
        else if (annex /= EC8_ANNEX_GR .and. annex /= EC8_ANNEX_RECOMMENDED) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'annex = '//int_str(annex)// &
                           ': must be 0 (EN recommended) or 1 (Greek National Annex)')
        else if (outside(ag, 0.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ag = '//real_str(ag)// &
                           ': must be a finite acceleration >= 0 (g)')
        else
            ag_out = ag
        end if
    end subroutine ec8_design_ag

    !> S, TB, TC, TD of EN 1998-1 Table 3.2 (Type 1) or 3.3 (Type 2), recommended values
    !> (a National Annex may give others).
    pure subroutine ec8_ground_parameters(spectrum_type, ground, s, tb, tc, td, stat, errmsg)
        integer, intent(in) :: spectrum_type  !! EC8_SPECTRUM_TYPE_1 or _2
        integer, intent(in) :: ground         !! EC8_GROUND_A .. EC8_GROUND_E (1..5)
        real(dp), intent(out) :: s            !! soil factor S (dimensionless)
        real(dp), intent(out) :: tb, tc, td   !! corner periods, s
        integer, intent(out) :: stat          !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        s = 0.0_dp
        tb = 0.0_dp
        tc = 0.0_dp
        td = 0.0_dp
        call check_type_ground(spectrum_type, ground, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        s = tab_s(ground, spectrum_type)
        tb = tab_tb(ground, spectrum_type)
        tc = tab_tc(ground, spectrum_type)
        td = tab_td(ground, spectrum_type)
    end subroutine ec8_ground_parameters

    pure subroutine check_type_ground(spectrum_type, ground, stat, errmsg)
        integer, intent(in) :: spectrum_type, ground
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (spectrum_type /= EC8_SPECTRUM_TYPE_1 .and. spectrum_type /= EC8_SPECTRUM_TYPE_2) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'spectrum_type = '// &
                           int_str(spectrum_type)//': must be 1 (Type 1, Ms > 5.5) or 2 '// &
                           '(Type 2, Ms <= 5.5)')
        else if (ground < EC8_GROUND_A .or. ground > EC8_GROUND_E) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ground = '//int_str(ground)// &
                           ': must be 1..5 (ground types A..E of EN 1998-1 Table 3.1)')
        end if
    end subroutine check_type_ground

    !> Damping correction eta = sqrt(10/(5 + xi)) >= 0.55, xi in percent (EN 1998-1
    !> (3.6)); eta(5 %) = 1, the floor is reached at xi = 28.06 %. NaN for xi < 0 or NaN
    !> (ec8_check_damping says why).
    elemental real(dp) function ec8_damping_correction(xi_percent) result(eta)
        real(dp), intent(in) :: xi_percent  !! viscous damping ratio, percent, >= 0
        if (outside(xi_percent, 0.0_dp, big, .false., .false.)) then
            eta = ieee_value(1.0_dp, ieee_quiet_nan)
        else
            eta = max(sqrt(10.0_dp/(5.0_dp + xi_percent)), 0.55_dp)   ! (3.6)
        end if
    end function ec8_damping_correction

    !> The check of ec8_damping_correction: xi finite and >= 0 (percent).
    pure subroutine ec8_check_damping(xi_percent, stat, errmsg)
        real(dp), intent(in) :: xi_percent  !! viscous damping ratio, percent
        integer, intent(out) :: stat        !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming xi_percent
        stat = SEISPULSE_SUCCESS
        if (outside(xi_percent, 0.0_dp, big, .false., .false.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'xi_percent = '// &
                           real_str(xi_percent)//': the damping ratio (percent) must be '// &
                           'finite and >= 0')
    end subroutine ec8_check_damping

    !> Horizontal elastic response spectrum, EN 1998-1 §3.2.2.2 (3.2)-(3.5), recommended
    !> S, TB, TC, TD. EN states the forms for 0 <= T <= 4 s; (3.5) is applied beyond 4 s
    !> too (EN 1998-1 Annex A covers long periods). Se is in the units of ag.
    !> spectrum_type, ground and xi_percent are optional (defaults as Python's
    !> `codes.elastic_spectrum`); when one is omitted, pass se and stat by keyword.
    pure subroutine ec8_elastic_spectrum(periods, ag, spectrum_type, ground, xi_percent, se, &
                                         stat, errmsg)
        real(dp), intent(in) :: periods(:)    !! periods T, s, finite, >= 0
        real(dp), intent(in) :: ag            !! ground accel. on type A ground (any unit), >= 0
        !> EC8_SPECTRUM_TYPE_1 or _2; default EC8_SPECTRUM_TYPE_1
        integer, intent(in), optional :: spectrum_type
        !> EC8_GROUND_A .. _E; default EC8_GROUND_A
        integer, intent(in), optional :: ground
        !> viscous damping, percent, >= 0 (5 gives eta = 1); default 5
        real(dp), intent(in), optional :: xi_percent
        real(dp), intent(out) :: se(:)        !! Se(T), units of ag (size of periods)
        integer, intent(out) :: stat          !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: s, tb, tc, td, eta, t, plateau
        integer :: i
        integer :: type_in, ground_in
        real(dp) :: xi_in
        type_in = optval(spectrum_type, EC8_SPECTRUM_TYPE_1)
        ground_in = optval(ground, EC8_GROUND_A)
        xi_in = optval(xi_percent, 5.0_dp)
        se = 0.0_dp
        call spectrum_check(periods, ag, size(se), 'se', type_in, ground_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call ec8_check_damping(xi_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call ec8_ground_parameters(type_in, ground_in, s, tb, tc, td, stat, errmsg)
        eta = ec8_damping_correction(xi_in)
        plateau = ag*s*eta*2.5_dp
        do i = 1, size(periods)
            t = periods(i)
            if (t <= tb) then
                se(i) = ag*s*(1.0_dp + t/tb*(eta*2.5_dp - 1.0_dp))   ! (3.2)
            else if (t <= tc) then
                se(i) = plateau                                      ! (3.3)
            else if (t <= td) then
                se(i) = plateau*(tc/t)                               ! (3.4)
            else
                se(i) = plateau*(tc*td/t**2)                         ! (3.5)
            end if
        end do
    end subroutine ec8_elastic_spectrum

    !> Design spectrum for elastic analysis, EN 1998-1 §3.2.2.5 (3.13)-(3.16), with the
    !> floor beta ag for T >= TC (beta = 0.2 recommended, an NDP). q >= 1 is accepted;
    !> the 2/3 ag S at T = 0 of (3.13) presumes q >= 1.5 (for q < 1.5 it lies below the
    !> elastic ag S/q).
    !> spectrum_type, ground, q and beta are optional (defaults as Python's
    !> `codes.design_spectrum`); when one is omitted, pass sd and stat by keyword.
    pure subroutine ec8_design_spectrum(periods, ag, spectrum_type, ground, q, beta, sd, stat, &
                                        errmsg)
        real(dp), intent(in) :: periods(:)    !! periods T, s, finite, >= 0
        real(dp), intent(in) :: ag            !! ground accel. on type A ground (any unit), >= 0
        !> EC8_SPECTRUM_TYPE_1 or _2; default EC8_SPECTRUM_TYPE_1
        integer, intent(in), optional :: spectrum_type
        !> EC8_GROUND_A .. _E; default EC8_GROUND_A
        integer, intent(in), optional :: ground
        !> behaviour factor, finite, >= 1; default 1.5
        real(dp), intent(in), optional :: q
        !> lower-bound factor, finite, >= 0; default 0.2 (recommended)
        real(dp), intent(in), optional :: beta
        real(dp), intent(out) :: sd(:)        !! Sd(T), units of ag (size of periods)
        integer, intent(out) :: stat          !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: s, tb, tc, td, t, plateau, floor
        integer :: i
        integer :: type_in, ground_in
        real(dp) :: q_in, beta_in
        type_in = optval(spectrum_type, EC8_SPECTRUM_TYPE_1)
        ground_in = optval(ground, EC8_GROUND_A)
        q_in = optval(q, 1.5_dp)
        beta_in = optval(beta, 0.2_dp)
        sd = 0.0_dp
        call spectrum_check(periods, ag, size(sd), 'sd', type_in, ground_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(q_in, 1.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'q = '//real_str(q_in)// &
                           ': the behaviour factor must be finite and >= 1')
            return
        end if
        if (outside(beta_in, 0.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'beta = '//real_str(beta_in)// &
                           ': the lower-bound factor must be finite and >= 0 (0.2 recommended)')
            return
        end if
        call ec8_ground_parameters(type_in, ground_in, s, tb, tc, td, stat, errmsg)
        plateau = ag*s*2.5_dp/q_in
        floor = beta_in*ag
        do i = 1, size(periods)
            t = periods(i)
            if (t <= tb) then
                sd(i) = ag*s*(2.0_dp/3.0_dp + t/tb*(2.5_dp/q_in - 2.0_dp/3.0_dp)) ! (3.13)
            else if (t <= tc) then
                sd(i) = plateau                                              ! (3.14)
            else if (t <= td) then
                sd(i) = max(plateau*(tc/t), floor)                           ! (3.15)
            else
                sd(i) = max(plateau*(tc*td/t**2), floor)                     ! (3.16)
            end if
        end do
    end subroutine ec8_design_spectrum

    !> Checks shared by the spectra: type, ground, ag, periods, output size.
    pure subroutine spectrum_check(periods, ag, nout, outname, spectrum_type, ground, stat, &
                                   errmsg)
        real(dp), intent(in) :: periods(:), ag
        integer, intent(in) :: nout, spectrum_type, ground
        character(len=*), intent(in) :: outname
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call check_type_ground(spectrum_type, ground, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(ag, 0.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ag = '//real_str(ag)// &
                           ': the design ground acceleration must be finite and >= 0')
            return
        end if
        call check_spectrum_periods(periods, nout, outname, stat, errmsg)
    end subroutine spectrum_check

end module seispulse_codes
