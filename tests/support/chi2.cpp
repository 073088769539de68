#include "support/chi2.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace raylab::test {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMinDepth = 2;   // every cell is split into at least 4 x 4 Simpson panels
constexpr int kMaxDepth = 18;  // 2^18 panels per dimension: only reached at discontinuities

// Adaptive Simpson on [a, b] (Lyness 1969), given f at a, (a+b)/2, b and the Simpson value on the whole.
// Richardson's correction (S2 - S1)/15 is added once the two halves agree to 15 tol.
template <typename F>
double adaptiveSimpsonStep(const F& f, double a, double b, double fa, double fm, double fb, double whole,
                           double tolerance, int depth) {
  const double m = 0.5 * (a + b);
  const double flm = f(0.5 * (a + m));
  const double frm = f(0.5 * (m + b));
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double delta = left + right - whole;
  if (depth >= kMaxDepth || (depth >= kMinDepth && std::abs(delta) <= 15.0 * tolerance)) {
    return left + right + delta / 15.0;
  }
  return adaptiveSimpsonStep(f, a, m, fa, flm, fm, left, 0.5 * tolerance, depth + 1) +
         adaptiveSimpsonStep(f, m, b, fm, frm, fb, right, 0.5 * tolerance, depth + 1);
}

template <typename F>
double adaptiveSimpson(const F& f, double a, double b, double tolerance) {
  const double fa = f(a);
  const double fm = f(0.5 * (a + b));
  const double fb = f(b);
  return adaptiveSimpsonStep(f, a, b, fa, fm, fb, (b - a) / 6.0 * (fa + 4.0 * fm + fb), tolerance, 0);
}

// The pdf integrated over the cell [c0, c1] x [phi0, phi1] of (cos theta, phi), where dw = dcos dphi.
double cellIntegral(const std::function<double(const glm::dvec3&)>& pdf, double c0, double c1, double phi0,
                    double phi1, double tolerance) {
  // The inner integrals feed the outer rule; their error must stay well below what the outer one allows.
  const double innerTolerance = 0.1 * tolerance / (c1 - c0);
  auto overPhi = [&](double c) {
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    auto density = [&](double phi) { return pdf(glm::dvec3(s * std::cos(phi), s * std::sin(phi), c)); };
    return adaptiveSimpson(density, phi0, phi1, innerTolerance);
  };
  return adaptiveSimpson(overPhi, c0, c1, tolerance);
}

// Q(a, x) by its series for P = 1 - Q, for x < a + 1 (NR 6.2.5).
double lowerGammaSeriesP(double a, double x) {
  double term = 1.0 / a;
  double sum = term;
  for (int n = 1; n < 100000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-17) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) by its continued fraction (NR 6.2.7), for x >= a + 1, evaluated with modified Lentz.
double upperGammaFractionQ(double a, double x) {
  constexpr double kTiny = 1e-300;  // stands in for a zero denominator (Lentz's rule)
  double b = x + 1.0 - a;
  double c = 1.0 / kTiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

struct Cell {
  double expected = 0.0;
  double observed = 0.0;
  int theta = -1;  // -1: the cell of failed samples
  int phi = -1;
};

std::string describe(const Cell& cell, const Chi2Options& options) {
  char text[160];
  if (cell.theta < 0) {
    std::snprintf(text, sizeof text, "failed samples: observed %.0f, expected %.1f", cell.observed,
                  cell.expected);
  } else {
    const double dc = 2.0 / options.thetaCells;
    const double dphi = 360.0 / options.phiCells;
    std::snprintf(text, sizeof text, "cos in [%.3f, %.3f], phi in [%.1f, %.1f] deg: observed %.0f, expected %.1f",
                  -1.0 + cell.theta * dc, -1.0 + (cell.theta + 1) * dc, cell.phi * dphi,
                  (cell.phi + 1) * dphi, cell.observed, cell.expected);
  }
  return text;
}

}  // namespace

double upperIncompleteGammaQ(double a, double x) {
  if (!(a > 0.0) || !(x >= 0.0)) throw std::invalid_argument("upperIncompleteGammaQ: needs a > 0, x >= 0");
  if (x == 0.0) return 1.0;
  if (x < a + 1.0) return 1.0 - lowerGammaSeriesP(a, x);
  return upperGammaFractionQ(a, x);
}

double sidakSignificance(double significance, int testCount) {
  // 1 - (1 - a)^(1/n) via expm1/log1p: the direct form loses digits for small a and large n.
  return -std::expm1(std::log1p(-significance) / testCount);
}

Chi2Result chi2Test(std::span<const glm::dvec3> directions, std::size_t attempts,
                    const std::function<double(const glm::dvec3&)>& pdf, const Chi2Options& options) {
  Chi2Result result;
  result.correctedSignificance = sidakSignificance(options.significance, options.testCount);
  const int thetaCells = options.thetaCells;
  const int phiCells = options.phiCells;
  const double n = static_cast<double>(attempts);

  std::vector<Cell> cells(static_cast<std::size_t>(thetaCells) * phiCells);
  for (int i = 0; i < thetaCells; ++i) {
    for (int j = 0; j < phiCells; ++j) {
      Cell& cell = cells[i * phiCells + j];
      cell.theta = i;
      cell.phi = j;
      const double c0 = -1.0 + 2.0 * i / thetaCells;
      const double c1 = -1.0 + 2.0 * (i + 1) / thetaCells;
      const double phi0 = 2.0 * kPi * j / phiCells;
      const double phi1 = 2.0 * kPi * (j + 1) / phiCells;
      const double probability = cellIntegral(pdf, c0, c1, phi0, phi1, options.countTolerance / n);
      result.pdfIntegral += probability;
      cell.expected = n * probability;
    }
  }
  for (const glm::dvec3& w : directions) {
    const glm::dvec3 d = w / std::sqrt(glm::dot(w, w));  // float directions from the GPU are not quite unit
    double phi = std::atan2(d.y, d.x);
    if (phi < 0.0) phi += 2.0 * kPi;
    const int i = std::clamp(static_cast<int>((d.z + 1.0) * 0.5 * thetaCells), 0, thetaCells - 1);
    const int j = std::clamp(static_cast<int>(phi / (2.0 * kPi) * phiCells), 0, phiCells - 1);
    cells[i * phiCells + j].observed += 1.0;
  }
  Cell failed;
  failed.observed = n - static_cast<double>(directions.size());
  failed.expected = std::max(0.0, n * (1.0 - result.pdfIntegral));
  cells.push_back(failed);

  std::string problems;
  for (const Cell& cell : cells) {
    if (cell.theta >= 0 && cell.expected == 0.0 && cell.observed > 0.0) {
      problems += "  samples where the pdf is zero: " + describe(cell, options) + "\n";
    }
  }

  // Pool the cells expecting fewer than minExpected samples, smallest first, until the pool expects enough.
  std::vector<Cell> sorted = cells;
  std::sort(sorted.begin(), sorted.end(), [](const Cell& a, const Cell& b) { return a.expected < b.expected; });
  double statistic = 0.0;
  int terms = 0;
  double pooledObserved = 0.0;
  double pooledExpected = 0.0;
  std::vector<std::pair<double, const Cell*>> contributions;
  for (const Cell& cell : sorted) {
    if (cell.expected < options.minExpected || (pooledExpected > 0.0 && pooledExpected < options.minExpected)) {
      pooledObserved += cell.observed;
      pooledExpected += cell.expected;
      continue;
    }
    const double diff = cell.observed - cell.expected;
    statistic += diff * diff / cell.expected;
    contributions.emplace_back(diff * diff / cell.expected, &cell);
    ++terms;
  }
  if (pooledExpected > 0.0) {
    const double diff = pooledObserved - pooledExpected;
    statistic += diff * diff / pooledExpected;
    ++terms;
  }
  result.statistic = statistic;
  result.degreesOfFreedom = terms - 1;  // the counts sum to the attempts
  if (result.degreesOfFreedom > 0) {
    result.pValue = upperIncompleteGammaQ(0.5 * result.degreesOfFreedom, 0.5 * statistic);
  } else {
    problems += "  no degrees of freedom: the grid is too coarse for this lobe\n";
    result.pValue = 0.0;
  }
  result.passed = problems.empty() && result.pValue >= result.correctedSignificance;

  char line[256];
  std::snprintf(line, sizeof line,
                "chi2 = %.2f, dof = %d, p = %.4g (Sidak-corrected alpha = %.3g over %d tests): %s; "
                "integral of pdf = %.8f, %zu valid of %zu attempts\n",
                statistic, result.degreesOfFreedom, result.pValue, result.correctedSignificance, options.testCount,
                result.passed ? "accepted" : "REJECTED", result.pdfIntegral, directions.size(), attempts);
  result.report = line + problems;
  std::sort(contributions.begin(), contributions.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t k = 0; k < std::min<std::size_t>(3, contributions.size()); ++k) {
    std::snprintf(line, sizeof line, "  worst cell %zu: %s (adds %.1f)\n", k + 1,
                  describe(*contributions[k].second, options).c_str(), contributions[k].first);
    result.report += line;
  }
  return result;
}

}  // namespace raylab::test
