"""Linear oscillator: closed forms, response histories and spectra (issue 6, placeholder)."""
