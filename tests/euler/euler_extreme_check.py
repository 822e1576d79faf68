#!/usr/bin/env python3
"""Positivity at the extremes: runs bin/euler (under mpiexec) on near-vacuum and huge
pressure-ratio problems and asserts positivity, the error against the exact solution, the retry count in the
summary line and the HDF5 output, and the conservation line of a zero initial total.

Needs h5py (the suite's Python environment). SUITE_BIN points at the build's bin/. Usage: euler_extreme_check.py CHECK
"""
import glob
import os
import re
import sys
import tempfile

import h5py
import numpy as np

from euler_harness import SRC, check, run

LEBLANC = ["-options_file", os.path.join(SRC, "inputs", "euler", "leblanc.yaml")]


def retried(out):
    return int(re.search(r"steps retried (\d+)", out).group(1))


def final_fields(path):
    with h5py.File(path, "r") as f:
        g = f["final"] if "final" in f else f
        return {k: np.asarray(g[k][()]) for k in ("rho", "p")}, int(f.attrs["steps_retried"])


def positive_finite(path):
    fl, retries = final_fields(path)
    ok = all(np.all(np.isfinite(v)) and np.all(v > 0) for v in fl.values())
    return ok, retries, float(fl["rho"].min()), float(fl["p"].min())


# L1(rho) against the exact solution, LeBlanc N = 200 at t = 0.1 with -upwinding llf (measured at 1 and 2 ranks,
# see leblanc()). Measured 2.586e-3, 2.587e-3, 2.717e-3, 2.266e-3 (the same at 1 and 2 ranks); bounds with ~15%
# margin. With rf-char upwinding, the default of crweno5 and weno5, those two measure 2.919e-3 and 2.985e-3
# (rf-char is 10-13% less accurate than Lax-Friedrichs on this case), within the same bounds.
LEBLANC_L1 = {"enopade6": 3.0e-3, "crweno5": 3.0e-3, "weno5": 3.1e-3, "muscl2": 2.6e-3}


def leblanc():
    """Every scheme at 1 and 2 ranks: completes with rho, p > 0 and finite, L1(rho) within its bound, the retry
    count of the summary line equal to the HDF5 attribute and the same at 1 and 2 ranks."""
    with tempfile.TemporaryDirectory() as d:
        for scheme, bound in LEBLANC_L1.items():
            counts = []
            for np_ in (1, 2):
                h5 = os.path.join(d, f"{scheme}{np_}.h5")
                out = run(LEBLANC + ["-scheme", scheme, "-output", h5], np_)
                ok, retries, rmin, pmin = positive_finite(h5)
                check(ok, f"{scheme} {np_} rank(s): rho, p > 0 and finite (min rho {rmin:.3e}, min p {pmin:.3e})")
                check(retries == retried(out), f"{scheme} {np_} rank(s): steps_retried {retries} in the output and "
                      "the summary line")
                e = float(re.search(r"error rho: L1 (\S+)", out).group(1))
                check(e <= bound, f"{scheme} {np_} rank(s): L1(rho) {e:.3e} <= {bound}")
                counts.append(retries)
            check(counts[0] == counts[1], f"{scheme}: steps retried {counts[0]} at 1 and 2 ranks")
        # enopade6 with Lax-Friedrichs splitting: step 1's stages pass the limiter's CFL bound, so the retry is
        # exercised at 1 and 2 ranks (with rf-char, and for crweno5 with either upwinding, the stage speeds stay
        # below the bound: no retry).
        for scheme in ("enopade6",):
            counts = []
            for np_ in (1, 2):
                h5 = os.path.join(d, f"{scheme}_llf{np_}.h5")
                out = run(LEBLANC + ["-scheme", scheme, "-upwinding", "llf", "-output", h5], np_)
                ok, retries, rmin, pmin = positive_finite(h5)
                check(ok and retries == retried(out), f"{scheme} -upwinding llf {np_} rank(s): positive, finite, "
                      f"{retries} retried")
                counts.append(retries)
            check(counts[0] == counts[1] and counts[0] >= 1,
                  f"{scheme} -upwinding llf: the retry is exercised ({counts} step(s) retried at 1, 2 ranks)")


def stage_retry():
    """A stage state that is not admissible is caught inside the step (not only the final state): LeBlanc with
    MUSCL2, the limiter off and -cfl 1.8 (allowed without the limiter) retries step 1 from its first stage at
    half dt and completes positive. (The high-order schemes need the limiter on LeBlanc: without it their first
    step stays non-positive down to 1/64 of that step: enopade6 because its shocked lines are all ENO-Pade rows,
    weno5 because of its p = 1 weights, weno5.hpp.)"""
    with tempfile.TemporaryDirectory() as d:
        h5 = os.path.join(d, "stage.h5")
        out = run(LEBLANC + ["-scheme", "muscl2", "-positivity", "false", "-cfl", 1.8, "-output", h5])
        check(re.search(r"step 1 retried at dt = 0.0135 \(a stage state: invalid p = ", out) is not None,
              "step 1 retried at half dt on a non-positive stage state")
        ok, retries, rmin, pmin = positive_finite(h5)
        check(ok and retries >= 1, f"completes positive (min rho {rmin:.3e}, min p {pmin:.3e}), {retries} retried")


def planar2d():
    """LeBlanc as a planar problem on a 2D grid (along x, 200 x 8 cells), enopade6 (Lax-Friedrichs splitting, so
    that step 1 is retried as in 1D) at 2 ranks: completes positive (the limiter's weighted directional split
    and the retry), L1(rho) as in 1D."""
    with tempfile.TemporaryDirectory() as d:
        h5 = os.path.join(d, "planar.h5")
        args = [a for a in LEBLANC] + ["-dim", 2, "-problem", "riemann", "-axis", "x", "-ny", 8, "-upwinding",
                                       "llf", "-output", h5]
        out = run(args, 2)
        ok, retries, rmin, pmin = positive_finite(h5)
        check(ok, f"2D planar LeBlanc: rho, p > 0 and finite (min rho {rmin:.3e}, min p {pmin:.3e})")
        check(retries == retried(out) and retries >= 1, f"2D planar LeBlanc: {retries} step(s) retried")
        e = float(re.search(r"error rho: L1 (\S+)", out).group(1))
        # measured 2.408e-3; bound + 2%
        check(e <= 2.46e-3, f"2D planar LeBlanc: L1(rho) {e:.3e} <= 2.46e-3 (1D: 2.586e-3)")


def sedov2d():
    """Sedov in 2D with ambient pressure 1e-14 (pressure ratio ~1e15), enopade6 at 2 ranks, 48 x 48 to t = 0.4:
    completes positive and finite; mass and energy change only by what the outflow boundaries let through
    (measured 1.4e-14 and 1.4e-14 relative: the blast stays inside; at 32 x 32 the smeared front reaches the
    boundary, 1.7e-9). Bound 1e-12: round-off over 2,240 steps of 2,304 cells."""
    with tempfile.TemporaryDirectory() as d:
        h5 = os.path.join(d, "sedov.h5")
        out = run(["-dim", 2, "-problem", "sedov", "-nx", 48, "-ny", 48, "-p_ambient", 1e-14, "-scheme",
                   "enopade6", "-output", h5], 2)
        ok, retries, rmin, pmin = positive_finite(h5)
        check(ok, f"2D Sedov p_ambient 1e-14: rho, p > 0 and finite (min rho {rmin:.3e}, min p {pmin:.3e})")
        for q in ("mass", "energy"):
            v = float(re.search(rf"conservation {q}: .* rel_change (\S+)", out).group(1))
            check(v <= 1e-12, f"2D Sedov: relative change of total {q} {v:.3e} <= 1e-12")


def conservation_zero():
    """Sod's total momentum starts at zero: the conservation line prints the absolute change (a relative
    change of the zero total would read ~1e+299), equal to |final - initial|; mass and energy keep the relative
    change."""
    out = run(["-problem", "sod", "-nx", 100, "-t_final", 0.1])
    m = re.search(r"conservation momentum: initial (\S+) final (\S+) abs_change (\S+) \(initial zero\)", out)
    check(m is not None and float(m.group(1)) == 0.0, "Sod: momentum line reports abs_change for the zero total")
    a, b, c = (float(m.group(i)) for i in (1, 2, 3))
    check(abs(c - abs(b - a)) <= 1e-3 * abs(b - a) and c < 1.0, f"Sod: abs_change {c:.3e} = |final - initial|")
    for q in ("mass", "energy"):
        check(re.search(rf"conservation {q}: .* rel_change \S+", out) is not None, f"Sod: {q} keeps rel_change")


# enopade6 against crweno5 where it is not at or below it (crweno5's Henrick-mapped weights, closer to the
# linear weights than the WENO-Z weights of enopade6's upwind rows): Toro 123 (measured 1.037), the rf-char loss
# of the compact schemes on its near-vacuum centre (docs/euler_extremes.md, "rf-char against local
# Lax-Friedrichs upwinding"), which the mapped weights reduce more; contact_1e6 (1.014), the moving contact at
# density ratio 1e6.
ENOPADE6_OVER_CRWENO5 = {"toro2_123": 1.04, "contact_1e6": 1.02}


def enopade6_vs_crweno5(ranks="1"):
    """On every 1D deck of the battery (inputs/euler/extreme_*.yaml with an exact solution,
    N = 200, the decks' settings) enopade6's L1(rho) is at or below crweno5's, at `ranks` ranks (the tests: 1
    and 2), except on the cases of ENOPADE6_OVER_CRWENO5, where it is within the ratio given. Measured: ratios
    0.83-0.993 (the closest pressure_1e10 0.993 and near_vacuum_left 0.990), the same at 1 and 2 ranks. The same at
    every rank count because faces with an ill-conditioned characteristic basis are treated component-wise
    (lib/euler/characteristic_conditioning.hpp; docs/euler_extremes.md): projected characteristic-wise there,
    pressure_1e10's compact-scheme noise in its cold gas depends on round-off (ratio 0.90 / 1.29 / 1.38 at 1 / 2 /
    3 ranks)."""
    decks = sorted(glob.glob(os.path.join(SRC, "inputs", "euler", "extreme_*.yaml")))
    decks = [d for d in decks if re.search(r"^error: true", open(d).read(), re.M)]
    check(len(decks) == 16, f"{len(decks)} 1D battery decks with an exact solution (16)")
    for deck in decks:
        e = {}
        for scheme in ("enopade6", "crweno5"):
            out = run(["-options_file", deck, "-scheme", scheme, "-quiet"], np_=int(ranks))  # no file: -error prints
            e[scheme] = float(re.search(r"error rho: L1 (\S+)", out).group(1))
        name = os.path.basename(deck)[len("extreme_"):-len(".yaml")]
        bound = ENOPADE6_OVER_CRWENO5.get(name, 1.0)
        check(e["enopade6"] <= bound * e["crweno5"], f"{name}, {ranks} rank(s): enopade6 L1(rho) "
              f"{e['enopade6']:.4e} <= {bound} x crweno5's {e['crweno5']:.4e} (ratio {e['enopade6'] / e['crweno5']:.4f})")


if __name__ == "__main__":
    globals()[sys.argv[1]](*sys.argv[2:])
