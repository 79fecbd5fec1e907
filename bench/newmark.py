#!/usr/bin/env python3
"""Benchmark: Newmark sliding on the Kocaeli ATS-090 record (26 780 steps): the rigid
block, and a flexible sliding mass (decoupled and coupled, linear and equivalent-linear).

Rigid: times seispulse.newmark.rigid (method 'exact' and 'slammer', one way) next to
pyslammer.RigidAnalysis on the same record, scale and ky, in the same run.

Flexible: times seispulse's decoupled and coupled analyses (rule 'slammer' and 'exact'),
run through the batch driver (analysis 'newmark', method 'decoupled' | 'coupled'), next
to pyslammer.Decoupled and pyslammer.Coupled on the same record (scaled to the PGA),
ky, H 50 m, Vs 600 m/s, Vs_base 600 m/s, damping 5 %, linear and equivalent-linear
(reference strain 0.05 %); `--tall` adds H 200 m, Vs 250 m/s. One seispulse analysis is
timed as the difference of two driver runs, one row and K + 1 rows (each row is the
record and its inverse), divided by 2 K: the driver's start, the reading of the record
and the writing of the table cancel out. Steps per second: the record's steps per
analysis (an equivalent-linear analysis runs the response once per iteration on top).

Medians of several runs; the ratio pySLAMMER time / seispulse time is what to quote,
since these machines are shared and noisy. Aims: at least 100 times faster than
pySLAMMER for each case (rigid: over 2e8 steps per second on one core). Also prints the
displacements, so the speed is seen next to the answer (pySLAMMER's Decoupled differs
from SLAMMER's arithmetic in three places, doc/flexible.md section 8).

usage: PYTHONPATH=build/python python3 bench/newmark.py [--runs R] [--ky KY] [--pga PGA]
       [--driver build/driver/seispulse] [--rows K] [--tall] [--no-rigid] [--no-flexible]
"""
import argparse
import csv
import os
import subprocess
import tempfile
import time
from pathlib import Path

from seispulse import newmark, records
from timing import median_time


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=9)
    parser.add_argument("--ky", type=float, default=0.1, help="yield acceleration (g)")
    parser.add_argument("--pga", type=float, default=0.4, help="target PGA (g)")
    parser.add_argument("--driver", default=os.environ.get(
        "SEISPULSE_DRIVER", str(Path(__file__).resolve().parents[1] / "build" / "driver" /
                                "seispulse")), help="the batch driver")
    parser.add_argument("--rows", type=int, default=10,
                        help="K: extra rows of the timed driver run")
    parser.add_argument("--peer-runs", type=int, default=3, help="runs of pySLAMMER")
    parser.add_argument("--tall", action="store_true", help="add H 200 m, Vs 250 m/s")
    parser.add_argument("--no-rigid", action="store_true")
    parser.add_argument("--no-flexible", action="store_true")
    args = parser.parse_args()
    try:
        import pyslammer
    except ImportError:
        raise SystemExit("pyslammer is not installed (pip install pyslammer): it ships the "
                         "record and is the peer")
    path = Path(pyslammer.__file__).parent / "sample_ground_motions" / "Kocaeli_1999_ATS-090.csv"
    rec = records.read(path).scaled_to_pga(args.pga)
    steps = rec.npts
    print(f"Kocaeli 1999 ATS-090: {steps} steps, dt {rec.dt} s, scaled to PGA {args.pga} g, "
          f"ky {args.ky} g; median of {args.runs} runs")

    gm = pyslammer.GroundMotion(rec.accel, rec.dt, "ATS-090")
    if not args.no_rigid:
        rigid(args, pyslammer, gm, rec, steps)
    if not args.no_flexible:
        flexible(args, pyslammer, path, steps)


def rigid(args, pyslammer, gm, rec, steps):
    peer = median_time(lambda: pyslammer.RigidAnalysis(args.ky, gm), args.runs)
    peer_disp = pyslammer.RigidAnalysis(args.ky, gm).max_sliding_disp
    print(f"  pyslammer.RigidAnalysis : {peer * 1e3:9.3f} ms   u = {peer_disp * 100:.4f} cm")
    for method in ("exact", "slammer"):
        t = median_time(lambda: newmark.rigid(rec, ky=args.ky, method=method), args.runs,
                        inner=50)
        u = newmark.rigid(rec, ky=args.ky, method=method).final_disp
        print(f"  seispulse rigid {method:8s}: {t * 1e3:9.3f} ms   u = {u * 100:.4f} cm   "
              f"{steps / t:10.3g} steps/s   pySLAMMER/seispulse = {peer / t:7.1f}")


def driver_table(driver, workdir, path, pga, method, rule, kys, mass):
    """(wall time s, rows of the CSV) of one driver run: `kys` rows on the record."""
    nml = Path(workdir) / "bench.nml"
    soil = mass["soil"]
    nml.write_text(
        "&run analysis='newmark', output='b' /\n"
        f"&records files='{path}', target_pga={pga} /\n"
        f"&newmark ky={', '.join(str(k) for k in kys)}, method='{method}', rule='{rule}' /\n"
        f"&slope height={mass['height']}, vs={mass['vs']}, vs_base={mass['vs_base']}, "
        f"damping={mass['damping']}, soil='{soil}', ref_strain_pct={mass['ref_strain_pct']} /\n")
    t0 = time.perf_counter()
    proc = subprocess.run([driver, str(nml)], cwd=workdir, capture_output=True, text=True)
    t = time.perf_counter() - t0
    if proc.returncode != 0:
        return t, proc.stderr.strip().splitlines()[-1]
    with open(Path(workdir) / "b_newmark.csv", newline="") as f:
        reader = csv.DictReader(f)
        return t, list(reader)


def flexible(args, pyslammer, path, steps):
    if not Path(args.driver).exists():
        raise SystemExit(f"no driver at {args.driver}: build it (meson compile -C build)")
    masses = [dict(height=50.0, vs=600.0, vs_base=600.0, damping=0.05)]
    if args.tall:
        masses.append(dict(height=200.0, vs=250.0, vs_base=600.0, damping=0.05))
    k = args.rows
    print(f"\nflexible sliding mass, ky {args.ky} g, damping 5 %, equivalent-linear with "
          f"reference strain 0.05 %; pySLAMMER: median of {args.peer_runs} runs, seispulse: "
          f"per analysis, (driver with {k + 1} rows - driver with 1 row) / {2 * k}, median of "
          f"{args.runs} runs")
    gm = pyslammer.GroundMotion(*_pyslammer_record(path), "ATS-090")
    with tempfile.TemporaryDirectory() as work:
        for mass0 in masses:
            print(f"H {mass0['height']} m, Vs {mass0['vs']} m/s, Vs_base {mass0['vs_base']} m/s")
            for method, peer_cls in (("decoupled", pyslammer.Decoupled),
                                     ("coupled", pyslammer.Coupled)):
                for soil, peer_soil in (("linear", "linear_elastic"),
                                        ("equivalent_linear", "equivalent_linear")):
                    mass = dict(mass0, soil=soil, ref_strain_pct=0.05)

                    def peer_run():
                        return peer_cls(args.ky, gm, mass["height"], mass["vs"],
                                        mass["vs_base"], mass["damping"], ref_strain=0.0005,
                                        target_pga=args.pga, soil_model=peer_soil)

                    peer = median_time(peer_run, args.peer_runs)
                    peer_disp = peer_run().max_sliding_disp
                    label = f"{method} {soil}"
                    print(f"  pyslammer.{peer_cls.__name__:9s} {soil:17s}: {peer * 1e3:9.2f} ms"
                          f"   u = {peer_disp * 100:9.4f} cm")
                    for rule in ("slammer", "exact"):
                        one, many = [], []
                        for _ in range(args.runs):
                            t1, rows = driver_table(args.driver, work, path, args.pga, method,
                                                    rule, [args.ky], mass)
                            if isinstance(rows, str):
                                break
                            tk, _ = driver_table(args.driver, work, path, args.pga, method,
                                                 rule, [args.ky] * (k + 1), mass)
                            one.append(t1)
                            many.append(tk)
                        if isinstance(rows, str):
                            print(f"  seispulse {label:27s} {rule:7s}: failed: {rows}")
                            continue
                        per = max(_median(many) - _median(one), 1e-9) / (2 * k)
                        row = rows[0]
                        u = float(row["max_normal (cm)"])
                        extra = ""
                        if soil == "equivalent_linear":
                            extra = (f", Vs {float(row['vs_final (m/s)']):.1f} m/s, "
                                     f"{int(float(row['iterations (-)']))} iterations")
                        print(f"  seispulse {label:27s} {rule:7s}: {per * 1e3:9.3f} ms"
                              f"   u = {u:9.4f} cm   {steps / per:10.3g} steps/s   "
                              f"pySLAMMER/seispulse = {peer / per:7.1f}{extra}")


def _median(xs):
    xs = sorted(xs)
    n = len(xs)
    return xs[n // 2] if n % 2 else 0.5 * (xs[n // 2 - 1] + xs[n // 2])


def _pyslammer_record(path):
    """(accel g, dt) of a SLAMMER CSV (pySLAMMER scales it itself)."""
    rec = records.read(path)
    return rec.accel, rec.dt


if __name__ == "__main__":
    main()
