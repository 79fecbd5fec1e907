"""seispulse.walls.comparison / pressure_profile (Fortran seispulse_wall_table) and the
batch driver's analysis 'walls': the rows against closed forms and the published
Mononobe-Okabe check, the profiles against their resultants, bad input, and the driver's
one-line errors. The full tables are checked against independent mpmath references by
the regression cases test/regression/walls_*."""
import math
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest
from mpmath import mp

from seispulse import walls
from seispulse.errors import InvalidInputError, NoSolutionError

HERE = Path(__file__).resolve().parent
INPUT = HERE.parents[1] / "input"


def psi_sigma(nu):
    return 2.0 / math.sqrt((1.0 - nu) * (2.0 - nu))


def test_published_check_and_closed_forms_in_the_table():
    H, gamma, kh, kv, a_s, nu = 6.0, 20.0, 0.24, 0.12, 0.3, 0.3
    t = walls.comparison(H, gamma, 30.0, kh, kv, a_s, nu=nu)
    assert t.method == walls.COMPARISON_ROWS
    # M-O: kv = -0.12 is the critical sign; K = 0.4856177257638489 (xc / eurocodeapplied)
    assert t.kv_used == -0.12
    np.testing.assert_allclose(t.thrust[1], 0.5 * gamma * 1.12 * 0.4856177257638489 * H**2,
                               rtol=1e-13)
    np.testing.assert_allclose(t.thrust[0], 0.5 * gamma * H**2 / 3, rtol=1e-13)   # Rankine
    np.testing.assert_allclose(t.z[0], H / 3, rtol=1e-15)
    np.testing.assert_allclose(t.thrust[2], t.thrust[1] - t.thrust[0], rtol=1e-13)
    np.testing.assert_allclose(t.z[2], H / 2, rtol=1e-15)
    np.testing.assert_allclose(t.z[1], (t.thrust[0] * H / 3 + t.thrust[2] * H / 2) / t.thrust[1],
                               rtol=1e-13)
    np.testing.assert_allclose([t.thrust[3], t.z[3]], [0.375 * kh * gamma * H**2, 0.6 * H],
                               rtol=1e-14)
    np.testing.assert_allclose([t.thrust[4], t.z[4]], [a_s * gamma * H**2, 0.6 * H], rtol=1e-14)
    np.testing.assert_allclose([t.thrust[5], t.z[5]], [a_s * gamma * H**2, 0.5 * H], rtol=1e-14)
    # Veletsos-Younan static: 14 zeta(3)/pi^3 psi_sigma at (2/pi) beta(4)/lambda(3) H
    lam3 = 7 / 8 * float(mp.zeta(3))
    beta4 = float((mp.zeta(4, 0.25) - mp.zeta(4, 0.75)) / 256)
    np.testing.assert_allclose(t.thrust[6], 16 / math.pi**3 * lam3 * psi_sigma(nu)
                               * a_s * gamma * H**2, rtol=1e-12)
    np.testing.assert_allclose(t.z[6] / H, 2 / math.pi * beta4 / lam3, rtol=1e-12)
    assert abs(t.z[6] / H - 0.59858) < 5e-6
    # one-term, sine: 16/pi^3 psi_sigma at 2H/pi (Eq. 2.51)
    np.testing.assert_allclose(t.thrust[7], 16 / math.pi**3 * psi_sigma(nu) * a_s * gamma * H**2,
                               rtol=1e-13)
    np.testing.assert_allclose(t.z[7], 2 * H / math.pi, rtol=1e-14)
    np.testing.assert_allclose(t.moment, t.thrust * t.z, rtol=1e-15)


def test_alpha_s_defaults_to_kh_and_elastic_rows_follow_the_routines():
    t = walls.comparison(5.0, 18.0, 35.0, 0.2, 0.1, nu=0.35, delta=0.1, omega_ratio=0.8,
                         n=0.5, d_theta=0.5)
    np.testing.assert_allclose(t.thrust[4], 0.2 * 18.0 * 25.0, rtol=1e-14)
    vy = walls.vy_rigid(0.8, 0.1, 0.35, tol=1e-13)
    np.testing.assert_allclose(t.thrust[6], abs(vy.q) * 0.2 * 18.0 * 25.0, rtol=1e-12)
    ot = walls.one_term(0.8, 0.1, 0.35, n=0.5, d_theta=0.5)
    np.testing.assert_allclose(t.thrust[7], abs(ot.q) * 0.2 * 18.0 * 25.0, rtol=1e-14)
    np.testing.assert_allclose(t.z[7], (5 + 0.5) / (4 * 2.5) * 5.0, rtol=1e-14)   # (5+n)/(4(2+n))


def test_pressure_profile_resultants():
    H, gamma, kh = 8.0, 19.0, 0.25
    depth = np.linspace(0.0, H, 4001)
    w = np.full(depth.size, depth[1] - depth[0])
    w[[0, -1]] /= 2                                     # trapezoid: error ~ h^2 log h, < 1e-7
    # static: every pressure is real and positive, so each column integrates to its thrust
    pr = walls.pressure_profile(depth, H, gamma, 32.0, kh, 0.1, 0.3)
    t = walls.comparison(H, gamma, 32.0, kh, 0.1, 0.3)
    np.testing.assert_allclose(w @ pr.static, t.thrust[0], rtol=1e-12)
    np.testing.assert_allclose(w @ pr.mo_dynamic, t.thrust[2], rtol=1e-12)
    np.testing.assert_allclose(w @ pr.ec8_rigid, t.thrust[5], rtol=1e-12)
    np.testing.assert_allclose(w @ pr.vy, t.thrust[6], rtol=2e-7)
    np.testing.assert_allclose(w @ pr.one_term, t.thrust[7], rtol=2e-7)
    # dynamic: the one-term pressure keeps one phase along the wall (exact again); the
    # Veletsos-Younan phase varies with depth, so |p| integrates to more than |Q|
    pr = walls.pressure_profile(depth, H, gamma, 32.0, kh, 0.1, 0.3, omega_ratio=0.6)
    t = walls.comparison(H, gamma, 32.0, kh, 0.1, 0.3, omega_ratio=0.6)
    np.testing.assert_allclose(w @ pr.one_term, t.thrust[7], rtol=2e-7)
    assert w @ pr.vy > t.thrust[6] * (1 + 1e-6)
    assert pr.vy[0] > 0 and pr.vy[-1] == 0.0 and pr.one_term[-1] == 0.0


def test_bad_input_names_the_parameter():
    with pytest.raises(NoSolutionError, match="beta"):
        walls.comparison(6.0, 20.0, 30.0, 0.3, 0.0, beta_deg=25.0)
    with pytest.raises(InvalidInputError, match="height"):
        walls.comparison(-1.0, 20.0, 30.0, 0.2)
    with pytest.raises(InvalidInputError, match="gamma"):
        walls.comparison(6.0, 0.0, 30.0, 0.2)
    with pytest.raises(InvalidInputError, match="nu"):
        walls.comparison(6.0, 20.0, 30.0, 0.2, nu=0.5)
    with pytest.raises(InvalidInputError, match="kv"):
        walls.comparison(6.0, 20.0, 30.0, 0.2, kv=1.0)
    with pytest.raises(InvalidInputError, match="water"):
        walls.comparison(6.0, 20.0, 30.0, 0.2, water="wet")
    with pytest.raises(InvalidInputError, match=r"depth\(2\)"):
        walls.pressure_profile([0.0, 7.0], 6.0, 20.0, 30.0, 0.2)


# ---------------------------------------------------------------- driver

def run(driver, cwd, text):
    (Path(cwd) / "case.nml").write_text(text)
    return subprocess.run([driver, "case.nml"], cwd=cwd, capture_output=True, text=True,
                          timeout=120)


def read_csv(path):
    import csv
    with open(path, newline="") as f:
        header = next(csv.reader(f))
        rows = list(csv.reader(f, quoting=csv.QUOTE_NONNUMERIC))
    return header, rows


def test_example_input(driver, tmp_path):
    proc = subprocess.run([driver, str(INPUT / "walls.nml")], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    header, rows = read_csv(tmp_path / "out" / "walls.csv")
    assert header == ["method (-)", "thrust (kN/m)", "z (m)", "z/H (-)", "moment (kNm/m)"]
    assert [r[0] for r in rows] == list(walls.COMPARISON_ROWS)
    # EN 1998: ag = 0.24 g, ground B type 1 (S = 1.2), r = 1: kh = 0.288, kv = 0.144
    t = walls.comparison(6.0, 20.0, 32.0, 0.288, 0.144, 0.288, nu=0.3, delta=0.1)
    np.testing.assert_allclose([r[1] for r in rows], t.thrust, rtol=1e-14)
    header, rows = read_csv(tmp_path / "out" / "walls_pressure.csv")
    assert header == ["depth (m)", "static (kPa)", "mo_dyn (kPa)", "ec8_rigid (kPa)", "vy (kPa)",
                      "one_term (kPa)"]
    assert len(rows) == 21


@pytest.mark.parametrize("group,keys", [
    ("wall", ["height", "psi_deg", "wall_friction_deg", "k_rotation", "d_theta", "spacing"]),
    ("backfill", ["gamma", "phi_deg", "beta_deg", "gamma_phi", "nu", "damping_ratio",
                  "loss_factor", "vs", "g_modulus", "stiffness_exponent", "shape", "water",
                  "gamma_w", "gamma_d", "frequency"]),
    ("seismic", ["code", "agr", "importance", "ground", "spectrum_type", "soil_factor", "r",
                 "wall_type", "kh", "kv", "alpha_s", "npoints"])])
def test_every_key_is_in_the_example(group, keys):
    text = (INPUT / "walls.nml").read_text()
    for key in keys:
        assert re.search(rf"\b{key}\b", text), key


BASE = {"wall": "height = 6.0", "backfill": "gamma = 20.0, phi_deg = 30.0",
        "seismic": "code = 'direct', kh = 0.2"}


def case(**groups):
    g = dict(BASE)
    g.update(groups)
    text = "&run analysis = 'walls', output = 'out/w' /\n"
    return text + "".join(f"&{k} {v} /\n" for k, v in g.items() if v is not None)


@pytest.mark.parametrize("groups,pattern", [
    (dict(seismic="code = 'EAK', kh = 0.2"),
     r"&seismic: code = 'EAK': not available: the retaining-wall clause of EAK 2000 could "
     r"not be found .*code = 'direct' with kh, kv"),
    (dict(seismic="code = 'EC8', agr = 0.2, ground = 'F'"), r"ground = 'F'"),
    (dict(seismic="code = 'EC8', agr = 0.2, ground = 'B', kh = 0.1"), r"kh, kv, alpha_s"),
    (dict(seismic="code = 'direct', kh = 0.2, kv = 1.0"), r"kv = 1.0"),
    (dict(wall="height = -2.0"), r"height = -2.0"),
    (dict(wall=None), r"&wall: missing group"),
    (dict(wall="height = 6.0, k_rotation = 1e5"), r"g_modulus: missing"),
    (dict(backfill="gamma = 20.0, phi_deg = 30.0, frequency = 2.0"), r"vs: missing"),
    (dict(backfill="gamma = 20.0, phi_deg = 30.0, nu = 0.5"), r"nu = 0.5"),
    (dict(backfill="gamma = 20.0, phi_deg = 95.0"), r"phi"),
    (dict(backfill="gamma = 20.0, phi_deg = 30.0, beta_deg = 25.0",
          seismic="code = 'direct', kh = 0.3"), r"beta"),
    (dict(backfill="gamma = 20.0, phi_deg = 30.0, water = 'permeable'"), r"gamma_d: missing"),
    (dict(backfill="gamma = 20.0, phi_deg = 30.0, damping = 0.05"), r"damping"),
    # undamped, at omega_1 = pi Vs/(2H) exactly (2 pi f = pi 100/12): a resonance
    (dict(backfill="gamma = 20.0, phi_deg = 30.0, loss_factor = 0.0, vs = 100.0, "
                   "frequency = 4.166666666666667"), r"&backfill: frequency = .*resonance"),
])
def test_driver_errors_one_line_exit_2_no_output(driver, tmp_path, groups, pattern):
    proc = run(driver, tmp_path, case(**groups))
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("seispulse: error: case.nml"), proc.stderr
    assert re.search(pattern, lines[0]), lines[0]
    assert not list(tmp_path.glob("out/*")), "no output on error"
