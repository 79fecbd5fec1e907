"""Helpers shared by the driver tests of the sliding and rocking analyses: read a CSV
table the driver wrote, run an example input file of input/."""
import csv
import subprocess

import numpy as np


def read_table(path):
    """{column name: array} of a CSV table of the driver (names without units)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = [h.rsplit(" (", 1)[0] for h in rows[0]]
    data = np.array([[float(x) for x in row] for row in rows[1:]], ndmin=2)
    return {n: data[:, j] for j, n in enumerate(names)}


def run_example(driver, source_root, tmp_path, name):
    proc = subprocess.run([driver, str(source_root / "input" / name)], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return proc
