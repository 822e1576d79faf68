"""Reader for the suite's HDF5 files: root attributes (provenance), datasets with units, snapshots."""
from __future__ import annotations

import re
from dataclasses import dataclass, field

import h5py
import numpy as np

PROVENANCE = ("program", "version", "options", "nranks", "start_time", "wall_seconds")


def _plain(value):
    """HDF5 attribute value as a plain Python value (str for strings, float/int for scalars)."""
    if isinstance(value, bytes):
        return value.decode()
    if isinstance(value, np.ndarray):
        if value.dtype.kind in "SO":
            return [v.decode() if isinstance(v, bytes) else v for v in value.tolist()]
        return value
    if isinstance(value, np.generic):
        return value.item()
    return value


@dataclass
class RunFile:
    """One output file of a suite program, read eagerly for attributes and lazily for data."""

    path: str
    attrs: dict = field(default_factory=dict)
    datasets: dict = field(default_factory=dict)  # path -> (shape, dtype, units)

    @property
    def program(self) -> str:
        return self.attrs.get("program", "")

    def read(self, dataset: str) -> np.ndarray:
        with h5py.File(self.path, "r") as f:
            if dataset not in f:
                raise KeyError(f"{self.path}: no dataset {dataset}")
            return f[dataset][...]

    def units(self, dataset: str) -> str:
        return self.datasets[dataset][2]

    def group_attrs(self, group: str) -> dict:
        with h5py.File(self.path, "r") as f:
            return {k: _plain(v) for k, v in f[group].attrs.items()}

    def snapshots(self, group: str = "/snapshots") -> list[tuple[str, float]]:
        """Snapshot groups (name, time) sorted by step number, from groups /snapshots/NNNNNN."""
        out = []
        with h5py.File(self.path, "r") as f:
            if group not in f:
                return out
            for name in sorted(f[group], key=lambda s: int(s) if s.isdigit() else s):
                g = f[group][name]
                out.append((f"{group}/{name}", float(_plain(g.attrs.get("time", np.nan)))))
        return out


def open_run(path: str) -> RunFile:
    """Reads the root attributes and the dataset index of a suite output file."""
    run = RunFile(path)
    with h5py.File(path, "r") as f:
        run.attrs = {k: _plain(v) for k, v in f.attrs.items()}

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                units = _plain(obj.attrs.get("units", ""))
                run.datasets["/" + name] = (obj.shape, obj.dtype, units)

        f.visititems(visit)
    missing = [a for a in PROVENANCE if a not in run.attrs]
    if missing:
        raise ValueError(f"{path}: not a suite output file (missing root attributes {', '.join(missing)})")
    return run


def option_value(run: RunFile, name: str, default=None):
    """Value of option -name in the run's options attribute (the whole options database as text)."""
    m = re.search(r"(?:^|\s)-" + re.escape(name) + r"(?:\s+([^-\s][^\s]*))?", run.attrs.get("options", ""))
    if not m:
        return default
    return m.group(1) if m.group(1) is not None else True
