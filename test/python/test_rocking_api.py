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
    assert ax.get_xlabel() == "omega_p / p"


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
