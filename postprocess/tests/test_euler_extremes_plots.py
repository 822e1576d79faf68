"""The extreme-battery figure (python -m postprocess euler-extremes) on a synthetic table: matrix layout, failure
marks, the nan of runs without an exact solution, and the command writing a PNG."""
import math

import numpy as np
import pytest

from postprocess import euler_extremes_plots as ee
from postprocess.__main__ import main

CSV = """case,dim,scheme,np,grid,outcome,reason,l1_rho,retries,wall_s
leblanc,1,enopade6,1,200,FAIL,exit 1: ERROR: invalid p,nan,0,0.1
leblanc,1,muscl2,1,200,ok,,4.0e-03,0,0.05
toro3,1,enopade6,1,200,ok,,1.0e-01,2,0.2
toro3,1,muscl2,1,200,ok,,1.0e-02,0,0.1
sedov_2d,2,enopade6,2,100x100,ok,,nan,0,3.0
sedov_2d,2,muscl2,2,100x100,FAIL,min rho -1,nan,0,1.0
"""


@pytest.fixture
def table(tmp_path):
    p = tmp_path / "table.csv"
    p.write_text(CSV)
    return p


def test_matrix_marks_failures_and_logs_l1(table):
    cases, schemes, l1, failed = ee.battery_matrix(ee.read_table(table))
    assert cases == ["leblanc", "toro3", "sedov_2d"]
    assert schemes == ["enopade6", "muscl2"]
    np.testing.assert_array_equal(failed, [[True, False], [False, False], [False, True]])
    assert l1[1, 0] == pytest.approx(-1.0, abs=1e-14)
    assert l1[0, 1] == pytest.approx(math.log10(4e-3), abs=1e-14)
    assert math.isnan(l1[0, 0]) and math.isnan(l1[2, 0]) and math.isnan(l1[2, 1])


def test_command_writes_png(table, tmp_path):
    out = tmp_path / "fig.png"
    assert main(["euler-extremes", str(table), "-o", str(out)]) == 0
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_missing_column_is_an_error(tmp_path):
    p = tmp_path / "bad.csv"
    p.write_text("case,scheme\nx,y\n")
    with pytest.raises(ValueError, match="outcome"):
        ee.read_table(p)
