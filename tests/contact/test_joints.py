"""Joints on the contact app's HDF5 output (run by ctest: test_joints.py <contact> <inputs/contact>).

- the 100-link hinge chain falling from horizontal at dt = 0.01 (tip turns of order 1 rad per step), 300 steps:
  /joints/error <= 1e-9 m at every step (measured: 1.0e-11, the -joint_tol), the energy never above its start;
- the same chain of ball joints: the same bound;
- 1 and 2 ranks: positions and joint forces bitwise identical (the joint block is solved identically on every rank);
- the hanging chain with an end load of 1e4 link masses: each joint's force is the weight below it (1e-12 relative;
  measured 4e-14);
- the rope bridge (10 planks, 3 boxes dropped on it; contacts on jointed bodies through the joint block's Schur
  complement): the joint error bound, and the boxes end resting on the planks (measured: 16 contacts);
- the wrecking ball (5 links and a sphere of 20 link masses into a pyramid of base 3, 60 steps): the joint error
  bound while it scatters the boxes (measured: a box moved 0.5 m by step 60);
- the MJCF model inputs/contact/chain25.xml: its time step (0.01) and gravity are the run's (/steps/time), and the
  joint error bound holds.
"""
import sys

import numpy as np
from contact_harness import SLOW_BUILD, Harness

APP, INPUTS = sys.argv[1], sys.argv[2]
H = Harness(APP, "contact_joints_")
run, check = H.run, H.check
STEPS = 100 if SLOW_BUILD else 300
G = 9.81


def energy(f):
    m = f["/bodies/mass"][:]
    x, v = f["/frames/positions"][:], f["/frames/velocities"][:]
    return (0.5 * m * (v[:, :, :3] ** 2).sum(axis=2) + m * G * x[:, :, 2]).sum(axis=1)


for joint in ("hinge", "ball"):
    f = run(f"chain100_{joint}", "-scene", "chain", "-links", 100, "-joint_type", joint, "-dt", 0.01, "-steps", STEPS,
            "-output_every", 10)
    err = f["/joints/error"][:].max()
    check(err <= 1e-9, f"100-link {joint} chain from horizontal, dt 0.01: max joint error {err:.2e} m <= 1e-9")
    e = energy(f)
    check(e.max() <= e[0] + 1e-9 * abs(e).max(), f"100-link {joint} chain: translational energy + potential "
          f"never above its start (largest rise {e.max() - e[0]:.2e} J)")

a = run("np1", "-scene", "chain", "-links", 30, "-steps", 100)
b = run("np2", "-scene", "chain", "-links", 30, "-steps", 100, np_=2)
same = all(np.array_equal(a[k][:], b[k][:]) for k in ("/frames/positions", "/frames/orientations", "/joints/force"))
check(same, "30-link chain: positions, orientations and joint forces bitwise identical at 1 and 2 ranks")

f = run("hanging", "-scene", "chain", "-links", 10, "-angle", 0, "-end_mass_ratio", 1e4, "-friction", "none",
        "-steps", 1)
m = f["/bodies/mass"][:]
below = np.array([m[k:].sum() * G for k in range(len(m))])
fz = f["/joints/force"][0, :, :]
rel = (np.abs(fz - np.outer(below, [0, 0, 1])).max(axis=1) / below).max()
check(rel <= 1e-12, f"hanging chain, end load 1e4: joint force = weight below to {rel:.1e} relative (<= 1e-12)")

f = run("mjcf", "-scene", "mjcf", "-scene_file", f"{INPUTS}/chain25.xml", "-steps", 50)
dt = np.diff(f["/steps/time"][:])
check(np.allclose(dt, 0.01, rtol=1e-12, atol=0), "chain25.xml: the run takes the file's time step 0.01")
err = f["/joints/error"][:].max()
check(err <= 1e-9, f"chain25.xml: max joint error {err:.2e} m <= 1e-9")
f = run("bridge", "-scene", "rope_bridge", "-links", 10, "-bridge_boxes", 3, "-dt", 0.01, "-steps", STEPS)
err = f["/joints/error"][:].max()
check(err <= 1e-9, f"rope bridge with 3 boxes dropped on it (contacts on jointed bodies): joint error {err:.2e} m <= 1e-9")
x = f["/frames/positions"][-1]
held = x[10:, 2].min() > x[:10, 2].min() and f["/steps/contacts"][-1] >= 12
check(held, f"rope bridge: the boxes rest on the planks at the end (lowest box z {x[10:, 2].min():.3f} m above the "
      f"lowest plank {x[:10, 2].min():.3f} m, {f['/steps/contacts'][-1]} contacts)")
f = run("wreck", "-scene", "wrecking_ball", "-links", 5, "-pyramid_base", 3, "-end_mass_ratio", 20, "-dt", 0.01,
        "-steps", 60)
err = f["/joints/error"][:].max()
x0, x = f["/frames/positions"][0], f["/frames/positions"][-1]
moved = np.linalg.norm(x[7:] - x0[7:], axis=1).max()  # bodies 0-5: links and ball, 6: ground, 7-12: the boxes
check(err <= 1e-9 and moved > 0.1, f"wrecking ball (5 links, 20-link-mass ball into a pyramid of 3): joint error "
      f"{err:.2e} m <= 1e-9, a box moved {moved:.2f} m (> 0.1)")
H.finish("joint")
