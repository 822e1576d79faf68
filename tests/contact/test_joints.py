"""Joints on the contact app's HDF5 output (run by ctest: test_joints.py <contact> <inputs/contact>).

- the 100-link hinge chain falling from horizontal at dt = 0.01 (tip turns of order 1 rad per step), 300 steps:
  /joints/error <= 1e-9 m at every step (measured: 1.0e-11, the -joint_tol), the energy never above its start;
- the same chain of ball joints: the same bound;
- 1 and 2 ranks: positions and joint forces bitwise identical (the joint block is solved identically on every rank);
- -joint_max_projections 1 on a 30-link chain: the steps whose projection does not converge are retried at a
  smaller dt, and every recorded step's joint error stays within the failure bound 1e3 -joint_tol;
- the 25-link chain with an end load of 1e4 link masses falling from horizontal: the joint error bound;
- the hanging chain with an end load of 1e4 link masses: each joint's force is the weight below it (1e-12 relative;
  measured 4e-14);
- the rope bridge (10 planks, 3 boxes dropped on it; contacts on jointed bodies through the joint block's Schur
  complement): the joint error bound, and the boxes end resting on the planks (measured: 16 contacts);
- the wrecking ball (5 links and a sphere of 20 link masses into a pyramid of base 3, 60 steps): the joint error
  bound while it scatters the boxes (measured: a box moved 0.5 m by step 60);
- the rope bridge with -contact_islands on: the planks are in the island of the boxes' contacts (13 bodies), the
  positions match islands off to 1e-8 m (each problem is accepted at the LCP tolerance 1e-8, as in
  test_islands.py; measured 0) and 1 and 2 ranks are bitwise identical;
- the MJCF model inputs/contact/chain25.xml: its time step (0.01) and gravity are the run's (/steps/time), and the
  joint error bound holds;
- balanced and fast: the wrecking ball with islands in fast mode (the joint bound, the boxes scattered, 1 and 2
  ranks bitwise); inputs/contact/supported_plank.scene (a crate on a plank pinned at both ends) in every mode:
  each pin's vertical force against the statics (measured relative errors: exact 1.1e-10, balanced 4.6e-10,
  fast 2.4e-7);
- motor_limit (a lever driven up by a bounded motor against its +60 degree limit, 200 steps): /joints/coordinate
  ends on the limit (1e-12; measured 0) with /joints/motor_power 0 there, after a phase where the saturated motor
  (1 N m) did work (measured: largest power 1.42 W); inputs/contact/motor_limit.xml (written by -write_mjcf) gives
  the same coordinates (measured: bitwise), and so does inputs/contact/lever.scene (the scene file's limit= and
  motor= keys);
- -write_mjcf of the registered scene reads back (-scene mjcf) to the same trajectory as the scene (double
  pendulum, 100 steps: to 1e-12; measured 9e-16, the round-off of the file's body-frame poses).
"""
import subprocess
import sys

import numpy as np
from contact_harness import ENV, SLOW_BUILD, Harness

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

# a projection capped at 1 Newton iteration does not converge at dt 0.01: those steps are retried at dt / 2 or
# dt / 4 (measured: 95 of 100 at dt / 4), and every recorded step stays within the failure bound 1e3 -joint_tol
# (measured 8.4e-9 m)
f = run("one_projection", "-scene", "chain", "-links", 30, "-steps", 100, "-joint_max_projections", 1)
dt = np.diff(np.r_[0.0, f["/steps/time"][:]])
err = f["/joints/error"][:].max()
check(len(dt) == 100 and dt.min() < 0.006 and err <= 1e-8, f"-joint_max_projections 1: 100 steps, "
      f"{(dt < 0.009).sum()} of them retried at a smaller dt (smallest {dt.min():g} s), joint error {err:.1e} <= 1e-8")

# the 25-link chain with an end load of 1e4 link masses falling from horizontal, 300 steps at dt 0.01: the
# projection's metric caps the mass ratio (joint_system.hpp; measured: 9.7e-12 m, 3.9 Newton iterations a step)
f = run("heavy_load", "-scene", "chain", "-links", 25, "-end_mass_ratio", 1e4, "-steps", STEPS)
err = f["/joints/error"][:].max()
check(err <= 1e-9 and len(f["/steps/time"]) == STEPS, f"25-link chain with a 1e4 end load from horizontal: joint "
      f"error {err:.1e} m <= 1e-9 over {STEPS} steps")

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
WRECK = ["-scene", "wrecking_ball", "-links", 5, "-pyramid_base", 3, "-end_mass_ratio", 20, "-dt", 0.01, "-steps", 60]
f = run("wreck", *WRECK)
err = f["/joints/error"][:].max()
x0, x = f["/frames/positions"][0], f["/frames/positions"][-1]
moved = np.linalg.norm(x[7:] - x0[7:], axis=1).max()  # bodies 0-5: links and ball, 6: ground, 7-12: the boxes
check(err <= 1e-9 and moved > 0.1, f"wrecking ball (5 links, 20-link-mass ball into a pyramid of 3): joint error "
      f"{err:.2e} m <= 1e-9, a box moved {moved:.2f} m (> 0.1)")
BRIDGE = ["-scene", "rope_bridge", "-links", 10, "-bridge_boxes", 3, "-dt", 0.01, "-steps", 100]
off = run("bridge_off", *BRIDGE)
a = run("bridge_islands", *BRIDGE, "-contact_islands", "on")
b = run("bridge_islands_np2", *BRIDGE, "-contact_islands", "on", np_=2)
big = a["/steps/largest_island_bodies"][:].max()
check(big == 13, f"rope bridge, islands: the planks join the island of the boxes' contacts (largest island {big} "
      "bodies = 10 planks + 3 boxes)")
dx = np.abs(a["/frames/positions"][:] - off["/frames/positions"][:]).max()
check(dx <= 1e-8, f"rope bridge: islands on vs off, positions to {dx:.1e} m (<= 1e-8, the LCP tolerance's scale)")
same = all(np.array_equal(a[k][:], b[k][:]) for k in ("/frames/positions", "/frames/orientations", "/joints/force"))
check(same, "rope bridge, islands on: positions, orientations and joint forces bitwise identical at 1 and 2 ranks")
# balanced / fast: the joint block solved exactly inside the block PGS (contact_accuracy.hpp)
w = run("wreck_fast", *WRECK, "-contact_accuracy", "fast", "-contact_islands", "on")
w2 = run("wreck_fast_np2", *WRECK, "-contact_accuracy", "fast", "-contact_islands", "on", np_=2)
x0, x = w["/frames/positions"][0], w["/frames/positions"][-1]
moved = np.linalg.norm(x[7:] - x0[7:], axis=1).max()
err = w["/joints/error"][:].max()
check(err <= 1e-9 and moved > 0.1, f"wrecking ball, fast: joint error {err:.2e} m <= 1e-9, a box moved {moved:.2f} m")
same = all(np.array_equal(w[k][:], w2[k][:]) for k in ("/frames/positions", "/joints/force"))
check(same, "wrecking ball, fast with islands: positions and joint forces bitwise identical at 1 and 2 ranks")
acc = w.attrs["contact_accuracy"]
check((acc.decode() if isinstance(acc, bytes) else acc) == "fast", "the output records contact_accuracy = fast")
# the crate on the plank pinned at both ends: the pins' vertical forces against the statics of
# inputs/contact/supported_plank.scene (measured relative errors: exact 1.1e-10, balanced 4.6e-10, fast 2.4e-7)
RL, RR = 2 * G / 2 + G * 0.3, 2 * G / 2 + G * 0.7
for acc, tol in (("exact", 1e-9), ("balanced", 3e-9), ("fast", 1e-6)):
    p = run(f"plank_{acc}", "-scene", "file", "-scene_file", f"{INPUTS}/supported_plank.scene", "-steps", 200,
            "-contact_accuracy", acc)
    fz = p["/joints/force"][-1, :, 2]
    rel = max(abs(fz[0] - RL) / RL, abs(fz[1] - RR) / RR)
    check(rel <= tol, f"supported plank, {acc}: the pins carry the crate by statics to {rel:.1e} relative "
          f"(<= {tol:g})")
f = run("motor_limit", "-scene", "motor_limit", "-steps", 200)
theta, power = f["/joints/coordinate"][:, 0], f["/joints/motor_power"][:, 0]
check(abs(theta[-1] - np.pi / 3) <= 1e-12 and abs(power[-1]) <= 1e-12 and power.max() > 1.0,
      f"motor_limit: the lever ends on its limit ({theta[-1] - np.pi / 3:.1e} rad off), the motor's power "
      f"{power[-1]:.1e} W there after up to {power.max():.2f} W")
g = run("motor_limit_xml", "-scene", "mjcf", "-scene_file", f"{INPUTS}/motor_limit.xml", "-steps", 200)
d = np.abs(g["/joints/coordinate"][:] - f["/joints/coordinate"][:]).max()
check(d <= 1e-12, f"motor_limit.xml: the registered scene's coordinates to {d:.1e} rad")
g = run("lever_scene", "-scene", "file", "-scene_file", f"{INPUTS}/lever.scene", "-steps", 200)
d = np.abs(g["/joints/coordinate"][:] - f["/joints/coordinate"][:]).max()
check(d <= 1e-12, f"lever.scene (limit= and motor= keys): the registered scene's coordinates to {d:.1e} rad")

xml = str(H.tmp / "double_pendulum.xml")
p = subprocess.run([APP, "-scene", "double_pendulum", "-angle", "40", "-write_mjcf", xml, "-quiet"], env=ENV)
check(p.returncode == 0, "-write_mjcf double_pendulum: exit 0")
a = run("dp_scene", "-scene", "double_pendulum", "-angle", 40, "-steps", 100)
b = run("dp_xml", "-scene", "mjcf", "-scene_file", xml, "-steps", 100)
d = max(np.abs(a[k][:] - b[k][:]).max() for k in ("/frames/positions", "/frames/orientations"))
check(d <= 1e-12, f"-write_mjcf double_pendulum read back: the scene's trajectory to {d:.1e} (<= 1e-12)")

H.finish("joint")
