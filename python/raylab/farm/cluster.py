"""Where the farm's jobs run: a LocalCluster of worker processes, or a running Dask scheduler; and lavapipe's
thread count on every worker, so that the workers on one machine share its cores instead of each taking all."""
import contextlib
import os
import threading

from distributed import Client, LocalCluster
from distributed.diagnostics.plugin import WorkerPlugin


def usable_cores() -> int:
    """The cores this process may run on: a Slurm allocation or a container's cpuset, not the whole machine."""
    return len(os.sched_getaffinity(0))


# How long a running scheduler may be without workers before the farm gives up.
WAIT_FOR_WORKERS_S = 60
# How long a scheduler may take to answer the client's first message. Dask's own connect timeout covers the TCP
# connection only: a server that accepts and never answers would hold the client forever.
SCHEDULER_ANSWER_S = 30
# Worker processes per usable core a local cluster may have: lavapipe already spreads one render over the cores,
# so more workers than this only multiply memory (a typo such as --workers 2000 would exhaust it).
MAX_WORKERS_PER_CORE = 2


def max_local_workers() -> int:
    return MAX_WORKERS_PER_CORE * usable_cores()


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
        with _client_of_scheduler(scheduler) as client:
            _prepare(client)
            yield client
        return
    count = workers if workers is not None else usable_cores()
    check_workers(count)
    # dashboard_address=None: no web server (and no port to collide with another farm).
    with LocalCluster(n_workers=count, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        client.wait_for_workers(count)
        _prepare(client)
        yield client


def check_workers(count: int):
    """--workers N is a count of processes on this machine: at least 1, at most MAX_WORKERS_PER_CORE per core."""
    if not 1 <= count <= max_local_workers():
        raise ValueError(f"raylab.farm: --workers must be within 1..{max_local_workers()} ({MAX_WORKERS_PER_CORE} per "
                         f"usable core of this machine), not {count}; spread wider with --scheduler (docs/farm.md)")


def _client_of_scheduler(address: str) -> Client:
    """A Client of the scheduler at `address`, or RuntimeError when it does not answer within SCHEDULER_ANSWER_S.
    The connection is made on a daemon thread so that a silent server cannot hold the process."""
    made = {}

    def connect_once():
        try:
            made["client"] = Client(address, timeout=SCHEDULER_ANSWER_S)
        except BaseException as error:  # noqa: BLE001 (handed to the caller's thread)
            made["error"] = error

    thread = threading.Thread(target=connect_once, name="raylab-farm-connect", daemon=True)
    thread.start()
    thread.join(SCHEDULER_ANSWER_S + 5)
    if thread.is_alive():
        raise RuntimeError(f"raylab.farm: {address} accepted the connection but did not answer as a Dask scheduler "
                           f"within {SCHEDULER_ANSWER_S} s (is it one? `dask scheduler` prints its address)")
    if "error" in made:
        error = made["error"]
        if isinstance(error, (OSError, TimeoutError)):
            raise RuntimeError(f"raylab.farm: cannot reach the scheduler at {address}: {error}") from None
        raise error
    return made["client"]


def _prepare(client):
    try:
        client.wait_for_workers(1, timeout=WAIT_FOR_WORKERS_S)
    except TimeoutError:
        raise RuntimeError(f"raylab.farm: the scheduler at {client.scheduler.address} has had no worker for "
                           f"{WAIT_FOR_WORKERS_S} s (start some with `dask worker ADDRESS --nthreads 1`, "
                           "docs/farm.md)") from None
    client.register_plugin(LavapipeThreads())
