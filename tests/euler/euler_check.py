#!/usr/bin/env python3
"""Regression checks of the 1D Euler app: runs bin/euler (under mpiexec) and asserts the numbers it prints.

Standard library only. SUITE_BIN points at the build's bin/ (set by ctest). Usage: euler_check.py CHECK
"""
import math
import os
import re
import subprocess
import sys
import tempfile

from euler_harness import BIN, MPIEXEC, SLOW_BUILD, check, error, run

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from process_wait import read_until_stepping  # noqa: E402 (tests/process_wait.py)



def density_wave_order():
    """Pade core: L1 order >= 5.8 on density_wave, N = 20..160, RK4 with dt ~ dx^1.5 (time error negligible)."""
    errs = []
    ns = [20, 40, 80, 160]
    for n in ns:
        dx = 2.0 / n
        dt = 0.25 * dx ** 1.5
        out = run(["-problem", "density_wave", "-nx", n, "-time", "rk4", "-dt", dt, "-t_final", 0.5, "-error",
                   "-quiet"])
        errs.append(error(out))
    orders = [math.log2(errs[i - 1] / errs[i]) for i in range(1, len(errs))]
    print("errors", errs, "orders", orders)
    check(min(orders) >= 5.8, f"ENO-Pade (Pade core) L1 orders {orders} >= 5.8")


def sod():
    """Sod N=200, enopade6 at its default CFL: L1(rho) against the exact solution, measured 1.781e-3; bound +2%
    (the run is deterministic: the margin is for another platform's libm and compiler, and a change that costs
    2% of the accuracy fails)."""
    out = run(["-problem", "sod", "-nx", 200, "-t_final", 0.2, "-error", "-quiet"])
    e = error(out)
    check(e <= 1.82e-3, f"Sod N=200 enopade6 L1(rho) = {e:.4e} <= 1.82e-3")


def hypar():
    """L1(rho) at HyPar's settings (cell-centred grid, fixed dt, SSP-RK3; Sod dt = 1e-3, t = 0.2;
    Lax dt = 5e-4, t = 0.13; N = 200) against HyPar's figures (CRWENO5 with rf-char upwinding: Sod 1.86e-3, Lax
    7.28e-3; WENO5: Sod 2.39e-3). Measured here (scripts/bench/euler-hypar-compare; rf-char, the default of every
    scheme): crweno5 1.899e-3 / 7.478e-3, weno5 2.216e-3 / 7.809e-3, enopade6 1.765e-3 / 6.263e-3: enopade6 below
    HyPar's CRWENO5 on both tubes, crweno5 2-3% above it. Bounds: every measured value + ~2% (deterministic
    runs: the margin is for another platform's libm and compiler; a change that costs 2% of the accuracy fails).
    Also asserted: rf-char beats Lax-Friedrichs splitting for crweno5 and weno5 on both tubes."""
    cases = [("sod", 1e-3, 0.2), ("lax", 5e-4, 0.13)]
    bounds = {("crweno5", "sod"): 1.94e-3, ("crweno5", "lax"): 7.63e-3, ("weno5", "sod"): 2.26e-3,
              ("weno5", "lax"): 7.97e-3, ("enopade6", "sod"): 1.80e-3, ("enopade6", "lax"): 6.39e-3}
    for (scheme, problem), bound in bounds.items():
        dt, tf = next((c[1], c[2]) for c in cases if c[0] == problem)
        base = ["-problem", problem, "-nx", 200, "-dt", dt, "-t_final", tf, "-scheme", scheme, "-error", "-quiet"]
        e = error(run(base))
        check(e <= bound, f"{problem} N=200 fixed dt {scheme}: L1(rho) {e:.4e} <= {bound}")
        if scheme != "enopade6":
            e_llf = error(run(base + ["-upwinding", "llf"]))
            check(e < 0.9 * e_llf, f"{problem} {scheme}: rf-char {e:.4e} < 0.9 x Lax-Friedrichs {e_llf:.4e}")


def shu_osher():
    """Shu-Osher N=400 (enopade6) against an N=6400 WENO5 reference, a self-generated reference: the same app's
    WENO5 (`mpiexec -n 2 build/bin/euler -problem shu_osher -nx 6400 -scheme weno5 -output ref.h5` regenerates
    it; the problem has no exact solution). With SUITE_REFERENCE_DIR set (scripts/test sets it, emptied, for both of its stages) it is computed once
    per test run and reused, so the ASan+UBSan stage checks its own N=400 run against the Release stage's
    reference instead of recomputing it under the sanitizers (> 10 CPU-minutes). The app writes the file under a
    temporary name and renames it when complete, so a partial reference is never taken for a finished one."""
    with tempfile.TemporaryDirectory() as d:
        ref = os.path.join(os.environ.get("SUITE_REFERENCE_DIR") or d, "shu_osher_weno5_6400.h5")
        if not os.path.exists(ref):
            run(["-problem", "shu_osher", "-nx", 6400, "-scheme", "weno5", "-output", ref, "-quiet"], np_=2)
        out = run(["-problem", "shu_osher", "-nx", 400, "-reference", ref, "-error", "-quiet"])
        e = error(out)
        # measured 1.0325e-2; bound +2.5% (deterministic runs: another platform's libm and compiler)
        check(e <= 1.06e-2, f"Shu-Osher N=400 enopade6 vs N=6400 reference: L1(rho) = {e:.4e} <= 1.06e-2")


def conservation():
    for scheme, problem in [("enopade6", "pulse"), ("crweno5", "density_wave"), ("weno5", "pulse"),
                            ("muscl2", "pulse")]:
        out = run(["-problem", problem, "-scheme", scheme, "-nx", 200, "-max_steps", 200])
        for q in ("mass", "momentum", "energy"):
            m = re.search(rf"conservation {q}: .* rel_change (\S+)", out)
            v = float(m.group(1))
            check(v <= 1e-13, f"{scheme}/{problem}: relative change of total {q} {v:.3e} <= 1e-13")


# 1D lines split over ranks are solved in place by substructuring: exact in exact arithmetic, so the rank count
# changes round-off only, which the nonlinear weights of the compact WENO rows amplify over the 60 steps (measured:
# up to 1.14e-12 for sod/enopade6 at 3 ranks, whose shocked lines hold such rows on every row).
ROUNDOFF = 1e-11


def ranks():
    with tempfile.TemporaryDirectory() as d:
        # rf-char upwinding (crweno5, weno5 by default; enopade6 on request): the face pick after the compact
        # solves at the face shared with the next rank (sod/crweno5, sod/enopade6 rf-char).
        for problem, scheme, extra in [("sod", "enopade6", []), ("density_wave", "crweno5", []),
                                       ("blast", "weno5", []), ("sod", "crweno5", []),
                                       ("sod", "enopade6", ["-upwinding", "rf-char"])]:
            one = os.path.join(d, f"{problem}1.h5" if not extra and scheme == "enopade6" else
                               f"{problem}_{scheme}{len(extra)}_1.h5")
            run(["-problem", problem, "-scheme", scheme, "-nx", 120, "-max_steps", 60, "-output", one, "-quiet"]
                + extra)
            out = run(["-problem", problem, "-scheme", scheme, "-nx", 120, "-max_steps", 60, "-reference", one,
                       "-error", "-quiet"] + extra, np_=2)
            m = re.search(r"reference max relative difference (\S+)", out)
            v = float(m.group(1))
            check(v <= ROUNDOFF, f"{problem}/{scheme} {' '.join(extra)}: 1 vs 2 ranks max relative difference "
                  f"{v:.3e} <= {ROUNDOFF}")
        # 3 ranks, and the substructured solve against the gathered one at 2 ranks.
        for np_, extra in [(3, []), (2, ["-line_solve", "gather"])]:
            out = run(["-problem", "sod", "-nx", 120, "-max_steps", 60, "-reference", os.path.join(d, "sod1.h5"),
                       "-error", "-quiet"] + extra, np_=np_)
            v = float(re.search(r"reference max relative difference (\S+)", out).group(1))
            check(v <= ROUNDOFF, f"sod/enopade6 {np_} ranks {' '.join(extra)}: max relative difference {v:.3e}")


def implicit():
    """Implicit BDF2 (JFNK) through Sod's shock with every scheme: Newton failures are retried at half dt."""
    for scheme, nx, bound in [("muscl2", 200, 3.5e-3), ("weno5", 200, 4.0e-3), ("enopade6", 100, 7.0e-3)]:
        out = run(["-problem", "sod", "-nx", nx, "-scheme", scheme, "-time", "bdf2", "-cfl", 1, "-error"])
        e = error(out)
        check(e <= bound, f"{scheme} BDF2 CFL 1 Sod N={nx}: L1(rho) {e:.3e} <= {bound}")


def restart():
    """Checkpoint/restart: a run stopped part-way (max_steps, SIGTERM) and restarted from its
    latest checkpoint ends bitwise equal to an uninterrupted run at the same rank count and within 1e-12 at
    another; a checkpoint of other numerics or a corrupted one is refused with one message."""
    import signal
    import time
    base = ["-problem", "shu_osher", "-nx", 400, "-t_final", 0.5]
    with tempfile.TemporaryDirectory() as d:
        full = {n: os.path.join(d, f"full{n}.h5") for n in (1, 2)}
        for n in (1, 2):
            run(base + ["-output", full[n], "-quiet"], np_=n)

        def restart_diff(ck, np_):
            """Restart at np_ ranks from ck's checkpoint of step 100; max relative difference to full[np_]."""
            out = run(base + ["-checkpoint_dir", ck, "-restart", "latest", "-reference", full[np_], "-error"],
                      np_=np_)
            check("at step 100," in out, f"restart at {np_} rank(s) read the checkpoint of step 100")
            return float(re.search(r"reference max relative difference (\S+)", out).group(1))

        ck = os.path.join(d, "ck")
        run(base + ["-checkpoint_dir", ck, "-checkpoint_every", 40, "-max_steps", 100, "-quiet"], np_=2)
        v = restart_diff(ck, 2)
        check(v == 0.0, f"stopped at step 100 (2 ranks), restarted at 2 ranks: max relative difference {v:.3e} == 0")
        ck_b = os.path.join(d, "ck_b")  # its own folder: ck holds the finished run's checkpoint of step 236
        run(base + ["-checkpoint_dir", ck_b, "-checkpoint_every", 40, "-max_steps", 100, "-quiet"], np_=2)
        v = restart_diff(ck_b, 1)
        check(v <= 1e-12, f"stopped at 2 ranks, restarted at 1 rank: max relative difference {v:.3e} <= 1e-12")

        # SIGTERM part-way: a final checkpoint at the step reached, then a bitwise restart.
        ck2 = os.path.join(d, "ck2")
        # Long enough to be stepping when the signal comes, 0.3 s after the first step: N = 4000 to t = 0.06,
        # ~280 steps, 1.7 s on one core (N = 2000 under the sanitizers: a quarter of the work at their ~4x cost
        # per cell-step, so the same wall time).
        big = base + ["-nx", 2000 if SLOW_BUILD else 4000, "-t_final", 0.06]
        cmd = [os.path.join(BIN, "euler")] + [str(a) for a in big + ["-checkpoint_dir", ck2]]  # singleton MPI
        p = subprocess.Popen(cmd + ["-progress_interval", "0.05"], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True)
        head = read_until_stepping(p)  # signal once the run is stepping, not after a fixed sleep
        time.sleep(0.3)
        p.send_signal(signal.SIGTERM)
        out, _ = p.communicate(timeout=120)
        out = head + out
        print(out)
        m = re.search(r"stopping at step (\d+)", out)
        check(p.returncode == 0 and m is not None, f"SIGTERM: clean stop (exit {p.returncode})")
        check(os.path.exists(os.path.join(ck2, f"euler_{int(m.group(1)):010d}.h5")), "SIGTERM: final checkpoint")
        ref = os.path.join(d, "big.h5")
        run(big + ["-output", ref, "-quiet"])
        out = run(big + ["-checkpoint_dir", ck2, "-restart", "latest", "-reference", ref, "-error"])
        v = float(re.search(r"reference max relative difference (\S+)", out).group(1))
        check(v == 0.0, f"SIGTERM at step {m.group(1)} + restart: max relative difference {v:.3e} == 0")

        # A job killed inside a checkpoint write (fault injection: abort after the data, before the rename,
        # at step 3 of a run checkpointing every step): checkpoint 2 stays complete and loads, the partial
        # .tmp of step 3 is never picked, and the restart ends bitwise equal to the uninterrupted run.
        ck3 = os.path.join(d, "ck3")
        env = dict(os.environ, SUITE_FAULT_ABORT_IN_CHECKPOINT="3")
        p = subprocess.run([MPIEXEC, "--oversubscribe", "-n", "2", os.path.join(BIN, "euler")] + [str(a) for a in base + [
            "-checkpoint_dir", ck3, "-checkpoint_every", 1, "-checkpoint_keep", 5, "-quiet"]], env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
        names = sorted(os.listdir(ck3))
        check(p.returncode != 0 and "euler_0000000003.h5.tmp" in names and "euler_0000000002.h5" in names,
              f"killed inside the write of checkpoint 3: exit {p.returncode}, files {names}")
        out = run(base + ["-checkpoint_dir", ck3, "-restart", "latest", "-reference", full[2], "-error"], np_=2)
        check(f"restarted from {os.path.join(ck3, 'euler_0000000002.h5')} at step 2" in out,
              "restart picked the last complete checkpoint (step 2), not the partial one")
        v = float(re.search(r"reference max relative difference (\S+)", out).group(1))
        check(v == 0.0, f"after the kill mid-write: max relative difference {v:.3e} == 0")

        # Refusals: other numerics, a flipped byte.
        latest = sorted(f for f in os.listdir(ck) if f.endswith(".h5"))[-1]
        path = os.path.join(ck, latest)
        for extra, pattern in [(["-scheme", "weno5"], "scheme"), (["-filter_alpha", 0.45], "scheme"),
                               (["-nx", 200], "grid")]:
            p = subprocess.run([MPIEXEC, "--oversubscribe", "-n", "2", os.path.join(BIN, "euler")] +
                               [str(a) for a in base + extra + ["-restart", path]],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
            lines = [ln for ln in p.stdout.splitlines() if ln.startswith("ERROR")]
            check(p.returncode != 0 and len(lines) == 1 and pattern in lines[0],
                  f"restart with {' '.join(map(str, extra))} refused once: {lines}")
        # A checkpoint whose tag names no dimension (no dim=/axis=): refused with a message that says so.
        import h5py
        old = os.path.join(d, "old_1d.h5")
        with open(path, "rb") as src, open(old, "wb") as dst:
            dst.write(src.read())
        with h5py.File(old, "r+") as f:
            tag = f["/checkpoint"].attrs["scheme"]
            tag = tag.decode() if isinstance(tag, bytes) else str(tag)
            f["/checkpoint"].attrs["scheme"] = tag.replace("dim=1:axis=x:", "")
        p = subprocess.run([MPIEXEC, "--oversubscribe", "-n", "2", os.path.join(BIN, "euler")] +
                           [str(a) for a in base + ["-restart", old]],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        lines = [ln for ln in p.stdout.splitlines() if ln.startswith("ERROR")]
        check(p.returncode != 0 and len(lines) == 1 and "names no dimension" in lines[0],
              f"checkpoint whose tag names no dimension refused once, saying so: {lines}")
        data = bytearray(open(path, "rb").read())
        data[len(data) // 2] ^= 0xFF
        bad = os.path.join(d, "bad.h5")
        open(bad, "wb").write(bytes(data))
        p = subprocess.run([MPIEXEC, "--oversubscribe", "-n", "2", os.path.join(BIN, "euler")] +
                           [str(a) for a in base + ["-restart", bad]],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
        lines = [ln for ln in p.stdout.splitlines() if ln.startswith("ERROR")]
        check(p.returncode != 0 and len(lines) == 1, f"corrupted checkpoint refused once: {lines}")


def extreme():
    """Extreme inputs that must complete with a verified answer (exact Riemann solutions)."""
    cases = [
        # Mach ~200 shock: the blast wave's states as one Riemann problem (pressure ratio 1e5).
        ("Mach ~200 shock", ["-problem", "riemann", "-p_l", 1000, "-p_r", 0.01, "-rho_l", 1, "-rho_r", 1,
                             "-t_final", 0.012, "-nx", 400], 3.5e-2),
        ("near vacuum", ["-problem", "riemann", "-rho_l", 1, "-p_l", 1, "-rho_r", 1e-3, "-p_r", 1e-10,
                         "-nx", 400, "-t_final", 0.15], 2.0e-3),
        ("gamma 1 + 1e-7", ["-problem", "sod", "-gamma", 1.0000001, "-nx", 400], 2.5e-3),
        ("smallest grid nx = 6", ["-problem", "sod", "-nx", 6], 6.0e-2),
    ]
    for name, args, bound in cases:
        e = error(run(args + ["-error"]))
        check(e <= bound, f"{name}: completed, L1(rho) against the exact solution {e:.3e} <= {bound}")


def disk_full():
    """A disk that fills during the run (a 1.2 MB tmpfs; needs root, as CI is): one clear message, non-zero
    exit on every rank, no crash, no partial file, and the previous good output left intact."""
    with tempfile.TemporaryDirectory() as d:
        mnt = os.path.join(d, "small")
        os.mkdir(mnt)
        m = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1200k", "tmpfs", mnt], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
        check(m.returncode == 0, f"mounted a 1.2 MB tmpfs (needs root): {m.stdout.strip()}")
        try:
            out = os.path.join(mnt, "o.h5")
            run(["-problem", "sod", "-nx", 200, "-output", out, "-quiet"])
            good = open(out, "rb").read()
            files = sorted(os.listdir(mnt))  # o.h5 and its XDMF sidecar
            for np_ in (1, 2):
                p = subprocess.run([MPIEXEC, "--oversubscribe", "-n", str(np_), os.path.join(BIN, "euler"), "-problem",
                                    "sod", "-nx", "20000", "-snapshot_every", "5", "-max_steps", "40", "-output", out],
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
                print(p.stdout)
                errors = [ln for ln in p.stdout.splitlines() if ln.startswith("ERROR")]
                check(p.returncode != 0 and len(errors) == 1 and "disk full" in errors[0],
                      f"{np_} rank(s): disk full mid-run reported once: {errors}")
                check("Segmentation" not in p.stdout and "signal" not in p.stdout, f"{np_} rank(s): no crash")
                check(sorted(os.listdir(mnt)) == files, f"{np_} rank(s): no partial file left: {os.listdir(mnt)}")
                check(open(out, "rb").read() == good, f"{np_} rank(s): previous output intact")
        finally:
            subprocess.run(["umount", mnt])


def positivity():
    """Near-vacuum and strong-blast tubes (Toro's 123 problem to t = 0.15, Woodward-Colella's blast to 0.038, a
    1e-10 pressure ratio to 0.15) at N = 400, enopade6 and weno5: every run reaches t_final with status completed
    (the app stops with an error if rho or p ever drops to <= 0) and its final rho and p are finite and > 0."""
    import h5py
    import numpy as np
    cases = [(["-problem", "toro123"], 0.15), (["-problem", "blast"], 0.038),
             (["-problem", "riemann", "-rho_l", 1, "-p_l", 1, "-rho_r", 1e-3, "-p_r", 1e-10], 0.15)]
    with tempfile.TemporaryDirectory() as d:
        for scheme in ("enopade6", "weno5"):
            for c, tf in cases:
                path = os.path.join(d, "p.h5")
                run(c + ["-nx", 400, "-t_final", tf, "-scheme", scheme, "-output", path, "-quiet"])
                with h5py.File(path, "r") as f:
                    t, status = float(f.attrs["time"]), f.attrs["status"]
                    rho, p = f["/final/rho"][...], f["/final/p"][...]
                ok = np.all(np.isfinite(rho)) and np.all(np.isfinite(p)) and rho.min() > 0 and p.min() > 0
                check(abs(t - tf) <= 1e-12 * tf and status in ("completed", b"completed") and ok,
                      f"{scheme} {' '.join(map(str, c))}: t = {t:.15g} (t_final {tf}), {status}, min rho "
                      f"{rho.min():.3e}, min p {p.min():.3e}")


if __name__ == "__main__":
    globals()[sys.argv[1]]()
