# SPDX-License-Identifier: MIT
"""Run by pvpython: connects to a pvserver, loads the volpost plugin on the server side (and on
the client, for its proxies), opens a file there and checks what the server read.

Usage: pvpython client_server.py PLUGIN PORT FILE CELLS
"""
import sys
import time

from paraview.simple import Connect, Disconnect, LoadPlugin, OpenDataFile

plugin, port, path, cells = sys.argv[1], int(sys.argv[2]), sys.argv[3], int(sys.argv[4])
connection = None
for attempt in range(60):  # the server takes a moment to listen
    try:
        connection = Connect("localhost", port)
        break
    except Exception:
        time.sleep(0.5)
if connection is None:
    raise SystemExit(f"no pvserver answered on port {port}")
LoadPlugin(plugin, remote=True, ns=globals())
LoadPlugin(plugin, remote=False, ns=globals())
reader = OpenDataFile(path)
if reader is None or not reader.GetXMLName().startswith("Volpost"):
    raise SystemExit(f"{path}: not opened by a volpost reader on the server")
reader.UpdatePipeline()
got = reader.GetDataInformation().GetNumberOfCells()
Disconnect()
if got != cells:
    raise SystemExit(f"{path}: the server read {got} cells, not {cells}")
print(f"{path}: {got} cells read by the server")
