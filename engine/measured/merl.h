// MERL BRDF database files (Matusik, Pfister, Brand & McMillan, "A Data-Driven Reflectance Model", SIGGRAPH 2003):
// reading with every check a user's download deserves, writing (the tests generate their files from known models:
// the database is not redistributable here), and the lookup of docs/brdfs.md ("measured"): Rusinkiewicz's
// half/difference angles, the database's own non-linear index in theta_h, nearest sample, negative = missing.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace raylab {

inline constexpr std::int32_t kMerlThetaH = 90;
inline constexpr std::int32_t kMerlThetaD = 90;
inline constexpr std::int32_t kMerlPhiD = 180;  // over [0, pi): reciprocity folds the other half
inline constexpr std::size_t kMerlSamples = std::size_t(kMerlThetaH) * kMerlThetaD * kMerlPhiD;  // 1,458,000
// Three int32 dimensions, then every red sample, every green, every blue, as float64: 34,992,012 bytes.
inline constexpr std::uint64_t kMerlFileBytes = 3 * sizeof(std::int32_t) + 3 * kMerlSamples * sizeof(double);
// The database's stored values are f times these per channel (its reader divides them out).
inline constexpr std::array<double, 3> kMerlScale = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

struct MerlTable {
  std::vector<double> stored;  // 3 * kMerlSamples, as in the file: red block, green block, blue block
  std::size_t missing = 0;     // samples that are negative in some channel (the database's missing data)
};

// Reads and checks a MERL file: a regular file of exactly kMerlFileBytes, dimensions 90 90 180, every sample
// finite, at least one sample present. Throws Error naming the file and what was wrong (FileError for the file
// itself).
MerlTable readMerl(const std::string& path);
MerlTable decodeMerl(const std::string& bytes, const std::string& where);

// The file's bytes, and the file written atomically.
std::string encodeMerl(const MerlTable& table);
void writeMerl(const std::string& path, const MerlTable& table);

// The sample index of a pair (docs/brdfs.md, "measured"); wi, wo unit, in the local frame, above the horizon.
std::size_t merlIndex(const glm::dvec3& wi, const glm::dvec3& wo);
// f(wi, wo), RGB: the stored sample times kMerlScale; 0 where the sample is missing or a direction is at or below
// the horizon.
glm::dvec3 merlLookup(const MerlTable& table, const glm::dvec3& wi, const glm::dvec3& wo);

// The table of a BRDF f(wi, wo) (RGB, per unit solid angle, without the cosine) sampled at the centre of every
// bin, so that merlLookup returns f exactly there: how the tests make MERL files of known models.
MerlTable tabulateMerl(const std::function<glm::dvec3(const glm::dvec3& wi, const glm::dvec3& wo)>& f);

// The pair (wi, wo) at half/difference angles (theta_h, theta_d, phi_d), with phi_h = 0.
void merlDirections(double thetaH, double thetaD, double phiD, glm::dvec3* wi, glm::dvec3* wo);
// The pair at the centre of bin (h, d, p); false where it does not exist (a direction at or below the horizon).
bool merlBinCentre(int h, int d, int p, glm::dvec3* wi, glm::dvec3* wo);

}  // namespace raylab
