"""Sine and cosine cycles with a number of cycles n: the closed forms against numerical
quadrature (mpmath) of A sin(2 pi t/T), A cos(2 pi t/T) written here, bad n refused naming
``cycles``, the overturning map's template carrying n, and the driver's ``cycles`` key."""
import csv
import math
import subprocess
from pathlib import Path

import numpy as np
import pytest
import mpmath as mp

from seispulse import pulse as P
from seispulse import rocking as R
from seispulse.errors import InvalidInputError
from driver_echo import echo_text

G = P.STANDARD_GRAVITY


def _ref(kind, t, amp, period):
    """a, v = int_0^t a(s) ds and d = int_0^t (t - s) a(s) ds (the repeated integral in
    Cauchy's form) by mpmath quadrature at 30 digits, split at every half period."""
    mp.mp.dps = 30
    f = mp.sin if kind == "sine_cycle" else mp.cos
    tt, aa, tp = mp.mpf(t), mp.mpf(amp), mp.mpf(period)

    def acc(s):
        return aa * f(2 * mp.pi * s / tp)

    nodes = [k * tp / 2 for k in range(int(2 * t / period) + 1)] + [tt]
    v = mp.quad(acc, nodes)
    d = mp.quad(lambda s: (tt - s) * acc(s), nodes)
    return float(acc(tt)), float(v), float(d)


@pytest.mark.parametrize("kind", ["sine_cycle", "cosine_cycle"])
def test_three_cycles_against_quadrature(kind):
    amp, period, n = 1.7, 0.9, 3
    fn = getattr(P, kind)
    for t in [0.1, 0.45, 0.9, 1.23, 1.8, 2.0, 2.6, 2.69]:
        a, v, d = fn(t, amp, period, cycles=n)
        ra, rv, rd = _ref(kind, t, amp, period)
        assert a == pytest.approx(ra, rel=1e-13, abs=1e-14 * amp)
        assert v == pytest.approx(rv, rel=1e-13, abs=1e-14 * amp * period)
        assert d == pytest.approx(rd, rel=1e-13, abs=1e-14 * amp * period ** 2)
    # after n T: rest, the sine at its fling n A T^2/(2 pi), the cosine at 0
    a, v, d = fn(5.0, amp, period, cycles=n)
    assert a == 0.0 and v == 0.0
    expected = n * amp * period ** 2 / (2 * math.pi) if kind == "sine_cycle" else 0.0
    assert d == pytest.approx(expected, rel=1e-14, abs=1e-15)


def test_one_cycle_is_the_default_bit_for_bit():
    t = np.linspace(-0.1, 2.0, 211)
    for fn in (P.sine_cycle, P.cosine_cycle):
        ref = fn(t, 2.5, 1.2)
        for got in (fn(t, 2.5, 1.2, cycles=1), fn(t, 2.5, 1.2, cycles=1.0)):
            for x, y in zip(got, ref):
                np.testing.assert_array_equal(x, y)


def test_twenty_cycles_define_and_broadcast():
    p = P.define("sine_cycle", amp=0.4, amp_unit="g", period=1.0, cycles=20)
    assert p.kind == "sine_cycle"
    # cycles broadcasts like every parameter
    h = P.sine_cycle(25.0, 0.4 * G, 1.0, cycles=np.array([1, 5, 20]))
    np.testing.assert_allclose(h.d, 0.4 * G * np.array([1, 5, 20]) / (2 * math.pi),
                               rtol=1e-14)


@pytest.mark.parametrize("bad", [0, 2.5, math.nan, 1e7, -1, math.inf])
@pytest.mark.parametrize("kind", ["sine_cycle", "cosine_cycle"])
def test_bad_cycles_refused(kind, bad):
    with pytest.raises(InvalidInputError, match=r"^cycles = .*whole number"):
        getattr(P, kind)(0.1, 1.0, 1.0, cycles=bad)
    with pytest.raises(InvalidInputError, match=r"^cycles"):
        P.define(kind, amp=1.0, period=1.0, cycles=bad)


def test_map_template_carries_cycles():
    """Cells of a map of 2 sine cycles = rocking.simulate under the 2-cycle pulse on a
    block with the same alpha, e, and p, g of its own (the map is dimensionless)."""
    alpha, e = 0.25, 0.9
    freq = np.array([2.0, 4.0, 7.0])
    amp = np.array([1.5, 3.0, 6.0])
    two = R.overturning_map("sine_cycle", freq, amp, alpha=alpha, e=e, cycles=2)
    one = R.overturning_map("sine_cycle", freq, amp, alpha=alpha, e=e)
    assert not np.array_equal(one, two), "the second cycle changes some cell"
    blk = R.symmetric_block(1.3, alpha, 4.0 / 3.0, e=e)
    to_class = {"rest": 0, "no_uplift": 0, "overturn_no_impact": 1,
                "overturn_one_impact": 2, "overturn_many_impacts": 3}
    for j, fr in enumerate(freq):
        for i, ar in enumerate(amp):
            pulse = P.define("sine_cycle", amp=ar * blk.g * math.tan(alpha),
                             period=2 * math.pi / (fr * blk.p), cycles=2)
            run = R.simulate(blk, pulse)
            assert to_class[run.outcome] == two[i, j], (fr, ar, run.outcome)
    with pytest.raises(InvalidInputError, match=r"^cycles"):
        R.overturning_map("sine_cycle", freq, amp, alpha=alpha, cycles=0)


def _run(driver, cwd, text):
    (Path(cwd) / "case.nml").write_text(text)
    return subprocess.run([driver, "case.nml"], cwd=cwd, capture_output=True, text=True,
                          timeout=60)


def test_driver_cycles_key(driver, tmp_path):
    proc = _run(driver, tmp_path, "&run analysis='pulse', output='c' /\n"
                                  "&pulse kind='sine_cycle', amp=0.4, amp_unit='g', "
                                  "duration=1.0, cycles=20 /\n&time t_end=22.0, dt=0.01 /\n")
    assert proc.returncode == 0, proc.stderr
    assert "cycles = 20.0" in echo_text(tmp_path, proc.stdout), "cycles is echoed"
    table = np.loadtxt(tmp_path / "c_pulse.csv", delimiter=",", skiprows=1, ndmin=2)
    ref = P.sine_cycle(table[:, 0], 0.4, 1.0, cycles=20, amp_unit="g")
    np.testing.assert_allclose(table[:, 1], ref.a, rtol=1e-15, atol=1e-15)
    np.testing.assert_allclose(table[:, 4], ref.d, rtol=1e-15, atol=1e-16)
    # the end: 20 A T^2/(2 pi), written out here
    assert table[-1, 4] == pytest.approx(20 * 0.4 * G / (2 * math.pi), rel=1e-14)
    # a key not given is not echoed
    proc = _run(driver, tmp_path, "&run analysis='pulse', output='d' /\n"
                                  "&pulse kind='sine_cycle', duration=1.0 /\n")
    assert proc.returncode == 0 and "cycles" not in echo_text(tmp_path, proc.stdout)
    proc = _run(driver, tmp_path, "&run analysis='pulse', output='w' /\n"
                                  "&pulse kind='half_sine', cycles=3 /\n")
    assert proc.returncode == 0 and "cycles: not used by kind half_sine" in proc.stderr


@pytest.mark.parametrize("value, shown", [("0", "cycles = 0"), ("2.5", "cycles = 2.5"),
                                          ("nan", "cycles = NaN"), ("1e7", "cycles = ")])
def test_driver_bad_cycles(driver, tmp_path, value, shown):
    proc = _run(driver, tmp_path, "&run analysis='pulse', output='o' /\n\n"
                                  f"&pulse kind='cosine_cycle', cycles={value} /\n")
    assert proc.returncode == 2, proc.stdout
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and ("case.nml:3: &pulse: " + shown) in lines[0], lines
    assert "whole number" in lines[0]
    assert sorted(x.name for x in tmp_path.iterdir()) == ["case.nml"]


def test_driver_map_cycles(driver, tmp_path):
    text = ("&run analysis='rocking', output='m' /\n&block alpha=0.25, r=1.0, e=0.9 /\n"
            "&rocking what='map' /\n&map kind='sine_cycle', cycles={} , "
            "freq_ratio=2.0, 4.0, 7.0, amp_ratio=1.5, 3.0, 6.0 /\n")
    proc = _run(driver, tmp_path, text.format(2))
    assert proc.returncode == 0, proc.stderr
    with open(tmp_path / "m_rocking_map.csv", newline="") as f:
        classes = [row[2] for row in list(csv.reader(f))[1:]]     # names
    ref = R.overturning_map("sine_cycle", [2.0, 4.0, 7.0], [1.5, 3.0, 6.0], alpha=0.25,
                            e=0.9, cycles=2)
    # the driver names the classes of R.MAP_CLASSES by the run outcomes' words
    names = ["safe", "overturn_no_impact", "overturn_one_impact", "overturn_many_impacts"]
    assert len(names) == len(R.MAP_CLASSES)
    assert classes == [names[c] for c in np.ravel(ref)]
    assert "cycles = 2" in (tmp_path / "m_rocking_map.txt").read_text()
    proc = _run(driver, tmp_path, text.format(0))
    assert proc.returncode == 2 and "&map: cycles = 0" in proc.stderr, proc.stderr


@pytest.mark.parametrize("period", [2.3433216877729124, 0.9, 1.0 / 3.0])
def test_end_decided_in_time(period):
    """The pulse ends at t_end = T n as computed in floating point, even where t_end/T
    rounds below n (T = 2.3433216877729124, n = 7): there the cosine is 0 (the value after
    its final jump), and afterwards the ground rests, v = 0 and d constant."""
    n = 7
    t_end = period * n
    after = np.array([t_end, t_end + 1.0, t_end + 50.0])
    cos = P.cosine_cycle(after, 1.0, period, cycles=n)
    assert cos.a.tolist() == [0.0, 0.0, 0.0]
    assert cos.v.tolist() == [0.0, 0.0, 0.0] and cos.d.tolist() == [0.0, 0.0, 0.0]
    sin = P.sine_cycle(after, 1.0, period, cycles=n)
    assert sin.a.tolist() == [0.0, 0.0, 0.0] and sin.v.tolist() == [0.0, 0.0, 0.0]
    np.testing.assert_allclose(sin.d, n * period**2 / (2 * np.pi), rtol=1e-14)
    assert len(set(sin.d.tolist())) == 1
    # just before the end the cosine is still at its peak
    before = P.cosine_cycle(np.nextafter(t_end, 0.0), 1.0, period, cycles=n)
    assert before.a == pytest.approx(1.0, abs=1e-12)


def test_end_beyond_the_largest_number_refused():
    """T n must be a finite number: T = 1e303 is valid alone, not with a million cycles."""
    assert P.sine_cycle(1.0, 1.0, 1e303, cycles=1).a > 0.0
    with pytest.raises(InvalidInputError, match=r"^cycles = 1000000\.0: the pulse would end"):
        P.sine_cycle(1.0, 1.0, 1e303, cycles=1000000)
