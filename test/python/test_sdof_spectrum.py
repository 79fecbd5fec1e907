"""seispulse.sdof on records: response histories and spectra.

* eqsig's exact Nigam-Jennings recurrence on the 18 records of pyslammer, where eqsig
  is exact (T >= 6 dt, maxima at the samples): agreement to 1e-6 (eqsig takes
  omega = 6.2831853/T, 1e-8 off);
* where eqsig is wrong (it reports PSA = PGA for T < 6 dt) and pyrotd is wrong (FFT
  without zero padding at long periods), a closed-form answer shows which is right;
* response() against scipy's solve_ivp at tight tolerance;
* threads, Record input, shapes, bad input.
The optional peers (eqsig, pyrotd, pyslammer) are skipped with a reason when absent;
`make test` installs eqsig and pyslammer.
"""

from pathlib import Path

import numpy as np
import pytest

from seispulse import InvalidInputError, records, sdof

G = 9.80665


@pytest.fixture(scope="module")
def pyslammer_records():
    pyslammer = pytest.importorskip(
        "pyslammer", reason="pyslammer (PyPI) is not installed: it ships the 18 records")
    folder = Path(pyslammer.__file__).parent / "sample_ground_motions"
    recs = [records.read(p) for p in sorted(folder.glob("*.csv"))]
    assert len(recs) == 18
    return recs


def _eqsig_spectra(accel_g, dt, periods, zeta):
    eqsig_sdof = pytest.importorskip("eqsig.sdof", reason="eqsig (PyPI) is not installed")
    u, v, a = eqsig_sdof.nigam_and_jennings_response(np.asarray(accel_g) * G, dt, periods, zeta)
    return np.abs(u).max(axis=1), np.abs(v).max(axis=1), np.abs(a).max(axis=1) / G


@pytest.mark.parametrize("zeta", [0.02, 0.05])
def test_eqsig_on_18_records(pyslammer_records, zeta):
    """Maxima at the samples: seispulse = eqsig to 1e-6 where eqsig is exact (T >= 6 dt)."""
    worst = 0.0
    for rec in pyslammer_records:
        periods = np.geomspace(6 * rec.dt, 10.0, 25)
        sd_e, sv_e, sa_e = _eqsig_spectra(rec.accel, rec.dt, periods, zeta)
        ours = sdof.spectrum(rec, periods=periods, damping=zeta, peaks="samples")
        for mine, theirs in ((ours.sd, sd_e), (ours.sv, sv_e), (ours.sa, sa_e)):
            rel = np.max(np.abs(mine / theirs - 1))
            worst = max(worst, rel)
            assert rel < 1e-6, rec.name
        np.testing.assert_allclose(ours.psa, (2 * np.pi / periods) ** 2 * ours.sd / G,
                                   rtol=1e-15)
    assert worst < 1e-6


def test_exact_maxima_above_samples_on_18_records(pyslammer_records):
    """True maxima are never below the sample maxima, and never below those of the
    record linearly upsampled 16 times (the same problem, sampled finer); SD stays
    within 1 - cos(pi/32) of the upsampled one for T >= 2 dt."""
    for i, rec in enumerate(pyslammer_records):
        periods = np.geomspace(0.5 * rec.dt, 10.0, 30)
        ex = sdof.spectrum(rec, periods=periods)
        sm = sdof.spectrum(rec, periods=periods, peaks="samples")
        for a, b in ((ex.sd, sm.sd), (ex.sv, sm.sv), (ex.sa, sm.sa)):
            assert np.all(a >= b * (1 - 1e-12)), rec.name
        if i % 6:
            continue
        k = 16
        fine = np.interp(np.arange((rec.npts - 1) * k + 1) / k, np.arange(rec.npts), rec.accel)
        up = sdof.spectrum(fine, rec.dt / k, periods, peaks="samples")
        for a, b in ((ex.sd, up.sd), (ex.sv, up.sv), (ex.sa, up.sa)):
            assert np.all(a >= b * (1 - 1e-12)), rec.name
        dense = periods >= 2 * rec.dt
        assert np.all(ex.sd[dense] <= up.sd[dense] * (1 + (1 - np.cos(np.pi / 32)))), rec.name


def test_step_record_closed_form_where_eqsig_clips():
    """A constant acceleration a0 from t = 0: z = -(a0/w^2)(1 - cos w t) (undamped), so
    SD = 2 a0/w^2 and PSA = 2 a0 at every period whose half lies within the record.
    eqsig reports PSA = PGA = a0 for T < 6 dt; the samples miss the peak between them."""
    dt, a0 = 0.02, 0.25
    accel = np.full(51, a0)
    periods = np.array([0.013, 0.03, 0.05, 0.07, 0.11, 0.5])
    ex = sdof.spectrum(accel, dt, periods, damping=0.0)
    np.testing.assert_allclose(ex.psa, 2 * a0, rtol=1e-12)
    np.testing.assert_allclose(ex.sd, 2 * a0 * G / (2 * np.pi / periods) ** 2, rtol=1e-12)
    # undamped, the peak repeats every period: at T/2 modulo T
    np.testing.assert_allclose(np.mod(ex.t_sd, periods), periods / 2, rtol=1e-8)
    eqsig_sdof = pytest.importorskip("eqsig.sdof", reason="eqsig (PyPI) is not installed")
    _, _, psa_eqsig = eqsig_sdof.pseudo_response_spectra(accel * G, dt, periods, 0.0)
    clipped = periods < 6 * dt
    np.testing.assert_allclose(psa_eqsig[clipped] / G, a0, rtol=1e-12)  # eqsig: PGA, off by 2x
    assert np.all(np.abs(psa_eqsig[clipped] / G - 2 * a0) > 0.4 * a0)


def _step_then_rest_psa(a0, t1, t_end, period, zeta):
    """omega^2 max|z| (g) for a_g = a0 (g) on [0, t1), then rest, up to t_end: the step
    response in closed form, then free vibration from its state at t1, on a dense grid."""
    w = 2 * np.pi / period
    wd = w * np.sqrt(1 - zeta ** 2)
    t = np.linspace(0.0, t_end, 400001)
    tf = np.minimum(t, t1)
    e = np.exp(-zeta * w * tf)
    z = -(a0 * G / w ** 2) * (1 - e * (np.cos(wd * tf) + zeta * w / wd * np.sin(wd * tf)))
    v = -(a0 * G / wd) * e * np.sin(wd * tf)
    tau = t - tf
    free = np.exp(-zeta * w * tau) * (z * np.cos(wd * tau)
                                      + (v + zeta * w * z) / wd * np.sin(wd * tau))
    return w ** 2 * np.abs(free).max() / G


def test_pyrotd_long_periods_against_closed_form():
    """A step a0 for 10 s, then 30 s of rest: seispulse equals the closed form; pyrotd's
    FFT transfer function without zero padding wraps the free vibration around the
    record and is off at long periods."""
    dt, a0, zeta = 0.01, 0.1, 0.05
    accel = np.zeros(4001)
    accel[:1001] = a0
    periods = np.array([2.0, 5.0, 10.0])
    ours = sdof.spectrum(accel, dt, periods, damping=zeta)
    # the record is linear between samples: the step ends with a ramp over (10, 10.01) s,
    # which the closed form takes as a step ending at its midpoint: O(dt/T)^2 at most
    closed = np.array([_step_then_rest_psa(a0, 10.005, 40.0, T, zeta) for T in periods])
    np.testing.assert_allclose(ours.psa, closed, rtol=1e-7)
    pyrotd = pytest.importorskip("pyrotd", reason="pyrotd (PyPI) is not installed")
    theirs = pyrotd.calc_spec_accels(dt, accel, 1 / periods, zeta).spec_accel
    assert abs(theirs[0] / closed[0] - 1) < 0.02
    assert np.max(np.abs(theirs / closed - 1)) > 0.02


def test_response_against_solve_ivp():
    integrate = pytest.importorskip("scipy.integrate")
    dt = 0.01
    t = np.arange(301) * dt
    accel = 0.3 * np.sin(2 * np.pi * 1.7 * t) * np.exp(-t) + 0.1 * np.cos(2 * np.pi * 5 * t)
    period, zeta = 0.4, 0.07
    w = 2 * np.pi / period
    r = sdof.response(accel, dt, period, zeta)

    def rhs(time, y):
        ag = np.interp(time, t, accel) * G
        return [y[1], -ag - 2 * zeta * w * y[1] - w * w * y[0]]

    sol = integrate.solve_ivp(rhs, (0, t[-1]), [0.0, 0.0], t_eval=t, rtol=1e-12, atol=1e-14,
                              max_step=dt / 4)
    np.testing.assert_allclose(r.disp, sol.y[0], atol=1e-9 * np.abs(sol.y[0]).max())
    np.testing.assert_allclose(r.vel, sol.y[1], atol=1e-9 * np.abs(sol.y[1]).max())
    np.testing.assert_allclose(r.acc, -(2 * zeta * w * r.vel + w * w * r.disp) / G, rtol=1e-12,
                               atol=1e-15)
    np.testing.assert_allclose(r.time, t)
    ground = sdof.response(accel, dt, 0.0)
    np.testing.assert_array_equal(ground.acc, accel)
    assert not ground.disp.any() and not ground.vel.any()


def test_spectrum_shapes_threads_and_record():
    dt = 0.01
    t = np.arange(801) * dt
    accel = 0.2 * np.sin(2 * np.pi * 2.1 * t) * np.exp(-0.5 * t)
    rec = records.from_array(accel, dt, name="synthetic")
    periods = np.geomspace(0.02, 4, 37)
    s1 = sdof.spectrum(rec, periods=periods, damping=[0.0, 0.05, 0.1], threads=1)
    s2 = sdof.spectrum(accel, dt, periods, damping=[0.0, 0.05, 0.1], threads=2)
    for a, b in zip(s1[2:], s2[2:]):
        assert a.shape == (3, 37)
        np.testing.assert_array_equal(a, b)  # bitwise, whatever the thread count
    one = sdof.spectrum(accel, dt, periods, damping=0.05)
    assert one.sd.shape == (37,)
    np.testing.assert_array_equal(one.sd, s1.sd[1])
    single = sdof.spectrum(accel, dt, 1.0)
    assert isinstance(single.psa, float) and isinstance(single.periods, float)
    assert sdof.default_threads() >= 1


def test_envelope_and_shape():
    periods = np.array([0.05, 0.1, 0.2, 0.4, 1.0])
    spectra = np.array([[1.0, 1.5, 2.2, 2.0, 1.0], [1.2, 1.3, 1.8, 2.6, 1.1]])
    np.testing.assert_array_equal(sdof.envelope(periods, spectra), [1.2, 1.5, 2.2, 2.6, 1.1])
    np.testing.assert_array_equal(sdof.envelope(periods, spectra, plateau_below=0.2),
                                  [2.6, 2.6, 2.2, 2.6, 1.1])
    shape = sdof.normalized_shape(periods, spectra[1], 0.4)
    np.testing.assert_allclose(shape.shape, spectra[1] / 0.4)
    assert shape.t_peak == 0.4 and shape.peak == pytest.approx(6.5)


@pytest.mark.parametrize("kwargs, match", [
    (dict(periods=[-0.1]), r"periods\[0\] = -0.1"),
    (dict(periods=[0.1, np.nan]), r"periods\[1\]"),
    (dict(periods=[0.1], damping=1.0), r"damping\[0\] = 1.0.*\[0, 1\)"),
    (dict(periods=[0.1], damping=[0.05, -0.1]), r"damping\[1\]"),
    (dict(periods=[0.1], dt=0.0), r"dt"),
    (dict(periods=[0.1], dt=-0.01), r"dt"),
    (dict(periods=[]), r"periods"),
    (dict(periods=[0.1], peaks="max"), r"peaks"),
    (dict(periods=[0.1], threads=0), r"threads"),
    (dict(periods=[0.1], g=-9.8), r"g"),
])
def test_spectrum_bad_input(kwargs, match):
    args = dict(accel=[0.0, 0.1, -0.1, 0.05], dt=0.01)
    args.update(kwargs)
    with pytest.raises(InvalidInputError, match=match):
        sdof.spectrum(**args)


def test_response_bad_input():
    with pytest.raises(InvalidInputError, match=r"accel\[2\] = NaN"):
        sdof.response([0.0, 0.1, np.nan], 0.01, 1.0)
    with pytest.raises(InvalidInputError, match="empty"):
        sdof.response([], 0.01, 1.0)
    with pytest.raises(InvalidInputError, match="period"):
        sdof.response([0.0, 0.1], 0.01, -1.0)
    with pytest.raises(InvalidInputError, match=r"period = .*a positive period must be >="):
        sdof.response([0.0, 0.1], 0.01, 1e-308)
    with pytest.raises(InvalidInputError, match="damping"):
        sdof.response([0.0, 0.1], 0.01, 1.0, damping=1.5)
    with pytest.raises(InvalidInputError, match="period"):
        sdof.response([0.0, 0.1], 0.01)
    # periods in any order: the plateau goes by period, not by position
    np.testing.assert_array_equal(sdof.envelope([0.4, 0.1, 0.2], [[1.0, 2.0, 3.0]],
                                                plateau_below=0.3), [1.0, 3.0, 3.0])
    with pytest.raises(InvalidInputError, match="pga"):
        sdof.normalized_shape([0.1], [1.0], 0.0)
