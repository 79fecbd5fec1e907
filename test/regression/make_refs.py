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
sliding.md (mpmath, 40 digits):
  * rectangle, full cycle: kind 'exponential' with beta = -inf, full = .true.
    (sliding.md 5.5; the block always slips);
  * rectangle, half cycle: kind 'rectangular', or 'exponential' with beta = -inf
    (Newmark 1965, sliding.md 3.5 Eq. 1.10a);
  * triangle, half cycle: kind 'triangular' with peak_frac = 0.5, or 'exponential' with
    beta = 0 (sliding.md 3.5, the table of explicit triangle results; V_m/V_g = (1-eta)^2);
and &block gives mu (mu_list; any slope_deg, xi_deg: Eq. 1.31 and the factors K of
sliding.md 7.1) or eta1 (eta_list), with static_factor. Static friction only moves the
onset: for the rectangle the onset stays at t = 0 (no sliding if static_factor eta >= 1);
for the triangle these references support static_factor = 1 only.

Analysis 'rocking' (never by running the driver): the linearized model (&block
model = 'linearized') under the rectangular half-cycle pulse (kind 'rectangular', or
'exponential' with beta = -inf and full = .false.), written out from rocking.md in mpmath
(40 digits): the response (2.12, 2.13), the wall eta_w = 1 - e^-f (2.21), the region
boundaries cosh(f/2), cosh(f) = 1/(1 - eta) (2.17b, 2.17a), the critical time, the time of
the maximum (2.25), the maximum rotation (2.29) and the first impact (2.33). Summaries and
histories need restitution e = 0 (the block rests at its first impact; overturning
blocks need none); maps use the wall alone (the rectangle's impacts come after the
pulse, where a stable block cannot overturn: rocking.md 5.4), with cells at least 1e-6
(relative) away from it.
"""
import math
import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "python"))

import pulse_reference as ref  # noqa: E402
from mpmath import mp, mpf  # noqa: E402

HEADER = "t (s),a (m/s2),a (g),v (m/s),d (m)"
SLIDING_HEADER = ("case (-),mu (-),eta1 (-),eta2 (-),mode (-),t_y1 (s),t_m1 (s),u_m1 (m),"
                  "t_y2 (s),t_m2 (s),u_m2 (m),u_res (m),v_m1 (m/s),v_m2 (m/s)")
MODES = ("no_sliding", "unilateral", "stick", "slip", "stuck", "reverse_only")

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
        kw = dict(period=float(p.pop("period") if "period" in p else p.pop("duration")))
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
# Analysis 'sliding': closed forms of the limit shapes, written from sliding.md
# ---------------------------------------------------------------------------

def _as_list(x):
    return x if isinstance(x, list) else [x]


def resistances(mu, ag_over_g, slope_deg, xi_deg):
    """Eq. 1.31 and the along-plane factors of sliding.md 7.1, from the force balance:
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
    """Box full cycle (sliding.md 5.5), dimensionless: the forward slide starts at 0 with
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
    """Symmetric triangle half cycle (sliding.md 3.5, explicit triangle results; lobe
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
        rows = sliding_rows(nml)
        lines = [SLIDING_HEADER] + [",".join(repr(float(x)) for x in row) for row in rows]
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out} ({len(lines) - 1} rows)")


# ---------------------------------------------------------------------------
# Analysis 'rocking': the linearized rectangle in closed form, written from rocking.md
# ---------------------------------------------------------------------------

ROCKING_HEADER = ("alpha (rad),p (rad/s),e (-),f (-),eta (-),outcome (-),t_uplift (s),"
                  "t_overturn (s),n_impacts (-),t_impact1 (s),theta_max (rad),"
                  "theta_min (rad),psi_max (-),psi_min (-),t_end (s),region (-),"
                  "t_up_cf (s),t_c_cf (s),t_m_cf (s),psi_max_cf (-),t_i_cf (s)")
ROCKING_HISTORY_HEADER = "t (s),a_g (m/s2),theta (rad),omega (rad/s)"
ROCKING_MAP_HEADER = "freq_ratio (-),amp_ratio (-),class (-)"
# outcome codes: 0 rest, 2 overturn_no_impact; region codes: 1 O1, 2 O2, 3 O3, 5 S2


def rocking_block(b, g):
    """(alpha, p, e) of &block (rocking.md 2: R = sqrt(b^2 + h^2), alpha = atan(b/h),
    p = sqrt(g/(io R)), io = I_o/(m R^2) = 4/3 for the uniform rectangle; Housner's
    e = 1 - (2/io) sin^2 alpha, rocking.md 7)."""
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

    def axis(name):
        if f"{name}_ratio" in m:
            return [mpf(x) for x in _as_list(m[f"{name}_ratio"])]
        lo, hi = (float(x) for x in m[f"{name}_range"])
        n = int(m.get(f"{name}_count", 21))
        # the driver's doubles: lo + (hi - lo) * ((k - 1)/(n - 1)), the last one hi
        return [mpf(lo + (hi - lo) * ((k - 1) / (n - 1))) for k in range(1, n)] + [mpf(hi)]

    rows = []
    for a in axis("amp"):
        for fr in axis("freq"):
            f = 2 * mp.pi / fr                          # p = 1, T = 2 pi/freq_ratio
            if a == 0:
                cls = 0
            else:
                eta = alpha / (a * mp.tan(alpha))       # uplift at g alpha (linearized)
                wall = 1 - mp.exp(-f)
                if abs(eta - wall) < mpf(10)**-6 * wall or abs(eta - 1) < mpf(10)**-6:
                    raise ValueError(f"cell ({fr}, {a}) is too close to a boundary")
                cls = 1 if eta < wall else 0
            rows.append([fr, a, mpf(cls)])
    return rows


def make_rocking_ref(nml_path, nml):
    what = nml.get("rocking", {}).get("what", "summary").lower()
    with mp.workdps(40):
        if what == "summary":
            header, rows = ROCKING_HEADER, rocking_summary_rows(nml)
        elif what == "history":
            header, rows = ROCKING_HISTORY_HEADER, rocking_history_rows(nml)
        else:
            header, rows = ROCKING_MAP_HEADER, rocking_map_rows(nml)
        lines = [header] + [",".join(repr(float(x)) for x in row) for row in rows]
    out = Path(nml_path).with_suffix(".ref")
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out} ({len(lines) - 1} rows)")


def make_ref(nml_path):
    nml = parse_namelist(Path(nml_path).read_text())
    analysis = nml.get("run", {}).get("analysis", "pulse").lower()
    if analysis == "sliding":
        make_sliding_ref(nml_path, nml)
        return
    if analysis == "rocking":
        make_rocking_ref(nml_path, nml)
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


def main(argv):
    cases = argv or sorted(HERE.glob("*.nml"))
    for case in cases:
        make_ref(case)


if __name__ == "__main__":
    main(sys.argv[1:])
