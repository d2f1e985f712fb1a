#!/usr/bin/env python3
"""Checks a rupture run directory the way ParaView and users read it.

- run.json parses and carries the stable keys;
- history.csv has the energy columns and complete rows;
- particles.xdmf is well-formed XML following XDMF 3 conventions, and every HDF5 path it
  references exists with the dimensions it declares (read back with h5py).
"""
import csv
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import h5py


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def main(run_dir):
    with open(os.path.join(run_dir, "run.json")) as f:
        run = json.load(f)
    for key in ("dt", "steps", "cells", "particles", "wall_seconds", "particle_updates_per_second"):
        if key not in run:
            fail(f"run.json lacks '{key}'")
    if run["status"] != "completed":
        fail(f"status {run['status']}")

    with open(os.path.join(run_dir, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    for col in ("time", "kinetic_energy", "strain_energy", "external_work", "relative_balance_error"):
        if col not in rows[0]:
            fail(f"history.csv lacks column {col}")
    if not all(math.isfinite(float(r["total_energy"])) for r in rows):
        fail("history.csv has a non-finite or incomplete row")

    tree = ET.parse(os.path.join(run_dir, "particles.xdmf"))
    root = tree.getroot()
    if root.tag != "Xdmf" or root.get("Version") != "3.0":
        fail("root element is not <Xdmf Version='3.0'>")
    collection = root.find("Domain/Grid")
    if collection is None or collection.get("CollectionType") != "Temporal":
        fail("no temporal collection")
    grids = collection.findall("Grid")
    if len(grids) < 2:
        fail(f"expected several time steps, found {len(grids)}")
    times = []
    for g in grids:
        times.append(float(g.find("Time").get("Value")))
        n = int(g.find("Topology").get("NumberOfElements"))
        if n != run["particles"]:
            fail(f"topology has {n} elements, run.json {run['particles']} particles")
        items = g.findall(".//DataItem")
        for item in items:
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            fname, path = item.text.strip().split(":")
            with h5py.File(os.path.join(run_dir, fname), "r") as h5:
                if path not in h5:
                    fail(f"{fname} lacks {path}")
                if h5[path].shape != dims:
                    fail(f"{fname}:{path} has shape {h5[path].shape}, XDMF says {dims}")
                if not all(math.isfinite(v) for v in h5[path][...].ravel()[:1000]):
                    fail(f"{fname}:{path} has non-finite values")
        names = {a.get("Name") for a in g.findall("Attribute")}
        for required in ("velocity", "sxx", "syy", "sxy", "tau_max", "body"):
            if required not in names:
                fail(f"attribute {required} missing")
    if times != sorted(times):
        fail("snapshot times are not increasing")
    leftovers = [f for f in os.listdir(run_dir) if f.endswith(".tmp")]
    if leftovers:
        fail(f"temporary files left behind: {leftovers}")
    print(f"ok: {len(grids)} snapshots, {run['particles']} particles, {len(rows)} history rows")


if __name__ == "__main__":
    main(sys.argv[1])
