!> Veletsos-Younan series (seispulse_walls_vy) against independent values: closed forms
!> (14 zeta(3)/pi^3, Dirichlet beta(4), Catalan's constant, the 1-D free-field shear
!> layer solved here with complex cosines), the doc/walls.md section 3 table, and reference sums
!> computed with mpmath (30 digits: 4000 direct terms plus Hurwitz-zeta tails for q and m;
!> Clausen functions plus direct remainders for p; term-by-term decaying sums plus the
!> closed free field for the fields). Quadrature (graded Gauss-Legendre, written here)
!> checks the integral and first moment of p against q and m. Each corrected equation of
!> the source has a test at a point where the printed form differs.
module test_walls_vy
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_SINGULAR
    use seispulse_walls_common, only: wall_psi_t, wall_psi, free_field_frequencies
    use seispulse_walls_vy, only: vy_rigid, vy_rigid_sweep, vy_pressure, vy_fields, &
                                  vy_default_tol
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_walls_vy

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: zeta3 = 1.202056903159594285399738161511449991_dp
    real(dp), parameter :: beta4 = 0.988944551741105336108422633639_dp
    real(dp), parameter :: catalan = 0.915965594177219015054603514932384110_dp
    !> psi_sigma(0.3) = 2/sqrt(0.7 x 1.7)
    real(dp), parameter :: psis03 = 1.833396994056422375_dp

contains

    subroutine collect_walls_vy(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [ &
            new_unittest('psi_factors', test_psi), &
            new_unittest('free_field_frequencies', test_free_field_frequencies), &
            new_unittest('static_thrust_moment', test_static), &
            new_unittest('erratum_2_35_n4', test_erratum_235), &
            new_unittest('dynamic_table', test_table), &
            new_unittest('mpmath_q_m', test_mpmath_qm), &
            new_unittest('tolerance_nterms', test_tolerance), &
            new_unittest('sweep_equals_pointwise', test_sweep), &
            new_unittest('static_pressure', test_static_pressure), &
            new_unittest('pressure_mpmath', test_pressure_mpmath), &
            new_unittest('pressure_integrates_to_q_m', test_pressure_integrals), &
            new_unittest('fields_at_wall', test_fields_wall), &
            new_unittest('fields_free_field', test_free_field), &
            new_unittest('fields_mpmath', test_fields_mpmath), &
            new_unittest('branch_delta_zero', test_branch), &
            new_unittest('signed_zero', test_signed_zero), &
            new_unittest('resonance', test_resonance), &
            new_unittest('bad_input', test_bad_input) &
        ]
    end subroutine collect_walls_vy

    ! ------------------------------------------------------------------ helpers

    subroutine check_c(error, actual, expected, rtol, atol, message)
        type(test_error), allocatable, intent(inout) :: error
        complex(dp), intent(in) :: actual, expected
        real(dp), intent(in), optional :: rtol, atol
        character(len=*), intent(in) :: message
        real(dp) :: tolr, tola
        character(len=160) :: buf
        tolr = 0.0_dp
        tola = 0.0_dp
        if (present(rtol)) tolr = rtol
        if (present(atol)) tola = atol
        if (abs(actual - expected) <= max(tola, tolr*abs(expected))) return
        allocate(error)
        write(buf, '(a, 2es23.15, a, 2es23.15)') 'got ', actual, ' expected ', expected
        error%message = message//': '//trim(buf)
    end subroutine check_c

    !> Bit-for-bit equal values (no -Wcompare-reals): neither part differs.
    elemental logical function same(a, b)
        complex(dp), intent(in) :: a, b
        same = .not. (real(a, dp) < real(b, dp) .or. real(a, dp) > real(b, dp) .or. &
                      aimag(a) < aimag(b) .or. aimag(a) > aimag(b))
    end function same

    !> Message starts with `name`.
    subroutine check_msg(error, msg, name)
        type(test_error), allocatable, intent(inout) :: error
        character(len=*), intent(in) :: msg, name
        call check(error, index(msg, name) == 1, 'message "'//trim(msg)//'" should start with "' &
                   //name//'"')
    end subroutine check_msg

    !> Gauss-Legendre nodes and weights on [-1, 1] by Newton on P_n.
    subroutine gauss_legendre(n, xg, wg)
        integer, intent(in) :: n
        real(dp), intent(out) :: xg(n), wg(n)
        integer :: i, k, it
        real(dp) :: z, p0, p1, p2, dp1
        do i = 1, n
            z = cos(pi*(real(i, dp) - 0.25_dp)/(real(n, dp) + 0.5_dp))
            do it = 1, 100
                p0 = 1.0_dp
                p1 = z
                do k = 2, n
                    p2 = (real(2*k - 1, dp)*z*p1 - real(k - 1, dp)*p0)/real(k, dp)
                    p0 = p1
                    p1 = p2
                end do
                dp1 = real(n, dp)*(z*p1 - p0)/(z*z - 1.0_dp)
                if (abs(p1/dp1) < 1.0e-16_dp) exit
                z = z - p1/dp1
            end do
            xg(i) = z
            wg(i) = 2.0_dp/((1.0_dp - z*z)*dp1*dp1)
        end do
    end subroutine gauss_legendre

    !> 1-D free-field shear layer (not a series): u'' + k^2 u = Xg/V*^2, u(0) = 0,
    !> u'(H) = 0 gives u = (Xg/omega^2)(1 - cos(k(H - y))/cos(kH)); in rho Xg H^2/G,
    !> u = (4/(pi w)^2)(1 - cos(kap (1 - y))/cos kap), kap = (pi/2) w/sqrt(1 + i delta);
    !> tau = G* du/dy.
    subroutine free_field(w, delta, y, u, tau)
        real(dp), intent(in) :: w, delta, y
        complex(dp), intent(out) :: u, tau
        complex(dp) :: kap, g
        g = cmplx(1.0_dp, delta, dp)
        kap = 0.5_dp*pi*w/sqrt(g)
        u = 4.0_dp/(pi*w)**2*(1.0_dp - cos(kap*(1.0_dp - y))/cos(kap))
        tau = g*4.0_dp/(pi*w)**2*(-kap*sin(kap*(1.0_dp - y))/cos(kap))
    end subroutine free_field

    ! ------------------------------------------------------------------ tests

    subroutine test_psi(error)
        type(test_error), allocatable, intent(out) :: error
        type(wall_psi_t) :: psi
        integer :: stat
        character(len=200) :: msg
        ! doc/walls.md section 1 derived values
        call wall_psi(0.3_dp, psi, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, psi%e, 1.5584_dp, atol=5.0e-5_dp, message='psi_e(0.3)')
        if (allocated(error)) return
        call check(error, psi%o, 1.6903_dp, atol=5.0e-5_dp, message='psi_o(0.3)')
        if (allocated(error)) return
        call check(error, psi%sigma, 1.8334_dp, atol=5.0e-5_dp, message='psi_sigma(0.3)')
        if (allocated(error)) return
        call check(error, psi%v, 0.2750_dp, atol=5.0e-5_dp, message='psi_v(0.3)')
        if (allocated(error)) return
        call check(error, psi%sigma, psi%o**2/psi%e, rtol=1.0e-15_dp, message='psi_o^2/psi_e')
        if (allocated(error)) return
        call wall_psi(1.0_dp/3.0_dp, psi, stat)
        call check(error, psi%e, 1.5811_dp, atol=5.0e-5_dp, message='psi_e(1/3)')
        if (allocated(error)) return
        call check(error, psi%o, 1.7321_dp, atol=5.0e-5_dp, message='psi_o(1/3)')
        if (allocated(error)) return
        call check(error, psi%sigma, 1.8974_dp, atol=5.0e-5_dp, message='psi_sigma(1/3)')
        if (allocated(error)) return
        ! nu -> 0.5: sqrt(3), 2, 4/sqrt(3) (1.7321, 2, 2.3094); psi_t unbounded
        call wall_psi(0.5_dp - 1.0e-12_dp, psi, stat)
        call check(error, psi%e, sqrt(3.0_dp), rtol=1.0e-11_dp, message='psi_e(0.5-)')
        if (allocated(error)) return
        call check(error, psi%o, 2.0_dp, rtol=1.0e-11_dp, message='psi_o(0.5-)')
        if (allocated(error)) return
        call check(error, psi%sigma, 2.3094_dp, atol=5.0e-5_dp, message='psi_sigma(0.5-)')
        if (allocated(error)) return
        call check(error, psi%t > 1.0e5_dp, 'psi_t should blow up as nu -> 0.5')
        if (allocated(error)) return
        call wall_psi(0.5_dp, psi, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT)
        if (allocated(error)) return
        call check_msg(error, msg, 'nu')
    end subroutine test_psi

    subroutine test_free_field_frequencies(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: om(3)
        integer :: stat
        character(len=200) :: msg
        ! H = 10 m, Vs = 200 m/s: omega_1 = pi 200/20 = 10 pi rad/s, then 3x, 5x
        call free_field_frequencies(10.0_dp, 200.0_dp, om, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, om, [10.0_dp*pi, 30.0_dp*pi, 50.0_dp*pi], rtol=1.0e-15_dp)
        if (allocated(error)) return
        call free_field_frequencies(0.0_dp, 200.0_dp, om, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT)
        if (allocated(error)) return
        call check_msg(error, msg, 'height')
        if (allocated(error)) return
        call free_field_frequencies(10.0_dp, -1.0_dp, om, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT)
        if (allocated(error)) return
        call check_msg(error, msg, 'vs')
    end subroutine test_free_field_frequencies

    !> omega = 0: q = 14 zeta(3)/pi^3 psi_sigma, m = 32 beta(4)/pi^4 psi_sigma,
    !> h/H = (2/pi) beta(4)/lambda(3) = 0.59858; |q| = 0.9951 at nu = 0.3 (VY's 0.995).
    subroutine test_static(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: q, m
        real(dp) :: h
        integer :: stat, nt
        call vy_rigid(0.0_dp, 0.1_dp, 0.3_dp, 1.0e-12_dp, q, m, h, stat, nterms=nt)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, 14.0_dp*zeta3/pi**3, 0.542755_dp, atol=5.0e-7_dp, &
                   message='the closed form itself')
        if (allocated(error)) return
        call check_c(error, q, cmplx(14.0_dp*zeta3/pi**3*psis03, 0.0_dp, dp), rtol=1.0e-14_dp, &
                     message='static q')
        if (allocated(error)) return
        call check(error, abs(q), 0.9951_dp, atol=5.0e-5_dp, message='|q| at nu = 0.3')
        if (allocated(error)) return
        call check_c(error, m, cmplx(32.0_dp*beta4/pi**4*psis03, 0.0_dp, dp), rtol=1.0e-14_dp, &
                     message='static m')
        if (allocated(error)) return
        call check(error, h, 2.0_dp/pi*beta4/(7.0_dp*zeta3/8.0_dp), rtol=1.0e-14_dp, &
                   message='static h/H')
        if (allocated(error)) return
        call check(error, h, 0.59858_dp, atol=5.0e-6_dp, message='static h/H 0.59858')
        if (allocated(error)) return
        call check(error, nt, 1, 'omega = 0: the closed-form tail is exact after one term')
    end subroutine test_static

    !> (2.35)/(2.36) printed with 1/n^3 would give h/H = (2/pi) sum (-1)^k/n^3 / lambda(3)
    !> = (2/pi)(pi^3/32)/lambda(3) = 0.58647; the corrected 1/n^4 gives 0.59858.
    subroutine test_erratum_235(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: q, m
        real(dp) :: h, printed
        integer :: stat
        printed = 2.0_dp/pi*(pi**3/32.0_dp)/(7.0_dp*zeta3/8.0_dp)
        call check(error, printed, 0.58647_dp, atol=5.0e-6_dp, message='printed-form value')
        if (allocated(error)) return
        call vy_rigid(0.0_dp, 0.0_dp, 0.3_dp, vy_default_tol, q, m, h, stat)
        call check(error, abs(h - printed) > 0.01_dp, 'h/H must not be the printed 1/n^3 value')
        if (allocated(error)) return
        ! dynamic: the mpmath value with 1/n^4 at omega_ratio = 2, delta = 0.1
        call vy_rigid(2.0_dp, 0.1_dp, 0.3_dp, 1.0e-12_dp, q, m, h, stat)
        call check_c(error, m, (0.014097470809358711_dp, -0.34735250229276665_dp), &
                     rtol=1.0e-10_dp, message='m at omega_ratio 2')
    end subroutine test_erratum_235

    !> doc/walls.md section 3, nu = 0.3: VY |Q| and |h/H| columns to their printed digits.
    subroutine test_table(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: rows(4, 10) = reshape([ &
            0.1_dp, 0.5_dp, 1.1399_dp, 0.6030_dp, &
            0.1_dp, 0.8_dp, 1.6019_dp, 0.6123_dp, &
            0.1_dp, 1.0_dp, 3.0376_dp, 0.6268_dp, &
            0.1_dp, 1.5_dp, 0.8543_dp, 0.6302_dp, &
            0.1_dp, 2.0_dp, 0.5568_dp, 0.6243_dp, &
            0.1_dp, 3.0_dp, 0.4261_dp, 0.4632_dp, &
            0.05_dp, 1.0_dp, 4.2710_dp, 0.6298_dp, &
            0.2_dp, 1.0_dp, 2.1765_dp, 0.6223_dp, &
            0.0_dp, 0.5_dp, 1.1420_dp, 0.6031_dp, &
            0.0_dp, 2.0_dp, 0.5497_dp, 0.6328_dp], [4, 10])
        complex(dp) :: q, m
        real(dp) :: h
        integer :: stat, i
        character(len=40) :: lab
        do i = 1, 10
            call vy_rigid(rows(2, i), rows(1, i), 0.3_dp, 1.0e-10_dp, q, m, h, stat)
            write(lab, '(a, f5.2, a, f5.2)') 'delta ', rows(1, i), ' w ', rows(2, i)
            call check(error, stat, SEISPULSE_SUCCESS, trim(lab))
            if (allocated(error)) return
            call check(error, abs(q), rows(3, i), atol=5.0e-5_dp, message=trim(lab)//' |Q|')
            if (allocated(error)) return
            call check(error, h, rows(4, i), atol=5.0e-5_dp, message=trim(lab)//' |h/H|')
            if (allocated(error)) return
        end do
    end subroutine test_table

    !> q, m to 1e-10 against the mpmath sums (tol 1e-12).
    subroutine test_mpmath_qm(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: wd(2, 4) = reshape([0.5_dp, 0.1_dp, 2.0_dp, 0.0_dp, &
                                                   3.0_dp, 0.1_dp, 7.3_dp, 0.02_dp], [2, 4])
        complex(dp), parameter :: qref(4) = [(1.1397428533774365_dp, -0.01798109922950665_dp), &
            (0.06184373622879662_dp, -0.5462183074551296_dp), &
            (0.11740112234552671_dp, -0.40962713615270857_dp), &
            (0.007761507869471355_dp, -0.1629398321641886_dp)]
        complex(dp), parameter :: mref(4) = [(0.6872817170797274_dp, -0.011401821861456675_dp), &
            (-0.009120240017553275_dp, -0.3477333745550901_dp), &
            (-0.00452092088940568_dp, -0.19734218033392392_dp), &
            (0.0008420458490311993_dp, -0.08002047566112988_dp)]
        complex(dp) :: q, m
        real(dp) :: h
        integer :: stat, i
        do i = 1, 4
            call vy_rigid(wd(1, i), wd(2, i), 0.3_dp, 1.0e-12_dp, q, m, h, stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call check_c(error, q, qref(i), rtol=1.0e-10_dp, message='q')
            if (allocated(error)) return
            call check_c(error, m, mref(i), rtol=1.0e-10_dp, message='m')
            if (allocated(error)) return
        end do
    end subroutine test_mpmath_qm

    !> The error follows tol and more terms are summed as tol shrinks.
    subroutine test_tolerance(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp), parameter :: qref = (0.11740112234552671_dp, -0.40962713615270857_dp)
        complex(dp), parameter :: mref = (-0.00452092088940568_dp, -0.19734218033392392_dp)
        real(dp), parameter :: tols(4) = [1.0e-4_dp, 1.0e-8_dp, 1.0e-12_dp, 1.0e-15_dp]
        complex(dp) :: q, m
        real(dp) :: h
        integer :: stat, i, nt, nprev
        nprev = 0
        do i = 1, 4
            call vy_rigid(3.0_dp, 0.1_dp, 0.3_dp, tols(i), q, m, h, stat, nterms=nt)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call check_c(error, q, qref, rtol=tols(i) + 4.0e-15_dp, message='q within tol')
            if (allocated(error)) return
            call check_c(error, m, mref, rtol=tols(i) + 4.0e-15_dp, message='m within tol')
            if (allocated(error)) return
            call check(error, nt > nprev, 'nterms must grow as tol shrinks')
            if (allocated(error)) return
            nprev = nt
        end do
    end subroutine test_tolerance

    subroutine test_sweep(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: w(7)
        complex(dp) :: q(7), m(7), q1, m1
        real(dp) :: h(7), h1
        integer :: stat, i, nt(7), nt1
        w = [0.0_dp, 0.3_dp, 1.0_dp, 1.7_dp, 2.5_dp, 5.0_dp, 12.0_dp]
        call vy_rigid_sweep(w, 0.1_dp, 0.3_dp, 1.0e-8_dp, q, m, h, stat, nterms=nt)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        do i = 1, 7
            call vy_rigid(w(i), 0.1_dp, 0.3_dp, 1.0e-8_dp, q1, m1, h1, stat, nterms=nt1)
            call check(error, same(q(i), q1) .and. same(m(i), m1) .and. nt(i) == nt1, &
                       'sweep and pointwise must agree exactly')
            if (allocated(error)) return
            call check(error, h(i), h1, rtol=0.0_dp)
            if (allocated(error)) return
        end do
    end subroutine test_sweep

    !> omega = 0: p(1) = (8/pi^2) Catalan psi_sigma = 0.742454 psi_sigma; p(0) = 0.
    subroutine test_static_pressure(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: p(3)
        integer :: stat
        call vy_pressure(0.0_dp, 0.0_dp, 0.3_dp, [0.0_dp, 1.0_dp, 0.5_dp], 1.0e-12_dp, p, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, same(p(1), (0.0_dp, 0.0_dp)), 'p(0) must be 0')
        if (allocated(error)) return
        call check(error, 8.0_dp*catalan/pi**2, 0.742454_dp, atol=5.0e-7_dp, message='8G/pi^2')
        if (allocated(error)) return
        call check_c(error, p(2), cmplx(8.0_dp*catalan/pi**2*psis03, 0.0_dp, dp), &
                     rtol=1.0e-14_dp, message='static surface pressure')
        if (allocated(error)) return
        ! y = 1/2, t = pi/4: sum_odd sin(n pi/4)/n^2 = (Cl2(pi/4) + Cl2(3 pi/4))/2 (mpmath)
        call check_c(error, p(3), cmplx(8.0_dp/pi**2*0.7528807525058986030_dp*psis03, 0.0_dp, dp), &
                     rtol=1.0e-13_dp, message='static mid-height pressure')
    end subroutine test_static_pressure

    subroutine test_pressure_mpmath(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: p(2)
        integer :: stat
        call vy_pressure(2.0_dp, 0.1_dp, 0.3_dp, [0.3_dp, 0.8_dp], 1.0e-12_dp, p, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check_c(error, p(1), (0.26278607875581134_dp, -0.39840550972212085_dp), &
                     atol=1.0e-11_dp, message='p(0.3)')
        if (allocated(error)) return
        call check_c(error, p(2), (-0.06666262619048004_dp, -0.810976010611128_dp), &
                     atol=1.0e-11_dp, message='p(0.8)')
    end subroutine test_pressure_mpmath

    !> int_0^1 p dy = q and int_0^1 y p dy = m (graded Gauss-Legendre: dyadic panels
    !> toward the y log y behaviour at the base).
    subroutine test_pressure_integrals(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: ng = 12, npan = 40
        real(dp) :: xg(ng), wg(ng), y(ng*npan), wy(ng*npan), a, b
        complex(dp) :: p(ng*npan), q, m, iq, im
        real(dp) :: h
        integer :: stat, k, j, i, icase
        real(dp), parameter :: cases(2, 3) = reshape([0.8_dp, 0.1_dp, 2.0_dp, 0.0_dp, &
                                                      4.4_dp, 0.05_dp], [2, 3])
        call gauss_legendre(ng, xg, wg)
        i = 0
        do k = 1, npan
            b = 0.5_dp**(k - 1)
            a = 0.5_dp*b
            do j = 1, ng
                i = i + 1
                y(i) = 0.5_dp*(a + b) + 0.5_dp*(b - a)*xg(j)
                wy(i) = 0.5_dp*(b - a)*wg(j)
            end do
        end do
        do icase = 1, 3
            call vy_pressure(cases(1, icase), cases(2, icase), 0.3_dp, y, 1.0e-13_dp, p, stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call vy_rigid(cases(1, icase), cases(2, icase), 0.3_dp, 1.0e-13_dp, q, m, h, stat)
            iq = sum(wy*p)
            im = sum(wy*y*p)
            call check_c(error, iq, q, rtol=1.0e-10_dp, message='int p dy = q')
            if (allocated(error)) return
            call check_c(error, im, m, rtol=1.0e-10_dp, message='int y p dy = m')
            if (allocated(error)) return
        end do
    end subroutine test_pressure_integrals

    !> x = 0: sigma_x = -p, u = 0, tau = -nu/(2 - nu) y; v(0, 0.6) against mpmath.
    subroutine test_fields_wall(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: y(4)
        complex(dp) :: u(4), v(4), sx(4), tau(4), p(4)
        integer :: stat, i
        y = [0.0_dp, 0.25_dp, 0.6_dp, 1.0_dp]
        call vy_fields(2.0_dp, 0.1_dp, 0.3_dp, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], y, 1.0e-12_dp, &
                       u, v, sx, tau, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call vy_pressure(2.0_dp, 0.1_dp, 0.3_dp, y, 1.0e-12_dp, p, stat)
        do i = 1, 4
            call check(error, same(u(i), (0.0_dp, 0.0_dp)), 'u(0, y) = 0')
            if (allocated(error)) return
            call check_c(error, sx(i), -p(i), rtol=0.0_dp, message='sigma_x(0, y) = -p(y)')
            if (allocated(error)) return
            call check_c(error, tau(i), cmplx(-0.3_dp/1.7_dp*y(i), 0.0_dp, dp), rtol=1.0e-15_dp, &
                         message='tau(0, y)')
            if (allocated(error)) return
        end do
        call check_c(error, v(3), (0.014292326595633415_dp, -0.035752385948604234_dp), &
                     atol=1.0e-12_dp, message='v(0, 0.6)')
        if (allocated(error)) return
        call check(error, same(v(1), (0.0_dp, 0.0_dp)), 'v(0, 0) = 0')
    end subroutine test_fields_wall

    !> Far from the wall u and tau are the free-field shear-layer response; static surface
    !> value -rho Xg H^2/(2G) exactly.
    subroutine test_free_field(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: u(3), v(3), sx(3), tau(3), uff, tff
        real(dp) :: y(3)
        integer :: stat, i
        call vy_fields(0.0_dp, 0.0_dp, 0.3_dp, [60.0_dp], [1.0_dp], 1.0e-12_dp, u(1:1), v(1:1), &
                       sx(1:1), tau(1:1), stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check_c(error, u(1), (-0.5_dp, 0.0_dp), rtol=1.0e-12_dp, message='static u_ff(H)')
        if (allocated(error)) return
        ! omega_ratio 1.4 > 1: mode 1 radiates and decays only through delta,
        ! |E_1| = exp(-0.1 x), so x = 1000 is far enough
        y = [0.2_dp, 0.7_dp, 1.0_dp]
        call vy_fields(1.4_dp, 0.1_dp, 0.3_dp, [1000.0_dp, 1000.0_dp, 1000.0_dp], y, &
                       1.0e-12_dp, u, v, sx, tau, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        do i = 1, 3
            call free_field(1.4_dp, 0.1_dp, y(i), uff, tff)
            call check_c(error, u(i), uff, rtol=1.0e-11_dp, message='u -> u_ff')
            if (allocated(error)) return
            call check_c(error, tau(i), tff, rtol=1.0e-10_dp, atol=1.0e-12_dp, &
                         message='tau -> tau_ff')
            if (allocated(error)) return
            call check(error, abs(sx(i)) < 1.0e-30_dp .and. abs(v(i)) < 1.0e-30_dp, &
                       'sigma_x, v -> 0')
            if (allocated(error)) return
        end do
    end subroutine test_free_field

    !> Fields inside the backfill against term-by-term mpmath sums.
    subroutine test_fields_mpmath(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: u(3), v(3), sx(3), tau(3)
        complex(dp), parameter :: ref(4, 3) = reshape([ &
            (0.026533567902015887_dp, 0.07391143064427397_dp), &
            (-0.0155904695979746_dp, -0.03780910246726888_dp), &
            (0.3506334426993527_dp, 0.663393839841254_dp), &
            (-0.010902346260033613_dp, 0.0957260150119187_dp), &
            (0.1250216265533164_dp, 0.11976949211429923_dp), &
            (-0.022345931927507553_dp, 0.004179259315168354_dp), &
            (0.5814541187278588_dp, -0.1056583008916017_dp), &
            (0.343643878772137_dp, 0.22938918087183302_dp), &
            (0.004033605395151935_dp, 0.01445057098485123_dp), &
            (-0.002006224545600874_dp, -0.0817097864576937_dp), &
            (0.17749448608437768_dp, 0.8466649633432708_dp), &
            (-0.16594646017908826_dp, 0.012422909010288754_dp)], [4, 3])
        real(dp), parameter :: pts(3, 3) = reshape([0.1_dp, 0.3_dp, 0.7_dp, &
                                                    0.0_dp, 1.0_dp, 0.5_dp, &
                                                    0.1_dp, 0.05_dp, 1.0_dp], [3, 3])
        integer :: stat, i
        do i = 1, 3
            call vy_fields(2.0_dp, pts(1, i), 0.3_dp, pts(2, i:i), pts(3, i:i), 1.0e-12_dp, &
                           u(i:i), v(i:i), sx(i:i), tau(i:i), stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call check_c(error, u(i), ref(1, i), atol=1.0e-11_dp, message='u')
            if (allocated(error)) return
            call check_c(error, v(i), ref(2, i), atol=1.0e-11_dp, message='v')
            if (allocated(error)) return
            call check_c(error, sx(i), ref(3, i), atol=1.0e-11_dp, message='sigma_x')
            if (allocated(error)) return
            call check_c(error, tau(i), ref(4, i), atol=1.0e-11_dp, message='tau')
            if (allocated(error)) return
        end do
    end subroutine test_fields_mpmath

    !> delta = 0 above resonance (radiating) equals the delta -> 0+ limit.
    subroutine test_branch(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: q0, m0, q1, m1, p0(2), p1(2)
        complex(dp) :: u0(1), v0(1), s0(1), t0(1), u1(1), v1(1), s1(1), t1(1)
        real(dp) :: h0, h1
        integer :: stat
        call vy_rigid(2.0_dp, 0.0_dp, 0.3_dp, 1.0e-12_dp, q0, m0, h0, stat)
        call vy_rigid(2.0_dp, 1.0e-13_dp, 0.3_dp, 1.0e-12_dp, q1, m1, h1, stat)
        call check_c(error, q0, q1, rtol=1.0e-9_dp, message='q, delta 0 vs 1e-13')
        if (allocated(error)) return
        call check_c(error, m0, m1, rtol=1.0e-9_dp, message='m, delta 0 vs 1e-13')
        if (allocated(error)) return
        ! radiation damping: Im q < 0 (r_1 = -i/sqrt(3))
        call check(error, aimag(q0) < -0.1_dp, 'radiating branch: Im q < 0')
        if (allocated(error)) return
        call vy_pressure(2.0_dp, 0.0_dp, 0.3_dp, [0.4_dp, 1.0_dp], 1.0e-12_dp, p0, stat)
        call vy_pressure(2.0_dp, 1.0e-13_dp, 0.3_dp, [0.4_dp, 1.0_dp], 1.0e-12_dp, p1, stat)
        call check_c(error, p0(1), p1(1), rtol=1.0e-9_dp, message='p(0.4)')
        if (allocated(error)) return
        call check_c(error, p0(2), p1(2), rtol=1.0e-9_dp, message='p(1)')
        if (allocated(error)) return
        call vy_fields(2.0_dp, 0.0_dp, 0.3_dp, [0.5_dp], [0.8_dp], 1.0e-12_dp, u0, v0, s0, t0, &
                       stat)
        call vy_fields(2.0_dp, 1.0e-13_dp, 0.3_dp, [0.5_dp], [0.8_dp], 1.0e-12_dp, u1, v1, s1, &
                       t1, stat)
        call check_c(error, u0(1), u1(1), rtol=1.0e-9_dp, message='u')
        if (allocated(error)) return
        call check_c(error, v0(1), v1(1), rtol=1.0e-9_dp, message='v')
        if (allocated(error)) return
        call check_c(error, s0(1), s1(1), rtol=1.0e-9_dp, message='sigma_x')
        if (allocated(error)) return
        call check_c(error, t0(1), t1(1), rtol=1.0e-9_dp, message='tau')
    end subroutine test_branch

    !> -0.0 for delta, omega_ratio, x or y gives the results of +0.0 bit for bit.
    subroutine test_signed_zero(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: nz, h0, h1
        complex(dp) :: q0, m0, q1, m1, p0(1), p1(1)
        complex(dp) :: u0(2), v0(2), s0(2), t0(2), u1(2), v1(2), s1(2), t1(2)
        integer :: stat
        nz = -0.0_dp
        call vy_rigid(2.0_dp, 0.0_dp, 0.3_dp, 1.0e-10_dp, q0, m0, h0, stat)
        call vy_rigid(2.0_dp, nz, 0.3_dp, 1.0e-10_dp, q1, m1, h1, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. same(q0, q1) .and. same(m0, m1), &
                   'delta = -0.0 (radiating branch)')
        if (allocated(error)) return
        call vy_rigid(0.0_dp, 0.1_dp, 0.3_dp, 1.0e-10_dp, q0, m0, h0, stat)
        call vy_rigid(nz, 0.1_dp, 0.3_dp, 1.0e-10_dp, q1, m1, h1, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. same(q0, q1) .and. same(m0, m1), &
                   'omega_ratio = -0.0')
        if (allocated(error)) return
        call vy_pressure(2.5_dp, 0.0_dp, 0.3_dp, [0.7_dp], 1.0e-10_dp, p0, stat)
        call vy_pressure(2.5_dp, nz, 0.3_dp, [0.7_dp], 1.0e-10_dp, p1, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. same(p0(1), p1(1)), &
                   'pressure, delta -0.0')
        if (allocated(error)) return
        call vy_fields(2.5_dp, 0.0_dp, 0.3_dp, [0.0_dp, 0.4_dp], [0.0_dp, 0.6_dp], 1.0e-10_dp, &
                       u0, v0, s0, t0, stat)
        call vy_fields(2.5_dp, nz, 0.3_dp, [nz, 0.4_dp], [nz, 0.6_dp], 1.0e-10_dp, u1, v1, s1, &
                       t1, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'fields with -0.0')
        if (allocated(error)) return
        call check(error, all(same(u0, u1)) .and. all(same(v0, v1)) .and. all(same(s0, s1)) .and. &
                   all(same(t0, t1)), 'fields, -0.0 for delta, x, y')
        if (allocated(error)) return
        call check(error, all(sign(1.0_dp, [real(u1(1), dp), aimag(u1(1)), real(v1(1), dp), &
                   aimag(v1(1)), real(s1(1), dp), aimag(s1(1)), real(t1(1), dp), aimag(t1(1))]) &
                   > 0.0_dp), 'the corner (0, 0) gives +0.0, no -0.0')
    end subroutine test_signed_zero

    subroutine test_resonance(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: q, m, qs(2), ms(2), p(1), u(1), v(1), sx(1), tau(1)
        real(dp) :: h, hs(2)
        integer :: stat
        character(len=256) :: msg
        call vy_rigid(1.0_dp, 0.0_dp, 0.3_dp, vy_default_tol, q, m, h, stat, msg)
        call check(error, stat, SEISPULSE_SINGULAR, 'omega_ratio = 1')
        if (allocated(error)) return
        call check_msg(error, msg, 'omega_ratio')
        if (allocated(error)) return
        call vy_rigid(3.0_dp, 0.0_dp, 0.3_dp, vy_default_tol, q, m, h, stat, msg)
        call check(error, stat, SEISPULSE_SINGULAR, 'omega_ratio = 3')
        if (allocated(error)) return
        call vy_rigid_sweep([0.5_dp, 5.0_dp], 0.0_dp, 0.3_dp, vy_default_tol, qs, ms, hs, stat, msg)
        call check(error, stat, SEISPULSE_SINGULAR, 'sweep at 5')
        if (allocated(error)) return
        call check_msg(error, msg, 'omega_ratios(2)')
        if (allocated(error)) return
        call vy_pressure(3.0_dp, 0.0_dp, 0.3_dp, [0.5_dp], vy_default_tol, p, stat)
        call check(error, stat, SEISPULSE_SINGULAR, 'pressure at 3')
        if (allocated(error)) return
        call vy_fields(1.0_dp, 0.0_dp, 0.3_dp, [0.5_dp], [0.5_dp], vy_default_tol, u, v, sx, tau, &
                       stat)
        call check(error, stat, SEISPULSE_SINGULAR, 'fields at 1')
        if (allocated(error)) return
        ! even integers are not resonances; 1 +- 1e-9 is finite and large:
        ! |q| ~ (16 psi/pi^3)/sqrt(2e-9) = 2.1e4
        call vy_rigid(2.0_dp, 0.0_dp, 0.3_dp, vy_default_tol, q, m, h, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'omega_ratio = 2')
        if (allocated(error)) return
        call vy_rigid(1.0_dp + 1.0e-9_dp, 0.0_dp, 0.3_dp, vy_default_tol, q, m, h, stat)
        call check(error, stat, SEISPULSE_SUCCESS, '1 + 1e-9')
        if (allocated(error)) return
        call check(error, abs(q), 16.0_dp*psis03/pi**3/sqrt(2.0e-9_dp), rtol=1.0e-3_dp, &
                   message='|q| near resonance (first term)')
        if (allocated(error)) return
        call check(error, abs(aimag(q)) > 1.0e4_dp .and. abs(real(q, dp)) < 10.0_dp, &
                   'above 1: radiating, q almost -i |q|')
        if (allocated(error)) return
        call vy_rigid(1.0_dp - 1.0e-9_dp, 0.0_dp, 0.3_dp, vy_default_tol, q, m, h, stat)
        call check(error, stat, SEISPULSE_SUCCESS, '1 - 1e-9')
        if (allocated(error)) return
        call check(error, real(q, dp) > 1.0e4_dp .and. abs(aimag(q)) <= 0.0_dp, &
                   'below 1: real and large')
    end subroutine test_resonance

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: nan
        complex(dp) :: q, m, qs(2), ms(2), p(2), u(2), v(2), sx(2), tau(2)
        real(dp) :: h, hs(2)
        integer :: stat
        character(len=256) :: msg
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        call vy_rigid(nan, 0.1_dp, 0.3_dp, vy_default_tol, q, m, h, stat, msg)
        call expect('omega_ratio')
        if (allocated(error)) return
        call vy_rigid(-1.0_dp, 0.1_dp, 0.3_dp, vy_default_tol, q, m, h, stat, msg)
        call expect('omega_ratio')
        if (allocated(error)) return
        call vy_rigid(2.0e4_dp, 0.1_dp, 0.3_dp, vy_default_tol, q, m, h, stat, msg)
        call expect('omega_ratio')
        if (allocated(error)) return
        call vy_rigid(1.0_dp, nan, 0.3_dp, vy_default_tol, q, m, h, stat, msg)
        call expect('delta')
        if (allocated(error)) return
        call vy_rigid(1.0_dp, -0.1_dp, 0.3_dp, vy_default_tol, q, m, h, stat, msg)
        call expect('delta')
        if (allocated(error)) return
        call vy_rigid(1.0_dp, 0.1_dp, 0.5_dp, vy_default_tol, q, m, h, stat, msg)
        call expect('nu')
        if (allocated(error)) return
        call vy_rigid(1.0_dp, 0.1_dp, -0.1_dp, vy_default_tol, q, m, h, stat, msg)
        call expect('nu')
        if (allocated(error)) return
        call vy_rigid(1.0_dp, 0.1_dp, nan, vy_default_tol, q, m, h, stat, msg)
        call expect('nu')
        if (allocated(error)) return
        call vy_rigid(1.0_dp, 0.1_dp, 0.3_dp, 1.0e-16_dp, q, m, h, stat, msg)
        call expect('tol')
        if (allocated(error)) return
        call vy_rigid(1.0_dp, 0.1_dp, 0.3_dp, 0.1_dp, q, m, h, stat, msg)
        call expect('tol')
        if (allocated(error)) return
        call vy_rigid(1.0_dp, 0.1_dp, 0.3_dp, nan, q, m, h, stat, msg)
        call expect('tol')
        if (allocated(error)) return
        call vy_rigid_sweep([0.5_dp, nan], 0.1_dp, 0.3_dp, vy_default_tol, qs, ms, hs, stat, msg)
        call expect('omega_ratios(2)')
        if (allocated(error)) return
        call vy_rigid_sweep([0.5_dp, 1.0_dp], 0.1_dp, 0.3_dp, vy_default_tol, qs(1:1), ms, hs, &
                            stat, msg)
        call expect('q, m, h_ratio')
        if (allocated(error)) return
        call vy_pressure(1.0_dp, 0.1_dp, 0.3_dp, [0.5_dp, 1.5_dp], vy_default_tol, p, stat, msg)
        call expect('y(2)')
        if (allocated(error)) return
        call vy_pressure(1.0_dp, 0.1_dp, 0.3_dp, [nan, 0.5_dp], vy_default_tol, p, stat, msg)
        call expect('y(1)')
        if (allocated(error)) return
        call vy_pressure(1.0_dp, 0.1_dp, 0.3_dp, [0.5_dp, -0.5_dp], vy_default_tol, p, stat, msg)
        call expect('y(2)')
        if (allocated(error)) return
        call vy_pressure(1.0_dp, 0.1_dp, 0.3_dp, [0.5_dp], vy_default_tol, p, stat, msg)
        call expect('p')
        if (allocated(error)) return
        call vy_fields(1.0_dp, 0.1_dp, 0.3_dp, [0.5_dp, -1.0_dp], [0.5_dp, 0.5_dp], &
                       vy_default_tol, u, v, sx, tau, stat, msg)
        call expect('x(2)')
        if (allocated(error)) return
        call vy_fields(1.0_dp, 0.1_dp, 0.3_dp, [ieee_value(1.0_dp, ieee_positive_inf), 1.0_dp], &
                       [0.5_dp, 0.5_dp], &
                       vy_default_tol, u, v, sx, tau, stat, msg)
        call expect('x(1)')
        if (allocated(error)) return
        call vy_fields(1.0_dp, 0.1_dp, 0.3_dp, [0.5_dp, 1.0_dp], [0.5_dp, 2.0_dp], &
                       vy_default_tol, u, v, sx, tau, stat, msg)
        call expect('y(2)')
        if (allocated(error)) return
        call vy_fields(1.0_dp, 0.1_dp, 0.3_dp, [0.5_dp, 1.0_dp], [0.5_dp], &
                       vy_default_tol, u, v, sx, tau, stat, msg)
        call expect('x, y')
        if (allocated(error)) return
        call vy_fields(1.0_dp, 0.1_dp, 0.3_dp, [0.5_dp], [0.5_dp], &
                       vy_default_tol, u, v, sx, tau, stat, msg)
        call expect('u, v, sigma_x, tau')
    contains
        subroutine expect(name)
            character(len=*), intent(in) :: name
            call check(error, stat, SEISPULSE_INVALID_INPUT, name)
            if (allocated(error)) return
            call check_msg(error, msg, name)
        end subroutine expect
    end subroutine test_bad_input

end module test_walls_vy
