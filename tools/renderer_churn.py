#!/usr/bin/env python3
"""Creates and destroys many raylab.Renderer objects in one process, some with an injected Vulkan failure
(raylab._fail_at_creation), and reports the process's resident memory along the way: a long-lived process (the
viewer, a notebook, a farm worker) must not grow with the renderers it has made.

    .venv/bin/python tools/renderer_churn.py --count 1000            # about 8 minutes on lavapipe
    .venv/bin/python tools/renderer_churn.py --count 200 --failing 1  # only failing creations: seconds
"""
from __future__ import annotations

import argparse
import random
import time

import raylab

from raylab_tools import REPO, run_main


def resident_mib() -> float:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096 / 2**20


def churn(scene, count: int, failing: float, seed: int) -> list[tuple[int, float]]:
    """Makes `count` renderers (a fraction `failing` of them with a failure injected at an early creation step)
    and returns (renderers made, resident MiB) every tenth of the way."""
    rng = random.Random(seed)
    marks = []
    for i in range(1, count + 1):
        if rng.random() < failing:
            raylab._fail_at_creation(rng.randint(1, 40))
            try:
                raylab.Renderer(scene, width=8, height=8, integrator="slides")
            except (RuntimeError, MemoryError, ValueError):
                pass
            finally:
                raylab._fail_at_creation(0)
        else:
            renderer = raylab.Renderer(scene, width=8, height=8, integrator="slides")
            renderer.render(1)
            del renderer
        if i % max(1, count // 10) == 0:
            marks.append((i, resident_mib()))
    return marks


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--count", type=int, default=1000)
    parser.add_argument("--failing", type=float, default=0.5, help="fraction with an injected failure (0.5)")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    scene = raylab.Scene.load(str(REPO / "assets" / "scenes" / "sweep_lambert_rho_d.gltf"))
    start = time.time()
    marks = churn(scene, args.count, args.failing, args.seed)
    for made, mib in marks:
        print(f"{made:6d} renderers: {mib:7.1f} MiB resident")
    growth = marks[-1][1] - marks[0][1]
    print(f"growth from {marks[0][0]} to {marks[-1][0]} renderers: {growth:+.1f} MiB in {time.time() - start:.0f} s")


if __name__ == "__main__":
    run_main(main)
