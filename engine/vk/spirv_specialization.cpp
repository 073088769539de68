#include "vk/spirv_specialization.h"

#include <spirv-tools/optimizer.hpp>

#include <string>
#include <unordered_map>

#include "util/error.h"

namespace raylab {

std::vector<std::uint32_t> specializeSpirv(std::span<const std::uint32_t> spirv,
                                           std::span<const std::pair<std::uint32_t, std::uint32_t>> constants,
                                           std::string_view kernelName) {
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> values;
  for (const auto& [id, value] : constants) values[id] = {value};
  std::string messages;
  spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
  optimizer.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
    messages += std::string(messages.empty() ? "" : "; ") + message;
  });
  optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values))
      .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
      .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass())
      .RegisterPass(spvtools::CreateDeadBranchElimPass())
      .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass());
  // The build validated every kernel (spirv-val); validating again here would cost ten times the passes.
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);
  std::vector<std::uint32_t> specialized;
  if (!optimizer.Run(spirv.data(), spirv.size(), &specialized, options)) {
    throw Error("kernel " + std::string(kernelName) + " could not be specialised: " + messages);
  }
  return specialized;
}

}  // namespace raylab
