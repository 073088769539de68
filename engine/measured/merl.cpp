#include "measured/merl.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "scene/radiance_limits.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"
#include "util/number_text.h"

namespace raylab {

static_assert(std::endian::native == std::endian::little, "MERL files are little-endian, and so is this reader");

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::array<std::int32_t, 3> kDimensions = {kMerlThetaH, kMerlThetaD, kMerlPhiD};
constexpr std::size_t kHeaderBytes = 3 * sizeof(std::int32_t);

// Rodrigues' rotation of v about the unit axis by angle.
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + axis * (glm::dot(axis, v) * (1.0 - c)) + glm::cross(axis, v) * s;
}

int clampIndex(double value, int count) { return std::clamp(static_cast<int>(value), 0, count - 1); }

// The sample of bins (theta_h, theta_d, phi_d), in the file's order: phi_d fastest.
std::size_t binIndex(int h, int d, int p) {
  return std::size_t(p) + std::size_t(kMerlPhiD) * (std::size_t(d) + std::size_t(kMerlThetaD) * std::size_t(h));
}

}  // namespace

MerlTable decodeMerl(const std::string& bytes, const std::string& where) {
  if (bytes.size() != kMerlFileBytes) {
    throw Error(where + ": " + std::to_string(bytes.size()) + " bytes; a MERL file has " +
                std::to_string(kMerlFileBytes) + " (three int32 dimensions 90 90 180, then 3 x 1,458,000 float64)" +
                (bytes.size() < kMerlFileBytes ? ": truncated" : ""));
  }
  std::array<std::int32_t, 3> dimensions{};
  std::memcpy(dimensions.data(), bytes.data(), kHeaderBytes);
  if (dimensions != kDimensions) {
    throw Error(where + ": dimensions " + std::to_string(dimensions[0]) + " " + std::to_string(dimensions[1]) + " " +
                std::to_string(dimensions[2]) + "; a MERL file has 90 90 180 (theta_h, theta_d, phi_d)");
  }
  MerlTable table;
  table.stored.resize(3 * kMerlSamples);
  std::memcpy(table.stored.data(), bytes.data() + kHeaderBytes, table.stored.size() * sizeof(double));
  std::size_t nonFinite = 0, first = 0;
  for (std::size_t i = 0; i < table.stored.size(); ++i) {
    if (!std::isfinite(table.stored[i]) && nonFinite++ == 0) first = i;
  }
  if (nonFinite > 0) {
    throw Error(where + ": " + std::to_string(nonFinite) + (nonFinite == 1 ? " sample is" : " samples are") +
                " NaN or infinite, the first at channel " +
                std::to_string(first / kMerlSamples) + " index " + std::to_string(first % kMerlSamples));
  }
  // f is bounded as radiance is (scene/radiance_limits.h): a value a float cannot hold, or one that f times a
  // light would overflow, is refused rather than dropped on the device (1e42 used to become inf, and its samples
  // vanished from renders with exit 0).
  std::size_t huge = 0;
  for (std::size_t i = 0; i < table.stored.size(); ++i) {
    if (table.stored[i] * kMerlScale[i / kMerlSamples] > double(kMaxRadiance) && huge++ == 0) first = i;
  }
  if (huge > 0) {
    char value[64];  // nine digits: the scaled double, not its shortest form
    std::snprintf(value, sizeof value, "%.9g", table.stored[first] * kMerlScale[first / kMerlSamples]);
    throw Error(where + ": " + std::to_string(huge) + (huge == 1 ? " sample has" : " samples have") + " f above " +
                numberText(kMaxRadiance) + " /sr (the bound raylab keeps radiance within), the first at channel " +
                std::to_string(first / kMerlSamples) + " index " + std::to_string(first % kMerlSamples) + ": " + value);
  }
  for (std::size_t i = 0; i < kMerlSamples; ++i) {
    const bool missing = table.stored[i] < 0.0 || table.stored[i + kMerlSamples] < 0.0 ||
                         table.stored[i + 2 * kMerlSamples] < 0.0;
    table.missing += missing ? 1 : 0;
  }
  if (table.missing == kMerlSamples) throw Error(where + ": every sample is missing (negative)");
  return table;
}

MerlTable readMerl(const std::string& path) { return decodeMerl(readInputFile(path, kMerlFileBytes), path); }

std::string encodeMerl(const MerlTable& table) {
  if (table.stored.size() != 3 * kMerlSamples) throw Error("encodeMerl: the table does not hold 3 x 1,458,000 samples");
  std::string bytes(kMerlFileBytes, '\0');
  std::memcpy(bytes.data(), kDimensions.data(), kHeaderBytes);
  std::memcpy(bytes.data() + kHeaderBytes, table.stored.data(), table.stored.size() * sizeof(double));
  return bytes;
}

void writeMerl(const std::string& path, const MerlTable& table) { writeFileAtomically(path, encodeMerl(table)); }

std::size_t merlIndex(const glm::dvec3& wi, const glm::dvec3& wo) {
  // Rusinkiewicz's coordinates as the database's reader computes them: the half vector's angles, and wi turned
  // by -phi_h about the normal, then by -theta_h about the bitangent.
  const glm::dvec3 half = glm::normalize(wi + wo);
  const double thetaH = std::acos(std::clamp(half.z, -1.0, 1.0));
  const double phiH = std::atan2(half.y, half.x);
  const glm::dvec3 diff = rotate(rotate(wi, {0.0, 0.0, 1.0}, -phiH), {0.0, 1.0, 0.0}, -thetaH);
  const double thetaD = std::acos(std::clamp(diff.z, -1.0, 1.0));
  double phiD = std::atan2(diff.y, diff.x);
  if (phiD < 0.0) phiD += kPi;  // reciprocity: phi_d and phi_d + pi are the same pair
  const int h = thetaH <= 0.0 ? 0 : clampIndex(std::sqrt(thetaH / (0.5 * kPi)) * kMerlThetaH, kMerlThetaH);
  const int d = clampIndex(thetaD / (0.5 * kPi) * kMerlThetaD, kMerlThetaD);
  const int p = clampIndex(phiD / kPi * kMerlPhiD, kMerlPhiD);
  return binIndex(h, d, p);
}

glm::dvec3 merlLookup(const MerlTable& table, const glm::dvec3& wi, const glm::dvec3& wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return glm::dvec3(0.0);
  const std::size_t index = merlIndex(wi, wo);
  glm::dvec3 f;
  for (int c = 0; c < 3; ++c) f[c] = std::max(0.0, table.stored[index + c * kMerlSamples]) * kMerlScale[c];
  return f;
}

void merlDirections(double thetaH, double thetaD, double phiD, glm::dvec3* wi, glm::dvec3* wo) {
  const glm::dvec3 half(std::sin(thetaH), 0.0, std::cos(thetaH));
  const glm::dvec3 diff(std::sin(thetaD) * std::cos(phiD), std::sin(thetaD) * std::sin(phiD), std::cos(thetaD));
  *wi = rotate(diff, {0.0, 1.0, 0.0}, thetaH);
  *wo = 2.0 * glm::dot(half, *wi) * half - *wi;
}

bool merlBinCentre(int h, int d, int p, glm::dvec3* wi, glm::dvec3* wo) {
  // The centre of bin h of the non-linear axis: sqrt(theta_h / (pi/2)) * 90 = h + 1/2.
  const double u = (h + 0.5) / kMerlThetaH;
  merlDirections(u * u * 0.5 * kPi, (d + 0.5) / kMerlThetaD * 0.5 * kPi, (p + 0.5) / kMerlPhiD * kPi, wi, wo);
  return wi->z > 0.0 && wo->z > 0.0;
}

MerlTable tabulateMerl(const std::function<glm::dvec3(const glm::dvec3& wi, const glm::dvec3& wo)>& f) {
  MerlTable table;
  table.stored.assign(3 * kMerlSamples, 0.0);
  for (int h = 0; h < kMerlThetaH; ++h) {
    for (int d = 0; d < kMerlThetaD; ++d) {
      for (int p = 0; p < kMerlPhiD; ++p) {
        glm::dvec3 wi, wo;
        const std::size_t index = binIndex(h, d, p);
        if (!merlBinCentre(h, d, p, &wi, &wo)) {
          // Below the horizon the pair does not exist: the database marks such samples missing.
          for (int c = 0; c < 3; ++c) table.stored[index + c * kMerlSamples] = -1.0;
          ++table.missing;
          continue;
        }
        const glm::dvec3 value = f(wi, wo);
        for (int c = 0; c < 3; ++c) table.stored[index + c * kMerlSamples] = value[c] / kMerlScale[c];
      }
    }
  }
  return table;
}

}  // namespace raylab
