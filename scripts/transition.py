#!/usr/bin/env python3
"""What the interface shows around the sub-Rayleigh -> intersonic transition (issue 14, theory §6).

Usage: /usr/bin/python3 scripts/transition.py RUN_DIR... [--from T_US] [--profiles]

For each run directory (a `rupture run` with output.interface_interval set) prints one table row:
initiation time, the first times the E11 speed (crack_tip.csv) passes c_R and c_S, the most
separated stretches at any crack sample (crack_tip.csv `stretches`, sampled every
output.crack_sample_interval; in brackets, counted apart only across an intact ligament of one
grid cell h, as the summary's daughter crack), and the most maxima of the shear traction |T_t| ahead of the tip
(uncracked points beyond the leading tip, arc length s) in any interface profile from T_US
(default 10.0 us). A maximum counts when it exceeds 2 MPa and stands out by a prominence of
1 MPa. A daughter crack needs a second maximum ahead of the cohesive peak that reaches the
shear strength, so the largest second maximum seen (its traction, time and distance ahead of the
tip) is printed too: on coarse grids the node-to-node kinks of the profile give small ones. With --profiles, every profile's tip, peak
traction and its distance ahead of the tip, and |T_t| at 0.5, 1, 2 and 3 mm ahead.
"""
import glob
import sys

import numpy as np
from scipy.signal import find_peaks

from stretches import fronts_by_time, rupture  # stretches puts the package on the path

HEIGHT = 2e6       # Pa: a maximum to count
PROMINENCE = 1e6   # Pa: how far it must stand above the dips either side


def first_time_above(t, v, level):
    i = np.flatnonzero(np.nan_to_num(v, nan=-1.0) > level)
    return t[i[0]] if i.size else float("nan")


def profile_maxima(path):
    """(time, tip s, [(s ahead of tip, |T_t|) of each maximum], |T_t| ahead(s) function)."""
    rows = rupture.read_table(path)
    t = float(rows["time"][0])
    s = rows["s"]
    tt = np.abs(rows["traction_t"])
    cracked = rows["cracked"].astype(int)
    idx = np.flatnonzero(cracked)
    tip = s[idx[-1]] if idx.size else s[0]
    ahead = s > tip
    sa, ta = s[ahead] - tip, tt[ahead]
    peaks, _ = find_peaks(np.concatenate(([0.0], ta, [0.0])), height=HEIGHT, prominence=PROMINENCE)
    peaks -= 1
    return t, tip, [(sa[p], ta[p]) for p in peaks], (lambda d: float(np.interp(d, sa, ta)))


def main(argv):
    t_from = 10.0e-6
    show = "--profiles" in argv
    dirs = []
    i = 0
    while i < len(argv):
        if argv[i] == "--from":
            t_from = float(argv[i + 1]) * 1e-6
            i += 2
            continue
        if argv[i] != "--profiles":
            dirs.append(argv[i])
        i += 1
    print("| run | initiation (us) | E11 past c_R (us) | past c_S (us) | most separated stretches (apart by >= h) "
          "| most traction maxima > 2 MPa ahead | largest second maximum (MPa, at us, mm ahead) | profiles |")
    print("|---|---|---|---|---|---|---|---|")
    details = []
    for d in dirs:
        try:
            run = rupture.open_run(d).record
        except OSError:
            print(f"| {d} | (no run.json) |")
            continue
        speeds = next(iter(run["wave_speeds"].values()))
        tips = rupture.open_run(d).crack_tip()
        t, v = tips["time"], tips["speed"]
        stretches = int(tips["stretches"].max())
        fronts = max(fronts_by_time(d, run["input"]["grid"]["cell_size"]).values(), default=0)
        most, count, second = 0, 0, (0.0, float("nan"), float("nan"))
        for path in sorted(glob.glob(f"{d}/interface/interface_*.csv")):
            tp, tip, peaks, at = profile_maxima(path)
            if tp < t_from - 1e-12:
                continue
            count += 1
            most = max(most, len(peaks))
            for s_ahead, value in sorted(peaks, key=lambda p: -p[1])[1:2]:
                if value > second[0]:
                    second = (value, tp, s_ahead)
            if show:
                first = peaks[0] if peaks else (float("nan"), float("nan"))
                details.append(f"{d} t={1e6 * tp:.3f} us tip={1e3 * tip:.3f} mm maxima={len(peaks)} "
                               f"first={first[1] / 1e6:.1f} MPa at {1e3 * first[0]:.3f} mm ahead; |T_t| at "
                               f"0.5/1/2/3 mm ahead: " + ", ".join(f"{at(x) / 1e6:.1f}" for x in
                                                                   (0.5e-3, 1e-3, 2e-3, 3e-3)) + " MPa")
        init = run["crack"]["initiation_time"]
        print(f"| {d.rstrip('/').split('/')[-1]} | {1e6 * init:.3f} | "
              f"{1e6 * first_time_above(t, v, speeds['rayleigh']):.2f} | "
              f"{1e6 * first_time_above(t, v, speeds['shear']):.2f} | {stretches} ({fronts}) | {most} | "
              f"{second[0] / 1e6:.1f} ({1e6 * second[1]:.2f}, {1e3 * second[2]:.2f}) | {count} |")
    for line in details:
        print(line)


if __name__ == "__main__":
    main(sys.argv[1:])
