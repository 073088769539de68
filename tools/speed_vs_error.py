#!/usr/bin/env python3
"""Speed against error: how fast each kernel variant reaches a given image error, in one command.

For each scene of a small fixed set, raylab renders a high-spp reference with the baseline kernel (cached in
OUT/reference/ and reused), then renders at 1, 2, 4, ... spp with each kernel variant:

  baseline      the scene-specialised kernel, exact Fresnel, max depth 8 (raylab render's defaults)
  schlick       --fresnel schlick: Schlick's approximation in glass
  depth2        --max-depth 2: at most two bounces after the primary hit (mirror, glass)
  all_features  --all-features: every model and feature compiled in, not only what the scene uses

Every variant is compared with the BASELINE's reference, so a variant that changes the converged image
(schlick, depth2) shows its bias as an error floor. Errors over all pixels and the R, G, B channels of the
linear images (alpha ignored): RMSE = sqrt(mean((x - r)^2)); relMSE = mean((x - r)^2 / (r^2 + 0.01)), each
channel divided by its own reference value; FLIP = the mean of HDR-FLIP (flip-evaluator) on the linear
images. The time of a point is spp x the variant's steady time per sample from raylab's own report
(`raylab render --report`), the best of its four highest-spp renders: by default in CPU seconds of the raylab
process (lavapipe's worker threads included), which varies far less than wall-clock time on a shared machine;
--clock wall uses wall-clock seconds. Kernel compilation (the first sample) is excluded and reported
separately. Test renders use seed 0 and the reference seed 1000, so their samples are independent.

Writes OUT/speed_vs_error.csv, OUT/summary.md (the table of docs/performance.md), OUT/run.json (machine and
load) and one log-log plot per scene, OUT/speed_vs_error_<scene>.png (with --docs docs/images/performance, copied there to update the docs).

    .venv/bin/python tools/speed_vs_error.py              # about 7 minutes on 2 cores; 2.5 with cached references
    .venv/bin/python tools/speed_vs_error.py --quick      # smoke test: one scene, 64x36, two points
"""
from __future__ import annotations

import argparse
import csv
import hashlib
import json
import math
import os
import shutil
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from raylab_tools import REPO, ToolError, add_raylab_option, check_raylab, run_main, run_raylab, venv_hint

try:
    import flip_evaluator
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from image_io import read_exr
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

EPSILON = 0.01  # relMSE's guard against division by a black reference pixel
TEST_SEED = 0
REFERENCE_SEED = 1000


@dataclass(frozen=True)
class Scene:
    name: str
    file: str | None  # None: the built-in showcase
    camera: str | None = None  # None: the scene's first camera


@dataclass(frozen=True)
class Variant:
    name: str
    options: tuple[str, ...]
    style: str


# The default scene (every BRDF model, one glass sphere, a mirror), a closed box with a mirror and a glass sphere,
# and the glass sweep's close-up camera, where two glass spheres (eta 1.64 and 1.86) in front of a checkered wall
# fill the frame: glass is where the variants differ.
SCENES = [
    Scene("showcase", None),
    Scene("cornell_box", "assets/scenes/cornell_box.gltf"),
    Scene("sweep_glass_eta", "assets/scenes/sweep_glass_eta.gltf", camera="row"),
]
BASELINE = ("--fresnel", "exact", "--max-depth", "8")
VARIANTS = [
    Variant("baseline", BASELINE, "o-"),
    Variant("schlick", ("--fresnel", "schlick", "--max-depth", "8"), "s--"),
    Variant("depth2", ("--fresnel", "exact", "--max-depth", "2"), "^-."),
    Variant("all_features", (*BASELINE, "--all-features"), "x:"),
]
COLUMNS = ["scene", "variant", "spp", "time_s", "per_sample_s", "cpu_per_sample_s", "run_per_sample_s",
           "run_cpu_per_sample_s", "first_sample_s", "rmse", "relmse", "flip"]
TIMED_RUNS = 4  # the variant's highest-spp renders whose steady times give its best-of-N time per sample


@dataclass
class Point:
    scene: str
    variant: str
    spp: int
    run_per_sample_s: float      # this render's steady wall time per sample (NaN at 1 spp: no steady samples)
    run_cpu_per_sample_s: float  # the same in CPU time of the raylab process
    first_sample_s: float
    rmse: float
    relmse: float
    flip: float
    per_sample_s: float = math.nan      # the variant's: best of its TIMED_RUNS highest-spp renders, wall
    cpu_per_sample_s: float = math.nan  # likewise in CPU time
    time_s: float = math.nan            # spp x per-sample time of --clock


@dataclass
class Settings:
    width: int
    height: int
    spps: list[int]
    reference_spp: int
    scenes: list[Scene]
    variants: list[Variant]
    out: Path
    docs: Path | None
    fresh_reference: bool
    clock: str
    timings: dict[str, float] = field(default_factory=dict)


def parse_args() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--out", type=Path, default=None,
                        help="output directory (default out/speed_vs_error, or out/speed_vs_error_quick)")
    parser.add_argument("--docs", type=Path, default=None, metavar="DIR",
                        help="also copy the plots here (e.g. docs/images/performance, to update the tracked "
                             "figures); by default they stay in --out")
    parser.add_argument("--no-docs", action="store_true", help="(the default) do not copy the plots anywhere")
    parser.add_argument("--quick", action="store_true",
                        help="smoke test: cornell_box only, 64x36, 1 and 16 spp, a 256-spp reference, no docs")
    parser.add_argument("--scenes", default=None, metavar="LIST",
                        help="comma-separated subset of " + ", ".join(s.name for s in SCENES))
    parser.add_argument("--variants", default=None, metavar="LIST",
                        help="comma-separated subset of " + ", ".join(v.name for v in VARIANTS))
    parser.add_argument("--width", type=int, default=256, help="image width (default 256)")
    parser.add_argument("--height", type=int, default=144, help="image height (default 144)")
    parser.add_argument("--max-spp", type=int, default=128, help="highest spp of the test renders, a power of "
                        "two (default 128: 1, 2, 4, ..., 128)")
    parser.add_argument("--reference-spp", type=int, default=2048, help="spp of the references (default 2048)")
    parser.add_argument("--fresh-reference", action="store_true", help="render the references again")
    parser.add_argument("--clock", choices=["cpu", "wall"], default="cpu",
                        help="time axis: CPU seconds of the raylab process (default; they vary far less on a "
                        "shared machine) or wall-clock seconds")
    add_raylab_option(parser)
    return parser.parse_args()


def pick(names: str | None, items: list, what: str) -> list:
    if names is None:
        return list(items)
    by_name = {item.name: item for item in items}
    unknown = [n for n in names.split(",") if n not in by_name]
    if unknown:
        raise ToolError(f"--{what}: unknown {', '.join(unknown)} (known: {', '.join(by_name)})")
    return [by_name[n] for n in names.split(",")]


def settings_from(args: argparse.Namespace) -> Settings:
    if args.quick:
        out = args.out or REPO / "out" / "speed_vs_error_quick"
        scenes = pick(args.scenes or "cornell_box", SCENES, "scenes")
        return Settings(64, 36, [1, 16], 256, scenes, pick(args.variants, VARIANTS, "variants"), out.resolve(),
                        None, args.fresh_reference, args.clock)
    if args.max_spp < 2 or args.max_spp & (args.max_spp - 1):
        raise ToolError(f"--max-spp: {args.max_spp} is not a power of two of at least 2")
    if args.reference_spp < 4 * args.max_spp:
        raise ToolError(f"--reference-spp: {args.reference_spp} should be at least 4x --max-spp ({args.max_spp}), "
                        f"or the reference's own noise dominates the last points")
    if args.width < 1 or args.height < 1:
        raise ToolError("--width, --height: must be positive")
    spps = [2 ** k for k in range(int(math.log2(args.max_spp)) + 1)]
    out = (args.out or REPO / "out" / "speed_vs_error").resolve()
    docs = None if args.no_docs or args.docs is None else args.docs.resolve()
    return Settings(args.width, args.height, spps, args.reference_spp, pick(args.scenes, SCENES, "scenes"),
                    pick(args.variants, VARIANTS, "variants"), out, docs, args.fresh_reference, args.clock)


def render(raylab: Path, scene: Scene, settings: Settings, options: tuple[str, ...], spp: int, seed: int,
           exr: Path) -> dict:
    """One `raylab render`; returns its --report."""
    report = exr.with_suffix(".json")
    command = ["render"] + ([str(REPO / scene.file)] if scene.file else [])
    command += ["--camera", scene.camera] if scene.camera else []
    command += ["--width", str(settings.width), "--height", str(settings.height), "--spp", str(spp),
                "--seed", str(seed), *options, "--out", str(exr), "--report", str(report)]
    run_raylab(raylab, command, f"rendering {scene.name}")
    return json.loads(report.read_text())


def scene_digest(scene: Scene) -> str:
    """A digest of the scene file (the built-in showcase is assets/scenes/showcase.gltf compiled in), so that a
    cached reference of an edited scene is not reused."""
    path = REPO / (scene.file or "assets/scenes/showcase.gltf")
    return hashlib.sha256(path.read_bytes()).hexdigest()[:12]


def reference(raylab: Path, scene: Scene, settings: Settings) -> np.ndarray:
    directory = settings.out / "reference"
    directory.mkdir(parents=True, exist_ok=True)
    camera = f"_{scene.camera}" if scene.camera else ""
    name = (f"{scene.name}{camera}_{scene_digest(scene)}_{settings.width}x{settings.height}_"
            f"{settings.reference_spp}spp")
    exr = directory / f"{name}.exr"
    if exr.exists() and exr.with_suffix(".json").exists() and not settings.fresh_reference:
        if raylab.stat().st_mtime > exr.stat().st_mtime:
            print(f"  note: {exr.name} is older than {raylab}; pass --fresh-reference if the renderer changed")
        print(f"  reference: cached {exr.relative_to(settings.out)}")
    else:
        start = time.monotonic()
        print(f"  reference: {settings.reference_spp} spp ...", flush=True)
        render(raylab, scene, settings, BASELINE, settings.reference_spp, REFERENCE_SEED, exr)
        settings.timings[f"reference {scene.name}"] = time.monotonic() - start
    return read_exr(exr)


def errors(test: np.ndarray, ref: np.ndarray) -> tuple[float, float, float]:
    difference = test - ref
    rmse = float(np.sqrt(np.mean(difference ** 2)))
    relmse = float(np.mean(difference ** 2 / (ref ** 2 + EPSILON)))
    if not (np.all(np.isfinite(test)) and np.all(np.isfinite(ref))):
        return rmse, relmse, math.nan
    # HDR-FLIP: the images are linear radiance with values above 1; the exposure range comes from the reference.
    _, flip, _ = flip_evaluator.evaluate(ref.astype(np.float32), np.maximum(test, 0.0).astype(np.float32), "HDR")
    return rmse, relmse, float(flip)


def measure_scene(raylab: Path, scene: Scene, settings: Settings) -> list[Point]:
    print(f"{scene.name}: {settings.width}x{settings.height}, spp {settings.spps}", flush=True)
    digest = scene_digest(scene)
    ref = reference(raylab, scene, settings)
    renders = settings.out / "renders"
    renders.mkdir(parents=True, exist_ok=True)
    points = []
    start = time.monotonic()
    # spp in the outer loop: the variants' renders of one spp run back to back, under the same machine load.
    for spp in settings.spps:
        for variant in settings.variants:
            exr = renders / f"{scene.name}_{variant.name}_{spp}spp.exr"
            report = render(raylab, scene, settings, variant.options, spp, TEST_SEED, exr)
            rmse, relmse, flip = errors(read_exr(exr), ref)
            steady = spp > 1
            points.append(Point(scene.name, variant.name, spp, report["per_sample_s"] if steady else math.nan,
                                report["cpu_per_sample_s"] if steady else math.nan, report["first_sample_s"],
                                rmse, relmse, flip))
            if spp != settings.spps[-1]:
                exr.unlink()
                exr.with_suffix(".json").unlink()
        print(f"  {spp:5d} spp: " + ", ".join(f"{p.variant} {p.rmse:.4g}" for p in points[-len(settings.variants):])
              + " (RMSE)", flush=True)
    settings.timings[f"variants {scene.name}"] = time.monotonic() - start
    if scene_digest(scene) != digest:
        raise ToolError(f"{scene.file or 'assets/scenes/showcase.gltf'} changed during the run: its renders do not "
                        f"match; run again")
    for variant in settings.variants:
        mine = [p for p in points if p.variant == variant.name]
        timed = [p for p in mine if p.spp > 1][-TIMED_RUNS:]
        # Best of N: the run least disturbed by the other work on the machine.
        wall = min(p.run_per_sample_s for p in timed)
        cpu = min(p.run_cpu_per_sample_s for p in timed)
        for p in mine:
            p.per_sample_s, p.cpu_per_sample_s = wall, cpu
            p.time_s = p.spp * (wall if settings.clock == "wall" else cpu)
    return points


def write_csv(points: list[Point], path: Path) -> None:
    with path.open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(COLUMNS)
        for p in points:
            writer.writerow([p.scene, p.variant, p.spp] + [f"{getattr(p, c):.6g}" if not math.isnan(getattr(p, c))
                                                           else "" for c in COLUMNS[3:]])


def error_floor(points: list[Point], metric: str) -> float:
    """Fits error = a / spp + c to the variant's MSE-like metric (RMSE squared, or relMSE) by least squares
    relative to each point, and returns c >= 0: the squared bias plus the reference's own noise."""
    spp = np.array([p.spp for p in points], dtype=float)
    value = np.array([getattr(p, metric) ** (2 if metric == "rmse" else 1) for p in points])
    if len(points) < 2 or not np.all(np.isfinite(value)) or np.any(value <= 0):
        return math.nan
    weights = 1.0 / value
    design = np.stack([1.0 / spp, np.ones_like(spp)], axis=1) * weights[:, None]
    (_, c), *_ = np.linalg.lstsq(design, value * weights, rcond=None)
    c = max(float(c), 0.0)
    return math.sqrt(c) if metric == "rmse" else c


def time_to_reach(points: list[Point], metric: str, target: float) -> float:
    """The time at which the variant's error first falls to `target`, interpolated in log-log; NaN if never."""
    if getattr(points[0], metric) <= target:
        return points[0].time_s
    for before, after in zip(points, points[1:]):
        a, b = getattr(before, metric), getattr(after, metric)
        if a > target >= b:
            s = (math.log(target) - math.log(a)) / (math.log(b) - math.log(a))
            return math.exp(math.log(before.time_s) + s * (math.log(after.time_s) - math.log(before.time_s)))
    return math.nan


def summary(points: list[Point], settings: Settings) -> str:
    target_spp = settings.spps[max(0, len(settings.spps) - 4)]
    lines = [f"Times per sample: best of the {TIMED_RUNS} highest-spp renders, wall clock and CPU time of the "
             f"process; speed: the baseline's time over the variant's. Errors at {settings.spps[-1]} spp. RMSE "
             f"floor: sqrt(c) of MSE = a/spp + c fitted to the points. Time to target ({settings.clock} clock): "
             f"when the variant's error falls to the baseline's at {target_spp} spp.", "",
             "| scene | variant | ms / sample | CPU ms / sample | speed (wall, CPU) | RMSE | relMSE | FLIP | "
             "RMSE floor | time to target RMSE | time to target FLIP |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for scene in settings.scenes:
        base = [p for p in points if p.scene == scene.name and p.variant == "baseline"]
        rmse_target = next((p.rmse for p in base if p.spp == target_spp), math.nan)
        flip_target = next((p.flip for p in base if p.spp == target_spp), math.nan)
        for variant in settings.variants:
            mine = [p for p in points if p.scene == scene.name and p.variant == variant.name]
            last = mine[-1]
            speed = (base[-1].per_sample_s / last.per_sample_s, base[-1].cpu_per_sample_s / last.cpu_per_sample_s)
            reach = [time_to_reach(mine, "rmse", rmse_target), time_to_reach(mine, "flip", flip_target)]
            shown = ["never" if math.isnan(t) else f"{t:.3g} s" for t in reach]
            lines.append(f"| {scene.name} | {variant.name} | {last.per_sample_s * 1e3:.1f} | "
                         f"{last.cpu_per_sample_s * 1e3:.1f} | {speed[0]:.2f}x, {speed[1]:.2f}x | "
                         f"{last.rmse:.4g} | {last.relmse:.3g} | {last.flip:.4f} | "
                         f"{error_floor(mine, 'rmse'):.3g} | {shown[0]} | {shown[1]} |")
    return "\n".join(lines) + "\n"


def plot_scene(points: list[Point], scene: Scene, settings: Settings, path: Path) -> None:
    figure, axes = plt.subplots(1, 3, figsize=(13.5, 4.0))
    metrics = [("rmse", "RMSE", 0.5), ("relmse", f"relMSE (ε = {EPSILON:g})", 1.0), ("flip", "HDR-FLIP (mean)", None)]
    by_name = {v.name: v for v in settings.variants}
    for ax, (metric, label, slope) in zip(axes, metrics):
        for variant in settings.variants:
            mine = [p for p in points if p.scene == scene.name and p.variant == variant.name]
            ax.plot([p.time_s for p in mine], [getattr(p, metric) for p in mine], by_name[variant.name].style,
                    ms=4, lw=1.3, label=f"{variant.name} ({mine[-1].time_s / mine[-1].spp * 1e3:.0f} ms/spp)")
        base = [p for p in points if p.scene == scene.name and p.variant == "baseline"]
        if slope is not None and base:
            t = np.array([base[0].time_s, base[-1].time_s])
            ax.plot(t, getattr(base[0], metric) * (t / t[0]) ** -slope, color="0.6", lw=0.8, ls=":",
                    label=f"∝ time^-{slope:g} (unbiased Monte Carlo)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        clock = "wall-clock" if settings.clock == "wall" else "CPU"
        ax.set_xlabel(f"render time ({clock} seconds, kernel compilation excluded)", fontsize=9)
        ax.set_title(label, fontsize=10)
        ax.grid(alpha=0.3, which="both")
        ax.tick_params(labelsize=8)
    axes[0].legend(fontsize=7.5)
    camera = f" (camera {scene.camera})" if scene.camera else ""
    spps = f"{settings.spps[0]}–{settings.spps[-1]} spp"
    figure.suptitle(f"{scene.name}{camera}: {settings.width}x{settings.height}, {spps}; reference: baseline at "
                    f"{settings.reference_spp} spp", fontsize=11)
    figure.tight_layout()
    figure.savefig(path, dpi=80)
    plt.close(figure)


def main() -> None:
    args = parse_args()
    raylab = check_raylab(args.raylab)
    settings = settings_from(args)
    settings.out.mkdir(parents=True, exist_ok=True)
    began = time.monotonic()
    load_before = os.getloadavg()
    points = []
    for scene in settings.scenes:
        points += measure_scene(raylab, scene, settings)
    write_csv(points, settings.out / "speed_vs_error.csv")
    table = summary(points, settings)
    (settings.out / "summary.md").write_text(table)
    plots = []
    for scene in settings.scenes:
        path = settings.out / f"speed_vs_error_{scene.name}.png"
        plot_scene(points, scene, settings, path)
        plots.append(path)
        if settings.docs is not None:
            settings.docs.mkdir(parents=True, exist_ok=True)
            shutil.copy2(path, settings.docs / path.name)
    settings.timings["total"] = time.monotonic() - began
    run = {"cores": os.cpu_count(), "load_average_before": load_before, "load_average_after": os.getloadavg(),
           "lp_num_threads": os.environ.get("LP_NUM_THREADS", ""), "seconds": settings.timings,
           "width": settings.width, "height": settings.height, "spps": settings.spps,
           "reference_spp": settings.reference_spp, "clock": settings.clock,
           "scene_digests": {scene.name: scene_digest(scene) for scene in settings.scenes}}
    (settings.out / "run.json").write_text(json.dumps(run, indent=2) + "\n")
    print("\n" + table)
    print(f"wrote {settings.out / 'speed_vs_error.csv'}, summary.md, run.json and {len(plots)} plots"
          + (f" (copied to {settings.docs})" if settings.docs else ""))
    print(f"took {settings.timings['total']:.0f} s; load average {load_before[0]:.2f} before, "
          f"{run['load_average_after'][0]:.2f} after, {os.cpu_count()} cores")


if __name__ == "__main__":
    run_main(main)
