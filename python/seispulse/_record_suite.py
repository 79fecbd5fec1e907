"""EN 1998-1 3.2.3.1.2(4): a suite of recorded accelerograms checked against the code's
elastic spectrum (Fortran module ``seispulse_record_suite``; doc/record-suites.md). Users
reach these names as ``seispulse.codes.<name>``.

The rules: (a) at least 3 records; (b) the mean PGA of the records (their zero-period
spectral acceleration) not below a_g S, the elastic spectrum at T = 0; (c) over
[0.2 T1, 2 T1] no value of the mean 5 %-damped elastic spectrum (PSA) of the suite below
90 % of the code's elastic spectrum, checked on a grid and refined between its periods.
With at least 7 records the mean response should be used (EN 1998-1 4.3.3.4.3(3)); else
the most unfavourable one.
"""

import math
import numbers
import re
import warnings
from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_ec8_suite_check_records, sp_suite_records_room,
                         sp_suite_spectrum_fraction)
from ._table import TableResult, format_number, format_table
from .errors import InvalidInputError

__all__ = ["SUITE_FITS", "SUITE_DAMPING", "SUITE_REFINE_MARGIN", "SUITE_SPECTRUM_FRACTION",
           "SuiteCheck", "SpectrumTarget",
           "check_record_suite", "elastic_target", "eak2000_target"]

#: Per-record scale factors fitted to the target over the check grid: least squares on
#: the ordinates (doc/record-suites.md (M.2)) or on their logarithms (M.3).
_FIT_CODES = {"linear": _f.SUITE_FIT_LINEAR, "log": _f.SUITE_FIT_LOG}
SUITE_FITS = tuple(_FIT_CODES)
#: Damping ratio of the records' spectra: the code's elastic spectrum is 5 %-damped.
SUITE_DAMPING = 0.05
#: Grid intervals whose smaller end ratio lies within a margin of the least ratio on the
#: grid are searched for the least ratio between grid periods (with the intervals next to
#: the grid's local minima within twice the margin); the margin is one grid spacing,
#: 10^(1/(n_points - 1)) - 1, at least this value (doc/record-suites.md section 2).
SUITE_REFINE_MARGIN = 0.005
#: Rule (c): the mean spectrum of the suite must not lie below this fraction of the
#: target (EN 1998-1 3.2.3.1.2(4)c: 90 %; the library's SUITE_SPECTRUM_FRACTION) (-).
SUITE_SPECTRUM_FRACTION = float(sp_suite_spectrum_fraction())
_RULES = {_f.SUITE_RULE_PGA: "pga", _f.SUITE_RULE_SPECTRUM: "spectrum"}
#: PGA (g) above which a record given in g probably was in m/s2 or cm/s2 (a warning).
_PLAUSIBLE_PGA = 5.0

_VALUE_FIELDS = ("t1", "t_low", "t_high", "pga_mean", "pga_target", "pga_ratio", "min_ratio",
                 "t_min_ratio", "common_scale", "own_pga_ratio", "own_min_ratio",
                 "own_t_min_ratio", "grid_min_ratio", "grid_own_min_ratio")
_FLAG_FIELDS = ("pga_ok", "spectrum_ok", "count_ok", "mean_allowed", "passed", "own_passed")

_FIELDS = ["t1", "t_range", "periods", "target", "mean", "ratio", "names", "psa", "pga",
           "pga_mean", "pga_target", "pga_ratio", "pga_ok", "min_ratio", "t_min_ratio",
           "spectrum_ok", "count_ok", "mean_allowed", "passed", "common_scale", "own_scale",
           "own_pga_ratio", "own_min_ratio", "own_t_min_ratio", "own_passed", "own_mean", "fit",
           "target_label", "scale_rule", "grid_min_ratio", "grid_own_min_ratio", "n_grid",
           "n_searched"]


class SuiteCheck(TableResult, namedtuple("SuiteCheck", _FIELDS)):
    """Outcome of :func:`check_record_suite` (EN 1998-1 3.2.3.1.2(4), doc/record-suites.md).

    The suite: t1 (s), t_range = (0.2 T1, 2 T1) (s); on the periods ``periods`` (s, the
    check grid with the refined least ratios added): target, the code spectrum (g), mean,
    the mean 5 % PSA of the records (g), ratio = mean/target (-); names of the records,
    psa (g, shape (n_records, n_periods)), pga (g). target_label describes the target;
    n_grid is the number of grid periods (without the refined ones).

    The rules: pga_mean (g), pga_target (the target at T = 0: a_g S for EN 1998-1,
    gamma_I A for EAK 2000, g), pga_ratio (-) and pga_ok (rule (b)); min_ratio (-), the
    least mean/target over [0.2 T1, 2 T1] (grid, then refined between grid periods), at
    t_min_ratio (s), and spectrum_ok = min_ratio >= 0.9 (rule (c)); grid_min_ratio, the
    least on the grid alone; count_ok (rule (a): at least 3 records); mean_allowed (at
    least 7 records: EN 1998-1 4.3.3.4.3(3), the mean response should then be used, else
    the most unfavourable one; not part of the check); passed = (a) and (b) and (c) at the
    checked periods.

    Scaling: common_scale (-), the smallest factor for all records that makes (b) and (c)
    hold (M.1), set by rule scale_rule ('pga' or 'spectrum'); own_scale (-), one factor per
    record fitted to the target over the grid periods (``fit`` 'linear' (M.2) or 'log'
    (M.3)); own_pga_ratio, own_min_ratio (refined; grid_own_min_ratio on the grid),
    own_t_min_ratio (s), own_passed and own_mean (g): the suite with each record scaled by
    its own factor. n_searched: grid intervals searched by the refinement.

    ``print()`` shows the check (name, value, unit) and the per-record table;
    :meth:`table` and :meth:`to_frame` give the per-period table (period, target,
    0.9 target, mean, ratio, common-scaled and own mean, each record's PSA).
    """

    __slots__ = ()

    def _table_columns(self):
        cols = [("period", "s", np.asarray(self.periods)),
                ("target", "g", np.asarray(self.target)),
                ("target_90", "g", SUITE_SPECTRUM_FRACTION * np.asarray(self.target)),
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
        at_zero = "gamma_I A" if self.target_label.startswith("EAK") else "a_g S"
        rows = [
            ("target", self.target_label, "", "elastic 5 % spectrum"),
            ("records", len(self.names), "", "rule (a): at least 3 " + yes(self.count_ok)),
            ("t1", self.t1, "s", ""),
            ("t_range", f"{format_number(self.t_range[0], digits)} .. "
                        f"{format_number(self.t_range[1], digits)}", "s", "0.2 T1 .. 2 T1"),
            ("periods checked", self.n_grid, "",
             f"grid; {self.n_searched} intervals searched between them"),
            ("pga_mean", self.pga_mean, "g", "mean PGA of the records"),
            ("pga_target", self.pga_target, "g", f"{at_zero}, the target at T = 0"),
            ("pga_ratio", self.pga_ratio, "-", "rule (b): >= 1 " + yes(self.pga_ok)),
            ("min_ratio", self.min_ratio, "-",
             f"rule (c): mean/target >= {SUITE_SPECTRUM_FRACTION:g} "
             + yes(self.spectrum_ok)),
            ("t_min_ratio", self.t_min_ratio, "s", "where min_ratio is"),
            ("grid_min_ratio", self.grid_min_ratio, "-", "least on the grid periods alone"),
            ("check", yes(self.passed), "", "(a), (b) and (c) at the checked periods"),
            ("mean_allowed", "yes" if self.mean_allowed else "no", "",
             ">= 7 records: use the mean response (4.3.3.4.3(3))" if self.mean_allowed else
             "< 7 records: use the most unfavourable response"),
            ("common_scale", self.common_scale, "-",
             f"least factor on all records to pass; set by rule "
             f"{'(b) pga' if self.scale_rule == 'pga' else '(c) spectrum'}"),
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
        T1, a grid period) (str)."""
        at = int(np.argmin(np.abs(np.asarray(self.periods) - self.t1)))
        psa = np.asarray(self.psa)
        return format_table([("name", "", list(self.names)),
                             ("pga", "g", np.asarray(self.pga)),
                             ("own_scale", "-", np.asarray(self.own_scale)),
                             ("psa_t1", "g", psa[:, at])], digits=digits)

    def __str__(self):
        return (f"EN 1998-1 3.2.3.1.2(4) record-suite check: "
                f"{'passed' if self.passed else 'FAILED'} (at the checked periods)\n"
                f"{self.summary()}\n\n"
                f"{self.record_table()}\n[.table() or .to_frame(): the per-period table]")

    def __repr__(self):
        return f"{type(self).__name__}:\n{self}"


class SpectrumTarget:
    """The target of :func:`check_record_suite`: a code's elastic 5 % spectrum that the
    library evaluates at any period. Made by :func:`elastic_target` (EN 1998-1) or
    :func:`eak2000_target` (EAK 2000); not constructed directly.

    Attributes: ``code`` ('EC8' or 'EAK'), ``label`` (a description), ``corner_periods``
    (s; they join the check grid where they fall inside [0.2 T1, 2 T1]), ``pga`` (the
    spectrum at T = 0, g: a_g S or gamma_I A). ``target(periods)`` gives the spectrum (g).
    """

    __slots__ = ("code", "label", "corner_periods", "pga", "_args", "_spectrum")

    def __init__(self, code, args, spectrum, corner_periods, label):
        self.code = code
        self._args = dict(args)
        self._spectrum = spectrum
        self.corner_periods = tuple(float(t) for t in corner_periods)
        self.label = str(label)
        self.pga = float(spectrum(0.0))

    def __call__(self, periods):
        """The spectrum at ``periods`` (s, >= 0), g."""
        return self._spectrum(periods)

    def __repr__(self):
        return f"SpectrumTarget({self.label}, corner_periods={self.corner_periods})"


def _positive_acceleration(name, value):
    if not (math.isfinite(value) and value > 0.0):
        raise InvalidInputError(f"{name} = {value!r}: the target's ground acceleration (g) "
                                "must be finite and > 0 (a record suite cannot be checked "
                                "against a zero spectrum)")
    return value


def elastic_target(ag=None, spectrum_type=1, ground="A", *, zone=None, national_annex=None,
                   importance=1.0):
    """The EN 1998-1 elastic spectrum (3.2)-(3.5) at 5 % damping as the target of
    :func:`check_record_suite`: the arguments of :func:`seispulse.codes.elastic_spectrum`
    without the periods and the damping (e.g. ``elastic_target(0.24, ground='B')`` or
    ``elastic_target(zone='Z2', ground='C', importance=1.2)``); ag (g) must be > 0. Its
    corner periods TB, TC, TD join the check grid; its value at T = 0, a_g S, is the PGA
    target. Returns :class:`SpectrumTarget`."""
    from . import codes
    a = _positive_acceleration("ag", codes._design_ag(ag, zone, national_annex, importance))
    stype = codes._spectrum_type(spectrum_type)
    gcode = codes._ground(ground)
    par = codes.ground_parameters(spectrum_type, ground)
    gname = ground.strip().upper()

    def spectrum(periods):
        return codes.elastic_spectrum(periods, a, spectrum_type, ground)

    where = f"zone {zone}, importance {importance:g}" if zone is not None else ""
    label = (f"EC8 type {stype} ground {gname}, a_g = {a:.6g} g"
             + (f" ({where})" if where else ""))
    return SpectrumTarget("EC8", {"code": _f.SUITE_TARGET_EC8, "spectrum_type": stype,
                                  "ag": a, "ground": gcode},
                          spectrum, (par.tb, par.tc, par.td), label)


def eak2000_target(zone="Z2", ground="B", importance=1.0, *, alpha=None, zone_map="2003",
                   eta_min=0.0, elastic_exponent=2.0 / 3.0):
    """The EAK 2000 elastic spectrum Phi_e ((K.1)-(K.3) with q = theta = 1) at 5 % damping
    as the target of :func:`check_record_suite`; the arguments of
    :func:`seispulse.codes.eak2000_spectrum` (``kind='elastic'``) without the periods,
    q, theta and damping; alpha = A/g must be > 0. Its corner periods T1, T2 (of the
    ground, not the structure's T1) join the check grid; its value at T = 0, gamma_I A,
    is the PGA target. EAK's values are SECONDARY and partly unverified
    (doc/eak2000.md). Returns :class:`SpectrumTarget`."""
    from . import _eak2000, codes
    a = _positive_acceleration("alpha", _eak2000._alpha(zone, zone_map, alpha))
    gcode = _eak2000._ground(ground)
    gamma_i = _eak2000._importance(importance)
    floor = _eak2000._eta_min(eta_min)
    expo = _core.as_number("elastic_exponent", elastic_exponent)
    par = codes.eak2000_parameters(ground=ground, alpha=a, eta_min=floor)

    def spectrum(periods):
        return codes.eak2000_spectrum(periods, ground=ground, importance=gamma_i, alpha=a,
                                      kind="elastic", eta_min=floor, elastic_exponent=expo)

    spectrum(0.0)      # refuse a bad exponent now
    where = f"zone {zone}" if alpha is None else "alpha given"
    label = (f"EAK 2000 elastic ground {ground.strip().upper()}, A/g = {a:.6g} ({where}), "
             f"gamma_I = {gamma_i:.6g}")
    return SpectrumTarget("EAK", {"code": _f.SUITE_TARGET_EAK, "alpha": a, "ground": gcode,
                                  "importance": gamma_i, "eta_min": floor, "exponent": expo},
                          spectrum, (par.t1, par.t2), label)


def _is_pair(item):
    return (isinstance(item, (tuple, list)) and len(item) == 2 and np.ndim(item[0]) == 1
            and np.ndim(item[1]) == 0)


def _records(records, dt, names, units):
    """[(name, accel g, dt s)] of a sequence of Records, (accel, dt) pairs or arrays (with
    dt; in ``units``)."""
    from .records import accel_unit_factor
    if isinstance(records, (str, bytes)) or not hasattr(records, "__len__"):
        raise InvalidInputError("records: must be a sequence of seispulse.records.Record or "
                                "of (accel, dt) pairs")
    factor = accel_unit_factor(units)
    out = []
    for k, item in enumerate(records):
        what = f"records[{k}]"
        is_record = False
        if _is_pair(item):
            if dt is not None:
                raise InvalidInputError(f"dt = {dt!r}: {what} is an (accel, dt) pair with its "
                                        "own dt; give dt only for plain arrays")
            acc, step = item
            name = f"record {k}"
        else:
            acc, step = item, dt
            is_record = hasattr(item, "accel") and hasattr(item, "dt")
            name = getattr(item, "name", None) or f"record {k}"
            if dt is None and not is_record:
                raise InvalidInputError(f"dt: {what} is an array of samples; its time step "
                                        "(s, > 0) is required (or give (accel, dt) pairs)")
        try:
            acc, step = _core.record_and_step(acc, step)
        except InvalidInputError as exc:
            raise InvalidInputError(f"{what}: {exc}") from None
        bad = np.flatnonzero(~np.isfinite(acc))
        if bad.size:
            raise InvalidInputError(f"{what} ({name!r}): accel[{bad[0]}] = "
                                    f"{float(acc[bad[0]])!r}: every sample must be finite")
        if is_record:
            if factor != 1.0:
                raise InvalidInputError(f"units = {units!r}: {what} is a Record, already in g;"
                                        " units applies to arrays and (accel, dt) pairs")
        else:
            acc = acc * factor
        out.append([name, acc, step])
    if names is not None:
        if isinstance(names, str) or len(names) != len(out):
            raise InvalidInputError(f"names: needs one name per record ({len(out)})")
        for row, name in zip(out, names):
            row[0] = str(name)
    for k, (name, acc, _) in enumerate(out):
        peak = float(np.max(np.abs(acc)))
        if peak > _PLAUSIBLE_PGA:
            warnings.warn(f"records[{k}] ({name!r}): PGA = {peak:.4g} g; is the record in g? "
                          "(give units='m/s2' or 'cm/s2' for other units)", stacklevel=3)
    return out


def _integer(name, value, least, rule):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral) \
            or value < least:
        raise InvalidInputError(f"{name} = {value!r}: must be an integer >= {least} ({rule})")
    return int(value)


_TARGET_HELP = ("target: must be a SpectrumTarget from codes.elastic_target(...) (EN 1998-1) "
                "or codes.eak2000_target(...) (EAK 2000); other (site-specific) targets are "
                "not supported yet")


def check_record_suite(records, t1, target, *, dt=None, units="g", n_points=400,
                       extra_periods=None, fit="linear", min_records=3, names=None,
                       _margin=None):
    """Check a record suite against the code's elastic spectrum, EN 1998-1 3.2.3.1.2(4)
    (doc/record-suites.md).

    Parameters
    ----------
    records : sequence
        The records: :class:`seispulse.records.Record` objects (in g), ``(accel, dt)``
        pairs (samples in ``units``, step in s), or arrays of samples in ``units`` with
        ``dt``. A PGA above 5 g gives a warning (a record in m/s2 taken as g?).
    t1 : float
        Fundamental period T1 of the structure (s, > 0): the check runs over
        [0.2 T1, 2 T1].
    target : SpectrumTarget
        The code's elastic 5 % spectrum: :func:`elastic_target` (EN 1998-1, e.g.
        ``codes.elastic_target(0.24, ground='B')``) or :func:`eak2000_target` (EAK 2000).
        Its value at T = 0 (a_g S; gamma_I A for EAK) is the PGA target of rule (b), its
        corner periods join the grid. A plain callable is refused: the library must
        evaluate the target between grid periods; site-specific targets (or a design
        spectrum, other damping) are not supported yet.
    dt : float, optional
        Time step (s) of records given as plain arrays.
    units : {'g', 'm/s2', 'cm/s2', 'gal'}
        Unit of the samples of arrays and ``(accel, dt)`` pairs (default g; Records are
        in g already and need no units).
    n_points : int
        Log-spaced periods from 0.2 T1 to 2 T1, both included (default 400; >= 2). The
        grid also holds T1, the target's corner periods and ``extra_periods`` inside the
        range. Rule (c) is then searched between grid periods (Brent) on every interval
        whose smaller end ratio lies within one grid spacing (0.58 % at 400 points, at
        least 0.5 %, :data:`SUITE_REFINE_MARGIN`) of the least grid ratio, and next to
        the grid's local minima within twice that; the refined least ratio gives
        min_ratio, common_scale and the verdict, and its period joins ``periods``. A
        trough narrower than the grid spacing whose grid neighbours both lie above the
        margin, away from such a local minimum, can be missed (doc/record-suites.md).
    extra_periods : array_like, optional
        Further periods (s, finite) to check; those outside [0.2 T1, 2 T1] are left out.
    fit : {'linear', 'log'}
        The own scale factor of each record: least squares over the grid periods on the
        ordinates (M.2) or on their logarithms (M.3).
    min_records : int
        Fewer records raise InvalidInputError (default 3, rule (a); 1 or 2 give a check
        with count_ok False).
    names : sequence of str, optional
        The records' names (default: a Record's name, else 'record k').

    Returns
    -------
    SuiteCheck
        The check, the scale factors and the spectra on the checked periods.

    The records' spectra are 5 %-damped PSA = (2 pi / T)^2 SD / g with the true maxima
    (the library's sdof_spectrum with exact peaks, as :func:`seispulse.sdof.spectrum`);
    their PGA is max |accel|. A record whose PGA or PSA on the grid is 0 cannot be
    scaled: InvalidInputError names it.
    """
    t1 = _core.as_scalar("t1", t1)
    n_points = _integer("n_points", n_points, 2, "log-spaced periods from 0.2 T1 to 2 T1")
    min_records = _integer("min_records", min_records, 1, "EN 1998-1 3.2.3.1.2(4)a asks for 3")
    fit_code = _core.choice_code("fit", fit, _FIT_CODES)
    if not isinstance(target, SpectrumTarget):
        raise InvalidInputError(_TARGET_HELP)
    recs = _records(records, dt, names, units)
    if len(recs) < min_records:
        raise InvalidInputError(f"records: {len(recs)} given; the suite needs at least "
                                f"{min_records} (EN 1998-1 3.2.3.1.2(4)a: at least 3)")
    extra = np.ascontiguousarray(np.zeros(0) if extra_periods is None else
                                 _core.as_float_array("extra_periods", extra_periods)
                                 .reshape(-1))
    lengths = np.array([r[1].size for r in recs], dtype=np.int32)
    first = (np.concatenate([[0], np.cumsum(lengths)[:-1]]) + 1).astype(np.int32)
    accel = np.ascontiguousarray(np.concatenate([r[1] for r in recs]))
    steps = np.array([r[2] for r in recs], dtype=np.float64)
    a = target._args
    nmax = int(sp_suite_records_room(n_points, extra.size))
    (periods, n, psa, pga, target_psa, mean, ratio, own_mean, own_scale, values, flags, ints,
     stat, msg) = sp_ec8_suite_check_records(
        accel, first, lengths, steps, a["code"], a.get("spectrum_type", 1), a.get("ag", 0.0),
        a["ground"], a.get("alpha", 0.0), a.get("importance", 1.0), a.get("eta_min", 0.0),
        a.get("exponent", 2.0 / 3.0), t1, fit_code, n_points, extra, min_records,
        -1.0 if _margin is None else float(_margin), nmax)
    if stat != 0:
        text = (msg.decode("ascii", "replace") if isinstance(msg, bytes) else str(msg)).strip()
        found = re.match(r"record (\d+): (.*)", text, re.S)
        if found:
            k = int(found.group(1)) - 1
            text = f"records[{k}] ({recs[k][0]!r}): {found.group(2)}"
        _core.raise_for_status(stat, text, indexed={"extra": "extra_periods",
                                                    "accel": "accel"})
    v = dict(zip(_VALUE_FIELDS, map(float, values)))
    f = dict(zip(_FLAG_FIELDS, (bool(x) for x in flags)))
    n = int(n)
    return SuiteCheck(
        t1=v["t1"], t_range=(v["t_low"], v["t_high"]), periods=periods[:n].copy(),
        target=target_psa[:n].copy(), mean=mean[:n].copy(), ratio=ratio[:n].copy(),
        names=tuple(r[0] for r in recs), psa=np.ascontiguousarray(psa[:n].T), pga=pga,
        pga_mean=v["pga_mean"], pga_target=v["pga_target"], pga_ratio=v["pga_ratio"],
        pga_ok=f["pga_ok"], min_ratio=v["min_ratio"], t_min_ratio=v["t_min_ratio"],
        spectrum_ok=f["spectrum_ok"], count_ok=f["count_ok"],
        mean_allowed=f["mean_allowed"], passed=f["passed"], common_scale=v["common_scale"],
        own_scale=own_scale, own_pga_ratio=v["own_pga_ratio"],
        own_min_ratio=v["own_min_ratio"], own_t_min_ratio=v["own_t_min_ratio"],
        own_passed=f["own_passed"], own_mean=own_mean[:n].copy(), fit=fit,
        target_label=target.label, scale_rule=_RULES.get(int(ints[0]), "?"),
        grid_min_ratio=v["grid_min_ratio"], grid_own_min_ratio=v["grid_own_min_ratio"],
        n_grid=int(ints[3]), n_searched=int(ints[1]))
