// raylab.brdf: the BRDF library over numpy arrays, on the device (the shaders' code, as `raylab brdf eval
// --backend gpu`) or the double-precision reference (`--backend cpu`). Directions are float32 on the way in, as
// the CSV's are, so both backends evaluate exactly the values the command line would.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "brdf_eval/albedo_estimate.h"
#include "brdf_eval/brdf_cases.h"
#include "brdf_eval/cpu_evaluator.h"
#include "brdf_params/material_params.h"
#include "device_context.h"
#include "errors.h"
#include "fit/fit.h"
#include "measured/merl.h"
#include "util/atomic_file.h"
#include "reference/brdf_reference.h"
#include "util/error.h"
#include "util/files.h"

namespace py = pybind11;

namespace raylab::python {

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

[[noreturn]] void usage(const std::string& message) { throw Error(message, kExitUsage); }

// Largest batch of one call: 2^24 cases are 2.3 GiB of device buffers.
constexpr std::size_t kMaxCases = std::size_t(1) << 24;

// (N, 3), or (3,): one vector for every case. `count` is the common N: unset until an (N, 3) array sets it, and
// N may be 0 (an empty batch gives empty results).
std::vector<glm::vec3> vectors(const FloatArray& array, const char* name, std::optional<std::size_t>& count) {
  std::size_t rows = 0;
  const bool broadcast = array.ndim() == 1 && array.shape(0) == 3;
  if (broadcast) rows = 1;
  else if (array.ndim() == 2 && array.shape(1) == 3) rows = array.shape(0);
  else usage(std::string("raylab.brdf: ") + name + " must have shape (N, 3) or (3,)");
  if (rows > kMaxCases) usage(std::string("raylab.brdf: ") + name + ": more than 2^24 vectors in one call");
  if (!broadcast) {
    if (count && *count != rows) {
      usage(std::string("raylab.brdf: ") + name + " has " + std::to_string(rows) + " rows, the others " +
            std::to_string(*count));
    }
    count = rows;
  }
  std::vector<glm::vec3> out(rows);
  const float* data = array.data();
  for (std::size_t i = 0; i < rows; ++i) {
    out[i] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z)) {
      usage(std::string("raylab.brdf: ") + name + "[" + std::to_string(i) + "] is not finite");
    }
  }
  return out;
}

glm::vec3 pick(const std::vector<glm::vec3>& v, std::size_t i) { return v.size() == 1 ? v[0] : v[i]; }

gpu::MaterialRecord material(const std::string& model, const py::object& params) {
  const std::string where = "raylab.brdf: " + model;
  if (params.is_none()) return recordOf(model, py::dict(), where);
  if (py::isinstance<py::str>(params)) {
    try {
      return parseMaterial(model, params.cast<std::string>(), "raylab.brdf");
    } catch (const Error& error) {
      usage(error.what());
    }
  }
  if (py::isinstance<py::dict>(params)) return recordOf(model, params.cast<py::dict>(), where);
  usage(where + ": params is a dict {name: value} or a string 'k=v;k=v' as in `raylab brdf eval`");
}

void checkBackend(const std::string& backend) {
  if (backend != "gpu" && backend != "cpu") usage("raylab.brdf: backend is gpu or cpu, not '" + backend + "'");
}

// f and pdf of every case, on the chosen backend.
std::vector<BrdfResult> evaluate(const std::string& model, const py::object& params, const FloatArray& wi,
                                 const FloatArray& wo, const FloatArray& n, const FloatArray& t,
                                 const std::string& backend, std::optional<std::uint32_t> device) {
  checkBackend(backend);
  const gpu::MaterialRecord record = material(model, params);
  std::optional<std::size_t> rows;
  const std::vector<glm::vec3> wis = vectors(wi, "wi", rows), wos = vectors(wo, "wo", rows);
  const std::vector<glm::vec3> ns = vectors(n, "n", rows), ts = vectors(t, "t", rows);
  const std::size_t count = rows.value_or(1);
  std::vector<gpu::BrdfEvalCase> cases(count);
  for (std::size_t i = 0; i < count; ++i) {
    cases[i] = {record, pick(wis, i), pick(wos, i), pick(ns, i), pick(ts, i)};
    if (glm::dot(cases[i].n, cases[i].n) == 0.0f) usage("raylab.brdf: n[" + std::to_string(i) + "] is zero");
  }
  std::vector<BrdfResult> results(count);
  if (count == 0) return results;  // nothing to dispatch: an empty batch is a valid one
  if (backend == "cpu") {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < count; ++i) results[i] = evaluateBrdfCaseOnCpu(cases[i]);
    return results;
  }
  const std::shared_ptr<DeviceContext> context = deviceContext(device);
  py::gil_scoped_release release;
  const std::lock_guard<std::mutex> lock(context->queue);
  BrdfEvaluator& evaluator = context->evaluatorFor(std::uint32_t(count));
  const std::vector<gpu::BrdfEvalValue> values = evaluateBrdfCases(context->session.device, evaluator, cases);
  for (std::size_t i = 0; i < count; ++i) results[i] = fromDevice(values[i]);
  return results;
}

DoubleArray rgbArray(const std::vector<BrdfResult>& results) {
  DoubleArray out({results.size(), std::size_t(3)});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < results.size(); ++i) {
    for (int c = 0; c < 3; ++c) data[3 * i + c] = results[i].f[c];
  }
  return out;
}

py::dict models() {
  py::dict all;
  for (const ModelInfo& model : allModels()) {
    py::list params;
    std::vector<ParamInfo> list = model.params;
    list.push_back(deltaParam());
    for (const ParamInfo& param : list) {
      py::dict p;
      p["name"] = std::string(param.name);
      p["rgb"] = param.rgb;
      p["min"] = param.min;
      p["max"] = param.max;
      p["default"] = param.defaultValue;
      p["log_scale"] = param.logScale;
      p["meaning"] = std::string(param.meaning);
      p["role"] = std::string(param.role);
      params.append(p);
    }
    all[py::str(std::string(model.name))] = params;
  }
  return all;
}

}  // namespace

void bindBrdf(py::module_& parent) {
  py::module_ m = parent.def_submodule(
      "brdf", "The BRDF library over numpy arrays: on the device (backend='gpu', the shaders' own code) or the "
              "double-precision reference (backend='cpu'). Models and parameters are those of docs/brdfs.md; "
              "params is a dict {name: value} (RGB as (r, g, b)) or `raylab brdf eval`'s 'k=v;k=v'.");
  m.def("models", &models, "Every model with its parameters: name, rgb, min, max, default, log_scale, meaning, role (what the parameter "
        "means across models: diffuse, specular, slope_x, transmittance, ...; empty for none).");
  m.def(
      "eval",
      [](const std::string& model, const py::object& params, const FloatArray& wi, const FloatArray& wo,
         const FloatArray& n, const FloatArray& t, const std::string& backend, std::optional<std::uint32_t> device) {
        return rgbArray(evaluate(model, params, wi, wo, n, t, backend, device));
      },
      py::arg("model"), py::arg("params") = py::none(), py::kw_only(), py::arg("wi"), py::arg("wo"),
      py::arg("n") = std::vector<float>{0.0f, 0.0f, 1.0f}, py::arg("t") = std::vector<float>{1.0f, 0.0f, 0.0f},
      py::arg("backend") = kDefaultBrdfBackend, py::arg("device") = py::none(),
      "f(wi, wo), RGB, shape (N, 3), for directions wi, wo (N, 3) pointing away from the surface, in the frame of "
      "the normal n and tangent hint t (each (3,) or (N, 3)); the values of `raylab brdf eval` on the same rows. "
      "0 below the horizon and for glass (a delta BSDF).");
  m.def(
      "pdf",
      [](const std::string& model, const py::object& params, const FloatArray& wi, const FloatArray& wo,
         const FloatArray& n, const FloatArray& t, const std::string& backend, std::optional<std::uint32_t> device) {
        const std::vector<BrdfResult> results = evaluate(model, params, wi, wo, n, t, backend, device);
        DoubleArray out(std::vector<py::ssize_t>{py::ssize_t(results.size())});
        for (std::size_t i = 0; i < results.size(); ++i) out.mutable_data()[i] = results[i].pdf;
        return out;
      },
      py::arg("model"), py::arg("params") = py::none(), py::kw_only(), py::arg("wi"), py::arg("wo"),
      py::arg("n") = std::vector<float>{0.0f, 0.0f, 1.0f}, py::arg("t") = std::vector<float>{1.0f, 0.0f, 0.0f},
      py::arg("backend") = kDefaultBrdfBackend, py::arg("device") = py::none(),
      "The density per unit solid angle with which sample() draws wi given wo, shape (N,).");
  m.def(
      "sample",
      [](const std::string& model, const py::object& params, const FloatArray& wo, const FloatArray& u,
         const std::string& backend, std::optional<std::uint32_t> device) {
        checkBackend(backend);
        const gpu::MaterialRecord record = material(model, params);
        std::optional<std::size_t> rows;
        const std::vector<glm::vec3> uniforms = vectors(u, "u", rows);
        std::vector<glm::vec3> wos = vectors(wo, "wo", rows);
        const std::size_t count = rows.value_or(1);
        for (const glm::vec3& v : uniforms) {
          if (glm::any(glm::lessThan(v, glm::vec3(0.0f))) || glm::any(glm::greaterThanEqual(v, glm::vec3(1.0f)))) {
            usage("raylab.brdf.sample: every u must lie in [0, 1)^3");
          }
        }
        for (std::size_t i = 0; i < wos.size(); ++i) {
          if (!(glm::length(wos[i]) > 0.0f)) usage("raylab.brdf.sample: wo[" + std::to_string(i) + "] is zero");
          wos[i] = glm::normalize(wos[i]);
        }
        DoubleArray wi({count, std::size_t(3)}), f({count, std::size_t(3)});
        DoubleArray pdf(std::vector<py::ssize_t>{py::ssize_t(count)});
        if (count == 0) {
          // nothing to draw
        } else if (backend == "cpu") {
          const reference::Material reference = reference::fromRecord(record);
          for (std::size_t i = 0; i < count; ++i) {
            const glm::dvec3 w = glm::dvec3(pick(wos, i));
            const reference::Sample s = reference::sample(reference, w, glm::dvec3(pick(uniforms, i)));
            for (int c = 0; c < 3; ++c) {
              wi.mutable_data()[3 * i + c] = s.wi[c];
              f.mutable_data()[3 * i + c] = s.f[c];
            }
            pdf.mutable_data()[i] = s.pdf;
          }
        } else {
          const std::shared_ptr<DeviceContext> context = deviceContext(device);
          // The device kernel draws for one wo per dispatch: one dispatch per run of equal wo (a single wo, the
          // common case, is one dispatch).
          std::vector<gpu::BrdfSampleValue> draws(count);
          {
            py::gil_scoped_release release;
            const std::lock_guard<std::mutex> lock(context->queue);
            BrdfSampler& sampler = context->samplerFor(std::uint32_t(count));
            std::vector<glm::vec3> run;
            for (std::size_t begin = 0; begin < count;) {
              std::size_t end = begin + 1;
              while (end < count && pick(wos, end) == pick(wos, begin)) ++end;
              run.resize(end - begin);
              for (std::size_t i = begin; i < end; ++i) run[i - begin] = pick(uniforms, i);
              const std::vector<gpu::BrdfSampleValue> part =
                  drawBrdfSamples(context->session.device, sampler, record, pick(wos, begin), run);
              std::copy(part.begin(), part.end(), draws.begin() + std::ptrdiff_t(begin));
              begin = end;
            }
          }
          for (std::size_t i = 0; i < count; ++i) {
            for (int c = 0; c < 3; ++c) {
              wi.mutable_data()[3 * i + c] = draws[i].wi[c];
              f.mutable_data()[3 * i + c] = draws[i].f[c];
            }
            pdf.mutable_data()[i] = draws[i].pdf;
          }
        }
        py::dict out;
        out["wi"] = wi;
        out["f"] = f;
        out["pdf"] = pdf;
        return out;
      },
      py::arg("model"), py::arg("params") = py::none(), py::kw_only(), py::arg("wo"), py::arg("u"),
      py::arg("backend") = kDefaultBrdfBackend, py::arg("device") = py::none(),
      "Importance samples wi given wo, one direction (3,) or one per row (N, 3), in the local frame (z the normal), "
      "for each row of u (N, 3) in [0, 1)^3: a dict of wi (N, 3), f (N, 3) = f(wi, wo) and pdf (N,); pdf 0 for a "
      "failed sample. N may be 0.");
  m.def(
      "tabulate",
      [](const std::string& model, const py::object& params, const py::object& pathObject) {
        const std::string path = pathArgument(pathObject, "raylab.brdf.tabulate: path");
        if (!path.ends_with(".binary")) usage("raylab.brdf.tabulate: path must end in .binary (a MERL file): " + path);
        const gpu::MaterialRecord record = material(model, params);
        if (isDeltaOnly(record.model)) usage("raylab.brdf.tabulate: " + model + " is a delta BSDF and has no f");
        try {
          checkFileParams(record, "raylab.brdf.tabulate: " + model);
          checkOutputPath(path, "path");
        } catch (const FileError&) {
          throw;
        } catch (const Error& error) {
          usage(error.what());
        }
        py::gil_scoped_release release;
        const reference::Material m = reference::fromRecord(record);
        writeMerl(path, tabulateMerl([&](const glm::dvec3& wi, const glm::dvec3& wo) { return reference::eval(m, wi, wo); }));
      },
      py::arg("model"), py::arg("params"), py::arg("path"),
      "Writes a MERL .binary file of the material: f at the centre of each of the database's 90 x 90 x 180 bins, as "
      "`raylab brdf tabulate` does (docs/fitting.md).");
  // pybind11 keeps the pointer: the text lives as long as the module.
  static const std::string fitDoc =
      "Fits the analytic models (all, or `models`) to target: a MERL .binary file, a MERL phi_d = 90 .slice, a "
      ".csv of samples (optional weight column), or 'MODEL[:k=v,...]'. Returns the ranking of `raylab brdf fit "
      "--json`: a list of dicts with model, params (name -> value, RGB as a list), param_list (as --material takes "
      "it), error, relative_error, seconds, iterations, starts, failed_starts, warnings, metric, isotropic and "
      "target, best first (docs/fitting.md). metric is 'cosine' (Ngan et al. 2005) or 'log'; search points of the "
      "nonlinear parameters pick the `starts` Levenberg-Marquardt starts (None: each model's own, " +
          describeStarts(FitOptions{}) + "); isotropic ties x and y parameters (None: "
      "as the target says, True for MERL files and slices).";
  m.def(
      "fit",
      [](const py::object& targetObject, const std::optional<std::vector<std::string>>& models,
         const std::string& metric, std::optional<std::int64_t> starts, std::int64_t search, std::int64_t seed, std::int64_t threads,
         std::optional<bool> isotropic) {
        // Signed, and checked here: an unsigned argument turns starts=-1 into pybind11's list of overloads.
        const std::string target = pathArgument(targetObject, "raylab.brdf.fit: target");
        if (starts && (*starts < 1 || *starts > 64)) {
          usage("raylab.brdf.fit: starts must be within 1..64 or None, not " + std::to_string(*starts));
        }
        if (search < 0 || search > 65536) usage("raylab.brdf.fit: search must be within 0..65536, not " + std::to_string(search));
        if (seed < 0 || seed > std::int64_t(UINT32_MAX)) usage("raylab.brdf.fit: seed must be within 0..4294967295");
        if (threads < 0 || threads > 256) usage("raylab.brdf.fit: threads must be within 0..256 (0: one per core)");
        FitOptions options;
        options.starts = starts ? int(*starts) : 0;
        options.searchPoints = int(search);
        options.seed = unsigned(seed);
        options.threads = int(threads);
        options.isotropic = isotropic;
        std::vector<FitResult> fits;
        bool targetIsotropic = false;
        try {
          options.metric = parseFitMetric(metric, "raylab.brdf.fit");
          if (models) options.models = *models;
          py::gil_scoped_release release;
          const FitTarget loaded = loadFitTarget(target);
          targetIsotropic = loaded.isotropic;
          fits = fitModels(loaded, options);
        } catch (const FileError&) {
          throw;
        } catch (const Error& error) {
          usage(error.what());
        }
        py::list table;
        for (const FitResult& f : fits) {
          py::dict params;
          for (const auto& [name, values] : fitParams(f)) {
            params[py::str(name)] = values.size() == 1 ? py::object(py::float_(values[0])) : py::object(py::cast(values));
          }
          py::dict row;
          row["model"] = f.model;
          row["params"] = params;
          row["param_list"] = fitParamList(f);
          row["error"] = f.error;
          row["relative_error"] = f.relativeError;
          row["seconds"] = f.seconds;
          row["iterations"] = f.iterations;
          row["starts"] = f.starts;
          row["failed_starts"] = f.failedStarts;
          row["warnings"] = f.warnings;
          row["metric"] = std::string(fitMetricName(options.metric));
          row["isotropic"] = options.isotropic.value_or(targetIsotropic);
          row["target"] = target;
          table.append(row);
        }
        return table;
      },
      py::arg("target"), py::kw_only(), py::arg("models") = py::none(), py::arg("metric") = "cosine",
      py::arg("starts") = py::none(), py::arg("search") = 256, py::arg("seed") = 1, py::arg("threads") = 0,
      py::arg("isotropic") = py::none(),
      fitDoc.c_str());
  m.def("fittable_models", &fittableModels, py::kw_only(), py::arg("by_name") = false,
        "The models `fit` fits by default: every model of the library with a density that is not read from a file; "
        "with by_name=True also those it fits only when named (openpbr: its fit costs several of the others').");
  m.def(
      "fit_error",
      [](const py::object& targetObject, const std::string& model, const py::object& params,
         const std::string& metric) {
        const std::string target = pathArgument(targetObject, "raylab.brdf.fit_error: target");
        const gpu::MaterialRecord record = material(model, params);
        double relative = 0.0, error = 0.0;
        try {
          const FitMetric m = parseFitMetric(metric, "raylab.brdf.fit_error");
          py::gil_scoped_release release;
          error = fitError(loadFitTarget(target), record, m, &relative);
        } catch (const FileError&) {
          throw;
        } catch (const Error& e) {
          usage(e.what());
        }
        return py::make_tuple(error, relative);
      },
      py::arg("target"), py::arg("model"), py::arg("params") = py::none(), py::kw_only(), py::arg("metric") = "cosine",
      "The error of one material against a fit target, as `fit` reports it: (error, relative_error).");
  m.def(
      "albedo",
      [](const std::string& model, const py::object& params, const DoubleArray& theta, double phi,
         const std::string& backend, std::uint32_t samples, std::uint32_t seed, double tolerance,
         std::optional<std::uint32_t> device) {
        checkBackend(backend);
        const gpu::MaterialRecord record = material(model, params);
        if (isDeltaOnly(record.model)) {
          usage("raylab.brdf.albedo: " + std::string(modelInfo(record.model).name) +
                " is a delta BSDF and has no albedo integral");
        }
        if (!(tolerance >= 1e-12 && tolerance <= 1e-2)) usage("raylab.brdf.albedo: tolerance must be within [1e-12, 0.01]");
        if (samples < 1 || samples > (1u << 22)) usage("raylab.brdf.albedo: samples must be within 1..4194304");
        const std::size_t count = std::size_t(theta.size());
        std::vector<AlbedoEstimate> estimates(count);
        for (std::size_t i = 0; i < count; ++i) {
          const double angle = theta.data()[i];
          if (!(angle >= 0.0 && angle < 90.0)) usage("raylab.brdf.albedo: every theta must lie in [0, 90) degrees");
        }
        if (backend == "cpu") {
          py::gil_scoped_release release;
          for (std::size_t i = 0; i < count; ++i) estimates[i] = albedoByCubature(record, theta.data()[i], phi, tolerance);
        } else {
          const std::shared_ptr<DeviceContext> context = deviceContext(device);
          py::gil_scoped_release release;
          const std::lock_guard<std::mutex> lock(context->queue);
          BrdfSampler& sampler = context->samplerFor(samples);
          for (std::size_t i = 0; i < count; ++i) {
            // The seeds of `raylab brdf albedo --backend gpu --seed S`: angle i uses S * 1000 + i.
            estimates[i] = albedoBySampling(context->session.device, sampler, record, theta.data()[i], phi, samples,
                                            std::uint64_t(seed) * 1000 + i);
          }
        }
        DoubleArray value({count, std::size_t(3)});
        DoubleArray error(std::vector<py::ssize_t>{py::ssize_t(count)});
        for (std::size_t i = 0; i < count; ++i) {
          for (int c = 0; c < 3; ++c) value.mutable_data()[3 * i + c] = estimates[i].value[c];
          error.mutable_data()[i] = estimates[i].error;
        }
        py::dict out;
        out["albedo"] = value;
        out["error"] = error;
        return out;
      },
      py::arg("model"), py::arg("params") = py::none(), py::kw_only(), py::arg("theta_deg"), py::arg("phi_deg") = 0.0,
      py::arg("backend") = kDefaultBrdfBackend, py::arg("samples") = 1u << 18, py::arg("seed") = 1u, py::arg("tolerance") = 1e-6,
      py::arg("device") = py::none(),
      "Directional albedo a(wo) = integral of f cos_i dwi at the outgoing angles theta_deg (N,) (azimuth phi_deg), as "
      "`raylab brdf albedo`: the reference's adaptive cubature (cpu, to `tolerance`) or the mean of f cos / pdf over "
      "`samples` draws of the device's sampler (gpu). A dict of albedo (N, 3) and error (N,).");
}

}  // namespace raylab::python
