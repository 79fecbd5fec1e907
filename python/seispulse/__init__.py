"""seispulse: closed-form and exact numerical answers for idealized near-fault
pulses and accelerograms.

Modules: :mod:`seispulse.pulse` (pulses), :mod:`seispulse.sliding` (sliding blocks),
:mod:`seispulse.rocking` (rocking blocks), :mod:`seispulse.records` (accelerograms),
:mod:`seispulse.newmark` (Newmark sliding on records), :mod:`seispulse.sdof` (the linear
oscillator: closed forms, responses and spectra). Errors: :mod:`seispulse.errors`; bad input
raises :class:`InvalidInputError`, a ValueError whose message names the parameter.
"""

from . import errors, newmark, pulse, records, rocking, sdof, sliding
from .errors import (ConvergenceError, FileError, InternalError, InvalidInputError,
                     NoBracketError, SeispulseError, SingularError)

__version__ = "0.1.0"

__all__ = ["pulse", "sliding", "rocking", "records", "newmark", "sdof", "errors", "SeispulseError", "InvalidInputError", "SingularError",
           "ConvergenceError", "NoBracketError", "InternalError", "FileError", "__version__"]
