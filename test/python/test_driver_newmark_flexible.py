"""Batch driver, analysis 'newmark' with a flexible sliding mass (method 'decoupled' or
'coupled', group &slope; doc/flexible.md section 9): the columns, the old and new forms
of `method` and `rule`, limit cases (a very stiff mass slides as the rigid block; a yield
table of one value is that constant ky), SLAMMER 1.1's arithmetic on a real record against
the plain-Python transcription slammer_reference.py, an unconverged equivalent-linear
iteration (a warning, converged = no, exit status 0), and the located one-line input
errors (exit status 2, no output)."""
import csv
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import slammer_reference as sref
from driver_tables import coded

HERE = Path(__file__).resolve().parent
RECORDS = HERE.parent / "regression" / "records"

RIGID = ["pga (g)", "scale (-)", "ky (g)", "ky_up (g)", "max_normal (m)", "max_normal_cm (cm)",
         "final_normal (m)", "final_normal_cm (cm)", "max_inverse (m)", "max_inverse_cm (cm)",
         "final_inverse (m)", "final_inverse_cm (cm)"]
FLEX = ["kmax (g)", "vs_final (m/s)", "damping_final (-)", "period (s)", "iterations (-)",
        "converged (-)"]
HEADER = ["record (-)"] + RIGID + FLEX + ["status (-)"]
COL = {name: i for i, name in enumerate(HEADER[1:])}

SLOPE = "&slope height=20, vs=300, vs_base=600 /"


def run(driver, cwd, text, name="case.nml"):
    (Path(cwd) / name).write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def case(driver, tmp_path, records, newmark, slope=SLOPE, output="o"):
    if not (tmp_path / "records").exists():
        shutil.copytree(RECORDS, tmp_path / "records")
    return run(driver, tmp_path, f"&run analysis='newmark', output='{output}' /\n"
                                 f"&records {records} /\n&newmark {newmark} /\n{slope}\n")


def table(tmp_path, output="o"):
    with open(tmp_path / f"{output}_newmark.csv", newline="") as f:
        header = next(csv.reader(f))
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    # status and converged are names ("ok"/"failed", "no"/"yes"): as their codes 0, 1
    return header, [r[0] for r in rows], coded(header, rows)


def gravity_record(path, scale=1.0):
    """(accel in g, dt) of a SLAMMER CSV record (time, accel g), times scale."""
    rows = [ln.split(",")[:2] for ln in Path(path).read_text(encoding="utf-8-sig")
            .splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    t = [float(r[0]) for r in rows]
    return [float(r[1]) * scale for r in rows], (t[-1] - t[0]) / (len(t) - 1)


# ---------------------------------------------------------------- the table

def test_columns_and_header(driver, tmp_path):
    proc = case(driver, tmp_path, "files='records/quake_b.csv', target_pga=0.4",
                "ky=0.05, 0.1, method='decoupled', rule='slammer'",
                "&slope height=20, vs=300, vs_base=600, soil='equivalent_linear' /")
    assert proc.returncode == 0, proc.stderr
    header, names, data = table(tmp_path)
    assert header == HEADER and names == ["quake_b"] * 2
    assert np.all(data[:, -1] == 0) and np.all(data[:, COL["converged (-)"]] == 1)
    last = (tmp_path / "o_newmark.csv").read_text().splitlines()[-1]
    assert re.search(r',\d+,"yes","ok"$', last), "iterations an integer, names for the codes"
    # the mass's properties do not depend on ky; period = 4 H / Vs
    for c in ("kmax (g)", "vs_final (m/s)", "damping_final (-)", "iterations (-)"):
        assert data[0, COL[c]] == data[1, COL[c]]
    assert data[0, COL["iterations (-)"]] >= 2          # SLAMMER's start: two at least
    assert 0 < data[0, COL["vs_final (m/s)"]] < 300
    assert data[0, COL["period (s)"]] == pytest.approx(80 / data[0, COL["vs_final (m/s)"]],
                                                        rel=1e-15)
    # one way: max = final; cm = 100 m; more ky, less sliding
    np.testing.assert_array_equal(data[:, COL["max_normal (m)"]],
                                  data[:, COL["final_normal (m)"]])
    np.testing.assert_allclose(data[:, COL["max_normal_cm (cm)"]],
                               100 * data[:, COL["max_normal (m)"]], rtol=1e-15)
    assert data[0, COL["max_normal (m)"]] > data[1, COL["max_normal (m)"]] > 0
    assert np.all(np.isinf(data[:, COL["ky_up (g)"]]))
    txt = (tmp_path / "o_newmark.txt").read_text()
    for words in ["method = decoupled, rule = slammer, mode = down",
                  "sliding mass: height = 20.0 m, vs = 300.0 m/s, vs_base = 600.0 m/s",
                  "soil = equivalent_linear, ref_strain_pct = 0.05 %, max_iter = 100"]:
        assert words in txt
    echo = proc.stdout.upper()
    assert "&SLOPE" in echo and 'METHOD="decoupled"'.upper() in echo


def test_echo_reads_back(driver, tmp_path):
    proc = case(driver, tmp_path, "files='records/quake_a.AT2', target_pga=0.3",
                "ky=0.07, method='coupled', rule='slammer'",
                "&slope height=15, vs=250, vs_base=900, damping=0.02 /", output="first")
    assert proc.returncode == 0, proc.stderr
    echo = proc.stdout.split("newmark table written")[0].replace('"first', '"second')
    proc2 = run(driver, tmp_path, echo, name="echo.nml")
    assert proc2.returncode == 0, proc2.stderr
    _, _, d1 = table(tmp_path, "first")
    _, _, d2 = table(tmp_path, "second")
    np.testing.assert_array_equal(d1, d2)


def test_old_method_is_rigid_with_that_rule(driver, tmp_path):
    """method = 'slammer' (the old form) = method = 'rigid', rule = 'slammer': the same
    table, byte for byte."""
    rec = "files='records/quake_a.AT2', 'records/quake_b.csv', target_pga=0.3"
    for out, newmark in [("old", "ky=0.05, 0.1, method='slammer'"),
                         ("new", "ky=0.05, 0.1, method='rigid', rule='slammer'")]:
        proc = case(driver, tmp_path, rec, newmark, slope="", output=out)
        assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "old_newmark.csv").read_bytes() == \
        (tmp_path / "new_newmark.csv").read_bytes()


@pytest.mark.parametrize("method, rule, soil", [("decoupled", "slammer", "equivalent_linear"),
                                               ("coupled", "slammer", "linear"),
                                               ("decoupled", "exact", "linear"),
                                               ("coupled", "exact", "equivalent_linear")])
def test_agrees_with_python_api(driver, tmp_path, method, rule, soil):
    """The driver's rows are seispulse.newmark.decoupled / coupled on the record and its
    inverse (the same library routines; the driver reads, scales and writes)."""
    from seispulse import newmark, records
    proc = case(driver, tmp_path, "files='records/quake_a.AT2', 'records/quake_d.dat', "
                "units='auto', 'm/s2', target_pga=0.35", f"ky=0.06, 0.12, method='{method}', "
                f"rule='{rule}'", f"&slope height=25, vs=280, vs_base=700, damping=0.03, "
                f"soil='{soil}', ref_strain_pct=0.08 /")
    assert proc.returncode == 0, proc.stderr
    _, _, data = table(tmp_path)
    run = newmark.decoupled if method == "decoupled" else newmark.coupled
    expected = []
    for name, units in (("quake_a.AT2", None), ("quake_d.dat", "m/s2")):
        rec = records.read(RECORDS / name, units=units).scaled_to_pga(0.35)
        for ky in (0.06, 0.12):
            kw = dict(ky=ky, height=25.0, vs=280.0, vs_base=700.0, damping=0.03, soil=soil,
                      ref_strain_pct=0.08, method=rule)
            n = run(rec.accel, rec.dt, **kw)
            i = run(-rec.accel, rec.dt, **kw)
            expected.append([rec.pga, rec.scale_factor, ky, np.inf, n.max_disp,
                             100 * n.max_disp, n.final_disp, 100 * n.final_disp, i.max_disp,
                             100 * i.max_disp, i.final_disp, 100 * i.final_disp, n.kmax,
                             n.vs_final, n.damping_final, n.period, n.iterations,
                             float(n.converged and i.converged), 0.0])
    np.testing.assert_allclose(data, np.array(expected), rtol=1e-12, atol=1e-15)
    assert np.all(data[:, COL["max_normal (m)"]] > 0)


# ---------------------------------------------------------------- independent values

def test_slammer_rule_matches_slammer_transcription(driver, tmp_path):
    """A real record (Cape Mendocino PET-090 of pySLAMMER's samples, scaled by 1.3):
    SLAMMER's Decoupled and Coupled (equivalent-linear) in slammer_reference.py."""
    pyslammer = pytest.importorskip("pyslammer")
    src = Path(pyslammer.__file__).parent / "sample_ground_motions" / \
        "Cape_Mendocino_1992_PET-090.csv"
    shutil.copy(src, tmp_path / "pet.csv")
    accel, dt = gravity_record(src, 1.3)
    mass = dict(height=40.0, vs=400.0, vs_base=800.0, damping=0.05,
                soil="equivalent_linear", ref_strain_pct=0.1)
    slope = ("&slope height=40, vs=400, vs_base=800, damping=0.05, "
             "soil='equivalent_linear', ref_strain_pct=0.1 /")
    for method, ref in (("decoupled", sref.decoupled), ("coupled", sref.coupled)):
        proc = case(driver, tmp_path, "files='pet.csv', scale=1.3",
                    f"ky=0.1, method='{method}', rule='slammer'", slope, output=method)
        assert proc.returncode == 0, proc.stderr
        _, _, data = table(tmp_path, method)
        normal = ref(accel, dt, 0.1, **mass)
        inverse = ref([-a for a in accel], dt, 0.1, **mass)
        row = data[0]
        assert row[COL["max_normal_cm (cm)"]] == pytest.approx(normal.disp_cm, rel=1e-12)
        assert row[COL["max_inverse_cm (cm)"]] == pytest.approx(inverse.disp_cm, rel=1e-12)
        assert row[COL["kmax (g)"]] == pytest.approx(normal.kmax_g, rel=1e-12)
        assert row[COL["vs_final (m/s)"]] == pytest.approx(normal.vs_final_mps, rel=1e-12)
        assert row[COL["damping_final (-)"]] == pytest.approx(normal.damping_final, rel=1e-12)
        assert row[COL["iterations (-)"]] == normal.iterations
        assert normal.disp_cm > 0.1 and inverse.disp_cm > 0.1


@pytest.mark.parametrize("method", ["decoupled", "coupled"])
def test_stiff_mass_slides_as_the_rigid_block(driver, tmp_path, method):
    """H = 0.5 m, Vs = 5000 m/s (period 0.4 ms, 25 times below dt): the mass moves with
    its base, HEA = the record, and the exact rule gives the exact rigid block's
    displacement (to the small transients of the mode) and kmax = the signed PGA."""
    rec = "files='records/quake_a.AT2', 'records/quake_b.csv', target_pga=0.4"
    proc = case(driver, tmp_path, rec, "ky=0.05, 0.15, method='rigid'", slope="",
                output="rigid")
    assert proc.returncode == 0, proc.stderr
    _, _, rigid = table(tmp_path, "rigid")
    proc = case(driver, tmp_path, rec, f"ky=0.05, 0.15, method='{method}', rule='exact'",
                "&slope height=0.5, vs=5000, vs_base=5000, damping=0.05 /", output="flex")
    assert proc.returncode == 0, proc.stderr
    _, _, flex = table(tmp_path, "flex")
    for c in ("max_normal (m)", "final_normal (m)", "max_inverse (m)", "final_inverse (m)"):
        np.testing.assert_allclose(flex[:, COL[c]], rigid[:, COL[c]], rtol=2e-3, atol=1e-6)
    assert np.all(np.maximum(rigid[:, COL["max_normal (m)"]],
                             rigid[:, COL["max_inverse (m)"]]) > 1e-2)
    assert np.all(np.abs(np.abs(flex[:, COL["kmax (g)"]]) - 0.4) < 0.01)
    # the radiation damping is at its cap 0.2 for vs_base = vs
    np.testing.assert_allclose(flex[:, COL["damping_final (-)"]], 0.25, rtol=1e-15)


def test_one_value_table_is_constant_ky(driver, tmp_path):
    """A yield table whose rows all hold 0.1 g slides as ky = 0.1 (both rules, every
    method); SLAMMER's flexible rule takes the table's second row from the first step, so
    (0, 0.3), (1000 m, 0.1) is ky = 0.1 too."""
    rec = "files='records/quake_b.csv', target_pga=0.45"
    slope = "&slope height=20, vs=300, vs_base=600 /"
    for method in ("rigid", "decoupled", "coupled"):
        for rule in ("exact", "slammer"):
            if method == "coupled" and rule == "exact":
                continue  # the same check below, through the table of two rows
            mass = "" if method == "rigid" else slope
            proc = case(driver, tmp_path, rec, f"ky=0.1, method='{method}', rule='{rule}'",
                        mass, output="k")
            assert proc.returncode == 0, proc.stderr
            _, _, const = table(tmp_path, "k")
            proc = case(driver, tmp_path, rec, "ky_disp=0, 0.01, 0.5, ky_table=0.1, 0.1, 0.1, "
                        f"method='{method}', rule='{rule}'", mass, output="t")
            assert proc.returncode == 0, proc.stderr
            _, _, tab = table(tmp_path, "t")
            np.testing.assert_allclose(tab, const, rtol=1e-12, atol=0)
    proc = case(driver, tmp_path, rec, "ky=0.1, method='coupled', rule='slammer'", slope,
                output="k")
    _, _, const = table(tmp_path, "k")
    proc = case(driver, tmp_path, rec, "ky_disp=0, 1000, ky_table=0.3, 0.1, method='coupled', "
                "rule='slammer'", slope, output="t")
    assert proc.returncode == 0, proc.stderr
    _, _, tab = table(tmp_path, "t")
    cols = [COL[c] for c in RIGID[4:] + FLEX]
    np.testing.assert_array_equal(tab[:, cols], const[:, cols])
    assert tab[0, COL["ky (g)"]] == 0.3 and "yield table" in (tmp_path / "t_newmark.txt") \
        .read_text()


def test_unconverged_iteration_warns_and_keeps_the_row(driver, tmp_path):
    """max_iter = 1 stops SLAMMER's iteration, which needs two passes at least: the row
    holds the first pass's results with converged = no, status ok, a warning on stderr
    and in the header; exit status 0. With max_iter = 100 the same case converges."""
    rec = "files='records/quake_b.csv', target_pga=0.4"
    for max_iter, out in ((1, "one"), (100, "all")):
        proc = case(driver, tmp_path, rec, "ky=0.1, method='decoupled', rule='slammer'",
                    "&slope height=30, vs=250, vs_base=500, soil='equivalent_linear', "
                    f"max_iter={max_iter} /", output=out)
        assert proc.returncode == 0, proc.stderr
        if max_iter == 1:
            warnings = [ln for ln in proc.stderr.splitlines() if "warning" in ln]
            assert len(warnings) == 1, proc.stderr
            for word in ["case.nml:2:", "files(1) = 'records/quake_b.csv'", "ky = 0.1",
                         "max_iter = 1"]:
                assert word in warnings[0], warnings[0]
            assert "NOT CONVERGED" in (tmp_path / "one_newmark.txt").read_text()
    _, _, one = table(tmp_path, "one")
    _, _, full = table(tmp_path, "all")
    assert one[0, COL["converged (-)"]] == 0 and one[0, COL["iterations (-)"]] == 1
    assert one[0, -1] == 0 and np.all(np.isfinite(np.delete(one[0], COL["ky_up (g)"])))
    assert full[0, COL["converged (-)"]] == 1 and full[0, COL["iterations (-)"]] >= 2
    # the first pass's Vs: SLAMMER's equivalent-linear step on the linear response
    accel, dt = gravity_record(RECORDS / "quake_b.csv")
    pga = max(abs(a) for a in accel)
    accel = [a * 0.4 / pga for a in accel]
    beam = sref._beam([a * sref.G_CM for a in accel], dt, 30.0, 250.0, 500.0, 0.05,
                      "linear", 0.05, 20.0, True)
    u, _ = beam.response()
    gamma_pct = 100 * 0.65 * 1.57 * max(abs(x) for x in u) / 3000.0
    assert one[0, COL["vs_final (m/s)"]] == pytest.approx(250 / np.sqrt(1 + gamma_pct / 0.05),
                                                          rel=1e-12)


# ---------------------------------------------------------------- input errors

R = "files='records/quake_a.AT2'"
S = "&slope height=20, vs=300, vs_base=600"
BAD = [
    # (newmark group, slope group, words of the one-line message)
    ("ky=0.1, method='decoupled'", "",
     ["case.nml:3:", "&newmark", "method = 'decoupled'", "&slope"]),
    ("ky=0.1, method='coupled'", "",
     ["case.nml:3:", "&newmark", "method = 'coupled'", "&slope"]),
    ("ky=0.1", S + " /", ["case.nml:4:", "&slope", "method = 'rigid'"]),
    ("ky=0.1, method='slammer'", S + " /", ["case.nml:4:", "&slope", "method = 'rigid'"]),
    ("ky=0.1, method='decoupled'", S + ", soil='clay' /",
     ["case.nml:4:", "&slope", "soil = 'clay'", "linear, equivalent_linear"]),
    ("ky=0.1, method='decoupled'", S + ", soil='equivalent_linear', ref_strain_pct=0 /",
     ["case.nml:4:", "&slope", "ref_strain_pct = 0", "> 0", "percent"]),
    ("ky=0.1, method='coupled'", S + ", ref_strain_pct=-0.1 /",
     ["case.nml:4:", "&slope", "ref_strain_pct = -0.1", "> 0"]),
    ("ky=0.1, method='slammer', rule='exact'", "",
     ["case.nml:3:", "&newmark", "rule", "method = 'slammer'"]),
    ("ky=0.1, method='exact', rule='slammer'", "",
     ["case.nml:3:", "&newmark", "rule", "method = 'exact'"]),
    ("ky_disp=0, 0.1, 0.05, ky_table=0.2, 0.1, 0.1, method='decoupled'", S + " /",
     ["case.nml:3:", "&newmark", "ky_disp(3)", "increasing"]),
    ("ky_disp=0, 0.1, 0.1, ky_table=0.2, 0.1, 0.1, method='rigid'", "",
     ["case.nml:3:", "&newmark", "ky_disp(3)", "increasing"]),
    ("ky_disp=0.01, 0.1, ky_table=0.2, 0.1, method='coupled'", S + " /",
     ["&newmark", "ky_disp(1)", "0"]),
    ("ky_disp=0, 0.1, ky_table=0.2, -0.1, method='coupled'", S + " /",
     ["&newmark", "ky_table(2) = -0.1", "> 0"]),
    ("ky_disp=0, 0.1, ky_table=0.2, method='coupled'", S + " /",
     ["&newmark", "ky_table: 1 values for 2 ky_disp"]),
    ("ky_disp=0, 0.1, method='decoupled'", S + " /", ["&newmark", "ky_table: missing"]),
    ("ky=0.1, ky_disp=0, 0.1, ky_table=0.2, 0.1", "", ["&newmark", "ky, ky_table"]),
    ("ky_disp=0, 0.1, ky_table=0.2, 0.1, mode='both'", "",
     ["&newmark", "mode = 'both'", "'down'"]),
    ("ky=0.1, method='coupled', mode='both'", S + " /",
     ["case.nml:3:", "&newmark", "mode = 'both'", "'decoupled'", "'exact'"]),
    ("ky=0.1, method='decoupled', rule='slammer', mode='asym', ky_up=0.2", S + " /",
     ["&newmark", "mode = 'asym'", "rule 'slammer'"]),
    ("ky=0.1, method='decoupled', rule='rk4'", S + " /",
     ["&newmark", "rule = 'rk4'", "exact, slammer"]),
    ("ky=0.1, method='flexible'", S + " /",
     ["&newmark", "method = 'flexible'", "rigid, decoupled, coupled"]),
    ("mu=0.3, method='coupled'", S + " /", ["&newmark", "mu: only with method = 'rigid'"]),
    ("ky=0.1, method='decoupled', mode='asym', ky_up=0.2, k_up=0.9", S + " /",
     ["&newmark", "k_up: only with method = 'rigid'"]),
    ("ky=0.1, method='decoupled'", "&slope height=20, vs=300 /",
     ["case.nml:4:", "&slope", "vs_base: missing"]),
    ("ky=0.1, method='decoupled'", S + ", height=-2 /", ["&slope", "height"]),
    ("ky=0.1, method='decoupled'", "&slope height=-2, vs=300, vs_base=600 /",
     ["case.nml:4:", "&slope", "height = -2", "> 0 (m)"]),
    ("ky=0.1, method='decoupled'", S + ", damping=1.5 /", ["&slope", "damping = 1.5"]),
    ("ky=0.1, method='decoupled'", S + ", max_iter=0 /", ["&slope", "max_iter = 0"]),
    ("ky=0.1, method='decoupled'", S + ", gamma=1 /", ["&slope", "gamma", "unknown key"]),
    ("ky=0.1, method='decoupled'", "&slope height=20, vs=abc, vs_base=600 /",
     ["case.nml:4:", "&slope", "vs", "bad value"]),
]


@pytest.mark.parametrize("newmark, slope, words", BAD)
def test_bad_input_one_line_exit_2_no_output(driver, tmp_path, newmark, slope, words):
    proc = case(driver, tmp_path, R, newmark, slope)
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    for word in words:
        assert word in lines[0], lines[0]
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml", "records"]


def test_linear_soil_warns_of_unused_keys(driver, tmp_path):
    proc = case(driver, tmp_path, R, "ky=0.1, method='decoupled', rule='slammer'",
                S + ", ref_strain_pct=0.1 /")
    assert proc.returncode == 0, proc.stderr
    assert "case.nml:4: &slope: ref_strain_pct: not used with soil = 'linear'" in proc.stderr
