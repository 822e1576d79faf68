"""scripts/scaling-study on the skeleton driver at 1 and 2 ranks, then the scaling figure."""
import csv
import os
import subprocess
import sys
from pathlib import Path

from postprocess.__main__ import main
from postprocess.scaling_plots import read_scaling, speedup

ROOT = Path(__file__).resolve().parents[2]


def test_scaling_study_and_plot(tmp_path, suite_bin):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    cmd = [sys.executable, str(ROOT / "scripts" / "scaling-study"), "--app", "skeleton_driver", "--np", "1,2",
           "--outdir", str(tmp_path), "--", "-n", "4096", "-steps", "20"]
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert p.returncode == 0, p.stdout
    rows = read_scaling(tmp_path / "scaling.csv")
    assert [r["nranks"] for r in rows] == [1, 2]
    assert all(r["wall_seconds"] > 0 for r in rows)
    # the -log_view stage table was parsed: the three standard stages are columns
    assert {"stage_Setup", "stage_Solve", "stage_Output"} <= set(rows[0])
    s = speedup(rows)
    assert s[0][1] == 1.0 and s[0][2] == 1.0
    assert main(["scaling", str(tmp_path / "scaling.csv"), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "scaling_skeleton_driver_strong.png").stat().st_size > 1000


def test_emit_slurm(tmp_path):
    job = tmp_path / "job.sbatch"
    cmd = [sys.executable, str(ROOT / "scripts" / "scaling-study"), "--app", "euler", "--np", "1,2,4",
           "--weak", "nx=1000", "--outdir", str(tmp_path), "--emit-slurm", str(job), "--", "-problem", "sod"]
    subprocess.run(cmd, check=True, stdout=subprocess.PIPE)
    text = job.read_text()
    assert "#SBATCH --array=0-2" in text and "--signal=USR1@300" in text
    assert "HDF5_USE_FILE_LOCKING=FALSE" in text and "-nx $((1000 * NP))" in text


def test_fem_scale_bench_and_plot(tmp_path, suite_bin):
    """scripts/bench/fem-scale on a small beam: the table, the memory/weak-scaling lines, the model at 64 and
    1024 ranks, and the fem-scale figure."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", SUITE_BIN=str(suite_bin))
    cmd = [sys.executable, str(ROOT / "scripts" / "bench" / "fem-scale"), "--runs", "1:20,2,2", "2:20,2,2",
           "2:40,2,2", "--steps", "1", "--outdir", str(tmp_path)]
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert p.returncode == 0, p.stdout
    with open(tmp_path / "scale.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [(int(r["ranks"]), int(r["dofs"])) for r in rows] == [(1, 540), (2, 540), (2, 1080)]
    assert all(float(r["rss_gib_max_rank"]) > 0 and float(r["cpu_s_per_step"]) > 0 for r in rows)
    assert "memory per rank at 2 ranks / 1 rank" in p.stdout and "weak scaling 1 -> 2 ranks" in p.stdout
    with open(tmp_path / "model.csv", newline="") as f:
        model = {int(r["ranks"]): float(r["s_per_step"]) for r in csv.DictReader(f)}
    assert set(model) == {1, 2, 64, 1024} and model[1024] >= model[64] >= model[1] > 0
    assert main(["fem-scale", str(tmp_path / "scale.csv"), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "fem_scale.png").stat().st_size > 1000
