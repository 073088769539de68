#include "support/hostile_exr.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

namespace raylab::test {

void writeExrUnchecked(const std::string& path, const Image& image) {
  Imf::Header header(static_cast<int>(image.width), static_cast<int>(image.height));
  Imf::FrameBuffer frameBuffer;
  char* base = reinterpret_cast<char*>(const_cast<float*>(image.rgba.data()));
  const char* names[4] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    frameBuffer.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 4 * sizeof(float),
                                            4 * sizeof(float) * image.width));
  }
  Imf::OutputFile output(path.c_str(), header);
  output.setFrameBuffer(frameBuffer);
  output.writePixels(static_cast<int>(image.height));
}

}  // namespace raylab::test
