"""Figure of the Euler extreme-case battery (scripts/euler-extremes, docs/euler_extremes.md): a heat map of
log10 L1(rho) per case (rows) and scheme (columns); failed runs are marked with a red cross and "FAIL", passing
runs without an exact solution (2D/3D) are grey and marked "ok".

    python -m postprocess euler-extremes table.csv [-o FILE] [--outdir DIR]    (default DIR/euler_extremes.png)

The CSV is the runner's table.csv: one row per run with the columns case, scheme, outcome (ok / FAIL), l1_rho
(nan when there is no exact solution), retries, wall_s, among others.
"""
from __future__ import annotations

import csv
import math

import numpy as np

from .cli import add_output_options, figure_command, figure_file


def read_table(path):
    """Rows of the battery's CSV as dicts (numbers as floats where the column is numeric)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ValueError(f"{path}: no runs")
    for col in ("case", "scheme", "outcome", "l1_rho"):
        if col not in rows[0]:
            raise ValueError(f"{path}: no column '{col}'")
    for r in rows:
        r["l1_rho"] = float(r["l1_rho"]) if r["l1_rho"] not in ("", None) else math.nan
    return rows


def battery_matrix(rows):
    """(cases, schemes, log10 L1 matrix with nan where unknown, failed boolean matrix), in first-seen order."""
    cases = list(dict.fromkeys(r["case"] for r in rows))
    schemes = list(dict.fromkeys(r["scheme"] for r in rows))
    l1 = np.full((len(cases), len(schemes)), np.nan)
    failed = np.zeros((len(cases), len(schemes)), dtype=bool)
    for r in rows:
        i, j = cases.index(r["case"]), schemes.index(r["scheme"])
        failed[i, j] = r["outcome"] != "ok"
        if not failed[i, j] and r["l1_rho"] > 0:
            l1[i, j] = math.log10(r["l1_rho"])
    return cases, schemes, l1, failed


def plot_battery(path, outdir=".", output=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cases, schemes, l1, failed = battery_matrix(read_table(path))
    fig, ax = plt.subplots(figsize=(1.6 * len(schemes) + 3.5, 0.32 * len(cases) + 1.5))
    ax.set_facecolor("0.85")
    im = ax.imshow(np.ma.masked_invalid(l1), cmap="viridis", aspect="auto")
    for i in range(len(cases)):
        for j in range(len(schemes)):
            if failed[i, j]:
                ax.plot(j, i, marker="x", color="red", markersize=14, markeredgewidth=2.5, alpha=0.45)
                ax.text(j, i, "FAIL", ha="center", va="center", color="darkred", fontsize=7, weight="bold")
            elif math.isnan(l1[i, j]):
                ax.text(j, i, "ok", ha="center", va="center", color="0.3", fontsize=7)
            else:
                bright = im.norm(l1[i, j]) > 0.6  # viridis is light at its top end
                ax.text(j, i, f"{10 ** l1[i, j]:.1e}", ha="center", va="center", fontsize=6,
                        color="black" if bright else "white")
    ax.set_xticks(range(len(schemes)), schemes)
    ax.set_yticks(range(len(cases)), cases, fontsize=7)
    ax.set_title(f"Euler extreme-case battery: {int(failed.sum())} of {failed.size} runs fail")
    if np.isfinite(l1).any():
        fig.colorbar(im, ax=ax, label="log10 L1(rho) vs exact")
    fig.tight_layout()
    out = str(figure_file(outdir, "euler_extremes.png", output))
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return [out]


def register(sub):
    p = sub.add_parser("euler-extremes",
                       help="euler: extreme-case battery heat map (L1(rho) per case x scheme, failures marked)")
    p.add_argument("csv", help="table.csv written by scripts/euler-extremes")
    add_output_options(p, "euler_extremes.png")
    p.set_defaults(func=figure_command(plot_battery, inputs="csv"))
