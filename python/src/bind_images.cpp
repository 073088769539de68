// EXR and PNG files as numpy arrays, through the engine's readers and writers (every write atomic).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <vector>

#include "bindings.h"
#include "errors.h"
#include "util/error.h"

namespace py = pybind11;

namespace raylab::python {

py::array_t<float> arrayOf(const Image& image) {
  py::array_t<float> array({std::size_t(image.height), std::size_t(image.width), std::size_t(4)});
  std::memcpy(array.mutable_data(), image.rgba.data(), image.rgba.size() * sizeof(float));
  return array;
}

Image imageOf(const py::array_t<float, py::array::c_style | py::array::forcecast>& array, const std::string& where) {
  if (array.ndim() != 3 || (array.shape(2) != 3 && array.shape(2) != 4) || array.shape(0) < 1 || array.shape(1) < 1) {
    throw Error(where + ": expected an array of shape (height, width, 3 or 4)", kExitUsage);
  }
  const std::size_t height = array.shape(0), width = array.shape(1), channels = array.shape(2);
  if (width > kMaxImageSide || height > kMaxImageSide) {
    throw Error(where + ": " + std::to_string(width) + "x" + std::to_string(height) + " is larger than " +
                    std::to_string(kMaxImageSide) + " pixels a side",
                kExitUsage);
  }
  Image image(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height));
  const float* data = array.data();
  for (std::size_t i = 0; i < width * height; ++i) {
    for (std::size_t c = 0; c < 4; ++c) image.rgba[i * 4 + c] = c < channels ? data[i * channels + c] : 1.0f;
  }
  try {
    checkFinite(image, where);
  } catch (const Error& error) {
    throw Error(error.what(), kExitUsage);
  }
  return image;
}

namespace {

using FloatImage = py::array_t<float, py::array::c_style | py::array::forcecast>;

std::string checkedOutput(const std::filesystem::path& path, const char* extension, const std::string& where) {
  if (path.extension() != extension) {
    throw Error(where + ": '" + path.string() + "' must end in " + extension, kExitUsage);
  }
  return path.string();
}

ToneMap toneMapNamed(const std::string& name) {
  if (name == "clamp") return ToneMap::kClamp;
  if (name == "reinhard") return ToneMap::kReinhard;
  if (name == "aces") return ToneMap::kAces;
  throw Error("raylab.write_png: tonemap is clamp, reinhard or aces, not '" + name + "'", kExitUsage);
}

// An 8-bit array is display-referred already (read_png's): written as it is, without a tone curve.
void writeDisplayPng(const std::string& path, const py::array_t<std::uint8_t, py::array::c_style>& array) {
  if (array.ndim() != 3 || (array.shape(2) != 3 && array.shape(2) != 4) || array.shape(0) < 1 || array.shape(1) < 1 ||
      array.shape(0) > py::ssize_t(kMaxImageSide) || array.shape(1) > py::ssize_t(kMaxImageSide)) {
    throw Error("raylab.write_png: expected a uint8 array of shape (height, width, 3 or 4), at most " +
                    std::to_string(kMaxImageSide) + " a side",
                kExitUsage);
  }
  const std::size_t height = array.shape(0), width = array.shape(1), channels = array.shape(2);
  std::vector<std::uint8_t> rgb(width * height * 3);
  for (std::size_t i = 0; i < width * height; ++i) {
    for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = array.data()[i * channels + c];
  }
  writePngRgb8(path, std::uint32_t(width), std::uint32_t(height), rgb.data());
}

}  // namespace

void bindImages(py::module_& m) {
  m.def(
      "read_exr",
      [](const std::filesystem::path& path) {
        requireFile(path.string(), "raylab.read_exr");
        return arrayOf(readExr(path.string()));
      },
      py::arg("path"),
      "An OpenEXR image as a float32 array (height, width, 4), linear RGBA: R, G, B (or r, g, b, one layer's "
      "NAME.R/G/B, or luminance Y as grey), alpha 1 where the file has none; the display window, 0 outside the "
      "data window.");
  m.def(
      "write_exr",
      [](const std::filesystem::path& path, const FloatImage& array) {
        writeExr(checkedOutput(path, ".exr", "raylab.write_exr"), imageOf(array, "raylab.write_exr"));
      },
      py::arg("path"), py::arg("image"),
      "Writes a float array (height, width, 3 or 4) as OpenEXR float32 RGBA, atomically (a temporary file renamed "
      "over the target), as `raylab render` writes. NaN or infinity is refused (ValueError).");
  m.def(
      "write_png",
      [](const std::filesystem::path& path, const py::array& array, float exposure, const std::string& tonemap) {
        const std::string file = checkedOutput(path, ".png", "raylab.write_png");
        const ToneMap curve = toneMapNamed(tonemap);
        if (!(std::abs(exposure) <= kMaxExposureStops)) {
          throw Error("raylab.write_png: exposure must be a finite number of stops within [-20, 20]", kExitUsage);
        }
        if (array.dtype().is(py::dtype::of<std::uint8_t>())) {
          writeDisplayPng(file, array.cast<py::array_t<std::uint8_t, py::array::c_style>>());
          return;
        }
        writePng(file, imageOf(array.cast<FloatImage>(), "raylab.write_png"), exposure, curve);
      },
      py::arg("path"), py::arg("image"), py::kw_only(), py::arg("exposure") = 0.0f, py::arg("tonemap") = "clamp",
      "Writes a linear float image as an 8-bit sRGB PNG after exposure (stops) and a tone curve, as `raylab render "
      "--png`; a uint8 array (read_png's) is display-referred and written as it is.");
  m.def(
      "read_png",
      [](const std::filesystem::path& path) {
        requireFile(path.string(), "raylab.read_png");
        const Rgb8Image image = readPngRgb8(path.string());
        py::array_t<std::uint8_t> array({std::size_t(image.height), std::size_t(image.width), std::size_t(3)});
        std::memcpy(array.mutable_data(), image.rgb.data(), image.rgb.size());
        return array;
      },
      py::arg("path"), "A PNG as a uint8 array (height, width, 3), sRGB as stored.");
}

}  // namespace raylab::python
