"""Post-processing of the suite's HDF5 output: readers and one plotting module per app (``*_plots.py``).

Command line: ``python -m postprocess {info,plot,<figure>} FILE ...`` (``-h`` lists the figures); every figure
command takes ``-o/--output FILE`` and ``--outdir DIR`` and prints ``wrote PATH`` per figure (``cli.py``).
Installed by scripts/install-deps (``pip install -e postprocess``), so it runs from any directory.
"""
from .reader import RunFile, open_run  # noqa: F401

__all__ = ["RunFile", "open_run"]
