#!/usr/bin/env python3
"""raylab against Mitsuba 3, an independent renderer (PyPI `mitsuba`), on scenes both can express.

Each scene is written twice from one description: as glTF for `raylab render --integrator path` and as a
Mitsuba 3 scene dictionary for its `path` integrator. The conventions that must agree (docs/integrators.md):
max depth (raylab's D bounces after the primary hit = Mitsuba's max_depth D + 2), a one-sided area light on the
side of the counter-clockwise normal, the equirectangular environment (Mitsuba's `envmap` with an identity
transform), a pinhole camera with a vertical field of view, and a box pixel filter (raylab's uniform jitter).

The scenes:
  cornell   a Lambert Cornell box (white, red and green walls, two white spheres) lit by a quad light
  spheres   a Lambert, a mirror and a glass sphere on a Lambert floor, lit by an HDR environment
            (Blender's CC0 `courtyard` world, copied to assets/scenes/environments by tools/setup.sh)
  metals    three GGX conductors (gold, a brushed anisotropic aluminium, and k = 0) on the same floor under the
            same environment and a point light
  glass     rough glass (ggx_dielectric against Mitsuba's roughdielectric) at three roughnesses on the same
            floor under the same environment and a point light

Agreement: both images are averaged over blocks of BLOCK x BLOCK pixels and relMAE = sum |raylab - mitsuba| /
sum mitsuba over the blocks and the R, G, B channels. The noise floor is the same figure between two raylab
renders with different seeds; --check fails (exit 1) when a scene's relMAE exceeds --tolerance (1%).

With --speed it also measures, per scene, the CPU time each renderer needs to reach relMSE 1e-3, where
relMSE = mean((x - r)^2 / (r^2 + 0.01)) over pixels and channels and r is the converged image. For an unbiased
renderer that is its variance, which falls as 1/spp; it is estimated from two independent renders x1, x2 of
the same renderer as mean((x1 - x2)^2 / 2 / (r^2 + 0.01)), with r the mean of all four renders (the
denominator only), so neither renderer's noise is correlated with the reference. The time is the steady CPU
time per sample (all threads) times the spp at which relMSE reaches 1e-3. Both renderers run on all cores of
this machine, in one run; the ratio raylab / Mitsuba is the machine-independent figure (docs/performance.md).

    .venv/bin/python tools/mitsuba_compare.py --check          # the agreement test that ctest runs
    .venv/bin/python tools/mitsuba_compare.py --speed          # also time to relMSE 1e-3, and the ratio
"""
from __future__ import annotations

import argparse
import json
import math
import os
import platform
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from raylab_tools import (REPO, ToolError, add_raylab_option, check_raylab, point_mitsuba_at_libllvm, run_main,
                          run_raylab, venv_hint)

sys.path.insert(0, str(REPO / "tools" / "scenes"))
import make_scenes  # noqa: E402  (the committed scenes' glTF writer)

point_mitsuba_at_libllvm()

try:
    import numpy as np
    import mitsuba as mi
    from image_io import read_exr
except ImportError as missing:
    sys.exit(f"{Path(sys.argv[0]).name}: error: {venv_hint(missing.name)}")

ENVIRONMENTS = REPO / "assets" / "scenes" / "environments"
EPSILON = 0.01  # relMSE's guard against division by a black reference pixel
TARGET_RELMSE = 1e-3


@dataclass(frozen=True)
class Material:
    name: str
    # diffuse, mirror, glass, conductor (GGX: raylab's ggx_conductor, Mitsuba's roughconductor) or roughglass
    # (raylab's ggx_dielectric, Mitsuba's roughdielectric)
    kind: str
    rgb: tuple[float, float, float] = (0.0, 0.0, 0.0)  # diffuse reflectance
    emission: tuple[float, float, float] | None = None  # radiance of an area light
    alpha: float = 0.0  # conductor, roughglass: GGX roughness along the tangent
    alpha_v: float | None = None  # along the bitangent, when anisotropic (the tangent runs along latitudes)
    eta: tuple[float, float, float] = (1.0, 1.0, 1.0)  # conductor: complex index of refraction eta + i k
    k: tuple[float, float, float] = (0.0, 0.0, 0.0)
    metal: str | None = None  # conductor: a named metal of both renderers instead of eta and k


@dataclass(frozen=True)
class Quad:
    """The parallelogram corner + [0,1] u + [0,1] v, two triangles facing u x v (make_scenes.quad)."""
    name: str
    corner: tuple[float, float, float]
    u: tuple[float, float, float]
    v: tuple[float, float, float]
    material: str


@dataclass(frozen=True)
class Ball:
    name: str
    center: tuple[float, float, float]
    radius: float
    material: str


@dataclass
class Case:
    name: str
    materials: list[Material]
    quads: list[Quad]
    balls: list[Ball]
    camera: tuple[tuple[float, float, float], tuple[float, float, float], float]  # position, target, yfov (deg)
    environment: str | None = None  # a file of ENVIRONMENTS
    point_light: tuple[tuple[float, float, float], float] | None = None  # position, intensity (W/sr, white)
    max_depth: int = 6  # raylab's D
    notes: dict = field(default_factory=dict)


def cornell() -> Case:
    w = 1.75
    materials = [Material("white", "diffuse", (0.73, 0.73, 0.73)), Material("red", "diffuse", (0.63, 0.065, 0.05)),
                 Material("green", "diffuse", (0.14, 0.45, 0.09)),
                 Material("lamp", "diffuse", (0.0, 0.0, 0.0), emission=(12.0, 10.2, 7.2))]
    quads = [Quad("floor", (-w, 0.0, 1.0), (2 * w, 0.0, 0.0), (0.0, 0.0, -2.0), "white"),
             Quad("ceiling", (-w, 2.0, -1.0), (2 * w, 0.0, 0.0), (0.0, 0.0, 2.0), "white"),
             Quad("back wall", (-w, 0.0, -1.0), (2 * w, 0.0, 0.0), (0.0, 2.0, 0.0), "white"),
             Quad("left wall", (-w, 0.0, 1.0), (0.0, 0.0, -2.0), (0.0, 2.0, 0.0), "red"),
             Quad("right wall", (w, 0.0, -1.0), (0.0, 0.0, 2.0), (0.0, 2.0, 0.0), "green"),
             Quad("light", (-0.45, 1.995, -0.35), (0.9, 0.0, 0.0), (0.0, 0.0, 0.7), "lamp")]
    balls = [Ball("left sphere", (-0.6, 0.45, -0.3), 0.45, "white"),
             Ball("right sphere", (0.65, 0.45, 0.3), 0.45, "white")]
    return Case("cornell", materials, quads, balls, ((0.0, 1.0, 4.2), (0.0, 1.0, 0.0), 34.0))


def spheres() -> Case:
    materials = [Material("floor", "diffuse", (0.5, 0.5, 0.5)), Material("lambert", "diffuse", (0.8, 0.3, 0.2)),
                 Material("mirror", "mirror"), Material("glass", "glass")]
    quads = [Quad("floor", (-4.0, 0.0, 4.0), (8.0, 0.0, 0.0), (0.0, 0.0, -8.0), "floor")]
    balls = [Ball("lambert", (-1.3, 0.6, 0.0), 0.6, "lambert"), Ball("mirror", (0.0, 0.6, -0.4), 0.6, "mirror"),
             Ball("glass", (1.3, 0.6, 0.0), 0.6, "glass")]
    return Case("spheres", materials, quads, balls, ((0.0, 1.6, 5.0), (0.0, 0.5, 0.0), 35.0),
                environment="courtyard.exr")


# A point light beside the environment, up and to the right of the camera (W/sr).
POINT_LIGHT = ((2.5, 3.5, 3.0), 6.0)


def metals() -> Case:
    """GGX conductors (gold named on both sides, a brushed aluminium-like index at 650, 550 and 450 nm with
    anisotropic roughness, and a rough dielectric index with k = 0, whose F0 is 4%) on a Lambert floor under the
    environment and a point light: the second library's ggx_conductor against Mitsuba's roughconductor with
    distribution=ggx."""
    materials = [Material("floor", "diffuse", (0.5, 0.5, 0.5)),
                 Material("gold", "conductor", alpha=0.1, metal="Au"),
                 Material("aluminium", "conductor", alpha=0.05, alpha_v=0.4, eta=(1.66, 0.96, 0.62),
                          k=(8.07, 6.69, 5.31)),
                 Material("low", "conductor", alpha=0.05, eta=(1.5, 1.5, 1.5))]
    quads = [Quad("floor", (-4.0, 0.0, 4.0), (8.0, 0.0, 0.0), (0.0, 0.0, -8.0), "floor")]
    balls = [Ball("gold", (-1.3, 0.6, 0.0), 0.6, "gold"), Ball("aluminium", (0.0, 0.6, -0.4), 0.6, "aluminium"),
             Ball("low", (1.3, 0.6, 0.0), 0.6, "low")]
    return Case("metals", materials, quads, balls, ((0.0, 1.6, 5.0), (0.0, 0.5, 0.0), 35.0),
                environment="courtyard.exr", point_light=POINT_LIGHT)


def glass() -> Case:
    """Rough glass spheres (eta 1.5; GGX alpha 0.05, 0.2 and 0.5) on a Lambert floor under the environment and a
    point light: ggx_dielectric against Mitsuba's roughdielectric with distribution=ggx, light refracted in and out
    of each sphere (max depth 8)."""
    materials = [Material("floor", "diffuse", (0.5, 0.5, 0.5)),
                 Material("frosted 0.05", "roughglass", alpha=0.05), Material("frosted 0.2", "roughglass", alpha=0.2),
                 Material("frosted 0.5", "roughglass", alpha=0.5)]
    quads = [Quad("floor", (-4.0, 0.0, 4.0), (8.0, 0.0, 0.0), (0.0, 0.0, -8.0), "floor")]
    balls = [Ball("frosted 0.05", (-1.3, 0.6, 0.0), 0.6, "frosted 0.05"),
             Ball("frosted 0.2", (0.0, 0.6, -0.4), 0.6, "frosted 0.2"),
             Ball("frosted 0.5", (1.3, 0.6, 0.0), 0.6, "frosted 0.5")]
    return Case("glass", materials, quads, balls, ((0.0, 1.6, 5.0), (0.0, 0.5, 0.0), 35.0),
                environment="courtyard.exr", point_light=POINT_LIGHT, max_depth=8)


CASES = {"cornell": cornell, "spheres": spheres, "metals": metals, "glass": glass}


def write_gltf(case: Case, directory: Path) -> Path:
    g = make_scenes.Gltf(case.name)
    index = {}
    for m in case.materials:
        if m.kind == "diffuse":
            raylab = {"model": "lambert", "rho_d": list(m.rgb)}
        elif m.kind == "mirror":
            raylab = {"model": "lambert", "rho_d": [0.0, 0.0, 0.0], "delta": 1.0}
        elif m.kind == "conductor":
            raylab = {"model": "ggx_conductor", "alpha_x": m.alpha, "alpha_y": m.alpha_v or m.alpha,
                      "rho_s": [1.0, 1.0, 1.0]}
            raylab.update({"metal": m.metal} if m.metal else {"eta": list(m.eta), "k": list(m.k)})
        elif m.kind == "roughglass":
            raylab = {"model": "ggx_dielectric", "alpha_x": m.alpha, "alpha_y": m.alpha_v or m.alpha, "eta": 1.5}
        else:
            raylab = {"model": "glass", "eta": 1.5, "tint": [1.0, 1.0, 1.0]}
        index[m.name] = g.material(m.name, raylab)
        if m.emission:
            peak = max(m.emission)
            g.doc["materials"][index[m.name]]["emissiveFactor"] = [c / peak for c in m.emission]
            g.doc["materials"][index[m.name]]["extensions"] = {
                "KHR_materials_emissive_strength": {"emissiveStrength": peak}}
            if "KHR_materials_emissive_strength" not in g.doc["extensionsUsed"]:
                g.doc["extensionsUsed"].append("KHR_materials_emissive_strength")
    for q in case.quads:
        make_scenes.add_quad(g, q.name, list(q.corner), list(q.u), list(q.v), index[q.material])
    for b in case.balls:
        g.sphere(b.name, list(b.center), b.radius, index[b.material])
    position, target, yfov = case.camera
    g.camera("camera", list(position), list(target), yfov)
    if case.point_light:
        g.point_light("point light", list(case.point_light[0]), case.point_light[1])
    if case.environment:
        (directory / "environments").mkdir(parents=True, exist_ok=True)
        link = directory / "environments" / case.environment
        source = ENVIRONMENTS / case.environment
        if not source.exists():
            raise ToolError(f"{source} is missing: tools/setup.sh copies Blender's HDR worlds there")
        if not link.exists():
            link.write_bytes(source.read_bytes())
        g.environment("environments/" + case.environment)
    return Path(g.write(str(directory)))


def write_obj(quad: Quad, path: Path) -> None:
    c, u, v = np.array(quad.corner), np.array(quad.u), np.array(quad.v)
    corners = [c, c + u, c + u + v, c + v]
    lines = [f"v {p[0]:.9g} {p[1]:.9g} {p[2]:.9g}" for p in corners] + ["f 1 2 3", "f 1 3 4"]
    path.write_text("\n".join(lines) + "\n")


def mitsuba_scene(case: Case, directory: Path, width: int, height: int, spp: int, sampler: str) -> dict:
    T = mi.ScalarTransform4f
    position, target, yfov = case.camera
    bsdfs = {}
    for m in case.materials:
        if m.kind == "diffuse":
            bsdfs[m.name] = {"type": "diffuse", "reflectance": {"type": "rgb", "value": list(m.rgb)}}
        elif m.kind == "mirror":
            bsdfs[m.name] = {"type": "conductor", "material": "none"}
        elif m.kind == "conductor":
            bsdfs[m.name] = {"type": "roughconductor", "distribution": "ggx"}
            bsdfs[m.name].update({"alpha_u": m.alpha, "alpha_v": m.alpha_v} if m.alpha_v else {"alpha": m.alpha})
            bsdfs[m.name].update({"material": m.metal} if m.metal else {
                "eta": {"type": "rgb", "value": list(m.eta)}, "k": {"type": "rgb", "value": list(m.k)}})
        elif m.kind == "roughglass":
            bsdfs[m.name] = {"type": "roughdielectric", "distribution": "ggx", "int_ior": 1.5, "ext_ior": 1.0}
            bsdfs[m.name].update({"alpha_u": m.alpha, "alpha_v": m.alpha_v} if m.alpha_v else {"alpha": m.alpha})
        else:
            bsdfs[m.name] = {"type": "dielectric", "int_ior": 1.5, "ext_ior": 1.0}
    emission = {m.name: m.emission for m in case.materials}
    scene = {
        "type": "scene",
        # Mitsuba counts segments: raylab's D bounces after the primary hit is max_depth D + 2.
        "integrator": {"type": "path", "max_depth": case.max_depth + 2},
        "sensor": {
            "type": "perspective", "fov_axis": "y", "fov": yfov,
            "to_world": T().look_at(origin=list(position), target=list(target), up=[0.0, 1.0, 0.0]),
            "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
                     "pixel_format": "rgb"},
            "sampler": {"type": sampler, "sample_count": spp},
        },
    }
    for i, q in enumerate(case.quads):
        obj = directory / f"{case.name}_quad{i}.obj"
        write_obj(q, obj)
        shape = {"type": "obj", "filename": str(obj), "face_normals": True, "bsdf": bsdfs[q.material]}
        if emission[q.material]:
            shape["emitter"] = {"type": "area", "radiance": {"type": "rgb", "value": list(emission[q.material])}}
        scene[f"quad{i}"] = shape
    for i, b in enumerate(case.balls):
        # Turned so that the sphere's own pole axis z is the world's y: its dp/du, the tangent of anisotropic
        # roughness, then runs along latitudes around y, as raylab's sphere tangent does.
        to_world = T().translate(list(b.center)) @ T().rotate([1.0, 0.0, 0.0], -90.0) @ T().scale(b.radius)
        scene[f"ball{i}"] = {"type": "sphere", "to_world": to_world, "bsdf": bsdfs[b.material]}
    if case.point_light:
        scene["point light"] = {"type": "point", "position": list(case.point_light[0]),
                                "intensity": {"type": "rgb", "value": [case.point_light[1]] * 3}}
    if case.environment:
        scene["environment"] = {"type": "envmap", "filename": str(ENVIRONMENTS / case.environment), "scale": 1.0}
    return scene


@dataclass
class Render:
    image: np.ndarray
    cpu_per_sample_s: float  # steady CPU seconds per sample (all threads of the renderer)
    wall_per_sample_s: float


def render_raylab(raylab: Path, scene: Path, case: Case, out: Path, width: int, height: int, spp: int,
                  seed: int, schedule: str = "auto") -> Render:
    exr = out / f"{case.name}_raylab_{spp}spp_seed{seed}.exr"
    report = exr.with_suffix(".json")
    run_raylab(raylab, ["render", str(scene), "--integrator", "path", "--max-depth", str(case.max_depth),
                        "--width", str(width), "--height", str(height), "--spp", str(spp), "--seed", str(seed),
                        "--out", str(exr), "--no-png", "--report", str(report), "--schedule", schedule],
               f"raylab on {case.name}")
    figures = json.loads(report.read_text())
    if figures.get("dropped_samples", 0):
        raise ToolError(f"raylab dropped {figures['dropped_samples']} NaN or Inf samples on {case.name}")
    return Render(read_exr(exr), figures["cpu_per_sample_s"], figures["per_sample_s"])


def render_mitsuba(case: Case, out: Path, width: int, height: int, spp: int, seed: int, sampler: str) -> Render:
    scene = mi.load_dict(mitsuba_scene(case, out, width, height, spp, sampler))
    # The first render of a scene compiles its kernels (Dr.Jit's LLVM JIT); the timed one reuses them.
    mi.render(scene, spp=1, seed=seed + 7919)
    cpu, wall = time.process_time(), time.perf_counter()
    image = np.array(mi.render(scene, spp=spp, seed=seed), dtype=np.float64)
    cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
    return Render(image[..., :3], cpu / spp, wall / spp)


def block_means(image: np.ndarray, block: int) -> np.ndarray:
    h, w = (image.shape[0] // block) * block, (image.shape[1] // block) * block
    return image[:h, :w].reshape(h // block, block, w // block, block, 3).mean(axis=(1, 3))


def rel_mae(a: np.ndarray, b: np.ndarray, block: int) -> float:
    a, b = block_means(a, block), block_means(b, block)
    return float(np.abs(a - b).sum() / b.sum())


def variance_rel_mse(x1: np.ndarray, x2: np.ndarray, converged: np.ndarray) -> float:
    """The relMSE of one of two independent renders against the converged image: half their squared difference."""
    return float(np.mean((x1 - x2) ** 2 / 2.0 / (converged ** 2 + EPSILON)))


def parse_args() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    add_raylab_option(parser)
    parser.add_argument("--scenes", default=",".join(CASES), help="comma-separated (default: all): "
                        + ", ".join(CASES))
    parser.add_argument("--width", type=int, default=160)
    parser.add_argument("--height", type=int, default=90)
    parser.add_argument("--spp", type=int, default=1024, help="samples per pixel of each render (default 1024)")
    parser.add_argument("--block", type=int, default=10, help="block size in pixels for relMAE (default 10)")
    parser.add_argument("--tolerance", type=float, default=0.01, help="largest relMAE --check accepts (0.01)")
    parser.add_argument("--check", action="store_true", help="exit 1 when a scene's relMAE exceeds --tolerance")
    parser.add_argument("--speed", action="store_true", help="also time to relMSE 1e-3 for each renderer")
    parser.add_argument("--mitsuba-sampler", default="independent", choices=["independent", "stratified",
                        "multijitter", "orthogonal", "ldsampler"], help="Mitsuba's sample generator (default "
                        "independent; ldsampler is its low-discrepancy one, the counterpart of raylab's Sobol points)")
    parser.add_argument("--schedule", default="auto", choices=["auto", "megakernel", "wavefront"],
                        help="raylab's schedule (raylab render --schedule; default auto: the wavefront)")
    parser.add_argument("--variant", default="llvm_ad_rgb", help="Mitsuba variant (default llvm_ad_rgb; "
                        "scalar_rgb needs no libLLVM but is far slower)")
    parser.add_argument("--out", type=Path, default=REPO / "out" / "mitsuba_compare",
                        help="where scenes, images and results.json go (default out/mitsuba_compare)")
    args = parser.parse_args()
    for name in args.scenes.split(","):
        if name not in CASES:
            parser.error(f"--scenes: unknown scene '{name}' (the scenes are {', '.join(CASES)})")
    if min(args.width, args.height, args.spp, args.block) < 1:
        parser.error("--width, --height, --spp and --block must be positive")
    return args


def main() -> None:
    args = parse_args()
    raylab = check_raylab(args.raylab)
    try:
        mi.set_variant(args.variant)
    except Exception as error:  # Mitsuba raises ImportError or a bare Exception for an unusable variant
        raise ToolError(f"Mitsuba variant {args.variant} is unusable here ({error}); the LLVM variants need "
                        f"libLLVM 19 (tools/setup.sh installs libllvm19), or pass --variant scalar_rgb")
    args.out.mkdir(parents=True, exist_ok=True)
    results = {"mitsuba_sampler": args.mitsuba_sampler, "raylab_schedule": args.schedule,
               "machine": {"cpus": os.cpu_count(), "platform": platform.platform(), "mitsuba": mi.__version__,
                           "variant": args.variant, "load_average": os.getloadavg()},
               "width": args.width, "height": args.height, "spp": args.spp, "block": args.block, "scenes": {}}
    failed = []
    for name in args.scenes.split(","):
        case = CASES[name]()
        gltf = write_gltf(case, args.out)
        print(f"{name}: {args.width}x{args.height}, {args.spp} spp, max depth {case.max_depth} "
              f"(Mitsuba max_depth {case.max_depth + 2})", flush=True)
        ours = render_raylab(raylab, gltf, case, args.out, args.width, args.height, args.spp, 1, args.schedule)
        again = render_raylab(raylab, gltf, case, args.out, args.width, args.height, args.spp, 2, args.schedule)
        theirs = render_mitsuba(case, args.out, args.width, args.height, args.spp, 3, args.mitsuba_sampler)
        theirs_again = render_mitsuba(case, args.out, args.width, args.height, args.spp, 4,
                                      args.mitsuba_sampler) if args.speed else None
        np.save(args.out / f"{name}_mitsuba_{args.spp}spp.npy", theirs.image)
        agreement = rel_mae(ours.image, theirs.image, args.block)
        floor = rel_mae(ours.image, again.image, args.block)
        means = [ours.image.mean(axis=(0, 1)).round(5).tolist(), theirs.image.mean(axis=(0, 1)).round(5).tolist()]
        print(f"  relMAE raylab vs Mitsuba {agreement:.4%} (noise floor raylab vs raylab {floor:.4%}); "
              f"mean RGB raylab {means[0]}, Mitsuba {means[1]}", flush=True)
        entry = {"rel_mae": agreement, "noise_floor": floor, "mean_raylab": means[0], "mean_mitsuba": means[1]}
        if args.speed:
            converged = 0.25 * (ours.image + again.image + theirs.image + theirs_again.image)
            ours_spp = args.spp * variance_rel_mse(ours.image, again.image, converged) / TARGET_RELMSE
            theirs_spp = args.spp * variance_rel_mse(theirs.image, theirs_again.image, converged) / TARGET_RELMSE
            entry["raylab"] = {"cpu_per_sample_s": ours.cpu_per_sample_s, "wall_per_sample_s": ours.wall_per_sample_s,
                               "spp_to_target": ours_spp, "cpu_s_to_target": ours_spp * ours.cpu_per_sample_s}
            entry["mitsuba"] = {"cpu_per_sample_s": theirs.cpu_per_sample_s,
                                "wall_per_sample_s": theirs.wall_per_sample_s, "spp_to_target": theirs_spp,
                                "cpu_s_to_target": theirs_spp * theirs.cpu_per_sample_s}
            entry["ratio_cpu_s_to_target"] = entry["raylab"]["cpu_s_to_target"] / entry["mitsuba"]["cpu_s_to_target"]
            print(f"  to relMSE 1e-3: raylab {entry['raylab']['cpu_s_to_target']:.2f} CPU s ({ours_spp:.0f} spp), "
                  f"Mitsuba {entry['mitsuba']['cpu_s_to_target']:.2f} CPU s ({theirs_spp:.0f} spp); ratio "
                  f"{entry['ratio_cpu_s_to_target']:.2f}", flush=True)
        results["scenes"][name] = entry
        if agreement > args.tolerance:
            failed.append(f"{name}: relMAE {agreement:.3%} > {args.tolerance:.1%}")
    path = args.out / "results.json"
    temporary = path.with_suffix(".json.tmp")
    temporary.write_text(json.dumps(results, indent=2) + "\n")
    temporary.replace(path)
    print(f"wrote {path}")
    if args.check and failed:
        raise ToolError("raylab and Mitsuba disagree: " + "; ".join(failed))


if __name__ == "__main__":
    run_main(main)
