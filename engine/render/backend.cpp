#include "render/backend.h"

#include "util/error.h"

namespace raylab {

Backend chooseBackend(const Device& device, BackendChoice choice) {
  const std::string name = device.report.name;
  switch (choice) {
    case BackendChoice::kQuery:
      if (!device.rayQueries) {
        throw Error("--backend query: " + name + " offers no ray queries" +
                        (device.report.rayQueriesHidden ? std::string(" (hidden by ") + kHideRayQueriesVariable + ")"
                                                        : std::string()) +
                        "; use --backend pipeline or auto",
                    kExitNoDevice);
      }
      return Backend::kQuery;
    case BackendChoice::kPipeline:
      if (!device.rayTracingPipelines) {
        throw Error("--backend pipeline: " + name + " offers no ray-tracing pipelines; use --backend query or auto",
                    kExitNoDevice);
      }
      return Backend::kPipeline;
    case BackendChoice::kAuto: break;
  }
  return device.rayQueries ? Backend::kQuery : Backend::kPipeline;
}

const char* backendName(Backend backend) { return backend == Backend::kPipeline ? "pipeline" : "query"; }

}  // namespace raylab
