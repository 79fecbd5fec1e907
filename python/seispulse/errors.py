"""Exceptions raised by seispulse.

Every error the Fortran library reports as a status becomes one of these. Bad input
raises :class:`InvalidInputError`, a :class:`ValueError`, whose message starts with
the parameter's name and states the allowed range.
"""

from . import _fortran_codes as _f


class SeispulseError(Exception):
    """Base class of every seispulse error."""


class InvalidInputError(SeispulseError, ValueError):
    """An argument is outside its domain (NaN, wrong sign, unknown name, bad shape)."""


class SingularError(SeispulseError, ArithmeticError):
    """A matrix or system is singular."""


class ConvergenceError(SeispulseError, RuntimeError):
    """An iteration reached its limit before converging."""


class NoBracketError(SeispulseError, ValueError):
    """A root finder was given an interval without a sign change."""


class InternalError(SeispulseError, RuntimeError):
    """A bug in seispulse: please report it with the input that caused it."""


class FileError(SeispulseError, OSError):
    """A file cannot be opened or read (missing, unreadable). A file that opens but
    does not hold what its format promises raises InvalidInputError instead."""


class NoSolutionError(SeispulseError, ValueError):
    """The data are valid but the problem has no solution, e.g. a Mononobe-Okabe
    backfill steeper than phi - theta (the soil wedge cannot be in equilibrium)."""


#: Fortran status code (module seispulse_errors) -> exception class.
STATUS_ERRORS = {
    _f.SEISPULSE_INVALID_INPUT: InvalidInputError,
    _f.SEISPULSE_SINGULAR: SingularError,
    _f.SEISPULSE_NO_CONVERGENCE: ConvergenceError,
    _f.SEISPULSE_NO_BRACKET: NoBracketError,
    _f.SEISPULSE_INTERNAL: InternalError,
    _f.SEISPULSE_IO: FileError,
    _f.SEISPULSE_NO_SOLUTION: NoSolutionError,
}
