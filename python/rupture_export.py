#!/usr/bin/env python3
"""rupture export DIR --format scec: a finished run's stations and rupture fronts in the text
files of the SCEC/USGS dynamic-rupture code-verification uploads (Harris et al. 2009, 2018;
the format the benchmark descriptions give for every TPV problem).

Written into DIR/scec/ (never elsewhere: the names come from the case's stations, which
input/names.cpp restricts to letters, digits, '_' and '-'):

  NAME.txt        one per fault station ([stations.NAME] with `interface`): the header lines
                  (# problem=, # author=, # date=, # code=, # code_version=, # element_size=,
                  # time_step=, # num_time_steps=, # location=, one # Column #k = ... line per
                  column), then the field names
                      t h-slip h-slip-rate h-shear-stress v-slip v-slip-rate v-shear-stress n-stress
                  and one row per sample. A 2D in-plane fault slips along strike only: the
                  horizontal columns hold the slip (m), the slip rate friction sees (m/s) and the
                  shear traction (MPa); the vertical ones are 0; n-stress is the normal traction
                  (MPa, negative in compression, as the SCEC files have it). On a
                  rate-and-state fault (a station file with a `state` column) a ninth column,
                  psi, the state variable (dimensionless), as the rate-and-state benchmarks'
                  files (TPV101-105) have it.
  NAME.txt        one per body station: t h-disp h-vel v-disp v-vel n-disp n-vel, with x as the
                  horizontal (along-strike) and y as the fault-normal direction (the axes of
                  every example: faults along x); vertical 0.
  cplot.txt       the rupture-time contour file of the fault (cplot_INTERFACE.txt for each when
                  the case has several): j k t = distance along strike (the node's x, m), down
                  dip (0 in 2D), rupture time (s; 1e9 where the node never ruptured, as the
                  format asks).
Numbers are written as E15.7 (the format's), times with 12 digits.
Standard library only (it runs under any python3).
"""
import argparse
import csv
import datetime
import json
import os
import re
import sys

SAFE_NAME = re.compile(r"^[A-Za-z0-9_-]+$")
NEVER = 1.0e9  # the format's rupture time of a node that never ruptured


def fail(message):
    print(f"error: {message}", file=sys.stderr)
    sys.exit(1)


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        fail(f"'{path}' is empty")
    head = rows[0]
    return {k: [float(r[i]) for r in rows[1:]] for i, k in enumerate(head)}


def e15(v):
    return f"{v:15.7E}"


def header(info, location, columns, names):
    lines = [
        f"# problem={info['problem']}",
        f"# author={info['author']}",
        f"# date={info['date']}",
        "# code=rupture",
        f"# code_version={info['version']}",
        f"# element_size={info['element_size']:g} m",
        f"# time_step={info['time_step']:.6g} s",
        f"# num_time_steps={info['num_time_steps']}",
        f"# location={location}",
        f"# Time series in {len(columns)} columns in format E15.7",
    ]
    lines += [f"# Column #{k + 1} = {c}" for k, c in enumerate(columns)]
    lines += ["#", "# The line below lists the names of the data fields:", " ".join(names), "#",
              "# Here is the time-series data.", f"# There should be {len(columns)} columns of data:"]
    return "\n".join(lines) + "\n"


FAULT_COLUMNS = ["Time (s)", "horizontal slip (m)", "horizontal slip rate (m/s)",
                 "horizontal shear stress (MPa)", "vertical slip (m)", "vertical slip rate (m/s)",
                 "vertical shear stress (MPa)", "normal stress (MPa)"]
FAULT_NAMES = ["t", "h-slip", "h-slip-rate", "h-shear-stress", "v-slip", "v-slip-rate",
               "v-shear-stress", "n-stress"]
# The CSV column and scale behind each data column after the time (None: 0 in 2D).
FAULT_SOURCES = [("slip", 1.0), ("slip_rate", 1.0), ("shear_traction", 1e-6), None, None, None,
                 ("normal_traction", 1e-6)]
# A rate-and-state fault's ninth column.
STATE_COLUMN, STATE_NAME, STATE_SOURCE = "state variable psi (dimensionless)", "psi", ("state", 1.0)
BODY_COLUMNS = ["Time (s)", "horizontal displacement (m)", "horizontal velocity (m/s)",
                "vertical displacement (m)", "vertical velocity (m/s)", "normal displacement (m)",
                "normal velocity (m/s)"]
BODY_NAMES = ["t", "h-disp", "h-vel", "v-disp", "v-vel", "n-disp", "n-vel"]
BODY_SOURCES = [("ux", 1.0), ("vx", 1.0), None, None, ("uy", 1.0), ("vy", 1.0)]


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def export_scec(run, problem, author):
    run_json = os.path.join(run, "run.json")
    if not os.path.isfile(run_json):
        fail(f"'{run}' is not a run directory: it has no run.json (rupture run writes one)")
    with open(run_json) as f:
        record = json.load(f)
    case = record.get("input", {})
    stations = case.get("stations", {})
    if not stations:
        fail(f"the run in '{run}' has no [stations]: nothing to export (a SCEC upload is station "
             "files and the rupture-time contours)")
    out = os.path.join(run, "scec")
    os.makedirs(out, exist_ok=True)
    info = {
        "problem": problem or record.get("title", "") or "unnamed",
        "author": author,
        "date": datetime.date.today().strftime("%Y/%m/%d"),
        "version": f"{record.get('version', '')} (commit {record.get('git_commit', 'unknown')})",
        "element_size": float(case.get("grid", {}).get("cell_size", 0.0)),
        "time_step": float(record.get("dt", 0.0)),  # until a series gives its own
    }
    written = []
    for name, st in stations.items():
        if not SAFE_NAME.match(name):
            fail(f"station name {name!r} is not a plain name; nothing written for it")
        path = os.path.join(run, "stations", name + ".csv")
        if not os.path.isfile(path):
            fail(f"'{path}' is missing: the run did not write station '{name}'")
        c = read_columns(path)
        t = c["time"]
        at = st.get("at", [0.0, 0.0])
        info["num_time_steps"] = len(t)
        if len(t) > 1:  # the series' own step (output.station_interval, or the run's dt)
            info["time_step"] = (t[-1] - t[0]) / (len(t) - 1)
        fault = "interface" in st
        # Each column of the format: (the CSV column, its scale to the format's unit), or None: 0.
        cols = FAULT_SOURCES if fault else BODY_SOURCES
        columns, names = (FAULT_COLUMNS, FAULT_NAMES) if fault else (BODY_COLUMNS, BODY_NAMES)
        if fault and "state" in c:  # rate and state
            cols, columns, names = cols + [STATE_SOURCE], columns + [STATE_COLUMN], names + [STATE_NAME]
        for key in {src[0] for src in cols if src}:
            if key not in c:
                fail(f"'{path}' has no column '{key}': not a {'fault' if fault else 'body'} station's file")
        location = (f"on fault '{st['interface']}', {at[0] / 1e3:g} km along strike" if fault else
                    f"{at[0] / 1e3:g} km along strike, {at[1] / 1e3:g} km across")
        location += f" (x = {at[0]:g} m, y = {at[1]:g} m)"
        text = header(info, location, columns, names)
        for k in range(len(t)):
            text += f"{t[k]:.12E}" + "".join(" " + e15(c[src[0]][k] * src[1] if src else 0.0)
                                             for src in cols) + "\n"
        write_atomic(os.path.join(out, name + ".txt"), text)
        written.append(name + ".txt")
    faults = sorted({st["interface"] for st in stations.values() if "interface" in st})
    for iface in faults:
        if not SAFE_NAME.match(iface):
            fail(f"interface name {iface!r} is not a plain name")
        path = os.path.join(run, f"rupture_time_{iface}.csv")
        if not os.path.isfile(path):
            fail(f"'{path}' is missing: the run did not write the rupture-time profile of '{iface}'")
        c = read_columns(path)
        lines = [f"# problem={info['problem']}", f"# author={info['author']}",
                 f"# date={info['date']}", "# code=rupture", f"# code_version={info['version']}",
                 f"# element_size={info['element_size']:g} m",
                 "# Column #1 = horizontal coordinate, distance along strike (m)",
                 "# Column #2 = vertical coordinate, distance down-dip (m)",
                 "# Column #3 = rupture time (s)", "#",
                 "# The line below lists the names of the data fields.",
                 "# It indicates that the first column contains the horizontal",
                 "# coordinate (j), the second column contains the vertical",
                 "# coordinate (k), and the third column contains the time (t).",
                 "j k t", "#", "# Here is the rupture history"]
        text = "\n".join(lines) + "\n"
        for x, tr in zip(c["x"], c["rupture_time"]):
            text += f"{e15(x)} {e15(0.0)} {e15(tr if tr >= 0 else NEVER)}\n"
        name = "cplot.txt" if len(faults) == 1 else f"cplot_{iface}.txt"
        write_atomic(os.path.join(out, name), text)
        written.append(name)
    print(f"scec_files={len(written)}")
    print(f"scec_dir={out}")
    return written


def main():
    ap = argparse.ArgumentParser(prog="rupture export", description=__doc__.splitlines()[0])
    ap.add_argument("dir", help="run directory")
    ap.add_argument("--format", required=True, choices=["scec"])
    ap.add_argument("--problem", default="", help="the benchmark's name (# problem=); default: the case's title")
    ap.add_argument("--author", default="", help="# author= line")
    a = ap.parse_args()
    if not os.path.isdir(a.dir):
        fail(f"'{a.dir}' is not a directory")
    export_scec(a.dir, a.problem, a.author)


if __name__ == "__main__":
    main()
