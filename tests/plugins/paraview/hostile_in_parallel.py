# SPDX-License-Identifier: MIT
"""Run by `mpirun -np N pvbatch --mpi`: damaged files opened through the volpost plugin fail
that reader with a message naming the file, on every rank, and the session goes on: a good
file opened after them reads whole, one rank reading it and the others holding nothing.

Usage: mpirun -np N pvbatch --mpi hostile_in_parallel.py PLUGIN RANKS GOOD CELLS GRID GRID_CELLS BAD...
(GOOD holds CELLS cells, GRID, a SEG-Y file, GRID_CELLS: each comes once across the ranks.)
"""
import sys

from paraview import servermanager
from paraview.simple import Delete, LoadPlugin, OpenDataFile
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

plugin, ranks, good, good_cells = sys.argv[1], int(sys.argv[2]), sys.argv[3], int(sys.argv[4])
grid, grid_cells_expected = sys.argv[5], int(sys.argv[6])
bad_files = sys.argv[7:]
LoadPlugin(plugin, remote=False, ns=globals())
# ParaView's messages (and Python's print) go to the output window: caught in a string while
# the files are read, the usual window given back to report.
usual = vtkOutputWindow.GetInstance()
messages = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(messages)
report = []
failures = []
# ParaView has readers of its own for .inp (AVS UCD) and .sgy: a script names the volpost one.
VOLPOST_READERS = {"inp": "volpostAbaqusCalculiXInputDeck", "sgy": "volpostSEGYVolume", "segy": "volpostSEGYVolume"}


def open_with_volpost(path):
    extension = path.rsplit(".", 1)[-1].lower()
    return globals()[VOLPOST_READERS[extension]](FileName=path) if extension in VOLPOST_READERS else OpenDataFile(path)


partitions = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
if partitions != ranks:
    failures.append(f"the session has {partitions} ranks, not {ranks}")

try:
    for path in bad_files:
        before = len(messages.GetOutput())
        reader = open_with_volpost(path)
        if reader is None or not reader.GetXMLName().startswith("Volpost"):
            failures.append(f"{path}: not opened by a volpost reader")
            continue
        reader.UpdatePipeline()
        said = messages.GetOutput()[before:]
        data = servermanager.Fetch(reader)
        if "ERR" not in said and "Error" not in said:
            failures.append(f"{path}: no error was reported")
        elif path.rsplit("/", 1)[-1] not in said:
            failures.append(f"{path}: the error does not name the file: {said.strip()}")
        if data is not None and data.GetNumberOfCells() > 0:
            failures.append(f"{path}: {data.GetNumberOfCells()} cells came out of a damaged file")
        report.append(f"{path}: refused")
        Delete(reader)

    # One rank reads a finite-element file, and its cells come once.
    reader = OpenDataFile(good)
    reader.UpdatePipeline()
    cells = reader.GetDataInformation().GetNumberOfCells()  # summed over the ranks
    if cells != good_cells:
        failures.append(f"{good}: {cells} cells across the ranks after the damaged files, not {good_cells}")
    report.append(f"{good}: {cells} cells across {partitions} ranks")

    # A grid is shared out by extent: every cell once (neighbouring pieces share a plane of
    # samples), and more than one rank holds some.
    seismic = open_with_volpost(grid)
    seismic.UpdatePipeline()
    grid_cells = seismic.GetDataInformation().GetNumberOfCells()
    if grid_cells != grid_cells_expected:
        failures.append(f"{grid}: {grid_cells} cells across the ranks, not {grid_cells_expected}")
    local = servermanager.Fetch(seismic).GetNumberOfCells()  # the first rank's piece
    if ranks > 1 and local >= grid_cells_expected:
        failures.append(f"{grid}: the first rank holds all {local} cells")
    report.append(f"{grid}: {grid_cells} cells across {partitions} ranks, {local} on the first")

except Exception as e:  # said after the usual window is back
    failures.append(f"{type(e).__name__}: {e}")
vtkOutputWindow.SetInstance(usual)
for line in report:
    print(line)
for f in failures:
    print("FAIL:", f)
# Leaving the script normally closes every rank; sys.exit would strand the others.
if failures:
    raise SystemExit(f"{len(failures)} failure(s)")
