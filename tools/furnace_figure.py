#!/usr/bin/env python3
"""The white furnace of ggx_conductor: single scattering against Kulla & Conty's multiple-scattering compensation.

Spheres of a white conductor (eta 0.01, k 20: F = 0.9999 at every angle) in a uniform white environment of
radiance 1, path traced (`raylab render --integrator path`). An energy-conserving surface there is invisible: every
pixel of it is 1. Each row is its own render, so that a sphere sees only spheres like itself (a darker neighbour
would dim the furnace). Top row: single scattering (`multiscatter=0`), which loses the light that bounces between
microfacets, more at higher roughness and at grazing (the dark rims); bottom row: `multiscatter=1`. Roughness
alpha = 0.05, 0.2, 0.4, 0.7, 1 from left to right. The printed table gives each sphere's mean radiance over the
inner 80% of its disk.

    .venv/bin/python tools/furnace_figure.py --out docs/images/furnace_ggx.png
"""
from __future__ import annotations

import argparse
import math
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
    from image_io import read_exr
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

ALPHAS = [0.05, 0.2, 0.4, 0.7, 1.0]
SPACING = 1.3
RADIUS = 0.5
DISTANCE = 12.0
YFOV_DEG = 8.0
WIDTH, HEIGHT = 800, 160  # each row's render


def scene(work: Path, multiscatter: int) -> Path:
    g = make_scenes.Gltf(f"furnace_ggx_{multiscatter}")
    g.background((1.0, 1.0, 1.0))
    for column, alpha in enumerate(ALPHAS):
        name = f"alpha {alpha:g} multiscatter {multiscatter}"
        material = {"model": "ggx_conductor", "alpha_x": alpha, "alpha_y": alpha, "eta": [0.01] * 3,
                    "k": [20.0] * 3, "rho_s": [1.0] * 3, "multiscatter": multiscatter}
        g.sphere(name, centre(column), RADIUS, g.material(name, material))
    g.camera("camera", [0.0, 0.0, DISTANCE], [0.0, 0.0, 0.0], YFOV_DEG)
    # A scene without lights gets raylab's headlight (docs/scenes.md); a dark one keeps the furnace's only light
    # its white background.
    g.point_light("dark", [0.0, 0.0, DISTANCE], 0.0)
    return Path(g.write(str(work)))


def centre(column: int) -> list[float]:
    return [(column - 2) * SPACING, 0.0, 0.0]


def pixels_per_unit() -> float:
    """At the spheres' plane."""
    return (HEIGHT / 2) / math.tan(math.radians(YFOV_DEG) / 2) / DISTANCE


def disk_mean(image: np.ndarray, column: int) -> float:
    """Mean of R, G, B over the inner 80% of the sphere's projected disk."""
    scale = pixels_per_unit()
    cx, cy = WIDTH / 2 + centre(column)[0] * scale, HEIGHT / 2
    yy, xx = np.mgrid[0:HEIGHT, 0:WIDTH]
    inside = (xx + 0.5 - cx) ** 2 + (yy + 0.5 - cy) ** 2 <= (0.8 * RADIUS * scale) ** 2
    if not inside.any():
        raise ToolError("a sphere's disk holds no pixel: the layout and the camera disagree")
    return float(image[inside][:, :3].mean())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    add_raylab_option(parser)
    parser.add_argument("--out", type=Path, default=REPO / "out" / "furnace_ggx.png", help="the PNG to write")
    parser.add_argument("--spp", type=int, default=256, help="samples per pixel (256)")
    args = parser.parse_args()
    if args.spp < 1:
        parser.error("--spp must be positive")
    raylab = check_raylab(args.raylab)
    images, pictures = [], []
    with tempfile.TemporaryDirectory() as directory:
        work = Path(directory)
        for multiscatter in (0, 1):
            exr = work / f"furnace_{multiscatter}.exr"
            png = work / f"furnace_{multiscatter}.png"
            run_raylab(raylab, ["render", str(scene(work, multiscatter)), "--integrator", "path", "--max-depth", "8",
                                "--width", str(WIDTH), "--height", str(HEIGHT), "--spp", str(args.spp), "--out",
                                str(exr), "--png", str(png)], "raylab render")
            images.append(read_exr(exr))
            pictures.append(plt.imread(png))
    print(f"{'alpha':>6} {'single scattering':>18} {'compensated':>12}")
    means = [(disk_mean(images[0], column), disk_mean(images[1], column)) for column in range(len(ALPHAS))]
    for alpha, (single, compensated) in zip(ALPHAS, means):
        print(f"{alpha:>6g} {single:>18.4f} {compensated:>12.4f}")
    label = 60  # pixels of caption under each row
    figure = plt.figure(figsize=(WIDTH / 100, (2 * (HEIGHT + label) + 30) / 100), dpi=100)
    total = 2 * (HEIGHT + label) + 30
    scale = pixels_per_unit()
    for row, (picture, name) in enumerate(zip(pictures, ("single scattering (multiscatter=0)",
                                                          "Kulla & Conty's compensation (multiscatter=1)"))):
        bottom = (total - 30 - (row + 1) * (HEIGHT + label) + label) / total
        ax = figure.add_axes([0.0, bottom, 1.0, HEIGHT / total])
        ax.imshow(picture)
        ax.axis("off")
        ax.text(WIDTH / 2, -8, name, ha="center", fontsize=9)
        for column, alpha in enumerate(ALPHAS):
            x = WIDTH / 2 + centre(column)[0] * scale
            ax.text(x, HEIGHT + 18, f"α = {alpha:g}: {means[column][row]:.3f}", ha="center", fontsize=8)
    save_figure(figure, args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    run_main(main)
