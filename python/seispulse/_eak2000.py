"""EAK 2000, the Greek seismic code with its 2003 amendment of the zones: design and
elastic spectra (Fortran module ``seispulse_eak2000``; doc/eak2000.md). Users reach these
names as ``seispulse.codes.<name>``.

Provenance: the primary text of EAK 2000 could not be read. The formulas of Phi_d and the
values of beta0, T1/T2, gamma_I and eta are SECONDARY (two implementations by one author
group, which agree on them); the 2003 zones: [PRDA24] states that the 2003 map has three
zones spanning 0.16-0.36 g, the middle value 0.24 g and the names Z1-Z3 are from press
reports of the 2003 amendment (SECONDARY). The elastic spectrum Phi_e (``kind='elastic'``)
is UNVERIFIED as a whole: it is in one implementation only, and EAK may not define a
separate elastic spectrum. UNVERIFIED items are parameters with documented defaults:
``eta_min`` (EAK's lower limit of eta; default none), ``theta`` (its rules; default 1),
``lower_bound`` (a floor of Phi_d; default none), ``elastic_exponent`` (the long-period
exponent of Phi_e; default 2/3), ground X (refused).

Damping: ``damping`` here is a RATIO (0.05 = 5 %), whereas the EC8 functions
(``codes.elastic_spectrum``, ``codes.damping_correction``) take ``xi_percent`` in PERCENT.
"""

import math
import numbers
from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_eak2000_beta0, sp_eak2000_damping_correction,
                         sp_eak2000_design_spectrum, sp_eak2000_elastic_spectrum,
                         sp_eak2000_ground_parameters, sp_eak2000_importance_factor,
                         sp_eak2000_zone_acceleration)
from .errors import InvalidInputError

__all__ = ["EAK_ZONES_2003", "EAK_ZONES_2000", "EAK_GROUNDS", "EAK_IMPORTANCE",
           "EakParameters", "eak2000_spectrum", "eak2000_parameters"]



def _library_table(routine, names, *args):
    """{name: the library's value of entry 1..len(names)} (routine(k, *args) -> value, stat,
    msg)."""
    table = {}
    for k, name in enumerate(names, start=1):
        value, stat, msg = routine(k, *args)
        _core.raise_for_status(stat, msg)
        table[name] = float(value)
    return table


#: alpha = A/g of the zones of the 2003 amendment (in force from 1 January 2004; SECONDARY:
#: [PRDA24] gives three zones spanning 0.16-0.36 g, the value 0.24 and the names Z1-Z3
#: are from press reports): Z1 0.16, Z2 0.24, Z3 0.36 (read from the library). The default
#: map.
EAK_ZONES_2003 = _library_table(sp_eak2000_zone_acceleration, ("Z1", "Z2", "Z3"),
                                _f.EAK_MAP_2003)
#: alpha = A/g of the zones of the original EAK 2000 map (SECONDARY), replaced in 2003:
#: I 0.12, II 0.16, III 0.24, IV 0.36 (read from the library). The labels I..IV are
#: seispulse's own (the source implementation calls 0.12 g "Z1").
EAK_ZONES_2000 = _library_table(sp_eak2000_zone_acceleration, ("I", "II", "III", "IV"),
                                _f.EAK_MAP_2000)
#: Soil categories with values (SECONDARY); X (site-specific study) is refused.
EAK_GROUNDS = ("A", "B", "C", "D")
#: gamma_I of the importance categories Sigma1..Sigma4 (SECONDARY): I 0.85, II 1.00,
#: III 1.15, IV 1.30 (read from the library).
EAK_IMPORTANCE = _library_table(sp_eak2000_importance_factor, ("I", "II", "III", "IV"))

_MAPS = {"2003": (_f.EAK_MAP_2003, EAK_ZONES_2003), "2000": (_f.EAK_MAP_2000, EAK_ZONES_2000)}
_GROUND_CODES = {"A": _f.EAK_GROUND_A, "B": _f.EAK_GROUND_B, "C": _f.EAK_GROUND_C,
                 "D": _f.EAK_GROUND_D}
_CATEGORY_ALIASES = {"Σ1": "I", "Σ2": "II", "Σ3": "III", "Σ4": "IV"}
_KINDS = ("design", "elastic")
_DESIGN_EXPONENT = 2.0 / 3.0
#: kind='design' accepts an elastic_exponent within this of 2/3 (e.g. 1 - 1/3)
_EXPONENT_TOL = 1e-12
_DEFAULT_ZONE = "Z2"

EakParameters = namedtuple("EakParameters", ["alpha", "gamma_i", "eta", "t1", "t2", "beta0"])
EakParameters.__doc__ = """Parameters of an EAK 2000 spectrum: alpha = A/g (zone or given),
gamma_i (importance factor), eta (damping correction, with eta_min applied), t1 and t2
(corner periods, s) and beta0 = 2.5 (all SECONDARY; see :func:`eak2000_spectrum`)."""


def _zone_map(zone_map):
    key = str(zone_map) if isinstance(zone_map, numbers.Integral) \
        and not isinstance(zone_map, (bool, np.bool_)) else zone_map
    if not isinstance(key, str) or key.strip() not in _MAPS:
        raise InvalidInputError(f"zone_map = {zone_map!r}: unknown map (allowed: '2003', the "
                                "2003 amendment (default), '2000', the original map)")
    return _MAPS[key.strip()]


def _alpha(zone, zone_map, alpha):
    """A/g from `alpha` or from the zone of the map. With `alpha`, the zone must be the
    default 'Z2' (which cannot be told from an omitted zone): any other valid zone is
    refused ("give zone or alpha, not both"), an invalid one as such."""
    code, zones = _zone_map(zone_map)
    if alpha is not None:
        value = _core.as_number("alpha", alpha)
        if not math.isfinite(value) or value < 0.0:
            raise InvalidInputError(f"alpha = {value!r}: the ground acceleration A/g must be "
                                    "finite and >= 0")
        if isinstance(zone, str) and zone.strip().upper() == _DEFAULT_ZONE:
            return value
        _zone_number(zone, code, zones)
        raise InvalidInputError(f"zone = {zone!r} and alpha = {value!r}: give zone or alpha, "
                                "not both (zone defaults to 'Z2'; alpha = A/g replaces it)")
    number = _zone_number(zone, code, zones)
    value, stat, msg = sp_eak2000_zone_acceleration(number, code)
    _core.raise_for_status(stat, msg)
    return float(value)


def _zone_number(zone, code, zones):
    """Zone number 1..n of `zone` on the map `code` (names as in `zones`, or 1..n)."""
    names = tuple(zones)
    if isinstance(zone, numbers.Integral) and not isinstance(zone, (bool, np.bool_)) \
            and 1 <= int(zone) <= len(names):
        number = int(zone)
    elif isinstance(zone, str) and zone.strip().upper() in names:
        number = names.index(zone.strip().upper()) + 1
    else:
        other = "'I'..'IV' are the 2000 map's" if code == _f.EAK_MAP_2003 \
            else "'Z1'..'Z3' are the 2003 map's"
        raise InvalidInputError(
            f"zone = {zone!r}: unknown zone of the {'2003' if code == _f.EAK_MAP_2003 else '2000'}"
            f" map (allowed: {', '.join(map(repr, names))} or 1..{len(names)}; {other}; "
            "or give alpha)")
    return number


def _ground(ground):
    key = ground.strip().upper() if isinstance(ground, str) else None
    if key == "X":    # the library refuses X with its reason
        _, _, stat, msg = sp_eak2000_ground_parameters(_f.EAK_GROUND_X)
        _core.raise_for_status(stat, msg, rename={f"ground = {_f.EAK_GROUND_X} (X)":
                                                  f"ground = {ground!r}"})
    if key not in _GROUND_CODES:
        raise InvalidInputError(f"ground = {ground!r}: unknown soil category (allowed: 'A', "
                                "'B', 'C', 'D', EAK 2000 §2.3.6)")
    return _GROUND_CODES[key]


def _importance(importance):
    """gamma_I from a number or a category name 'I'..'IV' / 'Σ1'..'Σ4'."""
    if isinstance(importance, str):
        key = importance.strip().upper()
        key = _CATEGORY_ALIASES.get(key, key)
        if key not in EAK_IMPORTANCE:
            raise InvalidInputError(f"importance = {importance!r}: unknown category (allowed: "
                                    "'I', 'II', 'III', 'IV' (also 'Σ1'..'Σ4'), or gamma_I > 0)")
        number = tuple(EAK_IMPORTANCE).index(key) + 1
        gamma_i, stat, msg = sp_eak2000_importance_factor(number)
        _core.raise_for_status(stat, msg)
        return float(gamma_i)
    if isinstance(importance, (bool, np.bool_)):
        raise InvalidInputError(f"importance = {importance!r}: must be gamma_I (> 0) or a "
                                "category 'I'..'IV'")
    value = _core.as_number("importance", importance)
    if not math.isfinite(value) or value <= 0.0:
        raise InvalidInputError(f"importance = {value!r}: the importance factor gamma_I must "
                                "be finite and > 0 (categories 'I'..'IV': 0.85, 1.0, 1.15, 1.3)")
    return value


def _xi_percent(damping):
    value = _core.as_number("damping", damping)
    if not math.isfinite(value) or not 0.0 <= value < 1.0:
        raise InvalidInputError(f"damping = {value!r}: the damping RATIO must lie in [0, 1) "
                                "(0.05 for 5 %; the EC8 functions take xi_percent in percent)")
    return 100.0 * value


def _eta_min(eta_min):
    value = _core.as_number("eta_min", eta_min)
    if not math.isfinite(value) or not 0.0 <= value <= 1.0:
        raise InvalidInputError(f"eta_min = {value!r}: the lower limit of eta must lie in "
                                "[0, 1] (0 = none; EAK's own limit is unverified)")
    return value


def eak2000_parameters(zone="Z2", ground="B", importance=1.0, damping=0.05, *, alpha=None,
                       zone_map="2003", eta_min=0.0):
    """Parameters of an EAK 2000 spectrum (SECONDARY values; doc/eak2000.md).

    Arguments as in :func:`eak2000_spectrum` (defaults zone 'Z2', ground 'B'; ``damping``
    a RATIO; ``alpha`` with a zone other than 'Z2' is refused). Returns
    :class:`EakParameters` (alpha, gamma_i, eta, t1 (s), t2 (s), beta0).
    """
    a = _alpha(zone, zone_map, alpha)
    code = _ground(ground)
    gamma_i = _importance(importance)
    xi = _xi_percent(damping)
    floor = _eta_min(eta_min)
    t1, t2, stat, msg = sp_eak2000_ground_parameters(code)
    _core.raise_for_status(stat, msg)
    eta, stat, msg = sp_eak2000_damping_correction(np.array([xi]), floor)
    _core.raise_for_status(stat, msg)
    return EakParameters(a, gamma_i, float(eta[0]), float(t1), float(t2),
                         float(sp_eak2000_beta0()))


def eak2000_spectrum(periods, zone="Z2", ground="B", importance=1.0, q=1.0, theta=1.0,
                     damping=0.05, *, alpha=None, zone_map="2003", kind="design", eta_min=0.0,
                     lower_bound=0.0, elastic_exponent=2.0 / 3.0):
    """Horizontal spectrum of EAK 2000 (§2.3.1) with the 2003 zones, in g.

    The formulas and values are SECONDARY (two implementations by one author group; for
    the 2003 zones [PRDA24] gives 0.16-0.36 g, the value 0.24 and the names Z1-Z3 are from
    press reports; the code's text itself could not be read); the items marked UNVERIFIED
    below are parameters with stated defaults. See doc/eak2000.md.

    Defaults: zone 'Z2', ground 'B', q = 1, i.e. ``eak2000_spectrum(T)`` gives
    elastic-level ordinates (no behaviour factor) of a Z2 site on soil B; name the zone
    (or alpha), the ground and q of your site.

    Design spectrum (``kind='design'``), A = alpha g, eta = max(sqrt(7 / (2 + xi)),
    eta_min) with xi in percent, beta0 = 2.5:

    * T <= T1: gamma_I A [1 + T/T1 (eta theta beta0 / q - 1)] (K.1)
    * T1 < T <= T2: gamma_I A eta theta beta0 / q (K.2)
    * T > T2: gamma_I A eta theta beta0 / q (T2/T)^(2/3) (K.3)
    * and >= lower_bound gamma_I A (K.5).

    Elastic spectrum (``kind='elastic'``): the same with q = theta = 1, no floor and the
    exponent ``elastic_exponent`` beyond T2 (K.6). UNVERIFIED as a whole: one secondary
    implementation only; whether EAK defines an elastic spectrum beyond Phi_d with
    q = theta = 1 is unknown.

    Inputs whose spectrum would overflow (e.g. ``importance=1e308``) are refused with
    :class:`~seispulse.InvalidInputError`; no NaN or inf is returned. Bools are refused
    where numbers are expected.

    Parameters
    ----------
    periods : float or array
        T (s, >= 0).
    zone : str or int
        Seismic zone: 'Z1', 'Z2', 'Z3' (0.16, 0.24, 0.36) for ``zone_map='2003'``, 'I'..'IV'
        (0.12, 0.16, 0.24, 0.36) for ``zone_map='2000'``; or the zone number. Default 'Z2'.
        With ``alpha``, a zone other than the default 'Z2' is refused ("give zone or
        alpha, not both"); an invalid zone is refused in any case.
    ground : {'A', 'B', 'C', 'D'}
        Soil category (T1/T2 = 0.10/0.40, 0.15/0.60, 0.20/0.80, 0.20/1.20 s); default
        'B'. 'X' (a site-specific study, unverified) is refused.
    importance : float or str
        gamma_I (> 0), or a category 'I'..'IV' (also 'Σ1'..'Σ4'): 0.85, 1.0, 1.15, 1.30
        (importance 'I' is gamma_I = 0.85, not zone 'I' of the 2000 map).
    q : float
        Behaviour factor (>= 1; design only); default 1, elastic-level ordinates.
    theta : float
        Foundation factor in (0, 1] (design only; its rules are UNVERIFIED: one secondary
        source offers 0.8-1.0; values below 0.8 have no source at all).
    damping : float
        Viscous damping as a RATIO in [0, 1) (0.05 = 5 %, eta = 1). Unlike the EC8
        functions, whose ``xi_percent`` is in PERCENT (5 = 5 %).
    alpha : float or None
        A/g (>= 0) instead of a zone (then leave ``zone`` at its default).
    zone_map : {'2003', '2000'}
        The 2003 amendment's map (default) or the original 2000 map.
    kind : {'design', 'elastic'}
        Phi_d or Phi_e. With 'elastic', ``q``, ``theta`` must stay 1 and ``lower_bound``
        0; with 'design', ``elastic_exponent`` must stay 2/3 (within 1e-12). Phi_e is
        UNVERIFIED (see above).
    eta_min : float
        Lower limit of eta in [0, 1]; default 0 = none. Neither secondary implementation
        applies a limit; one implementation's docstring states eta >= 0.55 without
        applying it; 0.7 is recalled as ENV 1998's limit for this form. All UNVERIFIED.
    lower_bound : float
        Floor factor of Phi_d (>= 0): Phi_d >= lower_bound gamma_I A; default 0 = none (a
        floor of 0.25 is recalled but UNVERIFIED; a factor above 1 lifts Phi_d(0) above
        gamma_I A).
    elastic_exponent : float
        Exponent of (T2/T) in Phi_e beyond T2 (any value > 0); default 2/3 (= Phi_d with
        q = theta = 1), 1 in one secondary implementation (UNVERIFIED).

    Returns
    -------
    float or array
        The spectral acceleration in g, shaped like ``periods``.
    """
    mode = _core.check_choice("kind", kind, _KINDS)
    a = _alpha(zone, zone_map, alpha)
    code = _ground(ground)
    gamma_i = _importance(importance)
    xi = _xi_percent(damping)
    floor = _eta_min(eta_min)
    qq, th = _core.as_number("q", q), _core.as_number("theta", theta)
    lb = _core.as_number("lower_bound", lower_bound)
    expo = _core.as_number("elastic_exponent", elastic_exponent)
    arr = _core.as_number_array("periods", periods)
    shape, flat = arr.shape, np.ascontiguousarray(arr.reshape(-1))
    if mode == "elastic":
        for name, value, default in (("q", qq, 1.0), ("theta", th, 1.0),
                                     ("lower_bound", lb, 0.0)):
            if value != default:
                raise InvalidInputError(f"{name} = {value!r}: kind = 'elastic' takes no "
                                        f"{name} (must stay {default:g}); use kind = 'design'")
        out, stat, msg = sp_eak2000_elastic_spectrum(flat, a, code, gamma_i, xi, floor, expo)
        _core.raise_for_status(stat, msg, rename={"exponent": "elastic_exponent"},
                               indexed=("periods",))
    else:
        if not abs(expo - _DESIGN_EXPONENT) <= _EXPONENT_TOL:
            raise InvalidInputError(f"elastic_exponent = {expo!r}: applies to kind = 'elastic' "
                                    "only (Phi_d falls off as (T2/T)^(2/3))")
        out, stat, msg = sp_eak2000_design_spectrum(flat, a, code, gamma_i, qq, th, xi, floor,
                                                    lb)
        _core.raise_for_status(stat, msg, indexed=("periods",))
    return float(out[0]) if shape == () else out.reshape(shape)
