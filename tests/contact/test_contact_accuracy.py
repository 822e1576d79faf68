"""-contact_accuracy on the contact app's HDF5 output (run by ctest: test_contact_accuracy.py <contact>).

- every mode completes a pyramid of base 4 (10 boxes) and records per step the residual (complementarity
  error), cone violation, penetration, factorisations and whether the sweeps ended at the budget;
- a budget of one sweep per step never stops the run (fast: the step goes on with its error recorded), while
  the same budget in exact mode (-lcp_max_iterations 1, pgs, no fallback) does stop it;
- exact on the sparse path (-contact_dense_max_rows 0) keeps the pyramid at rest to 1e-6 m, like the dense path;
- fast and the sparse exact path give bitwise identical results at 1 and 2 ranks.
"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

APP = sys.argv[1]
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
TMP = Path(tempfile.mkdtemp(prefix="contact_accuracy_"))
PYRAMID = ["-scene", "pyramid", "-pyramid_base", 4, "-steps", 100]
failures = []


def run(name, *args, np_=1, ok=True):
    out = TMP / f"{name}.h5"
    cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), APP, *map(str, args), "-output", str(out), "-quiet"]
    p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if ok and p.returncode != 0:
        raise SystemExit(f"FAILED: {' '.join(cmd)}\n{p.stdout}")
    return h5py.File(out, "r") if p.returncode == 0 else p


def check(cond, what):
    print(("ok    " if cond else "FAIL  ") + what)
    if not cond:
        failures.append(what)


def drift(f):
    p = f["/frames/positions"][:]
    return np.abs(p[-1] - p[0]).max()


# measured with the block sweeps (block_pgs.hpp): fast 5.4e-5, balanced 6.1e-7, exact 3.2e-8
for mode, bound in (("fast", 2e-4), ("balanced", 1e-5), ("exact", 1e-6)):
    f = run(f"pyr_{mode}", *PYRAMID, "-contact_accuracy", mode, "-contact_dense_max_rows", 0)
    s = f["/steps"]
    done = f.attrs["status"] in ("completed", b"completed") and len(s["residual"]) == 100
    fields = all(k in s for k in ("residual", "cone_violation", "penetration", "factorizations", "budget_stop"))
    finite = all(np.all(np.isfinite(s[k][:])) for k in ("residual", "cone_violation", "penetration"))
    check(done and fields and finite, f"pyramid 4 ({mode}): 100 steps, errors recorded per step")
    d = drift(f)
    check(d <= bound, f"pyramid 4 ({mode}): drift {d:.2e} m in 1 s <= {bound:g}; max residual "
          f"{s['residual'][:].max():.2e}, max penetration {s['penetration'][:].max():.2e} m, "
          f"{int(s['factorizations'][:].sum())} factorisations, {int(s['budget_stop'][:].sum())} budget stops")

f = run("pyr_fast_1", *PYRAMID, "-contact_accuracy", "fast", "-contact_sweeps", 1)
check(f.attrs["status"] in ("completed", b"completed") and int(f["/steps/budget_stop"][:].sum()) > 0,
      f"fast, one sweep a step: never stopped ({int(f['/steps/budget_stop'][:].sum())} budget stops of 100)")
p = run("pyr_exact_1", *PYRAMID, "-lcp_solver", "pgs", "-lcp_max_iterations", 1, "-fallback_solvers", "none",
        "-contact_dense_max_rows", 1000000, ok=False)
check(not isinstance(p, h5py.File) and "not solved" in p.stdout, "exact, one pgs iteration, no fallback: stops")

for mode in ("fast", "exact"):
    a = run(f"np1_{mode}", *PYRAMID, "-contact_accuracy", mode, "-contact_dense_max_rows", 0)
    b = run(f"np2_{mode}", *PYRAMID, "-contact_accuracy", mode, "-contact_dense_max_rows", 0, np_=2)
    check(np.array_equal(a["/frames/positions"][:], b["/frames/positions"][:]), f"{mode}: identical at 1 and 2 ranks")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all contact accuracy checks passed")
