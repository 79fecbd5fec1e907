#!/usr/bin/env python3
"""Benchmark: a 1000-frequency Veletsos-Younan sweep of the rigid-wall thrust and base
moment (omega/omega_1 from 0 to 5, loss factor 0.1, nu = 0.3) to a relative tolerance
of 1e-8. Aim: under 10 ms.

No other program implements the Veletsos & Younan (1994a) series, so the peer is the
series as one would write it in numpy: the plain sums (2.34)-(2.35) over a fixed number
of odd terms, vectorised over frequencies, with enough terms for 1e-8 (the tail of
sum 1/n^3 beyond N is about 1/(4 N^2)). Prints medians of several runs, the ratio peer
time / seispulse time, and the largest relative difference between the two answers.
Also times the one-term solution on the same grid and one Mononobe-Okabe coefficient.

usage: PYTHONPATH=build/python python3 bench/walls.py [--runs R] [--frequencies N]
"""
import argparse

import numpy as np

from seispulse import codes, walls
from timing import median_time


def numpy_vy(ratios, delta, nu, n_terms):
    """Plain (2.34)-(2.35) with the first n_terms odd terms: thrust and moment (positive)."""
    psi_sigma = 2.0 / np.sqrt((1.0 - nu) * (2.0 - nu))
    n = np.arange(1, 2 * n_terms, 2, dtype=float)
    phi2 = (ratios[:, None] / n[None, :]) ** 2
    r = 1.0 / np.sqrt(1.0 - phi2 / (1.0 + 1j * delta))
    sign = np.where(((n - 1) / 2) % 2 == 0, 1.0, -1.0)
    q = 16.0 * psi_sigma / np.pi**3 * (r / n**3).sum(axis=1)
    m = 32.0 * psi_sigma / np.pi**4 * (sign * r / n**4).sum(axis=1)
    return q, m


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--frequencies", type=int, default=1000)
    args = parser.parse_args()

    ratios = np.linspace(0.0, 5.0, args.frequencies)
    delta, nu, tol = 0.1, 0.3, 1e-8
    n_peer = 5000          # 1/(4 N^2) = 1e-8: the peer's tail at tolerance 1e-8

    sweep = walls.vy_sweep(ratios, delta, nu, tol=tol)
    q_peer, m_peer = numpy_vy(ratios, delta, nu, n_peer)
    diff_q = np.max(np.abs(sweep.q - q_peer) / np.abs(q_peer))
    diff_m = np.max(np.abs(sweep.m - m_peer) / np.abs(m_peer))

    t_sp = median_time(lambda: walls.vy_sweep(ratios, delta, nu, tol=tol), args.runs, inner=5)
    t_peer = median_time(lambda: numpy_vy(ratios, delta, nu, n_peer), args.runs)
    t_ot = median_time(lambda: walls.one_term(ratios, delta, nu), args.runs, inner=5)
    t_mo = median_time(lambda: codes.mononobe_okabe(30.0, 0.24, -0.12), args.runs, inner=200)

    print(f"Veletsos-Younan sweep: {args.frequencies} frequencies, omega/omega_1 in [0, 5], "
          f"delta = {delta}, nu = {nu}, tol = {tol:g}; medians of {args.runs} runs")
    print(f"  seispulse.walls.vy_sweep      {t_sp * 1e3:9.3f} ms   (aim: < 10 ms)")
    print(f"  numpy plain series, N = {n_peer}  {t_peer * 1e3:9.3f} ms   "
          f"ratio peer/seispulse = {t_peer / t_sp:6.1f}")
    print(f"  largest relative difference from the peer: Q {diff_q:.2e}, M {diff_m:.2e}")
    print(f"one-term solution, same grid:   {t_ot * 1e3:9.3f} ms")
    print(f"one Mononobe-Okabe coefficient: {t_mo * 1e6:9.3f} us")


if __name__ == "__main__":
    main()
