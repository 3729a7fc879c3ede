#!/usr/bin/env python3
"""Write the hostile inputs of the applications' reliability tests into a directory.

Usage: make_hostile_inputs.py OUTDIR

Images (each refused by ofbexample::ReadImageChecked before a decoder allocates), meshes
(refused by ofbexample::ReadMeshChecked before VTK's readers and filters see them) and
stroke files (refused by OFBPaint's replay), as small files made at test time.
"""
import os
import stat
import struct
import sys
import zlib


def chunk(kind, data, crc=None):
    crc = zlib.crc32(kind + data) if crc is None else crc
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc & 0xFFFFFFFF)


def png(width, height, rows=None, idat=None, ihdr_crc=None, idat_crc=None):
    """An 8-bit RGB PNG; rows default to grey pixels of the claimed size."""
    if idat is None:
        raw = rows if rows is not None else b"".join(
            b"\0" + b"\x80" * (3 * width) for _ in range(height))
        idat = zlib.compress(raw)
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr, ihdr_crc) +
            chunk(b"IDAT", idat, idat_crc) + chunk(b"IEND", b""))


def images():
    good = png(16, 16)
    corrupt = bytearray(zlib.compress(b"\0" + b"\x80" * 48) * 1)
    corrupt[2:6] = b"\xff\xff\xff\xff"  # an invalid deflate block after the zlib header
    bmp_header = struct.pack("<2sIHHI", b"BM", 1000, 0, 0, 54) + struct.pack(
        "<IiiHHIIiiII", 40, 100000, 100000, 1, 24, 0, 0, 2835, 2835, 0, 0)
    return {
        "good.png": good,
        "truncated.png": good[: len(good) - 20],  # cut inside the image data
        "truncated-header.png": good[:20],  # cut inside IHDR
        "bad-crc.png": png(16, 16, idat_crc=0x12345678),
        "bad-zlib.png": png(4, 4, idat=bytes(corrupt)),
        "zero-width.png": png(0, 16, rows=b""),
        "zero-height.png": png(16, 0, rows=b""),
        "width-2pow31.png": png(2 ** 31, 1, idat=zlib.compress(b"\0" * 64)),
        "implausible.png": png(8000, 8000, idat=zlib.compress(b"\0" * 64)),
        "huge.bmp": bmp_header + b"\0" * 64,
        "huge.ppm": b"P6\n100000 100000\n255\n" + b"\0" * 64,
        "zero-size.ppm": b"P6\n0 0\n255\n",
    }


VTP = """<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian" header_type="UInt64">
<PolyData><Piece NumberOfPoints="3" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0"
 NumberOfPolys="1">
<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0
</DataArray></Points>
<Polys><DataArray type="Int64" Name="connectivity" format="ascii">0 1 99999</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">3</DataArray></Polys>
</Piece></PolyData></VTKFile>
"""


VTU = """<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian">
<UnstructuredGrid><Piece NumberOfPoints="4" NumberOfCells="1">
<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">
0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>
<Cells><DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 99999</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">4</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">10</DataArray></Cells>
</Piece></UnstructuredGrid></VTKFile>
"""


def collection(*files):
    return ('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1"><Collection>\n' +
            "".join('<DataSet timestep="%d" file="%s"/>\n' % (i, f) for i, f in enumerate(files))
            + "</Collection></VTKFile>\n")


def data_files():
    """Simulation-result formats (ofbexample::ReadDataSurface)."""
    return {
        "bad-index.vtu": VTU,
        "truncated.vtu": VTU[:200],
        "missing-part.pvd": collection("not-there.vtp"),
        "nested.pvd": collection("nested.pvd"),
        "no-datasets.pvd": collection(),
        "legacy-garbage.vtk": "# vtk DataFile Version 3.0\nbroken\nASCII\nDATASET NOSUCH\n",
    }


def meshes():
    tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    ply_ascii = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                 "property float y\nproperty float z\nelement face 1\n"
                 "property list uchar int vertex_indices\nend_header\n"
                 "0 0 0\n1 0 0\n0 1 0\n")
    binary_header = ("ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                     "property float x\nproperty float y\nproperty float z\n"
                     "element face 1\nproperty list uchar int vertex_indices\nend_header\n")
    body = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<B3i", 3, 0, 1, 2)
    return {
        "bad-index.obj": tri + "f 1 2 99999\n",
        "bad-texture-index.obj": tri + "vt 0 0\nf 1/1 2/99 3/1\n",
        "bad-normal-index.obj": tri + "vn 0 0 1\nf 1//1 2//1 3//7\n",
        "bad-index.vtp": VTP,
        "bad-index.ply": ply_ascii + "3 0 1 99999\n",
        "truncated.ply": (binary_header.encode() + body)[:-7],
        "billion.ply": ("ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\n"
                        "property float x\nproperty float y\nproperty float z\n"
                        "element face 1\nproperty list uchar int vertex_indices\n"
                        "end_header\n").encode() + body,
        "truncated.stl": b"\0" * 80 + struct.pack("<I", 1000000) + b"\0" * 50,
    }


def strokes(out):
    os.makedirs(os.path.join(out, "strokes-directory"), exist_ok=True)
    fifo = os.path.join(out, "strokes.fifo")
    if not os.path.exists(fifo):
        os.mkfifo(fifo)
    with open(os.path.join(out, "too-large.txt"), "wb") as f:
        f.truncate(17 << 20)  # sparse: over the 16 MiB limit without writing it
    with open(os.path.join(out, "too-many-lines.txt"), "w") as f:
        f.write("\n" * 1000001)
    return {
        # 40 bytes: two million dabs at the smallest step
        "dab-bomb.txt": "radius 1e-9\nstroke\n0 0 0\n7000 0 0\nend\n",
    }


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    files = {}
    files.update(images())
    files.update(meshes())
    files.update(data_files())
    files.update(strokes(out))
    for name, data in files.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data.encode() if isinstance(data, str) else data)
    print("wrote %d hostile inputs into %s" % (len(files), out))


if __name__ == "__main__":
    main()
