"""seispulse.pulse against the independent mpmath references of pulse_reference.py.

Claim tested: for every quantity q in (a, v, d),
    |q_lib - q_ref| <= rtol |q_ref| + 1e-14 * peak|q|,
with rtol = 1e-13, except for the exponential pulse with large |beta|, where the
values' condition number in tau and beta is ~|beta| and rtol = 4 |beta| eps + 1e-14.
"""
import math
import sys
from pathlib import Path

import numpy as np
import pytest
from mpmath import mp, mpf

sys.path.insert(0, str(Path(__file__).resolve().parent))
import pulse_reference as ref  # noqa: E402

p = pytest.importorskip("seispulse.pulse")

EPS = 2.220446049250313e-16
RTOL = 1e-13
ATOL_PEAK = 1e-14
NAMES = ("a", "v", "d")
INF = math.inf


def _beside(x):
    """x and the doubles just below and above it."""
    return [np.nextafter(x, -INF), x, np.nextafter(x, INF)]


def _fmt(x):
    s = mp.nstr(x, 17)
    return s if len(s) <= 40 else s[:40] + "..."


def _compare(label, ts, got, want, peaks, rtol):
    """got: (a, v, d) arrays from the library; want: per-t (a, v, d) mpf tuples."""
    bad = []
    for q, name in enumerate(NAMES):
        atol = mpf(ATOL_PEAK) * peaks[q]
        for i, t in enumerate(ts):
            g = float(np.asarray(got[q]).reshape(-1)[i])
            w = want[i][q]
            if not math.isfinite(g):
                bad.append(f"{name}(t={t!r}): library {g!r}, reference {_fmt(w)}")
                continue
            err = abs(mpf(g) - w)
            if err > rtol * abs(w) + atol:
                rel = mp.nstr(err / abs(w), 3) if w else "inf"
                bad.append(f"{name}(t={t!r}): library {g!r}, reference {_fmt(w)}, "
                           f"rel err {rel}")
    assert not bad, f"{label}: {len(bad)} mismatches\n  " + "\n  ".join(bad[:20])


# ---------------------------------------------------------------------------
# Exponential pulse, dimensionless
# ---------------------------------------------------------------------------

BETAS = [0.0, 1e-300, -1e-300, 1e-15, -1e-15, 1e-9, -1e-9, 1e-7, -1e-7, 1e-3, -1e-3,
         0.5, -0.5, 1.0, -1.0, math.pi, -math.pi, 2 * math.pi, -2 * math.pi, 2.5,
         10.0, -10.0, 50.0, -50.0, 700.0, -700.0, 710.0, -710.0, 1e3, -1e3, 1e6, -1e6,
         INF, -INF]

TAUS = sorted(set(
    [-0.5, -1e-300, 1e-300, 1e-12, 1e-9, 0.1, 0.25, 0.4999, 0.5 - 1e-9, 0.5 + 1e-9, 0.7,
     0.9, 1 - 1e-9, 1 + 1e-9, 1.2, 1.5 - 1e-9, 1.5 + 1e-9, 1.75, 2 - 1e-9, 2 + 1e-9,
     2.5, 3.0]
    + _beside(0.0) + _beside(0.5) + _beside(1.0) + _beside(1.5) + _beside(2.0)))


def _exp_rtol(beta):
    if math.isinf(beta):
        return RTOL
    return max(RTOL, 4 * abs(beta) * EPS + 1e-14)


@pytest.mark.parametrize("full", [False, True], ids=["half", "full"])
@pytest.mark.parametrize("beta", BETAS, ids=[repr(b) for b in BETAS])
def test_exp_pulse(beta, full):
    tau = np.array(TAUS)
    with np.errstate(all="raise"):
        got = p.exp_pulse(tau, beta, full=full)
    want = [ref.exp_pulse(t, beta, full) for t in TAUS]
    vg, dg = ref.exp_peaks(beta, full)
    _compare(f"exp_pulse(beta={beta!r}, full={full})", TAUS, got, want,
             (mpf(1), vg, dg), _exp_rtol(beta))


@pytest.mark.parametrize("beta", [0.0, -1e-15, 1.0, -math.pi, 1e6, INF, -INF])
def test_exp_pulse_scalar_is_float(beta):
    for tau in (-0.1, 0.0, 0.3, 0.5, 1.0, 1.7, 2.0):
        for full in (False, True):
            h = p.exp_pulse(tau, beta, full=full)
            assert all(type(x) is float for x in h), (tau, beta, full, h)
            want = ref.exp_pulse(tau, beta, full)
            vg, dg = ref.exp_peaks(beta, full)
            _compare(f"exp_pulse scalar beta={beta!r} full={full}", [tau],
                     [np.array([x]) for x in h], [want], (mpf(1), vg, dg), _exp_rtol(beta))


def test_exp_pulse_broadcast():
    tau = np.array([0.2, 0.5, 0.8, 1.3, 2.4])[:, None]
    betas = np.array([-3.0, -1e-9, 0.0, 2.0, INF])[None, :]
    h = p.exp_pulse(tau, betas, full=True)
    assert all(np.shape(x) == (5, 5) for x in h)
    for i in range(5):
        for j in range(5):
            b, t = float(betas[0, j]), float(tau[i, 0])
            vg, dg = ref.exp_peaks(b, True)
            _compare(f"broadcast beta={b!r}", [t], [np.array([x[i, j]]) for x in h],
                     [ref.exp_pulse(t, b, True)], (mpf(1), vg, dg), RTOL)


@pytest.mark.parametrize("full", [False, True], ids=["half", "full"])
@pytest.mark.parametrize("beta", BETAS, ids=[repr(b) for b in BETAS])
def test_exp_pulse_peaks(beta, full):
    pk = p.exp_pulse_peaks(beta, full=full)
    vg, dg = ref.exp_peaks(beta, full)
    for name, g, w in (("vg", pk.vg, vg), ("dg", pk.dg, dg)):
        assert math.isfinite(g), (name, g)
        assert abs(mpf(g) - w) <= RTOL * abs(w), \
            f"exp_pulse_peaks({beta!r}, full={full}).{name} = {g!r}, reference {mp.nstr(w, 17)}"


@pytest.mark.parametrize("beta,published", [
    (-2 * math.pi, 0.8427159935), (-math.pi, 0.7268558192), (-1.0, 0.5819767069),
    (1.0, 0.4180232931), (math.pi, 0.2731441808), (2 * math.pi, 0.1572840065),
    (-INF, 1.0), (0.0, 0.5), (INF, 0.0)])
def test_exp_pulse_peaks_published(beta, published):
    assert abs(p.exp_pulse_peaks(beta).vg - published) <= 6e-11


@pytest.mark.parametrize("beta", BETAS, ids=[repr(b) for b in BETAS])
def test_exp_pulse_impulse_amplitude(beta):
    got = p.exp_pulse_impulse_amplitude(beta)
    want = ref.exp_impulse_amplitude(beta)
    if mp.isinf(want):
        assert got == INF
    else:
        assert abs(mpf(got) - want) <= RTOL * abs(want), (beta, got, mp.nstr(want, 17))


def test_exp_pulse_impulse_amplitude_array():
    betas = np.array([-INF, -2.0, 0.0, 1e-12, 3.0, INF])
    got = p.exp_pulse_impulse_amplitude(betas)
    assert np.shape(got) == (6,)
    for b, g in zip(betas, got):
        w = ref.exp_impulse_amplitude(float(b))
        assert (g == INF) if mp.isinf(w) else abs(mpf(float(g)) - w) <= RTOL * abs(w), (b, g)


# ---------------------------------------------------------------------------
# SI pulses
# ---------------------------------------------------------------------------

def _grid(t_lo, t_hi, n, specials):
    ts = list(np.linspace(t_lo, t_hi, n)) + [1e-12 * max(abs(t_hi), 1.0), 1e-300]
    for s in specials:
        ts += _beside(float(s))
    return sorted(set(float(t) for t in ts))


def _peaks(want, ts, t_end):
    """Peak magnitude of each quantity over the pulse (test points with t <= t_end)."""
    inside = [w for t, w in zip(ts, want) if t <= t_end] or want
    return tuple(max(abs(w[q]) for w in inside) for q in range(3))


# (kind, params, end of the pulse, special times)
def _si_cases():
    cases = []
    pi = math.pi
    cases.append(("exponential", dict(amp=3.0, td=0.8, beta=2.5), 0.8, [0.4, 0.8]))
    cases.append(("exponential", dict(amp=0.5, td=0.6, beta=-pi, full=True, amp_unit="g"),
                  1.2, [0.3, 0.6, 0.9, 1.2]))
    cases.append(("exponential", dict(amp=0.2, td=1.3, beta=-1e-9, full=True, amp_unit="g",
                                      g=9.81), 2.6, [0.65, 1.3, 1.95, 2.6]))
    cases.append(("exponential", dict(amp=-4.0, td=0.25, beta=0.0), 0.25, [0.125, 0.25]))
    cases.append(("exponential", dict(amp=1.5, td=0.5, beta=-INF, full=True), 1.0, [0.5, 1.0]))
    cases.append(("exponential", dict(amp=1.5, td=0.5, beta=INF, full=True), 1.0,
                  [0.25, 0.75, 0.5, 1.0]))
    cases.append(("exponential", dict(amp=2.0, td=0.4, beta=1e3, full=True), 0.8,
                  [0.2, 0.4, 0.6, 0.8]))
    for amp, T, extra in ((2.0, 0.7, {}), (0.3, 1.3, dict(amp_unit="g")),
                          (-1.5, 0.05, dict(amp_unit="g", g=9.81))):
        cases.append(("half_sine", dict(amp=amp, duration=T, **extra), T, [T / 2, T]))
        cases.append(("rectangular", dict(amp=amp, duration=T, **extra), T, [T]))
    for amp, T, extra in ((2.0, 0.7, {}), (0.4, 2.0, dict(amp_unit="g")),
                          (-0.8, 0.1, dict(amp_unit="g", g=9.81))):
        cases.append(("sine_cycle", dict(amp=amp, period=T, **extra), T, [T / 4, T / 2, T]))
        cases.append(("cosine_cycle", dict(amp=amp, period=T, **extra), T,
                      [T / 4, T / 2, 3 * T / 4, T]))
    for r in (0.0, 0.3, 0.5, 1.0):
        cases.append(("triangular", dict(amp=1.7, duration=0.9, peak_frac=r), 0.9,
                      [0.9 * r, 0.9]))
    cases.append(("triangular", dict(amp=0.25, duration=1.1, peak_frac=0.75, amp_unit="g"),
                  1.1, [0.825, 1.1]))
    cases.append(("triangular", dict(amp=1.0, duration=0.6), 0.6, [0.3, 0.6]))   # default r
    for amp, f, t0, extra in ((3.0, 1.2, None, {}), (3.0, 1.2, 0.2, {}),
                              (0.3, 1.5, 1.0, dict(amp_unit="g", g=9.81)),
                              (2.0, 5.0, 0.0, {}), (1.0, 0.5, 0.05, dict(amp_unit="g"))):
        tc = 1.5 / f if t0 is None else t0
        params = dict(amp=amp, freq=f, **extra)
        if t0 is not None:
            params["t0"] = t0
        cases.append(("ricker", params, tc + 3 / f, [tc, tc + 0.5 / f]))
    for A, f, gam, nu, t0 in ((0.9, 0.8, 1.0001, 0.0, None), (0.9, 0.8, 2.0, 90.0, None),
                              (0.5, 1.5, 1.5, -45.0, 2.0), (1.2, 0.4, 3.0, 30.0, None),
                              (0.7, 2.0, 1.0001, 90.0, 0.4), (0.6, 1.0, 1.0001, -45.0, None),
                              (1.0, 0.5, 1.01, 0.0, 2.0)):
        tc = gam / (2 * f) if t0 is None else t0
        half = gam / (2 * f)
        params = dict(vamp=A, freq=f, gamma=gam, nu_deg=nu)
        if t0 is not None:
            params["t0"] = t0
        cases.append(("mavroeidis_papageorgiou", params, tc + half,
                      [tc - half, tc, tc + half, tc - half / 2]))
    return cases


SI_CASES = _si_cases()


def _case_id(case):
    kind, params, _, _ = case
    return kind + "(" + ",".join(f"{k}={v}" for k, v in params.items()) + ")"


def _si_peaks(kind, params, t_end, specials):
    ts = _grid(0.0, t_end, 41, specials)
    return _peaks([ref.evaluate(kind, t, **params) for t in ts], ts, t_end)


def _check_si(kind, params, t_end, specials, call):
    # every special time and the doubles beside it; t = 0 from the right only (the
    # doubles just below 0 are tested in test_tiny_negative_time)
    ts = _grid(-0.1 * t_end, 1.3 * t_end, 41, list(specials))
    ts = sorted(set(ts + [0.0, 5e-324]))
    want = [ref.evaluate(kind, t, **params) for t in ts]
    with np.errstate(all="raise"):
        got = call(np.array(ts))
    assert all(np.shape(x) == (len(ts),) for x in got)
    rtol = _exp_rtol(params["beta"]) if kind == "exponential" else RTOL
    _compare(_case_id((kind, params, 0, 0)), ts, got, want, _peaks(want, ts, t_end), rtol)


@pytest.mark.parametrize("case", SI_CASES, ids=[_case_id(c) for c in SI_CASES])
def test_si_pulse(case):
    kind, params, t_end, specials = case
    _check_si(kind, params, t_end, specials, lambda t: getattr(p, kind)(t, **params))


@pytest.mark.parametrize("case", SI_CASES[::3], ids=[_case_id(c) for c in SI_CASES[::3]])
def test_evaluate_by_name(case):
    kind, params, t_end, specials = case
    _check_si(kind, params, t_end, specials, lambda t: p.evaluate(kind, t, **params))


@pytest.mark.parametrize("kind", ref.KINDS)
def test_scalar_returns_floats(kind):
    case = next(c for c in SI_CASES if c[0] == kind)
    _, params, t_end, specials = case
    peaks = _si_peaks(kind, params, t_end, specials)
    for t in (-0.5 * t_end, 0.0, 0.37 * t_end, t_end, 1.5 * t_end):
        h = getattr(p, kind)(t, **params)
        assert all(type(x) is float for x in h), (kind, t, h)
        _compare(f"{kind} scalar", [t], [np.array([x]) for x in h],
                 [ref.evaluate(kind, t, **params)], peaks, RTOL)


# t < 0 is before the pulse even when t / (time scale) underflows to -0.0.
TINY_NEGATIVE = [
    ("rectangular", dict(amp=1.0, duration=2.0), 2.0, []),
    ("cosine_cycle", dict(amp=1.0, period=2.0), 2.0, []),
    ("triangular", dict(amp=1.0, duration=2.0, peak_frac=0.0), 2.0, []),
    ("exponential", dict(amp=1.0, td=2.0, beta=-INF), 2.0, []),
    ("ricker", dict(amp=1.0, freq=0.5, t0=0.05), 6.05, []),
    ("half_sine", dict(amp=1.0, duration=0.7), 0.7, []),
    ("mavroeidis_papageorgiou", dict(vamp=1.0, freq=1.0, gamma=2.0), 2.0, []),
]


@pytest.mark.parametrize("case", TINY_NEGATIVE, ids=[_case_id(c) for c in TINY_NEGATIVE])
def test_tiny_negative_time(case):
    kind, params, t_end, _ = case
    ts = [-5e-324, -1e-310, -1e-300]
    got = getattr(p, kind)(np.array(ts), **params)
    for q, name in enumerate(NAMES):
        assert all(x == 0 for x in got[q]), \
            f"{_case_id(case)}: {name}(t={ts}) = {list(got[q])}, expected 0 before the pulse"


# Far-from-unit time scales: results must stay finite and accurate.
EXTREME = [
    ("ricker", dict(amp=1.0, freq=1.0), 3.0, [1e10, 1e155, 1e300]),
    ("half_sine", dict(amp=1.0, duration=1e-200), 1e-200, [1e3, 1e150]),
    ("half_sine", dict(amp=1.0, duration=1e150), 1e150, [0.5]),
    ("rectangular", dict(amp=1.0, duration=1e160), 1e160, [0.5, 1e-300]),
    ("triangular", dict(amp=1.0, duration=1e-10, peak_frac=1e-300), 1e-10, [1e300]),
]


@pytest.mark.parametrize("case", EXTREME, ids=[_case_id(c) + f"@t={c[3]}" for c in EXTREME])
def test_extreme_scales(case):
    kind, params, t_end, ts = case
    peaks = _si_peaks(kind, params, t_end, [])
    with np.errstate(all="ignore"):
        got = getattr(p, kind)(np.array(ts), **params)
    _compare(_case_id(case), ts, got, [ref.evaluate(kind, t, **params) for t in ts],
             peaks, RTOL)


def test_broadcast_parameters():
    t = np.array([0.0, 0.1, 0.35, 0.6, 0.9])[:, None]
    amp = np.array([1.0, -2.0, 0.5])[None, :]
    dur = np.array([0.4, 0.7, 1.0])[None, :]
    h = p.half_sine(t, amp, dur, amp_unit="g")
    assert all(np.shape(x) == (5, 3) for x in h)
    for i in range(5):
        for j in range(3):
            want = ref.half_sine(float(t[i, 0]), float(amp[0, j]), float(dur[0, j]), "g")
            for q in range(3):
                assert abs(mpf(float(h[q][i, j])) - want[q]) <= RTOL * abs(want[q]) + 1e-15


def test_amp_unit_g_matches_si():
    t = np.linspace(-0.1, 1.5, 17)
    hg = p.exponential(t, 0.5, 0.6, -math.pi, full=True, amp_unit="g")
    hs = p.exponential(t, 0.5 * 9.80665, 0.6, -math.pi, full=True)
    for x, y in zip(hg, hs):
        np.testing.assert_allclose(x, y, rtol=1e-15, atol=1e-16)
