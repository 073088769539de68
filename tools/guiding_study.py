#!/usr/bin/env python3
"""Path guiding against BSDF sampling, at equal CPU time: how soon each scene reaches a given error with --guiding
off, on and auto (docs/performance.md, "Path guiding").

For each scene raylab renders an unguided reference (16384 spp by default, cached in OUT/reference/), then, in N
independent runs (seeds 1..N), each mode progressively to 4, 8, 16, ... spp, the guide training from nothing in
every run. The error is the one a user sees (tools/image_error.py): channels clamped at 1, relMSE against the
reference, averaged over the runs. Cost: CPU seconds of this process (lavapipe's threads and the guide's updates
included, kernel compilation excluded), summed along each run. "Time to 1e-2" interpolates the mean curve log-log.

--survey instead runs off against auto on every committed scene that is not a sweep, without references: the
clamped relative variance over --survey-runs runs at --survey-spp, times the CPU per run, gives each mode's cost to
equal variance; auto may not be more than 5% dearer anywhere.

Writes OUT/guiding_study.csv, OUT/summary.md, OUT/run.json (machine, load) and OUT/guiding_<scene>.png; with
--survey OUT/survey.md. With --docs DIR the plots and summaries are copied there.

    .venv/bin/python tools/guiding_study.py --docs docs/images/guiding            # about 40 min on 2 cores
    .venv/bin/python tools/guiding_study.py --survey --docs docs/images/guiding   # about 10 min
    .venv/bin/python tools/guiding_study.py --quick                               # smoke test: seconds
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
    from image_error import EPSILON, TARGET, clamped_relmse, reference, scene_path, time_to
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

SCENES = ("showcase_modern", "glossy_room", "cornell_box_area")
SURVEY_SCENES = ("glossy_room", "cornell_box_area", "cornell_box", "minimal", "showcase", "showcase_hdri",
                 "showcase_modern", "showcase_layered")
MODES = raylab.render_options["guiding"]["values"]


def ladder(max_spp: int) -> list[int]:
    spps, spp = [], 4
    while spp <= max_spp:
        spps.append(spp)
        spp *= 2
    return spps


def study_scene(name: str, args, out: Path, rows: list[dict]) -> dict:
    print(f"{name}:", flush=True)
    ref = reference(name, args.width, args.height, args.reference_spp, out)
    scene = raylab.Scene.load(str(scene_path(name)))
    checkpoints = ladder(args.max_spp)
    summary = {"scene": name, "modes": {}}
    for mode in args.modes:
        renderer = raylab.Renderer(scene, width=args.width, height=args.height, guiding=mode)
        renderer.render(spp=1, seed=12345)  # the kernel compiles at its first dispatch: not timed
        errors = np.zeros((args.runs, len(checkpoints)))
        costs = np.zeros_like(errors)
        for run in range(args.runs):
            start = time.process_time()
            renderer.render(spp=1, seed=1 + run)  # a new image: the guide starts from nothing
            for i, spp in enumerate(checkpoints):
                renderer.add_samples(spp - renderer.samples)
                costs[run, i] = time.process_time() - start
                errors[run, i] = clamped_relmse(renderer.image(), ref)
        guide = renderer.report().get("guide", {})
        points = [{"scene": name, "mode": mode, "spp": spp, "relmse": float(errors[:, i].mean()),
                   "relmse_sd": float(errors[:, i].std()), "cpu_s": float(costs[:, i].mean())}
                  for i, spp in enumerate(checkpoints)]
        rows.extend(points)
        result = {"points": points, "guide": guide.get("text", "off"),
                  "time_to_target": time_to(TARGET, [p["cpu_s"] for p in points], [p["relmse"] for p in points]),
                  "spp_to_target": time_to(TARGET, [float(p["spp"]) for p in points], [p["relmse"] for p in points])}
        summary["modes"][mode] = result
        last = points[-1]
        print(f"  {mode:4s}: {last['spp']} spp relMSE {last['relmse']:.4g} in {last['cpu_s']:.1f} CPU s; "
              f"to {TARGET:g}: {seconds(result['time_to_target'])}; {result['guide']}", flush=True)
    plot(name, summary, out / f"guiding_{name}.png")
    return summary


def relative_variance(images: list[np.ndarray], mean: np.ndarray) -> float:
    stack = np.array([np.minimum(image[..., :3], 1.0) for image in images], dtype=np.float64)
    return float(np.mean(stack.var(axis=0, ddof=1) / (mean * mean + EPSILON)))


def survey(args, out: Path) -> list[dict]:
    results = []
    for name in SURVEY_SCENES:
        scene = raylab.Scene.load(str(scene_path(name)))
        renderers = {mode: raylab.Renderer(scene, width=args.width, height=args.height, integrator="path",
                                           guiding=mode) for mode in ("off", "auto")}
        images = {mode: [] for mode in renderers}
        cpu = {mode: [] for mode in renderers}
        for renderer in renderers.values():
            renderer.render(spp=1, seed=12345)  # compilation, not timed
        for run in range(args.survey_runs):  # the modes interleaved, so that a busy moment costs both alike
            for mode, renderer in renderers.items():
                start = time.process_time()
                images[mode].append(renderer.render(spp=args.survey_spp, seed=1 + run))
                cpu[mode].append(time.process_time() - start)
        guide = renderers["auto"].report().get("guide", {})
        mean = np.mean([np.minimum(image[..., :3], 1.0) for mode in images for image in images[mode]], axis=0)
        variance = {mode: relative_variance(images[mode], mean) for mode in images}
        # The least CPU of the runs: the render's own cost, without what other processes took from it.
        least = {mode: min(cpu[mode]) for mode in cpu}
        identical = all(np.array_equal(a, b) for a, b in zip(images["off"], images["auto"]))
        cost_ratio = (variance["auto"] * least["auto"]) / (variance["off"] * least["off"])
        results.append({"scene": name, "variance_off": variance["off"], "variance_auto": variance["auto"],
                        "cpu_off": least["off"], "cpu_auto": least["auto"], "cost_ratio": cost_ratio,
                        "identical": identical, "auto": guide.get("text", "")})
        print(f"{name}: cost to equal variance, auto / off = {cost_ratio:.3f}{' (images identical)' if identical else ''}"
              f" ({guide.get('text', '')})", flush=True)
    with open(out / "survey.md", "w") as file:
        file.write("| scene | relative variance off | auto | least CPU s per run off | auto | auto's cost to equal "
                   "variance | what auto decided (last run) |\n|---|---|---|---|---|---|---|\n")
        for r in results:
            decided = r["auto"].split("; trial: ")[-1] if "trial" in r["auto"] else r["auto"]
            same = " (the same images)" if r["identical"] else ""
            file.write(f"| {r['scene']} | {r['variance_off']:.4g} | {r['variance_auto']:.4g}{same} | {r['cpu_off']:.2f} | "
                       f"{r['cpu_auto']:.2f} | {r['cost_ratio']:.2f}x | {decided} |\n")
    return results


def plot(name: str, summary: dict, path: Path) -> None:
    figure, axis = plt.subplots(figsize=(5.2, 3.6), dpi=110)
    for mode, marker in zip(summary["modes"], "osd"):
        points = summary["modes"][mode]["points"]
        axis.loglog([p["cpu_s"] for p in points], [p["relmse"] for p in points], marker=marker, label=f"guiding {mode}")
    axis.axhline(TARGET, color="grey", linestyle=":", linewidth=1)
    axis.set_xlabel("CPU seconds (2 cores, lavapipe)")
    axis.set_ylabel("clamped relMSE")
    axis.set_title(name)
    axis.legend()
    figure.tight_layout()
    save_figure(figure, path)


def seconds(value: float | None) -> str:
    if value is None:
        return "not reached"
    return f"< {-value:.2f} s" if value < 0 else f"{value:.2f} s"


def write_summary(summaries: list[dict], args, path: Path) -> None:
    lines = [f"| scene | guiding | spp to {TARGET:g} | CPU s to {TARGET:g} | against off | relMSE at {args.max_spp} spp "
             f"| CPU s | speed-up at equal error | the guide |", "|---|---|---|---|---|---|---|---|---|"]
    for summary in summaries:
        off = summary["modes"].get("off", {})
        for mode, result in summary["modes"].items():
            t = result["time_to_target"]
            t_off = off.get("time_to_target")
            ratio = f"{t_off / t:.2f}x sooner" if t_off and t and t_off > 0 and t > 0 else "-"
            spp = result["spp_to_target"]
            spp_text = "not reached" if spp is None else (f"< {-spp:.0f}" if spp < 0 else f"{spp:.0f}")
            last = result["points"][-1]
            # Where the error falls as 1 / time, the time to any error scales with error x time at the last point.
            speedup = "-"
            if off:
                last_off = off["points"][-1]
                speedup = f"{last_off['relmse'] * last_off['cpu_s'] / (last['relmse'] * last['cpu_s']):.2f}x"
            guide = result["guide"].replace("path guiding ", "")
            lines.append(f"| {summary['scene']} | {mode} | {spp_text} | {seconds(t)} | {ratio} | "
                         f"{last['relmse']:.4g} | {last['cpu_s']:.1f} | {speedup} | {guide} |")
    path.write_text("\n".join(lines) + "\n")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scenes", nargs="+", default=list(SCENES), choices=SURVEY_SCENES)
    parser.add_argument("--modes", nargs="+", default=list(MODES), choices=MODES)
    parser.add_argument("--width", type=int, default=160)
    parser.add_argument("--height", type=int, default=90)
    parser.add_argument("--max-spp", type=int, default=1024)
    parser.add_argument("--runs", type=int, default=8)
    parser.add_argument("--reference-spp", type=int, default=16384)
    parser.add_argument("--survey", action="store_true", help="auto against off on every committed scene")
    parser.add_argument("--survey-spp", type=int, default=128)
    parser.add_argument("--survey-runs", type=int, default=4)
    parser.add_argument("--out", type=Path, default=REPO / "out" / "guiding")
    parser.add_argument("--docs", type=Path, help="copy the figures and summaries here")
    parser.add_argument("--quick", action="store_true", help="one scene, 32x18, to 8 spp, 2 runs: a smoke test")
    args = parser.parse_args()
    if args.quick:
        args.scenes, args.width, args.height, args.max_spp, args.runs, args.reference_spp = (
            ["glossy_room"], 32, 18, 8, 2, 32)
    if args.runs < 2 or args.max_spp < 4 or args.reference_spp < 1 or args.survey_runs < 2 or args.survey_spp < 1:
        raise ToolError("--runs and --survey-runs must be at least 2, --max-spp at least 4, the spp at least 1")
    (args.out / "reference").mkdir(parents=True, exist_ok=True)
    load_before = os.getloadavg()
    started = time.time()
    if args.survey:
        survey(args, args.out)
        outputs = ["survey.md"]
    else:
        rows: list[dict] = []
        summaries = [study_scene(name, args, args.out, rows) for name in args.scenes]
        with open(args.out / "guiding_study.csv", "w", newline="") as file:
            writer = csv.DictWriter(file, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
        write_summary(summaries, args, args.out / "summary.md")
        outputs = ["summary.md"] + [f"guiding_{name}.png" for name in args.scenes]
    run = {"cpus": os.cpu_count(), "load_before": load_before, "load_after": os.getloadavg(),
           "wall_s": time.time() - started, "width": args.width, "height": args.height, "runs": args.runs,
           "device": raylab.devices()[0]}
    (args.out / ("survey_run.json" if args.survey else "run.json")).write_text(json.dumps(run, indent=2, default=str))
    print((args.out / outputs[0]).read_text())
    if args.docs:
        args.docs.mkdir(parents=True, exist_ok=True)
        for name in outputs:
            shutil.copy(args.out / name, args.docs / name)


if __name__ == "__main__":
    run_main(main)
