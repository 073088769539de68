#include "denoise/oidn_library.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

#include "util/error.h"

namespace raylab::oidn {

namespace {

namespace fs = std::filesystem;

constexpr const char* kSoname = "libOpenImageDenoise.so.2";
constexpr const char* kInstall =
    "install Open Image Denoise from PyPI: run tools/setup.sh, or `.venv/bin/pip install -r tools/requirements.txt` "
    "(the package pyoidn bundles the library), or set RAYLAB_OIDN_LIBRARY to a libOpenImageDenoise.so.2";

// libOpenImageDenoise.so.2 in the pyoidn package of every python* folder of a virtual environment.
void addVenvLibraries(const fs::path& venv, std::vector<fs::path>& candidates) {
  std::error_code error;
  const fs::path lib = venv / "lib";
  if (!fs::is_directory(lib, error)) return;
  for (const fs::directory_entry& entry : fs::directory_iterator(lib, error)) {
    if (entry.path().filename().string().rfind("python", 0) != 0) continue;
    candidates.push_back(entry.path() / "site-packages" / "pyoidn" / "oidn" / "lib" / kSoname);
  }
}

// The .venv of the executable's folder and of each folder above it (build/release/raylab finds the repository's),
// and the environment the executable itself may be in (.venv/bin/python running the Python module).
std::vector<fs::path> venvCandidates() {
  std::vector<fs::path> candidates;
  std::error_code error;
  fs::path folder = fs::read_symlink("/proc/self/exe", error).parent_path();
  if (error) return candidates;
  for (int up = 0; up < 5 && !folder.empty(); ++up) {
    addVenvLibraries(folder / ".venv", candidates);
    addVenvLibraries(folder, candidates);
    if (folder == folder.parent_path()) break;
    folder = folder.parent_path();
  }
  return candidates;
}

template <typename Function>
void bind(void* library, const char* name, Function& function, const std::string& path) {
  function = reinterpret_cast<Function>(dlsym(library, name));
  if (function == nullptr) throw Error(path + " has no " + name + ": not Open Image Denoise 2.x? " + kInstall, kExitUsage);
}

Api load(void* library, const std::string& path) {
  Api api{};
  bind(library, "oidnNewDevice", api.newDevice, path);
  bind(library, "oidnSetDeviceInt", api.setDeviceInt, path);
  bind(library, "oidnCommitDevice", api.commitDevice, path);
  bind(library, "oidnReleaseDevice", api.releaseDevice, path);
  bind(library, "oidnGetDeviceError", api.getDeviceError, path);
  bind(library, "oidnNewFilter", api.newFilter, path);
  bind(library, "oidnSetSharedFilterImage", api.setSharedFilterImage, path);
  bind(library, "oidnSetFilterBool", api.setFilterBool, path);
  bind(library, "oidnSetFilterInt", api.setFilterInt, path);
  bind(library, "oidnCommitFilter", api.commitFilter, path);
  bind(library, "oidnExecuteFilter", api.executeFilter, path);
  bind(library, "oidnReleaseFilter", api.releaseFilter, path);
  api.path = path;
  return api;
}

Api find() {
  if (const char* chosen = std::getenv("RAYLAB_OIDN_LIBRARY"); chosen != nullptr && *chosen != '\0') {
    void* library = dlopen(chosen, RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) {
      throw Error(std::string("RAYLAB_OIDN_LIBRARY=") + chosen + " does not load (" + dlerror() + "); " + kInstall,
                  kExitUsage);
    }
    return load(library, chosen);
  }
  std::string tried;
  for (const fs::path& candidate : venvCandidates()) {
    std::error_code error;
    if (!fs::is_regular_file(candidate, error)) continue;
    if (void* library = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL)) return load(library, candidate.string());
    tried += std::string("; ") + candidate.string() + ": " + dlerror();
  }
  if (void* library = dlopen(kSoname, RTLD_NOW | RTLD_LOCAL)) return load(library, kSoname);
  throw Error(std::string("Open Image Denoise is not installed (no pyoidn in a .venv beside raylab, no ") + kSoname +
                  " on the library path" + tried + "): " + kInstall,
              kExitUsage);
}

}  // namespace

const Api& api() {
  // Loaded once; a failure is remembered and thrown again, never retried half-way.
  static std::once_flag once;
  static Api loaded;
  static std::string failure;
  static ExitCode failureCode = kExitUsage;
  std::call_once(once, [] {
    try {
      loaded = find();
    } catch (const Error& error) {
      failure = error.what();
      failureCode = error.exitCode();
    }
  });
  if (!failure.empty()) throw Error(failure, failureCode);
  return loaded;
}

}  // namespace raylab::oidn
