#!/usr/bin/env python3
"""Benchmark: the batch driver on a suite of many records: a Newmark job and a spectrum job,
serial, with 2 OpenMP threads and with 2 MPI ranks, and the driver's peak memory as the
suite grows.

The suite is made from pySLAMMER's 18 sample records (1000 to 26 780 samples): record i is
sample i mod 18, stretched in time by a factor in [0.6, 1.6] (linear interpolation onto the
sample's own time step, so lengths differ by up to 40 times) and written as an AT2 file to a
temporary folder; a CSV list (`&records list`) gives each record a name and a scale factor in
[0.5, 1.5]. Jobs:
  newmark  rigid block, ky = 0.05, 0.1, 0.2 g, one way, both polarities (6 sliding runs
           per record)
  sdof     5 %-damped spectra at 40 log-spaced periods from 0.05 to 4 s, exact peaks
Each job runs `--runs` times per configuration (median wall time; records per second):
  serial   OMP_NUM_THREADS=1
  openmp   OMP_NUM_THREADS=2 (the records are spread over the threads)
  mpi      mpirun -n 2 with OMP_NUM_THREADS=1 (only if the driver was built with MPI)
The parallel runs' tables are compared with the serial run's, byte for byte. Peak memory:
the driver's maximum resident set (serial runs, from GNU time's %M) at `--small` and at
`--records` records; the ratio shows whether memory grows with the number of records.

usage: PYTHONPATH=build/python python3 bench/batch.py [--records N] [--small N] [--runs R]
       [--driver build/driver/seispulse] [--keep DIR]
"""
import argparse
import filecmp
import os
import shutil
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent


def sample_records():
    """The pySLAMMER sample records as (name, dt (s), accel (g)) tuples."""
    try:
        import pyslammer
    except ImportError:
        raise SystemExit("pyslammer is not installed (pip install pyslammer): it ships the "
                         "sample records")
    folder = Path(pyslammer.__file__).parent / "sample_ground_motions"
    from seispulse import records
    out = []
    for path in sorted(folder.glob("*.csv")):
        rec = records.read(path)
        out.append((path.stem, float(rec.dt), np.asarray(rec.accel, dtype=float)))
    return out


def write_at2(path, name, dt, accel):
    """accel (g) at time step dt (s) as a PEER AT2 file, five values per line."""
    n = accel.size
    rows = n // 5 * 5
    body = "\n".join("  ".join(f"{v:.7E}" for v in accel[i:i + 5]) for i in range(0, rows, 5))
    tail = "  ".join(f"{v:.7E}" for v in accel[rows:])
    with open(path, "w") as f:
        f.write("PEER NGA STRONG MOTION DATABASE RECORD\n")
        f.write(f"{name} (seispulse benchmark suite: a pySLAMMER sample, stretched)\n")
        f.write("ACCELERATION TIME SERIES IN UNITS OF G\n")
        f.write(f"NPTS={n:8d}, DT={dt:10.6f} SEC\n")
        f.write(body + "\n")
        if tail:
            f.write(tail + "\n")


def make_suite(folder, count, rng):
    """count AT2 files in folder and a list file suite.csv (path, name, scale); the total
    number of samples."""
    samples = sample_records()
    folder.mkdir(parents=True, exist_ok=True)
    lines = ["path,name,scale"]
    total = 0
    for i in range(count):
        name, dt, accel = samples[i % len(samples)]
        stretch = rng.uniform(0.6, 1.6)
        t_old = np.arange(accel.size) * dt
        t_new = np.arange(int((accel.size - 1) * stretch) + 1) * dt
        stretched = np.interp(t_new / stretch, t_old, accel)
        label = f"r{i:05d}_{name}"
        write_at2(folder / f"{label}.AT2", label, dt, stretched)
        lines.append(f"{label}.AT2,{label},{rng.uniform(0.5, 1.5):.6f}")
        total += stretched.size
    (folder / "suite.csv").write_text("\n".join(lines) + "\n")
    return total


JOBS = {
    "newmark": """&run analysis = 'newmark', output = 'out/newmark' /
&records list = 'records/suite.csv' /
&newmark ky = 0.05, 0.1, 0.2, mode = 'down' /
""",
    "sdof": """&run analysis = 'sdof', output = 'out/sdof' /
&records list = 'records/suite.csv' /
&sdof period_range = 0.05, 4.0, period_count = 40, spacing = 'log', damping = 0.05,
      peaks = 'exact', envelope = .false. /
""",
}


GNU_TIME = "/usr/bin/time"


def run(cmd, cwd, env):
    """Run cmd; (wall time (s), peak resident set of the command (MiB), from GNU time: the
    rusage of a child forked from this Python process would count Python's own pages)."""
    timed = os.access(GNU_TIME, os.X_OK)
    with tempfile.NamedTemporaryFile("r") as rss_file:
        full = [GNU_TIME, "-f", "%M", "-o", rss_file.name] + cmd if timed else cmd
        t0 = time.perf_counter()
        proc = subprocess.run(full, cwd=cwd, env=env, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE)
        wall = time.perf_counter() - t0
        if proc.returncode != 0:
            err = proc.stderr.decode(errors="replace")
            raise SystemExit(f"{' '.join(cmd)} exited {proc.returncode}:\n{err[-2000:]}")
        rss = float(rss_file.read().split()[-1]) / 1024.0 if timed else float("nan")
    return wall, rss


def mpi_built(driver):
    try:
        out = subprocess.run(["ldd", str(driver)], capture_output=True, text=True).stdout
    except OSError:
        return False
    return "libmpi" in out


def mpirun_cmd(n):
    cmd = ["mpirun", "--oversubscribe", "-n", str(n)]
    if os.geteuid() == 0:
        cmd.insert(1, "--allow-run-as-root")
    return cmd


def same_tables(a, b):
    names = sorted(p.name for p in a.iterdir() if p.suffix in (".txt", ".csv"))
    return names and all(filecmp.cmp(a / n, b / n, shallow=False) for n in names)


def job_dir(base, records_dir, job):
    """A job folder with its input and a link to the records."""
    d = base / job
    d.mkdir(parents=True, exist_ok=True)
    (d / "out").mkdir(exist_ok=True)
    link = d / "records"
    if not link.exists():
        link.symlink_to(records_dir)
    (d / "job.nml").write_text(JOBS[job])
    return d


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--records", type=int, default=2000)
    parser.add_argument("--small", type=int, default=200, help="suite size of the memory check")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--driver", default=str(ROOT / "build" / "driver" / "seispulse"))
    parser.add_argument("--keep", help="make the suites in this folder and keep them")
    parser.add_argument("--seed", type=int, default=2026)
    args = parser.parse_args()
    driver = Path(args.driver).resolve()
    if not driver.is_file():
        raise SystemExit(f"{driver}: no driver (make build)")
    base = Path(args.keep) if args.keep else Path(tempfile.mkdtemp(prefix="seispulse_batch_"))
    base = base.resolve()
    try:
        rng = np.random.default_rng(args.seed)
        t0 = time.perf_counter()
        big = base / f"records_{args.records}"
        nsamp = make_suite(big, args.records, rng)
        small = base / f"records_{args.small}"
        make_suite(small, args.small, np.random.default_rng(args.seed))
        print(f"suite: {args.records} AT2 records, {nsamp} samples "
              f"({nsamp / args.records:.0f} per record), made in "
              f"{time.perf_counter() - t0:.1f} s under {base}")
        have_mpi = mpi_built(driver) and shutil.which("mpirun") is not None
        if not have_mpi:
            print("mpi: the driver was not built with MPI (or mpirun is missing): no MPI runs")
        configs = [("serial", [], "1"), ("openmp", [], "2")]
        if have_mpi:
            configs.append(("mpi", mpirun_cmd(2), "1"))
        for job in JOBS:
            print(f"\n{job} job, {args.records} records "
                  f"(median of {args.runs} runs; tables compared with the serial run)")
            ref = None
            serial_time = None
            for label, prefix, threads in configs:
                d = job_dir(base / label, big, job)
                env = dict(os.environ, OMP_NUM_THREADS=threads)
                times = []
                mem = 0.0
                for _ in range(args.runs):
                    wall, rss = run(prefix + [str(driver), "job.nml"], d, env)
                    times.append(wall)
                    mem = max(mem, rss)
                wall = statistics.median(times)
                if ref is None:
                    ref, serial_time = d / "out", wall
                    same = "reference"
                else:
                    same = "identical" if same_tables(ref, d / "out") else "DIFFERENT"
                mem_text = f", peak RSS {mem:.1f} MiB" if not prefix else ""
                print(f"  {label:7s} {wall:8.2f} s  {args.records / wall:8.1f} records/s  "
                      f"speed-up {serial_time / wall:4.2f}{mem_text}  tables {same}")
            # memory: serial, the small suite against the big one
            d = job_dir(base / "memory", small, job)
            env = dict(os.environ, OMP_NUM_THREADS="1")
            rss_small = max(run([str(driver), "job.nml"], d, env)[1] for _ in range(2))
            d = job_dir(base / "memory_big", big, job)
            rss_big = max(run([str(driver), "job.nml"], d, env)[1] for _ in range(2))
            print(f"  memory  peak RSS {rss_small:.1f} MiB at {args.small} records, "
                  f"{rss_big:.1f} MiB at {args.records} records (ratio "
                  f"{rss_big / rss_small:.2f})")
    finally:
        if not args.keep:
            shutil.rmtree(base, ignore_errors=True)


if __name__ == "__main__":
    main()
