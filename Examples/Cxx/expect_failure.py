#!/usr/bin/env python3
"""Run a command that must fail cleanly: a non-zero exit status (not a crash by a signal),
its output matching a regular expression, within a time limit.

Usage: expect_failure.py [--file-size-limit BYTES] REGEX SECONDS COMMAND [ARG...]

--file-size-limit runs the command as on a full disk, without root: RLIMIT_FSIZE at BYTES
with SIGXFSZ ignored, so that a write past it fails with EFBIG ("File too large").
"""
import re
import resource
import signal
import subprocess
import sys
import time


def main():
    args = sys.argv[1:]
    limit = None
    if args[0] == "--file-size-limit":
        limit = int(args[1])
        args = args[2:]
    pattern, seconds, command = args[0], float(args[1]), args[2:]

    def prepare():
        if limit is not None:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    start = time.monotonic()
    try:
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             timeout=max(seconds, 1.0) * 4, preexec_fn=prepare)
    except subprocess.TimeoutExpired:
        print("FAIL: still running after %.1f s" % (max(seconds, 1.0) * 4))
        return 1
    elapsed = time.monotonic() - start
    output = run.stdout.decode(errors="replace")
    sys.stdout.write(output)
    problems = []
    if run.returncode == 0:
        problems.append("exit status 0")
    elif run.returncode < 0:
        problems.append("killed by signal %d (a crash)" % -run.returncode)
    if not re.search(pattern, output):
        problems.append("no output matching '%s'" % pattern)
    if elapsed > seconds:
        problems.append("took %.2f s, over %.2f s" % (elapsed, seconds))
    if problems:
        print("FAIL: " + "; ".join(problems))
        return 1
    print("check passed: exit status %d in %.2f s" % (run.returncode, elapsed))
    return 0


if __name__ == "__main__":
    sys.exit(main())
