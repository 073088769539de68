// The smooth dielectric of the reference (reference::glass) against optics: Snell's law, reversibility of
// refraction, F = 1 under total internal reflection, F = 0 at eta = 1, reflectance + transmittance = 1 with the
// transmittance computed independently from Fresnel's transmission amplitudes, continuity at the critical
// angle, and the documented behaviour of the two Schlick forms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "reference/brdf_reference.h"
#include "reference/terms.h"

namespace raylab::test {
namespace {

using reference::dvec3;
using reference::dielectricEvent;
using reference::DielectricEvent;
using reference::kPi;

const std::vector<double> kEtas = {1.0001, 1.33, 1.5, 2.4, 10.0};

// A direction making angle acos(c) with n (c < 0: on the inside), in a frame around an arbitrary world-space n
// so that nothing depends on n being the z axis.
struct WorldFrame {
  dvec3 n;
  dvec3 t;
  dvec3 b;
};

WorldFrame worldFrame(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const dvec3 n = glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
  const reference::Frame frame = reference::makeFrame(n, dvec3(normal(rng), normal(rng), normal(rng)));
  return {frame.n, frame.t, frame.b};
}

dvec3 incident(const WorldFrame& s, double c, double phi) {
  const double sine = std::sqrt((1.0 - c) * (1.0 + c));
  return sine * std::cos(phi) * s.t + sine * std::sin(phi) * s.b + c * s.n;
}

double sine(const dvec3& w, const dvec3& n) { return glm::length(glm::cross(w, n)); }

// Transmittance from Fresnel's transmission amplitudes (Born & Wolf 1.5.2), independent of the reflectance
// formula: T = (eta_t cos_t)/(eta_i cos_i) (t_s^2 + t_p^2)/2.
double transmittance(double etaI, double etaT, double cosI, double cosT) {
  const double ts = 2.0 * etaI * cosI / (etaI * cosI + etaT * cosT);
  const double tp = 2.0 * etaI * cosI / (etaT * cosI + etaI * cosT);
  return (etaT * cosT) / (etaI * cosI) * 0.5 * (ts * ts + tp * tp);
}

TEST(Glass, SnellsLawAndTheGeometryOfBothRays) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (double eta : kEtas) {
    for (int k = 0; k < 2000; ++k) {
      const WorldFrame s = worldFrame(rng);
      const bool outside = k % 2 == 0;
      const double c = (outside ? 1.0 : -1.0) * std::max(1e-9, uniform(rng));
      const dvec3 wi = incident(s, c, 2 * kPi * uniform(rng));
      const DielectricEvent g = dielectricEvent(eta, wi, s.n);
      const double etaI = outside ? 1.0 : eta;
      const double etaT = outside ? eta : 1.0;
      // Mirror reflection: unit, same side, same angle, in the plane of incidence.
      EXPECT_NEAR(glm::length(g.reflected), 1.0, 1e-12);
      EXPECT_NEAR(glm::dot(g.reflected, s.n), glm::dot(wi, s.n), 1e-12);
      EXPECT_NEAR(glm::dot(glm::cross(wi, s.n), g.reflected), 0.0, 1e-12);
      if (g.tir) {
        EXPECT_GE(etaI / etaT * sine(wi, s.n), 1.0 - 1e-12);
        continue;
      }
      // Refraction: unit, on the other side, in the plane of incidence, eta_i sin_i = eta_t sin_t.
      EXPECT_NEAR(glm::length(g.refracted), 1.0, 1e-12);
      EXPECT_LT(glm::dot(g.refracted, s.n) * glm::dot(wi, s.n), 0.0);
      EXPECT_NEAR(glm::dot(glm::cross(wi, s.n), g.refracted), 0.0, 1e-12);
      EXPECT_NEAR(etaI * sine(wi, s.n), etaT * sine(g.refracted, s.n), 1e-12 * eta);
    }
  }
}

TEST(Glass, RefractionIsReversibleAndFresnelIsTheSameBothWays) {
  // Light arriving along the refracted ray from the other side leaves along the original wi.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (double eta : kEtas) {
    for (int k = 0; k < 2000; ++k) {
      const WorldFrame s = worldFrame(rng);
      const double c = (k % 2 == 0 ? 1.0 : -1.0) * std::max(1e-6, uniform(rng));
      const dvec3 wi = incident(s, c, 2 * kPi * uniform(rng));
      const DielectricEvent there = dielectricEvent(eta, wi, s.n);
      if (there.tir) continue;
      const DielectricEvent back = dielectricEvent(eta, there.refracted, s.n);
      ASSERT_FALSE(back.tir);
      EXPECT_NEAR(glm::length(back.refracted - wi), 0.0, 1e-9) << "eta " << eta << " cos " << c;
      EXPECT_NEAR(back.fresnelExact, there.fresnelExact, 1e-9);
    }
  }
}

TEST(Glass, ReflectancePlusTransmittanceIsOne) {
  for (double eta : kEtas) {
    for (bool outside : {true, false}) {
      for (double c = 1.0; c > 1e-7; c *= 0.8) {
        const dvec3 wi(std::sqrt((1 - c) * (1 + c)), 0.0, outside ? c : -c);
        const DielectricEvent g = dielectricEvent(eta, wi, dvec3(0, 0, 1));
        if (g.tir) continue;
        const double etaI = outside ? 1.0 : eta;
        const double etaT = outside ? eta : 1.0;
        const double cosT = std::abs(g.refracted.z);
        EXPECT_NEAR(g.fresnelExact + transmittance(etaI, etaT, c, cosT), 1.0, 1e-12) << eta << " " << c;
        EXPECT_GE(g.fresnelExact, 0.0);
        EXPECT_LE(g.fresnelExact, 1.0);
      }
    }
  }
  // At normal incidence the exact and Schlick reflectances are both F0.
  EXPECT_NEAR(dielectricEvent(1.5, dvec3(0, 0, 1), dvec3(0, 0, 1)).fresnelExact, 0.04, 1e-15);
}

TEST(Glass, TotalInternalReflectionGivesFOfOne) {
  for (double eta : kEtas) {
    const double sinCritical = 1.0 / eta;
    // From inside, above the critical angle; not exactly on the horizon, where wi.n = -0 counts as outside.
    for (double sinI : {sinCritical + 1e-9, 0.5 * (1.0 + sinCritical), 1.0 - 1e-12}) {
      const dvec3 wi(sinI, 0.0, -std::sqrt((1.0 - sinI) * (1.0 + sinI)));
      const DielectricEvent g = dielectricEvent(eta, wi, dvec3(0, 0, 1));
      EXPECT_TRUE(g.tir) << eta << " " << sinI;
      EXPECT_EQ(g.fresnelExact, 1.0);
      EXPECT_EQ(g.fresnelSchlick, 1.0);
      EXPECT_EQ(g.refracted, dvec3(0.0));
      EXPECT_EQ(g.reflected, dvec3(-wi.x, 0.0, wi.z));  // mirrored back inside
    }
  }
}

TEST(Glass, NoInterfaceAtEtaOne) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int k = 0; k < 1000; ++k) {
    const dvec3 wi = glm::normalize(dvec3(uniform(rng), uniform(rng), uniform(rng)));
    const DielectricEvent g = dielectricEvent(1.0, wi, dvec3(0, 0, 1));
    EXPECT_EQ(g.fresnelExact, 0.0);
    EXPECT_FALSE(g.tir);
    EXPECT_EQ(g.refracted, -wi);  // the ray goes straight on
  }
  // Even exactly on the horizon, where Snell's sin^2 reaches 1 (docs/brdfs.md, "Glass").
  const DielectricEvent grazing = dielectricEvent(1.0, dvec3(1, 0, 0), dvec3(0, 0, 1));
  EXPECT_EQ(grazing.fresnelExact, 0.0);
  EXPECT_FALSE(grazing.tir);
}

TEST(Glass, CriticalAngleJustBelowAndAbove) {
  for (double eta : kEtas) {
    const double thetaC = std::asin(1.0 / eta);
    auto at = [eta](double theta) { return dielectricEvent(eta, dvec3(std::sin(theta), 0.0, -std::cos(theta)), dvec3(0, 0, 1)); };
    const DielectricEvent below = at(thetaC - 1e-8);
    const DielectricEvent above = at(thetaC + 1e-8);
    EXPECT_FALSE(below.tir) << eta;
    EXPECT_TRUE(above.tir) << eta;
    // Just below, the refracted ray leaves almost along the surface and F has almost reached 1 (it rises
    // like sqrt of the distance to the critical angle).
    EXPECT_LT(std::abs(below.refracted.z), 1e-2) << eta;
    EXPECT_GT(below.fresnelExact, 0.97) << eta;
    EXPECT_LT(below.fresnelExact, 1.0) << eta;
    // Schlick with the cosine on the thinner side also tends to 1 (cos_t -> 0); the naive form, with the
    // inside cos_i, stays far from it.
    EXPECT_GT(below.fresnelSchlick, 0.99) << eta;
    std::printf("eta %-7g critical angle %.4f deg: just below F_exact %.5f, F_schlick %.5f, F_schlick_naive %.5f\n",
                eta, thetaC * 180.0 / kPi, below.fresnelExact, below.fresnelSchlick, below.fresnelSchlickNaive);
  }
}

TEST(Glass, SchlickVariantsBehaveAsDocumented) {
  for (double eta : kEtas) {
    const double f0 = reference::F0FromEta(eta);
    for (double c : {1.0, 0.9, 0.5, 0.2, 0.01}) {
      const double s = std::sqrt((1 - c) * (1 + c));
      // From outside both Schlick forms use cos_i: they agree.
      const DielectricEvent outside = dielectricEvent(eta, dvec3(s, 0, c), dvec3(0, 0, 1));
      EXPECT_EQ(outside.fresnelSchlick, outside.fresnelSchlickNaive);
      EXPECT_NEAR(outside.fresnelSchlick, f0 + (1 - f0) * std::pow(1 - c, 5.0), 1e-15);
      // From inside: F_schlick uses cos_t (1 under TIR), F_schlick_naive the inside cos_i.
      const DielectricEvent inside = dielectricEvent(eta, dvec3(s, 0, -c), dvec3(0, 0, 1));
      EXPECT_NEAR(inside.fresnelSchlickNaive, f0 + (1 - f0) * std::pow(1 - c, 5.0), 1e-15);
      if (inside.tir) {
        EXPECT_EQ(inside.fresnelSchlick, 1.0);
      } else {
        EXPECT_NEAR(inside.fresnelSchlick, f0 + (1 - f0) * std::pow(1 - std::abs(inside.refracted.z), 5.0), 1e-14);
      }
      if (c < 1.0 && eta > 1.01) {
        EXPECT_NE(inside.fresnelSchlick, inside.fresnelSchlickNaive) << eta << " " << c;
      }
    }
  }
  // The thinner-side Schlick follows the exact reflectance closely on both sides; the naive one does not
  // from inside near the critical angle.
  const double eta = 1.5;
  double worstSchlick = 0.0;
  double worstNaive = 0.0;
  for (double c = 0.999; c > 0.0; c -= 0.001) {
    const double s = std::sqrt((1 - c) * (1 + c));
    for (double side : {1.0, -1.0}) {
      const DielectricEvent g = dielectricEvent(eta, dvec3(s, 0, side * c), dvec3(0, 0, 1));
      worstSchlick = std::max(worstSchlick, std::abs(g.fresnelSchlick - g.fresnelExact));
      worstNaive = std::max(worstNaive, std::abs(g.fresnelSchlickNaive - g.fresnelExact));
    }
  }
  std::printf("eta 1.5: largest |F_schlick - F_exact| %.4f, |F_schlick_naive - F_exact| %.4f\n", worstSchlick,
              worstNaive);
  EXPECT_LT(worstSchlick, 0.05);
  EXPECT_GT(worstNaive, 0.5);
}

}  // namespace
}  // namespace raylab::test
