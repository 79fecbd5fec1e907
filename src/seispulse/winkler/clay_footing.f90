!> A rigid circular footing on undrained clay: the reduced-order (normalised stiffness
!> degradation) method of [AD11] chapter 3 that turns the elastic Winkler pushover into an
!> inelastic one without finite elements (doc/winkler.md section 10, (W.60)-(W.74)):
!> - vertical bearing: N_ult = n_c S_u pi r^2 with n_c = pi + 3 ([AD11], supported by
!>   [SLSY04]), the factor of safety SF = N_ult/N and chi = 1/SF (W.60)-(W.61);
!> - the initial-stiffness ratio k/k_el(chi) (W.63) and the Gaussian correction G(chi; x) of
!>   the normalised curve (W.66)-(W.67): their coefficients are lost in [AD11] and must be
!>   given by the user (degradation_coeffs_t; nothing is defaulted except k_el = 1, a
!>   stated assumption; the base of "log" in G is lost too and is the user's);
!> - the uplift angle theta_up = 1/2 asin(N r/(2 K_R)) (W.65);
!> - the inelastic pushover on a theta grid (W.68)-(W.72), the elastic curve being that of
!>   the constant-k Winkler circle (winkler_master_curve of seispulse_winkler); its scalars
!>   (peaks, overturning angle) come from an internal scan of the branch, not the grid;
!> - the moment capacity: [TC00]'s peak 0.8 A D S_u or the effective-width N D (1 - chi)/2
!>   (W.73)-(W.74).
!> Units: m, N, Pa (S_u, G), rad, N m, N m/rad; chi, SF, k/k_el, G dimensionless.
module seispulse_clay_footing
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_checks, only: finite_positive, finite_at_least, outside, in_closed
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_SOLUTION, set_error
    use seispulse_format, only: real_str, int_str
    use seispulse_special, only: pi
    use seispulse_roots, only: scalar_function, find_root, find_minimum
    use seispulse_winkler_contact, only: FOOTING_CIRCLE
    use seispulse_winkler, only: halfspace_rocking_stiffness, winkler_master_curve, &
                                 check_scale
    implicit none
    private

    public :: degradation_coeffs_t, inelastic_pushover_t
    public :: clay_bearing, initial_stiffness_ratio, gaussian_correction, theta_uplift
    public :: inelastic_pushover, moment_capacity_circle
    public :: IP_THETA, IP_K_R, IP_M_FOUND, IP_M_IMPOSED, IP_FORCE, IP_X, IP_G, IP_NCOL
    public :: CAPACITY_TC00_PEAK, CAPACITY_EFFECTIVE_WIDTH
    public :: NC_CIRCLE_CLAY, CHI_ELASTIC_LIMIT, SF_WEAK_LIMIT

    !> Columns of the inelastic pushover curve(size(theta), IP_NCOL)
    integer, parameter :: IP_THETA = 1      !! rotation theta (rad)
    integer, parameter :: IP_K_R = 2        !! secant rotational stiffness K_R (N m/rad)
    integer, parameter :: IP_M_FOUND = 3    !! foundation moment about the base centre (N m)
    integer, parameter :: IP_M_IMPOSED = 4  !! imposed moment M_found - W h sin(theta) (N m)
    integer, parameter :: IP_FORCE = 5      !! force at the CoM M_imp/(h cos(theta)) (N)
    integer, parameter :: IP_X = 6          !! theta/theta_up (-)
    integer, parameter :: IP_G = 7          !! Gaussian correction G(chi; theta/theta_up) (-)
    integer, parameter :: IP_NCOL = 7
    !> Models of moment_capacity_circle
    integer, parameter :: CAPACITY_TC00_PEAK = 1        !! [TC00] peak 0.8 A D S_u (W.73)
    integer, parameter :: CAPACITY_EFFECTIVE_WIDTH = 2  !! N D (1 - chi)/2 (W.74)

    real(dp), parameter :: NC_CIRCLE_CLAY = pi + 3.0_dp  !! n_c of a circle on clay (W.60)
    real(dp), parameter :: CHI_ELASTIC_LIMIT = 0.1_dp    !! k/k_el = 1 for chi <= 0.1 (W.63)
    real(dp), parameter :: SF_WEAK_LIMIT = 1.25_dp       !! below it the collapse is weakest
    !> the weak zone of the collapse: theta/theta_up within a factor 2 of 0.1
    real(dp), parameter :: x_weak_lo = 0.05_dp, x_weak_hi = 0.2_dp
    real(dp), parameter :: tc00_peak = 0.8_dp            !! M_ult/(A D S_u) of [TC00] (W.73)
    real(dp), parameter :: qnan = transfer(9221120237041090560_int64, 1.0_dp)  !! quiet NaN
    !> |(log_B x - b)/c| beyond which exp(-z^2/2) underflows: G = 1
    real(dp), parameter :: z_max = 38.0_dp
    !> relative size of a jump of k/k_el at chi = 0.1 that counts as a discontinuity
    real(dp), parameter :: jump_rtol = 1.0e-12_dp

    !> The coefficients of [AD11]'s fits that did not survive (doc/winkler.md (W.63),
    !> (W.67)): no value is invented; NaN means "not given" and is an error wherever the
    !> coefficient is needed.
    type :: degradation_coeffs_t
        real(dp) :: k_el = 1.0_dp       !! elastic initial-stiffness ratio K_R0/HK_R at chi
                                        !! -> 0 (assumption 1; [AD11] used 1.14 to 1.28)
        real(dp) :: kr_c1 = qnan        !! k/k_el = kr_c1 - kr_c2 chi for chi > 0.1 (lost)
        real(dp) :: kr_c2 = qnan        !! (lost)
        real(dp) :: a_poly(0:4) = qnan  !! a(chi) = sum a_i chi^i (only "5.11" survives)
        real(dp) :: b1 = qnan           !! b(chi) = b1 ln(chi) + b2 (lost)
        real(dp) :: b2 = qnan           !! (lost)
        real(dp) :: c1 = qnan           !! c(chi) = c1 chi + c2 (lost)
        real(dp) :: c2 = qnan           !! (lost)
        real(dp) :: log_base = qnan     !! base B of "log" in G (lost; needed when a(chi)
                                        !! /= 0; b and c are in log_B units)
    end type degradation_coeffs_t

    !> Scalars of the inelastic pushover (NaN where not computed).
    type :: inelastic_pushover_t
        real(dp) :: n_ult = qnan          !! vertical capacity (N) (W.60)
        real(dp) :: sf = qnan             !! factor of safety N_ult/W (-)
        real(dp) :: chi = qnan            !! 1/SF (-)
        real(dp) :: hk_r = qnan           !! halfspace rocking stiffness (N m/rad) (W.62)
        real(dp) :: k_ratio = qnan        !! k/k_el(chi) (-) (W.63)
        real(dp) :: kappa = qnan          !! K_R0/HK_R = k_el k/k_el (-) (W.64)
        real(dp) :: k_r0 = qnan           !! initial rotational stiffness (N m/rad) (W.64)
        real(dp) :: theta_up = qnan       !! uplift angle (rad) (W.65); NaN: no uplift
        real(dp) :: a = qnan, b = qnan, c = qnan  !! Gaussian parameters at chi (W.67)
        real(dp) :: max_moment = qnan     !! peak imposed moment on [0, pi/4] (N m)
        real(dp) :: theta_at_max_moment = qnan  !! its theta (rad)
        real(dp) :: max_force_over_weight = qnan  !! peak F/W on [0, pi/4] (-)
        real(dp) :: theta_at_max = qnan   !! its theta (rad)
        real(dp) :: theta_overturn = qnan !! first zero of M_imp (rad); NaN if none in
                                          !! (0, pi/4] or the start search fails
        logical :: no_uplift = .false.    !! N r/(2 K_R0) > 1: no uplift angle
        logical :: weak_zone = .false.    !! SF < 1.25 and the grid reaches theta ~ 0.1 theta_up
        logical :: kr_discontinuous = .false.  !! the user's k/k_el jumps at chi = 0.1
        real(dp) :: kr_jump = 0.0_dp      !! kr_c1 - 0.1 kr_c2 - 1 (0 when not given)
    end type inelastic_pushover_t

    !> The imposed moment M_imp(theta) of one problem, for the overturning root.
    type, extends(scalar_function) :: imposed_moment_t
        real(dp) :: k_r0, sin2_up, theta_up, weight, h, a, b, c, ln_base
    contains
        procedure :: eval => imposed_moment_eval
    end type imposed_moment_t

    !> -M_imp (N m) or -F/W (-) of a pushover at theta (rad): the peak search's function.
    type, extends(scalar_function) :: peak_fn_t
        type(imposed_moment_t) :: f
        logical :: force = .false.
    contains
        procedure :: eval => peak_fn_eval
    end type peak_fn_t

contains

    ! ------------------------------------------------------------------------------
    ! Bearing capacity and factor of safety
    ! ------------------------------------------------------------------------------

    !> Vertical capacity of a circular footing of radius r on clay of undrained strength
    !> S_u: N_ult = n_c S_u pi r^2 (W.60), n_c = pi + 3 by default ([AD11], supported by
    !> [SLSY04]), SF = N_ult/weight and chi = 1/SF (W.61). SF <= 1 (vertical bearing
    !> failure) is an error; n_ult, sf and chi are returned all the same. su, r, weight and
    !> nc must lie in [1e-30, 1e30] (in their units), so no product overflows.
    subroutine clay_bearing(su, r, weight, n_ult, sf, chi, stat, errmsg, nc)
        real(dp), intent(in) :: su                            !! undrained strength (Pa), > 0
        real(dp), intent(in) :: r                             !! footing radius (m), > 0
        real(dp), intent(in) :: weight                        !! vertical load N (N), > 0
        real(dp), intent(out) :: n_ult                        !! N_ult (N)
        real(dp), intent(out) :: sf                           !! N_ult/weight (-)
        real(dp), intent(out) :: chi                          !! weight/N_ult (-)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(in), optional :: nc                  !! bearing factor (default pi + 3)
        real(dp) :: ncv
        n_ult = qnan
        sf = qnan
        chi = qnan
        call check_soil(su, r, ncv, stat, errmsg, nc)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(weight, 'weight', 'the vertical load', 'N', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        n_ult = ncv * su * pi * r * r                                       ! (W.60)
        if (.not. ieee_is_finite(n_ult)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'su = '//real_str(su) &
                           //', r = '//real_str(r)//': N_ult = n_c su pi r^2 overflows (N)')
            return
        end if
        sf = n_ult / weight                                                 ! (W.61)
        chi = weight / n_ult
        if (.not. sf > 1.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'weight = ' &
                           //real_str(weight)//' N, su = '//real_str(su)//' Pa: SF = N_ult/' &
                           //'weight = '//real_str(sf)//' must exceed 1 (N_ult = ' &
                           //real_str(n_ult)//' N): the footing fails vertically')
        end if
    end subroutine clay_bearing

    ! ------------------------------------------------------------------------------
    ! The normalisation laws (their coefficients are the user's)
    ! ------------------------------------------------------------------------------

    !> Initial-stiffness ratio k/k_el(chi) (W.63): 1 for chi <= 0.1, kr_c1 - kr_c2 chi
    !> above (coefficients lost in [AD11]: an error naming kr_c1/kr_c2 when needed and not
    !> given; never defaulted). kappa = k_el k/k_el = K_R0/HK_R (W.64). `discontinuous` is
    !> set when the given law does not meet 1 at chi = 0.1 (jump = kr_c1 - 0.1 kr_c2 - 1,
    !> beyond 1e-12 relative): allowed, but the user should know.
    subroutine initial_stiffness_ratio(chi, coeffs, k_ratio, stat, errmsg, kappa, &
                                       discontinuous, jump)
        real(dp), intent(in) :: chi                           !! 1/SF, in [0, 1)
        type(degradation_coeffs_t), intent(in) :: coeffs      !! the user's coefficients
        real(dp), intent(out) :: k_ratio                      !! k/k_el (-)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(out), optional :: kappa              !! k_el k/k_el (-)
        logical, intent(out), optional :: discontinuous       !! the law jumps at chi = 0.1
        real(dp), intent(out), optional :: jump               !! kr_c1 - 0.1 kr_c2 - 1 (-)
        real(dp) :: jmp
        logical :: given, disc
        k_ratio = qnan
        if (present(kappa)) kappa = qnan
        if (present(discontinuous)) discontinuous = .false.
        if (present(jump)) jump = 0.0_dp
        if (outside(chi, 0.0_dp, 1.0_dp, .false., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'chi = '//real_str(chi) &
                           //': 1/SF must be in [0, 1)')
            return
        end if
        call check_scale(coeffs%k_el, 'k_el', 'the elastic stiffness ratio', '-', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        given = ieee_is_finite(coeffs%kr_c1) .and. ieee_is_finite(coeffs%kr_c2)
        jmp = 0.0_dp
        disc = .false.
        if (given) then
            jmp = coeffs%kr_c1 - CHI_ELASTIC_LIMIT * coeffs%kr_c2 - 1.0_dp
            disc = abs(jmp) > jump_rtol * max(1.0_dp, abs(coeffs%kr_c1), &
                                              CHI_ELASTIC_LIMIT * abs(coeffs%kr_c2))
        end if
        if (chi <= CHI_ELASTIC_LIMIT) then
            k_ratio = 1.0_dp                                                ! (W.63)
        else
            if (.not. given) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kr_c1 = ' &
                               //real_str(coeffs%kr_c1)//', kr_c2 = '//real_str(coeffs%kr_c2) &
                               //': not given (finite numbers needed for chi = ' &
                               //real_str(chi)//' > 0.1): the coefficients of k/k_el = kr_c1' &
                               //' - kr_c2 chi are lost in [AD11] and have no default')
                return
            end if
            k_ratio = coeffs%kr_c1 - coeffs%kr_c2 * chi                     ! (W.63)
            ! in [1e-30, 1e30] like every other factor of K_R0 (no overflow downstream)
            if (.not. in_closed(k_ratio, 1.0e-30_dp, 1.0e30_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kr_c1 = ' &
                               //real_str(coeffs%kr_c1)//', kr_c2 = '//real_str(coeffs%kr_c2) &
                               //': k/k_el = kr_c1 - kr_c2 chi = '//real_str(k_ratio) &
                               //' at chi = '//real_str(chi)//' must be finite and > 0, in [1e-30, 1e30]')
                k_ratio = qnan
                return
            end if
        end if
        if (present(kappa)) kappa = coeffs%k_el * k_ratio                  ! (W.64)
        if (present(discontinuous)) discontinuous = disc
        if (present(jump)) jump = jmp
    end subroutine initial_stiffness_ratio

    !> Gaussian correction of the normalised curve (W.66): G(chi; x) = 1 + a exp(-(log_B(x)
    !> - b)^2/(2 c^2)) at x = theta/theta_up >= 0, with a(chi) = sum a_i chi^i,
    !> b = b1 ln(chi) + b2, c = c1 chi + c2 (W.67) from the user's coefficients (lost in
    !> [AD11]; an error naming a_poly/b1/b2/c1/c2 when needed and not given). b and c are
    !> needed only when a(chi) /= 0; c(chi) = 0 is an error, only c^2 enters. a(chi) must
    !> exceed -1 (G > 0). G(chi; 0) = 1 (log_B(x) -> -inf); the peak 1 + a is at
    !> log_B(x) = b.
    subroutine gaussian_correction(chi, x, coeffs, g_corr, stat, errmsg, a, b, c)
        real(dp), intent(in) :: chi                           !! 1/SF, in (0, 1)
        real(dp), intent(in) :: x                             !! theta/theta_up, finite, >= 0
        type(degradation_coeffs_t), intent(in) :: coeffs      !! the user's coefficients
        real(dp), intent(out) :: g_corr                       !! G(chi; x) (-)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(out), optional :: a, b, c            !! a(chi), b(chi), c(chi) (-)
        real(dp) :: av, bv, cv, ln_b
        g_corr = qnan
        if (present(a)) a = qnan
        if (present(b)) b = qnan
        if (present(c)) c = qnan
        if (outside(chi, 0.0_dp, 1.0_dp, .true., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'chi = '//real_str(chi) &
                           //': 1/SF must be in (0, 1)')
            return
        end if
        if (.not. finite_at_least(x, 0.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'x = '//real_str(x) &
                           //': theta/theta_up must be a finite number >= 0')
            return
        end if
        call gauss_params(chi, coeffs, av, bv, cv, ln_b, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        g_corr = gauss_value(av, bv, cv, ln_b, x)
        if (present(a)) a = av
        if (present(b)) b = bv
        if (present(c)) c = cv
    end subroutine gaussian_correction

    !> Uplift angle theta_up = 1/2 asin(N r/(2 K_R)) (W.65) of a circle of radius r under
    !> the load N on the initial rotational stiffness K_R (the constant-k Winkler circle's
    !> with k = 4 K_R/(pi r^4)). When N r/(2 K_R) > 1 there is no uplift: theta_up = NaN,
    !> no_uplift = .true. and stat = SEISPULSE_SUCCESS. weight, r and k_r must lie in
    !> [1e-30, 1e30] (in their units).
    subroutine theta_uplift(weight, r, k_r, theta_up, stat, errmsg, no_uplift)
        real(dp), intent(in) :: weight                        !! vertical load N (N), > 0
        real(dp), intent(in) :: r                             !! footing radius (m), > 0
        real(dp), intent(in) :: k_r                           !! initial K_R (N m/rad), > 0
        real(dp), intent(out) :: theta_up                     !! uplift angle (rad) or NaN
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        logical, intent(out), optional :: no_uplift           !! N r/(2 K_R) > 1
        logical :: none
        theta_up = qnan
        if (present(no_uplift)) no_uplift = .false.
        call check_scale(weight, 'weight', 'the vertical load', 'N', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(r, 'r', 'the footing radius', 'm', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(k_r, 'k_r', 'the rotational stiffness', 'N m/rad', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call uplift_angle(weight, r, k_r, theta_up, none)
        if (present(no_uplift)) no_uplift = none
    end subroutine theta_uplift

    ! ------------------------------------------------------------------------------
    ! The inelastic pushover
    ! ------------------------------------------------------------------------------

    !> Inelastic rotational pushover of a rigid cylinder (base radius r, centre of mass at
    !> height h, weight W) on clay (S_u, G, nu) by the reduced-order method of [AD11]
    !> (doc/winkler.md (W.60)-(W.72)):
    !> 1. SF, chi (W.60)-(W.61) (SF <= 1 is an error); 2. HK_R = 8 G r^3/(3 (1 - nu)) (W.62);
    !> 3. K_R0 = HK_R k_el k/k_el(chi) (W.63)-(W.64); 4. theta_up (W.65) (no uplift is an
    !> error SEISPULSE_NO_SOLUTION, res%no_uplift set); 5. the elastic normalised secant
    !> curve of the constant-k Winkler circle with k = 4 K_R0/(pi r^4) (W.68); 6. K_R(theta)
    !> = K_R0 K_EL(theta)/G(chi; theta/theta_up) (W.69), K_R the SECANT stiffness (an
    !> assumption), M_found = K_R theta (W.70); 7. M_imp = M_found - W h sin(theta), F =
    !> M_imp/(h cos(theta)) (W.71). theta >= 0 ascending; a point beyond pi/4 (end of the
    !> Winkler branch) has NaN in columns 2..IP_NCOL. Scalars in res, all independent of
    !> the grid (from an internal scan of the branch [0, pi/4] that resolves the bell of G,
    !> see branch_scalars): the peaks of M_imp and F/W on [0, pi/4] and their angles;
    !> theta_overturn = the first zero of M_imp after its first positive value, by Brent on
    !> the first scan interval where M_imp stops being positive (W.72) (0 when K_R0 <= W h:
    !> upright equilibrium unstable; NaN when M_imp stays positive up to pi/4, or when the
    !> halving towards 0 finds no positive value); weak_zone when SF < 1.25 and the grid
    !> reaches theta/theta_up in [0.05, 0.2] (where [AD11]'s collapse deviates);
    !> kr_discontinuous when the user's k/k_el jumps at chi = 0.1. r, h, weight, g_mod, su
    !> and nc must lie in [1e-30, 1e30] (in their units).
    subroutine inelastic_pushover(r, h, weight, g_mod, nu, su, coeffs, theta, curve, res, &
                                  stat, errmsg, nc)
        real(dp), intent(in) :: r                             !! footing radius (m), > 0
        real(dp), intent(in) :: h                             !! CoM height (m), > 0
        real(dp), intent(in) :: weight                        !! weight N (N), > 0
        real(dp), intent(in) :: g_mod                         !! soil shear modulus (Pa), > 0
        real(dp), intent(in) :: nu                            !! Poisson's ratio, in (0, 0.5)
        real(dp), intent(in) :: su                            !! undrained strength (Pa), > 0
        type(degradation_coeffs_t), intent(in) :: coeffs      !! the user's coefficients
        real(dp), intent(in) :: theta(:)                      !! rotations (rad), >= 0, ascending
        real(dp), intent(out) :: curve(:, :)                  !! size(theta) x IP_NCOL
        type(inelastic_pushover_t), intent(out) :: res        !! scalars
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(in), optional :: nc                  !! bearing factor (default pi + 3)
        type(imposed_moment_t) :: f
        real(dp) :: x, gv, m_found, m_imp, x_lo, x_hi
        integer :: i, n
        logical :: any_ok

        curve = qnan
        if (size(curve, 1) /= size(theta) .or. size(curve, 2) /= IP_NCOL) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'curve: must be ' &
                           //int_str(size(theta))//' x '//int_str(IP_NCOL) &
                           //' (size(theta) x IP_NCOL)')
            return
        end if
        call check_scale(h, 'h', 'the height of the centre of mass', 'm', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(g_mod, 'g_mod', 'the shear modulus G', 'Pa', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(nu, 0.0_dp, 0.5_dp, .true., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'nu = '//real_str(nu) &
                           //": Poisson's ratio must be in (0, 0.5)")
            return
        end if
        n = size(theta)
        do i = 1, n
            if (.not. finite_at_least(theta(i), 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'theta('//int_str(i) &
                               //') = '//real_str(theta(i))//': must be a finite number >= 0' &
                               //' (rad)')
                return
            end if
        end do
        do i = 2, n
            if (theta(i) < theta(i - 1)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'theta('//int_str(i) &
                               //') = '//real_str(theta(i))//': the rotations must be' &
                               //' ascending (rad)')
                return
            end if
        end do
        ! 1. bearing (W.60)-(W.61)
        call clay_bearing(su, r, weight, res%n_ult, res%sf, res%chi, stat, errmsg, nc)
        if (stat /= SEISPULSE_SUCCESS) return
        ! 2.-3. stiffness (W.62)-(W.64)
        call halfspace_rocking_stiffness(g_mod, nu, r, res%hk_r, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call initial_stiffness_ratio(res%chi, coeffs, res%k_ratio, stat, errmsg, &
                                     kappa=res%kappa, discontinuous=res%kr_discontinuous, &
                                     jump=res%kr_jump)
        if (stat /= SEISPULSE_SUCCESS) return
        res%k_r0 = res%hk_r * res%kappa                                     ! (W.64)
        if (.not. ieee_is_finite(res%k_r0)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g_mod = '//real_str(g_mod) &
                           //', r = '//real_str(r)//': K_R0 overflows (N m/rad)')
            return
        end if
        call gauss_params(res%chi, coeffs, res%a, res%b, res%c, f%ln_base, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        ! 4. uplift angle (W.65)
        call uplift_angle(weight, r, res%k_r0, res%theta_up, res%no_uplift)
        if (res%no_uplift) then
            call set_error(stat, errmsg, SEISPULSE_NO_SOLUTION, 'g_mod = '//real_str(g_mod) &
                           //' Pa, su = '//real_str(su)//' Pa: N r/(2 K_R0) = ' &
                           //real_str(weight * r / (2.0_dp * res%k_r0))//' > 1: no uplift' &
                           //' angle, the normalised method does not apply')
            return
        end if
        if (.not. res%theta_up > 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g_mod = '//real_str(g_mod) &
                           //' Pa: theta_up = 1/2 asin(N r/(2 K_R0)) underflows (K_R0 = ' &
                           //real_str(res%k_r0)//' N m/rad against N r = ' &
                           //real_str(weight * r)//' N m)')
            return
        end if
        f%k_r0 = res%k_r0
        f%theta_up = res%theta_up
        f%sin2_up = sin(2.0_dp * res%theta_up)
        f%weight = weight
        f%h = h
        f%a = res%a
        f%b = res%b
        f%c = res%c
        ! 5.-7. the curve (W.68)-(W.71)
        x_lo = huge(1.0_dp)
        x_hi = -huge(1.0_dp)
        any_ok = .false.
        do i = 1, n
            curve(i, IP_THETA) = theta(i)
            x = theta(i) / res%theta_up
            curve(i, IP_X) = x
            if (theta(i) > 0.25_dp * pi) cycle
            call found_moment(f, theta(i), m_found, gv)
            m_imp = m_found - weight * h * sin(theta(i))                    ! (W.71)
            curve(i, IP_G) = gv
            curve(i, IP_M_FOUND) = m_found
            if (theta(i) > 0.0_dp) then
                curve(i, IP_K_R) = m_found / theta(i)                       ! (W.70)
            else
                curve(i, IP_K_R) = res%k_r0 / gv
            end if
            curve(i, IP_M_IMPOSED) = m_imp
            curve(i, IP_FORCE) = m_imp / (h * cos(theta(i)))                ! (W.71)
            x_lo = min(x_lo, x)
            x_hi = max(x_hi, x)
            any_ok = .true.
        end do
        res%weak_zone = res%sf < SF_WEAK_LIMIT .and. any_ok .and. x_lo <= x_weak_hi &
                        .and. x_hi >= x_weak_lo
        ! the scalars, independent of the grid: an internal scan of the branch [0, pi/4]
        call branch_scalars(f, res, stat, errmsg)
    end subroutine inelastic_pushover

    ! ------------------------------------------------------------------------------
    ! Moment capacity
    ! ------------------------------------------------------------------------------

    !> Moment capacity of a circular footing on clay (doc/winkler.md (W.73)-(W.74)), A =
    !> pi r^2, D = 2 r: CAPACITY_TC00_PEAK: [TC00]'s peak over the vertical load, M_ult =
    !> 0.8 A D S_u (chi not used); CAPACITY_EFFECTIVE_WIDTH: rigid-plastic effective width,
    !> M_u = N D (1 - chi)/2 with N = chi N_ult, i.e. M_u/(A D S_u) = (n_c/2) chi (1 - chi),
    !> peak (pi + 3)/8 = 0.768 at chi = 1/2.
    subroutine moment_capacity_circle(su, r, chi, model, m_ult, stat, errmsg, nc)
        real(dp), intent(in) :: su                            !! undrained strength (Pa), > 0
        real(dp), intent(in) :: r                             !! footing radius (m), > 0
        real(dp), intent(in) :: chi                           !! 1/SF, in [0, 1]
        integer, intent(in) :: model                          !! CAPACITY_* code
        real(dp), intent(out) :: m_ult                        !! moment capacity (N m)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(in), optional :: nc                  !! bearing factor (default pi + 3)
        real(dp) :: ncv, adsu
        m_ult = qnan
        call check_soil(su, r, ncv, stat, errmsg, nc)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(chi, 0.0_dp, 1.0_dp, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'chi = '//real_str(chi) &
                           //': 1/SF must be in [0, 1]')
            return
        end if
        adsu = 2.0_dp * pi * r**3 * su                                      ! A D S_u
        select case (model)
        case (CAPACITY_TC00_PEAK)
            m_ult = tc00_peak * adsu                                        ! (W.73)
        case (CAPACITY_EFFECTIVE_WIDTH)
            m_ult = 0.5_dp * ncv * chi * (1.0_dp - chi) * adsu              ! (W.74)
        case default
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'model = '//int_str(model) &
                           //': must be 1 (CAPACITY_TC00_PEAK) or 2 (CAPACITY_EFFECTIVE_WIDTH)')
            return
        end select
        if (.not. ieee_is_finite(m_ult)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'su = '//real_str(su) &
                           //', r = '//real_str(r)//': the capacity overflows (N m)')
            m_ult = qnan
        end if
    end subroutine moment_capacity_circle

    ! ------------------------------------------------------------------------------
    ! Internals
    ! ------------------------------------------------------------------------------

    !> su, r and the bearing factor ncv = nc (default pi + 3) in [1e-30, 1e30] (the scale
    !> check of seispulse_winkler: n_c S_u pi r^2 and every later product stay finite).
    subroutine check_soil(su, r, ncv, stat, errmsg, nc)
        real(dp), intent(in) :: su, r
        real(dp), intent(out) :: ncv
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(in), optional :: nc
        ncv = NC_CIRCLE_CLAY
        if (present(nc)) ncv = nc
        call check_scale(su, 'su', 'the undrained strength', 'Pa', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(r, 'r', 'the footing radius', 'm', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scale(ncv, 'nc', 'the bearing factor', '-', stat, errmsg)
    end subroutine check_soil

    !> theta_up = 1/2 asin(N r/(2 K_R)) (W.65), NaN and none = .true. when the argument
    !> exceeds 1; inputs already checked.
    pure subroutine uplift_angle(weight, r, k_r, theta_up, none)
        real(dp), intent(in) :: weight, r, k_r
        real(dp), intent(out) :: theta_up
        logical, intent(out) :: none
        real(dp) :: s
        s = (weight / k_r) * (0.5_dp * r)
        none = .not. s <= 1.0_dp
        if (none) then
            theta_up = qnan
        else
            theta_up = 0.5_dp * asin(s)                                     ! (W.65)
        end if
    end subroutine uplift_angle

    !> a(chi), b(chi), c(chi) of (W.67) and ln(B) of (W.66) from the user's coefficients,
    !> checked; b, c and B only when a(chi) /= 0 (else NaN, NaN and ln_base = 1).
    subroutine gauss_params(chi, coeffs, a, b, c, ln_base, stat, errmsg)
        real(dp), intent(in) :: chi
        type(degradation_coeffs_t), intent(in) :: coeffs
        real(dp), intent(out) :: a, b, c, ln_base
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: i
        logical :: valid_base
        character(len=*), parameter :: lost = ': not given (NaN): the coefficients of ' &
            //'[AD11]''s Gaussian correction are lost and have no default'
        a = qnan
        b = qnan
        c = qnan
        ln_base = 1.0_dp
        stat = SEISPULSE_SUCCESS
        do i = 0, 4
            if (.not. ieee_is_finite(coeffs%a_poly(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'a_poly('//int_str(i) &
                               //') = '//real_str(coeffs%a_poly(i))//lost &
                               //' (give all five a_0..a_4, 0 for unused terms)')
                return
            end if
        end do
        a = coeffs%a_poly(4)                                                ! (W.67)
        do i = 3, 0, -1
            a = a * chi + coeffs%a_poly(i)
        end do
        if (.not. (a > -1.0_dp .and. ieee_is_finite(a))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'a_poly: a(chi) = ' &
                           //real_str(a)//' at chi = '//real_str(chi)//': must be finite and' &
                           //' > -1 (G > 0)')
            a = qnan
            return
        end if
        if (.not. abs(a) > 0.0_dp) return   ! G = 1: b, c and log_base not needed
        ! nested: a NaN log_base must not reach the ordered comparison
        valid_base = finite_positive(coeffs%log_base)
        if (valid_base) valid_base = abs(coeffs%log_base - 1.0_dp) > 0.0_dp
        if (.not. valid_base) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'log_base = ' &
                           //real_str(coeffs%log_base)//': the base B of log in G is lost' &
                           //' in [AD11] and has no default; needed when a(chi) /= 0 (b and' &
                           //' c are in log_B units): a finite number > 0, not 1')
            return
        end if
        ln_base = log(coeffs%log_base)
        if (.not. ieee_is_finite(coeffs%b1)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'b1 = ' &
                           //real_str(coeffs%b1)//lost)
        else if (.not. ieee_is_finite(coeffs%b2)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'b2 = ' &
                           //real_str(coeffs%b2)//lost)
        else if (.not. ieee_is_finite(coeffs%c1)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'c1 = ' &
                           //real_str(coeffs%c1)//lost)
        else if (.not. ieee_is_finite(coeffs%c2)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'c2 = ' &
                           //real_str(coeffs%c2)//lost)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        b = coeffs%b1 * log(chi) + coeffs%b2                                ! (W.67)
        c = coeffs%c1 * chi + coeffs%c2                                     ! (W.67)
        if (.not. (ieee_is_finite(b) .and. ieee_is_finite(c) .and. abs(c) > 0.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'c1 = ' &
                           //real_str(coeffs%c1)//', c2 = '//real_str(coeffs%c2)//', b = ' &
                           //real_str(b)//': c(chi) = c1 chi + c2 = '//real_str(c)//' at chi' &
                           //' = '//real_str(chi)//' must be finite and nonzero (b finite)')
            b = qnan
            c = qnan
        end if
    end subroutine gauss_params

    !> G = 1 + a exp(-(ln(x)/ln(B) - b)^2/(2 c^2)) (W.66); 1 at x = 0 and where the
    !> exponential underflows (no overflow for any c /= 0).
    elemental function gauss_value(a, b, c, ln_base, x) result(g)
        real(dp), intent(in) :: a, b, c, ln_base, x
        real(dp) :: g, d, z
        g = 1.0_dp
        if (.not. (abs(a) > 0.0_dp .and. x > 0.0_dp)) return
        d = log(x) / ln_base - b
        if (abs(d) > z_max * abs(c)) return
        z = d / c
        g = 1.0_dp + a * exp(-0.5_dp * z * z)
    end function gauss_value

    !> Foundation moment M_found(theta) (N m) and G at theta in [0, pi/4] (W.68)-(W.70):
    !> the constant-k Winkler circle's M_EL = K_R0 Khat(x_s) sin(theta) cos^2(theta), x_s =
    !> sin(2 theta)/sin(2 theta_up) (Khat = K_sec/K_0 of winkler_master_curve), over G.
    subroutine found_moment(f, theta, m_found, g)
        type(imposed_moment_t), intent(in) :: f
        real(dp), intent(in) :: theta
        real(dp), intent(out) :: m_found, g
        real(dp) :: k_hat, m_ratio, b_ratio, a_ratio
        call winkler_master_curve(FOOTING_CIRCLE, sin(2.0_dp * theta) / f%sin2_up, k_hat, &
                                  m_ratio, b_ratio, a_ratio)                ! (W.68)
        g = gauss_value(f%a, f%b, f%c, f%ln_base, theta / f%theta_up)     ! (W.66)
        m_found = f%k_r0 * k_hat * sin(theta) * cos(theta)**2 / g          ! (W.69)-(W.70)
    end subroutine found_moment

    !> M_imp(theta) = M_found - W h sin(theta) (W.71).
    function imposed_moment_value(f, theta) result(m_imp)
        type(imposed_moment_t), intent(in) :: f
        real(dp), intent(in) :: theta
        real(dp) :: m_imp, m_found, g
        call found_moment(f, theta, m_found, g)
        m_imp = m_found - f%weight * f%h * sin(theta)
    end function imposed_moment_value

    !> The scalars of the pushover from the branch theta in [0, pi/4], independent of the
    !> user's grid (doc/winkler.md, "The pushover"): M_imp and F/W on an internal scan (a
    !> geometric scan pi/4 2^(-k/8), k = 0..480, a uniform one in steps of pi/1024, and
    !> where a(chi) /= 0 the bell log_B(x) = b + j |c|/4, j = -24..24, i.e. b +- 6 c in steps
    !> of c/4); the peaks are the largest scan values refined by golden section between
    !> their scan neighbours, theta_overturn (W.72) is Brent's root on the first scan
    !> interval where M_imp stops being positive (0 when K_R0 <= W h; NaN when M_imp stays
    !> positive up to pi/4, or when the first scan point is not positive and halving
    !> towards 0 finds no positive value).
    subroutine branch_scalars(f, res, stat, errmsg)
        type(imposed_moment_t), intent(inout) :: f
        type(inelastic_pushover_t), intent(inout) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer, parameter :: n_geo = 481, n_uni = 255, n_bell = 49
        !> |b|, |c| beyond which the bell is not scanned: it is then either out of reach
        !> (theta = theta_up B^b) or so wide that the other scans resolve it
        real(dp), parameter :: bell_max = 1.0e4_dp
        real(dp) :: ts(n_geo + n_uni + n_bell), mv(n_geo + n_uni + n_bell), fv(n_geo + n_uni &
                    + n_bell), t, u, lnx, th_pos, f_pos, root
        integer :: i, j, k, m
        logical :: bell
        stat = SEISPULSE_SUCCESS
        m = 0
        do k = 0, n_geo - 1
            m = m + 1
            ts(m) = 0.25_dp * pi * 2.0_dp**(-real(k, dp) / 8.0_dp)
        end do
        do k = 1, n_uni
            m = m + 1
            ts(m) = 0.25_dp * pi * real(k, dp) / real(n_uni + 1, dp)
        end do
        ! nested: b and c are NaN when a = 0 (no ordered comparison with NaN)
        bell = abs(f%a) > 0.0_dp
        if (bell) bell = abs(f%b) <= bell_max .and. abs(f%c) <= bell_max
        if (bell) then
            do k = -(n_bell - 1) / 2, (n_bell - 1) / 2
                u = f%b + abs(f%c) * real(k, dp) / 4.0_dp
                lnx = u * f%ln_base                                         ! ln(x) (W.66)
                if (lnx < -700.0_dp .or. lnx > log(0.25_dp * pi / f%theta_up)) cycle
                t = f%theta_up * exp(lnx)
                if (.not. (t > 0.0_dp .and. t <= 0.25_dp * pi)) cycle
                m = m + 1
                ts(m) = t
            end do
        end if
        do i = 2, m                                 ! insertion sort, ascending
            t = ts(i)
            j = i - 1
            do while (j >= 1)
                if (ts(j) <= t) exit
                ts(j + 1) = ts(j)
                j = j - 1
            end do
            ts(j + 1) = t
        end do
        do i = 1, m
            mv(i) = imposed_moment_value(f, ts(i))
            fv(i) = mv(i) / (f%h * cos(ts(i)) * f%weight)
        end do
        ! the peaks (the scan starts above 0, where M_imp = 0)
        call scan_peak(mv, .false., res%max_moment, res%theta_at_max_moment)
        call scan_peak(fv, .true., res%max_force_over_weight, res%theta_at_max)
        ! (W.72) the overturning angle
        if (f%k_r0 <= f%weight * f%h) then
            res%theta_overturn = 0.0_dp         ! dM_imp/dtheta(0) = K_R0 - W h <= 0
            return
        end if
        j = 0
        do i = 1, m
            if (.not. mv(i) > 0.0_dp) then
                j = i
                exit
            end if
        end do
        if (j == 0) return                      ! positive up to pi/4: NaN
        if (j > 1) then
            th_pos = ts(j - 1)
            f_pos = mv(j - 1)
        else
            ! M_imp > 0 just above 0 (K_R0 > W h) but not at the first scan point: halve
            th_pos = ts(1)
            f_pos = 0.0_dp
            do k = 1, 1074
                th_pos = 0.5_dp * th_pos
                f_pos = imposed_moment_value(f, th_pos)
                if (f_pos > 0.0_dp) exit
            end do
            if (.not. f_pos > 0.0_dp) return    ! no positive value found: NaN
        end if
        call find_root(f, th_pos, ts(j), root, stat, errmsg, fa_known=f_pos, &
                       fb_known=mv(j))
        if (stat /= SEISPULSE_SUCCESS) return
        res%theta_overturn = root
    contains
        !> The largest of vals(1:m), refined between its scan neighbours (0 below the first).
        subroutine scan_peak(vals, force, v_best, t_best)
            real(dp), intent(in) :: vals(:)
            logical, intent(in) :: force
            real(dp), intent(out) :: v_best, t_best
            integer :: ib
            real(dp) :: lo
            ib = maxloc(vals(1:m), dim=1)
            v_best = vals(ib)
            t_best = ts(ib)
            if (ib == m) return
            lo = 0.0_dp
            if (ib > 1) lo = ts(ib - 1)
            call refine_peak(f, force, lo, ts(ib + 1), t_best, v_best)
        end subroutine scan_peak
    end subroutine branch_scalars

    !> The largest M_imp (force = .false., N m) or F/W (.true.) in [lo, hi] (rad, within
    !> [0, pi/4]) by the bounded minimiser of seispulse_roots; theta_best and v_best hold
    !> the best grid point on entry and are replaced by a better point found.
    subroutine refine_peak(f, force, lo, hi, theta_best, v_best)
        type(imposed_moment_t), intent(in) :: f
        logical, intent(in) :: force
        real(dp), intent(in) :: lo, hi
        real(dp), intent(inout) :: theta_best, v_best
        type(peak_fn_t) :: fn
        real(dp) :: x, fx
        integer :: stat
        fn%f = f
        fn%force = force
        call find_minimum(fn, lo, hi, x, fx, stat)
        if (stat == SEISPULSE_SUCCESS .and. -fx > v_best) then
            v_best = -fx
            theta_best = x
        end if
    end subroutine refine_peak

    function peak_fn_eval(self, x) result(y)
        class(peak_fn_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        y = -imposed_moment_value(self%f, x)
        if (self%force) y = y / (self%f%h * cos(x) * self%f%weight)
    end function peak_fn_eval

    !> The root function of the overturning angle (W.72).
    function imposed_moment_eval(self, x) result(y)
        class(imposed_moment_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        y = imposed_moment_value(self, x)
    end function imposed_moment_eval

end module seispulse_clay_footing
