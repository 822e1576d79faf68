"""euler figures: final profiles against the exact (or reference) solution, the pulse density x-t image, and, from
scripts/bench/euler-tradeoff files, error-vs-wall-time Pareto fronts and convergence (L1 error vs N).

    python -m postprocess euler-profiles run.h5 [-o FILE] [--outdir DIR]      <stem>_profiles.png
    python -m postprocess euler-pulse pulse.h5 [-o FILE] [--outdir DIR]       <stem>_xt.png
    python -m postprocess euler-tradeoff tradeoff.h5 [-o FILE] [--outdir DIR]  <stem>_pareto.png
    python -m postprocess euler-convergence tradeoff.h5 [-o FILE] [--outdir DIR]  <stem>_convergence.png
"""
from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np

from .cli import add_output_options, chain, figure_command, figure_file

PROGRAM = "euler"


def _attr(f, name, default=""):
    v = f.attrs.get(name, default)
    return v.decode() if isinstance(v, bytes) else v


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def plot_profiles(path, outdir=".", output=None):
    """rho, u, p at the final time, with the exact/reference solution when the run had -error."""
    plt = _plt()
    with h5py.File(path, "r") as f:
        x = f["grid/x"][...]
        title = (f"{_attr(f, 'problem')} / {_attr(f, 'scheme')}, nx = {_attr(f, 'nx')}, "
                 f"t = {float(_attr(f, 'time', 0)):.4g}")
        fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
        for ax, var in zip(axes, ("rho", "u", "p")):
            if f"exact/{var}" in f:
                ax.plot(x, f[f"exact/{var}"][...], "k-", lw=1.0, label="exact / reference")
            ax.plot(x, f[f"final/{var}"][...], "o", ms=2.5, mfc="none", label=_attr(f, "scheme"))
            ax.set_xlabel("x")
            ax.set_title(var)
        axes[0].legend(fontsize=8)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    out = figure_file(outdir, f"{Path(path).stem}_profiles.png", output)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return [str(out)]


def plot_pulse(path, outdir=".", output=None):
    """Density x-t image from /spacetime/rho (written with -spacetime_every; default for -problem pulse)."""
    plt = _plt()
    with h5py.File(path, "r") as f:
        if "spacetime" not in f:
            raise ValueError(f"{path}: no /spacetime group (run with -spacetime_every N)")
        rho = f["spacetime/rho"][...]
        t = f["spacetime/time"][...]
        x0, x1 = float(_attr(f, "xmin", 0.0)), float(_attr(f, "xmax", 1.0))
        scheme = _attr(f, "scheme")
    fig, ax = plt.subplots(figsize=(6, 5))
    im = ax.imshow(rho, origin="lower", aspect="auto", extent=[x0, x1, t[0], t[-1]], cmap="viridis")
    fig.colorbar(im, ax=ax, label="density")
    ax.set_xlabel("x")
    ax.set_ylabel("t")
    ax.set_title(f"pulse: density x-t ({scheme})")
    fig.tight_layout()
    out = figure_file(outdir, f"{Path(path).stem}_xt.png", output)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return [str(out)]


def read_tradeoff(path):
    """{problem: {(scheme, integrator): (nx, l1, seconds)}} from a euler-tradeoff file."""
    res = {}
    with h5py.File(path, "r") as f:
        for prob, g in f["runs"].items():
            for scheme, gs in g.items():
                for integ, gi in gs.items():
                    res.setdefault(prob, {})[(scheme, integ)] = (gi["nx"][...], gi["l1_rho"][...], gi["seconds"][...])
    return res


def pareto(points):
    """Indices of the error-vs-time Pareto front (minimise both), sorted by time."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], np.inf
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def plot_tradeoff(path, outdir=".", output=None):
    plt = _plt()
    res = read_tradeoff(path)
    fig, axes = plt.subplots(1, len(res), figsize=(5 * len(res), 4.2), squeeze=False)
    for ax, (prob, runs) in zip(axes[0], sorted(res.items())):
        pts = []
        for (scheme, integ), (nx, l1, sec) in sorted(runs.items()):
            ok = np.isfinite(l1) & (l1 > 0)
            ax.loglog(sec[ok], l1[ok], "o-" if integ != "bdf2" else "s--", ms=4, label=f"{scheme}/{integ}")
            pts += [(s, e) for s, e in zip(sec[ok], l1[ok])]
        if pts:
            front = pareto(pts)
            ax.loglog([pts[i][0] for i in front], [pts[i][1] for i in front], "k:", lw=2, label="Pareto front")
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel("L1 error of rho")
        ax.set_title(prob)
        ax.legend(fontsize=6)
    fig.tight_layout()
    out = figure_file(outdir, f"{Path(path).stem}_pareto.png", output)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return [str(out)]


def plot_convergence(path, outdir=".", output=None, problem="density_wave"):
    plt = _plt()
    res = read_tradeoff(path)
    if problem not in res:
        raise ValueError(f"{path}: no runs of {problem}")
    fig, ax = plt.subplots(figsize=(5.5, 4.5))
    for (scheme, integ), (nx, l1, _) in sorted(res[problem].items()):
        if integ == "bdf2":
            continue
        ok = np.isfinite(l1) & (l1 > 0)
        order = np.polyfit(np.log(nx[ok][-2:]), np.log(l1[ok][-2:]), 1)[0] if ok.sum() >= 2 else np.nan
        ax.loglog(nx[ok], l1[ok], "o-", label=f"{scheme}/{integ} (order {-order:.2f})")
    ax.set_xlabel("N")
    ax.set_ylabel("L1 error of rho")
    ax.set_title(f"convergence: {problem}")
    ax.legend(fontsize=7)
    fig.tight_layout()
    out = figure_file(outdir, f"{Path(path).stem}_convergence.png", output)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return [str(out)]


def default_plot(h5path, outdir=".", output=None):
    with h5py.File(h5path, "r") as f:
        has_st = "spacetime" in f
        dim = int(f.attrs.get("dim", 1))
    if dim >= 2:  # 2D/3D runs: density and schlieren images (euler_nd_plots)
        from .euler_nd_plots import default_plot as nd_plot

        return nd_plot(h5path, outdir, output)
    figures = [lambda d, o: plot_profiles(h5path, d, o)]
    if has_st:
        figures.append(lambda d, o: plot_pulse(h5path, d, o))
    return chain(outdir, output, *figures)


def register(sub):
    for name, fn, default, text in [
            ("euler-profiles", plot_profiles, "<stem>_profiles.png",
             "euler: final rho, u, p against the exact solution"),
            ("euler-pulse", plot_pulse, "<stem>_xt.png", "euler: pulse density x-t image"),
            ("euler-tradeoff", plot_tradeoff, "<stem>_pareto.png", "euler: error vs wall time Pareto fronts"),
            ("euler-convergence", plot_convergence, "<stem>_convergence.png", "euler: L1 error vs N (density_wave)")]:
        p = sub.add_parser(name, help=text)
        p.add_argument("file")
        add_output_options(p, default)
        p.set_defaults(func=figure_command(fn))
