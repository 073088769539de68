#!/usr/bin/env python3
"""Beckmann against GGX at matched roughness: the figure of docs/brdfs.md ("Beckmann against GGX").

The two distributions meet in models that differ in nothing else that matters here: `cooktorrance` (Beckmann D with
slope m, Torrance-Sparrow's V-cavity G) and `gltf_pbr` with base colour 0 and metallic 0 (GGX D with alpha =
roughness^2, height-correlated Smith G), both with Schlick's Fresnel term of the same F0 (eta = ior = 1.5), so the
Fresnel term is matched exactly and alpha = m matches the roughness (both are the RMS slope's scale for small values).

Top: spheres of each pair under one point light (the slides' integrator: the highlight alone), Beckmann left and
GGX right of each pair, m = alpha = 0.05, 0.15, 0.3. Bottom: f in the plane of incidence for light at 30 degrees
(`raylab brdf eval`, the shaders' own numbers) on a log scale: GGX's long tail, orders of magnitude above Beckmann's
exp(-tan^2/m^2) away from the peak. The printed table gives the ratio GGX / Beckmann at 20, 40 and 60 degrees off the
mirror direction.

    .venv/bin/python tools/beckmann_vs_ggx.py --out docs/images/beckmann_vs_ggx.png
"""
from __future__ import annotations

import argparse
import csv
import math
import sys
import tempfile
from pathlib import Path

from raylab_tools import REPO, add_raylab_option, check_raylab, run_main, run_raylab, save_figure, venv_hint

sys.path.insert(0, str(REPO / "tools" / "scenes"))
import make_scenes  # noqa: E402

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

ROUGHNESS = [0.05, 0.15, 0.3]  # m = alpha
THETA_I = 30.0


RGB = {"rho_d", "rho_s", "base_color"}


def material(model: str, params: dict) -> tuple[str, str, dict]:
    """The model, its `raylab brdf eval` parameter list, and its extras.raylab object."""
    extras = {"model": model, **{k: [v] * 3 if k in RGB else v for k, v in params.items()}}
    return model, ";".join(f"{k}={v:.9g}" for k, v in params.items()), extras


def beckmann(m: float) -> tuple[str, str, dict]:
    return material("cooktorrance", {"rho_d": 0.0, "rho_s": 1.0, "m": m, "eta": 1.5})


def ggx(alpha: float) -> tuple[str, str, dict]:
    return material("gltf_pbr", {"base_color": 0.0, "metallic": 0.0, "roughness": math.sqrt(alpha), "ior": 1.5})


def in_plane(theta_deg: float) -> str:
    t = math.radians(theta_deg)
    return f"{math.sin(t):.9g} 0 {math.cos(t):.9g}"


def curves(raylab: Path, work: Path, angles: np.ndarray) -> dict[tuple[str, float], np.ndarray]:
    cases = work / "cases.csv"
    with cases.open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["id", "model", "params", "wi", "wo", "n", "t"])
        for m in ROUGHNESS:
            for name, make in (("beckmann", beckmann), ("ggx", ggx)):
                model, params, _ = make(m)
                for k, theta_o in enumerate(angles):
                    writer.writerow([f"{name}/{m}/{k}", model, params, in_plane(-THETA_I), in_plane(theta_o), "0 0 1",
                                     "1 0 0"])
    values = work / "values.csv"
    run_raylab(raylab, ["brdf", "eval", "--in", str(cases), "--out", str(values)], "raylab brdf eval")
    f: dict[str, float] = {}
    with values.open(newline="") as file:
        for row in csv.DictReader(file):
            f[row["id"]] = float(row["value"].split()[0])
    return {(name, m): np.array([f[f"{name}/{m}/{k}"] for k in range(len(angles))])
            for m in ROUGHNESS for name in ("beckmann", "ggx")}


def render_spheres(raylab: Path, work: Path, width: int, height: int, spp: int) -> np.ndarray:
    g = make_scenes.Gltf("beckmann_vs_ggx")
    g.background((0.02, 0.02, 0.025))
    floor = g.material("floor", {"model": "lambert", "rho_d": [0.05, 0.05, 0.05]})
    make_scenes.add_quad(g, "floor", [-10.0, 0.0, 6.0], [20.0, 0.0, 0.0], [0.0, 0.0, -16.0], floor)
    radius = 0.45
    for i, m in enumerate(ROUGHNESS):
        for j, make in enumerate((beckmann, ggx)):
            _, _, material = make(m)
            x = (i - 1) * 2.3 + (j - 0.5) * 1.0
            g.sphere(f"{material['model']} {m}", [x, radius, 0.0], radius,
                     g.material(f"{material['model']} {m}", material))
    g.point_light("key", [0.0, 6.0, 6.0], 600.0)
    g.camera("camera", [0.0, 1.0, 5.2], [0.0, 0.45, 0.0], 24.0)
    scene = Path(g.write(str(work)))
    png = work / "spheres.png"
    run_raylab(raylab, ["render", str(scene), "--integrator", "slides", "--width", str(width), "--height",
                        str(height), "--spp", str(spp), "--out", str(work / "spheres.exr"), "--png", str(png)],
               "raylab render")
    return plt.imread(png)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    add_raylab_option(parser)
    parser.add_argument("--out", type=Path, default=REPO / "out" / "beckmann_vs_ggx.png", help="the PNG to write")
    parser.add_argument("--spp", type=int, default=64, help="samples per pixel of the sphere render (64)")
    args = parser.parse_args()
    if args.spp < 1:
        parser.error("--spp must be positive")
    raylab = check_raylab(args.raylab)
    angles = np.linspace(-89.5, 89.5, 359)
    with tempfile.TemporaryDirectory() as directory:
        work = Path(directory)
        lobes = curves(raylab, work, angles)
        image = render_spheres(raylab, work, 960, 300, args.spp)

    figure = plt.figure(figsize=(9.6, 6.4), dpi=100)
    top = figure.add_axes([0.0, 0.53, 1.0, 0.47])
    top.imshow(image)
    top.axis("off")
    for i, m in enumerate(ROUGHNESS):
        top.text(480 + (i - 1) * 300, 285, f"m = α = {m:g}: Beckmann | GGX", color="white", ha="center", fontsize=9)
    colours = ["tab:blue", "tab:orange", "tab:green"]
    ax = figure.add_axes([0.08, 0.08, 0.88, 0.4])
    print(f"{'m = alpha':>10} {'GGX / Beckmann at 20, 40, 60 deg off the mirror direction':>60}")
    for colour, m in zip(colours, ROUGHNESS):
        b, g = lobes[("beckmann", m)], lobes[("ggx", m)]
        ax.semilogy(angles, b, color=colour, ls="--", lw=1.2, label=f"Beckmann m = {m:g}")
        ax.semilogy(angles, g, color=colour, lw=1.4, label=f"GGX α = {m:g}")
        ratios = []
        for off in (20.0, 40.0, 60.0):
            k = int(np.argmin(np.abs(angles - (THETA_I - off))))
            ratios.append(g[k] / b[k] if b[k] > 0 else math.inf)
        print(f"{m:>10g} " + "  ".join(f"{r:>12.3g}" for r in ratios))
    ax.set_xlim(-90, 90)
    ax.set_ylim(1e-6, 1e1)
    ax.axvline(THETA_I, color="0.6", lw=0.8)
    ax.set_xlabel(f"θo in the plane of incidence (degrees; light at {-THETA_I:g}°, mirror direction at {THETA_I:g}°)")
    ax.set_ylabel("f (1/sr)")
    ax.legend(fontsize=7.5, ncol=3, loc="lower center")
    ax.grid(True, which="major", color="0.9")
    save_figure(figure, args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    run_main(main)
