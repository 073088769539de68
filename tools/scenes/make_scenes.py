#!/usr/bin/env python3
"""Writes raylab's committed glTF scenes (assets/scenes/*.gltf): one parameter sweep per figure of the
original slides, a showcase of every model, a Cornell-style box and the minimal example of docs/scenes.md.

    python3 tools/scenes/make_scenes.py [OUTPUT_DIR] [--raylab BINARY]
        OUTPUT_DIR  default: assets/scenes of this repository
        BINARY      default: build/release/raylab (build it first: cmake --preset release && cmake --build ...)
    python3 tools/scenes/make_scenes.py --gallery docs/images/gallery [--raylab BINARY]
        renders the sweeps' contact sheets for docs/gallery.md instead (about 90 s on lavapipe, 2 cores)

Python 3 standard library only; the output is deterministic, so regenerating an unchanged scene gives an
identical file. The conventions (extras.raylab materials and spheres, lights in W/sr) are docs/scenes.md's.

Sweeps: raylab lays them out (`raylab sweep --gltf`, the layout of its contact sheets, docs/gallery.md): eight
spheres in a row along +x, the swept parameter growing from left to right, a telephoto camera and a distant
light from the upper front left. Each sweep's scene carries extras.sweep: raylab's model, parameter, values and
title, and from this script the command, and the statistic of each sphere's image that
tests/scene/scene_render_test.cpp checks along the row, its trend and the physical reason.
"""

import argparse
import base64
import functools
import json
import math
import os
import struct
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import raylab_tools  # noqa: E402 (standard library only, as this script)

FLOAT = 5126
UNSIGNED_SHORT = 5123
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963

# --------------------------------------------------------------------------------------------- vector maths


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def add(a, b):
    return [a[i] + b[i] for i in range(3)]


def scale(a, s):
    return [x * s for x in a]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalize(a):
    length = math.sqrt(dot(a, a))
    return [x / length for x in a]


def look_rotation(forward, up):
    """The unit quaternion [x, y, z, w] turning -Z to `forward` and +Y towards `up` (glTF camera and light
    nodes look down their -Z axis)."""
    z = normalize(scale(forward, -1.0))
    x = normalize(cross(up, z))
    y = cross(z, x)
    m = [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]  # rows; columns are the axes
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s]
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = 2.0 * math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2])
        q = [0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s]
    elif m[1][1] > m[2][2]:
        s = 2.0 * math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2])
        q = [(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s]
    else:
        s = 2.0 * math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1])
        q = [(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s]
    return normalize4(q)


def normalize4(q):
    length = math.sqrt(sum(x * x for x in q))
    return [x / length for x in q]


def rounded(values, digits=6):
    """Short, stable numbers in the JSON."""
    return [round(v, digits) + 0.0 for v in values]


# ----------------------------------------------------------------------------------------------- the writer


# Each model's look (its GLSL header's `look:` line, raylab_tools.look_material), read by main.
LOOKS = {}
# Each named metal's reflectance at normal incidence, from its eta and k (`raylab brdf models --json`, read by main):
# the base colour glTF's metallic workflow gives a metal.
METAL_F0 = {}


@functools.lru_cache(maxsize=None)
def registry(raylab):
    """The BRDF model registry as `raylab brdf models --json` prints it."""
    return json.loads(subprocess.run([raylab, "brdf", "models", "--json"], check=True, capture_output=True,
                                     text=True).stdout)


def metal_presets(raylab):
    """{name: F0 RGB} of ggx_conductor's named metals, as the raylab binary declares them."""
    conductor = next(model for model in registry(raylab) if model["name"] == "ggx_conductor")
    return {preset["name"]: [((n - 1) ** 2 + k * k) / ((n + 1) ** 2 + k * k)
                             for n, k in zip(preset["values"]["eta"], preset["values"]["k"])]
            for preset in conductor["presets"] if preset["key"] == "metal"}


def fallback_pbr(raylab, preview):
    """glTF's own pbrMetallicRoughness for viewers that do not read extras.raylab: a named metal is metallic with
    its F0 as base colour, GGX models keep their roughness (glTF's alpha is roughness squared), glTF's BRDF its own
    values, and diffuse models are rough dielectrics in the preview colour."""
    model = raylab["model"]
    base, metallic, roughness = list(preview), 0.0, 0.5
    if model == "gltf_pbr":
        base, metallic, roughness = raylab["base_color"], raylab["metallic"], raylab["roughness"]
    elif model in ("ggx_conductor", "ggx_dielectric"):
        roughness = math.sqrt(math.sqrt(raylab["alpha_x"] * raylab["alpha_y"]))
        if model == "ggx_conductor":
            metallic = 1.0
            if "metal" in raylab:
                base = METAL_F0[raylab["metal"]]
    elif model in ("lambert", "oren_nayar", "eon"):
        roughness = 1.0
    elif model == "openpbr":
        base = raylab.get("base_color", base)
        metallic, roughness = raylab.get("base_metalness", 0.0), raylab.get("specular_roughness", 0.3)
    return {"baseColorFactor": rounded(list(base)) + [1.0], "metallicFactor": metallic,
            "roughnessFactor": rounded([roughness])[0]}


class Gltf:
    """A glTF 2.0 document under construction, with one binary buffer written as a data URI."""

    def __init__(self, name):
        self.name = name
        self.doc = {
            "asset": {"version": "2.0", "generator": "raylab tools/scenes/make_scenes.py"},
            "extensionsUsed": ["KHR_lights_punctual"],
            "scene": 0,
            "scenes": [{"name": name, "nodes": []}],
            "nodes": [],
            "meshes": [],
            "materials": [],
            "cameras": [],
            "accessors": [],
            "bufferViews": [],
            "buffers": [],
            "extensions": {"KHR_lights_punctual": {"lights": []}},
        }
        self.data = bytearray()
        self.stand_in = None  # accessors of the shared low-poly sphere

    def _view(self, payload, target):
        while len(self.data) % 4:
            self.data.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload),
                                        "target": target})
        self.data.extend(payload)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, values, kind):
        if kind == "SCALAR":
            payload = struct.pack("<%dH" % len(values), *values)
            view = self._view(payload, ELEMENT_ARRAY_BUFFER)
            accessor = {"bufferView": view, "componentType": UNSIGNED_SHORT, "count": len(values), "type": "SCALAR"}
        else:
            flat = [float(x) for v in values for x in v]
            view = self._view(struct.pack("<%df" % len(flat), *flat), ARRAY_BUFFER)
            accessor = {"bufferView": view, "componentType": FLOAT, "count": len(values), "type": kind}
            if kind == "VEC3":  # POSITION needs bounds
                accessor["min"] = rounded([min(v[i] for v in values) for i in range(3)])
                accessor["max"] = rounded([max(v[i] for v in values) for i in range(3)])
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def mesh(self, name, positions, indices, material, normals=None):
        attributes = {"POSITION": self.accessor(positions, "VEC3")}
        if normals is not None:
            attributes["NORMAL"] = self.accessor(normals, "VEC3")
        primitive = {"attributes": attributes, "indices": self.accessor(indices, "SCALAR"), "material": material}
        self.doc["meshes"].append({"name": name, "primitives": [primitive]})
        return len(self.doc["meshes"]) - 1

    def node(self, node):
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)
        return len(self.doc["nodes"]) - 1

    def material(self, name, raylab, preview=None):
        """A material whose raylab model is `raylab`; `preview` is the base colour other viewers show, with the
        metalness and roughness closest to the model's (fallback_pbr)."""
        material = {"name": name}
        if preview is not None:
            material["pbrMetallicRoughness"] = fallback_pbr(raylab, preview)
        material["extras"] = {"raylab": raylab}
        self.doc["materials"].append(material)
        return len(self.doc["materials"]) - 1

    def sphere(self, name, center, radius, material):
        """An exact raylab sphere; its node also carries a unit low-poly sphere for other glTF viewers."""
        if self.stand_in is None:
            positions, indices = uv_sphere(8, 12)
            self.stand_in = (self.accessor(positions, "VEC3"), self.accessor(indices, "SCALAR"))
        position, index = self.stand_in
        self.doc["meshes"].append({"name": name + " stand-in", "primitives": [
            {"attributes": {"POSITION": position, "NORMAL": position}, "indices": index, "material": material}]})
        return self.node({"name": name, "translation": rounded(center), "scale": [radius] * 3,
                          "mesh": len(self.doc["meshes"]) - 1,
                          "extras": {"raylab": {"sphere": {"radius": 1.0, "material": material}}}})

    def camera(self, name, position, target, yfov_degrees, up=(0.0, 1.0, 0.0)):
        self.doc["cameras"].append({"name": name, "type": "perspective",
                                    "perspective": {"yfov": round(math.radians(yfov_degrees), 6), "znear": 0.05}})
        return self.node({"name": name + " node", "camera": len(self.doc["cameras"]) - 1,
                          "translation": rounded(position),
                          "rotation": rounded(look_rotation(sub(target, position), list(up)))})

    def point_light(self, name, position, intensity, color=(1.0, 1.0, 1.0)):
        """A KHR_lights_punctual point light; `intensity` in W/sr (docs/scenes.md)."""
        lights = self.doc["extensions"]["KHR_lights_punctual"]["lights"]
        lights.append({"name": name, "type": "point", "color": rounded(list(color)), "intensity": round(intensity, 3)})
        return self.node({"name": name, "translation": rounded(position),
                          "extensions": {"KHR_lights_punctual": {"light": len(lights) - 1}}})

    def background(self, rgb):
        self.doc["scenes"][0].setdefault("extras", {})["raylab"] = {"background": rounded(list(rgb))}

    def environment(self, uri, strength=1.0):
        """Lights the scene with an equirectangular EXR beside it (docs/integrators.md)."""
        self.doc["extras"] = {"raylab": {"environment": {"uri": uri, "strength": strength}}}

    def write(self, directory):
        doc = dict(self.doc)
        if self.data:
            uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.data)).decode("ascii")
            doc["buffers"] = [{"byteLength": len(self.data), "uri": uri}]
        for key in ["cameras", "materials", "meshes", "accessors", "bufferViews", "buffers"]:
            if not doc[key]:
                del doc[key]
        path = os.path.join(directory, self.name + ".gltf")
        with open(path, "w", encoding="ascii") as out:
            out.write(to_json(doc) + "\n")
        return path


def to_json(value, indent=""):
    """JSON with one property per line but short arrays of numbers on one line, so that diffs and the
    example in docs/scenes.md stay readable."""
    inner = indent + "  "
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = ",\n".join(inner + json.dumps(key) + ": " + to_json(item, inner) for key, item in value.items())
        return "{\n" + items + "\n" + indent + "}"
    if isinstance(value, list):
        if all(not isinstance(item, (dict, list)) for item in value):
            return "[" + ", ".join(json.dumps(item) for item in value) + "]"
        return "[\n" + ",\n".join(inner + to_json(item, inner) for item in value) + "\n" + indent + "]"
    return json.dumps(value)


# ------------------------------------------------------------------------------------------------ geometry


def uv_sphere(rings, segments):
    """A unit sphere: positions double as normals."""
    positions = []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            positions.append(rounded([math.sin(theta) * math.sin(phi), math.cos(theta),
                                      math.sin(theta) * math.cos(phi)], 5))
    indices = []
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            if r > 0:
                indices += [a, b, a + 1]
            if r < rings - 1:
                indices += [a + 1, b, b + 1]
    return positions, indices


def quad(corner, edge_u, edge_v):
    """Two triangles over the parallelogram corner + [0,1] edge_u + [0,1] edge_v, facing edge_u x edge_v."""
    positions = [corner, add(corner, edge_u), add(add(corner, edge_u), edge_v), add(corner, edge_v)]
    return positions, [0, 1, 2, 0, 2, 3]


def add_quad(gltf, name, corner, edge_u, edge_v, material):
    positions, indices = quad(corner, edge_u, edge_v)
    normal = normalize(cross(edge_u, edge_v))
    mesh = gltf.mesh(name, positions, indices, material, normals=[normal] * 4)
    return gltf.node({"name": name, "mesh": mesh})


def add_checker(gltf, name, x_range, z_range, height, tile, materials):
    """A checkerboard in the plane y = height as two meshes (one per colour) over one shared grid of
    vertices, so that no texture is needed."""
    columns = round((x_range[1] - x_range[0]) / tile)
    rows = round((z_range[1] - z_range[0]) / tile)
    grid = [[x_range[0] + i * tile, height, z_range[0] + k * tile] for k in range(rows + 1) for i in range(columns + 1)]
    position = gltf.accessor(grid, "VEC3")
    for parity, material in enumerate(materials):
        indices = []
        for k in range(rows):
            for i in range(columns):
                if (i + k) % 2 != parity:
                    continue
                a = k * (columns + 1) + i  # (x0, z0); counter-clockwise seen from +y
                b = a + columns + 1        # (x0, z0 + tile)
                indices += [a, b, b + 1, a, b + 1, a + 1]
        primitive = {"attributes": {"POSITION": position}, "indices": gltf.accessor(indices, "SCALAR"),
                     "material": material}
        gltf.doc["meshes"].append({"name": "%s %d" % (name, parity), "primitives": [primitive]})
        gltf.node({"name": "%s %d" % (name, parity), "mesh": len(gltf.doc["meshes"]) - 1})


# ----------------------------------------------------------------------------------------------- the sweeps

# The sweeps are the `// sweep scene:` lines of the models' GLSL headers (docs/extending.md), laid out by raylab
# itself (engine/scene/sweep_scene.cpp, the layout of `raylab sweep`'s contact sheets): this script runs
# `raylab sweep ... --gltf` and adds to the scene's extras.sweep the command and what
# tests/scene/scene_render_test.cpp checks along the row: a statistic of each sphere's image and how it must change
# from left to right (the line's statistic and trend), with the physical reason (its `sweep why:` lines).
#   mean            mean radiance over the sphere's projected disc (its anti-aliased rim left out)
#   highlight_area  the number of the disc's pixels brighter than half the disc's brightest: the size of the
#                   highlight at half its maximum

def sweeps(raylab):
    """(name, raylab sweep arguments, statistic, trend, why) of every `// sweep scene:` line of the registered models'
    GLSL headers (docs/extending.md), in the registry's order."""
    result = []
    for model in registry(raylab):
        if model["glsl"].startswith("tests/"):
            continue
        for sweep in raylab_tools.model_notes(model)["sweep_scenes"]:
            arguments = ["--model", model["name"], "--param", sweep["param"], "--from", sweep["start"],
                         "--to", sweep["stop"]] + (["--log"] if sweep["log"] else [])
            for value in sweep["set"]:
                arguments += ["--set", value]
            result.append(("sweep_%s_%s" % (model["name"], sweep["param"]), arguments, sweep["statistic"],
                           sweep["trend"], sweep["why"]))
    return result


def sweep_scene(raylab, name, arguments, statistic, trend, why):
    """The scene `raylab sweep ARGUMENTS --gltf` writes, with the test's expectation in extras.sweep."""
    with tempfile.TemporaryDirectory() as scratch:
        path = os.path.join(scratch, name + ".gltf")
        subprocess.run([raylab, "sweep"] + arguments + ["--gltf", path], check=True, stdout=subprocess.DEVNULL)
        with open(path, encoding="utf-8") as file:
            doc = json.load(file)
    if doc["scenes"][0]["name"] != name:
        sys.exit("make_scenes.py: %s: raylab named the scene %s" % (name, doc["scenes"][0]["name"]))
    doc["asset"]["generator"] = "raylab sweep, through tools/scenes/make_scenes.py"
    doc["scenes"][0]["extras"]["sweep"].update({
        "command": "raylab sweep " + " ".join(arguments),
        "statistic": statistic, "trend": trend, "why": why})
    return Document(name, doc)


def gallery_figure(raylab, name, arguments, directory):
    """docs/gallery.md's contact sheet of a sweep (the PNG only: the page shows no EXR)."""
    png = os.path.join(directory, name[len("sweep_"):] + ".png")
    subprocess.run([raylab, "sweep"] + arguments + ["--png", png], check=True, stdout=subprocess.DEVNULL)
    os.remove(png[:-len(".png")] + ".exr")
    return png


class Document:
    """A finished glTF document, written like the others."""

    def __init__(self, name, doc):
        self.name = name
        self.doc = doc

    def write(self, directory):
        path = os.path.join(directory, self.name + ".gltf")
        with open(path, "w", encoding="ascii") as out:
            out.write(to_json(self.doc) + "\n")
        return path


# ------------------------------------------------------------------------------------- showcase and others


def showcase():
    """Every model side by side on a checkerboard, under a warm key, a cool fill and a rim light."""
    g = Gltf("showcase")
    g.background((0.03, 0.035, 0.05))
    showcase_objects(g)
    g.point_light("key", [-5.0, 8.0, 6.0], 120.0, (1.0, 0.92, 0.8))
    g.point_light("fill", [7.0, 4.0, 5.0], 35.0, (0.7, 0.8, 1.0))
    g.point_light("rim", [2.0, 6.0, -8.0], 60.0, (1.0, 1.0, 1.0))
    return g


def showcase_hdri():
    """The showcase's spheres lit by a real HDR environment alone (Blender's CC0 studio-light worlds, copied
    beside the scenes by tools/setup.sh), so that `raylab render` picks the path integrator."""
    g = Gltf("showcase_hdri")
    showcase_objects(g)
    g.environment("environments/%s.exr" % SHOWCASE_HDRI)
    return g


def showcase_modern():
    """The second library under an HDR environment (the path integrator): the named metals and a brushed
    anisotropic one in the back row; rough glass at three roughnesses and Lambert, Oren-Nayar and EON side by side
    in the middle; a gltf_pbr metallic x roughness grid in front."""
    g = Gltf("showcase_modern")
    light = g.material("checker light", {"model": "lambert", "rho_d": [0.7, 0.7, 0.68]}, (0.7, 0.7, 0.68))
    dark = g.material("checker dark", {"model": "lambert", "rho_d": [0.18, 0.18, 0.2]}, (0.18, 0.18, 0.2))
    add_checker(g, "floor", (-10.0, 10.0), (-8.0, 8.0), 0.0, 1.0, (light, dark))
    radius = 0.5
    back = [(metal, {"model": "ggx_conductor", "metal": metal, "alpha_x": 0.12, "alpha_y": 0.12})
            for metal in ("Au", "Ag", "Cu", "Al", "Cr")]
    back.append(("brushed", {"model": "ggx_conductor", "metal": "Al", "alpha_x": 0.03, "alpha_y": 0.35}))
    for i, (name, params) in enumerate(back):
        g.sphere(name, [(i - 2.5) * 1.25, radius, -2.0], radius, g.material(name, params, (0.8, 0.8, 0.8)))
    middle = [("rough glass 0.02", {"model": "ggx_dielectric", "alpha_x": 0.02, "alpha_y": 0.02, "eta": 1.5}),
              ("rough glass 0.1", {"model": "ggx_dielectric", "alpha_x": 0.1, "alpha_y": 0.1, "eta": 1.5}),
              ("rough glass 0.3", {"model": "ggx_dielectric", "alpha_x": 0.3, "alpha_y": 0.3, "eta": 1.5}),
              ("lambert", {"model": "lambert", "rho_d": [0.8, 0.45, 0.3]}),
              ("oren_nayar", {"model": "oren_nayar", "rho_d": [0.8, 0.45, 0.3], "sigma": 1.0}),
              ("eon", {"model": "eon", "rho_d": [0.8, 0.45, 0.3], "r": 1.0})]
    for i, (name, params) in enumerate(middle):
        preview = params.get("rho_d", [0.9, 0.9, 0.9])
        g.sphere(name, [(i - 2.5) * 1.25, radius, -0.4], radius, g.material(name, params, preview))
    small = 0.3
    for row, metallic in enumerate((0.0, 0.5, 1.0)):
        for column, roughness in enumerate((0.1, 0.4, 0.8)):
            name = "gltf_pbr metallic %g roughness %g" % (metallic, roughness)
            params = {"model": "gltf_pbr", "base_color": [0.9, 0.6, 0.2], "metallic": metallic,
                      "roughness": roughness, "ior": 1.5}
            g.sphere(name, [(column - 1) * 0.8, small, 0.9 + 0.75 * row], small,
                     g.material(name, params, (0.9, 0.6, 0.2)))
    g.camera("camera", [0.0, 4.0, 8.0], [0.0, 0.2, -0.3], 36.0)
    # Half the sky's radiance: at full strength the sunlit floor and spheres clip (4.4% of the pixels) and the
    # orange-red diffuse spheres read as cream; at half, a diffuse sphere's lit side shows its albedo and only the
    # sun's reflections in the metals clip (0.7%).
    g.environment("environments/%s.exr" % SHOWCASE_HDRI, strength=0.5)
    return g


def showcase_layered():
    """openpbr's layers under the showcase's HDR environment (the path integrator), one idea per sphere: in the back
    row a coat over a metal, over a red diffuse base, a tinted coat and a coat without darkening; in the middle a
    velvet fuzz, a dusty fuzz, a thin film over a dark dielectric and over a metal; in front coloured glass with
    absorption inside, rough translucent glass, and a brushed (anisotropic) metal beside glTF's own BRDF for
    comparison."""
    g = Gltf("showcase_layered")
    light = g.material("checker light", {"model": "lambert", "rho_d": [0.7, 0.7, 0.68]}, (0.7, 0.7, 0.68))
    dark = g.material("checker dark", {"model": "lambert", "rho_d": [0.18, 0.18, 0.2]}, (0.18, 0.18, 0.2))
    add_checker(g, "floor", (-10.0, 10.0), (-8.0, 8.0), 0.0, 1.0, (light, dark))
    red = [0.7, 0.08, 0.06]
    gold = {"base_color": [0.95, 0.75, 0.35], "base_metalness": 1.0, "specular_color": [1.0, 0.85, 0.6]}
    rows = [
        (-2.0, [("coat over metal", dict(gold, specular_roughness=0.45, coat_weight=1.0, coat_roughness=0.03)),
                ("coat over diffuse", {"base_color": red, "specular_roughness": 0.5, "coat_weight": 1.0,
                                       "coat_roughness": 0.05}),
                ("tinted coat", {"base_color": [0.85, 0.85, 0.85], "specular_roughness": 0.4, "coat_weight": 1.0,
                                 "coat_color": [0.3, 0.55, 0.9], "coat_roughness": 0.1}),
                ("coat without darkening", {"base_color": red, "specular_roughness": 0.5, "coat_weight": 1.0,
                                            "coat_roughness": 0.05, "coat_darkening": 0.0})]),
        (-0.4, [("velvet fuzz", {"base_color": [0.25, 0.02, 0.06], "specular_roughness": 0.7, "fuzz_weight": 1.0,
                                 "fuzz_color": [1.0, 0.6, 0.7], "fuzz_roughness": 0.3}),
                ("dusty fuzz", {"base_color": [0.1, 0.1, 0.12], "specular_roughness": 0.2, "fuzz_weight": 0.8,
                                "fuzz_color": [0.85, 0.8, 0.7], "fuzz_roughness": 1.0}),
                ("thin film over dielectric", {"base_color": [0.03, 0.03, 0.04], "specular_roughness": 0.15,
                                               "thin_film_weight": 1.0, "thin_film_thickness": 0.35,
                                               "thin_film_ior": 2.0}),
                ("thin film over metal", dict(gold, specular_roughness=0.2, thin_film_weight=1.0,
                                              thin_film_thickness=0.3, thin_film_ior=1.8))]),
        (1.2, [("coloured glass", {"specular_roughness": 0.0, "transmission_weight": 1.0,
                                   "transmission_color": [0.25, 0.65, 0.9], "transmission_depth": 0.6}),
               ("rough translucent", {"specular_roughness": 0.35, "transmission_weight": 1.0,
                                      "transmission_color": [0.95, 0.6, 0.25], "transmission_depth": 1.0}),
               ("brushed metal", {"base_color": [0.9, 0.9, 0.92], "base_metalness": 1.0, "specular_roughness": 0.5,
                                  "specular_roughness_anisotropy": 0.85}),
               ("gltf_pbr", None)]),
    ]
    radius = 0.5
    for z, spheres in rows:
        for i, (name, params) in enumerate(spheres):
            if params is None:
                raylab = {"model": "gltf_pbr", "base_color": red, "metallic": 0.0, "roughness": 0.5, "ior": 1.5}
            else:
                raylab = dict({"model": "openpbr"}, **params)
            preview = raylab.get("base_color", [0.9, 0.9, 0.9])
            g.sphere(name, [(i - 1.5) * 1.3, radius, z], radius, g.material(name, raylab, preview))
    g.camera("camera", [0.0, 2.9, 5.6], [0.0, 0.35, -0.3], 38.0)
    g.environment("environments/%s.exr" % SHOWCASE_HDRI, strength=0.5)
    return g


# The world of showcase_hdri.gltf, from /usr/share/blender/datafiles/studiolights/world (Debian blender-data).
SHOWCASE_HDRI = "sunrise"


def showcase_objects(g):
    """Ten spheres, one per model plus glass and a mirror, in two staggered rows on a checkerboard floor."""
    light = g.material("checker light", {"model": "lambert", "rho_d": [0.7, 0.7, 0.68]}, (0.7, 0.7, 0.68))
    dark = g.material("checker dark", {"model": "lambert", "rho_d": [0.18, 0.18, 0.2]}, (0.18, 0.18, 0.2))
    add_checker(g, "floor", (-10.0, 10.0), (-8.0, 8.0), 0.0, 1.0, (light, dark))
    models = [(name, LOOKS[name]) for name in ("lambert", "phong", "blinnphong", "cooktorrance", "ward", "ward_duer",
                                                "ward_gmd", "ashikhmin_shirley", "glass")] + [
        ("mirror", {"model": "cooktorrance", "rho_d": [0.02, 0.02, 0.02], "rho_s": [1.0, 1.0, 1.0], "m": 0.05,
                    "eta": 10.0, "delta": 0.85}),
    ]
    radius = 0.55
    for i, (name, params) in enumerate(models):
        # Two staggered rows of five, so that each sphere of the back row shows between two of the front.
        row, column = divmod(i, 5)
        x = (column - 2) * 1.5 + (0.375 if row == 1 else -0.375)
        z = -1.1 if row == 0 else 1.1
        preview = params.get("rho_d", params.get("Rd", params.get("tint", [0.8, 0.8, 0.8])))
        g.sphere(name, [x, radius, z], radius, g.material(name, params, preview))
    g.camera("camera", [0.0, 4.2, 9.0], [0.0, 0.3, 0.0], 33.0)


def cornell_room(g):
    """The box of both Cornell scenes: x in [-w, w], y in [0, 2], z in [-1, 1], as wide as a 16:9 frame of its
    opening, every wall facing the inside, with a mirror and a glass sphere."""
    white = g.material("white", {"model": "lambert", "rho_d": [0.73, 0.73, 0.73]}, (0.73, 0.73, 0.73))
    red = g.material("red", {"model": "lambert", "rho_d": [0.63, 0.065, 0.05]}, (0.63, 0.065, 0.05))
    green = g.material("green", {"model": "lambert", "rho_d": [0.14, 0.45, 0.09]}, (0.14, 0.45, 0.09))
    mirror = g.material("mirror", {"model": "lambert", "rho_d": [0.9, 0.9, 0.9], "delta": 0.95}, (0.9, 0.9, 0.9))
    glass = g.material("glass", {"model": "glass", "eta": 1.5}, (0.95, 0.95, 1.0))
    w = 1.75
    add_quad(g, "floor", [-w, 0.0, 1.0], [2 * w, 0.0, 0.0], [0.0, 0.0, -2.0], white)
    add_quad(g, "ceiling", [-w, 2.0, -1.0], [2 * w, 0.0, 0.0], [0.0, 0.0, 2.0], white)
    add_quad(g, "back wall", [-w, 0.0, -1.0], [2 * w, 0.0, 0.0], [0.0, 2.0, 0.0], white)
    add_quad(g, "left wall", [-w, 0.0, 1.0], [0.0, 0.0, -2.0], [0.0, 2.0, 0.0], red)
    add_quad(g, "right wall", [w, 0.0, -1.0], [0.0, 0.0, 2.0], [0.0, 2.0, 0.0], green)
    g.sphere("mirror sphere", [-0.6, 0.45, -0.3], 0.45, mirror)
    g.sphere("glass sphere", [0.65, 0.45, 0.3], 0.45, glass)


def cornell_box():
    """A Cornell-style box (red left, green right, open towards the camera) with a mirror and a glass sphere
    under a point light below the ceiling."""
    g = Gltf("cornell_box")
    cornell_room(g)
    # The opening (z = 1) just fills the frame's height.
    g.camera("camera", [0.0, 1.0, 4.2], [0.0, 1.0, 0.0], 34.0)
    g.point_light("lamp", [0.0, 1.7, 0.2], 6.0, (1.0, 0.95, 0.85))
    return g


def cornell_box_area():
    """The Cornell box lit the way the original is: a quad light in the ceiling (glTF emissiveFactor x
    KHR_materials_emissive_strength), no punctual light, so `raylab render` picks the path integrator."""
    g = Gltf("cornell_box_area")
    cornell_room(g)
    lamp = g.material("lamp", {"model": "lambert", "rho_d": [0.0, 0.0, 0.0]}, (0.0, 0.0, 0.0))
    g.doc["materials"][lamp]["emissiveFactor"] = [1.0, 0.85, 0.6]
    g.doc["materials"][lamp]["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 12.0}}
    g.doc.setdefault("extensionsUsed", []).append("KHR_materials_emissive_strength")
    # Just below the ceiling, facing down (the counter-clockwise normal of u x v points to -y).
    add_quad(g, "light", [-0.45, 1.995, -0.35], [0.9, 0.0, 0.0], [0.0, 0.0, 0.7], lamp)
    g.camera("camera", [0.0, 1.0, 4.2], [0.0, 1.0, 0.0], 34.0)
    return g


def glossy_room():
    """A room lit only through a glossy ceiling: a lamp in a tray on the floor shines upwards, its walls hide it
    from the rest of the room, and the brushed-aluminium ceiling (GGX alpha 0.08) reflects its light down. Every
    surface the camera sees is lit by that reflection, a path that neither light sampling from the floor (the tray
    blocks it) nor BSDF sampling of the floor (a small glossy highlight) finds often: path guiding's test case
    (docs/integrators.md, "Path guiding")."""
    g = Gltf("glossy_room")
    white = g.material("white", {"model": "lambert", "rho_d": [0.73, 0.73, 0.73]}, (0.73, 0.73, 0.73))
    red = g.material("red", {"model": "lambert", "rho_d": [0.63, 0.065, 0.05]}, (0.63, 0.065, 0.05))
    green = g.material("green", {"model": "lambert", "rho_d": [0.14, 0.45, 0.09]}, (0.14, 0.45, 0.09))
    ceiling = g.material("glossy ceiling", {"model": "ggx_conductor", "alpha_x": 0.08, "alpha_y": 0.08,
                                            "metal": "Al"}, (0.9, 0.9, 0.9))
    tray = g.material("tray", {"model": "lambert", "rho_d": [0.2, 0.2, 0.2]}, (0.2, 0.2, 0.2))
    lamp = g.material("lamp", {"model": "lambert", "rho_d": [0.0, 0.0, 0.0]}, (0.0, 0.0, 0.0))
    g.doc["materials"][lamp]["emissiveFactor"] = [1.0, 0.9, 0.75]
    g.doc["materials"][lamp]["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 150.0}}
    g.doc.setdefault("extensionsUsed", []).append("KHR_materials_emissive_strength")
    w = 1.75
    add_quad(g, "floor", [-w, 0.0, 1.0], [2 * w, 0.0, 0.0], [0.0, 0.0, -2.0], white)
    add_quad(g, "ceiling", [-w, 2.0, -1.0], [2 * w, 0.0, 0.0], [0.0, 0.0, 2.0], ceiling)
    add_quad(g, "back wall", [-w, 0.0, -1.0], [2 * w, 0.0, 0.0], [0.0, 2.0, 0.0], white)
    add_quad(g, "left wall", [-w, 0.0, 1.0], [0.0, 0.0, -2.0], [0.0, 2.0, 0.0], red)
    add_quad(g, "right wall", [w, 0.0, -1.0], [0.0, 0.0, 2.0], [0.0, 2.0, 0.0], green)
    # The lamp faces up (u x v points to +y) inside a tray whose walls face out and in.
    x0, z0, size, height = 0.9, -0.7, 0.3, 0.12
    add_quad(g, "lamp", [x0, 0.02, z0 + size], [size, 0.0, 0.0], [0.0, 0.0, -size], lamp)
    for name, corner, edge in (("tray front", [x0, 0.0, z0 + size], [size, 0.0, 0.0]),
                               ("tray right", [x0 + size, 0.0, z0 + size], [0.0, 0.0, -size]),
                               ("tray back", [x0 + size, 0.0, z0], [-size, 0.0, 0.0]),
                               ("tray left", [x0, 0.0, z0], [0.0, 0.0, size])):
        add_quad(g, name + " outside", corner, edge, [0.0, height, 0.0], tray)
        add_quad(g, name + " inside", add(corner, [0.0, height, 0.0]), edge, [0.0, -height, 0.0], tray)
    g.sphere("sphere", [-0.5, 0.4, 0.0], 0.4, white)
    g.camera("camera", [0.0, 1.0, 4.2], [0.0, 1.0, 0.0], 34.0)
    return g


def minimal():
    """The example of docs/scenes.md: a ground square, one sphere, one light, one camera."""
    g = Gltf("minimal")
    g.background((0.25, 0.3, 0.4))
    ground = g.material("ground", {"model": "lambert", "rho_d": [0.5, 0.5, 0.5]})
    red = g.material("red plastic", {"model": "cooktorrance", "rho_d": [0.6, 0.1, 0.1], "rho_s": [1.0, 1.0, 1.0],
                                     "m": 0.2, "eta": 1.5})
    positions, indices = quad([-3.0, 0.0, 3.0], [6.0, 0.0, 0.0], [0.0, 0.0, -6.0])
    g.node({"name": "ground", "mesh": g.mesh("ground", positions, indices, ground)})
    g.node({"name": "ball", "translation": [0.0, 1.0, 0.0],
            "extras": {"raylab": {"sphere": {"radius": 1.0, "material": red}}}})
    g.camera("camera", [0.0, 2.0, 6.0], [0.0, 0.8, 0.0], 40.0)
    g.point_light("lamp", [-3.0, 5.0, 4.0], 80.0)
    return g


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.normpath(os.path.join(here, "..", ".."))
    parser = argparse.ArgumentParser(description="Writes raylab's committed glTF scenes, or the gallery's figures.")
    parser.add_argument("directory", nargs="?", default=os.path.join(root, "assets", "scenes"),
                        help="output directory of the scenes (default: assets/scenes)")
    parser.add_argument("--raylab", default=os.path.join(root, "build", "release", "raylab"),
                        help="the raylab binary that lays out the sweeps (default: build/release/raylab)")
    parser.add_argument("--gallery", metavar="DIRECTORY",
                        help="instead of the scenes, render each sweep's contact sheet into DIRECTORY "
                             "(docs/images/gallery for docs/gallery.md)")
    options = parser.parse_args()
    if not os.access(options.raylab, os.X_OK):
        sys.exit("make_scenes.py: %s is not an executable: build raylab first, or give --raylab" % options.raylab)
    if options.gallery:
        os.makedirs(options.gallery, exist_ok=True)
        for name, arguments, *_ in sweeps(options.raylab):
            path = gallery_figure(options.raylab, name, arguments, options.gallery)
            print("wrote %s (%d bytes)" % (os.path.relpath(path), os.path.getsize(path)))
        return
    os.makedirs(options.directory, exist_ok=True)
    METAL_F0.update(metal_presets(options.raylab))
    LOOKS.update({model["name"]: raylab_tools.look_material(model) for model in registry(options.raylab)})
    documents = [sweep_scene(options.raylab, *sweep) for sweep in sweeps(options.raylab)]
    for scene in documents + [showcase(), showcase_hdri(), showcase_modern(), showcase_layered(), cornell_box(), cornell_box_area(), glossy_room(),
                                  minimal()]:
        path = scene.write(options.directory)
        print("wrote %s (%d bytes)" % (os.path.relpath(path), os.path.getsize(path)))


if __name__ == "__main__":
    main()
