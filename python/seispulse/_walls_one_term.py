"""One-term (Vlasov-Leontiev / Kloukinas) solution for seismic earth pressures on rigid walls
and its extensions (Fortran module ``seispulse_walls_one_term``; doc/walls.md sections 3-6).
Users reach these functions as ``seispulse.walls.<name>``.

Model: a viscoelastic layer of height H on rigid rock, retained by a rigid wall, harmonic
rock acceleration Xg exp(i omega t); u(x, y) = X(x) Phi(y), y measured up from the rock,
x from the wall into the backfill. Shear modulus G(y) = G_H g(y) (1 + i delta) with
g = 1 (homogeneous soil) or g = ((H - y)/H)^n (power law, -1 < n < 2: G = 0 at the
surface for n > 0, G_H at the base); V_SH = sqrt(G_H / rho). ``delta`` is the loss
factor (about twice the hysteretic damping ratio), ``nu`` Poisson's ratio in [0, 0.5).

Shapes (``SHAPES``): ``"linear"`` y/H, ``"sine"`` sin(pi y / 2H), ``"parabolic"``
(y/H)(2 - y/H) - homogeneous soil only (n = 0) - and ``"power"``, the static shape (2.68)
Phi = 1 - ((H - y)/H)^(2 - n) of the power-law layer (identical to ``"parabolic"`` at
n = 0). ``shape=None`` means ``"sine"`` for n = 0 and ``"power"`` otherwise.

Frequency convention: ``omega_ratio`` = omega / omega_ref with omega_ref = pi V_SH / (2H)
for every shape and every n, i.e. omega H / V_SH = (pi/2) omega_ratio. For homogeneous soil
omega_ref is the fundamental frequency omega_1 of the layer (as in the Veletsos-Younan
routines); for the power law it is not (see :func:`power_law_fundamental`), and the
one-term cut-off is at omega H / V_SH = sqrt((5 - 2n)/2) (:func:`power_law_cutoff`).

Signs and units (all dimensionless): thrust ``q`` positive for a positive rock
acceleration (q = -Q_b of Eq. 2.48/2.71), in rho Xg H^2; moment about the base
``m = q h``, in rho Xg H^3; wall pressure p = -sigma_x(0, y), in rho Xg H; displacements
relative to the rock keep the source's sign (u < 0 for Xg > 0), in rho Xg H^2 / G_H; base
rotation ``theta = u0 / H``, in rho Xg H / G_H; Winkler moduli in G_H / H; dashpots in
rho V_SH. Results are the dynamic increment only (no geostatic thrust) and are complex
transfer functions (take abs() for amplitudes).

Errata of the source used in corrected form (doc/walls.md): Eq. 2.39 (sign of k*^2), 2.60/2.73
(G* inside the integrals, normalised by G_H, so Lf s0 is real), the claim "0.979 at
nu = 0.30" after Eq. 2.51 (it is 0.9461; 0.9791 is nu = 1/3), Eq. 2.95 (a spurious
G(1 + i delta)), Eq. 2.102b (sign of B: only the corrected sign gives X(L) = 0), Eq. 2.104
(prefactor) and the Phi column of Table 2.2 (the numbers use Eq. 2.68).
"""

import numbers
from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_ot_cutoff, sp_ot_dashpot, sp_ot_displacement, sp_ot_fundamental,
                         sp_ot_pressure, sp_ot_scott, sp_ot_shape, sp_ot_solve, sp_ot_vy_spring,
                         sp_ot_winkler)
from .errors import InvalidInputError

__all__ = ["SHAPES", "ShapeConstants", "OneTerm", "shape_constants", "one_term",
           "one_term_pressure", "one_term_displacement", "power_law_fundamental",
           "power_law_cutoff", "winkler_spring", "winkler_dashpot", "scott_spring", "vy_spring"]

#: Shape functions of the one-term method (Fortran SHAPE_* codes).
_SHAPE_CODES = {"linear": _f.WALL_SHAPE_LINEAR, "sine": _f.WALL_SHAPE_SINE,
                "parabolic": _f.WALL_SHAPE_PARABOLIC, "power": _f.WALL_SHAPE_POWER}
SHAPES = tuple(_SHAPE_CODES)

ShapeConstants = namedtuple("ShapeConstants", ["shape", "n", "a_oc", "l_factor", "mass_factor",
                                               "s0", "s1", "h_ratio"])
ShapeConstants.__doc__ = """Constants of a shape function (dimensionless, real; integrals over
eta = y/H from 0 to 1, g = G/G_H): a_oc = sqrt(int g Phi'^2 / int g Phi^2), the cut-off
(Eq. 2.43b/2.64a); l_factor = int Phi / int g Phi^2 (the source's L of Eq. 2.43c for
homogeneous soil, L (1 + i delta) of Eq. 2.64c for the power law);
mass_factor = int Phi^2 / int g Phi^2, so that a_o^2 = (omega H/V_SH)^2 mass_factor /
(1 + i delta); s0 = int g Phi and s1 = int g Phi eta (Eq. 2.50/2.73 divided by G_H);
h_ratio = s1 / s0, the height of the resultant over H (frequency independent)."""

OneTerm = namedtuple("OneTerm", ["q", "m", "h_ratio", "u_ff0", "u0", "theta", "lam", "flex"])
OneTerm.__doc__ = """One-term solution (complex unless stated): q, thrust in rho Xg H^2
(positive = compression of the wall); m = q h, base moment in rho Xg H^3; h_ratio, h/H (real);
u_ff0, free-field surface displacement (Eq. 2.98) in rho Xg H^2/G_H; u0, wall-top displacement
(Eq. 2.99b; 0 for a rigid wall or a pair); theta = u0/H, base rotation in rho Xg H/G_H; lam,
the pair factor tanh(mL/2) (Eq. 2.105; 1 for one wall); flex, Q/Q_rigid of the rotational
spring (Eq. 2.96; 1 when d_theta = 0)."""


def _shape_code(shape, n):
    if shape is None:
        shape = "sine" if n == 0.0 else "power"
    return _core.choice_code("shape", shape, _SHAPE_CODES)


def _common(delta, nu, shape, n, d_theta=0.0, l_over_h=np.inf):
    n = _core.as_scalar("n", n)
    return (_core.as_scalar("delta", delta), _core.as_scalar("nu", nu), _shape_code(shape, n), n,
            _core.as_scalar("d_theta", d_theta), _core.as_scalar("l_over_h", l_over_h))


def _omegas(omega_ratio, name="omega_ratio"):
    arr = _core.as_float_array(name, omega_ratio)
    return arr.shape, np.ascontiguousarray(arr.reshape(-1))


def _out(shape, arr):
    """A flat result as an array of `shape`, or a Python scalar for a 0-d shape."""
    if shape == ():
        return arr.reshape(-1)[0].item()
    return arr.reshape(shape)


#: Fortran arrays whose elements name(i) errors give as the caller's name[i - 1].
_INDEXED = ("accel", "x", "y")


def shape_constants(shape="sine", n=0.0):
    """Constants of a one-term shape function (Table 2.1, Eq. 2.69).

    Parameters
    ----------
    shape : {'linear', 'sine', 'parabolic', 'power'}
        Shape function; the first three are for homogeneous soil (n = 0).
    n : float
        Stiffness exponent of G = G_H ((H - y)/H)^n, -1 < n < 2 (``"power"`` only).

    Returns
    -------
    ShapeConstants
        Closed forms: linear a_oc = sqrt(3), l_factor = 3/2, s0 = 1/2, h/H = 2/3; sine
        pi/2, 4/pi, 2/pi, 2/pi; power law a_oc^2 = 3(5 - n)(1 + n)/(2(3 - n)),
        l_factor = a_oc^2/(2 - n), mass_factor = 2 a_oc^2/(5 - 2n), s0 = (2 - n)/(3(1 + n)),
        h/H = (5 + n)/(4(2 + n)) (the parabola is n = 0).
    """
    n = _core.as_scalar("n", n)
    code = _shape_code(shape, n)
    *vals, stat, errmsg = sp_ot_shape(code, n)
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return ShapeConstants(SHAPES[code - 1], n, *vals)


def one_term(omega_ratio, delta, nu, shape=None, n=0.0, d_theta=0.0, l_over_h=np.inf):
    """Thrust, moment and displacements of the one-term solution (doc/walls.md sections 3-5).

    Rigid wall (Eq. 2.48/2.71): q = psi_sigma l_factor s0 / s with
    s = sqrt(a_oc^2 - a_o^2) (Re s >= 0; for delta = 0 above the cut-off the delta -> 0+
    branch +i sqrt(a_o^2 - a_oc^2), radiating waves), psi_sigma = 2/sqrt((1 - nu)(2 - nu)).
    Rotational base spring (Eq. 2.96, corrected 2.95): q = q_rigid F,
    F = 1/(1 + psi_sigma s s0 (h/H)(1 + i delta) d_theta), u0 = (1 - F) u_ff0.
    Pair of walls at distance L (Eq. 2.105-2.107): q = q_single tanh(mL/2),
    mL = s (L/H)/psi_e, psi_e = sqrt((2 - nu)/(1 - nu)); |lam| can exceed 1 near the cut-off.

    Parameters
    ----------
    omega_ratio : float or array
        omega / omega_ref, omega_ref = pi V_SH / (2H) (>= 0); an array gives arrays.
    delta : float
        Loss factor, G* = G (1 + i delta), >= 0.
    nu : float
        Poisson's ratio, 0 <= nu < 0.5.
    shape : {'linear', 'sine', 'parabolic', 'power'} or None
        None: ``"sine"`` if n == 0 else ``"power"``.
    n : float
        Stiffness exponent, -1 < n < 2 (0 for the homogeneous shapes).
    d_theta : float
        Rotational flexibility H^2 G_H / K_R >= 0 (0: fixed base; ``inf``: a hinge, q = 0,
        u0 = u_ff0).
    l_over_h : float
        Distance L/H to a second rigid wall, > 0 (``inf``: one wall). A pair with
        d_theta > 0 is not derived in the source and is refused.

    Returns
    -------
    OneTerm
        Complex fields (Python complex scalars for a scalar omega_ratio), units in the
        :class:`OneTerm` doc.

    Raises
    ------
    InvalidInputError
        A parameter outside its range (the message names it).
    SingularError
        delta = 0 exactly at the one-term cut-off (a_o = a_oc), or the undamped
        standing-wave resonance of a pair.
    """
    shape_out, om = _omegas(omega_ratio)
    delta, nu, code, n, d_theta, l_over_h = _common(delta, nu, shape, n, d_theta, l_over_h)
    q, m, h, uff0, u0, theta, lam, flex, stat, errmsg = sp_ot_solve(
        om, delta, nu, code, n, d_theta, l_over_h)
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return OneTerm(*(_out(shape_out, a) for a in (q, m, h, uff0, u0, theta, lam, flex)))


def one_term_pressure(omega_ratio, delta, nu, y, shape=None, n=0.0, d_theta=0.0,
                      l_over_h=np.inf):
    """Wall pressure p(y) = -sigma_x(0, y) (Eq. 2.47/2.70), in rho Xg H (complex).

    p = psi_sigma l_factor g(y) Phi(y) F lam / s: proportional to G(y) Phi(y) at every
    frequency (zero at the base; at the surface zero for n > 0 and unbounded for n < 0,
    where y = 1 is refused). It integrates over y/H to q and its first moment to m.

    Parameters
    ----------
    omega_ratio : float
        omega / omega_ref (scalar), omega_ref = pi V_SH / (2H).
    delta, nu, shape, n, d_theta, l_over_h
        As in :func:`one_term`.
    y : float or array
        Heights above the base, y/H in [0, 1].

    Returns
    -------
    complex or ndarray of complex
        Shaped like ``y``.
    """
    om = _core.as_scalar("omega_ratio", omega_ratio)
    arr = _core.as_float_array("y", y)
    delta, nu, code, n, d_theta, l_over_h = _common(delta, nu, shape, n, d_theta, l_over_h)
    p, stat, errmsg = sp_ot_pressure(om, delta, nu, code, n, d_theta, l_over_h,
                                     np.ascontiguousarray(arr.reshape(-1)))
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return _out(arr.shape, p)


def one_term_displacement(omega_ratio, delta, nu, x, y, shape=None, n=0.0, d_theta=0.0,
                          l_over_h=np.inf):
    """Horizontal soil displacement u(x, y) relative to the rock, in rho Xg H^2 / G_H (complex).

    One wall (Eq. 2.46/2.67/2.93): u = Phi(y) [u_ff0 (1 - exp(-m x)) + u0 exp(-m x)],
    m x = s (x/H)/psi_e, tending to the free field u_ff0 Phi(y) as x grows (decaying below
    the cut-off or with delta > 0; an undamped travelling wave above it). Pair (Eq. 2.103
    with the corrected B of 2.102b): u = u_ff0 Phi(y) [1 - cosh(m(x - L/2))/cosh(mL/2)],
    zero at both walls.

    Parameters
    ----------
    omega_ratio : float
        omega / omega_ref (scalar).
    delta, nu, shape, n, d_theta, l_over_h
        As in :func:`one_term`.
    x : float or array
        Distance from the wall x/H (finite, >= 0; <= l_over_h for a pair).
    y : float or array
        Height above the base y/H in [0, 1]; broadcasts with ``x``.

    Returns
    -------
    complex or ndarray of complex
        Shaped like ``x`` and ``y`` broadcast together.
    """
    om = _core.as_scalar("omega_ratio", omega_ratio)
    shape_out, arrs = _core.broadcast(x=x, y=y)
    delta, nu, code, n, d_theta, l_over_h = _common(delta, nu, shape, n, d_theta, l_over_h)
    u, stat, errmsg = sp_ot_displacement(om, delta, nu, code, n, d_theta, l_over_h,
                                         _core.flat(arrs["x"], shape_out),
                                         _core.flat(arrs["y"], shape_out))
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return _out(shape_out, u)


def power_law_fundamental(n):
    """Exact fundamental frequency omega_1 H / V_SH of the power-law layer (not in the source).

    G = G_H ((H - y)/H)^n on rigid rock: omega_1 H / V_SH = ((2 - n)/2) j_(q,1) with
    q = -(1 - n)/(2 - n) and j_(q,1) the first zero of the Bessel function J_q (pi/2 at
    n = 0, 1.20241 at n = 1, -> 1/2 as n -> 2). Found by Brent's method on proven bounds
    (Euler-Rayleigh for q < 1, Qu-Wong 1999 for q >= 1) applied to x J_q / J_(q+1) from its
    continued fraction; relative error below 1e-14 for every n in (-1, 2). In units of
    omega_ref = pi V_SH/(2H) the ratio is 2 omega_1 H / (pi V_SH).

    Parameters
    ----------
    n : float or array
        Stiffness exponent, -1 < n < 2.

    Returns
    -------
    float or ndarray
    """
    shape_out, arr = _omegas(n, "n")
    w1, stat, errmsg = sp_ot_fundamental(arr)
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return _out(shape_out, w1)


def power_law_cutoff(n):
    """Cut-off omega_c H / V_SH = sqrt((5 - 2n)/2) of the one-term power-law model (Eq. 2.69).

    0.7 % (n = 0) to 1.9 % (n = 1) above :func:`power_law_fundamental` (at n = 0
    sqrt(5/2) = 1.58114 versus pi/2).

    Parameters
    ----------
    n : float or array
        Stiffness exponent, -1 < n < 2.
    """
    shape_out, arr = _omegas(n, "n")
    wc, stat, errmsg = sp_ot_cutoff(arr)
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return _out(shape_out, wc)


def winkler_spring(omega_ratio, delta, nu, shape=None, n=0.0):
    """Equivalent Winkler spring k = psi_sigma s (1 + i delta) (Eq. 2.110), in G_H / H.

    sigma_x(0, y) = k u_ff(y): independent of depth for homogeneous soil; for the power law
    this is the base value and k(y) = k G(y)/G_H. Static sine shape: (pi/2) psi_sigma
    (Eq. 2.112: 2.742, 2.880, 2.980, 3.206 at nu = 0.25, 0.3, 1/3, 0.4). Zero at the cut-off,
    a pure dashpot above it when delta = 0 (see :func:`winkler_dashpot`). Multiply by the
    rotational-spring or pair factor (``flex``, ``lam`` of :func:`one_term`) for those cases.

    Parameters
    ----------
    omega_ratio : float or array
        omega / omega_ref, omega_ref = pi V_SH / (2H).
    delta, nu, shape, n
        As in :func:`one_term`.

    Returns
    -------
    complex or ndarray of complex
    """
    shape_out, om = _omegas(omega_ratio)
    delta, nu, code, n, _, _ = _common(delta, nu, shape, n)
    k, stat, errmsg = sp_ot_winkler(om, delta, nu, code, n)
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return _out(shape_out, k)


def winkler_dashpot(omega_ratio, nu, shape=None, n=0.0):
    """High-frequency dashpot (Eq. 2.111) for delta = 0 above the cut-off, in rho V_SH.

    c = psi_sigma sqrt(a_o^2 - a_oc^2) / (omega H / V_SH), so that k = i omega c (for the
    power law times G(y)/G_H). Below the cut-off (omega_ratio = 1 for the sine shape) the
    spring is real and this raises InvalidInputError.

    Parameters
    ----------
    omega_ratio : float or array
        omega / omega_ref, at or above the cut-off.
    nu, shape, n
        As in :func:`one_term`.
    """
    shape_out, om = _omegas(omega_ratio)
    _, nu, code, n, _, _ = _common(0.0, nu, shape, n)
    c, stat, errmsg = sp_ot_dashpot(om, nu, code, n)
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return _out(shape_out, c)


def scott_spring(nu):
    """Scott (1973) Winkler spring (Eq. 2.113): K_s = 0.8 (1 - nu)/(1 - 2 nu), in G / H.

    Frequency independent and undamped; 1.4 at nu = 0.3, 2.4 at 0.4, 4.4 at 0.45, unbounded
    as nu -> 0.5 (nu = 0.5 is refused).

    Parameters
    ----------
    nu : float or array
        Poisson's ratio, 0 <= nu < 0.5.
    """
    shape_out, arr = _omegas(nu, "nu")
    k, stat, errmsg = sp_ot_scott(arr)
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return _out(shape_out, k)


def vy_spring(mode, omega_ratio, delta, nu):
    """Veletsos-Younan (1994b) Winkler spring of mode j (Eq. 2.114), in G / H (complex).

    K_j = ((2j - 1) pi/2) psi_o sqrt(1 + i delta) sqrt(1 - phi_j^2 + i delta),
    phi_j = omega_ratio / (2j - 1), psi_o = sqrt(2/(1 - nu)). The printed
    sqrt((1 + i delta)(1 - phi_j^2 + i delta)) is taken as the product of principal roots
    (Im K >= 0: a positive dashpot, the delta -> 0+ limit); the principal root of the
    product has the opposite sign when phi_j^2 > 2. Static mode 1: (pi/2) psi_o; it differs
    from :func:`winkler_spring` (sine) only by psi_o versus psi_sigma.

    Parameters
    ----------
    mode : int
        Mode number j >= 1.
    omega_ratio : float or array
        omega / omega_1, omega_1 = pi V_s / (2H).
    delta : float
        Loss factor >= 0.
    nu : float
        Poisson's ratio, 0 <= nu < 0.5.
    """
    if isinstance(mode, (bool, np.bool_)) or not isinstance(mode, numbers.Integral):
        raise InvalidInputError(f"mode = {mode!r}: must be an integer >= 1")
    if not -2**31 < int(mode) < 2**31:
        raise InvalidInputError(f"mode = {mode!r}: must be an integer >= 1 (and < 2**31)")
    shape_out, om = _omegas(omega_ratio)
    k, stat, errmsg = sp_ot_vy_spring(int(mode), om, _core.as_scalar("delta", delta),
                                      _core.as_scalar("nu", nu))
    _core.raise_for_status(stat, errmsg, indexed=_INDEXED)
    return _out(shape_out, k)
