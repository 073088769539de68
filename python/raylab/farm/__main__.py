"""python -m raylab.farm sweep|turntable ... [--workers N | --scheduler ADDRESS]"""
import argparse
import math
import sys

from .. import _raylab
from .cluster import MAX_WORKERS_PER_CORE, max_local_workers
from .renders import MAX_FRAMES

USAGE = """python -m raylab.farm sweep [raylab sweep's options] [--workers N | --scheduler ADDRESS] [--quiet]
       python -m raylab.farm turntable [SCENE] [options] [--workers N | --scheduler ADDRESS] [--quiet]"""

WHERE_HELP = """  --workers N          a local cluster of N worker processes (default: one per core, at most 2 per core)
  --scheduler ADDRESS  a running Dask scheduler instead, e.g. tcp://head:8786 (`dask scheduler`, `dask worker`)
  --quiet              no progress line"""

FARM_HELP = """Usage: {usage}

Studies as independent renders on a Dask cluster; finished jobs are kept, so a rerun after an interruption
renders only what is missing. docs/farm.md says how to run on several machines.

  sweep      raylab sweep, one job per cell: the same contact sheet (PNG and EXR) as `raylab sweep` with the same
             options, bit for bit. Finished cells are kept in FILE.cells/ beside the sheet.
  turntable  frames of a scene with its camera turned about its target (`turntable --help`)

Where the jobs run:
{where}

raylab sweep's options (all taken as they are):
{sweep_help}"""


def _bounded(low, high, option):
    """An argparse type: an integer within [low, high], else a usage error naming the option and the range."""
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected an integer, not {text!r}") from None
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(f"{option} must be within {low}..{high}, not {value}")
        return value
    return parse


def _point(text):
    """An argparse type: three finite numbers x,y,z."""
    try:
        point = tuple(float(word) for word in text.split(","))
    except ValueError:
        point = ()
    if len(point) != 3 or not all(math.isfinite(p) for p in point):
        raise argparse.ArgumentTypeError(f"expected three finite numbers x,y,z, not {text!r}")
    return point


def _where(parser):
    group = parser.add_argument_group("where the jobs run")
    group.add_argument("--workers", type=_bounded(1, max_local_workers(), "--workers"), metavar="N",
                       help="a local cluster of N worker processes (default: one per core; at most "
                            f"{MAX_WORKERS_PER_CORE} per core)")
    group.add_argument("--scheduler", metavar="ADDRESS", help="a running Dask scheduler instead, e.g. "
                       "tcp://head:8786")
    group.add_argument("--quiet", action="store_true", help="no progress line")


def _turntable_parser():
    parser = argparse.ArgumentParser(
        prog="python -m raylab.farm turntable", allow_abbrev=False,
        description="Frames of SCENE (default: the built-in scene) with its camera turned about its target by "
                    "360/FRAMES degrees per frame, one job per frame; frame 0 equals `raylab render` with the same "
                    "options bit for bit. A rerun renders only the frames missing or made with other options.")
    parser.add_argument("scene", nargs="?", default="", metavar="SCENE", help="a .gltf or .glb file")
    parser.add_argument("--frames", type=_bounded(1, MAX_FRAMES, "--frames"), default=36,
                        help=f"number of frames, 1..{MAX_FRAMES} (default 36)")
    parser.add_argument("--out", default="out/turntable.exr", metavar="FILE.exr",
                        help="frames as FILE_000.exr, FILE_001.exr, ... (default out/turntable.exr)")
    parser.add_argument("--target", type=_point, metavar="X,Y,Z",
                        help="a point of the vertical axis the camera turns about (default: the centre of the scene's "
                             "bounds)")
    parser.add_argument("--png", nargs="?", const=True, default=False, metavar="FILE.png",
                        help="also tone-mapped frames FILE_000.png, ... as `raylab render --png FILE.png` (alone: "
                             "beside the EXRs)")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=360)
    parser.add_argument("--spp", type=int, default=16, help="samples per pixel (default 16)")
    parser.add_argument("--seed", type=int, default=0)
    options = _raylab.render_options  # the engine's declarations (util/render_options.h)
    parser.add_argument("--max-depth", type=int, default=options["max_depth"]["default"],
                        help=options["max_depth"]["help"])
    for name in ("integrator", "backend", "guiding"):
        parser.add_argument(f"--{name}", default=options[name]["default"], choices=options[name]["values"],
                            help=options[name]["help"])
    parser.add_argument("--env", default="", metavar="FILE.exr", help="an equirectangular HDR environment")
    _where(parser)
    return parser


def _sweep(arguments) -> int:
    if any(a in ("-h", "--help") for a in arguments):
        print(FARM_HELP.format(usage=USAGE, where=WHERE_HELP, sweep_help=_raylab.sweep_help()))
        return 0
    parser = argparse.ArgumentParser(prog="python -m raylab.farm sweep", add_help=False, allow_abbrev=False)
    _where(parser)
    farm, sweep_arguments = parser.parse_known_args(arguments)  # the rest is raylab sweep's
    from .sweep import sweep
    return _run(lambda: sweep(sweep_arguments, workers=farm.workers, scheduler=farm.scheduler,
                              progress=not farm.quiet))


def _turntable(arguments) -> int:
    options = _turntable_parser().parse_args(arguments)
    from .renders import renders, turntable

    def run():
        jobs = turntable(options.scene, options.frames, options.out, target=options.target,
                         width=options.width, height=options.height,
                         spp=options.spp, seed=options.seed, max_depth=options.max_depth,
                         integrator=options.integrator, backend=options.backend, guiding=options.guiding,
                         env=options.env, png=options.png)
        report = renders(jobs, workers=options.workers, scheduler=options.scheduler, progress=not options.quiet,
                         label="raylab.farm turntable")
        print(f"wrote {jobs[0].out} .. {jobs[-1].out}")
        return report
    return _run(run)


def _run(study) -> int:
    try:
        report = study()
    except ValueError as error:
        print(error, file=sys.stderr)
        return 2
    except (RuntimeError, OSError) as error:  # OSError: FileNotFoundError and the like
        print(error, file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("\nraylab.farm: interrupted; finished jobs are kept, a rerun renders the rest", file=sys.stderr)
        return 130
    if report.jobs:
        print(report.summary())
    return 0


def main(argv) -> int:
    if not argv or argv[0] in ("-h", "--help"):
        print(FARM_HELP.format(usage=USAGE, where=WHERE_HELP, sweep_help=_raylab.sweep_help()))
        return 0
    studies = {"sweep": _sweep, "turntable": _turntable}
    if argv[0] not in studies:
        print(f"raylab.farm: unknown study '{argv[0]}' (studies: {', '.join(studies)})\nusage: {USAGE}",
              file=sys.stderr)
        return 2
    try:
        return studies[argv[0]](argv[1:])
    except SystemExit as exit:  # argparse: --help (0) or a usage error it has printed (2)
        return exit.code if isinstance(exit.code, int) else 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
