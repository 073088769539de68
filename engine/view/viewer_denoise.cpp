// The viewer's denoised view (docs/viewer.md, "Denoising"): while the camera is still, Open Image Denoise runs on a
// thread of its own over the refined image and its first-hit albedo and normal, at 1, 16, 64, 256, ... samples per
// pixel and at the spp limit, and each result replaces what the display pass reads until the next one or until the
// view changes. The
// kernel accumulates the albedo and normal only while the switch is on (kFeatureAovs, a background rebuild).
// Comparisons are never denoised: the split and difference views show the raw images, so that a denoiser can
// neither hide nor invent a difference between two BRDFs.
#include <cstdio>
#include <exception>

#include "denoise/denoise.h"
#include "shared/features.h"
#include "view/viewer_state.h"

namespace raylab {

namespace {

// The samples per pixel at which the still image is denoised next after `samples`: 1, 16, 64, 256, ... Each denoise
// takes the CPU from tracing (0.46 s of both cores at 1280x720): one at 1 spp shows a clean image at once, and
// skipping 4 spp brings the denoised 16 spp about a second sooner (docs/performance.md, "Denoising").
std::uint32_t nextDenoiseTarget(std::uint32_t samples) {
  std::uint32_t target = 1;
  while (target <= samples && target < (1u << 28)) target = target == 1 ? 16 : target * 4;
  return target;
}

// The viewer denoises for the screen: OIDN's fast quality, about half the time of high (issue 39's figures).
constexpr DenoiseQuality kViewerQuality = DenoiseQuality::kFast;

// Puts the denoised image where the display pass reads the accumulation: its colour with a sample count of 1.
void showDenoised(Viewer& v, const Image& image) {
  waitForFrames(v);  // frames in flight read the buffer being replaced
  DenoisedView& d = v.denoised;
  const VkDeviceSize bytes = VkDeviceSize(image.rgba.size()) * sizeof(float);
  if (d.shown.size != bytes) {
    destroyBuffer(v.device, d.shown);
    d.shown = createBuffer(v.device, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           MemoryUse::kDevice, "denoised image");
  }
  uploadBuffer(v.device, d.shown, image.rgba.data(), bytes);  // readImage and denoise leave alpha (the count) at 1
  bindAccumulation(v.device, v.display, d.shown.handle);
  d.showing = true;
  d.image = image;
  v.pending.display = true;  // every tile again, from the new source
}

}  // namespace

bool denoiseApplies(const Viewer& v) { return v.settings.denoise && !v.comparison.active; }

void discardDenoised(Viewer& v, bool rebind) {
  DenoisedView& d = v.denoised;
  ++d.generation;  // a job still running belongs to the old view: its result is dropped
  d.nextSamples = 1;
  d.jobSamples = 0;
  if (!d.showing) return;
  d.showing = false;
  d.image = {};
  if (rebind) {
    waitForFrames(v);
    bindAccumulation(v.device, v.display, v.renderer.accumulation.handle);
    v.pending.display = true;
  }
}

void updateDenoise(Viewer& v) {
  DenoisedView& d = v.denoised;
  if (d.job.valid() && (v.automation || d.job.wait_for(std::chrono::seconds(0)) == std::future_status::ready)) {
    try {
      Image image = d.job.get();
      if (d.jobGeneration == d.generation && denoiseApplies(v)) {
        showDenoised(v, image);
        d.shownSamples = d.jobSamples;
        v.report.denoised.push_back({d.jobSamples, d.jobStartSeconds, v.clock.seconds()});
      }
    } catch (const std::exception& error) {
      // A failed denoise turns the switch off and says why; the raw image goes on refining.
      v.settings.denoise = false;
      v.status.message = std::string("denoise: ") + error.what();
      if (!v.options.quiet) std::fprintf(stderr, "raylab view: %s\n", v.status.message.c_str());
    }
  }
  if (!denoiseApplies(v)) {
    if (d.showing) discardDenoised(v, true);
    return;
  }
  if (d.job.valid() || v.scheduler.preview || !hasAuxiliaryImages(v.renderer)) return;
  const std::uint32_t samples = v.scheduler.sampleIndex;  // complete full-resolution passes
  // At 1, 4, 16, ... spp, and once more at the limit, whatever it is.
  const bool due = samples >= d.nextSamples || (converged(v.scheduler) && samples > d.jobSamples);
  if (!due || samples == 0 || v.scheduler.traceExtent != v.scheduler.fullExtent) return;
  waitForFrames(v);
  Image colour = readImage(v.device, v.renderer);
  AuxiliaryImages guides = readAuxiliaryImages(v.device, v.renderer);
  d.jobGeneration = d.generation;
  d.jobSamples = samples;
  d.jobStartSeconds = v.clock.seconds();
  d.nextSamples = nextDenoiseTarget(samples);
  d.job = std::async(std::launch::async, [colour = std::move(colour), guides = std::move(guides)] {
    return denoise(colour, &guides, kViewerQuality);
  });
}

void setDenoise(Viewer& v, bool on) {
  if (v.settings.denoise == on) return;
  v.settings.denoise = on;
  if (on) {
    try {
      loadDenoiser();
    } catch (const std::exception& error) {
      v.settings.denoise = false;
      v.status.message = std::string("denoise: ") + error.what();
      if (!v.options.quiet) std::fprintf(stderr, "raylab view: %s\n", v.status.message.c_str());
      return;
    }
    v.denoised.nextSamples = 1;
  } else {
    discardDenoised(v, true);
  }
  v.needed = neededKernel(v);  // the albedo and normal images, compiled in while it is on
  ensureKernel(v);
}

bool denoisedToTheLimit(const Viewer& v) {
  return !denoiseApplies(v) || (v.denoised.showing && v.denoised.shownSamples >= v.scheduler.sampleIndex);
}

std::string denoiseStatus(const Viewer& v) {
  if (!v.settings.denoise) return "";
  if (v.comparison.active) return "not denoised: comparisons show the raw images";
  if (v.denoised.showing) return "denoised at " + std::to_string(v.denoised.shownSamples) + " spp (Open Image Denoise)";
  if (!hasAuxiliaryImages(v.renderer)) return "denoise: waiting for the kernel with albedo and normal";
  return "denoise: waiting for the image to settle";
}

void destroyDenoisedView(Viewer& v) {
  if (v.denoised.job.valid()) v.denoised.job.wait();
  destroyBuffer(v.device, v.denoised.shown);
  v.denoised = {};
}

}  // namespace raylab
