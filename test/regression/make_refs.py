#!/usr/bin/env python3
"""Write the driver regression references <case>.ref from <case>.nml, computed
independently with the mpmath pulse references in test/python/pulse_reference.py
(analysis 'pulse') or with the closed forms of the limit shapes (analysis 'sliding').

usage: make_refs.py [CASE.nml ...]   (default: every *.nml next to this script)

Analysis 'pulse':
The time grid follows the driver: t_i = t_start + dt * i in double precision, with
npts = floor((t_end - t_start) / dt * (1 + 1e-12)) + 1 when dt is given, or
dt = (t_end - t_start) / (npts - 1) when npts is given. Each row is evaluated at that
exact double t in high precision and printed with repr(float(x)).

Analysis 'sliding' (one row per friction value; never by running the driver): the
pulse must be one of the shapes with a closed-form answer, written out below from
doc/sliding.md (mpmath, 40 digits):
  * rectangle, full cycle: kind 'exponential' with beta = -inf, full = .true.
    (doc/sliding.md section 5; the block always slips);
  * rectangle, half cycle: kind 'rectangular', or 'exponential' with beta = -inf
    (Newmark 1965, doc/sliding.md section 3 Eq. 1.10a);
  * triangle, half cycle: kind 'triangular' with peak_frac = 0.5, or 'exponential' with
    beta = 0 (doc/sliding.md section 3, the explicit triangle results;
    V_m/V_g = (1-eta)^2);
and &block gives mu (mu_list; any slope_deg, xi_deg: Eq. 1.31 and the factors K of
doc/sliding.md section 7) or eta1 (eta_list), with static_factor. Static friction only moves the
onset: for the rectangle the onset stays at t = 0 (no sliding if static_factor eta >= 1);
for the triangle these references support static_factor = 1 only.

Analysis 'rocking' (never by running the driver): the linearized model (&block
model = 'linearized') under the rectangular half-cycle pulse (kind 'rectangular', or
'exponential' with beta = -inf and full = .false.), written out from doc/rocking.md in mpmath
(40 digits): the response (2.12, 2.13), the wall eta_w = 1 - e^-f (2.21), the region
boundaries cosh(f/2), cosh(f) = 1/(1 - eta) (2.17b, 2.17a), the critical time, the time of
the maximum (2.25), the maximum rotation (2.29) and the first impact (2.33). Summaries and
histories need restitution e = 0 (the block rests at its first impact; overturning
blocks need none); maps use the wall alone (the rectangle's impacts come after the
pulse, where a stable block cannot overturn: doc/rocking.md section 3), with cells at least 1e-6
(relative) away from it.

With &records: records that are rectangular pulses (equal samples, linear in between,
0 after the last: the pulse of duration (n - 1) dt), the same closed forms per record:
the summary (one row per record, also the largest |theta| and its time) or the history
(stacked, the record's name first); polarity -1 mirrors them.

Analysis 'cylinder' (never by running the driver): the properties of the body and of its
equivalent body (J_G by the parallel-axis theorem, J_o, p, Housner's e, the equivalence by
the same p and the same M_max) and the rigid pushover (F, M, M/(m g r)), written out from
doc/cylinder.md; a linearized history (e = 0) under a rectangular pulse and a map of the
rectangular family (dimensional axes, with the equivalent block) from the block's closed
forms above with alpha = theta_c and the body's own p; and a linearized history (e = 0)
under a record, solved piece by piece in closed form (cosh, sinh and the linear
particular solution) with uplifts, impacts and rests located in mpmath.

Analysis 'winkler' (never by running the driver): rigid bodies on tensionless Winkler
springs, written out from doc/winkler.md in mpmath (40 digits). The pushover of a circle
(constant or varying k) and of a block (constant or varying k): full contact while
sin 2 theta <= 2 W/(k pi r^3) (circle) or W/(2 alpha b^2 k) (block), with the closed-form
moments; after uplift the contact width solves k(b) Phi(b) = 2 W/sin 2 theta by bisection
(Phi = J1 - c A0 of the contact segment; the block's b'^2 alpha k(b') = 2 W/sin 2 theta),
the pole is the centroid of the contact, the centre rises by (r - b) sin theta; varying k
is Gazetas' K_R/I of the rectangle of the contact scaled to k at full contact; past pi/4
there is no equilibrium (NaN). The master curve in x = theta/theta_up (the same segment
integrals at small angles, or b' = 2 b/sqrt(x) for the rectangle), the capacities on clay
(N_ult = N_c S_u pi r^2, SF, chi, 0.8 A D S_u, W D (1 - chi)/2), and the inelastic pushover
with G = 1 (a_poly = 0): the elastic Winkler curve of K_R0 = HK_R k_el (k/k_el)(chi).

Analysis 'empirical' (never by running the driver): every model of doc/empirical.md whose
inputs the case has, per case, ky and model, written out here from the sources in mpmath
(40 digits). With &records the cases are the records read above (the 'newmark' part), with
their measures from record_measures (the 'intensity' part: PGV in cm/s here), Sa(1.5 Ts)
from the exact oscillator (the 'sdof' part; the PGA for Ts < 0.05 s) and the rigorous
columns from newmark_exact and newmark_slammer (downslope); a record that does not exist
gives NaN rows with status 1. The models: the rigid-block regressions (E.1)-(E.12) (ky >=
PGA in a model of ky/PGA: 0), Bray & Travasarou (E.13)-(E.16) with the exact normal
distribution (mpmath ncdf) or, with slammer, SLAMMER's polynomial, Rathje & Antonakos
(E.26)-(E.32), the probability of failure (E.35) at the median.

Analysis 'newmark' (never by running the driver): the record files are read here by a
small parser of their own (AT2, SLAMMER CSV, two columns, one column; the decimals taken
exactly), turned over by the polarity and scaled (scale, or target_pga over the PGA,
optionally rounded to 0.001 g as SLAMMER does); then per ky (or mu) and for the record
and its inverse (x -1):
  * method 'exact': the exact rigid-block solution of the record taken as linear between
    samples, event by event in mpmath (40 digits): while sliding in direction s the
    speed z obeys z' = s a(t) - ky_s, a quadratic on each step, so the stop is the first
    root of a quadratic; at rest an onset is where a crosses ky or -ky_up (linear);
    after the last sample a = 0 and a sliding block decelerates at ky_s; the slip along
    the plane is K_s times the integral of z;
  * method 'slammer': SLAMMER 1.1's explicit one-way recurrence (doc/newmark.md,
    RigidBlock.java of SLAMMER 1.1): cm/s^2 with g = 100 g, at rest n = sign(a) if |a| > ky else a/ky,
    y = a - n ky; sliding y = a - ky; v = v_prev + dt/2 (y + y_prev); v <= 0: v = y = 0;
    u += dt/2 (v + v_prev).
With mu the yields and factors are Eq. 1.31 and doc/sliding.md section 7 (resistances() above, A_g
= 1 g). A record file that does not exist gives NaN results and status 1 in its rows.
With &newmark intensity = .true. the intensity table goes to <case>.intensity.ref, per
record (scaled as above) in mpmath (40 digits): PGA; PGV and PGD as the largest |v|, |d|
at the samples and at the stationary points inside the steps (v and d integrated step by
step, the roots of v by mpmath's polyroots); Arias intensity and CAV by Gauss-Legendre
quadrature (mp.quad) of a^2 and |a| on each step (split at the zero of a); the Husid
times by the real root in the step of the cubic cumulative integral (polyroots); Tm by a
DFT summed directly at k/(N dt), N the power of two >= max(n, 1/(0.05 dt)); Sa from the
oscillator pieces of analysis 'sdof' below (true peaks, damping 0.05), (2 pi/T)^2 SD/g.

Analysis 'spectra' (never by running the driver): the EN 1998-1 elastic and design
spectra (3.2)-(3.6), (3.13)-(3.16) with Tables 3.2 and 3.3 and the Greek National Annex
zones, and EAK 2000 (K.1)-(K.6), written out here in mpmath; with &suite the check of
EN 1998-1 3.2.3.1.2(4): the grid in double as the driver builds it, the 5 % PSA of each
record from the oscillator pieces of analysis 'sdof' (true peaks), the mean, (M.1) and
(M.2)/(M.3): <case>.ref (the mean table; the spectra table when &spectra is given, then
the mean in <case>.mean.ref) and <case>.summary.ref (the one-row summary).

Analysis 'newmark' with method 'decoupled' or 'coupled' (a flexible sliding mass, &slope;
doc/flexible.md), per ky (or yield table) and polarity:
  * rule 'slammer': SLAMMER 1.1's Decoupled and Coupled as transcribed in plain Python by
    test/python/slammer_reference.py (float arithmetic in SLAMMER's order and units,
    checked there against SLAMMER's own Java); kmax, the final Vs and damping and the
    iterations from the same run, period = 4 height / vs_final;
  * rule 'exact', linear soil, method 'decoupled': the one-mode shear beam (omega =
    pi Vs / (2 H), damping + min(0.2, 0.55016 (vs_base/vs)^-0.9904)) driven by
    -(4/pi) a(t) g, a linear between samples, solved in closed form step by step in mpmath
    (homogeneous e^(-xi w t) (A cos w_d t + B sin w_d t) plus the linear particular
    solution) from rest; HEA = a + (2/pi) u''/g at the samples, taken as linear between
    them, drives the exact rigid block above (newmark_exact).
"""
import math
import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "python"))

import pulse_reference as ref  # noqa: E402
from mpmath import mp, mpf  # noqa: E402

HEADER = "t (s),a (m/s2),a_in_g (g),v (m/s),d (m)"
SLIDING_HEADER = ("case (-),mu (-),eta1 (-),eta2 (-),mode (-),t_y1 (s),t_m1 (s),u_m1 (m),"
                  "t_y2 (s),t_m2 (s),u_m2 (m),u_res (m),v_m1 (m/s),v_m2 (m/s)")
MODES = ("no_sliding", "unilateral", "stick", "slip", "stuck", "reverse_only")
# The names the driver writes in its category columns (code k: names[k]; -1: undecided)
ROCK_OUTCOMES = ("rest", "no_uplift", "overturn_no_impact", "overturn_one_impact",
                 "overturn_many_impacts", "time_limit")
ROCK_REGIONS = ("no_rocking", "O1", "O2", "O3", "S1", "S2")
MAP_CLASSES = ("safe", "overturn_no_impact", "overturn_one_impact",
               "overturn_many_impacts")
STATUS = ("ok", "failed")
CATEGORIES = {"mode (-)": MODES, "outcome (-)": ROCK_OUTCOMES, "region (-)": ROCK_REGIONS,
              "class (-)": MAP_CLASSES, "status (-)": STATUS, "converged (-)": ("no", "yes")}


def named(header, rows, categories=CATEGORIES):
    """rows with the code of each category column (by its header cell) as its name,
    as the driver writes it: code k -> names[k], -1 -> 'undecided', NaN -> 'nan'."""
    cols = {j: categories[h] for j, h in enumerate(header.split(",")) if h in categories}
    out = []
    for row in rows:
        row = list(row)
        for j, names in cols.items():
            x = row[j]
            if isinstance(x, str):
                continue
            if mp.isnan(x):
                row[j] = "nan"
            else:
                k = int(x)
                row[j] = "undecided" if k == -1 else names[k]
        out.append(row)
    return out

_TOKEN = re.compile(r"""
    \s*(?:
      (?P<group>&\w+)
    | (?P<end>/)
    | (?P<key>\w+)\s*=
    | (?P<str>'[^']*'|"[^"]*")
    | (?P<logical>\.(?:true|false|t|f)\.)
    | (?P<special>[-+]?(?:infinity|inf|nan)\b)
    | (?P<num>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?)
    | (?P<sep>,)
    )""", re.VERBOSE | re.IGNORECASE)


def parse_namelist(text):
    """Minimal Fortran namelist reader: {group: {key: value}} (lower-case names;
    strings, logicals, integers, reals including inf and nan; a key followed by several
    values, "mu_list = 0.1, 0.2", gives a list)."""
    text = "\n".join(line.split("!", 1)[0] for line in text.splitlines())
    groups, group, key, pos = {}, None, None, 0
    last = None        # the key of the last value, for list continuations
    while pos < len(text):
        if text[pos:].strip() == "":
            break
        m = _TOKEN.match(text, pos)
        if not m:
            raise ValueError(f"cannot parse namelist near {text[pos:pos + 30]!r}")
        pos = m.end()
        kind = m.lastgroup
        tok = m.group(kind)
        if kind == "group":
            group = groups.setdefault(tok[1:].lower(), {})
            last = None
        elif kind == "end":
            group, key, last = None, None, None
        elif kind == "key":
            if group is None:
                raise ValueError(f"key {tok!r} outside a group")
            key = tok.lower()
            last = None
        elif kind == "sep":
            continue
        else:
            if group is None or (key is None and last is None):
                raise ValueError(f"value {tok!r} without a key")
            if kind == "str":
                value = tok[1:-1]
            elif kind == "logical":
                value = tok.lower() in (".true.", ".t.")
            elif kind == "special":
                value = float(tok)
            elif re.fullmatch(r"[-+]?\d+", tok):
                value = int(tok)
            else:
                value = float(tok.replace("d", "e").replace("D", "e"))
            if key is None:             # a further value of the last key: a list
                if not isinstance(group[last], list):
                    group[last] = [group[last]]
                group[last].append(value)
            else:
                group[key] = value
                last, key = key, None
    return groups


def time_grid(tgroup):
    t_start = float(tgroup.get("t_start", 0.0))
    if "t_end" not in tgroup:
        raise ValueError("these references need an explicit t_end")
    t_end = float(tgroup["t_end"])
    if "dt" in tgroup:
        dt = float(tgroup["dt"])
        npts = math.floor((t_end - t_start) / dt * (1 + 1e-12)) + 1
    else:
        npts = int(tgroup["npts"])
        dt = (t_end - t_start) / (npts - 1)
    return [t_start + dt * i for i in range(npts)]          # double precision, as the driver


def pulse_function(pgroup):
    """(callable t -> (a, v, d) as mpf, g of the group)."""
    p = dict(pgroup)
    kind = p.pop("kind").lower()
    g = float(p.pop("g", ref.G_STANDARD))
    amp_unit = p.pop("amp_unit", "m/s2")
    amp = float(p.pop("amp"))
    if kind == "exponential":
        kw = dict(td=float(p.pop("duration")), beta=float(p.pop("beta")),
                  full=bool(p.pop("full", False)))
    elif kind in ("half_sine", "rectangular"):
        kw = dict(duration=float(p.pop("duration")))
    elif kind == "triangular":
        kw = dict(duration=float(p.pop("duration")), peak_frac=float(p.pop("peak_frac", 0.5)))
    elif kind in ("sine_cycle", "cosine_cycle"):
        kw = dict(period=float(p.pop("period") if "period" in p else p.pop("duration")),
                  cycles=int(float(p.pop("cycles", 1))))
    elif kind == "ricker":
        kw = dict(freq=float(p.pop("freq")))
        if "t0" in p:
            kw["t0"] = float(p.pop("t0"))
    elif kind == "mavroeidis_papageorgiou":
        if amp_unit != "m/s":
            amp_unit = "m/s"   # a velocity amplitude: no g scaling
        kw = dict(freq=float(p.pop("freq")), gamma=float(p.pop("gamma")),
                  nu_deg=float(p.pop("nu_deg", 0.0)))
        if "t0" in p:
            kw["t0"] = float(p.pop("t0"))
        if p:
            raise ValueError(f"unhandled &pulse keys {sorted(p)}")
        return (lambda t: ref.mavroeidis_papageorgiou(t, amp, **kw)), g
    else:
        raise ValueError(f"unknown kind {kind!r}")
    if p:
        raise ValueError(f"unhandled &pulse keys {sorted(p)}")
    func = ref.KINDS[kind]
    return (lambda t: func(t, amp, amp_unit=amp_unit, g=g, **kw)), g


# ---------------------------------------------------------------------------
# Analysis 'sliding': closed forms of the limit shapes, written from doc/sliding.md
# ---------------------------------------------------------------------------

def _as_list(x):
    return x if isinstance(x, list) else [x]


def resistances(mu, ag_over_g, slope_deg, xi_deg):
    """Eq. 1.31 and the along-plane factors of doc/sliding.md section 7, from the force balance:
    eta1,2 = (mu/A_g)(cos lambda -+ sin lambda/mu)/K1,2, K1,2 = cos(lambda - xi) +- mu
    sin(lambda - xi); eta = +inf where K <= 0."""
    mu, lam = mpf(mu), mp.radians(mpf(slope_deg))
    dl = lam - mp.radians(mpf(xi_deg))
    if not mp.tan(lam) < mu:
        raise ValueError("statically unstable slope: no reference")
    k1 = mp.cos(dl) + mu * mp.sin(dl)
    k2 = mp.cos(dl) - mu * mp.sin(dl)
    eta = mu / mpf(ag_over_g)
    eta1 = eta * (mp.cos(lam) - mp.sin(lam) / mu) / k1 if k1 > 0 else mp.inf
    eta2 = eta * (mp.cos(lam) + mp.sin(lam) / mu) / k2 if k2 > 0 else mp.inf
    return eta1, eta2, max(k1, mpf(0)), max(k2, mpf(0))


def rectangle_full(eta):
    """Box full cycle (doc/sliding.md section 5), dimensionless: the forward slide starts at 0 with
    relative acceleration 1 - eta, runs to tau = 1 at speed 1 - eta, then decelerates at
    1 + eta: stop tau_m1 = 1 + (1 - eta)/(1 + eta) = 2/(1 + eta), u_m1 = (1 - eta)/(1 + eta).
    There a = -1 exceeds eta the other way: slip. The reverse slide accelerates at 1 - eta
    up to tau = 2 (speed 2 eta (1 - eta)/(1 + eta)), then stops at rate eta:
    tau_m2 = 4/(1 + eta), u_m2 = 2 eta (1 - eta)/(1 + eta)^2."""
    q = (1 - eta) / (1 + eta)
    return dict(mode=3, ty1=mpf(0), tm1=2 / (1 + eta), um1=q, vm1=1 - eta,
                ty2=2 / (1 + eta), tm2=4 / (1 + eta), um2=2 * eta * q / (1 + eta),
                vm2=2 * eta * q)


def rectangle_half(eta):
    """Box half cycle (Newmark; Eq. 1.10a with tau_y = 0): tau_m = 1/eta,
    u_m = (1 - eta)/(2 eta), peak speed 1 - eta at tau = 1."""
    return dict(mode=1, ty1=mpf(0), tm1=1 / eta, um1=(1 - eta) / (2 * eta), vm1=1 - eta)


def triangle_half(eta):
    """Symmetric triangle half cycle (doc/sliding.md section 3, explicit triangle results; lobe
    area 1/2): tau_y = eta/2, V_m = (1 - eta)^2/2; free stop for eta <= 2 - sqrt 2."""
    if eta <= 2 - mp.sqrt(2):
        tm = (eta**2 + 2) / (4 * eta)
        um = (12 - 24 * eta + 12 * eta**2 - eta**4) / (96 * eta)
    else:
        tm = 1 - eta / 2 + (1 - eta) / mp.sqrt(2)
        um = (3 + 2 * mp.sqrt(2)) * (1 - eta)**3 / 12
    return dict(mode=1, ty1=eta / 2, tm1=tm, um1=um, vm1=(1 - eta)**2 / 2)


def sliding_shape(pgroup):
    """(shape name, full, A (m/s2), A/g, T (s), g) of a &pulse group with a closed form."""
    p = dict(pgroup)
    kind = p.get("kind", "exponential").lower()
    g = mpf(p.get("g", ref.G_STANDARD))
    amp = mpf(p.get("amp", 1.0))
    ag_over_g = amp if p.get("amp_unit", "m/s2") == "g" else amp / g
    a = ag_over_g * g if p.get("amp_unit", "m/s2") == "g" else amp
    td = mpf(p.get("duration", 1.0))
    full = bool(p.get("full", False))
    beta = p.get("beta", 0.0)
    if kind == "rectangular" or (kind == "exponential" and beta == -math.inf):
        shape = "rectangle"
    elif (kind == "triangular" and p.get("peak_frac", 0.5) == 0.5) or \
            (kind == "exponential" and beta == 0):
        shape = "triangle"
    else:
        raise ValueError(f"no closed-form reference for &pulse {pgroup}")
    if kind != "exponential":
        full = False
    if shape == "triangle" and full:
        raise ValueError("no closed-form reference for the triangular full cycle")
    return shape, full, a, ag_over_g, td, g


def sliding_rows(nml):
    shape, full, a, ag_over_g, td, g = sliding_shape(nml["pulse"])
    b = nml["block"]
    slope, xi = b.get("slope_deg", 0.0), b.get("xi_deg", 0.0)
    static = mpf(b.get("static_factor", 1.0))
    along = bool(b.get("along_plane", True))
    if shape == "triangle" and static != 1:
        raise ValueError("triangle references: static_factor = 1 only")
    if "mu_list" in b or "mu" in b:
        mus = _as_list(b.get("mu_list", b.get("mu")))
        cases = []
        for mu in mus:
            eta1, eta2, k1, k2 = resistances(mu, ag_over_g, slope, xi)
            if not along:
                k1 = k2 = mpf(1)
            cases.append((mpf(mu), eta1, eta2, k1, k2))
    else:
        etas = _as_list(b.get("eta_list", b.get("eta1")))
        eta2s = [b.get("eta2", e) for e in etas] if "eta1" in b else etas
        cases = [(mp.nan, mpf(e1), mpf(e2), mpf(1), mpf(1)) for e1, e2 in zip(etas, eta2s)]
    rows = []
    length, speed = a * td**2, a * td
    for i, (mu, eta1, eta2, k1, k2) in enumerate(cases, start=1):
        r = dict(mode=0, ty1=mp.nan, tm1=mp.nan, um1=mpf(0), vm1=mpf(0),
                 ty2=mp.nan, tm2=mp.nan, um2=mpf(0), vm2=mpf(0))
        if static * eta1 < 1:
            if shape == "rectangle" and full:
                if not eta2 == eta1:
                    raise ValueError("rectangle full-cycle references: symmetric friction")
                r.update(rectangle_full(eta1))
            elif shape == "rectangle":
                r.update(rectangle_half(eta1))
            else:
                r.update(triangle_half(eta1))
        elif full and static * eta2 < 1:
            raise ValueError("no reference for a reverse-only full cycle")
        row = [mpf(i), mu, eta1, eta2, mpf(r["mode"]), r["ty1"] * td, r["tm1"] * td,
               k1 * r["um1"] * length, r["ty2"] * td, r["tm2"] * td, k2 * r["um2"] * length,
               (k1 * r["um1"] - k2 * r["um2"]) * length, k1 * r["vm1"] * speed,
               k2 * r["vm2"] * speed]
        rows.append(row)
    return rows


def make_sliding_ref(nml_path, nml):
    with mp.workdps(40):
        rows = named(SLIDING_HEADER, sliding_rows(nml))
        lines = [SLIDING_HEADER] + [",".join(csv_cell(x) for x in row) for row in rows]
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out} ({len(lines) - 1} rows)")


# ---------------------------------------------------------------------------
# Analysis 'rocking': the linearized rectangle in closed form, written from doc/rocking.md
# ---------------------------------------------------------------------------

ROCKING_HEADER = ("alpha (rad),p (rad/s),e (-),f (-),eta (-),outcome (-),t_uplift (s),"
                  "t_overturn (s),n_impacts (-),t_impact1 (s),theta_max (rad),"
                  "theta_min (rad),psi_max (-),psi_min (-),t_end (s),region (-),"
                  "t_up_cf (s),t_c_cf (s),t_m_cf (s),psi_max_cf (-),t_i_cf (s)")
ROCKING_HISTORY_HEADER = "t (s),a_g (m/s2),theta (rad),omega (rad/s)"
ROCKING_MAP_HEADER = "freq_ratio (-),amp_ratio (-),class (-)"
# outcome codes: 0 rest, 2 overturn_no_impact; region codes: 1 O1, 2 O2, 3 O3, 5 S2


def rocking_block(b, g):
    """(alpha, p, e) of &block (doc/rocking.md section 1: R = sqrt(b^2 + h^2), alpha = atan(b/h),
    p = sqrt(g/(io R)), io = I_o/(m R^2) = 4/3 for the uniform rectangle; Housner's
    e = 1 - (2/io) sin^2 alpha, doc/rocking.md section 6)."""
    if str(b.get("model", "nonlinear")).lower() != "linearized":
        raise ValueError("rocking references: model = 'linearized' only")
    io = mpf(b["io_over_mr2"]) if "io_over_mr2" in b else mpf(4) / 3
    if "b" in b:
        bb, hh = mpf(b["b"]), mpf(b["h"])
        radius, alpha = mp.sqrt(bb**2 + hh**2), mp.atan(bb / hh)
    else:
        alpha = mp.radians(mpf(b["alpha_deg"])) if "alpha_deg" in b else mpf(b["alpha"])
        radius = mpf(b.get("r", 1.0))      # a map does not need r
    p = mp.sqrt(g / (io * radius))
    e = mpf(b["e"]) if "e" in b else max(mpf(0), 1 - (2 / io) * mp.sin(alpha)**2)
    return alpha, p, e


def rectangle_pulse(pgroup):
    """(A (m/s2), A/g, T (s), g) of a rectangular half-cycle &pulse."""
    p = dict(pgroup)
    kind = p.get("kind", "exponential").lower()
    rect = kind in ("rectangular", "rect") or (
        kind in ("exponential", "exp") and p.get("beta", 0.0) == -math.inf
        and not p.get("full", False))
    if not rect:
        raise ValueError(f"rocking references: rectangular half-cycle pulses only, not {p}")
    g = mpf(p.get("g", ref.G_STANDARD))
    amp = mpf(p.get("amp", 1.0))
    if p.get("amp_unit", "m/s2") == "g":
        return amp * g, amp, mpf(p.get("duration", 1.0)), g
    return amp, amp / g, mpf(p.get("duration", 1.0)), g


def rect_psi(tau, f, eta):
    """psi = theta/alpha and dpsi = (dtheta/dt)/(alpha p) of the first excursion,
    Eqs. 2.12, 2.13 (uplift at tau = 0)."""
    psi = (1 / eta - 1) * (mp.cosh(f * tau) - 1)
    dpsi = (1 / eta - 1) * mp.sinh(f * tau)
    if tau > 1:
        psi -= (mp.cosh(f * (tau - 1)) - 1) / eta
        dpsi -= mp.sinh(f * (tau - 1)) / eta
    return psi, dpsi


def rect_summary(f, eta, psi_cap):
    """Region and times (in t_d) of the linearized rectangle, and the time psi reaches
    psi_cap (|theta| = pi/2) for an overturning block."""
    if not eta < 1:
        raise ValueError("rocking references: eta < 1 only")
    one = 1 / (1 - eta)
    r = dict(tau_c=mp.nan, tau_m=mp.nan, psi_max=mp.nan, tau_i=mp.nan, tau_cap=mp.nan)
    if mp.cosh(f / 2) >= one:
        r["region"] = 1
    elif mp.cosh(f) >= one:
        r["region"] = 2
    elif eta < 1 - mp.exp(-f):                         # below the wall, Eq. 2.21
        r["region"] = 3
    else:
        r["region"] = 5                                # S2: the rectangle has no S1
    if r["region"] in (1, 2):
        r["tau_c"] = mp.acosh(one) / f                 # (1/eta - 1)(cosh f tau - 1) = 1
    elif r["region"] == 3:
        # psi - 1 = (1/eta - 1) cosh f tau - (1/eta) cosh f(tau - 1) = 0 after the pulse
        r["tau_c"] = mp.log((mp.exp(f) - 1 + eta) / (1 - eta - mp.exp(-f))) / (2 * f)
    if r["region"] == 5:
        tm = mp.log((1 - eta - mp.exp(f)) / (1 - eta - mp.exp(-f))) / (2 * f)    # 2.25
        r["tau_m"] = tm
        r["psi_max"] = (eta + (1 - eta) * mp.cosh(f * tm) - mp.cosh(f * (tm - 1))) / eta
        r["tau_i"] = mp.log(((mp.exp(-f) - 1) * mp.sqrt(mp.exp(f) * (1 - eta)) - eta)
                            / (1 - eta - mp.exp(-f))) / f                       # 2.33
        check = mp.findroot(lambda x: rect_psi(x, f, eta)[0], r["tau_i"])
        assert abs(check - r["tau_i"]) < mpf(10)**-30, "2.33 against 2.12"
    else:
        # psi = psi_cap: during the pulse, or A z + B/z = psi_cap - 1 after it (z = e^(f tau))
        during = mp.acosh(1 + (psi_cap * eta) / (1 - eta)) / f
        if during <= 1:
            r["tau_cap"] = during
        else:
            a = ((1 / eta - 1) - mp.exp(-f) / eta) / 2
            b = ((1 / eta - 1) - mp.exp(f) / eta) / 2
            y = psi_cap - 1
            r["tau_cap"] = mp.log((y + mp.sqrt(y * y - 4 * a * b)) / (2 * a)) / f
    return r


def rocking_summary_rows(nml):
    amp, amp_g, td, g = rectangle_pulse(nml["pulse"])
    alpha, p, e = rocking_block(nml["block"], g)
    f, eta = p * td, alpha / amp_g
    psi_cap = mp.pi / 2 / alpha
    r = rect_summary(f, eta, psi_cap)
    nan = mp.nan
    if r["region"] == 5:
        if e != 0:
            raise ValueError("rocking summary references: e = 0 for stable blocks")
        outcome, t_ov, n_imp, t_i1 = 0, nan, 1, r["tau_i"] * td
        theta_max, t_end = r["psi_max"] * alpha, r["tau_i"] * td
        cf = [r["region"], mpf(0), nan, r["tau_m"] * td, r["psi_max"], r["tau_i"] * td]
    else:
        outcome, t_ov, n_imp, t_i1 = 2, r["tau_c"] * td, 0, nan
        theta_max, t_end = mp.pi / 2, r["tau_cap"] * td
        cf = [r["region"], mpf(0), r["tau_c"] * td, nan, mp.inf, nan]
    row = [alpha, p, e, f, eta, outcome, mpf(0), t_ov, n_imp, t_i1, theta_max, mpf(0),
           theta_max / alpha, mpf(0), t_end] + cf
    return [row]


def rocking_history_rows(nml):
    amp, amp_g, td, g = rectangle_pulse(nml["pulse"])
    alpha, p, e = rocking_block(nml["block"], g)
    f, eta = p * td, alpha / amp_g
    r = rect_summary(f, eta, mp.pi / 2 / alpha)
    if r["region"] != 5 or e != 0:
        raise ValueError("rocking history references: a stable block (S2) with e = 0")
    func, _ = pulse_function(nml["pulse"])
    rows = []
    for t in time_grid({"t_end": nml["rocking"]["t_end"], **nml["rocking"]}):
        tau = mpf(t) / td
        if abs(tau - r["tau_i"]) < mpf(10)**-6 or abs(tau - 1) < mpf(10)**-6:
            raise ValueError(f"t = {t}: too close to the impact or the end of the pulse")
        if tau < r["tau_i"]:
            psi, dpsi = rect_psi(tau, f, eta)
        else:
            psi, dpsi = mpf(0), mpf(0)        # at rest after the impact (e = 0)
        rows.append([mpf(t), func(t)[0], psi * alpha, dpsi * alpha * p])
    return rows


def rocking_map_rows(nml):
    m = nml["map"]
    kind = m.get("kind", "exponential").lower()
    if not (kind in ("rectangular", "rect") or (kind in ("exponential", "exp")
                                                 and m.get("beta", 0.0) == -math.inf
                                                 and not m.get("full", False))):
        raise ValueError("rocking map references: the rectangular family only")
    alpha, _, _ = rocking_block(nml["block"], mpf(1))

    rows = []
    for a in axis_mp(m, "amp_ratio", "amp", 21):
        for fr in axis_mp(m, "freq_ratio", "freq", 21):
            rows.append([fr, a, mpf(map_class(alpha, fr, a))])   # p = 1, T = 2 pi/fr
    return rows


def rect_records(nml_path, nml):
    """The block (alpha, p, e, g) of &block and, per file of &records, (label, polarity,
    A (g), t_d (s), rect_summary) for records that are rectangular pulses: every sample A
    (g) of a record, n samples dt apart, is the rectangular half-cycle pulse of amplitude
    A and duration (n - 1) dt (the record is linear between samples and 0 after the
    last); None for a file that does not exist."""
    nr, b = nml["records"], nml["block"]
    files = _as_list(nr["files"])
    n = len(files)
    if any(k in nr for k in ("scale", "target_pga")) or "g" in b:
        raise ValueError("rocking records references: records as read, g = 9.80665")
    g = mpf(ref.G_STANDARD)
    alpha, p, e = rocking_block(b, g)
    out = []
    for file, fmt, units, step, pol in zip(files, per_file(nr, "format", n, "auto"),
                                           per_file(nr, "units", n, "auto"),
                                           per_file(nr, "dt", n, 0.0),
                                           per_file(nr, "polarity", n, 1)):
        path = Path(nml_path).parent / file
        if not path.exists():
            out.append((path.stem, pol, None, None, None))
            continue
        acc, step = read_record(path, fmt.lower(), units.lower(), step)
        if any(x != acc[0] for x in acc) or not acc[0] > 0:
            raise ValueError(f"{file}: a rectangular pulse (equal samples > 0) only")
        td = mpf(float((len(acc) - 1) * float(step)))     # the last sample, in double
        r = rect_summary(p * td, alpha / acc[0], mp.pi / 2 / alpha)
        if r["region"] == 5 and e != 0:
            raise ValueError("rocking records references: e = 0 for stable blocks")
        out.append((path.stem, pol, acc[0], td, r))
    return (alpha, p, e, g), out


def rocking_records_history_rows(nml_path, nml):
    """The stacked history (label, t, a_g, theta, omega) from rect_records, in closed
    form (e = 0; a stable block rests at its first impact, an overturning one stays at
    +-pi/2 from the time it gets there). Polarity -1 mirrors theta and a_g; a file that
    does not exist gives one row of NaN."""
    (alpha, p, e, g), recs = rect_records(nml_path, nml)
    grid = time_grid(nml["rocking"])
    rows = []
    for label, pol, amp_g, td, r in recs:
        if r is None:
            rows.append([label] + [mp.nan] * 4)
            continue
        f, eta = p * td, alpha / amp_g
        t_stop = r["tau_i"] if r["region"] == 5 else r["tau_cap"]
        for t in grid:
            tau = mpf(t) / td
            if abs(tau - t_stop) < mpf(10)**-6 or abs(tau - 1) < mpf(10)**-6:
                raise ValueError(f"t = {t}: too close to an event or the end of {label}")
            if tau < t_stop:
                psi, dpsi = rect_psi(tau, f, eta)
                theta, omega = psi * alpha, dpsi * alpha * p
            elif r["region"] == 5:
                theta, omega = mpf(0), mpf(0)          # at rest after the impact (e = 0)
            else:
                theta, omega = mp.pi / 2, mpf(0)       # overturned
            a_g = amp_g * g if tau <= 1 else mpf(0)
            rows.append([label, mpf(t), pol * a_g, pol * theta, pol * omega])
    return rows


ROCKING_RECORDS_HEADER = ("record (-),pga (g),alpha (rad),p (rad/s),e (-),outcome (-),"
                          "t_uplift (s),t_overturn (s),n_impacts (-),t_impact1 (s),"
                          "theta_max (rad),theta_min (rad),psi_max (-),psi_min (-),t_end (s),"
                          "theta_abs_max (rad),t_abs_max (s),status (-)")


def rocking_records_summary_rows(nml_path, nml):
    """One summary row per record from rect_records: a stable block (S2, e = 0) rests at
    its first impact tau_i (2.33) with its maximum psi_max (2.29) at tau_m (2.25); an
    overturning one (no impact) crosses alpha at tau_c and reaches pi/2 at tau_cap.
    Polarity -1 swaps theta_max and -theta_min. Outcome and status by code (named by
    the caller); a file that does not exist: NaN but the block, status 1."""
    (alpha, p, e, g), recs = rect_records(nml_path, nml)
    nan = mp.nan
    rows = []
    for label, pol, amp_g, td, r in recs:
        if r is None:
            rows.append([label, nan, alpha, p, e] + [nan] * 12 + [mpf(1)])
            continue
        if r["region"] == 5:
            outcome, t_ov, n_imp, t_i1 = 0, nan, 1, r["tau_i"] * td
            peak, t_peak, t_end = r["psi_max"] * alpha, r["tau_m"] * td, r["tau_i"] * td
        else:
            outcome, t_ov, n_imp, t_i1 = 2, r["tau_c"] * td, 0, nan
            peak, t_end = mp.pi / 2, r["tau_cap"] * td
            t_peak = t_end
        th_max, th_min = (peak, mpf(0)) if pol > 0 else (mpf(0), -peak)
        rows.append([label, amp_g, alpha, p, e, outcome, mpf(0), t_ov, n_imp, t_i1, th_max,
                     th_min, th_max / alpha, th_min / alpha, t_end, peak, t_peak, mpf(0)])
    return rows


def ref_cell(x):
    """A reference cell: text quoted, a number as repr(float)."""
    return f'"{x}"' if isinstance(x, str) else repr(float(x))


def make_rocking_ref(nml_path, nml):
    what = nml.get("rocking", {}).get("what", "summary").lower()
    if "records" in nml:
        with mp.workdps(40):
            if what == "history":
                header = "record (-)," + ROCKING_HISTORY_HEADER
                rows = rocking_records_history_rows(nml_path, nml)
            else:
                header = ROCKING_RECORDS_HEADER
                rows = named(header, rocking_records_summary_rows(nml_path, nml))
        lines = [header] + [",".join(ref_cell(x) for x in row) for row in rows]
        out = Path(nml_path).with_suffix(".ref")
        out.write_text("\n".join(lines) + "\n")
        print(f"wrote {out} ({len(lines) - 1} rows)")
        return
    with mp.workdps(40):
        if what == "summary":
            header, rows = ROCKING_HEADER, rocking_summary_rows(nml)
        elif what == "history":
            header, rows = ROCKING_HISTORY_HEADER, rocking_history_rows(nml)
        else:
            header, rows = ROCKING_MAP_HEADER, rocking_map_rows(nml)
        rows = named(header, rows)
        lines = [header] + [",".join(csv_cell(x) for x in row) for row in rows]
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out} ({len(lines) - 1} rows)")


# ---------------------------------------------------------------------------
# Analysis 'cylinder': a rigid body of revolution or a block on a rigid base, written
# from doc/cylinder.md and the mechanics of a rigid body (never from the driver)
# ---------------------------------------------------------------------------

CYLINDER_PROPS_LABELS = ("shape (-)", "r (m)", "r_inner (m)", "h (m)", "mass (kg)",
                         "g (m/s2)", "theta_c (rad)", "theta_c (deg)", "h/r (-)", "R (m)",
                         "J_o (kg m2)", "J_G (kg m2)", "J_axis (kg m2)", "J_o/(m R2) (-)",
                         "p (rad/s)", "e (-)", "W (N)", "M_max (N m)", "F_uplift (N)",
                         "tan(theta_c) (g)")
CYLINDER_PROPS_HEADER = "quantity (in name),body (as named),equivalent (as named)"
CYLINDER_PUSHOVER_HEADER = ("theta (rad),theta_ratio (-),force (N),moment (N m),"
                            "m_ratio (-),stable (-)")
CYLINDER_HISTORY_HEADER = "t (s),a_g (m/s2),theta (rad),omega (rad/s)"
SHAPES = {"solid": 1, "hollow": 2, "custom": 3, "block": 4}


def rigid_body(shape, r, h, m, g, r_inner=None, j_o=None, j_axis=None):
    """Properties of a body on a rigid base, from the parallel-axis theorem: J_G of a
    solid cylinder about a transverse diameter m (3 r^2 + 4 h^2)/12 (h: half-height),
    hollow m (3 (r^2 + r_i^2) + 4 h^2)/12, uniform block (half-width b = r) m (b^2 + h^2)/3;
    J_o = J_G + m R^2 with R = sqrt(r^2 + h^2); p = sqrt(m g R/J_o); Housner's
    e = max(0, 1 - (2 m R^2/J_o) sin^2 theta_c) (doc/cylinder.md)."""
    nan = mp.nan
    big_r2 = r**2 + h**2
    ri = mpf(0)
    if shape == "solid":
        j_g, j_ax = m * (3 * r**2 + 4 * h**2) / 12, m * r**2 / 2
    elif shape == "hollow":
        ri = r_inner
        j_g, j_ax = m * (3 * (r**2 + ri**2) + 4 * h**2) / 12, m * (r**2 + ri**2) / 2
    elif shape == "custom":
        j_g, j_ax = j_o - m * big_r2, (j_axis if j_axis is not None else nan)
    else:
        j_g, j_ax = m * big_r2 / 3, nan
    jo = j_g + m * big_r2
    big_r = mp.sqrt(big_r2)
    tc = mp.atan(r / h)
    p = mp.sqrt(m * g * big_r / jo)
    e = max(mpf(0), 1 - 2 * m * big_r2 / jo * mp.sin(tc)**2)
    w = m * g
    return dict(shape=SHAPES[shape], r=r, r_inner=ri, h=h, mass=m, g=g, theta_c=tc,
                theta_c_deg=tc * 180 / mp.pi, h_over_r=h / r, R=big_r, J_o=jo, J_G=j_g,
                J_axis=j_ax, j=jo / (m * big_r2), p=p, e=e, W=w, M_max=w * r,
                F_uplift=w * r / h, tan_c=mp.tan(tc))


def props_values(bd):
    keys = ("shape", "r", "r_inner", "h", "mass", "g", "theta_c", "theta_c_deg", "h_over_r",
            "R", "J_o", "J_G", "J_axis", "j", "p", "e", "W", "M_max", "F_uplift", "tan_c")
    return [bd[k] for k in keys]


def cylinder_body(b):
    """The body of &body (SI, mpf)."""
    shape = str(b.get("shape", "solid")).lower()
    g = mpf(b.get("g", 9.80665))
    m = mpf(b.get("mass", 1.0))
    h = mpf(b["h"])
    if shape == "block":
        return rigid_body("block", mpf(b["b"]), h, m, g)
    kw = {}
    if shape == "hollow":
        kw["r_inner"] = mpf(b["r_inner"])
    if shape == "custom":
        kw["j_o"] = mpf(b["j_o"])
        if "j_axis" in b:
            kw["j_axis"] = mpf(b["j_axis"])
    return rigid_body(shape, mpf(b["r"]), h, m, g, **kw)


def equivalent_of(bd, angle=None):
    """The equivalent body: the same p and the same static M_max = m g r (doc/cylinder.md).
    Of a cylinder, the uniform block with slenderness alpha (default theta_c): p^2 =
    3 g/(4 R_b) gives R_b, then b = R_b sin(alpha), h = R_b cos(alpha), m_b = m r/b. Of a
    block, the solid cylinder with slenderness theta_c (default alpha): J_o/(m R^2) =
    (5/4) sin^2 + (4/3) cos^2 = j, R = g/(p^2 j), r = R sin, h = R cos, m_c = m b/r."""
    g, p = bd["g"], bd["p"]
    a = bd["theta_c"] if angle is None else mpf(angle)
    if bd["shape"] == 4:
        j = mpf(5) / 4 * mp.sin(a)**2 + mpf(4) / 3 * mp.cos(a)**2
        big_r = g / (p**2 * j)
        r = big_r * mp.sin(a)
        return rigid_body("solid", r, big_r * mp.cos(a), bd["mass"] * bd["r"] / r, g)
    big_r = 3 * g / (4 * p**2)
    b = big_r * mp.sin(a)
    return rigid_body("block", b, big_r * mp.cos(a), bd["mass"] * bd["r"] / b, g)


def axis_mp(group, lname, stem, count_default):
    """The values of a list key or of a range, as mpf (axis_grid: the driver's doubles,
    both ends exact), count_default when `<stem>_count` is not given."""
    return [mpf(x) for x in axis_grid(group, lname, stem, count_default)]


def cylinder_pushover_rows(bd, c):
    """F = W tan(theta_c - theta) at the centre of mass, M = W (r cos theta - h sin theta)
    about the pivot, M/(m g r), stable = theta <= theta_c (doc/cylinder.md)."""
    if "theta" in c or "theta_range" in c:
        th = axis_mp(c, "theta", "theta", 21)
        us = [t / bd["theta_c"] for t in th]
    else:
        if "theta_ratio" in c or "theta_ratio_range" in c:
            us = axis_mp(c, "theta_ratio", "theta_ratio", 21)
        else:
            us = [mpf(float(i / 20)) for i in range(21)]
        # the driver's theta: the double u times the double theta_c (stable: u <= 1)
        th = [mpf(float(u) * float(bd["theta_c"])) for u in us]
    rows = []
    for t, u in zip(th, us):
        w, r, h = bd["W"], bd["r"], bd["h"]
        force = w * mp.tan(bd["theta_c"] - t)
        moment = w * (r * mp.cos(t) - h * mp.sin(t))
        rows.append([t, u, force, moment, moment / (bd["mass"] * bd["g"] * r),
                     mpf(1 if u <= 1 else 0)])
    return rows


def cylinder_history_rows(nml, bd):
    """The linearized rocking of the body under a rectangular half-cycle pulse, e = 0:
    the block's closed forms of doc/rocking.md with alpha = theta_c and the body's p."""
    body = nml["body"]
    if str(body.get("model", "nonlinear")).lower() != "linearized" or float(body["e"]) != 0:
        raise ValueError("cylinder history references: model = 'linearized', e = 0 only")
    amp, amp_g, td, g = rectangle_pulse(nml["pulse"])
    alpha, p = bd["theta_c"], bd["p"]
    f, eta = p * td, alpha / amp_g
    r = rect_summary(f, eta, mp.pi / 2 / alpha)
    if r["region"] != 5:
        raise ValueError("cylinder history references: a stable body (S2)")
    func, _ = pulse_function(nml["pulse"])
    rows = []
    for t in time_grid(nml["cylinder"]):
        tau = mpf(t) / td
        if abs(tau - r["tau_i"]) < mpf(10)**-6 or abs(tau - 1) < mpf(10)**-6:
            raise ValueError(f"t = {t}: too close to the impact or the end of the pulse")
        psi, dpsi = rect_psi(tau, f, eta) if tau < r["tau_i"] else (mpf(0), mpf(0))
        rows.append([mpf(t), func(t)[0], psi * alpha, dpsi * alpha * p])
    return rows


def linearized_record_segments(acc, dt, alpha, p, g, t_stop):
    """Linearized rocking (doc/rocking.md (2.7), a_g > 0 drives theta > 0) with e = 0 under a
    record acc (g) at t = k dt, linear in between, 0 after the last sample, from rest, up
    to t_stop: on side s, theta'' = p^2 (theta - s alpha + a/g); on a piece where
    a = a0 + k (t - t0) the solution is C1 cosh p(t - t0) + C2 sinh p(t - t0) + s alpha
    - a/g. Uplift when |a| > g alpha (side sign(a)); an impact (theta = 0) stops the body
    (e = 0) and it waits for the next uplift. Returns the segments (t0, t1, state) with
    state None (rest) or (s, C1, C2, a0, k) on [t0, t1], and the impact times."""
    n = len(acc)
    knots = [k * dt for k in range(n)]
    pieces = [(knots[k], knots[k + 1], g * acc[k], g * (acc[k + 1] - acc[k]) / dt)
              for k in range(n - 1)]
    if knots[-1] < t_stop:
        pieces.append((knots[-1], mpf(t_stop), mpf(0), mpf(0)))
    thr = g * alpha
    segs, impacts = [], []

    def theta(st, t0, u):
        s, c1, c2, a0, k = st
        x = p * (u - t0)
        return (c1 * mp.cosh(x) + c2 * mp.sinh(x) + s * alpha - (a0 + k * (u - t0)) / g,
                p * (c1 * mp.sinh(x) + c2 * mp.cosh(x)) - k / g)

    state, t, th, om = None, mpf(0), mpf(0), mpf(0)
    for ta, tb, a0, k in pieces:
        def acc_at(u):
            return a0 + k * (u - ta)
        while t < tb:
            if state is None:
                # the first time in [t, tb) where |a| > g alpha
                up = t if abs(acc_at(t)) > thr else None
                if up is None and k != 0:
                    cands = [ta + (lvl - a0) / k for lvl in (thr, -thr)]
                    cands = [u for u in cands if t < u < tb and k * mp.sign(acc_at(u)) > 0]
                    up = min(cands) if cands else None
                if up is None:
                    segs.append((t, tb, None))
                    t = tb
                    continue
                if up > t:
                    segs.append((t, up, None))
                # at the uplift a is at the threshold or beyond: the side is its sign
                side = mp.sign(acc_at(up)) if acc_at(up) != 0 else mp.sign(k)
                t, th, om, state = up, mpf(0), mpf(0), side
            s = state
            c1 = th - s * alpha + acc_at(t) / g
            c2 = (om + k / g) / p
            st = (s, c1, c2, acc_at(t), k)
            # the first return to theta = 0 on this piece, by sampling and bisection
            m = 400
            prev = t
            hit = None
            for j in range(1, m + 1):
                u = t + (tb - t) * j / m
                if s * theta(st, t, u)[0] <= 0:
                    hit = mp.findroot(lambda v: theta(st, t, v)[0], (prev, u),
                                      solver="anderson")
                    break
                prev = u
            if hit is None:
                segs.append((t, tb, (st, t)))
                th, om = theta(st, t, tb)
                if abs(th) >= mp.pi / 2:
                    raise ValueError("cylinder record references: the body overturns")
                t = tb
                continue
            segs.append((t, hit, (st, t)))
            impacts.append(hit)
            t, th, om, state = hit, mpf(0), mpf(0), None
    return segs, impacts, theta


def cylinder_record_rows(nml_path, nml, bd):
    """The history table of one record (label, t, a_g, theta, omega) from
    linearized_record_segments, for a body with alpha = theta_c and the body's own p."""
    body, nr = nml["body"], nml["records"]
    if str(body.get("model", "nonlinear")).lower() != "linearized" or float(body["e"]) != 0:
        raise ValueError("cylinder record references: model = 'linearized', e = 0 only")
    if isinstance(nr["files"], list) or any(k in nr for k in ("scale", "target_pga",
                                                               "polarity")):
        raise ValueError("cylinder record references: one record as read")
    path = Path(nml_path).parent / nr["files"]
    acc, step = read_record(path, nr.get("format", "auto").lower(),
                            nr.get("units", "auto").lower(), nr.get("dt", 0.0))
    grid = time_grid(nml["cylinder"])
    g, alpha, p = bd["g"], bd["theta_c"], bd["p"]
    segs, impacts, theta = linearized_record_segments(acc, step, alpha, p, g, grid[-1])
    label = Path(path).stem
    rows = []
    for t in grid:
        tt = mpf(t)
        if any(abs(tt - u) < mpf(10)**-6 for u in impacts):
            raise ValueError(f"t = {t}: too close to an impact")
        k = min(int(tt / step), len(acc) - 1)
        if k < len(acc) - 1:
            a = acc[k] + (acc[k + 1] - acc[k]) * (tt / step - k)
        else:
            a = acc[-1] if tt == (len(acc) - 1) * step else mpf(0)
        th = om = mpf(0)
        for t0, t1, state in segs:
            if t0 <= tt <= t1:
                if state is not None:
                    th, om = theta(state[0], state[1], tt)
                break
        rows.append([label, tt, g * a, th, om])
    return rows


def map_class(alpha, fr, a):
    """Class of a cell of the linearized rectangular-pulse map (p = 1, f = 2 pi/fr, amp
    ratio a): uplift at g alpha, so eta = alpha/(a tan alpha); overturns (1) below the
    stability wall eta = 1 - e^(-f), safe (0) above it or without uplift."""
    if a == 0:
        return 0
    f = 2 * mp.pi / fr
    eta = alpha / (a * mp.tan(alpha))
    wall = 1 - mp.exp(-f)
    if abs(eta - wall) < mpf(10)**-6 * wall or abs(eta - 1) < mpf(10)**-6:
        raise ValueError(f"cell ({fr}, {a}) is too close to a boundary")
    return 1 if eta < wall else 0


CYLINDER_MAP_DIFF = ("same", "only_cylinder", "only_block", "other_mode")


def cylinder_map_rows(nml, bd):
    """Overturning map of the rectangular family, linearized model, on either axis
    system: freq_ratio = 2 pi f_p/p, amp_ratio = PGA/tan(theta_c); with compare_block the
    equivalent block (same p; its own slenderness) on the same cells and the difference
    (same, only the body, only the block, both by other classes). The classes and the
    difference are written by name (text cells)."""
    m = nml["map"]
    if str(nml["body"].get("model", "nonlinear")).lower() != "linearized":
        raise ValueError("cylinder map references: model = 'linearized' only")
    kind = m.get("kind", "sine_cycle").lower()
    if kind not in ("rectangular", "rect"):
        raise ValueError("cylinder map references: the rectangular family only")
    dimensional = str(m.get("axes", "dimensionless")).lower() == "dimensional"
    compare = bool(m.get("compare_block", False))
    eq = equivalent_of(bd, nml["body"].get("equivalent_angle")) if compare else None
    if dimensional:
        xs, ys = axis_mp(m, "freq_hz", "freq_hz", 21), axis_mp(m, "pga", "pga", 21)
    else:
        xs = axis_mp(m, "freq_ratio", "freq", 21)
        ys = axis_mp(m, "amp_ratio", "amp", 21)
    rows = []
    for y in ys:
        for x in xs:
            if dimensional:
                fr, ar = 2 * mp.pi * x / bd["p"], y / bd["tan_c"]
                row = [x, y, fr, ar]
            else:
                fr, ar = x, y
                row = [x, y, x * bd["p"] / (2 * mp.pi), y * bd["tan_c"]]
            cls = map_class(bd["theta_c"], fr, ar)
            row.append(MAP_CLASSES[cls])
            if compare:
                if dimensional:
                    frb, arb = 2 * mp.pi * x / eq["p"], y / eq["tan_c"]
                else:
                    frb, arb = fr, ar
                clb = map_class(eq["theta_c"], frb, arb)
                if cls == clb:
                    diff = 0
                elif clb == 0:
                    diff = 1
                elif cls == 0:
                    diff = 2
                else:
                    diff = 3
                row += [MAP_CLASSES[clb], CYLINDER_MAP_DIFF[diff]]
            rows.append(row)
    header = (("freq_hz (Hz),pga (g),freq_ratio (-),amp_ratio (-)" if dimensional else
               "freq_ratio (-),amp_ratio (-),freq_hz (Hz),pga (g)") + ",class (-)"
              + (",class_block (-),diff (-)" if compare else ""))
    return header, rows


def make_cylinder_ref(nml_path, nml):
    c = nml.get("cylinder", {})
    what = str(c.get("what", "props")).lower()
    with mp.workdps(40):
        bd = cylinder_body(nml["body"])
        if what == "props":
            eq = equivalent_of(bd, nml["body"].get("equivalent_angle"))
            lines = [CYLINDER_PROPS_HEADER] + [
                f'"{label}",' + ",".join(repr(float(x)) for x in (u, v))
                for label, u, v in zip(CYLINDER_PROPS_LABELS, props_values(bd),
                                       props_values(eq))]
        else:
            if what == "pushover":
                header, rows = CYLINDER_PUSHOVER_HEADER, cylinder_pushover_rows(bd, c)
            elif what == "history" and "records" in nml:
                header = "record (-)," + CYLINDER_HISTORY_HEADER
                rows = cylinder_record_rows(nml_path, nml, bd)
            elif what == "history":
                header, rows = CYLINDER_HISTORY_HEADER, cylinder_history_rows(nml, bd)
            elif what == "map":
                header, rows = cylinder_map_rows(nml, bd)
            else:
                raise ValueError(f"cylinder references: no reference for what = {what!r}")
            lines = [header] + [",".join(csv_cell(x) for x in row) for row in rows]
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out} ({len(lines) - 1} rows)")


# ---------------------------------------------------------------------------
# Analysis 'newmark': rigid-block sliding on record files, event by event in mpmath
# ---------------------------------------------------------------------------

G_STANDARD = mpf("9.80665")
TO_G = {"g": mpf(1), "m/s2": G_STANDARD, "m/s^2": G_STANDARD, "cm/s2": 100 * G_STANDARD,
        "cm/s^2": 100 * G_STANDARD, "gal": 100 * G_STANDARD}


def read_record(path, fmt, units, dt, as_double=False):
    """(accel in g, dt) of a record file, values as the exact decimals written (as_double:
    as the driver holds them, each decimal rounded to a double and divided in double by
    9.80665 or 100 * 9.80665)."""
    if as_double:
        acc, step = read_record(path, fmt, "g", dt)
        file_units, undo = ("g" if units == "auto" else units), 1
        if Path(path).suffix.lower() == ".at2" or fmt == "at2":
            line3 = Path(path).read_text().splitlines()[2].upper()
            file_units = "cm/s2" if "CM/S" in line3 else "m/s2" if "M/S" in line3 else "g"
            undo = TO_G[file_units]                   # read_record divided by it
        gd = 9.80665
        div = {"g": None, "m/s2": gd, "m/s^2": gd}.get(file_units, 100.0 * gd)
        raw = [float(x * undo) for x in acc]          # the decimals as doubles
        return [x if div is None else x / div for x in raw], step
    lines = Path(path).read_text().splitlines()
    if fmt == "auto" and Path(path).suffix.lower() == ".at2":
        fmt = "at2"
    if fmt == "at2":
        line3 = lines[2].upper()
        file_units = "cm/s2" if "CM/S" in line3 else "m/s2" if "M/S" in line3 else "g"
        m = re.search(r"NPTS=\s*(\d+),\s*DT=\s*([0-9.]+)", lines[3].upper())
        npts, step = int(m.group(1)), mpf(m.group(2))
        values = [mpf(x) for line in lines[4:] for x in line.split()]
        assert len(values) == npts
        return [x / TO_G[file_units] for x in values], step
    rows = [line.replace(",", " ").split() for line in lines
            if line.strip() and not line.lstrip().startswith("#")]
    if len(rows[0]) == 1:
        values, step = [mpf(r[0]) for r in rows], mpf(dt)
    else:
        times = [mpf(r[0]) for r in rows]
        values, step = [mpf(r[1]) for r in rows], (times[-1] - times[0]) / (len(rows) - 1)
    scale = TO_G["g" if units == "auto" else units]
    return [x / scale for x in values], step


def first_stop(z, b, c, h):
    """Smallest x in (0, h] with z + b x + c x^2 = 0 (z >= 0), or None."""
    if z == 0:
        roots = [-b / c] if c != 0 else []
    elif c == 0:
        roots = [-z / b] if b != 0 else []
    else:
        disc = b * b - 4 * c * z
        if disc < 0:
            return None
        sq = mp.sqrt(disc)
        roots = [(-b - sq) / (2 * c), (-b + sq) / (2 * c)]
    roots = [x for x in roots if 0 < x <= h]
    return min(roots) if roots else None


def newmark_exact(acc, dt, ky, ky_up, k_dn, k_up):
    """(max |u|, final u) in g s^2 of the block on the piecewise-linear record acc (g);
    ky_up = inf: one way."""
    u = umax = umin = z = mpf(0)
    d = 0                                 # direction of the slide, 0 at rest

    def yield_of(s):
        return (ky, k_dn) if s > 0 else (ky_up, k_up)

    for a0, a1 in zip(acc[:-1], acc[1:]):
        slope = (a1 - a0) / dt
        x, stopped = mpf(0), 0
        while True:
            ax = a0 + slope * x
            h = dt - x
            if d != 0:
                ay, k = yield_of(d)
                b, c = d * ax - ay, d * slope / 2
                xs = first_stop(z, b, c, h)
                if xs is None:            # slides to the end of the step
                    u += d * k * (z * h + b * h**2 / 2 + c * h**3 / 3)
                    z += b * h + c * h**2
                    break
                u += d * k * (z * xs + b * xs**2 / 2 + c * xs**3 / 3)
                x, z, stopped, d = x + xs, mpf(0), d, 0
                umax, umin = max(umax, u), min(umin, u)
                continue
            # at rest: an onset now (not the way it just stopped), or a crossing later
            if stopped != 1 and ax > ky:
                d = 1
            elif stopped != -1 and -ax > ky_up:
                d = -1
            elif a1 > ky:
                x, d, stopped = x + (ky - ax) / slope, 1, 0
            elif -a1 > ky_up:
                x, d, stopped = x + (-ky_up - ax) / slope, -1, 0
            else:
                break
    if d != 0:                            # after the record a = 0: decelerates at ky
        ay, k = yield_of(d)
        u += d * k * z * z / (2 * ay)
        umax, umin = max(umax, u), min(umin, u)
    return max(umax, -umin), u


def newmark_slammer(acc, dt, ky, g):
    """(max u, final u) in cm of SLAMMER's one-way recurrence."""
    gcm = 100 * g
    t = ky * gcm
    u_prev = v_prev = y_prev = mpf(0)
    u_max = mpf(0)
    for a_g in acc:
        a = a_g * gcm
        if v_prev < mpf("1e-15"):         # at rest: n = sign(a) if |a| > ky else a/ky
            y = a - mp.sign(a) * t if abs(a) > t else mpf(0)
        else:
            y = a - t
        v = v_prev + dt / 2 * (y + y_prev)
        if v <= 0:
            v = y = mpf(0)
        u = u_prev + dt / 2 * (v + v_prev)
        u_max = max(u_max, u)
        u_prev, v_prev, y_prev = u, v, y
    return u_max, u_prev


def newmark_header(with_mu):
    cols = ["record (-)", "pga (g)", "scale (-)"] + (["mu (-)"] if with_mu else [])
    cols += ["ky (g)", "ky_up (g)"]
    for which in ("normal", "inverse"):
        for what in ("max", "final"):
            cols += [f"{what}_{which} (m)", f"{what}_{which}_cm (cm)"]
    return ",".join(cols + ["status (-)"])


def per_file(group, key, n, default):
    values = _as_list(group.get(key, default))
    return values if len(values) == n else values * n


def newmark_blocks(nb):
    """[(mu, ky, ky_up, k_down, k_up)] of &newmark and the mode."""
    mode = nb.get("mode", "asym" if "mu" in nb else "down").lower()
    if "mu" in nb:
        along = bool(nb.get("along_plane", True))
        blocks = []
        for mu in _as_list(nb["mu"]):
            eta1, eta2, k1, k2 = resistances(mu, 1, nb.get("slope_deg", 0.0),
                                             nb.get("xi_deg", 0.0))
            if not along:
                k1 = k2 = mpf(1)
            # a way that cannot slide (eta = inf, K = 0) keeps K = 1: never used
            blocks.append((mpf(mu), eta1, eta2, k1 if k1 > 0 else mpf(1),
                           k2 if k2 > 0 else mpf(1)))
        return blocks, mode
    kys = [mpf(k) for k in _as_list(nb["ky"])]
    if mode == "down":
        ups = [mp.inf] * len(kys)
    elif mode == "both":
        ups = kys
    else:
        ups = [mpf(k) for k in per_file(nb, "ky_up", len(kys), None)]
    kd, ku = (mpf(nb.get("k_down", 1)), mpf(nb.get("k_up", 1))) if mode == "asym" else (1, 1)
    return [(mp.nan, k, up, mpf(kd), mpf(ku)) for k, up in zip(kys, ups)], mode


FLEX_COLUMNS = ["kmax (g)", "vs_final (m/s)", "damping_final (-)", "period (s)",
                "iterations (-)", "converged (-)"]


def radiation_damping(vs, vs_base):
    """Lee's radiation damping (fraction), capped at 0.2 (doc/flexible.md)."""
    return min(mpf("0.2"), mpf("0.55016") * (mpf(vs_base) / mpf(vs)) ** mpf("-0.9904"))


def modal_hea_exact(acc, dt, g, omega, xi):
    """HEA (g) at the samples of the one-mode beam u'' + 2 xi w u' + w^2 u = -(4/pi) a g
    under the piecewise-linear record acc (g), from rest, in closed form per step."""
    wd = omega * mp.sqrt(1 - xi * xi)
    c = -4 / mp.pi * g
    u = v = mpf(0)
    hea = []
    for i, a0 in enumerate(acc):
        f0 = c * a0
        hea.append(a0 + 2 / mp.pi * (f0 - 2 * xi * omega * v - omega**2 * u) / g)
        if i + 1 == len(acc):
            break
        s = (c * acc[i + 1] - f0) / dt                 # load slope (m/s^3)
        big_a = u - (f0 / omega**2 - 2 * xi * s / omega**3)
        big_b = (v - s / omega**2 + xi * omega * big_a) / wd
        e, co, si = mp.exp(-xi * omega * dt), mp.cos(wd * dt), mp.sin(wd * dt)
        u = e * (big_a * co + big_b * si) + (f0 + s * dt) / omega**2 - 2 * xi * s / omega**3
        v = e * ((-xi * omega * big_a + wd * big_b) * co
                 + (-xi * omega * big_b - wd * big_a) * si) + s / omega**2
    return hea


def signed_peak(values):
    """The value of largest magnitude (the positive one on a tie)."""
    top = max(values)
    low = min(values)
    return top if top >= -low else low


def driver_doubles(path, fmt, units, dt, target, scale, polarity, slammer_rounding):
    """The scaled record (g) in the driver's double arithmetic: the decimals as doubles,
    the unit division, factor = target / PGA (or scale) times the polarity, each sample
    times the factor (SLAMMER's loops amplify a last-bit change of the input)."""
    acc, _ = read_record(path, fmt, units, dt, as_double=True)
    pga = max(abs(x) for x in acc)
    if target > 0:
        ref_pga = round(pga * 1000) / 1000 if slammer_rounding else pga
        factor = float(target) / ref_pga
    else:
        factor = float(scale)
    factor = polarity * factor
    return [x * factor for x in acc]


def flexible_case(acc, dt, g, ky, nb, ns, acc_double=None):
    """[max, max cm, final, final cm] x (normal, inverse) + the flexible columns
    (acc_double: the record as the driver holds it, for SLAMMER's rule)."""
    method = nb["method"].lower()
    rule = nb.get("rule", "exact").lower()
    height, vs, vs_base = (mpf(ns[k]) for k in ("height", "vs", "vs_base"))
    damping = mpf(ns.get("damping", "0.05"))
    soil = ns.get("soil", "linear").lower()
    table = None
    if "ky_disp" in nb:
        table = ([float(x) for x in _as_list(nb["ky_disp"])],
                 [float(x) for x in _as_list(nb["ky_table"])])
    out = []
    if rule == "slammer":
        import slammer_reference as sref
        run = sref.decoupled if method == "decoupled" else sref.coupled
        kw = dict(soil=soil, ref_strain_pct=float(ns.get("ref_strain_pct", 0.05)),
                  ky_table=table)
        for sign in (1, -1):
            r = run([sign * x for x in acc_double], float(dt), float(ky), float(height),
                    float(vs), float(vs_base), float(damping), **kw)
            d = mpf(r.disp_cm) / 100          # one way: max = final
            out += [d, 100 * d, d, 100 * d]
            if sign == 1:
                first = r
        return out + [mpf(first.kmax_g), mpf(first.vs_final_mps), mpf(first.damping_final),
                      4 * height / mpf(first.vs_final_mps), mpf(first.iterations), mpf(1)]
    if method != "decoupled" or soil != "linear" or table is not None:
        raise ValueError("exact references: method 'decoupled', soil 'linear', no table")
    xi = damping + radiation_damping(vs, vs_base)
    hea = modal_hea_exact(acc, dt, g, mp.pi * vs / (2 * height), xi)
    for sign in (1, -1):
        mx, fin = (x * g for x in newmark_exact([sign * h for h in hea], dt, mpf(ky), mp.inf,
                                                1, 1))
        out += [mx, 100 * mx, fin, 100 * fin]
    return out + [signed_peak(hea), vs, xi, 4 * height / vs, mpf(0), mpf(1)]


def newmark_rows(nml_path, nml):
    nr, nb = nml["records"], nml["newmark"]
    files = _as_list(nr["files"])
    n = len(files)
    fmts = [f.lower() for f in per_file(nr, "format", n, "auto")]
    units = [u.lower() for u in per_file(nr, "units", n, "auto")]
    dts = per_file(nr, "dt", n, 0.0)
    scales = per_file(nr, "scale", n, 1.0)
    targets = per_file(nr, "target_pga", n, 0.0)
    pols = per_file(nr, "polarity", n, 1)
    slammer_rounding = nr.get("pga_rounding", "exact").lower() == "slammer"
    flexible = nb.get("method", "").lower() in ("decoupled", "coupled")
    if "ky_disp" in nb:
        nb = dict(nb, ky=_as_list(nb["ky_table"])[0])
    blocks, mode = newmark_blocks(nb)
    method = nb.get("method", "exact").lower()
    g = mpf(nb.get("g", G_STANDARD))
    with_mu = "mu" in nb
    rows = []
    for i, file in enumerate(files):
        name = Path(file).stem
        try:
            acc, dt = read_record(Path(nml_path).parent / file, fmts[i], units[i], dts[i])
        except FileNotFoundError:
            acc = None
        factor = pga = mp.nan
        if acc is not None:
            pga_read = max(abs(x) for x in acc)
            if targets[i] > 0:
                ref_pga = mp.floor(pga_read * 1000 + mpf(1) / 2) / 1000 if slammer_rounding \
                    else pga_read
                factor = mpf(targets[i]) / ref_pga
            else:
                factor = mpf(scales[i])
            factor *= pols[i]
            acc = [x * factor for x in acc]
            pga = pga_read * abs(factor)
        for mu, ky, ky_up, kd, ku in blocks:
            row = [name, pga, factor] + ([mu] if with_mu else []) + [ky, ky_up]
            if acc is None:
                rows.append(row + [mp.nan] * (14 if flexible else 8) + [mpf(1)])
                continue
            if flexible:
                dbl = driver_doubles(Path(nml_path).parent / file, fmts[i], units[i], dts[i],
                                     targets[i], scales[i], pols[i], slammer_rounding)
                rows.append(row + flexible_case(acc, dt, g, ky, nb, nml["slope"], dbl)
                            + [mpf(0)])
                continue
            for sign in (1, -1):
                signed = [sign * x for x in acc]
                if method == "slammer":
                    if mode != "down":
                        raise ValueError("slammer references: mode 'down' only")
                    mx, fin = (x / 100 for x in newmark_slammer(signed, dt, ky, g))
                else:
                    mx, fin = (x * g for x in newmark_exact(signed, dt, ky, ky_up, kd, ku))
                row += [mx, 100 * mx, fin, 100 * fin]
            rows.append(row + [mpf(0)])
    header = newmark_header(with_mu)
    if flexible:
        header = header.replace("status (-)", ",".join(FLEX_COLUMNS + ["status (-)"]))
    return header, rows


def csv_cell(x):
    if isinstance(x, str):
        return '"' + x.replace('"', '""') + '"'
    return repr(float(x))


def make_newmark_ref(nml_path, nml):
    tables = [(".ref", newmark_rows)]
    if bool(nml["newmark"].get("intensity", False)):
        tables.append((".intensity.ref", intensity_rows))
    for suffix, table_rows in tables:
        with mp.workdps(40):
            header, rows = table_rows(nml_path, nml)
            rows = named(header, rows)
            lines = [header] + [",".join(csv_cell(x) for x in row) for row in rows]
        out = Path(nml_path).with_suffix(suffix)
        out.write_text("\n".join(lines) + "\n")
        print(f"wrote {out} ({len(lines) - 1} rows)")


def real_roots_in(coeffs, lo, hi):
    """Real roots in [lo, hi] of the polynomial (highest power first; leading zeros
    dropped)."""
    while coeffs and coeffs[0] == 0:
        coeffs = coeffs[1:]
    if len(coeffs) < 2:
        return []
    roots = mp.polyroots(coeffs, maxsteps=200, extraprec=200) if len(coeffs) > 2 \
        else [-coeffs[1] / coeffs[0]]
    out = []
    for r in roots:
        r = mp.mpc(r)
        if abs(r.imag) <= mpf(10) ** (-mp.dps + 8) * (1 + abs(r.real)) and lo <= r.real <= hi:
            out.append(r.real)
    return out


def record_measures(acc, dt, g):
    """PGA (g), PGV (m/s), PGD (m), Arias (m/s), CAV (m/s), D5-75, D5-95 (s), Tm (s) of
    the record acc (g, linear between samples from rest)."""
    n = len(acc)
    pga = max(abs(x) for x in acc)
    # velocity and displacement, with their stationary points inside the steps
    v = d = mpf(0)
    pgv = pgd = mpf(0)
    for a0, a1 in zip(acc[:-1], acc[1:]):
        s = (a1 - a0) / dt
        vel = lambda t: v + g * (a0 * t + s * t * t / 2)                      # noqa: E731
        dis = lambda t: d + v * t + g * (a0 * t * t / 2 + s * t ** 3 / 6)     # noqa: E731
        for t in real_roots_in([s, a0], 0, dt):
            pgv = max(pgv, abs(vel(t)))
        for t in real_roots_in([g * s / 2, g * a0, v], 0, dt):
            pgd = max(pgd, abs(dis(t)))
        v, d = vel(dt), dis(dt)
        pgv, pgd = max(pgv, abs(v)), max(pgd, abs(d))
    # Arias and CAV by quadrature step by step; the cumulative curve at the samples
    cum = [mpf(0)]
    cav = mpf(0)
    for a0, a1 in zip(acc[:-1], acc[1:]):
        f = lambda t: (a0 + (a1 - a0) * t / dt)                                # noqa: E731
        cum.append(cum[-1] + mp.quad(lambda t: f(t) ** 2, [0, dt]))
        if a0 * a1 < 0:
            t0 = dt * a0 / (a0 - a1)
            cav += mp.quad(lambda t: abs(f(t)), [0, t0, dt])
        else:
            cav += mp.quad(lambda t: abs(f(t)), [0, dt])
    arias = mp.pi / (2 * g) * g * g * cum[-1]
    cav *= g

    def husid(p):
        target = p * cum[-1]
        k = next(i for i in range(n - 1) if cum[i + 1] >= target)
        a0, s = acc[k], (acc[k + 1] - acc[k]) / dt
        delta = target - cum[k]
        # int_0^t (a0 + s u)^2 du = a0^2 t + a0 s t^2 + s^2 t^3 / 3 = delta
        roots = real_roots_in([s * s / 3, a0 * s, a0 * a0, -delta], 0, dt)
        return k * dt + min(roots)

    t5, t75, t95 = husid(mpf("0.05")), husid(mpf("0.75")), husid(mpf("0.95"))
    # Tm: DFT summed directly at the frequencies of the band
    npad = 1
    while npad < max(n, int(mp.ceil(1 / (mpf("0.05") * dt)))):
        npad *= 2
    s0 = s1 = mpf(0)
    for k in range(1, npad // 2 + 1):
        f = k / (npad * dt)
        if f > 20:
            break
        if f < mpf("0.25"):
            continue
        x = mp.fsum(a * mp.expjpi(-mpf(2 * ((j * k) % npad)) / npad)
                    for j, a in enumerate(acc))
        c2 = abs(x) ** 2
        s0 += c2
        s1 += c2 / f
    return [pga, pgv, pgd, arias, cav, t75 - t5, t95 - t5, s1 / s0]


def intensity_rows(nml_path, nml):
    nb = nml["newmark"]
    g = mpf(nb.get("g", G_STANDARD))
    periods = [float(x) for x in _as_list(nb.get("sa_periods", []))]
    header = ("record (-),pga (g),pgv (m/s),pgd (m),arias (m/s),cav (m/s),d5_75 (s),"
              "d5_95 (s),tm (s),"
              + "".join(f"sa_T={repr(t)} (g)," for t in periods) + "status (-)")
    rows = []
    for name, acc, dt, pga in sdof_records(nml_path, nml["records"]):
        if acc is None:
            rows.append([name] + [mp.nan] * (8 + len(periods)) + [mpf(1)])
            continue
        row = [name] + record_measures(acc, dt, g)
        for period in periods:
            if period == 0:
                row.append(pga)
                continue
            (sd, _, _), _ = sdof_record_response(acc, dt, period, mpf("0.05"), g, True)
            w = 2 * mp.pi / mpf(period)
            row.append(w * w * sd / g)
        rows.append(row + [mpf(0)])
    return header, rows


# ---------------------------------------------------------------------------
# Analyses 'sdof', 'sdof_beta', 'sdof_shock': the linear oscillator, in mpmath
# ---------------------------------------------------------------------------

def axis_grid(group, lname, stem, count_default=None):
    """The driver's axis in double precision: the list `lname`, or `<stem>_range` with
    `<stem>_count` (count_default when absent) and spacing (linear: a + (b - a) (i/(n-1));
    log: exp(log a + (log b - log a) (i/(n-1)))), both ends exact; None if neither is
    given."""
    if lname in group:
        return [float(x) for x in _as_list(group[lname])]
    if f"{stem}_range" not in group:
        return None
    a, b = (float(x) for x in group[f"{stem}_range"])
    n = int(group.get(f"{stem}_count", count_default))
    if group.get("spacing", "linear").lower() == "log":
        values = [math.exp(math.log(a) + (math.log(b) - math.log(a)) * (i / (n - 1)))
                  for i in range(n)]
    else:
        values = [a + (b - a) * (i / (n - 1)) for i in range(n)]
    values[0], values[-1] = a, b
    return values


class Piece:
    """The oscillator z'' + 2 zeta omega z' + omega^2 z = -(a0 + s tau) (m, s) on one
    piece 0 <= tau <= h, from z(0) = z0, z'(0) = v0, written out by hand: the particular
    solution A + B tau (omega^2 B = -s, omega^2 A = -a0 - 2 zeta omega B) plus the damped
    free vibration e^(-zeta omega tau) (C1 cos omega_d tau + C2 sin omega_d tau)."""

    def __init__(self, omega, zeta, z0, v0, a0, s):
        self.w, self.zeta, self.a0, self.s = omega, zeta, a0, s
        self.wd = omega * mp.sqrt(1 - zeta * zeta)
        self.sig = zeta * omega
        self.B = -s / omega**2
        self.A = (-a0 - 2 * zeta * omega * self.B) / omega**2
        c1 = z0 - self.A
        c2 = (v0 - self.B + self.sig * c1) / self.wd
        d1 = -self.sig * c1 + self.wd * c2          # z' = B + e (d1 cos + d2 sin)
        d2 = -self.sig * c2 - self.wd * c1
        e1 = -self.sig * d1 + self.wd * d2          # z'' = e (e1 cos + e2 sin)
        e2 = -self.sig * d2 - self.wd * d1
        self.c, self.d, self.e = (c1, c2), (d1, d2), (e1, e2)

    def _osc(self, k, tau):
        x = self.wd * tau
        return mp.exp(-self.sig * tau) * (k[0] * mp.cos(x) + k[1] * mp.sin(x))

    def z(self, tau):
        return self.A + self.B * tau + self._osc(self.c, tau)

    def v(self, tau):
        return self.B + self._osc(self.d, tau)

    def zdd(self, tau):
        return self._osc(self.e, tau)

    def a_abs(self, tau):
        return -(2 * self.zeta * self.w * self.v(tau) + self.w**2 * self.z(tau))

    def da_abs(self, tau):
        return -(2 * self.zeta * self.w * self.zdd(tau) + self.w**2 * self.v(tau))

    def peaks(self, h, k):
        """Largest |z|, |z'|, |a_abs| on [0, h]: the ends and every zero of the
        derivative, bracketed on a grid of k intervals and refined by bisection."""
        out = []
        for f, df in ((self.z, self.v), (self.v, self.zdd), (self.a_abs, self.da_abs)):
            best = max(abs(f(mpf(0))), abs(f(h)))
            grid = [h * i / k for i in range(k + 1)]
            slopes = [df(x) for x in grid]
            for x0, x1, d0, d1 in zip(grid[:-1], grid[1:], slopes[:-1], slopes[1:]):
                if d0 == 0:
                    best = max(best, abs(f(x0)))
                elif d0 * d1 < 0:
                    lo, hi, dlo = x0, x1, d0
                    for _ in range(120):          # bisection to 40 digits
                        mid = (lo + hi) / 2
                        dm = df(mid)
                        if dm * dlo > 0:
                            lo, dlo = mid, dm
                        else:
                            hi = mid
                    best = max(best, abs(f((lo + hi) / 2)))
            out.append(best)
        return out


def sdof_record_response(acc, dt, period, zeta, g, exact):
    """(peaks (max |z| m, |z'| m/s, |a_abs| g), samples [(z, z', a_abs g)]) of the oscillator
    from rest on the record acc (g, linear between samples); exact: maxima between the
    samples too (12 bisection brackets per step), else at the samples only."""
    if period == 0:
        pga = max(abs(x) for x in acc)
        return (mpf(0), mpf(0), pga), [(mpf(0), mpf(0), x) for x in acc]
    w = 2 * mp.pi / mpf(period)
    z = v = mpf(0)
    hist = [(z, v, mpf(0))]
    top = [mpf(0)] * 3
    for a0, a1 in zip(acc[:-1], acc[1:]):
        piece = Piece(w, zeta, z, v, a0 * g, (a1 - a0) * g / dt)
        if exact:
            pz, pv, pa = piece.peaks(dt, 12)
            top = [max(top[0], pz), max(top[1], pv), max(top[2], pa / g)]
        z, v = piece.z(dt), piece.v(dt)
        hist.append((z, v, -(2 * zeta * w * v + w * w * z) / g))
    for z, v, a in hist:
        top = [max(top[0], abs(z)), max(top[1], abs(v)), max(top[2], abs(a))]
    return top, hist


def sdof_records(nml_path, nr):
    """[(name, acc (g) scaled or None, dt, pga after scaling)] of &records."""
    files = _as_list(nr["files"])
    n = len(files)
    fmts = [f.lower() for f in per_file(nr, "format", n, "auto")]
    units = [u.lower() for u in per_file(nr, "units", n, "auto")]
    dts = per_file(nr, "dt", n, 0.0)
    scales = per_file(nr, "scale", n, 1.0)
    targets = per_file(nr, "target_pga", n, 0.0)
    pols = per_file(nr, "polarity", n, 1)
    slammer_rounding = nr.get("pga_rounding", "exact").lower() == "slammer"
    out = []
    for i, file in enumerate(files):
        try:
            acc, dt = read_record(Path(nml_path).parent / file, fmts[i], units[i], dts[i])
        except FileNotFoundError:
            out.append((Path(file).stem, None, None, mp.nan))
            continue
        pga_read = max(abs(x) for x in acc)
        if targets[i] > 0:
            ref_pga = mp.floor(pga_read * 1000 + mpf(1) / 2) / 1000 if slammer_rounding \
                else pga_read
            factor = mpf(targets[i]) / ref_pga
        else:
            factor = mpf(scales[i])
        factor *= pols[i]
        out.append((Path(file).stem, [x * factor for x in acc], dt, pga_read * abs(factor)))
    return out


def sdof_rows(nml_path, nml):
    """The spectra table, or the history table when &sdof has no periods."""
    ns, nh = nml.get("sdof", {}), nml.get("sdof_history")
    g = mpf(ns.get("g", G_STANDARD))
    dampings = [mpf(z) for z in _as_list(ns.get("damping", 0.05))]
    periods = axis_grid(ns, "periods", "period")
    exact = ns.get("peaks", "exact").lower() == "exact"
    shape = bool(ns.get("shape", False))
    recs = sdof_records(nml_path, nml["records"])
    rows = []
    if periods is None:
        header = ("record (-),damping (-),T (s),t (s),a_g (g),z (m),z' (m/s),a_abs (g),"
                  "status (-)")
        hp = [float(x) for x in _as_list(nh["periods"])]
        hz = [mpf(z) for z in _as_list(nh["damping"])] if "damping" in nh else dampings
        for name, acc, dt, _ in recs:
            for zeta in hz:
                for period in hp:
                    if acc is None:
                        rows.append([name, zeta, period] + [mp.nan] * 5 + [mpf(1)])
                        continue
                    _, hist = sdof_record_response(acc, dt, period, zeta, g, False)
                    for i, (z, v, a) in enumerate(hist):
                        rows.append([name, zeta, period, float(dt) * i, acc[i], z, v, a,
                                     mpf(0)])
        return header, rows
    header = ("record (-),damping (-),T (s),SD (m),SV (m/s),SA (g),PSV (m/s),PSA (g),"
              + ("PSA/PGA (-)," if shape else "") + "status (-)")
    for name, acc, dt, pga in recs:
        for zeta in dampings:
            for period in periods:
                if acc is None:
                    rows.append([name, zeta, period] + [mp.nan] * (6 if shape else 5)
                                + [mpf(1)])
                    continue
                (sd, sv, sa), _ = sdof_record_response(acc, dt, period, zeta, g, exact)
                if period == 0:
                    psv, psa = mpf(0), pga
                else:
                    w = 2 * mp.pi / mpf(period)
                    psv, psa = w * sd, w * w * sd / g
                rows.append([name, zeta, period, sd, sv, sa, psv, psa]
                            + ([psa / pga] if shape else []) + [mpf(0)])
    return header, rows


def sdof_beta_rows(nml):
    """beta (Eq. 2.17, 2.20 with the square root, or viscous) and 2|beta|."""
    nb = nml["sdof_beta"]
    ratios = axis_grid(nb, "ratios", "ratio")
    gammas = [mpf(x) for x in _as_list(nb.get("gamma", 0.1))]
    viscous = nb.get("model", "hysteretic").lower() == "viscous"
    rows = []
    for gamma in gammas:
        for r in ratios:
            d = 1 - mpf(r)**2
            if gamma == 0:
                beta = 1 / d if d != 0 else mp.nan
            else:
                beta = 1 / mp.sqrt(d * d + (gamma * r)**2 if viscous else d * d + gamma**2)
            rows.append([gamma, r, beta, 2 * abs(beta) if d != 0 or gamma != 0 else mp.inf])
    return "gamma (-),theta/omega (-),beta (-),beta_cos (-)", rows


def shock_peaks(pieces, period, zeta):
    """Largest |z|, |z'|, |a_abs| (m, m/s, m/s2) over t >= 0 of the oscillator from rest
    under the piecewise-linear ground acceleration [(a0, a1, length)], then free
    vibration (its extrema decay, so one and a half periods after the pulse hold the
    largest)."""
    w = 2 * mp.pi / mpf(period)
    z = v = mpf(0)
    top = [mpf(0)] * 3
    for a0, a1, h in pieces + [(mpf(0), mpf(0), 3 * mpf(period) / 2)]:
        piece = Piece(w, zeta, z, v, a0, (a1 - a0) / h)
        k = 64 * (1 + int(h / mpf(period)))
        top = [max(p, q) for p, q in zip(top, piece.peaks(h, k))]
        z, v = piece.z(h), piece.v(h)
    return top


def sdof_shock_rows(nml):
    """Rectangular and triangular pulses (piecewise linear): the exact pieces above."""
    pg, nk = nml["pulse"], nml["sdof_shock"]
    kind = pg.get("kind", "exponential").lower()
    g = float(pg.get("g", 9.80665))
    amp = float(pg.get("amp", 1.0))
    if pg.get("amp_unit", "m/s2").lower() == "g":
        amp = amp * g                                # as the driver, in double
    td = float(pg.get("duration", 1.0))
    if kind in ("rectangular", "rect"):
        pieces = [(mpf(amp), mpf(amp), mpf(td))]
    elif kind in ("triangular", "triangle"):
        tp = float(pg.get("peak_frac", 0.5)) * td
        pieces = [(mpf(0), mpf(amp), mpf(tp)), (mpf(amp), mpf(0), mpf(td) - mpf(tp))]
    else:
        raise ValueError("sdof_shock references: rectangular or triangular pulses only")
    ratios = axis_grid(nk, "ratios", "ratio")
    if ratios is not None:
        periods = [td / r for r in ratios]           # double, as the driver
    else:
        periods = axis_grid(nk, "periods", "period")
        ratios = [td / t if t > 0 else math.inf for t in periods]
    dampings = [mpf(z) for z in _as_list(nk.get("damping", 0.05))]
    gm = mpf(g)
    pga = abs(mpf(amp)) / gm
    rows = []
    for zeta in dampings:
        for r, period in zip(ratios, periods):
            if period == 0:
                sd, sv, sa, psv, psa = mpf(0), mpf(0), pga, mpf(0), pga
            else:
                sd, sv, sa = shock_peaks(pieces, period, zeta)
                sa = sa / gm
                w = 2 * mp.pi / mpf(period)
                psv, psa = w * sd, w * w * sd / gm
            rows.append([zeta, r, period, sd, sv, sa, psv, psa, sa / pga, psa / pga])
    return ("damping (-),t_d/T (-),T (s),SD (m),SV (m/s),SA (g),PSV (m/s),PSA (g),"
            "SA/PGA (-),PSA/PGA (-)"), rows


def make_sdof_ref(nml_path, nml, analysis):
    with mp.workdps(40):
        if analysis == "sdof":
            header, rows = sdof_rows(nml_path, nml)
        elif analysis == "sdof_beta":
            header, rows = sdof_beta_rows(nml)
        else:
            header, rows = sdof_shock_rows(nml)
        rows = named(header, rows)
        lines = [header] + [",".join(csv_cell(x) for x in row) for row in rows]
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out} ({len(lines) - 1} rows)")



# ---------------------------------------------------------------------------
# Analysis 'walls': every row written out in mpmath from the formulas (never by
# running the driver): Coulomb / Mononobe-Okabe (EN 1998-5 E.1, E.2, the water cases
# of Annex E), Seed-Whitman, Wood, the EN 1998-5 rigid wall; Veletsos-Younan (doc/walls.md
# 2.32, 2.34, 2.35 with 1/n^4) summed with the static sums subtracted (lambda(3), beta(4),
# and the static pressure through dilogarithms); the one-term solution in closed form
# (Table 2.1 sine; 2.68-2.69 power law; 2.96 rotational spring; 2.105 wall pair).
# EN 1998-1 Table 3.2/3.3 soil factors and EN 1998-5 Table 7.1 r are transcribed here.

WALLS_HEADER = "method (-),thrust (kN/m),z (m),z/H (-),moment (kNm/m)"
WALLS_PRESSURE_HEADER = ("depth (m),static (kPa),mo_dyn (kPa),ec8_rigid (kPa),vy (kPa),"
                         "one_term (kPa)")
WALL_LABELS = ("static active (Coulomb)", "Mononobe-Okabe total, EN 1998-5 E.1",
               "Mononobe-Okabe dynamic increment", "Seed-Whitman increment (3/4 kh)",
               "Wood (1973) rigid wall", "EN 1998-5 rigid wall", "Veletsos-Younan rigid wall",
               "one-term solution")
EC8_S = {1: dict(a=1.0, b=1.2, c=1.15, d=1.35, e=1.4), 2: dict(a=1.0, b=1.35, c=1.5, d=1.8, e=1.6)}
EC8_R = {"gravity_300": 2.0, "gravity_200": 1.5, "restrained": 1.0}
G_STD = mpf("9.80665")


def mo_active_k(phi, delta, psi, beta, theta):
    """EN 1998-5 E.2 (angles in radians)."""
    s = mp.sin
    root = mp.sqrt(s(phi + delta) * s(phi - beta - theta) / (s(psi - theta - delta) * s(psi + beta)))
    return s(psi + phi - theta) ** 2 / (mp.cos(theta) * s(psi) ** 2 * s(psi - theta - delta)
                                       * (1 + root) ** 2)


def walls_case(nml):
    w, b, s = nml["wall"], nml["backfill"], nml["seismic"]
    c = dict(H=mpf(w["height"]), psi=mp.radians(w.get("psi_deg", 90)),
             wdelta=mp.radians(w.get("wall_friction_deg", 0)), gamma=mpf(b["gamma"]),
             phi=mp.radians(b["phi_deg"]), beta=mp.radians(b.get("beta_deg", 0)),
             gphi=mpf(b.get("gamma_phi", 1)), nu=mpf(b.get("nu", 0.3)),
             water=b.get("water", "dry").lower(), gw=mpf(b.get("gamma_w", 9.81)),
             gd=mpf(b.get("gamma_d", 0)), n=mpf(b.get("stiffness_exponent", 0)),
             shape=b.get("shape", "").lower(), npoints=int(s.get("npoints", 21)))
    c["delta"] = 2 * mpf(b.get("damping_ratio", 0.05)) if "loss_factor" not in b \
        else mpf(b["loss_factor"])
    if not c["shape"]:
        c["shape"] = "sine" if c["n"] == 0 else "power"
    vs = mpf(b["vs"]) if "vs" in b else (mp.sqrt(mpf(b["g_modulus"]) * G_STD / c["gamma"])
                                         if "g_modulus" in b else None)
    f = mpf(b.get("frequency", 0))
    c["ratio"] = 2 * mp.pi * f / (mp.pi * vs / (2 * c["H"])) if f > 0 else mpf(0)
    c["d_theta"] = mpf(w.get("d_theta", 0))
    if "k_rotation" in w:
        g_base = c["gamma"] / G_STD * vs ** 2 if "vs" in b else mpf(b["g_modulus"])
        c["d_theta"] = c["H"] ** 2 * g_base / mpf(w["k_rotation"])
    c["l_over_h"] = mpf(w["spacing"]) / c["H"] if "spacing" in w else mp.inf
    if s["code"].lower() == "ec8":
        typ = int(s.get("spectrum_type", 1))
        alpha = mpf(s.get("importance", 1)) * mpf(s["agr"])
        S = mpf(s["soil_factor"]) if "soil_factor" in s else mpf(EC8_S[typ][s["ground"].lower()])
        r = mpf(s["r"]) if "r" in s else mpf(EC8_R[s.get("wall_type", "restrained").lower()])
        c["kh"] = alpha * S / r
        c["kv"] = c["kh"] * (mpf("0.5") if typ == 1 else mpf("0.33"))
        c["alpha_s"] = alpha * S
    else:
        c["kh"] = mpf(s["kh"])
        c["kv"] = abs(mpf(s.get("kv", 0)))
        c["alpha_s"] = mpf(s.get("alpha_s", s["kh"]))
    return c


def mo_thrust(c, kv):
    """EN 1998-5 thrust (active, signed kv): static, dynamic increment, water terms."""
    H, g, gw, kh = c["H"], c["gamma"], c["gw"], c["kh"]
    phi = mp.atan(mp.tan(c["phi"]) / c["gphi"])
    dl = mp.atan(mp.tan(c["wdelta"]) / c["gphi"])
    if c["water"] == "dry":
        gs, ratio, ews, ewd = g, mpf(1), mpf(0), mpf(0)
    elif c["water"] == "impervious":
        gs, ratio, ews, ewd = g - gw, g / (g - gw), gw * H ** 2 / 2, mpf(0)
    else:
        gs, ratio = g - gw, c["gd"] / (g - gw)
        ews, ewd = gw * H ** 2 / 2, mpf(7) / 12 * kh * gw * H ** 2
    theta = mp.atan(ratio * kh / (1 - kv))
    K = mo_active_k(phi, dl, c["psi"], c["beta"], theta)
    K0 = mo_active_k(phi, dl, c["psi"], c["beta"], mpf(0))
    e_st = gs * K0 * H ** 2 / 2
    e_d = gs * (1 - kv) * K * H ** 2 / 2
    total = e_d + ews + ewd
    mom = e_st * H / 3 + (e_d - e_st) * H / 2 + ews * H / 3 + ewd * H * mpf("0.4")
    return dict(e_st=e_st, e_dyn=e_d - e_st, total=total, z_total=mom / total, K0=K0, gs=gs)


def vy_sums(ratio, delta, y=None, terms=20000):
    """Veletsos-Younan sums with the static parts in closed form: (sum r_n/n^3,
    sum (-1)^k r_n/n^4) or, with y, sum r_n sin(n pi y/2)/n^2."""
    lam3 = mpf(7) / 8 * mp.zeta(3)
    beta4 = (mp.zeta(4, mpf(1) / 4) - mp.zeta(4, mpf(3) / 4)) / 256
    if y is not None:
        t = mp.pi * y / 2
        z = mp.expj(t)
        total = mp.im(mp.polylog(2, z) - mp.polylog(2, z ** 2) / 4)
    else:
        total_q, total_m = lam3, beta4
    for k in range(terms):
        n = 2 * k + 1
        if ratio == 0:
            break
        zn = (ratio / n) ** 2 / (1 + 1j * delta)
        arg = 1 - zn
        root = mp.sqrt(arg) if (mp.im(arg) > 0 or mp.re(arg) >= 0) else 1j * mp.sqrt(-mp.re(arg))
        rn1 = 1 / root - 1
        if y is not None:
            total += rn1 * mp.sin(n * t) / n ** 2
        else:
            total_q += rn1 / n ** 3
            total_m += (-1) ** k * rn1 / n ** 4
    if y is not None:
        return total
    if ratio != 0:     # leading tail: r_n - 1 ~ z_n/2, sum over odd n > 2 terms of 1/n^5
        n0 = 2 * terms + 1
        tail5 = (ratio ** 2 / (2 * (1 + 1j * delta))) * mp.zeta(5, mpf(n0) / 2) / 32
        total_q += tail5
    return total_q, total_m


def one_term_consts(shape, n):
    if shape == "sine":
        return dict(aoc2=mp.pi ** 2 / 4, lf=4 / mp.pi, mf=mpf(1), s0=2 / mp.pi, h=2 / mp.pi)
    if shape == "linear":
        return dict(aoc2=mpf(3), lf=mpf(3) / 2, mf=mpf(1), s0=mpf(1) / 2, h=mpf(2) / 3)
    if shape == "parabolic":
        n = mpf(0)
    aoc2 = mpf(3) / 2 * (5 - n) * (1 + n) / (3 - n)
    return dict(aoc2=aoc2, lf=aoc2 / (2 - n), mf=2 * aoc2 / (5 - 2 * n),
                s0=(2 - n) / (3 * (1 + n)), h=(5 + n) / (4 * (2 + n)))


def one_term_q(c):
    """|q| (rho Xg H^2), h/H and the complex factor p(y) = factor g(y) Phi(y)."""
    k = one_term_consts(c["shape"], c["n"])
    psi_e = mp.sqrt((2 - c["nu"]) / (1 - c["nu"]))
    psi_s = 2 / mp.sqrt((1 - c["nu"]) * (2 - c["nu"]))
    a0 = mp.pi / 2 * c["ratio"]
    s = mp.sqrt(k["aoc2"] - a0 ** 2 * k["mf"] / (1 + 1j * c["delta"]))
    factor = psi_s * k["lf"] / s
    if c["d_theta"] > 0:
        factor /= 1 + psi_s * s * k["s0"] * k["h"] * (1 + 1j * c["delta"]) * c["d_theta"]
    if c["l_over_h"] != mp.inf:
        factor *= mp.tanh(s * c["l_over_h"] / psi_e / 2)
    return abs(factor * k["s0"]), k["h"], factor


def one_term_shape_value(c, y):
    if c["shape"] == "sine":
        return mp.sin(mp.pi * y / 2)
    if c["shape"] == "linear":
        return y
    n = mpf(0) if c["shape"] == "parabolic" else c["n"]
    return (1 - y) ** n * (1 - (1 - y) ** (2 - n))


def walls_rows(nml):
    c = walls_case(nml)
    H, g = c["H"], c["gamma"]
    mo = mo_thrust(c, c["kv"])
    if c["kv"] != 0:
        other = mo_thrust(c, -c["kv"])
        if other["total"] > mo["total"]:
            mo = other
    psi_s = 2 / mp.sqrt((1 - c["nu"]) * (2 - c["nu"]))
    scale = g * c["alpha_s"] * H ** 2
    sq, sm = vy_sums(c["ratio"], c["delta"])
    q_vy = 16 * psi_s / mp.pi ** 3 * sq
    m_vy = 32 * psi_s / mp.pi ** 4 * sm
    q_ot, h_ot, factor = one_term_q(c)
    rows = [(mo["e_st"], H / 3), (mo["total"], mo["z_total"]), (mo["e_dyn"], H / 2),
            (mpf(3) / 8 * c["kh"] * g * H ** 2, mpf("0.6") * H),
            (c["alpha_s"] * g * H ** 2, mpf("0.6") * H), (c["alpha_s"] * g * H ** 2, H / 2),
            (abs(q_vy) * scale, abs(m_vy) / abs(q_vy) * H), (q_ot * scale, h_ot * H)]
    table = [(WALL_LABELS[i], p, z, z / H, p * z) for i, (p, z) in enumerate(rows)]
    depths = [H * i / (c["npoints"] - 1) for i in range(c["npoints"])]
    pres = []
    for d in depths:
        y = 1 - d / H
        p_vy = 8 * psi_s / mp.pi ** 2 * vy_sums(c["ratio"], c["delta"], y=y)
        pres.append((d, 2 * mo["e_st"] / H ** 2 * d, mo["e_dyn"] / H, c["alpha_s"] * g * H,
                     abs(p_vy) * g * c["alpha_s"] * H,
                     abs(factor * one_term_shape_value(c, y)) * g * c["alpha_s"] * H))
    return table, pres


def make_walls_ref(nml_path, nml):
    with mp.workdps(30):
        table, pres = walls_rows(nml)
        main = [WALLS_HEADER] + [",".join(csv_cell(x) for x in row) for row in table]
        prof = [WALLS_PRESSURE_HEADER] + [",".join(csv_cell(x) for x in row) for row in pres]
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(main) + "\n")
    out2 = Path(nml_path).with_suffix(".pressure.ref")
    out2.write_text("\n".join(prof) + "\n")
    print(f"wrote {out} ({len(main) - 1} rows) and {out2} ({len(prof) - 1} rows)")


# ---------------------------------------------------------------------------
# Analysis 'winkler': rigid bodies on tensionless Winkler springs, clay capacities
# ---------------------------------------------------------------------------

WINKLER_PUSHOVER_HEADER = ("theta (rad),b (m),pole (m),area (m2),settlement (m),k (N/m3),"
                           "m_found (N m),m_imposed (N m),force (N),force_ratio (-),"
                           "force_rigid (N)")
WINKLER_MASTER_HEADER = "theta_ratio (-),k_ratio (-),m_ratio (-),b_ratio (-),a_ratio (-)"
WINKLER_INELASTIC_HEADER = ("theta (rad),k_r (N m/rad),m_found (N m),m_imposed (N m),"
                            "force (N),theta_ratio (-),g_corr (-),force_ratio (-)")
WINKLER_CAPACITY_HEADER = ("su (Pa),r (m),weight (N),nc (-),n_ult (N),sf (-),chi (-),"
                           "m_ult_tc (N m),m_ult_width (N m),m_tc_norm (-),m_width_norm (-)")


def circle_segment(r, b):
    """The contact segment of a circle of radius r, width b (0 < b <= 2 r) from an edge,
    c = r - b its chord's distance from the centre (across the centre: c < 0): area A0,
    first moment J1 and second moment J2 about the centre line, and Phi = J1 - c A0
    (pressure integral per k sin(theta) cos(theta)), from the segment's closed forms
    (widths 2 sqrt(r^2 - s^2))."""
    c = r - b
    s = mp.sqrt(max(2 * r * b - b**2, mpf(0)))
    a0 = r**2 * mp.acos(c / r) - c * s
    j1 = mpf(2) / 3 * s**3
    j2 = r**4 / 4 * (mp.pi / 2 - mp.asin(c / r)) - c / 4 * (2 * c**2 - r**2) * s
    return a0, j1, j2, j1 - c * a0


def bisect_up(f, target, lo, hi):
    """The x in (lo, hi) where the increasing f(x) reaches target: 400 halvings (far below
    the 40 digits of the references)."""
    for _ in range(400):
        mid = (lo + hi) / 2
        if f(mid) > target:
            hi = mid
        else:
            lo = mid
    return (lo + hi) / 2


def gazetas_k_over_i(width, length, axis=None):
    """K_R/I of a rectangle width (rocking direction) x length on a halfspace, per
    G/(1 - nu) (Gazetas 1991, half-sides B <= L): about the long axis I^0.75 (L/B)^0.25
    (2.4 + 0.5 B/L), about the short axis 3 I^0.75 (L/B)^0.15, I = length width^3/12 the
    second moment about the rotation axis; the axis the sides select (long when width <=
    length), or the one given ('long', 'short': the reading of a circle's varying k)."""
    i_ax = length * width**3 / 12
    big_b, big_l = min(width, length) / 2, max(width, length) / 2
    if axis is None:
        axis = "long" if width <= length else "short"
    if axis == "long":
        k_r = i_ax**mpf("0.75") * (big_l / big_b)**mpf("0.25") * (mpf("2.4") + big_b / big_l / 2)
    else:
        k_r = 3 * i_ax**mpf("0.75") * (big_l / big_b)**mpf("0.15")
    return k_r / i_ax


def winkler_block_state(b, alpha, k, w, th, varying):
    """Block (half-width b, half-length alpha) at tilt th: (b', a, area, settlement,
    k(b'), foundation moment), or None past the end of the branch. Full contact while
    sin(2 th) <= W/(2 alpha b^2 k); then theta = 1/2 asin(2 W/(alpha b'^2 k(b'))) solved
    for the contact width b' (constant k: b'^2 = 2 W/(alpha k sin 2th)); with varying k,
    k(b') = k (K_R/I)(b' x 2 alpha)/(K_R/I)(2 b x 2 alpha)."""
    s2 = mp.sin(2 * th)

    def k_of(bp):
        if not varying:
            return k
        return k * gazetas_k_over_i(bp, 2 * alpha) / gazetas_k_over_i(2 * b, 2 * alpha)

    if s2 <= w / (2 * alpha * b**2 * k):
        bp, c = 2 * b, -b
    else:
        if th >= mp.pi / 4:
            return None
        if varying:
            f = lambda bp: alpha * bp**2 * k_of(bp) * s2 - 2 * w
            if f(2 * b) < 0:
                raise ValueError("no root")
            bp = bisect_up(f, 0, mpf(0), 2 * b)
        else:
            bp = mp.sqrt(2 * w / (alpha * k * s2))
        c = b - bp
    kb = k_of(bp)
    cos2 = mp.cos(th)**2
    if bp == 2 * b:
        moment = mpf(4) / 3 * alpha * b**3 * kb * cos2 * mp.sin(th)
        return (bp, mpf(0), 4 * alpha * b * mp.cos(th), w / (kb * 4 * alpha * b * mp.cos(th)),
                kb, moment)
    moment = 2 * alpha * kb * mp.sin(th) * cos2 * ((b**3 - c**3) / 3 - c * (b**2 - c**2) / 2)
    return (bp, b - bp / 2, 2 * alpha * bp * mp.cos(th), -c * mp.sin(th), kb, moment)


def winkler_circle_state(r, k, w, th, reading=None):
    """Circle of radius r at tilt th: (b, a, area, settlement, k(b), moment), or None past
    the end of the branch (theta = pi/4). Full contact while sin(2 th) <= 2 W/(k pi r^3):
    settlement W/(k pi r^2 cos th), M = pi k r^4 cos^2 sin/4; then the contact width b
    solves k(b) Phi(b) = 2 W/sin 2th (increasing in b; bisection), the pole is the
    segment's centroid a = J1/A0, the area A0 cos th, the centre rises by (r - b) sin th,
    M = k(b) sin cos^2 (J2 - c J1). Constant k (reading None), or varying: k(b) = k
    (K_R/I)(b x 2 sqrt(r^2 - a^2))/(K_R/I)(2r x 2r), both by the formula of `reading`."""
    def k_of(b):
        if reading is None or b >= 2 * r:
            return k
        a0, j1, _, _ = circle_segment(r, b)
        a = j1 / a0
        chord = 2 * mp.sqrt(r**2 - a**2)
        return k * gazetas_k_over_i(b, chord, reading) / gazetas_k_over_i(2 * r, 2 * r, reading)

    s2 = mp.sin(2 * th)
    cs = mp.cos(th)
    if s2 * k * mp.pi * r**3 <= 2 * w:
        return (2 * r, mpf(0), mp.pi * r**2 * cs, w / (k * mp.pi * r**2 * cs), k,
                mp.pi * k * r**4 * cs**2 * mp.sin(th) / 4)
    if th >= mp.pi / 4:
        return None
    b = bisect_up(lambda x: k_of(x) * circle_segment(r, x)[3], 2 * w / s2, mpf(0), 2 * r)
    a0, j1, j2, _ = circle_segment(r, b)
    c = r - b
    kb = k_of(b)
    return (b, j1 / a0, a0 * cs, -c * mp.sin(th), kb,
            kb * mp.sin(th) * cs**2 * (j2 - c * j1))


def winkler_theta_grid(wk):
    """The driver's theta grid of &winkler: a list, a range with a count (axis_grid), or
    0 .. theta_max in theta_count values (the last exactly theta_max); these references
    need one of them (the default top, the rigid theta_c, is a double of the library)."""
    th = axis_grid(wk, "theta", "theta", 101)
    if th is None:
        top, n = float(wk["theta_max"]), int(wk.get("theta_count", 101))
        th = [top * (i / (n - 1)) for i in range(n)]
        th[-1] = top
    return [mpf(t) for t in th]


def winkler_weight(wk):
    g = mpf(wk.get("g", 9.80665))
    return (mpf(wk["weight"]) if "weight" in wk else mpf(wk["mass"]) * g), g


def winkler_pushover_rows(wk):
    """The static pushover on constant- or varying-k Winkler springs, with F = (M - W h
    sin th)/(h cos th) and the rigid W tan(theta_c - th)."""
    w, _ = winkler_weight(wk)
    h = mpf(wk["h"])
    if "k" in wk:
        k = mpf(wk["k"])
    elif str(wk.get("footing", "circle")).lower() == "circle":
        # the halfspace K_R = 8 G r^3/(3 (1 - nu)) over I = pi r^4/4
        k = 32 * mpf(wk["g_mod"]) / (3 * mp.pi * (1 - mpf(wk["nu"])) * mpf(wk["r"]))
    else:
        raise ValueError("winkler references: a block needs k")
    varying = str(wk.get("k_method", "constant")).lower() == "varying"
    block = str(wk.get("footing", "circle")).lower() == "block"
    if block:
        b, alpha = mpf(wk["b"]), mpf(wk["alpha"])
        half = b
    else:
        r = mpf(wk["r"])
        half = r
        reading = str(wk.get("reading", "long")).lower() if varying else None
    tc = mp.atan(half / h)
    nan = mp.nan
    rows = []
    for th in winkler_theta_grid(wk):
        st = (winkler_block_state(b, alpha, k, w, th, varying) if block
              else winkler_circle_state(r, k, w, th, reading))
        rigid = w * mp.tan(tc - th)
        if st is None:
            rows.append([th] + [nan] * 9 + [rigid])
            continue
        bb, a, area, v, kb, m = st
        m_imp = m - w * h * mp.sin(th)
        force = m_imp / (h * mp.cos(th))
        rows.append([th, bb, a, area, v, kb, m, m_imp, force, force / w, rigid])
    return rows


def winkler_master_rows(wk):
    """The universal small-angle curve against x = theta/theta_up: full contact for
    x <= 1 (K/K_0 = 1, M/(W r) = x/4 for the circle, x/3 for the rectangle); beyond, the
    contact width b from x = pi r^3/Phi(b) (circle; K/K_0 = (J2 - c J1)/I, M/(W r) =
    (J2 - c J1)/(Phi r), a = J1/A0) or x = 4 r^2/b^2 (rectangle of half-width r; K/K_0 =
    2 [(r^3 - c^3)/3 - c (r^2 - c^2)/2]/((4/3) r^3 (half-length 1)), M/(W r) =
    2 [...]/(b^2 r), a = r - b/2)."""
    block = str(wk.get("footing", "circle")).lower() == "block"
    xs = axis_grid(wk, "theta_ratio", "theta_ratio", 101)
    if xs is None:
        n = int(wk.get("theta_ratio_count", 101))
        xs = [10.0 * (i / (n - 1)) for i in range(n)]
        xs[-1] = 10.0
    rows = []
    r = mpf(1)
    for x in (mpf(v) for v in xs):
        if x <= 1:
            rows.append([x, mpf(1), x / (3 if block else 4), mpf(1), mpf(0)])
            continue
        if block:
            b = 2 * r / mp.sqrt(x)
            c = r - b
            inner = (r**3 - c**3) / 3 - c * (r**2 - c**2) / 2
            rows.append([x, 2 * inner / (mpf(4) / 3 * r**3), 2 * inner / (b**2 * r),
                         b / (2 * r), (r - b / 2) / r])
            continue
        b = bisect_up(lambda v: circle_segment(r, v)[3], mp.pi * r**3 / x, mpf(0), 2 * r)
        a0, j1, j2, phi = circle_segment(r, b)
        c = r - b
        rows.append([x, (j2 - c * j1) / (mp.pi * r**4 / 4), (j2 - c * j1) / (phi * r),
                     b / (2 * r), j1 / (a0 * r)])
    return rows


def winkler_capacity_rows(wk):
    """N_ult = N_c S_u pi r^2 (N_c = pi + 3 by default), SF = N_ult/W, chi = 1/SF,
    M_ult = 0.8 A D S_u (Taiebat & Carter) and W D (1 - chi)/2 (effective width), and
    both over A D S_u (A = pi r^2, D = 2 r)."""
    w, _ = winkler_weight(wk)
    su, r = mpf(wk["su"]), mpf(wk["r"])
    nc = mpf(wk["nc"]) if "nc" in wk else mp.pi + 3
    n_ult = nc * su * mp.pi * r**2
    sf = n_ult / w
    chi = 1 / sf
    adsu = mp.pi * r**2 * 2 * r * su
    m_tc = mpf("0.8") * adsu
    m_ew = w * 2 * r * (1 - chi) / 2
    return [[su, r, w, nc, n_ult, sf, chi, m_tc, m_ew, m_tc / adsu, m_ew / adsu]]


def circle_master_k(x):
    """K_sec/K_0 of the constant-k circle's master curve at x = theta/theta_up (1 up to
    x = 1; beyond, (J2 - c J1)/I at the contact width b with Phi(b) = pi r^3/x, r = 1)."""
    if x <= 1:
        return mpf(1)
    b = bisect_up(lambda v: circle_segment(mpf(1), v)[3], mp.pi / x, mpf(0), mpf(2))
    _, j1, j2, _ = circle_segment(mpf(1), b)
    return (j2 - (1 - b) * j1) / (mp.pi / 4)


def winkler_inelastic_rows(wk):
    """The inelastic pushover with G = 1 (a_poly all 0): SF = N_c S_u pi r^2/W, chi = 1/SF,
    K_R0 = 8 G r^3/(3 (1 - nu)) k_el (k/k_el), k/k_el = 1 for chi < 0.1 else kr_c1 -
    kr_c2 chi; theta_up = asin(W r/(2 K_R0))/2; M_found = K_R0 Khat(sin 2th/sin 2th_up)
    sin th cos^2 th (the elastic Winkler curve of the same K_R0), K_R = M_found/th (K_R0
    at 0), M_imp = M_found - W h sin th, F = M_imp/(h cos th)."""
    if any(float(a) != 0 for a in _as_list(wk["a_poly"])):
        raise ValueError("winkler inelastic references: a_poly = 0 (G = 1) only")
    w, _ = winkler_weight(wk)
    r, h, su = mpf(wk["r"]), mpf(wk["h"]), mpf(wk["su"])
    g_mod, nu = mpf(wk["g_mod"]), mpf(wk["nu"])
    nc = mpf(wk["nc"]) if "nc" in wk else mp.pi + 3
    chi = w / (nc * su * mp.pi * r**2)
    ratio = mpf(1) if chi < mpf("0.1") else mpf(wk["kr_c1"]) - mpf(wk["kr_c2"]) * chi
    k_r0 = 8 * g_mod * r**3 / (3 * (1 - nu)) * mpf(wk.get("k_el", 1.0)) * ratio
    th_up = mp.asin(w * r / (2 * k_r0)) / 2
    rows = []
    for th in winkler_theta_grid(wk):
        m = k_r0 * circle_master_k(mp.sin(2 * th) / mp.sin(2 * th_up)) * mp.sin(th) \
            * mp.cos(th)**2
        m_imp = m - w * h * mp.sin(th)
        force = m_imp / (h * mp.cos(th))
        rows.append([th, m / th if th > 0 else k_r0, m, m_imp, force, th / th_up, mpf(1),
                     force / w])
    return rows


def make_winkler_ref(nml_path, nml):
    wk = nml["winkler"]
    what = str(wk.get("what", "pushover")).lower()
    with mp.workdps(40):
        if what == "pushover":
            header, rows = WINKLER_PUSHOVER_HEADER, winkler_pushover_rows(wk)
        elif what == "master":
            header, rows = WINKLER_MASTER_HEADER, winkler_master_rows(wk)
        elif what == "inelastic":
            header, rows = WINKLER_INELASTIC_HEADER, winkler_inelastic_rows(wk)
        elif what == "capacity":
            header, rows = WINKLER_CAPACITY_HEADER, winkler_capacity_rows(wk)
        else:
            raise ValueError(f"winkler references: no reference for what = {what!r}")
        lines = [header] + [",".join(csv_cell(x) for x in row) for row in rows]
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out} ({len(lines) - 1} rows)")


# ---------------------------------------------------------------------------
# Analysis 'spectra' (never by running the driver): the code spectra written out here
# in mpmath from EN 1998-1 3.2.2.2 (3.2)-(3.6) and 3.2.2.5 (3.13)-(3.16) with Tables 3.2
# and 3.3 (recommended values) and the zones of the Greek National Annex, and from
# EAK 2000 (K.1)-(K.6) as doc/eak2000.md gives them (secondary sources); and the
# record-suite check of EN 1998-1 3.2.3.1.2(4) (doc/record-suites.md (M.1), (M.2)) on
# the 5 % PSA of the records from the oscillator pieces of analysis 'sdof' above.
# ---------------------------------------------------------------------------

# EN 1998-1 Table 3.2 (type 1) and 3.3 (type 2): S, TB, TC, TD (s)
EC8_TABLE = {1: dict(a=("1.0", "0.15", "0.4", "2.0"), b=("1.2", "0.15", "0.5", "2.0"),
                     c=("1.15", "0.2", "0.6", "2.0"), d=("1.35", "0.2", "0.8", "2.0"),
                     e=("1.4", "0.15", "0.5", "2.0")),
             2: dict(a=("1.0", "0.05", "0.25", "1.2"), b=("1.35", "0.05", "0.25", "1.2"),
                     c=("1.5", "0.1", "0.25", "1.2"), d=("1.8", "0.1", "0.3", "1.2"),
                     e=("1.6", "0.05", "0.25", "1.2"))}
GR_ZONES = {"z1": "0.16", "z2": "0.24", "z3": "0.36"}
EAK_T = {"a": ("0.10", "0.40"), "b": ("0.15", "0.60"), "c": ("0.20", "0.80"),
         "d": ("0.20", "1.20")}
EAK_ZONES = {"2003": {"z1": "0.16", "z2": "0.24", "z3": "0.36"},
             "2000": {"i": "0.12", "ii": "0.16", "iii": "0.24", "iv": "0.36"}}
EAK_CLASSES = {"i": "0.85", "ii": "1.00", "iii": "1.15", "iv": "1.30"}


def dec(x):
    """A number of the input as the decimal it was written as."""
    return mpf(repr(float(x)) if isinstance(x, float) else str(x))


def ec8_params(c):
    """(ag, ground, xi percent, q, beta) of &ec8."""
    if "zone" in c:
        ag = dec(c.get("importance", 1.0)) * mpf(GR_ZONES[c["zone"].lower()])
    else:
        ag = dec(c["ag"])
    return (ag, c.get("ground", "A").lower(), 100 * dec(c.get("damping", 0.05)),
            dec(c.get("q", 1.5)), dec(c.get("beta", 0.2)))


def ec8_value(t, stype, c, elastic, xi=None):
    ag, ground, xi_in, q, beta = ec8_params(c)
    s, tb, tc, td = (mpf(x) for x in EC8_TABLE[stype][ground])
    t = mpf(t)
    if elastic:
        eta = max(mp.sqrt(10 / (5 + (xi_in if xi is None else xi))), mpf("0.55"))  # (3.6)
        top = ag * s * eta * mpf("2.5")
        if t <= tb:
            return ag * s * (1 + t / tb * (eta * mpf("2.5") - 1))                    # (3.2)
        return top if t <= tc else top * tc / t if t <= td else top * tc * td / t**2
    top = ag * s * mpf("2.5") / q
    if t <= tb:
        return ag * s * (mpf(2) / 3 + t / tb * (mpf("2.5") / q - mpf(2) / 3))          # (3.13)
    if t <= tc:
        return top
    return max(top * tc / t if t <= td else top * tc * td / t**2, beta * ag)


def eak_value(t, k, elastic, xi=None):
    """Phi_e or Phi_d of &eak (g)."""
    if "alpha" in k:
        a = dec(k["alpha"])
    else:
        zmap = str(k.get("zone_map", "2003"))
        a = mpf(EAK_ZONES[zmap][str(k.get("zone", "Z2" if zmap == "2003" else "II")).lower()])
    gi = mpf(EAK_CLASSES[k["importance_class"].lower()]) if "importance_class" in k \
        else dec(k.get("importance", 1.0))
    t1, t2 = (mpf(x) for x in EAK_T[k.get("ground", "B").lower()])
    xi = 100 * dec(k.get("damping", 0.05)) if xi is None else xi
    eta = max(mp.sqrt(7 / (2 + xi)), dec(k.get("eta_min", 0.0)))                      # (K.4)
    if elastic:                                                                          # (K.6)
        q, theta, floor = mpf(1), mpf(1), mpf(0)
        expo = dec(k["elastic_exponent"]) if "elastic_exponent" in k else mpf(2) / 3
    else:
        q, theta = dec(k.get("q", 1.0)), dec(k.get("theta", 1.0))
        floor, expo = dec(k.get("lower_bound", 0.0)), mpf(2) / 3
    aa = gi * a
    t = mpf(t)
    if t <= t1:
        v = aa * (1 + t / t1 * (eta * theta * mpf("2.5") / q - 1))                       # (K.1)
    elif t <= t2:
        v = aa * eta * theta * mpf("2.5") / q                                            # (K.2)
    else:
        v = aa * eta * theta * mpf("2.5") / q * (t2 / t)**expo                          # (K.3)
    return max(v, floor * aa)                                                            # (K.5)


def code_value(code, t, nml, elastic, xi=None):
    if code == "eak":
        return eak_value(t, nml["eak"], elastic, xi)
    return ec8_value(t, int(code[-1]), nml["ec8"], elastic, xi)


def spectra_rows(nml):
    sp = nml["spectra"]
    periods = axis_grid(sp, "periods", "period")
    names = [c.lower() for c in _as_list(sp.get("codes", ["EC8_1", "EC8_2", "EAK"]))]
    kinds = {"elastic": ("elastic",), "design": ("design",),
             "both": ("elastic", "design")}[sp.get("kind", "both").lower()]
    cols = [(c, k) for c in names for k in kinds]
    header = "period (s)," + ",".join(f"{c}_{k} (g)" for c, k in cols)
    rows = [[mpf(t)] + [code_value(c, t, nml, k == "elastic") for c, k in cols]
            for t in periods]
    return header, rows


def suite_tables(nml_path, nml):
    """(mean table header, rows), (summary header, row) of the check."""
    su = nml["suite"]
    t1 = float(su["t1"])
    n = int(su.get("n_points", 400))                # the driver's default
    target = su.get("target", "EC8_1").lower()
    lo, hi = 0.2 * t1, 2.0 * t1
    grid = [lo] + [lo * 10.0 ** ((i - 1) / (n - 1)) for i in range(2, n)] + [hi]
    if target == "eak":
        corners = [float(x) for x in EAK_T[nml["eak"].get("ground", "B").lower()]]
    else:
        ground = nml["ec8"].get("ground", "A").lower()
        corners = [float(x) for x in EC8_TABLE[int(target[-1])][ground][1:]]
    extra = [t1] + corners             # the check grid: T1 and the target's corners only
    grid = sorted(set(grid + [x for x in extra if lo <= x <= hi]))
    five = mpf(5)
    tgt = [code_value(target, t, nml, True, five) for t in grid]
    tgt0 = code_value(target, 0.0, nml, True, five)
    psa, pga = [], []
    for name, acc, dt, p in sdof_records(nml_path, nml["records"]):
        row = []
        for t in grid:
            (sd, _, _), _ = sdof_record_response(acc, dt, t, mpf("0.05"), G_STANDARD, True)
            row.append((2 * mp.pi / mpf(t))**2 * sd / G_STANDARD)
        psa.append(row)
        pga.append(p)
    nr = len(psa)
    mean = [sum(r[i] for r in psa) / nr for i in range(len(grid))]
    ratio = [m / x for m, x in zip(mean, tgt)]
    pga_mean = sum(pga) / nr
    common = max([tgt0 / pga_mean] + [mpf("0.9") * x / m for m, x in zip(mean, tgt)])   # (M.1)
    if su.get("fit", "linear").lower() == "linear":
        own = [sum(a * x for a, x in zip(r, tgt)) / sum(a * a for a in r) for r in psa]  # (M.2)
    else:
        own = [mp.exp(sum(mp.log(x) - mp.log(a) for a, x in zip(r, tgt)) / len(grid))
               for r in psa]                                                            # (M.3)
    own_mean = [sum(s * r[i] for s, r in zip(own, psa)) / nr for i in range(len(grid))]
    # between the grid periods (doc/record-suites.md section 2): a golden-section search
    # of each least ratio in the two grid intervals next to its grid minimum (25 steps,
    # the PSA in mpmath as above); a lower value found there is a row of its own and
    # sets min_ratio, common_scale and the rule (so the reference cannot pass because
    # the minimum happens to lie on the grid)
    recs = list(sdof_records(nml_path, nml["records"]))
    cache = {}

    def psa_at(t):
        if t not in cache:
            cache[t] = [(2 * mp.pi / t)**2 * sdof_record_response(
                acc, dt, t, mpf("0.05"), G_STANDARD, True)[0][0] / G_STANDARD
                for _, acc, dt, _ in recs]
        return cache[t]

    def least(values, factors):
        i = min(range(len(grid)), key=lambda k: values[k])
        f = lambda t: sum(c * a for c, a in zip(factors, psa_at(t))) / nr \
            / code_value(target, t, nml, True, five)
        best = (values[i], mpf(grid[i]))
        for a, b in ((i - 1, i), (i, i + 1)):
            if a < 0 or b >= len(grid):
                continue
            lo_, hi_ = mpf(grid[a]), mpf(grid[b])
            r = (mp.sqrt(5) - 1) / 2
            x1, x2 = hi_ - r * (hi_ - lo_), lo_ + r * (hi_ - lo_)
            f1, f2 = f(x1), f(x2)
            for _ in range(25):
                if f1 <= f2:
                    hi_, x2, f2 = x2, x1, f1
                    x1 = hi_ - r * (hi_ - lo_)
                    f1 = f(x1)
                else:
                    lo_, x1, f1 = x1, x2, f2
                    x2 = lo_ + r * (hi_ - lo_)
                    f2 = f(x2)
            for v, t in ((f1, x1), (f2, x2)):
                if v < best[0] * (1 - mpf("1e-12")):
                    best = (v, t)
        return best

    low, t_low = least(ratio, [mpf(1)] * nr)
    own_ratio = [o / x for o, x in zip(own_mean, tgt)]
    own_low, own_t = least(own_ratio, own)
    extra_t = sorted({t for t in (t_low, own_t) if t not in [mpf(g) for g in grid]})
    common = max(common, mpf("0.9") / low)
    header = ("period (s),target (g),target_90 (g),mean (g),ratio (-),mean_common (g),"
              "mean_own (g)")
    rows = [[mpf(t), x, mpf("0.9") * x, m, m / x, common * m, o]
            for t, x, m, o in zip(grid, tgt, mean, own_mean)]
    for t in extra_t:
        x, ps = code_value(target, t, nml, True, five), psa_at(t)
        m, o = sum(ps) / nr, sum(c * a for c, a in zip(own, ps)) / nr
        rows.append([t, x, mpf("0.9") * x, m, m / x, common * m, o])
    rows.sort(key=lambda row: row[0])
    own_pga = sum(s * p for s, p in zip(own, pga)) / nr / tgt0
    word = lambda ok: "pass" if ok else "fail"
    pga_ok, spec_ok = pga_mean >= tgt0, low >= mpf("0.9")
    own_ok = nr >= 3 and own_pga >= 1 and own_low >= mpf("0.9")
    # the rule that sets common_scale: the larger of the two factors of (M.1), which must
    # lie well apart (at a tie either rule is right and the reference could not tell)
    f_pga, f_spec = tgt0 / pga_mean, mpf("0.9") / low
    assert abs(f_pga - f_spec) > mpf("1e-6") * max(f_pga, f_spec), "(M.1): the rules tie"
    rule = "pga" if f_pga > f_spec else "spectrum"
    summary = ("n_listed (-),n_failed (-),n_records (-),target (-),fit (-),t1 (s),"
               "t_low (s),t_high (s),n_periods (-),pga_mean (g),pga_target (g),"
               "pga_ratio (-),pga_check (-),min_ratio (-),t_min_ratio (s),"
               "spectrum_check (-),count_check (-),mean_allowed (-),check (-),"
               "common_scale (-),common_rule (-),own_pga_ratio (-),own_min_ratio (-),"
               "own_t_min_ratio (s),own_check (-),status (-)")
    srow = [mpf(nr), mpf(0), mpf(nr), target.upper(), su.get("fit", "linear").lower(),
            mpf(t1), mpf(lo), mpf(hi), mpf(len(rows)), pga_mean, tgt0, pga_mean / tgt0,
            word(pga_ok), low, t_low, word(spec_ok), word(nr >= 3),
            "yes" if nr >= 7 else "no", word(nr >= 3 and pga_ok and spec_ok), common, rule,
            own_pga, own_low, own_t, word(own_ok), "ok"]
    return (header, rows), (summary, [srow])


def make_spectra_ref(nml_path, nml):
    tables = []
    with mp.workdps(40):
        if "spectra" in nml:
            tables.append((".ref", spectra_rows(nml)))
        if "suite" in nml:
            mean, summary = suite_tables(nml_path, nml)
            tables += [(".ref" if "spectra" not in nml else ".mean.ref", mean),
                       (".summary.ref", summary)]
        for suffix, (header, rows) in tables:
            lines = [header] + [",".join(csv_cell(x) for x in row) for row in rows]
            out = Path(nml_path).with_suffix(suffix)
            out.write_text("\n".join(lines) + "\n")
            print(f"wrote {out} ({len(lines) - 1} rows)")


def make_ref(nml_path):
    nml = parse_namelist(Path(nml_path).read_text())
    analysis = nml.get("run", {}).get("analysis", "pulse").lower()
    if analysis in ("sdof", "sdof_beta", "sdof_shock"):
        make_sdof_ref(nml_path, nml, analysis)
        return
    if analysis == "newmark":
        make_newmark_ref(nml_path, nml)
        return
    if analysis == "sliding":
        make_sliding_ref(nml_path, nml)
        return
    if analysis == "rocking":
        make_rocking_ref(nml_path, nml)
        return
    if analysis == "walls":
        make_walls_ref(nml_path, nml)
        return
    if analysis == "cylinder":
        make_cylinder_ref(nml_path, nml)
        return
    if analysis == "winkler":
        make_winkler_ref(nml_path, nml)
        return
    if analysis == "empirical":
        make_empirical_ref(nml_path, nml)
        return
    if analysis == "spectra":
        make_spectra_ref(nml_path, nml)
        return
    func, g = pulse_function(nml["pulse"])
    lines = [HEADER]
    for t in time_grid(nml["time"]):
        a, v, d = func(t)
        row = (mpf(t), a, a / mpf(g), v, d)
        lines.append(",".join(repr(float(x)) for x in row))
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out} ({len(lines) - 1} rows)")


# ---------------------------------------------------------------------------
# Analysis 'empirical' (given parameters; never by running the driver): the regressions
# of doc/empirical.md (E.1)-(E.35) written out here from the sources, in mpmath
# ---------------------------------------------------------------------------

EMP_KEYS = ("pga", "pgv", "arias", "magnitude", "ts", "sa_15ts", "tm")
EMP_HEADER = ("model (-),case (-),ky (g),pga (g),pgv (cm/s),arias (m/s),magnitude (-),ts (s),"
              "sa_15ts (g),tm (s),disp (cm),sigma (-),base (-),d16 (cm),d84 (cm),p_zero (-),"
              "p_failure (-),kmax (g),newmark_exact (cm),newmark_slammer (cm),status (-)")


def emp_log10_ratio(r, a, b):
    return a * mp.log10(1 - r) + b * mp.log10(r)


def emp_quartic(r, c):
    return c[0] + c[1] * r + c[2] * r**2 + c[3] * r**3 + c[4] * r**4


def emp_rs09(ky, pga, m):
    r = ky / pga
    return mp.exp(emp_quartic(r, (4.89, -4.85, -19.64, 42.49, -29.06)) + mpf("0.72") * mp.log(pga)
                  + mpf("0.89") * (m - 6))


def emp_sr08_pgv(ky, pga, pgv):
    r = ky / pga
    return mp.exp(emp_quartic(r, (-1.56, -4.58, -20.84, 44.75, -30.50))
                  - mpf("0.64") * mp.log(pga) + mpf("1.55") * mp.log(pgv))


def emp_rigid_models():
    """(name, inputs, log base, median(ky, p), sigma(ky, p)) of (E.1)-(E.12); p the dict of
    inputs (mpf)."""
    m = lambda x: mpf(str(x))
    return [
        ("jibson_1993", ("arias",), 10,
         lambda k, p: 10**(m(1.460) * mp.log10(p["arias"]) - m(6.642) * k + m(1.546)),
         lambda k, p: m(0.409)),
        ("jibson_1998", ("arias",), 10,
         lambda k, p: 10**(m(1.521) * mp.log10(p["arias"]) - m(1.993) * mp.log10(k) - m(1.546)),
         lambda k, p: m(0.375)),
        ("jibson_2007_ratio", ("pga",), 10,
         lambda k, p: 10**(m(0.215) + emp_log10_ratio(k / p["pga"], m(2.341), m(-1.438))),
         lambda k, p: m(0.510)),
        ("jibson_2007_ratio_m", ("pga", "magnitude"), 10,
         lambda k, p: 10**(m(-2.710) + emp_log10_ratio(k / p["pga"], m(2.335), m(-1.478))
                           + m(0.424) * p["magnitude"]),
         lambda k, p: m(0.454)),
        ("jibson_2007_arias", ("arias",), 10,
         lambda k, p: 10**(m(2.401) * mp.log10(p["arias"]) - m(3.481) * mp.log10(k) - m(3.230)),
         lambda k, p: m(0.656)),
        ("jibson_2007_arias_ratio", ("pga", "arias"), 10,
         lambda k, p: 10**(m(0.561) * mp.log10(p["arias"]) - m(3.833) * mp.log10(k / p["pga"])
                           - m(1.474)),
         lambda k, p: m(0.616)),
        ("ambraseys_menu_1988", ("pga",), 10,
         lambda k, p: 10**(m(0.90) + emp_log10_ratio(k / p["pga"], m(2.53), m(-1.09))),
         lambda k, p: m(0.30)),
        ("saygili_rathje_2008_pga", ("pga",), 0,
         lambda k, p: mp.exp(emp_quartic(k / p["pga"], [m(x) for x in (5.52, -4.43, -20.39,
                                                                      42.61, -28.74)])
                             + m(0.72) * mp.log(p["pga"])),
         lambda k, p: m(1.13)),
        ("saygili_rathje_2008_pgv", ("pga", "pgv"), 0,
         lambda k, p: emp_sr08_pgv(k, p["pga"], p["pgv"]),
         lambda k, p: m(0.41) + m(0.52) * k / p["pga"]),
        ("saygili_rathje_2008_pgv_ia", ("pga", "pgv", "arias"), 0,
         lambda k, p: mp.exp(emp_quartic(k / p["pga"], [m(x) for x in (-0.74, -4.93, -19.91,
                                                                      43.75, -30.12)])
                             - m(1.30) * mp.log(p["pga"]) + m(1.04) * mp.log(p["pgv"])
                             + m(0.67) * mp.log(p["arias"])),
         lambda k, p: m(0.20) + m(0.79) * k / p["pga"]),
        ("rathje_saygili_2009", ("pga", "magnitude"), 0,
         lambda k, p: emp_rs09(k, p["pga"], p["magnitude"]),
         lambda k, p: m(0.732) + m(0.789) * k / p["pga"] - m(0.539) * (k / p["pga"])**2),
    ]


def emp_bt07(ky, p, slammer):
    """(E.13)-(E.16): (disp cm, P(D = 0))."""
    lk, ls, ts = mp.log(ky), mp.log(p["sa_15ts"]), p["ts"]
    lnd = (-mpf("2.83") * lk - mpf("0.333") * lk**2 + mpf("0.566") * lk * ls + mpf("3.04") * ls
           - mpf("0.244") * ls**2 + mpf("0.278") * (p["magnitude"] - 7))
    if ts < mpf("0.05") and not slammer:
        lnd += mpf("-0.22")
    else:
        lnd += mpf("-1.10") + mpf("1.50") * ts
    x = -mpf("1.76") - mpf("3.22") * lk - mpf("0.484") * ts * lk + mpf("3.52") * ls
    if slammer:
        t = 1 / (1 + mpf("0.2316419") * x)
        b = [mpf(v) for v in ("0.319381530", "-0.356563782", "1.781477937", "-1.821255978",
                              "1.330274429")]
        p0 = mp.npdf(x) * sum(bk * t**(i + 1) for i, bk in enumerate(b))
    else:
        p0 = 1 - mp.ncdf(x)
    return mp.exp(lnd), p0


def emp_ra11(ky, p, form, slammer):
    """(E.26)-(E.32): (disp cm, sigma, kmax)."""
    ts, pga = p["ts"], p["pga"]
    pr = ts / p["tm"]
    if slammer:
        pr = min(pr, mpf(8))
    kmax = pga if pr < mpf("0.1") else pga * mp.exp(
        (mpf("0.459") - mpf("0.702") * pga) * mp.log(pr / mpf("0.1"))
        + (mpf("-0.228") + mpf("0.076") * pga) * mp.log(pr / mpf("0.1"))**2)
    r = ky / kmax
    if form == "m":
        sigma = mpf("0.694") + mpf("0.322") * r
        f = mpf("3.69") * ts - mpf("1.22") * ts**2 if ts <= mpf("1.5") else mpf("2.78")
        d = emp_rs09(ky, kmax, p["magnitude"]) * mp.exp(f) if r < 1 else mpf(0)
    else:
        kvel = p["pgv"] if pr < mpf("0.2") else p["pgv"] * mp.exp(
            mpf("0.240") * mp.log(pr / mpf("0.2"))
            + (mpf("-0.091") - mpf("0.171") * pga) * mp.log(pr / mpf("0.2"))**2)
        sigma = mpf("0.400") + mpf("0.284") * r
        f = mpf("1.42") * ts if ts <= mpf("0.5") else mpf("0.71")
        d = emp_sr08_pgv(ky, kmax, kvel) * mp.exp(f) if r < 1 else mpf(0)
    if slammer and ky > pga:
        d = mpf(0)
    return d, sigma, kmax


def emp_pfail(d):
    return mpf("0.335") * (1 - mp.exp(-mpf("0.048") * d**mpf("1.565")))


def empirical_case_rows(c, p, kys, slammer, exact=None, slam=None, failed=False):
    """The rows of case c (1-based) with inputs p ({key: mpf}, the keys given): per ky,
    every model whose inputs p has, in the driver's order. exact, slam: the rigorous
    columns per ky (cm; NaN without records). failed: a record that could not be read
    (the rows its given inputs and a record's measures would allow, NaN, status 1)."""
    nan, rows = mpf("nan"), []
    inputs = [p.get(k, nan) for k in EMP_KEYS]
    have = set(p)
    if failed:
        have |= {"pga", "pgv", "arias", "tm"} | ({"sa_15ts"} if "ts" in p else set())
    for i, ky in enumerate(kys):
        ex = exact[i] if exact else nan
        sl = slam[i] if slam else nan

        def row(name, d, sigma, base, p0=nan, kmax=nan):
            if failed:
                rows.append([name, mpf(c), ky] + inputs + [nan] * 8 + [ex, sl, mpf(1)])
                return
            if d == 0 and sigma != sigma:       # ky >= PGA: no sliding
                d16 = d84 = pf = mpf(0)
                base = nan
            else:
                fac = base**sigma
                d16, d84, pf = d / fac, d * fac, emp_pfail(d)
            rows.append([name, mpf(c), ky] + inputs
                        + [d, sigma, base, d16, d84, p0, pf, kmax, ex, sl, mpf(0)])
        for name, needs, base, med, sig in emp_rigid_models():
            if not set(needs) <= have:
                continue
            b = mpf(10) if base == 10 else mp.e
            if failed:
                row(name, nan, nan, b)
            elif "pga" in needs and not ky < p["pga"]:
                row(name, mpf(0), nan, b)
            else:
                row(name, med(ky, p), sig(ky, p), b)
        if {"ts", "sa_15ts", "magnitude"} <= have:
            d, p0 = (nan, nan) if failed else emp_bt07(ky, p, slammer)
            row("bray_travasarou_2007", d, mpf("0.66"), mp.e, p0=p0)
        for form, need in (("m", "magnitude"), ("pgv", "pgv")):
            if {"ts", "tm", "pga", need} <= have:
                d, sigma, kmax = (nan, nan, nan) if failed else emp_ra11(ky, p, form, slammer)
                row("rathje_antonakos_2011_" + form, d, sigma, mp.e, kmax=kmax)
    return rows


def empirical_rows(nml_path, nml):
    e = nml["empirical"]
    slammer = bool(e.get("slammer", False))
    kys = [mpf(x) for x in _as_list(e["ky"])]
    given = {k: [mpf(x) for x in _as_list(e[k])] for k in EMP_KEYS if k in e}
    if "records" not in nml:
        ncase = max(len(v) for v in given.values())
        return [r for c in range(ncase) for r in empirical_case_rows(
            c + 1, {k: v[min(c, len(v) - 1)] for k, v in given.items()}, kys, slammer)]
    # records: each record's own PGA, PGV (cm/s), Ia, Tm and Sa(1.5 Ts) (the PGA for
    # Ts < 0.05 s), the rigorous rigid block downslope (exact in mpmath, SLAMMER's loop)
    g = mpf(e.get("g", G_STANDARD))
    zeta = mpf(e.get("damping", 0.05))
    rows = []
    for c, (name, acc, dt, pga) in enumerate(sdof_records(nml_path, nml["records"])):
        p = {k: v[min(c, len(v) - 1)] for k, v in given.items()}
        if acc is None:
            rows += empirical_case_rows(c + 1, p, kys, slammer, failed=True)
            continue
        pga_m, pgv, _, arias, _, _, _, tm = record_measures(acc, dt, g)
        p.update(pga=pga_m, pgv=100 * pgv, arias=arias, tm=tm)
        if "ts" in p:
            if p["ts"] < mpf("0.05"):
                p["sa_15ts"] = pga_m
            else:
                period = 3 * p["ts"] / 2
                (sd, _, _), _ = sdof_record_response(acc, dt, period, zeta, g, True)
                p["sa_15ts"] = (2 * mp.pi / period)**2 * sd / g
        inf = mpf("inf")
        exact = [100 * g * newmark_exact(acc, dt, ky, inf, mpf(1), mpf(1))[0] for ky in kys]
        slam = [newmark_slammer(acc, dt, ky, g)[0] for ky in kys]
        rows += empirical_case_rows(c + 1, p, kys, slammer, exact, slam)
    return rows


def make_empirical_ref(nml_path, nml):
    with mp.workdps(40):
        rows = named(EMP_HEADER, empirical_rows(nml_path, nml))
        lines = [EMP_HEADER] + [",".join(csv_cell(x) for x in row) for row in rows]
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out} ({len(lines) - 1} rows)")


def main(argv):
    cases = argv or sorted(HERE.glob("*.nml"))
    for case in cases:
        make_ref(case)


if __name__ == "__main__":
    main(sys.argv[1:])
