"""Contact figures: per-run histories (heights, contacts, force ratio, solver and splitting iterations,
energy), splitting convergence (error between iterates against pass), and the inclined-plane experiment of
Lacoursiere (SIGRAD 2003, Fig. 7): force ratio against tan(theta) for the splitting scheme started from zero
and from infinite friction, with the exact Coulomb curve min(tan theta, mu) (scripts/bench/contact-incline)."""
from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np

PROGRAM = "contact"


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _attr(v):
    return v.decode() if isinstance(v, bytes) else v


def read_run(path):
    """(steps dict, frames dict, root attributes, static mask) of a contact run file."""
    with h5py.File(path, "r") as f:
        attrs = {k: _attr(v) for k, v in f.attrs.items()}
        steps = {k: f["steps"][k][...] for k in f["steps"]} if "steps" in f else {}
        frames = {k: f["frames"][k][...] for k in f["frames"]} if "frames" in f else {}
        static = f["bodies/static"][...].astype(bool) if "bodies/static" in f else None
        if "steps" in f:
            steps["solver_names"] = str(_attr(f["steps"].attrs.get("solver_names", ""))).split(",")
        split = None
        if "splitting" in f:
            split = {k: f["splitting"][k][...] for k in f["splitting"]}
    return steps, frames, attrs, static, split


def plot_history(h5path, outdir):
    steps, frames, attrs, static, _ = read_run(h5path)
    Path(outdir).mkdir(parents=True, exist_ok=True)
    if not frames:
        return []
    plt = _plt()
    fig, ax = plt.subplots(2, 2, figsize=(12, 7))
    t = frames["time"]
    z = frames["positions"][:, :, 2]
    dyn = np.nonzero(~static)[0] if static is not None else np.arange(z.shape[1])
    for i in dyn[:12]:
        ax[0, 0].plot(t, z[:, i], lw=0.8)
    ax[0, 0].set(xlabel="t (s)", ylabel="z (m)", title=f"{attrs.get('scene', '')}: heights of "
                 f"{min(len(dyn), 12)} of {len(dyn)} bodies")
    if steps:
        ts = steps["time"]
        ax[0, 1].plot(ts, steps["contacts"], "k-", lw=0.8)
        ax[0, 1].set(xlabel="t (s)", ylabel="contacts", title="contact points per step")
        ax[1, 0].plot(ts, steps["force_ratio"], label="force ratio |F_t|/F_n")
        ax[1, 0].plot(ts, steps["cone_violation"], label="cone violation")
        ax[1, 0].axhline(float(attrs.get("mu", 0)), color="gray", ls=":", label="mu")
        ax[1, 0].set(xlabel="t (s)", title=f"friction {attrs.get('friction', '')}")
        ax[1, 0].legend(fontsize=8)
        ax[1, 1].plot(ts, steps["iterations"], label="solver iterations")
        ax[1, 1].plot(ts, steps["splitting_iterations"], label="splitting passes")
        ax2 = ax[1, 1].twinx()
        ax2.plot(ts, steps["energy"], "k--", lw=0.8, label="energy")
        ax2.set_ylabel("energy (J)")
        ax[1, 1].set(xlabel="t (s)", title=f"solver {attrs.get('lcp_solver', '')}")
        ax[1, 1].legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    png = Path(outdir) / f"contact_{Path(h5path).stem}_history.png"
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return [str(png)]


def plot_splitting(h5path, outdir, max_steps=40):
    """Error max|delta lambda_n| between splitting iterates against the pass, one line per step."""
    steps, _, attrs, _, split = read_run(h5path)
    if not split:
        return []
    Path(outdir).mkdir(parents=True, exist_ok=True)
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6, 4))
    off = split["offset"]
    nsteps = len(off) - 1
    for s in np.linspace(0, nsteps - 1, min(nsteps, max_steps)).astype(int):
        e = split["error"][off[s] + 1:off[s + 1]]
        if len(e):
            ax.semilogy(np.arange(2, len(e) + 2), np.maximum(e, 1e-300), lw=0.7, alpha=0.7)
    ax.set(xlabel="splitting pass", ylabel="max |delta lambda_n| (N s)",
           title=f"{attrs.get('scene', '')}: splitting convergence ({min(nsteps, max_steps)} steps)")
    fig.tight_layout()
    png = Path(outdir) / f"contact_{Path(h5path).stem}_splitting.png"
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return [str(png)]


def default_plot(h5path, outdir):
    return plot_history(h5path, outdir) + plot_splitting(h5path, outdir)


def read_incline(path):
    """The sweep written by scripts/bench/contact-incline (HDF5)."""
    with h5py.File(path, "r") as f:
        d = {k: f[k][...] for k in f if isinstance(f[k], h5py.Dataset)}
        d["mu"] = float(f.attrs["mu"])
    return d


def plot_incline(path, outdir):
    d = read_incline(path)
    Path(outdir).mkdir(parents=True, exist_ok=True)
    plt = _plt()
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
    tt = d["tan_theta"]
    x = np.linspace(0, tt.max() * 1.02, 400)
    a1.plot(x, np.minimum(x, d["mu"]), "k-", lw=1, label="exact min(tan th, mu)")
    a1.plot(tt, d["ratio_zero"], "o", mfc="none", label="splitting from zero friction")
    a1.plot(tt, d["ratio_infinite"], "x", label="splitting from infinite friction")
    a1.set(xlabel="tan theta", ylabel="|F_t| / F_n", title=f"inclined plane, mu = {d['mu']:g}")
    a1.legend(fontsize=8)
    a2.plot(tt, d["passes_zero"], "o-", mfc="none", label="from zero friction")
    a2.plot(tt, d["passes_infinite"], "x-", label="from infinite friction")
    a2.set(xlabel="tan theta", ylabel="passes to reach 1e-6", title="splitting passes")
    a2.legend(fontsize=8)
    fig.tight_layout()
    png = Path(outdir) / f"contact_incline_{Path(path).stem}.png"
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


def register(sub):
    p = sub.add_parser("contact-incline", help="force ratio against tan(theta), splitting from zero/infinite "
                       "friction (scripts/bench/contact-incline output)")
    p.add_argument("file")
    p.add_argument("--outdir", default="out")
    p.set_defaults(func=lambda a: _report(plot_incline(a.file, a.outdir)))
    p = sub.add_parser("contact-splitting", help="splitting convergence of a contact run")
    p.add_argument("file")
    p.add_argument("--outdir", default="out")
    p.set_defaults(func=lambda a: _report(plot_splitting(a.file, a.outdir)))


def _report(pngs):
    for png in pngs:
        print(f"wrote {png}")
    return 0
