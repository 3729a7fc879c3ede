"""The OFB plugin's pipeline for the client tests, run the same way in every ParaView:

    pvbatch ofbClientPipeline.py PLUGIN OUTPUT_DIR
    pvpython ofbClientPipeline.py PLUGIN OUTPUT_DIR --url cs://localhost:PORT
    OFB_PIPELINE_ARGS="PLUGIN OUTPUT_DIR --gui" paraview --plugin-search-paths=PLUGIN_DIR \
        --plugins=OFB --script=ofbClientPipeline.py --exit

- pvbatch (no --url, no --gui): the builtin session, or the first rank of
  `mpiexec -np N pvbatch`; the plugin is loaded with LoadPlugin.
- A client of a pvserver (--url): it connects, and loads the plugin on the server
  (remote=True: the filters, the writer and the representation run there) and in this
  process (remote=False: the representation for the client's own rendering).
- The paraview GUI (--gui; its --script passes no arguments, so they come from
  OFB_PIPELINE_ARGS): the plugin is the one the GUI loaded at startup (--plugins), the
  view is the GUI's own render view, and the filters are registered where the Pipeline
  Browser lists them.

The pipeline, on a sphere with a tangent field distributed by ParaView:

    Sphere -> Calculator (Field) -> RedistributeDataSet -> ExtractSurface
           -> GhostCellsGenerator -> OFB Sampler -> OFB LIC -> OFB Paint Strokes (a band)
           -> OFB Particles (its OFB input: the painted OFB) -> OFB Probe (onto the mesh)
           -> shown as "OFB Surface" (the probe's input OFB: LIC, paint and footprints)

It writes OUTPUT_DIR/values.json (what was computed where the data is, fetched to this
process), OUTPUT_DIR/ofb-surface.png (the view rendered where the data is: by the server
in client-server mode) and, through the OFB writer (Save Data, on any number of
processes: the first one writes the gathered mesh), OUTPUT_DIR/ofb-cs-sphere.obj (+ .mtl,
.png) and ofb-cs-sphere.gltf, written where the data is. As a
client it also renders the view on the client (local rendering: the server delivers the
surface) and writes OUTPUT_DIR/ofb-surface-local.png, with the OFB Surface representation
building its OFB and LIC from the delivered surface; pvbatch and the GUI write the same
picture of the whole surface in one process as OUTPUT_DIR/ofb-surface-whole.png (on one
process only). A client also renders the probe's view locally (check_delivered_ofb): with
the OFB the servers pack into the delivered surface (ofb-probe-local.png), at the mesh's
resolution (ofb-probe-mesh.png), and surfaces with unusable packs (ofb-bad-*.png).
TestOFBClients.py runs them and compares.
"""
import argparse
import json
import os
import shlex
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import *
from vtkmodules.util.numpy_support import vtk_to_numpy

SIZE = 300
OFB_FILTERS = ["OFBSampler", "OFBLIC", "OFBPaintStrokes", "OFBParticles", "OFBProbe"]

parser = argparse.ArgumentParser(description="The OFB plugin's pipeline for the client tests")
parser.add_argument("plugin")
parser.add_argument("output")
parser.add_argument("--url", help="the pvserver to connect to (client-server mode)")
parser.add_argument("--gui", action="store_true", help="run in the paraview GUI (--script)")
argv = [a for a in sys.argv[1:] if a]
args = parser.parse_args(argv if argv else shlex.split(os.environ.get("OFB_PIPELINE_ARGS", "")))
os.makedirs(args.output, exist_ok=True)
client = args.url is not None


def say(*what):
    print(*what, flush=True)


values = {}
if client:
    # cs://HOST:PORT: paraview.simple.Connect takes the host and the port.
    host, port = args.url.split("://", 1)[-1].rsplit(":", 1)
    if Connect(host, int(port), timeout=30) is None:
        raise RuntimeError("no connection to the server at %s" % args.url)
    say("connected to", args.url, "with",
        servermanager.ActiveConnection.GetNumberOfDataPartitions(), "server processes")
    LoadPlugin(args.plugin, remote=True, ns=globals())
    LoadPlugin(args.plugin, remote=False, ns=globals())
elif args.gui:
    # What the GUI loaded at startup (--plugins) and shows under Filters > OFB.
    plugins = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager() \
        .GetLocalInformation()
    values["gui_plugins"] = sorted(
        plugins.GetPluginFileName(i) for i in range(plugins.GetNumberOfPlugins())
        if plugins.GetPluginLoaded(i) and plugins.GetPluginName(i) == "OFB")
    values["gui_simple_functions"] = [name for name in OFB_FILTERS if name in globals()]
    categories = {}
    for name in OFB_FILTERS:
        prototype = servermanager.ProxyManager().SMProxyManager.GetPrototypeProxy("filters", name)
        hints = prototype.GetHints() if prototype else None
        menu = hints.FindNestedElementByName("ShowInMenu") if hints else None
        categories[name] = menu.GetAttribute("category") if menu else None
    values["gui_menu_categories"] = categories
else:
    LoadPlugin(args.plugin, ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
values["ranks"] = ranks

sphere = Sphere(ThetaResolution=128, PhiResolution=64, Radius=0.5)
field = Calculator(Input=sphere, ResultArrayName="Field",
                   Function="(-coordsY+0.3*coordsZ)*iHat+coordsX*jHat-0.3*coordsX*kHat")
pieces = RedistributeDataSet(Input=field)
surface = ExtractSurface(Input=pieces)
ghosted = GhostCellsGenerator(Input=surface, BuildIfRequired=1)

sampler = OFBSampler(Input=ghosted, Resolution=96)
sampler.Vectors = ["POINTS", "Field"]
sampler.UpdatePipeline()
values["samples"] = sampler.GetDataInformation().GetNumberOfPoints()
lic = OFBLIC(Input=sampler, NumberOfSteps=10, NumberOfGhostLevels=12)
equator = PolyLineSource(Points=[0.5 * c for a in np.linspace(0, 2 * np.pi, 64)
                                 for c in (np.cos(a), np.sin(a), 0.0)])
paint = OFBPaintStrokes(Input=lic, Strokes=equator)
paint.BrushRadius = 0.06
paint.BrushColor = [1.0, 0.0, 0.0, 1.0]
k = np.arange(40) + 0.5
z = 1.0 - 2.0 * k / 40
r = np.sqrt(1.0 - z * z)
golden = np.pi * (3 - np.sqrt(5)) * k
seeds = PolyPointSource(Points=list((0.5 * np.column_stack(
    (r * np.cos(golden), r * np.sin(golden), z))).ravel()))
particles = OFBParticles(Input=ghosted, OFB=paint, Seeds=seeds, FootprintRadius=2.0,
                         NumberOfTimeSteps=30, StepSize=1.5)
particles.Vectors = ["POINTS", "Field"]
particles.UpdatePipeline(20.0)
values["particles"] = particles.GetDataInformation(1).GetNumberOfPoints()
values["trails"] = particles.GetDataInformation(2).GetNumberOfCells()
probe = OFBProbe(Input=ghosted, OFB=OutputPort(particles, 0))
probe.UpdatePipeline(20.0)

# What the server computed, fetched to this process: the probed mesh (gathered from every
# rank) with the LIC, the paint and the footprints on its points.
mesh = servermanager.Fetch(probe)
point_data = mesh.GetPointData()
valid = vtk_to_numpy(point_data.GetArray("vtkValidPointMask")) != 0
licvalues = vtk_to_numpy(point_data.GetArray("LIC"))[valid].astype(np.float64)
colors = vtk_to_numpy(point_data.GetArray("Colors"))[valid].astype(np.int64)
red = (colors[:, 0] > 200) & (colors[:, 1] < 60) & (colors[:, 2] < 60)
values.update({
    "mesh_points": mesh.GetNumberOfPoints(),
    "mesh_cells": mesh.GetNumberOfCells(),
    "valid_points": int(valid.sum()),
    "lic_mean": float(licvalues.mean()),
    "lic_std": float(licvalues.std()),
    "red_points": int(red.sum()),
    "colour_sum": [int(s) for s in colors.sum(axis=0)],
})
ends = servermanager.Fetch(particles, idx=1)
end_points = vtk_to_numpy(ends.GetPoints().GetData()) if ends.GetNumberOfPoints() else []
values["particle_ends"] = sorted([round(float(c), 6) for c in p] for p in end_points)
say("values:", json.dumps({key: value for key, value in values.items()
                           if key != "particle_ends"}))

# Packs of the probe's OFB (vtkOFBSamplePack's arrays, rank 0's prefix) made unusable, one
# way each: the client that renders them locally reports them and builds its own OFB.
BAD_PACKS = {
    "cells-outside": "cells[:] = 4000000000",
    "short-depths": "depths = depths[:-1]",
    "frame-of-five": "frame = frame[:5]",
    "short-colors": "colors = colors[:-3]",
}
BAD_PACK_SCRIPT = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
output.ShallowCopy(inputs[0].VTKObject)
n = 50
frame = np.array([-0.5, -0.5, -0.5, 0.01, 100, 100, 100], dtype=np.float64)
cells = np.arange(n, dtype=np.uint32)
depths = np.linspace(0.0, 0.5, n).astype(np.float32)
colors = np.full((n, 4), 255, dtype=np.uint8)
%s
fields = output.GetFieldData()
for name, values in (("Frame", frame), ("Cell", cells), ("Depth", depths),
                     ("Sample_Colors", colors)):
    array = numpy_to_vtk(values, deep=1)
    array.SetName("vtkOFBPiece0_" + name)
    fields.AddArray(array)
"""


def save_local(view, name):
    """Renders `view` on the client (local rendering) into OUTPUT_DIR/name."""
    Render(view)
    values[name + ".remote"] = bool(
        view.GetClientSideObject().GetUseDistributedRenderingForRender())
    SaveScreenshot(os.path.join(args.output, name), view, ImageResolution=[SIZE, SIZE])


def check_delivered_ofb(view, display, settings):
    """The probe's OFB rendered on the client: with the OFB packed into the delivered
    surface (ofb-probe-local.png, as the server's ofb-surface.png), at the mesh's resolution
    (Use Input OFB off: the client's own OFB, ofb-probe-mesh.png), and from unusable packs
    (ofb-bad-KIND.png, the mesh-resolution picture of that surface ofb-bad-mesh.png)."""
    settings.RemoteRenderThreshold = 1.0e6
    save_local(view, "ofb-probe-local.png")
    # The delivered surface's size (KiB) with the packed samples, and without.
    values["probe_delivered_kib"] = display.GetRepresentedDataInformation().GetMemorySize()
    values["probe_ofb_samples"] = particles.GetDataInformation(0).GetNumberOfPoints()
    display.UseInputOFB = 0
    save_local(view, "ofb-probe-mesh.png")
    values["mesh_delivered_kib"] = display.GetRepresentedDataInformation().GetMemorySize()
    display.UseInputOFB = 1
    Hide(probe, view)
    for kind, corruption in sorted(BAD_PACKS.items()):
        # The surface without ghost cells: ParaView's geometry filter keeps its field data.
        bad = ProgrammableFilter(Input=surface, Script=BAD_PACK_SCRIPT % corruption)
        shown = Show(bad, view)
        shown.SetRepresentationType("OFB Surface")
        shown.ColorArrayName = ["POINTS", ""]
        shown.DiffuseColor = [1.0, 1.0, 1.0]
        shown.OFBResolution = 128
        say("bad packs:", kind)
        save_local(view, "ofb-bad-%s.png" % kind)
        if kind == sorted(BAD_PACKS)[0]:
            shown.UseInputOFB = 0
            save_local(view, "ofb-bad-mesh.png")
        Hide(bad, view)
        Delete(bad)
    Show(probe, view)
    settings.RemoteRenderThreshold = 0.0


# The view: the probed mesh as OFB Surface, its colours from the OFB it carries.
view = GetActiveViewOrCreate("RenderView") if args.gui else CreateView("RenderView")
if not args.gui:
    view.ViewSize = [SIZE, SIZE]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
view.CameraPosition = [1.2, -2.2, 1.0]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
view.CameraParallelScale = 0.6
display = Show(probe, view)
display.SetRepresentationType("OFB Surface")
display.ColorArrayName = ["POINTS", ""]
display.DiffuseColor = [1.0, 1.0, 1.0]
display.OFBLIC = 1
display.SelectOFBInputVectors = ["POINTS", "Field"]
display.OFBLICIntensity = 0.6
settings = GetSettingsProxy("RenderViewSettings")
if client:
    # Remote rendering: the server renders (IceT composites its ranks) and sends the image.
    settings.RemoteRenderThreshold = 0.0
Render(view)
values["remote_render"] = bool(view.GetClientSideObject().GetUseDistributedRenderingForRender())
SaveScreenshot(os.path.join(args.output, "ofb-surface.png"), view, ImageResolution=[SIZE, SIZE])
if client:
    check_delivered_ofb(view, display, settings)

# The surface of one process rendered with the OFB the representation builds: on the client
# (local rendering: the server delivers the surface) and, as its reference, in a pvbatch of
# one process.
Hide(probe, view)
whole = Show(ghosted, view)
whole.SetRepresentationType("OFB Surface")
whole.ColorArrayName = ["POINTS", ""]
whole.DiffuseColor = [1.0, 0.85, 0.5]
whole.OFBResolution = 256
whole.OFBLIC = 1
whole.SelectOFBInputVectors = ["POINTS", "Field"]
whole.OFBLICIntensity = 0.8
if client:
    settings.RemoteRenderThreshold = 1.0e6
    Render(view)
    values["local_remote_render"] = bool(
        view.GetClientSideObject().GetUseDistributedRenderingForRender())
    SaveScreenshot(os.path.join(args.output, "ofb-surface-local.png"), view,
                   ImageResolution=[SIZE, SIZE])
elif ranks == 1:
    Render(view)
    if args.gui:
        values["gui_representation_types"] = [
            t for t in whole.GetProperty("RepresentationTypesInfo")[:] if t.startswith("OFB")]
        # What the Pipeline Browser lists: the proxies registered as sources.
        values["gui_sources"] = sorted(
            name for (name, _), proxy in GetSources().items()
            if proxy.GetXMLName() in OFB_FILTERS)
    SaveScreenshot(os.path.join(args.output, "ofb-surface-whole.png"), view,
                   ImageResolution=[SIZE, SIZE])

# The OFB writer (File > Save Data), run where the OFB is: on the server.
obj = os.path.join(args.output, "ofb-cs-sphere.obj")
gltf = os.path.join(args.output, "ofb-cs-sphere.gltf")
try:
    SaveData(gltf, proxy=probe, TextureSize=256)  # the only .gltf writer
    values["writer"] = "SaveData"
except Exception as error:  # ParaView finds no writer for the data (an error) and raises
    values["writer"] = "refused"
    say("Save Data refused:", error)
if values["writer"] == "SaveData":
    # .obj has ParaView's own writer too: the OFB writer by name.
    writer = servermanager.writers.OFBTexturedMeshWriter(Input=probe, FileName=obj,
                                                         TextureSize=256)
    writer.UpdatePipeline(20.0)
say("writer:", values["writer"])

with open(os.path.join(args.output, "values.json"), "w") as stream:
    json.dump(values, stream, indent=1)
say("ofbClientPipeline done:", "client of %s" % args.url if client else
    "the paraview GUI" if args.gui else "pvbatch", "on %d server processes" % ranks)
