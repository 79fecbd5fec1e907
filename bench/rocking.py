#!/usr/bin/env python3
"""Benchmark: rocking blocks through Python, next to scipy's solve_ivp on the same cases.

1. classify + max_rotation (seispulse.rocking.extremes, the linearized closed forms) on N
   random cases (f in [0.2, 8], eta in (0.01, 0.99), beta in [-3 pi, 3 pi]), cases per
   second; the peer integrates the linearized equation of the same cases with
   scipy.integrate.solve_ivp (DOP853, rtol 1e-10, events for the maximum and for
   psi = 1) on a subsample, and the regions are compared.
2. A 200 x 200 nonlinear overturning map of the one-sine pulse (alpha = 0.25, Housner's
   e; omega_p/p in [0.5, 12], a_p/(g tan alpha) in [0.5, 15]), seconds; the peer
   integrates Housner's equations with impacts by solve_ivp (events at theta = 0 and
   |theta| = pi/2) on a subsample of cells, and the classes are compared.
Aims: > 1e6 cases/s, map < 10 s on one core. Quote the ratios: the machine is noisy.

usage: PYTHONPATH=build/python python3 bench/rocking.py [--cases N] [--runs R] [--grid M]
       (needs scipy for the peer columns)
"""
import argparse
import math
import time

import numpy as np

from seispulse import rocking
from timing import median_time

try:
    from scipy.integrate import solve_ivp
except ImportError:  # the peer is optional
    solve_ivp = None


def shape(tau, beta):
    """Half-cycle exponential pulse a/A_g (moderate beta != 0)."""
    s = np.minimum(tau, 1.0 - tau)
    return np.where((tau < 0) | (tau > 1), 0.0, np.expm1(2 * beta * s) / np.expm1(beta))


def peer_region(f, eta, beta):
    """Region by solve_ivp of psi'' = f^2 (psi - 1 + s/eta) from the uplift."""
    tau_up = math.log1p(eta * math.expm1(beta)) / (2 * beta)
    rhs = lambda t, y: [y[1], f * f * (y[0] - 1 + shape(t, beta) / eta)]
    top = lambda t, y: y[0] - 1.0
    top.terminal, top.direction = True, 1
    peak = lambda t, y: y[1]
    peak.terminal, peak.direction = True, -1
    sol = solve_ivp(rhs, (tau_up, 60.0), [0.0, 0.0], method="DOP853", rtol=1e-10,
                    atol=1e-12, events=[top, peak], max_step=0.05)
    if sol.t_events[0].size:
        t = sol.t_events[0][0]
        return "O1" if t <= 0.5 else "O2" if t <= 1 else "O3"
    return "S1" if sol.t_events[1].size and sol.t_events[1][0] <= 1 else "S2"


def peer_cell(w, amp, alpha, e):
    """Class of one map cell by solve_ivp of Housner's equations (p = g = 1)."""
    period = 2 * math.pi / w
    a_p = amp * math.tan(alpha)
    ag = lambda t: a_p * math.sin(w * t) if t < period else 0.0
    if a_p <= math.tan(alpha):
        return 0
    t0 = math.asin(math.tan(alpha) / a_p) / w
    state, sgn, impacts, t = [0.0, 0.0], 1.0, 0, t0
    t_end = period + 40.0
    while t < t_end:
        rhs = lambda tt, y: [y[1], -(math.sin(alpha * sgn - y[0])
                                     - ag(tt) * math.cos(alpha * sgn - y[0]))]
        hit = lambda tt, y: y[0]
        hit.terminal, hit.direction = True, -sgn
        fall = lambda tt, y: abs(y[0]) - math.pi / 2
        fall.terminal = True
        sol = solve_ivp(rhs, (t, t_end), state, method="DOP853", rtol=1e-10, atol=1e-12,
                        events=[hit, fall], max_step=0.1)
        if sol.t_events[1].size:
            return min(1 + impacts, 3)
        if not sol.t_events[0].size:
            return 0
        t = sol.t_events[0][0]
        state = [0.0, e * sol.y_events[0][0][1]]
        sgn, impacts = -sgn, impacts + 1
        if abs(state[1]) < 1e-8:
            return 0
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=1_000_000)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--grid", type=int, default=200)
    parser.add_argument("--peer-cases", type=int, default=200)
    args = parser.parse_args()
    rng = np.random.default_rng(1)
    n = args.cases
    f = rng.uniform(0.2, 8.0, n)
    eta = rng.uniform(0.01, 0.99, n)
    beta = rng.uniform(-3 * np.pi, 3 * np.pi, n)
    t = median_time(lambda: rocking.extremes(f, eta, beta), args.runs)
    print(f"classify + max_rotation, {n:.0e} random cases, median of {args.runs} runs")
    print(f"  seispulse.rocking.extremes: {n / t:12.4g} cases/s  ({t:.3f} s)")
    if solve_ivp is not None:
        m = args.peer_cases
        t0 = time.perf_counter()
        regions = [peer_region(f[i], eta[i], beta[i]) for i in range(m)]
        t_peer = (time.perf_counter() - t0) / m
        ours = rocking.classify(f[:m], eta[:m], beta[:m])
        agree = np.mean([a == b for a, b in zip(ours, regions)])
        print(f"  scipy solve_ivp (peer)    : {1 / t_peer:12.4g} cases/s  ({m} cases)")
        print(f"  ratio seispulse / peer speed: {t_peer / (t / n):10.4g}   regions agree: "
              f"{agree:.1%}")
    k = args.grid
    freq = np.linspace(0.5, 12.0, k)
    amp = np.linspace(0.5, 15.0, k)
    alpha = 0.25
    e = 1 - 1.5 * math.sin(alpha) ** 2
    t_map = median_time(lambda: rocking.overturning_map("sine_cycle", freq, amp, alpha=alpha),
                        max(1, args.runs // 2))
    print(f"nonlinear one-sine overturning map {k} x {k}: {t_map:.2f} s "
          f"({t_map / k / k * 1e6:.1f} us per cell)")
    if solve_ivp is not None:
        classes = rocking.overturning_map("sine_cycle", freq, amp, alpha=alpha)
        cells = [(i, j) for i in range(0, k, max(1, k // 12)) for j in range(0, k, max(1, k // 12))]
        t0 = time.perf_counter()
        peer = [peer_cell(freq[j], amp[i], alpha, e) for i, j in cells]
        t_cell = (time.perf_counter() - t0) / len(cells)
        agree = np.mean([classes[i, j] == c for (i, j), c in zip(cells, peer)])
        print(f"  scipy solve_ivp (peer)    : {t_cell * 1e6:.0f} us per cell ({len(cells)} cells)"
              f" -> {t_cell * k * k:.0f} s for the map; ratio {t_cell * k * k / t_map:.1f}; "
              f"classes agree: {agree:.1%}")


if __name__ == "__main__":
    main()
