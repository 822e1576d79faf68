"""Shared helpers of the contact app's Python checks (test_contact_app.py, test_islands.py, test_lcp_auto.py):
run the app into a temporary HDF5 file, record named checks, exit non-zero when any failed."""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from slow_build import SLOW_BUILD  # noqa: E402,F401 (tests/slow_build.py; re-exported to the contact checks)


class Harness:
    def __init__(self, app, prefix):
        self.app = app
        self.tmp = Path(tempfile.mkdtemp(prefix=prefix))
        self.failures = []

    def run(self, name, *args, np_=1):
        """Runs the app on np_ ranks with -output TMP/name.h5 and returns that file open; stops on a failed run."""
        out = self.tmp / f"{name}.h5"
        cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), self.app, *map(str, args), "-output", str(out),
               "-quiet"]
        p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if p.returncode != 0:
            raise SystemExit(f"FAILED: {' '.join(cmd)}\n{p.stdout}")
        return h5py.File(out, "r")

    def check(self, cond, what):
        print(("ok    " if cond else "FAIL  ") + what)
        if not cond:
            self.failures.append(what)

    def finish(self, what):
        if self.failures:
            print(f"{len(self.failures)} check(s) failed")
            sys.exit(1)
        print(f"all {what} checks passed")
