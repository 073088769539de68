// The glTF entry points and the walk over the default scene's node hierarchy: transforms, mesh instances,
// raylab spheres, cameras and lights, and the defaults for files without a camera or lights.
#include "gltf_read/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/camera_pivot.h"
#include "scene/tangents.h"
#include "gltf_read/gltf_document.h"
#include "gltf_read/gltf_environment.h"
#include "gltf_read/gltf_files.h"
#include "gltf_read/gltf_geometry.h"
#include "gltf_read/gltf_lights.h"
#include "gltf_read/gltf_materials.h"
#include "util/error.h"
#include "util/files.h"

namespace raylab {

namespace {

using gltf::Document;
using gltf::findPath;
using nlohmann::json;

constexpr float kUniformScaleTolerance = 1e-4f;  // relative, for the scale of a raylab sphere's node
// Defaults for a file without a camera (docs/scenes.md): the bounds seen from +Z, raised 20 degrees.
constexpr float kDefaultYfov = glm::radians(40.0f);
constexpr float kDefaultElevation = glm::radians(20.0f);
constexpr float kFramingMargin = 1.05f;
// The default light: irradiance at the scene's centre such that white Lambert facing it has radiance 0.8.
constexpr float kDefaultLightRadiance = 0.8f;
constexpr float kPi = 3.14159265358979323846f;
// More instances than any device's TLAS comfortably holds (lavapipe: 2^24) and a bound on the memory a small
// file can ask for (docs/scenes.md, Limits).
constexpr std::size_t kMaxMeshInstances = std::size_t(1) << 20;
constexpr float kMaxPreciseReach = 1e7f;

bool isFinite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

// A [r, g, b] of finite numbers >= 0, or an Error naming `where`.
glm::vec3 readColor(const json& value, const std::string& where) {
  const bool ok = value.is_array() && value.size() == 3 && value[0].is_number() && value[1].is_number() &&
                  value[2].is_number();
  const glm::vec3 color =
      ok ? glm::vec3(value[0].get<float>(), value[1].get<float>(), value[2].get<float>()) : glm::vec3(-1.0f);
  if (!ok || !(color.r >= 0.0f && color.g >= 0.0f && color.b >= 0.0f) || !std::isfinite(color.r + color.g + color.b)) {
    throw Error(where + ": expected [r, g, b] of finite numbers >= 0, found " + value.dump());
  }
  return color;
}

struct CameraUse {
  int camera;
  int node;
  glm::mat4 world;
};

struct Bounds {
  glm::vec3 low{std::numeric_limits<float>::max()};
  glm::vec3 high{-std::numeric_limits<float>::max()};
  void add(glm::vec3 p) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
};

class SceneBuilder {
 public:
  SceneBuilder(Document& document, const GltfOptions& options, Scene& scene)
      : document_(document), model_(document.model), options_(options), scene_(scene) {}

  void build() {
    gltf::convertMaterials(document_, scene_);
    scene_.environment = gltf::readEnvironment(document_, options_);
    const std::vector<int> roots = sceneRoots();
    walk(roots);
    if (scene_.instances.empty() && scene_.spheres.empty()) {
      std::string skipped;
      for (const std::string& feature : document_.ignored) skipped += (skipped.empty() ? "" : "; ") + feature;
      document_.fail("the scene has nothing to render (no triangle meshes or raylab spheres" +
                     (skipped.empty() ? std::string() : "; ignored: " + skipped) + ")");
    }
    if (!model_.animations.empty()) document_.ignore("animations");
    warnIfBeyondFloatPrecision();
    chooseCamera();
    // A scene lit by its own emitters or environment needs no stand-in light (it would add light the file does
    // not have).
    if (scene_.lights.empty() && !hasEmissiveGeometry(scene_) && !scene_.environment.hasImage()) addDefaultLight();
    document_.reportIgnored();
  }

 private:
  // The nodes of the default scene (the first when the file names none); a file without scenes shows every
  // node that is nobody's child.
  std::vector<int> sceneRoots() {
    if (model_.scenes.empty()) {
      if (model_.nodes.empty()) document_.fail("has no scenes and no nodes: nothing to render");
      std::vector<bool> isChild(model_.nodes.size(), false);
      for (const tinygltf::Node& node : model_.nodes) {
        for (int child : node.children) {
          if (child >= 0 && std::size_t(child) < isChild.size()) isChild[std::size_t(child)] = true;
        }
      }
      std::vector<int> roots;
      for (std::size_t i = 0; i < isChild.size(); ++i) {
        if (!isChild[i]) roots.push_back(int(i));
      }
      document_.warnOnce("no scene", "has no scenes; showing every root node");
      return roots;
    }
    const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (std::size_t(sceneIndex) >= model_.scenes.size()) {
      document_.fail("the default scene " + std::to_string(sceneIndex) + " does not exist (the file has " +
                     std::to_string(model_.scenes.size()) + ")");
    }
    readSceneExtras(document_.json.at("scenes").at(std::size_t(sceneIndex)),
                    gltf::describe("scene", sceneIndex, model_.scenes[std::size_t(sceneIndex)].name));
    return model_.scenes[std::size_t(sceneIndex)].nodes;
  }

  void readSceneExtras(const json& sceneJson, const std::string& sceneWhere) {
    const json* raylab = findPath(sceneJson, {"extras", "raylab"});
    if (raylab == nullptr) return;
    const std::string where = document_.label + ": " + sceneWhere + ": extras.raylab";
    if (!raylab->is_object()) throw Error(where + ": expected an object, found " + raylab->dump());
    for (const auto& [key, value] : raylab->items()) {
      if (key == "background") {
        scene_.background = readColor(value, where + ".background");
      } else {
        throw Error(where + ": unknown key '" + key + "' (a scene's extras.raylab has background)");
      }
    }
  }

  glm::mat4 localTransform(const tinygltf::Node& node, const std::string& where) {
    glm::mat4 local(1.0f);
    if (node.matrix.size() == 16) {
      // glTF matrices are column-major, as glm's are.
      for (int i = 0; i < 16; ++i) glm::value_ptr(local)[i] = float(node.matrix[std::size_t(i)]);
    } else {
      glm::vec3 t(0.0f), s(1.0f);
      glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
      if (node.translation.size() == 3) t = glm::vec3(node.translation[0], node.translation[1], node.translation[2]);
      if (node.scale.size() == 3) s = glm::vec3(node.scale[0], node.scale[1], node.scale[2]);
      if (node.rotation.size() == 4) {
        // glTF stores x, y, z, w; glm's constructor takes w first.
        const std::vector<double>& q = node.rotation;
        r = glm::quat(float(q[3]), float(q[0]), float(q[1]), float(q[2]));
        const float length = glm::length(r);
        if (!(length > 0.0f) || !std::isfinite(length)) document_.fail(where + ": rotation is not a unit quaternion");
        r /= length;
      }
      local = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
    }
    if (!isFinite(local)) document_.fail(where + ": the transform has non-finite entries");
    return local;
  }

  // glTF 2.0 § 3.5.3: the node hierarchy is a set of disjoint trees. A node listed as a child twice (or by two
  // parents) would make a tiny file expand exponentially, and a scene root with a parent would be drawn twice:
  // both are refused before the walk.
  void checkHierarchy(const std::vector<int>& roots) {
    std::vector<int> parent(model_.nodes.size(), -1);
    for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
      for (int child : model_.nodes[i].children) {
        if (child < 0 || std::size_t(child) >= model_.nodes.size()) {
          document_.fail(gltf::describe("node", int(i), model_.nodes[i].name) + ": node " + std::to_string(child) +
                         " does not exist (the file has " + std::to_string(model_.nodes.size()) + ")");
        }
        if (parent[std::size_t(child)] >= 0) {
          document_.fail(gltf::describe("node", child, model_.nodes[std::size_t(child)].name) +
                         ": is a child of node " + std::to_string(parent[std::size_t(child)]) + " and again of node " +
                         std::to_string(i) + "; glTF allows each node one parent");
        }
        parent[std::size_t(child)] = int(i);
      }
    }
    for (int root : roots) {
      if (root >= 0 && std::size_t(root) < parent.size() && parent[std::size_t(root)] >= 0) {
        int ancestor = parent[std::size_t(root)];
        for (std::size_t step = 0; ancestor >= 0 && ancestor != root && step < parent.size(); ++step) {
          ancestor = parent[std::size_t(ancestor)];
        }
        if (ancestor == root) {
          document_.fail(gltf::describe("node", root, model_.nodes[std::size_t(root)].name) +
                         ": is its own ancestor (the node hierarchy has a cycle)");
        }
        document_.fail(gltf::describe("node", root, model_.nodes[std::size_t(root)].name) +
                       ": is a scene root and a child of node " + std::to_string(parent[std::size_t(root)]) +
                       "; glTF scene nodes must be roots");
      }
    }
  }

  // Depth first, in file order, without recursion: a 10,000-level chain must not overflow the stack.
  void walk(const std::vector<int>& roots) {
    checkHierarchy(roots);
    struct Pending {
      int node;
      glm::mat4 parent;
      std::string parentWhere;
    };
    std::vector<Pending> stack;
    for (auto root = roots.rbegin(); root != roots.rend(); ++root) stack.push_back({*root, glm::mat4(1.0f), "scene"});
    std::vector<bool> visited(model_.nodes.size(), false);
    while (!stack.empty()) {
      Pending next = std::move(stack.back());
      stack.pop_back();
      const glm::mat4 world = visit(next.node, next.parent, next.parentWhere, visited);
      const tinygltf::Node& node = model_.nodes[std::size_t(next.node)];
      const std::string where = gltf::describe("node", next.node, node.name);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
        stack.push_back({*child, world, where});
      }
    }
  }

  // One node: its transform, sphere or mesh instances, camera and light. Returns its world transform.
  glm::mat4 visit(int nodeIndex, const glm::mat4& parent, const std::string& parentWhere, std::vector<bool>& visited) {
    if (nodeIndex < 0 || std::size_t(nodeIndex) >= model_.nodes.size()) {
      document_.fail(parentWhere + ": node " + std::to_string(nodeIndex) + " does not exist (the file has " +
                     std::to_string(model_.nodes.size()) + ")");
    }
    const tinygltf::Node& node = model_.nodes[std::size_t(nodeIndex)];
    const std::string where = gltf::describe("node", nodeIndex, node.name);
    if (visited[std::size_t(nodeIndex)]) {
      document_.fail(where + ": is reached twice (listed twice in the scene, or the hierarchy has a cycle)");
    }
    visited[std::size_t(nodeIndex)] = true;

    const glm::mat4 world = parent * localTransform(node, where);
    if (!isFinite(world)) document_.fail(where + ": the world transform overflows");
    const json& nodeJson = document_.json.at("nodes").at(std::size_t(nodeIndex));
    if (node.skin >= 0) document_.ignore("skins (meshes are shown in their bind pose)");

    const json* sphere = nodeRaylabSphere(nodeJson, where);
    if (sphere != nullptr) {
      addSphere(*sphere, node, world, where);
    } else if (node.mesh >= 0) {
      if (std::size_t(node.mesh) >= model_.meshes.size()) {
        document_.fail(where + ": mesh " + std::to_string(node.mesh) + " does not exist (the file has " +
                       std::to_string(model_.meshes.size()) + ")");
      }
      addMeshInstances(node.mesh, world, where);
    }
    if (node.camera >= 0) {
      if (std::size_t(node.camera) >= model_.cameras.size()) {
        document_.fail(where + ": camera " + std::to_string(node.camera) + " does not exist (the file has " +
                       std::to_string(model_.cameras.size()) + ")");
      }
      cameras_.push_back({node.camera, nodeIndex, world});
    }
    if (const json* light = findPath(nodeJson, {"extensions", "KHR_lights_punctual", "light"})) {
      scene_.lights.push_back(gltf::convertLight(document_, light->get<int>(), world, where));
    }
    return world;
  }

  // The node's extras.raylab.sphere object, or null; extras.raylab may hold nothing else.
  const json* nodeRaylabSphere(const json& nodeJson, const std::string& where) {
    const json* raylab = findPath(nodeJson, {"extras", "raylab"});
    if (raylab == nullptr) return nullptr;
    const std::string prefix = document_.label + ": " + where + ": extras.raylab";
    if (!raylab->is_object()) throw Error(prefix + ": expected an object, found " + raylab->dump());
    for (const auto& [key, value] : raylab->items()) {
      if (key != "sphere") throw Error(prefix + ": unknown key '" + key + "' (a node's extras.raylab has sphere)");
    }
    return findPath(*raylab, {"sphere"});
  }

  void addSphere(const json& sphere, const tinygltf::Node& node, const glm::mat4& world, const std::string& where) {
    const std::string prefix = document_.label + ": " + where + ": extras.raylab.sphere";
    if (!sphere.is_object()) {
      throw Error(prefix + ": expected {\"radius\": r, \"material\": i}, found " + sphere.dump());
    }
    for (const auto& [key, value] : sphere.items()) {
      if (key != "radius" && key != "material") {
        throw Error(prefix + ": unknown key '" + key + "' (a sphere has radius and material)");
      }
    }
    const auto radius = sphere.find("radius");
    if (radius == sphere.end() || !radius->is_number() || !(radius->get<double>() > 0.0) ||
        !std::isfinite(radius->get<float>())) {
      throw Error(prefix + ".radius: expected a finite number > 0, found " +
                  (radius == sphere.end() ? std::string("nothing") : radius->dump()));
    }

    std::uint32_t material = 0;
    if (const auto index = sphere.find("material"); index != sphere.end()) {
      if (!index->is_number_integer() || index->get<std::int64_t>() < 0 ||
          index->get<std::int64_t>() >= std::int64_t(model_.materials.size())) {
        throw Error(prefix + ".material: " + index->dump() + " is not a material index (the file has " +
                    std::to_string(model_.materials.size()) + " materials)");
      }
      material = index->get<std::uint32_t>();
    } else {
      // The material of the stand-in mesh's first primitive, so that other viewers and raylab agree.
      const bool hasMesh = node.mesh >= 0 && std::size_t(node.mesh) < model_.meshes.size() &&
                           !model_.meshes[std::size_t(node.mesh)].primitives.empty();
      const int first = hasMesh ? model_.meshes[std::size_t(node.mesh)].primitives[0].material : -1;
      material = first >= 0 && std::size_t(first) < model_.materials.size() ? std::uint32_t(first)
                                                                            : defaultMaterial_.index(scene_);
    }

    // An exact sphere stays one only under a similarity: equal scale on three orthogonal axes.
    const glm::mat3 linear(world);
    const glm::vec3 scale(glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2]));
    const float largest = std::max({scale.x, scale.y, scale.z});
    const float smallest = std::min({scale.x, scale.y, scale.z});
    const float skew = std::max({std::abs(glm::dot(linear[0], linear[1])), std::abs(glm::dot(linear[1], linear[2])),
                                 std::abs(glm::dot(linear[0], linear[2]))});
    if (!(smallest > 0.0f) || largest - smallest > kUniformScaleTolerance * largest ||
        skew > kUniformScaleTolerance * largest * largest) {
      char axes[96];
      std::snprintf(axes, sizeof axes, "(%g, %g, %g)", scale.x, scale.y, scale.z);
      document_.fail(where + ": a raylab sphere needs a uniform scale, but the world transform scales the axes by " +
                     axes + (skew > kUniformScaleTolerance * largest * largest ? " with shear" : ""));
    }
    scene_.spheres.push_back({glm::vec3(world[3]), radius->get<float>() * scale.x, material});
  }

  // The vertex data a material's textures read: the UV sets they use (a missing set is reported: the texture is
  // then read at (0, 0)), and tangents for a normal map, generated from its UV set when the file has none
  // (scene/tangents.h). Data no texture reads is dropped rather than uploaded.
  void prepareForTextures(Mesh& mesh, const gpu::MaterialRecord& record) {
    bool readsSet[2] = {false, false};
    const gpu::TextureRef* normalMap = nullptr;
    if (record.textures >= 0) {
      const gpu::MaterialTextures& uses = scene_.materialTextures[std::size_t(record.textures)];
      for (const gpu::TextureRef& ref : uses.refs) {
        if (ref.texture >= 0) readsSet[ref.texCoord] = true;
      }
      if (uses.refs[gpu::kTextureNormal].texture >= 0) normalMap = &uses.refs[gpu::kTextureNormal];
    }
    const std::vector<glm::vec2>* sets[2] = {&mesh.uvs, &mesh.uvs1};
    for (int set = 0; set < 2; ++set) {
      if (readsSet[set] && sets[set]->empty()) {
        document_.warnOnce("no uvs " + std::to_string(set),
                           mesh.name + ": a textured material reads TEXCOORD_" + std::to_string(set) +
                               ", which the mesh does not have (the texture is read at (0, 0))");
      }
    }
    if (!readsSet[1]) mesh.uvs1.clear();
    if (normalMap == nullptr) {
      mesh.tangents.clear();
    } else if (mesh.tangents.empty() && !sets[normalMap->texCoord]->empty()) {
      mesh.tangents = generateTangents(mesh, *sets[normalMap->texCoord]);
    }
  }

  void addMeshInstances(int meshIndex, const glm::mat4& world, const std::string& where) {
    auto cached = meshes_.find(meshIndex);
    if (cached == meshes_.end()) {
      std::vector<std::pair<std::uint32_t, std::uint32_t>> parts;  // scene mesh, scene material
      for (gltf::PrimitiveMesh& primitive : gltf::convertMesh(document_, meshIndex)) {
        const std::uint32_t material =
            primitive.material >= 0 ? std::uint32_t(primitive.material) : defaultMaterial_.index(scene_);
        prepareForTextures(primitive.mesh, scene_.materials[material].record);
        parts.emplace_back(std::uint32_t(scene_.meshes.size()), material);
        scene_.meshes.push_back(std::move(primitive.mesh));
      }
      cached = meshes_.emplace(meshIndex, std::move(parts)).first;
    }
    // A singular transform (zero scale hides a node) would give the kernel an infinite inverse.
    const float determinant = glm::determinant(glm::mat3(world));
    if (!(std::abs(determinant) > 0.0f)) {
      document_.warnOnce("singular", where + ": has a zero scale; its mesh is not shown");
      return;
    }
    if (scene_.instances.size() + cached->second.size() > kMaxMeshInstances) {
      document_.fail(where + ": the scene has more than " + std::to_string(kMaxMeshInstances) +
                     " mesh instances (raylab's limit, docs/scenes.md)");
    }
    for (const auto& [mesh, material] : cached->second) scene_.instances.push_back({mesh, world, material});
  }

  std::string cameraName(const CameraUse& use) const {
    const std::string& name = model_.cameras[std::size_t(use.camera)].name;
    if (!name.empty()) return name;
    const std::string& nodeName = model_.nodes[std::size_t(use.node)].name;
    return nodeName.empty() ? "camera " + std::to_string(use.camera) : nodeName;
  }

  void chooseCamera() {
    for (const CameraUse& use : cameras_) scene_.cameraNames.push_back(cameraName(use));
    const CameraUse* chosen = nullptr;
    if (!options_.camera.empty()) {
      std::string known;
      for (const CameraUse& use : cameras_) {
        const std::string& ownName = model_.cameras[std::size_t(use.camera)].name;
        const std::string& nodeName = model_.nodes[std::size_t(use.node)].name;
        // By the camera's name, its node's, or the name raylab lists it under ("camera 1" for an unnamed one).
        if (chosen == nullptr &&
            (ownName == options_.camera || nodeName == options_.camera || cameraName(use) == options_.camera)) {
          chosen = &use;
        }
        known += (known.empty() ? "'" : ", '") + cameraName(use) + "'";
      }
      if (chosen == nullptr) {
        document_.fail("has no camera named '" + options_.camera + "' (" +
                       (known.empty() ? std::string("it has no cameras") : "cameras: " + known) + ")");
      }
      if (model_.cameras[std::size_t(chosen->camera)].type != "perspective") {
        document_.fail("camera '" + options_.camera + "' is " + model_.cameras[std::size_t(chosen->camera)].type +
                       "; raylab renders perspective cameras only");
      }
    } else {
      // The first perspective camera of the file's list that the scene uses.
      for (const CameraUse& use : cameras_) {
        if (model_.cameras[std::size_t(use.camera)].type != "perspective") {
          document_.ignore("orthographic cameras");
          continue;
        }
        if (chosen == nullptr || use.camera < chosen->camera) chosen = &use;
      }
    }
    if (chosen == nullptr) {
      frameBounds();
      return;
    }
    const tinygltf::Camera& camera = model_.cameras[std::size_t(chosen->camera)];
    const std::string where = gltf::describe("camera", chosen->camera, camera.name);
    if (camera.type != "perspective") document_.fail(where + ": type \"" + camera.type + "\" is not perspective");
    const double yfov = camera.perspective.yfov;
    if (!(float(yfov) >= kMinYfov && float(yfov) < kMaxYfov)) {
      document_.fail(where + ": yfov " + gltf::formatNumber(yfov) + " rad is outside [0.0001, 3.1)");
    }
    // The camera looks down its node's -Z with +Y up (glTF 2.0 § 3.10.1).
    const glm::mat4& world = chosen->world;
    const glm::vec3 forward(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    const glm::vec3 up(world * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    const float across = glm::length(glm::cross(forward, up));
    if (!(across > 0.0f) || !std::isfinite(across)) {
      document_.fail(where + ": its node's transform collapses the view direction or the up axis");
    }
    scene_.camera.name = cameraName(*chosen);
    scene_.camera.position = glm::vec3(world[3]);
    // The viewer orbits and zooms about the target: put it on the scene, where the view ray meets it.
    scene_.camera.target = orbitPivot(scene_, scene_.camera.position, forward);
    // The viewer orbits about camera.up: for a camera without roll that must be the world's vertical, not the
    // node's tilted +Y (a 180-degree orbit about that puts the camera under the floor). Both give the same
    // image, as applyCamera only takes the plane of forward and up.
    const glm::vec3 worldUp(0.0f, 1.0f, 0.0f);
    const glm::vec3 side = glm::cross(forward, worldUp);
    const bool unrolled = glm::length(side) > 1e-3f * glm::length(forward) &&
                          std::abs(glm::dot(glm::normalize(side), glm::normalize(up))) < 1e-4f &&
                          glm::dot(up, worldUp) > 0.0f;
    scene_.camera.up = unrolled ? worldUp : glm::normalize(up);
    scene_.camera.yfov = float(yfov);
  }

  // Traversal and intersection run in float32: 1e7 units from the origin one ulp is a whole unit, and a
  // ground plane scaled to 1e8 vanishes or leaks without an error. Warn with the extent.
  void warnIfBeyondFloatPrecision() {
    const Bounds bounds = sceneBounds();
    const float reach = std::max(glm::length(bounds.low), glm::length(bounds.high));
    if (reach > kMaxPreciseReach) {
      document_.warnOnce("float range", "geometry reaches " + gltf::formatNumber(reach) +
                                            " units from the origin; float32 traversal resolves about " +
                                            gltf::formatNumber(reach * 6e-8) +
                                            " units there, so surfaces may vanish or leak (docs/scenes.md, Limits)");
    }
  }

  Bounds sceneBounds() const {
    Bounds bounds;
    for (const MeshInstance& instance : scene_.instances) {
      for (const glm::vec3& p : scene_.meshes[instance.mesh].positions) {
        bounds.add(glm::vec3(instance.transform * glm::vec4(p, 1.0f)));
      }
    }
    for (const Sphere& sphere : scene_.spheres) {
      bounds.add(sphere.center - sphere.radius);
      bounds.add(sphere.center + sphere.radius);
    }
    return bounds;
  }

  void frameBounds() {
    const Bounds bounds = sceneBounds();
    const glm::vec3 center = 0.5f * (bounds.low + bounds.high);
    float radius = 0.5f * glm::length(bounds.high - bounds.low);
    if (!(radius > 0.0f)) radius = 1.0f;
    const float distance = kFramingMargin * radius / std::sin(0.5f * kDefaultYfov);
    const glm::vec3 direction(0.0f, std::sin(kDefaultElevation), std::cos(kDefaultElevation));
    scene_.camera.name = "default";
    scene_.camera.position = center + distance * direction;
    scene_.camera.target = center;
    scene_.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    scene_.camera.yfov = kDefaultYfov;
    document_.warnOnce("no camera", "has no perspective camera; framing the scene's bounds from +Z (docs/scenes.md)");
  }

  // A white headlight above and to the left of the camera, carried with it (kLightHeadlight), so that whatever
  // the camera is turned to is lit; bright enough that white Lambert at the scene's centre facing it has radiance
  // 0.8 from the loaded camera.
  void addDefaultLight() {
    const Bounds bounds = sceneBounds();
    const glm::vec3 center = 0.5f * (bounds.low + bounds.high);
    const Camera& camera = scene_.camera;
    const glm::vec3 w = glm::normalize(camera.target - camera.position);
    const glm::vec3 u = glm::normalize(glm::cross(w, camera.up));
    const glm::vec3 v = glm::cross(u, w);
    const float distance = std::max(glm::length(center - camera.position), 1e-3f);
    const glm::vec3 offset(-0.3f * distance, 0.3f * distance, 0.0f);  // along right, up, forward
    const float toCenter = glm::length(center - (camera.position + offset.x * u + offset.y * v));
    const float intensity = kDefaultLightRadiance * kPi * toCenter * toCenter;
    PunctualLight record = pointLight(offset, glm::vec3(intensity));
    record.type = gpu::kLightHeadlight;
    scene_.lights.push_back({"default", record});
    document_.warnOnce("no lights", "has no KHR_lights_punctual lights; added a default headlight, carried with the "
                                    "camera (docs/scenes.md)");
  }

  Document& document_;
  const tinygltf::Model& model_;
  const GltfOptions& options_;
  Scene& scene_;
  std::vector<CameraUse> cameras_;
  std::map<int, std::vector<std::pair<std::uint32_t, std::uint32_t>>> meshes_;
  gltf::DefaultMaterial defaultMaterial_;
};

Scene loadDocument(Document& document, const std::string& name, const GltfOptions& options) {
  Scene scene;
  scene.name = name;
  SceneBuilder(document, options, scene).build();
  return scene;
}

}  // namespace

Scene loadGltfFile(const std::string& path, const GltfOptions& options) {
  // What the file is comes first (a FIFO or /dev/zero is refused as such), then what its name says it holds.
  FileProblem problem{};
  const std::string refused = inputFileProblem(path, gltf::kMaxSceneFileBytes, &problem);
  if (!refused.empty()) throw FileError(path + ": " + refused, problem);
  const std::filesystem::path file(path);
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".gltf" && extension != ".glb") {
    throw Error(path + ": raylab reads glTF 2.0 scenes (.gltf or .glb), not '" +
                    (extension.empty() ? std::string("a file without an extension") : extension) +
                    "' (convert it, e.g. with Blender or assimp export)",
                kExitUsage);
  }
  const std::string bytes = readInputFile(path, gltf::kMaxSceneFileBytes);
  const std::string directory = file.parent_path().empty() ? "." : file.parent_path().string();
  Document document = gltf::parseDocument(bytes, directory, path, extension == ".glb", options.allowOutsideUris);
  return loadDocument(document, file.stem().string(), options);
}

Scene loadGltfText(const std::string& json, const std::string& baseDirectory, const std::string& sceneName,
                   const GltfOptions& options) {
  Document document = gltf::parseDocument(json, baseDirectory, sceneName, false, options.allowOutsideUris);
  return loadDocument(document, sceneName, options);
}

}  // namespace raylab
