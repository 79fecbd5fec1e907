!> Empirical displacement models (seispulse_empirical): each regression against its
!> source equation written out here term by term (doc/empirical.md), the published
!> examples of [BT07], the exact P(D = 0) against SLAMMER's polynomial, the unified
!> model's limits, and the checks naming the parameter.
module test_empirical
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_empirical
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_empirical

contains

    subroutine collect_empirical(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('Jibson 1993, 1998, 2007 (four forms) by hand', test_jibson), &
                 new_unittest('Ambraseys & Menu 1988 by hand', test_am88), &
                 new_unittest('Saygili & Rathje 2008, Rathje & Saygili 2009 by hand', test_sr), &
                 new_unittest('empirical_rigid: every model, sigma and base', test_rigid), &
                 new_unittest('Bray & Travasarou 2007: published examples', test_bt07_examples), &
                 new_unittest('Bray & Travasarou 2007: nearly rigid form', test_bt07_rigid), &
                 new_unittest('P(D = 0): erfc vs SLAMMER polynomial', test_p_zero), &
                 new_unittest('Rathje & Antonakos 2011 by hand and limits', test_ra11), &
                 new_unittest('probability of failure', test_failure), &
                 new_unittest('bad input names the parameter', test_bad_input)]
    end subroutine collect_empirical

    subroutine test_jibson(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: ia, ky, pga, r, m
        ia = 1.7_dp
        ky = 0.12_dp
        pga = 0.35_dp
        m = 6.8_dp
        r = ky / pga
        call check(error, jibson_1993(ia, ky), &
                   10.0_dp**(1.460_dp * log10(ia) - 6.642_dp * ky + 1.546_dp), message='J93')
        if (allocated(error)) return
        call check(error, jibson_1998(ia, ky), &
                   10.0_dp**(1.521_dp * log10(ia) - 1.993_dp * log10(ky) - 1.546_dp), &
                   message='J98')
        if (allocated(error)) return
        call check(error, jibson_2007_ratio(ky, pga), &
                   10.0_dp**0.215_dp * (1.0_dp - r)**2.341_dp * r**(-1.438_dp), &
                   rtol=1.0e-13_dp, message='J07 Eq. 6')
        if (allocated(error)) return
        call check(error, jibson_2007_ratio_m(ky, pga, m), &
                   10.0_dp**(-2.710_dp + 0.424_dp * m) * (1.0_dp - r)**2.335_dp &
                   * r**(-1.478_dp), rtol=1.0e-13_dp, message='J07 Eq. 7')
        if (allocated(error)) return
        call check(error, jibson_2007_arias(ia, ky), &
                   ia**2.401_dp * ky**(-3.481_dp) * 10.0_dp**(-3.230_dp), rtol=1.0e-13_dp, &
                   message='J07 Eq. 9')
        if (allocated(error)) return
        call check(error, jibson_2007_arias_ratio(ia, ky, pga), &
                   ia**0.561_dp * r**(-3.833_dp) * 10.0_dp**(-1.474_dp), rtol=1.0e-13_dp, &
                   message='J07 Eq. 10')
        if (allocated(error)) return
        ! a value worked by hand: Ia = 1 m/s, ky = 0.1 g in J98: 10^(1.993 - 1.546)
        call check(error, jibson_1998(1.0_dp, 0.1_dp), 2.7989813_dp, rtol=1.0e-7_dp, &
                   message='J98 at Ia = 1, ky = 0.1')
    end subroutine test_jibson

    subroutine test_am88(error)
        type(test_error), allocatable, intent(out) :: error
        ! ky/PGA = 0.5: 10^0.9 0.5^2.53 0.5^-1.09 = 10^0.9 0.5^1.44 = 2.92763...
        call check(error, ambraseys_menu_1988(0.1_dp, 0.2_dp), &
                   10.0_dp**0.9_dp * 0.5_dp**1.44_dp, rtol=1.0e-13_dp, message='r = 0.5')
        if (allocated(error)) return
        call check(error, ambraseys_menu_1988(0.1_dp, 0.2_dp), 2.927634_dp, rtol=1.0e-6_dp, &
                   message='r = 0.5, digits')
        if (allocated(error)) return
        ! r -> 1: no displacement
        call check(error, ambraseys_menu_1988(0.2_dp * (1.0_dp - 1.0e-12_dp), 0.2_dp) < 1.0e-25_dp, &
                   message='r -> 1 gives 0')
    end subroutine test_am88

    subroutine test_sr(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: ky, pga, pgv, ia, m, r
        ky = 0.1_dp
        pga = 0.4_dp
        pgv = 40.0_dp
        ia = 2.0_dp
        m = 7.0_dp
        r = ky / pga
        call check(error, log(saygili_rathje_2008_pga(ky, pga)), &
                   5.52_dp - 4.43_dp * r - 20.39_dp * r**2 + 42.61_dp * r**3 &
                   - 28.74_dp * r**4 + 0.72_dp * log(pga), rtol=1.0e-14_dp, message='SR08 PGA')
        if (allocated(error)) return
        call check(error, log(saygili_rathje_2008_pgv(ky, pga, pgv)), &
                   -1.56_dp - 4.58_dp * r - 20.84_dp * r**2 + 44.75_dp * r**3 &
                   - 30.50_dp * r**4 - 0.64_dp * log(pga) + 1.55_dp * log(pgv), &
                   rtol=1.0e-14_dp, message='SR08 PGA-PGV')
        if (allocated(error)) return
        call check(error, log(saygili_rathje_2008_pgv_arias(ky, pga, pgv, ia)), &
                   -0.74_dp - 4.93_dp * r - 19.91_dp * r**2 + 43.75_dp * r**3 &
                   - 30.12_dp * r**4 - 1.30_dp * log(pga) + 1.04_dp * log(pgv) &
                   + 0.67_dp * log(ia), rtol=1.0e-14_dp, message='SR08 PGA-PGV-Ia')
        if (allocated(error)) return
        call check(error, log(rathje_saygili_2009(ky, pga, m)), &
                   4.89_dp - 4.85_dp * r - 19.64_dp * r**2 + 42.49_dp * r**3 &
                   - 29.06_dp * r**4 + 0.72_dp * log(pga) + 0.89_dp * (m - 6.0_dp), &
                   rtol=1.0e-14_dp, message='RS09 PGA-M')
        if (allocated(error)) return
        ! r = 0.25 worked by hand: 4.89 - 1.2125 - 1.2275 + 0.66390625 - 0.113515625
        ! + 0.72 ln 0.4 + 0.89 = 3.89 + ... -> ln D = 3.230...
        call check(error, log(rathje_saygili_2009(ky, pga, m)), &
                   4.89_dp - 1.2125_dp - 1.2275_dp + 0.66390625_dp - 0.113515625_dp &
                   + 0.72_dp * (-0.916290731874155_dp) + 0.89_dp, rtol=1.0e-14_dp, &
                   message='RS09 by hand')
        if (allocated(error)) return
        call check(error, sr08_pgv_sigma(0.25_dp), 0.54_dp, rtol=1.0e-15_dp, message='sigma')
        if (allocated(error)) return
        call check(error, sr08_pgv_arias_sigma(0.25_dp), 0.3975_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, rs09_sigma(0.25_dp), 0.732_dp + 0.19725_dp - 0.0336875_dp, &
                   rtol=1.0e-15_dp)
    end subroutine test_sr

    subroutine test_rigid(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: d, s, expected(EMP_RIGID_MODELS), sig(EMP_RIGID_MODELS)
        integer :: k, base, stat, bases(EMP_RIGID_MODELS)
        real(dp), parameter :: ky = 0.08_dp, pga = 0.3_dp, pgv = 25.0_dp, ia = 0.9_dp, &
                               m = 6.5_dp
        expected = [jibson_1993(ia, ky), jibson_1998(ia, ky), jibson_2007_ratio(ky, pga), &
                    jibson_2007_ratio_m(ky, pga, m), jibson_2007_arias(ia, ky), &
                    jibson_2007_arias_ratio(ia, ky, pga), ambraseys_menu_1988(ky, pga), &
                    saygili_rathje_2008_pga(ky, pga), saygili_rathje_2008_pgv(ky, pga, pgv), &
                    saygili_rathje_2008_pgv_arias(ky, pga, pgv, ia), &
                    rathje_saygili_2009(ky, pga, m)]
        sig = [0.409_dp, 0.375_dp, 0.510_dp, 0.454_dp, 0.656_dp, 0.616_dp, 0.30_dp, 1.13_dp, &
               0.41_dp + 0.52_dp * ky / pga, 0.20_dp + 0.79_dp * ky / pga, &
               0.732_dp + 0.789_dp * ky / pga - 0.539_dp * (ky / pga)**2]
        bases = [10, 10, 10, 10, 10, 10, 10, 1, 1, 1, 1]
        do k = 1, EMP_RIGID_MODELS
            call empirical_rigid(k, ky, pga, pgv, ia, m, d, s, base, stat)
            call check(error, stat, SEISPULSE_SUCCESS, message=empirical_model_name(k))
            if (allocated(error)) return
            call check(error, d, expected(k), message=empirical_model_name(k))
            if (allocated(error)) return
            call check(error, s, sig(k), rtol=1.0e-15_dp, message=empirical_model_name(k))
            if (allocated(error)) return
            call check(error, base, bases(k), message=empirical_model_name(k))
            if (allocated(error)) return
            call check(error, empirical_model_code(empirical_model_name(k)), k)
            if (allocated(error)) return
        end do
        call check(error, EMP_LOG10 == 10 .and. EMP_LN == 1, message='base codes')
    end subroutine test_rigid

    subroutine test_bt07_examples(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: d, s, p
        integer :: stat
        ! [BT07] earth dam example: ky = 0.14, Ts = 0.33 s, Sa(0.5 s) = 1.07 g, M 6.9:
        ! ln D = 3.77 (printed), P(D = 0) = 0 (printed)
        call bray_travasarou_2007(0.14_dp, 0.33_dp, 1.07_dp, 6.9_dp, d, s, p, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, log(d), 3.77_dp, atol=0.005_dp, message='dam example ln D')
        if (allocated(error)) return
        call check(error, p < 0.005_dp, message='dam example P(D = 0) = 0 to 2 digits')
        if (allocated(error)) return
        call check(error, s, 0.66_dp, message='sigma')
        if (allocated(error)) return
        ! Bray's 30 m fill example: ky = 0.14, Ts = 0.4 s, Sa(0.6 s) = 0.48 g, M 7.2:
        ! P(D = 0) = 0.01, ln D = 2.29, D ~ 10 cm (printed)
        call bray_travasarou_2007(0.14_dp, 0.4_dp, 0.48_dp, 7.2_dp, d, s, p, stat)
        call check(error, log(d), 2.29_dp, atol=0.005_dp, message='fill example ln D')
        if (allocated(error)) return
        call check(error, p, 0.01_dp, atol=0.005_dp, message='fill example P(D = 0)')
        if (allocated(error)) return
        call check(error, d, 10.0_dp, atol=0.5_dp, message='fill example D')
    end subroutine test_bt07_examples

    subroutine test_bt07_rigid(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: d, s, p, lk, ls
        integer :: stat
        lk = log(0.1_dp)
        ls = log(0.4_dp)
        ! Eq. 6 of [BT07]: -0.22, no Ts term, Sa = PGA
        call bray_travasarou_2007(0.1_dp, 0.03_dp, 0.4_dp, 7.0_dp, d, s, p, stat)
        call check(error, log(d), -0.22_dp - 2.83_dp * lk - 0.333_dp * lk**2 &
                   + 0.566_dp * lk * ls + 3.04_dp * ls - 0.244_dp * ls**2, rtol=1.0e-14_dp, &
                   message='Ts = 0.03 s')
        if (allocated(error)) return
        ! SLAMMER: Eq. 5 at every Ts
        call bray_travasarou_2007(0.1_dp, 0.03_dp, 0.4_dp, 7.0_dp, d, s, p, stat, slammer=.true.)
        call check(error, log(d), -1.10_dp - 2.83_dp * lk - 0.333_dp * lk**2 &
                   + 0.566_dp * lk * ls + 3.04_dp * ls - 0.244_dp * ls**2 + 1.5_dp * 0.03_dp, &
                   rtol=1.0e-14_dp, message='SLAMMER at Ts = 0.03 s')
        if (allocated(error)) return
        ! Ts = 0.05 s exactly: Eq. 5
        call check(error, bt07_ln_disp(0.1_dp, 0.05_dp, 0.4_dp, 6.0_dp, .false.), &
                   bt07_ln_disp(0.1_dp, 0.05_dp, 0.4_dp, 6.0_dp, .true.), message='Ts = 0.05 s')
    end subroutine test_bt07_rigid

    subroutine test_p_zero(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: sa, x, worst, pe
        integer :: i
        ! along ky = 1 (ln ky = 0) x = -1.76 + 3.52 ln Sa: x from 0 to 8
        worst = 0.0_dp
        do i = 0, 400
            x = 0.02_dp * i
            sa = exp((x + 1.76_dp) / 3.52_dp)
            pe = bt07_p_zero(1.0_dp, 0.7_dp, sa)
            worst = max(worst, abs(pe - bt07_p_zero_slammer(1.0_dp, 0.7_dp, sa)))
            ! the exact value: erfc written out at x = 0, 1 below
        end do
        call check(error, worst < 7.5e-8_dp, message='A&S 26.2.17 bound for x >= 0')
        if (allocated(error)) return
        call check(error, worst > 1.0e-9_dp, message='the polynomial is not exact')
        if (allocated(error)) return
        ! x = 0: 1/2; x = 1: 0.15865525393145707 (1 - Phi(1))
        call check(error, bt07_p_zero(1.0_dp, 0.0_dp, exp(1.76_dp / 3.52_dp)), 0.5_dp, &
                   rtol=1.0e-15_dp, message='x = 0')
        if (allocated(error)) return
        call check(error, bt07_p_zero(1.0_dp, 0.0_dp, exp(2.76_dp / 3.52_dp)), &
                   0.15865525393145707_dp, rtol=1.0e-13_dp, message='x = 1')
        if (allocated(error)) return
        ! x = -3: P(D = 0) = Phi(3) = 0.99865..., SLAMMER's polynomial gives 1.56
        sa = exp((-3.0_dp + 1.76_dp) / 3.52_dp)
        call check(error, bt07_p_zero(1.0_dp, 0.0_dp, sa), 0.9986501019683699_dp, &
                   rtol=1.0e-14_dp, message='x = -3')
        if (allocated(error)) return
        call check(error, bt07_p_zero_slammer(1.0_dp, 0.0_dp, sa) > 1.5_dp, &
                   message='SLAMMER outside its domain at x = -3')
        if (allocated(error)) return
        ! far tail: no cancellation (x = 12: 1.7764821120776e-33)
        sa = exp((12.0_dp + 1.76_dp) / 3.52_dp)
        call check(error, bt07_p_zero(1.0_dp, 0.0_dp, sa), 1.7764821120776e-33_dp, &
                   rtol=1.0e-10_dp, message='x = 12')
    end subroutine test_p_zero

    subroutine test_ra11(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: d, s, kmax, kvel, drig, l, q, r, expected
        integer :: stat
        real(dp), parameter :: ky = 0.1_dp, pga = 0.4_dp, pgv = 40.0_dp, m = 7.0_dp, &
                               tm = 0.5_dp
        ! Ts = 0: rigid, kmax = PGA, no period term
        call rathje_antonakos_2011(EMP_RA11_PGA_M, ky, 0.0_dp, tm, pga, pgv, m, d, s, kmax, &
                                   kvel, drig, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, d, rathje_saygili_2009(ky, pga, m), rtol=1.0e-15_dp, message='Ts = 0')
        if (allocated(error)) return
        call check(error, kmax, pga, message='Ts = 0 kmax')
        if (allocated(error)) return
        ! Ts = 0.3 s, Ts/Tm = 0.6: L = ln 6
        call rathje_antonakos_2011(EMP_RA11_PGA_M, ky, 0.3_dp, tm, pga, pgv, m, d, s, kmax, &
                                   kvel, drig, stat)
        l = log(6.0_dp)
        q = exp((0.459_dp - 0.702_dp * pga) * l + (-0.228_dp + 0.076_dp * pga) * l**2)
        call check(error, kmax, q * pga, rtol=1.0e-14_dp, message='kmax')
        if (allocated(error)) return
        r = ky / kmax
        expected = exp(4.89_dp - 4.85_dp * r - 19.64_dp * r**2 + 42.49_dp * r**3 &
                       - 29.06_dp * r**4 + 0.72_dp * log(kmax) + 0.89_dp * (m - 6.0_dp) &
                       + 3.69_dp * 0.3_dp - 1.22_dp * 0.09_dp)
        call check(error, d, expected, rtol=1.0e-13_dp, message='PGA-M form')
        if (allocated(error)) return
        call check(error, s, 0.694_dp + 0.322_dp * r, rtol=1.0e-15_dp, message='sigma M')
        if (allocated(error)) return
        ! PGA-PGV form at Ts = 0.8 s (Ts/Tm = 1.6, f = 0.71)
        call rathje_antonakos_2011(EMP_RA11_PGA_PGV, ky, 0.8_dp, tm, pga, pgv, m, d, s, kmax, &
                                   kvel, drig, stat)
        l = log(16.0_dp)
        q = exp((0.459_dp - 0.702_dp * pga) * l + (-0.228_dp + 0.076_dp * pga) * l**2)
        call check(error, kmax, q * pga, rtol=1.0e-14_dp, message='kmax 2')
        if (allocated(error)) return
        l = log(8.0_dp)
        call check(error, kvel, pgv * exp(0.240_dp * l + (-0.091_dp - 0.171_dp * pga) * l**2), &
                   rtol=1.0e-14_dp, message='kvelmax')
        if (allocated(error)) return
        r = ky / kmax
        expected = exp(-1.56_dp - 4.58_dp * r - 20.84_dp * r**2 + 44.75_dp * r**3 &
                       - 30.50_dp * r**4 - 0.64_dp * log(kmax) + 1.55_dp * log(kvel) + 0.71_dp)
        call check(error, d, expected, rtol=1.0e-13_dp, message='PGA-PGV form')
        if (allocated(error)) return
        call check(error, s, 0.400_dp + 0.284_dp * r, rtol=1.0e-15_dp, message='sigma PGV')
        if (allocated(error)) return
        ! ky >= kmax: no sliding
        call rathje_antonakos_2011(EMP_RA11_PGA_M, 0.39_dp, 3.0_dp, tm, pga, pgv, m, d, s, &
                                   kmax, kvel, drig, stat)
        call check(error, kmax < 0.39_dp .and. .not. d > 0.0_dp, message='ky >= kmax')
        if (allocated(error)) return
        ! SLAMMER's cap Ts/Tm <= 8: Ts/Tm = 20 gives the kmax of 8
        call rathje_antonakos_2011(EMP_RA11_PGA_M, ky, 10.0_dp, tm, pga, pgv, m, d, s, kmax, &
                                   kvel, drig, stat, slammer=.true.)
        call check(error, kmax, ra11_kmax_ratio(8.0_dp, pga) * pga, rtol=1.0e-15_dp, &
                   message='SLAMMER cap')
        if (allocated(error)) return
        ! SLAMMER: D = 0 when ky > PGA even if ky < kmax (Ts/Tm = 0.3 amplifies at low PGA)
        call rathje_antonakos_2011(EMP_RA11_PGA_M, 0.11_dp, 0.15_dp, tm, 0.1_dp, pgv, m, d, s, &
                                   kmax, kvel, drig, stat, slammer=.true.)
        call check(error, kmax > 0.11_dp .and. .not. d > 0.0_dp .and. drig > 0.0_dp, &
                   message='SLAMMER ky > PGA')
        if (allocated(error)) return
        call rathje_antonakos_2011(EMP_RA11_PGA_M, 0.11_dp, 0.15_dp, tm, 0.1_dp, pgv, m, d, s, &
                                   kmax, kvel, drig, stat)
        call check(error, d > 0.0_dp, message='paper: ky > PGA but < kmax slides')
    end subroutine test_ra11

    subroutine test_failure(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: p
        integer :: stat
        call check(error, probability_of_failure(0.0_dp), 0.0_dp, message='D = 0')
        if (allocated(error)) return
        call check(error, probability_of_failure(1.0e6_dp), 0.335_dp, message='large D')
        if (allocated(error)) return
        ! D = 10 cm: 0.335 (1 - exp(-0.048 10^1.565)) = 0.335 = 0.277535...
        call check(error, probability_of_failure(10.0_dp), &
                   0.335_dp * (1.0_dp - exp(-0.048_dp * 10.0_dp**1.565_dp)), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, probability_of_failure(10.0_dp), 0.277535_dp, atol=5.0e-6_dp, &
                   message='D = 10 cm digits')
        if (allocated(error)) return
        ! tiny D: 0.335 * 0.048 D^1.565 without cancellation
        call check(error, probability_of_failure(1.0e-8_dp), &
                   0.335_dp * 0.048_dp * 1.0e-8_dp**1.565_dp, rtol=1.0e-12_dp, message='tiny D')
        if (allocated(error)) return
        call probability_of_failure_checked(-1.0_dp, p, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, message='negative D')
    end subroutine test_failure

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: d, s, p, k1, k2, k3
        integer :: stat, base
        character(len=256) :: msg
        msg = ''
        call empirical_rigid(EMP_JIBSON_2007_RATIO, 0.3_dp, 0.3_dp, 1.0_dp, 1.0_dp, 7.0_dp, &
                             d, s, base, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:5) == 'ky = ' .and. &
                   index(msg, 'ky/pga') > 0, message='ky = PGA: '//trim(msg))
        if (allocated(error)) return
        ! J93 takes no PGA: ky above a junk PGA is fine
        call empirical_rigid(EMP_JIBSON_1993, 0.3_dp, -1.0_dp, 1.0_dp, 1.0_dp, 7.0_dp, &
                             d, s, base, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, message='J93 ignores pga')
        if (allocated(error)) return
        call empirical_rigid(EMP_RS09_PGA_M, 0.1_dp, 0.3_dp, 1.0_dp, 1.0_dp, 12.0_dp, &
                             d, s, base, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:12) == 'magnitude = ', &
                   message=trim(msg))
        if (allocated(error)) return
        call empirical_rigid(EMP_SR08_PGA_PGV_ARIAS, 0.1_dp, 0.3_dp, 20.0_dp, 0.0_dp, 7.0_dp, &
                             d, s, base, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:8) == 'arias = ', &
                   message=trim(msg))
        if (allocated(error)) return
        call empirical_rigid(12, 0.1_dp, 0.3_dp, 20.0_dp, 1.0_dp, 7.0_dp, d, s, base, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:8) == 'model = ', &
                   message=trim(msg))
        if (allocated(error)) return
        call bray_travasarou_2007(0.1_dp, -0.1_dp, 0.4_dp, 7.0_dp, d, s, p, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:5) == 'ts = ', &
                   message=trim(msg))
        if (allocated(error)) return
        call rathje_antonakos_2011(EMP_RA11_PGA_PGV, 0.1_dp, 0.3_dp, 0.0_dp, 0.4_dp, 30.0_dp, &
                                   7.0_dp, d, s, k1, k2, k3, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:5) == 'tm = ', &
                   message=trim(msg))
        if (allocated(error)) return
        call rathje_antonakos_2011(EMP_RA11_PGA_PGV, 0.1_dp, 0.3_dp, 0.5_dp, 0.4_dp, -3.0_dp, &
                                   7.0_dp, d, s, k1, k2, k3, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. msg(1:6) == 'pgv = ', &
                   message=trim(msg))
    end subroutine test_bad_input

end module test_empirical
