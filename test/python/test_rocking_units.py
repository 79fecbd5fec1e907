"""seispulse.rocking.simulate on records: the units of accel (``units=``, the names of
seispulse.records) and a seispulse.records.Record as accel. The uplift time of a ramp
record is written out here (a_g = k t reaches g tan(alpha) at t = g tan(alpha)/k), so the
unit conversion is checked against an independent number, not against itself."""
import math

import numpy as np
import pytest

from seispulse import cylinder as C
from seispulse import pulse as P
from seispulse import records as REC
from seispulse import rocking as R
from seispulse.errors import InvalidInputError

G = 9.80665
DT = 0.01
RAMP = 0.05 * np.arange(101)          # 0 to 5 in 1 s (slope 5 per s), in the test's unit


def _block(g=G):
    return R.rectangular_block(0.2, 0.8, g=g, e=0.8)


def _same(a, b):
    for name in ("outcome", "t_uplift", "t_overturn", "n_impacts", "theta_max", "theta_min",
                 "t_end"):
        np.testing.assert_equal(getattr(a, name), getattr(b, name), err_msg=name)
    np.testing.assert_array_equal(a.t_impacts, b.t_impacts)


def test_default_is_m_s2():
    """Without units an array is in m/s^2, as before units existed: bit-identical runs,
    and the uplift where k t = g tan(alpha) with k the ramp's slope in m/s^3."""
    blk = _block()
    acc = 5.0 * RAMP                          # 25 m/s^3
    run = R.simulate(blk, accel=acc, dt=DT, t_max=3.0)
    for units in ("m/s2", "M/S^2", "m/s^2"):
        _same(run, R.simulate(blk, accel=acc, dt=DT, units=units, t_max=3.0))
    k = 25.0
    assert run.t_uplift == pytest.approx(G * math.tan(blk.alpha) / k, rel=1e-12)


@pytest.mark.parametrize("g", [G, 9.81, 5.0])
def test_units_g_uses_the_block_g(g):
    """units='g': a_g = block.g x the samples, so a ramp of k g/s uplifts at
    t = tan(alpha)/k whatever g is (and p changes with g)."""
    blk = _block(g)
    acc = RAMP                                # 5 g/s
    run = R.simulate(blk, accel=acc, dt=DT, units="g", t_max=3.0)
    assert run.t_uplift == pytest.approx(math.tan(blk.alpha) / 5.0, rel=1e-12)
    _same(run, R.simulate(blk, accel=g * acc, dt=DT, units="m/s2", t_max=3.0))


@pytest.mark.parametrize("units", ["cm/s2", "cm/s^2", "gal", "GAL"])
def test_units_cm_s2(units):
    """cm/s^2: the samples times 0.01; the uplift at 100 g tan(alpha)/k for a ramp of
    k cm/s^3."""
    blk = _block()
    acc = 500.0 * RAMP                        # 2500 cm/s^3
    run = R.simulate(blk, accel=acc, dt=DT, units=units, t_max=3.0)
    assert run.t_uplift == pytest.approx(100.0 * G * math.tan(blk.alpha) / 2500.0, rel=1e-12)
    _same(run, R.simulate(blk, accel=0.01 * acc, dt=DT, t_max=3.0))


def test_record_object_is_in_g():
    """A seispulse.records.Record (in g, with its dt): the same run as its samples with
    units='g'; accel_v follows the units of accel."""
    blk = _block(9.81)
    acc = 0.6 * np.sin(2 * np.pi * DT * np.arange(150) / 0.7)
    rec = REC.from_array(acc, DT, units="g", name="sine")
    t = np.linspace(0.0, 3.0, 31)
    a = R.simulate(blk, accel=rec, t=t)
    _same(a, R.simulate(blk, accel=acc, dt=DT, units="g", t=t))
    np.testing.assert_array_equal(a.theta, R.simulate(blk, accel=9.81 * acc, dt=DT, t=t).theta)
    _same(R.simulate(blk, accel=rec, accel_v=rec),
          R.simulate(blk, accel=9.81 * acc, dt=DT, accel_v=9.81 * acc))
    _same(R.simulate(blk, accel=acc, dt=DT, units="g", accel_v=0.5 * acc),
          R.simulate(blk, accel=9.81 * acc, dt=DT, accel_v=9.81 * (0.5 * acc)))


def test_cylinder_simulate_passes_units():
    body = C.props(0.3, 1.2, g=9.81)
    acc = 0.5 * np.sin(2 * np.pi * DT * np.arange(120) / 0.75)
    blk = C.rocking_block(body)
    _same(C.simulate(body, accel=acc, dt=DT, units="g"),
          R.simulate(blk, accel=body.g * acc, dt=DT))


@pytest.mark.parametrize("call, match", [
    (lambda b: R.simulate(b, accel=[0.0, 1.0], dt=DT, units="ft/s2"), r"^units = 'ft/s2'"),
    (lambda b: R.simulate(b, accel=[0.0, 1.0], dt=DT, units=9.81), r"^units = 9.81"),
    (lambda b: R.simulate(b, accel=REC.from_array([0.0, 1.0], DT), units="m/s2"),
     r"^units = 'm/s2': a seispulse.records.Record"),
    (lambda b: R.simulate(b, accel=REC.from_array([0.0, 1.0], DT), dt=0.02), r"^dt = 0.02"),
    (lambda b: R.simulate(b, P.define("half_sine", amp=1.0, duration=0.5), units="g"),
     r"^units: the units of a record"),
])
def test_units_errors(call, match):
    with pytest.raises(InvalidInputError, match=match):
        call(_block())
