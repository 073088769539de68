"""Does `raylab brdf fit` find the basin? Each model's default fit of each slice against the best of a 64-start
search of the same model: the plain multi-start (Levenberg-Marquardt from the defaults and 63 random points of the
parameter box, every pair) and raylab's own search with 64 starts, whichever ends lower (docs/fitting.md, "How a fit
finds its basin").

    .venv/bin/python tools/fit_basins.py --slices ../shared/measured/merl_slices --out out/basins.json
    .venv/bin/python tools/fit_basins.py --slices DIR --materials blue-acrylic,chrome --models cooktorrance
    .venv/bin/python tools/fit_basins.py --slices DIR --models ggx_conductor --reference search64 --sample 24

Prints, per model, on how many materials the default fit is within 1% (relative error) of the reference, and the
worst cases; --out keeps every figure as JSON. A job is one material x model on one process (one thread each).
With --out, each finished job is also appended to OUT.partial.jsonl, and a run that finds that file takes its jobs
as done: a check of all 100 materials (hours of CPU) survives being stopped and resumes where it was.
"""
from __future__ import annotations

import argparse
import json
import os
import random
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import measured_data as md  # noqa: E402
from measured_study import StudyError, check_slices, find_slices  # noqa: E402

TOLERANCE = 0.01


# The references a check may compare with: the plain 64-start multi-start (every pair; about 3 CPU-minutes per
# material for all models) and raylab's search with 64 starts (about a quarter of that).
REFERENCES = {"multistart": {"search": 0, "starts": 64}, "search64": {"starts": 64, "search": 1024}}


def job(slice_path: str, model: str, metric: str, references: list[str]) -> dict:
    raylab = md.import_raylab()
    out = {"model": model}
    for name, options in [("default", {})] + [(r, REFERENCES[r]) for r in references]:
        start = time.process_time()
        fit = raylab.brdf.fit(slice_path, models=[model], metric=metric, threads=1, **options)[0]
        out[name] = {"relative": fit["relative_error"], "params": fit["param_list"],
                     "seconds": time.process_time() - start}
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("--slices", type=Path, required=True, help="a folder of MERL phi_d = 90 .slice files")
    parser.add_argument("--materials", help="a,b,...: only these materials")
    parser.add_argument("--models", help="a,b,...: only these models (default: every model raylab fits)")
    parser.add_argument("--metric", choices=["cosine", "log"], default="log")
    parser.add_argument("--processes", type=int, default=os.cpu_count(), help="jobs at once (default: the cores)")
    parser.add_argument("--out", type=Path, help="also write every figure as JSON")
    parser.add_argument("--reference", choices=["both", "search64"], default="both",
                        help="both references (default), or raylab's 64-start search alone (a quarter of the time)")
    parser.add_argument("--sample", type=int, metavar="N",
                        help="only N materials, drawn at random with a fixed seed from those selected")
    args = parser.parse_args(argv)
    try:
        slices = find_slices(args.slices, args.materials.split(",") if args.materials else None)
        if args.sample is not None:
            if not 1 <= args.sample <= len(slices):
                raise StudyError(f"--sample: 1..{len(slices)}")
            chosen = sorted(random.Random(1).sample(sorted(slices), args.sample))
            slices = {name: slices[name] for name in chosen}
        check_slices(slices)
        raylab = md.import_raylab()
        known = list(raylab.brdf.fittable_models())
        models = args.models.split(",") if args.models else known
        if any(m not in known for m in models):
            raise StudyError(f"--models: not models raylab fits: {[m for m in models if m not in known]}")
        if not 1 <= args.processes <= 4 * (os.cpu_count() or 1):
            raise StudyError(f"--processes: 1..{4 * (os.cpu_count() or 1)}")
    except StudyError as error:
        print(f"fit_basins: {error}", file=sys.stderr)
        return 2
    references = list(REFERENCES) if args.reference == "both" else ["search64"]
    partial = args.out.with_name(args.out.name + ".partial.jsonl") if args.out else None
    results = []
    if partial is not None and partial.is_file():
        for line in partial.read_text().splitlines():
            record = json.loads(line)
            if record["material"] in slices and record["model"] in models and all(r in record for r in references):
                results.append(record)
        print(f"fit_basins: resuming: {len(results)} jobs done in {partial}", file=sys.stderr)
    done = {(r["material"], r["model"]) for r in results}
    started = time.monotonic()
    with ProcessPoolExecutor(args.processes) as pool:
        futures = {pool.submit(job, str(path), model, args.metric, references): material
                   for material, path in slices.items() for model in models if (material, model) not in done}
        for n, future in enumerate(as_completed(futures), 1):
            record = future.result()
            record["material"] = futures[future]
            reference = min(record[r]["relative"] for r in references)
            record["reference"] = reference
            record["within"] = record["default"]["relative"] <= reference * (1 + TOLERANCE) + 1e-12
            results.append(record)
            if partial is not None:
                partial.parent.mkdir(parents=True, exist_ok=True)
                with partial.open("a") as f:
                    f.write(json.dumps(record) + "\n")
            print(f"fit_basins: {n}/{len(futures)} {record['material']} {record['model']}: default "
                  f"{record['default']['relative']:.4f}, reference {reference:.4f}"
                  f"{'' if record['within'] else '  OUTSIDE 1%'}  ({time.monotonic() - started:.0f} s)",
                  file=sys.stderr)
    print(f"{'model':<20} {'within 1%':>12} {'worst ratio':>12}  worst material")
    for model in models:
        rs = [r for r in results if r["model"] == model]
        worst = max(rs, key=lambda r: r["default"]["relative"] / max(r["reference"], 1e-300))
        print(f"{model:<20} {sum(r['within'] for r in rs):>5}/{len(rs):<6} "
              f"{worst['default']['relative'] / max(worst['reference'], 1e-300):>12.4f}  {worst['material']}")
    if args.out:
        md_out = sorted(results, key=lambda r: (r["material"], r["model"]))
        args.out.parent.mkdir(parents=True, exist_ok=True)
        temporary = args.out.with_name(args.out.name + ".tmp")
        # One record a line: small enough to keep beside the docs (docs/results/), and diffs stay readable.
        temporary.write_text("[\n" + ",\n".join(json.dumps(r) for r in md_out) + "\n]\n")
        temporary.replace(args.out)
        partial.unlink(missing_ok=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
