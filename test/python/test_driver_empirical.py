"""Batch driver, analysis 'empirical': the two example inputs (the numbers their comments
state; every row equal to the Python API, seispulse.empirical, on the inputs of that
row; on records the inputs are the records' own intensity measures and Sa(1.5 Ts), and
the rigorous columns seispulse.newmark.rigid), a bad record among good ones, which
models a case gets, and the located one-line input errors (file, line, group, key)."""
import csv
import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from seispulse import empirical, newmark, records

HERE = Path(__file__).resolve().parent
RECORDS = HERE.parent / "regression" / "records"


def run(driver, cwd, text, name="case.nml"):
    (Path(cwd) / name).write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True,
                          timeout=120)


def read_rows(path):
    """[{column name (no unit): value}] of the driver's CSV (model names and the status,
    "ok" or "failed", as str)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = [h.rsplit(" (", 1)[0] for h in rows[0]]
    return [{n: (x if n in ("model", "status") else float(x))
             for n, x in zip(names, row)} for row in rows[1:]]


def api(row, slammer=False):
    """The Python API's result for the model and inputs of a driver row."""
    m, ky = row["model"], row["ky"]
    pga, pgv, ia, mag = row["pga"], row["pgv"], row["arias"], row["magnitude"]
    ts, sa, tm = row["ts"], row["sa_15ts"], row["tm"]
    calls = {
        "jibson_1993": lambda: empirical.jibson_1993(ia, ky),
        "jibson_1998": lambda: empirical.jibson_1998(ia, ky),
        "jibson_2007_ratio": lambda: empirical.jibson_2007_ratio(ky, pga),
        "jibson_2007_ratio_m": lambda: empirical.jibson_2007_ratio_m(ky, pga, mag),
        "jibson_2007_arias": lambda: empirical.jibson_2007_arias(ia, ky),
        "jibson_2007_arias_ratio": lambda: empirical.jibson_2007_arias_ratio(ia, ky, pga),
        "ambraseys_menu_1988": lambda: empirical.ambraseys_menu_1988(ky, pga),
        "saygili_rathje_2008_pga": lambda: empirical.saygili_rathje_2008_pga(ky, pga),
        "saygili_rathje_2008_pgv": lambda: empirical.saygili_rathje_2008_pgv(ky, pga, pgv),
        "saygili_rathje_2008_pgv_ia": lambda: empirical.saygili_rathje_2008_pgv_arias(
            ky, pga, pgv, ia),
        "rathje_saygili_2009": lambda: empirical.rathje_saygili_2009(ky, pga, mag),
        "bray_travasarou_2007": lambda: empirical.bray_travasarou_2007(ky, ts, sa, mag,
                                                                       slammer=slammer),
        "rathje_antonakos_2011_m": lambda: empirical.rathje_antonakos_2011(
            ky, ts, tm, pga, magnitude=mag, slammer=slammer),
        "rathje_antonakos_2011_pgv": lambda: empirical.rathje_antonakos_2011(
            ky, ts, tm, pga, pgv=pgv, slammer=slammer),
    }
    return calls[m]()


def check_rows_against_api(rows, slammer=False):
    for row in rows:
        r = api(row, slammer)
        assert row["disp"] == pytest.approx(r.disp_cm, rel=1e-14), row["model"]
        assert row["sigma"] == pytest.approx(r.sigma, rel=1e-15), row["model"]
        assert row["base"] == pytest.approx(10.0 if r.log_base == "log10" else math.e)
        assert row["d16"] == pytest.approx(r.d16_cm, rel=1e-14)
        assert row["d84"] == pytest.approx(r.d84_cm, rel=1e-14)
        assert row["p_failure"] == pytest.approx(empirical.probability_of_failure(r.disp_cm),
                                                 rel=1e-14, abs=1e-300)
        if row["model"] == "bray_travasarou_2007":
            assert row["p_zero"] == pytest.approx(r.p_zero, rel=1e-14)
        else:
            assert math.isnan(row["p_zero"])
        if row["model"].startswith("rathje_antonakos"):
            assert row["kmax"] == pytest.approx(r.kmax, rel=1e-15)
        assert row["status"] == "ok"


def test_example_input(driver, source_root, tmp_path):
    proc = subprocess.run([driver, str(source_root / "input" / "empirical.nml")],
                          cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    rows = read_rows(tmp_path / "out" / "empirical.csv")
    assert len(rows) == 3 * 14          # every model has its inputs
    check_rows_against_api(rows)
    # the numbers the input's comment states, at ky = 0.1 g
    at = {r["model"]: r for r in rows if r["ky"] == 0.1}
    stated = {"jibson_2007_ratio": 6.1, "ambraseys_menu_1988": 17.4,
              "saygili_rathje_2008_pgv": 21.3, "rathje_saygili_2009": 25.3,
              "rathje_antonakos_2011_m": 20.6, "bray_travasarou_2007": 45.2}
    for model, value in stated.items():
        assert round(at[model]["disp"], 1) == value, model
    assert f"{at['bray_travasarou_2007']['p_zero']:.0e}" == "3e-08"
    assert all(math.isnan(r["newmark_exact"]) for r in rows)


def test_records_example(driver, source_root, tmp_path):
    proc = subprocess.run([driver, str(source_root / "input" / "empirical_records.nml")],
                          cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    rows = read_rows(tmp_path / "out" / "empirical_records_empirical.csv")
    # no Ia/PGV given but the records have them: all 14 models, 2 records x 2 ky
    assert len(rows) == 2 * 2 * 14
    check_rows_against_api(rows)
    for case, name in ((1, "quake_a.AT2"), (2, "quake_b.csv")):
        rec = records.read(source_root / "input" / "records" / name).scaled_to_pga(0.3)
        im = records.intensity(rec)
        sa = records.spectral_acceleration(rec, 1.5 * 0.2, damping=0.05)
        mine = [r for r in rows if r["case"] == case]
        for r in mine:
            assert r["pga"] == pytest.approx(im.pga, rel=1e-15)
            assert r["pgv"] == pytest.approx(100 * im.pgv, rel=1e-15)
            assert r["arias"] == pytest.approx(im.arias, rel=1e-15)
            assert r["tm"] == pytest.approx(im.tm, rel=1e-15)
            assert r["sa_15ts"] == pytest.approx(float(sa), rel=1e-15)
            assert (r["magnitude"], r["ts"]) == (6.5, 0.2)
            exact = newmark.rigid(rec, ky=r["ky"]).max_disp
            slam = newmark.rigid(rec, ky=r["ky"], method="slammer").max_disp
            assert r["newmark_exact"] == pytest.approx(100 * exact, rel=1e-14)
            assert r["newmark_slammer"] == pytest.approx(100 * slam, rel=1e-14)


def test_nearly_rigid_takes_pga_for_sa(driver, tmp_path):
    shutil.copytree(RECORDS, tmp_path / "records")
    proc = run(driver, tmp_path, """&run analysis = 'empirical', output = 'out/t' /
&records files = 'records/quake_a.AT2' /
&empirical ky = 0.1, magnitude = 7.0, ts = 0.03 /
""")
    assert proc.returncode == 0, proc.stderr
    rows = read_rows(tmp_path / "out" / "t_empirical.csv")
    bt = [r for r in rows if r["model"] == "bray_travasarou_2007"][0]
    assert bt["sa_15ts"] == bt["pga"]
    check_rows_against_api(rows)


def test_slammer_rules(driver, tmp_path):
    proc = run(driver, tmp_path, """&run analysis = 'empirical', output = 'out/s' /
&empirical ky = 0.105, pga = 0.1, pgv = 12.0, magnitude = 7.2, ts = 0.02, sa_15ts = 0.1,
  tm = 0.15, slammer = .true. /
""")
    assert proc.returncode == 0, proc.stderr
    rows = read_rows(tmp_path / "out" / "s_empirical.csv")
    check_rows_against_api([r for r in rows if r["model"] in (
        "bray_travasarou_2007", "rathje_antonakos_2011_m", "rathje_antonakos_2011_pgv")],
        slammer=True)
    ra = [r for r in rows if r["model"] == "rathje_antonakos_2011_m"][0]
    assert ra["disp"] == 0.0 and ra["kmax"] > 0.105     # SLAMMER: 0 as ky > PGA


def test_models_by_inputs_and_ky_above_pga(driver, tmp_path):
    proc = run(driver, tmp_path, """&run analysis = 'empirical', output = 'out/m' /
&empirical ky = 0.1, 0.25, pga = 0.2 /
""")
    assert proc.returncode == 0, proc.stderr
    rows = read_rows(tmp_path / "out" / "m_empirical.csv")
    assert [r["model"] for r in rows[:3]] == ["jibson_2007_ratio", "ambraseys_menu_1988",
                                               "saygili_rathje_2008_pga"]
    assert len(rows) == 6
    above = rows[3:]
    assert all(r["disp"] == 0.0 and math.isnan(r["sigma"]) and r["status"] == "ok"
               for r in above)


def test_bad_record_fails_its_rows(driver, tmp_path):
    shutil.copytree(RECORDS, tmp_path / "records")
    proc = run(driver, tmp_path, """&run analysis = 'empirical', output = 'out/f' /
&records files = 'records/quake_b.csv', 'records/nothing.AT2' /
&empirical ky = 0.1, magnitude = 6.0 /
""")
    assert proc.returncode == 1
    assert "nothing.AT2" in proc.stderr and "rows failed" in proc.stderr
    rows = read_rows(tmp_path / "out" / "f_empirical.csv")
    good = [r for r in rows if r["case"] == 1]
    bad = [r for r in rows if r["case"] == 2]
    assert good and all(r["status"] == "ok" for r in good)
    assert bad and all(r["status"] == "failed" and math.isnan(r["disp"]) for r in bad)
    assert len(good) == len(bad)


@pytest.mark.parametrize("body, expected", [
    ("&empirical pga = 0.3 /", "case.nml:2: &empirical: ky: missing"),
    ("&empirical ky = 0.1, -0.2, pga = 0.3 /", "case.nml:2: &empirical: ky(2) = -0.2: must be"),
    ("&empirical ky = 0.1 /", "case.nml:2: &empirical: pga, pgv, arias, magnitude, ts, "
                              "sa_15ts, tm: none given"),
    ("&empirical ky = 0.1, pga = 0.3, 0.4, pgv = 1, 2, 3 /",
     "case.nml:2: &empirical: pga: 2 values for 3 cases"),
    ("&empirical ky = 0.1, magnitude = 12 /", "case.nml:2: &empirical: magnitude = 12"),
    ("&empirical ky = 0.1, ts = -1, pga = 0.3 /", "case.nml:2: &empirical: ts = -1"),
    ("&empirical ky = 0.1, pga = 0.3, damping = 1.5 /", "case.nml:2: &empirical: damping = 1.5"),
    ("&empirical ky = 0.1, pga = 0.3, kyy = 2 /", "case.nml:2: &empirical: kyy"),
    ("&empirical ky = 0.1, pga = 0.3 /\n&newmark ky = 0.1 /", "&newmark: not a group of "
                                                              "analysis 'empirical'"),
    ("&records files = 'a.AT2' /\n&empirical ky = 0.1, pga = 0.3 /",
     "case.nml:3: &empirical: pga: not with &records"),
])
def test_input_errors_are_located(driver, tmp_path, body, expected):
    proc = run(driver, tmp_path, "&run analysis = 'empirical', output = 'out/e' /\n" + body
               + "\n")
    assert proc.returncode == 2
    assert expected in proc.stderr, proc.stderr
    assert proc.stderr.count("\n") == 1
    assert not (tmp_path / "out").exists()


def _write_record(path, accel, dt=0.02):
    lines = ["# " + path.stem, "# time_s, accel_g"]
    lines += [f"{i * dt:.2f},{a!r}" for i, a in enumerate(accel)]
    path.write_text("\n".join(lines) + "\n")


def test_record_without_energy_gives_no_sliding(driver, tmp_path):
    """A record of zeros (PGA = 0, Ia = 0) among good ones: every model's row is there,
    with disp 0 (no sliding, as at ky >= PGA), status 0 and P(D = 0) = 1, and the run is
    a success; the good record's rows are the API's."""
    shutil.copytree(RECORDS, tmp_path / "records")
    _write_record(tmp_path / "records" / "zero.csv", [0.0] * 201)
    proc = run(driver, tmp_path, """&run analysis = 'empirical', output = 'out/z' /
&records files = 'records/zero.csv', 'records/quake_b.csv' /
&empirical ky = 0.1, magnitude = 6.5, ts = 0.2 /
""")
    assert proc.returncode == 0, proc.stderr
    rows = read_rows(tmp_path / "out" / "z_empirical.csv")
    zero = [r for r in rows if r["case"] == 1]
    good = [r for r in rows if r["case"] == 2]
    assert len(zero) == len(good) == 14
    assert [r["model"] for r in zero] == [r["model"] for r in good]
    assert all(r["disp"] == 0.0 and r["d16"] == 0.0 and r["d84"] == 0.0
               and r["p_failure"] == 0.0 and r["status"] == "ok" for r in zero)
    assert [r["p_zero"] for r in zero if r["model"] == "bray_travasarou_2007"] == [1.0]
    assert all(r["pga"] == 0.0 and r["arias"] == 0.0 and math.isnan(r["tm"]) for r in zero)
    check_rows_against_api(good)


def test_tm_nan_fails_unified_rows_and_names_the_record(driver, tmp_path):
    """A record with energy but no Fourier amplitude at 0.25-20 Hz (dt = 3 s: Tm NaN)
    keeps its unified-model rows, failed (status failed, NaN) with a message naming tm, next to
    the other models' results; the summary names that record, and only it."""
    shutil.copytree(RECORDS, tmp_path / "records")
    _write_record(tmp_path / "records" / "slow.csv", [0.0, 0.2, -0.1, 0.15, 0.0], dt=3.0)
    proc = run(driver, tmp_path, """&run analysis = 'empirical', output = 'out/t' /
&records files = 'records/quake_b.csv', 'records/slow.csv' /
&empirical ky = 0.05, magnitude = 6.5, ts = 0.2 /
""")
    assert proc.returncode == 1
    rows = read_rows(tmp_path / "out" / "t_empirical.csv")
    slow = [r for r in rows if r["case"] == 2]
    assert len(slow) == 14 and math.isnan(slow[0]["tm"]) and slow[0]["pga"] == 0.2
    ra = [r for r in slow if r["model"].startswith("rathje_antonakos_2011")]
    assert len(ra) == 2 and all(r["status"] == "failed" and math.isnan(r["disp"]) for r in ra)
    check_rows_against_api([r for r in slow if not r["model"].startswith("rathje_antonakos")])
    assert "rathje_antonakos_2011_m, ky = 0.05: tm = NaN" in proc.stderr
    last = proc.stderr.strip().splitlines()[-1]
    assert "2 of 28 rows failed (records: 2 'slow')" in last, last
    assert "quake_b" not in last

