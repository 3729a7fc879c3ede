"""The OFB writer under MPI when a process is killed, or when the processes' OFBs differ.

    python3 TestOFBWriterFaults.py SCENARIO --mpiexec MPIEXEC --pvbatch PVBATCH
        --paraview-python DIR --plugin OFB.so --mesh MESH --output DIR

runs `MPIEXEC -np 2 PVBATCH --symmetric ofbWriterFaultRun.py ...` (the pipeline of
TestOFBWriterDistributed.py with texture coordinates, written to OUTPUT/SCENARIO/export/
writer.obj, .mtl and .png) and acts on it from outside. SCENARIO:

- first-fresh: the first process (the one that writes) is killed (SIGKILL) while it writes
  the files of a TextureSize 2048 export into an empty folder;
- first-existing: the same over a complete export written just before (TextureSize 64);
- other-gather: the other process kills itself once the first has begun its write, before
  it sends its piece: the first is waiting for it in the gather;
- other-stopped: the other process stops itself (SIGSTOP) there instead: mpiexec sees no
  failure and waits; this script's timeout (HANG_TIMEOUT seconds) kills every process of
  mpiexec's session, and nothing is written;
- other-writing: the other process is killed while the first writes over a complete
  export (the first is stopped in its write meanwhile, then continued: mpiexec ends it
  before or after it renamed its files into place);
- frames-differ: the first process samples at another resolution than the other: the
  writer refuses the write.

The write is caught in the middle thus: the writer stages its files in a
folder `.writer.obj.tmp-<host>-<process id>-<n>` beside the targets (vtkOFBStagedFiles) and
renames them into place at the end, after the texture's PNG (about 0.2 s at TextureSize
2048); this script polls the folder every millisecond, stops (SIGSTOP) the process named
by the staging folder once its staged PNG exists, checks that nothing was renamed into
place yet (else the try is repeated, at most three times) and then kills the process.

The checks after a kill: mpiexec ends (within TIMEOUT seconds; else every process of its
session is killed and the test fails) with a failure status, no process of its session is
left, and the export folder holds no file under the targets' names (fresh) or the complete
export of before byte for byte (existing), and nothing else but the killed process's hidden
staging folder (`.writer.obj.tmp-<host>-<its id>-<n>`, never a visible name); in other-writing,
where mpiexec ends the first process, either that or, when the first finished its write
first, the complete new export (the new texture a whole 2048 x 2048 PNG) and no staging
folder. first-fresh then writes again into the same folder (pvbatch on 2 processes, no
kill): the complete export is there and the dead process's staging folder is gone.
frames-differ: the writer's error ("the processes' OFBs have different frames"), the same
failure code on every process, nothing written, and pvbatch ends normally.
"""
import argparse
import ctypes
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

import ofbParaViewTesting

TIMEOUT = 120  # seconds for one mpiexec run
HANG_TIMEOUT = 20  # seconds for the run that hangs (other-stopped)
TRIES = 3  # runs that may miss the write before the test fails
TARGETS = ["writer.obj", "writer.mtl", "writer.png"]
# .writer.obj.tmp-<host>-<process id>-<n>: group 1 the process id.
STAGE = re.compile(r"^\.writer\.obj\.tmp-[A-Za-z0-9_.]+-(\d+)-(\d+)$")

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("scenario", choices=["first-fresh", "first-existing", "other-gather",
                                         "other-stopped", "other-writing", "frames-differ"])
parser.add_argument("--mpiexec", required=True)
parser.add_argument("--pvbatch", required=True)
parser.add_argument("--paraview-python", required=True)
parser.add_argument("--plugin", required=True)
parser.add_argument("--mesh", required=True)
parser.add_argument("--output", required=True)
args = parser.parse_args()

here = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(args.output, args.scenario)
export = os.path.join(out, "export")
control = os.path.join(out, "control")
check, failures = ofbParaViewTesting.collector()

# The ranks orphaned when mpiexec is killed become this process's children (Linux's child
# subreaper), so that they are collected here rather than left as zombies.
try:
    ctypes.CDLL(None, use_errno=True).prctl(36, 1, 0, 0, 0)  # PR_SET_CHILD_SUBREAPER
except (OSError, AttributeError):
    pass


def session(sid):
    """The ids of the live processes of session `sid` (mpiexec's: its ranks keep it, also
    when orphaned; they are in process groups of their own)."""
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open("/proc/%s/stat" % entry) as stream:
                    fields = stream.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[3]) == sid and fields[0] != "Z":
                found.append(int(entry))
    return found


class Run:
    """mpiexec -np 2 pvbatch --symmetric ofbWriterFaultRun.py, in a session of its own."""

    def __init__(self, *options, timeout=TIMEOUT):
        os.makedirs(export, exist_ok=True)
        shutil.rmtree(control, ignore_errors=True)
        os.makedirs(control)
        # ParaView's Python; no display (nothing is rendered); not the main build's libraries.
        env = dict(os.environ, PYTHONPATH=args.paraview_python)
        for name in ("DISPLAY", "LD_LIBRARY_PATH"):
            env.pop(name, None)
        command = [args.mpiexec, "-np", "2", args.pvbatch, "--symmetric",
                   "--force-offscreen-rendering", os.path.join(here, "ofbWriterFaultRun.py"),
                   args.plugin, args.mesh, export, control] + list(options)
        print(" ".join(command), flush=True)
        self.lines = []
        self.popen = subprocess.Popen(command, env=env, stdin=subprocess.DEVNULL,
                                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                      start_new_session=True, text=True, errors="replace")
        self.timeout = timeout
        self.deadline = time.monotonic() + timeout
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        for line in self.popen.stdout:
            self.lines.append(line.rstrip("\n"))
            print("[pvbatch] " + self.lines[-1], flush=True)

    def said(self, text):
        return any(text in line for line in self.lines)

    def wait_for(self, test, what):
        """Polls `test` every millisecond until it gives a value; None when mpiexec ended
        or the time ran out first."""
        while time.monotonic() < self.deadline:
            value = test()
            if value:
                return value
            if self.popen.poll() is not None:
                print("mpiexec ended before %s" % what, flush=True)
                return None
            time.sleep(0.001)
        print("no %s within %d s" % (what, self.timeout), flush=True)
        return None

    def pid(self, rank):
        path = os.path.join(control, "pid-%d" % rank)
        with open(path) as stream:
            return int(stream.read())

    def end(self, hangs=False):
        """mpiexec's exit status once it ended; when it runs past its time, every process
        of its session is killed (SIGKILL) and the status is None. Checks that it ended
        in time and left no process, or with `hangs`, that it ran past its time and that
        killing its session left no process."""
        try:
            status = self.popen.wait(timeout=max(1.0, self.deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            status = None
        left = session(self.popen.pid)
        for pid in left:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        self.popen.wait()
        self.reader.join(timeout=10)
        deadline = time.monotonic() + 10
        while session(self.popen.pid) and time.monotonic() < deadline:
            time.sleep(0.1)
        while True:  # the orphans adopted above
            try:
                if os.waitpid(-1, os.WNOHANG)[0] == 0:
                    break
            except ChildProcessError:
                break
        remaining = session(self.popen.pid)
        if hangs:
            check(status is None, "mpiexec still ran after %d s (status %s)"
                  % (self.timeout, status))
            check(left and not remaining, "its session's processes %s killed, none left: %s"
                  % (left, remaining))
        else:
            check(status is not None, "mpiexec ended within %d s (status %s)"
                  % (self.timeout, status))
            check(not left and not remaining, "no process of mpiexec's session left: %s"
                  % (left or remaining))
        return status


def listing():
    return sorted(os.listdir(export)) if os.path.isdir(export) else []


def snapshot():
    """The targets' bytes (None for a missing one)."""
    found = {}
    for name in TARGETS:
        path = os.path.join(export, name)
        found[name] = open(path, "rb").read() if os.path.exists(path) else None
    return found


def staged_png():
    """(process id, staging folder) once a staging folder holds its writer.png."""
    for name in listing():
        match = STAGE.match(name)
        if match and os.path.exists(os.path.join(export, name, "writer.png")):
            return int(match.group(1)), name
    return None


def stop_in_write(run, before):
    """Stops the writing process once its staged PNG exists; True when it was stopped in
    its write (the staging folder still there, the targets still `before`)."""
    found = run.wait_for(staged_png, "a staged writer.png")
    if not found:
        return False
    pid, stage = found
    os.kill(pid, signal.SIGSTOP)
    staged = os.path.join(export, stage)
    inside = sorted(os.listdir(staged)) if os.path.isdir(staged) else None
    caught = inside is not None and snapshot() == before
    print("process %d stopped: its staging folder %s holds %s; the targets are %s" % (
        pid, stage, inside and ["%s (%d bytes)" % (n, os.path.getsize(os.path.join(staged, n)))
                                for n in inside],
        "untouched" if snapshot() == before else "changed"), flush=True)
    check(pid == run.pid(0), "the staging folder is the first process's (%d)" % run.pid(0))
    return caught


def check_targets(before):
    """The targets after a kill: as `before` (None: no file)."""
    after = snapshot()
    for name in TARGETS:
        if before[name] is None:
            check(after[name] is None, "no %s" % name)
        else:
            check(after[name] == before[name],
                  "%s: the complete export of before, byte for byte (%d bytes)"
                  % (name, len(before[name])))


def check_stages(killed):
    """Nothing in the export folder but the targets and staging folders, hidden, of the
    processes in `killed`; the staging folders."""
    others = [name for name in listing() if name not in TARGETS]
    stages = [name for name in others if STAGE.match(name)]
    check(others == stages, "nothing else in the folder but staging folders: %s" % others)
    check(all(name.startswith(".") and int(STAGE.match(name).group(1)) in killed
              for name in stages),
          "the staging folders left are hidden and the killed process's %s: %s"
          % (killed, stages))
    return stages


def kill_first(existing):
    """first-fresh, first-existing: the first process killed in its write."""
    for attempt in range(1, TRIES + 1):
        shutil.rmtree(export, ignore_errors=True)
        run = Run("--texture", "2048", *(["--existing"] if existing else []))
        before = dict.fromkeys(TARGETS)
        if existing:
            if run.wait_for(lambda: run.said("complete export written"), "the export"):
                before = snapshot()
            check(all(before.values()), "a complete export before: %s" % {
                name: len(data) if data else None for name, data in before.items()})
        caught = stop_in_write(run, before)
        pid = run.pid(0) if os.path.exists(os.path.join(control, "pid-0")) else None
        if pid:
            os.kill(pid, signal.SIGKILL)
            print("killed the first process (%d)" % pid, flush=True)
        status = run.end()
        if caught:
            break
        print("try %d: the write was not caught in the middle; again" % attempt, flush=True)
    check(caught, "the first process was stopped and killed in its write (try %d)" % attempt)
    check(status not in (0, None), "mpiexec reports the failure (status %s)" % status)
    check(not run.said("the write ended"), "no process ended its write")
    check_targets(before)
    stages = check_stages([pid])
    check(len(stages) == 1, "one staging folder left: %s" % stages)
    if not existing:
        # The next write into the folder removes the dead process's staging folder.
        again = Run("--texture", "64")
        status = again.end()
        check(status == 0 and again.said("the write ended"), "a new write (status %s)" % status)
        left = listing()
        check(left == sorted(TARGETS),
              "the new write's complete export and nothing else: %s" % left)


def other_gather():
    """The other process killed before it sends its piece."""
    shutil.rmtree(export, ignore_errors=True)
    run = Run("--texture", "64", "--other-at-gather", "kill")
    status = run.end()
    check(status not in (0, None), "mpiexec reports the failure (status %s)" % status)
    check(run.said("rank 0: the write starts") and run.said("rank 1: killing itself"),
          "the first process began its write, the other killed itself before sending")
    check(not run.said("the write ended"), "no process ended its write")
    check(listing() == [], "nothing in the export folder: %s" % listing())


def other_stopped():
    """The other process stopped (not dead) before it sends its piece: mpiexec cannot see
    it, so the run hangs; after HANG_TIMEOUT seconds this script kills mpiexec's session."""
    shutil.rmtree(export, ignore_errors=True)
    run = Run("--texture", "64", "--other-at-gather", "stop", timeout=HANG_TIMEOUT)
    run.end(hangs=True)
    check(run.said("rank 0: the write starts") and run.said("rank 1: stopping"),
          "the first process began its write, the other stopped before sending")
    check(not run.said("the write ended"), "no process ended its write")
    check(listing() == [], "nothing in the export folder: %s" % listing())


def complete_png(data, size):
    """Whether `data` is a whole PNG of `size` x `size` pixels (its header, its end chunk)."""
    return (data is not None and data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR"
            and int.from_bytes(data[16:20], "big") == size
            and int.from_bytes(data[20:24], "big") == size and data[-8:-4] == b"IEND")


def other_writing():
    """The other process killed while the first writes over a complete export. The first
    is stopped in its write when the other is killed, then continued: mpiexec ends it,
    before or after it has renamed its files into place (Open MPI continues a stopped
    process and ends it after a delay of its own), so the folder holds either the export
    of before or the complete new one, never a part."""
    for attempt in range(1, TRIES + 1):
        shutil.rmtree(export, ignore_errors=True)
        run = Run("--texture", "2048", "--existing")
        before = dict.fromkeys(TARGETS)
        if run.wait_for(lambda: run.said("complete export written"), "the export"):
            before = snapshot()
        check(all(before.values()), "a complete export before")
        caught = stop_in_write(run, before)
        other = run.pid(1) if os.path.exists(os.path.join(control, "pid-1")) else None
        if other:
            os.kill(other, signal.SIGKILL)
            print("killed the other process (%d) while the first is in its write" % other,
                  flush=True)
        first = run.pid(0) if os.path.exists(os.path.join(control, "pid-0")) else None
        if first:
            os.kill(first, signal.SIGCONT)
        status = run.end()
        if caught:
            break
        print("try %d: the write was not caught in the middle; again" % attempt, flush=True)
    check(caught, "the other process was killed while the first was in its write (try %d)"
          % attempt)
    check(status not in (0, None), "mpiexec reports the failure (status %s)" % status)
    after = snapshot()
    # The .obj and .mtl do not depend on TextureSize: both exports have the same.
    for name in ("writer.obj", "writer.mtl"):
        check(after[name] == before[name], "%s: complete, byte for byte the export's (%d bytes)"
              % (name, len(before[name] or b"")))
    old = after["writer.png"] == before["writer.png"]
    new = complete_png(after["writer.png"], 2048)
    check(old or new, "writer.png: %s" % ("the export of before, byte for byte" if old else
                                          "the complete new texture (2048 x 2048)" if new else
                                          "NEITHER the old nor a complete new texture"))
    print("the first process was ended %s" % ("in its write" if old else "after its write"),
          flush=True)
    stages = check_stages([first])
    check(len(stages) == (1 if old else 0), "%s staging folder left: %s"
          % ("one (the write did not finish)" if old else "no (the write finished)", stages))


def frames_differ():
    shutil.rmtree(export, ignore_errors=True)
    run = Run("--frames-differ")
    status = run.end()
    check(status == 0, "pvbatch ends normally (status %s)" % status)
    check(run.said("Cannot write '%s': the processes' OFBs have different frames"
                   % os.path.join(export, "writer.obj")), "the writer's error names the cause")
    check(run.said("frames-differ checks passed on 2 processes"),
          "every process has the writer's failure code and nothing was written")
    check(listing() == [], "nothing in the export folder: %s" % listing())


{"first-fresh": lambda: kill_first(False), "first-existing": lambda: kill_first(True),
 "other-gather": other_gather, "other-stopped": other_stopped,
 "other-writing": other_writing,
 "frames-differ": frames_differ}[args.scenario]()
if failures:
    sys.exit("%d check(s) failed in %s" % (len(failures), args.scenario))
print("all writer fault checks passed: %s" % args.scenario)
