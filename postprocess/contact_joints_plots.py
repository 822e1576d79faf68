"""Joint figures of the contact app: the joint chains' time per step against the chain length, this suite beside
MuJoCo (scripts/bench/contact-joints), and the largest joint position error against time of contact runs."""
from __future__ import annotations

import h5py
import numpy as np

from .cli import add_output_options, figure_command, figure_file


def _save(fig, outdir, name, output):
    import matplotlib.pyplot as plt

    fig.tight_layout()
    png = str(figure_file(outdir, name, output))
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [png]


def read_table(path):
    """Rows of a contact-joints file as a list of dicts (strings decoded)."""
    with h5py.File(path, "r") as f:
        cols = {k: f[k][...] for k in f.keys()}
    dec = lambda v: v.decode() if isinstance(v, bytes) else v  # noqa: E731
    return [{k: dec(v[i]) for k, v in cols.items()} for i in range(len(cols["code"]))]


def plot_cost(path, outdir=".", output=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = read_table(path)
    joints = list(dict.fromkeys(r["joint"] for r in rows))
    fig, axes = plt.subplots(1, len(joints), figsize=(4.5 * len(joints), 3.8), squeeze=False)
    for ax, joint in zip(axes.flat, joints):
        series = dict.fromkeys((r["code"], r["dt"]) for r in rows if r["joint"] == joint)
        for code, dt in series:
            sel = [r for r in rows if r["joint"] == joint and r["code"] == code and r["dt"] == dt]
            n = [r["links"] for r in sel]
            t = [1e3 * r["time_per_step"] for r in sel]
            ax.loglog(n, t, "o-" if code == "suite" else "s--", label=f"{code} dt {dt:g}")
            for r, tt in zip(sel, t):
                if not r["stable"]:
                    ax.plot(r["links"], tt, "rx", ms=10)
        ax.set_title(f"{joint} chains (x: unstable)")
        ax.set_xlabel("links")
        ax.set_ylabel("time per step (ms)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    return _save(fig, outdir, "contact_joints.png", output)


def plot_joint_error(paths, outdir=".", output=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for p in paths:
        with h5py.File(p, "r") as f:
            t, e = f["/steps/time"][:], f["/joints/error"][:]
            name = [f.attrs.get(k, "") for k in ("scene", "contact_accuracy")]
            name = [v.decode() if isinstance(v, bytes) else str(v) for v in name]
            label = f"{' '.join(v for v in name if v)}: {p}"
        ax.semilogy(t, np.maximum(e, 1e-18), label=label)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("largest joint error (m)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    return _save(fig, outdir, "contact_joint_error.png", output)


def register(sub):
    p = sub.add_parser("contact-joints", help="joint chains: time per step against the chain length, this suite "
                       "beside MuJoCo (scripts/bench/contact-joints output)")
    p.add_argument("file")
    add_output_options(p, "contact_joints.png")
    p.set_defaults(func=figure_command(plot_cost))
    p = sub.add_parser("contact-joint-error", help="largest joint error against time of contact runs")
    p.add_argument("files", nargs="+")
    add_output_options(p, "contact_joint_error.png")
    p.set_defaults(func=figure_command(plot_joint_error, inputs="files"))
