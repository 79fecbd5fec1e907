"""seispulse.newmark.coupled(method='exact') against an independent integration written
here: scipy's solve_ivp (DOP853, rtol 1e-12) sample step by sample step, with the onset
(HEA = ky) and the stop (s' = 0) as terminal events, on a real record (pySLAMMER's
Cape Mendocino PET-090, skipped without pyslammer) and on a short soft mass with many
short slides (H = 5 m, Vs = 600 m/s: the sliding period, 15 ms, is 3 samples)."""
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from seispulse import newmark

G = 9.80665
D1 = 1.0 - 8.0 / np.pi**2


def reference(a, dt, omega, xi, ky):
    """The coupled model (doc/flexible.md (F.30)-(F.33)) integrated by solve_ivp: s at the
    samples and at rest after the run-out (a = 0 after the record)."""
    n = a.size
    c, w2 = 2 * xi * omega, omega**2

    def acc(t, i):
        if i >= n - 1:
            return 0.0
        return a[i] + (a[i + 1] - a[i]) * (t - i * dt) / dt

    def stick(t, y, i):
        return [y[1], -4 / np.pi * G * acc(t, i) - c * y[1] - w2 * y[0], 0.0, 0.0]

    def slide(t, y, i):
        upp = (-4 / np.pi * G * ky - c * y[1] - w2 * y[0]) / D1
        return [y[1], upp, y[3], G * (acc(t, i) - ky) + 2 / np.pi * upp]

    def onset(t, y, i):
        return G * acc(t, i) + 2 / np.pi * stick(t, y, i)[1] - G * ky
    onset.terminal, onset.direction = True, 1

    def stop(t, y, i):
        return y[3]
    stop.terminal, stop.direction = True, -1

    y = np.zeros(4)
    sliding = D1 * a[0] > ky   # HEA at the first sample (the mass at rest)
    hist = [0.0]
    i = 0
    while i < n - 1 or sliding:
        t, t_end = i * dt, (i + 1) * dt
        while t < t_end - 1e-13:
            fun, ev = (slide, stop) if sliding else (stick, onset)
            # steps of at most dt/16: an event inside one of solve_ivp's steps is seen only
            # through a sign change at its ends
            sol = solve_ivp(fun, (t, t_end), y, method="DOP853", rtol=1e-12, atol=1e-14,
                            max_step=dt / 16, events=ev, args=(i,))
            y, t = sol.y[:, -1].copy(), sol.t[-1]
            if sol.status == 1:
                if sliding:
                    y[3] = 0.0
                sliding = not sliding
        if i < n - 1:
            hist.append(y[2])
        i += 1
    return np.array(hist), y[2]


def check(a, dt, height, vs, ky, rtol):
    r = newmark.coupled(a, dt, ky, height=height, vs=vs, vs_base=vs, damping=0.05,
                        method="exact", history=True)
    omega = np.pi * r.vs_final / (2 * height)
    s, s_end = reference(a, dt, omega, r.damping_final, ky)
    assert r.final_disp > 1e-3
    assert r.final_disp == pytest.approx(s_end, rel=rtol)
    assert np.max(np.abs(r.disp - s)) <= rtol * r.final_disp


def synthetic(n, dt):
    t = np.arange(n) * dt
    env = (t / 2.5) ** 2 * np.exp(2.0 - 2.0 * t / 2.5)
    return 1.5 * env * (0.15 * np.sin(5.7 * t + 0.4) + 0.22 * np.sin(13.2 * t + 0.8)
                        + 0.12 * np.sin(23.2 * t + 1.2))


def test_many_short_slides():
    check(synthetic(1000, 0.005), 0.005, 5.0, 600.0, 0.1, 1e-11)


def test_real_record():
    pyslammer = pytest.importorskip("pyslammer", reason="pyslammer ships the record")
    path = Path(pyslammer.__file__).parent / "sample_ground_motions" / \
        "Cape_Mendocino_1992_PET-090.csv"
    data = np.loadtxt(path, delimiter=",", comments="#")
    dt = data[1, 0] - data[0, 0]
    a = data[:, 1] * 0.4 / np.max(np.abs(data[:, 1]))
    a = a[: int(round(20.0 / dt)) + 1]
    check(a, dt, 20.0, 600.0, 0.1, 1e-11)
