"""`raylab sweep` on a Dask cluster: one job per cell, the same contact sheet (PNG and EXR) bit for bit.

Finished cells are kept as EXR files in FILE.cells/KEY/ beside the sheet, KEY standing for everything that
decides their pixels, so a rerun of an interrupted sweep renders only the missing cells, and a rerun with other
options starts a new set."""
import threading
from pathlib import Path

from .. import _raylab
from .jobs import FarmReport, Job, Stopwatch, farm

# Options that name the sheet's files: the client writes those; workers, maybe on other machines, never see them.
_OUTPUT_OPTIONS = ("--out", "--png", "--gltf")

# Per worker process: the studies it has rendered cells of, each holding the process's device and the cell scene
# (made at its first cell). One job at a time uses them.
_studies: dict = {}
_device_lock = threading.Lock()


def worker_arguments(arguments: list[str]) -> tuple[str, ...]:
    """The sweep's options without the output files (--out FILE, --out=FILE, --png, --gltf ...)."""
    kept, skip = [], False
    for argument in arguments:
        if skip:
            skip = False
        elif argument in _OUTPUT_OPTIONS:
            skip = True
        elif not argument.startswith(tuple(option + "=" for option in _OUTPUT_OPTIONS)):
            kept.append(argument)
    return tuple(kept)


def render_cell(arguments: tuple[str, ...], cell: int):
    """A farm job, on a worker: cell `cell` of the sweep `raylab sweep ARGUMENTS` describes."""
    with _device_lock:
        clock = Stopwatch()
        study = _studies.get(arguments)
        if study is None:
            study = _raylab.SweepStudy(list(arguments), outputs=False)
            study.prepare()
            _studies[arguments] = study
        clock.setup_done()
        image = study.render_cell(cell)
        return image, clock.info()


def cells_directory(study) -> Path:
    return Path(study.png_path).with_suffix(".cells") / study.key


def sweep(arguments, *, workers=None, scheduler=None, client=None, progress=True) -> FarmReport:
    """Renders `raylab sweep ARGUMENTS` (a list of its command-line arguments) on a LocalCluster of `workers`
    processes, on the running scheduler at `scheduler`, or through `client`, and writes its contact sheet as the
    command does. Raises ValueError with the command's message for bad options."""
    arguments = [str(argument) for argument in arguments]
    study = _raylab.SweepStudy(arguments, outputs=True)
    if not study.renders:  # --gltf alone: written above
        return FarmReport()
    directory = cells_directory(study)
    on_workers = worker_arguments(arguments)
    jobs = [Job(key=f"raylab-sweep-{study.key}-cell-{cell:03d}", name=f"cell {cell} ({study.label(cell)})",
                path=directory / f"cell_{cell:03d}.exr", function=render_cell, args=(on_workers, cell),
                samples=study.spp, description=f"raylab sweep {study.key} cell {cell}")
            for cell in range(study.cells)]
    report = farm(jobs, directory / "jobs.log", "raylab.farm sweep", client=client, workers=workers,
                  scheduler=scheduler, progress=progress)
    study.write_sheet([_raylab.read_exr(str(job.path)) for job in jobs])
    return report
