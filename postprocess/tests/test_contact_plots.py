"""Contact figures on files the contact app and the incline benchmark wrote."""
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

from postprocess import contact_plots as cp
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
    assert incline_run.with_suffix(".xmf").exists()  # the XDMF sidecar: FILE.h5 -> FILE.xmf


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



@pytest.fixture
def heights_legend(monkeypatch):
    """Filled at each savefig with the legend labels of the figure's first axes (the heights panel)."""
    from matplotlib.figure import Figure

    labels, save = [], Figure.savefig

    def savefig(fig, *a, **kw):
        legend = fig.axes[0].get_legend()
        labels[:] = [t.get_text() for t in legend.get_texts()] if legend else []
        return save(fig, *a, **kw)

    monkeypatch.setattr(Figure, "savefig", savefig)
    return labels


def _synthetic_run(path, names=None, nbodies=3, nframes=5):
    """A contact run file with frames and bodies (the first body static), optionally /bodies/name."""
    with h5py.File(path, "w") as f:
        for k in ("version", "options", "start_time"):
            f.attrs[k] = ""
        f.attrs["program"], f.attrs["scene"], f.attrs["nranks"], f.attrs["wall_seconds"] = "contact", "stack", 1, 0.1
        f["frames/time"] = np.linspace(0.0, 0.1, nframes)
        pos = np.zeros((nframes, nbodies, 3))
        pos[:, :, 2] = np.arange(nbodies)[None, :] + np.linspace(0, -0.01, nframes)[:, None]
        f["frames/positions"] = pos
        f["bodies/static"] = np.array([1] + [0] * (nbodies - 1), dtype=np.int8)
        if names is not None:
            f["bodies/name"] = names


@pytest.mark.parametrize("kind", ["vlen", "fixed"])
def test_body_names_label_the_heights(tmp_path, kind, heights_legend, capsys):
    """/bodies/name (variable-length or fixed strings) labels the bodies in the legend of the heights panel."""
    names = ["ground", "box_low", "box_top"]
    data = np.array(names, dtype=h5py.string_dtype()) if kind == "vlen" else np.array(names, dtype="S16")
    path = tmp_path / "named.h5"
    _synthetic_run(path, data)
    assert cp.body_labels(path) == names
    out = tmp_path / "figs" / "named.png"
    assert main(["contact-history", str(path), "-o", str(out)]) == 0
    assert capsys.readouterr().out == f"wrote {out}\n" and out.stat().st_size > 1000
    assert heights_legend == ["box_low", "box_top"]  # the dynamic bodies in body order; the static ground is not drawn


def test_body_labels_without_names(tmp_path, heights_legend):
    path = tmp_path / "plain.h5"
    _synthetic_run(path)
    assert cp.body_labels(path) == ["body 0", "body 1", "body 2"]
    assert main(["plot", str(path), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "contact_plain_history.png").stat().st_size > 1000
    assert heights_legend == ["body 1", "body 2"]
