"""-friction auto -target_error E on the contact app's HDF5 output (run by ctest: test_friction_auto.py
<contact>). E = 1e-3 throughout; the cone violation is /steps/cone_violation (sum max(0, |l_t| - mu l_n) / sum l_n).

- incline 30 deg, mu 0.3 (slides): speed after 1 s = g (sin 30 - mu cos 30) = 2.3563 m/s to 4 digits and the force
  ratio = mu to 4 digits in every step; mu 0.7 (sticks): the box creeps <= 1e-8 m in 2 s, force ratio tan 30;
- a resting stack of 10 boxes: drift < 1e-6 m over 2 s (islands off: one problem);
- every step's cone violation <= E, and every problem's (/friction_auto/cone_violation), in every run here;
- mu = 0: the ladder is the frictionless rows alone;
- pile_grid (4 pyramids of base 3, islands on): positions, orientations, velocities and the per-island rungs
  bitwise identical at 1 and 2 ranks over 30 steps;
- a log heap of 10 checkpointed at step 25 (2 ranks) and restarted (1 rank) ends bitwise where the uninterrupted
  run ends (the checkpoint holds the rungs and the probe schedule).
"""
import sys

from contact_harness import Harness
import numpy as np

APP = sys.argv[1]
H = Harness(APP, "contact_friction_auto_")
run, check = H.run, H.check
E = 1e-3
AUTO = ["-friction", "auto", "-target_error", E]
G = 9.81


def within_target(f, name):
    steps = f["/steps/cone_violation"][:]
    problems = f["/friction_auto/cone_violation"][:]
    check(steps.max() <= E and problems.max() <= E and f["/friction_auto/step_target_missed"][:].sum() == 0,
          f"{name}: every step's cone violation <= {E:g} (largest {steps.max():.2e}, problems {problems.max():.2e})")


th = np.radians(30)
with run("slide", "-scene", "incline", "-theta", 30, "-mu", 0.3, "-steps", 100, *AUTO) as f:
    v = np.linalg.norm(f["/frames/velocities"][-1, 1, :3])
    exact = G * (np.sin(th) - 0.3 * np.cos(th))
    ratio = f["/steps/force_ratio"][:]
    check(abs(f["/frames/time"][-1] - 1.0) < 1e-12 and abs(v - exact) < 5e-5,
          f"incline mu 0.3: speed after 1 s {v:.5f} m/s (exact {exact:.5f})")
    check(np.abs(ratio - 0.3).max() < 5e-5, f"incline mu 0.3: force ratio {ratio.min():.6f}..{ratio.max():.6f} = mu")
    within_target(f, "incline mu 0.3")

with run("stick", "-scene", "incline", "-theta", 30, "-mu", 0.7, "-steps", 200, *AUTO) as f:
    p = f["/frames/positions"][:, 1]
    creep = np.linalg.norm(p[-1] - p[0])
    ratio = f["/steps/force_ratio"][:]
    check(creep <= 1e-8, f"incline mu 0.7: creep {creep:.2e} m <= 1e-8 in 2 s")
    check(np.abs(ratio - np.tan(th)).max() < 5e-5,
          f"incline mu 0.7: force ratio {ratio.min():.6f}..{ratio.max():.6f} = tan 30 deg {np.tan(th):.6f}")
    within_target(f, "incline mu 0.7")

with run("stack", "-scene", "box_stack", "-stack_height", 10, "-steps", 200, *AUTO) as f:
    x = f["/frames/positions"][:]
    drift = np.abs(x[-1] - x[0]).max()
    check(drift < 1e-6, f"stack of 10 at rest: drift {drift:.2e} m < 1e-6 in 2 s")
    within_target(f, "stack of 10")

with run("frictionless", "-scene", "incline", "-theta", 30, "-mu", 0, "-steps", 20, *AUTO) as f:
    a = f["/friction_auto"]
    check(a.attrs["rungs"] == "none" and a["rung"][:].max() == 0, "mu = 0: frictionless rows only")


def frames(f):
    return [f[k][:] for k in ("/frames/positions", "/frames/orientations", "/frames/velocities",
                              "/friction_auto/rung", "/friction_auto/offset")]


GRID = ["-scene", "pile_grid", "-piles", 4, "-pyramid_base", 3, "-steps", 30, "-contact_islands", "on", *AUTO]
a = run("np1", *GRID)
b = run("np2", *GRID, np_=2)
check(all(np.array_equal(x, y) for x, y in zip(frames(a), frames(b))),
      "pile_grid, islands on: positions and per-island rungs bitwise identical at 1 and 2 ranks")
o = a["/friction_auto/offset"][:]
check(a["/steps/islands"][-1] == 4 and o[-1] - o[-2] == 4, "pile_grid: one rung per island and step")
within_target(a, "pile_grid")

# a checkpoint holds every contact's rung and the probe schedule: a restart ends bitwise in the uninterrupted
# run's state (the log heap: islands climb and come down between the rungs)
HEAP = ["-scene", "log_heap", "-n_logs", 10, "-steps", 40, "-contact_islands", "on", *AUTO]
ck = H.tmp / "ck"
full = run("ck_full", *HEAP, "-checkpoint_dir", ck, "-checkpoint_every", 25, np_=2)
rs = run("ck_restart", *HEAP, "-restart", ck / "contact_0000000025.h5")
rungs = full["/friction_auto/rung"][:]
check(np.array_equal(full["/frames/positions"][-1], rs["/frames/positions"][-1]) and len(set(rungs)) > 1,
      f"restart at step 25 (1 rank) ends bitwise in the uninterrupted run's state (2 ranks; rungs used "
      f"{sorted(int(r) for r in set(rungs))})")
within_target(full, "log heap of 10")

H.finish("friction auto")
