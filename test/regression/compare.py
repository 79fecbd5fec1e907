#!/usr/bin/env python3
"""Driver regression: run the driver on a case in a scratch directory and compare
its CSV table with the reference table <case>.ref (computed independently by
make_refs.py with mpmath). Also checks that the text table holds the same numbers.

usage: compare.py DRIVER CASE.nml CASE.ref
"""
import csv
import math
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
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in row] for row in rows[1:]]


def read_txt(path):
    rows = []
    for line in Path(path).read_text().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(x) for x in line.split()])
    return rows


def main():
    # meson may pass the driver relative to the build dir; the run happens elsewhere
    driver = str(Path(sys.argv[1]).resolve())
    case, ref = Path(sys.argv[2]), Path(sys.argv[3])
    ref_header, ref_rows = read_csv(ref)
    with tempfile.TemporaryDirectory() as scratch:
        shutil.copy(case, scratch)
        proc = subprocess.run([driver, case.name], cwd=scratch, capture_output=True, text=True)
        if proc.returncode != 0:
            print(f"FAIL driver exited {proc.returncode}: {proc.stderr.strip()}")
            return 1
        outputs = sorted(Path(scratch).glob("out/*.csv"))
        if len(outputs) != 1:
            print(f"FAIL expected one CSV table, found {[p.name for p in outputs]}")
            return 1
        header, rows = read_csv(outputs[0])
        txt_rows = read_txt(outputs[0].with_suffix(".txt"))
    failures = 0
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
    scales = [max((abs(r[j]) for r in ref_rows if math.isfinite(r[j])), default=0.0) or 1.0
              for j in range(len(ref_header))]
    for i, (row, ref_row, txt_row) in enumerate(zip(rows, ref_rows, txt_rows)):
        for j, (x, y, z) in enumerate(zip(row, ref_row, txt_row)):
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
