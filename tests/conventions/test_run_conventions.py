#!/usr/bin/env python3
"""The conventions every program shares (docs/architecture.md, "Conventions every program shares"), checked on
each program's own output at 1 and 2 ranks:
  - the last line is `<program>: <status>: ...; wrote FILE[, FILE.xmf]`, or `...; no output file (...)` without
    -output, in which case no file is written;
  - the XDMF sidecar of out.h5 is out.xmf beside it (never out.h5.xmf);
  - the root attribute `status` is `completed`, `stopped by walltime` (-max_walltime) or `stopped by signal`
    (SIGTERM, at 1 rank), the same word as the summary line;
  - a restart from a checkpoint at the end says that no step was left (no rate of zero steps in zero seconds);
  - contact writes the scene's body names as /bodies/name;
  - an -output that names an existing FIFO (as /dev/null names a device) is refused with one ERROR line and left
    in place (the rename of the finished file would replace it).

Usage: test_run_conventions.py NRANKS
"""
import os
import re
import signal
import stat
import subprocess
import sys
import tempfile
import time

import h5py

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from process_wait import read_until_stepping  # noqa: E402 (tests/process_wait.py)

BIN = os.environ.get("SUITE_BIN", os.path.join(os.path.dirname(__file__), "..", "..", "build", "bin"))
NP = int(sys.argv[1]) if len(sys.argv) > 1 else 1
failures = 0


def check(ok, what):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += not ok


def mpi(prog, *args):
    return ["mpiexec", "--oversubscribe", "-n", str(NP), os.path.join(BIN, prog)] + [str(a) for a in args]


def run(prog, *args):
    p = subprocess.run(mpi(prog, *args), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
    lines = [ln for ln in p.stdout.splitlines() if ln.strip()]
    check(p.returncode == 0, f"{prog} {' '.join(map(str, args))}: exit 0")
    if p.returncode != 0:
        print(p.stdout[-2000:])
    return lines[-1] if lines else ""


def status_of(path):
    with h5py.File(path, "r") as f:
        v = f.attrs["status"]
        return v.decode() if isinstance(v, bytes) else str(v)


def wrote(prog, last, status, files):
    pattern = rf"^{prog}: {status}: .*; wrote {re.escape(', '.join(files))}$"
    check(re.match(pattern, last) is not None,
          f"{prog}: last line says '{status}' and 'wrote {', '.join(files)}': {last!r}")


def with_output(prog, args, sidecar=True):
    wrote(prog, run(prog, *args, "-output", "o.h5"), "completed", ["o.h5", "o.xmf"] if sidecar else ["o.h5"])
    check(status_of("o.h5") == "completed", f"{prog}: status attribute 'completed'")
    if sidecar:
        check(os.path.exists("o.xmf") and not os.path.exists("o.h5.xmf"), f"{prog}: sidecar o.xmf beside o.h5")
        check("o.h5:" in open("o.xmf").read(), f"{prog}: o.xmf refers to o.h5 by its name")
    for f in ("o.h5", "o.xmf"):
        if os.path.exists(f):
            os.remove(f)


def without_output(prog, args):
    before = set(os.listdir("."))
    last = run(prog, *args)
    check(re.match(rf"^{prog}: completed: .*; no output file \(-output FILE writes one\)$", last) is not None,
          f"{prog} without -output: last line says no output file: {last!r}")
    check(set(os.listdir(".")) == before, f"{prog} without -output: no file written")


def refuses_special_file(prog, args):
    os.mkfifo("fifo.h5")
    p = subprocess.run(mpi(prog, *args, "-output", "fifo.h5"), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, timeout=120)
    errors = [ln for ln in p.stdout.splitlines() if ln.startswith("ERROR")]
    check(p.returncode != 0 and len(errors) == 1 and "fifo.h5: exists and is not a regular file" in errors[0],
          f"{prog} -output FIFO: refused with one ERROR line: {errors}")
    check(stat.S_ISFIFO(os.stat("fifo.h5").st_mode), f"{prog} -output FIFO: the FIFO is left in place")
    os.remove("fifo.h5")


def euler_stops():
    last = run("euler", "-problem", "sod", "-nx", 2000, "-max_walltime", 1e-6, "-output", "w.h5")
    check(last.startswith("euler: stopped by walltime: ") and status_of("w.h5") == "stopped by walltime",
          f"-max_walltime: 'stopped by walltime' on the last line and in the file: {last!r}")
    if NP != 1:  # the signal goes to a singleton run (mpiexec itself exits non-zero when it is signalled)
        return
    cmd = [os.path.join(BIN, "euler"), "-problem", "sod", "-nx", "40000", "-progress_interval", "0.05",
           "-output", "s.h5"]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    head = read_until_stepping(p)  # signal once the run is stepping, not after a fixed sleep
    time.sleep(0.2)
    p.send_signal(signal.SIGTERM)
    out, _ = p.communicate(timeout=120)
    last = [ln for ln in (head + out).splitlines() if ln.strip()][-1]
    check(p.returncode == 0 and last.startswith("euler: stopped by signal: ") and status_of("s.h5") ==
          "stopped by signal", f"SIGTERM: exit {p.returncode}, 'stopped by signal' on the last line and in the file")


def euler_restart_at_end():
    base = ["-problem", "sod", "-nx", 100, "-checkpoint_dir", "ck"]
    run("euler", *base)
    last = run("euler", *base, "-restart", "latest")
    check("no step left after the restart at step" in last and "cell-steps/s" not in last,
          f"restart from the final checkpoint: no step left, no rate: {last!r}")


def reorder_matrix():
    with open("tri.mtx", "w") as f:  # 6 x 6 tridiagonal (lower triangle, symmetric)
        f.write("%%MatrixMarket matrix coordinate real symmetric\n6 6 11\n")
        for i in range(1, 7):
            f.write(f"{i} {i} 2\n")
        for i in range(1, 6):
            f.write(f"{i + 1} {i} -1\n")
    return "tri.mtx"


def main():
    with tempfile.TemporaryDirectory() as d:
        os.chdir(d)
        euler = ["-problem", "sod", "-nx", 100]
        with_output("euler", euler)
        without_output("euler", euler)
        refuses_special_file("euler", euler)
        euler_stops()
        euler_restart_at_end()
        femdyn = ["-beam_cells", "4,1,1", "-steps", 3]
        with_output("femdyn", femdyn)
        without_output("femdyn", femdyn)
        refuses_special_file("femdyn", femdyn)
        contact = ["-scene", "incline", "-steps", 5]
        with_output("contact", contact)
        without_output("contact", contact)
        refuses_special_file("contact", contact)
        run("contact", *contact, "-output", "c.h5")
        with h5py.File("c.h5", "r") as f:
            names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["/bodies/name"][...]]
            joined = f["/bodies"].attrs["names"]
            joined = joined.decode() if isinstance(joined, bytes) else str(joined)
        check(len(names) == 2 and names == joined.split(","), f"contact: /bodies/name {names} are the scene's bodies")
        lcp = ["-family", "random_box", "-n", 10, "-count", 20, "-solvers", "bpp,lemke"]
        with_output("lcpbench", lcp, sidecar=False)
        refuses_special_file("lcpbench", lcp)
        mtx = reorder_matrix()
        with_output("reorder", ["-matrix", mtx], sidecar=False)
        without_output("reorder", ["-matrix", mtx])
        refuses_special_file("reorder", ["-matrix", mtx])
        if NP == 1 and os.path.exists(os.path.join(BIN, "lcpcompare")):  # lcpcompare times one core
            without_output("lcpcompare", ["-family", "random_box", "-n", 10, "-count", 10])
            refuses_special_file("lcpcompare", ["-family", "random_box", "-n", 10, "-count", 10])
        os.chdir("/")
    print(f"{'FAILED' if failures else 'passed'}: {failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
