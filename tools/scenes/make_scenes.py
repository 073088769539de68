#!/usr/bin/env python3
"""Writes raylab's committed glTF scenes (assets/scenes/*.gltf): one parameter sweep per figure of the
original slides, a showcase of every model, a Cornell-style box and the minimal example of docs/scenes.md.

    python3 tools/scenes/make_scenes.py [OUTPUT_DIR]     (default: assets/scenes next to this repository)

Python 3 standard library only; the output is deterministic, so regenerating an unchanged scene gives an
identical file. The conventions (extras.raylab materials and spheres, lights in W/sr) are docs/scenes.md's.

Sweeps: eight spheres in a row along +x, the swept parameter growing from left to right. A telephoto camera
40 units away and lights about 60 units away make every sphere see nearly the same view and light
directions, so that brightness differences along the row come from the parameter, not from the position.
Each sweep's scene carries extras.sweep = {model, parameter, values, brightness, why}: `brightness` is what
the mean radiance in a window around each sphere's projected centre does along the row, which
tests/scene/scene_render_test.cpp checks.
"""

import base64
import json
import math
import os
import struct
import sys

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


def rotate_towards(direction, axis, degrees):
    """`direction` rotated by `degrees` about the unit `axis` (Rodrigues)."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    k = normalize(axis)
    return add(add(scale(direction, c), scale(cross(k, direction), s)), scale(k, dot(k, direction) * (1 - c)))


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


def sweep(first, last, count, log):
    if log:
        return [first * (last / first) ** (i / (count - 1)) for i in range(count)]
    return [first + (last - first) * i / (count - 1) for i in range(count)]


# ----------------------------------------------------------------------------------------------- the writer


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
        """A material whose raylab model is `raylab`; `preview` is the base colour other viewers show."""
        material = {"name": name}
        if preview is not None:
            material["pbrMetallicRoughness"] = {"baseColorFactor": rounded(list(preview)) + [1.0],
                                                "metallicFactor": 0.0, "roughnessFactor": 0.5}
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

ROW_COUNT = 8
ROW_SPACING = 1.0
ROW_RADIUS = 0.4
ROW_TARGET = [0.0, ROW_RADIUS, 0.0]
CAMERA_DISTANCE = 40.0
CAMERA_ELEVATION = 6.0  # degrees
CAMERA_YFOV = 7.0  # degrees: the row fills a 16:9 image
LIGHT_DISTANCE = 60.0
LIGHT_IRRADIANCE = 3.0  # W/m² at the row: white Lambert facing the light has radiance 0.95


def view_direction():
    """From the row towards the camera."""
    e = math.radians(CAMERA_ELEVATION)
    return [0.0, math.sin(e), math.cos(e)]


def light_direction(away_degrees, towards):
    """A direction `away_degrees` from the view direction, turned towards `towards` (e.g. up or right)."""
    v = view_direction()
    axis = cross(v, towards)
    return normalize(rotate_towards(v, axis, away_degrees))


def sweep_scene(name, model, parameter, values, fixed, brightness, why, light_away, light_towards,
                ground=(0.35, 0.35, 0.35), colour=(0.8, 0.8, 0.8)):
    g = Gltf(name)
    g.background((0.02, 0.022, 0.03))
    g.doc["scenes"][0]["extras"]["sweep"] = {
        "model": model, "parameter": parameter, "values": rounded(values, 5), "brightness": brightness, "why": why}
    ground_material = g.material("ground", {"model": "lambert", "rho_d": list(ground)}, ground)
    add_quad(g, "ground", [-60.0, 0.0, 60.0], [120.0, 0.0, 0.0], [0.0, 0.0, -120.0], ground_material)
    for i, value in enumerate(values):
        params = dict(fixed)
        params["model"] = model
        params[parameter] = [value] * 3 if parameter in ("rho_d", "rho_s", "Rd", "Rs") else value
        label = "%s %s=%.4g" % (model, parameter, value)
        material = g.material(label, params, colour)
        x = (i - (len(values) - 1) / 2) * ROW_SPACING
        g.sphere(label, [x, ROW_RADIUS, 0.0], ROW_RADIUS, material)
    add_sweep_camera(g)
    direction = light_direction(light_away, light_towards)
    g.point_light("key", add(ROW_TARGET, scale(direction, LIGHT_DISTANCE)), LIGHT_IRRADIANCE * LIGHT_DISTANCE ** 2)
    return g


def add_sweep_camera(g):
    g.camera("camera", add(ROW_TARGET, scale(view_direction(), CAMERA_DISTANCE)), ROW_TARGET, CAMERA_YFOV)


UP = [0.0, 1.0, 0.0]
RIGHT = [1.0, 0.0, 0.0]


def sweeps():
    scenes = []
    scenes.append(sweep_scene(
        "sweep_lambert_rho_d", "lambert", "rho_d", sweep(0.0, 1.0, ROW_COUNT, False), {},
        "increasing", "the diffuse term rho_d/pi grows linearly", 35, UP))
    scenes.append(sweep_scene(
        "sweep_phong_rho_s", "phong", "rho_s", sweep(0.0, 1.0, ROW_COUNT, False), {"rho_d": [0.1, 0.1, 0.1], "s": 30},
        "increasing", "the highlight lies inside the window and grows linearly with rho_s", 16, UP,
        colour=(0.3, 0.4, 0.8)))
    # With the light 86 degrees from the view, the highlights sit near the spheres' upper right rim and the
    # window around the centre sees only the lobes' tails, which narrower lobes make darker. Without a diffuse
    # term (rho_d = 0) the tails are all the window sees, so position cannot disturb the order.
    scenes.append(sweep_scene(
        "sweep_phong_s", "phong", "s", sweep(1.0, 1000.0, ROW_COUNT, True), {"rho_d": [0.0] * 3, "rho_s": [1.0] * 3},
        "decreasing", "the light is 86 degrees from the view: the window's mirror directions are at least 56 "
                      "degrees from the camera, where (s+2) cos^s falls with s (the highlight near the rim "
                      "shrinks)", 86,
        normalize(add(UP, RIGHT)), colour=(0.9, 0.9, 0.9)))
    scenes.append(sweep_scene(
        "sweep_blinnphong_s", "blinnphong", "s", sweep(1.0, 1000.0, ROW_COUNT, True),
        {"rho_d": [0.0] * 3, "rho_s": [1.0] * 3},
        "decreasing", "the light is 86 degrees from the view: the window's normals are at least 28 degrees "
                      "from the half vector, where (s+8) (N.H)^s falls with s (the highlight near the rim shrinks)", 86,
        normalize(add(UP, RIGHT)), colour=(0.9, 0.9, 0.9)))
    scenes.append(delta_sweep())
    scenes.append(sweep_scene(
        "sweep_cooktorrance_m", "cooktorrance", "m", sweep(0.01, 1.0, ROW_COUNT, True),
        {"rho_d": [0.0] * 3, "rho_s": [1.0] * 3, "eta": 1.5},
        "increasing", "the light is 86 degrees above the view: the window's normals are 28 to 58 degrees "
                      "from the half vector, where the Beckmann D, averaged over the window, grows with m from 0.01 "
                      "to 1 (the highlight near the rim widens)", 86, UP, colour=(0.9, 0.9, 0.9)))
    scenes.append(sweep_scene(
        "sweep_cooktorrance_eta", "cooktorrance", "eta", sweep(1.0, 10.0, ROW_COUNT, False),
        {"rho_d": [0.1, 0.02, 0.02], "rho_s": [1.0] * 3, "m": 0.2},
        "increasing", "Schlick's F0 = ((eta-1)/(eta+1))^2 grows with eta at every angle", 16, UP,
        colour=(0.6, 0.1, 0.1)))
    scenes.append(sweep_scene(
        "sweep_ward_alpha_y", "ward", "alpha_y", sweep(0.02, 0.8, ROW_COUNT, True),
        {"rho_d": [0.0] * 3, "rho_s": [1.0] * 3, "alpha_x": 0.1},
        "increasing", "the light is 86 degrees above the view, so the half vector tilts along the bitangent "
                      "(sphere latitude lines run along the tangent): a wider alpha_y lets more of the lobe reach "
                      "the window", 86, UP, colour=(0.8, 0.7, 0.3)))
    scenes.append(sweep_scene(
        "sweep_ashikhmin_shirley_nv", "ashikhmin_shirley", "nv", sweep(1.0, 1000.0, ROW_COUNT, True),
        {"Rd": [0.0] * 3, "Rs": [1.0] * 3, "nu": 10.0},
        "decreasing", "the light is 86 degrees above the view, so the half vector tilts along the bitangent "
                      "where nv is the exponent: a larger nv narrows the lobe there and the window darkens", 86, UP,
        colour=(0.3, 0.7, 0.5)))
    scenes.append(glass_sweep())
    return scenes


def delta_sweep():
    """Mirror weight 0 to 1 over a checkerboard: the reflections show the board, and the window centre
    reflects the dark sky behind the camera, so brightness falls as delta rises."""
    g = Gltf("sweep_lambert_delta")
    g.background((0.02, 0.022, 0.03))
    values = sweep(0.0, 1.0, ROW_COUNT, False)
    g.doc["scenes"][0]["extras"]["sweep"] = {
        "model": "lambert", "parameter": "delta", "values": rounded(values, 5), "brightness": "decreasing",
        "why": "L = (1 - delta) diffuse + delta reflected, and the window centre reflects the dark sky behind "
               "the camera; the lower half of each sphere shows the checkerboard"}
    light = g.material("checker light", {"model": "lambert", "rho_d": [0.8, 0.8, 0.8]}, (0.8, 0.8, 0.8))
    dark = g.material("checker dark", {"model": "lambert", "rho_d": [0.05, 0.1, 0.3]}, (0.05, 0.1, 0.3))
    add_checker(g, "checker", (-8.0, 8.0), (-8.0, 8.0), 0.0, 1.0, (light, dark))
    for i, value in enumerate(values):
        label = "lambert delta=%.4g" % value
        material = g.material(label, {"model": "lambert", "rho_d": [0.8, 0.55, 0.3], "delta": value}, (0.8, 0.55, 0.3))
        g.sphere(label, [(i - (len(values) - 1) / 2) * ROW_SPACING, ROW_RADIUS, 0.0], ROW_RADIUS, material)
    add_sweep_camera(g)
    direction = light_direction(35, normalize(add(UP, scale(RIGHT, -0.5))))
    g.point_light("key", add(ROW_TARGET, scale(direction, LIGHT_DISTANCE)), LIGHT_IRRADIANCE * LIGHT_DISTANCE ** 2)
    return g


def glass_sweep():
    """Glass eta 1 to 2.5 in front of a bright sky, standing at the back edge of a checkerboard floor, with a
    black wall behind the camera: each sphere shows the floor refracted (upside down, in its upper part) and
    the window centre sees the sky through the glass, dimmed by the Fresnel reflections that grow with eta."""
    g = Gltf("sweep_glass_eta")
    g.background((0.75, 0.8, 0.9))
    values = sweep(1.0, 2.5, ROW_COUNT, False)
    g.doc["scenes"][0]["extras"]["sweep"] = {
        "model": "glass", "parameter": "eta", "values": rounded(values, 5), "brightness": "decreasing",
        "why": "the window centre sees the bright sky through the sphere with weight (1 - F)^2, and its "
               "reflection sees the black wall behind the camera; F grows with eta"}
    light = g.material("checker light", {"model": "lambert", "rho_d": [0.8, 0.8, 0.8]}, (0.8, 0.8, 0.8))
    dark = g.material("checker dark", {"model": "lambert", "rho_d": [0.6, 0.1, 0.05]}, (0.6, 0.1, 0.05))
    add_checker(g, "checker", (-8.0, 8.0), (-0.5, 15.5), 0.0, 1.0, (light, dark))
    black = g.material("black wall", {"model": "lambert", "rho_d": [0.0, 0.0, 0.0]}, (0.0, 0.0, 0.0))
    # Facing the scene (-z), well behind the camera.
    add_quad(g, "black wall", [100.0, -100.0, 60.0], [-200.0, 0.0, 0.0], [0.0, 200.0, 0.0], black)
    for i, value in enumerate(values):
        label = "glass eta=%.4g" % value
        material = g.material(label, {"model": "glass", "eta": value}, (0.9, 0.95, 1.0))
        g.sphere(label, [(i - (len(values) - 1) / 2) * ROW_SPACING, ROW_RADIUS, 0.0], ROW_RADIUS, material)
    add_sweep_camera(g)
    direction = light_direction(35, UP)
    g.point_light("key", add(ROW_TARGET, scale(direction, LIGHT_DISTANCE)), LIGHT_IRRADIANCE * LIGHT_DISTANCE ** 2)
    return g


# ------------------------------------------------------------------------------------- showcase and others


def showcase():
    """Every model side by side on a checkerboard, under a warm key, a cool fill and a rim light."""
    g = Gltf("showcase")
    g.background((0.03, 0.035, 0.05))
    light = g.material("checker light", {"model": "lambert", "rho_d": [0.7, 0.7, 0.68]}, (0.7, 0.7, 0.68))
    dark = g.material("checker dark", {"model": "lambert", "rho_d": [0.18, 0.18, 0.2]}, (0.18, 0.18, 0.2))
    add_checker(g, "floor", (-10.0, 10.0), (-8.0, 8.0), 0.0, 1.0, (light, dark))
    models = [
        ("lambert", {"model": "lambert", "rho_d": [0.75, 0.2, 0.15]}),
        ("phong", {"model": "phong", "rho_d": [0.7, 0.5, 0.1], "rho_s": [0.3, 0.3, 0.3], "s": 60}),
        ("blinnphong", {"model": "blinnphong", "rho_d": [0.3, 0.65, 0.2], "rho_s": [0.3, 0.3, 0.3], "s": 120}),
        ("cooktorrance", {"model": "cooktorrance", "rho_d": [0.1, 0.3, 0.7], "rho_s": [1.0, 1.0, 1.0],
                          "m": 0.15, "eta": 1.5}),
        ("ward", {"model": "ward", "rho_d": [0.15, 0.1, 0.05], "rho_s": [0.9, 0.7, 0.4],
                  "alpha_x": 0.08, "alpha_y": 0.4}),
        ("ward_duer", {"model": "ward_duer", "rho_d": [0.4, 0.1, 0.5], "rho_s": [0.5, 0.5, 0.5],
                       "alpha_x": 0.2, "alpha_y": 0.2}),
        ("ward_gmd", {"model": "ward_gmd", "rho_d": [0.1, 0.45, 0.45], "rho_s": [0.5, 0.5, 0.5],
                      "alpha_x": 0.15, "alpha_y": 0.15}),
        ("ashikhmin_shirley", {"model": "ashikhmin_shirley", "Rd": [0.6, 0.3, 0.5], "Rs": [0.05, 0.05, 0.05],
                               "nu": 1000, "nv": 40}),
        ("glass", {"model": "glass", "eta": 1.5, "tint": [0.95, 0.98, 1.0]}),
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
    g.point_light("key", [-5.0, 8.0, 6.0], 120.0, (1.0, 0.92, 0.8))
    g.point_light("fill", [7.0, 4.0, 5.0], 35.0, (0.7, 0.8, 1.0))
    g.point_light("rim", [2.0, 6.0, -8.0], 60.0, (1.0, 1.0, 1.0))
    return g


def cornell_box():
    """A Cornell-style box (red left, green right, open towards the camera) with a mirror and a glass sphere
    under a point light below the ceiling."""
    g = Gltf("cornell_box")
    white = g.material("white", {"model": "lambert", "rho_d": [0.73, 0.73, 0.73]}, (0.73, 0.73, 0.73))
    red = g.material("red", {"model": "lambert", "rho_d": [0.63, 0.065, 0.05]}, (0.63, 0.065, 0.05))
    green = g.material("green", {"model": "lambert", "rho_d": [0.14, 0.45, 0.09]}, (0.14, 0.45, 0.09))
    mirror = g.material("mirror", {"model": "lambert", "rho_d": [0.9, 0.9, 0.9], "delta": 0.95}, (0.9, 0.9, 0.9))
    glass = g.material("glass", {"model": "glass", "eta": 1.5}, (0.95, 0.95, 1.0))
    # The box spans x in [-w, w], y in [0, 2] and z in [-1, 1], as wide as a 16:9 frame of its opening;
    # every wall faces the inside.
    w = 1.75
    add_quad(g, "floor", [-w, 0.0, 1.0], [2 * w, 0.0, 0.0], [0.0, 0.0, -2.0], white)
    add_quad(g, "ceiling", [-w, 2.0, -1.0], [2 * w, 0.0, 0.0], [0.0, 0.0, 2.0], white)
    add_quad(g, "back wall", [-w, 0.0, -1.0], [2 * w, 0.0, 0.0], [0.0, 2.0, 0.0], white)
    add_quad(g, "left wall", [-w, 0.0, 1.0], [0.0, 0.0, -2.0], [0.0, 2.0, 0.0], red)
    add_quad(g, "right wall", [w, 0.0, -1.0], [0.0, 0.0, 2.0], [0.0, 2.0, 0.0], green)
    g.sphere("mirror sphere", [-0.6, 0.45, -0.3], 0.45, mirror)
    g.sphere("glass sphere", [0.65, 0.45, 0.3], 0.45, glass)
    # The opening (z = 1) just fills the frame's height.
    g.camera("camera", [0.0, 1.0, 4.2], [0.0, 1.0, 0.0], 34.0)
    g.point_light("lamp", [0.0, 1.7, 0.2], 6.0, (1.0, 0.95, 0.85))
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
    directory = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "assets", "scenes")
    os.makedirs(directory, exist_ok=True)
    for scene in sweeps() + [showcase(), cornell_box(), minimal()]:
        path = scene.write(directory)
        print("wrote %s (%d bytes)" % (os.path.relpath(path), os.path.getsize(path)))


if __name__ == "__main__":
    main()
