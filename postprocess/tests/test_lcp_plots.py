"""lcpbench figures: performance profile on a hand-made table, the three figures from a synthetic batch file,
and (when the executable is built) from a real lcpbench run."""
import h5py
import numpy as np
import pytest

from postprocess.__main__ import main
from postprocess.lcp_plots import performance_profile, read_batch


def test_performance_profile_hand_table():
    inf = np.inf
    t = np.array([[1.0, 2.0], [3.0, 1.0], [2.0, inf], [inf, inf]])  # last problem: nobody solves it
    taus, rho = performance_profile(t, taus=[1.0, 2.0, 3.0])
    # 3 problems with a best time; solver 0 best on 2 of them, within 3x on all 3
    assert rho[0].tolist() == pytest.approx([2 / 3, 1 / 3])
    assert rho[1].tolist() == pytest.approx([2 / 3, 2 / 3])
    assert rho[2].tolist() == pytest.approx([1.0, 2 / 3])


def write_batch(path, solvers, count=30, n=10):
    rng = np.random.default_rng(0)
    with h5py.File(path, "w") as f:
        f.attrs["program"] = "lcpbench"
        f.attrs["solvers"] = ", ".join(solvers)
        f["problems/n"] = np.full(count, n, dtype=np.int32)
        for k, s in enumerate(solvers):
            g = f.create_group(f"results/{s}")
            g["status"] = (rng.random(count) < 0.1 * k).astype(np.int32)
            g["iterations"] = rng.integers(1, 30, count)
            g["pivots"] = rng.integers(n, 3 * n, count)
            g["time"] = rng.random(count) * 1e-3
            g["residual"] = rng.random(count) * 1e-11


def test_figures_from_synthetic_batch(tmp_path):
    h5 = tmp_path / "batch.h5"
    write_batch(h5, ["lemke", "bpp", "fb_newton"])
    solvers, sizes, res = read_batch(h5)
    assert solvers == ["lemke", "bpp", "fb_newton"] and sizes[0] == 10
    assert main(["lcp-histograms", str(h5), "--outdir", str(tmp_path)]) == 0
    for suffix in ("iterations", "time_residual", "profile"):
        assert (tmp_path / f"lcp_batch_{suffix}.png").stat().st_size > 1000


def test_figures_from_lcpbench_run(tmp_path, suite_bin, run_suite):
    if not (suite_bin / "lcpbench").exists():
        pytest.skip("lcpbench not built")
    h5 = tmp_path / "run.h5"
    run_suite("lcpbench", "-family", "random_box", "-n", 10, "-count", 12, "-solvers", "lemke,bpp,fb_newton,pgs",
              "-output", h5, "-quiet", np=2)
    solvers, sizes, res = read_batch(h5)
    assert solvers == ["lemke", "bpp", "fb_newton", "pgs"]
    assert all((res[s]["status"] == 0).all() for s in ("lemke", "bpp", "fb_newton"))
    assert main(["plot", str(h5), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "lcp_run_profile.png").stat().st_size > 1000


def test_portfolio_figure_from_lcpbench_auto(tmp_path, suite_bin, run_suite):
    """-solvers auto: the per-problem class, succeeding and tried solvers are read back and drawn."""
    if not (suite_bin / "lcpbench").exists():
        pytest.skip("lcpbench not built")
    from postprocess.lcp_plots import portfolio_table, read_portfolio

    h5 = tmp_path / "auto.h5"
    run_suite("lcpbench", "-family", "random_spd", "-n", 10, "-count", 6, "-solvers", "auto,bpp",
              "-output", h5, "-quiet", np=1)
    pf = read_portfolio(h5)
    assert pf["classes"] == ["lcp-spd-small"] * 6 or all(c.startswith("lcp-") for c in pf["classes"])
    assert all(s and t and t[-1] == s for s, t in zip(pf["solver"], pf["tried"]))
    assert sum(sum(r.values()) for r in portfolio_table(pf).values()) == 6
    assert main(["lcp-histograms", str(h5), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "lcp_auto_portfolio.png").stat().st_size > 1000
    assert read_portfolio(tmp_path / "auto.h5") is not None
