#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""docs/images/element_field_gpu.png: a shell of one value in a mesh of 4x4x4 hexahedra drawn by
the GPU ray caster through the split, by the GPU ray caster on the refined pieces, and by the
reference through the cells' own field (360x360 each).

    /usr/bin/python3 docs/scripts/element_field_gpu_picture.py   (from the repository root, after a build)
"""
import os
import subprocess
import sys

sys.path.insert(0, "docs/scripts")
import element_field_error as e
from PIL import Image, ImageDraw, ImageFont
work = "/tmp/gpu_panels"; os.makedirs(work, exist_ok=True)
model = os.path.join(work, "hex8.vtk"); e.write_vtk(model, "hex8", 4)
tf = os.path.join(work, "peak.json")
open(tf, "w").write('''{"format": "volpost-tf", "version": 1, "points": [
 {"value": -1.6, "color": [0.2, 0.3, 0.9], "extinction": 0.0},
 {"value": 0.36, "color": [0.2, 0.6, 0.9], "extinction": 0.0},
 {"value": 0.40, "color": [1.0, 0.7, 0.2], "extinction": 60.0},
 {"value": 0.44, "color": [0.9, 0.2, 0.1], "extinction": 0.0},
 {"value": 1.6, "color": [0.9, 0.2, 0.1], "extinction": 0.0}]}''')
panels = [("raycast", "tetrahedra", "GPU ray caster: the split's field"),
          ("raycast", "element", "GPU ray caster: refined pieces"),
          ("reference", "element", "reference: the cells' own field")]
ims = []
for r, how, label in panels:
    out = os.path.join(work, f"{r}_{how}.png")
    subprocess.run(["build/bin/volpost", "render", model, "--field", "wave", "--renderer", r, "--tf", tf,
                    "--interpolation", how, "--size", "360x360", "--camera", "iso,az=20,zoom=1.1",
                    "--no-legend", "--no-triad", "-o", out], check=True)
    im = Image.open(out).convert("RGB")
    d = ImageDraw.Draw(im)
    font = ImageFont.truetype("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", 15)
    d.text((10, 8), label, fill=(30, 30, 30), font=font)
    ims.append(im)
W = sum(i.width for i in ims); out = Image.new("RGB", (W, ims[0].height)); x = 0
for i in ims: out.paste(i, (x, 0)); x += i.width
out.save("docs/images/element_field_gpu.png", optimize=True)
