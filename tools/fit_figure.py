#!/usr/bin/env python3
"""The figure of a fit: the target and each fitted model as spheres, with difference images and lobe plots.

Reads the JSON of `raylab brdf fit TARGET --json FIT.json` (its entries name the target). Top: a sphere on a
checker floor under the sunrise environment and a point light, path traced, for the target (first column) and each
fit, best first; below each fit, |fit - target| of the luminance, scaled x4 and false-coloured. Bottom: f cos(theta_i)
in the plane of incidence at several incidence angles (`raylab brdf eval`, the shaders' own numbers) for the target
(black) and each fit. A MERL target renders as the `measured` model; a material target as itself.

    .venv/bin/python tools/fit_figure.py out/fit.json --out docs/images/fitting/fit_gold.png
"""
from __future__ import annotations

import argparse
import csv
import json
import math
import shutil
import sys
import tempfile
from pathlib import Path

from raylab_tools import REPO, ToolError, add_raylab_option, check_raylab, run_main, run_raylab, save_figure, venv_hint

sys.path.insert(0, str(REPO / "tools" / "scenes"))
import make_scenes  # noqa: E402

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

INCIDENCE = [0.0, 30.0, 60.0, 75.0]


def target_material(target: str) -> tuple[str, str]:
    """(model, parameter list) of the target as `--material` and `raylab brdf eval` take it."""
    if target.endswith(".binary"):
        return "measured", f"file={Path(target).resolve()}"
    model, _, params = target.partition(":")
    return model, params


def fit_material(entry: dict) -> tuple[str, str]:
    def value(v):
        return "/".join(f"{c:.9g}" for c in v) if isinstance(v, list) else f"{v:.9g}"
    return entry["model"], ",".join(f"{k}={value(v)}" for k, v in entry["params"].items())


def render(raylab: Path, scene: Path, work: Path, name: str, material: tuple[str, str], size: int, spp: int):
    model, params = material
    spec = f"sphere={model}" + (f":{params}" if params else "")
    exr, png = work / f"{name}.exr", work / f"{name}.png"
    run_raylab(raylab, ["render", str(scene), "--material", spec, "--width", str(size), "--height", str(size),
                        "--spp", str(spp), "--out", str(exr), "--png", str(png)], f"raylab render ({name})")
    import image_io
    return image_io.read_exr(exr), plt.imread(png)


def lobes(raylab: Path, work: Path, materials: list[tuple[str, str]], angles: np.ndarray) -> np.ndarray:
    cases = work / "lobes.csv"
    with cases.open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["id", "model", "params", "wi", "wo", "n", "t"])
        for m, (model, params) in enumerate(materials):
            for a, theta_i in enumerate(INCIDENCE):
                ti = math.radians(theta_i)
                for k, theta_o in enumerate(angles):
                    to = math.radians(theta_o)
                    writer.writerow([f"{m}/{a}/{k}", model, params.replace(",", ";"),
                                     f"{-math.sin(ti):.9g} 0 {math.cos(ti):.9g}",
                                     f"{math.sin(to):.9g} 0 {math.cos(to):.9g}", "0 0 1", "1 0 0"])
    values = work / "lobe_values.csv"
    run_raylab(raylab, ["brdf", "eval", "--in", str(cases), "--out", str(values)], "raylab brdf eval")
    f = np.zeros((len(materials), len(INCIDENCE), len(angles)))
    with values.open(newline="") as file:
        for row in csv.DictReader(file):
            m, a, k = (int(x) for x in row["id"].split("/"))
            f[m, a, k] = float(np.mean([float(x) for x in row["value"].split()]))
    return f * np.cos(np.radians(np.array(INCIDENCE)))[None, :, None]


def scene_file(work: Path) -> Path:
    g = make_scenes.Gltf("fit_figure")
    shutil.copy(REPO / "assets" / "scenes" / "environments" / "sunrise.exr", work / "sunrise.exr")
    g.environment("sunrise.exr", 1.0)
    light = g.material("checker light", {"model": "lambert", "rho_d": [0.6, 0.6, 0.6]})
    dark = g.material("checker dark", {"model": "lambert", "rho_d": [0.15, 0.15, 0.15]})
    make_scenes.add_checker(g, "floor", (-3.0, 3.0), (-3.0, 3.0), 0.0, 0.5, (light, dark))
    g.sphere("sphere", [0.0, 0.6, 0.0], 0.6, g.material("sphere", {"model": "lambert"}))
    g.point_light("key", [2.0, 3.5, 2.5], 12.0)
    g.camera("camera", [0.0, 1.3, 2.6], [0.0, 0.55, 0.0], 34.0)
    return Path(g.write(str(work)))


# The difference maps' full scale, in linear luminance (the target's renders peak near 1).
DIFFERENCE_SCALE = 0.25


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    add_raylab_option(parser)
    parser.add_argument("fit", type=Path, help="the JSON of raylab brdf fit --json")
    parser.add_argument("--out", type=Path, default=REPO / "out" / "fit_figure.png", help="the PNG to write")
    parser.add_argument("--fits", type=int, default=4, help="how many fits to show, best first (4)")
    parser.add_argument("--size", type=int, default=200, help="pixels of each sphere image (200)")
    parser.add_argument("--spp", type=int, default=64, help="samples per pixel (64)")
    args = parser.parse_args()
    if args.fits < 1 or args.size < 16 or args.spp < 1:
        parser.error("--fits, --size and --spp must be positive (--size at least 16)")
    raylab = check_raylab(args.raylab)
    try:
        entries = json.loads(args.fit.read_text())[:args.fits]
    except (OSError, ValueError) as error:
        raise ToolError(f"{args.fit}: {error}")
    if not entries or "target" not in entries[0]:
        raise ToolError(f"{args.fit}: not the JSON of raylab brdf fit (a list of fits naming their target)")
    target = entries[0]["target"]
    materials = [target_material(target)] + [fit_material(e) for e in entries]
    labels = ["target"] + [f"{e['model']}\nerror {e['error']:.3g} ({100 * e['relative_error']:.1f}%)" for e in entries]
    angles = np.linspace(-89.0, 89.0, 179)
    with tempfile.TemporaryDirectory() as directory:
        work = Path(directory)
        scene = scene_file(work)
        images = [render(raylab, scene, work, f"m{i}", m, args.size, args.spp) for i, m in enumerate(materials)]
        curves = lobes(raylab, work, materials, angles)

    columns = len(materials)
    figure = plt.figure(figsize=(2.2 * columns, 7.6), dpi=100)
    luminance = [0.2126 * hdr[..., 0] + 0.7152 * hdr[..., 1] + 0.0722 * hdr[..., 2] for hdr, _ in images]
    for i, (_, png) in enumerate(images):
        ax = figure.add_axes([i / columns, 0.70, 1.0 / columns, 0.26])
        ax.imshow(png)
        ax.axis("off")
        ax.set_title(labels[i], fontsize=8)
        if i > 0:
            ax = figure.add_axes([i / columns, 0.44, 1.0 / columns, 0.24])
            difference = ax.imshow(np.abs(luminance[i] - luminance[0]), cmap="magma", vmin=0.0, vmax=DIFFERENCE_SCALE)
            ax.axis("off")
            ax.text(0.5, -0.05, "|fit - target|", transform=ax.transAxes, ha="center", va="top", fontsize=7)
    if columns > 1:
        # The difference maps' scale, in the target column's free space: linear luminance, clipped at its top.
        bar = figure.add_axes([0.3 / columns, 0.46, 0.12 / columns, 0.20])
        figure.colorbar(difference, cax=bar, extend="max")
        bar.tick_params(labelsize=6)
        bar.set_title("|Δ| luminance", fontsize=7)
    for a, theta_i in enumerate(INCIDENCE):
        ax = figure.add_axes([0.05 + a * 0.24, 0.06, 0.2, 0.3])
        for m in range(columns):
            ax.semilogy(angles, np.maximum(curves[m, a], 1e-5), color="black" if m == 0 else f"C{m - 1}",
                        lw=1.6 if m == 0 else 1.0, ls="-" if m == 0 else "--", label=labels[m].split("\n")[0])
        ax.set_title(f"light at {theta_i:g}°", fontsize=8)
        ax.set_xlabel("θo in the plane of incidence (°)", fontsize=7)
        ax.tick_params(labelsize=7)
        if a == 0:
            ax.set_ylabel("f cos θi (1/sr)", fontsize=7)
            ax.legend(fontsize=6)
    save_figure(figure, args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    run_main(main)
