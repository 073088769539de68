"""python -m raylab.farm sweep [raylab sweep's options] [--workers N | --scheduler ADDRESS]"""
import argparse
import sys

from .. import _raylab

USAGE = "python -m raylab.farm sweep [raylab sweep's options] [--workers N | --scheduler ADDRESS] [--quiet]"

FARM_HELP = """Usage: {usage}

raylab sweep on a Dask cluster: one job per cell, each on whichever worker takes it; the same contact sheet (PNG and
EXR) as `raylab sweep` with the same options, bit for bit. Finished cells are kept in FILE.cells/ beside the sheet:
a rerun after an interruption renders only the missing ones. docs/farm.md says how to run on several machines.

Farm options:
  --workers N          a local cluster of N worker processes (default: one per core)
  --scheduler ADDRESS  a running Dask scheduler instead, e.g. tcp://head:8786 (`dask scheduler`, `dask worker`)
  --quiet              no progress line

raylab sweep's options (all taken as they are):
{sweep_help}"""


def _farm_options(arguments):
    parser = argparse.ArgumentParser(add_help=False, allow_abbrev=False)
    parser.add_argument("--workers", type=int)
    parser.add_argument("--scheduler")
    parser.add_argument("--quiet", action="store_true")
    return parser.parse_known_args(arguments)


def main(argv) -> int:
    if not argv or argv[0] in ("-h", "--help"):
        print(FARM_HELP.format(usage=USAGE, sweep_help=_raylab.sweep_help()))
        return 0
    if argv[0] != "sweep":
        print(f"raylab.farm: unknown study '{argv[0]}' (the farm runs: sweep)\nusage: {USAGE}", file=sys.stderr)
        return 2
    if any(a in ("-h", "--help") for a in argv[1:]):
        print(FARM_HELP.format(usage=USAGE, sweep_help=_raylab.sweep_help()))
        return 0
    try:
        farm, sweep_arguments = _farm_options(argv[1:])
    except SystemExit:  # argparse has printed what was wrong (e.g. --workers without a number)
        return 2
    from .sweep import sweep
    try:
        report = sweep(sweep_arguments, workers=farm.workers, scheduler=farm.scheduler, progress=not farm.quiet)
    except ValueError as error:
        print(error, file=sys.stderr)
        return 2
    except (RuntimeError, FileNotFoundError, OSError) as error:
        print(error, file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("\nraylab.farm: interrupted; finished cells are kept, a rerun renders the rest", file=sys.stderr)
        return 130
    if report.jobs:
        print(report.summary())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
