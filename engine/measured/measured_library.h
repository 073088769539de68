// The measured files this process has loaded: a material of model `measured` holds its file's id here in its
// `file` parameter (an integer in a float slot, exact below 2^24), so that the reference, the parameter table and
// the device all find the same table however many materials use it. Thread-safe (the Python module is called from
// threads).
//
// Memory stays bounded however many files a session names: a file (an inode: hard links are one file) is loaded
// once; a file that changed on disk gets a new id when loaded again, its old table is freed and its old id reads
// the new one; and at most kResidentMeasuredFiles tables stay in memory, the least recently used that nothing holds
// being read again from their files when next used. Ids stay valid for the life of the process.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "measured/measured_sampling.h"
#include "measured/merl.h"
#include "shared/brdf_tables.h"

namespace raylab {

// No file: the value of a `file` parameter no file was given for. A scene refuses a measured material without one.
inline constexpr std::uint32_t kNoMeasuredFile = 0;

// The measured files one scene (or one `brdf eval` CSV) may use: as many blocks as fit, after the build-time tables,
// in the 2^27 bytes of maxStorageBufferRange every Vulkan device provides (lavapipe's limit too).
inline constexpr std::size_t kMaxMeasuredFilesPerScene =
    ((std::size_t(1) << 27) / sizeof(float) - gpu::kMeasuredOffset) / gpu::kMeasuredBlockFloats;
// Tables kept in memory when nothing holds them (33 MiB each, in doubles).
inline constexpr std::size_t kResidentMeasuredFiles = 8;

struct MeasuredFile {
  std::string path;  // absolute, as loaded
  MerlTable table;
  MeasuredSampling sampling;
};

// While one is alive on a thread, loadMeasured counts the distinct files loaded there and refuses, before reading
// it, a file beyond kMaxMeasuredFilesPerScene: a scene's loader and a CSV's reader hold one. `what` names the
// whole ("scene.gltf").
class MeasuredFileLimit {
 public:
  explicit MeasuredFileLimit(std::string what);
  ~MeasuredFileLimit();
  MeasuredFileLimit(const MeasuredFileLimit&) = delete;
  MeasuredFileLimit& operator=(const MeasuredFileLimit&) = delete;

 private:
  friend std::uint32_t loadMeasured(const std::string& path);
  std::string what_;
  std::vector<std::string> files_;
  MeasuredFileLimit* outer_;
};

// Reads and checks the MERL file at `path` (readMerl's checks) unless the same file, unchanged, is loaded already;
// returns its id (>= 1). Throws Error naming the file.
std::uint32_t loadMeasured(const std::string& path);
// The file of an id loadMeasured returned (read again if it was evicted; the newest version if it changed); throws
// Error for any other id, or when an evicted file can no longer be read.
std::shared_ptr<const MeasuredFile> measuredFile(std::uint32_t id);
// Its path, without reading it.
std::string measuredFilePath(std::uint32_t id);

// How many files were loaded: their ids are 1 to this (the viewer lists their folders, and a material switched to
// `measured` takes the last one).
std::uint32_t measuredFileCount();
// How many tables are in memory now.
std::size_t residentMeasuredFiles();

// The floats of one block of the device's BRDF tables (shared/brdf_tables.h, kMeasuredBlockFloats): f in RGB
// triples (scaled, missing as 0), the sampler's tables and its cosine probability.
std::vector<float> measuredDeviceBlock(const MeasuredFile& file);

}  // namespace raylab
