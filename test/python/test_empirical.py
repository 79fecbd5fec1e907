"""seispulse.empirical: every model against its source equation worked out here (not
through the library), the published examples of Bray & Travasarou (2007), SLAMMER 1.1's
Java formulas (RigidBlockSimplified, CoupledSimplified, UnifiedModel) rewritten here and
compared at the digits SLAMMER prints, and bad input naming the parameter."""
import math
import re

import numpy as np
import pytest

from seispulse import InvalidInputError, empirical

LN10 = math.log(10.0)


# --- SLAMMER 1.1's Java, rewritten line by line (the strings its GUI prints) ----------

def fmt(x, digits):
    """java.text.DecimalFormat('0.0...') (HALF_EVEN on the exact double) for finite x."""
    return f"{x:.{digits}f}"


def slammer_rigid(name, ky, pga=None, pgv=None, ia=None, m=None):
    if name == "jibson_1993":
        return 10 ** (1.46 * math.log10(ia) - 6.642 * ky + 1.546)
    if name == "jibson_1998":
        return 10 ** (1.521 * math.log10(ia) - 1.993 * math.log10(ky) - 1.546)
    r = None if pga is None else ky / pga
    if name == "jibson_2007_ratio":
        return 10 ** (0.215 + math.log10((1.0 - r) ** 2.341 * r ** -1.438))
    if name == "jibson_2007_ratio_m":
        return 10 ** (-2.71 + math.log10((1.0 - r) ** 2.335 * r ** -1.478) + 0.424 * m)
    if name == "jibson_2007_arias":
        return 10 ** (2.401 * math.log10(ia) - 3.481 * math.log10(ky) - 3.23)
    if name == "jibson_2007_arias_ratio":
        return 10 ** (0.561 * math.log10(ia) - 3.833 * math.log10(r) - 1.474)
    if name == "ambraseys_menu_1988":
        return 10 ** (0.90 + math.log10((1.0 - r) ** 2.53 * r ** -1.09))
    r2, r3, r4 = r * r, r * r * r, r * r * r * r
    if name == "saygili_rathje_2008_pga":
        return math.e ** (5.52 - 4.43 * r - 20.39 * r2 + 42.61 * r3 - 28.74 * r4
                          + 0.72 * math.log(pga))
    if name == "saygili_rathje_2008_pgv":
        return math.e ** (-1.56 - 4.58 * r - 20.84 * r2 + 44.75 * r3 - 30.50 * r4
                          - 0.64 * math.log(pga) + 1.55 * math.log(pgv))
    if name == "saygili_rathje_2008_pgv_arias":
        return math.e ** (-0.74 - 4.93 * r - 19.91 * r2 + 43.75 * r3 - 30.12 * r4
                          - 1.30 * math.log(pga) + 1.04 * math.log(pgv) + 0.67 * math.log(ia))
    if name == "rathje_saygili_2009":
        return math.e ** (4.89 - 4.85 * r - 19.64 * r2 + 42.49 * r3 - 29.06 * r4
                          + 0.72 * math.log(pga) + 0.89 * (m - 6.0))
    raise KeyError(name)


def slammer_bt07(ky, ts, sa, m):
    """CoupledSimplified.BrayAndTravasarou2007: (disp cm, P(D = 0)) as doubles."""
    p, b = 0.2316419, (0.319381530, -0.356563782, 1.781477937, -1.821255978, 1.330274429)
    lnky, lnsa = math.log(ky), math.log(sa)
    disp = math.exp(-1.1 - 2.83 * lnky - 0.333 * lnky * lnky + 0.566 * lnky * lnsa
                    + 3.04 * lnsa - 0.244 * lnsa * lnsa + ts * 1.5 + 0.278 * (m - 7.0))
    x = -1.76 - 3.22 * lnky - 0.484 * ts * lnky + 3.52 * lnsa
    zx = (1.0 / math.sqrt(2 * math.pi)) * math.exp(-(x * x) / 2.0)
    t = 1.0 / (1.0 + p * x)
    px = 1 - zx * sum(bk * t ** (k + 1) for k, bk in enumerate(b))
    return disp, 1.0 - px


def jlog(x):
    """Java's Math.log: -Infinity at 0 (where Python raises)."""
    return math.log(x) if x > 0 else -math.inf


def slammer_unified(ac, ts, m, pga, pgv, tm, method):
    """UnifiedModel.UnifiedModel: (kmax, kvelmax, rigid disp, flexible disp) as doubles."""
    pr = min(ts / tm, 8.0)
    kmax_pga = 1.0 if pr < 0.1 else math.exp(
        (0.459 - 0.702 * pga) * math.log(pr / 0.1)
        + (-0.228 + 0.076 * pga) * math.log(pr / 0.1) ** 2)
    kvel_pgv = 1.0 if pr < 0.2 else math.exp(
        0.24 * math.log(pr / 0.2) + (-0.091 - 0.171 * pga) * math.log(pr / 0.2) ** 2)
    kmax = kmax_pga * pga
    kvel = 0.0
    if method == 2008:
        kvel = kvel_pgv * pgv
        disp = slammer_rigid("saygili_rathje_2008_pgv", ac, pga=kmax, pgv=kvel)
        flex = math.exp(jlog(disp) + (1.42 * ts if ts <= 0.5 else 0.71))
    else:
        disp = slammer_rigid("rathje_saygili_2009", ac, pga=kmax, m=m)
        flex = math.exp(jlog(disp) + (3.69 * ts - 1.22 * ts * ts if ts <= 1.5 else 2.78))
    if ac > pga or ac > kmax:
        flex = 0.0
    return kmax, kvel, disp, flex


# --- every model, a value worked by hand from its source equation ---------------------

def test_jibson_1993_by_hand():
    # Ia = 1 m/s: log10 D = 1.546 - 6.642 * 0.1 = 0.8818
    r = empirical.jibson_1993(1.0, 0.1)
    assert r.disp_cm == pytest.approx(10 ** 0.8818, rel=1e-13)
    assert r.disp_m == pytest.approx(10 ** 0.8818 / 100, rel=1e-13)
    assert (r.sigma, r.log_base) == (0.409, "log10")
    assert r.d84_cm == pytest.approx(10 ** (0.8818 + 0.409), rel=1e-13)
    assert r.d16_cm == pytest.approx(10 ** (0.8818 - 0.409), rel=1e-13)


def test_jibson_1998_by_hand():
    # Ia = 10 m/s, ky = 0.1: 1.521 + 1.993 - 1.546 = 1.968
    r = empirical.jibson_1998(10.0, 0.1)
    assert r.disp_cm == pytest.approx(10 ** 1.968, rel=1e-13)
    assert (r.sigma, r.log_base) == (0.375, "log10")


def test_jibson_2007_four_forms_by_hand():
    # ky/PGA = 0.5
    r = empirical.jibson_2007_ratio(0.1, 0.2)
    assert r.disp_cm == pytest.approx(10 ** 0.215 * 0.5 ** (2.341 - 1.438), rel=1e-13)
    assert r.sigma == 0.510
    r = empirical.jibson_2007_ratio_m(0.1, 0.2, 7.0)
    assert r.disp_cm == pytest.approx(10 ** (-2.710 + 0.424 * 7.0) * 0.5 ** (2.335 - 1.478),
                                      rel=1e-13)
    assert r.sigma == 0.454
    # Ia = 1 m/s, ky = 0.1 g: log10 D = 3.481 - 3.230 = 0.251
    r = empirical.jibson_2007_arias(1.0, 0.1)
    assert r.disp_cm == pytest.approx(10 ** 0.251, rel=1e-13)
    assert r.sigma == 0.656
    # Ia = 1, ky/PGA = 0.1: 3.833 - 1.474 = 2.359
    r = empirical.jibson_2007_arias_ratio(1.0, 0.05, 0.5)
    assert r.disp_cm == pytest.approx(10 ** 2.359, rel=1e-13)
    assert r.sigma == 0.616


def test_ambraseys_menu_1988_by_hand():
    r = empirical.ambraseys_menu_1988(0.1, 0.2)
    assert r.disp_cm == pytest.approx(10 ** 0.90 * 0.5 ** 2.53 * 0.5 ** -1.09, rel=1e-13)
    assert (r.sigma, r.log_base) == (0.30, "log10")


def test_saygili_rathje_2008_by_hand():
    # ky/PGA = 0.5, PGA = 0.2 g: the quartic at 0.5
    q_pga = 5.52 - 4.43 / 2 - 20.39 / 4 + 42.61 / 8 - 28.74 / 16
    r = empirical.saygili_rathje_2008_pga(0.1, 0.2)
    assert r.disp_cm == pytest.approx(math.exp(q_pga + 0.72 * math.log(0.2)), rel=1e-13)
    assert (r.sigma, r.log_base) == (1.13, "ln")
    q_pgv = -1.56 - 4.58 / 2 - 20.84 / 4 + 44.75 / 8 - 30.50 / 16
    r = empirical.saygili_rathje_2008_pgv(0.1, 0.2, 30.0)
    assert r.disp_cm == pytest.approx(math.exp(q_pgv - 0.64 * math.log(0.2)
                                               + 1.55 * math.log(30.0)), rel=1e-13)
    assert r.sigma == pytest.approx(0.41 + 0.52 * 0.5, rel=1e-15)
    q_ia = -0.74 - 4.93 / 2 - 19.91 / 4 + 43.75 / 8 - 30.12 / 16
    r = empirical.saygili_rathje_2008_pgv_arias(0.1, 0.2, 30.0, 1.5)
    assert r.disp_cm == pytest.approx(math.exp(q_ia - 1.30 * math.log(0.2) + 1.04
                                               * math.log(30.0) + 0.67 * math.log(1.5)),
                                      rel=1e-13)
    assert r.sigma == pytest.approx(0.20 + 0.79 * 0.5, rel=1e-15)


def test_rathje_saygili_2009_by_hand():
    q = 4.89 - 4.85 / 2 - 19.64 / 4 + 42.49 / 8 - 29.06 / 16
    r = empirical.rathje_saygili_2009(0.1, 0.2, 7.5)
    assert r.disp_cm == pytest.approx(math.exp(q + 0.72 * math.log(0.2) + 0.89 * 1.5),
                                      rel=1e-13)
    assert r.sigma == pytest.approx(0.732 + 0.789 * 0.5 - 0.539 * 0.25, rel=1e-15)
    assert r.log_base == "ln"


def test_bray_travasarou_published_examples():
    # Bray & Travasarou (2007), earth dam: ky 0.14, Ts 0.33 s, Sa(0.5 s) 1.07 g, M 6.9:
    # P(D = 0) = 0, ln D = 3.77, 16 % / 84 % about 20 / 80 cm
    r = empirical.bray_travasarou_2007(0.14, 0.33, 1.07, 6.9)
    assert math.log(r.disp_cm) == pytest.approx(3.77, abs=0.005)
    assert round(r.p_zero, 2) == 0.0
    assert 20 <= r.d16_cm <= 25 and 80 <= r.d84_cm <= 85
    assert (r.sigma, r.log_base) == (0.66, "ln")
    # A 30 m fill (worked by hand from the same equations): ky 0.14, Ts 0.4 s,
    # Sa(0.6 s) 0.48 g, M 7.2: P(D = 0) = 0.01, ln D = 2.29, D about 10 cm, 16-84 % range
    # 5 to 20 cm
    r = empirical.bray_travasarou_2007(0.14, 0.4, 0.48, 7.2)
    assert round(r.p_zero, 2) == 0.01
    assert math.log(r.disp_cm) == pytest.approx(2.29, abs=0.005)
    assert round(r.disp_cm) == 10
    assert round(r.d16_cm) == 5 and round(r.d84_cm) in (19, 20)


def test_bray_travasarou_by_hand():
    lk, ls = math.log(0.1), math.log(0.5)
    lnd = (-1.10 - 2.83 * lk - 0.333 * lk ** 2 + 0.566 * lk * ls + 3.04 * ls - 0.244 * ls ** 2
           + 1.50 * 0.6 + 0.278 * (6.5 - 7.0))
    x = -1.76 - 3.22 * lk - 0.484 * 0.6 * lk + 3.52 * ls
    r = empirical.bray_travasarou_2007(0.1, 0.6, 0.5, 6.5)
    assert r.disp_cm == pytest.approx(math.exp(lnd), rel=1e-13)
    assert r.p_zero == pytest.approx(1.0 - 0.5 * (1.0 + math.erf(x / math.sqrt(2))), abs=1e-15)
    # nearly rigid (Ts < 0.05 s): -0.22, no Ts term, Sa = PGA
    lnd0 = -0.22 - 2.83 * lk - 0.333 * lk ** 2 + 0.566 * lk * ls + 3.04 * ls - 0.244 * ls ** 2
    assert empirical.bray_travasarou_2007(0.1, 0.02, 0.5, 7.0).disp_cm == pytest.approx(
        math.exp(lnd0), rel=1e-13)


def test_rathje_antonakos_by_hand():
    # ky 0.1, Ts 0.3, Tm 0.5 (Ts/Tm = 0.6), PGA 0.4, M 7
    l1 = math.log(6.0)
    kmax = 0.4 * math.exp((0.459 - 0.702 * 0.4) * l1 + (-0.228 + 0.076 * 0.4) * l1 ** 2)
    r = 0.1 / kmax
    lnd = (4.89 - 4.85 * r - 19.64 * r ** 2 + 42.49 * r ** 3 - 29.06 * r ** 4
           + 0.72 * math.log(kmax) + 0.89 * 1.0 + 3.69 * 0.3 - 1.22 * 0.09)
    u = empirical.rathje_antonakos_2011(0.1, 0.3, 0.5, 0.4, magnitude=7.0)
    assert u.kmax == pytest.approx(kmax, rel=1e-14)
    assert u.disp_cm == pytest.approx(math.exp(lnd), rel=1e-13)
    assert u.sigma == pytest.approx(0.694 + 0.322 * r, rel=1e-15)
    assert (u.form, u.kvelmax) == ("pga_m", 0.0)
    # PGA-PGV form, Ts 0.3 (f = 1.42 Ts), PGV 40 cm/s
    l2 = math.log(3.0)
    kvel = 40.0 * math.exp(0.240 * l2 + (-0.091 - 0.171 * 0.4) * l2 ** 2)
    lnd = (-1.56 - 4.58 * r - 20.84 * r ** 2 + 44.75 * r ** 3 - 30.50 * r ** 4
           - 0.64 * math.log(kmax) + 1.55 * math.log(kvel) + 1.42 * 0.3)
    u = empirical.rathje_antonakos_2011(0.1, 0.3, 0.5, 0.4, pgv=40.0)
    assert u.kvelmax == pytest.approx(kvel, rel=1e-14)
    assert u.disp_cm == pytest.approx(math.exp(lnd), rel=1e-13)
    assert u.sigma == pytest.approx(0.400 + 0.284 * r, rel=1e-15)
    # a rigid mass (Ts = 0) is Rathje & Saygili (2009) itself
    u = empirical.rathje_antonakos_2011(0.1, 0.0, 0.5, 0.4, magnitude=7.0)
    assert u.disp_cm == pytest.approx(empirical.rathje_saygili_2009(0.1, 0.4, 7.0).disp_cm,
                                      rel=1e-15)


def test_probability_of_failure_by_hand():
    p = empirical.probability_of_failure([0.0, 5.0, 1e9])
    assert p[0] == 0.0 and p[2] == pytest.approx(0.335, rel=1e-15)
    assert p[1] == pytest.approx(0.335 * (1 - math.exp(-0.048 * 5.0 ** 1.565)), rel=1e-14)


def test_broadcasting():
    r = empirical.jibson_2007_ratio(np.array([[0.05], [0.1]]), np.array([0.2, 0.3, 0.4]))
    assert r.disp_cm.shape == (2, 3) and r.log_base.shape == (2, 3)
    assert r.disp_cm[1, 2] == pytest.approx(empirical.jibson_2007_ratio(0.1, 0.4).disp_cm)


# --- SLAMMER 1.1 at the digits it prints ------------------------------------------------

CASES = [dict(ky=ky, pga=pga, pgv=pgv, ia=ia, m=m)
         for ky in (0.02, 0.05, 0.1, 0.17, 0.3) for pga, pgv, ia in
         ((0.35, 30.0, 1.2), (0.62, 75.0, 4.4), (0.91, 110.0, 9.7))
         for m in (5.5, 7.1)]

FUNCS = {
    "jibson_1993": lambda c: empirical.jibson_1993(c["ia"], c["ky"]),
    "jibson_1998": lambda c: empirical.jibson_1998(c["ia"], c["ky"]),
    "jibson_2007_ratio": lambda c: empirical.jibson_2007_ratio(c["ky"], c["pga"]),
    "jibson_2007_ratio_m": lambda c: empirical.jibson_2007_ratio_m(c["ky"], c["pga"], c["m"]),
    "jibson_2007_arias": lambda c: empirical.jibson_2007_arias(c["ia"], c["ky"]),
    "jibson_2007_arias_ratio": lambda c: empirical.jibson_2007_arias_ratio(c["ia"], c["ky"],
                                                                           c["pga"]),
    "ambraseys_menu_1988": lambda c: empirical.ambraseys_menu_1988(c["ky"], c["pga"]),
    "saygili_rathje_2008_pga": lambda c: empirical.saygili_rathje_2008_pga(c["ky"], c["pga"]),
    "saygili_rathje_2008_pgv": lambda c: empirical.saygili_rathje_2008_pgv(c["ky"], c["pga"],
                                                                           c["pgv"]),
    "saygili_rathje_2008_pgv_arias": lambda c: empirical.saygili_rathje_2008_pgv_arias(
        c["ky"], c["pga"], c["pgv"], c["ia"]),
    "rathje_saygili_2009": lambda c: empirical.rathje_saygili_2009(c["ky"], c["pga"], c["m"]),
}


@pytest.mark.parametrize("name", sorted(FUNCS))
def test_rigid_models_match_slammer(name):
    """Every case prints the same as SLAMMER ('0.0' format) and agrees to 1e-12."""
    for c in CASES:
        ours = FUNCS[name](c).disp_cm
        theirs = slammer_rigid(name, c["ky"], c["pga"], c["pgv"], c["ia"], c["m"])
        assert ours == pytest.approx(theirs, rel=1e-12), (name, c)
        assert fmt(ours, 1) == fmt(theirs, 1), (name, c)


def test_probability_of_failure_matches_slammer():
    for d in (0.0, 0.3, 1.0, 2.5, 7.0, 15.0, 40.0, 200.0):
        theirs = 0.335 * (1.0 - math.exp(-0.048 * d ** 1.565))
        ours = empirical.probability_of_failure(d)
        assert fmt(ours, 3) == fmt(theirs, 3) and ours == pytest.approx(theirs, abs=1e-15)


def test_bray_travasarou_matches_slammer_where_it_is_right():
    """Ts >= 0.05 s and x >= 0 (P(D = 0) <= 1/2): the paper and SLAMMER agree, P(D = 0)
    to the bound of Abramowitz & Stegun 26.2.17 (7.5e-8) and at its printed digits."""
    worst = 0.0
    for ky in (0.02, 0.05, 0.1, 0.2):
        for ts in (0.05, 0.2, 0.5, 1.0, 2.0):
            for sa in (0.3, 0.6, 1.2):
                for m in (6.0, 7.5):
                    d_s, p_s = slammer_bt07(ky, ts, sa, m)
                    x = (-1.76 - 3.22 * math.log(ky) - 0.484 * ts * math.log(ky)
                         + 3.52 * math.log(sa))
                    r = empirical.bray_travasarou_2007(ky, ts, sa, m)
                    assert r.disp_cm == pytest.approx(d_s, rel=1e-13)
                    assert fmt(r.disp_cm, 1) == fmt(d_s, 1)
                    assert fmt(r.disp_cm / 2.54, 1) == fmt(d_s / 2.54, 1)
                    if x >= 0:
                        worst = max(worst, abs(r.p_zero - p_s))
                        assert fmt(r.p_zero, 2) == fmt(p_s, 2)
                    s = empirical.bray_travasarou_2007(ky, ts, sa, m, slammer=True)
                    assert s.p_zero == pytest.approx(p_s, abs=1e-15)
    assert 0 < worst < 7.5e-8


def test_bray_travasarou_slammer_wrong_for_likely_zero():
    """For P(D = 0) > 1/2 (x < 0) SLAMMER's polynomial is outside its domain: with ky 0.3,
    Ts 0.3 s and Sa 0.22 g (x = -3.04) it gives a probability above 1 (1.628), with Sa 0.1 g
    (x = -5.8, past the pole at -1/0.2316419) a negative one; the exact values are
    0.99881... and 0.99999999..."""
    for sa, wrong in ((0.22, lambda p: p > 1.5), (0.1, lambda p: p < 0.0)):
        d_s, p_s = slammer_bt07(0.3, 0.3, sa, 7.0)
        assert wrong(p_s)
        r = empirical.bray_travasarou_2007(0.3, 0.3, sa, 7.0)
        x = -1.76 - 3.22 * math.log(0.3) - 0.484 * 0.3 * math.log(0.3) + 3.52 * math.log(sa)
        assert r.p_zero == pytest.approx(0.5 * math.erfc(x / math.sqrt(2)), rel=1e-14)
        assert 0.998 < r.p_zero < 1.0


def test_doc_example_of_slammer_polynomial(source_root):
    """doc/empirical.md section 5 states x, SLAMMER's value and the exact P(D = 0) of its
    example inputs: the printed digits are those of the inputs it names."""
    text = (source_root / "doc" / "empirical.md").read_text(encoding="utf-8")
    m = re.search(r"at x = (-[\d.]+) \(ky = ([\d.]+), Ts = ([\d.]+) s, Sa = ([\d.]+) g\)"
                  r"\s+it gives ([\d.]+) instead of ([\d.]+)", text)
    assert m, "the example sentence of doc/empirical.md section 5"
    x_doc, ky, ts, sa, slam_doc, exact_doc = (float(v) for v in m.groups())
    x = -1.76 - 3.22 * math.log(ky) - 0.484 * ts * math.log(ky) + 3.52 * math.log(sa)
    decimals = lambda s: len(s.split(".")[1]) if "." in s else 0
    assert round(x, decimals(m.group(1))) == x_doc
    p_slammer = slammer_bt07(ky, ts, sa, 7.0)[1]
    assert round(p_slammer, decimals(m.group(5))) == slam_doc
    exact = 0.5 * math.erfc(x / math.sqrt(2))
    assert round(exact, decimals(m.group(6))) == exact_doc
    assert empirical.bray_travasarou_2007(ky, ts, sa, 7.0, slammer=True).p_zero == \
        pytest.approx(p_slammer, rel=1e-14)


def test_unified_matches_slammer():
    for ky in (0.05, 0.1, 0.2):
        for ts in (0.0, 0.04, 0.3, 0.7, 1.2, 2.0, 6.0):
            for pga in (0.15, 0.4, 0.8):
                for tm in (0.3, 0.6):
                    for method, kw in ((2009, dict(magnitude=6.8)), (2008, dict(pgv=45.0))):
                        kmax, kvel, disp, flex = slammer_unified(ky, ts, 6.8, pga, 45.0, tm,
                                                                 method)
                        if not ky < kmax:
                            continue   # SLAMMER takes the log of a polynomial beyond its range
                        u = empirical.rathje_antonakos_2011(ky, ts, tm, pga, slammer=True, **kw)
                        assert u.kmax == pytest.approx(kmax, rel=1e-14)
                        assert u.kvelmax == pytest.approx(kvel, rel=1e-14)
                        assert u.disp_rigid_cm == pytest.approx(disp, rel=1e-12)
                        assert u.disp_cm == pytest.approx(flex, rel=1e-12, abs=1e-300)
                        for ours, theirs in ((u.kmax, kmax), (u.disp_rigid_cm, disp),
                                             (u.disp_cm, flex), (u.disp_cm / 2.54, flex / 2.54)):
                            assert fmt(ours, 3) == fmt(theirs, 3)
                        if ts / tm <= 8.0 and ky <= pga:
                            # below SLAMMER's cap and its ky > PGA rule: the paper's result
                            p = empirical.rathje_antonakos_2011(ky, ts, tm, pga, **kw)
                            assert p.disp_cm == u.disp_cm


# --- bad input -------------------------------------------------------------------------

@pytest.mark.parametrize("call, name", [
    (lambda: empirical.jibson_2007_ratio(0.3, 0.2), "ky"),
    (lambda: empirical.ambraseys_menu_1988(0.1, float("nan")), "pga"),
    (lambda: empirical.jibson_1993(0.0, 0.1), "arias"),
    (lambda: empirical.jibson_1998(1.0, -0.1), "ky"),
    (lambda: empirical.saygili_rathje_2008_pgv(0.1, 0.3, -5.0), "pgv"),
    (lambda: empirical.rathje_saygili_2009(0.1, 0.3, 11.0), "magnitude"),
    (lambda: empirical.bray_travasarou_2007(0.1, -0.2, 0.5, 7.0), "ts"),
    (lambda: empirical.bray_travasarou_2007(0.1, 0.2, 0.0, 7.0), "sa"),
    (lambda: empirical.rathje_antonakos_2011(0.1, 0.2, 0.0, 0.4, magnitude=7.0), "tm"),
    (lambda: empirical.rathje_antonakos_2011(0.1, 0.2, 0.5, 0.4), "magnitude, pgv"),
    (lambda: empirical.rathje_antonakos_2011(0.1, 0.2, 0.5, 0.4, magnitude=7, pgv=30),
     "magnitude, pgv"),
    (lambda: empirical.probability_of_failure(-1.0), "disp_cm"),
    (lambda: empirical.bray_travasarou_2007(0.1, 0.2, 0.5, 7.0, slammer="yes"), "slammer"),
    (lambda: empirical.jibson_2007_ratio([0.1, 0.2], [0.3, 0.4, 0.5]), "shapes"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(InvalidInputError) as info:
        call()
    assert str(info.value).startswith(name)


def test_readme_example(source_root, capsys):
    """The example of the README's section "Empirical displacement models" prints what its
    comments say."""
    text = (source_root / "README.md").read_text(encoding="utf-8")
    section = text[text.index("\n## Empirical displacement models\n"):]
    code = section[section.index("```python\n") + 10:section.index("\n```\n")]
    exec(compile(code, "README.md (Empirical displacement models)", "exec"), {})
    printed = capsys.readouterr().out.splitlines()
    stated = [line[2:] for line in code.splitlines() if line.startswith("# ")
              and not line.startswith("# a 30 m fill")]
    assert len(printed) == 4 and len(stated) == 4
    for out, claim in zip(printed, stated):
        assert claim.startswith(out), (out, claim)


@pytest.mark.parametrize("call, start", [
    (lambda: empirical.rathje_antonakos_2011([0.1, 0.1], [0.3, 0.3], [0.5, -1], 0.4,
                                             magnitude=7), "tm[1] = -1"),
    (lambda: empirical.jibson_2007_ratio([[0.1], [0.2]], [0.3, 0.15, 0.5]),
     "ky[1, 0] = 0.2: ky/pga"),
    (lambda: empirical.jibson_1993([1.0, 2.0, 3.0, -4.0, 5.0], 0.1), "arias[3] = -4"),
    (lambda: empirical.bray_travasarou_2007(0.1, 0.2, [0.5, 0.6], [7.0, 12.0]),
     "magnitude[1] = 12"),
    (lambda: empirical.probability_of_failure([1.0, np.nan]), "disp_cm[1] = NaN"),
    (lambda: empirical.jibson_1993([1.0, 2.0], -0.1), "ky = -0.1"),
])
def test_broadcast_errors_name_the_element(call, start):
    """An element out of range is named by its index in the argument passed (a single
    value, the same for every element, by its bare name)."""
    with pytest.raises(InvalidInputError) as info:
        call()
    assert str(info.value).startswith(start), str(info.value)
