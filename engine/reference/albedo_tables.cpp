#include "reference/albedo_tables.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "generated/ggx_albedo.h"
#include "shared/brdf_tables.h"

namespace raylab::reference {
namespace {

constexpr int kSize = static_cast<int>(gpu::kGgxAlbedoSize);
constexpr int kEpsSize = static_cast<int>(gpu::kDielectricAlbedoEpsSize);

// A coordinate in [0, 1] on an axis of n entries: the lower entry and the fraction towards the next.
struct Cell {
  int index;
  double t;
};
Cell cellOf(double x01, int n) {
  const double x = std::clamp(x01, 0.0, 1.0) * (n - 1);
  const int i = std::min(int(x), n - 2);
  return {i, x - i};
}

}  // namespace

double ggxAlbedoLoss(double mu, double alpha) {
  const Cell x = cellOf(mu, kSize), y = cellOf(alpha, kSize);
  const auto at = [](int row, int column) { return kGgxAlbedoLoss[row * kSize + column]; };
  return (1.0 - y.t) * ((1.0 - x.t) * at(y.index, x.index) + x.t * at(y.index, x.index + 1)) +
         y.t * ((1.0 - x.t) * at(y.index + 1, x.index) + x.t * at(y.index + 1, x.index + 1));
}

double ggxAverageLoss(double alpha) {
  const Cell y = cellOf(alpha, kSize);
  return (1.0 - y.t) * kGgxAverageLoss[y.index] + y.t * kGgxAverageLoss[y.index + 1];
}

double dielectricReflectionLoss(double mu, double alpha, double eps) {
  const Cell x = cellOf(std::sqrt(std::clamp(mu, 0.0, 1.0)), kSize);
  const Cell y = cellOf(std::sqrt(std::clamp(alpha, 0.0, 1.0)), kSize);
  const Cell z = cellOf(eps, kEpsSize);
  double sum = 0.0;
  for (int dz = 0; dz < 2; ++dz) {
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        const std::size_t i = (std::size_t(z.index + dz) * kSize + y.index + dy) * kSize + x.index + dx;
        sum += (dz ? z.t : 1.0 - z.t) * (dy ? y.t : 1.0 - y.t) * (dx ? x.t : 1.0 - x.t) * kDielectricAlbedoLoss[i];
      }
    }
  }
  return sum;
}

double mirrorAverageLoss(double alpha) {
  const Cell y = cellOf(std::sqrt(std::clamp(alpha, 0.0, 1.0)), kSize);
  return (1.0 - y.t) * kMirrorAverageLoss[y.index] + y.t * kMirrorAverageLoss[y.index + 1];
}

double averageFresnel(double eps) {
  const Cell z = cellOf(eps, kEpsSize);
  return (1.0 - z.t) * kAverageFresnel[z.index] + z.t * kAverageFresnel[z.index + 1];
}

}  // namespace raylab::reference
