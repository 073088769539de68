#include "reference/cubature.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <utility>

namespace raylab::reference {

namespace {

// The 15-point Kronrod nodes on [-1, 1] (positive half, the last is 0) and their weights; the odd entries
// are the nodes of the embedded 7-point Gauss rule, whose weights follow.
constexpr std::array<double, 8> kKronrodNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr std::array<double, 8> kKronrodWeights = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kGaussWeights = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Rule {
  std::array<double, 15> node{};
  std::array<double, 15> kronrod{};
  std::array<double, 15> gauss{};  // 0 off the Gauss nodes
};

Rule makeRule() {
  Rule rule;
  for (int k = 0; k < 8; ++k) {
    const double gauss = (k % 2 == 1) ? kGaussWeights[k / 2] : 0.0;
    for (int side : {-1, 1}) {
      const int index = 7 + side * (7 - k);
      rule.node[index] = side * kKronrodNodes[k];
      rule.kronrod[index] = kKronrodWeights[k];
      rule.gauss[index] = gauss;
    }
  }
  return rule;
}

const Rule kRule = makeRule();

double largest(const dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

struct Region {
  dvec2 lower;
  dvec2 upper;
  dvec3 value{0.0};
  double error = 0.0;
  bool splitX = true;
  bool operator<(const Region& other) const { return error < other.error; }
};

void evaluate(const Integrand2d& f, Region& region) {
  const dvec2 centre = 0.5 * (region.lower + region.upper);
  const dvec2 half = 0.5 * (region.upper - region.lower);
  dvec3 kk(0.0), gk(0.0), kg(0.0), gg(0.0);
  for (int i = 0; i < 15; ++i) {
    const double x = centre.x + half.x * kRule.node[i];
    dvec3 kRow(0.0), gRow(0.0);
    for (int j = 0; j < 15; ++j) {
      const dvec3 value = f(x, centre.y + half.y * kRule.node[j]);
      kRow += kRule.kronrod[j] * value;
      gRow += kRule.gauss[j] * value;
    }
    kk += kRule.kronrod[i] * kRow;
    kg += kRule.kronrod[i] * gRow;
    gk += kRule.gauss[i] * kRow;
    gg += kRule.gauss[i] * gRow;
  }
  const double area = half.x * half.y;
  region.value = area * kk;
  region.error = area * largest(kk - gg);
  // Split along the coordinate whose Gauss rule misses more.
  region.splitX = largest(kk - gk) >= largest(kk - kg);
}

// The total value and error, summed afresh so that no drift of the running sums enters the result.
std::pair<dvec3, double> sumRegions(std::priority_queue<Region> queue) {
  dvec3 value(0.0);
  double error = 0.0;
  for (; !queue.empty(); queue.pop()) {
    value += queue.top().value;
    error += queue.top().error;
  }
  return {value, error};
}

}  // namespace

CubatureResult integrate2d(const Integrand2d& f, const dvec2& lower, const dvec2& upper,
                           const CubatureOptions& options) {
  std::priority_queue<Region> queue;
  CubatureResult result;
  const dvec2 step = (upper - lower) / dvec2(options.initialX, options.initialY);
  for (int i = 0; i < options.initialX; ++i) {
    for (int j = 0; j < options.initialY; ++j) {
      Region region{lower + step * dvec2(i, j), lower + step * dvec2(i + 1, j + 1)};
      if (i == options.initialX - 1) region.upper.x = upper.x;
      if (j == options.initialY - 1) region.upper.y = upper.y;
      evaluate(f, region);
      queue.push(region);
    }
  }
  int regions = options.initialX * options.initialY;
  auto [value, error] = sumRegions(queue);
  while (true) {
    const double target = std::max(options.absTolerance, options.relTolerance * largest(value));
    if (error <= target) {
      result.converged = true;
      break;
    }
    if (regions >= options.maxRegions) break;
    const Region worst = queue.top();
    queue.pop();
    Region a = worst;
    Region b = worst;
    if (worst.splitX) {
      a.upper.x = b.lower.x = 0.5 * (worst.lower.x + worst.upper.x);
    } else {
      a.upper.y = b.lower.y = 0.5 * (worst.lower.y + worst.upper.y);
    }
    evaluate(f, a);
    evaluate(f, b);
    value += a.value + b.value - worst.value;
    error += a.error + b.error - worst.error;
    queue.push(a);
    queue.push(b);
    ++regions;
  }
  const auto [finalValue, finalError] = sumRegions(queue);
  result.value = finalValue;
  result.errorEstimate = finalError;
  result.regions = regions;
  result.evaluations = 225LL * (2 * regions - options.initialX * options.initialY);
  return result;
}

}  // namespace raylab::reference
