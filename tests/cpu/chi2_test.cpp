// The χ² machinery of tests/support/chi2 on its own: the incomplete gamma function against closed forms and
// tables, Šidák's correction, acceptance of correct samplers and, above all, rejection of wrong ones, so that
// a passing sampling test means something.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "reference/models.h"
#include "reference/sampling.h"
#include "reference/terms.h"
#include "reference_materials.h"
#include "support/chi2.h"

namespace raylab::test {
namespace {

using reference::dvec2;
using reference::dvec3;
using reference::kPi;

double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }  // [0, 1)

TEST(IncompleteGamma, MatchesClosedForms) {
  for (double x : {1e-6, 0.01, 0.5, 1.0, 2.0, 5.0, 20.0, 100.0, 600.0}) {
    const double exp1 = std::exp(-x);
    EXPECT_NEAR(upperIncompleteGammaQ(1.0, x), exp1, 1e-13 * exp1) << x;
    const double half = std::erfc(std::sqrt(x));
    EXPECT_NEAR(upperIncompleteGammaQ(0.5, x), half, 1e-12 * half) << x;
    // Integer a: Q(n, x) = exp(-x) sum_{k<n} x^k / k!.
    for (int n : {2, 5, 30}) {
      double term = 1.0;
      double sum = 0.0;
      for (int k = 0; k < n; ++k) {
        sum += term;
        term *= x / (k + 1);
      }
      const double exact = std::exp(-x) * sum;
      EXPECT_NEAR(upperIncompleteGammaQ(n, x), exact, 1e-12 * exact) << n << " " << x;
    }
  }
  EXPECT_EQ(upperIncompleteGammaQ(3.0, 0.0), 1.0);
}

TEST(IncompleteGamma, ReproducesChiSquareTables) {
  // Upper 1% points of the χ² distribution (Abramowitz & Stegun, table 26.8).
  struct Point {
    int dof;
    double x;
  };
  for (const Point& p : {Point{1, 6.63490}, Point{10, 23.2093}, Point{30, 50.8922}, Point{100, 135.807}}) {
    EXPECT_NEAR(upperIncompleteGammaQ(0.5 * p.dof, 0.5 * p.x), 0.01, 2e-6) << p.dof;
  }
  // Large dof (a fine grid): the median of χ²_k is close to k (1 - 2/(9k))^3.
  const int k = 3000;
  const double median = k * std::pow(1.0 - 2.0 / (9.0 * k), 3.0);
  EXPECT_NEAR(upperIncompleteGammaQ(0.5 * k, 0.5 * median), 0.5, 1e-3);
}

TEST(Sidak, CorrectsForTheNumberOfTests) {
  EXPECT_DOUBLE_EQ(sidakSignificance(0.01, 1), 0.01);
  EXPECT_NEAR(sidakSignificance(0.01, 50), 1.0 - std::pow(0.99, 1.0 / 50.0), 1e-15);
  EXPECT_NEAR(1.0 - std::pow(1.0 - sidakSignificance(0.01, 40), 40.0), 0.01, 1e-14);
}

std::vector<dvec3> uniformSphere(std::mt19937_64& rng, std::size_t count) {
  std::vector<dvec3> directions(count);
  for (dvec3& d : directions) {
    const double z = 1.0 - 2.0 * uniform01(rng);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * kPi * uniform01(rng);
    d = {r * std::cos(phi), r * std::sin(phi), z};
  }
  return directions;
}

TEST(Chi2, AcceptsCorrectSamplers) {
  std::mt19937_64 rng(1);
  const std::size_t n = 1000000;
  const Chi2Result sphere = chi2Test(uniformSphere(rng, n), n, [](const dvec3&) { return 1.0 / (4.0 * kPi); }, {});
  std::printf("uniform sphere: %s", sphere.report.c_str());
  EXPECT_TRUE(sphere.passed);
  EXPECT_NEAR(sphere.pdfIntegral, 1.0, 1e-9);

  std::vector<dvec3> cosine;
  for (std::size_t k = 0; k < n; ++k) {
    cosine.push_back(reference::sampleCosineHemisphere({uniform01(rng), uniform01(rng)}));
  }
  Chi2Options options;
  options.thetaCells = 20;
  options.phiCells = 40;
  const Chi2Result hemisphere = chi2Test(cosine, n, reference::pdfCosineHemisphere, options);
  std::printf("cosine hemisphere: %s", hemisphere.report.c_str());
  EXPECT_TRUE(hemisphere.passed);
}

TEST(Chi2, RejectsPhongSampledWithTheWrongExponent) {
  // Sampling phong's lobe with s * 1.2 against the pdf with s: the lobe is only 10% narrower.
  const reference::Material truth = makeMaterial("phong", {{"rho_d", 0}, {"rho_s", 1}, {"s", 20}});
  reference::Material wrong = truth;
  setParamExactly(wrong, "s", dvec3(1.2 * scalarParam(truth, "s")));
  const dvec3 wo = glm::normalize(dvec3(0.5, 0.2, 0.8));
  std::mt19937_64 rng(2);
  const std::size_t n = 1000000;
  std::vector<dvec3> directions;
  for (std::size_t k = 0; k < n; ++k) {
    const dvec3 wi = reference::sampleSpecular(wrong, wo, {uniform01(rng), uniform01(rng)});
    if (wi.z > 0.0) directions.push_back(wi);
  }
  Chi2Options options;
  options.thetaCells = 20;
  options.phiCells = 40;
  options.testCount = 40;  // a Šidák correction as large as the sampling suite's
  const auto start = std::chrono::steady_clock::now();
  const Chi2Result result =
      chi2Test(directions, n, [&](const dvec3& wi) { return reference::pdf(truth, wi, wo); }, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("phong sampled with s = 24 against the pdf of s = 20 (%.2f s): %s", seconds, result.report.c_str());
  EXPECT_FALSE(result.passed);
  EXPECT_LT(result.pValue, 1e-10);
  // The same samples against their own pdf pass.
  const Chi2Result own =
      chi2Test(directions, n, [&](const dvec3& wi) { return reference::pdf(wrong, wi, wo); }, options);
  std::printf("the same samples against their own pdf: %s", own.report.c_str());
  EXPECT_TRUE(own.passed);
}

TEST(Chi2, RejectsASamplerThatLosesSamples) {
  // Correct directions, but 1% of the attempts silently dropped while the pdf integrates to 1: only the cell
  // of failed samples can see it.
  std::mt19937_64 rng(3);
  const std::size_t n = 1000000;
  std::vector<dvec3> directions;
  for (std::size_t k = 0; k < n; ++k) {
    const dvec3 wi = reference::sampleCosineHemisphere({uniform01(rng), uniform01(rng)});
    if (uniform01(rng) >= 0.01) directions.push_back(wi);
  }
  const Chi2Result result = chi2Test(directions, n, reference::pdfCosineHemisphere, {});
  std::printf("cosine sampler losing 1%%: %s", result.report.c_str());
  EXPECT_FALSE(result.passed);
}

TEST(Chi2, RejectsSamplesWherePdfIsZero) {
  std::mt19937_64 rng(4);
  const std::size_t n = 100000;
  std::vector<dvec3> directions = uniformSphere(rng, n);  // half of them below the horizon
  const Chi2Result result = chi2Test(directions, n, reference::pdfCosineHemisphere, {});
  EXPECT_FALSE(result.passed);
  EXPECT_NE(result.report.find("pdf is zero"), std::string::npos) << result.report;
}

}  // namespace
}  // namespace raylab::test
