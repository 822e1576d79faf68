"""contact-front figure and its error measure on a small hand-made table."""
import math

import h5py
import numpy as np

from postprocess import contact_front_plots as cf


def _write(path, rows):
    with h5py.File(path, "w") as f:
        for k in rows[0]:
            v = [r[k] for r in rows]
            f[k] = np.array(v, dtype=h5py.string_dtype()) if isinstance(v[0], str) else np.array(v)


def _row(scene, code, mode, drift, speed=math.nan, completed=200):
    return dict(scene=scene, code=code, mode=mode, steps=200, completed=completed, time_per_step=1e-4,
                first_step=1e-3, drift=drift, speed=speed, speed_exact=2.3563, cone_violation=0.0,
                penetration=0.0)


def test_error_measure_and_figure(tmp_path):
    rows = [_row("incline_slide", "suite", "exact", 4.7, speed=2.3563),
            _row("incline_slide", "mujoco", "pyramidal", 4.6, speed=2.2931),
            _row("stack10", "suite", "fast", 3e-4), _row("stack10", "mujoco", "elliptic", 6.1e-3),
            _row("pyramid30", "suite", "exact", math.nan, completed=0), _row("logheap40", "suite", "fast", 1.6)]
    path = tmp_path / "front.h5"
    _write(path, rows)
    back = cf.read_front(path)
    assert [r["scene"] for r in back] == [r["scene"] for r in rows]
    assert abs(cf.run_error(back[1]) - (2.3563 - 2.2931)) < 1e-12  # speed error on the sliding incline
    assert cf.run_error(back[3]) == 6.1e-3  # drift elsewhere
    assert math.isnan(cf.run_error(back[4]))  # a run that made no step has no error
    back[5]["penetration"] = 2e-3
    assert cf.run_error(back[5]) == 2e-3  # the falling heap: its penetration, not its drift
    pngs = cf.plot_front(path, tmp_path)
    assert len(pngs) == 1 and (tmp_path / "contact_front.png").stat().st_size > 1000
