#!/usr/bin/env python3
"""Benchmark: time per evaluated point of the exponential pulse through Python.

Evaluates a, v, d of the half-cycle exponential pulse at 1e7 points (tau spread over
[-0.1, 1.1], one beta), several runs, and prints the median time per point. The peer,
measured in the same run, is a plain numpy evaluation of the printed closed forms
(doc/pulses.md section 1: expm1-based, no special cases): the ratio is what to quote, since
these machines are shared and noisy. Targets: under 20 ns per point.

usage: PYTHONPATH=build/python python3 bench/pulses.py [--points N] [--runs R] [--beta B]
"""
import argparse

import numpy as np

from seispulse import pulse
from timing import median_time


def numpy_peer(tau, beta):
    """The printed forms in numpy (valid for moderate beta != 0 only): the peer."""
    s = np.minimum(tau, 1.0 - tau).clip(0.0, 0.5)
    c = 1.0 / (1.0 - np.exp(beta))
    e = np.expm1(2.0 * beta * s)
    vg = c + 1.0 / beta
    a = -e * c
    vr = c * (s - e / (2.0 * beta))
    ur = c * (s * s / 2.0 - (e - 2.0 * beta * s) / (4.0 * beta * beta))
    rising = tau <= 0.5
    v = np.where(rising, vr, vg - vr)
    d = np.where(rising, ur, vg * (tau - 0.5) + ur)
    after = tau >= 1.0
    a = np.where(tau < 0, 0.0, np.where(after, 0.0, a))
    v = np.where(tau < 0, 0.0, np.where(after, vg, v))
    d = np.where(tau < 0, 0.0, np.where(after, vg * (tau - 0.5), d))
    return a, v, d


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=10_000_000)
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--beta", type=float, default=-np.pi)
    args = parser.parse_args()
    tau = np.linspace(-0.1, 1.1, args.points)
    n = args.points
    t_ours = median_time(lambda: pulse.exp_pulse(tau, args.beta), args.runs)
    print(f"exponential pulse, beta = {args.beta:g}, {n:.0e} points, median of {args.runs} runs")
    print(f"  seispulse.pulse.exp_pulse : {t_ours / n * 1e9:7.2f} ns/point  ({t_ours:.3f} s)")
    if args.beta == 0.0 or not np.isfinite(args.beta):
        print("  numpy printed forms (peer): undefined at this beta (0/0 or inf/inf)")
        return
    # agreement first (the peer is accurate at moderate beta only)
    ours = pulse.exp_pulse(tau[::1000], args.beta)
    peer = numpy_peer(tau[::1000], args.beta)
    worst = max(np.max(np.abs(x - y)) for x, y in zip(ours, peer))
    t_peer = median_time(lambda: numpy_peer(tau, args.beta), args.runs)
    print(f"  numpy printed forms (peer): {t_peer / n * 1e9:7.2f} ns/point  ({t_peer:.3f} s)")
    print(f"  ratio seispulse / peer    : {t_ours / t_peer:7.3f}")
    print(f"  max |difference| on a subsample: {worst:.2e}")


if __name__ == "__main__":
    main()
