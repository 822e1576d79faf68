"""Log-heap figures of the contact issue on small generated files: iteration histograms of an lcpbench result
file (medians checked against the generated values), splitting convergence of a short contact run, and the
speed-against-accuracy plot of a contact-logheap table."""
import h5py
import numpy as np
import pytest

from postprocess import contact_plots as cp
from postprocess.__main__ import main


def _bench_file(path):
    n = np.array([10, 20, 40, 40])
    with h5py.File(path, "w") as f:
        f.attrs["solvers"] = "lemke,smoothed_newton"
        f["problems/n"] = n
        for s, piv, it, st in (("lemke", [10, 30, 40, 80], [10, 30, 40, 80], [0, 0, 0, 2]),
                               ("smoothed_newton", [0, 0, 0, 0], [5, 7, 9, 11], [0, 0, 0, 0])):
            g = f.create_group(f"results/{s}")
            g["status"] = np.array(st)
            g["iterations"] = np.array(it)
            g["pivots"] = np.array(piv)
            g["time"] = np.ones(4) * 1e-3
            g["residual"] = np.zeros(4)


def test_heap_histograms(tmp_path, capsys):
    path = tmp_path / "heap.h5"
    _bench_file(path)
    st = cp.heap_histogram_stats(path)
    # lemke: pivots / n of the solved problems = 1, 1.5, 1 -> median 1; the failed one is counted
    assert st["lemke"]["unit"] == "pivots/n" and st["lemke"]["median"] == pytest.approx(1.0)
    assert st["lemke"]["failed"] == 1 and st["lemke"]["solved"] == 3
    assert st["smoothed_newton"]["unit"] == "iterations" and st["smoothed_newton"]["median"] == pytest.approx(8.0)
    assert main(["contact-heap-histograms", str(path), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "contact_heap_histograms_heap.png").stat().st_size > 0
    assert "lemke: 3 solved, 1 failed, median 1 pivots/n" in capsys.readouterr().out


def test_split_convergence(tmp_path, run_suite):
    out = tmp_path / "heap.h5"
    run_suite("contact", "-scene", "log_heap", "-n_logs", 5, "-steps", 40, "-friction", "splitting",
              "-splitting_max_it", 6, "-splitting_tol", 1e-12, "-regularisation", 1e-4, "-quiet", "-output", out)
    d = cp.splitting_convergence_stats(out)
    assert d["steps"] > 10 and 2 <= len(d["median"]) <= 5  # passes 2..6 (or until converged)
    assert d["median"][-1] <= d["median"][0] and d["max"][-1] < d["max"][0]  # the iteration contracts
    assert np.all(d["max"] >= d["median"])
    assert main(["contact-split-convergence", str(out), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "contact_heap_split_convergence.png").stat().st_size > 0


def test_speed_accuracy(tmp_path, capsys):
    path = tmp_path / "sa.h5"
    with h5py.File(path, "w") as f:
        for name, ms, v, failed in (("box", 2.0, 0.03, 0), ("polyhedral", 5.0, 1e-9, 0), ("x", 0, 0, 1)):
            g = f.create_group(f"cases/{name}")
            g.attrs["failed"] = failed
            if not failed:
                g.attrs["step_ms"] = ms
                g.attrs["cone_violation"] = v
    rows = cp.read_speed_accuracy(path)
    assert {r["name"] for r in rows} == {"box", "polyhedral", "x"}
    assert main(["contact-speed-accuracy", str(path), "--outdir", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "polyhedral  5.000  1.000e-09" in out and "\nx " not in out
    assert (tmp_path / "contact_speed_accuracy_sa.png").stat().st_size > 0
