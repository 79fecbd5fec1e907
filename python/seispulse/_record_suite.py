"""EN 1998-1 3.2.3.1.2(4): a suite of recorded accelerograms checked against the code's
elastic spectrum (Fortran module ``seispulse_record_suite``; doc/record-suites.md). Users
reach these names as ``seispulse.codes.<name>``.

The rules: (a) at least 3 records; (b) the mean PGA of the records (their zero-period
spectral acceleration) not below a_g S, the elastic spectrum at T = 0; (c) over
[0.2 T1, 2 T1] no value of the mean 5 %-damped elastic spectrum (PSA) of the suite below
90 % of the code's elastic spectrum. With at least 7 records the mean response may be
used (EN 1998-1 4.3.3.4.3(3)); else the most unfavourable one.
"""

import inspect
import numbers
from collections import namedtuple

import numpy as np

from . import _core, sdof
from . import _fortran_codes as _f
from ._seispulse import sp_ec8_suite_check, sp_suite_check_periods
from ._table import TableResult, format_number, format_table
from .errors import InvalidInputError

__all__ = ["SUITE_FITS", "SUITE_DAMPING", "SuiteCheck", "SpectrumTarget", "check_record_suite",
           "elastic_target"]

#: Per-record scale factors fitted to the target over the check grid: least squares on
#: the ordinates (doc/record-suites.md (M.2)) or on their logarithms (M.3).
_FIT_CODES = {"linear": _f.SUITE_FIT_LINEAR, "log": _f.SUITE_FIT_LOG}
SUITE_FITS = tuple(_FIT_CODES)
#: Damping ratio of the records' spectra: the code's elastic spectrum is 5 %-damped.
SUITE_DAMPING = 0.05
#: Standard gravity (m/s^2), the default g.
STANDARD_GRAVITY = 9.80665

_VALUE_FIELDS = ("t1", "t_low", "t_high", "pga_mean", "pga_target", "pga_ratio", "min_ratio",
                 "t_min_ratio", "common_scale", "own_pga_ratio", "own_min_ratio",
                 "own_t_min_ratio")
_FLAG_FIELDS = ("pga_ok", "spectrum_ok", "count_ok", "mean_allowed", "passed", "own_passed")

_FIELDS = ["t1", "t_range", "periods", "target", "mean", "ratio", "names", "psa", "pga",
           "pga_mean", "pga_target", "pga_ratio", "pga_ok", "min_ratio", "t_min_ratio",
           "spectrum_ok", "count_ok", "mean_allowed", "passed", "common_scale", "own_scale",
           "own_pga_ratio", "own_min_ratio", "own_t_min_ratio", "own_passed", "own_mean", "fit"]


class SuiteCheck(TableResult, namedtuple("SuiteCheck", _FIELDS)):
    """Outcome of :func:`check_record_suite` (EN 1998-1 3.2.3.1.2(4), doc/record-suites.md).

    The suite: t1 (s), t_range = (0.2 T1, 2 T1) (s); on the check grid ``periods`` (s):
    target, the code spectrum (g), mean, the mean 5 % PSA of the records (g), ratio =
    mean/target (-); names of the records, psa (g, shape (n_records, n_periods)), pga (g).

    The rules: pga_mean (g), pga_target (a_g S, g), pga_ratio (-) and pga_ok (rule (b));
    min_ratio (-), the least mean/target on the grid, at t_min_ratio (s), and spectrum_ok
    = min_ratio >= 0.9 (rule (c)); count_ok (rule (a): at least 3 records);
    mean_allowed (at least 7: the mean response may be used, EN 1998-1 4.3.3.4.3(3));
    passed = (a) and (b) and (c).

    Scaling: common_scale (-), the smallest factor for all records that makes (b) and (c)
    hold (M.1); own_scale (-), one factor per record fitted to the target over the grid
    (``fit`` 'linear' (M.2) or 'log' (M.3)); own_pga_ratio, own_min_ratio,
    own_t_min_ratio (s), own_passed and own_mean (g): the suite with each record scaled by
    its own factor.

    ``print()`` shows the check (name, value, unit) and the per-record table;
    :meth:`table` and :meth:`to_frame` give the per-period table (period, target,
    0.9 target, mean, ratio, own mean and each record's PSA).
    """

    __slots__ = ()

    def _table_columns(self):
        cols = [("period", "s", np.asarray(self.periods)),
                ("target", "g", np.asarray(self.target)),
                ("target_90", "g", 0.9 * np.asarray(self.target)),
                ("mean", "g", np.asarray(self.mean)),
                ("ratio", "-", np.asarray(self.ratio)),
                ("mean_common", "g", self.common_scale * np.asarray(self.mean)),
                ("mean_own", "g", np.asarray(self.own_mean))]
        for name, row in zip(self.names, self.psa):
            cols.append((f"psa {name}", "g", np.asarray(row)))
        return cols

    def _frame_attrs(self):
        return {"t1": self.t1, "passed": self.passed, "common_scale": self.common_scale}

    def summary(self, digits=6):
        """The check as aligned lines: quantity, value, unit (str)."""
        def yes(flag):
            return "pass" if flag else "fail"
        rows = [
            ("records", len(self.names), "", "rule (a): at least 3 " + yes(self.count_ok)),
            ("t1", self.t1, "s", ""),
            ("t_range", f"{format_number(self.t_range[0], digits)} .. "
                        f"{format_number(self.t_range[1], digits)}", "s", "0.2 T1 .. 2 T1"),
            ("periods checked", len(self.periods), "", ""),
            ("pga_mean", self.pga_mean, "g", "mean PGA of the records"),
            ("pga_target", self.pga_target, "g", "a_g S, the target at T = 0"),
            ("pga_ratio", self.pga_ratio, "-", "rule (b): >= 1 " + yes(self.pga_ok)),
            ("min_ratio", self.min_ratio, "-", "rule (c): mean/target >= 0.9 "
             + yes(self.spectrum_ok)),
            ("t_min_ratio", self.t_min_ratio, "s", "where min_ratio is"),
            ("check", yes(self.passed), "", "(a), (b) and (c)"),
            ("mean_allowed", "yes" if self.mean_allowed else "no", "",
             "mean response allowed (>= 7 records)" if self.mean_allowed else
             "< 7 records: use the most unfavourable response"),
            ("common_scale", self.common_scale, "-", "least factor on all records to pass"),
            ("fit", self.fit, "", "own_scale fit of each record"),
            ("own_pga_ratio", self.own_pga_ratio, "-", "each record x own_scale"),
            ("own_min_ratio", self.own_min_ratio, "-", ""),
            ("own_t_min_ratio", self.own_t_min_ratio, "s", ""),
            ("own_check", yes(self.own_passed), "", ""),
        ]
        return format_table([("quantity", "", [r[0] for r in rows]),
                             ("value", "", [format_number(r[1], digits) for r in rows]),
                             ("unit", "", [r[2] for r in rows]),
                             ("note", "", [r[3] for r in rows])], digits=digits)

    def record_table(self, digits=6):
        """One line per record: name, pga (g), own_scale (-), psa_t1 (g, the 5 % PSA at
        T1, on the grid) (str)."""
        at = int(np.argmin(np.abs(np.asarray(self.periods) - self.t1)))
        psa = np.asarray(self.psa)
        return format_table([("name", "", list(self.names)),
                             ("pga", "g", np.asarray(self.pga)),
                             ("own_scale", "-", np.asarray(self.own_scale)),
                             ("psa_t1", "g", psa[:, at])], digits=digits)

    def __str__(self):
        return (f"EN 1998-1 3.2.3.1.2(4) record-suite check: "
                f"{'passed' if self.passed else 'FAILED'}\n{self.summary()}\n\n"
                f"{self.record_table()}\n[.table() or .to_frame(): the per-period table]")

    def __repr__(self):
        return f"{type(self).__name__}:\n{self}"


class SpectrumTarget:
    """A target spectrum for :func:`check_record_suite` that knows its corner periods:
    ``spectrum(periods)`` -> ordinates (g), and ``corner_periods`` (s), added to the check
    grid where they fall inside [0.2 T1, 2 T1]. :func:`elastic_target` makes one for
    EN 1998-1."""

    __slots__ = ("spectrum", "corner_periods", "label")

    def __init__(self, spectrum, corner_periods=(), label="target"):
        if not callable(spectrum):
            raise InvalidInputError("spectrum: must be a callable periods (s) -> g")
        self.spectrum = spectrum
        self.corner_periods = tuple(float(t) for t in corner_periods)
        self.label = str(label)

    def __call__(self, periods):
        return self.spectrum(periods)

    def __repr__(self):
        return f"SpectrumTarget({self.label}, corner_periods={self.corner_periods})"


def elastic_target(*args, **kwargs):
    """The EN 1998-1 elastic spectrum as a target of :func:`check_record_suite`: the
    arguments of :func:`seispulse.codes.elastic_spectrum` without the periods (e.g.
    ``elastic_target(0.24, ground='B')``); its corner periods TB, TC, TD join the check
    grid. Damping must stay 5 % (the records' PSA is 5 %-damped). Returns
    :class:`SpectrumTarget`."""
    from . import codes
    try:
        bound = inspect.signature(codes.elastic_spectrum).bind(0.0, *args, **kwargs)
    except TypeError as exc:
        raise InvalidInputError(f"elastic_target: {exc}") from None
    bound.apply_defaults()
    params = dict(bound.arguments)
    params.pop("periods", None)
    xi = params.get("xi_percent", 5.0)
    if xi is None or _core.as_scalar("xi_percent", xi) != 5.0:
        raise InvalidInputError(f"xi_percent = {xi!r}: the record-suite check compares 5 % "
                                "spectra (EN 1998-1 3.2.3.1.2(4)); leave it at 5")
    ground = codes.ground_parameters(params.get("spectrum_type", 1), params.get("ground", "A"))
    codes.elastic_spectrum(0.0, *args, **kwargs)     # refuse bad arguments now

    def spectrum(periods):
        return codes.elastic_spectrum(periods, *args, **kwargs)

    shown = ", ".join([repr(a) for a in args] + [f"{k}={v!r}" for k, v in kwargs.items()])
    return SpectrumTarget(spectrum, (ground.tb, ground.tc, ground.td),
                          f"elastic_spectrum({shown})")


def _is_pair(item):
    return (isinstance(item, (tuple, list)) and len(item) == 2 and np.ndim(item[0]) == 1
            and np.ndim(item[1]) == 0)


def _records(records, dt, names):
    """[(name, accel g, dt s)] of a sequence of Records, (accel, dt) pairs or arrays (with
    dt)."""
    if isinstance(records, (str, bytes)) or not hasattr(records, "__len__"):
        raise InvalidInputError("records: must be a sequence of seispulse.records.Record or "
                                "of (accel_g, dt) pairs")
    out = []
    for k, item in enumerate(records):
        what = f"records[{k}]"
        if _is_pair(item):
            if dt is not None:
                raise InvalidInputError(f"dt = {dt!r}: {what} is an (accel_g, dt) pair with its "
                                        "own dt; give dt only for plain arrays")
            acc, step = item
            name = f"record {k}"
        else:
            acc, step = item, dt
            name = getattr(item, "name", None) or f"record {k}"
            if dt is None and not hasattr(item, "dt"):
                raise InvalidInputError(f"dt: {what} is an array of samples; its time step "
                                        "(s, > 0) is required (or give (accel_g, dt) pairs)")
        try:
            acc, step = _core.record_and_step(acc, step)
        except InvalidInputError as exc:
            raise InvalidInputError(f"{what}: {exc}") from None
        out.append([name, acc, step])
    if names is not None:
        if isinstance(names, str) or len(names) != len(out):
            raise InvalidInputError(f"names: needs one name per record ({len(out)})")
        for row, name in zip(out, names):
            row[0] = str(name)
    return out


def _min_records(value):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral) \
            or value < 1:
        raise InvalidInputError(f"min_records = {value!r}: must be an integer >= 1 "
                                "(EN 1998-1 3.2.3.1.2(4)a asks for 3)")
    return int(value)


def _n_points(value):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral) \
            or value < 2:
        raise InvalidInputError(f"n_points = {value!r}: must be an integer >= 2 (log-spaced "
                                "periods from 0.2 T1 to 2 T1)")
    return int(value)


def _target_values(target, periods):
    """The target at T = 0 and on the grid (g), checked."""
    if not callable(target):
        raise InvalidInputError("target: must be a callable periods (s) -> elastic 5 % "
                                "spectrum (g), e.g. lambda T: codes.elastic_spectrum(T, 0.24, "
                                "ground='B')")
    at = np.concatenate([[0.0], periods])
    values = np.asarray(target(at), dtype=np.float64)
    if values.shape != at.shape:
        values = np.array([float(target(float(t))) for t in at])
    bad = np.flatnonzero(~np.isfinite(values) | (values <= 0.0))
    if bad.size:
        k = bad[0]
        raise InvalidInputError(f"target: its value at T = {float(at[k])!r} s is "
                                f"{float(values[k])!r}: the "
                                "target spectrum (g) must be finite and > 0 at T = 0 and on "
                                "[0.2 T1, 2 T1]")
    return float(values[0]), np.ascontiguousarray(values[1:])


def check_record_suite(records, t1, target, *, dt=None, n_points=50, extra_periods=None,
                       fit="linear", min_records=3, g=STANDARD_GRAVITY, names=None):
    """Check a record suite against the code's elastic spectrum, EN 1998-1 3.2.3.1.2(4)
    (doc/record-suites.md).

    Parameters
    ----------
    records : sequence
        The records: :class:`seispulse.records.Record` objects, ``(accel_g, dt)`` pairs
        (samples in g, step in s), or arrays of samples in g with ``dt``.
    t1 : float
        Fundamental period T1 of the structure (s, > 0): the check runs over
        [0.2 T1, 2 T1].
    target : callable
        The code's elastic 5 % spectrum, periods (s, array) -> g, e.g.
        ``lambda T: codes.elastic_spectrum(T, 0.24, ground='B')``; its value at T = 0 is
        the PGA target a_g S. A target with ``corner_periods`` (s) (a
        :class:`SpectrumTarget`, e.g. from :func:`elastic_target`) adds them to the grid.
    dt : float, optional
        Time step (s) of records given as plain arrays.
    n_points : int
        Log-spaced periods from 0.2 T1 to 2 T1, both included (default 50; >= 2). The
        grid also holds T1, the target's corner periods and ``extra_periods`` that fall
        inside the range. The rule (c) is checked at the grid's periods only: between
        them the ratio can dip below its least value on the grid (50 points: 4.8 %
        apart, 10^(1/49); a record's spectrum can have narrow peaks and troughs
        between them: raise n_points to look closer; the corners are on the grid when
        the target gives them).
    extra_periods : array_like, optional
        Further periods (s, finite) to check; those outside [0.2 T1, 2 T1] are left out.
    fit : {'linear', 'log'}
        The own scale factor of each record: least squares on the ordinates (M.2) or
        on their logarithms (M.3).
    min_records : int
        Fewer records raise InvalidInputError (default 3, rule (a); 1 or 2 give a check
        with count_ok False).
    g : float
        Gravity (m/s^2) of the spectra (the PSA in g does not depend on it).
    names : sequence of str, optional
        The records' names (default: a Record's name, else 'record k').

    Returns
    -------
    SuiteCheck
        The check, the scale factors and the spectra on the grid.

    The records' spectra are 5 %-damped PSA = (2 pi / T)^2 SD / g with the true maxima
    (:func:`seispulse.sdof.spectrum`, ``peaks='exact'``); their PGA is the spectrum at
    T = 0 (max |accel|). A record whose PGA or PSA on the grid is 0 cannot be scaled:
    InvalidInputError names it.
    """
    t1 = _core.as_scalar("t1", t1)
    n_points = _n_points(n_points)
    min_records = _min_records(min_records)
    fit_code = _core.choice_code("fit", fit, _FIT_CODES)
    recs = _records(records, dt, names)
    if len(recs) < min_records:
        raise InvalidInputError(f"records: {len(recs)} given; the suite needs at least "
                                f"{min_records} (EN 1998-1 3.2.3.1.2(4)a: at least 3)")
    extra = [] if extra_periods is None else list(
        _core.as_float_array("extra_periods", extra_periods).reshape(-1))
    extra.append(t1)
    extra.extend(getattr(target, "corner_periods", ()) or ())
    extra = np.ascontiguousarray(np.asarray(extra, dtype=np.float64))
    grid, n, stat, msg = sp_suite_check_periods(t1, n_points, extra, n_points + extra.size)
    _core.raise_for_status(stat, msg, rename={"extra": "extra_periods"},
                           indexed={"extra": "extra_periods"})
    periods = np.ascontiguousarray(grid[:n])
    target_pga, target_grid = _target_values(target, periods)

    with_zero = np.concatenate([[0.0], periods])
    psa = np.empty((len(recs), n))
    pga = np.empty(len(recs))
    for k, (name, acc, step) in enumerate(recs):
        try:
            spec = sdof.spectrum(acc, step, periods=with_zero, damping=SUITE_DAMPING, g=g,
                                 peaks="exact")
        except InvalidInputError as exc:
            raise InvalidInputError(f"records[{k}] ({name!r}): {exc}") from None
        pga[k] = spec.psa[0]
        psa[k] = spec.psa[1:]
        if not pga[k] > 0.0:
            raise InvalidInputError(f"records[{k}] ({name!r}): its PGA is {float(pga[k])!r} g; a "
                                    "record with zero PGA cannot be scaled")
        bad = np.flatnonzero(~(psa[k] > 0.0))
        if bad.size:
            raise InvalidInputError(f"records[{k}] ({name!r}): its 5 % PSA at T = "
                                    f"{float(periods[bad[0]])!r} s is "
                                    f"{float(psa[k, bad[0]])!r} g; a record "
                                    "with zero PSA cannot be scaled")

    values, flags, own_scale, mean, ratio, own_mean, stat, msg = sp_ec8_suite_check(
        periods, np.asfortranarray(psa.T), pga, target_grid, target_pga, t1, fit_code,
        min_records)
    _core.raise_for_status(stat, msg, indexed=("periods",))
    v = dict(zip(_VALUE_FIELDS, map(float, values)))
    f = dict(zip(_FLAG_FIELDS, (bool(x) for x in flags)))
    return SuiteCheck(
        t1=v["t1"], t_range=(v["t_low"], v["t_high"]), periods=periods, target=target_grid,
        mean=mean, ratio=ratio, names=tuple(r[0] for r in recs), psa=psa, pga=pga,
        pga_mean=v["pga_mean"], pga_target=v["pga_target"], pga_ratio=v["pga_ratio"],
        pga_ok=f["pga_ok"], min_ratio=v["min_ratio"], t_min_ratio=v["t_min_ratio"],
        spectrum_ok=f["spectrum_ok"], count_ok=f["count_ok"],
        mean_allowed=f["mean_allowed"], passed=f["passed"], common_scale=v["common_scale"],
        own_scale=own_scale, own_pga_ratio=v["own_pga_ratio"],
        own_min_ratio=v["own_min_ratio"], own_t_min_ratio=v["own_t_min_ratio"],
        own_passed=f["own_passed"], own_mean=own_mean, fit=fit)
