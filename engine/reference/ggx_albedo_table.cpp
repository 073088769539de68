// Writes the directional albedo of single-scattering GGX with F = 1, E(mu, alpha), and its cosine-weighted mean
// E_avg(alpha): the tables of ggx_conductor's multiple-scattering compensation (Kulla & Conty, "Revisiting
// Physically Based Shading at Imageworks", SIGGRAPH 2017 course). They are stored as the energy lost, 1 - E and
// 1 - E_avg, which float keeps to full relative precision where E is nearly 1 (the compensation divides by
// 1 - E_avg), in a C++ header: the reference reads it, and the host uploads it into the kernels' BRDF table buffer
// (shared/brdf_tables.h fixes the layout). Run at build time (tools/cmake/ggx_albedo.cmake); deterministic.
//
// E(mu) = integral of D G1(wi) G1(wo) / (4 cos_i cos_o) cos_i dwi. Drawing wi by GGX visible normals from wo
// (density G1(wo) D / (4 cos_o)) leaves the weight G1(wi) for wi above the horizon, 0 below: E is the mean of
// that weight, estimated on a stratified grid of kGrid x kGrid points.
//
// It also writes the albedo of the reflection of a GGX dielectric interface, the F-weighted E_r(mu, alpha, eps)
// with the exact Fresnel term of the index eta = (1 + eps) / (1 - eps) (eps = sqrt(F0)): openpbr's layers scale
// what lies below an interface by 1 - E_r (docs/brdfs.md, "openpbr"). The same sampler gives the weight
// F(wo.m) G1(wi). Stored as 1 - E_r, the light an interface passes on, which float keeps to full relative
// precision where E_r is nearly 1 (a smooth mirror's multiple scattering divides such small differences). Its eps = 1
// slice is F = 1: openpbr's metal takes its multiple scattering from it, with the mean
// of that slice as the kernels interpolate it.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "reference/ggx.h"
#include "reference/sampling.h"
#include "reference/terms.h"
#include "shared/brdf_tables.h"

namespace {

using raylab::reference::dvec2;
using raylab::reference::dvec3;

constexpr int kSize = raylab::gpu::kGgxAlbedoSize;  // mu and alpha entries
constexpr int kGrid = 256;  // stratified samples per axis per entry

// The table's axes: mu_j = j / (kSize - 1) and alpha_i = i / (kSize - 1), alpha clamped at the model's 0.001
// and mu at 1e-4 (where the masking of a grazing view is what the limit says: E -> 0 for alpha > 0).
double muAt(int j) { return std::max(1e-4, double(j) / (kSize - 1)); }
double alphaAt(int i) { return std::max(1e-3, double(i) / (kSize - 1)); }

// The dielectric table's axes (shared/brdf_tables.h): mu_j = (j / (size - 1))^2, dense at grazing where E_r
// turns fastest; alpha_i = (i / (size - 1))^2, the roughness r = sqrt(alpha) evenly, dense where smooth lobes
// change fastest; eps_k = k / (kDielectricEpsSize - 1).
constexpr int kEpsSize = raylab::gpu::kDielectricAlbedoEpsSize;
constexpr int kDielectricGrid = 64;
double squaredAxis(int j) { return double(j) * j / ((kSize - 1.0) * (kSize - 1.0)); }
double dielectricMuAt(int j) { return std::max(1e-4, squaredAxis(j)); }
double dielectricAlphaAt(int i) { return std::max(1e-3, squaredAxis(i)); }
double epsAt(int k) { return double(k) / (kEpsSize - 1); }

// 1 - E_avg of a row of the table (of 1 - E) as the kernels read it, linear in sqrt(mu) between entries: 2 integral
// (1 - E) mu dmu of that interpolant (4096 midpoints), so that the multiple-scattering term restores exactly what
// the table says single scattering loses.
double interpolatedAverageLoss(const double* lossRow) {
  constexpr int kPoints = 4096;
  double sum = 0.0;
  for (int n = 0; n < kPoints; ++n) {
    const double mu = (n + 0.5) / kPoints;
    const double x = std::sqrt(mu) * (kSize - 1);
    const int j = std::min(int(x), kSize - 2);
    sum += ((1.0 - (x - j)) * lossRow[j] + (x - j) * lossRow[j + 1]) * mu;
  }
  return 2.0 * sum / kPoints;
}

double dielectricAlbedo(double mu, double alpha, double eps) {
  if (eps <= 0.0) return 0.0;  // index 1: no interface
  const double eta = (1.0 + eps) / (1.0 - eps);
  const dvec3 wo(std::sqrt(1.0 - mu * mu), 0.0, mu);
  double sum = 0.0;
  for (int a = 0; a < kDielectricGrid; ++a) {
    // u.x, the squared radius on the visible-normal disk, is drawn densest near 1 (u.x = 1 - (1 - t)^3, weight
    // 3 (1 - t)^2): GGX's long tail, the normals tilted past 45 degrees that send wi below the horizon, holds a
    // share alpha^2 / (1 + alpha^2) of the normals, under one stratum of an even grid for small alpha.
    const double t = (a + 0.5) / kDielectricGrid;
    const double ux = 1.0 - (1.0 - t) * (1.0 - t) * (1.0 - t), weight = 3.0 * (1.0 - t) * (1.0 - t);
    for (int b = 0; b < kDielectricGrid; ++b) {
      const dvec3 m = raylab::reference::sampleGgxVisibleNormal(wo, alpha, alpha, dvec2(ux, (b + 0.5) / kDielectricGrid));
      const dvec3 wi = raylab::reference::reflectAbout(wo, m);
      if (!(wi.z > 0.0)) continue;
      const double F = eps >= 1.0 ? 1.0 : raylab::reference::F_DielectricFromOutside(eta, glm::dot(wo, m));
      sum += weight * F * raylab::reference::G1_GGX(wi, alpha, alpha);
    }
  }
  return sum / (double(kDielectricGrid) * kDielectricGrid);
}

double albedo(double mu, double alpha) {
  const dvec3 wo(std::sqrt(1.0 - mu * mu), 0.0, mu);
  double sum = 0.0;
  for (int a = 0; a < kGrid; ++a) {
    for (int b = 0; b < kGrid; ++b) {
      const dvec2 u((a + 0.5) / kGrid, (b + 0.5) / kGrid);
      const dvec3 m = raylab::reference::sampleGgxVisibleNormal(wo, alpha, alpha, u);
      const dvec3 wi = raylab::reference::reflectAbout(wo, m);
      if (wi.z > 0.0) sum += raylab::reference::G1_GGX(wi, alpha, alpha);
    }
  }
  return sum / (double(kGrid) * kGrid);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT.h\n", argv[0]);
    return 2;
  }
  std::vector<double> table(kSize * kSize), average(kSize);
  for (int i = 0; i < kSize; ++i) {
    for (int j = 0; j < kSize; ++j) table[i * kSize + j] = 1.0 - albedo(muAt(j), alphaAt(i));
    // E_avg = 2 integral E(mu) mu dmu, by the midpoint rule on 64 points of its own.
    double sum = 0.0;
    for (int k = 0; k < 64; ++k) {
      const double mu = (k + 0.5) / 64.0;
      sum += albedo(mu, alphaAt(i)) * mu;
    }
    average[i] = 1.0 - 2.0 * sum / 64.0;
  }
  std::vector<double> dielectric(std::size_t(kEpsSize) * kSize * kSize);
  for (int k = 0; k < kEpsSize; ++k) {
    for (int i = 0; i < kSize; ++i) {
      for (int j = 0; j < kSize; ++j) {
        dielectric[(std::size_t(k) * kSize + i) * kSize + j] =
            1.0 - dielectricAlbedo(dielectricMuAt(j), dielectricAlphaAt(i), epsAt(k));
      }
    }
  }
  // 2 integral F(mu) mu dmu of each eps's Fresnel term (4096 midpoints): openpbr's coat darkening reads it.
  std::vector<double> averageFresnel(kEpsSize);
  for (int k = 0; k < kEpsSize; ++k) {
    const double eps = epsAt(k), eta = (1.0 + eps) / (1.0 - eps);
    double sum = 0.0;
    for (int n = 0; n < 4096; ++n) {
      const double mu = (n + 0.5) / 4096.0;
      sum += (eps >= 1.0 ? 1.0 : eps <= 0.0 ? 0.0 : raylab::reference::F_DielectricFromOutside(eta, mu)) * mu;
    }
    averageFresnel[k] = 2.0 * sum / 4096.0;
  }
  std::vector<double> mirrorAverageLoss(kSize);
  for (int i = 0; i < kSize; ++i) {
    mirrorAverageLoss[i] = interpolatedAverageLoss(&dielectric[(std::size_t(kEpsSize - 1) * kSize + i) * kSize]);
  }
  std::ostringstream values, averages, dielectricValues, mirrorAverages, fresnelAverages;
  fresnelAverages.precision(9);
  for (int k = 0; k < kEpsSize; ++k) fresnelAverages << (k ? ", " : "") << averageFresnel[k];
  values.precision(9);
  averages.precision(9);
  dielectricValues.precision(9);
  mirrorAverages.precision(9);
  for (int i = 0; i < kSize; ++i) mirrorAverages << (i ? ", " : "") << mirrorAverageLoss[i];
  for (int k = 0; k < kSize * kSize; ++k) values << (k ? ", " : "") << table[k];
  for (std::size_t k = 0; k < dielectric.size(); ++k) dielectricValues << (k ? ", " : "") << dielectric[k];
  for (int i = 0; i < kSize; ++i) averages << (i ? ", " : "") << average[i];
  const std::string temporary = std::string(argv[1]) + ".tmp";
  {
    std::ofstream header(temporary);
    header << "// Generated by engine/reference/ggx_albedo_table.cpp at build time: do not edit.\n"
           << "// 1 - E(mu, alpha) of single-scattering GGX with F = 1 and 1 - E_avg(alpha), as shared/brdf_tables.h lays them out.\n"
           << "#pragma once\n\nnamespace raylab::reference {\n\n"
           << "inline constexpr double kGgxAlbedoLoss[" << kSize * kSize << "] = {" << values.str() << "};\n"
           << "inline constexpr double kGgxAverageLoss[" << kSize << "] = {" << averages.str() << "};\n"
           << "// 1 - E_r(mu, alpha, eps) of a GGX dielectric interface's reflection, as shared/brdf_tables.h lays it out.\n"
           << "inline constexpr double kDielectricAlbedoLoss[" << dielectric.size() << "] = {" << dielectricValues.str()
           << "};\n"
           << "// 1 - E_avg(alpha) of its eps = 1 slice (F = 1), as the kernels interpolate that slice.\n"
           << "inline constexpr double kMirrorAverageLoss[" << kSize << "] = {" << mirrorAverages.str() << "};\n"
           << "// 2 integral F(mu) mu dmu of the Fresnel term of each eps.\n"
           << "inline constexpr double kAverageFresnel[" << kEpsSize << "] = {" << fresnelAverages.str() << "};\n\n"
           << "}  // namespace raylab::reference\n";
    if (!header) return 1;
  }
  return std::rename(temporary.c_str(), argv[1]) == 0 ? 0 : 1;
}
