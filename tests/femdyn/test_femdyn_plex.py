#!/usr/bin/env python3
"""femdyn -backend plex (distributed DMPlex mesh, state and output) against the serial CHOLMOD path.

Usage: test_femdyn_plex.py FEMDYN

- static linear cantilever (20x2x2 hexahedra, tip load 1; CG + GAMG at -ksp_rtol 1e-13) at 1, 2 and 3 ranks:
  tip deflection and the displacement field (matched by node coordinates) equal to CHOLMOD's to 1e-10 relative;
- 10 full-Newton StVK Newmark steps (and corotational at 2 ranks) (8x2x2, tip load 2, dt 0.02, Newton rtol 1e-12) at 1, 2 and 3 ranks (CG +
  GAMG at -ksp_rtol 1e-14) and at 2 ranks with MUMPS LU and with CG + hypre BoomerAMG: the tip history, the kinetic and strain energies and the
  final field equal to CHOLMOD's to 1e-10 relative;
- generalized-alpha (rho_inf 0.5), Rayleigh damping (alpha 0.5, beta 0.01) and both (rho_inf 0.8, 0.2, 0.005):
  10 StVK steps at 1 and 2 ranks, the tip history, the energies and the final field equal to CHOLMOD's to 1e-10
  relative (measured: at most 1e-14);
- snapshots (-snapshot_every 5 of 10 steps, 2 ranks): /snapshots/000000..000002 with u and the per-cell
  von_mises, the last equal to /final/u and /final/von_mises, and the XDMF sidecar a series of 3 grids with the
  von Mises stress as cell data;
- distribution: at 3 ranks every rank holds cells (/partition/cells, summing to the global count), and with
  -plex_rank_cap 2500 (a 30x2x2 beam holds 3,933 mesh points) the 1-rank run stops with a clear error while the
  3-rank run fits under the cap and gives the uncapped 1-rank tip deflection;
- a checkpoint written at 3 ranks restarts at 2 ranks and ends on the uninterrupted run (1e-10); the output is in
  the replicated path's node numbering (coordinates and /final/u row by row); a restart with another material
  is refused;
- the XDMF sidecar names /final/u; options the path does not have are refused by name.
"""
import os
import subprocess
import sys
import tempfile

import femdyn_harness as harness
from femdyn_harness import FAILS, check, rel
import h5py
import numpy as np

EXE = sys.argv[1]
ENV = harness.ENV
TOL = 1e-10


def launch(np_, out, *args):
    return harness.launch(EXE, np_, out, *args, timeout=300)


def run(np_, out, *args):
    return harness.run(EXE, np_, out, *args, timeout=300)


def field_by_coordinates(f):
    """(coordinates, u) sorted by node coordinates, so that two numberings of the same mesh compare."""
    x, u = f["mesh/coordinates"][:], f["final/u"][:]
    order = np.lexsort((x[:, 2], x[:, 1], x[:, 0]))
    return x[order], u[order]


def compare_field(label, f, ref):
    (x, u), (xr, ur) = field_by_coordinates(f), field_by_coordinates(ref)
    same_mesh = x.shape == xr.shape and np.abs(x - xr).max() < 1e-12
    check(same_mesh and rel(u, ur) <= TOL, f"{label}: field equal to CHOLMOD's: {rel(u, ur) if same_mesh else 'mesh differs'}")


def main():
    static = ["-static", "-tip_load", 1, "-beam_cells", "20,2,2"]
    dynamic = ["-material", "stvk", "-beam_cells", "8,2,2", "-tip_load", 2, "-dt", 0.02, "-steps", 10,
               "-newton_rtol", 1e-12]
    with tempfile.TemporaryDirectory() as d:
        p = lambda n: os.path.join(d, n)
        ref_s = run(1, p("s_ref.h5"), *static, "-solver", "cholmod")
        ref_d = run(1, p("d_ref.h5"), *dynamic, "-solver", "cholmod")
        for n in (1, 2, 3):
            f = run(n, p(f"s{n}.h5"), *static, "-backend", "plex", "-ksp_rtol", 1e-13)
            t, tr = f.attrs["tip_deflection"], ref_s.attrs["tip_deflection"]
            check(abs(t - tr) <= TOL * abs(tr), f"static, {n} ranks: tip {t:.12f} vs CHOLMOD {tr:.12f}")
            compare_field(f"static, {n} ranks", f, ref_s)
        tip_ref = ref_d["steps/tip_deflection"][1:]  # the replicated path records step 0 too
        cases = [(n, ["-ksp_rtol", 1e-14], "CG+GAMG") for n in (1, 2, 3)]
        cases.append((2, ["-ksp_type", "preonly", "-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps"], "MUMPS"))
        cases.append((2, ["-pc_type", "hypre", "-ksp_rtol", 1e-14], "CG+BoomerAMG"))
        for n, ksp, name in cases:
            f = run(n, p(f"d{n}_{name}.h5"), *dynamic, "-backend", "plex", *ksp)
            tip = f["steps/tip_deflection"][:]
            ok = tip.shape == tip_ref.shape and rel(tip, tip_ref) <= TOL
            check(ok, f"StVK Newmark, {n} ranks, {name}: tip history vs CHOLMOD {rel(tip, tip_ref) if ok else tip.shape}")
            compare_field(f"StVK Newmark, {n} ranks, {name}", f, ref_d)
            for e in ("kinetic_energy", "strain_energy"):
                v, vr = f[f"steps/{e}"][:], ref_d[f"steps/{e}"][1:]
                check(v.shape == vr.shape and rel(v, vr) <= TOL,
                      f"StVK Newmark, {n} ranks, {name}: {e} vs CHOLMOD {rel(v, vr) if v.shape == vr.shape else v.shape}")

        for name, extra in (("generalized-alpha", ["-time_scheme", "generalized_alpha", "-rho_inf", 0.5]),
                            ("Rayleigh damping", ["-rayleigh_alpha", 0.5, "-rayleigh_beta", 0.01]),
                            ("generalized-alpha + damping", ["-time_scheme", "generalized_alpha", "-rho_inf", 0.8,
                                                             "-rayleigh_alpha", 0.2, "-rayleigh_beta", 0.005])):
            ref_x = run(1, p(f"x_ref_{len(extra)}.h5"), *dynamic, *extra, "-solver", "cholmod")
            for n in (1, 2):
                f = run(n, p(f"x{n}_{len(extra)}.h5"), *dynamic, *extra, "-backend", "plex", "-ksp_rtol", 1e-14)
                errs = [rel(f["steps/tip_deflection"][:], ref_x["steps/tip_deflection"][1:]),
                        rel(f["final/u"][:], ref_x["final/u"][:])]
                errs += [rel(f[f"steps/{e}"][:], ref_x[f"steps/{e}"][1:]) for e in ("kinetic_energy", "strain_energy")]
                check(max(errs) <= TOL, f"{name}, {n} ranks: tip, field, kinetic, strain vs CHOLMOD "
                      + ", ".join(f"{e:.1e}" for e in errs))

        fs = run(2, p("snap.h5"), *dynamic, "-backend", "plex", "-snapshot_every", 5)
        names = sorted(fs["snapshots"].keys()) if "snapshots" in fs else []
        last = fs[f"snapshots/{names[-1]}"] if names else None
        ok = (names == ["000000", "000001", "000002"] and np.array_equal(last["u"][:], fs["final/u"][:]) and
              np.array_equal(last["von_mises"][:], fs["final/von_mises"][:]) and last["von_mises"].shape == (192,))
        xmf = open(p("snap.xmf")).read()
        check(ok and xmf.count("<Grid Name=\"mesh\"") == 3 and 'Name="von_mises" AttributeType="Scalar" Center="Cell"' in xmf,
              f"snapshots every 5 of 10 steps: {names}, the last = /final, XDMF series of 3 with von Mises cell data")

        corot = ["-material", "corotational", *dynamic[2:-1], 1e-10]  # its tangent reaches 1e-10, not 1e-12
        ref_c = run(1, p("c_ref.h5"), *corot, "-solver", "cholmod")
        fc = run(2, p("c2.h5"), *corot, "-backend", "plex", "-ksp_rtol", 1e-14)
        tc, tcr = fc["steps/tip_deflection"][:], ref_c["steps/tip_deflection"][1:]
        check(tc.shape == tcr.shape and rel(tc, tcr) <= TOL,
              f"corotational Newmark, 2 ranks: tip history vs CHOLMOD {rel(tc, tcr) if tc.shape == tcr.shape else tc.shape}")

        # A checkpoint written at 3 ranks (step 5 of 10) restarts at 2: the uninterrupted run's history and field.
        ck = p("ck")
        full = run(3, p("full3.h5"), *dynamic, "-backend", "plex", "-ksp_rtol", 1e-14, "-checkpoint_dir", ck,
                   "-checkpoint_every", 5)
        rs = run(2, p("rs2.h5"), *dynamic, "-backend", "plex", "-ksp_rtol", 1e-14, "-restart",
                 os.path.join(ck, "femdyn_0000000005.h5"))
        ta, tb = full["steps/tip_deflection"][:], rs["steps/tip_deflection"][:]
        du = rel(rs["final/u"][:], full["final/u"][:])
        check(ta.shape == tb.shape == (10,) and rel(tb, ta) <= TOL and du <= TOL,
              f"checkpoint at 3 ranks, restart at 2: tip history {rel(tb, ta):.1e}, field {du:.1e} (<= {TOL:g})")
        check(np.array_equal(rs["mesh/tets"][:].shape, (384 // 2, 4)) and
              np.abs(rs["mesh/coordinates"][:] - ref_d["mesh/coordinates"][:]).max() == 0.0 and
              rel(rs["final/u"][:], ref_d["final/u"][:]) <= TOL,
              "output in the replicated path's node numbering: same coordinates and /final/u rows")
        other = launch(2, p("bad_rs.h5"), "-material", "linear", *dynamic[2:], "-backend", "plex", "-restart",
                       os.path.join(ck, "femdyn_0000000005.h5"))
        check(other.returncode != 0 and "material stvk, this run linear" in other.stdout,
              "restart with another material: refused, naming it")

        f3 = run(3, p("part.h5"), *static, "-backend", "plex")
        cells = f3["partition/cells"][:]
        check(len(cells) == 3 and cells.min() > 0 and cells.sum() == f3.attrs["elements"] == 480,
              f"3 ranks: cells per rank {list(cells)} (of 480)")
        xmf = open(p("part.xmf")).read()
        check("/final/u" in xmf and "Tetrahedron" in xmf, "XDMF sidecar: tetrahedra and /final/u")

        capped = ["-static", "-tip_load", 1, "-beam_cells", "30,2,2", "-backend", "plex"]
        one = launch(1, p("cap1.h5"), *capped, "-plex_rank_cap", 2500)
        check(one.returncode != 0 and "above -plex_rank_cap 2500" in one.stdout,
              "-plex_rank_cap 2500 at 1 rank: a clear error (the whole mesh is 3,933 points)")
        three = run(3, p("cap3.h5"), *capped, "-plex_rank_cap", 2500, "-ksp_rtol", 1e-13)
        free = run(1, p("cap_free.h5"), *capped, "-ksp_rtol", 1e-13)
        t3, t1 = three.attrs["tip_deflection"], free.attrs["tip_deflection"]
        check(abs(t3 - t1) <= TOL * abs(t1), f"-plex_rank_cap 2500 at 3 ranks fits: tip {t3:.12f} vs {t1:.12f}")

        for bad, expect in ((["-static", "-order", 2], "-order is not available with -backend plex"),
                            (["-material", "auto", "-steps", 2], "has no -material auto")):
            r = launch(1, p("bad.h5"), "-backend", "plex", *bad)
            check(r.returncode != 0 and expect in r.stdout, f"{' '.join(map(str, bad))}: refused ({expect})")
    if FAILS:
        print(f"{len(FAILS)} check(s) failed")
        sys.exit(1)
    print("femdyn -backend plex: all checks passed")


main()
