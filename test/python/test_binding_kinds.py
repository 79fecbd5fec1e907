"""The f2py layer passes real(dp) as C double everywhere: a kind f2py misreads becomes a C
float and silently rounds every number to single precision."""

import importlib.util
import os
import re
from pathlib import Path

import numpy as np

from seispulse import _seispulse

ROOT = Path(os.environ.get("SEISPULSE_SOURCE_ROOT", Path(__file__).resolve().parents[2]))

# 1 + 2^-40 and an odd multiple of a tiny power of two: neither is a float32 value.
NOT_SINGLE = (1.0 + 2.0**-40, 3.0e-300 * 3.0)


def _routines():
    return sorted(name for name in dir(_seispulse) if name.startswith("sp_"))


def test_no_routine_has_a_single_precision_array():
    found = []
    for name in _routines():
        doc = getattr(_seispulse, name).__doc__
        for line in doc.splitlines():
            m = re.match(r"(\w+) : .*array\('(\w)'\)", line)
            if m and m.group(2) not in "diD":      # double, int, complex double
                found.append(f"{name}: {line.strip()}")
    assert found == []
    assert len(_routines()) > 50


def test_build_check_finds_single_precision(tmp_path):
    """The build's kind check (gen_binding.check_kinds) flags every single-precision form
    f2py can write, and a kind missing from the map; f2py's docstrings say "float" for C
    float and C double alike, so only this check guards the scalars."""
    spec = importlib.util.spec_from_file_location(
        "gen_binding", ROOT / "python" / "seispulse" / "gen_binding.py")
    gen = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(gen)
    f2cmap = ROOT / "python" / "seispulse" / ".f2py_f2cmap"
    good_pyf = "real(kind=dp) :: x\ncomplex(kind=dp) :: z\n"
    good_c = "    double x = 0;\n    complex_double z;\n    NPY_DOUBLE\n"
    assert gen.check_kinds(good_pyf, good_c, f2cmap) == []
    for c_text in ("    float y = 0;\n", "    complex_float z;\n", "  type_num = NPY_FLOAT;\n",
                   "  type_num = NPY_CFLOAT;\n"):
        assert len(gen.check_kinds(good_pyf, good_c + c_text, f2cmap)) == 1, c_text
    assert len(gen.check_kinds("real(kind=sp) :: y\n", good_c, f2cmap)) == 1


def test_scalar_roundtrip_keeps_double_precision():
    # sp_rocking_block(2, ...) returns R (its first real argument) unchanged.
    for r in NOT_SINGLE:
        *_, r_out, stat, _ = _seispulse.sp_rocking_block(2, r, 0.2, 4.0 / 3.0, 9.81)
        assert stat == 0
        assert isinstance(r_out, float)
        assert r_out == r
        assert float(np.float32(r)) != r


def test_array_roundtrip_keeps_double_precision():
    # sp_limit_form(1, ...) fills out[:, 0:4] and leaves the in/out column 4 as given.
    eta = np.array([0.3, 0.5])
    out = np.zeros((2, 5), order="F")
    out[:, 4] = NOT_SINGLE
    out = _seispulse.sp_limit_form(1, eta, out)
    assert out.dtype == np.float64
    assert list(out[:, 4]) == list(NOT_SINGLE)


def test_many_intervals_come_back_from_one_run():
    """More sliding intervals than any first guess of a buffer: all of them, in time order,
    adding up to the final displacement; a run without intervals leaves none behind."""
    from seispulse import newmark
    dt = 0.01
    t = np.arange(0.0, 150.0, dt)
    accel = 0.5 * np.sin(2.0 * np.pi * t)
    plain = newmark.rigid(accel, dt, ky=0.1)
    run = newmark.rigid(accel, dt, ky=0.1, intervals=True)
    assert run.slides is not None and len(run.slides) >= 140
    starts = [s.t_start for s in run.slides]
    assert starts == sorted(starts)
    assert all(s.t_stop > s.t_start for s in run.slides)
    total = sum(s.u_stop - s.u_start for s in run.slides)
    assert abs(total - run.final_disp) <= 1e-9 * abs(run.final_disp)
    assert plain.final_disp == run.final_disp
    assert plain.slides is None
