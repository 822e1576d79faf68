"""femdyn output -> history figure through `python -m postprocess plot`; CSV figures from synthetic rows."""
import csv

import h5py

from postprocess.__main__ import main
from postprocess.fem_plots import read_history


def test_femdyn_history_plot(tmp_path, run_suite):
    out = tmp_path / "dyn.h5"
    run_suite("femdyn", "-material", "stvk", "-beam_cells", "6,2,2", "-steps", 5, "-tip_load", 1, "-output", out)
    s, attrs = read_history(out)
    assert attrs["program"] == "femdyn" and len(s["time"]) == 6
    with h5py.File(out, "r") as f:
        assert f["mesh/tets"].shape[1] == 4 and f["final/u"].shape == f["mesh/coordinates"].shape
    assert main(["plot", str(out), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "femdyn_dyn_history.png").stat().st_size > 1000
    assert (tmp_path / "dyn.xmf").exists()  # the XDMF sidecar: FILE.h5 -> FILE.xmf


def test_rate_and_orderings_figures(tmp_path):
    rate = tmp_path / "rate.csv"
    with open(rate, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "method", "ordering", "solver", "dofs", "hz"])
        for dofs, hz in ((1000, 400.0), (5000, 60.0)):
            w.writerow(["beam", "stvk-newton", "rcm", "cholmod", dofs, hz])
    assert main(["fem-rate", str(rate), "--outdir", str(tmp_path)]) == 0
    # the real-time benchmark's rows: an error column, one panel of Hz against error per case
    with open(rate, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "method", "ordering", "solver", "dofs", "hz", "error"])
        for m, hz, err in (("stvk-newton", 30.0, 1e-9), ("stvk-lagged", 120.0, 3e-7), ("linear-fixed", 900.0, "")):
            w.writerow(["block-5k", m, "metis", "cholmod", 4860, hz, err])
    out = tmp_path / "rt"
    assert main(["fem-rate", str(rate), "--outdir", str(out)]) == 0
    assert (out / "fem_rate.png").stat().st_size > 1000
    orders = tmp_path / "orders.csv"
    with open(orders, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["source", "ordering", "nnz_L", "profile"])
        for o, v in zip(["natural", "rcm", "amd"], [100, 50, 40]):
            w.writerow(["can_24", o, v, 2 * v])
    assert main(["fem-orderings", str(orders), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "fem_orderings.png").stat().st_size > 1000


def test_femdyn_probe_plot(tmp_path, run_suite):
    out = tmp_path / "probe.h5"
    run_suite("femdyn", "-probe", "-probe_stiffness", 100, "-beam_cells", "6,2,2", "-steps", 5, "-output", out)
    with h5py.File(out, "r") as f:
        assert len(f["probe/haptic_force"]) == 10 * len(f["probe/sync_time"])
    assert main(["plot", str(out), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "femdyn_probe_probe.png").stat().st_size > 1000


def test_femdyn_material_auto_plot(tmp_path, run_suite):
    out = tmp_path / "auto.h5"
    run_suite("femdyn", "-material", "auto", "-target_error", 1e-2, "-tip_load", 1, "-beam_cells", "10,1,1",
              "-dt", 0.2, "-steps", 40, "-output", out)
    with h5py.File(out, "r") as f:
        g = f["material_auto"]
        assert len(g["law"]) == 41 and g.attrs["switches"] >= 1 and g["law"][-1] in (0, 1)
    assert main(["fem-material-auto", str(out), "--outdir", str(tmp_path)]) == 0
    assert (tmp_path / "femdyn_auto_material_auto.png").stat().st_size > 1000
