// OpenEXR files through the OpenEXR library: linear float32 RGBA.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>

#include <sstream>

#include "image/image.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace raylab {

namespace {

constexpr const char* kChannels[4] = {"R", "G", "B", "A"};

}  // namespace

void writeExr(const std::string& path, const Image& image) {
  // Encoded in memory, then written with every write checked: OpenEXR's file output finishes in a destructor
  // that swallows errors, so a full disk could otherwise pass unnoticed.
  try {
    Imf::StdOSStream stream;
    Imf::Header header(static_cast<int>(image.width), static_cast<int>(image.height));
    Imf::FrameBuffer frameBuffer;
    char* base = reinterpret_cast<char*>(const_cast<float*>(image.rgba.data()));
    for (int c = 0; c < 4; ++c) {
      header.channels().insert(kChannels[c], Imf::Channel(Imf::FLOAT));
      frameBuffer.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 4 * sizeof(float),
                                                  4 * sizeof(float) * image.width));
    }
    {
      Imf::OutputFile output(stream, header);
      output.setFrameBuffer(frameBuffer);
      output.writePixels(static_cast<int>(image.height));
    }
    writeFileAtomically(path, stream.str());
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(path + ": cannot encode OpenEXR file: " + e.what());
  }
}


Image readExr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    Image image(static_cast<std::uint32_t>(window.max.x - window.min.x + 1),
                static_cast<std::uint32_t>(window.max.y - window.min.y + 1));
    Imf::FrameBuffer frameBuffer;
    char* base = reinterpret_cast<char*>(image.rgba.data()) -
                 (std::ptrdiff_t(window.min.x) + std::ptrdiff_t(window.min.y) * image.width) * 4 * sizeof(float);
    for (int c = 0; c < 4; ++c) {
      // Missing channels (an RGB file) read as 0, except alpha which defaults to 1.
      frameBuffer.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 4 * sizeof(float),
                                                  4 * sizeof(float) * image.width, 1, 1, c == 3 ? 1.0 : 0.0));
    }
    file.setFrameBuffer(frameBuffer);
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const std::exception& e) {
    throw Error(path + ": cannot read OpenEXR file: " + e.what());
  }
}

}  // namespace raylab
