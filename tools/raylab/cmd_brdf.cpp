// `raylab brdf`: the BRDF library from the command line, one subcommand per job: eval (values of f and of
// glass) and albedo (brdf_albedo.cpp), the data of tools/brdf_plot.py.
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>

#include "args.h"
#include "brdf_eval/brdf_cases.h"
#include "brdf_eval/cpu_evaluator.h"
#include "brdf_eval/device_evaluator.h"
#include "brdf_commands.h"
#include "commands.h"
#include "gpu_session.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/timer.h"

namespace raylab {

namespace {

int runBrdfEval(int argc, char** argv) {
  std::string inPath;
  std::string outPath;
  std::string backend = "gpu";
  std::optional<std::uint32_t> deviceIndex;
  ArgParser args("raylab brdf eval", "--in CASES.csv --out VALUES.csv [options]",
                 "Evaluates the BRDF library on every row of CASES.csv and writes VALUES.csv\n"
                 "(docs/brdfs.md). Input columns: id,model,params,wi,wo,n,t, with params as\n"
                 "k=v;k=v (RGB as r/g/b; unnamed parameters take their defaults) and vectors as 'x y z';\n"
                 "glass may leave wo and t empty. Output columns: the same, then quantity,value: f for the\n"
                 "BRDF models, F_exact, F_schlick, F_schlick_naive, reflect, refract and tir for glass.\n"
                 "The gpu backend runs the shader library in one dispatch; cpu runs the double-precision\n"
                 "reference on the same float32 inputs. A malformed row is reported with its line and field,\n"
                 "the other rows are still written, and the exit code is 1.");
  args.option("--in", &inPath, "CASES.csv", "the cases to evaluate");
  args.option("--out", &outPath, "VALUES.csv", "where to write the values");
  args.choice("--backend", &backend, {"gpu", "cpu"}, "the shader library on the device, or the CPU reference (default gpu)");
  args.option("--device", &deviceIndex, "gpu backend: Vulkan device index from `raylab devices` (default: best capable)");
  if (!args.parse(argc, argv)) return kExitOk;
  if (inPath.empty()) throw Error("raylab brdf eval: --in is required (see `raylab brdf eval --help`)", kExitUsage);
  if (outPath.empty()) throw Error("raylab brdf eval: --out is required (see `raylab brdf eval --help`)", kExitUsage);
  checkOutputPath(outPath, "--out");

  const Stopwatch total;
  const BrdfCaseFile file = parseBrdfCases(readTextFile(inPath), inPath);
  for (const std::string& error : file.errors) std::fprintf(stderr, "raylab brdf eval: %s\n", error.c_str());

  std::vector<BrdfResult> results;
  results.reserve(file.cases.size());
  double evaluationSeconds = 0.0;
  if (backend == "gpu") {
    GpuSession session(deviceIndex);
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

struct Subcommand {
  const char* name;
  int (*run)(int, char**);
  const char* summary;
};

constexpr Subcommand kSubcommands[] = {
    {"eval", runBrdfEval, "evaluate the BRDF library on the cases of a CSV file (gpu or cpu backend)"},
    {"albedo", runBrdfAlbedo, "directional albedo of one material against the outgoing angle, as CSV"},
};

void printUsage(std::FILE* stream) {
  std::fprintf(stream, "Usage: raylab brdf <subcommand> [options]\n\n"
                       "The BRDF library of raylab (docs/brdfs.md) outside the renderer.\n\nSubcommands:\n");
  for (const Subcommand& s : kSubcommands) std::fprintf(stream, "  %-10s %s\n", s.name, s.summary);
  std::fprintf(stream, "\n`raylab brdf <subcommand> --help` describes each subcommand.\n");
}

}  // namespace

int runBrdf(int argc, char** argv) {
  if (argc < 1) {
    std::fprintf(stderr, "raylab brdf: which subcommand? (eval or albedo)\n\n");
    printUsage(stderr);
    return kExitUsage;
  }
  const std::string name = argv[0];
  if (name == "--help" || name == "-h") {
    printUsage(stdout);
    return kExitOk;
  }
  for (const Subcommand& s : kSubcommands) {
    if (name == s.name) return s.run(argc - 1, argv + 1);
  }
  throw Error("raylab brdf: unknown subcommand '" + name + "' (see `raylab brdf --help`)", kExitUsage);
}

}  // namespace raylab
