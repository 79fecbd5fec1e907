"""seispulse: closed-form and exact numerical answers for idealized near-fault
pulses and accelerograms.

Modules: :mod:`seispulse.pulse` (pulses), :mod:`seispulse.sliding` (sliding blocks), :mod:`seispulse.rocking` (rocking blocks). Errors: :mod:`seispulse.errors`; bad input
raises :class:`InvalidInputError`, a ValueError whose message names the parameter.
"""

from . import errors, pulse, rocking, sliding
from .errors import (ConvergenceError, InternalError, InvalidInputError, NoBracketError,
                     SeispulseError, SingularError)

__version__ = "0.1.0"

__all__ = ["pulse", "sliding", "rocking", "errors", "SeispulseError", "InvalidInputError", "SingularError",
           "ConvergenceError", "NoBracketError", "InternalError", "__version__"]
