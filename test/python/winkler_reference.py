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
import warnings
from dataclasses import dataclass
from typing import Callable, Optional

import numpy as np
from scipy.integrate import IntegrationWarning, quad, solve_ivp
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


def _gazetas_k_over_i(width, length):
    """K_R/I of a rectangle width x length (width along the rocking direction, rotation
    about the axis parallel to length) by [G91] over G/(1 - nu), I = length width^3/12,
    B <= L the half-sides: K_rx = I^0.75 (L/B)^0.25 (2.4 + 0.5 B/L) when length >= width
    (the long axis), else K_ry = 3 I^0.75 (L/B)^0.15 (1/m^3 times G/(1 - nu))."""
    i = length * width ** 3 / 12
    if length >= width:
        big_b, big_l = width / 2, length / 2
        return i ** 0.75 * (big_l / big_b) ** 0.25 * (2.4 + 0.5 * big_b / big_l) / i
    big_b, big_l = length / 2, width / 2
    return 3 * i ** 0.75 * (big_l / big_b) ** 0.15 / i


def varying_k(body, k, b):
    """The varying-k modulus (N/m^3) at the geometric contact width b (m) from the
    full-contact k: k times (K_R/I) of the equivalent rectangle over that of full contact
    ([G91] for both). Circle: rectangle b x L, L = 2 sqrt(r^2 - a^2) the chord through the
    pole a, the centroid of the contact segment (by quadrature here), full contact the
    square 2 r x 2 r (reading K_rx: b <= L); rectangle: b x 2 alpha over 2 b x 2 alpha."""
    r = body.r
    if b >= 2 * r:
        return k
    if body.footing == "circle":
        # segment from the edge s = r - b to r (by symmetry), in u = acos(s/r)
        u_b = math.acos(max(-1.0, min(1.0, (r - b) / r)))
        # in x = u/u_b on [0, 1]: smooth integrands of one scale; quad's roundoff warning
        # at epsrel 1e-13 on a slice (u_b << 1) is a false alarm (the integrand is a
        # polynomial in x to rounding): checked against the library's closed forms
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", IntegrationWarning)
            a0 = u_b * quad(lambda x: 2 * r * r * math.sin(u_b * x) ** 2, 0.0, 1.0,
                            epsabs=0.0, epsrel=1e-13)[0]
            j1 = u_b * quad(lambda x: 2 * r ** 3 * math.cos(u_b * x)
                            * math.sin(u_b * x) ** 2, 0.0, 1.0, epsabs=0.0, epsrel=1e-13)[0]
        pole = j1 / a0
        chord = 2 * math.sqrt(max(r * r - pole * pole, 0.0))
        return k * _gazetas_k_over_i(b, chord) / _gazetas_k_over_i(2 * r, 2 * r)
    return k * _gazetas_k_over_i(b, 2 * body.alpha) / _gazetas_k_over_i(2 * r, 2 * body.alpha)


def geometric_width(body, y):
    """Width of {delta > 0} on the base (m)."""
    a = _positive_part(lambda s: y[0] - s * math.sin(y[1]), body.r)
    return 0.0 if a is None else a[1] - a[0]


def contact_quad(body, k, c, y, varying=False):
    """(N, M, contact width (m)) by adaptive quadrature over the active interval; with
    varying, k is varying_k of the geometric contact width."""
    if varying:
        b = geometric_width(body, y)
        if b <= 0.0:
            return 0.0, 0.0, 0.0
        k = varying_k(body, k, b)
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
        u_hi = math.acos(min(1.0, max(-1.0, lo / r)))
        u_lo = math.acos(min(1.0, max(-1.0, hi / r)))
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


def spring_energy(body, k, v, theta):
    """U = cos(theta) (k/2) int delta^2 2 w ds over delta > 0 (J), by quadrature."""
    sn, cs = math.sin(theta), math.cos(theta)
    a = _positive_part(lambda s: v - s * sn, body.r)
    if a is None:
        return 0.0
    r = body.r
    if body.footing == "circle":
        f = lambda u: (v - r * math.cos(u) * sn) ** 2 * 2 * r * r * math.sin(u) ** 2
        lo, hi = math.acos(min(1.0, max(-1.0, a[1] / r))), math.acos(min(1.0, max(-1.0, a[0] / r)))
    else:
        f = lambda s: (v - s * sn) ** 2 * 2 * body.alpha
        lo, hi = a
    scale = (abs(v) + r * abs(sn)) ** 2 * body.area
    return 0.5 * k * cs * quad(f, lo, hi, epsabs=1e-15 * scale, epsrel=1e-13, limit=100)[0]


def rest_energy(body, k, theta):
    """U_min(theta) = min over v of V_g + U (J): at N(v) = W (brentq on the proven bracket
    [-r |sin|, r |sin| + W/(k A cos)]), constant k."""
    sn, cs = math.sin(theta), math.cos(theta)
    lo = -body.r * abs(sn)
    hi = body.r * abs(sn) + body.weight / (k * body.area * cs)
    v = brentq(lambda x: contact_quad(body, k, 0.0, (x, theta, 0.0, 0.0))[0] - body.weight,
               lo, hi, xtol=1e-15 * hi, rtol=1e-15)
    return body.weight * (body.h * cs - v) + spring_energy(body, k, v, theta)


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


def _edge_functions(body, k_of, c):
    """The functions whose sign changes are contact changes (named for the restarts);
    k_of(y) the modulus (N/m^3) at the state."""
    r = body.r

    def delta_hi(t, y):          # delta at s = +r
        return y[0] - r * math.sin(y[1])

    def delta_lo(t, y):          # delta at s = -r
        return y[0] + r * math.sin(y[1])

    def q_hi(t, y):              # k delta + c delta' at s = +r
        return k_of(y) * (y[0] - r * math.sin(y[1])) + c * (y[2] - r * math.cos(y[1]) * y[3])

    def q_lo(t, y):              # k delta + c delta' at s = -r
        return k_of(y) * (y[0] + r * math.sin(y[1])) + c * (y[2] + r * math.cos(y[1]) * y[3])

    def roots_meet(t, y):
        # delta' at the root of delta (times sin theta): the end of the active interval
        # switches there between the root of delta and that of k delta + c delta'
        return y[2] * math.sin(y[1]) - y[0] * math.cos(y[1]) * y[3]

    return delta_hi, delta_lo, q_hi, q_lo, roots_meet


def _armed(body, c, y, funcs):
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


OUTCOME_TIME_LIMIT = 4


@dataclass
class Run:
    """A run of simulate: histories on t (s) and the events (the library's definitions,
    doc/winkler.md section 9.4)."""
    t: np.ndarray
    v: np.ndarray
    theta: np.ndarray
    v_rate: np.ndarray
    theta_rate: np.ndarray
    normal: np.ndarray
    moment: np.ndarray
    width: np.ndarray           # of the active interval (pressure > 0) (m)
    work: np.ndarray            # work of the contact forces and the ground inertia (J)
    outcome: int                # OUTCOME_*
    n_impacts: int
    t_impacts: np.ndarray
    t_uplift: float             # first loss of contact of an edge (delta < 0) (s)
    t_lift_off: float           # first loss of contact of both edges (s)
    t_touch_down: float         # first contact of an edge after both were out (s)
    t_overturn: float           # last outward crossing of theta_overturn, or of theta_fall
    t_safe: float               # time of the energy proof (s)
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
             theta_fall=math.pi / 2, theta_overturn=None, t_exc=None, varying=False,
             prove_safe=False, stop_when_safe=False, contact: Optional[Callable] = None,
             max_step=np.inf, max_segments=100000):
    """Run the model on [0, t_max] (default t[-1]) and sample it on the grid t (s).

    accel: a_g(t) (m/s^2) with the times `breakpoints` where it is not smooth; t_exc the
    end of the excitation (default the last breakpoint). v0 default the static settlement
    W/(k A). varying: k of varying_k at the geometric contact width. contact(body, k, c, y,
    varying) -> (N, M, width), default contact_quad.

    Events as the library defines them (doc/winkler.md section 9.4): t_uplift the first
    edge leaving the soil (delta(+-r) < 0), t_lift_off both, t_touch_down an edge back
    after both were out; an impact is a sign change of theta with an edge lifted since
    the previous one (|theta'| > 1e-12 rad/s there). Overturning: |theta| reaches
    theta_fall (pi/2), or after t_exc |theta| is beyond theta_overturn and moving away
    (its outward crossing, or at t_exc).
    prove_safe (constant k): after t_exc, every segment end and every 0.25/p s, the run is
    proved safe when E - U_min(0) < U_min(theta_overturn) - U_min(0) with |theta| <
    theta_overturn (E = T + V_g + U); stop_when_safe ends it there (a map cell).
    Outcome: 1 + min(impacts, 2) if overturned, else 0 if proved safe, else 4."""
    contact = contact or contact_quad
    t = np.asarray(t, dtype=float)
    t_max = t[-1] if t_max is None else t_max
    if v0 is None:
        v0 = body.weight / (k * body.area)
    if atol is None:
        atol = default_atol(body, k, rtol)
    if t_exc is None:
        t_exc = max(breakpoints) if len(breakpoints) else 0.0
    m, h = body.mass, body.h
    nfev = [0]

    def k_of(y):
        if not varying:
            return k
        b = geometric_width(body, y)
        return varying_k(body, k, b) if b > 0.0 else k

    def rhs(tt, y):
        nfev[0] += 1
        normal, moment, _ = contact(body, k, c, y[:4], varying)
        a_g = accel(tt)
        vdd, thdd = accelerations(body, normal, moment, a_g, y[:4])
        power = -normal * y[2] + moment * y[3] + m * a_g * h * math.cos(y[1]) * y[3]
        return [y[2], y[3], vdd, thdd, power]

    funcs = _edge_functions(body, k_of, c)
    delta_names = ("delta_hi", "delta_lo")

    def fall(tt, y):
        return abs(y[1]) - theta_fall
    fall.terminal = True

    def zero(tt, y):
        return y[1]
    zero.terminal = False

    def turn(tt, y):             # theta' = 0: the extremes of theta, for theta_max
        return y[3]
    turn.terminal = False

    th_ot = theta_overturn if theta_overturn is not None else theta_fall

    def beyond(tt, y):
        return abs(y[1]) - th_ot

    if prove_safe:
        u0 = rest_energy(body, k, 0.0)
        barrier = rest_energy(body, k, th_ot) - u0
    stops = {b for b in breakpoints if 0.0 < b < t_max} | {t_max}
    if 0.0 < t_exc < t_max:
        stops.add(t_exc)
    if prove_safe:
        chunk = 0.25 / body.p
        stops |= set(np.arange(t_exc + chunk, t_max, chunk).tolist())
    stops = sorted(stops)
    y = np.array([v0, theta0, v_rate0, theta_rate0, 0.0])
    t0 = 0.0
    out = np.full((5, t.size), np.nan)
    t_impacts = []
    t_uplift = t_lift_off = t_overturn = t_touch_down = t_safe = t_out_cross = math.nan
    sides = {"delta_hi": funcs[0](0.0, y) > 0, "delta_lo": funcs[1](0.0, y) > 0}
    lifted = not (sides["delta_hi"] and sides["delta_lo"])
    if lifted:
        t_uplift = 0.0
        if not (sides["delta_hi"] or sides["delta_lo"]):
            t_lift_off = 0.0
    back, skip = {}, set()
    n_seg = 0
    theta_max = abs(theta0)
    overturned = False
    while t0 < t_max and not overturned:
        n_seg += 1
        if n_seg > max_segments:
            raise RuntimeError(f"more than {max_segments} segments by t = {t0}")
        t_stop = next(s for s in stops if s > t0)
        free = t0 >= t_exc
        armed = [f for f in _armed(body, c, y, funcs) if f.__name__ not in skip]
        evs = []
        for f in armed:
            ev = (lambda fn: (lambda tt, yy: fn(tt, yy)))(f)
            ev.terminal, ev.direction = True, back.get(f.__name__, 0.0)
            evs.append(ev)
        out_ev = (lambda tt, yy: beyond(tt, yy))
        out_ev.terminal, out_ev.direction = free, 1.0
        if "beyond" in skip:
            out_ev.direction = -1.0
        sol = solve_ivp(rhs, (t0, t_stop), y, method=method, rtol=rtol, atol=atol,
                        events=evs + [fall, out_ev, zero, turn], dense_output=True,
                        max_step=max_step)
        if sol.status < 0:
            raise RuntimeError(f"solve_ivp: {sol.message} at t = {sol.t[-1]}")
        t1 = sol.t[-1]
        sel = (t >= t0) & (t <= t1)
        if np.any(sel):
            out[:, sel] = sol.sol(t[sel])
        n_ev = len(evs)
        theta_max = max([theta_max, abs(float(sol.y[1, -1]))]
                        + [abs(float(yt[1])) for yt in sol.y_events[n_ev + 3]])
        t_out = [float(x) for x in sol.t_events[n_ev + 1] if x > t0]
        if t_out:
            t_out_cross = t_out[-1]
        for tz, yz in zip(sol.t_events[n_ev + 2], sol.y_events[n_ev + 2]):
            # a crossing, not the rounding of a theta that is 0 (a vertical motion)
            if tz > t0 and abs(yz[3]) > 1e-12:
                if lifted:
                    t_impacts.append(float(tz))
                lifted = False
        y_start = y
        y = sol.y[:, -1].copy()
        if t1 > t0:
            back, skip = {}, set()
        if sol.status == 1:
            if sol.t_events[n_ev].size:                 # |theta| = theta_fall
                if math.isnan(t_out_cross):
                    t_out_cross = t1
                overturned = True
            elif free and sol.t_events[n_ev + 1].size:   # outward past theta_overturn
                overturned = True
            for f, te in zip(armed, sol.t_events):
                if not te.size:
                    continue
                # the next segment starts on this zero: armed for the crossing back only
                # (an event at the restart itself: the sign it starts from)
                before = sol.sol(0.5 * (t0 + t1)) if t1 > t0 else y_start
                g_before = f(t0, before)
                if g_before == 0.0:
                    skip.add(f.__name__)
                else:
                    back[f.__name__] = 1.0 if g_before > 0 else -1.0
                if f.__name__ in delta_names and g_before != 0.0:
                    was_free = not (sides["delta_hi"] or sides["delta_lo"])
                    sides[f.__name__] = g_before < 0
                    if g_before > 0:                     # an edge lifted
                        lifted = True
                        if math.isnan(t_uplift):
                            t_uplift = t1
                        if not (sides["delta_hi"] or sides["delta_lo"]) \
                                and math.isnan(t_lift_off):
                            t_lift_off = t1
                    elif was_free and math.isnan(t_touch_down):
                        t_touch_down = t1
        t0 = t1
        if overturned:
            break
        if abs(t0 - t_exc) <= 1e-14 * max(1.0, t_exc) and abs(y[1]) > th_ot \
                and y[1] * y[3] > 0:
            overturned = True                            # beyond and moving away at t_exc
            break
        if prove_safe and t0 >= t_exc and math.isnan(t_safe) and abs(y[1]) < th_ot:
            e = 0.5 * m * y[2] ** 2 + m * h * math.sin(y[1]) * y[2] * y[3] \
                + 0.5 * body.i_o * y[3] ** 2 + m * body.g * (h * math.cos(y[1]) - y[0]) \
                + spring_energy(body, k, y[0], y[1])
            if e - u0 < barrier:
                t_safe = t0
                if stop_when_safe:
                    break
    normal = np.full(t.size, np.nan)
    moment = np.full(t.size, np.nan)
    width = np.full(t.size, np.nan)
    for j in range(t.size):
        if np.isfinite(out[0, j]):
            normal[j], moment[j], width[j] = contact(body, k, c, out[:4, j], varying)
    n_imp = len(t_impacts)
    if overturned:
        t_overturn = t_out_cross
        outcome = min(1 + n_imp, OUTCOME_IMPACTS)
    else:
        outcome = OUTCOME_SAFE if not math.isnan(t_safe) else OUTCOME_TIME_LIMIT
    return Run(t, out[0], out[1], out[2], out[3], normal, moment, width, out[4], outcome,
               n_imp, np.array(t_impacts), t_uplift, t_lift_off, t_touch_down, t_overturn,
               t_safe, theta_max, t0, n_seg, nfev[0])


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


def block_pushover_uplift(b, alpha, h, weight, k, bp):
    """Constant-k block after uplift at contact width b' in (0, 2 b] (m): (theta (rad),
    F (N)) with theta = asin(2 W/(alpha b'^2 k))/2 and M = alpha k sin cos^2 b'^2 (3 b -
    b')/3, F = (M - W h sin(theta))/(h cos(theta)); NaN where 2 W/(alpha b'^2 k) > 1."""
    bp = np.asarray(bp, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        theta = 0.5 * np.arcsin(2 * weight / (alpha * bp * bp * k))
    mom = alpha * k * np.sin(theta) * np.cos(theta) ** 2 * bp * bp * (3 * b - bp) / 3
    return theta, (mom - weight * h * np.sin(theta)) / (h * np.cos(theta))


def static_theta_overturn(body, k):
    """First zero of the imposed moment M_found - W h sin(theta) along the constant-k
    pushover after its peak (rad): brentq on F(b) between the peak of F (a scan of 20001
    widths) and the smallest admissible width (2 W/(k Phi) = 1)."""
    r, h, w = body.r, body.h, body.weight
    if body.footing == "circle":
        def force(b):
            return float(circle_pushover_uplift(r, h, w, k, b)[1])

        def theta(b):
            return float(circle_pushover_uplift(r, h, w, k, b)[0])

        def phi_gap(b):
            cc = r - b
            s = math.sqrt(2 * r * b - b * b)
            return k * (2 / 3 * s ** 3 + cc * cc * s - r * r * cc * math.acos(cc / r)) - 2 * w
        b_min = brentq(phi_gap, 1e-12 * r, 2 * r, xtol=1e-15 * r, rtol=1e-15)
    else:
        def force(bp):
            return float(block_pushover_uplift(r, body.alpha, h, w, k, bp)[1])

        def theta(bp):
            return float(block_pushover_uplift(r, body.alpha, h, w, k, bp)[0])
        b_min = math.sqrt(2 * w / (body.alpha * k))
    grid = np.linspace(b_min, 2 * r, 20001)[1:]
    forces = np.array([force(x) for x in grid])
    i = int(np.argmax(forces))
    lo = b_min * (1 + 1e-12)
    if force(lo) > 0:
        return math.nan
    return theta(brentq(force, lo, grid[i], xtol=1e-15 * r, rtol=1e-15))


def map_cell(body, k, c, x, y, theta_overturn=None, method="BDF", rtol=1e-8, contact=None,
             free_p=100.0):
    """Class of one cell of the one-sine overturning map on the dimensionless axes (x =
    omega_p/p, y = a_p/(g tan theta_c), rigid p and theta_c of the body): a run from rest
    on W/(k A) to the end of the pulse and on for at most free_p/p (s), proved safe (0),
    overturned (1..3), or undecided (-1) (doc/winkler.md (W.58))."""
    period = 2 * math.pi / (x * body.p)
    accel, breaks = sine_pulse(y * body.g * math.tan(body.theta_c), period)
    th_ot = static_theta_overturn(body, k) if theta_overturn is None else theta_overturn
    run = simulate(body, k, c, accel, np.array([0.0]), breaks, t_max=period + free_p / body.p,
                   method=method, rtol=rtol, theta_overturn=th_ot, t_exc=period,
                   prove_safe=True, stop_when_safe=True, contact=contact)
    return -1 if run.outcome == OUTCOME_TIME_LIMIT else run.outcome
