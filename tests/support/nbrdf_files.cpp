#include "support/nbrdf_files.h"

#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>
#include <stdexcept>

#include "measured/measured_library.h"

namespace raylab::test {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Index of kernel element (input i, output j) and of bias j of layer l in NbrdfNetwork::weights.
constexpr int kWidths[4] = {kNbrdfInputs, kNbrdfHidden, kNbrdfHidden, kNbrdfOutputs};
std::size_t layerStart(int l) {
  std::size_t at = 0;
  for (int k = 0; k < l; ++k) at += std::size_t(kWidths[k]) * kWidths[k + 1] + kWidths[k + 1];
  return at;
}
std::size_t kernelIndex(int l, int i, int j) { return layerStart(l) + std::size_t(i) * kWidths[l + 1] + j; }
std::size_t biasIndex(int l, int j) { return layerStart(l) + std::size_t(kWidths[l]) * kWidths[l + 1] + j; }

void check(bool ok, const char* what) {
  if (!ok) throw std::runtime_error(std::string("writing a test .h5: ") + what);
}

// A fixed-length string array attribute, as Keras writes names.
void writeStrings(hid_t object, const char* name, const std::vector<std::string>& strings) {
  std::size_t size = 1;
  for (const std::string& s : strings) size = std::max(size, s.size());
  std::string buffer(size * strings.size(), '\0');
  for (std::size_t i = 0; i < strings.size(); ++i) buffer.replace(i * size, strings[i].size(), strings[i]);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, size);
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  const hsize_t count = strings.size();
  const hid_t space = H5Screate_simple(1, &count, nullptr);
  const hid_t attribute = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  check(attribute >= 0 && H5Awrite(attribute, type, buffer.data()) >= 0, name);
  H5Aclose(attribute);
  H5Sclose(space);
  H5Tclose(type);
}

void writeDataset(hid_t group, const std::string& name, const std::vector<unsigned long long>& shape,
                  const std::vector<float>& values) {
  const std::vector<hsize_t> dims(shape.begin(), shape.end());
  const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
  const hid_t set = H5Dcreate2(group, name.c_str(), H5T_IEEE_F32LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  check(set >= 0 && H5Dwrite(set, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0, name.c_str());
  H5Dclose(set);
  H5Sclose(space);
}

}  // namespace

NbrdfNetwork testNetwork(int which) {
  NbrdfNetwork network;
  auto& w = network.weights;
  if (which == 0) {
    const double rho[3] = {0.6, 0.3, 0.1}, gloss[3] = {2.0, 2.2, 2.5};
    w[kernelIndex(0, 2, 0)] = 20.0f;  // unit 0 of the first layer: 20 cos theta_h - 19
    w[biasIndex(0, 0)] = -19.0f;
    w[kernelIndex(1, 0, 0)] = 1.0f;  // passed on by unit 0 of the second layer
    for (int c = 0; c < 3; ++c) {
      w[kernelIndex(2, 0, c)] = float(gloss[c]);
      w[biasIndex(2, c)] = float(std::log1p(rho[c] / kPi));
    }
    return network;
  }
  std::mt19937 engine(20210501u);
  std::uniform_real_distribution<float> uniform(-0.5f, 0.5f);
  for (float& value : w) value = uniform(engine);
  for (int c = 0; c < 3; ++c) w[biasIndex(2, c)] = -1.0f;  // f of a few tenths, as the published networks give
  return network;
}

std::vector<KerasLayer> kerasLayers(const NbrdfNetwork& network) {
  std::vector<KerasLayer> layers;
  for (int l = 0; l < 3; ++l) {
    const auto in = static_cast<unsigned long long>(kWidths[l]), out = static_cast<unsigned long long>(kWidths[l + 1]);
    KerasLayer layer{"dense_" + std::to_string(l + 1), {in, out}, {out}, {}, {}};
    layer.kernel.assign(network.weights.begin() + std::ptrdiff_t(layerStart(l)),
                        network.weights.begin() + std::ptrdiff_t(biasIndex(l, 0)));
    layer.bias.assign(network.weights.begin() + std::ptrdiff_t(biasIndex(l, 0)),
                      network.weights.begin() + std::ptrdiff_t(biasIndex(l, 0) + kWidths[l + 1]));
    layers.push_back(layer);
  }
  return layers;
}

std::string kerasArchitecture() {
  const auto dense = [](int n, int units, const char* activation, bool first) {
    return std::string(R"({"class_name": "Dense", "config": {"name": "dense_)") + std::to_string(n) + R"(", )" +
           (first ? R"("batch_input_shape": [null, 6], )" : "") + R"("units": )" + std::to_string(units) +
           R"(, "activation": ")" + activation + R"(", "use_bias": true}})";
  };
  return R"({"class_name": "Sequential", "config": {"name": "sequential_1", "layers": [)" + dense(1, 21, "relu", true) +
         ", " + dense(2, 21, "relu", false) + ", " + dense(3, 3, "linear", false) +
         R"(, {"class_name": "Lambda", "config": {"name": "lambda_1"}}]}, )" +
         R"("keras_version": "2.2.4", "backend": "tensorflow"})";
}

void writeKerasFiles(const std::string& path, const std::vector<KerasLayer>& layers, const std::string& architecture) {
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  check(file >= 0, "create");
  std::vector<std::string> names;
  for (const KerasLayer& layer : layers) names.push_back(layer.name);
  names.push_back("lambda_1");
  writeStrings(file, "layer_names", names);
  for (const KerasLayer& layer : layers) {
    const hid_t outer = H5Gcreate2(file, layer.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    writeStrings(outer, "weight_names", {layer.name + "/kernel:0", layer.name + "/bias:0"});
    const hid_t inner = H5Gcreate2(outer, layer.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    writeDataset(inner, "kernel:0", layer.kernelShape, layer.kernel);
    writeDataset(inner, "bias:0", layer.biasShape, layer.bias);
    H5Gclose(inner);
    H5Gclose(outer);
  }
  const hid_t lambda = H5Gcreate2(file, "lambda_1", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  writeStrings(lambda, "weight_names", {""});
  H5Gclose(lambda);
  H5Fclose(file);
  std::ofstream(std::filesystem::path(path).replace_extension(".json")) << architecture;
}

std::string nbrdfTestPath(int which) {
  static std::mutex mutex;
  static std::string paths[2];
  const std::lock_guard lock(mutex);
  std::string& path = paths[which];
  if (path.empty()) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "raylab_measured_test_files";
    std::filesystem::create_directories(dir);
    // Per process: parallel test processes never write the same path.
    path = (dir / (std::to_string(::getpid()) + "_network" + std::to_string(which) + ".h5")).string();
    writeKerasFiles(path, kerasLayers(testNetwork(which)), kerasArchitecture());
  }
  return path;
}

std::uint32_t nbrdfTestFile(int which) { return loadMeasured(nbrdfTestPath(which)); }

}  // namespace raylab::test
