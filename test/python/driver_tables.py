"""Helpers shared by the driver tests of the sliding and rocking analyses: read a CSV
table the driver wrote, run an example input file of input/."""
import csv
import subprocess

import numpy as np


def read_table(path):
    """{column name: array} of a CSV table of the driver (names without units): a column
    with a quoted cell (a category such as an outcome, written as its name) is an array
    of str, any other an array of float."""
    with open(path, newline="") as f:
        header = next(csv.reader(f))
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    names = [h.rsplit(" (", 1)[0] for h in header]
    table = {}
    for j, n in enumerate(names):
        cells = [row[j] for row in rows]
        if any(isinstance(c, str) for c in cells):
            table[n] = np.array([str(c) for c in cells], dtype=object)
        else:
            table[n] = np.array(cells, dtype=float)
    return table


def run_example(driver, source_root, tmp_path, name):
    proc = subprocess.run([driver, str(source_root / "input" / name)], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return proc


def g_text(x, digits=6):
    """A cell as the driver's text table writes it: a name as is, a number as C's
    %.<digits>g (Python's % operator is C's), an integer-valued count as an integer."""
    if isinstance(x, str):
        return x
    return "%.*g" % (digits, x)


def read_summary_txt(path):
    """{name: (value text, unit)} of a one-row summary's text table (`name  value  unit`
    lines after the # comments)."""
    out = {}
    for line in open(path).read().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        name, rest = line.split(None, 1)
        value, unit = rest.split(None, 1) if " " in rest.strip() else (rest.strip(), "")
        out[name] = (value, unit.strip())
    return out


#: The names of the driver's category columns by header cell, in code order (code k is
#: names[k]).
CATEGORY_NAMES = {"status (-)": ("ok", "failed"), "converged (-)": ("no", "yes")}


def coded(header, rows, first=1):
    """rows[:, first:] as numbers, the category cells (names, asserted to be the names
    of their column) as their codes."""
    out = []
    for row in rows:
        cells = []
        for h, x in zip(header[first:], row[first:]):
            if h in CATEGORY_NAMES:
                assert x in CATEGORY_NAMES[h], (h, x)
                x = float(CATEGORY_NAMES[h].index(x))
            cells.append(x)
        out.append(cells)
    return np.array(out, dtype=float, ndmin=2)
