#!/usr/bin/env python3
"""Run a command that must fail cleanly: non-zero exit, no hang, and the expected message exactly once.

Usage: expect_failure.py --expect REGEX [--timeout S] [--count N] -- command args...
Passes when the command exits non-zero within the timeout and REGEX matches exactly N (default 1)
lines of its combined stdout+stderr: one clear message for the whole job, not one per rank.
"""
import argparse
import os
import re
import subprocess
import sys


# When a rank exits non-zero, mpiexec ends the job and waits odls_base_sigkill_timeout (1 s) before killing what is
# left, twice: 2 s of every refused run (also `mpiexec -n 2 sh -c 'exit 1'`). The message is printed before any
# rank exits (the ranks pass MPI_Finalize together), so 0 loses nothing here; tests that signal mpiexec keep the
# default.
ENV = dict(os.environ, OMPI_MCA_odls_base_sigkill_timeout="0")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--expect", required=True)
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--count", type=int, default=1)
    ap.add_argument("cmd", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    cmd = a.cmd[1:] if a.cmd and a.cmd[0] == "--" else a.cmd
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=a.timeout, env=ENV)
    except subprocess.TimeoutExpired as e:
        print(f"FAIL: command hung (> {a.timeout} s): {' '.join(cmd)}")
        print((e.stdout or b"").decode(errors="replace"))
        return 1
    out = p.stdout.decode(errors="replace")
    print(out)
    rx = re.compile(a.expect)
    hits = [line for line in out.splitlines() if rx.search(line)]
    ok = True
    if p.returncode == 0:
        print("FAIL: command exited 0, expected a non-zero exit")
        ok = False
    if len(hits) != a.count:
        print(f"FAIL: /{a.expect}/ matched {len(hits)} lines, expected {a.count}")
        ok = False
    if ok:
        print(f"OK: refused (exit {p.returncode}): {hits[0].strip() if hits else ''}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
