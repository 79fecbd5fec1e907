"""EN 1998 seismic earth-pressure checks and response spectra (Fortran module
``seispulse_codes``).

* EN 1998-5 §7.3.2.2: seismic coefficients kh = alpha S / r (7.1), kv = 0.5 kh or
  0.33 kh (7.2, 7.3), the r of Table 7.1 (:func:`seismic_coefficients`,
  :func:`r_factor`).
* EN 1998-5 Annex E: Mononobe-Okabe coefficients (:func:`mononobe_okabe`) and the thrust
  on a yielding wall with the three water cases (:func:`earth_thrust`), the Westergaard
  pressure of free water (:func:`westergaard_pressure`), the rigid-wall increment
  alpha S gamma H^2 (:func:`rigid_wall_thrust`).
* Seed & Whitman (1970) and Wood (1973) as quoted by UFC 3-220-20 (:func:`seed_whitman`,
  :func:`wood`).
* EN 1998-1 §3.2.2.2 and §3.2.2.5: ground parameters (Tables 3.2, 3.3), damping
  correction, elastic and design spectra; the seismic zones of the Greek National Annex
  (:func:`reference_pga`, ``zone=`` of the spectra).
* EN 1998-1 3.2.3.1.2(4): a suite of records against the elastic spectrum
  (:func:`check_record_suite`, :class:`SuiteCheck`, :func:`elastic_target`;
  doc/record-suites.md).

Units: SI (unit weights kN/m^3, lengths m, thrusts kN/m, moments kNm/m), angles in
DEGREES (theta is returned in radians), alpha = ag/g dimensionless, spectra in the units
of ``ag``. Damping: the EC8 functions take ``xi_percent`` in PERCENT (5 = 5 %; a value in
(0, 1) draws a UserWarning), the ``eak2000_*`` functions take ``damping`` as a RATIO
(0.05 = 5 %). Bools are refused where numbers are expected. ``kv`` is signed: kv > 0 is
an upward inertia force, the effective gravity is g (1 - kv) and tan(theta) = kh /
(1 - kv); check both signs of EN's kv.

Geometry: ``psi_deg`` is the inclination of the back face to the horizontal (90 =
vertical; psi < 90 sets the top of the back face back from the heel, away from the
backfill, so that soil rests on it; psi > 90 overhangs the backfill); ``beta_deg`` is the
backfill slope (> 0 rising away from the wall); the height H is vertical.

Sources and what could not be verified
--------------------------------------
The EN texts themselves could not be read here (only their cover pages were
reachable). Every formula and table value is taken from at least two agreeing secondary
transcriptions (MIDAS design-guide components, GEO5 help, the xc project, eurocodepy,
TCVN 9386:2012 for EN 1998-1 Type 1; Type 2 from MIDAS only plus the structure of the
standard). The Westergaard 7/8 and 7/12 terms, Seed-Whitman's 3/8 kh gamma H^2 at 0.6 H
and Wood's kh gamma H^2 at 0.6 H are from UFC 3-220-20 (2025) as transcribed; the
primary reports (Seed & Whitman 1970, Wood 1973) were not read. The Annex E equation
numbers E.5-E.17 and the clause of the rigid-wall rule are recollection, not verified.
The published check phi = 30, delta = 0, vertical wall, flat backfill, kh = 0.24,
kv = -0.12 (theta = 0.2110933 rad, K = 0.4856177, K_pd = 2.600) is reproduced (from the
xc project's test, which cites eurocodeapplied.com).

Table values (S, TB, TC, TD, avg/ag, beta = 0.2, r) are EN's RECOMMENDED values; a
National Annex may change them; of the Greek National Annex only the seismic zones are
implemented (:func:`reference_pga`): [PRDA24] states that the Greek NA adopted the 2003
zonation map, three zones spanning 0.16-0.36 g; the middle value 0.24 g and the names
Z1-Z3 are from press reports of the 2003 amendment (SECONDARY). gamma_phi = 1.25 is
recalled as EN 1998-5's recommended value (its NOTE was not verified); the default here
is 1.0.

[TEXT ERROR?] The passive coefficient E.4 (delta = 0) as transcribed has the numerator
sin^2(psi + phi_d - theta); a brute-force planar-wedge search gives sin^2(psi + theta -
phi_d) (the same for a vertical wall, different otherwise). This module implements the
wedge-consistent form, generalised to wall friction (tested against the wedge search).

For a backfill steeper than phi_d - theta, EN prints E.3; no soil wedge is in
equilibrium there, so :func:`mononobe_okabe` raises :class:`seispulse.NoSolutionError`
unless ``beyond_limit="en1998"`` asks for EN's number.

EAK 2000 (the Greek seismic code, with the zones of its 2003 amendment): the design
spectrum Phi_d (K.1)-(K.3) and an elastic spectrum Phi_e (:func:`eak2000_spectrum`), and
its parameters (:func:`eak2000_parameters`, :data:`EAK_ZONES_2003`, :data:`EAK_ZONES_2000`,
:data:`EAK_GROUNDS`, :data:`EAK_IMPORTANCE`); doc/eak2000.md. Its primary text could not
be read: the formulas of Phi_d and the values of beta0, T1/T2, gamma_I and eta are
SECONDARY (two implementations by one author group, which agree on them); for the 2003
zones [PRDA24] gives three zones spanning 0.16-0.36 g, the middle value 0.24 g and the
names Z1-Z3 are from press reports. Phi_e as a whole is UNVERIFIED (one implementation
only; EAK may not define a separate elastic spectrum). UNVERIFIED, and therefore
parameters with stated defaults: the lower limit of eta (``eta_min``, default none), the
rules for the foundation factor theta (default 1), a lower bound of Phi_d
(``lower_bound``, default none), the long-period exponent of Phi_e (``elastic_exponent``,
default 2/3); ground X is refused. Defaults of :func:`eak2000_spectrum`: zone 'Z2',
ground 'B', q = 1 (elastic-level ordinates); ``alpha`` with another zone is refused.
There are still no EAK wall rules: its retaining-wall clause could not be found (give kh,
kv directly, e.g. from EN 1998-5, with the driver's ``code = 'direct'``).
"""

import math
import numbers
import warnings
from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_ec8_damping_correction, sp_ec8_design_spectrum,
                         sp_ec8_elastic_spectrum, sp_ec8_ground_parameters, sp_ec8_r_factor,
                         sp_ec8_design_ag, sp_ec8_reference_pga, sp_ec8_rigid_thrust,
                         sp_ec8_seismic_coefficients,
                         sp_ec8_thrust,
                         sp_ec8_vertical_ratio, sp_mononobe_okabe, sp_seed_whitman_increment,
                         sp_westergaard_pressure, sp_wood_thrust)
from .errors import STATUS_ERRORS, InvalidInputError, NoSolutionError
from ._eak2000 import (EAK_GROUNDS, EAK_IMPORTANCE, EAK_ZONES_2000,  # noqa: F401
                       EAK_ZONES_2003, EakParameters, eak2000_parameters,
                       eak2000_spectrum)
from . import _eak2000

__all__ = ["WALL_TYPES", "WATER_CASES", "GROUND_TYPES", "MononobeOkabe", "SeismicCoefficients",
           "EarthThrust", "WallThrust", "GroundParameters", "mononobe_okabe",
           "seismic_coefficients", "r_factor", "vertical_ratio", "earth_thrust",
           "westergaard_pressure", "rigid_wall_thrust", "seed_whitman", "wood",
           "ground_parameters", "damping_correction", "elastic_spectrum", "design_spectrum",
           "NATIONAL_ANNEXES", "GR_ZONES", "reference_pga"]
__all__ += _eak2000.__all__

#: EN 1998-5 Table 7.1 wall types: r = 2 (free gravity wall, displacement up to
#: 300 alpha S mm), 1.5 (up to 200 alpha S mm), 1 (flexural RC walls, anchored or braced
#: walls, RC walls on vertical piles, restrained basement walls, bridge abutments).
_WALL_CODES = {"gravity_300": _f.EC8_WALL_GRAVITY_300, "gravity_200": _f.EC8_WALL_GRAVITY_200,
               "restrained": _f.EC8_WALL_RESTRAINED}
WALL_TYPES = tuple(_WALL_CODES)
#: EN 1998-5 Annex E water cases: dry (or water table below the wall); dynamically
#: impervious soil below the water table; highly permeable soil below the water table.
_WATER_CODES = {"dry": _f.WATER_DRY, "impervious": _f.WATER_IMPERVIOUS,
                "permeable": _f.WATER_PERMEABLE}
WATER_CASES = tuple(_WATER_CODES)
#: EN 1998-1 Table 3.1 ground types.
_GROUND_CODES = {"A": _f.EC8_GROUND_A, "B": _f.EC8_GROUND_B, "C": _f.EC8_GROUND_C,
                 "D": _f.EC8_GROUND_D, "E": _f.EC8_GROUND_E}
GROUND_TYPES = tuple(_GROUND_CODES)
#: National Annexes to EN 1998-1 whose seismic zones are implemented: the Greek one.
_ANNEX_CODES = {"GR": _f.EC8_ANNEX_GR}
NATIONAL_ANNEXES = tuple(_ANNEX_CODES)
#: Reference peak ground acceleration a_gR on type A ground (g) of the seismic zones of
#: the Greek National Annex to EN 1998-1: the 2003 zonation map, Z1 0.16, Z2 0.24,
#: Z3 0.36 ([PRDA24]: three zones spanning 0.16-0.36 g; 0.24 and the names Z1-Z3 from
#: press reports, SECONDARY; doc/codes.md section 1). Read from the Fortran layer
#: (ec8_reference_pga).
GR_ZONES = {f"Z{z}": float(sp_ec8_reference_pga(_f.EC8_ANNEX_GR, z)[0]) for z in (1, 2, 3)}

MononobeOkabe = namedtuple("MononobeOkabe", ["k", "theta"])
MononobeOkabe.__doc__ = """Mononobe-Okabe coefficient K (dimensionless; the thrust is
1/2 gamma (1 - kv) K H^2) and the seismic angle theta = atan(kh / (1 - kv)) (radians)."""

SeismicCoefficients = namedtuple("SeismicCoefficients", ["kh", "kv"])
SeismicCoefficients.__doc__ = """kh = alpha S / r and the magnitude of kv (dimensionless);
check both signs of kv."""

_THRUST_FIELDS = ["k", "theta", "e_soil", "e_static", "e_dynamic", "e_ws", "e_wd", "total",
                  "z_static", "z_dynamic", "z_ws", "z_wd", "z_total", "m_base", "k_static"]
EarthThrust = namedtuple("EarthThrust", _THRUST_FIELDS)
EarthThrust.__doc__ = """Active seismic thrust on a yielding wall (EN 1998-5 Annex E).

k: Mononobe-Okabe K with the theta of the water case; theta (rad); e_soil =
1/2 gamma* (1 - kv) K H^2 (kN/m); e_static = 1/2 gamma* K_static H^2 (Coulomb, kh = kv = 0)
at z_static = H/3; e_dynamic = e_soil - e_static at z_dynamic = H/2 (negative possible
when kv > 0); e_ws = 1/2 gamma_w H^2 at z_ws = H/3 (water cases); e_wd = 7/12 kh gamma_w
H^2 at z_wd = 0.4 H (permeable case); total = e_soil + e_ws + e_wd (kN/m); z_total =
m_base / total (m above the base); m_base = sum of thrust x height (kNm/m, thrusts taken
as horizontal forces: exact for a vertical back and delta = 0); k_static: the static K."""

WallThrust = namedtuple("WallThrust", ["thrust", "height_of_application"])
WallThrust.__doc__ = """A thrust (kN/m) and the height of its point of application above
the base of the wall (m)."""

GroundParameters = namedtuple("GroundParameters", ["s", "tb", "tc", "td"])
GroundParameters.__doc__ = """Soil factor S and corner periods TB, TC, TD (s) of EN 1998-1
Table 3.2 (Type 1) or 3.3 (Type 2), recommended values."""


def _scalar(name, value):
    return _core.as_number(name, value)


def _warn_ratio(values):
    """UserWarning when an xi_percent lies in (0, 1): probably a ratio given as percent."""
    small = values[(values > 0.0) & (values < 1.0)]
    if small.size:
        x = float(small[0])
        warnings.warn(f"xi_percent = {x!r}: xi_percent is in percent; {x:g} means {x:g} %, "
                      f"did you mean {100.0 * x:g}?", UserWarning, stacklevel=3)


def _spectrum_type(value):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral) \
            or int(value) not in (1, 2):
        raise InvalidInputError(f"spectrum_type = {value!r}: must be 1 (Type 1, Ms > 5.5) or "
                                "2 (Type 2, Ms <= 5.5)")
    return int(value)


def _ground(value):
    if not isinstance(value, str) or value.strip().upper() not in GROUND_TYPES:
        raise InvalidInputError(f"ground = {value!r}: unknown ground type (allowed: "
                                "'A', 'B', 'C', 'D', 'E', EN 1998-1 Table 3.1)")
    return _GROUND_CODES[value.strip().upper()]


#: Fortran arrays whose elements name(i) errors give as the caller's name[i - 1].
_INDEXED = ("accel", "periods", "z", "xi_percent")


# ------------------------------------------------------------------ EN 1998-5 §7.3.2.2

def vertical_ratio(spectrum_type=1):
    """avg / ag of EN 1998-1 Table 3.4 (recommended): 0.90 for Type 1, 0.45 for Type 2."""
    return float(sp_ec8_vertical_ratio(_spectrum_type(spectrum_type)))


def seismic_coefficients(alpha, s, r=1.0, spectrum_type=1):
    """Seismic coefficients of EN 1998-5 §7.3.2.2.

    Parameters
    ----------
    alpha : float
        ag / g, with ag = gamma_I agR the design ground acceleration on ground type A
        (>= 0).
    s : float
        Soil factor S (> 0), e.g. from :func:`ground_parameters`.
    r : float
        Wall factor of Table 7.1 (:func:`r_factor`), in [1, 2]; values between 1, 1.5 and 2
        are accepted (for National Annexes), EN itself lists only those three.
    spectrum_type : {1, 2}
        Decides kv through avg / ag (Table 3.4): 0.90 > 0.6 for Type 1, so kv = 0.5 kh
        (7.2); 0.45 for Type 2, so kv = 0.33 kh (7.3).

    Returns
    -------
    SeismicCoefficients
        kh = alpha S / r (7.1) and kv (a positive magnitude: check +kv and -kv).
    """
    ratio = vertical_ratio(spectrum_type)
    kh, kv, stat, msg = sp_ec8_seismic_coefficients(_scalar("alpha", alpha), _scalar("s", s),
                                                    _scalar("r", r), ratio)
    _core.raise_for_status(stat, msg)
    return SeismicCoefficients(float(kh), float(kv))


def r_factor(wall_type):
    """r of EN 1998-5 Table 7.1 for ``wall_type`` in :data:`WALL_TYPES`:
    'gravity_300' -> 2.0 (free gravity wall accepting a displacement up to
    300 alpha S mm), 'gravity_200' -> 1.5 (up to 200 alpha S mm), 'restrained' -> 1.0
    (flexural RC walls, anchored or braced walls, RC walls on vertical piles, restrained
    basement walls, bridge abutments)."""
    code = _core.choice_code("wall_type", wall_type, _WALL_CODES)
    r, stat, msg = sp_ec8_r_factor(code)
    _core.raise_for_status(stat, msg)
    return float(r)


# ------------------------------------------------------------------ Annex E

def mononobe_okabe(phi_deg, kh, kv, delta_deg=0.0, psi_deg=90.0, beta_deg=0.0, passive=False,
                   gamma_phi=1.0, beyond_limit="error"):
    """Mononobe-Okabe earth-pressure coefficient, EN 1998-5 Annex E (dry backfill).

    Parameters
    ----------
    phi_deg : float
        Friction angle of the soil phi' (degrees, in (0, 90)).
    kh : float
        Horizontal seismic coefficient (>= 0).
    kv : float
        Vertical seismic coefficient, SIGNED (> 0 upward inertia, < 1).
    delta_deg : float
        Soil-wall friction angle (degrees, in [0, phi_deg]).
    psi_deg : float
        Inclination of the back face to the horizontal (degrees, in (0, 180); 90 vertical).
    beta_deg : float
        Backfill slope (degrees, in (-90, 90), > 0 rising; psi + beta in (0, 180)).
    passive : bool
        False: active coefficient E.2; True: passive coefficient (inertia away from the
        wall), the wedge-consistent generalisation of E.4 with wall friction.
    gamma_phi : float
        Partial factor on tan(phi') and tan(delta) (>= 1; 1 = characteristic; EN
        1998-5 recommends 1.25 (not verified), check the National Annex): phi_d = atan(tan(phi') /
        gamma_phi), delta_d likewise (Annex E(4)).
    beyond_limit : {'error', 'en1998'}
        Active case with beta > phi_d - theta, where no soil wedge is in equilibrium:
        'error' raises :class:`seispulse.NoSolutionError`; 'en1998' returns EN's E.3 value
        sin^2(psi + phi_d - theta) / (cos(theta) sin^2(psi) sin(psi - theta - delta_d)).

    Returns
    -------
    MononobeOkabe
        k (dimensionless; thrust 1/2 gamma (1 - kv) K H^2) and theta (radians).

    Raises :class:`seispulse.NoSolutionError` where no planar wedge is in equilibrium
    (message says why), :class:`seispulse.InvalidInputError` for bad input.
    """
    mode = _core.check_choice("beyond_limit", beyond_limit, ("error", "en1998"))
    is_passive = _core.check_bool("passive", passive)
    k, theta, k_e3, stat, msg = sp_mononobe_okabe(
        _scalar("phi_deg", phi_deg), _scalar("kh", kh), _scalar("kv", kv),
        _scalar("delta_deg", delta_deg), _scalar("psi_deg", psi_deg),
        _scalar("beta_deg", beta_deg), int(is_passive), _scalar("gamma_phi", gamma_phi))
    no_solution = STATUS_ERRORS.get(int(stat)) is NoSolutionError
    if no_solution and mode == "en1998" and not is_passive and k_e3 > 0.0:
        return MononobeOkabe(float(k_e3), float(theta))
    _core.raise_for_status(stat, msg)
    return MononobeOkabe(float(k), float(theta))


def earth_thrust(height, gamma, phi_deg, kh, kv, delta_deg=0.0, psi_deg=90.0, beta_deg=0.0,
                 water="dry", gamma_w=9.81, gamma_d=None, gamma_phi=1.0):
    """Active seismic thrust on a yielding wall, EN 1998-5 Annex E (E.1 with the water
    terms; equation numbers E.5-E.13 not verified).

    Parameters
    ----------
    height : float
        Vertical height H of the back face (m, > 0).
    gamma : float
        Unit weight of the soil (kN/m^3, > 0; saturated unit weight below the water table).
    phi_deg, kh, kv, delta_deg, psi_deg, beta_deg, gamma_phi
        As in :func:`mononobe_okabe` (kv signed).
    water : {'dry', 'impervious', 'permeable'}
        'dry': dry soil or water table below the wall, gamma* = gamma,
        tan(theta) = kh / (1 - kv).
        'impervious': dynamically impervious soil, water table at the surface,
        gamma* = gamma - gamma_w, tan(theta) = gamma / (gamma - gamma_w) kh / (1 - kv),
        plus the hydrostatic 1/2 gamma_w H^2.
        'permeable': highly permeable soil, water table at the surface,
        gamma* = gamma - gamma_w, tan(theta) = gamma_d / (gamma - gamma_w) kh / (1 - kv),
        plus the hydrostatic thrust and the hydrodynamic 7/12 kh gamma_w H^2 (E.13) at
        0.4 H.
    gamma_w : float
        Unit weight of water (kN/m^3, in (0, gamma) for the water cases).
    gamma_d : float or None
        Dry unit weight of the soil (kN/m^3, > 0): required for 'permeable'.

    Returns
    -------
    EarthThrust
        See :class:`EarthThrust` (static part at H/3, dynamic increment at H/2).

    Active thrust only; passive thrusts: :func:`mononobe_okabe` with ``passive=True``.
    Raises :class:`seispulse.NoSolutionError` when no wedge is in equilibrium.
    """
    case = _core.choice_code("water", water, _WATER_CODES)
    if case == _f.WATER_PERMEABLE:
        if gamma_d is None:
            raise InvalidInputError("gamma_d: the dry unit weight (kN/m^3, > 0) is required "
                                    "for water='permeable'")
        gd = _scalar("gamma_d", gamma_d)
    else:
        gd = 0.0 if gamma_d is None else _scalar("gamma_d", gamma_d)
    out, stat, msg = sp_ec8_thrust(
        _scalar("height", height), _scalar("gamma", gamma), _scalar("phi_deg", phi_deg),
        _scalar("delta_deg", delta_deg), _scalar("psi_deg", psi_deg),
        _scalar("beta_deg", beta_deg), _scalar("kh", kh), _scalar("kv", kv), case,
        _scalar("gamma_w", gamma_w), gd, _scalar("gamma_phi", gamma_phi))
    _core.raise_for_status(stat, msg, rename={"water_case": "water"})
    return EarthThrust(*(float(x) for x in out))


def westergaard_pressure(kh, gamma_w, h_water, z):
    """Hydrodynamic pressure of free water on the outer face of a wall (Westergaard,
    EN 1998-5 E.14, number not verified; UFC 3-220-20 eq. 4-19):
    q = 7/8 kh gamma_w sqrt(h_water z), magnitude (it acts both ways).

    Parameters
    ----------
    kh : float
        Horizontal seismic coefficient (>= 0).
    gamma_w : float
        Unit weight of water (kN/m^3, > 0).
    h_water : float
        Water depth at the wall (m, > 0).
    z : float or array
        Depth below the free water surface (m, in [0, h_water]).

    Returns
    -------
    float or array
        q (kPa), shaped like ``z``. Its resultant is 7/12 kh gamma_w h_water^2 at
        0.4 h_water above the base.
    """
    arr = _core.as_float_array("z", z)
    flat = np.ascontiguousarray(arr.reshape(-1))
    q, stat, msg = sp_westergaard_pressure(_scalar("kh", kh), _scalar("gamma_w", gamma_w),
                                           _scalar("h_water", h_water), flat)
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return float(q[0]) if arr.shape == () else q.reshape(arr.shape)


def _wall(fun, name, a, gamma, height):
    thrust, z, stat, msg = fun(_scalar(name, a), _scalar("gamma", gamma),
                               _scalar("height", height))
    _core.raise_for_status(stat, msg)
    return WallThrust(float(thrust), float(z))


def rigid_wall_thrust(alpha_s, gamma, height):
    """Dynamic thrust on a rigid (completely restrained) wall, EN 1998-5 Annex E rigid
    structures (clause number not verified): alpha S gamma H^2 at H/2 (vertical wall,
    horizontal backfill). ``alpha_s`` = ag S / g (no r, >= 0); gamma in kN/m^3; height H
    in m. Returns :class:`WallThrust` (kN/m, m)."""
    return _wall(sp_ec8_rigid_thrust, "alpha_s", alpha_s, gamma, height)


def seed_whitman(kh, gamma, height):
    """Seed & Whitman (1970) dynamic increment on a yielding wall as quoted by
    UFC 3-220-20 eq. 4-17: dK = 3/4 kh, thrust 3/8 kh gamma H^2 at 0.6 H (vertical wall,
    horizontal backfill; proposed for kh up to about 0.4, not enforced). Seed & Whitman's
    kh is the peak ground acceleration over g; in an EN 1998-5 check it is the code's
    kh = alpha S/r. Returns :class:`WallThrust` (kN/m, m)."""
    return _wall(sp_seed_whitman_increment, "kh", kh, gamma, height)


def wood(alpha_s, gamma, height):
    """Wood (1973) non-yielding wall as commonly quoted (UFC 3-220-20 eq. 4-18):
    alpha_s gamma H^2 at 0.6 H, i.e. Wood's F_p = 1. Wood's own F_p depends on Poisson's
    ratio and on L/H (distance to the next wall): see :mod:`seispulse.walls` for the
    elastic solutions. ``alpha_s`` = ag S/g is the ground acceleration over g (no r), as
    in :func:`rigid_wall_thrust`. Returns :class:`WallThrust` (kN/m, m)."""
    return _wall(sp_wood_thrust, "alpha_s", alpha_s, gamma, height)


# ------------------------------------------------------------------ EN 1998-1 spectra

def ground_parameters(spectrum_type, ground):
    """S, TB, TC, TD (s) of EN 1998-1 Table 3.2 (Type 1) or 3.3 (Type 2) for ground
    'A'..'E' (recommended values; a National Annex may change them)."""
    s, tb, tc, td, stat, msg = sp_ec8_ground_parameters(_spectrum_type(spectrum_type),
                                                        _ground(ground))
    _core.raise_for_status(stat, msg)
    return GroundParameters(float(s), float(tb), float(tc), float(td))


def damping_correction(xi_percent):
    """eta = sqrt(10 / (5 + xi)) >= 0.55 (EN 1998-1 (3.6)), xi in PERCENT (>= 0; 5 = 5 %,
    not the ratio 0.05 that :func:`eak2000_spectrum` takes as ``damping``): 1 at 5 %, the
    floor 0.55 from xi = 28.06 %. A value in (0, 1) draws a UserWarning (probably a
    ratio). Float or array like ``xi_percent``."""
    arr = _core.as_number_array("xi_percent", xi_percent)
    _warn_ratio(arr.reshape(-1))
    eta, stat, msg = sp_ec8_damping_correction(np.ascontiguousarray(arr.reshape(-1)))
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return float(eta[0]) if arr.shape == () else eta.reshape(arr.shape)


def _periods(periods):
    arr = _core.as_number_array("periods", periods)
    return arr.shape, np.ascontiguousarray(arr.reshape(-1))


def _annex(value):
    """The Fortran code of a National Annex name ('GR', any case); None means 'GR'."""
    if value is None:
        return _f.EC8_ANNEX_GR
    if not isinstance(value, str) or value.strip().upper() not in _ANNEX_CODES:
        raise InvalidInputError(
            f"national_annex = {value!r}: unknown National Annex (allowed: "
            f"{', '.join(map(repr, NATIONAL_ANNEXES))}; EN's recommended values have no "
            "seismic zones: give ag instead of zone)")
    return _ANNEX_CODES[value.strip().upper()]


def _zone(value):
    """Zone number 1..3 of 'Z1'..'Z3' (any case) or of the integers 1..3."""
    if isinstance(value, str) and value.strip().upper() in GR_ZONES:
        return int(value.strip()[1:])
    if isinstance(value, numbers.Integral) and not isinstance(value, (bool, np.bool_)) \
            and int(value) in (1, 2, 3):
        return int(value)
    raise InvalidInputError(f"zone = {value!r}: unknown seismic zone of the Greek National "
                            "Annex (allowed: 'Z1', 'Z2', 'Z3' or 1, 2, 3)")


def reference_pga(zone, national_annex="GR"):
    """Reference peak ground acceleration a_gR on type A ground (g) of a seismic zone.

    Parameters
    ----------
    zone : {'Z1', 'Z2', 'Z3'} or {1, 2, 3}
        Seismic zone of the National Annex.
    national_annex : {'GR'} or None
        'GR' (also None): the Greek National Annex to EN 1998-1, which adopted the 2003
        zonation map: Z1 0.16 g, Z2 0.24 g, Z3 0.36 g (:data:`GR_ZONES`). [PRDA24] states
        the adoption and three zones spanning 0.16-0.36 g; the middle value 0.24 g and the
        names Z1-Z3 are from press reports of the 2003 amendment (SECONDARY).

    Returns
    -------
    float
        a_gR in g. The design ground acceleration is ag = gamma_I a_gR (importance factor
        gamma_I): ``importance=`` of :func:`elastic_spectrum` and :func:`design_spectrum`.
    """
    code = _annex(national_annex)
    agr, stat, msg = sp_ec8_reference_pga(code, _zone(zone))
    _core.raise_for_status(stat, msg)
    return float(agr)


def _design_ag(ag, zone, national_annex, importance):
    """ag of a spectrum (g): the given ag, or importance x a_gR of the zone; the rule is the
    library's (ec8_design_ag, the same as the driver's &ec8): one of ag and zone; with ag,
    importance must be 1 and national_annex is only checked."""
    if isinstance(importance, (bool, np.bool_)):
        _scalar("importance", importance)        # refuses bools, naming importance
    gamma_i = _core.check_positive("importance", importance)
    code = _annex(national_annex)
    a = math.nan if ag is None else _scalar("ag", ag)
    out, stat, msg = sp_ec8_design_ag(a, code, 0 if zone is None else _zone(zone), gamma_i)
    _core.raise_for_status(stat, msg)
    return float(out)


def elastic_spectrum(periods, ag=None, spectrum_type=1, ground="A", xi_percent=5.0, *,
                     zone=None, national_annex=None, importance=1.0):
    """Horizontal elastic response spectrum Se(T), EN 1998-1 §3.2.2.2 (3.2)-(3.5).

    Parameters
    ----------
    periods : float or array
        T (s, >= 0). EN states the forms up to 4 s; (3.5) is applied beyond.
    ag : float or None
        Design ground acceleration on type A ground, ag = gamma_I a_gR (>= 0); Se has its
        units. None: give ``zone``.
    spectrum_type : {1, 2}
        Type 1 (Ms > 5.5) or Type 2.
    ground : {'A', 'B', 'C', 'D', 'E'}
        Ground type (Table 3.1); S, TB, TC, TD from :func:`ground_parameters`.
    xi_percent : float
        Viscous damping in PERCENT (>= 0; 5 = 5 %, not the ratio 0.05 that
        :func:`eak2000_spectrum` takes as ``damping``); eta of :func:`damping_correction`.
        A value in (0, 1) draws a UserWarning ("did you mean 5?").
    zone : {'Z1', 'Z2', 'Z3'} or {1, 2, 3} or None, keyword-only
        Seismic zone of the National Annex, instead of ``ag``: ag = importance x a_gR in g
        (:func:`reference_pga`; Greek NA Z1 0.16, Z2 0.24, Z3 0.36 g: [PRDA24] gives
        0.16-0.36 g, the value 0.24 and the names from press reports). Giving both ``ag``
        and ``zone`` is an error.
    national_annex : {'GR'} or None, keyword-only
        The National Annex of ``zone``; None means 'GR' (the only one with zones here).
        With ``ag`` it is only checked.
        Only its zones are used: the Greek NA's other nationally determined parameters
        (S, TB, TC, TD, beta, the importance factors of its importance classes) were not
        verified here; S, TB, TC, TD and beta stay EN's recommended values and gamma_I is
        the ``importance`` given.
    importance : float, keyword-only
        Importance factor gamma_I (> 0) multiplying the a_gR of ``zone``. With ``ag`` it
        must stay 1: ``ag`` is already gamma_I a_gR.

    Returns
    -------
    float or array
        Se, shaped like ``periods`` (units of ``ag``; g with ``zone``): ag S [1 + T/TB
        (2.5 eta - 1)] up to TB, 2.5 eta ag S up to TC, times TC/T up to TD, times
        TC TD / T^2 beyond.
    """
    a = _design_ag(ag, zone, national_annex, importance)
    shape, t = _periods(periods)
    xi = _scalar("xi_percent", xi_percent)
    _warn_ratio(np.array([xi]))
    se, stat, msg = sp_ec8_elastic_spectrum(t, a, _spectrum_type(spectrum_type),
                                            _ground(ground), xi)
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return float(se[0]) if shape == () else se.reshape(shape)


def design_spectrum(periods, ag=None, spectrum_type=1, ground="A", q=1.5, beta=0.2, *,
                    zone=None, national_annex=None, importance=1.0):
    """Design spectrum Sd(T) for elastic analysis, EN 1998-1 §3.2.2.5 (3.13)-(3.16).

    Parameters
    ----------
    periods : float or array
        T (s, >= 0).
    ag : float or None
        Design ground acceleration on type A ground, ag = gamma_I a_gR (>= 0); Sd has its
        units. None: give ``zone``.
    spectrum_type, ground
        As in :func:`elastic_spectrum`.
    q : float
        Behaviour factor (>= 1; the 2/3 ag S at T = 0 presumes q >= 1.5).
    beta : float
        Lower-bound factor (>= 0; 0.2 recommended, an NDP): Sd >= beta ag for T >= TC.
    zone, national_annex, importance : keyword-only
        As in :func:`elastic_spectrum` (instead of ``ag``: ag = importance x a_gR in g).

    Returns
    -------
    float or array
        Sd, shaped like ``periods`` (units of ``ag``; g with ``zone``).
    """
    a = _design_ag(ag, zone, national_annex, importance)
    shape, t = _periods(periods)
    sd, stat, msg = sp_ec8_design_spectrum(t, a, _spectrum_type(spectrum_type),
                                           _ground(ground), _scalar("q", q),
                                           _scalar("beta", beta))
    _core.raise_for_status(stat, msg, indexed=_INDEXED)
    return float(sd[0]) if shape == () else sd.reshape(shape)


# EN 1998-1 3.2.3.1.2(4): record suites against the code spectrum (doc/record-suites.md)
from . import _record_suite  # noqa: E402
from ._record_suite import *  # noqa: E402,F401,F403
__all__ += _record_suite.__all__
