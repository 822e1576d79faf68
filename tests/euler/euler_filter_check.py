#!/usr/bin/env python3
"""Regression checks of the compact filter of the Euler app (-filter_alpha, -filter_time).

    euler_filter_check.py order | noise

order: 1D density wave, RK4 with dt ~ dx^1.5 (the Pade core's orders test, time error negligible), N = 20..160:
  with -filter_alpha 0.45 -filter_time 0.01 the L1(rho) order stays >= 5.8 (sixth order kept); the full filter
  every step (no -filter_time) costs order as its header states: O(steps dx^6) = O(dx^4.5) here (4.3 .. 4.7).
  2D planar density wave (periodic, no jump: every face filtered) at 1 and 2 ranks: mass and energy conserved to
  round-off, and the two rank counts agree to 1e-12 (x lines split over the 2 ranks: the filter's partition-method solve: round-off, not bitwise);
  2D explosion in a closed box (walls, shocks: faces switched off) conserves mass and energy to round-off.
noise: Liska-Wendroff 3 at 50^2 (t = 0.3, 2 ranks), ENO-Pade without and with -filter_alpha 0.45: the odd-even
  (2-dx) content of rho in the cells away from jumps (scripts/bench/euler-checkerboard's measure, its mask from
  the unfiltered run) drops at least 20-fold (measured: 4.5e-4 -> 4.1e-6), density and pressure stay positive.
"""
import importlib.machinery
import importlib.util
import math
import os
import re
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

from euler_harness import check, error, run

SOURCE = Path(os.environ.get("SUITE_SOURCE", Path(__file__).resolve().parents[2]))


def density_wave_errors(extra):
    errs = []
    for n in (20, 40, 80, 160):
        dx = 2.0 / n
        errs.append(error(run(["-problem", "density_wave", "-nx", n, "-time", "rk4", "-dt", 0.25 * dx ** 1.5,
                                  "-t_final", 0.5, "-error"] + extra)))
    return errs, [math.log2(errs[i - 1] / errs[i]) for i in range(1, len(errs))]


def conservation_change(out, quantity):
    m = re.search(rf"conservation {quantity}: initial (\S+) final (\S+)", out)
    if not m:
        raise SystemExit(f"FAIL: no conservation {quantity} line")
    a, b = float(m.group(1)), float(m.group(2))
    return abs(b - a) / abs(a)


def order():
    errs, o = density_wave_errors(["-filter_alpha", 0.45, "-filter_time", 0.01])
    print("errors", errs, "orders", o)
    check(min(o) >= 5.8, f"-filter_alpha 0.45 -filter_time 0.01: L1 orders {o} >= 5.8")
    errs, o = density_wave_errors(["-filter_alpha", 0.45])
    print("errors", errs, "orders", o)
    check(all(4.3 <= x <= 4.7 for x in o), f"-filter_alpha 0.45 every step: L1 orders {o} ~ 4.5 (steps dx^6)")
    with tempfile.TemporaryDirectory() as d:
        rho = []
        for np_ in (1, 2):
            path = os.path.join(d, f"dw{np_}.h5")
            out = run(["-dim", 2, "-problem", "density_wave", "-nx", 32, "-ny", 8, "-t_final", 0.5,
                       "-filter_alpha", 0.4, "-output", path] + (["-da_processors_x", 2] if np_ == 2 else []), np_)
            for q in ("mass", "energy"):
                ch = conservation_change(out, q)
                check(ch <= 1e-13, f"np {np_}: {q} relative change {ch:.2e} <= 1e-13 (periodic, filtered)")
            with h5py.File(path, "r") as f:
                rho.append(f["final/rho"][...])
        diff = np.abs(rho[0] - rho[1]).max() / np.abs(rho[0]).max()
        check(diff <= 1e-12, f"1 vs 2 ranks with the filter: max relative rho difference {diff:.2e} <= 1e-12")
    # A closed box with shocks (faces near jumps and walls carry no filter flux): still conserved to round-off.
    for np_ in (1, 2):
        out = run(["-dim", 2, "-problem", "explosion", "-closed_box", "-nx", 40, "-ny", 40, "-max_steps", 100,
                   "-filter_alpha", 0.45], np_)
        for q in ("mass", "energy"):
            ch = conservation_change(out, q)
            check(ch <= 1e-13, f"closed explosion, np {np_}: {q} relative change {ch:.2e} <= 1e-13 (filtered)")


def load_measure():
    path = SOURCE / "scripts" / "bench" / "euler-checkerboard"
    loader = importlib.machinery.SourceFileLoader("euler_checkerboard", str(path))
    spec = importlib.util.spec_from_loader("euler_checkerboard", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


def noise():
    cb = load_measure()
    with tempfile.TemporaryDirectory() as d:
        rho = {}
        for alpha in (0.5, 0.45):
            path = os.path.join(d, f"lw3_{alpha}.h5")
            run(["-dim", 2, "-problem", "liska_wendroff_3", "-nx", 50, "-ny", 50, "-filter_alpha", alpha,
                 "-output", path], 2)
            rho[alpha], cell, _, _ = cb.read_rho(path)
        m0 = cb.measure(rho[0.5], rho[0.5], cell)
        m1 = cb.measure(rho[0.45], rho[0.5], cell)
        print(f"smooth cells {m0['cells_smooth']} of {m0['cells_all']}: noise {m0['noise_smooth']:.3e} unfiltered, "
              f"{m1['noise_smooth']:.3e} filtered")
        check(m0["cells_smooth"] >= 400, f"{m0['cells_smooth']} smooth cells >= 400")
        check(m1["noise_smooth"] <= m0["noise_smooth"] / 20,
              f"2-dx noise {m1['noise_smooth']:.3e} <= {m0['noise_smooth']:.3e} / 20 with -filter_alpha 0.45")


if __name__ == "__main__":
    globals()[sys.argv[1]]()
