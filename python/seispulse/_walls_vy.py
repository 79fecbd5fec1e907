"""Veletsos-Younan (1994a) series for a rigid, fixed-base wall on a homogeneous viscoelastic
layer (Fortran module ``seispulse_walls_vy``; doc/walls.md section 2), and the shared
compressibility factors. Users reach these functions as ``seispulse.walls.<name>``.

Model: a layer of height H on rigid rock, shear modulus G* = G(1 + i delta) (``delta`` is
the loss factor, about twice the hysteretic damping ratio), Poisson's ratio ``nu``, retained
by a rigid wall at x = 0; harmonic rock acceleration Xg exp(i omega t). Frequencies enter
as ``omega_ratio`` = omega/omega_1 with omega_1 = pi Vs/(2H) the fundamental frequency of
the free-field layer. The results are complex transfer functions of the dynamic increment
only (no geostatic thrust).

Units and signs:

- q, the thrust on the wall (= -Q_b of Eq. 2.34), in rho Xg H^2; positive when it pushes
  the wall. Static value 14 zeta(3)/pi^3 psi_sigma = 0.542755 psi_sigma (0.9951 at
  nu = 0.3).
- m, the overturning moment about the base (= -M_b of Eq. 2.35), in rho Xg H^3.
- h_ratio = |m|/|q| = |h|/H, the height of the point of application (static 0.59858).
- p(y) = -sigma_x(0, y), the wall pressure (compression positive), in rho Xg H.
- u, v (rho Xg H^2/G), sigma_x and tau (rho Xg H) keep the source's signs of Eqs.
  2.30-2.33 (tension positive; u < 0 for positive Xg: the soil lags toward the wall).
- x/H >= 0 from the wall into the backfill, y/H in [0, 1] measured up from the base.

Errata of the printed source corrected here (doc/walls.md): Eq. 2.25 has psi_e outside the
bracket; Eq. 2.29 misses H^2; Eq. 2.30 counts the damping factor (1 + i delta) twice; Eqs.
2.31 and 2.32 are re-derived; Eqs. 2.35/2.36 need 1/n^4 (the printed 1/n^3 gives a static
h/H of 0.58647 instead of 0.59858). For delta = 0 above a free-field frequency the square
roots take the delta -> 0+ branch (radiating waves); delta = 0 exactly at an odd
omega_ratio raises :class:`seispulse.SingularError`.

Tolerance: ``tol`` bounds the relative truncation error of q (and of m unless |m| <
6e-4 |q| H); for the pressure and the fields it bounds the truncation error relative to
the sum of the absolute modal amplitudes of that quantity (for p: (8 psi_sigma/pi^2)
sum |r_n|/n^2, psi_sigma in the static case), so values far below that scale are accurate
in absolute, not relative, terms. Rounding adds a few 1e-16 of the same scales.
"""

from collections import namedtuple
import numbers

import numpy as np

from . import _core
from ._seispulse import (sp_free_field_frequencies, sp_vy_fields, sp_vy_pressure,
                         sp_vy_rigid, sp_vy_rigid_sweep, sp_wall_psi)
from .errors import InvalidInputError

__all__ = ["PsiFactors", "VYRigid", "VYFields", "VYSweep", "VY_DEFAULT_TOL", "psi_factors",
           "free_field_frequencies", "vy_rigid", "vy_pressure", "vy_fields", "vy_sweep"]

#: Default tolerance of :func:`vy_rigid`, :func:`vy_pressure`, :func:`vy_fields`.
VY_DEFAULT_TOL = 1e-10

PsiFactors = namedtuple("PsiFactors", ["psi_e", "psi_o", "psi_sigma", "psi_v", "psi_t"])
PsiFactors.__doc__ = """Compressibility factors of doc/walls.md section 1 (dimensionless):
psi_e = sqrt((2 - nu)/(1 - nu)) (x-decay, Eq. 2.10), psi_o = sqrt(2/(1 - nu))
(sigma_x = psi_o^2 G* du/dx), psi_sigma = psi_o^2/psi_e = 2/sqrt((1 - nu)(2 - nu)) (wall
stresses, thrust, moment), psi_v = nu/sqrt((1 - nu)(2 - nu)) (vertical displacement, Eq.
2.31), psi_t = sqrt(2(1 - nu)/(1 - 2 nu)) (the Matsuo-Ohara/Tajimi v = 0 factor)."""

VYRigid = namedtuple("VYRigid", ["q", "m", "h_ratio", "n_terms"])
VYRigid.__doc__ = """Rigid-wall resultants: q, the thrust -Q_b (complex, rho Xg H^2); m, the
base moment -M_b (complex, rho Xg H^3); h_ratio = |m|/|q| = |h|/H; n_terms, the number of
odd-n terms summed explicitly (the tail beyond them is summed in closed form)."""

VYFields = namedtuple("VYFields", ["u", "v", "sigma_x", "tau"])
VYFields.__doc__ = """Complex fields of Eqs. 2.30-2.33 (source signs): u, v displacements
relative to the rock (rho Xg H^2/G); sigma_x normal stress, tension positive, and tau shear
stress (rho Xg H)."""

VYSweep = namedtuple("VYSweep", ["omega_ratio", "q", "m", "h_ratio", "amplification"])
VYSweep.__doc__ = """A frequency sweep: omega_ratio (omega/omega_1); q (rho Xg H^2) and m
(rho Xg H^3), complex; h_ratio = |m|/|q|; amplification = |q|/q_static with q_static =
14 zeta(3)/pi^3 psi_sigma, the omega = 0 thrust."""

#: Fortran arrays whose elements name(i) errors give as Python's name[i - 1] (flat index);
#: omega_ratios(i) is omega_ratio[i - 1] except in the sweep (_SWEEP_INDEXED).
_INDEXED = {"accel": "accel", "x": "x", "y": "y", "omega_ratio": "omega_ratio",
            "delta": "delta", "nu": "nu", "omega_ratios": "omega_ratio"}
_SWEEP_INDEXED = {**_INDEXED, "omega_ratios": "omega_ratios"}


def _tol(tol):
    return _core.as_scalar("tol", tol)


def _complex_shaped(shape, *arrays):
    if shape == ():
        return tuple(complex(a[0]) for a in arrays)
    return tuple(np.asarray(a).reshape(shape) for a in arrays)


def psi_factors(nu):
    """Compressibility factors for Poisson's ratio ``nu`` in [0, 0.5).

    Returns :class:`PsiFactors` (floats for a scalar ``nu``, arrays shaped like it
    otherwise). At nu = 0.3: psi_e = 1.5584, psi_o = 1.6903, psi_sigma = 1.8334,
    psi_v = 0.2750. psi_t grows without bound as nu -> 0.5 (nu = 0.5 itself is refused).
    """
    shape, arr = _core.broadcast(nu=nu)
    out = sp_wall_psi(_core.flat(arr["nu"], shape))
    _core.raise_for_status(out[-2], out[-1], indexed=_INDEXED)
    return PsiFactors(*_core.shaped(shape, *out[:-2]))


def free_field_frequencies(height, vs, n_modes=5):
    """Natural circular frequencies of the free-field layer, Eq. 2.22:
    omega_k = (2k - 1) pi Vs/(2H), k = 1..n_modes (rad/s).

    Parameters: ``height`` H (m, > 0), ``vs`` shear-wave velocity (m/s, > 0), ``n_modes``
    (integer >= 1). Returns a float array of length n_modes.
    """
    if isinstance(n_modes, (bool, np.bool_)) or not isinstance(n_modes, numbers.Integral) \
            or n_modes < 1:
        raise InvalidInputError(f"n_modes = {n_modes!r}: must be an integer >= 1")
    omegas, stat, msg = sp_free_field_frequencies(_core.as_scalar("height", height),
                                                  _core.as_scalar("vs", vs), int(n_modes))
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return omegas


def vy_rigid(omega_ratio, delta, nu, tol=VY_DEFAULT_TOL):
    """Thrust, base moment and point of application on a rigid wall (Eqs. 2.34-2.36,
    with the 1/n^4 of the corrected 2.35):

        q = (16 psi_sigma/pi^3) sum_{n odd} r_n/n^3,
        m = (32 psi_sigma/pi^4) sum_{n odd} (-1)^((n-1)/2) r_n/n^4,
        r_n = sqrt(1 + i delta)/sqrt(1 - phi_n^2 + i delta),  phi_n = omega_ratio/n.

    Parameters
    ----------
    omega_ratio : float or array
        omega/omega_1, in [0, 1e4].
    delta : float or array
        Loss factor (>= 0); G* = G(1 + i delta).
    nu : float or array
        Poisson's ratio in [0, 0.5); enters only through psi_sigma.
    tol : float
        Relative tolerance on q and m, in [1e-15, 1e-2] (m: relative unless
        |m| < 6e-4 |q| H, then absolute to tol x 6e-4 |q| H).

    Returns
    -------
    VYRigid
        q (rho Xg H^2), m (rho Xg H^3), h_ratio = |m|/|q|, n_terms. Scalars for scalar
        input; arrays of the broadcast shape otherwise (computed by the sweep routine
        when delta and nu are single values).

    Raises :class:`seispulse.SingularError` for delta = 0 at an odd omega_ratio (1, 3,
    5, ...), :class:`seispulse.InvalidInputError` for bad input.
    """
    tol = _tol(tol)
    shape, arr = _core.broadcast(omega_ratio=omega_ratio, delta=delta, nu=nu)
    w = _core.flat(arr["omega_ratio"], shape)
    if shape != () and arr["delta"].size == 1 and arr["nu"].size == 1:
        q, m, h, nt, stat, msg = sp_vy_rigid_sweep(w, float(arr["delta"].reshape(-1)[0]),
                                                   float(arr["nu"].reshape(-1)[0]), tol)
    else:
        q, m, h, nt, stat, msg = sp_vy_rigid(w, _core.flat(arr["delta"], shape),
                                             _core.flat(arr["nu"], shape), tol)
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    if shape == ():
        return VYRigid(complex(q[0]), complex(m[0]), float(h[0]), int(nt[0]))
    return VYRigid(q.reshape(shape), m.reshape(shape), h.reshape(shape), nt.reshape(shape))


def vy_pressure(omega_ratio, delta, nu, y, tol=VY_DEFAULT_TOL):
    """Wall pressure p(y) = -sigma_x(0, y) = (8 psi_sigma/pi^2) sum r_n sin(n pi y/2)/n^2
    (Eq. 2.32 at x = 0), compression positive, in rho Xg H.

    ``y`` = y/H in [0, 1], measured up from the base (p(0) = 0; static p(1) =
    0.742454 psi_sigma). ``omega_ratio``, ``delta``, ``nu`` single values as in
    :func:`vy_rigid`. ``tol`` bounds the truncation error relative to
    (8 psi_sigma/pi^2) sum |r_n|/n^2 (psi_sigma in the static case). Returns complex
    values shaped like ``y`` (a complex scalar for a scalar y).
    """
    tol = _tol(tol)
    yarr = _core.as_float_array("y", y)
    p, stat, msg = sp_vy_pressure(_core.as_scalar("omega_ratio", omega_ratio),
                                  _core.as_scalar("delta", delta), _core.as_scalar("nu", nu),
                                  np.ascontiguousarray(yarr.reshape(-1)), tol)
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return _complex_shaped(yarr.shape, p)[0]


def vy_fields(omega_ratio, delta, nu, x, y, tol=VY_DEFAULT_TOL):
    """Displacements and stresses in the backfill, Eqs. 2.30-2.33 as corrected in
    doc/walls.md, at the points (x, y) (broadcast together):

        u = -(16/(pi^3 (1 + i delta))) sum r_n^2 (1 - e^(-a_n x)) sin(n pi y/2)/n^3,
        v = (16 psi_v/(pi^3 (1 + i delta))) sum r_n e^(-a_n x) (1 - cos(n pi y/2))/n^3,
        sigma_x = -(8 psi_sigma/pi^2) sum r_n e^(-a_n x) sin(n pi y/2)/n^2,
        tau = -(8/pi^2) sum [r_n^2 (1 - e^(-a_n x)) cos(n pi y/2)
                             + nu/(2 - nu) e^(-a_n x) (1 - cos(n pi y/2))]/n^2,

    with a_n H = (n pi/(2 psi_e)) sqrt(1 - phi_n^2/(1 + i delta)), Re a_n >= 0 (Eq. 2.25).
    At the wall u = 0, sigma_x = -p and tau = -nu/(2 - nu) y exactly; far from it u and
    tau tend to the free-field shear-beam response (u(H) = -1/(2(1 + i delta)) statically).

    Parameters: ``x`` = x/H in [0, 1e6], ``y`` = y/H in [0, 1]; ``tol`` bounds each
    field's truncation error relative to the sum of its absolute modal amplitudes.
    Returns :class:`VYFields` of complex values of the broadcast shape (u, v in
    rho Xg H^2/G; sigma_x, tau in rho Xg H). Points next to the wall (x -> 0+) converge
    like the wall itself. A tolerance too tight for a large omega_ratio (more than 2
    million terms: tol = 1e-15 at omega_ratio = 500, or the default 1e-10 above
    omega_ratio = 7000 or so) raises :class:`seispulse.ConvergenceError` naming ``tol``;
    so does :func:`vy_pressure`.
    """
    tol = _tol(tol)
    shape, arr = _core.broadcast(x=x, y=y)
    u, v, sx, tau, stat, msg = sp_vy_fields(
        _core.as_scalar("omega_ratio", omega_ratio), _core.as_scalar("delta", delta),
        _core.as_scalar("nu", nu), _core.flat(arr["x"], shape), _core.flat(arr["y"], shape),
        tol)
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return VYFields(*_complex_shaped(shape, u, v, sx, tau))


def vy_sweep(omega_ratios, delta, nu, tol=1e-8):
    """Thrust and moment over a set of frequencies (one ``delta``, one ``nu``), with the
    dynamic amplification |q|/q_static of the thrust.

    ``omega_ratios``: omega/omega_1 values (1-d or any shape, each in [0, 1e4]); ``tol``
    as in :func:`vy_rigid` (default 1e-8, plenty for plotting; a 1000-point sweep takes
    a few milliseconds). Returns :class:`VYSweep` with arrays shaped like omega_ratios.
    """
    tol = _tol(tol)
    w = _core.as_float_array("omega_ratios", omega_ratios)
    d = _core.as_scalar("delta", delta)
    nu_ = _core.as_scalar("nu", nu)
    q, m, h, _, stat, msg = sp_vy_rigid_sweep(np.ascontiguousarray(w.reshape(-1)), d, nu_, tol)
    _core.raise_for_status(stat, msg, indexed=_SWEEP_INDEXED)
    q0, _, _, _, stat, msg = sp_vy_rigid_sweep(np.zeros(1), d, nu_, tol)
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    q_static = abs(complex(q0[0]))
    return VYSweep(w.copy(), q.reshape(w.shape), m.reshape(w.shape), h.reshape(w.shape),
                   (np.abs(q) / q_static).reshape(w.shape))
