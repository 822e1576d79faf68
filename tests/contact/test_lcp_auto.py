"""-lcp_solver auto in the contact app (issue #20; run by ctest: test_lcp_auto.py <contact>): the LCP portfolio
(lib/lcp/portfolio, the entry point of lcpbench -solvers auto) picks the solver of each dense contact problem.

- incline (30 degrees, mu 0.3, 100 steps): auto gives the positions of the default bpp to 1e-8 m (both
  accepted at lcp_tol 1e-8), and every step records the solver that succeeded (/steps/solver, a name of lib/lcp's
  registry);
- a pyramid of base 3 on the dense path (-contact_dense_max_rows 1000) stays at rest: drift <= 1e-6 m in 1 s.
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
TMP = Path(tempfile.mkdtemp(prefix="contact_auto_"))
REGISTRY = {"lemke", "keller", "cottle_dantzig", "murty", "bpp", "pgs", "pgs_block", "fb_newton",
            "smoothed_newton", "petsc_ssls", "petsc_rsls", "lemke_rf"}
failures = []


def run(name, *args):
    out = TMP / f"{name}.h5"
    cmd = [APP, *map(str, args), "-output", str(out), "-quiet"]
    p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        raise SystemExit(f"FAILED: {' '.join(cmd)}\n{p.stdout}")
    return h5py.File(out, "r")


def check(cond, what):
    print(("ok    " if cond else "FAIL  ") + what)
    if not cond:
        failures.append(what)


def solvers(f):
    names = f["/steps"].attrs["solver_names"]
    names = (names.decode() if isinstance(names, bytes) else names).split(",")
    idx = f["/steps/solver"][:]
    return names, idx


INCLINE = ["-scene", "incline", "-theta", 30, "-mu", 0.3, "-steps", 100]
ref = run("incline_bpp", *INCLINE)
auto = run("incline_auto", *INCLINE, "-lcp_solver", "auto")
dx = np.abs(auto["/frames/positions"][:] - ref["/frames/positions"][:]).max()
check(dx <= 1e-8, f"incline: auto vs bpp |dx| {dx:.2e} m <= 1e-8")
names, idx = solvers(auto)
check(idx.min() >= 0 and set(names) <= REGISTRY,
      f"incline: every step records the solver auto used ({', '.join(names)})")

pyr = run("pyramid_auto", "-scene", "pyramid", "-pyramid_base", 3, "-steps", 100, "-lcp_solver", "auto",
          "-contact_dense_max_rows", 1000)
p = pyr["/frames/positions"][:]
drift = np.abs(p[-1] - p[0]).max()
names, idx = solvers(pyr)
check(drift <= 1e-6 and idx.min() >= 0, f"pyramid 3 (dense), auto: drift {drift:.2e} m <= 1e-6, solvers "
      f"{', '.join(f'{n} {int((idx == k).sum())}' for k, n in enumerate(names))}")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all contact lcp auto checks passed")
