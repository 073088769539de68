#include "gltf_write/sweep_gltf.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <glm/gtc/quaternion.hpp>

#include "brdf_params/material_params.h"
#include "scene/shapes.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"

namespace raylab {

namespace {

using tinygltf::Value;

constexpr int kArrayBuffer = 34962;         // GL_ARRAY_BUFFER
constexpr int kElementArrayBuffer = 34963;  // GL_ELEMENT_ARRAY_BUFFER

// Six significant digits: float values print as "0.1", not "0.10000000149011612", and stay exact enough.
double tidy(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return std::strtod(text, nullptr);
}

Value numbers(std::initializer_list<float> values) {
  Value::Array array;
  for (float v : values) array.emplace_back(tidy(v));
  return Value(std::move(array));
}

Value vec3Value(glm::vec3 v) { return numbers({v.x, v.y, v.z}); }

std::vector<double> doubles(glm::vec3 v) { return {tidy(v.x), tidy(v.y), tidy(v.z)}; }

class ModelBuilder {
 public:
  tinygltf::Model model;

  ModelBuilder() {
    model.asset.version = "2.0";
    model.asset.generator = "raylab sweep";
    model.buffers.emplace_back();
  }

  int positions(const std::vector<glm::vec3>& points) {
    std::vector<float> flat;
    glm::vec3 lo(points.front()), hi(points.front());
    for (const glm::vec3& p : points) {
      flat.insert(flat.end(), {p.x, p.y, p.z});
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    tinygltf::Accessor accessor;
    accessor.bufferView = view(flat.data(), flat.size() * sizeof(float), kArrayBuffer);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.count = points.size();
    accessor.type = TINYGLTF_TYPE_VEC3;
    accessor.minValues = doubles(lo);  // POSITION requires bounds
    accessor.maxValues = doubles(hi);
    return add(std::move(accessor));
  }

  int indices(const std::vector<std::uint32_t>& values, std::uint32_t vertexCount) {
    tinygltf::Accessor accessor;
    if (vertexCount <= 65536) {
      std::vector<std::uint16_t> shorts(values.begin(), values.end());
      accessor.bufferView = view(shorts.data(), shorts.size() * 2, kElementArrayBuffer);
      accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    } else {
      accessor.bufferView = view(values.data(), values.size() * 4, kElementArrayBuffer);
      accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    }
    accessor.count = values.size();
    accessor.type = TINYGLTF_TYPE_SCALAR;
    return add(std::move(accessor));
  }

  int mesh(const std::string& name, int positionAccessor, int normalAccessor, int indexAccessor, int material) {
    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = positionAccessor;
    if (normalAccessor >= 0) primitive.attributes["NORMAL"] = normalAccessor;
    primitive.indices = indexAccessor;
    primitive.material = material;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(std::move(primitive));
    model.meshes.push_back(std::move(mesh));
    return int(model.meshes.size()) - 1;
  }

  int node(tinygltf::Node node) {
    model.nodes.push_back(std::move(node));
    return int(model.nodes.size()) - 1;
  }

 private:
  int view(const void* data, std::size_t bytes, int target) {
    std::vector<unsigned char>& buffer = model.buffers[0].data;
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);  // accessors of floats must be 4-byte aligned
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), begin, begin + bytes);
    model.bufferViews.push_back(view);
    return int(model.bufferViews.size()) - 1;
  }

  int add(tinygltf::Accessor accessor) {
    model.accessors.push_back(std::move(accessor));
    return int(model.accessors.size()) - 1;
  }
};

// extras.raylab of a material: its model and every parameter of that model, delta when it is set.
Value raylabMaterial(const gpu::MaterialRecord& record) {
  const ModelInfo& model = modelInfo(record.model);
  Value::Object raylab{{"model", Value(std::string(model.name))}};
  for (const ParamInfo& param : model.params) {
    const glm::vec3 value = getParam(record, param.name);
    raylab[std::string(param.name)] = param.rgb ? vec3Value(value) : Value(tidy(value.x));
  }
  if (record.delta != 0.0f) raylab["delta"] = Value(tidy(record.delta));
  return Value(Value::Object{{"raylab", Value(std::move(raylab))}});
}

tinygltf::Material material(const Material& source) {
  tinygltf::Material material;
  material.name = source.name;
  const glm::vec3 preview = previewColour(source.record);  // the colour other glTF viewers show
  material.pbrMetallicRoughness.baseColorFactor = {tidy(preview.r), tidy(preview.g), tidy(preview.b), 1.0};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.5;
  material.extras = raylabMaterial(source.record);
  return material;
}

// glTF's rotation [x, y, z, w] of a camera at `camera.position` looking at its target (down its -Z, +Y up).
std::vector<double> cameraRotation(const Camera& camera) {
  const glm::vec3 z = glm::normalize(camera.position - camera.target);
  const glm::vec3 x = glm::normalize(glm::cross(camera.up, z));
  const glm::vec3 y = glm::cross(z, x);
  const glm::quat q = glm::normalize(glm::quat_cast(glm::mat3(x, y, z)));
  return {tidy(q.x), tidy(q.y), tidy(q.z), tidy(q.w)};
}

Value sweepExtras(const SweepScene& sweep) {
  Value::Array values;
  for (float v : sweep.values) values.emplace_back(tidy(v));
  return Value(Value::Object{
      {"model", Value(sweep.spec.model)},
      {"parameter", Value(sweep.spec.param)},
      {"from", Value(tidy(sweep.spec.from))},
      {"to", Value(tidy(sweep.spec.to))},
      {"steps", Value(int(sweep.spec.steps))},
      {"log", Value(sweep.spec.logScale)},
      {"values", Value(std::move(values))},
      {"title", Value(sweepTitle(sweep))},
  });
}

}  // namespace

void writeSweepGltf(const SweepScene& sweep, const std::string& path) {
  const Scene& scene = sweep.scene;
  ModelBuilder b;
  tinygltf::Model& model = b.model;
  for (const Material& m : scene.materials) model.materials.push_back(material(m));

  tinygltf::Scene root;
  root.name = scene.name;
  // Meshes: the stage's checker halves share one grid of positions.
  int sharedPositions = -1;
  const std::vector<glm::vec3>* sharedSource = nullptr;
  for (const MeshInstance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes.at(instance.mesh);
    if (instance.transform != glm::mat4(1.0f)) throw Error(path + ": sweep meshes are placed in world space");
    if (sharedSource == nullptr || *sharedSource != mesh.positions) {
      sharedPositions = b.positions(mesh.positions);
      sharedSource = &mesh.positions;
    }
    const int indices = b.indices(mesh.indices, std::uint32_t(mesh.positions.size()));
    tinygltf::Node node;
    node.name = mesh.name;
    node.mesh = b.mesh(mesh.name, sharedPositions, -1, indices, int(instance.material));
    root.nodes.push_back(b.node(std::move(node)));
  }
  // Spheres: exact raylab spheres, each with a unit low-poly stand-in (positions double as normals).
  const Mesh standIn = makeUvSphere(glm::vec3(0.0f), 1.0f, 8, 12);
  const int standInPositions = b.positions(standIn.positions);
  const int standInIndices = b.indices(standIn.indices, std::uint32_t(standIn.positions.size()));
  for (const Sphere& sphere : scene.spheres) {
    const std::string& name = scene.materials.at(sphere.material).name;
    tinygltf::Node node;
    node.name = name;
    node.translation = doubles(sphere.center);
    node.scale = doubles(glm::vec3(sphere.radius));
    node.mesh = b.mesh(name + " stand-in", standInPositions, standInPositions, standInIndices, int(sphere.material));
    node.extras = Value(Value::Object{{"raylab", Value(Value::Object{{"sphere", Value(Value::Object{
                                                                            {"radius", Value(1.0)},
                                                                            {"material", Value(int(sphere.material))},
                                                                        })}})}});
    root.nodes.push_back(b.node(std::move(node)));
  }

  // The overview first: raylab renders a file's first camera unless --camera names another.
  for (const Camera& source : {scene.camera, sweep.rowCamera}) {
    tinygltf::Camera camera;
    camera.name = source.name;
    camera.type = "perspective";
    camera.perspective.yfov = tidy(source.yfov);
    camera.perspective.znear = 0.05;
    camera.perspective.zfar = 1000.0;
    model.cameras.push_back(camera);
    tinygltf::Node node;
    node.name = source.name + " node";
    node.camera = int(model.cameras.size()) - 1;
    node.translation = doubles(source.position);
    node.rotation = cameraRotation(source);
    root.nodes.push_back(b.node(std::move(node)));
  }

  for (const Light& source : scene.lights) {
    if (source.record.type != gpu::kLightPoint) throw Error(path + ": sweeps are lit by point lights only");
    const glm::vec3 intensity = source.record.intensity;
    const float peak = std::max({intensity.r, intensity.g, intensity.b});
    tinygltf::Light light;
    light.name = source.name;
    light.type = "point";
    light.intensity = tidy(peak);  // W/sr (docs/scenes.md)
    light.color = peak > 0.0f ? doubles(intensity / peak) : std::vector<double>{1.0, 1.0, 1.0};
    model.lights.push_back(light);
    tinygltf::Node node;
    node.name = source.name;
    node.translation = doubles(source.record.position);
    node.extensions["KHR_lights_punctual"] = Value(Value::Object{{"light", Value(int(model.lights.size()) - 1)}});
    root.nodes.push_back(b.node(std::move(node)));
  }

  root.extras = Value(Value::Object{
      {"raylab", Value(Value::Object{{"background", vec3Value(scene.background)}})},
      {"sweep", sweepExtras(sweep)},
  });
  model.scenes.push_back(std::move(root));
  model.defaultScene = 0;

  tinygltf::TinyGLTF writer;
  replaceFileAtomically(path, [&](const std::string& temporary) {
    if (!writer.WriteGltfSceneToFile(&model, temporary, /*embedImages=*/true, /*embedBuffers=*/true,
                                     /*prettyPrint=*/true, /*writeBinary=*/false)) {
      throw Error(path + ": cannot write glTF file");
    }
  });
}

}  // namespace raylab
