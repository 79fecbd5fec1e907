"""Closed forms of the linear oscillator under base motion (Fortran module
``seispulse_sdof_closed``; doc/oscillator.md). Users reach these functions as
``seispulse.sdof.<name>``.

The oscillator (natural period ``period`` = T, omega = 2 pi / T, viscous damping ratio
``damping`` = zeta, 0 <= zeta < 1; the book's gamma = 2 zeta) starts from rest::

    z'' + 2 zeta omega z' + omega^2 z = -a_g(t),
    a_abs = a_g + z'' = -(2 zeta omega z' + omega^2 z)

with ``z`` the displacement of the mass relative to the ground. Everything here is in
SI units: accelerations in m/s^2, velocities in m/s, displacements in m, times and
periods in s (pulses from :func:`seispulse.pulse.define` are SI; an M&P pulse's
``vamp`` is a velocity).

Errata of the book restored here (doc/oscillator.md): Eq. 2.20 has a square root
(beta(theta = omega) = 1/gamma); Eq. 2.21 reads cos(omega t), not sin(omega t); Eq. 2.23
has a minus sign; Eq. 2.17 is the steady state, not the solution from rest; the book's
pulse coefficient 1 + 2 pi t1/T is an upper bound, the exact one is 2 sin(pi t1/T).
"""

import re
from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_beta_pulse, sp_dynamic_coefficient, sp_harmonic_response,
                         sp_impulse_max, sp_impulse_response, sp_pulse_peak_accel,
                         sp_rect_pulse_response, sp_sdof_pulse_peaks, sp_sdof_pulse_response,
                         sp_sdof_pulse_spectrum)
from ._table import TableResult
from .errors import InvalidInputError
from .pulse import Pulse

__all__ = ["DAMPING_MODELS", "HARMONIC_LAWS", "BETA_PULSE_VARIANTS", "MotionResponse",
           "ImpulseMax", "OscillatorPeaks", "PulseSpectrum", "SpectrumTimes", "ShockSpectrum",
           "dynamic_coefficient", "cosine_dynamic_coefficient", "harmonic_response",
           "rect_pulse_response", "beta_pulse", "impulse_max", "impulse_response",
           "pulse_response", "pulse_peaks", "pulse_spectrum", "shock_spectrum",
           "peak_ground_acceleration"]

#: Damping terms of the dynamic coefficient: the book's Eq. 2.20 (frequency
#: independent) and the viscous form.
_DAMPING_CODES = {"hysteretic": _f.BETA_HYSTERETIC, "viscous": _f.BETA_VISCOUS}
DAMPING_MODELS = tuple(_DAMPING_CODES)
#: Harmonic base displacement laws: Delta0 sin(theta t) and Delta0 cos(theta t).
_LAW_CODES = {"sine": _f.HARMONIC_SINE, "cosine": _f.HARMONIC_COSINE}
HARMONIC_LAWS = tuple(_LAW_CODES)
#: Dynamic coefficient of the rectangular pulse: exact, or the book's bound.
_VARIANT_CODES = {"exact": _f.BETA_PULSE_EXACT, "textbook": _f.BETA_PULSE_TEXTBOOK}
BETA_PULSE_VARIANTS = tuple(_VARIANT_CODES)

MotionResponse = namedtuple("MotionResponse", ["z", "v", "a_abs"])
MotionResponse.__doc__ = """Oscillator response: z, the displacement relative to the ground
(m); v = z' (m/s); a_abs = a_g + z'', the absolute acceleration of the mass (m/s^2)."""

ImpulseMax = namedtuple("ImpulseMax", ["z_max", "t_max"])
ImpulseMax.__doc__ = """Largest |z| after an acceleration impulse (m) and its first time (s)."""

OscillatorPeaks = namedtuple("OscillatorPeaks", ["z_max", "t_z", "v_max", "t_v", "a_max", "t_a"])
OscillatorPeaks.__doc__ = """Maxima over all t >= 0 (free vibration after the pulse included)
of |z| (m), |z'| (m/s), |a_abs| (m/s^2), and the times where they occur (s)."""


class PulseSpectrum(TableResult, namedtuple("PulseSpectrum", ["periods", "sd", "sv", "sa",
                                                              "psv", "psa"])):
    """Response spectra of a pulse: periods (s); sd = max|z| (m), sv = max|z'| (m/s),
    sa = max|a_abs| (m/s^2), the maxima over t >= 0 found as in :func:`pulse_peaks`;
    psv = omega sd (m/s) and psa = omega^2 sd (m/s^2), the pseudo-spectra of Eq. 2.33
    (period 0: psv = 0, psa = sa = peak |a_g|). ``print()`` shows the table;
    :meth:`to_frame` gives it as a pandas DataFrame."""

    __slots__ = ()
    _COLUMNS = (("periods", "period", "s"), ("sd", "sd", "m"), ("sv", "sv", "m/s"),
                ("sa", "sa", "m/s^2"), ("psv", "psv", "m/s"), ("psa", "psa", "m/s^2"))


SpectrumTimes = namedtuple("SpectrumTimes", ["t_sd", "t_sv", "t_sa"])
SpectrumTimes.__doc__ = """Times (s) where sd, sv and sa are reached."""


class ShockSpectrum(TableResult, namedtuple("ShockSpectrum", ["ratios", "periods", "sd", "sv",
                                                              "sa", "psv", "psa",
                                                              "amplification"])):
    """Shock spectrum of a pulse against ratios = t_d / T: periods (s), sd (m), sv (m/s),
    sa (m/s^2), psv (m/s), psa (m/s^2) as in :class:`PulseSpectrum`, and
    amplification = psa / peak |a_g| (dimensionless). ``print()`` shows the table (arrays
    flattened); :meth:`to_frame` gives it as a pandas DataFrame."""

    __slots__ = ()
    _COLUMNS = (("ratios", "ratio", "t_d/T"), ("periods", "period", "s"), ("sd", "sd", "m"),
                ("sv", "sv", "m/s"), ("sa", "sa", "m/s^2"), ("psv", "psv", "m/s"),
                ("psa", "psa", "m/s^2"), ("amplification", "amplification", "psa/pga"))


#: Fortran arrays whose elements name(i) errors give as the caller's name[i - 1] (flat
#: index for arrays of more than one dimension).
_INDEXED = ("accel", "t", "periods")


def _pulse_args(pulse):
    if not isinstance(pulse, Pulse):
        raise InvalidInputError("pulse: must be a seispulse.pulse.Pulse from "
                                "seispulse.pulse.define()")
    return pulse.code, np.ascontiguousarray(np.asarray(pulse.params, dtype=np.float64))


def _times(t):
    arr = _core.as_float_array("t", t)
    return arr.shape, np.ascontiguousarray(arr.reshape(-1))


def _motion(shape, z, v, a):
    return MotionResponse(*_core.shaped(shape, z, v, a))


# ------------------------------------------------------------------ book forms

def dynamic_coefficient(ratio, gamma=0.0, model="hysteretic"):
    """Dynamic coefficient beta of harmonic base motion (Eq. 2.17, 2.20).

    Parameters
    ----------
    ratio : float or array
        r = theta / omega, forcing over natural circular frequency (>= 0).
    gamma : float or array
        The book's damping parameter gamma = 2 zeta (>= 0); broadcasts with ``ratio``.
    model : {'hysteretic', 'viscous'}
        'hysteretic' (default): the book's Eq. 2.20 with its square root restored,
        1 / sqrt((1 - r^2)^2 + gamma^2); 'viscous': 1 / sqrt((1 - r^2)^2 + gamma^2 r^2).
        Both give 1 / gamma at resonance.

    Returns
    -------
    float or array
        beta (dimensionless). With gamma = 0 the signed 1 / (1 - r^2) of Eq. 2.17
        (negative above resonance). Raises :class:`seispulse.SingularError` at r = 1
        with gamma = 0, :class:`seispulse.InvalidInputError` for bad input.
    """
    return _dynamic(ratio, gamma, model)[0]


def cosine_dynamic_coefficient(ratio, gamma=0.0, model="hysteretic"):
    """The cosine law's coefficient from rest, 2 |beta| (after Eq. 2.21): the largest
    |z| omega^2 / W0 of the undamped (W0 beta / omega^2)(cos theta t - cos omega t).

    Defined for the undamped oscillator only: ``gamma`` must be 0 (any other value raises
    :class:`seispulse.InvalidInputError` naming it). With damping the from-rest maximum is
    not 2 |beta| (zeta = 0.05, r = 1: |z| omega^2 / W0 tends to 1 / gamma = 10, not 20); use
    :func:`harmonic_response` with ``law='cosine'`` and ``damping = gamma / 2`` for the
    damped history. ``ratio`` and ``model`` as in :func:`dynamic_coefficient`.
    """
    _, arr = _core.broadcast(gamma=gamma)
    g = arr["gamma"].reshape(-1)
    bad = np.flatnonzero(~(g == 0.0))
    if bad.size:
        raise InvalidInputError(f"gamma = {float(g[bad[0]])!r}: must be 0; the cosine law's "
                                "2|beta| is the from-rest maximum of the undamped oscillator "
                                "only (use harmonic_response(..., law='cosine', damping=gamma/2) "
                                "with damping)")
    return _dynamic(ratio, gamma, model)[1]


def _dynamic(ratio, gamma, model):
    code = _core.choice_code("model", model, _DAMPING_CODES)
    shape, arr = _core.broadcast(ratio=ratio, gamma=gamma)
    beta, beta_cos, stat, msg = sp_dynamic_coefficient(_core.flat(arr["ratio"], shape),
                                                       _core.flat(arr["gamma"], shape), code)
    _core.raise_for_status(stat, msg)
    return _core.shaped(shape, beta, beta_cos)


def harmonic_response(t, w0, period, ratio, damping=0.0, law="sine", transient=True):
    """Response to harmonic base motion (Sec. 2.3.2).

    The base displacement is Delta0 sin(theta t) (``law='sine'``, Mononobe, Eq. 2.15) or
    Delta0 cos(theta t) (``'cosine'``, Zavriev-Nazarov), so the ground acceleration is
    a_g = -W0 sin(theta t) or -W0 cos(theta t) with W0 = Delta0 theta^2.

    Parameters
    ----------
    t : float or array
        Times (s).
    w0 : float
        W0, amplitude of the base acceleration (m/s^2).
    period : float
        Natural period T (s), > 0.
    ratio : float
        r = theta / omega (>= 0).
    damping : float
        Viscous damping ratio zeta in [0, 1) of the oscillator (both for the history from
        rest and for the steady state).
    law : {'sine', 'cosine'}
    transient : bool
        True (default): the exact solution from rest at t = 0 (zero before), e.g. for the
        undamped sine law (W0 beta / omega^2)(sin theta t - r sin omega t), for the cosine
        law Eq. 2.21 (W0 beta / omega^2)(cos theta t - cos omega t); exact at resonance
        (t sin omega t growth) and without loss of digits near it. False: the steady state
        (Eq. 2.17 when undamped); the undamped steady state at r = 1 raises
        :class:`seispulse.SingularError`. The damped steady state is that of viscous
        damping zeta, amplitude (W0 / omega^2) / sqrt((1 - r^2)^2 + (2 zeta r)^2): it is
        :func:`dynamic_coefficient` with ``gamma = 2 * damping`` and ``model='viscous'``,
        not that function's default (the book's hysteretic Eq. 2.20).

    Returns
    -------
    MotionResponse
        z (m), v (m/s), a_abs (m/s^2), shaped like ``t``.
    """
    shape, tf = _times(t)
    code = _core.choice_code("law", law, _LAW_CODES)
    transient = _core.check_bool("transient", transient)
    z, v, a, stat, msg = sp_harmonic_response(
        tf, _core.as_scalar("w0", w0), _core.as_scalar("period", period),
        _core.as_scalar("ratio", ratio), _core.as_scalar("damping", damping), code,
        int(transient))
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return _motion(shape, z, v, a)


def rect_pulse_response(t, w0, t1, period):
    """Undamped response to the rectangular acceleration pulse a_g = W0 on 0 <= t < t1
    (Fig. 2.6), any t1: z = -(W0 / omega^2)(1 - cos omega t) during the pulse and
    Eq. 2.23 with its minus sign, z = -(2 W0 / omega^2) sin(omega t1 / 2)
    sin(omega (t - t1 / 2)), after it.

    Parameters: ``t`` times (s), ``w0`` pulse acceleration (m/s^2), ``t1`` duration (s, > 0),
    ``period`` natural period (s, > 0). Returns MotionResponse (m, m/s, m/s^2). The damped
    rectangle: :func:`pulse_response` with a 'rectangular' pulse.
    """
    shape, tf = _times(t)
    z, v, a, stat, msg = sp_rect_pulse_response(tf, _core.as_scalar("w0", w0),
                                                _core.as_scalar("t1", t1),
                                                _core.as_scalar("period", period))
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return _motion(shape, z, v, a)


def beta_pulse(t1_over_period, variant="exact"):
    """Dynamic coefficient of the undamped rectangular pulse, max S / (m W0), against
    t1 / T (>= 0).

    ``variant='exact'``: 2 sin(pi t1 / T) for t1 <= T / 2, 2 beyond (doc/oscillator.md section 4:
    t1/T = 0.05, 0.1, 0.25, 0.4 give 0.3129, 0.6180, 1.4142, 1.9021). ``'textbook'``: the
    book's 1 + 2 pi t1 / T, which adds the peak of the ground acceleration to the peak
    relative acceleration although they do not coincide (an upper bound; -> 1 as
    t1 -> 0, the printed "beta -> 0" is a typo). Dimensionless.
    """
    fortran_code = _core.choice_code("variant", variant, _VARIANT_CODES)
    shape, arr = _core.broadcast(t1_over_period=t1_over_period)
    beta, stat, msg = sp_beta_pulse(_core.flat(arr["t1_over_period"], shape), fortran_code)
    _core.raise_for_status(stat, msg)
    return _core.shaped(shape, beta)[0]


def impulse_max(jw, period, damping=0.0):
    """Largest |z| after an instantaneous acceleration impulse J_W = W0 t1 (m/s), and its
    first time: undamped J_W / omega at T / 4 (Eq. 2.25); damped
    (|J_W| / omega) exp(-zeta omega t*) at t* = atan2(sqrt(1 - zeta^2), zeta) / omega_d.
    Broadcasts; returns ImpulseMax(z_max (m), t_max (s))."""
    shape, arr = _core.broadcast(jw=jw, period=period, damping=damping)
    zmax, tmax, stat, msg = sp_impulse_max(_core.flat(arr["jw"], shape),
                                           _core.flat(arr["period"], shape),
                                           _core.flat(arr["damping"], shape))
    _core.raise_for_status(stat, msg)
    return ImpulseMax(*_core.shaped(shape, zmax, tmax))


def impulse_response(t, jw, period, damping=0.0):
    """Response to an instantaneous acceleration impulse J_W (m/s) at t = 0, the t1 -> 0
    limit of the rectangle at fixed J_W = W0 t1 (Eq. 2.24 when undamped):
    z = -J_W exp(-zeta omega t) sin(omega_d t) / omega_d for t >= 0, zero before.
    Returns MotionResponse (m, m/s, m/s^2)."""
    shape, tf = _times(t)
    z, v, a, stat, msg = sp_impulse_response(tf, _core.as_scalar("jw", jw),
                                             _core.as_scalar("period", period),
                                             _core.as_scalar("damping", damping))
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return _motion(shape, z, v, a)


# ------------------------------------------------------------------ pulses

def pulse_response(pulse, period, damping=0.05, t=None):
    """Response of the oscillator to a pulse, from rest, at arbitrary times.

    Parameters
    ----------
    pulse : seispulse.pulse.Pulse
        Any pulse from :func:`seispulse.pulse.define` (SI).
    period : float
        Natural period T (s), > 0.
    damping : float
        Viscous damping ratio zeta in [0, 1).
    t : float or array
        Times (s), required. Zero before the pulse; after it the free vibration,
        evaluated analytically at any t.

    Returns
    -------
    MotionResponse
        z (m), v (m/s), a_abs (m/s^2), shaped like ``t``. Closed form for every kind
        except the Ricker wavelet (Gauss-Legendre quadrature to rounding level, the
        wavelet cut where |a_g| < 1e-40 of its peak).
    """
    if t is None:
        raise InvalidInputError("t: the times (s) of the response are required")
    kind, params = _pulse_args(pulse)
    shape, tf = _times(t)
    z, v, a, stat, msg = sp_sdof_pulse_response(kind, params, _core.as_scalar("period", period),
                                                _core.as_scalar("damping", damping), tf)
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return _motion(shape, z, v, a)


def pulse_peaks(pulse, period, damping=0.05):
    """Maxima of |z| (m), |z'| (m/s) and |a_abs| (m/s^2) over all t >= 0 (free vibration
    included) and their times (s). Stationary points are bracketed on a scan of at least
    32 steps per natural period and per cycle of the pulse, at most 2^20 steps per segment
    of the pulse, and refined by Brent's method. So a period shorter than 1/32768 of the
    pulse's longest segment (e.g. 6.1e-5 s for a 2 s rectangle), or an M&P pulse with
    gamma > 32767, raises :class:`seispulse.InvalidInputError` naming the period (or
    gamma) and the shortest period allowed: a coarser scan would alias. Returns
    OscillatorPeaks."""
    kind, params = _pulse_args(pulse)
    out, stat, msg = sp_sdof_pulse_peaks(kind, params, _core.as_scalar("period", period),
                                         _core.as_scalar("damping", damping))
    _core.raise_for_status(stat, msg)
    return OscillatorPeaks(*map(float, out))


def pulse_spectrum(pulse, periods, damping=0.05, return_times=False):
    """Response spectra of a pulse (SI).

    Parameters
    ----------
    pulse : seispulse.pulse.Pulse
    periods : float or array
        Natural periods (s, >= 0); 0 is the rigid oscillator (sd = sv = 0, sa = peak |a_g|).
    damping : float
        Viscous damping ratio zeta in [0, 1).
    return_times : bool
        Also return the times of the maxima.

    Returns
    -------
    PulseSpectrum
        periods (s), sd (m), sv (m/s), sa (m/s^2): the maxima over t >= 0 found as in
        :func:`pulse_peaks`; psv = omega sd (m/s), psa = omega^2 sd (m/s^2). With
        ``return_times``: (PulseSpectrum, SpectrumTimes).

    Period 0 gives sa = the peak |a_g| (PGA). For a pulse whose acceleration jumps
    ('rectangular', 'cosine_cycle', an 'exponential' with beta = -inf) the limit T -> 0+
    of sa is larger than the PGA (the step overshoot: up to 2 PGA undamped, 1.8588 PGA at
    T = 1e-4 s with damping 0.05), so sa is not continuous at T = 0 for those pulses.
    Positive periods must be >= 1e-60 s and long enough for the peak search (see
    :func:`pulse_peaks`); otherwise :class:`seispulse.InvalidInputError` names
    ``periods[i]``.
    """
    kind, params = _pulse_args(pulse)
    return_times = _core.check_bool("return_times", return_times)
    arr = _core.as_float_array("periods", periods)
    shape = arr.shape
    flat = np.ascontiguousarray(arr.reshape(-1))
    sd, sv, sa, tsd, tsv, tsa, stat, msg = sp_sdof_pulse_spectrum(
        kind, params, flat, _core.as_scalar("damping", damping))
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    psv, psa = _pseudo(flat, sd, sa)
    spec = PulseSpectrum(*(x.reshape(shape) if shape != () else float(x[0])
                           for x in (flat, sd, sv, sa, psv, psa)))
    if return_times:
        return spec, SpectrumTimes(*_core.shaped(shape, tsd, tsv, tsa))
    return spec


def _pseudo(periods, sd, sa):
    """psv = omega sd, psa = omega^2 sd; at period 0: psv = 0, psa = sa (the PGA)."""
    rigid = periods == 0.0
    omega = 2.0 * np.pi / np.where(rigid, 1.0, periods)
    psv = np.where(rigid, 0.0, omega * sd)
    psa = np.where(rigid, sa, omega * (omega * sd))
    return psv, psa


def peak_ground_acceleration(pulse):
    """Peak |a_g| of a pulse (m/s^2) and its time (s)."""
    kind, params = _pulse_args(pulse)
    amax, tmax, stat, msg = sp_pulse_peak_accel(kind, params)
    _core.raise_for_status(stat, msg)
    return float(amax), float(tmax)


def _time_scale(pulse):
    """t_d of the shock spectrum: the duration of one lobe (exponential), the pulse length
    (half sine, rectangle, triangle), the period (sine and cosine cycles), 1/f_p (Ricker,
    M&P)."""
    if pulse.kind in ("ricker", "mavroeidis_papageorgiou"):
        return 1.0 / float(pulse.params[5])
    return float(pulse.params[1])


def shock_spectrum(pulse, ratios, damping=0.05, time_scale=None):
    """Shock spectrum: the pulse's spectra against ratios = t_d / T.

    Parameters
    ----------
    pulse : seispulse.pulse.Pulse
    ratios : float or array
        t_d / T (> 0; +inf is the rigid oscillator, T = 0).
    damping : float
        Viscous damping ratio zeta in [0, 1).
    time_scale : float, optional
        t_d (s). Default: the duration of one lobe for 'exponential', the pulse length
        for 'half_sine', 'rectangular', 'triangular', the period for 'sine_cycle' and
        'cosine_cycle', 1 / f_p for 'ricker' and 'mavroeidis_papageorgiou'.

    Returns
    -------
    ShockSpectrum
        ratios, periods = t_d / ratios (s), sd (m), sv (m/s), sa (m/s^2), psv (m/s),
        psa (m/s^2), amplification = psa / peak |a_g| (0 when the pulse has no
        acceleration); the maxima as in :func:`pulse_spectrum` (ratio +inf: the rigid
        oscillator, sa = PGA; see there for the limit of jump pulses).

    A ratio that is not > 0, so large that t_d / ratio is below 1e-60 s or too short for
    the peak search, or so small that t_d / ratio overflows raises
    :class:`seispulse.InvalidInputError` naming ``ratios[i]``, its value and the period
    it gives.
    """
    kind, params = _pulse_args(pulse)
    td = _time_scale(pulse) if time_scale is None else _core.check_positive(
        "time_scale", time_scale, " (s)")
    arr = _core.as_float_array("ratios", ratios)
    shape = arr.shape
    flat = np.ascontiguousarray(arr.reshape(-1))
    bad = np.flatnonzero(np.isnan(flat) | (flat <= 0.0))
    if bad.size:
        raise InvalidInputError(f"{_ratio_name(shape, bad[0])} = {float(flat[bad[0]])!r}: "
                                "must be > 0 (t_d / T; +inf for T = 0)")
    with np.errstate(over="ignore"):
        periods = np.where(np.isinf(flat), 0.0, td / flat)
    bad = np.flatnonzero(np.isinf(periods))
    if bad.size:
        raise InvalidInputError(f"{_ratio_name(shape, bad[0])} = {float(flat[bad[0]])!r}: "
                                f"too small, the period t_d / ratio overflows (t_d = {td!r} s; "
                                f"must be >= {float(td / np.finfo(float).max)!r})")
    sd, sv, sa, tsd, tsv, tsa, stat, msg = sp_sdof_pulse_spectrum(
        kind, params, np.ascontiguousarray(periods), _core.as_scalar("damping", damping))
    if stat != 0:
        _raise_for_ratio(stat, msg, shape, flat, periods, td)
    psv, psa = _pseudo(periods, sd, sa)
    pga, _ = peak_ground_acceleration(pulse)
    amp = psa / pga if pga > 0.0 else np.zeros_like(psa)
    out = (flat, periods, sd, sv, sa, psv, psa, amp)
    return ShockSpectrum(*(x.reshape(shape) if shape != () else float(x[0]) for x in out))


def _ratio_name(shape, k):
    """ratios[k] (flat index k) as the user indexes the array: ratios[i, j] for 2-d."""
    if len(shape) <= 1:
        return f"ratios[{k}]" if shape else "ratios"
    return "ratios[" + ", ".join(map(str, np.unravel_index(k, shape))) + "]"


def _raise_for_ratio(stat, msg, shape, flat, periods, td):
    """A refusal of periods(i) by the Fortran spectrum, restated for ratios[i - 1]: the
    ratio the caller passed, the period it gave, then the Fortran reason."""
    text = msg.decode("ascii", "replace") if isinstance(msg, bytes) else str(msg)
    text = text.strip()
    found = re.match(r"periods\((\d+)\) = [^:]*: ?(.*)", text, re.S)
    if found:
        k = int(found.group(1)) - 1
        text = (f"{_ratio_name(shape, k)} = {float(flat[k])!r}: gives the period "
                f"t_d / ratio = {float(periods[k])!r} s (t_d = {td!r} s), refused: "
                f"{found.group(2)}")
    _core.raise_for_status(stat, text)
