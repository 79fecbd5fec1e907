"""seispulse.plot: every helper renders a non-empty PNG with the Agg backend from a plain
savefig, labels its axes with units, keeps its legends (and every axes with its tick
labels) inside the figure, and draws exactly the numbers the API returns."""
import re
import struct
import subprocess
import sys

import numpy as np
import pytest

mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from seispulse import (InvalidInputError, newmark, plot, pulse, records,  # noqa: E402
                       rocking, sdof, walls)

G = 9.80665
PNG = b"\x89PNG\r\n\x1a\n"
# an axis label ends with its unit in parentheses; (-) for a dimensionless quantity
UNIT = re.compile(r"\((g|m|m/s|m/s\^2|s|rad|rad/s|kPa|-)\)")
RECORD_B = "input/records/quake_b.csv"
RECORD_A = "input/records/quake_a.AT2"


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.fixture
def rec(source_root):
    return records.read(source_root / RECORD_B)


def rendered(fig, path, units=True):
    """Save fig with a plain savefig and check the file, the labels and the layout."""
    fig.savefig(path)
    data = path.read_bytes()
    assert data[:8] == PNG and len(data) > 10_000
    width, height = struct.unpack(">II", data[16:24])   # IHDR
    assert (width, height) == (round(fig.bbox.width), round(fig.bbox.height))
    renderer = fig.canvas.get_renderer()
    box = fig.bbox
    inside = (lambda b: b.x0 >= box.x0 - 1 and b.y0 >= box.y0 - 1 and b.x1 <= box.x1 + 1
              and b.y1 <= box.y1 + 1)
    legends = [a.get_legend() for a in fig.axes if a.get_legend() is not None] + fig.legends
    for legend in legends:
        assert inside(legend.get_window_extent(renderer)), "legend cut off by savefig"
    for axis in fig.axes:
        assert inside(axis.get_tightbbox(renderer)), f"axes {axis.get_ylabel()!r} cut off"
        for label in (axis.get_xlabel(), axis.get_ylabel()):
            if units and label:
                assert UNIT.search(label), f"no unit in {label!r}"
    return legends


def lines_of(axis):
    """The data lines of an axes (not the horizontal and vertical guide lines)."""
    return [ln for ln in axis.get_lines() if np.size(ln.get_xdata()) > 2]


# ------------------------------------------------------------------ spectra

def test_spectra_of_a_record(rec, tmp_path):
    periods = [1.0, 0.0, 0.1, 3.0, 0.5]   # any order, with the ground itself
    fig = plot.spectra(rec, periods=periods, damping=[0.02, 0.05, 0.1])
    legends = rendered(fig, tmp_path / "spectra.png")
    (axis,) = fig.axes
    assert axis.get_xscale() == "log" and axis.get_xlabel() == "period T (s)"
    assert axis.get_ylabel().endswith("(g)") and axis.get_title() == "quake_b"
    assert [t.get_text() for t in legends[0].get_texts()] == [
        "zeta = 2 %", "zeta = 5 %", "zeta = 10 %"]
    ref = sdof.spectrum(rec, periods=periods, damping=[0.02, 0.05, 0.1])
    order = [2, 4, 0, 3]   # T > 0 ascending: the log axis leaves T = 0 out
    assert len(axis.get_lines()) == 3
    for k, line in enumerate(axis.get_lines()):
        np.testing.assert_array_equal(line.get_xdata(), np.array(periods)[order])
        np.testing.assert_array_equal(line.get_ydata(), ref.psa[k][order])
    # linear axis: T = 0 drawn (PSA = PGA there)
    fig = plot.spectra(rec, periods=periods, damping=0.05, quantity="sd", xscale="linear")
    (line,) = fig.axes[0].get_lines()
    np.testing.assert_array_equal(line.get_xdata(), [0.0, 0.1, 0.5, 1.0, 3.0])
    ref = sdof.spectrum(rec, periods=periods, damping=0.05)
    np.testing.assert_array_equal(line.get_ydata(), ref.sd[[1, 2, 4, 0, 3]])
    assert fig.axes[0].get_ylabel().endswith("(m)")


@pytest.mark.parametrize("quantity, unit", [("sa", "(g)"), ("psa", "(g)"), ("sv", "(m/s)"),
                                            ("psv", "(m/s)"), ("sd", "(m)")])
def test_spectra_given(rec, quantity, unit, tmp_path):
    spec = sdof.spectrum(rec, periods=np.geomspace(0.05, 5, 30), damping=[0.05, 0.2])
    fig = plot.spectra(spec, quantity=quantity)
    rendered(fig, tmp_path / "s.png")
    axis = fig.axes[0]
    assert axis.get_ylabel().endswith(unit)
    assert len(axis.get_lines()) == 2
    for k, line in enumerate(axis.get_lines()):
        np.testing.assert_array_equal(line.get_ydata(), getattr(spec, quantity)[k])


def test_spectra_of_a_pulse_and_into_an_axes(tmp_path):
    p = pulse.define("half_sine", amp=0.3, amp_unit="g", duration=0.5)
    spec = sdof.pulse_spectrum(p, np.geomspace(0.05, 4, 40), damping=0.05)
    fig, axis = plt.subplots(layout="constrained")
    assert plot.spectra(spec, ax=axis) is fig
    rendered(fig, tmp_path / "p.png")
    assert axis.get_ylabel().endswith("(m/s^2)")
    np.testing.assert_array_equal(axis.get_lines()[0].get_ydata(), spec.psa)


def test_spectra_default_grid(source_root, tmp_path):
    fig = plot.spectra(records.read(source_root / RECORD_A))
    rendered(fig, tmp_path / "d.png")
    assert len(fig.axes[0].get_lines()) == len(plot.DEFAULT_DAMPINGS)
    np.testing.assert_array_equal(fig.axes[0].get_lines()[0].get_xdata(), plot.DEFAULT_PERIODS)


# ------------------------------------------------------------------ Newmark

def test_newmark_rigid(rec, tmp_path):
    r = newmark.rigid(rec, ky=0.05, mode="both", history=True)
    fig = plot.newmark(r, rec, ky=0.05, ky_up=0.05)
    rendered(fig, tmp_path / "rigid.png")
    ax_a, ax_v, ax_u = fig.axes
    assert (ax_a.get_ylabel(), ax_v.get_ylabel(), ax_u.get_ylabel()) == (
        "acceleration (g)", "relative velocity (m/s)", "sliding displacement (m)")
    assert ax_u.get_xlabel() == "time t (s)"
    assert ax_a.get_shared_x_axes().joined(ax_a, ax_u)
    np.testing.assert_array_equal(lines_of(ax_a)[0].get_ydata(), rec.accel)
    np.testing.assert_array_equal(lines_of(ax_v)[0].get_ydata(), r.vel)
    np.testing.assert_array_equal(lines_of(ax_u)[0].get_ydata(), r.disp)
    np.testing.assert_array_equal(lines_of(ax_u)[0].get_xdata(), rec.time)
    guides = sorted(float(ln.get_ydata()[0]) for ln in ax_a.get_lines()
                    if np.size(ln.get_xdata()) == 2)
    assert guides == [-0.05, 0.05]
    # no record: the two motion panels only; an array record in g with the result's step
    assert len(plot.newmark(r).axes) == 2
    fig = plot.newmark(r, rec.accel)
    np.testing.assert_array_equal(lines_of(fig.axes[0])[0].get_xdata(), r.time)


def test_newmark_flexible(rec, tmp_path):
    f = newmark.decoupled(rec, ky=0.05, height=20.0, vs=300.0, vs_base=600.0, history=True)
    fig = plot.newmark(f, rec)
    rendered(fig, tmp_path / "flex.png")
    ax_a, ax_v, ax_u = fig.axes
    data = lines_of(ax_a)
    np.testing.assert_array_equal(data[1].get_ydata(), f.hea)
    np.testing.assert_array_equal(lines_of(ax_v)[0].get_ydata(), f.vel)
    np.testing.assert_array_equal(lines_of(ax_u)[0].get_ydata(), f.disp)
    # into the caller's axes
    fig2, axes = plt.subplots(3, 1, layout="constrained")
    assert plot.newmark(f, rec, ax=axes) is fig2


# ------------------------------------------------------------------ rocking

def test_rocking_under_a_pulse(tmp_path):
    blk = rocking.rectangular_block(0.2, 1.0)   # tan(alpha) = 0.2
    p = pulse.define("sine_cycle", amp=0.4, amp_unit="g", period=0.6)
    t = np.linspace(0.0, 4.0, 801)
    run = rocking.simulate(blk, p, t=t)
    assert run.outcome.startswith("overturn")
    fig = plot.rocking(run, blk, p)
    rendered(fig, tmp_path / "rock.png")
    ax_a, ax_th, ax_om = fig.axes[:3]
    a = pulse.sine_cycle(t, amp=0.4, amp_unit="g", period=0.6).a / G
    np.testing.assert_allclose(lines_of(ax_a)[0].get_ydata(), a, rtol=0, atol=1e-15)
    levels = sorted(float(ln.get_ydata()[0]) for ln in ax_a.get_lines()
                    if np.size(ln.get_ydata()) == 2 and ln.get_ydata()[0] == ln.get_ydata()[1])
    np.testing.assert_allclose(levels, [-0.2, 0.2], rtol=1e-15)
    np.testing.assert_array_equal(lines_of(ax_th)[0].get_ydata(), run.theta)
    np.testing.assert_array_equal(lines_of(ax_om)[0].get_ydata(), run.omega)
    assert ax_th.get_ylabel() == "rotation theta (rad)"
    assert ax_om.get_ylabel() == "angular velocity theta' (rad/s)"
    # theta/alpha on a second axis: its ticks are theta/alpha
    second = [c for c in ax_th.get_children() if type(c).__name__ == "SecondaryAxis"]
    assert second and second[0].get_ylabel() == "theta / alpha (-)"
    texts = [t.get_text() for t in ax_th.get_legend().get_texts()]
    assert "impacts" in texts and "overturned" in texts


def test_rocking_under_records(rec, tmp_path):
    blk = rocking.rectangular_block(0.1, 1.0)
    acc = rec.accel * G   # simulate takes m/s^2
    run = rocking.simulate(blk, accel=acc, dt=rec.dt, t=np.linspace(0, 5, 501))
    for excitation, kw in ((rec, {}), (acc, {"dt": rec.dt}),
                           (rec.accel, {"dt": rec.dt, "units": "g"})):
        fig = plot.rocking(run, blk, excitation, **kw)
        rendered(fig, tmp_path / "r.png")
        np.testing.assert_allclose(lines_of(fig.axes[0])[0].get_ydata(), rec.accel,
                                   rtol=1e-15)
        np.testing.assert_allclose(lines_of(fig.axes[0])[0].get_xdata(), rec.time, rtol=1e-15)
    # samples in m/s^2 are drawn over the run's g, as the uplift threshold tan(alpha)
    blk = rocking.rectangular_block(0.1, 1.0, g=9.81)
    run = rocking.simulate(blk, accel=acc, dt=rec.dt, t=np.linspace(0, 5, 501))
    fig = plot.rocking(run, blk, acc, dt=rec.dt)
    np.testing.assert_allclose(lines_of(fig.axes[0])[0].get_ydata(), acc / 9.81, rtol=1e-15)
    fig = plot.rocking(run)   # no block, no excitation: theta and theta'
    rendered(fig, tmp_path / "r2.png")
    assert len(fig.axes) == 2


# ------------------------------------------------------------------ pulses

def test_pulse_defined(tmp_path):
    p = pulse.define("half_sine", amp=0.3, amp_unit="g", duration=0.8)
    fig = plot.pulse(p)
    rendered(fig, tmp_path / "pulse.png")
    ax_a, ax_v, ax_d = fig.axes[:3]
    t = lines_of(ax_a)[0].get_xdata()
    assert t[0] == 0.0 and t[-1] == pytest.approx(1.0)   # 1.25 times the pulse
    ref = pulse.half_sine(t, amp=0.3 * G, duration=0.8)
    for axis, y in zip((ax_a, ax_v, ax_d), ref):
        np.testing.assert_allclose(lines_of(axis)[0].get_ydata(), y, rtol=1e-15, atol=1e-15)
    assert [ax.get_ylabel() for ax in (ax_a, ax_v, ax_d)] == [
        "acceleration a (m/s^2)", "velocity v (m/s)", "displacement d (m)"]
    second = [c for c in ax_a.get_children() if type(c).__name__ == "SecondaryAxis"]
    assert second[0].get_ylabel() == "a (g)"
    # the default grid covers every cycle, and the Ricker wavelet's whole length
    p = pulse.define("sine_cycle", amp=1.0, period=0.5, cycles=4)
    t = lines_of(plot.pulse(p).axes[0])[0].get_xdata()
    assert t[-1] == pytest.approx(1.25 * 2.0)
    p = pulse.define("ricker", amp=1.0, freq=2.0)
    t = lines_of(plot.pulse(p).axes[0])[0].get_xdata()
    assert t[-1] == pytest.approx(1.25 * 1.5)


def test_pulse_history(tmp_path):
    tau = np.linspace(0, 2.5, 251)
    h = pulse.exp_pulse(tau, beta=-np.pi, full=True)
    fig = plot.pulse(h, tau, dimensionless=True)
    rendered(fig, tmp_path / "exp.png")
    assert fig.axes[2].get_xlabel() == "tau = t / t_d (-)"
    for axis, y in zip(fig.axes, h):
        np.testing.assert_array_equal(lines_of(axis)[0].get_ydata(), y)
    t = np.linspace(0, 2, 101)
    fig = plot.pulse(pulse.ricker(t, amp=3.0, freq=1.2), t, title="Ricker")
    assert fig.axes[0].get_title() == "Ricker"


def test_newmark_run_out_after_the_record(tmp_path):
    """A record that ends mid-slide: the exact rule slides on until the block stops; the
    plot marks final_disp at t_end, both from the closed form of this record."""
    acc = np.r_[np.zeros(5), np.full(50, 0.5)]   # g; a ramp 0 -> 0.5 g over 0.04..0.05 s
    dt, ky = 0.01, 0.1
    r = newmark.rigid(acc, dt=dt, ky=ky, history=True)
    # onset where the ramp reaches ky: t0 = 0.04 + 0.01 ky/0.5; on the ramp u'' = 50 g (t - t0)
    t0 = 0.04 + dt * ky / 0.5
    v5, u5 = 25.0 * G * (0.05 - t0) ** 2, 50.0 * G / 6.0 * (0.05 - t0) ** 3
    tau = 0.54 - 0.05                             # then u'' = (0.5 - ky) g to the last sample
    v_n = v5 + (0.5 - ky) * G * tau
    u_n = u5 + v5 * tau + 0.5 * (0.5 - ky) * G * tau ** 2
    t_end, final = 0.54 + v_n / (ky * G), u_n + v_n ** 2 / (2.0 * ky * G)   # u'' = -ky g
    assert (r.t_end, r.final_disp) == (pytest.approx(t_end, rel=1e-12),
                                       pytest.approx(final, rel=1e-12))
    assert r.disp[-1] < 0.25 * final       # the history alone shows a fifth of it
    fig = plot.newmark(r, acc)
    rendered(fig, tmp_path / "run_out.png")
    ax_a, ax_v, ax_u = fig.axes
    drawn = np.concatenate([ln.get_ydata() for ln in ax_u.get_lines()])
    assert drawn.max() == pytest.approx(final, rel=1e-12)
    end = [ln for ln in ax_u.get_lines() if np.size(ln.get_xdata()) == 1]
    assert len(end) == 1
    assert (end[0].get_xdata()[0], end[0].get_ydata()[0]) == (r.t_end, r.final_disp)
    assert ax_u.get_xlim()[1] >= t_end
    (text,) = [t.get_text() for t in ax_u.get_legend().get_texts()
               if t.get_text().startswith("run-out")]
    assert f"{final:.4g} m" in text and f"{t_end:.4g} s" in text
    stop = [ln for ln in ax_v.get_lines() if np.size(ln.get_xdata()) == 1]
    assert len(stop) == 1 and stop[0].get_ydata()[0] == 0.0
    # a record that ends at rest has no run-out mark
    quiet = newmark.rigid(np.r_[acc, np.zeros(400)], dt=dt, ky=ky, history=True)
    assert quiet.t_end < quiet.time[-1]
    fig = plot.newmark(quiet)
    assert not [ln for ln in fig.axes[-1].get_lines() if np.size(ln.get_xdata()) == 1]


def test_newmark_two_way_draws_both_yields(rec):
    r = newmark.rigid(rec, ky=0.05, mode="both", history=True)
    assert r.ky_up == 0.05
    fig = plot.newmark(r, rec)
    levels = sorted(float(ln.get_ydata()[0]) for ln in fig.axes[0].get_lines()
                    if np.size(ln.get_ydata()) == 2 and ln.get_ydata()[0] == ln.get_ydata()[1])
    assert levels == [-0.05, 0.05]
    one_way = plot.newmark(newmark.rigid(rec, ky=0.05, history=True), rec)
    levels = [float(ln.get_ydata()[0]) for ln in one_way.axes[0].get_lines()
              if np.size(ln.get_ydata()) == 2 and ln.get_ydata()[0] == ln.get_ydata()[1]]
    assert levels == [0.05]


def test_psa_label_matches_its_unit(rec):
    """(2 pi/T)^2 SD is in m/s^2: in g the label divides by g."""
    spec = sdof.spectrum(rec, periods=[0.1, 1.0], damping=0.05)
    ylabel = plot.spectra(spec).axes[0].get_ylabel()
    assert ylabel == "PSA = (2 pi/T)^2 SD / g (g)"
    np.testing.assert_allclose(spec.psa, (2 * np.pi / spec.periods) ** 2 * spec.sd / G,
                               rtol=1e-12)
    p = pulse.define("half_sine", amp=0.3, amp_unit="g", duration=0.5)
    ps = sdof.pulse_spectrum(p, [0.1, 1.0], damping=0.05)
    assert plot.spectra(ps).axes[0].get_ylabel() == "PSA = (2 pi/T)^2 SD (m/s^2)"
    assert plot.spectra(spec, quantity="psv").axes[0].get_ylabel() == \
        "PSV = (2 pi/T) SD (m/s)"


def test_spectra_refuses_options_of_a_record_for_a_spectrum(rec):
    spec = sdof.spectrum(rec, periods=[0.1, 1.0], damping=0.05)
    for kw in ({"g": 9.81}, {"peaks": "samples"}):
        with pytest.raises(InvalidInputError, match="^periods, damping, dt, g, peaks: only"):
            plot.spectra(spec, **kw)
    # for a record they reach sdof.spectrum
    fig = plot.spectra(rec, periods=[0.5], damping=0.05, peaks="samples", quantity="sa")
    ref = sdof.spectrum(rec, periods=[0.5], damping=0.05, peaks="samples")
    np.testing.assert_array_equal(fig.axes[0].get_lines()[0].get_ydata(), ref.sa[0])


def test_rocking_units_non_ascii_and_record_in_the_blocks_g(rec):
    blk = rocking.rectangular_block(0.1, 1.0, g=9.81)
    run = rocking.simulate(blk, accel=rec.accel * G, dt=rec.dt, t=np.linspace(0, 2, 201))
    with pytest.raises(InvalidInputError, match=r"^units = 'm/s\u00b2': .*\(allowed: g, "):
        plot.rocking(run, blk, rec.accel * G, dt=rec.dt, units="m/s\u00b2")
    fig = plot.rocking(run, blk, rec)   # standard g, drawn in the block's g
    np.testing.assert_allclose(lines_of(fig.axes[0])[0].get_ydata(), rec.accel * G / 9.81,
                               rtol=1e-15)


@pytest.mark.parametrize("kind, params, end", [
    ("half_sine", dict(duration=0.5), 0.5),
    ("sine_cycle", dict(period=0.4, cycles=3), 1.2),
    ("exponential", dict(td=0.3, beta=2.0, full=True), 0.6),
    ("ricker", dict(freq=2.0, t0=1.0), 1.0 + 1.5 / 2.0),
])
def test_pulse_default_times_end_at_the_pulse_end(kind, params, end):
    """The default grid runs to 1.25 times the library's pulse end (the Ricker wavelet:
    t0 + 1.5/f)."""
    p = pulse.define(kind, amp=1.0, **params)
    line = plot.pulse(p).axes[0].get_lines()[0]
    assert line.get_xdata()[-1] == pytest.approx(1.25 * end, rel=1e-14)


# ------------------------------------------------------------------ walls

WALL = dict(height=6.0, gamma=20.0, phi_deg=32.0, kh=0.2, kv=0.1, alpha_s=0.24)


def test_walls(tmp_path):
    prof = walls.pressure_profile(np.linspace(0, 6, 61), **WALL)
    cmp = walls.comparison(**WALL)
    fig = plot.walls(prof, cmp, title="H = 6 m")
    rendered(fig, tmp_path / "walls.png")
    ax_p, ax_q = fig.axes
    assert ax_p.get_xlabel() == "pressure on the wall (kPa)"
    assert ax_p.get_ylabel() == "depth below the top (m)"
    assert ax_p.get_ylim()[0] > ax_p.get_ylim()[1]   # depth grows downward
    assert len(ax_p.get_lines()) == 5
    for line, field in zip(ax_p.get_lines(), ("static", "mo_dynamic", "ec8_rigid", "vy",
                                              "one_term")):
        np.testing.assert_array_equal(line.get_xdata(), getattr(prof, field))
        np.testing.assert_array_equal(line.get_ydata(), prof.depth)
    widths = [bar.get_width() for bar in ax_q.patches]
    np.testing.assert_array_equal(widths, cmp.thrust)
    assert [t.get_text() for t in ax_q.get_yticklabels()] == list(walls.COMPARISON_ROWS)
    assert "(kN/m)" in ax_q.get_xlabel()
    notes = [t.get_text() for t in ax_q.texts]
    assert notes == [f" z = {z:.2f} m" for z in cmp.z]
    # the profile alone, into an axes
    fig, axis = plt.subplots(layout="constrained")
    plot.walls(prof, ax=axis)
    rendered(fig, tmp_path / "w1.png")


# ------------------------------------------------------------------ overturning maps

def test_overturning_map(tmp_path):
    freq, amp = np.linspace(0.5, 6, 12), np.linspace(0.5, 4, 9)
    classes = rocking.overturning_map("sine_cycle", freq, amp, alpha=0.2)
    fig = plot.overturning_map(classes, freq, amp, title="sine cycle")
    legends = rendered(fig, tmp_path / "map.png")
    (axis,) = fig.axes
    assert (axis.get_xlabel(), axis.get_ylabel()) == ("omega_p / p (-)",
                                                      "a_p / (g tan alpha) (-)")
    assert [t.get_text() for t in legends[0].get_texts()] == list(rocking.MAP_CLASSES)
    # below the cells, not over them
    renderer = fig.canvas.get_renderer()
    assert legends[0].get_window_extent(renderer).y1 < axis.get_window_extent(renderer).y0
    np.testing.assert_array_equal(axis.collections[0].get_array().reshape(classes.shape),
                                  classes)
    # the old entry point: the same drawing, returns the axes; in the caller's axes the
    # legend goes inside them
    ax = rocking.plot_overturning_map(classes, freq, amp)
    rendered(ax.figure, tmp_path / "map2.png", units=False)
    fig, axis = plt.subplots()
    assert rocking.plot_overturning_map(classes, freq, amp, ax=axis) is axis
    legends = rendered(fig, tmp_path / "map3.png", units=False)
    assert axis.get_window_extent(fig.canvas.get_renderer()).contains(
        *legends[0].get_window_extent().get_points()[0])


# ------------------------------------------------------------------ errors, dependency

def test_bad_input(rec):
    r = newmark.rigid(rec, ky=0.05)
    with pytest.raises(InvalidInputError, match="^result: has no history"):
        plot.newmark(r)
    r = newmark.rigid(rec, ky=0.05, history=True)
    with pytest.raises(InvalidInputError, match="^record: must have the 200 samples"):
        plot.newmark(r, rec.accel[:10])
    with pytest.raises(InvalidInputError, match="^result"):
        plot.newmark(rec)
    with pytest.raises(InvalidInputError, match="^ax: needs 3 axes"):
        plot.newmark(r, rec, ax=plt.subplots(2)[1])
    with pytest.raises(InvalidInputError, match="^quantity"):
        plot.spectra(rec, quantity="pga")
    with pytest.raises(InvalidInputError, match="^xscale"):
        plot.spectra(rec, xscale="loglog")
    spec = sdof.spectrum(rec, periods=[0.1, 1.0])
    with pytest.raises(InvalidInputError, match="^periods, damping, dt"):
        plot.spectra(spec, damping=0.05)
    with pytest.raises(InvalidInputError, match="^dt"):
        plot.spectra(rec.accel)
    blk = rocking.rectangular_block(0.2, 1.0)
    p = pulse.define("half_sine", amp=3.0, duration=0.5)
    with pytest.raises(InvalidInputError, match="^run: has no history"):
        plot.rocking(rocking.simulate(blk, p), blk)
    with pytest.raises(InvalidInputError, match="^units"):
        plot.rocking(rocking.simulate(blk, p, t=[0.0, 1.0]), blk, [0.0, 1.0], dt=0.1,
                     units="furlongs")
    with pytest.raises(InvalidInputError, match="^t: the times"):
        plot.pulse(pulse.half_sine(np.linspace(0, 1, 5), amp=1.0, duration=1.0))
    with pytest.raises(InvalidInputError, match="^t: 5 times, but the PulseHistory has 3"):
        plot.pulse(pulse.half_sine(np.linspace(0, 1, 3), amp=1.0, duration=1.0),
                   np.linspace(0, 1, 5))
    with pytest.raises(InvalidInputError, match="^source"):
        plot.spectra(walls.comparison(**WALL))
    with pytest.raises(InvalidInputError, match="^p: must be"):
        plot.pulse("half_sine")
    with pytest.raises(InvalidInputError, match="^profile"):
        plot.walls(walls.comparison(**WALL))
    with pytest.raises(InvalidInputError, match="^legend"):
        plot.overturning_map(np.zeros((2, 2)), [1, 2], [1, 2], legend="left")


def test_matplotlib_optional(source_root):
    """import seispulse does not import matplotlib; without it a plot raises ImportError
    naming it and how to install it."""
    code = ("import sys\n"
            "import seispulse\n"
            "assert 'matplotlib' not in sys.modules, 'imported at import seispulse'\n"
            "sys.modules['matplotlib'] = None\n"
            "sys.modules['matplotlib.pyplot'] = None\n"
            "from seispulse import plot, pulse\n"
            "try:\n"
            "    plot.pulse(pulse.define('half_sine', amp=1.0, duration=1.0))\n"
            "except ImportError as exc:\n"
            "    print(exc)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert "matplotlib" in out and "pip install matplotlib" in out


def test_screenshot_script(source_root, tmp_path):
    """tools/make_screenshots.py renders the README's pictures (small PNGs of the sizes it
    sets) and a text table given with --table."""
    table = tmp_path / "table.txt"
    table.write_text("# a table\n  ky (g)  max_disp (m)\n    0.05        0.1008\n")
    out = subprocess.run([sys.executable, str(source_root / "tools" / "make_screenshots.py"),
                          "--out", str(tmp_path), "--table", str(table)],
                         capture_output=True, text=True, check=True).stdout
    sizes = {"spectra.png": (700, 400), "newmark.png": (700, 600)}
    for name, (width, height) in sizes.items():
        data = (tmp_path / name).read_bytes()
        assert data[:8] == PNG and 10_000 < len(data) < 150_000
        assert struct.unpack(">II", data[16:24]) == (width, height)
        assert name in out
    assert (tmp_path / "table.png").read_bytes()[:8] == PNG


# ------------------------------------------------------------------ record suites

def test_record_suite(tmp_path):
    """The check of codes.check_record_suite: every record's PSA, the mean, the target and
    0.9 x target drawn at the check's own numbers, the band [0.2 T1, 2 T1] shaded, T1
    marked, log period axis, units on the axes, the legend inside."""
    from seispulse import codes
    t = np.arange(0.0, 6.0, 0.01)
    tri = np.interp(t, [0.0, 0.25, 0.5], [0.0, 1.0, 0.0], right=0.0)
    suite = [(a * tri, 0.01) for a in (0.2, 0.3, 0.4)]
    check = codes.check_record_suite(suite, 0.4, codes.elastic_target(0.3, ground="B"),
                                     n_points=40)
    fig = plot.record_suite(check)
    legends = rendered(fig, tmp_path / "suite.png")
    (axis,) = fig.axes
    assert axis.get_xscale() == "log" and axis.get_xlabel() == "period T (s)"
    assert axis.get_ylabel() == "PSA, 5 % damping (g)"
    assert axis.get_title() == "EN 1998-1 3.2.3.1.2(4): failed (3 records)"
    lines = lines_of(axis)
    assert len(lines) == 3 + 3     # records, mean, target, 0.9 target
    for line, row in zip(lines[:3], check.psa):
        np.testing.assert_array_equal(line.get_xdata(), check.periods)
        np.testing.assert_array_equal(line.get_ydata(), row)
    np.testing.assert_array_equal(lines[3].get_ydata(), check.mean)
    np.testing.assert_array_equal(lines[4].get_ydata(), check.target)
    np.testing.assert_array_equal(lines[5].get_ydata(), 0.9 * check.target)
    labels = [t.get_text() for t in legends[0].get_texts()]
    assert labels[:4] == ["records, 5 % PSA", "mean of 3 records", "target (elastic spectrum)",
                          "0.9 x target"]
    assert "T1 = 0.4 s" in labels and "0.2 T1 .. 2 T1" in labels
    (band,) = axis.patches
    x = band.get_patch_transform().transform(band.get_path().vertices)[:, 0]   # data x
    assert min(x) == pytest.approx(0.08, rel=1e-15) and max(x) == pytest.approx(0.8, rel=1e-15)
    assert f"least mean/target = {check.min_ratio:.4f} (fail, >= 0.9)" in labels
    assert axis.get_xlim() == pytest.approx((0.08, 0.8), rel=1e-12)
    (text,) = axis.texts
    assert text.get_text() == (f"rule (b): mean PGA {check.pga_mean:.4g} g vs a_g S 0.36 g "
                               "(fail)")
    fig = plot.record_suite(check, scaled="common")
    extra = lines_of(fig.axes[0])[6]
    np.testing.assert_allclose(extra.get_ydata(), check.common_scale * check.mean, rtol=1e-15)
    fig = plot.record_suite(check, scaled="own")
    np.testing.assert_array_equal(lines_of(fig.axes[0])[6].get_ydata(), check.own_mean)
    with pytest.raises(InvalidInputError, match="^scaled = 'x': must be None"):
        plot.record_suite(check, scaled="x")
    with pytest.raises(InvalidInputError, match="^check: must be the result of"):
        plot.record_suite(check._asdict())
    fig, ax = plt.subplots()
    assert plot.record_suite(check, ax=ax, title="mine") is fig and ax.get_title() == "mine"
