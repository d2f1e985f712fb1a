#!/usr/bin/env python3
"""The crack-speed map (the paper's Fig. 13) as one table from `rupture sweep` directories.

Usage: /usr/bin/python3 scripts/map_table.py SWEEP_DIR...

Each SWEEP_DIR holds a summary.csv whose runs vary boundary.impact.velocity; the finest cell
size is read from each run's run.json. One row per run, sorted by impact speed: regime, sustained
speed (m/s, and in c_R and c_S), the first time the E11 speed passes c_S, the daughter-crack time,
the Mach angle with the speed it implies (theory E12), arrest, and the run's status. Times in us;
"-" where the crack never did it. The daughter-crack time is recomputed from crack_stretches.csv
with the summary's rule (a second stretch beyond an intact ligament of one grid cell), so runs
summarised before that rule read the same.
"""
import sys

from stretches import daughter_time, rupture  # stretches puts the package on the path


def us(value):
    t = float(value)
    return f"{1e6 * t:.2f}" if t >= 0 else "-"


def main(dirs):
    rows = []
    for d in dirs:
        sweep = rupture.open_run(d)
        for k in range(len(sweep)):
            r = sweep.row(k)
            h = float("nan")
            try:
                h = rupture.open_run(f"{d}/{r['run']}").case["grid"]["cell_size"]
                r["daughter_crack_time_s"] = str(daughter_time(f"{d}/{r['run']}", h))
            except (OSError, KeyError):
                pass
            rows.append((float(r["boundary.impact.velocity"]), h, r))
    rows.sort(key=lambda x: (x[0], x[1]))
    print("| V (m/s) | finest h (um) | regime | sustained (m/s) | /c_R | /c_S | steady window (us) "
          "| first > c_S (us) | daughter crack (us) | Mach angle (deg) | Mach speed (m/s) | status |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for v, h, r in rows:
        if r["status"] != "completed":
            print(f"| {v:g} | {1e6 * h:g} | | | | | | | | | | {r['status']} {r.get('message', '')} |")
            continue
        regime = r["regime"] + (f", arrested at s = {1e3 * float(r['arrest_s_m']):.2f} mm"
                                if r["arrested"] == "true" else "")
        mach = float(r["mach_angle_deg"])
        angle = f"{mach:.1f}" if mach > 0 else "-"
        implied = f"{float(r['mach_speed_m_per_s']):.0f}" if mach > 0 else "-"
        print(f"| {v:g} | {1e6 * h:g} | {regime} | {float(r['sustained_speed_m_per_s']):.0f} | "
              f"{float(r['sustained_over_cR']):.3f} | {float(r['sustained_over_cS']):.3f} | "
              f"{us(r['steady_begin_s'])}-{us(r['steady_end_s'])} | {us(r['intersonic_time_s'])} | "
              f"{us(r['daughter_crack_time_s'])} | "
              f"{angle} | {implied} | {r['status']} |")


if __name__ == "__main__":
    main(sys.argv[1:])
