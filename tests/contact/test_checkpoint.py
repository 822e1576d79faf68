"""Checkpoint/restart of the contact app, at 1 and 2 ranks: a run with periodic checkpoints
restarted from the latest one, and a run stopped by -max_walltime (which writes a final checkpoint) then
restarted, both end in exactly (bitwise) the final state of the uninterrupted run: positions, orientations,
velocities. The scene (a small log heap with sleeping on and the splitting model, warm-started from the
previous step) makes every part of the checkpointed state matter. Also: a restart with another friction
model is refused with a clear message.

    test_checkpoint.py <contact executable> <ranks>
"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

APP = sys.argv[1]
NP = int(sys.argv[2])
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
TMP = Path(tempfile.mkdtemp(prefix="contact_ckpt_"))
SCENE = ["-scene", "log_heap", "-n_logs", "6", "-sleep", "-sleep_steps", "10", "-regularisation", "1e-4",
         "-friction", "splitting", "-splitting_max_it", "3"]
failures = []


def run(np_, out, *args, check=True):
    cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), APP, *SCENE, *map(str, args), "-output", str(out)]
    p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if check and p.returncode != 0:
        raise SystemExit(f"FAILED: {' '.join(cmd)}\n{p.stdout}")
    return p


def final(path):
    with h5py.File(path, "r") as f:
        st = f.attrs["status"]
        st = st.decode() if isinstance(st, bytes) else str(st)
        return {k: f["/frames/" + k][-1] for k in ("positions", "orientations", "velocities")}, st, \
            int(f["/frames/step"][-1]) if "step" in f["/frames"] else None, int(f["/steps/sleeping"][-1])


def same(name, a, b):
    for k in a:
        if not np.array_equal(a[k], b[k]):
            failures.append(f"{name}: {k} differ (max {np.abs(a[k] - b[k]).max():.3e})")
            return
    print(f"{name}: final state bitwise equal")


for np_ in (NP,):
    steps = 120
    ref, _, _, asleep = final(run(np_, TMP / f"a{np_}.h5", "-steps", steps, "-quiet") and TMP / f"a{np_}.h5")
    print(f"np {np_}: reference run, {asleep} bodies asleep at the end")
    # periodic checkpoints (every 50 steps, and the time loop's final one at step 120; the newest 3 kept),
    # restart from the last periodic one (step 100; "latest" is the final one, tested after the stop below)
    d = TMP / f"ck{np_}"
    run(np_, TMP / f"b{np_}.h5", "-steps", steps, "-checkpoint_dir", d, "-checkpoint_every", 50,
        "-checkpoint_keep", 3, "-quiet")
    files = sorted(p.name for p in d.glob("contact_*.h5"))
    if files != ["contact_0000000050.h5", "contact_0000000100.h5", "contact_0000000120.h5"]:
        failures.append(f"np {np_}: checkpoint files {files}")
    run(np_, TMP / f"c{np_}.h5", "-steps", steps, "-restart", d / "contact_0000000100.h5", "-quiet")
    same(f"np {np_} periodic + restart from step 100", ref, final(TMP / f"c{np_}.h5")[0])
    # stopped by the wall-time limit (at whatever step k it reaches): a final checkpoint at k, then the restart
    # runs to k + 50 and must equal an uninterrupted run of k + 50 steps
    d2 = TMP / f"wall{np_}"
    p = run(np_, TMP / f"w{np_}.h5", "-steps", 10**7, "-checkpoint_dir", d2, "-max_walltime", 0.3)
    _, status, _, _ = final(TMP / f"w{np_}.h5")
    ck = sorted(d2.glob("contact_*.h5"))
    if not status.startswith("stopped"):
        failures.append(f"np {np_}: the -max_walltime run was not stopped (status '{status}')")
    elif not ck:
        failures.append(f"np {np_}: no final checkpoint after the stop:\n{p.stdout}")
    else:
        k = int(ck[-1].stem.split("_")[1])
        print(f"np {np_}: {status}; final checkpoint {ck[-1].name}")
        ref2 = final(run(np_, TMP / f"r{np_}.h5", "-steps", k + 50, "-quiet") and TMP / f"r{np_}.h5")[0]
        run(np_, TMP / f"x{np_}.h5", "-steps", k + 50, "-checkpoint_dir", d2, "-restart", "latest", "-quiet")
        same(f"np {np_} -max_walltime stop at step {k} + restart to {k + 50}", ref2, final(TMP / f"x{np_}.h5")[0])

# a checkpoint of another friction model is refused (one clear line, non-zero exit)
p = subprocess.run(["mpiexec", "--oversubscribe", "-n", str(NP), APP, *SCENE[:-4], "-friction", "box", "-steps",
                    "120", "-restart", str(TMP / f"ck{NP}" / "contact_0000000100.h5"), "-output", str(TMP / "bad.h5")],
                   env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
if p.returncode == 0 or "written with scheme 'scene=log_heap friction=splitting'" not in p.stdout:
    failures.append(f"mismatched restart not refused clearly (rc {p.returncode}):\n{p.stdout}")
else:
    print("restart with another friction model refused")

if failures:
    print("\n".join(["FAILED:"] + failures))
    sys.exit(1)
print("all checkpoint checks passed")
