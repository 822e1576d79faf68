"""-contact_islands on the contact app's HDF5 output (run by ctest: test_islands.py <contact>).

- pile_grid of 6 pyramids of base 4 (60 boxes), 60 steps (0.6 s): with islands, 6 islands of 10 boxes each step
  (/steps/islands, /steps/largest_island_bodies), the same positions as the whole-scene solve to 1e-8 m and
  velocities to 1e-7 m/s (splitting, box; polyhedral on 4 pyramids of base 2): each problem is accepted at
  the natural-map residual lcp_tol (1 + |b|_inf) = 1e-8 (1 + ~0.1), which bounds the velocity error of a step
  only through the Delassus matrix (measured: 1.1e-8 m/s with box friction), and 1e-8 m/s over 0.6 s moves a
  body 6e-9 m;
- islands on: positions, orientations and velocities bitwise identical at 1 and 2 ranks over 30 steps (splitting,
  polyhedral, -contact_accuracy fast, -sleep);
- islands off: 1 and 2 ranks bitwise identical as before;
- a checkpoint written at 2 ranks, restarted at 1 rank, ends bitwise where the uninterrupted run ends;
- -dump_problems with islands writes every island's problems (at least one per island and step).
"""
import sys

import h5py
from contact_harness import SLOW_BUILD, Harness
import numpy as np

APP = sys.argv[1]
H = Harness(APP, "contact_islands_")
run, check, TMP = H.run, H.check, H.tmp
# Under the sanitizers half the steps (the piles touch down by step ~10, so every check still has steps in contact).
STEPS = 30 if SLOW_BUILD else 60
GRID = ["-scene", "pile_grid", "-piles", 6, "-pyramid_base", 4, "-steps", STEPS]
SMALL = ["-scene", "pile_grid", "-piles", 4, "-pyramid_base", 2, "-steps", STEPS]  # polyhedral: dense Lemke
# The rank checks need steps in contact, not a long run: STEPS / 2.
GRID30, SMALL30 = GRID[:-1] + [STEPS // 2], SMALL[:-1] + [STEPS // 2]
TOL_X, TOL_V = 1e-8, 1e-7




def frames(f):
    return [f[k][:] for k in ("/frames/positions", "/frames/orientations", "/frames/velocities")]


def same(a, b):
    return all(np.array_equal(x, y) for x, y in zip(frames(a), frames(b)))


for friction, scene, piles, boxes in (("splitting", GRID, 6, 10), ("box", GRID, 6, 10),
                                     ("polyhedral", SMALL, 4, 3)):
    off = run(f"off_{friction}", *scene, "-friction", friction)
    on = run(f"on_{friction}", *scene, "-friction", friction, "-contact_islands", "on")
    s = on["/steps"]
    counts = s["islands"][:].min() == s["islands"][:].max() == piles and s["largest_island_bodies"][:].max() == boxes
    check(counts and off["/steps/islands"][:].max() == 0, f"{friction}: {piles} islands of {boxes} boxes every step")
    dx = np.abs(on["/frames/positions"][:] - off["/frames/positions"][:]).max()
    dv = np.abs(on["/frames/velocities"][:] - off["/frames/velocities"][:]).max()
    check(dx <= TOL_X and dv <= TOL_V,
          f"{friction}: islands vs whole scene |dx| {dx:.2e} m <= {TOL_X:g}, |dv| {dv:.2e} m/s <= {TOL_V:g}")

for name, scene, extra in (("splitting", GRID30, []), ("polyhedral", SMALL30, ["-friction", "polyhedral"]),
                           ("fast", GRID30, ["-contact_accuracy", "fast"]),
                           ("sleep", GRID30, ["-sleep", "-sleep_steps", 5])):
    a = run(f"np1_{name}", *scene, *extra, "-contact_islands", "on")
    b = run(f"np2_{name}", *scene, *extra, "-contact_islands", "on", np_=2)
    check(same(a, b), f"islands on, {name}: bitwise identical at 1 and 2 ranks")
    if name == "sleep":
        check(int(a["/steps/sleeping"][:].max()) > 0, "sleep: bodies fell asleep with islands")

a = run("np1_off", *GRID30)
b = run("np2_off", *GRID30, np_=2)
check(same(a, b), "islands off: bitwise identical at 1 and 2 ranks")

ck = TMP / "ck"
full = run("ck_full", *GRID[:-1], 40, "-contact_islands", "on", "-checkpoint_dir", ck, "-checkpoint_every", 20,
           np_=2)
rs = run("ck_restart", *GRID[:-1], 40, "-contact_islands", "on", "-restart", ck / "contact_0000000020.h5")
check(np.array_equal(full["/frames/positions"][-1], rs["/frames/positions"][-1]),
      "islands: restart at step 20 (1 rank) ends bitwise in the uninterrupted run's state (2 ranks)")

dump = TMP / "dump" / "p"
dump.parent.mkdir()
# (the sparse path above -contact_dense_max_rows keeps no problem to dump, with or without islands)
f = run("dump", *GRID[:-1], 2, "-contact_islands", "on", "-dump_problems", dump, "-contact_dense_max_rows", 1000,
        np_=2)
n = len(list(dump.parent.glob("p_step*.h5")))
check(n >= 12 and f["/steps/islands"][0] == 6, f"-dump_problems with islands: {n} problems for 2 steps of 6 islands")

H.finish("contact islands")
