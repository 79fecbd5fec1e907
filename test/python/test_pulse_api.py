"""Python conventions of seispulse.pulse: broadcasting, result types, errors, units.

Numerical accuracy against independent references is in test_pulse_reference.py."""
import math

import numpy as np
import pytest

import seispulse
from seispulse import pulse as p


def test_scalars_give_python_floats_and_named_tuples():
    r = p.exp_pulse(0.25, 0.0)
    assert isinstance(r, p.PulseHistory)
    assert all(type(x) is float for x in r)
    # triangle: a = 2 tau, v = tau^2, d = tau^3 / 3
    assert r == (0.5, 0.0625, 0.25**3 / 3)
    peaks = p.exp_pulse_peaks(0.0, full=True)
    assert isinstance(peaks, p.PulsePeaks) and peaks == (0.5, 0.5)
    assert p.exp_pulse_impulse_amplitude(0.0) == 2.0


def test_broadcasting_like_a_ufunc():
    tau = np.linspace(0.0, 2.0, 5)[:, None]
    beta = np.array([-np.inf, -1.0, 0.0, 3.0])
    r = p.exp_pulse(tau, beta, full=True)
    assert r.a.shape == r.v.shape == r.d.shape == (5, 4)
    for j, b in enumerate(beta):
        column = p.exp_pulse(tau[:, 0], b, full=True)
        np.testing.assert_array_equal(r.d[:, j], column.d)
    # lists and 0-d arrays are accepted; shapes are kept
    assert p.exp_pulse([[0.1, 0.2]], 1.0).v.shape == (1, 2)
    assert p.exp_pulse_peaks(np.array([-1.0, 1.0])).vg.shape == (2,)
    # SI parameters broadcast too: two amplitudes, three times
    r = p.half_sine(np.array([0.1, 0.2, 0.3])[:, None], np.array([1.0, 2.0]), 0.6)
    assert r.a.shape == (3, 2)
    np.testing.assert_allclose(r.a[:, 1], 2.0 * r.a[:, 0], rtol=1e-15)


def test_parameter_arrays_match_scalar_calls():
    t = np.linspace(-0.1, 2.0, 7)
    freqs = np.array([0.8, 1.3])
    r = p.ricker(t[:, None], 2.0, freqs, t0=1.0)
    for j, f in enumerate(freqs):
        np.testing.assert_array_equal(r.v[:, j], p.ricker(t, 2.0, f, t0=1.0).v)


def test_amplitude_in_g():
    a_g = p.rectangular(0.1, 0.5, 1.0, amp_unit="g")
    assert a_g.a == 0.5 * p.STANDARD_GRAVITY
    assert p.rectangular(0.1, 0.5, 1.0, amp_unit="g", g=9.81).a == 0.5 * 9.81
    si = p.exponential(0.3, 0.5 * 9.81, 0.6, -2.0)
    in_g = p.exponential(0.3, 0.5, 0.6, -2.0, amp_unit="g", g=9.81)
    assert si == pytest.approx(in_g, rel=1e-15)


def test_si_scaling_of_the_dimensionless_pulse():
    amp, td = 2.5, 0.7
    t = np.linspace(-0.2, 2.0, 23)
    si = p.exponential(t, amp, td, -1.5, full=True)
    nd = p.exp_pulse(t / td, -1.5, full=True)
    np.testing.assert_allclose(si.a, amp * nd.a, rtol=1e-15)
    np.testing.assert_allclose(si.v, amp * td * nd.v, rtol=1e-15)
    np.testing.assert_allclose(si.d, amp * td**2 * nd.d, rtol=1e-15)


def test_defaults_of_ricker_and_mp():
    # Ricker peaks at t0 = 1.5 / f_p by default
    assert p.ricker(1.5 / 2.0, 3.0, 2.0).a == pytest.approx(3.0, rel=1e-15)
    # M&P starts at t = 0 by default: envelope peak at gamma / (2 f_p), v = A there (nu = 0)
    r = p.mavroeidis_papageorgiou(2.0 / (2 * 1.5), 0.8, 1.5, 2.0)
    assert r.v == pytest.approx(0.8, rel=1e-15)
    assert p.mavroeidis_papageorgiou(-1e-9, 0.8, 1.5, 2.0) == (0.0, 0.0, 0.0)


def test_evaluate_by_name_and_alias():
    t = np.linspace(0, 1, 11)
    np.testing.assert_array_equal(p.evaluate("ricker", t, amp=1.0, freq=2.0).a,
                                  p.ricker(t, 1.0, 2.0).a)
    np.testing.assert_array_equal(p.evaluate("mp", t, vamp=1.0, freq=2.0, gamma=2.0).v,
                                  p.mavroeidis_papageorgiou(t, 1.0, 2.0, 2.0).v)
    np.testing.assert_array_equal(p.evaluate("Triangle", t, amp=1.0, duration=1.0).d,
                                  p.triangular(t, 1.0, 1.0).d)
    assert set(p.KINDS) <= {"exponential", "half_sine", "sine_cycle", "cosine_cycle",
                            "rectangular", "triangular", "ricker", "mavroeidis_papageorgiou"}


def test_large_arrays_and_non_contiguous_input():
    tau = np.linspace(-1, 3, 200001)[::2]           # strided view
    r = p.exp_pulse(tau, -2.0, full=True)
    assert np.all(np.isfinite(r.d))
    np.testing.assert_array_equal(r.d, p.exp_pulse(np.ascontiguousarray(tau), -2.0, True).d)
    assert p.exp_pulse(np.array([], dtype=float), 1.0).a.shape == (0,)


@pytest.mark.parametrize("call, name", [
    (lambda: p.exp_pulse(0.1, math.nan), "beta"),
    (lambda: p.exp_pulse(math.nan, 0.0), "tau"),
    (lambda: p.exp_pulse(math.inf, 0.0), "tau"),
    (lambda: p.exp_pulse(0.1, 0.0, full="yes"), "full"),
    (lambda: p.exp_pulse_peaks(math.nan), "beta"),
    (lambda: p.exp_pulse_impulse_amplitude([0.0, math.nan]), "beta"),
    (lambda: p.exponential(0.1, 1.0, 0.0, 0.0), "td"),
    (lambda: p.exponential(0.1, math.inf, 1.0, 0.0), "amp"),
    (lambda: p.half_sine(0.1, 1.0, -1.0), "duration"),
    (lambda: p.half_sine(0.1, 1.0, 1.0, amp_unit="ft/s2"), "amp_unit"),
    (lambda: p.half_sine(0.1, 1.0, 1.0, amp_unit="g", g=-9.8), "g"),
    (lambda: p.sine_cycle(0.1, 1.0, math.nan), "period"),
    (lambda: p.cosine_cycle(0.1, 1.0, 0.0), "period"),
    (lambda: p.rectangular(0.1, 1.0, -2.0), "duration"),
    (lambda: p.triangular(0.1, 1.0, 1.0, peak_frac=1.5), "peak_frac"),
    (lambda: p.triangular(0.1, 1.0, 1.0, peak_frac=[0.5, -0.1]), "peak_frac"),
    (lambda: p.ricker(0.1, 1.0, 0.0), "freq"),
    (lambda: p.ricker(0.1, 1.0, 1.0, t0=-1.0), "t0"),
    (lambda: p.mavroeidis_papageorgiou(0.1, 1.0, 1.0, 1.0), "gamma"),
    (lambda: p.mavroeidis_papageorgiou(0.1, 1.0, 1.0, 2.0, nu_deg=math.inf), "nu_deg"),
    (lambda: p.mavroeidis_papageorgiou(0.1, 1.0, 1.0, 2.0, t0=0.5), "t0"),
    (lambda: p.mavroeidis_papageorgiou(0.1, math.nan, 1.0, 2.0), "vamp"),
    (lambda: p.evaluate("gabor", 0.1), "kind"),
    (lambda: p.evaluate("ricker", 0.1, amp=1.0), "ricker"),
    (lambda: p.exp_pulse([0.1, 0.2], [1.0, 2.0, 3.0]), "shapes"),
    (lambda: p.exp_pulse("abc", 0.0), "tau"),
    (lambda: p.exp_pulse(0.1, [[1.0], [2.0, 3.0]]), "beta"),
    (lambda: p.exp_pulse(0.1 + 1j, 0.0), "tau"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(seispulse.InvalidInputError) as info:
        call()
    assert isinstance(info.value, ValueError)
    assert str(info.value).startswith(name), str(info.value)


def test_messages_state_the_allowed_range():
    with pytest.raises(ValueError, match=r"peak_frac = 1\.5: must be in \[0, 1\]"):
        p.triangular(0.1, 1.0, 1.0, peak_frac=1.5)
    with pytest.raises(ValueError, match=r"t0 = 0\.5: must be >= gamma/\(2 freq\) = 1\.0 s"):
        p.mavroeidis_papageorgiou(0.1, 1.0, 1.0, 2.0, t0=0.5)
    with pytest.raises(ValueError, match="allowed: exponential, half_sine"):
        p.evaluate("gabor", 0.1)


def test_exception_hierarchy():
    assert issubclass(seispulse.InvalidInputError, ValueError)
    assert issubclass(seispulse.InvalidInputError, seispulse.SeispulseError)
    assert issubclass(seispulse.ConvergenceError, RuntimeError)
