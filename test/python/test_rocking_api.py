"""seispulse.rocking: the Python face of the linearized closed forms and of the
nonlinear integrator, and the two against each other (the linearized integrator must
reproduce the closed forms of the exponential pulse)."""
import math

import numpy as np
import pytest

from seispulse import pulse as P
from seispulse import rocking as R
from seispulse.errors import InvalidInputError

PI = math.pi
G = 9.80665


def linear_case(f, eta, beta, alpha=0.1, p=2.0):
    """Block and exponential half cycle of the dimensionless (f, eta, beta): t_d = f/p,
    A_g = g alpha/eta (the linearized uplift amplitude is g alpha)."""
    k = 4.0 / 3.0
    r = G / (k * p * p)
    block = R.symmetric_block(r, alpha, k, g=G, e=0.0)
    pulse = P.define("exponential", amp=G * alpha / eta, td=f / p, beta=beta)
    return block, pulse, f / p


@pytest.mark.parametrize("f, eta, beta", [(1.0, 0.15, PI), (1.0, 0.19, PI), (2.0, 0.5, -PI),
                                          (4.0, 0.9, 0.0), (0.7, 0.6, -np.inf), (3.0, 0.3, 1.0),
                                          (2.0, 0.8, -1.0)])
def test_closed_forms_equal_linearized_integrator(f, eta, beta):
    s = R.summary(f, eta, beta)
    block, pulse, td = linear_case(f, eta, beta)
    run = R.simulate(block, pulse, linearized=True, t_max=50 * td)
    alpha = block.alpha
    assert run.t_uplift / td == pytest.approx(s.tau_up, rel=1e-9, abs=1e-12)
    if s.region.startswith("O"):
        assert run.outcome == "overturn_no_impact"
        assert run.t_overturn / td == pytest.approx(s.tau_c, rel=1e-9)
        assert math.isinf(s.psi_max)
    else:
        assert run.n_impacts >= 1
        assert run.t_impacts[0] / td == pytest.approx(s.tau_i, rel=1e-9)
        assert run.theta_max / alpha == pytest.approx(s.psi_max, rel=1e-9)


def test_published_and_limit_values():
    # doc/rocking.md section 3 oracle (beta = pi, f = 1) and the corrected 2.16a value
    assert R.critical_time(1.0, [0.15, 0.19, 0.198], PI) == pytest.approx(
        [1.4103182142, 2.3430539314, 4.2505629625], abs=1e-9)
    assert R.overturn_boundary(1.0, PI) == pytest.approx(0.1011941262, abs=1e-10)
    # Housner's wall for the box (2.21) and the triangle (2.22)
    f = np.array([0.3, 1.0, 3.0])
    assert R.stability_wall(f, -np.inf) == pytest.approx(1 - np.exp(-f), rel=1e-14)
    assert R.stability_wall(f, 0.0) == pytest.approx(2 - 2 / f * np.log(2 * np.exp(f / 2) - 1),
                                                     rel=1e-13)
    assert R.min_overturning_amplitude(1.0, -np.inf) == pytest.approx(1 / (1 - math.exp(-1)))
    # removable singularity f = 2|beta| (doc/rocking.md section 3)
    assert R.stability_wall(2.0, 1.0) == pytest.approx(0.4447161183, abs=1e-10)
    assert R.stability_wall(2.0, -1.0) == pytest.approx(0.5739634818, abs=1e-10)
    # corrected 2.30 (the printed form gives -0.053)
    assert R.rectangle_normalized(0.5, 0.3)[1] == pytest.approx(0.1328337665, abs=1e-10)
    assert R.uplift_time(0.4, 0.0) == pytest.approx(0.2)
    assert R.classify(1.0, 1.0, 0.0) == "no_rocking"
    assert R.max_rotation(1.0, 1.2, 0.0) == 0.0


def test_inverses_and_boundaries_are_consistent():
    for beta in (-np.inf, -PI, 0.0, PI):
        eta_w = R.stability_wall(1.5, beta)
        assert R.stability_wall_inverse(eta_w, beta) == pytest.approx(1.5, rel=1e-9)
        for at in ("end", "mid"):
            eta_b = R.overturn_boundary(1.5, beta, at=at)
            assert R.overturn_boundary_inverse(eta_b, beta, at=at) == pytest.approx(1.5,
                                                                                    rel=1e-9)
    # the regions sit between the boundaries
    f, beta = 2.0, PI
    mid, end, wall = (R.overturn_boundary(f, beta, "mid"), R.overturn_boundary(f, beta),
                      R.stability_wall(f, beta))
    assert mid < end < wall
    assert R.classify(f, [0.5 * mid, 0.5 * (mid + end), 0.5 * (end + wall), 0.5 * (wall + 1)],
                      beta).tolist()[:3] == ["O1", "O2", "O3"]


def test_blocks():
    b = R.rectangular_block(0.2, 0.8)
    alpha = math.atan(0.25)
    assert b.alpha == pytest.approx(alpha)
    assert b.r == pytest.approx(math.hypot(0.2, 0.8))
    assert b.p == pytest.approx(math.sqrt(3 * G / (4 * b.r)))
    assert b.e == pytest.approx(1 - 1.5 * math.sin(alpha) ** 2)
    assert R.rectangular_block(0.2, 0.8, e=0.8).e == 0.8
    # squat block, b/h > sqrt 2: Housner's 1 - 1.5 sin^2(alpha) < 0 is floored at 0
    assert R.rectangular_block(2.0, 1.0).e == 0.0
    assert R.overturning_map("half_sine", [1.0], [2.0], alpha=1.2).shape == (1, 1)
    s = R.symmetric_block(1.0, 0.2, 4.0 / 3.0)
    assert s.p == pytest.approx(math.sqrt(3 * G / 4))


def test_simulate_any_pulse_and_history():
    b = R.rectangular_block(0.2, 0.8)
    p = P.define("sine_cycle", amp=0.5, amp_unit="g", period=0.5)
    t = np.linspace(0, 3, 301)
    run = R.simulate(b, p, t=t)
    assert run.outcome in R.OUTCOMES
    assert run.theta.shape == t.shape and np.all(np.abs(run.theta) <= math.pi / 2 + 1e-12)
    weak = R.simulate(b, P.define("half_sine", amp=0.1, amp_unit="g", duration=0.5))
    assert weak.outcome == "no_uplift" and math.isnan(weak.t_uplift)


def test_overturning_maps():
    freq = np.linspace(1.0, 12.0, 6)
    amp = np.linspace(0.5, 12.0, 5)
    classes = R.overturning_map("sine_cycle", freq, amp, alpha=0.25)
    assert classes.shape == (5, 6) and set(np.unique(classes)) <= {0, 1, 2, 3}
    # the closed-form map of the exponential half cycle = the linearized integrator's
    # overturning-without-impact cells
    freq = np.array([1.0, 3.0, 6.0])
    amp = np.array([1.5, 3.0, 8.0])
    closed = R.overturning_map("exponential", freq, amp, alpha=0.1, method="closed", beta=PI)
    integ = R.overturning_map("exponential", freq, amp, alpha=0.1, linearized=True, beta=PI)
    np.testing.assert_array_equal(closed, (integ == 1).astype(int))
    assert closed.any() and not closed.all()


def test_plot_needs_matplotlib_or_draws():
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    ax = R.plot_overturning_map(np.zeros((2, 3), int), [1, 2, 3], [1, 2])
    assert ax.get_xlabel() == "omega_p / p (-)"


@pytest.mark.parametrize("call, pattern", [
    (lambda: R.summary(0.0, 0.5, 0.0), r"^f = 0.0"),
    (lambda: R.summary(1.0, -0.5, 0.0), r"^eta = -0.5"),
    (lambda: R.summary(1.0, math.nan, 0.0), r"^eta = NaN"),
    (lambda: R.overturn_boundary(1.0, 0.0, at="start"), r"^at = 'start'"),
    (lambda: R.rectangular_block(-0.2, 0.8), r"^b = -0.2"),
    (lambda: R.rectangular_block(0.2, 0.8, e=1.5), r"^e = 1.5"),
    (lambda: R.rectangular_block([0.2, 0.3], 0.8), r"^b: must be a single number"),
    (lambda: R.simulate(None, None), r"^block"),
    (lambda: R.simulate(R.rectangular_block(0.2, 0.8)), r"^pulse, accel"),
    (lambda: R.overturning_map("sine_cycle", [1.0], [1.0], alpha=2.0), r"^alpha = 2.0"),
    (lambda: R.overturning_map("sine_cycle", [1.0], [1.0], alpha=0.2, method="closed"),
     r"^method = 'closed'"),
    (lambda: R.rectangle_normalized(1.2, 0.3), r"^fbar = 1.2"),
])
def test_bad_input(call, pattern):
    with pytest.raises(InvalidInputError, match=pattern):
        call()


GRID_F = [0.2, 0.5, 1.0, 2.0, 4.0, 8.0]
GRID_ETA = [0.05, 0.2, 0.5, 0.8, 0.95]
GRID_BETA = [-np.inf, -3 * PI, -PI, -1.0, -1e-9, 0.0, 1e-9, 1.0, PI, 3 * PI, 2.0]


@pytest.mark.parametrize("beta", GRID_BETA)
def test_grid_closed_forms_against_linearized_integrator(beta):
    """doc/rocking.md: the closed forms against the library's own linearized integrator
    on a grid of f in [0.2, 8], eta in (0, 1), beta in [-3 pi, 3 pi] with 0, tiny
    |beta|, -inf and f = 2|beta| (beta = 2 with f = 4; beta = 1 with f = 2)."""
    for f in GRID_F:
        for eta in GRID_ETA:
            s = R.summary(f, eta, beta)
            block, pulse, td = linear_case(f, eta, beta)
            # rtol 1e-14: the tiny excursions near eta = 1 need the absolute accuracy
            run = R.simulate(block, pulse, linearized=True, t_max=60 * td + 60, rtol=1e-14,
                             t=[td])
            where = f"f={f}, eta={eta}, beta={beta}"
            assert run.t_uplift / td == pytest.approx(s.tau_up, rel=1e-9, abs=1e-12), where
            # the integrator's own region: when theta reaches alpha (O1/O2/O3), or whether
            # the block still rises at the end of the pulse (S2) or not (S1)
            if run.outcome == "overturn_no_impact":
                tc = run.t_overturn / td
                region = "O1" if tc <= 0.5 else "O2" if tc <= 1 else "O3"
            else:
                region = "S2" if run.omega[0] > 0 else "S1"
            assert region == s.region, where
            if s.region in ("O1", "O2", "O3"):
                assert run.t_overturn / td == pytest.approx(s.tau_c, rel=1e-9), where
            else:
                assert run.outcome == "rest" and run.n_impacts == 1, where   # e = 0
                assert run.t_impacts[0] / td == pytest.approx(s.tau_i, rel=1e-9), where
                assert run.theta_max / block.alpha == pytest.approx(s.psi_max, rel=1e-9), where


# ------------------------------------------------ vertical ground acceleration (section 7)

def _same_run(a, b):
    assert (a.outcome, a.n_impacts) == (b.outcome, b.n_impacts)
    for x, y in [(a.t_uplift, b.t_uplift), (a.t_overturn, b.t_overturn), (a.t_end, b.t_end),
                 (a.theta_max, b.theta_max), (a.theta_min, b.theta_min)]:
        assert np.array_equal([x], [y], equal_nan=True)
    np.testing.assert_array_equal(a.t_impacts, b.t_impacts)
    if a.t is not None:
        np.testing.assert_array_equal(a.theta, b.theta)
        np.testing.assert_array_equal(a.omega, b.omega)


@pytest.mark.parametrize("linearized", [False, True])
def test_vertical_zero_is_bit_identical(linearized):
    block = R.rectangular_block(0.2, 0.8, e=0.9)
    pulse = P.define("sine_cycle", amp=3 * G * math.tan(block.alpha), period=1.1)
    t = np.linspace(0, 4, 81)
    _same_run(R.simulate(block, pulse, linearized=linearized, t=t),
              R.simulate(block, pulse, linearized=linearized, t=t, kv=0.0))
    # kv = 1e-300 takes the vertical code path with 1 + a_v/g == 1 exactly: the vertical
    # right-hand side and thresholds must then give the horizontal-only run bit for bit
    _same_run(R.simulate(block, pulse, linearized=linearized, t=t),
              R.simulate(block, pulse, linearized=linearized, t=t, kv=1e-300))
    acc = 0.6 * G * np.sin(0.21 * np.arange(61))
    a = R.simulate(block, accel=acc, dt=0.02, linearized=linearized, t=t)
    assert a.n_impacts >= 1
    _same_run(a, R.simulate(block, accel=acc, dt=0.02, linearized=linearized, t=t,
                            accel_v=np.zeros_like(acc)))
    freq, amp = [1.0, 3.0, 8.0], [1.5, 3.0, 6.0]
    np.testing.assert_array_equal(
        R.overturning_map("sine_cycle", freq, amp, alpha=0.2, linearized=linearized),
        R.overturning_map("sine_cycle", freq, amp, alpha=0.2, linearized=linearized, kv=0.0))


def _housner_vertical(block, ag, av, t0, t1, linearized=False):
    """First impact after an uplift at t0 on side +1 (theta = 0, theta' = 0), by solve_ivp
    of doc/rocking.md (R.9) written here: theta'' = -p^2 [(1 + a_v/g) sin(alpha - theta)
    - (a_g/g) cos(alpha - theta)] (linearized: sin x ~ x, cos x ~ 1)."""
    from scipy.integrate import solve_ivp
    g, p2, al = block.g, block.p ** 2, block.alpha

    def rhs(t, y):
        gv, a = 1 + av(t) / g, ag(t) / g
        if linearized:
            return [y[1], -p2 * (gv * (al - y[0]) - a)]
        return [y[1], -p2 * (gv * math.sin(al - y[0]) - a * math.cos(al - y[0]))]

    hit = lambda t, y: y[0]
    hit.terminal, hit.direction = True, -1
    sol = solve_ivp(rhs, (t0, t1), [0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-15,
                    events=hit, max_step=0.002)
    return sol.t_events[0][0]


@pytest.mark.parametrize("kv, linearized", [(0.5, False), (-0.4, False), (0.5, True)])
def test_vertical_pulse_against_solve_ivp(kv, linearized):
    """a_v = kv a_g under a one-sine pulse: the uplift at A sin(w t) = g tu/(1 - kv tu)
    (tu = tan(alpha), alpha when linearized), and the first impact by solve_ivp."""
    pytest.importorskip("scipy")
    block = R.rectangular_block(0.2, 0.8, e=0.9)
    tu = block.alpha if linearized else math.tan(block.alpha)
    amp, period = 2.5 * G * tu, 0.5
    w = 2 * PI / period
    run = R.simulate(block, P.define("sine_cycle", amp=amp, period=period), kv=kv,
                     linearized=linearized)
    t_up = math.asin(G * tu / (1 - kv * tu) / amp) / w
    assert run.t_uplift == pytest.approx(t_up, rel=1e-12)
    ag = lambda t: amp * math.sin(w * t) if t < period else 0.0
    t_hit = _housner_vertical(block, ag, lambda t: kv * ag(t), t_up, 20.0, linearized)
    assert run.n_impacts >= 1
    assert run.t_impacts[0] == pytest.approx(t_hit, rel=1e-7)


def test_vertical_record_against_solve_ivp():
    """A sampled horizontal and vertical record (linear in between): the uplift where
    a_g = (g + a_v) tan(alpha) on a step (a root of a line), the first impact by
    solve_ivp of (R.9)."""
    pytest.importorskip("scipy")
    block = R.rectangular_block(0.2, 0.8, e=0.9)
    dt, n = 0.02, 101
    ts = dt * np.arange(n)
    acc = 0.3 * G * np.sin(2 * PI * ts / 0.6)
    vert = 0.6 * G * np.sin(2 * PI * ts / 0.37 + 0.4)
    run = R.simulate(block, accel=acc, dt=dt, accel_v=vert)
    f = acc - math.tan(block.alpha) * (G + vert)
    k = int(np.argmax(f > 0))
    t_up = ts[k - 1] + dt * f[k - 1] / (f[k - 1] - f[k])
    assert run.t_uplift == pytest.approx(t_up, rel=1e-12)
    t_plain = R.simulate(block, accel=acc, dt=dt).t_uplift
    assert abs(t_plain - t_up) > 1e-3        # the vertical record matters
    ag = lambda t: np.interp(t, ts, acc)
    av = lambda t: np.interp(t, ts, vert)
    t_hit = _housner_vertical(block, ag, av, t_up, ts[-1])
    assert run.n_impacts >= 1
    assert run.t_impacts[0] == pytest.approx(t_hit, rel=1e-6)


def test_vertical_map_equals_single_runs():
    alpha, e, kv = 0.2, 0.85, 0.7
    freq, amp = np.array([1.0, 2.5, 6.0]), np.array([1.2, 2.0, 4.0])
    classes = R.overturning_map("sine_cycle", freq, amp, alpha=alpha, e=e, kv=kv)
    plain = R.overturning_map("sine_cycle", freq, amp, alpha=alpha, e=e)
    assert not np.array_equal(classes, plain)
    block = R.Block(alpha, 1.0, e, 1.0, 1.0)
    code = {"rest": 0, "no_uplift": 0, "overturn_no_impact": 1, "overturn_one_impact": 2,
            "overturn_many_impacts": 3}
    for j, fr in enumerate(freq):
        for i, a in enumerate(amp):
            pulse = P.define("sine_cycle", amp=a * math.tan(alpha), period=2 * PI / fr)
            run = R.simulate(block, pulse, kv=kv, t_max=200.0)
            assert code[run.outcome] == classes[i, j], (fr, a)


@pytest.mark.parametrize("call, pattern", [
    (lambda: R.simulate(R.rectangular_block(0.2, 0.8), P.define("sine_cycle", amp=5.0,
                                                                period=1.0), kv=2.5),
     r"^kv = 2.5: .* below -g"),
    (lambda: R.simulate(R.rectangular_block(0.2, 0.8), P.define("sine_cycle", amp=5.0,
                                                                period=1.0), kv=math.nan),
     r"^kv = NaN"),
    (lambda: R.simulate(R.rectangular_block(0.2, 0.8), accel=[1.0, 2.0, 0.0], dt=0.01,
                        accel_v=[0.0, -10.0, 0.0]), r"^accel_v\[1\] = -10.0 at t = .*leave the ground"),
    (lambda: R.simulate(R.rectangular_block(0.2, 0.8), accel=[1.0, 2.0, 0.0], dt=0.01,
                        accel_v=[0.0, 0.0]), r"^accel_v: 2 samples"),
    (lambda: R.simulate(R.rectangular_block(0.2, 0.8), accel=[1.0, 2.0, 0.0], dt=0.01,
                        accel_v=[0.0, math.inf, 0.0]), r"^accel_v\[1\] = \+?Inf"),
    (lambda: R.simulate(R.rectangular_block(0.2, 0.8), accel=[1.0, 2.0, 0.0], dt=0.01,
                        kv=0.3), r"^kv: scales a pulse"),
    (lambda: R.simulate(R.rectangular_block(0.2, 0.8), P.define("sine_cycle", amp=5.0,
                                                                period=1.0),
                        accel_v=[0.0]), r"^accel_v: a vertical record"),
    (lambda: R.overturning_map("sine_cycle", [1.0], [1.0, 3.0], alpha=0.2, kv=2.0),
     r"^kv = 2.0, amp_ratio\[1\] = 3.0"),
    (lambda: R.overturning_map("exponential", [1.0], [1.0], alpha=0.2, kv=0.5,
                               method="closed"), r"^kv: method = 'closed'"),
])
def test_vertical_bad_input(call, pattern):
    with pytest.raises(InvalidInputError, match=pattern):
        call()
