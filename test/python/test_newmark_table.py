"""seispulse.newmark.rigid with a yield table (ky_table): the exact rule against an
independent integration written here (scipy solve_ivp, DOP853 at rtol 1e-12, with the
stop and the table's breakpoints as events), SLAMMER RigidBlock's rule written out here
for method='slammer', a one-row table equal to the constant yield bit for bit, and the
errors."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from seispulse import InvalidInputError, newmark

G = 9.80665
DT = 0.005


def record(n=1600, seed=1):
    """A deterministic strong-motion-like record (g)."""
    t = np.arange(n) * DT
    env = (t / 2.5) ** 2 * np.exp(2.0 - 2.0 * t / 2.5)
    a = sum(amp * np.sin(2 * np.pi * f * t + 0.41 * k * seed)
            for k, (f, amp) in enumerate(zip([0.9, 2.1, 3.7, 6.3], [0.15, 0.22, 0.12, 0.06]), 1))
    return 1.5 * env * a


def reference(a, disp, kyv):
    """Rigid block with ky(u) interpolated in the table: at rest the onset is where the
    linear a(t) crosses ky(u); sliding is integrated by solve_ivp (DOP853, rtol 1e-12) with
    the stop (u' = 0) and the next breakpoint (u = disp[i]) as terminal events."""
    def ky(u):
        return np.interp(u, disp, kyv)

    def acc(t):
        i = min(int(t / DT), a.size - 2)
        if t >= (a.size - 1) * DT:
            return 0.0
        r = t / DT - i
        return a[i] + (a[i + 1] - a[i]) * r

    u, w, sliding = 0.0, 0.0, a[0] > ky(0.0)
    hist = [0.0]
    t = 0.0
    i = 0
    while i < a.size - 1 or sliding:
        t_end = (i + 1) * DT
        a0 = acc(i * DT) if i < a.size - 1 else 0.0
        a1 = a[i + 1] if i < a.size - 1 else 0.0
        while t < t_end - 1e-15:
            if not sliding:
                k = ky(u)
                a_t = a0 + (a1 - a0) * (t - i * DT) / DT
                if a_t > k:
                    sliding = True
                    continue
                if a1 > k and a1 > a_t:
                    t = t + (t_end - t) * (k - a_t) / (a1 - a_t)
                    sliding = True
                    continue
                t = t_end
                continue
            nxt = disp[disp > u + 1e-15]
            events = []

            def stop(tt, y):
                return y[1]
            stop.terminal, stop.direction = True, -1
            events.append(stop)
            if nxt.size:
                def brk(tt, y, d=nxt[0]):
                    return y[0] - d
                brk.terminal, brk.direction = True, 1
                events.append(brk)
            sol = solve_ivp(lambda tt, y: [y[1], G * (acc(tt) - ky(y[0]))], (t, t_end), [u, w],
                            method="DOP853", rtol=1e-12, atol=1e-15, events=events)
            u, w = sol.y[0, -1], sol.y[1, -1]
            t = sol.t[-1]
            if sol.status == 1:
                if sol.t_events[0].size:
                    w, sliding = 0.0, False
                else:
                    u = nxt[0]
        if i < a.size - 1:
            hist.append(u)
        i += 1
    return np.array(hist), u


TABLE = (np.array([0.0, 0.02, 0.1]), np.array([0.15, 0.06, 0.11]))


def test_exact_table_equals_independent_integration():
    a = record()
    r = newmark.rigid(a, DT, ky_table=TABLE, history=True)
    hist, u_end = reference(a, *TABLE)
    assert r.final_disp > 0.1
    assert r.final_disp == pytest.approx(u_end, rel=1e-10)
    assert np.max(np.abs(r.disp - hist)) <= 1e-10 * u_end


def test_slammer_table_is_rigidblock_rule():
    """SLAMMER RigidBlock.SlammerRigorous (one way, cm): the yield is updated after each
    step from the table at u."""
    a = record(seed=2)
    r = newmark.rigid(a, DT, ky_table=TABLE, method="slammer", history=True)
    gcm = 100 * G
    dcm, kv = 100 * TABLE[0], TABLE[1]
    t = kv[0] * gcm
    q = rr = s = u = v = 0.0
    pos = 0
    out = []
    for x in a:
        aa = x * gcm
        if abs(v) < 1e-15:
            n = np.sign(aa) if abs(aa) > t else aa / t
        else:
            n = np.sign(v)
        y = aa - n * t
        v = rr + DT / 2 * (y + s)
        if v <= 0:
            v = y = 0.0
        u = q + DT / 2 * (v + rr)
        q, rr, s = u, v, y
        out.append(u / 100)
        if pos == len(dcm) - 1:
            continue
        while u > dcm[pos + 1]:
            pos += 1
            if pos == len(dcm) - 1:
                break
        if pos == len(dcm) - 1:
            t = gcm * kv[pos]
        else:
            prop = (u - dcm[pos]) / (dcm[pos + 1] - dcm[pos])
            t = gcm * (kv[pos] - (kv[pos] - kv[pos + 1]) * prop)
    out = np.array(out)
    assert out[-1] > 0.05
    assert np.max(np.abs(r.disp - out)) <= 1e-15 * out[-1]


@pytest.mark.parametrize("method", ["exact", "slammer"])
def test_one_row_is_constant_ky(method):
    a = record(seed=3)
    r1 = newmark.rigid(a, DT, 0.12, method=method, history=True, intervals=True)
    r2 = newmark.rigid(a, DT, ky_table=([0.0], [0.12]), method=method, history=True,
                       intervals=True)
    assert r1.final_disp > 0.01
    assert r1[:6] == r2[:6]
    assert np.array_equal(r1.disp, r2.disp) and np.array_equal(r1.vel, r2.vel)
    assert r1.slides == r2.slides


def test_table_errors():
    a = record()
    with pytest.raises(InvalidInputError, match="ky_table"):
        newmark.rigid(a, DT, 0.1, ky_table=TABLE)
    with pytest.raises(InvalidInputError, match="mode"):
        newmark.rigid(a, DT, ky_table=TABLE, mode="both")
    with pytest.raises(InvalidInputError, match=r"ky_table\[0\]\[0\]"):
        newmark.rigid(a, DT, ky_table=([0.01, 0.02], [0.1, 0.1]))
    with pytest.raises(InvalidInputError, match=r"ky_table\[1\]\[1\]"):
        newmark.rigid(a, DT, ky_table=([0.0, 0.02], [0.1, 0.0]))
    with pytest.raises(InvalidInputError, match="ky_table"):
        newmark.rigid(a, DT, ky_table=([0.0, 0.02], [0.1]))
