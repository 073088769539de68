#include "denoise/denoise.h"

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

// The device and filter of one call, released however it ends.
struct Session {
  const oidn::Api& api;
  oidn::Device device = nullptr;
  oidn::Filter filter = nullptr;
  ~Session() {
    if (filter != nullptr) api.releaseFilter(filter);
    if (device != nullptr) api.releaseDevice(device);
  }
  void check(const char* step) const {
    const char* message = nullptr;
    if (api.getDeviceError(device, &message) != oidn::kErrorNone) {
      throw Error(std::string("Open Image Denoise (") + api.path + ") failed at " + step + ": " +
                  (message != nullptr ? message : "no message"));
    }
  }
};

// An RGBA float image as OIDN's FLOAT3 at a 16-byte pixel stride: the alpha channel is skipped, nothing copied.
void setImage(const Session& session, const char* name, const Image& image) {
  session.api.setSharedFilterImage(session.filter, name, const_cast<float*>(image.rgba.data()), oidn::kFormatFloat3,
                                   image.width, image.height, 0, 4 * sizeof(float),
                                   std::size_t(image.width) * 4 * sizeof(float));
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
  Session session{oidn::api()};
  session.device = session.api.newDevice(oidn::kDeviceTypeCpu);
  if (session.device == nullptr) throw Error("Open Image Denoise (" + session.api.path + ") made no CPU device");
  session.api.commitDevice(session.device);
  session.check("its CPU device");
  session.filter = session.api.newFilter(session.device, "RT");
  session.check("its RT filter");
  Image output(color.width, color.height);
  setImage(session, "color", color);
  if (aux != nullptr) {
    setImage(session, "albedo", aux->albedo);
    setImage(session, "normal", aux->normal);
    // Accumulated over every sample they are noise-free: prefiltering them would cost about five times the denoise.
    session.api.setFilterBool(session.filter, "cleanAux", true);
  }
  setImage(session, "output", output);
  session.api.setFilterBool(session.filter, "hdr", true);
  session.api.setFilterInt(session.filter, "quality", qualityValue(quality));
  session.api.commitFilter(session.filter);
  session.check("committing the filter");
  session.api.executeFilter(session.filter);
  session.check("denoising");
  for (std::size_t i = 3; i < output.rgba.size(); i += 4) output.rgba[i] = 1.0f;
  checkFinite(output, "the denoised image");
  return output;
}

}  // namespace raylab
