#!/usr/bin/env python3
"""femdyn checkpoint/restart, label reliability. Usage: test_femdyn_checkpoint.py FEMDYN NP

At NP ranks, a StVK beam under a suddenly applied tip load (full Newton, Newmark):
- periodic checkpoints, then restart from an intermediate file and from `latest`: the final displacement,
  the energy/tip histories and the snapshots equal the uninterrupted run bitwise;
- a stop request (SIGTERM to the process at NP = 1; SIGUSR1 and SIGTERM to mpiexec at NP > 1, which forwards
  them) and a -max_walltime stop each write a final checkpoint; restarting it with -restart latest reaches the
  same final state bitwise;
- a checkpoint of another mesh or other physics is refused with a clear message.
"""
import glob
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

EXE, NP = sys.argv[1], int(sys.argv[2])
# SIGTERM reaches the ranks through mpiexec, as a scheduler sends it: with Open MPI's default grace before it
# kills them (1 s; SUITE_TEST_ENV in cmake/SuiteTesting.cmake sets 0 for every test), which the ranks' clean
# stop needs.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_odls_base_sigkill_timeout="1")
CASE = ["-material", "stvk", "-beam_cells", "8,2,2", "-tip_load", 2, "-dt", 0.02, "-newton_rtol", 1e-10]
FAILS = []


def check(cond, msg):
    print(("ok   " if cond else "FAIL ") + msg, flush=True)
    if not cond:
        FAILS.append(msg)


def cmd(*args, np_=NP):
    base = [EXE] if np_ == 1 else ["mpiexec", "--oversubscribe", "-n", str(np_), EXE]
    return base + [str(a) for a in CASE + list(args)]


def run(*args, check_rc=True, np_=NP):
    p = subprocess.run(cmd(*args, np_=np_), env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       timeout=120)
    if check_rc and p.returncode != 0:
        raise AssertionError(f"{' '.join(cmd(*args, np_=np_))} failed:\n{p.stdout}")
    return p


def state(path):
    with h5py.File(path, "r") as f:
        s = f["steps"]
        hist = np.stack([s[k][:] for k in ("time", "kinetic_energy", "strain_energy", "tip_deflection",
                                               "newton_iterations", "rejected")])
        snaps = [f["snapshots"][k]["u"][:] for k in sorted(f["snapshots"].keys())] if "snapshots" in f else []
        return f["final/u"][:], hist, snaps, int(f.attrs["steps"])


def same(a, b):
    ua, ha, sa, na = a
    ub, hb, sb, nb = b
    return (na == nb and np.array_equal(ua, ub) and np.array_equal(ha, hb) and len(sa) == len(sb)
            and all(np.array_equal(x, y) for x, y in zip(sa, sb)))


def ckpt_steps(d):
    return sorted(int(re.search(r"_(\d+)\.h5$", f).group(1)) for f in glob.glob(os.path.join(d, "femdyn_*.h5")))


def main():
    with tempfile.TemporaryDirectory() as d:
        p = lambda name: os.path.join(d, name)
        # Periodic checkpoints; restart from an intermediate file and from latest.
        run("-steps", 30, "-snapshot_every", 10, "-output", p("ref.h5"), "-quiet")
        ref = state(p("ref.h5"))
        check(ref[3] == 30 and np.max(np.abs(ref[0])) > 0.1, "reference run: 30 steps, beam deflected")
        run("-steps", 30, "-snapshot_every", 10, "-checkpoint_dir", p("c1"), "-checkpoint_every", 7,
            "-checkpoint_keep", 5, "-output", p("a.h5"), "-quiet")
        have = ckpt_steps(p("c1"))
        # The time loop's rule: a final checkpoint at the end when none was written at the last step.
        check(have == [7, 14, 21, 28, 30], f"checkpoints at steps {have} (every 7, keep 5, and the final step)")
        check(same(state(p("a.h5")), ref), "a checkpointing run equals the plain run bitwise")
        run("-steps", 30, "-snapshot_every", 10, "-restart", p("c1/femdyn_0000000014.h5"), "-output", p("r14.h5"),
            "-quiet")
        check(same(state(p("r14.h5")), ref), f"restart from step 14 at {NP} rank(s): final u, histories and "
              "snapshots equal the uninterrupted run bitwise")
        run("-steps", 30, "-snapshot_every", 10, "-checkpoint_dir", p("c1"), "-restart", "latest", "-output",
            p("rl30.h5"), "-quiet")
        check(same(state(p("rl30.h5")), ref), "restart from latest (the final step 30, no step left) equals the "
              "uninterrupted run bitwise")
        os.remove(p("c1/femdyn_0000000030.h5"))
        # This run writes the final checkpoint (step 30) again: keep 5 so that step 21 stays for the next check.
        run("-steps", 30, "-snapshot_every", 10, "-checkpoint_dir", p("c1"), "-checkpoint_keep", 5, "-restart",
            "latest", "-output", p("rl.h5"), "-quiet")
        check(same(state(p("rl.h5")), ref), "restart from latest (step 28) equals the uninterrupted run bitwise")
        # The restarted state at the other rank count (the FEM state is replicated: also bitwise).
        other = 2 if NP == 1 else 1
        run("-steps", 30, "-snapshot_every", 10, "-restart", p("c1/femdyn_0000000021.h5"), "-output", p("ro.h5"),
            "-quiet", np_=other)
        u_o, u_r = state(p("ro.h5"))[0], ref[0]
        rel = np.max(np.abs(u_o - u_r)) / np.max(np.abs(u_r))
        check(rel <= 1e-12, f"restart at {other} rank(s) from a {NP}-rank checkpoint: relative difference {rel:.1e}")

        # Stop request by signal: final checkpoint, restart to the same final state.
        nlong = 200000
        sigs = [signal.SIGTERM] if NP == 1 else [signal.SIGUSR1, signal.SIGTERM]
        for sig in sigs:
            name = signal.Signals(sig).name
            cdir = p("c_" + name)
            proc = subprocess.Popen(cmd("-steps", nlong, "-checkpoint_dir", cdir, "-checkpoint_every", 100,
                                        "-output", p("sig.h5")), env=ENV, stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, text=True)
            t0 = time.time()
            while not ckpt_steps(cdir) and time.time() - t0 < 60 and proc.poll() is None:
                time.sleep(0.05)
            proc.send_signal(sig)
            out, _ = proc.communicate(timeout=60)
            m = re.findall(r"stopping at step (\d+)", out)
            # mpiexec itself exits non-zero after forwarding SIGTERM; the ranks stop cleanly all the same.
            rc_ok = proc.returncode == 0 or (NP > 1 and sig == signal.SIGTERM)
            check(rc_ok and len(m) == 1, f"{name}: clean stop (rc {proc.returncode}), one stop message ({len(m)})")
            kstop = int(m[0]) if m else -1
            check(ckpt_steps(cdir)[-1:] == [kstop], f"{name}: final checkpoint written at the stop step {kstop}")
            nfinal = kstop + 10
            run("-steps", nfinal, "-output", p("sigref.h5"), "-quiet")
            run("-steps", nfinal, "-checkpoint_dir", cdir, "-restart", "latest", "-output", p("sigres.h5"), "-quiet")
            check(same(state(p("sigres.h5")), state(p("sigref.h5"))),
                  f"{name}: stopped at step {kstop} and restarted to {nfinal}: equals the uninterrupted run bitwise")

        # -max_walltime stop.
        out = run("-steps", nlong, "-checkpoint_dir", p("c3"), "-max_walltime", 1.0, "-output", p("w.h5")).stdout
        m = re.findall(r"stopping at step (\d+) \(max_walltime\)", out)
        check(len(m) == 1 and ckpt_steps(p("c3")) == [int(m[0])] if m else False,
              f"-max_walltime: stopped once, final checkpoint at that step ({m})")

        # Haptic probe: the probe force histories (full model, local model, 1 kHz output) survive a restart.
        probe = ["-probe", "-probe_stiffness", 100, "-steps", 20]
        run(*probe, "-output", p("pref.h5"), "-quiet")
        # Checkpoints at steps 8, 16 and the final step 20: keep 3 so that step 8 stays.
        run(*probe, "-checkpoint_dir", p("cp"), "-checkpoint_every", 8, "-checkpoint_keep", 3, "-output", p("pa.h5"),
            "-quiet")
        run(*probe, "-checkpoint_dir", p("cp"), "-restart", p("cp/femdyn_0000000008.h5"), "-output", p("pr.h5"),
            "-quiet")

        def probe_hist(path):
            with h5py.File(path, "r") as f:
                return [f["probe"][k][:] for k in ("sync_time", "force_full", "force_predicted", "haptic_force")]

        a, b = probe_hist(p("pref.h5")), probe_hist(p("pr.h5"))
        check(same(state(p("pr.h5")), state(p("pref.h5"))) and all(np.array_equal(x, y) for x, y in zip(a, b))
              and len(b[3]) == 400, "probe run restarted at step 8: state and probe histories equal bitwise")

        # Tangent predictor (-newton_predictor tangent) and lagged tangent (-jacobian lagged): the factorisation
        # they reuse is part of the state (point and dt of the last factorised tangent); a restart refactorises
        # it and continues bitwise, with and without the probe (whose penalty enters that tangent).
        for mode in (["-newton_predictor", "tangent"], ["-jacobian", "lagged"]):
            for extra in ([], ["-probe", "-probe_stiffness", 100]):
                tp = [*mode, "-steps", 20, *extra]
                label = f"{' '.join(mode)} {'probe run' if extra else 'run'}"
                run(*tp, "-output", p("tref.h5"), "-quiet")
                cdir = p(f"ct_{mode[1]}{'_probe' if extra else ''}")
                run(*tp, "-checkpoint_dir", cdir, "-checkpoint_every", 8, "-checkpoint_keep", 3, "-output",
                    p("ta.h5"), "-quiet")
                run(*tp, "-restart", os.path.join(cdir, "femdyn_0000000008.h5"), "-output", p("tr.h5"), "-quiet")
                ref_t = state(p("tref.h5"))
                with h5py.File(os.path.join(cdir, "femdyn_0000000008.h5"), "r") as f:
                    has = "u_tangent" in f["fields"] and "dt_tangent" in f["fields"]
                check(has and same(state(p("ta.h5")), ref_t) and same(state(p("tr.h5")), ref_t),
                      f"{label} restarted at step 8: equals the uninterrupted run bitwise")

        # Refusals: another mesh, other physics.
        for args, pattern in ((["-beam_cells", "9,2,2"], r"restart .*grid"),
                              (["-young", "2000"], r"restart .*written with scheme"),
                              (["-newton_predictor", "tangent"], r"restart .*written with scheme"),
                              (["-jacobian", "lagged"], r"restart .*written with scheme")):
            q = run("-steps", 30, "-restart", p("c1/femdyn_0000000014.h5"), "-output", p("bad.h5"), *args,
                    check_rc=False)
            check(q.returncode != 0 and len(re.findall(pattern, q.stdout)) == 1,
                  f"restart with {' '.join(args)} refused with one clear message")
    print(f"{len(FAILS)} failure(s)")
    return 1 if FAILS else 0


if __name__ == "__main__":
    sys.exit(main())
