"""2D side-by-side runs of the Euler app and HyPar (Ghosh's finite-difference solver, built from its source by
`build_hypar`), used by scripts/bench/euler-hypar-compare --set 2d.

Both codes get the same point values on the same periodic grid (HyPar's initial.inp is written here from the
suite's definition of the case), the same fixed dt, SSP-RK3, characteristic reconstruction and rf-char
upwinding; HyPar's WENO weights are its defaults (Henrick-mapped Jiang-Shu, epsilon 1e-6, p = 2). The judge is
this file's own exact solution (the isentropic vortex summed over 5 x 5 periodic images, as
lib/euler/problem_nd_vortex.cpp defines it), evaluated at each code's own grid points: L1(rho) = mean |rho -
rho_exact| over the points. Wall time per step: the app's time-loop seconds (`solve_seconds`) and HyPar's
"Solver runtime", each over its number of steps."""
import math
import os
import re
import shutil
import subprocess
import time
from pathlib import Path

import h5py
import numpy as np

GAMMA = 1.4
VORTEX = {"beta": 5.0, "u0": 1.0, "v0": 1.0, "L": 10.0}


def vortex_state(x, y, t):
    """(rho, u, v, p) of the isentropic vortex at points x[i], y[j] (arrays indexed [i, j]) and time t."""
    b, u0, v0, L = VORTEX["beta"], VORTEX["u0"], VORTEX["v0"], VORTEX["L"]
    X, Y = np.meshgrid(x, y, indexing="ij")
    x0 = X - L / 2 - u0 * t
    y0 = Y - L / 2 - v0 * t
    x0 -= L * np.floor(x0 / L + 0.5)
    y0 -= L * np.floor(y0 / L + 0.5)
    du, dv, de = np.zeros_like(X), np.zeros_like(X), np.zeros_like(X)
    for a in range(-2, 3):
        for c in range(-2, 3):
            xb, yb = x0 + a * L, y0 + c * L
            r2 = xb * xb + yb * yb
            s = b / (2 * math.pi) * np.exp(0.5 * (1 - r2))
            du -= s * yb
            dv += s * xb
            de += np.exp(1 - r2)
    T = 1 - (GAMMA - 1) * b * b / (8 * GAMMA * math.pi ** 2) * de
    rho = T ** (1 / (GAMMA - 1))
    return rho, u0 + du, v0 + dv, rho * T


def build_hypar(src, build_dir):
    """HyPar's executable, configured and built with CMake from the source tree `src` into build_dir (kept: a
    second call reuses it)."""
    exe = Path(build_dir) / "src" / "HyPar"
    if exe.exists():
        return exe
    subprocess.run(["cmake", "-S", str(src), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                    "-DBUILD_TESTING=OFF"], check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", str(build_dir), "-j", str(os.cpu_count() or 1)], check=True,
                   stdout=subprocess.DEVNULL)
    return exe


def write_inputs(d, n, dt, steps, scheme, upwinding):
    """HyPar's input files for the vortex on n x n points x_i = (i + 1/2) L / n (the app's cell centres)."""
    L = VORTEX["L"]
    (d / "solver.inp").write_text(
        "begin\n  ndims 2\n  nvars 4\n" f"  size {n} {n}\n  iproc 1 1\n  ghost 3\n  n_iter {steps}\n"
        "  time_scheme rk\n  time_scheme_type ssprk3\n" f"  hyp_space_scheme {scheme}\n"
        "  hyp_interp_type characteristic\n" f"  dt {dt!r}\n  screen_op_iter {steps}\n  file_op_iter {steps}\n"
        "  ip_file_type binary\n  op_file_format binary\n  op_overwrite yes\n  model euler2d\nend\n")
    (d / "physics.inp").write_text(f"begin\n  gamma {GAMMA}\n  upwinding {upwinding}\nend\n")
    (d / "boundary.inp").write_text(
        "4\n" f"periodic 0 1 0 0 0 {L}\nperiodic 0 -1 0 0 0 {L}\nperiodic 1 1 0 {L} 0 0\nperiodic 1 -1 0 {L} 0 0\n")
    (d / "lusolver.inp").write_text("begin\n  reducedsolvetype gather-and-solve\nend\n")
    x = (np.arange(n) + 0.5) * L / n
    rho, u, v, p = vortex_state(x, x, 0.0)
    E = p / (GAMMA - 1) + 0.5 * rho * (u * u + v * v)
    U = np.stack([rho, rho * u, rho * v, E], axis=-1)  # [i, j, var]
    with open(d / "initial.inp", "wb") as f:
        x.astype("<f8").tofile(f)
        x.astype("<f8").tofile(f)
        U.transpose(1, 0, 2).astype("<f8").tofile(f)  # point q = n j + i, 4 values each
    return x


def read_hypar_rho(path, n):
    """rho of HyPar's binary solution file (ndims, nvars, dims, x, y, U with point index q = n j + i)."""
    with open(path, "rb") as f:
        ndims, nvars = np.fromfile(f, "<i4", 2)
        dims = np.fromfile(f, "<i4", ndims)
        assert ndims == 2 and nvars == 4 and list(dims) == [n, n], (ndims, nvars, dims)
        np.fromfile(f, "<f8", 2 * n)
        U = np.fromfile(f, "<f8", 4 * n * n).reshape(n, n, 4)  # [j, i, var]
    return U[:, :, 0].T


def run_hypar_vortex(exe, workdir, n, dt, steps, scheme, upwinding, mpiexec):
    """L1(rho) at t = steps dt, wall seconds per step (HyPar's solver runtime), or (nan, nan, reason)."""
    d = Path(workdir) / f"hypar_vortex_{scheme}_{upwinding}_{n}"
    shutil.rmtree(d, ignore_errors=True)
    d.mkdir(parents=True)
    x = write_inputs(d, n, dt, steps, scheme, upwinding)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    p = subprocess.run([mpiexec, "-n", "1", str(exe)], cwd=d, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, env=env)
    m = re.search(r"Solver runtime \(in seconds\):\s*(\S+)", p.stdout)
    out = d / "op.bin"
    if p.returncode != 0 or not out.exists() or not m:
        return math.nan, math.nan, f"exit {p.returncode}"
    rho = read_hypar_rho(out, n)
    if not np.all(np.isfinite(rho)):
        return math.nan, float(m.group(1)) / steps, "non-finite values"
    exact = vortex_state(x, x, steps * dt)[0]
    return float(np.mean(np.abs(rho - exact))), float(m.group(1)) / steps, ""


def run_suite_vortex(app, workdir, n, dt, steps, scheme, np_, mpiexec):
    """L1(rho) (judged here, as for HyPar) and wall seconds per step of the Euler app's time loop."""
    out = Path(workdir) / f"suite_vortex_{scheme}_{n}.h5"
    cmd = ([mpiexec, "--oversubscribe", "-n", str(np_)] if np_ > 1 else []) + [
        str(app), "-dim", "2", "-problem", "isentropic_vortex", "-nx", str(n), "-ny", str(n), "-dt", repr(dt),
        "-t_final", repr(steps * dt), "-scheme", scheme, "-time", "ssprk3", "-positivity", "false", "-quiet",
        "-output", str(out)]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    if p.returncode != 0:
        return math.nan, math.nan, f"exit {p.returncode}: {p.stdout.strip()[-200:]}"
    with h5py.File(out, "r") as f:
        rho = np.asarray(f["final/rho"])  # [j, i]
        x, y = np.asarray(f["grid/x"]), np.asarray(f["grid/y"])
        t, secs, nsteps = float(f.attrs["time"]), float(f.attrs["solve_seconds"]), int(f.attrs["steps"])
    exact = vortex_state(x, y, t)[0].T
    return float(np.mean(np.abs(rho - exact))), secs / nsteps, ""
