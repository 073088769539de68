// `raylab sweep`: a row of spheres sweeping one parameter of one BRDF model, rendered into a labelled contact
// sheet (PNG, and the linear cells as OpenEXR beside it), the figures of the original slides; or the sweep's
// scene as glTF (--gltf), which is how assets/scenes/sweep_*.gltf are written.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli.h"
#include "commands.h"
#include "gpu_session.h"
#include "image/contact_sheet.h"
#include "image/image.h"
#include "render/renderer.h"
#include "render/gpu_scene.h"
#include "brdf_params/material_params.h"
#include "scene/sweep_gltf.h"
#include "scene/sweep_scene.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/progress.h"
#include "util/timer.h"

namespace raylab {

namespace {

constexpr const char* kCommand = "raylab sweep";

struct SweepOptions {
  std::string model;
  std::string param;
  std::string from;
  std::string to;
  std::uint32_t steps = 8;
  bool log = false;
  bool linear = false;
  std::vector<std::string> sets;
  std::string pngPath;
  std::string gltfPath;
  std::uint32_t cell = 192;  // labels as long as "alpha_x = 0.00139" fit at twice the font's size
  std::uint32_t spp = 64;
  RenderSettings render;     // --seed and --max-depth; the size is the cell's
  float exposure = 0.0f;
  std::string toneMap = "clamp";
  std::optional<std::uint32_t> device;
  std::string backend = "auto";
};

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

std::string modelNames() {
  std::string names;
  for (const ModelInfo& model : allModels()) names += (names.empty() ? "" : ", ") + std::string(model.name);
  return names;
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

// Renders every cell and returns them in order. One render per cell, not one render of the whole row: each
// sphere is rendered alone, at the same place, under the same camera and light, so that every sphere is seen
// and lit from exactly the same directions, as on the slides, and differences between cells come from the
// parameter alone (in a row, the camera and a point light see the outer spheres from other directions, and
// neighbours shadow each other and show in mirrors). Every cell uses the same seed, so the sampling noise is
// the same pattern in every cell too. One upload and one kernel serve every cell: only the material changes.
std::vector<Image> renderCells(const SweepOptions& o, const SweepScene& sweep) {
  const Scene scene = cellScene(sweep);
  GpuSession gpu(o.device);
  GpuScene gpuScene = uploadScene(gpu.device, scene);
  Renderer renderer;
  std::vector<Image> cells;
  try {
    RenderSettings settings = o.render;
    settings.width = o.cell;
    settings.height = o.cell;
    settings.backend = chooseBackend(gpu.device, parseBackendChoice(o.backend));
    renderer = createRenderer(gpu.device, gpuScene, scene, settings);
    const std::uint32_t count = std::uint32_t(sweep.values.size());
    // One line for the whole sheet: its samples count those of every cell.
    ProgressLine progress(std::string(kCommand) + " (all " + std::to_string(count) + " cells)",
                          std::uint64_t(count) * o.spp);
    const Stopwatch clock;
    for (std::uint32_t i = 0; i < count; ++i) {
      updateMaterials(gpu.device, gpuScene, cellMaterials(sweep, i));
      resetAccumulation(gpu.device, renderer);
      // Submissions of about a quarter second keep the progress line live (as in `raylab render`).
      std::uint32_t batch = 1;
      while (renderer.samplesDone < o.spp) {
        const Stopwatch batchClock;
        const std::uint32_t samples = std::min(batch, o.spp - renderer.samplesDone);
        renderSamples(gpu.device, renderer, samples);
        progress.update(std::uint64_t(i) * o.spp + renderer.samplesDone, renderer.rays.total());
        const double perSample = batchClock.seconds() / samples;
        batch = std::clamp<std::uint32_t>(static_cast<std::uint32_t>(0.25 / std::max(perSample, 1e-6)), 1, 256);
      }
      cells.push_back(readImage(gpu.device, renderer));
    }
    progress.finish();
    std::printf("rendered %u cells of %ux%u, %u spp, in %s (%s)\n", count, o.cell, o.cell, o.spp,
                formatSeconds(clock.seconds()).c_str(), formatCount(double(renderer.rays.total()), "rays").c_str());
  } catch (...) {
    destroyRenderer(gpu.device, renderer);
    destroyGpuScene(gpu.device, gpuScene);
    throw;
  }
  destroyRenderer(gpu.device, renderer);
  destroyGpuScene(gpu.device, gpuScene);
  return cells;
}

// The sweep the options ask for; `o` by value: defaults are filled in.
void sweep(SweepOptions o) {
  const SweepSpec spec = validatedSpec(o);
  const bool render = o.gltfPath.empty() || !o.pngPath.empty();
  if (o.pngPath.empty()) o.pngPath = "out/sweep_" + spec.model + "_" + spec.param + ".png";
  if (std::filesystem::path(o.pngPath).extension() != ".png") {
    usage("--out: '" + o.pngPath + "' must end in .png (the EXR is written beside it)");
  }
  if (!o.gltfPath.empty() && std::filesystem::path(o.gltfPath).extension() != ".gltf") {
    usage("--gltf: '" + o.gltfPath + "' must end in .gltf");
  }

  const std::string exrPath = std::filesystem::path(o.pngPath).replace_extension(".exr").string();
  if (!o.gltfPath.empty()) checkOutputPath(o.gltfPath, "--gltf");
  if (render) {
    checkOutputPath(o.pngPath, "--out");
    checkOutputPath(exrPath, "--out (the EXR beside it)");
  }

  const SweepScene sweep = makeSweepScene(spec);
  if (!o.gltfPath.empty()) {
    writeSweepGltf(sweep, o.gltfPath);
    std::printf("wrote %s\n", o.gltfPath.c_str());
  }
  if (!render) return;

  const std::vector<Image> cells = renderCells(o, sweep);
  const std::string title = sweepTitle(sweep);
  std::vector<std::string> labels;
  for (std::uint32_t i = 0; i < sweep.values.size(); ++i) labels.push_back(sweepLabel(sweep, i));
  const ContactSheetLayout layout = layoutContactSheet(std::uint32_t(cells.size()), o.cell, title, labels);
  const Image sheet = composeContactSheet(layout, cells);
  writeExr(exrPath, sheet);
  writePng(o.pngPath, annotateContactSheet(layout, sheet, o.exposure, parseToneMap(o.toneMap), title, labels));
  std::printf("%s\nwrote %s (%ux%u)\nwrote %s\n", title.c_str(), o.pngPath.c_str(), layout.width, layout.height,
              exrPath.c_str());
}

}  // namespace

void addSweepCommand(CLI::App& raylab) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* command = addCommand(
      raylab, "sweep",
      "render a parameter sweep of one BRDF model into a labelled contact sheet\n"
      "Renders a row of spheres sweeping one parameter of one BRDF model, like the figures of the original "
      "slides, into a contact sheet: one cell per value, each labelled, under a title line. Every sphere is seen "
      "and lit from the same directions (upper front left, one point light). Writes FILE.png (tone-mapped, with "
      "text) and FILE.exr beside it (linear cells, no text). --gltf writes the sweep's scene instead (and also "
      "renders when --out is given). Models and parameters are those of `raylab brdf` and docs/brdfs.md.",
      [o] {
        sweep(*o);
        return kExitOk;
      });
  addText(command, "--model", o->model, "M", "the BRDF model: " + modelNames());
  addText(command, "--param", o->param, "P", "the parameter to sweep (one of the model's, or delta)");
  addText(command, "--from", o->from, "X", "first value (default: the parameter's minimum)");
  addText(command, "--to", o->to, "X", "last value (default: the parameter's maximum)");
  addCount(command, "--steps", o->steps, "number of spheres", 2, 64);
  addFlag(command, "--log", o->log, "geometric steps (default for exponents and roughnesses)");
  addFlag(command, "--linear", o->linear, "linear steps (default for the others)");
  addTextList(command, "--set", o->sets, "K=V",
              "another parameter of the model, RGB as r/g/b (repeatable), e.g. --set rho_d=0.2/0.1/0.05");
  addText(command, "--out", o->pngPath, "FILE.png", "the contact sheet (default out/sweep_<model>_<param>.png)");
  addText(command, "--gltf", o->gltfPath, "FILE.gltf", "write the sweep's scene as glTF 2.0");
  addCount(command, "--cell", o->cell, "cell size in pixels", 16, 2048);
  addCount(command, "--spp", o->spp, "samples per pixel", 1, 1u << 16);
  addSampleOptions(command, o->render);
  addToneOptions(command, o->exposure, o->toneMap, "the PNG");
  addBackendOption(command, o->backend);
  addDeviceOption(command, o->device);
}

}  // namespace raylab
