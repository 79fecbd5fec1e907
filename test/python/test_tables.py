"""Table-like results (walls.comparison, sdof.spectrum, sdof.pulse_spectrum,
sdof.shock_spectrum, batch newmark.rigid): the printed table holds every value with 6
significant digits (checked cell by cell against Python's own %.6g of the fields), units
in the header, and to_frame() gives the same values exactly; pandas stays optional (not
imported by `import seispulse`, a clear ImportError when missing), and the sample records
of pyslammer read through records.sample() equal numpy.loadtxt of the files."""
import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from seispulse import _core, _table, codes, newmark, pulse, records, sdof, walls
from seispulse.errors import InvalidInputError

ROOT = Path(os.environ.get("SEISPULSE_SOURCE_ROOT", Path(__file__).resolve().parents[2]))
QUAKE_A = ROOT / "input" / "records" / "quake_a.AT2"


def cells(text):
    """The printed table as rows of whitespace-separated cells (header line first)."""
    return [line.split() for line in text.splitlines()]


def g6(x):
    return "%.6g" % x


@pytest.fixture(scope="module")
def comparison():
    kh, kv = codes.seismic_coefficients(alpha=0.24, s=1.2, r=1.0, spectrum_type=1)
    return walls.comparison(6.0, 20.0, 32.0, kh, kv, alpha_s=0.288)


def test_comparison_table(comparison):
    text = str(comparison)
    lines = text.splitlines()
    assert lines[0].split() == ["method", "thrust", "(kN/m)", "z", "(m)", "moment", "(kNm/m)"]
    assert len(lines) == 1 + len(walls.COMPARISON_ROWS) + 1
    for k, label in enumerate(walls.COMPARISON_ROWS):
        row = lines[1 + k]
        assert row.startswith(label + " ")           # the text column is left-aligned
        assert row[len(label):].split() == [g6(comparison.thrust[k]), g6(comparison.z[k]),
                                            g6(comparison.moment[k])]
    assert lines[-1].startswith(f"kv_used = {g6(comparison.kv_used)} ")
    # numbers right-aligned: every row ends at the same column
    assert len({len(line) for line in lines[:-1]}) == 1
    assert repr(comparison) == "Comparison:\n" + text
    assert comparison.table(digits=3).splitlines()[1].split()[-3:] == [
        "%.3g" % comparison.thrust[0], "%.3g" % comparison.z[0], "%.3g" % comparison.moment[0]]
    # still the namedtuple it was
    method, thrust, z, moment, kv_used = comparison
    assert method == walls.COMPARISON_ROWS and kv_used == comparison.kv_used


def test_comparison_frame(comparison):
    pd = pytest.importorskip("pandas")
    frame = comparison.to_frame()
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == ["method", "thrust", "z", "moment"]
    assert list(frame["method"]) == list(walls.COMPARISON_ROWS)
    for col in ("thrust", "z", "moment"):
        np.testing.assert_array_equal(frame[col].to_numpy(), getattr(comparison, col))
    assert frame.attrs["units"] == {"method": "", "thrust": "kN/m", "z": "m",
                                    "moment": "kNm/m"}
    assert frame.attrs["kv_used"] == comparison.kv_used


@pytest.fixture(scope="module")
def quake():
    return records.read(QUAKE_A)


def test_spectrum_table_and_frame(quake):
    periods, damping = [0.0, 0.1, 0.5, 2.0], [0.02, 0.05, 0.1]
    s = sdof.spectrum(quake, periods=periods, damping=damping)
    rows = cells(s.table())
    assert rows[0] == ["damping", "(ratio)", "period", "(s)", "sd", "(m)", "sv", "(m/s)", "sa",
                       "(g)", "psv", "(m/s)", "psa", "(g)", "t_sd", "(s)", "t_sv", "(s)",
                       "t_sa", "(s)"]
    assert len(rows) == 1 + len(periods) * len(damping)
    fields = ("sd", "sv", "sa", "psv", "psa", "t_sd", "t_sv", "t_sa")
    for i, z in enumerate(damping):             # damping-major rows
        for j, t in enumerate(periods):
            row = rows[1 + i * len(periods) + j]
            assert row == [g6(z), g6(t)] + [g6(getattr(s, f)[i, j]) for f in fields]
    pytest.importorskip("pandas")
    frame = s.to_frame()
    assert list(frame.columns) == ["damping", "period"] + list(fields)
    np.testing.assert_array_equal(frame["psa"].to_numpy(), s.psa.reshape(-1))
    np.testing.assert_array_equal(frame["period"].to_numpy(), np.tile(periods, 3))
    assert frame.attrs["units"]["psa"] == "g" and frame.attrs["units"]["sd"] == "m"
    # one damping, one period: one row, the same numbers as the 2-d call
    one = sdof.spectrum(quake, periods=0.5, damping=0.05)
    assert cells(str(one))[1] == rows[1 + 1 * len(periods) + 2]


def test_long_table_is_cut_and_table_shows_all():
    p = pulse.define("half_sine", amp=0.3, amp_unit="g", duration=0.5)
    ratios = np.linspace(0.1, 4.0, 100)
    sh = sdof.shock_spectrum(p, ratios=ratios, damping=0.0)
    short = str(sh).splitlines()
    assert len(short) == 1 + _table.MAX_ROWS + 2          # head, rows, '...', the count
    assert short[1 + _table.MAX_ROWS // 2].split() == ["..."] * 8
    assert short[-1].startswith("[100 rows;")
    full = cells(sh.table())
    assert len(full) == 101
    assert full[0][:4] == ["ratio", "(t_d/T)", "period", "(s)"]
    for k in (0, 57, 99):
        assert full[1 + k] == [g6(x) for x in (sh.ratios[k], sh.periods[k], sh.sd[k], sh.sv[k],
                                                 sh.sa[k], sh.psv[k], sh.psa[k],
                                                 sh.amplification[k])]
    ps = sdof.pulse_spectrum(p, [0.1, 0.5], 0.05)
    prow = cells(str(ps))
    assert prow[0] == ["period", "(s)", "sd", "(m)", "sv", "(m/s)", "sa", "(m/s^2)", "psv",
                       "(m/s)", "psa", "(m/s^2)"]
    assert prow[2] == [g6(x) for x in (0.5, ps.sd[1], ps.sv[1], ps.sa[1], ps.psv[1], ps.psa[1])]


def test_newmark_batch_table(quake):
    kys = [0.05, 0.1, 0.2]
    r = newmark.rigid(quake, ky=kys)
    np.testing.assert_array_equal(r.ky, kys)
    assert r.ky_up is None
    rows = cells(str(r))
    assert rows[0] == ["ky", "(g)", "max_disp", "(m)", "final_disp", "(m)", "u_max", "(m)",
                       "u_min", "(m)", "max_vel", "(m/s)", "t_end", "(s)"]
    for k, ky in enumerate(kys):
        one = newmark.rigid(quake, ky=ky)           # each ky alone gives its row
        assert one.ky == ky
        assert rows[1 + k] == [g6(x) for x in (ky, one.max_disp, one.final_disp, one.u_max,
                                               one.u_min, one.max_vel, one.t_end)]
        assert cells(str(one))[1] == rows[1 + k]
    pytest.importorskip("pandas")
    frame = r.to_frame()
    assert list(frame.columns) == ["ky", "max_disp", "final_disp", "u_max", "u_min", "max_vel",
                                   "t_end"]
    np.testing.assert_array_equal(frame["max_disp"].to_numpy(), r.max_disp)
    asym = newmark.rigid(quake, ky=[0.05, 0.1], mode="asym", ky_up=0.3).to_frame()
    assert list(asym["ky_up"]) == [0.3, 0.3] and asym.attrs["units"]["ky_up"] == "g"


def test_newmark_batch_table_shows_what_varies(quake):
    """k_down (or k_up) varying between rows is a column: each row is that run alone."""
    kd = [0.8, 1.0, 1.2]
    r = newmark.rigid(quake, ky=0.05, mode="asym", ky_up=0.3, k_down=kd)
    np.testing.assert_array_equal(r.k_down, kd)
    np.testing.assert_array_equal(r.k_up, [1.0, 1.0, 1.0])
    rows = cells(str(r))
    assert rows[0][:8] == ["ky", "(g)", "ky_up", "(g)", "k_down", "(-)", "k_up", "(-)"]
    for k, f in enumerate(kd):
        one = newmark.rigid(quake, ky=0.05, mode="asym", ky_up=0.3, k_down=f)
        assert one.k_down == (None if f == 1.0 else f)   # factors of 1 alone: no column
        assert rows[1 + k] == [g6(x) for x in (0.05, 0.3, f, 1.0, one.max_disp, one.final_disp,
                                               one.u_max, one.u_min, one.max_vel, one.t_end)]
    assert len({row[4] for row in rows[1:]}) == 3      # three different max_disp
    # factors of 1 are left out; a two-way run's upslope yield is ky
    plain = newmark.rigid(quake, ky=[0.05, 0.1], mode="asym", ky_up=0.3)
    assert plain.k_down is None and plain.k_up is None
    both = newmark.rigid(quake, ky=[0.05, 0.1], mode="both")
    np.testing.assert_array_equal(both.ky_up, [0.05, 0.1])
    assert cells(str(both))[0][:4] == ["ky", "(g)", "ky_up", "(g)"]
    pytest.importorskip("pandas")
    frame = r.to_frame()
    assert list(frame["k_down"]) == kd and frame.attrs["units"]["k_down"] == "-"


def test_newmark_single_notes_and_table_yield(quake):
    r = newmark.rigid(quake, ky=0.1, history=True, intervals=True)
    lines = str(r).splitlines()
    assert lines[-2] == f"history: time, disp, vel at {quake.npts} samples"
    assert lines[-1] == f"slides: {len(r.slides)} sliding intervals"
    t = newmark.rigid(quake, ky_table=([0.0, 0.01], [0.1, 0.05]))
    assert t.ky is None and cells(str(t))[0][:2] == ["max_disp", "(m)"]


def test_format_number_specials():
    assert [_table.format_number(x) for x in (np.nan, np.inf, -np.inf, 3, 0.1 + 0.2, 1e-7,
                                              123456789.0, "a b")] == \
        ["nan", "inf", "-inf", "3", "0.3", "1e-07", "1.23457e+08", "a b"]


def test_missing_pandas_names_it(comparison, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)     # import pandas now fails
    with pytest.raises(ImportError, match=r"needs the optional package 'pandas'.*"
                                          r"pip install pandas") as info:
        comparison.to_frame()
    assert info.value.name == "pandas"


def test_import_seispulse_imports_no_optional_package():
    code = ("import sys, seispulse, seispulse.records, seispulse.walls; "
            "print(sorted(m for m in ('pandas', 'pyslammer', 'matplotlib') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "[]"


# ------------------------------------------------------------------ records.sample

def pyslammer_folder():
    spec = importlib.util.find_spec("pyslammer")
    if spec is None:
        pytest.skip("pyslammer is not installed (pip install pyslammer)")
    return Path(spec.origin).parent / "sample_ground_motions"


def test_sample_lists_the_files():
    folder = pyslammer_folder()
    names = records.sample()
    assert names == tuple(sorted(p.stem for p in folder.glob("*.csv")))
    assert "Kocaeli_1999_ATS-090" in names and len(names) == 18   # as the README says


def test_sample_without_its_folder_says_so(monkeypatch):
    pyslammer_folder()
    monkeypatch.setattr(records, "_SAMPLE_DIR", "no_such_folder")
    with pytest.raises(ImportError) as info:
        records.sample()
    msg = str(info.value)
    assert info.value.name == "pyslammer"
    assert "has no no_such_folder folder" in msg and \
        "pip install --force-reinstall pyslammer" in msg
    assert "not installed" not in msg


@pytest.mark.parametrize("name", ["Kobe_1995_TAK-090", "Kocaeli_1999_ATS-090.csv"])
def test_sample_reads_like_loadtxt(name):
    folder = pyslammer_folder()
    path = folder / (name if name.endswith(".csv") else name + ".csv")
    data = np.loadtxt(path, delimiter=",", comments="#")
    rec = records.sample(name)
    assert isinstance(rec, records.Record)
    np.testing.assert_array_equal(rec.accel, data[:, 1])          # g, as in the file
    assert rec.dt == pytest.approx(data[1, 0] - data[0, 0], rel=1e-12)
    assert rec.fmt == "slammer" and rec.path == str(path)
    ref = records.read(path)
    np.testing.assert_array_equal(rec.accel, ref.accel)
    assert (rec.dt, rec.name, rec.title) == (ref.dt, ref.name, ref.title)


def test_sample_unknown_name_lists_the_known():
    pyslammer_folder()
    with pytest.raises(InvalidInputError, match=r"name = 'Nowhere_2099'.*Kobe_1995_TAK-090"):
        records.sample("Nowhere_2099")
    with pytest.raises(InvalidInputError, match="name = 3"):
        records.sample(3)


def test_sample_without_pyslammer(monkeypatch):
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "pyslammer" else real(name, *a))
    for args in ((), ("Kobe_1995_TAK-090",)):
        with pytest.raises(ImportError, match=r"optional package 'pyslammer'.*"
                                              r"pip install pyslammer"):
            records.sample(*args)


def test_missing_package_message():
    err = _core.missing_package("foo", "bar()")
    assert isinstance(err, ImportError) and err.name == "foo"
    assert str(err) == ("bar() needs the optional package 'foo', which is not installed: "
                        "pip install foo")
