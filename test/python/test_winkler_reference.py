"""Self-tests of the independent Winkler rocking reference (winkler_reference.py): its
contact quadrature against the printed closed forms of the full and partial contact, a
free drop (touch-down at sqrt(2 d/g)), static rest at W/(k A), the work balance of its
equations of motion, Radau against BDF, a block held by a steady lateral force against
its static closed form, and a one-sine pulse of T = 19 s against the static pushover of
the constant-k circle. Nothing here uses the library."""
import math

import numpy as np
import pytest

pytest.importorskip("scipy")
from scipy.optimize import brentq  # noqa: E402

import winkler_reference as wr  # noqa: E402

E_SOIL, NU = 100e6, 0.3           # Pa, -


def thesis_cylinder():
    """r = 1 m, h = 3 m, solid, rho = 2500 kg/m^3 on E = 100 MPa, nu = 0.3 (k in N/m^3)."""
    body = wr.solid_cylinder(1.0, 3.0, rho=2500.0)
    return body, wr.modulus_circle(E_SOIL / (2 * (1 + NU)), NU, 1.0)


@pytest.mark.parametrize("footing", ["circle", "rectangle"])
def test_contact_full(footing):
    """Full contact: N = cos(theta) (k v + c v') A, M = -cos^2(theta) (k sin(theta) +
    c cos(theta) theta') I (the first moment of the base vanishes)."""
    body = wr.solid_cylinder(0.8, 2.0, rho=2000.0) if footing == "circle" else \
        wr.solid_block(0.6, 1.1, 2.0, rho=2000.0)
    k, c = 5e7, 3e5
    y = (2e-3, 1e-3, 1e-3, -0.02)
    n, m, width = wr.contact_quad(body, k, c, y)
    sn, cs = math.sin(y[1]), math.cos(y[1])
    assert width == 2 * body.r
    assert n == pytest.approx(cs * (k * y[0] + c * y[2]) * body.area, rel=1e-12)
    assert m == pytest.approx(-cs * cs * (k * sn + c * cs * y[3]) * body.inertia, rel=1e-12)


@pytest.mark.parametrize("b", [1e-3, 0.1, 0.7, 1.0, 1.6, 1.999])
def test_contact_partial_circle_closed_forms(b):
    """Uplift (c = 0), contact width b from the compressed edge s = -r: with c_ = r - b,
    S = sqrt(2 r b - b^2), A0 = r^2 acos(c_/r) - c_ S, J1 = 2/3 S^3, J2 = r^4/4 (pi/2 -
    asin(c_/r)) - c_/4 (2 c_^2 - r^2) S: N = k sin cos Phi, Phi = J1 - c_ A0, and
    M = -k sin cos^2 (J2 - c_ J1), evaluated with mpmath at 40 digits (they cancel for
    slivers). The quadrature keeps 1e-11 down to b = 1e-3 r."""
    mp = pytest.importorskip("mpmath").mp
    r, k, th = 1.0, 2e8, 0.05
    body = wr.solid_cylinder(r, 3.0, rho=2500.0)
    s0 = b - r                              # the root of delta
    v = s0 * math.sin(th)
    n, m, width = wr.contact_quad(body, k, 0.0, (v, th, 0.0, 0.0))
    with mp.workdps(40):
        bb, rr = mp.mpf(b), mp.mpf(r)
        cc = rr - bb
        s = mp.sqrt(2 * rr * bb - bb * bb)
        a0 = rr * rr * mp.acos(cc / rr) - cc * s
        j1 = mp.mpf(2) / 3 * s ** 3
        j2 = rr ** 4 / 4 * (mp.pi / 2 - mp.asin(cc / rr)) - cc / 4 * (2 * cc * cc - rr * rr) * s
        sn, cs = mp.sin(mp.mpf(th)), mp.cos(mp.mpf(th))
        n_ref = float(k * sn * cs * (j1 - cc * a0))
        m_ref = float(-k * sn * cs * cs * (j2 - cc * j1))
    assert width == pytest.approx(b, rel=1e-13)
    assert n == pytest.approx(n_ref, rel=1e-11)
    assert m == pytest.approx(m_ref, rel=1e-11)


def test_contact_dashpot_ends():
    """The end of the active interval is the root of k delta + c delta' when the contact
    edge lifts faster than the springs unload, that of delta otherwise (rectangle, where
    the integrals are elementary: N = 2 alpha cos(theta) int q ds)."""
    body = wr.solid_block(1.0, 0.5, 2.0, rho=2000.0)
    k, c = 1e8, 2e6
    th, v = 0.01, 0.002                     # delta root at s = 0.2 (rad, m)
    for vd, thd in ((0.0, 0.5), (0.0, -0.5)):
        sn, cs = math.sin(th), math.cos(th)
        s_q = (k * v + c * vd) / (k * sn + c * cs * thd)
        hi = min(v / sn, s_q) if k * sn + c * cs * thd > 0 else v / sn
        n, _, width = wr.contact_quad(body, k, c, (v, th, vd, thd))
        a0, a1 = k * v + c * vd, k * sn + c * cs * thd
        expect = 2 * body.alpha * cs * (a0 * (hi + 1) - a1 * (hi * hi - 1) / 2)
        assert width == pytest.approx(hi + 1, rel=1e-13)
        assert n == pytest.approx(expect, rel=1e-12)


def test_free_drop_touches_down_at_sqrt_2d_over_g():
    body, k = thesis_cylinder()
    d = 1e-3
    run = wr.simulate(body, k, wr.damping_vertical(body, k, 0.05), lambda t: 0.0,
                      np.linspace(0.0, 0.03, 31), v0=-d)
    assert run.t_lift_off == 0.0
    assert run.t_touch_down == pytest.approx(math.sqrt(2 * d / body.g), rel=1e-10)
    # no rocking from a vertical drop
    assert np.max(np.abs(run.theta)) < 1e-15 and run.n_impacts == 0   # rounding only


@pytest.mark.parametrize("footing", ["circle", "rectangle"])
def test_static_rest_at_w_over_k_a(footing):
    """From half the static settlement with vertical damping xi = 0.5 the base settles at
    v = W/(k A) (the vertical period 2 pi sqrt(m/(k A)) ~ 0.06 s; 1 s of decay)."""
    body = wr.solid_cylinder(1.0, 3.0, rho=2500.0) if footing == "circle" else \
        wr.solid_block(1.0, 0.8, 3.0, rho=2500.0)
    k = 1.5e8
    v_s = body.weight / (k * body.area)
    run = wr.simulate(body, k, wr.damping_vertical(body, k, 0.5), lambda t: 0.0,
                      np.linspace(0.0, 1.0, 11), v0=0.5 * v_s, method="BDF")
    assert run.v[-1] == pytest.approx(v_s, rel=1e-8)
    assert run.normal[-1] == pytest.approx(body.weight, rel=1e-8)
    assert math.isnan(run.t_uplift)


@pytest.mark.parametrize("c_xi", [0.0, 0.003])
def test_work_balance_and_radau_vs_bdf(c_xi):
    """Free rocking with uplift and two impacts from theta0 = 0.01 rad (5 theta_up): the
    kinetic + gravity energy changes by the work of the contact forces (integrated along,
    state 5) to 1e-8 of the energy exchanged, and Radau (rtol 1e-9) and BDF (rtol 1e-10)
    agree to 1e-6 theta_max and the impact times to 1e-7 s."""
    body, k = thesis_cylinder()
    c = wr.damping_rocking(body, k, c_xi)
    t = np.linspace(0.0, 0.8, 81)
    runs = [wr.simulate(body, k, c, lambda t: 0.0, t, theta0=0.01, method=m, rtol=rtol)
            for m, rtol in (("Radau", 1e-9), ("BDF", 1e-10))]
    for run in runs:
        e = run.energy(body)
        assert run.n_impacts >= 2 and run.t_uplift == 0.0
        assert np.ptp(e - run.work) < 1e-8 * np.ptp(e)
    assert np.max(np.abs(runs[0].theta - runs[1].theta)) < 1e-6 * runs[0].theta_max
    np.testing.assert_allclose(runs[0].t_impacts, runs[1].t_impacts, rtol=0, atol=1e-7)


def test_block_under_steady_force_matches_static_closed_form():
    """A block (b = 0.5 m, alpha = 0.6 m, h = 1.5 m) under a_g = F/m reached by a ramp of
    2 s and then held, with critical rocking damping (xi = 1: 6 s of decay), rests at the
    static angle of the closed forms after uplift: theta = asin(2 W/(alpha b'^2 k))/2 (b'
    the contact width), M = 2 alpha k sin cos^2 [(b^3 - c^3)/3 - c (b^2 - c^2)/2]
    (c = b - b'), F = (M - W h sin)/(h cos); F = 3/4 of the peak of F (0.197 W), past the
    uplift (0.104 W)."""
    b, alpha, h, k = 0.5, 0.6, 1.5, 2e7
    body = wr.solid_block(b, alpha, h, rho=2500.0)
    w = body.weight

    def static(bp):
        th = 0.5 * math.asin(2 * w / (alpha * bp * bp * k))
        cc = b - bp
        mom = 2 * alpha * k * math.sin(th) * math.cos(th) ** 2 * (
            (b ** 3 - cc ** 3) / 3 - cc * (b * b - cc * cc) / 2)
        return th, (mom - w * h * math.sin(th)) / (h * math.cos(th))

    bp_min = math.sqrt(2 * w / (alpha * k)) * 1.0000001
    grid = np.linspace(bp_min, 2 * b, 4001)
    forces = np.array([static(x)[1] for x in grid])
    i_peak = int(np.argmax(forces))
    f = 0.75 * forces[i_peak]
    bp = brentq(lambda x: static(x)[1] - f, grid[i_peak], 2 * b, xtol=1e-15)
    theta_s = static(bp)[0]
    assert bp < 2 * b                           # after uplift
    run = wr.simulate(body, k, wr.damping_rocking(body, k, 1.0),
                      lambda t: f / body.mass * min(t / 2, 1.0), np.linspace(0.0, 8.0, 17),
                      breakpoints=[2.0], method="BDF")
    assert run.theta[-1] == pytest.approx(theta_s, rel=1e-7)
    assert run.width[-1] == pytest.approx(bp, rel=1e-7)
    assert run.normal[-1] == pytest.approx(w, rel=1e-9)


def test_quasi_static_sine_follows_the_static_pushover():
    """One sine cycle of T = 19 s, a_p = 0.2 g, on the thesis cylinder (xi = 0.003): theta(t)
    follows the static pushover theta(F = m a_g(t)) of the constant-k circle (closed forms
    before and after uplift, winkler_reference.circle_static_theta). The start of the
    pulse (slope a_p 2 pi/T) excites the free rocking, amplitude ~ (2 pi/T)/omega_r of the
    static angle ~ 2 % (omega_r = 15.9 rad/s), larger where the tangent stiffness falls
    near the peak of F (0.245 W): the bound 3.5 % of the static peak holds with margin
    (largest 3.0 %), and the mean of the difference over the pulse is below 0.3 %."""
    body, k = thesis_cylinder()
    accel, breaks = wr.sine_pulse(0.2 * body.g, 19.0)
    t = np.linspace(0.0, 19.0, 761)
    run = wr.simulate(body, k, wr.damping_rocking(body, k, 0.003), accel, t, breaks,
                      method="BDF", rtol=1e-8)
    static = wr.circle_static_theta(1.0, 3.0, body.weight, k,
                                    body.mass * np.array([accel(x) for x in t]))
    peak = np.max(np.abs(static))
    assert peak == pytest.approx(wr.circle_static_theta(1.0, 3.0, body.weight, k,
                                                        0.2 * body.weight), rel=1e-3)
    diff = run.theta - static
    assert np.max(np.abs(diff)) < 0.035 * peak
    assert abs(np.mean(diff)) < 0.003 * peak
    assert 1.0 < run.t_uplift < 1.6 and math.isnan(run.t_overturn)
