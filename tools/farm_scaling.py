#!/usr/bin/env python3
"""raylab.farm's scaling and overhead on this machine (docs/performance.md, "The farm").

Scaling: one sweep of 16 cells (ward alpha_x, 192x192, --spp, default 1024) rendered
  - by `raylab sweep` in one process (lavapipe's threads: one per core),
  - by the farm on 1 worker with 1 lavapipe thread (one core's worth: the unit the farm multiplies),
  - by the farm on 1 worker with lavapipe's threads on every core (what the farm gives a lone worker),
  - by the farm on N workers (one per core) with 1 lavapipe thread each (what the farm does by default).
Each farm run starts from no finished cells; its time is the farm's own (first submission to last result: the
workers' device set-up included, the cluster's start-up not, which is reported apart). Best of --repeat runs.

Overhead: a sweep of 64 cells of 16x16 at 1 spp, whose renders take about a millisecond, so the farm's time per
job beyond rendering and set-up (scheduling, transfer of the result, the client writing the EXR and the
manifest) is what remains: (wall x workers - render - set-up) / jobs.

    .venv/bin/python tools/farm_scaling.py            # about 6 minutes on 2 cores
    .venv/bin/python tools/farm_scaling.py --spp 256  # quicker, smaller renders
"""
from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from raylab_tools import ToolError, add_raylab_option, check_raylab, run_main, venv_hint

try:
    import raylab
    import raylab.farm
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)} (raylab itself: tools/setup.sh writes "
             ".venv's raylab.pth)")

CORES = os.cpu_count() or 1


def sweep_arguments(spp: int, out: Path) -> list[str]:
    return ["--model", "ward", "--param", "alpha_x", "--steps", "16", "--cell", "192", "--spp", str(spp),
            "--out", str(out)]


def with_lavapipe_threads(threads: int | None):
    """LP_NUM_THREADS for the worker processes started from now on (they inherit it; the farm keeps a set value)."""
    if threads is None:
        os.environ.pop("LP_NUM_THREADS", None)
    else:
        os.environ["LP_NUM_THREADS"] = str(threads)


def farm_run(arguments: list[str], workers: int, threads: int | None) -> tuple[raylab.farm.FarmReport, float]:
    with_lavapipe_threads(threads)
    start = time.monotonic()
    with raylab.farm.connect(workers=workers) as client:
        started = time.monotonic() - start
        report = raylab.farm.sweep(arguments, client=client, progress=False)
    with_lavapipe_threads(None)
    return report, started


def single_process(raylab_binary: Path, arguments: list[str]) -> float:
    start = time.monotonic()
    subprocess.run([str(raylab_binary), "sweep", *arguments], check=True, capture_output=True)
    return time.monotonic() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_raylab_option(parser)
    parser.add_argument("--spp", type=int, default=1024, help="samples per pixel of the scaling sweep (1024)")
    parser.add_argument("--repeat", type=int, default=2, help="runs of each configuration; the best counts (2)")
    options = parser.parse_args()
    raylab_binary = check_raylab(options.raylab)
    device = raylab.devices()[0]
    print(f"machine: {CORES} cores, {platform.processor() or platform.machine()}, load average "
          f"{os.getloadavg()[0]:.2f} at the start")
    print(f"device: {device['name']}; driver {device['driver']}")

    with tempfile.TemporaryDirectory(prefix="raylab-farm-scaling-") as scratch:
        scratch = Path(scratch)
        runs = 0

        def fresh(name: str) -> list[str]:
            nonlocal runs
            runs += 1
            return sweep_arguments(options.spp, scratch / f"{name}_{runs}" / "sheet.png")

        print(f"\nscaling: 16 cells of 192x192 at {options.spp} spp, best of {options.repeat}")
        single = min(single_process(raylab_binary, fresh("single")) for _ in range(options.repeat))
        print(f"  raylab sweep, one process, {CORES} lavapipe threads: {single:.2f} s")
        configurations = [("1 worker, 1 lavapipe thread", 1, 1), (f"1 worker, {CORES} lavapipe threads", 1, None),
                          (f"{CORES} workers, 1 lavapipe thread each", CORES, None)]
        times, cpu = {}, {}
        for label, workers, threads in configurations:
            best = None
            for _ in range(options.repeat):
                report, started = farm_run(fresh("farm"), workers, threads)
                if report.rendered != 16:
                    raise ToolError(f"{label}: {report.rendered} cells rendered, not 16")
                if best is None or report.wall_s < best[0].wall_s:
                    best = (report, started)
            report, started = best
            times[label] = report.wall_s
            cpu[label] = report.render_cpu_s / 16
            print(f"  farm, {label}: {report.wall_s:.2f} s (cluster start {started:.2f} s); worker time: render "
                  f"{report.render_s:.2f} s, set-up {report.setup_s:.2f} s; mean job {report.render_s / 16:.3f} s, "
                  f"{cpu[label]:.3f} CPU s; cores busy {report.render_cpu_s / report.wall_s:.2f}; "
                  f"overhead {report.overhead_per_job_s * 1000:.0f} ms per job")
        (one, lone, many), (one_cpu, lone_cpu, many_cpu) = ([table[label] for label, _, _ in configurations]
                                                            for table in (times, cpu))
        print(f"  speed-up of {CORES} workers (wall clock): {one / many:.2f}x over 1 worker with 1 thread, "
              f"{lone / many:.2f}x over 1 worker with {CORES} threads, {single / many:.2f}x over raylab sweep")
        # On a shared machine the wall clock depends on what else runs; the CPU time a cell costs does not much.
        # Equal CPU per cell means the workers lose nothing to each other: on idle cores the speed-up would be
        # the number of cores busy at that cost.
        print(f"  CPU s per cell: {one_cpu:.3f} (1 worker, 1 thread), {lone_cpu:.3f} (1 worker, {CORES} threads), "
              f"{many_cpu:.3f} ({CORES} workers); CPU efficiency of {CORES} workers against 1 worker with 1 thread "
              f"{one_cpu / many_cpu:.2f}, against 1 worker with {CORES} threads {lone_cpu / many_cpu:.2f}")

        print("\noverhead: 64 cells of 16x16 at 1 spp")
        arguments = ["--model", "ward", "--param", "alpha_x", "--steps", "64", "--cell", "16", "--spp", "1"]
        report, _ = farm_run(arguments + ["--out", str(scratch / "overhead" / "sheet.png")], CORES, None)
        print(f"  {report.rendered} jobs on {report.workers} workers in {report.wall_s:.2f} s: render "
              f"{report.render_s * 1000 / report.rendered:.1f} ms per job, set-up {report.setup_s:.2f} s in all, "
              f"overhead {report.overhead_per_job_s * 1000:.1f} ms per job")
    print(f"\nload average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    run_main(main)
