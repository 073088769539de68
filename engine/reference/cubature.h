// Globally adaptive cubature over a rectangle with the tensor product of the 15-point Gauss-Kronrod rule
// (the 1-D rule of QUADPACK's qk15: Piessens et al., "QUADPACK", Springer 1983). Each region's error is
// estimated by the difference to the embedded 7-point Gauss product rule; the region with the largest error
// is halved along the coordinate that contributes most of it, until the summed error meets the tolerance.
// The integrand is RGB so that one pass integrates all three channels.
#pragma once

#include <functional>

#include <glm/glm.hpp>

namespace raylab::reference {

using glm::dvec2;
using glm::dvec3;

struct CubatureOptions {
  double relTolerance = 1e-8;   // of the largest channel of the result
  double absTolerance = 0.0;
  int maxRegions = 20000;       // 225 integrand calls each
  int initialX = 4;             // the starting grid of regions
  int initialY = 8;
};

struct CubatureResult {
  dvec3 value{0.0};
  double errorEstimate = 0.0;   // absolute, largest channel; an upper bound in practice for smooth integrands
  int regions = 0;
  long long evaluations = 0;
  bool converged = false;       // false: maxRegions was reached first
};

using Integrand2d = std::function<dvec3(double x, double y)>;

CubatureResult integrate2d(const Integrand2d& f, const dvec2& lower, const dvec2& upper,
                           const CubatureOptions& options = {});

}  // namespace raylab::reference
