// raylab's errors as Python exceptions, with the command line's messages: a usage error (a bad option, name or
// value) is ValueError, a missing file FileNotFoundError, a directory IsADirectoryError, anything else (no
// capable device, a failed dispatch) RuntimeError.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include <pybind11/pybind11.h>

namespace raylab::python {

// Registers the translation of raylab::Error with pybind11.
void registerErrorTranslation();

// Throws FileError (FileNotFoundError, IsADirectoryError, ValueError for a FIFO or device) naming `what` and
// `path` when it is not a regular file of at most maxBytes, before any work starts.
void requireFile(const std::string& path, const std::string& what,
                 std::uint64_t maxBytes = std::numeric_limits<std::uint64_t>::max());

// A path argument: str, bytes or os.PathLike (decoded as os.fsdecode does). ValueError naming `where` for any
// other type, and for a NUL character, which the operating system would silently cut the path at.
std::string pathArgument(const pybind11::object& value, const std::string& where);

}  // namespace raylab::python
