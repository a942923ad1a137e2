#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""How far the tetrahedra's piecewise-linear field is from the cells' own field.

Writes [0,1]^3 meshes of 8^3 cells (tet4 from a six-tet split of each cube, hex8, hex20,
tet10 from the same six-tet split with midside nodes) carrying one smooth wave field at
every node, draws each with `volpost render --renderer reference` twice (--interpolation
tetrahedra and element) at 256x256 through a sharp opacity peak, and prints a Markdown
table: the two pictures' RMSE, largest difference and pixels off by more than 0.05 (RGBA
premultiplied floats), with the wall time of each render (the reading of the file and the
split included).

    /usr/bin/python3 docs/scripts/element_field_error.py build/bin/volpost [cells] [size]
"""
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

KUHN = [(0, 1, 3, 7), (0, 1, 5, 7), (0, 2, 3, 7), (0, 2, 6, 7), (0, 4, 5, 7), (0, 4, 6, 7)]
HEX_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
TET_EDGES = [(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)]
VTK_TYPE = {"tet4": 10, "hex8": 12, "hex20": 25, "tet10": 24}


def field(p):
    x, y, z = p
    return math.sin(3.0 * x) * math.cos(2.0 * y) + 0.5 * math.sin(4.0 * z + 2.0 * x)


def mesh(kind, n):
    """Nodes on a lattice of step 1/(2n) (midside nodes included), cells as node lists."""
    index, nodes, cells = {}, [], []

    def node(key):  # key: integer lattice coordinates, step 1/(2n)
        if key not in index:
            index[key] = len(nodes)
            nodes.append(tuple(k / (2.0 * n) for k in key))
        return index[key]

    def mid(a, b):
        return tuple((u + v) // 2 for u, v in zip(a, b))

    for k in range(n):
        for j in range(n):
            for i in range(n):
                # Cube corners in VTK hexahedron order, then in bit order (x, y, z bits).
                corner = lambda dx, dy, dz: (2 * (i + dx), 2 * (j + dy), 2 * (k + dz))
                hexc = [corner(0, 0, 0), corner(1, 0, 0), corner(1, 1, 0), corner(0, 1, 0),
                        corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1)]
                bits = [corner(b & 1, (b >> 1) & 1, (b >> 2) & 1) for b in range(8)]
                if kind in ("hex8", "hex20"):
                    ids = [node(c) for c in hexc]
                    if kind == "hex20":
                        ids += [node(mid(hexc[a], hexc[b])) for a, b in HEX_EDGES]
                    cells.append(ids)
                else:
                    for t in KUHN:
                        c = [bits[v] for v in t]
                        ids = [node(p) for p in c]
                        if kind == "tet10":
                            ids += [node(mid(c[a], c[b])) for a, b in TET_EDGES]
                        cells.append(ids)
    return nodes, cells


def write_vtk(path, kind, n):
    nodes, cells = mesh(kind, n)
    with open(path, "w") as out:
        out.write(f"# vtk DataFile Version 4.2\n{kind} block\nASCII\nDATASET UNSTRUCTURED_GRID\n")
        out.write(f"POINTS {len(nodes)} double\n")
        out.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in nodes)
        out.write(f"CELLS {len(cells)} {sum(len(c) + 1 for c in cells)}\n")
        out.writelines(f"{len(c)} " + " ".join(map(str, c)) + "\n" for c in cells)
        out.write(f"CELL_TYPES {len(cells)}\n" + f"{VTK_TYPE[kind]}\n" * len(cells))
        out.write(f"POINT_DATA {len(nodes)}\nSCALARS wave double 1\nLOOKUP_TABLE default\n")
        out.writelines(f"{field(p)!r}\n" for p in nodes)
    return len(cells)


TF = """{"format": "volpost-tf", "version": 1, "points": [
 {"value": -1.6, "color": [0.2, 0.3, 0.9], "extinction": 0.0},
 {"value": 0.30, "color": [0.2, 0.6, 0.9], "extinction": 0.0},
 {"value": 0.40, "color": [1.0, 0.7, 0.2], "extinction": 40.0},
 {"value": 0.50, "color": [0.9, 0.2, 0.1], "extinction": 0.0},
 {"value": 1.6, "color": [0.9, 0.2, 0.1], "extinction": 0.0}]}"""


def npy(path):
    return np.load(path).astype(np.float64)


def main():
    volpost = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    size = int(sys.argv[3]) if len(sys.argv) > 3 else 256
    work = tempfile.mkdtemp(prefix="element_field_")
    tf = os.path.join(work, "peak.json")
    open(tf, "w").write(TF)
    print(f"| mesh of [0,1]^3, {n}^3 cubes | cells | RMSE | max | pixels off by > 0.05 | "
          f"time, tetrahedra | time, element |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for kind in ("tet4", "hex8", "hex20", "tet10"):
        model = os.path.join(work, kind + ".vtk")
        count = write_vtk(model, kind, n)
        pictures, seconds = {}, {}
        for how in ("tetrahedra", "element"):
            out = os.path.join(work, f"{kind}_{how}.npy")
            args = [volpost, "render", model, "--field", "wave", "--renderer", "reference", "--tf", tf,
                    "--interpolation", how, "--size", f"{size}x{size}", "--camera", "iso",
                    "-o", os.path.join(work, f"{kind}_{how}.png"), "--float", out]
            start = time.monotonic()
            subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
            seconds[how] = time.monotonic() - start
            pictures[how] = npy(out)
        d = pictures["element"] - pictures["tetrahedra"]
        rmse = math.sqrt(float(np.mean(d * d)))
        off = int(np.count_nonzero(np.max(np.abs(d), axis=-1) > 0.05))
        print(f"| {kind} | {count} | {rmse:.2g} | {np.max(np.abs(d)):.2g} | {off} | "
              f"{seconds['tetrahedra']:.1f} s | {seconds['element']:.1f} s |")


if __name__ == "__main__":
    main()
