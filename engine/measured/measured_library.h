// The measured files this process has loaded, each once: a material of model `measured` holds its file's id here
// in its `file` parameter (an integer in a float slot, exact below 2^24), so that the reference, the parameter
// table and the device all find the same table however many materials use it. The store only grows: an id stays
// valid for the life of the process, and loading the same unchanged file again returns the same id. Thread-safe
// (the Python module is called from threads).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "measured/measured_sampling.h"
#include "measured/merl.h"

namespace raylab {

// No file: the value of a `file` parameter no file was given for. A scene refuses a measured material without one.
inline constexpr std::uint32_t kNoMeasuredFile = 0;

struct MeasuredFile {
  std::string path;  // absolute, as loaded
  MerlTable table;
  MeasuredSampling sampling;
};

// Reads and checks the MERL file at `path` (readMerl's checks) unless the same file, unchanged (size and
// modification time), is loaded already; returns its id (>= 1). Throws Error naming the file.
std::uint32_t loadMeasured(const std::string& path);
// The file of an id loadMeasured returned; throws Error for any other id.
std::shared_ptr<const MeasuredFile> measuredFile(std::uint32_t id);

// How many files are loaded: their ids are 1 to this (the viewer lists their folders, and a material switched to
// `measured` takes the last one).
std::uint32_t measuredFileCount();

// The floats of one block of the device's BRDF tables (shared/brdf_tables.h, kMeasuredBlockFloats): f in RGB
// triples (scaled, missing as 0), the sampler's tables and its cosine probability.
std::vector<float> measuredDeviceBlock(const MeasuredFile& file);

}  // namespace raylab
