"""Plots of the results a person wants to look at, with matplotlib (an optional
dependency: ``pip install matplotlib``; imported only when a function here is called).

Each function takes the result objects of the other modules as they are returned, draws
them in one call and returns the matplotlib :class:`~matplotlib.figure.Figure`; axes are
labelled with their units and legends lie inside the figure (a figure made here uses
matplotlib's constrained layout, so a plain ``fig.savefig(path)`` keeps everything).
Where one axes suffices ``ax=`` draws into the caller's axes; where there are several
panels ``ax=`` takes a sequence of as many axes.

* :func:`spectra`: response spectra of a record for several dampings (computed here with
  :func:`seispulse.sdof.spectrum`, or a :class:`~seispulse.sdof.Spectrum` or
  :class:`~seispulse.sdof.PulseSpectrum` already computed); SA, PSA (g; m/s^2 for a
  pulse), SV, PSV (m/s) or SD (m) against the period (s), log or linear period axis.
* :func:`newmark`: a Newmark run (:func:`seispulse.newmark.rigid`,
  :func:`~seispulse.newmark.decoupled`, :func:`~seispulse.newmark.coupled` with
  ``history=True``): the record (g) with the
  yield lines, the relative velocity (m/s) and the sliding displacement (m) on one time
  axis (s).
* :func:`rocking`: a run of :func:`seispulse.rocking.simulate` on a time grid: the
  excitation (g) with the uplift thresholds, theta (rad, and theta/alpha) and the angular
  velocity (rad/s).
* :func:`walls`: the pressure profiles of :func:`seispulse.walls.pressure_profile` (kPa
  against depth in m) beside the thrusts of every rule of :func:`seispulse.walls.comparison`
  (kN/m, with the point of application in m).
* :func:`pulse`: acceleration (m/s^2 and g), velocity (m/s) and displacement (m) of a
  pulse of :func:`seispulse.pulse.define` or a :class:`~seispulse.pulse.PulseHistory`.
* :func:`overturning_map`: a map of :func:`seispulse.rocking.overturning_map`, the
  legend of the classes under the axes.
* :func:`record_suite`: a record-suite check of :func:`seispulse.codes.check_record_suite`:
  each record's 5 % PSA, their mean, the target and 90 % of it over [0.2 T1, 2 T1] (g)
  against the period (s).
"""

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import sp_pulse_end_time, sp_pulse_eval
from .errors import InvalidInputError
from .pulse import STANDARD_GRAVITY   # m/s^2: converts m/s^2 to g where a plot shows both

__all__ = ["QUANTITIES", "spectra", "newmark", "rocking", "walls", "pulse", "overturning_map",
           "record_suite"]

#: Ordinates of :func:`spectra`: the field of the spectrum and its label without the unit
#: (PSA in m/s^2; in g, as a record's spectrum gives it, the label adds ``/ g``).
QUANTITIES = {"sa": "SA, max |absolute acceleration|", "psa": "PSA = (2 pi/T)^2 SD",
              "sv": "SV, max |relative velocity|", "psv": "PSV = (2 pi/T) SD",
              "sd": "SD, max |relative displacement|"}
#: Damping ratios of :func:`spectra` when it computes the spectra.
DEFAULT_DAMPINGS = (0.02, 0.05, 0.10)
#: Periods (s) of :func:`spectra` when it computes the spectra.
DEFAULT_PERIODS = np.geomspace(0.02, 10.0, 150)


def _plt(what):
    """matplotlib.pyplot, or ImportError naming matplotlib and how to install it (when
    matplotlib itself is missing)."""
    from .cylinder import _pyplot
    return _pyplot(f"seispulse.plot.{what}")


def _figure(what, ax, n, width=7.0, height=None):
    """(figure, list of n axes): the caller's ax (one axes for n = 1, else a sequence of
    n), or a new constrained-layout figure with n panels on one shared x axis."""
    if ax is not None:
        axes = [ax] if n == 1 and not isinstance(ax, (list, tuple, np.ndarray)) else list(
            np.ravel(np.asarray(ax, dtype=object)))
        if len(axes) != n:
            raise InvalidInputError(f"ax: needs {n} axes for this plot (got {len(axes)})")
        return axes[0].figure, axes
    plt = _plt(what)
    fig, axes = plt.subplots(n, 1, sharex=True, squeeze=False, layout="constrained",
                             figsize=(width, height if height else 1.0 + 2.1 * n))
    return fig, list(axes[:, 0])


def _legend(ax, loc="best"):
    """A legend inside ax (when ax holds labelled artists)."""
    handles, _ = ax.get_legend_handles_labels()
    if handles:
        ax.legend(loc=loc, fontsize="small", framealpha=0.85)


def _title(axes, title):
    if title:
        axes[0].set_title(title)


def _record_accel(name, record, dt, units="g", why=""):
    """(time s, acceleration g) of a Record, or of samples in `units` (the names
    :func:`seispulse.records.from_array` takes) at the time step dt (s); `why`: the
    reason dt is needed, for the message."""
    from . import records
    if not isinstance(record, records.Record):
        if dt is None:
            raise InvalidInputError(f"dt: the time step of {name} (s, > 0) is required{why}")
        acc = _core.as_float_array(name, record)
        if acc.ndim != 1:
            raise InvalidInputError(f"{name}: must be a 1-d array of samples "
                                    f"(got shape {acc.shape})")
        record = records.from_array(acc, dt, units)
    return record.time, np.asarray(record.accel, float)


# ------------------------------------------------------------------ spectra

def spectra(source, dt=None, periods=None, damping=None, quantity="psa", xscale="log",
            g=None, peaks=None, ax=None, title=None):
    """Response spectra for several dampings on one axes.

    Parameters
    ----------
    source : Record, array_like, seispulse.sdof.Spectrum or seispulse.sdof.PulseSpectrum
        A record (a :class:`seispulse.records.Record`, or samples in g with ``dt``): its
        spectra are computed here with :func:`seispulse.sdof.spectrum`; or spectra
        already computed (then leave periods, damping, g and peaks out).
    dt : float, optional
        Time step (s) of an array of samples.
    periods : array_like, optional
        Periods (s) of the computed spectra, any order (default 150 from 0.02 to 10 s,
        geometric). On a log axis a period of 0 is not drawn.
    damping : float or sequence of float, optional
        Damping ratio(s) of the computed spectra (default 0.02, 0.05, 0.10).
    quantity : {'psa', 'sa', 'psv', 'sv', 'sd'}
        The ordinate: (pseudo-)acceleration in g (m/s^2 for a PulseSpectrum),
        (pseudo-)velocity in m/s, displacement in m (the units the spectrum's table
        gives).
    xscale : {'log', 'linear'}
        The period axis.
    g, peaks
        As :func:`seispulse.sdof.spectrum` (g in m/s^2; default: its defaults); only
        for a record.
    ax : matplotlib Axes, optional
        Draw there instead of on a new figure.
    title : str, optional
        Default: the record's name.

    Returns
    -------
    matplotlib.figure.Figure
        One line per damping ratio, labelled ``zeta = 5 %``, in the order given.
    """
    from . import sdof
    quantity = _core.check_choice("quantity", quantity, tuple(QUANTITIES))
    xscale = _core.check_choice("xscale", xscale, ("log", "linear"))
    computed = isinstance(source, (sdof.Spectrum, sdof.PulseSpectrum))
    if not computed and hasattr(source, "_fields"):
        raise InvalidInputError("source: must be a Record, samples in g, a sdof.Spectrum or a "
                                f"sdof.PulseSpectrum (got {type(source).__name__})")
    if computed:
        if any(v is not None for v in (periods, damping, dt, g, peaks)):
            raise InvalidInputError("periods, damping, dt, g, peaks: only for a record (the "
                                    "spectrum given was computed with its own)")
        spec = source
    else:
        if title is None and hasattr(source, "name"):
            title = source.name
        options = {k: v for k, v in (("g", g), ("peaks", peaks)) if v is not None}
        spec = sdof.spectrum(source, dt, DEFAULT_PERIODS if periods is None else periods,
                             DEFAULT_DAMPINGS if damping is None else damping, **options)
    fig, (axis,) = _figure("spectra", ax, 1, height=4.2)
    per = np.atleast_1d(np.asarray(spec.periods, float))
    values = np.asarray(getattr(spec, quantity), float)
    unit = {field: u for field, _, u in type(spec)._COLUMNS}[quantity]   # the table's
    ylabel = QUANTITIES[quantity] + (" / g" if quantity == "psa" and unit == "g" else "")
    if isinstance(spec, sdof.PulseSpectrum):
        curves, labels = values.reshape(1, -1), [None]
    else:
        dampings = np.atleast_1d(spec.damping)
        curves = values.reshape(dampings.size, per.size)
        labels = [f"zeta = {100 * z:g} %" for z in dampings]
    keep = per > 0 if xscale == "log" else np.ones(per.size, bool)
    order = np.argsort(per[keep], kind="stable")
    for curve, label in zip(curves, labels):
        axis.plot(per[keep][order], curve[keep][order], label=label)
    axis.set_xscale(xscale)
    axis.set_xlabel("period T (s)")
    axis.set_ylabel(f"{ylabel} ({unit})")
    axis.grid(True, which="both", linewidth=0.3)
    _legend(axis)
    _title([axis], title)
    return fig


# ------------------------------------------------------------------ Newmark sliding

def _accel_panel(axis, t_rec, acc, t, hea, ky, ky_up):
    """The acceleration panel of a Newmark run (g): the record, the HEA of a flexible
    mass, the yield +ky (one line per value) and -ky_up."""
    if acc is not None:
        axis.plot(t_rec, acc, color="0.6", linewidth=0.8, label="ground a (g)")
    if hea is not None:
        axis.plot(t, hea, color="C0", linewidth=1.0, label="HEA (g)")
    for k, value in enumerate(np.atleast_1d(ky) if ky is not None else ()):
        axis.axhline(value, color="C3", linestyle="--", linewidth=0.9,
                     label="ky" if k == 0 else None)
    if ky_up is not None and np.isfinite(ky_up):
        axis.axhline(-ky_up, color="C3", linestyle=":", linewidth=0.9, label="-ky_up")
    axis.set_ylabel("acceleration (g)")


def _newmark_parts(result, record, dt):
    """Checked (t, record time, record accel) of a Newmark result with a history."""
    from . import newmark as nm
    if not isinstance(result, (nm.Rigid, nm.Flexible)):
        raise InvalidInputError("result: must be the result of newmark.rigid, decoupled or "
                                "coupled")
    if result.time is None:
        raise InvalidInputError("result: has no history (run it with history=True)")
    t = np.asarray(result.time, float)
    t_rec = acc = None
    if record is not None:
        if dt is None and t.size > 1:
            dt = t[1] - t[0]   # the result's step
        t_rec, acc = _record_accel("record", record, dt,
                                   why=" (the result's history has one sample, so its step "
                                   "cannot be taken)")
        if acc.shape != t.shape:
            raise InvalidInputError(f"record: must have the {t.size} samples of the result")
    return t, t_rec, acc


def newmark(result, record=None, ky=None, ky_up=None, dt=None, ax=None, title=None):
    """A Newmark sliding run: the record with the yield lines, the relative velocity and
    the sliding displacement on one time axis.

    Parameters
    ----------
    result : seispulse.newmark.Rigid or seispulse.newmark.Flexible
        Made with ``history=True``.
    record : Record or array_like, optional
        The record of the run (a Record, or samples in g; the result's time step is
        taken), drawn in g. Without it and without a HEA (rigid runs) the acceleration
        panel is left out.
    ky, ky_up : float, optional
        Yield accelerations (g) drawn at +ky and -ky_up; by default those the result
        keeps (a flexible result keeps both; give ky_up = ky to draw -ky of a two-way
        rigid run).
    dt : float, optional
        Time step (s) of an array ``record``; default the result's.
    ax : sequence of matplotlib Axes, optional
        Three axes (two without the acceleration panel) to draw into.
    title : str, optional
        Title of the top panel (default: the record's name).

    Returns
    -------
    matplotlib.figure.Figure
        Panels, top to bottom: acceleration (g), relative velocity u' (m/s),
        sliding displacement u (m) against t (s from the first sample); positive
        downslope. When the block still slides at the last sample (the exact rule goes
        on until it stops), the history ends there: the end of the run-out, the
        result's final_disp at t_end (and u' = 0 there), is marked with a point and
        joined to the last sample by a dotted straight line (not the path).
    """
    t, t_rec, acc = _newmark_parts(result, record, dt)
    hea = getattr(result, "hea", None)   # a flexible mass's
    ky = getattr(result, "ky", None) if ky is None else ky
    ky_up = getattr(result, "ky_up", None) if ky_up is None else ky_up
    show_acc = acc is not None or hea is not None
    fig, axes = _figure("newmark", ax, 3 if show_acc else 2)
    if show_acc:
        _accel_panel(axes[0], t_rec, acc, t, hea, ky, ky_up)
        _legend(axes[0])
    ax_v, ax_u = axes[-2:]
    ax_v.plot(t, result.vel, color="C2", label="relative velocity u'")
    ax_v.axhline(0.0, color="0.8", linewidth=0.8)
    ax_v.set_ylabel("relative velocity (m/s)")
    ax_u.plot(t, result.disp, color="C1", label="sliding displacement u")
    _run_out(ax_v, ax_u, t, result)
    ax_u.set_ylabel("sliding displacement (m)")
    ax_u.set_xlabel("time t (s)")
    if title is None and hasattr(record, "name"):
        title = record.name
    _title(axes, title)
    return fig


def _run_out(ax_v, ax_u, t, result, legend=True):
    """Mark the end of a slide that goes on after the last sample: (t_end, final_disp) on
    the u panel, (t_end, 0) on the u' panel (ax_v; None: none), each joined to the last
    sample by a dotted straight line (not the path); the u panel's label says so."""
    disp, vel = np.asarray(result.disp, float), np.asarray(result.vel, float)
    if t.size == 0 or (result.t_end <= t[-1] and result.final_disp == disp[-1]):
        return
    t_end = max(float(result.t_end), float(t[-1]))
    ax_u.plot([t[-1], t_end], [disp[-1], result.final_disp], color="C1", linestyle=":",
              linewidth=1.0)
    ax_u.plot([t_end], [result.final_disp], "o", color="C1", markersize=4,
              label=f"run-out after the record: final u = {result.final_disp:.4g} m "
                    f"at t = {t_end:.4g} s")
    if ax_v is not None:
        ax_v.plot([t[-1], t_end], [vel[-1], 0.0], color="C2", linestyle=":", linewidth=1.0)
        ax_v.plot([t_end], [0.0], "o", color="C2", markersize=4)
    if legend:
        _legend(ax_u, "upper left")


def _flexible_pair(result, record=None, ax=None):
    """The two-panel drawing of :func:`seispulse.newmark.plot_flexible` (its layout and
    return value: the acceleration axes and the displacement axes)."""
    from . import newmark as nm
    if not isinstance(result, nm.Flexible):
        raise InvalidInputError("result: must be the result of newmark.decoupled or coupled")
    t, t_rec, acc = _newmark_parts(result, record, None)
    plt = _plt("newmark")
    if ax is None:
        _, (ax_a, ax_s) = plt.subplots(2, 1, sharex=True, layout="constrained")
    elif isinstance(ax, (tuple, list, np.ndarray)):
        if len(ax) != 2:
            raise InvalidInputError("ax: one axes or a pair of them")
        ax_a, ax_s = ax
    else:
        ax_a = ax
        ax_s = ax.twinx()
    _accel_panel(ax_a, t_rec, acc, t, result.hea, result.ky, result.ky_up)
    ax_a.legend(loc="upper right", fontsize="small")
    ax_s.plot(t, result.disp, color="C1", label="sliding s (m)")
    _run_out(None, ax_s, t, result, legend=False)
    ax_s.set_ylabel("sliding displacement s (m)")
    ax_s.set_xlabel("t (s)")
    ax_s.legend(loc="lower right" if ax_s is not ax_a else "upper left", fontsize="small")
    return ax_a, ax_s


# ------------------------------------------------------------------ pulses

def _param(params, name):
    return float(params[getattr(_f, "PULSE_PARAM_" + name) - 1])


def _pulse_end(p):
    """The time (s) at which a pulse of define() is over: the library's pulse_end_time;
    for the Ricker wavelet (never exactly zero) t0 + 1.5/f, where its tail is below
    1e-7 of the peak."""
    t_end, stat, msg = sp_pulse_end_time(p.code, np.asarray(p.params, float))
    _core.raise_for_status(stat, msg)
    if p.code == _f.PULSE_RICKER:
        return _param(p.params, "T0") + 1.5 / _param(p.params, "FREQ")
    return float(t_end)


def _pulse_history(p, t):
    """(a m/s^2, v m/s, d m) of a pulse of define() at the times t (s)."""
    packed = np.asfortranarray(np.asarray(p.params, float).reshape(1, -1))
    a, v, d, stat, msg = sp_pulse_eval(p.code, np.ascontiguousarray(t, dtype=float), packed)
    _core.raise_for_status(stat, msg)
    return a, v, d


def _pulse_times(p, t):
    if t is not None:
        arr = _core.as_float_array("t", t)
        if arr.ndim != 1 or arr.size < 2:
            raise InvalidInputError("t: must be a 1-d array of at least two times (s)")
        return arr
    end = _pulse_end(p)
    n = int(min(max(2001, 50 * _param(p.params, "CYCLES")), 200001))
    return np.linspace(0.0, 1.25 * end, n)


def pulse(p, t=None, dimensionless=False, g=STANDARD_GRAVITY, ax=None, title=None):
    """Acceleration, velocity and displacement of a pulse on one time axis.

    Parameters
    ----------
    p : seispulse.pulse.Pulse or seispulse.pulse.PulseHistory
        A pulse of :func:`seispulse.pulse.define` (evaluated here at t), or the (a, v, d)
        of a pulse function evaluated at t.
    t : array_like, optional
        Times (s; t/t_d for a dimensionless history). Required with a PulseHistory;
        for a Pulse the default runs from 0 to 1.25 times the end of the pulse.
    dimensionless : bool
        The history is :func:`seispulse.pulse.exp_pulse`'s (a/A_g, v/(A_g t_d),
        d/(A_g t_d^2) against t/t_d): label the axes so.
    g : float
        Gravity (m/s^2) of the acceleration's second axis in g (a Pulse keeps its
        acceleration in m/s^2, not the g of an ``amp_unit='g'`` definition: give that g
        here).
    ax : sequence of three matplotlib Axes, optional
    title : str, optional
        Default: the pulse's kind.

    Returns
    -------
    matplotlib.figure.Figure
        Panels a (m/s^2, with a second axis in g), v (m/s), d (m) against t (s).
    """
    from . import pulse as pl
    dimensionless = _core.check_bool("dimensionless", dimensionless)
    g = _core.check_positive("g", g, " (m/s^2)")
    if isinstance(p, pl.Pulse):
        tt = _pulse_times(p, t)
        a, v, d = _pulse_history(p, tt)
        if title is None:
            title = p.kind
    elif isinstance(p, pl.PulseHistory):
        if t is None:
            raise InvalidInputError("t: the times of the PulseHistory are required")
        tt = _core.as_float_array("t", t).reshape(-1)
        if any(np.size(x) != tt.size for x in p):
            raise InvalidInputError(f"t: {tt.size} times, but the PulseHistory has "
                                    f"{np.size(p.a)} values")
        a, v, d = (np.asarray(x, float).reshape(-1) for x in p)
    else:
        raise InvalidInputError("p: must be a seispulse.pulse.Pulse (define) or a PulseHistory")
    fig, axes = _figure("pulse", ax, 3)
    if dimensionless:
        labels = ("a / A_g (-)", "v / (A_g t_d) (-)", "d / (A_g t_d^2) (-)")
        xlabel = "tau = t / t_d (-)"
    else:
        labels = ("acceleration a (m/s^2)", "velocity v (m/s)", "displacement d (m)")
        xlabel = "time t (s)"
    for axis, y, label, colour in zip(axes, (a, v, d), labels, ("C0", "C2", "C1")):
        axis.plot(tt, y, color=colour)
        axis.axhline(0.0, color="0.8", linewidth=0.8)
        axis.set_ylabel(label)
    if not dimensionless:
        second = axes[0].secondary_yaxis("right", functions=(lambda x: x / g, lambda x: x * g))
        second.set_ylabel("a (g)")
    axes[-1].set_xlabel(xlabel)
    _title(axes, title)
    return fig


# ------------------------------------------------------------------ rocking

def rocking(run, block=None, excitation=None, dt=None, units="m/s2", ax=None, title=None):
    """A rocking run: the excitation, theta and the angular velocity on one time axis.

    Parameters
    ----------
    run : seispulse.rocking.RockingRun
        From :func:`seispulse.rocking.simulate` with a time grid ``t``.
    block : seispulse.rocking.Block, optional
        The block: adds theta/alpha on a second axis and the uplift thresholds
        +-tan(alpha) to the excitation, and takes its g for the excitation in g.
    excitation : Pulse, Record or array_like, optional
        What drove the run: a pulse of :func:`seispulse.pulse.define` (evaluated at the
        run's times), a Record (g), or samples in ``units`` at ``dt``. Without it the
        excitation panel is left out.
    dt : float, optional
        Time step (s) of an array excitation.
    units : str
        Units of an array excitation, as :func:`seispulse.records.from_array` names them
        (default m/s^2, as :func:`seispulse.rocking.simulate` takes it; 'g', 'cm/s2' ...).
    ax : sequence of matplotlib Axes, optional
        Three axes (two without an excitation).
    title : str, optional
        Default: the outcome.

    Returns
    -------
    matplotlib.figure.Figure
        Panels: ground acceleration a_g (g of the block: a pulse or samples in SI units
        over the block's g, a Record or samples in standard g converted to it; samples in
        g as they are), theta (rad; theta/alpha on the right), angular velocity theta'
        (rad/s) against t (s); impacts marked on theta; for a block that overturned, a
        dotted line at its t_end (after it simulate reports theta = +-pi/2 and
        theta' = 0: the state at rest on its side, not a motion).
    """
    from . import pulse as pl
    from . import records
    from . import rocking as rk
    if not isinstance(run, rk.RockingRun):
        raise InvalidInputError("run: must be the result of seispulse.rocking.simulate")
    if run.t is None:
        raise InvalidInputError("run: has no history (run simulate with a time grid t)")
    if block is not None and not isinstance(block, rk.Block):
        raise InvalidInputError("block: must be a seispulse.rocking.Block")
    g = block.g if block is not None else STANDARD_GRAVITY
    t = np.asarray(run.t, float)
    exc = None
    if excitation is not None:
        if isinstance(excitation, pl.Pulse):
            exc = (t, _pulse_history(excitation, t)[0] / g)
        else:
            t_exc, acc = _record_accel("excitation", excitation, dt, units)
            if isinstance(excitation, records.Record) or \
                    records._unit_code(units) != _f.UNITS_G:
                acc = acc * (STANDARD_GRAVITY / g)   # in standard g: in units of the run's g
            exc = (t_exc, acc)
    fig, axes = _figure("rocking", ax, 3 if exc is not None else 2)
    if exc is not None:
        axes[0].plot(*exc, color="0.4", linewidth=0.9, label="ground a_g")
        if block is not None:
            for s in (1, -1):
                axes[0].axhline(s * np.tan(block.alpha), color="C3", linestyle="--",
                                linewidth=0.9, label="uplift +-tan(alpha)" if s > 0 else None)
        axes[0].set_ylabel("ground acceleration a_g (g)")
        _legend(axes[0], "upper right")
    ax_th, ax_om = axes[-2:]
    ax_th.plot(t, run.theta, color="C0", label="theta")
    ax_th.axhline(0.0, color="0.8", linewidth=0.8)
    if run.n_impacts:
        ax_th.plot(run.t_impacts, np.zeros(len(run.t_impacts)), "k|", markersize=10,
                   label="impacts")
    ax_th.set_ylabel("rotation theta (rad)")
    if block is not None:
        alpha = block.alpha
        second = ax_th.secondary_yaxis("right", functions=(lambda x: x / alpha,
                                                           lambda x: x * alpha))
        second.set_ylabel("theta / alpha (-)")
    if run.outcome.startswith("overturn"):
        for axis in axes:
            axis.axvline(run.t_end, color="C3", linestyle=":", linewidth=0.9,
                         label="overturned" if axis is ax_th else None)
    _legend(ax_th, "upper right")
    ax_om.plot(t, run.omega, color="C2")
    ax_om.axhline(0.0, color="0.8", linewidth=0.8)
    ax_om.set_ylabel("angular velocity theta' (rad/s)")
    ax_om.set_xlabel("time t (s)")
    _title(axes, title if title is not None else f"outcome: {run.outcome}")
    return fig


def overturning_map(classes, freq_ratio, amp_ratio, ax=None, title=None, legend=None):
    """A map of :func:`seispulse.rocking.overturning_map`: one colour per class over
    (omega_p/p, a_p/(g tan alpha)), both dimensionless.

    ``legend``: 'below' (under the axes, outside the cells; the default on a figure made
    here, whose constrained layout keeps it in a plain ``savefig``) or 'inside' (the
    upper right corner of the axes; the default with ``ax=``, where the caller's layout
    might not make room below). Returns the Figure."""
    from . import rocking as rk
    fig, (axis,) = _figure("overturning_map", ax, 1, height=5.0)
    from matplotlib.patches import Patch
    legend = _core.check_choice("legend", "inside" if legend is None and ax is not None
                                else legend or "below", ("below", "inside"))
    rk._draw_classes(axis, classes, freq_ratio, amp_ratio)
    handles = [Patch(facecolor=c, edgecolor="0.4", label=name)
               for c, name in zip(rk._MAP_COLOURS, rk.MAP_CLASSES)]
    if legend == "below":
        axis.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2,
                    fontsize="small", frameon=False)
    else:
        axis.legend(handles=handles, loc="upper right", fontsize="small", framealpha=0.9)
    axis.set_xlabel("omega_p / p (-)")
    axis.set_ylabel("a_p / (g tan alpha) (-)")
    if title:
        axis.set_title(title)
    return fig


# ------------------------------------------------------------------ walls

#: Labels of the columns of :class:`seispulse.walls.PressureProfile` in :func:`walls`.
_PROFILE_LABELS = (("static", "static, Coulomb K gamma z"),
                   ("mo_dynamic", "M-O increment (uniform)"),
                   ("ec8_rigid", "EN 1998-5 rigid wall increment"),
                   ("vy", "Veletsos-Younan |p| increment"),
                   ("one_term", "one-term |p| increment"))


def walls(profile, comparison=None, ax=None, title=None):
    """Pressure profiles on a wall beside the thrusts of every rule.

    Parameters
    ----------
    profile : seispulse.walls.PressureProfile
        From :func:`seispulse.walls.pressure_profile`: pressures (kPa) against the depth
        below the top (m).
    comparison : seispulse.walls.Comparison, optional
        From :func:`seispulse.walls.comparison` for the same wall: a second panel with
        the thrust of each rule (kN/m; totals for the static and M-O total rows,
        dynamic increments for the others), each bar marked with its point of
        application z (m above the base).
    ax : matplotlib Axes, or a pair with a comparison, optional
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    from . import walls as wl
    if not isinstance(profile, wl.PressureProfile):
        raise InvalidInputError("profile: must be the result of seispulse.walls.pressure_profile")
    if comparison is not None and not isinstance(comparison, wl.Comparison):
        raise InvalidInputError("comparison: must be the result of seispulse.walls.comparison")
    n = 1 if comparison is None else 2
    if ax is None:
        plt = _plt("walls")
        fig, axes = plt.subplots(1, n, squeeze=False, layout="constrained",
                                 figsize=(5.0 if n == 1 else 11.0, 5.0),
                                 width_ratios=None if n == 1 else (1.0, 1.3))
        axes = list(axes[0])
    else:
        fig, axes = _figure("walls", ax, n)
    ax_p = axes[0]
    depth = np.asarray(profile.depth, float)
    for field, label in _PROFILE_LABELS:
        ax_p.plot(getattr(profile, field), depth, label=label)
    ax_p.set_ylim(float(depth.max()), float(depth.min()))   # depth grows downward
    ax_p.set_xlim(left=0.0)
    ax_p.set_xlabel("pressure on the wall (kPa)")
    ax_p.set_ylabel("depth below the top (m)")
    ax_p.grid(True, linewidth=0.3)
    _legend(ax_p, "lower left")
    if comparison is not None:
        from matplotlib.patches import Patch
        ax_q = axes[1]
        thrust = np.asarray(comparison.thrust, float)
        rows = np.arange(thrust.size)
        colours = ("0.55", "C0")   # totals (static, M-O total), dynamic increments
        ax_q.barh(rows, thrust, color=[colours[0] if m in wl.TOTAL_ROWS else colours[1]
                                       for m in comparison.method])
        for k, (q, z) in enumerate(zip(thrust, comparison.z)):
            ax_q.annotate(f" z = {z:.2f} m", (max(q, 0.0), k), va="center", fontsize="small")
        ax_q.set_yticks(rows, list(comparison.method), fontsize="small")
        ax_q.invert_yaxis()
        ax_q.set_xlim(1.3 * min(float(np.nanmin(thrust)), 0.0),
                      1.4 * max(float(np.nanmax(thrust)), 1e-300))
        ax_q.set_xlabel("thrust (kN/m), applied at z (m) above the base")
        ax_q.legend(handles=[Patch(facecolor=colours[0], label="total thrust"),
                             Patch(facecolor=colours[1], label="dynamic increment")],
                    loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=2, fontsize="small",
                    frameon=False)   # above the bars, inside the figure
    if title and ax is None:
        fig.suptitle(title)
    else:
        _title(axes, title)
    return fig


# ------------------------------------------------------------------ record suites

def record_suite(check, ax=None, title=None, scaled=None):
    """A record-suite check (EN 1998-1 3.2.3.1.2(4)) on one axes.

    Parameters
    ----------
    check : seispulse.codes.SuiteCheck
        From :func:`seispulse.codes.check_record_suite`.
    ax : matplotlib Axes, optional
        Draw there instead of on a new figure.
    title : str, optional
        Default: the verdict, e.g. ``EN 1998-1 3.2.3.1.2(4): passed (3 records)``.
    scaled : {None, 'common', 'own'}
        Also draw the mean of the suite scaled by ``common_scale`` ('common') or of the
        records each scaled by its ``own_scale`` ('own').

    Returns
    -------
    matplotlib.figure.Figure
        On the checked periods, the period axis (log, s) set to [0.2 T1, 2 T1]: each
        record's 5 % PSA (thin grey lines), their mean (bold), the target and 0.9 x target
        (g); T1 and the period of the least mean/target marked (its value to 4 decimals and
        the verdict of rule (c)); rule (b) as a line of text (mean PGA against the target
        at T = 0).
    """
    from .codes import SUITE_SPECTRUM_FRACTION, SuiteCheck
    if not isinstance(check, SuiteCheck):
        raise InvalidInputError("check: must be the result of "
                                "seispulse.codes.check_record_suite")
    if scaled not in (None, "common", "own"):
        raise InvalidInputError(f"scaled = {scaled!r}: must be None, 'common' or 'own'")
    import matplotlib.ticker as mticker
    fig, (axis,) = _figure("record_suite", ax, 1, height=4.6)
    per = np.asarray(check.periods, float)
    target = np.asarray(check.target, float)
    for k, row in enumerate(np.asarray(check.psa, float)):
        axis.plot(per, row, color="0.6", linewidth=0.7,
                  label="records, 5 % PSA" if k == 0 else None)
    axis.plot(per, np.asarray(check.mean, float), color="C0", linewidth=2.4,
              label=f"mean of {len(check.names)} records")
    axis.plot(per, target, color="k", linewidth=1.4, label="target (elastic spectrum)")
    frac = SUITE_SPECTRUM_FRACTION
    axis.plot(per, frac * target, color="k", linewidth=1.2, linestyle="--",
              label=f"{frac:g} x target")
    if scaled == "common":
        axis.plot(per, check.common_scale * np.asarray(check.mean, float), color="C2",
                  linewidth=1.6, label=f"mean x common_scale {check.common_scale:.4f}")
    elif scaled == "own":
        axis.plot(per, np.asarray(check.own_mean, float), color="C2", linewidth=1.6,
                  label="mean of records x own_scale")
    axis.axvspan(check.t_range[0], check.t_range[1], color="C1", alpha=0.08,
                 label="0.2 T1 .. 2 T1")
    axis.axvline(check.t1, color="C1", linewidth=1.0, label=f"T1 = {check.t1:g} s")
    axis.axvline(check.t_min_ratio, color="C3", linewidth=0.8, linestyle=":",
                 label=f"least mean/target = {check.min_ratio:.4f} "
                       f"({'pass' if check.spectrum_ok else 'fail'}, >= {frac:g})")
    at_zero = "gamma_I A" if str(check.target_label).startswith("EAK") else "a_g S"
    axis.text(0.99, 0.02, f"rule (b): mean PGA {check.pga_mean:.4g} g vs {at_zero} "
              f"{check.pga_target:.4g} g ({'pass' if check.pga_ok else 'fail'})",
              transform=axis.transAxes, ha="right", va="bottom", fontsize="small")
    axis.set_xscale("log")
    axis.set_xlim(check.t_range[0], check.t_range[1])   # the checked periods only
    axis.xaxis.set_major_formatter(mticker.ScalarFormatter())
    axis.xaxis.set_minor_formatter(mticker.NullFormatter())
    axis.set_xlabel("period T (s)")
    axis.set_ylabel("PSA, 5 % damping (g)")
    axis.set_ylim(bottom=0.0)
    axis.grid(True, which="both", linewidth=0.3)
    _legend(axis)
    if title is None:
        title = (f"EN 1998-1 3.2.3.1.2(4): {'passed' if check.passed else 'failed'} "
                 f"({len(check.names)} records)")
    _title([axis], title)
    return fig
