"""lcpbench figures (Lacoursiere 2003, SIGRAD): iteration-count histograms (pivoting methods in units of n,
Newton / splitting methods absolute), time and residual distributions, and Dolan-More performance profiles
(Dolan & More 2002, Math. Prog. 91) across solvers, from the /results/<solver>/ datasets of an lcpbench file;
with `-solvers auto` also the portfolio's choices
(the succeeding solver per problem class, and how many solvers were tried).

    python -m postprocess lcp-histograms batch.h5 [-o FILE] [--outdir DIR]

Figures: lcp_<stem>_iterations.png (the main one, named by -o), lcp_<stem>_time_residual.png,
lcp_<stem>_profile.png and, with -solvers auto, lcp_<stem>_portfolio.png.
"""
from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np

from .cli import add_output_options, figure_command, figure_file

PROGRAM = "lcpbench"
PIVOTING = ("lemke", "keller", "cottle_dantzig", "murty")  # histogram of pivots / n
STATUS_SOLVED = 0


def read_batch(path):
    """(solvers, sizes, results): results[solver] = dict of arrays status, iterations, pivots, time, residual."""
    with h5py.File(path, "r") as f:
        if "results" not in f:
            raise ValueError(f"{path}: no /results group (not an lcpbench file?)")
        attr = f.attrs.get("solvers", "")
        attr = attr.decode() if isinstance(attr, bytes) else str(attr)
        solvers = [s.strip() for s in attr.split(",") if s.strip()]
        solvers = [s for s in solvers if s in f["results"]] or sorted(f["results"])
        sizes = f["problems/n"][...] if "problems/n" in f else None
        res = {}
        for s in solvers:
            g = f["results"][s]
            res[s] = {k: g[k][...] for k in ("status", "iterations", "pivots", "time", "residual")}
    if sizes is None:
        sizes = np.ones(len(next(iter(res.values()))["status"]))
    return solvers, np.asarray(sizes, dtype=float), res


def read_portfolio(path):
    """None without /results/auto, else dict: classes (per problem), solver (succeeding, "" = none), tried
    (list of names per problem)."""
    with h5py.File(path, "r") as f:
        if "results/auto/class" not in f:
            return None
        g = f["results/auto"]

        def names(key):
            v = g.attrs[key]
            return [x.strip() for x in (v.decode() if isinstance(v, bytes) else str(v)).split(",")]

        cls_names, solver_names = names("class_names"), names("solver_names")
        cls = [cls_names[c] if c >= 0 else "invalid" for c in g["class"][...]]
        chosen = [solver_names[s] if s >= 0 else "" for s in g["solver"][...]]
        count = g["tried_count"][...]
        cols = [g[f"tried_{j}"][...] for j in range(len([k for k in g if k.startswith("tried_") and k[6:].isdigit()]))]
        tried = [[solver_names[cols[j][i]] for j in range(count[i])] for i in range(len(cls))]
    return {"classes": cls, "solver": chosen, "tried": tried}


def portfolio_table(pf):
    """{class: {solver or "none": problems}} of the succeeding solvers."""
    table = {}
    for c, s in zip(pf["classes"], pf["solver"]):
        row = table.setdefault(c, {})
        row[s or "none"] = row.get(s or "none", 0) + 1
    return dict(sorted(table.items()))


def plot_portfolio(pf, outdir, stem, plt):
    """Stacked bars: per class, the solver whose answer auto accepted; and the number of solvers tried."""
    table = portfolio_table(pf)
    classes = list(table)
    solvers = sorted({s for row in table.values() for s in row}, key=lambda s: (s == "none", s))
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4), gridspec_kw={"width_ratios": [3, 1]})
    bottom = np.zeros(len(classes))
    for k, s in enumerate(solvers):
        h = np.array([table[c].get(s, 0) for c in classes], dtype=float)
        a1.bar(range(len(classes)), h, bottom=bottom, label=s, color="k" if s == "none" else f"C{k % 10}")
        bottom += h
    a1.set_xticks(range(len(classes)), classes, rotation=45, ha="right", fontsize=8)
    a1.set(ylabel="problems", title="auto: succeeding solver per problem class")
    a1.legend(fontsize=7)
    ntried = np.array([len(t) for t in pf["tried"]])
    a2.bar(*np.unique(ntried, return_counts=True), color="C0")
    a2.set(xlabel="solvers tried", ylabel="problems", title="auto: attempts per problem")
    fig.tight_layout()
    png = figure_file(outdir, f"lcp_{stem}_portfolio.png")
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return str(png)


def performance_profile(times, taus=None):
    """Dolan-More profile: times is (problems, solvers) with np.inf for failures; returns (taus, rho) with
    rho[i, s] = fraction of problems where solver s is within a factor taus[i] of the best solver."""
    t = np.asarray(times, dtype=float)
    best = np.min(t, axis=1)
    ok = np.isfinite(best) & (best > 0)
    ratios = t[ok] / best[ok, None]
    if taus is None:
        finite = ratios[np.isfinite(ratios)]
        hi = max(2.0, float(finite.max()) * 1.05) if finite.size else 2.0
        taus = np.logspace(0, np.log10(hi), 200)
    rho = np.array([[np.mean(ratios[:, s] <= tau) if ratios.shape[0] else 0.0 for s in range(t.shape[1])]
                    for tau in taus])
    return np.asarray(taus), rho


def plot_histograms(path, outdir=".", output=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    solvers, sizes, res = read_batch(path)
    out = outdir
    stem = Path(path).stem
    written = []
    # 1. iteration-count histograms
    ncol = min(4, len(solvers))
    nrow = (len(solvers) + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.4 * ncol, 2.8 * nrow), squeeze=False)
    for ax, s in zip(axes.ravel(), solvers):
        r = res[s]
        ok = r["status"] == STATUS_SOLVED
        if s in PIVOTING:
            data, label = r["pivots"][ok] / sizes[ok], "pivots / n"
        else:
            data, label = r["iterations"][ok], "iterations" if s != "bpp" else "block iterations"
        if data.size:
            ax.hist(data, bins=min(40, max(5, len(np.unique(data)))), color="C0")
        fails = int((~ok).sum())
        ax.set(title=f"{s} ({fails} failed)", xlabel=label, ylabel="problems")
    for ax in axes.ravel()[len(solvers):]:
        ax.axis("off")
    fig.tight_layout()
    png = figure_file(out, f"lcp_{stem}_iterations.png", output)
    fig.savefig(png, dpi=110)
    plt.close(fig)
    written.append(str(png))
    # 2. time and residual distributions
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
    tdata = [np.maximum(res[s]["time"], 1e-9) for s in solvers]
    rdata = [np.maximum(res[s]["residual"][np.isfinite(res[s]["residual"])], 1e-20) for s in solvers]
    a1.boxplot(tdata, tick_labels=solvers, whis=(0, 100))
    a1.set(yscale="log", ylabel="time per problem [s]")
    a2.boxplot(rdata, tick_labels=solvers, whis=(0, 100))
    a2.set(yscale="log", ylabel="natural-map residual")
    for a in (a1, a2):
        a.tick_params(axis="x", rotation=45)
    fig.tight_layout()
    png = figure_file(out, f"lcp_{stem}_time_residual.png")
    fig.savefig(png, dpi=110)
    plt.close(fig)
    written.append(str(png))
    # 3. performance profiles on time (failures = infinite time)
    times = np.column_stack([np.where(res[s]["status"] == STATUS_SOLVED, res[s]["time"], np.inf) for s in solvers])
    taus, rho = performance_profile(times)
    fig, ax = plt.subplots(figsize=(6, 4))
    for k, s in enumerate(solvers):
        ax.step(taus, rho[:, k], where="post", label=s)
    ax.set(xscale="log", xlabel="tau (time / best time)", ylabel="fraction of problems", ylim=(0, 1.02),
           title="performance profile (Dolan-More)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    png = figure_file(out, f"lcp_{stem}_profile.png")
    fig.savefig(png, dpi=110)
    plt.close(fig)
    written.append(str(png))
    # 4. the portfolio's choices (-solvers auto)
    pf = read_portfolio(path)
    if pf is not None:
        written.append(plot_portfolio(pf, out, stem, plt))
    return written


def default_plot(path, outdir=".", output=None):
    return plot_histograms(path, outdir, output)


def register(sub):
    p = sub.add_parser("lcp-histograms", help="lcpbench: iteration histograms, time/residual, performance profiles")
    p.add_argument("file")
    add_output_options(p, "lcp_<stem>_iterations.png", several=True)
    p.set_defaults(func=figure_command(plot_histograms))
