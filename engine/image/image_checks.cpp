#include <cmath>
#include <cstdio>

#include "image/image.h"
#include "util/error.h"

namespace raylab {

void checkFinite(const Image& image, const std::string& path) {
  std::size_t bad = 0, first = 0;
  for (std::size_t i = 0; i < image.rgba.size(); ++i) {
    if (!std::isfinite(image.rgba[i])) {
      if (bad++ == 0) first = i / 4;
    }
  }
  if (bad == 0) return;
  const std::size_t x = image.width ? first % image.width : 0, y = image.width ? first / image.width : 0;
  char value[64];
  std::snprintf(value, sizeof value, "(%g, %g, %g, %g)", image.rgba[first * 4], image.rgba[first * 4 + 1],
                image.rgba[first * 4 + 2], image.rgba[first * 4 + 3]);
  throw Error(path + ": not written: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is " + value +
              ", and " + std::to_string(bad) + " values in all are not finite; raylab writes no NaN or infinity");
}

}  // namespace raylab
