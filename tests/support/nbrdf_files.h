// Neural BRDF files for the tests, written in the published layout (Keras .h5 weights through HDF5, .json
// architecture beside them) from networks made here: the published files are optional data
// (../shared/measured/nbrdf), and a reader is only tested by files it did not write itself if the bytes come
// from a real writer. HDF5's own library writes them, as Keras does.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "measured/nbrdf.h"

namespace raylab::test {

// 0: a glossy lobe in theta_h over a diffuse floor, f = expm1(log1p(rho/pi) + g relu(20 cos theta_h - 19))
//    (closed form, docs/brdfs.md); 1: seeded random weights that read every input (the difference vector too).
NbrdfNetwork testNetwork(int which);

// One Dense layer as the .h5 holds it: its group's name and each dataset's shape and values.
struct KerasLayer {
  std::string name;
  std::vector<unsigned long long> kernelShape, biasShape;
  std::vector<float> kernel, bias;
};
// The three Dense layers of `network`, named dense_1 to dense_3.
std::vector<KerasLayer> kerasLayers(const NbrdfNetwork& network);
// The published architecture (.json) for layers named dense_1 to dense_3 and lambda_1.
std::string kerasArchitecture();
// Writes `layers` to `path` (.h5) as Keras 2.2 saves weights, and `architecture` beside it (.json).
void writeKerasFiles(const std::string& path, const std::vector<KerasLayer>& layers, const std::string& architecture);

// The path of test network `which`, written on first use (per process), and its id, loaded on first use.
std::string nbrdfTestPath(int which);
std::uint32_t nbrdfTestFile(int which);

}  // namespace raylab::test
