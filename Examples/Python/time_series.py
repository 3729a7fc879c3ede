#!/usr/bin/env python3
"""A time series of an unsteady flow on a surface, animated as LIC and particles.

1. Writes the series: the mesh with a rotation field whose axis turns with time, one
   .vtp file a time step, and a .pvd collection naming them with their times (ParaView
   opens it as a time series).
2. Reads it back through a time-aware reader (PVDSeriesReader below: TIME_STEPS from
   the .pvd, the file of the step at or below UPDATE_TIME_STEP, as VTK's readers do;
   VTK 9.1 has no .pvd reader of its own) into
       reader -> vtkOFBSampler -> vtkOFBLIC -> vtkOFBPolyDataMapper
       reader -> vtkOFBParticleAdvector (pathlines) -> trails as lines
   and steps through the time steps: the sampler re-samples the field alone on the
   structure of the first step (StructureReuse), the LIC keeps its noise
   (LastRecomputed), the particles go on from step to step through the field
   interpolated in time.
3. Writes the last frame as a PNG.

Run with Debian's /usr/bin/python3 and PYTHONPATH=<build>/lib/python3.11/dist-packages:
    python3 Examples/Python/time_series.py mesh.obj out.png [--directory DIR]
Options: --steps (time steps written), --resolution (OFB cells on the longest side),
--particles, --check (exit with an error unless every step after the first was
re-sampled, the LIC kept its noise, and the particles went on without a restart).
"""

import argparse
import math
import os
import sys
import xml.etree.ElementTree as ET

import vtkofb
from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factories)

from ofb_example_view import add_view_options, read_surface, render_offscreen, save_png

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("mesh")
parser.add_argument("image")
parser.add_argument("--directory", default=None, help="where the series goes (default: "
                    "beside the image)")
parser.add_argument("--steps", type=int, default=8)
parser.add_argument("--resolution", type=int, default=512)
parser.add_argument("--particles", type=int, default=300)
parser.add_argument("--check", action="store_true")
add_view_options(parser)
args = parser.parse_args()

DT = 0.25      # time between steps
ALPHA = 1.2    # turning rate of the rotation axis (radians per unit time)


def axis(t):
    """The rotation axis at time t: it turns from y towards x."""
    return (math.sin(ALPHA * t), math.cos(ALPHA * t), 0.2)


# 1. The series: one .vtp a step, and the .pvd naming them with their times.
normals = vtkPolyDataNormals()
normals.SetInputData(read_surface(args.mesh))
normals.SplittingOff()
normals.Update()
mesh = normals.GetOutput()
cx, cy, cz = mesh.GetCenter()
directory = args.directory or os.path.dirname(os.path.abspath(args.image))
os.makedirs(directory, exist_ok=True)
collection = ET.Element("VTKFile", type="Collection", version="0.1")
datasets = ET.SubElement(collection, "Collection")
for k in range(args.steps):
    t = k * DT
    w = axis(t)
    field = vtkFloatArray()
    field.SetName("Velocity")
    field.SetNumberOfComponents(3)
    for i in range(mesh.GetNumberOfPoints()):
        x, y, z = mesh.GetPoint(i)
        r = (x - cx, y - cy, z - cz)
        field.InsertNextTuple3(w[1] * r[2] - w[2] * r[1], w[2] * r[0] - w[0] * r[2],
                               w[0] * r[1] - w[1] * r[0])
    step = vtkPolyData()
    step.ShallowCopy(mesh)
    step.GetPointData().SetVectors(field)
    name = f"series_{k:03d}.vtp"
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(os.path.join(directory, name))
    writer.SetInputData(step)
    writer.Write()
    ET.SubElement(datasets, "DataSet", timestep=repr(t), part="0", file=name)
pvd = os.path.join(directory, "series.pvd")
ET.ElementTree(collection).write(pvd)
print(f"wrote {pvd} ({args.steps} steps)")


# 2. A time-aware reader of the .pvd.
class PVDSeriesReader(VTKPythonAlgorithmBase):
    """The .vtp files of a .pvd as a time series: TIME_STEPS from the collection, the
    file of the step at or below the requested time (clamped to the first and last
    steps, as VTK's readers do)."""

    def __init__(self, path):
        VTKPythonAlgorithmBase.__init__(self, nInputPorts=0, nOutputPorts=1,
                                        outputType="vtkPolyData")
        root = ET.parse(path).getroot()
        items = sorted((float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet"))
        base = os.path.dirname(os.path.abspath(path))
        self.times = [t for t, _ in items]
        self.files = [os.path.join(base, f) for _, f in items]

    def RequestInformation(self, request, inInfo, outInfo):
        info = outInfo.GetInformationObject(0)
        sddp = vtkStreamingDemandDrivenPipeline
        info.Set(sddp.TIME_STEPS(), self.times, len(self.times))
        info.Set(sddp.TIME_RANGE(), [self.times[0], self.times[-1]], 2)
        return 1

    def RequestData(self, request, inInfo, outInfo):
        info = outInfo.GetInformationObject(0)
        t = info.Get(vtkStreamingDemandDrivenPipeline.UPDATE_TIME_STEP()) \
            if info.Has(vtkStreamingDemandDrivenPipeline.UPDATE_TIME_STEP()) else self.times[0]
        k = max([0] + [i for i, s in enumerate(self.times) if s <= t + 1e-9])
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(self.files[k])
        reader.Update()
        output = vtkPolyData.GetData(outInfo)
        output.ShallowCopy(reader.GetOutput())
        output.GetInformation().Set(vtkPolyData.DATA_TIME_STEP(), self.times[k])
        return 1


series = PVDSeriesReader(pvd)
sampler = vtkofb.vtkOFBSampler()
sampler.SetInputConnection(series.GetOutputPort())
sampler.SetResolution(args.resolution)
lic = vtkofb.vtkOFBLIC()
lic.SetInputConnection(sampler.GetOutputPort())
lic.SetNumberOfSteps(20)
lic.SetNoiseGeneratorSeed(1)
lic.EnhancedLICOn()
lic.SetEnhanceContrast(vtkofb.vtkOFBLIC.ENHANCE_CONTRAST_LIC)
advector = vtkofb.vtkOFBParticleAdvector()
advector.SetInputConnection(series.GetOutputPort())
advector.SetNumberOfParticles(args.particles)
advector.SetStepSize(1.0)
advector.SetTrailLength(60)
advector.PaintOff()

mapper = vtkofb.vtkOFBPolyDataMapper()
mapper.SetInputData(mesh)
mapper.SetOFBConnection(lic.GetOutputPort())
coloring = mapper.GetColoring()
coloring.SetIntensityArrayName("LIC")
coloring.IntensityModulationOn()
coloring.SetLICColorModeToBlend()
coloring.SetLICIntensity(1.0)
surface = vtkActor()
surface.SetMapper(mapper)
trails = vtkPolyDataMapper()
trails.SetInputConnection(advector.GetOutputPort(2))
trails.ScalarVisibilityOff()
# The trails lie on the surface: drawn in front of it (VTK's coincident topology offset).
trails.SetResolveCoincidentTopologyToPolygonOffset()
trails.SetRelativeCoincidentTopologyLineOffsetParameters(-4.0, -40.0)
lines = vtkActor()
lines.SetMapper(trails)
lines.GetProperty().SetColor(1.0, 0.55, 0.1)
lines.GetProperty().SetLineWidth(3.0)
lines.GetProperty().LightingOff()

failures = []
window = None
last_step = -1
for k in range(args.steps):
    t = k * DT
    lic.UpdateTimeStep(t)
    advector.UpdateTimeStep(t)
    recomputed = lic.GetLastRecomputed()
    print(f"t = {t:.2f}: {'re-sampled' if sampler.GetLastUpdateResampled() else 'built'} "
          f"in {sampler.GetLastBuildTime():.0f} ms, LIC recomputed {recomputed:#x}, "
          f"{advector.GetCurrentStep()} particle steps")
    if k > 0:
        if not sampler.GetLastUpdateResampled():
            failures.append(f"step {k} was built, not re-sampled")
        if recomputed & vtkofb.vtkOFBLIC.RECOMPUTED_NOISE:
            failures.append(f"step {k}: the LIC computed its noise again")
        if advector.GetCurrentStep() <= last_step:
            failures.append(f"step {k}: the particles restarted")
    last_step = advector.GetCurrentStep()
    if window is None:
        window = render_offscreen(surface, args)
        window.GetRenderers().GetFirstRenderer().AddActor(lines)
    window.Render()

save_png(window, args.image)
if args.check:
    if advector.GetParticles().GetNumberOfPoints() != args.particles:
        failures.append("particles were lost")
    if failures:
        sys.exit("; ".join(failures))
    print("check passed")
