"""Batch driver, analysis 'newmark': the example input, agreement with the Python API
(seispulse.records + seispulse.newmark) on every format and mode, a bad record among
good ones (its rows fail, the others are computed, exit status 1), the located one-line
input errors (exit 2, no output), progress on stderr, the quoted record names of the
CSV, and record paths relative to the input file."""
import csv
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from seispulse import newmark, records
from driver_tables import coded, g_text

HERE = Path(__file__).resolve().parent
RECORDS = HERE.parent / "regression" / "records"

NUMERIC = ["pga (g)", "scale (-)", "ky (g)", "ky_up (g)", "max_normal (m)",
           "max_normal_cm (cm)", "final_normal (m)", "final_normal_cm (cm)", "max_inverse (m)",
           "max_inverse_cm (cm)", "final_inverse (m)", "final_inverse_cm (cm)", "status (-)"]
HEADER = ["record (-)"] + NUMERIC
RESULTS = NUMERIC[4:12]


def run(driver, cwd, text, name="case.nml", args=None):
    path = Path(cwd) / name
    path.write_text(text)
    return subprocess.run([driver, *(args or [name])], cwd=cwd, capture_output=True,
                          text=True, timeout=120)


def with_records(tmp_path):
    """The synthetic regression records, copied to tmp_path/records."""
    shutil.copytree(RECORDS, tmp_path / "records")
    return tmp_path / "records"


def read_table(path):
    """(header, record names, numbers) of a CSV table of the driver; the names must be
    quoted (QUOTE_NONNUMERIC turns every unquoted cell into a float), the status too
    ("ok", "failed": 0, 1 in the numbers)."""
    with open(path, newline="") as f:
        header = next(csv.reader(f))
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    assert all(isinstance(r[0], str) for r in rows), "record names are quoted"
    assert all(isinstance(x, float) for r in rows for x in r[1:-1])
    return header, [r[0] for r in rows], coded(header, rows)


def read_txt(path, ncol):
    """(names, cells) of the text table (names may hold blanks)."""
    names, cells = [], []
    for line in Path(path).read_text().splitlines():
        if line.startswith("#"):
            continue
        parts = line.rsplit(None, ncol - 1)
        names.append(parts[0].strip())
        cells.append(parts[1:])
    return names, cells


def txt_of(data):
    """The text table's cells of the numbers of read_table: 6 significant digits, the
    status by name."""
    return [[g_text(x) for x in row[:-1]] + [("ok", "failed")[int(row[-1])]] for row in data]


def newmark_run(driver, tmp_path, records_group, newmark_group, output="o"):
    proc = run(driver, tmp_path, f"&run analysis='newmark', output='{output}' /\n"
                                 f"&records {records_group} /\n&newmark {newmark_group} /\n")
    return proc


def table_of(tmp_path, output="o"):
    return read_table(tmp_path / f"{output}_newmark.csv")


# ---------------------------------------------------------------- example input

def test_example_input_runs(driver, source_root, tmp_path):
    proc = subprocess.run([driver, str(source_root / "input" / "newmark_example.nml")],
                          cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert "out/newmark_example_newmark.txt" in proc.stdout
    assert "out/newmark_example_newmark.csv" in proc.stdout
    assert "&RECORDS" in proc.stdout.upper() and "&NEWMARK" in proc.stdout.upper()
    header, names, data = read_table(tmp_path / "out" / "newmark_example_newmark.csv")
    assert header == HEADER
    assert names == ["quake_a"] * 4 + ["quake_b"] * 4
    assert np.all(data[:, -1] == 0)
    np.testing.assert_allclose(data[:, 0], 0.3, rtol=2e-3)         # PGA after scaling
    assert np.all(data[:4, 1] > 0) and np.all(data[4:, 1] < 0)      # polarity 1, -1
    txt_names, txt = read_txt(tmp_path / "out" / "newmark_example_newmark.txt", len(HEADER))
    assert txt_names == names
    assert txt == txt_of(data)
    assert all(row[-1] == "ok" for row in txt)
    progress = [ln for ln in proc.stderr.splitlines() if ln.startswith("newmark: record ")]
    assert len(progress) == 2 and progress[0].startswith("newmark: record 1/2: quake_a")


EXAMPLES = sorted((HERE.parents[1] / "input").glob("*.nml"))


@pytest.mark.parametrize("example", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_every_example_input_runs(driver, tmp_path, example):
    """Every commented example under input/ (of any analysis) runs from another
    directory and writes its tables."""
    proc = subprocess.run([driver, str(example)], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert "written to" in proc.stdout
    assert list(tmp_path.rglob("*.csv")) and list(tmp_path.rglob("*.txt"))


# ---------------------------------------------------------------- the Python API

def python_rows(path, ky, mode="down", method="exact", ky_up=None, k_down=1.0, k_up=1.0,
                fmt="auto", units=None, dt=None, scale=1.0, target=None, rounding="exact",
                polarity=1):
    """The table rows of one record, from seispulse.records and seispulse.newmark."""
    rec = records.read(path, fmt=fmt, units=units, dt=dt)
    if polarity < 0:
        rec = rec.inverted()
    rec = rec.scaled_to_pga(target, rounding=rounding) if target else rec.scaled(scale)
    rows = []
    for i, k in enumerate(ky):
        kw = dict(mode=mode, method=method)
        if mode == "asym":
            kw.update(ky_up=ky_up[i] if isinstance(ky_up, list) else ky_up, k_down=k_down,
                      k_up=k_up)
        n = newmark.rigid(rec.accel, rec.dt, k, **kw)
        r = newmark.rigid(-rec.accel, rec.dt, k, **kw)
        up = {"down": math.inf, "both": k}.get(mode, kw.get("ky_up"))
        rows.append([rec.pga, rec.scale_factor, k, up, n.max_disp, 100 * n.max_disp, n.final_disp,
                     100 * n.final_disp, r.max_disp, 100 * r.max_disp, r.final_disp,
                     100 * r.final_disp, 0.0])
    return rows


CASES = [
    # (records group, newmark group, python_rows keyword sets per file, ky list)
    ("files='records/quake_a.AT2', 'records/quake_c.txt', units='auto', 'cm/s2', "
     "dt=0, 0.005", "ky=0.04, 0.1, 0.2",
     [dict(path="quake_a.AT2"), dict(path="quake_c.txt", units="cm/s2", dt=0.005)],
     dict(ky=[0.04, 0.1, 0.2])),
    ("files='records/quake_b.csv', 'records/quake_d.dat', format='slammer', 'time_accel', "
     "units='g', 'm/s2', scale=1.3, 2.0, polarity=-1, 1",
     "ky=0.07, 0.13, mode='both'",
     [dict(path="quake_b.csv", fmt="slammer", scale=1.3, polarity=-1),
      dict(path="quake_d.dat", fmt="time_accel", units="m/s2", scale=2.0)],
     dict(ky=[0.07, 0.13], mode="both")),
    ("files='records/quake_a.AT2', 'records/quake_b.csv', target_pga=0.35, 0.28, "
     "pga_rounding='slammer'", "ky=0.05, 0.11, method='slammer'",
     [dict(path="quake_a.AT2", target=0.35, rounding="slammer"),
      dict(path="quake_b.csv", target=0.28, rounding="slammer")],
     dict(ky=[0.05, 0.11], method="slammer")),
    ("files='records/quake_d.dat', units='m/s2', scale=2.4",
     "ky=0.06, 0.12, mode='asym', ky_up=0.2, 0.09, k_down=1.05, k_up=0.95",
     [dict(path="quake_d.dat", units="m/s2", scale=2.4)],
     dict(ky=[0.06, 0.12], mode="asym", ky_up=[0.2, 0.09], k_down=1.05, k_up=0.95)),
]


@pytest.mark.parametrize("rgroup, ngroup, per_file, blocks", CASES)
def test_agrees_with_python_api(driver, tmp_path, rgroup, ngroup, per_file, blocks):
    rdir = with_records(tmp_path)
    proc = newmark_run(driver, tmp_path, rgroup, ngroup)
    assert proc.returncode == 0, proc.stderr
    header, names, data = table_of(tmp_path)
    assert header == HEADER
    expected = []
    for kw in per_file:
        kw = dict(kw)
        path = rdir / kw.pop("path")
        expected += python_rows(path, **blocks, **kw)
        assert names.count(path.stem) == len(blocks["ky"])
    expected = np.array(expected)
    assert data.shape == expected.shape
    np.testing.assert_allclose(data, expected, rtol=1e-12, atol=1e-15)
    assert np.any(data[:, 4] > 1e-4), "some block slides"


def test_scale_column_is_signed_factor(driver, tmp_path):
    with_records(tmp_path)
    proc = newmark_run(driver, tmp_path, "files='records/quake_a.AT2', 'records/quake_b.csv',"
                       " scale=2.0, polarity=1, -1", "ky=0.1")
    assert proc.returncode == 0, proc.stderr
    _, _, data = table_of(tmp_path)
    assert list(data[:, 1]) == [2.0, -2.0]
    np.testing.assert_allclose(data[:, 0], [2 * 0.395579, 2 * 0.235738], rtol=1e-15)
    # polarity -1 swaps normal and inverse
    proc = newmark_run(driver, tmp_path, "files='records/quake_b.csv', scale=2.0", "ky=0.1",
                       output="p")
    _, _, plus = table_of(tmp_path, "p")
    np.testing.assert_array_equal(plus[0, 4:8], data[1, 8:12])
    np.testing.assert_array_equal(plus[0, 8:12], data[1, 4:8])


def test_incline_rows(driver, tmp_path):
    rdir = with_records(tmp_path)
    proc = newmark_run(driver, tmp_path, "files='records/quake_b.csv', target_pga=0.5",
                       "mu=0.3, 0.45, slope_deg=12, xi_deg=5")
    assert proc.returncode == 0, proc.stderr
    header, names, data = table_of(tmp_path)
    assert header == HEADER[:3] + ["mu (-)"] + HEADER[3:]
    rec = records.read(rdir / "quake_b.csv").scaled_to_pga(0.5)
    for i, mu in enumerate([0.3, 0.45]):
        inc = newmark.incline(mu, 12.0, 5.0)
        n = newmark.rigid(rec.accel, rec.dt, incline=inc)
        r = newmark.rigid(-rec.accel, rec.dt, incline=inc)
        assert data[i, 2] == mu and data[i, 3] == inc.ky and data[i, 4] == inc.ky_up
        np.testing.assert_allclose(data[i, [5, 7, 9, 11]],
                                   [n.max_disp, n.final_disp, r.max_disp, r.final_disp],
                                   rtol=1e-12, atol=1e-15)


# ---------------------------------------------------------------- failed rows

BAD_CSV = "# bad record\n# time_s, accel_g\n0.00, 0.01\n0.02, 0.0.3\n0.04, 0.02\n"


def test_bad_record_fails_its_rows_only(driver, tmp_path):
    with_records(tmp_path)
    (tmp_path / "records" / "bad.csv").write_text(BAD_CSV)
    good = "files='records/quake_b.csv', 'records/quake_c.txt', dt=0, 0.005, " \
           "units='g', 'cm/s2'"
    proc = newmark_run(driver, tmp_path, good, "ky=0.05, 0.1", output="good")
    assert proc.returncode == 0, proc.stderr
    _, _, ref = table_of(tmp_path, "good")
    text = ("&run analysis='newmark', output='mixed' /\n"
            "&records\n"
            "  files='records/quake_b.csv', 'records/bad.csv', 'records/quake_c.txt'\n"
            "  dt=0, 0, 0.005, units='g', 'g', 'cm/s2' /\n"
            "&newmark ky=0.05, 0.1 /\n")
    proc = run(driver, tmp_path, text, name="mixed.nml")
    assert proc.returncode == 1, proc.stderr
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("seispulse: error: ")]
    assert len(errors) == 2, proc.stderr
    first = errors[0]
    for word in ["mixed.nml:2:", "&records", "files(2) = 'records/bad.csv'",
                 "records/bad.csv, line 4", "0.0.3"]:
        assert word in first, first
    assert errors[1] == "seispulse: error: 2 of 6 rows failed (records: 2 'bad')"
    header, names, data = table_of(tmp_path, "mixed")
    assert names == ["quake_b", "quake_b", "bad", "bad", "quake_c", "quake_c"]
    np.testing.assert_array_equal(data[[0, 1, 4, 5]], ref)
    assert np.all(np.isnan(data[2:4, [0, 1] + list(range(4, 12))]))
    assert list(data[2:4, 2]) == [0.05, 0.1] and np.all(np.isinf(data[2:4, 3]))
    assert list(data[:, -1]) == [0, 0, 1, 1, 0, 0]
    assert [ln.rsplit(",", 1)[1] for ln in (tmp_path / "mixed_newmark.csv").read_text()
            .splitlines()[1:]] == ['"ok"', '"ok"', '"failed"', '"failed"', '"ok"', '"ok"']
    txt = (tmp_path / "mixed_newmark.txt").read_text()
    assert "FAILED" in txt and "records/bad.csv, line 4" in txt
    progress = [ln for ln in proc.stderr.splitlines() if ln.startswith("newmark: record ")]
    assert [p.split(":")[1] for p in progress] == [" record 1/3", " record 2/3",
                                                   " record 3/3"]


def test_unscalable_record_fails(driver, tmp_path):
    (tmp_path / "zero.txt").write_text("0\n0\n0\n")
    (tmp_path / "ok.txt").write_text("0\n0.3\n-0.2\n0\n")
    proc = newmark_run(driver, tmp_path, "files='zero.txt', 'ok.txt', dt=0.01, "
                       "target_pga=0.2", "ky=0.05")
    assert proc.returncode == 1
    assert "files(1) = 'zero.txt'" in proc.stderr and "target_pga" in proc.stderr
    _, _, data = table_of(tmp_path)
    assert list(data[:, -1]) == [1, 0] and data[1, 0] == pytest.approx(0.2, rel=1e-15)


# ---------------------------------------------------------------- input errors

R = "files='records/quake_a.AT2', 'records/quake_b.csv'"
BAD = [
    # (records group, newmark group, words of the one-line message)
    (R + ", fomat='auto'", "ky=0.1", ["case.nml:2:", "&records", "fomat", "unknown key"]),
    (R, "ky=0.1, kyup=0.2", ["case.nml:3:", "&newmark", "kyup", "unknown key"]),
    (R, "ky=0.1, 0.0", ["case.nml:3:", "&newmark", "ky(2) = 0.0", "> 0"]),
    (R, "ky=-0.1", ["&newmark", "ky = -0.1", "> 0"]),
    (R, "ky=0.1, nan, 0.2", ["&newmark", "ky(2)", "missing or NaN"]),
    (R + ", dt=0.01, 0.02, 0.01", "ky=0.1", ["&records", "dt: 3 values for 2 files"]),
    (R + ", format='at2', 'slammer', 'auto'", "ky=0.1",
     ["&records", "format: 3 values for 2 files", "one per file"]),
    (R, "ky=0.1, mode='asym'", ["&newmark", "ky_up: missing", "asym"]),
    (R, "ky=0.1, ky_up=0.2", ["&newmark", "ky_up: only for mode 'asym'"]),
    (R, "ky=0.1, 0.2, 0.3, mode='asym', ky_up=0.1, 0.2", ["&newmark", "ky_up: 2 values for 3"]),
    (R, "ky=0.1, mode='asym', ky_up=0.2, k_down=0", ["&newmark", "k_down = 0", "> 0"]),
    (R, "ky=0.1, mu=0.3", ["&newmark", "ky, mu", "one of them"]),
    (R, "mu=0.3, mode='down'", ["&newmark", "mode = 'down'", "asym"]),
    (R, "mu=0.3, ky_up=0.2", ["&newmark", "ky_up: not with mu"]),
    (R, "mu=0.2, slope_deg=20", ["&newmark", "mu"]),
    (R, "ky=0.1, slope_deg=10", ["&newmark", "slope_deg: only with mu"]),
    (R, "mode='down'", ["&newmark", "ky: missing"]),
    (R + ", format='peer'", "ky=0.1", ["&records", "format = 'peer'", "unknown format",
                                       "at2"]),
    (R + ", units='ft/s2'", "ky=0.1", ["&records", "units = 'ft/s2'", "unknown units",
                                       "cm/s2"]),
    (R, "ky=0.1, method='rk4'", ["&newmark", "method = 'rk4'", "exact, slammer"]),
    (R, "ky=0.1, mode='up'", ["&newmark", "mode = 'up'", "down, both, asym"]),
    (R, "ky=0.1, g=0", ["&newmark", "g = 0.0", "> 0"]),
    (R + ", polarity=0", "ky=0.1", ["&records", "polarity = 0", "1 or -1"]),
    (R + ", scale=-1", "ky=0.1", ["&records", "scale = -1.0", "> 0"]),
    (R + ", scale=2, target_pga=0.3", "ky=0.1", ["&records", "scale, target_pga",
                                                  "files(1)"]),
    (R + ", target_pga=-0.3", "ky=0.1", ["&records", "target_pga = -0.3"]),
    (R + ", pga_rounding='floor'", "ky=0.1", ["&records", "pga_rounding = 'floor'"]),
    (R + ", dt=-0.01", "ky=0.1", ["&records", "dt = -0.01"]),
    ("files='records/quake_c.txt', format='column'", "ky=0.1",
     ["&records", "dt: files(1) = 'records/quake_c.txt'", "column", "dt > 0"]),
    ("files='records/quake_a.AT2', '', 'records/quake_b.csv'", "ky=0.1",
     ["&records", "files(2)", "missing"]),
    ("format='auto'", "ky=0.1", ["&records", "files: missing"]),
    (R, "ky=abc", ["&newmark", "ky", "bad value"]),
]


@pytest.mark.parametrize("rgroup, ngroup, words", BAD)
def test_bad_input_one_line_exit_2_no_output(driver, tmp_path, rgroup, ngroup, words):
    with_records(tmp_path)
    proc = newmark_run(driver, tmp_path, rgroup, ngroup)
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    for word in words:
        assert word in lines[0], lines[0]
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml", "records"]


@pytest.mark.parametrize("text, words", [
    ("&run analysis='newmark', output='o' /\n&newmark ky=0.1 /\n",
     ["&records", "missing group"]),
    ("&run analysis='newmark', output='o' /\n&records files='a.csv' /\n",
     ["&newmark", "missing group"]),
    ("&run analysis='newmark', output='o' /\n&records files='a.csv' /\n&newmark ky=0.1 /\n"
     "&pulse kind='ricker' /\n", ["case.nml:4:", "&pulse", "not a group of analysis"]),
])
def test_missing_or_foreign_groups(driver, tmp_path, text, words):
    proc = run(driver, tmp_path, text)
    assert proc.returncode == 2
    line = proc.stderr.strip()
    assert len(line.splitlines()) == 1 and all(w in line for w in words), line
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml"]


# ---------------------------------------------------------------- paths, names, echo

def test_paths_relative_to_the_input_file(driver, tmp_path):
    case_dir = tmp_path / "cases"
    case_dir.mkdir()
    shutil.copytree(RECORDS, case_dir / "records")
    (case_dir / "c.nml").write_text(
        "&run analysis='newmark', output='out/c' /\n"
        f"&records files='records/quake_b.csv', '{RECORDS / 'quake_a.AT2'}' /\n"
        "&newmark ky=0.1 /\n")
    work = tmp_path / "work"
    work.mkdir()
    proc = subprocess.run([driver, "../cases/c.nml"], cwd=work, capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    _, names, data = read_table(work / "out" / "c_newmark.csv")
    assert names == ["quake_b", "quake_a"] and np.all(data[:, -1] == 0)


def test_csv_quotes_odd_names(driver, tmp_path):
    odd = 'odd, "name" x'
    shutil.copy(RECORDS / "quake_b.csv", tmp_path / (odd + ".csv"))
    proc = newmark_run(driver, tmp_path, "files='odd, \"name\" x.csv'", "ky=0.1, 0.2")
    assert proc.returncode == 0, proc.stderr
    lines = (tmp_path / "o_newmark.csv").read_text().splitlines()
    assert lines[1].startswith('"odd, ""name"" x",')
    _, names, data = table_of(tmp_path)
    assert names == [odd, odd]
    txt_names, txt = read_txt(tmp_path / "o_newmark.txt", len(HEADER))
    assert txt_names == names
    assert txt == txt_of(data)
    header_lines = [ln for ln in (tmp_path / "o_newmark.txt").read_text().splitlines()
                    if ln.startswith("#record") or ln.startswith("#(-)")]
    assert len(header_lines) == 2
    # the label column is left-adjusted and padded to the longest name, so the numeric
    # columns line up with their names
    width = len(odd)
    assert header_lines[0][1:1 + width] == "record".ljust(width)
    assert header_lines[1][1:1 + width] == "(-)".ljust(width)
    data_line = (tmp_path / "o_newmark.txt").read_text().splitlines()[-1]
    assert data_line[1:1 + width] == odd and data_line[1 + width] == " "
    assert len(data_line) == len(header_lines[0]) == len(header_lines[1])


def test_echo_reads_back_to_the_same_table(driver, tmp_path):
    with_records(tmp_path)
    rg = ("files='records/quake_a.AT2', 'records/quake_c.txt', units='auto', 'cm/s2', "
          "dt=0, 0.005, target_pga=0.3, 0, scale=1, 1.2, polarity=-1, pga_rounding='slammer'")
    proc = newmark_run(driver, tmp_path, rg, "ky=0.05, 0.1, mode='asym', ky_up=0.2, "
                       "k_down=1.1", output="first")
    assert proc.returncode == 0, proc.stderr
    echo = proc.stdout.split("newmark table written")[0]
    echo = re.sub(r'OUTPUT="first\s*"', 'OUTPUT="second"', echo)
    (tmp_path / "echo.nml").write_text(echo)
    proc2 = subprocess.run([driver, "echo.nml"], cwd=tmp_path, capture_output=True,
                           text=True, timeout=120)
    assert proc2.returncode == 0, proc2.stderr
    _, n1, d1 = table_of(tmp_path, "first")
    _, n2, d2 = table_of(tmp_path, "second")
    assert n1 == n2
    np.testing.assert_array_equal(d1, d2)


def test_progress_one_line_per_record(driver, tmp_path):
    with_records(tmp_path)
    files = ", ".join(["'records/quake_b.csv'"] * 5)
    proc = newmark_run(driver, tmp_path, f"files={files}, target_pga=0.4", "ky=0.1")
    assert proc.returncode == 0, proc.stderr
    lines = proc.stderr.splitlines()
    assert len(lines) == 5
    for i, line in enumerate(lines, start=1):
        assert re.fullmatch(rf"newmark: record {i}/5: quake_b \(npts 200, dt 0\.02 s, "
                            r"PGA 0\.2357 g -> 0\.4 g\)", line), line


def test_unused_rounding_warns(driver, tmp_path):
    with_records(tmp_path)
    proc = newmark_run(driver, tmp_path, R + ", pga_rounding='slammer'", "ky=0.1")
    assert proc.returncode == 0
    assert "pga_rounding: not used without target_pga" in proc.stderr
