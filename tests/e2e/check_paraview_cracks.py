"""DIR/cracks.xdmf (output/crack_xdmf.hpp) opens in ParaView beside DIR/particles.xdmf: run with
pvpython (Debian's python3-paraview).

Usage: pvpython check_paraview_cracks.py RUN_DIR

With ParaView's default XDMF 3 reader: the collection's times are the particle snapshots'
times; at each time the crack is one polyline, as many points as the drawn line's vertices plus
the rows of crack_path_NAME.csv made by then, and one line cell fewer; its points are the drawn
line's ends and the grown vertices (reference coordinates, z = 0) to round-off, and the last
time's polyline reaches the last grown vertex of each end.
"""
import csv
import sys
import xml.etree.ElementTree as ET

import numpy as np
from paraview import servermanager as sm
from paraview import simple
from vtk.util.numpy_support import vtk_to_numpy

run = sys.argv[1]
ok = True


def check(cond, what):
    global ok
    print(("ok   " if cond else "FAIL ") + what)
    ok = ok and bool(cond)


particle_times = [float(g.find("Time").get("Value")) for g in ET.parse(f"{run}/particles.xdmf").getroot().iter("Grid")
                  if g.get("GridType") == "Uniform"]
rows = list(csv.DictReader(open(f"{run}/crack_path_crack.csv")))
check(len(rows) > 0, f"the crack grew ({len(rows)} rows)")
reader = simple.Xdmf3ReaderS(FileName=[f"{run}/cracks.xdmf"])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
check(np.allclose(times, particle_times, rtol=1e-9), f"{len(times)} times, the particle snapshots' ({len(particle_times)})")
for t in times:
    reader.UpdatePipeline(t)
    data = sm.Fetch(reader)
    block = data.GetBlock(0) if data.IsA("vtkMultiBlockDataSet") else data
    points = vtk_to_numpy(block.GetPoints().GetData())
    made = [r for r in rows if float(r["time"]) <= t * (1 + 1e-12)]
    want = 2 + len(made)  # the example's drawn line has two vertices
    check(len(points) == want and block.GetNumberOfCells() == want - 1,
          f"t = {t:.3e}: {len(points)} points (want {want}), {block.GetNumberOfCells()} line cells")
    grown = np.array([[float(r["x"]), float(r["y"]), 0.0] for r in made]).reshape(-1, 3)
    if len(grown):
        gap = max(np.min(np.linalg.norm(points - g, axis=1)) for g in grown)
        check(gap < 1e-12, f"t = {t:.3e}: every grown vertex is a point of the polyline (largest gap {gap:.1e} m)")
    check(abs(points[:, 2]).max() == 0.0, f"t = {t:.3e}: z = 0")
sys.exit(0 if ok else 1)
