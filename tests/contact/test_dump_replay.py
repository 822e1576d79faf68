#!/usr/bin/env python3
"""Contact problems dumped with -dump_problems replay as an lcpbench batch (the interface from
the contact app to lcpbench).

Asserts: the incline run dumps one problem per step and splitting pass; lcpbench reads every dump
(-file alone implies -family file) and bpp and lemke solve all of them (status 0, verified residual).
"""
import glob
import os
import subprocess
import sys

import h5py
import numpy as np

BIN = os.environ["SUITE_BIN"]


def run(*cmd):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} ({p.returncode})\n{p.stdout}")


for f in glob.glob("replay_*.h5"):
    os.remove(f)
run(f"{BIN}/contact", "-scene", "incline", "-steps", "5", "-quiet", "-dump_problems", "replay", "-output", "rc.h5")
dumps = sorted(glob.glob("replay_step*.h5"))
ok = len(dumps) >= 5
print(("ok   " if ok else "FAIL ") + f"{len(dumps)} problems dumped for 5 steps")
run(f"{BIN}/lcpbench", "-file", ",".join(dumps), "-solvers", "bpp,lemke", "-quiet", "-output", "replay_batch.h5")
with h5py.File("replay_batch.h5", "r") as f:
    for s in ("bpp", "lemke"):
        st = f[f"/results/{s}/status"][...]
        res = f[f"/results/{s}/residual"][...]
        good = st.shape == (len(dumps),) and np.all(st == 0) and np.all(res <= 1e-8)
        ok = ok and good
        print(("ok   " if good else "FAIL ") + f"{s}: {np.sum(st == 0)}/{len(dumps)} solved, max residual {res.max():.1e}")
sys.exit(0 if ok else 1)
