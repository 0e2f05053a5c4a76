"""render_damage_paraview.py - render a cdmpm run with ParaView: the particles of one frame coloured by ice
`damage` (0 intact to 1 broken), water shown apart in blue. Frames write damage as NaN on materials without it
(water), so the water takes ParaView's NaN colour, set here to blue; nothing else is needed to tell them apart.

    xvfb-run -a pvpython tools/render_damage_paraview.py RUN_DIR [--time T] [--out FOLDER] [--size 1600 500]

Reads RUN_DIR/particles.pvd (compressed or not), picks the frame at or after time T (default: the last), and
writes FOLDER/damage_t<T>.png (default FOLDER: RUN_DIR/plots; a folder holding committed files is refused
unless --force) and prints what it drew: the frame, the number of
particles, how many are ice and how many are water, and the damage range. 2D runs are viewed from +z, 3D runs
from an oblique angle. (Debian packages paraview and xvfb.)
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdmpm_tools.cli import add_output_arguments, fail as fail_as, output_folder  # noqa: E402
from cdmpm_tools.plotting import ICE_DAMAGE_COLOURS  # noqa: E402

TOOL = "render_damage_paraview"


def fail(message):
    fail_as(TOOL, message)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="a cdmpm run folder (with particles.pvd)")
    ap.add_argument("--time", type=float, help="frame time [s] (default: the last frame)")
    add_output_arguments(ap, "output folder (default RUN/plots)")
    ap.add_argument("--size", type=int, nargs=2, default=[1600, 500], metavar=("W", "H"), help="image size [px]")
    args = ap.parse_args()
    pvd = os.path.join(args.run, "particles.pvd")
    if not os.path.isfile(pvd):
        fail(f"{args.run}: no particles.pvd (not a cdmpm run folder, or a run without frames)")
    try:
        from paraview import servermanager
        from paraview import simple as pv
        from vtkmodules.util.numpy_support import vtk_to_numpy
    except ImportError as e:
        fail(f"needs ParaView's python (run with pvpython from Debian's paraview package): {e}")
    folder = output_folder(TOOL, args.out or os.path.join(args.run, "plots"), args.force)

    reader = pv.PVDReader(FileName=pvd)
    times = list(reader.TimestepValues or [0.0])
    t = times[-1] if args.time is None else next((s for s in times if s >= args.time - 1e-12), times[-1])
    reader.UpdatePipeline(t)
    grid = servermanager.Fetch(reader)
    n = grid.GetNumberOfPoints()
    damage_array = grid.GetPointData().GetArray("damage")
    if damage_array is None:
        fail(f"{args.run}: the frames have no damage field (a run without ice)")
    damage = vtk_to_numpy(damage_array)
    import numpy as np
    ice = ~np.isnan(damage)
    bounds = grid.GetBounds()
    three_d = bounds[5] - bounds[4] > 0

    view = pv.CreateView("RenderView")
    view.ViewSize = args.size
    view.Background = [1, 1, 1]
    try:  # ParaView >= 5.10 uses a palette unless told to use the view's own background
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.OrientationAxesVisibility = 0
    view.ViewTime = t
    display = pv.Show(reader, view)
    display.SetRepresentationType("Points")
    display.PointSize = max(1.0, min(4.0, 4e5 / max(n, 1) ** 0.5 / 100))
    pv.ColorBy(display, ("POINTS", "damage"))
    lut = pv.GetColorTransferFunction("damage")
    # The ice colours of cdmpm_tools.plotting, at damage 0, 0.5 and 1.
    lut.RGBPoints = [v for d, rgb in zip((0.0, 0.5, 1.0), ICE_DAMAGE_COLOURS) for v in (d, *rgb)]
    lut.ColorSpace = "RGB"
    lut.RescaleTransferFunction(0.0, 1.0)
    lut.NanColor = [0.23, 0.48, 0.84]  # water: no damage field, drawn blue
    bar = pv.GetScalarBar(lut, view)
    bar.Title = "ice damage [-]"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    display.SetScalarBarVisibility(view, True)
    text = pv.Text(Text=f"t = {t:.3g} s   ice coloured by damage (0 intact, 1 broken), water in blue")
    text_display = pv.Show(text, view)
    text_display.Color = [0, 0, 0]
    text_display.FontSize = 14
    text_display.WindowLocation = "Upper Left Corner"
    view.ResetCamera()
    if three_d:
        cam = view.GetActiveCamera()
        cam.Elevation(25)
        cam.Azimuth(-35)
        view.ResetCamera()
    else:
        view.CameraParallelProjection = 1
        width, height = bounds[1] - bounds[0], bounds[3] - bounds[2]
        aspect = args.size[0] / args.size[1]
        view.CameraParallelScale = 0.55 * max(height, width / aspect)
    png = os.path.join(folder, f"damage_t{t:g}.png")
    pv.SaveScreenshot(png, view, ImageResolution=args.size)
    d = damage[ice]
    print(f"{png}: frame t = {t:g} s, {n} particles: {int(ice.sum())} ice (damage {d.min() if d.size else math.nan:.3g}"
          f" .. {d.max() if d.size else math.nan:.3g}), {int((~ice).sum())} water (NaN damage, blue)")


if __name__ == "__main__":
    main()
