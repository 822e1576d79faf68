"""The run/check harness the femdyn Python checks share (test_femdyn_material_auto.py, test_femdyn_dt_adapt.py,
test_femdyn_plex.py, test_femdyn_plex_mesh_file.py): check() records failures in FAILS; Runner launches femdyn
-material M -tip_load P BASE EXTRA into numbered output files and raises with the command's output when it fails;
launch() and run() start femdyn ARGS -output OUT -quiet at N ranks; rel() is the relative max-norm difference."""
import os
import subprocess

import h5py
import numpy as np

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OPENBLAS_NUM_THREADS="1")
FAILS = []


def check(cond, msg):
    print(("ok   " if cond else "FAIL ") + msg, flush=True)
    if not cond:
        FAILS.append(msg)


class Runner:
    def __init__(self, exe, base, d, timeout):
        self.exe, self.base, self.d, self.timeout, self.k = exe, base, d, timeout, 0

    def launch(self, material, load, *extra, np_=1):
        """(output file, stdout) of femdyn -material material -tip_load load BASE EXTRA at np_ ranks."""
        self.k += 1
        out = os.path.join(self.d, f"r{self.k}.h5")
        cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), self.exe, "-material", material, "-tip_load",
               str(load), *map(str, self.base), *map(str, extra), "-output", out]
        p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           timeout=self.timeout)
        if p.returncode != 0:
            raise AssertionError(f"{' '.join(cmd)} failed:\n{p.stdout}")
        return out, p.stdout


def launch(exe, np_, out, *args, timeout=300):
    """femdyn ARGS -output out -quiet at np_ ranks: the finished process (stdout and stderr together)."""
    cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), exe, *map(str, args), "-output", out, "-quiet"]
    return subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout)


def run(exe, np_, out, *args, timeout=300):
    """launch(), raising with the output when the run fails; the output file, open for reading."""
    p = launch(exe, np_, out, *args, timeout=timeout)
    if p.returncode != 0:
        raise AssertionError(f"femdyn {' '.join(map(str, args))} at {np_} ranks failed:\n{p.stdout}")
    return h5py.File(out, "r")


def rel(a, b):
    """max |a - b| / max |b|."""
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / np.max(np.abs(b)))
