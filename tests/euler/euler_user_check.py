#!/usr/bin/env python3
"""Checks of a user's own Euler problems (docs/euler_user_problems.md): initial states from HDF5 files and from
formulas, boundary conditions per face, solid obstacles. Each asserts bitwise equality with the registered run it
must reproduce, or a stated round-off or discretisation bound with its measured value.

Needs numpy and h5py. Usage: euler_user_check.py CHECK [NP]
"""
import math
import os
import sys
import tempfile

import h5py
import numpy as np

from euler_harness import check, run

TMP = tempfile.mkdtemp(prefix="euler_user_")
NP = int(sys.argv[2]) if len(sys.argv) > 2 else 1


def path(name):
    return os.path.join(TMP, name)


def final(p, names=None):
    with h5py.File(p, "r") as f:
        g = f["/final"]
        return {k: g[k][...] for k in (names or g.keys()) if k in g}


def same(a, b, keys=("rho", "u", "v", "w", "p")):
    return all(np.array_equal(a[k], b[k]) for k in keys if k in a)


def max_rel(a, b, keys=("rho", "u", "p")):
    return max(np.abs(a[k] - b[k]).max() / max(np.abs(a[k]).max(), 1.0) for k in keys if k in a)


# The registered runs written as files: (label, registered args, faces the file run names itself)
ROUNDTRIP = [
    ("sod", ["-problem", "sod", "-nx", "100"], []),
    ("shu_osher", ["-problem", "shu_osher", "-nx", "100", "-t_final", "0.5"],
     ["-bc_x_lo", "inflow", "-bc_x_lo_state", "3.857143, 2.629369, 10.33333"]),
    ("density_wave", ["-problem", "density_wave", "-nx", "64", "-t_final", "0.5"],
     ["-bc_x_lo", "periodic", "-bc_x_hi", "periodic"]),
    ("isentropic_vortex", ["-dim", "2", "-problem", "isentropic_vortex", "-nx", "32", "-ny", "32", "-t_final", "1"],
     ["-bc_x_lo", "periodic", "-bc_x_hi", "periodic", "-bc_y_lo", "periodic", "-bc_y_hi", "periodic"]),
    ("lax_liu_6", ["-dim", "2", "-problem", "lax_liu_6", "-nx", "48", "-ny", "48", "-t_final", "0.1"], []),
    ("explosion", ["-dim", "3", "-problem", "explosion", "-nx", "24", "-ny", "24", "-nz", "24", "-t_final", "0.05"],
     []),
]


def t_final_of(args, out):
    if "-t_final" in args:
        return args[args.index("-t_final") + 1]
    with h5py.File(out, "r") as f:
        return repr(float(f.attrs["time"]))


def file_roundtrip():
    """Every registered case's own initial output (-output_initial: /initial, conservative) read back by
    -problem file reproduces the registered run bitwise, at NP ranks, and the primitive /final of one run is a
    valid input too (the same state to the round-off of the primitive round trip)."""
    for label, args, faces in ROUNDTRIP:
        ref = path(f"{label}_ref.h5")
        run(args + ["-output", ref, "-output_initial"], np_=NP)
        got = path(f"{label}_file.h5")
        run(dims_only(args) + ["-problem", "file", "-initial_state", ref, "-initial_group", "/initial",
                               "-t_final", t_final_of(args, ref), "-output", got] + faces, np_=NP)
        check(same(final(ref), final(got)), f"{label}: -problem file from /initial equals the registered run bitwise "
              f"at {NP} rank(s)")
    # A run's /final as the next run's initial state (primitive datasets, extents and gamma from the file)
    first = path("sod_ref.h5")
    nxt = path("sod_next.h5")
    run(["-problem", "file", "-initial_state", first, "-initial_group", "/final", "-t_final", "0.01",
         "-max_steps", "1", "-output", nxt, "-output_initial"], np_=NP)
    with h5py.File(first, "r") as f, h5py.File(nxt, "r") as g:
        rho0, rho1 = f["/final/rho"][...], g["/initial/rho"][...]
        check(g.attrs["xmin"] == f.attrs["xmin"] and g.attrs["xmax"] == f.attrs["xmax"],
              "the file's xmin/xmax became the run's domain")
    check(np.array_equal(rho0, rho1), "/final read back as primitive: the density unchanged bitwise")


def dims_only(args):
    out = []
    for i, a in enumerate(args):
        if a in ("-dim",):
            out += [a, args[i + 1]]
    return out


FORMULAS = [
    # label, registered args, formula args (bitwise: piecewise-constant states)
    ("sod", ["-problem", "sod", "-nx", "200"],
     ["-ic_rho", "x < 0.5 ? 1 : 0.125", "-ic_p", "x < 0.5 ? 1 : 0.1", "-nx", "200", "-t_final", "0.2"]),
    ("lax_liu_6", ["-dim", "2", "-problem", "lax_liu_6", "-nx", "48", "-ny", "48", "-t_final", "0.1"],
     ["-dim", "2", "-nx", "48", "-ny", "48", "-t_final", "0.1",
      "-ic_rho", "y > 0.5 ? (x > 0.5 ? 1 : 2) : (x > 0.5 ? 3 : 1)",
      "-ic_u", "y > 0.5 ? 0.75 : -0.75", "-ic_v", "x > 0.5 ? (y > 0.5 ? -0.5 : -0.5) : 0.5", "-ic_p", "1"]),
    ("explosion", ["-dim", "3", "-problem", "explosion", "-nx", "24", "-ny", "24", "-nz", "24", "-t_final", "0.05"],
     ["-dim", "3", "-nx", "24", "-ny", "24", "-nz", "24", "-t_final", "0.05", "-xmin", "-1", "-xmax", "1",
      "-ymin", "-1", "-ymax", "1", "-zmin", "-1", "-zmax", "1", "-ic_param", "r0=0.4",
      "-ic_rho", "x*x + y*y + z*z < r0*r0 ? 1 : 0.125", "-ic_p", "x*x + y*y + z*z < r0*r0 ? 1 : 0.1"]),
]


def formula():
    """Piecewise-constant registered problems as formulas: bitwise at NP ranks; smooth formulas (the density
    wave in 1D and planar 2D) within 1e-13 relative in the final state (measured 0: the same operations as the
    registered problem's, with _pi at double precision)."""
    for label, reg, form in FORMULAS:
        a, b = path(f"{label}_reg.h5"), path(f"{label}_formula.h5")
        run(reg + ["-output", a], np_=NP)
        run(["-problem", "formula"] + form + ["-output", b], np_=NP)
        check(same(final(a), final(b)), f"{label}: -problem formula equals the registered run bitwise at {NP} rank(s)")
    for dim in (1, 2):
        extra = ["-dim", "2", "-ny", "6"] if dim == 2 else []
        a, b = path(f"dw{dim}_reg.h5"), path(f"dw{dim}_formula.h5")
        run(["-problem", "density_wave", "-nx", "64", "-t_final", "0.5", "-output", a] + extra, np_=NP)
        run(["-problem", "formula", "-nx", "64", "-t_final", "0.5", "-xmin", "-1", "-xmax", "1",
             "-ic_rho", "1 + A*sin(_pi*x)", "-ic_param", "A=0.2", "-ic_u", "1", "-ic_p", "1",
             "-bc_x_lo", "periodic", "-bc_x_hi", "periodic", "-output", b] +
            (extra + ["-bc_y_lo", "periodic", "-bc_y_hi", "periodic"] if dim == 2 else []), np_=NP)
        d = max_rel(final(a), final(b))
        check(d <= 1e-13, f"density wave ({dim}D) as a formula: final state within {d:.2e} relative (<= 1e-13)")


def exact_average_density_wave(n, t, amp=0.2):
    # cell averages of rho = 1 + A sin(pi (x - t)) over [-1, 1] with n cells (closed form)
    x = -1.0 + 2.0 * np.arange(n + 1) / n
    F = -amp / math.pi * np.cos(math.pi * (x - t))
    return 1.0 + (F[1:] - F[:-1]) / (2.0 / n)


def average():
    """-ic_average: cell averages of the conservative state. The density wave (linear advection of rho, so
    averaging commutes with the flow) keeps the scheme's order against the exact cell averages: enopade6 L1
    order >= 5.5 from 32 to 64 cells (measured 5.9); the point-value default is the scheme's own (measured order
    identical). The averages differ from the point values by dx^2/24 rho'': checked at 32 cells to 2% of that
    estimate."""
    errs = []
    for n in (32, 64):
        out = path(f"avg{n}.h5")
        run(["-problem", "formula", "-nx", str(n), "-t_final", "0.5", "-xmin", "-1", "-xmax", "1", "-time", "rk4",
             "-dt", str(0.1 / n), "-ic_rho", "1 + 0.2*sin(_pi*x)", "-ic_u", "1", "-ic_p", "1", "-ic_average",
             "-bc_x_lo", "periodic", "-bc_x_hi", "periodic", "-output", out, "-output_initial"], np_=NP)
        with h5py.File(out, "r") as f:
            rho, rho0 = f["/final/rho"][...], f["/initial/rho"][...]
        errs.append(np.abs(rho - exact_average_density_wave(n, 0.5)).mean())
        if n == 32:
            x = -1.0 + (np.arange(n) + 0.5) * 2.0 / n
            diff = rho0 - (1.0 + 0.2 * np.sin(math.pi * x))
            estimate = -(2.0 / n) ** 2 / 24.0 * 0.2 * math.pi ** 2 * np.sin(math.pi * x)
            rel = np.abs(diff - estimate).max() / np.abs(estimate).max()
            check(rel < 0.02, f"initial averages - point values = dx^2/24 rho'' to {rel:.2e} of it (< 2%)")
    order = math.log(errs[0] / errs[1]) / math.log(2.0)
    check(order >= 5.5, f"-ic_average density wave: L1 against exact averages {errs[0]:.3e} -> {errs[1]:.3e}, "
          f"order {order:.2f} (>= 5.5)")


def faces():
    """Boundary conditions per face: a wall-bounded 1D blast from a formula and -bc_* equals `blast` bitwise;
    a supersonic inflow face holds its state (the 10 cells next to it equal it to 1e-12 relative once the start-up
    wave has left, measured 7.1e-13); symmetry planes equal the mirrored full domain to round-off (<= 1e-12 relative, 2D explosion
    quarter against the whole, explicit schemes)."""
    a, b = path("blast_reg.h5"), path("blast_formula.h5")
    run(["-problem", "blast", "-nx", "200", "-output", a], np_=NP)
    run(["-problem", "formula", "-nx", "200", "-t_final", "0.038", "-ic_rho", "1",
         "-ic_p", "x < 0.1 ? 1000 : (x < 0.9 ? 0.01 : 100)", "-bc_x_lo", "wall", "-bc_x_hi", "wall",
         "-output", b], np_=NP)
    check(same(final(a), final(b)), "wall-bounded blast from -bc_x_lo/-bc_x_hi wall equals blast bitwise")
    c = path("inflow.h5")
    run(["-problem", "formula", "-nx", "100", "-t_final", "0.5", "-ic_rho", "1", "-ic_p", "1",
         "-bc_x_lo", "inflow", "-bc_x_lo_state", "2, 3, 1.5", "-output", c], np_=NP)
    fc = final(c)
    dev = max(abs(fc["rho"][:10] - 2).max() / 2, abs(fc["u"][:10] - 3).max() / 3, abs(fc["p"][:10] - 1.5).max() / 1.5)
    check(dev <= 1e-12, f"supersonic inflow face state held in the 10 cells next to it to {dev:.1e} (<= 1e-12)")
    # Symmetry planes: the explicit schemes' boundary faces take their interior rows on the mirrored ghosts, so
    # the quarter equals the whole domain's quarter to round-off (measured 1.3e-15 weno5, 7.8e-16 muscl2); the
    # compact schemes close their line systems at every domain face with explicit boundary rows (measured 3.8e-3
    # enopade6, 7.9e-3 crweno5 near the planes: docs/euler_user_problems.md).
    for scheme in ("weno5", "muscl2"):
        q, w = path(f"quarter_{scheme}.h5"), path(f"whole_{scheme}.h5")
        common = ["-dim", "2", "-problem", "explosion", "-scheme", scheme, "-t_final", "0.1"]
        run(common + ["-nx", "80", "-ny", "80", "-output", w], np_=NP)
        run(common + ["-nx", "40", "-ny", "40", "-xmin", "0", "-ymin", "0", "-bc_x_lo", "symmetry", "-bc_y_lo",
                      "symmetry", "-output", q], np_=NP)
        fq, fw = final(q), final(w)
        d = max(np.abs(fq[k] - fw[k][40:, 40:]).max() / np.abs(fw[k]).max() for k in ("rho", "u", "v", "p"))
        check(d <= 1e-14, f"{scheme} symmetry faces: quarter domain = the whole one's quarter to {d:.1e} relative "
              "(<= 1e-14)")


def obstacle():
    """A solid half-domain aligned with the grid is exactly a wall there: Sod reflecting off x = 0.75 (1D and
    planar 2D, enopade6 and weno5) bitwise equal to the domain [0, 0.75] with a wall face, at NP ranks against
    1; mass and energy in a closed box with a pillar conserved to round-off (<= 1e-13 relative, measured 6.0e-16 and
    1.7e-15)."""
    for dim, scheme in ((1, "enopade6"), (1, "weno5"), (2, "enopade6"), (2, "crweno5")):
        extra = ["-dim", "2"] if dim == 2 else []
        wall, solid = path(f"wall{dim}{scheme}.h5"), path(f"solid{dim}{scheme}.h5")
        run(extra + ["-problem", "sod", "-scheme", scheme, "-xmax", "0.75", "-nx", "150", "-t_final", "0.4",
                     "-bc_x_hi", "wall", "-output", wall])
        run(extra + ["-problem", "sod", "-scheme", scheme, "-nx", "200", "-t_final", "0.4", "-solid", "x - 0.75",
                     "-output", solid], np_=NP)
        fw, fs = final(wall), final(solid)
        ok = all(np.array_equal(fw[k], fs[k][..., :150]) for k in ("rho", "u", "p"))
        check(ok, f"{dim}D {scheme}: solid x > 0.75 at {NP} rank(s) = wall at x = 0.75 bitwise")
        check(fs["mask"][..., 150:].min() == 1 and fs["mask"][..., :150].max() == 0, "mask field marks the solid")
    box = path("box.h5")
    out = run(["-dim", "2", "-problem", "explosion", "-closed_box", "-nx", "64", "-ny", "64", "-t_final", "0.5",
               "-solid", "0.04 - (x-0.5)^2 - (y-0.3)^2", "-output", box], np_=NP)
    with h5py.File(box, "r") as f:
        t0, t1 = f.attrs["totals_initial"], f.attrs["totals_final"]
    rel = [abs(t1[c] - t0[c]) / abs(t0[c]) for c in (0, 3)]
    check(max(rel) <= 1e-13, f"closed box with a pillar: mass and energy change {rel[0]:.1e}, {rel[1]:.1e} (<= 1e-13)")
    check("solid obstacle of" in out, "the run reports its solid cells")


def shock_position(row, x, lo, hi):
    """x of the largest density rise (a shock met by the flow, which runs along +x) along `row` in (lo, hi)."""
    k = np.where((x[:-1] > lo) & (x[1:] < hi))[0]
    j = k[np.argmax(np.diff(row)[k])]
    return 0.5 * (x[j] + x[j + 1])


def step_features(p):
    with h5py.File(p, "r") as f:
        rho, mask = f["/final/rho"][...], f["/final/mask"][...]
        x, y = f["/grid/x"][...], f["/grid/y"][...]
    ny = len(y)
    bow = shock_position(rho[int(0.1 * ny)], x, 0.0, 0.6)   # y = 0.1: the bow shock ahead of the step
    stem = shock_position(rho[-1], x, 0.0, 1.5)              # the top wall: the Mach stem's foot
    # the reflected shock on its way to the step's top, at y = 0.3 (above the entropy layer the corner leaves on
    # the step's top, whose density rise the search would take instead)
    refl = shock_position(rho[int(0.3 * ny)], x, 0.7, 2.5)
    top2 = shock_position(rho[-1], x, 1.5, 3.0)              # its reflection meeting the top wall
    return {"bow shock x (y = 0.1)": bow, "Mach stem x (top wall)": stem, "reflected shock x (y = 0.3)": refl,
            "second reflection x (top wall)": top2}, rho[mask == 0].min()


def forward_step():
    """Woodward & Colella's forward step at t = 4 (weno5, 240 x 80 and 480 x 160): the bow shock, the Mach stem's
    foot on the top wall and the reflected shock above the step agree between the grids within two coarse cells
    (2/80; measured 0, 1.0 and 0.5 cells); the second reflection on the top wall within four (measured 3.5: the
    coarse grid smears its Mach-type foot). Every scheme stays positive at 120 x 40 (density and pressure > 0 in
    every fluid cell; the run stops otherwise)."""
    feats = []
    for n in (240, 480):
        p = path(f"step{n}.h5")
        run(["-dim", "2", "-problem", "forward_step", "-scheme", "weno5", "-nx", str(n), "-ny", str(n // 3),
             "-output", p])
        f, rmin = step_features(p)
        feats.append(f)
        print(f"grid {n} x {n // 3}: " + ", ".join(f"{k} {v:.4f}" for k, v in f.items()) + f", min rho {rmin:.3f}")
    for k in feats[0]:
        d, bound = abs(feats[0][k] - feats[1][k]), 4.0 if k.startswith("second") else 2.0
        check(d <= bound / 80.0, f"{k}: {feats[0][k]:.4f} vs {feats[1][k]:.4f} ({d * 80:.2f} coarse cells, "
              f"<= {bound:g})")
    for scheme in ("enopade6", "crweno5", "weno5", "muscl2"):
        p = path(f"step_{scheme}.h5")
        run(["-dim", "2", "-problem", "forward_step", "-scheme", scheme, "-nx", "120", "-ny", "40", "-output", p])
        with h5py.File(p, "r") as f:
            m = f["/final/mask"][...] == 0
            rmin, pmin = f["/final/rho"][...][m].min(), f["/final/p"][...][m].min()
        check(rmin > 0 and pmin > 0, f"{scheme}: forward step to t = 4 positive (min rho {rmin:.3f}, min p {pmin:.3f})")


def obstacle_ranks():
    """The forward step and the shock over a cylinder at 2 ranks equal 1 rank bitwise (enopade6, 40 steps), and
    the 3D shock over a sphere (weno5, 10 steps)."""
    cases = [["-dim", "2", "-problem", "forward_step", "-nx", "96", "-ny", "32", "-max_steps", "40"],
             ["-dim", "2", "-problem", "shock_cylinder", "-nx", "80", "-ny", "60", "-max_steps", "40"],
             ["-dim", "3", "-problem", "shock_sphere", "-scheme", "weno5", "-nx", "32", "-ny", "24", "-nz", "24",
              "-max_steps", "10"]]
    for i, args in enumerate(cases):
        a, b = path(f"r1_{i}.h5"), path(f"r2_{i}.h5")
        run(args + ["-output", a])
        run(args + ["-output", b], np_=2)
        check(same(final(a), final(b)), f"{args[3]}: 2 ranks = 1 rank bitwise")


def bad_input():
    """Bad user input: one error naming the dataset, cell, option or position, and a non-zero exit, at NP ranks."""
    x = np.ones((10, 20))

    def write(name, **sets):
        with h5py.File(path(name), "w") as f:
            for k, v in sets.items():
                f[k] = v
        return path(name)

    neg_p = x.copy()
    neg_p[3, 7] = -2.0
    nan_rho = x.copy()
    nan_rho[9, 19] = np.nan
    files = {
        "negative pressure": (write("neg.h5", rho=x, u=0 * x, v=0 * x, p=neg_p),
                              r"dataset /p holds -2 at cell \(i, j\) = \(7, 3\): pressure must be > 0"),
        "missing dataset": (write("missing.h5", rho=x, u=0 * x, p=x), r"missing dataset /v of the primitive 2D"),
        "extra dataset": (write("extra.h5", rho=x, u=0 * x, v=0 * x, p=x, pressure=x),
                          r"dataset /pressure is not part of a 2D initial state"),
        "mixed sets": (write("mixed.h5", rho=x, u=0 * x, v=0 * x, p=x, E=x), r"mixes primitive .* and conservative"),
        "wrong shape": (write("shape.h5", rho=x, u=0 * x, v=np.zeros((10, 19)), p=x),
                        r"dataset /v has another shape than /rho"),
        "NaN": (write("nan.h5", rho=nan_rho, u=0 * x, v=0 * x, p=x),
                r"dataset /rho holds nan at cell \(i, j\) = \(19, 9\): initial values must be finite"),
    }
    cases = [(k, ["-dim", "2", "-problem", "file", "-initial_state", f, "-t_final", "1"], m)
             for k, (f, m) in files.items()]
    good = write("good.h5", rho=x, u=0 * x, v=0 * x, p=x)
    f2 = ["-dim", "2", "-problem", "formula", "-nx", "20", "-ny", "10", "-t_final", "1", "-ic_rho", "1", "-ic_p", "1"]
    cases += [
        ("grid change", ["-dim", "2", "-problem", "file", "-initial_state", good, "-t_final", "1", "-nx", "30"],
         r"-nx 30 differs from the 20 cells along x of -initial_state"),
        ("no file", ["-problem", "file", "-t_final", "1"], r"-problem file needs -initial_state FILE.h5"),
        ("syntax", ["-problem", "formula", "-ic_rho", "1 + (x", "-ic_p", "1", "-nx", "10", "-t_final", "1"],
         r'Cannot parse -ic_rho "1 \+ \(x": Missing parenthesis \(at position 8'),
        ("negative density", ["-problem", "formula", "-ic_rho", "x - 0.3", "-ic_p", "1", "-nx", "10", "-t_final", "1"],
         r"-ic_rho evaluates to -0.25 at cell \(0, 0, 0\), x = \(0.05, 0, 0\): density must be > 0"),
        ("NaN formula", ["-problem", "formula", "-ic_rho", "1", "-ic_p", "sqrt(0.5 - x)", "-nx", "10", "-t_final", "1"],
         r"-ic_p evaluates to -?nan at cell \(5, 0, 0\)"),
        ("no t_final", ["-problem", "formula", "-ic_rho", "1", "-ic_p", "1", "-nx", "10"], r"needs -t_final"),
        ("no nx", ["-problem", "formula", "-ic_rho", "1", "-ic_p", "1", "-t_final", "1"], r"needs -nx"),
        ("unknown name", ["-problem", "formula", "-ic_rho", "1 + a", "-ic_p", "1", "-nx", "10", "-t_final", "1"],
         r'Cannot parse -ic_rho "1 \+ a": Unexpected token "a"'),
        ("param clash", ["-problem", "formula", "-ic_rho", "1", "-ic_p", "1", "-nx", "10", "-t_final", "1",
                         "-ic_param", "x=2"], r'Invalid -ic_param name "x": it is a variable'),
        ("unpaired periodic", f2 + ["-bc_x_lo", "periodic"],
         r"Periodic boundaries come in pairs: -bc_x_lo periodic with -bc_x_hi outflow"),
        ("inflow state count", f2 + ["-bc_y_hi", "inflow", "-bc_y_hi_state", "1,2"],
         r'-bc_y_hi_state "1,2" has 2 entries; a 2D state has 4: rho,u,v,p'),
        ("inflow without state", f2 + ["-bc_y_hi", "inflow"], r"-bc_y_hi inflow needs -bc_y_hi_state"),
        ("two names of a face", ["-problem", "sod", "-bc_left", "outflow", "-bc_x_lo", "wall"],
         r"-bc_x_lo and -bc_left name the same face"),
        ("no fluid", f2 + ["-solid", "1"], r"The solid obstacle covers every cell: no fluid is left"),
        ("narrow gap", f2 + ["-solid", "x > 0.15 && x < 0.6 ? 1 : -1"],
         r"the solid leaves a fluid gap of 3 cell\(s\) .*a fluid segment needs at least 6 cells"),
        ("solid and preset", ["-dim", "2", "-problem", "forward_step", "-solid", "1"],
         r"-problem forward_step has its obstacle built in"),
        ("solid and -error", ["-problem", "sod", "-solid", "x - 0.9", "-error"], r"-error with a solid obstacle"),
        ("mask file shape", f2 + ["-solid_mask", good], r"missing dataset /mask"),
    ]
    import re
    for label, args, pattern in cases:
        out, code = run(args, np_=NP, expect_ok=False, with_code=True)
        found = re.search(pattern, out) is not None
        check(code != 0 and found and out.count("ERROR:") == 1,
              f"{label}: exit {code}, one ERROR line matching '{pattern}'")


CHECKS = {f.__name__: f for f in (file_roundtrip, formula, average, faces, obstacle, forward_step, obstacle_ranks,
                                    bad_input)}

if __name__ == "__main__":
    CHECKS[sys.argv[1]]()
