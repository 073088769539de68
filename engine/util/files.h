// Small file-system helpers whose errors name the file, and the one reader every input file goes through.
#pragma once

#include <cstdint>
#include <string>

#include "util/error.h"

namespace raylab {

// What was wrong with an input file, so that callers (the Python module) can choose their exception.
enum class FileProblem { kMissing, kDirectory, kNotRegular, kTooLarge, kUnreadable };

class FileError : public Error {
 public:
  FileError(const std::string& message, FileProblem problem) : Error(message), problem_(problem) {}
  FileProblem problem() const { return problem_; }

 private:
  FileProblem problem_;
};

// Limits of the input files that are not scenes (those are in scene/gltf_files.h).
inline constexpr std::uint64_t kMaxScriptBytes = std::uint64_t(16) << 20;     // raylab view --script
inline constexpr std::uint64_t kMaxCaseFileBytes = std::uint64_t(1) << 30;    // raylab brdf eval --in
inline constexpr std::uint64_t kMaxImageFileBytes = std::uint64_t(1) << 32;   // EXR and PNG read back

// Creates the directories above `path` so that it can be written, when they lie below the current directory;
// a missing directory elsewhere is an error (a typo must not create /nonexistent_dir).
void createParentDirectories(const std::string& path);

// Every input file of every command and of the Python module is read here: only a regular file (a FIFO would
// hang, /dev/zero would grow without bound, a directory is a mistake) of at most `maxBytes`, whole. Throws
// FileError "PATH: what was wrong".
std::string readInputFile(const std::string& path, std::uint64_t maxBytes);

// What readInputFile would refuse `path` for, without reading it: empty when it is a regular file of at most
// maxBytes; else the reason ("no such file", ...), with its kind in *problem.
std::string inputFileProblem(const std::string& path, std::uint64_t maxBytes, FileProblem* problem = nullptr);

}  // namespace raylab
