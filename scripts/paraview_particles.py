"""Opens a run's particles in ParaView ready to look at: the particles as discs coloured by
tau_max (theory E13, the isochromatics' quantity) on one colour scale over all output times, at
the last output time.

  pvpython scripts/paraview_particles.py RUN_DIR [--array NAME] [--png FILE]
      --png: render the last time to FILE (no window needed) and exit
  paraview --script=scripts/paraview_particles.py   (asks nothing: set RUPTURE_RUN=RUN_DIR)

Why: the first snapshot (t = 0) is at rest, so ParaView's automatic colour range is [0, 0]
until rescaled; this script rescales over every time.
"""
import os
import sys

from paraview import simple

args = [a for a in sys.argv[1:]]
run = os.environ.get("RUPTURE_RUN") or (args[0] if args and not args[0].startswith("--") else ".")
array = args[args.index("--array") + 1] if "--array" in args else "tau_max"
png = args[args.index("--png") + 1] if "--png" in args else None

reader = simple.Xdmf3ReaderS(FileName=[os.path.join(run, "particles.xdmf")])
times = list(reader.TimestepValues)
lo, hi = float("inf"), float("-inf")
for t in times:  # one colour scale across all times (the t = 0 field is all zero)
    reader.UpdatePipeline(t)
    r = reader.PointData[array].GetRange(-1 if array == "velocity" else 0)
    lo, hi = min(lo, r[0]), max(hi, r[1])
view = simple.GetActiveViewOrCreate("RenderView")
view.ViewTime = times[-1]
display = simple.Show(reader, view)
# Each particle as a disc of its spacing: the bounding box's area over the particle count.
b = reader.GetDataInformation().GetBounds()
n = reader.GetDataInformation().GetNumberOfPoints()
spacing = ((b[1] - b[0]) * (b[3] - b[2]) / max(n, 1)) ** 0.5
display.SetRepresentationType("Point Gaussian")
display.ShaderPreset = "Plain circle"
display.GaussianRadius = 0.5 * spacing
simple.ColorBy(display, ("POINTS", array))
lut = simple.GetColorTransferFunction(array)
lut.RescaleTransferFunction(lo, hi)
lut.AutomaticRescaleRangeMode = "Never"
display.SetScalarBarVisibility(view, True)
view.InteractionMode = "2D"
simple.ResetCamera(view)
scene = simple.GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = times[-1]
print(f"{run}/particles.xdmf: {len(times)} times, {array} in [{lo:.4g}, {hi:.4g}], showing t = {times[-1]:.4g} s")
if png:
    simple.SaveScreenshot(png, view, ImageResolution=[1200, 900])
    print(f"wrote {png}")
