"""seispulse.codes (Fortran seispulse_codes, EN 1998 earth-pressure checks and spectra)
against computations that do not use the library:

* a brute-force planar-wedge search written here (limit equilibrium of the soil wedge
  over the angle of its failure plane, wall reaction at delta to the wall normal,
  gravity g (1 - kv), inertia kh g; scipy's bounded minimiser refines the best grid
  point) for the active (E.2) and the passive coefficient on a grid psi = 80..110,
  beta = -25..25, delta = 0 and 2/3 phi, kh = 0, 0.2, kv = -0.1, 0.1, phi = 30, 38.
  Result (recorded in src/seispulse/codes/codes.f90): E.2 and the passive form
  sin^2(psi + theta - phi_d) / {cos(theta) sin^2(psi) sin(psi + theta + delta_d)
  [1 - sqrt(sin(phi_d + delta_d) sin(phi_d + beta - theta) / (sin(psi + beta)
  sin(psi + theta + delta_d)))]^2} match the wedge to 1e-9 wherever they are defined;
  where the library reports no solution the wedge has none either; the transcribed E.4
  numerator sin^2(psi + phi_d - theta) misses it for psi != 90;
* the published check (xc / eurocodeapplied.com), Coulomb's textbook forms (Das) and
  Rankine's sloping-backfill forms at kh = kv = 0;
* the water cases, Westergaard's resultant by scipy quadrature, the rigid-wall rules;
* EN 1998-1 spectra transcribed again here, at and between the corner periods;
* bad input (messages name the parameter).
"""
import math
import warnings

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import minimize_scalar

from seispulse import InvalidInputError, NoSolutionError
from seispulse import codes as C

RAD = math.pi / 180.0


# ------------------------------------------------------------------ planar wedge

def wedge_force(rho, psi_deg, beta_deg, phi_deg, delta_deg, kh, kv, passive):
    """Wall force P / (gamma H^2) and soil reaction R / (gamma H^2) on a planar wedge with
    failure plane at angle rho (rad) to the horizontal, heel at the origin, backfill on
    +x, back face at a = 180 - psi from +x, top at height 1."""
    a = (180.0 - psi_deg) * RAD
    beta, phi, delta = beta_deg * RAD, phi_deg * RAD, delta_deg * RAD
    rho = np.asarray(rho, dtype=float)
    weight = 0.5 * math.sin(a - beta) * np.sin(a - rho) / (math.sin(a) ** 2 * np.sin(rho - beta))
    sg = -1.0 if passive else 1.0        # friction up the wall / down the plane when active
    t = np.array([math.cos(a), math.sin(a)])
    n = np.array([t[1], -t[0]])          # wall normal into the soil
    p_dir = math.cos(delta) * n + sg * math.sin(delta) * t
    u = np.array([np.cos(rho), np.sin(rho)])
    m = np.array([-np.sin(rho), np.cos(rho)])
    q_dir = math.cos(phi) * m + sg * math.sin(phi) * u
    f = np.array([kh if passive else -kh, -(1.0 - kv)])
    pq = p_dir[0] * q_dir[1] - p_dir[1] * q_dir[0]
    p = -weight * (f[0] * q_dir[1] - f[1] * q_dir[0]) / pq
    r = -weight * (p_dir[0] * f[1] - p_dir[1] * f[0]) / pq
    return p, r


def wedge_k(phi_deg, kh, kv, delta_deg, psi_deg, beta_deg, passive, n=4001):
    """K = 2 P / (1 - kv) of the critical planar wedge (max P active, min P passive), or
    None when there is no interior extremum with P > 0 and R > 0 (active: P grows without
    bound towards the slope; passive: the wedge slides with P <= 0, or nothing is valid)."""
    a = (180.0 - psi_deg) * RAD
    beta = beta_deg * RAD
    rho = np.linspace(beta, a, n + 2)[1:-1]
    with np.errstate(divide="ignore", invalid="ignore"):
        p, r = wedge_force(rho, psi_deg, beta_deg, phi_deg, delta_deg, kh, kv, passive)
    valid = (r > 0) & np.isfinite(p)
    sg = 1.0 if passive else -1.0
    if passive and np.any(valid & (p <= 0)):
        return None
    valid &= p > 0
    if not valid.any():
        return None
    i = int(np.argmin(np.where(valid, sg * p, np.inf)))
    if i in (0, n - 1) or not (valid[i - 1] and valid[i + 1]):
        return None
    res = minimize_scalar(lambda x: sg * float(wedge_force(x, psi_deg, beta_deg, phi_deg,
                                                           delta_deg, kh, kv, passive)[0]),
                          bounds=(rho[i - 1], rho[i + 1]), method="bounded",
                          options={"xatol": 1e-14})
    return 2.0 * sg * res.fun / (1.0 - kv)


GRID = [(phi, delta_frac, beta, kh, kv)
        for phi in (30.0, 38.0) for delta_frac in (0.0, 2.0 / 3.0)
        for beta in (-25.0, -15.0, 0.0, 10.0, 25.0) for kh in (0.0, 0.2) for kv in (-0.1, 0.1)]


@pytest.mark.parametrize("passive", [False, True])
@pytest.mark.parametrize("psi", [30.0, 35.0, 80.0, 90.0, 100.0, 110.0])
def test_mononobe_okabe_matches_wedge_search(psi, passive):
    solved = 0
    for phi, delta_frac, beta, kh, kv in GRID:
        delta = delta_frac * phi
        ref = wedge_k(phi, kh, kv, delta, psi, beta, passive)
        try:
            k = C.mononobe_okabe(phi, kh, kv, delta, psi, beta, passive=passive).k
        except NoSolutionError:
            assert ref is None, (phi, delta, beta, kh, kv)
            continue
        assert ref is not None, (phi, delta, beta, kh, kv)
        assert k == pytest.approx(ref, rel=1e-9), (phi, delta, beta, kh, kv)
        solved += 1
    assert solved >= len(GRID) // 2      # the grid is mostly inside the domain


@pytest.mark.parametrize("psi", [30.0, 39.9, 40.0, 40.1])
def test_passive_back_flatter_than_phi(psi):
    """psi + theta <= phi: the square root of E.4 reaches or passes 1, yet K is finite and
    continuous (Coulomb, static, phi = 40); the wedge search and Das agree."""
    k = C.mononobe_okabe(40.0, 0.0, 0.0, 0.0, psi, 0.0, passive=True).k
    assert k == pytest.approx(wedge_k(40.0, 0.0, 0.0, 0.0, psi, 0.0, True), rel=1e-9)
    if psi != 40.0:                      # Das's form is 0/0 at psi = phi
        assert k == pytest.approx(das_coulomb(40.0, 0.0, psi, 0.0, True), rel=1e-12)


def transcribed_e4(phi, kh, kv, psi, beta):
    """E.4 as transcribed (delta = 0): numerator sin^2(psi + phi - theta)."""
    th = math.atan(kh / (1 - kv))
    phi, psi, beta = phi * RAD, psi * RAD, beta * RAD
    root = math.sqrt(math.sin(phi) * math.sin(phi + beta - th)
                     / (math.sin(psi + beta) * math.sin(psi + th)))
    return math.sin(psi + phi - th) ** 2 / (math.cos(th) * math.sin(psi) ** 2
                                            * math.sin(psi + th) * (1 - root) ** 2)


def test_transcribed_e4_differs_off_vertical():
    # vertical wall: the two numerators agree, and both match the wedge
    k90 = C.mononobe_okabe(30, 0.2, 0.0, psi_deg=90, passive=True).k
    assert k90 == pytest.approx(transcribed_e4(30, 0.2, 0.0, 90, 0), rel=1e-13)
    assert k90 == pytest.approx(wedge_k(30, 0.2, 0.0, 0.0, 90, 0, True), rel=1e-9)
    # psi = 80: the wedge (independent value: 2.27405) rejects the printed numerator (2.88765)
    ref = wedge_k(30, 0.2, 0.0, 0.0, 80, 0, True)
    k80 = C.mononobe_okabe(30, 0.2, 0.0, psi_deg=80, passive=True).k
    assert k80 == pytest.approx(ref, rel=1e-9)
    assert k80 == pytest.approx(2.27405, rel=1e-5)
    assert transcribed_e4(30, 0.2, 0.0, 80, 0) == pytest.approx(2.88765, rel=1e-5)


# ------------------------------------------------------------------ published, textbook

def test_published_check():
    mo = C.mononobe_okabe(30.0, 0.24, -0.12)
    assert mo.theta == pytest.approx(0.2110933332227465, rel=1e-12)
    assert mo.k == pytest.approx(0.4856177257638489, rel=1e-12)
    kpd = C.mononobe_okabe(30.0, 0.24, -0.12, passive=True).k
    assert kpd == pytest.approx(2.6, rel=1e-3)           # xc's tolerance
    assert kpd == pytest.approx(2.600280, rel=2e-7)
    # the other sign of kv (independent values: theta = 0.2662520, K = 0.5407058)
    mo = C.mononobe_okabe(30.0, 0.24, 0.12)
    assert mo.theta == pytest.approx(0.2662520, rel=1e-6)
    assert mo.k == pytest.approx(0.5407058, rel=1e-6)


def das_coulomb(phi, delta, psi, beta, passive):
    """Das (Principles of Foundation Engineering), wall back at alpha = 90 - psi from the
    vertical, backfill slope beta, wall friction delta (degrees)."""
    phi, delta, al, beta = phi * RAD, delta * RAD, (90 - psi) * RAD, beta * RAD
    if not passive:
        root = math.sqrt(math.sin(delta + phi) * math.sin(phi - beta)
                         / (math.cos(delta + al) * math.cos(al - beta)))
        return math.cos(phi - al) ** 2 / (math.cos(al) ** 2 * math.cos(delta + al)
                                          * (1 + root) ** 2)
    root = math.sqrt(math.sin(phi + delta) * math.sin(phi + beta)
                     / (math.cos(delta - al) * math.cos(beta - al)))
    return math.cos(phi + al) ** 2 / (math.cos(al) ** 2 * math.cos(delta - al) * (1 - root) ** 2)


@pytest.mark.parametrize("phi,delta,psi,beta", [(30, 0, 90, 0), (34, 20, 85, 12),
                                                (28, 18, 100, -8), (40, 20, 95, 15)])
@pytest.mark.parametrize("passive", [False, True])
def test_static_limit_is_coulomb(phi, delta, psi, beta, passive):
    mo = C.mononobe_okabe(phi, 0.0, 0.0, delta, psi, beta, passive=passive)
    assert mo.theta == 0.0
    assert mo.k == pytest.approx(das_coulomb(phi, delta, psi, beta, passive), rel=1e-13)


def test_rankine():
    assert C.mononobe_okabe(30, 0, 0).k == pytest.approx(1 / 3, rel=1e-14)
    assert C.mononobe_okabe(30, 0, 0, passive=True).k == pytest.approx(3.0, rel=1e-14)
    cb, cf = math.cos(20 * RAD), math.cos(30 * RAD)
    root = math.sqrt(cb * cb - cf * cf)
    assert C.mononobe_okabe(30, 0, 0, delta_deg=20, beta_deg=20).k == pytest.approx(
        cb * (cb - root) / (cb + root), rel=1e-13)
    assert C.mononobe_okabe(30, 0, 0, delta_deg=20, beta_deg=-20, passive=True).k == \
        pytest.approx(cb * (cb + root) / (cb - root), rel=1e-13)


def test_gamma_phi():
    phid = math.atan(math.tan(32 * RAD) / 1.25) / RAD
    deltad = math.atan(math.tan(20 * RAD) / 1.25) / RAD
    k = C.mononobe_okabe(32, 0.15, -0.05, 20, 95, 5, gamma_phi=1.25).k
    assert k == pytest.approx(C.mononobe_okabe(phid, 0.15, -0.05, deltad, 95, 5).k, rel=1e-13)
    assert k > C.mononobe_okabe(32, 0.15, -0.05, 20, 95, 5).k


# ------------------------------------------------------------------ no solution

def test_beyond_limit():
    with pytest.raises(NoSolutionError, match=r"^beta_deg = 25\.0: .*no finite active thrust"):
        C.mononobe_okabe(30, 0.24, -0.12, 10, 95, 25)
    mo = C.mononobe_okabe(30, 0.24, -0.12, 10, 95, 25, beyond_limit="en1998")
    th = math.atan(0.24 / 1.12)
    e3 = math.sin(95 * RAD + 30 * RAD - th) ** 2 / (
        math.cos(th) * math.sin(95 * RAD) ** 2 * math.sin(95 * RAD - th - 10 * RAD))
    assert mo.theta == pytest.approx(th, rel=1e-15)
    assert mo.k == pytest.approx(e3, rel=1e-14)
    # the wedge: P grows without bound as the plane approaches the backfill slope
    p, r = wedge_force(25 * RAD + 1e-7, 95, 25, 30, 10, 0.24, -0.12, False)
    assert r > 0 and p > 1e4
    # E.2 tends to E.3 at the limit
    limit = 30 - th / RAD
    assert C.mononobe_okabe(30, 0.24, -0.12, 10, 95, limit - 1e-9).k == pytest.approx(e3, rel=1e-4)
    # 'en1998' does not cover the other failures
    with pytest.raises(NoSolutionError, match=r"^beta_deg = -20"):
        C.mononobe_okabe(25, 0.3, 0.0, beta_deg=-20, passive=True, beyond_limit="en1998")
    with pytest.raises(NoSolutionError, match=r"^psi_deg = 20"):
        C.mononobe_okabe(30, 0.1, 0.0, 15, 20, 0, beyond_limit="en1998")


@pytest.mark.parametrize("args,passive,start", [
    ((30, 0.1, 0.0, 15, 20, 0), False, "psi_deg = 20"),       # psi - theta - delta <= 0
    ((30, 0.0, 0.0, 0, 160, 0), False, "psi_deg = 160"),      # overhang: psi + phi >= 180
    ((25, 0.3, 0.0, 0, 90, -20), True, "beta_deg = -20"),     # ground in front slides
    ((45, 0.0, 0.0, 45, 90, 0), True, "psi_deg = 90"),        # psi + phi + delta = 180
    ((30, 0.0, 0.0, 15, 170, 0), True, "psi_deg = 170"),      # psi + theta + delta >= 180
])
def test_no_solution_branches(args, passive, start):
    with pytest.raises(NoSolutionError, match="^" + start):
        C.mononobe_okabe(*args, passive=passive)
    assert wedge_k(*args, passive) is None      # no critical wedge either


def test_passive_near_unbounded():
    # phi = delta = 44.9: the square root is just below 1, K is large and still the wedge's
    k = C.mononobe_okabe(44.9, 0.0, 0.0, 44.9, passive=True).k
    assert k > 1e5
    assert k == pytest.approx(wedge_k(44.9, 0.0, 0.0, 44.9, 90, 0, True), rel=1e-9)


# ------------------------------------------------------------------ coefficients

def test_seismic_coefficients():
    kh, kv = C.seismic_coefficients(0.24, 1.2, 2.0, spectrum_type=1)
    assert kh == pytest.approx(0.144, rel=1e-15) and kv == pytest.approx(0.072, rel=1e-15)
    kh, kv = C.seismic_coefficients(0.24, 1.2, 2.0, spectrum_type=2)
    assert kv == pytest.approx(0.33 * 0.144, rel=1e-15)
    assert C.seismic_coefficients(0.3, 1.0) == pytest.approx((0.3, 0.15), rel=1e-15)
    assert C.vertical_ratio(1) == 0.9 and C.vertical_ratio(2) == 0.45
    assert [C.r_factor(w) for w in C.WALL_TYPES] == [2.0, 1.5, 1.0]
    with pytest.raises(InvalidInputError, match="^wall_type = 'cantilever'"):
        C.r_factor("cantilever")
    with pytest.raises(InvalidInputError, match="^r = 0.5"):
        C.seismic_coefficients(0.2, 1.0, 0.5)
    with pytest.raises(InvalidInputError, match="^alpha = -0.2"):
        C.seismic_coefficients(-0.2, 1.0)
    with pytest.raises(InvalidInputError, match="^s = 0"):
        C.seismic_coefficients(0.2, 0.0)
    for bad in (3, True, "1", 1.0):
        with pytest.raises(InvalidInputError, match="^spectrum_type"):
            C.seismic_coefficients(0.2, 1.0, spectrum_type=bad)


@pytest.mark.parametrize("kwargs,start", [
    (dict(phi_deg=0.0), "phi_deg = 0"), (dict(phi_deg=90.0), "phi_deg = 90"),
    (dict(phi_deg=float("nan")), "phi_deg = NaN"), (dict(delta_deg=-1.0), "delta_deg = -1"),
    (dict(delta_deg=31.0), "delta_deg = 31"), (dict(psi_deg=0.0), "psi_deg = 0"),
    (dict(psi_deg=180.0), "psi_deg = 180"), (dict(beta_deg=90.0), "beta_deg = 90"),
    (dict(psi_deg=40.0, beta_deg=-50.0), "beta_deg = -50"), (dict(kh=-0.1), "kh = -0.1"),
    (dict(kh=float("inf")), "kh = "), (dict(kv=1.0), "kv = 1"), (dict(kv=1.5), "kv = 1.5"),
    (dict(gamma_phi=0.9), "gamma_phi = 0.9"), (dict(kh="a"), "kh"),
    (dict(beyond_limit="ignore"), "beyond_limit"), (dict(passive=2), "passive"),
])
def test_mononobe_okabe_bad_input(kwargs, start):
    args = dict(phi_deg=30.0, kh=0.1, kv=0.0)
    args.update(kwargs)
    with pytest.raises(InvalidInputError, match="^" + start):
        C.mononobe_okabe(**args)


# ------------------------------------------------------------------ thrust

def mo_vertical(phi_deg, theta):
    """Vertical wall, flat backfill, delta = 0 (the classical M-O form)."""
    phi = phi_deg * RAD
    return math.cos(phi - theta) ** 2 / (math.cos(theta) ** 2 * (
        1 + math.sqrt(math.sin(phi) * math.sin(phi - theta) / math.cos(theta))) ** 2)


@pytest.mark.parametrize("water", ["dry", "impervious", "permeable"])
@pytest.mark.parametrize("kv", [-0.1, 0.1])
def test_earth_thrust_water_cases(water, kv):
    h, g, gw, gd, kh, phi = 5.0, 20.0, 9.81, 16.5, 0.2, 32.0
    res = C.earth_thrust(h, g, phi, kh, kv, water=water, gamma_w=gw, gamma_d=gd)
    gstar = g if water == "dry" else g - gw
    ratio = {"dry": 1.0, "impervious": g / (g - gw), "permeable": gd / (g - gw)}[water]
    theta = math.atan(ratio * kh / (1 - kv))
    k = mo_vertical(phi, theta)
    ks = (1 - math.sin(phi * RAD)) / (1 + math.sin(phi * RAD))
    es = 0.5 * gstar * (1 - kv) * k * h * h
    est = 0.5 * gstar * ks * h * h
    ews = 0.0 if water == "dry" else 0.5 * gw * h * h
    ewd = 7 / 12 * kh * gw * h * h if water == "permeable" else 0.0
    assert res.theta == pytest.approx(theta, rel=1e-14)
    assert res.k == pytest.approx(k, rel=1e-13)
    assert res.k_static == pytest.approx(ks, rel=1e-14)
    assert res.e_soil == pytest.approx(es, rel=1e-13)
    assert res.e_static == pytest.approx(est, rel=1e-13)
    assert res.e_dynamic == pytest.approx(es - est, rel=1e-12)
    assert res.e_ws == pytest.approx(ews, rel=1e-15, abs=0.0)
    assert res.e_wd == pytest.approx(ewd, rel=1e-15, abs=0.0)
    assert res.total == pytest.approx(es + ews + ewd, rel=1e-13)
    assert (res.z_static, res.z_dynamic, res.z_ws, res.z_wd) == pytest.approx(
        (h / 3, h / 2, h / 3, 0.4 * h), rel=1e-15)
    m = est * h / 3 + (es - est) * h / 2 + ews * h / 3 + ewd * 0.4 * h
    assert res.m_base == pytest.approx(m, rel=1e-13)
    assert res.z_total == pytest.approx(m / (es + ews + ewd), rel=1e-13)


def test_earth_thrust_published_and_errors():
    res = C.earth_thrust(6.0, 20.0, 30.0, 0.24, -0.12)
    assert res.e_soil == pytest.approx(0.5 * 20 * 1.12 * 0.4856177257638489 * 36, rel=1e-12)
    assert res.e_static == pytest.approx(120.0, rel=1e-14)
    with pytest.raises(InvalidInputError, match="^gamma_d"):
        C.earth_thrust(5, 20, 30, 0.2, 0.0, water="permeable")
    with pytest.raises(InvalidInputError, match="^gamma_w = 9.81"):
        C.earth_thrust(5, 9.5, 30, 0.2, 0.0, water="impervious")
    with pytest.raises(InvalidInputError, match="^water = 'wet'"):
        C.earth_thrust(5, 20, 30, 0.2, 0.0, water="wet")
    with pytest.raises(InvalidInputError, match="^height = -5"):
        C.earth_thrust(-5, 20, 30, 0.2, 0.0)
    with pytest.raises(InvalidInputError, match="^gamma = 0"):
        C.earth_thrust(5, 0, 30, 0.2, 0.0)
    with pytest.raises(InvalidInputError, match="^kv = 1"):
        C.earth_thrust(5, 20, 30, 0.2, 1.0)
    # dry at beta = 15 is fine; impervious soil raises theta beyond phi - beta
    C.earth_thrust(5, 20, 30, 0.2, 0.0, beta_deg=15)
    with pytest.raises(NoSolutionError, match=r"^beta_deg = 15.*impervious soil"):
        C.earth_thrust(5, 20, 30, 0.2, 0.0, beta_deg=15, water="impervious")


def test_westergaard():
    kh, gw, h = 0.15, 9.81, 4.0
    z = np.array([[0.0, 1.0], [2.25, 4.0]])
    q = C.westergaard_pressure(kh, gw, h, z)
    assert q.shape == (2, 2)
    np.testing.assert_allclose(q, 0.875 * kh * gw * np.sqrt(h * z), rtol=1e-15)
    assert isinstance(C.westergaard_pressure(kh, gw, h, 1.0), float)
    force = quad(lambda x: C.westergaard_pressure(kh, gw, h, x), 0, h, epsabs=0,
                 epsrel=1e-12)[0]
    moment = quad(lambda x: C.westergaard_pressure(kh, gw, h, x) * (h - x), 0, h, epsabs=0,
                  epsrel=1e-12)[0]
    assert force == pytest.approx(7 / 12 * kh * gw * h * h, rel=1e-10)
    assert moment / force == pytest.approx(0.4 * h, rel=1e-10)
    # the permeable case's hydrodynamic thrust is this resultant
    res = C.earth_thrust(h, 20.0, 30.0, kh, 0.0, water="permeable", gamma_w=gw, gamma_d=16.0)
    assert res.e_wd == pytest.approx(force, rel=1e-10)
    with pytest.raises(InvalidInputError, match=r"^z\[1\] = 4.5"):
        C.westergaard_pressure(kh, gw, h, [0.0, 4.5])
    with pytest.raises(InvalidInputError, match="^h_water = 0"):
        C.westergaard_pressure(kh, gw, 0.0, [0.0])


def test_rigid_wall_rules():
    t = C.rigid_wall_thrust(0.3, 19.0, 7.0)
    assert t == pytest.approx((0.3 * 19 * 49, 3.5), rel=1e-15)
    t = C.seed_whitman(0.2, 19.0, 7.0)
    assert t.thrust == pytest.approx(0.5 * 19 * 49 * 0.75 * 0.2, rel=1e-15)
    assert t.height_of_application == pytest.approx(4.2, rel=1e-15)
    assert C.wood(0.2, 19.0, 7.0) == pytest.approx((0.2 * 19 * 49, 4.2), rel=1e-15)
    with pytest.raises(InvalidInputError, match="^alpha_s = -0.1"):
        C.rigid_wall_thrust(-0.1, 19, 7)
    with pytest.raises(InvalidInputError, match="^height = 0"):
        C.wood(0.2, 19, 0)
    with pytest.raises(InvalidInputError, match="^gamma = -19"):
        C.seed_whitman(0.2, -19, 7)


# ------------------------------------------------------------------ EN 1998-1 spectra

TABLES = {  # (type, ground): S, TB, TC, TD, typed again from EN 1998-1 Tables 3.2/3.3
    (1, "A"): (1.00, 0.15, 0.40, 2.0), (1, "B"): (1.20, 0.15, 0.50, 2.0),
    (1, "C"): (1.15, 0.20, 0.60, 2.0), (1, "D"): (1.35, 0.20, 0.80, 2.0),
    (1, "E"): (1.40, 0.15, 0.50, 2.0),
    (2, "A"): (1.00, 0.05, 0.25, 1.2), (2, "B"): (1.35, 0.05, 0.25, 1.2),
    (2, "C"): (1.50, 0.10, 0.25, 1.2), (2, "D"): (1.80, 0.10, 0.30, 1.2),
    (2, "E"): (1.60, 0.05, 0.25, 1.2),
}


def se_ref(t, ag, s, tb, tc, td, eta):
    if t <= tb:
        return ag * s * (1 + t / tb * (eta * 2.5 - 1))
    if t <= tc:
        return ag * s * eta * 2.5
    if t <= td:
        return ag * s * eta * 2.5 * tc / t
    return ag * s * eta * 2.5 * tc * td / t ** 2


def sd_ref(t, ag, s, tb, tc, td, q, beta):
    if t <= tb:
        return ag * s * (2 / 3 + t / tb * (2.5 / q - 2 / 3))
    if t <= tc:
        return ag * s * 2.5 / q
    if t <= td:
        return max(ag * s * 2.5 / q * tc / t, beta * ag)
    return max(ag * s * 2.5 / q * tc * td / t ** 2, beta * ag)


def corner_grid(tb, tc, td):
    return np.array([0.0, tb / 2, tb, (tb + tc) / 2, tc, (tc + td) / 2, td, 3.0, 4.0, 5.0])


@pytest.mark.parametrize("key", sorted(TABLES))
def test_spectra_every_ground(key):
    typ, ground = key
    s, tb, tc, td = TABLES[key]
    assert C.ground_parameters(typ, ground) == (s, tb, tc, td)
    t = corner_grid(tb, tc, td)
    ag, xi = 2.5, 7.0
    eta = math.sqrt(10 / (5 + xi))
    se = C.elastic_spectrum(t, ag, typ, ground, xi)
    np.testing.assert_allclose(se, [se_ref(x, ag, s, tb, tc, td, eta) for x in t], rtol=1e-14)
    assert se[0] == pytest.approx(ag * s, rel=1e-15)
    assert se[2] == pytest.approx(2.5 * eta * ag * s, rel=1e-15)       # plateau from TB
    for q, beta in ((1.5, 0.2), (4.0, 0.2), (1.0, 0.0)):
        sd = C.design_spectrum(t, ag, typ, ground, q=q, beta=beta)
        np.testing.assert_allclose(sd, [sd_ref(x, ag, s, tb, tc, td, q, beta) for x in t],
                                   rtol=1e-14)
        assert sd[0] == pytest.approx(2 / 3 * ag * s, rel=1e-15)
        assert sd[3] == pytest.approx(2.5 / q * ag * s, rel=1e-15)
    # continuity at the corner periods
    for corner in (tb, tc, td):
        lo, hi = C.elastic_spectrum([corner * (1 - 1e-12), corner * (1 + 1e-12)], ag, typ,
                                    ground, xi)
        assert lo == pytest.approx(hi, rel=1e-10)
        lo, hi = C.design_spectrum([corner * (1 - 1e-12), corner * (1 + 1e-12)], ag, typ, ground,
                                   q=3.0)
        assert lo == pytest.approx(hi, rel=1e-10)


def test_design_floor_and_damping():
    # ground A Type 1, q = 4: (2.5/4) S TC / T = 0.25/T falls below 0.2 at T = 1.25 s, in
    # the (3.15) branch; (3.16) beyond TD = 2 s: 0.5/T^2 < 0.2
    sd = C.design_spectrum([1.0, 1.2, 1.5, 2.5, 6.0], 1.0, 1, "A", q=4.0, beta=0.2)
    np.testing.assert_allclose(sd, [0.25, 0.25 / 1.2, 0.2, 0.2, 0.2], rtol=1e-14)
    sd = C.design_spectrum([1.5, 2.5], 1.0, 1, "A", q=4.0, beta=0.0)
    np.testing.assert_allclose(sd, [0.25 / 1.5, 0.5 / 6.25], rtol=1e-14)
    assert C.damping_correction(5.0) == 1.0
    assert C.damping_correction(0.0) == pytest.approx(math.sqrt(2), rel=1e-15)
    assert C.damping_correction(28.0) == pytest.approx(math.sqrt(10 / 33), rel=1e-15)
    assert C.damping_correction(28.06) == 0.55          # floor from 10/0.3025 - 5 = 28.0579
    eta = C.damping_correction(np.array([[5.0, 10.0], [50.0, 0.0]]))
    np.testing.assert_allclose(eta, [[1.0, math.sqrt(2 / 3)], [0.55, math.sqrt(2)]], rtol=1e-15)
    # eta scales the plateau
    assert C.elastic_spectrum(0.3, 1.0, 1, "A", 10.0) == pytest.approx(
        2.5 * math.sqrt(2 / 3), rel=1e-15)
    assert C.elastic_spectrum(0.3, 1.0, 1, "a") == 2.5


def test_xi_percent_looking_like_a_ratio_warns():
    """xi_percent is in percent: 0 < xi < 1 (e.g. 0.05 meant as 5 %) draws a UserWarning
    naming the value; 0, 1 and 5 do not. The value is still used as given: eta(0.05 %) =
    sqrt(10/5.05) (3.6), so Se(0.3 s) = 0.24 1.2 2.5 eta on ground B, Type 1."""
    msg = r"^xi_percent = 0.05: xi_percent is in percent; 0.05 means 0.05 %, did you mean 5\?"
    with pytest.warns(UserWarning, match=msg):
        se = C.elastic_spectrum(0.3, 0.24, 1, "B", 0.05)
    assert se == pytest.approx(0.24 * 1.2 * 2.5 * math.sqrt(10 / 5.05), rel=1e-14)
    with pytest.warns(UserWarning, match=r"^xi_percent = 0.5: .*did you mean 50\?"):
        eta = C.damping_correction([5.0, 0.5])
    assert eta[1] == pytest.approx(math.sqrt(10 / 5.5), rel=1e-15)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        C.elastic_spectrum(0.3, 0.24, 1, "B", 5.0)
        C.elastic_spectrum(0.3, 0.24, 1, "B", 0.0)
        C.damping_correction([0.0, 1.0, 5.0])


@pytest.mark.parametrize("call,start", [
    (lambda: C.elastic_spectrum(0.1, True), "ag = True: must be a real number, not a bool"),
    (lambda: C.elastic_spectrum(0.1, 1.0, xi_percent=True), "xi_percent = True"),
    (lambda: C.design_spectrum(0.1, 1.0, q=True), "q = True"),
    (lambda: C.design_spectrum(0.1, zone="Z2", importance=True), "importance = True"),
    (lambda: C.elastic_spectrum([True, False], 1.0), "periods: .*not bools"),
    (lambda: C.damping_correction(np.array([True])), "xi_percent: .*not bools"),
])
def test_spectra_refuse_bools(call, start):
    with pytest.raises(InvalidInputError, match="^" + start):
        call()


@pytest.mark.parametrize("call,start", [
    (lambda: C.elastic_spectrum([0.1, -0.5], 1.0), r"periods\[1\] = -0.5"),
    (lambda: C.elastic_spectrum([0.1, float("nan")], 1.0), r"periods\[1\] = NaN"),
    (lambda: C.elastic_spectrum(0.1, -1.0), "ag = -1"),
    (lambda: C.elastic_spectrum(0.1, 1.0, xi_percent=-5.0), "xi_percent = -5"),
    (lambda: C.elastic_spectrum(0.1, 1.0, ground="F"), "ground = 'F'"),
    (lambda: C.elastic_spectrum(0.1, 1.0, spectrum_type=0), "spectrum_type = 0"),
    (lambda: C.design_spectrum(0.1, 1.0, q=0.9), "q = 0.9"),
    (lambda: C.design_spectrum(0.1, 1.0, beta=-0.2), "beta = -0.2"),
    (lambda: C.damping_correction([5.0, -1.0]), r"xi_percent\[1\] = -1"),
    (lambda: C.damping_correction(-1.0), "xi_percent = -1"),
    (lambda: C.ground_parameters(1, "G"), "ground = 'G'"),
    (lambda: C.ground_parameters(2.0, "A"), "spectrum_type = 2.0"),
])
def test_spectra_bad_input(call, start):
    with pytest.raises(InvalidInputError, match="^" + start):
        call()


def test_inertia_beyond_friction_names_kh():
    """theta > phi' behind a level backfill: the message blames kh, not the slope."""
    with pytest.raises(NoSolutionError, match=r"^kh: theta = 38\.6598 deg exceeds phi_d = 30"):
        C.mononobe_okabe(30.0, 0.8, 0.0)
