#!/usr/bin/env python3
"""reorder on Harwell-Boeing matrices: every ordering is a permutation; RCM reduces the profile of the CAN/BCSSTK
matrices listed below and never has a larger bandwidth; on bcsstk10, whose natural order is already banded, RCM
keeps the bandwidth 37 (SPARSEPAK's GENRCM gives the same permutation: test_reorder_sparsepak.py); nnz(L) fits in
the envelope; auto equals the smallest nnz(L) of natural/rcm/amd/metis (on bcsstk10 that is the input order:
20771 against RCM's 21029); AMD and METIS fill less than RCM on the 2D/3D FE
meshes can_1072, can_838 and bcsstk01 (measured nnz(L) amd / metis / rcm: 20548 / 22439 / 49406,
18924 / 18379 / 37300, 489 / 481 / 617). Not asserted, because it does not hold: on the banded bcsstk10 both fill
more than RCM (23689, 27702 vs 21029), on can_24 METIS does (125 vs 121)."""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

MATRICES = ["can_24", "can_1072", "bcsstk01", "bcsstk10", "can_838"]
FILL_BELOW_RCM = ["can_1072", "bcsstk01", "can_838"]  # 2D/3D FE meshes where AMD and METIS fill less than RCM


def main(exe, mdir):
    fails = []

    def check(cond, msg):
        print(("ok   " if cond else "FAIL ") + msg)
        if not cond:
            fails.append(msg)

    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with tempfile.TemporaryDirectory() as d:
        for name in MATRICES:
            out = os.path.join(d, name + ".h5")
            cmd = [exe, "-matrix", os.path.join(mdir, name + ".mtx"), "-ordering", "all", "-output", out]
            p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            print(p.stdout)
            if p.returncode:
                check(False, f"{name}: reorder failed")
                continue
            with h5py.File(out, "r") as f:
                n = int(f.attrs["n"])
                g = {k: {m: f[k][m][()] for m in ("bandwidth", "profile", "nnz_L", "permutation")} for k in f.keys()}
            for k, v in g.items():
                check(np.array_equal(np.sort(v["permutation"]), np.arange(n)), f"{name}/{k}: permutation of 0..{n-1}")
                check(v["nnz_L"][0] <= v["profile"][0] + n, f"{name}/{k}: nnz(L) {v['nnz_L'][0]} <= profile + n")
            check(g["rcm"]["profile"][0] < g["natural"]["profile"][0],
                  f"{name}: rcm profile {g['rcm']['profile'][0]} < natural {g['natural']['profile'][0]}")
            check(g["rcm"]["bandwidth"][0] <= g["natural"]["bandwidth"][0],
                  f"{name}: rcm bandwidth {g['rcm']['bandwidth'][0]} <= natural {g['natural']['bandwidth'][0]}")
            if name == "bcsstk10":
                check(g["rcm"]["bandwidth"][0] == 37, f"{name}: rcm bandwidth {g['rcm']['bandwidth'][0]} == 37")
            if name in FILL_BELOW_RCM:
                for k in ("amd", "metis"):
                    check(g[k]["nnz_L"][0] < g["rcm"]["nnz_L"][0],
                          f"{name}: {k} nnz(L) {g[k]['nnz_L'][0]} < rcm {g['rcm']['nnz_L'][0]}")
            best = min(g[k]["nnz_L"][0] for k in ("natural", "rcm", "amd", "metis"))
            check(g["auto"]["nnz_L"][0] == best, f"{name}: auto nnz(L) {g['auto']['nnz_L'][0]} = best {best}")
    print(f"{len(fails)} failure(s)")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
