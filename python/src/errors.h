// raylab's errors as Python exceptions, with the command line's messages: a usage error (a bad option, name or
// value) is ValueError, a missing file FileNotFoundError, anything else (no capable device, a failed dispatch)
// RuntimeError.
#pragma once

#include <string>

namespace raylab::python {

// Registers the translation of raylab::Error with pybind11.
void registerErrorTranslation();

// Throws FileNotFoundError naming `path` when it is not a regular file ("raylab render: FILE: no such file").
void requireFile(const std::string& path, const std::string& what);

}  // namespace raylab::python
