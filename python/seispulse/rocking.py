"""Rocking and overturning of free-standing rigid blocks (chapter 2 of Ref. [GR],
corrected; Fortran modules ``seispulse_rocking_closed`` and ``seispulse_rocking_sim``).

Linearized closed forms under the half-cycle exponential pulse, dimensionless as in the
chapter: ``f = p t_d`` (the printed ``f = p/t_d`` is an erratum), ``eta = alpha /
alpha_g`` with ``alpha_g = A_g / g``, ``beta`` the pulse shape (-inf box, 0 triangle,
+inf spike), ``tau = t / t_d``, ``psi = theta / alpha`` and ``dpsi = (dtheta/dt) /
(alpha p)``. Regions (doc/rocking.md section 3): 'no_rocking' (eta >= 1), 'O1', 'O2', 'O3'
(overturning without impact: during the rising branch, the falling branch, after the
pulse) and 'S1', 'S2' (stable, maximum during or after the pulse).

The nonlinear model (Housner's Eqs. 2.5/2.6, or the linearized 2.7) runs under any
pulse of :mod:`seispulse.pulse` or a sampled accelerogram with impacts and restitution
(:func:`simulate`), and overturning maps classify whole grids (:func:`overturning_map`).

Parameters of the closed forms broadcast like numpy ufuncs; scalars in give Python
scalars out.
"""

from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_fetch_impacts, sp_overturn_boundary, sp_overturn_boundary_inverse,
                         sp_overturning_map, sp_rock, sp_rocking_block, sp_rocking_extremes,
                         sp_rocking_rect_normalized, sp_rocking_response, sp_rocking_summary,
                         sp_s1_s2_boundary, sp_stability_wall, sp_stability_wall_inverse,
                         sp_uplift_time)
from .errors import InvalidInputError
from .pulse import STANDARD_GRAVITY, _excitation, define
from .records import _unit_code

__all__ = ["REGIONS", "Response", "Summary", "uplift_time", "response", "summary",
           "extremes", "classify", "critical_time", "time_of_max", "max_rotation", "impact_time",
           "stability_wall", "stability_wall_inverse", "min_overturning_amplitude",
           "overturn_boundary", "overturn_boundary_inverse", "s1_s2_boundary",
           "rectangle_normalized", "Block", "rectangular_block", "symmetric_block",
           "OUTCOMES", "RockingRun", "simulate", "MAP_CLASSES", "overturning_map",
           "plot_overturning_map"]

#: Regions of the (f, eta) plane, by code.
REGIONS = _core.by_code({_f.ROCK_NONE: "no_rocking", _f.ROCK_O1: "O1", _f.ROCK_O2: "O2",
                         _f.ROCK_O3: "O3", _f.ROCK_S1: "S1", _f.ROCK_S2: "S2"})

Response = namedtuple("Response", ["psi", "dpsi"])
Response.__doc__ = """First excursion: psi = theta/alpha and dpsi = (dtheta/dt)/(alpha p)."""

Summary = namedtuple("Summary", ["region", "tau_up", "tau_c", "tau_m", "psi_max", "tau_i"])
Summary.__doc__ = """Everything of the first excursion: region, uplift tau_up, critical
(overturning) time tau_c (O regions, else NaN), time of the maximum tau_m and first
impact tau_i (S regions, else NaN), psi_max = theta_max/alpha (0 without rocking,
+inf when the block overturns). Times are t/t_d."""

# Each curve: its wrapper and the extra arguments after (x, beta) (at_end of the overturn
# boundaries).
_CURVES = {"uplift": (sp_uplift_time,), "wall": (sp_stability_wall,),
           "wall_inverse": (sp_stability_wall_inverse,), "end": (sp_overturn_boundary, 1),
           "mid": (sp_overturn_boundary, 0), "end_inverse": (sp_overturn_boundary_inverse, 1),
           "mid_inverse": (sp_overturn_boundary_inverse, 0), "s1_s2": (sp_s1_s2_boundary,)}


def _curve(which, x_name, x, beta, rename=None):
    shape, arr = _core.broadcast(**{x_name: x, "beta": beta})
    run, *extra = _CURVES[which]
    y, stat, msg = run(_core.flat(arr[x_name], shape), _core.flat(arr["beta"], shape), *extra)
    _core.raise_for_status(stat, msg, rename)
    return _core.shaped(shape, y)[0]


def uplift_time(eta, beta):
    """Uplift (rocking onset) time tau_up = t_up/t_d (Eq. 2.4); NaN for eta >= 1."""
    return _curve("uplift", "eta", eta, beta)


def response(tau, f, eta, beta):
    """psi = theta/alpha and dpsi = (dtheta/dt)/(alpha p) of the first excursion
    (Eqs. 2.10-2.15 in stable form): 0 before uplift, NaN after the first impact."""
    shape, arr = _core.broadcast(tau=tau, f=f, eta=eta, beta=beta)
    psi, dpsi, stat, msg = sp_rocking_response(*(_core.flat(arr[k], shape)
                                                 for k in ("tau", "f", "eta", "beta")))
    _core.raise_for_status(stat, msg)
    return Response(*_core.shaped(shape, psi, dpsi))


def summary(f, eta, beta):
    """Region, tau_up, tau_c, tau_m, psi_max and tau_i in one pass (:class:`Summary`)."""
    shape, arr = _core.broadcast(f=f, eta=eta, beta=beta)
    region, out, stat, msg = sp_rocking_summary(*(_core.flat(arr[k], shape)
                                                  for k in ("f", "eta", "beta")))
    _core.raise_for_status(stat, msg)
    cols = _core.shaped(shape, *(np.ascontiguousarray(out[:, j]) for j in range(5)))
    return Summary(_core.names(REGIONS, region, shape), *cols)


def extremes(f, eta, beta):
    """(region, psi_max) from one evaluation per case: the fast path of :func:`classify`
    and :func:`max_rotation` for many cases."""
    shape, arr = _core.broadcast(f=f, eta=eta, beta=beta)
    region, psi_max, stat, msg = sp_rocking_extremes(*(_core.flat(arr[k], shape)
                                                       for k in ("f", "eta", "beta")))
    _core.raise_for_status(stat, msg)
    return _core.names(REGIONS, region, shape), _core.shaped(shape, psi_max)[0]


def classify(f, eta, beta):
    """'no_rocking', 'O1', 'O2', 'O3', 'S1' or 'S2' (doc/rocking.md section 3)."""
    return extremes(f, eta, beta)[0]


def critical_time(f, eta, beta):
    """Time tau_c at which theta reaches alpha (O regions; NaN otherwise)."""
    return summary(f, eta, beta).tau_c


def time_of_max(f, eta, beta):
    """Time of the maximum rotation tau_m (Eqs. 2.23-2.26; S regions, NaN otherwise)."""
    return summary(f, eta, beta).tau_m


def max_rotation(f, eta, beta):
    """theta_max/alpha: 0 without rocking, +inf when the block overturns."""
    return extremes(f, eta, beta)[1]


def impact_time(f, eta, beta):
    """Time of the first impact tau_i (corrected Eqs. 2.32-2.36; S regions, else NaN)."""
    return summary(f, eta, beta).tau_i


def stability_wall(f, beta):
    """eta_w(f, beta) (Eq. 2.20; 2.21 rectangle, 2.22 triangle): the block overturns for
    eta < eta_w."""
    return _curve("wall", "f", f, beta)


def min_overturning_amplitude(f, beta):
    """Minimum overturning amplitude alpha_g,min/alpha = 1/eta_w(f, beta)."""
    return 1.0 / stability_wall(f, beta)


def stability_wall_inverse(eta, beta):
    """f on the stability wall for a given eta (0 < eta < 1)."""
    return _curve("wall_inverse", "eta", eta, beta)


def _check_at(at):
    return _core.check_choice("at", at, ("end", "mid"))


def overturn_boundary(f, beta, at="end"):
    """eta on the boundary of overturning by the end of the pulse (at='end', corrected
    Eq. 2.16a, O2/O3) or by mid-pulse (at='mid', Eq. 2.16b, O1/O2)."""
    return _curve(_check_at(at), "f", f, beta)


def overturn_boundary_inverse(eta, beta, at="end"):
    """f on :func:`overturn_boundary` for a given eta."""
    return _curve(_check_at(at) + "_inverse", "eta", eta, beta)


def s1_s2_boundary(f, beta):
    """eta on the S1/S2 boundary (the maximum at the end of the pulse); NaN for the
    rectangle, which has no S1."""
    return _curve("s1_s2", "f", f, beta)


def rectangle_normalized(fbar, eta):
    """The normalized rectangle forms with fbar = f/ln(1/(1 - eta)) in (0, 1) and
    0 < eta < 1: (eta tau_m (Eq. 2.27), theta_max/alpha (corrected 2.30),
    eta tau_i/(1 + sqrt(1 - eta)) (corrected 2.35))."""
    shape, arr = _core.broadcast(fbar=fbar, eta=eta)
    fb, e = _core.flat(arr["fbar"], shape), _core.flat(arr["eta"], shape)
    for name, v in (("fbar", fb), ("eta", e)):
        bad = ~((v > 0) & (v < 1))
        if np.any(bad):
            raise InvalidInputError(f"{name} = {float(v[np.argmax(bad)])!r}: must satisfy "
                                    f"0 < {name} < 1")
    out = sp_rocking_rect_normalized(fb, e)
    return _core.shaped(shape, *(np.ascontiguousarray(out[:, j]) for j in range(3)))


# ------------------------------------------------------------------ nonlinear rocking

Block = namedtuple("Block", ["alpha", "p", "e", "g", "r"])
Block.__doc__ = """A rigid block: slenderness alpha (rad), frequency parameter
p = sqrt(m g R / I_o) (rad/s), restitution e (angular velocity ratio at an impact),
gravity g (m/s^2) and R, the distance from a base corner to the centre of mass (m)."""

#: Outcomes of :func:`simulate`, by code.
OUTCOMES = _core.by_code({_f.ROCK_RUN_REST: "rest", _f.ROCK_RUN_NO_UPLIFT: "no_uplift",
                          _f.ROCK_RUN_OVERTURN_NO_IMPACT: "overturn_no_impact",
                          _f.ROCK_RUN_OVERTURN_ONE_IMPACT: "overturn_one_impact",
                          _f.ROCK_RUN_OVERTURN_MANY: "overturn_many_impacts",
                          _f.ROCK_RUN_TIME_LIMIT: "time_limit"})

#: Classes of :func:`overturning_map` cells, by value.
MAP_CLASSES = ("safe", "overturns without impact", "overturns after one impact",
               "overturns after more impacts")

RockingRun = namedtuple("RockingRun", ["outcome", "t_uplift", "t_overturn", "n_impacts",
                                       "t_impacts", "theta_max", "theta_min", "t_end", "t",
                                       "theta", "omega"])
RockingRun.__doc__ = """Result of :func:`simulate`: outcome (see :data:`OUTCOMES`), first
uplift (s, NaN if none), last outward crossing of |theta| = alpha before overturning
(s, NaN if the block is safe), number and times (s) of the impacts, extremes of theta
(rad), time of rest, overturning (|theta| = pi/2) or the limit (s); with a time grid,
t, theta(t) (rad) and omega(t) = theta'(t) (rad/s), else None."""


def _block_tuple(alpha, p, e, r, g):
    return Block(float(alpha), float(p), float(e), float(g), float(r))


def rectangular_block(b, h, g=STANDARD_GRAVITY, e=None):
    """Uniform rectangular block of half-width b and half-height h (m): alpha = atan(b/h),
    R = sqrt(b^2 + h^2), p = sqrt(3 g/(4 R)) and Housner's e = 1 - 1.5 sin^2(alpha)
    unless `e` is given."""
    alpha, p, e_h, r, stat, msg = sp_rocking_block(1, _core.as_scalar("b", b),
                                                   _core.as_scalar("h", h), 0.0,
                                                   _core.as_scalar("g", g))
    _core.raise_for_status(stat, msg)
    blk = _block_tuple(alpha, p, e_h, r, g)
    return blk if e is None else blk._replace(e=_restitution(e))


def symmetric_block(r, alpha, io_over_mr2, g=STANDARD_GRAVITY, e=None):
    """A body symmetric about the vertical through its centre of mass: R (m) from a base
    corner to the centre of mass, slenderness alpha (rad) and I_o = io_over_mr2 m R^2
    about the corner (4/3 for a uniform rectangle): p = sqrt(g/(io_over_mr2 R)) and
    Housner's e = 1 - (2/io_over_mr2) sin^2(alpha) unless `e` is given."""
    alpha, p, e_h, r, stat, msg = sp_rocking_block(2, _core.as_scalar("r", r),
                                                   _core.as_scalar("alpha", alpha),
                                                   _core.as_scalar("io_over_mr2", io_over_mr2),
                                                   _core.as_scalar("g", g))
    _core.raise_for_status(stat, msg)
    blk = _block_tuple(alpha, p, e_h, r, g)
    return blk if e is None else blk._replace(e=_restitution(e))


def _restitution(e):
    x = _core.as_scalar("e", e)
    if not 0.0 <= x <= 1.0:
        raise InvalidInputError(f"e = {x!r}: the coefficient of restitution must be in [0, 1]")
    return x


def _is_record(x):
    """A seispulse.records.Record (samples in g with their dt)."""
    return hasattr(x, "accel") and hasattr(x, "dt")


def _record_factor(block, accel, accel_v, units):
    """(units, factor to m/s^2) of the record samples: 'm/s2' (or 'm/s^2') 1, 'cm/s2'
    (or 'cm/s^2', 'gal') 0.01, 'g' block.g; units None: 'g' for a Record, else 'm/s2'."""
    given_record = _is_record(accel) or _is_record(accel_v)
    if units is None:
        units = "g" if _is_record(accel) else "m/s2"
    code = _unit_code(units)
    if given_record and code != _f.UNITS_G:
        raise InvalidInputError(f"units = {units!r}: a seispulse.records.Record holds its "
                                "samples in g (leave units out, or give units='g')")
    return {_f.UNITS_G: block.g, _f.UNITS_M_S2: 1.0, _f.UNITS_CM_S2: 0.01}[code]


def simulate(block, pulse=None, *, accel=None, dt=None, linearized=False, t=None,
             t_max=None, theta0=0.0, omega0=0.0, rtol=1e-12, kv=0.0, accel_v=None,
             units=None):
    """Rocking of `block` (:class:`Block`) under a pulse (from
    :func:`seispulse.pulse.define`, SI) or a sampled accelerogram (accel at t = i dt,
    linear in between, zero after; an array with dt, or a
    :class:`seispulse.records.Record`, which carries dt), from rest (or theta0 in rad,
    omega0 in rad/s at t = 0) until rest, overturning or t_max (s).

    Units of accel (and accel_v): ``units`` takes the names of
    :mod:`seispulse.records` ('g', 'm/s2', 'cm/s2'; aliases 'm/s^2', 'cm/s^2', 'gal';
    any case). 'g': the samples are in units of g = block.g (m/s^2: a_g = block.g *
    accel, as the driver and the Fortran rock_record take records); 'm/s2': as they
    are; 'cm/s2': times 0.01. Default (units=None): 'm/s2' for an array (the behaviour
    before ``units`` existed) and 'g' for a Record (a Record is in g; other units are an
    InvalidInputError).

    Sign (doc/rocking.md section 1): a positive ground acceleration drives theta > 0 (rotation about
    one base corner); Housner's and Makris' form has the opposite sign, which flipping
    the sign of the excitation gives.

    Housner's nonlinear equations 2.5/2.6 (linearized=True: Eq. 2.7); uplift at
    |a_g| > g tan(alpha) (alpha when linearized); impacts at theta = 0 located exactly,
    the angular velocity multiplied by e; overturning when |theta| reaches pi/2 (or,
    once the excitation is over, as soon as the energy settles it). Returns
    :class:`RockingRun`. rtol: relative tolerance of the integration steps (absolute:
    alpha and p alpha times it), in [1e-14, 1e-3].

    Vertical ground acceleration a_v (positive up; doc/rocking.md section 7): gravity
    becomes g + a_v. With a pulse, ``kv`` gives a_v = kv a_g (the same pulse scaled; uplift
    at a_g > g tan(alpha)/(1 - kv tan(alpha)) or a_g < -g tan(alpha)/(1 + kv tan(alpha)));
    with a record, ``accel_v`` is a second record in the units of accel (same dt and
    length, linear in between, zero after). a_v < -g anywhere is an InvalidInputError.
    """
    if not isinstance(block, Block):
        raise InvalidInputError("block: must be a seispulse.rocking.Block (rectangular_block "
                                "or symmetric_block)")
    if (pulse is None) == (accel is None):
        raise InvalidInputError("pulse, accel: give exactly one of them")
    linearized = _core.check_bool("linearized", linearized)
    kv = _core.as_scalar("kv", kv)
    if accel_v is not None and accel is None:
        raise InvalidInputError("accel_v: a vertical record goes with a record (accel); "
                                "with a pulse give kv")
    if kv != 0.0 and pulse is None:
        raise InvalidInputError("kv: scales a pulse; with a record give accel_v")
    if units is not None and pulse is not None:
        raise InvalidInputError("units: the units of a record (accel); a pulse is in SI "
                                "(seispulse.pulse.define converts amp_unit='g')")
    if accel is not None:
        factor = _record_factor(block, accel, accel_v, units)
        if _is_record(accel):
            accel, dt = _core.record_and_step(accel, dt)
        if _is_record(accel_v):
            accel_v = accel_v.accel
        if factor != 1.0:
            accel = factor * _core.as_float_array("accel", accel)
            if accel_v is not None:
                accel_v = factor * _core.as_float_array("accel_v", accel_v)
    kind, params, rec, step, grid = _excitation(
        pulse, accel, dt, "dt: the time step (> 0, s) of accel is required", t)
    limit = t_max is not None
    t_lim = _core.check_positive("t_max", t_max, " (s)") if limit else 0.0
    theta0 = _core.as_scalar("theta0", theta0)
    omega0 = _core.as_scalar("omega0", omega0)
    rtol = _core.as_scalar("rtol", rtol)
    rec_v = np.zeros_like(rec)
    if accel_v is not None:
        rec_v = np.ascontiguousarray(_core.as_float_array("accel_v", accel_v).reshape(-1))
        if rec_v.size != rec.size:
            raise InvalidInputError(f"accel_v: {rec_v.size} samples: must have as many as "
                                    f"accel ({rec.size}), at the same dt")
    with _core.HELD_LOCK:
        (thg, omg, n_imp, outcome, t_uplift, t_overturn, theta_max, theta_min, t_end,
         _, stat, msg) = sp_rock(kind, params, rec, step, block.alpha, block.p, block.e, block.g,
                                 int(linearized), int(limit), t_lim, theta0, omega0, rtol,
                                 kv, int(accel_v is not None), rec_v, grid)
        impacts = sp_fetch_impacts(n_imp if stat == 0 else 0)
    _core.raise_for_status(stat, msg, rename={"t_grid": "t"}, indexed=("accel_v",))
    hist = (None, None, None) if t is None else (grid.copy(), thg.copy(), omg.copy())
    return RockingRun(OUTCOMES[outcome], float(t_uplift), float(t_overturn), int(n_imp),
                      impacts, float(theta_max), float(theta_min), float(t_end),
                      *hist)


def overturning_map(kind, freq_ratio, amp_ratio, alpha, e=None, linearized=False,
                    method="integrator", kv=0.0, **shape):
    """Overturning map of a pulse family over frequency ratios omega_p/p and amplitude
    ratios a_p/(g tan alpha): an integer array of shape (len(amp_ratio),
    len(freq_ratio)) with 0 safe, 1 overturns without impact, 2 after one impact,
    3 after more (:data:`MAP_CLASSES`).

    omega_p = 2 pi/T_p with T_p the period (sine_cycle, cosine_cycle), the pulse length
    (half_sine, rectangular, triangular) or t_d (exponential: f = p t_d =
    2 pi/freq_ratio); omega_p = 2 pi f_p for the Ricker wavelet. `shape` takes beta and
    full (exponential), peak_frac (triangular), cycles (sine_cycle, cosine_cycle: n whole
    periods of 2 pi/omega_p each, 1 <= n <= 10^6, default 1). e defaults to Housner's
    1 - 1.5 sin^2(alpha). method='closed' (exponential half cycle only) classifies with
    the linearized closed forms (regions O -> 1, S and no rocking -> 0), with the
    linearized uplift amplitude g alpha: eta = alpha/(amp_ratio tan alpha).

    kv: vertical ground acceleration a_v = kv a_g in every cell (doc/rocking.md section 7;
    integrator only); a cell whose kv a_g goes below -g is an InvalidInputError naming kv
    and amp_ratio[i].
    """
    _core.check_choice("method", method, ("integrator", "closed"))
    alpha = _core.as_scalar("alpha", alpha)
    kv = _core.as_scalar("kv", kv)
    if kv != 0.0 and method == "closed":
        raise InvalidInputError("kv: method = 'closed' has no vertical acceleration; use "
                                "method = 'integrator'")
    if not 0.0 < alpha < np.pi / 2:
        raise InvalidInputError(f"alpha = {alpha!r}: must be in (0, pi/2) (rad)")
    freq = np.ascontiguousarray(_core.as_float_array("freq_ratio", freq_ratio).reshape(-1))
    amp = np.ascontiguousarray(_core.as_float_array("amp_ratio", amp_ratio).reshape(-1))
    if method == "closed":
        if kind not in ("exponential", "exp") or shape.get("full", False):
            raise InvalidInputError("method = 'closed': the closed forms are for the "
                                    "half-cycle exponential pulse only")
        beta = _core.as_scalar("beta", shape.get("beta", 0.0))
        if np.any(~(freq > 0)):
            raise InvalidInputError("freq_ratio: must be > 0")
        if np.any(~(amp > 0)):
            raise InvalidInputError("amp_ratio: must be > 0 for method = 'closed'")
        f = 2 * np.pi / freq
        eta = alpha / (amp[:, None] * np.tan(alpha))
        region = summary(f[None, :], eta, beta).region
        return np.isin(region, ("O1", "O2", "O3")).astype(np.int32)
    # Housner's e of a uniform rectangle (floored at 0), from the library's formula
    e = symmetric_block(1.0, alpha, 4.0 / 3.0).e if e is None else _restitution(e)
    linearized = _core.check_bool("linearized", linearized)
    template = define(kind, **_template_params(kind, shape))
    classes, stat, msg = sp_overturning_map(alpha, e, template.code, template.params,
                                            int(linearized), freq, amp, kv)
    _core.raise_for_status(stat, msg, indexed=("amp_ratio",))
    return np.array(classes)


def _template_params(kind, shape):
    """Parameters of define() for the template of a map (unit amplitude and time)."""
    k = kind.strip().lower() if isinstance(kind, str) else kind
    if k in ("exponential", "exp"):
        return {"amp": 1.0, "td": 1.0, "beta": shape.get("beta", 0.0),
                "full": shape.get("full", False)}
    if k in ("sine_cycle", "sine", "cosine_cycle", "cosine"):
        return {"amp": 1.0, "period": 1.0, "cycles": shape.get("cycles", 1)}
    if k in ("triangular", "triangle"):
        return {"amp": 1.0, "duration": 1.0, "peak_frac": shape.get("peak_frac", 0.5)}
    if k == "ricker":
        return {"amp": 1.0, "freq": 1.0, "t0": shape.get("t0_periods", 1.5)}
    return {"amp": 1.0, "duration": 1.0}


#: Colour of each class of :data:`MAP_CLASSES` in the plots of overturning maps.
_MAP_COLOURS = ("#f0f0f0", "#d7301f", "#fc8d59", "#fdcc8a")


def _draw_classes(ax, classes, x, y):
    """The cells of a class map on ax in the colours of _MAP_COLOURS (shared with
    seispulse.cylinder; the caller has imported matplotlib)."""
    from matplotlib.colors import ListedColormap
    return ax.pcolormesh(np.asarray(x), np.asarray(y), np.asarray(classes),
                         cmap=ListedColormap(list(_MAP_COLOURS)), vmin=-0.5, vmax=3.5,
                         shading="nearest")


def plot_overturning_map(classes, freq_ratio, amp_ratio, ax=None, title=None):
    """Draw a map of :func:`overturning_map` with matplotlib (an optional dependency):
    one colour per class over (omega_p/p, a_p/(g tan alpha)), the legend of the classes
    inside the figure. Returns the axes (:func:`seispulse.plot.overturning_map` draws
    it and returns the figure)."""
    from . import plot
    fig = plot.overturning_map(classes, freq_ratio, amp_ratio, ax=ax, title=title)
    return ax if ax is not None else fig.axes[0]
