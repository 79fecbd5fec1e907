"""Closed forms of the linear oscillator (issue 6, placeholder)."""
