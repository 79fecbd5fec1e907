"""seispulse.sdof closed forms (Fortran seispulse_sdof_closed) against computations that do
not use the library: scipy.integrate.quad and mpmath quadrature of Duhamel's integral,
scipy's solve_ivp (DOP853, rtol 1e-12), the ground accelerations written here from their
definitions; the book's numbers with its errata corrected (doc/oscillator.md); bad input."""
import math
import warnings

import mpmath as mp
import numpy as np
import pytest
from scipy.integrate import IntegrationWarning, quad, solve_ivp

import seispulse
from seispulse import pulse as P
from seispulse import sdof as S
from seispulse.errors import InvalidInputError, SingularError

PI = math.pi


# ------------------------------------------------------------------ independent a_g

def exp_accel(t, amp, td, beta, full):
    """Jacobsen & Ayre lobe, (e^(2 beta r) - 1)/(e^beta - 1) on the rising half."""
    lobe, tau = (1.0, t / td) if t < td else (-1.0, t / td - 1.0)
    if t < 0 or tau >= 1.0 or (lobe < 0 and not full):
        return 0.0
    x = min(tau, 1.0 - tau)
    if beta == 0.0:
        return lobe * amp * 2 * x
    return lobe * amp * math.expm1(2 * beta * x) / math.expm1(beta)


def make_accel(kind, **p):
    A = p.get("amp", p.get("vamp"))
    if kind == "exponential":
        return lambda t: exp_accel(t, A, p["td"], p["beta"], p.get("full", False))
    if kind == "half_sine":
        return lambda t: A * math.sin(PI * t / p["duration"]) if 0 <= t < p["duration"] else 0.0
    if kind == "sine_cycle":
        return lambda t: A * math.sin(2 * PI * t / p["period"]) if 0 <= t < p["period"] else 0.0
    if kind == "cosine_cycle":
        return lambda t: A * math.cos(2 * PI * t / p["period"]) if 0 <= t < p["period"] else 0.0
    if kind == "rectangular":
        return lambda t: A if 0 <= t < p["duration"] else 0.0
    if kind == "triangular":
        d, r = p["duration"], p["peak_frac"]
        return lambda t: (0.0 if t < 0 or t >= d else A * t / (r * d) if t < r * d
                          else A * (d - t) / ((1 - r) * d))
    if kind == "ricker":
        f, t0 = p["freq"], p["t0"]
        return lambda t: (A * (1 - 2 * (PI * f * (t - t0)) ** 2)
                          * math.exp(-(PI * f * (t - t0)) ** 2) if t >= 0 else 0.0)
    if kind == "mavroeidis_papageorgiou":
        f, g, nu, t0 = p["freq"], p["gamma"], math.radians(p.get("nu_deg", 0.0)), p["t0"]

        def acc(t):
            x = t - t0
            if abs(x) > g / (2 * f):
                return 0.0
            env = 1 + math.cos(2 * PI * f * x / g)
            denv = -2 * PI * f / g * math.sin(2 * PI * f * x / g)
            c, s = math.cos(2 * PI * f * x + nu), math.sin(2 * PI * f * x + nu)
            return 0.5 * A * (denv * c - env * 2 * PI * f * s)
        return acc
    raise ValueError(kind)


def breaks(kind, **p):
    if kind == "exponential":
        td = p["td"]
        return [td / 2, td, 1.5 * td, 2 * td] if p.get("full") else [td / 2, td]
    if kind == "triangular":
        return [p["peak_frac"] * p["duration"], p["duration"]]
    if kind == "ricker":
        f, t0 = p["freq"], p["t0"]
        return [t0 - 0.39 / f, t0, t0 + 0.39 / f, t0 + 12 / (PI * f)]
    if kind == "mavroeidis_papageorgiou":
        h = p["gamma"] / (2 * p["freq"])
        return [p["t0"] - h, p["t0"] + h]
    return [p.get("duration", p.get("period"))]


def duhamel_quad(acc, brk, period, zeta, t):
    """z, z', a_abs at t by scipy.quad of Duhamel's integral (epsrel 1e-13: quad may warn
    that rounding keeps it from that target; the comparison tolerance is 1e-9)."""
    w = 2 * PI / period
    wd = w * math.sqrt(1 - zeta ** 2)
    pts = [0.0] + [b for b in brk if 0 < b < t] + [t]
    z = v = 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", IntegrationWarning)
        for a, b in zip(pts[:-1], pts[1:]):
            if b <= a:
                continue
            z -= quad(lambda s: math.exp(-zeta * w * (t - s)) * math.sin(wd * (t - s)) / wd
                      * acc(s), a, b, epsabs=0, epsrel=1e-13, limit=400)[0]
            v -= quad(lambda s: math.exp(-zeta * w * (t - s)) * (math.cos(wd * (t - s))
                      - zeta * w / wd * math.sin(wd * (t - s))) * acc(s), a, b, epsabs=0,
                      epsrel=1e-13, limit=400)[0]
    return z, v, -(2 * zeta * w * v + w * w * z)


def ode_history(acc, brk, period, zeta, t_eval):
    """z, z', a_abs by DOP853 (rtol 1e-12), restarted at every break of a_g."""
    w = 2 * PI / period
    t_eval = np.asarray(t_eval, float)
    out = np.zeros((3, t_eval.size))
    edges = [0.0] + sorted(b for b in brk if b > 0)
    edges.append(max(t_eval.max(), edges[-1]) + 1.0)
    y = np.zeros(2)
    for a, b in zip(edges[:-1], edges[1:]):
        sel = (t_eval >= a) & (t_eval < b)
        # a_g on (a, b), evaluated just inside so that a jump at an end is honoured
        inside = (lambda s, a=a, b=b: acc(min(max(s, a + 1e-13 * (b - a)), b - 1e-13 * (b - a))))
        sol = solve_ivp(lambda s, u: [u[1], -inside(s) - 2 * zeta * w * u[1] - w * w * u[0]],
                        (a, b), y, method="DOP853", rtol=1e-12, atol=1e-16,
                        t_eval=np.append(t_eval[sel], b), max_step=min(period, b - a) / 20)
        zz, vv = sol.y[:, :-1]
        out[0, sel], out[1, sel] = zz, vv
        out[2, sel] = -(2 * zeta * w * vv + w * w * zz)
        y = sol.y[:, -1]
    return out


PULSES = [
    ("exponential", dict(amp=2.0, td=0.7, beta=0.0)),
    ("exponential", dict(amp=2.0, td=0.7, beta=0.6, full=True)),
    ("exponential", dict(amp=-2.0, td=0.7, beta=-3.0, full=True)),
    ("exponential", dict(amp=2.0, td=0.7, beta=25.0)),
    ("half_sine", dict(amp=1.5, duration=0.45)),
    ("sine_cycle", dict(amp=1.1, period=0.8)),
    ("cosine_cycle", dict(amp=0.9, period=0.8)),
    ("rectangular", dict(amp=1.2, duration=0.35)),
    ("triangular", dict(amp=1.2, duration=0.6, peak_frac=0.3)),
    ("ricker", dict(amp=2.0, freq=1.3, t0=1.1)),
    ("mavroeidis_papageorgiou", dict(vamp=0.4, freq=0.9, gamma=2.3, nu_deg=40.0, t0=1.5)),
]
CASES = [(0.23, 0.0), (0.9, 0.05), (3.1, 0.3)]


def ids(p):
    return f"{p[0]}-{p[1].get('beta', '')}"


@pytest.mark.parametrize("pulse_def", PULSES, ids=ids)
@pytest.mark.parametrize("period, zeta", CASES)
def test_pulse_response_equals_quad(pulse_def, period, zeta):
    kind, p = pulse_def
    acc, brk = make_accel(kind, **p), breaks(kind, **p)
    end = max(brk)
    t = np.array([0.01, 0.11, 0.3, 0.349, 0.5, 0.71, 0.93, end, end + 0.37 * period,
                  end + 2.2 * period])
    r = S.pulse_response(P.define(kind, **p), period, zeta, t=t)
    ref = np.array([duhamel_quad(acc, brk, period, zeta, ti) for ti in t]).T
    for got, want in zip(r, ref):
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-9 * np.abs(want).max())


@pytest.mark.parametrize("pulse_def", PULSES, ids=ids)
def test_pulse_response_equals_solve_ivp(pulse_def):
    kind, p = pulse_def
    period, zeta = 0.6, 0.04
    acc, brk = make_accel(kind, **p), breaks(kind, **p)
    t = np.linspace(0.0, max(brk) + 1.5, 97)
    ref = ode_history(acc, brk, period, zeta, t)
    r = S.pulse_response(P.define(kind, **p), period, zeta, t=t)
    for got, want in zip(r, ref):
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-8 * np.abs(want).max())


def test_mpmath_duhamel_exponential():
    # 30-digit Duhamel integral of a full-cycle exponential pulse, beta = 5
    amp, td, beta, period, zeta = 2.0, 0.7, 5.0, 0.55, 0.05
    with mp.workdps(30):
        w = 2 * mp.pi / period
        wd = w * mp.sqrt(1 - mp.mpf(zeta) ** 2)

        def acc(s):
            if s >= 2 * td:
                return 0
            lobe, tau = (1, s / td) if s < td else (-1, s / td - 1)
            x = min(tau, 1 - tau)
            return lobe * amp * mp.expm1(2 * beta * x) / mp.expm1(beta)

        for t in (0.3, 0.9, 2.0):
            pts = [0] + [b for b in (td / 2, td, 1.5 * td, 2 * td) if b < t] + [t]
            z = -mp.quad(lambda s: mp.exp(-zeta * w * (t - s)) * mp.sin(wd * (t - s)) / wd
                         * acc(s), pts)
            got = S.pulse_response(P.define("exponential", amp=amp, td=td, beta=beta,
                                            full=True), period, zeta, t=t).z
            assert abs(got - float(z)) <= 1e-14 * 0.05


def mp_duhamel(acc, edges, period, zeta, t, dps=40):
    """z(t), z'(t) by mpmath quadrature of Duhamel's integral (kernel
    e^(-zeta w u) sin(w_d u) / w_d, with w_d from (1 - zeta)(1 + zeta): exact for zeta
    near 1), over the pieces of [0, t] cut at `edges` and 16 sub-panels each."""
    with mp.workdps(dps):
        z = mp.mpf(zeta)
        w = 2 * mp.pi / period
        wd = w * mp.sqrt((1 - z) * (1 + z))
        t = mp.mpf(t)
        cuts = [mp.mpf(0)] + [mp.mpf(e) for e in edges if 0 < e < t] + [t]
        pts = []
        for a, b in zip(cuts[:-1], cuts[1:]):
            pts += list(mp.linspace(a, b, 17))[:-1]
        pts.append(t)
        kz = lambda s: mp.exp(-z * w * (t - s)) * mp.sin(wd * (t - s)) / wd * acc(s)
        kv = lambda s: mp.exp(-z * w * (t - s)) * (mp.cos(wd * (t - s))
                                                  - z * w / wd * mp.sin(wd * (t - s))) * acc(s)
        return float(-mp.quad(kz, pts)), float(-mp.quad(kv, pts))


@pytest.mark.parametrize("zeta", [1 - 2.0 ** -53, 1 - 1e-12])
def test_zeta_near_one_keeps_digits(zeta):
    # Re V = -Im K / sqrt(1 - zeta^2) lost eps / sqrt(1 - zeta^2) (2e-8 at 1 - 2^-53)
    amp, td = 1.0, 0.5
    t = [0.05, 0.2, 0.5, 0.9, 2.0]
    r = S.pulse_response(P.define("half_sine", amp=amp, duration=td), 1.0, zeta, t=t)
    acc = lambda s: amp * mp.sin(mp.pi * s / td) if s < td else mp.mpf(0)
    for i, ti in enumerate(t):
        z, v = mp_duhamel(acc, [td], 1.0, zeta, ti)
        assert r.z[i] == pytest.approx(z, rel=1e-13, abs=0)
        assert r.v[i] == pytest.approx(v, rel=1e-13, abs=0)


# ------------------------------------------------------------------ book forms

def test_dynamic_coefficient_book():
    assert S.dynamic_coefficient(0.5) == pytest.approx(4 / 3, rel=1e-15)
    assert S.dynamic_coefficient(2.0) == pytest.approx(-1 / 3, rel=1e-15)   # Eq. 2.17 signed
    # Eq. 2.20 with the square root: beta = 1/gamma at resonance (both models)
    assert S.dynamic_coefficient(1.0, 0.2) == pytest.approx(5.0, rel=1e-15)
    assert S.dynamic_coefficient(1.0, 0.2, model="viscous") == pytest.approx(5.0, rel=1e-15)
    r, g = 0.6, 0.2
    assert S.dynamic_coefficient(r, g) == pytest.approx(1 / math.sqrt((1 - r * r) ** 2 + g * g))
    assert S.dynamic_coefficient(r, g, "viscous") == pytest.approx(
        1 / math.sqrt((1 - r * r) ** 2 + (g * r) ** 2))
    # cosine law: 2|beta| (doc/oscillator.md section 3)
    np.testing.assert_allclose(S.cosine_dynamic_coefficient([0.3, 0.5, 2.0]),
                               [2.1978, 2.6667, 0.6667], atol=1e-4)
    b = S.dynamic_coefficient(np.array([[0.5], [1.5]]), [0.1, 0.2, 0.3])
    assert b.shape == (2, 3)
    with pytest.raises(SingularError, match="ratio"):
        S.dynamic_coefficient(1.0)


def test_mononobe_is_steady_state():
    period, w0, r = 1.0, 3.0, 0.5
    w = 2 * PI / period
    beta = 1 / (1 - r * r)
    t = np.linspace(0, 8, 200001)
    ss = S.harmonic_response(t, w0, period, r, law="sine", transient=False)
    np.testing.assert_allclose(ss.z, w0 * beta * np.sin(r * w * t) / w ** 2, atol=1e-15)
    np.testing.assert_allclose(-ss.a_abs, w0 * beta * np.sin(r * w * t), atol=1e-13)   # Eq. 2.18
    tr = S.harmonic_response(t, w0, period, r, law="sine")
    assert np.abs(tr.z).max() * w ** 2 / (w0 * beta) == pytest.approx(1.299, abs=5e-4)
    with pytest.raises(SingularError):
        S.harmonic_response(t[:3], w0, period, 1.0, transient=False)


def test_cosine_law_erratum():
    period, w0, r = 0.7, 1.7, 0.5
    w = 2 * PI / period
    beta = 1 / (1 - r * r)
    t = 0.3 * period
    z = S.harmonic_response(t, w0, period, r, law="cosine").z
    corrected = w0 * beta / w ** 2 * (math.cos(r * w * t) - math.cos(w * t))
    printed = w0 * beta / w ** 2 * (math.cos(r * w * t) - math.sin(w * t))
    assert z == pytest.approx(corrected, rel=1e-13)
    assert abs(z - printed) > 0.5 * abs(printed)
    assert abs(S.harmonic_response(period, w0, period, r, law="cosine").z) * w ** 2 / w0 == \
        pytest.approx(2 * beta, rel=1e-13)


@pytest.mark.parametrize("r", [1.0, 1 - 1e-9, 1 + 1e-9, 1 - 1e-5])
@pytest.mark.parametrize("law", ["sine", "cosine"])
def test_resonance_against_mpmath(r, law):
    # 50-digit closed forms: no cancellation problem at that precision
    period, w0 = 1.0, 2.0
    t = np.array([0.3, 1.7, 5.25, 20.1])
    got = S.harmonic_response(t, w0, period, r, law=law).z
    with mp.workdps(50):
        w = 2 * mp.pi / period
        rr = mp.mpf(r)
        for ti, zi in zip(t, got):
            ti = mp.mpf(ti)
            if rr == 1:
                ref = (w0 / (2 * w ** 2) * (mp.sin(w * ti) - w * ti * mp.cos(w * ti))
                       if law == "sine" else w0 / (2 * w) * ti * mp.sin(w * ti))
            elif law == "sine":
                ref = w0 / w ** 2 * (mp.sin(rr * w * ti) - rr * mp.sin(w * ti)) / (1 - rr ** 2)
            else:
                ref = w0 / w ** 2 * (mp.cos(rr * w * ti) - mp.cos(w * ti)) / (1 - rr ** 2)
            assert abs(zi - float(ref)) <= 1e-13 * w0 / float(w) * 20


@pytest.mark.parametrize("law", ["sine", "cosine"])
@pytest.mark.parametrize("r", [0.5, 1.0, 2.0])
def test_damped_steady_state(r, law):
    # z'' + 2 zeta w z' + w^2 z = W0 sin(theta t) (or cos): the particular solution
    # (W0/w^2)[(1 - r^2) sin - 2 zeta r cos]/D, cosine [(1 - r^2) cos + 2 zeta r sin]/D,
    # D = (1 - r^2)^2 + (2 zeta r)^2
    period, w0, zeta = 0.8, 2.5, 0.07
    w = 2 * PI / period
    th = r * w
    t = np.array([0.0, 0.13, 0.9, 3.7, 12.2])
    d, den = 1 - r * r, (1 - r * r) ** 2 + (2 * zeta * r) ** 2
    if law == "sine":
        z = w0 / w ** 2 * (d * np.sin(th * t) - 2 * zeta * r * np.cos(th * t)) / den
        v = w0 / w ** 2 * th * (d * np.cos(th * t) + 2 * zeta * r * np.sin(th * t)) / den
    else:
        z = w0 / w ** 2 * (d * np.cos(th * t) + 2 * zeta * r * np.sin(th * t)) / den
        v = w0 / w ** 2 * th * (-d * np.sin(th * t) + 2 * zeta * r * np.cos(th * t)) / den
    a = -(2 * zeta * w * v + w * w * z)
    got = S.harmonic_response(t, w0, period, r, damping=zeta, law=law, transient=False)
    amp = w0 / w ** 2 / math.sqrt(den)
    np.testing.assert_allclose(got.z, z, rtol=0, atol=1e-14 * amp)
    np.testing.assert_allclose(got.v, v, rtol=0, atol=1e-14 * amp * th)
    np.testing.assert_allclose(got.a_abs, a, rtol=0, atol=1e-13 * amp * w * w)
    # its amplitude is the viscous beta with gamma = 2 zeta, not the default (hysteretic)
    assert S.dynamic_coefficient(r, 2 * zeta, "viscous") == pytest.approx(1 / math.sqrt(den),
                                                                          rel=1e-14)


def test_cosine_coefficient_is_undamped_only():
    # 2|beta| is the from-rest maximum of the cosine law only without damping: with
    # zeta = 0.05 at r = 1 the history from rest (solve_ivp) tends to 1/gamma = 10 < 20
    with pytest.raises(InvalidInputError, match="^gamma"):
        S.cosine_dynamic_coefficient(1.0, 0.1)
    with pytest.raises(InvalidInputError, match="^gamma"):
        S.cosine_dynamic_coefficient([0.5, 1.0], [0.0, 0.1])
    assert S.cosine_dynamic_coefficient(0.5, 0.0) == pytest.approx(8 / 3, rel=1e-15)
    period, zeta = 1.0, 0.05
    w = 2 * PI / period
    sol = solve_ivp(lambda s, u: [u[1], math.cos(w * s) - 2 * zeta * w * u[1] - w * w * u[0]],
                    (0, 40), [0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-14,
                    t_eval=np.linspace(0, 40, 400001))
    top = np.abs(sol.y[0]).max() * w * w
    assert top == pytest.approx(10.0, rel=1e-4)
    assert top < 0.51 * 2 * S.dynamic_coefficient(1.0, 2 * zeta)


def test_rect_pulse_book_forms():
    period, w0 = 0.9, 1.3
    w = 2 * PI / period
    for t1 in (0.27, 0.45, 1.6):
        t = np.array([0.3 * t1, t1 + 0.37, 3.0])
        r = S.rect_pulse_response(t, w0, t1, period)
        assert r.z[0] == pytest.approx(-w0 / w ** 2 * (1 - math.cos(w * t[0])), rel=1e-13)
        # Eq. 2.23 with the minus sign
        assert r.z[1] == pytest.approx(-2 * w0 / w ** 2 * math.sin(w * t1 / 2)
                                       * math.sin(w * (t[1] - t1 / 2)), rel=1e-12)
        ref = [duhamel_quad(make_accel("rectangular", amp=w0, duration=t1), [t1], period, 0.0, x)
               for x in t]
        np.testing.assert_allclose(r.z, [x[0] for x in ref], atol=1e-11 * w0 / w ** 2)


@pytest.mark.parametrize("period", [1e160, 1e200])
def test_rect_pulse_huge_period(period):
    # W0 / omega^2 alone overflows for T > ~1e154 (it gave -inf and nan); the closed form
    # -(2 W0 / omega^2) sin^2(omega t / 2), -(2 W0 / omega^2) sin(omega t1 / 2)
    # sin(omega (t - t1 / 2)) at 60 digits
    t = np.array([0.5, 2.0, 7.0])
    r = S.rect_pulse_response(t, 1.0, 1.0, period)
    with mp.workdps(60):
        w = 2 * mp.pi / mp.mpf(period)
        ref = [-2 / w ** 2 * mp.sin(w * mp.mpf(0.5) / 2) ** 2]
        ref += [-2 / w ** 2 * mp.sin(w / 2) * mp.sin(w * (mp.mpf(x) - mp.mpf(0.5)))
                for x in t[1:]]
        vref = [-mp.sin(w * mp.mpf(0.5)) / w] + [-2 / w * mp.sin(w / 2) * mp.cos(
            w * (mp.mpf(x) - mp.mpf(0.5))) for x in t[1:]]
    np.testing.assert_allclose(r.z, [float(x) for x in ref], rtol=1e-15)
    np.testing.assert_allclose(r.z, [-0.125, -1.5, -6.5], rtol=1e-15)   # z = -d_g
    np.testing.assert_allclose(r.v, [float(x) for x in vref], rtol=1e-15)
    assert np.all(np.isfinite(r.a_abs)) and np.all(np.abs(r.a_abs) < 1e-300)


def test_beta_pulse_values():
    x = np.array([0.05, 0.1, 0.25, 0.4])
    np.testing.assert_allclose(S.beta_pulse(x), [0.3128, 0.6180, 1.4143, 1.9021], atol=1e-4)
    np.testing.assert_allclose(S.beta_pulse(x, "textbook"), [1.3142, 1.6283, 2.5708, 3.5133],
                               atol=1e-4)
    assert S.beta_pulse(0.8) == 2.0
    # independent: the largest |omega^2 z|/W0 of the undamped rectangle on a dense grid
    for xi in x:
        t = np.linspace(0, 3, 300001)
        r = S.rect_pulse_response(t, 1.0, xi, 1.0)
        assert np.abs(r.a_abs).max() == pytest.approx(S.beta_pulse(xi), rel=1e-6)


def test_impulse():
    jw, period = 0.8, 0.6
    w = 2 * PI / period
    zmax, tmax = S.impulse_max(jw, period)
    assert zmax == pytest.approx(jw / w) and tmax == pytest.approx(period / 4)   # Eq. 2.25
    for zeta in (0.05, 0.4):
        zm, tm = S.impulse_max(jw, period, zeta)
        t = np.linspace(0, period, 200001)
        z = S.impulse_response(t, jw, period, zeta).z
        assert zm == pytest.approx(np.abs(z).max(), rel=1e-8)
        assert tm == pytest.approx(t[np.abs(z).argmax()], abs=2 * period / 200000)
        # rectangle with t1 -> 0 at fixed J_W
        t1 = 1e-7 * period
        pk = S.pulse_peaks(P.define("rectangular", amp=jw / t1, duration=t1), period, zeta)
        assert pk.z_max == pytest.approx(zm, rel=1e-6)


# ------------------------------------------------------------------ peaks and spectra

@pytest.mark.parametrize("pulse_def", PULSES, ids=ids)
@pytest.mark.parametrize("period, zeta", [(0.31, 0.0), (1.7, 0.08)])
def test_peaks_against_dense_samples(pulse_def, period, zeta):
    kind, p = pulse_def
    pulse = P.define(kind, **p)
    pk = S.pulse_peaks(pulse, period, zeta)
    t = np.linspace(0, max(breaks(kind, **p)) + 2 * period, 200001)
    r = S.pulse_response(pulse, period, zeta, t=t)
    for peak, when, hist in ((pk.z_max, pk.t_z, r.z), (pk.v_max, pk.t_v, r.v),
                             (pk.a_max, pk.t_a, r.a_abs)):
        sample = np.abs(hist).max()
        assert sample * (1 - 1e-14) <= peak <= sample * (1 + 1e-5)
    # the value at the reported time is the peak, quantity by quantity
    for peak, when, name in ((pk.z_max, pk.t_z, "z"), (pk.v_max, pk.t_v, "v"),
                             (pk.a_max, pk.t_a, "a_abs")):
        at = getattr(S.pulse_response(pulse, period, zeta, t=when), name)
        assert abs(at) == pytest.approx(peak, rel=1e-13)


def test_spectrum_and_shock_spectrum():
    pulse = P.define("half_sine", amp=3.0, duration=0.5)
    periods = np.array([0.0, 0.1, 0.5, 2.0])
    sp, times = S.pulse_spectrum(pulse, periods, 0.05, return_times=True)
    assert sp.sd[0] == 0 and sp.sv[0] == 0 and sp.sa[0] == 3.0 and sp.psa[0] == 3.0
    w = 2 * PI / periods[1:]
    np.testing.assert_allclose(sp.psv[1:], w * sp.sd[1:], rtol=1e-15)
    np.testing.assert_allclose(sp.psa[1:], w * w * sp.sd[1:], rtol=1e-15)
    # damped maxima against solve_ivp on a dense grid (its grid sits within (w dt)^2 of them)
    for i in (1, 2, 3):
        grid = np.linspace(0, 0.5 + 2 * periods[i], 40001)
        ref = ode_history(make_accel("half_sine", amp=3.0, duration=0.5), [0.5], periods[i],
                          0.05, grid)
        for got, hist, when in ((sp.sd[i], ref[0], times.t_sd[i]),
                                (sp.sv[i], ref[1], times.t_sv[i]),
                                (sp.sa[i], ref[2], times.t_sa[i])):
            k = np.abs(hist).argmax()
            assert got == pytest.approx(np.abs(hist[k]), rel=2e-6)
            assert when == pytest.approx(grid[k], abs=2 * (grid[1] - grid[0]))
    # undamped, t_d / T = tau < 1/2: the residual maximum
    # omega^2 sd / A = 4 tau cos(pi tau) / (1 - 4 tau^2) at t = t_d / 2 + T / 4
    und, ut = S.pulse_spectrum(pulse, [2.0, 5.0], 0.0, return_times=True)
    for k, T in enumerate((2.0, 5.0)):
        tau = 0.5 / T
        assert (2 * PI / T) ** 2 * und.sd[k] / 3.0 == pytest.approx(
            4 * tau * math.cos(PI * tau) / (1 - 4 * tau * tau), rel=1e-13)
        assert ut.t_sd[k] == pytest.approx(0.25 + T / 4, rel=1e-12)
    assert S.pulse_spectrum(pulse, [[0.2, 0.3]]).sd.shape == (1, 2)
    # classic shock spectrum of the undamped half sine: peak amplification ~1.77 near 0.8
    ratios = np.linspace(0.5, 1.2, 141)
    sh = S.shock_spectrum(pulse, ratios, damping=0.0)
    np.testing.assert_allclose(sh.periods, 0.5 / ratios)
    np.testing.assert_allclose(sh.amplification, sh.psa / 3.0)
    assert 1.75 < sh.amplification.max() < 1.78
    assert 0.75 < ratios[sh.amplification.argmax()] < 0.9
    # independent check of one point with solve_ivp
    T = 0.5 / 0.8
    ref = ode_history(make_accel("half_sine", amp=3.0, duration=0.5), [0.5], T, 0.0,
                      np.linspace(0, 3, 30001))
    assert S.shock_spectrum(pulse, 0.8, damping=0.0).sd == pytest.approx(
        np.abs(ref[0]).max(), rel=1e-6)
    rk = P.define("ricker", amp=2.0, freq=1.3, t0=1.1)
    assert S.shock_spectrum(rk, 1.0).periods == pytest.approx(1 / 1.3)
    assert S.shock_spectrum(rk, 1.0, time_scale=2.0).periods == pytest.approx(2.0)


def test_jump_pulse_spectrum_near_zero_period():
    # period 0 is the PGA, but a jump of a_g overshoots: T -> 0+ is the step response,
    # 2 undamped, max of 1 - e^(-zeta x)(cos(wd x) - (zeta / wd) sin(wd x)) damped
    rect = P.define("rectangular", amp=2.0, duration=0.5)
    assert S.pulse_spectrum(rect, [0.0, 1e-4], 0.0).sa / 2.0 == pytest.approx([1.0, 2.0],
                                                                               rel=1e-9)
    with mp.workdps(30):
        z = mp.mpf(0.05)
        wd = mp.sqrt(1 - z * z)
        f = lambda x: 1 - mp.exp(-z * x) * (mp.cos(wd * x) - z / wd * mp.sin(wd * x))
        step = float(f(mp.findroot(lambda x: mp.diff(f, x), 3.0)))
    assert step == pytest.approx(1.8587581017750918, rel=1e-15)
    assert S.pulse_spectrum(rect, 1e-4, 0.05).sa / 2.0 == pytest.approx(step, rel=1e-9)


def test_peak_scan_limit():
    # 2^20 scan steps of <= T / 32 per segment: a 2 s rectangle needs T >= 2 / 32768 s;
    # shorter periods aliased silently (1.3e-10 instead of 1 at T = 2^-19)
    rect = P.define("rectangular", amp=1.0, duration=2.0)
    with pytest.raises(InvalidInputError, match=r"^period = .*must be >= 0.6103515625E-4"):
        S.pulse_peaks(rect, 2.0 ** -19, 0.0)
    with pytest.raises(InvalidInputError, match=r"^periods\[1\] = "):
        S.pulse_spectrum(rect, [1.0, 2.0 ** -19], 0.02)
    # just above: the step overshoot (W0 / omega^2)(1 + exp(-zeta pi / sqrt(1 - zeta^2)))
    T = 2.0 / 16384
    for zeta in (0.0, 0.02):
        pk = S.pulse_peaks(rect, T, zeta)
        assert pk.z_max * (2 * PI / T) ** 2 == pytest.approx(
            1 + math.exp(-zeta * PI / math.sqrt(1 - zeta * zeta)), rel=1e-12)
    mp_pulse = P.define("mavroeidis_papageorgiou", vamp=0.4, freq=1.0, gamma=40000.0,
                        nu_deg=0.0, t0=20000.0)
    with pytest.raises(InvalidInputError, match="^gamma"):
        S.pulse_peaks(mp_pulse, 1.0)


@pytest.mark.parametrize("gamma", [1e5, 1e8])
def test_mp_peak_acceleration_huge_gamma(gamma):
    # 64 gamma overflowed the integer step count beyond 3.4e7; the scan aliased beyond 1.6e4.
    # gamma -> inf: the peak is 2 pi f |A| (1 + O(1 / gamma^2)) within a cycle of t0
    pulse = P.define("mavroeidis_papageorgiou", vamp=0.4, freq=0.9, gamma=gamma, nu_deg=30.0,
                     t0=gamma / 1.8)
    amax, tmax = S.peak_ground_acceleration(pulse)
    assert amax == pytest.approx(2 * PI * 0.9 * 0.4, rel=1e-13 + 10 / gamma ** 2)
    assert abs(tmax - gamma / 1.8) <= 1 / 0.9


def test_exponential_limits():
    # beta = 0 is the triangle, beta = -inf the box: against Duhamel quadrature of the
    # triangle's and the rectangle's a_g written here (not the library's segments)
    t = np.array([0.05, 0.2, 0.35, 0.6, 0.9, 1.7, 3.0])
    tri = [duhamel_quad(make_accel("triangular", amp=2.0, duration=0.7, peak_frac=0.5),
                        [0.35, 0.7], 0.6, 0.05, x)[0] for x in t]
    for beta in (0.0, 1e-300):
        e0 = S.pulse_response(P.define("exponential", amp=2.0, td=0.7, beta=beta), 0.6, 0.05,
                              t=t)
        np.testing.assert_allclose(e0.z, tri, rtol=0, atol=1e-11 * np.abs(tri).max())
    box = [duhamel_quad(make_accel("rectangular", amp=2.0, duration=0.7), [0.7], 0.6, 0.05,
                        x)[0] for x in t]
    for beta in (-np.inf, -1e300):
        ebox = S.pulse_response(P.define("exponential", amp=2.0, td=0.7, beta=beta), 0.6, 0.05,
                                t=t)
        np.testing.assert_allclose(ebox.z, box, rtol=0, atol=1e-11 * np.abs(box).max())
    spike = S.pulse_peaks(P.define("exponential", amp=2.0, td=0.7, beta=np.inf), 0.6, 0.05)
    assert spike.z_max == spike.v_max == spike.a_max == 0.0
    huge = S.pulse_peaks(P.define("exponential", amp=2.0, td=0.7, beta=1e300), 0.6, 0.05)
    assert all(np.isfinite(huge)) and huge.z_max > 0


# ------------------------------------------------------------------ bad input

def test_bad_input_names_the_parameter():
    pulse = P.define("half_sine", amp=1.0, duration=0.5)
    with pytest.raises(InvalidInputError, match="^period"):
        S.pulse_peaks(pulse, -1.0)
    with pytest.raises(InvalidInputError, match="^period"):
        S.pulse_response(pulse, float("nan"), t=[0.1])
    with pytest.raises(InvalidInputError, match="^damping"):
        S.pulse_spectrum(pulse, [0.5], damping=1.0)
    with pytest.raises(InvalidInputError, match="^damping"):
        S.harmonic_response(0.1, 1.0, 1.0, 0.5, damping=-0.1)
    with pytest.raises(InvalidInputError, match="^pulse"):
        S.pulse_peaks("half_sine", 1.0)
    with pytest.raises(InvalidInputError, match="^t"):
        S.pulse_response(pulse, 1.0)
    with pytest.raises(InvalidInputError, match="^law"):
        S.harmonic_response(0.1, 1.0, 1.0, 0.5, law="tangent")
    with pytest.raises(InvalidInputError, match="^model"):
        S.dynamic_coefficient(0.5, model="coulomb")
    with pytest.raises(InvalidInputError, match="^variant"):
        S.beta_pulse(0.1, variant="book")
    with pytest.raises(InvalidInputError, match="^ratio"):
        S.dynamic_coefficient(-0.5)
    with pytest.raises(InvalidInputError, match="^t1"):
        S.rect_pulse_response(0.1, 1.0, 0.0, 1.0)
    with pytest.raises(InvalidInputError, match="^ratios"):
        S.shock_spectrum(pulse, [1.0, -1.0])
    with pytest.raises(ValueError):   # InvalidInputError is a ValueError
        S.impulse_max(1.0, 0.0)
    assert issubclass(seispulse.InvalidInputError, ValueError)
    # impulse_response, peak_ground_acceleration
    with pytest.raises(InvalidInputError, match="^jw"):
        S.impulse_response([0.1], float("nan"), 1.0)
    with pytest.raises(InvalidInputError, match="^period"):
        S.impulse_response([0.1], 1.0, -1.0)
    with pytest.raises(InvalidInputError, match="^damping"):
        S.impulse_response([0.1], 1.0, 1.0, damping=1.0)
    with pytest.raises(InvalidInputError, match="^pulse"):
        S.peak_ground_acceleration("ricker")
    # NaN and Inf ratios and times
    inf, nan = float("inf"), float("nan")
    for bad in (nan, inf):
        with pytest.raises(InvalidInputError, match="^ratio"):
            S.harmonic_response(0.1, 1.0, 1.0, bad)
        with pytest.raises(InvalidInputError, match="^ratio"):
            S.harmonic_response(0.1, 1.0, 1.0, bad, damping=0.05, transient=False)
        with pytest.raises(InvalidInputError, match="^ratio"):
            S.dynamic_coefficient(bad)
        with pytest.raises(InvalidInputError, match=r"^t\[1\] = "):
            S.harmonic_response([0.1, bad], 1.0, 1.0, 0.5)
        with pytest.raises(InvalidInputError, match=r"^t\[1\] = "):
            S.rect_pulse_response([0.1, bad], 1.0, 0.5, 1.0)
        with pytest.raises(InvalidInputError, match=r"^t\[1\] = "):
            S.impulse_response([0.1, bad], 1.0, 1.0)
        with pytest.raises(InvalidInputError, match="^t1"):
            S.rect_pulse_response(0.1, 1.0, bad, 1.0)


def test_tiny_periods_are_refused():
    # omega = 2 pi / 1e-308 overflows (it gave sa = 0 with no error): both modules refuse
    # 0 < T < 1e-60
    pulse = P.define("half_sine", amp=1.0, duration=0.5)
    for call in (lambda: S.pulse_peaks(pulse, 1e-308),
                 lambda: S.pulse_response(pulse, 1e-308, t=[0.1]),
                 lambda: S.harmonic_response(0.1, 1.0, 1e-308, 0.5),
                 lambda: S.impulse_max(1.0, 1e-308),
                 lambda: S.rect_pulse_response(0.1, 1.0, 0.5, 1e-61)):
        with pytest.raises(InvalidInputError, match="^period = "):
            call()
    with pytest.raises(InvalidInputError, match=r"^periods\[1\] = .*1e-60|^periods\[1\] = .*E-59"):
        S.pulse_spectrum(pulse, [0.5, 1e-308])
    # 2e-60 is accepted: quasi-static, z = -a_g / omega^2
    r = S.pulse_response(pulse, 2e-60, 0.05, t=[0.1])
    assert r.z[0] * (2 * PI / 2e-60) ** 2 == pytest.approx(-math.sin(PI * 0.2), rel=1e-12)


def test_shock_spectrum_names_the_ratio():
    pulse = P.define("half_sine", amp=1.0, duration=0.5)
    # the Fortran refusal of periods(i) is restated for the ratio the caller passed
    with pytest.raises(InvalidInputError, match=r"^ratios\[1\] = 1e\+300: gives the period"):
        S.shock_spectrum(pulse, [1.0, 1e300])
    with pytest.raises(InvalidInputError, match=r"^ratios\[1, 0\] = 1e\+62"):
        S.shock_spectrum(pulse, [[1.0, 2.0], [1e62, 3.0]])
    # too short for the peak scan (t_d / ratio < t_d / 32768)
    with pytest.raises(InvalidInputError, match=r"^ratios\[0\] = 100000.0: .*peak search"):
        S.shock_spectrum(pulse, [1e5, 1.0])
    # t_d / ratio overflows: ratio ~ 1e-320 gave period = inf and a message about periods
    with pytest.raises(InvalidInputError, match=r"^ratios\[2\] = 1e-320: .*overflows"):
        S.shock_spectrum(pulse, [1.0, 2.0, 1e-320])
    with pytest.raises(InvalidInputError, match=r"^ratios\[1\] = nan"):
        S.shock_spectrum(pulse, [1.0, np.nan])
    with pytest.raises(InvalidInputError, match=r"^ratios\[0\] = -1.0"):
        S.shock_spectrum(pulse, [-1.0])
