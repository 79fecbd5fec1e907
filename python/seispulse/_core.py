"""Shared plumbing of the Python layer: argument conversion, ufunc-style
broadcasting, and turning Fortran status codes into exceptions."""

import numbers
import re
import threading

import numpy as np

from ._fortran_codes import SEISPULSE_SUCCESS
from .errors import STATUS_ERRORS, InternalError, InvalidInputError


#: Held by a run that keeps its intervals or impacts in Fortran until they are fetched
#: (sp_stickslip, sp_newmark_rigid, sp_rock, then sp_fetch_slides / sp_fetch_impacts).
HELD_LOCK = threading.Lock()


def slides(make, fields):
    """The intervals of sp_fetch_slides as a list of make(direction, t_start, t_stop,
    u_start, u_stop, w_peak, t_peak, from_slip) (Python int, floats, bool)."""
    direction, t_start, t_stop, u_start, u_stop, w_peak, t_peak, from_slip = fields
    return [make(d, t0, t1, u0, u1, w, tw, bool(f)) for d, t0, t1, u0, u1, w, tw, f in zip(
        direction.tolist(), t_start.tolist(), t_stop.tolist(), u_start.tolist(),
        u_stop.tolist(), w_peak.tolist(), t_peak.tolist(), from_slip.tolist())]


def as_float_array(name, value):
    """`value` as a float64 array; raise InvalidInputError naming `name` if it is not
    real-valued numeric data."""
    try:
        arr = np.asarray(value)
    except Exception as exc:  # ragged lists and the like
        raise InvalidInputError(f"{name}: must be a real number or an array of them") from exc
    if arr.dtype == object or arr.dtype.kind not in "biuf":
        raise InvalidInputError(
            f"{name}: must be a real number or an array of them (got {arr.dtype} data)")
    return arr.astype(np.float64, copy=False)


def as_scalar(name, value):
    """One real number as a Python float; InvalidInputError naming `name` for anything
    else (arrays of more than one element, strings, None, bools)."""
    if _is_bool(value):
        raise InvalidInputError(f"{name} = {value!r}: must be a real number, not a bool")
    arr = as_float_array(name, value)
    if arr.size != 1:
        raise InvalidInputError(f"{name}: must be a single number")
    return float(arr.reshape(-1)[0])


def _is_bool(value):
    if isinstance(value, (bool, np.bool_)):
        return True
    try:
        return np.asarray(value).dtype.kind == "b"
    except Exception:  # ragged lists and the like: as_float_array names them
        return False


def as_number(name, value):
    """As :func:`as_scalar`, refusing bools (True is not the number 1 here)."""
    if _is_bool(value):
        raise InvalidInputError(f"{name} = {value!r}: must be a real number, not a bool")
    return as_scalar(name, value)


def as_number_array(name, value):
    """As :func:`as_float_array`, refusing bools and arrays of them."""
    if _is_bool(value):
        raise InvalidInputError(f"{name}: must be a real number or an array of them, not "
                                "bools")
    return as_float_array(name, value)


def names(table, codes, shape):
    """Integer codes from the Fortran layer as their names: a str for a 0-d result,
    else an array of the given shape."""
    out = np.asarray(table)[np.asarray(codes)]
    if shape == ():
        return str(out.reshape(-1)[0])
    return out.reshape(shape)


def broadcast(empty_ok=False, **arrays):
    """Broadcast named float arrays together like a numpy ufunc.

    Returns (shape, {name: array}) with each array converted; raises
    InvalidInputError naming the arguments when the shapes do not broadcast, when they are
    bools (True is not the number 1 here) or when one is empty, unless `empty_ok` (the
    caller's Fortran routine takes zero-length arrays and gives empty results: f2py refuses
    a zero length for the second and later arrays that share one size)."""
    converted = {name: as_number_array(name, value) for name, value in arrays.items()}
    empty = [name for name, a in converted.items() if a.size == 0]
    if empty and not empty_ok:
        raise InvalidInputError(f"{', '.join(empty)}: empty array (at least one value needed)")
    try:
        shape = np.broadcast_shapes(*(a.shape for a in converted.values()))
    except ValueError as exc:
        described = ", ".join(f"{n} {a.shape}" for n, a in converted.items())
        raise InvalidInputError(f"shapes do not broadcast together: {described}") from exc
    return shape, converted


def flat(arr, shape):
    """`arr` broadcast to `shape`, as a contiguous 1-d float64 array (no copy when
    it already is one)."""
    return np.ascontiguousarray(np.broadcast_to(arr, shape).reshape(-1))


def compact(arr, shape):
    """A parameter for the Fortran layer: length 1 when it is a single value
    (the fast path), else broadcast to `shape` and flattened."""
    if arr.size == 1:
        return arr.reshape(1)
    return flat(arr, shape)


def check_bool(name, value):
    """A flag given as bool (or 0/1); InvalidInputError otherwise."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral) and value in (0, 1):
        return bool(value)
    raise InvalidInputError(f"{name} = {value!r}: must be True or False")


def check_choice(name, value, allowed):
    """A name from `allowed`; InvalidInputError listing them otherwise."""
    if not isinstance(value, str) or value not in allowed:
        raise InvalidInputError(
            f"{name} = {value!r}: unknown value (allowed: {', '.join(map(repr, allowed))})")
    return value


def choice_code(name, value, codes):
    """The Fortran code of `value`, a name from `codes` ({name: code}, codes from
    _fortran_codes); InvalidInputError listing the names otherwise."""
    return codes[check_choice(name, value, tuple(codes))]


def by_code(names_of):
    """{code: name} for the Fortran codes 0, 1, ..., n - 1 as the tuple of names indexed
    by code (what names() takes)."""
    codes = sorted(names_of)
    if codes != list(range(len(codes))):
        raise ImportError(f"seispulse: Fortran codes {codes} are not 0..{len(codes) - 1}")
    return tuple(names_of[code] for code in codes)


def check_positive(name, value, unit=""):
    """A finite real scalar > 0 (a number: not a str or a bool)."""
    if isinstance(value, (str, bytes, bool, np.bool_)):
        raise InvalidInputError(f"{name} = {value!r}: must be a finite number > 0{unit}")
    try:
        x = float(value)
    except (TypeError, ValueError) as exc:
        raise InvalidInputError(f"{name} = {value!r}: must be a finite number > 0{unit}") from exc
    if not np.isfinite(x) or x <= 0.0:
        raise InvalidInputError(f"{name} = {x!r}: must be a finite number > 0{unit}")
    return x


def accel_unit_code(name, units):
    """The Fortran UNITS_* code of an acceleration unit given as argument ``name``: the
    library's one vocabulary (accel_unit_code), the same as the driver's: 'g', 'm/s2',
    'm/s^2', 'cm/s2', 'cm/s^2', 'gal', case and surrounding blanks ignored."""
    from ._seispulse import sp_accel_unit_code
    # f2py takes ASCII text only: any other value is sent as '?' (never a unit), so the
    # library's message (with the list of the allowed names) names what was given
    plain = isinstance(units, str) and units.isascii() and units.strip()
    code, stat, msg = sp_accel_unit_code(units if plain else "?")
    if stat != SEISPULSE_SUCCESS:
        msg = msg.decode("ascii", "replace") if isinstance(msg, bytes) else str(msg)
        if not plain:
            msg = msg.replace("'?'", repr(units), 1)
        raise_for_status(stat, f"{name} = {msg.strip()}")
    return int(code)


def raise_for_status(stat, errmsg, rename=None, indexed=None):
    """Raise the exception of a nonzero Fortran status, with its message.

    `rename` maps Fortran parameter names to the Python ones, so the message names
    the argument the caller actually passed. `indexed` names Fortran arrays (an iterable,
    or {Fortran name: Python name}) whose elements name(i) the message gives as Python's
    name[i - 1]."""
    if stat == SEISPULSE_SUCCESS:
        return
    msg = errmsg.decode("ascii", "replace") if isinstance(errmsg, bytes) else str(errmsg)
    msg = msg.strip()
    if indexed:
        table = indexed if isinstance(indexed, dict) else {name: name for name in indexed}
        pattern = r"\b(" + "|".join(map(re.escape, table)) + r")\((\d+)\)"
        msg = re.sub(pattern, lambda m: f"{table[m.group(1)]}[{int(m.group(2)) - 1}]", msg)
    for fortran_name, python_name in (rename or {}).items():
        if msg.startswith(fortran_name + " ") or msg.startswith(fortran_name + ":"):
            msg = python_name + msg[len(fortran_name):]
    raise STATUS_ERRORS.get(int(stat), InternalError)(msg or f"status {stat}")


def shaped(shape, *arrays):
    """Reshape flat results; 0-d results become Python floats."""
    if shape == ():
        return tuple(float(a[0]) for a in arrays)
    return tuple(a.reshape(shape) for a in arrays)


def record_and_step(accel, dt):
    """accel and dt from an array and a step, or from a seispulse.records.Record."""
    if hasattr(accel, "accel") and hasattr(accel, "dt"):
        if dt is not None and float(dt) != float(accel.dt):
            raise InvalidInputError(f"dt = {dt!r}: differs from the record's dt = {accel.dt!r}"
                                    " (leave dt out for a Record)")
        dt = accel.dt
        accel = accel.accel
    rec = as_number_array("accel", accel)
    if rec.ndim != 1:
        raise InvalidInputError(f"accel: must be a 1-d array of samples (got shape {rec.shape})")
    if rec.size == 0:
        raise InvalidInputError("accel: the record is empty")
    if dt is None:
        raise InvalidInputError("dt: the time step of accel (s, > 0) is required")
    return np.ascontiguousarray(rec), check_positive("dt", dt, " (s)")


def missing_package(package, purpose):
    """The ImportError of an optional package that is not installed: it names the package,
    what needs it and how to install it (``package``: the name pip knows)."""
    return ImportError(f"{purpose} needs the optional package '{package}', which is not "
                       f"installed: pip install {package}", name=package)


def optional_import(package, purpose):
    """Import an optional package (pandas, ...) at the point of use; a missing one raises
    :func:`missing_package`'s ImportError. Never called at ``import seispulse``."""
    import importlib
    try:
        return importlib.import_module(package)
    except ModuleNotFoundError as exc:
        if exc.name != package:     # the package is there but one of its imports fails
            raise
        raise missing_package(package, purpose) from None
