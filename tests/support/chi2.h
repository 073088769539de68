// χ² goodness-of-fit of a direction sampler against its pdf, in the manner of pbrt-v4 and Mitsuba 3: the
// sphere is cut into cells in (cos theta, phi), each cell's expected count is the pdf integrated over it
// (adaptive quadrature) times the sample count, cells with fewer than 5 expected samples are pooled, and the
// statistic's p-value is compared with a significance level corrected for the number of tests (Šidák).
#pragma once

#include <functional>
#include <span>
#include <string>

#include <glm/glm.hpp>

namespace raylab::test {

struct Chi2Options {
  int thetaCells = 10;       // cells in cos(theta) over [-1, 1]
  int phiCells = 20;         // cells in phi over [0, 2 pi)
  double significance = 0.01;
  int testCount = 1;         // tests in the whole suite, for the Šidák correction
  double minExpected = 5.0;  // cells expecting fewer samples are pooled
  // Absolute error allowed in each cell's expected count (probability times attempts); the adaptive
  // quadrature refines until it is met, so it must stay well below the statistical noise sqrt(expected).
  double countTolerance = 1e-3;
};

struct Chi2Result {
  double statistic = 0.0;
  int degreesOfFreedom = 0;
  double pValue = 1.0;
  double correctedSignificance = 0.0;
  double pdfIntegral = 0.0;  // the pdf integrated over the sphere: <= 1 (less when samples can fail)
  bool passed = false;
  std::string report;        // one paragraph for the test log: statistic, dof, p-value, worst cells
};

// `directions`: the unit directions of the valid samples (failed samples are left out), `attempts`: how many
// samples were drawn in all, valid or not. `pdf`: density per unit solid angle of one attempt.
// The failed attempts form one more cell, expecting attempts * (1 - integral of pdf), so that a sampler that
// fails too often (or a pdf that misses mass) is caught too. A sample in a cell where the pdf integrates to
// exactly 0 fails the test outright. Each cell's integral of the pdf is computed by nested adaptive Simpson
// quadrature in (cos theta, phi) with at least 4 x 4 panels per cell.
Chi2Result chi2Test(std::span<const glm::dvec3> directions, std::size_t attempts,
                    const std::function<double(const glm::dvec3&)>& pdf, const Chi2Options& options);

// The regularised upper incomplete gamma function Q(a, x) = Γ(a, x) / Γ(a), for a > 0, x >= 0: the p-value of a
// χ² statistic x with k degrees of freedom is Q(k/2, x/2). Series for x < a + 1, continued fraction beyond
// (Press et al., "Numerical Recipes", 3rd ed., 6.2), with a relative accuracy near 1e-13 in both tails.
double upperIncompleteGammaQ(double a, double x);

// Šidák's correction: the per-test significance that keeps the chance of any false alarm among `testCount`
// independent tests at `significance`: 1 - (1 - significance)^(1/testCount).
double sidakSignificance(double significance, int testCount);

}  // namespace raylab::test
