"""Elastodynamic seismic earth pressures on retaining walls (walls.md, seed 004).

Placeholder docstring (issue 7).
"""
from . import _walls_one_term, _walls_vy
from ._walls_one_term import *  # noqa: F401,F403
from ._walls_vy import *  # noqa: F401,F403

__all__ = list(_walls_vy.__all__) + list(_walls_one_term.__all__)
