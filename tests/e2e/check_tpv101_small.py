#!/usr/bin/python3
"""TPV101-2D in small (ctest): examples/tpv101_2d.toml at 200 m and 100 m to 4 s, 10 km off
the fault (the rupture times to 4 s do not change from 10 to 20 km: docs/faults.md), against
the uguca reference (tests/data/validation/tpv101-2d-uguca, 50 m). Checks what could fail if
the rate-and-state fault were wrong:
  - the rupture nucleates as the reference's: at x = 0 inside its bracket + 0.05 s;
  - the rupture is bilateral and symmetric: the rupture times at -x and +x equal to within one
    time step, for x = 2.5, 5 km;
  - the rupture times approach the reference with the grid and meet the issue's criterion at
    100 m: at 2.5, 5 and 7.5 km the 100 m run is no farther from the reference's bracket than
    the 200 m run, and within 0.05 s of it.
    check_tpv101_small.py RUN_200 RUN_100 REF_DIR
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from tpv101_compare import compare, read_csv  # noqa: E402


def rupture_at(run, x):
    rt = read_csv(os.path.join(run, "rupture_time_fault.csv"))
    xs, ts = rt["x"], rt["rupture_time"]
    for i in range(1, len(xs)):
        if xs[i] >= x:
            f = (x - xs[i - 1]) / (xs[i] - xs[i - 1])
            return ts[i - 1] + f * (ts[i] - ts[i - 1])
    return -1.0


def main():
    coarse, fine, ref = sys.argv[1:4]
    rc = {r[0]: r for r in compare(coarse, ref, "50m", 4.0)}
    rf = {r[0]: r for r in compare(fine, ref, "50m", 4.0)}
    failures = []
    for km in (0.0, 2.5, 5.0, 7.5):
        print(f"x = {km} km: 200 m {rc[km][1]:.3f} s (gap {rc[km][4]:.3f}), 100 m {rf[km][1]:.3f} s "
              f"(gap {rf[km][4]:.3f}), reference {rf[km][2]:.3f}-{rf[km][3]:.3f} s")
    if rf[0.0][4] > 0.05:
        failures.append("100 m: nucleation at x = 0 outside the reference bracket + 0.05 s")
    for km in (2.5, 5.0, 7.5):
        if rf[km][4] > rc[km][4] or rf[km][4] > 0.05:
            failures.append(f"x = {km} km: no convergence to the reference (gap 200 m {rc[km][4]:.3f}, 100 m {rf[km][4]:.3f} s)")
    dt = 0.4 * 100.0 / 6000.0  # a step at 100 m (cfl 0.4, c_P)
    for km in (2.5, 5.0):
        tm, tp = rupture_at(fine, -km * 1000.0), rupture_at(fine, km * 1000.0)
        print(f"symmetry at {km} km: {tm:.4f} / {tp:.4f} s")
        if tm < 0 or abs(tm - tp) > dt:
            failures.append(f"x = +-{km} km: rupture times {tm:.4f} and {tp:.4f} s differ by more than a step")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
