// The extension `raylab._raylab`: the engine library through pybind11. python/raylab/__init__.py re-exports it
// as the package `raylab` (docs/python.md).
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "device_context.h"
#include "errors.h"

namespace py = pybind11;

PYBIND11_MODULE(_raylab, m) {
  m.doc() = "raylab's engine: scenes, the renderer, the BRDF library and image files (docs/python.md).";
  raylab::python::registerErrorTranslation();
  raylab::python::bindScene(m);
  raylab::python::bindRenderer(m);
  raylab::python::bindBrdf(m);
  raylab::python::bindImages(m);
  raylab::python::bindSweep(m);
  // Vulkan devices are released before the interpreter tears the module down.
  py::module_::import("atexit").attr("register")(py::cpp_function([] { raylab::python::releaseDeviceContexts(); }));
}
