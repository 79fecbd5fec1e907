"""seispulse.sliding: the closed forms against the independent mpmath oracle of the
chapter's own equations, the published numbers of doc/sliding.md, the corrected equations
at points where the printed ones differ, and the Python face (broadcasting, errors)."""
import math

import numpy as np
import pytest

import seispulse
from seispulse import sliding as S
from seispulse.errors import InvalidInputError

import sliding_reference as R

PI = math.pi


@pytest.mark.parametrize("beta", [-2 * PI, -PI, -1.0, 0.5, 1.0, PI, 2 * PI])
@pytest.mark.parametrize("eta", [0.05, 0.2, 0.5, 0.8])
def test_half_and_full_cycle_against_oracle(beta, eta):
    h, ref = S.half_cycle(eta, beta), R.half_cycle(eta, beta)
    for key in ("tau_y", "tau_m", "um", "vm"):
        assert getattr(h, key) == pytest.approx(float(ref[key]), rel=1e-12), key
    f, ref = S.full_cycle(eta, beta), R.full_cycle(eta, beta)
    assert f.mode == ref["mode"]
    for key in ("tau_y1", "tau_m1", "um1", "tau_y2", "tau_m2", "um2"):
        assert getattr(f, key) == pytest.approx(float(ref[key]), rel=1e-12), key
    assert f.ures == pytest.approx(float(ref["ures"]), rel=1e-10, abs=1e-14)


def test_printed_1_9_cancels_where_1_5_does_not():
    # doc/sliding.md section 3: in double precision the printed 1.9 gives 2.54 at beta = -pi,
    # eta = 0.1 (true 2.284) and 0 at beta = -2 pi (true 3.133)
    for beta, true, in ((-PI, 2.284), (-2 * PI, 3.133)):
        h = S.half_cycle(0.1, beta)
        b, ty, tm, eta = beta, h.tau_y, h.tau_m, 0.1
        x1 = (-math.exp(2 * b * (1 - tm)) + math.exp(2 * b * ty)
              + 2 * b * (math.exp(b) * (1 - 2 * tm) + math.exp(2 * b * ty) * (tm - ty))
              + 2 * b * b * (tm - ty) ** 2 * (1 - eta * (1 - math.exp(b))))
        printed = (x1 - 2 * b * (1 - tm) * (1 + b * (1 - tm)) - 1 + math.exp(2 * b * (1 - tm))) \
            / (4 * b * b * (1 - math.exp(b)))
        assert abs(printed - true) > 0.2
        assert h.um == pytest.approx(true, abs=5e-4)


@pytest.mark.parametrize("beta, eta, true, printed", [(-1.0, 0.05, 0.0678, 0.0338),
                                                     (PI, 0.05, 0.0491, -2.15)])
def test_corrected_1_24(beta, eta, true, printed):
    # slip with a late reverse onset (tau_y2 - 1 > 1/2): doc/sliding.md Corrections 5,
    # e^(beta(1 + 2 tyb)) -> e^beta
    f = S.full_cycle(eta, beta)
    assert f.mode == "slip" and f.tau_y2 - 1 > 0.5
    assert f.um2 == pytest.approx(true, abs=5e-5)
    p = float(R.printed_1_24(R.mpf(f.tau_y2 - 1), R.mpf(f.tau_m2 - 1), R.mpf(eta), R.mpf(beta)))
    assert p == pytest.approx(printed, abs=0.01)


def test_example_1_9_1_exact_column():
    f = S.full_cycle(0.5, -PI)
    assert f.mode == "slip"
    assert f.tau_y1 == pytest.approx(0.1035846, abs=5e-8)
    assert f.tau_m1 == pytest.approx(1.2465561, abs=5e-8)      # printed 1.19 gives 1.0
    assert f.um1 == pytest.approx(0.1706088, abs=5e-8)
    assert f.tau_m2 == pytest.approx(2.4468988, abs=5e-8)
    assert f.um2 == pytest.approx(0.1643832, abs=5e-8)
    assert f.ures == pytest.approx(0.0062257, abs=5e-8)
    b = S.block(0.33, 0.66, 0.6, -PI, full=True, g=9.81)
    assert b.u_m1 == pytest.approx(0.398, abs=5e-4)
    assert b.u_m2 == pytest.approx(0.383, abs=5e-4)
    assert b.u_res == pytest.approx(0.0145, abs=5e-5)
    assert b.t_y1 == pytest.approx(0.6 * 0.1035846, abs=1e-7)


def test_example_1_9_2():
    # tan 30 deg > mu = 0.33: statically unstable; the chapter used |eta1|
    with pytest.raises(InvalidInputError, match=r"^slope_deg = 30.*statically unstable"):
        S.inclined_resistances(0.33, 0.66, 30.0)
    lam = math.radians(30)
    eta1 = 0.5 * (1 - math.tan(lam) / 0.33) / (1 + 0.33 * math.tan(lam))
    eta2 = 0.5 * (1 + math.tan(lam) / 0.33) / (1 - 0.33 * math.tan(lam))
    assert (eta1, eta2) == pytest.approx((-0.3148, 1.6984), abs=5e-5)
    # the exact column of doc/sliding.md section 10 is for the text's rounded eta1 = 0.315
    f = S.full_cycle(0.315, -PI, eta2=eta2)
    assert f.mode == "unilateral" and f.ures == f.um1
    assert f.tau_y1 == pytest.approx(0.0571, abs=5e-5)
    assert f.tau_m1 == pytest.approx(1.4227, abs=5e-5)
    assert f.um1 == pytest.approx(0.31608, abs=5e-6)


def test_stuck_mode_corrected_1_32b():
    # doc/sliding.md Corrections 7: no reverse slide when tau_m1 >= 2 - tau_y(eta2)
    f = S.full_cycle(0.05, 0.4, eta2=0.7)
    assert f.mode == "stuck" and f.um2 == 0 and f.ures == f.um1 and math.isnan(f.tau_y2)
    assert f.tau_m1 >= 2 - S.yield_time(0.7, 0.4)


def test_forced_reverse_stop():
    f = S.full_cycle(0.05, -PI, eta2=0.7)
    assert f.mode == "slip"
    assert f.tau_m2 - 1 == pytest.approx(0.84597, abs=5e-6)
    assert f.um2 == pytest.approx(1.72069e-5, rel=5e-6)


def test_regressions():
    assert S.eta_critical([0.0, PI], method="regression") == pytest.approx([0.4383, 0.2211],
                                                                          abs=5e-5)
    assert S.eta_critical(0.0) == pytest.approx(math.sqrt(2) - 1, rel=1e-13)
    with pytest.warns(UserWarning, match="fitted on"):
        S.eta_critical(20.0, method="regression")
    # Eq. 1.30 against the exact full-cycle slip over V_g t_d (doc/sliding.md section 6)
    from seispulse.pulse import exp_pulse_peaks
    vg = exp_pulse_peaks(0.0).vg
    assert S.full_cycle_peak_regression(0.1, 0.0) == pytest.approx(0.729, abs=5e-4)
    assert S.full_cycle(0.1, 0.0).um1 / vg == pytest.approx(0.7093, abs=5e-5)
    assert S.full_cycle_peak_regression(0.5, -np.inf) == pytest.approx(0.5 ** 1.5)


def test_limit_shapes_match_general_route():
    eta = np.linspace(0.02, 0.98, 49)
    tau_m, um, ratio, vm = S.rectangle_half(eta)
    h = S.half_cycle(eta, -np.inf)
    np.testing.assert_allclose(h.um, um, rtol=1e-13)
    np.testing.assert_allclose(h.um / h.dugm, ratio, rtol=1e-13)
    tau_y, tau_m, um, vm, regime = S.triangle_half(eta)
    h = S.half_cycle(eta, 0.0)
    np.testing.assert_allclose(h.um, um, rtol=1e-11)
    assert list(h.regime) == list(regime)
    f = S.full_cycle(eta, -np.inf)
    np.testing.assert_allclose(f.ures, S.rectangle_full(eta)[4], rtol=1e-12)
    assert S.spike_velocity_ratio(1.0) == 0.0


def test_static_friction_published():
    assert S.half_cycle(0.3, -PI, static_factor=1.2).um == pytest.approx(0.53457, abs=5e-6)
    assert S.half_cycle(0.6, 0.5, static_factor=1.2).um == pytest.approx(0.020987, abs=5e-7)
    # onset at a*eta (1.34), sliding at eta
    assert S.yield_time(0.5, 1.0, static_factor=1.2) == pytest.approx(S.yield_time(0.6, 1.0))
    assert S.half_cycle(0.9, 0.0, static_factor=1.2).regime == "none"


def test_normalization():
    lengths = S.basic_lengths(3.0, 0.7, 0.2, 0.9)
    assert lengths == pytest.approx([3 * 0.81, 0.49 / 3, 0.2, 0.63, 0.14 / 2.7, 0.54 / 0.7])
    assert S.characteristic_length(-1, 2, 0, 0, 3.0, 0.7, 0.2, 0.9) == pytest.approx(0.49 / 3)
    with pytest.raises(InvalidInputError, match=r"^a \+ b \+ c = 2.0: must be 1"):
        S.characteristic_length(1, 1, 0, 3, 1, 1, 1, 1)
    for t in "abcdef":
        e = S.table_1_2(t)
        assert e.shape == (9, 9, 4)
        np.testing.assert_allclose(e[..., 0] + e[..., 1] + e[..., 2], 1.0)
        np.testing.assert_allclose(2 * e[..., 0] + e[..., 1] - e[..., 3], 0.0)
    half, full = S.table_1_3(-PI), S.table_1_3(-PI, full=True)
    k = seispulse.pulse.exp_pulse_peaks(-PI).vg
    assert half == pytest.approx([1, k * k, k / 2, k, k * k / 2, 0.5])
    assert full == pytest.approx([1, k * k, k, k, k * k, 1])


def test_broadcasting_and_scalars():
    h = S.half_cycle([[0.2], [0.4]], [-PI, 0.0, PI])
    assert h.um.shape == (2, 3) and h.regime.shape == (2, 3)
    assert isinstance(S.half_cycle(0.2, 0.0).um, float)
    assert isinstance(S.full_cycle(0.2, 0.0).mode, str)
    none = S.half_cycle(1.5, 0.0)
    assert none.regime == "none" and math.isnan(none.tau_y) and math.isnan(none.tau_m)
    assert (none.um, none.dugm, none.vm) == (0.0, 0.0, 0.0)


@pytest.mark.parametrize("call, pattern", [
    (lambda: S.half_cycle(0.0, 0.0), r"^eta = 0.0: must be > 0"),
    (lambda: S.half_cycle(math.nan, 0.0), r"^eta = NaN"),
    (lambda: S.half_cycle(0.3, math.nan), r"^beta = NaN"),
    (lambda: S.half_cycle(0.3, 0.0, static_factor=0.9), r"^static_factor = 0.9: must be .* >= 1"),
    (lambda: S.full_cycle(0.3, 0.0, eta2=-1), r"^eta2 = -1.0"),
    (lambda: S.full_cycle(0.3, 0.0, static_reverse="yes"), r"^static_reverse"),
    (lambda: S.inclined_resistances(0.3, 0.5, 95.0), r"^slope_deg = 95.0: must be in \[0, 90\)"),
    (lambda: S.inclined_resistances(0.3, -0.5, 5.0), r"^ag_over_g = -0.5"),
    (lambda: S.eta_critical(0.0, method="fit"), r"^method = 'fit': unknown value"),
    (lambda: S.rectangle_half(1.0), r"^eta = 1.0: must satisfy 0 < eta < 1"),
    (lambda: S.table_1_2("g"), r"^table = 'g'"),
    (lambda: S.block(0.3, 0.5, -1.0, 0.0), r"^td = -1.0"),
])
def test_bad_input(call, pattern):
    with pytest.raises(InvalidInputError, match=pattern):
        call()
    assert issubclass(InvalidInputError, ValueError)
