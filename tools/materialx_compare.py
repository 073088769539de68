#!/usr/bin/env python3
"""raylab's openpbr and gltf_pbr against MaterialX's own: an independent implementation of both.

MaterialX (PyPI `materialx`, pinned in tools/requirements.txt) holds OpenPBR Surface and glTF's BRDF as node
graphs and generates Vulkan GLSL for them. This tool generates the pixel shader of `open_pbr_surface` and of
`gltf_pbr` under one directional light with no environment, turns it into a compute shader (its uniforms become
globals each invocation sets from a case), compiles it with glslangValidator, runs it on the Vulkan device (lavapipe)
through build/release/raylab_spirv_batch, and compares the radiance it returns, f cos(theta_i) for a light of
irradiance 1, with raylab's f (raylab.brdf.eval) times cos(theta_i), on a grid of directions for each material of
the table below (coat, fuzz, thin film, metal tint, anisotropy, ...). Prints a Markdown table (docs/brdfs.md,
"Against MaterialX"); --json writes the rows.

  .venv/bin/python tools/materialx_compare.py [--raylab-build build/release] [--json out/materialx.json]
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

try:
    import MaterialX as mx
    from MaterialX import PyMaterialXGenGlsl as mx_glsl
    from MaterialX import PyMaterialXGenShader as mx_gen
except ImportError:
    sys.exit("materialx_compare: MaterialX is not installed; run tools/setup.sh (it installs tools/requirements.txt "
             "into .venv) or .venv/bin/pip install -r tools/requirements.txt")

import raylab

WORKGROUP = 64
CASE_HEADER = 6  # wi, wo

# Each row: a label, MaterialX's node and its parameters, and raylab's model and parameters: the same names and values
# where raylab implements the node itself (openpbr is OpenPBR's names in both, gltf_pbr glTF's), else the mapping
# raylab's glTF reader makes (docs/gltf.md: KHR_materials_clearcoat and _sheen onto openpbr). `bound`: what --check
# holds it to, ("shape", median, p90) of the relative difference where they agree, or ("energy", tolerance) on the
# ratio of the sums where the lobes are known to differ in shape, or where MaterialX is wrong (a film over a metal
# below the Airy minimum): docs/brdfs.md, "Against MaterialX", says which and why.
def row(label, node, params, bound, raylab_model=None, raylab_params=None):
    model = raylab_model or {"open_pbr_surface": "openpbr", "gltf_pbr": "gltf_pbr"}[node]
    return {"label": label, "node": node, "params": params, "bound": bound, "model": model,
            "raylab_params": raylab_params if raylab_params is not None else params}


# glTF's defaults differ from raylab's gltf_pbr table (metallic 1 and roughness 1 against 0 and 0.5): all given.
GLTF_BASE = {"base_color": (0.8, 0.3, 0.2), "metallic": 0.0, "roughness": 0.4}
OPENPBR_OF_GLTF_BASE = {"base_color": (0.8, 0.3, 0.2), "base_metalness": 0.0, "specular_roughness": 0.4}
MATERIALS = [
    row("dielectric", "open_pbr_surface", {"base_color": (0.8, 0.3, 0.2), "specular_roughness": 0.3}, ("shape", 0.01, 0.03)),
    row("rough dielectric", "open_pbr_surface", {"base_color": (0.2, 0.5, 0.8), "specular_roughness": 0.7},
        ("shape", 0.01, 0.03)),
    row("coat", "open_pbr_surface", {"base_color": (0.8, 0.3, 0.2), "specular_roughness": 0.4, "coat_weight": 1.0,
                                     "coat_roughness": 0.1}, ("shape", 0.05, 0.07)),
    row("coat, tinted, darkening", "open_pbr_surface", {"base_color": (0.6, 0.6, 0.6), "coat_weight": 1.0,
                                                        "coat_roughness": 0.3, "coat_color": (0.9, 0.7, 0.5),
                                                        "coat_darkening": 1.0}, ("shape", 0.07, 0.11)),
    row("fuzz", "open_pbr_surface", {"base_color": (0.3, 0.1, 0.1), "fuzz_weight": 1.0, "fuzz_color": (0.9, 0.9, 0.9),
                                     "fuzz_roughness": 0.5}, ("shape", 0.03, 0.06)),
    # The film's index differs from the base's 1.5: a film of the substrate's own index has no lower interface.
    row("thin film on a dielectric", "open_pbr_surface", {"base_color": (0.5, 0.5, 0.5), "specular_roughness": 0.3,
                                                          "thin_film_weight": 1.0, "thin_film_thickness": 0.5,
                                                          "thin_film_ior": 1.8}, ("shape", 0.06, 0.08)),
    row("thin film on a metal", "open_pbr_surface", {"base_metalness": 1.0, "base_color": (0.9, 0.9, 0.9),
                                                     "specular_roughness": 0.3, "thin_film_weight": 1.0,
                                                     "thin_film_thickness": 0.5, "thin_film_ior": 1.8},
        ("energy", 0.5)),
    row("metal", "open_pbr_surface", {"base_metalness": 1.0, "base_color": (0.9, 0.9, 0.9), "specular_roughness": 0.3},
        ("energy", 0.05)),
    row("rough metal", "open_pbr_surface", {"base_metalness": 1.0, "base_color": (0.9, 0.9, 0.9),
                                            "specular_roughness": 0.6}, ("energy", 0.08)),
    row("metal, F82 tint", "open_pbr_surface", {"base_metalness": 1.0, "base_color": (0.95, 0.64, 0.54),
                                                "specular_color": (0.95, 0.8, 0.75), "specular_roughness": 0.3},
        ("energy", 0.05)),
    row("anisotropic metal", "open_pbr_surface", {"base_metalness": 1.0, "base_color": (0.9, 0.9, 0.9),
                                                  "specular_roughness": 0.4, "specular_roughness_anisotropy": 0.6},
        ("energy", 0.1)),
    row("diffuse roughness 1", "open_pbr_surface", {"base_color": (0.8, 0.8, 0.8), "specular_weight": 0.0,
                                                    "base_diffuse_roughness": 1.0}, ("energy", 0.03)),
    row("gltf_pbr dielectric", "gltf_pbr", {"base_color": (0.8, 0.3, 0.2), "metallic": 0.0, "roughness": 0.5},
        ("shape", 0.01, 0.08)),
    row("gltf_pbr dielectric, ior 1.8", "gltf_pbr", {"base_color": (0.2, 0.6, 0.3), "metallic": 0.0, "roughness": 0.3,
                                                     "ior": 1.8}, ("shape", 0.01, 0.18)),
    row("gltf_pbr metal", "gltf_pbr", {"base_color": (0.95, 0.64, 0.54), "metallic": 1.0, "roughness": 0.3},
        ("shape", 0.02, 0.05)),
    row("glTF clearcoat, as raylab maps it", "gltf_pbr", dict(GLTF_BASE, clearcoat=1.0, clearcoat_roughness=0.1),
        ("shape", 0.1, 0.3), "openpbr",
        dict(OPENPBR_OF_GLTF_BASE, coat_weight=1.0, coat_roughness=0.1, coat_ior=1.5, coat_darkening=0.0)),
    row("glTF sheen, as raylab maps it", "gltf_pbr", dict(GLTF_BASE, sheen_color=(0.8, 0.8, 0.8), sheen_roughness=0.5),
        ("shape", 0.1, 0.3), "openpbr",
        dict(OPENPBR_OF_GLTF_BASE, fuzz_weight=0.8, fuzz_color=(1.0, 1.0, 1.0), fuzz_roughness=0.5)),
]


def library():
    lib = mx.createDocument()
    search = mx.getDefaultDataSearchPath()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), search, lib)
    return lib, search


def generate(node_name):
    """The pixel shader of NODE under one directional light and no environment, and its public inputs in order."""
    lib, search = library()
    doc = mx.createDocument()
    doc.importLibrary(lib)
    node = doc.addNode(node_name, "surface", "surfaceshader")
    doc.addMaterialNode("surface_material", node)
    generator = mx_glsl.VkShaderGenerator.create()
    context = mx_gen.GenContext(generator)
    context.registerSourceCodeSearchPath(search)
    options = context.getOptions()
    options.hwSpecularEnvironmentMethod = mx_gen.HwSpecularEnvironmentMethod.SPECULAR_ENVIRONMENT_NONE
    options.hwMaxActiveLightSources = 1
    options.hwShadowMap = False
    mx_gen.HwShaderGenerator.bindLightShader(doc.getNodeDef("ND_directional_light"), 1, context)
    shader = generator.generate("surface_material", node, context)
    source = shader.getSourceCode(mx_gen.PIXEL_STAGE)
    block = re.search(r"uniform PublicUniforms_pixel\s*\{(.*?)\};", source, re.S)
    inputs = re.findall(r"^\s*(float|vec3|bool|int)\s+(\w+);", block.group(1), re.M) if block else []
    defaults = {i.getName(): i.getValue() for i in node.getNodeDef().getActiveInputs()}
    return source, inputs, defaults


def to_compute(source, inputs):
    """The pixel shader as a compute shader: uniform blocks and vertex data become globals set per case."""
    text = source.replace("#pragma shader_stage(fragment)", "")
    text = re.sub(r"layout \(std140, binding=\d+\) uniform \w+\s*\{(.*?)\};", r"\1", text, flags=re.S)
    text = re.sub(r"layout \(location = 0\) in VertexData\s*\{(.*?)\} vd;", r"struct VertexData {\1};\nVertexData vd;",
                  text, flags=re.S)
    text = text.replace("layout (location = 0) out vec4 out1;", "vec4 out1;")
    text = re.sub(r"\bvoid main\(\)", "void mx_main()", text)
    header = "#version 450\nlayout(local_size_x = %d) in;" % WORKGROUP
    # Read by the refraction of the environment, which is off; the generator leaves it undeclared then.
    if "u_refractionTwoSided" in text and not re.search(r"\bbool\s+u_refractionTwoSided\b", text):
        header += "\nconst bool u_refractionTwoSided = false;"
    # Screen-space derivatives (its subsurface approximation's curvature) do not exist in a compute shader: a flat
    # surface's are zero. Subsurface is not in the table.
    header += "\n#define fwidth(x) (0.0 * (x))"
    text = text.replace("#version 450", header, 1)
    stride = CASE_HEADER + sum(3 if kind == "vec3" else 1 for kind, _ in inputs)
    lines = ["layout(std430, binding = 0) readonly buffer Cases { float cases[]; };",
             "layout(std430, binding = 1) writeonly buffer Values { vec4 values[]; };",
             "layout(push_constant) uniform Push { uint caseCount; };",
             "void main() {",
             "  const uint i = gl_GlobalInvocationID.x;",
             "  if (i >= caseCount) return;",
             "  const uint b = i * %du;" % stride,
             "  const vec3 wi = vec3(cases[b], cases[b + 1u], cases[b + 2u]);",
             "  const vec3 wo = vec3(cases[b + 3u], cases[b + 4u], cases[b + 5u]);"]
    offset = CASE_HEADER
    for kind, name in inputs:
        if kind == "vec3":
            lines.append("  %s = vec3(cases[b + %du], cases[b + %du], cases[b + %du]);" % (name, offset, offset + 1, offset + 2))
            offset += 3
        elif kind == "bool":
            lines.append("  %s = cases[b + %du] > 0.5;" % (name, offset))
            offset += 1
        elif kind == "int":
            lines.append("  %s = int(cases[b + %du]);" % (name, offset))
            offset += 1
        else:
            lines.append("  %s = cases[b + %du];" % (name, offset))
            offset += 1
    lines += ["  vd.normalWorld = vec3(0.0, 0.0, 1.0);",
              "  vd.tangentWorld = vec3(1.0, 0.0, 0.0);",
              "  vd.positionWorld = vec3(0.0);",
              "  u_viewPosition = wo;  // V = normalize(u_viewPosition - positionWorld)",
              "  u_numActiveLightSources = 1;",
              "  u_lightData[0].direction = -wi;  // the direction the light travels",
              "  u_lightData[0].color = vec3(1.0);",
              "  u_lightData[0].intensity = 1.0;",
              "  u_lightData[0].type = 1;",
              "  mx_main();",
              "  values[i] = out1;",
              "}"]
    return text + "\n" + "\n".join(lines) + "\n", stride


def directions():
    """Pairs (wi, wo) over the upper hemisphere: elevations 0-75 degrees, relative azimuths 0-180, two wo azimuths."""
    pairs = []
    for ti in (0, 20, 40, 60, 75):
        for to in (0, 20, 40, 60, 75):
            for dphi in (0, 60, 120, 180):
                for phi_o in (0, 45):  # 45: off the anisotropic axes
                    if (ti == 0 or to == 0) and dphi != 0:
                        continue
                    a, b = math.radians(ti), math.radians(to)
                    po, pi_ = math.radians(phi_o), math.radians(phi_o + dphi)
                    pairs.append(((math.sin(a) * math.cos(pi_), math.sin(a) * math.sin(pi_), math.cos(a)),
                                  (math.sin(b) * math.cos(po), math.sin(b) * math.sin(po), math.cos(b))))
    return pairs


def value_of(setting, default):
    """A parameter's floats: the row's value, else MaterialX's default (a tuple, or MaterialX's Color3 / Vector3)."""
    if setting is None:
        setting = default
    if setting is None:  # gltf_pbr's attenuation_distance: no default, meaning no attenuation
        setting = 1e30
    if hasattr(setting, "__len__") and not isinstance(setting, str):
        return [float(x) for x in setting]
    if isinstance(setting, bool):
        return [1.0 if setting else 0.0]
    return [float(setting)]


def run_materialx(node_name, materials, pairs, spirv_batch, work):
    source, inputs, defaults = generate(node_name)
    compute, stride = to_compute(source, inputs)
    glsl = os.path.join(work, node_name + ".comp")
    spv = os.path.join(work, node_name + ".spv")
    with open(glsl, "w") as f:
        f.write(compute)
    compiled = subprocess.run(["glslangValidator", "--target-env", "vulkan1.2", "-S", "comp", "-o", spv, glsl],
                              capture_output=True, text=True)
    if compiled.returncode != 0:
        sys.exit(f"materialx_compare: MaterialX's {node_name} did not compile as a compute shader:\n{compiled.stdout}")
    rows = []
    for _, params in materials:
        for wi, wo in pairs:
            row = list(wi) + list(wo)
            for kind, name in inputs:
                values = value_of(params.get(name), defaults.get(name))
                if kind == "vec3" and len(values) == 1:
                    values = values * 3
                row += values[:3] if kind == "vec3" else values[:1]
            assert len(row) == stride, (len(row), stride)
            rows.append(row)
    cases = os.path.join(work, node_name + ".cases")
    out = os.path.join(work, node_name + ".values")
    np.asarray(rows, dtype=np.float32).tofile(cases)
    subprocess.run([spirv_batch, spv, cases, out, str(stride), "4"], check=True)
    return np.fromfile(out, dtype=np.float32).reshape(-1, 4)[:, :3].astype(np.float64)


def raylab_params(params):
    return {k: (tuple(v) if isinstance(v, (tuple, list)) else v) for k, v in params.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("--raylab-build", default="build/release", help="where raylab_spirv_batch was built")
    parser.add_argument("--json", help="write the rows here too")
    parser.add_argument("--check", action="store_true", help="exit 1 when a row is outside what it is held to")
    args = parser.parse_args()
    spirv_batch = os.path.join(args.raylab_build, "raylab_spirv_batch")
    if not os.access(spirv_batch, os.X_OK):
        sys.exit(f"materialx_compare: {spirv_batch} is missing: build raylab first (tools/setup.sh)")
    pairs = directions()
    wi = np.array([p[0] for p in pairs], dtype=np.float32)
    wo = np.array([p[1] for p in pairs], dtype=np.float32)
    cos_i = wi[:, 2].astype(np.float64)
    results = []
    with tempfile.TemporaryDirectory(prefix="materialx_compare_") as work:
        for node_name in ("open_pbr_surface", "gltf_pbr"):
            chosen = [m for m in MATERIALS if m["node"] == node_name]
            theirs = run_materialx(node_name, [(m["label"], m["params"]) for m in chosen], pairs, spirv_batch, work)
            for material, values in zip(chosen, theirs.reshape(len(chosen), len(pairs), 3)):
                ours = raylab.brdf.eval(material["model"], raylab_params(material["raylab_params"]), wi=wi, wo=wo)
                ours = ours * cos_i[:, None]
                luminance = np.array([0.2126, 0.7152, 0.0722])
                a, b = ours @ luminance, values @ luminance
                significant = np.maximum(a, b) > 1e-3
                rel = np.abs(a - b)[significant] / np.maximum(a, b)[significant]
                result = {"material": material["label"], "model": material["model"], "pairs": int(significant.sum()),
                          "median_relative": float(np.median(rel)), "p90_relative": float(np.percentile(rel, 90)),
                          "max_relative": float(np.max(rel)), "materialx_over_raylab": float(np.sum(b) / np.sum(a)),
                          "bound": list(material["bound"])}
                bound = material["bound"]
                if bound[0] == "shape":
                    result["holds"] = result["median_relative"] <= bound[1] and result["p90_relative"] <= bound[2]
                else:
                    result["holds"] = abs(result["materialx_over_raylab"] - 1.0) <= bound[1]
                results.append(result)
    print("| material | raylab model | direction pairs | median rel. difference | 90th percentile | max | "
          "MaterialX / raylab (sum) | held to |")
    print("|---|---|---|---|---|---|---|---|")
    for r in results:
        bound = r["bound"]
        held = (f"median ≤ {bound[1]:g}, p90 ≤ {bound[2]:g}" if bound[0] == "shape" else f"sum within {bound[1]:g}")
        print(f"| {r['material']} | `{r['model']}` | {r['pairs']} | {r['median_relative']:.3f} | {r['p90_relative']:.3f} | "
              f"{r['max_relative']:.3f} | {r['materialx_over_raylab']:.3f} | {held}{'' if r['holds'] else ' **FAILS**'} |")
    if args.json:
        with open(args.json + ".tmp", "w") as f:
            json.dump(results, f, indent=1)
        os.replace(args.json + ".tmp", args.json)
    failed = [r["material"] for r in results if not r["holds"]]
    if args.check and failed:
        sys.exit("materialx_compare: outside their bounds: " + ", ".join(failed))


if __name__ == "__main__":
    main()
