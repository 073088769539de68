// raylab.Renderer: a scene on a device and the render kernel over it, accumulating samples per pixel, as
// `raylab render` does with the same options (same kernel, same sample order: the same image bit for bit).
// Samples run in submissions of about a quarter second with the GIL released; between two, Ctrl-C
// (KeyboardInterrupt) and Renderer.cancel() from another thread stop the render.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "bindings.h"
#include "device_context.h"
#include "render/gpu_scene.h"
#include "render/renderer.h"
#include "util/error.h"
#include "util/timer.h"
#include "render/render_choices.h"
#include "shared/features.h"
#include "util/render_options.h"

namespace py = pybind11;

namespace raylab::python {

namespace {

// Renderer.cancel() was called: raised as raylab.Cancelled (a RuntimeError).
struct Cancelled : std::runtime_error {
  using std::runtime_error::runtime_error;
};

constexpr double kSubmissionSeconds = 0.25;

class PythonRenderer {
 public:
  PythonRenderer(const Scene& scene, std::uint32_t width, std::uint32_t height, const std::string& integrator,
                 const std::string& sampling, const std::string& fresnel, bool allFeatures, const std::string& backend,
                 const std::string& schedule, std::uint32_t maxDepth, std::uint32_t seed, bool jitter, bool aovs,
                 const std::string& guiding, std::optional<std::uint32_t> device)
      : scene_(scene) {
    const std::string where = "raylab.Renderer";
    checkCount(kMaxDepthOption, maxDepth, where);
    KernelOptions kernel;
    kernel.integrator = parseIntegratorChoice(integrator, where);
    kernel.sampling = parseSampling(sampling, where);
    kernel.schlickFresnel = parseSchlickFresnel(fresnel, where);
    const Schedule scheduleChoice = parseSchedule(schedule, where);
    const BackendChoice backendChoice = parseBackendChoice(backend, where);
    const Guiding guidingChoice = parseGuiding(guiding, where);
    kernel.allFeatures = allFeatures;
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.maxDepth = maxDepth;
    settings.seed = seed;
    settings.jitter = jitter;
    settings.aovs = aovs;
    settings.kernel = kernelFor(scene_, kernel);
    settings.schedule = scheduleChoice;
    settings.guiding = guidingChoice;

    context_ = deviceContext(device);
    const Device& d = context_->session.device;
    const std::lock_guard<std::mutex> lock(context_->queue);
    settings.backend = chooseBackend(d, backendChoice);
    checkImageSize(d, width, height);
    gpuScene_ = uploadScene(d, scene_);
    try {
      renderer_ = createRenderer(d, gpuScene_, scene_, settings);
    } catch (...) {
      destroyGpuScene(d, gpuScene_);
      throw;
    }
  }

  ~PythonRenderer() {
    const std::lock_guard<std::mutex> lock(context_->queue);
    destroyRenderer(context_->session.device, renderer_);
    destroyGpuScene(context_->session.device, gpuScene_);
  }

  py::object render(std::int64_t spp, std::optional<std::uint32_t> seed, bool denoise,
                    const std::string& denoiseQuality) {
    if (spp < 1 || spp > std::int64_t(kMaxSamplesPerPixel)) {
      throw Error("raylab.Renderer.render: spp must be within 1.." + std::to_string(kMaxSamplesPerPixel), kExitUsage);
    }
    checkDenoiseQuality(denoiseQuality);
    // Refused before the render when Open Image Denoise is missing, as `raylab render --denoise` does.
    if (denoise) py::module_::import("raylab.denoise").attr("_load")();
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(context_->queue);
      if (denoise) accumulateAuxiliaryImages();
      if (seed) renderer_.params.seed = *seed;
      resetAccumulation(context_->session.device, renderer_);
    }
    addSamples(spp);
    if (!denoise) return image();
    const py::tuple guides = auxiliary();
    return py::module_::import("raylab.denoise").attr("_denoised_rgba")(image(), guides[0], guides[1], denoiseQuality);
  }

  // The first-hit albedo and normal of the samples so far, float32 (height, width, 4) each.
  py::tuple auxiliary() {
    AuxiliaryImages images;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(context_->queue);
      if (!hasAuxiliaryImages(renderer_)) {
        throw Error("raylab.Renderer.auxiliary: this renderer does not accumulate them: make it with aovs=True, or "
                    "render(..., denoise=True)",
                    kExitUsage);
      }
      images = readAuxiliaryImages(context_->session.device, renderer_);
    }
    return py::make_tuple(arrayOf(images.albedo), arrayOf(images.normal));
  }

  // Python integers of any size arrive here unconverted, so that 2^32 is refused rather than wrapped.
  void addSamples(std::int64_t samples) {
    // Checked as a sum: samplesDone + samples must neither wrap nor pass the accumulation's limit.
    if (samples < 1) throw Error("raylab.Renderer.add_samples: n must be at least 1", kExitUsage);
    if (std::uint64_t(samples) > kMaxSamplesPerPixel - std::min(renderer_.samplesDone, kMaxSamplesPerPixel)) {
      throw Error("raylab.Renderer.add_samples: " + std::to_string(renderer_.samplesDone) + " + " +
                      std::to_string(samples) + " samples would pass the limit of " +
                      std::to_string(kMaxSamplesPerPixel) + " per pixel",
                  kExitUsage);
    }
    cancelled_ = false;
    const std::uint32_t target = renderer_.samplesDone + std::uint32_t(samples);
    std::uint32_t batch = 1;
    while (renderer_.samplesDone < target) {
      const std::uint32_t count = std::min(batch, target - renderer_.samplesDone);
      double seconds = 0.0;
      {
        py::gil_scoped_release release;
        const std::lock_guard<std::mutex> lock(context_->queue);
        const Stopwatch clock;
        renderSamples(context_->session.device, renderer_, count);
        seconds = clock.seconds();
      }
      if (!firstSampleSeconds_) {
        firstSampleSeconds_ = seconds;  // the driver compiles the kernel at its first dispatch
      } else {
        renderSeconds_ += seconds;
        renderSamples_ += count;
      }
      const double perSample = seconds / count;
      batch = std::clamp<std::uint32_t>(static_cast<std::uint32_t>(kSubmissionSeconds / std::max(perSample, 1e-6)), 1, 256);
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C: KeyboardInterrupt
      if (cancelled_.exchange(false)) {
        throw Cancelled("raylab.Renderer: cancelled after " + std::to_string(renderer_.samplesDone) + " samples");
      }
    }
  }

  py::array_t<float> image() {
    Image image;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(context_->queue);
      image = readImage(context_->session.device, renderer_);
    }
    return arrayOf(image);
  }

  void cancel() { cancelled_ = true; }

 private:
  static void checkDenoiseQuality(const std::string& quality) {
    choiceIndex(kDenoiseQualityOption, quality, "raylab.Renderer.render: denoise_quality");
  }

  // Switches the kernel to the variant that also accumulates the first-hit images (once; the driver compiles it at
  // its first dispatch). The caller holds the queue and resets the accumulation.
  void accumulateAuxiliaryImages() {
    if (hasAuxiliaryImages(renderer_)) return;
    const Device& d = context_->session.device;
    KernelFeatures kernel = renderer_.kernel;
    kernel.features |= gpu::kFeatureAovs;
    swapRenderPipelines(d, renderer_, createRenderPipelines(d, renderer_, kernel), kernel);
    firstSampleSeconds_.reset();  // the next first sample includes the new kernel's compilation
  }

 public:
  std::uint32_t samples() const { return renderer_.samplesDone; }

  py::dict report() const {
    const DeviceReport& device = context_->session.device.report;
    py::dict d;
    d["width"] = renderer_.params.width;
    d["height"] = renderer_.params.height;
    d["samples"] = renderer_.samplesDone;
    d["device"] = device.name;
    d["driver"] = device.driver;
    d["backend"] = backendName(renderer_.trace.backend);
    d["integrator"] = std::string(integratorName(renderer_.kernel.integrator));
    d["kernel"] = describe(renderer_.kernel);
    d["schedule"] = renderer_.wavefrontActive ? "wavefront" : "megakernel";
    d["guiding"] = std::string(kGuidingValues[std::size_t(renderer_.guide.mode)]);
    if (renderer_.guide.mode != Guiding::kOff) {
      py::dict guide;
      guide["updates"] = renderer_.guide.summary.updates;
      guide["cells"] = renderer_.guide.summary.cellsGuided;
      guide["moment_ratio"] = renderer_.guide.summary.decided ? py::object(py::float_(renderer_.guide.summary.momentRatio))
                                                              : py::object(py::none());
      guide["guiding"] = renderer_.guide.summary.guiding;
      guide["text"] = describeGuide(renderer_.guide);
      d["guide"] = guide;
    }
    d["acceleration_s"] = gpuScene_.accelerationBuildSeconds;
    d["first_sample_s"] = firstSampleSeconds_.value_or(0.0);
    d["steady_s"] = renderSeconds_;
    d["per_sample_s"] = renderSamples_ > 0 ? renderSeconds_ / renderSamples_ : firstSampleSeconds_.value_or(0.0);
    py::dict rays;
    rays["primary"] = renderer_.rays.primary;
    rays["shadow"] = renderer_.rays.shadow;
    rays["secondary"] = renderer_.rays.secondary;
    rays["total"] = renderer_.rays.total();
    d["rays"] = rays;
    const double seconds = renderSeconds_ + firstSampleSeconds_.value_or(0.0);
    d["rays_per_s"] = seconds > 0.0 ? double(renderer_.rays.total()) / seconds : 0.0;
    d["dropped_samples"] = renderer_.droppedSamples;
    return d;
  }

 private:
  Scene scene_;
  std::shared_ptr<DeviceContext> context_;
  GpuScene gpuScene_;
  Renderer renderer_;
  std::atomic<bool> cancelled_{false};
  std::optional<double> firstSampleSeconds_;
  double renderSeconds_ = 0.0;
  std::uint64_t renderSamples_ = 0;
};

}  // namespace

void bindRenderer(py::module_& m) {
  py::register_exception<Cancelled>(m, "Cancelled", PyExc_RuntimeError);
  py::class_<PythonRenderer>(m, "Renderer",
                             "A scene on a Vulkan device with its render kernel, accumulating samples per pixel. "
                             "The options are `raylab render`'s; render(spp) gives the image `raylab render --spp "
                             "SPP` writes to its EXR, bit for bit. The renderer holds a copy of the scene: edits "
                             "made to the Scene afterwards need a new Renderer.")
      .def(py::init<const Scene&, std::uint32_t, std::uint32_t, const std::string&, const std::string&,
                    const std::string&, bool, const std::string&, const std::string&, std::uint32_t, std::uint32_t,
                    bool, bool, const std::string&, std::optional<std::uint32_t>>(),
           py::arg("scene"), py::kw_only(), py::arg("width") = 640, py::arg("height") = 360,
           py::arg("integrator") = std::string(kIntegratorOption.defaultValue),
           py::arg("sampling") = std::string(kSamplingOption.defaultValue),
           py::arg("fresnel") = std::string(kFresnelOption.defaultValue), py::arg("all_features") = false,
           py::arg("backend") = std::string(kBackendOption.defaultValue),
           py::arg("schedule") = std::string(kScheduleOption.defaultValue),
           py::arg("max_depth") = kMaxDepthOption.defaultValue, py::arg("seed") = 0, py::arg("jitter") = true, py::arg("aovs") = false,
           py::arg("guiding") = std::string(kGuidingOption.defaultValue), py::arg("device") = py::none())
      .def("render", &PythonRenderer::render, py::arg("spp") = 16, py::arg("seed") = py::none(),
           py::arg("denoise") = false,
           py::arg("denoise_quality") = std::string(kDenoiseQualityOption.defaultValue),
           "Clears the accumulation and renders spp samples per pixel (with `seed`, else the renderer's); returns the "
           "mean radiance, float32 (height, width, 4), alpha 1. denoise=True returns it denoised by Open Image "
           "Denoise (raylab.denoise, guided by the first-hit albedo and normal, which the renderer then accumulates; "
           "image() still reads the raw mean).")
      .def("auxiliary", &PythonRenderer::auxiliary,
           "The first-hit albedo and normal images of the samples so far, a pair of float32 (height, width, 4): what "
           "raylab.denoise takes as albedo and normal. Needs aovs=True or a render with denoise=True.")
      .def("add_samples", &PythonRenderer::addSamples, py::arg("n"),
           "Adds n samples per pixel to the accumulation, for progressive use; image() reads the result.")
      .def("image", &PythonRenderer::image, "The mean radiance so far, float32 (height, width, 4).")
      .def("cancel", &PythonRenderer::cancel,
           "Stops a render running in another thread after its current submission (it raises raylab.Cancelled).")
      .def_property_readonly("samples", &PythonRenderer::samples, "Samples per pixel accumulated so far.")
      .def("report", &PythonRenderer::report,
           "What `raylab render --report` records: size, samples, device, backend, integrator, kernel, schedule, "
           "guiding (and with it the guide's cells), times (acceleration, first sample, steady) and ray counts.");
}

}  // namespace raylab::python
