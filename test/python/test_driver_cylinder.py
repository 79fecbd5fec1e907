"""Batch driver, analysis 'cylinder': the examples under input/ and their documented
tables; the body's properties and pushover against the formulas written out here; the
planar rocking history against Housner's nonlinear equations integrated here with scipy
(test_driver_rocking.housner) and, through the library's own block equivalence (a body
with J_o = 4/3 m R^2 is the uniform block), against seispulse.rocking; maps on both axis
systems and the block comparison; histories on records; and the located one-line errors
(exit 2, nothing written)."""
import math
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

from driver_tables import read_table, run_example

G = 9.80665
OUTCOMES = ["rest", "no_uplift", "overturn_no_impact", "overturn_one_impact",
            "overturn_many_impacts", "time_limit"]
SUMMARY = ["theta_c", "p", "e", "outcome", "t_uplift", "t_overturn", "n_impacts",
           "t_impact1", "theta_max", "theta_min", "psi_max", "psi_min", "t_end"]
SUMMARY_UNITS = ["rad", "rad/s", "-", "-", "s", "s", "-", "s", "rad", "rad", "-", "-", "s"]
CLASSES = ["safe", "overturn_no_impact", "overturn_one_impact",
           "overturn_many_impacts"]
DIFFS = ["same", "only_cylinder", "only_block", "other_mode"]
PROPS_LABELS = ["shape (-)", "r (m)", "r_inner (m)", "h (m)", "mass (kg)", "g (m/s2)",
                "theta_c (rad)", "theta_c (deg)", "h/r (-)", "R (m)", "J_o (kg m2)",
                "J_G (kg m2)", "J_axis (kg m2)", "J_o/(m R2) (-)", "p (rad/s)", "e (-)",
                "W (N)", "M_max (N m)", "F_uplift (N)", "tan(theta_c) (g)"]


def run(driver, cwd, text, name="case.nml"):
    (Path(cwd) / name).write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def codes(names, table=CLASSES):
    """The library's codes of a column of names (undecided: -1)."""
    return np.array([-1 if x == "undecided" else table.index(x) for x in names])


def cylinder(driver, tmp_path, body, opts, extra="", output="c", status=0):
    """Run a case; return {table suffix: {column: array}} of every table it wrote."""
    text = (f"&run analysis='cylinder', output='{output}' /\n&body {body} /\n"
            f"&cylinder {opts} /\n{extra}")
    proc = run(driver, tmp_path, text, name=f"{output}.nml")
    assert proc.returncode == status, proc.stderr
    out = {}
    for path in sorted(tmp_path.glob(f"{output}_cylinder*.csv")):
        out[path.stem[len(output) + 1:]] = read_table(path)
    return out


def header(path):
    """(names, units) of a CSV table."""
    first = Path(path).read_text().splitlines()[0].split(",")
    return [c.rsplit(" (", 1)[0] for c in first], [c.rsplit(" (", 1)[1][:-1] for c in first]


def props_table(path):
    """{label: (body, equivalent)} of a properties table."""
    rows = Path(path).read_text().splitlines()[1:]
    out = {}
    for row in rows:
        label, rest = row[1:].split('",', 1)
        out[label] = tuple(float(x) for x in rest.split(","))
    return out


def solid(r, h, m=1.0, g=G):
    """Solid cylinder written out: J_G = m (3 r^2 + 4 h^2)/12 about a transverse diameter
    (h: half-height), J_o = J_G + m R^2, p = sqrt(m g R/J_o), Housner's e."""
    big_r = math.hypot(r, h)
    j_o = m * (3 * r * r + 4 * h * h) / 12 + m * big_r**2
    tc = math.atan2(r, h)
    return dict(theta_c=tc, R=big_r, J_o=j_o, p=math.sqrt(m * g * big_r / j_o),
                e=max(0.0, 1 - 2 * m * big_r**2 / j_o * math.sin(tc)**2),
                io_over_mr2=j_o / (m * big_r**2))


# ---------------------------------------------------------------- the examples

def test_example_props(driver, source_root, tmp_path):
    """input/cylinder_props.nml: r = 1, h = 3, 45 t and the numbers of its comments."""
    run_example(driver, source_root, tmp_path, "cylinder_props.nml")
    path = tmp_path / "out" / "cylinder_props.csv"
    assert header(path) == (["quantity", "body", "equivalent"],
                            ["in name", "as named", "as named"])
    t = props_table(path)
    assert list(t) == PROPS_LABELS
    ref = solid(1.0, 3.0, 45000.0)
    assert t["theta_c (rad)"][0] == pytest.approx(ref["theta_c"], rel=1e-15)
    assert t["J_o (kg m2)"][0] == pytest.approx(596250.0, rel=1e-14)
    assert t["p (rad/s)"] == pytest.approx((ref["p"], ref["p"]), rel=1e-14)
    assert t["e (-)"] == pytest.approx((0.8490566037735849, 0.85), rel=1e-14)
    assert t["M_max (N m)"] == pytest.approx((45000 * G, 45000 * G), rel=1e-14)
    assert t["F_uplift (N)"][0] == pytest.approx(45000 * G / 3, rel=1e-14)
    assert t["tan(theta_c) (g)"] == pytest.approx((1 / 3, 1 / 3), rel=1e-14)
    assert t["J_o/(m R2) (-)"] == pytest.approx((1.325, 4 / 3), rel=1e-14)
    assert t["shape (-)"] == (1.0, 4.0)
    assert math.isnan(t["J_axis (kg m2)"][1])
    # the equivalent block: R_b = 3 g/(4 p^2), b = R_b sin(theta_c), m_b = m r/b
    r_b = 3 * G / (4 * ref["p"]**2)
    assert t["R (m)"][1] == pytest.approx(r_b, rel=1e-14)
    assert t["r (m)"][1] == pytest.approx(0.99375, rel=1e-12)
    assert t["mass (kg)"][1] == pytest.approx(45000 / 0.99375, rel=1e-12)


def test_example_pushover(driver, source_root, tmp_path):
    """input/cylinder_pushover.nml: theta/theta_c = 0 .. 1.2 in 25 values; F, M, M/(m g r)
    and the stable flag against the formulas."""
    run_example(driver, source_root, tmp_path, "cylinder_pushover.nml")
    path = tmp_path / "out" / "cylinder_pushover.csv"
    assert header(path) == (["theta", "theta_ratio", "force", "moment", "m_ratio", "stable"],
                            ["rad", "-", "N", "N m", "-", "-"])
    t = read_table(path)
    u = t["theta_ratio"]
    assert u == pytest.approx(np.linspace(0, 1.2, 25), abs=1e-15)
    tc, w = math.atan(1 / 3), 45000 * G
    th = u * tc
    assert t["theta"] == pytest.approx(th, rel=1e-15)
    np.testing.assert_allclose(t["force"], w * np.tan(tc - th), rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(t["moment"], w * (np.cos(th) - 3 * np.sin(th)), rtol=1e-12,
                               atol=1e-9)
    np.testing.assert_allclose(t["m_ratio"], t["moment"] / w, rtol=1e-12, atol=1e-15)
    assert list(t["stable"]) == [1.0 if x <= 1 else 0.0 for x in u]
    assert t["force"][0] == pytest.approx(w / 3, rel=1e-15)


def test_example_history(driver, source_root, tmp_path):
    """input/cylinder_history.nml: r = 1, h = 3 under one sine cycle of 0.8 g, 1 s:
    overturns after one impact, as Housner's equations with the cylinder's p integrated
    here with scipy say (uplift, impact, overturning times)."""
    from test_driver_rocking import housner
    proc = run_example(driver, source_root, tmp_path, "cylinder_history.nml")
    assert "cylinder: overturn_one_impact" in proc.stdout
    out = tmp_path / "out"
    s_path = out / "cylinder_history_cylinder.csv"
    h_path = out / "cylinder_history.csv"
    assert header(s_path) == (SUMMARY, SUMMARY_UNITS)
    assert header(h_path) == (["t", "a_g", "theta", "omega"], ["s", "m/s2", "rad", "rad/s"])
    s = {k: v[0] for k, v in read_table(s_path).items()}
    ref = solid(1.0, 3.0)
    assert s["outcome"] == "overturn_one_impact"
    # the one-row summary: name, value, unit lines in the text table
    assert re.search(r"^outcome +overturn_one_impact +-$", s_path.with_suffix(".txt")
                     .read_text(), re.MULTILINE)
    t_up = math.asin(1 / (3 * 0.8)) / (2 * math.pi)
    assert s["t_uplift"] == pytest.approx(t_up, rel=1e-12)

    def ag(t):
        return 0.8 * G * math.sin(2 * math.pi * t) if t <= 1.0 else 0.0
    h = housner(ref["theta_c"], ref["p"], ref["e"], G, ag, [0.5, 1.0], t_up, 10.0)
    assert s["n_impacts"] == len(h["t_impacts"]) == 1
    assert s["t_impact1"] == pytest.approx(h["t_impacts"][0], rel=1e-8)
    assert s["t_end"] == pytest.approx(h["t_over"], rel=1e-8)
    assert s["t_overturn"] == pytest.approx(h["t_cross"][-1], rel=1e-8)
    assert s["theta_max"] == pytest.approx(h["theta_max"], rel=1e-8)
    assert s["theta_min"] == -math.pi / 2
    assert s["p"] == pytest.approx(ref["p"], rel=1e-14)
    hist = read_table(h_path)
    assert len(hist["t"]) == 2001
    assert hist["t"][-1] == pytest.approx(1.25 * s["t_end"], rel=1e-12)
    assert hist["theta"][-1] == -math.pi / 2
    assert hist["a_g"] == pytest.approx([ag(t) for t in hist["t"]], abs=1e-12)


def test_example_records(driver, source_root, tmp_path):
    """input/cylinder_records.nml: two records scaled to 0.5 g, one summary row each and
    the history rows of each record (label column 'record')."""
    run_example(driver, source_root, tmp_path, "cylinder_records.nml")
    out = tmp_path / "out"
    names, units = header(out / "cylinder_records_cylinder.csv")
    assert names == ["record", "pga"] + SUMMARY and units == ["-", "g"] + SUMMARY_UNITS
    rows = (out / "cylinder_records_cylinder.csv").read_text().splitlines()[1:]
    assert [r.split(",")[0] for r in rows] == ['"quake_a"', '"quake_b"']
    assert [float(r.split(",")[1]) for r in rows] == pytest.approx([0.5, 0.5], rel=1e-12)
    assert all(float(r.split(",")[4]) == 0.8 for r in rows)         # e given
    s = read_table(out / "cylinder_records_cylinder.csv")
    assert set(s["outcome"]) <= set(OUTCOMES)
    assert all(re.fullmatch(r"[0-9]+", r.split(",")[8]) for r in rows)  # n_impacts: integers
    names, units = header(out / "cylinder_records_cylinder_history.csv")
    assert names == ["record", "t", "a_g", "theta", "omega"]
    assert units == ["-", "s", "m/s2", "rad", "rad/s"]


def test_example_map(driver, source_root, tmp_path):
    """input/cylinder_map.nml: 12 x 12 cells on the dimensional axes with the block's map;
    the pulse of input/cylinder_history.nml (1 Hz, 0.8 g) is class 2 in both."""
    run_example(driver, source_root, tmp_path, "cylinder_map.nml")
    path = tmp_path / "out" / "cylinder_map.csv"
    assert header(path) == (["freq_hz", "pga", "freq_ratio", "amp_ratio", "class",
                             "class_block", "diff"], ["Hz", "g", "-", "-", "-", "-", "-"])
    t = read_table(path)
    assert len(t["class"]) == 144
    cell = (np.abs(t["freq_hz"] - 1.0) < 1e-12) & (np.abs(t["pga"] - 0.8) < 1e-12)
    assert t["class"][cell] == ["overturn_one_impact"]
    assert t["class_block"][cell] == ["overturn_one_impact"]
    ref = solid(1.0, 3.0)
    np.testing.assert_allclose(t["freq_ratio"], 2 * np.pi * t["freq_hz"] / ref["p"],
                               rtol=1e-14)
    np.testing.assert_allclose(t["amp_ratio"], t["pga"] * 3, rtol=1e-14)
    assert set(CLASSES[:3]) <= set(t["class"])


# ---------------------------------------------------------------- against the library

def test_custom_block_inertia_gives_the_block(driver, tmp_path):
    """A body with J_o = 4/3 m R^2 is the uniform block of half-width r: its history
    (summary and theta(t), omega(t)) is seispulse.rocking's for rectangular_block(r, h),
    and shape = 'block' gives the same numbers."""
    from seispulse import pulse as sp_pulse
    from seispulse import rocking as sp_rocking
    r, h, m = 0.3, 1.1, 7.0
    j_o = 4 / 3 * m * (r * r + h * h)
    pul = "&pulse kind='half_sine', amp=0.45, amp_unit='g', duration=0.6 /\n"
    opts = "what='history', t_end=4.0, npts=81"
    a = cylinder(driver, tmp_path, f"shape='custom', r={r}, h={h}, mass={m}, j_o={j_o!r}",
                 opts, pul, output="a")
    b = cylinder(driver, tmp_path, f"shape='block', b={r}, h={h}", opts, pul, output="b")
    blk = sp_rocking.rectangular_block(r, h)
    t = np.linspace(0.0, 4.0, 81)
    ref = sp_rocking.simulate(blk, sp_pulse.define("half_sine", amp=0.45, amp_unit="g",
                                                   duration=0.6), t=t)
    for out in (a, b):
        s = {k: v[0] for k, v in out["cylinder"].items()}
        assert s["outcome"] == ref.outcome
        assert s["p"] == pytest.approx(blk.p, rel=1e-13)
        assert s["e"] == pytest.approx(blk.e, rel=1e-13)
        assert s["n_impacts"] == ref.n_impacts > 0
        assert s["t_impact1"] == pytest.approx(ref.t_impacts[0], rel=1e-10)
        assert s["theta_max"] == pytest.approx(ref.theta_max, rel=1e-10)
        np.testing.assert_allclose(out["cylinder_history"]["theta"], ref.theta, rtol=1e-9,
                                   atol=1e-12)
        np.testing.assert_allclose(out["cylinder_history"]["omega"], ref.omega, rtol=1e-9,
                                   atol=1e-12)


def test_map_axes_and_block_equivalence(driver, tmp_path):
    """A J_o = 4/3 m R^2 body's map on the dimensionless axes is seispulse.rocking's
    overturning map; on the dimensional axes the same classes sit at omega_p/p =
    2 pi f_p/p and a_p/(g tan theta_c) = PGA/tan(theta_c)."""
    from seispulse import rocking as sp_rocking
    r, h = 0.25, 1.0
    j_o = 4 / 3 * (r * r + h * h)
    body = f"shape='custom', r={r}, h={h}, j_o={j_o!r}"
    freq = [0.8, 1.5, 2.5, 4.0, 6.0]
    amp = [0.5, 1.0, 1.5, 2.0, 3.0, 4.0]
    a = cylinder(driver, tmp_path, body, "what='map'",
                 f"&map kind='half_sine', freq_ratio={', '.join(map(str, freq))}, "
                 f"amp_ratio={', '.join(map(str, amp))} /\n", output="a")["cylinder_map"]
    blk = sp_rocking.rectangular_block(r, h)
    ref = sp_rocking.overturning_map("half_sine", freq, amp, blk.alpha)
    assert codes(a["class"]).reshape(len(amp), len(freq)).tolist() == ref.tolist()
    assert len(set(a["class"])) > 1
    # the same cells in f_p (Hz) and PGA (g)
    f_hz = [x * blk.p / (2 * math.pi) for x in freq]
    pga = [x * math.tan(blk.alpha) for x in amp]
    d = cylinder(driver, tmp_path, body, "what='map'",
                 f"&map axes='dimensional', kind='half_sine', "
                 f"freq_hz={', '.join(map(repr, f_hz))}, pga={', '.join(map(repr, pga))} /\n",
                 output="d")["cylinder_map"]
    np.testing.assert_allclose(d["freq_ratio"], np.tile(freq, len(amp)), rtol=1e-13)
    np.testing.assert_allclose(d["amp_ratio"], np.repeat(amp, len(freq)), rtol=1e-13)
    assert d["class"].tolist() == a["class"].tolist()


def test_map_with_vertical_acceleration(driver, tmp_path):
    """kv in a map: the classes are seispulse.rocking's overturning map with the same kv
    (alpha = theta_c, the body's e), they differ from the map without it, and a cell where
    a_v would fall below -g is an error located at &cylinder's kv."""
    from seispulse import cylinder as sp_cyl
    from seispulse import rocking as sp_rocking
    body = sp_cyl.props(0.4, 1.6)
    freq = [1.5, 3.0, 6.0]
    amp = [1.2, 2.0, 3.0, 4.5, 6.0]
    grid = (f"&map kind='sine_cycle', freq_ratio={', '.join(map(str, freq))}, "
            f"amp_ratio={', '.join(map(str, amp))} /\n")
    out = cylinder(driver, tmp_path, "r=0.4, h=1.6", "what='map', kv=-0.5", grid,
                   output="k")["cylinder_map"]
    ref = sp_rocking.overturning_map("sine_cycle", freq, amp, body.theta_c,
                                     e=body.restitution, kv=-0.5)
    assert codes(out["class"]).reshape(len(amp), len(freq)).tolist() == ref.tolist()
    plain = cylinder(driver, tmp_path, "r=0.4, h=1.6", "what='map'", grid,
                     output="n")["cylinder_map"]
    assert out["class"].tolist() != plain["class"].tolist()
    head = (tmp_path / "k_cylinder_map.txt").read_text()
    assert "vertical ground acceleration a_v = kv a_g in every cell, kv = -0.5" in head
    text = ("&run analysis='cylinder', output='bad' /\n&body r=0.4, h=1.6 /\n"
            "&cylinder what='map', kv=-1.0 /\n&map axes='dimensional', kind='sine_cycle', "
            "freq_hz=1.0, pga=1.0, 20.0, 40.0 /\n")
    proc = run(driver, tmp_path, text, name="bad.nml")
    assert proc.returncode == 2
    assert ("bad.nml:3: &cylinder: kv = -1.0: a_v = kv a_g falls below -g at pga(2) = 20.0"
            in proc.stderr), proc.stderr
    assert not list(tmp_path.glob("bad_*"))


def test_map_compare_block(driver, tmp_path):
    """compare_block on the dimensional axes with a block of another slenderness: the
    block's classes are seispulse.rocking's map of that block (same p, its own tan alpha
    and Housner e) and diff is the code of the two classes."""
    from seispulse import rocking as sp_rocking
    r, h, alpha = 0.5, 2.0, 0.2
    ref = solid(r, h)
    f_hz = [0.3, 0.6, 1.0, 1.6]
    pga = [0.15, 0.3, 0.45, 0.6, 0.9]
    out = cylinder(driver, tmp_path, f"r={r}, h={h}, equivalent_angle={alpha}", "what='map'",
                   f"&map axes='dimensional', kind='sine_cycle', compare_block=.true., "
                   f"freq_hz={', '.join(map(str, f_hz))}, pga={', '.join(map(str, pga))} /\n"
                   )["cylinder_map"]
    fr = [2 * math.pi * f / ref["p"] for f in f_hz]
    cyl = sp_rocking.overturning_map("sine_cycle", fr, [a / math.tan(ref["theta_c"])
                                                        for a in pga],
                                     ref["theta_c"], e=ref["e"])
    blk = sp_rocking.overturning_map("sine_cycle", fr, [a / math.tan(alpha) for a in pga],
                                     alpha)
    assert codes(out["class"]).reshape(cyl.shape).tolist() == cyl.tolist()
    assert codes(out["class_block"]).reshape(blk.shape).tolist() == blk.tolist()

    def code(a, b):
        return 0 if a == b else 1 if b == 0 else 2 if a == 0 else 3
    assert codes(out["diff"], DIFFS).tolist() == [code(a, b) for a, b in zip(cyl.ravel(),
                                                                             blk.ravel())]
    assert any(out["diff"] != "same")


def test_pushover_default_grid_and_mirror_free(driver, tmp_path):
    """Without a grid: theta/theta_c = 0, 0.05, .., 1 (21 values); a hollow cylinder's
    theta_c = atan(r/h) only, F(theta_c) = 0 and M/(m g r) = sin(theta_c (1 - u))/
    sin(theta_c)."""
    t = cylinder(driver, tmp_path, "shape='hollow', r=0.8, r_inner=0.7, h=2.4, mass=5000",
                 "what='pushover'")["cylinder_pushover"]
    u = t["theta_ratio"]
    assert u == pytest.approx(np.arange(21) / 20, abs=1e-15)
    tc = math.atan(0.8 / 2.4)
    np.testing.assert_allclose(t["m_ratio"], np.sin(tc * (1 - u)) / math.sin(tc), rtol=1e-12,
                               atol=1e-15)
    assert abs(t["force"][-1]) < 1e-9 and all(t["stable"] == 1)


def test_history_on_records(driver, tmp_path):
    """&records (one column file with dt, in g): the history is seispulse.rocking's on
    the samples in m/s2 for the symmetric block of the body; a file that cannot be read
    gives NaN rows, the other record is still computed, and the exit status is 1."""
    from seispulse import rocking as sp_rocking
    dt = 0.01
    tt = np.arange(0, 1.5, dt)
    acc = 0.5 * np.sin(2 * np.pi * tt / 0.75) * np.exp(-tt)
    (tmp_path / "rec.txt").write_text("\n".join(repr(float(x)) for x in acc) + "\n")
    r, h = 0.3, 1.2
    out = cylinder(driver, tmp_path, f"r={r}, h={h}", "what='history', dt=0.05",
                   f"&records files='rec.txt', 'nothere.txt', format='column', dt={dt} /\n",
                   status=1)
    ref = solid(r, h)
    blk = sp_rocking.symmetric_block(ref["R"], ref["theta_c"], ref["io_over_mr2"])
    s = out["cylinder"]
    h_tab = out["cylinder_history"]
    n = int(np.sum(~np.isnan(h_tab["t"])))
    run_ref = sp_rocking.simulate(blk, accel=acc * G, dt=dt, t=h_tab["t"][:n])
    assert s["outcome"][0] == run_ref.outcome
    assert s["n_impacts"][0] == run_ref.n_impacts
    assert s["theta_max"][0] == pytest.approx(run_ref.theta_max, rel=1e-10)
    np.testing.assert_allclose(h_tab["theta"][:n], run_ref.theta, rtol=1e-9, atol=1e-12)
    # a_g: the samples, linear in between (m/s2)
    np.testing.assert_allclose(h_tab["a_g"][:n], G * np.interp(h_tab["t"][:n], tt, acc,
                                                               right=0.0), atol=1e-12)
    assert list(s["outcome"][1:]) == ["nan"] and len(s["outcome"]) == 2
    assert n == len(h_tab["t"]) - 1 and np.isnan(h_tab["theta"][-1])


def test_vertical_acceleration(driver, tmp_path):
    """kv (a_v = kv a_g, doc/rocking.md section 7) under a pulse and under a record: the
    history is seispulse.rocking's with kv, and with accel_v = kv x the record, for the
    symmetric block of the body; kv changes the answer."""
    from seispulse import pulse as sp_pulse
    from seispulse import rocking as sp_rocking
    r, h = 0.3, 1.2
    ref = solid(r, h)
    blk = sp_rocking.symmetric_block(ref["R"], ref["theta_c"], ref["io_over_mr2"])
    t = np.linspace(0.0, 3.0, 61)
    pul = sp_pulse.define("sine_cycle", amp=0.6, amp_unit="g", period=0.8)
    out = cylinder(driver, tmp_path, f"r={r}, h={h}", "what='history', kv=0.4, t_end=3.0, "
                   "npts=61", "&pulse kind='sine_cycle', amp=0.6, amp_unit='g', "
                   "duration=0.8 /\n", output="p")
    run_kv = sp_rocking.simulate(blk, pul, t=t, kv=0.4)
    run_0 = sp_rocking.simulate(blk, pul, t=t)
    np.testing.assert_allclose(out["cylinder_history"]["theta"], run_kv.theta, rtol=1e-9,
                               atol=1e-12)
    assert np.max(np.abs(run_kv.theta - run_0.theta)) > 1e-3
    dt = 0.02
    tt = np.arange(0, 2.0, dt)
    acc = 0.6 * np.sin(2 * np.pi * tt / 0.8) * (tt < 0.8)
    (tmp_path / "rec.txt").write_text("\n".join(repr(float(x)) for x in acc) + "\n")
    out = cylinder(driver, tmp_path, f"r={r}, h={h}", "what='history', kv=-0.3, t_end=3.0, "
                   "npts=61", f"&records files='rec.txt', format='column', dt={dt} /\n",
                   output="q")
    run_rec = sp_rocking.simulate(blk, accel=acc * G, dt=dt, t=t, kv=0.0,
                                  accel_v=-0.3 * acc * G)
    np.testing.assert_allclose(out["cylinder_history"]["theta"], run_rec.theta, rtol=1e-9,
                               atol=1e-12)
    assert out["cylinder"]["outcome"][0] == run_rec.outcome
    # a kv that lifts the body off in a record fails that row, naming kv
    text = (f"&run analysis='cylinder', output='lift' /\n&body r={r}, h={h} /\n"
            "&cylinder what='history', kv=-3.0 /\n"
            f"&records files='rec.txt', format='column', dt={dt} /\n")
    proc = run(driver, tmp_path, text, name="lift.nml")
    assert proc.returncode == 1, proc.stderr
    assert "files(1) = 'rec.txt': &cylinder: kv = -3.0: a_v = kv a_g falls below -g" \
        in proc.stderr, proc.stderr


ROLL_SUMMARY = ["theta_c", "p", "e", "outcome", "t_uplift", "n_impacts", "n_floor",
                "t_impact1", "theta_max", "theta_ratio_max", "friction_max", "t_lift_off",
                "energy_drift", "t_end"]
ROLL_COLUMNS = ["t", "a_x", "a_y", "theta", "psi", "spin", "theta_rate", "psi_rate",
                "spin_rate", "x_contact", "y_contact", "x_g", "y_g", "normal_force",
                "friction_demand", "energy"]
ROLL_UNITS = ["s", "m/s2", "m/s2", "rad", "rad", "rad", "rad/s", "rad/s", "rad/s", "m", "m",
              "m", "m", "N", "-", "J"]


def test_example_roll(driver, source_root, tmp_path):
    """input/cylinder_roll.nml: a pulse along 0.5 rad and no spin keep the motion in one
    vertical plane: theta = |theta| of seispulse.rocking's planar history of the
    cylinder's symmetric block, the heading is the direction -+ pi/2, the ground
    acceleration and the centre of mass lie along the direction."""
    from seispulse import pulse as sp_pulse
    from seispulse import rocking as sp_rocking
    proc = run_example(driver, source_root, tmp_path, "cylinder_roll.nml")
    assert "cylinder: overturn" in proc.stdout
    out = tmp_path / "out"
    assert header(out / "cylinder_roll.csv") == (
        ROLL_SUMMARY, ["rad", "rad/s", "-", "-", "s", "-", "-", "s", "rad", "-", "-", "s",
                       "-", "s"])
    assert header(out / "cylinder_roll_history.csv") == (ROLL_COLUMNS, ROLL_UNITS)
    s = {k: v[0] for k, v in read_table(out / "cylinder_roll.csv").items()}
    h = read_table(out / "cylinder_roll_history.csv")
    ref = solid(1.0, 3.0)
    blk = sp_rocking.symmetric_block(ref["R"], ref["theta_c"], ref["io_over_mr2"])
    planar = sp_rocking.simulate(blk, sp_pulse.define("sine_cycle", amp=0.8, amp_unit="g",
                                                      period=1.0), t=h["t"])
    assert s["outcome"] == "overturn"
    assert re.search(r"^outcome +overturn +-$", (out / "cylinder_roll.txt").read_text(),
                     re.MULTILINE)
    assert planar.outcome == "overturn_one_impact" and s["n_impacts"] == 1
    assert s["t_impact1"] == pytest.approx(planar.t_impacts[0], rel=1e-8)
    assert s["t_end"] == pytest.approx(planar.t_end, rel=1e-8)
    np.testing.assert_allclose(h["theta"], np.abs(planar.theta), atol=1e-7)
    up = h["theta"] > 0
    assert set(np.round(h["psi"][up] - 0.5, 9)) <= {round(-math.pi / 2, 9),
                                                    round(math.pi / 2, 9)}
    a = np.hypot(h["a_x"], h["a_y"])
    np.testing.assert_allclose(h["a_x"], np.sign(h["a_x"]) * a * math.cos(0.5), atol=1e-9)
    moved = np.hypot(h["x_g"], h["y_g"]) > 1e-6
    np.testing.assert_allclose(h["y_g"][moved] / h["x_g"][moved], math.tan(0.5), rtol=1e-8)
    assert np.all(h["friction_demand"][up & (h["normal_force"] > 0)] >= 0)


def test_roll_free_energy(driver, tmp_path):
    """Free rocking from theta0 = 0.2 rad at rest: the planar free rocking of
    seispulse.rocking (theta = |theta|), and before the first impact the energy is the
    potential energy at the start, m g R cos(theta_c - theta0)."""
    from seispulse import rocking as sp_rocking
    r, h, m = 0.5, 1.5, 20.0
    ref = solid(r, h, m)
    out = cylinder(driver, tmp_path, f"r={r}, h={h}, mass={m}",
                   "what='roll', t_end=3.0, npts=301, rtol=1e-12",
                   "&roll theta0=0.2 /\n")
    t = out["cylinder_roll_history"]
    blk = sp_rocking.symmetric_block(ref["R"], ref["theta_c"], ref["J_o"] / (m * ref["R"]**2))
    # the planar free rocking of the same body: a zero pulse is no excitation at all
    planar = sp_rocking.simulate(blk, accel=np.zeros(2), dt=1.0, theta0=0.2, t=t["t"],
                                 t_max=3.0)
    np.testing.assert_allclose(t["theta"], np.abs(planar.theta), atol=1e-8)
    first = out["cylinder_roll"]["t_impact1"][0]
    before = t["t"] < first
    e0 = m * G * ref["R"] * math.cos(ref["theta_c"] - 0.2)
    np.testing.assert_allclose(t["energy"][before], e0, rtol=1e-9)
    assert out["cylinder_roll"]["n_impacts"][0] >= 1


def test_roll_two_components(driver, tmp_path):
    """Two equal record components x and y: the ground moves along 45 degrees with
    sqrt(2) times the record; the tilt is the planar history under that record."""
    from seispulse import rocking as sp_rocking
    dt = 0.02
    tt = np.arange(0, 1.6, dt)
    acc = 0.45 * np.sin(2 * np.pi * tt / 0.8) * (tt < 0.8)
    text = "\n".join(repr(float(x)) for x in acc) + "\n"
    (tmp_path / "x.txt").write_text(text)
    (tmp_path / "y.txt").write_text(text)
    r, h, m = 0.4, 1.6, 100.0
    out = cylinder(driver, tmp_path, f"r={r}, h={h}, mass={m}",
                   "what='roll', t_end=3.0, npts=151, rtol=1e-12",
                   f"&records files='x.txt', 'y.txt', format='column', dt={dt} /\n")
    t = out["cylinder_roll_history"]
    ref = solid(r, h, m)
    blk = sp_rocking.symmetric_block(ref["R"], ref["theta_c"], ref["J_o"] / (m * ref["R"]**2))
    planar = sp_rocking.simulate(blk, accel=math.sqrt(2) * acc * G, dt=dt, t=t["t"],
                                 t_max=3.0)
    np.testing.assert_allclose(t["theta"], np.abs(planar.theta), atol=1e-8)
    assert np.max(t["theta"]) > 0.01
    np.testing.assert_allclose(t["a_x"], t["a_y"], rtol=0, atol=0)


# ---------------------------------------------------------------- errors

ERRORS = [
    # (body, &cylinder, extra groups, expected fragments)
    ("r=-1.0, h=2.0, mass=1.0", "what='props'", "",
     ["case.nml:2:", "&body", "r = -1", "> 0"]),
    ("r=1.0, mass=1.0", "what='props'", "", ["&body", "h: missing"]),
    ("r=1.0, h=2.0", "what='props'", "", ["&body", "mass: missing"]),
    ("r=1.0, h=2.0, mass=-5.0", "what='props'", "", ["&body", "mass = -5", "> 0"]),
    ("r=1.0, h=2.0, mass=1.0", "what='stress'", "",
     ["case.nml:3:", "&cylinder", "what = 'stress'", "props, pushover, history, map, roll"]),
    ("r=1.0, h=2.0", "what='map'", "&map axes='polar', freq_ratio=1.0, amp_ratio=1.0 /\n",
     ["case.nml:4:", "&map", "axes = 'polar'", "dimensionless, dimensional"]),
    ("shape='hollow', r=1.0, r_inner=1.0, h=2.0, mass=1.0", "what='props'", "",
     ["&body", "r_inner = 1", "[0, r)"]),
    ("shape='hollow', r=1.0, h=2.0, mass=1.0", "what='props'", "",
     ["&body", "r_inner: missing"]),
    ("r=1.0, r_inner=0.5, h=2.0, mass=1.0", "what='props'", "",
     ["&body", "r_inner: only with a hollow cylinder"]),
    ("r=1.0, h=2.0, e=1.5", "what='history'", "&pulse amp=3.0 /\n",
     ["&body", "e = 1.5", "[0, 1]"]),
    ("r=1.0, h=2.0, e=-0.1", "what='history'", "&pulse amp=3.0 /\n",
     ["&body", "e = -0.1", "[0, 1]"]),
    ("r=1.0, h=2.0", "what='history'", "", ["&pulse: missing group", "&records"]),
    ("r=1.0, h=2.0", "what='history'", "&pulse amp=3.0 /\n&records files='a.txt' /\n",
     ["&records", "not with &pulse"]),
    ("r=1.0, h=2.0, mass=1.0", "what='props'", "&pulse amp=3.0 /\n",
     ["&pulse", "only with what = 'history'"]),
    ("r=1.0, h=2.0, mass=1.0", "what='props'", "&map freq_ratio=1.0 /\n",
     ["&map", "only with what = 'map'"]),
    ("r=1.0, h=2.0", "what='map'", "", ["&map: missing group"]),
    ("shape='cone', r=1.0, h=2.0, mass=1.0", "what='props'", "",
     ["&body", "shape = 'cone'", "solid, hollow, custom, block"]),
    ("shape='block', r=1.0, h=2.0, mass=1.0", "what='props'", "",
     ["&body", "r: only with", "half-width b"]),
    ("b=1.0, h=2.0, mass=1.0", "what='props'", "", ["&body", "b: only with a block"]),
    ("shape='custom', r=1.0, h=2.0, mass=1.0, j_o=2.0", "what='props'", "",
     ["&body", "j_o = 2", "m R^2"]),
    ("shape='custom', r=1.0, h=2.0, mass=1.0", "what='props'", "",
     ["&body", "j_o: missing"]),
    ("r=1.0, h=2.0, mass=1.0, model='elastic'", "what='props'", "",
     ["&body", "model = 'elastic'", "nonlinear, linearized"]),
    ("r=1.0, h=2.0, mass=1.0, equivalent_angle=2.0", "what='props'", "",
     ["&body", "equivalent_angle = 2", "(0, pi/2)"]),
    ("r=1.0, h=2.0, mass=1.0", "what='pushover', theta=0.1, 2.0", "",
     ["&cylinder", "theta(2)", "pi/2"]),
    ("r=1.0, h=2.0, mass=1.0", "what='pushover', theta=0.2, 0.1", "",
     ["&cylinder", "theta(2)", "ascending"]),
    ("r=1.0, h=2.0, mass=1.0", "what='pushover', theta=0.1, theta_ratio=0.5", "",
     ["&cylinder", "theta, theta_ratio", "one of them"]),
    ("r=1.0, h=2.0, mass=1.0", "what='props', npts=11", "",
     ["&cylinder", "npts: only with what = 'history'"]),
    ("r=1.0, h=2.0, mass=1.0", "what='props', theta=0.1", "",
     ["&cylinder", "theta: only with what = 'pushover'"]),
    ("r=1.0, h=2.0", "what='map', t_max=3.0", "&map freq_ratio=1.0, amp_ratio=1.0 /\n",
     ["&cylinder", "t_max: not with what = 'map'"]),
    ("r=1.0, h=2.0", "what='map'", "&map freq_hz=1.0, amp_ratio=1.0 /\n",
     ["&map", "freq_hz: only with axes = 'dimensional'"]),
    ("r=1.0, h=2.0", "what='map'", "&map axes='dimensional', freq_hz=1.0, amp_ratio=1.0 /\n",
     ["&map", "amp_ratio: only with axes = 'dimensionless'"]),
    ("r=1.0, h=2.0", "what='map'", "&map freq_ratio=1.0, 0.0, amp_ratio=1.0 /\n",
     ["&map", "freq_ratio(2)", "> 0"]),
    ("shape='block', b=1.0, h=2.0", "what='map'",
     "&map compare_block=.true., freq_ratio=1.0, amp_ratio=1.0 /\n",
     ["&map", "compare_block", "a block already"]),
    ("r=1.0, h=2.0, g=9.81", "what='history'", "&pulse amp=3.0, g=9.8 /\n",
     ["&body", "g = 9.81", "&pulse"]),
    ("r=1.0, h=2.0, g=9.81", "what='history'", "&pulse amp=0.5, amp_unit='g' /\n",
     ["&body", "g = 9.81", "not the g of &pulse (9.80665 m/s2)", "give g in &pulse"]),
    ("r=1.0, h=2.0, mass=1.0, radius=2.0", "what='props'", "",
     ["&body", "radius: unknown key"]),
    ("r=1.0, h=2.0", "what='history', rtol=0.1", "&pulse amp=3.0 /\n",
     ["&cylinder", "rtol = 0.1", "[1e-14, 1e-3]"]),
    ("shape='block', b=1.0, h=2.0, mass=1.0", "what='roll'", "&roll theta0=0.1 /\n",
     ["&body", "shape = 'block'", "body of revolution"]),
    ("shape='custom', r=1.0, h=2.0, mass=1.0, j_o=7.0", "what='roll'",
     "&roll theta0=0.1 /\n", ["&body", "j_axis: missing"]),
    ("r=1.0, h=2.0, mass=1.0, model='linearized'", "what='roll'", "&roll theta0=0.1 /\n",
     ["&body", "model = 'linearized'", "nonlinear model only"]),
    ("r=1.0, h=2.0", "what='roll'", "&roll theta0=0.1 /\n", ["&body", "mass: missing"]),
    ("r=1.0, h=2.0, mass=1.0", "what='roll'", "&roll theta0=2.0 /\n",
     ["case.nml:4:", "&roll", "theta0 = 2", "[0, pi/2)"]),
    ("r=1.0, h=2.0, mass=1.0", "what='roll'", "&roll psi0=1.0 /\n",
     ["&roll", "theta0, theta_rate0", "upright at rest"]),
    ("r=1.0, h=2.0, mass=1.0", "what='roll'", "", ["&pulse: missing group", "&roll"]),
    ("r=1.0, h=2.0, mass=1.0", "what='roll'",
     "&records files='a.txt', 'b.txt', 'c.txt', format='column', dt=0.01 /\n",
     ["&records", "files", "one record", "not 3"]),
    ("r=1.0, h=2.0", "what='history'", "&pulse amp=3.0 /\n&roll theta0=0.1 /\n",
     ["&roll", "only with what = 'roll'"]),
    ("r=1.0, h=2.0, mass=1.0", "what='roll', kv=0.2", "&roll theta0=0.1 /\n",
     ["&cylinder", "kv: only with what = 'history'"]),
    ("r=1.0, h=2.0, mass=1.0", "what='pushover', kv=0.2", "",
     ["&cylinder", "kv: only with what = 'history'"]),
    ("r=1.0, h=2.0, mass=1.0, e=0.3", "what='props'", "",
     ["&body", "e: only with what = 'history', 'map' or 'roll'"]),
    ("r=1.0, h=2.0, mass=1.0, model='linearized'", "what='pushover'", "",
     ["&body", "model: only with what = 'history' or 'map'"]),
    ("r=1.0, h=2.0, equivalent_angle=0.3", "what='history'", "&pulse amp=3.0 /\n",
     ["&body", "equivalent_angle: only with what = 'props' or 'map'"]),
    ("r=1.0, h=2.0", "what='history', kv=-3.0", "&pulse amp=5.0 /\n",
     ["&cylinder", "kv = -3", "below -g"]),
]


@pytest.mark.parametrize("body, opts, extra, fragments", ERRORS)
def test_errors(driver, tmp_path, body, opts, extra, fragments):
    """One located line on stderr (file:line: &group: key: problem), exit 2, no table."""
    text = f"&run analysis='cylinder', output='o' /\n&body {body} /\n&cylinder {opts} /\n"
    proc = run(driver, tmp_path, text + extra)
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert lines[-1].startswith("seispulse: error: case.nml"), lines
    for fragment in fragments:
        assert fragment in lines[-1], (fragment, lines[-1])
    assert not list(tmp_path.glob("o_*"))


def test_missing_body_and_foreign_group(driver, tmp_path):
    """&body is required; a group of another analysis is refused by name."""
    proc = run(driver, tmp_path, "&run analysis='cylinder', output='o' /\n"
               "&cylinder what='props' /\n")
    assert proc.returncode == 2 and "&body: missing group" in proc.stderr
    proc = run(driver, tmp_path, "&run analysis='cylinder', output='o' /\n"
               "&block b=1.0, h=2.0 /\n")
    assert proc.returncode == 2
    assert "&block: not a group of analysis 'cylinder'" in proc.stderr
    assert not list(tmp_path.glob("o_*"))
