"""Contact figures on files the contact app and the incline benchmark wrote."""
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

from postprocess.__main__ import main

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def incline_run(tmp_path_factory, run_suite):
    d = tmp_path_factory.mktemp("contact")
    run_suite("contact", "-scene", "incline", "-theta", 30, "-mu", 0.3, "-steps", 20, "-output_every", 1, "-quiet",
              "-output", d / "incline.h5", np=2)
    return d / "incline.h5"


def test_output_contents(incline_run):
    with h5py.File(incline_run, "r") as f:
        assert f.attrs["program"] in ("contact", b"contact")
        assert f["/frames/positions"].shape == (21, 2, 3)
        assert f["/frames/orientations"].shape == (21, 2, 4)
        assert f["/frames/velocities"].shape == (21, 2, 6)
        np.testing.assert_allclose(f["/steps/force_ratio"][:], 0.3, atol=1e-6)
        assert np.all(f["/steps/contacts"][:] == 4)
        assert f["/steps/force_ratio"].attrs["units"] in ("", b"")
    assert Path(str(incline_run) + ".xmf").exists()


def test_default_plot(incline_run, tmp_path, capsys):
    assert main(["plot", str(incline_run), "--outdir", str(tmp_path)]) == 0
    pngs = sorted(tmp_path.glob("contact_*.png"))
    assert len(pngs) == 2 and all(p.stat().st_size > 0 for p in pngs)


def test_incline_figure(suite_bin, tmp_path):
    out = tmp_path / "incline.h5"
    cmd = [sys.executable, str(ROOT / "scripts/bench/contact-incline"), "--bin", str(suite_bin / "contact"),
           "--count", "6", "--out", str(out)]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert p.returncode == 0, p.stdout
    assert "6/6 converged" in p.stdout
    assert out.with_suffix(".csv").exists()
    assert main(["contact-incline", str(out), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "contact_incline_incline.png").stat().st_size > 0
