#!/usr/bin/env python3
"""lcpbench regression: runs the executable and asserts numbers from its HDF5 output.

- Batch results identical at 1 and 2 ranks (every dataset except the wall times).
- Murty's example n = 8: Lemke takes exactly 2^8 - 1 = 255 pivots; all solvers solve it.
- The Siconos reference files (../shared/data/lcp) are solved by fb_newton: the residual recomputed from its stored z
  by the independent judge (lcp_judge.py) <= 1e-10 (1 + |q|).
- A batch with one good and one malformed file exits non-zero and keeps the good problem's results.
Usage: test_lcpbench.py LCPBENCH SICONOS_DIR TEST_DIR
"""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lcp_judge import natural_residual, read_problem, stored_solution  # noqa: E402

STATUS_SOLVED, STATUS_INVALID = 0, 6


def run(exe, *args, np_=1, check=True):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), exe, *map(str, args), "-quiet"]
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if check and p.returncode != 0:
        raise AssertionError(f"{' '.join(cmd)} failed:\n{p.stdout}")
    return p


def datasets(path):
    """{dataset path: list of numbers} of every dataset in the file."""
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.__setitem__("/" + n, o[...].ravel().tolist())
                     if isinstance(o, h5py.Dataset) else None)
    return out


def main(exe, siconos, testdir):
    fails = []

    def check(cond, msg):
        print(("ok   " if cond else "FAIL ") + msg)
        if not cond:
            fails.append(msg)

    solvers = "lemke,keller,cottle_dantzig,murty,bpp,fb_newton,smoothed_newton,pgs,pgs_block"
    with tempfile.TemporaryDirectory() as d:
        p = lambda name: os.path.join(d, name)
        # 1 vs 2 ranks
        args = ["-family", "random_box", "-n", 20, "-count", 40, "-cond", 1e3, "-qrange", 10, "-solvers", solvers,
                "-chunk", 3]
        run(exe, *args, "-output", p("np1.h5"), np_=1)
        run(exe, *args, "-output", p("np2.h5"), np_=2)
        a, b = datasets(p("np1.h5")), datasets(p("np2.h5"))
        keys = sorted(k for k in a if not k.endswith("time"))  # wall and CPU times differ run to run
        check(set(a) == set(b), "same datasets at 1 and 2 ranks")
        diff = [k for k in keys if a[k] != b.get(k)]
        check(not diff, f"{len(keys)} datasets (all but time, cpu_time) identical at 1 and 2 ranks {diff[:3]}")
        for s in ("lemke", "keller", "bpp", "fb_newton"):
            st = a[f"/results/{s}/status"]
            check(len(st) == 40 and all(v == STATUS_SOLVED for v in st), f"{s}: 40/40 random box problems solved")
        # Murty's example
        run(exe, "-family", "murty", "-n", 8, "-count", 1, "-solvers", "lemke,keller,bpp,murty,fb_newton",
            "-output", p("murty.h5"))
        m = datasets(p("murty.h5"))
        check(m["/results/lemke/pivots"] == [255], f"Lemke pivots on Murty n=8: {m['/results/lemke/pivots']} == 255")
        for s in ("lemke", "keller", "bpp", "murty", "fb_newton"):
            check(m[f"/results/{s}/status"] == [STATUS_SOLVED], f"{s} solves Murty's example")
        # Siconos reference files
        files = sorted(f for f in os.listdir(siconos) if f.endswith(".dat"))
        paths = ",".join(os.path.join(siconos, f) for f in files)
        run(exe, "-family", "file", "-file", paths, "-solvers", solvers, "-strict", "false", "-save_solutions",
            "-output", p("sic.h5"), np_=2)
        s = datasets(p("sic.h5"))
        with h5py.File(p("sic.h5"), "r") as sic:
            for k, f in enumerate(files):
                solved_by = [sv for sv in solvers.split(",") if s[f"/results/{sv}/status"][k] == STATUS_SOLVED]
                # the independent judge (lcp_judge.py), from the stored z
                prob = read_problem(os.path.join(siconos, f))
                r = natural_residual(prob, stored_solution(sic, "fb_newton", k, prob.q.size))
                tol = 1e-10 * (1 + np.max(np.abs(prob.q)))
                check(s["/results/fb_newton/status"][k] == STATUS_SOLVED and r <= tol,
                      f"{f}: fb_newton residual from its z {r:.2e} <= 1e-10 (1 + |q|); solved by {' '.join(solved_by)}")
        # mixed good and bad input: non-zero exit, results kept
        pr = run(exe, "-family", "file", "-file", os.path.join(siconos, "lcp_deudeu.dat") + "," +
                 os.path.join(testdir, "lcp_nonsquare.dat"), "-solvers", "lemke,bpp", "-output", p("mixed.h5"),
                 check=False)
        check(pr.returncode != 0, "mixed good/bad batch exits non-zero")
        check(os.path.exists(p("mixed.h5")), "mixed batch still wrote its results")
        if os.path.exists(p("mixed.h5")):
            x = datasets(p("mixed.h5"))
            check(x["/results/lemke/status"] == [STATUS_SOLVED, STATUS_INVALID],
                  f"statuses of the mixed batch {x['/results/lemke/status']} == [0, 6]")
    print(f"{len(fails)} failure(s)")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
