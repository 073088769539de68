#include "scene/gltf_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cctype>
#include <cstring>

#include "util/error.h"

namespace raylab::gltf {

namespace {

// Reads a regular file of at most maxBytes into `out`; an empty string, or what was wrong.
std::string readRegular(const std::string& path, std::uint64_t maxBytes, std::string* out) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it is then refused as not regular.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return errno == ENOENT ? "no such file" : std::string("cannot open: ") + std::strerror(errno);
  struct stat info {};
  std::string problem;
  if (::fstat(fd, &info) != 0) {
    problem = std::string("cannot read: ") + std::strerror(errno);
  } else if (S_ISDIR(info.st_mode)) {
    problem = "is a directory, not a file";
  } else if (!S_ISREG(info.st_mode)) {
    problem = "is not a regular file (a device, FIFO or socket); raylab reads only regular files";
  } else if (std::uint64_t(info.st_size) > maxBytes) {
    problem = "has " + std::to_string(info.st_size) + " bytes, over raylab's limit of " + std::to_string(maxBytes) +
              " (docs/scenes.md, Limits)";
  } else {
    out->resize(std::size_t(info.st_size));
    std::size_t done = 0;
    while (done < out->size()) {
      const ssize_t n = ::read(fd, out->data() + done, out->size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        problem = n < 0 ? std::string("cannot read: ") + std::strerror(errno) : "changed size while being read";
        break;
      }
      done += std::size_t(n);
    }
  }
  ::close(fd);
  return problem;
}

bool isInside(const std::filesystem::path& path, const std::filesystem::path& root) {
  const auto mismatch = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
  return mismatch.first == root.end();
}

// The canonical path if `path` may be read under the policy; else an empty path and policy.error set.
std::filesystem::path admitted(const std::string& path, UriPolicy& policy) {
  std::error_code error;
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(path, error);
  if (error) return {};
  if (policy.allowOutside) return resolved;
  if (policy.root.empty()) {
    if (policy.error.empty()) policy.error = "'" + path + "': a scene held in memory may not read external files";
    return {};
  }
  if (!isInside(resolved, policy.root)) {
    if (policy.error.empty()) {
      policy.error = "the URI '" + path + "' resolves to " + resolved.string() + ", outside the scene's directory " +
                     policy.root.string() + "; scene files may read only files in their own directory tree " +
                     "(--allow-outside-uris lifts this for a file you trust)";
    }
    return {};
  }
  return resolved;
}

// Refused files "exist", so that readWholeFile reports why instead of tinygltf's "File not found".
bool fileExists(const std::string& path, void*) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0;
}

std::string expandFilePath(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool readWholeFile(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* user) {
  auto& policy = *static_cast<UriPolicy*>(user);
  const std::filesystem::path resolved = admitted(path, policy);
  if (resolved.empty()) {
    if (error) *error = policy.error;
    return false;
  }
  std::string bytes;
  const std::string problem = readRegular(resolved.string(), kMaxExternalFileBytes, &bytes);
  if (!problem.empty()) {
    if (policy.error.empty()) policy.error = "'" + path + "' " + problem;
    if (error) *error = problem;
    return false;
  }
  out->assign(bytes.begin(), bytes.end());
  return true;
}

bool writeWholeFile(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
  if (error) *error = "the loader writes no files";
  return false;
}

}  // namespace

tinygltf::FsCallbacks fsCallbacks(UriPolicy& policy) {
  return tinygltf::FsCallbacks{&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, &policy};
}

bool keepEncodedImage(tinygltf::Image* image, int, std::string*, std::string*, int, int, const unsigned char* bytes,
                      int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->width = image->height = image->component = -1;
  image->bits = 0;  // encoded
  return true;
}

void checkJsonDepth(const std::string& text, const std::string& label) {
  std::size_t depth = 0, line = 1;
  bool inString = false, escaped = false;
  for (const char c : text) {
    if (c == '\n') ++line;
    if (inString) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') inString = false;
      continue;
    }
    if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) {
        throw Error(label + ": line " + std::to_string(line) + ": JSON nested deeper than " +
                    std::to_string(kMaxJsonDepth) + " levels (raylab's limit, docs/scenes.md)");
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

std::string resolveUri(const std::string& uri, const std::string& baseDirectory, UriPolicy& policy) {
  std::string decoded;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      decoded += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      decoded += uri[i];
    }
  }
  // A scheme ("data:", "file:", "https:") is a letter followed by letters, digits, '+', '-' or '.', then ':'.
  const std::size_t colon = uri.find(':');
  if (colon != std::string::npos && colon > 0 && std::isalpha(static_cast<unsigned char>(uri[0])) &&
      std::all_of(uri.begin(), uri.begin() + std::ptrdiff_t(colon), [](unsigned char c) {
        return std::isalnum(c) || c == '+' || c == '-' || c == '.';
      })) {
    throw Error("the URI '" + uri + "' has a scheme; raylab reads only relative file paths here");
  }
  if (decoded.empty()) throw Error("the URI is empty");
  const std::filesystem::path path = std::filesystem::path(decoded).is_absolute()
                                         ? std::filesystem::path(decoded)
                                         : std::filesystem::path(baseDirectory.empty() ? "." : baseDirectory) / decoded;
  policy.error.clear();
  const std::filesystem::path resolved = admitted(path.string(), policy);
  if (resolved.empty()) throw Error(policy.error.empty() ? "the URI '" + uri + "' cannot be resolved" : policy.error);
  return resolved.string();
}

std::string readSceneFile(const std::string& path, std::uint64_t maxBytes) {
  std::string bytes;
  const std::string problem = readRegular(path, maxBytes, &bytes);
  if (!problem.empty()) throw Error(path + ": " + problem);
  return bytes;
}

}  // namespace raylab::gltf
