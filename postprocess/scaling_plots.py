"""Scaling figures: speed-up and parallel efficiency against the ideal line, from scripts/scaling-study's CSV;
femdyn -backend plex memory and time per step (scripts/bench/fem-scale's scale.csv and model.csv)."""
from __future__ import annotations

import csv
from pathlib import Path

from .cli import add_output_options, figure_command, figure_file


def read_scaling(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ValueError(f"{path}: no runs")
    for r in rows:
        r["nranks"] = int(r["nranks"])
        for k in list(r):
            if k == "wall_seconds" or k.startswith("stage_"):
                r[k] = float(r[k]) if r[k] not in ("", None) else float("nan")
    return sorted(rows, key=lambda r: r["nranks"])


def speedup(rows, key="wall_seconds"):
    """(ranks, speed-up, efficiency); weak scaling: speed-up = ideal * t0 / t."""
    base = rows[0]
    out = []
    for r in rows:
        ideal = r["nranks"] / base["nranks"]
        s = base[key] / r[key] if r["mode"] == "strong" else ideal * base[key] / r[key]
        out.append((r["nranks"], s, s / ideal))
    return out


def plot_scaling(csv_path, outdir=".", output=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = read_scaling(csv_path)
    keys = ["wall_seconds"] + [k for k in rows[0] if k.startswith("stage_")]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    n = [r["nranks"] for r in rows]
    for k in keys:
        data = speedup(rows, k)
        label = "whole run" if k == "wall_seconds" else k[len("stage_"):]
        a1.plot(n, [d[1] for d in data], "o-", label=label)
        a2.plot(n, [d[2] for d in data], "o-", label=label)
    a1.plot(n, [x / n[0] for x in n], "k--", label="ideal")
    a2.axhline(1.0, color="k", ls="--", label="ideal")
    a1.set(xlabel="MPI ranks", ylabel="speed-up", xscale="log", yscale="log",
           title=f"{rows[0]['app']} ({rows[0]['mode']})")
    a2.set(xlabel="MPI ranks", ylabel="parallel efficiency", xscale="log", ylim=(0, 1.2))
    a1.legend(fontsize=8)
    fig.tight_layout()
    png = figure_file(outdir, f"scaling_{rows[0]['app']}_{rows[0]['mode']}.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


def plot_fem_scale(scale_csv, outdir=".", output=None):
    """femdyn -backend plex (scripts/bench/fem-scale): peak memory per rank, and time per DOF and step against
    the rank count, measured and (model.csv beside the table) projected in weak scaling."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with open(scale_csv, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ValueError(f"{scale_csv}: no runs")
    model_path = Path(scale_csv).with_name("model.csv")
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    for r in rows:
        n, dofs = int(r["ranks"]), int(r["dofs"])
        a1.plot(n, float(r["rss_gib_max_rank"]), "o", label=f"{dofs / 1e6:.2f}M DOFs on {n} rank(s)")
        a2.plot(n, float(r["cpu_us_per_dof_step"]), "o", label=f"measured, {dofs / 1e6:.2f}M DOFs on {n} rank(s)")
    if model_path.exists():
        with open(model_path, newline="") as f:
            m = list(csv.DictReader(f))
        x = [int(r["ranks"]) for r in m]
        y = [1e6 * float(r["s_per_step"]) / float(r["dofs_per_rank"]) for r in m]
        a2.plot(x, y, "k--", label="model, CG count as measured")
        if "s_per_step_assumed_growth" in m[0]:
            y2 = [1e6 * float(r["s_per_step_assumed_growth"]) / float(r["dofs_per_rank"]) for r in m]
            a2.plot(x, y2, "k:", label=f"model, CG count +{float(m[0]['cg_growth_assumed']):g} per doubling")
    ranks = sorted({int(r["ranks"]) for r in rows})
    a1.set(xlabel="MPI ranks", ylabel="peak resident memory per rank [GiB]", title="femdyn plex memory",
           xticks=ranks, xlim=(0.5, max(ranks) + 0.5), ylim=(0, None))
    a2.set(xlabel="MPI ranks", ylabel="CPU us per DOF per StVK step", xscale="log", title="time per step")
    a1.legend(fontsize=8)
    a2.legend(fontsize=8)
    fig.tight_layout()
    png = figure_file(outdir, "fem_scale.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


def register(sub):
    q = sub.add_parser("fem-scale", help="femdyn -backend plex memory and time per step (scripts/bench/fem-scale)")
    q.add_argument("csv")
    add_output_options(q, "fem_scale.png")
    q.set_defaults(func=figure_command(plot_fem_scale, inputs="csv"))
    p = sub.add_parser("scaling", help="speed-up and efficiency from scripts/scaling-study's scaling.csv")
    p.add_argument("csv")
    add_output_options(p, "scaling_<app>_<mode>.png")
    p.set_defaults(func=figure_command(plot_scaling, inputs="csv"))
