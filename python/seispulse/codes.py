"""Placeholder (issue 7): EN 1998 seismic earth-pressure checks and spectra."""
__all__ = []
