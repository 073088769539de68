// The extension `raylab._raylab`: the engine library through pybind11. python/raylab/__init__.py re-exports it
// as the package `raylab` (docs/python.md).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

#include "bindings.h"
#include "device_context.h"
#include "errors.h"
#include "image/image.h"
#include "render/renderer.h"
#include "vk/vk_check.h"

namespace py = pybind11;

PYBIND11_MODULE(_raylab, m) {
  m.doc() = "raylab's engine: scenes, the renderer, the BRDF library and image files (docs/python.md).";
  m.attr("__version__") = RAYLAB_VERSION;
  // pybind11 initialises NumPy's C API lazily, under the GIL, at the first array: two threads whose first call
  // returns an array would deadlock in that initialisation (one holds its static guard and waits for the GIL,
  // the other holds the GIL and waits for the guard). Done here, at import, no thread can race it.
  py::module_::import("numpy");
  py::detail::npy_api::get();
  py::array_t<float> warmUp(std::vector<py::ssize_t>{1});
  py::array_t<std::uint8_t> warmUpBytes(std::vector<py::ssize_t>{1});
  py::array_t<double> warmUpDoubles(std::vector<py::ssize_t>{1});
  raylab::python::registerErrorTranslation();
  // The ranges the command line checks, for Python code that validates before work starts (raylab.farm).
  py::dict limits;
  limits["max_image_side"] = raylab::kMaxImageSide;
  limits["max_spp"] = raylab::kMaxSamplesPerPixel;
  limits["max_depth"] = raylab::kMaxDepthOption.max;
  limits["max_exposure_stops"] = raylab::kMaxExposureStops;
  m.attr("limits") = limits;
  // The render options as the engine declares them (util/render_options.h): values, defaults, ranges, help; the
  // farm's RenderJob and command line read these rather than repeating them. Keys use '_' for '-'.
  py::dict options;
  auto key = [](std::string_view name) {
    std::string text(name);
    for (char& c : text) c = c == '-' ? '_' : c;
    return text;
  };
  for (const raylab::ChoiceOption* option : raylab::kChoiceOptions) {
    py::list values;
    for (std::string_view value : option->values) values.append(std::string(value));
    py::dict entry;
    entry["values"] = values;
    entry["default"] = std::string(option->defaultValue);
    entry["help"] = std::string(option->help);
    options[py::str(key(option->name))] = entry;
  }
  {
    // Not a Renderer option (Renderer.render and raylab.denoise take it), but declared with them.
    py::list values;
    for (std::string_view value : raylab::kDenoiseQualityOption.values) values.append(std::string(value));
    py::dict entry;
    entry["values"] = values;
    entry["default"] = std::string(raylab::kDenoiseQualityOption.defaultValue);
    entry["help"] = std::string(raylab::kDenoiseQualityOption.help);
    options[py::str(key(raylab::kDenoiseQualityOption.name))] = entry;
  }
  py::dict depth;
  depth["min"] = raylab::kMaxDepthOption.min;
  depth["max"] = raylab::kMaxDepthOption.max;
  depth["default"] = raylab::kMaxDepthOption.defaultValue;
  depth["help"] = std::string(raylab::kMaxDepthOption.help);
  options[py::str(key(raylab::kMaxDepthOption.name))] = depth;
  m.attr("render_options") = options;
  // A test hook (vk/vk_check.h): the Nth Vulkan object created from now on fails to be created; 0 turns it off.
  // tests/python/test_renderer_churn.py checks that such failures release everything, with flat memory.
  m.def("_fail_at_creation", [](unsigned n) { raylab::failAtCreation(n); }, py::arg("n"));
  raylab::python::bindScene(m);
  raylab::python::bindRenderer(m);
  raylab::python::bindBrdf(m);
  raylab::python::bindImages(m);
  raylab::python::bindSweep(m);
  // Vulkan devices are released before the interpreter tears the module down.
  py::module_::import("atexit").attr("register")(py::cpp_function([] { raylab::python::releaseDeviceContexts(); }));
}
