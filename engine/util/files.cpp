#include "util/files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <algorithm>
#include <filesystem>

namespace raylab {

namespace {

struct Problem {
  std::string message;  // empty: none
  FileProblem kind = FileProblem::kUnreadable;
};

// What fstat says of an open file: a regular file of at most maxBytes, or why not.
Problem checkOpenFile(int fd, std::uint64_t maxBytes, struct stat& info) {
  if (::fstat(fd, &info) != 0) return {std::string("cannot read: ") + std::strerror(errno), FileProblem::kUnreadable};
  if (S_ISDIR(info.st_mode)) return {"is a directory, not a file", FileProblem::kDirectory};
  if (!S_ISREG(info.st_mode)) {
    return {"is not a regular file (a device, FIFO or socket); raylab reads only regular files",
            FileProblem::kNotRegular};
  }
  if (std::uint64_t(info.st_size) > maxBytes) {
    return {"has " + std::to_string(info.st_size) + " bytes, over raylab's limit of " + std::to_string(maxBytes) +
                " for this kind of file",
            FileProblem::kTooLarge};
  }
  return {};
}

Problem openProblem() {
  return errno == ENOENT ? Problem{"no such file", FileProblem::kMissing}
                         : Problem{std::string("cannot open: ") + std::strerror(errno), FileProblem::kUnreadable};
}

}  // namespace

void createParentDirectories(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code error;
  if (std::filesystem::is_directory(parent, error)) return;
  // A typo'd directory (/nonexistent_dir/x.png) must not appear silently, least of all at the root: only
  // directories below the current one (out/, results/run1/) are created.
  const std::filesystem::path here = std::filesystem::current_path(error);
  const std::filesystem::path target = std::filesystem::weakly_canonical(std::filesystem::absolute(parent), error);
  const auto mismatch = std::mismatch(here.begin(), here.end(), target.begin(), target.end());
  if (error || mismatch.first != here.end()) {
    throw Error(path + ": the directory " + parent.string() + " does not exist; raylab creates output " +
                "directories only below the current directory (create it first if it is meant)");
  }
  std::filesystem::create_directories(parent, error);
  if (error) throw Error(path + ": cannot create directory " + parent.string() + ": " + error.message());
}

std::string inputFileProblem(const std::string& path, std::uint64_t maxBytes, FileProblem* kind) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it is then refused as not regular.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  Problem problem;
  if (fd < 0) {
    problem = openProblem();
  } else {
    struct stat info {};
    problem = checkOpenFile(fd, maxBytes, info);
    ::close(fd);
  }
  if (kind != nullptr) *kind = problem.kind;
  return problem.message;
}

std::string readInputFile(const std::string& path, std::uint64_t maxBytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const Problem problem = openProblem();
    throw FileError(path + ": " + problem.message, problem.kind);
  }
  struct stat info {};
  Problem problem = checkOpenFile(fd, maxBytes, info);
  std::string bytes;
  if (problem.message.empty()) {
    bytes.resize(std::size_t(info.st_size));
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        problem = {n < 0 ? std::string("cannot read: ") + std::strerror(errno) : "changed size while being read",
                   FileProblem::kUnreadable};
        break;
      }
      done += std::size_t(n);
    }
  }
  ::close(fd);
  if (!problem.message.empty()) throw FileError(path + ": " + problem.message, problem.kind);
  return bytes;
}

}  // namespace raylab
