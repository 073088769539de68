// The fuzz layer (OpenPBR's fuzz after Zeltner, Burley & Chiang 2022; docs/brdfs.md, "Fuzz"), against what defines it:
//   - its lobe D(wi | wo) is a probability density over the hemisphere, and its sampler draws from it (a
//     chi-square test over cells of equal expected count, false-alarm rate 1e-4 per case);
//   - the committed table is the fibre volume's: at nodes of the table, fresh random walks (other seeds) reflect the
//     tabulated albedo (a z-test at 4.5 sigma over table and fresh noise) and leave in directions whose mean cosine
//     and mean tangential component the fitted lobe reproduces (the LTC is a fit: the distance is printed and
//     bounded);
//   - layered in openpbr it conserves energy as the specification's furnace list asks (a white fuzz over a white
//     metal or diffuse base, coated or not, has albedo 1), and a black fuzz darkens a white base by exactly
//     1 - fuzz_weight E_fuzz(mu_o): what the fuzz does not reflect it passes on, untinted.
// Regenerate the figures: ctest --test-dir build/release -R fuzz_test -V
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "reference/albedo.h"
#include "reference/fuzz.h"
#include "reference/fuzz_volume.h"
#include "reference/terms.h"
#include "reference_materials.h"

namespace raylab::test {
namespace {

using reference::dvec2;
using reference::dvec3;
using reference::FuzzLobe;
using reference::kPi;

constexpr double kDegree = kPi / 180.0;

dvec3 fromAngles(double thetaDeg) { return {std::sin(thetaDeg * kDegree), 0.0, std::cos(thetaDeg * kDegree)}; }

// The integral of D over the hemisphere by the midpoint rule in (cos theta, phi), fine enough for the broadest and
// the narrowest lobes of the table.
double integrateDensity(const FuzzLobe& lobe, const dvec3& wo) {
  constexpr int kN = 600;
  double sum = 0.0;
  for (int i = 0; i < kN; ++i) {
    const double c = (i + 0.5) / kN, s = std::sqrt(1.0 - c * c);
    for (int j = 0; j < kN; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / kN;
      sum += reference::fuzzDensity({s * std::cos(phi), s * std::sin(phi), c}, wo, lobe);
    }
  }
  return sum * 2.0 * kPi / (double(kN) * kN);
}

TEST(Fuzz, TheLobeIsADensityAndItsSamplerDrawsIt) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worstIntegral = 0.0;
  for (double roughness : {0.2, 0.5, 1.0}) {
    for (double theta : {0.0, 45.0, 80.0}) {
      const dvec3 wo = glm::normalize(fromAngles(theta) + dvec3(0.0, 0.3 * std::sin(theta * kDegree), 0.0));
      const FuzzLobe lobe = reference::fuzzLobe(wo.z, roughness);
      const double integral = integrateDensity(lobe, wo);
      worstIntegral = std::max(worstIntegral, std::abs(integral - 1.0));
      EXPECT_NEAR(integral, 1.0, 2e-3) << "roughness " << roughness << " theta " << theta;

      // Chi-square over 8 x 8 cells in (cos theta, phi), expected probabilities by the midpoint rule.
      constexpr int kCells = 8, kSub = 60, kSamples = 200000;
      std::vector<double> expected(kCells * kCells, 0.0), observed(kCells * kCells, 0.0);
      for (int i = 0; i < kCells * kSub; ++i) {
        const double c = (i + 0.5) / (kCells * kSub), s = std::sqrt(1.0 - c * c);
        for (int j = 0; j < kCells * kSub; ++j) {
          const double phi = 2.0 * kPi * (j + 0.5) / (kCells * kSub);
          expected[(i / kSub) * kCells + j / kSub] +=
              reference::fuzzDensity({s * std::cos(phi), s * std::sin(phi), c}, wo, lobe) * 2.0 * kPi /
              (double(kCells * kSub) * (kCells * kSub));
        }
      }
      for (int n = 0; n < kSamples; ++n) {
        const dvec3 wi = reference::sampleFuzz(wo, lobe, {uniform(random), uniform(random)});
        ASSERT_GT(wi.z, 0.0);
        const double phi = std::atan2(wi.y, wi.x) + (wi.y < 0.0 ? 2.0 * kPi : 0.0);
        const int i = std::min(kCells - 1, int(wi.z * kCells)), j = std::min(kCells - 1, int(phi / (2.0 * kPi) * kCells));
        observed[i * kCells + j] += 1.0;
      }
      double chi2 = 0.0;
      int dof = -1;
      double pooledExpected = 0.0, pooledObserved = 0.0;
      for (int k = 0; k < kCells * kCells; ++k) {
        const double e = expected[k] * kSamples;
        if (e < 5.0) {  // pooled, as Mitsuba's chi-square test does
          pooledExpected += e, pooledObserved += observed[k];
          continue;
        }
        chi2 += (observed[k] - e) * (observed[k] - e) / e;
        ++dof;
      }
      if (pooledExpected > 0.0) {
        chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++dof;
      }
      // The 1 - 1e-4 quantile of chi-square with dof degrees of freedom (Wilson-Hilferty), z = 3.719.
      const double z = 3.719, k = dof;
      const double bound = k * std::pow(1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k)), 3.0);
      EXPECT_LT(chi2, bound) << "roughness " << roughness << " theta " << theta << " dof " << dof;
    }
  }
  std::printf("fuzz lobe: worst |integral - 1| = %.1e\n", worstIntegral);
}

TEST(Fuzz, TheTableIsTheFibreVolumesFit) {
  constexpr std::int64_t kWalks = 100000, kTableWalks = 200000;  // fresh here, and the table's (its header)
  double worstMoment = 0.0;
  for (const auto& [i, j] : {std::pair{6, 10}, std::pair{15, 15}, std::pair{25, 5}, std::pair{31, 28}, std::pair{20, 1}}) {
    const double roughness = double(i) / (gpu::kFuzzLtcSize - 1), mu = double(j) / (gpu::kFuzzLtcSize - 1);
    const FuzzLobe lobe = reference::fuzzLobe(mu, roughness);
    std::mt19937_64 random(0xf0220000u + std::uint64_t(i * 64 + j));
    const dvec3 wo(std::sqrt(1.0 - mu * mu), 0.0, mu);
    std::int64_t reflected = 0;
    double meanZ = 0.0, meanX = 0.0;
    for (std::int64_t n = 0; n < kWalks; ++n) {
      if (const auto out = reference::walkFuzzVolume(wo, roughness, random)) {
        ++reflected;
        meanZ += out->z;
        meanX += out->x;
      }
    }
    const double albedo = double(reflected) / kWalks;
    const double sigma = std::sqrt(std::max(albedo * (1.0 - albedo), 1e-6) * (1.0 / kWalks + 1.0 / kTableWalks));
    EXPECT_NEAR(albedo, lobe.albedo, 4.5 * sigma) << "roughness " << roughness << " mu " << mu;
    meanZ /= std::max<std::int64_t>(reflected, 1);
    meanX /= std::max<std::int64_t>(reflected, 1);
    // The same moments of the fitted lobe, by the midpoint rule.
    constexpr int kN = 400;
    double lobeZ = 0.0, lobeX = 0.0;
    for (int a = 0; a < kN; ++a) {
      const double c = (a + 0.5) / kN, s = std::sqrt(1.0 - c * c);
      for (int b = 0; b < kN; ++b) {
        const double phi = 2.0 * kPi * (b + 0.5) / kN;
        const dvec3 w(s * std::cos(phi), s * std::sin(phi), c);
        const double d = reference::fuzzDensity(w, wo, lobe) * 2.0 * kPi / (double(kN) * kN);
        lobeZ += d * w.z;
        lobeX += d * w.x;
      }
    }
    const double distance = std::max(std::abs(lobeZ - meanZ), std::abs(lobeX - meanX));
    worstMoment = std::max(worstMoment, distance);
    std::printf("fuzz r %.2f mu %.2f: albedo %.4f (table %.4f); mean cos %.3f (lobe %.3f), mean x %.3f (lobe %.3f)\n",
                roughness, mu, albedo, lobe.albedo, meanZ, lobeZ, meanX, lobeX);
    EXPECT_LT(distance, 0.05) << "roughness " << roughness << " mu " << mu;
  }
  std::printf("fuzz table against fresh walks: worst moment distance %.3f\n", worstMoment);
}

double albedoOf(const reference::Material& m, double thetaDeg) {
  reference::AlbedoOptions options;
  options.relTolerance = 1e-6;
  options.maxRegions = 200000;
  const reference::Albedo albedo = reference::directionalAlbedo(m, reference::directionFromAngles(thetaDeg * kDegree, 30.0 * kDegree), options);
  EXPECT_TRUE(albedo.converged) << "theta " << thetaDeg;
  return albedo.value.x;
}

TEST(Fuzz, AWhiteFuzzKeepsTheFurnaceAndABlackOneDarkensByWhatItReflects) {
  double worst = 0.0;
  for (double metalness : {0.0, 1.0}) {
    for (double coat : {0.0, 1.0}) {
      for (double roughness : {0.2, 0.8}) {
        const reference::Material m = makeMaterial(
            "openpbr", {{"base_color", 1.0}, {"base_metalness", metalness}, {"specular_roughness", 0.4},
                        {"coat_weight", coat}, {"coat_roughness", 0.2}, {"fuzz_weight", 1.0}, {"fuzz_roughness", roughness}});
        for (double theta : {0.0, 60.0, 85.0}) {
          const double a = albedoOf(m, theta);
          worst = std::max(worst, std::abs(a - 1.0));
          EXPECT_NEAR(a, 1.0, 4e-3) << "metalness " << metalness << " coat " << coat << " r " << roughness << " theta " << theta;
        }
      }
    }
  }
  std::printf("white furnace under fuzz: worst |albedo - 1| = %.1e\n", worst);
  // A black fuzz of weight 0.7 over the white metal: 1 - 0.7 E_fuzz(mu_o).
  const reference::Material dark = makeMaterial("openpbr", {{"base_color", 1.0}, {"base_metalness", 1.0},
                                                            {"fuzz_weight", 0.7}, {"fuzz_color", 0.0},
                                                            {"fuzz_roughness", 0.5}});
  for (double theta : {0.0, 60.0, 85.0}) {
    const double expected = 1.0 - 0.7 * reference::fuzzLobe(std::cos(theta * kDegree), 0.5).albedo;
    EXPECT_NEAR(albedoOf(dark, theta), expected, 4e-3) << "theta " << theta;
  }
}

}  // namespace
}  // namespace raylab::test
