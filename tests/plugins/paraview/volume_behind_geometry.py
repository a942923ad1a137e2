# SPDX-License-Identifier: MIT
"""Run by pvbatch: an opaque box between the eye and a volume drawn by "volpost Volume" hides
the volume behind it, and the volume elsewhere is what it is without the box. And the view's
depth peeling of volumes (on by default in ParaView's window, where the ray caster's picture
drawn inside the peeling pass showed as garbage around the volume) is off while it draws.

Three pictures with one camera: the box alone, the volume alone, both. Where the box covers
the picture (its outline, blended by multisampling, left out), both must equal the box alone;
elsewhere, the volume alone (within 1/255).

Usage: pvbatch volume_behind_geometry.py PLUGIN OUTDIR
"""
import math
import os
import sys

import numpy as np
from paraview.simple import (Box, CreateView, GetColorTransferFunction, GetOpacityTransferFunction, LegacyVTKReader,
                             LoadPlugin, Render, SaveScreenshot, Show)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scenes import kuhn_grid, png  # noqa: E402

plugin, outdir = sys.argv[1:3]
LoadPlugin(plugin, remote=False, ns=globals())
os.makedirs(outdir, exist_ok=True)
WIDTH, HEIGHT = 160, 120

grid_path = os.path.join(outdir, "kuhn_grid_behind.vtk")
kuhn_grid(grid_path)
grid = LegacyVTKReader(FileNames=[grid_path])
center = [0.5, 0.5, 0.5]
size = math.sqrt(3.0)
eye = [center[0] + 1.1 * size, center[1] - 0.8 * size, center[2] + 0.9 * size]
# A box a third of the way from the eye: wholly in front of the grid, covering part of it.
box = Box(XLength=0.12, YLength=0.12, ZLength=0.12,
          Center=[c + 0.62 * (e - c) for c, e in zip(center, eye)])

colors = GetColorTransferFunction("wave")
colors.ColorSpace = "RGB"
colors.RGBPoints = [-0.9, 0.1, 0.2, 0.9, 0.3, 0.9, 0.9, 0.3, 1.5, 0.9, 0.1, 0.1]
opacity = GetOpacityTransferFunction("wave")
opacity.Points = [-0.9, 0.0, 0.5, 0.0, 0.3, 0.6, 0.5, 0.0, 1.5, 0.15, 0.5, 0.0]


views = []


def picture(name, with_volume, with_box):
    """One view of its own per picture: ParaView fits the camera on a view's first picture
    (and again when what it shows changes), so each view gets ours after that."""
    view = CreateView("RenderView")
    views.append(view)
    view.ViewSize = [WIDTH, HEIGHT]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    if with_volume:
        volume = Show(grid, view)
        volume.ColorArrayName = ["POINTS", "wave"]
        volume.LookupTable = colors
        volume.ScalarOpacityFunction = opacity
        volume.ScalarOpacityUnitDistance = size / 20.0
        volume.SetRepresentationType("volpost Volume")
    if with_box:
        solid = Show(box, view)
        solid.AmbientColor = solid.DiffuseColor = [0.2, 0.8, 0.3]
    Render(view)
    view.CameraPosition = eye
    view.CameraFocalPoint = center
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    Render(view)
    path = os.path.join(outdir, name + ".png")
    SaveScreenshot(path, view, ImageResolution=[WIDTH, HEIGHT])
    return png(path)


both = picture("both", True, True)
box_alone = picture("box_alone", False, True)
volume_alone = picture("volume_alone", True, False)

# The box's outline pixels are a blend of box and what lies behind (multisampling): left out.
drawn = box_alone.max(axis=2) > 0
covered = drawn.copy()
for dy, dx in ((1, 0), (-1, 0), (0, 1), (0, -1)):
    covered &= np.roll(np.roll(drawn, dy, 0), dx, 1)
failures = []
if covered.sum() < 100 or (volume_alone.max(axis=2) > 8).sum() < 1000:
    failures.append(f"the scene is not as meant: {covered.sum()} box pixels")
behind = np.abs(both - box_alone)[covered].max()
elsewhere = np.abs(both - volume_alone)[~drawn].max()
hidden = int((volume_alone.max(axis=2)[covered] > 8).sum())
print(f"box covers {int(covered.sum())} pixels ({hidden} of them over the volume): largest difference there "
      f"{behind}/255 from the box alone; elsewhere {elsewhere}/255 from the volume alone")
if hidden < 50:
    failures.append("the box hides too little of the volume to tell")
if behind > 1:
    failures.append(f"the volume shows through the box in front of it ({behind}/255)")
if elsewhere > 1:
    failures.append(f"the volume beside the box changed ({elsewhere}/255)")
# Each view starts with ParaView's default (peel volumes too); the one with the volume drew it
# with volume peeling off, the one without is left as it was.
peeling = [(bool(v.DepthPeelingForVolumes), bool(v.GetRenderer().GetUseDepthPeelingForVolumes())) for v in views]
print(f"depth peeling of volumes (the view's setting, the renderer's while drawing): {peeling}")
if peeling != [(True, False), (True, True), (True, False)]:
    failures.append("the views with volpost Volume still peel volumes (or the setting is not ParaView's default)")
for f in failures:
    print("FAIL:", f)
if failures:
    raise SystemExit(f"{len(failures)} failure(s)")
