"""Batch driver, analysis 'sliding': the worked examples of doc/sliding.md section 10 (the
input files under input/), the located one-line errors (exit 2, no output), sweeps,
the history table, and the agreement of the closed forms with the event-driven
integrator."""
import math
import subprocess
from pathlib import Path

import numpy as np
import pytest

from driver_tables import g_text, read_summary_txt, read_table, run_example
import sliding_reference

PI = "3.141592653589793"
COLUMNS = ["case", "mu", "eta1", "eta2", "mode", "t_y1", "t_m1", "u_m1", "t_y2", "t_m2",
           "u_m2", "u_res", "v_m1", "v_m2"]
UNITS = ["-", "-", "-", "-", "-", "s", "s", "m", "s", "s", "m", "m", "m/s", "m/s"]
MODES = ["no_sliding", "unilateral", "stick", "slip", "stuck", "reverse_only"]


def run(driver, cwd, text, name="case.nml"):
    (Path(cwd) / name).write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True, timeout=120)


def sliding(driver, tmp_path, pulse, block, extra="", output="s"):
    """Run a sliding case; return (main table, history table or None)."""
    proc = run(driver, tmp_path, f"&run analysis='sliding', output='{output}' /\n"
                                 f"&pulse {pulse} /\n&block {block} /\n{extra}")
    assert proc.returncode == 0, proc.stderr
    hist = tmp_path / f"{output}_sliding_history.csv"
    return (read_table(tmp_path / f"{output}_sliding.csv"),
            read_table(hist) if hist.exists() else None)


def near(x, value, digits):
    """x agrees with `value` to the digits given (half a unit of the last one)."""
    return abs(x - value) <= 0.5 * 10.0 ** -digits * (1 + 1e-9)


# ---------------------------------------------------------------- worked examples

AG, TD = 0.66 * 9.81, 0.6
LEN = AG * TD * TD          # A_g t_d^2 = 2.330856 m


def test_example_1_9_1(driver, source_root, tmp_path):
    """doc/sliding.md section 10 (exact column): eta = 0.5, beta = -pi, full cycle."""
    proc = run_example(driver, source_root, tmp_path, "sliding_example_1_9_1.nml")
    assert "out/example_1_9_1_sliding.csv" in proc.stdout
    t = read_table(tmp_path / "out" / "example_1_9_1_sliding.csv")
    # one case: the text table is a summary, `name  value  unit` per column, the CSV's
    # numbers to 6 significant digits, the case as an integer, the mode by name
    txt = read_summary_txt(tmp_path / "out" / "example_1_9_1_sliding.txt")
    assert list(txt) == COLUMNS
    assert [txt[c] for c in COLUMNS] == [(g_text(t[c][0]), u) for c, u in zip(COLUMNS, UNITS)]
    assert txt["case"][0] == "1" and txt["mode"][0] == "slip"
    assert t["eta1"][0] == 0.5 and t["eta2"][0] == 0.5 and t["mu"][0] == 0.33
    assert t["mode"][0] == "slip"
    assert near(t["t_y1"][0] / TD, 0.1035846, 7)
    assert near(t["t_m1"][0] / TD, 1.2465561, 7)
    assert near(t["t_m1"][0], 0.74793, 5)
    assert near(t["u_m1"][0] / LEN, 0.1706088, 7)
    assert near(t["u_m1"][0], 0.398, 3)
    assert t["t_y2"][0] == t["t_m1"][0]                 # slip: reverses at once
    assert near(t["t_m2"][0] / TD, 2.4468988, 7)
    assert near(t["u_m2"][0] / LEN, 0.1643832, 7)
    assert near(t["u_m2"][0], 0.383, 3)
    assert near(t["u_res"][0] / LEN, 0.0062257, 7)
    assert near(t["u_res"][0], 0.0145, 4)
    assert math.isclose(t["u_res"][0], t["u_m1"][0] - t["u_m2"][0], rel_tol=1e-12)
    # the CSV header gives the units
    csv_head = (tmp_path / "out" / "example_1_9_1_sliding.csv").read_text().splitlines()[0]
    assert csv_head == ",".join(f"{c} ({u})" for c, u in zip(COLUMNS, UNITS))


def test_example_1_9_2(driver, source_root, tmp_path):
    """doc/sliding.md section 10 with the exact |eta1| and eta2 of Eq. 1.31: unilateral.

    With the exact eta1 = 0.3147964 the values are tau_y1 = 0.057038, tau_m1 = 1.422938,
    u_m1 = 0.3162655 A_g t_d^2 (the forward slide does not depend on eta2 > 1: asserted
    against the mpmath oracle sliding_reference.py); doc/sliding.md section 10 lists
    0.0571, 1.4227, 0.31608, which are the values for the chapter's rounded eta1 = 0.315
    (checked below)."""
    run_example(driver, source_root, tmp_path, "sliding_example_1_9_2.nml")
    t = read_table(tmp_path / "out" / "example_1_9_2_sliding.csv")
    assert math.isnan(t["mu"][0])
    assert near(t["eta1"][0], 0.3148, 4) and near(t["eta2"][0], 1.6984, 4)
    assert t["mode"][0] == "unilateral"
    assert near(t["t_y1"][0] / TD, 0.057038, 6)
    assert near(t["t_y1"][0], 0.034, 3)
    assert near(t["t_m1"][0] / TD, 1.422938, 6)
    assert near(t["t_m1"][0], 0.854, 3)
    ref = sliding_reference.full_cycle(t["eta1"][0], -math.pi)
    assert t["t_y1"][0] / TD == pytest.approx(float(ref["tau_y1"]), rel=1e-9)
    assert t["t_m1"][0] / TD == pytest.approx(float(ref["tau_m1"]), rel=1e-9)
    assert t["u_m1"][0] / LEN == pytest.approx(float(ref["um1"]), rel=1e-9)
    assert near(t["u_m1"][0], 0.737, 3)
    assert t["u_res"][0] == t["u_m1"][0] and t["u_m2"][0] == 0.0
    assert math.isnan(t["t_y2"][0]) and math.isnan(t["t_m2"][0])


def test_example_1_9_2_chapter_rounding(driver, tmp_path):
    """The chapter's own numbers come back with its rounded eta1 = 0.315."""
    t, _ = sliding(driver, tmp_path, f"amp=0.66, amp_unit='g', g=9.81, duration=0.6, "
                                     f"beta=-{PI}, full=.true.", "eta1 = 0.315, eta2 = 1.70")
    assert near(t["t_y1"][0] / TD, 0.0571, 4)
    assert near(t["t_m1"][0] / TD, 1.4227, 4)
    assert near(t["u_m1"][0] / LEN, 0.31608, 5)


def test_example_1_9_2_physical_input_is_unstable(driver, source_root, tmp_path):
    """mu = 0.33 on 30 deg: tan 30 > 0.33, the library's 'statically unstable' error."""
    text = (source_root / "input" / "sliding_example_1_9_2.nml").read_text()
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("&block"))
    lines[start + 1:start + 3] = ["    mu = 0.33, slope_deg = 30.0"]
    proc = run(driver, tmp_path, "\n".join(lines) + "\n")
    assert proc.returncode == 2
    msg = proc.stderr.strip()
    assert len(msg.splitlines()) == 1
    assert f"case.nml:{start + 1}: &block: slope_deg = 30.0" in msg
    assert "statically unstable" in msg
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml"]


# ---------------------------------------------------------------- errors

GOOD_PULSE = "&pulse amp = 0.5, amp_unit = 'g', duration = 0.6, beta = -2.0, full = .true. /\n"
HEAD = "&run analysis='sliding', output='o' /\n" + GOOD_PULSE

BAD = [
    (HEAD + "&block mu = -0.1 /\n", ["case.nml:3:", "&block", "mu = -0.1", "> 0"]),
    (HEAD + "&block mu = 0 /\n", ["case.nml:3:", "&block", "mu = 0.0", "> 0"]),
    (HEAD + "&block mu = 0.33, slope_deg = 30 /\n",
     ["case.nml:3:", "&block", "slope_deg = 30.0", "statically unstable"]),
    (HEAD + "&block mu = 0.3, static_factor = 0.9 /\n",
     ["&block", "static_factor = 0.9", ">= 1"]),
    (HEAD + "&block mu = 0.3, eta1 = 0.5 /\n", ["&block", "mu, eta1", "only one"]),
    (HEAD + "&block mu_list = 0.1, 0.2, eta_list = 0.3 /\n",
     ["&block", "mu_list, eta_list", "only one"]),
    (HEAD + "&block slope_deg = 5 /\n", ["&block", "mu: missing", "mu, eta1, mu_list, eta_list"]),
    (HEAD + "&block eta2 = 0.5 /\n", ["&block", "eta2", "only with eta1"]),
    (HEAD + "&block eta1 = 0.5, slope_deg = 5 /\n", ["&block", "slope_deg", "not with eta1"]),
    (HEAD + "&block eta1 = 0.5, xi_deg = 5 /\n", ["&block", "xi_deg", "not with eta1"]),
    (HEAD + "&block eta1 = -0.5 /\n", ["&block", "eta1 = -0.5", "> 0"]),
    (HEAD + "&block eta_list = 0.2, 0.0 /\n", ["&block", "eta_list(2) = 0.0", "> 0"]),
    (HEAD + "&block mu_list = 0.1, 0.2, -0.3 /\n", ["&block", "mu_list(3)", "mu = -0.3"]),
    (HEAD + "&block mu_list = 0.1, , 0.3 /\n", ["&block", "mu_list(2)", "missing"]),
    (HEAD + "&block mu = 0.3, xi_deg = 100 /\n", ["&block", "xi_deg = 100.0", "[-90, 90]"]),
    (HEAD + "&block mu = 0.3, friction = 2 /\n", ["case.nml:3:", "&block", "friction",
                                                   "unknown key"]),
    (HEAD + "&block mu = abc /\n", ["&block", "mu", "bad value"]),
    (HEAD + "\n&block mu = 0.3 /\n&method solver = 'rk4' /\n",
     ["case.nml:5:", "&method", "solver = 'rk4'", "allowed: auto, closed, integrator"]),
    ("&run analysis='sliding', output='o' /\n&pulse kind='half_sine', amp=3 /\n"
     "&block mu = 0.1 /\n&method solver = 'closed' /\n",
     ["case.nml:4:", "&method", "solver = 'closed'", "exponential only"]),
    ("&run analysis='sliding', output='o' /\n&pulse amp = -3 /\n"
     "&block mu = 0.1 /\n&method solver = 'closed' /\n",
     ["&method", "solver = 'closed'", "amp > 0"]),
    ("&run analysis='sliding', output='o' /\n&pulse kind='mp', vamp=0.5 /\n"
     "&block eta1 = 0.1 /\n", ["&block", "eta1", "velocity amplitude"]),
    (HEAD + "&block mu = 0.3 /\n&history dt = 0.1, npts = 5 /\n",
     ["&history", "dt, npts", "one of them"]),
    (HEAD + "&block mu = 0.3 /\n&history npts = 1 /\n", ["&history", "npts", "2 .. "]),
    (HEAD + "&block mu = 0.3 /\n&history t_end = -1 /\n", ["&history", "t_end = -1.0", "> 0"]),
    (HEAD + "&block mu = 0.3 /\n&history dt = 0 /\n", ["&history", "dt = 0.0", "> 0"]),
    (HEAD + "&block mu = 0.3 /\n&time t_end = 1 /\n",
     ["case.nml:4:", "&time", "not a group of analysis 'sliding'"]),
    (HEAD, ["&block", "missing group"]),
    ("&run analysis='sliding', output='o' /\n&pulse duration = -1 /\n&block mu = 0.3 /\n",
     ["case.nml:2:", "&pulse", "duration = -1.0", "> 0"]),
    ("&run analysis='sliding', output='o' /\n&pulse g = 0 /\n&block mu = 0.3 /\n",
     ["&pulse", "g:", "> 0"]),
    ("&run analysis='sliding', output='o' /\n&pulse kind='mp', gamma=2e6 /\n"
     "&block mu = 0.3 /\n", ["case.nml:2:", "&pulse", "gamma = 2000000.0", "integrator"]),
    ("&run analysis='pulse', output='o' /\n&block mu = 0.3 /\n",
     ["case.nml:2:", "&block", "not a group of analysis 'pulse'"]),
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


def test_unwritable_history_leaves_nothing(driver, tmp_path):
    """The second table fails: the first one is removed again."""
    (tmp_path / "o_sliding_history.txt").mkdir()     # a directory where a file must go
    proc = run(driver, tmp_path, HEAD + "&block mu = 0.3 /\n&history npts = 5 /\n")
    assert proc.returncode == 2
    assert "&run: output" in proc.stderr and len(proc.stderr.strip().splitlines()) == 1
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml", "o_sliding_history.txt"]


def test_unused_keys_warn(driver, tmp_path):
    proc = run(driver, tmp_path, "&run analysis='sliding', output='w' /\n"
                                 "&pulse kind='half_sine', amp=3, beta=1 /\n"
                                 "&block eta1 = 0.2, along_plane = .false. /\n")
    assert proc.returncode == 0, proc.stderr
    assert "beta: not used by kind half_sine" in proc.stderr
    assert "along_plane: not used with eta1" in proc.stderr


# ---------------------------------------------------------------- sweeps

def test_mu_sweep_rows_equal_single_runs(driver, tmp_path):
    mus = [0.05, 0.1, 0.2, 0.3, 0.45, 0.6]
    pulse = f"amp=0.5, amp_unit='g', duration=0.6, beta=-{PI}, full=.true."
    t, _ = sliding(driver, tmp_path, pulse, "mu_list = " + ", ".join(map(str, mus)))
    np.testing.assert_array_equal(t["case"], np.arange(1, len(mus) + 1))
    np.testing.assert_array_equal(t["mu"], mus)
    np.testing.assert_allclose(t["eta1"], np.array(mus) / 0.5, rtol=1e-15)
    assert set(t["mode"]) >= {"no_sliding", "stick", "slip"}   # eta >= 1: no sliding
    for i, mu in enumerate(mus):
        one, _ = sliding(driver, tmp_path, pulse, f"mu = {mu}", output=f"one{i}")
        for c in COLUMNS[1:]:
            np.testing.assert_array_equal(one[c], t[c][i:i + 1], err_msg=c)
    nos = t["mode"] == "no_sliding"
    assert np.all(np.isnan(t["t_y1"][nos])) and np.all(t["u_m1"][nos] == 0)
    assert np.all(t["u_m1"][~nos] > 0)


def test_eta_sweep_is_symmetric(driver, tmp_path):
    etas = [0.1, 0.3, 0.5, 0.9, 1.5]
    t, _ = sliding(driver, tmp_path, "amp=4.0, duration=0.5, beta=1.0, full=.true.",
                   "eta_list = " + ", ".join(map(str, etas)))
    assert np.all(np.isnan(t["mu"]))
    np.testing.assert_array_equal(t["eta1"], etas)
    np.testing.assert_array_equal(t["eta2"], etas)
    assert t["mode"][-1] == "no_sliding"


def test_along_plane_factor(driver, tmp_path):
    """along_plane multiplies slips and velocities by K1,2 = cos(l - x) +- mu sin(l - x)."""
    pulse = "amp=0.6, amp_unit='g', duration=0.5, beta=0.5, full=.true."
    blk = "mu = 0.4, slope_deg = 8.0, xi_deg = 20.0"
    a, _ = sliding(driver, tmp_path, pulse, blk, output="a")
    b, _ = sliding(driver, tmp_path, pulse, blk + ", along_plane = .false.", output="b")
    dl = math.radians(8.0 - 20.0)
    k1, k2 = math.cos(dl) + 0.4 * math.sin(dl), math.cos(dl) - 0.4 * math.sin(dl)
    assert a["mode"][0] == b["mode"][0] and a["mode"][0] in ("stick", "slip")
    for c, k in [("u_m1", k1), ("v_m1", k1), ("u_m2", k2), ("v_m2", k2)]:
        assert math.isclose(a[c][0], k * b[c][0], rel_tol=1e-13), c
    assert math.isclose(a["u_res"][0], k1 * b["u_m1"][0] - k2 * b["u_m2"][0], rel_tol=1e-12)
    for c in ("eta1", "eta2", "t_y1", "t_m1", "t_y2", "t_m2"):
        assert a[c][0] == b[c][0], c


# ---------------------------------------------------------------- history

@pytest.mark.parametrize("solver", ["closed", "integrator"])
def test_history_ends_at_u_res_and_rest(driver, tmp_path, solver):
    mus = [0.1, 0.25, 0.45]
    t, h = sliding(driver, tmp_path, f"amp=0.5, amp_unit='g', duration=0.6, beta=-{PI}, "
                                     "full=.true.", "mu_list = 0.1, 0.25, 0.45",
                   f"&method solver = '{solver}' /\n&history npts = 401 /\n")
    assert h is not None and set(h) == {"case", "t", "a_g", "u", "u'"}
    for i in range(len(mus)):
        rows = h["case"] == i + 1
        tt, u, w = h["t"][rows], h["u"][rows], h["u'"][rows]
        assert len(tt) == 401 and tt[0] == 0.0
        t_rest = np.nanmax([t["t_m1"][i], t["t_m2"][i]])
        assert math.isclose(tt[-1], max(1.25 * t_rest, 1.2), rel_tol=1e-14)
        assert math.isclose(u[-1], t["u_res"][i], rel_tol=1e-9, abs_tol=1e-12)
        assert np.all(w[tt > t_rest * (1 + 1e-12)] == 0.0), "u' = 0 at rest"
        assert np.all(w[tt <= t["t_y1"][i]] == 0.0)
        assert abs(np.max(u) - t["u_m1"][i]) < 1e-3 * t["u_m1"][i]   # grid sampling
        assert np.max(np.abs(w)) <= max(t["v_m1"][i], t["v_m2"][i]) * (1 + 1e-12)
    # the ground acceleration of the history is the pulse of &pulse
    rows = h["case"] == 1
    assert np.max(h["a_g"][rows]) <= 0.5 * 9.80665 * (1 + 1e-15)
    assert math.isclose(np.max(h["a_g"][rows]), 0.5 * 9.80665, rel_tol=1e-3)


def test_history_t_end_dt_and_along_plane(driver, tmp_path):
    t, h = sliding(driver, tmp_path, "amp=0.7, amp_unit='g', duration=0.5, beta=-1.0, "
                                     "full=.true.", "mu = 0.45, slope_deg = 10, xi_deg = 5",
                   "&history t_end = 3.0, dt = 0.01 /\n")
    np.testing.assert_allclose(h["t"], np.arange(301) * 0.01, rtol=0, atol=1e-15)
    assert t["mode"][0] in ("stick", "slip")
    # along the plane: the history carries the K factors too
    assert math.isclose(h["u"][-1], t["u_res"][0], rel_tol=1e-9)
    assert np.max(np.abs(h["u'"])) <= max(t["v_m1"][0], t["v_m2"][0]) * (1 + 1e-12)


def test_history_any_pulse_kind(driver, tmp_path):
    for kind, extra in [("half_sine", "duration = 0.5"), ("sine_cycle", "duration = 0.5"),
                        ("ricker", "freq = 2.0"),
                        ("mavroeidis_papageorgiou", "vamp = 0.6, freq = 1.0, gamma = 2.5")]:
        t, h = sliding(driver, tmp_path, f"kind='{kind}', amp=0.6, amp_unit='g', {extra}",
                       "mu = 0.15", "&history /\n", output=kind)
        assert len(h["t"]) == 1001 and np.all(np.isfinite(h["u"]))
        assert math.isclose(h["u"][-1], t["u_res"][0], rel_tol=1e-12, abs_tol=1e-15)
        assert h["u'"][-1] == 0.0
        if kind == "mavroeidis_papageorgiou":
            assert math.isnan(t["eta1"][0])       # no acceleration amplitude


# ---------------------------------------------------------------- closed vs integrator

AGREE = [
    # (pulse, block): exponential pulses in every mode the closed forms have
    (f"amp=0.66, amp_unit='g', g=9.81, duration=0.6, beta=-{PI}, full=.true.", "mu = 0.33"),
    ("amp=5.0, duration=0.4, beta=2.0, full=.true.", "eta_list = 0.05, 0.2, 0.5, 0.8, 1.2"),
    ("amp=5.0, duration=0.4, beta=-6.0, full=.true.", "eta_list = 0.1, 0.6, 0.9"),
    ("amp=5.0, duration=0.4, beta=0.0, full=.true.", "eta1 = 0.3, eta2 = 0.7"),
    ("amp=5.0, duration=0.4, beta=-1.0, full=.true.", "eta1 = 1.5, eta2 = 0.4"),
    ("amp=3.0, duration=0.8, beta=1.0, full=.false.", "eta_list = 0.1, 0.4, 0.9"),
    ("amp=0.6, amp_unit='g', duration=0.5, beta=-2.0, full=.true.",
     "mu_list = 0.15, 0.3, 0.5, slope_deg = 6, xi_deg = 15"),
    ("amp=0.6, amp_unit='g', duration=0.5, beta=-2.0, full=.true.",
     "mu = 0.3, static_factor = 1.2, static_reverse = .true."),
    ("amp=0.6, amp_unit='g', duration=0.5, beta=3.0, full=.false.",
     "mu = 0.2, static_factor = 1.3"),
    # 'stuck' (doc/sliding.md section 7): eta2 < 1 but no reverse slide
    ("amp=5.0, duration=0.4, beta=0.4, full=.true.", "eta1 = 0.05, eta2 = 0.7"),
]


@pytest.mark.parametrize("pulse, block", AGREE)
def test_closed_forms_agree_with_integrator(driver, tmp_path, pulse, block):
    c, _ = sliding(driver, tmp_path, pulse, block, "&method solver='closed' /\n", output="c")
    i, _ = sliding(driver, tmp_path, pulse, block, "&method solver='integrator' /\n",
                   output="i")
    np.testing.assert_array_equal(c["mode"], i["mode"])
    for col in [c for c in COLUMNS[1:] if c != "mode"]:
        x, y = c[col], i[col]
        assert np.array_equal(np.isnan(x), np.isnan(y)), col
        ok = ~np.isnan(x)
        scale = max(np.max(np.abs(x[ok]), initial=0.0), 1e-300)
        np.testing.assert_allclose(y[ok], x[ok], rtol=1e-9, atol=1e-9 * scale, err_msg=col)


def test_auto_picks_closed_forms_for_the_exponential_pulse(driver, tmp_path):
    for kind, word in [("exponential", "closed forms"), ("half_sine", "integrator")]:
        proc = run(driver, tmp_path, f"&run analysis='sliding', output='{kind}' /\n"
                                     f"&pulse kind='{kind}', amp=3.0, duration=0.5 /\n"
                                     "&block mu = 0.1 /\n")
        assert proc.returncode == 0, proc.stderr
        assert word in (tmp_path / f"{kind}_sliding.txt").read_text().splitlines()[0]
