#!/usr/bin/env python3
"""femdyn -solver petsc (MPIAIJ on a METIS node partition, KSP): results independent of the rank count.

Usage: test_femdyn_petsc.py FEMDYN

For CG + GAMG (-ksp_rtol 1e-12) and the default (MUMPS Cholesky when PETSc has it):
- static linear cantilever (20x2x2, tip load 1): tip deflection at 1 and 2 ranks agree to <= 1e-11 relative,
  and agree with the serial CHOLMOD solution to <= 1e-11;
- 10 full-Newton StVK Newmark steps: final displacement at 1 and 2 ranks agree to <= 1e-11 relative (max norm)
  and with CHOLMOD to <= 1e-11.
Every bound here is 1e-11 (TOL): measured at most 1.9e-12 (the default solver's static deflection against
CHOLMOD; the others 4e-15 to 5.7e-13); the margin covers CG stopping at -ksp_rtol 1e-12 after another iteration
count when the ranks reduce in another order.
The 2-rank runs must report a distributed matrix (log line "petsc: ... rows on 2 ranks").
"""
import os
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

TOL = 1e-11  # relative agreement of every comparison (docstring: measured at most 1.9e-12)

EXE = sys.argv[1]
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
FAILS = []


def check(cond, msg):
    print(("ok   " if cond else "FAIL ") + msg, flush=True)
    if not cond:
        FAILS.append(msg)


def run(np_, out, *args):
    cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), EXE, *map(str, args), "-output", out]
    p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
    if p.returncode != 0:
        raise AssertionError(f"{' '.join(cmd)} failed:\n{p.stdout}")
    with h5py.File(out, "r") as f:
        return f["final/u"][:], float(f.attrs["tip_deflection"]), p.stdout


def rel(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def main():
    static = ["-static", "-tip_load", 1, "-beam_cells", "20,2,2"]
    dynamic = ["-material", "stvk", "-beam_cells", "8,2,2", "-tip_load", 2, "-dt", 0.02, "-steps", 10,
               "-newton_rtol", 1e-10]
    with tempfile.TemporaryDirectory() as d:
        p = lambda n: os.path.join(d, n)
        ref_s = run(1, p("s_ref.h5"), *static, "-solver", "cholmod")
        ref_d = run(1, p("d_ref.h5"), *dynamic, "-solver", "cholmod")
        for label, ksp in (("cg+gamg", ["-ksp_type", "cg", "-pc_type", "gamg", "-ksp_rtol", 1e-12]),
                           ("default", [])):
            s1 = run(1, p("s1.h5"), *static, "-solver", "petsc", *ksp)
            s2 = run(2, p("s2.h5"), *static, "-solver", "petsc", *ksp)
            check(re.search(r"petsc: \d+ rows on 2 ranks.*distributed assembly", s2[2]) is not None,
                  f"{label}: the 2-rank run distributes the matrix and the element assembly")
            dw = abs(s1[1] - s2[1]) / abs(s1[1])
            print(f"  {label} static tip deflection: np1 {s1[1]:.12f}, np2 {s2[1]:.12f}, cholmod {ref_s[1]:.12f}")
            check(dw <= TOL, f"{label}: static tip deflection 1 vs 2 ranks, relative difference {dw:.2e} <= {TOL}")
            dc = abs(s2[1] - ref_s[1]) / abs(ref_s[1])
            check(dc <= TOL, f"{label}: static tip deflection vs CHOLMOD, relative difference {dc:.2e} <= {TOL}")
            d1 = run(1, p("d1.h5"), *dynamic, "-solver", "petsc", *ksp)
            d2 = run(2, p("d2.h5"), *dynamic, "-solver", "petsc", *ksp)
            r12, rc = rel(d2[0], d1[0]), rel(d2[0], ref_d[0])
            check(r12 <= TOL, f"{label}: 10 StVK Newmark steps, final u 1 vs 2 ranks, relative difference {r12:.2e}")
            check(rc <= TOL, f"{label}: 10 StVK Newmark steps vs CHOLMOD, relative difference {rc:.2e}")
        # Distributed assembly with a lumped mass, Rayleigh damping and the haptic probe (penalty added once):
        # final state, energies and probe forces at 1 and 2 ranks.
        extra = ["-mass", "lumped", "-rayleigh_alpha", 0.1, "-probe", "-probe_stiffness", 100, "-solver", "petsc"]
        run(1, p("e1.h5"), *dynamic, *extra)
        run(2, p("e2.h5"), *dynamic, *extra)
        with h5py.File(p("e1.h5"), "r") as f1, h5py.File(p("e2.h5"), "r") as f2:
            for name in ("final/u", "steps/kinetic_energy", "steps/strain_energy", "probe/force_full",
                         "probe/haptic_force"):
                a, b = f1[name][:], f2[name][:]
                r = float(np.max(np.abs(a - b)) / max(np.max(np.abs(a)), 1e-300))
                check(r <= TOL, f"lumped mass + damping + probe: {name} 1 vs 2 ranks, relative difference {r:.2e}")
    print(f"{len(FAILS)} failure(s)")
    return 1 if FAILS else 0


if __name__ == "__main__":
    sys.exit(main())
