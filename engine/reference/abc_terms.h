// Terms shared by the references of Löw's two ABC models (models/abc_microfacet.cpp, models/abc_smooth.cpp).
#pragma once

#include <cmath>

#include "reference/terms.h"

namespace raylab::reference {

// The integral of (1 + B t)^-C over t in [0, 1]: log(1 + B) expm1(s) / (s B), s = (1 - C) log(1 + B).
inline double abcIntegral(double b, double c) {
  const double logB = std::log1p(b);
  return logB / b * expm1OverX((1.0 - c) * logB);
}

}  // namespace raylab::reference
