#include "errors.h"

#include <pybind11/pybind11.h>

#include "util/error.h"
#include "util/files.h"

namespace py = pybind11;

namespace raylab::python {

namespace {

// The Python exception for what was wrong with an input file: the built-in OSError subclasses where one fits.
PyObject* exceptionFor(FileProblem problem) {
  switch (problem) {
    case FileProblem::kMissing: return PyExc_FileNotFoundError;
    case FileProblem::kDirectory: return PyExc_IsADirectoryError;
    case FileProblem::kNotRegular:
    case FileProblem::kTooLarge: return PyExc_ValueError;
    case FileProblem::kUnreadable: return PyExc_OSError;
  }
  return PyExc_OSError;
}

}  // namespace

void registerErrorTranslation() {
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const FileError& error) {
      PyErr_SetString(exceptionFor(error.problem()), error.what());
    } catch (const Error& error) {
      if (error.exitCode() == kExitUsage) {
        PyErr_SetString(PyExc_ValueError, error.what());
      } else {
        PyErr_SetString(PyExc_RuntimeError, error.what());
      }
    }
  });
}

void requireFile(const std::string& path, const std::string& what, std::uint64_t maxBytes) {
  FileProblem problem{};
  const std::string message = inputFileProblem(path, maxBytes, &problem);
  if (!message.empty()) throw FileError(what + ": " + path + ": " + message, problem);
}

std::string pathArgument(const pybind11::object& value, const std::string& where) {
  namespace py = pybind11;
  if (!py::isinstance<py::str>(value) && !py::isinstance<py::bytes>(value) && !py::hasattr(value, "__fspath__")) {
    throw Error(where + ": expected a path (str, bytes or os.PathLike)", kExitUsage);
  }
  const py::module_ os = py::module_::import("os");
  const std::string path = os.attr("fsdecode")(os.attr("fspath")(value)).cast<std::string>();
  if (path.find('\0') != std::string::npos) throw Error(where + ": the path has a NUL character", kExitUsage);
  if (path.empty()) throw Error(where + ": the path is empty", kExitUsage);
  return path;
}

}  // namespace raylab::python
