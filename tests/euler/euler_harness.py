"""What every Euler test script shares: running build/bin/euler under mpiexec (output echoed, a non-zero exit a
failure unless expected) and the OK/FAIL check line. SUITE_BIN and SUITE_MPIEXEC choose the binaries."""
import os
import re
import subprocess
import sys

BIN = os.environ.get("SUITE_BIN", "build/bin")
MPIEXEC = os.environ.get("SUITE_MPIEXEC", "mpiexec")
SRC = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from slow_build import SLOW_BUILD  # noqa: E402,F401 (tests/slow_build.py; re-exported to the Euler checks)


def run(args, np_=1, expect_ok=True, timeout=1500, tail=4000, with_code=False):
    """Runs euler with args on np_ ranks and returns its output (stdout and stderr); with_code: and its exit
    status."""
    cmd = [MPIEXEC, "--oversubscribe", "-n", str(np_), os.path.join(BIN, "euler")] + [str(a) for a in args]
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout, env=env)
    print("$ " + " ".join(cmd))
    print(p.stdout[-tail:] if tail else p.stdout)
    if expect_ok and p.returncode != 0:
        raise SystemExit(f"FAIL: exit {p.returncode}")
    return (p.stdout, p.returncode) if with_code else p.stdout


def check(cond, msg):
    print(("OK: " if cond else "FAIL: ") + msg)
    if not cond:
        raise SystemExit(1)


def error(out, var="rho", norm="L1"):
    """The norm of the error line `error VAR: L1 a L2 b Linf c` that -error prints."""
    m = re.search(rf"error {var}: L1 (\S+) L2 (\S+) Linf (\S+)", out)
    if not m:
        raise SystemExit(f"FAIL: no error line for {var}")
    return float(m.group({"L1": 1, "L2": 2, "Linf": 3}[norm]))
