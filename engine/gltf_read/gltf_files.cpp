#include "gltf_read/gltf_files.h"

#include <algorithm>
#include <cctype>

#include "util/error.h"
#include "util/files.h"

namespace raylab::gltf {

namespace {

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

// Every file "exists" for tinygltf, so that readWholeFile says what is wrong with it, in raylab's words and
// after the folder rule: a missing file outside the scene's folder is refused as outside (tinygltf's "File not
// found" would hide that), a missing one inside is "no such file" with the URI.
bool fileExists(const std::string&, void*) { return true; }

std::string expandFilePath(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool readWholeFile(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* user) {
  auto& policy = *static_cast<UriPolicy*>(user);
  const std::filesystem::path resolved = admitted(path, policy);
  if (resolved.empty()) {
    if (error) *error = policy.error;
    return false;
  }
  try {
    const std::string bytes = readInputFile(resolved.string(), kMaxExternalFileBytes);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const FileError& e) {
    if (policy.error.empty()) policy.error = e.what();
    if (error) *error = e.what();
    return false;
  }
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

}  // namespace raylab::gltf
