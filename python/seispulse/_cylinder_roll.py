"""Rocking with rolling of a rigid circular cylinder on its base rim, without slip, on a
rigid base shaken horizontally (Koh & Mustafa 1990 [KM90]; Fortran module
``seispulse_cylinder_roll``; theory in doc/rolling.md).

Z-X-Z Euler angles: heading ``psi``, tilt ``theta >= 0``, spin ``phi_s`` about the axis.
The body leans towards the horizontal direction ``(sin psi, -cos psi)``; the contact
point is the rim point on that side. Units: m, s, kg, rad, rad/s, N, J.
"""

from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import sp_cylinder_roll, sp_fetch_impacts
from .errors import InvalidInputError
from .pulse import Pulse

__all__ = ["ROLL_OUTCOMES", "ROLL_COLUMNS", "RollRun", "roll", "plot_roll"]

#: Outcomes of a run, by code.
ROLL_OUTCOMES = _core.by_code({_f.ROLL_RUN_REST: "rest", _f.ROLL_RUN_NO_UPLIFT: "no_uplift",
                               _f.ROLL_RUN_OVERTURN: "overturn",
                               _f.ROLL_RUN_TIME_LIMIT: "time_limit"})

#: The output histories, in the order of the Fortran columns ROLL_OUT_*.
ROLL_COLUMNS = _core.by_code({
    _f.ROLL_OUT_THETA - 1: "theta", _f.ROLL_OUT_PSI - 1: "psi", _f.ROLL_OUT_SPIN - 1: "spin",
    _f.ROLL_OUT_THETA_RATE - 1: "theta_rate", _f.ROLL_OUT_PSI_RATE - 1: "psi_rate",
    _f.ROLL_OUT_SPIN_RATE - 1: "spin_rate", _f.ROLL_OUT_XP - 1: "x_contact",
    _f.ROLL_OUT_YP - 1: "y_contact", _f.ROLL_OUT_XG - 1: "x_g", _f.ROLL_OUT_YG - 1: "y_g",
    _f.ROLL_OUT_NORMAL - 1: "normal_force", _f.ROLL_OUT_FRICTION - 1: "friction_demand",
    _f.ROLL_OUT_ENERGY - 1: "energy"})

_SUMMARY = ["outcome", "t_uplift", "n_impacts", "t_impacts", "n_floor", "theta_max",
            "friction_max", "t_lift_off", "energy_drift", "t_end", "n_steps"]

RollRun = namedtuple("RollRun", _SUMMARY + ["t"] + list(ROLL_COLUMNS))
RollRun.__doc__ = """Result of :func:`roll`.

Summary: outcome (:data:`ROLL_OUTCOMES`), first uplift t_uplift (s; 0 for an initial
tilt, NaN if none), n_impacts and their times t_impacts (s), n_floor of them counted by the
floor rule (passes below 1e-5 theta_c, doc/rolling.md section 4), theta_max (rad),
friction_max (largest |F_t|/N while in contact), t_lift_off (first time N <= 0, s: the model
does not cover it; NaN if never) -- both sampled at the step ends and output times, not
located --, energy_drift (largest |E - E0|/(E0 - m g h) within a free flight, E0 at its
start: relative to the energy above rest), t_end (rest, overturning or limit, s), n_steps.

Histories at the output times t (s): theta, psi, spin (rad), their rates (rad/s), the
contact point x_contact, y_contact and the centre of mass x_g, y_g on the ground (m,
ground frame, G at the origin at t = 0), normal_force N (N), friction_demand |F_t|/N and
energy (kinetic + potential in the ground frame, J). After overturning theta = pi/2 and
the forces are NaN; after a time limit everything is NaN."""

def roll(body, pulse=None, *, accel_x=None, accel_y=None, dt=None, direction_deg=0.0,
         theta0=0.0, psi0=0.0, spin0=0.0, theta_rate0=0.0, psi_rate0=0.0, spin_rate0=0.0,
         e=None, t=None, t_max=None, rtol=1e-10):
    """Rocking with rolling of `body`, a cylinder of :func:`seispulse.cylinder.props` (solid,
    hollow, or custom with j_axis given: the model needs the moment of inertia about the
    axis).

    Excitation: a pulse (:func:`seispulse.pulse.define`, SI) along the horizontal
    direction `direction_deg` (degrees from x), or a record of two components accel_x,
    accel_y (in g = body.g, sampled at dt s, linear in between, 0 after), or none (free
    rocking from the initial state). Initial state at t = 0: theta0 in [0, pi/2) (rad),
    psi0, spin0 (rad) and the rates (rad/s); from rest the body uplifts when |a_g| >
    g tan(theta_c), its rocking plane along a_g. e: restitution in [0, 1] (default body.restitution).

    t: output times (s, ascending); default 1001 points on [0, t_max]. t_max: end of the
    run (s; default the last output time). rtol: step tolerance in [1e-14, 1e-3].
    Returns :class:`RollRun`.
    """
    from .cylinder import _body_args   # seispulse.cylinder imports this module
    args = _body_args(body)
    e_run = body.restitution if e is None else _core.as_scalar("e", e)
    g = body.g
    rec_given = accel_x is not None or accel_y is not None
    if pulse is not None and rec_given:
        raise InvalidInputError("pulse, accel_x: give a pulse or a record, not both")
    params = np.zeros(_f.PULSE_NPARAM)
    ax = ay = np.zeros(1)
    step = 1.0
    if pulse is not None:
        if not isinstance(pulse, Pulse):
            raise InvalidInputError("pulse: must be a seispulse.pulse.Pulse from "
                                    "seispulse.pulse.define()")
        kind, params = pulse.code, np.asarray(pulse.params, float)
    elif rec_given:
        if accel_x is None or accel_y is None:
            raise InvalidInputError("accel_x, accel_y: give both components of the record")
        ax = np.ascontiguousarray(_core.as_float_array("accel_x", accel_x).reshape(-1))
        ay = np.ascontiguousarray(_core.as_float_array("accel_y", accel_y).reshape(-1))
        if ax.size != ay.size:
            raise InvalidInputError(f"accel_y: must have the length of accel_x ({ax.size}), "
                                    f"got {ay.size}")
        if dt is None:
            raise InvalidInputError("dt: the time step (> 0, s) of the record is required")
        step = _core.as_scalar("dt", dt)
        kind = 0
    else:
        kind = -1
    limit = t_max is not None
    t_lim = _core.as_scalar("t_max", t_max) if limit else 0.0
    if t is None:
        if not limit:
            raise InvalidInputError("t, t_max: give the output times t or the end t_max (s)")
        t = np.linspace(0.0, _core.check_positive("t_max", t_lim, " (s)"), 1001)
    grid = np.ascontiguousarray(_core.as_float_array("t", t).reshape(-1))
    state = [_core.as_scalar(name, value) for name, value in (
        ("theta0", theta0), ("psi0", psi0), ("spin0", spin0), ("theta_rate0", theta_rate0),
        ("psi_rate0", psi_rate0), ("spin_rate0", spin_rate0))]
    direction = np.radians(_core.as_scalar("direction_deg", direction_deg))
    rtol = _core.as_scalar("rtol", rtol)
    with _core.HELD_LOCK:
        (hist, n_imp, n_floor, outcome, t_uplift, theta_max, friction_max, t_lift_off,
         energy_drift, t_end, n_steps, stat, msg) = sp_cylinder_roll(
            *args, e_run, kind, params, direction, ax, ay, step, g, *state, int(limit), t_lim,
            rtol, grid)
        impacts = sp_fetch_impacts(n_imp if stat == 0 else 0)
    _core.raise_for_status(stat, msg, rename={"t_grid": "t", "body%e": "body.e",
                                              "body%j_axis": "body.j_axis"})
    columns = [hist[k].copy() for k in range(len(ROLL_COLUMNS))]
    return RollRun(ROLL_OUTCOMES[outcome], float(t_uplift), int(n_imp),
                   impacts, int(n_floor), float(theta_max), float(friction_max),
                   float(t_lift_off), float(energy_drift), float(t_end), int(n_steps),
                   grid.copy(), *columns)


def plot_roll(run, axes=None, title=None):
    """Draw a :class:`RollRun` with matplotlib (an optional dependency): theta(t),
    psi(t) and the path of the contact point on the ground (with the centre of mass).
    axes: three matplotlib axes (default: a new figure). Returns the axes."""
    from .cylinder import _pyplot
    plt = _pyplot("plot_roll")
    if not isinstance(run, RollRun):
        raise InvalidInputError("run: must be a RollRun from roll()")
    if axes is None:
        fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
        if title:
            fig.suptitle(title)
    ax_th, ax_psi, ax_path = axes
    ax_th.plot(run.t, run.theta, label="theta")
    ax_th.set_xlabel("t (s)")
    ax_th.set_ylabel("theta (rad)")
    ax_th.legend(loc="upper right")
    ax_psi.plot(run.t, run.psi, label="psi (heading)")
    ax_psi.set_xlabel("t (s)")
    ax_psi.set_ylabel("psi (rad)")
    ax_psi.legend(loc="best")
    ax_path.plot(run.x_contact, run.y_contact, lw=0.8, label="contact point")
    ax_path.plot(run.x_g, run.y_g, lw=1.2, label="centre of mass")
    ax_path.set_aspect("equal", adjustable="datalim")
    ax_path.set_xlabel("x (m)")
    ax_path.set_ylabel("y (m)")
    ax_path.legend(loc="best")
    return axes
