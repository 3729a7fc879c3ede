"""The plumbing the Python examples share, kept out of their pipelines: reading data (the
same inputs and options as the C++ applications: .vtp, .vtu, .vtm, .pvd, legacy .vtk, .stl,
.obj, .ply by content or extension; --field, --block, --time, --time-step), the view options,
an off-screen window that frames the surface, its picture written as a PNG (and returned
as an array, for the examples' --check), and how much of a picture is vivid colour.

The examples import it from their own folder (Python puts a script's folder on sys.path).
"""

import os
import struct
import sys
import xml.etree.ElementTree as ElementTree

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkCommand, vtkLookupTable
from vtkmodules.vtkCommonDataModel import (vtkCompositeDataSet, vtkDataObjectTree, vtkDataSet,
                                           vtkMultiBlockDataSet, vtkPolyData)
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOLegacy import vtkGenericDataObjectReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL implementations)


class DataError(Exception):
    """Why a data file cannot be used (the message the examples print before exiting)."""


def _detect(path):
    """The format of the file by its first bytes, else by its extension."""
    with open(path, "rb") as f:
        head = f.read(1024)
    size = os.path.getsize(path)
    text = head.lstrip(b" \t\r\n\xef\xbb\xbf")
    if text.startswith(b"<?xml") or text.startswith(b"<VTKFile"):
        return "collection" if b'type="Collection"' in text else "xml"
    if text.startswith(b"# vtk DataFile"):
        return "legacy"
    if text.startswith(b"ply\n") or text.startswith(b"ply\r\n"):
        return "ply"
    if text.startswith(b"solid") or (len(head) >= 84 and
                                     size == 84 + 50 * struct.unpack("<I", head[80:84])[0]):
        return "stl"
    ext = os.path.splitext(path)[1].lower()
    if ext in (".obj", ".ply", ".stl"):
        return ext[1:]
    for line in head.decode("latin-1").splitlines():
        words = line.split()
        if words and not words[0].startswith("#"):
            return "obj" if words[0] in ("v", "vt", "vn", "f", "o", "g", "s", "mtllib",
                                         "usemtl", "l", "p") else None
    return None


def _choose_step(times, time, time_step):
    """The index of the step asked for in `times` (0 without a time option)."""
    asked = time is not None or time_step is not None
    if not times:
        if asked:
            raise DataError("the file has no time steps (--time and --time-step need a .pvd "
                            "or a file with time steps)")
        return 0
    described = "%d time step%s, times %g to %g" % (len(times), "s" if len(times) > 1 else "",
                                                    times[0], times[-1])
    if time_step is not None:
        if not 0 <= time_step < len(times):
            raise DataError("time step %d is outside the file's %s (steps 0 to %d)"
                            % (time_step, described, len(times) - 1))
        return time_step
    if time is not None:
        slack = 1e-9 * max(1.0, abs(times[-1] - times[0]))
        if not times[0] - slack <= time <= times[-1] + slack:
            raise DataError("time %g is outside the file's %s" % (time, described))
        return min(range(len(times)), key=lambda i: abs(times[i] - time))
    return 0


def _run(reader, time=None, time_step=None):
    """Update a VTK reader at the asked time step; its errors become a DataError."""
    errors = []
    reader.AddObserver(vtkCommand.ErrorEvent, lambda o, e, d=None: errors.append(d),
                       1.0)
    reader.UpdateInformation()
    info = reader.GetOutputInformation(0)
    key = vtkStreamingDemandDrivenPipeline.TIME_STEPS()
    times = list(info.Get(key)) if not errors and info.Has(key) else []
    step = _choose_step(times, time, time_step)
    if times:
        reader.UpdateTimeStep(times[step])
    else:
        reader.Update()
    data = reader.GetOutputDataObject(0)
    if errors or data is None:
        raise DataError("the reader failed")
    return data


def _read_file(path, time, time_step, in_collection=False):
    if not os.path.isfile(path):
        raise DataError("no such file" if not os.path.exists(path) else "not a regular file")
    kind = _detect(path)
    if kind == "collection":
        if in_collection:
            raise DataError("a collection inside a collection")
        return _read_collection(path, time, time_step)
    if kind in ("xml", "legacy"):
        reader = vtkXMLGenericDataObjectReader() if kind == "xml" else vtkGenericDataObjectReader()
        if kind == "legacy":
            reader.ReadAllScalarsOn()
            reader.ReadAllVectorsOn()
            reader.ReadAllFieldsOn()
        reader.SetFileName(path)
        return _run(reader, None if in_collection else time, None if in_collection else time_step)
    if kind in ("obj", "ply", "stl"):
        if not in_collection and (time is not None or time_step is not None):
            _choose_step([], time, time_step)
        reader = {"obj": vtkOBJReader, "ply": vtkPLYReader, "stl": vtkSTLReader}[kind]()
        reader.SetFileName(path)
        return _run(reader)
    raise DataError("unknown format: not a VTK XML (.vtp, .vtu, .vtm, ...), .pvd, legacy .vtk, "
                    "PLY, STL or OBJ file (extension '%s')" % os.path.splitext(path)[1])


def _read_collection(path, time, time_step):
    """A .pvd: the parts of the chosen time step as the blocks of a multiblock."""
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as error:
        raise DataError("not a readable .pvd collection: %s" % error)
    entries = []
    for n, e in enumerate(root.iter("DataSet")):
        try:
            entries.append((float(e.get("timestep", 0)), int(e.get("part", 0)), e.attrib["file"]))
        except (KeyError, ValueError):
            raise DataError("DataSet entry %d has no file or a bad timestep" % n)
    if not entries:
        raise DataError("the collection lists no DataSet")
    times = sorted(set(t for t, _, _ in entries))
    chosen = times[_choose_step(times, time, time_step)]
    blocks = vtkMultiBlockDataSet()
    for t, _, name in sorted(entries, key=lambda e: e[1]):
        if t != chosen:
            continue
        try:
            part = _read_file(os.path.join(os.path.dirname(path), name), None, None, True)
        except DataError as error:
            raise DataError("its file '%s': %s" % (name, error))
        n = blocks.GetNumberOfBlocks()
        blocks.SetBlock(n, part)
        blocks.GetMetaData(n).Set(vtkCompositeDataSet.NAME(), os.path.splitext(name)[0])
    return blocks


def _leaves(data):
    """(flat index, name, data set) of every non-empty leaf."""
    if isinstance(data, vtkDataSet):
        return [(0, "", data)]
    if not isinstance(data, vtkDataObjectTree):
        return []
    leaves = []
    it = data.NewTreeIterator()
    it.VisitOnlyLeavesOn()
    it.SkipEmptyNodesOn()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        name = ""
        if it.HasCurrentMetaData() and it.GetCurrentMetaData().Has(vtkCompositeDataSet.NAME()):
            name = it.GetCurrentMetaData().Get(vtkCompositeDataSet.NAME())
        if isinstance(it.GetCurrentDataObject(), vtkDataSet):
            leaves.append((it.GetCurrentFlatIndex(), name, it.GetCurrentDataObject()))
        it.GoToNextItem()
    return leaves


def _check_block(index, data):
    """Finite points and cell point ids in range, before a filter reads them."""
    n = data.GetNumberOfPoints()
    if n and data.GetPoints() is not None:
        points = numpy_support.vtk_to_numpy(data.GetPoints().GetData())
        if not np.isfinite(points).all():
            raise DataError("block %d: a point is not finite" % index)
    cells = ([data.GetVerts(), data.GetLines(), data.GetPolys(), data.GetStrips()]
             if isinstance(data, vtkPolyData) else
             [data.GetCells()] if hasattr(data, "GetCells") and data.GetCells() is not None
             else [])
    for array in cells:
        ids = numpy_support.vtk_to_numpy(array.GetConnectivityArray())
        if ids.size and (ids.min() < 0 or ids.max() >= n):
            raise DataError("block %d: a cell uses point %d, not one of the %d points"
                            % (index, ids.max() if ids.max() >= n else ids.min(), n))


def _merge_blocks(data, chosen):
    """The chosen blocks as one surface, as the C++ applications' MergeBlocks: a data set's
    polygons or outer surface; a composite data set's chosen blocks through
    vtkOFBMergeBlocks (BlockIndex, shared points merged, the union of the arrays), the
    others left empty so that the flat indices stay the file's."""
    for index, _, block in chosen:
        _check_block(index, block)
    if isinstance(data, vtkPolyData):
        return data
    if isinstance(data, vtkDataSet):
        extract = vtkDataSetSurfaceFilter()
        extract.SetInputData(data)
        extract.Update()
        return extract.GetOutput()
    import vtkofb  # the examples' own module, built beside them
    blocks = data.NewInstance()
    blocks.CopyStructure(data)
    wanted = set(index for index, _, _ in chosen)
    it = data.NewTreeIterator()
    it.VisitOnlyLeavesOn()
    it.SkipEmptyNodesOn()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        if it.GetCurrentFlatIndex() in wanted:
            blocks.SetDataSet(it, it.GetCurrentDataObject())
        it.GoToNextItem()
    merge = vtkofb.vtkOFBMergeBlocks()
    merge.SetInputData(blocks)
    merge.Update()
    return merge.GetOutput()


def describe_arrays(surface):
    """The surface's arrays, vectors first, for a message."""
    parts = []
    for label, data, vectors in (("point vectors", surface.GetPointData(), True),
                                 ("cell vectors", surface.GetCellData(), True),
                                 ("other point arrays", surface.GetPointData(), False),
                                 ("other cell arrays", surface.GetCellData(), False)):
        names = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays())
                 if data.GetArray(i) is not None and
                 (data.GetArray(i).GetNumberOfComponents() == 3) == vectors]
        if names:
            parts.append(label + ": " + ", ".join(names))
    return "; ".join(parts) if parts else "no point or cell arrays"


def read_data(path, field=None, block=None, time=None, time_step=None, vectors=False):
    """The data at `path` as one surface: (surface, field array or None, True when the field
    is a cell array). `block` a comma-separated list of flat indices or names (None: all),
    `time` the step closest to it, `time_step` a step by index, `field` a point or cell array
    (with `vectors`, of 3 components). Raises DataError with the reason."""
    try:
        data = _read_file(path, time, time_step)
    except OSError as error:
        raise DataError("cannot read '%s': %s" % (path, error.strerror or error))
    except DataError as error:
        raise DataError("cannot read '%s': %s" % (path, error))
    leaves = _leaves(data)
    listed = ", ".join("%d%s" % (i, " (%s)" % n if n else "") for i, n, _ in leaves) or "none"
    chosen = leaves
    if block:
        chosen = []
        for item in block.split(","):
            match = [leaf for leaf in leaves if leaf[1] == item or str(leaf[0]) == item]
            if not match:
                raise DataError("cannot read '%s': no block '%s'; its blocks (flat index and "
                                "name): %s" % (path, item, listed))
            chosen += match[:1]
    if not chosen:
        raise DataError("cannot read '%s': no data set in the file" % path)
    try:
        surface = _merge_blocks(data, chosen)
    except DataError as error:
        raise DataError("cannot read '%s': %s" % (path, error))
    if surface.GetNumberOfPolys() + surface.GetNumberOfStrips() == 0:
        raise DataError("cannot read '%s': no polygons in the file" % path)
    array, on_cells = None, False
    if field:
        array = surface.GetPointData().GetArray(field)
        if array is None:
            array = surface.GetCellData().GetArray(field)
            on_cells = array is not None
        if array is None:
            raise DataError("'%s' has no point or cell array '%s'; its arrays: %s"
                            % (path, field, describe_arrays(surface)))
        if vectors and array.GetNumberOfComponents() != 3:
            raise DataError("'%s' of '%s' has %d component(s), not a vector field; its arrays: %s"
                            % (field, path, array.GetNumberOfComponents(),
                               describe_arrays(surface)))
    return surface, array, on_cells


def add_data_options(parser, field_help="a point or cell array of the data"):
    """--field, --block, --time and --time-step, as the C++ applications take them."""
    parser.add_argument("--field", help=field_help)
    parser.add_argument("--block", help="the blocks to show: flat indices or names, "
                                        "comma-separated (default all)")
    parser.add_argument("--time", type=float, help="the time step closest to this time")
    parser.add_argument("--time-step", type=int, help="the time step by its index, from 0")


def read_data_or_exit(path, args, vectors=False, field=None):
    """read_data with the options of add_data_options; exits with the message on failure."""
    try:
        return read_data(path, args.field if field is None else field, args.block, args.time,
                         args.time_step, vectors)
    except DataError as error:
        sys.exit(str(error))


def paint_field(ofb, name):
    """Start the paint from the OFB's sample array `name` (a point array interpolated, a
    cell array per triangle; a vector's magnitude) through a blue-to-red map over its
    range, as OFBPaint --field does."""
    data = ofb.GetSampleData()
    values = numpy_support.vtk_to_numpy(data.GetArray(name)).astype(np.float64)
    if values.ndim > 1:
        values = np.linalg.norm(values, axis=1)
    finite = np.isfinite(values)
    low, high = (values[finite].min(), values[finite].max()) if finite.any() else (0.0, 1.0)
    table = vtkLookupTable()
    table.SetHueRange(0.667, 0.0)
    table.Build()
    rgba = np.array([table.GetTableValue(i) for i in range(table.GetNumberOfTableValues())])
    values = np.where(finite, values, low)
    index = np.clip(((values - low) / max(high - low, 1e-300) * len(rgba)).astype(np.int64),
                    0, len(rgba) - 1)
    colors = numpy_support.vtk_to_numpy(data.GetArray("Colors"))
    colors[:] = np.round(255.0 * rgba[index]).astype(np.uint8)
    data.GetArray("Colors").Modified()
    ofb.MarkAllSamplesModified()
    ofb.Modified()


def read_surface(path):
    """The surface of a mesh or data file (read_data, every block, the first time step);
    exits with a message when it cannot be read or has no polygons."""
    try:
        return read_data(path)[0]
    except DataError as error:
        sys.exit(str(error))


def add_view_options(parser, azimuth=0.0):
    """--size, --up, --azimuth and --elevation, as the examples' help describes them."""
    parser.add_argument("--size", type=int, default=600, help="image width and height (pixels)")
    parser.add_argument("--up", choices=["x", "y", "z"], default="y",
                        help="the mesh's up axis (the bunny's is y, the horse's z)")
    parser.add_argument("--azimuth", type=float, default=azimuth, help="degrees")
    parser.add_argument("--elevation", type=float, default=10.0, help="degrees")


def render_offscreen(actor, args, background=(0.1, 0.1, 0.15)):
    """Render `actor` off screen, seen from the side (up axis `args.up`, turned by
    `args.azimuth` and `args.elevation`) and filling most of a square of `args.size`
    pixels. Returns the window."""
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(*background)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(args.size, args.size)
    window.AddRenderer(renderer)
    frame_camera(renderer, args, 1.4)
    window.Render()
    return window


def frame_camera(renderer, args, dolly):
    """Point the renderer's camera at its props from the side (up axis `args.up`, turned
    by `args.azimuth` and `args.elevation`), reset it and move it closer by `dolly`."""
    up = "xyz".index(args.up)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetPosition(*[1.0 if k == (up + 1) % 3 else 0.0 for k in range(3)])
    camera.SetViewUp(*[1.0 if k == up else 0.0 for k in range(3)])
    camera.Azimuth(args.azimuth)
    camera.Elevation(args.elevation)
    renderer.ResetCamera()
    camera.Dolly(dolly)
    renderer.ResetCameraClippingRange()


def save_png(window, path):
    """Write the window's picture to `path`; returns its pixels, (n, 3) uint8 RGB."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"wrote {path}")
    return numpy_support.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3]


def vivid_share(rgb, saturation=0.4):
    """The share of pixels of (n, 3) uint8 RGB whose HSV saturation exceeds `saturation`."""
    c = rgb.astype(float) / 255.0
    high = c.max(axis=1)
    return float(np.mean((high - c.min(axis=1)) / np.maximum(high, 1e-6) > saturation))
