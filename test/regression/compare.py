#!/usr/bin/env python3
"""Driver regression: run the driver on a case (in place, so that files it names are
found relative to it) with a scratch directory as the working directory, and compare
its CSV table with the reference table <case>.ref (computed independently by
make_refs.py with mpmath). Also checks that the text table holds the same cells.

In the CSV files a quoted cell is text (the record names of analysis 'newmark', the
names of a category column such as an outcome or a status) and an unquoted cell a
number; a text cell of the reference is compared exactly. Numbers are compared with a
relative tolerance; NaN matches NaN only, an infinity the same infinity only. A case
whose .nml has a comment line "! expect exit status N" must end with that status
(default 0) and still write its table.

The text table: each number must be the CSV's number written as C's "%.<digits>g"
(digits: the &run key, default 6), each text cell the same text; a one-row table may
be written as `name  value  unit` lines (a summary).

An analysis that writes several tables (analysis 'walls') names the one to compare:
the file of table TABLE (table_path below: out/<base>_<TABLE>.csv, an overlap of the
base and the table name written once).

usage: compare.py DRIVER CASE.nml CASE.ref [TABLE]
"""
import csv
import math
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

RTOL = 1e-12


def close(x, y, tol):
    """x matches y within tol; NaN matches NaN only, an infinity the same infinity only
    (an ordinary difference would let NaN and inf pass every comparison)."""
    if math.isnan(y) or math.isnan(x):
        return math.isnan(x) and math.isnan(y)
    if math.isinf(y) or math.isinf(x):
        return x == y
    return abs(x - y) <= tol



def read_csv(path):
    """Header and rows: a quoted cell is a str, any other a float (ValueError if it is
    not a number)."""
    with open(path, newline="") as f:
        header = next(csv.reader(f))
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    return header, rows


def text_columns(ref_rows):
    return {j for row in ref_rows for j, x in enumerate(row) if isinstance(x, str)}


def table_path(prefix, table, ext):
    """The driver's file name of `table` under output prefix `prefix` (driver_tables'
    table_path): <dir>/<base>_<table>.<ext>, a `_`-word suffix of base equal to a
    `_`-word prefix of table written once."""
    k = prefix.rfind("/")
    d, base = prefix[:k + 1], prefix[k + 1:]
    bw, tw = (base.split("_") if base else []), table.split("_")
    over = next((n for n in range(min(len(bw), len(tw)), 0, -1) if bw[len(bw) - n:] == tw[:n]),
                0)
    if not base:
        name = table
    elif over == len(tw):
        name = base
    else:
        name = "_".join([base] + tw[over:])
    return f"{d}{name}.{ext}"


def read_txt(path):
    """The lines of the text table that are not comments."""
    return [line for line in Path(path).read_text().splitlines()
            if line.strip() and not line.startswith("#")]


def split_txt(line, ncol, ntext):
    """The ncol cells of a text-table line; with ntext = 1 the first cell is a label that
    may hold blanks (the other cells are split off from the right)."""
    parts = line.rsplit(None, ncol - 1) if ntext else line.split()
    if len(parts) != ncol:
        return None
    return [p.strip() for p in parts]


def split_summary(lines, header):
    """The cells of a summary (`name  value  unit` lines, one per column of header's
    "name (unit)" cells), or None if the lines are not that."""
    if len(lines) != len(header):
        return None
    cells = []
    for line, h in zip(lines, header):
        name, unit = h.rsplit(" (", 1)
        unit = unit[:-1]
        if not (line.startswith(name + " ") and line.rstrip().endswith(" " + unit)):
            return None
        cells.append(line.rstrip()[len(name):len(line.rstrip()) - len(unit)].strip())
    return cells


def txt_matches(z, x, digits):
    """The text-table cell z is the CSV cell x: the same text, the same integer, or x
    written as C's %.<digits>g (Python's % operator is C's)."""
    if isinstance(x, str):
        return z == x
    if z == "%.*g" % (digits, x):
        return True
    # an integer column: the CSV cell and the text cell are the same integer
    return math.isfinite(x) and x == int(x) and z == str(int(x))


def main():
    # meson may pass the driver relative to the build dir; the run happens elsewhere
    driver = str(Path(sys.argv[1]).resolve())
    case, ref = Path(sys.argv[2]).resolve(), Path(sys.argv[3])
    ref_header, ref_rows = read_csv(ref)
    texts = text_columns(ref_rows)
    nml = case.read_text()
    m = re.search(r"^\s*!\s*expect exit status (\d+)", nml, re.MULTILINE)
    expected_status = int(m.group(1)) if m else 0
    m = re.search(r"^[^!]*\bdigits\s*=\s*(\d+)", nml, re.MULTILINE | re.IGNORECASE)
    digits = int(m.group(1)) if m else 6
    m = re.search(r"^[^!]*\boutput\s*=\s*['\"]([^'\"]*)['\"]", nml, re.MULTILINE)
    prefix = m.group(1) if m else "out/x"
    with tempfile.TemporaryDirectory() as scratch:
        proc = subprocess.run([driver, str(case)], cwd=scratch, capture_output=True, text=True)
        if proc.returncode != expected_status:
            print(f"FAIL driver exited {proc.returncode} (expected {expected_status}): "
                  f"{proc.stderr.strip()}")
            return 1
        leftover = sorted(p.name for p in Path(scratch).rglob("*.part"))
        if leftover:
            print(f"FAIL temporary files left: {leftover}")
            return 1
        if len(sys.argv) > 4:
            outputs = [Path(scratch) / table_path(prefix, sys.argv[4], "csv")]
            outputs = [p for p in outputs if p.exists()]
        else:
            outputs = sorted(Path(scratch).glob("out/*.csv"))
        if len(outputs) != 1:
            print(f"FAIL expected one CSV table, found {[p.name for p in outputs]}")
            return 1
        try:
            header, rows = read_csv(outputs[0])
        except ValueError as exc:
            print(f"FAIL {outputs[0].name}: an unquoted cell is not a number ({exc})")
            return 1
        txt_lines = read_txt(outputs[0].with_suffix(".txt"))
    failures = 0
    if header != ref_header:
        print(f"FAIL header {header} != {ref_header}")
        failures += 1
    if len(rows) != len(ref_rows):
        print(f"FAIL {len(rows)} rows, reference has {len(ref_rows)}")
        return 1
    if len(rows) == 1 and split_summary(txt_lines, header) is not None:
        txt_rows = [split_summary(txt_lines, header)]
    else:
        ntext = 1 if 0 in texts else 0
        txt_rows = [split_txt(line, len(ref_header), ntext) for line in txt_lines]
        if any(r is None for r in txt_rows):
            print(f"FAIL a text-table row does not have {len(ref_header)} cells")
            return 1
    # the text table must hold every cell too (zip below would silently stop short)
    if len(txt_rows) != len(rows) or any(len(r) != len(ref_header) for r in rows + txt_rows):
        print(f"FAIL the CSV and text tables do not both have {len(rows)} rows of "
              f"{len(ref_header)} cells")
        return 1
    scales = [1.0 if j in texts else
              max((abs(r[j]) for r in ref_rows if math.isfinite(r[j])), default=0.0) or 1.0
              for j in range(len(ref_header))]
    for i, (row, ref_row, txt_row) in enumerate(zip(rows, ref_rows, txt_rows)):
        for j, (x, y, z) in enumerate(zip(row, ref_row, txt_row)):
            if not txt_matches(z, x, digits):
                print(f"FAIL row {i + 1}, {header[j]}: text table {z!r} vs CSV {x!r} "
                      f"({digits} digits)")
                failures += 1
            if j in texts or isinstance(x, str):
                # text: exactly the reference's
                if x != y:
                    print(f"FAIL row {i + 1}, {header[j]}: {x!r} vs reference {y!r}")
                    failures += 1
                continue
            if not close(x, y, RTOL * max(abs(y), scales[j] * 1e-3) if math.isfinite(y) else 0):
                print(f"FAIL row {i + 1}, {header[j]}: {x!r} vs reference {y!r}")
                failures += 1
            if failures > 10:
                break
    checked = len(rows) * len(ref_header)
    print(f"{checked - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
