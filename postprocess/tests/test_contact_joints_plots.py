"""contact-joints and contact-joint-error figures on small hand-made files."""
import h5py
import numpy as np

from postprocess import contact_joints_plots as cj


def test_cost_table_and_figure(tmp_path):
    rows = [dict(code=c, joint="hinge", links=n, dt=dt, steps=100, stable=int(s), time_per_step=t,
                 time_per_sim_second=t / dt, joint_error=e)
            for c, dt, n, s, t, e in (("suite", 0.01, 25, 1, 3e-4, 1e-11), ("suite", 0.01, 100, 1, 2e-3, 1e-11),
                                      ("mujoco", 0.01, 100, 0, 1e-4, np.nan), ("mujoco", 0.001, 100, 1, 5e-4, 0.0))]
    path = tmp_path / "joints.h5"
    with h5py.File(path, "w") as f:
        for k in rows[0]:
            v = [r[k] for r in rows]
            f[k] = np.array(v, dtype=h5py.string_dtype()) if isinstance(v[0], str) else np.array(v)
    back = cj.read_table(path)
    assert [r["code"] for r in back] == ["suite", "suite", "mujoco", "mujoco"]
    assert back[2]["stable"] == 0 and back[1]["links"] == 100
    pngs = cj.plot_cost(path, tmp_path)
    assert len(pngs) == 1 and (tmp_path / "contact_joints.png").stat().st_size > 1000


def test_joint_error_figure(tmp_path):
    path = tmp_path / "run.h5"
    with h5py.File(path, "w") as f:
        f.attrs["scene"] = "chain"
        f["/steps/time"] = np.linspace(0.01, 1, 100)
        f["/joints/error"] = np.full(100, 1e-11)
    pngs = cj.plot_joint_error([str(path)], tmp_path)
    assert len(pngs) == 1 and (tmp_path / "contact_joint_error.png").stat().st_size > 1000
