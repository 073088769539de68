// Measured materials from the command line as users name them (issues 24 and 36): `raylab brdf tabulate` writes a MERL
// file (of any model, a neural BRDF's too),
// `--material NAME=measured:file=...` and extras.raylab's "file" render it, `raylab brdf fit` ranks models on it;
// every bad file (truncated, wrong dimensions, NaN, all missing, a directory, a device, a file outside the scene's
// folder) is refused with a message naming it, a non-zero exit, and nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "measured/merl.h"
#include "measured/nbrdf.h"
#include "support/nbrdf_files.h"
#include "support/run_command.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / ("raylab_measured_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// A scene folder with minimal.gltf whose sphere is `model` (measured or nbrdf) with `file` (as written in the glTF).
fs::path sceneWithFile(const fs::path& dir, const std::string& file, const std::string& model = "measured") {
  fs::create_directories(dir);
  std::string text = readBytes(fs::path(RAYLAB_SOURCE_DIR) / "assets" / "scenes" / "minimal.gltf");
  const std::string from = R"("model": "cooktorrance",)";
  const std::size_t at = text.find(from);
  const std::size_t end = text.find('}', at);
  text.replace(at, end - at, R"("model": ")" + model + R"(", "file": ")" + file + "\"\n        ");
  const fs::path scene = dir / "scene.gltf";
  writeBytes(scene, text);
  return scene;
}

class MeasuredCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    good_ = scratch() / "good.binary";
    const CommandResult made = runRaylab({"brdf", "tabulate", "cooktorrance:rho_d=0.3,rho_s=0.7,m=0.25",
                                          "--out", good_.string()});
    ASSERT_EQ(made.exitCode, 0) << made.output;
  }
  static fs::path good_;
};
fs::path MeasuredCliTest::good_;

TEST_F(MeasuredCliTest, AMeasuredMaterialRendersFromTheCommandLineAndFromGltf) {
  const fs::path out = scratch() / "render";
  fs::create_directories(out);
  const CommandResult cli = runRaylab({"render", "--material", "phong=measured:file=" + good_.string(), "--out",
                                       (out / "cli.exr").string(), "--spp", "2", "--width", "32", "--height", "24"});
  EXPECT_EQ(cli.exitCode, 0) << cli.output;
  EXPECT_TRUE(fs::exists(out / "cli.exr"));
  const fs::path folder = scratch() / "scene_inside";
  fs::create_directories(folder);
  fs::copy_file(good_, folder / "good.binary", fs::copy_options::overwrite_existing);
  const CommandResult gltf = runRaylab({"render", sceneWithFile(folder, "good.binary").string(), "--out",
                                        (out / "gltf.exr").string(), "--spp", "2", "--width", "32", "--height", "24"});
  EXPECT_EQ(gltf.exitCode, 0) << gltf.output;
  EXPECT_TRUE(fs::exists(out / "gltf.exr"));
  const CommandResult info = runRaylab({"brdf", "albedo", "--model", "measured", "--params", "file=" + good_.string(),
                                        "--angles", "0,60", "--backend", "cpu"});
  EXPECT_EQ(info.exitCode, 0) << info.output;
}

// `raylab brdf eval`: file= is relative to the CSV's folder; both backends give the tabulated model's value (within
// the table's step, 2% at these directions away from the highlight) and agree with each other.
TEST_F(MeasuredCliTest, BrdfEvalReadsTheFileBesideTheCsv) {
  const fs::path dir = scratch() / "eval";
  fs::create_directories(dir);
  fs::copy_file(good_, dir / "beside.binary", fs::copy_options::overwrite_existing);
  const std::string header = "id,model,params,wi,wo,n,t\n";
  writeBytes(dir / "cases.csv", header + "m,measured,file=beside.binary,0.5 0 0.866025,-0.3 0.2 0.932738,0 0 1,1 0 0\n" +
                                    "c,cooktorrance,rho_d=0.3;rho_s=0.7;m=0.25,0.5 0 0.866025,-0.3 0.2 0.932738,0 0 1,1 0 0\n");
  double values[2][2];
  int column = 0;
  for (const std::string backend : {"cpu", "gpu"}) {
    const fs::path out = dir / ("values_" + backend + ".csv");
    const CommandResult eval = runRaylab({"brdf", "eval", "--in", (dir / "cases.csv").string(), "--out", out.string(),
                                          "--backend", backend});
    ASSERT_EQ(eval.exitCode, 0) << eval.output;
    std::istringstream lines(readBytes(out));
    std::string line;
    int row = 0;
    std::getline(lines, line);
    while (std::getline(lines, line) && row < 2) values[column][row++] = std::stod(line.substr(line.rfind(',') + 1));
    ++column;
  }
  EXPECT_NEAR(values[0][0], values[0][1], 0.02 * values[0][1]) << "measured against the model it tabulates";
  EXPECT_NEAR(values[1][0], values[0][0], 1e-5 * values[0][0]) << "gpu against cpu";
}

TEST_F(MeasuredCliTest, BadFilesAreRefusedNamingThemAndNothingIsWritten) {
  const fs::path dir = scratch() / "bad";
  fs::create_directories(dir);
  const std::string bytes = readBytes(good_);
  writeBytes(dir / "truncated.binary", bytes.substr(0, bytes.size() - 8));
  std::string dimensions = bytes;
  const std::int32_t ninety = 90;
  std::memcpy(dimensions.data() + 8, &ninety, 4);  // 90 90 90
  writeBytes(dir / "dimensions.binary", dimensions);
  std::string nan = bytes;
  const double notANumber = std::nan("");
  std::memcpy(nan.data() + 12 + 8 * 1000, &notANumber, 8);
  writeBytes(dir / "nan.binary", nan);
  std::string missing = bytes;
  const double minusOne = -1.0;
  for (std::size_t at = 12; at + 8 <= missing.size(); at += 8) std::memcpy(missing.data() + at, &minusOne, 8);
  writeBytes(dir / "missing.binary", missing);
  // Finite as doubles, beyond what f may be (1e42 used to become inf on the device; 1e30 overflows a lit sample).
  for (const double value : {1e300, 1e42, 1e30}) {
    std::string huge = bytes;
    std::memcpy(huge.data() + 12 + 8 * 2000, &value, 8);
    char name[32];
    std::snprintf(name, sizeof name, "huge%g.binary", value);
    writeBytes(dir / name, huge);
  }
  fs::create_directories(dir / "folder.binary");
  struct Case {
    std::string file;
    std::string mentions;
  };
  const Case cases[] = {
      {(dir / "truncated.binary").string(), "truncated"},
      {(dir / "dimensions.binary").string(), "dimensions 90 90 90"},
      {(dir / "nan.binary").string(), "NaN or infinite"},
      {(dir / "missing.binary").string(), "every sample is missing"},
      {(dir / "huge1e+300.binary").string(), "f above 1e+20 /sr"},
      {(dir / "huge1e+42.binary").string(), "index 2000: 6.66666667e+38"},
      {(dir / "huge1e+30.binary").string(), "f above 1e+20 /sr"},
      {(dir / "folder.binary").string(), "is a directory"},
      {"/dev/zero", "not a regular file"},
      {(dir / "absent.binary").string(), "no such file"},
  };
  const fs::path out = dir / "image.exr", json = dir / "fit.json";
  for (const Case& c : cases) {
    const CommandResult render = runRaylab({"render", "--material", "phong=measured:file=" + c.file, "--out",
                                            out.string(), "--spp", "1", "--width", "8", "--height", "8"});
    EXPECT_NE(render.exitCode, 0) << c.file;
    EXPECT_NE(render.exitCode, -1) << c.file << ": crashed";
    EXPECT_NE(render.output.find(c.file), std::string::npos) << render.output;
    EXPECT_NE(render.output.find(c.mentions), std::string::npos) << render.output;
    EXPECT_FALSE(fs::exists(out)) << c.file;
    const CommandResult fit = runRaylab({"brdf", "fit", c.file, "--json", json.string()});
    EXPECT_NE(fit.exitCode, 0) << c.file;
    EXPECT_NE(fit.exitCode, -1) << c.file << ": crashed";
    EXPECT_FALSE(fs::exists(json)) << c.file;
  }
  // A file outside the scene's folder, named by a glTF (like every URI).
  fs::copy_file(good_, dir / "outside.binary", fs::copy_options::overwrite_existing);
  const CommandResult outside = runRaylab({"render", sceneWithFile(dir / "scene", "../outside.binary").string(),
                                           "--out", out.string(), "--spp", "1", "--width", "8", "--height", "8"});
  EXPECT_NE(outside.exitCode, 0);
  EXPECT_NE(outside.output.find("outside the scene's directory"), std::string::npos) << outside.output;
  EXPECT_FALSE(fs::exists(out));
  // A measured material without its file, and a file parameter given a number.
  for (const std::string& material : {std::string("phong=measured"), std::string("phong=measured:file=3")}) {
    const CommandResult none = runRaylab({"render", "--material", material, "--out", out.string(), "--spp", "1",
                                          "--width", "8", "--height", "8"});
    EXPECT_NE(none.exitCode, 0) << material;
    EXPECT_FALSE(fs::exists(out)) << material;
  }
}

TEST_F(MeasuredCliTest, FitRanksTheTabulatedModelFirstAndWritesJson) {
  const fs::path json = scratch() / "fit.json";
  const CommandResult fit =
      runRaylab({"brdf", "fit", good_.string(), "--models", "ward,cooktorrance", "--starts", "1", "--json", json.string()});
  ASSERT_EQ(fit.exitCode, 0) << fit.output;
  const std::string text = readBytes(json);
  EXPECT_LT(text.find("\"cooktorrance\""), text.find("\"ward\"")) << text;
  EXPECT_NE(text.find("\"params\""), std::string::npos);
  EXPECT_NE(fit.output.find("1    cooktorrance"), std::string::npos) << fit.output;
  EXPECT_NE(fit.output.find("starts"), std::string::npos) << "a progress line";
  // A CSV target that is also the JSON output (renamed .json): refused, the target untouched.
  const fs::path samples = scratch() / "samples.json";
  writeBytes(samples, "wi_x,wi_y,wi_z,wo_x,wo_y,wo_z,f_r,f_g,f_b\n0,0,1,0,0,1,0.1,0.1,0.1\n");
  const CommandResult same = runRaylab({"brdf", "fit", samples.string(), "--json", samples.string()});
  EXPECT_EQ(same.exitCode, 2) << same.output;
  EXPECT_NE(readBytes(samples).find("wi_x"), std::string::npos) << "the target was overwritten";
  const CommandResult bad = runRaylab({"brdf", "fit", good_.string(), "--models", "glass"});
  EXPECT_EQ(bad.exitCode, 2) << "a model that cannot be fitted is a usage error";
  EXPECT_NE(bad.output.find("is not a model that can be fitted"), std::string::npos) << bad.output;
}

// A scene or CSV may use at most 7 measured files (the device tables' limit): the 8th is refused before it is read
// (40 files used to cost 1.4 GiB before the refusal), and hard links to one file are one file, read once.
TEST_F(MeasuredCliTest, FilesBeyondTheLimitAreRefusedBeforeTheyAreReadAndLinksAreOneFile) {
  const fs::path dir = scratch() / "limit";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string header = "id,model,params,wi,wo,n,t\n";
  const std::string directions = ",0.5 0 0.866025,-0.3 0.2 0.932738,0 0 1,1 0 0\n";
  std::string links = header, distinct = header;
  for (int i = 0; i < 40; ++i) {
    const std::string name = "link" + std::to_string(i) + ".binary";
    fs::create_hard_link(good_, dir / name);
    links += "l" + std::to_string(i) + ",measured,file=" + name + directions;
  }
  for (int i = 0; i < 12; ++i) {
    // Not MERL files: the first 7 are read and refused as such; the rest must not be read at all.
    const std::string name = "other" + std::to_string(i) + ".binary";
    writeBytes(dir / name, "abc");
    distinct += "d" + std::to_string(i) + ",measured,file=" + name + directions;
  }
  writeBytes(dir / "links.csv", links);
  writeBytes(dir / "distinct.csv", distinct);
  const CommandResult linked = runRaylab({"brdf", "eval", "--in", (dir / "links.csv").string(), "--out",
                                          (dir / "links_out.csv").string()});
  EXPECT_EQ(linked.exitCode, 0) << linked.output;
  const CommandResult many = runRaylab({"brdf", "eval", "--in", (dir / "distinct.csv").string(), "--out",
                                        (dir / "distinct_out.csv").string()});
  EXPECT_NE(many.exitCode, 0);
  for (int i = 0; i < 12; ++i) {
    const std::string name = "other" + std::to_string(i) + ".binary";
    const std::size_t at = many.output.find(name);
    ASSERT_NE(at, std::string::npos) << many.output;
    const std::string line = many.output.substr(at, many.output.find('\n', at) - at);
    EXPECT_EQ(line.find("would use more than 7 measured files") != std::string::npos, i >= 7) << line;
  }
}

// A MERL phi_d = 90 slice of a Lambertian 0.3 (f = 0.3 / pi in every bin), or of `value` at one bin.
std::string lambertSlice(float bad = 0.0f, std::size_t at = std::size_t(-1)) {
  std::string bytes(90 * 90 * 3 * sizeof(float), '\0');
  for (std::size_t i = 0; i < 90 * 90 * 3; ++i) {
    const float f = i == at ? bad : float(0.3 / 3.14159265358979323846);
    std::memcpy(bytes.data() + i * sizeof f, &f, sizeof f);
  }
  return bytes;
}

TEST(MeasuredCli, ASliceIsATargetAndABadOneIsAUsageError) {
  const fs::path dir = scratch();
  const fs::path slice = dir / "lambert.slice", json = dir / "slice_fit.json";
  writeBytes(slice, lambertSlice());
  const CommandResult fit =
      runRaylab({"brdf", "fit", slice.string(), "--models", "cooktorrance,lambert", "--json", json.string()});
  ASSERT_EQ(fit.exitCode, 0) << fit.output;
  // What the target holds, before fitting.
  EXPECT_NE(fit.output.find("6401 samples"), std::string::npos) << fit.output;
  EXPECT_NE(fit.output.find("decades"), std::string::npos) << fit.output;
  EXPECT_NE(fit.output.find("isotropic (x and y parameters tied)"), std::string::npos) << fit.output;
  EXPECT_NE(fit.output.find("1    lambert"), std::string::npos) << "a tie goes to the simpler model\n" << fit.output;
  EXPECT_NE(fit.output.find("m is not constrained"), std::string::npos) << fit.output;
  const std::string text = readBytes(json);
  EXPECT_NE(text.find("\"isotropic\": true"), std::string::npos) << text;
  EXPECT_NE(text.find("\"warnings\""), std::string::npos) << text;

  const auto refused = [&](const std::string& name, const std::string& bytes, const std::string& says) {
    writeBytes(dir / name, bytes);
    fs::remove(json);
    const CommandResult r = runRaylab({"brdf", "fit", (dir / name).string(), "--json", json.string()});
    EXPECT_EQ(r.exitCode, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find(name), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(json)) << name;
  };
  refused("short.slice", lambertSlice().substr(0, 4000), "holds 4000 bytes");
  refused("nan.slice", lambertSlice(NAN, 4), "theta_d row 0, theta_h column 1, green is NaN");
  refused("inf.slice", lambertSlice(INFINITY, 2), "is inf");
  refused("negative.slice", lambertSlice(-1.0f, 0), "negative");
  refused("zeros.slice", std::string(90 * 90 * 3 * sizeof(float), '\0'), "every value is zero");
  const CommandResult both = runRaylab({"brdf", "fit", slice.string(), "--isotropic", "--anisotropic"});
  EXPECT_EQ(both.exitCode, 2) << both.output;
  // measured:file=... names a material whose file is missing, not a file called "measured:file=...".
  const CommandResult material = runRaylab({"brdf", "fit", "measured:file=" + (dir / "absent.binary").string()});
  EXPECT_NE(material.exitCode, 0);
  EXPECT_EQ(material.output.find("neither"), std::string::npos) << material.output;
  EXPECT_NE(material.output.find("absent.binary"), std::string::npos) << material.output;
}

TEST_F(MeasuredCliTest, ANeuralBrdfRendersFromTheCommandLineAndFromGltfAndTabulatesOnTheMerlGrid) {
  const fs::path network = nbrdfTestPath(1);
  const fs::path out = scratch() / "neural";
  fs::create_directories(out);
  const CommandResult cli = runRaylab({"render", "--material", "phong=nbrdf:file=" + network.string(), "--out",
                                       (out / "cli.exr").string(), "--spp", "2", "--width", "32", "--height", "24"});
  EXPECT_EQ(cli.exitCode, 0) << cli.output;
  EXPECT_TRUE(fs::exists(out / "cli.exr"));
  const fs::path folder = scratch() / "neural_scene";
  fs::create_directories(folder);
  for (const char* extension : {".h5", ".json"}) {
    fs::copy_file(fs::path(network).replace_extension(extension), folder / (std::string("net") + extension),
                  fs::copy_options::overwrite_existing);
  }
  const CommandResult gltf = runRaylab({"render", sceneWithFile(folder, "net.h5", "nbrdf").string(), "--out",
                                        (out / "gltf.exr").string(), "--spp", "2", "--width", "32", "--height", "24"});
  EXPECT_EQ(gltf.exitCode, 0) << gltf.output;

  // The MERL grid of the network: the reference's f at every bin's centre, so the study fits full-3D targets too.
  const fs::path table = out / "net.binary";
  const CommandResult made = runRaylab({"brdf", "tabulate", "nbrdf:file=" + network.string(), "--out", table.string()});
  ASSERT_EQ(made.exitCode, 0) << made.output;
  const MerlTable merl = readMerl(table.string());
  const NbrdfNetwork weights = testNetwork(1);
  int checked = 0;
  for (int h = 0; h < kMerlThetaH; h += 7) {
    for (int d = 0; d < kMerlThetaD; d += 11) {
      for (int p = 0; p < kMerlPhiD; p += 13) {
        glm::dvec3 wi, wo;
        if (!merlBinCentre(h, d, p, &wi, &wo)) continue;
        const glm::dvec3 expected = nbrdfEval(weights, wi, wo);
        const std::size_t i = std::size_t(p) + std::size_t(kMerlPhiD) * (std::size_t(d) + std::size_t(kMerlThetaD) * h);
        for (int c = 0; c < 3; ++c) {
          ASSERT_NEAR(merl.stored[i + c * kMerlSamples] * kMerlScale[c], expected[c], 1e-12 * expected[c] + 1e-300);
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 500);

  // The architecture beside it is part of the file: without it the scene is refused, naming both.
  fs::remove(folder / "net.json");
  const CommandResult lonely = runRaylab({"render", sceneWithFile(folder, "net.h5", "nbrdf").string(), "--out",
                                          (out / "lonely.exr").string(), "--spp", "1", "--width", "8", "--height",
                                          "8"});
  EXPECT_NE(lonely.exitCode, 0);
  EXPECT_NE(lonely.output.find("net.h5: its architecture"), std::string::npos) << lonely.output;
  EXPECT_NE(lonely.output.find("net.json"), std::string::npos) << lonely.output;
  EXPECT_FALSE(fs::exists(out / "lonely.exr"));
}

}  // namespace
}  // namespace raylab::test
