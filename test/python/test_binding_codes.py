"""Named Fortran codes reach Python from the sources (gen_binding.py codes)."""

import importlib.util
import os
from pathlib import Path

import pytest

from seispulse import _fortran_codes, errors, records, rocking, sliding

ROOT = Path(os.environ.get("SEISPULSE_SOURCE_ROOT", Path(__file__).resolve().parents[2]))
GEN = ROOT / "python" / "seispulse" / "gen_binding.py"


@pytest.fixture(scope="module")
def gen():
    spec = importlib.util.spec_from_file_location("gen_binding", GEN)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_parameters_with_continuations_comments_and_conflicts(gen, tmp_path):
    a = tmp_path / "a.f90"
    a.write_text("module a\n"
                 "    integer, parameter :: A_ONE = 1, A_TWO = 2, &  !! two codes\n"
                 "                          A_THREE = -3\n"
                 "    integer, parameter :: n_local = 40  ! a limit, not a code\n"
                 "    integer, parameter :: SAME = 5\n"
                 "    real(dp), parameter :: A_REAL = 1.0_dp\n"
                 "end module a\n")
    b = tmp_path / "b.f90"
    b.write_text("module b\n    integer, parameter :: SAME = 6, OTHER = 7\nend module b\n")
    found = gen.integer_parameters([a, b], upper_only=True)
    assert found == {"A_ONE": 1, "A_TWO": 2, "A_THREE": -3, "SAME": None, "OTHER": 7}
    assert gen.integer_parameters([a])["N_LOCAL"] == 40


def test_library_codes_reach_python():
    assert _fortran_codes.SEISPULSE_SUCCESS == 0
    assert errors.STATUS_ERRORS[_fortran_codes.SEISPULSE_IO] is errors.FileError
    # every name table against the Fortran constant names themselves: the code of
    # SLIDING_MODE_STICK must index "stick", and so on for each entry
    codes = vars(_fortran_codes)

    def by_names(prefix, rename=None):
        table = {v: n[len(prefix):].lower() for n, v in codes.items()
                 if n.startswith(prefix) and not n[len(prefix):].startswith("RUN_")}
        for old, new in (rename or {}).items():
            table = {k: (new if v == old else v) for k, v in table.items()}
        return tuple(table[k] for k in sorted(table))

    assert rocking.REGIONS == tuple(n if n in ("no_rocking",) else n.upper() for n in
                                    by_names("ROCK_", {"none": "no_rocking"}))
    assert rocking.OUTCOMES == by_names("ROCK_RUN_", {"overturn_many": "overturn_many_impacts"})
    assert sliding.MODES == by_names("SLIDING_MODE_")
    assert sliding.REGIMES == by_names("SLIDING_REGIME_")
    assert records.FORMATS == by_names("RECORD_")


def test_loop_wrapper_from_its_description(gen):
    spec = ("!> doc\n"
            "sp_demo(x, flag:int, s:real, >y, >k:int, >z(3))\n"
            "    some_module: demo(x, flag /= 0, s, y, k, z(2), z, stat, errmsg)\n")
    (entry,) = gen.loop_entries(spec)
    text = gen.loop_routine(*entry)
    assert text.splitlines()[:2] == ["!> doc",
                                     "subroutine sp_demo(n, x, flag, s, y, k, z, stat, errmsg)"]
    for line in ("    real(dp), intent(in) :: x(n)", "    integer, intent(in) :: flag",
                 "    real(dp), intent(in) :: s", "    real(dp), intent(out) :: y(n)",
                 "    integer, intent(out) :: k(n)", "    real(dp), intent(out) :: z(n, 3)",
                 "    !f2py intent(hide) :: n", "    y = 0.0_dp", "    k = 0",
                 "        call demo(x(i), flag /= 0, s, y(i), k(i), z(i, 2), z(i, :), stat, errmsg)",
                 "        if (stat /= SEISPULSE_SUCCESS) return"):
        assert line in text.splitlines()
    assert max(map(len, text.splitlines())) <= 100


def test_loop_wrapper_with_a_derived_type_result(gen):
    spec = ("sp_demo(x, flag:int,\n"
            "        >a=r%a, >k:int=r%k)\n"
            "    some_module: demo(x, flag, r, stat, errmsg)\n"
            "    type(demo_t) :: r\n")
    (entry,) = gen.loop_entries(spec)
    lines = gen.loop_routine(*entry).splitlines()
    assert lines[0] == "subroutine sp_demo(n, x, flag, a, k, stat, errmsg)"
    assert "    use some_module, only: demo_t, demo" in lines
    assert "    type(demo_t) :: r" in lines
    call = lines.index("        call demo(x(i), flag, r, stat, errmsg)")
    assert lines[call + 1:call + 4] == ["        if (stat /= SEISPULSE_SUCCESS) return",
                                        "        a(i) = r%a", "        k(i) = r%k"]


def test_loop_wrapper_with_a_check_then_a_function(gen):
    # two statements in their order: the checking call (stat tested), then a function
    # without stat whose result is y(i); each module used once with its names
    spec = ("sp_demo(x, s:real, >y)\n"
            "    mod_a: check(x, stat, errmsg)\n"
            "    mod_b: y = f(x, s,\n"
            "                 x)\n")
    (entry,) = gen.loop_entries(spec)
    lines = gen.loop_routine(*entry).splitlines()
    assert lines[0] == "subroutine sp_demo(n, x, s, y, stat, errmsg)"
    assert "    use mod_a, only: check" in lines and "    use mod_b, only: f" in lines
    loop = lines.index("    do i = 1, n")
    assert lines[loop + 1:loop + 5] == ["        call check(x(i), stat, errmsg)",
                                        "        if (stat /= SEISPULSE_SUCCESS) return",
                                        "        y(i) = f(x(i), s, x(i))",
                                        "    end do"]


def test_pulse_parameter_positions_from_fortran():
    # pulse.define packs by the positions PULSE_PARAM_<NAME> of pulses.f90: one position
    # per parameter, 1 .. PULSE_NPARAM, none missing, in the order pulse_from_params reads
    from seispulse import pulse
    positions = sorted(v for n, v in vars(_fortran_codes).items()
                       if n.startswith("PULSE_PARAM_"))
    assert positions == list(range(1, _fortran_codes.PULSE_NPARAM + 1))
    assert pulse._PARAM_ORDER == ("amp", "duration", "beta", "full", "peak_frac", "freq",
                                  "t0", "gamma", "nu_deg", "cycles")
    packed = pulse.define("mavroeidis_papageorgiou", vamp=0.7, freq=1.3, gamma=2.5,
                          nu_deg=40.0, t0=1.5).params
    assert packed[_fortran_codes.PULSE_PARAM_FREQ - 1] == 1.3
    assert packed[_fortran_codes.PULSE_PARAM_NU_DEG - 1] == 40.0
    assert packed[_fortran_codes.PULSE_PARAM_CYCLES - 1] == 1.0
    packed = pulse.define("sine_cycle", amp=2.0, period=0.5, cycles=20).params
    assert packed[_fortran_codes.PULSE_PARAM_CYCLES - 1] == 20.0
