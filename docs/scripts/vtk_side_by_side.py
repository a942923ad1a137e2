#!/usr/bin/python3
"""VTK's unstructured volume renderers on the cases volpost_volume_bench exports, for a
side-by-side table: milliseconds per frame (wall and process CPU) and the image error
against volpost's exact reference (premultiplied RGBA in 0..1, as the bench reports).

    build/bin/volpost_volume_bench --size 512 --frames 5 --mesh wave --cpu-only --export /tmp/cases
    xvfb-run -a /usr/bin/python3 docs/scripts/vtk_side_by_side.py /tmp/cases --frames 5

Needs Debian's python3-vtk9 and python3-numpy (not volpost itself). VTK's opacity is per
unit distance: alpha = 1 - (1 - o)^(L / u); volpost's extinction tau gives
alpha = 1 - exp(-tau L), so o = 1 - exp(-tau u) with u = 1 model unit, sampled at 512
values so that VTK's piecewise-linear opacity follows volpost's piecewise-linear tau.
"""
import argparse
import glob
import json
import math
import os
import subprocess
import sys
import time

import numpy as np
import vtk
from vtk.util import numpy_support


def transfer_functions(tf_path):
    points = json.load(open(tf_path))["points"]
    values = [p["value"] for p in points]
    color = vtk.vtkColorTransferFunction()
    for p in points:
        color.AddRGBPoint(p["value"], *p["color"])
    opacity = vtk.vtkPiecewiseFunction()
    lo, hi = values[0], values[-1]
    samples = sorted(set([lo + (hi - lo) * i / 511.0 for i in range(512)] + values))
    for s in samples:
        tau = np.interp(s, values, [p["extinction"] for p in points])
        opacity.AddPoint(s, 1.0 - math.exp(-tau * 1.0))
    return color, opacity


def render(case, mapper_name, frames):
    camera_spec = json.load(open(case + ".camera.json"))
    size = camera_spec["size"]
    width, height = (size, size) if isinstance(size, int) else size  # N (older exports) or [W, H]
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(case + ".vtu")
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetNumberOfCells() == 0 or grid.GetPointData().GetArray("s") is None:
        sys.exit("%s.vtu: VTK read no cells or no field s (see its messages above)" % case)
    grid.GetPointData().SetActiveScalars("s")
    color, opacity = transfer_functions(case + ".tf.json")
    prop = vtk.vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(1.0)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()
    resample_ms = 0.0
    if mapper_name == "projected tetrahedra":
        mapper = vtk.vtkProjectedTetrahedraMapper()
        mapper.SetInputData(grid)
    elif mapper_name == "ray cast, partial pre-integration":
        mapper = vtk.vtkUnstructuredGridVolumeRayCastMapper()
        mapper.SetRayIntegrator(vtk.vtkUnstructuredGridPartialPreIntegration())
        mapper.SetInputData(grid)
    elif mapper_name == "z-sweep":
        mapper = vtk.vtkUnstructuredGridVolumeZSweepMapper()
        mapper.SetInputData(grid)
    else:  # resampled to a 256^3 image, then VTK's GPU ray caster on it
        start = time.perf_counter()
        resample = vtk.vtkResampleToImage()
        resample.SetInputDataObject(grid)
        resample.SetSamplingDimensions(256, 256, 256)
        resample.Update()
        resample_ms = (time.perf_counter() - start) * 1e3
        image = resample.GetOutput()
        image.GetPointData().SetActiveScalars("s")
        mapper = vtk.vtkGPUVolumeRayCastMapper()
        mapper.SetInputData(image)
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtk.vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(0, 0, 0)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetAlphaBitPlanes(1)
    window.SetSize(width, height)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*camera_spec["eye"])
    camera.SetFocalPoint(*camera_spec["target"])
    camera.SetViewUp(*camera_spec["up"])
    camera.SetViewAngle(camera_spec["viewAngle"])
    renderer.ResetCameraClippingRange()
    setup = time.perf_counter()
    window.Render()  # the first frame builds VTK's structures: reported apart
    first_ms = (time.perf_counter() - setup) * 1e3
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGBA()
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    rgba = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, 4)[::-1] / 255.0
    walls, cpus = [], []
    for _ in range(frames):
        camera.Azimuth(360.0 / frames)
        renderer.ResetCameraClippingRange()
        w0, c0 = time.perf_counter(), time.process_time()
        window.Render()
        walls.append((time.perf_counter() - w0) * 1e3)
        cpus.append((time.process_time() - c0) * 1e3)
    reference = np.load(case + ".reference.npy")
    diff = rgba - reference
    return resample_ms + first_ms, float(np.median(walls)), float(np.median(cpus)), float(np.sqrt(np.mean(diff ** 2))), float(np.abs(diff).max())


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("cases", help="the folder volpost_volume_bench --export wrote")
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--mappers", default="all",
                        help="comma-separated: projected, raycast, zsweep, resampled (default all)")
    parser.add_argument("--one", nargs=2, metavar=("CASE", "MAPPER"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one:  # one mapper in a process of its own: VTK's GPU mapper does not share a process well
        print(json.dumps(render(args.one[0], args.one[1], args.frames)))
        return
    names = {"projected": "projected tetrahedra", "raycast": "ray cast, partial pre-integration",
             "zsweep": "z-sweep", "resampled": "resampled to 256^3 + GPU ray caster"}
    wanted = list(names) if args.mappers == "all" else args.mappers.split(",")
    unknown = [m for m in wanted if m not in names]
    if unknown:
        sys.exit("--mappers: %s is not one of %s" % (", ".join(unknown), ", ".join(names)))
    chosen = [names[m] for m in wanted]
    print("VTK %s, %s" % (vtk.vtkVersion.GetVTKVersion(), os.uname().nodename))
    print("| case | VTK mapper | setup + first frame ms | ms/frame (wall, median) | process CPU ms/frame | RMSE | max error |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for case in sorted(glob.glob(os.path.join(args.cases, "*.vtu"))):
        case = case[:-4]
        for mapper in chosen:
            run = subprocess.run([sys.executable, __file__, args.cases, "--frames", str(args.frames), "--one", case, mapper],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                print("| %s | %s | failed (exit %d): %s |" % (os.path.basename(case), mapper, run.returncode,
                                                           run.stderr.strip().splitlines()[-1:] or ""), flush=True)
                continue
            first, wall, cpu, rmse, worst = json.loads(run.stdout.strip().splitlines()[-1])
            print("| %s | %s | %.0f | %.0f | %.0f | %.2g | %.2g |" % (os.path.basename(case), mapper, first, wall, cpu, rmse, worst),
                  flush=True)


if __name__ == "__main__":
    main()
