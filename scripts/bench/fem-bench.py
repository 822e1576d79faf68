"""Benchmarks of the FEM app (driven by scripts/bench/fem-rate and fem-orderings): write CSV, no figures."""
import csv
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py

ROOT = Path(__file__).resolve().parents[2]
BIN = Path(os.environ.get("SUITE_BIN", ROOT / "build" / "bin"))
DATA = Path(os.environ.get("SUITE_DATA", ROOT.parent / "shared" / "data"))

MESHES = ROOT / "inputs" / "femdyn"
# name, mesh options, tip load of the nonlinear runs (the block and the ellipsoids: compact bodies)
RATE_CASES = [
    ("beam-1k", ["-beam_cells", "37,2,2", "-beam_length", 18.5], 5),
    ("beam-5k", ["-beam_cells", "104,3,3", "-beam_length", 104 / 3], 5),
    ("block-5k", ["-beam_cells", "20,8,8", "-beam_length", 2.5], 5),
    ("ellipsoid-5k", ["-mesh", "file", "-mesh_file", MESHES / "ellipsoid_5k.msh", "-dirichlet", "x=-1.6"], 20),
    ("ellipsoid-20k", ["-mesh", "file", "-mesh_file", MESHES / "ellipsoid_20k.msh", "-dirichlet", "x=-1.6"], 20),
]
RTOL = ["-newton_rtol", "1e-6"]
LOOSE = ["-newton_rtol", "1e-4"]
GA = ["-time_scheme", "generalized_alpha", "-rho_inf", "0.5"]  # the scheme is part of the reference's key  # the lagged modes' default here: tip-history error ~1e-7 (the error column)
RATE_METHODS = [
    # label, material, options; the error of the tip history is against the same material's reference
    ("stvk-newton", "stvk", RTOL),
    # the same full Newton started from the predictor corrected with the last step's factorisation (one solve)
    ("stvk-newton-tp", "stvk", [*RTOL, "-newton_predictor", "tangent"]),
    # modified Newton: the last factorisation, refreshed by the contraction / iteration rule
    ("stvk-lagged", "stvk", ["-jacobian", "lagged", *LOOSE]),
    ("stvk-lagged-1e-5", "stvk", ["-jacobian", "lagged", "-newton_rtol", "1e-5"]),
    ("stvk-lagged-tight", "stvk", ["-jacobian", "lagged", *RTOL]),
    # the work cap of a haptic loop: at most 2 corrections per step, with generalized-alpha's damping (the
    # trapezoidal rule amplifies the residuals capped steps leave: the block diverges at t = 0.25)
    ("stvk-lagged-cap2-ga", "stvk", ["-jacobian", "lagged", *LOOSE, "-newton_max_corrections", "2", *GA]),
    ("corot-initial", "corotational", ["-jacobian", "initial", *RTOL]),
    ("corot-lagged", "corotational", ["-jacobian", "lagged", *LOOSE]),
    ("linear-fixed", "linear", ["-mass", "lumped"]),
]
# per case: more modes (the 20k body: one factorisation costs ~25 solves there, so a larger refresh budget)
CASE_METHODS = {"ellipsoid-20k": [("stvk-lagged-n12", "stvk", ["-jacobian", "lagged", *LOOSE,
                                                               "-lagged_refresh_iterations", "12"])]}
# the reference of each nonlinear material and time scheme: full Newton at a tight tolerance (atol: the residual's
# round-off floor, ~3e-9 on the block)
REFERENCE = ["-ordering", "metis", "-solver", "cholmod", "-newton_rtol", "1e-12", "-newton_atol", "1e-8",
             "-newton_max_it", "30"]
RATE_SOLVERS = [("rcm", "skyline"), ("rcm", "banded"), ("rcm", "cholmod"), ("amd", "cholmod"), ("metis", "cholmod")]
STEPS = 40


def femdyn(out, *args, allow_failure=False):
    """Runs femdyn; with allow_failure a failed run returns its ERROR line (a str) instead of raising."""
    # One core: the threaded OpenBLAS would make the per-thread CPU times miss the BLAS threads' work.
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OPENBLAS_NUM_THREADS="1")
    cmd = [str(BIN / "femdyn"), *map(str, args), "-output", out, "-quiet"]
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        if allow_failure:
            return next((line for line in p.stdout.splitlines() if line.startswith("ERROR")), "failed")
        raise subprocess.CalledProcessError(p.returncode, cmd, p.stdout)
    return h5py.File(out, "r")


def history_error(tip, ref):
    """max_t |tip(t) - ref(t)| / max_t |ref(t)| (the -target_error measure)."""
    return float(max(abs(a - b) for a, b in zip(tip, ref)) / max(abs(b) for b in ref))


def rate(csv_path, cases=None, methods=None):
    """cases, methods: comma-separated names to run (default: all)."""
    rows = []
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "r.h5")
        for case, mesh, load in RATE_CASES:
            if cases and case not in cases.split(","):
                continue
            common = [*mesh, "-dt", 0.01, "-steps", STEPS]
            refs = {}

            def reference(material, scheme):
                if (material, scheme) not in refs:
                    with femdyn(out, *common, "-material", material, "-tip_load", load, *REFERENCE, *scheme) as f:
                        refs[material, scheme] = f["steps"]["tip_deflection"][:]
                return refs[material, scheme]
            for label, material, extra in RATE_METHODS + CASE_METHODS.get(case, []):
                if methods and label not in methods.split(","):
                    continue
                for ordering, solver in RATE_SOLVERS:
                    if case == "ellipsoid-20k" and (solver == "skyline" or (ordering == "rcm" and "lagged" not in label)):
                        continue  # minutes per run: RCM's envelope at 20k costs 2-3 s per factorisation
                    tip_load = 1 if material == "linear" else load
                    scheme = tuple(GA) if "generalized_alpha" in extra else ()
                    ref = None if material == "linear" else reference(material, scheme)
                    f = femdyn(out, *common, "-material", material, "-ordering", ordering, "-solver", solver,
                               "-tip_load", tip_load, *extra, allow_failure=True)
                    if isinstance(f, str):  # the run stopped with an error: the row says so
                        rows.append(dict(case=case, method=label, ordering=ordering, solver=solver, failed=f))
                        print(f"{case},{label},{ordering},{solver},failed: {f}", flush=True)
                        continue
                    with f:
                        s = f["steps"]
                        n = len(s["wall"]) - 1
                        err = "" if ref is None else history_error(s["tip_deflection"][:], ref)
                        row = dict(case=case, method=label, ordering=ordering, solver=solver,
                                   dofs=int(f.attrs["dofs"]), hz=float(f.attrs["rate_hz"]),
                                   hz_wall=n / float(s["wall"][1:].sum()), error=err,
                                   ms_assemble=1e3 * s["assemble"][1:].sum() / n,
                                   ms_factor=1e3 * s["factor"][1:].sum() / n,
                                   ms_solve=1e3 * s["solve"][1:].sum() / n,
                                   newton_per_step=s["newton_iterations"][1:].mean(),
                                   factorizations_per_step=s["factorizations"][1:].mean(),
                                   unconverged_steps=int(n - s["converged"][1:].sum()),
                                   nnz_L=int(f["ordering"].attrs["nnz_L"]),
                                   flops=float(f["ordering"].attrs["factor_flops"]),
                                   bandwidth=int(f["ordering"].attrs["bandwidth"]),
                                   profile=int(f["ordering"].attrs["profile"]),
                                   ordering_ms=1e3 * float(f["ordering"].attrs["time"]), failed="")
                    rows.append(row)
                    print(",".join(f"{v:.4g}" if isinstance(v, float) else str(v) for v in row.values()), flush=True)
    write(csv_path, rows)


def orderings(csv_path):
    rows = []
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "o.h5")
        for mtx in sorted((DATA / "matrices").glob("*.mtx")):
            subprocess.run([str(BIN / "reorder"), "-matrix", str(mtx), "-ordering", "all", "-output", out, "-quiet"],
                           env=env, check=True)
            with h5py.File(out, "r") as f:
                for k in f.keys():
                    rows.append(dict(source=mtx.stem, kind="matrix", n=int(f.attrs["n"]), ordering=k,
                                     bandwidth=int(f[k]["bandwidth"][0]), profile=int(f[k]["profile"][0]),
                                     nnz_L=int(f[k]["nnz_L"][0]), flops=float(f[k]["flops"][0]),
                                     time_ms=1e3 * float(f[k]["time"][0])))
        meshes = [("beam-40k", (110, 10, 10), 11.0), ("cube-40k", (23, 23, 23), 1.0), ("beam-5k", (104, 3, 3), 104 / 3),
                  ("cube-5k", (11, 11, 11), 1.0)]
        for name, cells, length in meshes:
            for k in ("natural", "cm", "rcm", "amd", "metis", "auto"):
                with femdyn(out, "-beam_cells", ",".join(map(str, cells)), "-beam_length", length, "-ordering", k,
                            "-steps", 0) as f:
                    a = f["ordering"].attrs
                    rows.append(dict(source=name, kind="mesh", n=int(f.attrs["dofs"]), ordering=k,
                                     bandwidth=int(a["bandwidth"]), profile=int(a["profile"]), nnz_L=int(a["nnz_L"]),
                                     flops=float(a["factor_flops"]), time_ms=1e3 * float(a["time"])))
                print(rows[-1], flush=True)
    write(csv_path, rows)


def write(path, rows):
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=max((list(r) for r in rows), key=len))
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {path} ({len(rows)} rows)")


if __name__ == "__main__":
    {"rate": rate, "orderings": orderings}[sys.argv[1]](*sys.argv[2:])
