#!/usr/bin/env python3
"""How far apart two linear OpenEXR images are: the viewer's screenshot and its _compare.exr (the split view's
two sides), or any render against a reference. Prints, and with --json writes, the mean and the largest of the
per-pixel difference |A - B| (its largest channel, as the viewer's difference view shows it), the RMSE, the
relative MSE and HDR-FLIP (flip-evaluator, B as the reference).

    .venv/bin/python tools/image_diff.py out/view.exr out/view_compare.exr
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from raylab_tools import ToolError, run_main, venv_hint

try:
    import flip_evaluator
    import numpy as np
    from image_io import read_exr
except ModuleNotFoundError as error:
    print(venv_hint(error.name), file=sys.stderr)
    sys.exit(1)

EPSILON = 1e-2  # relative MSE's guard against dark reference pixels, as tools/speed_vs_error.py


def differences(a: np.ndarray, b: np.ndarray) -> dict:
    per_pixel = np.max(np.abs(a - b), axis=-1)
    difference = a - b
    _, flip, _ = flip_evaluator.evaluate(b.astype(np.float32), np.maximum(a, 0.0).astype(np.float32), "HDR")
    return {
        "mean_abs": float(np.mean(per_pixel)),
        "max_abs": float(np.max(per_pixel)),
        "rmse": float(np.sqrt(np.mean(difference ** 2))),
        "relmse": float(np.mean(difference ** 2 / (b ** 2 + EPSILON))),
        "flip": float(flip),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("a", type=Path, help="the image (the viewer's left side)")
    parser.add_argument("b", type=Path, help="the reference (the viewer's right side, FILE_compare.exr)")
    parser.add_argument("--json", type=Path, metavar="FILE", help="also write the figures here")
    args = parser.parse_args()
    for path in (args.a, args.b):
        if not path.is_file():
            raise ToolError(f"{path}: no such file")
    a, b = read_exr(args.a), read_exr(args.b)
    if a.shape != b.shape:
        raise ToolError(f"{args.a} is {a.shape[1]}x{a.shape[0]} but {args.b} is {b.shape[1]}x{b.shape[0]}")
    figures = differences(a, b)
    print("  ".join(f"{name} {value:.6g}" for name, value in figures.items()))
    if args.json:
        temporary = args.json.with_suffix(args.json.suffix + ".tmp")
        temporary.write_text(json.dumps(figures, indent=2) + "\n")
        temporary.replace(args.json)


if __name__ == "__main__":
    run_main(main)
