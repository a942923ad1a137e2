# SPDX-License-Identifier: MIT
"""Run by pvbatch: every file given, opened in ParaView through the volpost plugin, holds what
`volpost convert` writes of it, read back by ParaView's own VTU reader: the same points, cells
(VTK types and nodes), node and element ids, and every field at every time step (a field of
several steps is "NAME step K" in the VTU).

Usage: pvbatch readers_match_convert.py PLUGIN VOLPOST OUTDIR FILE...
"""
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile, XMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy
import numpy as np

plugin, volpost, outdir = sys.argv[1:4]
files = sys.argv[4:]
LoadPlugin(plugin, remote=False, ns=globals())
failures = []
VOLPOST_READERS = {"inp": "volpostAbaqusCalculiXInputDeck", "sgy": "volpostSEGYVolume", "segy": "volpostSEGYVolume"}


def fail(message):
    failures.append(message)
    print("FAIL:", message)


def arrays(attributes):
    return {attributes.GetArrayName(i): vtk_to_numpy(attributes.GetArray(i)) for i in range(attributes.GetNumberOfArrays())}


def step_counts(names):
    """Field name -> its step count, from the VTU's array names."""
    counts = {}
    for name in names:
        base, sep, k = name.rpartition(" step ")
        if sep and k.isdigit():
            counts[base] = max(counts.get(base, 0), int(k))
        else:
            counts.setdefault(name, 1)
    return counts


def step_times(vtu):
    """Field name -> the times of its steps, from the attributes volpost writes on each array."""
    times = {}
    for array in ElementTree.parse(vtu).getroot().iter("DataArray"):
        field = array.get("VolpostField")
        if field is not None:
            times.setdefault(field, []).append(float(array.get("VolpostTime")))
    return times


def step_shown(times, time, by_file_times):
    """The documented rule (docs/user/paraview.md): with the files' times, a field's last step at
    or before the time (its first before any); with step numbers, step min(time, count)."""
    if len(times) == 1 or time is None:
        return 0
    if not by_file_times:
        return min(int(round(time)), len(times)) - 1
    chosen = 0
    for k, t in enumerate(times):
        if t <= time:
            chosen = k
    return chosen


def compare_fields(path, got, expected, times_of, time, by_file_times, where):
    counts = step_counts(expected.keys())
    if set(got.keys()) != set(counts.keys()):
        fail(f"{path}: {where} arrays {sorted(got)} where the VTU has {sorted(counts)}")
    for name, count in counts.items():
        if name not in got:
            continue
        step_index = step_shown(times_of.get(name, [0.0]), time, by_file_times)
        want = expected[name] if count == 1 else expected[f"{name} step {step_index + 1}"]
        if got[name].shape != want.shape or not np.array_equal(got[name], want, equal_nan=True):
            fail(f"{path}: {where} array {name} at step {step_index + 1} differs from the VTU")


def image_points(image):
    n = image.GetNumberOfPoints()
    return np.array([image.GetPoint(i) for i in range(n)])


for path in files:
    name = os.path.basename(path)
    vtu = os.path.join(outdir, name + ".vtu")
    done = subprocess.run([volpost, "convert", path, vtu], capture_output=True, text=True)
    if done.returncode != 0:
        fail(f"{path}: volpost convert failed: {done.stderr.strip()}")
        continue
    expected = servermanager.Fetch(XMLUnstructuredGridReader(FileName=[vtu]))
    # ParaView has readers of its own for .inp (AVS UCD) and .sgy: File > Open asks which to
    # use; a script names the volpost one.
    extension = path.rsplit(".", 1)[-1].lower()
    reader = globals()[VOLPOST_READERS[extension]](FileName=path) if extension in VOLPOST_READERS else OpenDataFile(path)
    if reader is None or not reader.GetXMLName().startswith("Volpost"):
        fail(f"{path}: File > Open did not choose a volpost reader ({reader.GetXMLName() if reader else None})")
        continue
    times = list(reader.TimestepValues) if reader.TimestepValues else [None]
    times_of = step_times(vtu)
    by_file_times = all(all(b > a for a, b in zip(t, t[1:])) for t in times_of.values())
    print(f"{name}: {reader.GetXMLName()}, {len(times)} time step(s)")
    for time in times:
        if time is None:
            reader.UpdatePipeline()
        else:
            reader.UpdatePipeline(time)
        got = servermanager.Fetch(reader)
        if got.GetNumberOfPoints() != expected.GetNumberOfPoints():
            fail(f"{path}: {got.GetNumberOfPoints()} points where the VTU has {expected.GetNumberOfPoints()}")
            break
        if got.IsA("vtkImageData"):
            # Within a thousandth of the smallest spacing: survey axes a hair off a right angle
            # are squared for image data.
            points = image_points(got)
            moved = np.abs(points - vtk_to_numpy(expected.GetPoints().GetData())).max()
            if not moved <= 1e-3 * min(got.GetSpacing()):
                fail(f"{path}: the image's points are up to {moved} from the VTU's")
        else:
            if not np.array_equal(vtk_to_numpy(got.GetPoints().GetData()), vtk_to_numpy(expected.GetPoints().GetData())):
                fail(f"{path}: points differ from the VTU")
            if got.GetNumberOfCells() != expected.GetNumberOfCells():
                fail(f"{path}: {got.GetNumberOfCells()} cells where the VTU has {expected.GetNumberOfCells()}")
                break
            if not np.array_equal(vtk_to_numpy(got.GetCellTypesArray()), vtk_to_numpy(expected.GetCellTypesArray())):
                fail(f"{path}: cell types differ from the VTU")
            for which in ("GetConnectivityArray", "GetOffsetsArray"):
                a = vtk_to_numpy(getattr(got.GetCells(), which)())
                b = vtk_to_numpy(getattr(expected.GetCells(), which)())
                if not np.array_equal(a, b):
                    fail(f"{path}: cell {which[3:-5].lower()} differ from the VTU")
            compare_fields(path, arrays(got.GetCellData()), arrays(expected.GetCellData()), times_of, time, by_file_times, "cell")
        compare_fields(path, arrays(got.GetPointData()), arrays(expected.GetPointData()), times_of, time, by_file_times, "point")

if failures:
    print(f"{len(failures)} failure(s)")
    sys.exit(1)
print(f"all {len(files)} files match volpost convert")
