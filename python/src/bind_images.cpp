// EXR and PNG files as numpy arrays, through the engine's readers and writers (every write atomic).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstring>

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
  return image;
}

void bindImages(py::module_& m) {
  m.def(
      "read_exr",
      [](const std::string& path) {
        requireFile(path, "raylab.read_exr");
        return arrayOf(readExr(path));
      },
      py::arg("path"), "An OpenEXR image as a float32 array (height, width, 4), linear RGBA.");
  m.def(
      "write_exr", [](const std::string& path, const py::array_t<float, py::array::c_style | py::array::forcecast>& array) {
        writeExr(path, imageOf(array, "raylab.write_exr"));
      },
      py::arg("path"), py::arg("image"),
      "Writes a float array (height, width, 3 or 4) as OpenEXR float32 RGBA, atomically (a temporary file renamed "
      "over the target), as `raylab render` writes.");
  m.def(
      "write_png",
      [](const std::string& path, const py::array_t<float, py::array::c_style | py::array::forcecast>& array,
         float exposure, const std::string& tonemap) {
        ToneMap curve = ToneMap::kClamp;
        if (tonemap == "reinhard") curve = ToneMap::kReinhard;
        else if (tonemap == "aces") curve = ToneMap::kAces;
        else if (tonemap != "clamp") throw Error("raylab.write_png: tonemap is clamp, reinhard or aces, not '" + tonemap + "'", kExitUsage);
        writePng(path, imageOf(array, "raylab.write_png"), exposure, curve);
      },
      py::arg("path"), py::arg("image"), py::kw_only(), py::arg("exposure") = 0.0f, py::arg("tonemap") = "clamp",
      "Writes a linear image as an 8-bit sRGB PNG after exposure (stops) and a tone curve, as `raylab render --png`.");
  m.def(
      "read_png",
      [](const std::string& path) {
        requireFile(path, "raylab.read_png");
        const Rgb8Image image = readPngRgb8(path);
        py::array_t<std::uint8_t> array({std::size_t(image.height), std::size_t(image.width), std::size_t(3)});
        std::memcpy(array.mutable_data(), image.rgb.data(), image.rgb.size());
        return array;
      },
      py::arg("path"), "A PNG as a uint8 array (height, width, 3), sRGB as stored.");
}

}  // namespace raylab::python
