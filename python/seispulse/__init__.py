"""seispulse: closed-form and exact numerical answers for idealized near-fault
pulses and accelerograms.

Modules: :mod:`seispulse.pulse` (pulses), :mod:`seispulse.sliding` (sliding blocks),
:mod:`seispulse.rocking` (rocking blocks), :mod:`seispulse.cylinder` (rigid cylinders and
blocks rocking on a rigid base), :mod:`seispulse.winkler` (cylinders and blocks on
Winkler and inelastic clay foundations), :mod:`seispulse.records` (accelerograms and
their intensity measures), :mod:`seispulse.newmark` (Newmark sliding on records),
:mod:`seispulse.empirical` (empirical estimates of slope displacements), :mod:`seispulse.sdof` (the linear
oscillator: closed forms, responses and spectra), :mod:`seispulse.walls` (elastodynamic
seismic earth pressures on rigid walls), :mod:`seispulse.codes` (EN 1998 earth-pressure
checks and spectra), :mod:`seispulse.plot` (plots of the results; needs matplotlib).
Errors: :mod:`seispulse.errors`; bad input raises :class:`InvalidInputError`, a ValueError
whose message names the parameter.
"""

from . import (codes, cylinder, empirical, errors, newmark, plot, pulse, records, rocking,
               sdof, sliding, walls, winkler)
from .errors import (ConvergenceError, FileError, InternalError, InvalidInputError,
                     NoBracketError, NoSolutionError, SeispulseError, SingularError)

__version__ = "0.1.0"

__all__ = ["pulse", "sliding", "rocking", "cylinder", "records", "newmark", "sdof", "walls", "codes",
           "winkler", "empirical", "plot", "errors",
           "SeispulseError", "InvalidInputError", "SingularError", "ConvergenceError",
           "NoBracketError", "NoSolutionError", "InternalError", "FileError", "__version__"]
