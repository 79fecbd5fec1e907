#!/usr/bin/env python3
"""Benchmark: rocking on Winkler soil through Python, next to scipy's solve_ivp on the same
equations.

Body ([AD11] section 2.2's example): a solid cylinder r = 1 m, h = 3 m (centre of mass
height), rho = 2500 kg/m^3, on tensionless Winkler springs k = 32 G/(3 pi (1 - nu) r)
(E = 100 MPa, nu = 0.3: k = 1.866e8 N/m^3) and dashpots c of xi = 0.003 (rocking mode).
1. 20 s of rocking under one sine cycle a_p = 0.4 g, T_p = 1 s (uplift, about ten
   impacts, safe), output every 0.01 s: seispulse.winkler.simulate (Radau IIA in Fortran
   with the exact Jacobian) against scipy.integrate.solve_ivp's Radau and BDF on the same
   ODE (test/python/winkler_reference.py: the same model, restarted at every contact
   change, with the closed-form contact integrals written below, so that the comparison is
   of the integrators), all at the same rtol; seconds (median of --runs), the ratios, and
   the largest difference of theta(t) from seispulse's.
2. A --grid x --grid one-sine overturning map (x = omega_p/p in [0.5, 12], y = a_p/(g tan
   theta_c) in [0.5, 15], rigid p and theta_c of the body) by
   seispulse.winkler.overturning_map (its default rtol), seconds and microseconds per cell;
   the peer classifies --peer-cells cells of the middle row with solve_ivp (BDF, rtol
   1e-6; the library's rule (W.58): to the end of the pulse and on for 100/p, safe by the
   energy barrier), per-cell ratio and the agreement of the classes.
--quick: one run, a 20 x 20 map, 5 peer cells.
Quote the ratios: the machine is noisy.

usage: PYTHONPATH=build/python python3 bench/winkler.py [--runs R] [--grid M] [--quick]
       (needs scipy; the seispulse columns need the seispulse.winkler binding)
"""
import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

from timing import median_time

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "test" / "python"))
import winkler_reference as wr  # noqa: E402 (test/python/winkler_reference.py)

try:
    from seispulse import cylinder, pulse, winkler
except ImportError:  # the binding is optional here: the scipy columns run alone
    winkler = None

R, H, RHO = 1.0, 3.0, 2500.0           # m, m, kg/m^3
E_SOIL, NU, XI = 100e6, 0.3, 0.003     # Pa, -, -
A_P, T_P, DURATION = 0.4, 1.0, 20.0    # g, s, s
RTOL = 1e-8


# ------------------------------------------------------------------ closed-form contact

def _positive(a0, a1, r):
    """The part of [-r, r] where a0 - a1 s > 0 (None if empty)."""
    lo_val, hi_val = a0 + a1 * r, a0 - a1 * r
    if lo_val > 0 and hi_val > 0:
        return -r, r
    if lo_val <= 0 and hi_val <= 0:
        return None
    root = a0 / a1
    return (-r, root) if lo_val > 0 else (root, r)


def contact_closed(body, k, c, y, varying=False):
    """(N, M, width) of the active interval in closed form (constant k): with q = A_q -
    B_q s, A_q = k v + c v', B_q = k sin(theta) + c cos(theta) theta', N = cos (A_q m0 -
    B_q m1), M = cos^2 (A_q m1 - B_q m2), m_j = int s^j 2 w ds over [s_a, s_b]; circle,
    u = acos(s/r): m0 = r^2 [(2u - sin 2u)/2], m1 = 2 r^3/3 [sin^3 u], m2 = r^4 [(4u -
    sin 4u)/16] from u(s_b) to u(s_a); rectangle: m_j = 2 alpha [s^(j+1)/(j+1)]."""
    v, th, vd, thd = y
    sn, cs = math.sin(th), math.cos(th)
    r = body.r
    geo = _positive(v, sn, r)
    if geo is None:
        return 0.0, 0.0, 0.0
    a_q, b_q = k * v + c * vd, k * sn + c * cs * thd
    pres = _positive(a_q, b_q, r)
    if pres is None:
        return 0.0, 0.0, 0.0
    lo, hi = max(geo[0], pres[0]), min(geo[1], pres[1])
    if hi <= lo:
        return 0.0, 0.0, 0.0
    if body.footing == "circle":
        ua = math.acos(max(-1.0, min(1.0, lo / r)))
        ub = math.acos(max(-1.0, min(1.0, hi / r)))
        m0 = r * r * ((2 * ua - math.sin(2 * ua)) - (2 * ub - math.sin(2 * ub))) / 2
        m1 = 2 * r ** 3 / 3 * (math.sin(ua) ** 3 - math.sin(ub) ** 3)
        m2 = r ** 4 * ((4 * ua - math.sin(4 * ua)) - (4 * ub - math.sin(4 * ub))) / 16
    else:
        al = body.alpha
        m0 = 2 * al * (hi - lo)
        m1 = al * (hi * hi - lo * lo)
        m2 = 2 * al * (hi ** 3 - lo ** 3) / 3
    return cs * (a_q * m0 - b_q * m1), cs * cs * (a_q * m1 - b_q * m2), hi - lo


# ------------------------------------------------------------------------- the case

def reference_body():
    body = wr.solid_cylinder(R, H, rho=RHO)
    k = wr.modulus_circle(E_SOIL / (2 * (1 + NU)), NU, R)
    return body, k, wr.damping_rocking(body, k, XI)


def library_model(body, k):
    """The same body and soil through seispulse (None without the binding)."""
    if winkler is None:
        return None
    lib_body = cylinder.props(R, H, mass=body.mass, g=body.g)
    return winkler.model(lib_body, k, xi=XI)


def history(args):
    """Section 1: 20 s of rocking."""
    body, k, c = reference_body()
    t = np.linspace(0.0, DURATION, int(round(DURATION / 0.01)) + 1)
    accel, breaks = wr.sine_pulse(A_P * body.g, T_P)
    print(f"solid cylinder r = {R} m, h = {H} m, m = {body.mass:.0f} kg on k = {k:.4e} N/m^3, "
          f"c = {c:.4e} N s/m^3 (xi {XI}); one sine a_p = {A_P} g, T_p = {T_P} s, "
          f"{DURATION:g} s, rtol {RTOL:g}")
    theta = {}
    times = {}
    model = library_model(body, k)
    if model is not None:
        shaking = pulse.define("sine_cycle", amp=A_P, amp_unit="g", period=T_P,
                               g=body.g)
        run = winkler.simulate(model, shaking, t=t, rtol=RTOL)
        times["seispulse"] = median_time(
            lambda: winkler.simulate(model, shaking, t=t, rtol=RTOL), args.runs)
        theta["seispulse"] = run.theta
        print(f"  seispulse winkler.simulate: {times['seispulse'] * 1e3:9.1f} ms  (median of "
              f"{args.runs}; {run.n_steps} steps, {run.n_impacts} impacts, theta_max "
              f"{run.theta_max:.5f} rad, outcome {run.outcome}, energy error "
              f"{run.energy_error:.1e})")
    else:
        print("  seispulse winkler.simulate: the binding is not built, skipped")
    for method in ("Radau", "BDF"):
        def peer():
            return wr.simulate(body, k, c, accel, t, breaks, method=method, rtol=RTOL,
                               contact=contact_closed)
        ref = peer()
        times[method] = median_time(peer, args.runs)
        theta[method] = ref.theta
        line = (f"  scipy solve_ivp {method:5s}     : {times[method] * 1e3:9.1f} ms  "
                f"({ref.nfev} evaluations, {ref.n_segments} segments, {ref.n_impacts} impacts, "
                f"theta_max {ref.theta_max:.5f} rad)")
        if "seispulse" in theta:
            diff = np.max(np.abs(ref.theta - theta["seispulse"]))
            line += (f"; ratio {times[method] / times['seispulse']:.1f}, max |theta - "
                     f"theta_seispulse| = {diff:.1e} rad")
        print(line)
    print(f"  max |theta_Radau - theta_BDF| = "
          f"{np.max(np.abs(theta['Radau'] - theta['BDF'])):.1e} rad")


def overturning(args):
    """Section 2: the map and its peer."""
    body, k, c = reference_body()
    n = args.grid
    x = np.linspace(0.5, 12.0, n)
    y = np.linspace(0.5, 15.0, n)
    th_ot = wr.static_theta_overturn(body, k)
    model = library_model(body, k)
    row = n // 2
    step = max(1, n // args.peer_cells)
    cols = list(range(0, n, step))[:args.peer_cells]
    classes = None
    if model is not None:
        def run():
            return winkler.overturning_map(model, "sine_cycle", x, y, axes="dimensionless",
                                           compare_rigid=False)
        t_map = median_time(run, 1 if args.quick else min(args.runs, 3))
        classes = np.asarray(run().classes)
        print(f"one-sine Winkler overturning map {n} x {n} (omega_p/p {x[0]}-{x[-1]}, "
              f"a_p/(g tan theta_c) {y[0]}-{y[-1]}): {t_map:.2f} s "
              f"({t_map / n / n * 1e6:.0f} us per cell); theta_overturn "
              f"{model.theta_overturn:.5f} rad (closed forms {th_ot:.5f})")
        counts = np.bincount(classes.reshape(-1) + 1, minlength=5)
        print("  cells per class: " + ", ".join(
            f"{name} {cnt}" for name, cnt in zip(("undecided", "safe", "no impact",
                                                   "one impact", "impacts"), counts)))
    else:
        print("one-sine Winkler overturning map: the binding is not built, skipped")
    t0 = time.perf_counter()
    peer = [wr.map_cell(body, k, c, x[j], y[row], theta_overturn=th_ot, rtol=1e-6,
                        contact=contact_closed) for j in cols]
    t_cell = (time.perf_counter() - t0) / len(cols)
    line = (f"  scipy solve_ivp BDF (peer, row y = {y[row]:.3f}): {t_cell * 1e3:.0f} ms per "
            f"cell ({len(cols)} cells) -> {t_cell * n * n:.0f} s for the map")
    if classes is not None:
        agree = np.mean([classes[row, j] == cl for j, cl in zip(cols, peer)])
        line += (f"; ratio per cell {t_cell * n * n / t_map:.0f}; classes agree: "
                 f"{agree:.0%}")
    print(line)
    print("  peer classes: " + " ".join(str(cl) for cl in peer)
          + ("" if classes is None else
             "\n  seispulse   : " + " ".join(str(classes[row, j]) for j in cols)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--grid", type=int, default=100)
    parser.add_argument("--peer-cells", type=int, default=100,
                        help="cells of the middle row classified by the peer")
    parser.add_argument("--quick", action="store_true",
                        help="one run, a 20 x 20 map, 5 peer cells")
    args = parser.parse_args()
    if args.quick:
        args.runs, args.grid, args.peer_cells = 1, 20, 5
    history(args)
    overturning(args)


if __name__ == "__main__":
    main()
