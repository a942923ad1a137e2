#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes the Crawfis tornado (a vector field used for flow-visualization pictures since the
# 1990s) sampled at the nodes of a tetrahedralized unit cube, as an ASCII VTU that volpost
# reads (plain Python 3, no packages):   python3 docs/scripts/make_tornado.py /tmp/tornado.vtu [N]
# The field: at height z the flow circles a centre (xc, yc) that wanders with z, on a
# radius r(z) that widens upwards, with a small outward and upward drift.
import math
import sys


def tornado(x, y, z, time=0.0):
    xc = 0.5 + 0.1 * math.sin(0.04 * time + 10.0 * z)
    yc = 0.5 + 0.1 * math.cos(0.03 * time + 3.0 * z)
    r = 0.1 + 0.4 * z * z + 0.1 * z * math.sin(8.0 * z)
    r2 = 0.2 + 0.1 * z
    d = math.hypot(y - yc, x - xc)
    scale = abs(r - d)
    scale = 0.8 - scale if scale > r2 else 1.0
    z0 = max(0.1 * (0.1 - d * z), 0.0)
    d = math.hypot(d, z0)
    scale = (r + r2 - d) * scale / (d + 1e-11) / (1.0 + z)
    return (scale * (y - yc) + 0.1 * (x - xc), -scale * (x - xc) + 0.1 * (y - yc), scale * z0)


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 24
    points = [(i / n, j / n, k / n) for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)]
    field = [tornado(*p) for p in points]

    def node(i, j, k):
        return (k * (n + 1) + j) * (n + 1) + i

    def volume(t):
        a, b, c, d = (points[v] for v in t)
        u = [b[q] - a[q] for q in range(3)]
        v = [c[q] - a[q] for q in range(3)]
        w = [d[q] - a[q] for q in range(3)]
        return (u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] + (u[0] * v[1] - u[1] * v[0]) * w[2]

    # Six tets per cube around the diagonal 0-6, the same split in every cube (conforming),
    # each oriented positively (volpost flags inverted cells).
    split = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
    tets = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                c = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                     node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
                for a, b, d, e in split:
                    t = [c[a], c[b], c[d], c[e]]
                    tets.append(t if volume(t) > 0 else [t[0], t[2], t[1], t[3]])

    def rows(values):
        return "\n".join(" ".join(repr(v) for v in row) for row in values)

    with open(out, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian">\n')
        f.write(f'<UnstructuredGrid><Piece NumberOfPoints="{len(points)}" NumberOfCells="{len(tets)}">\n')
        f.write('<PointData Vectors="velocity"><DataArray type="Float64" Name="velocity" NumberOfComponents="3" format="ascii">\n')
        f.write(rows(field) + "\n</DataArray></PointData>\n")
        f.write('<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">\n')
        f.write(rows(points) + "\n</DataArray></Points>\n<Cells>\n")
        f.write('<DataArray type="Int64" Name="connectivity" format="ascii">\n' + rows(tets) + "\n</DataArray>\n")
        f.write('<DataArray type="Int64" Name="offsets" format="ascii">\n')
        f.write(" ".join(str(4 * (c + 1)) for c in range(len(tets))) + "\n</DataArray>\n")
        f.write('<DataArray type="UInt8" Name="types" format="ascii">\n' + " ".join(["10"] * len(tets)))
        f.write("\n</DataArray>\n</Cells></Piece></UnstructuredGrid></VTKFile>\n")
    top = max(math.sqrt(sum(c * c for c in v)) for v in field)
    print(f"{out}: {len(points)} nodes, {len(tets)} tets, largest speed {top:.3g}")


if __name__ == "__main__":
    main()
