#!/usr/bin/env python3
"""reorder's cm and rcm against SPARSEPAK (George & Liu 1981) on every Harwell-Boeing matrix in the data folder,
and auto's choice among natural, rcm, amd and metis.

The reference is sparsepak_rcm.genrcm, an independent Python transcription of GENRCM/FNROOT/ROOTLS/RCM/DEGREE
(checked once against PETSc's f2c translation of SPARSEPAK, MatGetOrdering "rcm": identical permutations on all
25 matrices). For each matrix and each of cm (GENRCM without the reversal) and rcm, reorder's permutation equals
the reference's, and so do the reported bandwidth and profile (recomputed here from the permutation), also on
the matrices whose input order has a smaller bandwidth or profile than SPARSEPAK's RCM (bcsstk04, bcsstk06 and
bcsstk09: counted, they must be exactly these). auto: its permutation is that of the ordering its `taken`
attribute names, and its nnz(L) is the smallest of the four candidates' (ties: the earlier one)."""
import glob
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

import sparsepak_rcm as sp

RCM_WORSE_THAN_INPUT = {"bcsstk04", "bcsstk06", "bcsstk09"}  # SPARSEPAK's RCM: larger bandwidth or profile
AUTO_CANDIDATES = ("natural", "rcm", "amd", "metis")  # in auto's order of preference on ties


def check_auto(f, name, check):
    """auto's permutation is the one of the candidate it names, whose nnz(L) is the smallest (first on ties)."""
    t = f["auto"].attrs["taken"]
    t = t.decode() if isinstance(t, bytes) else str(t)
    nnz = {k: int(f[k]["nnz_L"][0]) for k in AUTO_CANDIDATES}
    best = min(AUTO_CANDIDATES, key=lambda k: (nnz[k], AUTO_CANDIDATES.index(k)))
    check(t == best and np.array_equal(f["auto"]["permutation"][()], f[t]["permutation"][()])
          and int(f["auto"]["nnz_L"][0]) == nnz[best], f"{name}/auto: took {t} (nnz(L) {nnz}; smallest {best})")
    return t


def main(exe, mdir):
    fails = []

    def check(cond, msg):
        print(("ok   " if cond else "FAIL ") + msg)
        if not cond:
            fails.append(msg)

    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    paths = sorted(glob.glob(os.path.join(mdir, "*.mtx")))
    check(len(paths) >= 24, f"{len(paths)} matrices in {mdir}")
    exact = {"cm": 0, "rcm": 0}
    worse_than_input = {"cm": set(), "rcm": set()}
    taken = {}
    print(f"{'matrix':10s} {'n':>5s} {'natural bw/profile':>20s} {'SPARSEPAK rcm':>16s} {'reorder rcm':>16s}")
    with tempfile.TemporaryDirectory() as d:
        for path in paths:
            name = os.path.basename(path)[:-4]
            n, xadj, adjncy = sp.read_mtx_graph(path)
            out = os.path.join(d, name + ".h5")
            cmd = [exe, "-matrix", path, "-ordering", "all", "-repeat", "1", "-output", out]
            p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            if p.returncode:
                print(p.stdout)
                check(False, f"{name}: reorder failed")
                continue
            with h5py.File(out, "r") as f:
                got = {k: (f[k]["permutation"][()], f[k]["bandwidth"][0], f[k]["profile"][0]) for k in ("cm", "rcm")}
                taken[name] = check_auto(f, name, check)
            nat = sp.bandwidth_profile(xadj, adjncy, np.arange(n))
            for k, reverse in (("cm", False), ("rcm", True)):
                ref = sp.genrcm(n, xadj, adjncy, reverse)
                bp_ref = sp.bandwidth_profile(xadj, adjncy, ref)
                worse = bp_ref[0] > nat[0] or bp_ref[1] > nat[1]
                perm, bw, prof = got[k]
                bp = sp.bandwidth_profile(xadj, adjncy, perm)
                if worse:
                    worse_than_input[k].add(name)
                exact[k] += bool(np.array_equal(perm, ref))
                check(np.array_equal(perm, ref), f"{name}/{k}: SPARSEPAK permutation"
                      + (" (worse than the input order)" if worse else ""))
                check((bw, prof) == bp == bp_ref, f"{name}/{k}: bandwidth {bw} profile {prof} (recomputed {bp[0]} {bp[1]})")
                if k == "rcm":
                    print(f"{name:10s} {n:5d} {nat[0]:8d} {nat[1]:11d} {bp_ref[0]:5d} {bp_ref[1]:10d} "
                          f"{bw:5d} {prof:10d}")
    check(worse_than_input["rcm"] == RCM_WORSE_THAN_INPUT, f"rcm worse than the input order on "
          f"{sorted(worse_than_input['rcm'])}")
    check(exact["rcm"] == len(paths) and exact["cm"] == len(paths),
          f"rcm / cm equal to SPARSEPAK on {exact['rcm']} / {exact['cm']} of {len(paths)} matrices")
    print(f"cm worse than the input order on {sorted(worse_than_input['cm'])}")
    print("auto took: " + ", ".join(f"{n} {t}" for n, t in sorted(taken.items())))
    print(f"{len(fails)} failure(s)")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
