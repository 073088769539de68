#!/usr/bin/env python3
"""The fitting study of docs/fitting.md: every analytic model fitted to a set of physically based targets.

Runs `raylab brdf fit TARGET --json` for each target (the named metals of ggx_conductor, rough glass's reflection,
gltf_pbr at two roughness and two metallic values, EON), then writes the table Ngan, Durand & Matusik publish
(EGSR 2005): each model's error on each material (relative to the target's own RMS, in %) and its rank, the mean
rank, and each model's CPU seconds; and the figure of one target, a MERL file tabulated from gold (tools/fit_figure.py).
The tables go into docs/fitting.md between its `<!-- study -->` markers.

    .venv/bin/python tools/fitting_study.py --docs docs
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

from raylab_tools import REPO, ToolError, add_raylab_option, check_raylab, run_main, run_raylab

TARGETS = [
    ("gold", "ggx_conductor:metal=Au,alpha_x=0.15,alpha_y=0.15"),
    ("silver", "ggx_conductor:metal=Ag,alpha_x=0.15,alpha_y=0.15"),
    ("copper", "ggx_conductor:metal=Cu,alpha_x=0.15,alpha_y=0.15"),
    ("aluminium", "ggx_conductor:metal=Al,alpha_x=0.15,alpha_y=0.15"),
    ("chromium", "ggx_conductor:metal=Cr,alpha_x=0.15,alpha_y=0.15"),
    ("rough glass (reflection)", "ggx_dielectric:alpha_x=0.1,alpha_y=0.1,eta=1.5"),
    ("plastic, rough 0.2", "gltf_pbr:base_color=0.6/0.1/0.1,metallic=0,roughness=0.2"),
    ("plastic, rough 0.5", "gltf_pbr:base_color=0.6/0.1/0.1,metallic=0,roughness=0.5"),
    ("metal, rough 0.2", "gltf_pbr:base_color=0.9/0.7/0.4,metallic=1,roughness=0.2"),
    ("metal, rough 0.5", "gltf_pbr:base_color=0.9/0.7/0.4,metallic=1,roughness=0.5"),
    ("EON r 0.5", "eon:rho_d=0.8/0.6/0.4,r=0.5"),
]
BEGIN, END = "<!-- study: begin (tools/fitting_study.py writes this) -->", "<!-- study: end -->"


def fit(raylab: Path, target: str, out: Path, starts: int) -> list[dict]:
    print(f"fitting {target} ...", flush=True)
    run_raylab(raylab, ["brdf", "fit", target, "--json", str(out), "--starts", str(starts)], "raylab brdf fit")
    return json.loads(out.read_text())


def tables(results: dict[str, list[dict]]) -> str:
    models = sorted({e["model"] for fits in results.values() for e in fits})
    ranks: dict[str, list[int]] = {m: [] for m in models}
    seconds: dict[str, list[float]] = {m: [] for m in models}
    header = "| material | " + " | ".join(f"`{m}`" for m in models) + " |"
    lines = [header, "|---" * (len(models) + 1) + "|"]
    for name, fits in results.items():
        by_model = {e["model"]: (i + 1, e) for i, e in enumerate(fits)}
        cells = []
        for m in models:
            rank, e = by_model[m]
            ranks[m].append(rank)
            seconds[m].append(e["seconds"])
            cell = f"{100 * e['relative_error']:.1f} ({rank})"
            cells.append(f"**{cell}**" if rank == 1 else cell)
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    lines.append("| mean rank | " + " | ".join(f"{sum(ranks[m]) / len(ranks[m]):.1f}" for m in models) + " |")
    lines.append("| CPU s per material | " + " | ".join(f"{sum(seconds[m]) / len(seconds[m]):.1f}" for m in models) + " |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    add_raylab_option(parser)
    parser.add_argument("--docs", type=Path, default=None, help="write docs/fitting.md's tables and figure here")
    parser.add_argument("--starts", type=int, default=4, help="starts per model (4)")
    args = parser.parse_args()
    raylab = check_raylab(args.raylab)
    results: dict[str, list[dict]] = {}
    with tempfile.TemporaryDirectory() as directory:
        work = Path(directory)
        for i, (name, target) in enumerate(TARGETS):
            results[name] = fit(raylab, target, work / f"fit{i}.json", args.starts)
        text = tables(results)
        print(text)
        if args.docs is not None:
            page = args.docs / "fitting.md"
            body = page.read_text()
            if BEGIN not in body or END not in body:
                raise ToolError(f"{page}: no {BEGIN} ... {END} markers")
            before, rest = body.split(BEGIN, 1)
            _, after = rest.split(END, 1)
            page.write_text(before + BEGIN + "\n" + text + "\n" + END + after)
            merl = work / "gold.binary"
            run_raylab(raylab, ["brdf", "tabulate", TARGETS[0][1], "--out", str(merl)], "raylab brdf tabulate")
            gold = fit(raylab, str(merl), work / "gold.json", args.starts)
            (args.docs / "images" / "fitting").mkdir(parents=True, exist_ok=True)
            (args.docs / "images" / "fitting" / "gold_measured.json").write_text(
                json.dumps([{**e, "target": "gold.binary"} for e in gold], indent=2) + "\n")
            subprocess.run([sys.executable, str(REPO / "tools" / "fit_figure.py"), str(work / "gold.json"), "--raylab",
                            str(raylab), "--spp", "128", "--out",
                            str(args.docs / "images" / "fitting" / "gold_measured.png")], check=True)
            print(f"wrote {page}")


if __name__ == "__main__":
    run_main(main)
