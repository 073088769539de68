// What the window tests share: `raylab view` on a private X server (xvfb-run), scripts in a scratch directory,
// images compared with `raylab render`'s, and where a sphere of the scene is seen from its camera.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"
#include "support/run_command.h"

namespace raylab::test {

inline const std::string kMinimalScene = std::string(RAYLAB_SOURCE_DIR) + "/assets/scenes/minimal.gltf";

std::string scratchDir();
// xvfb-run from PATH; empty when it is not installed.
std::string findXvfbRun();
// Runs `raylab view ARGS` on a private X server; `environment` as runCommand's.
CommandResult runView(const std::vector<std::string>& arguments, const std::vector<std::string>& environment = {});
std::string writeScript(const std::string& name, const std::string& text);
// Exit 0 and no validation message.
void expectCleanRun(const CommandResult& result);
// Images equal up to float rounding: the same samples summed in the same order give the same floats, but a
// different kernel specialisation may contract a multiply-add differently.
void expectSameImage(const Image& actual, const Image& expected, const std::string& what);
double meanLuminance(const Image& image);
// `raylab render --out EXR --png EXR.png EXTRA...`, read back.
Image renderReference(const std::vector<std::string>& extra, const std::string& exrPath);
// Which pixels see the sphere of material `materialName` through their centre (the camera of `scene` at
// width x height): the host's own ray-sphere test, so the test does not trust the renderer to say where it is.
// `radiusScale` shrinks or grows the sphere, to leave the silhouette's pixels out of both sides.
std::vector<bool> sphereMask(const Scene& scene, const std::string& materialName, std::uint32_t width,
                             std::uint32_t height, float radiusScale);

}  // namespace raylab::test
