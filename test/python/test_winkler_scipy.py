"""Dynamics of seispulse.winkler (model, simulate, overturning_map; doc/winkler.md section
9) against the independent reference winkler_reference.py (numpy and scipy only: contact
integrals by adaptive quadrature over the active interval, solve_ivp BDF restarted at
every contact change, the events defined as in doc/winkler.md section 9.4): histories
theta(t), v(t), N(t), M(t) on a grid, event times, outcome and a 5 x 5 block of map
classes, for a cylinder and a block on constant k, a cylinder on varying k, and a record
in g. Both integrate at rtol 1e-10 (the maps: the library's default, the reference 1e-8).

Tolerances (measured differences in brackets): theta 2e-7 theta_max (3e-8 to 5e-8) and
v 3e-5 v_s (1e-6; v_s = W/(k A)): the integration errors of two rtol 1e-10 runs, grown by
the impacts (each shifts the phase by the error of its time); N and M 5e-6 of their
largest values (2e-7, 4e-7): on the grid the histories differ by the impact-time
differences (<= 1e-8 s) times the rate of N after an impact, up to omega_v N_max (omega_v =
sqrt(k A/m) = 111 rad/s for the cylinder); event times 1e-7 s (9e-9 s: located to ~1e-9 s
by both, the impacts carry the phase error); theta_max: the library's is at most 1e-5
below the reference's (the reference locates the extremes, theta' = 0; the library takes
the largest of sampled points of its steps, which misses the top by up to 6e-6 relative,
seen with the record). Varying k leaves the contact entirely (lift-off and touch-down
impacts): v to 3e-4 v_s (1e-4) and N, M to 2e-5 (3e-6, 5e-6)."""
import math

import numpy as np
import pytest

pytest.importorskip("scipy")
from seispulse import cylinder, pulse  # noqa: E402

winkler = pytest.importorskip("seispulse.winkler")

if not hasattr(winkler, "simulate"):
    pytest.skip("seispulse.winkler has no dynamics in this build", allow_module_level=True)

import winkler_reference as wr  # noqa: E402

G = 9.80665
E_SOIL, NU, XI = 100e6, 0.3, 0.003
CODES = {"safe": 0, "overturn_no_impact": 1, "overturn_one_impact": 2, "overturn_many_impacts": 3,
         "time_limit": 4}
RTOL = 1e-10


def thesis_cylinder(k_method="constant", xi=XI):
    """[AD11]'s example: solid r = 1 m, h = 3 m, rho = 2500 kg/m^3 on E = 100 MPa, nu = 0.3
    (k = 32 G/(3 pi (1 - nu) r) = 1.866e8 N/m^3): (reference body, library model)."""
    body = wr.solid_cylinder(1.0, 3.0, rho=2500.0, g=G)
    k = wr.modulus_circle(E_SOIL / (2 * (1 + NU)), NU, 1.0)
    model = winkler.model(cylinder.props(1.0, 3.0, mass=body.mass, g=G), k, xi=xi,
                          k_method=k_method)
    return body, model


def block_model():
    """A solid block b = 0.5 m, alpha = 0.6 m, h = 1.5 m, rho = 2500 kg/m^3 on k = 5e7 N/m^3."""
    body = wr.solid_block(0.5, 0.6, 1.5, rho=2500.0, g=G)
    model = winkler.model(cylinder.block_props(0.5, 1.5, mass=body.mass, g=G), 5e7,
                          alpha=0.6, xi=XI)
    return body, model


def test_models_agree():
    """The library's body, dashpot (DAMP_ROCKING) and static overturning angle equal the
    reference's (inertia written in winkler_reference, c = 2 xi I_O omega_r/I, the first
    zero of the closed-form imposed moment found by brentq)."""
    for body, model in (thesis_cylinder(), block_model()):
        assert model.body.J_G == pytest.approx(body.j_g, rel=1e-14)
        assert model.c == pytest.approx(wr.damping_rocking(body, model.k, XI), rel=1e-13)
        assert model.theta_overturn == pytest.approx(wr.static_theta_overturn(body, model.k),
                                                     rel=1e-10)


def sine(amp_g, period):
    """The library's one-sine pulse and the reference's (checked equal on a grid)."""
    shaking = pulse.define("sine_cycle", amp=amp_g, amp_unit="g", period=period, g=G)
    accel, breaks = wr.sine_pulse(amp_g * G, period)
    t = np.linspace(-0.1, 1.2 * period, 97)
    np.testing.assert_allclose(pulse.sine_cycle(t, amp_g, period, amp_unit="g", g=G).a,
                               [accel(x) for x in t], rtol=0, atol=1e-12 * amp_g * G)
    return shaking, accel, breaks


def reference(body, model, accel, breaks, t, **kw):
    return wr.simulate(body, model.k, model.c, accel, t, breaks, method="BDF", rtol=RTOL,
                       theta_overturn=model.theta_overturn,
                       varying=model.k_method == "varying", **kw)


def assert_histories_agree(run, ref, body, model, v_tol=3e-5, force_tol=5e-6):
    """The docstring's tolerances, on the part of the grid both runs reach."""
    ok = np.isfinite(ref.theta)
    assert np.all(np.isfinite(run.theta[ok]))
    v_s = body.weight / (model.k * body.area)
    np.testing.assert_allclose(run.theta[ok], ref.theta[ok], rtol=0, atol=2e-7 * ref.theta_max)
    np.testing.assert_allclose(run.v[ok], ref.v[ok], rtol=0, atol=v_tol * v_s)
    n_max, m_max = np.max(ref.normal[ok]), np.max(np.abs(ref.moment[ok]))
    np.testing.assert_allclose(run.normal[ok], ref.normal[ok], rtol=0, atol=force_tol * n_max)
    np.testing.assert_allclose(run.moment[ok], ref.moment[ok], rtol=0, atol=force_tol * m_max)
    # the library's width is that of delta > 0 (the geometric contact)
    geo = [wr.geometric_width(body, (v, th)) for v, th in zip(ref.v[ok], ref.theta[ok])]
    np.testing.assert_allclose(run.width[ok], geo, rtol=0, atol=1e-5 * body.r)


def assert_events_agree(run, ref):
    assert run.n_impacts == ref.n_impacts
    np.testing.assert_allclose(run.t_impacts, ref.t_impacts, rtol=0, atol=1e-7)
    for name in ("t_uplift", "t_lift_off", "t_overturn"):
        a, b = getattr(run, name), getattr(ref, name)
        assert math.isnan(a) == math.isnan(b), name
        if not math.isnan(a):
            assert a == pytest.approx(b, abs=1e-7), name
    # both locate the extremes (theta' = 0): they agree as the histories do
    assert run.theta_max == pytest.approx(ref.theta_max, rel=2e-7)


@pytest.mark.parametrize("footing", ["circle", "rectangle"])
def test_one_sine_with_uplift_and_impacts(footing):
    """One sine cycle (circle: 0.6 g, T_p = 0.5 s; block: 0.4 g, 0.5 s), 3 s: uplift, three
    and four impacts, safe (the reference proves it by the same energy barrier)."""
    body, model = thesis_cylinder() if footing == "circle" else block_model()
    shaking, accel, breaks = sine(0.6 if footing == "circle" else 0.4, 0.5)
    t = np.linspace(0.0, 3.0, 301)
    run = winkler.simulate(model, shaking, t=t, rtol=RTOL)
    ref = reference(body, model, accel, breaks, t, prove_safe=True)
    assert ref.n_impacts == (3 if footing == "circle" else 4)
    assert CODES[run.outcome] == ref.outcome == wr.OUTCOME_SAFE
    assert_events_agree(run, ref)
    assert_histories_agree(run, ref, body, model)
    assert run.energy_error < 1e-6


def overturning_case():
    """A cell of class 2 (omega_p = 7.5 p, a_p = 8 g tan(theta_c), T_p = 0.55 s): one impact
    (1.38 s), then out past theta_overturn (2.57 s)."""
    body, model = thesis_cylinder()
    period = 2 * math.pi / (7.5 * body.p)
    shaking, accel, breaks = sine(8.0 * math.tan(body.theta_c), period)
    t = np.linspace(0.0, 3.0, 301)
    run = winkler.simulate(model, shaking, t=t, rtol=RTOL)
    return body, model, run, accel, breaks, t


def test_one_sine_overturning_after_an_impact():
    """overturning_case: the outcome, the impact and the time of the outward crossing of
    theta_overturn agree, and the histories up to it."""
    body, model, run, accel, breaks, t = overturning_case()
    ref = reference(body, model, accel, breaks, t)
    assert CODES[run.outcome] == ref.outcome == wr.OUTCOME_ONE_IMPACT
    assert ref.t_overturn > 2.0
    assert run.n_impacts == ref.n_impacts == 1
    np.testing.assert_allclose(run.t_impacts, ref.t_impacts, rtol=0, atol=1e-7)
    assert run.t_uplift == pytest.approx(ref.t_uplift, abs=1e-7)
    assert run.t_overturn == pytest.approx(ref.t_overturn, abs=1e-7)
    assert run.t_end == pytest.approx(ref.t_end, abs=1e-7)
    ref.theta[t >= ref.t_overturn] = np.nan
    assert_histories_agree(run, ref, body, model)


def test_theta_max_reaches_theta_overturn_when_overturned():
    """A run that ends on the outward crossing of theta_overturn has theta_max >=
    theta_overturn (the reference: theta_max = theta_overturn there)."""
    body, model, run, _, _, _ = overturning_case()
    assert run.outcome == "overturn_one_impact"
    assert run.theta_max >= model.theta_overturn * (1 - 1e-12)


def test_varying_modulus_is_the_references():
    """The varying-k rule of the reference ([G91] K_R/I of the equivalent rectangle, the
    pole by quadrature) is the library's varying_modulus, from slivers to full contact;
    only then is the dynamic comparison below meaningful."""
    body, model = thesis_cylinder("varying")
    b = np.concatenate([np.geomspace(1e-6, 0.1, 9), np.linspace(0.2, 2.0, 10)])
    np.testing.assert_allclose(winkler.varying_modulus(b, 1.0, model.k),
                               [wr.varying_k(body, model.k, x) for x in b], rtol=1e-10)
    blk, bm = block_model()
    bb = np.linspace(0.05, 1.0, 8)
    np.testing.assert_allclose(winkler.varying_modulus(bb, 0.5, bm.k, footing="rectangle",
                                                       alpha=0.6),
                               [wr.varying_k(blk, bm.k, x) for x in bb], rtol=1e-12)


def test_varying_k_with_lift_off():
    """Varying k ([AD11]: k of the geometric contact width), one sine 0.4 g, T_p = 1 s,
    4 s: the body leaves the soil entirely (t_lift_off), two impacts; no energy criterion
    with varying k, so both end at the time limit."""
    body, model = thesis_cylinder("varying")
    shaking, accel, breaks = sine(0.4, 1.0)
    t = np.linspace(0.0, 4.0, 401)
    run = winkler.simulate(model, shaking, t=t, rtol=RTOL)
    ref = reference(body, model, accel, breaks, t)
    assert not math.isnan(ref.t_lift_off) and ref.n_impacts == 2
    assert CODES[run.outcome] == ref.outcome == wr.OUTCOME_TIME_LIMIT
    assert_events_agree(run, ref)
    assert_histories_agree(run, ref, body, model, v_tol=3e-4, force_tol=2e-5)


def test_record_in_g():
    """A record in g (dt = 0.01 s, 2.5 s of a decaying 1.6 Hz wave with a second
    harmonic, linear between samples, zero after), 4 s: the reference restarts at every
    sample (the kinks of the record)."""
    body, model = thesis_cylinder()
    dt = 0.01
    ts = np.arange(0.0, 2.5 + dt / 2, dt)
    rec = (0.45 * np.sin(2 * np.pi * 1.6 * ts) + 0.15 * np.sin(2 * np.pi * 3.2 * ts + 0.4)) \
        * np.exp(-0.4 * ts)
    rec[0] = 0.0
    t = np.linspace(0.0, 4.0, 401)
    run = winkler.simulate(model, accel=rec, dt=dt, g=G, t=t, rtol=RTOL)
    accel, breaks = wr.record_accel(rec, dt, G)
    ref = reference(body, model, accel, breaks, t, prove_safe=True)
    assert ref.n_impacts >= 2
    assert CODES[run.outcome] == ref.outcome
    assert_events_agree(run, ref)
    assert_histories_agree(run, ref, body, model)


def test_map_block_classes():
    """A 5 x 5 block of the one-sine map (omega_p/p 5 to 7, a_p/(g tan theta_c) 4 to 6:
    classes 0, 1 and 2 meet there) by overturning_map against the reference's cells
    (winkler_reference.map_cell: to the end of the pulse and on for 100/p, safe by the
    energy barrier; BDF at rtol 1e-8): identical classes."""
    body, model = thesis_cylinder()
    x = np.array([5.0, 5.5, 6.0, 6.5, 7.0])
    y = np.array([4.0, 4.5, 5.0, 5.5, 6.0])
    classes = winkler.overturning_map(model, "sine_cycle", x, y, compare_rigid=False).classes
    ref = np.array([[wr.map_cell(body, model.k, model.c, xx, yy,
                                 theta_overturn=model.theta_overturn) for xx in x] for yy in y])
    assert set(ref.reshape(-1)) == {0, 1, 2}
    np.testing.assert_array_equal(classes, ref)
