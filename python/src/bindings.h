// The parts of the Python module `raylab._raylab`, one file each, and the helpers they share.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "image/image.h"
#include "scene/scene.h"

namespace raylab::python {

void bindScene(pybind11::module_& m);     // devices(), Scene
void bindRenderer(pybind11::module_& m);  // Renderer
void bindBrdf(pybind11::module_& m);      // brdf.eval, sample, pdf, albedo, models
void bindImages(pybind11::module_& m);    // read_exr, write_exr, write_png, read_png
void bindSweep(pybind11::module_& m);     // SweepStudy, for raylab.farm

// A material's model and parameters as a dict; a record from a model name and parameters (each value a number or
// (r, g, b)); ValueError naming `where`, the parameter and its range on a bad one.
pybind11::dict materialDict(const Material& material);
gpu::MaterialRecord recordOf(const std::string& model, const pybind11::dict& params, const std::string& where);

// An image as a float32 array (height, width, 4), and back (3 or 4 channels; alpha 1 when absent).
pybind11::array_t<float> arrayOf(const Image& image);
Image imageOf(const pybind11::array_t<float, pybind11::array::c_style | pybind11::array::forcecast>& array,
              const std::string& where);

}  // namespace raylab::python
