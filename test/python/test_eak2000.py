"""EAK 2000 spectra (codes.eak2000_spectrum, codes.eak2000_parameters) against values
computed here: the check table of doc/eak2000.md (4 digits), the closed forms (K.1)-(K.3)
written out in numpy, left/right limits at T1 and T2 (np.nextafter), eta at 2..20 %,
the elastic spectrum, the optional floor and eta limit, the zone maps, the importance
categories, and every bad input (InvalidInputError naming the parameter)."""

import math

import numpy as np
import pytest

from seispulse import InvalidInputError, codes

T_TABLE = [0.0, 0.1, 0.2, 0.5, 1.0, 2.0, 3.0]
#: doc/eak2000.md check table: alpha 0.24, gamma_I = eta = theta = 1, q = 3.5 (g)
TABLE = {
    "A": [0.2400, 0.1714, 0.1714, 0.1477, 0.0931, 0.0586, 0.0447],
    "B": [0.2400, 0.1943, 0.1714, 0.1714, 0.1220, 0.0768, 0.0586],
    "C": [0.2400, 0.2057, 0.1714, 0.1714, 0.1477, 0.0931, 0.0710],
    "D": [0.2400, 0.2057, 0.1714, 0.1714, 0.1714, 0.1220, 0.0931],
}
#: T1, T2 (s), transcribed from doc/eak2000.md
CORNERS = {"A": (0.10, 0.40), "B": (0.15, 0.60), "C": (0.20, 0.80), "D": (0.20, 1.20)}


def phi_ref(t, alpha, ground, gamma_i=1.0, q=1.0, theta=1.0, xi=5.0, eta_min=0.0,
            lower_bound=0.0, p=2.0 / 3.0):
    """(K.1)-(K.3), (K.5) written out here."""
    t1, t2 = CORNERS[ground]
    eta = max(math.sqrt(7.0 / (2.0 + xi)), eta_min)
    a = gamma_i * alpha
    plateau = a * eta * theta * 2.5 / q
    t = np.asarray(t, dtype=float)
    out = np.where(t <= t1, a + (plateau - a) * t / t1,
                   np.where(t <= t2, plateau, plateau * (t2 / np.maximum(t, t2)) ** p))
    return np.maximum(out, lower_bound * a)


@pytest.mark.parametrize("ground", list(TABLE))
def test_check_table(ground):
    got = codes.eak2000_spectrum(T_TABLE, zone="Z2", ground=ground, q=3.5)
    assert got.shape == (7,)
    # compared at the table's 4-digit rounding
    assert np.array_equal(np.round(got * 1e4).astype(int),
                          np.round(np.array(TABLE[ground]) * 1e4).astype(int))


@pytest.mark.parametrize("ground", list(TABLE))
@pytest.mark.parametrize("gamma_i,q,theta,damping", [(1.0, 1.0, 1.0, 0.05),
                                                     (1.3, 2.0, 0.8, 0.02),
                                                     (0.85, 4.5, 0.9, 0.12)])
def test_closed_forms(ground, gamma_i, q, theta, damping):
    t = np.array([0.0, 0.03, 0.1, 0.17, 0.35, 0.7, 1.3, 4.0, 10.0])
    got = codes.eak2000_spectrum(t, alpha=0.36, ground=ground, importance=gamma_i, q=q,
                                 theta=theta, damping=damping)
    ref = phi_ref(t, 0.36, ground, gamma_i, q, theta, 100 * damping)
    np.testing.assert_allclose(got, ref, rtol=4e-15, atol=0)


def test_zero_plateau_and_shapes():
    for imp, gi in [("I", 0.85), ("II", 1.0), ("III", 1.15), ("IV", 1.3), ("Σ4", 1.3),
                    ("σ3", 1.15), (1.2, 1.2)]:
        assert codes.eak2000_spectrum(0.0, zone="Z3", importance=imp, q=3.0) == \
            pytest.approx(gi * 0.36, rel=1e-15)
        t1, t2 = CORNERS["C"]
        plateau = gi * 0.36 * 2.5 * 0.9 / 3.0
        got = codes.eak2000_spectrum([0.5 * (t1 + t2), t2], zone="Z3", ground="C",
                                     importance=imp, q=3.0, theta=0.9)
        np.testing.assert_allclose(got, [plateau, plateau], rtol=2e-15)
    assert isinstance(codes.eak2000_spectrum(0.3), float)
    assert codes.eak2000_spectrum(np.full((2, 3), 0.3)).shape == (2, 3)


@pytest.mark.parametrize("ground", list(TABLE))
def test_continuity_at_corners(ground):
    for tc in CORNERS[ground]:
        t = [np.nextafter(tc, 0.0), tc, np.nextafter(tc, 10.0)]
        for kind, kw in (("design", dict(q=2.0, theta=0.9)),
                         ("elastic", dict(elastic_exponent=1.0))):
            v = codes.eak2000_spectrum(t, ground=ground, damping=0.03, kind=kind, **kw)
            assert v[0] == pytest.approx(v[1], rel=1e-14)
            assert v[2] == pytest.approx(v[1], rel=1e-14)


def test_eta():
    for xi, eta4 in [(2, 1.3229), (5, 1.0000), (10, 0.7638), (15, 0.6417), (20, 0.5641)]:
        eta = codes.eak2000_parameters(damping=xi / 100).eta
        assert round(eta, 4) == eta4
        assert eta == pytest.approx(math.sqrt(7 / (2 + xi)), rel=1e-15)
    assert codes.eak2000_parameters(damping=0.05).eta == 1.0
    # eta_min acts only where sqrt(7/(2 + xi)) is below it
    assert codes.eak2000_parameters(damping=0.10, eta_min=0.7).eta == \
        pytest.approx(math.sqrt(7 / 12), rel=1e-15)
    assert codes.eak2000_parameters(damping=0.20, eta_min=0.7).eta == 0.7
    t = [0.0, 0.3, 2.0]
    assert np.array_equal(codes.eak2000_spectrum(t, damping=0.05, eta_min=0.7),
                          codes.eak2000_spectrum(t, damping=0.05))
    np.testing.assert_allclose(codes.eak2000_spectrum(t, damping=0.2, eta_min=0.7),
                               phi_ref(t, 0.24, "B", xi=20, eta_min=0.7), rtol=2e-15)
    assert codes.eak2000_spectrum(0.3, damping=0.2, eta_min=0.7) > \
        codes.eak2000_spectrum(0.3, damping=0.2)


def test_parameters():
    p = codes.eak2000_parameters()
    assert p == codes.EakParameters(0.24, 1.0, 1.0, 0.15, 0.60, 2.5)
    p = codes.eak2000_parameters(zone="IV", ground="D", importance="III", damping=0.1,
                                 zone_map="2000")
    assert (p.alpha, p.gamma_i, p.t1, p.t2, p.beta0) == (0.36, 1.15, 0.20, 1.20, 2.5)
    # alpha with the default zone 'Z2' (indistinguishable from no zone): alpha is used
    assert codes.eak2000_parameters(alpha=0.3).alpha == 0.3
    assert codes.eak2000_parameters(alpha=0.3, zone="Z2").alpha == 0.3
    assert codes.eak2000_parameters(alpha=0.3, zone_map="2000").alpha == 0.3


@pytest.mark.parametrize("fun", [codes.eak2000_spectrum, codes.eak2000_parameters])
def test_zone_and_alpha_not_both(fun):
    """alpha with a zone other than the default is refused; an invalid zone is refused as
    such even with alpha."""
    args = (0.3,) if fun is codes.eak2000_spectrum else ()
    for zone, zone_map in (("Z3", "2003"), ("Z1", "2003"), (2, "2003"), ("IV", "2000")):
        with pytest.raises(InvalidInputError,
                           match=rf"^zone = {zone!r} and alpha = 0.3: give zone or alpha, "
                                 r"not both"):
            fun(*args, zone=zone, zone_map=zone_map, alpha=0.3)
    with pytest.raises(InvalidInputError, match=r"^zone = 'nonsense': unknown zone"):
        fun(*args, zone="nonsense", alpha=0.3)
    with pytest.raises(InvalidInputError, match=r"^zone = 'IV': unknown zone of the 2003 map"):
        fun(*args, zone="IV", alpha=0.3)


def test_zone_maps():
    assert codes.EAK_ZONES_2003 == {"Z1": 0.16, "Z2": 0.24, "Z3": 0.36}
    assert codes.EAK_ZONES_2000 == {"I": 0.12, "II": 0.16, "III": 0.24, "IV": 0.36}
    assert codes.EAK_GROUNDS == ("A", "B", "C", "D")
    assert codes.EAK_IMPORTANCE == {"I": 0.85, "II": 1.0, "III": 1.15, "IV": 1.30}
    for i, (name, a) in enumerate(codes.EAK_ZONES_2003.items(), start=1):
        assert codes.eak2000_parameters(zone=name).alpha == a
        assert codes.eak2000_parameters(zone=i, zone_map="2003").alpha == a
        assert codes.eak2000_spectrum(0.0, zone=name) == a
    for i, (name, a) in enumerate(codes.EAK_ZONES_2000.items(), start=1):
        assert codes.eak2000_parameters(zone=name, zone_map="2000").alpha == a
        assert codes.eak2000_parameters(zone=i, zone_map="2000").alpha == a
    for name, gi in codes.EAK_IMPORTANCE.items():
        assert codes.eak2000_parameters(importance=name).gamma_i == gi
    for name in ("eak2000_spectrum", "eak2000_parameters", "EAK_ZONES_2003", "EAK_ZONES_2000",
                 "EAK_GROUNDS", "EAK_IMPORTANCE"):
        assert name in codes.__all__


@pytest.mark.parametrize("ground", list(TABLE))
def test_elastic(ground):
    t = np.array([0.0, 0.05, 0.15, 0.4, 0.6, 0.9, 2.0, 5.0])
    design = codes.eak2000_spectrum(t, zone="Z3", ground=ground, importance=1.15,
                                    damping=0.07)
    elastic = codes.eak2000_spectrum(t, zone="Z3", ground=ground, importance=1.15,
                                     damping=0.07, kind="elastic")
    assert np.array_equal(design, elastic)
    e1 = codes.eak2000_spectrum(t, zone="Z3", ground=ground, importance=1.15, damping=0.07,
                                kind="elastic", elastic_exponent=1.0)
    np.testing.assert_allclose(e1, phi_ref(t, 0.36, ground, 1.15, xi=7, p=1.0), rtol=2e-15)
    t2 = CORNERS[ground][1]
    assert np.array_equal(e1[t <= t2], design[t <= t2])
    assert np.all(e1[t > t2] < design[t > t2])


def test_lower_bound():
    for ground in TABLE:
        base = codes.eak2000_spectrum(T_TABLE, ground=ground, q=3.5)
        floored = codes.eak2000_spectrum(T_TABLE, ground=ground, q=3.5, lower_bound=0.25)
        below = base < 0.06
        np.testing.assert_allclose(floored[below], 0.06, rtol=1e-15)
        assert np.array_equal(floored[~below], base[~below])
    # soil A floored at 2 and 3 s, soil B at 3 s only
    a = codes.eak2000_spectrum([1.0, 2.0, 3.0], ground="A", q=3.5, lower_bound=0.25)
    assert a[0] > 0.06 and a[1] == pytest.approx(0.06) and a[2] == pytest.approx(0.06)
    b = codes.eak2000_spectrum([2.0, 3.0], ground="B", q=3.5, lower_bound=0.25)
    assert b[0] > 0.06 and b[1] == pytest.approx(0.06)
    # the crossings quoted in doc/eak2000.md section 5 (1.9318 s for A, 2.8977 s for B),
    # bracketed by the library: (K.3) governs 1e-4 s below, the floor 1e-4 s above
    for ground, tc_doc in (("A", 1.9318), ("B", 2.8977)):
        v = codes.eak2000_spectrum([tc_doc - 1e-4, tc_doc + 1e-4], ground=ground, q=3.5,
                                   lower_bound=0.25)
        assert v[0] > 0.06 and v[1] == 0.06
    # and at T2 (plateau / floor)^(3/2) computed here, to 1e-9
    for ground in ("A", "B"):
        tc = CORNERS[ground][1] * (2.5 / 3.5 / 0.25) ** 1.5
        v = codes.eak2000_spectrum([tc * (1 - 1e-9), tc * (1 + 1e-9)], ground=ground, q=3.5,
                                   lower_bound=0.25)
        assert v[0] > 0.06 and v[1] == pytest.approx(0.06, rel=1e-15)


@pytest.mark.parametrize("kwargs,pattern", [
    (dict(ground="X"), r"^ground = 'X': ground category X calls for a site-specific study "
                       r"\(unverified\); give ground A-D$"),
    (dict(ground="E"), r"^ground = 'E'.*'A', 'B', 'C', 'D'"),
    (dict(zone="Z4"), r"^zone = 'Z4'.*'Z1', 'Z2', 'Z3'"),
    (dict(zone="Z2", zone_map="2000"), r"^zone = 'Z2'.*'I', 'II', 'III', 'IV'"),
    (dict(zone="IV"), r"^zone = 'IV'.*2003"),
    (dict(zone=0), r"^zone = 0"),
    (dict(zone_map="1999"), r"^zone_map = '1999'.*'2003'.*'2000'"),
    (dict(kind="inelastic"), r"^kind = 'inelastic'.*'design', 'elastic'"),
    (dict(q=0.99), r"^q = 0.99.*>= 1"),
    (dict(q=math.nan), r"^q = "),
    (dict(theta=0.0), r"^theta = 0.*\(0, 1\]"),
    (dict(theta=1.2), r"^theta = 1.2.*\(0, 1\]"),
    (dict(alpha=-0.1), r"^alpha = -0.1.*>= 0"),
    (dict(alpha=math.inf), r"^alpha = "),
    (dict(importance="V"), r"^importance = 'V'.*'I', 'II', 'III', 'IV'"),
    (dict(importance=0.0), r"^importance = 0.0.*> 0"),
    (dict(importance=True), r"^importance = True"),
    (dict(damping=-0.01), r"^damping = -0.01.*RATIO"),
    (dict(damping=5.0), r"^damping = 5.0.*RATIO"),
    (dict(eta_min=1.5), r"^eta_min = 1.5.*\[0, 1\]"),
    (dict(lower_bound=-0.1), r"^lower_bound = -0.1.*>= 0"),
    (dict(kind="elastic", q=2.0), r"^q = 2.0: kind = 'elastic'"),
    (dict(kind="elastic", theta=0.9), r"^theta = 0.9: kind = 'elastic'"),
    (dict(kind="elastic", lower_bound=0.25), r"^lower_bound = 0.25: kind = 'elastic'"),
    (dict(kind="elastic", elastic_exponent=0.0), r"^elastic_exponent = 0.*> 0"),
    (dict(elastic_exponent=1.0), r"^elastic_exponent = 1.0: applies to kind = 'elastic'"),
    (dict(elastic_exponent=2 / 3 + 1e-9), r"^elastic_exponent = 0.66.*kind = 'elastic'"),
    (dict(zone="Z3", alpha=0.2), r"^zone = 'Z3' and alpha = 0.2: give zone or alpha"),
    (dict(q=True), r"^q = True: must be a real number, not a bool"),
    (dict(theta=True), r"^theta = True"),
    (dict(alpha=True), r"^alpha = True"),
    (dict(damping=False), r"^damping = False"),
    (dict(lower_bound=True), r"^lower_bound = True"),
    (dict(eta_min=np.bool_(False)), r"^eta_min = "),
    (dict(kind="elastic", elastic_exponent=True), r"^elastic_exponent = True"),
    (dict(alpha=10.0, importance=1e308), r"^alpha = 10.*the spectrum overflows"),
    (dict(alpha=1e308), r"^alpha = .*the spectrum overflows"),
    (dict(alpha=1e300, lower_bound=1e10), r"^alpha = .*the spectrum overflows"),
])
def test_bad_input(kwargs, pattern):
    with pytest.raises(InvalidInputError, match=pattern):
        codes.eak2000_spectrum([0.1, 0.5], **kwargs)


def test_edge_cases():
    """damping 0 (eta = sqrt(7/2), no cap), alpha 0 (zeros, also with a floor), a huge
    period (tiny but finite and positive), an exponent within 1e-12 of 2/3 for Phi_d."""
    eta0 = math.sqrt(3.5)
    assert codes.eak2000_parameters(damping=0.0).eta == pytest.approx(eta0, rel=1e-15)
    got = codes.eak2000_spectrum([0.0, 0.3, 2.0], damping=0.0)
    np.testing.assert_allclose(got, phi_ref([0.0, 0.3, 2.0], 0.24, "B", xi=0.0), rtol=2e-15)
    assert got[1] == pytest.approx(0.24 * eta0 * 2.5, rel=1e-15)
    for kind, kw in (("design", dict(q=3.0, lower_bound=0.25)), ("elastic", {})):
        z = codes.eak2000_spectrum([0.0, 0.3, 5.0], alpha=0.0, kind=kind, **kw)
        assert np.array_equal(z, [0.0, 0.0, 0.0])
    big = codes.eak2000_spectrum(1e300, q=3.5)
    assert big == pytest.approx(0.24 * 2.5 / 3.5 * (0.6 / 1e300) ** (2 / 3), rel=1e-13)
    assert math.isfinite(big) and big > 0.0
    t = [0.1, 0.5, 3.0]
    assert np.array_equal(codes.eak2000_spectrum(t, elastic_exponent=1 - 1 / 3),
                          codes.eak2000_spectrum(t))
    np.testing.assert_allclose(codes.eak2000_spectrum(t, kind="elastic", elastic_exponent=0.3),
                               phi_ref(t, 0.24, "B", p=0.3), rtol=2e-15)


@pytest.mark.parametrize("periods,pattern", [
    ([0.1, -0.5], r"^periods\[1\] = -0.5: the period \(s\) must be finite and >= 0"),
    ([math.nan], r"^periods\[0\] = NaN"),
    (["a"], r"^periods: must be a real number"),
    ([True, False], r"^periods: .*not bools"),
])
def test_bad_periods(periods, pattern):
    with pytest.raises(InvalidInputError, match=pattern):
        codes.eak2000_spectrum(periods)


@pytest.mark.parametrize("kwargs,pattern", [
    (dict(ground="X"), r"^ground = 'X'"),
    (dict(zone="Z9"), r"^zone = 'Z9'"),
    (dict(importance="Σ5"), r"^importance = 'Σ5'"),
    (dict(damping=1.0), r"^damping = 1.0"),
    (dict(eta_min=-1.0), r"^eta_min = -1.0"),
    (dict(zone_map=2001), r"^zone_map = 2001"),
])
def test_bad_parameters(kwargs, pattern):
    with pytest.raises(InvalidInputError, match=pattern):
        codes.eak2000_parameters(**kwargs)
