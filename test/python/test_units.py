"""One vocabulary of acceleration units (seispulse_records accel_unit_code): Python
(pulse amp_unit, records units) and the driver (&pulse amp_unit, &records units) accept
the same names, in any case, and refuse the same others with the same message."""
import re
import subprocess

import numpy as np
import pytest

from seispulse import pulse, records
from seispulse.errors import InvalidInputError

G = 9.80665
NAMES = {"g": G, "G": G, "m/s2": 1.0, "M/S2": 1.0, "m/s^2": 1.0, "cm/s2": 0.01,
         "cm/s^2": 0.01, "CM/S^2": 0.01, "gal": 0.01, "Gal": 0.01, "GAL": 0.01}
ALLOWED = "(allowed: g, m/s2, m/s^2, cm/s2, cm/s^2, gal)"


@pytest.mark.parametrize("name", sorted(NAMES))
def test_python_pulse_and_record_units(name):
    to_si = NAMES[name]
    # a half-sine of amplitude 2 (in `name`) at its crest: 2 x (m/s^2 per unit)
    assert pulse.half_sine(0.5, 2.0, 1.0, amp_unit=name).a == pytest.approx(2.0 * to_si,
                                                                              rel=1e-15)
    rec = records.from_array(np.array([0.0, 2.0, -1.0]), 0.01, units=name)
    np.testing.assert_allclose(rec.accel, np.array([0.0, 2.0, -1.0]) * to_si / G, rtol=1e-15)
    assert records.accel_unit_factor(name, g=9.81) == pytest.approx(
        {G: 1.0, 1.0: 1 / 9.81, 0.01: 1 / 981.0}[to_si], rel=1e-15)


@pytest.mark.parametrize("bad", ["ft/s2", "m/s", "", "gals"])
def test_python_refuses_the_same_names(bad):
    for call in (lambda: pulse.half_sine(0.5, 2.0, 1.0, amp_unit=bad),
                 lambda: records.from_array(np.zeros(3), 0.01, units=bad)):
        with pytest.raises(InvalidInputError, match=re.escape(ALLOWED)):
            call()


@pytest.mark.parametrize("bad", ["m/s\u00b2", "cm/s\u00b2", "\u00b5g", None, 9.81])
def test_non_ascii_or_not_a_str_names_the_argument_and_the_list(bad, tmp_path):
    """f2py takes ASCII only: 'm/s²' (and a value that is no str) must still give the
    library's InvalidInputError naming the argument, the value and the allowed names."""
    calls = {"amp_unit": (lambda: pulse.half_sine(0.5, 2.0, 1.0, amp_unit=bad),
                          lambda: pulse.define("half_sine", amp=2.0, amp_unit=bad,
                                               duration=1.0)),
             "units": (lambda: records.from_array(np.zeros(3), 0.01, units=bad),
                       lambda: records.accel_unit_factor(bad))
             + ((lambda: records.read(tmp_path / "none.txt", units=bad),) if bad is not None
                else ())}   # read: None is the file's own unit
    for name, entries in calls.items():
        for call in entries:
            with pytest.raises(InvalidInputError) as info:
                call()
            msg = str(info.value)
            assert msg.startswith(f"{name} = {bad!r}: ") and msg.endswith(ALLOWED), msg


def run(driver, tmp_path, text):
    (tmp_path / "u.nml").write_text(text)
    return subprocess.run([driver, "u.nml"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=60)


@pytest.mark.parametrize("name", sorted(NAMES))
def test_driver_accepts_the_same_names(driver, tmp_path, name):
    to_si = NAMES[name]
    proc = run(driver, tmp_path, "&run analysis='pulse', output='p' /\n"
               f"&pulse kind='half_sine', amp=2.0, amp_unit='{name}', duration=1.0 /\n"
               "&time t_end=1.0, npts=3 /\n")
    assert proc.returncode == 0, proc.stderr
    a = np.loadtxt(tmp_path / "p_pulse.csv", delimiter=",", skiprows=1, ndmin=2)[:, 1]
    assert a[1] == pytest.approx(2.0 * to_si, rel=1e-15)
    (tmp_path / "r.txt").write_text("0.0\n2.0\n-1.0\n")
    proc = run(driver, tmp_path, "&run analysis='newmark', output='n' /\n"
               f"&records files='r.txt', units='{name}', dt=0.01 /\n&newmark ky=10 /\n")
    assert proc.returncode == 0, proc.stderr
    # the table's pga (g) at full precision: |2 units| in g (the progress line on stderr
    # has 4 digits only, too few to tell g = 9.81 from 9.80665)
    pga = np.loadtxt(tmp_path / "n_newmark.csv", delimiter=",", skiprows=1, ndmin=2,
                     usecols=1)[0]
    assert pga == pytest.approx(2.0 * to_si / G, rel=1e-15)


@pytest.mark.parametrize("bad", ["ft/s2", "gals"])
def test_driver_refuses_the_same_names(driver, tmp_path, bad):
    proc = run(driver, tmp_path, "&run analysis='pulse', output='p' /\n"
               f"&pulse kind='half_sine', amp_unit='{bad}' /\n")
    assert proc.returncode == 2
    assert f"&pulse: amp_unit = '{bad}': unknown acceleration unit {ALLOWED}" in proc.stderr
    proc = run(driver, tmp_path, "&run analysis='newmark', output='n' /\n"
               f"&records files='r.txt', units='{bad}', dt=0.01 /\n&newmark ky=10 /\n")
    assert proc.returncode == 2
    assert f"&records: units = '{bad}': unknown acceleration unit {ALLOWED}" in proc.stderr
