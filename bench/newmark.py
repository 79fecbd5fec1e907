#!/usr/bin/env python3
"""Benchmark: Newmark rigid-block sliding on the Kocaeli ATS-090 record (26 780 steps).

Times seispulse.newmark.rigid (method 'exact' and 'slammer', one way) next to
pyslammer.RigidAnalysis on the same record, scale and ky, in the same run: medians of
several runs, the ratio pySLAMMER time / seispulse time and seispulse's steps per
second. The ratio is what to quote, since these machines are shared and noisy. Aims:
at least 100 times faster than pySLAMMER and over 2e8 steps per second on one core.
Also prints the displacements, so the speed is seen next to the answer.

usage: PYTHONPATH=build/python python3 bench/newmark.py [--runs R] [--ky KY] [--pga PGA]
"""
import argparse
from pathlib import Path

from seispulse import newmark, records
from timing import median_time


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=9)
    parser.add_argument("--ky", type=float, default=0.1, help="yield acceleration (g)")
    parser.add_argument("--pga", type=float, default=0.4, help="target PGA (g)")
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
    peer = median_time(lambda: pyslammer.RigidAnalysis(args.ky, gm), args.runs)
    peer_disp = pyslammer.RigidAnalysis(args.ky, gm).max_sliding_disp
    print(f"  pyslammer.RigidAnalysis : {peer * 1e3:9.3f} ms   u = {peer_disp * 100:.4f} cm")
    for method in ("exact", "slammer"):
        t = median_time(lambda: newmark.rigid(rec, ky=args.ky, method=method), args.runs,
                        inner=50)
        u = newmark.rigid(rec, ky=args.ky, method=method).final_disp
        print(f"  seispulse rigid {method:8s}: {t * 1e3:9.3f} ms   u = {u * 100:.4f} cm   "
              f"{steps / t:10.3g} steps/s   pySLAMMER/seispulse = {peer / t:7.1f}")


if __name__ == "__main__":
    main()
