"""Idealized ground-motion pulses: acceleration, velocity and displacement in
closed form (Fortran module ``seispulse_pulses``).

Every pulse starts from rest: ``a = v = d = 0`` for ``t < 0``, and ``v``, ``d`` are
the exact integrals of ``a`` from ``t = 0``. At a jump the acceleration takes the
value after the jump.

Two families:

* the generalized exponential pulse of Jacobsen & Ayre, dimensionless
  (:func:`exp_pulse`, :func:`exp_pulse_peaks`, :func:`exp_pulse_impulse_amplitude`)
  and in SI (:func:`exponential`);
* the classic pulses in SI: :func:`half_sine`, :func:`sine_cycle`,
  :func:`cosine_cycle`, :func:`rectangular`, :func:`triangular`, :func:`ricker`,
  :func:`mavroeidis_papageorgiou`, or any of them by name with :func:`evaluate`.

Parameters broadcast like numpy ufuncs: scalars in give Python floats out, arrays
give arrays of the broadcast shape. SI results are :class:`PulseHistory` tuples
``(a, v, d)`` in m/s^2, m/s and m.
"""

from collections import namedtuple

import numpy as np

from . import _core, _fortran_codes
from ._seispulse import (sp_exp_pulse, sp_exp_pulse_impulse_amplitude, sp_exp_pulse_peaks,
                         sp_pulse_eval, sp_pulse_kind)
from .errors import InvalidInputError

__all__ = ["PulseHistory", "PulsePeaks", "Pulse", "STANDARD_GRAVITY", "KINDS", "exp_pulse",
           "exp_pulse_peaks", "exp_pulse_impulse_amplitude", "exponential", "half_sine",
           "sine_cycle", "cosine_cycle", "rectangular", "triangular", "ricker",
           "mavroeidis_papageorgiou", "evaluate", "define"]

#: Standard gravity (m/s^2), the default ``g`` for amplitudes given in g.
STANDARD_GRAVITY = 9.80665

#: Pulse kinds accepted by :func:`evaluate` (aliases: exp, sine, cosine, rect,
#: triangle, mp).
KINDS = ("exponential", "half_sine", "sine_cycle", "cosine_cycle", "rectangular",
         "triangular", "ricker", "mavroeidis_papageorgiou")

PulseHistory = namedtuple("PulseHistory", ["a", "v", "d"])
PulseHistory.__doc__ = """Pulse time history.

SI functions: a (m/s^2), v (m/s), d (m). :func:`exp_pulse`: a / A_g, v / (A_g t_d),
d / (A_g t_d^2)."""

PulsePeaks = namedtuple("PulsePeaks", ["vg", "dg"])
PulsePeaks.__doc__ = """Peaks of the exponential pulse: vg = V_g / (A_g t_d),
dg = D_g / (A_g t_d^2)."""

Pulse = namedtuple("Pulse", ["kind", "code", "params"])
Pulse.__doc__ = """A validated pulse to hand to other modules (:func:`define`): its kind
name, the Fortran kind code and the packed SI parameter vector of pulse_from_params."""

# Passed as t by define(): _evaluate then returns the packed pulse instead of values.
_DEFINE = object()

# Order of the packed parameter vector of Fortran pulse_from_params: the positions
# PULSE_PARAM_<NAME> generated from the Fortran source.
_PARAM_ORDER = tuple(name[len("PULSE_PARAM_"):].lower() for name, _ in sorted(
    ((n, v) for n, v in vars(_fortran_codes).items() if n.startswith("PULSE_PARAM_")),
    key=lambda item: item[1]))
_PARAM_DEFAULTS = {"amp": 1.0, "duration": 1.0, "beta": 0.0, "full": 0.0, "peak_frac": 0.5,
                   "freq": 1.0, "t0": 0.0, "gamma": 2.0, "nu_deg": 0.0,
                   "cycles": 1.0}


# ------------------------------------------------------------------ exponential pulse

def exp_pulse(tau, beta, full=False):
    """Exponential pulse of Jacobsen & Ayre, dimensionless (doc/pulses.md Eq. 1.1b).

    Parameters
    ----------
    tau : float or array
        Time over the half-cycle duration, t / t_d (finite; < 0 is before the pulse).
    beta : float or array
        Shape: -inf box, -pi roughly a half sine, 0 triangle, +inf spike. Any real
        number or +-inf; broadcasts with ``tau``.
    full : bool
        Full cycle (a positive lobe on [0, 1], its negative mirror on [1, 2]) instead
        of a half cycle.

    Returns
    -------
    PulseHistory
        a / A_g, v / (A_g t_d), d / (A_g t_d^2). After a half cycle the ground keeps
        the velocity V_g; after a full cycle it rests at displacement D_g.
    """
    full = _core.check_bool("full", full)
    shape, arr = _core.broadcast(empty_ok=True, tau=tau, beta=beta)
    a, v, d, stat, msg = sp_exp_pulse(_core.flat(arr["tau"], shape),
                                      _core.compact(arr["beta"], shape), int(full))
    _core.raise_for_status(stat, msg)
    return PulseHistory(*_core.shaped(shape, a, v, d))


def exp_pulse_peaks(beta, full=False):
    """Peak ground velocity and displacement of the exponential pulse (Table 1.3).

    Returns PulsePeaks(vg, dg): vg = V_g / (A_g t_d) = 1/(1 - e^beta) + 1/beta (1 for
    the box, 1/2 for the triangle, 0 for the spike), reached at t_d; dg = D_g /
    (A_g t_d^2) = vg / 2 for a half cycle (the displacement at t_d) and vg for a
    full cycle (reached at 2 t_d and kept).
    """
    full = _core.check_bool("full", full)
    shape, arr = _core.broadcast(empty_ok=True, beta=beta)
    vg, dg, stat, msg = sp_exp_pulse_peaks(_core.flat(arr["beta"], shape), int(full))
    _core.raise_for_status(stat, msg)
    return PulsePeaks(*_core.shaped(shape, vg, dg))


def exp_pulse_impulse_amplitude(beta):
    """Amplitude A_g, in units of I / t_d, of the exponential lobe of impulse (area) I.

    Equals 1 / vg (the unit-impulse normalization of doc/pulses.md section 1, unit impulse);
    +inf for the spike, whose normalized form tends to a Dirac delta at t_d / 2.
    """
    shape, arr = _core.broadcast(empty_ok=True, beta=beta)
    amp, stat, msg = sp_exp_pulse_impulse_amplitude(_core.flat(arr["beta"], shape))
    _core.raise_for_status(stat, msg)
    return _core.shaped(shape, amp)[0]


# ------------------------------------------------------------------ SI pulses

def _amplitude(amp, amp_unit, g):
    """Amplitude in m/s^2 from a value in ``amp_unit``: 'g' (times g), 'm/s2' (as is),
    'cm/s2' (/ 100), with the aliases 'm/s^2', 'cm/s^2', 'gal', any case (the library's
    one vocabulary of acceleration units, as in the driver): amp times g times the
    library's factor to g (accel_unit_factor)."""
    from .records import accel_unit_factor
    code = _core.accel_unit_code("amp_unit", amp_unit)
    if code == _fortran_codes.UNITS_M_S2:
        return amp        # as given: no rounding through g
    g = _core.check_positive("g", g, " (m/s^2)")
    return _core.as_float_array("amp", amp) * (g * accel_unit_factor(amp_unit, g))


def _evaluate(kind, t, rename=None, **params):
    """Broadcast t and the parameters, pack them and call the Fortran evaluator."""
    code, stat, msg = sp_pulse_kind(kind)
    _core.raise_for_status(stat, msg)
    if t is _DEFINE:
        return _define(kind, code, rename, params)
    shape, arr = _core.broadcast(empty_ok=True, t=t, **params)
    values = {name: arr.get(name, np.float64(_PARAM_DEFAULTS[name])) for name in _PARAM_ORDER}
    if all(np.size(values[name]) == 1 for name in _PARAM_ORDER):
        packed = np.array([[float(np.reshape(values[n], -1)[0]) for n in _PARAM_ORDER]],
                          order="F")
    else:
        packed = np.asfortranarray(np.stack([_core.flat(values[n], shape)
                                             for n in _PARAM_ORDER], axis=1))
    a, v, d, stat, msg = sp_pulse_eval(code, _core.flat(arr["t"], shape), packed)
    _core.raise_for_status(stat, msg, rename)
    return PulseHistory(*_core.shaped(shape, a, v, d))


def exponential(t, amp, td, beta, full=False, amp_unit="m/s2", g=STANDARD_GRAVITY):
    """Exponential pulse in SI: A_g = ``amp``, half-cycle duration ``td`` (s).

    a = A_g a~(t/t_d), v = A_g t_d v~, d = A_g t_d^2 d~ with the dimensionless
    :func:`exp_pulse`. ``amp`` is in m/s^2, or in g with ``amp_unit='g'`` (times
    ``g``, default standard gravity). Returns PulseHistory in m/s^2, m/s, m.
    """
    full = _core.check_bool("full", full)
    return _evaluate("exponential", t, rename={"duration": "td"},
                     amp=_amplitude(amp, amp_unit, g), duration=td, beta=beta,
                     full=float(full))


def half_sine(t, amp, duration, amp_unit="m/s2", g=STANDARD_GRAVITY):
    """Half-sine acceleration pulse a = A sin(pi t / T) for 0 <= t < T (T = ``duration``, s).

    After the pulse the ground keeps the velocity 2 A T / pi. Returns PulseHistory
    in m/s^2, m/s, m.
    """
    return _evaluate("half_sine", t, amp=_amplitude(amp, amp_unit, g), duration=duration)


def sine_cycle(t, amp, period, cycles=1, amp_unit="m/s2", g=STANDARD_GRAVITY):
    """Sine acceleration pulse of n cycles, a = A sin(2 pi t / T_p) for 0 <= t < n T_p.

    ``amp`` = A (m/s^2, or g with ``amp_unit='g'``), ``period`` = T_p (s), ``cycles`` = n,
    a whole number 1 <= n <= 10^6 (default 1; e.g. 20 cycles of harmonic shaking).
    The velocity v = A T_p sin^2(pi t / T_p) / pi returns to zero at every cycle end;
    the displacement grows by A T_p^2 / (2 pi) per cycle and the ground keeps
    n A T_p^2 / (2 pi) after the pulse (a fling step). Returns PulseHistory in m/s^2,
    m/s, m.
    """
    return _evaluate("sine_cycle", t, rename={"duration": "period"},
                     amp=_amplitude(amp, amp_unit, g), duration=period, cycles=cycles)


def cosine_cycle(t, amp, period, cycles=1, amp_unit="m/s2", g=STANDARD_GRAVITY):
    """Cosine acceleration pulse of n cycles, a = A cos(2 pi t / T_p) for 0 <= t < n T_p.

    ``amp`` = A (m/s^2, or g with ``amp_unit='g'``), ``period`` = T_p (s), ``cycles`` = n,
    a whole number 1 <= n <= 10^6 (default 1). The acceleration jumps to A at t = 0
    and back to 0 at n T_p; velocity and displacement are periodic and return to zero
    at every cycle end. Returns PulseHistory in m/s^2, m/s, m.
    """
    return _evaluate("cosine_cycle", t, rename={"duration": "period"},
                     amp=_amplitude(amp, amp_unit, g), duration=period, cycles=cycles)


def rectangular(t, amp, duration, amp_unit="m/s2", g=STANDARD_GRAVITY):
    """Rectangular acceleration pulse a = A for 0 <= t < T (the exponential pulse with
    beta = -inf). Returns PulseHistory in m/s^2, m/s, m."""
    return _evaluate("rectangular", t, amp=_amplitude(amp, amp_unit, g), duration=duration)


def triangular(t, amp, duration, peak_frac=0.5, amp_unit="m/s2", g=STANDARD_GRAVITY):
    """Triangular acceleration pulse: 0 at t = 0, A at t = r T, 0 at t = T, with
    r = ``peak_frac`` in [0, 1] (0: jump then linear decay; 1: linear rise to a jump;
    0.5: the exponential pulse with beta = 0). Returns PulseHistory in m/s^2, m/s, m."""
    return _evaluate("triangular", t, amp=_amplitude(amp, amp_unit, g), duration=duration,
                     peak_frac=peak_frac)


def ricker(t, amp, freq, t0=None, amp_unit="m/s2", g=STANDARD_GRAVITY):
    """Ricker wavelet a = a_p (1 - 2 pi^2 f_p^2 (t - t0)^2) exp(-pi^2 f_p^2 (t - t0)^2).

    ``amp`` = a_p is the peak acceleration, reached at ``t0`` (s, default 1.5 / f_p,
    where the wavelet has decayed to 1e-8 of its peak); ``freq`` = f_p (Hz) is the
    frequency of the Fourier amplitude peak (omega_p = 2 pi f_p gives Makris' form).
    The wavelet is zero before t = 0; v and d integrate it from there. Returns
    PulseHistory in m/s^2, m/s, m.
    """
    if t0 is None:
        with np.errstate(divide="ignore", invalid="ignore"):  # bad freq is reported below
            t0 = 1.5 / _core.as_float_array("freq", freq)
    return _evaluate("ricker", t, amp=_amplitude(amp, amp_unit, g), freq=freq, t0=t0)


def mavroeidis_papageorgiou(t, vamp, freq, gamma, nu_deg=0.0, t0=None):
    """Mavroeidis & Papageorgiou (2003) near-fault velocity pulse.

    v = (A/2) [1 + cos(2 pi f_p (t - t0) / gamma)] cos(2 pi f_p (t - t0) + nu) for
    |t - t0| <= gamma / (2 f_p), zero outside; a is its derivative and d its integral
    from the start of the pulse (M&P pulses generally leave a residual displacement).

    Parameters: ``vamp`` = A (m/s), ``freq`` = f_p (Hz), ``gamma`` > 1, ``nu_deg`` = nu
    (degrees), ``t0`` = time of the envelope peak (s, default gamma / (2 f_p), so the
    pulse starts at t = 0; it must not start earlier). Returns PulseHistory in
    m/s^2, m/s, m.
    """
    if t0 is None:
        with np.errstate(divide="ignore", invalid="ignore"):  # bad freq is reported below
            t0 = _core.as_float_array("gamma", gamma) / (2.0 * _core.as_float_array("freq", freq))
    return _evaluate("mavroeidis_papageorgiou", t, amp=vamp, freq=freq, gamma=gamma,
                     nu_deg=nu_deg, t0=t0, rename={"amp": "vamp"})


def _define(kind, code, rename, params):
    """The packed, validated parameters of one pulse (scalars only)."""
    values = {name: _core.as_float_array(name, params.get(name, _PARAM_DEFAULTS[name]))
              for name in _PARAM_ORDER}
    for name, value in values.items():
        if value.size != 1:
            shown = (rename or {}).get(name, name)
            raise InvalidInputError(f"{shown}: define() takes one value per parameter")
    packed = np.array([[float(values[n].reshape(-1)[0]) for n in _PARAM_ORDER]], order="F")
    *_, stat, msg = sp_pulse_eval(code, np.zeros(1), packed)   # validates
    _core.raise_for_status(stat, msg, rename)
    return Pulse(kind, int(code), packed[0].copy())


_BY_NAME = {
    "exponential": exponential, "exp": exponential,
    "half_sine": half_sine,
    "sine_cycle": sine_cycle, "sine": sine_cycle,
    "cosine_cycle": cosine_cycle, "cosine": cosine_cycle,
    "rectangular": rectangular, "rect": rectangular,
    "triangular": triangular, "triangle": triangular,
    "ricker": ricker,
    "mavroeidis_papageorgiou": mavroeidis_papageorgiou, "mp": mavroeidis_papageorgiou,
}


def _excitation(pulse, accel, dt, dt_missing, t):
    """What the integrators of the other modules are driven by, as the f2py layer takes it:
    (kind, params, rec, step, grid) for a Pulse from :func:`define` (kind > 0) or a sampled
    record accel with its time step dt (kind = 0), and the output times t as a flat array
    (empty for none). The caller has checked that exactly one of pulse and accel is given;
    dt_missing is the message when dt is not."""
    if pulse is not None:
        if not isinstance(pulse, Pulse):
            raise InvalidInputError("pulse: must be a seispulse.pulse.Pulse from "
                                    "seispulse.pulse.define()")
        kind, params, rec, step = pulse.code, np.asarray(pulse.params, float), np.zeros(1), 1.0
    else:
        rec = _core.as_number_array("accel", accel)
        if rec.ndim != 1:
            raise InvalidInputError(f"accel: must be a 1-d array of samples (got shape "
                                    f"{rec.shape})")
        rec = np.ascontiguousarray(rec)
        if dt is None:
            raise InvalidInputError(dt_missing)
        kind, params, step = 0, np.zeros(_fortran_codes.PULSE_NPARAM), _core.as_number("dt", dt)
    grid = np.zeros(0) if t is None else np.ascontiguousarray(
        _core.as_float_array("t", t).reshape(-1))
    return kind, params, rec, step, grid


def define(kind, **params):
    """A pulse, validated, to pass to other modules (e.g.
    :func:`seispulse.sliding.simulate`): ``define('half_sine', amp=0.3, amp_unit='g',
    duration=0.8)`` or ``define('sine_cycle', amp=0.4, amp_unit='g', period=1.0,
    cycles=20)`` takes the keyword parameters of the pulse's function, scalars only.
    Returns :class:`Pulse`."""
    if not isinstance(kind, str) or kind.strip().lower() not in _BY_NAME:
        raise InvalidInputError(
            f"kind = {kind!r}: unknown pulse (allowed: {', '.join(KINDS)})")
    try:
        return _BY_NAME[kind.strip().lower()](_DEFINE, **params)
    except TypeError as exc:
        raise InvalidInputError(f"{kind}: {exc}") from exc


def evaluate(kind, t, **params):
    """Any pulse by name (see :data:`KINDS`), with the keyword parameters of its
    function, e.g. ``evaluate('ricker', t, amp=3.0, freq=1.2)``."""
    if not isinstance(kind, str) or kind.strip().lower() not in _BY_NAME:
        raise InvalidInputError(
            f"kind = {kind!r}: unknown pulse (allowed: {', '.join(KINDS)})")
    function = _BY_NAME[kind.strip().lower()]
    try:
        return function(t, **params)
    except TypeError as exc:
        raise InvalidInputError(f"{kind}: {exc}") from exc
