#!/usr/bin/env python3
"""lcpbench batch resilience: a killed batch resumes from its last flushed results and never
recomputes or loses finished problems.

- Reference: an uninterrupted 2-rank batch.
- SIGTERM part-way (2 ranks): clean stop, OUT.partial kept and OUT not written; resumed at 1 rank.
- SIGKILL of the whole job after at least one flush (2 ranks): OUT.partial readable; a resume with another
  -seed is refused (header mismatch, non-zero exit, OUT.partial untouched); resumed at 2 ranks.
- -max_walltime 1.5 (1 rank): clean stop at the limit; resumed at 2 ranks.
For each interrupted batch: the final per-problem results (status, iterations, pivots, residual, n) equal
the reference exactly; every problem flagged done in OUT.partial after the kill keeps its stored values,
times included (not recomputed: /batch/run = 0), every other problem was solved exactly once by the resume
(/batch/run = 1; solved_per_run = [done, count - done]).
Usage: test_lcpbench_resume.py LCPBENCH
"""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

os.environ["HDF5_USE_FILE_LOCKING"] = "FALSE"  # the test peeks at OUT.partial while the batch writes it
import h5py  # noqa: E402
import numpy as np  # noqa: E402

# SIGTERM reaches the ranks through mpiexec, as a scheduler sends it: with Open MPI's default grace before it
# kills them (1 s; SUITE_TEST_ENV in cmake/SuiteTesting.cmake sets 0 for every test), which the ranks' clean
# stop needs.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_odls_base_sigkill_timeout="1")
COUNT = 400
ARGS = ["-family", "random_box", "-n", "30", "-count", str(COUNT), "-cond", "1e4", "-solvers",
        "lemke,bpp,pgs,fb_newton", "-flush_every", "20", "-chunk", "4"]
FIELDS = ["status", "iterations", "pivots", "residual"]
SOLVERS = ["lemke", "bpp", "pgs", "fb_newton"]
failures = []


def check(cond, msg):
    print(("PASS " if cond else "FAIL ") + msg, flush=True)
    if not cond:
        failures.append(msg)


def mpi(np_, exe, *args):
    return ["mpiexec", "--oversubscribe", "-n", str(np_), exe, *ARGS, *args]


def run(cmd, expect_rc=0):
    p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
    if expect_rc is not None and p.returncode != expect_rc:
        raise AssertionError(f"{' '.join(cmd)} exited {p.returncode}:\n{p.stdout}")
    return p


def done_count(path):
    try:
        with h5py.File(path, "r") as f:
            return int(np.sum(f["/batch/done"][...]))
    except (OSError, KeyError):
        return 0


def snapshot(path):
    with h5py.File(path, "r") as f:
        done = f["/batch/done"][...].astype(bool)
        vals = {f"/results/{s}/{x}": f[f"/results/{s}/{x}"][...] for s in SOLVERS
                for x in FIELDS + ["time", "cpu_time"]}
        vals["/problems/n"] = f["/problems/n"][...]
    return done, vals


def start_interrupted(exe, out, min_done):
    """Starts a slowed-down 2-rank batch in its own process group; returns once OUT.partial holds at least
    min_done flushed problems."""
    p = subprocess.Popen(mpi(2, exe, "-output", out, "-delay_per_problem", "0.01", "-quiet"), env=ENV,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    t0 = time.time()
    while done_count(out + ".partial") < min_done:
        if p.poll() is not None or time.time() - t0 > 60:
            out_text = p.communicate()[0] if p.poll() is not None else ""
            p.kill()
            raise AssertionError(f"batch did not flush {min_done} problems in time:\n{out_text}")
        time.sleep(0.05)
    return p


def kill_session(sid, sig):
    """Sends sig to every process of the session (mpiexec puts each rank in its own process group, so
    killpg would miss them); returns once all are gone."""
    pids = []
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                if os.getsid(int(d)) == sid:
                    pids.append(int(d))
            except OSError:
                pass
    for pid in sorted(pids, reverse=True):
        try:
            os.kill(pid, sig)
        except OSError:
            pass
    return pids


def compare_final(ref, got, before_done, before_vals, what):
    with h5py.File(ref, "r") as a, h5py.File(got, "r") as b:
        same = all(np.array_equal(a[f"/results/{s}/{x}"][...], b[f"/results/{s}/{x}"][...])
                   for s in SOLVERS for x in FIELDS)
        same &= np.array_equal(a["/problems/n"][...], b["/problems/n"][...])
        check(same, f"{what}: status, iterations, pivots, residual of all {COUNT} problems equal the uninterrupted run")
        check(bool(np.all(b["/batch/done"][...] == 1)), f"{what}: every problem done")
        run_ = b["/batch/run"][...]
        nd = int(before_done.sum())
        check(0 < nd < COUNT, f"{what}: interrupted part-way ({nd} of {COUNT} flushed)")
        check(bool(np.all(run_[before_done] == 0)) and bool(np.all(run_[~before_done] == 1)),
              f"{what}: flushed problems kept from run 0, the other {COUNT - nd} solved by run 1")
        kept = all(np.array_equal(before_vals[k][before_done], b[k][...][before_done]) for k in before_vals)
        check(kept, f"{what}: flushed problems not recomputed (stored values, times included, unchanged)")
        spr = list(b["/batch"].attrs["solved_per_run"])
        check(spr == [nd, COUNT - nd], f"{what}: solved_per_run {spr} == [{nd}, {COUNT - nd}] (no problem twice)")
        for s in SOLVERS:
            h = b[f"/results/{s}/histogram/iterations_counts"][...]
            check(int(h.sum()) == COUNT - int(b[f"/results/{s}"].attrs["failures"]),
                  f"{what}: {s} iteration histogram counts every solved problem")


def main(exe):
    tmp = tempfile.mkdtemp(prefix="lcpbench_resume_")
    os.chdir(tmp)
    run(mpi(2, exe, "-output", "ref.h5", "-quiet"))
    with h5py.File("ref.h5", "r") as f:
        check(all(int(f[f"/results/{s}"].attrs["failures"]) == 0 for s in SOLVERS), "reference: 0 failures")
        check("/batch/done" in f and int(f["/batch"].attrs["complete"]) == 1, "reference file complete")
    check(not os.path.exists("ref.h5.partial"), "OUT.partial renamed to OUT at completion")

    # --- SIGTERM: clean stop, resume at another rank count ---
    p = start_interrupted(exe, "term.h5", 40)
    os.killpg(p.pid, signal.SIGTERM)
    out = p.communicate(timeout=60)[0]
    check(out.count("stop requested (signal)") == 1, "SIGTERM: one stop message")
    check(os.path.exists("term.h5.partial") and not os.path.exists("term.h5"), "SIGTERM: OUT.partial kept, no OUT")
    done, vals = snapshot("term.h5.partial")
    r = run(mpi(1, exe, "-output", "term.h5"))
    check(f"resuming term.h5.partial: {int(done.sum())} of {COUNT} problems done" in r.stdout,
          "SIGTERM: the resume reports what it skips")
    compare_final("ref.h5", "term.h5", done, vals, "SIGTERM + resume at 1 rank")

    # --- SIGKILL of every process after a flush ---
    p = start_interrupted(exe, "kill.h5", 60)
    pids = kill_session(p.pid, signal.SIGKILL)
    p.communicate(timeout=60)
    t0 = time.time()
    def alive(q):
        try:
            with open(f"/proc/{q}/stat") as fh:
                return fh.read().split()[2] != "Z"
        except OSError:
            return False
    while any(alive(q) for q in pids) and time.time() - t0 < 30:
        time.sleep(0.05)
    check(not any(alive(q) for q in pids), "SIGKILL: every process of the job gone")
    done, vals = snapshot("kill.h5.partial")  # readable after SIGKILL
    shutil.copy("kill.h5.partial", "kill_copy.h5")
    r = run(mpi(2, exe, "-output", "kill.h5", "-seed", "2"), expect_rc=None)
    lines = [l for l in r.stdout.splitlines() if "holds an interrupted batch with other parameters (seed" in l]
    check(r.returncode != 0 and len(lines) == 1, "resume with another -seed refused with one clear message")
    with open("kill.h5.partial", "rb") as a, open("kill_copy.h5", "rb") as b:
        check(a.read() == b.read(), "the refused resume left OUT.partial untouched")
    run(mpi(2, exe, "-output", "kill.h5"))
    compare_final("ref.h5", "kill.h5", done, vals, "SIGKILL + resume at 2 ranks")

    # --- -max_walltime: clean stop at the limit, then resume at 2 ranks ---
    r = run(mpi(1, exe, "-output", "wall.h5", "-delay_per_problem", "0.01", "-max_walltime", "1.5"))
    check("stop requested (max_walltime)" in r.stdout and os.path.exists("wall.h5.partial"),
          "-max_walltime: clean stop, OUT.partial kept")
    done, vals = snapshot("wall.h5.partial")
    run(mpi(2, exe, "-output", "wall.h5", "-quiet"))
    compare_final("ref.h5", "wall.h5", done, vals, "max_walltime + resume at 2 ranks")

    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
    shutil.rmtree(tmp, ignore_errors=True)
    print("all checks passed")


if __name__ == "__main__":
    main(sys.argv[1])
