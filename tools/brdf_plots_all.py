#!/usr/bin/env python3
"""Regenerates the BRDF figures of docs/brdfs.md: one tools/brdf_plot.py figure per model of the registry
(`raylab brdf models`; models of the test tree excluded) and a log-radius figure of a sharp lobe, into
docs/images/brdf/. Models without a hand-picked figure below get their defaults.

    .venv/bin/python tools/brdf_plots_all.py                 # about a minute
    .venv/bin/python tools/brdf_plots_all.py --only phong,glass --raylab build/debug/raylab
"""
from __future__ import annotations

import argparse
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from raylab_tools import REPO, ToolError, add_raylab_option, check_raylab, reads_file, registered_models, run_main

MAX_BYTES = 150 * 1024  # the repository's limit per image


@dataclass(frozen=True)
class Figure:
    name: str
    model: str
    params: str
    options: tuple[str, ...] = ()


ANISOTROPIC = ("--phi", "0,90")
# Hand-picked figures; every other registered model gets one of its defaults (figures()).
CHOSEN = [
    Figure("lambert", "lambert", "rho_d=1"),
    Figure("phong", "phong", "rho_d=0;rho_s=1;s=50"),
    Figure("blinnphong", "blinnphong", "rho_d=0;rho_s=1;s=50"),
    Figure("cooktorrance", "cooktorrance", "rho_d=0;rho_s=1;m=0.2;eta=1.5"),
    Figure("cooktorrance_sharp_log", "cooktorrance", "rho_d=0;rho_s=1;m=0.02;eta=10", ("--radius", "log")),
    Figure("ward", "ward", "rho_d=0;rho_s=1;alpha_x=0.1;alpha_y=0.4", ANISOTROPIC),
    Figure("ward_duer", "ward_duer", "rho_d=0;rho_s=1;alpha_x=0.1;alpha_y=0.4", ANISOTROPIC),
    Figure("ward_gmd", "ward_gmd", "rho_d=0;rho_s=1;alpha_x=0.1;alpha_y=0.4", ANISOTROPIC),
    Figure("ashikhmin_shirley", "ashikhmin_shirley", "Rd=0.5;Rs=0.5;nu=10;nv=1000", ANISOTROPIC),
    Figure("glass", "glass", "eta=1.5"),
    Figure("oren_nayar", "oren_nayar", "rho_d=1;sigma=0.5"),
    Figure("eon", "eon", "rho_d=1;r=1"),
    Figure("gltf_pbr", "gltf_pbr", "base_color=0.9/0.6/0.2;metallic=0;roughness=0.4"),
    Figure("ggx_conductor", "ggx_conductor", "metal=Au;alpha_x=0.1;alpha_y=0.4", ANISOTROPIC),
    Figure("ggx_dielectric", "ggx_dielectric", "alpha_x=0.15;alpha_y=0.15;eta=1.5"),
]


def parse_args() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--out", type=Path, default=REPO / "docs" / "images" / "brdf",
                        help="output directory (default docs/images/brdf)")
    parser.add_argument("--only", default=None, metavar="LIST",
                        help="comma-separated figure names (a model's name, or cooktorrance_sharp_log)")
    add_raylab_option(parser)
    return parser.parse_args()


def figures(raylab: Path) -> list[Figure]:
    chosen = {f.model for f in CHOSEN}
    extra = [Figure(m["name"], m["name"], "", ANISOTROPIC if any(p["role"].endswith("_x") for p in m["params"]) else ())
             for m in registered_models(raylab)
             # measured has no parameters to show: its figures are those of docs/fitting.md
             if m["name"] not in chosen and not m["glsl"].startswith("tests/") and not reads_file(m)]
    return CHOSEN + extra


def selected(all_figures: list[Figure], only: str | None) -> list[Figure]:
    if only is None:
        return all_figures
    by_name = {f.name: f for f in all_figures}
    unknown = [n for n in only.split(",") if n not in by_name]
    if unknown:
        raise ToolError(f"--only: unknown {', '.join(unknown)} (known: {', '.join(by_name)})")
    return [by_name[n] for n in only.split(",")]


def main() -> None:
    args = parse_args()
    raylab = check_raylab(args.raylab)
    script = Path(__file__).resolve().parent / "brdf_plot.py"
    for figure in selected(figures(raylab), args.only):
        out = args.out / f"{figure.name}.png"
        command = [sys.executable, str(script), "--model", figure.model, "--params", figure.params,
                   "--out", str(out), "--raylab", str(raylab), *figure.options]
        if subprocess.run(command).returncode != 0:
            raise ToolError(f"{figure.name}: brdf_plot.py failed: {' '.join(command)}")
        if out.stat().st_size > MAX_BYTES:
            raise ToolError(f"{out}: {out.stat().st_size // 1024} KB, over the {MAX_BYTES // 1024} KB limit of "
                            f"images in the repository (lower --dpi in brdf_plot.py)")


if __name__ == "__main__":
    run_main(main)
