// The measured files this process has loaded, MERL tables and neural BRDFs (nbrdf.h) alike: a material of model
// `measured` or `nbrdf` holds its file's id here in its file parameter (an integer in a float slot, exact below
// 2^24), so that the reference, the parameter table and the device all find the same table however many materials
// use it. Thread-safe (the Python module is called from
// threads).
//
// Memory stays bounded however many files a session names: a file (an inode: hard links are one file) is loaded
// once; a file that changed on disk gets a new id when loaded again, its old table is freed and its old id reads
// the new one; and at most kResidentMeasuredFiles tables stay in memory, the least recently used that nothing holds
// being read again from their files when next used. Ids stay valid for the life of the process.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "measured/measured_sampling.h"
#include "measured/merl.h"
#include "measured/nbrdf.h"
#include "shared/brdf_tables.h"

namespace raylab {

// No file: the value of a `file` parameter no file was given for. A scene refuses a measured material without one.
inline constexpr std::uint32_t kNoMeasuredFile = 0;

// The MERL files one scene (or one `brdf eval` CSV) may use: as many blocks as fit, after the build-time tables and
// the directory, in the 2^27 bytes of maxStorageBufferRange every Vulkan device provides (lavapipe's limit too).
inline constexpr std::size_t kMaxMeasuredFilesPerScene =
    ((std::size_t(1) << 27) / sizeof(float) - gpu::kFileBlocksOffset) / gpu::kMeasuredBlockFloats;
// Files of either kind in one scene: the directory's entries (a network's block is 4 KB).
inline constexpr std::size_t kMaxFilesPerScene = gpu::kMaxFileBlocks;
// MERL tables kept in memory when nothing holds them (33 MiB each, in doubles); networks are always kept.
inline constexpr std::size_t kResidentMeasuredFiles = 8;

struct MeasuredFile {
  std::string path;                     // absolute, as loaded
  MerlTable table;                      // a MERL file's (empty for a network)
  std::optional<NbrdfNetwork> network;  // a neural BRDF's (a `.h5` path)
  MeasuredSampling sampling;
};

// What a file parameter of `role` ("file": a MERL table; "network": a neural BRDF) accepts, as a user reads it.
std::string fileKindText(std::string_view role);
// Throws Error, naming `where`, unless the file at `path` is of the kind `role` accepts (a file's kind is its
// extension's: loadMeasured reads a `.h5` as a network, anything else as MERL).
void checkFileKind(const std::string& path, std::string_view role, const std::string& where);
// The same for a file already read: its kind is what was read, so the per-evaluation check of the reference models
// costs a comparison, not a parse of the path (that parse was a sixth of a measured material's sampling test).
void checkFileKind(const MeasuredFile& file, std::string_view role, const std::string& where);

// While one is alive on a thread, loadMeasured counts the distinct files loaded there and refuses, before reading
// it, a MERL file beyond kMaxMeasuredFilesPerScene or any file beyond kMaxFilesPerScene: a scene's loader and a
// CSV's reader hold one. `what` names the
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
  std::size_t merlFiles_ = 0;
  MeasuredFileLimit* outer_;
};

// Reads and checks the file at `path` (readNbrdf's checks for a `.h5`, else readMerl's) unless the same file,
// unchanged, is loaded already; returns its id (>= 1). Throws Error naming the file.
std::uint32_t loadMeasured(const std::string& path);
// The file of an id loadMeasured returned (read again if it was evicted; the newest version if it changed); throws
// Error for any other id, or when an evicted file can no longer be read.
std::shared_ptr<const MeasuredFile> measuredFile(std::uint32_t id);
// Its path, without reading it.
std::string measuredFilePath(std::uint32_t id);

// How many files were loaded: their ids are 1 to this (the viewer lists their folders, and a material switched to
// `measured` takes the last one).
std::uint32_t measuredFileCount();
// The id of the file of the kind `role` accepts (fileKindText) loaded most recently, or kNoMeasuredFile.
std::uint32_t latestMeasuredFile(std::string_view role);
// The extension of the files of that kind (".binary", ".h5").
std::string fileKindExtension(std::string_view role);
// How many tables are in memory now.
std::size_t residentMeasuredFiles();

// The floats of the file's block of the device's BRDF tables (shared/brdf_tables.h): a MERL file's f in RGB triples
// (scaled, missing as 0) or a network's weights, then the sampler's tables and its cosine probability.
std::vector<float> measuredDeviceBlock(const MeasuredFile& file);

}  // namespace raylab
