// `raylab sweep`: a row of spheres sweeping one parameter of one BRDF model, rendered into a labelled contact
// sheet (PNG, and the linear cells as OpenEXR beside it), the figures of the original slides; or the sweep's
// scene as glTF (--gltf), which is how assets/scenes/sweep_*.gltf are written. The study itself (options,
// cells, sheet) is sweep_study.h, which the Python farm shares.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "command_line/cli.h"
#include "commands.h"
#include "sweep_study/sweep_study.h"
#include "util/error.h"
#include "util/progress.h"
#include "util/timer.h"

namespace raylab {

namespace {

void sweep(const SweepOptions& options) {
  const SweepStudy study = planSweep(options);
  if (!study.render) return;
  const SweepOptions& o = study.options;
  std::vector<Image> cells;
  {
    SweepCellRenderer renderer(study);
    const std::uint32_t count = std::uint32_t(study.sweep.values.size());
    // One line for the whole sheet: its samples count those of every cell ("64/64 spp" for 4 cells of 16 spp
    // read as 64 samples per pixel).
    ProgressLine progress("raylab sweep", std::uint64_t(count) * o.spp, stderr,
                          "samples (" + std::to_string(o.spp) + " spp x " + std::to_string(count) + " cells)");
    const Stopwatch clock;
    for (std::uint32_t i = 0; i < count; ++i) {
      cells.push_back(renderSweepCell(renderer, study, i, [&](std::uint32_t samplesDone) {
        progress.update(std::uint64_t(i) * o.spp + samplesDone, renderer.renderer.rays.total());
      }));
    }
    progress.finish();
    std::printf("rendered %u cells of %ux%u, %u spp, in %s (%s)\n", count, o.cell, o.cell, o.spp,
                formatSeconds(clock.seconds()).c_str(),
                formatCount(double(renderer.renderer.rays.total()), "rays").c_str());
  }
  writeSweepSheet(study, cells);
}

}  // namespace

void addSweepCommand(CLI::App& raylab) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* command = addCommand(raylab, "sweep", kSweepDescription, [o] {
    sweep(*o);
    return kExitOk;
  });
  addSweepOptions(command, *o);
}

}  // namespace raylab
