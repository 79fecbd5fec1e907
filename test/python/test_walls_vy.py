"""seispulse.walls Veletsos-Younan series (Fortran seispulse_walls_vy) against values computed
here without the library: mpmath sums (direct terms with the principal square roots of the
source, Hurwitz-zeta tails for q and m, mpmath's Clausen functions for the pressure), the
closed-form 1-D free-field shear layer, finite differences of the fields (the constitutive
relations the corrected Eqs. 2.31-2.33 come from), Gauss-Legendre quadrature of the pressure,
and the doc/walls.md section 3 table. Each corrected equation has a test where the printed form
differs. Bad input for every parameter."""
import math

import mpmath as mp
import numpy as np
import pytest

from seispulse import walls as W
from seispulse.errors import ConvergenceError, InvalidInputError, SingularError

mp.mp.dps = 25
PI = math.pi
NU = 0.3
PSIS = 2 / math.sqrt((1 - NU) * (2 - NU))         # psi_sigma(0.3)
PSIO2 = 2 / (1 - NU)                               # psi_o^2(0.3)


# ------------------------------------------------------------------ references (mpmath)

def r_n(w, delta, n):
    """sqrt(1 + i delta)/sqrt(1 - phi^2 + i delta), principal roots as printed; delta = 0
    above resonance: the delta -> 0+ limit, sqrt(1 - phi^2) = +i sqrt(phi^2 - 1)."""
    w, delta = mp.mpf(w), mp.mpf(delta)
    phi2 = (w / n) ** 2
    if delta > 0:
        return mp.sqrt(1 + 1j * delta) / mp.sqrt(1 - phi2 + 1j * delta)
    if phi2 < 1:
        return 1 / mp.sqrt(1 - phi2)
    return 1 / (1j * mp.sqrt(phi2 - 1))


def qm_ref(w, delta, nu=NU, ndirect=3000, moment_power=4):
    """q = (16 psi/pi^3) sum r_n/n^3, m = (32 psi/pi^4) sum (-1)^k r_n/n^p (p = 4 corrected,
    3 as printed): direct terms, then r = sum_k c_k z^k with Hurwitz-zeta tails."""
    w, delta, nu = mp.mpf(w), mp.mpf(delta), mp.mpf(nu)
    psis = 2 / mp.sqrt((1 - nu) * (2 - nu))
    n0 = int(ndirect + 2 * w) | 1
    if n0 % 4 != 3:
        n0 += 2                       # the next odd a = n0 + 2 is 1 mod 4
    sq = sm = mp.mpc(0)
    for k in range((n0 + 1) // 2):
        n = 2 * k + 1
        r = r_n(w, delta, n)
        sq += r / n**3
        sm += (-1) ** k * r / n**moment_power
    a = n0 + 2
    zeta = w**2 / (1 + 1j * delta)
    for k in range(8):
        c = mp.binomial(2 * k, k) / mp.mpf(4) ** k
        sq += c * zeta**k * mp.mpf(2) ** (-3 - 2 * k) * mp.zeta(3 + 2 * k, mp.mpf(a) / 2)
        s = moment_power + 2 * k
        sm += c * zeta**k * mp.mpf(4) ** (-s) * (mp.zeta(s, mp.mpf(a) / 4)
                                                 - mp.zeta(s, mp.mpf(a + 2) / 4))
    return complex(16 * psis / mp.pi**3 * sq), complex(32 * psis / mp.pi**4 * sm)


def odd_sin(s, t):
    """sum_{n odd} sin(n t)/n^s from mpmath's Clausen function."""
    return mp.clsin(s, t) - mp.mpf(2) ** (-s) * mp.clsin(s, 2 * t)


def odd_cos(s, t):
    return mp.clcos(s, t) - mp.mpf(2) ** (-s) * mp.clcos(s, 2 * t)


def pressure_ref(w, delta, y, nu=NU, ndirect=1500):
    """(8 psi/pi^2) sum r_n sin(n pi y/2)/n^2: the sums of 1, z/2, 3z^2/8 by Clausen
    functions, the remainder (decaying like n^-8) term by term."""
    w, delta, nu, y = mp.mpf(w), mp.mpf(delta), mp.mpf(nu), mp.mpf(y)
    psis = 2 / mp.sqrt((1 - nu) * (2 - nu))
    t = mp.pi * y / 2
    zeta = w**2 / (1 + 1j * delta)
    c = [mp.mpf(1), mp.mpf(1) / 2, mp.mpf(3) / 8]
    tot = sum(c[k] * zeta**k * odd_sin(2 + 2 * k, t) for k in range(3))
    for n in range(1, ndirect + 1, 2):
        z = zeta / n**2
        tot += (r_n(w, delta, n) - 1 - z / 2 - 3 * z**2 / 8) * mp.sin(n * t) / n**2
    return complex(8 * psis / mp.pi**2 * tot)


def v_wall_ref(w, delta, y, nu=NU, ndirect=1500):
    """v(0, y) = (16 psi_v/(pi^3 (1 + i delta))) sum r_n (1 - cos(n t))/n^3."""
    w, delta, nu, y = mp.mpf(w), mp.mpf(delta), mp.mpf(nu), mp.mpf(y)
    t = mp.pi * y / 2
    zeta = w**2 / (1 + 1j * delta)
    c = [mp.mpf(1), mp.mpf(1) / 2, mp.mpf(3) / 8]
    tot = sum(c[k] * zeta**k * ((1 - mp.mpf(2) ** (-3 - 2 * k)) * mp.zeta(3 + 2 * k)
                                - odd_cos(3 + 2 * k, t)) for k in range(3))
    for n in range(1, ndirect + 1, 2):
        z = zeta / n**2
        tot += (r_n(w, delta, n) - 1 - z / 2 - 3 * z**2 / 8) * (1 - mp.cos(n * t)) / n**3
    psiv = nu / mp.sqrt((1 - nu) * (2 - nu))
    return complex(16 * psiv / mp.pi**3 / (1 + 1j * delta) * tot)


def free_field_ref(w, delta, y):
    """1-D shear layer, closed form: u'' + k^2 u = Xg/V*^2, u(0) = 0, u'(H) = 0 gives
    u = (4/(pi w)^2)(1 - cos(kap(1 - y))/cos kap) (rho Xg H^2/G), tau = G* du/dy."""
    w, delta, y = mp.mpf(w), mp.mpf(delta), mp.mpf(y)
    if w == 0:
        return complex(-(y - y**2 / 2) / (1 + 1j * delta)), complex(-(1 - y))
    kap = mp.pi / 2 * w / mp.sqrt(1 + 1j * delta)
    u = 4 / (mp.pi**2 * w**2) * (1 - mp.cos(kap * (1 - y)) / mp.cos(kap))
    tau = (1 + 1j * delta) * 4 / (mp.pi**2 * w**2) * (-kap * mp.sin(kap * (1 - y)) / mp.cos(kap))
    return complex(u), complex(tau)


def fields_ref(w, delta, x, y, nu=NU, eps=1e-22, psi_e_power=1, printed_u=False):
    """(2.30)-(2.33) at x > 0: free field in closed form plus the decaying sums term by
    term. psi_e_power = 2 puts psi_e^2 where (2.25) wants psi_e (the printed misplacement);
    printed_u divides u by (1 + i delta) once more, as the printed (2.30)."""
    w, delta, nu, x, y = (mp.mpf(v) for v in (w, delta, nu, x, y))
    psi_e = mp.sqrt((2 - nu) / (1 - nu))
    psis = 2 / mp.sqrt((1 - nu) * (2 - nu))
    psiv = nu / mp.sqrt((1 - nu) * (2 - nu))
    kappa = nu / (2 - nu)
    t = mp.pi * y / 2
    ds = du = dv = dt = mp.mpc(0)
    n = 1
    while True:
        phi2 = (w / n) ** 2
        r = r_n(w, delta, n)
        if delta > 0:
            sq = mp.sqrt(1 - phi2 / (1 + 1j * delta))
        else:
            sq = mp.sqrt(1 - phi2) if phi2 < 1 else 1j * mp.sqrt(phi2 - 1)
        e = mp.exp(-n * mp.pi / (2 * psi_e**psi_e_power) * sq * x)
        sn, cn = mp.sin(n * t), mp.cos(n * t)
        ds += r * e * sn / n**2
        du += r**2 * e * sn / n**3
        dv += r * e * (1 - cn) / n**3
        dt += (-r**2 * e * cn + kappa * e * (1 - cn)) / n**2
        if n > 2 * w + 2 and abs(e) < eps:
            break
        n += 2
    uff, tauff = free_field_ref(w, delta, y)
    g = 1 / (1 + 1j * delta)
    u = uff + complex(16 / mp.pi**3 * g * du)
    if printed_u:
        u = complex(u * g)
    v = complex(16 * psiv / mp.pi**3 * g * dv)
    sig = complex(-8 * psis / mp.pi**2 * ds)
    tau = tauff + complex(-8 / mp.pi**2 * dt)
    return u, v, sig, tau


def graded_gauss(npan=40, ng=12):
    """Nodes/weights on [0, 1]: dyadic panels toward y = 0 (p ~ y log y there)."""
    xg, wg = np.polynomial.legendre.leggauss(ng)
    ys, ws = [], []
    for k in range(npan):
        b = 0.5**k
        a = b / 2
        ys.append((a + b) / 2 + (b - a) / 2 * xg)
        ws.append((b - a) / 2 * wg)
    return np.concatenate(ys), np.concatenate(ws)


# ------------------------------------------------------------------ factors

def test_psi_factors_values():
    p = W.psi_factors(0.3)
    assert p.psi_e == pytest.approx(1.5584, abs=5e-5)
    assert p.psi_o == pytest.approx(1.6903, abs=5e-5)
    assert p.psi_sigma == pytest.approx(1.8334, abs=5e-5)
    assert p.psi_v == pytest.approx(0.2750, abs=5e-5)
    assert p.psi_sigma == pytest.approx(p.psi_o**2 / p.psi_e, rel=1e-15)
    p = W.psi_factors(1 / 3)
    assert (p.psi_e, p.psi_o, p.psi_sigma) == pytest.approx((1.5811, 1.7321, 1.8974), abs=5e-5)
    p = W.psi_factors([0.3, 1 / 3])
    assert p.psi_sigma.shape == (2,)


def test_psi_factors_half_limit():
    p = W.psi_factors(0.5 - 1e-12)
    assert p.psi_e == pytest.approx(math.sqrt(3), rel=1e-11)
    assert p.psi_o == pytest.approx(2.0, rel=1e-11)
    assert p.psi_sigma == pytest.approx(4 / math.sqrt(3), rel=1e-11)   # 2.3094
    assert p.psi_t > 1e5
    with pytest.raises(InvalidInputError, match=r"^nu"):
        W.psi_factors(0.5)


def test_free_field_frequencies():
    om = W.free_field_frequencies(10.0, 200.0, 4)
    assert om == pytest.approx([(2 * k - 1) * PI * 200 / 20 for k in (1, 2, 3, 4)], rel=1e-15)
    assert len(W.free_field_frequencies(10.0, 200.0)) == 5
    with pytest.raises(InvalidInputError, match=r"^height"):
        W.free_field_frequencies(-1.0, 200.0)
    with pytest.raises(InvalidInputError, match=r"^vs"):
        W.free_field_frequencies(10.0, float("nan"))
    with pytest.raises(InvalidInputError, match=r"^n_modes"):
        W.free_field_frequencies(10.0, 200.0, 0)
    with pytest.raises(InvalidInputError, match=r"^n_modes"):
        W.free_field_frequencies(10.0, 200.0, 2.5)


# ------------------------------------------------------------------ static values

def test_static_thrust_and_h():
    r = W.vy_rigid(0.0, 0.1, NU, tol=1e-12)
    q_st = 14 * float(mp.zeta(3)) / PI**3
    assert q_st == pytest.approx(0.542755, abs=5e-7)
    assert r.q == pytest.approx(q_st * PSIS, rel=1e-14)
    assert abs(r.q) == pytest.approx(0.9951, abs=5e-5)
    beta4 = float(mp.nsum(lambda k: (-1) ** k / (2 * k + 1) ** 4, [0, mp.inf]))
    assert r.m == pytest.approx(32 * beta4 / PI**4 * PSIS, rel=1e-14)
    assert r.h_ratio == pytest.approx(0.59858, abs=5e-6)
    assert r.h_ratio == pytest.approx(abs(r.m) / abs(r.q), rel=1e-15)


def test_erratum_235_moment_power():
    """(2.35)/(2.36) printed with 1/n^3 give h/H = 0.58647 statically; corrected 0.59858."""
    q3, m3 = qm_ref(0.0, 0.0, moment_power=3)
    h_printed = abs(m3) / abs(q3)        # = (2/pi) sum (-1)^k/n^3 / lambda(3)
    assert h_printed == pytest.approx(0.58647, abs=5e-6)
    r = W.vy_rigid(0.0, 0.0, NU)
    assert abs(r.h_ratio - h_printed) > 0.01
    # dynamic: matches the 1/n^4 sum, not the 1/n^3 one
    r = W.vy_rigid(1.5, 0.1, NU, tol=1e-12)
    q4, m4 = qm_ref(1.5, 0.1)
    _, m3 = qm_ref(1.5, 0.1, moment_power=3)
    assert r.m == pytest.approx(m4, rel=1e-10)
    assert abs(r.m - m3) > 0.01 * abs(m4)


def test_static_surface_pressure():
    catalan = float(mp.catalan)
    assert 8 * catalan / PI**2 == pytest.approx(0.742454, abs=5e-7)
    p = W.vy_pressure(0.0, 0.0, NU, [0.0, 1.0], tol=1e-12)
    assert p[0] == 0
    assert p[1] == pytest.approx(8 * catalan / PI**2 * PSIS, rel=1e-14)


def test_static_free_field_surface_displacement():
    f = W.vy_fields(0.0, 0.0, NU, 60.0, 1.0, tol=1e-12)
    assert f.u == pytest.approx(-0.5, rel=1e-12)             # -rho Xg H^2/(2G)
    f = W.vy_fields(0.0, 0.1, NU, 60.0, 1.0, tol=1e-12)
    assert f.u == pytest.approx(-0.5 / (1 + 0.1j), rel=1e-12)


# ------------------------------------------------------------------ dynamic table

TABLE = [  # delta, omega_ratio, |Q|, |h/H| (doc/walls.md section 3, nu = 0.3)
    (0.1, 0.5, 1.1399, 0.6030), (0.1, 0.8, 1.6019, 0.6123), (0.1, 1.0, 3.0376, 0.6268),
    (0.1, 1.5, 0.8543, 0.6302), (0.1, 2.0, 0.5568, 0.6243), (0.1, 3.0, 0.4261, 0.4632),
    (0.05, 1.0, 4.2710, 0.6298), (0.2, 1.0, 2.1765, 0.6223), (0.0, 0.5, 1.1420, 0.6031),
    (0.0, 2.0, 0.5497, 0.6328)]


@pytest.mark.parametrize("delta,w,qabs,h", TABLE)
def test_dynamic_table(delta, w, qabs, h):
    r = W.vy_rigid(w, delta, NU, tol=1e-12)
    assert abs(r.q) == pytest.approx(qabs, abs=5e-5)
    assert r.h_ratio == pytest.approx(h, abs=5e-5)
    q, m = qm_ref(w, delta)
    assert r.q == pytest.approx(q, rel=1e-9)
    assert r.m == pytest.approx(m, rel=1e-9)


def test_resonant_amplification():
    s = W.vy_sweep([0.0, 1.0], 0.1, NU)
    assert s.amplification[0] == pytest.approx(1.0, rel=1e-14)
    assert s.amplification[1] == pytest.approx(3.05, abs=5e-3)      # doc/walls.md: VY 3.05
    q, _ = qm_ref(1.0, 0.1)
    assert s.amplification[1] == pytest.approx(abs(q) / abs(qm_ref(0, 0.1)[0]), rel=1e-7)


# ------------------------------------------------------------------ tolerance

@pytest.mark.parametrize("w,delta", [(0.7, 0.1), (2.5, 0.0), (4.2, 0.03), (11.0, 0.1)])
def test_tight_tolerance_against_mpmath(w, delta):
    r = W.vy_rigid(w, delta, NU, tol=1e-12)
    q, m = qm_ref(w, delta)
    assert r.q == pytest.approx(q, rel=2e-12)
    assert r.m == pytest.approx(m, rel=2e-12)


def test_nterms_grow_as_tol_shrinks():
    n = [W.vy_rigid(2.3, 0.1, NU, tol=t).n_terms for t in (1e-3, 1e-6, 1e-9, 1e-12, 1e-15)]
    assert all(b > a for a, b in zip(n, n[1:])), n
    q, _ = qm_ref(2.3, 0.1)
    for t in (1e-3, 1e-6, 1e-9):
        assert abs(W.vy_rigid(2.3, 0.1, NU, tol=t).q - q) <= t * abs(q)


def test_sweep_equals_pointwise():
    w = np.linspace(0.0, 5.0, 41)
    s = W.vy_sweep(w, 0.1, NU, tol=1e-8)
    arr = W.vy_rigid(w, 0.1, NU, tol=1e-8)
    for i, wi in enumerate(w):
        one = W.vy_rigid(wi, 0.1, NU, tol=1e-8)
        assert s.q[i] == one.q and s.m[i] == one.m and s.h_ratio[i] == one.h_ratio
        assert arr.q[i] == one.q and arr.n_terms[i] == one.n_terms
    assert s.amplification == pytest.approx(np.abs(s.q) / abs(W.vy_rigid(0.0, 0.1, NU).q),
                                            rel=1e-9)
    # delta and nu as arrays: element by element
    mix = W.vy_rigid([0.5, 2.0], [0.1, 0.0], [0.3, 0.4])
    assert mix.q[1] == W.vy_rigid(2.0, 0.0, 0.4).q


# ------------------------------------------------------------------ pressure

@pytest.mark.parametrize("w,delta", [(0.8, 0.1), (2.0, 0.0), (3.0, 0.1)])
def test_pressure_against_clausen_reference(w, delta):
    ys = [1e-3, 0.05, 0.3, 0.8, 1.0]
    p = W.vy_pressure(w, delta, NU, ys, tol=1e-12)
    scale = 8 * PSIS / PI**2 * sum(abs(complex(r_n(w, delta, n))) / n**2 for n in range(1, 400, 2))
    for yi, pi in zip(ys, p):
        assert abs(pi - pressure_ref(w, delta, yi)) <= 1e-11 * scale


def test_pressure_integrates_to_q_and_m():
    y, wy = graded_gauss()
    for w, delta in [(0.6, 0.1), (2.0, 0.0), (5.5, 0.05)]:
        p = W.vy_pressure(w, delta, NU, y, tol=1e-13)
        r = W.vy_rigid(w, delta, NU, tol=1e-13)
        assert np.sum(wy * p) == pytest.approx(r.q, rel=1e-10)
        assert np.sum(wy * y * p) == pytest.approx(r.m, rel=1e-10)


def test_erratum_232_pressure_sign_and_factor():
    """(2.32) printed with '+' and an extra (1 + i delta): the wall pressure is compressive
    (p > 0 statically) and carries no extra factor."""
    p = W.vy_pressure(0.5, 0.1, NU, 0.7, tol=1e-12)
    ref = pressure_ref(0.5, 0.1, 0.7)
    assert p == pytest.approx(ref, rel=1e-11)
    assert abs(p - ref * (1 + 0.1j)) > 0.05 * abs(ref)
    assert p.real > 0
    assert W.vy_fields(0.5, 0.1, NU, 0.0, 0.7, tol=1e-12).sigma_x == -p


def test_pressure_shapes():
    assert isinstance(W.vy_pressure(1.2, 0.1, NU, 0.5), complex)
    assert W.vy_pressure(1.2, 0.1, NU, [[0.1, 0.2], [0.3, 0.4]]).shape == (2, 2)


# ------------------------------------------------------------------ fields

def test_fields_at_wall():
    y = np.array([0.0, 0.2, 0.6, 1.0])
    f = W.vy_fields(2.0, 0.1, NU, 0.0, y, tol=1e-12)
    assert np.all(f.u == 0)
    assert np.array_equal(f.sigma_x, -W.vy_pressure(2.0, 0.1, NU, y, tol=1e-12))
    assert f.tau == pytest.approx(-NU / (2 - NU) * y, abs=1e-15)
    for yi, vi in zip(y[1:], f.v[1:]):
        assert vi == pytest.approx(v_wall_ref(2.0, 0.1, yi), abs=1e-12)


@pytest.mark.parametrize("w,delta", [(0.6, 0.1), (1.4, 0.1), (2.5, 0.0)])
def test_fields_far_field(w, delta):
    # |E_1| = exp(-Re(a_1) x): radiating modes decay only through delta, so x is large
    x = 1000.0 if w > 1 and delta > 0 else 60.0
    y = np.array([0.2, 0.7, 1.0])
    f = W.vy_fields(w, delta, NU, x, y, tol=1e-12)
    if w > 1 and delta == 0:
        # undamped radiating waves never die out: free field plus the outgoing mode 1
        for yi, ui, ti in zip(y, f.u, f.tau):
            ref = fields_ref(w, delta, x, yi)
            assert ui == pytest.approx(ref[0], abs=1e-11)
            assert ti == pytest.approx(ref[3], abs=1e-11)
            assert abs(ui - free_field_ref(w, delta, yi)[0]) > 1e-3
        return
    for yi, ui, ti in zip(y, f.u, f.tau):
        uff, tff = free_field_ref(w, delta, yi)
        assert ui == pytest.approx(uff, rel=1e-11)
        assert ti == pytest.approx(tff, rel=1e-10, abs=1e-12)


@pytest.mark.parametrize("w,delta,x,y", [(2.0, 0.1, 0.3, 0.7), (2.5, 0.0, 0.05, 1.0),
                                         (2.5, 0.0, 1.0, 0.4), (0.5, 0.1, 0.2, 0.9),
                                         (4.0, 0.05, 2.0, 0.3)])
def test_fields_against_term_by_term(w, delta, x, y):
    f = W.vy_fields(w, delta, NU, x, y, tol=1e-12)
    ref = fields_ref(w, delta, x, y)
    for got, exp in zip(f, ref):
        assert got == pytest.approx(exp, abs=2e-11)


@pytest.mark.parametrize("w,delta,x,y", [(2.0, 0.1, 0.3, 0.7), (0.7, 0.0, 0.15, 0.45)])
def test_fields_constitutive_relations(w, delta, x, y):
    """The corrected (2.31)-(2.33) follow from (2.30): sigma_x = psi_o^2 G* du/dx,
    dv/dy = -nu/(1 - nu) du/dx (2.7), tau = G*(du/dy + dv/dx); central differences."""
    h = 1e-5
    g = 1 + 1j * delta
    f = W.vy_fields(w, delta, NU, x, y, tol=1e-13)
    d = W.vy_fields(w, delta, NU, [x + h, x - h, x, x], [y, y, y + h, y - h], tol=1e-13)
    dudx = (d.u[0] - d.u[1]) / (2 * h)
    dudy = (d.u[2] - d.u[3]) / (2 * h)
    dvdx = (d.v[0] - d.v[1]) / (2 * h)
    dvdy = (d.v[2] - d.v[3]) / (2 * h)
    assert f.sigma_x == pytest.approx(PSIO2 * g * dudx, rel=1e-7)
    assert dvdy == pytest.approx(-NU / (1 - NU) * dudx, rel=1e-7)
    assert f.tau == pytest.approx(g * (dudy + dvdx), rel=1e-7)


def test_erratum_230_damping_counted_once():
    f = W.vy_fields(2.0, 0.1, NU, 0.3, 0.7, tol=1e-12)
    u = fields_ref(2.0, 0.1, 0.3, 0.7)[0]
    printed = fields_ref(2.0, 0.1, 0.3, 0.7, printed_u=True)[0]
    assert f.u == pytest.approx(u, abs=1e-11)
    assert abs(f.u - printed) > 0.05 * abs(u)


def test_erratum_225_psi_e_placement():
    f = W.vy_fields(0.8, 0.1, NU, 0.5, 0.6, tol=1e-12)
    good = fields_ref(0.8, 0.1, 0.5, 0.6)
    bad = fields_ref(0.8, 0.1, 0.5, 0.6, psi_e_power=2)
    assert f.sigma_x == pytest.approx(good[2], abs=1e-11)
    assert abs(f.sigma_x - bad[2]) > 0.02 * abs(good[2])


def test_fields_broadcast_and_near_wall():
    f = W.vy_fields(1.2, 0.1, NU, [[0.0], [1e-6], [0.5]], [0.3, 1.0])
    assert f.u.shape == (3, 2)
    # x -> 0+: continuous onto the wall values
    assert f.sigma_x[1] == pytest.approx(f.sigma_x[0], rel=1e-5)
    assert f.tau[1] == pytest.approx(f.tau[0], rel=1e-4)
    assert abs(f.u[1, 1]) < 1e-5


# ------------------------------------------------------------------ branch, zeros, resonance

def test_branch_delta_zero_is_the_limit():
    a = W.vy_rigid(2.0, 0.0, NU, tol=1e-12)
    b = W.vy_rigid(2.0, 1e-13, NU, tol=1e-12)
    q, _ = qm_ref(2.0, 1e-13)             # principal roots of the printed form
    assert a.q == pytest.approx(b.q, rel=1e-9) and a.m == pytest.approx(b.m, rel=1e-9)
    assert a.q == pytest.approx(q, rel=1e-9)
    assert W.vy_pressure(2.0, 0.0, NU, 0.9) == pytest.approx(W.vy_pressure(2.0, 1e-13, NU, 0.9),
                                                             rel=1e-9)
    fa = W.vy_fields(2.0, 0.0, NU, 0.4, 0.8)
    fb = W.vy_fields(2.0, 1e-13, NU, 0.4, 0.8)
    for x, y in zip(fa, fb):
        assert x == pytest.approx(y, rel=1e-9)


def test_signed_zero_inputs():
    assert W.vy_rigid(2.0, -0.0, NU) == W.vy_rigid(2.0, 0.0, NU)
    assert W.vy_rigid(-0.0, 0.1, NU) == W.vy_rigid(0.0, 0.1, NU)
    assert W.vy_pressure(2.5, -0.0, NU, [0.7, -0.0]).tolist() == \
        W.vy_pressure(2.5, 0.0, NU, [0.7, 0.0]).tolist()
    a = W.vy_fields(2.5, -0.0, NU, [-0.0, 0.4], [-0.0, 0.6])
    b = W.vy_fields(2.5, 0.0, NU, [0.0, 0.4], [0.0, 0.6])
    for x, y in zip(a, b):
        assert x.tolist() == y.tolist()
    for c in a:
        assert math.copysign(1, c[0].real) > 0 and math.copysign(1, c[0].imag) > 0


@pytest.mark.parametrize("w", [1.0, 3.0, 5.0])
def test_resonance_refused(w):
    with pytest.raises(SingularError, match=r"^omega_ratio"):
        W.vy_rigid(w, 0.0, NU)
    with pytest.raises(SingularError, match=r"^omega_ratio"):
        W.vy_pressure(w, 0.0, NU, 0.5)
    with pytest.raises(SingularError, match=r"^omega_ratio"):
        W.vy_fields(w, 0.0, NU, 0.5, 0.5)
    with pytest.raises(SingularError, match=r"^omega_ratios\[1\]"):
        W.vy_sweep([0.5, w], 0.0, NU)


@pytest.mark.parametrize("w", [1 - 1e-9, 1 + 1e-9])
def test_near_resonance_finite(w):
    r = W.vy_rigid(w, 0.0, NU)
    assert np.isfinite(r.q.real) and np.isfinite(r.q.imag)
    assert abs(r.q) == pytest.approx(16 * PSIS / PI**3 / math.sqrt(2e-9), rel=1e-3)
    q, _ = qm_ref(w, 0.0)
    assert r.q == pytest.approx(q, rel=1e-8)
    assert W.vy_rigid(2.0, 0.0, NU).q == pytest.approx(qm_ref(2.0, 0.0)[0], rel=1e-9)


# ------------------------------------------------------------------ bad input

NAN = float("nan")


@pytest.mark.parametrize("kwargs,name", [
    (dict(omega_ratio=NAN), "omega_ratio"), (dict(omega_ratio=-1.0), "omega_ratio"),
    (dict(omega_ratio=2e4), "omega_ratio"), (dict(delta=NAN), "delta"),
    (dict(delta=-0.1), "delta"), (dict(nu=0.5), "nu"), (dict(nu=-0.1), "nu"),
    (dict(nu=NAN), "nu"), (dict(tol=0.0), "tol"), (dict(tol=1e-16), "tol"),
    (dict(tol=0.1), "tol"), (dict(tol=NAN), "tol"), (dict(omega_ratio="a"), "omega_ratio")])
def test_bad_input_rigid(kwargs, name):
    args = dict(omega_ratio=1.0, delta=0.1, nu=NU, tol=1e-10)
    args.update(kwargs)
    with pytest.raises(InvalidInputError, match=rf"^{name}"):
        W.vy_rigid(**args)


def test_bad_input_arrays():
    with pytest.raises(InvalidInputError, match=r"^omega_ratio\[1\]"):
        W.vy_rigid([0.5, NAN], 0.1, NU)
    # element by element (arrays of delta): the same index in the message
    with pytest.raises(InvalidInputError, match=r"^omega_ratio\[1\] = NaN"):
        W.vy_rigid([0.5, NAN], [0.1, 0.1], NU)
    with pytest.raises(InvalidInputError, match=r"^delta\[0\] = -0.1"):
        W.vy_rigid([0.5, 1.0], [-0.1, 0.1], NU)
    with pytest.raises(InvalidInputError, match=r"^omega_ratios\[2\]"):
        W.vy_sweep([0.5, 1.0, -2.0], 0.1, NU)
    with pytest.raises(InvalidInputError, match=r"^y\[1\]"):
        W.vy_pressure(1.0, 0.1, NU, [0.5, 1.5])
    with pytest.raises(InvalidInputError, match=r"^y\[0\]"):
        W.vy_pressure(1.0, 0.1, NU, [NAN])
    with pytest.raises(InvalidInputError, match=r"^y\[2\]"):
        W.vy_pressure(1.0, 0.1, NU, [0.0, 0.5, -0.1])
    with pytest.raises(InvalidInputError, match=r"^x\[1\]"):
        W.vy_fields(1.0, 0.1, NU, [0.5, -1.0], 0.5)
    with pytest.raises(InvalidInputError, match=r"^x\[0\]"):
        W.vy_fields(1.0, 0.1, NU, math.inf, 0.5)
    with pytest.raises(InvalidInputError, match=r"^x\[0\]"):
        W.vy_fields(1.0, 0.1, NU, NAN, 0.5)
    # far beyond 1e6 H, a_n x would overflow (NaN fields with no error before the cap)
    with pytest.raises(InvalidInputError, match=r"^x\[0\].*\[0, 1e6\]"):
        W.vy_fields(2.5, 0.0, NU, 1e308, 0.5)
    assert np.isfinite(W.vy_fields(2.5, 0.0, NU, 1e6, 0.5).u)
    with pytest.raises(InvalidInputError, match=r"^y\[1\]"):
        W.vy_fields(1.0, 0.1, NU, 0.5, [0.5, 2.0])
    with pytest.raises(InvalidInputError, match=r"x \(2,\), y \(3,\)"):
        W.vy_fields(1.0, 0.1, NU, [0.1, 0.2], [0.1, 0.2, 0.3])
    with pytest.raises(InvalidInputError, match=r"^delta"):
        W.vy_pressure(1.0, [0.1, 0.2], NU, 0.5)
    with pytest.raises(InvalidInputError, match=r"^nu"):
        W.vy_fields(1.0, 0.1, 0.7, 0.5, 0.5)
    with pytest.raises(InvalidInputError, match=r"^tol"):
        W.vy_fields(1.0, 0.1, NU, 0.5, 0.5, tol=1.0)


def test_too_tight_tol_for_large_frequency():
    """Past 2 million terms the series give up with ConvergenceError naming tol."""
    with pytest.raises(ConvergenceError, match=r"^tol"):
        W.vy_fields(500.0, 0.05, NU, 0.01, 0.5, tol=1e-15)
    f = W.vy_fields(500.0, 0.05, NU, 0.01, 0.5, tol=1e-12)
    assert np.isfinite(f.tau.real)
