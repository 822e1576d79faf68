"""Contact figures: per-run histories (heights, contacts, force ratio, solver and splitting iterations,
energy), splitting convergence (error between iterates against pass), and the inclined-plane experiment of
Lacoursiere (SIGRAD 2003, Fig. 7): force ratio against tan(theta) for the splitting scheme started from zero
and from infinite friction, with the exact Coulomb curve min(tan theta, mu) (scripts/bench/contact-incline)."""
from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np

from .cli import add_output_options, chain, figure_command, figure_file

PROGRAM = "contact"


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _attr(v):
    return v.decode() if isinstance(v, bytes) else v


def body_labels(path, count=None):
    """Legend label of each body: its name from /bodies/name (one string per body, in body order) when the file
    has that dataset, else "body <index>"."""
    with h5py.File(path, "r") as f:
        names = [_attr(v) for v in f["bodies/name"][...].tolist()] if "bodies/name" in f else []
        if count is None:
            count = len(names) or (len(f["bodies/static"]) if "bodies/static" in f else 0)
    names = [str(n).strip() for n in names]
    return [names[i] if i < len(names) and names[i] else f"body {i}" for i in range(count)]


def read_run(path):
    """(steps dict, frames dict, root attributes, static mask, splitting dict) of a contact run file."""
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


def plot_history(h5path, outdir=".", output=None):
    """Heights of up to 12 dynamic bodies (legend: body names), contacts, force ratio, iterations, energy."""
    steps, frames, attrs, static, _ = read_run(h5path)
    if not frames:
        return []
    plt = _plt()
    fig, ax = plt.subplots(2, 2, figsize=(12, 7))
    t = frames["time"]
    z = frames["positions"][:, :, 2]
    dyn = np.nonzero(~static)[0] if static is not None else np.arange(z.shape[1])
    labels = body_labels(h5path, z.shape[1])
    for i in dyn[:12]:
        ax[0, 0].plot(t, z[:, i], lw=0.8, label=labels[i])
    ax[0, 0].set(xlabel="t (s)", ylabel="z (m)", title=f"{attrs.get('scene', '')}: heights of "
                 f"{min(len(dyn), 12)} of {len(dyn)} bodies")
    if len(dyn):
        ax[0, 0].legend(fontsize=6, ncol=2 if len(dyn) > 6 else 1)
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
    png = figure_file(outdir, f"contact_{Path(h5path).stem}_history.png", output)
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return [str(png)]


def plot_splitting(h5path, outdir=".", output=None, max_steps=40):
    """Error max|delta lambda_n| between splitting iterates against the pass, one line per step."""
    steps, _, attrs, _, split = read_run(h5path)
    if not split:
        return []
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6, 4))
    off = split["offset"]
    nsteps = len(off) - 1
    for s in np.linspace(0, nsteps - 1, min(nsteps, max_steps)).astype(int):
        e = split["error"][off[s] + 1:off[s + 1]]
        if len(e):
            ax.semilogy(np.arange(2, len(e) + 2), np.maximum(e, 1e-300), lw=0.7, alpha=0.7)
    ax.set(xlabel="splitting pass", ylabel="max A_nn |delta lambda_n| (m/s)",
           title=f"{attrs.get('scene', '')}: splitting convergence ({min(nsteps, max_steps)} steps)")
    fig.tight_layout()
    png = figure_file(outdir, f"contact_{Path(h5path).stem}_splitting.png", output)
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return [str(png)]


def default_plot(h5path, outdir=".", output=None):
    return chain(outdir, output, lambda d, o: plot_history(h5path, d, o), lambda d, o: plot_splitting(h5path, d, o))


def read_incline(path):
    """The sweep written by scripts/bench/contact-incline (HDF5)."""
    with h5py.File(path, "r") as f:
        d = {k: f[k][...] for k in f if isinstance(f[k], h5py.Dataset)}
        d["mu"] = float(f.attrs["mu"])
    return d


def plot_incline(path, outdir=".", output=None):
    d = read_incline(path)
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
    png = figure_file(outdir, f"contact_incline_{Path(path).stem}.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


# ---- log-heap experiments (Lacoursiere 2003, Figs. 5, 6, 8) ----

PIVOT_SOLVERS = ("lemke", "keller", "cottle_dantzig", "murty", "bpp")
NEWTON_SOLVERS = ("fb_newton", "smoothed_newton")


def heap_histogram_stats(path):
    """Per solver of an lcpbench result file (the heap's dumped problems replayed): dict with solved count,
    failures, median and 90th percentile of pivots / n (pivoting) or iterations (Newton)."""
    from .lcp_plots import read_batch

    solvers, sizes, res = read_batch(path)
    out = {}
    for s in solvers:
        r = res[s]
        ok = r["status"] == 0
        pivoting = s in PIVOT_SOLVERS and s != "bpp"
        x = (r["pivots"] / sizes) if pivoting else r["iterations"].astype(float)
        x = x[ok]
        out[s] = {"solved": int(ok.sum()), "failed": int((~ok).sum()), "unit": "pivots/n" if pivoting else "iterations",
                  "median": float(np.median(x)) if x.size else float("nan"),
                  "p90": float(np.percentile(x, 90)) if x.size else float("nan"), "values": x,
                  "median_n": float(np.median(sizes))}
    return out


def plot_heap_histograms(path, outdir=".", output=None):
    """Iteration histograms of the pivoting (pivots / n) and Newton (iterations) solvers on the log heap's
    dumped problems (an lcpbench -file result), as the paper's Figs. 5, 6."""
    st = heap_histogram_stats(path)
    plt = _plt()
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
    for s, d in st.items():
        ax = a1 if d["unit"] == "pivots/n" else a2
        if d["values"].size:
            ax.hist(d["values"], bins=30, histtype="step", lw=1.2,
                    label=f"{s} (median {d['median']:.3g}, {d['failed']} failed)")
    a1.set(xlabel="pivots / n", ylabel="problems", title="pivoting solvers")
    a2.set(xlabel="iterations", ylabel="problems", title="Newton / block pivoting solvers")
    for ax in (a1, a2):
        if ax.has_data():
            ax.legend(fontsize=7)
    n = next(iter(st.values()))["median_n"] if st else 0
    fig.suptitle(f"log heap: {Path(path).stem}, median problem size {n:.0f}")
    fig.tight_layout()
    png = figure_file(outdir, f"contact_heap_histograms_{Path(path).stem}.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    for s, d in st.items():
        print(f"{s}: {d['solved']} solved, {d['failed']} failed, median {d['median']:.4g} {d['unit']}, "
              f"90% {d['p90']:.4g}")
    return [str(png)]


def splitting_convergence_stats(h5path, stagnation=0.9):
    """Splitting error between iterates per pass over all steps of a run: median/max error per pass, and
    per step the pass where it stagnates (the error stops shrinking by the factor `stagnation`) and the error
    there."""
    steps, _, attrs, _, split = read_run(h5path)
    if not split:
        raise ValueError(f"{h5path}: no splitting history (run with -friction splitting)")
    off = split["offset"]
    errs = [split["error"][off[s] + 1:off[s + 1]] for s in range(len(off) - 1)]  # pass 2.. (pass 1: |lambda|)
    errs = [e for e in errs if len(e)]
    kmax = max((len(e) for e in errs), default=0)
    med = np.array([np.median([e[k] for e in errs if len(e) > k]) for k in range(kmax)])
    mx = np.array([np.max([e[k] for e in errs if len(e) > k]) for k in range(kmax)])
    stag_pass, stag_err = [], []
    for e in errs:
        k = next((i for i in range(1, len(e)) if e[i] > stagnation * e[i - 1]), None)
        if k is not None:
            stag_pass.append(k + 2)  # e[0] is the change at pass 2
            stag_err.append(e[k])
    return {"errors": errs, "median": med, "max": mx, "stag_pass": np.array(stag_pass),
            "stag_err": np.array(stag_err), "steps": len(errs), "attrs": attrs}


def plot_splitting_convergence(h5path, outdir=".", output=None):
    """Error norm between splitting iterates against the iteration for every step of a run (log heap: the
    paper's Fig. 8), the median curve, and where the iteration stagnates."""
    d = splitting_convergence_stats(h5path)
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    top = max(float(d["max"].max()) if len(d["max"]) else 1.0, 1e-300)
    floor = 1e-12 * top  # exact zeros (converged steps) are drawn at the floor
    for e in d["errors"]:
        ax.semilogy(np.arange(2, len(e) + 2), np.maximum(e, floor), color="0.6", lw=0.4, alpha=0.5)
    k = np.arange(2, len(d["median"]) + 2)
    ax.semilogy(k, np.maximum(d["median"], floor), "k-", lw=2, label="median over steps")
    ax.semilogy(k, np.maximum(d["max"], floor), "r--", lw=1, label="max over steps")
    ax.set_ylim(0.5 * floor, 2 * top)
    if d["stag_pass"].size:
        ax.axhline(np.median(d["stag_err"]), color="b", ls=":", lw=1,
                   label=f"stagnation: median pass {np.median(d['stag_pass']):.0f}, level "
                         f"{np.median(d['stag_err']):.2g}")
    ax.set(xlabel="splitting iteration", ylabel="max A_nn |lambda_n^(k) - lambda_n^(k-1)| (m/s)",
           title=f"{d['attrs'].get('scene', '')}: splitting convergence, {d['steps']} steps")
    ax.legend(fontsize=7)
    fig.tight_layout()
    png = figure_file(outdir, f"contact_{Path(h5path).stem}_split_convergence.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    print("pass  median_error  max_error")
    for i, (a, b) in enumerate(zip(d["median"], d["max"])):
        print(f"{i + 2:4d}  {a:.3e}  {b:.3e}")
    if d["stag_pass"].size:
        print(f"stagnation in {d['stag_pass'].size}/{d['steps']} steps: median pass {np.median(d['stag_pass']):.0f},"
              f" median level {np.median(d['stag_err']):.3e}")
    return [str(png)]


def read_speed_accuracy(path):
    """scripts/bench/contact-logheap --h5 output: /cases/<name>/ with attributes model, step_ms (median wall
    per step), cpu_ms, cone_violation (mean relative), failed."""
    rows = []
    with h5py.File(path, "r") as f:
        for name in f["cases"]:
            a = f["cases"][name].attrs
            rows.append({"name": name, **{k: _attr(v) for k, v in a.items()}})
    return rows


def plot_speed_accuracy(path, outdir=".", output=None):
    """Wall time per step against the Coulomb-cone violation per friction model on the log heap."""
    rows = [r for r in read_speed_accuracy(path) if not int(r.get("failed", 0))]
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for r in rows:
        v = max(float(r["cone_violation"]), 1e-16)
        ax.loglog(float(r["step_ms"]), v, "o")
        ax.annotate(r["name"], (float(r["step_ms"]), v), fontsize=7, xytext=(4, 2), textcoords="offset points")
    ax.set(xlabel="time per step (ms, median)", ylabel="cone violation sum max(0,|l_t|-mu l_n) / sum l_n",
           title=f"log heap: speed against accuracy")
    fig.tight_layout()
    png = figure_file(outdir, f"contact_speed_accuracy_{Path(path).stem}.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    print("case  step_ms  cone_violation")
    for r in rows:
        print(f"{r['name']}  {float(r['step_ms']):.3f}  {float(r['cone_violation']):.3e}")
    return [str(png)]


def register(sub):
    for name, fn, default, text in (
        ("contact-incline", plot_incline, "contact_incline_<stem>.png", "force ratio against tan(theta), splitting "
         "from zero/infinite friction (scripts/bench/contact-incline output)"),
        ("contact-history", plot_history, "contact_<stem>_history.png", "contact run: heights of the bodies "
         "(legend: /bodies/name), contacts, force ratio, iterations, energy"),
        ("contact-splitting", plot_splitting, "contact_<stem>_splitting.png", "splitting convergence of a contact "
         "run"),
        ("contact-heap-histograms", plot_heap_histograms, "contact_heap_histograms_<stem>.png", "iteration "
         "histograms of pivoting and Newton solvers on the log heap's dumped problems (lcpbench -file ... result)"),
        ("contact-split-convergence", plot_splitting_convergence, "contact_<stem>_split_convergence.png",
         "error between splitting iterates against the iteration over all steps of a contact run, and where it "
         "stagnates"),
        ("contact-speed-accuracy", plot_speed_accuracy, "contact_speed_accuracy_<stem>.png", "time per step "
         "against cone violation per friction model (scripts/bench/contact-logheap --h5 output)"),
    ):
        p = sub.add_parser(name, help=text)
        p.add_argument("file")
        add_output_options(p, default)
        p.set_defaults(func=figure_command(fn))
