#!/usr/bin/env python3
"""Writes a published fit of a measured material as raylab material parameters: the `--material` value (MODEL:k=v,...)
or, with --gltf, the glTF `extras.raylab` block (docs/measured.md, "Published fits", has the mapping of each family).

    .venv/bin/python tools/published_fits.py ../shared/measured/fits_bbm/ngan_lafortune.fit blue-acrylic
    .venv/bin/python tools/published_fits.py ../shared/measured/fits_bbm/ngan_cooktorrance.fit chrome --gltf
    build/release/raylab render assets/scenes/minimal.gltf --material "red plastic=$(.venv/bin/python \\
        tools/published_fits.py ../shared/measured/fits_bbm/ngan_ward.fit blue-acrylic)"

FIT_FILE is one of ../shared/measured/fits_bbm/*.fit (bsdfbenchmark's Aggregate(Lambertian(...), Model(...)) lines)
or fits_djbrdf/*.csv (Löw's ABC and Bagher's SGD fits). A fit that raylab's models cannot express exactly is refused
with the reason (exit 1); a file or material that is not there is an error naming it (exit 2).
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import measured_data as md  # noqa: E402


def read_fit(path: Path, material: str) -> tuple[str, object, dict]:
    """(family, Lambert albedo, params) of `material` in a published fit file."""
    if path.suffix == ".fit":
        fits = {m: (f["family"], f["lambert"], f["params"]) for m, f in md.read_bbm_fits(path).items()}
    elif path.suffix == ".csv":
        rows = md.read_dj_csv(path)
        if "A_r" in next(iter(rows.values()), {}):
            fits = {m: ("LowMicrofacetFit", *md.low_abc_params(row)) for m, row in rows.items()}
        else:
            fits = {m: ("BagherSGD", *md.bagher_params(row)) for m, row in rows.items()}
    else:
        raise md.DataError(f"{path}: a published fit is a fits_bbm .fit file or a fits_djbrdf .csv file")
    if material not in fits:
        raise md.DataError(f"{path}: no fit of '{material}' (it has {len(fits)} materials, e.g. "
                           f"{', '.join(sorted(fits)[:5])})")
    return fits[material]


def number(value: float) -> str:
    return f"{value:.9g}"


def material_text(model: str, params: dict) -> str:
    """MODEL:k=v,... as `--material` and `raylab brdf` read it (RGB values r/g/b)."""
    return model + ":" + ",".join(f"{k}=" + ("/".join(number(x) for x in v) if isinstance(v, list) else number(v))
                                  for k, v in params.items())


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("fit_file", type=Path, metavar="FIT_FILE")
    parser.add_argument("material", metavar="MATERIAL", help="the measured material's name (blue-acrylic)")
    parser.add_argument("--gltf", action="store_true", help="print the glTF extras.raylab block instead")
    args = parser.parse_args(argv)
    family = "published"
    try:
        family, lambert, params = read_fit(args.fit_file, args.material)
        model, values = md.raylab_material(family, lambert, params)
    except (md.DataError, OSError) as error:
        print(f"published_fits.py: error: {error}", file=sys.stderr)
        return 2
    except KeyError as missing:
        # A column or parameter the family's formula needs is missing, or not a number ("sharpness = nan").
        print(f"published_fits.py: error: {args.fit_file}: the {family} fit of {args.material} has no number for "
              f"{missing}", file=sys.stderr)
        return 2
    except md.NotExpressible as reason:
        print(f"published_fits.py: {args.material} in {args.fit_file.name} ({family}) cannot be expressed exactly by "
              f"raylab's models: {reason}", file=sys.stderr)
        return 1
    if args.gltf:
        block = {"model": model}
        block.update({k: [float(x) for x in v] if isinstance(v, list) else float(v) for k, v in values.items()})
        print(json.dumps({"raylab": block}, indent=2))
    else:
        print(material_text(model, values))
    return 0


if __name__ == "__main__":
    sys.exit(main())
