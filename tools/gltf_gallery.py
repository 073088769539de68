#!/usr/bin/env python3
"""The gallery of docs/gltf.md: every glTF 2.0 file of Debian's assimp-testmodels rendered by raylab, or the error
that raylab gives for it. Writes a contact sheet of the renders and replaces the table between the page's
`<!-- gallery:begin -->` and `<!-- gallery:end -->` markers with one row per file.

Every file is rendered under one environment image (--env; the Khronos Sample Viewer likewise shows every sample
under image-based light): with raylab's defaults a file whose only emitters are textured labels (ClearCoatTest)
gets no default light and shows its labels alone.

    .venv/bin/python tools/gltf_gallery.py
"""
from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

from raylab_tools import REPO, ToolError, add_raylab_option, check_raylab, run_main, venv_hint

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ModuleNotFoundError as error:
    print(venv_hint(error.name), file=sys.stderr)
    sys.exit(1)

ASSIMP = Path("/usr/share/assimp/models/glTF2")
BEGIN, END = "<!-- gallery:begin -->", "<!-- gallery:end -->"


def render(raylab: Path, scene: Path, png: Path, args: argparse.Namespace) -> str | None:
    """Renders `scene` to `png`; returns raylab's error (its last line) when it refuses the file."""
    with tempfile.TemporaryDirectory() as scratch:
        command = [str(raylab), "render", str(scene), "--width", str(args.width), "--height", str(args.height),
                   "--spp", str(args.spp), "--env", str(args.env), "--env-strength", str(args.env_strength),
                   "--integrator", "path", "--png", str(png), "--out", str(Path(scratch) / "image.exr")]
        result = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
    if result.returncode == 0:
        return None
    lines = [line for line in result.stderr.strip().splitlines() if line.strip()]
    if not lines:
        raise ToolError(f"raylab exited {result.returncode} with no message: {' '.join(command)}")
    # raylab's message starts "raylab render: FILE: "; the table names the file already.
    return lines[-1].split(f"{scene}: ", 1)[-1]


def contact_sheet(renders: list[tuple[str, Path]], path: Path, columns: int) -> None:
    rows = (len(renders) + columns - 1) // columns
    figure, axes = plt.subplots(rows, columns, figsize=(2.4 * columns, 2.1 * rows), squeeze=False)
    for axis in axes.flat:
        axis.axis("off")
    for axis, (name, png) in zip(axes.flat, renders):
        axis.imshow(plt.imread(png))
        axis.set_title(textwrap.fill(name, 40), fontsize=6)
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_raylab_option(parser)
    parser.add_argument("--assimp", type=Path, default=ASSIMP, help=f"the glTF2 folder (default: {ASSIMP})")
    parser.add_argument("--page", type=Path, default=REPO / "docs" / "gltf.md", help="the page whose table to replace")
    parser.add_argument("--sheet", type=Path, default=REPO / "docs" / "images" / "gltf" / "assimp_gallery.png",
                        help="the contact sheet to write")
    parser.add_argument("--width", type=int, default=240)
    parser.add_argument("--height", type=int, default=180)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--env", type=Path, default=REPO / "assets" / "scenes" / "environments" / "studio.exr",
                        help="the environment image every file is lit by (default: the committed studio)")
    parser.add_argument("--env-strength", type=float, default=2.0, help="multiplies the environment (default: 2)")
    parser.add_argument("--timeout", type=float, default=600.0, help="seconds allowed for one render")
    args = parser.parse_args()
    raylab = check_raylab(args.raylab)
    if not args.env.is_file():
        raise ToolError(f"--env {args.env}: no such file")
    if not args.assimp.is_dir():
        raise ToolError(f"{args.assimp} is missing: install assimp-testmodels (tools/setup.sh test)")
    page = args.page.read_text()
    if BEGIN not in page or END not in page:
        raise ToolError(f"{args.page} has no {BEGIN} ... {END} markers to put the table between")

    files = sorted(p for p in args.assimp.rglob("*") if p.suffix in (".gltf", ".glb") and p.is_file())
    rows, renders = [], []
    with tempfile.TemporaryDirectory() as pngs:
        for index, scene in enumerate(files):
            name = str(scene.relative_to(args.assimp))
            png = Path(pngs) / f"{index}.png"
            print(f"[{index + 1}/{len(files)}] {name}", file=sys.stderr, flush=True)
            error = render(raylab, scene, png, args)
            if error is None:
                renders.append((f"{len(renders) + 1}. {name.replace('/', '/ ')}", png))
                rows.append(f"| `{name}` | renders (sheet, {len(renders)}) |")
            else:
                rows.append(f"| `{name}` | refused: {error.replace('|', '/')} |")
        if not renders:
            raise ToolError("no file rendered")
        args.sheet.parent.mkdir(parents=True, exist_ok=True)
        contact_sheet(renders, args.sheet, columns=5)
    table = "\n".join(["| file | result |", "|---|---|", *rows])
    before, rest = page.split(BEGIN, 1)
    after = rest.split(END, 1)[1]
    staged = args.page.with_suffix(".md.tmp")
    staged.write_text(f"{before}{BEGIN}\n{table}\n{END}{after}")
    staged.replace(args.page)
    print(f"{len(renders)} of {len(files)} files render; wrote {args.sheet} and the table of {args.page}",
          file=sys.stderr)


if __name__ == "__main__":
    run_main(main)
