"""seispulse.records: the formats through read() on fixture files written here (values
known from the text written), the 18 sample records shipped with pySLAMMER against
numpy.loadtxt, the strictness rules (InvalidInputError naming file and line, FileError
for files that cannot be opened), and the Record methods against numpy formulas."""
import os
import threading
from pathlib import Path

import numpy as np
import pytest

from seispulse import records as R
from seispulse.errors import FileError, InvalidInputError

G = 9.80665

AT2_WEST2 = """PEER NGA STRONG MOTION DATABASE RECORD
Imperial Valley-06, 10/15/1979, El Centro Array #6, 230
ACCELERATION TIME SERIES IN UNITS OF G
NPTS=     7, DT=   .0050 SEC
  .1000000E-01  -.2500000E+00   .3125000E-02  -.4000000E-03   .0000000E+00
  -.1234567E-02   .5000000E-01
"""

AT2_OLD_CM = """PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.
LOMA PRIETA 10/18/89 00:05, GILROY ARRAY #1, 000
ACCELERATION TIME HISTORY IN UNITS OF CM/SEC/SEC
    5    .0100    NPTS, DT
  980.665  -490.3325  9.80665  0.0  -1961.33
"""

AT2_HEAD = """PEER NGA STRONG MOTION DATABASE RECORD
title
ACCELERATION TIME SERIES IN UNITS OF G
"""


def write(directory, name, content):
    """A fixture file, bytes as given (no newline translation)."""
    path = Path(directory) / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8"))
    return path


def fails(path, where, *parts, **kwargs):
    """read() raises InvalidInputError starting with '<path><where>' and containing parts."""
    with pytest.raises(InvalidInputError) as info:
        R.read(path, **kwargs)
    msg = str(info.value)
    assert isinstance(info.value, ValueError)
    assert msg.startswith(f"{path}{where}"), msg
    for part in parts:
        assert part in msg, msg
    return msg


# ------------------------------------------------------------------ AT2

def test_at2_west2(tmp_path):
    path = write(tmp_path, "RSN179_IMPVALL.H_H-E06230.AT2", AT2_WEST2)
    rec = R.read(path)
    assert rec.fmt == "at2"
    assert rec.npts == 7 == len(rec.accel)
    assert rec.dt == 0.005
    np.testing.assert_array_equal(rec.accel, [0.01, -0.25, 0.003125, -0.0004, 0.0,
                                              -0.001234567, 0.05])
    assert rec.pga == 0.25
    assert rec.t0 == 0.0
    assert rec.title == "Imperial Valley-06, 10/15/1979, El Centro Array #6, 230"
    assert rec.name == "RSN179_IMPVALL.H_H-E06230"
    assert rec.path == str(path)
    assert rec.scale_factor == 1.0
    assert R.read(path, fmt="at2").accel.tobytes() == rec.accel.tobytes()


def test_at2_old_header_units(tmp_path):
    path = write(tmp_path, "gilroy.txt", AT2_OLD_CM)      # detected by 'PEER' on line 1
    rec = R.read(path)
    assert rec.fmt == "at2" and rec.npts == 5 and rec.dt == 0.01
    np.testing.assert_allclose(rec.accel, [1.0, -0.5, 0.01, 0.0, -2.0], rtol=3e-16, atol=0)
    for alias in ("cm/s2", "cm/s^2", "gal", "GAL"):
        assert R.read(path, units=alias).accel.tobytes() == rec.accel.tobytes()
    fails(path, ":3: ", "the header gives the units as cm/s2", "units = g was passed",
          units="g")
    fails(path, ":3: ", "units = m/s2 was passed", units="m/s^2")


def test_at2_npts_mismatch(tmp_path):
    fewer = write(tmp_path, "fewer.at2", AT2_HEAD + "NPTS=     6, DT=   .0050 SEC\n"
                  "  .1E-01  .2E-01  .3E-01\n  .4E-01  .5E-01\n")
    fails(fewer, ": ", "NPTS = 6", "only 5 values")
    more = write(tmp_path, "more.at2", AT2_HEAD + "NPTS=     4, DT=   .0050 SEC\n"
                 "  .1E-01  .2E-01  .3E-01\n  .4E-01  .5E-01\n")
    fails(more, ":6: ", "more values than NPTS = 4", "'.5E-01'")


def test_at2_bad_header(tmp_path):
    nodt = write(tmp_path, "nodt.at2", AT2_HEAD + "NPTS=     6\n1 2 3 4 5 6\n")
    fails(nodt, ":4: ", "DT missing", "'NPTS=  5590, DT=   .0050 SEC'",
          "'  3999    .0100    NPTS, DT'")
    vel = write(tmp_path, "vel.at2", AT2_WEST2.replace("ACCELERATION", "VELOCITY"))
    fails(vel, ":3: ", "not an acceleration record")
    dtbad = write(tmp_path, "dt.at2", AT2_WEST2)
    fails(dtbad, ":4: ", "DT = 0.005 s, but dt = 0.01 s was given", dt=0.01)
    assert R.read(dtbad, dt=0.005 * (1 + 5e-7)).dt == 0.005


@pytest.mark.parametrize("token", ["abc", "nan", "inf", "1.0.0", "1/2", ".", "1e", "-",
                                   "0x10", "1.5e3x"])
def test_non_numeric_token(tmp_path, token):
    text = AT2_HEAD + "NPTS=     4, DT=   .0050 SEC\n1.0 2.0\n3.0 " + token + "\n"
    path = write(tmp_path, "token.at2", text)
    fails(path, ":6: ", f"non-numeric value '{token}'")


def test_number_forms(tmp_path):
    path = write(tmp_path, "forms.txt", ".0050\n5.\n1D-3\n+2.5e+2\n-0\n"
                 "1.2345678901234567890123\n123456789012345678\n1e-27\n  -3.5d0  \n")
    rec = R.read(path, dt=0.01)
    assert rec.fmt == "column"
    expected = np.array([0.005, 5.0, 0.001, 250.0, -0.0, 1.2345678901234567890123,
                         123456789012345678.0, 1e-27, -3.5])
    assert rec.accel.tobytes() == expected.tobytes()     # -0.0 included


# ------------------------------------------------------------------ text formats

def test_slammer_bom_crlf_trailing_commas(tmp_path):
    content = (b"\xef\xbb\xbf# Time Series: Test 1999 - ABC-090,\r\n"
               b"# Time (s),Acceleration (g's),\r\n0,0.5\r\n0.01, -0.25\r\n0.02 ,1E-03")
    path = write(tmp_path, "Test_1999_ABC-090.csv", content)
    for fmt in ("auto", "slammer"):
        rec = R.read(path, fmt=fmt)
        assert rec.fmt == "slammer"
        assert rec.accel.tolist() == [0.5, -0.25, 0.001]
        assert rec.dt == 0.01
        assert rec.title == "Time Series: Test 1999 - ABC-090"
        assert rec.name == "Test_1999_ABC-090"


def test_time_accel(tmp_path):
    path = write(tmp_path, "two.dat", "# first comment\n# second\n# third\n\n1.0\t0.25\n"
                 "1.1 , -0.5\n# inside\n   \n1.2 0.125\n1.3,1\n1.4  -1\n")
    rec = R.read(path)
    assert rec.fmt == "time_accel"
    assert rec.accel.tolist() == [0.25, -0.5, 0.125, 1.0, -1.0]
    assert rec.t0 == 1.0
    assert rec.dt == pytest.approx(0.1, rel=1e-15)
    assert rec.title == "first comment"
    np.testing.assert_allclose(rec.time, np.arange(5) * rec.dt, rtol=0, atol=0)
    cm = write(tmp_path, "cm.txt", "0 980.665\n0.5 -490.3325\n")
    np.testing.assert_allclose(R.read(cm, units="cm/s2").accel, [1.0, -0.5], rtol=3e-16)
    np.testing.assert_allclose(R.read(cm, units="m/s2").accel, [100.0, -50.0], rtol=3e-16)


def test_time_accel_errors(tmp_path):
    grid = write(tmp_path, "grid.txt", "# t a\n0.0 1\n0.1 2\n0.2 3\n0.35 4\n0.4 5\n0.5 6\n")
    fails(grid, ":5: ", "time 0.35 is off the uniform time grid", "expected 0.3",
          "dt = 0.1 s")
    order = write(tmp_path, "order.txt", "0.0 1\n0.1 2\n0.1 3\n0.3 4\n")
    fails(order, ":3: ", "time 0.1 is not after the previous time 0.1 (line 2)")
    three = write(tmp_path, "three.txt", "0.0 1\n0.1 2 3\n")
    fails(three, ":2: ", "expected 2 values (time, acceleration), found 3")
    three_first = write(tmp_path, "three_first.txt", "# c\n0.0 1 2\n")
    fails(three_first, ":2: ", "expected 1 or 2 numbers", "'0.0 1 2'")
    ok = write(tmp_path, "ok.txt", "0 1\n0.02 2\n0.04 3\n")
    fails(ok, ": ", "the times give dt = 0.02 s", "dt = 0.01 s was given", dt=0.01)
    assert R.read(ok, dt=0.02).dt == pytest.approx(0.02, rel=1e-15)
    empty_value = write(tmp_path, "empty_value.csv", "0,1\n0.1,,2\n")
    fails(empty_value, ":2: ", "empty value")


def test_single_column(tmp_path):
    path = write(tmp_path, "column.txt", "# accel in g\n0.5\n\n-0.75\n# note\n  1.25E-1  \n")
    rec = R.read(path, dt=0.02)
    assert rec.fmt == "column" and rec.dt == 0.02 and rec.t0 == 0.0
    assert rec.accel.tolist() == [0.5, -0.75, 0.125]
    msg = fails(path, ": ", "dt: a single-column file has no time step; give dt")
    assert "line" not in msg


def test_empty_missing_directory(tmp_path):
    fails(write(tmp_path, "empty.txt", ""), ": ", "empty file")
    fails(write(tmp_path, "comments.txt", "# a\n\n# b\n"), ": ", "no data")
    missing = tmp_path / "missing.AT2"
    with pytest.raises(FileError) as info:
        R.read(missing)
    assert isinstance(info.value, OSError)
    assert str(info.value).startswith(f"{missing}: cannot open: ")
    with pytest.raises(FileError, match="cannot read"):
        R.read(tmp_path)


def test_long_lines(tmp_path):
    n = 20000
    values = [f"{k}.5E-03" for k in range(-n // 2, n // 2)]
    text = AT2_HEAD + f"NPTS= {n}, DT= 0.01\n" + " ".join(values) + "\n"
    rec = R.read(write(tmp_path, "long.at2", text))
    assert rec.npts == n
    assert rec.accel.tobytes() == np.array([float(v) for v in values]).tobytes()
    comment = "#" + "c" * 100000 + "\n#\n0 1\n0.5 2\n"
    rec = R.read(write(tmp_path, "longcomment.csv", comment))
    # the title crosses the f2py layer as character*256
    assert rec.npts == 2 and rec.title == "c" * 256


def test_paths_with_spaces_and_non_ascii(tmp_path):
    path = write(tmp_path / "dir with spaces" / "sous-dossier é", "Düzce 1999 ü.csv",
                 "# Düzce\n# t, a\n0,0.5\n0.01,-0.25\n")
    for arg in (path, str(path), os.fsencode(path)):
        rec = R.read(arg)
        assert rec.name == "Düzce 1999 ü"
        assert rec.title == "Düzce"
        assert rec.path == str(path)
        assert rec.accel.tolist() == [0.5, -0.25]
    bad = write(tmp_path / "dir with spaces", "mauvais é.csv", "0,1\n0.1,x\n")
    fails(bad, ":2: ", "non-numeric value 'x'")
    with pytest.raises(FileError, match="cannot open"):
        R.read(tmp_path / "dir with spaces" / "absent é.csv")


# ------------------------------------------------------------------ pySLAMMER samples

def _pyslammer_files():
    pyslammer = pytest.importorskip(
        "pyslammer", reason="pyslammer (pip install pyslammer) provides the 18 sample records")
    files = sorted((Path(pyslammer.__file__).parent / "sample_ground_motions").glob("*.csv"))
    assert files, "pyslammer is installed but has no sample_ground_motions/*.csv"
    return files


@pytest.mark.parametrize("fmt", ["auto", "slammer"])
def test_pyslammer_samples_equal_loadtxt(fmt):
    files = _pyslammer_files()
    for f in files:
        ref = np.loadtxt(f, delimiter=",", comments="#", encoding="utf-8-sig")
        rec = R.read(f, fmt=fmt)
        assert rec.fmt == "slammer", f.name
        assert rec.npts == ref.shape[0], f.name
        assert rec.accel.tobytes() == np.ascontiguousarray(ref[:, 1]).tobytes(), f.name
        assert rec.dt == pytest.approx(ref[1, 0] - ref[0, 0], abs=1e-12), f.name
        assert rec.dt == pytest.approx((ref[-1, 0] - ref[0, 0]) / (ref.shape[0] - 1),
                                       abs=1e-15), f.name
        assert rec.t0 == ref[0, 0]
        assert rec.name == f.stem
        assert rec.title.startswith("Time Series: "), rec.title
        assert rec.pga == np.max(np.abs(ref[:, 1]))


def test_pyslammer_kocaeli_slammer_scaling():
    files = {f.name: f for f in _pyslammer_files()}
    rec = R.read(files["Kocaeli_1999_ATS-090.csv"])
    assert rec.npts == 26780 and rec.pga == 0.184882
    s = rec.scaled_to_pga(0.3, rounding="slammer")
    assert s.scale_factor == pytest.approx(0.3 / 0.185, rel=1e-15)
    assert s.pga == pytest.approx(0.184882 * 0.3 / 0.185, rel=1e-15)


# ------------------------------------------------------------------ Record

def test_record_methods():
    a = np.array([0.0, 0.1, -0.184882, 0.05, 0.02])
    rec = R.from_array(a, 0.01, name="synthetic")
    assert rec.fmt == "array" and rec.path is None and rec.name == "synthetic"
    assert rec.pga == 0.184882 and rec.npts == 5 and rec.t0 == 0.0
    with pytest.raises(ValueError):
        rec.accel[0] = 1.0                                 # read-only
    s = rec.scaled(2.5)
    assert s.accel.tobytes() == (a * 2.5).tobytes() and s.scale_factor == 2.5
    assert rec.scale_factor == 1.0 and rec.accel.tobytes() == a.tobytes()
    e = rec.scaled_to_pga(0.3)
    assert e.pga == pytest.approx(0.3, rel=1e-15)
    assert e.scale_factor == 0.3 / 0.184882
    sl = rec.scaled_to_pga(0.3, rounding="slammer")
    assert sl.scale_factor == pytest.approx(0.3 / 0.185, rel=2e-16)
    np.testing.assert_allclose(sl.accel, a * (0.3 / 0.185), rtol=2e-16)
    inv = rec.inverted()
    assert inv.accel.tobytes() == (-a).tobytes() and inv.scale_factor == -1.0
    assert inv.scaled(2.0).scale_factor == -2.0
    assert inv.pga == rec.pga
    np.testing.assert_array_equal(rec.time, np.arange(5) * 0.01)
    assert "synthetic" in repr(rec) and "npts=5" in repr(rec)


def test_scaling_errors():
    rec = R.from_array([0.0004, -0.0002], 0.01)
    with pytest.raises(InvalidInputError, match=r"rounds to 0\.000 g, SLAMMER scaling"):
        rec.scaled_to_pga(0.3, rounding="slammer")
    assert rec.scaled_to_pga(0.3).scale_factor == pytest.approx(750.0, rel=1e-15)
    with pytest.raises(InvalidInputError, match=r"^target_pga = -1.0: must be"):
        rec.scaled_to_pga(-1.0)
    with pytest.raises(InvalidInputError, match=r"^rounding = 'nearest'"):
        rec.scaled_to_pga(0.3, rounding="nearest")
    zero = R.from_array([0.0, 0.0], 0.01)
    with pytest.raises(InvalidInputError, match=r"^pga = 0.0: must be"):
        zero.scaled_to_pga(0.3)
    for bad in (0.0, np.nan, np.inf, "x"):
        with pytest.raises(InvalidInputError, match=r"^factor"):
            rec.scaled(bad)


def test_velocity_displacement_against_numpy():
    rng = np.random.default_rng(7)
    a = rng.normal(0.0, 0.1, 2001)
    dt, g = 0.005, 9.81
    rec = R.from_array(a, dt)
    v, d = rec.velocity(g=g), rec.displacement(g=g)
    # cumulative trapezoid of g a, and the exact double integral of the linear pieces
    v_ref = np.concatenate([[0.0], np.cumsum(g * dt * (a[:-1] + a[1:]) / 2)])
    d_ref = np.concatenate([[0.0], np.cumsum(v_ref[:-1] * dt
                                             + g * dt**2 * (2 * a[:-1] + a[1:]) / 6)])
    np.testing.assert_allclose(v, v_ref, rtol=0, atol=1e-12 * np.max(np.abs(v_ref)))
    np.testing.assert_allclose(d, d_ref, rtol=0, atol=1e-12 * np.max(np.abs(d_ref)))
    # default g: standard gravity
    np.testing.assert_allclose(rec.velocity(), v * G / g, rtol=1e-13,
                               atol=1e-15 * np.max(np.abs(v)))


def test_velocity_displacement_closed_form():
    # a(t) = c0 + c1 t (g): v = g (c0 t + c1 t^2/2), d = g (c0 t^2/2 + c1 t^3/6), exactly
    c0, c1, dt, g = 0.3, -0.8, 0.01, 9.81
    t = np.arange(101) * dt
    rec = R.from_array(c0 + c1 * t, dt)
    np.testing.assert_allclose(rec.velocity(g), g * (c0 * t + c1 * t**2 / 2), rtol=1e-13,
                               atol=1e-15)
    np.testing.assert_allclose(rec.displacement(g), g * (c0 * t**2 / 2 + c1 * t**3 / 6),
                               rtol=1e-13, atol=1e-16)
    const = R.from_array(np.full(51, 0.25), 0.02)
    tc = const.time
    np.testing.assert_allclose(const.displacement(g), g * 0.25 * tc**2 / 2, rtol=1e-13)
    with pytest.raises(InvalidInputError, match=r"^g = 0.0: must be"):
        const.velocity(g=0.0)


def test_record_constructor_validation():
    with pytest.raises(InvalidInputError, match=r"^accel: must be a 1-d array"):
        R.Record(np.zeros((2, 2)), 0.01)
    with pytest.raises(InvalidInputError, match=r"^accel: the record is empty"):
        R.Record([], 0.01)
    with pytest.raises(InvalidInputError, match=r"^accel\[1\] = nan: must be finite"):
        R.Record([0.0, np.nan], 0.01)
    with pytest.raises(InvalidInputError, match=r"^accel: must be a real number"):
        R.Record(["a", "b"], 0.01)
    for dt in (0.0, -0.01, np.nan, np.inf, "x"):
        with pytest.raises(InvalidInputError, match=r"^dt"):
            R.Record([0.0, 1.0], dt)
    with pytest.raises(InvalidInputError, match=r"^t0"):
        R.Record([0.0, 1.0], 0.01, t0=np.nan)
    rec = R.Record([1, 2, 3], 0.5, name="x", title="y", t0=2.0)
    assert rec.accel.dtype == np.float64 and rec.dt == 0.5 and rec.t0 == 2.0


def test_from_array_units():
    a = [9.80665, -4.903325]
    np.testing.assert_allclose(R.from_array(a, 0.01, units="m/s2").accel, [1.0, -0.5],
                               rtol=3e-16)
    np.testing.assert_allclose(R.from_array(a, 0.01, units="m/s^2").accel, [1.0, -0.5],
                               rtol=3e-16)
    np.testing.assert_allclose(R.from_array([980.665], 0.01, units="gal").accel, [1.0],
                               rtol=3e-16)
    with pytest.raises(InvalidInputError, match=r"^units = 'ft/s2'"):
        R.from_array(a, 0.01, units="ft/s2")


def test_read_argument_errors(tmp_path):
    path = write(tmp_path, "ok.csv", "0 1\n0.1 2\n")
    with pytest.raises(InvalidInputError, match=r"^fmt = 'csv'"):
        R.read(path, fmt="csv")
    with pytest.raises(InvalidInputError, match=r"^units = 'furlongs'"):
        R.read(path, units="furlongs")
    with pytest.raises(InvalidInputError, match=r"^dt = -1.0"):
        R.read(path, dt=-1.0)
    with pytest.raises(InvalidInputError, match=r"^path"):
        R.read(None)
    with pytest.raises(InvalidInputError, match=r"NUL"):
        R.read("a\0b")


def test_concurrent_reads(tmp_path):
    paths = [write(tmp_path, f"r{k}.csv", "".join(f"{i * 0.01},{k + i}\n" for i in range(500)))
             for k in range(8)]
    results, errors = {}, []

    def worker(k):
        try:
            for _ in range(20):
                rec = R.read(paths[k])
                assert rec.accel[0] == k and rec.npts == 500 and rec.name == f"r{k}"
            results[k] = True
        except Exception as exc:  # collected and reported by the main thread
            errors.append(exc)

    threads = [threading.Thread(target=worker, args=(k,)) for k in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    assert len(results) == 8
