#!/usr/bin/env python3
"""Run a command that must fail cleanly: non-zero exit, no hang, and the expected message exactly once.

Usage: expect_failure.py --expect REGEX [--timeout S] [--count N] -- command args...
Passes when the command exits non-zero within the timeout and REGEX matches exactly N (default 1)
lines of its combined stdout+stderr: one clear message for the whole job, not one per rank.
"""
import argparse
import re
import sys

from command_run import run_command, verdict


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--expect", required=True)
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--count", type=int, default=1)
    ap.add_argument("cmd", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    result = run_command(a.cmd, a.timeout)
    if result is None:
        return 1
    returncode, out = result
    rx = re.compile(a.expect)
    hits = [line for line in out.splitlines() if rx.search(line)]
    failures = []
    if returncode == 0:
        failures.append("command exited 0, expected a non-zero exit")
    if len(hits) != a.count:
        failures.append(f"/{a.expect}/ matched {len(hits)} lines, expected {a.count}")
    return verdict(failures, f"refused (exit {returncode}): {hits[0].strip() if hits else ''}")


if __name__ == "__main__":
    sys.exit(main())
