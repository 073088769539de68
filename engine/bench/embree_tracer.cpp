#include "bench/embree_tracer.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>
#include <thread>

#include "util/error.h"
#include "util/timer.h"

namespace raylab {

struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

namespace {

void checkDevice(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) throw Error(std::string("Embree: ") + what + " failed (error " + std::to_string(error) + ")");
}

void addMesh(RTCDevice device, RTCScene scene, const Mesh& mesh, const glm::mat4& transform) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), mesh.positions.size()));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = glm::vec3(transform * glm::vec4(mesh.positions[i], 1.0f));
    vertices[3 * i] = p.x, vertices[3 * i + 1] = p.y, vertices[3 * i + 2] = p.z;
  }
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), mesh.indices.size() / 3));
  std::copy(mesh.indices.begin(), mesh.indices.end(), indices);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
}

void addSpheres(RTCDevice device, RTCScene scene, std::span<const Sphere> spheres) {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                             4 * sizeof(float), spheres.size()));
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    points[4 * i] = spheres[i].center.x, points[4 * i + 1] = spheres[i].center.y;
    points[4 * i + 2] = spheres[i].center.z, points[4 * i + 3] = spheres[i].radius;
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
}

// Runs body(begin, end) over [0, count) on `threads` threads in contiguous chunks.
template <class Body>
void parallelFor(std::size_t count, unsigned threads, const Body& body) {
  if (threads <= 1) {
    body(std::size_t(0), count);
    return;
  }
  std::vector<std::thread> workers;
  const std::size_t chunk = (count + threads - 1) / threads;
  for (unsigned t = 0; t < threads; ++t) {
    const std::size_t begin = std::min(count, t * chunk), end = std::min(count, begin + chunk);
    workers.emplace_back([&body, begin, end] { body(begin, end); });
  }
  for (std::thread& worker : workers) worker.join();
}

RTCRay toEmbreeRay(const gpu::ProbeRay& ray) {
  RTCRay r{};
  r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
  r.tnear = ray.tMin;
  r.tfar = ray.tMax;
  r.mask = 0xFFFFFFFFu;
  return r;
}

}  // namespace

EmbreeTracer createEmbreeTracer(const Scene& scene, unsigned threads) {
  EmbreeTracer tracer;
  tracer.threads = std::max(1u, threads);
  tracer.scene = new EmbreeScene;
  // Embree's own build threads follow the same count, so build times compare with raylab's.
  const std::string config = "threads=" + std::to_string(tracer.threads);
  tracer.scene->device = rtcNewDevice(config.c_str());
  if (tracer.scene->device == nullptr) throw Error("Embree: rtcNewDevice failed");
  const Stopwatch clock;
  tracer.scene->scene = rtcNewScene(tracer.scene->device);
  rtcSetSceneBuildQuality(tracer.scene->scene, RTC_BUILD_QUALITY_HIGH);
  for (const MeshInstance& instance : scene.instances) {
    addMesh(tracer.scene->device, tracer.scene->scene, scene.meshes[instance.mesh], instance.transform);
  }
  if (!scene.spheres.empty()) addSpheres(tracer.scene->device, tracer.scene->scene, scene.spheres);
  rtcCommitScene(tracer.scene->scene);
  checkDevice(tracer.scene->device, "building the scene");
  tracer.buildSeconds = clock.seconds();
  return tracer;
}

void destroyEmbreeTracer(EmbreeTracer& tracer) {
  if (tracer.scene != nullptr) {
    if (tracer.scene->scene != nullptr) rtcReleaseScene(tracer.scene->scene);
    if (tracer.scene->device != nullptr) rtcReleaseDevice(tracer.scene->device);
    delete tracer.scene;
  }
  tracer = {};
}

std::vector<gpu::ProbeHit> embreeTraceClosest(const EmbreeTracer& tracer, std::span<const gpu::ProbeRay> rays) {
  std::vector<gpu::ProbeHit> hits(rays.size());
  parallelFor(rays.size(), tracer.threads, [&](std::size_t begin, std::size_t end) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t i = begin; i < end; ++i) {
      RTCRayHit rayHit{};
      rayHit.ray = toEmbreeRay(rays[i]);
      rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(tracer.scene->scene, &context, &rayHit);
      gpu::ProbeHit& hit = hits[i];
      if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
        hit.t = rays[i].tMax;
        hit.instance = gpu::kProbeMiss;
        hit.primitive = gpu::kProbeMiss;
        continue;
      }
      hit.t = rayHit.ray.tfar;
      hit.instance = rayHit.hit.geomID;
      hit.primitive = rayHit.hit.primID;
      hit.position = rays[i].origin + hit.t * rays[i].direction;
      hit.geometricNormal = glm::normalize(glm::vec3(rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z));
      hit.frontFace = glm::dot(hit.geometricNormal, rays[i].direction) < 0.0f ? 1u : 0u;
    }
  });
  return hits;
}

std::vector<std::uint8_t> embreeTraceOcclusion(const EmbreeTracer& tracer, std::span<const gpu::ProbeRay> rays) {
  std::vector<std::uint8_t> occluded(rays.size());
  parallelFor(rays.size(), tracer.threads, [&](std::size_t begin, std::size_t end) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t i = begin; i < end; ++i) {
      RTCRay ray = toEmbreeRay(rays[i]);
      rtcOccluded1(tracer.scene->scene, &context, &ray);
      // Embree marks an occluded ray by setting tfar to -inf.
      occluded[i] = ray.tfar < 0.0f ? 1 : 0;
    }
  });
  return occluded;
}

std::string embreeVersion() { return RTC_VERSION_STRING; }

}  // namespace raylab
