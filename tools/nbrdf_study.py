"""The neural BRDFs against the measurements: each published network of a MERL material (Sztrajman et al. 2021,
../shared/measured/nbrdf) evaluated by raylab (model `nbrdf`) on its measured phi_d = 90 slice, in both metrics of
the measured study, beside raylab's best analytic fit of the same slice; and a contact sheet of all 159 networks as
spheres under one HDRI, each MERL material beside its best analytic fit (docs/measured.md, "Neural BRDFs").

    .venv/bin/python tools/nbrdf_study.py --docs docs                  # the table and the sheet in docs/measured.md
    .venv/bin/python tools/nbrdf_study.py --no-sheet                   # the errors only, printed

The networks are read from the published zip files, extracted (bounded, no path outside) into OUT/networks. The
analytic fits come from the measured study's OUT/fits.json (tools/measured_study.py); without it the table leaves
that column out. Optional data: without ../shared/measured the tool says so and exits 2.
"""
from __future__ import annotations

import argparse
import json
import shutil
import sys
import tempfile
import zipfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import measured_data as md  # noqa: E402

NBRDF = md.MEASURED / "nbrdf"
ARCHIVES = {"merl": "merl_nbrdf.zip", "rgl": "rgl-isotropic_nbrdf.zip", "nielsen": "nielsen_nbrdf.zip"}
MAX_MEMBER_BYTES = 1 << 20  # a network is 19 KB, its architecture 2 KB
MAX_MEMBERS = 1000
BEGIN, END = "<!-- nbrdf: begin (tools/nbrdf_study.py writes this) -->", "<!-- nbrdf: end -->"


def extract(archive: Path, into: Path) -> list[Path]:
    """The .h5 files of one published archive, each with its .json, extracted into `into` (sorted)."""
    into.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(archive) as z:
        members = [m for m in z.infolist() if not m.is_dir()]
        if len(members) > MAX_MEMBERS:
            raise SystemExit(f"{archive}: {len(members)} members, more than {MAX_MEMBERS}")
        for m in members:
            name = Path(m.filename).name
            if Path(name).suffix not in (".h5", ".json"):
                continue
            if m.file_size > MAX_MEMBER_BYTES:
                raise SystemExit(f"{archive}: {m.filename} is {m.file_size} bytes, more than {MAX_MEMBER_BYTES}")
            target = into / name  # the base name only: nothing lands outside `into`
            if not target.exists() or target.stat().st_size != m.file_size:
                with z.open(m) as source, open(target, "wb") as out:
                    shutil.copyfileobj(source, out)
    return sorted(p for p in into.glob("*.h5") if p.with_suffix(".json").exists())


def errors(raylab, networks: dict[str, Path], slices: dict[str, Path]) -> dict[str, dict]:
    """material -> slice_errors of its network, for the materials with both."""
    wi, wo = md.slice_directions("centre")
    out = {}
    for material in sorted(set(networks) & set(slices)):
        f = raylab.brdf.eval("nbrdf", {"file": str(networks[material])}, wi=wi.reshape(-1, 3), wo=wo.reshape(-1, 3),
                             backend="cpu").reshape(90, 90, 3)
        out[material] = md.slice_errors(f, md.read_slice(slices[material]))
    return out


def best_fits(fits_path: Path, key: str) -> dict[str, dict]:
    """material -> the measured study's best fit record in `key`, if the study has run."""
    if not fits_path.is_file():
        return {}
    best: dict[str, dict] = {}
    for record in json.loads(fits_path.read_text()):
        material = record["material"]
        if material not in best or record[key] < best[material][key]:
            best[material] = record
    return best


def table_section(errs: dict[str, dict], best: dict[str, dict]) -> str:
    med = lambda k: float(np.median([e[k] for e in errs.values()]))  # noqa: E731
    with_fit = [m for m in errs if m in best]
    lines = [f"The {len(errs)} MERL networks on their measured slices (the study's bins, weights and metrics): median "
             f"relative error {med('relative_cos'):.3f} (cosine) and {med('relative_log'):.3f} (log)."]
    if with_fit:
        closer = sum(errs[m]["relative_log"] < best[m]["relative_log"] for m in with_fit)
        ratio = np.median([errs[m]["relative_log"] / best[m]["relative_log"] for m in with_fit])
        lines.append(f"Against raylab's best analytic fit of the same slice (log metric, which the fits "
                     f"minimised), the network is closer on {closer} of {len(with_fit)} materials; the median "
                     f"ratio of the network's error to the fit's is {ratio:.2f}.")
    lines.append("")
    header = "| material | network, cosine | network, log |"
    lines.append(header + (" best analytic fit (log) | fit's model |" if with_fit else ""))
    lines.append("|---|---|---|" + ("---|---|" if with_fit else ""))
    for m in sorted(errs, key=lambda m: errs[m]["relative_log"]):
        row = f"| {m} | {errs[m]['relative_cos']:.3f} | {errs[m]['relative_log']:.3f} |"
        if with_fit:
            row += (f" {best[m]['relative_log']:.3f} | `{best[m]['model']}` |" if m in best else " — | — |")
        lines.append(row)
    return "\n".join(lines)


def contact_sheet(raylab, groups: dict[str, list[Path]], best: dict[str, dict], path: Path, size: int, spp: int):
    """Every network as a sphere under the sunrise world (path traced), labelled; a MERL material's best analytic
    fit beside it."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from measured_report import params_of, save_sheet, sphere_scene

    cells: list[tuple[str, str, dict]] = []  # title, model, parameters
    for group, files in groups.items():
        for h5 in files:
            cells.append((f"{h5.stem}\n{group} network", "nbrdf", {"file": str(h5)}))
            if group == "merl" and h5.stem in best:
                record = best[h5.stem]
                cells.append((f"{h5.stem}\nfit: {record['model']}", record["model"], params_of(record["params"])))
    transmittance = {name: [p["name"] for p in params if p.get("role") == "transmittance"]
                     for name, params in raylab.brdf.models().items()}
    with tempfile.TemporaryDirectory() as directory:
        work = Path(directory)
        scene = sphere_scene(raylab, work)
        columns = 14
        rows = (len(cells) + columns - 1) // columns
        figure, axes = plt.subplots(rows, columns, figsize=(1.0 * columns, 1.25 * rows), squeeze=False)
        for ax in axes.flat:
            ax.axis("off")
        for i, (ax, (title, model, params)) in enumerate(zip(axes.flat, cells)):
            for name in transmittance.get(model, []):
                params[name] = (0.0, 0.0, 0.0)  # a slice measures reflection only: render the fit opaque
            scene.set_material("sphere", model=model, **params)
            image = raylab.Renderer(scene, width=size, height=size).render(spp=spp)[..., :3]
            ax.imshow(np.clip(image, 0, 1) ** (1 / 2.2))
            ax.set_title(title, fontsize=4.5)
            print(f"nbrdf study: sheet {i + 1}/{len(cells)}", file=sys.stderr, flush=True)
        figure.tight_layout(pad=0.3, h_pad=0.5)
        save_sheet(figure, path, work)


def cost(raylab, networks: list[Path], spp: int = 32, repeats: int = 3) -> dict[str, float]:
    """CPU seconds per sample of a scene of eight spheres, each its own network, against the same scene with eight
    Cook-Torrance materials (path integrator, MIS, under the sunrise world, 160 x 90): the best of `repeats`
    renders after one that compiles the kernel."""
    import resource
    sys.path.insert(0, str(md.REPO / "tools" / "scenes"))
    import make_scenes

    def cpu():
        usage = resource.getrusage(resource.RUSAGE_SELF)
        return usage.ru_utime + usage.ru_stime

    out = {}
    with tempfile.TemporaryDirectory() as directory:
        work = Path(directory)
        g = make_scenes.Gltf("nbrdf_cost")
        shutil.copy(md.REPO / "assets" / "scenes" / "environments" / "sunrise.exr", work / "sunrise.exr")
        g.environment("sunrise.exr", 1.0)
        for i in range(8):
            g.sphere(f"s{i}", [(i % 4) * 1.1 - 1.65, (i // 4) * 1.1 - 0.55, 0.0], 0.5,
                     g.material(f"m{i}", {"model": "lambert"}))
        g.camera("camera", [0.0, 0.0, 4.2], [0.0, 0.0, 0.0], 40.0)
        scene = raylab.Scene.load(g.write(str(work)))
        for label in ("cooktorrance", "nbrdf"):
            for i in range(8):
                if label == "nbrdf":
                    scene.set_material(f"m{i}", model="nbrdf", file=str(networks[i % len(networks)]))
                else:
                    scene.set_material(f"m{i}", model="cooktorrance", rho_d=(0.2, 0.3, 0.5), rho_s=(0.8, 0.8, 0.8),
                                       m=0.1 + 0.05 * i)
            renderer = raylab.Renderer(scene, width=160, height=90, integrator="path")
            renderer.render(spp=1)  # compiles the kernel
            best = float("inf")
            for _ in range(repeats):
                start = cpu()
                renderer.render(spp=spp)
                best = min(best, (cpu() - start) / spp)
            out[label] = best
    out["ratio"] = out["nbrdf"] / out["cooktorrance"]
    return out


def write_docs(docs: Path, body: str):
    page = docs / "measured.md"
    text = page.read_text() if page.exists() else ""
    if BEGIN in text and END in text:
        head, rest = text.split(BEGIN, 1)
        text = head + BEGIN + "\n" + body + "\n" + END + rest.split(END, 1)[1]
    else:
        text = text.rstrip("\n") + f"\n\n## Neural BRDFs\n\n{BEGIN}\n{body}\n{END}\n"
    page.write_text(text)
    print(f"nbrdf study: wrote {page}", file=sys.stderr)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--networks", type=Path, default=NBRDF, help="the folder of the published zips")
    parser.add_argument("--slices", type=Path, default=md.MEASURED / "merl_slices", help="MERL phi_d = 90 slices")
    parser.add_argument("--out", type=Path, default=md.REPO / "out" / "nbrdf", help="where the networks are extracted")
    parser.add_argument("--fits", type=Path, default=md.REPO / "out" / "measured" / "fits.json",
                        help="the measured study's fits (optional)")
    parser.add_argument("--docs", type=Path, help="write DOCS/measured.md's section and its contact sheet")
    parser.add_argument("--no-sheet", action="store_true", help="leave out the contact sheet")
    parser.add_argument("--cost", action="store_true",
                        help="also time eight networks against eight Cook-Torrance materials (CPU s per sample)")
    parser.add_argument("--size", type=int, default=72, help="sheet sphere size in pixels")
    parser.add_argument("--spp", type=int, default=64, help="sheet samples per pixel")
    args = parser.parse_args()
    missing = [p for p in [args.networks / a for a in ARCHIVES.values()] + [args.slices] if not p.exists()]
    if missing:
        print(f"nbrdf study: {missing[0]} is absent: the networks and slices are optional data "
              "(../shared/measured; docs/measured.md says where to get them)", file=sys.stderr)
        return 2
    raylab = md.import_raylab()
    groups = {group: extract(args.networks / archive, args.out / "networks" / group)
              for group, archive in ARCHIVES.items()}
    print("nbrdf study: " + ", ".join(f"{len(v)} {k}" for k, v in groups.items()) + " networks", file=sys.stderr)
    slices = {p.stem: p for p in sorted(args.slices.glob("*.slice"))}
    errs = errors(raylab, {p.stem: p for p in groups["merl"]}, slices)
    best = best_fits(args.fits, "relative_log")
    body = table_section(errs, best)
    print(body)
    if args.cost:
        c = cost(raylab, groups["merl"][:8])
        print(f"nbrdf study: 8 networks {1e3 * c['nbrdf']:.1f} ms CPU per sample, 8 Cook-Torrance materials "
              f"{1e3 * c['cooktorrance']:.1f} ms: {c['ratio']:.2f}x", file=sys.stderr)
    if args.docs:
        sheet = "images/measured/nbrdf_sheet.jpg"
        if not args.no_sheet:
            contact_sheet(raylab, groups, best, args.docs / sheet, args.size, args.spp)
        intro = ("Sztrajman et al.'s networks ([brdfs.md](brdfs.md), `nbrdf`) encode the full 3-D measurement; a slice "
                 "holds one plane of it, so this is how far each encoding is from the measurement there. Regenerate "
                 "with `.venv/bin/python tools/nbrdf_study.py --docs docs` (after the measured study, whose fits it "
                 "reads).\n\n")
        figure = (f"\n\n![all 159 networks as spheres]({sheet})\n\nEvery published network (100 MERL, 51 RGL, 8 "
                  "Nielsen) as a sphere under Blender's sunrise world (path traced, "
                  f"{args.spp} spp), each MERL material followed by its best analytic fit from the study. A "
                  "material whose two spheres differ is one no analytic model of raylab captures.")
        write_docs(args.docs, intro + body + figure)
    return 0


if __name__ == "__main__":
    sys.exit(main())
