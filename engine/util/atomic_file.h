// Output files that are never lost: every output is written to a temporary file beside its target, each write
// checked and flushed to disk, then renamed over the target. A failure (full disk, kill, a concurrent writer)
// leaves either the old file or the new one, never a mix, and removes the temporary.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

// Writes `bytes` to `path` atomically. Parent directories are created. Errors name the file.
void writeFileAtomically(const std::string& path, std::string_view bytes);

// For libraries that write by path (OpenEXR): `write(temporaryPath)` writes the temporary, which is then
// flushed and renamed over `path`. If `write` throws, the temporary is removed and `path` is untouched.
void replaceFileAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

// Checks before any work that `path` can be written: its directory exists or can be created and accepts a new
// file, and `path` is not a directory or a device. `option` names where the path came from ("--png"), for the
// message. Throws Error.
void checkOutputPath(const std::string& path, const std::string& option);

// One command's outputs, each (option, path): throws Error (usage) when two name the same file, before any work
// (one would silently replace the other). Empty paths (an output not written) are skipped.
struct NamedOutput {
  std::string option;
  std::string path;
};
void checkDistinctOutputs(const std::string& command, const std::vector<NamedOutput>& outputs);

}  // namespace raylab
