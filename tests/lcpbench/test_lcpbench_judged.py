#!/usr/bin/env python3
"""lcpbench's answers judged independently (tests/lcpbench/lcp_judge.py: numpy, its own readers, no code of
lib/lcp): every solver on the Siconos reference files (../shared/data/lcp: LCP, relay, MLCP), the committed examples
of inputs/lcpbench and 12 box LCPs written here with numpy (positive-definite M, so a unique solution; bounds
[-1, 1], one-sided and infinite, so that lower and upper bounds are active), at 2 ranks with -save_solutions.
For every (problem, solver) that lcpbench reports solved:
  - the residual recomputed from the stored z is within the acceptance rel_tol (1 + |q|_inf) (rel_tol 1e-10);
  - it agrees with the residual lcpbench reports, to 1e-13 (1 + |q|_inf) (measured: at most 1.4e-16; the margin
    is the round-off of w = M z + q, which scales with |M| |z|, not |q|, and with the order of the sums);
  - where the problem has one solution (found by enumerating every index set, n <= 8), z is that solution to
    1e-8 (1 + |z|_inf) (measured: at most 1.7e-10 relative, the Newton solvers' answers within rel_tol);
  - z matches what the data publishes: lcp_4.dat's comment, /z_known of box_3.h5 and mlcp_4_csr.h5, the v and w
    that Siconos' MLCP files deudeu and m2n1 carry (to 1e-4 (1 + |w|): m2n1's file holds 1.3333 for the 4/3 its
    printed w = 5 was computed with, 4.9999 from the file's M), and CPS 2009's solution set z_1 + z_2 = 1 of
    lcp_CPS_1.dat (to 1e-9).
And every problem is solved by at least one solver (the judge's verdict on lcpbench's best answer).
Usage: test_lcpbench_judged.py LCPBENCH SICONOS_DIR INPUTS_DIR
"""
import os
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lcp_judge import brute_force, natural_residual, read_problem, stored_solution  # noqa: E402

SOLVERS = "lemke,keller,cottle_dantzig,murty,bpp,fb_newton,smoothed_newton,pgs,pgs_block"
REL_TOL = 1e-10
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def box_problems(d, count=12, n=6, seed=7):
    """Box LCPs with a unique solution: M = S + K (S symmetric positive definite, K skew) is positive definite,
    hence a P-matrix. Bounds cycle through [-1, 1], [0, 1], [-inf, 1] and [-1, inf]; q in [-6, 6] puts many
    variables at a bound."""
    rng = np.random.default_rng(seed)
    bounds = [(-1.0, 1.0), (0.0, 1.0), (-np.inf, 1.0), (-1.0, np.inf)]
    paths = []
    for k in range(count):
        A = rng.standard_normal((n, n))
        B = rng.standard_normal((n, n))
        M = A @ A.T / n + 0.5 * np.eye(n) + (B - B.T) / 2
        lo, hi = bounds[k % len(bounds)]
        path = os.path.join(d, f"numpy_box_{k:02d}.h5")
        with h5py.File(path, "w") as f:
            f["M"] = M
            f["q"] = rng.uniform(-6, 6, n)
            f["l"] = np.full(n, lo)
            f["u"] = np.full(n, hi)
        paths.append(path)
    return paths


def published(path, p):
    """(what, z -> error, tolerance) of the solution the data gives, or None."""
    name = os.path.basename(path)
    if "z" in p.known:
        z0 = p.known["z"]
        return "/z_known", lambda z: np.max(np.abs(z - z0)), 1e-9 * (1 + np.max(np.abs(z0)))
    if "v" in p.known:
        v0, w0 = p.known["v"], p.known["w"]
        err = lambda z: max(np.max(np.abs(z[p.comp] - v0)), np.max(np.abs((p.M @ z + p.q)[p.comp] - w0)))
        return "Siconos' v and w", err, 1e-4 * (1 + np.max(np.abs(w0)))
    m = re.search(r"Solution z = \(([^)]*)\)", open(path, errors="replace").read()) if path.endswith(".dat") else None
    if m:
        z0 = np.array([float(x) for x in m.group(1).split(",")])
        return "the comment's z", lambda z: np.max(np.abs(z - z0)), 1e-9
    if name == "lcp_CPS_1.dat":
        return "z_1 + z_2 = 1 (CPS 2009)", lambda z: abs(z[0] + z[1] - 1), 1e-9
    return None


def judge(path, k, f, solvers):
    p = read_problem(path)
    qn = 1 + np.max(np.abs(p.q))
    unique = brute_force(p) if p.q.size <= 8 else []
    unique = unique[0] if len(unique) == 1 else None
    pub = published(path, p)
    name = os.path.basename(path)
    solved_by, worst = [], {"agree": 0.0, "unique": 0.0}
    for s in solvers:
        g = f[f"/results/{s}"]
        if int(g["status"][k]) != 0:
            continue
        z = stored_solution(f, s, k, p.q.size)
        r = natural_residual(p, z)
        reported = float(g["residual"][k])
        solved_by.append(s)
        check(r <= REL_TOL * qn, f"{name} {s}: residual from z {r:.2e} <= rel_tol (1 + |q|) = {REL_TOL * qn:.2e}")
        worst["agree"] = max(worst["agree"], abs(r - reported) / qn)
        check(abs(r - reported) <= 1e-13 * qn, f"{name} {s}: lcpbench's residual {reported:.2e} = {r:.2e}")
        if unique is not None:
            e = np.max(np.abs(z - unique)) / (1 + np.max(np.abs(unique)))
            worst["unique"] = max(worst["unique"], e)
            check(e <= 1e-8, f"{name} {s}: z is the unique solution (relative difference {e:.1e})")
        if pub:
            what, err, tol = pub
            check(err(z) <= tol, f"{name} {s}: z matches {what} (difference {err(z):.1e} <= {tol:.1e})")
    check(bool(solved_by), f"{name}: solved by {' '.join(solved_by) or 'none'}")
    return worst


def main(exe, siconos, inputs):
    files = sorted(os.path.join(siconos, f) for f in os.listdir(siconos) if f.endswith(".dat"))
    files += [os.path.join(inputs, f) for f in ("lcp_4.dat", "relay_3.dat", "box_3.h5", "mlcp_4_csr.h5")]
    with tempfile.TemporaryDirectory() as d:
        files += box_problems(d)
        out = os.path.join(d, "judged.h5")
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        cmd = ["mpiexec", "--oversubscribe", "-n", "2", exe, "-family", "file", "-file", ",".join(files),
               "-solvers", SOLVERS, "-strict", "false", "-save_solutions", "-output", out, "-quiet"]
        p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        check(p.returncode == 0, f"lcpbench on {len(files)} files: exit {p.returncode}")
        if p.returncode != 0:
            print(p.stdout[-3000:])
            return 1
        worst = {"agree": 0.0, "unique": 0.0}
        with h5py.File(out, "r") as f:
            for k, path in enumerate(files):
                w = judge(path, k, f, SOLVERS.split(","))
                worst = {key: max(worst[key], w[key]) for key in worst}
    print(f"largest |residual from z - lcpbench's| / (1 + |q|): {worst['agree']:.1e}; largest relative distance "
          f"to the unique solution: {worst['unique']:.1e}")
    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
