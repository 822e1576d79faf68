"""Whether the tests run on an instrumented build: scripts/test-asan sets SUITE_TIMEOUT_SCALE > 1 for its
ASan+UBSan build (3-10x slower), where a check runs smaller grids or fewer steps that take the same code paths,
with the same bounds (the Release stage runs the sizes in the docstrings)."""
import os

SLOW_BUILD = float(os.environ.get("SUITE_TIMEOUT_SCALE", "1")) > 1
