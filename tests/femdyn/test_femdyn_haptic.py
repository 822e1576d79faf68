#!/usr/bin/env python3
"""femdyn haptic probe: the local model's force agrees with the full model at the synchronisation points.

Usage: test_femdyn_haptic.py FEMDYN

StVK beam 20x2x2, probe (penalty k = 100) pressing at 0.1 length/s on the top node of the free end, haptic
output at 1 kHz between FEM steps (10 local updates per FEM step of 10 ms):
- the force the local model predicts for the next synchronisation time agrees with the full-model force there
  to <= 2.5% of the maximum force (dt = 0.01) and <= 0.6% (dt = 0.005): the local model is consistent, its
  error at least halves when the FEM step is halved;
- 10 haptic outputs per FEM step, all forces >= 0 and finite, the full-model force equals k times the
  penetration of the probe node (checked from the output displacement at the last step).
"""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

EXE = sys.argv[1]
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
FAILS = []
K = 100.0


def check(cond, msg):
    print(("ok   " if cond else "FAIL ") + msg, flush=True)
    if not cond:
        FAILS.append(msg)


def run(out, dt, steps):
    cmd = [EXE, "-probe", "-probe_stiffness", str(K), "-probe_speed", "0.1", "-beam_cells", "20,2,2", "-material",
           "stvk", "-dt", str(dt), "-steps", str(steps), "-output", out, "-quiet"]
    p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
    if p.returncode != 0:
        raise AssertionError(f"{' '.join(cmd)} failed:\n{p.stdout}")
    with h5py.File(out, "r") as f:
        pr = f["probe"]
        d = {k: pr[k][:] for k in pr.keys()}
        d["node"] = int(pr.attrs["node"])
        d["u"] = f["final/u"][:]
        d["y0"] = f["mesh/coordinates"][d["node"], 1]
        return d


def sync_error(d):
    ff, fp = d["force_full"], d["force_predicted"]
    return float(np.max(np.abs(fp[:-1] - ff[1:])) / np.max(np.abs(ff)))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        a = run(os.path.join(tmp, "a.h5"), 0.01, 100)
        b = run(os.path.join(tmp, "b.h5"), 0.005, 200)
        ea, eb = sync_error(a), sync_error(b)
        print(f"  max force {np.max(a['force_full']):.4f}; local vs full model at synchronisations: "
              f"{ea:.3e} (dt 0.01), {eb:.3e} (dt 0.005) of the max force")
        check(np.max(a["force_full"]) > 0.3, "the probe presses on the beam")
        check(ea <= 0.025, f"dt = 0.01: local model agrees with the full model to {ea:.2e} <= 2.5% of max force")
        check(eb <= 0.006, f"dt = 0.005: local model agrees with the full model to {eb:.2e} <= 0.6% of max force")
        check(eb <= 0.5 * ea, "the agreement at least doubles when the FEM step is halved")
        check(len(a["haptic_force"]) == 10 * len(a["sync_time"]), "1 kHz output: 10 haptic forces per FEM step")
        hf = a["haptic_force"]
        check(np.all(np.isfinite(hf)) and np.all(hf >= 0), "haptic forces finite and >= 0")
        # Full-model force = k * penetration at the last step (probe at y0 - 0.1 t, t = 1).
        y = a["y0"] + a["u"][a["node"], 1]
        pen = max(0.0, y - (a["y0"] - min(0.1 * a["sync_time"][-1], 0.2)))
        check(abs(a["force_full"][-1] - K * pen) <= 1e-12 * max(1.0, K * pen),
              f"full-model force {a['force_full'][-1]:.6f} = k * penetration {K * pen:.6f}")
    print(f"{len(FAILS)} failure(s)")
    return 1 if FAILS else 0


if __name__ == "__main__":
    sys.exit(main())
