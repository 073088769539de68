#!/usr/bin/env python3
"""Denoised against raw, at equal CPU time: how soon each committed scene reaches a given error with and without
Open Image Denoise, and where denoising loses (docs/performance.md, "Denoising").

For each scene raylab renders a reference (4096 spp by default, cached in OUT/reference/), then, in N independent
runs (seeds 1..N), 1, 2, 4, ... spp with the first-hit albedo and normal; each image is compared with the
reference raw and denoised (raylab.denoise, the guides given). The error is the one a user sees: every channel
clamped at 1 in image and reference, then relMSE = mean((x - r)^2 / (r^2 + 0.01)), averaged over the runs.

Cost, in CPU seconds of this process (lavapipe's and OIDN's threads included; kernel compilation excluded): raw =
spp x the CPU time per sample of a renderer without the guides (what a user who does not denoise runs); denoised =
spp x that of the renderer with them + the denoise itself. "Time to 1e-2" interpolates each curve log-log.

Writes OUT/denoise_study.csv, OUT/summary.md (the table of docs/performance.md), OUT/run.json (machine, load),
OUT/denoise_<scene>.png (error against CPU time) and OUT/crops_<scene>.png (raw, denoised and reference side by
side at --crop-spp); with --docs DIR the plots and the summary are copied there (the small crops stay in OUT). --detail instead writes
OUT/detail_showcase_layered.png: regions of a 640x360 render, raw and denoised at 16 spp against 512 spp, where a
denoiser blurs BRDF detail.

    .venv/bin/python tools/denoise_study.py --docs docs/images/denoise   # about 25 min on 2 cores
    .venv/bin/python tools/denoise_study.py --detail --docs docs/images/denoise   # about 5 min
    .venv/bin/python tools/denoise_study.py --quick                      # smoke test: one scene, 32x18, seconds
"""
from __future__ import annotations

import argparse
import csv
import json
import os
import shutil
import sys
import time
from pathlib import Path

from raylab_tools import REPO, ToolError, run_main, save_figure, venv_hint

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    import raylab
    from image_error import REFERENCE_SEED, TARGET, clamped_relmse, cpu_seconds, reference, scene_path, time_to
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

SCENES = ("cornell_box_area", "cornell_box", "minimal", "showcase", "showcase_hdri", "showcase_modern",
          "showcase_layered")


def per_sample_cpu(renderer, spp: int) -> float:
    """The best of two renders' CPU seconds per sample (the kernel already compiled)."""
    return min(cpu_seconds(lambda: renderer.render(spp=spp, seed=99))[1] for _ in range(2)) / spp


def crop_sheet(name: str, raw: np.ndarray, denoised: np.ndarray, ref: np.ndarray, spp: int, path: Path) -> None:
    """raw | denoised | reference, tone-mapped as the PNG writer does, labelled."""
    figure, axes = plt.subplots(1, 3, figsize=(12, 2.6), dpi=110)
    for axis, image, title in zip(axes, (raw, denoised, ref),
                                  (f"raw, {spp} spp", f"denoised, {spp} spp", "reference")):
        axis.imshow(to_display(image), interpolation="nearest")
        axis.set_title(title, fontsize=9)
        axis.axis("off")
    figure.suptitle(name, fontsize=10)
    figure.tight_layout()
    save_figure(figure, path)
    plt.close(figure)


# Where denoising loses detail: regions of showcase_layered (fractions of the image: left, top, right, bottom).
DETAIL_SCENE = "showcase_layered"
DETAIL_REGIONS = (("dusty fuzz", (0.35, 0.33, 0.49, 0.53)), ("thin film over a dark dielectric", (0.51, 0.33, 0.63, 0.53)),
                  ("brushed metal", (0.52, 0.48, 0.70, 0.79)), ("floor and shadows", (0.00, 0.70, 0.30, 1.00)))


def to_display(image: np.ndarray) -> np.ndarray:
    shown = np.clip(image[..., :3], 0.0, 1.0)
    return np.where(shown <= 0.0031308, 12.92 * shown, 1.055 * np.power(shown, 1 / 2.4) - 0.055)


def detail_sheet(args, out: Path) -> None:
    """Raw and denoised at --detail-spp beside a raw render of --detail-reference-spp, region by region, at 640x360:
    what a denoiser blurs (fuzz's fine sparkle, thin-film colours, the brushed highlight's streaks) or keeps."""
    width, height = 640, 360
    scene = raylab.Scene.load(str(scene_path(DETAIL_SCENE)))
    renderer = raylab.Renderer(scene, width=width, height=height, aovs=True)
    print(f"detail: {DETAIL_SCENE} at {width}x{height}, {args.detail_spp} spp against {args.detail_reference_spp}",
          flush=True)
    raw = renderer.render(spp=args.detail_spp, seed=1)
    denoised = raylab.denoise(raw, *renderer.auxiliary(), quality=args.quality)
    ref = renderer.render(spp=args.detail_reference_spp, seed=REFERENCE_SEED)
    figure, axes = plt.subplots(len(DETAIL_REGIONS), 3, figsize=(9, 2.4 * len(DETAIL_REGIONS)), dpi=110)
    for row, (label, (left, top, right, bottom)) in enumerate(DETAIL_REGIONS):
        x0, x1, y0, y1 = int(left * width), int(right * width), int(top * height), int(bottom * height)
        for column, (image, title) in enumerate(((raw, f"raw, {args.detail_spp} spp"),
                                                 (denoised, f"denoised, {args.detail_spp} spp"),
                                                 (ref, f"raw, {args.detail_reference_spp} spp"))):
            axis = axes[row][column]
            axis.imshow(to_display(image[y0:y1, x0:x1]), interpolation="nearest")
            axis.set_title(f"{label}: {title}" if column == 0 else title, fontsize=8)
            axis.axis("off")
    figure.tight_layout()
    save_figure(figure, out / f"detail_{DETAIL_SCENE}.png")
    plt.close(figure)


def study_scene(name: str, args, out: Path, rows: list[dict]) -> dict:
    print(f"{name}:", flush=True)
    ref = reference(name, args.width, args.height, args.reference_spp, out)
    scene = raylab.Scene.load(str(scene_path(name)))
    plain = raylab.Renderer(scene, width=args.width, height=args.height)
    guided = raylab.Renderer(scene, width=args.width, height=args.height, aovs=True)
    plain.render(spp=1)  # the kernels compile at their first dispatch: not timed
    guided.render(spp=1)
    raylab.denoise(guided.image(), *guided.auxiliary(), quality=args.quality)  # OIDN's first run, not timed
    timing_spp = max(args.spp)
    raw_per_sample = per_sample_cpu(plain, timing_spp)
    guided_per_sample = per_sample_cpu(guided, timing_spp)
    summary = {"scene": name, "raw_cpu_per_sample": raw_per_sample, "guided_cpu_per_sample": guided_per_sample,
               "points": []}
    for spp in args.spp:
        raw_errors, denoised_errors, denoise_costs = [], [], []
        for run in range(args.runs):
            image = guided.render(spp=spp, seed=1 + run)
            albedo, normal = guided.auxiliary()
            denoised, cost = cpu_seconds(lambda: raylab.denoise(image, albedo, normal, quality=args.quality))
            raw_errors.append(clamped_relmse(image, ref))
            denoised_errors.append(clamped_relmse(denoised, ref))
            denoise_costs.append(cost)
            if run == 0 and spp == args.crop_spp:
                crop_sheet(name, image, denoised, ref, spp, out / f"crops_{name}.png")
        point = {"scene": name, "spp": spp,
                 "raw_relmse": float(np.mean(raw_errors)), "raw_relmse_sd": float(np.std(raw_errors)),
                 "denoised_relmse": float(np.mean(denoised_errors)),
                 "denoised_relmse_sd": float(np.std(denoised_errors)),
                 "raw_cpu_s": spp * raw_per_sample,
                 "denoise_cpu_s": float(np.mean(denoise_costs)),
                 "denoised_cpu_s": spp * guided_per_sample + float(np.mean(denoise_costs))}
        print(f"  {spp:5d} spp: raw {point['raw_relmse']:.4g} ({point['raw_cpu_s']:.3f} s), denoised "
              f"{point['denoised_relmse']:.4g} ({point['denoised_cpu_s']:.3f} s)", flush=True)
        rows.append(point)
        summary["points"].append(point)
    points = summary["points"]
    summary["raw_time_to_target"] = time_to(TARGET, [p["raw_cpu_s"] for p in points],
                                            [p["raw_relmse"] for p in points])
    summary["denoised_time_to_target"] = time_to(TARGET, [p["denoised_cpu_s"] for p in points],
                                                 [p["denoised_relmse"] for p in points])
    plot(name, points, out / f"denoise_{name}.png")
    return summary


def plot(name: str, points: list[dict], path: Path) -> None:
    figure, axis = plt.subplots(figsize=(5.2, 3.6), dpi=110)
    for key, label, marker in (("raw", "raw", "o"), ("denoised", "denoised (OIDN, albedo + normal)", "s")):
        costs = [p[f"{key}_cpu_s"] for p in points]
        errors = [p[f"{key}_relmse"] for p in points]
        axis.loglog(costs, errors, marker=marker, label=label)
        for p, c, e in zip(points, costs, errors):
            if p["spp"] in (1, 16, 256):
                axis.annotate(f"{p['spp']}", (c, e), fontsize=7, textcoords="offset points", xytext=(3, 3))
    axis.axhline(TARGET, color="grey", linestyle=":", linewidth=1)
    axis.set_xlabel("CPU seconds (spp x cost per sample, + the denoise)")
    axis.set_ylabel("relMSE, clamped at 1")
    axis.set_title(name, fontsize=10)
    axis.legend(fontsize=8)
    axis.grid(True, which="both", linewidth=0.3)
    figure.tight_layout()
    save_figure(figure, path)
    plt.close(figure)


def seconds(value: float | None) -> str:
    if value is None:
        return "not within the range"
    return f"at most {-value:.3g} s (below at 1 spp)" if value < 0 else f"{value:.3g} s"


def write_summary(summaries: list[dict], args, path: Path) -> None:
    lines = ["| scene | CPU ms / sample (raw, with guides) | denoise CPU s | relMSE at 1 spp (raw, denoised) | "
             "at 16 spp | at the most spp | CPU time to 1e-2 (raw, denoised) |",
             "|---|---|---|---|---|---|---|"]
    for s in summaries:
        points = {p["spp"]: p for p in s["points"]}
        first, most = points[min(points)], points[max(points)]
        mid = points.get(16, first)
        lines.append(
            f"| {s['scene']} | {1e3 * s['raw_cpu_per_sample']:.1f}, {1e3 * s['guided_cpu_per_sample']:.1f} | "
            f"{first['denoise_cpu_s']:.3f} | {first['raw_relmse']:.3g}, {first['denoised_relmse']:.3g} | "
            f"{mid['raw_relmse']:.3g}, {mid['denoised_relmse']:.3g} | "
            f"{most['raw_relmse']:.3g}, {most['denoised_relmse']:.3g} ({most['spp']} spp) | "
            f"{seconds(s['raw_time_to_target'])}, {seconds(s['denoised_time_to_target'])} |")
    header = (f"{args.width}x{args.height}, reference {args.reference_spp} spp, {args.runs} runs per point, OIDN "
              f"quality {args.quality}.\n\n")
    path.write_text(header + "\n".join(lines) + "\n")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scenes", nargs="+", default=list(SCENES), choices=SCENES)
    parser.add_argument("--width", type=int, default=160)
    parser.add_argument("--height", type=int, default=90)
    parser.add_argument("--spp", type=int, nargs="+", default=[1, 2, 4, 8, 16, 32, 64, 128, 256])
    parser.add_argument("--runs", type=int, default=8)
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--crop-spp", type=int, default=16, help="the spp of the raw | denoised | reference sheet")
    parser.add_argument("--quality", default=raylab.render_options["denoise_quality"]["default"],
                        choices=raylab.render_options["denoise_quality"]["values"])
    parser.add_argument("--detail", action="store_true",
                        help=f"only the detail sheet: {DETAIL_SCENE} at 640x360, raw and denoised against a reference")
    parser.add_argument("--detail-spp", type=int, default=16)
    parser.add_argument("--detail-reference-spp", type=int, default=512)
    parser.add_argument("--out", type=Path, default=REPO / "out" / "denoise_study")
    parser.add_argument("--docs", type=Path, help="copy the figures and summary.md here")
    parser.add_argument("--quick", action="store_true", help="one scene, 32x18, 1 and 4 spp, 2 runs: a smoke test")
    args = parser.parse_args()
    if args.quick:
        args.scenes, args.width, args.height, args.spp, args.runs = ["cornell_box_area"], 32, 18, [1, 4], 2
        args.reference_spp, args.crop_spp = 64, 4
    if args.runs < 1 or min(args.spp) < 1 or args.reference_spp < 1:
        raise ToolError("--runs, --spp and --reference-spp must be at least 1")
    args.spp = sorted(set(args.spp))
    (args.out / "reference").mkdir(parents=True, exist_ok=True)
    if args.detail:
        detail_sheet(args, args.out)
        if args.docs:
            args.docs.mkdir(parents=True, exist_ok=True)
            shutil.copy(args.out / f"detail_{DETAIL_SCENE}.png", args.docs / f"detail_{DETAIL_SCENE}.png")
        return
    load_before = os.getloadavg()
    started = time.time()
    rows: list[dict] = []
    summaries = [study_scene(name, args, args.out, rows) for name in args.scenes]
    with open(args.out / "denoise_study.csv", "w", newline="") as file:
        writer = csv.DictWriter(file, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    write_summary(summaries, args, args.out / "summary.md")
    run = {"cores": os.cpu_count(), "load_before": load_before, "load_after": os.getloadavg(),
           "seconds": time.time() - started, "raylab": raylab.__version__,
           "summaries": [{k: v for k, v in s.items() if k != "points"} for s in summaries]}
    (args.out / "run.json").write_text(json.dumps(run, indent=2) + "\n")
    print((args.out / "summary.md").read_text())
    if args.docs:
        args.docs.mkdir(parents=True, exist_ok=True)
        for name in args.scenes:
            shutil.copy(args.out / f"denoise_{name}.png", args.docs / f"denoise_{name}.png")
        shutil.copy(args.out / "summary.md", args.docs / "denoise_summary.md")


if __name__ == "__main__":
    run_main(main)
