"""Helpers shared by the driver tests of the analyses: read a CSV
table the driver wrote, run an example input file of input/."""
import csv
import subprocess

import numpy as np


def read_table(path):
    """{column name: array} of a CSV table of the driver (names without units): a column
    of numbers as floats, a column of double-quoted cells (labels, category names) as
    str."""
    with open(path, newline="") as f:
        names = [h.rsplit(" (", 1)[0] for h in next(csv.reader(f))]
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    cols = [[row[j] for row in rows] for j in range(len(names))]
    return {n: np.array(c, dtype=str if any(isinstance(x, str) for x in c) else float)
            for n, c in zip(names, cols)}


def run_example(driver, source_root, tmp_path, name):
    proc = subprocess.run([driver, str(source_root / "input" / name)], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return proc
