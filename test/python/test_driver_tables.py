"""The driver's table files: numbers in the CSV as Python's repr (the shortest text that
reads back to the same double, csv_digits = 0) or with csv_digits digits, numbers in the
text table as C's %.<digits>g, integer and category columns, one-row summaries, unique
column names, file names without a doubled table name, and atomic writes (temporary
.part files renamed at the end; a failed run removes the tables of an earlier run with
the same prefix)."""
import csv
import re
import subprocess
from pathlib import Path

import pytest

from driver_tables import read_summary_txt

HERE = Path(__file__).resolve().parent
INPUT = HERE.parents[1] / "input"

#: Awkward doubles (as Python writes them): the driver echoes each in the eta1 column.
AWKWARD = ["0.1", "0.3333333333333333", "1e-05", "123456.5", "5e-324",
           "1.7976931348623157e+308", "0.05", "9007199254740992.0", "1e+16", "2.5e-07"]
SLIDING = ("&run analysis='sliding', output='{out}' {run} /\n"
           "&pulse amp=4.0, duration=0.5, beta=1.0, full=.true. /\n"
           "&block eta_list = {etas} /\n")


def run(driver, cwd, text, name="case.nml"):
    (Path(cwd) / name).write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def csv_cells(path):
    """Header and rows of raw CSV cells, a quoted cell as ('text',)."""
    with open(path, newline="") as f:
        header = next(csv.reader(f))
        rows = [[(c,) if q else c for c, q in zip(row, quoted(line))]
                for line, row in ((ln, next(csv.reader([ln])))
                                  for ln in f.read().splitlines())]
    return header, rows


def quoted(line):
    """Whether each cell of a CSV line is quoted (no commas inside quotes here)."""
    return [cell.startswith('"') for cell in line.split(",")]


def text_rows(path):
    return [ln.split() for ln in Path(path).read_text().splitlines()
            if not ln.startswith("#")]


def test_csv_is_repr_round_trip(driver, tmp_path):
    """csv_digits = 0 (default): each awkward double is written as Python's repr, the
    shortest text that reads back to the same double."""
    proc = run(driver, tmp_path, SLIDING.format(out="a", run="", etas=", ".join(AWKWARD)))
    assert proc.returncode == 0, proc.stderr
    header, rows = csv_cells(tmp_path / "a_sliding.csv")
    eta1 = [r[header.index("eta1 (-)")] for r in rows]
    assert eta1 == AWKWARD
    assert [repr(float(x)) for x in eta1] == AWKWARD
    # the case column is an integer, the mode a quoted name
    assert [r[0] for r in rows] == [str(i) for i in range(1, len(AWKWARD) + 1)]
    assert all(isinstance(r[header.index("mode (-)")], tuple) for r in rows)
    # every number of the table: the text is repr of its value (shortest, round trip)
    # (an integer only in the integer column, case)
    for r in rows:
        for j, c in enumerate(r):
            if j == header.index("case (-)"):
                assert c == str(int(c)), c
            elif not isinstance(c, tuple) and c not in ("nan", "inf", "-inf"):
                assert c == repr(float(c)), c


def test_digits_and_csv_digits(driver, tmp_path):
    """&run digits = 3, csv_digits = 12: the text table holds %.3g and the CSV %.12g of
    the same doubles (those of a csv_digits = 0 run)."""
    etas = ", ".join(AWKWARD)
    assert run(driver, tmp_path, SLIDING.format(out="full", run="", etas=etas),
               "full.nml").returncode == 0
    proc = run(driver, tmp_path, SLIDING.format(out="short", run=", digits = 3, "
                                                "csv_digits = 12", etas=etas), "short.nml")
    assert proc.returncode == 0, proc.stderr
    h, full = csv_cells(tmp_path / "full_sliding.csv")
    _, short = csv_cells(tmp_path / "short_sliding.csv")
    txt = text_rows(tmp_path / "short_sliding.txt")
    assert len(txt) == len(full) == len(short) == len(AWKWARD)
    for rf, rs, rt in zip(full, short, txt):
        assert len(rf) == len(rs) == len(rt) == len(h)
        for j, (x, y, z) in enumerate(zip(rf, rs, rt)):
            if isinstance(x, tuple):                       # the mode: a name
                assert x == y and z == x[0]
            elif h[j] == "case (-)":                       # an integer
                assert x == y == z
            else:
                assert y == "%.12g" % float(x), (h[j], x, y)
                assert z == "%.3g" % float(x), (h[j], x, z)


@pytest.mark.parametrize("key, value", [("digits", 0), ("digits", 18), ("csv_digits", -1),
                                        ("csv_digits", 18)])
def test_digits_out_of_range(driver, tmp_path, key, value):
    proc = run(driver, tmp_path, SLIDING.format(out="o", run=f", {key} = {value}",
                                                etas="0.5"))
    assert proc.returncode == 2
    assert f"case.nml:1: &run: {key} = {value}: must be" in proc.stderr, proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["case.nml"]


def test_one_row_summary_layout(driver, tmp_path):
    """A one-case sliding table: `name  value  unit` lines in the .txt, one header and
    one row in the .csv."""
    proc = run(driver, tmp_path, SLIDING.format(out="one", run="", etas="0.3"))
    assert proc.returncode == 0, proc.stderr
    s = read_summary_txt(tmp_path / "one_sliding.txt")
    assert s["case"] == ("1", "-") and s["eta1"] == ("0.3", "-")
    assert s["mode"][0] in ("slip", "stick") and s["t_m1"][1] == "s"
    lines = (tmp_path / "one_sliding.csv").read_text().splitlines()
    assert len(lines) == 2 and lines[0].startswith("case (-),mu (-),eta1 (-)")


def test_failed_run_removes_earlier_tables_and_parts(driver, tmp_path):
    """A run that fails on an input error leaves no .part file and removes the tables
    an earlier run wrote under the same prefix (stale results never remain); the
    tables of another prefix stay."""
    good = SLIDING.format(out="out/p", run="", etas="0.3, 0.5") \
        + "&history npts = 11 /\n"
    assert run(driver, tmp_path, good).returncode == 0
    assert run(driver, tmp_path, good.replace("out/p", "out/q"), "q.nml").returncode == 0
    written = sorted(p.name for p in (tmp_path / "out").iterdir())
    assert written == ["p_input.nml", "p_sliding.csv", "p_sliding.txt",
                       "p_sliding_history.csv", "p_sliding_history.txt", "q_input.nml",
                       "q_sliding.csv", "q_sliding.txt", "q_sliding_history.csv",
                       "q_sliding_history.txt"]
    # the same prefix, now with a bad value: exit 2 and p's tables gone, with the echo
    # of its input (table 'input', out/p_input.nml)
    proc = run(driver, tmp_path, good.replace("npts = 11", "npts = 1"))
    assert proc.returncode == 2, proc.stderr
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == written[5:]


def test_failure_after_writing_leaves_no_part(driver, tmp_path):
    """The second table cannot be renamed into place (a directory has its name): the run
    fails with status 2 and leaves neither .part files nor the first table."""
    (tmp_path / "o_sliding_history.csv").mkdir()
    proc = run(driver, tmp_path, SLIDING.format(out="o", run="", etas="0.3")
               + "&history npts = 11 /\n")
    assert proc.returncode == 2
    # at the line of &run (its `output` names the files)
    line = 1 + SLIDING.split("&run")[0].count("\n")
    assert f"case.nml:{line}: &run: output: " in proc.stderr, proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["case.nml", "o_sliding_history.csv"]


EXAMPLES = sorted(INPUT.glob("*.nml"))


@pytest.mark.parametrize("example", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_example_tables(driver, tmp_path, example):
    """Every input/ example: no .part left, column names unique in each table (CSV and
    text header), no doubled table name in a file name, and the files named on standard
    output are the files written."""
    proc = subprocess.run([driver, str(example)], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert not list(tmp_path.rglob("*.part"))
    written = sorted(str(p.relative_to(tmp_path)) for p in tmp_path.rglob("*")
                     if p.is_file() and p.suffix in (".csv", ".txt", ".nml"))
    named = sorted(w for line in proc.stdout.splitlines() if " written to " in line
                   for w in re.split(r",? and |, ", line.split(" written to ")[1]))
    assert written and written == named
    for name in written:
        words = Path(name).stem.split("_")
        for k in range(1, len(words) // 2 + 1):
            for i in range(len(words) - 2 * k + 1):
                assert words[i:i + k] != words[i + k:i + 2 * k], name
        if name.endswith(".nml"):
            continue            # the echo of the input (test_driver_echo.py)
        if name.endswith(".csv"):
            with open(tmp_path / name, newline="") as f:
                header = next(csv.reader(f))
            cols = [h.rsplit(" (", 1)[0] for h in header]
            assert len(set(cols)) == len(cols), (name, cols)
        else:
            heads = [ln for ln in (tmp_path / name).read_text().splitlines()
                     if ln.startswith("#")]
            # a table ends its header with the names and the (units) lines; a summary
            # has `name  value  unit` lines instead
            if len(heads) >= 2 and re.fullmatch(r"#\s*(\([^)]*\)\s*)+", heads[-1]):
                cols = heads[-2][1:].split()
            else:
                cols = [ln.split()[0] for ln in (tmp_path / name).read_text().splitlines()
                        if not ln.startswith("#")]
            assert len(set(cols)) == len(cols), (name, cols)
