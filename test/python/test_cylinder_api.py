"""seispulse.cylinder: rigid cylinders rocking on a rigid base. Every expected value is
computed here independently of the library: the inertia and pushover formulas written out,
Housner's free-rocking period of the linearized equation, the uniform block of
seispulse.rocking, and overturning thresholds from Housner's nonlinear equations integrated
with scipy's solve_ivp (DOP853) event by event and bisected on the amplitude."""
import math

import numpy as np
import pytest

from seispulse import cylinder as C
from seispulse import pulse as P
from seispulse import rocking as R
from seispulse.errors import InvalidInputError

G = 9.80665


def solid(r, h, m=1.0):
    """J_o, p, restitution, theta_c, R of a solid cylinder, by the parallel-axis theorem."""
    big_r = math.hypot(r, h)
    j_g = m * (3 * r * r + 4 * h * h) / 12
    j_o = j_g + m * big_r ** 2
    theta_c = math.atan(r / h)
    p = math.sqrt(m * G * big_r / j_o)
    e = 1 - 2 * m * big_r ** 2 / j_o * math.sin(theta_c) ** 2
    return j_o, p, e, theta_c, big_r


# ------------------------------------------------------------------ properties

@pytest.mark.parametrize("r, h, m", [(1.0, 2.0, 1.0), (0.3, 1.7, 250.0), (2.0, 0.5, 3.5e4)])
def test_solid_cylinder_identities(r, h, m):
    b = C.props(r, h, mass=m)
    j_o, p, e, theta_c, big_r = solid(r, h, m)
    assert b.shape == "solid_cylinder" and b.g == G
    assert b.J_o == pytest.approx(5 / 4 * m * r * r + 4 / 3 * m * h * h, rel=1e-14)
    assert b.J_o == pytest.approx(j_o, rel=1e-14)
    assert b.J_G == pytest.approx(j_o - m * big_r ** 2, rel=1e-13)
    assert b.J_axis == pytest.approx(m * r * r / 2, rel=1e-14)
    assert b.theta_c == pytest.approx(theta_c, rel=1e-15)
    assert b.R == pytest.approx(big_r, rel=1e-15)
    assert b.p == pytest.approx(p, rel=1e-14)
    # closed form of Housner's restitution for a solid cylinder: 1 - 24 r^2/(15 r^2 + 16 h^2)
    assert b.restitution == pytest.approx(max(0.0, 1 - 24 * r * r / (15 * r * r + 16 * h * h)),
                                          rel=1e-13, abs=1e-15)
    assert b.restitution == pytest.approx(max(0.0, e), rel=1e-13, abs=1e-15)
    assert b.weight == pytest.approx(m * G, rel=1e-15)
    assert b.M_max == pytest.approx(m * G * r, rel=1e-15)
    assert b.F_uplift == pytest.approx(m * G * r / h, rel=1e-15)


def test_worked_numbers_h_over_r_2():
    """h/r = 2, r = 1 m: J_o/(m r^2) = 6.583, restitution 0.696, p = 1.825 rad/s."""
    b = C.props(1.0, 2.0)
    assert b.J_o == pytest.approx(6.583, abs=5e-4)
    assert b.restitution == pytest.approx(0.696, abs=5e-4)
    assert b.p == pytest.approx(1.825, abs=5e-4)


def test_hollow_custom_and_block():
    m, r, ri, h = 7.0, 0.8, 0.6, 2.5
    b = C.props(r, h, mass=m, r_inner=ri)
    assert b.shape == "hollow_cylinder" and b.r_inner == ri
    j_g = m * (3 * (r * r + ri * ri) + 4 * h * h) / 12
    assert b.J_G == pytest.approx(j_g, rel=1e-14)
    assert b.J_o == pytest.approx(j_g + m * (r * r + h * h), rel=1e-14)
    assert b.J_axis == pytest.approx(m * (r * r + ri * ri) / 2, rel=1e-14)
    c = C.props(r, h, mass=m, j_o=1.5 * m * (r * r + h * h))
    assert c.shape == "custom" and math.isnan(c.J_axis)
    assert c.p == pytest.approx(math.sqrt(G / (1.5 * math.hypot(r, h))), rel=1e-14)
    assert c.restitution == pytest.approx(1 - 2 / 1.5 * math.sin(math.atan(r / h)) ** 2,
                                          rel=1e-14)
    assert C.props(r, h, mass=m, j_o=1.5 * m * (r * r + h * h), j_axis=2.0).J_axis == 2.0
    blk = C.block_props(0.4, 1.2, mass=3.0)
    big_r = math.hypot(0.4, 1.2)
    assert blk.shape == "block" and math.isnan(blk.J_axis)
    assert blk.J_o == pytest.approx(4 / 3 * 3.0 * big_r ** 2, rel=1e-14)
    assert blk.J_G == pytest.approx(3.0 * (0.4 ** 2 + 1.2 ** 2) / 3, rel=1e-14)
    assert blk.p == pytest.approx(math.sqrt(3 * G / (4 * big_r)), rel=1e-14)
    assert blk.restitution == pytest.approx(1 - 1.5 * math.sin(math.atan(0.4 / 1.2)) ** 2,
                                            rel=1e-14)
    assert C.block_props(1.0, 2.0, g=9.81).g == 9.81


def test_equivalent_bodies_share_p_and_m_max():
    cyl = C.props(0.5, 2.0, mass=1200.0)
    blk = C.equivalent_block(cyl)
    assert blk.shape == "block"
    assert blk.p == pytest.approx(cyl.p, rel=1e-13)
    assert blk.M_max == pytest.approx(cyl.M_max, rel=1e-13)
    assert blk.theta_c == pytest.approx(cyl.theta_c, rel=1e-13)      # default slenderness
    assert blk.R == pytest.approx(3 * G / (4 * cyl.p ** 2), rel=1e-13)
    blk2 = C.equivalent_block(cyl, alpha=0.1)
    assert blk2.theta_c == pytest.approx(0.1, rel=1e-13)
    assert blk2.p == pytest.approx(cyl.p, rel=1e-13)
    assert blk2.M_max == pytest.approx(cyl.M_max, rel=1e-13)
    back = C.equivalent_cylinder(blk)
    assert back.shape == "solid_cylinder"
    for name in ("r", "h", "mass", "p", "M_max", "theta_c"):
        assert getattr(back, name) == pytest.approx(getattr(cyl, name), rel=1e-12), name
    other = C.equivalent_cylinder(blk, theta_c=0.3)
    assert other.theta_c == pytest.approx(0.3, rel=1e-13)
    assert other.p == pytest.approx(blk.p, rel=1e-13)
    assert other.M_max == pytest.approx(blk.M_max, rel=1e-13)


# ------------------------------------------------------------------ pushover

def test_rigid_pushover_closed_forms():
    r, h, m = 0.6, 1.8, 40.0
    w = m * G
    theta_c = math.atan(r / h)
    theta = np.array([0.0, 0.1, 0.5 * theta_c, theta_c, 0.4, -0.1])
    out = C.rigid_pushover(theta, r, h, mass=m)
    assert out.F[0] == pytest.approx(w * r / h, rel=1e-15)
    assert out.M[0] == pytest.approx(m * G * r, rel=1e-15)
    assert abs(out.M[3]) < 1e-12 * w * r and abs(out.F[3]) < 1e-12 * w
    th, sg = np.abs(theta), np.sign(theta + 0.0) + (theta == 0)   # theta < 0: the mirror image
    np.testing.assert_allclose(out.M, sg * w * (r * np.cos(th) - h * np.sin(th)), rtol=1e-13,
                               atol=1e-13 * w * r)
    np.testing.assert_allclose(out.F, sg * w * np.tan(theta_c - th), rtol=1e-13,
                               atol=1e-13 * w)
    np.testing.assert_array_equal(out.stable, [True, True, True, True, False, True])
    np.testing.assert_allclose(out.theta_normalized, theta / theta_c, rtol=1e-15)
    np.testing.assert_allclose(out.M_normalized, out.M / (m * G * r), rtol=1e-13, atol=1e-14)
    one = C.rigid_pushover(0.05, r, h, mass=m)
    assert isinstance(one.F, float) and one.stable is True
    grid = C.rigid_pushover(0.0, np.array([0.5, 1.0]), np.array([[1.0], [2.0]]))
    assert grid.F.shape == (2, 2)
    np.testing.assert_allclose(grid.F, G * np.array([[0.5, 1.0], [0.25, 0.5]]), rtol=1e-15)


def test_normalized_pushover_closed_form_and_midpoints():
    u = np.linspace(0.0, 1.0, 11)
    for theta_c in (0.05, 0.4636, 1.1):
        np.testing.assert_allclose(C.normalized_pushover(theta_c, u),
                                   np.sin(theta_c * (1 - u)) / np.sin(theta_c), rtol=1e-14,
                                   atol=1e-15)
    # u = 1/2: 0.514 (h/r = 2), 0.541 (h/r = 1), 0.588 (h/r = 1/2)
    for h_over_r, mid in ((2.0, 0.514), (1.0, 0.541), (0.5, 0.588)):
        assert C.normalized_pushover(math.atan(1 / h_over_r), 0.5) == pytest.approx(mid,
                                                                                     abs=5e-4)
    # the normalized curve is the dimensional one divided by m g r
    r, h = 1.0, 3.0
    out = C.rigid_pushover(u * math.atan(r / h), r, h, mass=2.0)
    np.testing.assert_allclose(out.M_normalized, C.normalized_pushover(math.atan(r / h), u),
                               rtol=1e-13, atol=1e-15)


# ------------------------------------------------------------------ planar rocking

def test_custom_body_equals_rocking_block():
    """A custom body with J_o = 4/3 m R^2 is the uniform block of seispulse.rocking."""
    b, h, m = 0.25, 1.0, 500.0
    body = C.props(b, h, mass=m, j_o=4 / 3 * m * (b * b + h * h))
    blk = R.rectangular_block(b, h)
    pulse = P.define("sine_cycle", amp=0.6, amp_unit="g", period=0.8)
    t = np.linspace(0.0, 6.0, 301)
    ours = C.simulate(body, pulse, t=t, t_max=6.0)
    ref = R.simulate(blk, pulse, t=t, t_max=6.0)
    assert isinstance(ours, R.RockingRun)
    assert ours.outcome == ref.outcome and ours.n_impacts == ref.n_impacts
    for name in ("t_uplift", "theta_max", "theta_min", "t_end"):
        assert getattr(ours, name) == pytest.approx(getattr(ref, name), rel=1e-11,
                                                    abs=1e-14), name
    np.testing.assert_allclose(ours.t_impacts, ref.t_impacts, rtol=1e-11)
    np.testing.assert_allclose(ours.theta, ref.theta, rtol=1e-9, atol=1e-12)
    assert C.rocking_block(body).e == pytest.approx(blk.e, rel=1e-14)
    assert C.rocking_block(body).p == pytest.approx(blk.p, rel=1e-14)


def test_vertical_excitation_is_passed_on():
    """kv and accel_v reach rocking.simulate: the same run as its block's, and an upward
    vertical acceleration kv a_g (gravity g + kv a_g) delays the uplift under a one-sine
    pulse to a_g (1 - kv tan(theta_c)) = g tan(theta_c)."""
    body = C.props(0.25, 1.0, mass=10.0)
    pulse = P.define("sine_cycle", amp=0.5, amp_unit="g", period=1.0)
    blk = C.rocking_block(body)
    for kv in (0.0, 0.4):
        ours = C.simulate(body, pulse, kv=kv, t_max=5.0)
        ref = R.simulate(blk, pulse, kv=kv, t_max=5.0)
        assert (ours.outcome, ours.t_uplift, ours.theta_max, ours.t_end) == \
            (ref.outcome, ref.t_uplift, ref.theta_max, ref.t_end)
    tan_c = 0.25
    t_up = math.asin(tan_c / (1 - 0.4 * tan_c) / 0.5) / (2 * math.pi)
    assert C.simulate(body, pulse, kv=0.4, t_max=5.0).t_uplift == pytest.approx(t_up, rel=1e-9)
    dt = 0.01
    tt = np.arange(200) * dt
    acc = 0.5 * G * np.sin(2 * np.pi * tt)
    acc[100:] = 0.0
    ours = C.simulate(body, accel=acc, dt=dt, accel_v=0.4 * acc, t_max=5.0)
    ref = R.simulate(blk, accel=acc, dt=dt, accel_v=0.4 * acc, t_max=5.0)
    assert ours.t_uplift == ref.t_uplift and ours.theta_max == ref.theta_max
    assert ours.t_uplift > C.simulate(body, accel=acc, dt=dt, t_max=5.0).t_uplift


def test_free_rocking_period_housner():
    """e = 1, linearized: theta = alpha - (alpha - theta0) cosh(p t) until the impact, so
    impacts come every T/2 = (2/p) acosh(1/(1 - theta0/alpha)) with the cylinder's p."""
    r, h = 0.3, 1.5
    _, p, _, alpha, _ = solid(r, h)
    body = C.props(r, h)
    for ratio in (0.2, 0.6):
        theta0 = ratio * alpha
        half = 2.0 / p * math.acosh(1.0 / (1.0 - ratio))
        run = C.simulate(body, accel=np.zeros(2), dt=0.01, e=1.0, linearized=True,
                         theta0=theta0, t_max=3.7 * half)
        assert run.n_impacts == 4
        np.testing.assert_allclose(run.t_impacts, half / 2 + half * np.arange(4), rtol=1e-9)
        assert run.theta_max == pytest.approx(theta0, rel=1e-9)
        assert run.theta_min == pytest.approx(-theta0, rel=1e-9)


# ------------------------------------------------------------------ thresholds (scipy)

def peer_overturns(amp, kind, period, p, alpha, e):
    """Does the body (p, alpha, restitution e) overturn under one cycle of a_g/g = amp
    sin(2 pi t/T) or amp cos(2 pi t/T) (0 <= t < T)? Housner's nonlinear equation,
    theta'' = -p^2 (sin(alpha s - theta) - (a_g/g) cos(alpha s - theta)), s = sgn(theta),
    integrated by solve_ivp (DOP853, rtol 1e-11) from event to event: impacts at theta = 0
    (theta' times e), overturning at |theta| = pi/2; after the pulse an impact below the
    energy p^2 (1 - cos alpha) needed to reach alpha is final rest."""
    from scipy.integrate import solve_ivp
    from scipy.optimize import brentq
    w = 2 * math.pi / period
    trig = math.sin if kind == "sine_cycle" else math.cos

    def ag(t):
        return amp * trig(w * t) if 0.0 <= t < period else 0.0
    thr = math.tan(alpha)

    def next_uplift(t0):
        """First time >= t0 with |a_g| > g tan(alpha) (None if none)."""
        if abs(ag(t0)) > thr:
            return t0
        grid = np.linspace(t0, period, 4001)
        vals = np.array([abs(ag(s)) - thr for s in grid[:-1]])
        hit = np.nonzero(vals > 0)[0]
        if hit.size == 0:
            return None
        k = hit[0]
        return brentq(lambda s: abs(ag(s)) - thr, grid[k - 1], grid[k], xtol=1e-15)

    t = next_uplift(0.0)
    if t is None:
        return False
    y = [0.0, 0.0]
    s = 1.0 if ag(t + 1e-12) > 0 else -1.0
    t_final = period + 400.0 / p
    while True:
        def rhs(tt, yy, s=s):
            d = alpha * s - yy[0]
            return [yy[1], -p * p * (math.sin(d) - ag(tt) * math.cos(d))]

        def hit(tt, yy, s=s):
            return yy[0]
        hit.terminal, hit.direction = True, -s

        def fall(tt, yy):
            return abs(yy[0]) - math.pi / 2
        fall.terminal = True
        stop = period if t < period else t_final
        sol = solve_ivp(rhs, (t, stop), y, method="DOP853", rtol=1e-11, atol=1e-13,
                        events=[hit, fall])
        if sol.t_events[1].size:
            return True
        if sol.t_events[0].size:
            t = sol.t_events[0][0]
            y = [0.0, e * sol.y_events[0][0][1]]
            s = -s
            if t >= period and 0.5 * y[1] ** 2 < p * p * (1 - math.cos(alpha)):
                return False
            if abs(y[1]) < 1e-12 * p:          # back at rest during the pulse
                t = next_uplift(t)
                if t is None:
                    return False
                y, s = [0.0, 0.0], (1.0 if ag(t + 1e-12) > 0 else -1.0)
            continue
        if t >= period:
            return False                       # rocking without overturning at t_final
        t, y = sol.t[-1], list(sol.y[:, -1])   # the end of the pulse: go on without it


@pytest.mark.parametrize("kind", ["sine_cycle", "cosine_cycle"])
def test_overturning_thresholds_against_scipy(kind):
    pytest.importorskip("scipy")
    r, h = 0.25, 1.0
    _, p, e, alpha, _ = solid(r, h)
    body = C.props(r, h, mass=80.0)
    freqs = np.array([0.6, 1.0, 1.5])
    ours = C.overturning_threshold(body, kind, freqs)
    assert ours.shape == (3,)
    for f, a_lib in zip(freqs, ours):
        assert math.isfinite(a_lib) and a_lib > math.tan(alpha)
        period = 1.0 / f
        # nothing below overturns (a scan from the uplift threshold) ...
        for a in np.geomspace(math.tan(alpha) * 1.0001, a_lib * (1 - 2e-5), 6):
            assert not peer_overturns(a, kind, period, p, alpha, e), (f, a)
        # ... and the peer's own threshold, bisected in a bracket around ours
        lo, hi = a_lib * (1 - 2e-5), a_lib * (1 + 2e-5)
        assert not peer_overturns(lo, kind, period, p, alpha, e)
        assert peer_overturns(hi, kind, period, p, alpha, e)
        while hi - lo > 1e-7 * hi:
            mid = 0.5 * (lo + hi)
            if peer_overturns(mid, kind, period, p, alpha, e):
                hi = mid
            else:
                lo = mid
        assert a_lib == pytest.approx(hi, rel=1e-5), f


def test_thresholds_side_by_side():
    body = C.props(0.3, 1.2, mass=10.0)
    freqs = [0.8, 2.0]
    side = C.thresholds_side_by_side(body, "sine_cycle", freqs)
    blk = C.equivalent_block(body)
    assert side.block._replace(J_axis=0.0) == blk._replace(J_axis=0.0)   # NaN != NaN
    np.testing.assert_array_equal(side.cylinder_pga_g,
                                  C.overturning_threshold(body, "sine_cycle", freqs))
    np.testing.assert_array_equal(side.block_pga_g,
                                  C.overturning_threshold(blk, "sine_cycle", freqs))
    assert side.cylinder_uplift_g == pytest.approx(0.3 / 1.2, rel=1e-14)
    assert side.block_uplift_g == pytest.approx(math.tan(blk.theta_c), rel=1e-14)
    # the same p: the two thresholds differ only through the restitution (a few %)
    np.testing.assert_allclose(side.cylinder_pga_g, side.block_pga_g, rtol=0.1)
    assert C.overturning_threshold(body, "sine_cycle", 1.0, pga_max_g=0.26) == math.inf


# ------------------------------------------------------------------ maps

def test_dimensional_and_dimensionless_maps_agree():
    body = C.props(0.4, 1.6, mass=3.0)
    f_hz = np.array([0.3, 0.7, 1.3, 2.9])
    pga = np.array([0.2, 0.3, 0.45, 0.8, 1.5])
    dim = C.overturning_map(body, "sine_cycle", f_hz, pga, axes="dimensional")
    x = 2 * np.pi * f_hz / body.p                 # omega_p/p
    y = pga / math.tan(body.theta_c)              # a_p/(g tan theta_c)
    nodim = C.overturning_map(body, "sine_cycle", x, y)
    assert dim.shape == (5, 4)
    np.testing.assert_array_equal(dim, nodim)
    assert dim.max() > 0 and dim.min() == 0       # the grid crosses the boundary
    assert set(np.unique(dim)) <= {0, 1, 2, 3}
    # the dimensionless map of a body is rocking's map of its slenderness and restitution
    ref = R.overturning_map("sine_cycle", x, y, alpha=body.theta_c, e=body.restitution)
    np.testing.assert_array_equal(nodim, ref)


def test_map_difference_and_compare_with_block():
    a = np.array([[0, 1, 2, 3], [0, 0, 2, 1]])
    b = np.array([[0, 0, 2, 1], [1, 0, 3, 1]])
    d = C.map_difference(a, b)
    want = np.where(a == b, 0, np.where(b == 0, 1, np.where(a == 0, 2, 3)))
    np.testing.assert_array_equal(d, want)
    assert C.MAP_DIFF[0] == "same" and len(C.MAP_DIFF) == 4
    body = C.props(0.3, 1.2, mass=10.0)
    f_hz, pga = np.array([0.5, 1.0, 2.0]), np.array([0.3, 0.6, 1.2, 2.4])
    cmp = C.compare_with_block(body, "sine_cycle", f_hz, pga)
    np.testing.assert_array_equal(cmp.cylinder_map, C.overturning_map(
        body, "sine_cycle", f_hz, pga, axes="dimensional"))
    np.testing.assert_array_equal(cmp.block_map, C.overturning_map(
        C.equivalent_block(body), "sine_cycle", f_hz, pga, axes="dimensional"))
    np.testing.assert_array_equal(cmp.difference,
                                  C.map_difference(cmp.cylinder_map, cmp.block_map))


def test_plots():
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt
    body = C.props(0.3, 1.2)
    f_hz, pga = np.linspace(0.3, 3, 8), np.linspace(0.2, 2, 7)
    classes = C.overturning_map(body, "sine_cycle", f_hz, pga, axes="dimensional")
    ax = C.plot_overturning_map(classes, f_hz, pga, axes="dimensional", title="cylinder")
    assert "(Hz)" in ax.get_xlabel() and "(g)" in ax.get_ylabel()
    legend = ax.get_legend()
    assert legend is not None and [t.get_text() for t in legend.get_texts()] == \
        list(C.MAP_CLASSES)
    ax2 = C.plot_overturning_map(classes, f_hz, pga)
    assert ax2.get_xlabel() == "omega_p / p"
    run = C.simulate(body, P.define("sine_cycle", amp=0.5, amp_unit="g", period=1.0),
                     t=np.linspace(0, 4, 200))
    ax3 = C.plot_history(run, body)
    assert ax3.get_ylabel() == "theta (rad)"
    plt.close("all")
    with pytest.raises(InvalidInputError, match="history"):
        C.plot_history(C.simulate(body, P.define("sine_cycle", amp=0.5, amp_unit="g",
                                                 period=1.0)))


# ------------------------------------------------------------------ bad input

@pytest.mark.parametrize("kwargs, name", [
    ({"r": 0.0, "h": 1.0}, "r"), ({"r": float("nan"), "h": 1.0}, "r"),
    ({"r": 1.0, "h": -1.0}, "h"), ({"r": 1.0, "h": 1.0, "mass": 0.0}, "mass"),
    ({"r": 1.0, "h": 1.0, "mass": float("nan")}, "mass"),
    ({"r": 1.0, "h": 1.0, "r_inner": 1.0}, "r_inner"),
    ({"r": 1.0, "h": 1.0, "r_inner": -0.1}, "r_inner"),
    ({"r": 1.0, "h": 1.0, "j_o": 1.0}, "j_o"), ({"r": 1.0, "h": 1.0, "g": 0.0}, "g"),
    ({"r": [1.0, 2.0], "h": 1.0}, "r")])
def test_bad_props(kwargs, name):
    with pytest.raises(InvalidInputError, match=rf"^{name}\b"):
        C.props(**kwargs)


def test_bad_input():
    body = C.props(0.3, 1.2)
    pulse = P.define("sine_cycle", amp=0.5, amp_unit="g", period=1.0)
    with pytest.raises(InvalidInputError, match="^b"):
        C.block_props(-1.0, 1.0)
    with pytest.raises(InvalidInputError, match=r"^e = 1\.5"):
        C.simulate(body, pulse, e=1.5)
    with pytest.raises(InvalidInputError, match=r"^body: "):
        C.simulate(R.rectangular_block(0.3, 1.2), pulse)
    with pytest.raises(InvalidInputError, match="kv"):
        C.simulate(body, accel=np.zeros(3), dt=0.01, kv=0.5)
    with pytest.raises(InvalidInputError, match="axes"):
        C.overturning_map(body, "sine_cycle", [1.0], [1.0], axes="hz")
    with pytest.raises(InvalidInputError, match="axes"):
        C.plot_overturning_map(np.zeros((1, 1)), [1.0], [1.0], axes="hz")
    with pytest.raises(InvalidInputError, match="kind"):
        C.overturning_map(body, "sawtooth", [1.0], [1.0])
    with pytest.raises(InvalidInputError, match=r"x\[1\]"):
        C.overturning_map(body, "sine_cycle", [1.0, -1.0], [1.0])
    with pytest.raises(InvalidInputError, match="a, b"):
        C.map_difference(np.zeros((2, 2)), np.zeros((2, 3)))
    with pytest.raises(InvalidInputError, match="theta_c"):
        C.normalized_pushover(2.0, 0.5)
    with pytest.raises(InvalidInputError, match="block"):
        C.equivalent_cylinder(body)
    with pytest.raises(InvalidInputError, match="n_scan"):
        C.overturning_threshold(body, "sine_cycle", 1.0, n_scan=2.5)
    with pytest.raises(InvalidInputError, match="shape"):
        C.simulate(body._replace(shape="cone"), pulse)
    with pytest.raises(InvalidInputError, match="^e "):
        C.simulate(body._replace(restitution=1.2), pulse)
    with pytest.raises(InvalidInputError, match="linearized"):
        C.overturning_map(body, "sine_cycle", [1.0], [1.0], linearized="yes")


def test_readme_example_runs(source_root):
    """The example of the README's Cylinders section runs and prints what it says."""
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt
    text = (source_root / "README.md").read_text(encoding="utf-8")
    section = text[text.index("\n## Cylinders\n"):]
    code = section[section.index("```python\n") + 10:section.index("\n```\n")]
    ns = {}
    exec(compile(code, "README.md (Cylinders)", "exec"), ns)
    plt.close("all")
    body = ns["body"]
    assert (round(body.theta_c, 4), round(body.p, 3), round(body.restitution, 4)) == \
        (0.2450, 1.892, 0.9114)
    assert round(body.M_max) == 4903
    assert round(ns["push"].F[0]) == 2452 and round(ns["push"].M[0]) == 4903
    assert ns["run"].outcome == "rest" and round(ns["run"].theta_max, 4) == 0.1045
    assert ns["run"].n_impacts == 121
    assert np.bincount(ns["cmp"].difference.ravel()).tolist() == [3599, 0, 1]
    np.testing.assert_allclose(ns["side"].cylinder_pga_g, [0.2965, 0.3725, 1.499], atol=6e-4)
    np.testing.assert_allclose(ns["side"].block_pga_g, [0.2965, 0.3724, 1.497], atol=6e-4)
    run3d = ns["run3d"]
    assert run3d.outcome == "time_limit" and run3d.n_impacts == 0
    assert (round(run3d.theta_max, 4), round(run3d.friction_max, 3)) == (0.2753, 0.357)
    assert round(run3d.psi[-1], 2) == -25.19


def test_map_with_vertical_acceleration_is_the_blocks_map_with_kv():
    """kv reaches every cell: the cylinder's dimensionless map with kv equals
    rocking.overturning_map with the same kv, alpha = theta_c and the cylinder's e, and
    differs from the map without it."""
    body = C.props(0.4, 1.6)
    x = np.array([1.5, 3.0, 6.0])
    y = np.linspace(1.2, 6.0, 9)
    with_kv = C.overturning_map(body, "sine_cycle", x, y, kv=-0.5)
    ref = R.overturning_map("sine_cycle", x, y, body.theta_c, e=body.restitution, kv=-0.5)
    np.testing.assert_array_equal(with_kv, ref)
    assert np.any(with_kv != C.overturning_map(body, "sine_cycle", x, y))
    with pytest.raises(InvalidInputError, match="kv"):
        C.overturning_map(body, "sine_cycle", x, [40.0], kv=-1.0)


def test_map_inputs_refused_with_the_place():
    body = C.props(0.4, 1.6)
    xx, yy = np.meshgrid([1.0, 2.0], [2.0, 3.0])
    with pytest.raises(InvalidInputError, match=r"^x: must be a 1-d"):
        C.overturning_map(body, "sine_cycle", xx, [2.0])
    a = np.zeros((2, 3))
    b = np.zeros((2, 3))
    b[1, 2] = 1e12
    with pytest.raises(InvalidInputError, match=r"^b\[1, 2\] = 1000000000000\.0: must be a class"):
        C.map_difference(a, b)
    b[1, 2] = 4
    with pytest.raises(InvalidInputError, match=r"^b\[1, 2\] = 4\.0"):
        C.map_difference(a, b)
