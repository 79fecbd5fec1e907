"""Exact spectrum peaks for periods far below the time step (many damped cycles in one
record step): bounded cost, and the same maxima as the sub-step search.

Above 64 sub-steps per record step sdof_sim searches only the first and the last damped
cycle of each step (cycles_run); below, every sub-step. The record is linear between
samples, so a record refined by linear interpolation is the same excitation: with a
refinement that brings the sub-steps to 64 or fewer, the sub-step search is an
independent computation of the same maxima.
"""

import os
import subprocess
import sys
import time

import numpy as np
import pytest

from seispulse import sdof
from seispulse.errors import InvalidInputError

ROOT = os.environ.get("SEISPULSE_SOURCE_ROOT",
                      os.path.join(os.path.dirname(__file__), "..", ".."))
FUZZ_INPUT = os.path.join(ROOT, "test", "data", "fuzz", "python",
                          "sdof_spectrum_tiny_period_slow.bin")


def refined(accel, r):
    """The record with r - 1 samples inserted on the line between neighbours."""
    accel = np.asarray(accel, dtype=float)
    q = np.arange(r) / r
    inner = accel[:-1, None] * (1.0 - q) + accel[1:, None] * q
    return np.append(inner.ravel(), accel[-1])


def sub_steps(period, zeta, dt):
    return int(2.0 * dt * np.sqrt(1.0 - zeta * zeta) / period) + 1


@pytest.mark.parametrize("zeta", [0.0, 1.0e-6, 0.02, 0.05, 0.3, 0.9])
@pytest.mark.parametrize("m", [65, 300, 2500])
def test_cycles_equal_sub_steps_on_refined_record(zeta, m):
    rng = np.random.default_rng(int(1000 * zeta) + m)
    accel = rng.normal(size=30) * 0.3
    dt = 0.01
    period = 2.0 * dt * np.sqrt(1.0 - zeta * zeta) / (m - 0.5)
    assert sub_steps(period, zeta, dt) == m
    r = -(-m // 40)  # 40 or fewer sub-steps on the refined record
    assert sub_steps(period, zeta, dt / r) <= 64
    fast = sdof.spectrum(accel, dt, [period], damping=zeta, threads=1)
    ref = sdof.spectrum(refined(accel, r), dt / r, [period], damping=zeta, threads=1)
    for name in ("sd", "sv", "sa"):
        np.testing.assert_allclose(getattr(fast, name), getattr(ref, name), rtol=5e-11,
                                   err_msg=name)
    # times: SD and SA peak where the ground does; SV ties between cycles when zeta = 0
    for name in ("t_sd", "t_sa") + (("t_sv",) if zeta > 0 else ()):
        np.testing.assert_allclose(getattr(fast, name), getattr(ref, name),
                                   atol=2.0 * period, err_msg=name)


@pytest.mark.parametrize("period", [1.0e-9, 1.0e-12, 1.0e-20, 1.0e-40, 1.0e-60])
@pytest.mark.parametrize("zeta", [0.0, 0.05])
def test_tiny_periods_are_fast_and_tend_to_the_ground(period, zeta):
    rng = np.random.default_rng(7)
    accel = rng.normal(size=400) * 0.3
    accel[0] = 0.0  # from rest: no free vibration of amplitude a_g(0) g / omega at t = 0
    dt = 0.01
    t0 = time.perf_counter()
    res = sdof.spectrum(accel, dt, [period], damping=zeta, threads=1)
    assert time.perf_counter() - t0 < 1.0
    # T -> 0: a_abs -> a_g (SA -> PGA over the samples, a_g being linear between
    # them), z ~ -a_g/omega^2 (SD -> PGA g / omega^2 to first order in T/dt)
    pga = np.max(np.abs(accel))
    omega = 2.0 * np.pi / period
    assert float(res.sa.ravel()[0]) == pytest.approx(pga, rel=1e-6)
    assert float(res.sd.ravel()[0]) == pytest.approx(pga * 9.80665 / omega**2, rel=1e-3)
    assert float(res.t_sa.ravel()[0]) == pytest.approx(np.argmax(np.abs(accel)) * dt,
                                                       abs=1e-6)
    # SV: the quasi-static z' = -slope / omega^2 plus the free vibrations started at
    # the kinks, of amplitude |jump of slope| / omega^2 each (at most all of them,
    # zeta = 0). The state (z, z') carries z' only to omega eps |z| ~ eps PGA g / omega,
    # above these for T below ~1e-14 s here: checked where they are resolved.
    if period < 1.0e-12:
        return
    slopes = np.diff(accel) / dt * 9.80665
    sv = float(res.sv.ravel()[0])
    assert np.max(np.abs(slopes)) / omega**2 <= sv * (1 + 1e-9)
    kicks = np.abs(np.diff(np.append(0.0, slopes)))
    assert sv <= (np.max(np.abs(slopes)) + np.sum(kicks)) / omega**2 * (1 + 1e-9)


def test_fuzz_input_replays_fast():
    pytest.importorskip("atheris")
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, os.path.join(ROOT, "fuzz", "fuzz_python.py"),
                           FUZZ_INPUT], capture_output=True, text=True, timeout=60,
                          env=dict(os.environ), check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "no finding" in done.stdout
    # the Python start and the instrumentation take most of this; the spectrum took
    # 5 s per period (11 periods) before cycles_run
    assert time.perf_counter() - t0 < 20.0


def test_spectrum_record_overflowing_with_g_is_an_error():
    """A sample whose product with g overflows (the fuzz input has 1.8e308 g) is an error
    naming it, not an infinite or meaningless spectrum."""
    accel = np.array([0.0, 1.0e308, -0.5e308, 0.0])
    with pytest.raises(InvalidInputError, match=r"accel\[1\] = .*overflows"):
        sdof.spectrum(accel, 0.01, [0.1, 1.0], damping=0.05)
    # the largest sample that does not overflow is accepted
    ok = np.array([0.0, np.finfo(float).max / 9.80665 * (1 - 1e-15), 0.0])
    sd = sdof.spectrum(ok, 0.01, [1.0], damping=0.05, peaks="samples")
    assert np.all(np.isfinite(np.asarray(sd.sa)))
