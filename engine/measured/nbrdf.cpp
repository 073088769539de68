#include "measured/nbrdf.h"

#include <hdf5.h>
#include <nlohmann/json.hpp>
#if defined(__has_include)
#if __has_include(<sanitizer/common_interface_defs.h>)
#include <sanitizer/common_interface_defs.h>
#endif
#endif

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <vector>

#include "shared/brdf_tables.h"
#include "util/error.h"
#include "util/files.h"

namespace raylab {

namespace {

constexpr std::string_view kHdf5Signature = "\x89HDF\r\n\x1a\n";
constexpr std::size_t kMaxAttributeStrings = 64;
constexpr std::size_t kMaxAttributeStringBytes = 256;

// One HDF5 handle, closed when it goes out of scope.
struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  Handle(hid_t handle, herr_t (*closeFunction)(hid_t)) : id(handle), close(closeFunction) {}
  ~Handle() {
    if (id >= 0) close(id);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
};

// The library is built thread-safe on Debian, but its error stack and the in-memory file driver are cheaper to
// reason about one call at a time; the files are small.
std::mutex& hdf5Mutex() {
  static std::mutex mutex;
  return mutex;
}

// A fixed-length string array attribute, as Keras writes its layer and weight names.
std::vector<std::string> stringAttribute(hid_t object, const char* name, const std::string& where) {
  if (H5Aexists(object, name) <= 0) throw Error(where + ": no '" + name + "' attribute: not a Keras weight file");
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  const Handle type(H5Aget_type(attribute.id), H5Tclose);
  const Handle space(H5Aget_space(attribute.id), H5Sclose);
  if (attribute.id < 0 || type.id < 0 || space.id < 0 || H5Tget_class(type.id) != H5T_STRING ||
      H5Tis_variable_str(type.id) != 0) {
    throw Error(where + ": its '" + name + "' attribute is not an array of fixed-length strings");
  }
  const std::size_t size = H5Tget_size(type.id);
  const hssize_t count = H5Sget_simple_extent_npoints(space.id);
  if (size == 0 || size > kMaxAttributeStringBytes || count < 1 || std::size_t(count) > kMaxAttributeStrings) {
    throw Error(where + ": its '" + name + "' attribute holds " + std::to_string(count) + " strings of " +
                std::to_string(size) + " bytes; expected at most " + std::to_string(kMaxAttributeStrings) + " of " +
                std::to_string(kMaxAttributeStringBytes));
  }
  std::string buffer(size * std::size_t(count), '\0');
  if (H5Aread(attribute.id, type.id, buffer.data()) < 0) {
    throw Error(where + ": its '" + name + "' attribute is unreadable");
  }
  std::vector<std::string> strings;
  for (hssize_t i = 0; i < count; ++i) {
    std::string text = buffer.substr(std::size_t(i) * size, size);
    text.erase(std::find(text.begin(), text.end(), '\0'), text.end());
    strings.push_back(text);
  }
  return strings;
}

// A float dataset of exactly `shape`, every value finite.
std::vector<float> floatDataset(hid_t file, const std::string& name, const std::vector<hsize_t>& shape,
                                const std::string& where) {
  if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) throw Error(where + ": no dataset '" + name + "'");
  const Handle dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
  const Handle type(H5Dget_type(dataset.id), H5Tclose);
  const Handle space(H5Dget_space(dataset.id), H5Sclose);
  if (dataset.id < 0 || type.id < 0 || space.id < 0 || H5Tget_class(type.id) != H5T_FLOAT) {
    throw Error(where + ": dataset '" + name + "' is not floating point");
  }
  std::vector<hsize_t> dims(std::size_t(std::max(0, H5Sget_simple_extent_ndims(space.id))));
  if (dims.size() > 8 || H5Sget_simple_extent_dims(space.id, dims.data(), nullptr) < 0 || dims != shape) {
    const auto text = [](const std::vector<hsize_t>& d) {
      std::string t;
      for (hsize_t n : d) t += (t.empty() ? "" : " x ") + std::to_string(n);
      return t.empty() ? std::string("a scalar") : t;
    };
    throw Error(where + ": dataset '" + name + "' is " + text(dims) + "; the network's is " + text(shape));
  }
  std::size_t count = 1;
  for (hsize_t n : shape) count *= std::size_t(n);
  std::vector<float> values(count);
  if (H5Dread(dataset.id, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    throw Error(where + ": dataset '" + name + "' is unreadable");
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw Error(where + ": dataset '" + name + "' has a non-finite weight at index " + std::to_string(i));
    }
  }
  return values;
}

// Members of the architecture's JSON read by their type: a member of another type reads as absent, so that JSON of the
// wrong shape is refused with a message (nlohmann's value() throws its own exception there; fuzzing found it).
std::string textOf(const nlohmann::json& object, const char* key) {
  const auto at = object.find(key);
  return at != object.end() && at->is_string() ? at->get<std::string>() : std::string();
}

std::int64_t integerOf(const nlohmann::json& object, const char* key) {
  const auto at = object.find(key);
  return at != object.end() && at->is_number_integer() ? at->get<std::int64_t>() : -1;
}

bool isTrue(const nlohmann::json& object, const char* key) {
  const auto at = object.find(key);
  return at != object.end() && at->is_boolean() && at->get<bool>();
}

// The architecture: a Keras Sequential of Dense 6 -> 21 relu, Dense 21 relu, Dense 3 linear, then the Lambda
// (the published exp(x) - 1, stored as Python bytecode, which is not read). Returns the layers' names.
std::vector<std::string> checkArchitecture(const std::string& text, const std::string& where) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  const auto refuse = [&](const std::string& what) -> std::vector<std::string> {
    throw Error(where + ": " + what + "; expected the published network (Keras Sequential: Dense 6 -> 21 relu, "
                "Dense 21 relu, Dense 3 linear, Lambda)");
  };
  if (json.is_discarded()) return refuse("not JSON");
  if (!json.is_object() || textOf(json, "class_name") != "Sequential") return refuse("not a Keras Sequential model");
  const nlohmann::json* layers = nullptr;
  if (const auto config = json.find("config"); config != json.end()) {
    if (config->is_array()) layers = &*config;
    else if (config->is_object() && config->contains("layers")) layers = &(*config)["layers"];
  }
  if (layers == nullptr || !layers->is_array() || layers->size() != 4) return refuse("not four layers");
  const struct {
    int units;
    const char* activation;
  } dense[3] = {{kNbrdfHidden, "relu"}, {kNbrdfHidden, "relu"}, {kNbrdfOutputs, "linear"}};
  std::vector<std::string> names;
  for (std::size_t i = 0; i < 4; ++i) {
    const nlohmann::json& layer = (*layers)[i];
    const std::string number = std::to_string(i + 1);
    if (!layer.is_object() || !layer.contains("config") || !layer["config"].is_object()) {
      return refuse("layer " + number + " has no config");
    }
    const nlohmann::json& config = layer["config"];
    const std::string name = textOf(config, "name"), kind = textOf(layer, "class_name");
    if (i == 3) {
      if (kind != "Lambda") return refuse("layer 4 is " + (kind.empty() ? "unnamed" : kind) + ", not the Lambda");
      names.push_back(name);
      break;
    }
    const bool ok = kind == "Dense" && integerOf(config, "units") == dense[i].units &&
                    textOf(config, "activation") == dense[i].activation && isTrue(config, "use_bias");
    if (!ok) {
      return refuse("layer " + number + " is not Dense " + std::to_string(dense[i].units) + " " + dense[i].activation +
                    " with a bias");
    }
    if (i == 0) {
      const auto shape = config.find("batch_input_shape");
      if (shape == config.end() || !shape->is_array() || shape->size() != 2 || !(*shape)[1].is_number_integer() ||
          (*shape)[1].get<std::int64_t>() != kNbrdfInputs) {
        return refuse("the input is not 6 wide");
      }
    }
    names.push_back(name);
  }
  return names;
}

// The weights from the HDF5 file's bytes, in this process (readWeightsIsolated runs it in a child).
NbrdfNetwork readWeights(const std::string& weightBytes, const std::vector<std::string>& layerNames,
                         const std::string& where) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become this function's messages, not prints on stderr
  // The file is opened from the bytes already read (and bounded), never from its path.
  const Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (access.id < 0 || H5Pset_fapl_core(access.id, 64 << 10, 0) < 0 ||
      H5Pset_file_image(access.id, const_cast<char*>(weightBytes.data()), weightBytes.size()) < 0) {
    throw Error(where + ": HDF5 could not take the file's bytes");
  }
  const Handle file(H5Fopen("nbrdf.h5", H5F_ACC_RDONLY, access.id), H5Fclose);
  if (file.id < 0) throw Error(where + ": HDF5 cannot open it (damaged or not an HDF5 file)");
  const std::vector<std::string> stored = stringAttribute(file.id, "layer_names", where);
  if (stored.size() != 4 || !std::equal(stored.begin(), stored.begin() + 3, layerNames.begin())) {
    throw Error(where + ": its layers are not the .json's (" + std::to_string(stored.size()) + " layers)");
  }
  const std::vector<hsize_t> shapes[3][2] = {
      {{hsize_t(kNbrdfInputs), hsize_t(kNbrdfHidden)}, {hsize_t(kNbrdfHidden)}},
      {{hsize_t(kNbrdfHidden), hsize_t(kNbrdfHidden)}, {hsize_t(kNbrdfHidden)}},
      {{hsize_t(kNbrdfHidden), hsize_t(kNbrdfOutputs)}, {hsize_t(kNbrdfOutputs)}}};
  NbrdfNetwork network;
  std::size_t at = 0;
  for (int layer = 0; layer < 3; ++layer) {
    const std::string& name = stored[std::size_t(layer)];
    if (H5Lexists(file.id, name.c_str(), H5P_DEFAULT) <= 0) throw Error(where + ": no group for layer '" + name + "'");
    const Handle group(H5Gopen2(file.id, name.c_str(), H5P_DEFAULT), H5Gclose);
    if (group.id < 0) throw Error(where + ": layer '" + name + "' is not a group");
    const std::vector<std::string> weights = stringAttribute(group.id, "weight_names", where + ", layer " + name);
    if (weights.size() != 2 || !weights[0].ends_with("kernel:0") || !weights[1].ends_with("bias:0")) {
      throw Error(where + ": layer '" + name + "' does not hold a kernel and a bias");
    }
    for (int part = 0; part < 2; ++part) {
      const std::vector<float> values =
          floatDataset(file.id, name + "/" + weights[std::size_t(part)], shapes[layer][part], where);
      std::copy(values.begin(), values.end(), network.weights.begin() + std::ptrdiff_t(at));
      at += values.size();
    }
  }
  return network;
}

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAYLAB_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define RAYLAB_SANITIZED 1
#endif

// In a sanitizer build (the fuzz preset), the child's report on a damaged file is libhdf5's, not raylab's: the child
// dies quietly with exit status 3, and the fuzzer (whose death handler it inherited) records no crash of its own.
void quietSanitizerDeath() {
#ifdef RAYLAB_SANITIZED
  __sanitizer_set_death_callback([] { ::_exit(3); });
  const int devNull = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (devNull >= 0) ::dup2(devNull, STDERR_FILENO);
#endif
}

// libhdf5 1.10 is not safe on damaged files: fuzzing found a heap over-read inside H5Aexists on a corrupted
// attribute message, and HDF5's bug tracker lists crashes and hangs of the same kind. So the file is read in a child
// process, which hands back the weights or the message through a pipe: a file that crashes or hangs HDF5 costs the
// child, never raylab, and is refused as damaged. The HDF5 lock is held across fork(), so that no other thread of
// this process is inside HDF5 when the child starts.
NbrdfNetwork readWeightsIsolated(const std::string& weightBytes, const std::vector<std::string>& layerNames,
                                 const std::string& where) {
  constexpr int kChildSeconds = 10;
  constexpr std::size_t kMaxMessage = 4096;
  const std::lock_guard lock(hdf5Mutex());
  int pipeEnds[2];
  if (::pipe2(pipeEnds, O_CLOEXEC) != 0) throw Error(where + ": cannot create a pipe to read it");
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(pipeEnds[0]);
    ::close(pipeEnds[1]);
    throw Error(where + ": cannot start the process that reads it");
  }
  if (child == 0) {
    ::close(pipeEnds[0]);
    quietSanitizerDeath();
    std::string reply;
    try {
      const NbrdfNetwork network = readWeights(weightBytes, layerNames, where);
      reply = "W" + std::string(reinterpret_cast<const char*>(network.weights.data()), sizeof(network.weights));
    } catch (const std::exception& error) {
      reply = "E" + std::string(error.what()).substr(0, kMaxMessage);
    }
    for (std::size_t done = 0; done < reply.size();) {
      const ssize_t n = ::write(pipeEnds[1], reply.data() + done, reply.size() - done);
      if (n <= 0) ::_exit(1);
      done += std::size_t(n);
    }
    ::_exit(0);
  }
  ::close(pipeEnds[1]);
  std::string reply;
  char buffer[4096];
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kChildSeconds);
  bool timedOut = false;
  for (;;) {
    using std::chrono::milliseconds;
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd readable{pipeEnds[0], POLLIN, 0};
    const int ready = left.count() > 0 ? ::poll(&readable, 1, int(left.count())) : 0;
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) {
      timedOut = true;
      break;
    }
    const ssize_t n = ::read(pipeEnds[0], buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    reply.append(buffer, std::size_t(n));
    if (reply.size() > 1 + kMaxMessage + sizeof(NbrdfNetwork::weights)) break;
  }
  ::close(pipeEnds[0]);
  if (timedOut) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (timedOut) {
    throw Error(where + ": HDF5 did not finish reading it in " + std::to_string(kChildSeconds) + " s (a damaged file)");
  }
  if (WIFSIGNALED(status)) {
    throw Error(where + ": HDF5 failed on it (signal " + std::to_string(WTERMSIG(status)) + "): a damaged file");
  }
  if (!reply.empty() && reply[0] == 'E') throw Error(reply.substr(1));
  NbrdfNetwork network;
  if (reply.size() != 1 + sizeof(network.weights) || reply[0] != 'W') {
    throw Error(where + ": its reader gave no answer");
  }
  std::memcpy(network.weights.data(), reply.data() + 1, sizeof(network.weights));
  return network;
}

}  // namespace

// Whatever the case of the extension (NAME.H5 too): a network named as a MERL file would be read as one.
bool isNbrdfPath(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  return extension.size() == 3 && extension[0] == '.' && (extension[1] == 'h' || extension[1] == 'H') &&
         extension[2] == '5';
}

NbrdfNetwork decodeNbrdf(const std::string& weightBytes, const std::string& architectureText,
                         const std::string& where) {
  const std::vector<std::string> layerNames = checkArchitecture(architectureText, where + " (its .json)");
  if (!std::string_view(weightBytes).starts_with(kHdf5Signature)) {
    throw Error(where + ": not an HDF5 file (no HDF5 signature at its start)");
  }
  return readWeightsIsolated(weightBytes, layerNames, where);
}

NbrdfNetwork readNbrdf(const std::string& path) {
  if (!isNbrdfPath(path)) throw Error(path + ": a neural BRDF is a Keras .h5 file (with its .json beside it)");
  const std::string weights = readInputFile(path, kMaxNbrdfWeightBytes);
  std::string architecture;
  try {
    architecture =
        readInputFile(std::filesystem::path(path).replace_extension(".json").string(), kMaxNbrdfArchitectureBytes);
  } catch (const FileError& error) {
    throw FileError(path + ": its architecture, " + error.what() + " (a Keras .h5 comes with its .json)",
                    error.problem());
  }
  return decodeNbrdf(weights, architecture, path);
}

void writeNbrdfDeviceLayout(const NbrdfNetwork& network, float* out) {
  static_assert(gpu::kNbrdfInputs == kNbrdfInputs && gpu::kNbrdfHidden == kNbrdfHidden &&
                gpu::kNbrdfOutputs == kNbrdfOutputs);
  constexpr int h = kNbrdfHidden, o = kNbrdfOutputs, n = kNbrdfInputs;
  const float* w1 = network.weights.data();
  const float* b1 = w1 + n * h;
  const float* w2 = b1 + h;
  const float* b2 = w2 + h * h;
  const float* w3 = b2 + h;
  const float* b3 = w3 + h * o;
  static_assert(gpu::kNbrdfTailVec4s * 4 >= kNbrdfHidden + kNbrdfHidden * kNbrdfOutputs + kNbrdfOutputs);
  std::fill(out, out + 4 * gpu::kNbrdfNetwork4, 0.0f);
  for (int i = 0; i < h; ++i) {
    float* unit = out + 4 * (gpu::kNbrdfUnits4 + gpu::kNbrdfUnitVec4s * i);
    for (int k = 0; k < 4; ++k) unit[k] = w1[k * h + i];
    for (int j = 0; j < h; ++j) unit[4 + j] = w2[i * h + j];  // 21 weights: five vec4s and the seventh's x
    unit[4 + h] = w1[4 * h + i];
    unit[5 + h] = w1[5 * h + i];
    unit[6 + h] = b1[i];
  }
  float* tail = out + 4 * gpu::kNbrdfTail4;
  std::copy(b2, b2 + h, tail);
  std::copy(w3, w3 + h * o, tail + h);
  std::copy(b3, b3 + o, tail + h + h * o);
}

std::array<double, kNbrdfInputs> nbrdfInput(const glm::dvec3& wi, const glm::dvec3& wo) {
  const glm::dvec3 h = glm::normalize(wi + wo);
  const double sinH = std::hypot(h.x, h.y);
  // wi turned by -phi_h about n, then by -theta_h about the bitangent (Rusinkiewicz's difference vector).
  const glm::dvec2 cs = sinH > 0.0 ? glm::dvec2(h.x, h.y) / sinH : glm::dvec2(1.0, 0.0);
  const glm::dvec3 turned(wi.x * cs.x + wi.y * cs.y, wi.y * cs.x - wi.x * cs.y, wi.z);
  glm::dvec3 d(turned.x * h.z - turned.z * sinH, turned.y, turned.x * sinH + turned.z * h.z);
  if (d.y < 0.0) d = glm::dvec3(-d.x, -d.y, d.z);  // phi_d + pi -> phi_d (nbrdf.h)
  return {sinH, 0.0, h.z, d.x, d.y, d.z};
}

glm::dvec3 nbrdfEval(const NbrdfNetwork& network, const glm::dvec3& wi, const glm::dvec3& wo) {
  if (!(wi.z > 0.0 && wo.z > 0.0)) return glm::dvec3(0.0);
  const std::array<double, kNbrdfInputs> input = nbrdfInput(wi, wo);
  const float* w = network.weights.data();
  // One dense layer: out[j] = sum_i in[i] kernel[i][j] + bias[j], the kernel row-major (inputs x outputs).
  const auto dense = [&w](const double* in, int inputs, double* out, int outputs, bool relu) {
    const float* kernel = w;
    const float* bias = w + inputs * outputs;
    for (int j = 0; j < outputs; ++j) {
      double sum = bias[j];
      for (int i = 0; i < inputs; ++i) sum += in[i] * double(kernel[i * outputs + j]);
      out[j] = relu ? std::max(sum, 0.0) : sum;
    }
    w = bias + outputs;
  };
  std::array<double, kNbrdfHidden> first{}, second{};
  std::array<double, kNbrdfOutputs> last{};
  dense(input.data(), kNbrdfInputs, first.data(), kNbrdfHidden, true);
  dense(first.data(), kNbrdfHidden, second.data(), kNbrdfHidden, true);
  dense(second.data(), kNbrdfHidden, last.data(), kNbrdfOutputs, false);
  // The published mapping exp(x) - 1 reaches down to -1; a BRDF is not negative (the authors' renderer clamps too).
  return glm::max(glm::dvec3(std::expm1(last[0]), std::expm1(last[1]), std::expm1(last[2])), glm::dvec3(0.0));
}

}  // namespace raylab
