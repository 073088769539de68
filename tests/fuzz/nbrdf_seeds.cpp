// Writes the neural-BRDF fuzz target's seeds into the folder named on the command line, at build time: a network of
// seeded random weights written by HDF5 in the published Keras layout (tests/support/nbrdf_files.h), and its first
// 4 KiB. Generated, not committed: the project commits no BRDF data files.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/nbrdf_files.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SEED_FOLDER\n", argv[0]);
    return 2;
  }
  const std::filesystem::path folder(argv[1]);
  std::filesystem::create_directories(folder);
  const std::string random = (folder / "random.h5").string();
  raylab::test::writeKerasFiles(random, raylab::test::kerasLayers(raylab::test::testNetwork(1)),
                                raylab::test::kerasArchitecture());
  std::filesystem::remove(folder / "random.json");  // the target reads the weights alone, with its own architecture
  std::ifstream in(random, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(folder / "truncated.h5", std::ios::binary).write(bytes.data(), std::streamsize(std::min<std::size_t>(bytes.size(), 4096)));
  return in ? 0 : 1;
}
