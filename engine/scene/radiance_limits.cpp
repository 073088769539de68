#include "scene/radiance_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "scene/environment.h"
#include "util/error.h"
#include "util/number_text.h"

namespace raylab {

namespace {

// Values that are floats (or products of floats) print as the float they are, so a limit reads "1e+20".
std::string shown(double value) {
  return std::abs(value) <= double(std::numeric_limits<float>::max()) ? numberText(float(value)) : numberText(value);
}

void checkRadiance(glm::vec3 value, const std::string& where, const char* what) {  // light intensity and the like
  for (int c = 0; c < 3; ++c) {
    if (!(value[c] >= 0.0f) || !std::isfinite(value[c])) {
      throw Error(where + ": " + what + " must be finite and >= 0, found " + shown(value[c]));
    }
  }
  const float brightest = std::max({value.r, value.g, value.b});
  if (brightest > kMaxRadiance) {
    throw Error(where + ": " + what + " " + shown(brightest) + " is over raylab's limit of " + shown(kMaxRadiance) +
                " (docs/scenes.md, Limits)");
  }
}

}  // namespace

void checkLightIntensity(glm::vec3 intensity, const std::string& where) {
  checkRadiance(intensity, where, "the light's intensity");
}

void checkEnvironmentStrength(const Environment& environment, float strength, const std::string& where) {
  if (!(strength >= 0.0f) || !std::isfinite(strength)) {
    throw Error(where + ": environment strength must be a finite number >= 0, found " + shown(strength));
  }
  const double product = double(strength) * double(environment.brightest);
  if (product > double(kMaxRadiance)) {
    throw Error(where + ": environment strength " + shown(strength) + " x the image's brightest texel " +
                shown(environment.brightest) + " = " + shown(product) + " is over raylab's limit of " +
                shown(kMaxRadiance) + " (docs/scenes.md, Limits)");
  }
}

}  // namespace raylab
