"""The linear oscillator: closed forms under base motion, exact response histories
and response spectra of records (Fortran modules ``seispulse_sdof_sim`` and
``seispulse_sdof_closed``; doc/oscillator.md).

The oscillator (natural period ``T``, viscous damping ratio ``damping`` = zeta; the
book's gamma = 2 zeta) starts from rest under the ground acceleration a_g::

    z'' + 2 zeta omega z' + omega^2 z = -a_g(t),   omega = 2 pi / T,

with ``z`` the displacement relative to the ground and ``a_abs = a_g + z''`` the
absolute acceleration of the mass.

Records (:func:`response`, :func:`spectrum`): the record is linear between samples and
every step is solved exactly (Nigam & Jennings 1968, in a form that loses no digits
when the step is much shorter than T). :func:`spectrum` reports the true maxima of
``|z|``, ``|z'|`` and ``|a_abs|`` over the record, between samples too
(``peaks='exact'``, default; ``'samples'`` gives the maxima over the samples, what
eqsig or OpenSees report), at any T/dt, with no clipping at short periods; T = 0 is the
ground itself. Units: accelerations in g, displacements in m, velocities in m/s, time
in s.

Closed forms (harmonic base motion, the dynamic coefficient, the rectangular pulse,
the impulse, every pulse of :mod:`seispulse.pulse`, shock spectra) are in SI units: see
:func:`dynamic_coefficient`, :func:`harmonic_response`, :func:`pulse_response`,
:func:`pulse_spectrum`, :func:`shock_spectrum`.
"""

from collections import namedtuple

import numpy as np

from . import _core, _sdof_pulse
from . import _fortran_codes as _f
from ._sdof_pulse import *  # noqa: F401,F403  (closed forms, seispulse.sdof.<name>)
from ._seispulse import (sp_design_envelope, sp_sdof_response, sp_sdof_spectrum,
                         sp_sdof_threads, sp_spectral_shape)
from ._table import TableResult
from .errors import InvalidInputError

__all__ = ["STANDARD_GRAVITY", "PEAKS", "Response", "Spectrum", "Shape", "response",
           "spectrum", "envelope", "normalized_shape", "default_threads"]
__all__ += list(getattr(_sdof_pulse, "__all__", []))

#: Standard gravity (m/s^2), the default g.
STANDARD_GRAVITY = 9.80665
#: Where spectral maxima are sought: everywhere (exact) or at the samples only.
_PEAK_CODES = {"exact": _f.SDOF_PEAKS_EXACT, "samples": _f.SDOF_PEAKS_SAMPLES}
PEAKS = tuple(_PEAK_CODES)

Response = namedtuple("Response", ["time", "disp", "vel", "acc"])
Response.__doc__ = """Response history of :func:`response` at the samples: time (s from the
first sample), disp = z, the displacement relative to the ground (m), vel = z' (m/s),
acc = a_abs, the absolute acceleration of the mass (g)."""


class Spectrum(TableResult, namedtuple("Spectrum", ["periods", "damping", "sd", "sv", "sa",
                                                    "psv", "psa", "t_sd", "t_sv", "t_sa"])):
    """Response spectra of :func:`spectrum`.

    periods (s) and damping (ratio) as given; sd = max|z| (m), sv = max|z'| (m/s),
    sa = max|a_abs| (g): true maxima over the record; psv = omega sd (m/s) and
    psa = omega^2 sd (g): the pseudo-spectra of Eq. 2.33 (T = 0: psv = 0, psa = PGA).
    t_sd, t_sv, t_sa: the times of the maxima (s from the first sample). For a scalar
    damping the arrays have the shape of periods; for a sequence of dampings they are
    (len(damping), len(periods)). ``print()`` shows one row per damping and period;
    :meth:`to_frame` gives that table as a pandas DataFrame."""

    __slots__ = ()
    _COLUMNS = (("sd", "sd", "m"), ("sv", "sv", "m/s"), ("sa", "sa", "g"),
                ("psv", "psv", "m/s"), ("psa", "psa", "g"), ("t_sd", "t_sd", "s"),
                ("t_sv", "t_sv", "s"), ("t_sa", "t_sa", "s"))

    def _table_columns(self):
        per = np.atleast_1d(np.asarray(self.periods, dtype=np.float64))
        damp = np.atleast_1d(np.asarray(self.damping, dtype=np.float64))
        # the arrays are (damping, period): damping-major rows
        return ([("damping", "ratio", np.repeat(damp, per.size)),
                 ("period", "s", np.tile(per, damp.size))]
                + super()._table_columns())


Shape = namedtuple("Shape", ["shape", "t_peak", "peak"])
Shape.__doc__ = """Normalized spectral shape of :func:`normalized_shape`: shape = PSA/PGA at
each period (the spectral theory's C_W(T)/PGA, dimensionless), t_peak the period of its
largest value (s) and peak that value."""


def _peaks_code(peaks):
    return _core.choice_code("peaks", peaks, _PEAK_CODES)


def _threads(threads):
    if threads is None:
        return 0
    if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)) or threads < 1:
        raise InvalidInputError(f"threads = {threads!r}: must be an integer >= 1 "
                                "(None: the OpenMP default)")
    return int(threads)


def _number_or_vector(name, value, item):
    """value as a contiguous 1-d float array and whether it was a number; a 2-d or more
    array, or an empty one, raises InvalidInputError naming `name` (`item`: one element)."""
    arr = _core.as_float_array(name, value)
    if arr.ndim > 1:
        raise InvalidInputError(f"{name}: must be a number or a 1-d array (got shape {arr.shape})")
    scalar = arr.ndim == 0
    arr = np.ascontiguousarray(arr.reshape(-1))
    if arr.size == 0:
        raise InvalidInputError(f"{name}: at least one {item} is needed")
    return arr, scalar


def default_threads():
    """Number of OpenMP threads :func:`spectrum` uses when ``threads`` is None (1 when
    the library was built without OpenMP). Set OMP_NUM_THREADS to change it."""
    return int(sp_sdof_threads())


def response(accel, dt=None, period=None, damping=0.05, g=STANDARD_GRAVITY):
    """Exact response of a linear oscillator to a record, at the samples.

    Parameters
    ----------
    accel : array_like or seispulse.records.Record
        Ground acceleration (g), samples at t = i dt, linear in between.
    dt : float
        Time step (s, > 0); leave out for a Record.
    period : float
        Natural period T (s): 0, or from 1e-60 s up. T = 0 gives the ground
        motion itself.
    damping : float
        Viscous damping ratio zeta, 0 <= zeta < 1.
    g : float
        Gravity (m/s^2) that turns g into m/s^2.

    Returns
    -------
    Response
        time (s), disp (m), vel (m/s), acc (absolute, g).
    """
    rec, step = _core.record_and_step(accel, dt)
    if period is None:
        raise InvalidInputError("period: the natural period (s, >= 0) is required")
    period = _core.as_scalar("period", period)
    damping = _core.as_scalar("damping", damping)
    g = _core.as_scalar("g", g)
    disp, vel, acc, stat, msg = sp_sdof_response(rec, step, period, damping, g)
    _core.raise_for_status(stat, msg, indexed=("accel",))
    return Response(np.arange(rec.size) * step, disp, vel, acc)


def spectrum(accel, dt=None, periods=None, damping=0.05, g=STANDARD_GRAVITY, peaks="exact",
             threads=None):
    """Response spectra of a record: SD, SV, SA (true maxima) and PSV, PSA.

    Parameters
    ----------
    accel : array_like or seispulse.records.Record
        Ground acceleration (g), samples at t = i dt, linear in between.
    dt : float
        Time step (s, > 0); leave out for a Record.
    periods : array_like
        Natural periods (s): 0 (the ground itself) or from 1e-60 up, any order.
    damping : float or sequence of float
        Damping ratio(s), each 0 <= zeta < 1. A sequence gives 2-d results.
    g : float
        Gravity (m/s^2).
    peaks : {'exact', 'samples'}
        'exact': maxima between the samples too (exact at any T/dt); 'samples': over
        the samples only (eqsig's, OpenSees' convention).
    threads : int, optional
        OpenMP threads for this call (None: the default, :func:`default_threads`). The
        results do not depend on it.

    Returns
    -------
    Spectrum
        periods (s), damping, sd (m), sv (m/s), sa (g), psv (m/s), psa (g), and the
        times of the maxima t_sd, t_sv, t_sa (s).
    """
    rec, step = _core.record_and_step(accel, dt)
    if periods is None:
        raise InvalidInputError("periods: the natural periods (s, >= 0) are required")
    per, scalar_period = _number_or_vector("periods", periods, "period")
    damp, scalar_damping = _number_or_vector("damping", damping, "damping ratio")
    g = _core.as_scalar("g", g)
    out = sp_sdof_spectrum(rec, step, per, damp, g, _peaks_code(peaks), _threads(threads))
    *arrays, stat, msg = out
    _core.raise_for_status(stat, msg, indexed={"accel": "accel", "periods": "periods",
                                                       "dampings": "damping"})
    # (period, damping) -> (damping, period), squeezed as the inputs were given
    shaped = []
    for a in arrays:
        a = np.ascontiguousarray(a.T)
        if scalar_damping:
            a = a[0]
            if scalar_period:
                a = float(a[0])
        elif scalar_period:
            a = a[:, 0]
        shaped.append(a)
    per_out = float(per[0]) if scalar_period else per
    damp_out = float(damp[0]) if scalar_damping else damp
    return Spectrum(per_out, damp_out, *shaped)


def envelope(periods, spectra, plateau_below=0.0):
    """Design envelope of several spectra on one period grid (doc/oscillator.md section 6).

    The largest ordinate at each period; below ``plateau_below`` (s) the curve is held
    at the largest ordinate at that or any longer period (the book's short-period
    plateau, 0.2 s in the text: peak values kept, not a decreasing branch).

    Parameters
    ----------
    periods : array_like
        Periods (s), in any order (the plateau goes by period, not by position).
    spectra : array_like
        Ordinates, shape (n_spectra, len(periods)) (or one spectrum), any units.
    plateau_below : float
        Plateau limit (s, >= 0; 0: none).

    Returns
    -------
    numpy.ndarray
        The envelope, same units as spectra.
    """
    per = np.ascontiguousarray(_core.as_float_array("periods", periods).reshape(-1))
    spec = _core.as_float_array("spectra", spectra)
    if spec.ndim == 1:
        spec = spec[np.newaxis, :]
    if spec.ndim != 2 or spec.shape[1] != per.size:
        raise InvalidInputError(f"spectra: must have shape (n_spectra, {per.size}) "
                                f"(got {spec.shape})")
    plateau_below = _core.as_scalar("plateau_below", plateau_below)
    env, stat, msg = sp_design_envelope(per, np.asfortranarray(spec.T), plateau_below)
    _core.raise_for_status(stat, msg, indexed=("accel", "periods"))
    return env


def normalized_shape(periods, psa, pga):
    """The spectral theory's normalized shape C_W(T)/PGA (СНиП II-7-81 style).

    Parameters
    ----------
    periods : array_like
        Periods (s).
    psa : array_like
        Pseudo-acceleration at those periods (g).
    pga : float
        Peak ground acceleration (g, > 0).

    Returns
    -------
    Shape
        shape = psa/pga, t_peak (s), peak.
    """
    per = np.ascontiguousarray(_core.as_float_array("periods", periods).reshape(-1))
    ps = np.ascontiguousarray(_core.as_float_array("psa", psa).reshape(-1))
    if ps.size != per.size:
        raise InvalidInputError(f"psa: needs one value per period ({per.size}), got {ps.size}")
    pga = _core.as_scalar("pga", pga)
    shape, t_peak, peak, stat, msg = sp_spectral_shape(per, ps, pga)
    _core.raise_for_status(stat, msg)
    return Shape(shape, float(t_peak), float(peak))
