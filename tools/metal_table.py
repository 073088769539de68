#!/usr/bin/env python3
"""The named metals of ggx_conductor: eta and k in linear sRGB as Mitsuba 3's RGB variants load its `conductor`
plugin's measured spectra (its data/ior/<metal>.{eta,k}.spd, converted by Mitsuba's spectrum-to-sRGB
projection), printed as the `// preset:` lines of shaders/brdf/ggx_conductor.glsl.

    .venv/bin/python tools/metal_table.py
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from raylab_tools import point_mitsuba_at_libllvm, run_main, venv_hint

point_mitsuba_at_libllvm()

try:
    import mitsuba as mi
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

METALS = ["Ag", "Al", "Au", "Cr", "Cu"]


def main() -> None:
    argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                            formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__).parse_args()
    mi.set_variant("scalar_rgb")
    print(f"// Mitsuba {mi.__version__}, variant scalar_rgb")
    for metal in METALS:
        params = mi.traverse(mi.load_dict({"type": "conductor", "material": metal}))
        eta = "/".join(f"{c:.6g}" for c in params["eta.value"])
        k = "/".join(f"{c:.6g}" for c in params["k.value"])
        print(f"// preset: metal={metal} eta={eta} k={k}")


if __name__ == "__main__":
    run_main(main)
