"""Property tests (Hypothesis): laws every result must obey, over random records and
parameters, corners included.

* Newmark one-way displacement never increases with the yield ky (exact and SLAMMER rules).
* Response spectra scale linearly with the record: SD, SV, SA, PSA of c a are |c| times
  those of a, bit for bit for c a power of two (every operation commutes with it), to
  rounding for other c.
* Polarity: the record -a with yields (ky, ky_up) slides as a with (ky_up, ky), mirrored;
  the one-way result of an inverted record is the upslope result of the original.
* The closed forms of the pulses (sliding half and full cycles, linearized rocking) equal
  the library's integrators, and the exact Newmark rule equals sliding.simulate on records.
* Bad values (NaN, inf, negative, wrong types, empty arrays) raise the documented
  seispulse errors, never anything else (and never crash the interpreter).

derandomize=True: the examples are the same on every run (CI is deterministic); no example
database is written.
"""
import math

import numpy as np
import pytest

pytest.importorskip("hypothesis", reason="the property tests need hypothesis (pip install "
                    "hypothesis; make deps installs it)")
from hypothesis import HealthCheck, example, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from hypothesis.extra.numpy import arrays  # noqa: E402

from seispulse import newmark, pulse, records, rocking, sdof, sliding  # noqa: E402
from seispulse.errors import InvalidInputError, SeispulseError  # noqa: E402

PROPS = settings(max_examples=60, deadline=None, derandomize=True, database=None,
                 suppress_health_check=[HealthCheck.too_slow])
INF = math.inf
G = 9.80665      # m/s^2

# accelerations (g) and steps (s)
# (values below 1e-30 g become 0: far below any record's resolution, and products of them
# would leave the normal range, where scaling by a power of two is no longer exact)
samples = st.floats(-1.5, 1.5, allow_nan=False, allow_infinity=False).map(
    lambda x: x if abs(x) > 1e-30 else 0.0)
steps = st.sampled_from([0.005, 0.01, 0.02, 0.025])


@st.composite
def records_g(draw, min_size=2, max_size=300):
    """(accel in g, dt in s): random samples, sometimes a smooth burst, sometimes mostly
    zeros (records with long still parts)."""
    n = draw(st.integers(min_size, max_size))
    base = draw(st.sampled_from(["random", "burst", "sparse"]))
    if base == "random":
        a = draw(arrays(np.float64, n, elements=samples))
    elif base == "burst":
        amp = draw(st.floats(0.05, 1.5))
        cycles = draw(st.floats(0.5, 8.0))
        t = np.linspace(0.0, 1.0, n)
        a = amp * np.sin(2 * np.pi * cycles * t) * np.sin(np.pi * t) ** 2
    else:
        a = np.zeros(n)
        idx = draw(st.lists(st.integers(0, n - 1), min_size=1, max_size=10))
        a[idx] = draw(arrays(np.float64, len(idx), elements=samples))
    a[np.abs(a) < 1e-30] = 0.0
    return np.ascontiguousarray(a), draw(steps)


yields = st.floats(0.005, 1.0, allow_subnormal=False)
#: the largest slip (m) SLAMMER's rule may give where the exact one gives none: the rounding
#: of a - (a/ky) ky it integrates below the yield
ROUNDING_SLIP = 1e-15


# --- Newmark: monotone in ky -------------------------------------------------------------

@PROPS
@given(rec=records_g(), k=st.tuples(yields, yields).map(sorted),
       method=st.sampled_from(["exact", "slammer"]))
def test_newmark_displacement_never_increases_with_ky(rec, k, method):
    a, dt = rec
    r = newmark.rigid(a, dt, ky=list(k), method=method)
    low, high = r.max_disp
    assert high <= low * (1 + 1e-12) + 1e-15, (k, low, high)
    assert r.final_disp[1] <= r.final_disp[0] * (1 + 1e-12) + 1e-15
    # one-way: the block never comes back, so the largest slip is the final one
    assert np.array_equal(r.max_disp, r.final_disp)


@PROPS
@given(rec=records_g(), ky=yields, method=st.sampled_from(["exact", "slammer"]))
def test_newmark_no_slip_below_the_yield(rec, ky, method):
    """No sample above ky: no slip (SLAMMER's rule: up to the rounding of its a - (a/ky) ky
    below the yield, which the library keeps: seispulse_newmark, rigid_slammer)."""
    a, dt = rec
    r = newmark.rigid(a, dt, ky=ky, method=method)
    if np.max(a) <= ky:
        assert r.max_disp <= (0.0 if method == "exact" else ROUNDING_SLIP)
    assert r.max_disp >= 0.0 and r.u_min >= 0.0


# --- spectra: linear in the record -------------------------------------------------------

periods_s = st.lists(st.floats(0.02, 5.0, allow_subnormal=False), min_size=1, max_size=6,
                     unique=True).map(sorted)
dampings = st.sampled_from([0.0, 0.02, 0.05, 0.2])
SPECTRA = ("sd", "sv", "sa", "psv", "psa")


@PROPS
@given(rec=records_g(min_size=2, max_size=200), periods=periods_s, damping=dampings,
       power=st.integers(-6, 6), sign=st.sampled_from([1.0, -1.0]),
       peaks=st.sampled_from(["exact", "samples"]))
def test_spectrum_scales_exactly_by_powers_of_two(rec, periods, damping, power, sign, peaks):
    a, dt = rec
    c = sign * 2.0 ** power
    s1 = sdof.spectrum(a, dt, periods, damping, peaks=peaks, threads=1)
    s2 = sdof.spectrum(c * a, dt, periods, damping, peaks=peaks, threads=1)
    for name in SPECTRA:
        assert np.array_equal(getattr(s2, name), abs(c) * getattr(s1, name)), name
    for name in ("t_sd", "t_sv", "t_sa"):
        assert np.array_equal(getattr(s2, name), getattr(s1, name)), name


@settings(PROPS, max_examples=40)
@given(rec=records_g(min_size=2, max_size=120), periods=periods_s, damping=dampings,
       c=st.floats(-30.0, 30.0).filter(lambda x: abs(x) > 1e-3))
@example(rec=(np.array([0.0, 1.0, -0.5, 0.25]), 0.01), periods=[0.02, 0.1, 5.0], damping=0.0,
         c=math.pi)
def test_spectrum_scales_linearly(rec, periods, damping, c):
    a, dt = rec
    s1 = sdof.spectrum(a, dt, periods, damping, threads=1)
    s2 = sdof.spectrum(c * a, dt, periods, damping, threads=1)
    for name in SPECTRA:
        x, y = abs(c) * getattr(s1, name), getattr(s2, name)
        floor = 1e-12 * max(np.max(np.abs(x)), 1e-300)
        np.testing.assert_allclose(y, x, rtol=1e-11, atol=floor, err_msg=name)


# --- polarity ----------------------------------------------------------------------------

@PROPS
@given(rec=records_g(), k1=yields, k2=yields, method=st.sampled_from(["exact", "slammer"]))
def test_inverted_record_swaps_the_two_senses(rec, k1, k2, method):
    """-a with (ky = k1 down, ky_up = k2) is a with (k2, k1), mirrored: u -> -u."""
    a, dt = rec
    r1 = newmark.rigid(-a, dt, ky=k1, mode="asym", ky_up=k2, method=method)
    r2 = newmark.rigid(a, dt, ky=k2, mode="asym", ky_up=k1, method=method)
    scale = max(abs(r2.u_max), abs(r2.u_min), 1e-12)
    assert r1.u_max == pytest.approx(-r2.u_min, rel=1e-12, abs=1e-14 * scale)
    assert r1.u_min == pytest.approx(-r2.u_max, rel=1e-12, abs=1e-14 * scale)
    assert r1.final_disp == pytest.approx(-r2.final_disp, rel=1e-12, abs=1e-14 * scale)
    assert r1.max_vel == pytest.approx(r2.max_vel, rel=1e-12, abs=1e-14)
    s1 = sliding.simulate(accel=-a, dt=dt, ay=k1, ay_rev=k2)
    s2 = sliding.simulate(accel=a, dt=dt, ay=k2, ay_rev=k1)
    assert s1.u_final == pytest.approx(-s2.u_final, rel=1e-12, abs=1e-14 * scale)
    assert [s.direction for s in s1.slides] == [-s.direction for s in s2.slides]


@PROPS
@given(rec=records_g(), ky=yields, method=st.just("exact"))
def test_one_way_of_the_inverse_record_is_the_upslope_result(rec, ky, method):
    """'down' on the inverted record (records.Record.inverted) = sliding upslope only on
    the record (a downslope yield no sample reaches), mirrored; 'down' = 'asym' without an
    upslope yield. The exact rule only: in SLAMMER's two-way rule a yield out of reach is
    not neutral (the rounding of a - (a/ky) ky below it leaves a velocity of ~1e-15 cm/s
    whose sign test then stops a reverse slide), so its two-way and one-way rules differ
    there, as SLAMMER's own do."""
    a, dt = rec
    record = records.from_array(a, dt)
    inv = newmark.rigid(record.inverted(), ky=ky, method=method)
    up = newmark.rigid(record, ky=100.0, mode="asym", ky_up=ky, method=method)
    assert inv.max_disp == pytest.approx(-up.u_min, rel=1e-12, abs=1e-15)
    assert up.u_max <= (0.0 if method == "exact" else ROUNDING_SLIP)
    down = newmark.rigid(record, ky=ky, method=method)
    same = newmark.rigid(record, ky=ky, mode="asym", ky_up=INF, method=method)
    assert down.max_disp == pytest.approx(same.max_disp, rel=1e-13, abs=1e-16)


# --- closed forms = the event-driven integrator -------------------------------------------

etas = st.one_of(st.floats(1e-3, 0.999), st.sampled_from([1e-3, 0.5, 0.999, 1.0, 1.5]))
betas = st.one_of(st.floats(-60.0, 60.0),
                  st.sampled_from([-INF, -1e3, -math.pi, -1e-9, 0.0, 1e-9, math.pi, 200.0,
                                   1e3]))
static = st.one_of(st.just(1.0), st.floats(1.0, 1.5))


def agree(closed, integ, what, rtol=1e-9, atol=1e-13):
    if isinstance(closed, str) or isinstance(integ, str):
        assert closed == integ, what
    elif math.isnan(closed) or math.isnan(integ):
        assert math.isnan(closed) and math.isnan(integ), (what, closed, integ)
    else:
        assert integ == pytest.approx(closed, rel=rtol, abs=atol), what


@PROPS
@given(eta=etas, beta=betas, a=static)
def test_half_cycle_closed_form_equals_integrator(eta, beta, a):
    h = sliding.half_cycle(eta, beta, static_factor=a)
    g = sliding.half_cycle(eta, beta, static_factor=a, method="integrator")
    if math.isinf(beta) and beta > 0:            # the spike: no area, no slide
        assert h.um == 0.0 and g.um == 0.0
        return
    for name in h._fields:
        agree(getattr(h, name), getattr(g, name), name)


@PROPS
@given(eta1=etas, eta2=etas, beta=betas, a=static, static_reverse=st.booleans())
def test_full_cycle_closed_form_equals_integrator(eta1, eta2, beta, a, static_reverse):
    f = sliding.full_cycle(eta1, beta, eta2=eta2, static_factor=a,
                           static_reverse=static_reverse)
    g = sliding.full_cycle(eta1, beta, eta2=eta2, static_factor=a,
                           static_reverse=static_reverse, method="integrator")
    if math.isinf(beta) and beta > 0:
        assert f.um1 == 0.0 and f.um2 == 0.0 and g.ures == 0.0
        return
    for name in f._fields:
        agree(getattr(f, name), getattr(g, name), name)


@PROPS
@given(rec=records_g(max_size=120), k1=yields, k2=yields)
def test_exact_newmark_equals_event_driven_integrator(rec, k1, k2):
    """Two integrators of the same sampled record (piecewise linear): the exact Newmark
    rule and sliding.simulate (event-driven, roots on the analytic velocity)."""
    a, dt = rec
    r = newmark.rigid(a, dt, ky=k1, mode="asym", ky_up=k2, g=1.0, history=True)
    s = sliding.simulate(accel=a, dt=dt, ay=k1, ay_rev=k2, t=r.time)
    scale = max(abs(s.u_max), abs(s.u_min), 1e-12)
    assert abs(r.final_disp - s.u_final) <= 1e-11 * scale
    assert abs(r.u_max - s.u_max) <= 1e-11 * scale
    assert abs(r.u_min - s.u_min) <= 1e-11 * scale
    assert np.max(np.abs(r.disp - s.u)) <= 1e-11 * scale


# --- bad values raise the documented errors ----------------------------------------------

class Junk:
    """An object that is no number."""


NOT_NUMBER = ["0.1", b"1", None, True, np.bool_(False), Junk(), complex(1.0, 1.0),
              [[1.0], [2.0, 3.0]]]
NOT_FINITE = [math.nan, np.float64("nan"), INF, -INF, 1e308 * 10]
NOT_POSITIVE = [-1.0, 0.0, -0.0, -1e-300, -INF]
BAD_RECORDS = [np.array([]), [], np.array([math.nan, 0.0]), [0.0, INF], "abc", None,
               np.zeros((2, 2)), [[0.0, 1.0], [0.0]], np.array(["a", "b"]),
               np.array([1.0, 2.0], dtype=complex), True, [True, False], Junk()]
GOOD_REC = np.array([0.0, 0.3, -0.2, 0.1, 0.0])
STEP = NOT_NUMBER + NOT_FINITE + NOT_POSITIVE

# name: (call, good arguments, {argument: values the documentation rules out})
CASES = {
    "newmark.rigid": (
        lambda accel, dt, ky: newmark.rigid(accel, dt, ky=ky),
        {"accel": GOOD_REC, "dt": 0.01, "ky": 0.1},
        {"accel": BAD_RECORDS, "dt": STEP,
         "ky": NOT_NUMBER + [math.nan, -INF] + NOT_POSITIVE + [np.array([])]}),
    "newmark.rigid slammer": (
        lambda accel, dt, ky: newmark.rigid(accel, dt, ky=ky, method="slammer"),
        {"accel": GOOD_REC, "dt": 0.01, "ky": 0.1},
        {"accel": BAD_RECORDS, "dt": STEP, "ky": NOT_NUMBER + [math.nan] + NOT_POSITIVE}),
    "sdof.spectrum": (
        lambda accel, dt, periods, damping: sdof.spectrum(accel, dt, periods, damping),
        {"accel": GOOD_REC, "dt": 0.01, "periods": [0.1, 1.0], "damping": 0.05},
        {"accel": BAD_RECORDS, "dt": STEP,
         "periods": [[math.nan], [-1.0], [], "x", None, [[0.1], [0.2, 0.3]], True, [INF]],
         "damping": NOT_NUMBER + NOT_FINITE + [-0.1, 1.0, 2.0]}),
    "sdof.response": (
        lambda accel, dt, period, damping: sdof.response(accel, dt, period, damping),
        {"accel": GOOD_REC, "dt": 0.01, "period": 0.5, "damping": 0.05},
        {"accel": BAD_RECORDS, "dt": STEP, "period": NOT_NUMBER + NOT_FINITE + [-1.0],
         "damping": NOT_NUMBER + NOT_FINITE + [-0.1, 1.0]}),
    "sliding.simulate": (
        lambda accel, dt, ay: sliding.simulate(accel=accel, dt=dt, ay=ay),
        {"accel": GOOD_REC, "dt": 0.01, "ay": 0.1},
        {"accel": BAD_RECORDS, "dt": STEP, "ay": NOT_NUMBER + [math.nan] + NOT_POSITIVE}),
    "sliding.half_cycle": (
        lambda eta, beta: sliding.half_cycle(eta, beta),
        {"eta": 0.3, "beta": -1.0},
        {"eta": NOT_NUMBER + [math.nan] + NOT_POSITIVE + [np.array([])],
         "beta": NOT_NUMBER + [math.nan, np.array([])]}),
    "pulse.half_sine": (
        lambda t, amp, duration: pulse.half_sine(t, amp, duration),
        {"t": [0.0, 0.1], "amp": 1.0, "duration": 0.5},
        {"t": [[math.nan], [INF], "x", None, [[0.0], [1.0, 2.0]], True],
         "amp": NOT_NUMBER + NOT_FINITE, "duration": STEP}),
    "records.from_array": (
        lambda accel, dt: records.from_array(accel, dt),
        {"accel": GOOD_REC, "dt": 0.01}, {"accel": BAD_RECORDS, "dt": STEP}),
    "records.intensity": (
        lambda accel, dt: records.intensity(accel, dt),
        {"accel": GOOD_REC, "dt": 0.01}, {"accel": BAD_RECORDS, "dt": STEP}),
}
ALL_BAD = [(name, arg, bad) for name, (_, _, bads) in CASES.items()
           for arg, values in bads.items() for bad in values]


def test_good_arguments_run():
    for call, good, _ in CASES.values():
        call(**good)


@settings(max_examples=200, deadline=None, derandomize=True, database=None)
@given(case=st.sampled_from(ALL_BAD))
def test_bad_values_raise_invalid_input(case):
    """Every value the documentation rules out raises InvalidInputError (a ValueError)
    whose message names the argument."""
    name, arg, bad = case
    call, good, _ = CASES[name]
    with pytest.raises(InvalidInputError) as info:
        call(**dict(good, **{arg: bad}))
    assert isinstance(info.value, ValueError)
    assert arg in str(info.value), (name, arg, str(info.value))


anything = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**30, 10**30), st.none(),
    st.booleans(), st.text(max_size=5), st.binary(max_size=5), st.complex_numbers(),
    st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=6),
    st.lists(st.lists(st.floats(-1, 1), max_size=3), max_size=3),
    arrays(np.float64, st.integers(0, 6)), arrays(np.int32, st.integers(0, 4)))


@settings(max_examples=120, deadline=None, derandomize=True, database=None)
@given(name=st.sampled_from(sorted(CASES)), data=st.data(), value=anything)
def test_any_value_runs_or_raises_a_seispulse_error(name, data, value):
    """Whatever an argument is, a call returns or raises a seispulse error: never another
    exception (and never crashes the interpreter)."""
    call, good, _ = CASES[name]
    arg = data.draw(st.sampled_from(sorted(good)))
    try:
        call(**dict(good, **{arg: value}))
    except SeispulseError:
        pass


@settings(max_examples=40, deadline=None, derandomize=True, database=None)
@given(f=st.floats(0.2, 6.0), eta=st.floats(0.05, 0.95),
       beta=st.one_of(st.floats(-10.0, 10.0),
                      st.sampled_from([-INF, -math.pi, -1e-9, 0.0, 1e-9, math.pi])))
def test_rocking_closed_forms_equal_linearized_integrator(f, eta, beta):
    """The linearized rocking closed forms (half-cycle exponential pulse) against the
    library's integrator run linearized on the same pulse (a block of alpha = 0.1, p = 2
    rad/s: t_d = f/p, A_g = g alpha/eta)."""
    s = rocking.summary(f, eta, beta)
    p, alpha, k = 2.0, 0.1, 4.0 / 3.0
    block = rocking.symmetric_block(G / (k * p * p), alpha, k, g=G, e=0.0)
    td = f / p
    run = rocking.simulate(block, pulse.define("exponential", amp=G * alpha / eta, td=td,
                                               beta=beta),
                           linearized=True, t_max=50 * td)
    assert run.t_uplift / td == pytest.approx(s.tau_up, rel=1e-9, abs=1e-12)
    if s.region.startswith("O"):
        assert run.outcome == "overturn_no_impact", (s, run.outcome)
        assert run.t_overturn / td == pytest.approx(s.tau_c, rel=1e-8)
    else:
        assert run.n_impacts >= 1, (s, run.outcome)
        assert run.t_impacts[0] / td == pytest.approx(s.tau_i, rel=1e-8)
        assert run.theta_max / alpha == pytest.approx(s.psi_max, rel=1e-8)
