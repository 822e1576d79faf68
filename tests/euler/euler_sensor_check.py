#!/usr/bin/env python3
"""Checks of the ENO-Pade shock sensor (lib/euler/enopade6.hpp): no shock rows on smooth
problems, shock rows only near the discontinuities of Sod and Shu-Osher, the flag field in the snapshots and the
XDMF sidecar, the same flags at 1 and 2 ranks. Runs bin/euler (under mpiexec), reads its printed sensor line and
its HDF5 output.

Needs numpy and h5py (the suite's Python environment). Usage: euler_sensor_check.py CHECK
"""
import os
import re
import sys
import tempfile

import h5py
import numpy as np

from euler_harness import check, run


# Sod (1978), x0 = 0.5, gamma = 1.4: wave speeds of the exact solution (Toro, Riemann Solvers, sec. 4.3.3).
SOD_SHOCK, SOD_CONTACT, SOD_HEAD, SOD_TAIL = 1.7521557, 0.9274526, -1.1832160, -0.0702728


def sensor_rows(out):
    m = re.search(r"shock sensor: (\d+) shock rows of (\d+) rows examined \(fraction (\S+)\)", out)
    if not m:
        raise SystemExit("FAIL: no shock sensor line")
    return int(m.group(1)), int(m.group(2)), float(m.group(3))


def snapshots(path):
    """[(time, shock flags)] of every snapshot and the final state, in time order."""
    with h5py.File(path, "r") as f:
        res = [(float(g.attrs["time"]), g["shock"][...]) for g in (f["/snapshots"][k] for k in sorted(f["/snapshots"]))]
        res.append((float(f.attrs["time"]), f["/final/shock"][...]))
        return res


def smooth():
    """Smooth problems: no shock row at any step (the count is summed over every right-hand side evaluation),
    to their default end times: isentropic vortex at 32^2 and 64^2 (t = 10), density wave at N = 20."""
    for args in (["-dim", 2, "-problem", "isentropic_vortex", "-nx", 32, "-ny", 32],
                 ["-dim", 2, "-problem", "isentropic_vortex", "-nx", 64, "-ny", 64],
                 ["-problem", "density_wave", "-nx", 20]):
        shock, rows, _ = sensor_rows(run(args))
        check(shock == 0 and rows > 0, f"{' '.join(map(str, args))}: {shock} shock rows of {rows} examined")


def near(x, fronts, k, dx):
    """Distance test: every x within k cells of one of the fronts."""
    return np.all(np.min(np.abs(x[:, None] - np.asarray(fronts)[None, :]), axis=1) <= k * dx)


def sod():
    """Sod N = 200 to t = 0.2, a snapshot every 10 steps: in every snapshot the flagged cells lie within K cells of
    the exact shock, contact or the rarefaction's head and tail (its kinks: while the fan is a few cells wide it
    is flagged too); the shock is flagged in every snapshot, the contact in at least one; the run's fraction of
    shock rows is small. Since the shocked lines are all ENO-Pade rows (enopade6.hpp) the contact stays 2-3
    cells wide and flagged all run: a band of 7-8 cells (the five rows whose stencils hold the jump, and the
    jump's own width) whose edge lies up to 4.02 cells from the exact contact (t = 0.084), so K = 5, and two
    such fronts in 200 rows make about 7% of the rows (bound 0.08; 0.05 while the contact smeared and lost its
    flags after t = 0.07)."""
    k = 5
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "sod.h5")
        shock, rows, frac = sensor_rows(run(["-problem", "sod", "-nx", 200, "-t_final", 0.2, "-snapshot_every", 10,
                                             "-output", path]))
        with h5py.File(path, "r") as f:
            x = f["/grid/x"][...]
        dx = x[1] - x[0]
        contact_seen = 0
        for t, flag in snapshots(path):
            xs = x[flag > 0]
            fronts = [0.5 + s * t for s in (SOD_SHOCK, SOD_CONTACT, SOD_HEAD, SOD_TAIL)]
            if t == 0.0:
                fronts = [0.5]
            check(near(xs, fronts, k, dx), f"t = {t:.4f}: {len(xs)} flagged cells all within {k} cells of {fronts}")
            check(t == 0.0 or np.any(np.abs(xs - fronts[0]) <= k * dx), f"t = {t:.4f}: the shock is flagged")
            contact_seen += t > 0.0 and bool(np.any(np.abs(xs - fronts[1]) <= k * dx))
        check(contact_seen >= 1, f"the contact is flagged in {contact_seen} snapshot(s)")
        check(frac <= 0.08, f"fraction of shock rows over the run {frac:.3e} ({shock} of {rows}) <= 0.08")


def shu_osher():
    """Shu-Osher N = 400 to t = 1.8: the smooth entropy waves behind the shock (about 13 cells per wavelength) are
    not flagged. Flagged cells of the final state lie within K cells of the steepest jumps of the final density:
    the shock (largest |drho| in x > 2) and the shocklets (|drho| above a tenth of the shock's)."""
    k = 4
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "so.h5")
        shock, rows, frac = sensor_rows(run(["-problem", "shu_osher", "-nx", 400, "-output", path]))
        with h5py.File(path, "r") as f:
            x, rho, flag = f["/grid/x"][...], f["/final/rho"][...], f["/final/shock"][...]
        dx = x[1] - x[0]
        jump = np.abs(np.diff(rho))
        xf = 0.5 * (x[1:] + x[:-1])
        fronts = xf[jump >= 0.1 * jump.max()]
        xs = x[flag > 0]
        print("flagged cells at", xs, "jumps at", fronts)
        check(len(xs) > 0 and near(xs, fronts, k, dx),
              f"{len(xs)} flagged cells all within {k} cells of the {len(fronts)} faces with the largest jumps")
        check(frac <= 0.05, f"fraction of shock rows over the run {frac:.3e} ({shock} of {rows}) <= 0.05")


def output():
    """The flag field: /snapshots/*/shock and /final/shock exist (the 2D lax_liu_4 run: four shocks), they are
    bit masks of the directions (0 .. 3 in 2D), the XDMF sidecar names them as cell attributes, and they agree
    at 1 and 2 ranks (1D Sod, 2D lax_liu_4) bitwise, as does the run's shock-row count."""
    with tempfile.TemporaryDirectory() as d:
        for args in (["-problem", "sod", "-nx", 120, "-max_steps", 40],
                     ["-dim", 2, "-problem", "lax_liu_4", "-nx", 48, "-ny", 48, "-max_steps", 20]):
            flags, counts = {}, {}
            for np_ in (1, 2):
                path = os.path.join(d, f"o{np_}.h5")
                counts[np_] = sensor_rows(run(args + ["-snapshot_every", 10, "-output", path], np_=np_))[:2]
                flags[np_] = snapshots(path)
                with open(path[:-3] + ".xmf") as f:
                    xmf = f.read()
                n = len(re.findall(r'<Attribute Name="shock" AttributeType="Scalar" Center="Cell"', xmf))
                check(n == len(flags[np_]), f"{np_} rank(s): XDMF names the shock attribute in all {n} steps")
            top = 1 if args[1] == "sod" else 3
            last = flags[1][-1][1]
            check(last.max() >= 1 and last.max() <= top and np.all(last == np.round(last)),
                  f"{args[1]}: flags in 0 .. {top}, {int((last > 0).sum())} cells flagged at the end")
            same = all(np.array_equal(a[1], b[1]) for a, b in zip(flags[1], flags[2]))
            check(same and counts[1] == counts[2], f"{args[1]}: flags and counts {counts[1]} equal at 1 and 2 ranks")


if __name__ == "__main__":
    {"smooth": smooth, "sod": sod, "shu_osher": shu_osher, "output": output}[sys.argv[1]]()
