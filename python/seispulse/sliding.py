"""Rigid block sliding on a frictional plane under the exponential pulse (Ref. [GR],
chapter 1, corrected; Fortran modules ``seispulse_sliding_closed``, ``seispulse_sliding_norm``
and ``seispulse_sliding_sim``).

Dimensionless, as in the chapter: ``tau = t / t_d``, ``eta = a_y / A_g`` (``mu g / A_g``
on a horizontal plane), velocities in ``A_g t_d`` or ``V_g``, displacements in
``A_g t_d^2``; ``beta`` is the shape of :func:`seispulse.pulse.exp_pulse` (-inf box,
0 triangle, +inf spike). :func:`block` is the SI entry point (metres, seconds) and
:func:`simulate` the event-driven stick-slip integrator that checks every closed form,
for any pulse or a sampled accelerogram.

Parameters broadcast like numpy ufuncs; scalars in give Python scalars out.
``eta >= 1`` is not an error: there is no sliding, with zero displacement.
"""

import warnings
from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_basic_lengths, sp_block, sp_characteristic_length,
                         sp_eta_critical, sp_eta_critical_regression, sp_fetch_slides,
                         sp_full_cycle, sp_full_cycle_integrated, sp_half_cycle,
                         sp_half_cycle_integrated, sp_inclined, sp_limit_form, sp_stickslip,
                         sp_table_1_2, sp_table_1_3, sp_yield_time)
from .errors import InvalidInputError
from .pulse import STANDARD_GRAVITY, _excitation

__all__ = ["REGIMES", "MODES", "HalfCycle", "FullCycle", "Resistances", "BlockResponse",
           "yield_time", "half_cycle", "full_cycle", "inclined_resistances", "block",
           "eta_critical", "full_cycle_peak_regression", "rectangle_half", "rectangle_full",
           "triangle_half", "spike_velocity_ratio", "characteristic_length", "basic_lengths",
           "BASIC_LENGTHS", "table_1_2", "table_1_3", "Slide", "Simulation", "simulate"]

#: Regimes of a half-cycle slide, by code: no sliding, stop during the pulse
#: (tau_m <= 1), stop after it.
REGIMES = _core.by_code({_f.SLIDING_REGIME_NONE: "none", _f.SLIDING_REGIME_FORCED: "forced",
                         _f.SLIDING_REGIME_FREE: "free"})

#: Full-cycle modes, by code (doc/sliding.md sections 5, 7).
MODES = _core.by_code({_f.SLIDING_MODE_NO_SLIDING: "no_sliding",
                       _f.SLIDING_MODE_UNILATERAL: "unilateral", _f.SLIDING_MODE_STICK: "stick",
                       _f.SLIDING_MODE_SLIP: "slip", _f.SLIDING_MODE_STUCK: "stuck",
                       _f.SLIDING_MODE_REVERSE_ONLY: "reverse_only"})

HalfCycle = namedtuple("HalfCycle", ["tau_y", "tau_m", "regime", "um", "dugm", "vm"])
HalfCycle.__doc__ = """Half-cycle response: onset tau_y and stop tau_m (t/t_d; NaN
without sliding), regime ('none', 'forced' tau_m <= 1, 'free' tau_m > 1), peak slip
um = u_m/(A_g t_d^2) (also the residual), ground displacement over the slide
dugm = du_gm/(A_g t_d^2), peak sliding velocity vm = V_m/V_g."""

FullCycle = namedtuple("FullCycle", ["mode", "tau_y1", "tau_m1", "um1", "tau_y2", "tau_m2",
                                     "um2", "ures", "vm1", "vm2"])
FullCycle.__doc__ = """Full-cycle response, times t/t_d from the start of the pulse,
slips in A_g t_d^2: forward onset/stop/slip (tau_y1, tau_m1, um1 = peak slip), reverse
onset/stop/slip (tau_y2, tau_m2, um2 >= 0; NaN times without a reverse slide), residual
ures = um1 - um2 (negative when the reverse slide is larger), peak sliding velocities
vm1, vm2 over V_g. mode: 'no_sliding', 'unilateral' (eta2 >= 1), 'stick', 'slip',
'stuck' (eta2 < 1 but the forward slide outlasts the reverse window) or
'reverse_only' (eta1 >= 1 > eta2)."""

Resistances = namedtuple("Resistances", ["eta1", "eta2", "k1", "k2"])
Resistances.__doc__ = """Resistances to downhill (eta1) and uphill (eta2) sliding over
A_g (+inf: the pulse cannot drive the block that way), and the along-plane factors
k1, k2: the slip along the plane is k times the slip of the dimensionless problem."""

BlockResponse = namedtuple("BlockResponse", ["mode", "eta1", "eta2", "t_y1", "t_m1", "u_m1",
                                             "t_y2", "t_m2", "u_m2", "u_res", "v_m1",
                                             "v_m2"])
BlockResponse.__doc__ = """Block on an incline in SI: mode (as FullCycle), resistances
eta1, eta2 (over A_g), onset/stop times (s, from the start of the pulse), slips along
the plane (m; u_m1 downhill = the peak, u_m2 uphill >= 0, u_res downhill positive) and
peak sliding velocities v_m1, v_m2 (m/s)."""

#: Names of the six basic lengths of Eq. 1.28 a-f, in the order returned.
BASIC_LENGTHS = ("Ag*t^2", "Vg^2/Ag", "Dg", "Vg*t", "Vg*Dg/(Ag*t)", "Ag*Dg*t/Vg")

_METHODS = ("closed", "integrator")


def _flat_all(shape, arrays):
    return [_core.flat(arrays[k], shape) for k in arrays]


# ------------------------------------------------------------------------ onset, cycles

def yield_time(eta, beta, static_factor=1.0):
    """Onset of sliding tau_y = t_y/t_d (Eq. 1.12; with static friction a*eta at the
    onset, Eq. 1.34): ln(1 - a eta (1 - e^beta)) / (2 beta).

    eta > 0 (a_y/A_g), beta any real or +-inf, static_factor a >= 1 (1: none).
    NaN when a*eta >= 1 (no sliding). beta = 0 gives a eta / 2, -inf gives 0, +inf 1/2.
    """
    shape, arr = _core.broadcast(eta=eta, beta=beta, static_factor=static_factor)
    tau, stat, msg = sp_yield_time(*_flat_all(shape, arr))
    _core.raise_for_status(stat, msg)
    return _core.shaped(shape, tau)[0]


def half_cycle(eta, beta, static_factor=1.0, method="closed"):
    """Response to a half-cycle exponential pulse (section 3 of doc/sliding.md).

    Parameters
    ----------
    eta : float or array
        a_y/A_g > 0; >= 1 gives regime 'none' and zero slip.
    beta : float or array
        Pulse shape (any real, +-inf).
    static_factor : float or array
        a >= 1: onset at a*eta (static friction, Eq. 1.34), sliding at eta.
    method : {'closed', 'integrator'}
        The closed forms, or the same quantities from the event-driven integrator
        (:func:`simulate` on the dimensionless pulse): the check of the closed forms.

    Returns
    -------
    HalfCycle
        tau_y, tau_m, regime, um, dugm, vm (see :class:`HalfCycle`).
    """
    run = {"closed": sp_half_cycle, "integrator": sp_half_cycle_integrated}[
        _core.check_choice("method", method, _METHODS)]
    shape, arr = _core.broadcast(eta=eta, beta=beta, static_factor=static_factor)
    tau_y, tau_m, regime, um, dugm, vm, stat, msg = run(*_flat_all(shape, arr))
    _core.raise_for_status(stat, msg)
    tau_y, tau_m, um, dugm, vm = _core.shaped(shape, tau_y, tau_m, um, dugm, vm)
    return HalfCycle(tau_y, tau_m, _core.names(REGIMES, regime, shape), um, dugm, vm)


def full_cycle(eta1, beta, eta2=None, static_factor=1.0, static_reverse=False,
               method="closed"):
    """Response to a full-cycle exponential pulse: forward slide, stick or slip, reverse
    slide (Tables 1.1 and 1.4, corrected; doc/sliding.md sections 4, 5, 7).

    Parameters
    ----------
    eta1 : float or array
        Resistance to forward (downhill) sliding over A_g, > 0.
    beta : float or array
        Pulse shape.
    eta2 : float or array, optional
        Resistance to reverse (uphill) sliding over A_g, > 0 (default eta1).
    static_factor : float or array
        a >= 1: static friction a*eta at the first onset.
    static_reverse : bool
        Static friction also at the reverse onset.
    method : {'closed', 'integrator'}
        The closed forms, or the event-driven integrator on the same pulse.

    Returns
    -------
    FullCycle
    """
    if eta2 is None:
        eta2 = eta1
    static_reverse = _core.check_bool("static_reverse", static_reverse)
    run = {"closed": sp_full_cycle, "integrator": sp_full_cycle_integrated}[
        _core.check_choice("method", method, _METHODS)]
    shape, arr = _core.broadcast(eta1=eta1, eta2=eta2, beta=beta, static_factor=static_factor)
    (mode, tau_y1, tau_m1, um1, tau_y2, tau_m2, um2, ures, vm1, vm2, stat,
     msg) = run(*_flat_all(shape, arr), int(static_reverse))
    _core.raise_for_status(stat, msg)
    return FullCycle(_core.names(MODES, mode, shape),
                     *_core.shaped(shape, tau_y1, tau_m1, um1, tau_y2, tau_m2, um2, ures, vm1,
                                   vm2))


def inclined_resistances(mu, ag_over_g, slope_deg, xi_deg=0.0):
    """Direction-dependent resistances on an incline (Eq. 1.31, doc/sliding.md section 7).

    mu > 0 friction coefficient, ag_over_g = A_g/g > 0, slope_deg in [0, 90) (a slope
    steeper than the friction angle atan(mu) is an error: the block would slide without
    any excitation), xi_deg in [-90, 90] the angle of the pulse to the horizontal,
    measured in the same sense as the slope (xi = slope_deg: along the plane).
    Returns :class:`Resistances` (eta1 downhill, eta2 uphill, k1, k2).
    """
    shape, arr = _core.broadcast(mu=mu, ag_over_g=ag_over_g, slope_deg=slope_deg,
                                 xi_deg=xi_deg)
    eta1, eta2, k1, k2, stat, msg = sp_inclined(*_flat_all(shape, arr))
    _core.raise_for_status(stat, msg, rename={"ag": "ag_over_g"})
    return Resistances(*_core.shaped(shape, eta1, eta2, k1, k2))


def block(mu, ag_over_g, td, beta, full=False, slope_deg=0.0, xi_deg=0.0, static_factor=1.0,
          static_reverse=False, along_plane=True, g=STANDARD_GRAVITY):
    """A block of friction mu on a plane of slope lambda = slope_deg hit by an exponential
    pulse of amplitude A_g = ag_over_g * g and lobe duration t_d = td (s; a full cycle
    lasts 2 t_d). Returns :class:`BlockResponse` in s, m and m/s.

    Sign conventions (doc/sliding.md sections 1, 7): the first lobe drives the block downhill
    (positive slips are downhill). xi_deg is the angle of the pulse to the horizontal,
    measured in the same sense as the slope: xi = 0 horizontal, xi = slope_deg along the
    plane, both pointing towards downhill.

    along_plane: slips and velocities along the plane, with the factors K of
    doc/sliding.md section 7 (False: without them, as the chapter's example 1.9.2 does).
    g: gravity (m/s^2) converting A_g to m/s^2.
    """
    full = _core.check_bool("full", full)
    static_reverse = _core.check_bool("static_reverse", static_reverse)
    along_plane = _core.check_bool("along_plane", along_plane)
    g = _core.check_positive("g", g, " (m/s^2)")
    shape, arr = _core.broadcast(mu=mu, ag_over_g=ag_over_g, td=td, beta=beta,
                                 slope_deg=slope_deg, xi_deg=xi_deg,
                                 static_factor=static_factor)
    f = dict(zip(arr, _flat_all(shape, arr)))
    (mode, eta1, eta2, t_y1, t_m1, u_m1, t_y2, t_m2, u_m2, u_res, v_m1, v_m2, stat,
     msg) = sp_block(f["mu"], f["ag_over_g"], f["td"], f["beta"], int(full), f["slope_deg"],
                     f["xi_deg"], f["static_factor"], int(static_reverse), int(along_plane), g)
    _core.raise_for_status(stat, msg, rename={"ag": "ag_over_g"})
    return BlockResponse(_core.names(MODES, mode, shape),
                         *_core.shaped(shape, eta1, eta2, t_y1, t_m1, u_m1, t_y2, t_m2, u_m2,
                                       u_res, v_m1, v_m2))


# ------------------------------------------------------------ stick/slip, regressions

def eta_critical(beta, method="exact"):
    """Critical strength of the symmetric full cycle: the block slips (reverses at once)
    for eta < eta_cr and sticks above (doc/sliding.md section 5).

    method='exact': the root of tau_m1(eta) = 1 + tau_y(eta) (1 for beta = -inf, 0 for
    +inf). method='regression': the chapter's fit, Eq. 1.22, 0.1 + 0.8 exp(-exp(0.25 beta
    - 0.15)), fitted on -4 pi <= beta <= 4 pi (a warning outside).
    """
    _core.check_choice("method", method, ("exact", "regression"))
    beta_arr = _core.as_float_array("beta", beta)
    shape = beta_arr.shape
    if method == "regression":
        finite = beta_arr[~np.isnan(beta_arr)]
        if np.any(np.abs(finite) > 4 * np.pi):
            warnings.warn("eta_critical: the regression 1.22 was fitted on "
                          "-4 pi <= beta <= 4 pi", stacklevel=2)
    run = sp_eta_critical if method == "exact" else sp_eta_critical_regression
    eta_cr, stat, msg = run(_core.flat(beta_arr, shape))
    _core.raise_for_status(stat, msg)
    return _core.shaped(shape, eta_cr)[0]


def _check_eta_open(eta, name="eta", upper_closed=False):
    arr = _core.as_float_array(name, eta)
    bad = ~((arr > 0) & ((arr <= 1) if upper_closed else (arr < 1)))
    if np.any(bad):
        value = float(arr.reshape(-1)[np.argmax(bad.reshape(-1))])
        limit = "0 < eta <= 1" if upper_closed else "0 < eta < 1"
        raise InvalidInputError(f"{name} = {value!r}: must satisfy {limit}")
    return arr


def _limit_form(which, eta, ncol, upper_closed=False, first_col=None):
    arr = _check_eta_open(eta, upper_closed=upper_closed)
    shape = arr.shape
    e = _core.flat(arr, shape)
    out = np.zeros((e.size, 5), order="F")
    if first_col is not None:
        out[:, 0] = first_col
    out = sp_limit_form(which, e, out)
    return _core.shaped(shape, *(np.ascontiguousarray(out[:, j]) for j in range(ncol)))


def full_cycle_peak_regression(eta, beta):
    """The chapter's fit of the full-cycle peak slip, Eq. 1.30: u_m/D_g = (1 - eta)^f
    with f = -9 + 12 e^(beta/20) (beta > 0) or (3 - 0.9 beta)/(1 - 0.6 beta) (beta <= 0),
    D_g = V_g t_d. An approximation only (large relative errors at high eta)."""
    shape, arr = _core.broadcast(eta=eta, beta=beta)
    e = _core.flat(arr["eta"], shape)
    if np.any(~(e > 0)):
        raise InvalidInputError(f"eta = {e[np.argmax(~(e > 0))]!r}: must be > 0")
    b = _core.flat(arr["beta"], shape)
    if np.any(np.isnan(b)):
        raise InvalidInputError("beta = nan: must be a real number or +-inf")
    out = np.zeros((e.size, 5), order="F")
    out[:, 0] = b
    out = sp_limit_form(5, e, out)
    return _core.shaped(shape, np.ascontiguousarray(out[:, 0]))[0]


def rectangle_half(eta):
    """Rectangular half cycle (beta = -inf; Eq. 1.10a, Newmark 1965), 0 < eta < 1:
    (tau_m, um, um/dugm, vm) = (1/eta, (1-eta)/(2 eta), (1-eta)/(2-eta), 1-eta)."""
    return _limit_form(1, eta, 4)


def rectangle_full(eta):
    """Rectangular full cycle (doc/sliding.md section 5), 0 < eta < 1; always slip:
    (tau_m1, um1, tau_m2, um2, ures) = (2/(1+eta), q, 4/(1+eta), 2 eta q/(1+eta), q^2)
    with q = (1-eta)/(1+eta)."""
    return _limit_form(2, eta, 5)


def triangle_half(eta):
    """Triangular half cycle (beta = 0; Eq. 1.10b with its sign corrected: doc/sliding.md,
    Corrections 3), 0 < eta < 1: (tau_y, tau_m, um, vm, regime) in closed form
    (doc/sliding.md section 3)."""
    tau_y, tau_m, um, vm, code = _limit_form(3, eta, 5)
    shape = np.shape(tau_y)
    return tau_y, tau_m, um, vm, _core.names(REGIMES, np.asarray(code, dtype=int), shape)


def spike_velocity_ratio(eta):
    """V_m/V_g under the spike (beta -> +inf): 1 - eta (1 - ln eta), 0 < eta <= 1, the
    lower bound over all shapes (doc/sliding.md section 3)."""
    return _limit_form(4, eta, 1, upper_closed=True)[0]


# ---------------------------------------------------------------------- normalization

def characteristic_length(a, b, c, d, ag, vg, dg, td):
    """D_c = A_g^a V_g^b D_g^c t^d (Eq. 1.25) with a + b + c = 1 and 2a + b = d checked
    (Eq. 1.26); ag (m/s^2), vg (m/s), dg (m), td (s) > 0; D_c in m."""
    shape, arr = _core.broadcast(a=a, b=b, c=c, d=d, ag=ag, vg=vg, dg=dg, td=td)
    dc, stat, msg = sp_characteristic_length(*_flat_all(shape, arr))
    _core.raise_for_status(stat, msg)
    return _core.shaped(shape, dc)[0]


def basic_lengths(ag, vg, dg, td):
    """The six basic lengths of Eq. 1.28 a-f (m), in the order of :data:`BASIC_LENGTHS`:
    A_g t^2, V_g^2/A_g, D_g, V_g t, V_g D_g/(A_g t), A_g D_g t/V_g. Array of shape
    (..., 6)."""
    shape, arr = _core.broadcast(ag=ag, vg=vg, dg=dg, td=td)
    out, stat, msg = sp_basic_lengths(*_flat_all(shape, arr))
    _core.raise_for_status(stat, msg)
    return np.ascontiguousarray(out).reshape(shape + (6,))


def table_1_2(table, rows=range(-4, 5), cols=range(-4, 5)):
    """Table 1.2 `table` ('a'..'f') generated from Eqs. 1.27: the exponents (a, b, c, d)
    of A_g, V_g, D_g, t for every (row, column) pair, shape (len(rows), len(cols), 4).
    Free exponents (row, column): a (b, a), b (c, a), c (d, a), d (c, b), e (d, b),
    f (d, c)."""
    _core.check_choice("table", table, ("a", "b", "c", "d", "e", "f"))
    r = np.ascontiguousarray(_core.as_float_array("rows", list(rows)).reshape(-1))
    c = np.ascontiguousarray(_core.as_float_array("cols", list(cols)).reshape(-1))
    exps, stat, msg = sp_table_1_2(table, r, c)
    _core.raise_for_status(stat, msg)
    return np.array(exps)


def table_1_3(beta, full=False):
    """Table 1.3: the six basic lengths over A_g t_d^2 for the exponential pulse (order
    of :data:`BASIC_LENGTHS`; Eq. 1.29 with n = 2 half cycle, 1 full cycle). beta finite
    or -inf. Array of shape (..., 6)."""
    full = _core.check_bool("full", full)
    beta_arr = _core.as_float_array("beta", beta)
    shape = beta_arr.shape
    out, stat, msg = sp_table_1_3(_core.flat(beta_arr, shape), int(full))
    _core.raise_for_status(stat, msg)
    return np.ascontiguousarray(out).reshape(shape + (6,))


# ---------------------------------------------------------------------- integrator

Slide = namedtuple("Slide", ["direction", "t_start", "t_stop", "u_start", "u_stop",
                             "w_peak", "t_peak", "from_slip"])
Slide.__doc__ = """One sliding interval of :func:`simulate`: direction +1 (forward) or -1,
onset and stop times, relative displacement at both, the largest |u'| and its time,
and whether it began as an immediate reversal at the previous stop ("slip")."""

Simulation = namedtuple("Simulation", ["slides", "u_final", "u_max", "u_min", "t_end",
                                       "t", "u", "w"])
Simulation.__doc__ = """Result of :func:`simulate`: the list of :class:`Slide`, the final,
largest and smallest relative displacement, the time the block comes to rest for good,
and, when a time grid was given, t with u(t) and u'(t) (else None)."""


def simulate(pulse=None, ay=None, *, accel=None, dt=None, ay_rev=None, static_factor=1.0,
             static_all=False, t=None):
    """Event-driven stick-slip integration of u'' = a_g(t) - ay_dir sgn(u') from rest
    (doc/sliding.md section 9): onsets and stops are located by root finding on the analytic
    relative velocity, never on a fixed time step.

    u is the slip of the block relative to the plane, positive in the sense a positive
    ground acceleration drives it ("forward"; doc/sliding.md section 1). Results are in the units
    of the input: times in the pulse's time unit (s for SI pulses, or of dt), u in
    acceleration units x time^2 (m for SI), u' in acceleration units x time (m/s).

    Parameters
    ----------
    pulse : seispulse.pulse.Pulse, optional
        Any pulse, from :func:`seispulse.pulse.define`. The dimensionless problem of
        the closed forms is ``define('exponential', amp=1, duration=1, beta=b,
        full=...)`` with ``ay = eta``.
    ay : float
        Kinetic resistance to forward (positive) sliding, in the units of the ground
        acceleration (m/s^2 for an SI pulse), > 0; +inf: no forward sliding.
    accel, dt : array, float, optional
        Instead of a pulse: a sampled accelerogram, accel[i] at t = i dt, linear in
        between, zero after the last sample (the block slides to rest).
    ay_rev : float, optional
        Resistance to reverse sliding (default ay).
    static_factor : float
        >= 1: onset needs static_factor * ay (first onset; every onset from rest with
        static_all).
    t : array, optional
        Ascending times for the histories u(t) and u'(t).

    Returns
    -------
    Simulation
    """
    if (pulse is None) == (accel is None):
        raise InvalidInputError("pulse, accel: give exactly one of them")
    if ay is None:
        raise InvalidInputError("ay: the resistance to forward sliding is required")
    ay = _core.as_scalar("ay", ay)
    ay_rev = ay if ay_rev is None else _core.as_scalar("ay_rev", ay_rev)
    static_factor = _core.as_scalar("static_factor", static_factor)
    static_all = _core.check_bool("static_all", static_all)
    kind, params, rec, step, grid = _excitation(
        pulse, accel, dt, "dt: must be the time step (> 0) of accel", t)
    with _core.HELD_LOCK:
        ug, wg, nslides, u_final, u_max, u_min, t_end, stat, msg = sp_stickslip(
            kind, params, rec, step, ay, ay_rev, static_factor, int(static_all), grid)
        fields = sp_fetch_slides(nslides if stat == 0 else 0)
    _core.raise_for_status(stat, msg, rename={"ay_fwd": "ay", "t_grid": "t"})
    out = _core.slides(Slide, fields)
    hist = (None, None, None) if t is None else (grid.copy(), ug.copy(), wg.copy())
    return Simulation(out, float(u_final), float(u_max), float(u_min), float(t_end), *hist)

