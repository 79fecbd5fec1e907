#!/usr/bin/env python3
"""Benchmark: overturning maps of a rigid cylinder through Python, next to scipy's solve_ivp.

1. Planar rocking: a 200 x 200 overturning map of the one-sine pulse for a solid cylinder
   (r = 0.5 m, h = 2 m, Housner's restitution of the cylinder) on the dimensional axes:
   f_p over omega_p/p in [0.5, 12], PGA over a_p/(g tan theta_c) in [0.5, 15]
   (seispulse.cylinder.overturning_map), seconds (median of --runs). The peer classifies
   a subsample of the cells by solve_ivp on Housner's equations with impacts (peer_cell of
   bench/rocking.py, reused: DOP853, rtol 1e-10, events at theta = 0 and |theta| = pi/2);
   the per-cell time ratio and the agreement of the classes are printed.
2. 3-D rocking with rolling: 20 s of harmonic shaking, run by bench/rolling.py (its own
   peer, scipy solve_ivp, and its aim: < 50 ms); --planar-only skips it.
Aim: the map < 2 s on one core. Quote the ratios: the machine is noisy.

usage: PYTHONPATH=build/python python3 bench/cylinder.py [--runs R] [--grid M] [--planar-only]
       (needs scipy for the peer columns)
"""
import argparse
import math
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from seispulse import cylinder
from timing import median_time

try:
    from scipy.integrate import solve_ivp  # noqa: F401 (the peer needs it)
    from rocking import peer_cell           # bench/rocking.py
except ImportError:  # the peer is optional
    peer_cell = None


def planar(args):
    """Section 1: the planar map and its peer."""
    body = cylinder.props(0.5, 2.0, mass=1000.0)
    k = args.grid
    # the grid of bench/rocking.py, on the dimensional axes of this body (Hz, g)
    f_hz = np.linspace(0.5, 12.0, k) * body.p / (2 * math.pi)
    pga_g = np.linspace(0.5, 15.0, k) * math.tan(body.theta_c)

    def run():
        return cylinder.overturning_map(body, "sine_cycle", f_hz, pga_g, axes="dimensional")
    t_map = median_time(run, args.runs)
    classes = run()
    print(f"solid cylinder r = {body.r} m, h = {body.h} m: theta_c = {body.theta_c:.4f} rad, "
          f"p = {body.p:.4f} rad/s, restitution {body.restitution:.4f}")
    print(f"planar one-sine overturning map {k} x {k} (f_p {f_hz[0]:.3f}-{f_hz[-1]:.3f} Hz, "
          f"PGA {pga_g[0]:.3f}-{pga_g[-1]:.3f} g): {t_map:.2f} s "
          f"({t_map / k / k * 1e6:.1f} us per cell; median of {args.runs})")
    counts = np.bincount(classes.reshape(-1) + 1, minlength=5)
    print("  cells per class: " + ", ".join(f"{name} {n}" for name, n in zip(
        ("undecided",) + cylinder.MAP_CLASSES, counts)))
    if peer_cell is None:
        print("  scipy solve_ivp (peer): scipy not installed, skipped")
        return
    step = max(1, k // args.peer_side)
    cells = [(i, j) for i in range(0, k, step) for j in range(0, k, step)]
    t0 = time.perf_counter()
    peer = [peer_cell(2 * math.pi * f_hz[j] / body.p, pga_g[i] / math.tan(body.theta_c),
                      body.theta_c, body.restitution) for i, j in cells]
    t_cell = (time.perf_counter() - t0) / len(cells)
    agree = np.mean([classes[i, j] == c for (i, j), c in zip(cells, peer)])
    overturn = np.mean([(classes[i, j] > 0) == (c > 0) for (i, j), c in zip(cells, peer)])
    print(f"  scipy solve_ivp (peer): {t_cell * 1e6:.0f} us per cell ({len(cells)} cells) -> "
          f"{t_cell * k * k:.0f} s for the map; ratio per cell {t_cell * k * k / t_map:.1f}; "
          f"classes agree: {agree:.1%}, overturns/safe agree: {overturn:.1%}")


# ------------------------------------------------------------------ 3-D rolling
# The 3-D rock-and-roll model is timed by bench/rolling.py (its own peer and aims); this
# section runs it, so that one command times both.

def rolling():
    """Section 2: bench/rolling.py."""
    script = Path(__file__).with_name("rolling.py")
    print("3-D rolling (bench/rolling.py):", flush=True)
    subprocess.run([sys.executable, str(script)], check=False)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--grid", type=int, default=200)
    parser.add_argument("--peer-side", type=int, default=12,
                        help="the peer takes about peer-side^2 cells")
    parser.add_argument("--planar-only", action="store_true",
                        help="skip section 2 (bench/rolling.py)")
    args = parser.parse_args()
    planar(args)
    if not args.planar_only:
        rolling()


if __name__ == "__main__":
    main()
