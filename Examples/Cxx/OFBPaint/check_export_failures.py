#!/usr/bin/env python3
"""OFBPaint's exports never leave a broken or half-written export behind.

Usage: check_export_failures.py OFBPaint STROKES WORKDIR

For each export format (.obj with its .mtl and texture, .gltf, .ply, .vtp):
1. a first export succeeds (the "previous export");
2. an export on a full disk (simulated without root: RLIMIT_FSIZE, with SIGXFSZ ignored,
   so that a write past the limit fails with EFBIG as it would with ENOSPC) must exit
   non-zero and name the cause, leave the previous export byte-identical, and leave no
   staging directory or temporary file behind;
3. an export whose texture or target is a directory must fail with a message.
(The OBJ's full disk is tried twice: at 20 kB its texture PNG, which the application
writes, fails; at 1 MB the .obj, which VTK's OBJ writer writes without checking, fails.)
Then an export killed with SIGKILL mid-export (three times: when its staging directory
appears, once its texture is staged, while the OBJ writer writes) must leave the previous
export byte-identical; the next export removes the killed ones' staging directories.
"""
import os
import resource
import signal
import subprocess
import sys
import time

FAILURES = []


def check(condition, text):
    if not condition:
        FAILURES.append(text)
        print("FAIL: " + text)


def run(command, limit=None):
    def prepare():
        if limit is not None:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    return subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          preexec_fn=prepare, timeout=300)


def snapshot(directory):
    files = {}
    for name in sorted(os.listdir(directory)):
        path = os.path.join(directory, name)
        files[name] = open(path, "rb").read() if os.path.isfile(path) else "<dir>"
    return files


def main():
    ofbpaint, strokes, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    base = [ofbpaint, "--resolution", "128", "--width", "64", "--height", "64",
            "--strokes", strokes, "--image", os.path.join(work, "view.png")]
    for ext, limit in (("obj", 20000), ("obj", 1000000), ("gltf", 20000), ("ply", 20000),
                       ("vtp", 20000)):
        directory = os.path.join(work, ext)
        os.makedirs(directory, exist_ok=True)
        for name in os.listdir(directory):
            path = os.path.join(directory, name)
            if os.path.isfile(path):
                os.remove(path)
        target = os.path.join(directory, "painted." + ext)
        first = run(base + ["--export", target, "--texture", "512"])
        check(first.returncode == 0, ext + ": the first export failed:\n" + first.stdout.decode())
        before = snapshot(directory)
        full = run(base + ["--export", target, "--texture", "1024"], limit=limit)
        text = full.stdout.decode()
        check(full.returncode != 0, ext + ": an export on a full disk exited 0:\n" + text)
        check("File too large" in text or "No space left" in text,
              ext + ": the full disk's cause is not named:\n" + text)
        check("Ran out of disk space" not in text, ext + ": VTK's wrong cause:\n" + text)
        check(snapshot(directory) == before,
              ext + ": the previous export changed, or files were left behind: " +
              str(sorted(snapshot(directory))))
        print(ext + ": full disk refused: " + text.strip().splitlines()[-1])
    # A directory where the texture or the export goes.
    directory = os.path.join(work, "obj")
    os.makedirs(os.path.join(directory, "blocked.png"), exist_ok=True)
    blocked = run(base + ["--export", os.path.join(directory, "blocked.obj")])
    check(blocked.returncode != 0 and "blocked.png': it is a directory" in blocked.stdout.decode(),
          "a directory in the texture's place: " + blocked.stdout.decode())
    os.makedirs(os.path.join(work, "ply", "dir.ply"), exist_ok=True)
    blocked = run(base + ["--export", os.path.join(work, "ply", "dir.ply")])
    check(blocked.returncode != 0 and "it is a directory" in blocked.stdout.decode(),
          "an export onto a directory: " + blocked.stdout.decode())
    # kill -9 mid-export, at three moments found by watching the staging directory (so the
    # kill lands inside the export every time): when it appears, when the texture is
    # staged, and while the OBJ writer writes the staged .obj.
    directory = os.path.join(work, "kill")
    os.makedirs(directory, exist_ok=True)
    target = os.path.join(directory, "painted.obj")
    first = run(base + ["--export", target, "--texture", "512"])
    check(first.returncode == 0, "the export before the kills failed: " + first.stdout.decode())
    before = snapshot(directory)
    for moment in ("staging directory", "painted.png", "painted.obj"):
        process = subprocess.Popen(base + ["--export", target, "--texture", "1024"],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        killed = False
        while process.poll() is None and not killed:
            stages = [n for n in os.listdir(directory) if ".tmp-" in n]
            staged = os.path.join(directory, stages[0], moment) if stages else None
            killed = bool(stages) and (moment == "staging directory" or (
                os.path.exists(staged) and os.path.getsize(staged) > 0))
            if killed:
                process.send_signal(signal.SIGKILL)
            else:
                time.sleep(0.001)
        process.wait()
        check(killed, "the export finished before the kill at its " + moment)
        after = {k: v for k, v in snapshot(directory).items() if ".tmp-" not in k}
        check(after == before, "killed at its %s: the previous export changed" % moment)
        print("killed at its %s: previous export intact" % moment)
    final = run(base + ["--export", target, "--texture", "512"])
    check(final.returncode == 0, "the export after the kills failed")
    check(not [n for n in os.listdir(directory) if ".tmp-" in n],
          "staging directories left after the kills: " + str(os.listdir(directory)))
    if FAILURES:
        print("%d checks failed" % len(FAILURES))
        return 1
    print("check passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
