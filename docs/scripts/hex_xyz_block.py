#!/usr/bin/env python3
# Writes a legacy VTK file of n^3 hex8 cells on [0,1]^3 carrying xyz at its nodes (the field
# is then exactly xyz: its own trilinear interpolant). Usage: hex_xyz_block.py N OUT.vtk
import sys, math
n=int(sys.argv[1]); out=sys.argv[2]
m=n+1
pts=[];vals=[]
for k in range(m):
  for j in range(m):
    for i in range(m):
      x,y,z=i/n,j/n,k/n; pts.append((x,y,z)); vals.append(x*y*z)
cells=[]
idx=lambda i,j,k:(k*m+j)*m+i
for k in range(n):
  for j in range(n):
    for i in range(n):
      cells.append([idx(i,j,k),idx(i+1,j,k),idx(i+1,j+1,k),idx(i,j+1,k),idx(i,j,k+1),idx(i+1,j,k+1),idx(i+1,j+1,k+1),idx(i,j+1,k+1)])
with open(out,'w') as f:
  f.write("# vtk DataFile Version 4.2\nhex8 xyz\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS %d double\n"%len(pts))
  for p in pts: f.write("%r %r %r\n"%p)
  f.write("CELLS %d %d\n"%(len(cells),9*len(cells)))
  for c in cells: f.write("8 "+" ".join(map(str,c))+"\n")
  f.write("CELL_TYPES %d\n"%len(cells)); f.write("12\n"*len(cells))
  f.write("POINT_DATA %d\nSCALARS xyz double 1\nLOOKUP_TABLE default\n"%len(pts))
  for v in vals: f.write("%r\n"%v)
