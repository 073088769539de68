// `raylab brdf`: the BRDF library from the command line, one subcommand per job: eval (values of f and of
// glass), albedo (brdf_albedo.cpp), the data of tools/brdf_plot.py, and models (brdf_models.cpp).
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include "command_line/cli.h"
#include "brdf_eval/brdf_cases.h"
#include "brdf_eval/cpu_evaluator.h"
#include "brdf_eval/device_evaluator.h"
#include "brdf_commands.h"
#include "commands.h"
#include "session/gpu_session.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/timer.h"

namespace raylab {

namespace {

struct EvalOptions {
  std::string inPath;
  std::string outPath;
  std::string backend = kDefaultBrdfBackend;
  std::optional<std::uint32_t> device;
};

int evaluate(const EvalOptions& o) {
  const std::string& outPath = o.outPath;
  const std::string& backend = o.backend;
  if (o.inPath.empty()) throw Error("raylab brdf eval: --in is required (see `raylab brdf eval --help`)", kExitUsage);
  if (outPath.empty()) throw Error("raylab brdf eval: --out is required (see `raylab brdf eval --help`)", kExitUsage);
  checkOutputPath(outPath, "--out");

  const Stopwatch total;
  const BrdfCaseFile file = parseBrdfCases(readInputFile(o.inPath, kMaxCaseFileBytes), o.inPath);
  for (const std::string& error : file.errors) std::fprintf(stderr, "raylab brdf eval: %s\n", error.c_str());

  std::vector<BrdfResult> results;
  results.reserve(file.cases.size());
  double evaluationSeconds = 0.0;
  if (backend == "gpu") {
    GpuSession session(o.device);
    std::vector<gpu::BrdfEvalCase> inputs;
    for (const BrdfCase& c : file.cases) inputs.push_back(c.input);
    for (const gpu::BrdfEvalValue& value : evaluateBrdfCasesOnce(session.device, inputs, &evaluationSeconds)) {
      results.push_back(fromDevice(value));
    }
  } else {
    const Stopwatch clock;
    for (const BrdfCase& c : file.cases) results.push_back(evaluateBrdfCaseOnCpu(c.input));
    evaluationSeconds = clock.seconds();
  }

  writeFileAtomically(outPath, formatBrdfValues(file.cases, results));

  std::fprintf(stderr, "raylab brdf eval: %zu rows (%zu malformed) on the %s backend: %s %.2f ms, total %.2f s\n",
               file.cases.size(), file.errors.size(), backend.c_str(), backend == "gpu" ? "dispatch" : "evaluation",
               evaluationSeconds * 1e3, total.seconds());
  return file.errors.empty() ? kExitOk : kExitFailure;
}

}  // namespace

void addBrdfCommands(CLI::App& raylab) {
  CLI::App* brdf = addCommandGroup(raylab, "brdf",
                                   "the BRDF library outside the renderer: brdf eval, brdf albedo, brdf models, brdf fit, brdf tabulate (docs/brdfs.md)");
  auto o = std::make_shared<EvalOptions>();
  CLI::App* command = addCommand(
      *brdf, "eval",
      "evaluate the BRDF library on the cases of a CSV file (gpu or cpu backend)\n"
      "Evaluates the BRDF library on every row of CASES.csv and writes VALUES.csv (docs/brdfs.md). Input "
      "columns: id,model,params,wi,wo,n,t, with params as k=v;k=v (RGB as r/g/b; unnamed parameters take their "
      "defaults) and vectors as 'x y z'; glass may leave wo and t empty. Output columns: the same, then "
      "quantity,value: f for the BRDF models, F_exact, F_schlick, F_schlick_naive, reflect, refract and tir for "
      "glass. The gpu backend runs the shader library in one dispatch; cpu runs the double-precision reference on "
      "the same float32 inputs. A malformed row is reported with its line and field, the other rows are still "
      "written, and the exit code is 1.",
      [o] { return evaluate(*o); });
  addText(command, "--in", o->inPath, "CASES.csv", "the cases to evaluate");
  addText(command, "--out", o->outPath, "VALUES.csv", "where to write the values");
  addChoice(command, "--backend", o->backend, {"gpu", "cpu"}, "the shader library on the device, or the CPU reference");
  addDeviceOption(command, o->device);
  addBrdfAlbedoCommand(*brdf);
  addBrdfModelsCommand(*brdf);
  addBrdfFitCommand(*brdf);
  addBrdfTabulateCommand(*brdf);
}

}  // namespace raylab
