"""Newmark rigid-block sliding on accelerograms.

:func:`rigid` slides a rigid block on a record: one way (downslope, as SLAMMER does),
two ways with the same yield, or with different yields down and up the slope; with
:func:`incline` the yields and along-plane factors come from the slope and friction of
a real incline (doc/sliding.md Eq. 1.31, section 7).

Two integration rules: ``method='exact'`` (default) takes the acceleration as
piecewise linear between samples and integrates each step exactly, with onsets and
stops located inside the step (after the last sample the ground is at rest and a
sliding block decelerates to a stop); ``method='slammer'`` is SLAMMER 1.1's rigorous
rigid loop step for step (trapezoidal rule, g = 980.665 cm/s^2, the block stops when
the relative velocity reaches zero, the record ends at its last sample).

Units: accelerations and yields in g, time in s, displacements in m, velocities in
m/s. Positive ground acceleration drives positive (downslope) sliding.
"""

from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_fetch_slides, sp_newmark_incline, sp_newmark_rigid,
                         sp_newmark_rigid_many, sp_newmark_rigid_table)
from .errors import InvalidInputError
from .sliding import Slide

__all__ = ["MODES", "METHODS", "STANDARD_GRAVITY", "Incline", "Rigid", "Slide", "incline",
           "rigid"]

#: Sliding modes: one way downslope, two ways alike, two ways with ky_up.
_MODE_CODES = {"down": _f.NEWMARK_DOWN, "both": _f.NEWMARK_BOTH, "asym": _f.NEWMARK_ASYM}
MODES = tuple(_MODE_CODES)
#: Integration rules.
_METHOD_CODES = {"exact": _f.NEWMARK_EXACT, "slammer": _f.NEWMARK_SLAMMER}
METHODS = tuple(_METHOD_CODES)
#: Standard gravity (m/s^2), the default g.
STANDARD_GRAVITY = 9.80665

Incline = namedtuple("Incline", ["ky", "ky_up", "k_down", "k_up"])
Incline.__doc__ = """A block on an incline (from :func:`incline`): yield accelerations
downslope ky and upslope ky_up (g; +inf: no sliding that way) and the along-plane
factors k_down, k_up (the slip along the plane is k times the slip of the yield
problem). Pass it to :func:`rigid` as ``incline=``."""

Rigid = namedtuple("Rigid", ["max_disp", "final_disp", "u_max", "u_min", "max_vel", "t_end",
                             "time", "disp", "vel", "slides"])
Rigid.__doc__ = """Result of :func:`rigid` (SI).

max_disp: largest |u| over time (m); final_disp: u when the block is at rest at the
end (m, signed, positive downslope); u_max >= 0 and u_min <= 0: the extremes of u (m);
max_vel: largest |u'| (m/s); t_end: end of the last slide (s from the first sample).
With ``history=True``: time (s), disp u (m) and vel u' (m/s) at the samples, else None.
With ``intervals=True``: slides, a list of :class:`seispulse.sliding.Slide` (times s,
u m, w_peak m/s), else None. For an array of ky the scalar fields are arrays."""


def incline(mu, slope_deg, xi_deg=0.0, along_plane=True):
    """Yields and along-plane factors of a block with friction coefficient mu on an
    incline of slope_deg (degrees, below the friction angle atan(mu)) shaken at xi_deg
    to the horizontal (the record is that component, positive downhill): Eq. 1.31
    with A_g = 1 g. ``along_plane=False`` sets the factors to 1 (the yield problem's
    slip, as SLAMMER reports it).

    Returns
    -------
    Incline
    """
    mu = _core.as_scalar("mu", mu)
    slope_deg = _core.as_scalar("slope_deg", slope_deg)
    xi_deg = _core.as_scalar("xi_deg", xi_deg)
    along_plane = _core.check_bool("along_plane", along_plane)
    ky, ky_up, k_down, k_up, stat, msg = sp_newmark_incline(mu, slope_deg, xi_deg,
                                                            int(along_plane))
    _core.raise_for_status(stat, msg)
    return Incline(ky=float(ky), ky_up=float(ky_up), k_down=float(k_down), k_up=float(k_up))


def rigid(accel, dt=None, ky=None, mode="down", ky_up=None, method="exact",
          g=STANDARD_GRAVITY, *, k_down=1.0, k_up=1.0, incline=None, history=False,
          intervals=False, ky_table=None):
    """Rigid-block (Newmark) sliding displacement on an accelerogram.

    Parameters
    ----------
    accel : array or seispulse.records.Record
        Ground acceleration (g), samples at t = 0, dt, 2 dt, ... (a Record carries dt).
    dt : float
        Time step (s) > 0.
    ky : float or 1-d array
        Yield acceleration for downslope sliding (g) > 0. An array gives one result per
        value (scalar fields become arrays; no histories or intervals).
    mode : {'down', 'both', 'asym'}
        'down': one-way sliding (SLAMMER's rigid analysis); 'both': two-way with ky both
        ways; 'asym': two-way with ky down and ky_up up (and factors k_down, k_up).
    ky_up : float or array, optional
        Upslope yield (g) > 0 or inf, for mode='asym' (required there).
    method : {'exact', 'slammer'}
        Exact piecewise-linear integration, or SLAMMER 1.1's loop step for step.
    g : float
        Gravity (m/s^2) > 0.
    k_down, k_up : float
        Along-plane factors for mode='asym' (> 0; 1 leaves them out).
    incline : Incline, optional
        From :func:`incline`: sets mode='asym' and ky, ky_up, k_down, k_up (give none
        of them then).
    history : bool
        Return time, disp and vel at the samples.
    intervals : bool
        Return the sliding intervals.
    ky_table : (disp_m, ky_g), optional
        A yield that depends on the sliding displacement, instead of ky (mode 'down' only):
        displacements (m, first 0, strictly increasing) and yields (g, > 0); ky(u) is
        interpolated linearly, constant beyond the last row. 'exact' applies it at every
        instant, 'slammer' as SLAMMER's RigidBlock (after each step, at u). With
        ``method='exact'`` the peak speeds (max_vel, w_peak) are taken at the samples and
        events only.

    Returns
    -------
    Rigid
        max_disp (m), final_disp (m), u_max, u_min (m), max_vel (m/s), t_end (s), and the
        optional histories and intervals.
    """
    rec, step = _core.record_and_step(accel, dt)
    mode = _core.check_choice("mode", mode, MODES)
    method = _core.check_choice("method", method, METHODS)
    g = _core.check_positive("g", g, " (m/s^2)")
    history = _core.check_bool("history", history)
    intervals = _core.check_bool("intervals", intervals)
    if ky_table is not None:
        return _rigid_table(rec, step, ky, mode, ky_up, method, g, k_down, k_up, incline,
                            history, intervals, ky_table)
    if incline is not None:
        if not isinstance(incline, Incline):
            raise InvalidInputError("incline: must be the result of seispulse.newmark.incline()")
        if ky is not None or ky_up is not None or k_down != 1.0 or k_up != 1.0:
            raise InvalidInputError("incline: give either incline or ky, ky_up, k_down, k_up")
        if mode not in ("down", "asym"):
            raise InvalidInputError(f"mode = {mode!r}: an incline is asymmetric, use 'asym'")
        mode = "asym"
        ky, ky_up, k_down, k_up = incline
    if ky is None:
        raise InvalidInputError("ky: the yield acceleration (g, > 0) is required")
    if mode == "asym":
        if ky_up is None:
            raise InvalidInputError("ky_up: required for mode='asym' (g, > 0, inf: none)")
    elif ky_up is not None:
        raise InvalidInputError(f"ky_up: only for mode='asym' (mode is {mode!r})")
    shape, arr = _core.broadcast(ky=ky, ky_up=np.inf if ky_up is None else ky_up,
                                 k_down=k_down, k_up=k_up)
    mode_code = _MODE_CODES[mode]
    method_code = _METHOD_CODES[method]
    if shape != ():
        if history or intervals:
            raise InvalidInputError("history, intervals: only for a single ky")
        flat = [_core.flat(arr[k], shape) for k in ("ky", "ky_up", "k_down", "k_up")]
        max_disp, final_disp, u_max, u_min, max_vel, t_end, stat, msg = sp_newmark_rigid_many(
            rec, step, mode_code, *flat, method_code, g)
        _core.raise_for_status(stat, msg, indexed=("accel",))
        return Rigid(max_disp.reshape(shape), final_disp.reshape(shape), u_max.reshape(shape),
                     u_min.reshape(shape), max_vel.reshape(shape), t_end.reshape(shape),
                     None, None, None, None)
    scalars = [float(arr[k]) for k in ("ky", "ky_up", "k_down", "k_up")]
    nh = rec.size if history else 1
    with _core.HELD_LOCK:
        (u, w, nslides, max_disp, final_disp, u_max, u_min, max_vel, t_end, stat,
         msg) = sp_newmark_rigid(rec, step, mode_code, *scalars, method_code, g, nh)
        fields = sp_fetch_slides(nslides if stat == 0 and intervals else 0)
    _core.raise_for_status(stat, msg, indexed=("accel",))
    out = _core.slides(Slide, fields) if intervals else None
    time = disp = vel = None
    if history:
        time = np.arange(rec.size) * step
        disp, vel = u, w
    return Rigid(float(max_disp), float(final_disp), float(u_max), float(u_min), float(max_vel),
                 float(t_end), time, disp, vel, out)


def _rigid_table(rec, step, ky, mode, ky_up, method, g, k_down, k_up, incline, history,
                 intervals, ky_table):
    """:func:`rigid` with ky_table (checked arguments: rec, step, mode, method, g, flags)."""
    if ky is not None or ky_up is not None or incline is not None or k_down != 1.0 \
            or k_up != 1.0:
        raise InvalidInputError("ky_table: give either ky_table or ky (and no ky_up, k_down, "
                                "k_up, incline)")
    if mode != "down":
        raise InvalidInputError(f"mode = {mode!r}: a yield table (ky_table) needs mode='down'")
    try:
        disp, kyv = ky_table
    except (TypeError, ValueError):
        raise InvalidInputError("ky_table: must be a pair (disp_m, ky_g) of 1-d arrays") \
            from None
    disp = np.atleast_1d(np.asarray(disp, dtype=float))
    kyv = np.atleast_1d(np.asarray(kyv, dtype=float))
    if disp.ndim != 1 or kyv.ndim != 1:
        raise InvalidInputError("ky_table: must be a pair (disp_m, ky_g) of 1-d arrays")
    if disp.size != kyv.size:
        raise InvalidInputError(f"ky_table: {disp.size} displacements but {kyv.size} yields")
    nh = rec.size if history else 1
    with _core.HELD_LOCK:
        (u, w, nslides, max_disp, final_disp, u_max, u_min, max_vel, t_end, stat,
         msg) = sp_newmark_rigid_table(rec, step, disp, kyv, _METHOD_CODES[method], g, nh)
        fields = sp_fetch_slides(nslides if stat == 0 and intervals else 0)
    _core.raise_for_status(stat, msg, indexed={"accel": "accel", "ky_disp": "ky_table[0]",
                                                 "ky_values": "ky_table[1]"})
    out = _core.slides(Slide, fields) if intervals else None
    time = disp_h = vel = None
    if history:
        time = np.arange(rec.size) * step
        disp_h, vel = u, w
    return Rigid(float(max_disp), float(final_disp), float(u_max), float(u_min), float(max_vel),
                 float(t_end), time, disp_h, vel, out)
