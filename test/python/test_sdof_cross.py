"""The closed forms of seispulse.sdof against the library's exact recurrence on records.

A triangular pulse sampled with its corners on samples is exactly piecewise linear (the
jump of peak_frac = 0 at t = 0 too; not the jump at the end of peak_frac = 1), so
the recurrence on the sampled record (padded with rest, long enough to hold the
free-vibration maximum) must give the closed-form spectrum to rounding, at any T/dt,
with the true maxima between samples; eqsig's sample maxima and its PSA = PGA for
T < 6 dt do not. Smooth pulses (half sine, exponential, Ricker, M&P) converge to
their closed forms at second order in dt.
"""

import numpy as np
import pytest

from seispulse import pulse, sdof

G = 9.80665


def _triangle_record(amp, duration, peak_frac, dt, pad):
    n_pulse = int(round(duration / dt))
    t = np.arange(n_pulse + int(round(pad / dt)) + 1) * dt
    return pulse.triangular(t, amp, duration, peak_frac).a / G


@pytest.mark.parametrize("zeta", [0.0, 0.05, 0.5])
@pytest.mark.parametrize("peak_frac", [0.0, 0.3, 0.5])
def test_triangle_closed_form_equals_recurrence(zeta, peak_frac):
    amp, duration, dt = 3.0, 0.4, 0.01          # m/s^2, s, s: corners on samples
    periods = np.array([0.003, 0.01, 0.017, 0.05, 0.13, 0.4, 1.1, 3.0])
    closed = sdof.pulse_spectrum(pulse.define("triangular", amp=amp, duration=duration,
                                              peak_frac=peak_frac), periods, zeta)
    rec = _triangle_record(amp, duration, peak_frac, dt, pad=2.5 * periods.max() + 1.0)
    exact = sdof.spectrum(rec, dt, periods, zeta)
    np.testing.assert_allclose(exact.sd, closed.sd, rtol=1e-9, atol=1e-14)
    np.testing.assert_allclose(exact.sv, closed.sv, rtol=1e-9, atol=1e-14)
    np.testing.assert_allclose(exact.sa * G, closed.sa, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(exact.psa * G, closed.psa, rtol=1e-9, atol=1e-12)


def test_exponential_beta_zero_is_the_sampled_triangle():
    amp, td, dt = 2.0, 0.5, 0.005
    periods = np.array([0.004, 0.02, 0.1, 0.5, 2.0])
    closed = sdof.pulse_spectrum(pulse.define("exponential", amp=amp, td=td, beta=0.0,
                                              full=True), periods, 0.05)
    t = np.arange(int(round((2 * td + 6.0) / dt)) + 1) * dt
    rec = pulse.exponential(t, amp, td, 0.0, full=True).a / G
    exact = sdof.spectrum(rec, dt, periods, 0.05)
    np.testing.assert_allclose(exact.sd, closed.sd, rtol=1e-9)
    np.testing.assert_allclose(exact.sa * G, closed.sa, rtol=1e-9)


def test_where_eqsig_is_wrong_the_closed_form_decides():
    """T < 6 dt: eqsig reports PSA = PGA; the closed form of the sampled triangle and
    the exact recurrence agree with each other and not with eqsig."""
    eqsig_sdof = pytest.importorskip("eqsig.sdof", reason="eqsig (PyPI) is not installed")
    amp, duration, dt = 3.0, 0.2, 0.01
    periods = np.array([0.02, 0.03, 0.05])
    closed = sdof.pulse_spectrum(pulse.define("triangular", amp=amp, duration=duration),
                                 periods, 0.05)
    rec = _triangle_record(amp, duration, 0.5, dt, pad=1.0)
    exact = sdof.spectrum(rec, dt, periods, 0.05)
    np.testing.assert_allclose(exact.psa * G, closed.psa, rtol=1e-9)
    _, _, psa_eqsig = eqsig_sdof.pseudo_response_spectra(rec * G, dt, periods, 0.05)
    np.testing.assert_allclose(psa_eqsig, amp, rtol=1e-12)          # PGA, clipped
    assert np.all(np.abs(closed.psa / amp - 1) > 0.01)


@pytest.mark.parametrize("kind, params, t_end", [
    ("half_sine", dict(amp=2.0, duration=0.6), 0.6),
    ("sine_cycle", dict(amp=2.0, period=0.5), 0.5),
    ("exponential", dict(amp=2.0, td=0.4, beta=-3.0, full=True), 0.8),
    ("exponential", dict(amp=2.0, td=0.4, beta=5.0, full=False), 0.4),
    ("ricker", dict(amp=2.0, freq=2.0, t0=0.75), 1.5),
    ("mavroeidis_papageorgiou", dict(vamp=0.5, freq=1.5, gamma=2.0, nu_deg=30.0, t0=1.0), 2.0),
])
def test_smooth_pulses_second_order(kind, params, t_end):
    periods = np.array([0.1, 0.35, 1.0, 2.5])
    zeta = 0.05
    closed = sdof.pulse_spectrum(pulse.define(kind, **params), periods, zeta)
    errors = []
    for dt in (0.004, 0.002):
        t = np.arange(int(round((t_end + 6.0) / dt)) + 1) * dt
        rec = pulse.evaluate(kind, t, **params).a / G
        exact = sdof.spectrum(rec, dt, periods, zeta)
        errors.append(np.max(np.abs(exact.sd / closed.sd - 1)))
    assert errors[1] < 1e-3
    # second order: halving dt divides the error by about 4
    assert errors[0] / errors[1] > 2.5
