"""Batch driver, &records `list` (a CSV file of records) and glob patterns in `files`:
every column of a list against the same records given in the namelist and against the
Python API, paths relative to the list's folder, quoted fields, errors that name the
list file, its line and the column, patterns (sorted, directories left out, a pattern
that matches nothing refused), files and list together, an echo that re-runs the same
job and stays short, and a list of 2000 records (no limit of 500)."""
import csv
import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from seispulse import newmark, records
from driver_echo import echo_text, with_output

HERE = Path(__file__).resolve().parent
RECORDS = HERE.parent / "regression" / "records"


def run(driver, cwd, text, name="case.nml"):
    path = Path(cwd) / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def newmark_input(records_group, ky="0.05, 0.1", output="o"):
    return (f"&run analysis='newmark', output='{output}' /\n&records {records_group} /\n"
            f"&newmark ky = {ky} /\n")


def table(path):
    """(names, rows) of a newmark CSV table: the quoted record names, the other cells."""
    with open(path, newline="") as f:
        next(f)
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    return [r[0] for r in rows], [r[1:] for r in rows]


@pytest.fixture
def recs(tmp_path):
    """The synthetic regression records under tmp_path/data/recs."""
    shutil.copytree(RECORDS, tmp_path / "data" / "recs")
    return tmp_path / "data" / "recs"


def python_row(path, ky, fmt="auto", units=None, dt=None, scale=1.0, target=None,
               polarity=1):
    """pga, scale, max_normal (m), max_inverse (m) of one record and ky from the Python
    API (seispulse.records, seispulse.newmark)."""
    rec = records.read(str(path), fmt=fmt, units=units, dt=dt)
    if polarity < 0:
        rec = rec.inverted()
    rec = rec.scaled_to_pga(target) if target else rec.scaled(scale)
    n = newmark.rigid(rec.accel, rec.dt, ky)
    r = newmark.rigid(-rec.accel, rec.dt, ky)
    return rec.pga, n.max_disp, r.max_disp


# ---------------------------------------------------------------- every column

LIST = '''# a suite of four records, every column (any order, any case)
Polarity, PATH, Name, SCALE, target_pga, units, format, dt

-1, recs/quake_a.AT2, "Kobe, TAK ""090""", 2.0, , , at2,
, "recs/quake_b.csv", b_scaled, , 0.3, g, ,
  # a comment between rows
1, recs/quake_c.txt, c_col, 1.5, , cm/s2, column, 0.01
, recs/quake_b.csv, , , , , , 0.02
'''


def test_list_every_column_matches_the_namelist_and_python(driver, tmp_path, recs):
    (tmp_path / "data" / "suite.csv").write_text(LIST)
    proc = run(driver, tmp_path, newmark_input("list = 'data/suite.csv'"))
    assert proc.returncode == 0, proc.stderr
    names, rows = table(tmp_path / "o_newmark.csv")
    # the name column labels the rows; an empty name: the file stem
    assert names == ['Kobe, TAK "090"'] * 2 + ["b_scaled"] * 2 + ["c_col"] * 2 \
        + ["quake_b"] * 2
    # the same records through the namelist's own keys (one value per file)
    nml = ("files = 'data/recs/quake_a.AT2', 'data/recs/quake_b.csv', "
           "'data/recs/quake_c.txt', 'data/recs/quake_b.csv', "
           "polarity = -1, 1, 1, 1, scale = 2.0, 1.0, 1.5, 1.0, "
           "target_pga = 0, 0.3, 0, 0, units = 'auto', 'g', 'cm/s2', 'auto', "
           "format = 'at2', 'auto', 'column', 'auto', dt = 0, 0, 0.01, 0.02")
    proc2 = run(driver, tmp_path, newmark_input(nml, output="n"), name="n.nml")
    assert proc2.returncode == 0, proc2.stderr
    names2, rows2 = table(tmp_path / "n_newmark.csv")
    assert rows == rows2
    assert names2[::2] == ["quake_a", "quake_b", "quake_c", "quake_b"]
    # and the Python API, row by row (pga, scale, max_normal, max_inverse)
    cases = [dict(fmt="at2", scale=2.0, polarity=-1), dict(units="g", target=0.3),
             dict(fmt="column", units="cm/s2", dt=0.01, scale=1.5), dict(dt=0.02)]
    files = ["quake_a.AT2", "quake_b.csv", "quake_c.txt", "quake_b.csv"]
    for i, (f, kw) in enumerate(zip(files, cases)):
        for j, ky in enumerate([0.05, 0.1]):
            pga, mn, mi = python_row(recs / f, ky, **kw)
            row = rows[2 * i + j]
            assert row[0] == pytest.approx(pga, rel=1e-5)
            assert row[2] == ky
            assert row[4] == pytest.approx(mn, rel=1e-12, abs=1e-15)
            assert row[8] == pytest.approx(mi, rel=1e-12, abs=1e-15)
    assert rows[0][1] == -2.0 and rows[4][1] == 1.5
    # the header comments name the list line of each record
    txt = (tmp_path / "o_newmark.txt").read_text()
    assert "# record 1: recs/quake_a.AT2 (list line 4): format at2" in txt
    assert "# record 4: recs/quake_b.csv (list line 8): format" in txt


def test_list_empty_cells_take_the_records_values(driver, tmp_path, recs):
    """An empty cell is the &records value for all records; a cell replaces it."""
    (tmp_path / "data" / "s.csv").write_text("path,scale\nrecs/quake_a.AT2,\n"
                                             "recs/quake_a.AT2,3\n")
    proc = run(driver, tmp_path, newmark_input("list = 'data/s.csv', scale = 2, "
                                               "polarity = -1"))
    assert proc.returncode == 0, proc.stderr
    _, rows = table(tmp_path / "o_newmark.csv")
    assert [r[1] for r in rows] == [-2.0, -2.0, -3.0, -3.0]


def test_files_and_list_together_files_first(driver, tmp_path, recs):
    (tmp_path / "data" / "s.csv").write_text("name,path\nfrom_list,recs/quake_b.csv\n")
    proc = run(driver, tmp_path, newmark_input(
        "files = 'data/recs/quake_d.dat', list = 'data/s.csv'", ky="0.1"))
    assert proc.returncode == 0, proc.stderr
    names, _ = table(tmp_path / "o_newmark.csv")
    assert names == ["quake_d", "from_list"]


# ---------------------------------------------------------------- errors

ERRORS = {
    "not_a_number": ("path,target_pga\nrecs/quake_a.AT2,0.3\n\nrecs/quake_b.csv,abc\n",
                     "s.csv:4: target_pga = 'abc': not a number"),
    "negative_scale": ("path,scale\nrecs/quake_a.AT2,-2\n",
                       "s.csv:2: scale = '-2': must be a finite factor > 0"),
    "polarity": ("path,polarity\nrecs/quake_a.AT2,2\n",
                 "s.csv:2: polarity = '2': must be 1 or -1"),
    "units": ("path,units\nrecs/quake_a.AT2,furlong\n",
              "s.csv:2: units = 'furlong': unknown acceleration unit"),
    "format": ("path,format\nrecs/quake_a.AT2,peer\n",
               "s.csv:2: format = 'peer': unknown format (allowed: auto, at2"),
    "dt": ("path,dt\nrecs/quake_a.AT2,-0.01\n", "s.csv:2: dt = '-0.01': must be a finite"),
    "column_without_dt": ("path,format\nrecs/quake_c.txt,column\n",
                          "s.csv:2: dt: the record 'recs/quake_c.txt' has format 'column'"),
    "scale_and_target": ("path,scale,target_pga\nrecs/quake_a.AT2,2,0.3\n",
                         "s.csv:2: scale = 2.0, target_pga = 0.3: both"),
    "unknown_column": ("path,weight\nrecs/quake_a.AT2,1\n",
                       "s.csv:1: column 'weight': unknown column (allowed: path, name"),
    "twice": ("path,scale,Scale\nrecs/quake_a.AT2,1,1\n", "s.csv:1: column 'Scale': given twice"),
    "no_path": ("name,scale\na,1\n", "s.csv:1: no column 'path' in the header"),
    "empty_path": ("path,name\n,a\n", "s.csv:2: path: empty"),
    "fields": ("path,name\nrecs/quake_a.AT2,Kobe, TAK\n",
               "s.csv:2: 3 fields, the header has 2 (a field with a comma is quoted"),
    "quote": ('path,name\nrecs/quake_a.AT2,"Kobe\n', 's.csv:2: field 2: no closing quote'),
    "after_quote": ('path,name\nrecs/quake_a.AT2,"Kobe" x\n',
                    "s.csv:2: field 2: text after the closing quote"),
    "no_rows": ("# nothing\npath,name\n", "s.csv: no record (one row per record"),
    "empty": ("\n# only a comment\n", "s.csv: no header row"),
    "nul": ("path\nrecs/quake_a.AT2\x00\n", "s.csv:2: a NUL byte at column 17: not a text"),
    "long_line": ("path\n" + "x" * 300000 + "\n", "s.csv:2: line longer than 262144"),
}


@pytest.mark.parametrize("case", sorted(ERRORS))
def test_list_errors_name_file_line_and_column(driver, tmp_path, recs, case):
    text, expected = ERRORS[case]
    (tmp_path / "data" / "s.csv").write_text(text)
    proc = run(driver, tmp_path, newmark_input("list = 'data/s.csv'"))
    assert proc.returncode == 2, proc.stderr
    line = proc.stderr.strip()
    assert len(line.splitlines()) == 1, line
    assert line.startswith("seispulse: error: case.nml:2: &records: list = 'data/s.csv': "
                           "data/s.csv"), line
    assert expected in line, line
    assert not list(tmp_path.glob("o_*")), "no output after an input error"


@pytest.mark.parametrize("target, expected", [
    ("missing.csv", "data/missing.csv: cannot open the list file: no such file"),
    ("recs", "data/recs: is a directory, not a list file"),
])
def test_list_file_not_readable(driver, tmp_path, recs, target, expected):
    proc = run(driver, tmp_path, newmark_input(f"list = 'data/{target}'"))
    assert proc.returncode == 2
    assert expected in proc.stderr, proc.stderr


def test_files_or_list_required(driver, tmp_path):
    proc = run(driver, tmp_path, newmark_input("format = 'auto'"))
    assert proc.returncode == 2
    assert "&records: files: missing" in proc.stderr and "list = 'suite.csv'" in proc.stderr


# ---------------------------------------------------------------- glob patterns

def test_pattern_is_sorted_and_skips_directories(driver, tmp_path, recs):
    (recs / "quake_z.dir").mkdir()            # a directory the pattern matches: left out
    proc = run(driver, tmp_path, newmark_input("files = 'data/recs/quake_[abdz].*', "
                                               "polarity = -1", ky="0.1"))
    assert proc.returncode == 0, proc.stderr
    names, rows = table(tmp_path / "o_newmark.csv")
    assert names == ["quake_a", "quake_b", "quake_d"]
    explicit = ", ".join(f"'data/recs/quake_{c}.{e}'" for c, e in
                         zip("abd", ["AT2", "csv", "dat"]))
    proc2 = run(driver, tmp_path, newmark_input(f"files = {explicit}, polarity = -1",
                                                ky="0.1", output="n"), name="n.nml")
    assert proc2.returncode == 0, proc2.stderr
    assert table(tmp_path / "n_newmark.csv") == (names, rows)


def test_pattern_values_per_entry(driver, tmp_path, recs):
    """One value per files entry: every file a pattern matches takes its entry's value."""
    proc = run(driver, tmp_path, newmark_input(
        "files = 'data/recs/quake_[ab].*', 'data/recs/quake_d.dat', scale = 2, 3", ky="0.1"))
    assert proc.returncode == 0, proc.stderr
    names, rows = table(tmp_path / "o_newmark.csv")
    assert names == ["quake_a", "quake_b", "quake_d"]
    assert [r[1] for r in rows] == [2.0, 2.0, 3.0]


@pytest.mark.parametrize("pattern, expected", [
    ("data/recs/*.xyz", "files(1) = 'data/recs/*.xyz': the pattern matches no file"),
    ("data/*", "files(1) = 'data/*': the pattern matches no file (only 1 directories"),
])
def test_pattern_matching_no_file_is_an_input_error(driver, tmp_path, recs, pattern,
                                                     expected):
    proc = run(driver, tmp_path, newmark_input(f"files = '{pattern}'"))
    assert proc.returncode == 2
    assert "case.nml:2: &records: " + expected in proc.stderr, proc.stderr


def test_more_than_500_files_through_a_pattern(driver, tmp_path, recs):
    many = tmp_path / "many"
    many.mkdir()
    for i in range(501):
        shutil.copy(recs / "quake_b.csv", many / f"r{i:04d}.csv")
    proc = run(driver, tmp_path, newmark_input("files = 'many/r*.csv'", ky="0.1"))
    assert proc.returncode == 0, proc.stderr
    names, rows = table(tmp_path / "o_newmark.csv")
    assert names == [f"r{i:04d}" for i in range(501)]
    assert all(r == rows[0] for r in rows)


# ---------------------------------------------------------------- the echo

def test_echo_keeps_list_and_patterns_and_reruns(driver, tmp_path, recs):
    (tmp_path / "data" / "s.csv").write_text("path,name,scale\nrecs/quake_b.csv,B,2\n")
    proc = run(driver, tmp_path, newmark_input(
        "files = 'data/recs/quake_a.AT2', 'data/recs/quake_[c].*', list = 'data/s.csv', "
        "units = 'auto', 'cm/s2', "
        "format = 'auto', 'column', dt = 0, 0.01", output="out/a"))
    assert proc.returncode == 0, proc.stderr
    text = echo_text(tmp_path, proc.stdout)
    # relative to the echo's folder (out/), the pattern and the list as given
    assert "files = '../data/recs/quake_a.AT2', '../data/recs/quake_[c].*'" in text
    assert "list = '../data/s.csv'" in text
    assert "units = 'auto', 'cm/s2'" in text
    (tmp_path / "out" / "b.nml").write_text(with_output(text, "out/a", "out/b"))
    proc2 = subprocess.run([driver, "out/b.nml"], cwd=tmp_path, capture_output=True,
                           text=True, timeout=120)
    assert proc2.returncode == 0, proc2.stderr
    assert table(tmp_path / "out" / "a_newmark.csv") == table(tmp_path / "out" /
                                                               "b_newmark.csv")
    names, _ = table(tmp_path / "out" / "a_newmark.csv")
    assert names == ["quake_a"] * 2 + ["quake_c"] * 2 + ["B"] * 2


def test_echo_with_a_list_keeps_one_value_for_all(driver, tmp_path, recs):
    """With a list, one value given for all records stays one value (it is also the value
    of the list's empty cells); the echo re-runs to the same table."""
    (tmp_path / "data" / "s.csv").write_text("path,scale\nrecs/quake_b.csv,\n"
                                             "recs/quake_b.csv,3\n")
    proc = run(driver, tmp_path, newmark_input(
        "files = 'data/recs/quake_a.AT2', 'data/recs/quake_d.dat', list = 'data/s.csv', "
        "scale = 2", ky="0.1"))
    assert proc.returncode == 0, proc.stderr
    text = echo_text(tmp_path, proc.stdout)
    assert "    scale = 2.0\n" in text
    (tmp_path / "b.nml").write_text(with_output(text, "o", "b"))
    proc2 = subprocess.run([driver, "b.nml"], cwd=tmp_path, capture_output=True, text=True,
                           timeout=120)
    assert proc2.returncode == 0, proc2.stderr
    first = table(tmp_path / "o_newmark.csv")
    assert first == table(tmp_path / "b_newmark.csv")
    assert [r[1] for r in first[1]] == [2.0, 2.0, 2.0, 3.0]


def test_list_of_2000_records(driver, tmp_path, recs):
    lines = ["path,name,scale,polarity"]
    for i in range(2000):
        f = ("recs/quake_a.AT2", "recs/quake_b.csv")[i % 2]
        lines.append(f"{f},r{i},{1 + i / 1000},{(1, -1)[i % 3 == 0]}")
    (tmp_path / "data" / "big.csv").write_text("\n".join(lines) + "\n")
    ky = [0.05, 0.1, 0.2]
    proc = run(driver, tmp_path, newmark_input("list = 'data/big.csv'",
                                               ky=", ".join(map(str, ky))))
    assert proc.returncode == 0, proc.stderr
    names, rows = table(tmp_path / "o_newmark.csv")
    assert len(rows) == 2000 * len(ky)
    assert names[::len(ky)] == [f"r{i}" for i in range(2000)]
    scales = np.array([r[1] for r in rows[::len(ky)]])
    expected = np.array([(1 + i / 1000) * (1, -1)[i % 3 == 0] for i in range(2000)])
    np.testing.assert_array_equal(scales, expected)
    # a row far past 500 against the Python API
    i = 1501
    pga, mn, mi = python_row(recs / "quake_b.csv", 0.1, scale=1 + i / 1000)
    row = rows[len(ky) * i + 1]
    assert row[0] == pytest.approx(pga, rel=1e-5)
    assert row[4] == pytest.approx(mn, rel=1e-12) and row[8] == pytest.approx(mi, rel=1e-12)
    # the echo names the list: a few lines, not 2000 files
    text = echo_text(tmp_path, proc.stdout)
    assert "list = 'data/big.csv'" in text and len(text.splitlines()) < 15
    assert not math.isnan(row[4])


def test_failed_list_record_named_by_its_list_line(driver, tmp_path, recs):
    """A record of the list that cannot be read is named by its line in the list file (not
    by a files(i) index that the input does not have); its rows fail, exit status 1."""
    (tmp_path / "data" / "l.csv").write_text(
        "path,name\n# a comment line\nrecs/quake_a.AT2,a\nrecs/missing.AT2,gone\n")
    proc = run(driver, tmp_path, newmark_input("list = 'data/l.csv'"))
    assert proc.returncode == 1, proc.stderr
    assert ("case.nml:2: &records: list line 4 = 'recs/missing.AT2': " in proc.stderr), \
        proc.stderr
    assert "files(2)" not in proc.stderr
