"""The run/check harness the femdyn Python checks share (test_femdyn_material_auto.py, test_femdyn_dt_adapt.py):
check() records failures in FAILS; Runner launches femdyn -material M -tip_load P BASE EXTRA into numbered
output files and raises with the command's output when it fails."""
import os
import subprocess

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
