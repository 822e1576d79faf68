"""Command line of the postprocess package.

    python -m postprocess info FILE                       root attributes and datasets (with units)
    python -m postprocess plot FILE [-o FILE] [--outdir DIR]  the default figures of the program that wrote FILE
    python -m postprocess <figure> ... [-o FILE] [--outdir DIR]  figures registered by the app modules

Every figure command takes -o/--output FILE (its figure; with several figures, the main one) and --outdir DIR
(the folder of the default-named figures: FILE's folder with -o, else the current directory), and prints
`wrote PATH` per figure (postprocess/cli.py).

Each app module ``postprocess/<app>_plots.py`` defines ``register(subparsers)`` (adds its figure commands)
and may define ``PROGRAM = "<program>"`` with ``default_plot(path, outdir, output=None) -> list[str]`` for
``plot``.
"""
from __future__ import annotations

import argparse
import importlib
import pkgutil
import sys
from pathlib import Path

from .cli import add_output_options, report, resolve_outdir
from .reader import open_run


def app_modules():
    pkg_dir = Path(__file__).parent
    for info in sorted(pkgutil.iter_modules([str(pkg_dir)]), key=lambda i: i.name):
        if info.name.endswith("_plots"):
            yield importlib.import_module(f"{__package__}.{info.name}")


def cmd_info(args):
    run = open_run(args.file)
    print(f"{args.file}")
    for k, v in sorted(run.attrs.items()):
        text = str(v)
        print(f"  @{k} = {text if len(text) < 200 else text[:197] + '...'}")
    for name, (shape, dtype, units) in sorted(run.datasets.items()):
        print(f"  {name}  {dtype}{list(shape)}" + (f"  [{units}]" if units else ""))
    return 0


def cmd_plot(args):
    run = open_run(args.file)
    for mod in app_modules():
        if getattr(mod, "PROGRAM", None) == run.program and hasattr(mod, "default_plot"):
            written = mod.default_plot(args.file, resolve_outdir(args), args.output)
            if not written:
                print(f"{args.file}: no default figure applies to this {run.program} run")
            return report(written)
    print(f"error: no plots registered for program '{run.program}' ({args.file})", file=sys.stderr)
    return 2


def build_parser():
    ap = argparse.ArgumentParser(prog="python -m postprocess", description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="command", required=True)
    p = sub.add_parser("info", help="root attributes and datasets of a suite output file")
    p.add_argument("file")
    p.set_defaults(func=cmd_info)
    p = sub.add_parser("plot", help="default figures for the program that wrote the file")
    p.add_argument("file")
    add_output_options(p, None, several=True)
    p.set_defaults(func=cmd_plot)
    for mod in app_modules():
        mod.register(sub)
    return ap


def main(argv=None):
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except (OSError, KeyError, ValueError) as e:
        text = e.args[0] if isinstance(e, KeyError) and e.args else e  # str(KeyError) would add quotes
        print(f"error: {text}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
