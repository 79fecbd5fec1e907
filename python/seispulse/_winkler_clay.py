"""A circular footing on undrained clay: bearing capacity, moment capacity and the
reduced-order inelastic rotational pushover of [AD11] chapter 3 (doc/winkler.md
"Inelastic soil"; Fortran module ``seispulse_clay_footing``): the inelastic part of
:mod:`seispulse.winkler`, re-exported there.

The pushover method corrects the elastic Winkler curve of the same footing: the initial
stiffness falls with chi = 1/SF (k/k_el), and the normalized secant stiffness is divided
by a Gaussian correction G(chi; theta/theta_up). The coefficients of both laws were lost
from [AD11]: they are required keyword arguments here, with no defaults. Units: m, N, Pa
(G, S_u), N m, N m/rad, rad.
"""

from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_clay_bearing, sp_clay_gaussian, sp_clay_inelastic_pushover,
                         sp_clay_moment_capacity, sp_clay_stiffness_ratio)
from .errors import InvalidInputError

__all__ = ["Bearing", "clay_bearing", "CAPACITY_MODELS", "moment_capacity",
           "StiffnessRatio", "stiffness_ratio", "gaussian_correction", "InelasticPushover",
           "inelastic_pushover", "plot_inelastic"]

#: Moment-capacity models: 'taiebat_carter' ([TC00]'s peak 0.8 A D S_u) or
#: 'effective_width' (the rigid-plastic N D (1 - chi)/2).
CAPACITY_MODELS = {"taiebat_carter": _f.CAPACITY_TC00_PEAK,
                   "effective_width": _f.CAPACITY_EFFECTIVE_WIDTH}

Bearing = namedtuple("Bearing", ["n_ult", "sf", "chi"])
Bearing.__doc__ = """Vertical bearing of a circular footing on clay: n_ult = n_c S_u pi r^2
(N), the factor of safety sf = n_ult/W (-) and chi = 1/sf (-)."""


def _nc(nc):
    return (0, 0.0) if nc is None else (1, _core.as_scalar("nc", nc))


def clay_bearing(su, r, weight, nc=None):
    """Vertical capacity of a circular footing of radius r (m) on clay of undrained shear
    strength su (Pa) under the weight W (N): N_ult = n_c S_u pi r^2 with n_c = pi + 3
    unless nc is given ([AD11] after [SLSY04]), SF = N_ult/W and chi = 1/SF. SF <= 1
    (vertical bearing failure) is an InvalidInputError. su, r, weight broadcast; returns
    :class:`Bearing`."""
    shape, arr = _core.broadcast(su=su, r=r, weight=weight)
    flat = [_core.flat(arr[k], shape) for k in ("su", "r", "weight")]
    n_ult, sf, chi, stat, msg = sp_clay_bearing(*flat, *_nc(nc))
    _core.raise_for_status(stat, msg)
    return Bearing(*_core.shaped(shape, n_ult, sf, chi))


def moment_capacity(su, r, chi, model="taiebat_carter", nc=None):
    """Moment capacity (N m) of a circular footing of radius r (m) on clay (su, Pa) at
    chi = 1/SF in [0, 1]: model 'taiebat_carter', M_ult = 0.8 A D S_u ([TC00]'s peak, chi
    not used), or 'effective_width', M_u = N D (1 - chi)/2 with N = chi N_ult, i.e.
    M_u/(A D S_u) = (n_c/2) chi (1 - chi); A = pi r^2, D = 2 r; nc as in
    :func:`clay_bearing`. su, r, chi broadcast."""
    code = _core.choice_code("model", model, CAPACITY_MODELS)
    shape, arr = _core.broadcast(su=su, r=r, chi=chi)
    flat = [_core.flat(arr[k], shape) for k in ("su", "r", "chi")]
    m_ult, stat, msg = sp_clay_moment_capacity(*flat, code, *_nc(nc))
    _core.raise_for_status(stat, msg)
    return _core.shaped(shape, m_ult)[0]


StiffnessRatio = namedtuple("StiffnessRatio", ["k_ratio", "kappa"])
StiffnessRatio.__doc__ = """The initial rotational stiffness on clay at chi = 1/SF:
k_ratio = k/k_el (-; 1 for chi <= 0.1, kr_c1 - kr_c2 chi above) and kappa = k_el k/k_el =
K_R0/HK_R (-)."""


def stiffness_ratio(chi, *, kr_c1, kr_c2, k_el=1.0):
    """k/k_el(chi) of [AD11]'s inelastic method at chi = 1/SF in [0, 1): 1 for chi <= 0.1,
    kr_c1 - kr_c2 chi above (the coefficients are lost from [AD11]: required, NaN = not
    given, an error where needed); kappa = k_el k/k_el with the elastic ratio k_el
    (default 1). chi broadcasts; returns :class:`StiffnessRatio`."""
    c = _core.as_float_array("chi", chi)
    k_ratio, kappa, stat, msg = sp_clay_stiffness_ratio(
        np.ascontiguousarray(c.reshape(-1)), _core.as_scalar("k_el", k_el),
        _core.as_scalar("kr_c1", kr_c1), _core.as_scalar("kr_c2", kr_c2))
    _core.raise_for_status(stat, msg)
    return StiffnessRatio(*_core.shaped(c.shape, k_ratio, kappa))


def _gauss_coeffs(a_poly, b1, b2, c1, c2, log_base):
    """The Gaussian's coefficients as the wrappers take them (a_poly: 5 numbers)."""
    poly = _core.as_float_array("a_poly", a_poly).reshape(-1)
    if poly.size != 5:
        raise InvalidInputError(f"a_poly: must hold the 5 coefficients a_0 .. a_4 of a(chi), "
                                f"got {poly.size}")
    return [np.ascontiguousarray(poly)] + [_core.as_scalar(name, v) for name, v in (
        ("b1", b1), ("b2", b2), ("c1", c1), ("c2", c2), ("log_base", log_base))]


def gaussian_correction(chi, x, *, a_poly, b1, b2, c1, c2, log_base):
    """[AD11]'s Gaussian correction of the normalized secant stiffness, G(chi; x) = 1 + a
    exp(-(log_B(x) - b)^2/(2 c^2)) (-) at chi = 1/SF in (0, 1) and x = theta/theta_up >= 0,
    with a(chi) = sum a_poly[i] chi^i, b = b1 ln(chi) + b2, c = c1 chi + c2 and B = log_base.
    The coefficients and the base are lost from [AD11]: required (NaN = not given; b, c and
    log_base are needed only where a(chi) /= 0, and b, c are in units of log_B). chi and x
    broadcast."""
    shape, arr = _core.broadcast(chi=chi, x=x)
    flat = [_core.flat(arr[k], shape) for k in ("chi", "x")]
    g, stat, msg = sp_clay_gaussian(*flat, *_gauss_coeffs(a_poly, b1, b2, c1, c2, log_base))
    _core.raise_for_status(stat, msg)
    return _core.shaped(shape, g)[0]


_CURVES = ("theta", "k_r", "m_found", "m_imposed", "force", "x", "g_corr")
_CURVE_COLUMNS = (_f.IP_THETA, _f.IP_K_R, _f.IP_M_FOUND, _f.IP_M_IMPOSED, _f.IP_FORCE, _f.IP_X,
                  _f.IP_G)
_SCALARS = ("n_ult", "sf", "chi", "hk_r", "k_ratio", "kappa", "k_r0", "theta_up", "gauss_a",
            "gauss_b", "gauss_c", "max_moment", "theta_at_max_moment", "max_force_over_weight",
            "theta_at_max", "theta_overturn")

InelasticPushover = namedtuple("InelasticPushover",
                               ("r", "h", "weight") + _CURVES + _SCALARS
                               + ("no_uplift", "weak_zone", "kr_discontinuous", "kr_jump"))
InelasticPushover.__doc__ = """Inelastic rotational pushover of a cylinder on clay
(:func:`inelastic_pushover`).

The body: r (footing radius, m), h (height of the centre of mass, m), weight W (N).

Curves at the rotations theta (rad): k_r, the secant rotational stiffness (N m/rad);
m_found = k_r theta, the foundation moment (N m); m_imposed = m_found - W h sin(theta)
(N m); force = m_imposed/(h cos theta) (N); x = theta/theta_up (-); g_corr, the Gaussian
correction G(chi; x) (-). NaN beyond pi/4 (the end of the Winkler branch).

Scalars: n_ult (N), sf, chi = 1/sf (-); hk_r = 8 G r^3/(3 (1 - nu)) (N m/rad); k_ratio =
k/k_el(chi) and kappa = k_el k/k_el = K_R0/HK_R (-); k_r0, the initial stiffness (N m/rad);
theta_up = asin(W r/(2 K_R0))/2 (rad); gauss_a, gauss_b, gauss_c, the Gaussian's peak,
centre and spread at chi (-); max_moment (N m) at theta_at_max_moment (rad) and
max_force_over_weight (-) at theta_at_max (rad), the peaks refined between the points
of an internal scan of [0, pi/4] (at or above the largest value on any grid); theta_overturn, the
first zero of the imposed moment up to pi/4 (rad; NaN if none, 0 when K_R0 <= W h).
Flags: no_uplift (W r/(2 K_R0) > 1), weak_zone (SF < 1.25 and the grid reaches theta/theta_up
in [0.05, 0.2], where [AD11]'s collapse of the curves deviates), kr_discontinuous (the
given k/k_el law does not meet 1 at chi = 0.1; kr_jump = kr_c1 - 0.1 kr_c2 - 1)."""


def inelastic_pushover(r, h, weight, g_mod, nu, su, theta=None, n=201, *, kr_c1, kr_c2, a_poly,
                       b1, b2, c1, c2, log_base, k_el=1.0, nc=None):
    """Inelastic rotational pushover of a rigid cylinder on undrained clay by [AD11]'s
    reduced-order method (doc/winkler.md section 10): footing radius r (m), centre of
    mass at h (m), weight W (N); soil shear modulus g_mod (Pa), Poisson's ratio nu in
    (0, 0.5), undrained strength su (Pa).

    Steps: SF = N_ult/W (:func:`clay_bearing`, nc), chi = 1/SF; HK_R = 8 G r^3/(3 (1 - nu));
    K_R0 = HK_R k_el k/k_el(chi); theta_up = asin(W r/(2 K_R0))/2; the elastic normalized
    secant stiffness of the constant-k Winkler circle divided by G(chi; theta/theta_up);
    M_found = K_R theta, M_imp = M_found - W h sin(theta), F = M_imp/(h cos theta).

    The coefficients, lost from [AD11], have no defaults (keyword-only; NaN says "not
    given", an error where the method needs it): k/k_el = kr_c1 - kr_c2 chi for chi > 0.1
    (1 below); a(chi) = sum a_poly[i] chi^i (a_poly: 5 numbers, a_0 .. a_4); b(chi) =
    b1 ln(chi) + b2; c(chi) = c1 chi + c2; G = 1 + a exp(-(log_B(x) - b)^2/(2 c^2)) with
    B = log_base (lost as well: no default; b and c are in its units). k_el: the elastic
    initial-stiffness ratio ([AD11]: 1 to 1.28; default 1).

    theta: rotations (rad, 1-d, ascending, >= 0); default n points from 0 to 1.25 times the
    overturning angle (or pi/4), half evenly spaced and half geometric from theta_up/20.
    Returns :class:`InelasticPushover`."""
    args = [_core.as_scalar(name, v) for name, v in (
        ("r", r), ("h", h), ("weight", weight), ("g_mod", g_mod), ("nu", nu), ("su", su))]
    coeffs = [_core.as_scalar("k_el", k_el), _core.as_scalar("kr_c1", kr_c1),
              _core.as_scalar("kr_c2", kr_c2)] + _gauss_coeffs(a_poly, b1, b2, c1, c2, log_base)

    def call(grid):
        return sp_clay_inelastic_pushover(*args, *coeffs, *_nc(nc), grid)

    def result(grid, out):
        curve, scalars, flags, kr_jump, stat, msg = out
        _core.raise_for_status(stat, msg, indexed={"theta": "theta"})
        return scalars, [np.array(curve[:, c - 1]) for c in _CURVE_COLUMNS], flags, kr_jump

    if theta is not None:
        grid = _core.as_float_array("theta", theta)
        if grid.ndim > 1:
            raise InvalidInputError(f"theta: must be a 1-d array of rotations (rad), got "
                                    f"shape {grid.shape}")
        grid = np.ascontiguousarray(grid.reshape(-1))
    else:
        from .winkler import _grid
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 4:
            raise InvalidInputError(f"n = {n!r}: must be an integer >= 4 (points of the curve)")
        end = np.pi / 4
        scalars, *_ = result(None, call(np.zeros(1)))
        grid = _grid(end, scalars[7], n)
        scalars, *_ = result(grid, call(grid))
        if np.isfinite(scalars[15]) and scalars[15] > 0.0:
            grid = _grid(min(end, 1.25 * scalars[15]), scalars[7], n)
    scalars, cols, flags, kr_jump = result(grid, call(grid))
    cols[0] = grid.copy()
    return InelasticPushover(*args[:3], *cols, *(float(s) for s in scalars),
                             *(bool(f) for f in flags), float(kr_jump))


def plot_inelastic(push, axes=None, title=None):
    """Draw an :class:`InelasticPushover` with matplotlib (an optional dependency): the
    normalized secant stiffness K_R/K_R0 against theta/theta_up (log axis) with the
    Gaussian correction, and the foundation and imposed moments (N m) against theta
    (rad), the overturning angle marked. axes: two matplotlib axes (default: a new
    figure). Returns the axes."""
    from .winkler import _pyplot
    if not isinstance(push, InelasticPushover):
        raise InvalidInputError("push: must be an InelasticPushover (inelastic_pushover)")
    plt = _pyplot("plot_inelastic")
    if axes is None:
        fig, axes = plt.subplots(1, 2, figsize=(11, 4))
        fig.suptitle(title or f"SF = {push.sf:.3g}, chi = {push.chi:.3g}")
    ax_k, ax_m = axes
    pos = push.x > 0
    ax_k.semilogx(push.x[pos], push.k_r[pos] / push.k_r0, color="C0", label="K_R / K_R0")
    ax_k.semilogx(push.x[pos], push.g_corr[pos], color="C1", linestyle="--",
                  label="G(chi; theta/theta_up)")
    ax_k.set_xlabel("theta / theta_up (-)")
    ax_k.set_ylabel("(-)")
    ax_m.plot(push.theta, push.m_found, color="C2", label="foundation moment")
    ax_m.plot(push.theta, push.m_imposed, color="C0", label="imposed moment")
    if np.isfinite(push.theta_overturn):
        ax_m.axvline(push.theta_overturn, color="C3", linestyle="-.", linewidth=0.9,
                     label=f"overturning {push.theta_overturn:.4g} rad")
    ax_m.axhline(0.0, color="0.8", linewidth=0.8)
    ax_m.set_xlabel("theta (rad)")
    ax_m.set_ylabel("moment (N m)")
    for ax in axes:
        ax.legend(loc="best", fontsize="small")
    return axes
