!> EAK 2000, the Greek seismic code (with its 2003 amendment of the zones): the horizontal
!> design spectrum Phi_d(T) of its §2.3.1 and an elastic spectrum Phi_e(T), with the
!> ground parameters T1, T2 (soil categories A-D), the zone accelerations, the importance
!> factors gamma_I and the damping correction eta (doc/eak2000.md).
!>
!> Provenance (doc/eak2000.md section 1). The primary text of EAK 2000 could NOT be read:
!> only the table of contents of its English translation (clause numbers §2.3.1-§2.3.7).
!> The formulas (K.1)-(K.3) and the values of beta0, T1, T2, gamma_I and eta are
!> SECONDARY: they are those of two implementations written by one author group (so not
!> independent of each other), which agree on them. The 2003 zones: [PRDA24] states that
!> the 2003 map has three zones spanning 0.16-0.36 g; the middle value 0.24 g and the names
!> Z1-Z3 are from press reports of the 2003 amendment (SECONDARY). The original four-zone
!> map is from one of those implementations and the press. The elastic spectrum Phi_e as a
!> whole is UNVERIFIED (one implementation only; EAK may not define a separate elastic
!> spectrum). UNVERIFIED items are parameters with documented defaults: the lower limit of
!> eta (eta_min, default none), the rules for the foundation factor theta (default 1), the
!> lower bound of Phi_d (lower_bound, default none), the long-period exponent of Phi_e
!> (default 2/3 = Phi_d's), and ground X (refused).
!> EAK 2000's retaining-wall clause was not found: no wall rule of EAK is implemented.
!>
!> Units: periods T1, T2, T in s; alpha = A/g dimensionless; the spectra in g (units of
!> alpha g); damping xi in percent (5 gives eta = 1).
module seispulse_eak2000
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_checks, only: outside, check_spectrum_periods
    use seispulse_optval, only: optval
    use seispulse_format, only: num_str, int_str
    implicit none
    private

    public :: eak2000_ground_parameters, eak2000_zone_acceleration, eak2000_importance_factor, &
              eak2000_damping_correction, eak2000_check_damping, eak2000_design_spectrum, &
              eak2000_elastic_spectrum
    public :: EAK_GROUND_A, EAK_GROUND_B, EAK_GROUND_C, EAK_GROUND_D, EAK_GROUND_X
    public :: EAK_MAP_2003, EAK_MAP_2000, EAK_BETA0

    !> EAK 2000 §2.3.6 soil categories A, B, C, D and X (Latin letters; the Greek letters of
    !> the code's text are unverified).
    !> X is refused (it calls for a site-specific study: unverified).
    integer, parameter :: EAK_GROUND_A = 1, EAK_GROUND_B = 2, EAK_GROUND_C = 3, &
                          EAK_GROUND_D = 4, EAK_GROUND_X = 5
    !> The zone map (§2.3.3): the 2003 amendment (in force from 1 January 2004), zones
    !> 1..3 = Z1/Z2/Z3 = 0.16/0.24/0.36 g; the original EAK 2000 map, zones 1..4 =
    !> I/II/III/IV = 0.12/0.16/0.24/0.36 g (I..IV are seispulse's labels). Both SECONDARY
    !> (doc/eak2000.md section 3).
    integer, parameter :: EAK_MAP_2003 = 1, EAK_MAP_2000 = 2
    !> Spectral amplification beta0 (SECONDARY: both implementations).
    real(dp), parameter :: EAK_BETA0 = 2.5_dp

    real(dp), parameter :: big = huge(1.0_dp)
    !> T1, T2 (s) of soil categories A..D (SECONDARY), doc/eak2000.md section 4.
    real(dp), parameter :: tab_t1(4) = [0.10_dp, 0.15_dp, 0.20_dp, 0.20_dp]
    real(dp), parameter :: tab_t2(4) = [0.40_dp, 0.60_dp, 0.80_dp, 1.20_dp]
    !> alpha = A/g of the zones of each map (SECONDARY), doc/eak2000.md section 3.
    real(dp), parameter :: zones_2003(3) = [0.16_dp, 0.24_dp, 0.36_dp]
    real(dp), parameter :: zones_2000(4) = [0.12_dp, 0.16_dp, 0.24_dp, 0.36_dp]
    !> gamma_I of the importance categories Sigma1..Sigma4 (SECONDARY).
    real(dp), parameter :: tab_gamma_i(4) = [0.85_dp, 1.00_dp, 1.15_dp, 1.30_dp]

contains

    !> Corner periods T1, T2 (s) of soil category A..D (EAK 2000 §2.3.6 as implemented by
    !> the secondary sources; doc/eak2000.md section 4): A 0.10/0.40, B 0.15/0.60,
    !> C 0.20/0.80, D 0.20/1.20. Category X is refused: it calls for a site-specific study
    !> (unverified).
    pure subroutine eak2000_ground_parameters(ground, t1, t2, stat, errmsg)
        integer, intent(in) :: ground   !! EAK_GROUND_A .. EAK_GROUND_D (1..4)
        real(dp), intent(out) :: t1     !! corner period T1, s (0 on error)
        real(dp), intent(out) :: t2     !! corner period T2, s (0 on error)
        integer, intent(out) :: stat    !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming ground
        t1 = 0.0_dp
        t2 = 0.0_dp
        call check_ground(ground, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        t1 = tab_t1(ground)
        t2 = tab_t2(ground)
    end subroutine eak2000_ground_parameters

    pure subroutine check_ground(ground, stat, errmsg)
        integer, intent(in) :: ground
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (ground == EAK_GROUND_X) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ground = '//int_str(ground)// &
                           ' (X): ground category X calls for a site-specific study '// &
                           '(unverified); give ground A-D')
        else if (ground < EAK_GROUND_A .or. ground > EAK_GROUND_D) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ground = '//int_str(ground)// &
                           ': must be 1..4 (EAK 2000 soil categories A..D)')
        end if
    end subroutine check_ground

    !> alpha = A/g of a seismic zone (EAK 2000 §2.3.3; SECONDARY, doc/eak2000.md section 3).
    !> EAK_MAP_2003 (the default; the 2003 amendment, in force from 1 January 2004): zones
    !> 1, 2, 3 = Z1, Z2, Z3 -> 0.16, 0.24, 0.36. EAK_MAP_2000 (the original map): zones
    !> 1..4 = I..IV -> 0.12, 0.16, 0.24, 0.36. zone_map is optional; when it is omitted,
    !> pass alpha and stat by keyword.
    pure subroutine eak2000_zone_acceleration(zone, zone_map, alpha, stat, errmsg)
        integer, intent(in) :: zone                !! zone number (1..3 or 1..4, see above)
        integer, intent(in), optional :: zone_map  !! EAK_MAP_2003 (default) or EAK_MAP_2000
        real(dp), intent(out) :: alpha             !! A/g (dimensionless); 0 on error
        integer, intent(out) :: stat  !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        integer :: map_in, n
        real(dp) :: table(size(zones_2000))
        character(len=:), allocatable :: names
        map_in = optval(zone_map, EAK_MAP_2003)
        alpha = 0.0_dp
        stat = SEISPULSE_SUCCESS
        table = 0.0_dp
        select case (map_in)
        case (EAK_MAP_2003)
            n = size(zones_2003)
            table(1:n) = zones_2003
            names = 'Z1, Z2, Z3 of the 2003 map'
        case (EAK_MAP_2000)
            n = size(zones_2000)
            table(1:n) = zones_2000
            names = 'I, II, III, IV of the original 2000 map'
        case default
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'zone_map = '// &
                           int_str(map_in)//': must be 1 (EAK_MAP_2003, the 2003 map) or 2 '// &
                           '(EAK_MAP_2000, the original 2000 map)')
            return
        end select
        if (zone < 1 .or. zone > n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'zone = '//int_str(zone)// &
                           ': must be 1..'//int_str(n)//' ('//names//')')
        else
            alpha = table(zone)
        end if
    end subroutine eak2000_zone_acceleration

    !> Importance factor gamma_I of category 1..4 (Sigma1..Sigma4, EAK 2000 §2.3.4;
    !> SECONDARY): 0.85, 1.00, 1.15, 1.30.
    pure subroutine eak2000_importance_factor(category, gamma_i, stat, errmsg)
        integer, intent(in) :: category   !! importance category 1..4 (Sigma1..Sigma4)
        real(dp), intent(out) :: gamma_i  !! gamma_I (dimensionless); 0 on error
        integer, intent(out) :: stat      !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming category
        gamma_i = 0.0_dp
        stat = SEISPULSE_SUCCESS
        if (category < 1 .or. category > size(tab_gamma_i)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'category = '// &
                           int_str(category)//': must be 1..4 (importance categories '// &
                           'Sigma1..Sigma4)')
        else
            gamma_i = tab_gamma_i(category)
        end if
    end subroutine eak2000_importance_factor

    !> Damping correction eta = max(sqrt(7/(2 + xi)), eta_min), xi in percent (K.4)
    !> (SECONDARY; eta(5 %) = 1). eta_min is optional, default 0 (none). Neither secondary
    !> implementation applies a limit; one implementation's docstring states eta >= 0.55
    !> without applying it; 0.7 is recalled as ENV 1998's limit for this form. All
    !> UNVERIFIED. NaN for xi < 0 or NaN, or eta_min outside [0, 1] (eak2000_check_damping
    !> says why).
    elemental real(dp) function eak2000_damping_correction(xi_percent, eta_min) result(eta)
        real(dp), intent(in) :: xi_percent         !! viscous damping ratio, percent, >= 0
        real(dp), intent(in), optional :: eta_min  !! lower limit of eta, in [0, 1]; default 0
        real(dp) :: floor
        floor = optval(eta_min, 0.0_dp)
        if (outside(xi_percent, 0.0_dp, big, .false., .false.) .or. &
            outside(floor, 0.0_dp, 1.0_dp, .false., .false.)) then
            eta = ieee_value(1.0_dp, ieee_quiet_nan)
        else
            eta = max(sqrt(7.0_dp/(2.0_dp + xi_percent)), floor)   ! (K.4)
        end if
    end function eak2000_damping_correction

    !> The check of eak2000_damping_correction: xi finite and >= 0 (percent); eta_min
    !> (optional, default 0) finite and in [0, 1]. When eta_min is omitted, pass stat by
    !> keyword.
    pure subroutine eak2000_check_damping(xi_percent, eta_min, stat, errmsg)
        real(dp), intent(in) :: xi_percent         !! viscous damping ratio, percent
        real(dp), intent(in), optional :: eta_min  !! lower limit of eta; default 0
        integer, intent(out) :: stat               !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: floor
        floor = optval(eta_min, 0.0_dp)
        stat = SEISPULSE_SUCCESS
        if (outside(xi_percent, 0.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'xi_percent = '// &
                           num_str(xi_percent)//': the damping ratio (percent) must be '// &
                           'finite and >= 0')
        else if (outside(floor, 0.0_dp, 1.0_dp, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'eta_min = '// &
                           num_str(floor)//': the lower limit of eta must lie in [0, 1] '// &
                           '(0 = none; EAK''s own limit is unverified)')
        end if
    end subroutine eak2000_check_damping

    !> Horizontal design spectrum Phi_d(T) of EAK 2000 §2.3.1 (SECONDARY; doc/eak2000.md
    !> section 2), with eta = eak2000_damping_correction(xi_percent, eta_min):
    !>   T <= T1:      gamma_I A [1 + T/T1 (eta theta beta0/q - 1)]        (K.1)
    !>   T1 < T <= T2: gamma_I A eta theta beta0/q                         (K.2)
    !>   T > T2:       gamma_I A eta theta beta0/q (T2/T)^(2/3)            (K.3)
    !> and Phi_d >= lower_bound gamma_I A (K.5) when lower_bound > 0 (a floor of 0.25 is
    !> recalled but UNVERIFIED; default 0 = none, as both secondary sources). Phi_d(0) =
    !> gamma_I A (for lower_bound <= 1); for q > eta theta beta0 (K.1) slopes down to the
    !> plateau. Inputs whose gamma_I A, plateau or floor overflow are refused (stat
    !> SEISPULSE_INVALID_INPUT), never a NaN or Inf with success; on error phi_d = 0. The
    !> optional arguments take the defaults of Python's `codes.eak2000_spectrum`; when one
    !> is omitted, pass phi_d and stat by keyword.
    pure subroutine eak2000_design_spectrum(periods, alpha, ground, importance, q, theta, &
                                            xi_percent, eta_min, lower_bound, phi_d, stat, &
                                            errmsg)
        real(dp), intent(in) :: periods(:)  !! periods T, s, finite, >= 0
        real(dp), intent(in) :: alpha       !! A/g, the zone's ground acceleration, >= 0
        integer, intent(in) :: ground       !! EAK_GROUND_A .. EAK_GROUND_D (1..4)
        !> importance factor gamma_I, finite, > 0; default 1 (eak2000_importance_factor)
        real(dp), intent(in), optional :: importance
        !> behaviour factor q, finite, >= 1; default 1
        real(dp), intent(in), optional :: q
        !> foundation factor theta, in (0, 1]; default 1 (its rules are UNVERIFIED; the
        !> secondary source offers 0.8-1.0; values below 0.8 have no source at all)
        real(dp), intent(in), optional :: theta
        !> viscous damping, percent, >= 0; default 5 (eta = 1)
        real(dp), intent(in), optional :: xi_percent
        !> lower limit of eta, in [0, 1]; default 0 (none; EAK's own limit UNVERIFIED)
        real(dp), intent(in), optional :: eta_min
        !> floor factor of Phi_d (times gamma_I A), finite, >= 0; default 0 (none;
        !> EAK's floor is UNVERIFIED; a factor above 1 lifts Phi_d(0) above gamma_I A)
        real(dp), intent(in), optional :: lower_bound
        real(dp), intent(out) :: phi_d(:)   !! Phi_d(T), g (size of periods)
        integer, intent(out) :: stat        !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        call eak_spectrum(periods, alpha, ground, optval(importance, 1.0_dp), &
                          optval(q, 1.0_dp), optval(theta, 1.0_dp), optval(xi_percent, 5.0_dp), &
                          optval(eta_min, 0.0_dp), optval(lower_bound, 0.0_dp), &
                          2.0_dp/3.0_dp, 'phi_d', phi_d, stat, errmsg)
    end subroutine eak2000_design_spectrum

    !> Elastic spectrum Phi_e(T) (doc/eak2000.md section 2): (K.1)-(K.3) with q = theta = 1,
    !> no floor, and the long-period branch gamma_I A eta beta0 (T2/T)^exponent (K.6).
    !> Phi_e as a whole is UNVERIFIED: it is in one secondary implementation only, and
    !> whether EAK 2000 defines an elastic spectrum beyond Phi_d with q = theta = 1 (and its
    !> exponent) is unknown; the default 2/3 makes Phi_e that Phi_d, exponent = 1 is what
    !> one secondary implementation uses. Overflow is refused as in
    !> eak2000_design_spectrum; on error phi_e = 0. The optional arguments take the defaults of
    !> Python's `codes.eak2000_spectrum(kind='elastic')`; when one is omitted, pass phi_e
    !> and stat by keyword.
    pure subroutine eak2000_elastic_spectrum(periods, alpha, ground, importance, xi_percent, &
                                             eta_min, exponent, phi_e, stat, errmsg)
        real(dp), intent(in) :: periods(:)  !! periods T, s, finite, >= 0
        real(dp), intent(in) :: alpha       !! A/g, the zone's ground acceleration, >= 0
        integer, intent(in) :: ground       !! EAK_GROUND_A .. EAK_GROUND_D (1..4)
        !> importance factor gamma_I, finite, > 0; default 1
        real(dp), intent(in), optional :: importance
        !> viscous damping, percent, >= 0; default 5 (eta = 1)
        real(dp), intent(in), optional :: xi_percent
        !> lower limit of eta, in [0, 1]; default 0 (none; UNVERIFIED)
        real(dp), intent(in), optional :: eta_min
        !> exponent of (T2/T) beyond T2, finite, > 0; default 2/3 (UNVERIFIED; 1 in one
        !> secondary implementation)
        real(dp), intent(in), optional :: exponent
        real(dp), intent(out) :: phi_e(:)   !! Phi_e(T), g (size of periods)
        integer, intent(out) :: stat        !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        call eak_spectrum(periods, alpha, ground, optval(importance, 1.0_dp), 1.0_dp, 1.0_dp, &
                          optval(xi_percent, 5.0_dp), optval(eta_min, 0.0_dp), 0.0_dp, &
                          optval(exponent, 2.0_dp/3.0_dp), 'phi_e', phi_e, stat, errmsg)
    end subroutine eak2000_elastic_spectrum

    !> Both spectra: checks, then (K.1)-(K.3) with the long-period exponent `expo` and the
    !> floor lower_bound gamma_I A (K.5). Refuses gamma_I A, the plateau or the floor that
    !> overflow (not finite). On error out = 0.
    pure subroutine eak_spectrum(periods, alpha, ground, gamma_i, q, theta, xi_percent, eta_min, &
                                 lower_bound, expo, outname, out, stat, errmsg)
        real(dp), intent(in) :: periods(:), alpha
        integer, intent(in) :: ground
        real(dp), intent(in) :: gamma_i, q, theta, xi_percent, eta_min, lower_bound, expo
        character(len=*), intent(in) :: outname
        real(dp), intent(out) :: out(:)
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: t1, t2, eta, a, plateau, floor, t, peak
        integer :: i
        out = 0.0_dp
        call check_ground(ground, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(alpha, 0.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'alpha = '//num_str(alpha)// &
                           ': the ground acceleration A/g must be finite and >= 0')
            return
        end if
        call check_spectrum_periods(periods, size(out), outname, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(gamma_i, 0.0_dp, big, .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'importance = '// &
                           num_str(gamma_i)//': the importance factor gamma_I must be '// &
                           'finite and > 0 (categories: 0.85, 1.00, 1.15, 1.30)')
        else if (outside(q, 1.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'q = '//num_str(q)// &
                           ': the behaviour factor must be finite and >= 1')
        else if (outside(theta, 0.0_dp, 1.0_dp, .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'theta = '//num_str(theta)// &
                           ': the foundation factor must lie in (0, 1]')
        else if (outside(lower_bound, 0.0_dp, big, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'lower_bound = '// &
                           num_str(lower_bound)//': the floor factor must be finite and >= 0 '// &
                           '(0 = none)')
        else if (outside(expo, 0.0_dp, big, .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'exponent = '// &
                           num_str(expo)//': the long-period exponent must be finite and > 0')
        else
            call eak2000_check_damping(xi_percent, eta_min, stat, errmsg)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        t1 = tab_t1(ground)
        t2 = tab_t2(ground)
        eta = eak2000_damping_correction(xi_percent, eta_min)
        ! gamma_I A max(1, eta theta beta0/q, lower_bound) bounds every ordinate: tested in
        ! logarithms (no overflow), a margin of 1e-6 below the largest double
        peak = max(1.0_dp, eta*theta*EAK_BETA0/q, lower_bound)
        if (alpha > 0.0_dp) then
            if (log(gamma_i) + log(alpha) + log(peak) > log(big) - 1.0e-6_dp) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'alpha = '// &
                               num_str(alpha)//', importance = '//num_str(gamma_i)// &
                               ': the spectrum overflows (gamma_I A, gamma_I A eta theta '// &
                               'beta0/q and lower_bound gamma_I A must be finite)')
                return
            end if
        end if
        a = gamma_i*alpha
        plateau = a*eta*theta*EAK_BETA0/q
        floor = 0.0_dp
        if (lower_bound > 0.0_dp) floor = lower_bound*a
        do i = 1, size(periods)
            t = periods(i)
            if (t <= t1) then
                out(i) = a*(1.0_dp + t/t1*(eta*theta*EAK_BETA0/q - 1.0_dp))   ! (K.1)
            else if (t <= t2) then
                out(i) = plateau                                            ! (K.2)
            else
                out(i) = plateau*(t2/t)**expo                               ! (K.3), (K.6)
            end if
            out(i) = max(out(i), floor)                                     ! (K.5)
        end do
    end subroutine eak_spectrum

end module seispulse_eak2000
