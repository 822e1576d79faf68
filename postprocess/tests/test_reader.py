"""The reader and the command line on a file the skeleton driver (the shared layer's test program) wrote."""
import numpy as np
import pytest

from postprocess.__main__ import main
from postprocess.reader import open_run, option_value


@pytest.fixture(scope="module")
def skeleton_file(tmp_path_factory, run_suite):
    d = tmp_path_factory.mktemp("skeleton")
    run_suite("skeleton_driver", "-n", 32, "-steps", 4, "-quiet", "-output", d / "s.h5", np=2)
    return d / "s.h5"


def test_provenance_and_units(skeleton_file):
    run = open_run(str(skeleton_file))
    assert run.program == "skeleton_driver"
    assert run.attrs["nranks"] == 2
    assert run.attrs["wall_seconds"] > 0
    assert option_value(run, "steps") == "4"
    assert option_value(run, "quiet") is True
    assert run.datasets["/final/u"][0] == (32,)
    assert run.units("/final/u") == "m/s"
    x = run.read("/grid/x")
    np.testing.assert_allclose(x, (np.arange(32) + 0.5) / 32, rtol=0, atol=1e-15)


def test_info_command(skeleton_file, capsys):
    assert main(["info", str(skeleton_file)]) == 0
    out = capsys.readouterr().out
    assert "@program = skeleton_driver" in out
    assert "/final/u  float64[32]  [m/s]" in out


def test_not_a_suite_file(tmp_path, capsys):
    import h5py

    with h5py.File(tmp_path / "x.h5", "w") as f:
        f["a"] = [1.0]
    assert main(["info", str(tmp_path / "x.h5")]) == 2
    assert "not a suite output file" in capsys.readouterr().err


def test_plot_unknown_program(skeleton_file, tmp_path, capsys):
    assert main(["plot", str(skeleton_file), "--outdir", str(tmp_path)]) == 2
    assert "no plots registered for program 'skeleton_driver'" in capsys.readouterr().err
