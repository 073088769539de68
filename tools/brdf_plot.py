#!/usr/bin/env python3
"""BRDF plots in the manner of Disney's BRDF Explorer, one PNG per material, from raylab's own numbers.

Left: polar plots of the lobe in the plane of incidence, one per incident angle theta_i. Light arrives from
wi at theta_i (the arrow, on the left of the normal); the curve is f(wi, wo) cos(theta_o) for wo swept through
the plane (the light scattered towards wo, whose integral over the hemisphere is the albedo), or f itself with
--quantity f. Each plot has its own radial scale, printed as its peak. The values are the shaders' own:
`raylab brdf eval --backend gpu`. The curve is the mean of the R, G and B channels.

Right: the directional albedo against the angle (`raylab brdf albedo`: the double-precision reference's
adaptive cubature as lines, the device sampler's Monte Carlo estimate as dots). The models are reciprocal, so
this is also the fraction of the light arriving from that angle that is reflected.

A two-sided model (rough glass: transmission with a density) is drawn over the whole plane, inside the surface
too, as f |cos(theta_o)|; its albedo is what it reflects and transmits of the light arriving from that angle.

Glass, a delta BSDF, gets its own figure: where the light goes (reflected and refracted rays, drawn as long as
the energy they carry) and the Fresnel reflectance against the angle of incidence, from outside and inside,
exact against Schlick's approximations.

    .venv/bin/python tools/brdf_plot.py --model phong --params "rho_d=0;rho_s=1;s=50" --out out/phong.png
"""
from __future__ import annotations

import argparse
import csv
import io
import math
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from raylab_tools import ToolError, add_raylab_option, check_raylab, registered_models, run_main, run_raylab, venv_hint

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

ANISOTROPIC_NOTE = "solid: plane of incidence along t (phi = 0); dashed: along b (phi = 90)"
ALBEDO_ANGLES = [*np.arange(0.0, 85.0, 2.5), 85.0, 86.0, 87.0, 88.0, 89.0, 89.5, 89.9]
ALBEDO_CHECK_ANGLES = [0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0]


@dataclass
class Lobe:
    theta_i: float
    phi: float
    theta_o: np.ndarray  # degrees, negative on the side of the light
    value: np.ndarray    # the plotted quantity, mean of RGB


def parse_args() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--model", required=True, help="a model of `raylab brdf models`")
    parser.add_argument("--params", default="", help="'k=v;k=v' as in `raylab brdf eval` (RGB as r/g/b); "
                        "others take the defaults of docs/brdfs.md")
    parser.add_argument("--out", type=Path, required=True, metavar="FILE.png", help="the figure to write")
    parser.add_argument("--incident", default="0,30,60,80", metavar="LIST",
                        help="incident angles theta_i in degrees, one polar plot each (default 0,30,60,80)")
    parser.add_argument("--phi", default="0", metavar="LIST", help="azimuths of the plane of incidence from the "
                        "tangent, degrees: '0' or '0,90' for anisotropic models (default 0)")
    parser.add_argument("--quantity", choices=["fcos", "f"], default="fcos",
                        help="radius: f cos(theta_o), the scattered light (default), or f")
    parser.add_argument("--radius", choices=["linear", "log"], default="linear",
                        help="radial scale; log shows --decades decades below each plot's peak (sharp lobes)")
    parser.add_argument("--decades", type=float, default=4.0, help="decades shown by --radius log (default 4)")
    parser.add_argument("--gpu-samples", type=int, default=1 << 18,
                        help="samples per angle of the device's albedo estimate; 0 skips it (default 262144)")
    parser.add_argument("--title", default=None, help="figure title (default: model and parameters)")
    parser.add_argument("--dpi", type=int, default=80, help="resolution of the PNG (default 80)")
    add_raylab_option(parser)
    return parser.parse_args()


def parse_angles(text: str, option: str, low: float, high: float) -> list[float]:
    try:
        angles = [float(part) for part in text.split(",")]
    except ValueError:
        raise ToolError(f"{option}: expected numbers separated by commas, got '{text}'") from None
    for angle in angles:
        if not low <= angle <= high:
            raise ToolError(f"{option}: {angle} is outside [{low}, {high}]")
    return angles


def vector(x: float, y: float, z: float) -> str:
    return f"{x:.9g} {y:.9g} {z:.9g}"


def in_plane(theta_deg: float, phi_deg: float) -> tuple[float, float, float]:
    """The unit direction at signed angle theta from the normal in the plane of azimuth phi."""
    theta, phi = math.radians(theta_deg), math.radians(phi_deg)
    return math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)


def lobe_angles(theta_i: float, two_sided: bool = False) -> np.ndarray:
    """theta_o: every 0.1 degree, and every 0.005 degree within 1 degree of the mirror direction, where the
    sharpest lobes of the contract (m = 0.001, about 0.1 degree wide) live; over the whole plane for a two-sided
    model (|theta_o| > 90: inside), less 0.05 degree either side of the horizon."""
    uniform = np.arange(-1799, 1800) / 10.0 if two_sided else np.arange(-899, 900) / 10.0
    mirror = theta_i + np.linspace(-1.0, 1.0, 401)
    angles = np.unique(np.concatenate([uniform, mirror]))
    return angles[np.abs(np.abs(angles) - 90.0) > 0.05] if two_sided else angles[np.abs(angles) < 89.95]


def is_two_sided(raylab: Path, model: str) -> bool:
    """Transmission with a density, as the registry's lobe flags say (`raylab brdf models --json`)."""
    for entry in registered_models(raylab):
        if entry["name"] == model:
            lobes = entry["lobes"].split()
            return "transmission" in lobes and ("glossy" in lobes or "diffuse" in lobes)
    raise ToolError(f"--model: '{model}' is not a model of `raylab brdf models`")


def evaluate(raylab: Path, rows: list[list[str]], workdir: Path) -> dict[str, list[tuple[str, str]]]:
    """Runs `raylab brdf eval --backend gpu` on the rows; returns id -> [(quantity, value), ...]."""
    cases = workdir / "cases.csv"
    values = workdir / "values.csv"
    with cases.open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["id", "model", "params", "wi", "wo", "n", "t"])
        writer.writerows(rows)
    run_raylab(raylab, ["brdf", "eval", "--in", str(cases), "--out", str(values), "--backend", "gpu"],
               "raylab brdf eval")
    result: dict[str, list[tuple[str, str]]] = {}
    with values.open(newline="") as file:
        for row in csv.DictReader(file):
            result.setdefault(row["id"], []).append((row["quantity"], row["value"]))
    return result


def mean_rgb(text: str) -> float:
    numbers = [float(x) for x in text.split()]
    return sum(numbers) / len(numbers)


def lobes(raylab: Path, args: argparse.Namespace, incident: list[float], phis: list[float],
          workdir: Path) -> list[Lobe]:
    rows, layout = [], []
    for phi in phis:
        for theta_i in incident:
            angles = lobe_angles(theta_i, args.two_sided)
            wi = vector(*in_plane(-theta_i, phi))
            for k, theta_o in enumerate(angles):
                rows.append([f"{phi}/{theta_i}/{k}", args.model, args.params, wi,
                             vector(*in_plane(theta_o, phi)), "0 0 1", "1 0 0"])
            layout.append((theta_i, phi, angles))
    values = evaluate(raylab, rows, workdir)
    result = []
    for theta_i, phi, angles in layout:
        f = np.array([mean_rgb(values[f"{phi}/{theta_i}/{k}"][0][1]) for k in range(len(angles))])
        if args.quantity == "fcos":
            f = f * np.abs(np.cos(np.radians(angles)))
        result.append(Lobe(theta_i, phi, angles, f))
    return result


def albedo(raylab: Path, args: argparse.Namespace, phi: float, backend: str, angles: list[float]) -> np.ndarray:
    """Rows of (theta_o, r, g, b, error) from `raylab brdf albedo`."""
    command = ["brdf", "albedo", "--model", args.model, "--params", args.params, "--phi", f"{phi:g}",
               "--backend", backend, "--angles", ",".join(f"{a:g}" for a in angles)]
    if backend == "gpu":
        command += ["--samples", str(args.gpu_samples)]
    output = run_raylab(raylab, command, f"raylab brdf albedo --backend {backend}").stdout
    table = list(csv.DictReader(io.StringIO(output)))
    return np.array([[float(r["theta_o"]), float(r["albedo_r"]), float(r["albedo_g"]), float(r["albedo_b"]),
                      float(r["error"])] for r in table])


def polar_grid(ax, rmax: float, rings: list[float], labels: list[str], full: bool = False) -> None:
    """A polar grid drawn on equal-aspect Cartesian axes, the normal pointing up and positive angles to the
    right: (x, y) = (r sin theta, r cos theta). `full` adds the lower half (inside a glass surface)."""
    low = -180 if full else -90
    sweep = np.radians(np.linspace(low, 180 if full else 90, 181))
    for ring in rings:
        ax.plot(ring * np.sin(sweep), ring * np.cos(sweep), color="0.85", lw=0.6, zorder=0)
    ax.plot(rmax * np.sin(sweep), rmax * np.cos(sweep), color="0.35", lw=0.8, zorder=0)
    for angle in range(low + 30, 180 if full else 90, 30):
        a = math.radians(angle)
        ax.plot([0, rmax * math.sin(a)], [0, rmax * math.cos(a)], color="0.88", lw=0.6, zorder=0)
    for angle in range(-150 if full else -90, 181 if full else 91, 30):
        a = math.radians(angle)
        ax.text(1.1 * rmax * math.sin(a), 1.1 * rmax * math.cos(a), f"{angle}°", fontsize=6.5, color="0.35",
                ha="center", va="center")
    ax.plot([-rmax, rmax], [0, 0], color="0.35", lw=0.8, zorder=0)
    for ring, label in zip(rings, labels):
        ax.text(-ring, -0.03 * rmax, label, fontsize=6, color="0.4", ha="center", va="top")
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_xlim(-1.2 * rmax, 1.2 * rmax)
    ax.set_ylim((-1.2 if full else -0.12) * rmax, 1.18 * rmax)


def polar_xy(theta_deg: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    theta = np.radians(theta_deg)
    return r * np.sin(theta), r * np.cos(theta)


def radius(values: np.ndarray, peak: float, args: argparse.Namespace) -> np.ndarray:
    if args.radius == "linear":
        return values
    with np.errstate(divide="ignore"):
        return np.maximum(np.log10(np.maximum(values, 0.0) / peak) + args.decades, 0.0)


def plot_lobe(ax, group: list[Lobe], args: argparse.Namespace) -> None:
    peak = max(float(lobe.value.max()) for lobe in group)
    if not peak > 0.0:
        peak = 1.0
    symbol = "f cos" if args.quantity == "fcos" else "f"
    if args.radius == "linear":
        rmax, rings, labels = peak, [peak / 2, peak], [f"{peak / 2:.2g}", f"{peak:.2g}"]
    else:
        rmax = args.decades
        rings = [float(d) for d in range(1, int(args.decades) + 1)]
        labels = [f"1e-{int(args.decades) - int(d)}" if d < args.decades else "peak" for d in rings]
    polar_grid(ax, rmax, rings, labels, full=args.two_sided)
    ax.set_title(f"θi = {group[0].theta_i:g}°   peak {symbol} = {peak:.3g}", fontsize=9, pad=1)
    for lobe in group:
        style = "-" if lobe.phi == group[0].phi else "--"
        ax.plot(*polar_xy(lobe.theta_o, radius(lobe.value, peak, args)), style, color="C0", lw=1.4)
    theta_i = group[0].theta_i
    ax.annotate("", xy=(0.0, 0.0), xytext=polar_xy(np.array(-theta_i), np.array(rmax)),
                arrowprops=dict(arrowstyle="-|>", color="C3", lw=1.2, shrinkA=0, shrinkB=0))
    ax.plot(*polar_xy(np.array([theta_i, theta_i]), np.array([0.0, rmax])), ":", color="0.5", lw=0.8)


def plot_albedo(ax, raylab: Path, args: argparse.Namespace, phis: list[float]) -> None:
    highest = 0.0
    for index, phi in enumerate(phis):
        style = "-" if index == 0 else "--"
        ref = albedo(raylab, args, phi, "cpu", ALBEDO_ANGLES)
        highest = max(highest, float(ref[:, 1:4].max()))
        grey = np.allclose(ref[:, 1], ref[:, 2]) and np.allclose(ref[:, 1], ref[:, 3])
        suffix = f", φ = {phi:g}°" if len(phis) > 1 else ""
        if grey:
            ax.plot(ref[:, 0], ref[:, 1], style, color="k", lw=1.3, label="reference (cubature)" + suffix)
        else:
            for channel, colour in zip((1, 2, 3), ("tab:red", "tab:green", "tab:blue")):
                ax.plot(ref[:, 0], ref[:, channel], style, color=colour, lw=1.2,
                        label=("reference R, G, B" + suffix) if channel == 1 else None)
        if args.gpu_samples > 0:
            mc = albedo(raylab, args, phi, "gpu", ALBEDO_CHECK_ANGLES)
            mean = mc[:, 1:4].mean(axis=1)
            ax.errorbar(mc[:, 0], mean, yerr=2 * mc[:, 4], fmt="o", ms=3.5, color="C1", mfc="none",
                        label=("device sampler (MC, RGB mean)" if index == 0 else None))
    ax.axhline(1.0, color="0.6", lw=0.8, ls=":")
    if highest > 1.6:
        ax.set_yscale("log")
    else:
        ax.set_ylim(0.0, max(1.1, highest * 1.05))
    ax.set_xlim(0, 90)
    ax.set_xticks(range(0, 91, 15))
    ax.set_xlabel("θ (degrees from the normal)", fontsize=9)
    ax.set_ylabel("directional albedo", fontsize=9)
    ax.tick_params(labelsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    ax.set_title("albedo against angle", fontsize=9)


def brdf_figure(raylab: Path, args: argparse.Namespace, workdir: Path):
    incident = parse_angles(args.incident, "--incident", 0.0, 89.9)
    phis = parse_angles(args.phi, "--phi", 0.0, 360.0)
    if len(incident) > 6:
        raise ToolError("--incident: at most 6 angles")
    if len(phis) > 2:
        raise ToolError("--phi: at most 2 planes")
    all_lobes = lobes(raylab, args, incident, phis, workdir)
    columns = 2 if len(incident) > 1 else 1
    rows = math.ceil(len(incident) / columns)
    figure = plt.figure(figsize=(3.4 * columns + 4.4, 2.0 * rows + 0.6))
    outer = figure.add_gridspec(1, 2, width_ratios=[3.4 * columns, 4.0], wspace=0.12)
    grid = outer[0].subgridspec(rows, columns, wspace=0.05, hspace=0.12)
    for index, theta_i in enumerate(incident):
        ax = figure.add_subplot(grid[index // columns, index % columns])
        plot_lobe(ax, [lobe for lobe in all_lobes if lobe.theta_i == theta_i], args)
    plot_albedo(figure.add_subplot(outer[1]), raylab, args, phis)
    symbol = "f·cos θo" if args.quantity == "fcos" else "f"
    scale = "linear radius" if args.radius == "linear" else f"log radius, {args.decades:g} decades"
    note = f"lobes: {symbol} in the plane of incidence, light from the arrow ({scale}, RGB mean)"
    if len(phis) > 1:
        note += f"; {ANISOTROPIC_NOTE}"
    figure.text(0.01, -0.01, note, fontsize=7.5, color="0.3", va="top")
    return figure


def glass_figure(raylab: Path, args: argparse.Namespace, workdir: Path):
    incident = parse_angles(args.incident, "--incident", 0.0, 89.9)
    sweep = np.linspace(0.0, 89.9, 360)
    rows = []
    for side, sign in (("out", 1.0), ("in", -1.0)):
        for k, theta in enumerate(sweep):
            x, _, z = in_plane(-theta, 0.0)
            rows.append([f"{side}/{k}", "glass", args.params, vector(x, 0.0, sign * z), "", "0 0 1", ""])
    for k, theta in enumerate(incident):
        rows.append([f"ray/{k}", "glass", args.params, vector(*in_plane(-theta, 0.0)), "", "0 0 1", ""])
    values = evaluate(raylab, rows, workdir)

    def quantity(key: str, name: str) -> str:
        return next(value for q, value in values[key] if q == name)

    figure = plt.figure(figsize=(10.5, 4.6))
    grid = figure.add_gridspec(1, 2, width_ratios=[1.0, 1.3], wspace=0.12)
    ax = figure.add_subplot(grid[0])
    polar_grid(ax, 1.0, [0.5, 1.0], ["0.5", "1"], full=True)
    ax.text(1.0, 0.04, "outside", fontsize=7, color="0.35", ha="right", va="bottom")
    ax.text(1.0, -0.04, "inside", fontsize=7, color="0.35", ha="right", va="top")
    for k, theta in enumerate(incident):
        colour = f"C{k}"
        fresnel = float(quantity(f"ray/{k}", "F_exact"))
        ax.annotate("", xy=(0.0, 0.0), xytext=polar_xy(np.array(-theta), np.array(1.0)),
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.0, shrinkA=0, shrinkB=0))
        rx, _, rz = (float(c) for c in quantity(f"ray/{k}", "reflect").split())
        ax.plot([0, fresnel * rx], [0, fresnel * rz], color=colour, lw=2.2)
        refracted = quantity(f"ray/{k}", "refract")
        if refracted != "none":
            tx, _, tz = (float(c) for c in refracted.split())
            ax.plot([0, (1.0 - fresnel) * tx], [0, (1.0 - fresnel) * tz], color=colour, lw=2.0, ls="--",
                    label=f"θi = {theta:g}°: F = {fresnel:.3f}")
    ax.legend(fontsize=7, loc="lower left", frameon=False)
    ax.set_title("light from outside (arrows): reflected (solid, length F),\n"
                 "refracted (dashed, length 1 − F)", fontsize=8.5)

    ax = figure.add_subplot(grid[1])
    for side, colour, label in (("out", "C0", "from outside"), ("in", "C3", "from inside")):
        for name, style in (("F_exact", "-"), ("F_schlick", "--"), ("F_schlick_naive", ":")):
            if side == "out" and name == "F_schlick_naive":
                continue  # from outside the thinner side is the incident one: the same as F_schlick
            curve = [float(quantity(f"{side}/{k}", name)) for k in range(len(sweep))]
            ax.plot(sweep, curve, style, color=colour, lw=1.3, label=f"{name}, {label}")
    tir = [k for k in range(len(sweep)) if quantity(f"in/{k}", "tir") == "1"]
    if tir:
        critical = sweep[tir[0]]
        ax.axvline(critical, color="0.5", lw=0.8, ls=":")
        ax.text(critical + 1.0, 0.5, f"total internal\nreflection from\n{critical:.1f}°", fontsize=7, color="0.35")
    ax.set_xlim(0, 90)
    ax.set_ylim(0, 1.02)
    ax.set_xticks(range(0, 91, 15))
    ax.set_xlabel("angle of incidence (degrees from the normal)", fontsize=9)
    ax.set_ylabel("Fresnel reflectance", fontsize=9)
    ax.tick_params(labelsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    ax.set_title("reflectance: exact against Schlick's approximations", fontsize=9)
    return figure


def main() -> None:
    args = parse_args()
    raylab = check_raylab(args.raylab)
    if args.out.suffix != ".png":
        raise ToolError(f"--out: '{args.out}' must end in .png")
    if "," in args.params:
        raise ToolError(f"--params: '{args.params}' has a comma: separate parameters with ';' and RGB channels "
                        f"with '/' (e.g. 'rho_d=0.5/0.2/0.1;s=50')")
    with tempfile.TemporaryDirectory(prefix="brdf_plot_") as temp:
        args.two_sided = is_two_sided(raylab, args.model)
        make = glass_figure if args.model == "glass" else brdf_figure
        figure = make(raylab, args, Path(temp))
    figure.suptitle(args.title or f"{args.model}   {args.params or '(defaults)'}", fontsize=11, y=0.99)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(args.out, dpi=args.dpi, bbox_inches="tight", pad_inches=0.08)
    plt.close(figure)
    print(f"wrote {args.out} ({args.out.stat().st_size // 1024} KB)")


if __name__ == "__main__":
    run_main(main)
