"""Pure functions of scripts/euler-extremes (the Euler extreme-case battery): the conservation measure, the retry
count read from the app's output, the markdown table and its insertion between the markers of the docs page."""
import importlib.machinery
import importlib.util
import math
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "euler-extremes"


@pytest.fixture(scope="module")
def ee():
    loader = importlib.machinery.SourceFileLoader("euler_extremes", str(SCRIPT))
    spec = importlib.util.spec_from_loader("euler_extremes", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


def test_every_case_has_a_deck_and_the_battery_is_large_enough(ee):
    decks = SCRIPT.parents[1] / "inputs" / "euler"
    assert all((decks / c.deck).is_file() for c in ee.CASES)
    assert sum(c.dim == 1 for c in ee.CASES) >= 15
    assert {c.dim for c in ee.CASES} == {1, 2, 3}


def test_conservation_error_is_relative(ee):
    assert ee.conservation_error(2.0, 2.0) == 0.0
    assert ee.conservation_error(4.0, 4.0 + 4e-12) == pytest.approx(1e-12, rel=1e-3)
    assert ee.conservation_error(0.0, 0.0) == 0.0


def test_conservation_tolerance_is_a_random_walk_of_roundings(ee):
    eps = 2.220446049250313e-16
    assert ee.conservation_tolerance(200, 200) == pytest.approx(100 * eps * 200, rel=1e-14)
    assert ee.conservation_tolerance(64000, 100) == pytest.approx(100 * eps * 2529.822128, rel=1e-9)


def test_retries_from_output_or_attribute(ee):
    summary = "euler: 40 steps to t = 0.2 in 0.1 s (...; rank 0 CPU 0.1 s); steps retried 3, shock rows 0"
    assert ee.retries_of(summary, {}) == 3
    assert ee.retries_of("no retry line", {"steps_retried": 2}) == 2
    assert ee.retries_of("euler: 10 steps to t = 0.2", {}) == 0


def _row(ee, case, scheme, outcome="ok", l1=1e-3, reason=""):
    return {"case": case, "dim": 1, "scheme": scheme, "np": 1, "grid": "200", "outcome": outcome,
            "reason": reason, "l1_rho": l1, "retries": 0, "wall_s": 0.5}


def test_markdown_table_and_docs_markers(ee, tmp_path):
    rows = [_row(ee, "toro3", "enopade6"), _row(ee, "toro3", "muscl2", "FAIL", math.nan, "exit 1: ERROR: p < 0")]
    table = ee.markdown_table(rows, ["enopade6", "muscl2"])
    assert "| `toro3`" in table and "ok · 1.00e-03 · 0 · 0.50 s" in table and "**FAIL**" in table
    assert "1 of 2 runs pass" in table and "- `toro3` / muscl2: exit 1: ERROR: p < 0" in table
    doc = tmp_path / "doc.md"
    doc.write_text(f"head\n{ee.MARK_BEGIN}\nold\n{ee.MARK_END}\ntail\n")
    ee.update_docs(doc, table)
    text = doc.read_text()
    assert text.startswith("head\n") and text.endswith("tail\n") and "old" not in text and table in text
    doc.write_text("no markers")
    with pytest.raises(SystemExit):
        ee.update_docs(doc, table)
