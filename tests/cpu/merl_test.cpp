// MERL files (engine/measured/merl.h), made by the project's own writer from known models, since the database may
// not be redistributed: written and read back bit for bit, looked up exactly at the bins' centres and within a
// bin's width elsewhere, reciprocal, and every bad file refused with a message naming it.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <random>

#include "measured/merl.h"
#include "reference/terms.h"
#include "reference_materials.h"
#include "support/error_text.h"
#include "util/error.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;
using glm::dvec3;

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "raylab_merl_test";
  fs::create_directories(dir);
  return (dir / name).string();
}

dvec3 direction(double cosTheta, double phi) {
  const double s = std::sqrt((1.0 - cosTheta) * (1.0 + cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

// Cook-Torrance (Beckmann, Schlick, V-cavity) of the first library, a known glossy model to tabulate.
const reference::Material& glossy() {
  static const reference::Material material =
      makeMaterial("cooktorrance", {{"rho_d", 0.2}, {"rho_s", 0.8}, {"m", 0.3}, {"eta", 1.5}});
  return material;
}

TEST(Merl, WrittenAndReadBackBitForBit) {
  const MerlTable table = tabulateMerl([](const dvec3& wi, const dvec3& wo) { return reference::eval(glossy(), wi, wo); });
  const std::string path = scratch("cooktorrance.binary");
  writeMerl(path, table);
  EXPECT_EQ(fs::file_size(path), kMerlFileBytes);
  const MerlTable back = readMerl(path);
  EXPECT_EQ(back.stored, table.stored);
  EXPECT_EQ(back.missing, table.missing);
  // Pairs below the horizon are missing, as in the database: half of the (theta_h, theta_d) plane's far corner.
  std::printf("tabulated Cook-Torrance: %zu of %zu samples missing (pairs below the horizon)\n", back.missing,
              kMerlSamples);
  EXPECT_GT(back.missing, 0u);
  EXPECT_LT(back.missing, kMerlSamples / 2);
}

TEST(Merl, TheLookupReturnsTheModelAtEveryBinCentreAndIsReciprocal) {
  const MerlTable table = tabulateMerl([](const dvec3& wi, const dvec3& wo) { return reference::eval(glossy(), wi, wo); });
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> h(0, kMerlThetaH - 1), d(0, kMerlThetaD - 1), p(0, kMerlPhiD - 1);
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    const double u = (h(rng) + 0.5) / kMerlThetaH;
    dvec3 wi, wo;
    merlDirections(u * u * 0.5 * M_PI, (d(rng) + 0.5) / kMerlThetaD * 0.5 * M_PI, (p(rng) + 0.5) / kMerlPhiD * M_PI,
                   &wi, &wo);
    if (!(wi.z > 0.0 && wo.z > 0.0)) continue;
    const dvec3 expected = reference::eval(glossy(), wi, wo);
    const dvec3 looked = merlLookup(table, wi, wo);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(looked[c], expected[c], 1e-12 * expected[c]) << k;
    // The lookup folds phi_d by reciprocity: swapping wi and wo finds the same sample.
    EXPECT_EQ(merlLookup(table, wo, wi), looked) << k;
    ++checked;
  }
  EXPECT_GT(checked, 10000);
}

TEST(Merl, ADiffuseTableIsItsAlbedoOverPiEverywhere) {
  // Lambert is constant: the nearest-sample lookup is exact at any pair, not only at bin centres.
  const dvec3 rho(0.5, 0.3, 0.2);
  const MerlTable table = tabulateMerl([&](const dvec3&, const dvec3&) { return rho / reference::kPi; });
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> cosine(1e-3, 1.0), phi(0.0, 2.0 * M_PI);
  int found = 0, missing = 0;
  for (int k = 0; k < 20000; ++k) {
    const dvec3 f = merlLookup(table, direction(cosine(rng), phi(rng)), direction(cosine(rng), phi(rng)));
    if (f == dvec3(0.0)) {
      ++missing;  // a bin whose centre lies below the horizon, reached by a pair just above it
      continue;
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], rho[c] / reference::kPi, 1e-15);
    ++found;
  }
  std::printf("diffuse table at 20000 random pairs: %d exact, %d in bins whose centre is below the horizon\n", found,
              missing);
  EXPECT_LT(missing, 20000 / 50);
  EXPECT_EQ(merlLookup(table, direction(-0.5, 0.0), direction(0.5, 1.0)), dvec3(0.0)) << "below the horizon";
}

TEST(Merl, BadFilesAreRefusedNamingTheFile) {
  const MerlTable good = tabulateMerl([](const dvec3&, const dvec3&) { return dvec3(0.1); });
  const std::string bytes = encodeMerl(good);
  const auto write = [](const std::string& name, const std::string& content) {
    const std::string path = scratch(name);
    std::ofstream(path, std::ios::binary) << content;
    return path;
  };
  struct Case {
    std::string path;
    std::string mentions;
  };
  std::string wrongDimensions = bytes;
  const std::int32_t ninety = 90;
  std::memcpy(wrongDimensions.data() + 8, &ninety, 4);
  std::string withNan = bytes;
  const double nan = std::nan("");
  std::memcpy(withNan.data() + 12 + 8 * (kMerlSamples + 7), &nan, 8);
  MerlTable allMissing = good;
  for (double& value : allMissing.stored) value = -1.0;
  const std::string fifo = scratch("fifo.binary");
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const Case cases[] = {
      {write("truncated.binary", bytes.substr(0, bytes.size() - 8)), "truncated"},
      {write("longer.binary", bytes + "x"), "over raylab's limit"},
      {write("empty.binary", ""), "0 bytes"},
      {write("dimensions.binary", wrongDimensions), "dimensions 90 90 90"},
      {write("nan.binary", withNan), "1 sample is NaN or infinite, the first at channel 1 index 7"},
      {write("missing.binary", encodeMerl(allMissing)), "every sample is missing"},
      {scratch(""), "is a directory"},
      {fifo, "not a regular file"},
      {scratch("absent.binary"), "no such file"},
  };
  for (const Case& c : cases) {
    const std::string message = errorOf([&] { readMerl(c.path); });
    EXPECT_NE(message.find(c.path), std::string::npos) << message;
    EXPECT_NE(message.find(c.mentions), std::string::npos) << c.path << ": " << message;
  }
}

}  // namespace
}  // namespace raylab::test
