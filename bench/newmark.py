#!/usr/bin/env python3
"""Benchmark: Newmark sliding on the Kocaeli ATS-090 record (26 780 steps): the rigid
block, and a flexible sliding mass (decoupled and coupled, linear and equivalent-linear).

Rigid: times seispulse.newmark.rigid (method 'exact' and 'slammer', one way) next to
pyslammer.RigidAnalysis on the same record, scale and ky, in the same run.

Flexible: times seispulse.newmark.decoupled and seispulse.newmark.coupled (rule
'slammer' and 'exact'; the driver's methods 'decoupled' and 'coupled' run the same
routines) next to pyslammer.Decoupled and pyslammer.Coupled on the same record (scaled
to the PGA), ky, H 50 m, Vs 600 m/s, Vs_base 600 m/s, damping 5 %, linear and
equivalent-linear (reference strain 0.05 %); `--tall` adds H 200 m, Vs 250 m/s. Steps
per second: the record's steps per analysis (an equivalent-linear analysis runs the
response once per iteration on top).

Medians of several runs; the ratio pySLAMMER time / seispulse time is what to quote,
since these machines are shared and noisy. Aims: at least 100 times faster than
pySLAMMER for each case (rigid: over 2e8 steps per second on one core). Also prints the
displacements, so the speed is seen next to the answer (pySLAMMER's Decoupled differs
from SLAMMER's arithmetic in three places, doc/flexible.md section 8).

usage: PYTHONPATH=build/python python3 bench/newmark.py [--runs R] [--ky KY] [--pga PGA]
       [--peer-runs R] [--tall] [--no-rigid] [--no-flexible]
"""
import argparse
import time
from pathlib import Path

from seispulse import newmark, records
from timing import median_time


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=9)
    parser.add_argument("--ky", type=float, default=0.1, help="yield acceleration (g)")
    parser.add_argument("--pga", type=float, default=0.4, help="target PGA (g)")
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
        flexible(args, pyslammer, rec, steps)


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


def flexible(args, pyslammer, rec, steps):
    masses = [dict(height=50.0, vs=600.0, vs_base=600.0, damping=0.05)]
    if args.tall:
        masses.append(dict(height=200.0, vs=250.0, vs_base=600.0, damping=0.05))
    print(f"\nflexible sliding mass, ky {args.ky} g, damping 5 %, equivalent-linear with "
          f"reference strain 0.05 %; pySLAMMER: median of {args.peer_runs} runs, seispulse: "
          f"median of {args.runs} runs")
    gm = pyslammer.GroundMotion(rec.accel, rec.dt, "ATS-090")
    for mass in masses:
        print(f"H {mass['height']} m, Vs {mass['vs']} m/s, Vs_base {mass['vs_base']} m/s")
        for method, ours, peer_cls in (("decoupled", newmark.decoupled, pyslammer.Decoupled),
                                       ("coupled", newmark.coupled, pyslammer.Coupled)):
            for soil, peer_soil in (("linear", "linear_elastic"),
                                    ("equivalent_linear", "equivalent_linear")):

                def peer_run():
                    return peer_cls(args.ky, gm, mass["height"], mass["vs"], mass["vs_base"],
                                    mass["damping"], ref_strain=0.0005, soil_model=peer_soil)

                peer = median_time(peer_run, args.peer_runs)
                peer_disp = peer_run().max_sliding_disp
                print(f"  pyslammer.{peer_cls.__name__:9s} {soil:17s}      : {peer * 1e3:9.2f} ms"
                      f"   u = {peer_disp * 100:9.4f} cm")
                for rule in ("slammer", "exact"):

                    def run():
                        return ours(rec, ky=args.ky, soil=soil, ref_strain_pct=0.05,
                                    method=rule, **mass)

                    try:
                        r = run()
                    except Exception as exc:        # a rule not available: say so, go on
                        print(f"  seispulse {method:9s} {soil:17s} {rule:7s}: failed: {exc}")
                        continue
                    t = median_time(run, args.runs, inner=max(1, int(0.05 / _once(run))))
                    extra = ""
                    if soil == "equivalent_linear":
                        extra = f", Vs {r.vs_final:.1f} m/s, {r.iterations} iterations"
                    print(f"  seispulse {method:9s} {soil:17s} {rule:7s}: {t * 1e3:9.3f} ms"
                          f"   u = {r.max_disp * 100:9.4f} cm   {steps / t:10.3g} steps/s   "
                          f"pySLAMMER/seispulse = {peer / t:7.1f}{extra}")


def _once(fn):
    t0 = time.perf_counter()
    fn()
    return max(time.perf_counter() - t0, 1e-6)


if __name__ == "__main__":
    main()
