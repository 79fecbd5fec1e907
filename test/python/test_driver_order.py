"""One ordering rule for period lists, driver and Python alike: any order, the answer
in the order given (spectra, envelope, shock and amplification spectra); a period twice
is refused only where it would name two table columns alike (sa_periods of the
intensity table). Angles of a pushover curve (theta of 'cylinder', 'winkler') stay
ascending: a curve, not a list of cases."""
import csv
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from seispulse import records, sdof

SOURCE = Path(__file__).resolve().parents[2]


def run(driver, cwd, text, name):
    (cwd / f"{name}.nml").write_text(text)
    proc = subprocess.run([driver, f"{name}.nml"], cwd=cwd, capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 0, proc.stderr
    return proc


def rows(path):
    with open(path, newline="") as f:
        data = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    return data[0], data[1:]


@pytest.mark.parametrize("table, key", [("sdof", ("record (-)", "damping (-)")),
                                        ("sdof_envelope", ("damping (-)",))])
def test_sdof_periods_any_order(driver, tmp_path, table, key):
    shutil.copytree(SOURCE / "input" / "records", tmp_path / "records")
    group = ("&records files='records/quake_a.AT2', 'records/quake_b.csv' /\n"
             "&sdof periods={}, damping=0.02, 0.05, envelope=.true., plateau_below=0.35 /\n")
    given = [0.5, 0.1, 2.0, 0.3]
    run(driver, tmp_path, "&run analysis='sdof', output='u' /\n"
        + group.format(", ".join(map(str, given))), "u")
    run(driver, tmp_path, "&run analysis='sdof', output='s' /\n"
        + group.format(", ".join(map(str, sorted(given)))), "s")
    head_u, u = rows(tmp_path / f"u_{table}.csv")
    head_s, s = rows(tmp_path / f"s_{table}.csv")
    assert head_u == head_s
    it = head_u.index("T (s)")
    ik = [head_u.index(k) for k in key]
    # the same rows (bit for bit), in the order given within each record and damping
    # 2 records x 2 dampings x 4 periods; the envelope: 2 dampings x 4 periods
    assert len(u) == {"sdof": 16, "sdof_envelope": 8}[table]
    assert sorted(u) == sorted(s)
    for start in range(0, len(u), len(given)):
        block = u[start:start + len(given)]
        assert len({tuple(r[i] for i in ik) for r in block}) == 1
        assert [float(r[it]) for r in block] == given


def test_shock_and_amplification_any_order(driver, tmp_path):
    for name, text in (("shock", "&pulse kind='half_sine', amp=2, duration=0.3 /\n"
                                 "&sdof_shock periods={} /\n"),
                       ("beta", "&sdof_beta ratios={}, gamma=0.1 /\n")):
        analysis = "sdof_shock" if name == "shock" else "sdof_beta"
        given = [1.5, 0.2, 0.7]
        for tag, values in (("u", given), ("s", sorted(given))):
            run(driver, tmp_path, f"&run analysis='{analysis}', output='{tag}{name}' /\n"
                + text.format(", ".join(map(str, values))), f"{tag}{name}")
        _, u = rows(tmp_path / f"u{name}_{analysis}.csv")
        _, s = rows(tmp_path / f"s{name}_{analysis}.csv")
        order = np.argsort(given)
        assert [u[i] for i in order] == s


def test_python_spectrum_any_order():
    rec = records.read(SOURCE / "input" / "records" / "quake_a.AT2")
    given = np.array([0.5, 0.1, 2.0, 0.3])
    a = sdof.spectrum(rec.accel, rec.dt, given)
    b = sdof.spectrum(rec.accel, rec.dt, np.sort(given))
    order = np.argsort(given)
    assert all(np.shape(getattr(a, f)) == (4,) for f in ("sd", "sa", "psa", "t_sa"))
    for field in a._fields:
        va, vb = np.asarray(getattr(a, field)), np.asarray(getattr(b, field))
        if va.shape and va.shape[-1] == given.size:
            np.testing.assert_array_equal(va[..., order], vb)
    sa = records.spectral_acceleration(rec, given)
    np.testing.assert_array_equal(np.asarray(sa)[order],
                                  records.spectral_acceleration(rec, np.sort(given)))
