# SPDX-License-Identifier: MIT
"""Run inside ParaView's window (paraview --script=in_the_window.py --exit): loads the plugin,
opens a file, shows it and writes how many cells the window's pipeline holds to a file.
Arguments come in the environment: VOLPOST_PV_PLUGIN, VOLPOST_PV_FILE, VOLPOST_PV_RESULT."""
import os

from paraview.simple import LoadPlugin, OpenDataFile, Render, Show

LoadPlugin(os.environ["VOLPOST_PV_PLUGIN"], remote=False, ns=globals())
reader = OpenDataFile(os.environ["VOLPOST_PV_FILE"])
reader.UpdatePipeline()
Show(reader)
Render()
with open(os.environ["VOLPOST_PV_RESULT"], "w") as result:
    result.write(f"{reader.GetXMLName()} {reader.GetDataInformation().GetNumberOfCells()}\n")
