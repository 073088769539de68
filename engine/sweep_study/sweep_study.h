// `raylab sweep`'s study, shared by the command and by the Python farm (`python -m raylab.farm sweep`, which takes
// exactly these options and renders the cells on a Dask cluster): the options and their checks, the row of
// spheres, one cell's render, and the contact sheet. Every cell is an independent job: the same options give the
// same cell bit for bit on any process, in any order.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "session/gpu_session.h"
#include "image/image.h"
#include "render/gpu_scene.h"
#include "render/renderer.h"
#include "sweep/sweep_scene.h"

namespace CLI {
class App;
}  // namespace CLI

namespace raylab {

// What `raylab sweep` was given.
struct SweepOptions {
  std::string model;
  std::string param;
  std::string from;
  std::string to;
  std::uint32_t steps = 8;
  bool log = false;
  bool linear = false;
  std::vector<std::string> sets;
  std::string exrPath;  // --out: the linear sheet, as `raylab render --out`
  std::string pngPath;  // --png: the labelled, tone-mapped sheet
  std::string gltfPath;
  std::uint32_t cell = 192;  // labels as long as "alpha_x = 0.00139" fit at twice the font's size
  std::uint32_t spp = 64;
  RenderSettings render;     // --seed and --max-depth; the size is the cell's
  float exposure = 0.0f;
  std::string toneMap = "clamp";
  std::optional<std::uint32_t> device;
  std::string backend{kBackendOption.defaultValue};
};


// The command's description (its help) and its options, declared once for both callers.
extern const char* const kSweepDescription;
void addSweepOptions(CLI::App* command, SweepOptions& options);

// The options parsed as `raylab sweep ARGUMENTS` would parse them, without running anything. Returns the help text
// when --help was given (empty otherwise); throws Error(kExitUsage) with the command's message on a usage error.
std::string parseSweepArguments(const std::vector<std::string>& arguments, SweepOptions& options);

struct SweepStudy {
  SweepOptions options;
  SweepScene sweep;
  std::string pngPath;  // the contact sheet
  std::string exrPath;  // its linear cells, beside it
  bool render = true;   // false: --gltf alone
};

// Whether planSweep checks the output paths (creating their directories) and writes --gltf: the command and the
// farm's client do; the farm's workers, which only render cells (maybe on other machines), do not.
enum class SweepOutputs { CheckAndWrite, None };

// Checks the options (every message names the option and the accepted range) and, unless told not to, the output
// paths; fills in the defaults and lays out the row. Writes --gltf when given.
SweepStudy planSweep(SweepOptions options, SweepOutputs outputs = SweepOutputs::CheckAndWrite);

// What decides a cell's pixels (model, parameters, values, cell size, samples, seed, depth, backend), as a short
// hexadecimal key: the farm keeps finished cells under it, so that a rerun with other options renders anew.
std::string sweepCellKey(const SweepStudy& study);

// One device's cell renders: the cell scene uploaded once, one renderer; only the material changes per cell.
struct SweepCellRenderer {
  explicit SweepCellRenderer(const SweepStudy& study, bool quiet = false);
  ~SweepCellRenderer();
  SweepCellRenderer(const SweepCellRenderer&) = delete;
  SweepCellRenderer& operator=(const SweepCellRenderer&) = delete;

  GpuSession gpu;
  GpuScene gpuScene;
  Renderer renderer;
};

// Renders cell `cell` (spp samples, in submissions of about a quarter second). `progress(samplesDone)` is called
// after each submission; it may throw to stop the render there (Ctrl-C in Python).
Image renderSweepCell(SweepCellRenderer& cells, const SweepStudy& study, std::uint32_t cell,
                      const std::function<void(std::uint32_t)>& progress = {});

// The contact sheet of the cells, in order: FILE.exr (linear cells) and FILE.png (tone-mapped, title and labels),
// each written atomically; prints what `raylab sweep` prints.
void writeSweepSheet(const SweepStudy& study, const std::vector<Image>& cells);

}  // namespace raylab
