"""Rigid cylinders and blocks on a tensionless Winkler foundation (elastic soil) and the
reduced-order method for inelastic clay (doc/winkler.md; Fortran modules
``seispulse_winkler``, ``seispulse_winkler_rock`` and ``seispulse_clay_footing``; [AD11]
chapters 2 and 3).

A module of its own, not a part of :mod:`seispulse.cylinder`: the soil model is shared by
cylinders and blocks (a circular or a rectangular footing) and by the elastic and the
inelastic methods (the inelastic pushover corrects the elastic Winkler curve), so it sits
beside the rigid-ground module and takes its bodies (:func:`seispulse.cylinder.props`,
:func:`seispulse.cylinder.block_props`) rather than belonging to one of them.

What it offers:

* stiffness: :func:`halfspace_rocking_stiffness`, :func:`rect_rocking_stiffness`
  ([G91]), the Winkler moduli k = K_R/I (:func:`modulus_circle`, :func:`modulus_rect`),
  the :func:`shape_factor` and the modulus of the varying-k method
  (:func:`varying_modulus`);
* static pushover on the closed forms: :func:`winkler_pushover` (circle),
  :func:`block_winkler_pushover` (rectangle), the universal small-angle curve
  :func:`master_curve`, the cylinder of a block on the same soil
  (:func:`equivalent_cylinder`);
* dynamics ([KH91], [KSR86]): :func:`model`, :func:`simulate`, :func:`overturning_map`
  (with the rigid-ground map of the same body and their difference);
* inelastic clay: :func:`clay_bearing`, :func:`inelastic_pushover`,
  :func:`moment_capacity`, and the two laws of the method, :func:`stiffness_ratio` and
  :func:`gaussian_correction`;
* plots (matplotlib, imported only when drawing): :func:`plot_pushover`,
  :func:`plot_history`, :func:`plot_map`, :func:`plot_inelastic`.

Units: m, kg, s, N, rad, rad/s; Winkler modulus k in N/m^3 (pressure per settlement),
dashpot c in N s/m^3, shear modulus G (``g_mod``) and S_u (``su``) in Pa, moments in N m,
rotational stiffness in N m/rad; records in g with a ``g`` argument (m/s^2, default
9.80665). Every number comes from the Fortran library; this module checks, broadcasts and
names.
"""

from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from . import cylinder
from ._seispulse import (sp_wk_block_pushover, sp_wk_equivalent_cylinder,
                         sp_wk_halfspace_rocking_stiffness, sp_wk_master_curve,
                         sp_wk_modulus_circle, sp_wk_modulus_rect, sp_wk_pushover,
                         sp_wk_rect_rocking_stiffness, sp_wk_shape_factor,
                         sp_wk_varying_modulus)
from .errors import InvalidInputError
from .pulse import STANDARD_GRAVITY

__all__ = ["FOOTINGS", "K_METHODS", "READINGS", "halfspace_rocking_stiffness",
           "modulus_circle", "RectStiffness", "rect_rocking_stiffness", "modulus_rect",
           "shape_factor", "varying_modulus", "WinklerPushover", "winkler_pushover",
           "block_winkler_pushover", "MasterCurve", "master_curve", "equivalent_cylinder",
           "plot_pushover"]

#: Footings by name: a circular base (radius r) or a rectangular one (half-width b along
#: the rocking direction, half-length alpha out of the plane).
FOOTINGS = {"circle": _f.FOOTING_CIRCLE, "rectangle": _f.FOOTING_RECTANGLE}

#: Winkler modulus during the pushover or the motion: 'constant' (the full-contact k) or
#: 'varying' ([AD11]: k of the equivalent rectangle of the current contact).
K_METHODS = {"constant": _f.K_CONSTANT, "varying": _f.K_VARYING}

#: Which of Gazetas' rectangle formulas defines the shape factor of the varying-k method
#: for a circle: 'long' (K_rx, about the long axis: 1.258) or 'short' (K_ry: 1.216).
READINGS = {"long": _f.AXIS_LONG, "short": _f.AXIS_SHORT}

_AXIS_NAMES = {code: name for name, code in READINGS.items()}


def _loop(wrapper, names, values, before=(), after=()):
    """Broadcast the named inputs, run an element-by-element wrapper of _wrap_loops.txt
    (scalar arguments `before` and `after` the arrays) and return (shape, outputs)."""
    shape, arr = _core.broadcast(**dict(zip(names, values)))
    flat = [_core.flat(arr[n], shape) for n in names]
    *outs, stat, msg = wrapper(*before, *flat, *after)
    _core.raise_for_status(stat, msg, indexed=names)
    return shape, outs


# ------------------------------------------------------------------ stiffness

def halfspace_rocking_stiffness(g_mod, nu, r):
    """Rocking stiffness of a rigid circular footing on a homogeneous halfspace,
    K_R = 8 G r^3/(3 (1 - nu)) (N m/rad); g_mod: shear modulus G (Pa, > 0), nu: Poisson's
    ratio in (0, 0.5), r: radius (m, > 0). Broadcasts like a numpy ufunc."""
    shape, (k_r,) = _loop(sp_wk_halfspace_rocking_stiffness, ("g_mod", "nu", "r"),
                          (g_mod, nu, r))
    return _core.shaped(shape, k_r)[0]


def modulus_circle(g_mod, nu, r):
    """Winkler modulus of a circular footing that gives the halfspace rocking stiffness,
    k = K_R/I = 32 G/(3 pi (1 - nu) r) (N/m^3), I = pi r^4/4; g_mod (Pa), nu, r (m) as in
    :func:`halfspace_rocking_stiffness`. Broadcasts."""
    shape, (k,) = _loop(sp_wk_modulus_circle, ("g_mod", "nu", "r"), (g_mod, nu, r))
    return _core.shaped(shape, k)[0]


RectStiffness = namedtuple("RectStiffness", ["k_r", "axis"])
RectStiffness.__doc__ = """Rocking stiffness of a rectangle ([G91]): k_r (N m/rad) and the
formula used, axis = 'long' (rotation about the long axis, K_rx) or 'short' (about the
short axis, K_ry), which follows from which side is longer."""


def rect_rocking_stiffness(g_mod, nu, width, length):
    """Gazetas (1991) rocking stiffness of a rigid rectangular footing on a halfspace:
    width (m) along the rocking direction, length (m) along the axis of rotation; g_mod
    (Pa, > 0), nu in (0, 0.5). Returns :class:`RectStiffness` (k_r in N m/rad; axis a
    name, or an array of names). Broadcasts."""
    shape, (k_r, axis) = _loop(sp_wk_rect_rocking_stiffness, ("g_mod", "nu", "width", "length"),
                               (g_mod, nu, width, length))
    names = np.array([_AXIS_NAMES[int(a)] for a in axis], dtype=object)
    return RectStiffness(_core.shaped(shape, k_r)[0],
                         str(names[0]) if shape == () else names.reshape(shape).astype(str))


def modulus_rect(g_mod, nu, width, length):
    """Winkler modulus of a rectangular footing, k = K_R/I (N/m^3) with the Gazetas
    stiffness of :func:`rect_rocking_stiffness` and I = length width^3/12 (m^4); width,
    length (m), g_mod (Pa), nu. Broadcasts."""
    shape, (k,) = _loop(sp_wk_modulus_rect, ("g_mod", "nu", "width", "length"),
                        (g_mod, nu, width, length))
    return _core.shaped(shape, k)[0]


def shape_factor(reading="long"):
    """k_circle/k_square (-) of the varying-k method: the ratio of K_R/I of a circle of
    radius r to that of the 2r x 2r square, for Gazetas' long-axis (reading='long':
    1.258) or short-axis formula ('short': 1.216); independent of G, nu and r ([AD11]'s
    own value is lost)."""
    factor, stat, msg = sp_wk_shape_factor(_core.choice_code("reading", reading, READINGS))
    _core.raise_for_status(stat, msg)
    return float(factor)


def varying_modulus(b, r, k, footing="circle", alpha=None, reading="long"):
    """Winkler modulus of the varying-k method (N/m^3) at the contact width b (m, measured
    from the compressed edge, 0 < b <= 2 r): k of the equivalent rectangle of the contact
    divided by its I, scaled so that it equals the full-contact k (N/m^3) at b = 2 r. For
    footing='circle' (radius r, m) the rectangle is b x the chord through the pole, with
    the shape factor of `reading`; for 'rectangle' (half-width r, half-length alpha, m) it
    is b x 2 alpha. b, r, k and alpha broadcast."""
    code = _core.choice_code("footing", footing, FOOTINGS)
    if code == _f.FOOTING_RECTANGLE and alpha is None:
        raise InvalidInputError("alpha: the half-length (m, > 0) of the rectangle is required")
    shape, (k_b,) = _loop(sp_wk_varying_modulus, ("r", "alpha", "k", "b"),
                          (r, 0.0 if alpha is None else alpha, k, b), before=(code,),
                          after=(_core.choice_code("reading", reading, READINGS),))
    return _core.shaped(shape, k_b)[0]


# ------------------------------------------------------------------ static pushover

_CURVE_FIELDS = ("theta", "b", "pole", "area", "settlement", "k", "m_found", "m_imposed",
                 "force")
_SCALAR_FIELDS = ("theta_up", "k0", "max_force_over_weight", "theta_at_max", "max_moment",
                  "theta_at_max_moment", "theta_overturn", "theta_end")
# the column of each curve field (WP_* of seispulse_winkler, 1-based)
_CURVE_COLUMNS = (_f.WP_THETA, _f.WP_B, _f.WP_POLE, _f.WP_AREA, _f.WP_SETTLEMENT, _f.WP_K,
                  _f.WP_M_FOUND, _f.WP_M_IMPOSED, _f.WP_FORCE)

WinklerPushover = namedtuple("WinklerPushover",
                             ("footing", "r", "alpha", "h", "weight", "k_method")
                             + _CURVE_FIELDS + _SCALAR_FIELDS)
WinklerPushover.__doc__ = """Static pushover of a rigid body on tensionless Winkler soil
(doc/winkler.md), from :func:`winkler_pushover` or :func:`block_winkler_pushover`.

The body: footing ('circle' or 'rectangle'), r (radius, or half-width b along the rocking
direction, m), alpha (half-length of a rectangle, m; NaN for a circle), h (height of the
centre of mass above the base, m), weight W (N), k_method ('constant' or 'varying').

Curves at the tilts theta (rad, arrays of one length): b, contact width from the compressed
edge (m; 2 r in full contact); pole, distance a of the rotation pole (the centroid of the
contact) from the base centre towards the compressed edge (m); area, projected contact area
(m^2); settlement of the base centre (m, + down); k, current Winkler modulus (N/m^3);
m_found, foundation moment about the base centre (N m); m_imposed = m_found - W h
sin(theta) (N m); force F = m_imposed/(h cos theta) (N), the horizontal force at the centre
of mass that holds the tilt (carried by the base). A tilt with no admissible equilibrium
(beyond theta_end) gives NaN in every curve but theta.

Scalars: theta_up, the uplift angle (rad; NaN when the branch has no uplift); k0, the
full-contact modulus (N/m^3); max_force_over_weight, the peak F/W (-) at theta_at_max
(rad); max_moment, the peak imposed moment (N m) at theta_at_max_moment (rad);
theta_overturn, the first zero of the imposed moment (rad; NaN if none); theta_end, the
largest admissible tilt, the end of the branch (rad)."""


def _pushover_result(body, grid, out):
    curve, scalars, stat, msg = out
    _core.raise_for_status(stat, msg, indexed={"theta": "theta"})
    cols = [np.array(curve[:, c - 1]) for c in _CURVE_COLUMNS]
    cols[0] = grid.copy()
    return WinklerPushover(*body, *cols, *(float(s) for s in scalars))


def _grid(end, theta_up, n):
    """About n tilts on [0, end] (rad): half evenly spaced, half geometric from
    theta_up/20 (the small-angle part, where the contact and the stiffness change)."""
    if not (np.isfinite(theta_up) and 0.0 < theta_up / 20 < end):
        return np.linspace(0.0, end, n)
    even = np.linspace(0.0, end, n - n // 2)
    geo = np.geomspace(theta_up / 20, end, n // 2 + 1)
    return np.unique(np.concatenate([even, geo]))


def _theta_grid(theta, n, call):
    """The tilts of a pushover: theta as given (1-d, rad), or about n points from 0 to the
    end of the branch (theta_up and theta_end from a first call on theta = 0)."""
    if theta is not None:
        grid = _core.as_float_array("theta", theta)
        if grid.ndim > 1:
            raise InvalidInputError(f"theta: must be a 1-d array of tilts (rad), got shape "
                                    f"{grid.shape}")
        return np.ascontiguousarray(grid.reshape(-1))
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 4:
        raise InvalidInputError(f"n = {n!r}: must be an integer >= 4 (points of the curve)")
    _, scalars, stat, msg = call(np.zeros(1))
    _core.raise_for_status(stat, msg)
    return _grid(float(scalars[7]), float(scalars[0]), int(n))


def winkler_pushover(r, h, weight, k, k_method="constant", theta=None, n=201, reading="long"):
    """Static pushover of a rigid body with a circular base on tensionless Winkler soil
    (doc/winkler.md; [AD11] chapter 2): radius r (m), centre of mass at height h (m) above
    the base, weight W (N), full-contact Winkler modulus k (N/m^3, e.g.
    :func:`modulus_circle`); k_method 'constant' or 'varying' (k of the equivalent
    rectangle of the contact, shape factor of `reading`, 'long' or 'short').

    Closed forms: full contact up to theta_up = asin(2 W/(k pi r^3))/2, then the contact
    segment of width b with theta(b) = asin(2 W/(k Phi(b)))/2. theta: the tilts (rad, a
    1-d array); default about n points from 0 to theta_end, the end of the admissible
    branch, half evenly spaced and half geometric from theta_up/20.
    Returns :class:`WinklerPushover`."""
    args = [_core.as_scalar(name, v) for name, v in (("r", r), ("h", h), ("weight", weight),
                                                     ("k", k))]
    method = _core.choice_code("k_method", k_method, K_METHODS)
    read = _core.choice_code("reading", reading, READINGS)

    def call(grid):
        return sp_wk_pushover(*args, method, read, grid)
    grid = _theta_grid(theta, n, call)
    body = ("circle", args[0], float("nan"), args[1], args[2], k_method)
    return _pushover_result(body, grid, call(grid))


def block_winkler_pushover(b, alpha, h, weight, k, k_method="constant", theta=None, n=201):
    """Static pushover of a rigid block on tensionless Winkler soil (doc/winkler.md;
    [AD11] section 2.2.4): half-width b along the rocking direction and half-length alpha
    out of the plane (m), centre of mass at height h (m), weight W (N), full-contact
    Winkler modulus k (N/m^3, e.g. :func:`modulus_rect` of 2b x 2alpha); k_method
    'constant' or 'varying' (k of the b' x 2 alpha contact rectangle).

    Closed forms: full contact up to theta_up = asin(W/(2 alpha b^2 k))/2, then the contact
    width b' with theta = asin(2 W/(alpha b'^2 k))/2. theta: the tilts (rad, 1-d); default
    about n points from 0 to theta_end (as :func:`winkler_pushover`). Returns
    :class:`WinklerPushover` (footing 'rectangle', r = b)."""
    args = [_core.as_scalar(name, v) for name, v in (("b", b), ("alpha", alpha), ("h", h),
                                                     ("weight", weight), ("k", k))]
    method = _core.choice_code("k_method", k_method, K_METHODS)

    def call(grid):
        return sp_wk_block_pushover(*args, method, grid)
    grid = _theta_grid(theta, n, call)
    body = ("rectangle", args[0], args[1], args[2], args[3], k_method)
    return _pushover_result(body, grid, call(grid))


MasterCurve = namedtuple("MasterCurve", ["k_ratio", "m_ratio", "b_ratio", "a_ratio"])
MasterCurve.__doc__ = """The universal small-angle curve of a constant-k footing at
x = theta/theta_up: k_ratio = K_sec/K_0 (secant over full-contact rotational stiffness),
m_ratio = M/(W r) (foundation moment over weight times radius or half-width), b_ratio =
b/(2 r) (contact width over the full width), a_ratio = a/r (pole over radius)."""


def master_curve(x, footing="circle"):
    """The universal small-angle pushover curve of a footing on constant-k Winkler soil
    (footing 'circle' or 'rectangle') at x = theta/theta_up >= 0 (-): in full contact (x <=
    1) K_sec/K_0 = 1 and M/(W r) = x/4 (circle; x/3 for the rectangle); beyond, the
    contact shrinks towards the edge (M -> W r, K_sec/K_0 -> 4/x for the circle). x
    broadcasts; returns :class:`MasterCurve`."""
    code = _core.choice_code("footing", footing, FOOTINGS)
    xx = _core.as_float_array("x", x)
    flat = np.ascontiguousarray(xx.reshape(-1))
    bad = np.flatnonzero(~(np.isfinite(flat) & (flat >= 0.0)))
    if bad.size:
        where = f"[{bad[0]}]" if xx.ndim else ""
        raise InvalidInputError(f"x{where} = {float(flat[bad[0]])!r}: must be a finite "
                                "theta/theta_up >= 0")
    out = sp_wk_master_curve(code, flat)
    return MasterCurve(*_core.shaped(xx.shape, *out))


def equivalent_cylinder(block, alpha, k, theta_c=None, k_method="constant"):
    """The solid cylinder of a block on the same Winkler soil ([AD11] p.43): the block's
    rigid p (rad/s) and the same peak imposed moment of the Winkler pushover (N m), with
    the slenderness theta_c (rad; default the block's). block: a
    :func:`seispulse.cylinder.block_props` body (half-width b = block.r); alpha: its
    half-length out of the plane (m); k: Winkler modulus (N/m^3) of the soil under both;
    k_method 'constant' or 'varying'. Returns the cylinder's
    :class:`seispulse.cylinder.Body`."""
    cylinder._check_body(block, "block")
    if block.shape != "block":
        raise InvalidInputError(f"block: must be a block (block_props), not a {block.shape}")
    has = theta_c is not None
    r_c, h_c, mass_c, stat, msg = sp_wk_equivalent_cylinder(
        block.r, block.h, block.mass, block.g, _core.as_scalar("alpha", alpha),
        _core.as_scalar("k", k), _core.choice_code("k_method", k_method, K_METHODS), int(has),
        _core.as_scalar("theta_c", theta_c) if has else 0.0)
    _core.raise_for_status(stat, msg)
    return cylinder.props(float(r_c), float(h_c), float(mass_c), block.g)


# ------------------------------------------------------------------ plots

_pyplot = cylinder._pyplot   # matplotlib on demand, one home


def _rigid_curve(push, n=201):
    """theta (rad), F/W and M (N m) of the rigid-ground pushover of the same body
    (:func:`seispulse.cylinder.rigid_pushover`: F = W tan(theta_c - theta), M = W R
    sin(theta_c - theta), geometry and weight only, so it serves a block too)."""
    theta_c = float(np.arctan2(push.r, push.h))
    theta = np.linspace(0.0, theta_c, n)
    rigid = cylinder.rigid_pushover(theta, push.r, push.h, mass=push.weight / STANDARD_GRAVITY,
                                    g=STANDARD_GRAVITY)
    return theta, rigid.F / push.weight, rigid.M


def plot_pushover(push, axes=None, rigid=True, title=None):
    """Draw a :class:`WinklerPushover` with matplotlib (an optional dependency): F/W (-)
    and the imposed moment (N m) against theta (rad), with the uplift angle and the
    overturning angle marked and (rigid=True) the rigid-ground curve of the same body
    (:func:`seispulse.cylinder.rigid_pushover`), the limit of a stiff soil (its F is
    referred to the pivot, the Winkler F to the base centre). axes: two matplotlib axes
    (default: a new figure). Returns the axes."""
    if not isinstance(push, WinklerPushover):
        raise InvalidInputError("push: must be a WinklerPushover (winkler_pushover or "
                                "block_winkler_pushover)")
    plt = _pyplot("plot_pushover")
    if axes is None:
        fig, axes = plt.subplots(1, 2, figsize=(11, 4))
        if title:
            fig.suptitle(title)
    ax_f, ax_m = axes
    label = f"Winkler, {push.k_method} k"
    ax_f.plot(push.theta, push.force / push.weight, color="C0", label=label)
    ax_m.plot(push.theta, push.m_imposed, color="C0", label=label)
    if rigid:
        theta, f_w, m = _rigid_curve(push)
        ax_f.plot(theta, f_w, color="0.4", linestyle="--", label="rigid ground")
        ax_m.plot(theta, m, color="0.4", linestyle="--", label="rigid ground")
    for ax in axes:
        for value, style, name in ((push.theta_up, ":", "uplift"),
                                   (push.theta_overturn, "-.", "overturning")):
            if np.isfinite(value):
                ax.axvline(value, color="C3", linestyle=style, linewidth=0.9,
                           label=f"{name} {value:.4g} rad")
        ax.axhline(0.0, color="0.8", linewidth=0.8)
        ax.set_xlabel("theta (rad)")
        ax.legend(loc="upper right", fontsize="small")
    ax_f.set_ylabel("F / W (-)")
    ax_m.set_ylabel("imposed moment M (N m)")
    return axes


# Dynamics ([KH91], [KSR86]) and inelastic clay ([AD11] chapter 3): their own modules,
# re-exported here
from ._winkler_clay import (CAPACITY_MODELS, Bearing, InelasticPushover,  # noqa: E402
                            StiffnessRatio, clay_bearing, gaussian_correction,
                            inelastic_pushover, moment_capacity, plot_inelastic,
                            stiffness_ratio)
from ._winkler_rock import (COLUMNS, DAMPING_REFS, OUTCOMES, WinklerMap,  # noqa: E402
                            WinklerModel, WinklerRun, model, overturning_map, plot_history,
                            plot_map, simulate)

__all__ += ["DAMPING_REFS", "WinklerModel", "model", "OUTCOMES", "COLUMNS", "WinklerRun",
            "simulate", "WinklerMap", "overturning_map", "plot_history", "plot_map",
            "Bearing", "clay_bearing", "CAPACITY_MODELS", "moment_capacity",
            "StiffnessRatio", "stiffness_ratio", "gaussian_correction", "InelasticPushover",
            "inelastic_pushover", "plot_inelastic"]
