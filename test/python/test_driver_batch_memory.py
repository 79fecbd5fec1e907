"""Batch driver: memory does not grow with the number of records, and an output that
cannot be written is found before any record is computed.

The analyses newmark and sdof write each record's rows into their tables as soon as the
records before it are done (the CSV at once; the aligned .txt from a scratch file once
every width is known), so a job holds its record list, not its tables. The peak resident
memory of the driver (its ru_maxrss, from wait4 in a small C parent) is measured at SMALL and at
LARGE records of one short record listed under many names; the growth per added record
must stay far below what holding the tables cost before (about 6 KB per record for this
Newmark job, 20 KB for this 40-period spectrum job). Tables are checked to be complete
(one row per record and ky or period) and, for the small job, equal to the same job with
its records given one by one in `files`."""
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

SMALL, LARGE = 100, 1000
#: a record's line in a table's header
RECORD_LINE = re.compile(r"# record \d+: ")
#: the allowed growth of peak memory per added record (bytes). Measured here: 150 to 900
#: (the record list, and the page-sized steps of the heap); with the tables held in memory
#: 6500 (newmark) and 19600 (sdof), and a restart holding its journal 5300 (sdof)
PER_RECORD = 2048

JOBS = {
    "newmark": ("&newmark ky = 0.05, 0.1, 0.2, mode = 'down' /\n", 3),
    "sdof": ("&sdof period_range = 0.05, 4.0, period_count = 40, spacing = 'log', "
             "damping = 0.05, peaks = 'samples' /\n", 40),
}


def write_record(path, n=200, dt=0.01):
    """A short AT2 record (g): a decaying 2 Hz sine of 0.3 g."""
    t = np.arange(n) * dt
    a = 0.3 * np.sin(2 * np.pi * 2.0 * t) * np.exp(-t)
    lines = ["PEER NGA STRONG MOTION DATABASE RECORD", "memory test record",
             "ACCELERATION TIME SERIES IN UNITS OF G", f"NPTS={n:8d}, DT={dt:10.6f} SEC"]
    lines += ["  ".join(f"{v:.7E}" for v in a[i:i + 5]) for i in range(0, n, 5)]
    path.write_text("\n".join(lines) + "\n")


def make_job(folder, analysis, count):
    """A job over `count` records (one file, listed under count names)."""
    folder.mkdir(parents=True)
    write_record(folder / "rec.AT2")
    rows = ["path,name,scale"] + [f"rec.AT2,record_{i:05d},{0.5 + i % 7 / 7:.6f}"
                                  for i in range(count)]
    (folder / "suite.csv").write_text("\n".join(rows) + "\n")
    group, _ = JOBS[analysis]
    (folder / "job.nml").write_text(f"&run analysis = '{analysis}', output = 'out/job' /\n"
                                    "&records list = 'suite.csv' /\n" + group)


#: a tiny C program that runs a command and writes its peak resident set (KiB, wait4's
#: ru_maxrss) to a file: a child forked from this Python process would count Python's
#: own pages in its ru_maxrss (Linux keeps the high-water mark across exec), a child of
#: this small program only its own
MAXRSS_C = r"""
#include <stdio.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
int main(int argc, char **argv) {
    int status;
    struct rusage ru;
    FILE *out;
    pid_t pid;
    if (argc < 3) return 126;
    pid = fork();
    if (pid == 0) {
        execvp(argv[2], argv + 2);
        _exit(127);
    }
    if (pid < 0 || wait4(pid, &status, 0, &ru) < 0) return 126;
    out = fopen(argv[1], "w");
    if (!out) return 126;
    fprintf(out, "%ld\n", ru.ru_maxrss);
    fclose(out);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
"""


@pytest.fixture(scope="module")
def maxrss(tmp_path_factory):
    """The path of the compiled MAXRSS_C (the C compiler that builds the driver's C part)."""
    compiler = shutil.which(os.environ.get("CC", "cc")) or shutil.which("gcc")
    assert compiler, "no C compiler (cc, gcc) on PATH: the driver's build needs one"
    folder = tmp_path_factory.mktemp("maxrss")
    (folder / "maxrss.c").write_text(MAXRSS_C)
    subprocess.run([compiler, "-O1", "-o", str(folder / "maxrss"), str(folder / "maxrss.c")],
                   check=True)
    return folder / "maxrss"


def peak_memory(maxrss, driver, folder):
    """Run the driver in folder (one thread): its exit status and peak resident set
    (bytes)."""
    env = dict(os.environ, OMP_NUM_THREADS="1")
    with open(folder / "stderr.txt", "w") as err:
        rc = subprocess.run([str(maxrss), str(folder / "maxrss.txt"), driver, "job.nml"],
                            cwd=folder, env=env, stdout=subprocess.DEVNULL, stderr=err,
                            timeout=300).returncode
    return rc, int((folder / "maxrss.txt").read_text()) * 1024


def data_rows(path):
    return [line for line in path.read_text().splitlines() if not line.startswith("#")]


@pytest.mark.parametrize("analysis", sorted(JOBS))
def test_memory_does_not_grow_with_the_records(driver, maxrss, tmp_path, analysis):
    rss = {}
    for count in (SMALL, LARGE):
        folder = tmp_path / f"{analysis}_{count}"
        make_job(folder, analysis, count)
        # the lower of two runs: the peak of one run can take a stray page or two
        runs = [peak_memory(maxrss, driver, folder) for _ in range(2)]
        assert all(rc == 0 for rc, _ in runs), (folder / "stderr.txt").read_text()
        rss[count] = min(m for _, m in runs)
        table = "job_newmark" if analysis == "newmark" else "job_sdof"
        rows_per_record = JOBS[analysis][1]
        assert len(data_rows(folder / "out" / f"{table}.txt")) == count * rows_per_record
        assert len(data_rows(folder / "out" / f"{table}.csv")) == 1 + count * rows_per_record
        header = (folder / "out" / f"{table}.txt").read_text().splitlines()
        assert sum(1 for h in header if RECORD_LINE.match(h)) == count, "a line per record"
    growth = (rss[LARGE] - rss[SMALL]) / (LARGE - SMALL)
    assert growth < PER_RECORD, (
        f"{analysis}: peak memory {rss[SMALL] / 2**20:.1f} MiB at {SMALL} records, "
        f"{rss[LARGE] / 2**20:.1f} MiB at {LARGE}: {growth:.0f} bytes per record")


@pytest.mark.parametrize("analysis", sorted(JOBS))
def test_list_equals_files(driver, maxrss, tmp_path, analysis):
    """The streamed tables of a list job equal those of the same records in `files`."""
    folder = tmp_path / "list"
    make_job(folder, analysis, 12)
    assert peak_memory(maxrss, driver, folder)[0] == 0
    names = [f"record_{i:05d}" for i in range(12)]
    scales = [f"{0.5 + i % 7 / 7:.6f}" for i in range(12)]
    two = tmp_path / "files"
    two.mkdir()
    for name in names:
        write_record(two / f"{name}.AT2")
    group, _ = JOBS[analysis]
    (two / "job.nml").write_text(
        f"&run analysis = '{analysis}', output = 'out/job' /\n&records files = "
        + ", ".join(f"'{n}.AT2'" for n in names) + ", scale = " + ", ".join(scales)
        + " /\n" + group)
    assert peak_memory(maxrss, driver, two)[0] == 0
    table = "job_newmark" if analysis == "newmark" else "job_sdof"
    for ext in ("csv", "txt"):
        one_text = (folder / "out" / f"{table}.{ext}").read_text().splitlines()
        two_text = (two / "out" / f"{table}.{ext}").read_text().splitlines()
        # the header names the input and the files; the rows are the same
        keep = [not (line.startswith("# input:") or RECORD_LINE.match(line))
                for line in one_text]
        assert [a for a, k in zip(one_text, keep) if k] == \
            [b for b, k in zip(two_text, keep) if k]


@pytest.mark.parametrize("analysis", sorted(JOBS))
def test_unwritable_output_found_before_computing(driver, maxrss, tmp_path, analysis):
    """A table that cannot be created (a directory in the way of its .part) stops the run
    at once: exit 2, no record computed, no journal, nothing else left."""
    folder = tmp_path / "job"
    make_job(folder, analysis, 20)
    table = "job_newmark" if analysis == "newmark" else "job_sdof"
    (folder / "out" / f"{table}.csv.part").mkdir(parents=True)
    rc, _ = peak_memory(maxrss, driver, folder)
    err = (folder / "stderr.txt").read_text()
    assert rc == 2
    assert f"cannot create out/{table}.csv.part" in err
    assert "record_00000" not in err and "1/20" not in err, "no record was computed"
    assert sorted(p.name for p in (folder / "out").iterdir()) == [f"{table}.csv.part"]


@pytest.mark.parametrize("analysis", sorted(JOBS))
def test_restart_memory_does_not_grow_with_the_records(driver, maxrss, tmp_path, analysis):
    """A restart from a complete journal reads each restored record's line again when
    its turn comes, rather than holding the journal: its memory does not grow with the
    records either, and its tables equal those of an uninterrupted run."""
    table = "job_newmark" if analysis == "newmark" else "job_sdof"
    rss = {}
    for count in (SMALL, LARGE):
        folder = tmp_path / f"{analysis}_{count}"
        make_job(folder, analysis, count)
        assert peak_memory(maxrss, driver, folder)[0] == 0
        reference = {ext: (folder / "out" / f"{table}.{ext}").read_bytes()
                     for ext in ("txt", "csv")}
        job = (folder / "job.nml").read_text()
        (folder / "job.nml").write_text(job.replace("output = 'out/job'",
                                                    "output = 'out/job', restart = .true."))
        # a complete journal: every record done, then the table cannot take its name
        for ext in ("txt", "csv"):
            (folder / "out" / f"{table}.{ext}").unlink()
        (folder / "out" / f"{table}.txt").mkdir()
        assert peak_memory(maxrss, driver, folder)[0] == 2
        (folder / "out" / f"{table}.txt").rmdir()
        assert (folder / "out" / "job.journal").exists()
        rc, rss[count] = peak_memory(maxrss, driver, folder)
        err = (folder / "stderr.txt").read_text()
        assert rc == 0, err
        assert f"{count} of {count} units restored" in err
        for ext in ("txt", "csv"):
            assert (folder / "out" / f"{table}.{ext}").read_bytes() == reference[ext]
    growth = (rss[LARGE] - rss[SMALL]) / (LARGE - SMALL)
    assert growth < PER_RECORD, (
        f"{analysis} restart: peak memory {rss[SMALL] / 2**20:.1f} MiB at {SMALL} records, "
        f"{rss[LARGE] / 2**20:.1f} MiB at {LARGE}: {growth:.0f} bytes per record")
