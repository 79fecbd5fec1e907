#!/usr/bin/env python3
"""Benchmark: 5 %-damped response spectra, 100 periods, of Kobe TAK-090 (4015 steps) and
Kocaeli ATS-090 (26 780 steps), the records shipped with pyslammer.

Times seispulse.sdof.spectrum single-threaded (peaks 'exact': true maxima between the
samples; and 'samples', eqsig's convention), and with the default OpenMP threads, next
to eqsig's Nigam-Jennings recurrence (numpy, vectorized over periods) and, when
installed, pyrotd (FFT) and openseespy (one transient analysis per period), in the same
run: medians of several runs and the ratio peer time / seispulse time, which is what
to quote on these shared, noisy machines. Aim: at least 20 times faster than eqsig
single-threaded. Also prints the largest relative difference from eqsig at T >= 6 dt
(samples) so the speed is seen next to the answer.

usage: PYTHONPATH=build/python python3 bench/sdof.py [--runs R] [--periods N]
"""
import argparse
from pathlib import Path

import numpy as np

from seispulse import records, sdof
from timing import median_time

G = 9.80665


def opensees_spectrum(accel, dt, periods, zeta):
    """Peak relative displacements with openseespy: one linear SDOF model per period
    (Newmark average acceleration at the record's step), as users of OpenSees do it."""
    import openseespy.opensees as ops
    sd = np.empty(len(periods))
    for i, period in enumerate(periods):
        w = 2 * np.pi / period
        ops.wipe()
        ops.model("basic", "-ndm", 1, "-ndf", 1)
        ops.node(1, 0.0)
        ops.node(2, 0.0, "-mass", 1.0)
        ops.fix(1, 1)
        ops.uniaxialMaterial("Elastic", 1, w * w)
        ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
        ops.timeSeries("Path", 1, "-dt", dt, "-values", *(accel * G))
        ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
        ops.rayleigh(2 * zeta * w, 0.0, 0.0, 0.0)
        ops.constraints("Plain")
        ops.numberer("Plain")
        ops.system("BandGeneral")
        ops.test("NormDispIncr", 1e-12, 10)
        ops.algorithm("Linear")
        ops.integrator("Newmark", 0.5, 0.25)
        ops.analysis("Transient")
        peak = 0.0
        for _ in range(len(accel) - 1):
            ops.analyze(1, dt)
            peak = max(peak, abs(ops.nodeDisp(2, 1)))
        sd[i] = peak
    ops.wipe()
    return sd


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--periods", type=int, default=100)
    args = parser.parse_args()
    try:
        import pyslammer
        import eqsig.sdof as eqsig_sdof
    except ImportError:
        raise SystemExit("pyslammer (the records) and eqsig (the peer) are needed: "
                         "pip install pyslammer eqsig")
    try:
        import pyrotd
    except ImportError:
        pyrotd = None
    try:
        import openseespy.opensees  # noqa: F401
        have_opensees = True
    except Exception:
        have_opensees = False
    folder = Path(pyslammer.__file__).parent / "sample_ground_motions"
    print(f"seispulse default OpenMP threads: {sdof.default_threads()}; medians of "
          f"{args.runs} runs; {args.periods} periods 0.01-10 s (log), 5 % damping")
    for name in ("Kobe_1995_TAK-090", "Kocaeli_1999_ATS-090"):
        rec = records.read(folder / f"{name}.csv")
        periods = np.geomspace(0.01, 10.0, args.periods)
        print(f"{name}: {rec.npts} steps, dt {rec.dt} s")
        peer = median_time(lambda: eqsig_sdof.pseudo_response_spectra(rec.accel * G, rec.dt,
                                                                       periods, 0.05), args.runs)
        print(f"  eqsig pseudo_response_spectra      : {peer * 1e3:9.2f} ms")
        if pyrotd is not None:
            t = median_time(lambda: pyrotd.calc_spec_accels(rec.dt, rec.accel, 1 / periods, 0.05),
                            args.runs)
            print(f"  pyrotd calc_spec_accels            : {t * 1e3:9.2f} ms")
        if have_opensees:
            few = periods[::10]
            t = median_time(lambda: opensees_spectrum(rec.accel, rec.dt, few, 0.05), 1)
            print(f"  openseespy, one model per period   : {t * len(periods) / len(few) * 1e3:9.2f}"
                  f" ms (timed on {len(few)} periods, scaled)")
        cases = [("exact", 1), ("samples", 1), ("exact", None)]
        for peaks, threads in cases:
            t = median_time(lambda: sdof.spectrum(rec, periods=periods, peaks=peaks,
                                                  threads=threads), args.runs)
            label = f"seispulse {peaks}, {'1 thread' if threads else 'default threads'}"
            print(f"  {label:35s}: {t * 1e3:9.2f} ms   eqsig/seispulse = {peer / t:6.1f}   "
                  f"{rec.npts * len(periods) / t:9.3g} oscillator-steps/s")
        # the answer next to the speed
        ok = periods >= 6 * rec.dt
        mine = sdof.spectrum(rec, periods=periods, peaks="samples")
        sd_e, _, _ = eqsig_sdof.pseudo_response_spectra(rec.accel * G, rec.dt, periods, 0.05)
        exact = sdof.spectrum(rec, periods=periods)
        print(f"  max |SD/SD_eqsig - 1| at T >= 6 dt (samples): "
              f"{np.max(np.abs(mine.sd[ok] / sd_e[ok] - 1)):.2e};  exact maxima exceed the "
              f"sample ones by up to {np.max(exact.psa / mine.psa - 1) * 100:.1f} %")


if __name__ == "__main__":
    main()
