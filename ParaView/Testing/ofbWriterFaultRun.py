"""The pvbatch part of TestOFBWriterFaults.py: the OFB writer under MPI, to be killed or fed
processes whose OFBs differ.

    mpiexec -np N pvbatch --symmetric ofbWriterFaultRun.py PLUGIN MESH DIR CONTROL [options]

Every process runs this script (--symmetric) and first writes its process id to
CONTROL/pid-<rank>. The mesh file MESH is given texture coordinates (Texture Map to
Plane: the writer bakes a texture of TextureSize a side rather than an atlas, so a large
TextureSize makes a long write), distributed by RedistributeDataSet with ghost cells,
sampled (OFB Sampler), and OFB Probe hands its mesh and OFB to the writer, which writes
DIR/writer.obj (+ writer.mtl, writer.png).

Options:
  --existing         first write a complete export at TextureSize 64 and print
                     "complete export written" (the driver reads its bytes then)
  --texture N        the TextureSize of the write that is to be killed (default 2048)
  --other-at-gather kill|stop
                     the writer's StartEvent on the first process creates
                     CONTROL/writing-0; on the others the StartEvent waits for that file
                     and kills (SIGKILL) or stops (SIGSTOP) its own process: the first
                     process is then inside its write, waiting for the others' pieces
                     (the gather)
  --frames-differ    the first process samples at resolution 64, the others at 48: their
                     OFBs have different frames; the writer must refuse the write on every
                     process with the same error code and write nothing. Prints
                     "frames-differ: error codes [...]" and "frames-differ checks passed".
"""
import argparse
import os
import signal
import time

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile, TextureMaptoPlane
from vtkmodules.vtkCommonCore import vtkIntArray

import ofbParaViewTesting

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("mesh")
parser.add_argument("dir")
parser.add_argument("control")
parser.add_argument("--existing", action="store_true")
parser.add_argument("--texture", type=int, default=2048)
parser.add_argument("--other-at-gather", choices=["kill", "stop"])
parser.add_argument("--frames-differ", action="store_true")
args = parser.parse_args()

LoadPlugin(args.plugin, ns=globals())
controller, rank, ranks = ofbParaViewTesting.processes()
say, _ = ofbParaViewTesting.reporter(rank=rank)
with open(os.path.join(args.control, "pid-%d" % rank), "w") as stream:
    stream.write("%d\n" % os.getpid())


textured = TextureMaptoPlane(Input=OpenDataFile(args.mesh))
ghosted = ofbParaViewTesting.distributed_surface(textured)
resolution = 48 if args.frames_differ and rank > 0 else 64
sampler = OFBSampler(Input=ghosted, Resolution=resolution)
probe = OFBProbe(Input=ghosted, OFB=sampler)
probe.UpdatePipeline()
target = os.path.join(args.dir, "writer.obj")
writer = servermanager.writers.OFBTexturedMeshWriter(Input=probe, FileName=target)
# The writer itself (pvbatch: the proxy's object on this process).
vtk_writer = writer.GetClientSideObject()

if args.existing:
    writer.TextureSize = 64
    writer.UpdatePipeline()
    controller.Barrier()
    say("complete export written")

if args.other_at_gather:
    marker = os.path.join(args.control, "writing-0")

    def started(caller, event):
        # (The pipeline and vtkWriter both send a StartEvent before the write.)
        if rank == 0:
            if not os.path.exists(marker):
                open(marker, "w").close()
                print("rank 0: the write starts", flush=True)
            return
        deadline = time.monotonic() + 60
        while not os.path.exists(marker) and time.monotonic() < deadline:
            time.sleep(0.01)
        print("rank %d: %s before it sends its piece" % (
            rank, "killing itself" if args.other_at_gather == "kill" else "stopping"),
            flush=True)
        os.kill(os.getpid(), signal.SIGKILL if args.other_at_gather == "kill" else signal.SIGSTOP)

    vtk_writer.AddObserver("StartEvent", started)

writer.TextureSize = args.texture
say("writing %s at TextureSize %d on %d processes" % (target, args.texture, ranks))
writer.UpdatePipeline()

if args.frames_differ:
    # Every process's error code and written texture size, on the first process.
    local = vtkIntArray()
    local.SetNumberOfComponents(2)
    local.InsertNextTuple2(vtk_writer.GetErrorCode(), len(os.listdir(args.dir)))
    gathered = vtkIntArray()
    controller.AllGather(local, gathered)
    codes = [[int(gathered.GetComponent(r, c)) for c in range(2)] for r in range(ranks)]
    say("frames-differ: [error code, files in the folder] per process %s" % codes)
    if any(code[0] == 0 or code[1] != 0 for code in codes):
        raise AssertionError("frames-differ: a process wrote or reported success")
    say("frames-differ checks passed on %d processes" % ranks)
else:
    say("the write ended")
