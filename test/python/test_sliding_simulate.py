"""seispulse.sliding.simulate, the event-driven stick-slip integrator, against the
closed forms (the grid of doc/sliding.md section 9, through Python; the Fortran suite 'sliding'
runs a larger one), on sampled records, and its Python face."""
import math

import numpy as np
import pytest

from seispulse import pulse as P
from seispulse import sliding as S
from seispulse.errors import InvalidInputError

PI = math.pi
BETAS = [-np.inf, -1e3, -4 * PI, -PI, -1e-12, 0.0, 1e-12, 1.0, 2 * PI, 4 * PI, 300.0]
ETAS = [1e-3, 0.1, 0.5, 0.9, 0.999]


def exp_pulse(beta, full):
    return P.define("exponential", amp=1.0, td=1.0, beta=beta, full=full)


def close(a, b, rel=1e-9, abs_=1e-13):
    return abs(a - b) <= max(rel * abs(b), abs_)


@pytest.mark.parametrize("beta", BETAS)
@pytest.mark.parametrize("eta", ETAS)
@pytest.mark.parametrize("static_factor", [1.0, 1.3])
def test_half_cycle_closed_form_equals_integrator(beta, eta, static_factor):
    h = S.half_cycle(eta, beta, static_factor=static_factor)
    r = S.simulate(exp_pulse(beta, False), eta, static_factor=static_factor)
    if h.regime == "none":
        assert r.slides == []
        return
    (s,) = r.slides
    vg = P.exp_pulse_peaks(beta).vg
    assert close(s.t_start, h.tau_y) and close(s.t_stop, h.tau_m)
    assert close(s.u_stop - s.u_start, h.um)
    assert close(s.w_peak, h.vm * vg)


@pytest.mark.parametrize("beta", BETAS)
@pytest.mark.parametrize("eta1, eta2", [(0.1, 0.1), (0.5, 0.5), (0.9, 0.9), (0.05, 0.7),
                                        (0.7, 0.05), (0.3, 1.2), (1.2, 0.3), (0.05, 0.4)])
@pytest.mark.parametrize("static_factor, static_reverse", [(1.0, False), (1.2, False),
                                                           (1.2, True)])
def test_full_cycle_closed_form_equals_integrator(beta, eta1, eta2, static_factor,
                                                  static_reverse):
    f = S.full_cycle(eta1, beta, eta2=eta2, static_factor=static_factor,
                     static_reverse=static_reverse)
    r = S.simulate(exp_pulse(beta, True), eta1, ay_rev=eta2, static_factor=static_factor,
                   static_all=static_reverse)
    forward = [s for s in r.slides if s.direction > 0]
    reverse = [s for s in r.slides if s.direction < 0]
    assert len(forward) <= 1 and len(reverse) <= 1
    if forward:
        s = forward[0]
        assert close(s.t_start, f.tau_y1) and close(s.t_stop, f.tau_m1)
        assert close(s.u_stop - s.u_start, f.um1)
    else:
        assert f.mode in ("no_sliding", "reverse_only")
    if reverse:
        s = reverse[0]
        assert close(s.t_start, f.tau_y2) and close(s.t_stop, f.tau_m2)
        assert close(s.u_start - s.u_stop, f.um2)
        assert f.mode in ("stick", "slip", "reverse_only")
        assert (f.mode == "slip") == s.from_slip
    else:
        assert f.mode in ("no_sliding", "unilateral", "stuck")
    assert close(r.u_final, f.ures)


def test_example_1_9_2_exact_eta():
    # the exact |eta1| of the (unstable) slope, not the text's 0.315
    lam = math.radians(30)
    eta1 = abs(0.5 * (1 - math.tan(lam) / 0.33) / (1 + 0.33 * math.tan(lam)))
    eta2 = 0.5 * (1 + math.tan(lam) / 0.33) / (1 - 0.33 * math.tan(lam))
    f = S.full_cycle(eta1, -PI, eta2=eta2)
    r = S.simulate(exp_pulse(-PI, True), eta1, ay_rev=eta2)
    assert f.mode == "unilateral" and len(r.slides) == 1
    assert close(r.u_final, f.um1)


def test_sampled_triangle_is_the_pulse():
    # the piecewise-linear record through the kinks IS the triangle: same answer
    dt = 1.0 / 64
    t = np.arange(0, 2 + dt / 2, dt)
    a = P.exp_pulse(t, 0.0, full=True).a
    for eta in (0.2, 0.45, 0.8):
        rec = S.simulate(accel=a, dt=dt, ay=eta)
        exact = S.full_cycle(eta, 0.0)
        assert rec.u_final == pytest.approx(exact.ures, rel=1e-12, abs=1e-15)
        assert rec.slides[0].t_stop == pytest.approx(exact.tau_m1, rel=1e-12)


def test_sampled_exponential_converges_at_second_order():
    beta, eta = -PI, 0.3
    exact = S.half_cycle(eta, beta).um
    errors = []
    for k in (6, 7, 8, 9):
        dt = 2.0 ** -k
        t = np.arange(0, 1 + dt / 2, dt)
        a = P.exp_pulse(t, beta).a
        r = S.simulate(accel=a, dt=dt, ay=eta)
        # a half cycle ends with the constant ground velocity: the record stops at t = 1
        errors.append(abs(r.slides[0].u_stop - exact))
    ratios = [errors[i] / errors[i + 1] for i in range(3)]
    assert all(3.5 < q < 4.5 for q in ratios), ratios


def test_histories_on_a_grid():
    p = exp_pulse(-np.inf, True)
    eta = 0.3
    t = np.linspace(0.0, 4.0, 401)
    r = S.simulate(p, eta, t=t)
    # rectangle: u = (1 - eta) t^2 / 2 on the first lobe
    first = t <= 1
    np.testing.assert_allclose(r.u[first], (1 - eta) * t[first] ** 2 / 2, rtol=1e-13, atol=1e-16)
    assert r.u[-1] == pytest.approx(r.u_final) and r.w[-1] == 0.0
    assert r.u_max == pytest.approx(S.rectangle_full(eta)[1])


def test_any_pulse_runs():
    g = 9.80665
    for p in (P.define("half_sine", amp=0.4, amp_unit="g", duration=0.5),
              P.define("sine_cycle", amp=0.4, amp_unit="g", period=0.5),
              P.define("ricker", amp=0.5, amp_unit="g", freq=2.0),
              P.define("mp", vamp=0.8, freq=1.0, gamma=2.5, nu_deg=30.0),
              P.define("triangular", amp=0.4, amp_unit="g", duration=0.5, peak_frac=0.2)):
        r = S.simulate(p, 0.1 * g, ay_rev=0.15 * g)
        assert r.slides and math.isfinite(r.u_final)
        assert r.u_min <= r.u_final <= r.u_max


@pytest.mark.parametrize("call, pattern", [
    (lambda: S.simulate(None, 0.1), r"^pulse, accel: give exactly one"),
    (lambda: S.simulate(exp_pulse(0.0, False), None), r"^ay:"),
    (lambda: S.simulate(exp_pulse(0.0, False), -0.1), r"^ay = -0.1"),
    (lambda: S.simulate(exp_pulse(0.0, False), 0.1, static_factor=0.5), r"^static_factor"),
    (lambda: S.simulate(accel=[0.0, 1.0], ay=0.1), r"^dt:"),
    (lambda: S.simulate(accel=[0.0, 1.0], dt=0.0, ay=0.1), r"^dt = 0.0"),
    (lambda: S.simulate(accel=[0.0, math.nan], dt=0.1, ay=0.1), r"^accel"),
    (lambda: S.simulate((1, 2), 0.1), r"^pulse: must be"),
])
def test_bad_input(call, pattern):
    with pytest.raises(InvalidInputError, match=pattern):
        call()
