!> Flexible sliding masses (seispulse_flexible_model, seispulse_flexible): the radiation
!> damping and the equivalent-linear curves against hand values, the equivalent-linear
!> iteration (two passes at least, the 5 % rule, the cap and its status), the checks,
!> SLAMMER's arithmetic against short records worked by the formulas in the test, the
!> stiff limit (HEA = a), SLAMMER's stepwise yield table, polarity and histories, and
!> SLAMMER 1.1's own Java code run on the same samples.
module test_flexible
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_CONVERGENCE
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid, &
                                 NEWMARK_BOTH, NEWMARK_ASYM, NEWMARK_EXACT
    use seispulse_flexible_model, only: flexible_mass_t, flexible_result_t, modal_peak_t, &
                                        flexible_mass_validate, radiation_damping, &
                                        eql_properties, ky_table_validate, eql_iterate, &
                                        masing_damping_pct, SOIL_LINEAR, SOIL_EQUIVALENT_LINEAR, &
                                        FLEX_SLAMMER, FLEX_EXACT
    use seispulse_flexible, only: flexible_decoupled, flexible_coupled
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_flexible

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: g0 = 9.80665_dp

    !> A response whose peak is fixed (m); it records what the iteration asks.
    type, extends(modal_peak_t) :: fixed_peak_t
        real(dp) :: u0 = 0.0_dp
        integer :: calls = 0
        real(dp) :: omega_seen(4) = 0.0_dp, xi_seen(4) = 0.0_dp
    contains
        procedure :: peak => fixed_peak
    end type fixed_peak_t

    !> A response whose peak alternates between two values: the iteration cannot settle.
    type, extends(modal_peak_t) :: flip_peak_t
        integer :: calls = 0
    contains
        procedure :: peak => flip_peak
    end type flip_peak_t

contains

    subroutine collect_flexible(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('radiation damping: Lee 2004 and its cap', test_radiation), &
                 new_unittest('equivalent-linear curves: hand values, small strains', &
                              test_eql_curves), &
                 new_unittest('EQL iteration: two passes at least, 5 % rule, user damping ' &
                              //'dropped', test_eql_iteration), &
                 new_unittest('EQL iteration: the cap gives a status and keeps the last pass', &
                              test_eql_cap), &
                 new_unittest('bad input is a status naming the parameter', test_bad_input), &
                 new_unittest('SLAMMER decoupled: a short record worked by the formulas', &
                              test_slammer_decoupled_hand), &
                 new_unittest('SLAMMER coupled: a short record worked by the formulas', &
                              test_slammer_coupled_hand), &
                 new_unittest('stiff mass: HEA = a, u = 0', &
                              test_stiff_limit), &
                 new_unittest('SLAMMER yield table: row 2 from the first step', test_ky_table), &
                 new_unittest('polarity, kmax sign and histories', test_polarity_histories), &
                 new_unittest('SLAMMER 1.1 Java on the same samples (LE, EQL, table)', &
                              test_slammer_java), &
                 new_unittest('exact rule: stiff limit = rigid block, two-way odd, near SLAMMER', &
                              test_exact_dispatch)]
    end subroutine collect_flexible

    ! ---------------------------------------------------------------- helpers

    subroutine fixed_peak(self, omega, xi, u_peak, stat, errmsg)
        class(fixed_peak_t), intent(inout) :: self
        real(dp), intent(in) :: omega, xi
        real(dp), intent(out) :: u_peak
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        if (present(errmsg)) continue
        self%calls = self%calls + 1
        if (self%calls <= size(self%omega_seen)) then
            self%omega_seen(self%calls) = omega
            self%xi_seen(self%calls) = xi
        end if
        u_peak = self%u0
        stat = SEISPULSE_SUCCESS
    end subroutine fixed_peak

    subroutine flip_peak(self, omega, xi, u_peak, stat, errmsg)
        class(flip_peak_t), intent(inout) :: self
        real(dp), intent(in) :: omega, xi
        real(dp), intent(out) :: u_peak
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        if (present(errmsg)) continue
        if (omega < 0.0_dp .or. xi < -1.0_dp) continue
        self%calls = self%calls + 1
        u_peak = 0.001_dp
        if (mod(self%calls, 2) == 0) u_peak = 0.05_dp
        stat = SEISPULSE_SUCCESS
    end subroutine flip_peak

    !> The synthetic record of the Java comparison (g), 1500 samples at 0.01 s.
    function synthetic() result(a)
        real(dp) :: a(1500), t
        integer :: i
        do i = 1, size(a)
            t = real(i - 1, dp) * 0.01_dp
            a(i) = (t / 3.0_dp)**2 * exp(2.0_dp * (1.0_dp - t / 3.0_dp)) &
                   * (0.35_dp * sin(6.9_dp * t) + 0.25_dp * sin(17.0_dp * t + 0.5_dp) &
                      + 0.1_dp * sin(39.6_dp * t))
        end do
    end function synthetic

    !> One step of Newmark's average-acceleration method (Chopra's incremental form with
    !> beta = 1/4, gamma = 1/2) for m u'' + c u' + k u = p: the constants reduce to
    !> k^ = k + 2c/dt + 4m/dt^2, a = 4m/dt + 2c, b = 2m.
    subroutine avg_accel_step(m, c, k, dt, dp_load, u, v, w)
        real(dp), intent(in) :: m, c, k, dt, dp_load
        real(dp), intent(inout) :: u, v, w
        real(dp) :: du
        du = (dp_load + (4.0_dp * m / dt + 2.0_dp * c) * v + 2.0_dp * m * w) &
             / (k + 2.0_dp * c / dt + 4.0_dp * m / dt**2)
        u = u + du
        w = w + 4.0_dp * du / dt**2 - 4.0_dp * v / dt - 2.0_dp * w
        v = v + 2.0_dp * du / dt - 2.0_dp * v
    end subroutine avg_accel_step

    ! ---------------------------------------------------------------- tests

    subroutine test_radiation(error)
        type(test_error), allocatable, intent(out) :: error
        ! 0.55016 (1000/200)^-0.9904 and 0.55016 2^-0.9904 (Python, double precision)
        call check(error, radiation_damping(200.0_dp, 1000.0_dp), 0.1117452622405082_dp, &
                   rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, radiation_damping(300.0_dp, 900.0_dp), 0.18533102200611595_dp, &
                   rtol=1.0e-14_dp)
        if (allocated(error)) return
        ! 0.55016 2^-0.9904 = 0.2769 is above the cap: 0.2; equal velocities (SLAMMER's
        ! whole test set): 0.2
        call check(error, radiation_damping(300.0_dp, 600.0_dp), 0.2_dp, &
                   message='capped at 0.2')
        if (allocated(error)) return
        call check(error, radiation_damping(600.0_dp, 600.0_dp), 0.2_dp)
        if (allocated(error)) return
        ! a stiff base lowers it: scale invariance (only the ratio counts)
        call check(error, radiation_damping(20.0_dp, 100.0_dp), &
                   radiation_damping(200.0_dp, 1000.0_dp), rtol=1.0e-15_dp)
    end subroutine test_radiation

    subroutine test_eql_curves(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: gr, xi, x, d_closed, d_series
        ! gamma = gamma_r: G/Gmax = 1/2, D_Masing = (100/pi)(8 (1 - ln 2) - 2) = 14.477451588 %
        call eql_properties(0.05_dp, 0.05_dp, gr, xi)
        call check(error, gr, 0.5_dp)
        if (allocated(error)) return
        call check(error, masing_damping_pct(1.0_dp), 14.477451588153134_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, xi, 0.0937492277837677_dp, rtol=1.0e-14_dp, &
                   message='0.62 (1/2)^0.1 D + 1 %')
        if (allocated(error)) return
        ! gamma = 3 gamma_r: G/Gmax = 1/4, D = (100/pi)(4 (4/9)(3 - ln 4) - 2)
        call eql_properties(0.3_dp, 0.1_dp, gr, xi)
        call check(error, gr, 0.25_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, xi, (0.62_dp * 0.25_dp**0.1_dp * 100.0_dp / pi &
                               * (16.0_dp / 9.0_dp * (3.0_dp - log(4.0_dp)) - 2.0_dp) &
                               + 1.0_dp) / 100.0_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        ! gamma -> 0: G/Gmax = 1, D -> 0 like (400/pi)(x/6 - x^2/12), xi -> 1 %
        call eql_properties(0.0_dp, 0.05_dp, gr, xi)
        call check(error, gr, 1.0_dp)
        if (allocated(error)) return
        call check(error, xi, 0.01_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        x = 1.0e-7_dp
        call check(error, masing_damping_pct(x), 400.0_dp / pi * (x / 6.0_dp - x**2 / 12.0_dp), &
                   rtol=1.0e-13_dp, message='small-strain series')
        if (allocated(error)) return
        ! the series and the closed form meet at x = 0.1 (both sides)
        d_series = masing_damping_pct(0.1_dp - epsilon(1.0_dp))
        x = 0.1_dp
        d_closed = 100.0_dp / pi * (4.0_dp * (1.0_dp + x) * (x - log(1.0_dp + x)) / x**2 - 2.0_dp)
        call check(error, d_series, d_closed, rtol=1.0e-11_dp, message='series at 0.1')
        if (allocated(error)) return
        call check(error, masing_damping_pct(0.1_dp), d_closed, rtol=1.0e-11_dp)
        if (allocated(error)) return
        ! large strains: D_Masing -> 200/pi %, G/Gmax -> 0
        call check(error, masing_damping_pct(1.0e12_dp), 200.0_dp / pi, rtol=1.0e-9_dp)
    end subroutine test_eql_curves

    subroutine test_eql_iteration(error)
        type(test_error), allocatable, intent(out) :: error
        type(flexible_mass_t) :: mass
        type(fixed_peak_t) :: resp
        real(dp) :: vs, xi, xi_f, gamma_pct, gr, d_mat
        integer :: it, stat
        logical :: conv
        mass = flexible_mass_t(height=20.0_dp, vs=300.0_dp, vs_base=900.0_dp, damping=0.07_dp, &
                               soil=SOIL_EQUIVALENT_LINEAR, ref_strain_pct=0.05_dp, max_iter=50)
        ! a fixed peak: the second pass sees the same strain -> converged after 2 passes
        resp%u0 = 0.01_dp
        call eql_iterate(mass, resp, vs, xi, xi_f, it, conv, stat)
        call check(error, stat == SEISPULSE_SUCCESS .and. conv, 'converged')
        if (allocated(error)) return
        call check(error, it, 2, 'at least two passes (previous material damping 0)')
        if (allocated(error)) return
        gamma_pct = 100.0_dp * 0.65_dp * 1.57_dp * 0.01_dp / 20.0_dp
        call check(error, vs, 300.0_dp / sqrt(1.0_dp + gamma_pct / 0.05_dp), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call eql_properties(gamma_pct, 0.05_dp, gr, d_mat)
        call check(error, xi_f, 0.55016_dp * (900.0_dp / vs)**(-0.9904_dp), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, xi, d_mat + xi_f, rtol=1.0e-14_dp)
        if (allocated(error)) return
        ! first pass: the user's damping with the radiation damping of Vs0, omega of Vs0
        call check(error, resp%omega_seen(1), pi * 300.0_dp / 40.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, resp%xi_seen(1), &
                   0.07_dp + min(0.2_dp, 0.55016_dp * 3.0_dp**(-0.9904_dp)), rtol=1.0e-14_dp)
        if (allocated(error)) return
        ! second pass: the user's damping is gone
        call check(error, resp%xi_seen(2), xi, rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! a linear mass: no pass
        mass%soil = SOIL_LINEAR
        resp%calls = 0
        call eql_iterate(mass, resp, vs, xi, xi_f, it, conv, stat)
        call check(error, it == 0 .and. resp%calls == 0 .and. conv, 'linear: no pass')
        if (allocated(error)) return
        call check(error, vs, 300.0_dp)
        if (allocated(error)) return
        call check(error, xi, 0.07_dp + min(0.2_dp, 0.55016_dp * 3.0_dp**(-0.9904_dp)), &
                   rtol=1.0e-14_dp)
    end subroutine test_eql_iteration

    subroutine test_eql_cap(error)
        type(test_error), allocatable, intent(out) :: error
        type(flexible_mass_t) :: mass
        type(flip_peak_t) :: resp
        type(flexible_result_t) :: res
        real(dp) :: vs, xi, xi_f, gr, d_mat
        integer :: it, stat
        logical :: conv
        character(len=300) :: msg
        mass = flexible_mass_t(height=10.0_dp, vs=200.0_dp, vs_base=200.0_dp, damping=0.05_dp, &
                               soil=SOIL_EQUIVALENT_LINEAR, ref_strain_pct=0.05_dp, max_iter=7)
        msg = ''
        call eql_iterate(mass, resp, vs, xi, xi_f, it, conv, stat, msg)
        call check(error, stat, SEISPULSE_NO_CONVERGENCE, 'status')
        if (allocated(error)) return
        call check(error, .not. conv .and. it == 7 .and. resp%calls == 7, 'seven passes')
        if (allocated(error)) return
        call check(error, index(msg, 'max_iter = 7') == 1 .and. index(msg, 'last iteration') > 0, &
                   'message: '//trim(msg))
        if (allocated(error)) return
        ! the last (7th, odd) pass saw u = 0.001 m
        call eql_properties(100.0_dp * 0.65_dp * 1.57_dp * 0.001_dp / 10.0_dp, 0.05_dp, gr, d_mat)
        call check(error, vs, 200.0_dp * sqrt(gr), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, xi, d_mat + 0.2_dp, rtol=1.0e-14_dp)
        if (allocated(error)) return
        ! through the analysis: one pass is never enough
        mass%max_iter = 1
        call flexible_decoupled(synthetic(), 0.01_dp, 0.1_dp, mass, FLEX_SLAMMER, g0, res, stat, &
                                msg)
        call check(error, stat, SEISPULSE_NO_CONVERGENCE, 'analysis status')
        if (allocated(error)) return
        call check(error, .not. res%converged .and. res%iterations == 1 &
                   .and. res%max_disp > 0.0_dp .and. res%vs_final < 200.0_dp &
                   .and. abs(res%kmax) > 0.0_dp, 'results kept')
    end subroutine test_eql_cap

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(flexible_mass_t) :: good, m
        type(flexible_result_t) :: res
        real(dp) :: a(20), short(3)
        integer :: stat
        character(len=300) :: msg
        a = 0.1_dp
        good = flexible_mass_t(height=10.0_dp, vs=200.0_dp, vs_base=400.0_dp, damping=0.05_dp)
        m = good
        m%height = 0.0_dp
        call expect_mass(m, 'height = ')
        if (allocated(error)) return
        m = good
        m%vs = -1.0_dp
        call expect_mass(m, 'vs = ')
        if (allocated(error)) return
        m = good
        m%vs_base = 0.0_dp
        call expect_mass(m, 'vs_base = ')
        if (allocated(error)) return
        m = good
        m%damping = -0.6_dp
        call expect_mass(m, 'damping = ')
        if (allocated(error)) return
        m%damping = 1.0_dp
        call expect_mass(m, 'damping = ')
        if (allocated(error)) return
        call check(error, index(msg, '[-0.5, 1)') > 0, msg)
        if (allocated(error)) return
        m = good
        m%soil = 3
        call expect_mass(m, 'soil = ')
        if (allocated(error)) return
        m = good
        m%ref_strain_pct = 0.0_dp
        call expect_mass(m, 'ref_strain_pct = ')
        if (allocated(error)) return
        call check(error, index(msg, 'percent') > 0, msg)
        if (allocated(error)) return
        m = good
        m%max_iter = 0
        call expect_mass(m, 'max_iter = ')
        if (allocated(error)) return
        ! the lower end of damping is allowed
        m = good
        m%damping = -0.5_dp
        call flexible_mass_validate(m, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'damping = -0.5')
        if (allocated(error)) return

        ! tables
        call ky_table_validate([0.0_dp, 0.1_dp], [0.1_dp], stat, msg)
        call expect('ky_values: ')
        if (allocated(error)) return
        call ky_table_validate([0.01_dp, 0.1_dp], [0.1_dp, 0.2_dp], stat, msg)
        call expect('ky_disp(1) = ')
        if (allocated(error)) return
        call ky_table_validate([0.0_dp, 0.1_dp, 0.1_dp], [0.1_dp, 0.2_dp, 0.3_dp], stat, msg)
        call expect('ky_disp(3) = ')
        if (allocated(error)) return
        call ky_table_validate([0.0_dp, 0.1_dp], [0.1_dp, 0.0_dp], stat, msg)
        call expect('ky_values(2) = ')
        if (allocated(error)) return
        call ky_table_validate(short(1:0), short(1:0), stat, msg)
        call expect('ky_disp: ')
        if (allocated(error)) return

        ! the analyses
        call flexible_decoupled(a, 0.01_dp, 0.0_dp, good, FLEX_SLAMMER, g0, res, stat, msg)
        call expect('ky = ')
        if (allocated(error)) return
        call flexible_decoupled(a, 0.0_dp, 0.1_dp, good, FLEX_SLAMMER, g0, res, stat, msg)
        call expect('dt = ')
        if (allocated(error)) return
        call flexible_coupled(a, 0.01_dp, 0.1_dp, good, 7, g0, res, stat, msg)
        call expect('method: ')
        if (allocated(error)) return
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, good, FLEX_SLAMMER, g0, res, stat, msg, &
                                mode=NEWMARK_BOTH)
        call expect('mode: ')
        if (allocated(error)) return
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, good, FLEX_SLAMMER, g0, res, stat, msg, &
                                mode=9)
        call expect('mode: ')
        if (allocated(error)) return
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, good, FLEX_EXACT, g0, res, stat, msg, &
                                mode=NEWMARK_ASYM)
        call expect('ky_up: ')
        if (allocated(error)) return
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, good, FLEX_EXACT, g0, res, stat, msg, &
                                mode=NEWMARK_BOTH, ky_disp=[0.0_dp], ky_values=[0.1_dp])
        call expect('mode: ')
        if (allocated(error)) return
        call flexible_coupled(a, 0.01_dp, 0.1_dp, good, FLEX_SLAMMER, g0, res, stat, msg, &
                              ky_disp=[0.0_dp])
        call expect('ky_disp, ky_values: ')
        if (allocated(error)) return
        call flexible_coupled(a, 0.01_dp, 0.1_dp, good, FLEX_SLAMMER, g0, res, stat, msg, &
                              ky_disp=[0.0_dp, 0.0_dp], ky_values=[0.1_dp, 0.2_dp])
        call expect('ky_disp(2) = ')
        if (allocated(error)) return
        call flexible_coupled(a, 0.01_dp, 0.1_dp, good, FLEX_SLAMMER, g0, res, stat, msg, &
                              s_hist=short)
        call expect('s_hist: ')
        if (allocated(error)) return
        m = good
        m%vs = 0.0_dp
        call flexible_coupled(a, 0.01_dp, 0.1_dp, m, FLEX_SLAMMER, g0, res, stat, msg)
        call expect('vs = ')
        if (allocated(error)) return
        ! a negative total damping: xi_f(200 on 800) = 0.55016 x 4^-0.9904 = 0.13938
        m = good
        m%vs_base = 800.0_dp
        m%damping = -0.14_dp
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, m, FLEX_EXACT, g0, res, stat, msg)
        call expect('damping = -0.14: with the radiation damping xi_f = 0.13938')
        if (allocated(error)) return
        m%soil = SOIL_EQUIVALENT_LINEAR
        call flexible_coupled(a, 0.01_dp, 0.1_dp, m, FLEX_SLAMMER, g0, res, stat, msg)
        call expect('damping = -0.14: with the radiation damping xi_f = 0.13938')
        if (allocated(error)) return
        m%damping = -0.13_dp   ! total 0.0094: allowed
        call flexible_coupled(a, 0.01_dp, 0.1_dp, m, FLEX_SLAMMER, g0, res, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'total damping 0.0094')
        if (allocated(error)) return
        ! omega = pi vs/(2 H) overflows: height named
        m = good
        m%height = 1.0e-300_dp
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, m, FLEX_EXACT, g0, res, stat, msg)
        call expect('height = 0.1E-299, vs = 200.0: omega = pi vs/(2 height) must be in [')
        if (allocated(error)) return
        ! SLAMMER's coupled arithmetic beyond omega dt = 10: H = 0.1 m, omega dt = 31.4
        m = good
        m%height = 0.1_dp
        call flexible_coupled(a, 0.01_dp, 0.1_dp, m, FLEX_SLAMMER, g0, res, stat, msg)
        call expect('height = 0.1: SLAMMER''s coupled arithmetic is unstable for omega ' &
                    //'dt = 31.4159265358979 > 10.0')
        if (allocated(error)) return
        call check(error, index(msg, 'use method=''exact''') > 0, msg)
        if (allocated(error)) return
        call flexible_coupled(a, 0.01_dp, 0.1_dp, m, FLEX_EXACT, g0, res, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'exact coupled at omega dt = 31')
        if (allocated(error)) return
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, m, FLEX_SLAMMER, g0, res, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'SLAMMER decoupled at omega dt = 31')
        if (allocated(error)) return
        ! SLAMMER's units: 100 g and accel(i) 100 g finite
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, good, FLEX_SLAMMER, 1.0e307_dp, res, &
                                stat, msg)
        call expect('g = 0.1E+308: 100 g')
        if (allocated(error)) return
        call flexible_coupled([a(1:4), 1.0e306_dp], 0.01_dp, 0.1_dp, good, FLEX_SLAMMER, g0, &
                              res, stat, msg)
        call expect('accel(5) = 0.1E+307: accel 100 g')
        if (allocated(error)) return
        ! a reference strain so small that gamma_eff/gamma_r overflows
        m = good
        m%soil = SOIL_EQUIVALENT_LINEAR
        m%ref_strain_pct = 1.0e-300_dp
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, m, FLEX_EXACT, g0, res, stat, msg)
        call expect('ref_strain_pct = 0.1E-299: the strain ratio')
        ! (valid input whose response overflows: test_newmark_flexible_api.py, as this
        ! suite also runs with overflow traps)

    contains

        subroutine expect_mass(mass, start)
            type(flexible_mass_t), intent(in) :: mass
            character(len=*), intent(in) :: start
            call flexible_mass_validate(mass, stat, msg)
            call expect(start)
        end subroutine expect_mass

        subroutine expect(start)
            character(len=*), intent(in) :: start
            call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, start) == 1, &
                       'expected "'//start//'...", got: '//trim(msg))
        end subroutine expect

    end subroutine test_bad_input

    !> Decoupled, SLAMMER rule, on 6 samples worked here: the modal response in Chopra's
    !> average-acceleration form in SI (first step from rest with the load increment of
    !> the first sample, u'' from equilibrium), HEA = a + (2/pi) u'', and the block driven
    !> by HEA (linear over each step) with positive velocity w = -s': a slide starts at the
    !> end of a step with HEA > ky g, w and s are the exact integrals, and the step where w
    !> falls to <= 0 is discarded.
    subroutine test_slammer_decoupled_hand(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 8
        real(dp), parameter :: acc(n) = [0.1_dp, 0.3_dp, 0.34_dp, 0.2_dp, -0.1_dp, -0.3_dp, &
                                         0.05_dp, 0.0_dp]
        real(dp), parameter :: dt = 0.02_dp, ky = 0.15_dp
        type(flexible_mass_t) :: mass
        type(flexible_result_t) :: res
        real(dp) :: hea(n), um(n), s(n), w(n), hea_h(n), u_h(n), s_h(n), w_h(n)
        real(dp) :: omega, xi, c, k, u, v, ud, e, dh, wn
        integer :: j, stat
        logical :: slide
        mass = flexible_mass_t(height=10.0_dp, vs=100.0_dp, vs_base=100.0_dp, damping=0.05_dp)
        call flexible_decoupled(acc, dt, ky, mass, FLEX_SLAMMER, g0, res, stat, hea=hea, &
                                u_modal=um, s_hist=s, sdot_hist=w)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        ! by hand: omega = pi Vs/(2H), xi = 0.05 + 0.2 (capped radiation damping)
        omega = pi * 100.0_dp / 20.0_dp
        xi = 0.25_dp
        c = 2.0_dp * xi * omega
        k = omega**2
        ! step 1 from rest: u = dp/k^ with dp = -(4/pi) a1 g, v = 2u/dt, u'' from equilibrium
        u = -4.0_dp / pi * acc(1) * g0 / (k + 2.0_dp * c / dt + 4.0_dp / dt**2)
        v = 2.0_dp * u / dt
        ud = -4.0_dp / pi * acc(1) * g0 - c * v - k * u
        u_h(1) = u
        hea_h(1) = acc(1) + 2.0_dp / pi * ud / g0
        do j = 2, n
            call avg_accel_step(1.0_dp, c, k, dt, -4.0_dp / pi * (acc(j) - acc(j - 1)) * g0, &
                                u, v, ud)
            u_h(j) = u
            hea_h(j) = acc(j) + 2.0_dp / pi * ud / g0
        end do
        call check(error, um, u_h, rtol=1.0e-12_dp, message='u')
        if (allocated(error)) return
        call check(error, hea, hea_h, rtol=1.0e-12_dp, message='HEA')
        if (allocated(error)) return
        ! the block (SI, HEA in m/s^2)
        slide = .false.
        s_h(1) = 0.0_dp
        w_h(1) = 0.0_dp
        if (hea_h(1) > ky) slide = .true.
        do j = 2, n
            s_h(j) = s_h(j - 1)
            w_h(j) = 0.0_dp
            if (slide) then
                e = (hea_h(j - 1) - ky) * g0
                dh = (hea_h(j) - hea_h(j - 1)) * g0
                wn = w_h(j - 1) + e * dt + 0.5_dp * dh * dt
                if (wn <= 0.0_dp) then
                    slide = .false.        ! the step is discarded
                else
                    s_h(j) = s_h(j - 1) + w_h(j - 1) * dt + 0.5_dp * e * dt**2 + dh * dt**2 / 6.0_dp
                    w_h(j) = wn
                end if
            else if (hea_h(j) > ky) then
                slide = .true.
            end if
        end do
        call check(error, s, s_h, rtol=1.0e-12_dp, message='s')
        if (allocated(error)) return
        call check(error, w, w_h, rtol=1.0e-12_dp, atol=1.0e-15_dp, message='s''')
        if (allocated(error)) return
        call check(error, s_h(n) > 0.0_dp .and. count(w_h > 0.0_dp) >= 2, 'the record slides')
        if (allocated(error)) return
        call check(error, res%final_disp, s_h(n), rtol=1.0e-12_dp)
        if (allocated(error)) return
        call check(error, res%max_disp, maxval(s_h), rtol=1.0e-12_dp)
        if (allocated(error)) return
        call check(error, res%kmax, maxval(hea_h), rtol=1.0e-12_dp, message='kmax')
        if (allocated(error)) return
        call check(error, res%period, 0.4_dp, rtol=1.0e-15_dp)
    end subroutine test_slammer_decoupled_hand

    !> Coupled, SLAMMER rule, worked here in the sign of the record (positive downslope;
    !> SLAMMER runs on the record times -1): the modal load is the record while sticking and
    !> the yield ky while sliding, with the modal mass d1 = 1 - 8/pi^2 while sliding (the
    !> load step at an onset is not applied: the increment is taken between equal loads,
    !> and u'' comes from equilibrium); the base acceleration a + (2/pi) u'' starts a slide
    !> above ky g; s'' = (a - ky) g + (2/pi) u'' by the trapezoidal rule; at a stop the
    !> fraction dd, s re-integrated over dd dt, and the sticking sub-step in SLAMMER's form.
    subroutine test_slammer_coupled_hand(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 12
        real(dp), parameter :: acc(n) = [0.0_dp, 0.2_dp, 0.45_dp, 0.5_dp, 0.3_dp, 0.0_dp, &
                                         -0.3_dp, -0.4_dp, -0.1_dp, 0.1_dp, 0.0_dp, 0.0_dp]
        real(dp), parameter :: dt = 0.02_dp, ky = 0.2_dp
        type(flexible_mass_t) :: mass
        type(flexible_result_t) :: res
        real(dp) :: s(n), sd(n), um(n), s_h(n), sd_h(n), u_h(n)
        real(dp) :: omega, xi, c, k, d1, m, u, v, ud, uo, vo, udo, sdd, sdd_o, sdo, so
        real(dp) :: load, dd, tau, abar, kh, ah, bh, a_prev, s_prev, sd_prev
        integer :: j, stat, nstop, nsub
        logical :: slide
        mass = flexible_mass_t(height=8.0_dp, vs=200.0_dp, vs_base=400.0_dp, damping=0.0_dp)
        call flexible_coupled(acc, dt, ky, mass, FLEX_SLAMMER, g0, res, stat, u_modal=um, &
                              s_hist=s, sdot_hist=sd)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        omega = pi * 200.0_dp / 16.0_dp
        xi = min(0.2_dp, 0.55016_dp * 2.0_dp**(-0.9904_dp))
        c = 2.0_dp * xi * omega
        k = omega**2
        d1 = 1.0_dp - 8.0_dp / pi**2
        slide = .false.
        u = 0.0_dp
        v = 0.0_dp
        ud = 0.0_dp
        s_h = 0.0_dp
        sd_h = 0.0_dp
        sdd = 0.0_dp
        nstop = 0
        nsub = 0
        a_prev = 0.0_dp
        s_prev = 0.0_dp
        sd_prev = 0.0_dp
        do j = 1, n
            uo = u
            vo = v
            udo = ud
            sdo = sd_prev
            so = s_prev
            sdd_o = sdd
            m = 1.0_dp
            if (slide) m = d1
            if (j == 1) then
                u = -4.0_dp / pi * acc(1) * g0 / (k + 2.0_dp * c / dt + 4.0_dp / dt**2)
                v = 2.0_dp * u / dt
            else if (slide) then
                ! the load is ky since the onset: no increment
                call avg_accel_step(m, c, k, dt, 0.0_dp, u, v, ud)
            else
                call avg_accel_step(m, c, k, dt, -4.0_dp / pi * (acc(j) - a_prev) * g0, &
                                    u, v, ud)
            end if
            load = acc(j)
            if (slide) load = ky
            ud = (-4.0_dp / pi * load * g0 - c * v - k * u) / m     ! from equilibrium
            s_h(j) = so
            if (.not. slide) then
                if (acc(j) * g0 + 2.0_dp / pi * ud > ky * g0) slide = .true.
                sdd = 0.0_dp
            else
                sdd = (acc(j) - ky) * g0 + 2.0_dp / pi * ud
                sd_h(j) = sdo + 0.5_dp * dt * (sdd + sdd_o)
                s_h(j) = so + 0.5_dp * dt * (sd_h(j) + sdo)
                if (sd_h(j) <= 0.0_dp) then
                    nstop = nstop + 1
                    slide = .false.
                    if (sdo > 0.0_dp) then
                        nsub = nsub + 1
                        dd = sdo / (sdo - sd_h(j))
                        tau = dd * dt
                        abar = a_prev + dd * (acc(j) - a_prev)
                        sdd = (abar - ky) * g0 + 2.0_dp / pi * ud
                        sd_h(j) = sdo + 0.5_dp * tau * (sdd + sdd_o)
                        s_h(j) = so + 0.5_dp * tau * (sdo + sd_h(j))
                        ! sticking sub-step over (1 - dd) dt from the sliding end state
                        tau = (1.0_dp - dd) * dt
                        kh = 1.0_dp + c * 0.5_dp * tau + k * 0.25_dp * tau**2
                        ah = d1 - c * 0.5_dp * tau - k * 0.25_dp * tau**2
                        bh = k * tau
                        uo = u
                        vo = v
                        udo = ud
                        ud = (-4.0_dp / pi * (acc(j) - ky) * g0 + ah * udo - bh * vo) / kh
                        v = vo + 0.5_dp * tau * (udo + ud)
                        u = uo + vo * tau + 0.25_dp * tau**2 * (udo + ud)
                    end if
                    sd_h(j) = 0.0_dp
                    sdd = 0.0_dp
                end if
            end if
            u_h(j) = u
            a_prev = acc(j)
            s_prev = s_h(j)
            sd_prev = sd_h(j)
        end do
        call check(error, nsub >= 1 .and. s_h(n) > 0.0_dp, 'a slide that stops inside a step')
        if (allocated(error)) return
        call check(error, um, u_h, rtol=1.0e-11_dp, atol=1.0e-16_dp, message='u')
        if (allocated(error)) return
        call check(error, s, s_h, rtol=1.0e-11_dp, atol=1.0e-16_dp, message='s')
        if (allocated(error)) return
        call check(error, sd, sd_h, rtol=1.0e-11_dp, atol=1.0e-16_dp, message='s''')
        if (allocated(error)) return
        call check(error, res%final_disp, s_h(n), rtol=1.0e-11_dp)
    end subroutine test_slammer_coupled_hand

    !> A very stiff mass (Vs = 1e9 m/s): HEA = a, u = 0; the decoupled analysis is then
    !> SLAMMER's block on the record itself.
    subroutine test_stiff_limit(error)
        type(test_error), allocatable, intent(out) :: error
        type(flexible_mass_t) :: mass
        type(flexible_result_t) :: res, res_stiff
        real(dp) :: a(1500), hea(1500), um(1500)
        integer :: stat
        a = synthetic()
        mass = flexible_mass_t(height=10.0_dp, vs=1.0e9_dp, vs_base=1.0e9_dp, damping=0.05_dp)
        call flexible_decoupled(a, 0.01_dp, 0.2_dp, mass, FLEX_SLAMMER, g0, res_stiff, stat, &
                                hea=hea, u_modal=um)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, hea, a, rtol=1.0e-9_dp, atol=1.0e-12_dp, message='HEA = a')
        if (allocated(error)) return
        call check(error, maxval(abs(um)) < 1.0e-15_dp, 'u = 0')
        if (allocated(error)) return
        call check(error, res_stiff%kmax, a(maxloc(abs(a), 1)), rtol=1.0e-9_dp, &
                   message='kmax = PGA')
        if (allocated(error)) return
        call check(error, res_stiff%period, 4.0e-8_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        ! a softer mass slides differently, a stiffer one (1e12) the same to 1e-9
        mass%vs = 1.0e12_dp
        mass%vs_base = 1.0e12_dp
        call flexible_decoupled(a, 0.01_dp, 0.2_dp, mass, FLEX_SLAMMER, g0, res, stat)
        call check(error, res%max_disp, res_stiff%max_disp, rtol=1.0e-9_dp, message='Vs 1e12')
        if (allocated(error)) return
        call check(error, res_stiff%max_disp > 0.01_dp, 'it slides')
    end subroutine test_stiff_limit

    !> SLAMMER's residual_mu: with [(0, ky1), (d, ky2)] the second row applies from the first
    !> step at rest, so the result is exactly that of the constant ky2 (any d, both
    !> analyses); a third row takes over only after the displacement reaches the second
    !> row's d, between slides.
    subroutine test_ky_table(error)
        type(test_error), allocatable, intent(out) :: error
        type(flexible_mass_t) :: mass
        type(flexible_result_t) :: r_tab, r_const, r3
        real(dp) :: a(1500), s(1500), sd(1500)
        integer :: stat, i
        a = synthetic()
        mass = flexible_mass_t(height=30.0_dp, vs=250.0_dp, vs_base=600.0_dp, damping=0.05_dp)
        call flexible_decoupled(a, 0.01_dp, 0.3_dp, mass, FLEX_SLAMMER, g0, r_tab, stat, &
                                ky_disp=[0.0_dp, 5.0_dp], ky_values=[0.3_dp, 0.1_dp])
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, mass, FLEX_SLAMMER, g0, r_const, stat)
        call check(error, r_tab%max_disp, r_const%max_disp, rtol=0.0_dp, message='decoupled')
        if (allocated(error)) return
        call check(error, r_const%max_disp > 0.1_dp, 'slides')
        if (allocated(error)) return
        call flexible_coupled(a, 0.01_dp, 0.3_dp, mass, FLEX_SLAMMER, g0, r_tab, stat, &
                              ky_disp=[0.0_dp, 5.0_dp], ky_values=[0.3_dp, 0.1_dp])
        call flexible_coupled(a, 0.01_dp, 0.1_dp, mass, FLEX_SLAMMER, g0, r3, stat)
        call check(error, r_tab%max_disp, r3%max_disp, rtol=0.0_dp, message='coupled')
        if (allocated(error)) return
        ! three rows: 0.1 g from the start, 0.9 g (above kmax = 0.67 g: no more sliding) once
        ! s >= 0.02 m at rest
        call flexible_decoupled(a, 0.01_dp, 0.3_dp, mass, FLEX_SLAMMER, g0, r3, stat, &
                                ky_disp=[0.0_dp, 0.02_dp, 0.03_dp], &
                                ky_values=[0.3_dp, 0.1_dp, 0.9_dp], s_hist=s, sdot_hist=sd)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, r3%max_disp < r_const%max_disp .and. r3%max_disp >= 0.02_dp, &
                   'stops sliding after the first slide past 0.02 m')
        if (allocated(error)) return
        ! from the first sample at rest with s >= 0.02 m on, s never changes
        i = findloc(s >= 0.02_dp .and. .not. sd > 0.0_dp, .true., 1)
        call check(error, i > 0, 'at rest past 0.02 m')
        if (allocated(error)) return
        call check(error, s(1500), s(i), rtol=0.0_dp)
    end subroutine test_ky_table

    subroutine test_polarity_histories(error)
        type(test_error), allocatable, intent(out) :: error
        type(flexible_mass_t) :: mass
        type(flexible_result_t) :: r, ri
        real(dp) :: a(1500), hea(1500), um(1500), s(1500), sd(1500), heai(1500), umi(1500)
        integer :: stat, i
        a = synthetic()
        mass = flexible_mass_t(height=30.0_dp, vs=250.0_dp, vs_base=600.0_dp, damping=0.05_dp, &
                               soil=SOIL_EQUIVALENT_LINEAR)
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, mass, FLEX_SLAMMER, g0, r, stat, hea=hea, &
                                u_modal=um, s_hist=s, sdot_hist=sd)
        call flexible_decoupled(-a, 0.01_dp, 0.1_dp, mass, FLEX_SLAMMER, g0, ri, stat, &
                                hea=heai, u_modal=umi)
        ! the response is odd in the record; the sliding is not
        call check(error, heai, -hea, rtol=0.0_dp, message='HEA odd')
        if (allocated(error)) return
        call check(error, umi, -um, rtol=0.0_dp, message='u odd')
        if (allocated(error)) return
        call check(error, ri%kmax, -r%kmax, rtol=0.0_dp, message='kmax odd')
        if (allocated(error)) return
        call check(error, r%kmax, hea(maxloc(abs(hea), 1)), rtol=0.0_dp, message='kmax')
        if (allocated(error)) return
        call check(error, ri%vs_final, r%vs_final, rtol=0.0_dp, message='EQL unchanged')
        if (allocated(error)) return
        call check(error, abs(ri%max_disp - r%max_disp) > 1.0e-3_dp * r%max_disp, &
                   'the two polarities slide differently')
        if (allocated(error)) return
        ! histories against the scalars; downslope: s >= 0 never decreasing, s' >= 0
        call check(error, r%max_disp, maxval(s), rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, r%final_disp, s(1500), rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, all(sd >= 0.0_dp) .and. all(s(2:) >= s(:1499)), 'monotone')
        if (allocated(error)) return
        ! s grows only while s' > 0 (or on the step a slide ends)
        do i = 2, 1500
            if (s(i) > s(i - 1) .and. .not. (sd(i) > 0.0_dp .or. sd(i - 1) > 0.0_dp)) then
                call check(error, .false., 's moves at rest')
                return
            end if
        end do
        ! a positive pulse slides downslope in both analyses, a negative one not at all
        call pulse_check(1.0_dp, .true.)
        if (allocated(error)) return
        call pulse_check(-1.0_dp, .false.)
    contains
        subroutine pulse_check(sgn, slides)
            real(dp), intent(in) :: sgn
            logical, intent(in) :: slides
            real(dp) :: p(400)
            type(flexible_result_t) :: rd, rc
            integer :: k
            do k = 1, 400
                p(k) = 0.0_dp
                if (k > 10 .and. k <= 60) p(k) = sgn * 0.5_dp * sin(pi * real(k - 10, dp) / 50.0_dp)
            end do
            mass%soil = SOIL_LINEAR
            call flexible_decoupled(p, 0.01_dp, 0.1_dp, mass, FLEX_SLAMMER, g0, rd, stat)
            call flexible_coupled(p, 0.01_dp, 0.1_dp, mass, FLEX_SLAMMER, g0, rc, stat)
            if (slides) then
                call check(error, rd%final_disp > 0.5_dp .and. rc%final_disp > 0.5_dp &
                           .and. rd%kmax > 0.0_dp .and. rc%kmax > 0.0_dp, 'positive pulse')
            else
                ! only the rebound after the pulse slides (0.9 m for the positive pulse)
                call check(error, rd%final_disp < 0.02_dp .and. rc%final_disp < 0.02_dp &
                           .and. rd%kmax < 0.0_dp .and. rc%kmax < 0.0_dp, 'negative pulse')
            end if
        end subroutine pulse_check
    end subroutine test_polarity_histories

    !> SLAMMER 1.1's Decoupled and Coupled (its Java code, through the harness that calls
    !> them as its GUI does, normal polarity, no scaling) on the synthetic record: disp
    !> (cm; SLAMMER returns |s| at the end of the record, so |final_disp|), |kmax| (g),
    !> final Vs (m/s) and total damping. Agreement to 1e-10 relative (measured 3.4e-12).
    subroutine test_slammer_java(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(1500)
        type(flexible_mass_t) :: m1, m2
        a = synthetic()
        m1 = flexible_mass_t(height=30.0_dp, vs=250.0_dp, vs_base=600.0_dp, damping=0.05_dp, &
                             ref_strain_pct=0.05_dp)
        m2 = flexible_mass_t(height=60.0_dp, vs=300.0_dp, vs_base=300.0_dp, damping=-0.1_dp, &
                             ref_strain_pct=0.03_dp, soil=SOIL_EQUIVALENT_LINEAR)
        call one(.false., a, 0.1_dp, m1, 151.10350093650558_dp, 0.6731824095380728_dp, &
                 250.0_dp, 0.25_dp)
        if (allocated(error)) return
        call one(.true., a, 0.1_dp, m1, 135.2945999965525_dp, 0.6731824095380728_dp, &
                 250.0_dp, 0.25_dp)
        if (allocated(error)) return
        m1%soil = SOIL_EQUIVALENT_LINEAR
        call one(.false., a, 0.1_dp, m1, 13.813890470239748_dp, 0.2438057480095921_dp, &
                 78.89116877491246_dp, 0.28888464563895105_dp)
        if (allocated(error)) return
        call one(.true., a, 0.1_dp, m1, 23.8476102433952_dp, 0.2438057480095921_dp, &
                 78.89116877491246_dp, 0.28888464563895105_dp)
        if (allocated(error)) return
        ! inverse polarity (the record times -1), negative user damping
        call one(.false., -a, 0.1_dp, m2, 2.94479072572147_dp, 0.19522435688035636_dp, &
                 111.27519455587604_dp, 0.39943356885831166_dp)
        if (allocated(error)) return
        call one(.true., -a, 0.1_dp, m2, 7.609852835423173_dp, 0.19522435688035636_dp, &
                 111.27519455587604_dp, 0.39943356885831166_dp)
        if (allocated(error)) return
        ! SLAMMER's table [(0, 0.15 g), (2 cm, 0.06 g)]
        call one(.false., a, 0.15_dp, m1, 38.3118771893579_dp, 0.2438057480095921_dp, &
                 78.89116877491246_dp, 0.28888464563895105_dp, [0.0_dp, 0.02_dp], &
                 [0.15_dp, 0.06_dp])
        if (allocated(error)) return
        call one(.true., a, 0.15_dp, m1, 58.9436826000949_dp, 0.2438057480095921_dp, &
                 78.89116877491246_dp, 0.28888464563895105_dp, [0.0_dp, 0.02_dp], &
                 [0.15_dp, 0.06_dp])
        if (allocated(error)) return
        ! (decoupled, coupled) pairs: the same kmax, Vs and damping
        ! three rows [(0, 0.15 g), (2 cm, 0.08 g), (10 cm, 0.04 g)]: the row after row 2
        call pair(a, 0.15_dp, m1, [53.133062784929194_dp, 83.24605469350666_dp], &
                  [0.2438057480095921_dp, 78.89116877491246_dp, 0.28888464563895105_dp], &
                  [0.0_dp, 0.02_dp, 0.1_dp], [0.15_dp, 0.08_dp, 0.04_dp])
        if (allocated(error)) return
        ! a reference strain of 0.001 %: Vs 250 -> 12.2 m/s
        m1%ref_strain_pct = 0.001_dp
        call pair(a, 0.1_dp, m1, [0.05122061132280804_dp, 0.24898093033406518_dp], &
                  [0.12193044308666648_dp, 12.213196669466289_dp, 0.23220781055611783_dp])
        if (allocated(error)) return
        ! user damping 0.9 (total 1.1), linear, inverse polarity
        m1 = flexible_mass_t(height=30.0_dp, vs=250.0_dp, vs_base=600.0_dp, damping=0.9_dp)
        call pair(-a, 0.1_dp, m1, [114.80295143020008_dp, 108.33866461790474_dp], &
                  [0.6576724151652487_dp, 250.0_dp, 1.1_dp])
    contains
        !> decoupled then coupled: disp_cm(2), props = (|kmax| g, Vs m/s, damping)
        subroutine pair(rec, ky, mass, disp_cm, props, tdisp, tky)
            real(dp), intent(in) :: rec(:), ky, disp_cm(2), props(3)
            type(flexible_mass_t), intent(in) :: mass
            real(dp), intent(in), optional :: tdisp(:), tky(:)
            call one(.false., rec, ky, mass, disp_cm(1), props(1), props(2), props(3), tdisp, &
                     tky)
            if (allocated(error)) return
            call one(.true., rec, ky, mass, disp_cm(2), props(1), props(2), props(3), tdisp, tky)
        end subroutine pair
        subroutine one(coupled, rec, ky, mass, disp_cm, kmax, vs, damp, tdisp, tky)
            logical, intent(in) :: coupled
            real(dp), intent(in) :: rec(:), ky
            type(flexible_mass_t), intent(in) :: mass
            real(dp), intent(in) :: disp_cm, kmax, vs, damp
            real(dp), intent(in), optional :: tdisp(:), tky(:)
            type(flexible_result_t) :: res
            integer :: stat
            if (coupled) then
                call flexible_coupled(rec, 0.01_dp, ky, mass, FLEX_SLAMMER, g0, res, stat, &
                                      ky_disp=tdisp, ky_values=tky)
            else
                call flexible_decoupled(rec, 0.01_dp, ky, mass, FLEX_SLAMMER, g0, res, stat, &
                                        ky_disp=tdisp, ky_values=tky)
            end if
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            call check(error, 100.0_dp * abs(res%final_disp), disp_cm, rtol=1.0e-10_dp, &
                       message='disp')
            if (allocated(error)) return
            call check(error, abs(res%kmax), kmax, rtol=1.0e-10_dp, message='kmax')
            if (allocated(error)) return
            call check(error, res%vs_final, vs, rtol=1.0e-10_dp, message='vs')
            if (allocated(error)) return
            call check(error, res%damping_final, damp, rtol=1.0e-10_dp, message='damping')
        end subroutine one
    end subroutine test_slammer_java

    !> The exact rule through flexible_decoupled / flexible_coupled: a very stiff mass is the
    !> rigid block (newmark_rigid, exact) on the record; two-way sliding is odd in the
    !> record; the histories match the scalars; and both analyses (linear and
    !> equivalent-linear) stay within 1 % of SLAMMER's arithmetic on a smooth record.
    subroutine test_exact_dispatch(error)
        type(test_error), allocatable, intent(out) :: error
        type(flexible_mass_t) :: mass
        type(flexible_result_t) :: r, ri, rs
        type(newmark_result_t) :: rr
        real(dp) :: a(1500), hea(1500), s(1500)
        integer :: stat, soil, k_coupled
        logical :: coupled
        a = synthetic()
        mass = flexible_mass_t(height=10.0_dp, vs=1.0e9_dp, vs_base=1.0e9_dp, damping=0.05_dp)
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, mass, FLEX_EXACT, g0, r, stat, hea=hea)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, hea, a, rtol=1.0e-9_dp, atol=1.0e-12_dp, message='HEA = a')
        if (allocated(error)) return
        call newmark_rigid(a, 0.01_dp, newmark_block_t(ky=0.1_dp), NEWMARK_EXACT, g0, rr, stat)
        call check(error, r%max_disp, rr%max_disp, rtol=1.0e-9_dp, message='stiff = rigid')
        if (allocated(error)) return
        call check(error, rr%max_disp > 0.5_dp, 'slides')
        if (allocated(error)) return
        ! two ways: the record times -1 gives the displacement times -1
        mass = flexible_mass_t(height=30.0_dp, vs=250.0_dp, vs_base=600.0_dp, damping=0.05_dp)
        call flexible_decoupled(a, 0.01_dp, 0.1_dp, mass, FLEX_EXACT, g0, r, stat, &
                                mode=NEWMARK_BOTH, s_hist=s)
        call flexible_decoupled(-a, 0.01_dp, 0.1_dp, mass, FLEX_EXACT, g0, ri, stat, &
                                mode=NEWMARK_BOTH)
        call check(error, ri%final_disp, -r%final_disp, rtol=1.0e-13_dp, message='two-way odd')
        if (allocated(error)) return
        ! the true extreme lies between samples: at least the largest sample, and close
        call check(error, r%max_disp >= maxval(abs(s)), 'max |s| >= the samples')
        if (allocated(error)) return
        call check(error, r%max_disp, maxval(abs(s)), rtol=1.0e-5_dp, message='max |s|')
        if (allocated(error)) return
        ! near SLAMMER's arithmetic
        do soil = SOIL_LINEAR, SOIL_EQUIVALENT_LINEAR
            mass%soil = soil
            do k_coupled = 0, 1
                coupled = k_coupled == 1
                if (coupled) then
                    call flexible_coupled(a, 0.01_dp, 0.1_dp, mass, FLEX_EXACT, g0, r, stat)
                    call flexible_coupled(a, 0.01_dp, 0.1_dp, mass, FLEX_SLAMMER, g0, rs, stat)
                else
                    call flexible_decoupled(a, 0.01_dp, 0.1_dp, mass, FLEX_EXACT, g0, r, stat)
                    call flexible_decoupled(a, 0.01_dp, 0.1_dp, mass, FLEX_SLAMMER, g0, rs, stat)
                end if
                call check(error, stat, SEISPULSE_SUCCESS)
                if (allocated(error)) return
                call check(error, r%max_disp, rs%max_disp, rtol=1.0e-2_dp, message='disp')
                if (allocated(error)) return
                call check(error, r%kmax, rs%kmax, rtol=1.0e-2_dp, message='kmax')
                if (allocated(error)) return
                call check(error, r%vs_final, rs%vs_final, rtol=1.0e-2_dp, message='vs')
                if (allocated(error)) return
                call check(error, r%iterations == rs%iterations .and. r%converged, 'passes')
                if (allocated(error)) return
            end do
        end do
        ! the total damping must stay in (-1, 1) for the exact recurrence
        mass%damping = 0.85_dp
        call flexible_coupled(a, 0.01_dp, 0.1_dp, mass, FLEX_EXACT, g0, r, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'total damping >= 1')
    end subroutine test_exact_dispatch

end module test_flexible
