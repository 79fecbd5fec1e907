"""Seismic earth pressures on retaining walls (doc/walls.md; Fortran modules
``seispulse_walls_vy``, ``seispulse_walls_one_term``, ``seispulse_wall_table``).

* The Veletsos & Younan (1994a) series for a rigid, fixed-base wall on a viscoelastic
  layer (:func:`vy_rigid`, :func:`vy_pressure`, :func:`vy_fields`, :func:`vy_sweep`).
* The one-term (Vlasov-Leontiev) solution of Kloukinas et al. for homogeneous soil and
  for stiffness growing with depth as a power law, with a rotational base spring, a
  pair of walls and the equivalent Winkler springs (:func:`one_term` and the rest).
* :func:`comparison`: the side-by-side table of one wall that a design report needs
  (yielding-wall rules of :mod:`seispulse.codes` next to the rigid-wall rules and the
  elastic solutions), and :func:`pressure_profile`.

Conventions: omega_ratio = omega/omega_ref, omega_ref = pi Vs/(2H) with Vs at the base;
delta is the loss factor (G* = G(1 + i delta), about twice the damping ratio); nu in
[0, 0.5). Thrusts are positive (the soil pushes on the wall for a rock acceleration
away from it): q in rho Xg H^2, m in rho Xg H^3, pressures in rho Xg H. These solutions
give the dynamic increment only.
"""
from collections import namedtuple

import numpy as np

from . import _core, _walls_one_term, _walls_vy, codes
from ._seispulse import sp_wall_comparison, sp_wall_pressure
from ._table import TableResult
from ._walls_one_term import *  # noqa: F401,F403
from ._walls_vy import *  # noqa: F401,F403

#: Rows of :func:`comparison`, in order.
COMPARISON_ROWS = ("static active (Coulomb)", "Mononobe-Okabe total, EN 1998-5 E.1",
                   "Mononobe-Okabe dynamic increment", "Seed-Whitman increment (3/4 kh)",
                   "Wood (1973) rigid wall", "EN 1998-5 rigid wall", "Veletsos-Younan rigid wall",
                   "one-term solution")
#: The rows of :data:`COMPARISON_ROWS` whose thrust is a total (the others: increments).
TOTAL_ROWS = COMPARISON_ROWS[:2]


class Comparison(TableResult, namedtuple("Comparison", ["method", "thrust", "z", "moment",
                                                        "kv_used"])):
    """One wall, every method: ``method`` (the labels of :data:`COMPARISON_ROWS`),
    ``thrust`` (kN/m: total for the static and M-O total rows, the dynamic increment for
    the others), ``z`` (m above the base, point of application), ``moment`` (kNm/m about
    the base), ``kv_used`` (the signed kv of the M-O rows: the sign with the larger total
    thrust; kv > 0 acts upward). ``print()`` shows the table; :meth:`to_frame` gives it as
    a pandas DataFrame (``attrs['kv_used']``)."""

    __slots__ = ()
    _COLUMNS = (("method", "method", ""), ("thrust", "thrust", "kN/m"), ("z", "z", "m"),
                ("moment", "moment", "kNm/m"))

    def _table_notes(self):
        return [f"kv_used = {self.kv_used:.6g} (the signed kv of the Mononobe-Okabe rows; "
                "> 0 acts upward)"]

    def _frame_attrs(self):
        return {"kv_used": self.kv_used}


PressureProfile = namedtuple("PressureProfile", ["depth", "static", "mo_dynamic", "ec8_rigid",
                                                 "vy", "one_term"])
PressureProfile.__doc__ = """Pressures on the wall (kPa) against ``depth`` below the top (m):
``static`` K gamma* z (Coulomb); ``mo_dynamic`` the M-O increment spread uniformly
(resultant at H/2); ``ec8_rigid`` ag S/g gamma H; ``vy`` and ``one_term`` the moduli of
the elastic pressures. Water pressures are not included."""

__all__ = (["COMPARISON_ROWS", "TOTAL_ROWS", "Comparison", "PressureProfile", "comparison",
            "pressure_profile"]
           + list(_walls_vy.__all__) + list(_walls_one_term.__all__))


def _case(height, gamma, phi_deg, kh, kv, alpha_s, wall_friction_deg, psi_deg, beta_deg,
          gamma_phi, water, gamma_w, gamma_d, nu, delta, omega_ratio, shape, n, d_theta,
          l_over_h):
    """The scalars of the Fortran wall_case_t, checked for type."""
    s = _core.as_scalar
    n = s("n", n)
    water_code = _core.choice_code("water", water, codes._WATER_CODES)
    shape_code = _walls_one_term._shape_code(shape, n)
    alpha_s = kh if alpha_s is None else alpha_s
    gamma_d = 0.0 if gamma_d is None else gamma_d
    return (s("height", height), s("gamma", gamma), s("phi_deg", phi_deg),
            s("wall_friction_deg", wall_friction_deg), s("psi_deg", psi_deg),
            s("beta_deg", beta_deg), s("gamma_phi", gamma_phi), water_code,
            s("gamma_w", gamma_w), s("gamma_d", gamma_d), s("kh", kh), s("kv", kv),
            s("alpha_s", alpha_s), s("nu", nu), s("delta", delta), s("omega_ratio", omega_ratio),
            shape_code, n, s("d_theta", d_theta), s("l_over_h", l_over_h))


def comparison(height, gamma, phi_deg, kh, kv=0.0, alpha_s=None, *, wall_friction_deg=0.0,
               psi_deg=90.0, beta_deg=0.0, gamma_phi=1.0, water="dry", gamma_w=9.81,
               gamma_d=None, nu=0.3, delta=0.1, omega_ratio=0.0, shape=None, n=0.0,
               d_theta=0.0, l_over_h=np.inf):
    """Seismic thrust on one wall by every method, with points of application.

    Parameters
    ----------
    height : float
        Wall height H (m), > 0.
    gamma : float
        Unit weight of the backfill (kN/m^3), > 0.
    phi_deg : float
        Friction angle phi' (degrees), in (0, 90).
    kh, kv : float
        Seismic coefficients of the yielding-wall rows (EN 1998-5: kh = alpha S/r,
        kv = 0.5 or 0.33 kh, see :func:`seispulse.codes.seismic_coefficients`). kv is
        a magnitude; both signs are checked and the one with the larger total thrust
        is used.
    alpha_s : float, optional
        ag S/g, the ground acceleration of the non-yielding rows (Wood, EN 1998-5 rigid
        wall, Veletsos-Younan, one-term). Default: kh (i.e. r = 1).
    wall_friction_deg, psi_deg, beta_deg, gamma_phi, water, gamma_w, gamma_d
        As in :func:`seispulse.codes.earth_thrust` (degrees, kN/m^3).
    nu, delta, omega_ratio, shape, n, d_theta, l_over_h
        The elastic rows: Poisson's ratio, loss factor, omega/omega_ref (0 =
        pseudo-static), the one-term shape and stiffness exponent, the rotational
        flexibility H^2 G/K_R and the distance to a second wall over H (one-term row
        only; the Veletsos-Younan row is the rigid, fixed-base wall on homogeneous soil).

    Returns
    -------
    Comparison
        Rows in the order of :data:`COMPARISON_ROWS`; thrust (kN/m), z (m), moment
        (kNm/m). The elastic rows are |Q| gamma alpha_s H^2 at h = |M|/|Q|.

    Raises
    ------
    InvalidInputError
        A parameter outside its range (the message names it).
    NoSolutionError
        The backfill is steeper than phi' - theta: no Mononobe-Okabe active thrust.
    SingularError
        Undamped resonance of an elastic row (delta = 0 at a natural frequency).
    """
    args = _case(height, gamma, phi_deg, kh, kv, alpha_s, wall_friction_deg, psi_deg, beta_deg,
                 gamma_phi, water, gamma_w, gamma_d, nu, delta, omega_ratio, shape, n, d_theta,
                 l_over_h)
    thrust, z, moment, kv_used, stat, msg = sp_wall_comparison(*args)
    _core.raise_for_status(stat, msg)
    return Comparison(COMPARISON_ROWS, thrust.copy(), z.copy(), moment.copy(), float(kv_used))


def pressure_profile(depth, height, gamma, phi_deg, kh, kv=0.0, alpha_s=None, *,
                     wall_friction_deg=0.0, psi_deg=90.0, beta_deg=0.0, gamma_phi=1.0,
                     water="dry", gamma_w=9.81, gamma_d=None, nu=0.3, delta=0.1,
                     omega_ratio=0.0, shape=None, n=0.0, d_theta=0.0, l_over_h=np.inf):
    """Pressures on the wall against ``depth`` below the top (m, within [0, height]);
    the other arguments as :func:`comparison`. Returns :class:`PressureProfile` (kPa)."""
    depth = np.ascontiguousarray(_core.as_float_array("depth", depth).reshape(-1))
    args = _case(height, gamma, phi_deg, kh, kv, alpha_s, wall_friction_deg, psi_deg, beta_deg,
                 gamma_phi, water, gamma_w, gamma_d, nu, delta, omega_ratio, shape, n, d_theta,
                 l_over_h)
    p, stat, msg = sp_wall_pressure(*args, depth)
    _core.raise_for_status(stat, msg)
    return PressureProfile(depth, *(p[:, j].copy() for j in range(5)))
