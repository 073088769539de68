"""raylab.farm: studies as independent renders on a Dask cluster (docs/farm.md).

    import raylab.farm
    report = raylab.farm.sweep(["--model", "ward", "--param", "alpha_x", "--steps", "16"], workers=2)
    print(report.summary())
    jobs = raylab.farm.turntable("assets/scenes/minimal.gltf", frames=36, out="out/turn.exr", spp=64)
    raylab.farm.renders(jobs, scheduler="tcp://head:8786")

or from a shell (a sweep takes exactly `raylab sweep`'s options, plus where to run):

    python -m raylab.farm sweep --model ward --param alpha_x --steps 16 --workers 2
    python -m raylab.farm turntable assets/scenes/minimal.gltf --frames 36 --png --scheduler tcp://head:8786

Each job renders on one worker process, which owns one Vulkan device; LP_NUM_THREADS is set per worker so that the
workers of a machine share its cores. Results are stored atomically as they arrive, a rerun skips finished jobs,
and a job whose worker dies is run again on another. Any other study is a list of RenderJobs (`renders`) or of
Jobs (`run_jobs`).
"""
from .jobs import FarmReport, Job, run_jobs  # noqa: F401
from .renders import RenderJob, renders, turntable  # noqa: F401
from .sweep import sweep  # noqa: F401

__all__ = ["FarmReport", "Job", "RenderJob", "connect", "renders", "run_jobs", "sweep", "turntable"]


def connect(workers=None, scheduler=None):
    """A Client on a new LocalCluster of `workers` processes, or on the scheduler at `scheduler` (a context
    manager; see cluster.connect)."""
    from .cluster import connect as _connect
    return _connect(workers, scheduler)
