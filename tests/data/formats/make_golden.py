#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the hand-made golden files of tests/data/formats (no dependencies).

One small model in every format volpost reads: a unit hex20 at x in [0,1], a wedge15 on
x in [1,2] (triangle (1,0,0) (2,0,0) (1,1,0) extruded in z), and a tet10 at x in [3,4].
Node ids are sparse (10, 20, 30, ...) to exercise id maps. Midside nodes sit exactly at
edge midpoints, so a reader that puts a midside node on the wrong edge is caught by the
test. Each file's element node order is written from that format's own documentation:
Gmsh ("Node ordering"), Abaqus/CalculiX manual figures, CalculiX frd (ccx frd.c writes
he20 and pe15 with the vertical edges before the top ones).
Results: nodal T = x + 10 y + 100 z at two steps (step 2 doubles it); element value
E = 1, 2, 3 per element.
"""
import struct

corners = {
    "hex": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
    # bottom triangle counter-clockwise seen from the top (Gmsh/Abaqus wedge convention)
    "wedge": [(1, 0, 0), (2, 0, 0), (1, 1, 0), (1, 0, 1), (2, 0, 1), (1, 1, 1)],
    "tet": [(3, 0, 0), (4, 0, 0), (3, 1, 0), (3, 0, 1)],
}
edges = {
    "gmsh": {
        "tet": [(0, 1), (1, 2), (2, 0), (3, 0), (3, 2), (3, 1)],
        "hex": [(0, 1), (0, 3), (0, 4), (1, 2), (1, 5), (2, 3), (2, 6), (3, 7), (4, 5), (4, 7), (5, 6), (6, 7)],
        "wedge": [(0, 1), (0, 2), (0, 3), (1, 2), (1, 4), (2, 5), (3, 4), (3, 5), (4, 5)],
    },
    "abaqus": {
        "tet": [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)],
        "hex": [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)],
        "wedge": [(0, 1), (1, 2), (2, 0), (3, 4), (4, 5), (5, 3), (0, 3), (1, 4), (2, 5)],
    },
    "frd": {
        "tet": [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)],
        "hex": [(0, 1), (1, 2), (2, 3), (3, 0), (0, 4), (1, 5), (2, 6), (3, 7), (4, 5), (5, 6), (6, 7), (7, 4)],
        "wedge": [(0, 1), (1, 2), (2, 0), (0, 3), (1, 4), (2, 5), (3, 4), (4, 5), (5, 3)],
    },
}

points = {}  # position -> id
def node_id(p):
    if p not in points:
        points[p] = 10 * (len(points) + 1)
    return points[p]

def element(kind, convention):
    c = corners[kind]
    ids = [node_id(p) for p in c]
    for a, b in edges[convention][kind]:
        mid = tuple((c[a][i] + c[b][i]) / 2 for i in range(3))
        ids.append(node_id(mid))
    return ids

order = ["hex", "wedge", "tet"]
for conv in ("gmsh", "abaqus", "frd"):  # same positions: the id table is shared
    for kind in order:
        element(kind, conv)
nodes = sorted(points.items(), key=lambda kv: kv[1])
def T(p, step):
    return step * (p[0] + 10 * p[1] + 100 * p[2])

def fmt(v):
    return repr(float(v))

gmsh_types = {"hex": 17, "wedge": 18, "tet": 11}
elem_ids = {"hex": 101, "wedge": 102, "tet": 103}
E = {"hex": 1.0, "wedge": 2.0, "tet": 3.0}

def data_sections(binary=False):
    out = b""
    for step in (1, 2):
        head = f'$NodeData\n1\n"T"\n1\n{float(step)}\n3\n{step - 1}\n1\n{len(nodes)}\n'.encode()
        body = b""
        for p, i in nodes:
            body += struct.pack("<id", i, T(p, step)) if binary else f"{i} {fmt(T(p, step))}\n".encode()
        out += head + body + (b"\n" if binary else b"") + b"$EndNodeData\n"
    head = f'$ElementData\n1\n"E"\n1\n0.0\n3\n0\n1\n3\n'.encode()
    body = b""
    for k in order:
        body += struct.pack("<id", elem_ids[k], E[k]) if binary else f"{elem_ids[k]} {fmt(E[k])}\n".encode()
    out += head + body + (b"\n" if binary else b"") + b"$EndElementData\n"
    # element-nodal: each corner of the tet gets 7 + its local index; averaged to nodes.
    head = f'$ElementNodeData\n1\n"EN"\n1\n0.0\n3\n0\n1\n1\n'.encode()
    tet = element("tet", "gmsh")
    vals = [7.0 + k for k in range(len(tet))]
    if binary:
        body = struct.pack("<ii", elem_ids["tet"], len(tet)) + struct.pack(f"<{len(tet)}d", *vals)
    else:
        body = (f"{elem_ids['tet']} {len(tet)} " + " ".join(fmt(v) for v in vals) + "\n").encode()
    out += head + body + (b"\n" if binary else b"") + b"$EndElementNodeData\n"
    return out

def write_gmsh41(path, binary):
    out = b"$MeshFormat\n4.1 %d 8\n" % (1 if binary else 0)
    if binary:
        out += struct.pack("<i", 1) + b"\n"
    out += b"$EndMeshFormat\n"
    out += b'$PhysicalNames\n1\n3 5 "solid"\n$EndPhysicalNames\n'
    # one volume entity with physical tag 5
    if binary:
        out += b"$Entities\n" + struct.pack("<4Q", 0, 0, 0, 1) + struct.pack("<i6dQiQ", 1, 0, 0, 0, 4, 1, 1, 1, 5, 0) + b"\n$EndEntities\n"
    else:
        out += b"$Entities\n0 0 0 1\n1 0 0 0 4 1 1 1 5 0\n$EndEntities\n"
    ids = [i for _, i in nodes]
    if binary:
        out += b"$Nodes\n" + struct.pack("<4Q", 1, len(nodes), min(ids), max(ids)) + struct.pack("<iiiQ", 3, 1, 0, len(nodes))
        out += struct.pack(f"<{len(ids)}Q", *ids)
        for p, _ in nodes:
            out += struct.pack("<3d", *p)
        out += b"\n$EndNodes\n"
    else:
        out += f"$Nodes\n1 {len(nodes)} {min(ids)} {max(ids)}\n3 1 0 {len(nodes)}\n".encode()
        out += "".join(f"{i}\n" for i in ids).encode()
        out += "".join(f"{fmt(p[0])} {fmt(p[1])} {fmt(p[2])}\n" for p, _ in nodes).encode()
        out += b"$EndNodes\n"
    # one block per type, plus a surface triangle block that is skipped
    blocks = [(2, 1, 2, [(900, [10, 20, 30])])] + [(3, 1, gmsh_types[k], [(elem_ids[k], element(k, "gmsh"))]) for k in order]
    total = sum(len(b[3]) for b in blocks)
    if binary:
        out += b"$Elements\n" + struct.pack("<4Q", len(blocks), total, 101, 900)
        for dim, ent, typ, elems in blocks:
            out += struct.pack("<iiiQ", dim, ent, typ, len(elems))
            for eid, ns in elems:
                out += struct.pack(f"<{1 + len(ns)}Q", eid, *ns)
        out += b"\n$EndElements\n"
    else:
        out += f"$Elements\n{len(blocks)} {total} 101 900\n".encode()
        for dim, ent, typ, elems in blocks:
            out += f"{dim} {ent} {typ} {len(elems)}\n".encode()
            for eid, ns in elems:
                out += (" ".join(str(v) for v in [eid] + ns) + "\n").encode()
        out += b"$EndElements\n"
    out += data_sections(binary)
    open(path, "wb").write(out)

def write_gmsh22(path, binary):
    out = b"$MeshFormat\n2.2 %d 8\n" % (1 if binary else 0)
    if binary:
        out += struct.pack("<i", 1) + b"\n"
    out += b"$EndMeshFormat\n$Nodes\n%d\n" % len(nodes)
    for p, i in nodes:
        out += struct.pack("<i3d", i, *p) if binary else f"{i} {fmt(p[0])} {fmt(p[1])} {fmt(p[2])}\n".encode()
    out += (b"\n" if binary else b"") + b"$EndNodes\n"
    elems = [(900, 2, [10, 20, 30])] + [(elem_ids[k], gmsh_types[k], element(k, "gmsh")) for k in order]
    out += b"$Elements\n%d\n" % len(elems)
    for eid, typ, ns in elems:
        if binary:
            out += struct.pack("<3i", typ, 1, 2) + struct.pack(f"<{3 + len(ns)}i", eid, 5, 1, *ns)
        else:
            out += (" ".join(str(v) for v in [eid, typ, 2, 5, 1] + ns) + "\n").encode()
    out += (b"\n" if binary else b"") + b"$EndElements\n"
    out += data_sections(binary)
    open(path, "wb").write(out)

def write_inp():
    with open("golden_nodes.inp", "w") as f:
        f.write("** nodes, pulled in by *INCLUDE\n*Node, nset=NALL\n")
        for p, i in nodes:
            f.write(f"{i}, {fmt(p[0])}, {fmt(p[1])}, {fmt(p[2])}\n")
    with open("golden.inp", "w") as f:
        f.write("** golden deck: include, lower-case keywords, continuation lines\n*Heading\ngolden model\n")
        f.write("*INCLUDE, INPUT=golden_nodes.inp\n")
        f.write("*Element, type=S3, elset=SKIN\n900, 10, 20, 30\n")
        for k, t in (("hex", "C3D20R"), ("wedge", "C3D15"), ("tet", "C3D10")):
            ns = element(k, "abaqus")
            f.write(f"*ELEMENT, TYPE={t}, ELSET=E_{k.upper()}\n")
            first, rest = ns[:15], ns[15:]
            f.write(f"{elem_ids[k]}, " + ", ".join(map(str, first)) + ("," if rest else "") + "\n")
            if rest:
                f.write(", ".join(map(str, rest)) + "\n")
        f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., .3\n")

def e12(v):
    return f"{v:12.5E}"

def write_frd():
    lines = ["    1C", "    1UUSER", "    1Ugolden model"]
    lines.append(f"    2C{len(nodes):30d}{'':37s}0")
    for p, i in nodes:
        lines.append(f" -1{i:5d}" + "".join(e12(v) for v in p))
    lines.append(" -3")
    codes = {"hex": 4, "wedge": 5, "tet": 6}
    lines.append(f"    3C{len(order):30d}{'':37s}0")
    for k in order:
        ns = element(k, "frd")
        lines.append(f" -1{elem_ids[k]:5d}{codes[k]:5d}{0:5d}{1:5d}")
        for s in range(0, len(ns), 15):
            lines.append(" -2" + "".join(f"{n:5d}" for n in ns[s:s + 15]))
    lines.append(" -3")
    for step in (1, 2):
        lines.append(f"    1PSTEP{step:25d}{1:12d}{1:12d}")
        lines.append(f"  100CL  101{e12(float(step))}{len(nodes):12d}{'':20s} 0{step:5d}{'':10s} 0")
        lines.append(" -4  NDTEMP      1    1")
        lines.append(" -5  T           1    1    0    0")
        for p, i in nodes:
            lines.append(f" -1{i:5d}{e12(T(p, step))}")
        lines.append(" -3")
    lines.append(" 9999")
    open("golden.frd", "w").write("\n".join(lines) + "\n")

write_gmsh41("golden_41.msh", False)
write_gmsh41("golden_41_binary.msh", True)
write_gmsh22("golden_22.msh", False)
write_gmsh22("golden_22_binary.msh", True)
write_inp()
write_frd()

# --- Tecgraf neutral file: BRICK20 + TET10 (+ a T3 surface, skipped), two steps --------
NF_TET10 = [2, 5, 1, 8, 4, 9, 6, 7, 10, 3]   # Abaqus node (1-based) at each NF position
NF_HEX20 = [5, 17, 1, 9, 2, 18, 6, 13, 16, 12, 10, 14, 8, 20, 4, 11, 3, 19, 7, 15]

def write_nf():
    hex_ab, tet_ab = element("hex", "abaqus"), element("tet", "abaqus")
    hex_nf = [hex_ab[a - 1] for a in NF_HEX20]
    tet_nf = [tet_ab[a - 1] for a in NF_TET10]
    used = sorted(set(hex_ab + tet_ab))
    pos = {i: p for p, i in points.items()}
    L = ["%HEADER", "golden neutral file, hand-made for volpost's tests", "",
         "%HEADER.VERSION", "1.00", "", "%HEADER.TITLE", "'golden neutral file'", "",
         "%HEADER.ANALYSIS", "'solid'", "", "%NODE", str(len(used)), "",
         "%NODE.COORD", str(len(used))]
    L += [f"{i} {fmt(pos[i][0])} {fmt(pos[i][1])} {fmt(pos[i][2])}" for i in used]
    L += ["", "%NODE.SUPPORT", "1", "10 1 1 1 0 0 0", "",
          "%MATERIAL", "1", "", "%MATERIAL.LABEL", "1", "1 'steel'", "",
          "%MATERIAL.ISOTROPIC", "1", "1 210000.0 0.3", "",
          "%THICKNESS", "1", "1 1.0", "", "%INTEGRATION.ORDER", "1", "1 2 2 2 2 2 2", "",
          "%ELEMENT", "3", "",
          "%ELEMENT.T3", "1", "900 1 1 1 10 20 30", "",
          "%ELEMENT.BRICK20", "1", "101 1 1 " + " ".join(map(str, hex_nf)), "",
          "%ELEMENT.TET10", "1", "103 1 1 " + " ".join(map(str, tet_nf)), "",
          "%RESULT", "1", "1 'golden analysis'", "",
          "%RESULT.CASE", "1 2", "1 'load case 1'", ""]
    for step in (1, 2):
        L += [f"%RESULT.CASE.STEP", str(step), "", "%RESULT.CASE.STEP.TIME", f"{float(step)}", "",
              "%RESULT.CASE.STEP.NODAL.DISPLACEMENT", f"{len(used)} 'displacement'"]
        L += [f"{i} {fmt(step * pos[i][0])} 0.0 0.0 0.0 0.0 0.0" for i in used]
        L += ["", "%RESULT.CASE.STEP.NODAL.SCALAR", "2", "'T' 'P'", "",
              "%RESULT.CASE.STEP.NODAL.SCALAR.DATA", str(len(used))]
        L += [f"{i} {fmt(T(pos[i], step))} {fmt(float(step))}" for i in used]
        L += ["", "%RESULT.CASE.STEP.NODAL.VECTOR", "1", "'V'", "",
              "%RESULT.CASE.STEP.NODAL.VECTOR.DATA", str(len(used))]
        L += [f"{i} 1.0 {fmt(float(step))} 3.0" for i in used]
        # Gauss points: 2 per element, values e and 3e: the element shows their mean 2e.
        L += ["", "%RESULT.CASE.STEP.ELEMENT.GAUSS.SCALAR", "1", "'SG'", "",
              "%RESULT.CASE.STEP.ELEMENT.GAUSS.SCALAR.DATA", "2"]
        for eid, e in ((101, 1.0), (103, 3.0)):
            L += [f"{eid} 2", fmt(e * step), fmt(3 * e * step)]
        # Element-nodal: each element node carries its own x; averaged, every node shows x.
        L += ["", "%RESULT.CASE.STEP.ELEMENT.NODAL.SCALAR", "1", "'SX'", "",
              "%RESULT.CASE.STEP.ELEMENT.NODAL.SCALAR.DATA", "2"]
        for eid, ns in ((101, hex_nf), (103, tet_nf)):
            L += [f"{eid} {len(ns)}"] + [fmt(pos[n][0]) for n in ns]
        L += [""]
    L += ["%END", ""]
    open("golden.nf", "w").write("\n".join(L))

write_nf()
