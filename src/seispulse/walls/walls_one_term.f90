!> One-term (Vlasov-Leontiev / Kloukinas) solution for the dynamic earth pressure on a rigid
!> wall retaining a viscoelastic layer (doc/walls.md sections 3-6; sections 1-2 of Ref. [TEI]), and
!> its extensions: a rotational base spring, a pair of walls, equivalent Winkler springs, and the
!> exact fundamental frequency of the power-law layer (doc/walls.md section 3, not in the source).
!>
!> Model: u(x, y) = X(x) Phi(y), y up from the rock (0 <= y <= H), x from the wall into the
!> backfill. G(y) = G_H g(y) with g = 1 (homogeneous) or g = ((H - y)/H)^n (power law,
!> -1 < n < 2, G = 0 at the surface for n > 0), G* = G (1 + i delta), V_SH = sqrt(G_H/rho).
!> Shapes Phi: linear y/H, sine sin(pi y/2H), parabolic (y/H)(2 - y/H) (homogeneous only) and
!> the power-law static shape (2.68) Phi = 1 - ((H - y)/H)^(2 - n) (equal to the parabola at
!> n = 0: the same code path, so the numbers are identical).
!>
!> Per shape (eta = y/H, integrals over 0..1):
!>     a_oc^2 = int g Phi'^2 / int g Phi^2            (2.43b, 2.64a)
!>     l_factor = int Phi / int g Phi^2 (real): the source's L of 2.43c for homogeneous
!>         soil (Table 2.1: 3/2, 4/pi, 5/4), and L (1 + i delta) of 2.64c for the power law
!>     mass_factor = int Phi^2 / int g Phi^2, a_o^2 = (omega H/V_SH)^2 mass_factor/(1 + i delta)
!>     s0 = int g Phi, s1 = int g Phi eta              (2.50, 2.73 [RECON]: divided by G_H)
!>     s = sqrt(a_oc^2 - a_o^2) with Re s >= 0 (the delta -> 0+ branch: +i sqrt above cut-off)
!> Frequency convention: omega_ratio = omega/omega_ref, omega_ref = pi V_SH/(2H) for every
!> shape and n, so (omega H/V_SH) = (pi/2) omega_ratio (for homogeneous soil omega_ref is the
!> fundamental frequency omega_1 of the layer).
!>
!> Signs and units (dimensionless): thrust q > 0 for a positive rock acceleration
!> (q = -Q_b of 2.48/2.71), in rho Xg H^2; moment about the base m = q h, in rho Xg H^3;
!> pressure p(y) = -sigma_x(0, y), in rho Xg H; displacements keep the source's sign
!> (u < 0 for Xg > 0), in rho Xg H^2/G_H; base rotation theta = u0/H, in rho Xg H/G_H;
!> Winkler k in G_H/H (for the power law at height y: k g(y)); dashpot c in rho V_SH.
!> The results are the dynamic increment only (no geostatic thrust), harmonic transfer
!> functions of the rock acceleration Xg exp(i omega t).
!>
!> Errata of the source implemented in corrected form (doc/walls.md): (2.39) sign of the k*^2
!> term; (2.60)/(2.73) G* and the 1/G_H normalisation (Lf S0 real); the 2.51 claim "0.979 at
!> nu = 0.3" (0.9461; 0.9791 is nu = 1/3); (2.95) spurious G(1 + i delta); (2.102b) sign of B
!> (X(L) = 0 only with the corrected sign); (2.104) prefactor; Table 2.2's Phi column.
module seispulse_walls_one_term
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
                                             ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_SINGULAR, &
                                SEISPULSE_NO_BRACKET, SEISPULSE_NO_CONVERGENCE, set_error
    use seispulse_checks, only: outside
    use seispulse_format, only: real_str, int_str
    use seispulse_special, only: expm1, log1p, exp_expm1, pi
    use seispulse_roots, only: scalar_function, find_root
    use seispulse_walls_common, only: wall_psi_t, wall_psi, check_nu, check_delta, &
                                      check_omega_ratio, sqrt_branch, resonance_error, &
                                      inv_one_plus_i
    implicit none
    private

    public :: WALL_SHAPE_LINEAR, WALL_SHAPE_SINE, WALL_SHAPE_PARABOLIC, WALL_SHAPE_POWER
    public :: one_term_shape_t, one_term_t
    public :: one_term_shape, one_term, one_term_sweep, one_term_pressure, one_term_displacement
    public :: power_law_fundamental, power_law_cutoff, check_exponent
    public :: winkler_one_term, winkler_dashpot, winkler_scott, winkler_vy

    integer, parameter :: WALL_SHAPE_LINEAR = 1     !! Phi = y/H (homogeneous soil)
    integer, parameter :: WALL_SHAPE_SINE = 2       !! Phi = sin(pi y/2H) (homogeneous soil)
    integer, parameter :: WALL_SHAPE_PARABOLIC = 3  !! Phi = (y/H)(2 - y/H) (homogeneous soil)
    integer, parameter :: WALL_SHAPE_POWER = 4
        !! Phi = 1 - ((H - y)/H)^(2 - n), G ~ ((H - y)/H)^n (2.68)

    !> Above this (omega H/V_SH) the decay root is formed scaled (no overflow of its square).
    real(dp), parameter :: big_w = 1.0e100_dp
    !> exp(-x) is 0 in double precision beyond this.
    real(dp), parameter :: exp_cut = 746.0_dp
    !> -a_1 2^(-1/3) and (3/20) a_1^2 2^(1/3), a_1 = -2.338107410459767 the first zero of Ai:
    !> the Qu-Wong (1999) bounds nu + A nu^(1/3) < j_(nu,1) < nu + A nu^(1/3) + B nu^(-1/3), nu > 0.
    real(dp), parameter :: qw_a = 1.8557570814892386_dp
    real(dp), parameter :: qw_b = 1.0331503036492369_dp
    !> Beyond this Bessel order the Qu-Wong upper bound is the zero to rounding (its error is
    !> 0.00397/nu + O(nu^(-5/3)): below 4e-15 relative), and the continued fraction would
    !> be evaluated where rounding of x exceeds the bracket.
    real(dp), parameter :: q_asym = 1.0e6_dp
    !> Continued-fraction terms allowed (about 40 nu^(1/3) are needed at nu = 1e6).
    integer, parameter :: cf_max_terms = 200000

    !> Constants of a shape function (all dimensionless, real).
    type :: one_term_shape_t
        integer :: shape = WALL_SHAPE_SINE          !! WALL_SHAPE_LINEAR .. WALL_SHAPE_POWER
        real(dp) :: n = 0.0_dp                 !! stiffness exponent (0 for shapes 1-3)
        real(dp) :: a_oc = 0.0_dp              !! cut-off frequency a_oc (2.43b/2.64a/2.69a)
        real(dp) :: l_factor = 0.0_dp
            !! int Phi/int g Phi^2: L of 2.43c (homogeneous), L (1 + i delta) of 2.64c/2.69c
        real(dp) :: mass_factor = 0.0_dp
            !! int Phi^2/int g Phi^2: a_o^2 = (omega H/V_SH)^2 mass_factor/(1 + i delta)
        real(dp) :: s0 = 0.0_dp                !! int_0^1 g Phi d(y/H) (2.50/2.73 [RECON])
        real(dp) :: s1 = 0.0_dp                !! int_0^1 g Phi (y/H) d(y/H)
        real(dp) :: h_ratio = 0.0_dp           !! h/H = s1/s0 (2.49/2.72), frequency independent
    end type one_term_shape_t

    !> Result at one frequency (units in the module header).
    type :: one_term_t
        complex(dp) :: q = (0.0_dp, 0.0_dp)      !! thrust, rho Xg H^2, positive = compression
        complex(dp) :: m = (0.0_dp, 0.0_dp)      !! base moment q h, rho Xg H^3
        real(dp) :: h_ratio = 0.0_dp             !! h/H of the resultant
        complex(dp) :: u_ff0 = (0.0_dp, 0.0_dp)
            !! free-field surface displacement (2.98), rho Xg H^2/G_H
        complex(dp) :: u0 = (0.0_dp, 0.0_dp)     !! wall-top displacement (2.99b), rho Xg H^2/G_H
        complex(dp) :: theta = (0.0_dp, 0.0_dp)  !! base rotation u0/H, rho Xg H/G_H
        complex(dp) :: lambda = (1.0_dp, 0.0_dp) !! pair factor tanh(mL/2) (2.105); 1 for one wall
        complex(dp) :: flex = (1.0_dp, 0.0_dp)   !! Q/Q_rigid of the rotational spring (2.96)
        complex(dp) :: s = (0.0_dp, 0.0_dp)      !! sqrt(a_oc^2 - a_o^2), Re >= 0
    end type one_term_t

    !> x J_q(x)/J_(q+1)(x), whose first positive zero is j_(q,1) (for the Brent search).
    type, extends(scalar_function) :: bessel_ratio_t
        real(dp) :: q = 0.0_dp          !! Bessel order, > -1
        logical :: failed = .false.     !! the continued fraction did not converge
    contains
        procedure :: eval => bessel_ratio_eval
    end type bessel_ratio_t

contains

    ! ------------------------------------------------------------------ shape constants

    !> The power-law exponent n must lie in (-1, 2) (the integrals (2.69) diverge at -1, the
    !> shape (2.68) degenerates at 2).
    pure subroutine check_exponent(n, stat, errmsg)
        real(dp), intent(in) :: n                          !! stiffness exponent of G ~ depth^n
        integer, intent(out) :: stat
            !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! "n = ...: ..." on error
        stat = SEISPULSE_SUCCESS
        if (outside(n, -1.0_dp, 2.0_dp, .true., .true.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'n = '//real_str(n)// &
                           ': the stiffness exponent must lie in (-1, 2)')
    end subroutine check_exponent

    !> Constants of a shape function, in closed form: Table 2.1 for the homogeneous shapes,
    !> (2.69) with s0 = (2 - n)/(3(1 + n)), s1 = (2 - n)(5 + n)/(12(1 + n)(2 + n)) and
    !> h/H = (5 + n)/(4(2 + n)) for the power law (the parabola is the power law at n = 0).
    pure subroutine one_term_shape(shape, n, c, stat, errmsg)
        integer, intent(in) :: shape
            !! WALL_SHAPE_LINEAR, _SINE, _PARABOLIC or _POWER
        real(dp), intent(in) :: n
            !! exponent: 0 for shapes 1-3, (-1, 2) for WALL_SHAPE_POWER
        type(one_term_shape_t), intent(out) :: c           !! the constants
        integer, intent(out) :: stat
            !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! message naming shape or n
        real(dp) :: a2
        stat = SEISPULSE_SUCCESS
        select case (shape)
        case (WALL_SHAPE_LINEAR, WALL_SHAPE_SINE, WALL_SHAPE_PARABOLIC)
            if (outside(n, 0.0_dp, 0.0_dp, .false., .false.)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'n = '//real_str(n)// &
                               ': the linear, sine and parabolic shapes are for homogeneous '// &
                               'soil (n = 0); use the power-law shape for n different from 0')
                return
            end if
        case (WALL_SHAPE_POWER)
            call check_exponent(n, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        case default
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'shape = '//int_str(shape)// &
                           ': must be 1 (linear), 2 (sine), 3 (parabolic) or 4 (power law)')
            return
        end select
        c%shape = shape
        c%n = n
        select case (shape)
        case (WALL_SHAPE_LINEAR)
            ! Table 2.1: int Phi'^2 = 1, int Phi^2 = 1/3, int Phi = 1/2, int Phi eta = 1/3
            c%a_oc = sqrt(3.0_dp)
            c%l_factor = 1.5_dp
            c%mass_factor = 1.0_dp
            c%s0 = 0.5_dp
            c%s1 = 1.0_dp/3.0_dp
            c%h_ratio = 2.0_dp/3.0_dp
        case (WALL_SHAPE_SINE)
            ! Table 2.1: int Phi'^2 = pi^2/8, int Phi^2 = 1/2, int Phi = 2/pi, int Phi eta = 4/pi^2
            c%a_oc = 0.5_dp*pi
            c%l_factor = 4.0_dp/pi
            c%mass_factor = 1.0_dp
            c%s0 = 2.0_dp/pi
            c%s1 = 4.0_dp/pi**2
            c%h_ratio = 2.0_dp/pi
        case default
            ! (2.69a-c) with the power-law shape (2.68); WALL_SHAPE_PARABOLIC is n = 0 exactly
            a2 = 1.5_dp*(5.0_dp - n)*(1.0_dp + n)/(3.0_dp - n)
            c%a_oc = sqrt(a2)
            c%l_factor = a2/(2.0_dp - n)
            c%mass_factor = 2.0_dp*a2/(5.0_dp - 2.0_dp*n)
            c%s0 = (2.0_dp - n)/(3.0_dp*(1.0_dp + n))
            ! 1/((n+1)(n+2)) - 1/12 without the cancellation as n -> 2
            c%s1 = (2.0_dp - n)*(5.0_dp + n)/(12.0_dp*(1.0_dp + n)*(2.0_dp + n))
            c%h_ratio = (5.0_dp + n)/(4.0_dp*(2.0_dp + n))
        end select
    end subroutine one_term_shape

    !> Phi(eta), eta = y/H in [0, 1].
    elemental function shape_value(shape, n, eta) result(phi)
        integer, intent(in) :: shape
        real(dp), intent(in) :: n, eta
        real(dp) :: phi
        select case (shape)
        case (WALL_SHAPE_LINEAR)
            phi = eta
        case (WALL_SHAPE_SINE)
            phi = sin(0.5_dp*pi*eta)
        case default
            ! (2.68) 1 - (1 - eta)^(2 - n), as -expm1 near the base (small eta)
            if (eta >= 1.0_dp) then
                phi = 1.0_dp
            else
                phi = -expm1((2.0_dp - n)*log1p(-eta))
            end if
        end select
    end function shape_value

    !> g(eta) = G/G_H = (1 - eta)^n (1 for n = 0); eta < 1 when n < 0.
    elemental function stiffness_value(n, eta) result(g)
        real(dp), intent(in) :: n, eta
        real(dp) :: g
        if (.not. outside(n, 0.0_dp, 0.0_dp, .false., .false.)) then
            g = 1.0_dp
        else if (eta >= 1.0_dp .and. n > 0.0_dp) then
            g = 0.0_dp
        else if (eta >= 1.0_dp) then
            g = huge(1.0_dp)     ! n < 0: G is unbounded at the surface (callers refuse it)
        else
            g = (1.0_dp - eta)**n
        end if
    end function stiffness_value

    ! ------------------------------------------------------------------ the one-term solution

    !> Rigid wall, rotational base spring or pair of walls at one frequency (doc/walls.md sections
    !> 3-5).
    !>
    !> Rigid wall (2.48/2.71): q = psi_sigma Lf s0/s, h/H = s1/s0, u_ff0 = -Lf/((1 + i delta) s^2).
    !> Rotational spring (2.96 [RECON], 2.99b): q = q_rigid F, F = 1/(1 + psi_sigma s s0 (h/H)
    !> (1 + i delta) d_theta), u0 = (1 - F) u_ff0, theta = u0/H; d_theta = +inf is the hinge
    !> (K_R = 0): q = 0, u0 = u_ff0. Pair of walls at distance L (2.105-2.107): q = q_single
    !> tanh(mL/2), mL = s (L/H)/psi_e (|lambda| may exceed 1 near the cut-off); not derived
    !> for d_theta > 0 (refused). delta = 0 exactly at the cut-off (s = 0) is SEISPULSE_SINGULAR.
    pure subroutine one_term(omega_ratio, delta, nu, shape, n, d_theta, l_over_h, res, stat, &
                             errmsg)
        real(dp), intent(in) :: omega_ratio
            !! omega/omega_ref, omega_ref = pi V_SH/(2H), >= 0
        real(dp), intent(in) :: delta
            !! loss factor, G* = G (1 + i delta), >= 0
        real(dp), intent(in) :: nu                         !! Poisson's ratio, [0, 0.5)
        integer, intent(in) :: shape                       !! WALL_SHAPE_LINEAR .. WALL_SHAPE_POWER
        real(dp), intent(in) :: n
            !! stiffness exponent (0 unless WALL_SHAPE_POWER)
        real(dp), intent(in) :: d_theta
            !! rotational flexibility H^2 G_H/K_R, >= 0 (+inf: hinge)
        real(dp), intent(in) :: l_over_h                   !! wall spacing L/H, > 0 (+inf: one wall)
        type(one_term_t), intent(out) :: res               !! the solution
        integer, intent(out) :: stat                       !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(wall_psi_t) :: psi
        type(one_term_shape_t) :: c
        call validate(delta, nu, shape, n, d_theta, l_over_h, psi, c, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call solve(omega_ratio, delta, psi, c, d_theta, l_over_h, res, stat, errmsg)
    end subroutine one_term

    !> Thrust and moment of `one_term` over an array of frequencies.
    pure subroutine one_term_sweep(omega_ratios, delta, nu, shape, n, d_theta, l_over_h, q, m, &
                                   stat, errmsg)
        real(dp), intent(in) :: omega_ratios(:)            !! omega/omega_ref, each >= 0
        real(dp), intent(in) :: delta                      !! loss factor, >= 0
        real(dp), intent(in) :: nu                         !! Poisson's ratio, [0, 0.5)
        integer, intent(in) :: shape                       !! WALL_SHAPE_LINEAR .. WALL_SHAPE_POWER
        real(dp), intent(in) :: n                          !! stiffness exponent
        real(dp), intent(in) :: d_theta                    !! rotational flexibility, >= 0
        real(dp), intent(in) :: l_over_h                   !! L/H, > 0 (+inf: one wall)
        complex(dp), intent(out) :: q(:)
            !! thrust, rho Xg H^2 (size of omega_ratios)
        complex(dp), intent(out) :: m(:)
            !! base moment, rho Xg H^3 (size of omega_ratios)
        integer, intent(out) :: stat                       !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(wall_psi_t) :: psi
        type(one_term_shape_t) :: c
        type(one_term_t) :: res
        integer :: i
        q = (0.0_dp, 0.0_dp)
        m = (0.0_dp, 0.0_dp)
        if (size(q) /= size(omega_ratios) .or. size(m) /= size(omega_ratios)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'q, m: must have the size '// &
                           'of omega_ratios ('//int_str(size(omega_ratios))//')')
            return
        end if
        call validate(delta, nu, shape, n, d_theta, l_over_h, psi, c, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        do i = 1, size(omega_ratios)
            call solve(omega_ratios(i), delta, psi, c, d_theta, l_over_h, res, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            q(i) = res%q
            m(i) = res%m
        end do
    end subroutine one_term_sweep

    !> Wall pressure p(y) = -sigma_x(0, y) = psi_sigma Lf g(y) Phi(y) F Lambda/s (2.47/2.70),
    !> proportional to G(y) Phi(y) at every frequency; integrates to q, its first moment to m.
    pure subroutine one_term_pressure(omega_ratio, delta, nu, shape, n, d_theta, l_over_h, y, p, &
                                      stat, errmsg)
        real(dp), intent(in) :: omega_ratio                !! omega/omega_ref, >= 0
        real(dp), intent(in) :: delta                      !! loss factor, >= 0
        real(dp), intent(in) :: nu                         !! Poisson's ratio, [0, 0.5)
        integer, intent(in) :: shape                       !! WALL_SHAPE_LINEAR .. WALL_SHAPE_POWER
        real(dp), intent(in) :: n                          !! stiffness exponent
        real(dp), intent(in) :: d_theta                    !! rotational flexibility, >= 0
        real(dp), intent(in) :: l_over_h                   !! L/H, > 0 (+inf: one wall)
        real(dp), intent(in) :: y(:)
            !! heights above the base y/H in [0, 1] ([0, 1) if n < 0)
        complex(dp), intent(out) :: p(:)                   !! pressure, rho Xg H (size of y)
        integer, intent(out) :: stat                       !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(wall_psi_t) :: psi
        type(one_term_shape_t) :: c
        type(one_term_t) :: res
        complex(dp) :: amp
        integer :: i
        p = (0.0_dp, 0.0_dp)
        if (size(p) /= size(y)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'p: must have the size of y ('// &
                           int_str(size(y))//')')
            return
        end if
        call validate(delta, nu, shape, n, d_theta, l_over_h, psi, c, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        do i = 1, size(y)
            call check_height(y(i), i, n, .true., stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end do
        call solve(omega_ratio, delta, psi, c, d_theta, l_over_h, res, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        amp = (psi%sigma*c%l_factor/res%s)*res%flex*res%lambda
        do i = 1, size(y)
            p(i) = amp*(stiffness_value(n, y(i))*shape_value(c%shape, n, y(i)))
        end do
    end subroutine one_term_pressure

    !> Horizontal displacement u(x, y) = X(x) Phi(y) relative to the rock:
    !> one wall (2.46/2.67, 2.93): X = u_ff0 (1 - exp(-m x)) + u0 exp(-m x), m x = s (x/H)/psi_e;
    !> pair (2.103 with the corrected B of 2.102b): X = u_ff0 (1 - exp(-m x))(1 - exp(-m (L - x)))
    !> /(1 + exp(-m L)) = u_ff0 [1 - cosh(m (x - L/2))/cosh(m L/2)], so X(0) = X(L) = 0.
    !> u at (x(i), y(i)) pairs.
    pure subroutine one_term_displacement(omega_ratio, delta, nu, shape, n, d_theta, l_over_h, &
                                          x, y, u, stat, errmsg)
        real(dp), intent(in) :: omega_ratio                !! omega/omega_ref, >= 0
        real(dp), intent(in) :: delta                      !! loss factor, >= 0
        real(dp), intent(in) :: nu                         !! Poisson's ratio, [0, 0.5)
        integer, intent(in) :: shape                       !! WALL_SHAPE_LINEAR .. WALL_SHAPE_POWER
        real(dp), intent(in) :: n                          !! stiffness exponent
        real(dp), intent(in) :: d_theta                    !! rotational flexibility, >= 0
        real(dp), intent(in) :: l_over_h                   !! L/H, > 0 (+inf: one wall)
        real(dp), intent(in) :: x(:)
            !! distances from the wall x/H, finite, in [0, L/H]
        real(dp), intent(in) :: y(:)
            !! heights above the base y/H in [0, 1] (size of x)
        complex(dp), intent(out) :: u(:)
            !! displacement, rho Xg H^2/G_H (size of x)
        integer, intent(out) :: stat                       !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(wall_psi_t) :: psi
        type(one_term_shape_t) :: c
        type(one_term_t) :: res
        complex(dp) :: e_x, em1_x, e_r, em1_r, e_l, em1_l
        logical :: pair
        integer :: i
        u = (0.0_dp, 0.0_dp)
        if (size(y) /= size(x) .or. size(u) /= size(x)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'y, u: must have the size '// &
                           'of x ('//int_str(size(x))//')')
            return
        end if
        call validate(delta, nu, shape, n, d_theta, l_over_h, psi, c, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        pair = ieee_is_finite(l_over_h)
        do i = 1, size(x)
            if (pair) then
                if (outside(x(i), 0.0_dp, l_over_h, .false., .false.)) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'x('//int_str(i)// &
                                   ') = '//real_str(x(i))//': must lie between the walls, '// &
                                   'in [0, l_over_h = '//real_str(l_over_h)//']')
                    return
                end if
            else if (outside(x(i), 0.0_dp, huge(1.0_dp), .false., .false.)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'x('//int_str(i)//') = '// &
                               real_str(x(i))//': the distance from the wall must be '// &
                               'finite and >= 0')
                return
            end if
            call check_height(y(i), i, n, .false., stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end do
        call solve(omega_ratio, delta, psi, c, d_theta, l_over_h, res, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (pair) then
            call decay(res%s, psi%e, l_over_h, 'l_over_h', e_l, em1_l, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end if
        do i = 1, size(x)
            call decay(res%s, psi%e, x(i), 'x('//int_str(i)//')', e_x, em1_x, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            if (pair) then
                ! (2.103), corrected B: the product form has no cancellation for small m L and
                ! only exponentials with Re <= 0 (no overflow for huge L/H)
                call decay(res%s, psi%e, l_over_h - x(i), 'x('//int_str(i)//')', e_r, em1_r, &
                           stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                u(i) = res%u_ff0*(em1_x*em1_r/(1.0_dp + e_l))
            else
                ! (2.93): (u0 - u_ff0) exp(-m x) + u_ff0; (2.46) for u0 = 0, stable -expm1
                u(i) = -res%u_ff0*em1_x + res%u0*e_x
            end if
            u(i) = u(i)*shape_value(c%shape, n, y(i))
        end do
    end subroutine one_term_displacement

    !> Height check: y/H in [0, 1]; at y = H the pressure is unbounded when n < 0.
    pure subroutine check_height(y, i, n, for_pressure, stat, errmsg)
        real(dp), intent(in) :: y, n
        integer, intent(in) :: i
        logical, intent(in) :: for_pressure
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (outside(y, 0.0_dp, 1.0_dp, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'y('//int_str(i)//') = '// &
                           real_str(y)//': the height above the base y/H must lie in [0, 1]')
        else if (for_pressure .and. n < 0.0_dp .and. y >= 1.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'y('//int_str(i)//') = 1: '// &
                           'for n < 0 the pressure (proportional to G(y)) is unbounded at the '// &
                           'surface; give y/H < 1')
        end if
    end subroutine check_height

    !> Checks shared by the solution routines (all but omega_ratio).
    pure subroutine validate(delta, nu, shape, n, d_theta, l_over_h, psi, c, stat, errmsg)
        real(dp), intent(in) :: delta, nu, n, d_theta, l_over_h
        integer, intent(in) :: shape
        type(wall_psi_t), intent(out) :: psi
        type(one_term_shape_t), intent(out) :: c
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call check_delta(delta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call wall_psi(nu, psi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call one_term_shape(shape, n, c, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (ieee_is_nan(d_theta)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'd_theta = NaN: the '// &
                           'rotational flexibility H^2 G_H/K_R must be >= 0 (0 rigid, +inf hinge)')
            return
        end if
        if (d_theta < 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'd_theta = '// &
                           real_str(d_theta)//': the rotational flexibility H^2 G_H/K_R must '// &
                           'be >= 0 (0 rigid, +inf hinge)')
            return
        end if
        if (ieee_is_nan(l_over_h)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'l_over_h = NaN: the wall '// &
                           'spacing L/H must be > 0 (+inf: one wall)')
            return
        end if
        if (.not. (l_over_h > 0.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'l_over_h = '// &
                           real_str(l_over_h)//': the wall spacing L/H must be > 0 '// &
                           '(+inf: one wall)')
            return
        end if
        if (ieee_is_finite(l_over_h) .and. d_theta > 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'd_theta = '// &
                           real_str(d_theta)//': a pair of walls (finite l_over_h) on '// &
                           'rotational springs is not '// &
                           'derived in the source; give d_theta = 0 or l_over_h = +inf')
        end if
    end subroutine validate

    !> s = sqrt(a_oc^2 - a_o^2) on the delta -> 0+ branch (Re s >= 0; +i sqrt above the
    !> cut-off when delta = 0). The argument's imaginary part W^2 mf delta/(1 + delta^2) >= 0.
    elemental function decay_root(omega_ratio, delta, c) result(s)
        real(dp), intent(in) :: omega_ratio, delta
        type(one_term_shape_t), intent(in) :: c
        complex(dp) :: s
        real(dp) :: w
        w = 0.5_dp*pi*omega_ratio     ! omega H/V_SH (omega_ref convention)
        if (w <= big_w) then
            ! a_oc^2 and W^2 rounded alike: exactly 0 at the sine cut-off omega_ratio = 1
            s = sqrt_branch(cmplx(c%a_oc**2, 0.0_dp, dp) - &
                            (w*w*c%mass_factor)*inv_one_plus_i(delta))
        else
            s = w*sqrt_branch(cmplx((c%a_oc**2/w)/w, 0.0_dp, dp) - &
                              c%mass_factor*inv_one_plus_i(delta))
        end if
    end function decay_root

    !> The solution at one frequency, inputs other than omega_ratio already checked.
    pure subroutine solve(omega_ratio, delta, psi, c, d_theta, l_over_h, res, stat, errmsg)
        real(dp), intent(in) :: omega_ratio, delta, d_theta, l_over_h
        type(wall_psi_t), intent(in) :: psi
        type(one_term_shape_t), intent(in) :: c
        type(one_term_t), intent(out) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        complex(dp) :: onep, coef, e_l, em1_l, one_minus_f, q_rigid
        real(dp) :: r
        call check_omega_ratio(omega_ratio, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        res%s = decay_root(omega_ratio, delta, c)
        if (.not. (abs(res%s) > 0.0_dp)) then
            ! delta = 0 exactly at the cut-off a_o = a_oc: unbounded free field and thrust
            call resonance_error(omega_ratio, 'the one-term cut-off a_o = a_oc', stat, errmsg)
            return
        end if
        onep = cmplx(1.0_dp, delta, dp)
        res%h_ratio = c%h_ratio
        ! (2.48)/(2.71) with L (1 + i delta) = l_factor and s0 real (2.73 [RECON])
        q_rigid = (psi%sigma*c%l_factor*c%s0)/res%s
        ! (2.98): free field at the surface, Phi(H) = 1
        res%u_ff0 = -((c%l_factor*inv_one_plus_i(delta))/res%s)/res%s
        res%lambda = (1.0_dp, 0.0_dp)
        res%flex = (1.0_dp, 0.0_dp)
        res%u0 = (0.0_dp, 0.0_dp)
        if (ieee_is_finite(l_over_h)) then
            ! (2.105)-(2.107): Lambda = tanh(mL/2) = -expm1(-mL)/(1 + exp(-mL)), overflow-safe
            call decay(res%s, psi%e, l_over_h, 'l_over_h', e_l, em1_l, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            if (.not. (abs(1.0_dp + e_l) > 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_SINGULAR, 'l_over_h = '// &
                               real_str(l_over_h)//': standing-wave resonance of the undamped '// &
                               'pair (cosh(mL/2) = 0); give delta > 0')
                return
            end if
            res%lambda = -em1_l/(1.0_dp + e_l)
        else if (d_theta > 0.0_dp) then
            ! (2.96 [RECON], no G in 2.95): F = 1/(1 + coef d_theta),
            ! coef = psi_sigma s s0 (h/H)(1 + i delta)
            coef = (psi%sigma*c%s0*c%h_ratio)*(onep*res%s)
            if (d_theta <= 1.0_dp) then
                res%flex = 1.0_dp/(1.0_dp + coef*d_theta)
                one_minus_f = (coef*d_theta)*res%flex
            else
                r = 1.0_dp/d_theta                   ! 0 for the hinge d_theta = +inf
                res%flex = r/(r + coef)
                one_minus_f = coef/(r + coef)
            end if
            res%u0 = one_minus_f*res%u_ff0             ! (2.99b)
        end if
        res%theta = res%u0                             ! theta = u0/H, in rho Xg H/G_H
        res%q = q_rigid*res%flex*res%lambda
        res%m = res%q*c%h_ratio
        if (.not. (finite_c(res%q) .and. finite_c(res%u_ff0) .and. finite_c(res%u0) .and. &
                   finite_c(res%m))) then
            call set_error(stat, errmsg, SEISPULSE_SINGULAR, 'omega_ratio = '// &
                           real_str(omega_ratio)//': the response overflows (too close to the '// &
                           'one-term cut-off with delta = '//real_str(delta)//')')
        end if
    end subroutine solve

    elemental logical function finite_c(z)
        complex(dp), intent(in) :: z
        finite_c = ieee_is_finite(real(z, dp)) .and. ieee_is_finite(aimag(z))
    end function finite_c

    !> e = exp(-w), em1 = expm1(-w) for w = s xlen/psi_e (Re w >= 0), overflow-safe: e = 0 once
    !> Re w is past the exponent range; an undamped wave (Re w = 0) whose phase overflows is
    !> refused.
    pure subroutine decay(s, psi_e, xlen, name, e, em1, stat, errmsg)
        complex(dp), intent(in) :: s
        real(dp), intent(in) :: psi_e, xlen
        character(len=*), intent(in) :: name   !! the argument that gave xlen, for messages
        complex(dp), intent(out) :: e, em1
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: wr, wi
        stat = SEISPULSE_SUCCESS
        wr = (real(s, dp)/psi_e)*xlen
        wi = (aimag(s)/psi_e)*xlen
        if (wr > exp_cut) then
            e = (0.0_dp, 0.0_dp)
            em1 = (-1.0_dp, 0.0_dp)
        else if (.not. ieee_is_finite(wi)) then
            e = (0.0_dp, 0.0_dp)
            em1 = (0.0_dp, 0.0_dp)
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name//': the phase of the '// &
                           'undamped wave over '//real_str(xlen)//' H overflows; give a '// &
                           'smaller '//name//' or delta > 0')
        else
            call exp_expm1(cmplx(-wr, -wi, dp), e, em1)
        end if
    end subroutine decay

    ! ------------------------------------------------------------------ Winkler springs

    !> Equivalent Winkler spring (2.110): k = sigma_x(0, y)/u_ff(y) = psi_sigma s (1 + i delta),
    !> in G_H/H, independent of depth for homogeneous soil; for the power law it is the base
    !> value and k(y) = k G(y)/G_H. Static sine: (pi/2) psi_sigma (2.112). Zero at the cut-off.
    pure subroutine winkler_one_term(omega_ratio, delta, nu, shape, n, k, stat, errmsg)
        real(dp), intent(in) :: omega_ratio                !! omega/omega_ref, >= 0
        real(dp), intent(in) :: delta                      !! loss factor, >= 0
        real(dp), intent(in) :: nu                         !! Poisson's ratio, [0, 0.5)
        integer, intent(in) :: shape                       !! WALL_SHAPE_LINEAR .. WALL_SHAPE_POWER
        real(dp), intent(in) :: n                          !! stiffness exponent
        complex(dp), intent(out) :: k                      !! spring modulus, G_H/H (complex)
        integer, intent(out) :: stat
            !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(wall_psi_t) :: psi
        type(one_term_shape_t) :: c
        k = (0.0_dp, 0.0_dp)
        call validate(delta, nu, shape, n, 0.0_dp, ieee_value(1.0_dp, ieee_positive_inf), psi, &
                      c, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_omega_ratio(omega_ratio, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        k = psi%sigma*(cmplx(1.0_dp, delta, dp)*decay_root(omega_ratio, delta, c))
    end subroutine winkler_one_term

    !> High-frequency dashpot (2.111) for delta = 0 above the cut-off: k = i omega c with
    !> c/(rho V_SH) = psi_sigma sqrt(a_o^2 - a_oc^2)/(omega H/V_SH) (for the power law times
    !> G(y)/G_H). Refused below the cut-off (there the spring is real: use winkler_one_term).
    pure subroutine winkler_dashpot(omega_ratio, nu, shape, n, c, stat, errmsg)
        real(dp), intent(in) :: omega_ratio
            !! omega/omega_ref, at or above the cut-off
        real(dp), intent(in) :: nu                         !! Poisson's ratio, [0, 0.5)
        integer, intent(in) :: shape                       !! WALL_SHAPE_LINEAR .. WALL_SHAPE_POWER
        real(dp), intent(in) :: n                          !! stiffness exponent
        real(dp), intent(out) :: c                         !! dashpot, rho V_SH
        integer, intent(out) :: stat
            !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(wall_psi_t) :: psi
        type(one_term_shape_t) :: sc
        real(dp) :: w, d, ratio_c
        c = 0.0_dp
        call validate(0.0_dp, nu, shape, n, 0.0_dp, ieee_value(1.0_dp, ieee_positive_inf), psi, &
                      sc, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_omega_ratio(omega_ratio, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        w = 0.5_dp*pi*omega_ratio
        if (w <= big_w) then
            d = w*w*sc%mass_factor - sc%a_oc**2
        else
            d = sc%mass_factor - (sc%a_oc**2/w)/w
        end if
        if (d < 0.0_dp .or. .not. (w > 0.0_dp)) then
            ratio_c = sc%a_oc/sqrt(sc%mass_factor)/(0.5_dp*pi)
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'omega_ratio = '// &
                           real_str(omega_ratio)//': the dashpot (2.111) holds above the '// &
                           'cut-off omega_ratio = '//real_str(ratio_c)//'; below it use the '// &
                           'spring (2.110)')
            return
        end if
        if (w <= big_w) then
            c = psi%sigma*sqrt(d)/w
        else
            c = psi%sigma*sqrt(d)
        end if
    end subroutine winkler_dashpot

    !> Scott (1973) spring (2.113): K_s = 0.8 (1 - nu)/(1 - 2 nu) G/H, frequency independent,
    !> undamped, unbounded as nu -> 0.5.
    pure subroutine winkler_scott(nu, k, stat, errmsg)
        real(dp), intent(in) :: nu                         !! Poisson's ratio, [0, 0.5)
        real(dp), intent(out) :: k                         !! spring modulus, G/H
        integer, intent(out) :: stat
            !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        k = 0.0_dp
        call check_nu(nu, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        k = 0.8_dp*(1.0_dp - nu)/(1.0_dp - 2.0_dp*nu)
    end subroutine winkler_scott

    !> Veletsos-Younan (1994b) spring of mode j (2.114):
    !> K_j = ((2j - 1) pi/2) psi_o sqrt(1 + i delta) sqrt(1 - phi_j^2 + i delta) G/H,
    !> phi_j = omega_ratio/(2j - 1) (omega_ratio = omega/omega_1). The printed
    !> sqrt((1 + i delta)(1 - phi_j^2 + i delta)) is read as this product of principal roots
    !> (Im K >= 0, a positive dashpot), the delta -> 0+ limit; the principal root of the product
    !> has the opposite sign once phi_j^2 > 2 (and delta > 0). Static j = 1: (pi/2) psi_o.
    pure subroutine winkler_vy(mode, omega_ratio, delta, nu, k, stat, errmsg)
        integer, intent(in) :: mode                        !! mode j >= 1
        real(dp), intent(in) :: omega_ratio                !! omega/omega_1, >= 0
        real(dp), intent(in) :: delta                      !! loss factor, >= 0
        real(dp), intent(in) :: nu                         !! Poisson's ratio, [0, 0.5)
        complex(dp), intent(out) :: k                      !! spring modulus, G/H (complex)
        integer, intent(out) :: stat
            !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(wall_psi_t) :: psi
        real(dp) :: odd, phi, r
        complex(dp) :: root
        k = (0.0_dp, 0.0_dp)
        if (mode < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'mode = '//int_str(mode)// &
                           ': the mode number j must be >= 1')
            return
        end if
        call check_omega_ratio(omega_ratio, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_delta(delta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call wall_psi(nu, psi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        odd = 2.0_dp*real(mode, dp) - 1.0_dp
        phi = omega_ratio/odd
        if (phi <= 1.0_dp) then
            root = sqrt_branch(cmplx((1.0_dp - phi)*(1.0_dp + phi), delta, dp))
            k = (odd*0.5_dp*pi*psi%o)*(sqrt(cmplx(1.0_dp, delta, dp))*root)
        else
            ! phi sqrt((1/phi - 1)(1/phi + 1) + i delta/phi^2): no overflow of phi^2
            r = 1.0_dp/phi
            root = sqrt_branch(cmplx((r - 1.0_dp)*(r + 1.0_dp), (delta*r)*r, dp))
            k = (0.5_dp*pi*psi%o*omega_ratio)*(sqrt(cmplx(1.0_dp, delta, dp))*root)
        end if
    end subroutine winkler_vy

    ! ------------------------------------------------------------------ power-law layer frequency

    !> Cut-off of the one-term power-law model, omega_c H/V_SH = sqrt((5 - 2n)/2) (from 2.69a,b);
    !> assumes -1 < n < 2 (see check_exponent). 0.7 % (n = 0) to 1.9 % (n = 1) above the
    !> exact fundamental frequency (power_law_fundamental).
    pure function power_law_cutoff(n) result(w)
        real(dp), intent(in) :: n  !! stiffness exponent, -1 < n < 2
        real(dp) :: w              !! omega_c H/V_SH
        w = sqrt(0.5_dp*(5.0_dp - 2.0_dp*n))
    end function power_law_cutoff

    !> Exact fundamental frequency of the power-law layer G = G_H ((H - y)/H)^n on rock
    !> (doc/walls.md section 3, not in the source): omega_1 H/V_SH = ((2 - n)/2) j_(q,1) with
    !> q = -(1 - n)/(2 - n) and j_(q,1) the first positive zero of J_q.
    !>
    !> Method: j_(q,1) is the zero of T(x) = x J_q(x)/J_(q+1)(x) = 2(q + 1) - x^2/T_(q+1)(x),
    !> T_(q+1) by its continued fraction (modified Lentz), found by Brent's method on a
    !> proven bracket inside (0, j_(q+1,1)) where T is continuous: -1 < q < 1, the
    !> Euler-Rayleigh bounds 4(q+1) sqrt(q+2) < j^2 < 2(q+1)(q+3) (Rayleigh sums sigma_2,
    !> sigma_3; Watson 15.51); q >= 1, the Qu-Wong (1999) bounds q + A q^(1/3) < j <
    !> q + A q^(1/3) + B q^(-1/3). The sign change is checked (SEISPULSE_NO_BRACKET otherwise).
    !> For q > 1e6 (n > 2 - 1e-6) the Qu-Wong upper bound is returned (error < 4e-15 relative).
    !> Accuracy: a few units of rounding (relative error < 1e-14) for every n in (-1, 2);
    !> omega_1 H/V_SH -> 1/2 as n -> 2 and 3 j_(-2/3,1)/2 = 1.8645 as n -> -1.
    subroutine power_law_fundamental(n, w1, stat, errmsg)
        real(dp), intent(in) :: n                          !! stiffness exponent, -1 < n < 2
        real(dp), intent(out) :: w1                        !! omega_1 H/V_SH
        integer, intent(out) :: stat                       !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(bessel_ratio_t) :: f
        real(dp) :: p, q, lo, hi, t_lo, t_hi, x
        w1 = 0.0_dp
        call check_exponent(n, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        p = 2.0_dp - n
        q = (n - 1.0_dp)/p
        if (q > q_asym) then
            w1 = 0.5_dp*p*(q + qw_a*q**(1.0_dp/3.0_dp) + qw_b*q**(-1.0_dp/3.0_dp))
            return
        end if
        if (q < 1.0_dp) then
            lo = sqrt(4.0_dp*(q + 1.0_dp)*sqrt(q + 2.0_dp))
            hi = sqrt(2.0_dp*(q + 1.0_dp)*(q + 3.0_dp))
        else
            lo = q + qw_a*q**(1.0_dp/3.0_dp)
            hi = lo + qw_b*q**(-1.0_dp/3.0_dp)
        end if
        f%q = q
        t_lo = f%eval(lo)
        t_hi = f%eval(hi)
        if (f%failed) then
            call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, 'n = '//real_str(n)// &
                           ': the continued fraction of J_(q+1)/J_(q+2) did not converge')
            return
        end if
        if (.not. (t_lo > 0.0_dp .and. t_hi < 0.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_NO_BRACKET, 'n = '//real_str(n)// &
                           ': the bounds on j_(q,1) do not bracket a sign change (please report)')
            return
        end if
        call find_root(f, lo, hi, x, stat, errmsg, fa_known=t_lo, fb_known=t_hi)
        if (stat /= SEISPULSE_SUCCESS) return
        if (f%failed) then
            call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, 'n = '//real_str(n)// &
                           ': the continued fraction of J_(q+1)/J_(q+2) did not converge')
            return
        end if
        w1 = 0.5_dp*p*x
    end subroutine power_law_fundamental

    !> T_q(x) = x J_q(x)/J_(q+1)(x) = 2(q + 1) - x^2/T_(q+1)(x), with T_(q+1) from the
    !> continued fraction 2(q+2) - x^2/(2(q+3) - x^2/(2(q+4) - ...)) (Lentz). The absolute
    !> error is about eps 2(q + 1) and the slope at the zero is -x: the zero to rounding.
    function bessel_ratio_eval(self, x) result(t)
        class(bessel_ratio_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: t
        real(dp), parameter :: tiny_cf = 1.0e-300_dp
        real(dp) :: a, b, f, cc, d, del
        integer :: k
        a = -x*x
        f = 2.0_dp*(self%q + 2.0_dp)
        cc = f
        d = 0.0_dp
        do k = 1, cf_max_terms
            b = 2.0_dp*(self%q + 2.0_dp + real(k, dp))
            d = b + a*d
            if (abs(d) < tiny_cf) d = tiny_cf
            cc = b + a/cc
            if (abs(cc) < tiny_cf) cc = tiny_cf
            d = 1.0_dp/d
            del = cc*d
            f = f*del
            if (abs(del - 1.0_dp) <= epsilon(1.0_dp)) exit
        end do
        if (k > cf_max_terms) self%failed = .true.
        t = 2.0_dp*(self%q + 1.0_dp) - x*x/f
    end function bessel_ratio_eval

end module seispulse_walls_one_term
