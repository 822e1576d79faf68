"""Output options shared by every figure command, and the `wrote PATH` report.

Every figure command takes

    -o, --output FILE   the file of its figure; a command that writes several figures (``plot``,
                        ``lcp-histograms``) writes its main figure (the first one) to FILE
    --outdir DIR        the folder of the figures that -o does not name, under their default names
                        (default: FILE's folder with -o, else the current directory)

and prints ``wrote PATH`` for each figure it writes. Folders are created as needed.

A plotting function follows one signature, ``fn(inputs, outdir=".", output=None, **options) -> list[str]``: it
saves its main figure at ``figure_file(outdir, default_name, output)`` and any further figures at
``figure_file(outdir, other_name)``, and returns the paths in the order written.
"""
from __future__ import annotations

import sys
from pathlib import Path


def add_output_options(parser, default, several=False):
    """Adds -o/--output FILE and --outdir DIR to a figure command's parser. `default` is the main figure's default
    file name as shown in -h (e.g. ``<stem>_profiles.png``, where <stem> is the input file's name without suffix;
    None: named by the figure's own rule); `several`: the command writes further figures beside the main one."""
    what = "the main figure (the first one written)" if several else "the figure"
    where = f"DIR/{default}" if default else "its default name in DIR"
    parser.add_argument("-o", "--output", metavar="FILE", default=None, help=f"file of {what} (default: {where})")
    parser.add_argument("--outdir", metavar="DIR", default=None,
                        help="folder of the default-named figure" + ("s" if several else "")
                        + " (default: FILE's folder with -o, else the current directory)")
    return parser


def resolve_outdir(args) -> str:
    """The folder of the default-named figures: --outdir, else -o's folder, else the current directory."""
    if getattr(args, "outdir", None):
        return str(args.outdir)
    if getattr(args, "output", None):
        return str(Path(args.output).parent)
    return "."


def figure_file(outdir, name, output=None) -> Path:
    """Where a figure goes: `output` when given, else `outdir`/`name`; its folder is created."""
    path = Path(output) if output else Path(outdir) / name
    path.parent.mkdir(parents=True, exist_ok=True)
    return path


def chain(outdir, output, *figures):
    """Runs figure functions `fn(outdir, output)` in order; `output` names the first figure written, the others
    keep their default names in `outdir`. Returns every path written."""
    written = []
    for fn in figures:
        got = fn(outdir, None if written else output)
        written += got
    return written


def report(paths) -> int:
    """Prints `wrote PATH` for each figure; the command's exit status (0)."""
    for p in paths:
        print(f"wrote {p}")
    return 0


def figure_command(fn, inputs="file", **options):
    """The `func` of a figure command: calls fn(args.<inputs>, outdir, output, **{kw: args.<attr>}) and reports
    the paths (exit status 2 when it drew nothing). `options` maps fn's keyword arguments to argument names (or
    callables of args)."""

    def run(args):
        kw = {k: (v(args) if callable(v) else getattr(args, v)) for k, v in options.items()}
        source = getattr(args, inputs)
        written = fn(source, outdir=resolve_outdir(args), output=args.output, **kw)
        if not written:
            shown = " ".join(map(str, source)) if isinstance(source, (list, tuple)) else source
            print(f"error: {shown}: nothing to draw (the file lacks the data of this figure)", file=sys.stderr)
            return 2
        return report(written)

    return run
