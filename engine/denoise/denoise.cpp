#include "denoise/denoise.h"

#include <mutex>
#include <string>

#include "denoise/oidn_library.h"
#include "util/error.h"
#include "util/render_options.h"

namespace raylab {

namespace {

int qualityValue(DenoiseQuality quality) {
  switch (quality) {
    case DenoiseQuality::kFast: return oidn::kQualityFast;
    case DenoiseQuality::kBalanced: return oidn::kQualityBalanced;
    case DenoiseQuality::kHigh: return oidn::kQualityHigh;
  }
  return oidn::kQualityHigh;
}

void checkSize(const Image& image, const Image& color, const char* name) {
  if (image.width != color.width || image.height != color.height) {
    throw Error(std::string("denoise: the ") + name + " image is " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + ", the colour " + std::to_string(color.width) + "x" +
                std::to_string(color.height));
  }
}

// Throws Error with the device's last error, if it has one.
void checkDevice(const oidn::Api& api, oidn::Device device, const char* step) {
  const char* message = nullptr;
  if (api.getDeviceError(device, &message) != oidn::kErrorNone) {
    throw Error(std::string("Open Image Denoise (") + api.path + ") failed at " + step + ": " +
                (message != nullptr ? message : "no message"));
  }
}

// What a filter was committed for. A filter's first execution costs about 0.5 s more than the next ones at 1280x720
// (measured: 1.4 against 0.9 s, balanced), so the viewer keeps its filter while the size and quality stay.
struct FilterKey {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  DenoiseQuality quality = DenoiseQuality::kHigh;
  bool guided = false;
  bool operator==(const FilterKey&) const = default;
};

// The process's one CPU device and its last filter. OIDN serialises the work of a device anyway; the mutex keeps
// one caller's images in the filter until its execution ends.
struct Denoiser {
  std::mutex mutex;
  oidn::Device device = nullptr;
  oidn::Filter filter = nullptr;
  FilterKey key;
};

Denoiser& denoiser() {
  static Denoiser instance;  // never released: the library stays loaded until the process ends
  return instance;
}

// An RGBA float image as OIDN's FLOAT3 at a 16-byte pixel stride: the alpha channel is skipped, nothing copied.
void setImage(const oidn::Api& api, oidn::Filter filter, const char* name, const Image& image) {
  api.setSharedFilterImage(filter, name, const_cast<float*>(image.rgba.data()), oidn::kFormatFloat3, image.width,
                           image.height, 0, 4 * sizeof(float), std::size_t(image.width) * 4 * sizeof(float));
}

}  // namespace

DenoiseQuality parseDenoiseQuality(std::string_view name, const std::string& where) {
  return static_cast<DenoiseQuality>(choiceIndex(kDenoiseQualityOption, name, where));
}

std::string loadDenoiser() { return oidn::api().path; }

Image denoise(const Image& color, const AuxiliaryImages* aux, DenoiseQuality quality) {
  if (color.width == 0 || color.height == 0) throw Error("denoise: the colour image is empty");
  checkFinite(color, "denoise input");
  if (aux != nullptr) {
    checkSize(aux->albedo, color, "albedo");
    checkSize(aux->normal, color, "normal");
    checkFinite(aux->albedo, "denoise albedo");
    checkFinite(aux->normal, "denoise normal");
  }
  const oidn::Api& api = oidn::api();
  Denoiser& d = denoiser();
  const std::lock_guard<std::mutex> lock(d.mutex);
  if (d.device == nullptr) {
    d.device = api.newDevice(oidn::kDeviceTypeCpu);
    if (d.device == nullptr) throw Error("Open Image Denoise (" + api.path + ") made no CPU device");
    api.commitDevice(d.device);
    checkDevice(api, d.device, "its CPU device");
  }
  const FilterKey key{color.width, color.height, quality, aux != nullptr};
  if (d.filter == nullptr || !(d.key == key)) {
    if (d.filter != nullptr) api.releaseFilter(d.filter);
    d.filter = api.newFilter(d.device, "RT");
    checkDevice(api, d.device, "making its RT filter");
    d.key = key;
    api.setFilterBool(d.filter, "hdr", true);
    // Accumulated over every sample the guides are noise-free: prefiltering them would cost about five times the
    // denoise.
    api.setFilterBool(d.filter, "cleanAux", key.guided);
    api.setFilterInt(d.filter, "quality", qualityValue(quality));
  }
  Image output(color.width, color.height);
  setImage(api, d.filter, "color", color);
  if (aux != nullptr) {
    setImage(api, d.filter, "albedo", aux->albedo);
    setImage(api, d.filter, "normal", aux->normal);
  }
  setImage(api, d.filter, "output", output);
  api.commitFilter(d.filter);
  checkDevice(api, d.device, "committing the filter");
  api.executeFilter(d.filter);
  checkDevice(api, d.device, "denoising");
  for (std::size_t i = 3; i < output.rgba.size(); i += 4) output.rgba[i] = 1.0f;
  checkFinite(output, "the denoised image");
  return output;
}

}  // namespace raylab
