#!/usr/bin/env python3
"""Speed against error of the path integrator's sampling strategies: MIS, BSDF sampling alone and light
sampling alone, for each BRDF model under a real HDR environment.

Each model gets one scene: a sphere of that model (its GLSL header's `look:`) on a grey Lambert floor, lit
only by Blender's CC0 `sunrise` world (a sun of radiance 3.4e4 over a sky of about 0.5: five orders of
magnitude). raylab renders a reference with MIS at --reference-spp (seed 1000), then each strategy at 1, 2, 4,
..., --max-spp spp (seed 0). relMSE = mean((x - r)^2 / (r^2 + 0.01)) over pixels and R, G, B. An unbiased
estimator's relMSE falls as a / spp; a is fitted to the points of the two highest spp, and the time to relMSE
1e-3 is (a / 1e-3) spp times the strategy's steady CPU time per sample (raylab's --report, lavapipe's threads
included). Kernel compilation is excluded.

Writes OUT/sampling.csv, OUT/summary.md (the table of docs/performance.md), OUT/run.json (machine and load)
and OUT/sampling_study.png (with --docs DIR, copied there).

    .venv/bin/python tools/sampling_study.py            # about 3 minutes on 2 cores
    .venv/bin/python tools/sampling_study.py --quick    # smoke test: two models, 48x27
"""
from __future__ import annotations

import argparse
import csv
import json
import math
import os
import shutil
import sys
import time
import zipfile
from pathlib import Path

from raylab_tools import (REPO, ToolError, add_raylab_option, check_raylab, look_material, model_notes, reads_file,
                          registered_models, run_main, run_raylab, venv_hint)

sys.path.insert(0, str(REPO / "tools" / "scenes"))
import make_scenes  # noqa: E402

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from image_io import read_exr
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

ENVIRONMENT = REPO / "assets" / "scenes" / "environments" / "sunrise.exr"
EPSILON = 0.01
TARGET = 1e-3
STRATEGIES = [("mis", "o-"), ("bsdf", "s--"), ("light", "^-.")]
MEASURED_FILE = "measured_cooktorrance.binary"
# A model reading a neural BRDF renders a published network (optional data, ../shared/measured/nbrdf).
NETWORK_ARCHIVE = REPO.parent / "shared" / "measured" / "nbrdf" / "merl_nbrdf.zip"
NETWORK_FILE = "blue-acrylic.h5"
# name -> extras.raylab material: each model's `look:` line (raylab_tools.look_material), from parse_args.
MODELS_IN_USE: dict[str, dict] = {}

def write_scene(model: str, out: Path) -> Path:
    g = make_scenes.Gltf(f"sampling_{model}")
    floor = g.material("floor", {"model": "lambert", "rho_d": [0.5, 0.5, 0.5]})
    make_scenes.add_quad(g, "floor", [-6.0, 0.0, 6.0], [12.0, 0.0, 0.0], [0.0, 0.0, -12.0], floor)
    g.sphere(model, [0.0, 1.0, 0.0], 1.0, g.material(model, MODELS_IN_USE[model]))
    g.camera("camera", [0.0, 1.6, 4.2], [0.0, 0.8, 0.0], 40.0)
    g.environment("environments/" + ENVIRONMENT.name)
    return Path(g.write(str(out)))


def render(raylab: Path, scene: Path, args, strategy: str, spp: int, seed: int, exr: Path) -> dict:
    report = exr.with_suffix(".json")
    run_raylab(raylab, ["render", str(scene), "--sampling", strategy, "--width", str(args.width), "--height",
                        str(args.height), "--spp", str(spp), "--seed", str(seed), "--out", str(exr), "--no-png",
                        "--report", str(report)], f"rendering {scene.name} with --sampling {strategy}")
    figures = json.loads(report.read_text())
    if figures.get("dropped_samples", 0):
        raise ToolError(f"{scene.name}: {figures['dropped_samples']} NaN or Inf samples with --sampling {strategy}")
    return figures


def parse_args() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    add_raylab_option(parser)
    parser.add_argument("--models", default=None, help="comma-separated subset of the models (default: every model "
                        "of `raylab brdf models` with a density)")
    parser.add_argument("--width", type=int, default=128)
    parser.add_argument("--height", type=int, default=72)
    parser.add_argument("--max-spp", type=int, default=64, help="a power of two (default 64)")
    parser.add_argument("--reference-spp", type=int, default=2048, help="MIS reference (default 2048)")
    parser.add_argument("--quick", action="store_true", help="two models, 48x27, up to 8 spp, a 128-spp reference")
    parser.add_argument("--out", type=Path, default=None, help="default out/sampling_study")
    parser.add_argument("--docs", type=Path, default=None, metavar="DIR", help="also copy the plot here")
    args = parser.parse_args()
    if args.quick:
        args.models, args.width, args.height, args.max_spp, args.reference_spp = "lambert,cooktorrance", 48, 27, 8, 128
    registry = {m["name"]: m for m in registered_models(check_raylab(args.raylab)) if not m["delta_only"]}
    MODELS_IN_USE.update({name: look_material(model) for name, model in registry.items()})
    # A model reading a MERL file (measured) renders the Cook-Torrance look tabulated as a MERL file beside the scene;
    # one reading a network (nbrdf), the published blue acrylic.
    for name, model in registry.items():
        if reads_file(model):
            network = any(param["role"] == "network" for param in model["params"])
            MODELS_IN_USE[name] = {"model": name, "file": NETWORK_FILE if network else MEASURED_FILE}
    args.models = args.models or ",".join(registry)
    unknown = [m for m in args.models.split(",") if m not in registry]
    if unknown:
        parser.error(f"--models: unknown {', '.join(unknown)} (known: {', '.join(registry)})")
    if args.max_spp < 2 or args.max_spp & (args.max_spp - 1) or args.reference_spp < 4 * args.max_spp:
        parser.error("--max-spp must be a power of two >= 2 and --reference-spp at least 4x it")
    args.out = (args.out or REPO / "out" / ("sampling_study_quick" if args.quick else "sampling_study")).resolve()
    return args


def main() -> None:
    args = parse_args()
    raylab = check_raylab(args.raylab)
    if not ENVIRONMENT.exists():
        raise ToolError(f"{ENVIRONMENT} is missing: tools/setup.sh copies Blender's HDR worlds there")
    (args.out / "environments").mkdir(parents=True, exist_ok=True)
    shutil.copy2(ENVIRONMENT, args.out / "environments" / ENVIRONMENT.name)
    began, load_before = time.monotonic(), os.getloadavg()
    if any(MODELS_IN_USE[m].get("file") == NETWORK_FILE for m in args.models.split(",")):
        if not NETWORK_ARCHIVE.is_file():
            raise ToolError(f"{NETWORK_ARCHIVE} is absent: the networks are optional data (docs/measured.md)")
        with zipfile.ZipFile(NETWORK_ARCHIVE) as archive:
            for suffix in (".h5", ".json"):
                member = "merl_nbrdf/" + NETWORK_FILE.replace(".h5", suffix)
                (args.out / Path(member).name).write_bytes(archive.read(member))
    if any(MODELS_IN_USE[m].get("file") == MEASURED_FILE for m in args.models.split(",")):
        cooktorrance = next(m for m in registered_models(raylab) if m["name"] == "cooktorrance")
        params = model_notes(cooktorrance)["look"].replace(" ", "")
        run_raylab(raylab, ["brdf", "tabulate", f"cooktorrance:{params}", "--out", str(args.out / MEASURED_FILE)],
                   "raylab brdf tabulate")
    spps = [2 ** k for k in range(int(math.log2(args.max_spp)) + 1)]
    rows = []
    for model in args.models.split(","):
        scene = write_scene(model, args.out)
        reference_exr = args.out / f"{model}_reference.exr"
        render(raylab, scene, args, "mis", args.reference_spp, 1000, reference_exr)
        reference = read_exr(reference_exr)
        line = []
        for strategy, _ in STRATEGIES:
            points = []
            for spp in spps:
                exr = args.out / f"{model}_{strategy}_{spp}.exr"
                figures = render(raylab, scene, args, strategy, spp, 0, exr)
                relmse = float(np.mean((read_exr(exr) - reference) ** 2 / (reference ** 2 + EPSILON)))
                points.append((spp, relmse, figures["cpu_per_sample_s"]))
            cpu = min(p[2] for p in points if p[2] is not None)
            a = float(np.mean([p[0] * p[1] for p in points[-2:]]))  # relMSE = a / spp
            rows.append({"model": model, "strategy": strategy, "cpu_ms_per_sample": cpu * 1e3,
                         "relmse_at_max_spp": points[-1][1], "spp_to_target": a / TARGET,
                         "cpu_s_to_target": a / TARGET * cpu, "points": points})
            line.append(f"{strategy} {rows[-1]['cpu_s_to_target']:.3g} s")
        print(f"{model}: CPU time to relMSE 1e-3: " + ", ".join(line), flush=True)
    write_outputs(rows, args, spps, began, load_before)


def write_outputs(rows: list[dict], args, spps: list[int], began: float, load_before) -> None:
    with (args.out / "sampling.csv").open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["model", "strategy", "spp", "relmse", "cpu_per_sample_s"])
        for row in rows:
            for spp, relmse, cpu in row["points"]:
                cpu_text = "" if cpu is None else f"{cpu:.6g}"
                writer.writerow([row["model"], row["strategy"], spp, f"{relmse:.6g}", cpu_text])
    lines = ["| model | strategy | CPU ms / sample | spp to relMSE 1e-3 | CPU s to relMSE 1e-3 | vs MIS |",
             "|---|---|---|---|---|---|"]
    for row in rows:
        mis = next(r for r in rows if r["model"] == row["model"] and r["strategy"] == "mis")
        lines.append(f"| {row['model']} | {row['strategy']} | {row['cpu_ms_per_sample']:.1f} | "
                     f"{row['spp_to_target']:.3g} | {row['cpu_s_to_target']:.3g} | "
                     f"{row['cpu_s_to_target'] / mis['cpu_s_to_target']:.2f}x |")
    table = "\n".join(lines) + "\n"
    (args.out / "summary.md").write_text(table)
    models = list(dict.fromkeys(r["model"] for r in rows))
    columns = min(4, len(models))
    rows_of_plots = (len(models) + columns - 1) // columns
    figure, axes = plt.subplots(rows_of_plots, columns, figsize=(3.4 * columns, 2.9 * rows_of_plots), squeeze=False)
    for ax, model in zip(axes.flat, models):
        for strategy, style in STRATEGIES:
            row = next(r for r in rows if r["model"] == model and r["strategy"] == strategy)
            ax.plot([p[0] * row["cpu_ms_per_sample"] / 1e3 for p in row["points"]], [p[1] for p in row["points"]],
                    style, ms=3, lw=1.1, label=strategy)
        ax.axhline(TARGET, color="0.6", lw=0.8, ls=":")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(model, fontsize=9)
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3, which="both")
    for ax in axes.flat[len(models):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=7)
    figure.supxlabel("render time (CPU seconds, kernel compilation excluded)", fontsize=9)
    figure.supylabel(f"relMSE (ε = {EPSILON:g})", fontsize=9)
    figure.suptitle(f"Sampling strategies under the sunrise HDRI: {args.width}x{args.height}, {spps[0]}–{spps[-1]} "
                    f"spp, reference MIS at {args.reference_spp} spp", fontsize=10)
    figure.tight_layout()
    plot = args.out / "sampling_study.png"
    figure.savefig(plot, dpi=80)
    plt.close(figure)
    if args.docs:
        args.docs.mkdir(parents=True, exist_ok=True)
        shutil.copy2(plot, args.docs / plot.name)
    run = {"cores": os.cpu_count(), "load_average_before": load_before, "load_average_after": os.getloadavg(),
           "seconds": time.monotonic() - began, "width": args.width, "height": args.height, "spps": spps,
           "reference_spp": args.reference_spp}
    (args.out / "run.json").write_text(json.dumps(run, indent=2) + "\n")
    print("\n" + table)
    print(f"wrote {args.out}/sampling.csv, summary.md, run.json, sampling_study.png; took {run['seconds']:.0f} s, "
          f"load {load_before[0]:.2f} before, {run['load_average_after'][0]:.2f} after, {os.cpu_count()} cores")


if __name__ == "__main__":
    run_main(main)
