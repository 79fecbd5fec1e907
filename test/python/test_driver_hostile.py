"""Batch driver on hostile input: lines of 1 MB, NUL bytes, a list of a million values,
a binary file, an empty file, a directory, a missing file, an input over the size limit,
a million '=' (over 100000 items in a group), half a million groups (over 1000). Each is
one clear error line ("file:line: ..." or "file: ...") with exit status 2, in bounded
CPU time (< 5 s) and memory (the driver runs in 150 MB of address space)."""
import os
import resource
import subprocess
import threading
from pathlib import Path

import pytest

VALID = ("&run analysis = 'newmark', output = 'o' /\n"
         "&records files = 'a.AT2' /\n"
         "&newmark ky = 0.1 /\n")
LIMIT_S = 5.0
LIMIT_MB = 150.0


def limit_memory():
    """In the child before exec: at most LIMIT_MB of address space (an allocation beyond
    it fails, and the driver with it)."""
    limit = int(LIMIT_MB * 2**20)
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def run_bounded(driver, cwd, arg):
    """(exit status, stderr, CPU seconds) of the driver on `arg`, with LIMIT_MB of address
    space; killed after 60 s of wall time. The CPU time (user + system) is this child's
    own (os.wait4), so a machine busy with other jobs does not change it. (Its ru_maxrss
    is not used: it keeps the high-water mark of the forked copy of this test process.)"""
    err = Path(cwd) / "stderr.txt"
    with open(err, "w") as ferr:
        proc = subprocess.Popen([driver, str(arg)], cwd=cwd, stdout=subprocess.DEVNULL,
                                stderr=ferr, preexec_fn=limit_memory)
        timer = threading.Timer(60.0, proc.kill)
        timer.start()
        try:
            _, status, usage = os.wait4(proc.pid, 0)
        finally:
            timer.cancel()
    proc.returncode = os.waitstatus_to_exitcode(status)
    cpu = usage.ru_utime + usage.ru_stime
    return proc.returncode, err.read_text(errors="replace"), cpu


def check(driver, tmp_path, content, expected, name="case.nml"):
    path = tmp_path / name
    if isinstance(content, bytes):
        path.write_bytes(content)
    else:
        path.write_text(content)
    rc, err, seconds = run_bounded(driver, tmp_path, name)
    assert rc == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and len(lines[0]) < 1000, err[:2000]
    assert lines[0].startswith("seispulse: error: "), lines[0]
    assert expected in lines[0], lines[0]
    assert seconds < LIMIT_S, f"{seconds:.2f} s of CPU"
    assert not list(tmp_path.glob("o_*"))
    return lines[0]


def test_a_line_of_1_mb(driver, tmp_path):
    check(driver, tmp_path, VALID + "! " + "x" * 2**20 + "\n",
          "case.nml:4: line longer than 262144 characters")


def test_a_value_line_of_1_mb(driver, tmp_path):
    check(driver, tmp_path, VALID.replace("ky = 0.1", "ky = " + "0.1, " * 2**18),
          "case.nml:3: line longer than 262144 characters")


def test_a_long_line_within_the_limit_is_read_in_linear_time(driver, tmp_path):
    """50000 values on one line (250 kB, under the limit): scanned, then refused by name
    (the array holds 1000)."""
    check(driver, tmp_path, VALID.replace("ky = 0.1", "ky = " + ", ".join(["0.1"] * 50000)),
          "case.nml:3: &newmark: ky: 50000 values, more than the list holds (1000)")


def test_nul_bytes(driver, tmp_path):
    check(driver, tmp_path, VALID.replace("files", "fi\0les"),
          "case.nml:2: a NUL byte at column 12: not a text file")


def test_control_characters(driver, tmp_path):
    check(driver, tmp_path, VALID.replace("ky", "k\x1by"),
          "case.nml:3: control character 27 at column 11: not a text file")


def test_a_million_values(driver, tmp_path):
    values = ",\n".join([", ".join(["0.1"] * 10)] * 100000)
    check(driver, tmp_path, VALID.replace("ky = 0.1", "ky = " + values),
          "case.nml:3: &newmark: ky: 1000000 values, more than the list holds (1000)")


def test_a_million_values_by_repeat_count(driver, tmp_path):
    check(driver, tmp_path, VALID.replace("ky = 0.1", "ky = 1000000*0.1"),
          "case.nml:3: &newmark: ky: 1000000 values, more than the list holds (1000)")


def test_more_files_than_the_namelist_holds(driver, tmp_path):
    check(driver, tmp_path, VALID.replace("files = 'a.AT2'",
                                          "files = " + ", ".join(["'a.AT2'"] * 600)),
          "case.nml:2: &records: files: 600 values, more than the list holds (500)")


def test_a_bad_value_in_a_long_list_is_quoted_short(driver, tmp_path):
    line = check(driver, tmp_path, VALID.replace("ky = 0.1", "ky = " + "0.1, " * 900 + "abc"),
                 "case.nml:3: &newmark: ky: bad value in \"ky = 0.1, 0.1")
    assert " ...\" (" in line


def test_binary_file(driver, tmp_path):
    check(driver, tmp_path, bytes(range(256)) * 4096,
          "case.nml:1: a NUL byte at column 1: not a text file")


def test_binary_without_nul(driver, tmp_path):
    check(driver, tmp_path, bytes(range(1, 256)) * 4096, "case.nml:1: control character 1 at "
          "column 1: not a text file")


def test_empty_file(driver, tmp_path):
    check(driver, tmp_path, "", "case.nml:1: no namelist group in the input")


def test_only_comments(driver, tmp_path):
    check(driver, tmp_path, "! nothing here\n\n", "case.nml:1: no namelist group in the input")


def test_a_directory(driver, tmp_path):
    (tmp_path / "case.nml").mkdir()
    rc, err, seconds = run_bounded(driver, tmp_path, "case.nml")
    assert rc == 2
    assert err.strip() == "seispulse: error: case.nml: is a directory, not an input file"


def test_a_missing_file(driver, tmp_path):
    rc, err, seconds = run_bounded(driver, tmp_path, "nothing.nml")
    assert rc == 2
    assert err.strip().startswith("seispulse: error: nothing.nml: cannot open the input "
                                  "file: no such file")


def test_an_input_over_the_size_limit(driver, tmp_path):
    line = "! " + "x" * 1000 + "\n"
    check(driver, tmp_path, VALID + line * 9000, "the input is longer than 8388608 characters")


def test_a_million_equal_signs(driver, tmp_path):
    """A group holds at most 100000 items; the keys before each '=' are found by searches
    that stop at the '=' before (a quadratic search would take hours here)."""
    body = ("x)=" * 100 + "\n") * 10000
    check(driver, tmp_path, "&run " + body + "/\n",
          "case.nml:1: &run: more than 100000 items (key = value) in the group")
    body = ("x)=" * 100 + "\n") * 900
    check(driver, tmp_path, "&run " + body + "/\n", "case.nml:1: &run: x): unknown key")


def test_half_a_million_groups(driver, tmp_path):
    check(driver, tmp_path, "&newmark /\n" * 500000,
          "case.nml:1001: more than 1000 groups (not a namelist input file?)")
    check(driver, tmp_path, "&newmark /\n" * 1000, "case.nml:2: &newmark: group given twice")
