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
Chi2Result chi2Test(std::span<const glm::dvec3> directions, std::size_t attempts,
                    const std::function<double(const glm::dvec3&)>& pdf, const Chi2Options& options);

// The regularised upper incomplete gamma function Q(a, x): the p-value of a χ² statistic x with 2a degrees
// of freedom is Q(dof/2, x/2).
double upperIncompleteGammaQ(double a, double x);

}  // namespace raylab::test
