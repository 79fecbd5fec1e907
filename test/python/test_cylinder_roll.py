"""Rocking with rolling of a cylinder (seispulse._cylinder_roll.roll): an independent
Newton-Euler integration (rotation as a quaternion, contact point from the body's
geometry, scipy solve_ivp) of the same motion, the planar limit against
seispulse.rocking.simulate, energy, the [AD11] free-rocking scenarios (geometry of our
choice, r = 1 m, h = 3 m), bad input."""
from types import SimpleNamespace

import numpy as np
import pytest

from seispulse import cylinder, pulse, rocking
from seispulse.cylinder import ROLL_COLUMNS, RollRun, plot_roll, roll
from seispulse.errors import InvalidInputError

G = 9.80665


def solid(r=1.0, h=3.0, mass=1000.0):
    """A solid cylinder of seispulse.cylinder.props."""
    return cylinder.props(r, h, mass, g=G)


def inertia(body):
    """J_G (transverse, about the centre of mass) and J_axis of a solid cylinder, written
    here independently of the library (kg m^2)."""
    m, r, h = body.mass, body.r, body.h
    return m * (3 * r * r + 4 * h * h) / 12, m * r * r / 2


# ---- independent reference: quaternion + world-frame Newton-Euler ---------------------

def quat_mul(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return np.array([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2])


def quat_matrix(q):
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def euler_zxz(psi, theta, phi):
    """Quaternion of R = Rz(psi) Rx(theta) Rz(phi)."""
    qz1 = np.array([np.cos(psi / 2), 0, 0, np.sin(psi / 2)])
    qx = np.array([np.cos(theta / 2), np.sin(theta / 2), 0, 0])
    qz2 = np.array([np.cos(phi / 2), 0, 0, np.sin(phi / 2)])
    return quat_mul(quat_mul(qz1, qx), qz2)


def reference_rhs(body, accel):
    """y = (q (4), omega in the world frame (3), x_G, y_G). The contact point is the
    lowest rim point: P = B - r u, u = (Z - (Z.e3) e3)/|.|; rho = G - P = h e3 + r u and
    its time derivative from e3' = omega x e3; a_G = omega' x rho + omega x rho'; moments
    about G of the contact force R = m (a_G + g Z + a_g) acting at P."""
    m, r, h = body.mass, body.r, body.h
    a_t, c_ax = inertia(body)
    z = np.array([0.0, 0.0, 1.0])

    def rhs(t, y):
        q, om = y[:4], y[4:7]
        e3 = quat_matrix(q)[:, 2]
        e3d = np.cross(om, e3)
        w = z - e3[2] * e3
        wd = -e3d[2] * e3 - e3[2] * e3d
        nw = np.linalg.norm(w)
        u = w / nw
        ud = wd / nw - w * np.dot(w, wd) / nw**3
        rho = h * e3 + r * u
        rhod = h * e3d + r * ud
        i_g = a_t * np.eye(3) + (c_ax - a_t) * np.outer(e3, e3)
        i_p = i_g + m * (np.dot(rho, rho) * np.eye(3) - np.outer(rho, rho))
        ag = np.array([*accel(t), 0.0])
        b = -np.cross(om, i_g @ om) - m * np.cross(rho, np.cross(om, rhod) + G * z + ag)
        omd = np.linalg.solve(i_p, b)
        qd = 0.5 * quat_mul(np.array([0.0, *om]), q)
        vg = np.cross(om, rho)
        return np.concatenate([qd, omd, vg[:2]])

    return rhs


def reference_angles(y):
    e3 = quat_matrix(y[:4])[:, 2]
    return np.arccos(np.clip(e3[2], -1, 1)), np.arctan2(e3[0], -e3[1])


def run_reference(body, state, t_out, accel):
    from scipy.integrate import solve_ivp
    theta, psi, spin, thd, psd, phd = state
    n = np.array([np.cos(psi), np.sin(psi), 0.0])
    e3 = np.array([np.sin(theta) * np.sin(psi), -np.sin(theta) * np.cos(psi), np.cos(theta)])
    om = thd * n + psd * np.array([0.0, 0.0, 1.0]) + phd * e3
    y0 = np.concatenate([euler_zxz(psi, theta, spin), om, [0.0, 0.0]])
    sol = solve_ivp(reference_rhs(body, accel), (0.0, t_out[-1]), y0, method="DOP853",
                    rtol=1e-12, atol=1e-13, t_eval=t_out)
    assert sol.success
    return sol.y


def assert_matches_reference(run, body, state, t_out, accel):
    """theta, psi (mod 2 pi), x_G, y_G of `run` against run_reference to 1e-8 (rad, m)."""
    ref = run_reference(body, state, t_out, accel)
    th_ref, psi_ref = zip(*(reference_angles(ref[:, k]) for k in range(t_out.size)))
    np.testing.assert_allclose(run.theta, th_ref, rtol=0, atol=1e-8)
    dpsi = np.angle(np.exp(1j * (run.psi - np.array(psi_ref))))
    np.testing.assert_allclose(dpsi, 0.0, atol=1e-8)
    np.testing.assert_allclose(run.x_g, ref[7], rtol=0, atol=1e-8)
    np.testing.assert_allclose(run.y_g, ref[8], rtol=0, atol=1e-8)


@pytest.mark.parametrize("case", ["free", "pulse"])
def test_against_independent_newton_euler(case):
    pytest.importorskip("scipy")
    body = solid(0.8, 2.0, 350.0)
    state = (0.18, 0.4, 0.2, 0.15, 0.6, 2.0)
    t_out = np.linspace(0.0, 0.9, 10)
    if case == "free":
        accel, pl, beta = (lambda t: (0.0, 0.0)), None, 0.0
    else:
        beta = np.radians(70.0)
        amp, period = 0.25 * G, 0.6

        def accel(t):
            a = amp * np.sin(2 * np.pi * t / period) if t < period else 0.0
            return a * np.cos(beta), a * np.sin(beta)

        pl = pulse.define("sine_cycle", amp=amp, period=period)
    run = roll(body, pl, direction_deg=np.degrees(beta), theta0=state[0], psi0=state[1],
               spin0=state[2], theta_rate0=state[3], psi_rate0=state[4], spin_rate0=state[5],
               t=t_out, rtol=1e-12)
    assert run.n_impacts == 0
    assert_matches_reference(run, body, state, t_out, accel)
    # the motion is genuinely 3-D
    assert np.ptp(run.psi) > 0.3 and np.ptp(run.y_g) > 1e-3


@pytest.mark.parametrize("spin", [0.01, 0.1])
def test_near_grazing_against_independent_newton_euler(spin):
    """The [AD11] free runs from theta0 = 0.2 rad through the near-grazing pass (theta_min
    3.4e-5 and 3.6e-4 rad at t = 1.066 s, psi' up to 1.4e4 rad/s) against the quaternion
    reference: no floor pass, and theta, psi, x_G, y_G agree to 1e-8 (rad, m) after it.
    Both integrate at rtol 1e-12 (the reference with atol 1e-13 on the quaternion): the
    pass amplifies the local errors of either by at most the ratio of the time scales,
    theta_c/theta_min ~ 1e4, so 1e-8 is the error budget of the pair, not a fit."""
    pytest.importorskip("scipy")
    body = solid(1.0, 3.0, 1000.0)
    state = (0.2, 0.0, 0.0, 0.0, 0.0, spin)
    t_out = np.linspace(0.0, 1.3, 14)
    run = roll(body, theta0=0.2, spin_rate0=spin, t=t_out, rtol=1e-12)
    assert run.n_impacts == 0
    assert_matches_reference(run, body, state, t_out, lambda t: (0.0, 0.0))
    # the pass did turn the heading
    assert abs(run.psi[-1]) > 1.0


def test_planar_limit_equals_rocking_simulate():
    body = solid(1.0, 3.0, 1000.0)
    j_o = inertia(body)[0] + body.mass * (body.r**2 + body.h**2)
    blk = rocking.symmetric_block(np.hypot(body.r, body.h), body.theta_c,
                                  j_o / (body.mass * (body.r**2 + body.h**2)), g=G)
    pl = pulse.define("sine_cycle", amp=0.6, amp_unit="g", period=1.0)
    t = np.linspace(0.0, 12.0, 601)
    planar = rocking.simulate(blk, pl, t=t, t_max=12.0, rtol=1e-12)
    run = roll(body, pl, direction_deg=-40.0, t=t, t_max=12.0, rtol=1e-12, e=blk.e)
    assert planar.n_impacts >= 3
    assert run.n_impacts == planar.n_impacts
    np.testing.assert_allclose(run.t_impacts, planar.t_impacts, rtol=0, atol=1e-9)
    np.testing.assert_allclose(run.theta, np.abs(planar.theta), rtol=0, atol=1e-9)
    # after the uplift (rocking plane along the pulse: psi = -40 - 90 degrees) psi jumps
    # by pi at each impact (several impacts between two output times: k pi), nothing else
    up = t > run.t_uplift
    assert abs(run.psi[up][0] - np.radians(-130.0)) < 1e-12
    jumps = np.diff(run.psi[up])
    k = np.round(jumps / np.pi)
    np.testing.assert_allclose(jumps, k * np.pi, rtol=0, atol=1e-11)
    assert k.sum() == run.n_impacts


def test_energy_conserved_in_free_motion_with_spin():
    body = solid(1.0, 3.0, 1000.0)
    run = roll(body, theta0=0.25, theta_rate0=-0.1, psi_rate0=0.3, spin_rate0=0.8,
               t=np.linspace(0, 1.2, 121), rtol=1e-12)
    assert run.n_impacts == 0
    assert run.energy_drift < 1e-9
    # relative to the energy above rest (G at height h at rest), not to E
    above_rest = run.energy[0] - body.mass * G * body.h
    np.testing.assert_allclose(run.energy, run.energy[0], rtol=0, atol=1e-9 * above_rest)


@pytest.mark.parametrize("spin", [1e-9, 1e-5, 1e-3, 0.1, 1.0])
def test_energy_between_impacts_any_spin(spin):
    """From theta0 = 0.2 rad with the spin rate given: impacts (and floor passes) lose
    energy, every flight in between keeps it to 1e-9 of the energy above rest."""
    run = roll(solid(1.0, 3.0, 1000.0), theta0=0.2, spin_rate0=spin,
               t=np.linspace(0.0, 4.0, 401))
    assert run.energy_drift < 1e-9
    with_impacts = run.n_impacts > 0
    assert with_impacts == (spin < 1e-3)
    # with spin every impact is a pass below the floor (doc/rolling.md section 4)
    assert run.n_floor == run.n_impacts


def test_loose_tolerance_near_grazing_completes():
    """Small spin rates (near-grazing passes, floor passes, touches) at the loosest rtol:
    every run ends normally, as rest or at t_max with a finite history up to it (a step
    blown up near theta = 0 must be rejected, a touch must not end a run early)."""
    body = solid(1.0, 3.0, 1000.0)
    t = np.linspace(0.0, 6.0, 61)
    for w in np.geomspace(1e-6, 3e-3, 40):
        run = roll(body, theta0=0.2, spin_rate0=w, t=t, rtol=1e-3)
        assert run.outcome in ("rest", "time_limit"), (w, run.outcome)
        if run.outcome == "time_limit":
            assert run.t_end == 6.0, (w, run.t_end)
        assert np.all(np.isfinite(run.theta)), w


def test_small_spins_end_at_rest_like_the_planar_run():
    """doc/rolling.md section 7: spin rates up to 1e-4 rad/s from theta0 = 0.2 rad pass
    below the floor as often as the planar run impacts, and end at rest (t_max = inf),
    from the planar rest time on, within 13400 steps."""
    body = solid(1.0, 3.0, 1000.0)
    t = np.linspace(0.0, 20.0, 201)
    planar = roll(body, theta0=0.2, t=t, t_max=np.inf)
    assert planar.outcome == "rest" and planar.n_floor == 0
    assert planar.n_impacts == 68 and abs(planar.t_end - 8.73) < 0.005
    for w, t_end in ((1e-12, 8.73), (1e-5, 9.27), (1e-4, 15.47)):
        run = roll(body, theta0=0.2, spin_rate0=w, t=t, t_max=np.inf)
        assert run.outcome == "rest", w
        assert run.n_impacts == run.n_floor == planar.n_impacts, w
        assert abs(run.t_end - t_end) < 0.005, (w, run.t_end)
        assert run.n_steps <= 13400, (w, run.n_steps)


def test_thesis_free_rocking_scenarios():
    """theta0 = 0.2 rad, spin rates 0, 0.01, 0.1 rad/s ([AD11] section 1.2; r = 1 m,
    h = 3 m is our choice: the thesis' geometry is lost)."""
    body = solid(1.0, 3.0, 1000.0)
    t = np.linspace(0.0, 4.0, 4001)
    runs = [roll(body, theta0=0.2, spin_rate0=w, t=t, rtol=1e-11) for w in (0.0, 0.01, 0.1)]
    t_hit = runs[0].t_impacts[0]
    first = t < t_hit
    for other in runs[1:]:
        np.testing.assert_allclose(other.theta[first], runs[0].theta[first], atol=0.004)
    # zero spin: psi 0 then pi, no intermediate value
    assert set(np.round(runs[0].psi[t < t_hit + 0.5], 12)) == {0.0, round(np.pi, 12)}
    # with spin 0.1 rad/s the heading sweeps through intermediate values near theta ~ 0
    near = (t > t_hit - 0.5) & (t < t_hit + 0.5)
    folded = np.mod(runs[2].psi[near], np.pi)
    assert np.any((folded > 0.1 * np.pi) & (folded < 0.9 * np.pi))


def test_rolling_doc_section6_numbers():
    """The numbers quoted in doc/rolling.md section 6 (theta0 = 0.2 rad, r = 1 m, h = 3 m,
    rtol 1e-11), to the digits quoted: the spinless impact time, the distance to the
    spinless history over [0, t_1 - 0.5 ms], the minimum of the pass and the sweep of psi
    over the 2 ms centred on it (output grid 0.1 microsecond)."""
    body = solid(1.0, 3.0, 1000.0)
    t_1 = roll(body, theta0=0.2, t=[0.0, 2.0], rtol=1e-11).t_impacts[0]
    assert abs(t_1 - 1.0658) < 5e-5
    t = np.linspace(0.0, t_1, 2001)[:-1]       # up to t_1 - 0.53 ms
    base = roll(body, theta0=0.2, t=t, rtol=1e-11).theta
    quoted = {0.01: (3.6e-6, 3.4e-5, 1.06583, -0.08, -3.18, 1.4e4),
              0.1: (2.5e-4, 3.6e-4, 1.06607, -0.69, -2.48, 1.2e3)}
    for w, (dist, th_min, t_min, psi_a, psi_b, rate) in quoted.items():
        run = roll(body, theta0=0.2, spin_rate0=w, t=t, rtol=1e-11)
        assert np.max(np.abs(run.theta - base)) == pytest.approx(dist, rel=0.05)
        tf = np.linspace(t_1 - 2e-3, t_1 + 2e-3, 40001)
        fine = roll(body, theta0=0.2, spin_rate0=w, t=tf, rtol=1e-11)
        k = np.argmin(fine.theta)
        assert fine.n_impacts == 0
        assert fine.theta[k] == pytest.approx(th_min, rel=0.02)
        assert abs(tf[k] - t_min) < 5e-6
        assert fine.psi[k - 10000] == pytest.approx(psi_a, abs=0.005)
        assert fine.psi[k + 10000] == pytest.approx(psi_b, abs=0.005)
        assert np.max(np.abs(fine.psi_rate)) == pytest.approx(rate, rel=0.05)


def test_result_fields_and_plot(tmp_path):
    body = solid()
    run = roll(body, pulse.define("half_sine", amp=0.5, amp_unit="g", duration=0.5),
               direction_deg=20.0, t_max=3.0)
    assert isinstance(run, RollRun)
    assert run.t.size == 1001 and run.theta.size == 1001
    assert set(ROLL_COLUMNS) <= set(RollRun._fields)
    assert run.t_uplift > 0 and run.outcome in ("rest", "time_limit", "overturn")
    assert np.all(run.normal_force[np.isfinite(run.normal_force)] > 0)
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    axes = plot_roll(run, title="half-sine 0.5 g")
    assert len(axes) == 3
    axes[0].figure.savefig(tmp_path / "roll.png")


def test_two_component_record_rotating_direction():
    """A record whose direction turns: the heading follows, energy is finite, the run
    completes within its step budget."""
    body = solid(0.5, 1.5, 100.0)
    dt = 0.01
    tt = np.arange(0, 3.0, dt)
    amp = 0.5 * np.sin(np.pi * tt / 3.0)
    run = roll(body, accel_x=amp * np.cos(2 * tt), accel_y=amp * np.sin(2 * tt), dt=dt,
               t=np.linspace(0, 5, 501))
    assert run.t_uplift > 0
    assert np.all(np.isfinite(run.theta)) and np.ptp(run.psi) > 0.5


@pytest.mark.parametrize("kwargs, name", [
    (dict(theta0=-0.1), "theta0"),
    (dict(theta0=np.pi / 2), "theta0"),
    (dict(theta0=0.1, theta_rate0=np.nan), "theta_rate0"),
    (dict(theta0=0.1, psi_rate0=np.nan), "psi_rate0"),
    (dict(theta0=0.1, spin_rate0=np.inf), "spin_rate0"),
    (dict(theta0=0.1, e=1.2), "e ="),
    (dict(theta0=0.1, e=-0.1), "e ="),
    (dict(accel_x=[0.1, 0.2], accel_y=[0.1, 0.2], dt=0.0), "dt"),
    (dict(accel_x=[0.1, 0.2], accel_y=[0.1, 0.2], dt=-0.01), "dt"),
    (dict(accel_x=[0.1, 0.2], accel_y=[0.1], dt=0.01), "accel_y"),
    (dict(accel_x=[0.1, 0.2], dt=0.01), "accel_x, accel_y"),
    (dict(theta0=0.1, rtol=0.5), "rtol"),
])
def test_bad_input_names_the_parameter(kwargs, name):
    kwargs.setdefault("t", [0.0, 1.0])
    with pytest.raises(InvalidInputError, match=name):
        roll(solid(), **kwargs)


def test_body_must_be_a_cylinder_with_j_axis():
    with pytest.raises(InvalidInputError, match="body"):
        roll(SimpleNamespace(r=1.0, h=3.0, mass=1.0, g=G, restitution=0.8), theta0=0.1,
             t=[0.0, 1.0])
    custom = cylinder.props(1.0, 3.0, 1.0, g=G, j_o=20.0)   # J_axis not given
    with pytest.raises(InvalidInputError, match="j_axis"):
        roll(custom, theta0=0.1, t=[0.0, 1.0])
