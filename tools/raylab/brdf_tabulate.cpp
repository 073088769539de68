// `raylab brdf tabulate`: a MERL .binary file of any material of the library, sampled at the centre of every bin,
// so that the measured model, the fitter and their tests can be tried without the database (docs/fitting.md).
#include <cstdio>
#include <memory>
#include <string>

#include "brdf_commands.h"
#include "brdf_params/material_params.h"
#include "command_line/cli.h"
#include "util/atomic_file.h"
#include "measured/merl.h"
#include "reference/brdf_reference.h"
#include "util/error.h"
#include "util/files.h"
#include "util/timer.h"

namespace raylab {

namespace {

constexpr const char* kCommand = "raylab brdf tabulate";

struct TabulateOptions {
  std::string material;
  std::string outPath;
};

int tabulate(const TabulateOptions& o) {
  if (o.outPath.empty()) throw Error(std::string(kCommand) + ": --out is required", kExitUsage);
  checkOutputPath(o.outPath, "--out");
  requireExtension(kCommand, "--out", o.outPath, ".binary");
  const std::size_t colon = o.material.find(':');
  const ModelInfo* model = findModel(o.material.substr(0, colon));
  if (model == nullptr || isDeltaOnly(*model)) {
    throw Error(std::string(kCommand) + ": '" + o.material.substr(0, colon) +
                    "' is not a model with an f (models: " + modelNames() + ")",
                kExitUsage);
  }
  gpu::MaterialRecord record = defaultRecord(model->id);
  try {
    if (colon != std::string::npos) applyParamList(record, std::string_view(o.material).substr(colon + 1), kCommand);
    checkFileParams(record, kCommand);
  } catch (const Error& error) {
    throw Error(error.what(), kExitUsage);
  }
  const Stopwatch clock;
  const reference::Material material = reference::fromRecord(record);
  const MerlTable table =
      tabulateMerl([&](const glm::dvec3& wi, const glm::dvec3& wo) { return reference::eval(material, wi, wo); });
  writeMerl(o.outPath, table);
  std::fprintf(stderr, "%s: wrote %s (%s, %zu of 1,458,000 bins below the horizon, missing) in %.2f s\n", kCommand,
               o.outPath.c_str(), describeModelParams(record).c_str(), table.missing, clock.seconds());
  return kExitOk;
}

}  // namespace

void addBrdfTabulateCommand(CLI::App& brdf) {
  auto o = std::make_shared<TabulateOptions>();
  CLI::App* command = addCommand(
      brdf, "tabulate",
      "write a MERL .binary file of a material of the library\n"
      "Evaluates MODEL[:k=v,...] by the double-precision reference at the centre of each of the MERL database's "
      "90 x 90 x 180 bins (theta_h, theta_d, phi_d) and writes the file (bins whose centre lies below the horizon "
      "are missing, as in the database). The measured model then reproduces the material exactly at the bins' "
      "centres: how the tests and docs/fitting.md make measured materials without the database.",
      [o] { return tabulate(*o); });
  addPositional(command, "MATERIAL", o->material, "MODEL[:k=v,...], for example cooktorrance:rho_d=0.2,m=0.3");
  addText(command, "--out", o->outPath, "FILE.binary", "where to write the MERL file");
}

}  // namespace raylab
