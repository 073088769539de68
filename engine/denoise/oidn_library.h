// Open Image Denoise's C API, found and loaded at run time (dlopen): the functions raylab calls, by the names and
// signatures of OpenImageDenoise/oidn.h 2.x, and where the library comes from.
#pragma once

#include <cstddef>
#include <string>

namespace raylab::oidn {

using Device = void*;
using Filter = void*;

// Values of OIDN 2.x's enums that raylab passes (oidn.h: OIDNDeviceType, OIDNFormat, OIDNQuality, OIDNError).
inline constexpr int kDeviceTypeCpu = 1;
inline constexpr int kFormatFloat3 = 3;
inline constexpr int kQualityFast = 4;
inline constexpr int kQualityBalanced = 5;
inline constexpr int kQualityHigh = 6;
inline constexpr int kErrorNone = 0;

struct Api {
  Device (*newDevice)(int type);
  void (*setDeviceInt)(Device device, const char* name, int value);
  void (*commitDevice)(Device device);
  void (*releaseDevice)(Device device);
  int (*getDeviceError)(Device device, const char** message);
  Filter (*newFilter)(Device device, const char* type);
  void (*setSharedFilterImage)(Filter filter, const char* name, void* data, int format, std::size_t width,
                               std::size_t height, std::size_t byteOffset, std::size_t pixelByteStride,
                               std::size_t rowByteStride);
  void (*setFilterBool)(Filter filter, const char* name, bool value);
  void (*setFilterInt)(Filter filter, const char* name, int value);
  void (*commitFilter)(Filter filter);
  void (*executeFilter)(Filter filter);
  void (*releaseFilter)(Filter filter);
  std::string path;  // the library file it came from
};

// The library, loaded once per process (thread-safe). Where from, first found wins:
//   RAYLAB_OIDN_LIBRARY, a path to libOpenImageDenoise.so.2 (an error if it does not load);
//   the pyoidn package of a .venv beside or above the running executable (tools/setup.sh installs it there);
//   the system's library path.
// Throws Error(kExitUsage) saying what was tried and how to install pyoidn when none loads.
const Api& api();

}  // namespace raylab::oidn
