"""Any study as independent jobs on a Dask cluster: each job renders one image on whichever worker takes it; the
client stores each result as an EXR file (atomically) as soon as it arrives and records in its directory's
manifest (raylab-farm.json) what decided its pixels, so a rerun skips every job whose file exists with the same
description, and a worker killed mid-job costs only that job, which the scheduler gives to another worker.

Results travel back to the client (a cell of 192x192 is 0.6 MB), so workers on other machines need no shared
filesystem."""
import hashlib
import json
import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

from distributed import as_completed

from .. import _raylab
from .progress import Progress


@dataclass(frozen=True)
class Job:
    """One render. `function(*args)` runs on a worker and returns (float32 array, info) where info is a dict
    with at least "pid", "host", "render_s", "render_cpu_s" and "setup_s" (device and scene set-up paid by this
    job): Stopwatch.info()."""
    key: str           # unique for what decides the pixels: equal keys are the same work
    name: str          # for people: progress, logs, errors
    path: Path         # where the result is kept (EXR)
    function: Callable[..., Any]
    args: tuple
    samples: int       # samples per pixel, for the progress line
    description: str   # what decides the pixels: the job is done when its file exists and the manifest says this
    png: Callable[[Any, Path], None] | None = None  # also writes a PNG beside the EXR (e.g. a frame)


MANIFEST = "raylab-farm.json"


def file_digest(path: Path) -> str | None:
    """SHA-256 of a regular file's bytes; None when it is missing or not a regular file."""
    try:
        if not path.is_file():
            return None
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return None


# A manifest holds a line per result: megabytes for the largest studies. Beyond this it is not the farm's.
MAX_MANIFEST_BYTES = 64 << 20


def _read_manifest(path: Path) -> str:
    """The manifest's text, read as every raylab reader reads: a regular file only (a FIFO would hang, /dev/zero
    grow without bound), of at most MAX_MANIFEST_BYTES; OSError otherwise."""
    if not path.exists():
        raise FileNotFoundError(path)
    if not path.is_file():
        raise OSError(f"{path} is not a regular file")
    if path.stat().st_size > MAX_MANIFEST_BYTES:
        raise OSError(f"{path} has {path.stat().st_size} bytes, over {MAX_MANIFEST_BYTES}")
    with open(path, "rb") as file:
        return file.read(MAX_MANIFEST_BYTES + 1).decode()


class Manifests:
    """The manifests of the jobs' directories, each read once and kept in memory; a finished job is added and its
    directory's manifest rewritten atomically (a temporary file renamed over it). Each entry records what decided
    the file's pixels and the SHA-256 of the file written, so that a truncated, corrupted or replaced file is
    rendered again rather than trusted."""

    def __init__(self):
        self._by_directory: dict[Path, dict] = {}

    def _of(self, directory: Path) -> dict:
        if directory not in self._by_directory:
            path = directory / MANIFEST
            try:
                manifest = json.loads(_read_manifest(path))
            except FileNotFoundError:
                manifest = {}
            except (OSError, UnicodeDecodeError, RecursionError, json.JSONDecodeError) as error:
                print(f"raylab.farm: {path} is not readable JSON ({error}); its jobs are rendered again",
                      file=sys.stderr)
                manifest = {}
            if not isinstance(manifest, dict):
                print(f"raylab.farm: {path} is not a JSON object; its jobs are rendered again", file=sys.stderr)
                manifest = {}
            self._by_directory[directory] = manifest
        return self._by_directory[directory]

    def is_done(self, job: "Job") -> bool:
        entry = self._of(job.path.parent).get(job.path.name)
        return (isinstance(entry, dict) and entry.get("description") == job.description
                and entry.get("sha256") is not None and entry.get("sha256") == file_digest(job.path))

    def record(self, job: "Job", written: Path):
        """Records `job` as done by the file `written` (which is then renamed to job.path)."""
        manifest = self._of(job.path.parent)
        manifest[job.path.name] = {"description": job.description, "sha256": file_digest(written)}
        temporary = job.path.parent / f".{MANIFEST}.{os.getpid()}.tmp"
        temporary.write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n")
        os.replace(temporary, job.path.parent / MANIFEST)


@dataclass
class FarmReport:
    jobs: int = 0
    skipped: int = 0          # done by an earlier run
    rendered: int = 0
    workers: int = 0
    wall_s: float = 0.0       # submission to last result
    render_s: float = 0.0     # the workers' rendering, summed
    render_cpu_s: float = 0.0  # the CPU time of that rendering (all of lavapipe's threads), summed
    setup_s: float = 0.0      # the workers' device and scene set-up, summed
    by_pid: dict = field(default_factory=dict)  # job name -> the worker process that rendered it

    @property
    def overhead_per_job_s(self) -> float:
        """Worker time not spent rendering or setting up, per job: scheduling, transfers, storing, idle tails."""
        if not self.rendered:
            return 0.0
        return max(0.0, self.wall_s * self.workers - self.render_s - self.setup_s) / self.rendered

    def summary(self) -> str:
        if not self.rendered:
            return f"raylab.farm: all {self.jobs} jobs were already done"
        return (f"raylab.farm: {self.rendered} jobs rendered ({self.skipped} already done) on {self.workers} workers "
                f"in {self.wall_s:.2f} s: rendering {self.render_s:.2f} s, set-up {self.setup_s:.2f} s of worker "
                f"time; farm overhead {self.overhead_per_job_s * 1000:.0f} ms per job")


def run_jobs(client, jobs: list[Job], log_path: Path, label: str = "raylab.farm", progress: bool = True) -> FarmReport:
    """Runs the jobs that are not done yet; returns when every job is. A failing job (bad input, a device error)
    cancels the rest and raises its error with the job's name."""
    manifests = Manifests()
    todo = [job for job in jobs if not manifests.is_done(job)]
    report = FarmReport(jobs=len(jobs), skipped=len(jobs) - len(todo),
                        workers=len(client.scheduler_info()["workers"]))
    if not todo:
        return report
    log_path.parent.mkdir(parents=True, exist_ok=True)
    bar = Progress(label, len(jobs), jobs[0].samples, report.skipped, progress)
    bar.show()
    start = time.monotonic()
    # pure=False: a resubmission after an interruption must run again, not find a forgotten result.
    futures = {client.submit(job.function, *job.args, key=job.key, pure=False): job for job in todo}
    try:
        for future in as_completed(futures):
            job = futures[future]
            try:
                image, info = future.result()
            except Exception as error:
                raise _naming(job, error) from error
            job.path.parent.mkdir(parents=True, exist_ok=True)
            # The manifest records the file before it appears (written beside, renamed last): an interruption
            # at any point leaves either no file or a file the manifest vouches for.
            staged = job.path.with_name(f".{job.path.stem}.staged.exr")
            _raylab.write_exr(str(staged), image)
            if job.png is not None:
                job.png(image, job.path)
            manifests.record(job, staged)
            os.replace(staged, job.path)
            report.rendered += 1
            report.render_s += info["render_s"]
            report.render_cpu_s += info["render_cpu_s"]
            report.setup_s += info["setup_s"]
            report.by_pid[job.name] = info["pid"]
            with open(log_path, "a") as log:
                log.write(f"{job.path.name}\t{job.name}\tpid {info['pid']} on {info['host']}\t"
                          f"render {info['render_s']:.3f} s\tset-up {info['setup_s']:.3f} s\n")
            bar.job_done()
    finally:
        client.cancel(list(futures))
    report.wall_s = time.monotonic() - start
    return report


def farm(jobs: list[Job], log_path: Path, label: str, *, client=None, workers=None, scheduler=None,
         progress=True) -> FarmReport:
    """run_jobs through `client`, or on a cluster made for the jobs (cluster.connect) when any is left to do."""
    if client is not None:
        return run_jobs(client, jobs, log_path, label, progress)
    if all(Manifests().is_done(job) for job in jobs):
        return FarmReport(jobs=len(jobs), skipped=len(jobs))
    from .cluster import connect  # distributed's cluster machinery, only when there is work
    with connect(workers, scheduler) as own_client:
        return run_jobs(own_client, jobs, log_path, label, progress)


def _naming(job: Job, error: Exception) -> Exception:
    """The error again, its message prefixed with the job's name; the kinds the module raises keep their type."""
    for kind in (ValueError, FileNotFoundError, RuntimeError):
        if isinstance(error, kind):
            return kind(f"{job.name}: {error}")
    # e.g. distributed's KilledWorker, when a job took down every worker it was given
    return RuntimeError(f"{job.name}: {type(error).__name__}: {error}")


class Stopwatch:
    """Wall and CPU time (the process's: every lavapipe thread) of a worker's job, set-up and render apart."""

    def __init__(self):
        self.wall, self.cpu = time.monotonic(), time.process_time()
        self.setup_s = 0.0

    def setup_done(self):
        self.setup_s = time.monotonic() - self.wall
        self.wall, self.cpu = time.monotonic(), time.process_time()

    def info(self) -> dict:
        return {"pid": os.getpid(), "host": os.uname().nodename, "render_s": time.monotonic() - self.wall,
                "render_cpu_s": time.process_time() - self.cpu, "setup_s": self.setup_s}
