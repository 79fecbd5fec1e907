"""seispulse.winkler, statics: rigid footings on tensionless Winkler soil. Every expected
value is computed here independently of the library: the equilibrium of the pressure field
found by a root of its scipy quadrature (the settlement of the base centre that carries the
weight), the foundation moment, contact area and pole by dblquad over the projected
contact, the closed forms of doc/winkler.md typed out, Gazetas' (1991) stiffness formulas,
the small-angle curve table, and the rigid-ground limit of a very stiff soil."""
import math

import numpy as np
import pytest
from scipy import integrate, optimize

from seispulse import cylinder
from seispulse import winkler as W
from seispulse.errors import InvalidInputError

G = 9.80665
QUAD = dict(epsabs=0.0, epsrel=1e-11, limit=200)


# ------------------------------------------------------------------ references

def gazetas(g_mod, nu, width, length):
    """Gazetas (1991) rocking stiffness of a width x length rectangle (width along the
    rocking direction, rotation about the axis along length): K_rx about the long axis,
    K_ry about the short one; B <= L the half-sides, I the moment of the base about the
    axis of rotation."""
    i_base = length * width ** 3 / 12
    big, small = max(width, length) / 2, min(width, length) / 2
    if length >= width:     # rotation about the long axis
        return g_mod / (1 - nu) * i_base ** 0.75 * (big / small) ** 0.25 * (2.4 + 0.5 * small / big)
    return 3 * g_mod / (1 - nu) * i_base ** 0.75 * (big / small) ** 0.15


def width_circle(r, x, cos_t):
    """Full width (m) of the projected circle (an ellipse) at the projected abscissa x."""
    return 2 * math.sqrt(max(r * r - (x / cos_t) ** 2, 0.0))


def equilibrium(footing, r, alpha, weight, k_of_b, theta):
    """The settlement delta0 of the base centre (m, + down) that carries the weight on the
    tensionless springs at the tilt theta, pressure k (delta0 + x tan theta) over the
    projected base (x along the rocking direction, compressed edge at +r cos theta), by a
    root of the quadrature of the normal force; k_of_b(b) the modulus at contact width b.
    Returns (delta0, x0, k) with x0 the projected start of the contact."""
    cos_t, tan_t = math.cos(theta), math.tan(theta)
    x_end = r * cos_t

    def contact(d0):
        x0 = max(-x_end, -d0 / tan_t) if theta > 0 else -x_end
        b = r - x0 / cos_t
        return x0, b

    def normal(d0):
        x0, b = contact(d0)
        if x0 >= x_end:
            return -weight
        k = k_of_b(b)
        w = (lambda x: width_circle(r, x, cos_t)) if footing == "circle" else \
            (lambda x: 2 * alpha)
        n = integrate.quad(lambda x: k * (d0 + x * tan_t) * w(x), x0, x_end, **QUAD)[0]
        return n - weight
    hi = 1.0
    while normal(hi) < 0:
        hi *= 2
    lo = -x_end * tan_t
    d0 = optimize.brentq(normal, lo, hi, xtol=1e-15, rtol=1e-14, maxiter=500)
    x0, b = contact(d0)
    return d0, x0, k_of_b(b)


def field(footing, r, alpha, weight, k_of_b, theta):
    """Normal force N (N), foundation moment M about the base centre (N m), projected
    contact area A (m^2), pole a (centroid of the contact along the base, m), contact width
    b (m), settlement (m) and modulus (N/m^3) by dblquad over the projected contact."""
    d0, x0, k = equilibrium(footing, r, alpha, weight, k_of_b, theta)
    cos_t, tan_t = math.cos(theta), math.tan(theta)
    x_end = r * cos_t
    if footing == "circle":
        lo_y = lambda x: -width_circle(r, x, cos_t) / 2   # noqa: E731
        hi_y = lambda x: width_circle(r, x, cos_t) / 2    # noqa: E731
    else:
        lo_y, hi_y = -alpha, alpha
    def quad2(f, scale):
        """dblquad over the contact, to 1e-10 relative or 1e-13 of the scale of the
        integral (moments of a symmetric full contact cancel)."""
        return integrate.dblquad(f, x0, x_end, lo_y, hi_y, epsabs=1e-13 * scale,
                                 epsrel=1e-10)[0]
    p = lambda y, x: k * (d0 + x * tan_t)                 # noqa: E731
    n = quad2(p, weight)
    m = quad2(lambda y, x: x * p(y, x), weight * r)
    area = quad2(lambda y, x: 1.0, r * r)
    first = quad2(lambda y, x: x / cos_t, r ** 3)
    return dict(n=n, m=m, area=area, pole=first / area, b=r - x0 / cos_t, settlement=d0, k=k)


def phi_circle(r, b):
    """Phi(b) = J1 - c A0 of the circular segment of width b (doc/winkler.md)."""
    c = r - b
    s = math.sqrt(max(2 * r * b - b * b, 0.0))
    return 2 / 3 * s ** 3 + c * c * s - r * r * c * math.acos(c / r)


def moments_circle(r, b):
    """A0, J1, J2 of the circular segment s in [r - b, r] (widths 2 sqrt(r^2 - s^2))."""
    c = r - b
    s = math.sqrt(max(2 * r * b - b * b, 0.0))
    a0 = r * r * math.acos(c / r) - c * s
    j1 = 2 / 3 * s ** 3
    j2 = r ** 4 / 4 * (math.pi / 2 - math.asin(c / r)) - c / 4 * (2 * c * c - r * r) * s
    return a0, j1, j2


# a cylinder of [AD11]'s kind: r = 1 m, h = 3 m, concrete 2.5 t/m^3, on E = 100 MPa soil
R, H = 1.0, 3.0
WEIGHT = 2500.0 * math.pi * R * R * 2 * H * G
G_MOD, NU = 100e6 / (2 * 1.3), 0.3
K = 32 * G_MOD / (3 * math.pi * (1 - NU) * R)


# ------------------------------------------------------------------ stiffness

def test_moduli_closed_forms_and_broadcasting():
    r = np.array([0.5, 1.0, 2.0])
    k_r = W.halfspace_rocking_stiffness(G_MOD, NU, r)
    np.testing.assert_allclose(k_r, 8 * G_MOD * r ** 3 / (3 * (1 - NU)), rtol=1e-15)
    k = W.modulus_circle(G_MOD, NU, r)
    np.testing.assert_allclose(k, 32 * G_MOD / (3 * math.pi * (1 - NU) * r), rtol=1e-15)
    np.testing.assert_allclose(k * math.pi * r ** 4 / 4, k_r, rtol=1e-14)   # k = K_R/I
    assert isinstance(W.modulus_circle(G_MOD, NU, 1.0), float)
    grid = W.modulus_circle(np.array([[1e7], [2e7]]), np.array([0.2, 0.3, 0.4]), 1.0)
    assert grid.shape == (2, 3)
    np.testing.assert_allclose(grid[1, 2], 32 * 2e7 / (3 * math.pi * 0.6), rtol=1e-15)


@pytest.mark.parametrize("width, length", [(2.0, 2.0), (1.0, 3.0), (0.3, 4.0), (3.0, 1.0),
                                           (5.0, 0.5)])
def test_rect_stiffness_is_gazetas(width, length):
    st = W.rect_rocking_stiffness(G_MOD, NU, width, length)
    assert st.k_r == pytest.approx(gazetas(G_MOD, NU, width, length), rel=1e-13)
    assert st.axis == ("long" if length >= width else "short")
    k = W.modulus_rect(G_MOD, NU, width, length)
    assert k == pytest.approx(gazetas(G_MOD, NU, width, length) / (length * width ** 3 / 12),
                              rel=1e-13)


def test_rect_stiffness_vectorized_axis_names():
    st = W.rect_rocking_stiffness(G_MOD, NU, [1.0, 3.0], [2.0, 1.0])
    assert st.axis.tolist() == ["long", "short"]
    assert st.k_r.shape == (2,)


def test_shape_factor_by_definition():
    """k_circle/k_square of the 2r x 2r square, with K_rx (2.9 at L = B) or K_ry (3.0)."""
    i_sq = 16 / 12
    k_circle = 32 / (3 * math.pi)                     # G/(1 - nu) = 1, r = 1
    long = k_circle / (2.9 * i_sq ** 0.75 / i_sq)
    short = k_circle / (3.0 * i_sq ** 0.75 / i_sq)
    assert W.shape_factor() == pytest.approx(long, rel=1e-14)
    assert W.shape_factor("long") == pytest.approx(1.258, abs=5e-4)
    assert W.shape_factor("short") == pytest.approx(short, rel=1e-14)
    assert W.shape_factor("short") == pytest.approx(1.216, abs=5e-4)
    with pytest.raises(InvalidInputError, match="^reading = 'diagonal': unknown"):
        W.shape_factor("diagonal")


def test_varying_modulus_equivalent_rectangle():
    """Circle: the b x chord-through-the-pole rectangle, scaled to k at full contact;
    rectangle: b' x 2 alpha against the 2b x 2alpha footing."""
    b = np.array([2.0, 1.5, 0.6, 0.05])
    kb = W.varying_modulus(b, R, K)
    assert kb[0] == pytest.approx(K, rel=1e-14)
    for bi, ki in zip(b[1:], kb[1:]):
        a0, j1, _ = moments_circle(R, bi)
        pole = j1 / a0
        chord = 2 * math.sqrt(R * R - pole * pole)
        ref = K * W.modulus_rect(1.0, NU, bi, chord) / W.modulus_rect(1.0, NU, 2 * R, 2 * R)
        assert ki == pytest.approx(ref, rel=1e-12)
    alpha = 0.7
    kr = W.varying_modulus([1.4, 1.0, 0.2], 0.7, 2e8, footing="rectangle", alpha=alpha)
    ref = [2e8 * W.modulus_rect(1.0, NU, bb, 2 * alpha) / W.modulus_rect(1.0, NU, 1.4, 2 * alpha)
           for bb in (1.4, 1.0, 0.2)]
    np.testing.assert_allclose(kr, ref, rtol=1e-13)
    with pytest.raises(InvalidInputError, match="^alpha"):
        W.varying_modulus(1.0, 0.7, 2e8, footing="rectangle")
    with pytest.raises(InvalidInputError, match="^footing = 'square'"):
        W.varying_modulus(1.0, 0.7, 2e8, footing="square")


# ------------------------------------------------------------------ pushover: circle

def test_circle_full_contact_closed_forms():
    theta_up = 0.5 * math.asin(2 * WEIGHT / (K * math.pi * R ** 3))
    th = np.linspace(0.0, theta_up, 7)
    p = W.winkler_pushover(R, H, WEIGHT, K, theta=th)
    assert p.theta_up == pytest.approx(theta_up, rel=1e-13)
    assert p.k0 == K and p.footing == "circle" and math.isnan(p.alpha)
    np.testing.assert_array_equal(p.theta, th)
    m = math.pi * K * R ** 4 * np.cos(th) ** 2 * np.sin(th) / 4
    np.testing.assert_allclose(p.m_found, m, rtol=1e-12, atol=1e-9 * WEIGHT * R)
    f = math.pi * K * R ** 4 * np.sin(2 * th) / (8 * H) - WEIGHT * np.tan(th)
    np.testing.assert_allclose(p.force, f, rtol=1e-10, atol=1e-9 * WEIGHT)
    np.testing.assert_allclose(p.m_imposed, m - WEIGHT * H * np.sin(th), rtol=1e-10,
                               atol=1e-9 * WEIGHT * R)
    np.testing.assert_allclose(p.settlement, WEIGHT / (K * math.pi * R * R * np.cos(th)),
                               rtol=1e-13)
    np.testing.assert_allclose(p.area, math.pi * R * R * np.cos(th), rtol=1e-13)
    np.testing.assert_allclose(p.b, 2 * R, rtol=1e-13)
    np.testing.assert_allclose(p.pole, 0.0, atol=1e-12 * R)
    np.testing.assert_allclose(p.k, K, rtol=1e-15)
    # at theta_up the resultant is at the kern, r/4 (small angles): M = W r/4
    assert p.m_found[-1] == pytest.approx(WEIGHT * R / 4 * math.cos(th[-1]), rel=1e-6)


@pytest.mark.parametrize("k_method", ["constant", "varying"])
@pytest.mark.parametrize("ratio", [0.5, 3.0, 30.0, 250.0])
def test_circle_pushover_against_quadrature(k_method, ratio):
    """After uplift: the contact, pressure, moment and settlement of the library against the
    equilibrium of the pressure field found by quadrature."""
    theta_up = 0.5 * math.asin(2 * WEIGHT / (K * math.pi * R ** 3))
    theta = ratio * theta_up
    p = W.winkler_pushover(R, H, WEIGHT, K, k_method=k_method, theta=[theta])
    def k_of_b(b):
        return K if k_method == "constant" else W.varying_modulus(min(b, 2 * R), R, K)
    ref = field("circle", R, 0.0, WEIGHT, k_of_b, theta)
    assert ref["n"] == pytest.approx(WEIGHT, rel=1e-9)
    assert p.m_found[0] == pytest.approx(ref["m"], rel=1e-8)
    assert p.settlement[0] == pytest.approx(ref["settlement"], rel=1e-8, abs=1e-12 * R)
    assert p.area[0] == pytest.approx(ref["area"], rel=1e-8)
    assert p.b[0] == pytest.approx(ref["b"], rel=1e-8)
    assert p.pole[0] == pytest.approx(ref["pole"], rel=1e-7, abs=1e-12 * R)
    assert p.k[0] == pytest.approx(ref["k"], rel=1e-8)
    m_imp = ref["m"] - WEIGHT * H * math.sin(theta)
    assert p.m_imposed[0] == pytest.approx(m_imp, rel=1e-7, abs=1e-9 * WEIGHT * R)
    assert p.force[0] == pytest.approx(m_imp / (H * math.cos(theta)), rel=1e-7,
                                       abs=1e-9 * WEIGHT)


def test_circle_after_uplift_closed_forms():
    """theta(b) = asin(2 W/(k Phi(b)))/2 and M = k sin cos^2 (J2 - c J1), pole = J1/A0,
    area A0 cos, settlement -(r - b) sin, at chosen contact widths."""
    bs = np.array([1.9, 1.3, 0.8, 0.3])
    th = np.array([0.5 * math.asin(2 * WEIGHT / (K * phi_circle(R, b))) for b in bs])
    p = W.winkler_pushover(R, H, WEIGHT, K, theta=th)
    for i, b in enumerate(bs):
        a0, j1, j2 = moments_circle(R, b)
        c = R - b
        t = th[i]
        assert p.b[i] == pytest.approx(b, rel=1e-10)
        assert p.m_found[i] == pytest.approx(K * math.sin(t) * math.cos(t) ** 2 * (j2 - c * j1),
                                             rel=1e-10)
        assert p.pole[i] == pytest.approx(j1 / a0, rel=1e-10)
        assert p.area[i] == pytest.approx(a0 * math.cos(t), rel=1e-10)
        assert p.settlement[i] == pytest.approx(-(R - b) * math.sin(t), rel=1e-9,
                                                abs=1e-14)


def overturning_constant_k(r, h, weight, k):
    """The overturning angle of the constant-k circle: k cos^2 (J2 - c J1) = W h on the
    branch theta(b), by a root in b."""
    def m_imp(b):
        t = 0.5 * math.asin(min(1.0, 2 * weight / (k * phi_circle(r, b))))
        _, j1, j2 = moments_circle(r, b)
        return k * math.cos(t) ** 2 * (j2 - (r - b) * j1) - weight * h
    b_min = optimize.brentq(lambda b: k * phi_circle(r, b) - 2 * weight, 1e-9, 2 * r)
    b = optimize.brentq(m_imp, b_min * (1 + 1e-12), 2 * r, xtol=1e-15)
    return 0.5 * math.asin(2 * weight / (k * phi_circle(r, b)))


def test_circle_scalars():
    p = W.winkler_pushover(R, H, WEIGHT, K)
    assert p.theta_overturn == pytest.approx(overturning_constant_k(R, H, WEIGHT, K), rel=1e-9)
    assert p.theta[0] == 0.0 and p.theta[-1] == pytest.approx(p.theta_end, rel=1e-15)
    assert p.theta_overturn < p.theta_end <= math.pi / 4   # constant k: the end is pi/4
    # the peaks: the largest on the curve can only be below, and close
    f = p.force / WEIGHT
    assert np.nanmax(f) <= p.max_force_over_weight * (1 + 1e-12)
    assert np.nanmax(f) == pytest.approx(p.max_force_over_weight, rel=2e-3)
    assert np.nanmax(p.m_imposed) <= p.max_moment * (1 + 1e-12)
    ref = optimize.minimize_scalar(
        lambda t: -W.winkler_pushover(R, H, WEIGHT, K, theta=[t]).force[0],
        bounds=(p.theta_up, p.theta_overturn), method="bounded",
        options=dict(xatol=1e-12))
    assert p.max_force_over_weight == pytest.approx(-ref.fun / WEIGHT, rel=1e-8)
    assert p.theta_at_max == pytest.approx(ref.x, rel=1e-3)


def test_small_angle_curve_table():
    """The universal curve of the constant-k circle at theta/theta_up = 1, 2, 3, 5, 10, 100:
    b/(2r), a/r, K_sec/K_0, M/(W r) to the 4 decimals of the table computed from the
    parametric form theta/theta_up = pi r^3/Phi(b), K_sec/K_0 = (J2 - c J1)/I."""
    table = np.array([[1, 1.0, 0.0, 1.0, 0.25],
                      [2, 0.7246, 0.1950, 0.8441, 0.4220],
                      [3, 0.6067, 0.3117, 0.6770, 0.5078],
                      [5, 0.4876, 0.4378, 0.4790, 0.5987],
                      [10, 0.3646, 0.5741, 0.2785, 0.6962],
                      [100, 0.1420, 0.8311, 0.0352, 0.8795]])
    mc = W.master_curve(table[:, 0])
    np.testing.assert_allclose(mc.b_ratio, table[:, 1], atol=5.01e-5)
    np.testing.assert_allclose(mc.a_ratio, table[:, 2], atol=5.01e-5)
    np.testing.assert_allclose(mc.k_ratio, table[:, 3], atol=5.01e-5)
    np.testing.assert_allclose(mc.m_ratio, table[:, 4], atol=5.01e-5)
    # the parametric form itself, at chosen widths
    for b in (1.7, 0.9, 0.2):
        x = math.pi / phi_circle(1.0, b)
        _, j1, j2 = moments_circle(1.0, b)
        one = W.master_curve(x)
        assert one.b_ratio == pytest.approx(b / 2, rel=1e-10)
        assert one.k_ratio == pytest.approx((j2 - (1 - b) * j1) / (math.pi / 4), rel=1e-10)
        assert one.m_ratio == pytest.approx(one.k_ratio * x / 4, rel=1e-12)
    # full contact and the asymptotes K/K0 -> 4/x, M -> W r (slowly: 1 - M/(W r) ~ x^(-2/5),
    # the contact b ~ Phi^(2/5) of a sliver)
    np.testing.assert_allclose(W.master_curve([0.0, 0.5]).m_ratio, [0.0, 0.125], rtol=1e-15)
    x = np.array([1e6, 1e9, 1e12])
    far = W.master_curve(x)
    gap = 1 - far.m_ratio
    assert np.all(gap > 0) and gap[-1] < 2e-5
    np.testing.assert_allclose(gap[1:] / gap[:-1], 1e-3 ** 0.4, rtol=0.02)
    np.testing.assert_allclose(far.k_ratio * x / 4, far.m_ratio, rtol=1e-12)


def test_small_angle_curve_rectangle():
    """Rectangle: full contact M/(W b) = x/3; after uplift (small angles: theta_up =
    W/(4 alpha b^2 k), theta = W/(alpha b'^2 k)) b'/(2b) = 1/sqrt(x) and M/(W b) = 1 - b'/(3 b)
    = 1 - 2/(3 sqrt(x)) (the resultant at b'/3 from the edge)."""
    x = np.array([0.5, 1.0, 2.0, 7.0])
    mc = W.master_curve(x, footing="rectangle")
    np.testing.assert_allclose(mc.m_ratio[:2], x[:2] / 3, rtol=1e-14)
    np.testing.assert_allclose(mc.b_ratio[2:], 1 / np.sqrt(x[2:]), rtol=1e-12)
    np.testing.assert_allclose(mc.m_ratio[2:], 1 - 2 / (3 * np.sqrt(x[2:])), rtol=1e-12)
    np.testing.assert_allclose(mc.k_ratio, mc.m_ratio / (x / 3), rtol=1e-12)
    assert mc.k_ratio.shape == (4,)
    with pytest.raises(InvalidInputError, match=r"^x\[1\] = -1\.0"):
        W.master_curve([1.0, -1.0])


def test_rigid_limit_of_a_stiff_soil():
    """k -> inf: the imposed moment tends to the rigid-ground W R sin(theta_c - theta) and
    the overturning angle to theta_c = atan(r/h); the gap closes as the contact sliver b ~
    (W/k)^(2/5) does."""
    body = cylinder.props(R, H, mass=WEIGHT / G)
    th = np.linspace(0.02, 0.9 * body.theta_c, 9)
    rigid = cylinder.rigid_pushover(th, R, H, mass=WEIGHT / G)
    gaps = []
    for k in (1e6 * K, 1e8 * K):
        p = W.winkler_pushover(R, H, WEIGHT, k, theta=th)
        gap = np.max(np.abs(p.m_imposed - rigid.M)) / (WEIGHT * R)
        assert gap < 1e-3
        assert p.theta_overturn == pytest.approx(body.theta_c, rel=2e-3)
        assert np.all(p.b / (2 * R) < 1e-3)
        gaps.append(gap)
    assert gaps[1] / gaps[0] == pytest.approx(1e-2 ** 0.4, rel=0.1)


# ------------------------------------------------------------------ pushover: block

B, ALPHA, HB = 0.8, 1.2, 2.5
WB = 3.0e5
KB = 4.0e8


def test_block_closed_forms():
    theta_up = 0.5 * math.asin(WB / (2 * ALPHA * B * B * KB))
    bp = np.array([1.5, 1.0, 0.4])
    th_after = 0.5 * np.arcsin(2 * WB / (ALPHA * bp ** 2 * KB))
    th = np.concatenate([np.linspace(0, theta_up, 4), th_after])
    p = W.block_winkler_pushover(B, ALPHA, HB, WB, KB, theta=th)
    assert p.footing == "rectangle" and p.r == B and p.alpha == ALPHA
    assert p.theta_up == pytest.approx(theta_up, rel=1e-13)
    t = th[:4]
    np.testing.assert_allclose(p.m_found[:4], 4 / 3 * ALPHA * B ** 3 * KB * np.cos(t) ** 2
                               * np.sin(t), rtol=1e-12, atol=1e-9 * WB * B)
    np.testing.assert_allclose(p.force[:4], 2 * ALPHA * B ** 3 * KB * np.sin(2 * t) / (3 * HB)
                               - WB * np.tan(t), rtol=1e-9, atol=1e-9 * WB)
    np.testing.assert_allclose(p.b[4:], bp, rtol=1e-12)
    c = B - bp
    t = th_after
    m = 2 * ALPHA * KB * np.sin(t) * np.cos(t) ** 2 * ((B ** 3 - c ** 3) / 3
                                                      - c * (B * B - c * c) / 2)
    np.testing.assert_allclose(p.m_found[4:], m, rtol=1e-11)
    np.testing.assert_allclose(p.pole[4:], B - bp / 2, rtol=1e-12)
    np.testing.assert_allclose(p.area[4:], 2 * ALPHA * bp * np.cos(t), rtol=1e-12)


@pytest.mark.parametrize("k_method", ["constant", "varying"])
@pytest.mark.parametrize("ratio", [0.7, 4.0, 60.0])
def test_block_pushover_against_quadrature(k_method, ratio):
    theta_up = 0.5 * math.asin(WB / (2 * ALPHA * B * B * KB))
    theta = ratio * theta_up
    p = W.block_winkler_pushover(B, ALPHA, HB, WB, KB, k_method=k_method, theta=[theta])
    def k_of_b(b):
        if k_method == "constant":
            return KB
        return W.varying_modulus(min(b, 2 * B), B, KB, footing="rectangle", alpha=ALPHA)
    ref = field("rectangle", B, ALPHA, WB, k_of_b, theta)
    assert p.m_found[0] == pytest.approx(ref["m"], rel=1e-8)
    assert p.settlement[0] == pytest.approx(ref["settlement"], rel=1e-8, abs=1e-12)
    assert p.b[0] == pytest.approx(ref["b"], rel=1e-8)
    assert p.area[0] == pytest.approx(ref["area"], rel=1e-8)
    assert p.pole[0] == pytest.approx(ref["pole"], rel=1e-7, abs=1e-12)
    assert p.k[0] == pytest.approx(ref["k"], rel=1e-8)


def test_block_rigid_limit_and_overturning():
    body = cylinder.block_props(B, HB, mass=WB / G)
    p = W.block_winkler_pushover(B, ALPHA, HB, WB, 1e6 * KB)
    assert p.theta_overturn == pytest.approx(body.theta_c, rel=1e-3)
    # constant k: M_imp = 0 where 2 alpha k cos^2 [(b^3 - c^3)/3 - c (b^2 - c^2)/2] = W h
    q = W.block_winkler_pushover(B, ALPHA, HB, WB, KB)

    def m_imp(bp):
        t = 0.5 * math.asin(2 * WB / (ALPHA * bp * bp * KB))
        c = B - bp
        return 2 * ALPHA * KB * math.cos(t) ** 2 * ((B ** 3 - c ** 3) / 3
                                                   - c * (B * B - c * c) / 2) - WB * HB
    bp = optimize.brentq(m_imp, math.sqrt(2 * WB / (ALPHA * KB)) * (1 + 1e-12), 2 * B,
                         xtol=1e-15)
    assert q.theta_overturn == pytest.approx(0.5 * math.asin(2 * WB / (ALPHA * bp * bp * KB)),
                                             rel=1e-9)


def test_equivalent_cylinder_same_p_and_peak():
    block = cylinder.block_props(B, HB, mass=WB / G)
    cyl = W.equivalent_cylinder(block, ALPHA, KB)
    assert cyl.shape == "solid_cylinder"
    assert cyl.p == pytest.approx(block.p, rel=1e-10)
    assert cyl.theta_c == pytest.approx(block.theta_c, rel=1e-10)
    peak_b = W.block_winkler_pushover(B, ALPHA, HB, block.weight, KB).max_moment
    peak_c = W.winkler_pushover(cyl.r, cyl.h, cyl.weight, KB).max_moment
    assert peak_c == pytest.approx(peak_b, rel=1e-8)
    other = W.equivalent_cylinder(block, ALPHA, KB, theta_c=0.25)
    assert other.theta_c == pytest.approx(0.25, rel=1e-12)
    with pytest.raises(InvalidInputError, match="^block"):
        W.equivalent_cylinder(cyl, ALPHA, KB)


# ------------------------------------------------------------------ errors and shapes

def test_errors_name_the_parameter():
    with pytest.raises(InvalidInputError, match="^r "):
        W.winkler_pushover(-1.0, H, WEIGHT, K)
    with pytest.raises(InvalidInputError, match="^k "):
        W.winkler_pushover(R, H, WEIGHT, 0.0)
    with pytest.raises(InvalidInputError, match="^k_method = 'linear': unknown"):
        W.winkler_pushover(R, H, WEIGHT, K, k_method="linear")
    with pytest.raises(InvalidInputError, match="^theta: must be a 1-d"):
        W.winkler_pushover(R, H, WEIGHT, K, theta=np.zeros((2, 2)))
    with pytest.raises(InvalidInputError, match="^n = 1"):
        W.winkler_pushover(R, H, WEIGHT, K, n=1)
    with pytest.raises(InvalidInputError, match="^alpha "):
        W.block_winkler_pushover(B, -ALPHA, HB, WB, KB)
    with pytest.raises(InvalidInputError, match="^nu "):
        W.modulus_circle(G_MOD, 0.5, R)
    with pytest.raises(InvalidInputError, match="^g_mod "):
        W.halfspace_rocking_stiffness([G_MOD, -1.0], NU, R)
    with pytest.raises(InvalidInputError, match="shapes do not broadcast"):
        W.modulus_rect([1e7, 2e7], NU, [1.0, 2.0, 3.0], 1.0)
    with pytest.raises(InvalidInputError, match="^width "):
        W.rect_rocking_stiffness(G_MOD, NU, 0.0, 1.0)


def test_default_grid_and_names():
    p = W.winkler_pushover(R, H, WEIGHT, K, n=50)
    assert 45 <= p.theta.size <= 50
    assert np.all(np.diff(p.theta) > 0)
    assert p.theta[1] < p.theta_up        # the geometric half resolves the small angles
    for name in ("b", "pole", "area", "settlement", "k", "m_found", "m_imposed", "force"):
        assert getattr(p, name).shape == p.theta.shape
    beyond = W.winkler_pushover(R, H, WEIGHT, K, theta=[0.1, p.theta_end * 1.01])
    assert np.isnan(beyond.m_found[1]) and np.isnan(beyond.force[1])
    assert beyond.theta[1] == p.theta_end * 1.01


def test_plot_pushover_makes_a_figure():
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt
    p = W.winkler_pushover(R, H, WEIGHT, K, k_method="varying")
    ax_f, ax_m = W.plot_pushover(p, title="circle")
    labels = [line.get_label() for line in ax_f.get_lines()]
    assert "rigid ground" in labels and any("uplift" in s for s in labels)
    rigid = [line for line in ax_m.get_lines() if line.get_label() == "rigid ground"][0]
    body = cylinder.props(R, H, mass=WEIGHT / G)
    assert rigid.get_ydata()[0] == pytest.approx(body.M_max, rel=1e-12)
    q = W.block_winkler_pushover(B, ALPHA, HB, WB, KB)
    W.plot_pushover(q, rigid=False)
    plt.close("all")
    with pytest.raises(InvalidInputError, match="^push"):
        W.plot_pushover("not a pushover")


def readme_blocks(source_root):
    """The python code blocks of the README's `seispulse.winkler` section, in order."""
    text = (source_root / "README.md").read_text(encoding="utf-8")
    start = text.index("\n## Winkler foundations: Python (`seispulse.winkler`)\n")
    section = text[start:text.index("\n## ", start + 1)]
    return [block.split("\n```\n")[0] for block in section.split("```python\n")[1:]]


def test_readme_examples_run(source_root):
    """The examples of the README's seispulse.winkler section run and print what their
    comments say."""
    mpl = pytest.importorskip("matplotlib")
    mpl.use("Agg")
    import matplotlib.pyplot as plt
    ns = {}
    for i, code in enumerate(readme_blocks(source_root)):
        exec(compile(code, f"README.md (seispulse.winkler, block {i + 1})", "exec"), ns)
    plt.close("all")
    assert f"{ns['k']:.4g}" == "1.866e+08" and f"{ns['const'].theta_up:.4g}" == "0.0007885"
    assert (round(ns["const"].max_force_over_weight, 4), round(ns["const"].theta_overturn, 4)) \
        == (0.2446, 0.2999)
    assert (round(ns["vary"].max_force_over_weight, 4), round(ns["vary"].theta_overturn, 4)) \
        == (0.2833, 0.3172)
    assert round(ns["body"].theta_c, 4) == 0.3218
    assert (round(ns["bp"].theta_overturn, 4), round(ns["bp"].max_moment)) == (0.2361, 77895)
    cyl = ns["cyl"]
    assert (round(cyl.r, 4), round(cyl.h, 3), round(cyl.mass)) == (0.5018, 2.007, 26278)
    assert round(ns["mdl"].c) == 69925
    run = ns["run"]
    assert (run.outcome, round(run.theta_max, 5), run.n_impacts) == ("safe", 0.03554, 4)
    assert round(run.impact_normal_peak[0]) == 810418 and round(ns["body"].weight) == 462127
    assert round(ns["run_rec"].theta_max, 5) == 0.03553
    assert np.bincount(ns["wmap"].difference.ravel(), minlength=4).tolist() == [36, 5, 0, 1]
    bear = ns["bear"]
    assert (round(bear.sf, 3), round(bear.chi, 4)) == (4.175, 0.2395)
    inel = ns["inel"]
    assert (round(inel.k_ratio, 4), f"{inel.theta_up:.4g}", round(inel.theta_overturn, 4)) \
        == (0.8605, "0.0005091", 0.3035)
