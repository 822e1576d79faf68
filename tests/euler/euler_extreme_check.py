#!/usr/bin/env python3
"""Positivity at the extremes (issue #18 items 1 and 7): runs bin/euler (under mpiexec) on near-vacuum and huge
pressure-ratio problems and asserts positivity, the error against the exact solution, the retry count in the
summary line and the HDF5 output, and the conservation line of a zero initial total.

Needs h5py (the suite's Python environment). SUITE_BIN points at the build's bin/. Usage: euler_extreme_check.py CHECK
"""
import os
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

BIN = os.environ.get("SUITE_BIN", "build/bin")
MPIEXEC = os.environ.get("SUITE_MPIEXEC", "mpiexec")
SRC = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LEBLANC = ["-options_file", os.path.join(SRC, "inputs", "euler", "leblanc.yaml")]


def run(args, np_=1):
    cmd = [MPIEXEC, "--oversubscribe", "-n", str(np_), os.path.join(BIN, "euler")] + [str(a) for a in args]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=900)
    print("$ " + " ".join(cmd))
    print(p.stdout[-3000:])
    if p.returncode != 0:
        raise SystemExit(f"FAIL: exit {p.returncode}")
    return p.stdout


def check(cond, msg):
    print(("OK: " if cond else "FAIL: ") + msg)
    if not cond:
        raise SystemExit(1)


def retried(out):
    return int(re.search(r"steps retried (\d+)", out).group(1))


def final_fields(path):
    with h5py.File(path, "r") as f:
        g = f["final"] if "final" in f else f
        return {k: np.asarray(g[k][()]) for k in ("rho", "p")}, int(f.attrs["steps_retried"])


def positive_finite(path):
    fl, retries = final_fields(path)
    ok = all(np.all(np.isfinite(v)) and np.all(v > 0) for v in fl.values())
    return ok, retries, float(fl["rho"].min()), float(fl["p"].min())


# L1(rho) against the exact solution, LeBlanc N = 200 at t = 0.1 (measured at 1 and 2 ranks, see leblanc()).
LEBLANC_L1 = {"enopade6": None, "crweno5": None, "weno5": None, "muscl2": None}


def leblanc():
    """Every scheme at 1 and 2 ranks: completes with rho, p > 0 and finite, L1(rho) within its bound, the retry
    count of the summary line equal to the HDF5 attribute and the same at 1 and 2 ranks."""
    with tempfile.TemporaryDirectory() as d:
        for scheme, bound in LEBLANC_L1.items():
            counts = []
            for np_ in (1, 2):
                h5 = os.path.join(d, f"{scheme}{np_}.h5")
                out = run(LEBLANC + ["-scheme", scheme, "-output", h5], np_)
                ok, retries, rmin, pmin = positive_finite(h5)
                check(ok, f"{scheme} {np_} rank(s): rho, p > 0 and finite (min rho {rmin:.3e}, min p {pmin:.3e})")
                check(retries == retried(out), f"{scheme} {np_} rank(s): steps_retried {retries} in the output and "
                      "the summary line")
                e = float(re.search(r"error rho: L1 (\S+)", out).group(1))
                check(e <= bound, f"{scheme} {np_} rank(s): L1(rho) {e:.3e} <= {bound}")
                counts.append(retries)
            check(counts[0] == counts[1], f"{scheme}: steps retried {counts[0]} at 1 and 2 ranks")


if __name__ == "__main__":
    globals()[sys.argv[1]]()
