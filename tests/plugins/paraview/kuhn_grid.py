# SPDX-License-Identifier: MIT
"""Small test grids for the ParaView plugin's pvbatch scripts: tetrahedra and hexahedra."""
import math

import numpy as np
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, VTK_TETRA, vtkUnstructuredGrid
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridWriter


def kuhn_grid(path, n=6):
    """n^3 cubes over [0,1]^3, each split into the six Kuhn tetrahedra around its diagonal,
    f = sin(3x)cos(2y) + 0.5 sin(4z + 2x) at the nodes."""
    points = vtkPoints()
    points.SetDataTypeToDouble()
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
    at = lambda i, j, k: i + (n + 1) * (j + (n + 1) * k)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    kuhn = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
    for k in range(n):
        for j in range(n):
            for i in range(n):
                for tet in kuhn:
                    c = [corners[v] for v in tet]
                    e = [np.subtract(c[m], c[0]) for m in (1, 2, 3)]
                    ids = [at(i + dx, j + dy, k + dz) for dx, dy, dz in c]
                    if np.dot(np.cross(e[0], e[1]), e[2]) < 0:  # VTK's positive orientation
                        ids[1], ids[2] = ids[2], ids[1]
                    grid.InsertNextCell(VTK_TETRA, 4, ids)
    # Legacy VTK: ParaView 5.11's XML readers stop early on Debian 12 (docs/user/paraview.md),
    # on the ranks past the first even with inline data.
    writer = vtkUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.SetFileTypeToBinary()
    writer.Write()


def hex_block(path, n=6):
    """n^3 hexahedra over [0,1]^3 with the same wave at the nodes."""
    points = vtkPoints()
    points.SetDataTypeToDouble()
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
    at = lambda i, j, k: i + (n + 1) * (j + (n + 1) * k)
    for k in range(n):
        for j in range(n):
            for i in range(n):
                ids = [at(i, j, k), at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j + 1, k),
                       at(i, j, k + 1), at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1)]
                grid.InsertNextCell(VTK_HEXAHEDRON, 8, ids)
    writer = vtkUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.SetFileTypeToBinary()
    writer.Write()
