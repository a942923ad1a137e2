# SPDX-License-Identifier: MIT
"""Run by pvbatch, one process or under MPI: time per frame of volume rendering a Kuhn grid
of n^3 cubes x 6 tetrahedra (n = 128 is 12.6M tets) with "volpost Volume", ParaView's Volume
(projected tetrahedra) and ParaView's Volume of the grid resampled to an image (Resample To
Image, 128^3 samples), the same view, 512x512, ParaView's default color map and opacity ramp
(volpost Volume with its default early termination, 0.002); the RMSE of each picture against
volpost Volume's (8-bit RGB in 0..1).

  mpirun -np N --bind-to none -x LD_PRELOAD=libvolpost_expat_eager.so /usr/bin/time -f "rank peak %M KB" \\
      pvbatch --mpi bench/paraview/volume_ranks.py PLUGIN N_CUBES OUTDIR [REPRESENTATION...]

Representations: volpost, projected, resampled (default: all three). Peak memory per rank
comes from /usr/bin/time around each rank. The grid file is made on the first run (numpy).
"""
import os
import statistics
import sys
import time

import numpy as np
from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, Delete, Hide, LoadPlugin, OpenDataFile, Render, ResampleToImage,
                             SaveScreenshot, Show)
from vtkmodules.numpy_interface import dataset_adapter as dsa  # noqa: F401
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkCellArray, vtkUnstructuredGrid
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridWriter

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "plugins", "paraview"))
from scenes import png  # noqa: E402

SIZE = 512


def kuhn_file(path, n):
    """n^3 unit cubes scaled to [0,1]^3, six Kuhn tets each, f = sin(3x)cos(2y) + 0.5 sin(4z + 2x)."""
    m = n + 1
    k, j, i = np.meshgrid(np.arange(m), np.arange(m), np.arange(m), indexing="ij")
    xyz = np.stack([i.ravel(), j.ravel(), k.ravel()], axis=1).astype(np.float64) / n
    f = np.sin(3 * xyz[:, 0]) * np.cos(2 * xyz[:, 1]) + 0.5 * np.sin(4 * xyz[:, 2] + 2 * xyz[:, 0])
    base = (np.arange(n)[:, None, None] * m * m + np.arange(n)[None, :, None] * m + np.arange(n)[None, None, :]).ravel()
    corner = [0, 1, 1 + m, m, m * m, m * m + 1, m * m + 1 + m, m * m + m]  # offsets of the cube's 8 corners
    kuhn = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
    tets = []
    for t in kuhn:
        ids = np.stack([base + corner[c] for c in t], axis=1)
        p = xyz[ids[:1]][0]
        if np.dot(np.cross(p[1] - p[0], p[2] - p[0]), p[3] - p[0]) < 0:  # VTK's positive orientation
            ids[:, [1, 2]] = ids[:, [2, 1]]
        tets.append(ids)
    connectivity = np.concatenate(tets).astype(np.int64)
    count = connectivity.shape[0]
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(np.arange(0, 4 * count + 1, 4, dtype=np.int64), deep=True),
                  numpy_to_vtkIdTypeArray(connectivity.ravel(), deep=True))
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=True))
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points)
    grid.SetCells(VTK_TETRA, cells)
    values = numpy_to_vtk(f, deep=True)
    values.SetName("wave")
    grid.GetPointData().AddArray(values)
    writer = vtkUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.SetFileTypeToBinary()
    writer.Write()
    return count


def main():
    plugin, n, outdir = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    wanted = sys.argv[4:] or ["volpost", "projected", "resampled"]
    LoadPlugin(plugin, remote=False, ns=globals())
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    os.makedirs(outdir, exist_ok=True)
    path = os.path.join(outdir, f"kuhn{n}.vtk")
    if not os.path.exists(path):
        start = time.time()
        count = kuhn_file(path, n)
        print(f"made {path}: {count} tets in {time.time() - start:.1f} s", flush=True)
    reader = OpenDataFile(path)
    start = time.time()
    reader.UpdatePipeline()
    print(f"read in {time.time() - start:.1f} s on {ranks} rank(s)", flush=True)
    view = CreateView("RenderView")
    view.ViewSize = [SIZE, SIZE]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    pictures = {}
    for name in wanted:
        source = reader
        if name == "resampled":
            start = time.time()
            source = ResampleToImage(Input=reader, SamplingDimensions=[128, 128, 128])
            source.UpdatePipeline()
            print(f"resampled to 128^3 in {time.time() - start:.1f} s", flush=True)
        display = Show(source, view)
        display.SetRepresentationType("volpost Volume" if name == "volpost" else "Volume")
        ColorBy(display, ("POINTS", "wave"))
        display.RescaleTransferFunctionToDataRange(True)
        start = time.time()
        Render(view)
        first = time.time() - start
        frames = []
        for k in range(4):  # turning 7 degrees a frame, as the one-process figure
            view.CameraPosition = [0.5 + 1.9 * np.cos(0.3 + k * 0.122), 0.5 - 1.9 * np.sin(0.3 + k * 0.122), 2.0]
            view.CameraFocalPoint = [0.5, 0.5, 0.5]
            view.CameraViewUp = [0.0, 0.0, 1.0]
            start, cpu = time.time(), time.process_time()
            Render(view)
            frames.append((time.time() - start, time.process_time() - cpu))
        picture = os.path.join(outdir, f"{name}_{n}_{ranks}.png")
        SaveScreenshot(picture, view, ImageResolution=[SIZE, SIZE])
        pictures[name] = png(picture) / 255.0
        wall = statistics.median(f[0] for f in frames[1:])
        print(f"{name}, n={n}, {ranks} rank(s): first picture {first:.2f} s, then {1000 * wall:.0f} ms per frame "
              f"(wall, median of 3; first rank's CPU {1000 * statistics.median(f[1] for f in frames[1:]):.0f} ms)",
              flush=True)
        Hide(source, view)
        if source is not reader:
            Delete(source)
    if "volpost" in pictures:
        for name, picture in pictures.items():
            if name != "volpost":
                rmse = float(np.sqrt(np.mean((picture - pictures["volpost"]) ** 2)))
                print(f"{name}: RMSE {rmse:.4f} against volpost Volume", flush=True)


main()
