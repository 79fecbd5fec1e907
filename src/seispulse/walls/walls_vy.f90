!> Veletsos-Younan (1994a) series for a rigid, fixed-base wall retaining a homogeneous
!> viscoelastic layer (doc/walls.md section 2, the [RECON] forms of Eqs. 2.25 and 2.29-2.36).
!>
!> Dimensionless inputs: omega_ratio = omega/omega_1 with omega_1 = pi Vs/(2H), the loss
!> factor delta (G* = G(1 + i delta)), Poisson's ratio nu. phi_n = omega_ratio/n, n odd.
!> Every series is written with r_n = sqrt(1 + i delta)/sqrt(1 - phi_n^2 + i delta)
!> = (1 - z_n)^(-1/2), z_n = zeta/n^2, zeta = omega_ratio^2/(1 + i delta); the root has
!> Re >= 0 (sqrt_branch), so for delta = 0 and phi_n > 1, r_n = -i/sqrt(phi_n^2 - 1),
!> the delta -> 0+ limit (outgoing waves, radiation damping).
!>
!> Signs and units (results are the dynamic increment only):
!> - q = -Q_b of (2.34), the thrust on the wall, positive when it pushes the wall (rho Xg H^2);
!>   static q = 14 zeta(3)/pi^3 psi_sigma = 0.542755 psi_sigma.
!> - m = -M_b of (2.35) with the corrected 1/n^4, moment about the base (rho Xg H^3).
!> - h_ratio = |m|/|q| (h/H, real; doc/walls.md (2.36) leaves |h/H| or Re(h/H) open): static
!>   0.59858 (the printed 1/n^3 would give 0.58647).
!> - p(y) = -sigma_x(0, y), wall pressure, compression positive (rho Xg H).
!> - fields keep the source's signs (2.30)-(2.33): u, v in rho Xg H^2/G, sigma_x, tau in
!>   rho Xg H; u < 0 for a positive Xg (the soil lags toward the wall).
!> - coordinates x/H >= 0 from the wall into the backfill, y/H in [0, 1] up from the base.
!>
!> Errata of the printed source used here (doc/walls.md section 2): (2.25) psi_e (not psi_c) outside
!> the bracket; (2.29) H^2 restored; (2.30) one factor (1 + i delta) only; (2.31) and (2.32)
!> as re-derived; (2.35)/(2.36) 1/n^4.
!>
!> Tolerances. q: relative error <= tol (proven bound below). m: error <= tol max(|m|,
!> 1e-3 (2/pi) |q| H), i.e. relative unless the point of application is within 6e-4 H of
!> the base. Pressure and fields: truncation error <= tol A, A the l1 norm of the modal
!> amplitudes of that quantity (e.g. A = (8 psi_sigma/pi^2) sum_n |r_n|/n^2 for p and
!> sigma_x; static A = psi_sigma, 1.35 x the static surface pressure), plus rounding of a
!> few 1e-16 A. The number of terms is bounded before summing (q, m: from the tail bound
!> with |partial sum| >= |r_1|, about 1.3e5 at worst: omega_ratio 1e4, tol 1e-15). The
!> pressure and field series stop at 4 million (2 million odd terms) and return
!> SEISPULSE_NO_CONVERGENCE if that is not enough: a tight tol with a large omega_ratio
!> (tol 1e-15 at omega_ratio 500; tol 1e-12 is fine there), and even the default tol
!> 1e-10 above omega_ratio of about 7000 (q and m go to 1e4).
module seispulse_walls_vy
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_CONVERGENCE, set_error
    use seispulse_checks, only: outside
    use seispulse_format, only: real_str, int_str
    use seispulse_special, only: expm1, exp_expm1, pi
    use seispulse_walls_common, only: wall_psi_t, wall_psi, check_delta, &
                                      check_omega_ratio, sqrt_branch, resonance_error, &
                                      inv_one_plus_i
    implicit none
    private

    public :: vy_default_tol, vy_min_tol, vy_max_tol, vy_max_omega_ratio
    public :: vy_rigid, vy_rigid_sweep, vy_pressure, vy_fields

    real(dp), parameter :: vy_default_tol = 1.0e-10_dp     !! default relative tolerance
    real(dp), parameter :: vy_min_tol = 1.0e-15_dp         !! smallest tol accepted
    real(dp), parameter :: vy_max_tol = 1.0e-2_dp          !! largest tol accepted
    !> Largest omega/omega_1: the series sums about omega_ratio/2 terms before the tail
    !> expansion applies.
    real(dp), parameter :: vy_max_omega_ratio = 1.0e4_dp

    real(dp), parameter :: ln2 = 0.6931471805599453094172321214581766_dp
    !> Floor of |sum_M| relative to |sum_Q| in the tolerance on m (see module doc).
    real(dp), parameter :: m_floor = 1.0e-3_dp
    !> Hard cap on the last mode number of the pressure and field series.
    integer, parameter :: n_hard = 4000001
    real(dp), parameter :: vy_max_x = 1.0e6_dp   !! largest x/H of vy_fields

    !> Coefficients c_k of (1 - z)^(-1/2) = sum_k c_k z^k, c_k = binom(2k, k)/4^k (k = 0..3);
    !> they decrease, so |sum_{k>=K} c_k z^k| <= c_K |z|^K/(1 - |z|).
    real(dp), parameter :: c_half(0:3) = [1.0_dp, 0.5_dp, 0.375_dp, 0.3125_dp]

    !> Dirichlet lambda(s) = sum_{n odd} n^-s = (1 - 2^-s) zeta(s), s = 2..11 (mpmath).
    real(dp), parameter :: lambda_s(2:11) = [1.233700550136169827354_dp, &
        1.051799790264644999725_dp, 1.014678031604192054546_dp, 1.004523762795139616134_dp, &
        1.001447076640942121906_dp, 1.000471548652376554755_dp, 1.000155179025296119303_dp, &
        1.000051345183843772593_dp, 1.000017041363044825488_dp, 1.000005666051090109351_dp]

    !> Dirichlet eta(2j) = (1 - 2^(1-2j)) zeta(2j), j = 1..40 (mpmath, 22 digits).
    real(dp), parameter :: eta_2j(40) = [0.8224670334241132182362_dp, &
        0.9470328294972459175765_dp, 0.9855510912974351040984_dp, 0.9962330018526478992273_dp, &
        0.9990395075982715656392_dp, 0.9997576851438581908532_dp, 0.999939170345979718171_dp, &
        0.9999847642149061064417_dp, 0.9999961878696101134797_dp, 0.9999990466115815221151_dp, &
        0.9999997616132308225479_dp, 0.9999999403988923946284_dp, 0.9999999850992319965688_dp, &
        0.9999999962747534001087_dp, 0.999999999068682281454_dp, 0.9999999997671698959515_dp, &
        0.9999999999417923990453_dp, 0.9999999999854480914339_dp, 0.9999999999963620219332_dp, &
        0.9999999999990905053805_dp, 0.9999999999997726263337_dp, 0.9999999999999431565822_dp, &
        0.9999999999999857891454_dp, 0.9999999999999964472863_dp, 0.9999999999999991118216_dp, &
        0.9999999999999997779554_dp, 0.9999999999999999444888_dp, 0.9999999999999999861222_dp, &
        0.9999999999999999965306_dp, 0.9999999999999999991326_dp, 0.9999999999999999997832_dp, &
        0.9999999999999999999458_dp, 0.9999999999999999999864_dp, 0.9999999999999999999966_dp, &
        0.9999999999999999999992_dp, 0.9999999999999999999998_dp, 0.9999999999999999999999_dp, &
        1.0_dp, 1.0_dp, 1.0_dp]

    !> Bernoulli numbers B_2 .. B_20 (Euler-Maclaurin tails of the force and moment sums).
    real(dp), parameter :: bern(10) = [1.0_dp/6.0_dp, -1.0_dp/30.0_dp, 1.0_dp/42.0_dp, &
        -1.0_dp/30.0_dp, 5.0_dp/66.0_dp, -691.0_dp/2730.0_dp, 7.0_dp/6.0_dp, &
        -3617.0_dp/510.0_dp, 43867.0_dp/798.0_dp, -174611.0_dp/330.0_dp]

    !> One frequency: the quantities every mode needs.
    type :: vy_freq_t
        real(dp) :: w = 0.0_dp       !! omega_ratio
        real(dp) :: w2 = 0.0_dp      !! omega_ratio^2
        real(dp) :: cr = 1.0_dp      !! 1/(1 + delta^2)
        real(dp) :: ci = 0.0_dp      !! delta/(1 + delta^2)
        real(dp) :: omc = 0.0_dp     !! 1 - cr = delta^2/(1 + delta^2)
        real(dp) :: azeta = 0.0_dp   !! |zeta| = omega_ratio^2/sqrt(1 + delta^2)
        complex(dp) :: zeta = (0.0_dp, 0.0_dp)  !! omega_ratio^2/(1 + i delta)
    end type vy_freq_t

    !> Which atom sums of a point are wanted, and how they are accelerated.
    type :: vy_point_t
        real(dp) :: alpha = 1.0_dp   !! pi/(2 psi_e): a_n = n alpha s_n (per H), (2.25)
        real(dp) :: kappa = 0.0_dp   !! nu/(2 - nu), (2.33)
        integer :: k1 = 1            !! terms of (1-z)^(-1/2) subtracted at x = 0 (sigma, v)
        integer :: k2 = 1            !! terms of 1/(1-z) subtracted (u, tau)
        logical :: sigma_only = .false.
    end type vy_point_t

contains

    ! ------------------------------------------------------------------ public API

    !> Thrust and base moment on a rigid wall, (2.34)-(2.36) with the 1/n^4 of (2.35):
    !> q = (16 psi_sigma/pi^3) sum r_n/n^3, m = (32 psi_sigma/pi^4) sum (-1)^((n-1)/2) r_n/n^4.
    !> delta = 0 at an odd omega_ratio is refused (SEISPULSE_SINGULAR).
    subroutine vy_rigid(omega_ratio, delta, nu, tol, q, m, h_ratio, stat, errmsg, nterms)
        real(dp), intent(in) :: omega_ratio       !! omega/omega_1, in [0, 1e4]
        real(dp), intent(in) :: delta             !! loss factor, >= 0
        real(dp), intent(in) :: nu                !! Poisson's ratio, [0, 0.5)
        real(dp), intent(in) :: tol               !! relative tolerance on q and m, [1e-15, 1e-2]
        complex(dp), intent(out) :: q             !! thrust -Q_b, rho Xg H^2
        complex(dp), intent(out) :: m             !! base moment -M_b, rho Xg H^3
        real(dp), intent(out) :: h_ratio          !! |m|/|q| = |h|/H, dimensionless
        integer, intent(out) :: stat              !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        integer, intent(out), optional :: nterms  !! odd-n terms summed explicitly
        type(wall_psi_t) :: psi
        type(vy_freq_t) :: f
        complex(dp) :: sq, sm
        integer :: nt
        q = (0.0_dp, 0.0_dp)
        m = (0.0_dp, 0.0_dp)
        h_ratio = 0.0_dp
        if (present(nterms)) nterms = 0
        call check_common(omega_ratio, delta, nu, tol, psi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_resonance(omega_ratio, delta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call freq_setup(omega_ratio, delta, f)
        call qm_sums(f, tol, sq, sm, nt)
        q = (16.0_dp*psi%sigma/pi**3)*sq
        m = (32.0_dp*psi%sigma/pi**4)*sm
        h_ratio = abs(m)/abs(q)
        if (present(nterms)) nterms = nt
    end subroutine vy_rigid

    !> vy_rigid over many frequencies (one delta, one nu).
    subroutine vy_rigid_sweep(omega_ratios, delta, nu, tol, q, m, h_ratio, stat, errmsg, nterms)
        real(dp), intent(in) :: omega_ratios(:)   !! omega/omega_1 values, each in [0, 1e4]
        real(dp), intent(in) :: delta             !! loss factor, >= 0
        real(dp), intent(in) :: nu                !! Poisson's ratio, [0, 0.5)
        real(dp), intent(in) :: tol               !! relative tolerance, [1e-15, 1e-2]
        complex(dp), intent(out) :: q(:)          !! thrust, rho Xg H^2 (size of omega_ratios)
        complex(dp), intent(out) :: m(:)          !! base moment, rho Xg H^3
        real(dp), intent(out) :: h_ratio(:)       !! |m|/|q|
        integer, intent(out) :: stat              !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        integer, intent(out), optional :: nterms(:) !! odd-n terms summed per frequency
        type(wall_psi_t) :: psi
        type(vy_freq_t) :: f
        complex(dp) :: sq, sm
        integer :: i, nt
        q = (0.0_dp, 0.0_dp)
        m = (0.0_dp, 0.0_dp)
        h_ratio = 0.0_dp
        if (present(nterms)) nterms = 0
        stat = SEISPULSE_SUCCESS
        if (size(q) /= size(omega_ratios) .or. size(m) /= size(omega_ratios) .or. &
            size(h_ratio) /= size(omega_ratios)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'q, m, h_ratio: sizes '// &
                           'must equal size(omega_ratios) = '//int_str(size(omega_ratios)))
            return
        end if
        if (present(nterms)) then
            if (size(nterms) /= size(omega_ratios)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'nterms: size must '// &
                               'equal size(omega_ratios) = '//int_str(size(omega_ratios)))
                return
            end if
        end if
        call check_common(0.0_dp, delta, nu, tol, psi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        do i = 1, size(omega_ratios)
            call check_w(omega_ratios(i), stat, errmsg)
            if (stat == SEISPULSE_SUCCESS) &
                call check_resonance(omega_ratios(i), delta, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) then
                if (present(errmsg)) errmsg = 'omega_ratios('//int_str(i)//'): '//errmsg
                return
            end if
        end do
        do i = 1, size(omega_ratios)
            call freq_setup(omega_ratios(i), delta, f)
            call qm_sums(f, tol, sq, sm, nt)
            q(i) = (16.0_dp*psi%sigma/pi**3)*sq
            m(i) = (32.0_dp*psi%sigma/pi**4)*sm
            h_ratio(i) = abs(m(i))/abs(q(i))
            if (present(nterms)) nterms(i) = nt
        end do
    end subroutine vy_rigid_sweep

    !> Wall pressure p(y) = -sigma_x(0, y) = (8 psi_sigma/pi^2) sum r_n sin(n pi y/2)/n^2,
    !> (2.32) at x = 0, compression positive; p(0) = 0.
    subroutine vy_pressure(omega_ratio, delta, nu, y, tol, p, stat, errmsg)
        real(dp), intent(in) :: omega_ratio       !! omega/omega_1, in [0, 1e4]
        real(dp), intent(in) :: delta             !! loss factor, >= 0
        real(dp), intent(in) :: nu                !! Poisson's ratio, [0, 0.5)
        real(dp), intent(in) :: y(:)              !! heights y/H above the base, in [0, 1]
        real(dp), intent(in) :: tol               !! tolerance relative to A (module doc)
        complex(dp), intent(out) :: p(:)          !! pressure, rho Xg H (size of y)
        integer, intent(out) :: stat              !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(wall_psi_t) :: psi
        type(vy_freq_t) :: f
        type(vy_point_t) :: pt
        complex(dp) :: ss, su, sv, st
        integer :: i
        p = (0.0_dp, 0.0_dp)
        call check_common(omega_ratio, delta, nu, tol, psi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (size(p) /= size(y)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'p: size must equal '// &
                           'size(y) = '//int_str(size(y)))
            return
        end if
        call check_points(y, y, .false., stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_resonance(omega_ratio, delta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call freq_setup(omega_ratio, delta, f)
        call point_setup(f, psi, nu, tol, .true., pt)
        do i = 1, size(y)
            call point_sums(f, pt, 0.0_dp, y(i), tol, ss, su, sv, st, stat)
            if (stat /= SEISPULSE_SUCCESS) then
                call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, 'tol = '// &
                               real_str(tol)//': the pressure series at y('//int_str(i)// &
                               ') needs modes beyond n = '//int_str(n_hard)// &
                               ' (2 million terms); raise tol')
                return
            end if
            p(i) = (8.0_dp*psi%sigma/pi**2)*ss + (0.0_dp, 0.0_dp)
        end do
    end subroutine vy_pressure

    !> Displacements and stresses in the backfill, (2.30)-(2.33) as reconstructed in
    !> doc/walls.md, at the points (x(i), y(i)). At x = 0: u = 0, tau = -nu/(2 - nu) y and
    !> sigma_x = -p(y) exactly as in vy_pressure.
    subroutine vy_fields(omega_ratio, delta, nu, x, y, tol, u, v, sigma_x, tau, stat, errmsg)
        real(dp), intent(in) :: omega_ratio       !! omega/omega_1, in [0, 1e4]
        real(dp), intent(in) :: delta             !! loss factor, >= 0
        real(dp), intent(in) :: nu                !! Poisson's ratio, [0, 0.5)
        real(dp), intent(in) :: x(:)              !! distances x/H from the wall, finite, >= 0
        real(dp), intent(in) :: y(:)              !! heights y/H above the base, in [0, 1]
        real(dp), intent(in) :: tol               !! tolerance relative to A (module doc)
        complex(dp), intent(out) :: u(:)          !! horizontal displacement (2.30), rho Xg H^2/G
        complex(dp), intent(out) :: v(:)          !! vertical displacement (2.31), rho Xg H^2/G
        complex(dp), intent(out) :: sigma_x(:)    !! normal stress (2.32), tension +, rho Xg H
        complex(dp), intent(out) :: tau(:)        !! shear stress (2.33), rho Xg H
        integer, intent(out) :: stat              !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        type(wall_psi_t) :: psi
        type(vy_freq_t) :: f
        type(vy_point_t) :: pt
        complex(dp) :: ss, su, sv, st, gfac
        integer :: i
        u = (0.0_dp, 0.0_dp)
        v = (0.0_dp, 0.0_dp)
        sigma_x = (0.0_dp, 0.0_dp)
        tau = (0.0_dp, 0.0_dp)
        call check_common(omega_ratio, delta, nu, tol, psi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (size(y) /= size(x)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'x, y: sizes differ ('// &
                           int_str(size(x))//' and '//int_str(size(y))//'); one point each')
            return
        end if
        if (size(u) /= size(x) .or. size(v) /= size(x) .or. size(sigma_x) /= size(x) .or. &
            size(tau) /= size(x)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'u, v, sigma_x, tau: '// &
                           'sizes must equal size(x) = '//int_str(size(x)))
            return
        end if
        call check_points(x, y, .true., stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_resonance(omega_ratio, delta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call freq_setup(omega_ratio, delta, f)
        call point_setup(f, psi, nu, tol, .false., pt)
        ! 1/(1 + i delta) of (2.30)/(2.31), robust for any delta
        gfac = cmplx(f%cr, -f%ci, dp)
        do i = 1, size(x)
            call point_sums(f, pt, x(i), y(i), tol, ss, su, sv, st, stat)
            if (stat /= SEISPULSE_SUCCESS) then
                call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, 'tol = '// &
                               real_str(tol)//': the field series at x('//int_str(i)// &
                               ') need modes beyond n = '//int_str(n_hard)// &
                               ' (2 million terms); raise tol')
                return
            end if
            sigma_x(i) = -(8.0_dp*psi%sigma/pi**2)*ss
            v(i) = (16.0_dp*psi%v/pi**3)*gfac*sv
            ! at the wall point_sums gives su = 0 and st = kappa pi t/4: u = 0, tau = -kappa y
            u(i) = -(16.0_dp/pi**3)*gfac*su
            tau(i) = -(8.0_dp/pi**2)*st
            ! + (0, 0) turns a -0.0 (products with zero sums at y = 0) into +0.0
            u(i) = u(i) + (0.0_dp, 0.0_dp)
            v(i) = v(i) + (0.0_dp, 0.0_dp)
            sigma_x(i) = sigma_x(i) + (0.0_dp, 0.0_dp)
            tau(i) = tau(i) + (0.0_dp, 0.0_dp)
        end do
    end subroutine vy_fields

    ! ------------------------------------------------------------------ checks

    !> nu, delta, omega_ratio, tol in their ranges; psi(nu).
    subroutine check_common(omega_ratio, delta, nu, tol, psi, stat, errmsg)
        real(dp), intent(in) :: omega_ratio, delta, nu, tol
        type(wall_psi_t), intent(out) :: psi
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call wall_psi(nu, psi, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_delta(delta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_w(omega_ratio, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(tol, vy_min_tol, vy_max_tol, .false., .false.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'tol = '//real_str(tol)// &
                           ': the tolerance must lie in [1e-15, 1e-2]')
    end subroutine check_common

    !> omega_ratio finite, >= 0 and <= vy_max_omega_ratio.
    subroutine check_w(omega_ratio, stat, errmsg)
        real(dp), intent(in) :: omega_ratio
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call check_omega_ratio(omega_ratio, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (omega_ratio > vy_max_omega_ratio) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'omega_ratio = '// &
                           real_str(omega_ratio)//': must be <= 1e4 (the series needs '// &
                           'about omega_ratio/2 terms)')
    end subroutine check_w

    !> Resonance: delta = 0 and omega_ratio an odd integer (phi_n = 1 for n = omega_ratio).
    subroutine check_resonance(omega_ratio, delta, stat, errmsg)
        real(dp), intent(in) :: omega_ratio, delta
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: wi
        integer :: n
        stat = SEISPULSE_SUCCESS
        if (delta > 0.0_dp) return                  ! -0.0 is zero damping too
        wi = aint(omega_ratio)
        if (omega_ratio < wi .or. omega_ratio > wi) return   ! not an integer
        n = int(wi)
        if (mod(n, 2) == 1) call resonance_error(omega_ratio, 'omega_1 x '//int_str(n), stat, &
                                                 errmsg)
    end subroutine check_resonance

    !> x(i) finite >= 0 (when with_x) and y(i) in [0, 1].
    subroutine check_points(x, y, with_x, stat, errmsg)
        real(dp), intent(in) :: x(:), y(:)
        logical, intent(in) :: with_x
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: i
        stat = SEISPULSE_SUCCESS
        do i = 1, size(y)
            if (with_x) then
                ! beyond 1e6 H the undamped radiating phase is meaningless and a_n x overflows
                if (outside(x(i), 0.0_dp, vy_max_x, .false., .false.)) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'x('//int_str(i)// &
                                   ') = '//real_str(x(i))//': x/H must lie in [0, 1e6]')
                    return
                end if
            end if
            if (outside(y(i), 0.0_dp, 1.0_dp, .false., .false.)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'y('//int_str(i)// &
                               ') = '//real_str(y(i))//': y/H must lie in [0, 1]')
                return
            end if
        end do
    end subroutine check_points

    ! ------------------------------------------------------------------ modes

    !> Per-frequency constants; written so that no delta overflows delta^2.
    pure subroutine freq_setup(w, delta, f)
        real(dp), intent(in) :: w, delta
        type(vy_freq_t), intent(out) :: f
        complex(dp) :: c
        f%w = abs(w)            ! abs: -0.0 -> +0.0
        f%w2 = f%w*f%w
        c = inv_one_plus_i(abs(delta))
        f%cr = real(c, dp)
        f%ci = -aimag(c)
        f%omc = abs(delta)*f%ci     ! delta^2/(1 + delta^2)
        f%zeta = f%w2*cmplx(f%cr, -f%ci, dp)
        f%azeta = f%w2*sqrt(f%cr)
    end subroutine freq_setup

    !> Mode n: s_n = sqrt(1 - z_n) (Re, Im >= 0) and r_n = 1/s_n.
    !> 1 - z_n = cr (1 - w^2/n^2) + omc + i ci w^2/n^2 with 1 - w^2/n^2 = (n - w)(n + w)/n^2,
    !> exact near phi_n = 1 (no 1 - phi^2 cancellation); the imaginary part is >= 0 by
    !> construction (a -0.0 cannot reach the square root).
    pure subroutine mode(f, n, s, r)
        type(vy_freq_t), intent(in) :: f
        integer, intent(in) :: n
        complex(dp), intent(out) :: s, r
        real(dp) :: rn, rn2
        rn = real(n, dp)
        rn2 = rn*rn
        s = sqrt_branch(cmplx(f%cr*((rn - f%w)*(rn + f%w)/rn2) + f%omc, f%ci*(f%w2/rn2), dp))
        r = 1.0_dp/s
    end subroutine mode

    ! ------------------------------------------------------------------ force and moment

    !> sum_Q = sum_{n odd} r_n/n^3 and sum_M = sum_{n odd} (-1)^((n-1)/2) r_n/n^4.
    !>
    !> Terms n <= N are summed as they are; beyond, r_n = 1 + z/2 + 3z^2/8 + R_3(z) with the
    !> three leading terms summed in closed form (Euler-Maclaurin tails of n^-s, no
    !> cancellation) and the remainder bounded: for |z| <= rho < 1, since the c_k decrease,
    !>   |R_3(z)| <= c_3 |z|^3/(1 - rho),  c_3 = 5/16,
    !> and sum_{n >= N+2, odd} n^-p <= (1/2) int_N^inf x^-p dx = N^(1-p)/(2(p-1)), so
    !>   |tail_Q| <= c_3 |zeta|^3/((1 - rho) 2 (8) N^8),
    !>   |tail_M| <= c_3 |zeta|^3/((1 - rho) 2 (9) N^9)
    !> with rho = |zeta|/(N+2)^2. Stop when tail_Q <= tol |partial_Q| (every r_n lies in the
    !> closed fourth quadrant, so |sum_Q| >= |partial_Q|: relative error <= tol) and
    !> tail_M <= tol max(|partial_M| - |rest_M|, m_floor |partial_Q|), |rest_M| <=
    !> sum_{n>N} |r_n|/n^4 <= (1 - rho)^(-1/2) N^-3/6. With 1/(1 - rho) <= 2 and
    !> |partial_Q| >= |r_1| both hold at the a-priori n_cap below, so the loop ends there
    !> at the latest.
    pure subroutine qm_sums(f, tol, sq, sm, nterms)
        type(vy_freq_t), intent(in) :: f
        real(dp), intent(in) :: tol
        complex(dp), intent(out) :: sq, sm
        integer, intent(out) :: nterms
        real(dp), parameter :: c3 = 0.3125_dp
        complex(dp) :: s, r, z1, z2
        real(dp) :: a3, lq, rn, rho, bq, bm, lowm, nc1, nc2, nc3
        real(dp) :: acc(4), comp(4)     ! Neumaier sums of Re/Im sum_Q, Re/Im sum_M
        integer :: n, ncap, sgn
        a3 = c3*f%azeta**3
        call mode(f, 1, s, r)
        lq = abs(r)
        ! a-priori cap: rho <= 1/2, tail_Q <= tol lq/2, tail_M <= tol m_floor lq/2
        nc1 = sqrt(2.0_dp*f%azeta) - 2.0_dp
        nc2 = (2.0_dp*a3/(8.0_dp*tol*lq))**(1.0_dp/8.0_dp)
        nc3 = (2.0_dp*a3/(9.0_dp*tol*m_floor*lq))**(1.0_dp/9.0_dp)
        ncap = odd_ceiling(max(1.0_dp, nc1, nc2, nc3))
        ! compensated sums: up to 1e5 terms, rounding stays at a few ulps of the sums
        acc = 0.0_dp
        comp = 0.0_dp
        sgn = 1
        n = 1
        do
            if (n > 1) call mode(f, n, s, r)
            rn = real(n, dp)
            z1 = r/rn**3
            z2 = real(sgn, dp)*r/rn**4
            call neumaier(acc, comp, [real(z1, dp), aimag(z1), real(z2, dp), aimag(z2)])
            sq = cmplx(acc(1) + comp(1), acc(2) + comp(2), dp)
            sm = cmplx(acc(3) + comp(3), acc(4) + comp(4), dp)
            if (n >= ncap) exit
            rho = f%azeta/(rn + 2.0_dp)**2
            if (rho < 1.0_dp) then
                bq = a3/((1.0_dp - rho)*16.0_dp*rn**8)
                bm = a3/((1.0_dp - rho)*18.0_dp*rn**9)
                lowm = abs(sm) - 1.0_dp/(sqrt(1.0_dp - rho)*6.0_dp*rn**3)
                if (bq <= tol*abs(sq) .and. bm <= tol*max(lowm, m_floor*abs(sq))) exit
            end if
            n = n + 2
            sgn = -sgn
        end do
        nterms = (n + 1)/2
        ! closed-form tails from a = n + 2: sum (1 + z/2 + 3 z^2/8) n^-s
        z1 = 0.5_dp*f%zeta
        z2 = 0.375_dp*f%zeta**2
        sq = sq + odd_zeta_tail(3, n + 2) + z1*odd_zeta_tail(5, n + 2) + &
             z2*odd_zeta_tail(7, n + 2)
        sm = sm + odd_beta_tail(4, n + 2) + z1*odd_beta_tail(6, n + 2) + &
             z2*odd_beta_tail(8, n + 2)
    end subroutine qm_sums

    !> Neumaier's compensated summation, componentwise: acc + comp is the running sum.
    pure subroutine neumaier(acc, comp, x)
        real(dp), intent(inout) :: acc(:), comp(:)
        real(dp), intent(in) :: x(:)
        real(dp) :: t
        integer :: i
        do i = 1, size(acc)
            t = acc(i) + x(i)
            if (abs(acc(i)) >= abs(x(i))) then
                comp(i) = comp(i) + ((acc(i) - t) + x(i))
            else
                comp(i) = comp(i) + ((x(i) - t) + acc(i))
            end if
            acc(i) = t
        end do
    end subroutine neumaier

    !> Smallest odd integer >= x (x >= 1, moderate).
    pure integer function odd_ceiling(x) result(n)
        real(dp), intent(in) :: x
        integer, parameter :: nmax = 1073741823     ! odd, about huge(1)/2
        if (x >= real(nmax, dp)) then
            n = nmax
            return
        end if
        n = ceiling(x)
        if (mod(n, 2) == 0) n = n + 1
    end function odd_ceiling

    !> sum_{k>=0} (a + h k)^-s by Euler-Maclaurin, for a >= 24 h: ten Bernoulli terms.
    !> f(x) = x^-s is completely monotone, so the error is below the first omitted term,
    !> about 1e-18 relative here (term ratio (s+2j-1)(s+2j)/(4 pi^2 (a/h)^2) < 0.07).
    pure real(dp) function em_tail(s, a, h) result(total)
        integer, intent(in) :: s
        real(dp), intent(in) :: a, h
        real(dp) :: pj, rs
        integer :: j
        rs = real(s, dp)
        total = a**(1 - s)/(h*(rs - 1.0_dp)) + 0.5_dp*a**(-s)
        pj = h*rs*a**(-s - 1)/2.0_dp      ! h^(2j-1) (s)_(2j-1) a^(-s-2j+1)/(2j)!, j = 1
        do j = 1, size(bern)
            total = total + bern(j)*pj
            pj = pj*h*h*(rs + real(2*j - 1, dp))*(rs + real(2*j, dp))/ &
                 (a*a*real((2*j + 1)*(2*j + 2), dp))
        end do
    end function em_tail

    !> sum_{n >= a, n odd} n^-s (a odd >= 1): terms below 48, then em_tail(., 2).
    pure real(dp) function odd_zeta_tail(s, a) result(total)
        integer, intent(in) :: s, a
        integer :: n
        total = 0.0_dp
        n = a
        do while (n < 48)
            total = total + real(n, dp)**(-s)
            n = n + 2
        end do
        total = total + em_tail(s, real(n, dp), 2.0_dp)
    end function odd_zeta_tail

    !> sum_{n >= a, n odd} (-1)^((n-1)/2) n^-s (a odd >= 1): terms up to n = 1 (mod 4)
    !> >= 97, then the pairs as two em_tail(., 4).
    pure real(dp) function odd_beta_tail(s, a) result(total)
        integer, intent(in) :: s, a
        integer :: n
        total = 0.0_dp
        n = a
        do while (n < 97 .or. mod(n, 4) /= 1)
            if (mod(n, 4) == 1) then
                total = total + real(n, dp)**(-s)
            else
                total = total - real(n, dp)**(-s)
            end if
            n = n + 2
        end do
        total = total + (em_tail(s, real(n, dp), 4.0_dp) - em_tail(s, real(n + 2, dp), 4.0_dp))
    end function odd_beta_tail

    ! ------------------------------------------------------------------ closed forms

    !> O_s(theta) = sum_{n odd} exp(i n theta)/n^s, integer s >= 2, complex theta with
    !> |theta| <= 1.9 < pi and Im(theta) >= 0 (real theta may be negative). From the
    !> expansion of Li_s(e^{i theta}) - 2^-s Li_s(e^{2 i theta}) about theta = 0 (derived
    !> for this module, checked against mpmath polylog to 1e-15):
    !>   O_s = sum_{k=0}^{s-2} lambda(s-k) (i theta)^k/k!
    !>       + (i theta)^(s-1)/(2 (s-1)!) [H_(s-1) + ln 2 - ln(-i theta)]
    !>       - (i theta)^(s-1) sum_{j>=1} eta(2j) (2j-1)!/(s-1+2j)! (theta/pi)^(2j).
    !> Im O_2(t) = sum_odd sin(nt)/n^2 = (Cl2(t) + Cl2(pi - t))/2, O_2(pi/2) = i Catalan.
    pure complex(dp) function odd_polylog(s, theta) result(o)
        integer, intent(in) :: s
        complex(dp), intent(in) :: theta
        complex(dp) :: it, pw, q2, qq, ser, term
        real(dp) :: fact, hs, c
        integer :: k, j, mm
        if (abs(theta) <= 0.0_dp) then
            o = cmplx(lambda_s(s), 0.0_dp, dp)
            return
        end if
        it = (0.0_dp, 1.0_dp)*theta
        o = (0.0_dp, 0.0_dp)
        pw = (1.0_dp, 0.0_dp)
        fact = 1.0_dp
        do k = 0, s - 2
            o = o + lambda_s(s - k)*pw/fact
            pw = pw*it
            fact = fact*real(k + 1, dp)
        end do
        hs = 0.0_dp
        do k = 1, s - 1
            hs = hs + 1.0_dp/real(k, dp)
        end do
        o = o + pw/fact*0.5_dp*(hs + ln2 - log(-it))
        q2 = (theta/pi)**2
        qq = (1.0_dp, 0.0_dp)
        ser = (0.0_dp, 0.0_dp)
        do j = 1, size(eta_2j)
            qq = qq*q2
            c = 1.0_dp
            do mm = 2*j, s - 1 + 2*j
                c = c/real(mm, dp)
            end do
            term = eta_2j(j)*c*qq
            ser = ser + term
            if (abs(term) <= 1.0e-18_dp*abs(ser)) exit
        end do
        o = o - pw*ser
    end function odd_polylog

    ! ------------------------------------------------------------------ fields

    !> Constants of the point sums; the subtraction orders k1, k2 are the largest (<= 3)
    !> whose closed forms, of size c_k |zeta|^k, keep rounding below tol/10 of the
    !> smallest scale (first term).
    pure subroutine point_setup(f, psi, nu, tol, sigma_only, pt)
        type(vy_freq_t), intent(in) :: f
        type(wall_psi_t), intent(in) :: psi
        real(dp), intent(in) :: nu, tol
        logical, intent(in) :: sigma_only
        type(vy_point_t), intent(out) :: pt
        complex(dp) :: s, r
        real(dp) :: amp1, amp2
        integer :: k
        pt%alpha = pi/(2.0_dp*psi%e)
        pt%kappa = nu/(2.0_dp - nu)
        pt%sigma_only = sigma_only
        call mode(f, 1, s, r)
        pt%k1 = 1
        pt%k2 = 1
        amp1 = 0.0_dp
        amp2 = 0.0_dp
        do k = 1, 2
            amp1 = amp1 + c_half(k)*f%azeta**k
            amp2 = amp2 + f%azeta**k
            if (8.0_dp*epsilon(1.0_dp)*1.25_dp*amp1 <= 0.1_dp*tol*abs(r)) pt%k1 = k + 1
            if (8.0_dp*epsilon(1.0_dp)*1.25_dp*amp2 <= 0.1_dp*tol*abs(r)**2) pt%k2 = k + 1
        end do
    end subroutine point_setup

    !> Raw sums at one point (x, y):
    !>   ss = sum r E sin/n^2, su = sum r^2 (1 - E) sin/n^3, sv = sum r E (1 - cos)/n^3,
    !>   st = sum [r^2 (1 - E) cos + kappa E (1 - cos)]/n^2,
    !> E = exp(-a_n x), a_n x = n alpha x s_n, trig arguments n t, t = pi y/2.
    !> Acceleration: the x-independent parts subtract sum_{k<K} c_k z_n^k (closed forms
    !> Re/Im O_{s+2k}(t)); the decaying parts subtract e_n = exp(-n alpha x) when
    !> alpha x <= 1 (closed forms O_s(+-t + i alpha x)). Remainder bounds for n >= N+2
    !> (rho = |zeta|/(N+2)^2 < 1, mu = sqrt(max(0, 1 - cr w^2/(N+2)^2)) <= Re s_n):
    !>   |r^p - sum_{k<K} c_k z^k| <= c_K |zeta|^K/((1 - rho) n^(2K)),
    !>   |E| <= exp(-n alpha x mu),  |1 - s_n| <= |zeta|/(2 (1 - rho) n^2),
    !>   |E - e_n| <= n alpha x |1 - s_n| exp(-n alpha x mu)  (mean value theorem),
    !>   |r^p E - e_n| <= |zeta|/(1 - rho) [c_1 n^-2 + alpha x/(2n)] exp(-n alpha x mu).
    !> stat /= 0 when n_hard terms do not reach tol.
    pure subroutine point_sums(f, pt, x, y, tol, ss, su, sv, st, stat)
        type(vy_freq_t), intent(in) :: f
        type(vy_point_t), intent(in) :: pt
        real(dp), intent(in) :: x, y, tol
        complex(dp), intent(out) :: ss, su, sv, st
        integer, intent(out) :: stat
        complex(dp) :: s, r, r2, z, zk, ax, ee, ome, p2m1, p1, o, op, om, oi
        complex(dp) :: cs_, cu, cv, ct
        real(dp) :: t, ax_, rn, sh, ch, sn, cn, omcos, en, omen, ninv
        real(dp) :: asig, au, scal(4), n0scal(4)
        logical :: at_wall, cmp
        integer :: n, k, ncap, nchk
        stat = SEISPULSE_SUCCESS
        ss = (0.0_dp, 0.0_dp)
        su = (0.0_dp, 0.0_dp)
        sv = (0.0_dp, 0.0_dp)
        st = (0.0_dp, 0.0_dp)
        t = 0.5_dp*pi*y
        at_wall = .not. (x > 0.0_dp)
        ax_ = pt%alpha*x
        cmp = (.not. at_wall) .and. ax_ <= 1.0_dp
        if (at_wall .and. .not. (y > 0.0_dp)) return        ! every term vanishes
        ! ---- closed forms
        cs_ = (0.0_dp, 0.0_dp)
        cu = (0.0_dp, 0.0_dp)
        cv = (0.0_dp, 0.0_dp)
        ct = (0.0_dp, 0.0_dp)
        if (at_wall) then
            zk = (1.0_dp, 0.0_dp)
            do k = 0, pt%k1 - 1
                o = odd_polylog(2 + 2*k, cmplx(t, 0.0_dp, dp))
                cs_ = cs_ + c_half(k)*zk*aimag(o)
                if (.not. pt%sigma_only) then
                    o = odd_polylog(3 + 2*k, cmplx(t, 0.0_dp, dp))
                    cv = cv + c_half(k)*zk*(lambda_s(3 + 2*k) - real(o, dp))
                end if
                zk = zk*f%zeta
            end do
        else
            zk = (1.0_dp, 0.0_dp)
            do k = 0, pt%k2 - 1
                o = odd_polylog(2 + 2*k, cmplx(t, 0.0_dp, dp))
                ct = ct + zk*real(o, dp)
                o = odd_polylog(3 + 2*k, cmplx(t, 0.0_dp, dp))
                cu = cu + zk*aimag(o)
                zk = zk*f%zeta
            end do
            if (cmp) then
                ! sum e_n sin/n^s = (O(t+) - O(t-))/(2i); cos: (O(t+) + O(t-))/2;
                ! 1 - cos: O(i alpha x) - cos part
                op = odd_polylog(2, cmplx(t, ax_, dp))
                om = odd_polylog(2, cmplx(-t, ax_, dp))
                oi = odd_polylog(2, cmplx(0.0_dp, ax_, dp))
                cs_ = (op - om)/(2.0_dp*(0.0_dp, 1.0_dp))
                ct = ct - 0.5_dp*(op + om) + pt%kappa*(oi - 0.5_dp*(op + om))
                op = odd_polylog(3, cmplx(t, ax_, dp))
                om = odd_polylog(3, cmplx(-t, ax_, dp))
                oi = odd_polylog(3, cmplx(0.0_dp, ax_, dp))
                cu = cu - (op - om)/(2.0_dp*(0.0_dp, 1.0_dp))
                cv = oi - 0.5_dp*(op + om)
            end if
        end if
        ! ---- a-priori cap from the first-term scales
        n = 1
        call mode(f, 1, s, r)
        n0scal = [abs(r), abs(r)**2, 2.0_dp*abs(r), abs(r)**2 + 2.0_dp*pt%kappa]
        ncap = find_cap(f, pt, x, tol, n0scal)
        scal = 0.0_dp
        nchk = 1
        do
            rn = real(n, dp)
            ninv = 1.0_dp/rn
            if (n > 1) call mode(f, n, s, r)
            r2 = r*r
            z = f%zeta*ninv*ninv
            sh = sin(0.5_dp*rn*t)
            ch = cos(0.5_dp*rn*t)
            sn = 2.0_dp*sh*ch
            cn = (ch - sh)*(ch + sh)
            omcos = 2.0_dp*sh*sh
            asig = abs(r)
            scal(1) = scal(1) + asig*ninv**2
            if (at_wall) then
                ! r - sum_{k<k1} c_k z^k
                p1 = (0.0_dp, 0.0_dp)
                zk = (1.0_dp, 0.0_dp)
                do k = 0, pt%k1 - 1
                    p1 = p1 + c_half(k)*zk
                    zk = zk*z
                end do
                ss = ss + (r - p1)*(sn*ninv**2)
                if (.not. pt%sigma_only) then
                    sv = sv + (r - p1)*(omcos*ninv**3)
                    scal(3) = scal(3) + 2.0_dp*asig*ninv**3
                end if
            else
                ax = (rn*ax_)*s
                call exp_expm1(-ax, ee, ome)          ! E = exp(-a x), 1 - E = -expm1(-a x)
                ome = -ome
                if (cmp) then
                    en = exp(-rn*ax_)
                    omen = -expm1(-rn*ax_)
                else
                    en = 0.0_dp
                    omen = 1.0_dp
                end if
                ! sum_{k=1}^{k2-1} z^k
                p2m1 = (0.0_dp, 0.0_dp)
                zk = z
                do k = 1, pt%k2 - 1
                    p2m1 = p2m1 + zk
                    zk = zk*z
                end do
                ss = ss + (r*ee - en)*(sn*ninv**2)
                if (.not. pt%sigma_only) then
                    au = abs(r2)
                    su = su + (r2*ome - omen - p2m1)*(sn*ninv**3)
                    sv = sv + (r*ee - en)*(omcos*ninv**3)
                    st = st + (r2*ome - omen - p2m1)*(cn*ninv**2) + &
                         pt%kappa*(ee - en)*(omcos*ninv**2)
                    scal(2) = scal(2) + au*ninv**3
                    scal(3) = scal(3) + 2.0_dp*asig*ninv**3
                    scal(4) = scal(4) + (au + 2.0_dp*pt%kappa)*ninv**2
                end if
            end if
            if (n >= ncap) exit
            if (n >= nchk) then
                if (bounds_met(f, pt, x, n, tol, scal)) exit
                nchk = n + merge(2, 32, n < 127)
            end if
            n = n + 2
        end do
        if (ncap >= n_hard .and. n >= ncap) then
            if (.not. bounds_met(f, pt, x, n, tol, scal)) then
                stat = SEISPULSE_NO_CONVERGENCE
                return
            end if
        end if
        ss = ss + cs_
        if (at_wall) then
            sv = sv + cv
            ! (2.33) at x = 0: kappa sum_odd (1 - cos nt)/n^2 = kappa pi t/4 (derived:
            ! sum_odd cos(nt)/n^2 = pi (pi - 2t)/8 on [0, pi]); u(0, y) = 0
            st = cmplx(pt%kappa*0.25_dp*pi*t, 0.0_dp, dp)
            su = (0.0_dp, 0.0_dp)
        else
            su = su + cu
            sv = sv + cv
            st = st + ct
        end if
    end subroutine point_sums

    !> The four truncation bounds after mode N hold against tol * scal (sigma, u, v, tau);
    !> false while rho >= 1. See point_sums for the bounds.
    pure logical function bounds_met(f, pt, x, nlast, tol, scal) result(ok)
        type(vy_freq_t), intent(in) :: f
        type(vy_point_t), intent(in) :: pt
        real(dp), intent(in) :: x, tol, scal(4)
        integer, intent(in) :: nlast
        real(dp) :: b(4)
        call tail_bounds(f, pt, x, nlast, b, ok)
        if (.not. ok) return
        if (pt%sigma_only) then
            ok = b(1) <= tol*scal(1)
        else
            ok = all(b <= tol*scal)
        end if
    end function bounds_met

    !> Truncation bounds b (sigma, u, v, tau raw sums) after mode nlast; valid = rho < 1.
    pure subroutine tail_bounds(f, pt, x, nlast, b, valid)
        type(vy_freq_t), intent(in) :: f
        type(vy_point_t), intent(in) :: pt
        real(dp), intent(in) :: x
        integer, intent(in) :: nlast
        real(dp), intent(out) :: b(4)
        logical, intent(out) :: valid
        real(dp) :: rn, rho, qn, mu, gam, ax_
        logical :: cmp
        b = huge(1.0_dp)
        rn = real(nlast, dp)
        rho = f%azeta/(rn + 2.0_dp)**2
        valid = rho < 1.0_dp
        if (.not. valid) return
        qn = 1.0_dp/(1.0_dp - rho)
        mu = sqrt(max(0.0_dp, 1.0_dp - f%cr*f%w2/(rn + 2.0_dp)**2))
        ax_ = pt%alpha*x
        gam = ax_*mu
        if (.not. (x > 0.0_dp)) then
            b(1) = xbound(1, 2, pt%k1, 1.0_dp)
            b(2) = 0.0_dp
            b(3) = xbound(1, 3, pt%k1, 2.0_dp)
            b(4) = 0.0_dp
        else
            cmp = ax_ <= 1.0_dp
            b(1) = dbound(1, 2, 1.0_dp)
            b(2) = xbound(2, 3, pt%k2, 1.0_dp) + dbound(2, 3, 1.0_dp)
            b(3) = dbound(1, 3, 2.0_dp)
            b(4) = xbound(2, 2, pt%k2, 1.0_dp) + dbound(2, 2, 1.0_dp) + &
                   pt%kappa*dbound(0, 2, 2.0_dp)
        end if
    contains
        !> x-independent part: tmax c_K |zeta|^K qn N^(1-s-2K)/(2 (s+2K-1))
        pure real(dp) function xbound(p, s, kk, tmax)
            integer, intent(in) :: p, s, kk
            real(dp), intent(in) :: tmax
            real(dp) :: ck
            ck = 1.0_dp
            if (p == 1) ck = c_half(kk)
            xbound = tmax*ck*f%azeta**kk*qn*rn**(1 - s - 2*kk)/real(2*(s + 2*kk - 1), dp)
        end function xbound
        !> decaying part, with or without the e_n comparison
        pure real(dp) function dbound(p, s, tmax)
            integer, intent(in) :: p, s
            real(dp), intent(in) :: tmax
            real(dp) :: c1
            if (cmp) then
                c1 = 0.0_dp
                if (p == 1) c1 = 0.5_dp
                if (p == 2) c1 = 1.0_dp
                dbound = tmax*f%azeta*qn*(c1*tsum(s + 2) + 0.5_dp*ax_*tsum(s + 1))
            else
                dbound = tmax*qn**(0.5_dp*real(p, dp))*tsum(s)
            end if
        end function dbound
        !> sum_{n >= N+2, odd} n^-p exp(-gam n) <= min(N^(1-p)/(2(p-1)),
        !> (N+2)^-p exp(-gam (N+2))/(1 - exp(-2 gam)))
        pure real(dp) function tsum(p)
            integer, intent(in) :: p
            tsum = rn**(1 - p)/real(2*(p - 1), dp)
            if (gam > 0.0_dp) tsum = min(tsum, (rn + 2.0_dp)**(-p)*exp(-gam*(rn + 2.0_dp))/ &
                                          (-expm1(-2.0_dp*gam)))
        end function tsum
    end subroutine tail_bounds

    !> A-priori last mode: the smallest odd N whose bounds hold against the first-term
    !> scales (which the partial scales never fall below); n_hard if none up to n_hard.
    pure integer function find_cap(f, pt, x, tol, scal) result(ncap)
        type(vy_freq_t), intent(in) :: f
        type(vy_point_t), intent(in) :: pt
        real(dp), intent(in) :: x, tol, scal(4)
        integer :: lo, hi, mid
        hi = 1
        do
            if (bounds_met(f, pt, x, hi, tol, scal)) exit
            if (hi >= n_hard) then
                ncap = n_hard
                return
            end if
            hi = min(2*hi + 1, n_hard)
        end do
        lo = hi/2       ! odd (hi = 2^k - 1) or 0; bounds fail at lo (or lo = 0)
        if (mod(lo, 2) == 0) lo = lo - 1
        do while (hi - lo > 2)
            mid = (lo + hi)/2
            if (mod(mid, 2) == 0) mid = mid + 1
            if (mid >= hi) mid = hi - 2
            if (bounds_met(f, pt, x, mid, tol, scal)) then
                hi = mid
            else
                lo = mid
            end if
        end do
        ncap = hi
    end function find_cap

end module seispulse_walls_vy
