"""-lcp_solver auto in the contact app (run by ctest: test_lcp_auto.py <contact>): the LCP portfolio
(lib/lcp/portfolio, the entry point of lcpbench -solvers auto) picks the solver of each dense contact problem.

- incline (30 degrees, mu 0.3, 100 steps): auto gives the positions of the default bpp to 1e-12 m (it
  takes bpp there; measured 0), and every step records the solver that succeeded (/steps/solver, a name of lib/lcp's
  registry);
- a pyramid of base 3 on the dense path (-contact_dense_max_rows 1000) stays at rest: drift <= 1e-7 m in 1 s (measured 2.0e-8).
"""
import sys

import h5py
from contact_harness import Harness
import numpy as np

APP = sys.argv[1]
H = Harness(APP, "contact_auto_")
run, check, TMP = H.run, H.check, H.tmp
REGISTRY = {"lemke", "keller", "cottle_dantzig", "murty", "bpp", "pgs", "pgs_block", "fb_newton",
            "smoothed_newton", "petsc_ssls", "petsc_rsls", "lemke_rf"}




def solvers(f):
    names = f["/steps"].attrs["solver_names"]
    names = (names.decode() if isinstance(names, bytes) else names).split(",")
    idx = f["/steps/solver"][:]
    return names, idx


INCLINE = ["-scene", "incline", "-theta", 30, "-mu", 0.3, "-steps", 100]
ref = run("incline_bpp", *INCLINE)
auto = run("incline_auto", *INCLINE, "-lcp_solver", "auto")
dx = np.abs(auto["/frames/positions"][:] - ref["/frames/positions"][:]).max()
# auto takes bpp on the incline's steps: the same answer (measured |dx| 0)
check(dx <= 1e-12, f"incline: auto vs bpp |dx| {dx:.2e} m <= 1e-12")
names, idx = solvers(auto)
check(idx.min() >= 0 and set(names) <= REGISTRY,
      f"incline: every step records the solver auto used ({', '.join(names)})")

pyr = run("pyramid_auto", "-scene", "pyramid", "-pyramid_base", 3, "-steps", 100, "-lcp_solver", "auto",
          "-contact_dense_max_rows", 1000)
p = pyr["/frames/positions"][:]
drift = np.abs(p[-1] - p[0]).max()
names, idx = solvers(pyr)
# measured drift 2.0e-8 m
check(drift <= 1e-7 and idx.min() >= 0, f"pyramid 3 (dense), auto: drift {drift:.2e} m <= 1e-7, solvers "
      f"{', '.join(f'{n} {int((idx == k).sum())}' for k, n in enumerate(names))}")

H.finish("contact lcp auto")
