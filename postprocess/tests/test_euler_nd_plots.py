"""2D/3D euler figures on small synthetic files whose answers are known: gradient and schlieren of analytic
fields, the observed orders of errors built with a known slope, a spectrum that is exactly k^-5/3."""
import h5py
import numpy as np
import pytest

from postprocess.__main__ import main
from postprocess.euler_nd_plots import (convergence_table, fitted_order, gradient_magnitude, kolmogorov_guide,
                                        observed_orders, read_errors, read_field, schlieren)


def _write_run(path, rho, x, y, z=None, scheme="enopade6", errors=None, spectrum=None, snapshots=()):
    with h5py.File(path, "w") as f:
        f.attrs["program"] = "euler"
        f.attrs["dim"] = 3 if rho.ndim == 3 else 2
        f.attrs["nx"], f.attrs["ny"] = len(x), len(y)
        f.attrs["nz"] = len(z) if z is not None else 1
        f.attrs["problem"], f.attrs["scheme"] = "isentropic_vortex", scheme
        f.attrs["gamma"], f.attrs["time"], f.attrs["steps"] = 1.4, 0.5, 10
        f["grid/x"], f["grid/y"] = x, y
        if z is not None:
            f["grid/z"] = z
        for name in ("rho", "u", "v", "w", "p"):
            f[f"final/{name}"] = rho if name == "rho" else np.zeros_like(rho)
        for step, t, data in snapshots:
            g = f.create_group(f"snapshots/{step:06d}")
            g["rho"] = data
            g.attrs["time"], g.attrs["step"] = t, step
        if errors is not None:
            g = f.create_group("errors")
            for k, v in errors.items():
                g.attrs[k] = v
        if spectrum is not None:
            f["spectrum/k"], f["spectrum/E"] = spectrum


def _grid(n, lo=0.0, hi=1.0):
    h = (hi - lo) / n
    return lo + (np.arange(n) + 0.5) * h


def test_gradient_of_linear_field_is_exact():
    x, y = _grid(20), _grid(10, 0.0, 2.0)
    X, Y = np.meshgrid(x, y)
    g = gradient_magnitude(x, y, 2.0 * X + 3.0 * Y)
    assert g.shape == (10, 20)
    np.testing.assert_allclose(g, np.sqrt(13.0), rtol=1e-12)


def test_schlieren_values():
    x, y = _grid(64), _grid(32)
    X, Y = np.meshgrid(x, y)
    # uniform field: no gradient, schlieren 1
    np.testing.assert_array_equal(schlieren(x, y, np.ones_like(X)), 1.0)
    # a smooth front along x: darkest (exp(-k)) where |grad| is largest, ~1 far from it
    rho = 1.0 + np.tanh((X - 0.5) / 0.05)
    s = schlieren(x, y, rho, k=10.0)
    assert s.min() == pytest.approx(np.exp(-10.0), rel=1e-12)
    assert np.argmin(s[5]) in (31, 32)
    assert s[:, 0].min() > 0.999
    g = gradient_magnitude(x, y, rho)
    np.testing.assert_allclose(s, np.exp(-10.0 * g / g.max()))


def test_images_2d_3d_and_snapshot(tmp_path):
    x, y, z = _grid(16), _grid(8), _grid(6)
    rho2 = np.add.outer(y, x)  # (ny, nx)
    p2 = tmp_path / "run2d.h5"
    _write_run(p2, rho2, x, y, snapshots=[(40, 0.25, 2 * rho2)])
    out = tmp_path / "img2d.png"
    assert main(["euler2d-images", str(p2), "--schlieren", "-o", str(out)]) == 0
    assert out.stat().st_size > 1000
    _, _, v, info = read_field(p2, step=40)
    np.testing.assert_array_equal(v, 2 * rho2)
    assert info["time"] == 0.25
    # 3D: the middle z slice (index nz // 2 = 3) of a field that varies along z
    rho3 = np.stack([rho2 + 10.0 * k for k in range(6)])
    p3 = tmp_path / "run3d.h5"
    _write_run(p3, rho3, x, y, z)
    _, _, v, info = read_field(p3)
    np.testing.assert_array_equal(v, rho2 + 30.0)
    assert info["z"] == pytest.approx(z[3])
    _, _, v, _ = read_field(p3, z_index=5)
    np.testing.assert_array_equal(v, rho2 + 50.0)
    assert main(["euler2d-images", str(p3), "--field", "rho", "-o", str(tmp_path / "img3d.png")]) == 0
    assert (tmp_path / "img3d.png").stat().st_size > 1000


def test_images_bad_input(tmp_path, capsys):
    x, y = _grid(4), _grid(4)
    p = tmp_path / "r.h5"
    _write_run(p, np.ones((4, 4)), x, y)
    assert main(["euler2d-images", str(p), "--field", "entropy", "-o", str(tmp_path / "a.png")]) == 2
    assert "no field 'entropy'" in capsys.readouterr().err
    assert main(["euler2d-images", str(p), "--step", "7", "-o", str(tmp_path / "a.png")]) == 2
    assert "no group /snapshots/000007" in capsys.readouterr().err


def test_observed_orders_of_known_slopes():
    ns = [16, 32, 64, 128]
    np.testing.assert_allclose(observed_orders(ns, [3.0 * n**-5.0 for n in ns]), 5.0, rtol=1e-12)
    assert fitted_order(ns, [0.2 * n**-2.0 for n in ns]) == pytest.approx(2.0, rel=1e-12)
    o = observed_orders([10, 20, 40], [1e-2, 0.0, 1e-4])
    assert np.isnan(o).all()


def test_vortex_convergence_from_files(tmp_path, capsys):
    paths = []
    for scheme, order in (("enopade6", 6), ("weno5", 5)):
        for n in (16, 32, 64):
            p = tmp_path / f"{scheme}_{n}.h5"
            x = _grid(n, 0, 10)
            _write_run(p, np.ones((n, n)), x, x, scheme=scheme,
                       errors={"l1_rho": 5.0 * n**-order, "l2_rho": 7.0 * n**-order, "linf_rho": 20.0 * n**-order})
            paths.append(str(p))
    res = read_errors(paths)
    assert sorted(res) == ["enopade6", "weno5"]
    assert [r[0] for r in res["weno5"]] == [16, 32, 64]
    out = tmp_path / "conv.png"
    assert main(["euler-vortex-convergence", *paths, "-o", str(out)]) == 0
    assert out.stat().st_size > 1000
    printed = capsys.readouterr().out
    rows = [line.split() for line in printed.splitlines() if line.startswith(("enopade6", "weno5"))]
    assert len(rows) == 6
    for row in rows:
        if row[1] != "16":  # order columns (after each error) against the previous N
            expect = 6.0 if row[0] == "enopade6" else 5.0
            assert float(row[3]) == pytest.approx(expect, abs=0.005)
            assert float(row[5]) == pytest.approx(expect, abs=0.005)
        else:
            assert row[3] == "-" and row[5] == "-"
    assert "linf_rho" in convergence_table(res, ("linf",))


def test_vortex_convergence_bad_input(tmp_path, capsys):
    x = _grid(8)
    p = tmp_path / "noerr.h5"
    _write_run(p, np.ones((8, 8)), x, x)
    assert main(["euler-vortex-convergence", str(p), "-o", str(tmp_path / "c.png")]) == 2
    assert "no /errors" in capsys.readouterr().err
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    for q in (a, b):
        _write_run(q, np.ones((8, 8)), x, x, errors={"l1_rho": 1e-3, "l2_rho": 1e-3})
    assert main(["euler-vortex-convergence", str(a), str(b), "-o", str(tmp_path / "c.png")]) == 2
    assert "same N" in capsys.readouterr().err


def test_spectra(tmp_path, capsys):
    k = np.arange(0, 33, dtype=float)
    e = np.where(k > 0, 2.0 * np.maximum(k, 1) ** (-5.0 / 3.0), 0.0)  # k = 0 entry dropped
    x = _grid(4)
    p1, p2 = tmp_path / "s1.h5", tmp_path / "s2.h5"
    _write_run(p1, np.ones((4, 4)), x, x, spectrum=(k, e))
    _write_run(p2, np.ones((4, 4)), x, x, scheme="weno5", spectrum=(k, 0.5 * e))
    gk, ge = kolmogorov_guide(k[1:], e[1:])
    np.testing.assert_allclose(ge, e[1:], rtol=1e-12)  # the guide through an exact k^-5/3 spectrum is the spectrum
    # a spectrum peaking at k = 4: the guide starts there, through the peak, slope -5/3
    kk = np.arange(1, 17, dtype=float)
    ee = np.where(kk <= 4, kk**4, 256.0 * (kk / 4) ** -3.0)
    gk, ge = kolmogorov_guide(kk, ee)
    assert gk[0] == 4.0 and ge[0] == 256.0 and len(gk) == 13
    assert np.polyfit(np.log(gk), np.log(ge), 1)[0] == pytest.approx(-5.0 / 3.0, rel=1e-12)
    out = tmp_path / "spec.png"
    assert main(["euler-spectra", str(p1), str(p2), "-o", str(out)]) == 0
    assert out.stat().st_size > 1000
    p3 = tmp_path / "nospec.h5"
    _write_run(p3, np.ones((4, 4)), x, x)
    assert main(["euler-spectra", str(p3), "-o", str(out)]) == 2
    assert "no /spectrum" in capsys.readouterr().err


def test_from_euler_runs(tmp_path, suite_bin, run_suite, capsys):
    """End to end with the 2D app: vortex errors decrease with N and the figures read the app's files."""
    if not (suite_bin / "euler").exists():
        pytest.skip("euler not built")
    paths = []
    for n in (24, 48):
        p = tmp_path / f"vortex{n}.h5"
        run_suite("euler", "-dim", 2, "-problem", "isentropic_vortex", "-nx", n, "-ny", n, "-t_final", 0.5, "-error",
                  "-output", p, "-quiet")
        paths.append(str(p))
    res = read_errors(paths)
    (scheme, rows), = res.items()
    assert [r[0] for r in rows] == [24, 48]
    assert rows[1][1]["l1_rho"] < rows[0][1]["l1_rho"] / 4  # at least second order between 24 and 48
    assert main(["euler-vortex-convergence", *paths, "-o", str(tmp_path / "conv.png")]) == 0
    dm = tmp_path / "dm.h5"
    run_suite("euler", "-dim", 2, "-problem", "double_mach", "-nx", 48, "-ny", 12, "-max_steps", 10, "-output", dm,
              "-quiet", np=2)
    x, y, rho, info = read_field(dm)
    assert rho.shape == (12, 48) and info["problem"] == "double_mach"
    assert rho.max() > 7.9 and rho.min() < 1.41  # post- and pre-shock gas both present
    assert main(["euler2d-images", str(dm), "--schlieren", "-o", str(tmp_path / "dm.png")]) == 0


def test_mask_shown_gray_and_left_out_of_the_schlieren(tmp_path):
    """A run with a solid obstacle: read_field returns its mask; the field image paints exactly the solid cells
    gray (0.55, 0.55, 0.55) and the schlieren excludes them (NaN: no wall 'shock' in the image, nor in its scale)."""
    x, y = _grid(40), _grid(20)
    rho = np.tile(1.0 + x, (20, 1))  # a uniform gradient: the schlieren is exp(-k) on every fluid cell
    mask = np.zeros((20, 40))
    mask[5:10, 10:20] = 1
    rho[mask > 0] = 7.0  # a frozen state unlike the flow: a jump the schlieren must not show
    p = tmp_path / "step.h5"
    _write_run(p, rho, x, y)
    with h5py.File(p, "a") as f:
        f["final/mask"] = mask
    _, _, v, info = read_field(p)
    assert info["mask"].sum() == 50
    s = schlieren(x, y, np.where(info["mask"], np.nan, v))
    fluid = np.isfinite(s)
    assert np.isnan(s[info["mask"]]).all() and fluid.sum() > 600  # only the solid and its neighbours are left out
    assert np.allclose(s[fluid], np.exp(-15.0))  # the solid's jump to 7 does not set the scale
    main(["euler2d-images", str(p), "--outdir", str(tmp_path), "--schlieren"])
    import matplotlib.image as mpimg
    img = mpimg.imread(tmp_path / "step_rho.png")
    gray = np.all(np.abs(img[..., :3] - 0.55) < 0.01, axis=-1)
    assert gray.sum() > 0
