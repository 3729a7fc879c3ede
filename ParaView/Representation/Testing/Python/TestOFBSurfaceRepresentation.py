"""The OFB Surface representation in ParaView's render view, driven from paraview.simple.

    pvbatch TestOFBSurfaceRepresentation.py PLUGIN OUTPUT_DIR

Loads the plugin, shows a sphere with a rotation field about z and its elevation, and
renders it offscreen with the "OFB Surface" representation: by paint (the solid colour),
by a point array and a cell array through ParaView's colour map, at a coarse resolution,
and with the LIC blended and mapped, under two lookup modes. Each image is compared with
ParaView's own "Surface" rendering of the same colouring or measured: the LIC by its
high-pass energy inside the surface (streaks), the colour map by its hue from top to
bottom. The images are written to OUTPUT_DIR. Exits 1 with the failed checks listed.
"""

import os
import sys

import numpy as np
from paraview.simple import (Calculator, ColorBy, CreateView, Elevation, Hide, Line, LoadPlugin,
                             PointDatatoCellData, Render, SaveScreenshot, Show, Sphere,
                             Threshold)

# The plugin tests' support module (ParaView/Testing): PNG pixels, eroded masks.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir,
                                os.pardir, "Testing"))
from ofbParaViewTesting import erode, png_pixels  # noqa: E402

SIZE = 300
failures = []


def check(condition, message):
    print(("ok     " if condition else "FAILED ") + message)
    if not condition:
        failures.append(message)


def screenshot(view, name):
    """The view rendered offscreen, as a float array of shape (height, width, 3)."""
    path = os.path.join(OUTPUT_DIR, name + ".png")
    SaveScreenshot(path, view, ImageResolution=[SIZE, SIZE])
    return png_pixels(path)


def high_pass_energy(image, mask):
    """Mean square of the grey minus its 3x3 mean, inside the mask: streaks give energy."""
    grey = image.mean(axis=2)
    padded = np.pad(grey, 1, mode="edge")
    local = sum(padded[1 + dy:1 + dy + grey.shape[0], 1 + dx:1 + dx + grey.shape[1]]
                for dy in (-1, 0, 1) for dx in (-1, 0, 1)) / 9.0
    return float(((grey - local)[mask] ** 2).mean())


def mean_difference(a, b, mask):
    return float(np.abs(a - b)[mask].mean())


PLUGIN, OUTPUT_DIR = sys.argv[1], sys.argv[2]
os.makedirs(OUTPUT_DIR, exist_ok=True)
LoadPlugin(PLUGIN, remote=False, ns=globals())

# A sphere, the rotation about z (its streamlines are the parallels) and the elevation.
sphere = Sphere(ThetaResolution=48, PhiResolution=48)
field = Calculator(Input=sphere, ResultArrayName="V", Function="-coordsY*iHat + coordsX*jHat")
elevation = Elevation(Input=field, LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5])
cells = PointDatatoCellData(Input=elevation)

view = CreateView("RenderView")
view.ViewSize = [SIZE, SIZE]
view.OrientationAxesVisibility = 0
view.CameraPosition = [0, -3, 0.8]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
display = Show(elevation, view)
view.ResetCamera()

types = display.GetProperty("RepresentationTypesInfo")[:]
check("OFB Surface" in types, "'OFB Surface' is a representation type: %s" % types)

# ParaView's own rendering: the references and the surface's mask.
display.SetRepresentationType("Surface")
ColorBy(display, ("POINTS", "Elevation"))
surface_elevation = screenshot(view, "surface_elevation")
background = surface_elevation[0, 0]
mask = erode(np.abs(surface_elevation - background).sum(axis=2) > 30, 3)
# VTK's images start at the bottom row: the thirds of the sphere's rows from below.
rows = np.nonzero(mask.any(axis=1))[0]
bottom = mask.copy()
bottom[rows[0] + len(rows) // 3:, :] = False
top = mask.copy()
top[:rows[-1] - len(rows) // 3, :] = False
check(mask.sum() > 0.3 * np.pi * (0.4 * SIZE) ** 2 * 0.5, "the sphere covers the view")

display.SetRepresentationType("OFB Surface")

# Paint: the solid colour.
ColorBy(display, None)
display.DiffuseColor = [1.0, 0.0, 0.0]
display.AmbientColor = [1.0, 0.0, 0.0]
paint = screenshot(view, "ofb_paint")
red, green, blue = (paint[:, :, c][mask].mean() for c in range(3))
check(red > 120 and green < 40 and blue < 40,
      "paint shows the solid colour (mean RGB %.0f %.0f %.0f)" % (red, green, blue))

# A point array through ParaView's colour map: as ParaView's own surface.
ColorBy(display, ("POINTS", "Elevation"))
ofb_elevation = screenshot(view, "ofb_elevation")
difference = mean_difference(ofb_elevation, surface_elevation, mask)
check(difference < 4.0, "colour map by a point array as Surface (mean |difference| %.2f)"
      % difference)
plain_energy = high_pass_energy(ofb_elevation, mask)

# The colour resolution is the OFB's: 12 cells on the sphere's diameter show steps.
display.OFBResolution = 12
coarse = screenshot(view, "ofb_elevation_coarse")
coarse_difference = mean_difference(coarse, surface_elevation, mask)
check(coarse_difference > 2 * difference + 1.0,
      "OFB Resolution 12 is coarser (mean |difference| %.2f against %.2f)"
      % (coarse_difference, difference))
display.OFBResolution = 1024

# A cell array: each sample its cell's value, as Surface shows the cells.
cell_display = Show(cells, view)
display.Visibility = 0
cell_display.SetRepresentationType("Surface")
ColorBy(cell_display, ("CELLS", "Elevation"))
surface_cells = screenshot(view, "surface_cells")
cell_display.SetRepresentationType("OFB Surface")
ofb_cells = screenshot(view, "ofb_cells")
cell_difference = mean_difference(ofb_cells, surface_cells, erode(mask, 1))
check(cell_difference < 6.0, "colour map by a cell array as Surface (mean |difference| %.2f)"
      % cell_difference)
cell_display.Visibility = 0
display.Visibility = 1

# The LIC of the rotation, blended with the colour map (ParaView's default intensity).
display.OFBLIC = 1
display.SelectOFBInputVectors = ["POINTS", "V"]
blend = screenshot(view, "ofb_lic_blend")
blend_energy = high_pass_energy(blend, mask)
check(blend_energy > 20 * plain_energy and blend_energy > 40,
      "LIC blended shows streaks (high-pass energy %.1f, without LIC %.2f)"
      % (blend_energy, plain_energy))

# Mapped: the colour map's hue kept under the LIC (red at the top, blue at the bottom).
display.OFBLICColorMode = "Map"
mapped = screenshot(view, "ofb_lic_map")
map_energy = high_pass_energy(mapped, mask)
top_rb = mapped[:, :, 0][top].mean() - mapped[:, :, 2][top].mean()
bottom_rb = mapped[:, :, 0][bottom].mean() - mapped[:, :, 2][bottom].mean()
check(map_energy > 20 * plain_energy, "LIC mapped shows streaks (high-pass energy %.1f)"
      % map_energy)
check(top_rb > 20 and bottom_rb < 0,
      "LIC mapped keeps the colour map (red - blue: top %.0f, bottom %.0f)" % (top_rb, bottom_rb))
check(mean_difference(mapped, blend, mask) > 10, "Map differs from Blend")

# Lookup mode Nearest: the same streaks, read without filtering.
display.OFBLookupMode = "Nearest"
nearest = screenshot(view, "ofb_lic_map_nearest")
nearest_energy = high_pass_energy(nearest, mask)
nearest_difference = mean_difference(nearest, mapped, mask)
check(nearest_energy > 20 * plain_energy and nearest_difference > 1.0,
      "lookup mode Nearest renders the LIC (energy %.1f, mean |difference| to Automatic %.2f)"
      % (nearest_energy, nearest_difference))

# Paint from an OFB upstream: a stroke painted into the OFB by OFB Paint Strokes, carried
# to the representation by OFB Probe's output. The input OFB shows it at the OFB's
# resolution; the probed vertex colours (Use Input OFB off, or ParaView's Surface with
# direct colours) blur it over the mesh's triangles.
display.Visibility = 0
coarse_sphere = Sphere(ThetaResolution=24, PhiResolution=24)
sampled = OFBSampler(Input=coarse_sphere)
sampled.Resolution = 256
stroke = Line(Point1=[0, -0.5, -0.15], Point2=[0, -0.5, 0.15], Resolution=30)
painted = OFBPaintStrokes(Input=sampled, Strokes=stroke)
painted.BrushRadius = 0.06
painted.BrushColor = [1.0, 0.8, 0.0, 1.0]
probed = OFBProbe(Input=coarse_sphere, OFB=painted)
paint_display = Show(probed, view)
paint_display.SetRepresentationType("OFB Surface")
ColorBy(paint_display, None)
input_paint = screenshot(view, "ofb_input_paint")
ColorBy(paint_display, ("POINTS", "Colors"))
paint_display.MapScalars = 0
input_direct = screenshot(view, "ofb_input_paint_direct")
paint_display.SetRepresentationType("Surface")
vertex_paint = screenshot(view, "surface_vertex_paint")


def stroke_pixels(image):
    """Pixels of the stroke (yellow: green well above blue): the core and the blurred edge."""
    yellow = (image[:, :, 1] - image[:, :, 2])[mask]
    top = yellow.max()
    crisp = int((yellow > 0.7 * top).sum())
    blurred = int(((yellow > 0.15 * top) & (yellow <= 0.7 * top)).sum())
    return crisp, blurred


core, edge = stroke_pixels(input_paint)
vertex_core, vertex_edge = stroke_pixels(vertex_paint)
check(core > 100 and edge < core,
      "the input OFB's paint shows crisp (stroke core %d pixels, edge %d)" % (core, edge))
check(vertex_edge > 3 * edge,
      "the vertex colours blur it (edge %d pixels against %d from the OFB)" % (vertex_edge, edge))
check(mean_difference(input_direct, input_paint, mask) < 0.5,
      "direct colours (Map Scalars off) show the paint (mean |difference| %.2f)"
      % mean_difference(input_direct, input_paint, mask))
Hide(probed, view)

# Bad input: the OFB cannot be built (no polygons, no cells) or the LIC has no field. The
# sampler reports an error, the mapper draws the surface plainly; nothing crashes.
lines = Show(Line(Resolution=10), view)
lines.SetRepresentationType("OFB Surface")
screenshot(view, "ofb_lines")
Hide(lines.Input, view)
empty = Show(Threshold(Input=elevation, Scalars=["POINTS", "Elevation"],
                       LowerThreshold=5.0, UpperThreshold=6.0), view)
empty.SetRepresentationType("OFB Surface")
nothing = screenshot(view, "ofb_empty")
check(np.abs(nothing - background).sum(axis=2).max() < 30,
      "an empty input renders nothing (max difference to the background %.0f)"
      % np.abs(nothing - background).sum(axis=2).max())
Hide(empty.Input, view)
no_field = Show(Elevation(Input=Sphere(ThetaResolution=48, PhiResolution=48),
                          LowPoint=[0, 0, -0.5], HighPoint=[0, 0, 0.5]), view)
no_field.SetRepresentationType("OFB Surface")
ColorBy(no_field, ("POINTS", "Elevation"))
no_field.OFBLIC = 1
no_field.SelectOFBInputVectors = ["POINTS", "V"]
without_field = screenshot(view, "ofb_lic_without_field")
difference = mean_difference(without_field, ofb_elevation, mask)
check(difference < 1.0, "LIC on without a vector field shows the colours (mean |difference| "
      "to the colours alone %.2f)" % difference)

Render(view)
if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
