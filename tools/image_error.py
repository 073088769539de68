"""The error a user sees and how soon a renderer reaches it, shared by the speed-against-error studies
(tools/denoise_study.py, tools/guiding_study.py): every channel clamped at 1 in image and reference, then
relMSE = mean((x - r)^2 / (r^2 + 0.01)); a firefly costs at most one clamped pixel, as on screen. And the
committed scenes' references, rendered once and cached by the scene file's hash."""
from __future__ import annotations

import hashlib
import math
import time
from pathlib import Path

import numpy as np
import raylab

from raylab_tools import REPO

EPSILON = 0.01
TARGET = 1e-2  # the clamped relMSE of issue 39's targets
REFERENCE_SEED = 1000


def scene_path(name: str) -> Path:
    return REPO / "assets" / "scenes" / f"{name}.gltf"


def reference(name: str, width: int, height: int, spp: int, out: Path) -> np.ndarray:
    """The default renderer's image of committed scene `name` at `spp` (unguided, seed REFERENCE_SEED), from
    OUT/reference/ when an earlier run of the same scene file made it."""
    digest = hashlib.sha256(scene_path(name).read_bytes()).hexdigest()[:12]
    cached = out / "reference" / f"{name}_{width}x{height}_{spp}spp_{digest}.exr"
    if cached.exists():
        return raylab.read_exr(str(cached))
    print(f"  reference: {spp} spp", flush=True)
    image = raylab.Renderer(raylab.Scene.load(str(scene_path(name))), width=width, height=height).render(
        spp=spp, seed=REFERENCE_SEED)
    raylab.write_exr(str(cached), image)
    return image


def clamped_relmse(image: np.ndarray, reference: np.ndarray) -> float:
    x = np.minimum(image[..., :3], 1.0).astype(np.float64)
    r = np.minimum(reference[..., :3], 1.0).astype(np.float64)
    return float(np.mean((x - r) ** 2 / (r * r + EPSILON)))


def cpu_seconds(function):
    """(result, CPU seconds of the whole process) of function(): lavapipe's threads included."""
    start = time.process_time()
    result = function()
    return result, time.process_time() - start


def time_to(target: float, costs: list[float], errors: list[float]) -> float | None:
    """Where the error curve first falls to `target`, interpolated log-log; None when it never does, and the
    negated cost of the first point when that one is already below (at most that long)."""
    for i, error in enumerate(errors):
        if error <= target:
            if i == 0:
                return -costs[0]
            c0, c1, e0, e1 = costs[i - 1], costs[i], errors[i - 1], errors[i]
            t = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(c0) + t * (math.log(c1) - math.log(c0)))
    return None
