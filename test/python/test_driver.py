"""Batch driver: the example input runs, bad input gives one line naming file, line,
group, key and problem, exit status 2, and no output file."""
import subprocess
from pathlib import Path

import numpy as np
import pytest

from seispulse import pulse as p


def run(driver, cwd, text, name="case.nml"):
    (Path(cwd) / name).write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True, timeout=60)


def read_csv(path):
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def test_example_input_runs(driver, source_root, tmp_path):
    proc = subprocess.run([driver, str(source_root / "input" / "example.nml")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert "out/example_pulse.txt" in proc.stdout and "out/example_pulse.csv" in proc.stdout
    assert "&PULSE" in proc.stdout.upper(), "effective input is echoed"
    csv = read_csv(tmp_path / "out" / "example_pulse.csv")
    txt = np.loadtxt(tmp_path / "out" / "example_pulse.txt", comments="#")
    # the text table: the CSV's numbers to 6 significant digits (C's %.6g)
    np.testing.assert_array_equal(txt, np.vectorize(lambda x: float("%.6g" % x))(csv))
    assert csv.shape == (301, 5)
    # the driver's table is the Python API's pulse (same library, so this checks the
    # plumbing: grid, units, amplitude in g, column order)
    ref = p.exponential(csv[:, 0], 0.5, 0.6, -3.141592653589793, full=True, amp_unit="g")
    np.testing.assert_allclose(csv[:, 0], np.linspace(0.0, 1.5, 301), rtol=0, atol=1e-15)
    np.testing.assert_allclose(csv[:, 1], ref.a, rtol=1e-15, atol=1e-15)
    np.testing.assert_allclose(csv[:, 2], ref.a / p.STANDARD_GRAVITY, rtol=1e-15, atol=1e-16)
    np.testing.assert_allclose(csv[:, 3], ref.v, rtol=1e-15, atol=1e-16)
    np.testing.assert_allclose(csv[:, 4], ref.d, rtol=1e-15, atol=1e-16)
    header = (tmp_path / "out" / "example_pulse.csv").read_text().splitlines()[0]
    assert header == "t (s),a (m/s2),a_in_g (g),v (m/s),d (m)"


@pytest.mark.parametrize("kind, extra", [
    ("half_sine", "duration = 0.5"), ("sine_cycle", "duration = 0.5"),
    ("cosine_cycle", "duration = 0.5"), ("rectangular", "duration = 0.5"),
    ("triangular", "duration = 0.5, peak_frac = 0.2"), ("ricker", "freq = 2.0"),
    ("mavroeidis_papageorgiou", "vamp = 0.6, freq = 1.0, gamma = 2.5, nu_deg = 45"),
])
def test_every_kind_runs(driver, tmp_path, kind, extra):
    proc = run(driver, tmp_path, f"&run analysis='pulse', output='k' /\n"
                                 f"&pulse kind='{kind}', amp=2.0, {extra} /\n")
    assert proc.returncode == 0, proc.stderr
    table = read_csv(tmp_path / "k_pulse.csv")
    assert table.shape == (1001, 5) and np.all(np.isfinite(table))


def test_defaults_and_dt_grid(driver, tmp_path):
    proc = run(driver, tmp_path, "&run analysis='pulse', output='g' /\n"
                                 "&pulse duration=0.8 /\n&time t_end=1.0, dt=0.1 /\n")
    assert proc.returncode == 0, proc.stderr
    table = read_csv(tmp_path / "g_pulse.csv")
    np.testing.assert_allclose(table[:, 0], np.arange(11) * 0.1, atol=1e-15)
    ref = p.exponential(table[:, 0], 1.0, 0.8, 0.0)    # default: triangle, amp 1 m/s2
    np.testing.assert_allclose(table[:, 4], ref.d, rtol=1e-15, atol=1e-17)


def test_unused_key_warns(driver, tmp_path):
    proc = run(driver, tmp_path, "&run analysis='pulse', output='w' /\n"
                                 "&pulse kind='half_sine', beta=2.0 /\n")
    assert proc.returncode == 0
    assert "beta: not used by kind half_sine" in proc.stderr


BAD = [
    # (namelist text, words the one-line message must contain)
    ("&run analysis='pulse', output='o' /\n&pulse betta = 1.0 /\n",
     ["case.nml:2:", "&pulse", "betta", "unknown key"]),
    ("&run analysis='pulse', output='o' /\n&pulse beta = abc /\n",
     ["case.nml:2:", "&pulse", "beta", "bad value"]),
    ("&run analysis='pulse', output='o' /\n&pulse beta = nan /\n",
     ["case.nml:2:", "&pulse", "beta = NaN", "must be"]),
    ("&run analysis='pulse', output='o' /\n\n&pulse duration = -1 /\n",
     ["case.nml:3:", "&pulse", "duration = -1.0", "> 0"]),
    ("&run analysis='pulse', output='o' /\n&pulse kind = 'gabor' /\n",
     ["&pulse", "kind = 'gabor'", "allowed"]),
    ("&run analysis='pulse', output='o' /\n&pulse amp_unit = 'ft' /\n",
     ["&pulse", "amp_unit", "allowed: m/s2, g"]),
    ("&run analysis='pulse', output='o' /\n&pulse kind='triangular', peak_frac=2 /\n",
     ["&pulse", "peak_frac = 2.0", "[0, 1]"]),
    ("&run analysis='pulse', output='o' /\n&pulse kind='mp', gamma=0.5 /\n",
     ["&pulse", "gamma = 0.5", "> 1"]),
    ("&run analysis='pulse', output='o' /\n&time npts = 1 /\n",
     ["&time", "npts", "2 .. 10000000"]),
    ("&run analysis='pulse', output='o' /\n&time dt = 0.1, npts = 5 /\n",
     ["&time", "dt, npts", "one of them"]),
    ("&run analysis='pulse', output='o' /\n&time t_end = -1 /\n",
     ["&time", "t_end", "> t_start"]),
    ("&run analysis='pulse', output='o' /\n&pulses beta = 1 /\n",
     ["case.nml:2:", "&pulses", "unknown group"]),
    ("&run analysis='pulse', output='o' /\n&pulse beta=1 /\n&pulse beta=2 /\n",
     ["case.nml:3:", "&pulse", "twice"]),
    ("&run analysis='tower', output='o' /\n",
     ["case.nml:1:", "&run", "analysis = 'tower'", "allowed: pulse"]),
    ("&run output='o' /\n", ["&run", "analysis: missing"]),
    ("&run analysis='pulse' /\n", ["&run", "output: missing"]),
    ("&pulse beta = 1 /\n", ["&run", "missing group"]),
    ("&run analysis='pulse', output='o'\n", ["not closed"]),
    ("&run analysis='pulse', output='o', outptu='p' /\n", ["&run", "outptu", "unknown key"]),
]


@pytest.mark.parametrize("text, words", BAD)
def test_bad_input_one_line_exit_2_no_output(driver, tmp_path, text, words):
    proc = run(driver, tmp_path, text)
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    for word in words:
        assert word in lines[0], lines[0]
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml"], "no output left behind"


def test_missing_file_and_usage(driver, tmp_path):
    proc = subprocess.run([driver, "nope.nml"], cwd=tmp_path, capture_output=True, text=True)
    assert proc.returncode == 2
    assert proc.stderr.count("\n") == 1 and "nope.nml" in proc.stderr
    proc = subprocess.run([driver], cwd=tmp_path, capture_output=True, text=True)
    assert proc.returncode == 2 and "usage" in proc.stderr


def test_unwritable_output_leaves_nothing(driver, tmp_path):
    (tmp_path / "blocked").write_text("a file, not a directory")
    proc = run(driver, tmp_path, "&run analysis='pulse', output='blocked/x' /\n")
    assert proc.returncode == 2
    assert "&run: output" in proc.stderr and len(proc.stderr.strip().splitlines()) == 1
    assert sorted(x.name for x in tmp_path.iterdir()) == ["blocked", "case.nml"]
