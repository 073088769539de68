// Bad textures as `raylab render` users meet them: each is exit 1 with a message naming the material and the
// texture use, and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../scene/gltf_test_support.h"
#include "support/run_command.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A quad with TEXCOORD_0 whose material 'panel' reads image `uri` through `use` (a JSON path under the material).
GltfBuilder texturedQuad(const std::string& uri, const std::vector<std::string>& use) {
  GltfBuilder b;
  const int mesh = b.addQuad();
  b.doc()["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_0"] = b.addFloats({0, 0, 1, 0, 1, 1, 0, 1}, "VEC2");
  b.doc()["images"] = json::array({{{"uri", uri}}});
  b.doc()["textures"] = json::array({{{"source", 0}}});
  json material = {{"name", "panel"}};
  json* at = &material;
  for (const std::string& key : use) at = &(*at)[key];
  *at = {{"index", 0}};
  b.doc()["meshes"][mesh]["primitives"][0]["material"] = b.addMaterial(material);
  b.addNode({{"mesh", mesh}});
  return b;
}

TEST(TextureCli, BadTexturesExitNonZeroNamingTheMaterialAndTextureAndWriteNothing) {
  const fs::path dir = freshDir("texture_cli", "bad_textures");
  std::ofstream(dir / "corrupt.png") << "not a PNG at all";
  std::ofstream(dir / "huge.png", std::ios::binary) << pngHeader(20000, 20000);
  struct Case {
    const char* name;
    GltfBuilder scene;
    const char* mentions;
  };
  std::vector<Case> cases;
  cases.push_back({"missing image", texturedQuad("missing.png", {"pbrMetallicRoughness", "baseColorTexture"}),
                   "material 0 'panel' baseColorTexture: image 0 ('missing.png'): its file is missing"});
  GltfBuilder emissive = texturedQuad("corrupt.png", {"emissiveTexture"});
  emissive.doc()["materials"][0]["emissiveFactor"] = {1.0, 1.0, 1.0};  // the default 0 reads no texture
  cases.push_back({"corrupt image", emissive,
                   "material 0 'panel' emissiveTexture: image 0 ('corrupt.png'): is not a PNG or JPEG image"});
  cases.push_back({"normal map over the size limit", texturedQuad("huge.png", {"normalTexture"}),
                   "material 0 'panel' normalTexture: image 0 ('huge.png'): is 20000x20000, over raylab's limit"});
  GltfBuilder outOfRange = texturedQuad("corrupt.png", {"pbrMetallicRoughness", "metallicRoughnessTexture"});
  outOfRange.doc()["materials"][0]["pbrMetallicRoughness"]["metallicRoughnessTexture"]["index"] = 7;
  cases.push_back({"texture index out of range", outOfRange,
                   "material 0 'panel' metallicRoughnessTexture: texture 7 does not exist (the file has 1)"});
  for (const double cutoff : {-0.5, 1e39}) {  // below 0; beyond a float (JSON has no NaN)
    GltfBuilder masked = texturedQuad("corrupt.png", {"occlusionTexture"});
    masked.doc()["materials"][0].erase("occlusionTexture");
    masked.doc()["materials"][0]["alphaMode"] = "MASK";
    masked.doc()["materials"][0]["alphaCutoff"] = cutoff;
    cases.push_back({"bad alphaCutoff", masked, "material 0 'panel': alphaCutoff"});
  }
  // glTF's images are PNG and JPEG: a BMP (which stb would decode) is refused by what it is; an image outside the
  // scene's folder by the folder rule, as every other URI; a PNG whose data is damaged with stb's reason.
  std::ofstream(dir / "picture.bmp", std::ios::binary) << std::string("BM\x46\0\0\0\0\0\0\0\x36\0\0\0", 14)
                                                        << std::string(56, '\0');
  cases.push_back({"BMP image", texturedQuad("picture.bmp", {"pbrMetallicRoughness", "baseColorTexture"}),
                   "image 0 ('picture.bmp'): is a BMP image, not a PNG or JPEG image"});
  fs::create_directories(dir.parent_path() / "elsewhere");
  std::ofstream(dir.parent_path() / "elsewhere" / "outside.png") << "whatever";
  cases.push_back({"image outside the folder",
                   texturedQuad("../elsewhere/outside.png", {"pbrMetallicRoughness", "baseColorTexture"}),
                   "outside"});
  std::string damaged = pngHeader(4, 4);
  damaged += std::string(40, '\x7f');
  std::ofstream(dir / "damaged.png", std::ios::binary) << damaged;
  cases.push_back({"damaged PNG", texturedQuad("damaged.png", {"pbrMetallicRoughness", "baseColorTexture"}),
                   "image 0 ('damaged.png'): cannot be decoded ("});
  const std::string out = (dir / "image.exr").string(), png = (dir / "image.png").string();
  for (const Case& c : cases) {
    fs::remove(out);
    fs::remove(png);
    const fs::path scene = dir / "scene.gltf";
    std::ofstream(scene) << c.scene.text();
    const CommandResult result = runRaylab({"render", scene.string(), "--out", out, "--png", png, "--spp", "1",
                                            "--width", "16", "--height", "16"});
    // A value outside its range exits 2, as every material value does (docs/scenes.md); a bad file 1.
    EXPECT_EQ(result.exitCode, c.name == std::string("bad alphaCutoff") ? 2 : 1) << c.name << ": " << result.output;
    EXPECT_NE(result.output.find(c.mentions), std::string::npos) << c.name << ": " << result.output;
    EXPECT_EQ(result.output.find("()"), std::string::npos) << c.name << ": an empty reason\n" << result.output;
    EXPECT_EQ(result.output.find("missing or unreadable"), c.name == std::string("image outside the folder")
                                                               ? std::string::npos
                                                               : result.output.find("missing or unreadable"))
        << c.name << ": " << result.output;
    EXPECT_FALSE(fs::exists(out)) << c.name;
    EXPECT_FALSE(fs::exists(png)) << c.name;
  }
}

}  // namespace
}  // namespace raylab::test
