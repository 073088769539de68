// raylab.devices() and raylab.Scene: loading a glTF scene (or the built-in one), and its materials, lights, camera
// and environment read and edited by name, with the ranges and messages of the glTF loader and the viewer's script.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <filesystem>
#include <cmath>
#include <string>
#include <vector>

#include "bindings.h"
#include "brdf_params/material_params.h"
#include "errors.h"
#include "scene/camera_frame.h"
#include "scene/camera_pivot.h"
#include "scene/environment.h"
#include "builtin_scenes/load_scene.h"
#include "scene/radiance_limits.h"
#include "shared/scene_records.h"
#include "util/error.h"
#include "util/files.h"
#include "view_logic/scene_edits.h"
#include "vk/device.h"

namespace py = pybind11;

namespace raylab::python {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

[[noreturn]] void usage(const std::string& message) { throw Error(message, kExitUsage); }

std::string quotedNames(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "'" : ", '") + name + "'";
  return text;
}

template <class T>
std::vector<std::string> namesOf(const std::vector<T>& items) {
  std::vector<std::string> names;
  for (const T& item : items) names.push_back(item.name);
  return names;
}

Material& materialNamed(Scene& scene, const std::string& name) {
  Material* material = findMaterial(scene, name);
  if (material == nullptr) {
    usage("the scene has no material '" + name + "' (materials: " + quotedNames(namesOf(scene.materials)) + ")");
  }
  return *material;
}

Light& lightNamed(Scene& scene, const std::string& name) {
  Light* light = findLight(scene, name);
  if (light == nullptr) {
    usage("the scene has no light '" + name + "' (lights: " + quotedNames(namesOf(scene.lights)) + ")");
  }
  return *light;
}

py::tuple tupleOf(glm::vec3 v) { return py::make_tuple(v.x, v.y, v.z); }

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

py::dict lightDict(const Light& light) {
  const PunctualLight& r = light.record;
  py::dict d;
  d["name"] = light.name;
  d["type"] = lightTypeName(r.type);
  d["intensity"] = tupleOf(r.intensity);
  if (r.type != gpu::kLightDirectional) d["position"] = tupleOf(r.position);
  if (r.type == gpu::kLightSpot || r.type == gpu::kLightDirectional) d["direction"] = tupleOf(r.direction);
  if (r.type == gpu::kLightSpot) {
    d["cone_deg"] = py::make_tuple(std::acos(double(r.cosInner)) / kDegree, std::acos(double(r.cosOuter)) / kDegree);
  }
  return d;
}

// Python passes vectors as any 3-sequence (pybind11 has no caster for glm::vec3).
using Vec3 = std::array<float, 3>;
std::optional<glm::vec3> vec(const std::optional<Vec3>& v) {
  if (!v) return std::nullopt;
  return glm::vec3((*v)[0], (*v)[1], (*v)[2]);
}

void setLight(Scene& scene, const std::string& name, const std::optional<Vec3>& intensityIn,
              const std::optional<Vec3>& positionIn, const std::optional<Vec3>& directionIn,
              const std::optional<std::pair<float, float>>& cone) {
  const std::optional<glm::vec3> intensity = vec(intensityIn), position = vec(positionIn), direction = vec(directionIn);
  Light& light = lightNamed(scene, name);
  PunctualLight record = light.record;
  const std::string where = "light '" + name + "'";
  if (intensity) {
    try {
      checkLightIntensity(*intensity, where);
    } catch (const Error& error) {
      usage(error.what());
    }
    record.intensity = *intensity;
  }
  if (position) {
    if (record.type == gpu::kLightDirectional) usage(where + " is a directional light, which has no position");
    if (!finite(*position)) usage(where + ": the position must be finite");
    record.position = *position;
  }
  if (direction) {
    if (record.type != gpu::kLightSpot && record.type != gpu::kLightDirectional) {
      usage(where + " is a " + lightTypeName(record.type) + " light, which has no direction");
    }
    if (!finite(*direction) || !(glm::length(*direction) > 0.0f)) {
      usage(where + ": the direction must be a finite, non-zero vector");
    }
    record.direction = glm::normalize(*direction);
  }
  if (cone) {
    if (record.type != gpu::kLightSpot) usage(where + " is not a spot light");
    if (!(cone->first >= 0.0f && cone->first < cone->second && cone->second <= 90.0f)) {
      usage(where + ": cone angles must satisfy 0 <= inner < outer <= 90 degrees");
    }
    record.cosInner = float(std::cos(cone->first * kDegree));
    record.cosOuter = float(std::cos(cone->second * kDegree));
  }
  light.record = record;
}

void setCamera(Scene& scene, const std::optional<Vec3>& positionIn, const std::optional<Vec3>& targetIn,
               const std::optional<Vec3>& upIn, const std::optional<float>& fovDegrees) {
  const std::optional<glm::vec3> position = vec(positionIn), target = vec(targetIn), up = vec(upIn);
  Camera camera = scene.camera;
  if (position) camera.position = *position;
  if (target) camera.target = *target;
  if (up) camera.up = *up;
  if (fovDegrees) {
    const float radians = float(*fovDegrees * kDegree);
    if (!(radians >= kMinYfov && radians < kMaxYfov)) {
      usage("the camera's field of view must be within [" + std::to_string(kMinYfov / kDegree) + ", " +
            std::to_string(kMaxYfov / kDegree) + ") degrees, as a glTF camera's");
    }
    camera.yfov = float(*fovDegrees * kDegree);
  }
  if (!finite(camera.position) || !finite(camera.target) || !finite(camera.up)) usage("the camera must be finite");
  gpu::FrameParams probe{};
  try {
    applyCamera(probe, camera, 16, 16);
  } catch (const Error& error) {
    usage(std::string("this camera leaves no usable view: ") + error.what());
  }
  scene.camera = camera;
}

}  // namespace

py::dict materialDict(const Material& material) {
  const ModelInfo& model = modelInfo(material.record.model);
  py::dict d;
  d["model"] = std::string(model.name);
  for (const ParamInfo& param : model.params) {
    const glm::vec3 value = getParam(material.record, param.name);
    if (isFileParam(param)) d[py::str(std::string(param.name))] = fileParamPath(material.record, param);
    else if (param.rgb) d[py::str(std::string(param.name))] = tupleOf(value);
    else d[py::str(std::string(param.name))] = value.x;
  }
  d["delta"] = material.record.delta;
  return d;
}

// A number is anything Python can take as one (int, float, NumPy scalars, 0-d arrays); three numbers any sequence
// or array of three. bool is neither.
glm::vec3 paramValue(const py::handle& value, const std::string& where) {
  if (py::isinstance<py::bool_>(value)) usage(where + ": expected a number or three numbers (r, g, b), not a bool");
  const bool number = py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value) ||
                      (py::hasattr(value, "__float__") && !py::isinstance<py::sequence>(value) &&
                       (!py::isinstance<py::array>(value) || py::reinterpret_borrow<py::array>(value).ndim() == 0));
  if (number) {
    try {
      return glm::vec3(py::float_(py::reinterpret_borrow<py::object>(value)).cast<float>());
    } catch (const py::error_already_set&) {
      usage(where + ": expected a number or three numbers (r, g, b)");
    }
  }
  try {
    const std::vector<float> channels = value.cast<std::vector<float>>();
    if (channels.size() == 3) return {channels[0], channels[1], channels[2]};
  } catch (const py::cast_error&) {
  }
  usage(where + ": expected a number or three numbers (r, g, b)");
}

void applyParams(gpu::MaterialRecord& record, const py::dict& params, const std::string& where) {
  const ModelInfo& model = modelInfo(record.model);
  // Presets first (metal="Au"), so that the other keywords refine them.
  for (const auto& [key, value] : params) {
    const std::string name = key.cast<std::string>();
    if (!isPresetKey(model, name)) continue;
    if (!py::isinstance<py::str>(value)) usage(where + ": " + name + ": expected a name");
    try {
      applyPreset(record, name, value.cast<std::string>(), where);
    } catch (const Error& error) {
      usage(error.what());
    }
  }
  for (const auto& [key, value] : params) {
    const std::string name = key.cast<std::string>();
    if (name == "model" || isPresetKey(model, name)) continue;
    if (const ParamInfo* param = findParam(model, name); param != nullptr && isFileParam(*param)) {
      // A path (str or os.PathLike), relative to the current directory.
      if (!py::isinstance<py::str>(value) && !py::hasattr(value, "__fspath__")) {
        usage(where + ": " + name + ": expected a path (str or os.PathLike)");
      }
      const std::string path = py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>();
      try {
        py::gil_scoped_release release;  // a file takes a fraction of a second to read and check
        setFileParam(record, name, path, where);
      } catch (const FileError& error) {
        throw;
      } catch (const Error& error) {
        usage(error.what());
      }
      continue;
    }
    const glm::vec3 v = paramValue(value, where + ": " + name);
    if (!finite(v)) usage(where + ": " + name + " must be finite");
    try {
      setParam(record, name, v, where);
    } catch (const Error& error) {
      usage(error.what());
    }
  }
}

gpu::MaterialRecord recordOf(const std::string& modelName, const py::dict& params, const std::string& where) {
  const ModelInfo* model = findModel(modelName);
  if (model == nullptr) {
    usage(where + ": '" + modelName + "' is not a BRDF model (models: " + modelNames() + ")");
  }
  gpu::MaterialRecord record = defaultRecord(model->id);
  applyParams(record, params, where);
  return record;
}

void bindScene(py::module_& m) {
  m.def(
      "devices",
      [] {
        Instance instance = createInstance({});
        std::vector<DeviceReport> reports;
        try {
          reports = surveyDevices(instance);
        } catch (...) {
          destroyInstance(instance);
          throw;
        }
        destroyInstance(instance);
        py::list list;
        for (const DeviceReport& report : reports) {
          py::dict d;
          d["index"] = report.index;
          d["name"] = report.name;
          d["driver"] = report.driver;
          d["type"] = deviceTypeName(report.type);
          d["ray_queries"] = report.rayQueries;
          d["ray_tracing_pipelines"] = report.rayTracingPipelines;
          py::list backends;
          if (report.queryBackend()) backends.append("query");
          if (report.pipelineBackend()) backends.append("pipeline");
          d["backends"] = backends;
          d["missing"] = report.missing;
          list.append(d);
        }
        return list;
      },
      "The Vulkan devices, as `raylab devices` lists them: a dict per device (index, name, driver, type, "
      "ray_queries, ray_tracing_pipelines, the backends raylab runs on it, and what it is missing).");

  py::class_<Scene>(m, "Scene",
                    "A scene: meshes, spheres, materials, lights, a camera and an environment. Load one with "
                    "Scene.load(path) or take the built-in showcase with Scene.default(); edit its materials, lights "
                    "and camera by name, then render it with raylab.Renderer.")
      .def_static(
          "load",
          [](const std::filesystem::path& pathIn, const std::string& camera, const std::optional<std::filesystem::path>& envIn,
             std::optional<float> envStrength, std::optional<float> envRotationDegrees, bool allowOutsideUris) {
            const std::string path = pathIn.string(), env = envIn ? envIn->string() : "";
            requireFile(path, "raylab.Scene.load");
            if (envIn) {
              if (env.empty()) usage("raylab.Scene.load: env is an empty path (leave it out for the scene's own)");
              requireFile(env, "raylab.Scene.load: env");
            }
            SceneRequest request{path, camera, allowOutsideUris, env, envStrength, envRotationDegrees};
            try {
              return loadScene(request);
            } catch (const FileError&) {
              throw;
            } catch (const Error& error) {
              // A malformed file is bad input, as on the command line.
              throw Error(error.what(), error.exitCode() == kExitNoDevice ? kExitNoDevice : kExitUsage);
            }
          },
          py::arg("path"), py::kw_only(), py::arg("camera") = "", py::arg("env") = py::none(),
          py::arg("env_strength") = py::none(), py::arg("env_rotation_deg") = py::none(),
          py::arg("allow_outside_uris") = false,
          "Loads a glTF 2.0 file (.gltf or .glb), as `raylab render PATH --camera ... --env ...` does. "
          "FileNotFoundError for a missing file, ValueError (with the loader's message) for a malformed one.")
      .def_static("default", [] { return loadScene({}); }, "The built-in showcase scene, as `raylab render` without SCENE.")
      .def_readonly("name", &Scene::name)
      .def_property_readonly("materials", [](const Scene& s) { return namesOf(s.materials); },
                             "The materials' names, in order.")
      .def_property_readonly("lights", [](const Scene& s) { return namesOf(s.lights); }, "The lights' names.")
      .def_property_readonly("cameras", [](const Scene& s) { return s.cameraNames; }, "The file's cameras.")
      .def(
          "material", [](Scene& s, const std::string& name) { return materialDict(materialNamed(s, name)); },
          py::arg("name"), "A material's model and parameters as a dict (RGB parameters as (r, g, b)).")
      .def(
          "set_material",
          [](Scene& s, const std::string& name, const std::string& model, const py::kwargs& params) {
            Material& material = materialNamed(s, name);
            gpu::MaterialRecord record = material.record;
            if (!model.empty()) {
              const ModelInfo* info = findModel(model);
              if (info == nullptr) recordOf(model, {}, "material '" + name + "'");  // throws, listing the models
              switchModel(record, info->id);
            }
            applyParams(record, params, "material '" + name + "'");
            try {
              checkFileParams(record, "material '" + name + "'");
            } catch (const Error& error) {
              usage(error.what());
            }
            material.record = record;  // only when every value was valid
          },
          py::arg("name"), py::arg("model") = "",
          "Sets a material's model (keeping the parameters in range for it) and parameters by name, e.g. "
          "set_material('red plastic', model='ward', alpha_x=0.2, rho_d=(0.5, 0.1, 0.1)). Values outside the "
          "contract's ranges raise ValueError naming the range; nothing changes then.")
      .def(
          "light", [](Scene& s, const std::string& name) { return lightDict(lightNamed(s, name)); }, py::arg("name"),
          "A light as a dict: type, intensity, position, direction, cone_deg (inner, outer).")
      .def("set_light", &setLight, py::arg("name"), py::kw_only(), py::arg("intensity") = py::none(),
           py::arg("position") = py::none(), py::arg("direction") = py::none(), py::arg("cone_deg") = py::none(),
           "Edits a light, with the checks of the viewer's script: intensity finite and >= 0, a non-zero direction, "
           "0 <= inner < outer <= 90 degrees.")
      .def_property_readonly(
          "camera",
          [](const Scene& s) {
            py::dict d;
            d["name"] = s.camera.name;
            d["position"] = tupleOf(s.camera.position);
            d["target"] = tupleOf(s.camera.target);
            d["up"] = tupleOf(s.camera.up);
            d["fov_deg"] = s.camera.yfov / kDegree;
            return d;
          },
          "The camera: position, target, up and the vertical field of view in degrees.")
      .def("set_camera", &setCamera, py::kw_only(), py::arg("position") = py::none(), py::arg("target") = py::none(),
           py::arg("up") = py::none(), py::arg("fov_deg") = py::none(), "Moves the camera; a degenerate view raises.")
      .def_property_readonly(
          "bounds",
          [](const Scene& s) {
            const SceneBounds bounds = sceneBounds(s);
            return py::make_tuple(tupleOf(bounds.low), tupleOf(bounds.high));
          },
          "The axis-aligned box (low, high) around every triangle and sphere, in world space.")
      .def_property_readonly(
          "environment",
          [](const Scene& s) {
            py::dict d;
            d["path"] = s.environment.path;
            d["size"] = py::make_tuple(s.environment.width, s.environment.height);
            d["strength"] = s.environment.strength;
            d["rotation_deg"] = s.environment.rotation / kDegree;
            d["background"] = tupleOf(s.background);
            return d;
          },
          "The environment image (path and size, empty without one), its strength and rotation, and the "
          "uniform background radiance.")
      .def(
          "set_environment",
          [](Scene& s, const std::optional<std::filesystem::path>& path, std::optional<float> strength,
             std::optional<float> rotationDegrees) {
            const std::string where = "raylab.Scene.set_environment";
            if (rotationDegrees && !(std::abs(*rotationDegrees) <= kMaxEnvironmentRotationDegrees)) {
              usage(where + ": rotation_deg must be within [-360, 360]");
            }
            // Everything is checked before anything changes: a refused call leaves the scene as it was.
            Environment environment = s.environment;
            const float newStrength = strength.value_or(path ? 1.0f : environment.strength);
            if (path) {
              if (path->empty()) usage(where + ": the path is empty");
              requireFile(path->string(), where);
              try {
                environment = loadEnvironment(path->string(), newStrength, where);
              } catch (const FileError&) {
                throw;
              } catch (const Error& error) {
                usage(error.what());
              }
              environment.rotation = 0.0f;
            } else if (!environment.hasImage() && (strength || rotationDegrees)) {
              usage(where + ": the scene has no environment image (give one: set_environment(path))");
            }
            try {
              checkEnvironmentStrength(environment, newStrength, where);
            } catch (const Error& error) {
              usage(error.what());
            }
            environment.strength = newStrength;
            if (rotationDegrees) environment.rotation = float(*rotationDegrees * kDegree);
            s.environment = std::move(environment);
          },
          py::arg("path") = py::none(), py::kw_only(), py::arg("strength") = py::none(),
          py::arg("rotation_deg") = py::none(),
          "Lights the scene with an equirectangular OpenEXR image (+Y up) as `--env` does, and/or sets its strength "
          "and rotation about +Y in degrees (as --env-strength and --env-rotation). A new image starts at strength 1 "
          "and rotation 0 unless given.")
      .def("__repr__", [](const Scene& s) {
        return "<raylab.Scene '" + s.name + "': " + std::to_string(s.materials.size()) + " materials, " +
               std::to_string(s.lights.size()) + " lights, " + std::to_string(s.spheres.size()) + " spheres, " +
               std::to_string(s.instances.size()) + " mesh instances>";
      });
}

}  // namespace raylab::python
