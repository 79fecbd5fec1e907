"""Batch driver, analysis 'rocking': the examples under input/, the summary against
independent physics (the linearized closed forms of doc/rocking.md written out here with
numpy, and Housner's nonlinear equations integrated here with scipy), the history, the
overturning map against the stability wall and against summary runs of its cells, the
progress line of long maps, and the located one-line errors (exit 2, no output)."""
import math
import re
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest

from driver_tables import g_text, read_summary_txt, read_table, run_example
from driver_echo import echo_text

G = 9.80665
PI = "3.141592653589793"
SUMMARY = ["alpha", "p", "e", "f", "eta", "outcome", "t_uplift", "t_overturn", "n_impacts",
           "t_impact1", "theta_max", "theta_min", "psi_max", "psi_min", "t_end", "region",
           "t_up_cf", "t_c_cf", "t_m_cf", "psi_max_cf", "t_i_cf"]
UNITS = ["rad", "rad/s", "-", "-", "-", "-", "s", "s", "-", "s", "rad", "rad", "-", "-",
         "s", "-", "s", "s", "s", "-", "s"]
OUTCOMES = ["rest", "no_uplift", "overturn_no_impact", "overturn_one_impact",
            "overturn_many_impacts", "time_limit"]
REGIONS = ["no_rocking", "O1", "O2", "O3", "S1", "S2"]
#: map class of each outcome
CLASS_OF = {"rest": "safe", "no_uplift": "safe", "overturn_no_impact": "overturn_no_impact",
            "overturn_one_impact": "overturn_one_impact",
            "overturn_many_impacts": "overturn_many_impacts"}


def run(driver, cwd, text, name="case.nml"):
    (Path(cwd) / name).write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def rocking(driver, tmp_path, block, pulse=None, opts="", extra="", output="r"):
    """Run a rocking case; return its one table as {name: array} (scalars for a summary)."""
    text = f"&run analysis='rocking', output='{output}' /\n&block {block} /\n"
    if pulse is not None:
        text += f"&pulse {pulse} /\n"
    if opts:
        text += f"&rocking {opts} /\n"
    proc = run(driver, tmp_path, text + extra, name=f"{output}.nml")
    assert proc.returncode == 0, proc.stderr
    tables = sorted(tmp_path.glob(f"{output}_rocking*.csv"))
    assert len(tables) == 1, tables
    t = read_table(tables[0])
    if tables[0].name == f"{output}_rocking.csv":
        return {k: v[0] for k, v in t.items()}
    return t


# ---------------------------------------------------------------- independent physics

def rect_closed_forms(f, eta):
    """Linearized block, rectangular half-cycle pulse (doc/rocking.md (2.12), (2.17), (2.21),
    (2.25), (2.29), (2.33)), in t_d: region, tau_c, tau_m, psi_max, tau_i."""
    one = 1.0 / (1.0 - eta)
    r = dict(tau_c=math.nan, tau_m=math.nan, psi_max=math.inf, tau_i=math.nan)
    if math.cosh(f / 2) >= one:
        r["region"] = "O1"
    elif math.cosh(f) >= one:
        r["region"] = "O2"
    elif eta < 1 - math.exp(-f):                            # the wall, 2.21
        r["region"] = "O3"
    else:
        r["region"] = "S2"
    if r["region"] in ("O1", "O2"):
        r["tau_c"] = math.acosh(one) / f
    elif r["region"] == "O3":
        r["tau_c"] = math.log((math.exp(f) - 1 + eta) / (1 - eta - math.exp(-f))) / (2 * f)
    else:
        tm = math.log((1 - eta - math.exp(f)) / (1 - eta - math.exp(-f))) / (2 * f)  # 2.25
        r["tau_m"] = tm
        r["psi_max"] = (eta + (1 - eta) * math.cosh(f * tm) - math.cosh(f * (tm - 1))) / eta
        r["tau_i"] = math.log(((math.exp(-f) - 1) * math.sqrt(math.exp(f) * (1 - eta)) - eta)
                              / (1 - eta - math.exp(-f))) / f                        # 2.33
    return r


def rect_response(tau, f, eta):
    """psi, dpsi = (dtheta/dt)/(alpha p) of the rectangle, Eqs. 2.12 and 2.13."""
    tau = np.asarray(tau, float)
    after = tau > 1
    psi = (1 / eta - 1) * (np.cosh(f * tau) - 1) - after * (np.cosh(f * (tau - 1)) - 1) / eta
    dpsi = (1 / eta - 1) * np.sinh(f * tau) - after * np.sinh(f * (tau - 1)) / eta
    return psi, dpsi


def housner(alpha, p, e, g, ag, breaks, t_up, t_stop):
    """Housner's nonlinear rocking (doc/rocking.md section 1, Eqs. 2.5/2.6 with the + forcing) from
    uplift at t_up (theta > 0 first), integrated with scipy's DOP853 from event to event:
    impacts (theta = 0: the other corner, omega times e), outward crossings of
    |theta| = alpha, |theta| = pi/2 (overturned: stop). Independent of seispulse."""
    from scipy.integrate import solve_ivp
    s, t, y = 1.0, t_up, [0.0, 0.0]
    out = dict(t_impacts=[], t_cross=[], theta_max=0.0, theta_min=0.0, t_over=math.nan)
    pieces = sorted(set([b for b in breaks if b > t_up] + [t_stop]))
    while t < t_stop:
        def rhs(tt, yy):
            return [yy[1], -p * p * (math.sin(alpha * s - yy[0])
                                     - ag(tt) / g * math.cos(alpha * s - yy[0]))]

        def impact(tt, yy):
            return yy[0]
        impact.terminal, impact.direction = True, -s

        def cap(tt, yy):
            return abs(yy[0]) - math.pi / 2
        cap.terminal, cap.direction = True, 1

        def cross(tt, yy):
            return s * yy[0] - alpha
        cross.direction = 1

        def turn(tt, yy):
            return yy[1]

        t_next = min(b for b in pieces if b > t)
        sol = solve_ivp(rhs, (t, t_next), y, method="DOP853", rtol=1e-12, atol=1e-14,
                        events=[impact, cap, cross, turn])
        out["t_cross"] += list(sol.t_events[2])
        for ye in list(sol.y_events[3]) + [sol.y[:, -1]]:
            out["theta_max"] = max(out["theta_max"], ye[0])
            out["theta_min"] = min(out["theta_min"], ye[0])
        if sol.t_events[1].size:
            out["t_over"] = sol.t_events[1][0]
            out["theta_max" if s > 0 else "theta_min"] = s * math.pi / 2
            return out
        t, y = sol.t[-1], list(sol.y[:, -1])
        if sol.t_events[0].size:
            out["t_impacts"].append(t)
            s, y = -s, [0.0, e * y[1]]
    return out


def linearized_exponential(beta, f, eta):
    """First excursion of the linearized block under the half-cycle exponential pulse
    (doc/rocking.md section 1): psi'' = f^2 (psi + s(tau)/eta - 1) from rest at tau_up (Eq. 2.4),
    integrated with scipy. Returns tau_up, and tau_c (psi = 1) or tau_m, psi_max and
    tau_i (psi = 0)."""
    from scipy.integrate import solve_ivp
    if beta == 0:
        def shape(t):
            return 2 * min(t, 1 - t) if t <= 1 else 0.0
        tau_up = eta / 2
    else:
        c = -math.expm1(beta)

        def shape(t):
            return -math.expm1(2 * beta * min(t, 1 - t)) / c if t <= 1 else 0.0
        tau_up = math.log1p(-eta * c) / (2 * beta)

    def over(t, y):
        return y[0] - 1
    over.terminal, over.direction = True, 1

    def land(t, y):
        return y[0]
    land.terminal, land.direction = True, -1

    def top(t, y):
        return y[1]
    top.direction = -1
    out = dict(tau_up=tau_up)
    t, y = tau_up, [0.0, 0.0]
    for t1 in (0.5, 1.0, 60.0):
        if t1 <= t:
            continue
        sol = solve_ivp(lambda tt, yy: [yy[1], f * f * (yy[0] + shape(tt) / eta - 1)],
                        (t, t1), y, method="DOP853", rtol=1e-13, atol=1e-15,
                        events=[over, land, top])
        if sol.t_events[2].size:
            out["tau_m"], out["psi_max"] = sol.t_events[2][0], sol.y_events[2][0][0]
        if sol.t_events[0].size:
            out["tau_c"] = sol.t_events[0][0]
            return out
        if sol.t_events[1].size and sol.t_events[1][0] > tau_up + 1e-9:
            out["tau_i"] = sol.t_events[1][0]
            return out
        t, y = t1, list(sol.y[:, -1])
    raise AssertionError("no event")


def sine_cycle(amp, period):
    return lambda t: amp * math.sin(2 * math.pi * t / period) if 0 <= t <= period else 0.0


# ---------------------------------------------------------------- examples

def test_example_summary(driver, source_root, tmp_path):
    """input/rocking_block.nml: b = 0.2, h = 0.8 under a one-sine pulse of 0.5 g, 0.5 s:
    overturns after one impact; every number against scipy on Housner's equations."""
    proc = run_example(driver, source_root, tmp_path, "rocking_block.nml")
    assert "out/rocking_block_rocking.csv" in proc.stdout
    echo = echo_text(tmp_path, proc.stdout)
    assert "&block" in echo and "&rocking" in echo
    path = tmp_path / "out" / "rocking_block_rocking.csv"
    t = {k: v[0] for k, v in read_table(path).items()}
    # the text table: one `name  value  unit` line per column, the CSV's numbers to 6
    # significant digits, the outcome by name, the impacts as an integer
    txt = read_summary_txt(path.with_suffix(".txt"))
    assert list(txt) == SUMMARY
    assert [txt[c] for c in SUMMARY] == [(g_text(t[c]), u) for c, u in zip(SUMMARY, UNITS)]
    assert txt["outcome"][0] == "overturn_one_impact" and txt["n_impacts"][0] == "1"
    assert path.read_text().splitlines()[0] == ",".join(f"{c} ({u})"
                                                        for c, u in zip(SUMMARY, UNITS))
    # the block, doc/rocking.md sections 1, 6
    alpha, radius = math.atan(0.25), math.hypot(0.2, 0.8)
    p, e = math.sqrt(0.75 * G / radius), 1 - 1.5 * math.sin(alpha) ** 2
    assert math.isclose(t["alpha"], alpha, rel_tol=1e-15)
    assert math.isclose(t["p"], p, rel_tol=1e-15)
    assert math.isclose(t["e"], e, rel_tol=1e-15)
    # no closed forms for a sine cycle
    for c in ["f", "eta", "t_up_cf", "t_c_cf", "t_m_cf", "psi_max_cf", "t_i_cf"]:
        assert math.isnan(t[c]), c
    assert t["region"] == "nan"
    assert t["outcome"] == "overturn_one_impact"
    # uplift: 0.5 g sin(2 pi t/T) = g tan(alpha) -> t = T/12
    assert math.isclose(t["t_uplift"], 0.5 / 12, rel_tol=1e-12)
    ref = housner(alpha, p, e, G, sine_cycle(0.5 * G, 0.5), [0.5], t["t_uplift"], 20.0)
    assert t["n_impacts"] == len(ref["t_impacts"]) == 1
    assert math.isclose(t["t_impact1"], ref["t_impacts"][0], rel_tol=1e-9)
    assert math.isclose(t["theta_max"], ref["theta_max"], rel_tol=1e-8)
    assert t["theta_min"] == ref["theta_min"] == -math.pi / 2
    assert math.isclose(t["t_end"], ref["t_over"], rel_tol=1e-9)
    assert math.isclose(t["t_overturn"], ref["t_cross"][-1], rel_tol=1e-9)
    assert t["psi_max"] == t["theta_max"] / t["alpha"]
    assert t["psi_min"] == t["theta_min"] / t["alpha"]


def test_example_history(driver, source_root, tmp_path):
    """input/rocking_history.nml: the same case, t, a_g, theta, omega on 2001 points."""
    run_example(driver, source_root, tmp_path, "rocking_block.nml")
    s = {k: v[0] for k, v in read_table(tmp_path / "out" / "rocking_block_rocking.csv").items()}
    proc = run_example(driver, source_root, tmp_path, "rocking_history.nml")
    assert "out/rocking_history.csv" in proc.stdout
    path = tmp_path / "out" / "rocking_history.csv"
    h = read_table(path)
    assert path.read_text().splitlines()[0] == "t (s),a_g (m/s2),theta (rad),omega (rad/s)"
    # the text table: the CSV's numbers to 6 significant digits
    txt = [line.split() for line in path.with_suffix(".txt").read_text().splitlines()
           if not line.startswith("#")]
    np.testing.assert_array_equal(txt, np.vectorize(g_text)(
        np.column_stack([h[c] for c in ("t", "a_g", "theta", "omega")])))
    t = h["t"]
    assert len(t) == 2001 and t[0] == 0.0
    assert math.isclose(t[-1], 1.25 * s["t_end"], rel_tol=1e-14)
    a_ref = np.where(t <= 0.5, 0.5 * G * np.sin(2 * np.pi * t / 0.5), 0.0)
    np.testing.assert_allclose(h["a_g"], a_ref, rtol=0, atol=1e-14)
    # at rest before uplift, overturned (theta = -pi/2, omega = 0) after t_end
    assert np.all(h["theta"][t <= s["t_uplift"]] == 0.0)
    assert np.all(h["theta"][t > s["t_end"]] == -math.pi / 2)
    assert np.all(h["omega"][t > s["t_end"]] == 0.0)
    assert np.max(h["theta"]) <= s["theta_max"] and np.all(np.isfinite(h["theta"]))
    assert math.isclose(np.max(h["theta"]), s["theta_max"], rel_tol=2e-3)   # sampling
    # against scipy on Housner's equations, on the grid (first flight and the second)
    from scipy.integrate import solve_ivp
    alpha, p = s["alpha"], s["p"]
    ag = sine_cycle(0.5 * G, 0.5)

    def rhs(tt, yy):          # the first flight, about the corner of theta > 0
        return [yy[1], -p * p * (math.sin(alpha - yy[0])
                                 - ag(tt) / G * math.cos(alpha - yy[0]))]
    sel = (t > s["t_uplift"]) & (t <= s["t_impact1"])          # t_impact1 < 0.5 s
    sol = solve_ivp(rhs, (s["t_uplift"], t[sel][-1]), [0.0, 0.0], method="DOP853",
                    rtol=1e-12, atol=1e-14, t_eval=t[sel])
    np.testing.assert_allclose(h["theta"][sel], sol.y[0], rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(h["omega"][sel], sol.y[1], rtol=1e-8, atol=1e-11)


def test_example_map(driver, source_root, tmp_path):
    """input/rocking_map.nml: 39 x 31 cells of the one-sine family; the grids, the
    classes, and cells equal to summary runs of the same pulses."""
    proc = run_example(driver, source_root, tmp_path, "rocking_map.nml")
    assert "out/rocking_map.csv" in proc.stdout
    assert proc.stderr == "", "no progress line for a short map"
    path = tmp_path / "out" / "rocking_map.csv"
    m = read_table(path)
    assert path.read_text().splitlines()[0] == "freq_ratio (-),amp_ratio (-),class (-)"
    assert len(m["class"]) == 39 * 31
    freqs, amps = np.linspace(0.5, 10.0, 39), np.linspace(0.5, 8.0, 31)
    np.testing.assert_allclose(m["freq_ratio"], np.tile(freqs, 31), rtol=1e-15)
    np.testing.assert_allclose(m["amp_ratio"], np.repeat(amps, 39), rtol=1e-15)
    assert set(m["class"]) == {"safe", "overturn_no_impact", "overturn_one_impact"}
    # the example's own pulse lies between the columns 4.0 and 4.25 at amp_ratio 2.0
    for fr in (4.0, 4.25):
        cell = (np.abs(m["freq_ratio"] - fr) < 1e-12) & (np.abs(m["amp_ratio"] - 2.0) < 1e-12)
        assert m["class"][cell] == ["overturn_one_impact"]


def test_map_cells_equal_summary_runs(driver, tmp_path):
    """Every class of a map is the outcome of a summary run of the same pulse in SI
    (T = 2 pi/(freq_ratio p), a_p = amp_ratio g tan alpha)."""
    block = "b = 0.2, h = 0.8"
    freqs, amps = [1.0, 2.5, 4.0, 6.0, 9.0], [0.8, 1.5, 2.5, 4.0, 7.0]
    m = rocking(driver, tmp_path, block, opts="what = 'map'", output="map",
                extra=f"&map kind='sine_cycle', freq_ratio = {', '.join(map(str, freqs))}, "
                      f"amp_ratio = {', '.join(map(str, amps))} /\n")
    classes = m["class"].reshape(len(amps), len(freqs))
    assert len(set(classes.ravel())) >= 3
    alpha, p = math.atan(0.25), math.sqrt(0.75 * G / math.hypot(0.2, 0.8))
    for i, a in enumerate(amps):
        for j, fr in enumerate(freqs):
            s = rocking(driver, tmp_path, block,
                        f"kind='sine_cycle', amp={a * math.tan(alpha)!r}, amp_unit='g', "
                        f"duration={2 * math.pi / (fr * p)!r}", output=f"c{i}{j}")
            assert CLASS_OF[s["outcome"]] == classes[i, j], (fr, a)


def test_map_linearized_rectangle_is_the_wall(driver, tmp_path):
    """Linearized model, rectangular family: overturns (without impact) exactly below the
    stability wall eta < 1 - e^-f (doc/rocking.md (2.21)), f = 2 pi/freq_ratio,
    eta = alpha/(amp_ratio tan alpha)."""
    alpha = math.radians(8.0)
    m = rocking(driver, tmp_path, "alpha_deg = 8.0, model = 'linearized'",
                opts="what = 'map'", output="wall",
                extra="&map kind='rectangular', freq_range = 0.3, 12.0, freq_count = 40, "
                      "amp_range = 0.2, 4.0, amp_count = 39 /\n")
    f = 2 * np.pi / m["freq_ratio"]
    eta = alpha / (m["amp_ratio"] * math.tan(alpha))
    wall = 1 - np.exp(-f)
    clear = (np.abs(eta - wall) > 1e-6 * wall) & (np.abs(eta - 1) > 1e-6)
    assert np.sum(clear) > 0.95 * len(f)
    np.testing.assert_array_equal(m["class"][clear], np.where(eta < wall,
                                  "overturn_no_impact", "safe")[clear])


def test_long_map_reports_progress(driver, tmp_path):
    """A map that runs for seconds prints "map: row i/n" on stderr every few seconds
    (not per row), and the last line says it is done."""
    start = time.monotonic()
    proc = run(driver, tmp_path, "&run analysis='rocking', output='big' /\n"
                                 "&block b = 0.2, h = 0.8 /\n&rocking what='map', rtol=1e-14 /\n"
                                 "&map kind='sine_cycle', freq_range=0.5, 10, freq_count=400, "
                                 "amp_range=0, 8, amp_count=500 /\n")
    wall = time.monotonic() - start
    assert proc.returncode == 0, proc.stderr
    lines = proc.stderr.strip().splitlines()
    for line in lines:
        assert re.fullmatch(r"map: row \d+/500( \(done\))?", line), line
    assert len(lines) <= 2 + wall / 3
    if wall > 4.0:            # the map itself ran for more than 2 s
        assert len(lines) >= 2 and lines[-1] == "map: row 500/500 (done)"
    assert len(read_table(tmp_path / "big_rocking_map.csv")["class"]) == 200000


# ---------------------------------------------------------------- closed forms

RECT = [
    # (pulse, block): linearized model, e = 0, the rectangle in S2, O3, O2, O1
    ("kind='rectangular', amp=0.4, amp_unit='g', duration=0.3", "b=0.2, h=0.8"),
    ("kind='exponential', beta=-Inf, amp=0.4, amp_unit='g', duration=0.4", "b=0.2, h=0.8"),
    ("kind='rectangular', amp=3.5, duration=0.8", "alpha_deg=12, r=1.5"),
    ("kind='rectangular', amp=0.6, amp_unit='g', g=9.81, duration=1.5",
     "alpha=0.2, r=0.7, io_over_mr2=1.2"),
    ("kind='rectangular', amp=0.25, amp_unit='g', duration=0.15", "alpha=0.1, r=2.0"),
]


@pytest.mark.parametrize("pulse, block", RECT)
def test_linearized_rectangle_against_closed_forms(driver, tmp_path, pulse, block):
    """The driver's integrator run and its closed-form columns both equal doc/rocking.md
    2.12/2.17/2.21/2.25/2.29/2.33, written out above, to 1e-9."""
    s = rocking(driver, tmp_path, block + ", model='linearized', e=0.0", pulse,
                opts="rtol = 1e-14")
    amp_g = float(re.search(r"amp=([\d.]+)", pulse).group(1))
    g = 9.81 if "g=9.81" in pulse else G
    if "amp_unit" not in pulse:
        amp_g /= g
    td = float(re.search(r"duration=([\d.]+)", pulse).group(1))
    f, eta = s["p"] * td, s["alpha"] / amp_g
    assert math.isclose(s["f"], f, rel_tol=1e-15) and math.isclose(s["eta"], eta,
                                                                   rel_tol=1e-15)
    r = rect_closed_forms(f, eta)
    assert s["region"] == r["region"]
    assert s["t_uplift"] == 0.0 and s["t_up_cf"] == 0.0
    close = dict(rel_tol=1e-9, abs_tol=1e-12)
    if r["region"] == "S2":
        assert s["outcome"] == "rest" and s["n_impacts"] == 1
        for col, ref in [("t_m_cf", r["tau_m"] * td), ("psi_max_cf", r["psi_max"]),
                         ("psi_max", r["psi_max"]), ("t_i_cf", r["tau_i"] * td),
                         ("t_impact1", r["tau_i"] * td), ("t_end", r["tau_i"] * td)]:
            assert math.isclose(s[col], ref, **close), col
        assert math.isnan(s["t_overturn"]) and math.isnan(s["t_c_cf"])
        assert s["theta_min"] == 0.0            # e = 0: at rest after the impact
    else:
        assert s["outcome"] == "overturn_no_impact"
        for col in ("t_c_cf", "t_overturn"):
            assert math.isclose(s[col], r["tau_c"] * td, **close), col
        assert s["psi_max_cf"] == math.inf and s["theta_max"] == math.pi / 2
        assert s["n_impacts"] == 0 and math.isnan(s["t_impact1"])


EXPONENTIAL = [
    # (beta, f, eta): every region of the map (doc/rocking.md section 3) for several shapes
    (PI, 1.0, 0.15), (PI, 0.5, 0.379), (PI, 3.0, 0.7), (PI, 6.0, 0.1), (PI, 1.0, 0.1),
    ("-" + PI, 0.5, 0.5), ("-" + PI, 1.0, 0.9), ("-" + PI, 3.0, 0.6), ("-1.0", 1.0, 0.3),
    ("0.0", 1.0, 0.5), ("0.0", 3.0, 0.7), ("0.5", 3.0, 0.3), ("2.0", 4.0, 0.35),
    ("-6.0", 2.0, 0.45),
]


@pytest.mark.parametrize("beta, f, eta", EXPONENTIAL)
def test_linearized_exponential_integrator_equals_closed_forms(driver, tmp_path, beta, f,
                                                               eta):
    """Half-cycle exponential pulse, linearized model: the integrator's uplift, critical
    time, maximum and first impact equal the closed forms of seispulse_rocking_closed to 1e-9
    (two independent methods side by side in one row)."""
    p = math.sqrt(G)                               # r = 1, io_over_mr2 = 1
    td, amp = f / p, 0.1 / eta
    s = rocking(driver, tmp_path, "alpha=0.1, r=1.0, io_over_mr2=1.0, e=0.0, "
                "model='linearized'", f"beta={beta}, amp={amp!r}, amp_unit='g', "
                f"duration={td!r}", opts="rtol = 1e-14")
    assert math.isclose(s["f"], f, rel_tol=1e-14) and math.isclose(s["eta"], eta,
                                                                   rel_tol=1e-14)
    region = s["region"]
    close = dict(rel_tol=1e-9, abs_tol=1e-12)
    assert math.isclose(s["t_uplift"], s["t_up_cf"], **close)
    if region.startswith("O"):
        assert s["outcome"] == "overturn_no_impact"
        assert math.isclose(s["t_overturn"], s["t_c_cf"], **close)
    else:
        assert s["outcome"] == "rest"
        assert math.isclose(s["psi_max"], s["psi_max_cf"], **close)
        assert math.isclose(s["t_impact1"], s["t_i_cf"], **close)
        assert s["t_m_cf"] >= td * (1 - s["t_up_cf"] / td) - 1e-12      # Lemma 2.23
        assert (region == "S1") == (s["t_m_cf"] <= td)
    # independent: the linearized equation integrated with scipy (times in t_d)
    ref = linearized_exponential(float(beta), f, eta)
    assert math.isclose(s["t_up_cf"] / td, ref["tau_up"], rel_tol=1e-10, abs_tol=1e-13)
    if region.startswith("O"):
        assert math.isclose(s["t_c_cf"] / td, ref["tau_c"], rel_tol=1e-9)
    else:
        assert math.isclose(s["t_m_cf"] / td, ref["tau_m"], rel_tol=1e-8)
        assert math.isclose(s["psi_max_cf"], ref["psi_max"], rel_tol=1e-9)
        assert math.isclose(s["t_i_cf"] / td, ref["tau_i"], rel_tol=1e-9)
    # the oracle of doc/rocking.md section 3: tau_c in O3 at beta = pi, f = 1, eta = 0.15
    if (beta, f, eta) == (PI, 1.0, 0.15):
        assert region == "O3"
        assert math.isclose(s["t_c_cf"] / td, 1.4103182142, rel_tol=1e-9)
    # doc/rocking.md section 5 quotes tau_i "1.338" here (the corrected 2.32b/e; to ~3 digits)
    if (beta, f, eta) == (PI, 0.5, 0.379):
        assert abs(s["t_i_cf"] / td - 1.338) < 2e-3


def test_symmetric_triangle_is_beta_zero(driver, tmp_path):
    """kind 'triangular' with peak_frac = 0.5 gets the closed forms of beta = 0."""
    tri = rocking(driver, tmp_path, "b=0.2, h=0.8, model='linearized', e=0.0",
                  "kind='triangular', amp=0.5, amp_unit='g', duration=0.6",
                  opts="rtol=1e-14", output="tri")
    exp = rocking(driver, tmp_path, "b=0.2, h=0.8, model='linearized', e=0.0",
                  "kind='exponential', beta=0.0, amp=0.5, amp_unit='g', duration=0.6",
                  opts="rtol=1e-14", output="exp")
    for c in SUMMARY:
        if isinstance(tri[c], str):         # outcome, region: names
            assert tri[c] == exp[c], c
            continue
        assert math.isclose(tri[c], exp[c], rel_tol=1e-9) or \
            (math.isnan(tri[c]) and math.isnan(exp[c])), c
    skew = rocking(driver, tmp_path, "b=0.2, h=0.8, model='linearized', e=0.0",
                   "kind='triangular', amp=0.5, amp_unit='g', duration=0.6, peak_frac=0.3",
                   output="skew")
    assert skew["region"] == "nan" and math.isnan(skew["f"])


def test_history_linearized_rectangle(driver, tmp_path):
    """theta and omega of the history equal Eqs. 2.12, 2.13 up to the first impact, then
    rest (e = 0)."""
    block, pulse = "b=0.2, h=0.8, model='linearized', e=0.0", \
        "kind='rectangular', amp=0.4, amp_unit='g', duration=0.3"
    s = rocking(driver, tmp_path, block, pulse, opts="rtol=1e-14", output="s")
    h = rocking(driver, tmp_path, block, pulse, opts="what='history', rtol=1e-14, npts=777",
                output="h")
    t = h["t"]
    assert math.isclose(t[-1], 1.25 * s["t_end"], rel_tol=1e-14) and len(t) == 777
    f, eta, td = s["f"], s["eta"], 0.3
    psi, dpsi = rect_response(t / td, f, eta)
    before = t < s["t_impact1"]
    scale = s["theta_max"]
    np.testing.assert_allclose(h["theta"][before], s["alpha"] * psi[before], rtol=1e-9,
                               atol=1e-11 * scale)
    np.testing.assert_allclose(h["omega"][before], s["alpha"] * s["p"] * dpsi[before],
                               rtol=1e-9, atol=1e-11 * scale * s["p"])
    assert np.all(h["theta"][~before] == 0.0) and np.all(h["omega"][~before] == 0.0)
    np.testing.assert_array_equal(h["a_g"], np.where(t < 0.3, 0.4 * G, 0.0))


def test_history_dt_and_t_end(driver, tmp_path):
    h = rocking(driver, tmp_path, "b=0.15, h=0.6", "kind='half_sine', amp=0.4, "
                "amp_unit='g', duration=0.4", opts="what='history', t_end=3.0, dt=0.01")
    np.testing.assert_allclose(h["t"], np.arange(301) * 0.01, rtol=0, atol=1e-15)
    assert np.all(np.isfinite(h["theta"]))


# ---------------------------------------------------------------- options

def test_block_from_slenderness_and_size(driver, tmp_path):
    """alpha_deg with r and io_over_mr2: p = sqrt(g/(io R)), Housner's
    e = 1 - (2/io) sin^2(alpha); e given replaces it; g of &pulse is the block's g."""
    s = rocking(driver, tmp_path, "alpha_deg = 15, r = 1.2, io_over_mr2 = 1.5",
                "kind='half_sine', amp=0.1, amp_unit='g', g=9.81, duration=0.3")
    alpha = math.radians(15)
    assert math.isclose(s["alpha"], alpha, rel_tol=1e-15)
    assert math.isclose(s["p"], math.sqrt(9.81 / (1.5 * 1.2)), rel_tol=1e-15)
    assert math.isclose(s["e"], 1 - (2 / 1.5) * math.sin(alpha) ** 2, rel_tol=1e-15)
    assert s["outcome"] == "no_uplift"
    assert math.isnan(s["t_uplift"]) and s["t_end"] == 0.0 and s["theta_max"] == 0.0
    s = rocking(driver, tmp_path, "b = 0.3, h = 1.2, e = 0.8",
                "kind='half_sine', amp=0.1, amp_unit='g', duration=0.3", output="e")
    assert s["e"] == 0.8
    s = rocking(driver, tmp_path, "b = 0.3, h = 1.2, io_over_mr2 = 2.0",
                "kind='half_sine', amp=0.1, amp_unit='g', duration=0.3", output="io")
    assert math.isclose(s["p"], math.sqrt(G / (2.0 * math.hypot(0.3, 1.2))), rel_tol=1e-15)
    assert math.isclose(s["e"], 1 - math.sin(math.atan(0.25)) ** 2, rel_tol=1e-15)


def test_negative_pulse_mirrors_the_response(driver, tmp_path):
    """a_g -> -a_g gives theta -> -theta (the model is symmetric)."""
    pulse = "kind='sine_cycle', amp={}, amp_unit='g', duration=0.5"
    up = rocking(driver, tmp_path, "b=0.2, h=0.8", pulse.format(0.45), output="up")
    dn = rocking(driver, tmp_path, "b=0.2, h=0.8", pulse.format(-0.45), output="dn")
    assert up["outcome"] == dn["outcome"]
    for c in ("t_uplift", "n_impacts", "t_impact1", "t_end"):
        assert math.isclose(up[c], dn[c], rel_tol=1e-12), c
    assert math.isclose(up["theta_max"], -dn["theta_min"], rel_tol=1e-12)
    assert math.isclose(up["theta_min"], -dn["theta_max"], rel_tol=1e-12)


def test_t_max_and_elastic_impacts(driver, tmp_path):
    """e = 1: a safe block rocks for ever; t_max ends the run (outcome time_limit), and the
    history stops where the solution does."""
    block, pulse = "b=0.2, h=0.8, e=1.0", "kind='half_sine', amp=0.4, amp_unit='g', " \
        "duration=0.3"
    s = rocking(driver, tmp_path, block, pulse, opts="t_max = 6.0")
    assert s["outcome"] == "time_limit" and s["t_end"] == 6.0
    assert s["n_impacts"] > 3
    h = rocking(driver, tmp_path, block, pulse, opts="what='history', t_max = 6.0",
                output="h")
    assert math.isclose(h["t"][-1], 6.0, rel_tol=1e-15) and np.all(np.isfinite(h["theta"]))


def test_other_pulses_run(driver, tmp_path):
    for kind, extra in [("exponential", "duration=0.4, beta=-2.0, full=.true."),
                        ("cosine_cycle", "duration=0.6"), ("ricker", "freq=2.0"),
                        ("triangular", "duration=0.5, peak_frac=0.2")]:
        s = rocking(driver, tmp_path, "b=0.2, h=0.8", f"kind='{kind}', amp=0.5, "
                    f"amp_unit='g', {extra}", output=kind)
        assert s["outcome"] in OUTCOMES and s["region"] == "nan"
    s = rocking(driver, tmp_path, "b=0.2, h=0.8", "kind='mp', vamp=0.8, freq=1.5, "
                "gamma=2.5", output="mp")
    assert s["outcome"] in OUTCOMES and math.isnan(s["eta"])


def test_warnings(driver, tmp_path):
    proc = run(driver, tmp_path, "&run analysis='rocking', output='w' /\n"
                                 "&block alpha_deg = 10, r = 1.0 /\n&rocking what='map' /\n"
                                 "&map kind='sine_cycle', beta=1.0, freq_ratio=1.0, "
                                 "amp_ratio=2.0 /\n")
    assert proc.returncode == 0, proc.stderr
    assert "&block: r: not used by what = 'map'" in proc.stderr
    assert "&map: beta: not used by kind sine_cycle" in proc.stderr
    proc = run(driver, tmp_path, "&run analysis='rocking', output='w2' /\n"
                                 "&block b = 0.2, h = 0.8 /\n"
                                 "&pulse kind='half_sine', beta=1.0 /\n")
    assert proc.returncode == 0 and "beta: not used by kind half_sine" in proc.stderr


def test_python_api_agrees_if_available(driver, tmp_path):
    """The same library through seispulse.rocking (plumbing: units, block, pulse)."""
    try:
        from seispulse import pulse as sp_pulse
        from seispulse import rocking as sp_rocking
    except ImportError:
        pytest.skip("seispulse.rocking is not built")
    s = rocking(driver, tmp_path, "b=0.2, h=0.8", "kind='sine_cycle', amp=0.45, "
                "amp_unit='g', duration=0.5")
    blk = sp_rocking.rectangular_block(0.2, 0.8)
    r = sp_rocking.simulate(blk, sp_pulse.define("sine_cycle", amp=0.45 * G, period=0.5))
    assert s["outcome"] == r.outcome
    assert s["n_impacts"] == r.n_impacts
    for c, v in [("t_uplift", r.t_uplift), ("theta_max", r.theta_max),
                 ("theta_min", r.theta_min), ("t_end", r.t_end)]:
        assert math.isclose(s[c], v, rel_tol=1e-14), c


# ---------------------------------------------------------------- errors

HEAD = "&run analysis='rocking', output='o' /\n"
BLK = "&block b = 0.2, h = 0.8 /\n"
MAP = HEAD + BLK + "&rocking what='map' /\n"

BAD = [
    (HEAD + "&block b = -0.2, h = 0.8 /\n", ["case.nml:2:", "&block", "b = -0.2", "> 0"]),
    (HEAD + "&block b = 0.2, h = 0.0 /\n", ["case.nml:2:", "&block", "h = 0.0", "> 0"]),
    (HEAD + "&block b = nan, h = 0.8 /\n", ["&block", "b = NaN"]),
    (HEAD + "&block b = 0.2 /\n", ["&block", "h: missing"]),
    (HEAD + "&block h = 0.2 /\n", ["&block", "b: missing"]),
    (HEAD + "&block b = 0.2, h = 0.8, e = 1.5 /\n", ["&block", "e = 1.5", "[0, 1]"]),
    (HEAD + "&block b = 0.2, h = 0.8, e = -0.1 /\n", ["&block", "e = -0.1", "[0, 1]"]),
    (HEAD + "&block b = 0.2, h = 0.8, e = nan /\n", ["&block", "e = NaN", "[0, 1]"]),
    (HEAD + "&block alpha = 1.6, r = 1 /\n", ["&block", "alpha = 1.6", "(0, pi/2)"]),
    (HEAD + "&block alpha = nan, r = 1 /\n", ["&block", "alpha = NaN"]),
    (HEAD + "&block alpha_deg = 90, r = 1 /\n", ["&block", "alpha_deg = 90.0", "(0, 90)"]),
    (HEAD + "&block alpha_deg = -5, r = 1 /\n", ["&block", "alpha_deg = -5.0"]),
    (HEAD + "&block alpha = 0.2 /\n", ["&block", "r: missing"]),
    (HEAD + "&block alpha = 0.2, r = 0 /\n", ["&block", "r = 0.0", "> 0"]),
    (HEAD + "&block alpha = 0.2, alpha_deg = 10, r = 1 /\n",
     ["&block", "alpha, alpha_deg", "only one"]),
    (HEAD + "&block b = 0.2, h = 0.8, alpha = 0.2 /\n", ["&block", "b, h", "not with alpha"]),
    (HEAD + "&block b = 0.2, h = 0.8, r = 1 /\n", ["&block", "r: not with b and h"]),
    (HEAD + "&block alpha = 0.2, r = 1, io_over_mr2 = 0.9 /\n",
     ["&block", "io_over_mr2 = 0.9", ">= 1"]),
    (HEAD + "&block r = 1 /\n", ["&block", "b, h: missing"]),
    (HEAD + "&block b = 0.2, h = 0.8, model = 'exact' /\n",
     ["&block", "model = 'exact'", "allowed: nonlinear, linearized"]),
    (HEAD + "&block b = 0.2, h = 0.8, mu = 0.5 /\n",
     ["case.nml:2:", "&block", "mu", "unknown key"]),
    (HEAD + "&block b = 0.2, h = abc /\n", ["&block", "h", "bad value"]),
    (HEAD, ["&block", "missing group"]),
    (HEAD + BLK + "&rocking what = 'plot' /\n",
     ["case.nml:3:", "&rocking", "what = 'plot'", "allowed: summary, history, map"]),
    (HEAD + BLK + "&rocking t_max = 0 /\n", ["&rocking", "t_max = 0.0", "> 0"]),
    (HEAD + BLK + "&rocking t_max = nan /\n", ["&rocking", "t_max = NaN"]),
    (HEAD + BLK + "&rocking rtol = 0.1 /\n", ["&rocking", "rtol = 0.1", "[1e-14, 1e-3]"]),
    (HEAD + BLK + "&rocking npts = 11 /\n", ["&rocking", "npts", "only with what = 'history'"]),
    (HEAD + BLK + "&rocking what = 'history', dt = 0.1, npts = 5 /\n",
     ["&rocking", "dt, npts", "one of them"]),
    (HEAD + BLK + "&rocking what = 'history', npts = 1 /\n", ["&rocking", "npts", "2 .. "]),
    (HEAD + BLK + "&rocking what = 'history', t_end = -1 /\n",
     ["&rocking", "t_end = -1.0", "> 0"]),
    (HEAD + BLK + "&rocking what = 'history', dt = 0 /\n", ["&rocking", "dt = 0.0", "> 0"]),
    (HEAD + BLK + "&pulse duration = -1 /\n",
     ["case.nml:3:", "&pulse", "duration = -1.0", "> 0"]),
    (HEAD + BLK + "&pulse g = 0 /\n", ["&pulse", "g:", "> 0"]),
    (HEAD + BLK + "&pulse kind = 'mp', gamma = 2e6 /\n",
     ["case.nml:3:", "&pulse", "gamma = 2000000.0", "integrator"]),
    (HEAD + BLK + "&map freq_ratio = 1, amp_ratio = 1 /\n",
     ["case.nml:3:", "&map", "only with what = 'map'"]),
    (HEAD + BLK + "&time t_end = 1 /\n",
     ["case.nml:3:", "&time", "not a group of analysis 'rocking'"]),
    (HEAD + BLK + "&method solver = 'closed' /\n", ["&method", "not a group"]),
    (MAP, ["&map", "missing group"]),
    (MAP + "&pulse amp = 1 /\n&map freq_ratio = 1, amp_ratio = 1 /\n",
     ["case.nml:4:", "&pulse", "not used by what = 'map'"]),
    (MAP + "&map amp_ratio = 1 /\n", ["case.nml:4:", "&map", "freq_ratio: missing"]),
    (MAP + "&map freq_ratio = 1 /\n", ["&map", "amp_ratio: missing"]),
    (MAP + "&map freq_ratio = 1, 0, amp_ratio = 1 /\n", ["&map", "freq_ratio(2) = 0.0", "> 0"]),
    (MAP + "&map freq_ratio = 1, amp_ratio = -1 /\n", ["&map", "amp_ratio(1) = -1.0", ">= 0"]),
    (MAP + "&map freq_ratio = 1, amp_ratio = 1, , 2 /\n", ["&map", "amp_ratio(2)", "missing"]),
    (MAP + "&map freq_ratio = 1, freq_range = 1, 2, amp_ratio = 1 /\n",
     ["&map", "freq_ratio, freq_range", "only one"]),
    (MAP + "&map freq_range = 2, 1, amp_ratio = 1 /\n", ["&map", "freq_range", "above"]),
    (MAP + "&map freq_range = 0, 1, amp_ratio = 1 /\n", ["&map", "freq_range(1) = 0.0"]),
    (MAP + "&map freq_range = 1, 2, freq_count = 1, amp_ratio = 1 /\n",
     ["&map", "freq_count = 1", "2 .. 1000"]),
    (MAP + "&map freq_ratio = 1, amp_ratio = 1, amp_count = 3 /\n",
     ["&map", "amp_count", "only with amp_range"]),
    (MAP + "&map kind = 'mp', freq_ratio = 1, amp_ratio = 1 /\n",
     ["&map", "kind = 'mp'", "time scale"]),
    (MAP + "&map kind = 'wave', freq_ratio = 1, amp_ratio = 1 /\n",
     ["&map", "kind = 'wave'", "unknown pulse"]),
    (MAP + "&map beta = nan, freq_ratio = 1, amp_ratio = 1 /\n", ["&map", "beta = NaN"]),
    (MAP + "&map kind = 'triangular', peak_frac = 1.5, freq_ratio = 1, amp_ratio = 1 /\n",
     ["&map", "peak_frac = 1.5"]),
    (MAP + "&map kind = 'ricker', t0_periods = -1, freq_ratio = 1, amp_ratio = 1 /\n",
     ["&map", "t0_periods = -1.0", ">= 0"]),
    (MAP + "&map freq_ratio = 1, 1e-320, amp_ratio = 1 /\n",
     ["&map", "freq_ratio(2)", "no valid pulse"]),
    (HEAD + BLK + "&rocking what = 'map', t_max = 3 /\n&map freq_ratio = 1, amp_ratio = 1 /\n",
     ["&rocking", "t_max: not with what = 'map'"]),
    ("&run analysis='sliding', output='o' /\n&block mu = 0.3 /\n&map freq_ratio = 1 /\n",
     ["case.nml:3:", "&map", "not a group of analysis 'sliding'"]),
    ("&run analysis='rockin', output='o' /\n" + BLK,
     ["&run", "analysis = 'rockin'", "pulse, sliding, rocking"]),
]


@pytest.mark.parametrize("text, words", BAD)
def test_bad_input_one_line_exit_2_no_output(driver, tmp_path, text, words):
    proc = run(driver, tmp_path, text)
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    lines = [x for x in proc.stderr.strip().splitlines() if not x.startswith("warning:")]
    assert len(lines) == 1, proc.stderr
    for word in words:
        assert word in lines[0], lines[0]
    assert lines[0].startswith("seispulse: error: case.nml")
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml"], "no output left behind"


def test_unwritable_output_leaves_nothing(driver, tmp_path):
    (tmp_path / "o_rocking.txt").mkdir()           # a directory where a file must go
    proc = run(driver, tmp_path, HEAD + BLK)
    assert proc.returncode == 2
    assert "&run: output" in proc.stderr and len(proc.stderr.strip().splitlines()) == 1
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml", "o_rocking.txt"]


# ---------------------------------------------------------------- vertical acceleration

def test_kv_zero_is_the_plain_run(driver, tmp_path):
    """kv = 0 given: the same echo and the same table, byte for byte."""
    pulse = "kind='sine_cycle', amp=0.5, amp_unit='g', duration=0.5"
    outs = []
    for name, opts in (("a", "what = 'summary'"), ("b", "what = 'summary', kv = 0")):
        text = ("&run analysis='rocking', output='o' /\n&block b = 0.2, h = 0.8 /\n"
                f"&pulse {pulse} /\n&rocking {opts} /\n")
        (tmp_path / name).mkdir()
        proc = run(driver, tmp_path / name, text)
        assert proc.returncode == 0, proc.stderr
        outs.append((proc.stdout, (tmp_path / name / "o_rocking.csv").read_text()))
    assert outs[0] == outs[1]
    assert "KV" not in outs[0][0].upper()


def test_kv_summary_against_scipy(driver, tmp_path):
    """kv = 0.3 under the example's one-sine pulse: the uplift where
    0.5 g sin(w t) = g tan(alpha)/(1 - kv tan(alpha)) (doc/rocking.md section 7), the first
    impact by scipy on theta'' = -p^2 [(1 + kv a_g/g) sin(alpha - theta)
    - (a_g/g) cos(alpha - theta)] written here."""
    from scipy.integrate import solve_ivp
    kv, amp, period = 0.3, 0.5 * G, 0.5
    s = rocking(driver, tmp_path, "b = 0.2, h = 0.8",
                f"kind='sine_cycle', amp=0.5, amp_unit='g', duration={period}",
                opts=f"kv = {kv}")
    alpha = math.atan(0.25)
    p = math.sqrt(0.75 * G / math.hypot(0.2, 0.8))
    w = 2 * math.pi / period
    t_up = math.asin(math.tan(alpha) / (1 - kv * math.tan(alpha)) * G / amp) / w
    assert math.isclose(s["t_uplift"], t_up, rel_tol=1e-12)
    assert math.isnan(s["t_up_cf"])
    ag = sine_cycle(amp, period)

    def rhs(t, y):
        a = ag(t) / G
        return [y[1], -p * p * ((1 + kv * a) * math.sin(alpha - y[0])
                                - a * math.cos(alpha - y[0]))]

    hit = lambda t, y: y[0]
    hit.terminal, hit.direction = True, -1
    y, t_hit = [0.0, 0.0], None
    for ta, tb in ((t_up, period), (period, 20.0)):      # a_g has a kink at the end
        sol = solve_ivp(rhs, (ta, tb), y, method="DOP853", rtol=1e-12, atol=1e-14,
                        events=hit)
        if sol.t_events[0].size:
            t_hit = sol.t_events[0][0]
            break
        y = list(sol.y[:, -1])
    assert s["n_impacts"] >= 1 and t_hit is not None
    assert math.isclose(s["t_impact1"], t_hit, rel_tol=1e-9)


def test_kv_map_cells_equal_summary_runs(driver, tmp_path):
    block, kv = "b = 0.2, h = 0.8", 0.6
    freqs, amps = [1.0, 4.0, 9.0], [1.2, 2.5, 4.0]
    m = rocking(driver, tmp_path, block, opts=f"what = 'map', kv = {kv}", output="map",
                extra=f"&map kind='sine_cycle', freq_ratio = {', '.join(map(str, freqs))}, "
                      f"amp_ratio = {', '.join(map(str, amps))} /\n")
    classes = m["class"].reshape(len(amps), len(freqs))
    header = (tmp_path / "map_rocking_map.txt").read_text()
    assert "kv = 0.6" in header
    alpha, p = math.atan(0.25), math.sqrt(0.75 * G / math.hypot(0.2, 0.8))
    for i, a in enumerate(amps):
        for j, fr in enumerate(freqs):
            s = rocking(driver, tmp_path, block,
                        f"kind='sine_cycle', amp={a * math.tan(alpha)!r}, amp_unit='g', "
                        f"duration={2 * math.pi / (fr * p)!r}", opts=f"kv = {kv}",
                        output=f"c{i}{j}")
            assert CLASS_OF[s["outcome"]] == classes[i, j], (fr, a)


KV_BAD = [
    (HEAD + BLK + "&pulse kind='sine_cycle', amp=0.5, amp_unit='g', duration=0.5 /\n"
     "&rocking kv = nan /\n", ["case.nml:4:", "&rocking", "kv = NaN", "finite"]),
    (HEAD + BLK + "&pulse kind='sine_cycle', amp=0.5, amp_unit='g', duration=0.5 /\n"
     "&rocking kv = 2.5 /\n", ["case.nml:4:", "&rocking", "kv = 2.5", "below -g"]),
    (MAP.replace("what='map'", "what='map', kv = 2") + "&map kind='sine_cycle', "
     "freq_ratio = 1, amp_ratio = 1, 3 /\n", ["case.nml:3:", "&rocking", "kv = 2.0",
                                              "amp_ratio = 3.0", "below -g"]),
]


@pytest.mark.parametrize("text, words", KV_BAD)
def test_kv_bad_input_one_line_exit_2_no_output(driver, tmp_path, text, words):
    test_bad_input_one_line_exit_2_no_output(driver, tmp_path, text, words)
