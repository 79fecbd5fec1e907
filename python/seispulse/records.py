"""Accelerograms: reading record files, PGA scaling, ground velocity and displacement
(Fortran module ``seispulse_records``).

Accelerations are always held in g, times in s. :func:`read` reads

* PEER NGA ``.AT2`` files (both header forms; the units of header line 3: g, cm/s^2
  or m/s^2, converted to g),
* SLAMMER / pySLAMMER CSV files (two ``#`` comment lines, then ``time_s, accel_g``),
* two-column time/acceleration files (comments ``#``, commas and/or blanks; the time
  step must be uniform within 1 % of dt),
* single-column files (``dt`` given by the caller),

strictly: a malformed file raises :class:`~seispulse.errors.InvalidInputError` (a
ValueError) whose message names the file and the line, says what was expected and
quotes what was found; a file that cannot be opened raises
:class:`~seispulse.errors.FileError` (an OSError). Nothing is silently truncated.

:class:`Record` holds the samples and the file's metadata; its methods return new
records (:meth:`Record.scaled`, :meth:`Record.scaled_to_pga`, :meth:`Record.inverted`)
or the exact ground velocity and displacement of the piecewise linear acceleration
(:meth:`Record.velocity`, :meth:`Record.displacement`).

:func:`sample` lists and reads the sample records that ship with pySLAMMER (an optional
package, ``pip install pyslammer``).

:func:`intensity` (and :meth:`Record.intensity`) returns the ground-motion intensity
measures of a record (PGA, PGV, PGD, Arias intensity, CAV, the significant durations
D5-75 and D5-95, the mean period Tm; doc/intensity.md), :func:`spectral_acceleration`
the pseudo-spectral acceleration at a period (Fortran module ``seispulse_intensity``).
"""

import os
import threading
from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_ground_motion, sp_pga_scale_factor, sp_record_fetch,
                         sp_record_intensity, sp_record_read, sp_spectral_acceleration)
from .errors import InvalidInputError

__all__ = ["STANDARD_GRAVITY", "FORMATS", "UNITS", "Record", "read", "from_array", "sample",
           "Intensity", "intensity", "spectral_acceleration", "accel_unit_factor",
           "MAX_RECORD_SAMPLES", "MAX_RECORD_BYTES"]

#: Standard gravity (m/s^2): converts m/s^2 and cm/s^2 to g, default ``g`` of the
#: velocity and displacement.
STANDARD_GRAVITY = 9.80665

#: Format names accepted by :func:`read`, in the order of the Fortran RECORD_* codes.
_FORMAT_CODES = {"auto": _f.RECORD_AUTO, "at2": _f.RECORD_AT2, "slammer": _f.RECORD_SLAMMER,
                 "column": _f.RECORD_COLUMN, "time_accel": _f.RECORD_TIME_ACCEL}
FORMATS = tuple(_FORMAT_CODES)
_FORMAT_NAMES = {code: name for name, code in _FORMAT_CODES.items()}

#: The most samples :func:`read` accepts (10 000 000: some 100 times the longest
#: accelerograms in use, 27.8 h at 100 Hz; the reader's arrays stay under 200 MB): a
#: larger AT2 NPTS, or more rows, raises InvalidInputError naming the line.
MAX_RECORD_SAMPLES = _f.MAX_RECORD_SAMPLES
#: The largest file :func:`read` accepts, in bytes (512 MiB: some 50 characters for each
#: of MAX_RECORD_SAMPLES samples; the file is held in memory while it is parsed): a
#: larger one raises InvalidInputError before it is read.
MAX_RECORD_BYTES = _f.MAX_RECORD_BYTES

#: Units of the values in a file or array (aliases: 'm/s^2', 'cm/s^2', 'gal'; any case:
#: the library's one vocabulary, as in the driver and for pulses).
UNITS = ("g", "m/s2", "cm/s2")

# sp_record_read keeps the record in Fortran until sp_record_fetch: one reader at a time.
_READ_LOCK = threading.Lock()


def _text(raw):
    """A fixed-length Fortran string (bytes) as str."""
    if isinstance(raw, bytes):
        return raw.rstrip(b" \0").decode("utf-8", "replace")
    return str(raw).rstrip(" \0")


def _unit_code(units):
    return _core.accel_unit_code("units", units)


def accel_unit_factor(units, g=STANDARD_GRAVITY):
    """The factor from an acceleration unit to g: a value in ``units`` times the factor
    is in g (1 for 'g', 1/g for 'm/s2', 1/(100 g) for 'cm/s2'). ``units``: 'g', 'm/s2',
    'm/s^2', 'cm/s2', 'cm/s^2', 'gal', any case (the library's one vocabulary, the
    driver's too); ``g`` in m/s^2."""
    from ._seispulse import sp_accel_unit_factor
    _core.accel_unit_code("units", units)
    factor, stat, msg = sp_accel_unit_factor(units, _core.as_scalar("g", g))
    _core.raise_for_status(stat, msg)
    return float(factor)


class Record:
    """An accelerogram sampled at a constant time step.

    Attributes
    ----------
    accel : numpy.ndarray
        Ground acceleration (g), float64, read-only; ``accel[i]`` at ``t = i * dt``
        from the first sample.
    dt : float
        Time step (s).
    npts : int
        Number of samples.
    pga : float
        Peak ground acceleration max |accel| (g).
    t0 : float
        Time of the first sample in the file (s): 0 unless a time column says otherwise.
        :attr:`time` and every result count time from the first sample.
    name : str
        File name without directory and extension ('record' for arrays by default).
    title : str
        AT2: line 2 of the header (event, station); text files: the first comment line
        without '#'; '' otherwise. Read from a file, at most 256 bytes of it.
    fmt : str
        The format read: 'at2', 'slammer', 'column', 'time_accel', or 'array' for a
        record built from an array.
    path : str or None
        The file read (None for an array).
    scale_factor : float
        Product of the factors applied since reading (1.0 initially; :meth:`inverted`
        multiplies it by -1).

    Parameters
    ----------
    accel : array_like
        1-d, finite samples in g, at least one.
    dt : float
        Time step (s), finite and > 0.
    name, title, fmt, path, t0, scale_factor
        As the attributes (t0 in s, finite; scale_factor finite and non-zero).
    """

    __slots__ = ("accel", "dt", "npts", "pga", "t0", "name", "title", "fmt", "path",
                 "scale_factor")

    def __init__(self, accel, dt, name="record", title="", t0=0.0, fmt="array", path=None,
                 scale_factor=1.0):
        arr = _core.as_float_array("accel", accel)
        if arr.ndim != 1:
            raise InvalidInputError(
                f"accel: must be a 1-d array of samples (got shape {arr.shape})")
        if arr.size == 0:
            raise InvalidInputError("accel: the record is empty (at least 1 sample needed)")
        bad = ~np.isfinite(arr)
        if bad.any():
            i = int(np.argmax(bad))
            raise InvalidInputError(f"accel[{i}] = {float(arr[i])!r}: must be finite (g)")
        self._set(np.array(arr, dtype=np.float64, copy=True),
                  _core.check_positive("dt", dt, " (s)"), name, title,
                  self._finite("t0", t0, " (s)"), fmt, path,
                  self._factor("scale_factor", scale_factor))

    # -------------------------------------------------------------- construction

    @staticmethod
    def _finite(name, value, unit=""):
        x = _core.as_scalar(name, value)
        if not np.isfinite(x):
            raise InvalidInputError(f"{name} = {x!r}: must be a finite number{unit}")
        return x

    @staticmethod
    def _factor(name, value):
        x = _core.as_scalar(name, value)
        if not np.isfinite(x) or x == 0.0:
            raise InvalidInputError(f"{name} = {x!r}: must be a finite non-zero number")
        return x

    def _set(self, accel, dt, name, title, t0, fmt, path, scale_factor):
        """Fill the attributes from checked values (accel: a fresh float64 array)."""
        for key, value in (("name", name), ("title", title), ("fmt", fmt)):
            if not isinstance(value, str):
                raise InvalidInputError(f"{key} = {value!r}: must be a string")
        if path is not None and not isinstance(path, str):
            raise InvalidInputError(f"path = {path!r}: must be a string or None")
        accel.flags.writeable = False
        self.accel = accel
        self.dt = float(dt)
        self.npts = int(accel.size)
        self.pga = float(np.max(np.abs(accel)))
        self.t0 = float(t0)
        self.name = name
        self.title = title
        self.fmt = fmt
        self.path = path
        self.scale_factor = float(scale_factor)

    @classmethod
    def _trusted(cls, accel, dt, name, title, t0, fmt, path, scale_factor):
        """A record from values already checked (by the Fortran reader or a method)."""
        rec = cls.__new__(cls)
        rec._set(accel, dt, name, title, t0, fmt, path, scale_factor)
        return rec

    def _with(self, accel, factor):
        return Record._trusted(accel, self.dt, self.name, self.title, self.t0, self.fmt,
                               self.path, self.scale_factor * factor)

    # -------------------------------------------------------------- properties

    @property
    def time(self):
        """Time of each sample from the first one, ``i * dt`` (s); add :attr:`t0` for
        the times of the file."""
        return np.arange(self.npts, dtype=np.float64) * self.dt

    @property
    def duration(self):
        """Time from the first to the last sample, (npts - 1) dt (s)."""
        return (self.npts - 1) * self.dt

    def __len__(self):
        return self.npts

    def __repr__(self):
        return (f"Record(name={self.name!r}, npts={self.npts}, dt={self.dt!r} s, "
                f"pga={self.pga!r} g, fmt={self.fmt!r}, scale_factor={self.scale_factor!r})")

    # -------------------------------------------------------------- new records

    def scaled(self, factor):
        """The record times ``factor`` (finite, non-zero; negative also inverts it).
        :attr:`scale_factor` of the result is this record's times ``factor``."""
        factor = self._factor("factor", factor)
        return self._with(self.accel * factor, factor)

    def scaled_to_pga(self, target_pga, rounding="exact"):
        """The record scaled to a peak ground acceleration ``target_pga`` (g, > 0).

        rounding='exact': factor target_pga / pga, the result's PGA is target_pga (to
        rounding). rounding='slammer': SLAMMER's convention, target_pga / (pga rounded
        to 0.001 g, half away from zero); the result's PGA then differs from target_pga
        by the rounding (e.g. pga 0.184882 g, target 0.3 g: factor 0.3 / 0.185).
        An error (InvalidInputError) when the PGA rounds to 0.000 g.
        """
        _core.check_choice("rounding", rounding, ("exact", "slammer"))
        target = _core.as_scalar("target_pga", target_pga)
        factor, stat, msg = sp_pga_scale_factor(self.pga, target, int(rounding == "slammer"))
        _core.raise_for_status(stat, _text(msg))
        return self._with(self.accel * factor, factor)

    def inverted(self):
        """The record with its sign reversed (:attr:`scale_factor` times -1)."""
        return self._with(-self.accel, -1.0)

    # -------------------------------------------------------------- integrals

    def _ground_motion(self, g):
        g = _core.check_positive("g", g, " (m/s^2)")
        vel, disp, stat, msg = sp_ground_motion(self.accel, self.dt, g)
        _core.raise_for_status(stat, _text(msg))
        return vel, disp

    def velocity(self, g=STANDARD_GRAVITY):
        """Ground velocity (m/s) at the samples, from rest at the first sample: the exact
        integral of the acceleration taken linear between samples (trapezoidal sums of
        ``g * accel``). ``g`` (m/s^2) converts the accelerations from g."""
        return self._ground_motion(g)[0]

    def displacement(self, g=STANDARD_GRAVITY):
        """Ground displacement (m) at the samples, from rest at the first sample: the
        exact double integral of the piecewise linear acceleration,
        ``d[i+1] = d[i] + v[i] dt + g dt^2 (2 a[i] + a[i+1]) / 6``."""
        return self._ground_motion(g)[1]

    # -------------------------------------------------------------- intensity

    def intensity(self, g=STANDARD_GRAVITY):
        """The intensity measures of this record: :func:`intensity` (``g`` in m/s^2)."""
        return intensity(self, g=g)


def read(path, fmt="auto", units=None, dt=None):
    """Read an accelerogram file.

    Parameters
    ----------
    path : str, bytes or os.PathLike
        The file (any characters, spaces and non-ASCII included).
    fmt : {'auto', 'at2', 'slammer', 'column', 'time_accel'}
        The format; 'auto' takes AT2 for an ``.at2`` extension or a PEER header,
        otherwise the first data line decides (2 numbers: time and acceleration,
        reported as 'slammer' after exactly two comment lines; 1 number: a column).
    units : {'g', 'm/s2', 'cm/s2'} or None
        Units of the values in the file (aliases 'm/s^2', 'cm/s^2', 'gal'). None: as
        the AT2 header says, g for the other formats. Given for an AT2 file whose
        header names other units, it is an error.
    dt : float, optional
        Time step (s, > 0): required for a single column; for the other formats a
        check (more than 1e-6 relative from the file's step is an error).

    Returns
    -------
    Record
        Accelerations in g, ``path`` the str path.

    Raises
    ------
    InvalidInputError
        A malformed file (the message starts with ``<path>:<n>:``) or a bad
        argument; a file with a NUL byte (binary data), of more than
        :data:`MAX_RECORD_BYTES` bytes or more than :data:`MAX_RECORD_SAMPLES` samples
        (refused in bounded time and memory).
    FileError
        The file cannot be opened or read (missing, a directory).
    """
    try:
        fspath = os.fspath(path)
    except TypeError as exc:
        raise InvalidInputError(f"path = {path!r}: must be a str, bytes or os.PathLike") \
            from exc
    raw = os.fsencode(fspath)
    if not raw:
        raise InvalidInputError("path: empty")
    if b"\0" in raw:
        raise InvalidInputError(f"path = {fspath!r}: contains a NUL character")
    code = _core.choice_code("fmt", fmt, _FORMAT_CODES)
    ucode = 0 if units is None else _unit_code(units)
    step = 0.0 if dt is None else _core.check_positive("dt", dt, " (s)")
    with _READ_LOCK:
        npts, dt_out, t0, fmt_out, _, stat, msg = sp_record_read(raw, code, ucode, step)
        accel, name, title = sp_record_fetch(npts if stat == 0 else 0)
    _core.raise_for_status(stat, _text(msg))
    if npts < 1:  # the reader reports an empty file itself; a guard, not a path
        raise InvalidInputError(f"{os.fsdecode(fspath)}: no data")
    return Record._trusted(accel, dt_out, _text(name), _text(title), t0, _FORMAT_NAMES[fmt_out],
                           os.fsdecode(fspath), 1.0)


def from_array(accel, dt, units="g", name="record"):
    """A :class:`Record` from samples in ``units`` ('g', 'm/s2', 'cm/s2'; aliases
    'm/s^2', 'cm/s^2', 'gal') at time step ``dt`` (s); stored in g (times
    :func:`accel_unit_factor`: divided by STANDARD_GRAVITY or 100 STANDARD_GRAVITY, as
    the reader does)."""
    factor = accel_unit_factor(units)
    arr = _core.as_float_array("accel", accel)
    if factor != 1.0:
        arr = arr * factor
    return Record(arr, dt, name=name)


#: The optional package whose sample records :func:`sample` reads, and their folder in it.
_SAMPLE_PACKAGE = "pyslammer"
_SAMPLE_DIR = "sample_ground_motions"


def _sample_files():
    """{name: path} of the records shipped with pyslammer (name: file name without the
    .csv extension), located without importing pyslammer."""
    import importlib.util
    try:
        spec = importlib.util.find_spec(_SAMPLE_PACKAGE)
    except (ImportError, ValueError):
        spec = None
    purpose = "seispulse.records.sample() (the sample records)"
    if spec is None or not spec.submodule_search_locations:
        raise _core.missing_package(_SAMPLE_PACKAGE, purpose)
    for base in spec.submodule_search_locations:
        folder = os.path.join(base, _SAMPLE_DIR)
        if os.path.isdir(folder):
            return {f[:-4]: os.path.join(folder, f) for f in sorted(os.listdir(folder))
                    if f.lower().endswith(".csv")}
    raise ImportError(f"{purpose}: the installed {_SAMPLE_PACKAGE} "
                      f"({', '.join(spec.submodule_search_locations)}) has no {_SAMPLE_DIR} "
                      f"folder; reinstall it: pip install --force-reinstall {_SAMPLE_PACKAGE}",
                      name=_SAMPLE_PACKAGE)


def sample(name=None):
    """The sample accelerograms that ship with pySLAMMER (an optional package:
    ``pip install pyslammer``): SLAMMER's CSV files, accelerations in g.

    Parameters
    ----------
    name : str, optional
        A record's name, e.g. ``'Kocaeli_1999_ATS-090'`` (the file name; the ``.csv``
        extension may be given). None: list the names.

    Returns
    -------
    tuple of str or Record
        name None: the names, sorted; else the record, read by :func:`read` (as
        ``read(path)`` returns it: accel in g, ``path`` the file).

    Raises
    ------
    ImportError
        pyslammer is not installed (the message names it and the pip command).
    InvalidInputError
        An unknown name (the message lists the known ones).
    """
    files = _sample_files()
    if name is None:
        return tuple(files)
    if not isinstance(name, str):
        raise InvalidInputError(f"name = {name!r}: must be a record name (str) or None")
    key = name[:-4] if name.lower().endswith(".csv") else name
    if key not in files:
        raise InvalidInputError(f"name = {name!r}: no such sample record in pyslammer "
                                f"(known: {', '.join(files)})")
    return read(files[key])


class Intensity(namedtuple("Intensity", ["pga", "pgv", "pgd", "arias", "cav", "d5_75",
                                         "d5_95", "t5", "t75", "t95", "tm"])):
    """Intensity measures of a record (doc/intensity.md): pga (g), pgv (m/s), pgd (m),
    arias (m/s), cav (m/s), d5_75, d5_95 (s), t5, t75, t95 (s from the first sample),
    tm (s); and the property ``pgv_cm_s``, the PGV in cm/s, the unit of the empirical
    models of :mod:`seispulse.empirical` (``pgv`` is m/s: pass ``pgv_cm_s`` to them)."""

    __slots__ = ()

    @property
    def pgv_cm_s(self):
        """Peak ground velocity (cm/s): 100 * pgv, the unit seispulse.empirical takes."""
        return 100.0 * self.pgv


def intensity(rec_or_accel, dt=None, g=STANDARD_GRAVITY):
    """Ground-motion intensity measures of a record (doc/intensity.md).

    The acceleration is linear between samples and every measure is exact for it:

    * ``pga`` max |a| (g); ``pgv`` (m/s) and ``pgd`` (m) the largest |velocity| and
      |displacement| from rest at the first sample, between the samples too; the
      property ``pgv_cm_s`` is the PGV in cm/s, the unit of :mod:`seispulse.empirical`
      (e.g. ``saygili_rathje_2008_pgv(ky, im.pga, im.pgv_cm_s)``; ``arias`` (m/s) and
      ``tm`` (s) go in as they are);
    * ``arias`` = pi/(2g) int a^2 dt (m/s, a in m/s^2) [A70]; ``cav`` = int |a| dt
      (m/s) [EPRI88], sign changes inside a step included;
    * ``t5``, ``t75``, ``t95`` (s from the first sample): the first times the Husid
      curve (the normalized cumulative Arias intensity) reaches 5, 75 and 95 %, found
      inside their step; ``d5_75`` = t75 - t5 and ``d5_95`` = t95 - t5 (s) [TB75];
    * ``tm`` the mean period (s) [RAB98]: sum(C^2/f) / sum(C^2) over the Fourier
      amplitudes C at 0.25 <= f <= 20 Hz, the record zero-padded to the next power of
      two >= max(npts, 20/dt) points (df <= 0.05 Hz).

    A record without energy (all zeros, or one sample) has NaN durations, times and Tm,
    and Tm is NaN when no frequency of 0.25-20 Hz carries energy.

    Parameters
    ----------
    rec_or_accel : Record or array_like
        The record, or its samples (g) at t = i dt.
    dt : float
        Time step (s, > 0); leave out for a Record.
    g : float
        Gravity (m/s^2) that turns g into m/s^2.

    Returns
    -------
    Intensity
    """
    rec, step = _core.record_and_step(rec_or_accel, dt)
    g = _core.check_positive("g", g, " (m/s^2)")
    *values, stat, msg = sp_record_intensity(rec, step, g)
    _core.raise_for_status(stat, _text(msg), indexed=("accel",))
    return Intensity(*(float(v) for v in values))


def spectral_acceleration(rec, period, damping=0.05, g=STANDARD_GRAVITY, dt=None):
    """Pseudo-spectral acceleration PSA = (2 pi / T)^2 SD / g (g) of a record.

    SD is the true largest |relative displacement| of the oscillator (period T, damping
    ratio ``damping``) over the record, from its exact response (seispulse.sdof);
    T = 0 gives the PGA (doc/intensity.md (I.17)).

    Parameters
    ----------
    rec : Record or array_like
        The record, or its samples (g) at t = i dt (then ``dt`` is required).
    period : float or array_like
        Natural period(s) T (s), 0 or from 1e-60 up; an array gives an array.
    damping : float
        Damping ratio, 0 <= damping < 1 (default 5 %).
    g : float
        Gravity (m/s^2).
    dt : float, optional
        Time step (s, > 0) of an array of samples.

    Returns
    -------
    float or numpy.ndarray
        PSA (g), shaped as ``period``.
    """
    acc, step = _core.record_and_step(rec, dt)
    per = _core.as_float_array("period", period)
    damping = _core.as_scalar("damping", damping)
    g = _core.check_positive("g", g, " (m/s^2)")
    out = np.empty(per.shape)
    for i, p in enumerate(per.reshape(-1)):
        sa, stat, msg = sp_spectral_acceleration(acc, step, float(p), damping, g)
        name = "period" if per.ndim == 0 else f"period[{i}]"
        _core.raise_for_status(stat, _text(msg), rename={"period": name},
                               indexed=("accel",))
        out.reshape(-1)[i] = sa
    if per.ndim == 0:
        return float(out)
    return out
