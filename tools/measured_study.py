"""The measured study: every analytic model of raylab fitted to every real MERL slice (../shared/measured), spread
over Dask with the farm's machinery, beside the published fits of the same materials (docs/measured.md).

    .venv/bin/python tools/measured_study.py --slices ../shared/measured/merl_slices --out out/measured
    .venv/bin/python tools/measured_study.py --slices DIR --materials blue-acrylic,gold-metallic-paint \\
        --models cooktorrance,ward --out out/m --workers 2
    .venv/bin/python tools/measured_study.py --slices DIR --out out/measured --docs docs     # also docs/measured.md
    .venv/bin/python tools/measured_study.py --slices DIR --out out/m --scheduler tcp://head:8786

One job fits one model to one slice on one worker (`raylab.brdf.fit`, one thread). Each finished job is stored at
once as OUT/jobs/MATERIAL.MODEL.METRIC.json (written beside, renamed into place) with what decided it (the slice's
SHA-256, the model, the metric and the fit's options), so a rerun skips every job already done and a worker killed
mid-job costs only that job, which Dask gives to another worker. OUT/fits.json gathers the records, one per
material x model, sorted.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import measured_data as md  # noqa: E402

# What decides a fit besides the slice and the model: changing any of these reruns the job.
FIT_OPTIONS = {"starts": None, "search": 256, "seed": 1}  # starts None: each model's own (raylab brdf fit --help)
# Bumped when the fitting itself changes, so that a rerun fits again rather than keeping older fits.
FIT_VERSION = 7
# The kinds of material the figures show, by name (docs/measured.md).
FIGURE_MATERIALS = ["chrome", "gold-metallic-paint", "red-fabric", "blue-acrylic", "cherry-235", "specular-red-phenolic"]


class StudyError(Exception):
    """A usage or input error: printed with exit 2."""


def sha256(path: Path) -> str:
    return hashlib.sha256(md.read_bounded(path, md.SLICE_BYTES + 1)).hexdigest()


def fit_job(slice_path: str, model: str, metric: str, options: dict) -> dict:
    """On a worker: one model fitted to one slice, with both metrics' errors of the result."""
    import raylab  # the worker's own module (its Vulkan device is never touched: fitting runs on the CPU)
    start = time.process_time()
    fit = raylab.brdf.fit(slice_path, models=[model], metric=metric, threads=1, **options)[0]
    record = {"model": model, "params": fit["param_list"], "metric": metric, "starts": fit["starts"],
              "warnings": fit["warnings"]}
    for name in ("cosine", "log"):
        error, relative = raylab.brdf.fit_error(slice_path, model, fit["params"], metric=name)
        short = "cos" if name == "cosine" else "log"
        record[f"error_{short}"], record[f"relative_{short}"] = error, relative
    record["seconds"] = time.process_time() - start
    record["pid"] = os.getpid()
    return record


def write_atomically(path: Path, text: str):
    path.parent.mkdir(parents=True, exist_ok=True)
    staged = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    staged.write_text(text)
    os.replace(staged, path)


def job_path(out: Path, material: str, model: str, metric: str) -> Path:
    return out / "jobs" / f"{material}.{model}.{metric}.json"


def stored(path: Path, description: dict) -> dict | None:
    """The stored record of a finished job, when its description is this one."""
    try:
        data = json.loads(md.read_bounded(path, 1 << 20))
    except (md.DataError, ValueError):
        return None
    return data.get("record") if isinstance(data, dict) and data.get("description") == description else None


def model_tables() -> dict[str, str]:
    """A digest of each model's parameter table (ranges, defaults, scales, roles; not the meanings): a stored fit is
    reused only while its model's table is the one it was fitted with, so a changed model is refitted alone."""
    import raylab
    return {name: hashlib.sha256(json.dumps([{k: v for k, v in p.items() if k != "meaning"} for p in params],
                                            sort_keys=True).encode()).hexdigest()[:16]
            for name, params in raylab.brdf.models().items()}


def run_study(slices: dict[str, Path], models: list[str], metric: str, out: Path, workers=None, scheduler=None,
              kill_one_worker_after: int | None = None) -> list[dict]:
    """Fits every model to every slice on a Dask cluster; returns the records (also OUT/fits.json). With
    kill_one_worker_after N, one worker process is killed once N jobs have finished (the test of resumption)."""
    from distributed import as_completed

    md.import_raylab()
    from raylab.farm.cluster import connect
    from raylab.farm.progress import Progress

    digests = {material: sha256(path) for material, path in slices.items()}
    tables = model_tables()
    jobs, records = [], {}
    for material, path in slices.items():
        for model in models:
            description = {"slice": digests[material], "model": model, "table": tables[model], "metric": metric,
                           "version": FIT_VERSION, **FIT_OPTIONS}
            done = stored(job_path(out, material, model, metric), description)
            if done is not None:
                records[(material, model)] = done
            else:
                jobs.append((material, model, description))
    if jobs:
        with connect(workers, scheduler) as client:
            progress = Progress("measured study", len(slices) * len(models), 0, len(records))
            progress.show()
            futures = {client.submit(fit_job, str(slices[material]), model, metric, FIT_OPTIONS, pure=False,
                                     key=f"fit-{material}-{model}-{metric}-{time.time_ns()}"): (material, model, d)
                       for material, model, d in jobs}
            finished = 0
            try:
                for future in as_completed(futures):
                    material, model, description = futures[future]
                    try:
                        record = future.result()
                    except Exception as error:
                        raise RuntimeError(f"{material} x {model}: {type(error).__name__}: {error}") from error
                    record["material"] = material
                    write_atomically(job_path(out, material, model, metric),
                                     json.dumps({"description": description, "record": record}, indent=1))
                    records[(material, model)] = record
                    finished += 1
                    progress.job_done()
                    if kill_one_worker_after is not None and finished == kill_one_worker_after:
                        pids = client.run(os.getpid)
                        victim = sorted(pids.values())[0]
                        print(f"measured study: killing worker process {victim}", file=sys.stderr)
                        os.kill(victim, 9)
            finally:
                client.cancel(list(futures))
    ordered = [dict(records[key], material=key[0]) for key in sorted(records)]
    for record in ordered:
        record.pop("pid", None)
    write_atomically(out / "fits.json", json.dumps(ordered, indent=1) + "\n")
    return ordered


def find_slices(directory: Path, materials: list[str] | None) -> dict[str, Path]:
    if not directory.is_dir():
        raise StudyError(f"--slices {directory}: not a directory (the MERL slices are in ../shared/measured/"
                         "merl_slices; docs/measured.md says where to get them)")
    found = {path.stem: path for path in sorted(directory.glob("*.slice")) if path.is_file()}
    if not found:
        raise StudyError(f"--slices {directory}: no .slice files")
    if materials is None:
        return found
    missing = [m for m in materials if m not in found]
    if missing:
        raise StudyError(f"--materials: {', '.join(missing)} not in {directory} (it has {len(found)} materials, "
                         f"e.g. {', '.join(list(found)[:4])})")
    return {m: found[m] for m in materials}


def check_slices(slices: dict[str, Path]):
    """Every slice read and checked before any work: a bad one is named with what is wrong."""
    for path in slices.values():
        try:
            md.read_slice(path)
        except md.DataError as error:
            raise StudyError(str(error)) from None


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("--slices", type=Path, required=True, help="a folder of MERL phi_d = 90 .slice files")
    parser.add_argument("--materials", help="a,b,...: only these materials (file names without .slice)")
    parser.add_argument("--models", help="a,b,...: only these models (default: every model raylab fits)")
    parser.add_argument("--metric", choices=["cosine", "log"], default="log",
                        help="the error each fit minimises (both are reported)")
    parser.add_argument("--out", type=Path, required=True, help="where the jobs and fits.json go")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, help="worker processes of a local cluster (default: one per core)")
    where.add_argument("--scheduler", help="a running Dask scheduler, e.g. tcp://head:8786")
    parser.add_argument("--docs", type=Path, help="also write DOCS/measured.md and its figures")
    parser.add_argument("--bin-check", action="store_true",
                        help="print how the published fits score with values at the bins' starts and centres")
    parser.add_argument("--kill-one-worker-after", type=int, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    try:
        materials = args.materials.split(",") if args.materials else None
        slices = find_slices(args.slices, materials)
        check_slices(slices)
        raylab = md.import_raylab()
        # Every model raylab can fit, those fitted only by name (openpbr) included: the study ranks them all.
        known = list(raylab.brdf.fittable_models(by_name=True))
        models = args.models.split(",") if args.models else known
        unknown = [m for m in models if m not in known]
        if unknown:
            raise StudyError(f"--models: {', '.join(unknown)} is not a model raylab fits "
                             f"({', '.join(known)})")
        if args.bin_check:
            bin_check(slices)
        records = run_study(slices, models, args.metric, args.out, args.workers, args.scheduler,
                            args.kill_one_worker_after)
        print(f"measured study: {len(records)} fits in {args.out / 'fits.json'}", file=sys.stderr)
        if args.docs:
            import measured_report
            measured_report.write(records, slices, args.metric, args.docs)
    except StudyError as error:
        print(f"measured_study: {error}", file=sys.stderr)
        return 2
    return 0


def bin_check(slices: dict[str, Path]):
    """How the published fits score with the slice's values placed at the bins' starts and at their centres."""
    published = md.published_fits()
    directions = {p: md.slice_directions(p) for p in ("start", "centre")}
    targets = {m: md.read_slice(p) for m, p in slices.items()}
    print("bin check: published fits, median relative error (cosine / log) and materials where the start is "
          "closer", file=sys.stderr)
    for label, fits in published.items():
        errors = {p: [] for p in directions}
        for material, target in targets.items():
            if material in fits:
                for p, (wi, wo) in directions.items():
                    errors[p].append(md.slice_errors(md.published_f(*fits[material], wi, wo), target, p))
        if not errors["start"]:
            continue
        line = [label, str(len(errors["start"]))]
        for key in ("relative_cos", "relative_log"):
            s = np.array([e[key] for e in errors["start"]])
            c = np.array([e[key] for e in errors["centre"]])
            line.append(f"{key}: start {np.median(s):.3f} centre {np.median(c):.3f}, start closer on "
                        f"{int((s < c).sum())}")
        print("  " + "; ".join(line), file=sys.stderr)


if __name__ == "__main__":
    sys.exit(main())
