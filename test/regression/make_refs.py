#!/usr/bin/env python3
"""Write the driver regression references <case>.ref from <case>.nml, computed
independently with the mpmath pulse references in test/python/pulse_reference.py.

usage: make_refs.py [CASE.nml ...]   (default: pulse_exponential.nml pulse_classic.nml
                                      next to this script)

The time grid follows the driver: t_i = t_start + dt * i in double precision, with
npts = floor((t_end - t_start) / dt * (1 + 1e-12)) + 1 when dt is given, or
dt = (t_end - t_start) / (npts - 1) when npts is given. Each row is evaluated at that
exact double t in high precision and printed with repr(float(x)).
"""
import math
import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "python"))

import pulse_reference as ref  # noqa: E402
from mpmath import mpf  # noqa: E402

HEADER = "t (s),a (m/s2),a (g),v (m/s),d (m)"

_TOKEN = re.compile(r"""
    \s*(?:
      (?P<group>&\w+)
    | (?P<end>/)
    | (?P<key>\w+)\s*=
    | (?P<str>'[^']*'|"[^"]*")
    | (?P<logical>\.(?:true|false|t|f)\.)
    | (?P<num>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?)
    | (?P<sep>,)
    )""", re.VERBOSE | re.IGNORECASE)


def parse_namelist(text):
    """Minimal Fortran namelist reader: {group: {key: value}} (lower-case names;
    scalar values only: strings, logicals, integers, reals)."""
    text = "\n".join(line.split("!", 1)[0] for line in text.splitlines())
    groups, group, key, pos = {}, None, None, 0
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
        elif kind == "end":
            group, key = None, None
        elif kind == "key":
            if group is None:
                raise ValueError(f"key {tok!r} outside a group")
            key = tok.lower()
        elif kind == "sep":
            continue
        else:
            if group is None or key is None:
                raise ValueError(f"value {tok!r} without a key")
            if kind == "str":
                value = tok[1:-1]
            elif kind == "logical":
                value = tok.lower() in (".true.", ".t.")
            elif re.fullmatch(r"[-+]?\d+", tok):
                value = int(tok)
            else:
                value = float(tok.replace("d", "e").replace("D", "e"))
            group[key] = value
            key = None
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


def make_ref(nml_path):
    nml = parse_namelist(Path(nml_path).read_text())
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
    cases = argv or [HERE / "pulse_exponential.nml", HERE / "pulse_classic.nml"]
    for case in cases:
        make_ref(case)


if __name__ == "__main__":
    main(sys.argv[1:])
