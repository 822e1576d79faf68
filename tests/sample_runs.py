#!/usr/bin/env python3
"""Runs every command of the "Sample runs" block at the top of each apps/<app>/main.cpp (MFEM style):
each must exit 0. Commands run in a scratch folder; inputs/ and ../shared/ paths point at the checkout,
`mpiexec -n N` becomes `mpiexec --oversubscribe -n min(N, 2)`.

Usage: sample_runs.py [APP ...]   (default: every app)
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SRC = Path(os.environ.get("SUITE_SOURCE", Path(__file__).resolve().parents[1]))
BIN = Path(os.environ.get("SUITE_BIN", SRC / "build" / "bin"))
DATA = Path(os.environ.get("SUITE_DATA", SRC.parent / "shared" / "data"))


def sample_commands(main_cpp: Path):
    cmds, inside = [], False
    for line in main_cpp.read_text().splitlines():
        if line.startswith("// Sample runs"):
            inside = True
            continue
        if inside:
            if not line.startswith("//   "):
                break
            text = line[5:].split("#")[0].strip()
            if line.startswith("//       ") and cmds:  # continuation of the previous command
                cmds[-1] += " " + text
            elif text:
                cmds.append(text)
    return cmds


def to_argv(cmd: str):
    argv = shlex.split(cmd)
    nranks = 1
    if argv[0] == "mpiexec":
        nranks = min(int(argv[argv.index("-n") + 1]), 2)
        argv = argv[argv.index("-n") + 2:]
    argv[0] = str(BIN / argv[0])
    fixed = []
    for a in argv:
        a = a.replace("../shared/data/", f"{DATA}/")
        a = re.sub(r"(^|,)inputs/", lambda m: m.group(1) + f"{SRC}/inputs/", a)
        fixed.append(a)
    if "-output" in fixed and "/" in fixed[fixed.index("-output") + 1]:
        fixed[fixed.index("-output") + 1] = Path(fixed[fixed.index("-output") + 1]).name
    return ["mpiexec", "--oversubscribe", "-n", str(nranks)] + fixed + ["-quiet"]


def main(apps):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    failed = passed = 0
    for main_cpp in sorted(SRC.glob("apps/*/main.cpp")):
        if apps and main_cpp.parent.name not in apps:
            continue
        # One working directory per app, commands in order: a sample may use what an earlier one wrote
        # (a checkpoint to restart from).
        with tempfile.TemporaryDirectory() as d:
            for cmd in sample_commands(main_cpp):
                argv = to_argv(cmd)
                t0 = time.time()
                p = subprocess.run(argv, cwd=d, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
                ok = p.returncode == 0
                passed += ok
                failed += not ok
                print(f"{'ok  ' if ok else 'FAIL'} {time.time() - t0:6.1f} s  {cmd}")
                if not ok:
                    print(p.stdout[-3000:])
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
