#!/usr/bin/env python3
"""Expands the BRDF model registry (shaders/brdf/models.cmake) into the code that dispatches over it.

Each registered model is a GLSL file that opens with its lobe flags and parameter table, and a
double-precision reference file. From the tables this writes, at build time:
  glsl/generated/bsdf_models.glsl   the device dispatch (model id -> <prefix>Eval/Pdf/Sample/DeltaEvent)
  glsl/generated/model_opacity.glsl modelOpacity (a parameter of role opacity), for the alpha test
  cpp/brdf_model_table.cpp          the C++ model table (names, ids, lobes, parameters, slots, files)
  cpp/generated/reference_params.h  one parameter struct per model for the reference, and its functions
  cpp/reference_dispatch.cpp        the reference's dispatch
Outputs are rewritten only when their text changes, so that touching a model's formulas recompiles the
kernels and the model's reference file, nothing else. docs/extending.md describes the format.
"""
import argparse
import os
import re
import sys

MAX_PARAM_FLOATS = 52  # gpu::kMaxMaterialParams (shaders/shared/scene_records.h)
LOBES = {"reflection": 1, "transmission": 2, "diffuse": 4, "glossy": 8, "specular": 16}
ROLES = {"diffuse", "specular", "eta", "transmittance", "slope", "slope_x", "slope_y", "exponent", "mirror_exponent",
         "exponent_x", "exponent_y", "lobe_x", "lobe_y", "file", "network", "roughness", "metallic", "specular_weight",
         "specular_tint", "emission_luminance", "emission_color", "opacity"}
ROW = re.compile(r"^//\s*\|\s*`?(\w+)`?\s*\|\s*\[([-0-9.e]+),\s*([-0-9.e]+)\]\s*\|\s*([-0-9.e]+)\s*\|"
                 r"\s*([^|]*)\|\s*([^|]*?)\s*\|\s*$")


class RegistryError(Exception):
    pass


SWEEP_STATISTICS = {"mean", "highlight_area"}
SWEEP_TRENDS = {"increasing", "decreasing", "steady"}


def parse_model(name, prefix, include, path):
    """The lobes, parameter table, sweep line, presets and tool lines (look, figures, sweep scenes) of the comment
    a model's GLSL file opens with."""
    lobes, params, sweep, slot, preset_lines = None, [], "", 0, []
    look, figure_lines, sweep_scene_lines, non_reciprocal, fit_by_name, fit_starts = None, [], [], "", "", 0
    fit_search_factor = 1
    fit_start_line, fit_free_lines = None, []
    feature_lines, medium, sampled_albedo = [], None, None
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if not line.startswith("//"):
                break
            where = f"{path}:{number}"
            body = line[2:].strip()
            if body.startswith("lobes:"):
                words = body[len("lobes:"):].split()
                unknown = [w for w in words if w not in LOBES]
                if unknown or not words:
                    raise RegistryError(f"{where}: lobes are {', '.join(LOBES)}; got '{body}'")
                lobes = sum(LOBES[w] for w in words)
            elif body.startswith("reciprocal:"):
                answer, _, why = body[len("reciprocal:"):].partition(",")
                if answer.strip() != "no" or not why.strip():
                    raise RegistryError(f"{where}: 'reciprocal: no, WHY' marks a model that is not reciprocal "
                                        "(reciprocal models say nothing)")
                non_reciprocal = why.strip()
            elif body.startswith("feature:"):
                words = body[len("feature:"):].split()
                if len(words) != 2 or not re.fullmatch(r"[a-z][a-z0-9_]*", words[0]):
                    raise RegistryError(f"{where}: 'feature: NAME PARAM' names a part of the model that a scene uses "
                                        "when PARAM is not 0 in one of its materials (or a texture sets it); several "
                                        "lines of one NAME share its bit")
                feature_lines.append((where, words[0], words[1]))
            elif body.startswith("albedo sampled when:"):
                sampled_albedo = (where, body[len("albedo sampled when:"):].split())
            elif body.startswith("medium:"):
                medium = (where, body[len("medium:"):].split())
            elif body.startswith("fit:"):
                answer, _, why = body[len("fit:"):].partition(",")
                words = answer.split()
                if answer.strip() == "by name" and why.strip():
                    fit_by_name = why.strip()
                elif len(words) == 2 and words[0] == "starts" and words[1].isdigit() and \
                        1 <= int(words[1]) <= 64 and why.strip():
                    fit_starts = int(words[1])
                elif len(words) == 2 and words[0] == "search" and re.fullmatch(r"([2-9]|1[0-6])x", words[1]) and \
                        why.strip():
                    fit_search_factor = int(words[1][:-1])
                elif len(words) >= 2 and words[0] == "start" and why.strip():
                    fit_start_line = (where, words[1:])
                elif len(words) >= 2 and words[0] == "free":
                    fit_free_lines.append((where, words[1:], why.strip()))  # continued on more lines, one says why
                else:
                    raise RegistryError(f"{where}: 'fit: by name, WHY' keeps a model out of the default fits; "
                                        "'fit: starts N, WHY' gives it N (1..64) Levenberg-Marquardt starts by default; "
                                        "'fit: search Nx, WHY' searches N (2..16) times --search points; "
                                        "'fit: start NAME=VALUE ..., WHY' is one more start, the defaults with these; "
                                        "'fit: free NAME ..., WHY' fits only these parameters (the rest at defaults)")
            elif body.startswith("sweep:"):
                sweep = body[len("sweep:"):].strip()
            elif body.startswith("preset:"):
                preset_lines.append((where, body[len("preset:"):].split()))
            elif body.startswith("look:"):
                look = (where, body[len("look:"):].strip())
            elif body.startswith("figure") and ":" in body and re.fullmatch(r"figure( \w+)?", body.split(":")[0]):
                head, text = body.split(":", 1)
                figure_lines.append((where, head[len("figure"):].strip(), text.strip()))
            elif body.startswith("sweep scene:"):
                sweep_scene_lines.append([where, body[len("sweep scene:"):].strip(), ""])
            elif body.startswith("sweep why:"):
                if not sweep_scene_lines:
                    raise RegistryError(f"{where}: a 'sweep why:' line follows its 'sweep scene:' line")
                sweep_scene_lines[-1][2] = (sweep_scene_lines[-1][2] + " " + body[len("sweep why:"):].strip()).strip()
            elif line.lstrip("/ ").startswith("|") and not set(body) <= set("|- "):
                match = ROW.match(line.rstrip("\n"))
                if match is None:
                    if body.startswith("| parameter"):
                        continue
                    raise RegistryError(f"{where}: a parameter row is | name | [min, max] | default | kind | meaning |")
                pname, lo, hi, default, kind, meaning = match.groups()
                tags = kind.split()
                rgb, log = "rgb" in tags, "log" in tags
                roles = [t for t in tags if t not in ("rgb", "log")]
                if len(roles) > 1 or (roles and roles[0] not in ROLES):
                    raise RegistryError(f"{where}: kind is rgb, log and at most one role of {sorted(ROLES)}")
                if ("file" in roles or "network" in roles) and (rgb or log):
                    raise RegistryError(f"{where}: a file parameter is one scalar slot (the file's id), "
                                        "neither rgb nor log")
                lo, hi, default = float(lo), float(hi), float(default)
                if not lo <= default <= hi or (log and lo <= 0):
                    raise RegistryError(f"{where}: default {default} outside [{lo}, {hi}] (or a log range at 0)")
                params.append(dict(name=pname, rgb=rgb, min=lo, max=hi, default=default, log=log,
                                   role=roles[0] if roles else "", meaning=meaning, slot=slot))
                slot += 3 if rgb else 1
    if lobes is None:
        raise RegistryError(f"{path}: the opening comment has no 'lobes:' line")
    if slot > MAX_PARAM_FLOATS:
        raise RegistryError(f"{path}: {slot} parameter floats, more than the record's {MAX_PARAM_FLOATS}")
    names = [p["name"] for p in params]
    if len(set(names)) != len(names):
        raise RegistryError(f"{path}: a parameter is listed twice")
    two_sided = lobes & LOBES["transmission"] and lobes & (LOBES["diffuse"] | LOBES["glossy"])
    if two_sided and [p["role"] for p in params if not p["rgb"]].count("eta") != 1:
        raise RegistryError(f"{path}: a model with transmission and a density needs one scalar parameter of kind eta "
                            "(the index inside over outside)")
    by_name = {p["name"]: p for p in params}
    features = []
    for where, feature, param in feature_lines:
        if param not in by_name or by_name[param]["rgb"]:
            raise RegistryError(f"{where}: '{param}' is not a scalar parameter of the model")
        features.append(dict(name=feature, param=param))
    medium_params = []
    if medium is not None:
        where, words = medium
        if not two_sided or not words or any(w not in by_name for w in words):
            raise RegistryError(f"{where}: 'medium: PARAM...' names the parameters <prefix>MediumAbsorption takes, of "
                                "a model with transmission and a density")
        medium_params = [by_name[w] for w in words]
    fit_start = []
    if fit_start_line is not None:
        where, words = fit_start_line
        for word in words:
            pname, _, text = word.partition("=")
            try:
                value = float(text)
            except ValueError:
                value = None
            if pname not in by_name or value is None or not by_name[pname]["min"] <= value <= by_name[pname]["max"]:
                raise RegistryError(f"{where}: '{word}' is not NAME=VALUE for a parameter of the model within its range")
            fit_start.append((pname, value))
    fit_free = []
    for where, words, _ in fit_free_lines:
        if any(w not in by_name for w in words):
            raise RegistryError(f"{where}: 'fit: free' names parameters of the model: {[w for w in words if w not in by_name]}")
        fit_free += words
    if fit_free_lines and not any(why for _, _, why in fit_free_lines):
        raise RegistryError(f"{fit_free_lines[0][0]}: 'fit: free NAME ..., WHY': one of its lines says why")
    sampled_albedo_param = None
    if sampled_albedo is not None:
        where, words = sampled_albedo
        if len(words) != 1 or words[0] not in by_name or by_name[words[0]]["rgb"]:
            raise RegistryError(f"{where}: 'albedo sampled when: PARAM' names the scalar parameter whose value 0.5 or "
                                "more makes the albedo quadrature sample the model instead")
        sampled_albedo_param = by_name[words[0]]
    presets = [parse_preset(where, words, params) for where, words in preset_lines]
    keys = {p["name"] for p in params} | {"delta"} | {p["key"] for p in presets}
    if look is not None:
        check_param_list(look[0], look[1], keys)
    figures = []
    for where, figure_name, text in figure_lines:
        values, _, options = text.partition(" --")
        check_param_list(where, values, keys)
        figures.append(dict(name=f"{name}_{figure_name}" if figure_name else name, params=values.strip(),
                            options=("--" + options).split() if options else []))
    sweep_scenes = [parse_sweep_scene(where, text, why, params, keys) for where, text, why in sweep_scene_lines]
    return dict(name=name, prefix=prefix, include=include, path=path, lobes=lobes, params=params, sweep=sweep,
                presets=presets, look=look[1] if look else None, figures=figures, sweep_scenes=sweep_scenes,
                non_reciprocal=non_reciprocal, fit_by_name=fit_by_name, fit_starts=fit_starts, fit_start=fit_start,
                fit_search_factor=fit_search_factor,
                fit_free=fit_free, features=features, medium=medium_params, sampled_albedo=sampled_albedo_param)


def check_param_list(where, text, keys):
    """`rho_d=0.3/0.65/0.2, s=120`: every name one of the model's parameters, delta or a preset key."""
    for item in filter(None, (i.strip() for i in text.split(","))):
        if item.count("=") != 1 or item.split("=")[0].strip() not in keys:
            raise RegistryError(f"{where}: '{item}' is not name=value for a parameter of the model ({sorted(keys)})")


def parse_sweep_scene(where, text, why, params, keys):
    """`// sweep scene: s 1 1000 log [set k=v ...] -> highlight_area decreasing` and its `// sweep why:` lines: a
    committed scene of the sweep (tools/scenes/make_scenes.py) and the trend its test checks, with the reason."""
    sweep, arrow, expectation = text.partition("->")
    words, expected = sweep.split(), expectation.split()
    if not arrow or len(words) < 3 or len(expected) != 2 or expected[0] not in SWEEP_STATISTICS \
            or expected[1] not in SWEEP_TRENDS or not why:
        raise RegistryError(f"{where}: a sweep scene is 'PARAM FROM TO [log] [set NAME=VALUE ...] -> STATISTIC TREND' "
                            f"(statistics {sorted(SWEEP_STATISTICS)}, trends {sorted(SWEEP_TRENDS)}), followed by "
                            "'sweep why:' lines")
    param, start, stop, rest = words[0], words[1], words[2], words[3:]
    if param not in {p["name"] for p in params} | {"delta"}:
        raise RegistryError(f"{where}: '{param}' is not a parameter of the model")
    log = bool(rest) and rest[0] == "log"
    rest = rest[1:] if log else rest
    if rest and rest[0] != "set":
        raise RegistryError(f"{where}: after the range come 'log' and 'set NAME=VALUE ...'; got '{' '.join(rest)}'")
    fixed = rest[1:]
    check_param_list(where, ",".join(fixed), keys)
    return dict(param=param, start=start, stop=stop, log=log, set=fixed, statistic=expected[0], trend=expected[1],
                why=why)


def parse_preset(where, words, params):
    """`// preset: metal=Au eta=0.14/0.38/1.44 k=3.98/2.39/1.60`: a named set of parameter values, in range."""
    if len(words) < 2 or any(w.count("=") != 1 for w in words):
        raise RegistryError(f"{where}: a preset is 'key=Name param=value ...' (values r/g/b or one number)")
    key, name = words[0].split("=")
    values = []
    by_name = {p["name"]: p for p in params}
    for word in words[1:]:
        pname, text = word.split("=")
        param = by_name.get(pname)
        if param is None or key in by_name:
            raise RegistryError(f"{where}: '{pname}' is not a parameter, or the key '{key}' is one")
        channels = [float(c) for c in text.split("/")]
        if len(channels) not in (1, 3) or (len(channels) == 3 and not param["rgb"]):
            raise RegistryError(f"{where}: {pname} takes {'r/g/b or ' if param['rgb'] else ''}one number")
        if not all(param["min"] <= c <= param["max"] for c in channels):
            raise RegistryError(f"{where}: {pname} = {text} is outside [{param['min']}, {param['max']}]")
        values.append((pname, channels * 3 if len(channels) == 1 else channels))
    return dict(key=key, name=name, values=values)


def is_delta(model):
    return model["lobes"] & LOBES["specular"] and not model["lobes"] & (LOBES["diffuse"] | LOBES["glossy"])


def is_two_sided(model):
    """Transmission with a density (rough glass): the model samples and weighs both hemispheres itself."""
    return bool(model["lobes"] & LOBES["transmission"] and model["lobes"] & (LOBES["diffuse"] | LOBES["glossy"]))


def glsl_value(param):
    # An RGB parameter as its three slots: a helper function taking the record would copy all of it per call.
    slot = param["slot"]
    return f"vec3(m.params[{slot}], m.params[{slot + 1}], m.params[{slot + 2}])" if param["rgb"] else f"m.params[{slot}]"


def glsl_args(model):
    return "".join(glsl_value(p) + ", " for p in model["params"])


FIRST_MODEL_FEATURE_BIT = 16  # shared/features.h: the kSpecFeatures bits from here up are the models' own


def assign_feature_bits(models):
    """Each model's `feature:` names, in registry order, take the kSpecFeatures bits from FIRST_MODEL_FEATURE_BIT up;
    the lines of one name (a part several parameters turn on) share its bit."""
    bit = FIRST_MODEL_FEATURE_BIT
    for m in models:
        named = {}
        for feature in m["features"]:
            if feature["name"] not in named:
                if bit > 31:
                    raise RegistryError(f"{m['path']}: more model features than the 16 bits kSpecFeatures keeps for them")
                named[feature["name"]] = 1 << bit
                bit += 1
            feature["bit"] = named[feature["name"]]
            feature["constant"] = f"k{m['prefix'][0].upper()}{m['prefix'][1:]}Feature" + "".join(
                w.capitalize() for w in feature["name"].split("_"))


def glsl_dispatch(models):
    out = ["// Generated by tools/cmake/brdf_registry.py from the model registry; do not edit.",
           "// The dispatch over the registered models (bsdf.glsl wraps it). Each branch is guarded by",
           "// modelEnabled alone, a specialization-constant expression, so that specialising a kernel for a scene",
           "// removes the models the scene does not use before the driver compiles it (vk/spirv_specialization.h).",
           "#ifndef RAYLAB_GENERATED_BSDF_MODELS_GLSL", "#define RAYLAB_GENERATED_BSDF_MODELS_GLSL", ""]
    out.append("// The models' own features (their `feature:` lines): a kSpecFeatures bit each, for featureEnabled.")
    constants = {}
    for m in models:
        for f in m["features"]:
            constants.setdefault(f["constant"], (f["bit"], m["name"], []))[2].append(f["param"])
    out += [f"const uint {name} = {bit}u;  // {model}: {' or '.join(params)} not 0"
            for name, (bit, model, params) in constants.items()]
    out.append("")
    out += [f'#include "{m["include"]}"' for m in models]
    out.append("")
    surface = [(i, m) for i, m in enumerate(models) if not is_delta(m)]
    delta = [(i, m) for i, m in enumerate(models) if is_delta(m)]

    def chain(signature, call, fallback, entries):
        out.append(signature + " {")
        out.append("  const uint model = m.model;")
        for i, m in entries:
            out.append(f"  if (modelEnabled({i}u)) {{  // {m['name']}")
            out.append(f"    if (model == {i}u) return {m['prefix']}{call(m)};")
            out.append("  }")
        out.append(f"  return {fallback};")
        out.append("}")
        out.append("")

    chain("vec3 modelEval(MaterialRecord m, vec3 wi, vec3 wo)", lambda m: f"Eval({glsl_args(m)}wi, wo)",
          "vec3(0.0)", surface)
    chain("float modelPdf(MaterialRecord m, vec3 wi, vec3 wo)", lambda m: f"Pdf({glsl_args(m)}wi, wo)", "0.0",
          surface)
    chain("BsdfSample modelSample(MaterialRecord m, vec3 wo, vec3 u)", lambda m: f"Sample({glsl_args(m)}wo, u)",
          "noSample()", surface)
    chain("DeltaEvent modelDeltaEvent(MaterialRecord m, vec3 wi, vec3 n)",
          lambda m: f"DeltaEvent({glsl_args(m)}wi, n)", "noDeltaEvent()", delta)
    media = [(i, m) for i, m in enumerate(models) if m["medium"]]
    out.append("// The absorption coefficient inside a transmissive material (its `medium:` line), for the path integrator.")
    chain("vec3 modelMediumAbsorption(MaterialRecord m)",
          lambda m: "MediumAbsorption(" + ", ".join(glsl_value(p) for p in m["medium"]) + ")", "vec3(0.0)", media)
    out.append("uint modelFlags(uint model) {")
    for i, m in enumerate(models):
        guard = "featureEnabled(kFeatureDeltaBsdf) && " if is_delta(m) else ""
        out.append(f"  if ({guard}modelEnabled({i}u)) {{  // {m['name']}")
        out.append(f"    if (model == {i}u) return {m['lobes']}u;")
        out.append("  }")
    out += ["  return 0u;", "}", "", "#endif", ""]
    return "\n".join(out)


def glsl_opacity(models):
    """modelOpacity apart from the dispatch: the any-hit program reads it without including every model."""
    out = ["// Generated by tools/cmake/brdf_registry.py from the model registry; do not edit.",
           "// The coverage of a surface (its model's parameter of role opacity, openpbr's geometry_opacity): the alpha",
           "// test (kernel/alpha.glsl) lets a ray through with probability 1 - opacity. 1 for every other model.",
           "#ifndef RAYLAB_GENERATED_MODEL_OPACITY_GLSL", "#define RAYLAB_GENERATED_MODEL_OPACITY_GLSL", "",
           "float modelOpacity(MaterialRecord m) {", "  const uint model = m.model;"]
    for i, m in enumerate(models):
        for p in m["params"]:
            if p["role"] == "opacity":
                out.append(f"  if (modelEnabled({i}u) && model == {i}u) return {glsl_value(p)};  // {m['name']}")
    out += ["  return 1.0;", "}", "", "#endif", ""]
    return "\n".join(out)


def cpp_string(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def cpp_float(value):
    text = repr(float(value))
    return text + "f" if ("." in text or "e" in text) else text + ".0f"


def cpp_table(models, source_dir):
    out = ["// Generated by tools/cmake/brdf_registry.py from the model registry; do not edit.",
           '#include "brdf_params/material_params.h"', "", "namespace raylab {", "",
           "const std::vector<ModelInfo>& registeredModels() {",
           "  static const std::vector<ModelInfo> table = {"]
    for i, m in enumerate(models):
        params = ", ".join(
            "{" + ", ".join([cpp_string(p["name"]), "true" if p["rgb"] else "false", cpp_float(p["min"]),
                             cpp_float(p["max"]), cpp_float(p["default"]), "true" if p["log"] else "false",
                             cpp_string(p["meaning"]), cpp_string(p["role"]), f"{p['slot']}u"]) + "}"
            for p in m["params"])
        glsl = os.path.relpath(m["path"], source_dir)
        features = ", ".join("{" + f"{cpp_string(f['name'])}, {cpp_string(f['param'])}, {f['bit']}u" + "}"
                             for f in m["features"])
        fit_start = ", ".join("{" + f"{cpp_string(name)}, {repr(float(value))}" + "}" for name, value in m["fit_start"])
        fit_free = ", ".join(cpp_string(name) for name in m["fit_free"])
        presets = ", ".join(
            "{" + f"{cpp_string(p['key'])}, {cpp_string(p['name'])}, {{" + ", ".join(
                "{" + f"{cpp_string(param)}, glm::vec3({', '.join(cpp_float(c) for c in channels)})" + "}"
                for param, channels in p["values"]) + "}}"
            for p in m["presets"])
        out.append(f"      {{{cpp_string(m['name'])}, {i}u, {m['lobes']}u, {{{params}}}, {cpp_string(m['sweep'])}, "
                   f"{cpp_string(glsl)}, {cpp_string(m['reference'])}, {{{presets}}}, "
                   f"{cpp_string(m['non_reciprocal'])}, {cpp_string(m['fit_by_name'])}, {m['fit_starts']}u, {m['fit_search_factor']}u, "
                   f"{{{fit_start}}}, {{{fit_free}}}, {{{features}}}}},")
    out += ["  };", "  return table;", "}", "", "}  // namespace raylab", ""]
    return "\n".join(out)


def struct_name(model):
    return model["prefix"][0].upper() + model["prefix"][1:] + "Params"


def reference_header(models):
    out = ["// Generated by tools/cmake/brdf_registry.py from the model registry; do not edit.",
           "// One parameter struct per model (the names of its GLSL table) and the functions its reference file",
           "// defines: <prefix>Eval, and for a glossy lobe <prefix>SampleSpecular, <prefix>PdfSpecular and",
           "// <prefix>SpecularLobe (a two-sided model: <prefix>Sample and <prefix>Pdf over both hemispheres instead of",
           "// <prefix>SampleSpecular and <prefix>PdfSpecular); for a delta BSDF <prefix>DeltaEvent.",
           "#pragma once", "", '#include "reference/models.h"', "", "namespace raylab::reference {", ""]
    for m in models:
        s = struct_name(m)
        out.append(f"struct {s} {{")
        out += [f"  {'dvec3' if p['rgb'] else 'double'} {p['name']};" for p in m["params"]]
        out.append("};")
        fields = ", ".join((f"paramRgb(material, {p['slot']})" if p["rgb"] else f"material.params[{p['slot']}]")
                           for p in m["params"])
        out.append(f"inline {s} {m['prefix']}Params(const Material& material) {{ return {{{fields}}}; }}")
        if is_delta(m):
            out.append(f"DielectricEvent {m['prefix']}DeltaEvent(const {s}& p, const dvec3& wi, const dvec3& n);")
        else:
            out.append(f"Lobes {m['prefix']}Eval(const {s}& p, const dvec3& wi, const dvec3& wo);")
        if is_two_sided(m):
            out.append(f"dvec3 {m['prefix']}Sample(const {s}& p, const dvec3& wo, const dvec3& u);")
            out.append(f"double {m['prefix']}Pdf(const {s}& p, const dvec3& wi, const dvec3& wo);")
            out.append(f"dvec3 {m['prefix']}TransmissionEtas(const {s}& p);")
        elif m["lobes"] & LOBES["glossy"]:
            out.append(f"dvec3 {m['prefix']}SampleSpecular(const {s}& p, const dvec3& wo, const dvec2& u);")
            out.append(f"double {m['prefix']}PdfSpecular(const {s}& p, const dvec3& wi, const dvec3& wo);")
        if m["lobes"] & LOBES["glossy"]:
            out.append(f"SpecularLobe {m['prefix']}SpecularLobe(const {s}& p);")
        if m["medium"]:
            out.append(f"dvec3 {m['prefix']}MediumAbsorption(const {s}& p);")
        out.append("")
    out += ["}  // namespace raylab::reference", ""]
    return "\n".join(out)


def reference_dispatch(models):
    out = ["// Generated by tools/cmake/brdf_registry.py from the model registry; do not edit.",
           '#include "generated/reference_params.h"', "", "namespace raylab::reference {", ""]

    def switch(signature, body, fallback, keep):
        out.append(signature + " {")
        out.append("  switch (material.model) {")
        for i, m in enumerate(models):
            if keep(m):
                out.append(f"    case {i}: return {body(m)};  // {m['name']}")
        out.append(f"    default: return {fallback};")
        out.extend(["  }", "}", ""])

    glossy = lambda m: bool(m["lobes"] & LOBES["glossy"])
    one_sided_glossy = lambda m: glossy(m) and not is_two_sided(m)
    params = lambda m: f"{m['prefix']}Params(material)"
    switch("Lobes evalLobes(const Material& material, const dvec3& wi, const dvec3& wo)",
           lambda m: f"{m['prefix']}Eval({params(m)}, wi, wo)", "Lobes{}", lambda m: not is_delta(m))
    switch("dvec3 sampleSpecular(const Material& material, const dvec3& wo, const dvec2& u)",
           lambda m: f"{m['prefix']}SampleSpecular({params(m)}, wo, u)", "dvec3(0.0)", one_sided_glossy)
    switch("double pdfSpecular(const Material& material, const dvec3& wi, const dvec3& wo)",
           lambda m: f"{m['prefix']}PdfSpecular({params(m)}, wi, wo)", "0.0", one_sided_glossy)
    switch("std::optional<dvec3> sampleTwoSided(const Material& material, const dvec3& wo, const dvec3& u)",
           lambda m: f"{m['prefix']}Sample({params(m)}, wo, u)", "std::nullopt", is_two_sided)
    switch("std::optional<double> pdfTwoSided(const Material& material, const dvec3& wi, const dvec3& wo)",
           lambda m: f"{m['prefix']}Pdf({params(m)}, wi, wo)", "std::nullopt", is_two_sided)
    switch("std::optional<dvec3> transmissionEtas(const Material& material)",
           lambda m: f"{m['prefix']}TransmissionEtas({params(m)})", "std::nullopt", is_two_sided)
    switch("dvec3 mediumAbsorption(const Material& material)",
           lambda m: f"{m['prefix']}MediumAbsorption({params(m)})", "dvec3(0.0)", lambda m: bool(m["medium"]))
    switch("std::optional<SpecularLobe> specularLobe(const Material& material)",
           lambda m: f"{m['prefix']}SpecularLobe({params(m)})", "std::nullopt", glossy)
    switch("std::optional<DielectricEvent> deltaEvent(const Material& material, const dvec3& wi, const dvec3& n)",
           lambda m: f"{m['prefix']}DeltaEvent({params(m)}, wi, n)", "std::nullopt", is_delta)
    switch("std::uint32_t lobeFlags(const Material& material)", lambda m: f"{m['lobes']}u", "0u",
           lambda m: True)
    switch("bool isTabulated(const Material& material)", lambda m: "true", "false",
           lambda m: any(p["role"] == "file" for p in m["params"]))
    switch("bool albedoBySampling(const Material& material)",
           lambda m: f"material.params[{m['sampled_albedo']['slot']}] >= 0.5", "false",
           lambda m: m["sampled_albedo"] is not None)
    out += ["}  // namespace raylab::reference", ""]
    return "\n".join(out)


def write_if_changed(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            if f.read() == text:
                return
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--model", action="append", default=[],
                        help="name;prefix;glsl include name;glsl path;reference path, in id order")
    args = parser.parse_args()
    models, seen = [], set()
    try:
        for entry in args.model:
            name, prefix, include, path, reference = entry.split(";")
            if name in seen:
                raise RegistryError(f"model '{name}' is registered twice")
            seen.add(name)
            model = parse_model(name, prefix, include, path)
            model["reference"] = os.path.relpath(reference, args.source_dir)
            models.append(model)
        if len(models) > 32:
            raise RegistryError("more than 32 models: the specialization bit mask has 32 bits")
        assign_feature_bits(models)
    except (RegistryError, OSError, ValueError) as error:
        sys.exit(f"brdf_registry: {error}")
    write_if_changed(os.path.join(args.out, "glsl/generated/bsdf_models.glsl"), glsl_dispatch(models))
    write_if_changed(os.path.join(args.out, "glsl/generated/model_opacity.glsl"), glsl_opacity(models))
    write_if_changed(os.path.join(args.out, "cpp/brdf_model_table.cpp"), cpp_table(models, args.source_dir))
    write_if_changed(os.path.join(args.out, "cpp/generated/reference_params.h"), reference_header(models))
    write_if_changed(os.path.join(args.out, "cpp/reference_dispatch.cpp"), reference_dispatch(models))


if __name__ == "__main__":
    main()
