"""The output options every figure command shares (-o/--output FILE, --outdir DIR, `wrote PATH`), on small
synthetic inputs, and the installed package run from another directory."""
import os
import subprocess
import sys

import h5py
import numpy as np
import pytest

from postprocess.__main__ import build_parser, main
from postprocess.tests.test_lcp_plots import write_batch

EXTREMES_CSV = "case,scheme,outcome,l1_rho\nsod,weno5,ok,1e-3\nsod,muscl2,FAIL,nan\n"


def _figure_commands():
    sub = next(a for a in build_parser()._actions if a.dest == "command")
    return {name: p for name, p in sub.choices.items() if name != "info"}


def test_every_figure_command_takes_output_and_outdir():
    cmds = _figure_commands()
    assert len(cmds) >= 25
    for name, p in cmds.items():
        opts = {s for a in p._actions for s in a.option_strings}
        assert {"-o", "--output", "--outdir"} <= opts, name


@pytest.fixture
def extremes(tmp_path):
    p = tmp_path / "table.csv"
    p.write_text(EXTREMES_CSV)
    return p


def test_default_name_in_the_current_directory(extremes, tmp_path, monkeypatch, capsys):
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    assert main(["euler-extremes", str(extremes)]) == 0
    assert capsys.readouterr().out == "wrote euler_extremes.png\n"
    assert (work / "euler_extremes.png").stat().st_size > 1000


def test_output_and_outdir(extremes, tmp_path, capsys):
    out = tmp_path / "a" / "b" / "fig.png"  # folders are created
    assert main(["euler-extremes", str(extremes), "-o", str(out)]) == 0
    assert capsys.readouterr().out == f"wrote {out}\n" and out.stat().st_size > 1000
    d = tmp_path / "figs"
    assert main(["euler-extremes", str(extremes), "--outdir", str(d)]) == 0
    assert capsys.readouterr().out == f"wrote {d / 'euler_extremes.png'}\n"
    out2 = tmp_path / "x.png"  # -o wins over --outdir for the figure it names
    assert main(["euler-extremes", str(extremes), "--output", str(out2), "--outdir", str(d)]) == 0
    assert capsys.readouterr().out == f"wrote {out2}\n"


def test_several_figures_output_names_the_main_one(tmp_path, capsys):
    h5 = tmp_path / "batch.h5"
    write_batch(h5, ["lemke", "fb_newton"], count=8)
    out = tmp_path / "figs" / "main.png"
    assert main(["lcp-histograms", str(h5), "-o", str(out)]) == 0
    lines = capsys.readouterr().out.splitlines()
    d = tmp_path / "figs"  # the others beside FILE under their default names
    assert lines == [f"wrote {out}", f"wrote {d / 'lcp_batch_time_residual.png'}",
                     f"wrote {d / 'lcp_batch_profile.png'}"]
    other = tmp_path / "other"
    assert main(["lcp-histograms", str(h5), "-o", str(out), "--outdir", str(other)]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == f"wrote {out}" and all(line.startswith(f"wrote {other}") for line in lines[1:])


def test_plot_output_names_the_first_figure(tmp_path, capsys):
    path = tmp_path / "sod.h5"
    with h5py.File(path, "w") as f:
        for k in ("version", "options", "start_time", "problem", "scheme"):
            f.attrs[k] = "x"
        f.attrs["program"], f.attrs["nranks"], f.attrs["wall_seconds"], f.attrs["nx"] = "euler", 1, 0.1, 8
        f["grid/x"] = (np.arange(8) + 0.5) / 8
        for v in ("rho", "u", "p"):
            f[f"final/{v}"] = np.ones(8)
        f["spacetime/rho"], f["spacetime/time"] = np.ones((3, 8)), np.array([0.0, 0.1, 0.2])
    assert main(["plot", str(path), "-o", str(tmp_path / "p.png")]) == 0
    assert capsys.readouterr().out.splitlines() == [f"wrote {tmp_path / 'p.png'}", f"wrote {tmp_path / 'sod_xt.png'}"]


def test_a_figure_without_its_data_is_an_error(tmp_path, capsys):
    path = tmp_path / "static.h5"
    h5py.File(path, "w").close()  # no /material_auto group
    assert main(["fem-material-auto", str(path), "-o", str(tmp_path / "m.png")]) == 2
    assert "nothing to draw" in capsys.readouterr().err and not (tmp_path / "m.png").exists()


def test_runs_from_any_directory(extremes, tmp_path):
    """python -m postprocess resolves from outside the checkout (the package is installed: scripts/install-deps)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    p = subprocess.run([sys.executable, "-m", "postprocess", "euler-extremes", str(extremes)], cwd=tmp_path, env=env,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert p.returncode == 0, p.stdout + "\n(install the package: pip install -e postprocess, or scripts/install-deps)"
    assert p.stdout.strip() == "wrote euler_extremes.png" and (tmp_path / "euler_extremes.png").exists()
