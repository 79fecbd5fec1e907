"""Batch driver, analysis 'winkler': the examples under input/ and their documented tables;
the pushover summary against the closed forms written out here (theta_up, the peaks and
the overturning tilt bracketed by the curve); histories under a pulse and under records
(shapes, outcome names, a small pulse that leaves the base in full contact); maps with
the rigid comparison (a cell that must overturn, one that must not, the difference
recomputed from the two classes); and the located one-line errors (exit 2, nothing
written). The curves themselves are the regression cases winkler_* (mpmath references in
test/regression/make_refs.py)."""
import math
import re
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest

from driver_tables import read_table, run_example

G = 9.80665
PUSHOVER = ["theta", "b", "pole", "area", "settlement", "k", "m_found", "m_imposed", "force",
            "force_ratio", "force_rigid"]
PUSHOVER_UNITS = ["rad", "m", "m", "m2", "m", "N/m3", "N m", "N m", "N", "-", "N"]
SUMMARY = ["k", "c", "theta_c", "theta_overturn", "outcome", "t_uplift", "t_lift_off",
           "n_impacts", "t_impact1", "t_overturn", "theta_max", "normal_max", "energy_error",
           "t_end"]
OUTCOMES = ["safe", "overturn_no_impact", "overturn_one_impact", "overturn_many_impacts",
            "time_limit"]
DIFFS = ["same", "only_winkler", "only_rigid", "other_mode"]
# a soft soil keeps the dynamic runs short: r = 1, h = 3, 47 t on G = 2 MPa
SOFT = "r=1.0, h=3.0, mass=47124.0, g_mod=2.0e6, nu=0.3"


def run(driver, cwd, text, name="case.nml"):
    (Path(cwd) / name).write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True,
                          timeout=600)


def header(path):
    """(names, units) of a CSV table."""
    first = Path(path).read_text().splitlines()[0].split(",")
    return [c.rsplit(" (", 1)[0] for c in first], [c.rsplit(" (", 1)[1][:-1] for c in first]


def winkler(driver, tmp_path, opts, extra="", output="w", status=0):
    """Run a case; return {table suffix: {column: array}} of every table it wrote."""
    text = f"&run analysis='winkler', output='{output}' /\n&winkler {opts} /\n{extra}"
    proc = run(driver, tmp_path, text, name=f"{output}.nml")
    assert proc.returncode == status, proc.stderr
    out = {}
    for path in sorted(tmp_path.glob(f"{output}_winkler*.csv")):
        if Path(path).read_text().startswith("record (-)"):
            continue
        out[path.stem[len(output) + 1:]] = read_table(path)
    return out, proc


def circle_k(g_mod, nu, r):
    """k = K_R/I of the halfspace, 8 G r^3/(3 (1 - nu)) over pi r^4/4."""
    return 32 * g_mod / (3 * math.pi * (1 - nu) * r)


# ---------------------------------------------------------------- the examples

def test_example_pushover(driver, source_root, tmp_path):
    """input/winkler_pushover.nml: the documented numbers (peak F/W 0.245, overturning at
    0.300 rad) and the summary against theta_up = asin(2 W/(k pi r^3))/2."""
    run_example(driver, source_root, tmp_path, "winkler_pushover.nml")
    path = tmp_path / "out" / "winkler_pushover.csv"
    assert header(path) == (PUSHOVER, PUSHOVER_UNITS)
    t = read_table(path)
    s = read_table(tmp_path / "out" / "winkler_pushover_summary.csv")
    w, k = 47124.0 * G, circle_k(38.5e6, 0.3, 1.0)
    assert t["theta"] == pytest.approx(np.linspace(0, 0.32, 161), abs=1e-15)
    assert s["k0"][0] == pytest.approx(k, rel=1e-14)
    assert s["theta_up"][0] == pytest.approx(0.5 * math.asin(2 * w / (k * math.pi)), rel=1e-13)
    assert s["theta_c"][0] == pytest.approx(math.atan(1 / 3), rel=1e-15)
    assert s["force_ratio_rigid"][0] == pytest.approx(1 / 3, rel=1e-15)
    assert s["theta_end"][0] == pytest.approx(math.pi / 4, rel=1e-15)
    # the peaks lie on or above the curve, next to its own maxima
    assert s["max_force_ratio"][0] >= t["force_ratio"].max() - 1e-12
    assert s["max_force_ratio"][0] == pytest.approx(0.245, abs=5e-4)
    i = int(np.argmax(t["force_ratio"]))
    assert t["theta"][i - 1] <= s["theta_at_max"][0] <= t["theta"][i + 1]
    assert s["max_moment"][0] >= t["m_imposed"].max() - 1e-6
    # the imposed moment changes sign between the two grid points around theta_overturn
    j = int(np.argmax(t["m_imposed"] < 0))
    assert t["theta"][j - 1] < s["theta_overturn"][0] <= t["theta"][j]
    assert s["theta_overturn"][0] == pytest.approx(0.300, abs=5e-4)
    # F/W, F h cos = M_imp, M_imp = M_found - W h sin, rigid force
    np.testing.assert_allclose(t["force_ratio"], t["force"] / w, rtol=1e-15)
    np.testing.assert_allclose(t["force"] * 3 * np.cos(t["theta"]), t["m_imposed"],
                               rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(t["m_found"] - w * 3 * np.sin(t["theta"]), t["m_imposed"],
                               rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(t["force_rigid"], w * np.tan(math.atan(1 / 3) - t["theta"]),
                               rtol=1e-12, atol=1e-6)


def circle_moment(r, k, w, th):
    """Foundation moment (N m) of a circle of radius r on constant-k springs at tilt th,
    written out here: pi k r^4 cos^2 sin/4 in full contact; after uplift the contact width b
    from Phi(b) = J1 - c A0 = 2 W/(k sin 2 th) (brentq), M = k sin cos^2 (J2 - c J1), with
    the segment's area A0, first and second moments (c = r - b)."""
    from scipy.optimize import brentq

    def parts(b):
        c = r - b
        sq = math.sqrt(max(2 * r * b - b * b, 0.0))
        a0 = r * r * math.acos(c / r) - c * sq
        j1 = 2 / 3 * sq**3
        j2 = r**4 / 4 * (math.pi / 2 - math.asin(c / r)) - c / 4 * (2 * c * c - r * r) * sq
        return c, a0, j1, j2

    s2 = math.sin(2 * th)
    if s2 * k * math.pi * r**3 <= 2 * w:
        return math.pi * k * r**4 * math.cos(th)**2 * math.sin(th) / 4
    target = 2 * w / (k * s2)
    b = brentq(lambda x: parts(x)[2] - parts(x)[0] * parts(x)[1] - target, 1e-9, 2 * r,
               xtol=1e-15, rtol=1e-15)
    c, _, j1, j2 = parts(b)
    return k * math.sin(th) * math.cos(th)**2 * (j2 - c * j1)


def test_pushover_summary_against_scipy(driver, tmp_path):
    """The summary of the circle of the examples: the overturning tilt (the root of
    M - W h sin theta, brentq), the peak F/W and the peak imposed moment (bounded scalar
    maximisation of the curve written out here), and theta_up in closed form."""
    from scipy.optimize import brentq, minimize_scalar

    out, _ = winkler(driver, tmp_path, "r=1.0, h=3.0, mass=47124.0, g_mod=38.5e6, nu=0.3, "
                     "theta_max=0.05, theta_count=3")
    s = out["winkler_pushover_summary"]
    r, h, w, k = 1.0, 3.0, 47124.0 * G, circle_k(38.5e6, 0.3, 1.0)
    m_imp = lambda th: circle_moment(r, k, w, th) - w * h * math.sin(th)  # noqa: E731
    assert s["theta_overturn"][0] == pytest.approx(
        brentq(m_imp, 0.25, 0.31, xtol=1e-15, rtol=1e-15), rel=1e-11)
    force = minimize_scalar(lambda th: -m_imp(th) / (h * math.cos(th)) / w,
                            bounds=(0.005, 0.06), method="bounded",
                            options={"xatol": 1e-10})
    assert s["max_force_ratio"][0] == pytest.approx(-force.fun, rel=1e-11)
    assert s["theta_at_max"][0] == pytest.approx(force.x, abs=1e-6)
    moment = minimize_scalar(lambda th: -m_imp(th), bounds=(0.005, 0.06), method="bounded",
                             options={"xatol": 1e-10})
    assert s["max_moment"][0] == pytest.approx(-moment.fun, rel=1e-11)
    assert s["theta_at_max_moment"][0] == pytest.approx(moment.x, abs=1e-6)
    assert s["theta_up"][0] == pytest.approx(0.5 * math.asin(2 * w / (k * math.pi)),
                                             rel=1e-14)


def test_example_varying(driver, source_root, tmp_path):
    """input/winkler_pushover_varying.nml: the documented numbers (peak F/W 0.283,
    overturning at 0.317 rad, b/2r = 0.018 and a/r = 0.98 there); k grows as the contact
    shrinks."""
    run_example(driver, source_root, tmp_path, "winkler_pushover_varying.nml")
    t = read_table(tmp_path / "out" / "winkler_pushover_varying_winkler_pushover.csv")
    s = read_table(tmp_path / "out" / "winkler_pushover_varying_winkler_pushover_summary.csv")
    assert s["max_force_ratio"][0] == pytest.approx(0.283, abs=5e-4)
    assert s["theta_overturn"][0] == pytest.approx(0.317, abs=5e-4)
    j = int(np.argmax(t["m_imposed"] < 0))
    assert t["b"][j] / 2 == pytest.approx(0.018, abs=1e-3)
    assert t["pole"][j] == pytest.approx(0.98, abs=5e-3)
    up = t["b"] < 2.0
    assert np.all(np.diff(t["k"][up]) > 0)
    assert np.all(t["k"][~up] == t["k"][0])


def test_example_block_master_capacity(driver, source_root, tmp_path):
    """input/winkler_block.nml: theta_up = asin(W/(2 alpha b^2 k))/2 and full contact
    before it; input/winkler_master.nml: 41 log-spaced x from 1 to 100, M/(W r) rising
    towards 1 and K/K_0 falling towards 4/x; input/winkler_capacity.nml: N_ult, SF."""
    run_example(driver, source_root, tmp_path, "winkler_block.nml")
    t = read_table(tmp_path / "out" / "winkler_block_winkler_pushover.csv")
    s = read_table(tmp_path / "out" / "winkler_block_winkler_pushover_summary.csv")
    w = 60000.0 * G
    up = 0.5 * math.asin(w / (2 * 2.0 * 1.0 * 1e8))
    assert s["theta_up"][0] == pytest.approx(up, rel=1e-13)
    full = t["theta"] <= up
    assert np.all(t["b"][full] == 2.0) and np.all(t["b"][~full] < 2.0)
    np.testing.assert_allclose(t["m_found"][full], 4 / 3 * 2.0 * 1e8 * np.cos(
        t["theta"][full])**2 * np.sin(t["theta"][full]), rtol=1e-13)
    run_example(driver, source_root, tmp_path, "winkler_master.nml")
    m = read_table(tmp_path / "out" / "winkler_master.csv")
    assert m["theta_ratio"] == pytest.approx(np.logspace(0, 2, 41), rel=1e-13)
    assert np.all(np.diff(m["m_ratio"]) > 0) and np.all(np.diff(m["k_ratio"]) < 0)
    assert m["m_ratio"][0] == pytest.approx(0.25, rel=1e-13)
    assert m["k_ratio"][-1] * 100 / 4 == pytest.approx(1.0, abs=0.15)
    run_example(driver, source_root, tmp_path, "winkler_capacity.nml")
    c = read_table(tmp_path / "out" / "winkler_capacity.csv")
    n_ult = (math.pi + 3) * 40e3 * math.pi * 4.0
    assert c["n_ult"][0] == pytest.approx(n_ult, rel=1e-14)
    assert c["sf"][0] == pytest.approx(n_ult / (100000.0 * G), rel=1e-14)
    assert c["m_ult_tc"][0] == pytest.approx(0.8 * math.pi * 4.0 * 4.0 * 40e3, rel=1e-14)


def test_example_inelastic(driver, source_root, tmp_path):
    """input/winkler_inelastic.nml: SF = N_ult/W, chi = 1/SF; the imposed moment is the
    foundation moment less W h sin(theta), K_R = M_found/theta; the header says the
    coefficients are user-supplied."""
    proc = run_example(driver, source_root, tmp_path, "winkler_inelastic.nml")
    path = tmp_path / "out" / "winkler_inelastic.csv"
    assert header(path) == (["theta", "k_r", "m_found", "m_imposed", "force", "theta_ratio",
                             "g_corr", "force_ratio"],
                            ["rad", "N m/rad", "N m", "N m", "N", "-", "-", "-"])
    t = read_table(path)
    s = read_table(tmp_path / "out" / "winkler_inelastic_summary.csv")
    w = 100000.0 * G
    n_ult = (math.pi + 3) * 40e3 * math.pi * 4.0
    assert s["sf"][0] == pytest.approx(n_ult / w, rel=1e-14)
    assert s["chi"][0] == pytest.approx(w / n_ult, rel=1e-14)
    th = t["theta"][1:]
    np.testing.assert_allclose(t["m_found"][1:], t["k_r"][1:] * th, rtol=1e-12)
    np.testing.assert_allclose(t["m_imposed"], t["m_found"] - w * 4.0 * np.sin(t["theta"]),
                               rtol=1e-12, atol=1e-6)
    assert "USER-SUPPLIED" in path.with_suffix(".txt").read_text()
    assert "warning" not in proc.stderr


def test_example_history(driver, source_root, tmp_path):
    """input/winkler_history.nml: the summary row and 2001 history rows with every output
    column and its unit; the outcome is printed and named in the header."""
    proc = run_example(driver, source_root, tmp_path, "winkler_history.nml")
    s = read_table(tmp_path / "out" / "winkler_history_winkler.csv")
    path = tmp_path / "out" / "winkler_history.csv"
    names, units = header(path)
    assert names[:3] == ["t", "v", "theta"] and units[:3] == ["s", "m", "rad"]
    assert len(names) == 12 and "m/s2" in units and "J" in units and "N m" in units
    h = read_table(path)
    assert len(h["t"]) == 2001 and h["t"][0] == 0.0
    outcome = s["outcome"][0]
    # the example's stated result: uplift, then landings, back short of the static
    # overturning tilt
    assert outcome == "safe" and int(s["n_impacts"][0]) >= 1
    assert 0 < s["t_uplift"][0] < s["t_impact1"][0]
    assert s["theta_max"][0] < s["theta_overturn"][0] < s["theta_c"][0]
    assert f"winkler: {outcome}" in proc.stdout
    assert header(tmp_path / "out" / "winkler_history_winkler.csv")[0] == SUMMARY
    assert s["k"][0] == pytest.approx(circle_k(38.5e6, 0.3, 1.0), rel=1e-14)


def test_example_map(driver, source_root, tmp_path):
    """input/winkler_map.nml: 4 x 4 cells with the rigid map and the difference."""
    run_example(driver, source_root, tmp_path, "winkler_map.nml")
    path = tmp_path / "out" / "winkler_map.csv"
    names, _ = header(path)
    assert names == ["freq_hz", "pga", "freq_ratio", "amp_ratio", "class", "class_rigid",
                     "diff"]
    assert len(read_table(path)["class"]) == 16


# ---------------------------------------------------------------- histories and maps

def test_small_pulse_keeps_full_contact(driver, tmp_path):
    """A pulse far below uplift (0.01 g; uplift near 1/3 g x the static factor) leaves the
    base in full contact: outcome safe, no uplift, the contact width 2 r throughout and
    the settlement near the static W/(k pi r^2)."""
    out, proc = winkler(driver, tmp_path, f"what='history', {SOFT}, t_end=2.0, npts=201",
                        "&pulse kind='sine_cycle', amp=0.01, amp_unit='g', duration=1.0 /\n")
    s, h = out["winkler"], out["winkler_history"]
    assert s["outcome"][0] == "safe" and math.isnan(s["t_uplift"][0])
    assert "winkler: safe" in proc.stdout
    assert list(h) == ["t", "v", "theta", "v_rate", "theta_rate", "contact_width",
                       "normal_force", "moment", "ground_accel", "energy", "input_work",
                       "dissipated"]
    assert np.all(np.abs(h["contact_width"] - 2.0) < 1e-12)
    static = 47124.0 * G / (circle_k(2.0e6, 0.3, 1.0) * math.pi)
    assert h["v"][0] == pytest.approx(static, rel=1e-9)
    assert np.all(np.abs(h["v"] / static - 1) < 0.05)


@pytest.mark.parametrize("damping", ["xi=0.02", "xi=0.02, damping_ref='vertical'",
                                     "c=12345.0"])
def test_history_damping(driver, tmp_path, damping):
    """The dashpot of the summary: c = 2 xi I_O omega_r/I with omega_r^2 = (k I - m g h)/I_O,
    I_O = m (3 r^2 + 16 h^2)/12 about the base centre and I = pi r^4/4 (rocking), or
    c = 2 xi sqrt(k m/A), A = pi r^2 (vertical), or c as given."""
    out, _ = winkler(driver, tmp_path, f"what='history', {SOFT}, {damping}, t_end=1.0, "
                     "npts=11", "&pulse kind='half_sine', amp=0.05, amp_unit='g' /\n")
    m, r, h = 47124.0, 1.0, 3.0
    k = circle_k(2.0e6, 0.3, r)
    i_o, i_base = m * (3 * r**2 + 16 * h**2) / 12, math.pi * r**4 / 4
    if "vertical" in damping:
        c = 2 * 0.02 * math.sqrt(k * m / (math.pi * r**2))
    elif damping.startswith("xi"):
        c = 2 * 0.02 * i_o * math.sqrt((k * i_base - m * G * h) / i_o) / i_base
    else:
        c = 12345.0
    assert out["winkler"]["c"][0] == pytest.approx(c, rel=1e-12)
    assert out["winkler"]["k"][0] == pytest.approx(k, rel=1e-14)


@pytest.mark.parametrize("method, outcome", [("constant", "safe"), ("varying", "time_limit")])
def test_block_history_keeps_full_contact(driver, tmp_path, method, outcome):
    """A block (b = 0.5 m, alpha = 1 m, h = 1.5 m) under a pulse well below uplift: the
    contact width 2 b throughout and the static settlement W/(4 alpha b k) at t = 0; safe on
    constant k (the energy proof), a time limit at t_end on varying k (no proof there)."""
    out, proc = winkler(driver, tmp_path, "what='history', footing='block', b=0.5, alpha=1.0, "
                        f"h=1.5, mass=10000.0, k=5.0e7, k_method='{method}', t_end=2.0, "
                        "npts=101",
                        "&pulse kind='sine_cycle', amp=0.02, amp_unit='g', duration=1.0 /\n")
    h = out["winkler_history"]
    assert out["winkler"]["outcome"][0] == outcome
    assert f"winkler: {outcome}" in proc.stdout
    assert np.all(np.abs(h["contact_width"] - 1.0) < 1e-12)
    assert h["v"][0] == pytest.approx(10000.0 * G / (4 * 1.0 * 0.5 * 5.0e7), rel=1e-9)


def test_history_records(driver, source_root, tmp_path):
    """Two records of input/records: a summary row and the history rows of each, labelled."""
    rec = source_root / "input" / "records"
    out, _ = winkler(driver, tmp_path, f"what='history', {SOFT}, dt=0.05",
                     f"&records files='{rec / 'quake_a.AT2'}', '{rec / 'quake_b.csv'}', "
                     "target_pga=0.2 /\n")
    rows = (tmp_path / "w_winkler.csv").read_text().splitlines()
    assert rows[0].startswith("record (-),pga (g),k (N/m3)")
    assert [r.split(",")[0] for r in rows[1:]] == ['"quake_a"', '"quake_b"']
    assert all(float(r.split(",")[1]) == pytest.approx(0.2, rel=1e-12) for r in rows[1:])
    hist = (tmp_path / "w_winkler_history.csv").read_text().splitlines()
    assert hist[0].startswith("record (-),t (s),v (m)")
    assert {r.split(",")[0] for r in hist[1:]} == {'"quake_a"', '"quake_b"'}


def test_history_record_that_fails(driver, source_root, tmp_path):
    """A record that cannot be read: NaN rows for it, the other computed, exit status 1."""
    rec = source_root / "input" / "records"
    _, proc = winkler(driver, tmp_path, f"what='history', {SOFT}, dt=0.05",
                      f"&records files='{tmp_path / 'nope.AT2'}', '{rec / 'quake_a.AT2'}' /\n",
                      status=1)
    assert "1 of 2 records failed" in proc.stderr
    rows = (tmp_path / "w_winkler.csv").read_text().splitlines()[1:]
    assert math.isnan(float(rows[0].split(",")[2]))
    assert not math.isnan(float(rows[1].split(",")[2]))


def test_map_cells_and_rigid_comparison(driver, tmp_path):
    """A one-sine map at 1 Hz: 0.1 g (below the rigid uplift, tan(theta_c) = 1/3 g) must
    not overturn on either base, 1.5 g must overturn on both; the difference follows
    from the two classes (same, only_winkler, only_rigid, other_mode)."""
    out, _ = winkler(driver, tmp_path, f"what='map', {SOFT}",
                     "&map axes='dimensional', freq_hz=1.0, pga=0.1, 1.5, "
                     "compare_rigid=.true. /\n")
    m = out["winkler_map"]
    assert list(m["pga"]) == [0.1, 1.5]
    assert m["class"][0] == "safe" and m["class_rigid"][0] == "safe"
    assert m["class"][1] in OUTCOMES[1:4] and m["class_rigid"][1] in OUTCOMES[1:4]
    for cw, cr, d in zip(m["class"], m["class_rigid"], m["diff"]):
        cw, cr = OUTCOMES.index(cw), OUTCOMES.index(cr)
        expect = 0 if cw == cr else 1 if cr == 0 else 2 if cw == 0 else 3
        assert d == DIFFS[expect]
    # the dimensionless columns use the rigid p and theta_c
    tc = math.atan(1 / 3)
    assert m["amp_ratio"] == pytest.approx(m["pga"] / math.tan(tc), rel=1e-15)


def test_map_cells_equal_histories(driver, tmp_path):
    """Each cell of a map is the history of its own pulse: one-sine pulses of 2 s at 0.3 g
    and 0.6 g on the soil of the examples overturn (after one impact, and without one;
    on a rigid base 0.3 g does not even uplift the body: diff 1 there)."""
    body = "r=1.0, h=3.0, mass=47124.0, g_mod=38.5e6, nu=0.3"
    out, _ = winkler(driver, tmp_path, f"what='map', {body}",
                     "&map axes='dimensional', freq_hz=0.5, pga=0.3, 0.6, "
                     "compare_rigid=.true. /\n")
    m = out["winkler_map"]
    for i, amp in enumerate((0.3, 0.6)):
        hist, proc = winkler(driver, tmp_path, f"what='history', {body}",
                             f"&pulse kind='sine_cycle', amp={amp}, amp_unit='g', "
                             "duration=2.0 /\n", output=f"h{i}")
        outcome = hist["winkler"]["outcome"][0]
        assert outcome == m["class"][i] and outcome in OUTCOMES[1:4]
        assert f"winkler: {outcome}" in proc.stdout
    assert list(m["class_rigid"])[0] == "safe" and m["diff"][0] == "only_winkler"


def test_long_map_reports_progress(driver, tmp_path):
    """A map that runs for seconds prints "map: row i/n, N s elapsed, about M s left" on
    stderr every few seconds (not per row), and the last line says it is done."""
    start = time.monotonic()
    out, proc = winkler(driver, tmp_path, "what='map', r=1.0, h=3.0, mass=47124.0, "
                        "g_mod=38.5e6, nu=0.3",
                        "&map freq_range=0.5, 10.0, freq_count=24, amp_range=0.5, 4.0, "
                        "amp_count=24 /\n")
    wall = time.monotonic() - start
    lines = proc.stderr.strip().splitlines()
    for line in lines:
        assert re.fullmatch(r"map: row \d+/24(, \d+ s elapsed, about \d+ s left| \(done\))",
                            line), line
    assert len(lines) <= 2 + wall / 3
    if wall > 4.0:            # the map itself ran for more than 2 s
        assert len(lines) >= 2 and lines[-1] == "map: row 24/24 (done)"
    assert len(out["winkler_map"]["class"]) == 576


def test_map_without_comparison(driver, tmp_path):
    """compare_rigid = .false. (default): five columns, dimensionless axes first."""
    out, _ = winkler(driver, tmp_path, f"what='map', {SOFT}",
                     "&map freq_ratio=2.0, 4.0, amp_ratio=0.2 /\n")
    assert list(out["winkler_map"]) == ["freq_ratio", "amp_ratio", "freq_hz", "pga", "class"]


# ---------------------------------------------------------------- errors

ERRORS = [
    # (&winkler, extra groups, expected fragments)
    ("what='stress', r=1.0, h=2.0, mass=1.0, k=1e7", "",
     ["case.nml:2:", "&winkler", "what = 'stress'", "pushover, master, history, map, "
      "inelastic, capacity"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7, su=4e4", "",
     ["&winkler", "su: only with what = 'inelastic' or 'capacity' (now what = 'pushover')"]),
    ("what='capacity', r=1.0, mass=1.0, su=4e4, h=2.0", "",
     ["&winkler", "h: only with what = 'pushover', 'history', 'map' or 'inelastic'"]),
    ("footing='block', b=1.0, h=2.0, mass=1.0, k=1e7", "",
     ["&winkler", "alpha: missing"]),
    ("footing='block', r=1.0, h=2.0, mass=1.0, k=1e7", "",
     ["&winkler", "r: only with footing = 'circle'"]),
    ("footing='disc', r=1.0, h=2.0, mass=1.0, k=1e7", "",
     ["&winkler", "footing = 'disc'", "circle, block"]),
    ("r=1.0, h=2.0, mass=1.0, weight=9.8, k=1e7", "", ["&winkler", "mass, weight"]),
    ("r=1.0, h=2.0, k=1e7", "", ["&winkler", "mass: missing"]),
    ("r=1.0, h=2.0, mass=-3.0, k=1e7", "", ["&winkler", "mass = -3", "> 0 (kg)"]),
    ("r=1.0, h=2.0, mass=1.0", "", ["&winkler", "k: missing", "g_mod and nu"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7, g_mod=1e7, nu=0.3", "", ["&winkler", "k, g_mod"]),
    ("r=1.0, h=2.0, mass=1.0, g_mod=1e7", "", ["&winkler", "nu: missing"]),
    ("r=1.0, h=2.0, mass=1.0, k=-1e7", "", ["&winkler", "k = -1", "> 0 (N/m3"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7, k_method='linear'", "",
     ["&winkler", "k_method = 'linear'", "constant, varying"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7, reading='short'", "",
     ["&winkler", "reading: only with footing = 'circle' and k_method = 'varying'"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7, theta_max=2.0", "",
     ["&winkler", "theta_max = 2", "(0, pi/2]"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7, theta=0.1, 0.05", "",
     ["&winkler", "theta(2)", "ascending"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7, theta=0.1, theta_max=0.2", "",
     ["&winkler", "theta_max: not with theta"]),
    ("what='inelastic', footing='block', r=1.0, h=2.0, mass=1.0, su=4e4", "",
     ["&winkler", "footing = 'block'", "circular footing on clay"]),
    ("what='inelastic', r=1.0, h=2.0, mass=1.0, su=4e4", "", ["&winkler", "g_mod: missing"]),
    ("what='capacity', r=1.0, mass=1.0", "", ["&winkler", "su: missing"]),
    ("what='history', r=1.0, h=2.0, mass=1.0, k=1e7", "",
     ["&pulse: missing group", "what = 'history'"]),
    ("what='history', r=1.0, h=2.0, mass=1.0, k=1e7, c=1e3, xi=0.01",
     "&pulse kind='half_sine' /\n", ["&winkler", "c, xi"]),
    ("what='history', r=1.0, h=2.0, mass=1.0, k=1e7, damping_ref='horizontal'",
     "&pulse kind='half_sine' /\n", ["&winkler", "damping_ref = 'horizontal'",
                                     "rocking, vertical"]),
    ("what='history', r=1.0, h=2.0, mass=1.0, k=1e7, g=9.81",
     "&pulse kind='half_sine' /\n", ["&winkler", "g = 9.81", "not the g of &pulse"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7", "&pulse kind='half_sine' /\n",
     ["case.nml:3:", "&pulse", "only with what = 'history'"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7", "&map freq_ratio=1.0, amp_ratio=1.0 /\n",
     ["case.nml:3:", "&map", "only with what = 'map'"]),
    ("what='map', r=1.0, h=2.0, mass=1.0, k=1e7", "",
     ["&map: missing group"]),
    ("what='map', r=1.0, h=2.0, mass=1.0, k=1e7",
     "&map freq_ratio=1.0, amp_ratio=1.0, pga=0.3 /\n",
     ["case.nml:3:", "&map", "pga: only with axes = 'dimensional'"]),
    ("what='map', r=1.0, h=2.0, mass=1.0, k=1e7",
     "&map freq_ratio=1.0, amp_ratio=1.0, compare_block=.true. /\n",
     ["case.nml:3:", "&map", "compare_block: unknown key"]),
    ("what='map', r=1.0, h=2.0, mass=1.0, k=1e7, t_end=3.0",
     "&map freq_ratio=1.0, amp_ratio=1.0 /\n",
     ["&winkler", "t_end: only with what = 'history'"]),
    ("r=1.0, h=2.0, mass=1.0, k=1e7, rtol=1e-8", "",
     ["&winkler", "rtol: only with what = 'history' or 'map'"]),
]


@pytest.mark.parametrize("opts, extra, fragments", ERRORS)
def test_errors(driver, tmp_path, opts, extra, fragments):
    """One located line on stderr (file:line: &group: key: problem), exit 2, no table."""
    text = f"&run analysis='winkler', output='o' /\n&winkler {opts} /\n"
    proc = run(driver, tmp_path, text + extra)
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert lines[-1].startswith("seispulse: error: case.nml"), lines
    for fragment in fragments:
        assert fragment in lines[-1], (fragment, lines[-1])
    assert not list(tmp_path.glob("o_*"))


def test_missing_winkler_group(driver, tmp_path):
    proc = run(driver, tmp_path, "&run analysis='winkler', output='o' /\n")
    assert proc.returncode == 2
    assert "case.nml:1: &winkler: missing group" in proc.stderr
