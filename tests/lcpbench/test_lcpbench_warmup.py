#!/usr/bin/env python3
"""Fair solver timing: every solver gets the same untimed warm-up before its timed solves, read from the output
(no wall time is asserted).

lcpbench (1 and 2 ranks) and, when given, lcpcompare: /results/<solver> attribute warmup_solves is the same for
every solver and equals -warmup (at most the number of problems; lcpbench counts valid problems only), and the
summary table's warm-up column says the same. Listing the solvers in the reversed order changes no result of
lcpbench (status, iterations, pivots, residual per problem): the order only arranges the timed solves.

Usage: test_lcpbench_warmup.py LCPBENCH [LCPCOMPARE]
"""
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

SOLVERS = ["auto", "bpp", "lemke", "pgs"]


def env():
    return dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                OMPI_MCA_rmaps_base_oversubscribe="1")


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, env=env(), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
    out = p.stdout.decode(errors="replace")
    if p.returncode != 0:
        sys.exit(f"FAIL: exit {p.returncode}: {' '.join(cmd)}\n{out}")
    return out


def table_warmups(out, names):
    """solver -> the last column (warm-up) of its line in the summary table."""
    found = {}
    for line in out.splitlines():
        cells = line.split()
        if (cells and cells[0] in names and len(cells) >= 7 and re.fullmatch(r"\d+", cells[-1])
                and not any("(" in c for c in cells)):
            found[cells[0]] = int(cells[-1])
    return found


def check(failures, what, path, names, expected, out):
    with h5py.File(path, "r") as f:
        got = {s: int(f["results"][s].attrs["warmup_solves"]) for s in names}
    if set(got.values()) != {expected}:
        failures.append(f"{what}: warmup_solves {got}, want {expected} for every solver")
    shown = table_warmups(out, names)
    if shown != {s: expected for s in names}:
        failures.append(f"{what}: the table's warm-up column {shown}, want {expected} for every solver")
    print(f"{what}: every solver {expected} untimed warm-up solve(s)")


def results(path, names):
    with h5py.File(path, "r") as f:
        return {s: {c: f["results"][s][c][...] for c in ("status", "iterations", "pivots", "residual")}
                for s in names}


def main():
    lcpbench = sys.argv[1]
    lcpcompare = sys.argv[2] if len(sys.argv) > 2 else None
    failures = []
    with tempfile.TemporaryDirectory() as d:
        base = ["-family", "random_box", "-n", "6", "-count", "12", "-resume", "0"]
        for np_, warmup, expected in [(1, None, 1), (1, "0", 0), (2, "3", 3), (1, "50", 12)]:
            out_file = f"w{np_}_{warmup}.h5"
            cmd = ["mpiexec", "-n", str(np_), lcpbench, *base, "-solvers", ",".join(SOLVERS), "-output", out_file]
            cmd += ["-warmup", warmup] if warmup is not None else []
            out = run(cmd, d)
            check(failures, f"lcpbench np={np_} -warmup {warmup or '(default)'}", Path(d) / out_file, SOLVERS,
                  expected, out)
        # the reversed list: the same results per problem
        run(["mpiexec", "-n", "1", lcpbench, *base, "-solvers", ",".join(SOLVERS[::-1]), "-output", "rev.h5"], d)
        a, b = results(Path(d) / "w1_None.h5", SOLVERS), results(Path(d) / "rev.h5", SOLVERS)
        for s in SOLVERS:
            for c in a[s]:
                if not np.array_equal(a[s][c], b[s][c]):
                    failures.append(f"lcpbench: {s} {c} differs between -solvers {','.join(SOLVERS)} and reversed")
        print("lcpbench: the reversed -solvers list gives the same status, iterations, pivots and residuals")
        if lcpcompare:
            out = run([lcpcompare, "-n", "6", "-count", "5", "-warmup", "2", "-output", "c.h5"], d)
            with h5py.File(Path(d) / "c.h5", "r") as f:
                names = list(f["results"])
            check(failures, "lcpcompare -warmup 2", Path(d) / "c.h5", names, 2, out)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
