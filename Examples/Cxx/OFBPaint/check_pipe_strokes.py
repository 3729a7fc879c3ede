#!/usr/bin/env python3
"""Check OFBPaint's strokes on the pipe of make_data_inputs.py (pipe-strokes.txt, saved
with --save): the four sparse points around the wall at y = 0 painted one continuous red
ring (every sample of the wall within half the radius of y = 0 is red) and nothing far
from it (no red sample farther than the radius and two cells from y = 0).

Usage: check_pipe_strokes.py PAINTED.ofb
"""
import sys

import numpy as np
from vtkmodules.util import numpy_support

import vtkofb

RADIUS = 0.08  # pipe-strokes.txt's


def main():
    reader = vtkofb.vtkOFBReader()
    reader.SetFileName(sys.argv[1])
    reader.Update()
    ofb = reader.GetOutput()
    n = ofb.GetNumberOfSamples()
    if n == 0:
        sys.exit("FAIL: no samples in " + sys.argv[1])
    colors = numpy_support.vtk_to_numpy(ofb.GetSampleData().GetArray("Colors"))
    y = np.empty(n)
    x = [0.0, 0.0, 0.0]
    for i in range(n):
        ofb.GetSamplePosition(i, x)
        y[i] = x[1]
    red = (colors[:, 0] > 200) & (colors[:, 1] < 60) & (colors[:, 2] < 60)
    near = np.abs(y) < 0.5 * RADIUS
    far = np.abs(y) > RADIUS + 2.0 * ofb.GetCellSize()
    print("%d samples near the ring, %d of them red; %d red samples far from it"
          % (near.sum(), (red & near).sum(), (red & far).sum()))
    if near.sum() < 100 or not red[near].all() or red[far].any():
        sys.exit("FAIL: the strokes did not paint one continuous ring on the wall")
    print("check passed")


if __name__ == "__main__":
    main()
