"""Batch driver, analysis 'spectra': the code spectra table against seispulse.codes'
Python functions value for value (the CSV is round-trip exact, so compared exactly); the
record-suite check against an independent numpy computation of EN 1998-1 3.2.3.1.2(4)
from seispulse.sdof.spectrum (and against codes.check_record_suite); records_from; a
record that cannot be read; every input error (exit status 2, one located line, no
output). The regression case test/regression/spectra_codes checks the code spectra
against mpmath."""
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from driver_tables import read_summary_txt, read_table
from seispulse import codes, records, sdof

HERE = Path(__file__).resolve().parent
RECORDS = HERE.parent / "regression" / "records"
INPUT = HERE.parents[1] / "input"
FORM = re.compile(r"^seispulse: error: (?P<file>[^:\s]+):(?P<line>[1-9]\d*): "
                  r"&(?P<group>[a-z_0-9]+): (?P<rest>\S.*)$")

#: The records of the suite tests (files of test/regression/records, read as they are).
SUITE_FILES = ["records/quake_a.AT2", "records/quake_b.csv", "records/quake_d.dat"]


def run(driver, cwd, text, name="case.nml"):
    (Path(cwd) / name).write_text(text)
    return subprocess.run([driver, name], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def with_records(tmp_path):
    shutil.copytree(RECORDS, tmp_path / "records")


def exact(column, expected):
    """Every value equal, bit for bit (the CSV is round-trip exact)."""
    expected = np.asarray(expected, dtype=float)
    assert column.shape == expected.shape
    bad = np.flatnonzero(column != expected)
    assert bad.size == 0, (bad[:5], column[bad[:5]], expected[bad[:5]])


# ---------------------------------------------------------------------------
# the code spectra
# ---------------------------------------------------------------------------

def test_example_spectra_equal_python(driver, tmp_path):
    """input/spectra.nml: EN 1998-1 types 1 and 2 in zone Z2 of the Greek NA, ground B,
    and EAK 2000 zone Z2 ground B, elastic and design, equal to seispulse.codes."""
    proc = subprocess.run([driver, str(INPUT / "spectra.nml")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    t = read_table(tmp_path / "out" / "code_spectra.csv")
    assert list(t) == ["period", "ec8_1_elastic", "ec8_1_design", "ec8_2_elastic",
                       "ec8_2_design", "eak_elastic", "eak_design"]
    T = t["period"]
    assert T.size == 81 and T[0] == 0.0 and T[-1] == 4.0
    for k in (1, 2):
        exact(t[f"ec8_{k}_elastic"], codes.elastic_spectrum(T, spectrum_type=k, ground="B",
                                                             zone="Z2"))
        exact(t[f"ec8_{k}_design"], codes.design_spectrum(T, spectrum_type=k, ground="B",
                                                          q=1.5, beta=0.2, zone="Z2"))
    exact(t["eak_elastic"], codes.eak2000_spectrum(T, zone="Z2", ground="B", importance="II",
                                                   kind="elastic"))
    exact(t["eak_design"], codes.eak2000_spectrum(T, zone="Z2", ground="B", importance="II",
                                                  q=1.5, theta=1.0, kind="design"))
    # a closed form: the plateau of type 1, ground B (S = 1.2): 2.5 x 0.24 x 1.2 g
    assert t["ec8_1_elastic"][T == 0.3][0] == pytest.approx(0.72, rel=1e-15)
    head = (tmp_path / "out" / "code_spectra.txt").read_text()
    assert "EAK 2000 values from secondary sources; unverified:" in head
    assert "zone Z2 of the Greek National Annex" in head


def test_other_parameters_equal_python(driver, tmp_path):
    """ag given with damping 7 %, type 2 only, elastic only; EAK on the 2000 map with a
    number for gamma_I, eta_min, lower_bound and the elastic exponent 1; codes in the
    order given."""
    T = [0.0, 0.03, 0.1, 0.25, 0.6, 1.0, 1.7, 3.0, 5.0]
    proc = run(driver, tmp_path,
               "&run analysis='spectra', output='o' /\n"
               f"&spectra periods = {', '.join(map(str, T))}, codes = 'eak', 'ec8_2' /\n"
               "&ec8 ag = 0.31, ground = 'd', damping = 0.07, q = 3.9, beta = 0.15 /\n"
               "&eak zone = 'III', zone_map = '2000', ground = 'C', importance = 1.2, "
               "q = 2.5, theta = 0.8, damping = 0.1, eta_min = 0.7, lower_bound = 0.25, "
               "elastic_exponent = 1.0 /\n")
    assert proc.returncode == 0, proc.stderr
    t = read_table(tmp_path / "o_spectra.csv")
    assert list(t) == ["period", "eak_elastic", "eak_design", "ec8_2_elastic",
                       "ec8_2_design"]
    exact(t["period"], T)
    exact(t["ec8_2_elastic"], codes.elastic_spectrum(T, 0.31, 2, "D", xi_percent=100 * 0.07))
    exact(t["ec8_2_design"], codes.design_spectrum(T, 0.31, 2, "D", q=3.9, beta=0.15))
    eak = dict(zone="III", zone_map="2000", ground="C", importance=1.2, damping=0.1,
               eta_min=0.7)
    exact(t["eak_elastic"], codes.eak2000_spectrum(T, kind="elastic", elastic_exponent=1.0,
                                                   **eak))
    exact(t["eak_design"], codes.eak2000_spectrum(T, kind="design", q=2.5, theta=0.8,
                                                  lower_bound=0.25, **eak))
    # independent: eta = max(sqrt(7/12), 0.7) = 0.7637..., A = 0.24 g x 1.2, T2(C) = 0.8 s
    eta = max(math.sqrt(7 / 12), 0.7)
    assert t["eak_design"][T.index(0.25)] == pytest.approx(1.2 * 0.24 * eta * 0.8 * 2.5 / 2.5,
                                                          rel=1e-15)
    assert t["eak_elastic"][T.index(3.0)] == pytest.approx(1.2 * 0.24 * eta * 2.5 * 0.8 / 3.0,
                                                           rel=1e-15)
    # the floor lower_bound gamma_I A at long periods
    assert t["eak_design"][-1] == pytest.approx(0.25 * 1.2 * 0.24, rel=1e-15)

    proc = run(driver, tmp_path, "&run analysis='spectra', output='e' /\n"
               "&spectra periods = 0.1, 0.5, 2.0, codes = 'EC8_1', kind = 'design' /\n"
               "&ec8 zone = 'Z3', importance = 1.2, ground = 'C' /\n")
    assert proc.returncode == 0, proc.stderr
    t = read_table(tmp_path / "e_spectra.csv")
    assert list(t) == ["period", "ec8_1_design"]
    exact(t["ec8_1_design"], codes.design_spectrum([0.1, 0.5, 2.0], ground="C", zone="Z3",
                                                   importance=1.2))


# ---------------------------------------------------------------------------
# the record-suite check
# ---------------------------------------------------------------------------

def suite_reference(files, t1, target, fit, n_points, extra):
    """The check of EN 1998-1 3.2.3.1.2(4) in numpy: the grid (log-spaced from 0.2 T1 to
    2 T1, plus T1, the corners and the extra periods inside), each record's 5 % PSA
    there (seispulse.sdof.spectrum, exact peaks), the rules (b), (c), the scale
    factors."""
    lo, hi = 0.2 * t1, 2.0 * t1
    grid = lo * 10.0 ** (np.arange(n_points) / (n_points - 1))
    grid[0], grid[-1] = lo, hi
    grid = np.unique(np.concatenate([grid, [e for e in extra if lo <= e <= hi]]))
    psa, pga = [], []
    for f in files:
        rec = records.read(f)
        s = sdof.spectrum(rec.accel, rec.dt, grid, 0.05, peaks="exact")
        psa.append(np.asarray(s.psa, dtype=float).ravel())
        pga.append(rec.pga)
    psa, pga = np.array(psa), np.array(pga)                 # (record, period)
    tgt, tgt0 = target(grid), float(target(0.0))
    mean = psa.mean(axis=0)
    ratio = mean / tgt
    if fit == "linear":
        own = (psa * tgt).sum(axis=1) / (psa ** 2).sum(axis=1)
    else:
        own = np.exp((np.log(tgt) - np.log(psa)).mean(axis=1))
    own_mean = (own[:, None] * psa).mean(axis=0)
    return dict(grid=grid, psa=psa, pga=pga, target=tgt, target_pga=tgt0, mean=mean,
                ratio=ratio, own=own, own_mean=own_mean,
                common=max(tgt0 / pga.mean(), (0.9 * tgt / mean).max()),
                min_ratio=ratio.min(), t_min=grid[ratio.argmin()],
                own_pga_ratio=(own * pga).mean() / tgt0,
                own_min_ratio=(own_mean / tgt).min())


def least_ratio(recs, target, grid, ratio, factors):
    """The least of sum_k f_k PSA_k(T) / (n target(T)) over [grid[0], grid[-1]], found
    independently of the library: the grid's values, then in each grid interval next to
    the three smallest grid ratios a dense scan (401 periods, sdof.spectrum exact peaks)
    polished by scipy's bounded minimize_scalar (xatol 1e-12 s). Returns (ratio, T)."""
    from scipy.optimize import minimize_scalar

    def f(periods):
        periods = np.atleast_1d(np.asarray(periods, dtype=float))
        psa = [np.asarray(sdof.spectrum(r.accel, r.dt, periods, 0.05, peaks="exact").psa,
                          dtype=float).ravel() for r in recs]
        mean = sum(c * p for c, p in zip(factors, psa)) / len(recs)
        return mean / np.asarray(target(periods), dtype=float)

    best = (float(ratio.min()), float(grid[ratio.argmin()]))
    for i in np.argsort(ratio)[:3]:
        for a, b in ((i - 1, i), (i, i + 1)):
            if a < 0 or b >= grid.size:
                continue
            scan = np.linspace(grid[a], grid[b], 401)
            v = f(scan)
            j = int(np.argmin(v))
            lo, hi = scan[max(j - 1, 0)], scan[min(j + 1, scan.size - 1)]
            res = minimize_scalar(lambda t: float(f(t)[0]), bounds=(lo, hi), method="bounded",
                                  options=dict(xatol=1e-12))
            for val, t in ((float(v[j]), float(scan[j])), (float(res.fun), float(res.x))):
                if val < best[0]:
                    best = (val, t)
    return best


SUITE_CASES = {
    # name: (target, &suite and code groups, target callable, fit, n_points, corner
    # periods, Python's target)
    "ec8_1_linear": ("&suite t1 = 0.5, n_points = 30 /\n&ec8 zone = 'Z2', ground = 'B' /\n",
                     lambda T: codes.elastic_spectrum(T, zone="Z2", ground="B"), "linear",
                     30, [0.15, 0.5, 2.0], codes.elastic_target(zone="Z2", ground="B")),
    "ec8_2_log": ("&suite t1 = 0.3, target = 'EC8_2', fit = 'log', n_points = 12 /\n"
                  "&ec8 ag = 0.2, ground = 'C' /\n",
                  lambda T: codes.elastic_spectrum(T, 0.2, 2, "C"), "log", 12,
                  [0.1, 0.25, 1.2], codes.elastic_target(0.2, 2, "C")),
    # a coarse grid: the least ratios lie between grid periods (refined rows)
    "ec8_1_coarse": ("&suite t1 = 1.5, n_points = 5 /\n&ec8 ag = 0.25, ground = 'C' /\n",
                     lambda T: codes.elastic_spectrum(T, 0.25, 1, "C"), "linear", 5,
                     [0.2, 0.6, 2.0], codes.elastic_target(0.25, 1, "C")),
    "eak": ("&suite t1 = 0.45, target = 'EAK', n_points = 20 /\n"
            "&eak zone = 'Z3', ground = 'A', importance_class = 'III' /\n",
            lambda T: codes.eak2000_spectrum(T, zone="Z3", ground="A", importance="III",
                                             kind="elastic"), "linear", 20, [0.1, 0.4],
            codes.eak2000_target("Z3", "A", "III")),
}


@pytest.mark.parametrize("name", sorted(SUITE_CASES))
def test_suite_tables_against_numpy(driver, tmp_path, name):
    group, target, fit, n_points, corners, py_target = SUITE_CASES[name]
    t1 = float(re.search(r"t1 = ([0-9.]+)", group).group(1))
    with_records(tmp_path)
    files = ", ".join(f"'{f}'" for f in SUITE_FILES)
    proc = run(driver, tmp_path, f"&run analysis='spectra', output='s' /\n"
               f"&records files = {files} /\n" + group)
    assert proc.returncode == 0, proc.stderr
    ref = suite_reference([tmp_path / f for f in SUITE_FILES], t1, target, fit, n_points,
                          [t1] + corners)
    rel = dict(rel=1e-13, abs=0.0)

    # the tables hold the check grid (only &suite: T1, the target's corners) and the
    # refined least ratios between grid periods (1 or 2 more periods, or none)
    m = read_table(tmp_path / "s_suite_mean.csv")
    assert list(m) == ["period", "target", "target_90", "mean", "ratio", "mean_common",
                       "mean_own"]
    on = np.array([np.min(np.abs(ref["grid"] / p - 1)) < 1e-14 for p in m["period"]])
    assert on.sum() == ref["grid"].size and len(m["period"]) - on.sum() in (0, 1, 2)
    assert m["period"][on] == pytest.approx(ref["grid"], rel=1e-14)
    assert t1 in m["period"]
    exact(m["target"], target(m["period"]))
    assert m["target_90"][on] == pytest.approx(0.9 * ref["target"], **rel)
    assert m["mean"][on] == pytest.approx(ref["mean"], **rel)
    assert m["ratio"][on] == pytest.approx(ref["ratio"], **rel)
    u = read_table(tmp_path / "s_suite.csv")
    common = u["common_scale"][0]
    assert m["mean_common"] == pytest.approx(common * m["mean"], **rel)
    assert m["mean_own"][on] == pytest.approx(ref["own_mean"], **rel)

    r = read_table(tmp_path / "s_suite_records.csv")
    assert list(r["name"]) == ["quake_a", "quake_b", "quake_d"]
    assert list(r["index"]) == [1, 2, 3] and list(r["scale"]) == [1.0, 1.0, 1.0]
    assert r["own_total"] == pytest.approx(ref["own"], **rel)
    assert r["common_total"] == pytest.approx([common] * 3, **rel)
    if on.all():                    # no refined row: the grid's factor (else checked below)
        assert common == pytest.approx(ref["common"], **rel)
    assert r["pga"] == pytest.approx(ref["pga"], **rel)
    assert r["own_scale"] == pytest.approx(ref["own"], **rel)
    assert r["psa_t1"] == pytest.approx(ref["psa"][:, list(ref["grid"]).index(t1)], **rel)
    assert list(r["status"]) == ["ok"] * 3

    s = read_table(tmp_path / "s_suite_spectra.csv")
    n = len(m["period"])
    on_long = np.tile(on, 3)
    assert s["psa"][on_long] == pytest.approx(ref["psa"].ravel(), **rel)
    assert s["psa_own"][on_long] == pytest.approx((ref["own"][:, None] * ref["psa"]).ravel(),
                                                  **rel)
    assert list(s["name"]) == [x for x in ("quake_a", "quake_b", "quake_d") for _ in range(n)]
    assert list(s["index"]) == [k for k in (1, 2, 3) for _ in range(n)]

    assert u["n_records"][0] == 3 and u["t1"][0] == t1
    assert u["pga_mean"][0] == pytest.approx(ref["pga"].mean(), **rel)
    assert u["pga_target"][0] == ref["target_pga"]
    # the least ratios: refined, never above the grid's; on the tables' periods
    assert u["min_ratio"][0] <= ref["min_ratio"] * (1 + 1e-14)
    assert u["min_ratio"][0] == np.min(m["ratio"])
    assert u["t_min_ratio"][0] == m["period"][np.argmin(m["ratio"])]
    assert common == pytest.approx(max(ref["target_pga"] / ref["pga"].mean(),
                                       0.9 / u["min_ratio"][0]), **rel)
    assert u["own_pga_ratio"][0] == pytest.approx(ref["own_pga_ratio"], **rel)
    assert u["own_min_ratio"][0] <= ref["own_min_ratio"] * (1 + 1e-14)
    own_ratio = m["mean_own"] / m["target"]
    assert u["own_min_ratio"][0] == np.min(own_ratio)
    assert u["own_t_min_ratio"][0] == m["period"][np.argmin(own_ratio)]
    assert u["target"][0] == {"ec8_1_linear": "EC8_1", "ec8_1_coarse": "EC8_1",
                              "ec8_2_log": "EC8_2", "eak": "EAK"}[name]
    assert u["fit"][0] == fit and u["n_periods"][0] == n
    assert u["n_listed"][0] == 3 and u["n_failed"][0] == 0
    # the rule that sets common_scale: the larger of the two factors of (M.1), which must
    # lie well apart here (at a tie either rule is right)
    f_pga = ref["target_pga"] / ref["pga"].mean()
    f_spec = 0.9 / u["min_ratio"][0]
    assert abs(f_pga - f_spec) > 1e-6 * max(f_pga, f_spec)
    assert u["common_rule"][0] == ("pga" if f_pga > f_spec else "spectrum")
    pga_ok = ref["pga"].mean() >= ref["target_pga"]
    spec_ok = u["min_ratio"][0] >= 0.9
    assert u["pga_check"][0] == ("pass" if pga_ok else "fail")
    assert u["spectrum_check"][0] == ("pass" if spec_ok else "fail")
    assert u["count_check"][0] == "pass" and u["mean_allowed"][0] == "no"
    assert u["check"][0] == ("pass" if pga_ok and spec_ok else "fail")
    assert u["status"][0] == "ok"
    # the summary's text table is name / value / unit lines
    txt = read_summary_txt(tmp_path / "s_suite.txt")
    assert txt["check"][0] == u["check"][0] and txt["t1"] == ("%.6g" % t1, "s")

    # the refined rows (periods off the grid): each record's PSA there, independently
    recs = [records.read(tmp_path / f) for f in SUITE_FILES]
    off = m["period"][~on]
    if name == "ec8_1_coarse":
        assert off.size > 0           # the case tests the refined rows
    if off.size:
        psa_off = np.array([np.asarray(sdof.spectrum(x.accel, x.dt, off, 0.05,
                                                     peaks="exact").psa, dtype=float).ravel()
                            for x in recs])
        assert m["mean"][~on] == pytest.approx(psa_off.mean(axis=0), **rel)
        assert m["ratio"][~on] == pytest.approx(psa_off.mean(axis=0) / target(off), **rel)
        assert m["target_90"][~on] == pytest.approx(0.9 * target(off), **rel)
        assert m["mean_own"][~on] == pytest.approx((ref["own"][:, None] * psa_off).mean(axis=0),
                                                   **rel)
        assert s["psa"][~on_long] == pytest.approx(psa_off.ravel(), **rel)
    # min_ratio and own_min_ratio against a dense scan polished by scipy (the ratio is
    # flat at its minimum: 1e-9 relative in the value, 1e-4 s in its period)
    low, t_low = least_ratio(recs, target, ref["grid"], ref["ratio"], np.ones(3))
    assert u["min_ratio"][0] == pytest.approx(low, rel=1e-9)
    assert u["t_min_ratio"][0] == pytest.approx(t_low, abs=1e-4)
    own_low, own_t = least_ratio(recs, target, ref["grid"], ref["own_mean"] / ref["target"],
                                 ref["own"])
    assert u["own_min_ratio"][0] == pytest.approx(own_low, rel=1e-9)
    assert u["own_t_min_ratio"][0] == pytest.approx(own_t, abs=1e-4)
    assert common == pytest.approx(max(ref["target_pga"] / ref["pga"].mean(), 0.9 / low),
                                   rel=1e-9)

    # Python's check_record_suite: the same library routine, the same numbers
    chk = codes.check_record_suite(recs, t1, py_target, n_points=n_points, fit=fit)
    assert np.asarray(chk.periods) == pytest.approx(m["period"], rel=1e-15)
    assert np.asarray(chk.mean) == pytest.approx(m["mean"], rel=1e-14)
    assert chk.min_ratio == pytest.approx(u["min_ratio"][0], rel=1e-14)
    assert chk.t_min_ratio == pytest.approx(u["t_min_ratio"][0], rel=1e-15)
    assert chk.own_min_ratio == pytest.approx(u["own_min_ratio"][0], rel=1e-14)
    assert chk.common_scale == pytest.approx(u["common_scale"][0], rel=1e-14)
    assert np.asarray(chk.own_scale) == pytest.approx(r["own_scale"], rel=1e-14)
    assert chk.passed == (u["check"][0] == "pass")


def test_scaled_by_common_scale_passes(driver, tmp_path):
    """The suite scaled by the common scale factor (M.1) passes (b) and (c), with the
    least margin exactly at one of them."""
    with_records(tmp_path)
    files = ", ".join(f"'{f}'" for f in SUITE_FILES)
    head = "&run analysis='spectra', output='{}' /\n&records files = {}, scale = {} /\n"
    group = "&suite t1 = 0.5, n_points = 25 /\n&ec8 zone = 'Z2', ground = 'B' /\n"
    assert run(driver, tmp_path, head.format("a", files, 1.0) + group).returncode == 0
    s = read_table(tmp_path / "a_suite.csv")["common_scale"][0]
    proc = run(driver, tmp_path, head.format("b", files, repr(float(s))) + group)
    assert proc.returncode == 0, proc.stderr
    u = read_table(tmp_path / "b_suite.csv")
    assert u["check"][0] == "pass"
    assert u["common_scale"][0] == pytest.approx(1.0, rel=1e-12)
    assert min(u["pga_ratio"][0], u["min_ratio"][0] / 0.9) == pytest.approx(1.0, rel=1e-12)


def test_records_from_reads_the_other_input(driver, tmp_path):
    """&suite records_from: the &records group of another input (its paths relative to
    it) gives the same tables as that group written here; the echo re-runs."""
    with_records(tmp_path)
    files = ", ".join(f"'{f}'" for f in SUITE_FILES)
    (tmp_path / "newmark.nml").write_text(
        "&run analysis='newmark', output='n' /\n"
        f"&records files = {files}, polarity = 1, -1, 1, target_pga = 0.3 /\n"
        "&newmark ky = 0.1 /\n")
    group = "&suite t1 = 0.4, n_points = 15 /\n&ec8 ag = 0.25, ground = 'B' /\n"
    proc = run(driver, tmp_path, "&run analysis='spectra', output='here' /\n"
               f"&records files = {files}, polarity = 1, -1, 1, target_pga = 0.3 /\n" + group)
    assert proc.returncode == 0, proc.stderr
    (tmp_path / "sub").mkdir()
    proc = run(driver, tmp_path, "&run analysis='spectra', output='from' /\n"
               + group.replace("/\n", ", records_from = '../newmark.nml' /\n", 1),
               name="sub/case.nml")
    assert proc.returncode == 0, proc.stderr
    for table in ("suite", "suite_records", "suite_mean", "suite_spectra"):
        a = read_table(tmp_path / f"here_{table}.csv")
        b = read_table(tmp_path / f"from_{table}.csv")
        assert a.keys() == b.keys()
        for k in a:
            assert list(a[k]) == list(b[k]) or np.array_equal(a[k], b[k], equal_nan=True), k
    echo = (tmp_path / "from_input.nml").read_text()
    assert "records_from = 'sub/../newmark.nml'" in echo and "&records" not in echo
    (tmp_path / "again.nml").write_text(echo.replace("output = 'from'", "output = 'again'"))
    proc = subprocess.run([driver, "again.nml"], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "again_suite.csv").read_text() == (tmp_path / "from_suite.csv").read_text()


def test_records_from_error_is_placed_in_the_other_input(driver, tmp_path):
    """A bad &records of the input named by records_from: the error names that file, the
    line of its &records and the key (exit status 2, nothing written)."""
    with_records(tmp_path)
    (tmp_path / "other.nml").write_text("&run analysis='newmark', output='n' /\n\n"
                                        "&records files = 'records/quake_a.AT2', "
                                        "units = 'furlongs' /\n")
    proc = run(driver, tmp_path, RUN + "&suite t1 = 0.4, records_from = 'other.nml' /\n"
               + EC8)
    assert proc.returncode == 2, proc.stderr
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("seispulse: error:")]
    assert len(errors) == 1 and errors[0].startswith(
        "seispulse: error: other.nml:3: &records: units = "), proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir() if p.is_file()) == ["case.nml",
                                                                          "other.nml"]


def test_a_record_that_cannot_be_read(driver, tmp_path):
    """A missing record fails its rows (status failed, NaN) and the run exits 1; the check
    is made on the records read when at least min_records remain, else the summary holds
    NaN with status failed."""
    with_records(tmp_path)
    files = ", ".join(f"'{f}'" for f in SUITE_FILES + ["records/missing.AT2"])
    group = "&suite t1 = 0.5, n_points = 10 /\n&ec8 ag = 0.24, ground = 'B' /\n"
    proc = run(driver, tmp_path, f"&run analysis='spectra', output='f' /\n"
               f"&records files = {files} /\n" + group)
    assert proc.returncode == 1, proc.stderr
    assert re.search(r"case\.nml:2: &records: 1 of 4 records failed \(4 'missing'\)",
                     proc.stderr), proc.stderr
    r = read_table(tmp_path / "f_suite_records.csv")
    assert list(r["status"]) == ["ok", "ok", "ok", "failed"]
    assert np.isnan(r["pga"][3]) and np.isnan(r["own_scale"][3])
    u = read_table(tmp_path / "f_suite.csv")
    # the suite checked is not the one listed: the check fails, status failed
    assert u["n_records"][0] == 3 and u["status"][0] == "failed"
    assert u["n_listed"][0] == 4 and u["n_failed"][0] == 1
    assert u["check"][0] == "fail" and u["own_check"][0] == "fail"
    head = (tmp_path / "f_suite.txt").read_text()
    assert "CHECK FAILS: made on 3 of 4 records listed (failed: 4 'missing')" in head
    # the path of the missing file once in its header line
    line = [ln for ln in head.splitlines() if ln.startswith("# record 4:")][0]
    assert line.count("records/missing.AT2") == 1, line
    # the figures of the records read: as the three records alone
    files3 = ", ".join(f"'{f}'" for f in SUITE_FILES)
    assert run(driver, tmp_path, f"&run analysis='spectra', output='g' /\n"
               f"&records files = {files3} /\n" + group).returncode == 0
    g = read_table(tmp_path / "g_suite.csv")
    assert g["check"][0] == "pass"          # the three records alone pass
    assert g["status"][0] == "ok" and g["n_failed"][0] == 0 and g["n_listed"][0] == 3
    same = [k for k in g if k not in ("n_listed", "n_failed", "check", "own_check", "status")]
    assert all(list(u[k]) == list(g[k]) for k in same)

    proc = run(driver, tmp_path, f"&run analysis='spectra', output='h' /\n"
               f"&records files = {files} /\n"
               + group.replace("n_points = 10", "n_points = 10, min_records = 4"))
    assert proc.returncode == 1, proc.stderr
    assert "min_records = 4" in proc.stderr
    u = read_table(tmp_path / "h_suite.csv")
    assert u["status"][0] == "failed" and np.isnan(u["common_scale"][0])
    assert np.isnan(read_table(tmp_path / "h_suite_mean.csv")["mean"]).all()
    assert "NO CHECK" in (tmp_path / "h_suite.txt").read_text()


# ---------------------------------------------------------------------------
# input errors
# ---------------------------------------------------------------------------

RUN = "&run analysis='spectra', output='o' /\n"
SPEC = "&spectra periods = 0.1, 1.0, codes = 'EC8_1' /\n"
EC8 = "&ec8 ag = 0.24 /\n"
RECS = "&records files = 'records/quake_a.AT2', 'records/quake_b.csv', 'records/quake_d.dat' /\n"
ERRORS = {
    # name: (input after &run, group, start of the rest of the message)
    "unknown_code": ("&spectra periods = 0.1, codes = 'EC8_1', 'EC9' /\n" + EC8, "spectra",
                     "codes(2) = 'EC9': unknown code (allowed: EC8_1, EC8_2, EAK)"),
    "code_twice": ("&spectra periods = 0.1, codes = 'EC8_1', 'ec8_1' /\n" + EC8, "spectra",
                   "codes(2) = 'ec8_1': given twice"),
    "unknown_kind": ("&spectra periods = 0.1, codes = 'EC8_1', kind = 'inelastic' /\n" + EC8,
                     "spectra", "kind = 'inelastic': unknown kind"),
    "no_periods": ("&spectra codes = 'EC8_1' /\n" + EC8, "spectra", "periods: missing"),
    "unknown_target": (RECS + "&suite t1 = 0.5, target = 'EC8_3' /\n" + EC8, "suite",
                       "target = 'EC8_3': unknown target"),
    "unknown_ec8_zone": (SPEC + "&ec8 zone = 'Z4' /\n", "ec8", "zone = 'Z4': unknown zone"),
    "unknown_eak_zone": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak zone = 'IV' /\n",
                         "eak", "zone = 'IV': unknown zone of the 2003 map"),
    "unknown_ec8_ground": (SPEC + "&ec8 ag = 0.2, ground = 'F' /\n", "ec8",
                           "ground = 'F': unknown ground type"),
    "unknown_eak_ground": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak ground = 'E' /\n",
                           "eak", "ground = 'E': unknown ground category"),
    "eak_ground_x": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak ground = 'X' /\n",
                     "eak", "ground = 'X': ground category X calls for a site-specific study"),
    "unknown_annex": (SPEC + "&ec8 zone = 'Z1', national_annex = 'IT' /\n", "ec8",
                      "national_annex = 'IT': unknown national annex"),
    "unknown_fit": (RECS + "&suite t1 = 0.5, fit = 'cubic' /\n" + EC8, "suite",
                    "fit = 'cubic': unknown fit"),
    "unknown_map": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak zone_map = '1999' /\n",
                    "eak", "zone_map = '1999': unknown zone map"),
    "ec8_q": (SPEC + "&ec8 ag = 0.2, q = 0.9 /\n", "ec8", "q = 0.9: the behaviour factor"),
    "eak_q": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak q = 0.5 /\n", "eak",
              "q = 0.5: the behaviour factor"),
    "eak_theta_0": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak theta = 0 /\n", "eak",
                    "theta = 0.0: the foundation factor must lie in (0, 1]"),
    "eak_theta_big": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak theta = 1.2 /\n", "eak",
                      "theta = 1.2: the foundation factor must lie in (0, 1]"),
    "t1_zero": (RECS + "&suite t1 = 0 /\n" + EC8, "suite", "t1 = 0.0: must be a finite "
                "period > 0"),
    "t1_missing": (RECS + "&suite target = 'EC8_1' /\n" + EC8, "suite", "t1: missing"),
    "too_few_records": ("&records files = 'records/quake_a.AT2', 'records/quake_b.csv' /\n"
                        "&suite t1 = 0.5 /\n" + EC8, "records",
                        "files: 2 records, fewer than &suite min_records = 3"),
    # the library's rule and messages (ec8_design_ag), the same as Python's
    "ag_and_zone": (SPEC + "&ec8 ag = 0.2, zone = 'Z2' /\n", "ec8",
                    "ag and zone: give one of them"),
    "ag_missing": (SPEC + "&ec8 ground = 'B' /\n", "ec8",
                   "ag: give the design ground acceleration ag, or a seismic zone"),
    "importance_with_ag": (SPEC + "&ec8 ag = 0.2, importance = 1.2 /\n", "ec8",
                           "importance = 1.2: ag is already the design ground acceleration "
                           "gamma_I a_gR"),
    "importance_zero": (SPEC + "&ec8 zone = 'Z2', importance = 0 /\n", "ec8",
                        "importance = 0.0: must be a finite number > 0"),
    "ag_negative": (SPEC + "&ec8 ag = -0.1 /\n", "ec8",
                    "ag = -0.1: must be a finite acceleration >= 0 (g)"),
    "annex_with_ag": (SPEC + "&ec8 ag = 0.2, national_annex = 'IT' /\n", "ec8",
                      "national_annex = 'IT': unknown national annex"),
    "eak_exponent": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak elastic_exponent = 0 /\n",
                     "eak", "elastic_exponent = 0.0: the long-period exponent must be finite"),
    "eak_eta_min": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak eta_min = 2 /\n", "eak",
                    "eta_min = 2.0: the lower limit of eta must lie in [0, 1]"),
    "eak_lower_bound": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak lower_bound = -1 /\n",
                        "eak", "lower_bound = -1.0: the floor factor must be finite and >= 0"),
    "eak_importance": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak importance = 0 /\n",
                       "eak", "importance = 0.0: the importance factor gamma_I must be finite"),
    "eak_alpha": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak alpha = -0.1 /\n", "eak",
                  "alpha = -0.1: the ground acceleration A/g must be finite and >= 0"),
    "ec8_beta": (SPEC + "&ec8 ag = 0.2, beta = -1 /\n", "ec8",
                 "beta = -1.0: the lower-bound factor must be finite and >= 0"),
    "eak_2000_without_zone": ("&spectra periods = 0.1, codes = 'EAK' /\n"
                              "&eak zone_map = '2000' /\n", "eak",
                              "zone: missing (the default Z2 is a zone of the 2003 map"),
    "eak_zone_and_alpha": ("&spectra periods = 0.1, codes = 'EAK' /\n"
                           "&eak zone = 'Z1', alpha = 0.1 /\n", "eak", "zone, alpha: give only"),
    "eak_importance_twice": ("&spectra periods = 0.1, codes = 'EAK' /\n"
                             "&eak importance = 1.1, importance_class = 'II' /\n", "eak",
                             "importance, importance_class: give only one"),
    "eak_unknown_class": ("&spectra periods = 0.1, codes = 'EAK' /\n"
                          "&eak importance_class = 'V' /\n", "eak",
                          "importance_class = 'V': unknown importance class"),
    "records_and_records_from": (RECS + "&suite t1 = 0.5, records_from = 'other.nml' /\n" + EC8,
                                 "records", "not with &suite records_from"),
    "records_from_missing": ("&suite t1 = 0.5, records_from = 'nowhere.nml' /\n" + EC8, "suite",
                             "records_from = 'nowhere.nml': nowhere.nml: cannot open"),
    "records_from_no_records": ("&suite t1 = 0.5, records_from = 'case.nml' /\n" + EC8,
                                "suite", "records_from = 'case.nml': it has no &records group"),
    "records_without_suite": (SPEC + EC8 + RECS, "records", "only with &suite"),
    "suite_without_records": ("&suite t1 = 0.5 /\n" + EC8, "records", "missing group"),
    "ec8_missing": (SPEC, "ec8", "missing group"),
    "eak_missing": ("&spectra periods = 0.1 /\n" + EC8, "eak", "missing group"),
    "ec8_unused": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak zone = 'Z1' /\n" + EC8, "ec8",
                   "not used"),
    "no_group": (EC8, "spectra", "missing group"),
    "unknown_key": ("&spectra periods = 0.1, codes = 'EC8_1', damping = 0.05 /\n" + EC8,
                    "spectra", "damping: unknown key"),
    "n_points": (RECS + "&suite t1 = 0.5, n_points = 1 /\n" + EC8, "suite",
                 "n_points = 1: must be >= 2"),
    # a target of zero: refused before any record is read
    # (the library's refusal of the target, placed at &ec8 / &eak)
    "ag_zero_suite": (RECS + "&suite t1 = 0.5 /\n&ec8 ag = 0 /\n", "ec8",
                      "ag = 0.0: the design ground acceleration of the target (g) must be "
                      "finite and > 0"),
    "alpha_zero_suite": (RECS + "&suite t1 = 0.5, target = 'EAK' /\n&eak alpha = 0 /\n",
                         "eak", "alpha = 0.0: the ground acceleration A/g of the target must "
                         "be finite and > 0"),
    # a damping ratio in [0, 1), as &sdof: 5 (meant as 5 %) is refused
    "ec8_damping_percent": (SPEC + "&ec8 ag = 0.2, damping = 5 /\n", "ec8",
                            "damping = 5.0: must be a damping ratio in [0, 1) (a ratio: "
                            "0.05 = 5 %)"),
    "eak_damping_one": ("&spectra periods = 0.1, codes = 'EAK' /\n&eak damping = 1.0 /\n",
                        "eak", "damping = 1.0: must be a damping ratio in [0, 1)"),
}


def test_input_error_messages_read_well(driver, tmp_path):
    """EAK ground X without the library's numeric codes; a missing &records group in one
    pair of parentheses."""
    proc = run(driver, tmp_path, RUN + ERRORS["eak_ground_x"][0])
    assert proc.returncode == 2 and "(1..4)" not in proc.stderr, proc.stderr
    assert "give ground A-D" in proc.stderr, proc.stderr   # the library's message
    proc = run(driver, tmp_path, RUN + ERRORS["suite_without_records"][0])
    assert proc.returncode == 2 and ") (" not in proc.stderr, proc.stderr
    assert "; or &suite records_from = 'other.nml')" in proc.stderr, proc.stderr


def test_zero_ag_without_suite_is_allowed(driver, tmp_path):
    """ag = 0 is refused only as the target of the check: the code spectra are zero."""
    proc = run(driver, tmp_path, RUN + SPEC + "&ec8 ag = 0 /\n")
    assert proc.returncode == 0, proc.stderr
    t = read_table(tmp_path / "o_spectra.csv")
    assert (t["ec8_1_elastic"] == 0.0).all() and (t["ec8_1_design"] == 0.0).all()


def test_suite_prefix_collision_before_records(driver, tmp_path):
    """&spectra and &suite under a prefix ending in '_suite': the code spectra and the
    records' spectra would have one name; an input error before any record is read."""
    with_records(tmp_path)
    text = ("&run analysis='spectra', output='x_suite' /\n" + RECS + SPEC
            + "&suite t1 = 0.5 /\n" + EC8)
    proc = run(driver, tmp_path, text)
    assert proc.returncode == 2, proc.stderr
    assert "record 1/" not in proc.stderr, proc.stderr          # nothing was read
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("seispulse: error:")]
    assert errors == ["seispulse: error: case.nml:1: &run: output: the tables 'spectra' and "
                      "'suite_spectra' would both be x_suite_spectra.csv (&spectra and &suite "
                      "under an output prefix ending in '_suite'): choose another output "
                      "prefix"], proc.stderr
    # another prefix: both tables
    proc = run(driver, tmp_path, text.replace("x_suite", "x"))
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "x_spectra.csv").exists() and (tmp_path / "x_suite_spectra.csv").exists()


def test_examples_outputs_do_not_overlap(driver, tmp_path):
    """The suite example checks four distinct records with min_records = 3; an input
    error in a copy of the spectra example (which removes that example's outputs)
    leaves the suite example's tables."""
    proc = subprocess.run([driver, str(INPUT / "spectra_suite.nml")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    u = read_table(tmp_path / "out" / "record_suite.csv")
    assert u["n_listed"][0] == 4 and u["n_records"][0] == 4 and u["count_check"][0] == "pass"
    r = read_table(tmp_path / "out" / "record_suite_records.csv")
    assert list(r["name"]) == ["quake_a", "quake_b", "quake_c", "quake_d"]
    text = (INPUT / "spectra.nml").read_text().replace("kind = 'both'", "kind = 'bth'")
    assert "kind = 'bth'" in text
    proc = run(driver, tmp_path, text)
    assert proc.returncode == 2, proc.stderr
    outs = sorted(p.name for p in (tmp_path / "out").iterdir())
    for t in ("", "_records", "_mean", "_spectra"):
        assert f"record_suite{t}.csv" in outs and f"record_suite{t}.txt" in outs, outs


def test_suite_header_notes(driver, tmp_path):
    """EAK target: the value at T = 0 is gamma_I A (not a_g S); EAK's corner periods are
    not called the structure's T1; numbers to 6 digits, the exponent 2/3; the scale
    factors on top of &records; warnings (stderr and header) for 2 T1 beyond 4 s and
    beyond the longest record, and for &spectra periods beyond 4 s."""
    with_records(tmp_path)
    proc = run(driver, tmp_path, RUN + RECS + "&suite t1 = 0.4, target = 'EAK' /\n"
               "&eak zone = 'Z3', importance_class = 'III' /\n")
    assert proc.returncode == 0, proc.stderr
    head = (tmp_path / "o_suite.txt").read_text()
    assert "at T = 0 (gamma_I A): 0.414 g" in head and "a_g S" not in head
    assert "EAK corner periods T1/T2 = 0.15/0.6 s" in head
    assert "structure period T1 = 0.4 s" in head
    assert "[0.08, 0.8] s" in head and "0.08000000000000002" not in head
    assert "long-period exponent 2/3" in head and "0.6666" not in head
    assert "common_scale and own_scale apply on top of the &records scaling" in head
    assert "otherwise the most unfavourable response" in head
    assert "WARNING" not in head and "warning" not in proc.stderr
    # an EC8 target says a_g S
    proc = run(driver, tmp_path, RUN + RECS + "&suite t1 = 0.4 /\n" + EC8)
    assert "at T = 0 (a_g S): 0.24 g" in (tmp_path / "o_suite.txt").read_text()
    # the records last 2.39, 3.98 and 2.49 s; 2 T1 = 5 s exceeds both 4 s and them
    proc = run(driver, tmp_path, RUN + RECS + "&suite t1 = 2.5 /\n" + EC8
               + "&spectra periods = 0.5, 4.5, codes = 'EC8_1' /\n")
    assert proc.returncode == 0, proc.stderr
    warnings = [ln for ln in proc.stderr.splitlines() if ln.startswith("warning:")]
    assert len(warnings) == 3, proc.stderr
    assert warnings[0].startswith("warning: case.nml:5: &spectra: periods up to 4.5 s")
    assert warnings[1].startswith("warning: case.nml:3: &suite: t1 = 2.5: the check "
                                  "reaches 2 T1 = 5 s")
    assert warnings[2] == ("warning: case.nml:3: &suite: t1 = 2.5: 2 T1 = 5 s exceeds the "
                           "duration of the longest record read (3.98 s)")
    head = (tmp_path / "o_suite.txt").read_text()
    assert "# WARNING: t1 = 2.5: 2 T1 = 5 s exceeds the duration" in head
    assert "# WARNING: periods up to 4.5 s" in (tmp_path / "o_spectra.txt").read_text()


def test_total_scale_factors(driver, tmp_path):
    """scale and polarity of &records: the records table gives the factor with the
    polarity and the totals on the file as read; scaling each file by common_total makes
    common_scale 1."""
    with_records(tmp_path)
    files = ", ".join(f"'{f}'" for f in SUITE_FILES)
    group = "&suite t1 = 0.5, n_points = 12 /\n" + EC8
    proc = run(driver, tmp_path, "&run analysis='spectra', output='a' /\n"
               f"&records files = {files}, scale = 2.0, 0.5, 0.25, polarity = 1, -1, 1 /\n"
               + group)
    assert proc.returncode == 0, proc.stderr
    r = read_table(tmp_path / "a_suite_records.csv")
    c = read_table(tmp_path / "a_suite.csv")["common_scale"][0]
    assert list(r["scale"]) == [2.0, -0.5, 0.25]
    assert list(r["own_total"]) == list(r["scale"] * r["own_scale"])
    assert list(r["common_total"]) == list(r["scale"] * c)
    totals = ", ".join(repr(abs(float(x))) for x in r["common_total"])
    proc = run(driver, tmp_path, "&run analysis='spectra', output='b' /\n"
               f"&records files = {files}, scale = {totals}, polarity = 1, -1, 1 /\n" + group)
    assert proc.returncode == 0, proc.stderr
    assert read_table(tmp_path / "b_suite.csv")["common_scale"][0] == pytest.approx(1.0,
                                                                                   rel=1e-12)


@pytest.mark.parametrize("name", sorted(ERRORS))
def test_input_errors(driver, tmp_path, name):
    body, group, rest = ERRORS[name]
    with_records(tmp_path)
    text = RUN + body
    # an earlier run's table under the same prefix is removed by an input error
    (tmp_path / "o_spectra.csv").write_text("stale\n")
    proc = run(driver, tmp_path, text)
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("seispulse: error:")]
    assert len(errors) == 1, proc.stderr
    m = FORM.match(errors[0])
    assert m and m["file"] == "case.nml" and m["group"] == group, errors[0]
    lines = text.splitlines()
    where = [i for i, ln in enumerate(lines, 1) if ln.lower().startswith(f"&{group} ")]
    assert int(m["line"]) == (where[0] if where else 1), errors[0]
    assert m["rest"].startswith(rest), errors[0]
    left = sorted(p.name for p in tmp_path.iterdir() if p.is_file())
    assert left == ["case.nml"], left


def test_suite_does_not_depend_on_the_spectra_table(driver, tmp_path):
    """The check grid comes from &suite alone (T1, n_points, the target's corners): adding
    a &spectra table of code spectra leaves every suite table as it was."""
    with_records(tmp_path)
    files = ", ".join(f"'{f}'" for f in SUITE_FILES)
    group = "&suite t1 = 0.5, n_points = 20 /\n&ec8 ag = 0.24, ground = 'B' /\n"
    head = "&run analysis='spectra', output='{}' /\n&records files = " + files + " /\n"
    assert run(driver, tmp_path, head.format("a") + group).returncode == 0
    proc = run(driver, tmp_path, head.format("b") + group
               + "&spectra period_range = 0, 4, period_count = 81, codes = 'EC8_1' /\n")
    assert proc.returncode == 0, proc.stderr
    for table in ("suite", "suite_records", "suite_mean", "suite_spectra"):
        a = read_table(tmp_path / f"a_{table}.csv")
        b = read_table(tmp_path / f"b_{table}.csv")
        for k in a:
            assert list(a[k]) == list(b[k]), (table, k)


@pytest.mark.parametrize("ec8, kwargs", [
    ("ag = 0.2, zone = 'Z2'", dict(ag=0.2, zone="Z2")),
    ("ground = 'B'", dict()),
    ("ag = 0.2, importance = 1.2", dict(ag=0.2, importance=1.2)),
    ("ag = -0.1", dict(ag=-0.1)),
    ("zone = 'Z2', importance = -1", dict(zone="Z2", importance=-1.0)),
])
def test_ec8_ag_rule_as_python(driver, tmp_path, ec8, kwargs):
    """&ec8 and codes.elastic_spectrum refuse the same ag / zone / importance combinations
    with the same message (the library's ec8_design_ag)."""
    with pytest.raises(codes.InvalidInputError) as exc:
        codes.elastic_spectrum(0.1, **kwargs)
    proc = run(driver, tmp_path, RUN + SPEC + f"&ec8 {ec8} /\n")
    assert proc.returncode == 2, proc.stderr
    m = FORM.match(proc.stderr.splitlines()[0])
    assert m and m["group"] == "ec8" and m["rest"] == str(exc.value), proc.stderr


def test_ec8_ag_accepted_as_python(driver, tmp_path):
    """ag with importance = 1 and national_annex = 'GR' is accepted by both front ends
    (the annex only checked): the spectra are those of ag alone, bit for bit."""
    proc = run(driver, tmp_path, RUN + SPEC
               + "&ec8 ag = 0.2, importance = 1, national_annex = 'GR', ground = 'B' /\n")
    assert proc.returncode == 0, proc.stderr
    t = read_table(tmp_path / "o_spectra.csv")
    exact(t["ec8_1_elastic"], codes.elastic_spectrum([0.1, 1.0], 0.2, 1, "B", importance=1.0,
                                                     national_annex="GR"))
    exact(t["ec8_1_elastic"], codes.elastic_spectrum([0.1, 1.0], 0.2, 1, "B"))


def test_eak_2000_map_needs_a_zone_as_python(driver, tmp_path):
    """zone_map = '2000' without a zone: refused by the driver as by Python (the default
    zone Z2 is a zone of the 2003 map)."""
    with pytest.raises(codes.InvalidInputError, match="zone = 'Z2'"):
        codes.eak2000_spectrum(0.3, zone_map="2000")
    proc = run(driver, tmp_path, RUN + "&spectra periods = 0.1, codes = 'EAK' /\n"
               "&eak zone_map = '2000' /\n")
    assert proc.returncode == 2 and "&eak: zone: missing" in proc.stderr, proc.stderr
