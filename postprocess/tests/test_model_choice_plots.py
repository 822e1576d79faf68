"""The model-choice figure (python -m postprocess model-choice) on a synthetic /model_choice group: the reader,
the per-family front in order of cost (infinite predictions left out), and the command writing a PNG."""
import h5py
import numpy as np
import pytest

from postprocess import model_choice_plots as mc
from postprocess.__main__ import main


@pytest.fixture
def run_file(tmp_path):
    p = tmp_path / "run.h5"
    with h5py.File(p, "w") as f:
        f.attrs["error_l1_rho"] = 4e-4
        g = f.create_group("model_choice")
        attrs = {"families": "weno5,muscl2", "target_error": 5e-4, "chosen_label": "weno5 n=800",
                 "chosen_predicted_cost": 0.2, "chosen_predicted_error": 2.5e-4, "pilot_seconds": 0.1,
                 "total_seconds": 0.35}
        for k, v in attrs.items():
            g.attrs[k] = v
        g["candidates/family"] = np.array([0, 0, 0, 1, 1], dtype=np.int64)
        g["candidates/n"] = np.array([100, 400, 800, 100, 400], dtype=np.int64)
        g["candidates/predicted_cost"] = np.array([0.02, 0.1, 0.2, 0.01, 0.05])
        g["candidates/predicted_error"] = np.array([2e-3, 5e-4, 2.5e-4, np.inf, np.inf])
        for t in ("pilots", "finals"):
            g[f"{t}/family"] = np.array([0], dtype=np.int64)
            g[f"{t}/n"] = np.array([800], dtype=np.int64)
            g[f"{t}/seconds"] = np.array([0.25])
            g[f"{t}/difference"] = np.array([1e-3])
            g[f"{t}/estimate"] = np.array([3e-4])
    return p


def test_reader_and_front(run_file):
    ch = mc.read_choice(run_file)
    assert ch["families"] == ["weno5", "muscl2"]
    assert ch["exact_error"] == pytest.approx(4e-4)
    cost, err = mc.front(ch, 0)
    np.testing.assert_allclose(cost, [0.02, 0.1, 0.2])
    np.testing.assert_allclose(err, [2e-3, 5e-4, 2.5e-4])
    assert len(mc.front(ch, 1)[0]) == 0  # non-converging family: nothing to draw


def test_command_writes_png(run_file, tmp_path):
    out = tmp_path / "fig.png"
    assert main(["model-choice", str(run_file), "-o", str(out)]) == 0
    assert out.stat().st_size > 1000


def test_missing_group_is_an_error(tmp_path):
    p = tmp_path / "plain.h5"
    h5py.File(p, "w").close()
    assert main(["model-choice", str(p), "-o", str(tmp_path / "x.png")]) == 2


def test_bench_figure(tmp_path):
    p = tmp_path / "targets.csv"
    p.write_text("problem,target,failure,chosen,achieved\nsod,1e-3,,weno5 n=512,7e-4\nsod,1e-4,exit 1,,\n"
                 "density_wave,1e-6,,weno5 n=64,2.8e-7\n")
    data = mc.read_bench(p)
    assert data == {"sod": ([1e-3], [7e-4]), "density_wave": ([1e-6], [2.8e-7])}
    out = tmp_path / "b.png"
    assert main(["model-choice-bench", str(p), "-o", str(out)]) == 0
    assert out.stat().st_size > 1000


def test_bench_figure_of_several_tables(tmp_path):
    """Several targets.csv in one figure; a problem in two of them (1 and 2 ranks) keeps its points apart."""
    one, two, so = tmp_path / "targets.csv", tmp_path / "targets_np2.csv", tmp_path / "targets_shu_osher.csv"
    one.write_text("problem,target,chosen,achieved\nsod,1e-3,weno5 n=512,7e-4\n")
    two.write_text("problem,target,chosen,achieved\nsod,1e-3,weno5 n=512,6e-4\n")
    so.write_text("problem,target,chosen,achieved\nshu_osher,1e-2,muscl2 n=3456,5.5e-3\n")
    data = mc.read_bench([one, two, so])
    assert data == {"sod (targets)": ([1e-3], [7e-4]), "sod (targets_np2)": ([1e-3], [6e-4]),
                    "shu_osher": ([1e-2], [5.5e-3])}
    out = tmp_path / "c.png"
    assert main(["model-choice-bench", str(one), str(two), str(so), "-o", str(out)]) == 0
    assert out.stat().st_size > 1000
