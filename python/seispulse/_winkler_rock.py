"""Planar rocking of a rigid cylinder or block on tensionless Winkler springs and dashpots
([KH91] circle, [KSR86] block; doc/winkler.md "Dynamics"; Fortran module
``seispulse_winkler_rock``): the dynamic part of :mod:`seispulse.winkler`, re-exported
there.

Two degrees of freedom: the settlement v of the base centre (m, + down) and the tilt theta
(rad; theta > 0 lifts the side s > 0 of the base). The soil pressure is
q = max(0, k delta + c delta') over the part of the base that penetrates, delta = v -
s sin(theta). Units: m, kg, s, N, rad, rad/s, J; k in N/m^3, c in N s/m^3; records in g.
"""

from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from . import cylinder
from ._seispulse import sp_wk_fetch_impacts, sp_wk_map, sp_wk_model, sp_wk_rock
from .errors import InvalidInputError
from .pulse import Pulse

__all__ = ["DAMPING_REFS", "WinklerModel", "model", "OUTCOMES", "COLUMNS", "WinklerRun",
           "simulate", "WinklerMap", "overturning_map", "plot_history", "plot_map"]

#: What xi is the damping ratio of: 'rocking' (c = 2 xi I_O omega_r/I, omega_r^2 =
#: (k I - m g h)/I_O, the small-rotation full-contact rocking mode) or 'vertical'
#: (c = 2 xi sqrt(k m/A), the vertical mode).
DAMPING_REFS = {"rocking": _f.DAMP_ROCKING, "vertical": _f.DAMP_VERTICAL}

#: Outcomes of a run by code; the classes of a map are the codes 0..3 (-1 undecided).
OUTCOMES = _core.by_code({_f.WR_RUN_SAFE: "safe",
                          _f.WR_RUN_OVERTURN_NO_IMPACT: "overturn_no_impact",
                          _f.WR_RUN_OVERTURN_ONE_IMPACT: "overturn_one_impact",
                          _f.WR_RUN_OVERTURN_IMPACTS: "overturn_many_impacts",
                          _f.WR_RUN_TIME_LIMIT: "time_limit"})

#: The histories of a run, in the order of the Fortran columns WR_OUT_*.
COLUMNS = _core.by_code({
    _f.WR_OUT_V - 1: "v", _f.WR_OUT_THETA - 1: "theta", _f.WR_OUT_V_RATE - 1: "v_rate",
    _f.WR_OUT_THETA_RATE - 1: "theta_rate", _f.WR_OUT_WIDTH - 1: "width",
    _f.WR_OUT_NORMAL - 1: "normal", _f.WR_OUT_MOMENT - 1: "moment",
    _f.WR_OUT_ACCEL - 1: "accel", _f.WR_OUT_ENERGY - 1: "energy", _f.WR_OUT_WORK - 1: "work",
    _f.WR_OUT_DISSIPATED - 1: "dissipated"})

WinklerModel = namedtuple("WinklerModel", ["body", "footing", "k", "alpha", "k_method",
                                           "reading", "c", "theta_overturn"])
WinklerModel.__doc__ = """A rigid body on tensionless Winkler soil, from :func:`model`.

body: the :class:`seispulse.cylinder.Body` (mass, h, J_G, g; its rigid theta_c and p set
the axes of the dimensionless maps); footing: 'circle' (radius body.r) or 'rectangle'
(half-width body.r, half-length alpha); k: full-contact Winkler modulus (N/m^3); alpha:
half-length of a rectangle (m; NaN for a circle); k_method: 'constant' or 'varying';
reading: the shape factor of a varying k under a circle ('long' or 'short'); c: distributed
dashpot (N s/m^3); theta_overturn: the static overturning angle of the
same body on the same soil (rad, the first zero of the Winkler pushover's imposed
moment)."""

_SUMMARY = ["outcome", "n_impacts", "t_impacts", "impact_normal_peak", "impact_moment_peak",
            "theta_max", "t_uplift", "t_lift_off", "t_touch_down", "t_overturn", "normal_max",
            "energy_error", "t_end", "t_safe", "n_steps"]

WinklerRun = namedtuple("WinklerRun", _SUMMARY + ["t"] + list(COLUMNS))
WinklerRun.__doc__ = """Result of :func:`simulate`.

Summary: outcome (:data:`OUTCOMES`); n_impacts, the returns of theta through 0 after an
uplift, with their times t_impacts (s) and the peak normal force impact_normal_peak (N)
and foundation moment impact_moment_peak (N m) of each; theta_max, the largest |theta|
(rad); t_uplift, the first partial contact, t_lift_off, the first complete loss of
contact, and t_touch_down, the first contact after it (s; NaN if none); t_overturn, the
last outward crossing of the static overturning angle before overturning (s; NaN if the
body stays); normal_max, the largest normal force (N); energy_error, the largest
|E + D - E0 - W_in| relative to the energy scale of the run (-); t_end (s); t_safe, when
the energy criterion (doc/winkler.md (W.55)) decided the body is safe (s; NaN if not);
n_steps of the integrator.

Histories at the output times t (s): v, settlement of the base centre (m, + down); theta
(rad; > 0 lifts the s > 0 side of the base); v_rate (m/s); theta_rate (rad/s); width, the
contact width (m); normal, the normal force N (N); moment, the foundation moment about the
base centre (N m, in the sense of theta: restoring, so of the opposite sign to theta);
accel, the ground acceleration (m/s^2; a_g > 0 drives theta > 0); energy, kinetic +
potential + spring (J); work, the input work (J); dissipated, contact work minus spring
energy: the dashpots and the tension cut-off (J)."""

WinklerMap = namedtuple("WinklerMap", ["classes", "rigid", "difference"])
WinklerMap.__doc__ = """An overturning map on Winkler soil (:func:`overturning_map`):
classes on the soil, rigid, the map of the same body on rigid ground
(:func:`seispulse.cylinder.overturning_map`, with its restitution) and difference, their
:func:`seispulse.cylinder.map_difference` (codes :data:`seispulse.cylinder.MAP_DIFF`: 1
only on the soil, 2 only on rigid ground); int arrays of shape (len(y), len(x)); rigid
and difference are None without compare_rigid."""


def _model_args(m):
    """The defining numbers of a model for the wrappers (see _wrap_winkler_rock.f90)."""
    if not isinstance(m, WinklerModel):
        raise InvalidInputError("model: must be a seispulse.winkler.WinklerModel (from "
                                "seispulse.winkler.model)")
    from .winkler import K_METHODS, READINGS
    alpha = 0.0 if m.footing == "circle" else m.alpha
    return (*cylinder._body_args(m.body, "model.body"), m.k, alpha,
            _core.choice_code("model.k_method", m.k_method, K_METHODS),
            _core.choice_code("model.reading", m.reading, READINGS), m.c)


def model(body, k, alpha=None, k_method="constant", xi=None, damping_ref="rocking", c=None,
          reading="long"):
    """A rigid body on tensionless Winkler springs (modulus k, N/m^3) and dashpots: body a
    cylinder (:func:`seispulse.cylinder.props`: circular footing of radius body.r) or a
    block (:func:`seispulse.cylinder.block_props`: rectangular footing of half-width
    body.r and half-length alpha, m, required); k_method 'constant' or 'varying' (with the
    shape factor of `reading`, 'long' or 'short', under a circle). The
    dashpot: c (N s/m^3, >= 0) given, or from the damping ratio xi (>= 0, e.g. 0.003 as
    [AD11]) of the mode damping_ref (:data:`DAMPING_REFS`); neither: c = 0. Returns
    :class:`WinklerModel` (with c and the static overturning angle)."""
    from .winkler import K_METHODS, READINGS
    cylinder._check_body(body)
    block = body.shape == "block"
    if block and alpha is None:
        raise InvalidInputError("alpha: the half-length (m, > 0) of the block's base is "
                                "required")
    if not block and alpha is not None:
        raise InvalidInputError("alpha: only a block (block_props) has a half-length; a "
                                "cylinder's base is the circle of radius body.r")
    if xi is not None and c is not None:
        raise InvalidInputError("xi, c: give the damping ratio xi or the dashpot c, not both")
    kk = _core.as_scalar("k", k)
    aa = _core.as_scalar("alpha", alpha) if block else 0.0
    method = _core.choice_code("k_method", k_method, K_METHODS)
    read = _core.choice_code("reading", reading, READINGS)
    ref = _core.choice_code("damping_ref", damping_ref, DAMPING_REFS)
    has_c = c is not None or xi is None
    cc = _core.as_scalar("c", c) if c is not None else 0.0
    xx = _core.as_scalar("xi", xi) if xi is not None else 0.0
    footing, c_out, theta_ot, stat, msg = sp_wk_model(
        *cylinder._body_args(body), kk, aa, method, read, int(xi is not None), xx, ref,
        int(has_c), cc)
    _core.raise_for_status(stat, msg)
    name = "circle" if footing == _f.FOOTING_CIRCLE else "rectangle"
    return WinklerModel(body, name, kk, aa if block else float("nan"), k_method, reading,
                        float(c_out), float(theta_ot))


def simulate(model, pulse=None, *, accel=None, dt=None, g=None, t=None, t_max=None, v0=None,
             theta0=0.0, v_rate0=0.0, theta_rate0=0.0, rtol=None):
    """Planar rocking of a :class:`WinklerModel` under a pulse
    (:func:`seispulse.pulse.define`, SI) or a record: accel in g (samples at t = i dt, dt
    in s, linear in between, zero after; or a :class:`seispulse.records.Record`), g the
    m/s^2 of one g of the record (default the body's g, 9.80665 unless given); neither:
    free motion from the initial state. Initial state at t = 0: v0 (m, default the static
    settlement W/(k A)), theta0 (rad), v_rate0 (m/s), theta_rate0 (rad/s). t: output times
    (s, ascending; default 1001 points on [0, t_max]); t_max: end of the run (s; default
    the last output time; inf: until the outcome is known, with t given); the run also
    ends at overturning (later outputs: theta = +-pi/2, the rest NaN), or after its last
    output once the energy criterion has decided the body is safe. rtol: the integrator's relative tolerance
    (default 1e-9). Returns :class:`WinklerRun`."""
    args = _model_args(model)
    if pulse is not None and accel is not None:
        raise InvalidInputError("pulse, accel: give a pulse or a record, not both")
    params = np.zeros(_f.PULSE_NPARAM)
    rec, step = np.zeros(1), 1.0
    g_rec = model.body.g if g is None else _core.check_positive("g", g, " (m/s^2)")
    if pulse is not None:
        if not isinstance(pulse, Pulse):
            raise InvalidInputError("pulse: must be a seispulse.pulse.Pulse from "
                                    "seispulse.pulse.define()")
        kind, params = pulse.code, np.asarray(pulse.params, float)
    elif accel is not None:
        rec, step = _core.record_and_step(accel, dt)
        kind = 0
    else:
        kind = -1
    limit = t_max is not None
    t_lim = _core.as_scalar("t_max", t_max) if limit else 0.0
    if not t_lim > 0.0 and limit:
        raise InvalidInputError(f"t_max = {t_lim!r}: must be > 0 (s)")
    if t is None:
        if not (limit and np.isfinite(t_lim)):
            raise InvalidInputError("t, t_max: give the output times t or a finite end "
                                    "t_max (s)")
        t = np.linspace(0.0, t_lim, 1001)
    grid = np.ascontiguousarray(_core.as_float_array("t", t).reshape(-1))
    state = [_core.as_scalar(name, value) for name, value in (
        ("theta0", theta0), ("v_rate0", v_rate0), ("theta_rate0", theta_rate0))]
    has_v0 = v0 is not None
    vv = _core.as_scalar("v0", v0) if has_v0 else 0.0
    has_rtol = rtol is not None
    rr = _core.as_scalar("rtol", rtol) if has_rtol else 0.0
    with _core.HELD_LOCK:
        hist, outcome, n_imp, n_steps, summary, stat, msg = sp_wk_rock(
            *args, kind, params, rec, step, g_rec, int(has_v0), vv, *state, int(limit), t_lim,
            int(has_rtol), rr, grid)
        impacts = sp_wk_fetch_impacts(n_imp if stat == 0 else 0)
    _core.raise_for_status(stat, msg, rename={"t_grid": "t", "g_rec": "g"},
                           indexed={"accel": "accel", "t_grid": "t"})
    columns = [np.array(hist[j]) for j in range(len(COLUMNS))]
    theta_max, *middle, t_end, t_safe = (float(s) for s in summary)
    return WinklerRun(OUTCOMES[outcome], int(n_imp), np.array(impacts[:, 0]),
                      np.array(impacts[:, 1]), np.array(impacts[:, 2]), theta_max, *middle,
                      t_end, t_safe, int(n_steps), grid.copy(), *columns)


def overturning_map(model, kind, x, y, axes="dimensionless", compare_rigid=True, rtol=None,
                    **shape):
    """Overturning map of a :class:`WinklerModel` under a pulse family (kind and shape as
    in :func:`seispulse.cylinder.overturning_map`) on the axes 'dimensionless' (x =
    omega_p/p, y = a_p/(g tan theta_c), with the body's rigid p and theta_c, as the rigid
    map) or 'dimensional' (x = f_p in Hz, the dominant frequency of a Ricker wavelet;
    y = PGA in g). compare_rigid: also the rigid-ground map of the same body and the
    difference. Returns :class:`WinklerMap`."""
    args = _model_args(model)
    axes_code = _core.choice_code("axes", axes, cylinder.MAP_AXES)
    compare_rigid = _core.check_bool("compare_rigid", compare_rigid)
    tpl = cylinder._template(kind, shape)
    xv, yv = cylinder._vector("x", x), cylinder._vector("y", y)
    has_rtol = rtol is not None
    classes, stat, msg = sp_wk_map(*args, tpl.code, tpl.params, axes_code, int(has_rtol),
                                   _core.as_scalar("rtol", rtol) if has_rtol else 0.0, xv, yv)
    _core.raise_for_status(stat, msg, indexed=("x", "y"))
    classes = np.array(classes)
    if not compare_rigid:
        return WinklerMap(classes, None, None)
    rigid = cylinder.overturning_map(model.body, kind, xv, yv, axes, **shape)
    return WinklerMap(classes, rigid, cylinder.map_difference(classes, rigid))


# ------------------------------------------------------------------ plots

def plot_history(run, model=None, axes=None, title=None):
    """Draw a :class:`WinklerRun` with matplotlib (an optional dependency): theta (rad),
    the settlement v (m) and the contact width (m) against t (s), the impacts marked;
    with the model, the static overturning angle dashed and the full width of the base.
    axes: three matplotlib axes (default: a new figure). Returns the axes."""
    from .winkler import _pyplot
    if not isinstance(run, WinklerRun):
        raise InvalidInputError("run: must be a WinklerRun from simulate")
    plt = _pyplot("plot_history")
    if axes is None:
        fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
        fig.suptitle(title or f"outcome: {run.outcome}")
    ax_th, ax_v, ax_w = axes
    ax_th.plot(run.t, run.theta, color="C0", label="theta(t)")
    ax_v.plot(run.t, run.v, color="C1", label="v(t), + down")
    ax_w.plot(run.t, run.width, color="C2", label="contact width")
    for ax in axes:
        if run.n_impacts:
            for ti in run.t_impacts:
                ax.axvline(ti, color="k", linewidth=0.5, alpha=0.5)
    if run.n_impacts:
        ax_th.plot(run.t_impacts, np.zeros(run.n_impacts), "k|", markersize=10,
                   label="impacts")
    if model is not None:
        _model_args(model)
        for s in (1, -1):
            ax_th.axhline(s * model.theta_overturn, color="0.5", linestyle="--",
                          label="static overturning" if s > 0 else None)
        ax_w.axhline(2.0 * model.body.r, color="0.5", linestyle="--", label="full width")
    ax_th.set_ylabel("theta (rad)")
    ax_v.set_ylabel("v (m)")
    ax_w.set_ylabel("contact width (m)")
    ax_w.set_xlabel("t (s)")
    for ax in axes:
        ax.legend(loc="upper right", fontsize="small")
    return axes


def plot_map(wmap, x, y, axes="dimensionless", ax=None, title=None):
    """Draw a :class:`WinklerMap` (or a bare class array) with matplotlib: the classes on
    Winkler soil in the colours of :func:`seispulse.cylinder.plot_overturning_map` and,
    when the map has its rigid-ground companion, the boundary of the rigid map's
    overturning region (black line). x, y, axes: those of :func:`overturning_map`.
    Returns the axes."""
    classes = wmap.classes if isinstance(wmap, WinklerMap) else wmap
    ax = cylinder.plot_overturning_map(classes, x, y, axes=axes, ax=ax, title=title)
    if isinstance(wmap, WinklerMap) and wmap.rigid is not None:
        overturns = (np.asarray(wmap.rigid) > 0).astype(float)
        if 0.0 < overturns.mean() < 1.0:
            ax.contour(np.asarray(x, float), np.asarray(y, float), overturns, levels=[0.5],
                       colors="k", linewidths=1.2)
        from matplotlib.lines import Line2D
        legend = ax.get_legend()
        handles = list(getattr(legend, "legend_handles", None) or legend.legendHandles)
        handles.append(Line2D([], [], color="k", label="rigid ground: overturning boundary"))
        ax.legend(handles=handles, loc="upper right", fontsize="small", framealpha=0.9)
    return ax
