#include "measured/measured_library.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <mutex>

#include "shared/brdf_tables.h"
#include "util/error.h"

namespace raylab {

static_assert(gpu::kMerlSampleCount == kMerlSamples && gpu::kMerlThetaHBins == kMerlThetaH &&
              gpu::kMerlThetaDBins == kMerlThetaD && gpu::kMerlPhiDBins == kMerlPhiD);

namespace {

struct Entry {
  std::string path;
  std::int64_t size = 0;
  std::int64_t modified = 0;  // nanoseconds
  std::shared_ptr<const MeasuredFile> file;
};

std::mutex& storeMutex() {
  static std::mutex mutex;
  return mutex;
}

std::vector<Entry>& store() {
  static std::vector<Entry> entries;
  return entries;
}

}  // namespace

std::uint32_t loadMeasured(const std::string& path) {
  std::error_code error;
  const std::string absolute = std::filesystem::absolute(path, error).lexically_normal().string();
  struct stat info {};
  // Size and time only identify an unchanged file; readMerl does every check of what it reads.
  const bool known = !error && ::stat(absolute.c_str(), &info) == 0;
  const std::int64_t modified = known ? std::int64_t(info.st_mtim.tv_sec) * 1000000000 + info.st_mtim.tv_nsec : -1;
  if (known) {
    const std::lock_guard lock(storeMutex());
    for (std::size_t i = 0; i < store().size(); ++i) {
      const Entry& entry = store()[i];
      if (entry.path == absolute && entry.size == info.st_size && entry.modified == modified) {
        return std::uint32_t(i + 1);
      }
    }
  }
  // Read outside the lock: a file takes a fraction of a second, and other threads may be rendering.
  auto file = std::make_shared<MeasuredFile>();
  file->path = absolute.empty() ? path : absolute;
  file->table = readMerl(path);
  file->sampling = measuredSampling(file->table);
  const std::lock_guard lock(storeMutex());
  store().push_back({file->path, known ? std::int64_t(info.st_size) : -1, modified, std::move(file)});
  if (store().size() >= (std::size_t(1) << 24)) throw Error("more than 2^24 measured files loaded");
  return std::uint32_t(store().size());
}

std::shared_ptr<const MeasuredFile> measuredFile(std::uint32_t id) {
  const std::lock_guard lock(storeMutex());
  if (id == kNoMeasuredFile || id > store().size()) {
    throw Error(id == kNoMeasuredFile ? "a measured material without a file (file=PATH)"
                                      : "unknown measured file id " + std::to_string(id));
  }
  return store()[id - 1].file;
}

std::uint32_t measuredFileCount() {
  const std::lock_guard lock(storeMutex());
  return std::uint32_t(store().size());
}

std::vector<float> measuredDeviceBlock(const MeasuredFile& file) {
  std::vector<float> block(gpu::kMeasuredBlockFloats, 0.0f);
  for (std::size_t i = 0; i < kMerlSamples; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const double stored = file.table.stored[i + c * kMerlSamples];
      block[gpu::kMeasuredValues + 3 * i + c] = stored < 0.0 ? 0.0f : float(stored * kMerlScale[c]);
    }
  }
  for (int j = 0; j < kMerlThetaH; ++j) {
    block[gpu::kMeasuredPmf + j] = float(file.sampling.pmf[j]);
    block[gpu::kMeasuredCdf + j] = float(file.sampling.cdf[j]);
  }
  for (int k = 0; k <= kMerlThetaH; ++k) block[gpu::kMeasuredDensity + k] = float(file.sampling.density[k]);
  block[gpu::kMeasuredCosineProbability] = float(file.sampling.cosineProbability);
  return block;
}

}  // namespace raylab
