"""Intensity measures of records (seispulse.records.intensity, spectral_acceleration):
closed forms of piecewise-linear records, quadrature on a fine resampling of the linear
interpolant, eqsig on the pyslammer sample records (its rectangle/trapezoid rules
reproduced exactly), Tm against numpy.fft, spectral acceleration against
seispulse.sdof, argument errors."""
from pathlib import Path

import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid

from seispulse import records, sdof
from seispulse.errors import InvalidInputError

G = 9.80665


def _exact_fine(accel, dt, k=50):
    """The linear interpolant on a grid k times finer (the samples included)."""
    n = len(accel)
    t = np.arange(n) * dt
    tf = np.linspace(0.0, (n - 1) * dt, (n - 1) * k + 1)
    return tf, np.interp(tf, t, accel)


def _tm_numpy(accel, dt):
    """Tm of [RAB98] with numpy.fft: zero padding to the next power of two
    >= max(n, 1/(0.05 dt)), 0.25 <= f <= 20 Hz."""
    n = len(accel)
    npad = 1
    while npad < max(n, int(np.ceil(1.0 / (0.05 * dt)))):
        npad *= 2
    c2 = np.abs(np.fft.rfft(accel, npad)) ** 2
    f = np.fft.rfftfreq(npad, dt)
    m = (f >= 0.25) & (f <= 20.0)
    return float(np.sum(c2[m] / f[m]) / np.sum(c2[m]))


def _random_record(n=400, dt=0.02, seed=7):
    rng = np.random.default_rng(seed)
    env = np.sin(np.pi * np.arange(n) / (n - 1)) ** 2
    return 0.3 * env * rng.standard_normal(n), dt


def test_constant_record():
    c, dt, n = 0.2, 0.01, 501
    T = (n - 1) * dt
    im = records.intensity(np.full(n, -c), dt)
    assert im.pga == c
    np.testing.assert_allclose(im.arias, np.pi * G / 2 * c * c * T, rtol=1e-13)
    np.testing.assert_allclose(im.cav, G * c * T, rtol=1e-13)
    np.testing.assert_allclose([im.pgv, im.pgd], [G * c * T, G * c * T * T / 2], rtol=1e-13)
    np.testing.assert_allclose([im.t5, im.t75, im.t95], [0.05 * T, 0.75 * T, 0.95 * T],
                               rtol=1e-13)
    np.testing.assert_allclose([im.d5_75, im.d5_95], [0.7 * T, 0.9 * T], rtol=1e-13)


def test_triangle_record():
    amp, dt = 0.5, 0.2
    im = records.intensity([0.0, amp, 0.0], dt)
    np.testing.assert_allclose(im.arias, np.pi * G / 2 * amp ** 2 * 2 * dt / 3, rtol=1e-14)
    np.testing.assert_allclose(im.cav, G * amp * dt, rtol=1e-14)
    np.testing.assert_allclose(
        [im.t5, im.t75, im.t95],
        [0.1 ** (1 / 3) * dt, (2 - 0.5 ** (1 / 3)) * dt, (2 - 0.1 ** (1 / 3)) * dt],
        rtol=1e-14)


def test_sine_record_closed_forms():
    """Samples A sin(theta i) over whole cycles (m steps, M steps a half cycle): the
    Arias sum of (a_i^2 + a_i a_j + a_j^2) dt/3 is m (1 + cos(theta)/2) A^2 dt/3; the CAV
    of a half cycle is g A dt cot(pi/(2M))."""
    A, dt, M, cycles = 0.4, 0.005, 25, 4
    m = 2 * M * cycles
    theta = np.pi / M
    accel = A * np.sin(theta * np.arange(m + 1))
    im = records.intensity(accel, dt)
    np.testing.assert_allclose(
        im.arias, np.pi * G / 2 * A * A * dt / 3 * m * (1 + np.cos(theta) / 2), rtol=1e-13)
    np.testing.assert_allclose(im.cav, 2 * cycles * G * A * dt / np.tan(np.pi / (2 * M)),
                               rtol=1e-13)
    # the continuous sine's Arias pi g A^2 T / 4, approached at O(dt^2)
    T = m * dt
    np.testing.assert_allclose(im.arias, np.pi * G * A * A * T / 4, rtol=theta ** 2)


def test_quadrature_on_fine_resampling():
    """Every measure against quadrature of the linear interpolant sampled finely: Simpson
    (exact for the quadratic a^2 of each sub-step) for Arias, trapezoids (errors
    O(h^2)) for CAV, velocity, displacement and the Husid curve."""
    accel, dt = _random_record()
    im = records.intensity(accel, dt)
    tf, af = _exact_fine(accel, dt, k=50)
    h = tf[1] - tf[0]
    # a^2 is quadratic on each sub-step: Simpson on each sub-step with its midpoint
    tm_, am = _exact_fine(accel, dt, k=100)
    a2 = am ** 2
    arias = np.pi * G / 2 * np.sum(h / 6 * (a2[:-2:2] + 4 * a2[1:-1:2] + a2[2::2]))
    np.testing.assert_allclose(im.arias, arias, rtol=1e-12)
    # |a| is linear between the samples and its zeros: a trapezoid 2000 times finer than
    # the record (its error, O(h^2) at each zero, below 1e-7 here)
    tc, ac = _exact_fine(accel, dt, k=2000)
    np.testing.assert_allclose(im.cav, G * np.trapezoid(np.abs(ac), tc), rtol=1e-7)
    # velocity (trapezoid exact for the linear interpolant) and displacement
    v = G * cumulative_trapezoid(af, tf, initial=0.0)
    d = cumulative_trapezoid(v, tf, initial=0.0)
    np.testing.assert_allclose(im.pgv, np.max(np.abs(v)), rtol=1e-6)
    assert im.pgv >= np.max(np.abs(v)) * (1 - 1e-14)
    np.testing.assert_allclose(im.pgd, np.max(np.abs(d)), rtol=1e-12)
    # Husid times: the crossings of the fine cumulative curve, to 1 % of a step
    cf = cumulative_trapezoid(af ** 2, tf, initial=0.0)
    cf /= cf[-1]
    for p, t in ((0.05, im.t5), (0.75, im.t75), (0.95, im.t95)):
        assert abs(t - np.interp(p, cf, tf)) < 0.01 * dt
    assert im.d5_75 == pytest.approx(im.t75 - im.t5, abs=1e-15)
    assert im.d5_95 == pytest.approx(im.t95 - im.t5, abs=1e-15)
    # the time origin is the first sample: a record shifted by leading zeros
    im2 = records.intensity(np.concatenate([np.zeros(10), accel]), dt)
    np.testing.assert_allclose([im2.t5, im2.t95], [im.t5 + 10 * dt, im.t95 + 10 * dt],
                               rtol=1e-13)
    np.testing.assert_allclose(im2.d5_95, im.d5_95, rtol=1e-11)


def test_tm_numpy_and_sine():
    accel, dt = _random_record()
    np.testing.assert_allclose(records.intensity(accel, dt).tm, _tm_numpy(accel, dt),
                               rtol=1e-12)
    # a sine filling the padded window at a bin frequency: one spectral line
    dt, npad, k = 0.01, 2048, 73
    t = np.arange(npad) * dt
    f = k / (npad * dt)
    im = records.intensity(np.sin(2 * np.pi * f * t), dt)
    np.testing.assert_allclose(im.tm, 1 / f, rtol=1e-12)
    # a 60-s sine of f: leakage biases Tm by O(1/(f T)), below 0.5 % here
    for f in (0.5, 1.0, 3.0, 7.0):
        t = np.arange(0.0, 60.0 + dt / 2, dt)
        assert records.intensity(np.sin(2 * np.pi * f * t), dt).tm * f == pytest.approx(
            1.0, rel=5e-3)


def test_record_method_and_spectral_acceleration():
    accel, dt = _random_record()
    rec = records.from_array(accel, dt)
    assert rec.intensity() == records.intensity(rec)
    assert rec.intensity(g=9.81).arias == pytest.approx(
        records.intensity(accel, dt).arias * 9.81 / G, rel=1e-14)
    assert records.spectral_acceleration(rec, 0.0) == rec.pga
    periods = [0.0, 0.1, 0.5, 1.0, 2.0]
    sa = records.spectral_acceleration(rec, periods, damping=0.05)
    spec = sdof.spectrum(rec, periods=periods, damping=0.05)
    np.testing.assert_allclose(sa, spec.psa, rtol=1e-15)
    assert records.spectral_acceleration(accel, 1.0, dt=dt, damping=0.02) == pytest.approx(
        float(sdof.spectrum(accel, dt, periods=[1.0], damping=0.02).psa[0]), rel=1e-15)


def test_records_without_energy():
    im = records.intensity(np.zeros(100), 0.01)
    assert (im.pga, im.pgv, im.pgd, im.arias, im.cav) == (0.0, 0.0, 0.0, 0.0, 0.0)
    assert all(np.isnan([im.d5_75, im.d5_95, im.t5, im.t75, im.t95, im.tm]))
    one = records.intensity([0.1], 0.01)
    assert one.arias == 0.0 and np.isnan(one.d5_95) and np.isnan(one.tm)


def test_pgv_in_the_units_of_the_empirical_models():
    """Intensity.pgv is m/s; pgv_cm_s is the same peak in cm/s, the unit the empirical
    models take: fed to saygili_rathje_2008_pgv it gives the model at PGV (cm/s) written
    out ([SR08] PGA-PGV, doc/empirical.md (E.9))."""
    from seispulse import empirical
    dt = 0.01
    t = np.arange(400) * dt
    im = records.intensity(0.3 * np.sin(2 * np.pi * t) * np.exp(-t), dt)
    assert isinstance(im, tuple) and len(im) == 11 and im._fields[-1] == "tm"
    assert im.pgv_cm_s == 100.0 * im.pgv and 10.0 < im.pgv_cm_s < 100.0
    ky, r = 0.1, 0.1 / im.pga
    pgv = 100.0 * im.pgv
    ln_d = (-1.56 - 4.58 * r - 20.84 * r**2 + 44.75 * r**3 - 30.50 * r**4
            - 0.64 * math.log(im.pga) + 1.55 * math.log(pgv))
    d = empirical.saygili_rathje_2008_pgv(ky, im.pga, im.pgv_cm_s)
    assert d.disp_cm == pytest.approx(math.exp(ln_d), rel=1e-13)


@pytest.mark.parametrize("args, kwargs, name", [
    (([], 0.01), {}, "accel"),
    (([0.1, 0.2], 0.0), {}, "dt"),
    (([0.1, 0.2], -0.01), {}, "dt"),
    (([0.1, np.nan], 0.01), {}, "accel[1]"),
    (([0.1, np.inf], 0.01), {}, "accel[1]"),
    (([0.1, 0.2], 0.01), {"g": 0.0}, "g"),
    (([0.1, 0.2],), {}, "dt"),
    (([[0.1, 0.2]], 0.01), {}, "accel"),
])
def test_intensity_errors(args, kwargs, name):
    with pytest.raises(InvalidInputError, match=r"^" + name.replace("[", r"\[")):
        records.intensity(*args, **kwargs)


def test_spectral_acceleration_errors():
    rec = records.from_array([0.1, -0.2, 0.05], 0.01)
    with pytest.raises(InvalidInputError, match=r"^period = -1"):
        records.spectral_acceleration(rec, -1.0)
    with pytest.raises(InvalidInputError, match=r"^period\[1\] = NaN"):
        records.spectral_acceleration(rec, [1.0, np.nan])
    with pytest.raises(InvalidInputError, match=r"^damping"):
        records.spectral_acceleration(rec, 1.0, damping=1.0)
    with pytest.raises(InvalidInputError, match=r"^dt"):
        records.spectral_acceleration([0.1, 0.2], 1.0)
    with pytest.raises(InvalidInputError, match=r"^g"):
        records.spectral_acceleration(rec, 1.0, g=-9.8)


def _pyslammer_records():
    pyslammer = pytest.importorskip(
        "pyslammer", reason="pyslammer (pip install pyslammer) provides the 18 sample records")
    files = sorted((Path(pyslammer.__file__).parent / "sample_ground_motions").glob("*.csv"))
    if not files:
        pytest.skip("pyslammer ships no sample records")
    return [records.read(f) for f in files]


def test_eqsig_on_pyslammer_records():
    """eqsig integrates a^2 and |a| by the trapezoidal rule on the samples (g = 9.81 in its
    Arias constant) and takes the Husid times at samples (start: the first sample above
    5 %, end: the last below 95 %) of that trapezoidal curve. Both are reproduced here
    exactly: Arias differs from ours by pi/(2g) sum dt (Delta a)^2/6, the CAV by
    sum dt |a_i a_j| / (|a_i| + |a_j|) over the steps where a changes sign; the Husid
    times by the sample rule. eqsig has no mean period."""
    eqsig = pytest.importorskip("eqsig", reason="eqsig (PyPI) is not installed")
    from eqsig import im as eim
    g = 9.81
    for rec in _pyslammer_records():
        a, dt = rec.accel, rec.dt
        sig = eqsig.AccSignal(a * g, dt)
        ours = rec.intensity(g=g)
        da = np.diff(a) * g
        arias_e = eim.calc_arias_intensity(sig)[-1]
        np.testing.assert_allclose(ours.arias,
                                   arias_e - np.pi / (2 * g) * np.sum(dt * da ** 2 / 6),
                                   rtol=1e-12, err_msg=rec.name)
        x, y = a[:-1], a[1:]
        s = x * y < 0
        cav_e = eim.calc_cav(sig)[-1]
        np.testing.assert_allclose(
            ours.cav, cav_e - g * dt * np.sum(np.abs(x[s] * y[s]) / (np.abs(x[s]) + np.abs(y[s]))),
            rtol=1e-12, err_msg=rec.name)
        # eqsig's Husid times: its sample rule on the trapezoidal curve
        c = cumulative_trapezoid(a ** 2, dx=dt, initial=0.0)
        c /= c[-1]
        t5, t95 = eim.calc_sig_dur(sig, 0.05, 0.95, se=True)
        assert t5 == np.argmax(c > 0.05) * dt
        assert t95 == np.nonzero(c < 0.95)[0][-1] * dt
        # ours: the crossings of the exact curve (fine resampling), to 1 % of a step
        tf, af = _exact_fine(a, dt, k=50)
        cf = cumulative_trapezoid(af ** 2, tf, initial=0.0)
        cf /= cf[-1]
        for p, t in ((0.05, ours.t5), (0.75, ours.t75), (0.95, ours.t95)):
            assert abs(t - np.interp(p, cf, tf)) < 0.01 * dt, (rec.name, p)
        # eqsig's velocity is the exact one at the samples: our PGV is the same or
        # (a peak between samples) slightly larger
        assert sig.pgv * (1 - 1e-12) <= ours.pgv <= sig.pgv * 1.005, rec.name
        np.testing.assert_allclose(ours.tm, _tm_numpy(a, dt), rtol=1e-11, err_msg=rec.name)
    assert not hasattr(eim, "calc_mean_period")


# ---------------------------------------------------------------- the batch driver

def _read_csv(path):
    import csv
    with open(path, newline="") as f:
        header = next(csv.reader(f))
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    return header, rows


def test_driver_intensity_table(driver, source_root, tmp_path):
    """input/newmark_intensity.nml: the intensity table equals records.intensity and
    records.spectral_acceleration of the scaled records, bit for bit."""
    import subprocess
    example = source_root / "input" / "newmark_intensity.nml"
    proc = subprocess.run([driver, str(example)], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "out/newmark_intensity.csv" in proc.stdout
    assert "INTENSITY=T" in proc.stdout.upper().replace(" ", "")
    header, rows = _read_csv(tmp_path / "out" / "newmark_intensity.csv")
    assert header == ["record (-)", "pga (g)", "pgv (m/s)", "pgd (m)", "arias (m/s)",
                      "cav (m/s)", "d5_75 (s)", "d5_95 (s)", "tm (s)", "sa_T=0.2 (g)",
                      "sa_T=0.5 (g)", "sa_T=1.0 (g)", "status (-)"]
    assert [r[0] for r in rows] == ["quake_a", "quake_b"]
    for row, name in zip(rows, ("quake_a.AT2", "quake_b.csv")):
        rec = records.read(source_root / "input" / "records" / name).scaled_to_pga(0.3)
        im = rec.intensity()
        sa = records.spectral_acceleration(rec, [0.2, 0.5, 1.0])
        expect = [im.pga, im.pgv, im.pgd, im.arias, im.cav, im.d5_75, im.d5_95, im.tm,
                  *sa]
        np.testing.assert_array_equal(row[1:-1], expect)
        assert row[-1] == "ok"
    # without the key: no intensity table
    text = example.read_text().replace("intensity = .true.", "intensity = .false.")
    text = "\n".join(ln for ln in text.splitlines() if "sa_periods" not in ln) + "\n"
    (tmp_path / "records").mkdir()
    for f in (source_root / "input" / "records").iterdir():
        (tmp_path / "records" / f.name).write_bytes(f.read_bytes())
    (tmp_path / "off.nml").write_text(text.replace("out/newmark_intensity", "off/x"))
    proc = subprocess.run([driver, "off.nml"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert sorted(p.name for p in (tmp_path / "off").iterdir()) == ["x_newmark.csv",
                                                                    "x_newmark.txt"]


@pytest.mark.parametrize("group, message", [
    ("ky = 0.1, sa_periods = 0.5", "sa_periods: only with intensity = .true."),
    ("ky = 0.1, intensity = .true., sa_periods = 0.5, -1",
     "sa_periods(2) = -1.0: the period must be finite and >= 0 (s)"),
    ("ky = 0.1, intensity = .true., sa_periods = 0.5, nan, 1",
     "sa_periods(2): missing or NaN"),
])
def test_driver_intensity_input_errors(driver, source_root, tmp_path, group, message):
    import subprocess
    rec = source_root / "input" / "records" / "quake_a.AT2"
    (tmp_path / "e.nml").write_text(f"&run analysis = 'newmark', output = 'o' /\n"
                                    f"&records files = '{rec}' /\n&newmark {group} /\n")
    proc = subprocess.run([driver, "e.nml"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=60)
    assert proc.returncode == 2
    assert f"e.nml:3: &newmark: {message}" in proc.stderr
    assert not list(tmp_path.glob("o_*"))


def test_readme_example(source_root, monkeypatch, capsys):
    """The example of the README's "Intensity measures" section prints what it says."""
    text = (source_root / "README.md").read_text(encoding="utf-8")
    section = text[text.index("\n## Intensity measures\n"):]
    code = section[section.index("```python\n") + 10:section.index("\n```\n")]
    shown = section[section.index("prints (run from the source tree)"):]
    shown = shown[shown.index("```\n") + 4:]
    shown = shown[:shown.index("```")]
    monkeypatch.chdir(source_root)
    exec(compile(code, "README.md (Intensity measures)", "exec"), {})
    assert capsys.readouterr().out == shown
