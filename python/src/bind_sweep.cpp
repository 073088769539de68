// raylab._raylab.SweepStudy: `raylab sweep`'s study for raylab.farm. The farm parses the command line with the
// command's own options (sweep_study.h), renders each cell as an independent job on whichever worker takes it, and
// writes the same contact sheet from the cells.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "bindings.h"
#include "sweep_study/sweep_study.h"
#include "util/error.h"

namespace py = pybind11;

namespace raylab::python {

namespace {

struct PythonSweepStudy {
  SweepStudy study;
  std::unique_ptr<SweepCellRenderer> cells;  // this process's device, made at the first cell

  void prepare() {
    py::gil_scoped_release release;
    if (!cells) cells = std::make_unique<SweepCellRenderer>(study, true);
  }

  py::array_t<float> renderCell(std::uint32_t cell) {
    prepare();
    Image image;
    {
      py::gil_scoped_release release;
      image = renderSweepCell(*cells, study, cell, [](std::uint32_t) {
        // Between submissions: Ctrl-C stops the cell (the farm reruns it).
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      });
    }
    return arrayOf(image);
  }
};

}  // namespace

void bindSweep(py::module_& m) {
  m.def(
      "sweep_help",
      [] {
        SweepOptions options;
        return parseSweepArguments({"--help"}, options);
      },
      "`raylab sweep --help`.");
  py::class_<PythonSweepStudy>(m, "SweepStudy",
                               "A parameter sweep as `raylab sweep ARGUMENTS` describes it: its cells rendered one by "
                               "one (on any process) and its contact sheet.")
      .def(py::init([](const std::vector<std::string>& arguments, bool outputs) {
             SweepOptions options;
             const std::string help = parseSweepArguments(arguments, options);
             if (!help.empty()) throw Error("raylab sweep: --help is not a study", kExitUsage);
             auto study = std::make_unique<PythonSweepStudy>();
             study->study = planSweep(options, outputs ? SweepOutputs::CheckAndWrite : SweepOutputs::None);
             return study;
           }),
           py::arg("arguments"), py::kw_only(), py::arg("outputs") = true,
           "Parses and checks `raylab sweep`'s options (ValueError with the command's message). With outputs, "
           "also checks the output paths (creating their directories) and writes --gltf, as the command does: the "
           "farm's client; its workers pass outputs=False and only render cells.")
      .def_property_readonly("cells", [](const PythonSweepStudy& s) { return s.study.sweep.values.size(); })
      .def_property_readonly("spp", [](const PythonSweepStudy& s) { return s.study.options.spp; })
      .def_property_readonly("cell_size", [](const PythonSweepStudy& s) { return s.study.options.cell; })
      .def_property_readonly("renders", [](const PythonSweepStudy& s) { return s.study.render; },
                             "False for --gltf alone: nothing to render.")
      .def_property_readonly("png_path", [](const PythonSweepStudy& s) { return s.study.pngPath; })
      .def_property_readonly("exr_path", [](const PythonSweepStudy& s) { return s.study.exrPath; })
      .def_property_readonly("key", [](const PythonSweepStudy& s) { return sweepCellKey(s.study); },
                             "What decides the cells' pixels, as a hexadecimal key (finished cells are kept under it).")
      .def_property_readonly("values", [](const PythonSweepStudy& s) { return s.study.sweep.values; })
      .def("label", [](const PythonSweepStudy& s, std::uint32_t cell) { return sweepLabel(s.study.sweep, cell); })
      .def_property_readonly("title", [](const PythonSweepStudy& s) { return sweepTitle(s.study.sweep); })
      .def("prepare", &PythonSweepStudy::prepare,
           "Creates this process's device and uploads the cell scene (otherwise done by the first render_cell).")
      .def("render_cell", &PythonSweepStudy::renderCell, py::arg("cell"),
           "Renders one cell on this process's device: float32 (cell, cell, 4).")
      .def(
          "write_sheet",
          [](const PythonSweepStudy& s, const std::vector<py::array_t<float, py::array::c_style | py::array::forcecast>>& arrays) {
            std::vector<Image> cells;
            for (const auto& array : arrays) cells.push_back(imageOf(array, "raylab sweep: a cell"));
            py::gil_scoped_release release;
            writeSweepSheet(s.study, cells);
          },
          py::arg("cells"), "Writes the contact sheet (EXR and PNG) from the cells in order, as `raylab sweep`.");
}

}  // namespace raylab::python
