"""Figures of a rupture run (`rupture plot DIR`, or `python3 -m rupture.plot DIR`; needs numpy,
matplotlib, h5py).

Reads what `rupture run` wrote in DIR through the package's readers (rupture.open_run: one
reader per file) and writes PNGs to DIR/figures/:
  crack_tip.png         tip position and E11 speed vs time, with c_R, c_S, sqrt(2) c_S, c_D
                        (of the first interface's lower material; the upper one's too where
                        it differs)
  crack_tip_NAME.png    per interface: tip and back tip along s and their speeds
  rupture_time_NAME.png per interface: the time each node cracked along s (and, for faults,
                        the SCEC rupture time: slip rate above 1 mm/s)
  stations.png          fault stations' slip rate and slip, body stations' speed (stations/)
  tau_max_fringes.png   tau_max = (sigma_1 - sigma_2)/2 around the running crack tip (SPEC
                        E13, the paper's Fig. 7 look: banded contours read like isochromatics),
                        drawn where the particles are (their own extent: holes stay holes),
                        every running tip marked where it is, and the path of every crack
                        that grows (crack_path_NAME.csv) as far as it had grown then
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
Units follow the run's scale (Scale: mm and µs in the laboratory, km, s and km/s for faults).
Every figure is written to a temporary name and renamed, so none is ever half-written.
"""
import argparse
import math
import os
import sys
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .runs import Run, Sweep  # noqa: E402


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=130, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)
    print(f"figure={path}")


# ---- units by scale ---------------------------------------------------------------------------

def length_unit(size):
    """(factor, name) that shows lengths of this size (m) readably: mm in the laboratory, km
    for faults."""
    if size >= 1e3:
        return 1e-3, "km"
    if size >= 1.0:
        return 1.0, "m"
    return 1e3, "mm"


def time_unit(duration):
    """(factor, name) for times of this size (s): µs for a laboratory run, s for an earthquake."""
    if duration >= 0.1:
        return 1.0, "s"
    if duration >= 1e-3:
        return 1e3, "ms"
    return 1e6, "µs"


class Scale:
    """The units a run's figures use: lengths from the domain's size, times from the time a
    shear wave takes to cross it (so a short run of a fault case is still drawn in s), speeds in
    km/s where lengths are in km (faults), m/s otherwise."""

    def __init__(self, size, duration):
        self.lf, self.lname = length_unit(size)
        self.tf, self.tname = time_unit(duration)
        self.vf, self.vname = (1e-3, "km/s") if self.lname == "km" else (1.0, "m/s")
        self.size = size

    def time_label(self, t):
        return f"t = {self.tf * t:.{2 if self.tname != 's' else 3}f} {self.tname}"


def scale_of(run):
    grid = run.case.get("grid", {})
    try:
        size = max(float(b) - float(a) for a, b in zip(grid["min"], grid["max"]))
    except (KeyError, TypeError, ValueError):
        size = 0.1
    shear = [w["shear"] for w in run.record.get("wave_speeds", {}).values() if w.get("shear")]
    duration = size / min(shear) if shear else float(run.record.get("end_time") or 1e-4)
    return Scale(size, duration)


# ---- readers over the package -----------------------------------------------------------------

def optional_table(run, name):
    """run.table(name), or None where the run wrote no such file (or an empty one)."""
    if not os.path.exists(os.path.join(run.dir, name)):
        return None
    table = run.table(name)
    return table if len(table) else None


def material_speeds(run, material):
    """(c_D, c_S, c_R) of a material (m/s), from run.json."""
    w = run.record["wave_speeds"][material]
    return w["dilatational"], w["shear"], w["rayleigh"]


def interface_materials(run, k=0):
    """(upper, lower) material names of interface k (the first material where the run has no
    interface)."""
    first = next(iter(run.record["wave_speeds"]))
    cracks = run.record.get("cracks") or []
    if k >= len(cracks):
        return first, first
    bodies = run.case.get("bodies", {})

    def material(side):
        return bodies.get(cracks[k].get(side + "_body", ""), {}).get("material", first)

    return material("upper"), material("lower")


def label_lines(ax, lines, fontsize=8):
    """Horizontal reference lines [(value, text, style, colour)], their labels alternating
    between the left and the right end so that close values (c_R and c_S) do not overlap."""
    x0, x1 = ax.get_xlim()
    for k, (value, text, style, colour) in enumerate(sorted(lines, key=lambda e: e[0])):
        ax.axhline(value, color=colour, lw=0.8, ls=style)
        left = k % 2 == 0
        ax.text(x0 if left else x1, value, f" {text} " if left else f"{text} ", va="bottom",
                ha="left" if left else "right", fontsize=fontsize, color=colour)


# ---- figures of one run -------------------------------------------------------------------------

def plot_stations(run, fig_dir):
    """stations.png: every fault station's slip rate and slip against time, and every body
    station's velocity (DIR/stations/*.csv)."""
    series = [(n, s) for n, s in run.stations.items() if len(s)]
    fault = [(n, s) for n, s in series if "slip_rate" in s]
    body = [(n, s) for n, s in series if "vx" in s]
    panels = (2 if fault else 0) + (1 if body else 0)
    if panels == 0:
        return
    sc = scale_of(run)
    fig, axes = plt.subplots(panels, 1, figsize=(7, 3.2 * panels), sharex=True, squeeze=False)
    axes = axes[:, 0]
    k = 0
    if fault:
        for name, s in fault:
            axes[0].plot(sc.tf * s["time"], s["slip_rate"], label=name, lw=1)
            axes[1].plot(sc.tf * s["time"], s["slip"], label=name, lw=1)
        axes[0].set_ylabel("slip rate (m/s)")
        axes[1].set_ylabel("slip (m)")
        axes[0].legend(fontsize=7, ncol=2)
        k = 2
    if body:
        for name, s in body:
            axes[k].plot(sc.tf * s["time"], np.hypot(s["vx"], s["vy"]), label=name, lw=1)
        axes[k].set_ylabel("particle speed (m/s)")
        axes[k].legend(fontsize=7, ncol=2)
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel(f"time ({sc.tname})")
    fig.suptitle("stations")
    save(fig, os.path.join(fig_dir, "stations.png"))


def plot_crack_tip(runs, labels, out):
    fig, (ax_x, ax_v) = plt.subplots(2, 1, figsize=(7.5, 7.5), sharex=True)
    sc = scale_of(runs[0])
    speeds = None
    mach_shown = False
    for run, label in zip(runs, labels):
        upper, lower = interface_materials(run)
        speeds = (material_speeds(run, lower), lower, material_speeds(run, upper), upper)
        tip = optional_table(run, "crack_tip.csv")
        if tip is None:
            continue
        t = sc.tf * tip["time"]
        ax_x.plot(t, sc.lf * tip["tip_x"], label=label)
        line, = ax_v.plot(t, sc.vf * tip["speed"], label=label)
        # The speed the measured Mach angles imply (theory E12), an independent check of E11.
        mach = optional_table(run, "mach_angle.csv")
        if mach is not None:
            for key, marker in (("implied_speed_left", "^"), ("implied_speed_right", "v")):
                ax_v.plot(sc.tf * mach["time"], sc.vf * mach[key], marker, color=line.get_color(), ms=5,
                          ls="none", label=f"{label}: $c_S/\\sin\\beta$ ({key.split('_')[-1]} Mach front)")
            mach_shown = True
    ax_x.set_ylabel(f"crack-tip position x ({sc.lname})")
    ax_x.grid(alpha=0.3)
    if len(runs) > 1:
        ax_x.legend(fontsize=8)
    if speeds is not None:
        (c_d, c_s, c_r), lower, (u_d, u_s, u_r), upper = speeds
        both = upper != lower
        tag = f" ({lower})" if both else ""
        lines = [(sc.vf * v, f"{name}{tag} = {sc.vf * v:.{3 if sc.vf < 1 else 0}f} {sc.vname}", style, "k")
                 for v, name, style in [(c_r, "$c_R$", ":"), (c_s, "$c_S$", "--"),
                                        (math.sqrt(2.0) * c_s, r"$\sqrt{2}\,c_S$", "-."), (c_d, "$c_D$", "-")]]
        if both:  # a bimaterial interface: the other side's speeds, named
            lines += [(sc.vf * v, f"{name} ({upper}) = {sc.vf * v:.{3 if sc.vf < 1 else 0}f} {sc.vname}",
                       style, "0.45") for v, name, style in [(u_r, "$c_R$", ":"), (u_s, "$c_S$", "--"),
                                                               (u_d, "$c_D$", "-")]]
        label_lines(ax_v, lines, fontsize=7 if both else 8)
        top = 1.1 * max(c_d, u_d if both else c_d)
        ax_v.set_ylim(0, sc.vf * top)
        # The paper's Fig. 13a: the speed in units of c_R on the right (crack_tip.csv's
        # speed_over_cR: the lower body's material).
        ax_r = ax_v.twinx()
        ax_r.set_ylim(0, top / c_r)
        ax_r.set_ylabel(f"$v / c_R$ ({lower})" if both else "$v / c_R$")
    ax_v.set_xlabel(f"time ({sc.tname})")
    ax_v.set_ylabel(f"crack-tip speed ({sc.vname}, 31-point fit E11)")
    ax_v.grid(alpha=0.3)
    if mach_shown:
        ax_v.legend(fontsize=7, loc="lower right")
    fig.suptitle("Crack-tip history")
    save(fig, out)


def mach_line_points(reading, key, side, length):
    """The measured Mach front of one side (mach_angle.csv): from where it meets the crack line,
    back and away from the crack at angle_<key> (theory E12)."""
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


def tip_tracks(run):
    """Every interface's tip track [(name, Table with time, tip_x, tip_y, stretches)], input
    order; the first interface's from crack_tip.csv where it wrote no crack_tip_NAME.csv."""
    tracks = []
    for k, crack in enumerate(run.record.get("cracks") or []):
        name = crack.get("interface", "")
        tip = optional_table(run, f"crack_tip_{name}.csv")
        if tip is None and k == 0:
            tip = optional_table(run, "crack_tip.csv")
        if tip is not None:
            tracks.append((name, tip))
    if not tracks:
        tip = optional_table(run, "crack_tip.csv")
        if tip is not None:
            tracks.append(("", tip))
    return tracks


def tip_at(tip, t):
    """(x, y, running, direction) of a tip track at time t: running once the interface has a
    separated stretch; the direction from the tip's last move (+x before it moves)."""
    time = tip["time"]
    x = float(np.interp(t, time, tip["tip_x"]))
    y = float(np.interp(t, time, tip["tip_y"])) if "tip_y" in tip else 0.0
    before = time <= t
    running = bool(before.any() and "stretches" in tip and tip["stretches"][before][-1] > 0)
    d = np.array([1.0, 0.0])
    if before.sum() >= 2:
        xs = tip["tip_x"][before]
        ys = tip["tip_y"][before] if "tip_y" in tip else np.zeros_like(xs)
        moved = np.hypot(xs - xs[-1], ys - ys[-1]) > 0
        if moved.any():
            j = np.nonzero(moved)[0][-1]
            step = np.array([xs[-1] - xs[j], ys[-1] - ys[j]])
            d = step / np.linalg.norm(step)
    return x, y, running, d


def crack_paths(run):
    """The paths of the cracks that grow: {name: [(times, xs, ys) per grown end]}, each end's
    vertices in the order they were made (time 0 for the drawn line's end vertex), in reference
    coordinates (docs/fracture.md, "Growth"); the drawn line itself under the key (name, "drawn")
    as (xs, ys). Only interfaces that wrote crack_path_NAME.csv with rows."""
    paths = {}
    for name, spec in (run.case.get("interface") or {}).items():
        rows = optional_table(run, f"crack_path_{name}.csv")
        if not isinstance(spec, dict) or rows is None or not len(rows["time"]):
            continue
        points = spec.get("points")
        if points is None and all(k in spec for k in ("y", "start", "end")):  # the horizontal form
            points = [[spec["start"], spec["y"]], [spec["end"], spec["y"]]]
        if not points:
            continue
        drawn = np.array(points, dtype=float)
        ends = []
        own = rows["tip"] < 2  # tips 2, 3, ...: branches split off a tip (end 2, 3: the splits)
        for end, (x0, y0) in ((0, drawn[0]), (1, drawn[-1])):
            mine = (rows["end"] == end) & own
            if mine.any():
                ends.append((np.concatenate([[0.0], rows["time"][mine]]), np.concatenate([[x0], rows["x"][mine]]),
                             np.concatenate([[y0], rows["y"][mine]])))
        # Each branch from the tip it split off (the split row before its first segment).
        split, born = None, {}
        for i in range(len(rows["time"])):
            if rows["end"][i] >= 2:
                split = (rows["time"][i], rows["x"][i], rows["y"][i])
            elif rows["tip"][i] >= 2 and split is not None:
                born.setdefault(int(rows["tip"][i]), split)
        for label, (t0, x0, y0) in sorted(born.items()):
            mine = (rows["tip"] == label) & (rows["end"] < 2)
            ends.append((np.concatenate([[t0], rows["time"][mine]]), np.concatenate([[x0], rows["x"][mine]]),
                         np.concatenate([[y0], rows["y"][mine]])))
        paths[name] = ends
        paths[(name, "drawn")] = (drawn[:, 0], drawn[:, 1])
    return paths


def grown_tips(paths, t):
    """[(name, x, y, running, direction)] of every grown end at time t (as tip_at gives a
    tracked tip): its last vertex made by t, running once it has grown, the direction of its last
    segment; the one whose last vertex was made latest first (a branch's after a split)."""
    tips, made = [], []
    for name, ends in paths.items():
        if isinstance(name, tuple):
            continue
        for times, xs, ys in ends:
            k = int(np.searchsorted(times, t, side="right")) - 1
            if k < 0:  # a branch not split off yet
                continue
            d = np.array([xs[k] - xs[k - 1], ys[k] - ys[k - 1]]) if k >= 1 else np.array([1.0, 0.0])
            tips.append((name, float(xs[k]), float(ys[k]), k >= 1, d / max(np.linalg.norm(d), 1e-300)))
            made.append(float(times[k]) if k >= 1 else -np.inf)
    # The tip that grew last first (after a split, a branch's rather than the stopped tip's).
    order = sorted(range(len(tips)), key=lambda i: -made[i])
    return [tips[i] for i in order]


def box_any(mask, a, b):
    """mask dilated by a pixels along the first axis and b along the second (box sums)."""
    n0, n1 = mask.shape
    c = np.pad(mask.astype(np.int64), ((a + 1, a), (b + 1, b))).cumsum(0).cumsum(1)
    s = (c[2 * a + 1:2 * a + 1 + n0, 2 * b + 1:2 * b + 1 + n1] - c[:n0, 2 * b + 1:2 * b + 1 + n1]
         - c[2 * a + 1:2 * a + 1 + n0, :n1] + c[:n0, :n1])
    return s > 0


def covered_pixels(x, y, hx, hy, xe, ye):
    """Pixels of the image (edges xe, ye) whose centre lies in some particle's GIMP domain
    [x - hx, x + hx] x [y - hy, y + hy]: the body as its particles cover it (holes stay empty).
    Particles are grouped by their half-widths in pixels (a few sizes: one per level)."""
    px, py = xe[1] - xe[0], ye[1] - ye[0]
    kx = np.maximum(0, np.ceil(hx / px - 0.5 - 1e-9)).astype(int)
    ky = np.maximum(0, np.ceil(hy / py - 0.5 - 1e-9)).astype(int)
    covered = np.zeros((len(xe) - 1, len(ye) - 1), dtype=bool)
    for a, b in set(zip(kx.tolist(), ky.tolist())):
        sel = (kx == a) & (ky == b)
        occupied, _, _ = np.histogram2d(x[sel], y[sel], bins=(xe, ye))
        covered |= box_any(occupied > 0, a, b)
    # A closing by one pixel: gaps of one or two pixels between moved particles (two centres in
    # one pixel, a neighbour's empty) are filled; holes and gaps wider than that stay.
    covered = ~box_any(~box_any(covered, 1, 1), 1, 1)
    return covered, int(max(kx.max(initial=0), ky.max(initial=0)))


def fill_empty(image, allowed, passes):
    """Empty pixels (nan) where `allowed` take the mean of their filled neighbours, `passes`
    times: pixels the coarser particles leave empty between their centres."""
    for _ in range(passes):
        empty = np.isnan(image) & allowed
        if not empty.any():
            break
        padded = np.pad(image, 1, constant_values=np.nan)
        stack = np.stack([padded[1 + a:padded.shape[0] - 1 + a, 1 + b:padded.shape[1] - 1 + b]
                          for a in (-1, 0, 1) for b in (-1, 0, 1) if a or b])
        with np.errstate(invalid="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            fill = np.nanmean(stack, axis=0)
        image = np.where(empty, fill, image)
    return image


def fringe_panel(snap, tracks, width, paths=None):
    """One panel's image: tau_max (MPa) per pixel around the running tip, its edges, the tips
    at the snapshot's time. The window spans 0.32 x 0.32 of the domain's width, centred 0.04 of
    it behind the leading running tip (the first interface's while none runs): for the paper's
    plate 25 mm behind to 15 mm ahead of the tip, 20 mm either side of the crack line. A crack
    that grows (paths: crack_paths) has its tips where its path ends at that time, every grown
    end (the tracker follows one tip, the separated one furthest along the line)."""
    pos, tau, t = snap["position"], snap["tau_max"], snap.time
    x, y = pos[:, 0], pos[:, 1]
    names = snap.names()
    half = snap["half_size"] if "half_size" in names else None
    paths = paths or {}
    tips = grown_tips(paths, t) + [(name,) + tip_at(tip, t) for name, tip in tracks if name not in paths]
    lead = next((tp for tp in tips if tp[3]), tips[0] if tips else None)
    if lead is not None:
        _, tx, ty, _, d = lead
        cx, cy = tx - 0.04 * width * d[0], ty - 0.04 * width * d[1]
        r = 0.16 * width
        margin = float(half.max()) if half is not None else 0.0
        window = (np.abs(x - cx) < r + margin) & (np.abs(y - cy) < r + margin)
        if window.sum() > 100:
            x, y, tau = x[window], y[window], tau[window]
            if half is not None:
                half = half[window]
            lo_x, hi_x, lo_y, hi_y = cx - r, cx + r, cy - r, cy + r
        else:
            lead = None
    if lead is None:
        lo_x, hi_x, lo_y, hi_y = x.min(), x.max(), y.min(), y.max()
    span_x, span_y = hi_x - lo_x, hi_y - lo_y
    # Pixels at the finest particle spacing in the window (capped at 900 a side).
    if half is not None:
        spacing = 2.0 * float(half.min())
    else:  # snapshots written before half_size: the spacing from the particles' density
        spacing = math.sqrt(max(span_x * span_y, 1e-30) / max(len(x), 1))
    nx = max(8, min(900, int(span_x / spacing)))
    ny = max(8, min(900, int(span_y / spacing)))
    xe, ye = np.linspace(lo_x, hi_x, nx + 1), np.linspace(lo_y, hi_y, ny + 1)
    total, _, _ = np.histogram2d(x, y, bins=(xe, ye), weights=tau)
    count, _, _ = np.histogram2d(x, y, bins=(xe, ye))
    with np.errstate(invalid="ignore", divide="ignore"):
        image = np.where(count > 0, total / count, np.nan) / 1e6
    if half is not None:
        covered, reach = covered_pixels(x, y, half[:, 0], half[:, 1], xe, ye)
        image = fill_empty(image, covered, reach + 1)
        image = np.where(covered, image, np.nan)
    else:
        image = fill_empty(image, np.ones_like(count, dtype=bool), 8)
    return t, [tp for tp in tips if tp[3]], xe, ye, image


def plot_fringes(run, out, max_panels=4):
    snaps = run.snapshots
    if not len(snaps):
        print("note: no snapshots in DIR/snapshots; tau_max_fringes.png skipped")
        return
    sc = scale_of(run)
    tracks = tip_tracks(run)
    paths = crack_paths(run)
    mach = optional_table(run, "mach_angle.csv")
    width = sc.size
    grid = run.case.get("grid", {})
    if "min" in grid and "max" in grid:
        width = float(grid["max"][0]) - float(grid["min"][0])
    # The latest snapshots show the running crack: take up to max_panels, evenly spread over
    # the second half of the run.
    half = list(range(len(snaps) // 2, len(snaps))) or list(range(len(snaps)))
    pick = list(dict.fromkeys(half[int(round(i))] for i in np.linspace(0, len(half) - 1, min(max_panels, len(half)))))
    panels = [fringe_panel(snaps[k], tracks, width, paths) for k in pick]
    # One colour scale across the panels (the paper's Fig. 7): the largest 99.5th percentile.
    top = max(np.nanpercentile(p[4], 99.5) for p in panels)
    levels = np.linspace(0, top, 16)
    f = sc.lf
    fig, axes = plt.subplots(1, len(panels), figsize=(6.4 * len(panels), 5.4), squeeze=False)
    fig.subplots_adjust(wspace=0.25)
    for ax, (t, tips, xe, ye, image) in zip(axes[0], panels):
        xc, yc = 0.5 * (xe[1:] + xe[:-1]), 0.5 * (ye[1:] + ye[:-1])
        cs = ax.contourf(f * xc, f * yc, image.T, levels=levels, cmap="gray_r", extend="max")
        ax.contour(f * xc, f * yc, image.T, levels=levels, colors="k", linewidths=0.3)
        for name, ends in paths.items():  # every growing crack: drawn, then grown by time t
            if isinstance(name, tuple):
                ax.plot(f * ends[0], f * ends[1], "b-", lw=1.0)
                continue
            for times, xs, ys in ends:
                made = times <= t
                ax.plot(f * xs[made], f * ys[made], "b-", lw=1.4)
        for name, tx, ty, _, _ in tips:  # every running tip, where it is (E10)
            ax.plot([f * tx], [f * ty], "r^", ms=7)
            if len(tracks) > 1:
                ax.annotate(name, (f * tx, f * ty), xytext=(5, 5), textcoords="offset points",
                            color="r", fontsize=8)
        if mach is not None:
            k = int(np.argmin(np.abs(mach["time"] - t)))
            if abs(mach["time"][k] - t) < 1e-3 * max(t, 1e-30):
                reading = {key: mach[key][k] for key in mach}
                for key, side in (("left", 1), ("right", -1)):
                    pts = mach_line_points(reading, key, side, 0.096 * width)
                    if pts is not None:
                        ax.plot(f * pts[0], f * pts[1], "r-", lw=1.2)
                        # Each label beside its own front, 60 % along it (inside the window),
                        # offset away from the crack line on that front's side, so the two
                        # never sit on each other nor on the title.
                        at = (f * (0.4 * pts[0][0] + 0.6 * pts[0][1]), f * (0.4 * pts[1][0] + 0.6 * pts[1][1]))
                        ax.annotate(f"{reading['angle_' + key]:.1f}°", at, xytext=(6, 6 * side),
                                    textcoords="offset points", color="r", fontsize=9, ha="left",
                                    va="bottom" if side > 0 else "top", annotation_clip=True)
        ax.set_xlim(f * xe[0], f * xe[-1])
        ax.set_ylim(f * ye[0], f * ye[-1])
        ax.set_aspect("equal")
        ax.set_title(sc.time_label(t), fontsize=11)
        ax.set_xlabel(f"x ({sc.lname})")
    axes[0][0].set_ylabel(f"y ({sc.lname})")
    fig.colorbar(cs, ax=axes[0].tolist(), shrink=0.8, label=r"$\tau_{max}$ (MPa)")
    fig.suptitle(r"$\tau_{max} = (\sigma_1-\sigma_2)/2$ around the crack tip (red: running tips, E10; "
                 r"red lines: measured shear Mach fronts, E12" + ("; blue: crack paths" if paths else "") + ")")
    save(fig, out)


def plot_profiles(run, out, max_curves=4):
    # The first interface's profiles (interface_NNNNNN.csv; the others are NAME_NNNNNN.csv).
    profiles = [p for p in run.interface_profiles("interface") if len(p)]
    if not profiles:
        print("note: no DIR/interface/interface_*.csv; cohesive_profiles.png skipped")
        return
    sc = scale_of(run)
    pick = [profiles[int(round(i))] for i in np.linspace(len(profiles) // 2, len(profiles) - 1,
                                                         min(max_curves, len(profiles)))]
    pick = list({id(p): p for p in pick}.values())
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    for p in pick:
        label = sc.time_label(p["time"][0])
        x = sc.lf * p["x"]
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
        ax.set_xlabel(f"x along the interface ({sc.lname})")
    axes[0][0].legend(fontsize=8)
    fig.suptitle("Cohesive tractions and nodal forces along the interface")
    save(fig, out)


def plot_interfaces(run, fig_dir):
    """Per interface (run.json "cracks", input order): crack_tip_NAME.png (tip and back tip along
    the arc length s, and their E11 speeds against every material's c_R, c_S, c_D) and
    rupture_time_NAME.png (when each node cracked along s: the rupture-time profile)."""
    sc = scale_of(run)
    for crack in run.record.get("cracks") or []:
        name = crack["interface"]
        tip = optional_table(run, f"crack_tip_{name}.csv")
        if tip is not None:
            fig, (ax_s, ax_v) = plt.subplots(2, 1, figsize=(7, 7.5), sharex=True)
            t = sc.tf * tip["time"]
            ax_s.plot(t, sc.lf * tip["tip_s"], label="tip")
            ax_s.plot(t, sc.lf * tip["back_s"], label="back tip", ls="--")
            ax_s.set_ylabel(f"position along the interface s ({sc.lname})")
            ax_s.legend(fontsize=8)
            ax_s.grid(alpha=0.3)
            ax_v.plot(t, sc.vf * tip["speed"], label="tip")
            ax_v.plot(t, sc.vf * tip["back_speed"], label="back tip", ls="--")
            lines, top = [], 0.0
            shades = ["k", "0.45", "tab:brown", "tab:purple"]
            for k, (material, w) in enumerate(run.record["wave_speeds"].items()):
                for value, label, style in [(w["rayleigh"], "$c_R$", ":"), (w["shear"], "$c_S$", "--"),
                                            (w["dilatational"], "$c_D$", "-")]:
                    lines.append((sc.vf * value, f"{label} {material} = {sc.vf * value:.{3 if sc.vf < 1 else 0}f} "
                                  f"{sc.vname}", style, shades[k % len(shades)]))
                top = max(top, w["dilatational"])
            label_lines(ax_v, lines, fontsize=7)
            ax_v.set_ylim(0, 1.1 * sc.vf * top)
            ax_v.set_xlabel(f"time ({sc.tname})")
            ax_v.set_ylabel(f"speed along the interface ({sc.vname}, E11)")
            ax_v.grid(alpha=0.3)
            fig.suptitle(f"interface {name}: {crack.get('upper_body', '')} / {crack.get('lower_body', '')}")
            save(fig, os.path.join(fig_dir, f"crack_tip_{name}.png"))
        times = optional_table(run, f"rupture_time_{name}.csv")
        if times is not None:
            cracked = times["crack_time"] >= 0
            fig, ax = plt.subplots(figsize=(7, 4))
            ax.plot(sc.lf * times["s"][cracked], sc.tf * times["crack_time"][cracked], ".", ms=2,
                    label="cracked (the law's criterion; on a fault, slip = Dc)")
            if "rupture_time" in times:
                ruptured = times["rupture_time"] >= 0
                ax.plot(sc.lf * times["s"][ruptured], sc.tf * times["rupture_time"][ruptured], ".", ms=2,
                        label="ruptured (slip rate > rupture_slip_rate)")
                ax.legend(fontsize=7)
            ax.set_xlabel(f"position along the interface s ({sc.lname})")
            ax.set_ylabel(f"time ({sc.tname})")
            ax.set_title(f"interface {name}: rupture-time profile ({int(cracked.sum())} of {len(cracked)} nodes cracked)")
            ax.grid(alpha=0.3)
            save(fig, os.path.join(fig_dir, f"rupture_time_{name}.png"))


# ---- figures of sweeps ------------------------------------------------------------------------

def as_number(value):
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def shown(value):
    """A varied value as the label shows it (numbers without trailing zeros)."""
    return f"{value:g}" if isinstance(value, (float, np.floating)) else str(value)


def plot_sweep(sweeps, fig_dir):
    """The map and the speed histories of one or more sweeps, sweeps = [(label, dir)]. One line
    per value of the second varied key; with several sweeps (the paper's map on two meshes), one
    line per sweep and value."""
    rows, done = [], []
    for label, d in sweeps:
        sweep = Sweep(d)
        for k in range(len(sweep)):
            r = sweep.row(k)
            rows.append(r)
            if r["status"] == "completed":
                done.append((sweep.keys, dict(r, _dir=sweep.dir, _sweep=label)))
    if not done:
        print("note: no completed run in the sweep; no figures")
        return
    first_run = Run(os.path.join(done[0][1]["_dir"], str(done[0][1]["run"])))
    upper, lower = interface_materials(first_run)
    c_d, c_s, c_r = material_speeds(first_run, lower)
    sc = scale_of(first_run)
    first = done[0][0][0]
    groups = {}
    for keys, r in done:
        second = keys[1] if len(keys) > 1 else None
        parts = ([r["_sweep"]] if len(sweeps) > 1 else []) + ([f"{second} = {shown(r[second])}"] if second else [])
        groups.setdefault(", ".join(parts), []).append(r)
    # The map (the paper's Fig. 13 look).
    fig, ax = plt.subplots(figsize=(8, 5.5))
    xs = [as_number(r[first]) for _, r in done]
    for label, members in groups.items():
        members.sort(key=lambda r: as_number(r[first]))
        x = [as_number(r[first]) for r in members]
        v = [sc.vf * as_number(r["sustained_speed_m_per_s"]) for r in members]
        line, = ax.plot(x, v, "-", label=label or None)
        for xi, vi, r in zip(x, v, members):
            hollow = str(r["arrested"]) == "true"
            ax.plot(xi, vi, "o", color=line.get_color(), mfc="none" if hollow else line.get_color())
    lo, hi = min(xs), max(xs)
    bands = [(0, c_r, "sub-Rayleigh", "#e8f0ff"), (c_r, c_s, "Rayleigh-to-shear", "#fff0e0"),
             (c_s, c_d, "intersonic", "#e8ffe8"), (c_d, 1.15 * c_d, "supersonic", "#ffe8e8")]
    for a, b, name, colour in bands:
        ax.axhspan(sc.vf * a, sc.vf * b, color=colour, zorder=0)
        ax.text(hi, sc.vf * 0.5 * (a + b), name, ha="right", va="center", fontsize=8, color="0.4")
    for value, name in ((c_r, "$c_R$"), (c_s, "$c_S$"), (math.sqrt(2) * c_s, r"$\sqrt{2}c_S$"), (c_d, "$c_D$")):
        ax.axhline(sc.vf * value, color="0.5", lw=0.8, ls="--")
        ax.text(lo, sc.vf * value, " " + name, va="bottom", fontsize=9, color="0.3")
    ax.set_ylim(0, 1.1 * sc.vf * c_d)
    ax.set_xlabel(first)
    ax.set_ylabel(f"sustained speed, steady running phase ({sc.vname})")
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
            tip = optional_table(Run(os.path.join(r["_dir"], str(r["run"]))), "crack_tip.csv")
            if tip is None:
                continue
            colour = cmap(k / max(1, len(members) - 1))
            ax.plot(sc.tf * tip["time"], sc.vf * tip["speed"], color=colour, lw=1,
                    label=f"{first} = {shown(r[first])}")
        for value in (c_r, c_s, math.sqrt(2) * c_s, c_d):
            ax.axhline(sc.vf * value, color="0.5", lw=0.8, ls="--")
        ax.set_ylabel(f"E11 speed ({sc.vname})")
        ax.set_ylim(0, 1.1 * sc.vf * c_d)
        ax.set_title(label or "all runs", fontsize=9)
        ax.legend(fontsize=7, ncol=2)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel(f"time ({sc.tname})")
    save(fig, os.path.join(fig_dir, "sweep_histories.png"))


def main(argv=None):
    ap = argparse.ArgumentParser(prog="rupture plot", description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("dir", help="run directory written by `rupture run`, or a sweep directory")
    ap.add_argument("--compare", nargs="*", default=[],
                    help="more run directories to overlay (or, for a sweep, more sweeps: one map)")
    ap.add_argument("--labels", nargs="*", default=None, help="legend labels, one per run")
    args = ap.parse_args(argv)
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
    runs = [Run(d) for d in dirs]
    plot_crack_tip(runs, labels, os.path.join(fig_dir, "crack_tip.png"))
    plot_fringes(runs[0], os.path.join(fig_dir, "tau_max_fringes.png"))
    plot_profiles(runs[0], os.path.join(fig_dir, "cohesive_profiles.png"))
    plot_interfaces(runs[0], fig_dir)
    plot_stations(runs[0], fig_dir)


if __name__ == "__main__":
    main()
