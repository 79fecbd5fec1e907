"""Placeholder (issue 7): Veletsos-Younan series, reached as seispulse.walls.<name>."""
__all__ = []
