#!/usr/bin/env python3
"""euler -target_error: the chooser's achieved error against the exact solution is <= the target
on Sod, the density wave and the 2D isentropic vortex for two targets a decade apart (the vortex in 3D for one),
the /model_choice group is complete, and a 2-rank run given the 1-rank run's cost model (-cost_model) takes the
same choice. Each case runs in a few seconds.

A scheme whose run fails on the problem is left out (failing_scheme).

A target the final run misses is a clear error naming the limit reached and the output (missed).

Usage: euler_target_check.py sod|density_wave|vortex|vortex_3d|walltime|ranks|failing_scheme|missed
"""
import os
import re
import sys
import tempfile

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from euler_harness import check, error, run  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

ATTRS = ["families", "target_error", "chosen_family", "chosen_label", "chosen_n", "chosen_predicted_error", "chosen_predicted_cost",
         "estimated_error", "target_met", "pilot_seconds", "check_seconds", "final_seconds", "total_seconds",
         "most_accurate_label", "most_accurate_predicted_cost", "most_accurate_predicted_error", "summary"]
COLUMNS = {"candidates": ["family", "n", "predicted_cost", "predicted_error"],
           "pilots": ["family", "n", "seconds", "difference", "estimate"],
           "finals": ["family", "n", "seconds", "difference", "estimate"],
           "checks": ["family", "n", "seconds", "difference"]}


def check_group(path, target):
    with h5py.File(path, "r") as f:
        g = f["model_choice"]
        missing = [a for a in ATTRS if a not in g.attrs]
        missing += [f"{t}/{c}" for t, cols in COLUMNS.items() for c in cols if f"{t}/{c}" not in g]
        check(not missing, f"/model_choice complete (missing: {missing})")
        fams = g.attrs["families"].split(",")
        per = [int((g["pilots/family"][:] == i).sum()) for i in range(len(fams))]
        probes = [int(((g["timings/family"][:] == i) & (g["timings/n"][:] == g["pilots/n"][:].min())).sum())
                  for i in range(len(fams))]
        chosen = int(g.attrs["chosen_family"])
        probe = 0 if g.attrs["cost_model"] != "pilots" else 1  # a loaded cost model (-cost_model): no probes
        check(all(0 <= k <= 3 for k in per) and per[chosen] == 3 and all(k == probe for k in probes),
              f"pilots per family {per}, probes at n0 {probes}: a probe of every family ({probe}: "
              f"cost model {g.attrs['cost_model']}), the chosen one ({fams[chosen]}) piloted at n0, 2 n0, 4 n0 "
              f"(a family left out before its pilots has none)")
        full = [i for i, k in enumerate(per) if k == 3]  # families piloted to 4 n0: costed and estimated
        rows = [i for i, fam in enumerate(g["candidates/family"][:]) if fam in full]
        cost, err = g["candidates/predicted_cost"][:], g["candidates/predicted_error"][:]
        check(rows and all(cost[i] > 0 and err[i] > 0 for i in rows), "candidate table costed and estimated")
        check(g.attrs["target_met"] == 1 and g.attrs["estimated_error"] <= target,
              f"estimated error {g.attrs['estimated_error']:.3e} <= target {target:g}")
        achieved = f.attrs["error_l1_rho"] if "error_l1_rho" in f.attrs else f["errors"].attrs["l1_rho"]
        return g.attrs["chosen_label"], achieved


def target_case(problem, targets, extra=()):
    with tempfile.TemporaryDirectory() as tmp:
        for e in targets:
            out = os.path.join(tmp, f"{problem}.h5")
            log = run([*extra[:2], "-problem", problem, "-target_error", e, "-error", "-output", out, "-quiet", *extra[2:]])
            check("model_choice: target error" in log, "one-line summary printed")
            label, achieved = check_group(out, e)
            check(abs(achieved - error(log)) <= 1e-6 * achieved, "the output's error is the final run's")
            check(achieved <= e, f"{problem}: achieved L1 error {achieved:.3e} <= target {e:g} ({label})")


def sod():
    target_case("sod", [5e-3, 5e-4], ["-dim", 1])


def density_wave():
    target_case("density_wave", [1e-6, 1e-7], ["-dim", 1])


def walltime():
    """-target_walltime S: the chosen candidate is the most accurate one of the table whose predicted cost fits in
    what the pilots left of S (a check of the choice against its own table, not of timings)."""
    # S leaves the pilots room on slow builds too (ASan: SUITE_TIMEOUT_SCALE 3; its pilots take 0.64 s), and
    # -target_max_n bounds the final run whatever S.
    s = 2.0 * float(os.environ.get("SUITE_TIMEOUT_SCALE", "1"))
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "w.h5")
        log = run(["-problem", "sod", "-target_walltime", s, "-target_max_n", 1024, "-error", "-output", out,
                   "-quiet"])
        check(f"model_choice: target error 0, walltime {s:g} s" in log, "summary names the walltime target")
        with h5py.File(out, "r") as f:
            g = f["model_choice"]
            left = s - g.attrs["pilot_seconds"]
            cost, err = g["candidates/predicted_cost"][:], g["candidates/predicted_error"][:]
            fits = cost <= left
            chosen = g.attrs["chosen_predicted_error"]
            check(g.attrs["chosen_predicted_cost"] <= left, f"chosen fits in the {left:.3g} s left")
            check(chosen == err[fits].min(), f"chosen is the most accurate that fits ({chosen:.3e})")


def vortex():
    """2D: the isentropic vortex to t = 0.5, weno5 and muscl2 up to 128 x 128."""
    target_case("isentropic_vortex", [1e-4, 1e-5],
                ["-dim", 2, "-t_final", 0.5, "-target_schemes", "weno5,muscl2", "-target_max_n", 128])


def vortex_3d():
    """3D: the isentropic vortex extruded along z (the 2D errors), weno5 and muscl2 up to 64 cells across."""
    target_case("isentropic_vortex", [1e-4],
                ["-dim", 3, "-t_final", 0.5, "-target_schemes", "weno5,muscl2", "-target_max_n", 64])


def failing_scheme():
    """LeBlanc without the positivity limiter: enopade6 stops at step 1 (negative pressure), muscl2 runs. The
    1-rank target run leaves enopade6 out (its failed probe recorded) and meets the target with muscl2. The
    2-rank run loads its cost model from the 1-rank file, which has no complete run of enopade6: it leaves
    enopade6 out without running it, names the reason, and makes the same choice."""
    deck = os.path.join(ROOT, "inputs", "euler", "extreme_leblanc.yaml")
    with tempfile.TemporaryDirectory() as tmp:
        for np_ in (1, 2):
            out = os.path.join(tmp, f"leblanc_np{np_}.h5")
            cost_file = os.path.join(tmp, "leblanc_np1.h5")
            cost = ["-cost_model", cost_file] if np_ == 2 else []
            log = run(["-options_file", deck, "-positivity", "false", "-target_error", 2e-2, "-target_schemes",
                       "enopade6,muscl2", "-output", out, "-quiet", *cost], np_=np_)
            why = ("enopade6 left out: its run at N = 32" if np_ == 1 else
                   f"enopade6 left out: -cost_model {cost_file} has no complete runs of enopade6")
            check(why in log, f"the summary says why enopade6 is left out ({why})")
            label, achieved = check_group(out, 2e-2)
            check(label.startswith("muscl2") and achieved <= 2e-2,
                  f"{np_} rank(s): chose {label}, achieved {achieved:.3e} <= 2e-2")
            with h5py.File(out, "r") as f:
                g = f["model_choice"]
                failed = [(int(a), int(n)) for t in ("pilots", "timings") for a, n, x in
                          zip(g[f"{t}/family"][:], g[f"{t}/n"][:], g[f"{t}/failed"][:]) if x]
                ran = [int(a) for t in ("pilots", "timings", "finals") for a in g[f"{t}/family"][:]]
                # 1 rank: enopade6's probe (a timing run at n0) fails; 2 ranks: enopade6 never runs
                expect = [(0, 32)] if np_ == 1 else []
                check(failed == expect and (np_ == 1 or 0 not in ran),
                      f"failed runs (family, n) {failed}, families run {sorted(set(ran))}: {expect}")
                check(("invalid " in g.attrs["failure_enopade6"]) == (np_ == 1) and
                      g.attrs["failure_muscl2"] == "", "failure attributes")


def missed():
    """A target the final run misses, escalations used up (Toro 123, muscl2 alone, safety 1: n = 256 is predicted
    at 2.7e-3 and estimated at 5.1e-3 afterwards) or no finer candidate (-target_max_n 256; also with 300, whose
    ladder ends at 256): a non-zero exit, the error names the limit reached and the output file, which holds the
    run with /model_choice (not met), at 1 and 2 ranks."""
    base = ["-problem", "toro123", "-target_schemes", "muscl2", "-target_error", 3e-3, "-target_safety", 1, "-quiet"]
    with tempfile.TemporaryDirectory() as tmp:
        for np_, extra, why in ((1, ["-target_escalations", 0], "-target_escalations 0 used up"),
                                (2, ["-target_escalations", 0], "-target_escalations 0 used up"),
                                (1, ["-target_max_n", 256], "no finer candidate within -target_max_n 256"),
                                (1, ["-target_max_n", 300], "no finer candidate within -target_max_n 300")):
            out = os.path.join(tmp, f"missed_np{np_}_{extra[1]}.h5")
            log, code = run([*base, *extra, "-output", out], np_=np_, expect_ok=False, with_code=True)
            check(code != 0, f"{np_} rank(s), {extra}: non-zero exit ({code})")
            msg = (f"-target_error 0.003 missed: the final run's estimated error is {{e}} after 0 escalations "
                   f"(muscl2 n=256): {why}; best reachable is about that; that run's output, with /model_choice, "
                   f"is in {out}")
            m = re.search(re.escape(msg).replace(re.escape("{e}"), r"([0-9.e+-]+)"), log)
            check(m is not None and float(m.group(1)) > 3e-3, f"the error names the estimate and why: {why}")
            with h5py.File(out, "r") as f:
                g = f["model_choice"]
                check(g.attrs["target_met"] == 0 and abs(g.attrs["estimated_error"] - float(m.group(1))) <=
                      1e-3 * float(m.group(1)) and f["final/rho"].shape == (256,),
                      "the output holds the 256-cell run and /model_choice with the miss")


def ranks():
    with tempfile.TemporaryDirectory() as tmp:
        one, two = os.path.join(tmp, "one.h5"), os.path.join(tmp, "two.h5")
        args = ["-problem", "sod", "-target_error", 2e-3, "-error", "-quiet"]
        run(args + ["-output", one])
        run(args + ["-output", two, "-cost_model", one], np_=2)
        a, ea = check_group(one, 2e-3)
        b, eb = check_group(two, 2e-3)
        check(a == b, f"1 rank chose {a}, 2 ranks (same cost model) chose {b}")
        check(abs(ea - eb) <= 1e-12 * ea, f"achieved errors {ea:.15e} and {eb:.15e} agree")


if __name__ == "__main__":
    globals()[sys.argv[1]]()
