"""Checks of the contact app on its HDF5 output (run by ctest: test_contact_app.py <contact executable>).

- incline above the friction angle: acceleration g(sin th - mu cos th) and force ratio = mu at each friction
  model's measured accuracy (bounds below);
  below: the box sticks (|v| <= 4e-9; measured 3.8e-10) and the force ratio is tan th;
- splitting from zero and from infinite friction reproduces min(tan th, mu) to 1e-6 (pass counts printed);
- a failing solver is replaced by the fallback and the run records it;
- every mass x 1024: the same solver work and trajectory bitwise (log heap: dense path; pyramid: sparse);
- results identical at 1 and 2 ranks; every sample scene runs without NaN; no energy gain in a drop.
"""
import sys

import h5py
from contact_harness import Harness
import numpy as np

APP = sys.argv[1]
G = 9.81
H = Harness(APP, "contact_test_")
run, check, TMP = H.run, H.check, H.tmp




def downhill(theta):
    th = np.radians(theta)
    return np.array([-np.cos(th), 0.0, -np.sin(th)])


# incline sliding: acceleration and force ratio, per model at its measured accuracy (relative error of a, max
# |ratio - mu|): splitting 2.2e-8 and 1.1e-16, scaled_box 4.9e-13 and 3.6e-7, polyhedral 2.8e-7 and 1.4e-7; the
# bounds sit within 10x of those. A 5% friction loss moves a by mu cos th / (sin th - mu cos th) x 5% = 5.4%.
BOUNDS = {"splitting": (1e-7, 1e-12), "scaled_box": (5e-12, 1e-6), "polyhedral": (1e-6, 1e-6)}
for model in ("splitting", "scaled_box", "polyhedral"):
    th, mu = 30.0, 0.3
    with run(f"slide_{model}", "-scene", "incline", "-theta", th, "-mu", mu, "-friction", model, "-steps", 50,
             "-output_every", 1) as f:
        v = f["/frames/velocities"][:, 1, :3] @ downhill(th)
        t = f["/frames/time"][:]
        a = (v[-1] - v[1]) / (t[-1] - t[1])
        exact = G * (np.sin(np.radians(th)) - mu * np.cos(np.radians(th)))
        ratio = f["/steps/force_ratio"][1 if model == "scaled_box" else 0:]  # scaled_box: bounds from step 1's forces
        ba, br = BOUNDS[model]
        err, dev = abs(a / exact - 1), np.abs(ratio - mu).max()
        check(err <= ba, f"{model}: incline {th} deg mu {mu} slides with a = {a:.12f} (exact {exact:.12f}, relative "
              f"error {err:.2e} <= {ba:g})")
        check(dev <= br, f"{model}: sliding force ratio = mu (max dev {dev:.2e} <= {br:g})")

# incline sticking
with run("stick", "-scene", "incline", "-theta", 20, "-mu", 0.5, "-steps", 200) as f:
    vend = np.linalg.norm(f["/frames/velocities"][-1, 1, :3])
    ratio = f["/steps/force_ratio"][-1]
    check(vend <= 4e-9, f"incline 20 deg mu 0.5 sticks: |v| = {vend:.2e} <= 4e-9")  # measured 3.8e-10
    check(abs(ratio - np.tan(np.radians(20))) < 1e-6, f"sticking force ratio {ratio:.10f} = tan 20 deg")

# splitting from both starts (the paper's Fig. 7): first step of a box at rest
mu = 0.5
for start in ("zero", "infinite"):
    ok = 0
    passes = []
    thetas = [5, 10, 15, 20, 25, 30, 35, 40]
    for th in thetas:
        with run(f"split_{start}_{th}", "-scene", "incline", "-theta", th, "-mu", mu, "-splitting_start", start,
                 "-steps", 1) as f:
            exact = min(np.tan(np.radians(th)), mu)
            r = f["/splitting/force_ratio"][:]
            within = np.nonzero(np.abs(r - exact) > 1e-6)[0]
            passes.append(int(within[-1]) + 2 if len(within) else 1)
            ok += abs(f["/steps/force_ratio"][0] - exact) < 1e-6
    check(ok == len(thetas), f"splitting from {start} friction: {ok}/{len(thetas)} angles reach min(tan th, mu) "
          f"to 1e-6; passes needed {passes}")

# fallback: pgs with one iteration fails, lemke takes over
with run("fallback", "-scene", "incline", "-lcp_solver", "pgs", "-lcp_max_iterations", 1, "-steps", 5) as f:
    names = f["/steps"].attrs["solver_names"]
    names = names.decode() if isinstance(names, bytes) else str(names)
    fb = f["/steps/fallbacks"][:]
    check(fb[0] >= 1 and "lemke" in names.split(",") and np.all(np.isfinite(f["/frames/positions"][:])),
          f"failing solver replaced by the fallback (solvers used: {names}; fallbacks per step {fb.tolist()})")

# -dump_problems writes every problem in the LCP library's HDF5 format
prefix = TMP / "dump"
with run("dump", "-scene", "incline", "-steps", 2, "-dump_problems", prefix) as f:
    passes = int(f["/steps/splitting_iterations"][:].sum())
files = sorted(TMP.glob("dump_step*_pass*.h5"))
ok = len(files) == passes
for p in files:
    with h5py.File(p, "r") as g:
        n = g["/q"].shape[0]
        ok &= g["/M"].shape == (n, n) and g["/l"].shape == (n,) and np.all(np.isfinite(g["/M"][...]))
check(ok, f"-dump_problems wrote {len(files)} problem files (one per splitting pass: {passes})")

# identical at 1 and 2 ranks
a = run("stack_np1", "-scene", "box_stack", "-stack_height", 3, "-steps", 50)
b = run("stack_np2", "-scene", "box_stack", "-stack_height", 3, "-steps", 50, np_=2)
check(np.array_equal(a["/frames/positions"][:], b["/frames/positions"][:]), "box_stack identical at 1 and 2 ranks")
drift = np.abs(a["/frames/positions"][-1] - a["/frames/positions"][0]).max()
check(drift < 1e-6, f"box_stack of 3 stays at rest (drift {drift:.2e})")

# scale-free stopping: every mass x 1024 (a power of two, so every Delassus entry scales exactly) leaves the
# solvers' work and the trajectory bitwise the same; the box LCPs are solved in velocity units (ChainSolve).
# Measured: equal over 100 steps; with the acceptance on impulses in N s the runs part at step 35 (1e-13 m).
light = run("heap_1x", "-scene", "log_heap", "-n_logs", 8, "-steps", 100, "-density", 1000, "-output_every", 1)
heavy = run("heap_1024x", "-scene", "log_heap", "-n_logs", 8, "-steps", 100, "-density", 1024000, "-output_every", 1)
same = all(np.array_equal(light[k][:], heavy[k][:]) for k in
           ("/frames/positions", "/frames/velocities", "/steps/splitting_iterations", "/steps/pivots",
            "/steps/iterations"))
check(same, "log_heap of 8 with every mass x 1024: the same passes, pivots and trajectory bitwise")
# the same on the sparse path (the pyramid of 10: 55 boxes, its problems above -contact_dense_max_rows)
light = run("pyr_1x", "-scene", "pyramid", "-pyramid_base", 10, "-steps", 50, "-density", 1, "-output_every", 1)
heavy = run("pyr_1024x", "-scene", "pyramid", "-pyramid_base", 10, "-steps", 50, "-density", 1024, "-output_every", 1)
same = all(np.array_equal(light[k][:], heavy[k][:]) for k in
           ("/frames/positions", "/frames/velocities", "/steps/splitting_iterations", "/steps/pivots"))
check(same, "pyramid of 10 (sparse path) with every mass x 1024: the same passes, pivots and trajectory bitwise")

# sample scenes: finite, no energy gain in a frictional drop
for name, args in {
    "pyramid": ["-scene", "pyramid", "-pyramid_base", 3, "-steps", 100],
    "log_heap": ["-scene", "log_heap", "-n_logs", 10, "-steps", 150],
    "drop_box": ["-scene", "drop", "-drop_body", "box", "-tilt", 20, "-spin", 3, "-v0", 1, "-steps", 150],
    "drop_cyl": ["-scene", "drop", "-drop_body", "cylinder", "-tilt", 60, "-steps", 150],
}.items():
    with run(name, *args) as f:
        pos = f["/frames/positions"][:]
        check(np.all(np.isfinite(pos)) and f.attrs["status"] in ("completed", b"completed"), f"{name}: runs, finite")
        if name.startswith("drop"):
            e = f["/steps/energy"][:]
            inc = np.max(np.diff(e)) / abs(e[0])
            check(inc <= 1e-8, f"{name}: energy never increases (largest relative step change {inc:.2e})")

H.finish("contact app")
