"""pytest configuration: where the suite's executables and reference data are."""
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="session")
def suite_bin() -> Path:
    return Path(os.environ.get("SUITE_BIN", ROOT / "build" / "bin"))


@pytest.fixture(scope="session")
def run_suite(suite_bin):
    """Runs a suite executable with mpiexec; returns the CompletedProcess (raises on failure)."""

    def run(program, *args, np=1, cwd=None, check=True):
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        cmd = ["mpiexec", "--oversubscribe", "-n", str(np), str(suite_bin / program), *map(str, args)]
        p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if check and p.returncode != 0:
            raise AssertionError(f"{' '.join(cmd)} failed ({p.returncode}):\n{p.stdout}")
        return p

    return run
