#!/usr/bin/env python3
"""Runs the documented commands, so that a documented command that breaks fails the tests.

Two sources (MFEM style):
  - the "Sample runs" block at the top of each apps/<app>/main.cpp: each command must exit 0. Commands run in
    a scratch folder; inputs/ and ../shared/ paths point at the checkout, `mpiexec -n N` becomes
    `mpiexec --oversubscribe -n min(N, 2)`;
  - every fenced block opened with ```sh sample in README.md and docs/*.md (--docs): each block runs as one
    `bash -e -o pipefail` script, the blocks of one page in order in one scratch folder in which build/, inputs/,
    docs/, tests/, scripts/, postprocess/, .venv/ and ../shared/data resolve to the checkout's (symlinks), with
    the project's Python first on PATH and Open MPI allowed to run as root and to oversubscribe. The block must
    exit 0.

Usage: sample_runs.py [APP ...]          main.cpp samples (default: every app)
       sample_runs.py --docs [PAGE ...]  documentation samples (default: README.md and docs/*.md)
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


def doc_blocks(page: Path):
    """(line number, script) of each ```sh sample block of a Markdown page."""
    blocks, cur, start = [], None, 0
    for no, line in enumerate(page.read_text().splitlines(), 1):
        if cur is None and line.strip() == "```sh sample":
            cur, start = [], no
        elif cur is not None and line.strip() == "```":
            blocks.append((start, "\n".join(cur) + "\n"))
            cur = None
        elif cur is not None:
            cur.append(line)
    if cur is not None:
        raise SystemExit(f"{page}:{start}: sample block not closed")
    return blocks


def scratch_checkout(root: Path) -> Path:
    """A folder that looks like the repository root to a documented command (symlinks to the checkout)."""
    repo = root / "repo"
    (repo / "build").mkdir(parents=True)
    (repo / "build" / "bin").symlink_to(BIN)
    for name in ("inputs", "docs", "tests", "scripts", "postprocess", ".venv", "README.md"):
        if (SRC / name).exists():
            (repo / name).symlink_to(SRC / name)
    (root / "shared").symlink_to(DATA.parent)
    return repo


def main_docs(pages):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    venv_bin = SRC / ".venv" / "bin"
    if venv_bin.is_dir():
        env["PATH"] = f"{venv_bin}:{env.get('PATH', '')}"
    paths = [SRC / p for p in pages] if pages else [SRC / "README.md"] + sorted((SRC / "docs").glob("*.md"))
    failed = passed = 0
    for page in paths:
        blocks = doc_blocks(page)
        if not blocks:
            continue
        with tempfile.TemporaryDirectory() as d:
            repo = scratch_checkout(Path(d))
            for line, script in blocks:
                t0 = time.time()
                p = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", script], cwd=repo, env=env,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
                ok = p.returncode == 0
                passed += ok
                failed += not ok
                print(f"{'ok  ' if ok else 'FAIL'} {time.time() - t0:6.1f} s  {page.relative_to(SRC)}:{line}")
                if not ok:
                    print(script)
                    print(p.stdout[-3000:])
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    if sys.argv[1:2] == ["--docs"]:
        sys.exit(main_docs(sys.argv[2:]))
    sys.exit(main(sys.argv[1:]))
