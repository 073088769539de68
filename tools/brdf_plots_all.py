#!/usr/bin/env python3
"""Regenerates the BRDF figures of docs/brdfs.md: one tools/brdf_plot.py figure per model of the registry
(`raylab brdf models`; models of the test tree excluded), as each model's GLSL header declares them (`// figure:`
lines, docs/extending.md), into docs/images/brdf/. A model without one gets a figure of its defaults.

    .venv/bin/python tools/brdf_plots_all.py                 # about a minute
    .venv/bin/python tools/brdf_plots_all.py --only phong,glass --raylab build/debug/raylab
"""
from __future__ import annotations

import argparse
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

from raylab_tools import (REPO, ToolError, add_raylab_option, check_raylab, model_notes, reads_file,
                          registered_models, run_main)

MAX_BYTES = 150 * 1024  # the repository's limit per image


@dataclass(frozen=True)
class Figure:
    name: str
    model: str
    params: str
    options: tuple[str, ...] = ()


ANISOTROPIC = ("--phi", "0,90")


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
    """Each model's `figure:` lines (its GLSL header), or one figure of its defaults, both planes for an anisotropic
    one."""
    result = []
    # measured has no parameters to show: its figures are those of docs/fitting.md
    for model in registered_models(raylab):
        if model["glsl"].startswith("tests/") or reads_file(model):
            continue
        declared = model_notes(model)["figures"]
        for figure in declared:
            params = ";".join(item.strip() for item in figure["params"].split(",") if item.strip())
            result.append(Figure(figure["name"], model["name"], params, tuple(figure["options"])))
        if not declared:
            anisotropic = any(p["role"].endswith("_x") for p in model["params"])
            result.append(Figure(model["name"], model["name"], "", ANISOTROPIC if anisotropic else ()))
    return result


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
