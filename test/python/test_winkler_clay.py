"""seispulse.winkler, inelastic clay: bearing and moment capacity by the formulas typed out,
and the identities of the reduced-order pushover: with no Gaussian correction (a = 0, so
G = 1) and chi <= 0.1 the pushover is the elastic Winkler pushover of the circle with
k = 4 K_R0/(pi r^4), and its secant stiffness the small-angle curve to the order of
theta^2; the Gaussian and the stiffness law evaluated here; the coefficients lost from
[AD11] have no defaults."""
import math

import numpy as np
import pytest

from seispulse import winkler as W
from seispulse.errors import InvalidInputError

NAN = float("nan")
R, H = 1.0, 3.0
SU = 100e3
G_MOD, NU = 180e6 / 2.6, 0.3
NC = math.pi + 3
# chi = 0.05: the elastic range of the stiffness law (k/k_el = 1)
WEIGHT = 0.05 * NC * SU * math.pi * R * R
LOST = dict(kr_c1=NAN, kr_c2=NAN, a_poly=[NAN] * 5, b1=NAN, b2=NAN, c1=NAN, c2=NAN)
NO_G = dict(LOST, a_poly=[0.0] * 5)          # a(chi) = 0: G = 1, b and c not needed


def test_clay_bearing_formulas_and_broadcasting():
    b = W.clay_bearing(SU, R, WEIGHT)
    n_ult = NC * SU * math.pi * R * R
    assert b.n_ult == pytest.approx(n_ult, rel=1e-15)
    assert b.sf == pytest.approx(n_ult / WEIGHT, rel=1e-15)
    assert b.chi == pytest.approx(WEIGHT / n_ult, rel=1e-15)
    v = W.clay_bearing(SU, [0.5, 1.0, 2.0], WEIGHT, nc=6.0)
    np.testing.assert_allclose(v.n_ult, 6.0 * SU * math.pi * np.array([0.25, 1.0, 4.0]),
                               rtol=1e-15)
    assert v.sf.shape == (3,)
    with pytest.raises(InvalidInputError, match="^su "):
        W.clay_bearing(-1.0, R, WEIGHT)
    with pytest.raises(InvalidInputError):
        W.clay_bearing(SU, R, 2 * NC * SU * math.pi)     # SF < 1: vertical failure


def test_moment_capacity_models():
    adsu = math.pi * R * R * 2 * R * SU
    assert W.moment_capacity(SU, R, 0.3) == pytest.approx(0.8 * adsu, rel=1e-15)
    chi = np.array([0.0, 0.25, 0.5, 0.9])
    m = W.moment_capacity(SU, R, chi, model="effective_width")
    np.testing.assert_allclose(m, NC / 2 * chi * (1 - chi) * adsu, rtol=1e-15, atol=0)
    assert m[2] / adsu == pytest.approx(0.768, abs=5e-4)
    with pytest.raises(InvalidInputError, match="^model = 'plastic'"):
        W.moment_capacity(SU, R, 0.3, model="plastic")
    with pytest.raises(InvalidInputError, match="^chi "):
        W.moment_capacity(SU, R, 1.5)


def test_no_correction_is_the_elastic_curve():
    """G = 1, chi <= 0.1: K_R = K_R0 K_sec/K_0 of the Winkler circle at theta/theta_up,
    K_R0 = HK_R k_el, theta_up = asin(W r/(2 K_R0))/2."""
    k_el = 1.14
    p = W.inelastic_pushover(R, H, WEIGHT, G_MOD, NU, SU, np.linspace(0.0, 0.2, 41),
                             k_el=k_el, **NO_G)
    hk_r = 8 * G_MOD * R ** 3 / (3 * (1 - NU))
    assert p.hk_r == pytest.approx(hk_r, rel=1e-15)
    assert p.k_ratio == 1.0 and p.k_r0 == pytest.approx(hk_r * k_el, rel=1e-15)
    assert p.theta_up == pytest.approx(0.5 * math.asin(WEIGHT * R / (2 * hk_r * k_el)),
                                       rel=1e-14)
    assert p.chi == pytest.approx(0.05, rel=1e-14)
    np.testing.assert_allclose(p.g_corr, 1.0, rtol=0, atol=0)
    x = p.theta / p.theta_up
    np.testing.assert_allclose(p.x, x, rtol=1e-14)
    # the small-angle curve, to the order of theta^2 (exact trigonometry against it)
    np.testing.assert_allclose(p.k_r / p.k_r0, W.master_curve(x).k_ratio,
                               rtol=2 * p.theta[-1] ** 2)
    np.testing.assert_allclose(p.m_found, p.k_r * p.theta, rtol=1e-14)
    np.testing.assert_allclose(p.m_imposed, p.m_found - WEIGHT * H * np.sin(p.theta),
                               rtol=1e-12, atol=1e-9 * WEIGHT * R)
    np.testing.assert_allclose(p.force, p.m_imposed / (H * np.cos(p.theta)), rtol=1e-12,
                               atol=1e-9 * WEIGHT)


def test_no_correction_reduces_to_the_elastic_pushover():
    """The same soil as a Winkler circle, k = 4 K_R0/(pi r^4) (= modulus_circle with
    k_el = 1): every moment and the force of the elastic Winkler pushover."""
    th = np.linspace(0.0, 0.4, 41)
    p = W.inelastic_pushover(R, H, WEIGHT, G_MOD, NU, SU, th, **NO_G)
    k = 4 * p.k_r0 / (math.pi * R ** 4)
    assert k == pytest.approx(W.modulus_circle(G_MOD, NU, R), rel=1e-14)
    e = W.winkler_pushover(R, H, WEIGHT, k, theta=th)
    np.testing.assert_allclose(p.m_found, e.m_found, rtol=1e-12)
    np.testing.assert_allclose(p.m_imposed, e.m_imposed, rtol=1e-10, atol=1e-9 * WEIGHT * R)
    np.testing.assert_allclose(p.force, e.force, rtol=1e-10, atol=1e-9 * WEIGHT)
    assert p.theta_overturn == pytest.approx(e.theta_overturn, rel=1e-9)


def test_gaussian_correction_and_stiffness_law():
    """chi = 0.4: k/k_el = c1 - c2 chi; G = 1 + a exp(-(log10 x - b)^2/(2 c^2)) with
    a = sum a_i chi^i, b = b1 ln chi + b2, c = c1 chi + c2."""
    weight = 0.4 * NC * SU * math.pi * R * R
    co = dict(kr_c1=1.1, kr_c2=1.0, a_poly=[0.1, 0.5, 0.0, 0.0, 5.11], b1=0.3, b2=0.8,
              c1=0.2, c2=0.4)
    th = np.geomspace(1e-5, 0.1, 60)
    p = W.inelastic_pushover(R, H, weight, G_MOD, NU, SU, th, **co)
    chi = 0.4
    assert p.chi == pytest.approx(chi, rel=1e-14)
    assert p.k_ratio == pytest.approx(1.1 - chi, rel=1e-14)
    a = 0.1 + 0.5 * chi + 5.11 * chi ** 4
    b = 0.3 * math.log(chi) + 0.8
    c = 0.2 * chi + 0.4
    assert (p.gauss_a, p.gauss_b, p.gauss_c) == pytest.approx((a, b, c), rel=1e-14)
    x = th / p.theta_up
    g = 1 + a * np.exp(-(np.log10(x) - b) ** 2 / (2 * c * c))
    np.testing.assert_allclose(p.g_corr, g, rtol=1e-13)
    # K_R = K_EL/G, K_EL the secant stiffness of the elastic Winkler circle of K_R0
    e = W.winkler_pushover(R, H, weight, 4 * p.k_r0 / (math.pi * R ** 4), theta=th)
    np.testing.assert_allclose(p.k_r, e.m_found / th / g, rtol=1e-12)
    # natural logarithm in G when asked
    q = W.inelastic_pushover(R, H, weight, G_MOD, NU, SU, th, log_base=math.e, **co)
    np.testing.assert_allclose(q.g_corr, 1 + a * np.exp(-(np.log(x) - b) ** 2 / (2 * c * c)),
                               rtol=1e-13)


def test_lost_coefficients_have_no_defaults():
    with pytest.raises(TypeError):
        W.inelastic_pushover(R, H, WEIGHT, G_MOD, NU, SU)       # noqa: the keywords are required
    weight = 0.4 * NC * SU * math.pi * R * R
    with pytest.raises(InvalidInputError, match="^kr_c1"):
        W.inelastic_pushover(R, H, weight, G_MOD, NU, SU, [0.0, 0.01], **NO_G)
    with pytest.raises(InvalidInputError, match="a_poly"):
        W.inelastic_pushover(R, H, WEIGHT, G_MOD, NU, SU, [0.0, 0.01], **LOST)
    with pytest.raises(InvalidInputError, match="^a_poly: must hold the 5"):
        W.inelastic_pushover(R, H, WEIGHT, G_MOD, NU, SU, **dict(NO_G, a_poly=[0.0] * 4))


def test_default_grid_reaches_overturning_and_flags():
    p = W.inelastic_pushover(R, H, WEIGHT, G_MOD, NU, SU, **NO_G)
    assert np.all(np.diff(p.theta) > 0) and p.theta[0] == 0.0
    assert np.isfinite(p.theta_overturn) and p.theta[-1] > p.theta_overturn
    assert p.theta[1] < p.theta_up
    i = np.searchsorted(p.theta, p.theta_overturn)
    assert p.m_imposed[i - 1] > 0 >= p.m_imposed[i]
    # the peaks: refined between grid points, so at or above the largest grid value
    assert np.nanmax(p.m_imposed) <= p.max_moment * (1 + 1e-14)
    assert np.nanmax(p.m_imposed) == pytest.approx(p.max_moment, rel=1e-3)
    assert not p.no_uplift and not p.weak_zone and not p.kr_discontinuous


def test_plot_inelastic_makes_a_figure():
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt
    p = W.inelastic_pushover(R, H, WEIGHT, G_MOD, NU, SU, **NO_G)
    ax_k, ax_m = W.plot_inelastic(p)
    assert ax_k.get_xscale() == "log" and ax_m.get_xlabel() == "theta (rad)"
    plt.close("all")
    with pytest.raises(InvalidInputError, match="^push"):
        W.plot_inelastic("p")


def test_stiffness_ratio_and_gaussian_alone():
    """The two laws of the method by themselves, against the formulas typed out."""
    chi = np.array([0.0, 0.05, 0.1, 0.3, 0.8])
    st = W.stiffness_ratio(chi, kr_c1=1.1, kr_c2=1.0, k_el=1.28)
    ref = np.where(chi <= 0.1, 1.0, 1.1 - chi)
    np.testing.assert_allclose(st.k_ratio, ref, rtol=1e-15)
    np.testing.assert_allclose(st.kappa, 1.28 * ref, rtol=1e-15)
    assert W.stiffness_ratio(0.05, kr_c1=NAN, kr_c2=NAN).k_ratio == 1.0   # not needed below 0.1
    with pytest.raises(InvalidInputError, match="^kr_c1"):
        W.stiffness_ratio(0.3, kr_c1=NAN, kr_c2=NAN)
    co = dict(a_poly=[0.2, 0.0, 1.0, 0.0, 0.0], b1=0.5, b2=-0.2, c1=0.1, c2=0.5)
    x = np.geomspace(1e-3, 1e3, 13)
    g = W.gaussian_correction(0.5, x, **co)
    a, b, c = 0.2 + 0.25, 0.5 * math.log(0.5) - 0.2, 0.55
    np.testing.assert_allclose(g, 1 + a * np.exp(-(np.log10(x) - b) ** 2 / (2 * c * c)),
                               rtol=1e-14)
    assert W.gaussian_correction(0.5, 10 ** b, **co) == pytest.approx(1 + a, rel=1e-14)
    assert W.gaussian_correction(0.5, 0.0, **co) == 1.0
    assert W.gaussian_correction([[0.2], [0.6]], [1.0, 2.0, 3.0], **co).shape == (2, 3)
    with pytest.raises(InvalidInputError, match="^x "):
        W.gaussian_correction(0.5, -1.0, **co)
