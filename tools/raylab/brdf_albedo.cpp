// `raylab brdf albedo`: the directional albedo a(wo) = integral of f(wi, wo) cos_i dwi of one material at a list
// of angles, as CSV for plots (tools/brdf_plot.py). The cpu backend is the reference's adaptive cubature
// (engine/reference/albedo.h); the gpu backend is a Monte Carlo estimate from the device's own sampler
// (bsdfSample in brdf_sample.comp), an independent cross-check of the shaders' sampling and evaluation.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "command_line/cli.h"
#include "brdf_eval/brdf_cases.h"
#include "brdf_eval/device_evaluator.h"
#include "brdf_commands.h"
#include "session/gpu_session.h"
#include "brdf_eval/albedo_estimate.h"
#include "brdf_params/material_params.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/timer.h"

namespace raylab {

namespace {

constexpr const char* kCommand = "raylab brdf albedo";


// "0,10,45,89.9": angles in degrees from the normal, each in [0, 90).
std::vector<double> parseAngles(const std::string& text) {
  std::vector<double> angles;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string entry = text.substr(start, end - start);
    double angle = 0.0;
    const auto [last, error] = std::from_chars(entry.data(), entry.data() + entry.size(), angle);
    const bool parsed = !entry.empty() && error == std::errc() && last == entry.data() + entry.size();
    if (!parsed || !(angle >= 0.0 && angle < 90.0)) {
      throw Error(std::string(kCommand) + ": --angles: expected angles in degrees in [0, 90) separated by commas, " +
                      "got '" + entry + "'",
                  kExitUsage);
    }
    angles.push_back(angle);
    start = end + 1;
  }
  return angles;
}

std::string formatCsv(const std::string& model, const std::string& params, const std::string& backend, double phiDeg,
                      const std::vector<AlbedoEstimate>& rows) {
  std::ostringstream out;
  out << "model,params,backend,theta_o,phi_o,albedo_r,albedo_g,albedo_b,error,evaluations\n";
  char line[512];
  for (const AlbedoEstimate& row : rows) {
    std::snprintf(line, sizeof line, "%s,%s,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%lld\n", model.c_str(), params.c_str(),
                  backend.c_str(), row.thetaDegrees, phiDeg, row.value.x, row.value.y, row.value.z, row.error,
                  row.evaluations);
    out << line;
  }
  return out.str();
}

}  // namespace

namespace {

struct AlbedoOptions {
  std::string model;
  std::string params;
  std::string angles = "0,10,20,30,40,50,60,70,80,85,88,89,89.9";
  float phiDeg = 0.0f;
  std::string backend = kDefaultBrdfBackend;
  std::uint32_t samples = 1u << 18;
  std::uint32_t seed = 1;
  float tolerance = 1e-6f;
  std::string outPath;
  std::optional<std::uint32_t> device;
};

int albedo(const AlbedoOptions& o) {
  const std::string& model = o.model;
  const std::string& params = o.params;
  const std::string& anglesText = o.angles;
  const double phiDeg = o.phiDeg;
  const std::string& backend = o.backend;
  const std::uint32_t samples = o.samples;
  const std::uint32_t seed = o.seed;
  const double tolerance = o.tolerance;
  const std::string& outPath = o.outPath;
  const std::optional<std::uint32_t>& deviceIndex = o.device;
  if (!outPath.empty()) checkOutputPath(outPath, "--out");
  if (model.empty()) {
    throw Error(std::string(kCommand) + ": --model is required (see `raylab brdf albedo --help`)", kExitUsage);
  }

  gpu::MaterialRecord record;
  try {
    record = parseMaterial(model, params, kCommand);
  } catch (const Error& error) {
    throw Error(error.what(), kExitUsage);
  }
  if (isDeltaOnly(record.model)) {
    throw Error(std::string(kCommand) + ": " + std::string(modelInfo(record.model).name) +
                    " is a delta BSDF and has no albedo integral; its reflectance is F_exact of `raylab brdf eval`",
                kExitUsage);
  }
  const std::vector<double> angles = parseAngles(anglesText);

  const Stopwatch clock;
  std::vector<AlbedoEstimate> rows;
  if (backend == "cpu") {
    for (double theta : angles) {
      rows.push_back(albedoByCubature(record, theta, phiDeg, tolerance));
      if (!rows.back().converged) {
        std::fprintf(stderr, "%s: warning: the cubature did not reach its tolerance at theta_o = %g (error estimate "
                     "%.3g)\n", kCommand, theta, rows.back().error);
      }
    }
  } else {
    GpuSession session(deviceIndex, true);
    BrdfSampler sampler = createBrdfSampler(session.device, samples);
    try {
      for (std::size_t i = 0; i < angles.size(); ++i) {
        const std::uint64_t angleSeed = std::uint64_t(seed) * 1000 + i;
        rows.push_back(albedoBySampling(session.device, sampler, record, angles[i], phiDeg, samples, angleSeed));
      }
    } catch (...) {
      destroyBrdfSampler(session.device, sampler);
      throw;
    }
    destroyBrdfSampler(session.device, sampler);
  }

  const std::string csv = formatCsv(model, params, backend, phiDeg, rows);
  if (outPath.empty()) {
    std::fputs(csv.c_str(), stdout);
  } else {
    writeFileAtomically(outPath, csv);
  }
  std::fprintf(stderr, "%s: %s, %zu angles on the %s backend in %.2f s\n", kCommand, model.c_str(), angles.size(),
               backend.c_str(), clock.seconds());
  return kExitOk;
}

}  // namespace

void addBrdfAlbedoCommand(CLI::App& brdf) {
  auto o = std::make_shared<AlbedoOptions>();
  CLI::App* command = addCommand(
      brdf, "albedo",
      "directional albedo of one material against the outgoing angle, as CSV\n"
      "Prints the directional albedo a(wo), the integral of f(wi, wo) cos_i over the hemisphere of wi, of one "
      "material at the outgoing angles theta_o of --angles (azimuth --phi from the tangent), as CSV: model,params,"
      "backend,theta_o,phi_o,albedo_r,albedo_g,albedo_b,error,evaluations. For a reciprocal model (all "
      "but openpbr, whose layers scale by the albedo seen from wo) a(wo) is also the fraction of light arriving "
      "from wo that is reflected; for openpbr it is the fraction of the light leaving towards wo, which is what its "
      "energy conservation bounds. The cpu backend integrates the "
      "double-precision reference by adaptive cubature (error: its estimate, largest channel); the gpu backend "
      "averages f cos_i / pdf over samples of the device's bsdfSample (error: one standard error, largest "
      "channel). delta, the mirror weight of the integrator, is not part of f and does not change the albedo. "
      "Glass is a delta BSDF: its reflectance is F_exact of `raylab brdf eval`.",
      [o] { return albedo(*o); });
  addText(command, "--model", o->model, "MODEL", "a model of `raylab brdf models`: " + modelNames());
  addText(command, "--params", o->params, "'k=v,k=v'",
          "parameters as in `raylab brdf eval` (RGB as r/g/b); others take defaults");
  addText(command, "--angles", o->angles, "LIST", "theta_o in degrees, in [0, 90), comma-separated", true);
  addNumber(command, "--phi", o->phiDeg, "azimuth of wo from the tangent, degrees", 0.0f, 360.0f);
  addChoice(command, "--backend", o->backend, {"gpu", "cpu"}, "device Monte Carlo or reference cubature");
  addCount(command, "--samples", o->samples, "gpu backend: samples per angle", 1, 1u << 22);
  addCount(command, "--seed", o->seed, "gpu backend: seed of the uniform numbers", 0, UINT32_MAX);
  addNumber(command, "--tolerance", o->tolerance, "cpu backend: relative tolerance of the cubature", 1e-12f, 1e-2f);
  addText(command, "--out", o->outPath, "FILE.csv", "write the CSV here instead of standard output");
  addDeviceOption(command, o->device);
}

}  // namespace raylab
