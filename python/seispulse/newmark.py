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

Flexible sliding masses (doc/flexible.md): :func:`decoupled` and :func:`coupled` model
the sliding mass as a shear beam of height H (one mode, radiation damping, linear or
equivalent-linear soil) as SLAMMER does; ``method='slammer'`` (default) is SLAMMER 1.1's
arithmetic step for step, ``method='exact'`` the exact response to the piecewise-linear
record. :func:`plot_flexible` draws a result.

Units: accelerations and yields in g, time in s, displacements in m, velocities in
m/s. Positive ground acceleration drives positive (downslope) sliding, for the rigid,
decoupled and coupled analyses alike.
"""

from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_fetch_slides, sp_flexible, sp_newmark_incline, sp_newmark_rigid,
                         sp_newmark_rigid_many)
from ._table import TableResult
from .errors import ConvergenceError, InvalidInputError
from .sliding import Slide

__all__ = ["MODES", "METHODS", "SOILS", "STANDARD_GRAVITY", "Flexible", "Incline", "Rigid",
           "Slide", "coupled", "decoupled", "incline", "plot_flexible", "rigid"]

#: Sliding modes: one way downslope, two ways alike, two ways with ky_up.
_MODE_CODES = {"down": _f.NEWMARK_DOWN, "both": _f.NEWMARK_BOTH, "asym": _f.NEWMARK_ASYM}
MODES = tuple(_MODE_CODES)
#: Integration rules.
_METHOD_CODES = {"exact": _f.NEWMARK_EXACT, "slammer": _f.NEWMARK_SLAMMER}
METHODS = tuple(_METHOD_CODES)
#: Soil models of a flexible sliding mass.
_SOIL_CODES = {"linear": _f.SOIL_LINEAR, "equivalent_linear": _f.SOIL_EQUIVALENT_LINEAR}
SOILS = tuple(_SOIL_CODES)
_FLEX_METHOD_CODES = {"exact": _f.FLEX_EXACT, "slammer": _f.FLEX_SLAMMER}
#: Standard gravity (m/s^2), the default g.
STANDARD_GRAVITY = 9.80665

Incline = namedtuple("Incline", ["ky", "ky_up", "k_down", "k_up"])
Incline.__doc__ = """A block on an incline (from :func:`incline`): yield accelerations
downslope ky and upslope ky_up (g; +inf: no sliding that way) and the along-plane
factors k_down, k_up (the slip along the plane is k times the slip of the yield
problem). Pass it to :func:`rigid` as ``incline=``."""


class Rigid(TableResult, namedtuple("Rigid", ["max_disp", "final_disp", "u_max", "u_min",
                                              "max_vel", "t_end", "time", "disp", "vel",
                                              "slides", "ky", "ky_up", "k_down", "k_up"],
                                    defaults=(None, None, None, None))):
    """Result of :func:`rigid` (SI).

    max_disp: largest |u| over time (m); final_disp: u when the block is at rest at the
    end (m, signed, positive downslope); u_max >= 0 and u_min <= 0: the extremes of u (m);
    max_vel: largest |u'| (m/s); t_end: end of the last slide (s from the first sample).
    With ``history=True``: time (s), disp u (m) and vel u' (m/s) at the samples, else None.
    With ``intervals=True``: slides, a list of :class:`seispulse.sliding.Slide` (times s,
    u m, w_peak m/s), else None. For an array of ky the scalar fields are arrays.
    ky (g): the yield(s) of the run, shaped as the results (None with a yield table);
    ky_up (g): the upslope yield(s): ky_up of mode 'asym', ky itself for mode 'both'
    (None for mode 'down'); k_down, k_up (-): the along-plane factors of mode 'asym',
    shaped as the results (None when they are all 1).
    ``print()`` shows one row per run (ky, ky_up, k_down, k_up as they vary);
    :meth:`to_frame` gives that table as a pandas DataFrame."""

    __slots__ = ()
    _COLUMNS = (("ky", "ky", "g"), ("ky_up", "ky_up", "g"), ("k_down", "k_down", "-"),
                ("k_up", "k_up", "-"), ("max_disp", "max_disp", "m"),
                ("final_disp", "final_disp", "m"), ("u_max", "u_max", "m"),
                ("u_min", "u_min", "m"), ("max_vel", "max_vel", "m/s"),
                ("t_end", "t_end", "s"))

    def _table_notes(self):
        notes = []
        if self.time is not None:
            notes.append(f"history: time, disp, vel at {len(self.time)} samples")
        if self.slides is not None:
            notes.append(f"slides: {len(self.slides)} sliding intervals")
        return notes


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
        max_disp (m), final_disp (m), u_max, u_min (m), max_vel (m/s), t_end (s), the
        optional histories and intervals, and ky, ky_up (g) as used; ``print()`` shows a
        table (one row per ky), ``to_frame()`` gives it as a pandas DataFrame.
    """
    rec, step = _core.record_and_step(accel, dt)
    mode = _core.check_choice("mode", mode, MODES)
    method = _core.check_choice("method", method, METHODS)
    g = _core.check_positive("g", g, " (m/s^2)")
    history = _core.check_bool("history", history)
    intervals = _core.check_bool("intervals", intervals)
    table_disp = table_ky = np.zeros(1)   # a dummy row unless ky_table is given
    if ky_table is not None:
        table_disp, table_ky = _table(ky_table, ky, mode, ky_up, k_down, k_up, incline)
        ky = 1.0   # ignored: the table gives the yield
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
                     None, None, None, None, flat[0].reshape(shape),
                     *_upslope(mode, *(f.reshape(shape) for f in flat)))
    scalars = [float(arr[k]) for k in ("ky", "ky_up", "k_down", "k_up")]
    nh = rec.size if history else 1
    with _core.HELD_LOCK:
        (u, w, nslides, max_disp, final_disp, u_max, u_min, max_vel, t_end, stat,
         msg) = sp_newmark_rigid(rec, step, mode_code, *scalars, method_code, g, nh,
                                 int(ky_table is not None), table_disp, table_ky)
        fields = sp_fetch_slides(nslides if stat == 0 and intervals else 0)
    _core.raise_for_status(stat, msg, indexed={"accel": "accel", "ky_disp": "ky_table[0]",
                                               "ky_values": "ky_table[1]"})
    out = _core.slides(Slide, fields) if intervals else None
    time = disp = vel = None
    if history:
        time = np.arange(rec.size) * step
        disp, vel = u, w
    return Rigid(float(max_disp), float(final_disp), float(u_max), float(u_min), float(max_vel),
                 float(t_end), time, disp, vel, out,
                 None if ky_table is not None else scalars[0],
                 *_upslope(mode, *scalars))


def _upslope(mode, ky, ky_up, k_down, k_up):
    """(ky_up, k_down, k_up) of a Rigid result: the upslope yield (g; ky for mode 'both',
    None one way) and the along-plane factors (None unless mode 'asym' sets one /= 1)."""
    if mode == "down":
        return None, None, None
    if mode == "both":
        return ky, None, None
    plain = np.all(np.asarray(k_down) == 1.0) and np.all(np.asarray(k_up) == 1.0)
    return ky_up, None if plain else k_down, None if plain else k_up



def _table(ky_table, ky, mode, ky_up, k_down, k_up, incline):
    """The checked ky_table of :func:`rigid` as two float arrays (disp m, ky g)."""
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
    if disp.size == 0:
        raise InvalidInputError("ky_table: the table needs at least one row")
    return disp, kyv


Flexible = namedtuple("Flexible", ["max_disp", "final_disp", "kmax", "vs_final", "damping_final",
                                   "damping_radiation", "period", "iterations", "converged",
                                   "t_end", "time", "hea", "u_modal", "disp", "vel", "ky",
                                   "ky_up"])
Flexible.__doc__ = """Result of :func:`decoupled` or :func:`coupled` (SI).

max_disp: largest sliding displacement |s| over the run (m); final_disp: s at the end (m;
signed for two-way sliding, positive downslope). SLAMMER publishes |final_disp|; the two
differ only when SLAMMER's coupled trapezoid steps back after an onset (method='slammer',
coupled), where max_disp can exceed it. kmax: the equivalent acceleration (HEA) of largest
|value| of the final decoupled response, with the sign of the HEA of the record as given
(g), for both analyses (SLAMMER's Decoupled convention; SLAMMER's Coupled reports the
opposite sign, and SLAMMER's tables print |kmax|);
vs_final (m/s), damping_final (total: material or the user's, plus radiation) and
damping_radiation (fractions): the properties of the final response; period = 4 H/vs_final
(s); iterations of the equivalent-linear soil (0 for linear) and whether it converged;
t_end: end of the last slide (s from the first sample).
With ``history=True``: time (s), hea (g; for coupled, that of the decoupled response, the
one kmax comes from), u_modal (m, the modal displacement relative to the base, with the sign of
doc/flexible.md (F.30): a positive record acceleration drives it negative), disp s (m) and
vel s' (m/s; both positive downslope) at the samples, else None. ky and ky_up: the yields given (g; with a table, ky is the array of
its yields; ky_up: that of mode 'asym', ky for mode 'both', None for mode 'down'), for
:func:`plot_flexible`."""

def _flexible(analysis, accel, dt, ky, height, vs, vs_base, damping, soil, ref_strain_pct,
              method, g, mode, ky_up, ky_table, max_iter, history, allow_unconverged):
    rec, step = _core.record_and_step(accel, dt)
    for name, value in (("height", height), ("vs", vs), ("vs_base", vs_base)):
        if value is None:
            unit = "m" if name == "height" else "m/s"
            raise InvalidInputError(f"{name}: required ({unit}, > 0)")
    height = _core.as_scalar("height", height)
    vs = _core.as_scalar("vs", vs)
    vs_base = _core.as_scalar("vs_base", vs_base)
    damping = _core.as_scalar("damping", damping)
    ref_strain_pct = _core.as_scalar("ref_strain_pct", ref_strain_pct)
    soil_code = _core.choice_code("soil", soil, _SOIL_CODES)
    method_code = _core.choice_code("method", method, _FLEX_METHOD_CODES)
    mode_code = _core.choice_code("mode", mode, _MODE_CODES)
    g = _core.check_positive("g", g, " (m/s^2)")
    if isinstance(max_iter, (bool, np.bool_)) or not isinstance(max_iter, (int, np.integer)):
        raise InvalidInputError(f"max_iter = {max_iter!r}: must be an integer >= 1")
    max_iter = int(max_iter)
    if max_iter < 1:
        raise InvalidInputError(f"max_iter = {max_iter}: must be an integer >= 1")
    history = _core.check_bool("history", history)
    allow_unconverged = _core.check_bool("allow_unconverged", allow_unconverged)
    if mode == "asym":
        if ky_up is None:
            raise InvalidInputError("ky_up: required for mode='asym' (g, > 0, inf: none)")
        ky_up = _core.as_scalar("ky_up", ky_up)
    elif ky_up is not None:
        raise InvalidInputError(f"ky_up: only for mode='asym' (mode is {mode!r})")
    if ky_table is not None:
        if ky is not None:
            raise InvalidInputError("ky: give either ky or ky_table (a table replaces ky)")
        if not isinstance(ky_table, (tuple, list)) or len(ky_table) != 2:
            raise InvalidInputError("ky_table: must be a pair (disp_m, ky_g) of 1-d arrays")
        table_disp = _core.as_float_array("ky_table[0]", ky_table[0])
        table_ky = _core.as_float_array("ky_table[1]", ky_table[1])
        if table_disp.ndim != 1 or table_ky.ndim != 1 or table_disp.size == 0:
            raise InvalidInputError("ky_table: disp_m and ky_g must be non-empty 1-d arrays")
        if table_disp.size != table_ky.size:
            raise InvalidInputError(f"ky_table: disp_m has {table_disp.size} values, ky_g "
                                    f"{table_ky.size} (must be the same)")
        ky_value = 0.0
        ky_out = table_ky.copy()
    else:
        if ky is None:
            raise InvalidInputError("ky: the yield acceleration (g, > 0) is required "
                                    "(or a ky_table)")
        ky_value = _core.as_scalar("ky", ky)
        ky_out = ky_value
        table_disp = table_ky = np.zeros(1)
    nh = rec.size if history else 1
    (hea, u_modal, s_hist, sdot_hist, max_disp, final_disp, kmax, vs_final, damping_final,
     damping_radiation, period, iterations, converged, t_end, stat, msg) = sp_flexible(
        rec, step, ky_value, analysis, height, vs, vs_base, damping, soil_code, ref_strain_pct,
        max_iter, method_code, g, mode_code, np.inf if ky_up is None else ky_up,
        int(ky_table is not None), table_disp, table_ky, nh)
    if not (stat == _f.SEISPULSE_NO_CONVERGENCE and allow_unconverged):
        _core.raise_for_status(stat, msg, indexed={"accel": "accel", "ky_disp": "ky_table[0]",
                                                   "ky_values": "ky_table[1]"})
    time = None
    if history:
        time = np.arange(rec.size) * step
    else:
        hea = u_modal = s_hist = sdot_hist = None
    return Flexible(float(max_disp), float(final_disp), float(kmax), float(vs_final),
                    float(damping_final), float(damping_radiation), float(period),
                    int(iterations), bool(converged), float(t_end), time, hea, u_modal, s_hist,
                    sdot_hist, ky_out, ky_out if mode == "both" else ky_up)


_FLEXIBLE_DOC = """{summary}

    Parameters
    ----------
    accel : array or seispulse.records.Record
        Ground acceleration (g), samples at t = 0, dt, 2 dt, ... (a Record carries dt).
    dt : float
        Time step (s) > 0.
    ky : float
        Yield acceleration (g) > 0 (inf: no sliding). Leave it out with ky_table.
    height : float
        Height H of the sliding mass (m) > 0.
    vs : float
        Shear-wave velocity of the sliding mass (m/s) > 0 (the small-strain value for
        soil='equivalent_linear').
    vs_base : float
        Shear-wave velocity below the slip surface (m/s) > 0 (radiation damping).
    damping : float
        Viscous damping of the mass (fraction) in [-0.5, 1); the radiation damping
        xi_f = min(0.2, 0.55016 (vs_base/vs)^-0.9904) is added, and the total damping +
        xi_f must be >= 0 (a negative value cancels part of xi_f at most); with
        method='exact' also damping + xi_f < 1. The equivalent-linear soil replaces it by
        its material damping after the first pass.
    soil : {{'linear', 'equivalent_linear'}}
        Linear elastic, or equivalent-linear (hyperbolic G/Gmax, scaled Masing damping).
    ref_strain_pct : float
        Reference strain of the equivalent-linear soil, in PERCENT (0.05 = 0.05 %) > 0.
    method : {{'slammer', 'exact'}}
        SLAMMER 1.1's arithmetic step for step, or the exact response to the
        piecewise-linear record. SLAMMER's coupled arithmetic is unstable for a stiff mass
        on a coarse record: coupled with method='slammer' needs omega dt <= 10 (omega =
        pi vs_final/(2 height), i.e. T >= 0.63 dt), else InvalidInputError naming height.
    g : float
        Gravity (m/s^2) > 0.{mode_doc}
    ky_table : (disp_m, ky_g), optional
        Yield against sliding displacement: disp_m (m) starts at 0 and increases strictly,
        ky_g (g) > 0. SLAMMER's rule (method='slammer') is stepwise: the second row applies
        from the first step at rest, and the next row once the block, at rest, has slid
        as far as the current row's displacement.
    max_iter : int
        Cap of the equivalent-linear iteration (>= 1).
    history : bool
        Return time, hea, u_modal, disp and vel at the samples.
    allow_unconverged : bool
        If the equivalent-linear iteration reaches max_iter: return the last iteration's
        result with converged=False instead of raising ConvergenceError.

    Returns
    -------
    Flexible
    """


def decoupled(accel, dt=None, ky=None, height=None, vs=None, vs_base=None, damping=0.05,
              soil="linear", ref_strain_pct=0.05, method="slammer", g=STANDARD_GRAVITY, *,
              mode="down", ky_up=None, ky_table=None, max_iter=100, history=False,
              allow_unconverged=False):
    return _flexible(1, accel, dt, ky, height, vs, vs_base, damping, soil, ref_strain_pct,
                     method, g, mode, ky_up, ky_table, max_iter, history, allow_unconverged)


def coupled(accel, dt=None, ky=None, height=None, vs=None, vs_base=None, damping=0.05,
            soil="linear", ref_strain_pct=0.05, method="slammer", g=STANDARD_GRAVITY, *,
            ky_table=None, max_iter=100, history=False, allow_unconverged=False):
    return _flexible(2, accel, dt, ky, height, vs, vs_base, damping, soil, ref_strain_pct,
                     method, g, "down", None, ky_table, max_iter, history, allow_unconverged)


decoupled.__doc__ = _FLEXIBLE_DOC.format(
    summary="""Decoupled Newmark analysis of a flexible sliding mass: the modal response of the
    mass on a fixed base gives the equivalent acceleration HEA(t) = a + (2/pi) u''; a rigid
    block driven by HEA slides (doc/flexible.md).""",
    mode_doc="""
    mode : {'down', 'both', 'asym'}
        One-way (downslope) sliding, or two ways (method='exact' only, no ky_table).
    ky_up : float, optional
        Upslope yield (g) > 0 or inf, for mode='asym'.""")
coupled.__doc__ = _FLEXIBLE_DOC.format(
    summary="""Coupled Newmark analysis of a flexible sliding mass (Rathje and Bray): the
    sliding and the modal response are solved together; while the mass slides its base
    carries the yield force (doc/flexible.md). Downslope sliding only.""",
    mode_doc="")


def plot_flexible(result, record=None, ax=None):
    """Draw a :func:`decoupled` or :func:`coupled` result made with ``history=True`` with
    matplotlib (an optional dependency): the HEA (g) with the yield lines (+ky, and -ky_up
    for two-way sliding) and, with ``record`` (the accelerations in g or a Record), the
    ground acceleration, on one axes; the sliding displacement (m) on a second one. ``ax``:
    a pair of axes, or one (the displacement then goes on a twin y axis). Returns the two
    axes. :func:`seispulse.plot.newmark` draws the relative velocity too and returns the
    figure."""
    from . import plot
    return plot._flexible_pair(result, record, ax)
