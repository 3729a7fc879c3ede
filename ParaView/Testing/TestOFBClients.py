"""The OFB plugin in ParaView's clients, against pvbatch runs of the same script: a pvpython
client of a pvserver of N MPI processes, and the paraview GUI.

    python3 TestOFBClients.py --client pvpython --ranks N --mpiexec MPIEXEC
        --pvserver PVSERVER --pvpython PVPYTHON --pipeline ofbClientPipeline.py
        --plugin OFB.so --reference DIR --whole-reference DIR --output DIR
        [--compare-python PYTHON] [--vtkofb-build MAIN_BUILD --vtkofb-python-destination DEST]
    python3 TestOFBClients.py --client gui --paraview PARAVIEW --pipeline ... --plugin ...
        --reference DIR --whole-reference DIR --output DIR [...]

pvpython (client-server):
1. Starts `MPIEXEC -np N PVSERVER --server-port=0 --force-offscreen-rendering` (port 0:
   the system chooses a free port, which pvserver prints in its "Accepting connection(s):
   HOST:PORT" line) and waits for that line.
2. Runs `PVPYTHON ofbClientPipeline.py PLUGIN OUTPUT --url cs://localhost:PORT`: the
   client connects, loads the plugin on the server and on the client, builds the pipeline
   on the server, renders remotely (the server's N processes, composited by IceT) and
   locally (the client, from the delivered surface), saves the screenshots, and saves the
   data through the OFB writer (written by the server).
3. Waits for the client and the server to end.

gui: runs `PARAVIEW --dr --plugin-search-paths=PLUGIN_DIR --plugins=OFB
--script=ofbClientPipeline.py --exit` (the pipeline's arguments in OFB_PIPELINE_ARGS): the
GUI loads the plugin at startup, runs the pipeline in its Python shell with its own render
view, and exits.

Whatever still runs after its time (or when this script fails or is stopped) is ended with
its process group and every process below it (SIGTERM, then SIGKILL). This script is the
child subreaper of what it starts, so that processes orphaned below it (MPI ranks, Open
MPI's daemon) stay in its view; what is still below it 10 s after the end is ended, and
the test fails if anything was left. OFBPlugin.Clients.Stop checks this with a client that
hangs (ofbHangingClient.py). Then the results are compared with the pvbatch runs of the same script
(ctest's fixtures: `mpiexec -np N pvbatch` into --reference, one process into
--whole-reference):
- the values computed where the data is and fetched by the client (sample, particle,
  trail, point and cell counts, LIC mean and standard deviation, painted points, the sum
  of the colours, the particles' end points): equal;
- client-server: the remote rendering was remote, the local one local; the GUI: the plugin
  it loaded, its filters in paraview.simple and under Filters > OFB, the five filters
  registered (the Pipeline Browser's list) and "OFB Surface" among the representations;
- client-server: OFB Probe's output rendered by the client (local rendering), its OFB
  packed into the delivered surface (vtkOFBSamplePack), equals the server's picture of the
  same view (its paint and LIC; correlation >= 0.999) and differs from the client's own
  OFB at the mesh's resolution (Use Input OFB off); the delivered surface is larger by at
  least 8 bytes per sample; surfaces delivered with unusable packs (cells outside the
  frame, arrays of wrong lengths, a frame of five values) give the client's error, once
  per kind, and its own OFB built from the surface;
- the screenshots, by vtkOFBImageComparison (the LIC-aware comparison of
  OFB::TestingImage, run in Debian's Python with vtkofb): the one rendered where the data
  is against pvbatch's of N processes, the whole surface of one process (the client's
  local rendering, the GUI's) against pvbatch's of one process;
- the written files, on any number of processes (Save Data offers the OFB writer; on more
  than one the first process writes the gathered mesh): the .obj, .mtl, .png and .gltf
  exist, equal pvbatch's of as many processes byte for byte, the .obj has a face per cell
  of one process's mesh (the one-process pvbatch run's .obj), the .mtl names the .png, the
  .gltf embeds its texture, and no staging folder is left.

`TestOFBClients.py compare IMAGE BASELINE` is the image comparison alone (run by the test
in PYTHON with vtkofb on its path).
"""
import argparse
import glob
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import threading
import time

START_TIMEOUT = 120  # seconds for pvserver to accept connections
EXIT_TIMEOUT = 60  # seconds for the server to end once the client has disconnected
FLOAT_TOLERANCE = 1e-9  # relative, for the values (the same computation in both runs)
END_TOLERANCE = 1e-6  # particle end points (rounded to 6 digits by the pipeline)
OFB_FILTERS = ["OFBSampler", "OFBLIC", "OFBPaintStrokes", "OFBParticles", "OFBProbe"]
WRITTEN = ["ofb-cs-sphere.obj", "ofb-cs-sphere.mtl", "ofb-cs-sphere.png", "ofb-cs-sphere.gltf"]


def compare_images(image_path, baseline_path):
    """The LIC-aware comparison of two PNGs; prints its measures, returns success."""
    import vtkofb
    from vtkmodules.vtkIOImage import vtkPNGReader

    def read(path):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        return reader.GetOutput()

    comparison = vtkofb.vtkOFBImageComparison()
    comparison.SetImage(read(image_path))
    comparison.SetBaseline(read(baseline_path))
    passed = comparison.Compare()
    print("%s against %s: correlation %.5f, low-pass difference %.3f, VTK's error %.4f, "
          "%d mask pixels, %s" % (os.path.basename(image_path), baseline_path,
                                  comparison.GetCorrelation(), comparison.GetLowPassDifference(),
                                  comparison.GetImageDifferenceError(),
                                  comparison.GetNumberOfMaskPixels(),
                                  "passed" if passed else "FAILED " + comparison.GetErrorText()))
    return bool(passed)


if len(sys.argv) == 4 and sys.argv[1] == "compare":
    sys.exit(0 if compare_images(sys.argv[2], sys.argv[3]) else 1)

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--client", choices=["pvpython", "gui"], required=True)
parser.add_argument("--ranks", type=int, default=1, help="pvserver's MPI processes")
parser.add_argument("--mpiexec")
parser.add_argument("--mpiexec-numproc-flag", default="-np")
parser.add_argument("--pvserver")
parser.add_argument("--pvpython")
parser.add_argument("--paraview", help="the paraview GUI")
parser.add_argument("--pipeline", required=True)
parser.add_argument("--plugin", required=True)
parser.add_argument("--reference", required=True)
parser.add_argument("--whole-reference", required=True)
parser.add_argument("--output", required=True)
parser.add_argument("--compare-python", default="/usr/bin/python3")
parser.add_argument("--vtkofb-build", help="the main build, whose vtkofb compares the images")
parser.add_argument("--vtkofb-python-destination", default="lib/python3/dist-packages")
parser.add_argument("--client-timeout", type=float, default=400.0,
                    help="seconds for the client's whole script (default 400)")
args = parser.parse_args()
gui = args.client == "gui"
if gui:
    args.ranks = 1

failures = []


def check(condition, what):
    print("ok:" if condition else "FAILED:", what, flush=True)
    if not condition:
        failures.append(what)


# One connection to the X display for the whole run, so that the display does not reset
# between the processes' windows (as ofbKeepDisplayOpen.py does for a pvbatch script).
import ofbParaViewTesting  # noqa: E402 (beside this script)

ofbParaViewTesting.keep_display_open()


# ctest's timeout or ^C: end the processes started here before leaving.
def _stop(signum, frame):
    raise SystemExit("stopped by signal %d" % signum)


signal.signal(signal.SIGTERM, _stop)
signal.signal(signal.SIGINT, _stop)

# Processes orphaned below this one (an MPI rank whose mpiexec ended first) become its
# children, so that they are found, ended and collected here (Linux's child subreaper).
try:
    import ctypes

    PR_SET_CHILD_SUBREAPER = 36
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
except (OSError, AttributeError):
    pass


def below(pid):
    """The ids of the running processes below process `pid` (zombies are gone)."""
    children = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as stream:
                fields = stream.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if fields[0] != "Z":
            children.setdefault(int(fields[1]), []).append(int(entry))
    found, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def collect_children():
    """Collects the exit status of every ended child (the orphans adopted above)."""
    while True:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            return


class Process:
    """A process in a process group of its own, its output echoed with a prefix."""

    def __init__(self, name, command, watch=None):
        self.name = name
        self.lines = []
        self.matched = threading.Event()
        self.match = None
        self.watch = re.compile(watch) if watch else None
        print("[%s] %s" % (name, " ".join(command)), flush=True)
        self.popen = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                      stdin=subprocess.DEVNULL, start_new_session=True,
                                      text=True, errors="replace")
        self.pgid = self.popen.pid  # start_new_session: the group of the process's own id
        self.known = set()
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        for line in self.popen.stdout:
            line = line.rstrip("\n")
            self.lines.append(line)
            # ParaView's deprecation and replacement warnings are noise here.
            if "WARN|" not in line:
                print("[%s] %s" % (self.name, line), flush=True)
            if self.watch and not self.matched.is_set():
                found = self.watch.search(line)
                if found:
                    self.match = found
                    self.matched.set()
        self.matched.set()

    def wait(self, timeout):
        """The exit status, or None if it still runs after `timeout` seconds."""
        try:
            return self.popen.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            return None

    def descendants(self):
        """The ids of the running processes below this one (mpiexec puts its ranks in
        process groups of their own)."""
        return below(self.popen.pid)

    def alive(self):
        """The process ids left: the group's leader, its group, its descendants."""
        left = set(self.known)
        if self.popen.poll() is None:
            left.add(self.popen.pid)
        try:
            os.killpg(self.pgid, 0)
            left.add(-self.pgid)
        except (ProcessLookupError, PermissionError):
            pass
        for pid in list(left):
            if pid > 0:
                try:
                    with open("/proc/%d/stat" % pid) as stream:
                        if stream.read().rsplit(")", 1)[1].split()[0] == "Z":
                            left.discard(pid)
                except OSError:
                    left.discard(pid)
        return sorted(left)

    def stop(self):
        """Ends the process, its group and every process below it: first SIGTERM to the
        group (mpiexec passes it on to its ranks and collects them), then SIGTERM to what is
        left below it, then SIGKILL to all."""
        self.known = set(self.descendants()) if self.popen.poll() is None else set()
        for sig, group_only, grace in ((signal.SIGTERM, True, 10.0),
                                       (signal.SIGTERM, False, 5.0),
                                       (signal.SIGKILL, False, 5.0)):
            if not self.alive():
                break
            for target in [-self.pgid] + ([] if group_only else sorted(self.known)):
                try:
                    if target < 0:
                        os.killpg(-target, sig)
                    else:
                        os.kill(target, sig)
                except (ProcessLookupError, PermissionError):
                    pass
            deadline = time.monotonic() + grace
            while time.monotonic() < deadline and self.alive():
                self.popen.poll()
                time.sleep(0.1)
        self.popen.poll()
        self.reader.join(timeout=5)


def run_client_server():
    server = Process("pvserver", [args.mpiexec, args.mpiexec_numproc_flag, str(args.ranks),
                                  args.pvserver, "--server-port=0",
                                  "--force-offscreen-rendering"],
                     watch=r"Accepting connection\(s\): (\S+):(\d+)")
    processes.append(server)
    server.matched.wait(timeout=START_TIMEOUT)
    if server.match is None:
        raise AssertionError("pvserver did not accept connections within %d s (exit status %s)"
                             % (START_TIMEOUT, server.popen.poll()))
    port = int(server.match.group(2))
    check(port > 0, "pvserver on %d processes accepts connections on port %d"
          % (args.ranks, port))

    # --no-mpi: a client needs no MPI (with it, Open MPI starts a daemon of its own).
    client = Process("pvpython", [args.pvpython, "--no-mpi", "--force-offscreen-rendering",
                                  args.pipeline,
                                  args.plugin, args.output,
                                  "--url", "cs://localhost:%d" % port])
    processes.append(client)
    status = client.wait(args.client_timeout)
    if status is None:
        raise AssertionError("the client did not finish within %g s" % args.client_timeout)
    check(status == 0, "the client's script ran to its end (exit status %d)" % status)
    status = server.wait(EXIT_TIMEOUT)
    check(status is not None, "pvserver ended when the client disconnected (exit status %s)"
          % status)


def run_gui():
    # The pipeline's arguments (the GUI's --script takes none) and a settings folder of the
    # test's own (--dr reads no user settings; the GUI may still write them when it exits).
    os.environ["OFB_PIPELINE_ARGS"] = " ".join(
        shlex.quote(a) for a in [args.plugin, args.output, "--gui"])
    os.environ["XDG_CONFIG_HOME"] = os.path.join(args.output, "config")
    client = Process("paraview", [args.paraview, "--dr", "--no-mpi",
                                  "--plugin-search-paths=" + os.path.dirname(args.plugin),
                                  "--plugins=OFB", "--script=" + args.pipeline, "--exit"])
    processes.append(client)
    status = client.wait(args.client_timeout)
    if status is None:
        raise AssertionError("the GUI did not finish within %g s" % args.client_timeout)
    check(status == 0, "the GUI ran the script and exited (exit status %d)" % status)
    check(any("ofbClientPipeline done: the paraview GUI" in line for line in client.lines),
          "the GUI's Python ran the pipeline to its end")


shutil.rmtree(args.output, ignore_errors=True)
os.makedirs(args.output)
processes = []
try:
    if gui:
        run_gui()
    else:
        run_client_server()
finally:
    for process in reversed(processes):
        process.stop()
    # What is still below this script (adopted orphans included) after a few seconds to end
    # by itself is left over: ended too.
    deadline = time.monotonic() + 10.0
    while below(os.getpid()) and time.monotonic() < deadline:
        collect_children()
        time.sleep(0.2)
    stray = below(os.getpid())
    stray_names = {}
    for pid in stray:
        try:
            with open("/proc/%d/cmdline" % pid, "rb") as stream:
                stray_names[pid] = stream.read().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            stray_names[pid] = "?"
    for pid in stray:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    time.sleep(0.5 if stray else 0.0)
    collect_children()
    left = {process.name: process.alive() for process in processes if process.alive()}
    check(not left and not stray, "no process of %s left (left: %s, below this script: %s)"
          % (" or ".join(process.name for process in processes), left, stray_names or []))

# No error from the server, the client or the GUI, but the client's for the unusable packs
# of the bad-input case (ofbClientPipeline.BAD_PACKS: one per kind).
BAD_PACKS = ["cells-outside", "frame-of-five", "short-colors", "short-depths"]
BAD_PACK_ERROR = "The OFB delivered with the surface cannot be used"
errors = [line for process in processes for line in process.lines if "ERR|" in line]
pack_errors = [line for line in errors if BAD_PACK_ERROR in line]
check(len(errors) == len(pack_errors), "no error printed: %s"
      % [line for line in errors if BAD_PACK_ERROR not in line])
if not gui:
    check(len(pack_errors) == len(BAD_PACKS), "the client reported each unusable pack once: %s"
          % pack_errors)

# The values: the client's (computed on the server) against pvbatch's.
with open(os.path.join(args.output, "values.json")) as stream:
    values = json.load(stream)
with open(os.path.join(args.reference, "values.json")) as stream:
    reference = json.load(stream)
check(values["ranks"] == args.ranks and reference["ranks"] == args.ranks,
      "the %s and pvbatch ran on %d processes (%d, %d)"
      % ("GUI" if gui else "server", args.ranks, values["ranks"], reference["ranks"]))
if gui:
    check(values.get("gui_plugins") == [os.path.realpath(args.plugin)] or
          values.get("gui_plugins") == [args.plugin],
          "the GUI loaded the plugin at startup: %s" % values.get("gui_plugins"))
    check(values.get("gui_simple_functions") == OFB_FILTERS,
          "the GUI's paraview.simple has the OFB filters: %s" % values.get("gui_simple_functions"))
    check(values.get("gui_menu_categories") == {name: "OFB" for name in OFB_FILTERS},
          "the filters are in the menu Filters > OFB: %s" % values.get("gui_menu_categories"))
    check(values.get("gui_sources") == sorted(name + "1" for name in OFB_FILTERS),
          "the Pipeline Browser lists the filters: %s" % values.get("gui_sources"))
    check("OFB Surface" in values.get("gui_representation_types", []),
          "the GUI offers the OFB Surface representation: %s"
          % values.get("gui_representation_types"))
else:
    check(values.get("remote_render") is True, "the first picture was rendered by the server")
    check(values.get("local_remote_render") is False,
          "the second picture was rendered by the client")
for key, expected in sorted(reference.items()):
    if key in ("remote_render", "local_remote_render", "particle_ends"):
        continue
    got = values.get(key)
    if isinstance(expected, float):
        same = got is not None and abs(got - expected) <= FLOAT_TOLERANCE * max(1.0, abs(expected))
    else:
        same = got == expected
    check(same, "%s: client-server %s, pvbatch %s" % (key, got, expected))
ends, reference_ends = values["particle_ends"], reference["particle_ends"]
check(len(ends) == len(reference_ends) and all(
    abs(a - b) <= END_TOLERANCE for p, q in zip(ends, reference_ends) for a, b in zip(p, q)),
    "particle end points: %d, as pvbatch's %d" % (len(ends), len(reference_ends)))
check(values["samples"] > 0 and values["particles"] > 0 and values["red_points"] > 0 and
      values["lic_std"] > 0.1, "the pipeline made samples, particles, paint and a LIC")

# The pictures, by the LIC-aware comparison in Debian's Python with vtkofb.
compare_environment = dict(os.environ)
compare_environment.pop("PYTHONPATH", None)
if args.vtkofb_build:
    compare_environment["PYTHONPATH"] = os.path.join(args.vtkofb_build,
                                                     args.vtkofb_python_destination)
    libraries = sorted({os.path.dirname(path) for path in glob.glob(
        os.path.join(args.vtkofb_build, "lib*", "**", "libvtkOFBTestingImage*.so*"),
        recursive=True)})
    compare_environment["LD_LIBRARY_PATH"] = os.pathsep.join(
        libraries + [p for p in [os.environ.get("LD_LIBRARY_PATH")] if p])
images = {"ofb-surface.png": os.path.join(args.reference, "ofb-surface.png"),
          "ofb-surface-whole.png" if gui else "ofb-surface-local.png":
          os.path.join(args.whole_reference, "ofb-surface-whole.png")}


def same_picture(image, baseline, correlation=None):
    """Whether the LIC-aware comparison passes (run in Debian's Python with vtkofb), and
    where `correlation` is given, its correlation is at least that."""
    result = subprocess.run([args.compare_python, os.path.abspath(__file__), "compare",
                             image, baseline],
                            env=compare_environment, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=120)
    print(result.stdout.strip(), flush=True)
    measured = re.search(r"correlation (-?[0-9.]+)", result.stdout)
    return result.returncode == 0 and (
        correlation is None or (measured is not None and float(measured.group(1)) >= correlation))


for image, baseline in images.items():
    check(same_picture(os.path.join(args.output, image), baseline),
          "%s equals pvbatch's %s" % (image, os.path.basename(baseline)))
if not gui:
    # OFB Probe's output rendered by the client: its OFB, packed into the delivered surface,
    # as the server showed it, not the client's own OFB at the mesh's resolution.
    output = lambda name: os.path.join(args.output, name)  # noqa: E731
    for name in ["ofb-probe-local.png", "ofb-probe-mesh.png", "ofb-bad-mesh.png"] + [
            "ofb-bad-%s.png" % kind for kind in BAD_PACKS]:
        check(values.get(name + ".remote") is False, "%s was rendered by the client" % name)
    check(same_picture(output("ofb-probe-local.png"), output("ofb-surface.png"), 0.999),
          "the client's picture of the probe equals the server's, correlation >= 0.999 (its "
          "input OFB, paint and LIC, delivered)")
    check(not same_picture(output("ofb-probe-mesh.png"), output("ofb-surface.png")),
          "the probe's picture at the mesh's resolution differs from the server's")
    added = (values["probe_delivered_kib"] - values["mesh_delivered_kib"]) * 1024.0
    check(added >= 8 * values["probe_ofb_samples"],
          "the delivered surface carries the samples: %d KiB, %d KiB without, %.1f bytes for "
          "each of %d samples" % (values["probe_delivered_kib"], values["mesh_delivered_kib"],
                                   added / max(1, values["probe_ofb_samples"]),
                                   values["probe_ofb_samples"]))
    for kind in BAD_PACKS:
        check(same_picture(output("ofb-bad-%s.png" % kind), output("ofb-bad-mesh.png")),
              "unusable packs (%s): the client's own OFB from the surface" % kind)

# The files the server wrote.
staging = [name for name in os.listdir(args.output) if ".partial-" in name]
check(not staging, "no staging folder left: %s" % staging)
check(values["writer"] == "SaveData", "Save Data offers the OFB writer on %d processes (%s)"
      % (args.ranks, values["writer"]))
if values["writer"] == "SaveData":
    for name in WRITTEN:
        path = os.path.join(args.output, name)
        size = os.path.getsize(path) if os.path.exists(path) else -1
        with open(os.path.join(args.reference, name), "rb") as stream:
            expected = stream.read()
        same = size > 0 and open(path, "rb").read() == expected
        check(same, "%s written where the data is: %d bytes, equal to pvbatch's (%d bytes)"
              % (name, size, len(expected)))
    with open(os.path.join(args.output, "ofb-cs-sphere.obj")) as stream:
        faces = sum(1 for line in stream if line.startswith("f "))
    whole_obj = os.path.join(args.whole_reference, "ofb-cs-sphere.obj")
    if os.path.exists(whole_obj):
        with open(whole_obj) as stream:
            cells = sum(1 for line in stream if line.startswith("f "))
    else:
        cells = values["mesh_cells"]
    check(faces == cells and (args.ranks > 1 or faces == values["mesh_cells"]),
          "the .obj has a face per cell of the whole mesh: %d of %d" % (faces, cells))
    with open(os.path.join(args.output, "ofb-cs-sphere.mtl")) as stream:
        check("map_Kd ofb-cs-sphere.png" in stream.read(), "the .mtl names the texture")
    with open(os.path.join(args.output, "ofb-cs-sphere.png"), "rb") as stream:
        check(stream.read(8) == b"\x89PNG\r\n\x1a\n", "the texture is a PNG")
    with open(os.path.join(args.output, "ofb-cs-sphere.gltf")) as stream:
        gltf = json.load(stream)
    check(len(gltf.get("meshes", [])) == 1 and
          any(image.get("uri", "").startswith("data:image/png;base64,") or
              image.get("mimeType") == "image/png" for image in gltf.get("images", [])),
          "the .gltf is complete JSON with a mesh and its texture embedded")

what = "paraview GUI" if gui else "client-server mode on %d processes" % args.ranks
if failures:
    print("%d checks of the %s failed" % (len(failures), what))
    sys.exit(1)
print("all checks of the %s passed" % what)
