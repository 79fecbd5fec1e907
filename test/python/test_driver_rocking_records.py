"""Batch driver, analysis 'rocking' on records (&records instead of &pulse): the summary
row of each record against seispulse.rocking on the same samples (read, scaled and turned
over as &records says), a sampled rectangular pulse against the pulse run and the closed
forms of doc/rocking.md (written out in test_driver_rocking), the stacked history, a
record that fails its row (status `failed`, exit status 1), kv, the block's g, and the input errors
(exit status 2)."""
import csv
import math
import subprocess
from pathlib import Path

import numpy as np
import pytest

from test_driver_rocking import rect_closed_forms, rect_response, run

G = 9.80665
OUTCOMES = ["rest", "no_uplift", "overturn_no_impact", "overturn_one_impact",
            "overturn_many_impacts", "time_limit"]
SUMMARY = ["record", "pga", "alpha", "p", "e", "outcome", "t_uplift", "t_overturn",
           "n_impacts", "t_impact1", "theta_max", "theta_min", "psi_max", "psi_min", "t_end",
           "theta_abs_max", "t_abs_max", "status"]
UNITS = ["-", "g", "rad", "rad/s", "-", "-", "s", "s", "-", "s", "rad", "rad", "-", "-", "s",
         "rad", "s", "-"]
# the columns that mean the same in the summary of a pulse
SHARED = ["alpha", "p", "e", "t_uplift", "t_overturn", "n_impacts", "t_impact1", "theta_max",
          "theta_min", "psi_max", "psi_min", "t_end"]


def read_csv(path):
    """(header names, units, rows): a quoted cell is text, any other a float."""
    with open(path, newline="") as f:
        header = next(csv.reader(f))
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    names = [h.rsplit(" (", 1)[0] for h in header]
    units = [h.rsplit(" (", 1)[1][:-1] for h in header]
    return names, units, rows


def columns(path):
    names, _, rows = read_csv(path)
    return {n: [r[j] for r in rows] for j, n in enumerate(names)}


def write_column(path, values):
    Path(path).write_text("\n".join(repr(float(x)) for x in values) + "\n")


def rocking(driver, tmp_path, block, records, opts="", output="r", status=0, extra=""):
    text = (f"&run analysis='rocking', output='{output}' /\n&block {block} /\n"
            f"&records {records} /\n" + (f"&rocking {opts} /\n" if opts else "") + extra)
    proc = run(driver, tmp_path, text, name=f"{output}.nml")
    assert proc.returncode == status, proc.stderr
    return proc


def record(tmp_path, name="rec.txt", dt=0.01, n=200, amp=0.45, period=0.7):
    """A decaying sine record in g, written as one column."""
    t = dt * np.arange(n)
    acc = amp * np.sin(2 * np.pi * t / period) * np.exp(-0.6 * t)
    write_column(tmp_path / name, acc)
    return acc


def test_summary_matches_the_library(driver, tmp_path):
    """Each row is seispulse.rocking.simulate on the record as &records reads it (in g,
    units='g' with the block's g), scaled (scale) and turned over (polarity); the
    columns, units and kinds of the table; max |theta| is the larger extreme and theta
    is that at t_abs_max."""
    from seispulse import rocking as sp_rocking
    dt = 0.01
    acc = record(tmp_path, dt=dt)
    rocking(driver, tmp_path, "b=0.2, h=0.8",
            f"files='rec.txt', 'rec.txt', format='column', dt={dt}, scale=1.0, 1.5, "
            "polarity=1, -1")
    names, units, rows = read_csv(tmp_path / "r_rocking.csv")
    assert names == SUMMARY and units == UNITS
    blk = sp_rocking.rectangular_block(0.2, 0.8)
    for row, factor in zip(rows, (1.0, -1.5)):
        s = dict(zip(names, row))
        assert s["record"] == "rec" and s["status"] == "ok"
        assert s["pga"] == pytest.approx(abs(factor) * np.max(np.abs(acc)), rel=1e-15)
        ref = sp_rocking.simulate(blk, accel=acc * factor, dt=dt, units="g")
        assert s["outcome"] == ref.outcome
        assert s["n_impacts"] == ref.n_impacts and ref.n_impacts > 0
        for col in ("t_uplift", "t_end", "theta_max", "theta_min"):
            assert s[col] == pytest.approx(getattr(ref, col), rel=1e-12, abs=1e-15), col
        assert s["t_impact1"] == pytest.approx(ref.t_impacts[0], rel=1e-12)
        assert s["psi_max"] == pytest.approx(ref.theta_max / blk.alpha, rel=1e-14)
        assert s["theta_abs_max"] == max(s["theta_max"], -s["theta_min"])
        # theta at the time of the largest |theta| is that extreme, and a dense history
        # never goes beyond it
        t_dense = np.linspace(0.0, ref.t_end, 4001)
        dense = sp_rocking.simulate(blk, accel=acc * factor, dt=dt, units="g", t=t_dense)
        assert np.max(np.abs(dense.theta)) <= s["theta_abs_max"] * (1 + 1e-12)
        at = sp_rocking.simulate(blk, accel=acc * factor, dt=dt, units="g",
                                 t=[s["t_abs_max"]])
        assert abs(at.theta[0]) == pytest.approx(s["theta_abs_max"], rel=1e-9)


@pytest.mark.parametrize("amp, duration", [(0.4, 0.3), (0.4, 0.6), (0.6, 0.2)])
def test_sampled_rectangle_equals_the_pulse(driver, tmp_path, amp, duration):
    """A record of equal samples A (g), n of them dt apart, is the rectangular pulse of
    amplitude A and duration (n - 1) dt: the shared columns equal the pulse run's, and
    (linearized, e = 0) the closed forms of doc/rocking.md, including the time of the
    largest |theta|: tau_m (2.25) for a stable block, the time of |theta| = pi/2 (t_end)
    for one that overturns."""
    dt = 0.01
    n = int(round(duration / dt)) + 1
    write_column(tmp_path / "box.txt", [amp] * n)
    block = "b=0.2, h=0.8, model='linearized', e=0.0"
    rocking(driver, tmp_path, block, f"files='box.txt', format='column', dt={dt}",
            opts="rtol=1e-14")
    s = columns(tmp_path / "r_rocking.csv")
    text = (f"&run analysis='rocking', output='p' /\n&block {block} /\n"
            f"&pulse kind='rectangular', amp={amp}, amp_unit='g', duration={duration} /\n"
            "&rocking rtol=1e-14 /\n")
    proc = run(driver, tmp_path, text, name="p.nml")
    assert proc.returncode == 0, proc.stderr
    pnames, _, prows = read_csv(tmp_path / "p_rocking.csv")
    pul = dict(zip(pnames, prows[0]))
    for col in SHARED:
        x, y = s[col][0], pul[col]
        if isinstance(y, float) and math.isnan(y):
            assert math.isnan(x), col
        else:
            assert x == pytest.approx(y, rel=1e-10, abs=1e-13), col
    td = (n - 1) * dt
    f, eta = s["p"][0] * td, s["alpha"][0] / amp
    r = rect_closed_forms(f, eta)
    close = dict(rel=1e-9, abs=1e-12)
    if r["region"] == "S2":
        assert s["outcome"][0] == "rest"
        assert s["t_abs_max"][0] == pytest.approx(r["tau_m"] * td, **close)
        assert s["theta_abs_max"][0] == pytest.approx(r["psi_max"] * s["alpha"][0], **close)
        assert s["t_end"][0] == pytest.approx(r["tau_i"] * td, **close)
    else:
        assert s["outcome"][0] == "overturn_no_impact"
        assert s["t_overturn"][0] == pytest.approx(r["tau_c"] * td, **close)
        assert s["theta_abs_max"][0] == math.pi / 2
        assert s["t_abs_max"][0] == s["t_end"][0]
        psi, _ = rect_response(s["t_end"][0] / td, f, eta)
        assert psi * s["alpha"][0] == pytest.approx(math.pi / 2, rel=1e-9)


def test_history_stacked_and_a_failed_record(driver, tmp_path):
    """what = 'history': the records stacked with the record's name first, each row
    seispulse.rocking's theta and omega on the grid, a_g = g x the record (linear in
    between, 0 after); a file that cannot be read gives one row of NaN, the others are
    written and the exit status is 1 (the summary the same: a NaN row, status failed)."""
    from seispulse import rocking as sp_rocking
    dt = 0.02
    acc = record(tmp_path, dt=dt, n=100, amp=0.5)
    record(tmp_path, name="other.txt", dt=dt, n=60, amp=0.35, period=0.5)
    recs = f"files='rec.txt', 'gone.txt', 'other.txt', format='column', dt={dt}"
    proc = rocking(driver, tmp_path, "b=0.15, h=0.6", recs,
                   opts="what='history', t_end=4.0, dt=0.05", status=1)
    assert "files(2) = 'gone.txt'" in proc.stderr
    assert "1 of 3 records failed (2 'gone'): their rows hold NaN" in proc.stderr
    h = columns(tmp_path / "r_rocking_history.csv")
    labels = h["record"]
    assert labels[:81] == ["rec"] * 81 and labels[81] == "gone"
    assert labels[82:] == ["other"] * 81 and len(labels) == 163
    assert all(math.isnan(h[c][81]) for c in ("t", "a_g", "theta", "omega"))
    blk = sp_rocking.rectangular_block(0.15, 0.6)
    t = np.array(h["t"][:81])
    assert t == pytest.approx(0.05 * np.arange(81), abs=1e-14)
    ref = sp_rocking.simulate(blk, accel=acc, dt=dt, units="g", t=t)
    np.testing.assert_allclose(h["theta"][:81], ref.theta, rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose(h["omega"][:81], ref.omega, rtol=1e-10, atol=1e-13)
    ts = dt * np.arange(len(acc))
    np.testing.assert_allclose(h["a_g"][:81], G * np.interp(t, ts, acc, right=0.0),
                               rtol=1e-13, atol=1e-14)
    assert not (tmp_path / "r_rocking.csv").exists()
    rocking(driver, tmp_path, "b=0.15, h=0.6", recs, output="s", status=1)
    s = columns(tmp_path / "s_rocking.csv")
    assert s["record"] == ["rec", "gone", "other"]
    assert s["status"] == ["ok", "failed", "ok"]
    assert s["outcome"][1] == "nan" and math.isnan(s["t_end"][1])
    assert s["alpha"][1] == s["alpha"][0]


def test_kv_and_the_block_g(driver, tmp_path):
    """kv on records: a_v = kv a_g, seispulse.rocking's run with accel_v = kv x the
    record; a kv that lifts the block off fails that row naming kv. &block g: the gravity
    and the unit g of the records (a ramp of k g/s uplifts at tan(alpha)/k for any g)."""
    from seispulse import rocking as sp_rocking
    dt = 0.01
    acc = record(tmp_path, dt=dt)
    rocking(driver, tmp_path, "b=0.2, h=0.8", f"files='rec.txt', format='column', dt={dt}",
            opts="kv=-0.4")
    s = columns(tmp_path / "r_rocking.csv")
    blk = sp_rocking.rectangular_block(0.2, 0.8)
    ref = sp_rocking.simulate(blk, accel=acc, dt=dt, units="g", accel_v=-0.4 * acc)
    plain = sp_rocking.simulate(blk, accel=acc, dt=dt, units="g")
    assert s["theta_max"][0] == pytest.approx(ref.theta_max, rel=1e-12)
    assert abs(ref.theta_max - plain.theta_max) > 1e-4
    proc = rocking(driver, tmp_path, "b=0.2, h=0.8",
                   f"files='rec.txt', format='column', dt={dt}", opts="kv=-3.0",
                   output="lift", status=1)
    assert "files(1) = 'rec.txt': &rocking: kv = -3.0: a_v = kv a_g falls below -g" \
        in proc.stderr, proc.stderr
    write_column(tmp_path / "ramp.txt", 0.05 * np.arange(101))      # 5 g/s
    for g in (9.81, 5.0):
        rocking(driver, tmp_path, f"b=0.2, h=0.8, g={g}",
                "files='ramp.txt', format='column', dt=0.01", opts="t_max=2.0",
                output="ramp")
        s = columns(tmp_path / "ramp_rocking.csv")
        assert s["t_uplift"][0] == pytest.approx(0.25 / 5.0, rel=1e-12)
        assert s["p"][0] == pytest.approx(math.sqrt(0.75 * g / math.hypot(0.2, 0.8)),
                                          rel=1e-14)


def test_example_input(driver, source_root, tmp_path):
    """input/rocking_records.nml: two records of input/records scaled to 0.5 g."""
    proc = subprocess.run([driver, str(source_root / "input" / "rocking_records.nml")],
                          cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    s = columns(tmp_path / "out" / "records_rocking.csv")
    assert s["record"] == ["quake_a", "quake_b"]
    assert s["pga"] == pytest.approx([0.5, 0.5], rel=1e-15)
    assert all(o in OUTCOMES for o in s["outcome"]) and s["status"] == ["ok", "ok"]


@pytest.mark.parametrize("groups, words", [
    ("&block b=0.2, h=0.8 /\n&records files='rec.txt', format='column', dt=0.01 /\n"
     "&pulse amp=1.0 /\n", ["&pulse: not with &records"]),
    ("&block b=0.2, h=0.8 /\n&records files='rec.txt', format='column', dt=0.01 /\n"
     "&rocking what='map' /\n&map freq_ratio=1.0, amp_ratio=2.0 /\n",
     ["&records: not used by what = 'map'"]),
    ("&block b=0.2, h=0.8, g=9.81 /\n&pulse amp=1.0 /\n", ["&block: g: only with &records"]),
    ("&block b=0.2, h=0.8, g=-1.0 /\n&records files='rec.txt', format='column', dt=0.01 /\n",
     ["&block: g = -1", "> 0"]),
    ("&block b=0.2, h=0.8 /\n&records files='rec.txt', format='column' /\n",
     ["&records: dt:", "format 'column'"]),
    ("&block b=0.2, h=0.8 /\n&records files='rec.txt', format='column', dt=0.01 /\n"
     "&rocking dt=0.1 /\n", ["&rocking: dt: only with what = 'history'"]),
])
def test_input_errors(driver, tmp_path, groups, words):
    record(tmp_path)
    proc = run(driver, tmp_path, "&run analysis='rocking', output='e' /\n" + groups)
    assert proc.returncode == 2, proc.stderr
    for w in words:
        assert w in proc.stderr, (w, proc.stderr)
    assert not list(tmp_path.glob("e_*.csv"))
