#!/usr/bin/env python3
"""Driver regression: run the driver on a case (in place, so that files it names are
found relative to it) with a scratch directory as the working directory, and compare
its CSV table with the reference table <case>.ref (computed independently by
make_refs.py with mpmath). Also checks that the text table holds the same numbers.

In the CSV files a quoted cell is text (the record names of analysis 'newmark') and an
unquoted cell a number; a column of text in the reference is compared exactly.
Numbers are compared with a relative tolerance; NaN matches NaN only, an infinity the
same infinity only. A case whose .nml has a comment line "! expect exit status N"
must end with that status (default 0) and still write its table.

An analysis that writes several tables (analysis 'walls') names the one to compare:
out/*_TABLE.csv.

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


def number(x):
    try:
        return float(x)
    except ValueError:
        return None


def read_csv(path):
    """Header and rows: a quoted cell is a str, any other a float (ValueError if it is
    not a number)."""
    with open(path, newline="") as f:
        header = next(csv.reader(f))
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    return header, rows


def text_columns(ref_rows):
    return {j for row in ref_rows for j, x in enumerate(row) if isinstance(x, str)}


def read_txt(path, ntext):
    """Rows of the text table; the first ntext (0 or 1) cells are text (they may hold
    blanks: the numbers are split off from the right)."""
    rows = []
    for line in Path(path).read_text().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        if ntext:
            rows.append(line)          # split by split_txt once the width is known
        else:
            rows.append([float(x) for x in line.split()])
    return rows


def split_txt(line, ncol):
    """[label, numbers...] of a text-table line with one text column of ncol."""
    parts = line.rsplit(None, ncol - 1)
    if len(parts) != ncol:
        return None
    return [parts[0].strip()] + [number(x) for x in parts[1:]]


def main():
    # meson may pass the driver relative to the build dir; the run happens elsewhere
    driver = str(Path(sys.argv[1]).resolve())
    case, ref = Path(sys.argv[2]).resolve(), Path(sys.argv[3])
    pattern = f"out/*_{sys.argv[4]}.csv" if len(sys.argv) > 4 else "out/*.csv"
    ref_header, ref_rows = read_csv(ref)
    texts = text_columns(ref_rows)
    if texts - {0}:
        print(f"FAIL reference {ref.name}: only the first column may be text")
        return 1
    m = re.search(r"^\s*!\s*expect exit status (\d+)", case.read_text(), re.MULTILINE)
    expected_status = int(m.group(1)) if m else 0
    with tempfile.TemporaryDirectory() as scratch:
        proc = subprocess.run([driver, str(case)], cwd=scratch, capture_output=True, text=True)
        if proc.returncode != expected_status:
            print(f"FAIL driver exited {proc.returncode} (expected {expected_status}): "
                  f"{proc.stderr.strip()}")
            return 1
        outputs = sorted(Path(scratch).glob(pattern))
        if len(outputs) != 1:
            print(f"FAIL expected one CSV table, found {[p.name for p in outputs]}")
            return 1
        try:
            header, rows = read_csv(outputs[0])
        except ValueError as exc:
            print(f"FAIL {outputs[0].name}: an unquoted cell is not a number ({exc})")
            return 1
        txt_rows = read_txt(outputs[0].with_suffix(".txt"), len(texts))
    failures = 0
    if texts:
        txt_rows = [split_txt(line, len(ref_header)) for line in txt_rows]
        if any(r is None for r in txt_rows):
            print(f"FAIL a text-table row does not have {len(ref_header)} cells")
            return 1
    if header != ref_header:
        print(f"FAIL header {header} != {ref_header}")
        failures += 1
    if len(rows) != len(ref_rows):
        print(f"FAIL {len(rows)} rows, reference has {len(ref_rows)}")
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
            if j in texts or isinstance(x, str) or isinstance(z, str) or z is None:
                # text: exactly the reference's, and the same in both tables
                if not (x == y == z):
                    print(f"FAIL row {i + 1}, {header[j]}: {x!r} (text table {z!r}) vs "
                          f"reference {y!r}")
                    failures += 1
                continue
            if not close(x, y, RTOL * max(abs(y), scales[j] * 1e-3) if math.isfinite(y) else 0):
                print(f"FAIL row {i + 1}, {header[j]}: {x!r} vs reference {y!r}")
                failures += 1
            if not close(z, x, 1e-15 * max(abs(x), 1e-300) if math.isfinite(x) else 0):
                print(f"FAIL row {i + 1}, {header[j]}: text table {z!r} vs CSV {x!r}")
                failures += 1
            if failures > 10:
                break
    checked = len(rows) * len(ref_header)
    print(f"{checked - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
