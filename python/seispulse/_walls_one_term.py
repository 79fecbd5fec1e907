"""Placeholder (issue 7): one-term solution, reached as seispulse.walls.<name>."""
__all__ = []
