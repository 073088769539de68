#include "util/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "util/error.h"
#include "util/files.h"

namespace raylab {

namespace {

std::string systemError() { return std::strerror(errno); }

// A new, empty, uniquely named file in the directory of `path` (so that rename is atomic: same file system).
// Hidden, and named after the target, so that a leftover from a killed process says what it was.
std::string createTemporary(const std::string& path, int* fd) {
  const std::filesystem::path target(path);
  const std::filesystem::path directory = target.parent_path();
  std::string pattern = (directory / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  *fd = mkstemp(pattern.data());
  if (*fd < 0) {
    throw Error(path + ": cannot create a file in the directory '" +
                (directory.empty() ? std::string(".") : directory.string()) + "': " + systemError());
  }
  return pattern;
}

void removeQuietly(const std::string& path) { ::unlink(path.c_str()); }

void writeAll(int fd, std::string_view bytes, const std::string& path) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error(path + ": cannot write: " + (n < 0 ? systemError() : std::string("no space written")));
    written += std::size_t(n);
  }
}

// Flushes the temporary to disk, then puts it in place of the target.
void commit(const std::string& temporary, const std::string& path) {
  const int fd = ::open(temporary.c_str(), O_RDONLY);
  if (fd < 0) throw Error(path + ": cannot reopen the written file: " + systemError());
  const bool synced = ::fsync(fd) == 0;
  const std::string syncError = systemError();
  ::close(fd);
  if (!synced) throw Error(path + ": cannot flush to disk: " + syncError);
  // mkstemp makes the file private (0600); an output is an ordinary file of the user's.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(temporary.c_str(), 0666 & ~mask);
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    throw Error(path + ": cannot replace the file: " + systemError());
  }
}

void checkNotSpecial(const std::string& path, const std::string& label) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return;  // does not exist yet: fine
  if (S_ISDIR(info.st_mode)) throw Error(label + ": '" + path + "' is a directory; give a file name");
  if (!S_ISREG(info.st_mode)) {
    throw Error(label + ": '" + path + "' is not a regular file (a device or pipe); give a file name");
  }
}

}  // namespace

void writeFileAtomically(const std::string& path, std::string_view bytes) {
  replaceFileAtomically(path, [&](const std::string& temporary) {
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_TRUNC);
    if (fd < 0) throw Error(path + ": cannot open for writing: " + systemError());
    try {
      writeAll(fd, bytes, path);
    } catch (...) {
      ::close(fd);
      throw;
    }
    if (::close(fd) != 0) throw Error(path + ": cannot write: " + systemError());
  });
}

void replaceFileAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  checkNotSpecial(path, path);
  createParentDirectories(path);
  int fd = -1;
  const std::string temporary = createTemporary(path, &fd);
  ::close(fd);
  try {
    write(temporary);
    commit(temporary, path);
  } catch (...) {
    removeQuietly(temporary);
    throw;
  }
}

void checkOutputPath(const std::string& path, const std::string& option) {
  const std::string label = option.empty() ? path : option;
  checkNotSpecial(path, label);
  try {
    createParentDirectories(path);
  } catch (const Error& error) {
    throw Error(label + ": " + error.what());
  }
  int fd = -1;
  try {
    const std::string probe = createTemporary(path, &fd);
    ::close(fd);
    removeQuietly(probe);
  } catch (const Error& error) {
    throw Error(label + ": " + error.what());
  }
}

void checkDistinctOutputs(const std::string& command, const std::vector<NamedOutput>& outputs) {
  std::vector<std::filesystem::path> resolved;
  for (const NamedOutput& output : outputs) {
    std::error_code error;
    resolved.push_back(output.path.empty() ? std::filesystem::path()
                                           : std::filesystem::weakly_canonical(std::filesystem::absolute(output.path), error));
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (std::size_t j = i + 1; j < outputs.size(); ++j) {
      if (resolved[i].empty() || resolved[i] != resolved[j]) continue;
      const std::string same = outputs[i].option == outputs[j].option ? outputs[i].option + " (twice)"
                                                                       : outputs[i].option + " and " + outputs[j].option;
      throw Error(command + ": " + same + " would both write " + outputs[i].path +
                      "; give each output its own file",
                  kExitUsage);
    }
  }
}

}  // namespace raylab
