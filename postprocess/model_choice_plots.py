"""The accuracy-target run's choice: ``python -m postprocess model-choice run.h5`` draws every
candidate of /model_choice (lib/model_choice/choice_output.hpp) as predicted L1 error against predicted cost,
one line per family (scheme; a family whose run failed is named as left out), the target, the chosen candidate,
the final run's estimated error (at its measured cost) and, when the run had -error, the error against the exact
solution (default figure model_choice.png).
``python -m postprocess model-choice-bench targets.csv`` draws scripts/bench/euler-target-error's table: the
achieved error against the target per problem, with the lines E and E/4 (default figure target_error.png).
Both take -o FILE and --outdir DIR (postprocess/cli.py).
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

import h5py
import numpy as np

from .cli import add_output_options, figure_command, figure_file


def read_choice(path):
    """The /model_choice group as plain Python: families, candidate table, pilots, finals, attributes."""
    with h5py.File(path, "r") as f:
        if "model_choice" not in f:
            raise KeyError(f"{path}: no /model_choice group (not a -target_error / -target_walltime run)")
        g = f["model_choice"]
        attrs = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in g.attrs.items()}
        out = {"attrs": attrs, "families": str(attrs["families"]).split(",")}
        for t in ("candidates", "pilots", "finals"):
            out[t] = {k: np.asarray(g[t][k][:]) for k in g[t]}
        exact = f.attrs.get("error_l1_rho", (f["errors"].attrs.get("l1_rho") if "errors" in f else None))
        out["exact_error"] = float(exact) if exact is not None else math.nan
    return out


def front(choice, family):
    """(cost, error) of the family's candidates with a finite predicted error, in order of cost."""
    c = choice["candidates"]
    sel = (c["family"] == family) & np.isfinite(c["predicted_error"])
    order = np.argsort(c["predicted_cost"][sel])
    return c["predicted_cost"][sel][order], c["predicted_error"][sel][order]


def plot_choice(path, outdir=".", output=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ch = read_choice(path)
    a = ch["attrs"]
    fig, ax = plt.subplots(figsize=(7, 5))
    for i, name in enumerate(ch["families"]):
        cost, err = front(ch, i)
        why = str(a.get(f"failure_{name}", ""))
        label = f"{name} (failed at {why.split(':')[0]}: left out)" if why else name
        ax.loglog(cost, err, "o-", ms=3, lw=1, label=label)
    if a["target_error"] > 0:
        ax.axhline(a["target_error"], color="k", ls="--", lw=1, label=f"target {a['target_error']:.3g}")
    ax.loglog([a["chosen_predicted_cost"]], [a["chosen_predicted_error"]], "k*", ms=14,
              label=f"chosen {a['chosen_label']} (predicted)")
    final = ch["finals"]
    ax.loglog([final["seconds"][-1]], [final["estimate"][-1]], "rs", ms=8, mfc="none",
              label=f"estimate of the final run {final['estimate'][-1]:.3g}")
    if math.isfinite(ch["exact_error"]):
        ax.loglog([final["seconds"][-1]], [ch["exact_error"]], "gx", ms=10,
                  label=f"error vs exact {ch['exact_error']:.3g}")
    ax.set_xlabel("predicted cost [s] (final: measured)")
    ax.set_ylabel("L1 density error (predicted)")
    ax.set_title(f"model choice: pilots {a['pilot_seconds']:.3g} s, total {a['total_seconds']:.3g} s", fontsize=10)
    return _finish(plt, fig, ax, figure_file(outdir, "model_choice.png", output))


def _finish(plt, fig, ax, output):
    """Grid, legend, and the figure written to output and closed; returns [output]."""
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(output, dpi=120)
    plt.close(fig)
    return [str(output)]


def read_bench(paths):
    """{problem: (targets, achieved)} of the runs that completed, over one or several targets.csv files (a problem
    in several files, e.g. at 1 and 2 ranks, keeps its points apart under "problem (file stem)")."""
    paths = [paths] if isinstance(paths, (str, Path)) else list(paths)
    rows = {}
    for path in paths:
        with open(path, newline="") as f:
            rows[path] = [r for r in csv.DictReader(f) if r.get("achieved")]
    files = {}  # problem -> the files it is in
    for path, rs in rows.items():
        for r in rs:
            files.setdefault(r["problem"], set()).add(path)
    out = {}
    for path, rs in rows.items():
        for r in rs:
            key = r["problem"] if len(files[r["problem"]]) == 1 else f"{r['problem']} ({Path(path).stem})"
            t, a = out.setdefault(key, ([], []))
            t.append(float(r["target"]))
            a.append(float(r["achieved"]))
    return out


def plot_bench(paths, outdir=".", output=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    data = read_bench(paths)
    fig, ax = plt.subplots(figsize=(6, 5))
    lo, hi = math.inf, 0.0
    for i, (name, (t, a)) in enumerate(data.items()):
        ax.loglog(t, a, "os^Dv<>ph*"[i % 10], label=name, mfc="none" if i >= 10 else None)
        lo, hi = min(lo, *t, *a), max(hi, *t, *a)
    if hi > 0:
        x = np.array([lo / 2, hi * 2])
        ax.loglog(x, x, "k-", lw=1, label="achieved = E")
        ax.loglog(x, x / 4, "k:", lw=1, label="E / 4")
    ax.set_xlabel("target E (L1 density)")
    ax.set_ylabel("achieved L1 error (vs exact or reference)")
    return _finish(plt, fig, ax, figure_file(outdir, "target_error.png", output))


def register(sub):
    p = sub.add_parser("model-choice",
                       help="accuracy-target run: candidates' predicted error vs cost, the choice, its estimate")
    p.add_argument("file", help="HDF5 output of a -target_error / -target_walltime run")
    add_output_options(p, "model_choice.png")
    p.set_defaults(func=figure_command(plot_choice))
    q = sub.add_parser("model-choice-bench", help="euler-target-error benchmark: achieved error vs target")
    q.add_argument("csv", nargs="+", help="targets.csv file(s) written by scripts/bench/euler-target-error")
    add_output_options(q, "target_error.png")
    q.set_defaults(func=figure_command(plot_bench, inputs="csv"))
