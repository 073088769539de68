#include "measured/measured_library.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <optional>

#include "shared/brdf_tables.h"
#include "util/error.h"

namespace raylab {

static_assert(gpu::kMerlSampleCount == kMerlSamples && gpu::kMerlThetaHBins == kMerlThetaH &&
              gpu::kMerlThetaDBins == kMerlThetaD && gpu::kMerlPhiDBins == kMerlPhiD);

namespace {

// What tells one file, and one version of it, from another: the inode (hard links are one file), its size and
// both times (a copy made with `cp -p`, `rsync -t` or `tar x` keeps the size and the modification time, never the
// change time).
struct Identity {
  std::uint64_t device = 0, inode = 0;
  std::int64_t size = -1, modified = -1, changed = -1;
  bool operator==(const Identity&) const = default;
};

std::optional<Identity> identityOf(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;
  const auto nanoseconds = [](const timespec& t) { return std::int64_t(t.tv_sec) * 1000000000 + t.tv_nsec; };
  return Identity{std::uint64_t(info.st_dev), std::uint64_t(info.st_ino), std::int64_t(info.st_size),
                  nanoseconds(info.st_mtim), nanoseconds(info.st_ctim)};
}

struct Entry {
  std::string path;
  std::optional<Identity> identity;
  std::shared_ptr<const MeasuredFile> file;  // null once evicted: read again when next used
  std::uint64_t lastUse = 0;
  std::uint32_t replacedBy = kNoMeasuredFile;  // a newer version of the same path
};

struct Store {
  std::mutex mutex;
  std::vector<Entry> entries;
  std::uint64_t clock = 0;
};

Store& store() {
  static Store instance;
  return instance;
}

// A network's sampler reads every 10th phi_d bin: 48,600 evaluations, a few hundredths of a second.
constexpr int kNetworkSamplerPhiStride = 10;

std::shared_ptr<const MeasuredFile> readFile(const std::string& path) {
  auto file = std::make_shared<MeasuredFile>();
  file->path = path;
  if (isNbrdfPath(path)) {
    const NbrdfNetwork& network = file->network.emplace(readNbrdf(path));
    file->sampling = binnedSampling(
        [&network](int h, int d, int p) {
          glm::dvec3 wi, wo;
          return merlBinCentre(h, d, p, &wi, &wo) ? nbrdfEval(network, wi, wo) : glm::dvec3(-1.0);
        },
        kNetworkSamplerPhiStride);
  } else {
    file->table = readMerl(path);
    file->sampling = measuredSampling(file->table);
  }
  return file;
}

// Keeps at most kResidentMeasuredFiles MERL tables in memory (lock held): the least recently used that nothing
// outside the store holds are dropped, to be read again from their files when next used. Networks (19 KB each, 64 at
// most per scene) stay: reading one again costs a process.
void evictExcess(Store& s) {
  for (;;) {
    std::size_t resident = 0;
    Entry* oldest = nullptr;
    for (Entry& entry : s.entries) {
      if (entry.file == nullptr || entry.file->network) continue;
      ++resident;
      if (entry.file.use_count() == 1 && (oldest == nullptr || entry.lastUse < oldest->lastUse)) oldest = &entry;
    }
    if (resident <= kResidentMeasuredFiles || oldest == nullptr) return;
    oldest->file.reset();
  }
}

// The entry an id stands for now (lock held): a replaced version forwards to the newest.
std::uint32_t current(const Store& s, std::uint32_t id) {
  while (s.entries[id - 1].replacedBy != kNoMeasuredFile) id = s.entries[id - 1].replacedBy;
  return id;
}

thread_local MeasuredFileLimit* activeLimit = nullptr;

}  // namespace

MeasuredFileLimit::MeasuredFileLimit(std::string what) : what_(std::move(what)), outer_(activeLimit) {
  activeLimit = this;
}

MeasuredFileLimit::~MeasuredFileLimit() { activeLimit = outer_; }

std::uint32_t loadMeasured(const std::string& path) {
  std::error_code error;
  const std::string absolute = std::filesystem::absolute(path, error).lexically_normal().string();
  const std::string name = absolute.empty() ? path : absolute;
  const std::optional<Identity> identity = identityOf(name);
  Store& s = store();
  std::uint32_t id = kNoMeasuredFile;
  std::uint32_t older = kNoMeasuredFile;  // this path's previous version, replaced by this load
  {
    const std::lock_guard lock(s.mutex);
    for (std::size_t i = 0; i < s.entries.size() && identity; ++i) {
      const Entry& entry = s.entries[i];
      if (entry.replacedBy != kNoMeasuredFile) continue;
      if (entry.identity == identity) id = std::uint32_t(i + 1);  // the same file, or a hard link to it
      else if (entry.path == name) older = std::uint32_t(i + 1);
    }
  }
  if (activeLimit != nullptr) {
    // Refused before it is read: a scene of 40 links to one file, or a CSV naming 100, used to read them all.
    std::vector<std::string>& used = activeLimit->files_;
    const std::string usedKey =
        identity ? std::to_string(identity->device) + ":" + std::to_string(identity->inode) : name;
    if (std::find(used.begin(), used.end(), usedKey) == used.end()) {
      const bool merl = !isNbrdfPath(name);
      if (merl && activeLimit->merlFiles_ >= kMaxMeasuredFilesPerScene) {
        throw Error(path + ": " + activeLimit->what_ + " would use more than " +
                    std::to_string(kMaxMeasuredFilesPerScene) +
                    " measured files (MERL tables: the device holds that many in the 128 MiB every Vulkan device binds)");
      }
      if (used.size() >= kMaxFilesPerScene) {
        throw Error(path + ": " + activeLimit->what_ + " would use more than " + std::to_string(kMaxFilesPerScene) +
                    " measured and neural BRDF files (the device tables' directory holds that many)");
      }
      used.push_back(usedKey);
      activeLimit->merlFiles_ += merl ? 1 : 0;
    }
  }
  if (id != kNoMeasuredFile) {
    const std::lock_guard lock(s.mutex);
    Entry& entry = s.entries[id - 1];
    entry.lastUse = ++s.clock;
    if (entry.file != nullptr) return id;
  }
  // Read outside the lock: a file takes a fraction of a second, and other threads may be rendering.
  std::shared_ptr<const MeasuredFile> file = readFile(name);
  const std::lock_guard lock(s.mutex);
  if (id != kNoMeasuredFile) {
    Entry& entry = s.entries[id - 1];
    if (entry.file == nullptr) entry.file = std::move(file);
    evictExcess(s);
    return id;
  }
  if (s.entries.size() + 1 >= (std::size_t(1) << 24)) throw Error("more than 2^24 measured files loaded");
  s.entries.push_back({name, identity, std::move(file), ++s.clock, kNoMeasuredFile});
  const auto added = std::uint32_t(s.entries.size());
  if (older != kNoMeasuredFile && s.entries[older - 1].replacedBy == kNoMeasuredFile) {
    // The file changed on disk: its old table is dropped (held only while in use), and the old id reads the new one.
    s.entries[older - 1].replacedBy = added;
    s.entries[older - 1].file.reset();
  }
  evictExcess(s);
  return added;
}

std::shared_ptr<const MeasuredFile> measuredFile(std::uint32_t id) {
  Store& s = store();
  std::string path;
  {
    const std::lock_guard lock(s.mutex);
    if (id == kNoMeasuredFile || id > s.entries.size()) {
      throw Error(id == kNoMeasuredFile ? "a measured material without a file (file=PATH)"
                                        : "unknown measured file id " + std::to_string(id));
    }
    id = current(s, id);
    Entry& entry = s.entries[id - 1];
    entry.lastUse = ++s.clock;
    if (entry.file != nullptr) return entry.file;
    path = entry.path;
  }
  std::shared_ptr<const MeasuredFile> file = readFile(path);  // evicted: read again
  const std::lock_guard lock(s.mutex);
  Entry& entry = s.entries[id - 1];
  if (entry.file == nullptr) entry.file = file;
  std::shared_ptr<const MeasuredFile> result = entry.file;
  evictExcess(s);
  return result;
}

std::string measuredFilePath(std::uint32_t id) {
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  if (id == kNoMeasuredFile || id > s.entries.size()) throw Error("unknown measured file id " + std::to_string(id));
  return s.entries[current(s, id) - 1].path;
}

std::uint32_t measuredFileCount() {
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  return std::uint32_t(s.entries.size());
}

std::uint32_t latestMeasuredFile(std::string_view role) {
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  for (auto id = std::uint32_t(s.entries.size()); id > kNoMeasuredFile; --id) {
    if (isNbrdfPath(s.entries[id - 1].path) == (role == "network")) return id;
  }
  return kNoMeasuredFile;
}

std::string fileKindExtension(std::string_view role) { return role == "network" ? ".h5" : ".binary"; }

std::size_t residentMeasuredFiles() {
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  return std::size_t(std::count_if(s.entries.begin(), s.entries.end(), [](const Entry& e) { return e.file != nullptr; }));
}

std::string fileKindText(std::string_view role) {
  return role == "network" ? "a neural BRDF .h5 file (Keras weights, its .json beside it)" : "a MERL .binary file";
}

void checkFileKind(const MeasuredFile& file, std::string_view role, const std::string& where) {
  if (file.network.has_value() != (role == "network")) checkFileKind(file.path, role, where);
}

void checkFileKind(const std::string& path, std::string_view role, const std::string& where) {
  const bool network = isNbrdfPath(path);
  if (network != (role == "network")) {
    throw Error(where + ": " + path + " is " + fileKindText(network ? "network" : "file") + "; this parameter takes " +
                fileKindText(role) +
                (network ? " (a neural BRDF renders as model nbrdf)" : " (a MERL file renders as model measured)"));
  }
}

std::vector<float> measuredDeviceBlock(const MeasuredFile& file) {
  const auto writeSampler = [&file](float* sampler) {
    for (int j = 0; j < kMerlThetaH; ++j) {
      sampler[gpu::kSamplerPmf + j] = float(file.sampling.pmf[j]);
      sampler[gpu::kSamplerCdf + j] = float(file.sampling.cdf[j]);
    }
    for (int k = 0; k <= kMerlThetaH; ++k) sampler[gpu::kSamplerDensity + k] = float(file.sampling.density[k]);
    sampler[gpu::kSamplerCosineProbability] = float(file.sampling.cosineProbability);
  };
  if (file.network) {
    std::vector<float> block(gpu::kNbrdfBlockFloats, 0.0f);
    writeNbrdfDeviceLayout(*file.network, block.data());
    writeSampler(block.data() + gpu::kNbrdfSampler);
    return block;
  }
  std::vector<float> block(gpu::kMeasuredBlockFloats, 0.0f);
  for (std::size_t i = 0; i < kMerlSamples; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const double stored = file.table.stored[i + c * kMerlSamples];
      block[gpu::kMeasuredValues + 3 * i + c] = stored < 0.0 ? 0.0f : float(stored * kMerlScale[c]);
    }
  }
  writeSampler(block.data() + gpu::kMeasuredSampler);
  return block;
}

}  // namespace raylab
