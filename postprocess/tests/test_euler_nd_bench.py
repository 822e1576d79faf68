"""Numbers computed by scripts/bench/euler-nd (the 2D/3D Euler benchmarks): cell rate, block averaging of a fine
reference onto a coarse grid, the L1 difference, and the cost at which a scheme reaches an accuracy."""
import importlib.machinery
import importlib.util
import math
from pathlib import Path

import numpy as np
import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "bench" / "euler-nd"


@pytest.fixture(scope="module")
def bench():
    loader = importlib.machinery.SourceFileLoader("euler_nd_bench", str(SCRIPT))
    spec = importlib.util.spec_from_loader("euler_nd_bench", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


def test_cell_rate(bench):
    assert bench.cell_rate(64 ** 3, 3, 2.0) == pytest.approx(393216.0, rel=1e-15)
    assert math.isnan(bench.cell_rate(10, 3, 0.0))


def test_ns_per_point_equation_rhs(bench):
    # 1e6 cell updates per CPU second, 5 equations, 3 RHS per SSP-RK3 step: 1e9 / 1.5e7 ns
    assert bench.ns_per_point_equation_rhs(1e6) == pytest.approx(1e9 / 1.5e7, rel=1e-15)
    assert bench.ns_per_point_equation_rhs(1e6, equations=4, rhs_per_step=1) == pytest.approx(250.0, rel=1e-15)
    assert math.isnan(bench.ns_per_point_equation_rhs(0.0))


def test_block_average_of_a_linear_field_is_its_cell_centre_value(bench):
    # f(x, y) = 2 x + 3 y at fine cell centres of [0, 4] x [0, 1]; the average over a block of a linear field is
    # its value at the coarse cell centre.
    nfx, nfy, f = 32, 8, 4
    xf = (np.arange(nfx) + 0.5) * 4.0 / nfx
    yf = (np.arange(nfy) + 0.5) * 1.0 / nfy
    fine = 2 * xf[None, :] + 3 * yf[:, None]
    xc = (np.arange(nfx // f) + 0.5) * 4.0 / (nfx // f)
    yc = (np.arange(nfy // f) + 0.5) * 1.0 / (nfy // f)
    np.testing.assert_allclose(bench.block_average(fine, f), 2 * xc[None, :] + 3 * yc[:, None], rtol=1e-14)
    with pytest.raises(ValueError):
        bench.block_average(np.zeros((6, 8)), 4)


def test_l1_difference(bench):
    fine = np.ones((8, 32))
    coarse = np.ones((4, 16))
    assert bench.l1_difference(coarse, fine, 4.0, 1.0) == 0.0
    # coarse off by 0.5 on one cell of area (4 / 16) * (1 / 4) = 1 / 16
    coarse[1, 3] += 0.5
    assert bench.l1_difference(coarse, fine, 4.0, 1.0) == pytest.approx(0.5 / 16, rel=1e-14)
    # a constant offset d integrates to d times the domain area
    assert bench.l1_difference(np.full((4, 16), 1.25), fine, 4.0, 1.0) == pytest.approx(0.25 * 4.0, rel=1e-14)
    with pytest.raises(ValueError):  # different refinement factors in x and y
        bench.l1_difference(np.ones((4, 8)), fine, 4.0, 1.0)


def test_cost_to_reach_interpolates_in_log_log(bench):
    # error = 1 / cost^2 exactly: the interpolated cost for a target between runs is exact in log-log
    costs = [1.0, 10.0, 100.0]
    errors = [c ** -2 for c in costs]
    assert bench.cost_to_reach(costs, errors, 1e-3) == pytest.approx(10 ** 1.5, rel=1e-12)
    assert bench.cost_to_reach(costs, errors, 2.0) == 1.0  # the cheapest run is accurate enough
    assert bench.cost_to_reach(costs, errors, 1e-5) == math.inf  # never reached, no extrapolation
    assert bench.cost_to_reach(list(reversed(costs)), list(reversed(errors)), 1e-2) == pytest.approx(10.0)


def test_cheapest(bench):
    table = {"a": ([1.0, 10.0], [1e-2, 1e-4]),  # reaches 1e-3 at cost 10^0.5 ~ 3.16
             "b": ([2.0, 4.0], [1e-2, 1e-3]),  # reaches 1e-3 at cost 4
             "c": ([0.5, 1.0], [1e-1, 1e-2])}  # never reaches 1e-3
    scheme, cost = bench.cheapest(table, 1e-3)
    assert scheme == "a"
    assert cost == pytest.approx(10 ** 0.5, rel=1e-12)
    assert bench.cheapest(table, 1e-6) == (None, math.inf)
