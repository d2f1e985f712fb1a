#!/usr/bin/python3
"""Figures of a rupture run (called by `rupture plot DIR`; needs numpy, matplotlib, h5py).

Reads what `rupture run` wrote in DIR and writes PNGs to DIR/figures/:
  crack_tip.png         tip position and E11 speed vs time, with c_R, c_S, sqrt(2) c_S, c_D
  crack_tip_NAME.png    per interface: tip and back tip along s and their speeds
  rupture_time_NAME.png per interface: the time each node cracked along s (and, for faults,
                        the SCEC rupture time: slip rate above 1 mm/s)
  stations.png          fault stations' slip rate and slip, body stations' speed (stations/)
  tau_max_fringes.png   tau_max = (sigma_1 - sigma_2)/2 around the crack tip (SPEC E13,
                        the paper's Fig. 7 look: banded contours read like isochromatics)
  cohesive_profiles.png tangential and normal cohesive tractions and nodal forces along the
                        interface at several output times (the paper's Fig. 12)
With --compare DIR2 [DIR3 ...], crack_tip.png overlays the tip histories of every run (grid
or parameter studies), labelled by --labels or the directory names.

On a sweep directory (`rupture sweep`: DIR/summary.csv, one run per subdirectory):
  sweep_map.png         sustained speed (steady running phase) against the first varied key,
                        one line per value of the second, with c_R, c_S, sqrt(2) c_S and c_D
                        and the regime bands marked; arrested runs hollow, failed runs absent
  sweep_histories.png   the E11 speed histories of every run, one panel per value of the
                        second key, coloured by the first
With --compare SWEEP2 ..., one map of all the sweeps, one line per sweep (labelled by --labels
or the directory names) and value of the second key: the paper's map on its two meshes.
Every figure is written to a temporary name and renamed, so none is ever half-written.
"""
import argparse
import csv
import glob
import json
import math
import warnings
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return {}
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=130, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)
    print(f"figure={path}")


def length_unit(values):
    """(factor, name) that shows lengths of this size readably: mm in the laboratory, km for faults."""
    top = float(np.nanmax(np.abs(values))) if len(values) else 0.0
    if top >= 1e3:
        return 1e-3, "km"
    if top >= 1.0:
        return 1.0, "m"
    return 1e3, "mm"


def time_unit(values):
    """(factor, name) for times of this size: µs in the laboratory, s for earthquakes."""
    top = float(np.nanmax(np.abs(values))) if len(values) else 0.0
    return (1.0, "s") if top >= 1e-3 else (1e6, "µs")


def plot_stations(d, fig_dir):
    """stations.png: every fault station's slip rate and slip against time, and every body
    station's velocity (DIR/stations/*.csv)."""
    files = sorted(glob.glob(os.path.join(d, "stations", "*.csv")))
    series = [(os.path.basename(f)[:-4], read_csv(f)) for f in files]
    fault = [(n, s) for n, s in series if s and "slip_rate" in s]
    body = [(n, s) for n, s in series if s and "vx" in s]
    panels = (2 if fault else 0) + (1 if body else 0)
    if panels == 0:
        return
    fig, axes = plt.subplots(panels, 1, figsize=(7, 3.2 * panels), sharex=True, squeeze=False)
    axes = axes[:, 0]
    tf, tname = time_unit(np.concatenate([s["time"] for _, s in series]))
    k = 0
    if fault:
        for name, s in fault:
            axes[0].plot(tf * s["time"], s["slip_rate"], label=name, lw=1)
            axes[1].plot(tf * s["time"], s["slip"], label=name, lw=1)
        axes[0].set_ylabel("slip rate (m/s)")
        axes[1].set_ylabel("slip (m)")
        axes[0].legend(fontsize=7, ncol=2)
        k = 2
    if body:
        for name, s in body:
            axes[k].plot(tf * s["time"], np.hypot(s["vx"], s["vy"]), label=name, lw=1)
        axes[k].set_ylabel("particle speed (m/s)")
        axes[k].legend(fontsize=7, ncol=2)
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel(f"time ({tname})")
    fig.suptitle("stations")
    save(fig, os.path.join(fig_dir, "stations.png"))


def wave_speeds(run):
    """c_D, c_S, c_R of the first material (m/s), from run.json."""
    speeds = next(iter(run["wave_speeds"].values()))
    return speeds["dilatational"], speeds["shear"], speeds["rayleigh"]


def plot_crack_tip(dirs, labels, out):
    fig, (ax_x, ax_v) = plt.subplots(2, 1, figsize=(7.5, 7.5), sharex=True)
    c_d = c_s = c_r = None
    mach_shown = False
    for d, label in zip(dirs, labels):
        with open(os.path.join(d, "run.json")) as f:
            run = json.load(f)
        c_d, c_s, c_r = wave_speeds(run)
        tip = read_csv(os.path.join(d, "crack_tip.csv"))
        if not tip:
            continue
        t_us = 1e6 * tip["time"]
        ax_x.plot(t_us, 1e3 * tip["tip_x"], label=label)
        line, = ax_v.plot(t_us, tip["speed"], label=label)
        # The speed the measured Mach angles imply (SPEC E12), an independent check of E11.
        mach_path = os.path.join(d, "mach_angle.csv")
        mach = read_csv(mach_path) if os.path.exists(mach_path) else {}
        if mach:
            for key, marker in (("implied_speed_left", "^"), ("implied_speed_right", "v")):
                ax_v.plot(1e6 * mach["time"], mach[key], marker, color=line.get_color(), ms=5, ls="none",
                          label=f"{label}: $c_S/\\sin\\beta$ ({key.split('_')[-1]} Mach front)")
            mach_shown = True
    ax_x.set_ylabel("crack-tip position x (mm)")
    ax_x.grid(alpha=0.3)
    if len(dirs) > 1:
        ax_x.legend(fontsize=8)
    if c_d is not None:
        for value, name, style in [(c_r, "$c_R$", ":"), (c_s, "$c_S$", "--"),
                                   (math.sqrt(2.0) * c_s, r"$\sqrt{2}\,c_S$", "-."),
                                   (c_d, "$c_D$", "-")]:
            ax_v.axhline(value, color="k", lw=0.8, ls=style)
            ax_v.text(ax_v.get_xlim()[0], value, f" {name} = {value:.0f} m/s", va="bottom",
                      fontsize=8)
        ax_v.set_ylim(0, 1.1 * c_d)
        # The paper's Fig. 13a: the speed in units of c_R on the right.
        ax_r = ax_v.twinx()
        ax_r.set_ylim(0, 1.1 * c_d / c_r)
        ax_r.set_ylabel("$v / c_R$")
    ax_v.set_xlabel("time (µs)")
    ax_v.set_ylabel("crack-tip speed (m/s, 31-point fit E11)")
    ax_v.grid(alpha=0.3)
    if mach_shown:
        ax_v.legend(fontsize=7, loc="lower right")
    fig.suptitle("Crack-tip history")
    save(fig, out)


def snapshot_files(d):
    return sorted(glob.glob(os.path.join(d, "snapshots", "particles_*.h5")))


def tip_at(tip, t):
    if not tip:
        return None
    return float(np.interp(t, tip["time"], tip["tip_x"]))


def mach_line_points(reading, key, side, length):
    """The measured Mach front of one side (mach_angle.csv): from where it meets the crack line,
    back and away from the crack at angle_<key> (SPEC E12)."""
    beta = reading.get("angle_" + key)
    if beta is None or not np.isfinite(beta):
        return None
    ex, ey = reading.get("dir_x", 1.0), reading.get("dir_y", 0.0)
    nx, ny = -ey * side, ex * side
    b = math.radians(beta)
    x0 = reading["tip_x"] + reading["origin_" + key] * ex
    y0 = reading["tip_y"] + reading["origin_" + key] * ey
    r = np.array([0.0, length])
    return x0 - r * math.cos(b) * ex + r * math.sin(b) * nx, y0 - r * math.cos(b) * ey + r * math.sin(b) * ny


def plot_fringes(d, out, max_panels=4):
    import h5py

    files = snapshot_files(d)
    if not files:
        print("note: no snapshots in DIR/snapshots; tau_max_fringes.png skipped")
        return
    tip = read_csv(os.path.join(d, "crack_tip.csv"))
    mach = read_csv(os.path.join(d, "mach_angle.csv")) if os.path.exists(os.path.join(d, "mach_angle.csv")) else None
    # The latest snapshots show the running crack: take up to max_panels, evenly spread over
    # the second half of the run.
    half = files[len(files) // 2:] or files
    pick = [half[int(round(i))] for i in np.linspace(0, len(half) - 1, min(max_panels, len(half)))]
    pick = list(dict.fromkeys(pick))
    panels = []
    for path in pick:
        with h5py.File(path, "r") as h:
            pos = h["position"][:]
            tau = h["tau_max"][:]
            t = float(h.attrs["time"])
        x_tip = tip_at(tip, t)
        x, y = pos[:, 0], pos[:, 1]
        if x_tip is not None:
            window = (x > x_tip - 0.025) & (x < x_tip + 0.015) & (np.abs(y) < 0.02)
            if window.sum() > 100:
                x, y, tau = x[window], y[window], tau[window]
        # Particle values on a regular image (mean per pixel) at the finest particle spacing
        # (near the tip, on a refined grid); pixels the coarser particles leave empty take the
        # mean of their filled neighbours.
        span_x, span_y = x.max() - x.min(), y.max() - y.min()
        near = (np.abs(x - (x_tip if x_tip is not None else x.mean())) < 0.002) & (np.abs(y) < 0.002)
        box = 0.004 * 0.004 if near.sum() > 16 else span_x * span_y
        spacing = math.sqrt(max(box, 1e-30) / max(near.sum() if near.sum() > 16 else len(x), 1))
        nx = max(8, min(900, int(span_x / spacing)))
        ny = max(8, min(900, int(span_y / spacing)))
        total, xe, ye = np.histogram2d(x, y, bins=(nx, ny), weights=tau)
        count, _, _ = np.histogram2d(x, y, bins=(xe, ye))
        with np.errstate(invalid="ignore", divide="ignore"):
            image = np.where(count > 0, total / count, np.nan) / 1e6
        for _ in range(8):  # up to 8 pixels from a particle: a coarse level 16x the finest
            empty = np.isnan(image)
            if not empty.any():
                break
            padded = np.pad(image, 1, constant_values=np.nan)
            stack = np.stack([padded[1 + a:padded.shape[0] - 1 + a, 1 + b:padded.shape[1] - 1 + b]
                              for a in (-1, 0, 1) for b in (-1, 0, 1) if a or b])
            with np.errstate(invalid="ignore"), warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                fill = np.nanmean(stack, axis=0)
            image = np.where(empty, fill, image)
        panels.append((t, x_tip, xe, ye, image))
    # One colour scale across the panels (the paper's Fig. 7): the largest 99.5th percentile.
    top = max(np.nanpercentile(p[4], 99.5) for p in panels)
    levels = np.linspace(0, top, 16)
    fig, axes = plt.subplots(1, len(panels), figsize=(6.4 * len(panels), 5.4), squeeze=False)
    fig.subplots_adjust(wspace=0.25)
    for ax, (t, x_tip, xe, ye, image) in zip(axes[0], panels):
        xc, yc = 0.5 * (xe[1:] + xe[:-1]), 0.5 * (ye[1:] + ye[:-1])
        cs = ax.contourf(1e3 * xc, 1e3 * yc, image.T, levels=levels, cmap="gray_r", extend="max")
        ax.contour(1e3 * xc, 1e3 * yc, image.T, levels=levels, colors="k", linewidths=0.3)
        if x_tip is not None:
            ax.plot([1e3 * x_tip], [0.0], "r^", ms=7)
        if mach:
            k = int(np.argmin(np.abs(np.asarray(mach["time"]) - t)))
            if abs(mach["time"][k] - t) < 1e-3 * max(t, 1e-30):
                reading = {key: mach[key][k] for key in mach}
                for key, side in (("left", 1), ("right", -1)):
                    pts = mach_line_points(reading, key, side, 0.012)
                    if pts is not None:
                        ax.plot(1e3 * pts[0], 1e3 * pts[1], "r-", lw=1.2)
                        ax.annotate(f"{reading['angle_' + key]:.1f}°", (1e3 * pts[0][1], 1e3 * pts[1][1]),
                                    color="r", fontsize=9)
        ax.set_xlim(1e3 * xe[0], 1e3 * xe[-1])
        ax.set_ylim(1e3 * ye[0], 1e3 * ye[-1])
        ax.set_aspect("equal")
        ax.set_title(f"t = {1e6 * t:.2f} µs", fontsize=11)
        ax.set_xlabel("x (mm)")
    axes[0][0].set_ylabel("y (mm)")
    fig.colorbar(cs, ax=axes[0].tolist(), shrink=0.8, label=r"$\tau_{max}$ (MPa)")
    fig.suptitle(r"$\tau_{max} = (\sigma_1-\sigma_2)/2$ around the crack tip (red: tip, E10; "
                 r"red lines: measured shear Mach fronts, E12)")
    save(fig, out)


def plot_profiles(d, out, max_curves=4):
    # The first interface's profiles (interface_NNNNNN.csv; the others are NAME_NNNNNN.csv).
    files = sorted(glob.glob(os.path.join(d, "interface", "interface_*.csv")))
    if not files:
        print("note: no DIR/interface/interface_*.csv; cohesive_profiles.png skipped")
        return
    pick = [files[int(round(i))] for i in np.linspace(len(files) // 2, len(files) - 1,
                                                      min(max_curves, len(files)))]
    pick = list(dict.fromkeys(pick))
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    for path in pick:
        p = read_csv(path)
        if not p:
            continue
        label = f"t = {1e6 * p['time'][0]:.2f} µs"
        x = 1e3 * p["x"]
        axes[0][0].plot(x, p["traction_t"] / 1e6, label=label)
        axes[0][1].plot(x, p["traction_n"] / 1e6, label=label)
        axes[1][0].plot(x, p["force_x"], label=label)
        axes[1][1].plot(x, p["force_y"], label=label)
    axes[0][0].set_ylabel("tangential traction $T_t$ (MPa)")
    axes[0][1].set_ylabel("normal traction $T_n$ (MPa)")
    axes[1][0].set_ylabel("nodal cohesive force $f_x$ (N/m)")
    axes[1][1].set_ylabel("nodal cohesive force $f_y$ (N/m)")
    for ax in axes.flat:
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("x along the interface (mm)")
    axes[0][0].legend(fontsize=8)
    fig.suptitle("Cohesive tractions and nodal forces along the interface")
    save(fig, out)


def plot_interfaces(d, fig_dir):
    """Per interface (run.json "cracks", input order): crack_tip_NAME.png (tip and back tip along
    the arc length s, and their E11 speeds against every material's c_R, c_S, c_D) and
    rupture_time_NAME.png (when each node cracked along s: the rupture-time profile)."""
    with open(os.path.join(d, "run.json")) as f:
        run = json.load(f)
    for crack in run.get("cracks", []):
        name = crack["interface"]
        tip = read_csv(os.path.join(d, f"crack_tip_{name}.csv"))
        if tip:
            fig, (ax_s, ax_v) = plt.subplots(2, 1, figsize=(7, 7.5), sharex=True)
            t_us = 1e6 * tip["time"]
            ax_s.plot(t_us, 1e3 * tip["tip_s"], label="tip")
            ax_s.plot(t_us, 1e3 * tip["back_s"], label="back tip", ls="--")
            ax_s.set_ylabel("position along the interface s (mm)")
            ax_s.legend(fontsize=8)
            ax_s.grid(alpha=0.3)
            ax_v.plot(t_us, tip["speed"], label="tip")
            ax_v.plot(t_us, tip["back_speed"], label="back tip", ls="--")
            top = 0.0
            for material, w in run["wave_speeds"].items():
                for value, label, style in [(w["rayleigh"], "$c_R$", ":"), (w["shear"], "$c_S$", "--"),
                                            (w["dilatational"], "$c_D$", "-")]:
                    ax_v.axhline(value, color="k", lw=0.7, ls=style)
                    ax_v.text(ax_v.get_xlim()[0], value, f" {label} {material} = {value:.0f} m/s",
                              va="bottom", fontsize=7)
                top = max(top, w["dilatational"])
            ax_v.set_ylim(0, 1.1 * top)
            ax_v.set_xlabel("time (µs)")
            ax_v.set_ylabel("speed along the interface (m/s, E11)")
            ax_v.grid(alpha=0.3)
            fig.suptitle(f"interface {name}: {crack.get('upper_body', '')} / {crack.get('lower_body', '')}")
            save(fig, os.path.join(fig_dir, f"crack_tip_{name}.png"))
        times = read_csv(os.path.join(d, f"rupture_time_{name}.csv"))
        if times:
            cracked = times["crack_time"] >= 0
            lf, lname = length_unit(times["s"])
            tf, tname = time_unit(np.concatenate([times["crack_time"], times.get("rupture_time", [])]))
            fig, ax = plt.subplots(figsize=(7, 4))
            ax.plot(lf * times["s"][cracked], tf * times["crack_time"][cracked], ".", ms=2,
                    label="cracked (the law's criterion; on a fault, slip = Dc)")
            if "rupture_time" in times:
                ruptured = times["rupture_time"] >= 0
                ax.plot(lf * times["s"][ruptured], tf * times["rupture_time"][ruptured], ".", ms=2,
                        label="ruptured (slip rate > rupture_slip_rate)")
                ax.legend(fontsize=7)
            ax.set_xlabel(f"position along the interface s ({lname})")
            ax.set_ylabel(f"time ({tname})")
            ax.set_title(f"interface {name}: rupture-time profile ({int(cracked.sum())} of {len(cracked)} nodes cracked)")
            ax.grid(alpha=0.3)
            save(fig, os.path.join(fig_dir, f"rupture_time_{name}.png"))


def sweep_table(d):
    """The rows of DIR/summary.csv and the varied keys (the columns between run and status)."""
    with open(os.path.join(d, "summary.csv"), newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        cols = reader.fieldnames
    keys = cols[1:cols.index("status")]
    return rows, keys


def as_number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def plot_sweep(sweeps, fig_dir):
    """The map and the speed histories of one or more sweeps, sweeps = [(label, dir)]. One line
    per value of the second varied key; with several sweeps (the paper's map on two meshes), one
    line per sweep and value."""
    rows, done = [], []
    for label, d in sweeps:
        table, keys = sweep_table(d)
        rows += table
        for r in table:
            if r["status"] == "completed":
                r = dict(r, _dir=d, _sweep=label)
                done.append((keys, r))
    if not done:
        print("note: no completed run in the sweep; no figures")
        return
    run = json.load(open(os.path.join(done[0][1]["_dir"], done[0][1]["run"], "run.json")))
    c_d, c_s, c_r = wave_speeds(run)
    first = done[0][0][0]
    groups = {}
    for keys, r in done:
        second = keys[1] if len(keys) > 1 else None
        parts = ([r["_sweep"]] if len(sweeps) > 1 else []) + ([f"{second} = {r[second]}"] if second else [])
        groups.setdefault(", ".join(parts), []).append(r)
    # The map (the paper's Fig. 13 look).
    fig, ax = plt.subplots(figsize=(8, 5.5))
    xs = [as_number(r[first]) for _, r in done]
    for label, members in groups.items():
        members.sort(key=lambda r: as_number(r[first]))
        x = [as_number(r[first]) for r in members]
        v = [as_number(r["sustained_speed_m_per_s"]) for r in members]
        line, = ax.plot(x, v, "-", label=label or None)
        for xi, vi, r in zip(x, v, members):
            hollow = r["arrested"] == "true"
            ax.plot(xi, vi, "o", color=line.get_color(), mfc="none" if hollow else line.get_color())
    lo, hi = min(xs), max(xs)
    bands = [(0, c_r, "sub-Rayleigh", "#e8f0ff"), (c_r, c_s, "Rayleigh-to-shear", "#fff0e0"),
             (c_s, c_d, "intersonic", "#e8ffe8"), (c_d, 1.15 * c_d, "supersonic", "#ffe8e8")]
    for a, b, name, colour in bands:
        ax.axhspan(a, b, color=colour, zorder=0)
        ax.text(hi, 0.5 * (a + b), name, ha="right", va="center", fontsize=8, color="0.4")
    for value, name in ((c_r, "$c_R$"), (c_s, "$c_S$"), (math.sqrt(2) * c_s, r"$\sqrt{2}c_S$"), (c_d, "$c_D$")):
        ax.axhline(value, color="0.5", lw=0.8, ls="--")
        ax.text(lo, value, " " + name, va="bottom", fontsize=9, color="0.3")
    ax.set_ylim(0, 1.1 * c_d)
    ax.set_xlabel(first)
    ax.set_ylabel("sustained speed, steady running phase (m/s)")
    ax.set_title(f"{len(done)} of {len(rows)} runs completed (hollow: arrested)")
    if any(groups):  # below the c_D label
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(0.0, 0.88))
    ax.grid(alpha=0.3)
    save(fig, os.path.join(fig_dir, "sweep_map.png"))
    # Speed histories per group.
    n = len(groups)
    fig, axes = plt.subplots(n, 1, figsize=(8, 3.2 * n), squeeze=False, sharex=True)
    cmap = plt.get_cmap("viridis")
    for ax, (label, members) in zip(axes[:, 0], groups.items()):
        for k, r in enumerate(members):
            tip = read_csv(os.path.join(r["_dir"], r["run"], "crack_tip.csv"))
            if not tip:
                continue
            colour = cmap(k / max(1, len(members) - 1))
            ax.plot(1e6 * tip["time"], tip["speed"], color=colour, lw=1, label=f"{first} = {r[first]}")
        for value in (c_r, c_s, math.sqrt(2) * c_s, c_d):
            ax.axhline(value, color="0.5", lw=0.8, ls="--")
        ax.set_ylabel("E11 speed (m/s)")
        ax.set_ylim(0, 1.1 * c_d)
        ax.set_title(label or "all runs", fontsize=9)
        ax.legend(fontsize=7, ncol=2)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time (µs)")
    save(fig, os.path.join(fig_dir, "sweep_histories.png"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("dir", help="run directory written by `rupture run`, or a sweep directory")
    ap.add_argument("--compare", nargs="*", default=[],
                    help="more run directories to overlay (or, for a sweep, more sweeps: one map)")
    ap.add_argument("--labels", nargs="*", default=None, help="legend labels, one per run")
    args = ap.parse_args()
    sweep = os.path.isfile(os.path.join(args.dir, "summary.csv")) and not os.path.isfile(
        os.path.join(args.dir, "run.json"))
    dirs = [args.dir] + list(args.compare)
    need, what = ("summary.csv", "a rupture sweep directory") if sweep else (
        "run.json", "a finished rupture run directory")
    for d in dirs:
        if not os.path.isfile(os.path.join(d, need)):
            sys.exit(f"error: '{d}' has no {need}: not {what}")
    labels = args.labels if args.labels else [os.path.basename(os.path.normpath(d)) for d in dirs]
    if len(labels) != len(dirs):
        sys.exit(f"error: --labels has {len(labels)} entries for {len(dirs)} {'sweeps' if sweep else 'runs'}")
    fig_dir = os.path.join(args.dir, "figures")
    os.makedirs(fig_dir, exist_ok=True)
    if sweep:
        plot_sweep(list(zip(labels, dirs)), fig_dir)
        return
    plot_crack_tip(dirs, labels, os.path.join(fig_dir, "crack_tip.png"))
    plot_fringes(args.dir, os.path.join(fig_dir, "tau_max_fringes.png"))
    plot_profiles(args.dir, os.path.join(fig_dir, "cohesive_profiles.png"))
    plot_interfaces(args.dir, fig_dir)
    plot_stations(args.dir, fig_dir)


if __name__ == "__main__":
    main()
