"""seispulse.newmark.rigid: two-way and asymmetric sliding against the event-driven
integrator of seispulse.sliding on sampled pulses, second-order convergence to the
exponential-pulse closed forms, the incline relations, and the Python interface
(array ky, Records, histories, intervals, errors)."""
import numpy as np
import pytest

from seispulse import InvalidInputError, newmark, pulse, records, sliding

G = 9.80665


def exp_record(beta, n, full=True):
    """Exponential pulse, A_g = 1 g, t_d = 1 s, sampled at t_d/n."""
    tau = np.arange((2 if full else 1) * n + 1) / n
    a, _, _ = pulse.exp_pulse(tau, beta, full=full)
    return a


@pytest.mark.parametrize("beta", [-np.pi, -1.0, 0.0, 0.7, 3.0])
@pytest.mark.parametrize("ky,ky_up", [(0.2, 0.2), (0.35, 0.35), (0.15, 0.45), (0.5, 0.1)])
def test_two_way_equals_event_driven_integrator(beta, ky, ky_up):
    """On a sampled pulse the exact rule and sliding.simulate (the event-driven
    integrator of the sliding issue, on the same samples) are the same solution."""
    a = exp_record(beta, 40)
    dt = 0.025
    mode = "both" if ky == ky_up else "asym"
    kw = {} if mode == "both" else {"ky_up": ky_up}
    r = newmark.rigid(a, dt, ky, mode=mode, g=1.0, intervals=True, history=True, **kw)
    s = sliding.simulate(accel=a, dt=dt, ay=ky, ay_rev=ky_up, t=r.time)
    scale = max(abs(s.u_max), abs(s.u_min), 1e-12)
    assert abs(r.final_disp - s.u_final) <= 1e-12 * scale
    assert abs(r.u_max - s.u_max) <= 1e-12 * scale
    assert abs(r.u_min - s.u_min) <= 1e-12 * scale
    assert np.max(np.abs(r.disp - s.u)) <= 1e-12 * scale
    assert np.max(np.abs(r.vel - s.w)) <= 1e-11 * max(r.max_vel, 1e-12)
    assert len(r.slides) == len(s.slides)
    for x, y in zip(r.slides, s.slides):
        assert x.direction == y.direction and x.from_slip == y.from_slip
        assert x.t_start == pytest.approx(y.t_start, abs=1e-11)
        assert x.t_stop == pytest.approx(y.t_stop, abs=1e-11)


@pytest.mark.parametrize("beta,eta1,eta2", [(-np.pi, 0.5, 0.5), (0.4, 0.05, 0.7),
                                            (1.5, 0.3, 0.3), (-1.0, 0.25, 0.6)])
def test_exact_converges_to_closed_forms_at_second_order(beta, eta1, eta2):
    """Sampled full-cycle exponential pulses: mode 'asym' (or 'both') converges to
    sliding.full_cycle (peak and residual slip) with the error falling ~4x per halving."""
    fc = sliding.full_cycle(eta1, beta, eta2=eta2)
    errors = []
    for n in (50, 100, 200):
        a = exp_record(beta, n)
        if eta1 == eta2:
            r = newmark.rigid(a, 1.0 / n, eta1, mode="both", g=1.0)
        else:
            r = newmark.rigid(a, 1.0 / n, eta1, mode="asym", ky_up=eta2, g=1.0)
        errors.append(abs(r.final_disp - fc.ures) + abs(r.u_max - fc.um1))
    assert 3.3 < errors[0] / errors[1] < 4.7
    assert 3.3 < errors[1] / errors[2] < 4.7


def test_array_ky_matches_single_calls():
    a = exp_record(0.5, 100) * 0.8
    kys = np.array([0.05, 0.2, 0.5, 0.9])
    many = newmark.rigid(a, 0.01, kys, mode="both")
    for i, ky in enumerate(kys):
        one = newmark.rigid(a, 0.01, ky, mode="both")
        assert many.max_disp[i] == one.max_disp
        assert many.final_disp[i] == one.final_disp
    assert many.final_disp[-1] == 0.0      # 0.9 g > 0.8 g: no sliding
    assert many.max_disp.shape == (4,)
    assert np.all(np.diff(many.max_disp) <= 0)


def test_record_input_and_units():
    """A Record carries dt; accel in g and g in m/s^2 give metres (u scales with g)."""
    a = exp_record(-1.0, 200)
    rec = records.from_array(a, dt=0.005, name="exp")
    r1 = newmark.rigid(rec, ky=0.3)
    r2 = newmark.rigid(a, 0.005, 0.3)
    assert r1 == r2
    r3 = newmark.rigid(a, 0.005, 0.3, g=1.0)
    assert r3.final_disp * G == pytest.approx(r1.final_disp, rel=1e-14)
    with pytest.raises(InvalidInputError, match="dt"):
        newmark.rigid(rec, 0.01, 0.3)


def test_incline_and_factors():
    inc = newmark.incline(0.5, 15.0, xi_deg=0.0)
    res = sliding.inclined_resistances(0.5, 1.0, 15.0, 0.0)
    assert inc == newmark.Incline(res.eta1, res.eta2, res.k1, res.k2)
    lam = np.radians(15.0)
    assert inc.ky == pytest.approx((0.5 - np.tan(lam)) / (1 + 0.5 * np.tan(lam)), rel=1e-14)
    a = exp_record(0.3, 200) * 0.9
    r = newmark.rigid(a, 0.005, incline=inc, intervals=True)
    r1 = newmark.rigid(a, 0.005, inc.ky, mode="asym", ky_up=inc.ky_up, intervals=True)
    expected = sum((inc.k_down if s.direction > 0 else inc.k_up) * (s.u_stop - s.u_start)
                   for s in r1.slides)
    assert r.final_disp == pytest.approx(expected, rel=1e-13)
    flat = newmark.incline(0.5, 15.0, along_plane=False)
    assert flat.k_down == flat.k_up == 1.0
    with pytest.raises(InvalidInputError, match="slope_deg"):
        newmark.incline(0.2, 20.0)


def test_histories_and_intervals():
    a = exp_record(0.0, 100)
    r = newmark.rigid(a, 0.01, 0.4, history=True, intervals=True)
    assert r.time.shape == r.disp.shape == r.vel.shape == a.shape
    assert r.time[-1] == pytest.approx(0.01 * (a.size - 1))
    assert len(r.slides) >= 1 and all(s.direction == 1 for s in r.slides)
    assert r.max_disp == pytest.approx(max(s.u_stop for s in r.slides), rel=1e-15)
    plain = newmark.rigid(a, 0.01, 0.4)
    assert plain.time is None and plain.slides is None
    assert plain.final_disp == r.final_disp


@pytest.mark.parametrize("kwargs,name", [
    (dict(accel=[0.1, 0.2], dt=0.0, ky=0.1), "dt"),
    (dict(accel=[0.1, 0.2], dt=0.01, ky=-0.1), "ky"),
    (dict(accel=[0.1, 0.2], dt=0.01), "ky"),
    (dict(accel=[0.1, np.nan], dt=0.01, ky=0.1), r"accel\[1\]"),
    (dict(accel=[], dt=0.01, ky=0.1), "accel"),
    (dict(accel=[[0.1, 0.2]], dt=0.01, ky=0.1), "accel"),
    (dict(accel=[0.1, 0.2], dt=0.01, ky=0.1, mode="up"), "mode"),
    (dict(accel=[0.1, 0.2], dt=0.01, ky=0.1, method="rk4"), "method"),
    (dict(accel=[0.1, 0.2], dt=0.01, ky=0.1, mode="asym"), "ky_up"),
    (dict(accel=[0.1, 0.2], dt=0.01, ky=0.1, ky_up=0.2), "ky_up"),
    (dict(accel=[0.1, 0.2], dt=0.01, ky=0.1, mode="asym", ky_up=0.1, k_up=-1.0), "k_up"),
    (dict(accel=[0.1, 0.2], dt=0.01, ky=0.1, g=0.0), "g"),
    (dict(accel=[0.1, 0.2], dt=0.01, ky=[0.1, 0.2], history=True), "history"),
])
def test_bad_input_names_the_parameter(kwargs, name):
    with pytest.raises(InvalidInputError, match=f"^{name}"):
        newmark.rigid(**kwargs)
    assert issubclass(InvalidInputError, ValueError)
