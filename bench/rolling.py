#!/usr/bin/env python3
"""Benchmark: rocking with rolling of a cylinder through Python, next to scipy's solve_ivp.

Case ([AD11] section 1.2's forced run; the geometry is ours, the thesis' is lost): a solid
cylinder r = 1 m, h = 3 m (centre of mass height), 1000 kg, Housner's e, from theta0 =
0.2 rad with spin 0.1 rad/s, under 20 s of harmonic shaking T = 1 s, PGA 0.4 g (20 sine
cycles) along the initial rocking plane; output every 0.01 s.
seispulse.cylinder roll (DOP853 in Fortran, rtol 1e-10) is timed (median of R runs); the
peer integrates the same Euler-angle equations (doc/rolling.md (L.1)-(L.7), written here
in numpy) with scipy.integrate.solve_ivp (DOP853, the same rtol; events at theta = 0 with
the same impact rule). Printed: times, their ratio, the largest difference of theta, and
the energy drift of 20 s of free motion (same start, no shaking) from the run's summary.
Aim: < 50 ms on one core. Quote the ratio: the machine is noisy.

usage: PYTHONPATH=build/python python3 bench/rolling.py [--runs R]  (scipy for the peer)
"""
import argparse
import time
import numpy as np

from seispulse import cylinder, pulse
from seispulse.cylinder import roll
from timing import median_time

try:
    from scipy.integrate import solve_ivp
except ImportError:  # the peer is optional
    solve_ivp = None

G = 9.80665
R, H, M = 1.0, 3.0, 1000.0                 # base radius (m), CoM height (m), mass (kg)
A = M * (3 * R * R + 4 * H * H) / 12      # J_G, transverse (kg m^2)
C = M * R * R / 2                         # J_axis (kg m^2)
J_O = A + M * (R * R + H * H)
E = 1 - 2 * M * R * R / J_O               # Housner: 1 - (2 m R_c^2/J_o) sin^2(theta_c) with
                                          # R_c the corner distance: R_c sin(theta_c) = R
PGA, PERIOD, CYCLES = 0.4 * G, 1.0, 20
DIRECTION = np.pi / 2                     # along the initial rocking plane (psi0 = 0)
STATE0 = (0.2, 0.0, 0.0, 0.0, 0.0, 0.1)   # theta, psi, spin and their rates
RTOL = 1e-10


def peer_rhs(t, y):
    """(L.1)-(L.7) on the triad (n, d, Z): the moment equation about the contact point."""
    th, ps, _, thd, psd, phd = y[:6]
    s, c, sp, cp = np.sin(th), np.cos(th), np.sin(ps), np.cos(ps)
    a = PGA * np.sin(2 * np.pi * t / PERIOD) if t < CYCLES * PERIOD else 0.0
    ax, ay = a * np.cos(DIRECTION), a * np.sin(DIRECTION)
    an, ad = ax * cp + ay * sp, -ax * sp + ay * cp
    e3 = np.array([0.0, -s, c])
    rho = np.array([0.0, R * c - H * s, R * s + H * c])
    om = np.array([thd, -phd * s, psd + phd * c])
    omc = np.array([thd, 0.0, psd])
    w0 = np.array([phd * psd * s, thd * psd - phd * thd * c, -phd * thd * s])
    i_g = A * np.eye(3) + (C - A) * np.outer(e3, e3)
    i_p = i_g + M * (rho @ rho * np.eye(3) - np.outer(rho, rho))
    rdot = np.cross(omc, rho)
    rhs = (np.cross(rho, -M * np.array([an, ad, G])) - i_g @ w0 - np.cross(om, i_g @ om)
           - M * (np.cross(rho, np.cross(w0, rho)) + np.cross(rho, np.cross(om, rdot))))
    mat = np.column_stack([i_p[:, 0], i_p[:, 2], -i_p[:, 1]])
    x = np.linalg.solve(mat, rhs)
    phdd = x[2] / s
    v = np.cross(om, rho)
    return [thd, psd, phd, x[0], x[1] - c * phdd, phdd, v[0] * cp - v[1] * sp,
            v[0] * sp + v[1] * cp]


def peer(t_out):
    """solve_ivp from impact to impact (theta = 0: psi + pi, theta' -> e |theta'|)."""
    hit = lambda t, y: y[0]
    hit.terminal, hit.direction = True, -1
    y = np.array([*STATE0, 0.0, 0.0])
    t0, theta = 0.0, np.full(t_out.size, np.nan)
    p = np.sqrt(M * G * np.hypot(R, H) / J_O)
    for _ in range(1000):
        keep = (t_out >= t0) & (t_out <= t_out[-1])
        sol = solve_ivp(peer_rhs, (t0, t_out[-1]), y, method="DOP853", rtol=RTOL,
                        atol=RTOL * 1e-2, events=hit, max_step=0.5 / p, dense_output=True)
        ends = sol.t[-1]
        part = keep & (t_out <= ends)
        theta[part] = sol.sol(t_out[part])[0]
        if sol.status != 1:
            break
        y = sol.y_events[0][0].copy()
        y[0], y[1], y[3] = 0.0, y[1] + np.pi, E * abs(y[3])
        t0 = sol.t_events[0][0]
    return theta


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    body = cylinder.props(R, H, M, g=G)
    shaking = pulse.define("sine_cycle", amp=PGA, period=PERIOD, cycles=CYCLES)
    t_out = np.linspace(0.0, 20.0, 2001)
    kw = dict(theta0=STATE0[0], psi0=STATE0[1], spin0=STATE0[2], theta_rate0=STATE0[3],
              psi_rate0=STATE0[4], spin_rate0=STATE0[5], t=t_out, rtol=RTOL)
    run = roll(body, shaking, direction_deg=np.degrees(DIRECTION), **kw)
    t_ours = median_time(lambda: roll(body, shaking, direction_deg=np.degrees(DIRECTION), **kw),
                         args.runs)
    free = roll(body, **kw)
    print("rocking with rolling, 20 s of harmonic shaking T = 1 s, PGA 0.4 g, theta0 = 0.2 rad,"
          " spin 0.1 rad/s")
    print(f"  seispulse roll     : {t_ours * 1e3:8.2f} ms  (median of {args.runs}; "
          f"{run.n_steps} steps, {run.n_impacts} impacts, theta_max {run.theta_max:.4f} rad, "
          f"outcome {run.outcome}, max |F_t|/N {run.friction_max:.3f})")
    print(f"  energy drift, 20 s free from the same start: {free.energy_drift:.2e} "
          f"(relative, {free.n_impacts} impacts)")
    if solve_ivp is not None:
        t0 = time.perf_counter()
        theta_peer = peer(t_out)
        t_peer = time.perf_counter() - t0
        diff = np.nanmax(np.abs(theta_peer - run.theta))
        print(f"  scipy solve_ivp    : {t_peer * 1e3:8.2f} ms  (DOP853, rtol {RTOL:g})")
        print(f"  ratio peer / seispulse: {t_peer / t_ours:8.1f}   max |theta - theta_peer| = "
              f"{diff:.2e} rad")


if __name__ == "__main__":
    main()
