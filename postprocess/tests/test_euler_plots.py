"""euler figures: Pareto front on a hand-made table, the tradeoff/convergence figures from a synthetic file, and
profiles + pulse x-t image from real (small) euler runs when the executable is built."""
import h5py
import numpy as np
import pytest

from postprocess.__main__ import main
from postprocess.euler_plots import pareto


def test_pareto_front_hand_table():
    pts = [(1.0, 1e-2), (2.0, 1e-3), (3.0, 2e-3), (0.5, 5e-2), (4.0, 1e-4)]
    assert pareto(pts) == [3, 0, 1, 4]  # (3.0, 2e-3) is dominated by (2.0, 1e-3)


def test_tradeoff_and_convergence_from_synthetic_file(tmp_path):
    path = tmp_path / "tradeoff.h5"
    with h5py.File(path, "w") as f:
        f.attrs["program"] = "euler-tradeoff"
        for prob in ("density_wave", "sod"):
            for scheme, order in (("enopade6", 6), ("weno5", 5)):
                g = f.create_group(f"runs/{prob}/{scheme}/ssprk3")
                n = np.array([20, 40, 80])
                g["nx"] = n
                g["l1_rho"] = 1.0 / n.astype(float) ** order
                g["seconds"] = n * 1e-3
    assert main(["euler-tradeoff", str(path), "--outdir", str(tmp_path)]) == 0
    assert main(["euler-convergence", str(path), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "tradeoff_pareto.png").stat().st_size > 0
    assert (tmp_path / "tradeoff_convergence.png").stat().st_size > 0


def test_profiles_and_pulse_from_runs(tmp_path, suite_bin, run_suite):
    if not (suite_bin / "euler").exists():
        pytest.skip("euler not built")
    sod = tmp_path / "sod.h5"
    run_suite("euler", "-problem", "sod", "-nx", 100, "-error", "-output", sod, "-quiet")
    with h5py.File(sod, "r") as f:
        assert f.attrs["error_l1_rho"] < 1e-2
        assert f["final/rho"].shape == (100,) and f["exact/rho"].shape == (100,)
    pulse = tmp_path / "pulse.h5"
    run_suite("euler", "-problem", "pulse", "-nx", 112, "-max_steps", 100, "-output", pulse, "-quiet", np=2)
    with h5py.File(pulse, "r") as f:
        assert f["spacetime/rho"].shape == (11, 112)
    assert main(["plot", str(pulse), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "pulse_xt.png").exists() and (tmp_path / "pulse_profiles.png").exists()
    assert main(["euler-profiles", str(sod), "--outdir", str(tmp_path)]) == 0
