"""-contact_phase_times (lib/contact/phase_times.hpp; run by ctest: test_phase_times.py <contact>): each rank
prints one line of its wall and CPU time per step and phase at the end of the run. Checked on pile_grid of 6
pyramids of base 3 (36 boxes, 6 islands per step), 10 steps, islands on at 1 and 2 ranks and off at 1 rank:
- one line per rank, in rank order, over the run's 10 steps;
- every island of a step is solved by exactly one rank: the ranks' own islands per step add up to the step's
  6 islands (0 with islands off);
- the phases add up to the step and no time is negative (the CPU waiting, the dealing's CPU less the own
  solves', may round to a few microseconds below 0);
- timing changes nothing: the final positions with the option are bitwise those without it, at 1 and 2 ranks.
Wall and CPU values themselves are not checked (they depend on the machine).
"""
import re
import subprocess
import sys

import h5py
import numpy as np
from contact_harness import ENV, Harness

APP = sys.argv[1]
H = Harness(APP, "contact_phase_times_")
check = H.check
SCENE = ["-scene", "pile_grid", "-piles", 6, "-pyramid_base", 3, "-steps", 10, "-output_every", 10]
NUM = r"(-?[\d.]+)"
LINE = re.compile(
    rf"contact phase times, rank (\d+), ms per step over (\d+) steps: step {NUM} = collision {NUM} \+ match and "
    rf"split {NUM} \+ dealing {NUM} \(own island solves {NUM}, {NUM} of {NUM} islands; waiting and gather {NUM}\) "
    rf"\+ unpack {NUM} \+ integration {NUM} \+ rest {NUM}; CPU ms per step: step {NUM}, own island solves {NUM}, "
    rf"waiting and gather {NUM}, busy \(step less waiting\) {NUM}")


def run(name, np_, *extra):
    out = H.tmp / f"{name}.h5"
    cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), APP, *map(str, SCENE), *extra, "-output", str(out),
           "-quiet"]
    p = subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        raise SystemExit(f"FAILED: {' '.join(cmd)}\n{p.stdout}")
    with h5py.File(out, "r") as f:
        pos = f["/frames/positions"][-1]
    return [[float(g) for g in m.groups()] for m in LINE.finditer(p.stdout)], pos, p.stdout


for np_, islands, count in ((1, "on", 6), (2, "on", 6), (1, "off", 0)):
    lines, pos, text = run(f"np{np_}_{islands}", np_, "-contact_islands", islands, "-contact_phase_times")
    what = f"np {np_}, islands {islands}"
    ok = [int(l[0]) for l in lines] == list(range(np_)) and all(l[1] == 10 for l in lines)
    check(ok, f"{what}: one line per rank, over 10 steps" + ("" if ok else f"; the run printed\n{text}"))
    if len(lines) != np_:
        continue
    check(all(l[8] == count for l in lines) and abs(sum(l[7] for l in lines) - count) < 1e-9,
          f"{what}: the ranks' own islands add up to the step's {count}: {[l[7] for l in lines]}")
    parts = [l[3] + l[4] + l[5] + l[10] + l[11] + l[12] for l in lines]  # collision .. rest
    check(all(abs(p - l[2]) <= 0.05 + 1e-3 * l[2] for p, l in zip(parts, lines)),
          f"{what}: the phases add up to the step ({parts} vs {[l[2] for l in lines]} ms)")
    times = [v for l in lines for k, v in enumerate(l) if k >= 2 and k not in (7, 8, 12, 15)]
    check(min(times) >= 0 and all(l[15] > -0.05 for l in lines), f"{what}: no negative time")
    _, plain, _ = run(f"np{np_}_{islands}_plain", np_, "-contact_islands", islands)
    check(np.array_equal(pos, plain), f"{what}: final positions bitwise those without -contact_phase_times")
    if np_ == 2:
        check(np.array_equal(pos, one), "islands on: final positions bitwise identical at 1 and 2 ranks")
    one = pos

H.finish("contact phase times")
