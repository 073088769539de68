#include "errors.h"

#include <pybind11/pybind11.h>

#include <filesystem>

#include "util/error.h"

namespace py = pybind11;

namespace raylab::python {

void registerErrorTranslation() {
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const Error& error) {
      if (error.exitCode() == kExitUsage) {
        PyErr_SetString(PyExc_ValueError, error.what());
      } else {
        PyErr_SetString(PyExc_RuntimeError, error.what());
      }
    }
  });
}

void requireFile(const std::string& path, const std::string& what) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    PyErr_SetString(PyExc_FileNotFoundError, (what + ": " + path + ": no such file").c_str());
    throw py::error_already_set();
  }
}

}  // namespace raylab::python
