"""Post-processing of the suite's HDF5 output: readers and one plotting module per app (``*_plots.py``).

Command line: ``python -m postprocess {info,plot,<figure>} FILE ...`` (``-h`` lists the figures).
"""
from .reader import RunFile, open_run  # noqa: F401

__all__ = ["RunFile", "open_run"]
