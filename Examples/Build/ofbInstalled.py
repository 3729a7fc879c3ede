#!/usr/bin/env python3
"""A script that uses an installed vtkofb package: builds the OFB of a sphere on the
CPU, queries it, reads its paint through numpy, and writes and reads back its paint
bytes as a PNG (vtkOFBImageWriter and vtkOFBImageReader: the OpenImageIO module
installed beside the libraries). It opens no window.

Run it with Debian's /usr/bin/python3 (the interpreter python3-vtk9 installs into):
nothing more for the Debian package or the default prefix /usr/local, or
PYTHONPATH=<prefix>/lib/python3.<minor>/dist-packages for another prefix.
"""

import os
import sys
import tempfile

import vtkofb
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource

sphere = vtkSphereSource()
sphere.SetThetaResolution(48)
sphere.SetPhiResolution(24)

builder = vtkofb.vtkOFBBuilder()
builder.SetInputConnection(sphere.GetOutputPort())
builder.SetResolution(128)
builder.SetBackendToCPU()
builder.Update()

ofb = builder.GetOutput()
samples = ofb.GetNumberOfSamples()
if samples == 0:
    sys.exit("ofbInstalled.py: the builder made no samples")

x = (0.5, 0.0, 0.0)  # a point of the sphere (radius 0.5)
ids = vtkIdList()
ofb.FindSamplesInSphere(x, 3 * ofb.GetCellSize(), ids)
if ofb.FindClosestSample(x) < 0 or ids.GetNumberOfIds() == 0:
    sys.exit("ofbInstalled.py: no sample near (0.5, 0, 0)")
paint = vtk_to_numpy(ofb.GetSampleData().GetScalars())  # (samples, 4) uint8 RGBA

print(f"vtkofb {vtkofb.__version__} from {os.path.dirname(os.path.abspath(vtkofb.__file__))}")
print(f"{samples} samples (X {ofb.GetNumberOfSamples(0)}, Y {ofb.GetNumberOfSamples(1)}, "
      f"Z {ofb.GetNumberOfSamples(2)}), {ids.GetNumberOfIds()} within 3 cells of {x}, "
      f"paint {paint.shape[1]} channels")

# The first 64 samples' paint as an 8 x 8 RGBA PNG, written and read back.
image = vtkImageData()
image.SetDimensions(8, 8, 1)
image.GetPointData().SetScalars(numpy_to_vtk(paint[:64].copy(), deep=True))
with tempfile.TemporaryDirectory() as directory:
    png = os.path.join(directory, "paint.png")
    writer = vtkofb.vtkOFBImageWriter()
    writer.SetInputData(image)
    writer.SetFileName(png)
    written = writer.Write()
    reader = vtkofb.vtkOFBImageReader()
    reader.SetFileName(png)
    reader.Update()
    back = reader.GetOutput().GetPointData().GetScalars()
    if written != 1 or back is None or (vtk_to_numpy(back) != paint[:64]).any():
        sys.exit("ofbInstalled.py: the paint did not come back from a PNG")
print(f"paint written to and read back from a PNG ({reader.GetFormatName()})")
