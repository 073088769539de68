"""docs/measured.md from the measured study's records (tools/measured_study.py --docs DOCS): the models ranked on the
real MERL slices, raylab's fits beside the published fits of the same materials, the best model per material, and
the figures (slices beside their best fits; the best fits of every material as spheres)."""
from __future__ import annotations

import math
import shutil
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

import numpy as np

import measured_data as md

BEGIN, END = "<!-- study: begin (tools/measured_study.py writes this) -->", "<!-- study: end -->"
# Ngan et al. 2005's ranking on the same database (their Fig. 6): which families came out ahead.
NGAN_ORDER = "Ashikhmin-Shirley, Cook-Torrance and He best; Lafortune next; Ward and Blinn-Phong last"


def params_of(text: str) -> dict:
    """'a=1/2/3,b=4' as keyword arguments of Scene.set_material."""
    out = {}
    for item in filter(None, text.split(",")):
        key, _, value = item.partition("=")
        parts = [float(v) for v in value.split("/")]
        out[key] = tuple(parts) if len(parts) == 3 else parts[0]
    return out


def table(header: list[str], rows: list[list[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def by_material(records: list[dict]) -> dict[str, dict[str, dict]]:
    out: dict[str, dict[str, dict]] = defaultdict(dict)
    for r in records:
        out[r["material"]][r["model"]] = r
    return out


def model_table(records: list[dict], key: str) -> tuple[str, dict]:
    materials = by_material(records)
    ranks: dict[str, list[int]] = defaultdict(list)
    for fits in materials.values():
        for rank, (model, _) in enumerate(sorted(fits.items(), key=lambda kv: kv[1][key]), 1):
            ranks[model].append(rank)
    models = sorted(ranks, key=lambda m: np.mean(ranks[m]))
    rows = []
    for model in models:
        rs = [fits[model] for fits in materials.values() if model in fits]
        cos = np.array([r["relative_cos"] for r in rs])
        log = np.array([r["relative_log"] for r in rs])
        rows.append([f"`{model}`", f"{np.median(cos):.3f}", f"{cos.mean():.3f}", f"{np.median(log):.3f}",
                     f"{log.mean():.3f}", f"{np.mean(ranks[model]):.2f}", f"{np.mean([r['seconds'] for r in rs]):.2f}"])
    return table(["model", "median cosine", "mean cosine", "median log", "mean log", "mean rank", "CPU s"], rows), \
        {m: float(np.mean(ranks[m])) for m in models}


def published_errors(fits_by_label: dict, slices: dict[str, Path]) -> dict[str, dict[str, dict]]:
    """label -> material -> slice_errors of every published fit with a formula (measured_data.published_f)."""
    wi, wo = md.slice_directions("centre")
    out: dict[str, dict[str, dict]] = {}
    for label, fits in fits_by_label.items():
        out[label] = {}
        for material, path in slices.items():
            if material in fits:
                out[label][material] = md.slice_errors(md.published_f(*fits[material], wi, wo), md.read_slice(path))
    return out


def mapping_check(raylab, fits_by_label: dict, slices: dict[str, Path], published: dict) -> list[str]:
    """For the published fits raylab expresses exactly: raylab's own error of the mapped material against the
    formula's, the largest difference over the materials."""
    lines = []
    for label, mapping in md.MAPPINGS.items():
        worst, count, refused = 0.0, 0, defaultdict(int)
        for material, path in slices.items():
            if material not in fits_by_label[label]:
                continue
            family, lambert, params = fits_by_label[label][material]
            try:
                rmodel, rparams = md.raylab_material(family, lambert, params)
            except md.NotExpressible as reason:
                refused[str(reason).split(" = ")[0]] += 1
                continue
            text = ",".join(f"{k}=" + ("/".join(f"{x:.17g}" for x in v) if isinstance(v, list) else f"{v:.17g}")
                            for k, v in rparams.items())
            error, _ = raylab.brdf.fit_error(str(path), rmodel, text, metric="log")
            mine = published[label][material]["error_log"]
            worst = max(worst, abs(error - mine) / mine)
            count += 1
        note = "; ".join(f"{n} refused ({why})" for why, n in refused.items())
        lines.append(f"| {label} | {mapping} | {count} | "
                     f"{worst:.1e} | {note or '—'} |")
    return lines


def published_section(records: list[dict], fits_by_label: dict, published: dict, key: str) -> str:
    materials = by_material(records)
    short = key.split("_")[1]
    rows, exceptions = [], defaultdict(list)
    for label, errors in published.items():
        med = lambda k: np.median([e[k] for e in errors.values()])  # noqa: E731
        row = [label, str(len(errors)), f"{med('relative_cos'):.3f}", f"{med('relative_log'):.3f}"]
        model = label.split(" ", 1)[1] if label.startswith("Ngan ") else md.FAMILY_MODELS.get(label)
        if model is not None and all(model in materials[m] for m in errors):
            ours = {m: materials[m][model][key] for m in errors}
            theirs = {m: errors[m][key] for m in errors}
            wins = sum(ours[m] <= theirs[m] * (1 + 1e-9) for m in errors)
            row += [f"{np.median(list(ours.values())):.3f}", f"{wins}/{len(errors)} ({100 * wins / len(errors):.0f}%)"]
            for m in errors:
                if ours[m] > theirs[m] * (1 + 1e-9):
                    exceptions[(label, why_worse(fits_by_label[label][m]))].append((m, ours[m], theirs[m]))
        else:
            row += ["—", "—"]
        rows.append(row)
    text = table(["published fit", "materials", "median cosine", "median log",
                  f"raylab's fit of the family, median {short}", f"raylab no worse ({short})"], rows)
    if exceptions:
        text += "\n\nWhere raylab's fit is worse than the published parameters, by reason:\n"
        for (label, reason), cases in exceptions.items():
            worst = max(cases, key=lambda c: c[1] / c[2])
            names = ", ".join(c[0] for c in sorted(cases))
            text += (f"\n- {label}, {len(cases)} materials: {reason}. Worst: {worst[0]}, {worst[1]:.3f} against "
                     f"{worst[2]:.3f}. <details><summary>materials</summary>{names}</details>")
    return text


def why_worse(fit: tuple) -> str:
    family, lambert, params = fit
    try:
        md.raylab_material(family, lambert, params)
    except md.NotExpressible as reason:
        return f"the published fit is outside raylab's model ({reason})"
    return "the fit stopped in another basin"


def best_section(records: list[dict], published: dict, key: str) -> str:
    materials = by_material(records)
    ratios, wins, rows = [], 0, []
    best_published = ("Löw smooth", "Löw ABC", "Bagher SGD")
    for material, fits in sorted(materials.items()):
        best = min(fits.values(), key=lambda r: r[key])
        theirs = [(label, published[label][material][key]) for label in best_published if material in published[label]]
        if not theirs:
            continue
        label, value = min(theirs, key=lambda t: t[1])
        ratios.append(best[key] / value)
        wins += best[key] <= value
        rows.append([material, f"`{best['model']}`", f"{best[key]:.3f}", label, f"{value:.3f}",
                     f"{best[key] / value:.2f}"])
    head = (f"raylab's best model beats the best of Löw's smooth-surface and ABC fits and Bagher's SGD fits on {wins} of "
            f"{len(ratios)} "
            f"materials; its error is {np.median(ratios):.2f}x theirs at the median (best {min(ratios):.2f}x, worst "
            f"{max(ratios):.2f}x).\n\n")
    return head + "<details><summary>Every material</summary>\n\n" + table(
        ["material", "raylab's best", short_name(key), "best published", short_name(key), "ratio"], rows) + \
        "\n\n</details>"


def short_name(key: str) -> str:
    return "relative " + key.split("_")[1]


def slice_figure(raylab, records: list[dict], slices: dict[str, Path], key: str, path: Path):
    """Per material a row: the measured slice, then each of its three best fits and log10(fit / measured) beside it."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm, TwoSlopeNorm

    from measured_study import FIGURE_MATERIALS

    materials = by_material(records)
    chosen = [m for m in FIGURE_MATERIALS if m in slices and m in materials]
    wi, wo = md.slice_directions("centre")
    mask = md.kept("centre")
    figure, axes = plt.subplots(len(chosen), 7, figsize=(17, 2.5 * len(chosen)), squeeze=False,
                                gridspec_kw={"wspace": 0.7, "hspace": 0.45})
    # The slice's own square-root theta_h axis, labelled in degrees.
    ticks = [0, 2, 10, 30, 60, 90]
    columns = [math.sqrt(t / 90.0) * 90.0 for t in ticks]
    extent = (0, 90, 90, 0)
    for row, material in enumerate(chosen):
        target = md.read_slice(slices[material]).mean(-1)
        fits = sorted(materials[material].values(), key=lambda r: r[key])[:3]
        lo, hi = max(target[target > 0].min(), 1e-6 * target.max()), target.max()
        panels = [(f"{material}: measured", np.where(mask, target, np.nan), LogNorm(lo, hi), "magma")]
        for fit in fits:
            f = raylab.brdf.eval(fit["model"], fit["params"], wi=wi.reshape(-1, 3), wo=wo.reshape(-1, 3),
                                 backend="cpu").reshape(90, 90, 3).mean(-1)
            panels.append((f"{fit['model']} ({fit[key]:.3f})", np.where(mask, np.clip(f, lo, None), np.nan),
                           LogNorm(lo, hi), "magma"))
            ratio = np.log10(np.maximum(f, 1e-6) / np.maximum(target, 1e-6))
            panels.append(("log10(fit / measured)", np.where(mask, ratio, np.nan), TwoSlopeNorm(0.0, -1.0, 1.0),
                           "coolwarm"))
        for column, (title, image, norm, cmap) in enumerate(panels):
            ax = axes[row, column]
            shown = ax.imshow(image, norm=norm, extent=extent, cmap=cmap)
            ax.set_title(title, fontsize=8)
            bar = figure.colorbar(shown, ax=ax, fraction=0.046, pad=0.03)
            bar.ax.tick_params(labelsize=6)
            ax.set_xticks(columns, [str(t) for t in ticks], fontsize=6)
            ax.tick_params(labelsize=6)
            ax.set_xlabel("theta_h (deg)", fontsize=6)
            ax.set_ylabel("theta_d (deg)", fontsize=6)
    path.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(path, dpi=72, bbox_inches="tight")
    plt.close(figure)


def sphere_scene(raylab, work: Path):
    """The contact sheets' scene, written into `work`: one sphere (material "sphere") under Blender's sunrise world."""
    sys.path.insert(0, str(md.REPO / "tools" / "scenes"))
    import make_scenes

    g = make_scenes.Gltf("measured_sheet")
    shutil.copy(md.REPO / "assets" / "scenes" / "environments" / "sunrise.exr", work / "sunrise.exr")
    g.environment("sunrise.exr", 1.0)
    g.sphere("sphere", [0.0, 0.0, 0.0], 1.0, g.material("sphere", {"model": "lambert"}))
    g.camera("camera", [0.0, 0.4, 3.4], [0.0, 0.0, 0.0], 36.0)
    return raylab.Scene.load(g.write(str(work)))


def save_sheet(figure, path: Path, work: Path):
    """A contact sheet as a JPEG: a hundred path-traced spheres are a photograph; a 256-colour PNG bands their
    gradients, a full one is 2 MB."""
    import matplotlib.pyplot as plt
    from PIL import Image

    path.parent.mkdir(parents=True, exist_ok=True)
    staged = work / "sheet.png"
    figure.savefig(staged, dpi=90)
    plt.close(figure)
    Image.open(staged).convert("RGB").save(path, quality=88, optimize=True)


def contact_sheet(raylab, records: list[dict], key: str, path: Path, size: int = 80, spp: int = 128):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    materials = by_material(records)
    with tempfile.TemporaryDirectory() as directory:
        work = Path(directory)
        scene = sphere_scene(raylab, work)
        names = sorted(materials)
        columns = 10
        rows = (len(names) + columns - 1) // columns
        figure, axes = plt.subplots(rows, columns, figsize=(1.1 * columns, 1.35 * rows), squeeze=False)
        for ax in axes.flat:
            ax.axis("off")
        # A slice measures reflection only: a model's transmittance (rough glass's tint) is set to 0, so that a
        # material fitted best by a dielectric renders opaque, as it was measured.
        transmittance = {name: [p["name"] for p in params if p.get("role") == "transmittance"]
                         for name, params in raylab.brdf.models().items()}
        for ax, material in zip(axes.flat, names):
            best = min(materials[material].values(), key=lambda r: r[key])
            params = params_of(best["params"])
            for name in transmittance.get(best["model"], []):
                params[name] = (0.0, 0.0, 0.0)
            scene.set_material("sphere", model=best["model"], **params)
            image = raylab.Renderer(scene, width=size, height=size).render(spp=spp)[..., :3]
            ax.imshow(np.clip(image, 0, 1) ** (1 / 2.2))
            ax.set_title(f"{material}\n{best['model']}", fontsize=5)
        figure.tight_layout(pad=0.3, h_pad=0.6)
        save_sheet(figure, path, work)


def write(records: list[dict], slices: dict[str, Path], metric: str, docs: Path):
    raylab = md.import_raylab()
    key = "relative_log" if metric == "log" else "relative_cos"
    page = docs / "measured.md"
    models, mean_ranks = model_table(records, key)
    fits_by_label = md.published_fits()
    published = published_errors(fits_by_label, slices)
    images = docs / "images" / "measured"
    slice_figure(raylab, records, slices, key, images / "slices.png")
    contact_sheet(raylab, records, key, images / "best_fits.jpg")
    ranking = ", ".join(f"`{m}` ({r:.1f})" for m, r in mean_ranks.items())
    body = "\n\n".join([
        f"Fits minimise the {metric} metric; {len({r['material'] for r in records})} materials, "
        f"{len({r['model'] for r in records})} models. Relative errors (0: exact, 1: no better than black).",
        "### Per model\n\n" + models,
        "### Published fits beside raylab's\n\nEach published fit evaluated on the same slices by its own formula "
        "(tools/measured_data.py `published_f`), and raylab's fit of the same family. Errors in both metrics; the "
        f"last column compares in the {metric} metric, the one raylab minimised.\n\n" +
        published_section(records, fits_by_label, published, key),
        "Ngan's fits that raylab's models express exactly, evaluated through raylab (`raylab.brdf.fit_error`) "
        "against the formula (largest relative difference of the log error):\n\n"
        "| published fit | mapping | materials | largest difference | not expressible |\n|---|---|---|---|---|\n" +
        "\n".join(mapping_check(raylab, fits_by_label, slices, published)),
        f"### The ranking\n\nMean rank over the materials (1 best): {ranking}.\n\nNgan et al. 2005: {NGAN_ORDER}.",
        "### The best model per material against the best published fit\n\n" + best_section(records, published, key),
        "### Figures\n\n![measured slices beside their three best fits](images/measured/slices.png)\n\n"
        "Each material's measured slice (f averaged over RGB, log scale; white: the grazing bins a fit leaves out) "
        "beside its three best fits, with log10(fit / measured) below each.\n\n"
        "![every material's best fit as a sphere](images/measured/best_fits.jpg)\n\n"
        "Every material's best fit, a sphere under Blender's sunrise world (path traced, 128 spp; a dielectric's "
        "transmittance set to 0, since a slice measures reflection only).",
    ])
    text = page.read_text() if page.exists() else ""
    if BEGIN in text and END in text:
        head, rest = text.split(BEGIN, 1)
        text = head + BEGIN + "\n" + body + "\n" + END + rest.split(END, 1)[1]
    else:
        text = text + f"\n{BEGIN}\n{body}\n{END}\n"
    page.write_text(text)
    print(f"measured study: wrote {page}", file=sys.stderr)
