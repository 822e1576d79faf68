"""FEM figures: femdyn energy / tip-deflection / per-step timing histories, haptic probe force history, the
-material auto estimate with its switch points and target; Hz against DOF per ordering and solver
(scripts/bench/fem-rate CSV); ordering metrics per matrix or mesh (scripts/bench/fem-orderings CSV)."""
from __future__ import annotations

import csv
from pathlib import Path

import h5py
import numpy as np

from .cli import add_output_options, chain, figure_command, figure_file

PROGRAM = "femdyn"


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def read_history(path):
    """Per-step arrays of a dynamic femdyn run (dict of numpy arrays) and the root attributes."""
    with h5py.File(path, "r") as f:
        attrs = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()}
        if "steps" not in f:
            return {}, attrs
        return {k: f["steps"][k][...] for k in f["steps"]}, attrs


def plot_history(h5path, outdir=".", output=None):
    s, attrs = read_history(h5path)
    stem = Path(h5path).stem
    if not s:
        return []
    plt = _plt()
    fig, (a1, a2, a3) = plt.subplots(1, 3, figsize=(14, 4))
    t = s["time"]
    total = s["kinetic_energy"] + s["strain_energy"] - s["external_work"]
    a1.plot(t, s["kinetic_energy"], label="kinetic")
    a1.plot(t, s["strain_energy"], label="strain")
    a1.plot(t, total, "k--", label="T + U - f.u")
    a1.set(xlabel="t", ylabel="energy", title=f"{attrs.get('material', '')}, {int(attrs.get('dofs', 0))} DOF")
    a1.legend(fontsize=8)
    a2.plot(t, s["tip_deflection"])
    a2.set(xlabel="t", ylabel="tip deflection (mean -u_y)", title="tip")
    ms = lambda k: 1e3 * s[k][1:]
    steps = np.arange(1, len(t))
    a3.stackplot(steps, ms("assemble"), ms("factor"), ms("solve"), labels=["assemble", "factor", "solve"])
    a3.plot(steps, ms("wall"), "k-", lw=0.8, label="step wall")
    a3.set(xlabel="step", ylabel="ms", title=f"{attrs.get('ordering', '')}/{attrs.get('solver', '')}: "
           f"{float(attrs.get('rate_hz', 0)):.0f} Hz")
    a3.legend(fontsize=8)
    fig.tight_layout()
    png = figure_file(outdir, f"femdyn_{stem}_history.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


def read_probe(path):
    """Haptic probe output of a femdyn -probe run (dict of arrays, empty without a probe)."""
    with h5py.File(path, "r") as f:
        if "probe" not in f:
            return {}
        return {k: f["probe"][k][...] for k in f["probe"]}


def plot_probe(h5path, outdir=".", output=None):
    p = read_probe(h5path)
    if not p:
        return []
    plt = _plt()
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(p["haptic_time"], p["haptic_force"], "-", lw=0.8, label="haptic output (local model, 1 kHz)")
    ax.plot(p["sync_time"], p["force_full"], "o", ms=3, label="full model (FEM steps)")
    ax.plot(p["sync_time"][1:], p["force_predicted"][:-1], "x", ms=4, label="local model at the next step")
    ax.set(xlabel="t", ylabel="probe force", title="haptic probe force")
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = figure_file(outdir, f"femdyn_{Path(h5path).stem}_probe.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


def read_material_auto(path):
    """/material_auto of a femdyn -material auto run: (time, law, estimate, attrs); None without it."""
    with h5py.File(path, "r") as f:
        if "material_auto" not in f:
            return None
        g = f["material_auto"]
        attrs = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in g.attrs.items()}
        return f["steps/time"][...], g["law"][...], g["estimate"][...], attrs


def plot_material_auto(h5path, outdir=".", output=None):
    """Estimated relative error of the linear law against time, the law per step (shaded where nonlinear),
    the switch points, the target E and the switch band (up * E, down * E); the tip deflection below."""
    m = read_material_auto(h5path)
    if m is None:
        return []
    t, law, est, a = m
    s, _ = read_history(h5path)
    plt = _plt()
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    E, nl = float(a["target"]), a.get("nonlinear_law", "nonlinear")
    for ax in (a1, a2):
        for i in np.flatnonzero(law[1:] == 1) + 1:
            ax.axvspan(t[i - 1], t[i], color="tab:orange", alpha=0.15, lw=0)
    a1.semilogy(t[1:], np.maximum(est[1:], 1e-300), "k-", lw=1, label="estimate (linear law's error)")
    a1.axhline(E, color="tab:red", label=f"target E = {E:g}")
    a1.axhline(float(a["switch_up"]) * E, color="tab:red", ls="--", lw=0.8, label="switch up")
    a1.axhline(float(a["switch_down"]) * E, color="tab:blue", ls="--", lw=0.8, label="switch down")
    sw = np.flatnonzero(np.diff(law) != 0) + 1
    a1.plot(t[sw], np.maximum(est[sw], 1e-300), "o", color="tab:purple", ms=5, label="switch")
    a1.set(ylabel="estimated relative error",
           title=f"-material auto: linear / {nl} (shaded), {int(a['switches'])} switches")
    a1.legend(fontsize=7, loc="lower right")
    a2.plot(t, s["tip_deflection"], "k-", lw=1)
    a2.plot(t[sw], s["tip_deflection"][sw], "o", color="tab:purple", ms=5)
    a2.set(xlabel="t", ylabel="tip deflection (mean -u_y)")
    fig.tight_layout()
    png = figure_file(outdir, f"femdyn_{Path(h5path).stem}_material_auto.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


def read_time_adapt(path):
    """/time_adapt of a femdyn -dt_adapt run: (tries dict, attrs); None without it."""
    with h5py.File(path, "r") as f:
        if "time_adapt" not in f:
            return None
        g = f["time_adapt"]
        attrs = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in g.attrs.items()}
        return {k: g["tries"][k][...] for k in g["tries"]}, attrs


def plot_time_adapt(h5path, outdir=".", output=None):
    """-dt_adapt: dt of every try against its start time (accepted dots, rejected crosses), the estimate over
    the tolerance of each try (accept at <= 1), and the tip deflection below."""
    m = read_time_adapt(h5path)
    if m is None:
        return []
    tr, a = m
    s, _ = read_history(h5path)
    ok, rej = tr["accepted"] == 1, tr["accepted"] == 0
    plt = _plt()
    fig, (a1, a2, a3) = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    a1.semilogy(tr["time"][ok], tr["dt"][ok], "k.", ms=2, label="accepted")
    a1.semilogy(tr["time"][rej], tr["dt"][rej], "x", color="tab:red", ms=6, label="rejected")
    a1.set(ylabel="dt", title=f"-dt_adapt: target {float(a['target_error']):g} (time steps "
           f"{float(a['time_budget']):g}), {int(a['steps_accepted'])} steps, {int(a['tries_rejected'])} rejected")
    a1.legend(fontsize=7)
    est = tr["estimate"]
    a2.semilogy(tr["time"][ok & (est > 0)], est[ok & (est > 0)], "k.", ms=2)
    a2.semilogy(tr["time"][rej], est[rej], "x", color="tab:red", ms=6)
    a2.axhline(1.0, color="tab:red", lw=0.8)
    a2.set(ylabel="estimate / tolerance")
    a3.plot(s["time"], s["tip_deflection"], "k-", lw=1)
    a3.set(xlabel="t", ylabel="tip deflection (mean -u_y)")
    fig.tight_layout()
    png = figure_file(outdir, f"femdyn_{Path(h5path).stem}_time_adapt.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


def default_plot(h5path, outdir=".", output=None):
    return chain(outdir, output, *(lambda d, o, fn=fn: fn(h5path, d, o)
                                   for fn in (plot_history, plot_probe, plot_material_auto, plot_time_adapt)))


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ValueError(f"{path}: no rows")
    for r in rows:
        for k, v in r.items():
            try:
                r[k] = float(v)
            except ValueError:
                pass
    return rows


def plot_rate(csv_path, outdir=".", output=None):
    """Hz against DOF per method; with an `error` column (the real-time benchmark) also Hz against the
    tip-history error per case, one marker per ordering/solver."""
    rows = read_csv(csv_path)
    plt = _plt()
    methods = sorted({r["method"] for r in rows})
    cases = sorted({r["case"] for r in rows if r.get("error") not in (None, "")})
    ncol = max(len(methods), len(cases))
    nrow = 2 if cases else 1
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.5 * ncol, 4 * nrow), squeeze=False)
    for ax, m in zip(axes[0], methods):
        for key in sorted({(r["ordering"], r["solver"]) for r in rows if r["method"] == m}):
            sel = [r for r in rows if r["method"] == m and (r["ordering"], r["solver"]) == key]
            for case_marker, case in zip("os^v<>", sorted({r["case"] for r in sel})):
                pts = [r for r in sel if r["case"] == case]
                ax.plot([r["dofs"] for r in pts], [r["hz"] for r in pts], case_marker,
                        label=f"{key[0]}/{key[1]} {case}")
        ax.axhline(50, color="gray", ls=":")
        ax.set(xlabel="DOF", ylabel="steps per second (Hz)", yscale="log", title=m)
        ax.legend(fontsize=5)
    for ax in axes[0][len(methods):]:
        ax.axis("off")
    for ax, case in zip(axes[1] if cases else [], cases):
        sel = [r for r in rows if r["case"] == case and r.get("error") not in (None, "")]
        for m, marker in zip(sorted({r["method"] for r in sel}), "osv^<>Dp"):
            pts = [r for r in sel if r["method"] == m]
            ax.plot([max(r["error"], 1e-16) for r in pts], [r["hz"] for r in pts], marker, label=m)
        ax.axvline(1e-6, color="gray", ls=":")
        ax.set(xlabel="tip-history error vs full Newton (rtol 1e-12)", ylabel="Hz (one core)", xscale="log",
               yscale="log", title=case)
        ax.legend(fontsize=6)
    for ax in (axes[1][len(cases):] if cases else []):
        ax.axis("off")
    fig.tight_layout()
    png = figure_file(outdir, "fem_rate.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


def plot_orderings(csv_path, outdir=".", output=None):
    rows = read_csv(csv_path)
    plt = _plt()
    sources = list(dict.fromkeys(r["source"] for r in rows))
    orders = ["natural", "cm", "rcm", "amd", "metis", "auto"]
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(max(8, 0.6 * len(sources)), 7))
    w = 0.8 / len(orders)
    for i, o in enumerate(orders):
        x = np.arange(len(sources)) + i * w
        get = lambda s, k: next((r[k] for r in rows if r["source"] == s and r["ordering"] == o), np.nan)
        a1.bar(x, [get(s, "nnz_L") for s in sources], w, label=o)
        a2.bar(x, [get(s, "profile") for s in sources], w, label=o)
    for ax, lab in ((a1, "nnz(L)"), (a2, "profile (envelope)")):
        ax.set_xticks(np.arange(len(sources)) + 0.4)
        ax.set_xticklabels(sources, rotation=60, fontsize=7)
        ax.set(yscale="log", ylabel=lab)
    a1.legend(fontsize=7, ncol=6)
    fig.tight_layout()
    png = figure_file(outdir, "fem_orderings.png", output)
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return [str(png)]


def register(sub):
    for name, fn, default, help_text in (
        ("fem-history", plot_history, "femdyn_<stem>_history.png",
         "femdyn energy, tip deflection and step timings from an output file"),
        ("fem-probe", plot_probe, "femdyn_<stem>_probe.png", "femdyn -probe: haptic probe force history"),
        ("fem-material-auto", plot_material_auto, "femdyn_<stem>_material_auto.png",
         "femdyn -material auto: estimate against time with the switch points and the target"),
        ("fem-dt-adapt", plot_time_adapt, "femdyn_<stem>_time_adapt.png",
         "femdyn -dt_adapt: dt of every try (rejections marked), estimate / tolerance, tip deflection"),
        ("fem-rate", plot_rate, "fem_rate.png", "Hz against DOF per ordering and solver (scripts/bench/fem-rate CSV)"),
        ("fem-orderings", plot_orderings, "fem_orderings.png",
         "nnz(L) and profile per ordering (scripts/bench/fem-orderings CSV)"),
    ):
        p = sub.add_parser(name, help=help_text)
        p.add_argument("file")
        add_output_options(p, default)
        p.set_defaults(func=figure_command(fn))
