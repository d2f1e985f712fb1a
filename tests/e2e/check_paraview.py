"""DIR/particles.xdmf opens in ParaView as users open it: run with pvpython (Debian's
python3-paraview, ParaView 5.11).

Usage: pvpython check_paraview.py RUN_DIR

With each of ParaView's three XDMF readers (Xdmf3ReaderS, its default for .xdmf, Xdmf3ReaderT
and the XDMF 2 reader) and at every time of the collection: as many cells as points as
particles in that time's HDF5 file (one vertex cell per particle, so the default Surface
representation shows them), the time values of the files, and the point arrays by name and
size; the last time's tau_max and velocity equal the HDF5 datasets row for row.
"""
import sys

import h5py
import numpy as np
from paraview import servermanager as sm
from paraview import simple
from vtk.util.numpy_support import vtk_to_numpy

run = sys.argv[1]
xdmf = f"{run}/particles.xdmf"
ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and bool(cond)


# The files the collection names, in time order, with their times (root attribute "time").
import xml.etree.ElementTree as ET

steps = []
for grid in ET.parse(xdmf).getroot().iter("Grid"):
    if grid.get("GridType") != "Uniform":
        continue
    path = grid.find("Geometry/DataItem").text.strip().split(":")[0]
    with h5py.File(f"{run}/{path}", "r") as f:
        steps.append((float(f.attrs["time"]), path, f["tau_max"][:], f["velocity"][:]))
check(len(steps) >= 2, f"{len(steps)} snapshots listed in particles.xdmf")

arrays = {"velocity": 3, "sxx": 1, "syy": 1, "sxy": 1, "szz": 1, "tau_max": 1, "body": 1}
readers = [("Xdmf3ReaderS", lambda: simple.Xdmf3ReaderS(FileName=[xdmf])),
           ("Xdmf3ReaderT", lambda: simple.Xdmf3ReaderT(FileName=[xdmf])),
           ("XDMFReader", lambda: simple.XDMFReader(FileNames=[xdmf]))]
for name, make in readers:
    reader = make()
    times = list(reader.TimestepValues)
    check(np.allclose(times, [s[0] for s in steps], rtol=1e-8, atol=0.0),
          f"{name}: {len(times)} time values equal the files' times")
    for t, path, tau, vel in steps:
        reader.UpdatePipeline(t)
        data = sm.Fetch(reader)
        n = len(tau)
        check(data.GetNumberOfPoints() == n and data.GetNumberOfCells() == n,
              f"{name} t = {t:.3e} s: {data.GetNumberOfPoints()} points, {data.GetNumberOfCells()} "
              f"cells, {n} particles in {path}")
        pd = data.GetPointData()
        for a, comps in arrays.items():
            arr = pd.GetArray(a)
            check(arr is not None and arr.GetNumberOfTuples() == n and arr.GetNumberOfComponents() == comps,
                  f"{name} t = {t:.3e} s: point array {a} ({comps} components x {n})")
    t, path, tau, vel = steps[-1]
    reader.UpdatePipeline(t)
    pd = sm.Fetch(reader).GetPointData()
    check(np.array_equal(vtk_to_numpy(pd.GetArray("tau_max")), tau) and
          np.array_equal(vtk_to_numpy(pd.GetArray("velocity")), vel),
          f"{name}: tau_max and velocity at t = {t:.3e} s equal {path} row for row")
    simple.Delete(reader)
sys.exit(0 if ok else 1)
