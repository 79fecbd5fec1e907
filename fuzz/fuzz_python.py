"""atheris harness for the Python entry points of seispulse (fuzz/README.md).

One input drives one call, chosen by its first byte:

* ``records.read`` on the rest of the input written to a file (name, format, units
  and dt chosen from the input too),
* ``sdof.spectrum`` and ``sdof.response`` on fuzzed samples, dt, periods, damping,
* ``newmark.rigid`` on fuzzed samples, dt, ky, mode, method,
* ``pulse.evaluate`` of every pulse kind on fuzzed times and parameters.

Every exception other than seispulse's documented errors (``seispulse.errors``:
InvalidInputError, FileError, ... all SeispulseError) is a finding, as is a result
that breaks a documented promise (a record with a non-finite sample or dt <= 0).

Run it through ``make fuzz`` (fuzz/run.sh), or by hand:
``PYTHONPATH=build/python .venv/bin/python fuzz/fuzz_python.py -max_total_time=60 DIR``;
with file arguments (no option) it replays them once (regression inputs).
"""

import inspect
import math
import os
import sys
import tempfile

import atheris

with atheris.instrument_imports(include=["seispulse"]):
    import numpy as np
    from seispulse import newmark, pulse, records, sdof
    from seispulse.errors import SeispulseError

SCRATCH = tempfile.mkdtemp(prefix="seispulse-fuzz-py-")
NAMES = ("rec.AT2", "rec.csv", "rec.txt", "rec.dat", "rec")
FORMATS = records.FORMATS
UNITS = (None, "g", "m/s2", "cm/s2", "gal", "furlong")
MAX_SAMPLES = 512
MAX_PERIODS = 16


def floats(fdp, nmax):
    """Up to nmax doubles, any value (NaN, inf, subnormal) now and then."""
    n = fdp.ConsumeIntInRange(0, nmax)
    return [number(fdp) for _ in range(n)]


def number(fdp):
    """A double: mostly moderate, sometimes any bit pattern."""
    if fdp.ConsumeIntInRange(0, 7) == 0:
        return fdp.ConsumeFloat()
    return fdp.ConsumeFloatInRange(-1.0e3, 1.0e3)


def positive(fdp):
    """A step, period or parameter: mostly positive and moderate, sometimes anything."""
    if fdp.ConsumeIntInRange(0, 7) == 0:
        return fdp.ConsumeFloat()
    return fdp.ConsumeFloatInRange(1.0e-4, 10.0)


def check_record(rec):
    if not (rec.npts >= 1 and rec.accel.shape == (rec.npts,)
            and np.all(np.isfinite(rec.accel)) and math.isfinite(rec.dt) and rec.dt > 0
            and math.isfinite(rec.t0)):
        raise AssertionError(f"records.read returned a broken record: {rec!r}")


def do_read(fdp):
    name = NAMES[fdp.ConsumeIntInRange(0, len(NAMES) - 1)]
    fmt = FORMATS[fdp.ConsumeIntInRange(0, len(FORMATS) - 1)]
    units = UNITS[fdp.ConsumeIntInRange(0, len(UNITS) - 1)]
    dt = None if fdp.ConsumeBool() else positive(fdp)
    data = fdp.ConsumeBytes(fdp.remaining_bytes())
    path = os.path.join(SCRATCH, name)
    with open(path, "wb") as fh:
        fh.write(data)
    check_record(records.read(path, fmt=fmt, units=units, dt=dt))


def do_spectrum(fdp):
    accel = floats(fdp, MAX_SAMPLES)
    dt = positive(fdp)
    periods = [abs(x) for x in floats(fdp, MAX_PERIODS)]
    damping = fdp.ConsumeFloatInRange(-0.1, 1.1)
    if fdp.ConsumeBool():
        peaks = ("exact", "samples", "other")[fdp.ConsumeIntInRange(0, 2)]
        sdof.spectrum(accel, dt, periods, damping=damping, peaks=peaks, threads=1)
    else:
        period = abs(number(fdp))
        sdof.response(accel, dt, period, damping=damping)


def do_newmark(fdp):
    accel = floats(fdp, MAX_SAMPLES)
    dt = positive(fdp)
    ky = positive(fdp) if fdp.ConsumeBool() else [positive(fdp) for _ in range(3)]
    mode = ("down", "both", "asym", "sideways")[fdp.ConsumeIntInRange(0, 3)]
    ky_up = positive(fdp) if mode == "asym" or fdp.ConsumeBool() else None
    method = ("exact", "slammer", "other")[fdp.ConsumeIntInRange(0, 2)]
    newmark.rigid(accel, dt, ky, mode=mode, ky_up=ky_up, method=method)


def do_pulse(fdp):
    kind = pulse.KINDS[fdp.ConsumeIntInRange(0, len(pulse.KINDS) - 1)]
    function = getattr(pulse, kind)
    params = {}
    for pname, par in list(inspect.signature(function).parameters.items())[1:]:
        if pname in ("full",):
            params[pname] = fdp.ConsumeBool()
        elif pname == "amp_unit":
            params[pname] = UNITS[1 + fdp.ConsumeIntInRange(0, len(UNITS) - 2)]
        elif pname == "cycles":
            params[pname] = fdp.ConsumeIntInRange(-2, 50)
        elif par.default is inspect.Parameter.empty or fdp.ConsumeBool():
            params[pname] = positive(fdp)
    t = floats(fdp, MAX_SAMPLES)
    pulse.evaluate(kind, t, **params)


TARGETS = (do_read, do_spectrum, do_newmark, do_pulse)


def test_one_input(data):
    fdp = atheris.FuzzedDataProvider(data)
    target = TARGETS[fdp.ConsumeIntInRange(0, len(TARGETS) - 1)]
    try:
        target(fdp)
    except SeispulseError:
        pass  # a documented error: the library said what is wrong


def main():
    replay = [a for a in sys.argv[1:] if not a.startswith("-") and os.path.isfile(a)]
    if replay and len(replay) == len(sys.argv) - 1:
        for path in replay:
            with open(path, "rb") as fh:
                test_one_input(fh.read())
        print(f"fuzz_python: {len(replay)} inputs replayed, no finding")
        return
    atheris.Setup(sys.argv, test_one_input)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
