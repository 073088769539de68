// Neural BRDF files (engine/measured/nbrdf.h), written by HDF5's own library in the published Keras layout
// (tests/support/nbrdf_files.h): read back weight for weight, the input encoding against the MERL reader's
// independent rotation, a network of known closed form, exact reciprocity, and every bad file refused with a
// message naming it, before any network is evaluated.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include "brdf_params/material_params.h"
#include "measured/measured_library.h"
#include "measured/merl.h"
#include "measured/nbrdf.h"
#include "support/error_text.h"
#include "support/nbrdf_files.h"
#include "util/error.h"

namespace raylab::test {
namespace {

namespace fs = std::filesystem;
using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("raylab_nbrdf_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

dvec3 randomDirection(std::mt19937_64& engine) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double cosTheta = 0.02 + 0.98 * u(engine), phi = 2.0 * kPi * u(engine);
  const double s = std::sqrt((1.0 - cosTheta) * (1.0 + cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

TEST(Nbrdf, ReadsTheWeightsHdf5WroteInTheKerasLayout) {
  const std::string path = scratch("random.h5");
  const NbrdfNetwork written = testNetwork(1);
  writeKerasFiles(path, kerasLayers(written), kerasArchitecture());
  EXPECT_EQ(readNbrdf(path).weights, written.weights);
  // The extension's case does not matter: NAME.H5 is a network too, never read as a MERL file.
  const std::string upper = scratch("RANDOM.H5");
  writeKerasFiles(upper, kerasLayers(written), kerasArchitecture());
  EXPECT_TRUE(isNbrdfPath(upper));
  EXPECT_EQ(readNbrdf(upper).weights, written.weights);
  EXPECT_FALSE(isNbrdfPath(scratch("a.binary")));
  EXPECT_FALSE(isNbrdfPath(scratch("a.h55")));
}

// The input is the MERL reader's (merl.cpp rotates by Rodrigues' formula; nbrdf.cpp by the turned components).
TEST(Nbrdf, TheInputIsTheHalfVectorAndTheFoldedDifferenceVector) {
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const double thetaH = 0.5 * kPi * u(engine) * 0.95, thetaD = 0.5 * kPi * u(engine) * 0.95;
    const double phiD = 2.0 * kPi * u(engine);
    dvec3 wi, wo;
    merlDirections(thetaH, thetaD, phiD, &wi, &wo);
    if (!(wi.z > 1e-3 && wo.z > 1e-3)) continue;
    // Turned about the normal by any phi_h: the input does not change.
    const double phiH = 2.0 * kPi * u(engine), c = std::cos(phiH), s = std::sin(phiH);
    const auto turn = [&](const dvec3& v) { return dvec3(c * v.x - s * v.y, s * v.x + c * v.y, v.z); };
    const std::array<double, kNbrdfInputs> input = nbrdfInput(turn(wi), turn(wo));
    const double folded = std::fmod(phiD, kPi);  // phi_d and phi_d + pi are one pair (reciprocity)
    const std::array<double, kNbrdfInputs> expected = {std::sin(thetaH), 0.0, std::cos(thetaH),
                                                       std::sin(thetaD) * std::cos(folded),
                                                       std::sin(thetaD) * std::sin(folded), std::cos(thetaD)};
    for (int k = 0; k < kNbrdfInputs; ++k) ASSERT_NEAR(input[k], expected[k], 1e-9) << "input " << k << " case " << i;
  }
}

// Test network 0 is f = expm1(log1p(rho / pi) + g relu(20 cos theta_h - 19)): Lambert's rho / pi away from the
// mirror direction, a lobe within 18.2 degrees of it.
TEST(Nbrdf, AKnownNetworkIsItsClosedForm) {
  const NbrdfNetwork network = testNetwork(0);
  const double rho[3] = {0.6, 0.3, 0.1}, gloss[3] = {2.0, 2.2, 2.5};
  std::mt19937_64 engine(11);
  int inLobe = 0;
  for (int i = 0; i < 5000; ++i) {
    const dvec3 wi = randomDirection(engine), wo = randomDirection(engine);
    const double cosH = glm::normalize(wi + wo).z;
    const double unit = std::max(0.0, 20.0 * cosH - 19.0);
    inLobe += unit > 0.0;
    const dvec3 f = nbrdfEval(network, wi, wo);
    for (int c = 0; c < 3; ++c) {
      const double expected = std::expm1(double(float(std::log1p(rho[c] / kPi))) + double(float(gloss[c])) * unit);
      ASSERT_NEAR(f[c], expected, 1e-12 * expected) << "channel " << c << " case " << i;
    }
  }
  EXPECT_GT(inLobe, 10);  // the lobe was reached, not only the floor
  EXPECT_EQ(nbrdfEval(network, dvec3(0, 0, 1), dvec3(1, 0, 0)), dvec3(0.0));  // at the horizon
  EXPECT_EQ(nbrdfEval(network, dvec3(0, 0, 1), dvec3(0, 0.6, -0.8)), dvec3(0.0));
}

TEST(Nbrdf, ANetworkIsExactlyReciprocalAndNeverNegative) {
  const NbrdfNetwork network = testNetwork(1);
  std::mt19937_64 engine(13);
  for (int i = 0; i < 5000; ++i) {
    const dvec3 wi = randomDirection(engine), wo = randomDirection(engine);
    const dvec3 forward = nbrdfEval(network, wi, wo), backward = nbrdfEval(network, wo, wi);
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(forward[c], backward[c], 1e-12 * std::max(1.0, forward[c])) << "case " << i;
      ASSERT_GE(forward[c], 0.0);
    }
  }
}

TEST(Nbrdf, BadFilesAreRefusedNamingTheFileAndWhatWasWrong) {
  const std::vector<KerasLayer> good = kerasLayers(testNetwork(1));
  const auto write = [&](const std::string& name, const std::vector<KerasLayer>& layers, const std::string& json) {
    const std::string path = scratch(name);
    writeKerasFiles(path, layers, json);
    return path;
  };
  const auto expectRefused = [](const std::string& path, const std::string& words) {
    const std::string message = errorOf([&] { readNbrdf(path); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << "expected '" << words << "' in: " << message;
  };

  std::vector<KerasLayer> wrongShape = good;
  wrongShape[0].kernelShape = {5, 21};
  wrongShape[0].kernel.resize(5 * 21);
  expectRefused(write("shape.h5", wrongShape, kerasArchitecture()), "is 5 x 21; the network's is 6 x 21");

  std::vector<KerasLayer> nan = good;
  nan[1].kernel[17] = std::nanf("");
  expectRefused(write("nan.h5", nan, kerasArchitecture()), "non-finite weight at index 17");

  std::string wider = kerasArchitecture();
  wider.replace(wider.find("\"units\": 21"), 11, "\"units\": 20");
  expectRefused(write("wider.h5", good, wider), "layer 1 is not Dense 21 relu");
  expectRefused(write("notjson.h5", good, "{\"class_name\": "), "not JSON");

  const std::string lonely = write("lonely.h5", good, kerasArchitecture());
  fs::remove(fs::path(lonely).replace_extension(".json"));
  expectRefused(lonely, "lonely.json");

  const std::string text = scratch("text.h5");
  std::ofstream(text) << "not an HDF5 file at all";
  std::ofstream(fs::path(text).replace_extension(".json")) << kerasArchitecture();
  expectRefused(text, "not an HDF5 file");

  // Cut short: the signature is there, the rest is missing.
  const std::string whole = write("whole.h5", good, kerasArchitecture());
  std::string bytes(fs::file_size(whole) / 3, '\0');
  std::ifstream(whole, std::ios::binary).read(bytes.data(), std::streamsize(bytes.size()));
  const std::string cut = scratch("cut.h5");
  std::ofstream(cut, std::ios::binary) << bytes;
  fs::copy_file(fs::path(whole).replace_extension(".json"), fs::path(cut).replace_extension(".json"),
                fs::copy_options::overwrite_existing);
  EXPECT_NE(errorOf([&] { readNbrdf(cut); }).find(cut), std::string::npos);

  // Not regular files: a FIFO would hang a reader that opened it, a directory is a mistake.
  const std::string fifo = scratch("fifo.h5");
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::ofstream(fs::path(fifo).replace_extension(".json")) << kerasArchitecture();
  expectRefused(fifo, "not a regular file");
  const std::string folder = scratch("folder.h5");
  fs::create_directories(folder);
  expectRefused(folder, "directory");

  const std::string huge = scratch("huge.h5");
  fs::resize_file(write("huge.h5", good, kerasArchitecture()), kMaxNbrdfWeightBytes + 1);
  expectRefused(huge, "bytes");
}

// A file parameter takes only its own kind: a network is not a MERL table, and the message says which model
// renders it.
TEST(Nbrdf, EachModelTakesOnlyItsOwnKindOfFile) {
  const std::string network = nbrdfTestPath(0);
  gpu::MaterialRecord measured = defaultRecord(modelId("measured"));
  const std::string wrong = errorOf([&] { setFileParam(measured, "file", network, "scene.gltf: material 'm'"); });
  EXPECT_NE(wrong.find("neural BRDF"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("model nbrdf"), std::string::npos) << wrong;
  gpu::MaterialRecord nbrdf = defaultRecord(modelId("nbrdf"));
  EXPECT_NO_THROW(setFileParam(nbrdf, "file", network, "test"));
  const std::string merl = scratch("a.binary");
  const std::string other = errorOf([&] { setFileParam(nbrdf, "file", merl, "test"); });
  EXPECT_NE(other.find("model measured"), std::string::npos) << other;
  // A copied id is checked too.
  EXPECT_NE(errorOf([&] { setParam(measured, "file", glm::vec3(nbrdf.params[0]), "copy"); }).find("neural BRDF"),
            std::string::npos);
}

// A scene may name more networks than MERL files (4 KB each against 17 MiB), up to the directory's 64, refused
// before the file beyond is read.
TEST(Nbrdf, AScenesFilesAreBoundedByTheTablesDirectory) {
  const MeasuredFileLimit limit("scene.gltf");
  const std::vector<KerasLayer> layers = kerasLayers(testNetwork(1));
  std::string message;
  for (std::size_t i = 0; i <= kMaxFilesPerScene && message.empty(); ++i) {
    const std::string path = scratch("many" + std::to_string(i) + ".h5");
    writeKerasFiles(path, layers, kerasArchitecture());
    if (i == kMaxFilesPerScene) fs::resize_file(path, 10);  // refused before reading: never read, never damaged
    message = errorOf([&] { loadMeasured(path); });
    if (i < kMaxFilesPerScene) {
      ASSERT_EQ(message, "") << "file " << i;
    }
  }
  EXPECT_NE(message.find("more than 64 measured and neural BRDF files"), std::string::npos) << message;
  // Networks stay in memory (19 KB each): the bound on resident tables is for MERL's 33 MiB ones.
  EXPECT_GE(residentMeasuredFiles(), kMaxFilesPerScene);
}

}  // namespace
}  // namespace raylab::test
