# SPDX-License-Identifier: MIT
"""Run by pvbatch: while the view turns, "volpost Volume" draws fewer rays (one per n x n
pixels, n from the last picture's cost so that a frame keeps up with the interactive rate
ParaView asks for, 5 frames per second), and the still render after it draws every pixel.

A Kuhn grid of 32^3 cubes at 800x640: the still picture, then an interactive one (the view
proxy's InteractiveRender, as a drag in the window), each read back from the render window
as drawn. Where the still picture took longer than the interactive budget (200 ms), the
interactive one must be reduced (more neighbouring pixels alike) and close to the still one
(under 5% of the pixels off by more than 16/255); where it did not, the two must be the same.
Then a still render again must give the still picture back.

Usage: pvbatch interactive_frames.py PLUGIN OUTDIR
"""
import os
import sys
import time

import numpy as np
from paraview.simple import ColorBy, CreateView, LegacyVTKReader, LoadPlugin, Render, Show
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scenes import kuhn_grid  # noqa: E402

plugin, outdir = sys.argv[1:3]
LoadPlugin(plugin, remote=False, ns=globals())
os.makedirs(outdir, exist_ok=True)
grid_path = os.path.join(outdir, "kuhn_grid_32.vtk")
kuhn_grid(grid_path, 32)
grid = LegacyVTKReader(FileNames=[grid_path])

view = CreateView("RenderView")
view.ViewSize = [800, 640]
view.OrientationAxesVisibility = 0
volume = Show(grid, view)
volume.SetRepresentationType("volpost Volume")
ColorBy(volume, ("POINTS", "wave"))
view.CameraPosition = [2.5, -1.5, 2.0]
view.CameraFocalPoint = [0.5, 0.5, 0.5]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()


def drawn():
    """The render window's picture as it was drawn (no render of its own)."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ShouldRerenderOff()
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    width, height, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)[:, :, :3].astype(int)


def alike(picture):
    """The share of horizontally neighbouring pixels that are equal."""
    return float((np.abs(picture[:, 1:] - picture[:, :-1]).max(axis=2) == 0).mean())


Render(view)  # the first picture also builds the walk mesh: not timed
start = time.perf_counter()
Render(view)
still_ms = (time.perf_counter() - start) * 1e3
still = drawn()
view.SMProxy.InteractiveRender()
rate = view.GetRenderWindow().GetDesiredUpdateRate()
turning = drawn()
Render(view)
again = drawn()

off = np.abs(turning - still).max(axis=2)
print(f"still picture {still_ms:.0f} ms; interactive rate {rate} frames/s; neighbours alike: still "
      f"{alike(still):.3f}, turning {alike(turning):.3f}; turning off the still picture by more than 16/255 at "
      f"{(off > 16).mean():.2%} of the pixels; still again off by {np.abs(again - still).max()}/255")
failures = []
if alike(still) > 0.95:
    failures.append("the scene is not as meant: the still picture is nearly flat")
if rate < 1.0:
    failures.append(f"ParaView's interactive render asked for {rate} frames/s (expected 5)")
if still_ms > 1000.0 / rate:
    if alike(turning) < alike(still) + 0.05:
        failures.append("the interactive picture was not drawn with fewer rays")
    if (off > 16).mean() > 0.05:
        failures.append("the interactive picture is far from the still one")
elif np.abs(turning - still).max() > 0:
    failures.append("the still picture kept up with the rate, yet the interactive one differs")
if np.abs(again - still).max() > 0:
    failures.append("the still render after the interactive one is not the still picture")
for f in failures:
    print("FAIL:", f)
if failures:
    raise SystemExit(f"{len(failures)} failure(s)")
