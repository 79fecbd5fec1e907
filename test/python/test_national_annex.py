"""EN 1998-1 spectra with the seismic zones of the Greek National Annex
(seispulse.codes.reference_pga, zone= / national_annex= / importance= of elastic_spectrum
and design_spectrum):

* the zones against the values of the 2003 map that the Greek NA adopted (Z1 0.16 g,
  Z2 0.24 g, Z3 0.36 g): Pitilakis, Riga, Apostolaki, Danciu 2024 state the adoption and
  three zones spanning 0.16-0.36 g; the middle value 0.24 g and the names Z1-Z3 are from
  press reports of the 2003 amendment (secondary, as doc/eak2000.md section 3);
* a zone's spectrum is, bit for bit, the spectrum of ag = importance x a_gR, and the
  elastic spectrum of Z2 on ground B is transcribed again here (S = 1.2, TB = 0.15,
  TC = 0.5, TD = 2 s, EN 1998-1 Table 3.2);
* positional calls of the spectra are unchanged;
* every refusal names the parameter and the allowed values.
"""
import re

import numpy as np
import pytest

from seispulse import InvalidInputError
from seispulse import _fortran_codes
from seispulse import codes as C

ZONES_2003 = {"Z1": 0.16, "Z2": 0.24, "Z3": 0.36}   # g (see the module docstring)
PERIODS = np.array([0.0, 0.05, 0.15, 0.3, 0.5, 0.8, 2.0, 3.0, 4.5])


def test_constants_and_fortran_codes():
    assert C.NATIONAL_ANNEXES == ("GR",)
    assert C.GR_ZONES == ZONES_2003
    assert _fortran_codes.EC8_ANNEX_RECOMMENDED == 0
    assert _fortran_codes.EC8_ANNEX_GR == 1
    for name in ("NATIONAL_ANNEXES", "GR_ZONES", "reference_pga"):
        assert name in C.__all__


@pytest.mark.parametrize("zone, number", [("Z1", 1), ("Z2", 2), ("Z3", 3)])
def test_reference_pga_of_each_zone(zone, number):
    agr = ZONES_2003[zone]
    assert C.reference_pga(zone) == agr
    assert C.reference_pga(number) == agr
    assert C.reference_pga(np.int64(number)) == agr
    assert C.reference_pga(zone.lower()) == agr
    assert C.reference_pga(f" {zone} ", national_annex="gr") == agr
    assert C.reference_pga(zone, national_annex=None) == agr
    assert C.reference_pga(zone, "GR") == agr


@pytest.mark.parametrize("zone", ["Z1", "Z2", "Z3", 1, 3])
@pytest.mark.parametrize("importance", [1.0, 0.8, 1.2, 1.4])
def test_zone_spectrum_is_ag_spectrum_bit_for_bit(zone, importance):
    ag = importance * ZONES_2003[zone if isinstance(zone, str) else f"Z{zone}"]
    for ground in ("A", "B", "E"):
        for typ in (1, 2):
            se = C.elastic_spectrum(PERIODS, spectrum_type=typ, ground=ground, xi_percent=3.0,
                                    zone=zone, importance=importance)
            np.testing.assert_array_equal(se, C.elastic_spectrum(PERIODS, ag, typ, ground, 3.0))
            sd = C.design_spectrum(PERIODS, None, typ, ground, 3.0, 0.2, zone=zone,
                                   national_annex="GR", importance=importance)
            np.testing.assert_array_equal(sd, C.design_spectrum(PERIODS, ag, typ, ground, 3.0,
                                                                0.2))


def test_zone_spectrum_transcribed():
    # Z2, gamma_I = 1.2, ground B, Type 1, 5 %: ag = 0.288 g, S = 1.2, TB = 0.15, TC = 0.5,
    # TD = 2.0 (EN 1998-1 (3.2)-(3.5) and Table 3.2)
    ag, s, tb, tc, td = 0.24 * 1.2, 1.2, 0.15, 0.5, 2.0
    t = np.array([0.0, 0.075, 0.3, 1.0, 4.0])
    expected = [ag * s, ag * s * (1 + 0.5 * 1.5), 2.5 * ag * s, 2.5 * ag * s * tc / 1.0,
                2.5 * ag * s * tc * td / 16.0]
    np.testing.assert_allclose(C.elastic_spectrum(t, ground="B", zone="Z2", importance=1.2),
                               expected, rtol=1e-14)
    # design, q = 3: floor beta ag at 4 s (2.5 ag S TC TD/(q T^2) = 0.018 < 0.0576)
    sd = C.design_spectrum(4.0, ground="B", q=3.0, zone="Z2", importance=1.2)
    assert sd == pytest.approx(0.2 * ag, rel=1e-15)


def test_positional_calls_unchanged():
    assert C.elastic_spectrum(0.3, 0.24, 1, "B") == pytest.approx(0.72, rel=1e-15)
    assert C.elastic_spectrum(0.3, 0.24, 1, "B", 5.0) == C.elastic_spectrum(
        0.3, ag=0.24, spectrum_type=1, ground="B", xi_percent=5.0)
    assert C.design_spectrum(0.3, 0.24, 1, "B", 3.0, 0.2) == pytest.approx(0.24, rel=1e-15)
    assert C.design_spectrum(0.3, 0.24) == C.design_spectrum(0.3, 0.24, 1, "A", 1.5, 0.2)
    # an explicit importance of 1 and the annex without a zone change nothing
    assert C.elastic_spectrum(0.3, 0.24, 1, "B", importance=1.0) == C.elastic_spectrum(
        0.3, 0.24, 1, "B")
    assert C.design_spectrum(0.3, 0.24, national_annex="GR") == C.design_spectrum(0.3, 0.24)


def test_keywords_are_keyword_only():
    with pytest.raises(TypeError):
        C.elastic_spectrum(0.3, 0.24, 1, "B", 5.0, "Z2")
    with pytest.raises(TypeError):
        C.design_spectrum(0.3, 0.24, 1, "B", 1.5, 0.2, "Z2")


ZONES = re.escape("(allowed: 'Z1', 'Z2', 'Z3' or 1, 2, 3)")
ANNEXES = re.escape("(allowed: 'GR';")


@pytest.mark.parametrize("fun", [C.elastic_spectrum, C.design_spectrum])
@pytest.mark.parametrize("kwargs, pattern", [
    ({}, r"^ag: give the design ground acceleration ag, or a seismic zone"),
    ({"ag": 0.24, "zone": "Z2"}, r"^ag and zone: give one of them"),
    ({"ag": 0.24, "zone": "Z2", "importance": 1.2}, r"^ag and zone"),
    ({"zone": "Z4"}, r"^zone = 'Z4': unknown seismic zone .*" + ZONES),
    ({"zone": 0}, r"^zone = 0: .*" + ZONES),
    ({"zone": True}, r"^zone = True: .*" + ZONES),
    ({"zone": 2.0}, r"^zone = 2.0: .*" + ZONES),
    ({"zone": "II"}, r"^zone = 'II': .*" + ZONES),
    ({"zone": "Z2", "national_annex": "IT"}, r"^national_annex = 'IT': unknown .*" + ANNEXES),
    ({"zone": "Z2", "national_annex": "recommended"}, r"^national_annex = 'recommended'.*"
     r"recommended values have no seismic zones: give ag"),
    ({"zone": "Z2", "national_annex": 1}, r"^national_annex = 1: .*" + ANNEXES),
    ({"ag": 0.24, "national_annex": "EN"}, r"^national_annex = 'EN': .*" + ANNEXES),
    ({"ag": 0.24, "importance": 1.2}, r"^importance = 1.2: ag is already the design ground "
     r"acceleration gamma_I a_gR"),
    ({"zone": "Z2", "importance": 0.0}, r"^importance = 0.0: must be a finite number > 0"),
    ({"zone": "Z2", "importance": -1.0}, r"^importance = -1.0: must be a finite number > 0"),
    ({"zone": "Z2", "importance": float("nan")}, r"^importance = nan: must be a finite"),
    ({"zone": "Z2", "importance": "high"}, r"^importance = 'high': must be a finite"),
])
def test_refusals(fun, kwargs, pattern):
    with pytest.raises(InvalidInputError, match=pattern):
        fun([0.1, 0.5], **kwargs)


def test_reference_pga_refusals():
    with pytest.raises(InvalidInputError, match=r"^zone = 'Z0': .*" + ZONES):
        C.reference_pga("Z0")
    with pytest.raises(InvalidInputError, match=r"^zone = None: .*" + ZONES):
        C.reference_pga(None)
    with pytest.raises(InvalidInputError, match=r"^national_annex = 'IT': .*" + ANNEXES):
        C.reference_pga("Z1", "IT")
    # a valid zone still reaches the Fortran refusal of the recommended values' "zones"
    from seispulse._seispulse import sp_ec8_reference_pga
    agr, stat, msg = sp_ec8_reference_pga(_fortran_codes.EC8_ANNEX_RECOMMENDED, 1)
    assert agr == 0.0 and stat != 0      # 0 on error, as the spectra's outputs
    assert b"give ag" in msg
