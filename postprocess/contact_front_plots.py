"""Contact speed/accuracy front (scripts/bench/contact-front): time per step against the error of each run, this
suite's accuracy modes beside MuJoCo's pyramidal and elliptic cones, one panel per scene. The error is the
scene's own measure: the largest drift of a body at rest (stacks, pyramids, heap, sticking incline) or the
sliding speed's error against the exact g (sin theta - mu cos theta) (sliding incline), or the deepest
penetration (the log heap, which falls and has no rest position)."""
from __future__ import annotations

import math

import h5py
import numpy as np

from .cli import add_output_options, figure_command, figure_file

MARKERS = {"suite": "o", "mujoco": "s"}


def read_front(path):
    """Rows of a contact-front file as a list of dicts (strings decoded)."""
    with h5py.File(path, "r") as f:
        cols = {k: f[k][...] for k in f.keys()}
    n = len(cols["scene"])
    dec = lambda v: v.decode() if isinstance(v, bytes) else v  # noqa: E731
    return [{k: dec(v[i]) for k, v in cols.items()} for i in range(n)]


def run_error(r):
    """The scene's error measure of one row (NaN when the run made no step)."""
    if not r["completed"]:
        return math.nan
    if r["scene"] == "incline_slide":
        return abs(r["speed"] - r["speed_exact"])
    if r["scene"].startswith("logheap"):  # a falling heap has no rest position: its deepest penetration
        return r["penetration"]
    return r["drift"]


def plot_front(path, outdir=".", output=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = read_front(path)
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    ncol = min(3, len(scenes))
    nrow = math.ceil(len(scenes) / ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 3.6 * nrow), squeeze=False)
    for ax, scene in zip(axes.flat, scenes):
        for r in (r for r in rows if r["scene"] == scene):
            err = max(run_error(r), 1e-16)
            if not np.isfinite(err):
                continue
            label = f"{r['code']} {r['mode'] or 'default'}"
            if r["completed"] < r["steps"]:
                label += f" ({r['completed']}/{r['steps']} steps)"
            ax.loglog(1e3 * r["time_per_step"], err, MARKERS.get(r["code"], "x"), label=label)
        ax.set_title(scene)
        ax.set_xlabel("time per step (ms)")
        ax.set_ylabel({"incline_slide": "speed error (m/s)"}.get(scene, "penetration (m)" if scene.startswith(
            "logheap") else "drift (m)"))
        ax.grid(True, which="both", alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
        else:  # every run of the scene without a finite error (e.g. stopped before its first step)
            ax.text(0.5, 0.5, "no run with a finite error", ha="center", va="center", transform=ax.transAxes)
    for ax in list(axes.flat)[len(scenes):]:
        ax.axis("off")
    fig.tight_layout()
    png = str(figure_file(outdir, "contact_front.png", output))
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [png]


def register(sub):
    p = sub.add_parser("contact-front", help="time per step against error, this suite's modes beside MuJoCo "
                       "(scripts/bench/contact-front output)")
    p.add_argument("file")
    add_output_options(p, "contact_front.png")
    p.set_defaults(func=figure_command(plot_front))
