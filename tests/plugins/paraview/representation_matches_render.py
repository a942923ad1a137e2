# SPDX-License-Identifier: MIT
"""Run by pvbatch: "volpost Volume" in ParaView draws what `volpost render --renderer cpu` draws
of the same grid, camera, picture size and transfer function, within 1/255 per channel.

The grid is a Kuhn grid of tetrahedra carrying a smooth wave, or a file given on the command
line (tetrahedra: ParaView hands every volume mapper tetrahedra, splitting other cells its own
way, so only tetrahedral meshes draw the same field as `volpost render`). Under MPI (mpirun
-np N pvbatch --mpi) the picture would be the ranks' pieces composited by ParaView, allowed
2/255 (ParaView 5.11 on Debian 12 moves pieces between ranks only with
libvolpost_expat_eager.so preloaded, and the composite is not yet that close everywhere:
parallel_composite.py measures it). ParaView's color
map (linear RGB) and opacity function become volpost's transfer function by the rule
docs/user/paraview.md states, written here independently: control points at every node and
at 257 evenly spaced values, extinction -ln(1 - opacity) / unit distance.

Usage: pvbatch representation_matches_render.py [--hexahedra] [--element] [--clip] PLUGIN VOLPOST OUTDIR [FILE ARRAY]...
(--hexahedra: the made grid is of hexahedra, which volpost splits itself in one process;
--element: both sides draw the cells' own field, default tolerance; --clip: both sides cut
the volume with the same oblique plane through the grid's centre, ParaView's by the
representation's Clip properties, volpost's by --clip.)
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import (GetColorTransferFunction, GetOpacityTransferFunction, LoadPlugin, OpenDataFile,
                             Render, SaveScreenshot, Show, CreateView, XMLUnstructuredGridReader)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scenes import hex_block, kuhn_grid, png  # noqa: E402

ELEMENT = "--element" in sys.argv  # the cells' own field on both sides
HEXAHEDRA = "--hexahedra" in sys.argv  # the made grid of hexahedra rather than tetrahedra
CLIP = "--clip" in sys.argv  # an oblique clip plane through the centre on both sides
arguments = [a for a in sys.argv if a not in ("--element", "--hexahedra", "--clip")]
plugin, volpost, outdir = arguments[1:4]
RANKS = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
ALLOWED = 1 if RANKS == 1 else 2
LoadPlugin(plugin, remote=False, ns=globals())
os.makedirs(outdir, exist_ok=True)
WIDTH, HEIGHT = 160, 120


def volpost_tf(rgb_points, opacity_points, unit):
    """The documented rule, from ParaView's nodes (linear RGB, linear opacity)."""
    rgb = np.array(rgb_points).reshape(-1, 4)
    opa = np.array(opacity_points).reshape(-1, 4)
    low, high = min(rgb[0, 0], opa[0, 0]), max(rgb[-1, 0], opa[-1, 0])
    at = np.unique(np.concatenate([rgb[:, 0], opa[:, 0], low + (high - low) * np.arange(257) / 256]))
    points = []
    for v in at:
        color = [float(np.interp(v, rgb[:, 0], rgb[:, c])) for c in (1, 2, 3)]
        o = min(max(float(np.interp(v, opa[:, 0], opa[:, 1])), 0.0), 1.0)
        extinction = 1e20 if o >= 1.0 else min(-math.log1p(-o) / unit, 1e20)
        points.append({"value": float(v), "color": color, "extinction": extinction})
    return {"format": "volpost-tf", "version": 1, "points": points}


cases = list(zip(arguments[4::2], arguments[5::2]))
if not cases:
    grid_path = os.path.join(outdir, "hex_block.vtk" if HEXAHEDRA else "kuhn_grid.vtk")
    (hex_block if HEXAHEDRA else kuhn_grid)(grid_path)
    cases.append((grid_path, "wave"))

failures = []
for path, array in cases:
    name = os.path.basename(path)
    reader = XMLUnstructuredGridReader(FileName=[path]) if path.endswith(".vtu") else OpenDataFile(path)
    reader.UpdatePipeline()
    low, high = reader.PointData[array].GetRange()
    bounds = reader.GetDataInformation().GetBounds()
    center = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
    size = math.dist(bounds[0::2], bounds[1::2])
    eye = [center[0] + 1.1 * size, center[1] - 0.8 * size, center[2] + 0.9 * size]
    up = [0.0, 0.0, 1.0]
    unit = size / 20.0
    mid = low + 0.55 * (high - low)
    rgb_points = [low, 0.1, 0.2, 0.9, mid, 0.9, 0.9, 0.3, high, 0.9, 0.1, 0.1]
    opacity_points = [low, 0.0, 0.5, 0.0, mid, 0.6, 0.5, 0.0, high, 0.15, 0.5, 0.0]

    view = CreateView("RenderView")
    view.ViewSize = [WIDTH, HEIGHT]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    display = Show(reader, view)
    display.ColorArrayName = ["POINTS", array]
    colors = GetColorTransferFunction(array)
    colors.ColorSpace = "RGB"
    colors.Discretize = 0  # the color map itself, not a table of 256 colors from it
    colors.RGBPoints = rgb_points
    opacity = GetOpacityTransferFunction(array)
    opacity.Points = opacity_points
    display.LookupTable = colors
    display.ScalarOpacityFunction = opacity
    display.ScalarOpacityUnitDistance = unit
    display.SetRepresentationType("volpost Volume")
    display.EarlyTermination = 0.0
    if ELEMENT:
        display.CellInterpolation = "Cells' own field"
    clip_normal = [0.8, 0.5, -0.33]  # keeps the far side from the eye: the cut face shows
    if CLIP:
        display.Clipping = 1
        display.ClipOrigin = center
        display.ClipNormal = clip_normal
    Render(view)  # ParaView fits the camera to the data on a view's first picture: then set ours
    view.CameraPosition = eye
    view.CameraFocalPoint = center
    view.CameraViewUp = up
    view.CameraViewAngle = 30.0
    Render(view)
    variant = (".element" if ELEMENT else "") + (".clip" if CLIP else "")
    paraview_png = os.path.join(outdir, f"{name}{variant}.paraview{RANKS}.png")
    SaveScreenshot(paraview_png, view, ImageResolution=[WIDTH, HEIGHT])

    tf_path = os.path.join(outdir, name + ".tf.json")
    with open(tf_path, "w") as f:
        json.dump(volpost_tf(rgb_points, opacity_points, unit), f)
    volpost_png = os.path.join(outdir, name + variant + ".volpost.png")
    command = [volpost, "render", path, "--renderer", "cpu", "--field", array, "--tf", tf_path,
               "--eye", ",".join(map(repr, eye)), "--target", ",".join(map(repr, center)), "--up", "0,0,1",
               "--view-angle", "30", "--size", f"{WIDTH}x{HEIGHT}", "--background", "black", "--no-legend",
               "--no-triad", "--termination", "0", "-o", volpost_png]
    if ELEMENT:
        command[3:3] = ["--interpolation", "element"]
    if CLIP:
        command[3:3] = ["--clip", ",".join(map(repr, center + clip_normal))]
    if os.environ.get("VOLPOST_PV_SHOW_COMMAND"):
        print(" ".join(command))
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        failures.append(f"{name}: volpost render failed: {done.stdout}{done.stderr}")
        continue
    a, b = png(paraview_png), png(volpost_png)
    difference = np.abs(a - b)
    lit = int((b.max(axis=2) > 8).sum())
    print(f"{name}, {RANKS} rank(s): largest difference {difference.max()}/255, {int((difference > 1).any(axis=2).sum())} pixels "
          f"off by more than 1, {lit} lit pixels")
    if lit < WIDTH * HEIGHT // 20:
        failures.append(f"{name}: the volpost picture is nearly empty ({lit} lit pixels)")
    if CLIP:
        # The cut must show: the same scene without the plane differs by far more than the allowance.
        display.Clipping = 0
        Render(view)
        whole_png = os.path.join(outdir, f"{name}{variant}.unclipped{RANKS}.png")
        SaveScreenshot(whole_png, view, ImageResolution=[WIDTH, HEIGHT])
        cut = int((np.abs(png(whole_png) - a) > 16).any(axis=2).sum())
        print(f"{name}: the plane changed {cut} pixels by more than 16/255")
        if cut < WIDTH * HEIGHT // 20:
            failures.append(f"{name}: the clip plane changed only {cut} pixels")
    if difference.max() > ALLOWED:
        failures.append(f"{name}: ParaView's picture ({RANKS} ranks) differs from volpost render's by "
                        f"{difference.max()}/255, more than {ALLOWED}")

for f in failures:
    print("FAIL:", f)
if failures:
    raise SystemExit(f"{len(failures)} failure(s)")
