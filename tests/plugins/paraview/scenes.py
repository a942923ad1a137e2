# SPDX-License-Identifier: MIT
"""What the ParaView plugin's pvbatch scripts share: small test grids (tetrahedra and
hexahedra over [0,1]^3 carrying a smooth wave) and reading back a saved picture."""
import math

import numpy as np
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, VTK_TETRA, vtkUnstructuredGrid
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridWriter
from vtkmodules.util.numpy_support import vtk_to_numpy


def _wave_nodes(n):
    """The (n+1)^3 nodes of the cubes, exact in double, with f = sin(3x)cos(2y) +
    0.5 sin(4z + 2x); and the index of node (i, j, k)."""
    points = vtkPoints()
    points.SetDataTypeToDouble()  # the nodes written as computed, as volpost reads them
    values = vtkDoubleArray()
    values.SetName("wave")
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                x, y, z = i / n, j / n, k / n
                points.InsertNextPoint(x, y, z)
                values.InsertNextValue(math.sin(3 * x) * math.cos(2 * y) + 0.5 * math.sin(4 * z + 2 * x))
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points)
    grid.GetPointData().AddArray(values)
    return grid, lambda i, j, k: i + (n + 1) * (j + (n + 1) * k)


def _write(grid, path):
    # Legacy VTK: ParaView 5.11's XML readers stop early on Debian 12 (docs/user/paraview.md),
    # on the ranks past the first even with inline data.
    writer = vtkUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.SetFileTypeToBinary()
    writer.Write()


CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def kuhn_grid(path, n=6):
    """n^3 cubes, each split into the six Kuhn tetrahedra around its diagonal."""
    grid, at = _wave_nodes(n)
    kuhn = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
    for k in range(n):
        for j in range(n):
            for i in range(n):
                for tet in kuhn:
                    c = [CORNERS[v] for v in tet]
                    e = [np.subtract(c[m], c[0]) for m in (1, 2, 3)]
                    ids = [at(i + dx, j + dy, k + dz) for dx, dy, dz in c]
                    if np.dot(np.cross(e[0], e[1]), e[2]) < 0:  # VTK's positive orientation
                        ids[1], ids[2] = ids[2], ids[1]
                    grid.InsertNextCell(VTK_TETRA, 4, ids)
    _write(grid, path)


def hex_block(path, n=6):
    """n^3 hexahedra."""
    grid, at = _wave_nodes(n)
    for k in range(n):
        for j in range(n):
            for i in range(n):
                grid.InsertNextCell(VTK_HEXAHEDRON, 8, [at(i + dx, j + dy, k + dz) for dx, dy, dz in CORNERS])
    _write(grid, path)


def png(path):
    """A saved picture as rows of RGB integers, top row first."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3].astype(int)
