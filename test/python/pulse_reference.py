"""Independent high-precision (mpmath) reference values for the seispulse pulses.

Written from the mathematical definitions only (not from the library's code). Every
function takes Python floats (converted exactly to mpf) and returns (a, v, d) as
mpf: acceleration, velocity v = int_0^t a and displacement d = int_0^t v, all zero
before the pulse starts; at a jump a takes the value after the jump.

Closed forms used (derivations in the comments); ``_self_check()`` verifies them
against mp.quad and is meant to be run by hand: ``python3 pulse_reference.py``.
"""
from mpmath import mp, mpf

mp.dps = 50
G_STANDARD = 9.80665


def _amp(amp, amp_unit, g):
    if amp_unit == "g":
        return mpf(amp) * mpf(g)
    if amp_unit in ("m/s2", "m/s^2"):
        return mpf(amp)
    raise ValueError(f"unknown amp_unit {amp_unit!r}")


# ---------------------------------------------------------------------------
# Exponential pulse (Jacobsen & Ayre), dimensionless.
#
# With phi_k(x) = sum_n x^n / (n + k)!  (phi_1 = (e^x - 1)/x, phi_2 = (e^x - 1 - x)/x^2,
# phi_3 = (e^x - 1 - x - x^2/2)/x^3), on the rising half 0 <= x <= 1/2 of the lobe
#   a = (1 - e^{2 b x}) / (1 - e^b)           = 2 x   phi_1(2 b x) / phi_1(b)
#   v = int_0^x a                              = 2 x^2 phi_2(2 b x) / phi_1(b)
#   d = int_0^x v                              = 2 x^3 phi_3(2 b x) / phi_1(b)
# (b = 0 gives the triangle 2x, x^2, x^3/3). The lobe is symmetric about 1/2, so on
# 1/2 <= x <= 1, with h(.) the rising-half values and V = 2 v_h(1/2) the lobe area,
#   a = a_h(1 - x),  v = V - v_h(1 - x),  d = V (x - 1/2) + d_h(1 - x).
# V = phi_2(b)/phi_1(b) = 1/(1 - e^b) + 1/b.  These forms have no cancellation
# for any b, including tiny |b| (the phi series) and huge |b| (mpmath's exponent
# range is unbounded).
# ---------------------------------------------------------------------------

def _phi(k, x):
    """phi_k(x) = sum_{n>=0} x^n/(n+k)! for k = 1, 2, 3, accurate for all real x."""
    x = mpf(x)
    if abs(x) < 1:
        with mp.workdps(mp.dps + 10):
            term = mpf(1) / mp.factorial(k)
            total = term
            n = 0
            eps = mp.eps
            while abs(term) > eps * abs(total):
                n += 1
                term = term * x / (n + k)
                total += term
        return +total
    with mp.workdps(mp.dps + 10):   # |x| >= 1: at most ~1 digit lost to cancellation
        e = mp.expm1(x)
        if k == 1:
            r = e / x
        elif k == 2:
            r = (e - x) / x**2
        elif k == 3:
            r = (e - x - x**2 / 2) / x**3
        else:
            raise ValueError(k)
    return +r


def exp_vg(beta):
    """Lobe area V_g/(A_g t_d) = 1/(1 - e^beta) + 1/beta (box 1, triangle 1/2, spike 0)."""
    beta = mpf(beta)
    if mp.isinf(beta):
        return mpf(1) if beta < 0 else mpf(0)
    return _phi(2, beta) / _phi(1, beta)


def exp_peaks(beta, full=False):
    vg = exp_vg(beta)
    return vg, (vg if full else vg / 2)


def exp_impulse_amplitude(beta):
    vg = exp_vg(beta)
    return mp.inf if vg == 0 else 1 / vg


def _exp_lobe(x, beta):
    """(a, v, d) of one lobe at 0 <= x < 1 (plus x = 1 for finite beta)."""
    if mp.isinf(beta):
        if beta < 0:                          # box: a = 1 on [0, 1)
            return mpf(1), x, x**2 / 2
        return (mpf(1) if x == mpf(1) / 2 else mpf(0)), mpf(0), mpf(0)   # spike
    p1 = _phi(1, beta)

    def rising(y):
        z = 2 * beta * y
        return (2 * y * _phi(1, z) / p1, 2 * y**2 * _phi(2, z) / p1,
                2 * y**3 * _phi(3, z) / p1)

    half = mpf(1) / 2
    if x <= half:
        return rising(x)
    V = _phi(2, beta) / p1
    a, v, d = rising(1 - x)
    return a, V - v, V * (x - half) + d


def exp_pulse(tau, beta, full=False):
    """Dimensionless exponential pulse at tau = t/t_d: (a/A_g, v/(A_g t_d), d/(A_g t_d^2))."""
    tau, beta = mpf(tau), mpf(beta)
    zero = mpf(0)
    if tau < 0:
        return zero, zero, zero
    V = exp_vg(beta)
    if tau < 1:
        return _exp_lobe(tau, beta)
    if not full:                              # coasting at V after the half cycle
        return zero, V, V / 2 + V * (tau - 1)
    if tau < 2:                               # mirrored lobe on [1, 2)
        a, v, d = _exp_lobe(tau - 1, beta)
        return -a, V - v, V / 2 + V * (tau - 1) - d
    return zero, zero, V


def exponential(t, amp, td, beta, full=False, amp_unit="m/s2", g=G_STANDARD):
    A, td = _amp(amp, amp_unit, g), mpf(td)
    a, v, d = exp_pulse(mpf(t) / td, beta, full)
    return A * a, A * td * v, A * td**2 * d


# ---------------------------------------------------------------------------
# Classic pulses. For a = A sin(w t): v = A (1 - cos w t)/w, d = A (t - sin(w t)/w)/w;
# for a = A cos(w t): v = A sin(w t)/w, d = A (1 - cos w t)/w^2.  1 - cos x is
# evaluated as 2 sin^2(x/2) and x - sin x by its series for small x.
# ---------------------------------------------------------------------------

def _omc(x):
    """1 - cos x without cancellation."""
    return 2 * mp.sin(x / 2) ** 2


def _xms(x):
    """x - sin x without cancellation."""
    x = mpf(x)
    if abs(x) >= 1:
        with mp.workdps(mp.dps + 5):
            r = x - mp.sin(x)
        return +r
    with mp.workdps(mp.dps + 10):             # x^3/3! - x^5/5! + ...
        term = x**3 / 6
        total = term
        n = 3
        while abs(term) > mp.eps * abs(total):
            term = -term * x**2 / ((n + 1) * (n + 2))
            n += 2
            total += term
    return +total


def _after(end, a_v_d_end, t):
    """Free motion after the pulse: a = 0, v constant, d linear."""
    _, v1, d1 = a_v_d_end
    return mpf(0), v1, d1 + v1 * (t - end)


def half_sine(t, amp, duration, amp_unit="m/s2", g=G_STANDARD):
    A, T, t = _amp(amp, amp_unit, g), mpf(duration), mpf(t)
    if t < 0:
        return mpf(0), mpf(0), mpf(0)
    w = mp.pi / T
    if t >= T:    # v(T) = 2 A/w, d(T) = A T/w
        return _after(T, (0, 2 * A / w, A * T / w), t)
    return A * mp.sin(w * t), A * _omc(w * t) / w, A * _xms(w * t) / w**2


def sine_cycle(t, amp, period, amp_unit="m/s2", g=G_STANDARD, cycles=1):
    A, T, t = _amp(amp, amp_unit, g), mpf(period), mpf(t)
    n = int(cycles)
    if t < 0:
        return mpf(0), mpf(0), mpf(0)
    if t >= n * T:    # v(nT) = 0, d(nT) = n A T / w = n A T^2 / (2 pi)
        return mpf(0), mpf(0), n * A * T**2 / (2 * mp.pi)
    w = 2 * mp.pi / T
    return A * mp.sin(w * t), A * _omc(w * t) / w, A * _xms(w * t) / w**2


def cosine_cycle(t, amp, period, amp_unit="m/s2", g=G_STANDARD, cycles=1):
    A, T, t = _amp(amp, amp_unit, g), mpf(period), mpf(t)
    if t < 0 or t >= int(cycles) * T:   # v(nT) = d(nT) = 0
        return mpf(0), mpf(0), mpf(0)
    w = 2 * mp.pi / T
    return A * mp.cos(w * t), A * mp.sin(w * t) / w, A * _omc(w * t) / w**2


def rectangular(t, amp, duration, amp_unit="m/s2", g=G_STANDARD):
    A, T, t = _amp(amp, amp_unit, g), mpf(duration), mpf(t)
    if t < 0:
        return mpf(0), mpf(0), mpf(0)
    if t >= T:
        return mpf(0), A * T, A * T**2 / 2 + A * T * (t - T)
    return A, A * t, A * t**2 / 2


def triangular(t, amp, duration, peak_frac=0.5, amp_unit="m/s2", g=G_STANDARD):
    """Rise 0 -> A on [0, t1 = r T], fall A -> 0 on [t1, T].

    Rise: a = A t/t1, v = A t^2/(2 t1), d = A t^3/(6 t1).
    Fall (u = T - t, L = T - t1): a = A u/L, v = A t1/2 + A (L^2 - u^2)/(2 L),
      d = A t1^2/6 + (A t1/2)(t - t1) + A/(2L) [L^2 (t - t1) - (L^3 - u^3)/3].
    """
    A, T, t, r = _amp(amp, amp_unit, g), mpf(duration), mpf(t), mpf(peak_frac)
    if not 0 <= r <= 1:
        raise ValueError("peak_frac must be in [0, 1]")
    if t < 0:
        return mpf(0), mpf(0), mpf(0)
    t1 = r * T
    L = T - t1
    if t >= T:
        vT = A * T / 2
        dT = A * t1**2 / 6 + A * t1 * L / 2 + A * L**2 / 3
        return mpf(0), vT, dT + vT * (t - T)
    if t < t1:
        return A * t / t1, A * t**2 / (2 * t1), A * t**3 / (6 * t1)
    u = T - t
    a = A * u / L
    v = A * t1 / 2 + A * (L**2 - u**2) / (2 * L)
    d = A * t1**2 / 6 + A * t1 / 2 * (t - t1) + A / (2 * L) * (L**2 * (t - t1) - (L**3 - u**3) / 3)
    return a, v, d


def ricker(t, amp, freq, t0=None, amp_unit="m/s2", g=G_STANDARD):
    """a = A (1 - 2 k^2 s^2) e^{-k^2 s^2}, s = t - t0, k = pi f, switched on at t = 0.

    d/dt [s e^{-k^2 s^2}] = a/A, so with E0 = e^{-k^2 t0^2} and
    w = k^2 ((t - t0)^2 - t0^2) = k^2 t (t - 2 t0):
      v = A [s e^{-k^2 s^2} + t0 E0]            = A E0 [t e^{-w} - t0 expm1(-w)]
      d = A [(E0 - e^{-k^2 s^2})/(2 k^2) + t0 E0 t] = A E0 [-expm1(-w)/(2 k^2) + t0 t]
    """
    if t0 is None:
        t0 = 1.5 / freq               # the double the Python default produces
    A, f, t0, t = _amp(amp, amp_unit, g), mpf(freq), mpf(t0), mpf(t)
    if t < 0:
        return mpf(0), mpf(0), mpf(0)
    k2 = (mp.pi * f) ** 2
    s = t - t0
    a = A * (1 - 2 * k2 * s**2) * mp.exp(-k2 * s**2)
    E0 = mp.exp(-k2 * t0**2)
    w = k2 * t * (t - 2 * t0)
    em = mp.expm1(-w)
    v = A * E0 * (t * mp.exp(-w) - t0 * em)
    d = A * E0 * (-em / (2 * k2) + t0 * t)
    return a, v, d


def mavroeidis_papageorgiou(t, vamp, freq, gamma, nu_deg=0.0, t0=None):
    """Velocity pulse; with th = 2 pi f (t - t0) on [-pi gamma, pi gamma] and c = 1/gamma,
      v = (A/2) [cos(th+nu) + cos((1+c)th+nu)/2 + cos((1-c)th+nu)/2]
      a = dv/dt = -pi f A [sin(th+nu) + (1+c) sin((1+c)th+nu)/2 + (1-c) sin((1-c)th+nu)/2]
      d = (A/2)/(2 pi f) [G(1) + G(1+c)/2 + G(1-c)/2],
    G(al) = int_{-pi gamma}^{th} cos(al x + nu) dx = 2 cos(al (th+ths)/2 + nu) sin(al (th-ths)/2)/al
    (-> (th - ths) cos nu as al -> 0; no cancellation for gamma near 1).
    """
    if t0 is None:
        t0 = gamma / (2 * freq)       # the double the Python default produces
    A, f, gam, t, t0 = mpf(vamp), mpf(freq), mpf(gamma), mpf(t), mpf(t0)
    nu = mp.radians(mpf(nu_deg))
    half = gam / (2 * f)
    zero = mpf(0)
    if t < t0 - half:
        return zero, zero, zero
    c = 1 / gam
    ths = -mp.pi * gam

    def G(al, th):
        if al == 0:
            return (th - ths) * mp.cos(nu)
        return 2 * mp.cos(al * (th + ths) / 2 + nu) * mp.sin(al * (th - ths) / 2) / al

    def disp(th):
        return A / 2 / (2 * mp.pi * f) * (G(1, th) + G(1 + c, th) / 2 + G(1 - c, th) / 2)

    if t > t0 + half:
        return zero, zero, disp(-ths)
    th = 2 * mp.pi * f * (t - t0)
    v = A / 2 * (mp.cos(th + nu) + mp.cos((1 + c) * th + nu) / 2 + mp.cos((1 - c) * th + nu) / 2)
    a = -mp.pi * f * A * (mp.sin(th + nu) + (1 + c) * mp.sin((1 + c) * th + nu) / 2
                          + (1 - c) * mp.sin((1 - c) * th + nu) / 2)
    return a, v, disp(th)


KINDS = {
    "exponential": exponential,
    "half_sine": half_sine,
    "sine_cycle": sine_cycle,
    "cosine_cycle": cosine_cycle,
    "rectangular": rectangular,
    "triangular": triangular,
    "ricker": ricker,
    "mavroeidis_papageorgiou": mavroeidis_papageorgiou,
}


def evaluate(kind, t, **params):
    return KINDS[kind](t, **params)


# ---------------------------------------------------------------------------
# Self-check against numerical integration (run by hand, not part of the suite).
# ---------------------------------------------------------------------------

def _check_history(name, func, breaks, t_end, tol=mpf(10) ** -30):
    """v = int_0^t a and d = int_0^t v by mp.quad (split at the kinks); errors
    relative to max(|value|, 1e-3 * largest |value| at the checked times)."""
    ts = [mpf(t_end) * k / 7 for k in range(1, 8)] + [mpf(b) for b in breaks if b > 0]
    pts_all = sorted(set([mpf(0)] + [mpf(b) for b in breaks if 0 < b]))
    rows = []
    for t in ts:
        pts = [p for p in pts_all if p < t] + [t]
        a, v, d = func(t)
        vq = mp.quad(lambda s: func(s)[0], pts)
        dq = mp.quad(lambda s: func(s)[1], pts)
        rows.append((v, vq, d, dq))
    sv = max(abs(r[0]) for r in rows) * mpf(10) ** -3
    sd = max(abs(r[2]) for r in rows) * mpf(10) ** -3
    worst = max(max(abs(v - vq) / max(abs(v), sv), abs(d - dq) / max(abs(d), sd))
                for v, vq, d, dq in rows)
    status = "ok" if worst < tol else "FAIL"
    print(f"{status:4s} {name:45s} worst rel err {mp.nstr(worst, 3)}")
    return worst < tol


def _self_check():
    ok = True
    # published vg values
    pub = {-2 * mp.pi: "0.8427159935", -mp.pi: "0.7268558192", -1: "0.5819767069",
           1: "0.4180232931", mp.pi: "0.2731441808", 2 * mp.pi: "0.1572840065"}
    for b, s in pub.items():
        got = exp_vg(b)
        good = abs(got - mpf(s)) < 1e-10
        ok &= good
        print(f"{'ok' if good else 'FAIL':4s} vg({mp.nstr(b, 6)}) = {mp.nstr(got, 12)} (published {s})")
    # vg against the printed form where it is well conditioned
    for b in (mpf("0.3"), mpf(-5), mpf(40), mpf(-40)):
        good = abs(exp_vg(b) - (1 / (1 - mp.exp(b)) + 1 / b)) < mpf(10) ** -40
        ok &= good
    # tiny beta: compare with the printed forms evaluated at very high precision
    for b in (mpf("1e-30"), mpf("-1e-9"), mpf("1e-300"), mpf(0.7)):
        for tau in (mpf("0.2"), mpf("0.5"), mpf("0.8")):
            a, v, d = _exp_lobe(tau, b)
            with mp.workdps(700):
                bb = b
                s = min(tau, 1 - tau)
                a_ref = (1 - mp.exp(2 * bb * s)) / (1 - mp.exp(bb)) if bb else 2 * s
            good = abs(a - a_ref) <= mpf(10) ** -45 * abs(a_ref)
            ok &= good
            if not good:
                print("FAIL tiny beta a", b, tau, a, a_ref)
    # finite-difference check a = dv/dt for exp lobe; beta = 0 equals the triangle
    for tau in (mpf("0.1"), mpf("0.7"), mpf("1.3"), mpf("2.5")):
        e = exp_pulse(tau, 0, True)
        tr = triangular(tau, 1, 1, 0.5)
        tr2 = triangular(tau - 1, -1, 1, 0.5) if tau >= 1 else (0, 0, 0)
        V = mpf(1) / 2
        if 1 <= tau < 2:
            want = (tr2[0], V + tr2[1], V / 2 + V * (tau - 1) + tr2[2])
        elif tau >= 2:
            want = (0, 0, V)
        else:
            want = tr
        good = all(abs(x - y) < mpf(10) ** -40 for x, y in zip(e, want))
        ok &= good
        if not good:
            print("FAIL beta=0 vs triangle", tau, e, want)
    for beta in (-2 * mp.pi, -1, mpf("1e-12"), 0, 1, 2.5, 25, -25):
        for full in (False, True):
            ok &= _check_history(f"exp_pulse beta={mp.nstr(beta, 5)} full={full}",
                                 lambda s, b=beta, f=full: exp_pulse(s, b, f),
                                 [0.5, 1, 1.5, 2], 3)
    ok &= _check_history("exp_pulse box full", lambda s: exp_pulse(s, -mp.inf, True), [1, 2], 3)
    ok &= _check_history("exp_pulse box half", lambda s: exp_pulse(s, -mp.inf, False), [1], 3)
    ok &= _check_history("exponential SI", lambda s: exponential(s, 0.3, 0.8, 2.5, True, "g"),
                         [mpf(0.8) * k / 2 for k in range(1, 5)], 2)
    ok &= _check_history("half_sine", lambda s: half_sine(s, 2.0, 0.7), [0.7], 1.5)
    ok &= _check_history("sine_cycle", lambda s: sine_cycle(s, 2.0, 0.7), [0.35, 0.7], 1.5)
    ok &= _check_history("cosine_cycle", lambda s: cosine_cycle(s, 2.0, 0.7), [0.35, 0.7], 1.5)
    ok &= _check_history("rectangular", lambda s: rectangular(s, 2.0, 0.7), [0.7], 1.5)
    for r in (0, 0.3, 0.5, 1):
        ok &= _check_history(f"triangular r={r}", lambda s, r=r: triangular(s, 2.0, 0.7, r),
                             [mpf(0.7) * mpf(r), 0.7], 1.5)
    ok &= _check_history("ricker default t0", lambda s: ricker(s, 3.0, 1.2), [1.25], 3)
    ok &= _check_history("ricker t0 = 0.2", lambda s: ricker(s, 3.0, 1.2, 0.2), [0.2], 3)
    for gam, nu in ((1.0001, 0), (2.0, 90), (1.5, -45), (3.0, 30)):
        f = 0.8
        t0 = gam / (2 * f) + 0.1
        ok &= _check_history(f"M&P gamma={gam} nu={nu}",
                             lambda s, gam=gam, nu=nu, t0=t0: mavroeidis_papageorgiou(s, 0.9, f, gam, nu, t0),
                             [mpf(t0) + k * mpf(gam) / (2 * mpf(f)) for k in (-1, 0, 1)],
                             2 * t0 + 0.5)
        # a = dv/dt by central difference
        for t in (t0 - 0.3, t0 + 0.2):
            h = mpf(10) ** -15
            vp = mavroeidis_papageorgiou(t + h, 0.9, f, gam, nu, t0)[1]
            vm = mavroeidis_papageorgiou(t - h, 0.9, f, gam, nu, t0)[1]
            a = mavroeidis_papageorgiou(t, 0.9, f, gam, nu, t0)[0]
            good = abs((vp - vm) / (2 * h) - a) < mpf(10) ** -20
            ok &= good
            if not good:
                print("FAIL M&P a = dv/dt", gam, nu, t)
    print("ALL OK" if ok else "SOME CHECKS FAILED")
    return ok


if __name__ == "__main__":
    _self_check()
