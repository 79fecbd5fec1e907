"""Batch driver: an axis given as a list or as a range with a count (driver_axis), in
the forms of &sdof_beta (shortest numbers, a hint) and of the rocking &map (numbers as
real_str, every list value with its index, a default count)."""
import subprocess
from pathlib import Path

import numpy as np
import pytest


def run(driver, cwd, text):
    (Path(cwd) / "case.nml").write_text(text)
    return subprocess.run([driver, "case.nml"], cwd=cwd, capture_output=True, text=True,
                          timeout=60)


def beta(axis):
    return f"&run analysis='sdof_beta', output='o' /\n&sdof_beta {axis} /\n"


def rocking_map(freq, amp="amp_ratio = 1.0"):
    return ("&run analysis='rocking', output='o' /\n&block b = 0.2, h = 0.8 /\n"
            f"&rocking what='map' /\n&map {freq}, {amp} /\n")


BAD = [
    (beta("ratios = -0.5"), "&sdof_beta: ratios = -0.5: must be a finite number >= 0"),
    (beta("ratios = 0.5, 1.0e-7, -2.5"),
     "&sdof_beta: ratios(3) = -2.5: must be a finite number >= 0"),
    (beta("ratios = 1.0, 0.5"),
     "&sdof_beta: ratios(2) = 0.5: the values must be strictly ascending"),
    (beta("ratios = 0.5, ratio_range = 0.1, 1.0"),
     "&sdof_beta: ratios, ratio_range: give only one of them (a list, or a range with "
     "ratio_count)"),
    (beta("ratio_count = 5"), "&sdof_beta: ratio_count: only with ratio_range"),
    (beta("ratios = 0.5, spacing = 'log'"), "&sdof_beta: spacing: only with ratio_range"),
    (beta("ratio_range = 0.1, 1.0"),
     "&sdof_beta: ratio_count: missing (the number of values in ratio_range, 2 .. 1000)"),
    (beta("ratio_range = 0.1, 1.0, ratio_count = 1001"),
     "&sdof_beta: ratio_count = 1001: must be in 2 .. 1000"),
    (beta("ratio_range = 1.5, 0.25, ratio_count = 3"),
     "&sdof_beta: ratio_range = 1.5, 0.25: the maximum must be above the minimum"),
    (beta("ratio_range = 0.0, 1.0, ratio_count = 3, spacing = 'log'"),
     "&sdof_beta: spacing = 'log': needs ratio_range(1) > 0 (use 'linear', or a list "
     "ratios that starts with 0)"),
    (beta("ratio_range = 0.1, 1.0, ratio_count = 3, spacing = 'cubic'"),
     "&sdof_beta: spacing = 'cubic': unknown spacing (allowed: linear, log)"),
    (rocking_map("freq_ratio = -0.5"),
     "&map: freq_ratio(1) = -0.5: must be a finite number > 0"),
    (rocking_map("freq_ratio = 0.5, freq_range = 1.0, 2.0"),
     "&map: freq_ratio, freq_range: give only one of them"),
    (rocking_map("freq_count = 5"),
     "&map: freq_ratio: missing (give freq_ratio = a list, or freq_range = min, max with "
     "freq_count)"),
    (rocking_map("freq_ratio = 1.0, freq_count = 5"),
     "&map: freq_count: only with freq_range"),
    (rocking_map("freq_range = 0.0, 2.0"), "&map: freq_range(1) = 0.0: must be > 0"),
    (rocking_map("freq_range = 1.0, 2.0", "amp_range = 1.5, 0.25"),
     "&map: amp_range = 1.5, 0.25: the maximum must be above the minimum"),
]


@pytest.mark.parametrize("text, message", BAD)
def test_axis_message(driver, tmp_path, text, message):
    proc = run(driver, tmp_path, text)
    assert proc.returncode == 2
    lines = proc.stderr.splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("seispulse: error: case.nml:")
    assert lines[0].endswith(message), lines[0]
    assert not list(tmp_path.glob("o_*"))


def table(path):
    """The numbers of a CSV table (a category column, quoted names, as NaN)."""
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2,
                      converters=lambda s: float("nan") if s.startswith('"') else float(s))


def test_log_range_values(driver, tmp_path):
    proc = run(driver, tmp_path,
               beta("ratio_range = 0.1, 1.0, ratio_count = 4, spacing = 'log', gamma = 0.2"))
    assert proc.returncode == 0, proc.stderr
    r = table(tmp_path / "o_sdof_beta.csv")[:, 1]
    assert r[0] == 0.1 and r[-1] == 1.0
    np.testing.assert_allclose(r, [0.1, 10 ** (-2 / 3), 10 ** (-1 / 3), 1.0], rtol=1e-15)


def test_map_count_default(driver, tmp_path):
    # freq_count and amp_count default to 21
    proc = run(driver, tmp_path, rocking_map("freq_range = 1.0, 3.0", "amp_range = 0.0, 2.0"))
    assert proc.returncode == 0, proc.stderr
    t = table(tmp_path / "o_rocking_map.csv")
    assert t.shape == (21 * 21, 3)
    np.testing.assert_allclose(np.unique(t[:, 0]), np.linspace(1.0, 3.0, 21), rtol=1e-15)
    np.testing.assert_allclose(np.unique(t[:, 1]), np.linspace(0.0, 2.0, 21), rtol=0,
                               atol=1e-15)
