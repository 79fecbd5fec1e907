#!/usr/bin/env python3
"""Benchmark: sliding-block closed forms through Python, cases per second.

Times seispulse.sliding.half_cycle and full_cycle on arrays of N random cases
(eta uniform in (0.01, 0.99), beta uniform in [-4 pi, 4 pi]; symmetric friction), the
median of several runs, and, on the same cases, the event-driven stick-slip integrator
(method='integrator': the same quantities, computed by integration). The ratio is what
to quote, since these machines are shared and noisy. Aims: >= 2e6 half-cycle and >= 5e5
full-cycle cases per second on one core.

usage: PYTHONPATH=build/python python3 bench/sliding.py [--cases N] [--runs R] [--seed S]
"""
import argparse

import numpy as np

from seispulse import sliding
from timing import median_time


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=1_000_000)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    n = args.cases
    eta = rng.uniform(0.01, 0.99, n)
    beta = rng.uniform(-4 * np.pi, 4 * np.pi, n)
    print(f"sliding block, {n:.0e} random cases (eta, beta), median of {args.runs} runs")
    for name, fn in (("half_cycle", sliding.half_cycle), ("full_cycle", sliding.full_cycle)):
        closed = median_time(lambda: fn(eta, beta), args.runs)
        integ = median_time(lambda: fn(eta, beta, method="integrator"), args.runs)
        a, b = fn(eta[:20000], beta[:20000]), fn(eta[:20000], beta[:20000], method="integrator")
        um = "um" if name == "half_cycle" else "ures"
        scale = np.maximum(np.abs(getattr(b, um)), 1e-4)
        worst = np.max(np.abs(getattr(a, um) - getattr(b, um)) / scale)
        print(f"  {name:10s} closed forms : {n / closed:12.4g} cases/s  ({closed:.3f} s)")
        print(f"  {name:10s} integrator   : {n / integ:12.4g} cases/s  ({integ:.3f} s)")
        print(f"  {name:10s} ratio closed/integrator speed: {integ / closed:6.2f}"
              f"   max rel. difference ({um}, 2e4 cases): {worst:.1e}")


if __name__ == "__main__":
    main()
