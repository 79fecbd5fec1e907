"""One-term wall solution (seispulse.walls, Fortran seispulse_walls_one_term) against
independent computations: mpmath quadrature of the shape integrals, a Veletsos-Younan series
summed here with mpmath (static-subtracted, 1000 odd terms), mpmath Bessel zeros and a
Frobenius-series shooting of the power-law layer, scipy quadrature of the wall pressure,
the derived tables of doc/walls.md (§4-§7) and the Python-layer behaviour (shapes, arrays,
errors naming the argument)."""

import math

import mpmath as mp
import numpy as np
import pytest
from scipy import integrate

from seispulse import walls
from seispulse.errors import InvalidInputError, SingularError

PI = math.pi


@pytest.fixture(autouse=True)
def _restore_mpmath_precision():
    """The tests here set mp.mp.dps; leave it as found for other modules."""
    saved = mp.mp.dps
    yield
    mp.mp.dps = saved


def psi_sigma(nu):
    return 2.0 / math.sqrt((1.0 - nu) * (2.0 - nu))


def psi_e(nu):
    return math.sqrt((2.0 - nu) / (1.0 - nu))


# ------------------------------------------------------------------ shape constants

def _phi_g(shape, n):
    """Phi, Phi' and g of the shapes in eta = y/H (mpmath)."""
    if shape == "linear":
        return (lambda e: e), (lambda e: mp.mpf(1)), (lambda e: mp.mpf(1))
    if shape == "sine":
        return (lambda e: mp.sin(mp.pi * e / 2), lambda e: mp.pi / 2 * mp.cos(mp.pi * e / 2),
                lambda e: mp.mpf(1))
    if shape == "parabolic":
        return (lambda e: e * (2 - e)), (lambda e: 2 - 2 * e), (lambda e: mp.mpf(1))
    n = mp.mpf(n)
    return (lambda e: 1 - (1 - e) ** (2 - n), lambda e: (2 - n) * (1 - e) ** (1 - n),
            lambda e: (1 - e) ** n)


def _quad_constants(shape, n):
    mp.mp.dps = 30
    phi, dphi, g = _phi_g(shape, n)
    q = lambda f: mp.quad(f, [0, 0.5, 1])  # noqa: E731
    if shape == "power":
        # int g F d(eta) with t = 1 - eta = u^(1/(1+n)): (1/(1+n)) int F(1 - u^(1/(1+n))) du,
        # which takes the t^n endpoint singularity (n -> -1) out of the integrand
        p = 1 / (1 + mp.mpf(n))
        qg = lambda f: p * q(lambda u: f(1 - u ** p))  # noqa: E731
    else:
        qg = q
    igd = qg(lambda e: dphi(e) ** 2)
    ig2 = qg(lambda e: phi(e) ** 2)
    i1 = q(phi)
    i2 = q(lambda e: phi(e) ** 2)
    s0 = qg(phi)
    s1 = qg(lambda e: phi(e) * e)
    return dict(a_oc=float(mp.sqrt(igd / ig2)), l_factor=float(i1 / ig2),
                mass_factor=float(i2 / ig2), s0=float(s0), s1=float(s1), h_ratio=float(s1 / s0))


@pytest.mark.parametrize("shape,n", [("linear", 0.0), ("sine", 0.0), ("parabolic", 0.0),
                                     ("power", -0.99), ("power", -0.5), ("power", 0.3),
                                     ("power", 1.0), ("power", 1.9), ("power", 1.99)])
def test_shape_constants_against_quadrature(shape, n):
    c = walls.shape_constants(shape, n)
    ref = _quad_constants(shape, n)
    assert c.shape == shape and c.n == n
    for key, val in ref.items():
        assert getattr(c, key) == pytest.approx(val, rel=1e-11), key


@pytest.mark.parametrize("n", [-0.7, 0.0, 0.5, 1.0, 1.6])
def test_power_law_closed_forms_2_69(n):
    c = walls.shape_constants("power", n)
    a2 = 1.5 * (5 - n) * (1 + n) / (3 - n)
    assert c.a_oc ** 2 == pytest.approx(a2, rel=1e-14)
    assert c.l_factor == pytest.approx(a2 / (2 - n), rel=1e-14)
    assert c.mass_factor == pytest.approx(2 * a2 / (5 - 2 * n), rel=1e-14)
    assert c.s0 == pytest.approx((2 - n) / (3 * (1 + n)), rel=1e-14)
    assert c.s1 == pytest.approx(1 / ((n + 1) * (n + 2)) - 1 / 12, rel=1e-12)
    assert c.h_ratio == pytest.approx((5 + n) / (4 * (2 + n)), rel=1e-14)
    # (2.75) static thrust
    q = walls.one_term(0.0, 0.0, 0.3, shape="power", n=n).q
    assert q.real == pytest.approx(psi_sigma(0.3) * math.sqrt((5 - n) / (6 * (3 - n) * (1 + n))),
                                   rel=1e-14)


def test_table_2_1_and_2_2_decimals():
    ps = psi_sigma(0.3)
    for shape, qst, h in [("linear", 0.43301, 2 / 3), ("sine", 0.51602, 0.63662),
                          ("parabolic", 0.52705, 0.625)]:
        r = walls.one_term(0.0, 0.0, 0.3, shape=shape)
        assert r.q.real / ps == pytest.approx(qst, abs=5e-6)
        assert r.h_ratio == pytest.approx(h, abs=5e-6)
    q = [walls.one_term(0.0, 0.0, 0.3, "power", n).q.real / ps for n in (0.0, 0.5, 1.0)]
    assert q == pytest.approx([0.52705, 0.44721, 0.40825], abs=5e-6)
    # the source's "about 15 %" and "about 9 %": 1 - 6/sqrt(50) and 1 - sqrt(5/6)
    assert 1 - q[1] / q[0] == pytest.approx(1 - 6 / math.sqrt(50), rel=1e-12)
    assert 1 - q[2] / q[1] == pytest.approx(1 - math.sqrt(5 / 6), rel=1e-12)
    a = [walls.shape_constants("power", n).a_oc for n in (0.0, 0.5, 1.0)]
    assert a == pytest.approx([1.58114, 2.01246, 2.44949], abs=5e-6)


def test_shape_default_and_parabola_identity():
    assert walls.one_term(0.4, 0.1, 0.3) == walls.one_term(0.4, 0.1, 0.3, shape="sine")
    assert walls.one_term(0.4, 0.1, 0.3, n=0.5) == walls.one_term(0.4, 0.1, 0.3, "power", 0.5)
    assert walls.one_term(0.4, 0.1, 0.3, "parabolic") == walls.one_term(0.4, 0.1, 0.3, "power", 0.0)
    assert walls.SHAPES == ("linear", "sine", "parabolic", "power")


# ------------------------------------------------------------------ static and dynamic thrust

def test_eq_2_51_static_sine_and_erratum():
    q3 = walls.one_term(0.0, 0.0, 0.3).q.real
    q13 = walls.one_term(0.0, 0.0, 1 / 3).q.real
    assert q3 == pytest.approx(0.9461, abs=5e-5)
    assert q13 == pytest.approx(0.9791, abs=5e-5)
    assert abs(q3 - 0.979) > 0.03          # the source's "0.979 at nu = 0.30" is nu = 1/3
    for nu in (0.0, 0.2, 0.3, 0.49):
        q = walls.one_term(0.0, 0.0, nu).q.real
        vy = 14 * float(mp.zeta(3)) / PI ** 3 * psi_sigma(nu)
        assert q / vy == pytest.approx(16 / (14 * float(mp.zeta(3))), rel=1e-14)


@pytest.mark.parametrize("delta,om,absq", [
    (0.1, 0.5, 1.0903), (0.1, 0.8, 1.5516), (0.1, 1.0, 2.9992), (0.1, 1.5, 0.8470),
    (0.1, 2.0, 0.5474), (0.1, 3.0, 0.3353), (0.05, 1.0, 4.2336), (0.2, 1.0, 2.1363),
    (0.0, 0.5, 1.0924), (0.0, 2.0, 0.5462)])
def test_dynamic_sine_oracles(delta, om, absq):
    assert abs(walls.one_term(om, delta, 0.3).q) == pytest.approx(absq, abs=5e-5)


def _vy_sums(om, delta, nterms=1000):
    """Veletsos-Younan (2.34), (2.35) sums over n = 1, 3, ... (nterms odd terms), the force
    sum static-subtracted (remainder ~ n^-5); mpmath, principal roots (delta -> 0+ branch)."""
    mp.mp.dps = 20
    lam3 = 7 * mp.zeta(3) / 8
    r = mp.sqrt(mp.mpc(1, delta))
    s = mp.mpf(0)
    mo = mp.mpf(0)
    for k in range(nterms):
        n = 2 * k + 1
        phi = mp.mpf(om) / n
        f = r / mp.sqrt(mp.mpc(1 - phi ** 2, delta))
        s += (f - 1) / mp.mpf(n) ** 3
        mo += (-1) ** k * f / mp.mpf(n) ** 4
    return s + lam3, mo


def _vy_q_h(om, delta, nu):
    s, mo = _vy_sums(om, delta)
    q = 16 * psi_sigma(nu) / mp.pi ** 3 * s
    return complex(q), complex(2 / mp.pi * mo / s)


def test_vy_sum_reproduces_walls_md():
    # the independent series itself against the VY values of Ref. [TEI] (checks the oracle)
    for om, delta, q_ref, h_ref in [(0.0, 0.0, 0.9951, 0.5986), (0.5, 0.1, 1.1399, 0.6030),
                                    (1.0, 0.1, 3.0376, 0.6268), (2.0, 0.0, 0.5497, 0.6328)]:
        q, h = _vy_q_h(om, delta, 0.3)
        assert abs(q) == pytest.approx(q_ref, abs=5e-5)
        assert abs(h) == pytest.approx(h_ref, abs=5e-5)


def test_trend_against_vy_series():
    """|Q| one-term / VY stays within 0.951 .. 0.994 (Ref. [TEI], doc/walls.md section 3) for omega/omega_1 <= 2
    (delta = 0.1, nu = 0.3), and h/H = 2/pi within 10 % of |h_VY| (Fig. 2.5)."""
    oms = np.linspace(0.0, 2.0, 21)
    ot = walls.one_term(oms, 0.1, 0.3)
    for om, q1, h1 in zip(oms, ot.q, ot.h_ratio):
        q_vy, h_vy = _vy_q_h(om, 0.1, 0.3)
        ratio = abs(q1) / abs(q_vy)
        assert 0.9505 <= ratio <= 0.9945, (om, ratio)
        assert abs(h1 - abs(h_vy)) < 0.1 * abs(h_vy)     # "within 10 % for omega < 2 omega_1"
    # static ratio 16/(14 zeta(3)) exactly, and the missed second resonance at 3 omega_1
    q_vy, _ = _vy_q_h(3.0, 0.1, 0.3)
    assert abs(walls.one_term(3.0, 0.1, 0.3).q) / abs(q_vy) == pytest.approx(0.787, abs=1e-3)


def test_array_omega_matches_scalars():
    oms = np.array([[0.0, 0.3], [1.2, 2.5]])
    r = walls.one_term(oms, 0.15, 0.28, n=0.4, l_over_h=3.0)
    assert r.q.shape == (2, 2) and r.h_ratio.shape == (2, 2)
    for idx in np.ndindex(oms.shape):
        s = walls.one_term(float(oms[idx]), 0.15, 0.28, n=0.4, l_over_h=3.0)
        assert isinstance(s.q, complex) and isinstance(s.h_ratio, float)
        for field in walls.OneTerm._fields:
            assert getattr(r, field)[idx] == getattr(s, field)
    assert np.allclose(r.m, r.q * r.h_ratio, rtol=1e-15, atol=0)


# ------------------------------------------------------------------ rotational spring, pair

def test_rotational_spring_tables():
    nu = 1 / 3
    for d, ratio in zip([0, 0.25, 0.5, 1, 2, 5], [1, 0.7681, 0.6235, 0.4529, 0.2928, 0.1421]):
        r = walls.one_term(0.0, 0.0, nu, d_theta=d)
        assert r.flex.real == pytest.approx(ratio, abs=5e-5)
        assert r.flex.real == pytest.approx(1 / (1 + psi_sigma(nu) * 2 / PI * d), rel=1e-14)
    for om, qf, qr in zip([0, 0.5, 1.0, 1.5], [0.4428, 0.5505, 2.4087, 0.5227],
                          [0.9791, 1.1284, 3.1039, 0.8765]):
        assert abs(walls.one_term(om, 0.1, nu, d_theta=1.0).q) == pytest.approx(qf, abs=5e-5)
        assert abs(walls.one_term(om, 0.1, nu).q) == pytest.approx(qr, abs=5e-5)


@pytest.mark.parametrize("d_theta", [0.1, 1.0, 30.0])
def test_rotational_spring_equilibrium(d_theta):
    r = walls.one_term(0.9, 0.05, 0.25, n=0.6, d_theta=d_theta)
    # K_R theta = M (2.91): u0 = -m d_theta (u0 in rho Xg H^2/G_H, m in rho Xg H^3)
    assert r.u0 == pytest.approx(-r.m * d_theta, rel=1e-13)
    assert r.u0 == pytest.approx((1 - r.flex) * r.u_ff0, rel=1e-13)
    assert r.theta == r.u0
    # wall face: u(0, y) = u0 Phi(y); pressure scales with F
    y = 0.35
    phi = 1 - (1 - y) ** 1.4
    assert walls.one_term_displacement(0.9, 0.05, 0.25, 0.0, y, n=0.6, d_theta=d_theta) == \
        pytest.approx(r.u0 * phi, rel=1e-14)


def test_rotational_spring_limits():
    r = walls.one_term(0.5, 0.1, 0.3, d_theta=np.inf)
    assert r.q == 0 and r.u0 == r.u_ff0 and r.flex == 0
    big = walls.one_term(0.5, 0.1, 0.3, d_theta=1e15)
    assert abs(big.q) < 1e-14 and big.u0 == pytest.approx(big.u_ff0, rel=1e-14)
    rigid = walls.one_term(0.5, 0.1, 0.3, d_theta=0.0)
    assert rigid.u0 == 0 and rigid.flex == 1


def test_pair_lambda_table():
    static = [0.2468, 0.4652, 0.7649, 0.9651, 0.9953, 0.99992]
    d05 = [0.2152, 0.4114, 0.7038, 0.9414, 0.9896, 0.99968]
    d10 = [0.0795, 0.1588, 0.3166, 0.6200, 0.8761, 1.1057]
    for lh, a, b, c in zip([0.5, 1, 2, 4, 6, 10], static, d05, d10):
        half_unit = 5e-6 if lh == 10 else 5e-5          # the table's last decimal
        assert walls.one_term(0.0, 0.0, 0.3, l_over_h=lh).lam.real == pytest.approx(
            a, abs=half_unit)
        assert abs(walls.one_term(0.5, 0.1, 0.3, l_over_h=lh).lam) == pytest.approx(
            b, abs=half_unit)
        r = walls.one_term(1.0, 0.1, 0.3, l_over_h=lh)
        assert abs(r.lam) == pytest.approx(c, abs=5e-5)
        s = mp.sqrt(mp.mpc((PI / 2) ** 2) - (PI / 2) ** 2 / mp.mpc(1, 0.1))
        ml = complex(s) * lh / psi_e(0.3)
        assert r.lam == pytest.approx(complex(mp.tanh(ml / 2)), rel=1e-13)


def test_pair_displacement_corrected_b():
    lh, om, d, nu = 2.5, 0.7, 0.1, 0.3
    r = walls.one_term(om, d, nu, l_over_h=lh)
    x = np.array([0.0, 0.4, 1.25, 2.0, lh])
    u = walls.one_term_displacement(om, d, nu, x, 1.0, l_over_h=lh)
    assert u[0] == 0 and u[-1] == 0
    # (2.101)-(2.103) with mpmath exponentials: A, corrected B = +c (e^mL - 1)/(e^mL - e^-mL)
    mp.mp.dps = 30
    c = -mp.mpc(r.u_ff0)
    m = mp.sqrt(mp.mpc((PI / 2) ** 2) - mp.mpf(om * PI / 2) ** 2 / mp.mpc(1, d)) / psi_e(nu)
    den = mp.exp(m * lh) - mp.exp(-m * lh)
    A = -c * (mp.exp(-m * lh) - 1) / den
    B = c * (mp.exp(m * lh) - 1) / den
    for xi, ui in zip(x[1:-1], u[1:-1]):
        ref = A * mp.exp(m * xi) + B * mp.exp(-m * xi) - c
        assert ui == pytest.approx(complex(ref), rel=1e-12)
    printed = A * mp.exp(m * lh) - B * mp.exp(-m * lh) - c      # (2.102b) as printed
    assert abs(printed) > 0.1 * abs(c)
    assert abs(A * mp.exp(m * lh) + B * mp.exp(-m * lh) - c) < 1e-25 * abs(c)


def test_pair_huge_spacing_and_refusal():
    single = walls.one_term(0.5, 0.1, 0.3)
    for lh in (1e6, 1e300):
        r = walls.one_term(0.5, 0.1, 0.3, l_over_h=lh)
        assert r.lam == 1 and r.q == single.q
    u = walls.one_term_displacement(0.5, 0.1, 0.3, [0.0, 5e299, 1e300], 1.0, l_over_h=1e300)
    assert u[0] == 0 and u[2] == 0 and u[1] == pytest.approx(single.u_ff0, rel=1e-15)
    with pytest.raises(InvalidInputError, match=r"^d_theta"):
        walls.one_term(0.5, 0.1, 0.3, d_theta=1.0, l_over_h=4.0)


# ------------------------------------------------------------------ pressure and displacement

@pytest.mark.parametrize("shape,n,d_theta,lh", [("sine", 0.0, 0.0, np.inf),
                                                ("linear", 0.0, 0.5, np.inf),
                                                ("power", 0.5, 0.0, 3.0),
                                                ("power", -0.5, 1.5, np.inf),
                                                ("power", 1.5, 0.0, np.inf)])
def test_pressure_integrates_to_q_and_m(shape, n, d_theta, lh):
    om, d, nu = 0.8, 0.1, 0.3
    r = walls.one_term(om, d, nu, shape, n, d_theta, lh)

    def p(y):
        return walls.one_term_pressure(om, d, nu, y, shape, n, d_theta, lh)

    kw = dict(limit=200, epsabs=1e-14, epsrel=1e-12)
    q = complex(integrate.quad(lambda y: p(y).real, 0, 1, **kw)[0],
                integrate.quad(lambda y: p(y).imag, 0, 1, **kw)[0])
    m = complex(integrate.quad(lambda y: (p(y) * y).real, 0, 1, **kw)[0],
                integrate.quad(lambda y: (p(y) * y).imag, 0, 1, **kw)[0])
    assert q == pytest.approx(r.q, rel=1e-9)
    assert m == pytest.approx(r.m, rel=1e-9)


def test_pressure_shape_and_endpoints():
    y = np.linspace(0.0, 1.0, 11)
    p = walls.one_term_pressure(0.6, 0.1, 0.3, y, n=0.5)
    assert p.shape == (11,) and p[0] == 0 and p[-1] == 0       # G(H) = 0 for n > 0
    g_phi = (1 - y) ** 0.5 * (1 - (1 - y) ** 1.5)
    assert p[1:-1] / p[5] == pytest.approx(g_phi[1:-1] / g_phi[5], rel=1e-13)
    assert isinstance(walls.one_term_pressure(0.6, 0.1, 0.3, 0.5), complex)
    with pytest.raises(InvalidInputError, match=r"^y\[1\]"):
        walls.one_term_pressure(0.6, 0.1, 0.3, [0.5, 1.0], n=-0.3)   # unbounded at the surface


def test_displacement_free_field_and_broadcast():
    om, d, nu = 0.6, 0.1, 0.3
    r = walls.one_term(om, d, nu)
    x = np.array([0.0, 1e-10, 1.0, 400.0])[:, None]
    y = np.array([0.0, 0.5, 1.0])[None, :]
    u = walls.one_term_displacement(om, d, nu, x, y)
    assert u.shape == (4, 3)
    phi = np.sin(PI * y / 2)
    assert np.all(u[0] == 0) and np.all(u[:, 0] == 0)
    assert u[3] == pytest.approx(r.u_ff0 * phi[0], rel=1e-14)
    mp.mp.dps = 30
    s = mp.sqrt(mp.mpc((PI / 2) ** 2) - mp.mpf(om * PI / 2) ** 2 / mp.mpc(1, d))
    for i, xi in enumerate([1e-10, 1.0]):
        ref = complex(r.u_ff0 * (1 - mp.exp(-s * mp.mpf(xi) / psi_e(nu))))
        assert u[i + 1, 2] == pytest.approx(ref, rel=1e-13)
    # static power law free field (A.7): -(1 - (1 - y)^(2 - n))/(2 - n)
    uf = walls.one_term_displacement(0.0, 0.0, 0.3, 1e3, [0.3, 1.0], n=0.8)
    assert uf == pytest.approx([-(1 - 0.7 ** 1.2) / 1.2, -1 / 1.2], rel=1e-13)


# ------------------------------------------------------------------ Winkler springs

def test_winkler_values():
    k0 = walls.winkler_spring([0.0, 0.5, 2.0], 0.0, 0.3)
    assert k0[0].real == pytest.approx(2.8799, abs=5e-5)
    assert k0[1].real == pytest.approx(2.4941, abs=5e-5)
    assert k0[2].real == 0 and k0[2].imag == pytest.approx(4.9881, abs=5e-5)
    k1 = walls.winkler_spring([0.0, 0.5, 1.0, 2.0], 0.1, 0.3)
    ref = [2.8799 + 0.2880j, 2.4944 + 0.2909j, 0.6126 + 0.6769j, -0.1659 + 4.9992j]
    assert np.abs(k1 - ref).max() < 1e-4
    for nu, ks in zip([0.25, 0.3, 1 / 3, 0.4], [2.742, 2.880, 2.980, 3.206]):
        assert walls.winkler_spring(0.0, 0.0, nu).real == pytest.approx(ks, abs=5e-4)
    # (2.111) dashpot: k = i omega c at delta = 0 above the cut-off
    c = walls.winkler_dashpot([1.0, 2.0, 3.0], 0.3)
    assert c[0] == 0
    assert 1j * (PI / 2) * np.array([2.0, 3.0]) * c[1:] == pytest.approx(k0[2:].tolist() + [
        walls.winkler_spring(3.0, 0.0, 0.3)], rel=1e-14)
    with pytest.raises(InvalidInputError, match=r"^omega_ratio.*cut-off"):
        walls.winkler_dashpot(0.9, 0.3)
    assert walls.scott_spring([0.3, 0.4, 0.45]) == pytest.approx([1.4, 2.4, 4.4], rel=1e-13)
    with pytest.raises(InvalidInputError, match=r"^nu"):
        walls.scott_spring(0.5)


def test_vy_spring_branch_and_static():
    psi_o = math.sqrt(2 / 0.7)
    assert walls.vy_spring(1, 0.0, 0.0, 0.3) == pytest.approx(PI / 2 * psi_o, rel=1e-15)
    assert walls.vy_spring(3, 0.0, 0.0, 0.3) == pytest.approx(5 * PI / 2 * psi_o, rel=1e-15)
    k = walls.vy_spring(1, [0.5, 2.0], 0.1, 0.3)
    ks = walls.winkler_spring([0.5, 2.0], 0.1, 0.3)
    assert k == pytest.approx(ks * psi_o / psi_sigma(0.3), rel=1e-14)
    assert k[1].imag > 0      # radiation dashpot; principal sqrt of the product: Im < 0
    prod = PI / 2 * psi_o * np.sqrt((1 + 0.1j) * (1 - 4 + 0.1j))
    assert prod.imag < 0 and k[1] == pytest.approx(-prod, rel=1e-14)
    for bad in (0, 1.5, "1", True):
        with pytest.raises(InvalidInputError, match=r"^mode"):
            walls.vy_spring(bad, 0.5, 0.1, 0.3)


def test_winkler_power_law_depth_factor():
    om, d, nu, n = 0.7, 0.1, 0.3, 0.5
    k = walls.winkler_spring(om, d, nu, n=n)
    y = np.array([0.2, 0.6])
    p = walls.one_term_pressure(om, d, nu, y, n=n)
    uff = walls.one_term_displacement(om, d, nu, 1e4, y, n=n)
    assert -p / uff == pytest.approx(k * (1 - y) ** n, rel=1e-12)


# ------------------------------------------------------------------ branch, resonance

def test_branch_delta_to_zero_plus():
    for kw in (dict(), dict(shape="linear", l_over_h=3.0), dict(n=-0.5, d_theta=0.7)):
        r0 = walls.one_term(1.8, 0.0, 0.3, **kw)
        re = walls.one_term(1.8, 1e-11, 0.3, **kw)
        assert r0.q == pytest.approx(re.q, rel=1e-8)
        assert r0.u_ff0 == pytest.approx(re.u_ff0, rel=1e-8)
    assert walls.winkler_spring(1.8, 0.0, 0.3) == pytest.approx(
        walls.winkler_spring(1.8, 1e-11, 0.3), rel=1e-8)


def test_resonance_raises_singular():
    with pytest.raises(SingularError, match=r"^omega_ratio"):
        walls.one_term(1.0, 0.0, 0.3)
    with pytest.raises(SingularError):
        walls.one_term([0.5, 1.0], 0.0, 0.3)
    with pytest.raises(SingularError):
        walls.one_term_pressure(1.0, 0.0, 0.3, 0.5)
    assert abs(walls.one_term(1.0, 1e-6, 0.3).q) > 500


# ------------------------------------------------------------------ power-law frequency

def _first_zero_mpmath(q):
    mp.mp.dps = 30
    if q >= 0:
        return mp.besseljzero(q, 1)
    # q in (-1, 0): J_q -> +inf at 0+, so the first sign change on a grid is j_(q,1)
    x, f = mp.mpf("0.01"), mp.besselj(q, mp.mpf("0.01"))
    while True:
        x2 = x + mp.mpf("0.01")
        f2 = mp.besselj(q, x2)
        if f * f2 < 0:
            return mp.findroot(lambda t: mp.besselj(q, t), (x, x2), solver="anderson")
        x, f = x2, f2


@pytest.mark.parametrize("n", [-0.999, -0.99, -0.7, -0.3, 0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0,
                               1.3, 1.5, 1.75, 1.9, 1.95, 1.99])
def test_power_law_fundamental_mpmath(n):
    q = (n - 1) / (2 - n)
    ref = (2 - n) / 2 * _first_zero_mpmath(q)
    assert walls.power_law_fundamental(n) == pytest.approx(float(ref), rel=2e-15)


def _layer_shoot(n, omega):
    """u(rock) of the power-law layer from its Frobenius series at the surface (tau = 0):
    (t^n u')' + omega^2 u = 0, u = sum c_k t^((2-n) k), evaluated at t = 1 (mpmath)."""
    a, w2 = 2.0 - n, omega ** 2
    # working precision from the largest term (the series cancels down to O(1))
    logmax, lc, k = 0.0, 0.0, 0
    while True:
        k += 1
        lc += math.log10(w2) - math.log10(a * k * (a * (k - 1) + 1))
        logmax = max(logmax, lc)
        if lc < -400 and lc < logmax:     # terms below 1e-400 and falling (for large q the
            break                         # sum itself is exponentially small below the zero)
    with mp.workdps(int(logmax) + 450):
        a = mp.mpf(2) - mp.mpf(n)     # n, omega: exact binary values
        w2 = mp.mpf(omega) ** 2
        c, s = mp.mpf(1), mp.mpf(1)
        for j in range(1, k + 1):
            c = -c * w2 / (a * j * (a * (j - 1) + 1))
            s += c
        return s


@pytest.mark.parametrize("n", [-0.9, 0.0, 0.6, 1.2, 1.99, 1.999])
def test_power_law_fundamental_shooting(n):
    """Independent of Bessel theory: the rock displacement of the free layer changes sign
    at the returned frequency and at no lower frequency."""
    w = walls.power_law_fundamental(n)
    assert _layer_shoot(n, w * (1 - 1e-13)) > 0 > _layer_shoot(n, w * (1 + 1e-13))
    assert all(_layer_shoot(n, w * f) > 0 for f in np.linspace(0.05, 0.95, 10))


@pytest.mark.parametrize("n", [1.999, 1.9999, 2 - 2e-6, 2 - 1e-7])
def test_power_law_fundamental_large_order(n):
    """q = (n - 1)/(2 - n) from 1e3 to 1e7 (the last past the switch to the Qu-Wong bound):
    x J_q(x)/J_(q+1)(x) by backward recurrence of its continued fraction in mpmath (40 digits,
    20000 terms, far past the turning region ~ q^(1/3)) changes sign within 1e-13 of the
    returned zero."""
    w = walls.power_law_fundamental(n)
    with mp.workdps(40):
        q = (mp.mpf(n) - 1) / (2 - mp.mpf(n))
        x = 2 * mp.mpf(w) / (2 - mp.mpf(n))

        def t_q(z):
            t = 2 * (q + 20001)
            for k in range(20000, 0, -1):
                t = 2 * (q + k) - z * z / t
            return t

        assert t_q(x * (1 - mp.mpf("1e-13"))) > 0 > t_q(x * (1 + mp.mpf("1e-13")))


def test_power_law_fundamental_table_and_cutoff():
    ns = np.array([0.0, 0.25, 0.5, 0.75, 1.0])
    w1 = walls.power_law_fundamental(ns)
    assert w1 == pytest.approx([1.57080, 1.48789, 1.39976, 1.30520, 1.20241], abs=5e-6)
    wc = walls.power_law_cutoff(ns)
    assert wc == pytest.approx([1.58114, 1.5, 1.41421, 1.32288, 1.22474], abs=5e-6)
    assert np.all((wc / w1 > 1.006) & (wc / w1 < 1.02))
    # the one-term cut-off in omega_ratio units: omega_ref = pi V_SH/(2H)
    c = walls.shape_constants("power", 0.5)
    assert c.a_oc / math.sqrt(c.mass_factor) == pytest.approx(wc[2], rel=1e-15)
    near = walls.one_term(wc[2] / (PI / 2) * (1 - 1e-9), 0.0, 0.3, n=0.5)
    assert abs(near.q) > 1e3 and near.q.imag == 0      # undamped, just below the cut-off


def test_power_law_fundamental_near_two():
    w = walls.power_law_fundamental([1.999, 2 - 1e-7, 2 - 1e-12])
    assert np.all(np.diff(w) < 0) and np.all(w > 0.5)
    assert w[-1] == pytest.approx(0.5, rel=1e-7)
    for n, wi in zip([2 - 1e-7, 2 - 1e-12], w[1:]):
        q = (n - 1) / (2 - n)
        lo = (2 - n) / 2 * (q + 1.8557570814892386 * q ** (1 / 3))
        hi = lo + (2 - n) / 2 * 1.0331503036492369 * q ** (-1 / 3)
        assert lo * (1 - 1e-15) <= wi <= hi * (1 + 1e-15)


# ------------------------------------------------------------------ bad input

@pytest.mark.parametrize("kwargs,name", [
    (dict(omega_ratio=-1.0), "omega_ratio"), (dict(omega_ratio=np.nan), "omega_ratio"),
    (dict(delta=-0.1), "delta"), (dict(nu=0.5), "nu"), (dict(nu=-0.1), "nu"),
    (dict(shape="cosine"), "shape"), (dict(shape="sine", n=0.5), "n"),
    (dict(n=2.0), "n"), (dict(n=-1.0), "n"), (dict(n=np.nan), "n"),
    (dict(d_theta=-1.0), "d_theta"), (dict(d_theta=np.nan), "d_theta"),
    (dict(l_over_h=0.0), "l_over_h"), (dict(l_over_h=np.nan), "l_over_h"),
    (dict(l_over_h=-np.inf), "l_over_h"), (dict(omega_ratio="a"), "omega_ratio"),
    (dict(delta=[0.1, 0.2]), "delta")])
def test_bad_input_names_parameter(kwargs, name):
    args = dict(omega_ratio=0.5, delta=0.1, nu=0.3)
    args.update(kwargs)
    with pytest.raises(InvalidInputError, match="^" + name):
        walls.one_term(**args)


def test_bad_input_other_routines():
    with pytest.raises(InvalidInputError, match=r"^x\[1\]"):
        walls.one_term_displacement(0.5, 0.1, 0.3, [1.0, 3.0], 0.5, l_over_h=2.0)
    with pytest.raises(InvalidInputError, match=r"^x\[0\]"):
        walls.one_term_displacement(0.5, 0.1, 0.3, -1.0, 0.5)
    with pytest.raises(InvalidInputError, match=r"^y\[2\]"):
        walls.one_term_displacement(0.5, 0.1, 0.3, 1.0, [0.1, 0.2, 1.5])
    with pytest.raises(InvalidInputError, match="shapes do not broadcast"):
        walls.one_term_displacement(0.5, 0.1, 0.3, [1.0, 2.0], [0.1, 0.2, 0.3])
    with pytest.raises(InvalidInputError, match=r"^omega_ratio"):
        walls.one_term_pressure([0.5, 0.6], 0.1, 0.3, 0.5)
    with pytest.raises(InvalidInputError, match=r"^n"):
        walls.power_law_fundamental([0.5, 2.5])
    with pytest.raises(InvalidInputError, match=r"^n"):
        walls.power_law_cutoff(-1.0)
    with pytest.raises(InvalidInputError, match=r"^shape"):
        walls.shape_constants("square")
    with pytest.raises(InvalidInputError, match=r"^n"):
        walls.shape_constants("linear", 1.0)
    with pytest.raises(InvalidInputError, match=r"^delta"):
        walls.winkler_spring(0.5, -1.0, 0.3)
    with pytest.raises(InvalidInputError, match=r"^nu"):
        walls.vy_spring(1, 0.5, 0.1, 0.7)
