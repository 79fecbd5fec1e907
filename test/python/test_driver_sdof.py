"""Batch driver, analyses 'sdof', 'sdof_beta' and 'sdof_shock': the example inputs, the
relations between the columns (pseudo-spectra, T = 0, PSA/PGA, the envelope and its
plateau, histories against spectra, threads), a bad record among good ones (its rows
fail, the others are computed, exit status 1), the located one-line input errors (exit
2, no output), no half-written output, progress on stderr, the echo and record paths
relative to the input file. The numbers themselves are checked against independent
mpmath references by the regression cases (test/regression/sdof_*)."""
import csv
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from driver_echo import echo_text, with_output

from driver_tables import coded, g_text

HERE = Path(__file__).resolve().parent
RECORDS = HERE.parent / "regression" / "records"
INPUT = HERE.parents[1] / "input"
G = 9.80665

SPECTRA = ["record (-)", "damping (-)", "T (s)", "SD (m)", "SV (m/s)", "SA (g)", "PSV (m/s)",
           "PSA (g)"]
HISTORY = ["record (-)", "damping (-)", "T (s)", "t (s)", "a_g (g)", "z (m)", "z' (m/s)",
           "a_abs (g)", "status (-)"]
SHOCK = ["damping (-)", "t_d/T (-)", "T (s)", "SD (m)", "SV (m/s)", "SA (g)", "PSV (m/s)",
         "PSA (g)", "SA/PGA (-)", "PSA/PGA (-)"]


def run(driver, cwd, text, name="case.nml"):
    path = Path(cwd) / name
    path.write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def with_records(tmp_path):
    shutil.copytree(RECORDS, tmp_path / "records")
    return tmp_path / "records"


def read_table(path, labelled=True):
    """(header, labels or None, numbers) of a CSV table of the driver."""
    with open(path, newline="") as f:
        header = next(csv.reader(f))
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    if not labelled:
        return header, None, np.array(rows, ndmin=2)
    assert all(isinstance(r[0], str) for r in rows), "record names are quoted"
    # the status ("ok", "failed") as its code 0, 1
    return header, [r[0] for r in rows], coded(header, rows)


def sdof_run(driver, tmp_path, records, sdof=None, history=None, output="o"):
    text = f"&run analysis='sdof', output='{output}' /\n&records {records} /\n"
    if sdof is not None:
        text += f"&sdof {sdof} /\n"
    if history is not None:
        text += f"&sdof_history {history} /\n"
    return run(driver, tmp_path, text)


def omega(t):
    return 2 * np.pi / t


# ---------------------------------------------------------------- example inputs

def test_sdof_example(driver, tmp_path):
    proc = subprocess.run([driver, str(INPUT / "sdof_example.nml")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    out = tmp_path / "out"
    for table in ("sdof", "sdof_envelope", "sdof_history"):
        for ext in ("txt", "csv"):
            assert f"out/sdof_example_{table}.{ext}" in proc.stdout
    echo = echo_text(tmp_path, proc.stdout)
    for group in ("&records", "&sdof", "&sdof_history"):
        assert group in echo
    header, names, data = read_table(out / "sdof_example_sdof.csv")
    assert header == SPECTRA + ["PSA/PGA (-)", "status (-)"]
    assert names == ["quake_a"] * 80 + ["quake_b"] * 80            # 2 dampings x 40
    periods = data[:40, 1]
    assert periods[0] == 0.05 and periods[-1] == 3.0
    np.testing.assert_allclose(np.diff(np.log(periods)), np.log(60) / 39, rtol=1e-12)
    assert np.all(data[:, -1] == 0)
    # the text table: the CSV's numbers to 6 significant digits, the status by name
    txt = [ln.split()[1:] for ln in (out / "sdof_example_sdof.txt").read_text().splitlines()
           if not ln.startswith("#")]
    assert txt == [[g_text(x) for x in row[:-1]] + ["ok"] for row in data]
    progress = [ln for ln in proc.stderr.splitlines() if ln.startswith("sdof: record ")]
    assert len(progress) == 2 and progress[0].startswith("sdof: record 1/2: quake_a")
    assert "-> 0.3 g" in progress[0]
    # the envelope: the largest over both records, held at its peak below 0.2 s
    _, _, env = read_table(out / "sdof_example_sdof_envelope.csv", labelled=False)
    for j, zeta in enumerate([0.02, 0.05]):
        rows = env[env[:, 0] == zeta]
        both = [data[(data[:, 0] == zeta) & (np.array(names) == n)] for n in ("quake_a",
                                                                            "quake_b")]
        for col_env, col in ((2, 4), (3, 6), (4, 7)):        # SA, PSA, PSA/PGA
            top = np.maximum(both[0][:, col], both[1][:, col])
            held = np.array([top[i:].max() if periods[i] < 0.2 else top[i]
                             for i in range(40)])
            np.testing.assert_array_equal(rows[:, col_env], held)
    # the histories: one block per record, damping and period, from rest
    header, names, hist = read_table(out / "sdof_example_sdof_history.csv")
    assert header == HISTORY
    assert len(names) == 240 * 2 + 200 * 2
    assert np.all(hist[:, -1] == 0)
    assert sorted(set(hist[:, 1])) == [0.3, 1.0] and set(hist[:, 0]) == {0.05}
    starts = np.flatnonzero(hist[:, 2] == 0)
    assert len(starts) == 4 and np.all(hist[starts, 4:7] == 0)


def test_sdof_beta_example(driver, tmp_path):
    proc = subprocess.run([driver, str(INPUT / "sdof_beta.nml")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    header, _, t = read_table(tmp_path / "out" / "sdof_beta.csv", labelled=False)
    assert header == ["gamma (-)", "theta/omega (-)", "beta (-)", "beta_cos (-)"]
    assert t.shape == (4 * 61, 4)
    r, gamma, beta, bcos = t[:, 1], t[:, 0], t[:, 2], t[:, 3]
    at_one = r == 1.0
    assert np.isnan(beta[at_one & (gamma == 0)]).all() and np.isinf(bcos[at_one & (gamma == 0)]).all()
    damped = at_one & (gamma > 0)
    np.testing.assert_allclose(beta[damped], 1 / gamma[damped], rtol=1e-15)   # 1/gamma
    ok = ~(at_one & (gamma == 0))
    np.testing.assert_allclose(bcos[ok], 2 * np.abs(beta[ok]), rtol=1e-15)
    und = (gamma == 0) & ~at_one
    np.testing.assert_allclose(beta[und], 1 / (1 - r[und] ** 2), rtol=1e-14)
    assert np.all(beta[und & (r > 1)] < 0)


def test_sdof_shock_example(driver, tmp_path):
    proc = subprocess.run([driver, str(INPUT / "sdof_shock.nml")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    header, _, t = read_table(tmp_path / "out" / "sdof_shock.csv",
                              labelled=False)
    assert header == SHOCK and t.shape == (100, 10)
    und = t[t[:, 0] == 0]
    x = und[:, 1]
    exact = np.where(x <= 0.5, 2 * np.sin(np.pi * np.minimum(x, 0.5)), 2.0)
    np.testing.assert_allclose(und[:, 8], exact, rtol=1e-12)
    np.testing.assert_allclose(t[:, 2], 0.1 / t[:, 1], rtol=1e-15)
    np.testing.assert_allclose(t[:, 5], t[:, 8] * 0.2, rtol=1e-14)            # SA = ... PGA
    damped = t[t[:, 0] == 0.05]
    assert np.all(damped[:, 8] <= und[:, 8] * (1 + 1e-12))


@pytest.mark.parametrize("name", ["sdof_example.nml", "sdof_beta.nml", "sdof_shock.nml"])
def test_every_key_of_the_group_is_in_the_example(name):
    """The example inputs document every key of their analysis' own group."""
    text = (INPUT / name).read_text()
    keys = {
        "sdof_example.nml": ["periods", "period_range", "period_count", "spacing", "damping",
                             "g", "peaks", "threads", "envelope", "plateau_below", "shape"],
        "sdof_beta.nml": ["ratios", "ratio_range", "ratio_count", "spacing", "gamma",
                          "model"],
        "sdof_shock.nml": ["ratios", "ratio_range", "ratio_count", "periods", "period_range",
                           "period_count", "spacing", "damping"],
    }[name]
    for key in keys:
        assert re.search(rf"\b{key}\b", text), key


# ---------------------------------------------------------------- relations

R2 = "files='records/quake_a.AT2', 'records/quake_c.txt', units='auto', 'cm/s2', dt=0, 0.005"


def test_pseudo_spectra_ground_and_shape(driver, tmp_path):
    with_records(tmp_path)
    proc = sdof_run(driver, tmp_path, R2 + ", target_pga=0.4, 0, scale=1, 2.5",
                    "periods=0, 0.05, 0.3, 1.5, damping=0, 0.1, shape=.true., g=9.81")
    assert proc.returncode == 0, proc.stderr
    header, names, d = read_table(tmp_path / "o_sdof.csv")
    assert header == SPECTRA + ["PSA/PGA (-)", "status (-)"]
    assert names == ["quake_a"] * 8 + ["quake_c"] * 8
    zero = d[:, 1] == 0
    pga = np.where(np.array(names) == "quake_a", 0.4, np.nan)
    assert np.all(d[zero, 2:4] == 0) and np.all(d[zero, 5] == 0)               # SD SV PSV
    np.testing.assert_array_equal(d[zero, 4], d[zero, 6])                      # SA = PSA
    np.testing.assert_allclose(d[zero, 4][:2], pga[:2], rtol=1e-15)            # = PGA
    w = omega(d[~zero, 1])
    np.testing.assert_allclose(d[~zero, 5], w * d[~zero, 2], rtol=1e-15)
    np.testing.assert_allclose(d[~zero, 6], w * w * d[~zero, 2] / 9.81, rtol=1e-15)
    for name in ("quake_a", "quake_c"):
        rows = d[np.array(names) == name]
        np.testing.assert_allclose(rows[:, 7], rows[:, 6] / rows[0, 4], rtol=1e-15)
    txt = (tmp_path / "o_sdof.txt").read_text()
    assert "PSA/PGA peak" in txt and "scale factor 2.5" in txt


def test_exact_peaks_bound_the_samples(driver, tmp_path):
    with_records(tmp_path)
    spec = "period_range=0.02, 2, period_count=12, spacing='log', damping=0.05"
    assert sdof_run(driver, tmp_path, R2, spec + ", peaks='exact'", output="e").returncode == 0
    assert sdof_run(driver, tmp_path, R2, spec + ", peaks='samples'",
                    output="s").returncode == 0
    _, _, e = read_table(tmp_path / "e_sdof.csv")
    _, _, s = read_table(tmp_path / "s_sdof.csv")
    assert np.all(e[:, 2:7] >= s[:, 2:7] * (1 - 1e-14))
    assert np.any(e[:, 4] > s[:, 4] * (1 + 1e-6)), "short periods peak between samples"


def test_threads_do_not_change_the_results(driver, tmp_path):
    with_records(tmp_path)
    spec = "period_range=0.05, 3, period_count=30, damping=0.02, 0.05, 0.1"
    for n in (1, 3):
        proc = sdof_run(driver, tmp_path, R2, spec + f", threads={n}", output=f"t{n}")
        assert proc.returncode == 0, proc.stderr
    np.testing.assert_array_equal(read_table(tmp_path / "t1_sdof.csv")[2],
                                  read_table(tmp_path / "t3_sdof.csv")[2])


def test_histories_agree_with_the_spectrum_at_the_samples(driver, tmp_path):
    with_records(tmp_path)
    proc = sdof_run(driver, tmp_path, R2, "periods=0.2, 0.7, damping=0.03, 0.08, "
                    "peaks='samples'", "periods=0.7, 0, 0.2")
    assert proc.returncode == 0, proc.stderr
    _, snames, spec = read_table(tmp_path / "o_sdof.csv")
    _, hnames, hist = read_table(tmp_path / "o_sdof_history.csv")
    hnames = np.array(hnames)
    # order: record, damping, period (as given), then time
    blocks = [(n, z, t) for n in ("quake_a", "quake_c") for z in (0.03, 0.08)
              for t in (0.7, 0.0, 0.2)]
    starts = np.flatnonzero(hist[:, 2] == 0)
    assert len(starts) == len(blocks)
    for k, (n, z, t) in enumerate(blocks):
        b = hist[starts[k]:starts[k + 1] if k + 1 < len(starts) else None]
        assert set(hnames[starts[k]:starts[k] + len(b)]) == {n}
        assert np.all(b[:, 0] == z) and np.all(b[:, 1] == t)
        if t == 0:
            assert np.all(b[:, 4:6] == 0)
            np.testing.assert_array_equal(b[:, 6], b[:, 3])                    # a_abs = a_g
            continue
        row = spec[(np.array(snames) == n) & (spec[:, 0] == z) & (spec[:, 1] == t)][0]
        np.testing.assert_allclose(np.abs(b[:, 4:7]).max(axis=0), row[2:5], rtol=1e-12)
        # a_abs = -(2 zeta omega z' + omega^2 z) / g
        w = omega(t)
        np.testing.assert_allclose(b[:, 6], -(2 * z * w * b[:, 5] + w * w * b[:, 4]) / G,
                                   rtol=1e-10, atol=1e-12 * np.abs(b[:, 6]).max())


def test_histories_only(driver, tmp_path):
    with_records(tmp_path)
    proc = sdof_run(driver, tmp_path, "files='records/quake_b.csv'", None,
                    "periods=0.5, damping=0.2")
    assert proc.returncode == 0, proc.stderr
    assert sorted(p.name for p in tmp_path.glob("o_*")) == ["o_input.nml",
                                                           "o_sdof_history.csv",
                                                           "o_sdof_history.txt"]
    _, names, hist = read_table(tmp_path / "o_sdof_history.csv")
    assert len(names) == 200 and np.all(hist[:, 0] == 0.2)


def test_beta_models_and_log_range(driver, tmp_path):
    for model in ("hysteretic", "viscous"):
        proc = run(driver, tmp_path, f"&run analysis='sdof_beta', output='{model}' /\n"
                   f"&sdof_beta ratio_range=0.1, 10, ratio_count=21, spacing='log', "
                   f"gamma=0.3, model='{model}' /\n")
        assert proc.returncode == 0, proc.stderr
    _, _, h = read_table(tmp_path / "hysteretic_sdof_beta.csv", labelled=False)
    _, _, v = read_table(tmp_path / "viscous_sdof_beta.csv", labelled=False)
    r = h[:, 1]
    np.testing.assert_allclose(r, np.geomspace(0.1, 10, 21), rtol=1e-14)
    np.testing.assert_allclose(h[:, 2], 1 / np.hypot(1 - r * r, 0.3), rtol=1e-14)
    np.testing.assert_allclose(v[:, 2], 1 / np.hypot(1 - r * r, 0.3 * r), rtol=1e-14)
    assert h[10, 1] == pytest.approx(1.0, rel=1e-15)                           # r = 1
    assert h[10, 2] == pytest.approx(1 / 0.3, rel=1e-13)                      # 1/gamma
    assert v[10, 2] == pytest.approx(1 / 0.3, rel=1e-13)


def test_shock_periods_and_ratios_agree(driver, tmp_path):
    pulse = "&pulse kind='half_sine', amp=2.0, duration=0.4 /\n"
    head = "&run analysis='sdof_shock', output='{}' /\n" + pulse
    proc = run(driver, tmp_path, head.format("r") + "&sdof_shock ratios=0.4, 1.0, 2.0, "
               "damping=0.05 /\n")
    assert proc.returncode == 0, proc.stderr
    proc = run(driver, tmp_path, head.format("p") + "&sdof_shock periods=0, 0.2, 0.4, 1.0, "
               "damping=0.05 /\n")
    assert proc.returncode == 0, proc.stderr
    _, _, r = read_table(tmp_path / "r_sdof_shock.csv", labelled=False)
    _, _, p = read_table(tmp_path / "p_sdof_shock.csv", labelled=False)
    np.testing.assert_array_equal(r[::-1], p[1:])
    assert math.isinf(p[0, 1]) and p[0, 5] == p[0, 7] == pytest.approx(2.0 / G, rel=1e-15)
    assert p[0, 8] == p[0, 9] == 1.0


def test_shock_of_a_ricker_uses_one_over_freq(driver, tmp_path):
    proc = run(driver, tmp_path, "&run analysis='sdof_shock', output='k' /\n"
               "&pulse kind='ricker', amp=0.3, amp_unit='g', freq=2.0 /\n"
               "&sdof_shock ratios=0.5, 1, 2, damping=0 /\n")
    assert proc.returncode == 0, proc.stderr
    _, _, t = read_table(tmp_path / "k_sdof_shock.csv", labelled=False)
    np.testing.assert_allclose(t[:, 2], 0.5 / t[:, 1], rtol=1e-15)
    np.testing.assert_allclose(t[:, 5], 0.3 * t[:, 8], rtol=1e-14)
    assert "t_d = 1/freq = 0.5 s" in (tmp_path / "k_sdof_shock.txt").read_text()


# ---------------------------------------------------------------- failed rows

BAD_CSV = "# bad record\n# time_s, accel_g\n0.00, 0.01\n0.02, 0.0.3\n0.04, 0.02\n"


def test_bad_record_fails_its_rows_only(driver, tmp_path):
    with_records(tmp_path)
    (tmp_path / "records" / "bad.csv").write_text(BAD_CSV)
    spec = "periods=0.1, 0.5, damping=0.05, 0.1, envelope=.true., shape=.true."
    good = "files='records/quake_b.csv', 'records/quake_c.txt', dt=0, 0.005, units='g', " \
           "'cm/s2'"
    proc = sdof_run(driver, tmp_path, good, spec, "periods=0.3", output="good")
    assert proc.returncode == 0, proc.stderr
    _, _, ref = read_table(tmp_path / "good_sdof.csv")
    _, _, ref_env = read_table(tmp_path / "good_sdof_envelope.csv", labelled=False)
    _, _, ref_hist = read_table(tmp_path / "good_sdof_history.csv")
    mixed = "files='records/quake_b.csv', 'records/bad.csv', 'records/quake_c.txt', " \
            "dt=0, 0, 0.005, units='g', 'g', 'cm/s2'"
    proc = sdof_run(driver, tmp_path, mixed, spec, "periods=0.3", output="mixed")
    assert proc.returncode == 1, proc.stderr
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("seispulse: error: ")]
    assert len(errors) == 2, proc.stderr
    for word in ["case.nml:2:", "&records", "files(2) = 'records/bad.csv'",
                 "records/bad.csv:4", "0.0.3"]:
        assert word in errors[0], errors[0]
    assert errors[1] == ("seispulse: error: case.nml:2: &records: 1 of 3 records failed "
                         "(2 'bad'): their rows "
                         "hold NaN and status failed")
    progress = [ln for ln in proc.stderr.splitlines() if ln.startswith("sdof: record ")]
    assert [p.split(":")[1] for p in progress] == [" record 1/3", " record 2/3",
                                                   " record 3/3"]
    assert progress[1].endswith("bad (failed)")
    header, names, data = read_table(tmp_path / "mixed_sdof.csv")
    assert names == ["quake_b"] * 4 + ["bad"] * 4 + ["quake_c"] * 4
    np.testing.assert_array_equal(data[[0, 1, 2, 3, 8, 9, 10, 11]], ref)
    assert np.all(np.isnan(data[4:8, 2:8]))
    assert list(data[4:8, 0]) == [0.05, 0.05, 0.1, 0.1]
    assert list(data[4:8, 1]) == [0.1, 0.5, 0.1, 0.5]
    assert list(data[:, -1]) == [0] * 4 + [1] * 4 + [0] * 4
    # the envelope leaves the failed record out
    _, _, env = read_table(tmp_path / "mixed_sdof_envelope.csv", labelled=False)
    np.testing.assert_array_equal(env, ref_env)
    # its history: one row of NaN per damping and period, status 1
    _, hnames, hist = read_table(tmp_path / "mixed_sdof_history.csv")
    bad = np.array(hnames) == "bad"
    assert bad.sum() == 2 and np.all(hist[bad, -1] == 1) and np.all(np.isnan(hist[bad, 2:7]))
    assert list(hist[bad, 0]) == [0.05, 0.1] and np.all(hist[bad, 1] == 0.3)
    np.testing.assert_array_equal(hist[~bad], ref_hist)
    for table in ("sdof", "sdof_envelope", "sdof_history"):
        txt = (tmp_path / f"mixed_{table}.txt").read_text()
        assert "FAILED" in txt and "records/bad.csv:4" in txt


def test_every_record_failing_still_writes_the_tables(driver, tmp_path):
    proc = sdof_run(driver, tmp_path, "files='nothing.AT2'", "periods=0.5, envelope=.true.")
    assert proc.returncode == 1
    _, _, env = read_table(tmp_path / "o_sdof_envelope.csv", labelled=False)
    assert env.shape == (1, 4) and np.all(np.isnan(env[:, 2:]))
    _, names, data = read_table(tmp_path / "o_sdof.csv")
    assert names == ["nothing"] and data[0, -1] == 1


# ---------------------------------------------------------------- input errors

R = "files='records/quake_a.AT2', 'records/quake_b.csv'"
BAD = [
    # (records group, sdof group, history group, words of the one-line message)
    (R, "periods=0.1, -0.2", None, ["case.nml:3:", "&sdof", "periods(2) = -0.2", ">= 0"]),
    (R, "periods=-1", None, ["&sdof", "periods = -1.0", ">= 0"]),
    (R, "periods=0.1, nan, 0.3", None, ["&sdof", "periods(2)", "missing or NaN"]),
    (R, "periods=0.1, damping=1.0", None, ["&sdof", "damping = 1.0", "[0, 1)"]),
    (R, "periods=0.1, damping=0.05, -0.01", None, ["&sdof", "damping(2) = -0.01", "[0, 1)"]),
    (R, "period_range=0.1, 2, period_count=0", None, ["&sdof", "period_count = 0",
                                                      "2 .. 1000"]),
    (R, "period_range=0.1, 2", None, ["&sdof", "period_count: missing"]),
    (R, "period_range=2, 1, period_count=5", None, ["&sdof", "period_range = 2.0, 1.0",
                                                    "above the minimum"]),
    (R, "period_range=-1, 1, period_count=5", None, ["&sdof", "period_range(1) = -1.0"]),
    (R, "period_range=0, 2, period_count=5, spacing='log'", None,
     ["&sdof", "spacing = 'log'", "period_range(1) > 0"]),
    (R, "period_range=0.1, 2, period_count=5, spacing='cubic'", None,
     ["&sdof", "spacing = 'cubic'", "linear, log"]),
    (R, "periods=0.1, 0.2, period_range=0.1, 2, period_count=5", None,
     ["&sdof", "periods, period_range", "only one"]),
    (R, "periods=0.1, period_count=5", None, ["&sdof", "period_count: only with period_range"]),
    (R, "periods=0.1, spacing='log'", None, ["&sdof", "spacing: only with period_range"]),
    (R, "periods=0.1, pperiods=0.2", None, ["case.nml:3:", "&sdof", "pperiods", "unknown key"]),
    (R, "periods=abc", None, ["&sdof", "periods", "bad value"]),
    (R, "periods=0.1, peaks='max'", None, ["&sdof", "peaks = 'max'", "exact, samples"]),
    (R, "periods=0.1, threads=-1", None, ["&sdof", "threads = -1", ">= 0"]),
    (R, "periods=0.1, g=0", None, ["&sdof", "g = 0.0", "> 0"]),
    (R, "periods=0.1, plateau_below=0.2", None, ["&sdof", "plateau_below",
                                                 "envelope = .true."]),
    (R, "periods=0.1, envelope=.true., plateau_below=-1", None,
     ["&sdof", "plateau_below = -1.0", ">= 0"]),
    (R, "damping=0.05", None, ["&sdof", "periods: missing"]),
    (R, "damping=0.05, envelope=.true.", "periods=0.5", ["&sdof", "envelope: only with "
                                                          "spectra"]),
    (R, "periods=0.1", "damping=0.05", ["case.nml:4:", "&sdof_history", "periods: missing"]),
    (R, "periods=0.1", "periods=0.5, -1", ["&sdof_history", "periods(2) = -1.0"]),
    (R, "periods=0.1", "periods=0.5, damping=1.5", ["&sdof_history", "damping = 1.5"]),
    (R, "periods=0.1", "periods=0.5, step=2", ["&sdof_history", "step", "unknown key"]),
    (R + ", format='peer'", "periods=0.1", None, ["case.nml:2:", "&records",
                                                  "format = 'peer'", "unknown format"]),
    (R + ", scale=-1", "periods=0.1", None, ["&records", "scale = -1.0", "> 0"]),
    ("format='auto'", "periods=0.1", None, ["&records", "files: missing"]),
]


@pytest.mark.parametrize("rgroup, sgroup, hgroup, words", BAD)
def test_bad_input_one_line_exit_2_no_output(driver, tmp_path, rgroup, sgroup, hgroup,
                                             words):
    with_records(tmp_path)
    proc = sdof_run(driver, tmp_path, rgroup, sgroup, hgroup)
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    for word in words:
        assert word in lines[0], lines[0]
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml", "records"]


BAD_PULSE = [
    # (analysis, groups, words)
    ("sdof_beta", "&sdof_beta ratios=0.5, -1 /", ["case.nml:2:", "&sdof_beta",
                                                  "ratios(2) = -1.0", ">= 0"]),
    ("sdof_beta", "&sdof_beta ratios=0.5, gamma=-0.1 /", ["&sdof_beta", "gamma = -0.1"]),
    ("sdof_beta", "&sdof_beta ratios=0.5, model='linear' /",
     ["&sdof_beta", "model = 'linear'", "hysteretic, viscous"]),
    ("sdof_beta", "&sdof_beta ratio_range=0, 2, ratio_count=5, spacing='log' /",
     ["&sdof_beta", "spacing = 'log'", "ratio_range(1) > 0"]),
    ("sdof_beta", "&sdof_beta ratios=0.5, ratio_range=0, 2, ratio_count=3 /",
     ["&sdof_beta", "ratios, ratio_range", "only one"]),
    ("sdof_beta", "&sdof_beta gamma=0.1 /", ["&sdof_beta", "ratios: missing"]),
    ("sdof_beta", "&sdof_beta ratios=0.5, damping=0.05 /", ["&sdof_beta", "damping",
                                                            "unknown key"]),
    ("sdof_beta", "", ["&sdof_beta", "missing group"]),
    ("sdof_shock", "&pulse kind='rectangular' /\n&sdof_shock ratios=0.5, 0 /",
     ["case.nml:3:", "&sdof_shock", "ratios(2) = 0.0", "> 0"]),
    ("sdof_shock", "&sdof_shock ratios=0.5, periods=1.0 /",
     ["&sdof_shock", "ratios, periods", "only one"]),
    ("sdof_shock", "&sdof_shock periods=1.0, ratio_count=4 /",
     ["&sdof_shock", "ratio_count: only with ratio_range"]),
    ("sdof_shock", "&sdof_shock periods=0.5, damping=1 /", ["&sdof_shock", "damping = 1.0"]),
    ("sdof_shock", "&sdof_shock damping=0.05 /", ["&sdof_shock", "ratios: missing"]),
    ("sdof_shock", "&sdof_shock period_range=0.1, 1, period_count=1 /",
     ["&sdof_shock", "period_count = 1"]),
    ("sdof_shock", "&pulse duration=-1 /\n&sdof_shock ratios=1 /", ["case.nml:2:", "&pulse",
                                                                    "duration"]),
    ("sdof_shock", "&pulse kind='ricker', freq=50 /\n&sdof_shock periods=1e-6 /",
     ["case.nml:3:", "&sdof_shock", "periods = 1e-06", "too short"]),
    ("sdof_shock", "&pulse kind='rectangular' /", ["&sdof_shock", "missing group"]),
    ("sdof_shock", "&sdof_shock ratios=1 /\n&records files='a.AT2' /",
     ["&records", "not a group of analysis 'sdof_shock'"]),
]


@pytest.mark.parametrize("analysis, groups, words", BAD_PULSE)
def test_bad_pulse_input_one_line_exit_2_no_output(driver, tmp_path, analysis, groups,
                                                   words):
    proc = run(driver, tmp_path, f"&run analysis='{analysis}', output='o' /\n{groups}\n")
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    for word in words:
        assert word in lines[0], lines[0]
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml"]


@pytest.mark.parametrize("text, words", [
    ("&run analysis='sdof', output='o' /\n&sdof periods=0.1 /\n", ["&records",
                                                                  "missing group"]),
    ("&run analysis='sdof', output='o' /\n&records files='a.csv' /\n",
     ["&sdof", "missing group"]),
    ("&run analysis='sdof', output='o' /\n&records files='a.csv' /\n&sdof periods=0.1 /\n"
     "&newmark ky=0.1 /\n", ["case.nml:4:", "&newmark", "not a group of analysis 'sdof'"]),
    ("&run analysis='sdof', output='o' /\n&records files='a.csv' /\n&sdof periods=0.1 /\n"
     "&sdof_histroy periods=1 /\n", ["case.nml:4:", "&sdof_histroy", "unknown group"]),
])
def test_missing_or_foreign_groups(driver, tmp_path, text, words):
    proc = run(driver, tmp_path, text)
    assert proc.returncode == 2
    line = proc.stderr.strip()
    assert len(line.splitlines()) == 1 and all(w in line for w in words), line
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml"]


# ---------------------------------------------------------------- output, paths, echo

def test_no_half_written_output(driver, tmp_path):
    """A later table that cannot be written removes the earlier ones: exit 2, no table."""
    with_records(tmp_path)
    (tmp_path / "o_sdof_history.csv").mkdir()          # cannot be created as a file
    proc = sdof_run(driver, tmp_path, R, "periods=0.5, envelope=.true.", "periods=0.5")
    assert proc.returncode == 2
    line = proc.stderr.strip().splitlines()[-1]
    assert "&run: output:" in line and "o_sdof_history.csv" in line
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml", "o_sdof_history.csv",
                                                          "records"]


def test_paths_relative_to_the_input_file(driver, tmp_path):
    case_dir = tmp_path / "cases"
    case_dir.mkdir()
    shutil.copytree(RECORDS, case_dir / "records")
    (case_dir / "c.nml").write_text(
        "&run analysis='sdof', output='out/c' /\n"
        f"&records files='records/quake_b.csv', '{RECORDS / 'quake_a.AT2'}' /\n"
        "&sdof periods=0.5 /\n")
    work = tmp_path / "work"
    work.mkdir()
    proc = subprocess.run([driver, "../cases/c.nml"], cwd=work, capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    _, names, data = read_table(work / "out" / "c_sdof.csv")
    assert names == ["quake_b", "quake_a"] and np.all(data[:, -1] == 0)


@pytest.mark.parametrize("sdof, history", [
    ("period_range=0.05, 2, period_count=9, spacing='log', damping=0.02, 0.07, "
     "peaks='samples', envelope=.true., plateau_below=0.3, shape=.true., g=9.81",
     "periods=1.2, 0.4"),
    ("damping=0.1", "periods=0.4, damping=0.03"),
])
def test_echo_reads_back_to_the_same_tables(driver, tmp_path, sdof, history):
    with_records(tmp_path)
    rg = ("files='records/quake_a.AT2', 'records/quake_c.txt', units='auto', 'cm/s2', "
          "dt=0, 0.005, target_pga=0.3, 0, scale=1, 1.2, polarity=-1, pga_rounding='slammer'")
    proc = sdof_run(driver, tmp_path, rg, sdof, history, output="first")
    assert proc.returncode == 0, proc.stderr
    echo = with_output(echo_text(tmp_path, proc.stdout), "first", "second")
    (tmp_path / "echo.nml").write_text(echo)
    proc2 = subprocess.run([driver, "echo.nml"], cwd=tmp_path, capture_output=True,
                           text=True, timeout=120)
    assert proc2.returncode == 0, proc2.stderr
    firsts = sorted(tmp_path.glob("first_*.csv"))
    assert firsts
    for first in firsts:
        second = first.with_name(first.name.replace("first", "second"))
        labelled = "envelope" not in first.name
        t1, t2 = read_table(first, labelled), read_table(second, labelled)
        assert t1[0] == t2[0] and t1[1] == t2[1]
        np.testing.assert_array_equal(t1[2], t2[2])


@pytest.mark.parametrize("analysis, groups", [
    ("sdof_beta", "&sdof_beta ratio_range=0.1, 3, ratio_count=7, spacing='log', "
                  "gamma=0.2, 0, model='viscous' /"),
    ("sdof_shock", "&pulse kind='triangular', amp=2.5, duration=0.3, "
                   "peak_frac=0.2 /\n&sdof_shock period_range=0.1, 2, period_count=6, "
                   "damping=0, 0.1 /"),
])
def test_pulse_echo_reads_back(driver, tmp_path, analysis, groups):
    proc = run(driver, tmp_path, f"&run analysis='{analysis}', output='first' /\n{groups}\n")
    assert proc.returncode == 0, proc.stderr
    echo = with_output(echo_text(tmp_path, proc.stdout), "first", "second")
    (tmp_path / "echo.nml").write_text(echo)
    proc2 = subprocess.run([driver, "echo.nml"], cwd=tmp_path, capture_output=True,
                           text=True, timeout=120)
    assert proc2.returncode == 0, proc2.stderr
    np.testing.assert_array_equal(
        read_table(tmp_path / f"first_{analysis}.csv", False)[2],
        read_table(tmp_path / f"second_{analysis}.csv", False)[2])
