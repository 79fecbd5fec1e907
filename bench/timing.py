"""Timing helper shared by the benchmark scripts of this folder (run as
`python3 bench/<name>.py`, which puts this folder on sys.path)."""
import statistics
import time


def median_time(fn, runs, inner=1):
    """Median over `runs` runs of the wall time of one call fn() (s); each run times `inner`
    calls in a row and divides by `inner`."""
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        for _ in range(inner):
            fn()
        times.append((time.perf_counter() - t0) / inner)
    return statistics.median(times)
