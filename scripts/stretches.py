"""Separated stretches of a run (crack_stretches.csv), grouped as the summary groups them: two
stretches are apart (a daughter crack ahead of the main one) only across an intact ligament of
at least one grid cell (cohesive/crack_tip.hpp); closer ones are one front."""
import csv
from collections import defaultdict


def fronts_by_time(run_dir, ligament, name=""):
    """{time: number of fronts}, fronts = stretches merged across ligaments shorter than `ligament`."""
    spans = defaultdict(list)
    with open(f"{run_dir}/crack_stretches{name}.csv") as f:
        for r in csv.DictReader(f):
            spans[float(r["time"])].append((float(r["s_begin"]), float(r["s_end"])))
    fronts = {}
    for t, s in spans.items():
        s.sort()
        fronts[t] = 1 + sum(1 for a, b in zip(s, s[1:]) if b[0] - a[1] >= ligament)
    return fronts


def daughter_time(run_dir, ligament, name=""):
    """First time with two fronts (-1: never), s."""
    times = [t for t, n in fronts_by_time(run_dir, ligament, name).items() if n >= 2]
    return min(times) if times else -1.0
