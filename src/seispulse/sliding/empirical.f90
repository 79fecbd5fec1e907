!> Empirical (simplified) estimates of the permanent sliding displacement of a slope,
!> as SLAMMER 1.1 [SL13] offers them: the rigid-block regressions of Jibson [J93],
!> Jibson et al. [J98], Jibson [J07] (four forms), Ambraseys & Menu [AM88], Saygili &
!> Rathje [SR08] (three forms) and Rathje & Saygili [RS09]; the coupled flexible model
!> of Bray & Travasarou [BT07] with its probability of zero displacement; the unified
!> rigid/flexible model of Rathje & Antonakos [RA11]; and the probability-of-failure
!> curve of Jibson et al. [J98] (2000). Equations: doc/empirical.md (E.1)-(E.35).
!>
!> Units as the sources: displacements in cm, accelerations and yields in g, PGV in
!> cm/s, Arias intensity in m/s, periods in s. Each model's standard deviation is that
!> of log10 D or of ln D as its source gives it (EMP_LOG10 / EMP_LN).
!>
!> The elemental functions are the bare regressions (no checks: ky/PGA must be in
!> (0, 1) where a model takes it, every input finite and > 0); the subroutines
!> empirical_rigid, bray_travasarou_2007 and rathje_antonakos_2011 check their inputs
!> and return stat and a message naming the parameter and its range.
module seispulse_empirical
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_checks, only: finite_positive, finite_at_least, outside
    use seispulse_format, only: real_str, int_str
    use seispulse_special, only: expm1, log1p
    implicit none
    private

    public :: jibson_1993, jibson_1998, jibson_2007_ratio, jibson_2007_ratio_m, &
              jibson_2007_arias, jibson_2007_arias_ratio, ambraseys_menu_1988, &
              saygili_rathje_2008_pga, saygili_rathje_2008_pgv, saygili_rathje_2008_pgv_arias, &
              rathje_saygili_2009, sr08_pgv_sigma, sr08_pgv_arias_sigma, rs09_sigma, &
              bt07_ln_disp, bt07_p_zero, bt07_p_zero_slammer, ra11_kmax_ratio, &
              ra11_kvelmax_ratio, probability_of_failure
    public :: empirical_rigid, empirical_model_name, empirical_model_code, empirical_needs, &
              empirical_check, bray_travasarou_2007, rathje_antonakos_2011, &
              probability_of_failure_checked
    public :: EMP_JIBSON_1993, EMP_JIBSON_1998, EMP_JIBSON_2007_RATIO, &
              EMP_JIBSON_2007_RATIO_M, EMP_JIBSON_2007_ARIAS, EMP_JIBSON_2007_ARIAS_RATIO, &
              EMP_AMBRASEYS_MENU_1988, EMP_SR08_PGA, EMP_SR08_PGA_PGV, EMP_SR08_PGA_PGV_ARIAS, &
              EMP_RS09_PGA_M, EMP_RIGID_MODELS, EMP_LOG10, EMP_LN, EMP_RA11_PGA_M, &
              EMP_RA11_PGA_PGV, EMP_NEED_PGA, EMP_NEED_PGV, EMP_NEED_ARIAS, EMP_NEED_M
    public :: J93_SIGMA, J98_SIGMA, J07_RATIO_SIGMA, J07_RATIO_M_SIGMA, J07_ARIAS_SIGMA, &
              J07_ARIAS_RATIO_SIGMA, AM88_SIGMA, SR08_PGA_SIGMA, BT07_SIGMA, BT07_TS_RIGID

    !> Rigid-block models of empirical_rigid (codes 1..EMP_RIGID_MODELS).
    integer, parameter :: EMP_JIBSON_1993 = 1             !! (E.1), Ia and ky
    integer, parameter :: EMP_JIBSON_1998 = 2             !! (E.2), Ia and ky
    integer, parameter :: EMP_JIBSON_2007_RATIO = 3       !! (E.3), ky/PGA
    integer, parameter :: EMP_JIBSON_2007_RATIO_M = 4     !! (E.4), ky/PGA and M
    integer, parameter :: EMP_JIBSON_2007_ARIAS = 5       !! (E.5), Ia and ky
    integer, parameter :: EMP_JIBSON_2007_ARIAS_RATIO = 6 !! (E.6), Ia and ky/PGA
    integer, parameter :: EMP_AMBRASEYS_MENU_1988 = 7     !! (E.7), ky/PGA
    integer, parameter :: EMP_SR08_PGA = 8                !! (E.8), ky/PGA and PGA
    integer, parameter :: EMP_SR08_PGA_PGV = 9            !! (E.9), + PGV
    integer, parameter :: EMP_SR08_PGA_PGV_ARIAS = 10     !! (E.10), + PGV and Ia
    integer, parameter :: EMP_RS09_PGA_M = 11             !! (E.11), ky/PGA, PGA and M
    integer, parameter :: EMP_RIGID_MODELS = 11           !! number of rigid-block models

    !> Base of the logarithm a standard deviation belongs to.
    integer, parameter :: EMP_LOG10 = 10   !! sigma of log10 D
    integer, parameter :: EMP_LN = 1       !! sigma of ln D

    !> The two forms of the unified model [RA11] (E.26)-(E.32).
    integer, parameter :: EMP_RA11_PGA_M = 1    !! on [RS09] (PGA, M), the "2009" form
    integer, parameter :: EMP_RA11_PGA_PGV = 2  !! on [SR08] (PGA, PGV), the "2008" form

    !> Bits of empirical_needs: which inputs besides ky a model takes.
    integer, parameter :: EMP_NEED_PGA = 1, EMP_NEED_PGV = 2, EMP_NEED_ARIAS = 4, &
                          EMP_NEED_M = 8

    !> Standard deviations that are constants (log10 for [J93] .. [AM88], ln for [SR08]).
    real(dp), parameter :: J93_SIGMA = 0.409_dp              !! log10, [J93]
    real(dp), parameter :: J98_SIGMA = 0.375_dp              !! log10, [J98]
    real(dp), parameter :: J07_RATIO_SIGMA = 0.510_dp        !! log10, [J07] Eq. 6
    real(dp), parameter :: J07_RATIO_M_SIGMA = 0.454_dp      !! log10, [J07] Eq. 7
    real(dp), parameter :: J07_ARIAS_SIGMA = 0.656_dp        !! log10, [J07] Eq. 9
    real(dp), parameter :: J07_ARIAS_RATIO_SIGMA = 0.616_dp  !! log10, [J07] Eq. 10
    real(dp), parameter :: AM88_SIGMA = 0.30_dp              !! log10, [AM88]
    real(dp), parameter :: SR08_PGA_SIGMA = 1.13_dp          !! ln, [SR08] (PGA)
    real(dp), parameter :: BT07_SIGMA = 0.66_dp              !! ln, [BT07] Eq. 5
    !> [BT07]: below this site period (s) the nearly rigid form (E.14) applies.
    real(dp), parameter :: BT07_TS_RIGID = 0.05_dp

    real(dp), parameter :: ln10 = 2.302585092994045684017991454684364208_dp

    character(len=28), parameter :: model_names(EMP_RIGID_MODELS) = [character(len=28) :: &
        'jibson_1993', 'jibson_1998', 'jibson_2007_ratio', 'jibson_2007_ratio_m', &
        'jibson_2007_arias', 'jibson_2007_arias_ratio', 'ambraseys_menu_1988', &
        'saygili_rathje_2008_pga', 'saygili_rathje_2008_pgv', 'saygili_rathje_2008_pgv_ia', &
        'rathje_saygili_2009']

contains

    ! ------------------------------------------------------------------------------
    ! The regressions (no checks)
    ! ------------------------------------------------------------------------------

    !> [J93] (E.1): log10 D = 1.460 log10 Ia - 6.642 ky + 1.546; D in cm.
    elemental real(dp) function jibson_1993(arias, ky) result(d)
        real(dp), intent(in) :: arias  !! Arias intensity Ia (m/s), > 0
        real(dp), intent(in) :: ky     !! yield acceleration (g), > 0
        d = 10.0_dp**(1.460_dp * log10(arias) - 6.642_dp * ky + 1.546_dp)
    end function jibson_1993

    !> [J98] (E.2): log10 D = 1.521 log10 Ia - 1.993 log10 ky - 1.546; D in cm.
    elemental real(dp) function jibson_1998(arias, ky) result(d)
        real(dp), intent(in) :: arias  !! Arias intensity Ia (m/s), > 0
        real(dp), intent(in) :: ky     !! yield acceleration (g), > 0
        d = 10.0_dp**(1.521_dp * log10(arias) - 1.993_dp * log10(ky) - 1.546_dp)
    end function jibson_1998

    !> log10[(1 - r)^a r^b] of the ratio forms (E.3), (E.4), (E.7), r in (0, 1).
    elemental real(dp) function log10_ratio_term(r, a, b) result(s)
        real(dp), intent(in) :: r, a, b
        s = (a * log1p(-r) + b * log(r)) / ln10
    end function log10_ratio_term

    !> [J07] Eq. 6 (E.3): log10 D = 0.215 + log10[(1 - r)^2.341 r^-1.438], r = ky/PGA; cm.
    elemental real(dp) function jibson_2007_ratio(ky, pga) result(d)
        real(dp), intent(in) :: ky   !! yield acceleration (g), 0 < ky < pga
        real(dp), intent(in) :: pga  !! peak ground acceleration (g)
        d = 10.0_dp**(0.215_dp + log10_ratio_term(ky / pga, 2.341_dp, -1.438_dp))
    end function jibson_2007_ratio

    !> [J07] Eq. 7 (E.4): log10 D = -2.710 + log10[(1 - r)^2.335 r^-1.478] + 0.424 M; cm.
    elemental real(dp) function jibson_2007_ratio_m(ky, pga, m) result(d)
        real(dp), intent(in) :: ky   !! yield acceleration (g), 0 < ky < pga
        real(dp), intent(in) :: pga  !! peak ground acceleration (g)
        real(dp), intent(in) :: m    !! moment magnitude (-)
        d = 10.0_dp**(-2.710_dp + log10_ratio_term(ky / pga, 2.335_dp, -1.478_dp) &
                      + 0.424_dp * m)
    end function jibson_2007_ratio_m

    !> [J07] Eq. 9 (E.5): log10 D = 2.401 log10 Ia - 3.481 log10 ky - 3.230; cm.
    elemental real(dp) function jibson_2007_arias(arias, ky) result(d)
        real(dp), intent(in) :: arias  !! Arias intensity Ia (m/s), > 0
        real(dp), intent(in) :: ky     !! yield acceleration (g), > 0
        d = 10.0_dp**(2.401_dp * log10(arias) - 3.481_dp * log10(ky) - 3.230_dp)
    end function jibson_2007_arias

    !> [J07] Eq. 10 (E.6): log10 D = 0.561 log10 Ia - 3.833 log10(ky/PGA) - 1.474; cm.
    elemental real(dp) function jibson_2007_arias_ratio(arias, ky, pga) result(d)
        real(dp), intent(in) :: arias  !! Arias intensity Ia (m/s), > 0
        real(dp), intent(in) :: ky     !! yield acceleration (g), 0 < ky < pga
        real(dp), intent(in) :: pga    !! peak ground acceleration (g)
        d = 10.0_dp**(0.561_dp * log10(arias) - 3.833_dp * log10(ky / pga) - 1.474_dp)
    end function jibson_2007_arias_ratio

    !> [AM88] (E.7): log10 D = 0.90 + log10[(1 - r)^2.53 r^-1.09], r = ky/PGA; cm.
    elemental real(dp) function ambraseys_menu_1988(ky, pga) result(d)
        real(dp), intent(in) :: ky   !! yield acceleration (g), 0 < ky < pga
        real(dp), intent(in) :: pga  !! peak ground acceleration (g)
        d = 10.0_dp**(0.90_dp + log10_ratio_term(ky / pga, 2.53_dp, -1.09_dp))
    end function ambraseys_menu_1988

    !> a1 + a2 r + a3 r^2 + a4 r^3 + a5 r^4 of [SR08] and [RS09] (Horner).
    pure real(dp) function quartic(r, a) result(s)
        real(dp), intent(in) :: r, a(5)
        s = a(1) + r * (a(2) + r * (a(3) + r * (a(4) + r * a(5))))
    end function quartic

    !> [SR08] (E.8), PGA model: ln D = 5.52 - 4.43 r - 20.39 r^2 + 42.61 r^3 - 28.74 r^4
    !> + 0.72 ln PGA, r = ky/PGA; cm. sigma_ln = SR08_PGA_SIGMA.
    elemental real(dp) function saygili_rathje_2008_pga(ky, pga) result(d)
        real(dp), intent(in) :: ky   !! yield acceleration (g), 0 < ky < pga
        real(dp), intent(in) :: pga  !! peak ground acceleration (g)
        d = exp(quartic(ky / pga, [5.52_dp, -4.43_dp, -20.39_dp, 42.61_dp, -28.74_dp]) &
                + 0.72_dp * log(pga))
    end function saygili_rathje_2008_pga

    !> [SR08] (E.9), PGA-PGV model: ln D = -1.56 - 4.58 r - 20.84 r^2 + 44.75 r^3 -
    !> 30.50 r^4 - 0.64 ln PGA + 1.55 ln PGV; cm.
    elemental real(dp) function saygili_rathje_2008_pgv(ky, pga, pgv) result(d)
        real(dp), intent(in) :: ky   !! yield acceleration (g), 0 < ky < pga
        real(dp), intent(in) :: pga  !! peak ground acceleration (g)
        real(dp), intent(in) :: pgv  !! peak ground velocity (cm/s)
        d = exp(quartic(ky / pga, [-1.56_dp, -4.58_dp, -20.84_dp, 44.75_dp, -30.50_dp]) &
                - 0.64_dp * log(pga) + 1.55_dp * log(pgv))
    end function saygili_rathje_2008_pgv

    !> [SR08] (E.10), PGA-PGV-Ia model: ln D = -0.74 - 4.93 r - 19.91 r^2 + 43.75 r^3 -
    !> 30.12 r^4 - 1.30 ln PGA + 1.04 ln PGV + 0.67 ln Ia; cm.
    elemental real(dp) function saygili_rathje_2008_pgv_arias(ky, pga, pgv, arias) result(d)
        real(dp), intent(in) :: ky     !! yield acceleration (g), 0 < ky < pga
        real(dp), intent(in) :: pga    !! peak ground acceleration (g)
        real(dp), intent(in) :: pgv    !! peak ground velocity (cm/s)
        real(dp), intent(in) :: arias  !! Arias intensity (m/s)
        d = exp(quartic(ky / pga, [-0.74_dp, -4.93_dp, -19.91_dp, 43.75_dp, -30.12_dp]) &
                - 1.30_dp * log(pga) + 1.04_dp * log(pgv) + 0.67_dp * log(arias))
    end function saygili_rathje_2008_pgv_arias

    !> [RS09] (E.11), PGA-M model: ln D = 4.89 - 4.85 r - 19.64 r^2 + 42.49 r^3 -
    !> 29.06 r^4 + 0.72 ln PGA + 0.89 (M - 6); cm.
    elemental real(dp) function rathje_saygili_2009(ky, pga, m) result(d)
        real(dp), intent(in) :: ky   !! yield acceleration (g), 0 < ky < pga
        real(dp), intent(in) :: pga  !! peak ground acceleration (g)
        real(dp), intent(in) :: m    !! moment magnitude (-)
        d = exp(quartic(ky / pga, [4.89_dp, -4.85_dp, -19.64_dp, 42.49_dp, -29.06_dp]) &
                + 0.72_dp * log(pga) + 0.89_dp * (m - 6.0_dp))
    end function rathje_saygili_2009

    !> sigma of ln D of [SR08] PGA-PGV (E.12a): 0.41 + 0.52 ky/PGA.
    elemental real(dp) function sr08_pgv_sigma(ratio) result(s)
        real(dp), intent(in) :: ratio  !! ky/PGA
        s = 0.41_dp + 0.52_dp * ratio
    end function sr08_pgv_sigma

    !> sigma of ln D of [SR08] PGA-PGV-Ia (E.12b): 0.20 + 0.79 ky/PGA.
    elemental real(dp) function sr08_pgv_arias_sigma(ratio) result(s)
        real(dp), intent(in) :: ratio  !! ky/PGA
        s = 0.20_dp + 0.79_dp * ratio
    end function sr08_pgv_arias_sigma

    !> sigma of ln D of [RS09] PGA-M (E.12c): 0.732 + 0.789 r - 0.539 r^2, r = ky/PGA.
    elemental real(dp) function rs09_sigma(ratio) result(s)
        real(dp), intent(in) :: ratio  !! ky/PGA
        s = 0.732_dp + ratio * (0.789_dp - 0.539_dp * ratio)
    end function rs09_sigma

    !> [BT07] ln D (D in cm) of the non-zero displacement: Eq. 5 (E.13) for Ts >= 0.05 s,
    !> ln D = -1.10 - 2.83 ln ky - 0.333 (ln ky)^2 + 0.566 ln ky ln Sa + 3.04 ln Sa
    !> - 0.244 (ln Sa)^2 + 1.50 Ts + 0.278 (M - 7), Sa = Sa(1.5 Ts); Eq. 6 (E.14) for
    !> Ts < 0.05 s (nearly rigid): -0.22 in place of -1.10, no Ts term, Sa = PGA.
    !> slammer: SLAMMER 1.1's form, Eq. 5 at every Ts (it has no nearly rigid branch).
    elemental real(dp) function bt07_ln_disp(ky, ts, sa, m, slammer) result(lnd)
        real(dp), intent(in) :: ky   !! yield coefficient (g), > 0
        real(dp), intent(in) :: ts   !! site period of the sliding mass (s), >= 0
        real(dp), intent(in) :: sa   !! Sa(1.5 Ts) (g), > 0 (PGA when Ts < 0.05 s)
        real(dp), intent(in) :: m    !! moment magnitude (-)
        logical, intent(in) :: slammer  !! SLAMMER's form (no nearly rigid branch)
        real(dp) :: lk, ls
        lk = log(ky)
        ls = log(sa)
        lnd = -2.83_dp * lk - 0.333_dp * lk**2 + 0.566_dp * lk * ls + 3.04_dp * ls &
              - 0.244_dp * ls**2 + 0.278_dp * (m - 7.0_dp)
        if (ts < BT07_TS_RIGID .and. .not. slammer) then
            lnd = lnd - 0.22_dp                      ! (E.14)
        else
            lnd = lnd - 1.10_dp + 1.50_dp * ts       ! (E.13)
        end if
    end function bt07_ln_disp

    !> [BT07] Eq. 3 (E.15): P(D = 0) = 1 - Phi(x), x = -1.76 - 3.22 ln ky - 0.484 Ts ln ky
    !> + 3.52 ln Sa(1.5 Ts), with the exact normal distribution: 1 - Phi(x) =
    !> erfc(x/sqrt 2)/2 (no cancellation for large x). "Zero" is D <= 1 cm [BT07].
    elemental real(dp) function bt07_p_zero(ky, ts, sa) result(p)
        real(dp), intent(in) :: ky  !! yield coefficient (g), > 0
        real(dp), intent(in) :: ts  !! site period (s), >= 0
        real(dp), intent(in) :: sa  !! Sa(1.5 Ts) (g), > 0
        p = 0.5_dp * erfc(bt07_x(ky, ts, sa) / sqrt(2.0_dp))
    end function bt07_p_zero

    !> The argument x of Phi in (E.15).
    elemental real(dp) function bt07_x(ky, ts, sa) result(x)
        real(dp), intent(in) :: ky, ts, sa
        x = -1.76_dp - 3.22_dp * log(ky) - 0.484_dp * ts * log(ky) + 3.52_dp * log(sa)
    end function bt07_x

    !> SLAMMER 1.1's P(D = 0) (E.16): 1 - Phi(x) with Phi from Abramowitz & Stegun 26.2.17
    !> (error < 7.5e-8 for x >= 0), applied by SLAMMER at every x. For x < 0 the polynomial
    !> is outside its domain: wrong values, and a pole at x = -1/0.2316419. For tests and
    !> for reproducing SLAMMER; bt07_p_zero is the exact value.
    elemental real(dp) function bt07_p_zero_slammer(ky, ts, sa) result(p)
        real(dp), intent(in) :: ky  !! yield coefficient (g), > 0
        real(dp), intent(in) :: ts  !! site period (s), >= 0
        real(dp), intent(in) :: sa  !! Sa(1.5 Ts) (g), > 0
        real(dp), parameter :: pp = 0.2316419_dp, b(5) = [0.319381530_dp, -0.356563782_dp, &
                               1.781477937_dp, -1.821255978_dp, 1.330274429_dp]
        real(dp), parameter :: rsqrt2pi = 0.398942280401432677939946059934381868_dp
        real(dp) :: x, t, z
        x = bt07_x(ky, ts, sa)
        z = rsqrt2pi * exp(-0.5_dp * x * x)
        t = 1.0_dp / (1.0_dp + pp * x)
        p = z * t * (b(1) + t * (b(2) + t * (b(3) + t * (b(4) + t * b(5)))))
    end function bt07_p_zero_slammer

    !> [RA11] (E.26): kmax/PGA = 1 for Ts/Tm < 0.1, else exp[(0.459 - 0.702 PGA) L +
    !> (-0.228 + 0.076 PGA) L^2], L = ln((Ts/Tm)/0.1).
    elemental real(dp) function ra11_kmax_ratio(ts_tm, pga) result(q)
        real(dp), intent(in) :: ts_tm  !! Ts/Tm, >= 0
        real(dp), intent(in) :: pga    !! peak ground acceleration (g)
        real(dp) :: l
        if (ts_tm < 0.1_dp) then
            q = 1.0_dp
        else
            l = log(ts_tm / 0.1_dp)
            q = exp((0.459_dp - 0.702_dp * pga) * l + (-0.228_dp + 0.076_dp * pga) * l**2)
        end if
    end function ra11_kmax_ratio

    !> [RA11] (E.27): kvelmax/PGV = 1 for Ts/Tm < 0.2, else exp[0.240 L + (-0.091 -
    !> 0.171 PGA) L^2], L = ln((Ts/Tm)/0.2).
    elemental real(dp) function ra11_kvelmax_ratio(ts_tm, pga) result(q)
        real(dp), intent(in) :: ts_tm  !! Ts/Tm, >= 0
        real(dp), intent(in) :: pga    !! peak ground acceleration (g)
        real(dp) :: l
        if (ts_tm < 0.2_dp) then
            q = 1.0_dp
        else
            l = log(ts_tm / 0.2_dp)
            q = exp(0.240_dp * l + (-0.091_dp - 0.171_dp * pga) * l**2)
        end if
    end function ra11_kvelmax_ratio

    !> Probability of failure of [J98] (Jibson et al. 2000) (E.35):
    !> P = 0.335 [1 - exp(-0.048 D^1.565)], D the Newmark displacement in cm.
    elemental real(dp) function probability_of_failure(disp_cm) result(p)
        real(dp), intent(in) :: disp_cm  !! Newmark displacement (cm), >= 0
        p = -0.335_dp * expm1(-0.048_dp * disp_cm**1.565_dp)
    end function probability_of_failure

    ! ------------------------------------------------------------------------------
    ! Checked entry points
    ! ------------------------------------------------------------------------------

    !> The name of a rigid-block model code ('' for an unknown code).
    pure function empirical_model_name(model) result(name)
        integer, intent(in) :: model  !! EMP_* code of a rigid-block model
        character(len=len_trim(empirical_model_name_text(model))) :: name
        name = empirical_model_name_text(model)
    end function empirical_model_name

    !> empirical_model_name(model) padded with blanks.
    pure function empirical_model_name_text(model) result(name)
        integer, intent(in) :: model
        character(len=64) :: name
        if (model >= 1 .and. model <= EMP_RIGID_MODELS) then
            name = trim(model_names(model))
        else
            name = ''
        end if
    end function empirical_model_name_text

    !> The code of a rigid-block model name (0 for an unknown name).
    pure integer function empirical_model_code(name) result(model)
        character(len=*), intent(in) :: name  !! model name as empirical_model_name gives it
        integer :: k
        model = 0
        do k = 1, EMP_RIGID_MODELS
            if (trim(model_names(k)) == trim(adjustl(name))) model = k
        end do
    end function empirical_model_code

    !> The inputs besides ky a rigid-block model takes: a sum of EMP_NEED_* bits (0 for an
    !> unknown model).
    pure integer function empirical_needs(model) result(needs)
        integer, intent(in) :: model  !! EMP_* code of a rigid-block model
        select case (model)
        case (EMP_JIBSON_1993, EMP_JIBSON_1998, EMP_JIBSON_2007_ARIAS)
            needs = EMP_NEED_ARIAS
        case (EMP_JIBSON_2007_RATIO, EMP_AMBRASEYS_MENU_1988, EMP_SR08_PGA)
            needs = EMP_NEED_PGA
        case (EMP_JIBSON_2007_RATIO_M, EMP_RS09_PGA_M)
            needs = EMP_NEED_PGA + EMP_NEED_M
        case (EMP_JIBSON_2007_ARIAS_RATIO)
            needs = EMP_NEED_PGA + EMP_NEED_ARIAS
        case (EMP_SR08_PGA_PGV)
            needs = EMP_NEED_PGA + EMP_NEED_PGV
        case (EMP_SR08_PGA_PGV_ARIAS)
            needs = EMP_NEED_PGA + EMP_NEED_PGV + EMP_NEED_ARIAS
        case default
            needs = 0
        end select
    end function empirical_needs

    !> Check one input of the empirical models: 'ky', 'pga', 'pgv', 'arias', 'magnitude',
    !> 'ts', 'tm', 'sa', 'disp_cm'. stat SEISPULSE_INVALID_INPUT and a message
    !> "name = value: must be ..." when it is out of range.
    pure subroutine empirical_check(name, x, stat, errmsg)
        character(len=*), intent(in) :: name                 !! the input's name
        real(dp), intent(in) :: x                            !! its value
        integer, intent(out) :: stat                         !! SEISPULSE_SUCCESS or an error
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        character(len=:), allocatable :: rule
        logical :: ok
        stat = SEISPULSE_SUCCESS
        select case (name)
        case ('ky')
            ok = finite_positive(x)
            rule = 'a finite number > 0 (g)'
        case ('pga', 'sa')
            ok = finite_positive(x)
            rule = 'a finite number > 0 (g)'
        case ('pgv')
            ok = finite_positive(x)
            rule = 'a finite number > 0 (cm/s)'
        case ('arias')
            ok = finite_positive(x)
            rule = 'a finite number > 0 (m/s)'
        case ('magnitude')
            ok = .not. outside(x, 0.0_dp, 10.0_dp, .true., .true.)
            rule = 'a moment magnitude, 0 < M < 10'
        case ('ts')
            ok = finite_at_least(x, 0.0_dp)
            rule = 'a finite number >= 0 (s)'
        case ('tm')
            ok = finite_positive(x)
            rule = 'a finite number > 0 (s)'
        case ('disp_cm')
            ok = finite_at_least(x, 0.0_dp)
            rule = 'a finite number >= 0 (cm)'
        case default
            ok = .false.
            rule = 'not an input of the empirical models'
        end select
        if (.not. ok) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                                     name//' = '//real_str(x)//': must be '//rule)
    end subroutine empirical_check

    !> ky/PGA of a ratio model: in (0, 1) (at ky >= PGA a rigid block does not slide and
    !> the regressions do not apply).
    pure subroutine check_ratio(ky, pga, stat, errmsg)
        real(dp), intent(in) :: ky, pga
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. ky < pga) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
            'ky = '//real_str(ky)//': ky/pga = '//real_str(ky / pga)//' must be < 1 (pga = ' &
            //real_str(pga)//' g; a rigid block with ky >= PGA does not slide)')
    end subroutine check_ratio

    !> A rigid-block model (E.1)-(E.12) with its checks. The inputs the model does not
    !> take are ignored (any value). disp_cm: the median displacement (cm); sigma: the
    !> standard deviation of log10 D (log_base = EMP_LOG10) or ln D (EMP_LN).
    pure subroutine empirical_rigid(model, ky, pga, pgv, arias, magnitude, disp_cm, sigma, &
                                    log_base, stat, errmsg)
        integer, intent(in) :: model         !! EMP_JIBSON_1993 .. EMP_RS09_PGA_M
        real(dp), intent(in) :: ky           !! yield acceleration (g), > 0
        real(dp), intent(in) :: pga          !! peak ground acceleration (g), > ky
        real(dp), intent(in) :: pgv          !! peak ground velocity (cm/s), > 0
        real(dp), intent(in) :: arias        !! Arias intensity (m/s), > 0
        real(dp), intent(in) :: magnitude    !! moment magnitude (-), in (0, 10)
        real(dp), intent(out) :: disp_cm     !! median displacement (cm)
        real(dp), intent(out) :: sigma       !! standard deviation of log D
        integer, intent(out) :: log_base     !! EMP_LOG10 or EMP_LN
        integer, intent(out) :: stat         !! SEISPULSE_SUCCESS or an error
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, parameter :: bits(4) = [EMP_NEED_PGA, EMP_NEED_PGV, EMP_NEED_ARIAS, EMP_NEED_M]
        character(len=9), parameter :: inputs(4) = [character(len=9) :: 'pga', 'pgv', 'arias', &
                                                    'magnitude']
        integer :: needs, k
        real(dp) :: r, values(4)
        disp_cm = 0.0_dp
        sigma = 0.0_dp
        log_base = EMP_LN
        needs = empirical_needs(model)
        if (needs == 0) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'model = '//int_str(model) &
                //': unknown rigid-block model (1 to 11)')
            return
        end if
        call empirical_check('ky', ky, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        values = [pga, pgv, arias, magnitude]
        do k = 1, size(bits)
            if (iand(needs, bits(k)) == 0) cycle
            call empirical_check(trim(inputs(k)), values(k), stat, errmsg)
            if (stat == SEISPULSE_SUCCESS .and. k == 1) call check_ratio(ky, pga, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end do
        r = 0.0_dp
        if (iand(needs, EMP_NEED_PGA) /= 0) r = ky / pga
        log_base = EMP_LOG10
        select case (model)
        case (EMP_JIBSON_1993)
            disp_cm = jibson_1993(arias, ky)
            sigma = J93_SIGMA
        case (EMP_JIBSON_1998)
            disp_cm = jibson_1998(arias, ky)
            sigma = J98_SIGMA
        case (EMP_JIBSON_2007_RATIO)
            disp_cm = jibson_2007_ratio(ky, pga)
            sigma = J07_RATIO_SIGMA
        case (EMP_JIBSON_2007_RATIO_M)
            disp_cm = jibson_2007_ratio_m(ky, pga, magnitude)
            sigma = J07_RATIO_M_SIGMA
        case (EMP_JIBSON_2007_ARIAS)
            disp_cm = jibson_2007_arias(arias, ky)
            sigma = J07_ARIAS_SIGMA
        case (EMP_JIBSON_2007_ARIAS_RATIO)
            disp_cm = jibson_2007_arias_ratio(arias, ky, pga)
            sigma = J07_ARIAS_RATIO_SIGMA
        case (EMP_AMBRASEYS_MENU_1988)
            disp_cm = ambraseys_menu_1988(ky, pga)
            sigma = AM88_SIGMA
        case (EMP_SR08_PGA)
            disp_cm = saygili_rathje_2008_pga(ky, pga)
            sigma = SR08_PGA_SIGMA
            log_base = EMP_LN
        case (EMP_SR08_PGA_PGV)
            disp_cm = saygili_rathje_2008_pgv(ky, pga, pgv)
            sigma = sr08_pgv_sigma(r)
            log_base = EMP_LN
        case (EMP_SR08_PGA_PGV_ARIAS)
            disp_cm = saygili_rathje_2008_pgv_arias(ky, pga, pgv, arias)
            sigma = sr08_pgv_arias_sigma(r)
            log_base = EMP_LN
        case (EMP_RS09_PGA_M)
            disp_cm = rathje_saygili_2009(ky, pga, magnitude)
            sigma = rs09_sigma(r)
            log_base = EMP_LN
        end select
    end subroutine empirical_rigid

    !> [BT07] with its checks: the median non-zero displacement (cm) (E.13)/(E.14),
    !> sigma of ln D = BT07_SIGMA, and P(D = 0) (E.15). slammer (default .false.): SLAMMER
    !> 1.1's arithmetic, Eq. 5 at every Ts and its polynomial Phi (E.16).
    pure subroutine bray_travasarou_2007(ky, ts, sa, magnitude, disp_cm, sigma, p_zero, stat, &
                                         errmsg, slammer)
        real(dp), intent(in) :: ky           !! yield coefficient (g), > 0
        real(dp), intent(in) :: ts           !! site period (s), >= 0
        real(dp), intent(in) :: sa           !! Sa(1.5 Ts) (g), > 0 (PGA for Ts < 0.05 s)
        real(dp), intent(in) :: magnitude    !! moment magnitude (-), in (0, 10)
        real(dp), intent(out) :: disp_cm     !! median of the non-zero displacement (cm)
        real(dp), intent(out) :: sigma       !! standard deviation of ln D
        real(dp), intent(out) :: p_zero      !! probability of D <= 1 cm
        integer, intent(out) :: stat         !! SEISPULSE_SUCCESS or an error
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        logical, intent(in), optional :: slammer  !! SLAMMER 1.1's arithmetic; default .false.
        logical :: sl
        disp_cm = 0.0_dp
        sigma = BT07_SIGMA
        p_zero = 0.0_dp
        sl = .false.
        if (present(slammer)) sl = slammer
        call empirical_check('ky', ky, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call empirical_check('ts', ts, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call empirical_check('sa', sa, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call empirical_check('magnitude', magnitude, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        disp_cm = exp(bt07_ln_disp(ky, ts, sa, magnitude, sl))
        if (sl) then
            p_zero = bt07_p_zero_slammer(ky, ts, sa)
        else
            p_zero = bt07_p_zero(ky, ts, sa)
        end if
    end subroutine bray_travasarou_2007

    !> [RA11] unified model with its checks (E.26)-(E.32): kmax (E.26) and, for the
    !> PGA-PGV form, kvelmax (E.27); the rigid displacement of [RS09] (E.11) or [SR08]
    !> (E.9) with kmax for PGA (and kvelmax for PGV), then the period term (E.28)/(E.29);
    !> D = 0 when ky >= kmax (no sliding). sigma of ln D (E.30)/(E.31) with ky/kmax.
    !> slammer (default .false.): SLAMMER 1.1's rules, Ts/Tm capped at 8 and D = 0 also
    !> when ky > PGA (doc/empirical.md section 6).
    pure subroutine rathje_antonakos_2011(form, ky, ts, tm, pga, pgv, magnitude, disp_cm, &
                                          sigma, kmax, kvelmax, disp_rigid_cm, stat, errmsg, &
                                          slammer)
        integer, intent(in) :: form          !! EMP_RA11_PGA_M or EMP_RA11_PGA_PGV
        real(dp), intent(in) :: ky           !! yield acceleration (g), > 0
        real(dp), intent(in) :: ts           !! site period of the sliding mass (s), >= 0
        real(dp), intent(in) :: tm           !! mean period of the motion (s), > 0
        real(dp), intent(in) :: pga          !! peak ground acceleration (g), > 0
        real(dp), intent(in) :: pgv          !! PGV (cm/s), > 0 (PGA-PGV form only)
        real(dp), intent(in) :: magnitude    !! moment magnitude (PGA-M form only)
        real(dp), intent(out) :: disp_cm     !! median displacement of the flexible mass (cm)
        real(dp), intent(out) :: sigma       !! standard deviation of ln D
        real(dp), intent(out) :: kmax        !! peak average acceleration of the mass (g)
        real(dp), intent(out) :: kvelmax     !! its velocity counterpart (cm/s; PGA-PGV only,
                                             !! else 0)
        real(dp), intent(out) :: disp_rigid_cm  !! the rigid-model value at kmax (cm; 0 when
                                             !! ky >= kmax)
        integer, intent(out) :: stat         !! SEISPULSE_SUCCESS or an error
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        logical, intent(in), optional :: slammer  !! SLAMMER 1.1's rules; default .false.
        logical :: sl
        real(dp) :: pr, r, f
        disp_cm = 0.0_dp
        sigma = 0.0_dp
        kmax = 0.0_dp
        kvelmax = 0.0_dp
        disp_rigid_cm = 0.0_dp
        sl = .false.
        if (present(slammer)) sl = slammer
        if (form /= EMP_RA11_PGA_M .and. form /= EMP_RA11_PGA_PGV) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'form = '//int_str(form) &
                //': unknown form (1: PGA and M, 2: PGA and PGV)')
            return
        end if
        call empirical_check('ky', ky, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call empirical_check('ts', ts, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call empirical_check('tm', tm, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call empirical_check('pga', pga, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (form == EMP_RA11_PGA_M) then
            call empirical_check('magnitude', magnitude, stat, errmsg)
        else
            call empirical_check('pgv', pgv, stat, errmsg)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        pr = ts / tm
        if (sl) pr = min(pr, 8.0_dp)
        kmax = ra11_kmax_ratio(pr, pga) * pga                            ! (E.26)
        r = ky / kmax
        if (form == EMP_RA11_PGA_M) then
            sigma = 0.694_dp + 0.322_dp * r                              ! (E.30)
            if (ts <= 1.5_dp) then
                f = 3.69_dp * ts - 1.22_dp * ts**2                       ! (E.28)
            else
                f = 2.78_dp
            end if
            if (r < 1.0_dp) disp_rigid_cm = rathje_saygili_2009(ky, kmax, magnitude)
        else
            kvelmax = ra11_kvelmax_ratio(pr, pga) * pgv                  ! (E.27)
            sigma = 0.400_dp + 0.284_dp * r                              ! (E.31)
            if (ts <= 0.5_dp) then
                f = 1.42_dp * ts                                         ! (E.29)
            else
                f = 0.71_dp
            end if
            if (r < 1.0_dp) disp_rigid_cm = saygili_rathje_2008_pgv(ky, kmax, kvelmax)
        end if
        if (r < 1.0_dp) disp_cm = disp_rigid_cm * exp(f)                 ! (E.32)
        if (sl .and. ky > pga) disp_cm = 0.0_dp
    end subroutine rathje_antonakos_2011

    !> probability_of_failure (E.35) with its check (disp_cm finite, >= 0).
    pure subroutine probability_of_failure_checked(disp_cm, p, stat, errmsg)
        real(dp), intent(in) :: disp_cm      !! Newmark displacement (cm), >= 0
        real(dp), intent(out) :: p           !! probability of failure
        integer, intent(out) :: stat         !! SEISPULSE_SUCCESS or an error
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        p = 0.0_dp
        call empirical_check('disp_cm', disp_cm, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) p = probability_of_failure(disp_cm)
    end subroutine probability_of_failure_checked

end module seispulse_empirical
