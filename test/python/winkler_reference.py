"""Independent reference model of the planar 2-DOF rocking of a rigid cylinder (circular
base, radius r) or block (rectangular base, half-width b along the rocking direction,
half-length alpha) on tensionless Winkler springs k (N/m^3) and dashpots c (N s/m^3)
(doc/winkler.md, "Dynamics"; [KH91] circle, [KSR86] block), written with numpy and scipy
only, for the cross-checks of test/python/test_winkler_scipy.py and the peer of
bench/winkler.py. It shares no code with the library.

State y = (v, theta, v', theta'): v the settlement of the base centre (m, + down), theta
the tilt (rad; theta > 0 lifts the s > 0 side), s the coordinate along the rocking
diameter from the base centre (m), full widths 2 w(s), w = sqrt(r^2 - s^2) (circle) or
alpha (rectangle).
    penetration   delta(s) = v - s sin(theta),  rate delta'(s) = v' - s cos(theta) theta'
    pressure      q(s) = max(0, k delta + c delta') where delta > 0, else 0        (Pa)
    projected     dA = 2 w(s) cos(theta) ds
    N = int q dA (N),   M = int q s cos(theta) dA (N m, about the base centre)
Lagrange's equations with the base centre held horizontally (x_G = -h sin(theta),
z_G = -v + h cos(theta) in the ground frame, ground acceleration a_g along +x giving the
inertial force -m a_g on G; generalized forces of the vertical pressures Q_v = -N,
Q_theta = M):
    m (v'' + h sin(theta) theta'' + h cos(theta) theta'^2) = m g - N
    I_O theta'' + m h sin(theta) v'' = m g h sin(theta) + M + m a_g h cos(theta)
with I_O = I_G + m h^2. Static limit: N = W, -M = W h sin(theta) + F h cos(theta), F = m a_g.

The contact integrals are evaluated by adaptive quadrature (scipy.integrate.quad) over the
active interval, whose ends are roots (scipy.optimize.brentq) of delta and of
k delta + c delta' on [-r, r]; for the circle the integrals are taken in the angle
u = acos(s/r), where the integrand is smooth up to the edges. solve_ivp (Radau or BDF)
integrates from one contact change to the next: terminal events where delta or
k delta + c delta' changes sign at an edge, or where the two roots meet (the ends of the
active interval, hence the smoothness of N and M, change there); every ground-motion
breakpoint (end of a pulse, record samples) also starts a new segment.
"""
import math
from dataclasses import dataclass
from typing import Callable, Optional

import numpy as np
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq

G_STD = 9.80665    # m/s^2

OUTCOME_SAFE, OUTCOME_NO_IMPACT, OUTCOME_ONE_IMPACT, OUTCOME_IMPACTS = 0, 1, 2, 3


# ---------------------------------------------------------------------------- bodies

@dataclass(frozen=True)
class Body:
    """A rigid body on its base: mass (kg), h the height of the centre of mass above the base
    (m), j_g the moment of inertia about G normal to the rocking plane (kg m^2), footing
    'circle' (r the radius) or 'rectangle' (r the half-width b, alpha the half-length), g
    (m/s^2)."""
    mass: float
    h: float
    j_g: float
    footing: str
    r: float
    alpha: float = 0.0
    g: float = G_STD

    @property
    def weight(self):
        return self.mass * self.g

    @property
    def i_o(self):
        """I_O = I_G + m h^2 (kg m^2), about the base centre."""
        return self.j_g + self.mass * self.h ** 2

    @property
    def area(self):
        """Full base area (m^2)."""
        return math.pi * self.r ** 2 if self.footing == "circle" else 4 * self.r * self.alpha

    @property
    def inertia(self):
        """Second moment of the base about the axis normal to the rocking plane (m^4)."""
        if self.footing == "circle":
            return math.pi * self.r ** 4 / 4
        return 4 * self.alpha * self.r ** 3 / 3

    @property
    def theta_c(self):
        """Rigid overturning angle atan(r/h) (rad)."""
        return math.atan2(self.r, self.h)

    @property
    def p(self):
        """Rigid frequency parameter sqrt(m g R/J_o), J_o about the edge (rad/s)."""
        big_r = math.hypot(self.r, self.h)
        return math.sqrt(self.mass * self.g * big_r / (self.j_g + self.mass * big_r ** 2))


def solid_cylinder(r, h, rho=None, mass=None, g=G_STD):
    """Solid cylinder of radius r, half-height h (m): mass from rho (kg/m^3) or given;
    I_G = m (3 r^2 + 4 h^2)/12."""
    m = mass if mass is not None else rho * math.pi * r * r * 2 * h
    return Body(m, h, m * (3 * r * r + 4 * h * h) / 12, "circle", r, 0.0, g)


def solid_block(b, alpha, h, rho=None, mass=None, g=G_STD):
    """Solid block, half-width b (rocking direction), half-length alpha, half-height h (m):
    I_G = m (4 b^2 + 4 h^2)/12."""
    m = mass if mass is not None else rho * 8 * b * alpha * h
    return Body(m, h, m * (b * b + h * h) / 3, "rectangle", b, alpha, g)


def modulus_circle(g_mod, nu, r):
    """k = K_R/I = 32 G/(3 pi (1 - nu) r) (N/m^3), K_R = 8 G r^3/(3 (1 - nu)) ([G91])."""
    return 32 * g_mod / (3 * math.pi * (1 - nu) * r)


def damping_rocking(body, k, xi):
    """c = 2 xi I_O omega_r/I, omega_r^2 = (k I - m g h)/I_O (N s/m^3)."""
    omega = math.sqrt((k * body.inertia - body.mass * body.g * body.h) / body.i_o)
    return 2 * xi * body.i_o * omega / body.inertia


def damping_vertical(body, k, xi):
    """c = 2 xi sqrt(k m/A) (N s/m^3)."""
    return 2 * xi * math.sqrt(k * body.mass / body.area)


# ------------------------------------------------------------- contact by quadrature

def _positive_part(f, r):
    """The sub-interval of [-r, r] where the linear function f > 0, its end a root found
    by brentq; None when empty."""
    fa, fb = f(-r), f(r)
    if fa > 0 and fb > 0:
        return -r, r
    if fa <= 0 and fb <= 0:
        return None
    root = brentq(f, -r, r, xtol=1e-17 * r, rtol=1e-15, maxiter=200)
    return (-r, root) if fa > 0 else (root, r)


def active_interval(body, k, c, y):
    """(s_lo, s_hi) where delta > 0 and k delta + c delta' > 0 (m), or None."""
    v, th, vd, thd = y
    sn, cs = math.sin(th), math.cos(th)
    a = _positive_part(lambda s: v - s * sn, body.r)
    if a is None:
        return None
    b = _positive_part(lambda s: k * (v - s * sn) + c * (vd - s * cs * thd), body.r)
    if b is None:
        return None
    lo, hi = max(a[0], b[0]), min(a[1], b[1])
    return (lo, hi) if hi > lo else None


def contact_quad(body, k, c, y):
    """(N, M, contact width (m)) by adaptive quadrature over the active interval."""
    ends = active_interval(body, k, c, y)
    if ends is None:
        return 0.0, 0.0, 0.0
    v, th, vd, thd = y
    sn, cs = math.sin(th), math.cos(th)
    q = lambda s: k * (v - s * sn) + c * (vd - s * cs * thd)
    lo, hi = ends
    r = body.r
    if body.footing == "circle":
        # s = r cos(u), ds = -r sin(u) du, 2 w ds -> 2 r^2 sin^2(u) du, u from acos(hi/r)
        u_hi, u_lo = math.acos(min(1.0, max(-1.0, lo / r))), math.acos(min(1.0, max(-1.0, hi / r)))
        f0 = lambda u: q(r * math.cos(u)) * 2 * r * r * math.sin(u) ** 2
        f1 = lambda u: q(r * math.cos(u)) * r * math.cos(u) * 2 * r * r * math.sin(u) ** 2
        a, b = u_lo, u_hi
    else:
        f0 = lambda s: q(s) * 2 * body.alpha
        f1 = lambda s: q(s) * s * 2 * body.alpha
        a, b = lo, hi
    # absolute floor: 1e-14 of the integral of |q| bounds over the whole base
    q_bound = abs(k * v) + abs(c * vd) + r * (abs(k * sn) + abs(c * cs * thd))
    area = body.area
    n0 = quad(f0, a, b, epsabs=1e-14 * q_bound * area, epsrel=1e-13, limit=100)[0]
    n1 = quad(f1, a, b, epsabs=1e-14 * q_bound * area * r, epsrel=1e-13, limit=100)[0]
    return n0 * cs, n1 * cs * cs, hi - lo


# ------------------------------------------------------------------------ dynamics

def accelerations(body, normal, moment, a_g, y):
    """(v'', theta'') from the two equations of motion (a 2 x 2 solve)."""
    m, h, g = body.mass, body.h, body.g
    _, th, _, thd = y
    sn, cs = math.sin(th), math.cos(th)
    f1 = m * g - normal - m * h * cs * thd * thd
    f2 = m * g * h * sn + moment + m * a_g * h * cs
    a11, a12, a22 = m, m * h * sn, body.i_o
    det = a11 * a22 - a12 * a12
    return (a22 * f1 - a12 * f2) / det, (a11 * f2 - a12 * f1) / det


def _edge_functions(body, k, c):
    """The functions whose sign changes are contact changes (named for the restarts)."""
    r = body.r

    def delta_hi(t, y):          # delta at s = +r
        return y[0] - r * math.sin(y[1])

    def delta_lo(t, y):          # delta at s = -r
        return y[0] + r * math.sin(y[1])

    def q_hi(t, y):              # k delta + c delta' at s = +r
        return k * (y[0] - r * math.sin(y[1])) + c * (y[2] - r * math.cos(y[1]) * y[3])

    def q_lo(t, y):              # k delta + c delta' at s = -r
        return k * (y[0] + r * math.sin(y[1])) + c * (y[2] + r * math.cos(y[1]) * y[3])

    def roots_meet(t, y):
        # delta' at the root of delta (times sin theta): the end of the active interval
        # switches there between the root of delta and that of k delta + c delta'
        return y[2] * math.sin(y[1]) - y[0] * math.cos(y[1]) * y[3]

    return delta_hi, delta_lo, q_hi, q_lo, roots_meet


def _armed(body, k, c, y, funcs):
    """The contact functions that can change the active interval from state y: delta at
    both edges always; k delta + c delta' at an edge (c > 0) where delta > 0 there; the
    meeting of the roots (c > 0) while the root of delta is inside the base."""
    delta_hi, delta_lo, q_hi, q_lo, roots_meet = funcs
    armed = [delta_hi, delta_lo]
    if c > 0:
        if delta_hi(0.0, y) > 0:
            armed.append(q_hi)
        if delta_lo(0.0, y) > 0:
            armed.append(q_lo)
        if abs(y[0]) < body.r * abs(math.sin(y[1])):
            armed.append(roots_meet)
    return armed


@dataclass
class Run:
    """A run of simulate: histories on t (s) and the events."""
    t: np.ndarray
    v: np.ndarray
    theta: np.ndarray
    v_rate: np.ndarray
    theta_rate: np.ndarray
    normal: np.ndarray
    moment: np.ndarray
    width: np.ndarray
    work: np.ndarray            # work of the contact forces and the ground inertia (J)
    outcome: int
    n_impacts: int
    t_impacts: np.ndarray
    t_uplift: float
    t_lift_off: float
    t_overturn: float
    t_touch_down: float         # first contact after a flight (s)
    theta_max: float
    t_end: float
    n_segments: int
    nfev: int

    def energy(self, body):
        """Kinetic + gravity potential (J, G at h above the base centre at v = 0)."""
        m, h = body.mass, body.h
        sn, cs = np.sin(self.theta), np.cos(self.theta)
        kin = 0.5 * m * self.v_rate ** 2 + m * h * sn * self.v_rate * self.theta_rate \
            + 0.5 * body.i_o * self.theta_rate ** 2
        return kin + m * body.g * (h * cs - self.v)


def sine_pulse(a_p, period, cycles=1):
    """a_g = a_p sin(2 pi t/T_p) on [0, cycles T_p], else 0 (m/s^2): (callable, breakpoints)."""
    end = cycles * period

    def accel(t):
        return a_p * math.sin(2 * math.pi * t / period) if 0.0 <= t <= end else 0.0
    return accel, [end]


def record_accel(acc_g, dt, g=G_STD):
    """A record in g sampled at dt (s) from t = 0, linear between samples and 0 after the
    last one (m/s^2): (callable, breakpoints)."""
    acc = np.asarray(acc_g, dtype=float) * g
    n = acc.size
    end = (n - 1) * dt

    def accel(t):
        if t < 0.0 or t > end:
            return 0.0
        i = min(int(t / dt), n - 2)
        x = (t - i * dt) / dt
        return float(acc[i] * (1 - x) + acc[i + 1] * x)
    return accel, [i * dt for i in range(1, n)]


def default_atol(body, k, rtol):
    """Absolute tolerances of (v, theta, v', theta', work) for rtol: 1e-2 rtol times the
    scales W/(k A) (m), W r/(k I) (rad), those times sqrt(k A/m) (rates) and W^2/(k A) (J)."""
    v_s = body.weight / (k * body.area)
    th_s = body.weight * body.r / (k * body.inertia)
    om = math.sqrt(k * body.area / body.mass)
    return 1e-2 * rtol * np.array([v_s, th_s, v_s * om, th_s * om, body.weight * v_s])


def simulate(body, k, c, accel, t, breakpoints=(), v0=None, theta0=0.0, v_rate0=0.0,
             theta_rate0=0.0, t_max=None, method="Radau", rtol=1e-10, atol=None,
             theta_fall=math.pi / 2, contact: Optional[Callable] = None, max_step=np.inf,
             max_segments=100000):
    """Run the model on [0, t_max] (default t[-1]) and sample it on the grid t (s).

    accel: a_g(t) (m/s^2) with the times `breakpoints` where it is not smooth. v0 default
    the static settlement W/(k A). contact(body, k, c, y) -> (N, M, width), default
    contact_quad. Overturning: |theta| reaches theta_fall (rad). t_uplift: start of the
    first segment whose active interval does not cover the base; t_lift_off: of the first
    with no contact; impacts: sign changes of theta after t_uplift."""
    contact = contact or contact_quad
    t = np.asarray(t, dtype=float)
    t_max = t[-1] if t_max is None else t_max
    if v0 is None:
        v0 = body.weight / (k * body.area)
    if atol is None:
        atol = default_atol(body, k, rtol)
    m, h = body.mass, body.h
    nfev = [0]

    def rhs(tt, y):
        nfev[0] += 1
        normal, moment, _ = contact(body, k, c, y[:4])
        a_g = accel(tt)
        vdd, thdd = accelerations(body, normal, moment, a_g, y[:4])
        power = -normal * y[2] + moment * y[3] + m * a_g * h * math.cos(y[1]) * y[3]
        return [y[2], y[3], vdd, thdd, power]

    funcs = _edge_functions(body, k, c)

    def fall(tt, y):
        return abs(y[1]) - theta_fall
    fall.terminal = True

    def zero(tt, y):
        return y[1]
    zero.terminal = False

    stops = sorted({b for b in breakpoints if 0.0 < b < t_max} | {t_max})
    y = np.array([v0, theta0, v_rate0, theta_rate0, 0.0])
    t0 = 0.0
    out = np.full((5, t.size), np.nan)
    t_impacts = []
    t_uplift = t_lift_off = t_overturn = t_touch_down = math.nan
    back, skip = {}, set()
    n_seg = 0
    theta_max = abs(theta0)
    was_touching = active_interval(body, k, c, y[:4]) is not None
    while t0 < t_max:
        n_seg += 1
        if n_seg > max_segments:
            raise RuntimeError(f"more than {max_segments} segments by t = {t0}")
        t_stop = next(s for s in stops if s > t0)
        armed = [f for f in _armed(body, k, c, y, funcs) if f.__name__ not in skip]
        evs = []
        for f in armed:
            ev = (lambda fn: (lambda tt, yy: fn(tt, yy)))(f)
            ev.terminal, ev.direction = True, back.get(f.__name__, 0.0)
            evs.append(ev)
        # sign changes of theta count from the uplift on (theta may be 0 identically before)
        tail = [fall] if math.isnan(t_uplift) else [fall, zero]
        sol = solve_ivp(rhs, (t0, t_stop), y, method=method, rtol=rtol, atol=atol,
                        events=evs + tail, dense_output=True, max_step=max_step)
        if sol.status < 0:
            raise RuntimeError(f"solve_ivp: {sol.message} at t = {sol.t[-1]}")
        t1 = sol.t[-1]
        sel = (t >= t0) & (t <= t1)
        if np.any(sel):
            out[:, sel] = sol.sol(t[sel])
        theta_max = max(theta_max, float(np.max(np.abs(sol.y[1]))))
        y_start = y
        if t1 > t0:
            back, skip = {}, set()
            mid = sol.sol(0.5 * (t0 + t1))
            ends = active_interval(body, k, c, mid[:4])
            full = ends is not None and ends[1] - ends[0] >= 2 * body.r * (1 - 1e-12)
            if math.isnan(t_uplift) and not full and ends is not None:
                t_uplift = t0
            if math.isnan(t_lift_off) and ends is None:
                t_lift_off = t0
            if math.isnan(t_touch_down) and not was_touching and ends is not None:
                t_touch_down = t0
            was_touching = ends is not None
        if len(tail) == 2:
            t_impacts += [float(tz) for tz in sol.t_events[-1] if t0 < tz]
        y = sol.y[:, -1].copy()
        if sol.status == 1:
            if sol.t_events[len(evs)].size:
                t_overturn = float(sol.t_events[len(evs)][0])
                theta_max = max(theta_max, theta_fall)
                t0 = t1
                break
            for f, te in zip(armed, sol.t_events):
                if te.size:
                    # the next segment starts on this zero: armed for the crossing back only
                    # (an event at the restart itself: the sign it starts from)
                    before = sol.sol(0.5 * (t0 + t1)) if t1 > t0 else y_start
                    g_before = f(t0, before)
                    if g_before == 0.0:
                        skip.add(f.__name__)
                    else:
                        back[f.__name__] = 1.0 if g_before > 0 else -1.0
        t0 = t1
    normal = np.full(t.size, np.nan)
    moment = np.full(t.size, np.nan)
    width = np.full(t.size, np.nan)
    for j in range(t.size):
        if np.isfinite(out[0, j]):
            normal[j], moment[j], width[j] = contact(body, k, c, out[:4, j])
    n_imp = len(t_impacts)
    outcome = OUTCOME_SAFE if math.isnan(t_overturn) else min(1 + n_imp, OUTCOME_IMPACTS)
    return Run(t, out[0], out[1], out[2], out[3], normal, moment, width, out[4], outcome,
               n_imp, np.array(t_impacts), t_uplift, t_lift_off, t_overturn, t_touch_down,
               theta_max, t0, n_seg, nfev[0])


# -------------------------------------------------------------- static closed forms

def circle_pushover_uplift(r, h, weight, k, b):
    """Constant-k circle after uplift at contact width b in (0, 2 r] (m), closed forms
    ([AD11] section 2.2; doc/winkler.md statics): (theta (rad), F (N)) with
    theta = asin(2 W/(k Phi))/2, Phi = 2/3 S^3 + c^2 S - r^2 c acos(c/r), S =
    sqrt(2 r b - b^2), c = r - b, and M = k sin(theta) cos^2(theta) (J2 - c J1),
    F = (M - W h sin(theta))/(h cos(theta)); NaN where 2 W/(k Phi) > 1."""
    b = np.asarray(b, dtype=float)
    cc = r - b
    s = np.sqrt(np.maximum(2 * r * b - b * b, 0.0))
    phi = 2.0 / 3.0 * s ** 3 + cc * cc * s - r * r * cc * np.arccos(cc / r)
    with np.errstate(invalid="ignore", divide="ignore"):
        theta = 0.5 * np.arcsin(2 * weight / (k * phi))
    j1 = 2.0 / 3.0 * s ** 3
    j2 = r ** 4 / 4 * (math.pi / 2 - np.arcsin(cc / r)) - cc / 4 * (2 * cc * cc - r * r) * s
    mom = k * np.sin(theta) * np.cos(theta) ** 2 * (j2 - cc * j1)
    force = (mom - weight * h * np.sin(theta)) / (h * np.cos(theta))
    return theta, force


def circle_pushover_full(r, h, weight, k, theta):
    """Before uplift: F = pi k r^4 sin(2 theta)/(8 h) - W tan(theta) (N)."""
    return math.pi * k * r ** 4 * np.sin(2 * theta) / (8 * h) - weight * np.tan(theta)


def circle_static_theta(r, h, weight, k, force, n=20001):
    """theta (rad) of the rising branch of the constant-k circle's pushover at the
    horizontal force F (N, |F| below the peak), by interpolation on a fine parametric curve
    (b from 2 r down to the peak) built from the closed forms."""
    theta_up = 0.5 * math.asin(2 * weight / (k * math.pi * r ** 3))
    th_full = np.linspace(0.0, theta_up, n)
    f_full = circle_pushover_full(r, h, weight, k, th_full)
    b = np.linspace(2 * r, 1e-3 * r, 4 * n)
    th_up, f_up = circle_pushover_uplift(r, h, weight, k, b)
    ok = np.isfinite(th_up)
    th_up, f_up = th_up[ok], f_up[ok]
    peak = int(np.argmax(f_up))
    th_all = np.concatenate([th_full, th_up[1:peak + 1]])
    f_all = np.concatenate([f_full, f_up[1:peak + 1]])
    force = np.asarray(force, dtype=float)
    return np.sign(force) * np.interp(np.abs(force), f_all, th_all, right=np.nan)
