"""seispulse.winkler, dynamics: the binding of the planar Winkler rocking model (the
physics is cross-checked against an independent scipy model elsewhere). Tested here: the
model's dashpot from xi by the formulas typed out, its static overturning angle against
the pushover, the names, shapes and units of a run, a pulse and the same excitation as a
record in g giving the same run, the g of a record, the maps with their rigid companion,
errors that name the parameter, and the plots."""
import math

import numpy as np
import pytest

from seispulse import cylinder, pulse
from seispulse import winkler as W
from seispulse.errors import InvalidInputError

G = 9.80665
R, H, MASS = 1.0, 3.0, 2500.0 * math.pi * 6.0
G_MOD, NU = 100e6 / 2.6, 0.3
K = 32 * G_MOD / (3 * math.pi * (1 - NU) * R)


@pytest.fixture(scope="module")
def body():
    return cylinder.props(R, H, mass=MASS)


@pytest.fixture(scope="module")
def mdl(body):
    return W.model(body, K, xi=0.003)


def test_model_dashpot_from_xi(body):
    """c = 2 xi I_O omega_r/I with omega_r^2 = (k I - m g h)/I_O (rocking), or 2 xi
    sqrt(k m/A) (vertical); I_O = J_G + m h^2; I, A of the base."""
    i_o = body.J_G + MASS * H * H
    i_base = math.pi * R ** 4 / 4
    omega = math.sqrt((K * i_base - MASS * G * H) / i_o)
    m = W.model(body, K, xi=0.003)
    assert m.c == pytest.approx(2 * 0.003 * i_o * omega / i_base, rel=1e-12)
    assert m.footing == "circle" and m.k == K and math.isnan(m.alpha)
    m = W.model(body, K, xi=0.02, damping_ref="vertical")
    assert m.c == pytest.approx(2 * 0.02 * math.sqrt(K * MASS / (math.pi * R * R)), rel=1e-12)
    assert W.model(body, K, c=1234.5).c == 1234.5
    assert W.model(body, K).c == 0.0


def test_block_model_and_overturning_angle():
    b, alpha, h = 0.8, 1.2, 2.5
    blk = cylinder.block_props(b, h, mass=3e4)
    m = W.model(blk, 4e8, alpha=alpha, k_method="varying", xi=0.01)
    assert m.footing == "rectangle" and m.alpha == alpha and m.k_method == "varying"
    i_base = 2 * alpha * (2 * b) ** 3 / 12
    i_o = blk.J_G + blk.mass * h * h
    omega = math.sqrt((4e8 * i_base - blk.mass * G * h) / i_o)
    assert m.c == pytest.approx(2 * 0.01 * i_o * omega / i_base, rel=1e-12)
    push = W.block_winkler_pushover(b, alpha, h, blk.weight, 4e8, k_method="varying")
    assert m.theta_overturn == pytest.approx(push.theta_overturn, rel=1e-10)


def test_model_overturning_angle_is_the_pushovers(body, mdl):
    push = W.winkler_pushover(R, H, body.weight, K)
    assert mdl.theta_overturn == pytest.approx(push.theta_overturn, rel=1e-10)


def test_run_names_shapes_units(body, mdl):
    p = pulse.define("sine_cycle", amp=0.25, amp_unit="g", period=0.5)
    t = np.linspace(0.0, 1.5, 301)
    run = W.simulate(mdl, p, t=t)
    assert run._fields[:15] == ("outcome", "n_impacts", "t_impacts", "impact_normal_peak",
                                "impact_moment_peak", "theta_max", "t_uplift", "t_lift_off",
                                "t_touch_down", "t_overturn", "normal_max", "energy_error",
                                "t_end", "t_safe", "n_steps")
    assert run.outcome in W.OUTCOMES
    np.testing.assert_array_equal(run.t, t)
    for name in W.COLUMNS:
        assert getattr(run, name).shape == t.shape, name
    # units: the ground acceleration column is the pulse in m/s^2
    np.testing.assert_allclose(run.accel, pulse.sine_cycle(t, amp=0.25, period=0.5,
                                                           amp_unit="g").a,
                               rtol=1e-12, atol=1e-12)
    # from rest: the static settlement W/(k A) and the weight on the soil
    assert run.v[0] == pytest.approx(body.weight / (K * math.pi * R * R), rel=1e-10)
    assert run.normal[0] == pytest.approx(body.weight, rel=1e-8)
    assert run.width[0] == pytest.approx(2 * R, rel=1e-12)
    assert run.theta_max == pytest.approx(np.max(np.abs(run.theta)), rel=0.05)
    assert len(run.t_impacts) == run.n_impacts == len(run.impact_normal_peak) \
        == len(run.impact_moment_peak)
    assert run.n_impacts > 0 and np.all(np.diff(run.t_impacts) > 0)
    assert np.all(run.impact_normal_peak > body.weight)        # N: impacts load the soil
    assert run.normal_max >= np.max(run.impact_normal_peak) * (1 - 1e-12)
    assert run.n_steps > 0 and run.t_end > 0


def test_free_motion_from_a_tilt(mdl):
    """No excitation: free rocking from theta0 (the ground acceleration column is zero)."""
    run = W.simulate(mdl, theta0=0.02, t_max=2.0)
    assert run.t.size == 1001 and run.theta[0] == 0.02
    np.testing.assert_array_equal(run.accel, 0.0)
    assert run.n_impacts > 0


def test_pulse_and_record_are_the_same_excitation(mdl):
    """A triangular pulse is linear between samples that hit its corners: as a record in g
    (any g, the record's unit) it is the same ground motion, so the same run."""
    dt = 0.0025
    p = pulse.define("triangular", amp=0.3, amp_unit="g", duration=0.4, peak_frac=0.5)
    t = np.linspace(0.0, 1.2, 241)
    run_p = W.simulate(mdl, p, t=t)
    samples = pulse.triangular(np.arange(0, 161) * dt, amp=0.3, duration=0.4, peak_frac=0.5,
                               amp_unit="g").a
    run_g = W.simulate(mdl, accel=samples / G, dt=dt, t=t)
    run_5 = W.simulate(mdl, accel=samples / 5.0, dt=dt, g=5.0, t=t)
    scale = max(run_p.theta_max, 1e-12)
    np.testing.assert_allclose(run_g.theta, run_p.theta, atol=1e-5 * scale)
    np.testing.assert_allclose(run_g.accel, run_p.accel, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(run_5.theta, run_g.theta, rtol=1e-12, atol=1e-14 * scale)
    assert run_g.outcome == run_p.outcome


def test_record_object_in_g(mdl):
    from seispulse import records
    dt = 0.01
    acc = 0.2 * np.sin(2 * np.pi * np.arange(100) * dt / 0.5)
    rec = records.from_array(acc, dt, units="g")
    a = W.simulate(mdl, accel=rec, t_max=1.0)
    b = W.simulate(mdl, accel=acc, dt=dt, t_max=1.0)
    np.testing.assert_array_equal(a.theta, b.theta)
    assert a.t.size == 1001 and a.t[-1] == 1.0


def test_simulate_errors(body, mdl):
    p = pulse.define("sine_cycle", amp=0.2, amp_unit="g", period=0.5)
    with pytest.raises(InvalidInputError, match="^pulse, accel"):
        W.simulate(mdl, p, accel=[0.0, 0.1], dt=0.01, t_max=1.0)
    with pytest.raises(InvalidInputError, match="^dt"):
        W.simulate(mdl, accel=[0.0, 0.1], t_max=1.0)
    with pytest.raises(InvalidInputError, match="^t, t_max"):
        W.simulate(mdl, p)
    with pytest.raises(InvalidInputError, match="^model"):
        W.simulate(body, p, t_max=1.0)
    with pytest.raises(InvalidInputError, match="^t_max"):
        W.simulate(mdl, p, t_max=-1.0)
    with pytest.raises(InvalidInputError, match="^g "):
        W.simulate(mdl, accel=[0.0, 0.1], dt=0.01, g=0.0, t_max=1.0)
    with pytest.raises(InvalidInputError, match="^pulse"):
        W.simulate(mdl, "sine", t_max=1.0)


def test_model_errors(body):
    blk = cylinder.block_props(0.5, 2.0)
    with pytest.raises(InvalidInputError, match="^k "):
        W.model(body, -1.0)
    with pytest.raises(InvalidInputError, match="^alpha"):
        W.model(body, K, alpha=1.0)
    with pytest.raises(InvalidInputError, match="^alpha"):
        W.model(blk, K)
    with pytest.raises(InvalidInputError, match="^xi, c"):
        W.model(body, K, xi=0.01, c=10.0)
    with pytest.raises(InvalidInputError, match="^xi "):
        W.model(body, K, xi=-0.01)
    with pytest.raises(InvalidInputError, match="^damping_ref = 'horizontal'"):
        W.model(body, K, xi=0.01, damping_ref="horizontal")
    with pytest.raises(InvalidInputError, match="^k_method"):
        W.model(body, K, k_method="secant")
    with pytest.raises(InvalidInputError, match="^body"):
        W.model("cylinder", K)


def test_map_with_its_rigid_companion(mdl):
    x = np.array([2.0, 6.0])
    y = np.array([1.5, 4.0, 8.0])
    wm = W.overturning_map(mdl, "sine_cycle", x, y)
    assert wm.classes.shape == (3, 2) and wm.classes.dtype.kind == "i"
    assert set(np.unique(wm.classes)) <= {-1, 0, 1, 2, 3}
    rigid = cylinder.overturning_map(mdl.body, "sine_cycle", x, y)
    np.testing.assert_array_equal(wm.rigid, rigid)
    np.testing.assert_array_equal(wm.difference, cylinder.map_difference(wm.classes, rigid))
    alone = W.overturning_map(mdl, "sine_cycle", x, y, compare_rigid=False)
    assert alone.rigid is None and alone.difference is None
    np.testing.assert_array_equal(alone.classes, wm.classes)
    with pytest.raises(InvalidInputError, match=r"^x: must be a 1-d"):
        W.overturning_map(mdl, "sine_cycle", np.zeros((2, 2)), y)
    with pytest.raises(InvalidInputError, match="^axes"):
        W.overturning_map(mdl, "sine_cycle", x, y, axes="hz")
    with pytest.raises(InvalidInputError, match="^compare_rigid"):
        W.overturning_map(mdl, "sine_cycle", x, y, compare_rigid="yes")


def test_plots_make_figures(mdl):
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt
    run = W.simulate(mdl, pulse.define("sine_cycle", amp=0.3, amp_unit="g", period=0.5),
                     t_max=1.5)
    axes = W.plot_history(run, mdl)
    assert len(axes) == 3 and axes[2].get_ylabel() == "contact width (m)"
    x, y = np.array([2.0, 6.0]), np.array([1.5, 8.0])
    ax = W.plot_map(W.overturning_map(mdl, "sine_cycle", x, y), x, y)
    assert ax.get_xlabel() == "omega_p / p"
    plt.close("all")
    with pytest.raises(InvalidInputError, match="^run"):
        W.plot_history("run")
