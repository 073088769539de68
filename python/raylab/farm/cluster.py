"""Where the farm's jobs run: a LocalCluster of worker processes, or a running Dask scheduler; and lavapipe's
thread count on every worker, so that the workers on one machine share its cores instead of each taking all."""
import contextlib
import os

from distributed import Client, LocalCluster
from distributed.diagnostics.plugin import WorkerPlugin


def usable_cores() -> int:
    """The cores this process may run on: a Slurm allocation or a container's cpuset, not the whole machine."""
    return len(os.sched_getaffinity(0))


# How long a running scheduler may be without workers before the farm gives up.
WAIT_FOR_WORKERS_S = 60


class LavapipeThreads(WorkerPlugin):
    """Sets LP_NUM_THREADS on each worker (when its environment does not already) to the cores it may use divided
    by the worker processes on that host, before the worker creates its Vulkan device (at its first job). lavapipe
    otherwise starts one rasterizer thread per core in every process: N workers on N cores would run N² threads.

    Workers that join a host later count the workers present then; start every worker with `--nthreads 1`, or set
    LP_NUM_THREADS in the workers' environment to decide yourself (docs/farm.md)."""

    name = "raylab-lavapipe-threads"

    async def setup(self, worker):
        if "LP_NUM_THREADS" in os.environ:
            return
        identity = await worker.scheduler.identity()
        on_this_host = sum(1 for w in identity["workers"].values() if w["host"] == worker.ip)
        os.environ["LP_NUM_THREADS"] = str(max(1, usable_cores() // max(1, on_this_host)))


@contextlib.contextmanager
def connect(workers=None, scheduler=None):
    """A Client for the farm: on `scheduler` (an address such as tcp://host:8786) when given, else on a new
    LocalCluster of `workers` processes (default: one per core) with one job at a time each. The cluster is closed
    on exit, also on Ctrl-C."""
    if workers is not None and scheduler is not None:
        raise ValueError("raylab.farm: give --workers (a local cluster) or --scheduler (a running one), not both")
    if scheduler is not None:
        with Client(scheduler) as client:
            _prepare(client)
            yield client
        return
    count = workers if workers is not None else usable_cores()
    if count < 1:
        raise ValueError(f"raylab.farm: --workers must be at least 1, not {count}")
    # dashboard_address=None: no web server (and no port to collide with another farm).
    with LocalCluster(n_workers=count, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        client.wait_for_workers(count)
        _prepare(client)
        yield client


def _prepare(client):
    try:
        client.wait_for_workers(1, timeout=WAIT_FOR_WORKERS_S)
    except TimeoutError:
        raise RuntimeError(f"raylab.farm: the scheduler at {client.scheduler.address} has had no worker for "
                           f"{WAIT_FOR_WORKERS_S} s (start some with `dask worker ADDRESS --nthreads 1`, "
                           "docs/farm.md)") from None
    client.register_plugin(LavapipeThreads())
