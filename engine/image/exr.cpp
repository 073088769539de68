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
#include "util/files.h"

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


Image readExr(const std::string& path) { return decodeExr(readTextFile(path), path); }

Image decodeExr(const std::string& bytes, const std::string& label, std::uint64_t maxPixels) {
  try {
    Imf::StdISStream input;
    input.str(bytes);
    Imf::InputFile file(input);
    const Imath::Box2i window = file.header().dataWindow();
    const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
    const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
    // The header is checked before anything is allocated: a small file may claim any size.
    if (width <= 0 || height <= 0 || std::uint64_t(width) * std::uint64_t(height) > maxPixels) {
      throw Error(label + ": OpenEXR image of " + std::to_string(width) + "x" + std::to_string(height) +
                  " pixels, over the limit of " + std::to_string(maxPixels) + " pixels");
    }
    Image image(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height));
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
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(label + ": cannot read OpenEXR file: " + e.what());
  }
}

}  // namespace raylab
