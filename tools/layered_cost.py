#!/usr/bin/env python3
"""What openpbr's layers cost: assets/scenes/showcase_layered.gltf rendered as it is, and again with every openpbr
material replaced by gltf_pbr (glTF's own BRDF) of the same base colour, metalness and roughness, on the same
machine in one run. Prints the steady CPU seconds per sample of each (raylab's own report, kernel compilation
excluded and printed apart) and their ratio, as the row of docs/performance.md.

    .venv/bin/python tools/layered_cost.py                     # 640x360, 16 spp each: about 2 minutes on 2 cores
    .venv/bin/python tools/layered_cost.py --spp 4 --width 160 --height 90   # smoke test
"""
from __future__ import annotations

import argparse
import json
import os
import tempfile
from pathlib import Path

from raylab_tools import REPO, ToolError, add_raylab_option, check_raylab, run_main, run_raylab

SCENE = REPO / "assets" / "scenes" / "showcase_layered.gltf"


def gltf_pbr_overrides(scene: Path) -> list[str]:
    """--material NAME=gltf_pbr:... for every openpbr material of the scene."""
    overrides = []
    for material in json.loads(scene.read_text())["materials"]:
        raylab = material.get("extras", {}).get("raylab", {})
        if raylab.get("model") != "openpbr":
            continue
        colour = raylab.get("base_color", [0.8, 0.8, 0.8])
        values = {"base_color": "/".join(str(c) for c in colour), "metallic": raylab.get("base_metalness", 0.0),
                  "roughness": raylab.get("specular_roughness", 0.3)}
        overrides += ["--material", material["name"] + "=gltf_pbr:" + ",".join(f"{k}={v}" for k, v in values.items())]
    if not overrides:
        raise ToolError(f"{scene} has no openpbr material")
    return overrides


def render(raylab: Path, options: argparse.Namespace, extra: list[str], directory: Path, name: str) -> dict:
    report = directory / f"{name}.json"
    run_raylab(raylab, ["render", str(SCENE), "--width", str(options.width), "--height", str(options.height),
                        "--spp", str(options.spp), "--out", str(directory / f"{name}.exr"),
                        "--png", str(directory / f"{name}.png"), "--report", str(report), *extra],
               f"rendering {name}")
    return json.loads(report.read_text())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_raylab_option(parser)
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=360)
    parser.add_argument("--spp", type=int, default=16, help="samples per pixel of each render (default 16)")
    options = parser.parse_args()
    if options.spp < 2 or options.width < 1 or options.height < 1:
        raise ToolError("--spp must be 2 or more (the first sample compiles), --width and --height positive")
    raylab = check_raylab(options.raylab)
    with tempfile.TemporaryDirectory(prefix="layered_cost_") as temporary:
        directory = Path(temporary)
        layered = render(raylab, options, [], directory, "openpbr")
        plain = render(raylab, options, gltf_pbr_overrides(SCENE), directory, "gltf_pbr")
    print(f"machine: {os.cpu_count()} cores; {layered['driver']}; {options.width}x{options.height}, {options.spp} spp")
    print("| scene's materials | CPU s per sample | kernel compile s | kernel |")
    print("|---|---|---|---|")
    for label, report in (("openpbr (as committed)", layered), ("gltf_pbr (same colours)", plain)):
        print(f"| {label} | {report['cpu_per_sample_s']:.3f} | {report['first_sample_s']:.1f} | {report['kernel']} |")
    print(f"openpbr / gltf_pbr: {layered['cpu_per_sample_s'] / plain['cpu_per_sample_s']:.2f} x per sample")


if __name__ == "__main__":
    run_main(main)
