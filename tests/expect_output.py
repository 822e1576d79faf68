#!/usr/bin/env python3
"""Run a command that must succeed and print what it promises: exit 0, no hang, every --expect regex found in its
output (stdout and stderr together) and no --reject regex. Unlike ctest's PASS_REGULAR_EXPRESSION, a crash or a
non-zero exit after the expected text fails.

Usage: expect_output.py --expect=REGEX [--expect=REGEX ...] [--reject=REGEX ...] [--timeout S] -- command args...
The regexes are Python regexes searched over the whole output with re.DOTALL (`.` spans lines), so
`A.*B` asserts that B comes after A.
"""
import argparse
import re
import sys

from command_run import run_command, verdict


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--expect", action="append", default=[], required=True)
    ap.add_argument("--reject", action="append", default=[])
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("cmd", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    result = run_command(a.cmd, a.timeout)
    if result is None:
        return 1
    returncode, out = result
    failures = [] if returncode == 0 else [f"command exited {returncode}, expected 0"]
    failures += [f"/{rx}/ not found in the output" for rx in a.expect if not re.search(rx, out, re.DOTALL)]
    for rx in a.reject:
        m = re.search(rx, out, re.DOTALL)
        if m:
            failures.append(f"/{rx}/ found in the output: {m.group(0)[:200]!r}")
    return verdict(failures, f"exit 0, {len(a.expect)} expected pattern(s) found, {len(a.reject)} rejected one(s) "
                             "absent")

if __name__ == "__main__":
    sys.exit(main())
