"""2D/3D euler figures (``euler -dim 2|3``): field images with numerical schlieren, the isentropic-vortex
convergence study (error vs N per scheme with observed orders) and kinetic-energy spectra.

    python -m postprocess euler2d-images run.h5 [--field rho] [--schlieren] [--step N] [-o FILE] [--outdir DIR]
      (a run with a solid obstacle: its cells gray in the field image, left out of the schlieren)
    python -m postprocess euler-vortex-convergence a.h5 b.h5 ... [--norm l1 l2] [-o FILE] [--outdir DIR]
    python -m postprocess euler-spectra a.h5 [b.h5 ...] [-o FILE] [--outdir DIR]

Default names: <stem>_<field>.png, vortex_convergence.png, spectra.png.

File layout (written by the app): root attributes dim, nx, ny, nz, problem, scheme, gamma, time, steps;
/grid/x, /grid/y, /grid/z cell centres; /final/<rho|u|v|w|p> with shape (ny, nx) in 2D and (nz, ny, nx) in 3D;
/errors attributes l1_rho, l2_rho, linf_rho; /spectrum/k, /spectrum/E; /snapshots/<6-digit step>/<field>.

Numerical schlieren (Quirk, ICASE report 92-64, 1992): phi = exp(-k |grad rho| / max |grad rho|), dark where the
density gradient is large (k = 15 by default, --k).
"""
from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np

from .cli import add_output_options, figure_command, figure_file


def _attr(f, name, default=""):
    v = f.attrs.get(name, default)
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, np.generic):
        return v.item()
    return v


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


# ---------------------------------------------------------------- images


def read_field(path, field="rho", step=None, z_index=None):
    """(x, y, values (ny, nx), info dict) of a field at the final time (or snapshot `step`); a z slice of 3D data
    (the middle one unless z_index is given)."""
    with h5py.File(path, "r") as f:
        group = "final" if step is None else f"snapshots/{int(step):06d}"
        if group not in f:
            have = sorted(f["snapshots"]) if "snapshots" in f else []
            raise ValueError(f"{path}: no group /{group}" + (f" (snapshots: {', '.join(have[:10])})" if have else ""))
        if field not in f[group]:
            raise ValueError(f"{path}: no field '{field}' in /{group} (have: {', '.join(sorted(f[group]))})")
        data = f[group][field][...]
        if "grid/x" not in f or "grid/y" not in f:
            raise ValueError(f"{path}: no /grid/x and /grid/y (not a 2D/3D euler file?)")
        x, y = f["grid/x"][...], f["grid/y"][...]
        t = f[group].attrs.get("time", f.attrs.get("time", np.nan))
        info = {"problem": _attr(f, "problem"), "scheme": _attr(f, "scheme"), "time": float(t), "field": field}
        mask = f[group]["mask"][...] if "mask" in f[group] else None  # solid obstacle cells (1), if any
        if data.ndim == 3:
            k = data.shape[0] // 2 if z_index is None else int(z_index)
            if not 0 <= k < data.shape[0]:
                raise ValueError(f"{path}: z index {k} outside 0..{data.shape[0] - 1}")
            z = f["grid/z"][...] if "grid/z" in f else np.arange(data.shape[0], dtype=float)
            info["z"] = float(z[k])
            data = data[k]
            mask = mask[k] if mask is not None else None
        elif data.ndim != 2:
            raise ValueError(f"{path}: /{group}/{field} has shape {data.shape}, expected (ny, nx) or (nz, ny, nx)")
    if data.shape != (len(y), len(x)):
        raise ValueError(f"{path}: field shape {data.shape} does not match the grid (ny, nx) = ({len(y)}, {len(x)})")
    if mask is not None:
        info["mask"] = mask > 0
    return x, y, data, info


def gradient_magnitude(x, y, values):
    """|grad f| of an (ny, nx) array on the cell centres x, y (second-order central differences, one-sided at the
    edges; a direction with a single cell contributes 0)."""
    g2 = np.zeros_like(values, dtype=float)
    if len(y) > 1:
        g2 += np.gradient(values, y, axis=0) ** 2
    if len(x) > 1:
        g2 += np.gradient(values, x, axis=1) ** 2
    return np.sqrt(g2)


def schlieren(x, y, rho, k=15.0):
    """Numerical schlieren exp(-k |grad rho| / max |grad rho|) (1 everywhere for a uniform field)."""
    g = gradient_magnitude(x, y, rho)
    gmax = float(np.nanmax(g)) if g.size and np.isfinite(g).any() else 0.0
    if not np.isfinite(gmax) or gmax <= 0.0:
        return np.ones_like(g)
    return np.exp(-k * g / gmax)


def plot_images(path, outdir=".", output=None, field="rho", with_schlieren=False, k=15.0, step=None, z_index=None):
    plt = _plt()
    x, y, v, info = read_field(path, field, step, z_index)
    dx = x[1] - x[0] if len(x) > 1 else 1.0
    dy = y[1] - y[0] if len(y) > 1 else 1.0
    extent = [x[0] - dx / 2, x[-1] + dx / 2, y[0] - dy / 2, y[-1] + dy / 2]
    panels = 2 if with_schlieren else 1
    aspect = (extent[3] - extent[2]) / max(extent[1] - extent[0], 1e-300)
    width = 5.5 * panels
    fig, axes = plt.subplots(1, panels, figsize=(width, max(2.5, min(12.0, 5.0 * aspect)) + 0.8), squeeze=False)
    ax = axes[0][0]
    solid = info.get("mask")
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad("0.55")  # solid obstacle cells: gray
    shown = np.ma.masked_where(solid, v) if solid is not None else v
    im = ax.imshow(shown, origin="lower", extent=extent, cmap=cmap, interpolation="nearest")
    fig.colorbar(im, ax=ax, label=field, shrink=0.8)
    ax.set(xlabel="x", ylabel="y", title=field)
    if with_schlieren:
        ax = axes[0][1]
        # solid cells are left out of the gradients (NaN: their faces to the fluid are walls, not density jumps)
        s = schlieren(x, y, np.where(solid, np.nan, v), k) if solid is not None else schlieren(x, y, v, k)
        gray = plt.get_cmap("gray").copy()
        gray.set_bad("tab:blue")
        ax.imshow(np.ma.masked_invalid(s), origin="lower", extent=extent, cmap=gray, vmin=0, vmax=1,
                  interpolation="nearest")
        ax.set(xlabel="x", ylabel="y", title=f"schlieren of {field} (k = {k:g})")
    where = f", z = {info['z']:.4g}" if "z" in info else ""
    fig.suptitle(f"{info['problem']} / {info['scheme']}, {len(x)} x {len(y)}, t = {info['time']:.4g}{where}",
                 fontsize=10)
    fig.tight_layout()
    out = figure_file(outdir, f"{Path(path).stem}_{field}.png", output)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return [str(out)]


# ---------------------------------------------------------------- convergence


def read_errors(paths):
    """{scheme: [(N, {norm: error})]} sorted by N, from the /errors attributes of several output files. N = nx."""
    res = {}
    for p in paths:
        with h5py.File(p, "r") as f:
            if "errors" in f:
                errs = {k: float(v) for k, v in f["errors"].attrs.items()}
            else:  # the 1D app's layout: root attributes error_l1_rho, ...
                errs = {k[len("error_"):]: float(v) for k, v in f.attrs.items() if k.startswith("error_")}
            if not errs:
                raise ValueError(f"{p}: no /errors attributes (run with an exact solution and error output)")
            n = int(_attr(f, "nx", 0))
            if n <= 0:
                raise ValueError(f"{p}: no root attribute nx")
            res.setdefault(str(_attr(f, "scheme", "?")), []).append((n, errs))
    for scheme, rows in res.items():
        rows.sort(key=lambda r: r[0])
        ns = [r[0] for r in rows]
        if len(set(ns)) != len(ns):
            raise ValueError(f"scheme {scheme}: several files with the same N ({ns})")
    return res


def observed_orders(ns, errors):
    """Orders log(e_i / e_{i+1}) / log(N_{i+1} / N_i) between successive resolutions (len(ns) - 1 values; NaN
    where an error is not positive)."""
    ns = np.asarray(ns, dtype=float)
    e = np.asarray(errors, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        o = np.log(e[:-1] / e[1:]) / np.log(ns[1:] / ns[:-1])
    return np.where((e[:-1] > 0) & (e[1:] > 0), o, np.nan)


def fitted_order(ns, errors):
    """Least-squares slope -d log e / d log N over all positive errors (NaN with fewer than two)."""
    ns, e = np.asarray(ns, dtype=float), np.asarray(errors, dtype=float)
    ok = (e > 0) & np.isfinite(e)
    if ok.sum() < 2:
        return float("nan")
    return float(-np.polyfit(np.log(ns[ok]), np.log(e[ok]), 1)[0])


def convergence_table(res, norms=("l1", "l2")):
    """Text table: scheme, N, error per norm and the observed order against the previous N."""
    lines = []
    head = f"{'scheme':<14}{'N':>7}" + "".join(f"{n + '_rho':>14}{'order':>8}" for n in norms)
    lines.append(head)
    for scheme, rows in sorted(res.items()):
        ns = [r[0] for r in rows]
        orders = {n: observed_orders(ns, [r[1].get(f"{n}_rho", np.nan) for r in rows]) for n in norms}
        for i, (n, errs) in enumerate(rows):
            cells = ""
            for norm in norms:
                o = orders[norm][i - 1] if i > 0 else np.nan
                cells += f"{errs.get(f'{norm}_rho', np.nan):>14.4e}" + (f"{o:>8.2f}" if i > 0 else f"{'-':>8}")
            lines.append(f"{scheme:<14}{n:>7d}{cells}")
    return "\n".join(lines)


def plot_vortex_convergence(paths, outdir=".", output=None, norms=("l1", "l2")):
    plt = _plt()
    res = read_errors(paths)
    table = convergence_table(res, norms)
    print(table)
    fig, axes = plt.subplots(1, len(norms), figsize=(5.5 * len(norms), 4.5), squeeze=False)
    for ax, norm in zip(axes[0], norms):
        for scheme, rows in sorted(res.items()):
            ns = np.array([r[0] for r in rows], dtype=float)
            e = np.array([r[1].get(f"{norm}_rho", np.nan) for r in rows])
            ok = np.isfinite(e) & (e > 0)
            if not ok.any():
                continue
            o = fitted_order(ns, e)
            line, = ax.loglog(ns[ok], e[ok], "o-", label=f"{scheme} (slope {o:.2f})")
            if ok.sum() >= 2 and np.isfinite(o):  # reference slope through the finest point, dotted
                n0, e0 = ns[ok][-1], e[ok][-1]
                ax.loglog(ns[ok], e0 * (ns[ok] / n0) ** (-round(o)), ":", color=line.get_color(), lw=1)
        ax.set(xlabel="N (cells per direction)", ylabel=f"{norm.upper()} error of rho",
               title=f"{norm.upper()} density error")
        ax.legend(fontsize=8)
    fig.suptitle("isentropic vortex convergence (dotted: integer slope through the finest point)", fontsize=10)
    fig.tight_layout()
    out = figure_file(outdir, "vortex_convergence.png", output)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return [str(out)]


# ---------------------------------------------------------------- spectra


def read_spectrum(path):
    """(k, E, label) from /spectrum/k and /spectrum/E, without k <= 0 and E <= 0 entries."""
    with h5py.File(path, "r") as f:
        if "spectrum" not in f or "k" not in f["spectrum"] or "E" not in f["spectrum"]:
            raise ValueError(f"{path}: no /spectrum/k and /spectrum/E (run with the spectrum output enabled)")
        k, e = f["spectrum/k"][...].astype(float), f["spectrum/E"][...].astype(float)
        label = f"{_attr(f, 'scheme', '?')} N={_attr(f, 'nx', '?')} t={float(_attr(f, 'time', np.nan)):.3g}"
    if k.shape != e.shape:
        raise ValueError(f"{path}: /spectrum/k {k.shape} and /spectrum/E {e.shape} differ in shape")
    ok = (k > 0) & (e > 0) & np.isfinite(e)
    return k[ok], e[ok], label


def kolmogorov_guide(k, e):
    """A k^-5/3 line through the energy-containing peak (k_p, E(k_p)), over k >= k_p: (k, E(k_p) (k / k_p)^-5/3)."""
    i = int(np.argmax(e))
    kk = k[i:]
    return kk, e[i] * (kk / k[i]) ** (-5.0 / 3.0)


def plot_spectra(paths, outdir=".", output=None, name="spectra.png"):
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6, 4.8))
    first, emax = None, 0.0
    for p in paths:
        k, e, label = read_spectrum(p)
        if len(k) == 0:
            raise ValueError(f"{p}: spectrum has no positive entries")
        ax.loglog(k, e, "-", label=label)
        first = first or (k, e)
        emax = max(emax, float(e.max()))
    gk, ge = kolmogorov_guide(*first)
    ax.loglog(gk, ge, "k--", lw=1, label="k^-5/3 (through the peak)")
    ax.set_ylim(bottom=emax * 1e-12, top=emax * 3)  # round-off tails below 1e-12 of the peak are not shown
    ax.set(xlabel="k", ylabel="E(k)", title="kinetic energy spectrum")
    ax.legend(fontsize=8)
    fig.tight_layout()
    out = figure_file(outdir, name, output)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return [str(out)]


def default_plot(h5path, outdir=".", output=None):
    """Density image with schlieren (<stem>_rho.png), plus the spectrum (<stem>_spectrum.png) when the file has
    one (for `plot` on 2D/3D files); `output` names the image."""
    out = plot_images(h5path, outdir, output, "rho", True)
    with h5py.File(h5path, "r") as f:
        has_spec = "spectrum" in f
    if has_spec:
        out += plot_spectra([h5path], outdir, name=f"{Path(h5path).stem}_spectrum.png")
    return out


# ---------------------------------------------------------------- command line


def register(sub):
    p = sub.add_parser("euler2d-images", help="euler 2D/3D: field image (z slice in 3D) and numerical schlieren")
    p.add_argument("file")
    p.add_argument("--field", default="rho", help="rho, u, v, w or p (default rho)")
    p.add_argument("--schlieren", action="store_true", help="add a numerical schlieren panel")
    p.add_argument("--k", type=float, default=15.0, help="schlieren contrast (default 15)")
    p.add_argument("--step", type=int, default=None, help="snapshot step instead of /final")
    p.add_argument("--z-index", type=int, default=None, help="z slice of 3D data (default: the middle one)")
    add_output_options(p, "<stem>_<field>.png")
    p.set_defaults(func=figure_command(plot_images, field="field", with_schlieren="schlieren", k="k", step="step",
                                       z_index="z_index"))

    p = sub.add_parser("euler-vortex-convergence",
                       help="euler 2D/3D: density error vs N per scheme with observed orders (from /errors)")
    p.add_argument("files", nargs="+")
    p.add_argument("--norm", nargs="+", default=["l1", "l2"], choices=["l1", "l2", "linf"])
    add_output_options(p, "vortex_convergence.png")
    p.set_defaults(func=figure_command(plot_vortex_convergence, inputs="files", norms=lambda a: tuple(a.norm)))

    p = sub.add_parser("euler-spectra", help="euler 2D/3D: kinetic energy spectra E(k) with a k^-5/3 guide")
    p.add_argument("files", nargs="+")
    add_output_options(p, "spectra.png")
    p.set_defaults(func=figure_command(plot_spectra, inputs="files"))
