#!/usr/bin/env python3
"""Regression checks of the 2D/3D Euler app (euler -dim 2|3): runs bin/euler (under mpiexec), reads its HDF5
output and asserts the numbers against exact solutions, the 1D app, other rank counts and invariants.

Needs numpy and h5py (the suite's Python environment). Usage: euler_nd_check.py CHECK
"""
import math
import os
import re
import sys
import tempfile

import h5py
import numpy as np

from euler_harness import SLOW_BUILD, check, error, run



def fields(path):
    with h5py.File(path, "r") as f:
        return {k: f["/final/" + k][...] for k in ("rho", "u", "v", "w", "p")}


def max_rel_diff(a, b):
    return max(np.abs(a[k] - b[k]).max() / max(np.abs(a[k]).max(), 1e-300) for k in a)


def orders(ns, errs):
    return [math.log(errs[i - 1] / errs[i]) / math.log(ns[i] / ns[i - 1]) for i in range(1, len(ns))]


def fewer_steps(args):
    """args with each -max_steps value divided by 3 (at least 2)."""
    return [max(2, a // 3) if i > 0 and args[i - 1] == "-max_steps" else a for i, a in enumerate(args)]


def vortex_order():
    """Isentropic vortex (strength 5, mean flow (1, 1)): Pade core L1(rho) order >= 5.5 and ENO-Pade >= 4.8
    between 32^2 and 128^2; RK4 with dt = 4e-3 to t = 0.5 (time error below 1e-13: halving dt changes the
    128^2 error in the 7th digit)."""
    for label, extra, ns, bound in [("Pade core", ["-shock_threshold", 1e9], [32, 64, 128], 5.5),
                                    ("ENO-Pade", [], [32, 128], 4.8)]:
        errs = []
        for n in ns:
            out = run(["-dim", 2, "-problem", "isentropic_vortex", "-nx", n, "-ny", n, "-time", "rk4", "-dt", 4e-3,
                       "-t_final", 0.5, "-error", "-quiet"] + extra)
            errs.append(error(out))
        o = orders(ns, errs)
        total = math.log(errs[0] / errs[-1]) / math.log(ns[-1] / ns[0])
        print(label, "errors", errs, "orders", o)
        check(total >= bound and min(o) >= bound - 0.3,
              f"{label}: L1 errors {errs} on {ns}^2, orders {o}: 32->128 order {total:.2f} >= {bound}")


def planar():
    """Sod along x, y and z of a 3D grid (and along y of a 2D grid) equals the 1D run to round-off."""
    common = ["-problem", "sod", "-dt", 5e-4, "-t_final", 0.02 if SLOW_BUILD else 0.05]
    with tempfile.TemporaryDirectory() as d:
        one = os.path.join(d, "one.h5")
        run(common + ["-nx", 100, "-output", one, "-quiet"])
        with h5py.File(one, "r") as f:
            r1 = f["/final/rho"][...]
            u1 = f["/final/u"][...]
            p1 = f["/final/p"][...]
        cases = [(3, "x", {"-nx": 100}), (3, "y", {"-ny": 100}), (3, "z", {"-nz": 100}), (2, "y", {"-ny": 100})]
        for dim, axis, n in cases:
            path = os.path.join(d, f"p{dim}{axis}.h5")
            args = ["-dim", dim, "-axis", axis, "-output", path, "-quiet"] + common
            for k, v in n.items():
                args += [k, v]
            run(args)
            f = fields(path)
            vel = {"x": "u", "y": "v", "z": "w"}[axis]
            ax = {"x": -1, "y": -2, "z": -3}[axis]
            diff = 0.0
            for name, ref in (("rho", r1), ("p", p1), (vel, u1)):
                a = np.moveaxis(f[name], ax, -1).reshape(-1, f[name].shape[ax])
                diff = max(diff, np.abs(a - ref[None, :]).max() / np.abs(ref).max())
            others = [k for k in ("u", "v", "w") if k != vel]
            trans = max(np.abs(f[k]).max() for k in others)
            check(diff <= 1e-12 and trans <= 1e-13,
                  f"{dim}D Sod along {axis}: max relative difference to 1D {diff:.3e} <= 1e-12, "
                  f"transverse velocity {trans:.1e}")


def ranks():
    """1 vs 2 vs 4 ranks to 1e-12 relative: 2D Riemann (ENO-Pade, shocks: block line solves), 2D vortex (CRWENO5),
    3D explosion (ENO-Pade; also in 1 MiB block-line batches), 3D Taylor-Green (WENO5). Lines split over ranks are
    transposed (default -line_solve transpose: bitwise the 1-rank result, also for 2048-cell lines moved in
    1 MiB batches of 31 lines at 2 ranks) or solved in place (-line_solve substructured: round-off, amplified by
    the nonlinear weights of enopade6's shocked lines: 1.0e-11 after 8 steps of the 3D explosion at 4 ranks with
    the p = 1 WENO-Z weights (5.7e-13 with p = 2), 2.9e-12 after 25 steps of lax_liu_4 with p = 2: bound 1e-10)."""
    cases = [["-dim", 2, "-problem", "lax_liu_4", "-nx", 48, "-ny", 48, "-max_steps", 25],
             ["-dim", 2, "-problem", "lax_liu_4", "-nx", 48, "-ny", 48, "-max_steps", 25, "-line_solve",
              "substructured"],
             ["-dim", 2, "-problem", "lax_liu_4", "-nx", 2048, "-ny", 32, "-max_steps", 3, "-line_batch_mb", 1],
             ["-dim", 3, "-problem", "explosion", "-nx", 24, "-ny", 24, "-nz", 24, "-max_steps", 8, "-line_solve",
              "substructured"],
             ["-dim", 2, "-problem", "isentropic_vortex", "-scheme", "crweno5", "-nx", 40, "-ny", 40, "-max_steps",
              15],
             ["-dim", 3, "-problem", "explosion", "-nx", 24, "-ny", 24, "-nz", 24, "-max_steps", 8],
             # many small block-line batches: the batch size must agree on all ranks of a line (where it does
             # not, a rank with more block lines than one 256 MiB batch corrupts the heap at 2 ranks)
             ["-dim", 3, "-problem", "explosion", "-nx", 24, "-ny", 24, "-nz", 24, "-max_steps", 8,
              "-line_batch_mb", 1],
             ["-dim", 3, "-problem", "taylor_green", "-scheme", "weno5", "-nx", 16, "-ny", 16, "-nz", 16,
              "-max_steps", 8]]
    if SLOW_BUILD:  # the same decompositions, batches and line solves over fewer steps
        cases = [fewer_steps(c) for c in cases]
    with tempfile.TemporaryDirectory() as d:
        for i, c in enumerate(cases):
            res = {}
            for np_ in (1, 2, 4):
                path = os.path.join(d, f"c{i}_{np_}.h5")
                run(c + ["-output", path, "-quiet"], np_=np_)
                res[np_] = fields(path)
            for np_ in (2, 4):
                v = max_rel_diff(res[1], res[np_])
                bound = 1e-10 if "substructured" in c else 1e-12
                check(v <= bound, f"{' '.join(map(str, c))}: 1 vs {np_} ranks max relative difference {v:.3e} "
                      f"<= {bound}")


def conservation():
    """Periodic grids conserve mass, momentum and energy to round-off (every scheme, 2D and 3D)."""
    cases = [["-dim", 2, "-problem", "isentropic_vortex", "-nx", 32, "-ny", 32, "-max_steps", 20],
             ["-dim", 3, "-problem", "taylor_green", "-nx", 16, "-ny", 16, "-nz", 16, "-max_steps", 10]]
    for c in cases:
        for scheme in ("enopade6", "crweno5", "weno5", "muscl2"):
            out = run(c + ["-scheme", scheme])
            tot = [(float(a), float(b)) for a, b in re.findall(r"conservation \S+: initial (\S+) final (\S+)", out)]
            # momenta that start at zero are measured against the momentum scale sqrt(mass x energy)
            scale = math.sqrt(abs(tot[0][0] * tot[-1][0]))
            changes = [abs(b - a) / max(abs(a), scale) for a, b in tot]
            check(len(changes) == int(c[1]) + 2 and max(changes) <= 1e-13,
                  f"{c[3]} {scheme}: relative changes {changes} <= 1e-13")


def spectrum():
    """The kinetic-energy spectrum written by -spectrum sums to the mean kinetic energy of the final fields
    (Parseval), and the initial Taylor-Green field puts its energy in shell k = sqrt(3) -> 2 only."""
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "tg.h5")
        run(["-dim", 3, "-problem", "taylor_green", "-nx", 16, "-ny", 16, "-nz", 16, "-max_steps", 1, "-dt", 1e-9,
             "-spectrum", "-snapshot_every", 1, "-output", path, "-quiet"], np_=2)
        f = fields(path)
        with h5py.File(path, "r") as h:
            E = h["/spectrum/E"][...]
            snaps = {g: h[f"/snapshots/{g}/spectrum/E"][...] for g in h["/snapshots"]}
        ke = np.mean(0.5 * f["rho"] * (f["u"] ** 2 + f["v"] ** 2 + f["w"] ** 2))
        check(abs(E.sum() - ke) <= 1e-12 * ke, f"sum E(k) = {E.sum():.15e} equals mean kinetic energy {ke:.15e}")
        frac = E[2] / E.sum()
        check(frac >= 1 - 1e-6, f"Taylor-Green at t ~ 0: fraction of energy in shell k = 2 is {frac:.9f}")
        for g, Es in snaps.items():  # dt = 1e-9: the snapshots hold the initial kinetic energy to 1e-6
            check(abs(Es.sum() - ke) <= 1e-6 * ke, f"snapshot {g}: spectrum written, sum E(k) = {Es.sum():.12e}")
        check(len(snaps) == 2, f"spectra of the 2 snapshots (steps 0 and 1): {sorted(snaps)}")


def restart():
    """Checkpoint at 2 ranks, restart at 2 (bitwise) and at 1 and 3 ranks (1e-12) equals the uninterrupted run."""
    base = ["-dim", 2, "-problem", "lax_liu_6", "-nx", 48, "-ny", 48, "-t_final", 0.05]
    with tempfile.TemporaryDirectory() as d:
        full = os.path.join(d, "full.h5")
        run(base + ["-output", full, "-quiet"], np_=2)
        ref = fields(full)
        ck = os.path.join(d, "ck")
        for np_, bound in ((2, 0.0), (1, 1e-12), (3, 1e-12)):
            run(base + ["-checkpoint_dir", ck, "-checkpoint_every", 10, "-max_steps", 15, "-quiet"], np_=2)
            out_path = os.path.join(d, f"r{np_}.h5")
            out = run(base + ["-checkpoint_dir", ck, "-restart", "latest", "-output", out_path], np_=np_)
            check("restarted from" in out, f"restart at {np_} rank(s) read a checkpoint")
            v = max_rel_diff(ref, fields(out_path))
            check(v <= bound, f"stopped at 2 ranks, restarted at {np_}: max relative difference {v:.3e} <= {bound}")
        out = run(base + ["-scheme", "weno5", "-checkpoint_dir", ck, "-restart", "latest"], expect_ok=False)
        check("ERROR" in out and "weno5" in out, "a checkpoint of other numerics is refused")


def robustness():
    """Double Mach reflection (dx = 1/60, 2 ranks splitting y) and Rayleigh-Taylor (16 x 64, 2 ranks) run to their
    end times (0.2 and 1.95: the printed end time equals the header's t_final, to its 6 printed digits), with finite
    final fields and rho, p > 0 (the app stops with an error if density or pressure ever becomes <= 0 or
    non-finite on the way). Double Mach at dx = 1/120 takes ~5 CPU-minutes (too long for the
    30-minute CI) and Rayleigh-Taylor at 32 x 128 (2634 steps) were run by hand, positive throughout."""
    # Under the sanitizers (SLOW_BUILD) double Mach runs at dx = 1/30: the same
    # code paths (shock rows, limiter, the y split) at a quarter of the cells; the Release stage runs dx = 1/60.
    nx, ny = (120, 30) if SLOW_BUILD else (240, 60)
    with tempfile.TemporaryDirectory() as d:
        for args in (["-dim", 2, "-problem", "double_mach", "-nx", nx, "-ny", ny, "-da_processors_y", 2],
                     ["-dim", 2, "-problem", "rayleigh_taylor", "-nx", 16, "-ny", 64]):
            path = os.path.join(d, "r.h5")
            out = run(args + ["-output", path], np_=2)
            tf = float(re.search(r"t_final (\S+),", out).group(1))
            m = re.search(r"steps to t = (\S+)", out)
            t = float(m.group(1)) if m else float("nan")
            f = fields(path)
            low = min(f["rho"].min(), f["p"].min())
            finite = all(np.all(np.isfinite(v)) for v in f.values())
            check(abs(t - tf) <= 1e-6 * tf and "ERROR" not in out and finite and low > 0,
                  f"{args[3]}: ran to t = {t:g} (t_final {tf:g}), final fields finite, min(rho, p) {low:.3e} > 0")


if __name__ == "__main__":
    globals()[sys.argv[1]]()
