#!/usr/bin/env python3
"""lcpbench -solvers auto (the solver portfolio) against its per-solver results from the same run.

- Siconos files (../shared/data/lcp): auto solves every problem that some single solver solves; per problem the
  succeeding solver is the last one tried, the class index names a known class, at most 4 solvers tried.
- Fallback recorded: a -portfolio table whose chain starts with pgs, on lcp_CPS_2 (pgs: unsupported, a zero
  diagonal entry): tried pgs then fb_newton, fb_newton succeeded.
- Records identical at 1 and 2 ranks (every dataset but the times), auto included.
- Timing by repetition (-time_repeat, -time_batches): every record but the times identical to one timed run
  per solve, auto included; times positive and finite; the method in the /batch header; bad values refused.
- A bad -portfolio file (not HDF5, wrong format, unknown solver index, no "default" class) and -portfolio
  without auto: non-zero exit and the message exactly once, at 1 and 2 ranks.
Usage: test_lcpbench_portfolio.py LCPBENCH SICONOS_DIR
"""
import os
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

SOLVERS = ["lemke", "keller", "cottle_dantzig", "murty", "bpp", "fb_newton", "smoothed_newton", "pgs"]
failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def run(exe, *args, np_=1, quiet=True):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), exe, *map(str, args)] + (["-quiet"] if quiet else [])
    return subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)


def write_table(path, classes, chains, fmt="suite lcp portfolio 1", solvers=SOLVERS):
    with h5py.File(path, "w") as f:
        f.attrs["format"] = fmt
        f.attrs["classes"] = ", ".join(classes)
        f.attrs["solvers"] = ", ".join(solvers)
        c = -np.ones((len(chains), 4), dtype=np.int64)
        for i, ch in enumerate(chains):
            c[i, :len(ch)] = ch
        f["chain"] = c


def auto_records(path):
    with h5py.File(path, "r") as f:
        g = f["results/auto"]
        names = g.attrs["solver_names"].split(", ")
        classes = g.attrs["class_names"].split(", ")
        tried = [[names[g[f"tried_{j}"][i]] for j in range(g["tried_count"][i])] for i in range(len(g["class"]))]
        chosen = [names[s] if s >= 0 else "" for s in g["solver"][:]]
        cls = [classes[c] if c >= 0 else "" for c in g["class"][:]]
        status = {s: f[f"results/{s}/status"][:] for s in f["results"]}
    return cls, chosen, tried, status


def siconos_coverage(exe, sic, tmp):
    files = sorted(os.path.join(sic, f) for f in os.listdir(sic) if f.endswith(".dat"))
    out = os.path.join(tmp, "sic.h5")
    p = run(exe, "-file", ",".join(files), "-solvers", "auto," + ",".join(SOLVERS), "-strict", "0", "-output", out)
    check(p.returncode == 0, f"auto and the 8 solvers on {len(files)} Siconos files ran")
    cls, chosen, tried, st = auto_records(out)
    some = np.zeros(len(files), bool)
    for s in SOLVERS:
        some |= st[s] == 0
    missed = [os.path.basename(files[i]) for i in range(len(files)) if some[i] and st["auto"][i] != 0]
    check(not missed, f"auto solves all {int(some.sum())} files some single solver solves (missed: {missed})")
    check(all(c != "" for c in cls), "every file has a class")
    check(all((st["auto"][i] == 0) == (chosen[i] != "") and (not chosen[i] or tried[i][-1] == chosen[i])
              and 1 <= len(tried[i]) <= 4 for i in range(len(files))),
          "the succeeding solver is the last one tried; 1 to 4 tried")


def fallback(exe, sic, tmp):
    table = os.path.join(tmp, "pgs_first.h5")
    write_table(table, ["default"], [[SOLVERS.index("pgs"), SOLVERS.index("fb_newton")]])
    out = os.path.join(tmp, "fallback.h5")
    p = run(exe, "-file", os.path.join(sic, "lcp_CPS_2.dat"), "-solvers", "auto,pgs", "-strict", "0",
            "-portfolio", table, "-output", out)
    check(p.returncode == 0, "auto with a pgs-first -portfolio table ran")
    _, chosen, tried, st = auto_records(out)
    check(st["pgs"][0] == 4 and st["auto"][0] == 0, f"pgs alone: unsupported (status {st['pgs'][0]}); auto solved")
    check(tried[0] == ["pgs", "fb_newton"] and chosen[0] == "fb_newton", f"tried {tried[0]}, succeeded {chosen[0]}")
    check("needed more than one solver" in run(exe, "-file", os.path.join(sic, "lcp_CPS_2.dat"), "-solvers", "auto",
                                               "-portfolio", table, "-output", out, quiet=False).stdout,
          "summary line printed")


def ranks(exe, tmp):
    res = []
    for np_ in (1, 2):
        out = os.path.join(tmp, f"ranks{np_}.h5")
        p = run(exe, "-family", "random_box", "-n", "20", "-count", "30", "-cond", "1e6", "-solvers", "auto,bpp",
                "-output", out, np_=np_)
        check(p.returncode == 0, f"auto batch at {np_} rank(s) ran")
        d = {}
        with h5py.File(out, "r") as f:
            f.visititems(lambda n, o: d.__setitem__(n, o[...].tolist()) if isinstance(o, h5py.Dataset)
                         and not n.endswith("time") else None)
        res.append(d)
    diff = [k for k in res[0] if res[0][k] != res[1].get(k)]
    check(not diff and "results/auto/tried_0" in res[0], f"{len(res[0])} datasets identical at 1 and 2 ranks {diff[:3]}")


def non_time_datasets(path):
    d = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: d.__setitem__(n, o[...].tolist()) if isinstance(o, h5py.Dataset)
                     and n.startswith("results/") and not n.endswith("time") else None)
        times = np.concatenate([f[f"results/{s}/cpu_time"][:] for s in f["results"]])
        header = dict(f["batch"].attrs)
    return d, times, header


def repeated_timing(exe, tmp):
    args = ["-family", "random_box", "-n", "10", "-count", "6", "-cond", "1e2", "-solvers", "auto,bpp,pgs,lemke"]
    once, rep = os.path.join(tmp, "once.h5"), os.path.join(tmp, "rep.h5")
    p1 = run(exe, *args, "-output", once)
    p2 = run(exe, *args, "-time_repeat", "1e-4", "-time_batches", "2", "-output", rep)
    check(p1.returncode == 0 and p2.returncode == 0, "batches with one timed run and timed by repetition ran")
    d1, _, _ = non_time_datasets(once)
    d2, t2, h2 = non_time_datasets(rep)
    diff = [k for k in d1 if d1[k] != d2.get(k)]
    check(not diff and "results/auto/solver" in d1, f"{len(d1)} result datasets identical {diff[:3]}")
    check(bool(np.all(np.isfinite(t2)) and np.all(t2 > 0)), "times by repetition positive and finite")
    check(str(h2.get("time_repeat")) == "0.0001" and str(h2.get("time_batches")) == "2",
          f"timing method in the batch header ({h2.get('time_repeat')}, {h2.get('time_batches')})")
    for bad in (["-time_repeat", "-1"], ["-time_batches", "0"]):
        p = run(exe, *args, *bad, "-output", os.path.join(tmp, "bad_timing.h5"))
        check(p.returncode != 0 and "-time_repeat" in p.stdout and "-time_batches" in p.stdout,
              f"{' '.join(bad)} refused with a message")


def bad_tables(exe, tmp):
    cases = []
    junk = os.path.join(tmp, "junk.h5")
    with open(junk, "w") as f:
        f.write("not hdf5\n")
    cases.append((junk, r"is not a valid HDF5 file"))
    t = os.path.join(tmp, "fmt.h5")
    write_table(t, ["default"], [[0]], fmt="something else")
    cases.append((t, r"-portfolio .*fmt.h5: format 'something else', expected 'suite lcp portfolio 1'"))
    t = os.path.join(tmp, "index.h5")
    write_table(t, ["default"], [[0, 17]])
    cases.append((t, r"-portfolio .*index.h5: /chain\[0\]\[1\] = 17 is not a solver index"))
    t = os.path.join(tmp, "nodefault.h5")
    write_table(t, ["lcp-spd-small"], [[0]])
    cases.append((t, r"-portfolio .*nodefault.h5: no 'default' class"))
    t = os.path.join(tmp, "unknown.h5")
    write_table(t, ["default"], [[1]], solvers=["lemke", "bogus"])
    cases.append((t, r"unknown solver 'bogus' in the chain of class 'default'"))
    for np_ in (1, 2):
        for path, rx in (cases if np_ == 2 else cases[::2]):  # every case at 2 ranks, every other one at 1
            p = run(exe, "-n", "5", "-count", "2", "-solvers", "auto", "-portfolio", path,
                    "-output", os.path.join(tmp, "bad.h5"), np_=np_)
            hits = [l for l in p.stdout.splitlines() if re.search(rx, l)]
            check(p.returncode != 0 and len(hits) == 1,
                  f"np {np_}: bad table {os.path.basename(path)}: exit {p.returncode}, message x{len(hits)}")
        p = run(exe, "-n", "5", "-count", "2", "-solvers", "bpp", "-portfolio", cases[1][0],
                "-output", os.path.join(tmp, "bad.h5"), np_=np_)
        hits = [l for l in p.stdout.splitlines() if "-portfolio is only read with -solvers auto" in l]
        check(p.returncode != 0 and len(hits) == 1, f"np {np_}: -portfolio without auto refused")


def main():
    exe, sic = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        siconos_coverage(exe, sic, tmp)
        fallback(exe, sic, tmp)
        ranks(exe, tmp)
        repeated_timing(exe, tmp)
        bad_tables(exe, tmp)
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
