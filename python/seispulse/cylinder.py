"""Rigid cylinders (and blocks) rocking on a rigid base: properties, static pushover, planar
rocking, overturning maps and the cylinder-block equivalence (doc/cylinder.md; Fortran
module ``seispulse_cylinder``; the rigid-base part of [AD11]).

A body is a :class:`Body`, made by :func:`props` (a solid, hollow or custom cylinder of
base radius r and centre-of-mass height h) or :func:`block_props` (a uniform block of
half-width b). Units: m, kg, s, N, rad, rad/s; ground accelerations of :func:`simulate`
in m/s^2 (as :func:`seispulse.rocking.simulate`), PGA of the maps and thresholds in g,
pulse frequencies in Hz. ``g`` defaults to :data:`seispulse.pulse.STANDARD_GRAVITY`
(9.80665 m/s^2).

Planar rocking runs on the integrator of :mod:`seispulse.rocking` (Housner's equations with
the body's J_o, p and restitution): :func:`simulate` returns its
:class:`~seispulse.rocking.RockingRun`. Every number comes from the Fortran library; this
module checks, broadcasts and names.
"""

from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from . import rocking
from ._seispulse import (sp_body_block, sp_body_overturning_map, sp_body_overturning_threshold,
                         sp_body_props, sp_cyl_normalized_pushover, sp_cyl_rigid_pushover,
                         sp_equivalent_block, sp_equivalent_cylinder, sp_map_difference)
from .errors import InvalidInputError
from .pulse import STANDARD_GRAVITY, define
from .rocking import MAP_CLASSES, RockingRun

__all__ = ["SHAPES", "Body", "props", "block_props", "equivalent_cylinder",
           "equivalent_block", "Pushover", "rigid_pushover", "normalized_pushover",
           "rocking_block", "simulate", "MAP_AXES", "MAP_CLASSES", "MAP_DIFF",
           "overturning_map", "map_difference", "BlockComparison", "compare_with_block",
           "overturning_threshold", "Thresholds", "thresholds_side_by_side",
           "plot_overturning_map", "plot_history", "RockingRun", "roll", "RollRun",
           "ROLL_OUTCOMES", "ROLL_COLUMNS", "plot_roll"]

#: Names of the body shapes, by Fortran code (BODY_*).
SHAPES = {_f.BODY_SOLID_CYLINDER: "solid_cylinder", _f.BODY_HOLLOW_CYLINDER: "hollow_cylinder",
          _f.BODY_CUSTOM: "custom", _f.BODY_BLOCK: "block"}

#: Axis systems of the maps: x = omega_p/p, y = a_p/(g tan theta_c) ('dimensionless') or
#: x = f_p (Hz), y = PGA (g) ('dimensional').
MAP_AXES = {"dimensionless": _f.MAP_AXES_DIMENSIONLESS, "dimensional": _f.MAP_AXES_DIMENSIONAL}

#: Cells of :func:`map_difference`, by code (MAP_DIFF_*).
MAP_DIFF = _core.by_code({_f.MAP_DIFF_SAME: "same",
                          _f.MAP_DIFF_ONLY_FIRST: "only the first (cylinder) overturns",
                          _f.MAP_DIFF_ONLY_SECOND: "only the second (block) overturns",
                          _f.MAP_DIFF_OTHER_MODE: "both overturn, by different classes"})

Body = namedtuple("Body", ["shape", "r", "h", "mass", "g", "r_inner", "theta_c", "R", "J_o",
                           "J_G", "J_axis", "p", "restitution", "weight", "M_max", "F_uplift"])
Body.__doc__ = """A rigid body rocking on a rigid base about a point of its base edge.

shape: 'solid_cylinder', 'hollow_cylinder', 'custom' or 'block' (:data:`SHAPES`); r: base
radius, or the half-width b of a block (m); h: height of the centre of mass above the base
(m); mass (kg); g (m/s^2); r_inner: inner radius of a hollow cylinder (m, else 0);
theta_c = atan(r/h) (rad), the overturning angle; R = sqrt(r^2 + h^2) (m), pivot to centre
of mass; J_o, J_G, J_axis: moments of inertia about the pivot, the centre of mass
(transverse axes) and the axis of symmetry (kg m^2; J_axis NaN when unknown);
p = sqrt(m g R/J_o) (rad/s); restitution: Housner's angular-velocity ratio at an impact
max(0, 1 - (2 m R^2/J_o) sin^2 theta_c); weight m g (N); M_max = m g r (N m), the pushover
moment at theta = 0; F_uplift = W r/h (N), the horizontal force at the centre of mass
that starts the uplift.

Make it with :func:`props` or :func:`block_props`: the functions of this module rebuild
the body from shape, r, h, mass, g, r_inner (and J_o, J_axis of a custom body), so the
other fields are for reading; restitution alone may be replaced
(``body._replace(restitution=0.8)``) and is then the default e of :func:`simulate` and of
the maps."""

Pushover = namedtuple("Pushover", ["F", "M", "stable", "M_normalized", "theta_normalized"])
Pushover.__doc__ = """Static pushover of a rigid cylinder on a rigid base at tilt theta:
F = W tan(theta_c - theta) (N, horizontal at the centre of mass), M = W R sin(theta_c -
theta) (N m, about the pivot), stable (|theta| <= theta_c: beyond it F < 0 and the body
falls on its own), M_normalized = M/(m g r) and theta_normalized = theta/theta_c. A
negative theta is the mirror image (rotation about the other edge): F and M change sign."""

BlockComparison = namedtuple("BlockComparison", ["block", "cylinder_map", "block_map",
                                                 "difference"])
BlockComparison.__doc__ = """A body's overturning map next to its equivalent block's on the
same (f_p in Hz, PGA in g) grid: block (the :class:`Body` of :func:`equivalent_block`),
cylinder_map and block_map (classes as :data:`MAP_CLASSES`, shape (len(pga_g),
len(f_hz))), difference (:data:`MAP_DIFF` codes, from :func:`map_difference`)."""

Thresholds = namedtuple("Thresholds", ["freq_hz", "cylinder_pga_g", "block_pga_g",
                                       "cylinder_uplift_g", "block_uplift_g", "block"])
Thresholds.__doc__ = """Per pulse frequency freq_hz (Hz): the smallest PGA (g) that
overturns the body (cylinder_pga_g) and its equivalent block (block_pga_g; +inf when
nothing up to pga_max_g does), and the uplift thresholds tan(theta_c) of the body and
tan(alpha) of the block (g; theta_c and alpha in the linearized model), where the searches
start; block is the equivalent block's :class:`Body`."""


# ------------------------------------------------------------------ bodies

def _body_from_fortran(out, r, h, mass, g, r_inner):
    shape_code, theta_c, big_r, j_o, j_g, j_axis, p, e, weight, m_max, f_uplift, stat, msg = out
    _core.raise_for_status(stat, msg)
    return Body(SHAPES[int(shape_code)], r, h, mass, g, r_inner, float(theta_c), float(big_r),
                float(j_o), float(j_g), float(j_axis), float(p), float(e), float(weight),
                float(m_max), float(f_uplift))


def props(r, h, mass=1.0, g=STANDARD_GRAVITY, r_inner=0.0, j_o=None, j_axis=None):
    """A cylinder of base radius r (m) with its centre of mass at height h (m) above the
    base (the half-height of a uniform cylinder), mass (kg) and gravity g (m/s^2): solid
    (r_inner = 0), hollow (inner radius r_inner in (0, r), m) or, with j_o (kg m^2, its
    moment of inertia about the pivot, >= m R^2), a custom body of revolution (j_axis, about
    its axis, kg m^2, optional). Returns :class:`Body`.

    Solid: J_G = m (3 r^2 + 4 h^2)/12, J_o = 5/4 m r^2 + 4/3 m h^2, J_axis = m r^2/2; hollow:
    r^2 -> r^2 + r_inner^2 in J_G and J_axis (doc/cylinder.md)."""
    args = [_core.as_scalar(name, v) for name, v in
            (("r", r), ("h", h), ("mass", mass), ("g", g), ("r_inner", r_inner))]
    custom = j_o is not None
    jo = _core.as_scalar("j_o", j_o) if custom else 0.0
    ja = _core.as_scalar("j_axis", j_axis) if j_axis is not None else 0.0
    code = _f.BODY_CUSTOM if custom else _f.BODY_SOLID_CYLINDER
    out = sp_body_props(code, *args, jo, int(j_axis is not None), ja)
    return _body_from_fortran(out, *args)


def block_props(b, h, mass=1.0, g=STANDARD_GRAVITY):
    """A uniform rectangular block of half-width b (m; the field r of the :class:`Body`)
    with its centre of mass at height h (m; the half-height), mass (kg), gravity g
    (m/s^2): J_o = 4/3 m R^2, J_G = m (b^2 + h^2)/3, p = sqrt(3 g/(4 R)), Housner's
    restitution 1 - 1.5 sin^2 theta_c; J_axis NaN (the depth is not known)."""
    args = [_core.as_scalar(name, v) for name, v in (("b", b), ("h", h), ("mass", mass),
                                                     ("g", g))]
    out = sp_body_props(_f.BODY_BLOCK, *args, 0.0, 0.0, 0, 0.0)
    return _body_from_fortran(out, *args, 0.0)


def _check_body(body, name="body"):
    if not isinstance(body, Body):
        raise InvalidInputError(f"{name}: must be a seispulse.cylinder.Body (from props or "
                                "block_props)")
    return body


def _body_args(body, name="body"):
    """The defining numbers of a body for the wrappers (see _wrap_cylinder.f90)."""
    _check_body(body, name)
    code = {v: k for k, v in SHAPES.items()}.get(body.shape)
    if code is None:
        raise InvalidInputError(f"{name}.shape = {body.shape!r}: unknown (allowed: "
                                f"{', '.join(map(repr, SHAPES.values()))})")
    has_axis = code == _f.BODY_CUSTOM and not np.isnan(body.J_axis)
    return (code, body.r, body.h, body.mass, body.g, body.r_inner,
            body.J_o if code == _f.BODY_CUSTOM else 0.0, int(has_axis),
            body.J_axis if has_axis else 0.0)


def equivalent_cylinder(block, theta_c=None):
    """The solid cylinder equivalent to a block (a :class:`Body` of shape 'block'): the same
    p (rad/s) and the same static M_max (m_c r = m_b b, N m). Two conditions for three
    unknowns (r, h, mass): the third is the slenderness theta_c (rad; default the block's
    alpha), with R from p: R = g/(p^2 J_o/(m R^2)) at that theta_c."""
    _check_body(block, "block")
    if block.shape != "block":
        raise InvalidInputError(f"block: must be a block (block_props), not a {block.shape}")
    has = theta_c is not None
    th = _core.as_scalar("theta_c", theta_c) if has else 0.0
    r, h, mass, stat, msg = sp_equivalent_cylinder(block.r, block.h, block.mass, block.g,
                                                   int(has), th)
    _core.raise_for_status(stat, msg)
    return props(float(r), float(h), float(mass), block.g)


def equivalent_block(cyl, alpha=None):
    """The uniform block equivalent to a cylinder: the same p (R_b = 3 g/(4 p^2)) and the
    same static M_max (m_b b = m_c r); the extra condition is the slenderness alpha (rad;
    default the cylinder's theta_c). Returns the block's :class:`Body`."""
    has = alpha is not None
    a = _core.as_scalar("alpha", alpha) if has else 0.0
    b, h, mass, stat, msg = sp_equivalent_block(*_body_args(cyl, "cyl"), int(has), a)
    _core.raise_for_status(stat, msg)
    return block_props(float(b), float(h), float(mass), cyl.g)


# ------------------------------------------------------------------ static pushover

def rigid_pushover(theta, r, h, mass=1.0, g=STANDARD_GRAVITY):
    """Static pushover of a solid cylinder (base radius r, centre-of-mass height h, m;
    mass, kg) on a rigid base at the tilt theta (rad, |theta| <= pi/2): :class:`Pushover`.
    theta, r, h and mass broadcast like numpy ufuncs; scalars in give Python scalars out."""
    g = _core.as_scalar("g", g)
    shape, arr = _core.broadcast(theta=theta, r=r, h=h, mass=mass)
    flat = [_core.flat(arr[k], shape) for k in ("theta", "r", "h", "mass")]
    force, moment, stable, m_ratio, u, stat, msg = sp_cyl_rigid_pushover(*flat, g)
    _core.raise_for_status(stat, msg)
    f, m, mr, uu = _core.shaped(shape, force, moment, m_ratio, u)
    st = bool(stable[0]) if shape == () else stable.reshape(shape).astype(bool)
    return Pushover(f, m, st, mr, uu)


def normalized_pushover(theta_c, u):
    """The rigid pushover curve M/(m g r) = sin(theta_c (1 - u))/sin(theta_c) against
    u = theta/theta_c (theta_c in (0, pi/2) rad); broadcasts."""
    shape, arr = _core.broadcast(theta_c=theta_c, u=u)
    tc, uu = _core.flat(arr["theta_c"], shape), _core.flat(arr["u"], shape)
    bad = ~((tc > 0) & (tc < np.pi / 2))
    if np.any(bad):
        raise InvalidInputError(f"theta_c = {float(tc[np.argmax(bad)])!r}: must be in "
                                "(0, pi/2) (rad)")
    if not np.all(np.isfinite(uu)):
        raise InvalidInputError("u: must be finite")
    m, stat, msg = sp_cyl_normalized_pushover(tc, uu)
    _core.raise_for_status(stat, msg)
    return _core.shaped(shape, m)[0]


# ------------------------------------------------------------------ planar rocking

def rocking_block(body, e=None, linearized=False):
    """The :class:`seispulse.rocking.Block` of a body (alpha = theta_c, its p and R): what
    :func:`simulate` runs; e (restitution, [0, 1]) defaults to body.restitution."""
    _check_body(body)
    linearized = _core.check_bool("linearized", linearized)
    ee = body.restitution if e is None else _core.as_scalar("e", e)
    alpha, p, e_out, stat, msg = sp_body_block(*_body_args(body), ee, int(linearized))
    _core.raise_for_status(stat, msg)
    return rocking.Block(float(alpha), float(p), float(e_out), body.g, body.R)


def simulate(body, pulse=None, *, accel=None, dt=None, t_max=None, t=None, e=None,
             linearized=False, theta0=0.0, omega0=0.0, rtol=1e-12, kv=0.0, accel_v=None,
             units=None):
    """Planar rocking of a body on a rigid base under a pulse (from
    :func:`seispulse.pulse.define`, SI) or a sampled horizontal ground acceleration accel
    (an array in m/s^2 unless ``units`` says otherwise, or a
    :class:`seispulse.records.Record` in g; ``units`` as in
    :func:`seispulse.rocking.simulate`, 'g' meaning the body's g) at t = i dt (s): Housner's
    equations with the body's J_o (through p) and restitution (e overrides it), impacts at
    theta = 0, overturning at |theta| = pi/2. t (s): output times for theta(t), omega(t);
    t_max (s), theta0 (rad), omega0 (rad/s), rtol as in rocking.simulate. Vertical ground
    acceleration (positive up): kv scales a pulse (a_v = kv a_g), accel_v is a vertical
    record in m/s^2 with accel (as rocking.simulate). Returns
    :class:`seispulse.rocking.RockingRun`, exactly as rocking.simulate does for the block
    :func:`rocking_block` (body, e, linearized). The body's g sets the uplift threshold and
    the equation of motion; a pulse defined with amp_unit='g' was converted with its own g
    (seispulse.pulse.STANDARD_GRAVITY unless given): use the same g for both."""
    block = rocking_block(body, e=e, linearized=linearized)
    return rocking.simulate(block, pulse, accel=accel, dt=dt, linearized=linearized, t=t,
                            t_max=t_max, theta0=theta0, omega0=omega0, rtol=rtol, kv=kv,
                            accel_v=accel_v, units=units)


# ------------------------------------------------------------------ overturning maps

def _template(kind, shape):
    return define(kind, **rocking._template_params(kind, shape))


def _e_args(e):
    return (0, 0.0) if e is None else (1, _core.as_scalar("e", e))


def _vector(name, x):
    """A 1-d axis of a map (a 2-d meshgrid is refused: the map makes the grid itself)."""
    v = _core.as_float_array(name, x)
    if v.ndim > 1:
        raise InvalidInputError(f"{name}: must be a 1-d list of axis values (got shape "
                                f"{v.shape}); the map forms the grid of x and y itself")
    return np.ascontiguousarray(v.reshape(-1))


def overturning_map(body, kind, x, y, axes="dimensionless", e=None, linearized=False,
                    rtol=1e-12, kv=0.0, **shape):
    """Overturning map of a body under a pulse family (kind as in
    :func:`seispulse.rocking.overturning_map`; shape: beta, full, peak_frac, t0_periods) on
    either axis system: axes='dimensionless', x = omega_p/p, y = a_p/(g tan theta_c); or
    axes='dimensional', x = pulse frequency f_p = omega_p/(2 pi) (Hz), y = PGA (g). Returns
    the classes, an int array of shape (len(y), len(x)): 0 safe, 1 overturns without
    impact, 2 after one impact, 3 after more (:data:`MAP_CLASSES`). e defaults to
    body.restitution; rtol: the integrator's step tolerance; kv: vertical ground
    acceleration a_v = kv a_g in every cell (doc/rocking.md section 7; a cell where a_v
    would fall below -g is an error)."""
    axes_code = _core.choice_code("axes", axes, MAP_AXES)
    linearized = _core.check_bool("linearized", linearized)
    tpl = _template(kind, shape)
    e = body.restitution if e is None and isinstance(body, Body) else e
    has_e, ee = _e_args(e)
    classes, stat, msg = sp_body_overturning_map(
        *_body_args(body), tpl.code, tpl.params, axes_code, int(linearized), has_e, ee,
        _core.as_scalar("rtol", rtol), _core.as_scalar("kv", kv), _vector("x", x),
        _vector("y", y))
    _core.raise_for_status(stat, msg, indexed=("x", "y"))
    return np.array(classes)


def map_difference(a, b):
    """Cell-by-cell comparison of two class maps of the same shape: an int array of
    :data:`MAP_DIFF` codes (0 same class, 1 only a overturns, 2 only b overturns, 3 both
    overturn by different classes)."""
    ma = np.asarray(_core.as_float_array("a", a))
    mb = np.asarray(_core.as_float_array("b", b))
    if ma.ndim != 2 or mb.ndim != 2 or ma.shape != mb.shape:
        raise InvalidInputError(f"a, b: must be 2-d maps of the same shape (got {ma.shape} "
                                f"and {mb.shape})")
    for name, m in (("a", ma), ("b", mb)):
        bad = np.flatnonzero(~((m == np.round(m)) & (m >= -1) & (m <= 3)))
        if bad.size:
            where = np.unravel_index(bad[0], m.shape)
            raise InvalidInputError(f"{name}[{where[0]}, {where[1]}] = {float(m[where])!r}: must be "
                                    "a class of a map, an integer in [-1, 3]")
    diff, stat, msg = sp_map_difference(ma.astype(np.int32), mb.astype(np.int32))
    _core.raise_for_status(stat, msg)
    return np.array(diff)


def compare_with_block(body, kind, f_hz, pga_g, alpha=None, linearized=False, rtol=1e-12,
                       kv=0.0, **shape):
    """The body's overturning map, its equivalent block's (:func:`equivalent_block`, same p
    and M_max, slenderness alpha, default theta_c) and their :func:`map_difference`, on
    the same grid of pulse frequencies f_hz (Hz) and PGA pga_g (g); each body with its own
    restitution; kv: vertical ground acceleration a_v = kv a_g as in
    :func:`overturning_map`. Returns :class:`BlockComparison`."""
    block = equivalent_block(body, alpha)
    cyl_map = overturning_map(body, kind, f_hz, pga_g, "dimensional", linearized=linearized,
                              rtol=rtol, kv=kv, **shape)
    blk_map = overturning_map(block, kind, f_hz, pga_g, "dimensional", linearized=linearized,
                              rtol=rtol, kv=kv, **shape)
    return BlockComparison(block, cyl_map, blk_map, map_difference(cyl_map, blk_map))


def _thresholds(body, kind, freq_hz, pga_max_g, n_scan, e, linearized, rtol, shape):
    """(pga_g shaped like freq_hz, uplift_g) of overturning_threshold."""
    linearized = _core.check_bool("linearized", linearized)
    tpl = _template(kind, shape)
    f = _core.as_float_array("freq_hz", freq_hz)
    e = body.restitution if e is None and isinstance(body, Body) else e
    has_e, ee = _e_args(e)
    has_max = pga_max_g is not None
    has_n = n_scan is not None
    n = 0
    if has_n:
        if isinstance(n_scan, bool) or not isinstance(n_scan, (int, np.integer)):
            raise InvalidInputError(f"n_scan = {n_scan!r}: must be an integer")
        n = int(n_scan)
    pga, uplift, stat, msg = sp_body_overturning_threshold(
        *_body_args(body), tpl.code, tpl.params, np.ascontiguousarray(f.reshape(-1)),
        int(has_max), _core.as_scalar("pga_max_g", pga_max_g) if has_max else 0.0, int(has_n),
        n, has_e, ee, int(linearized), _core.as_scalar("rtol", rtol))
    _core.raise_for_status(stat, msg, indexed={"freq_hz": "freq_hz"})
    return _core.shaped(f.shape, pga)[0], float(uplift)


def overturning_threshold(body, kind, freq_hz, pga_max_g=None, n_scan=None, e=None,
                          linearized=False, rtol=1e-12, **shape):
    """Smallest PGA (g) that overturns the body under a pulse of frequency freq_hz (Hz; an
    array gives an array) of the kind (shape as in :func:`overturning_map`): the library
    scans n_scan amplitudes (default 200, geometric) from the uplift threshold tan(theta_c)
    up to pga_max_g (default 20 tan theta_c), then bisects the first safe -> overturn
    transition to a relative width of 1e-6; +inf when nothing up to pga_max_g overturns.
    e defaults to body.restitution."""
    return _thresholds(body, kind, freq_hz, pga_max_g, n_scan, e, linearized, rtol, shape)[0]


def thresholds_side_by_side(body, kind, freq_hz, alpha=None, pga_max_g=None, n_scan=None,
                            linearized=False, rtol=1e-12, **shape):
    """Per pulse frequency freq_hz (Hz), the body's and its equivalent block's
    (:func:`equivalent_block`, slenderness alpha, default theta_c) smallest overturning PGA
    (g, :func:`overturning_threshold`, each with its own restitution) and uplift
    thresholds (g). Returns :class:`Thresholds`."""
    block = equivalent_block(body, alpha)
    cyl, up_c = _thresholds(body, kind, freq_hz, pga_max_g, n_scan, None, linearized, rtol,
                            shape)
    blk, up_b = _thresholds(block, kind, freq_hz, pga_max_g, n_scan, None, linearized, rtol,
                            shape)
    f = _core.as_float_array("freq_hz", freq_hz)
    return Thresholds(float(f) if f.ndim == 0 else f, cyl, blk, up_c, up_b, block)


# ------------------------------------------------------------------ plots

_AXIS_LABELS = {"dimensionless": ("omega_p / p", "a_p / (g tan theta_c)"),
                "dimensional": ("pulse frequency f_p (Hz)", "PGA (g)")}


def _pyplot(what):
    """matplotlib.pyplot (optional): an ImportError naming matplotlib and the pip command
    when matplotlib itself is missing (_core.optional_import); any other import failure of
    an installed matplotlib is raised as it is."""
    _core.optional_import("matplotlib", what)
    import matplotlib.pyplot as plt
    return plt


def plot_overturning_map(classes, x, y, axes="dimensionless", ax=None, title=None):
    """Draw a map of :func:`overturning_map` with matplotlib (an optional dependency) in the
    colours of :func:`seispulse.rocking.plot_overturning_map`, the legend inside the axes
    and the axis labels (with units) of the axis system. Returns the axes."""
    _core.check_choice("axes", axes, tuple(MAP_AXES))
    plt = _pyplot("plot_overturning_map")
    from matplotlib.patches import Patch
    if ax is None:
        _, ax = plt.subplots()
    rocking._draw_classes(ax, classes, x, y)
    ax.legend(handles=[Patch(facecolor=c, edgecolor="0.4", label=name)
                       for c, name in zip(rocking._MAP_COLOURS, MAP_CLASSES)],
              loc="upper right", fontsize="small", framealpha=0.9)
    ax.set_xlabel(_AXIS_LABELS[axes][0])
    ax.set_ylabel(_AXIS_LABELS[axes][1])
    if title:
        ax.set_title(title)
    return ax


def plot_history(run, body=None, ax=None, title=None):
    """Draw theta(t) (rad against s) of a :func:`simulate` run made with output times t,
    the impacts marked; with the body, the overturning angles +-theta_c dashed. Returns the
    axes."""
    if not isinstance(run, RockingRun):
        raise InvalidInputError("run: must be a RockingRun from simulate")
    if run.t is None:
        raise InvalidInputError("run: has no history (give the output times t to simulate)")
    plt = _pyplot("plot_history")
    if ax is None:
        _, ax = plt.subplots()
    ax.plot(run.t, run.theta, color="C0", label="theta(t)")
    if run.n_impacts:
        ax.plot(run.t_impacts, np.zeros(len(run.t_impacts)), "k|", markersize=10,
                label="impacts")
    if body is not None:
        _check_body(body)
        for s in (1, -1):
            ax.axhline(s * body.theta_c, color="0.5", linestyle="--",
                       label="+-theta_c" if s > 0 else None)
    ax.axhline(0.0, color="0.8", linewidth=0.8)
    ax.set_xlabel("t (s)")
    ax.set_ylabel("theta (rad)")
    ax.legend(loc="upper right", fontsize="small")
    ax.set_title(title or f"outcome: {run.outcome}")
    return ax


# 3-D rocking with rolling on the base rim (doc/rolling.md): its own module, re-exported here
from ._cylinder_roll import ROLL_COLUMNS, ROLL_OUTCOMES, RollRun, plot_roll, roll  # noqa: E402
