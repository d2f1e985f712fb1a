"""Separated stretches of a run (crack_stretches.csv), grouped as the summary groups them: two
stretches are apart (a daughter crack ahead of the main one) only across an intact ligament of
at least one grid cell (cohesive/crack_tip.hpp); closer ones are one front."""
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import rupture  # noqa: E402  (the package's readers: one reader per file, python/rupture)


def fronts_by_time(run_dir, ligament, name=""):
    """{time: number of fronts}, fronts = stretches merged across ligaments shorter than `ligament`."""
    spans = defaultdict(list)
    table = rupture.open_run(run_dir).table(f"crack_stretches{name}.csv")
    for t, a, b in zip(table["time"], table["s_begin"], table["s_end"]):
        spans[float(t)].append((float(a), float(b)))
    fronts = {}
    for t, s in spans.items():
        s.sort()
        fronts[t] = 1 + sum(1 for a, b in zip(s, s[1:]) if b[0] - a[1] >= ligament)
    return fronts


def daughter_time(run_dir, ligament, name=""):
    """First time with two fronts (-1: never), s."""
    times = [t for t, n in fronts_by_time(run_dir, ligament, name).items() if n >= 2]
    return min(times) if times else -1.0
