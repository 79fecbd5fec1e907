"""Empirical (simplified) estimates of the permanent sliding displacement of a slope, as
SLAMMER 1.1 offers them (Fortran module ``seispulse_empirical``, doc/empirical.md):

* rigid block: :func:`jibson_1993`, :func:`jibson_1998`, the four forms of Jibson (2007)
  (:func:`jibson_2007_ratio`, :func:`jibson_2007_ratio_m`, :func:`jibson_2007_arias`,
  :func:`jibson_2007_arias_ratio`), :func:`ambraseys_menu_1988`, the three forms of
  Saygili & Rathje (2008) (:func:`saygili_rathje_2008_pga`, :func:`saygili_rathje_2008_pgv`,
  :func:`saygili_rathje_2008_pgv_arias`) and :func:`rathje_saygili_2009`;
* flexible, coupled: :func:`bray_travasarou_2007` (with the probability of zero
  displacement);
* flexible or rigid, decoupled: :func:`rathje_antonakos_2011` (the unified model);
* :func:`probability_of_failure` (Jibson et al. 2000).

Units are the sources': yields and accelerations in g, PGV in cm/s, Arias intensity in
m/s, periods in s; displacements come back in cm (``disp_cm``) and m (``disp_m``).
:func:`seispulse.records.intensity` gives ``pgv`` in m/s: pass its ``pgv_cm_s`` (cm/s),
e.g. ``im = records.intensity(rec); saygili_rathje_2008_pgv(ky, im.pga, im.pgv_cm_s)``;
its ``pga`` (g), ``arias`` (m/s) and ``tm`` (s) are in these units already.
Every argument broadcasts like a numpy ufunc. ``sigma`` is the standard deviation of
log10 D or of ln D as the source gives it (``log_base`` 'log10' or 'ln'); ``d16_cm`` and
``d84_cm`` are the median divided and multiplied by base**sigma (the 16 % and 84 %
values of the lognormal scatter).

The models that take ky/PGA need 0 < ky < PGA (a rigid block with ky >= PGA does not
slide): anything else raises :class:`~seispulse.errors.InvalidInputError` naming the
parameter, as does any other input out of range (ky, PGA, PGV, Ia > 0; 0 < M < 10;
Ts >= 0; Tm > 0).
"""

from collections import namedtuple

import numpy as np

from . import _core
from . import _fortran_codes as _f
from ._seispulse import (sp_emp_bray_travasarou, sp_emp_probability_of_failure,
                         sp_emp_rathje_antonakos, sp_emp_rigid)
from .errors import InvalidInputError

__all__ = ["Displacement", "BrayTravasarou", "Unified", "jibson_1993", "jibson_1998",
           "jibson_2007_ratio", "jibson_2007_ratio_m", "jibson_2007_arias",
           "jibson_2007_arias_ratio", "ambraseys_menu_1988", "saygili_rathje_2008_pga",
           "saygili_rathje_2008_pgv", "saygili_rathje_2008_pgv_arias", "rathje_saygili_2009",
           "bray_travasarou_2007", "rathje_antonakos_2011", "probability_of_failure"]

Displacement = namedtuple("Displacement", ["disp_cm", "disp_m", "sigma", "log_base", "d16_cm",
                                           "d84_cm"])
Displacement.__doc__ = """A rigid-block estimate: median displacement (cm and m), the
standard deviation of log10 D or ln D (log_base 'log10' or 'ln'), and the median divided
and multiplied by base**sigma (cm)."""

BrayTravasarou = namedtuple("BrayTravasarou", Displacement._fields + ("p_zero",))
BrayTravasarou.__doc__ = """Bray & Travasarou (2007): the median of the non-zero
displacement (cm, m), sigma of ln D (0.66), the 16 % / 84 % values (cm), and p_zero, the
probability that the displacement is "zero" (D <= 1 cm)."""

Unified = namedtuple("Unified", Displacement._fields + ("kmax", "kvelmax", "disp_rigid_cm",
                                                       "form"))
Unified.__doc__ = """Rathje & Antonakos (2011): the displacement of the flexible sliding
mass (cm, m), sigma of ln D, the 16 % / 84 % values (cm), kmax (g) and kvelmax (cm/s;
0 for the PGA-M form), the rigid model's value at kmax before the period term (cm), and
the form used ('pga_m' or 'pga_pgv')."""

_BASES = {_f.EMP_LOG10: "log10", _f.EMP_LN: "ln"}


def _spread(disp, sigma, base):
    """d16, d84 from the median and sigma in `base` (codes EMP_LOG10 / EMP_LN)."""
    factor = np.where(base == _f.EMP_LOG10, 10.0, np.e) ** sigma
    return disp / factor, disp * factor


def _loop(wrapper, arrays, before=(), after=()):
    """Broadcast the named inputs ({name: value}), run the element-by-element wrapper
    (scalar arguments `before` and `after` the arrays) and return (shape, outputs). An
    element out of range raises InvalidInputError naming it as name[index] of the
    argument the caller passed (the wrapper stops at the first bad element: found by
    bisecting on prefixes, log2(n) more calls, on the error path only)."""
    shape, arr = _core.broadcast(**arrays)
    flat = [_core.flat(arr[name], shape) for name in arrays]
    *outs, stat, msg = wrapper(*before, *flat, *after)
    if stat != _core.SEISPULSE_SUCCESS and len(flat[0]) > 1:
        good, bad = 0, len(flat[0])             # prefix `good` passes, prefix `bad` fails
        while bad - good > 1:
            mid = (good + bad) // 2
            if wrapper(*before, *(f[:mid] for f in flat), *after)[-2] == \
                    _core.SEISPULSE_SUCCESS:
                good = mid
            else:
                bad = mid
        index = np.unravel_index(bad - 1, shape)
        _core.raise_for_status(stat, msg, rename={name: _element(name, arr[name], index)
                                                  for name in arrays})
    _core.raise_for_status(stat, msg)
    return shape, outs


def _element(name, arr, index):
    """`name` with the index of its element at the broadcast `index` (a single value: the
    bare name, the same for every element)."""
    if arr.size == 1:
        return name
    own = index[len(index) - arr.ndim:]
    return f"{name}[{', '.join(str(0 if n == 1 else int(k)) for n, k in zip(arr.shape, own))}]"


def _base_names(base, shape):
    return _core.names([_BASES.get(code, "") for code in range(max(_BASES) + 1)], base, shape)


def _rigid(model, ky, pga=0.0, pgv=0.0, arias=0.0, magnitude=0.0):
    shape, (disp, sigma, base) = _loop(sp_emp_rigid, {"ky": ky, "pga": pga, "pgv": pgv,
                                                      "arias": arias, "magnitude": magnitude},
                                       before=(model,))
    d16, d84 = _spread(disp, sigma, base)
    disp_cm, sig, lo, hi = _core.shaped(shape, disp, sigma, d16, d84)
    return Displacement(disp_cm, disp_cm / 100.0, sig, _base_names(base, shape), lo, hi)


def jibson_1993(arias, ky):
    """Jibson (1993), doc/empirical.md (E.1): log10 D = 1.460 log10 Ia - 6.642 ky + 1.546
    (D cm, Ia m/s, ky g); sigma 0.409 (log10)."""
    return _rigid(_f.EMP_JIBSON_1993, ky, arias=arias)


def jibson_1998(arias, ky):
    """Jibson et al. (1998, 2000), (E.2): log10 D = 1.521 log10 Ia - 1.993 log10 ky - 1.546;
    sigma 0.375 (log10)."""
    return _rigid(_f.EMP_JIBSON_1998, ky, arias=arias)


def jibson_2007_ratio(ky, pga):
    """Jibson (2007) Eq. 6, (E.3): log10 D = 0.215 + log10[(1 - r)^2.341 r^-1.438],
    r = ky/PGA (0 < r < 1); sigma 0.510 (log10)."""
    return _rigid(_f.EMP_JIBSON_2007_RATIO, ky, pga=pga)


def jibson_2007_ratio_m(ky, pga, magnitude):
    """Jibson (2007) Eq. 7, (E.4): log10 D = -2.710 + log10[(1 - r)^2.335 r^-1.478] +
    0.424 M; sigma 0.454 (log10)."""
    return _rigid(_f.EMP_JIBSON_2007_RATIO_M, ky, pga=pga, magnitude=magnitude)


def jibson_2007_arias(arias, ky):
    """Jibson (2007) Eq. 9, (E.5): log10 D = 2.401 log10 Ia - 3.481 log10 ky - 3.230;
    sigma 0.656 (log10)."""
    return _rigid(_f.EMP_JIBSON_2007_ARIAS, ky, arias=arias)


def jibson_2007_arias_ratio(arias, ky, pga):
    """Jibson (2007) Eq. 10, (E.6): log10 D = 0.561 log10 Ia - 3.833 log10(ky/PGA) - 1.474;
    sigma 0.616 (log10)."""
    return _rigid(_f.EMP_JIBSON_2007_ARIAS_RATIO, ky, pga=pga, arias=arias)


def ambraseys_menu_1988(ky, pga):
    """Ambraseys & Menu (1988), (E.7): log10 D = 0.90 + log10[(1 - r)^2.53 r^-1.09],
    r = ky/PGA; sigma 0.30 (log10)."""
    return _rigid(_f.EMP_AMBRASEYS_MENU_1988, ky, pga=pga)


def saygili_rathje_2008_pga(ky, pga):
    """Saygili & Rathje (2008), PGA model (E.8); sigma 1.13 (ln)."""
    return _rigid(_f.EMP_SR08_PGA, ky, pga=pga)


def saygili_rathje_2008_pgv(ky, pga, pgv):
    """Saygili & Rathje (2008), PGA-PGV model (E.9), PGV in cm/s (a record's
    ``records.intensity(rec).pgv_cm_s``, not its ``pgv`` in m/s); sigma 0.41 + 0.52 ky/PGA
    (ln)."""
    return _rigid(_f.EMP_SR08_PGA_PGV, ky, pga=pga, pgv=pgv)


def saygili_rathje_2008_pgv_arias(ky, pga, pgv, arias):
    """Saygili & Rathje (2008), PGA-PGV-Ia model (E.10), PGV cm/s (``pgv_cm_s`` of
    records.intensity, not its ``pgv`` in m/s), Ia m/s; sigma 0.20 + 0.79 ky/PGA (ln)."""
    return _rigid(_f.EMP_SR08_PGA_PGV_ARIAS, ky, pga=pga, pgv=pgv, arias=arias)


def rathje_saygili_2009(ky, pga, magnitude):
    """Rathje & Saygili (2009), PGA-M model (E.11); sigma 0.732 + 0.789 r - 0.539 r^2,
    r = ky/PGA (ln)."""
    return _rigid(_f.EMP_RS09_PGA_M, ky, pga=pga, magnitude=magnitude)


def bray_travasarou_2007(ky, ts, sa, magnitude, slammer=False):
    """Bray & Travasarou (2007), (E.13)-(E.15): the median non-zero displacement of a
    flexible sliding mass of site period ts (s), yield coefficient ky (g), under a motion
    of spectral acceleration sa = Sa(1.5 ts) (g, 5 % damping) and moment magnitude M,
    and the probability of "zero" displacement (D <= 1 cm) with the exact normal
    distribution. For ts < 0.05 s the paper's nearly rigid form applies (-0.22 in place
    of -1.10, no ts term) and sa is the PGA.

    slammer=True: SLAMMER 1.1's arithmetic (Eq. 5 at every ts, its polynomial normal
    distribution, which is wrong for P(D = 0) > 1/2: doc/empirical.md section 5)."""
    slammer = _core.check_bool("slammer", slammer)
    shape, (disp, sigma, p_zero) = _loop(sp_emp_bray_travasarou, {
        "ky": ky, "ts": ts, "sa": sa, "magnitude": magnitude}, after=(int(slammer),))
    base = np.full(disp.shape, _f.EMP_LN)
    d16, d84 = _spread(disp, sigma, base)
    disp_cm, sig, lo, hi, p0 = _core.shaped(shape, disp, sigma, d16, d84, p_zero)
    return BrayTravasarou(disp_cm, disp_cm / 100.0, sig, _base_names(base, shape), lo, hi, p0)


def rathje_antonakos_2011(ky, ts, tm, pga, magnitude=None, pgv=None, slammer=False):
    """Rathje & Antonakos (2011), the unified model (E.26)-(E.32): the displacement of a
    sliding mass of site period ts (s) under a motion of mean period tm (s) and peak
    acceleration pga (g): kmax from ts/tm and pga, then Rathje & Saygili (2009) with
    magnitude (the 'pga_m' form) or Saygili & Rathje (2008) with pgv (cm/s: a record's
    ``records.intensity(rec).pgv_cm_s``; kvelmax, the 'pga_pgv' form) at kmax, times the
    period factor. Give exactly one of magnitude and
    pgv. ky >= kmax: no sliding (0).

    slammer=True: SLAMMER 1.1's rules, ts/tm capped at 8 and 0 also when ky > pga."""
    slammer = _core.check_bool("slammer", slammer)
    if (magnitude is None) == (pgv is None):
        raise InvalidInputError("magnitude, pgv: give exactly one of them (magnitude: the "
                                "PGA-M form; pgv in cm/s: the PGA-PGV form)")
    form, name = ((_f.EMP_RA11_PGA_M, "pga_m") if pgv is None else
                  (_f.EMP_RA11_PGA_PGV, "pga_pgv"))
    shape, (disp, sigma, kmax, kvel, drig) = _loop(sp_emp_rathje_antonakos, {
        "ky": ky, "ts": ts, "tm": tm, "pga": pga, "pgv": 0.0 if pgv is None else pgv,
        "magnitude": 0.0 if magnitude is None else magnitude},
        before=(form,), after=(int(slammer),))
    base = np.full(disp.shape, _f.EMP_LN)
    d16, d84 = _spread(disp, sigma, base)
    disp_cm, sig, lo, hi, km, kv, dr = _core.shaped(shape, disp, sigma, d16, d84, kmax, kvel,
                                                    drig)
    return Unified(disp_cm, disp_cm / 100.0, sig, _base_names(base, shape), lo, hi, km, kv,
                   dr, name)


def probability_of_failure(disp_cm):
    """Jibson et al. (2000), (E.35): P(failure) = 0.335 [1 - exp(-0.048 D^1.565)], D the
    Newmark displacement in cm (>= 0). Calibrated on shallow, disrupted landslides of the
    1994 Northridge earthquake."""
    shape, (p,) = _loop(sp_emp_probability_of_failure, {"disp_cm": disp_cm})
    return _core.shaped(shape, p)[0]
