#include "sweep_study/sweep_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "brdf_params/material_params.h"
#include "command_line/cli.h"
#include "image/contact_sheet.h"
#include "gltf_write/sweep_gltf.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/timer.h"
#include "render/render_choices.h"

namespace raylab {

namespace {

constexpr const char* kCommand = "raylab sweep";

[[noreturn]] void usage(const std::string& message) {
  throw Error(std::string(kCommand) + ": " + message + " (see `" + kCommand + " --help`)", kExitUsage);
}

std::string rangeText(const ParamInfo& param) {
  return "[" + formatSweepValue(param.min) + ", " + formatSweepValue(param.max) + "]";
}

// A finite number, or a usage error naming the option.
float parseNumber(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const float value = std::strtof(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value)) {
    usage(option + ": expected a finite number, got '" + text + "'");
  }
  return value;
}

// "0.5" or "0.8/0.5/0.2" (RGB parameters only).
glm::vec3 parseParamValue(const std::string& option, const std::string& text, const ParamInfo& param) {
  const std::size_t first = text.find('/');
  if (first == std::string::npos) return glm::vec3(parseNumber(option, text));
  if (!param.rgb) usage(option + ": " + std::string(param.name) + " is a single number, got '" + text + "'");
  const std::size_t second = text.find('/', first + 1);
  if (second == std::string::npos || text.find('/', second + 1) != std::string::npos) {
    usage(option + ": expected one number or r/g/b, got '" + text + "'");
  }
  return {parseNumber(option, text.substr(0, first)), parseNumber(option, text.substr(first + 1, second - first - 1)),
          parseNumber(option, text.substr(second + 1))};
}

std::string paramNames(const ModelInfo& model) {
  std::string names;
  for (const ParamInfo& param : model.params) names += std::string(param.name) + ", ";
  return names + std::string(deltaParam().name);
}

// Every check of the command line that needs the parameter table, each failing with the option's name and
// the accepted range.
SweepSpec validatedSpec(const SweepOptions& o) {
  if (o.model.empty()) usage("--model is required (one of " + modelNames() + ")");
  const ModelInfo* model = findModel(o.model);
  if (model == nullptr) usage("--model: unknown model '" + o.model + "' (one of " + modelNames() + ")");
  if (o.param.empty()) usage("--param is required (" + o.model + " has " + paramNames(*model) + ")");
  const ParamInfo* param = findParam(*model, o.param);
  if (param == nullptr) {
    usage("--param: '" + o.param + "' is not a parameter of " + o.model + " (it has " + paramNames(*model) + ")");
  }
  if (o.log && o.linear) usage("--log and --linear exclude each other");
  // A sweep's scene is a glTF of numbers (gltf_write); a model reading a file is rendered from a scene of yours.
  if (findFileParam(*model) != nullptr) {
    usage("--model " + o.model + " reads a file: sweeps take models of numbers only (render a scene of yours with "
          "--material NAME=" + o.model + ":file=PATH, docs/fitting.md)");
  }

  SweepSpec spec;
  spec.model = o.model;
  spec.param = o.param;
  spec.steps = o.steps;
  spec.logScale = o.log || (!o.linear && param->logScale);
  spec.from = o.from.empty() ? param->min : parseNumber("--from", o.from);
  spec.to = o.to.empty() ? param->max : parseNumber("--to", o.to);
  for (const auto& [option, value] : {std::pair{"--from", spec.from}, std::pair{"--to", spec.to}}) {
    if (value < param->min || value > param->max) {
      usage(std::string(option) + ": " + o.param + " = " + formatSweepValue(value) + " is outside " +
            rangeText(*param));
    }
    if (spec.logScale && value <= 0.0f) {
      usage(std::string(option) + ": " + o.param + " = " + formatSweepValue(value) +
            " cannot bound a geometric (--log) sweep: both bounds must be positive");
    }
  }
  if (spec.from == spec.to) usage("--from and --to are equal (" + formatSweepValue(spec.from) + ")");

  // --set: parsed against the table, then checked by setParam on a scratch material.
  gpu::MaterialRecord scratch = sweepBaseMaterial(model->id);
  for (const std::string& set : o.sets) {
    const std::size_t equals = set.find('=');
    if (equals == std::string::npos || equals == 0) usage("--set: expected K=V, got '" + set + "'");
    const std::string name = set.substr(0, equals);
    const std::string option = "--set " + name;
    if (isPresetKey(*model, name)) {
      // A named set (metal=Au): its parameters, in the order the model's file lists them.
      const std::string presetName = set.substr(equals + 1);
      try {
        gpu::MaterialRecord preset = sweepBaseMaterial(model->id);
        applyPreset(preset, name, presetName, option);  // refuses an unknown name, listing the known ones
      } catch (const Error& error) {
        usage(error.what());
      }
      for (const Preset& candidate : model->presets) {
        if (candidate.key != name || candidate.name != presetName) continue;
        for (const PresetValue& v : candidate.values) {
          if (v.param == o.param) usage(option + " sets " + std::string(v.param) + ", the swept parameter");
          spec.fixed.emplace_back(std::string(v.param), v.value);
        }
      }
      continue;
    }
    const ParamInfo* fixed = findParam(*model, name);
    if (fixed == nullptr) {
      usage("--set: '" + name + "' is not a parameter of " + o.model + " (it has " + paramNames(*model) + ")");
    }
    if (name == o.param) usage(option + ": " + name + " is the swept parameter (use --from and --to)");
    const glm::vec3 value = parseParamValue(option, set.substr(equals + 1), *fixed);
    try {
      setParam(scratch, name, value, option);
    } catch (const Error& error) {
      usage(error.what());
    }
    spec.fixed.emplace_back(name, value);
  }
  return spec;
}

// FNV-1a, 64 bits: a stable key of the text that decides the cells' pixels.
std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace

const char* const kSweepDescription =
    "render a parameter sweep of one BRDF model into a labelled contact sheet\n"
    "Renders a row of spheres sweeping one parameter of one BRDF model, like the figures of the original "
    "slides, into a contact sheet: one cell per value, each labelled, under a title line. Every sphere is seen "
    "and lit from the same directions (upper front left, one point light). Writes the sheet as FILE.exr (--out: "
    "linear cells, no text) and FILE.png (--png: tone-mapped, with text), as `raylab render` names its outputs; "
    "either given alone puts the other beside it. --gltf writes the sweep's scene instead (and also renders "
    "when --out or --png is given). Models and parameters are those of `raylab brdf` and docs/brdfs.md.";

void addSweepOptions(CLI::App* command, SweepOptions& o) {
  addText(command, "--model", o.model, "M", "the BRDF model: " + modelNames());
  addText(command, "--param", o.param, "P", "the parameter to sweep (one of the model's, or delta)");
  addText(command, "--from", o.from, "X", "first value (default: the parameter's minimum)");
  addText(command, "--to", o.to, "X", "last value (default: the parameter's maximum)");
  addCount(command, "--steps", o.steps, "number of spheres", 2, 64);
  addFlag(command, "--log", o.log, "geometric steps (default for exponents and roughnesses)");
  addFlag(command, "--linear", o.linear, "linear steps (default for the others)");
  addTextList(command, "--set", o.sets, "K=V",
              "another parameter of the model, RGB as r/g/b, or a named set of them (repeatable), e.g. --set "
              "rho_d=0.2/0.1/0.05, --set metal=Au");
  addText(command, "--out", o.exrPath, "FILE.exr",
          "the linear contact sheet (default out/sweep_<model>_<param>.exr; a .png name here is taken as --png)");
  addText(command, "--png", o.pngPath, "FILE.png", "the labelled, tone-mapped contact sheet (default: beside --out)");
  addText(command, "--gltf", o.gltfPath, "FILE.gltf", "write the sweep's scene as glTF 2.0");
  addCount(command, "--cell", o.cell, "cell size in pixels", 16, 2048);
  addCount(command, "--spp", o.spp, "samples per pixel", 1, 1u << 16);
  addSampleOptions(command, o.render);
  addToneOptions(command, o.exposure, o.toneMap, "the PNG");
  addBackendOption(command, o.backend);
  addDeviceOption(command, o.device);
}

std::string parseSweepArguments(const std::vector<std::string>& arguments, SweepOptions& options) {
  return parseCommandOptions(kCommand, kSweepDescription, [&](CLI::App* command) { addSweepOptions(command, options); },
                             arguments);
}

SweepStudy planSweep(SweepOptions o, SweepOutputs outputs) {
  const SweepSpec spec = validatedSpec(o);
  SweepStudy study;
  // `--out FILE.png` was the sheet's PNG before --out became the EXR everywhere: still accepted as --png.
  if (std::filesystem::path(o.exrPath).extension() == ".png") {
    if (!o.pngPath.empty()) usage("--out '" + o.exrPath + "' and --png: --out is the EXR (FILE.exr)");
    o.pngPath = std::exchange(o.exrPath, "");
  }
  study.render = o.gltfPath.empty() || !o.pngPath.empty() || !o.exrPath.empty();
  const std::string stem = "out/sweep_" + spec.model + "_" + spec.param;
  if (o.exrPath.empty()) {
    o.exrPath = o.pngPath.empty() ? stem + ".exr" : std::filesystem::path(o.pngPath).replace_extension(".exr").string();
  }
  if (o.pngPath.empty()) o.pngPath = std::filesystem::path(o.exrPath).replace_extension(".png").string();
  if (std::filesystem::path(o.exrPath).extension() != ".exr") usage("--out: '" + o.exrPath + "' must end in .exr");
  if (std::filesystem::path(o.pngPath).extension() != ".png") usage("--png: '" + o.pngPath + "' must end in .png");
  if (!o.gltfPath.empty() && std::filesystem::path(o.gltfPath).extension() != ".gltf") {
    usage("--gltf: '" + o.gltfPath + "' must end in .gltf");
  }
  study.pngPath = o.pngPath;
  study.exrPath = o.exrPath;
  const bool writes = outputs == SweepOutputs::CheckAndWrite;
  if (writes && !o.gltfPath.empty()) checkOutputPath(o.gltfPath, "--gltf");
  if (writes && study.render) {
    checkOutputPath(study.exrPath, "--out");
    checkOutputPath(study.pngPath, "--png");
  }
  study.sweep = makeSweepScene(spec);
  study.options = o;
  if (writes && !o.gltfPath.empty()) {
    writeSweepGltf(study.sweep, o.gltfPath);
    std::printf("wrote %s\n", o.gltfPath.c_str());
  }
  return study;
}

std::string sweepCellKey(const SweepStudy& study) {
  const SweepOptions& o = study.options;
  std::string text = o.model + "|" + o.param + "|" + std::to_string(o.cell) + "|" + std::to_string(o.spp) + "|" +
                     std::to_string(o.render.seed) + "|" + std::to_string(o.render.maxDepth) + "|" + o.backend;
  char value[32];
  for (float v : study.sweep.values) {
    std::snprintf(value, sizeof value, "|%a", double(v));
    text += value;
  }
  for (const auto& [name, v] : study.sweep.spec.fixed) {
    std::snprintf(value, sizeof value, "%a,%a,%a", double(v.x), double(v.y), double(v.z));
    text += "|" + name + "=" + value;
  }
  char key[17];
  std::snprintf(key, sizeof key, "%016llx", static_cast<unsigned long long>(fnv1a(text)));
  return key;
}

// One render per cell, not one render of the whole row: each sphere is rendered alone, at the same place, under
// the same camera and light, so that every sphere is seen and lit from exactly the same directions, as on the
// slides, and differences between cells come from the parameter alone (in a row, the camera and a point light see
// the outer spheres from other directions, and neighbours shadow each other and show in mirrors). Every cell uses
// the same seed, so the sampling noise is the same pattern in every cell too. One upload and one kernel serve
// every cell: only the material changes.
SweepCellRenderer::SweepCellRenderer(const SweepStudy& study, bool quiet) : gpu(study.options.device, quiet) {
  const Scene scene = cellScene(study.sweep);
  gpuScene = uploadScene(gpu.device, scene);
  try {
    RenderSettings settings = study.options.render;
    settings.width = study.options.cell;
    settings.height = study.options.cell;
    settings.backend = chooseBackend(gpu.device, parseBackendChoice(study.options.backend, "raylab sweep: --backend"));
    renderer = createRenderer(gpu.device, gpuScene, scene, settings);
  } catch (...) {
    destroyGpuScene(gpu.device, gpuScene);
    throw;
  }
}

SweepCellRenderer::~SweepCellRenderer() {
  destroyRenderer(gpu.device, renderer);
  destroyGpuScene(gpu.device, gpuScene);
}

Image renderSweepCell(SweepCellRenderer& cells, const SweepStudy& study, std::uint32_t cell,
                      const std::function<void(std::uint32_t)>& progress) {
  if (cell >= study.sweep.values.size()) {
    throw Error(std::string(kCommand) + ": cell " + std::to_string(cell) + " of a sweep of " +
                    std::to_string(study.sweep.values.size()),
                kExitUsage);
  }
  const Device& device = cells.gpu.device;
  Renderer& renderer = cells.renderer;
  const std::uint32_t spp = study.options.spp;
  if (updateMaterials(device, cells.gpuScene, cellMaterials(study.sweep, cell)).tablesReplaced) {
    writeSceneDescriptors(device, renderer.trace.descriptors.set, cells.gpuScene);
  }
  resetAccumulation(device, renderer);
  // Submissions of about a quarter second keep a progress line live (as in `raylab render`).
  std::uint32_t batch = 1;
  while (renderer.samplesDone < spp) {
    const Stopwatch batchClock;
    const std::uint32_t samples = std::min(batch, spp - renderer.samplesDone);
    renderSamples(device, renderer, samples);
    if (progress) progress(renderer.samplesDone);
    const double perSample = batchClock.seconds() / samples;
    batch = std::clamp<std::uint32_t>(static_cast<std::uint32_t>(0.25 / std::max(perSample, 1e-6)), 1, 256);
  }
  return readImage(device, renderer);
}

void writeSweepSheet(const SweepStudy& study, const std::vector<Image>& cells) {
  const SweepScene& sweep = study.sweep;
  if (cells.size() != sweep.values.size()) {
    throw Error(std::string(kCommand) + ": " + std::to_string(cells.size()) + " cells for a sweep of " +
                std::to_string(sweep.values.size()));
  }
  for (const Image& cell : cells) {
    if (cell.width != study.options.cell || cell.height != study.options.cell) {
      throw Error(std::string(kCommand) + ": a cell of " + std::to_string(cell.width) + "x" +
                  std::to_string(cell.height) + " in a sheet of " + std::to_string(study.options.cell) + "-pixel cells");
    }
  }
  const std::string title = sweepTitle(sweep);
  std::vector<std::string> labels;
  for (std::uint32_t i = 0; i < sweep.values.size(); ++i) labels.push_back(sweepLabel(sweep, i));
  const ContactSheetLayout layout = layoutContactSheet(std::uint32_t(cells.size()), study.options.cell, title, labels);
  const Image sheet = composeContactSheet(layout, cells);
  writeExr(study.exrPath, sheet);
  writePng(study.pngPath,
           annotateContactSheet(layout, sheet, study.options.exposure, parseToneMap(study.options.toneMap), title, labels));
  std::printf("%s\nwrote %s (%ux%u)\nwrote %s\n", title.c_str(), study.pngPath.c_str(), layout.width, layout.height,
              study.exrPath.c_str());
}

}  // namespace raylab
