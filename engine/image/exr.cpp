// OpenEXR files through the OpenEXR library: linear float32 RGBA.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfMultiPartInputFile.h>
#include <ImfPartType.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>
#include <vector>

#include "image/image.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/files.h"

namespace raylab {

namespace {

constexpr const char* kChannels[4] = {"R", "G", "B", "A"};

// The largest ratio of decoded pixel bytes to file bytes raylab believes: zlib's limit is about 1032:1, and a
// file claiming more pixels than that could hold asks for memory its content cannot fill.
constexpr std::uint64_t kMaxCompressionRatio = 4096;

std::string channelList(const Imf::ChannelList& channels) {
  std::string names;
  for (auto c = channels.begin(); c != channels.end(); ++c) names += (names.empty() ? "" : ", ") + std::string(c.name());
  return names.empty() ? "none" : names;
}

// Which of the file's channels become R, G, B and A: "R,G,B[,A]", a single layer's "name.R,...", lower-case
// "r,g,b", or luminance "Y" as grey. Throws naming the channels found when none of these is there.
std::array<std::string, 4> chooseChannels(const Imf::ChannelList& channels, const std::string& label) {
  const auto has = [&](const std::string& name) { return channels.findChannel(name) != nullptr; };
  const auto rgbWith = [&](const std::string& prefix, bool lower) -> std::optional<std::array<std::string, 4>> {
    const std::array<std::string, 4> names = lower ? std::array<std::string, 4>{"r", "g", "b", "a"}
                                                   : std::array<std::string, 4>{"R", "G", "B", "A"};
    if (!has(prefix + names[0]) || !has(prefix + names[1]) || !has(prefix + names[2])) return std::nullopt;
    return std::array<std::string, 4>{prefix + names[0], prefix + names[1], prefix + names[2],
                                      has(prefix + names[3]) ? prefix + names[3] : ""};
  };
  if (auto plain = rgbWith("", false)) return *plain;
  if (auto lower = rgbWith("", true)) return *lower;
  std::set<std::string> layers;
  channels.layers(layers);
  std::vector<std::array<std::string, 4>> layered;
  for (const std::string& layer : layers) {
    if (auto named = rgbWith(layer + ".", false)) layered.push_back(*named);
  }
  if (layered.size() == 1) return layered[0];
  if (layered.size() > 1) {
    throw Error(label + ": OpenEXR file with several RGB layers (" + channelList(channels) +
                "); raylab reads R, G, B or a single layer's");
  }
  if (has("Y")) return {"Y", "Y", "Y", has("A") ? "A" : ""};
  throw Error(label + ": OpenEXR file without colour channels: it has " + channelList(channels) +
              "; raylab reads R, G, B (or r, g, b, one layer's NAME.R, NAME.G, NAME.B, or luminance Y)");
}

}  // namespace

void writeExr(const std::string& path, const Image& image) {
  checkFinite(image, path);
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


Image readExr(const std::string& path) { return decodeExr(readInputFile(path, kMaxImageFileBytes), path); }

Image decodeExr(const std::string& bytes, const std::string& label, std::uint64_t maxPixels,
                const std::function<void(std::uint32_t, std::uint32_t)>& checkSize) {
  try {
    Imf::StdISStream input;
    input.str(bytes);
    {
      // A multi-part file would otherwise be read as its first part, silently.
      Imf::MultiPartInputFile parts(input);
      if (parts.parts() != 1) {
        std::string names;
        for (int i = 0; i < parts.parts(); ++i) {
          const Imf::Header& header = parts.header(i);
          names += (i ? ", " : "") + (header.hasName() ? "'" + header.name() + "'" : "#" + std::to_string(i));
        }
        throw Error(label + ": OpenEXR file of " + std::to_string(parts.parts()) + " parts (" + names +
                    "); raylab reads single-part files");
      }
    }
    input.clear();
    input.seekg(0);
    Imf::InputFile file(input);
    if (file.header().hasType() && file.header().type() != Imf::SCANLINEIMAGE &&
        file.header().type() != Imf::TILEDIMAGE) {
      throw Error(label + ": OpenEXR file of type '" + file.header().type() + "'; raylab reads flat images");
    }
    const Imath::Box2i data = file.header().dataWindow();
    const Imath::Box2i display = file.header().displayWindow();
    const auto sizeOf = [](const Imath::Box2i& box) {
      return std::array<std::int64_t, 2>{std::int64_t(box.max.x) - box.min.x + 1, std::int64_t(box.max.y) - box.min.y + 1};
    };
    const auto [width, height] = sizeOf(display);
    const auto [dataWidth, dataHeight] = sizeOf(data);
    // The header is checked before anything is allocated: a small file may claim any size.
    for (const auto& [w, h, what] : {std::tuple{width, height, "display window"}, std::tuple{dataWidth, dataHeight, "data window"}}) {
      if (w <= 0 || h <= 0 || w > kMaxImageSide || h > kMaxImageSide || std::uint64_t(w) * std::uint64_t(h) > maxPixels) {
        throw Error(label + ": OpenEXR image whose " + what + " is " + std::to_string(w) + "x" + std::to_string(h) +
                    " pixels, over the limit of " + std::to_string(maxPixels) + " pixels (and " +
                    std::to_string(kMaxImageSide) + " a side)");
      }
    }
    if (checkSize) checkSize(std::uint32_t(width), std::uint32_t(height));
    const std::array<std::string, 4> channels = chooseChannels(file.header().channels(), label);
    std::uint64_t pixelBytes = 0;
    for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c) {
      pixelBytes += c.channel().type == Imf::HALF ? 2 : 4;
    }
    const std::uint64_t claimed = std::uint64_t(dataWidth) * std::uint64_t(dataHeight) * pixelBytes;
    if (claimed > kMaxCompressionRatio * std::max<std::uint64_t>(bytes.size(), 1)) {
      throw Error(label + ": OpenEXR header claims " + std::to_string(dataWidth) + "x" + std::to_string(dataHeight) +
                  " pixels (" + std::to_string(claimed) + " bytes) in a file of " + std::to_string(bytes.size()) +
                  " bytes, more than any compression holds: the file is damaged");
    }
    if (!file.isComplete()) {
      throw Error(label + ": OpenEXR file does not hold every pixel its header declares (truncated or damaged)");
    }
    // Read the data window, then place it in the display window; pixels outside the data window are 0.
    Image window(static_cast<std::uint32_t>(dataWidth), static_cast<std::uint32_t>(dataHeight));
    Imf::FrameBuffer frameBuffer;
    char* base = reinterpret_cast<char*>(window.rgba.data()) -
                 (std::ptrdiff_t(data.min.x) + std::ptrdiff_t(data.min.y) * window.width) * 4 * sizeof(float);
    for (int c = 0; c < 4; ++c) {
      // Absent alpha is 1 (below); a channel read twice (Y as grey) is copied after the read.
      if (channels[c].empty() || frameBuffer.findSlice(channels[c]) != nullptr) continue;
      frameBuffer.insert(channels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 4 * sizeof(float),
                                                 4 * sizeof(float) * window.width, 1, 1, 0.0));
    }
    if (channels[3].empty()) {
      for (std::size_t i = 3; i < window.rgba.size(); i += 4) window.rgba[i] = 1.0f;
    }
    file.setFrameBuffer(frameBuffer);
    file.readPixels(data.min.y, data.max.y);
    if (channels[1] == channels[0]) {
      for (std::size_t i = 0; i < window.rgba.size(); i += 4) window.rgba[i + 1] = window.rgba[i + 2] = window.rgba[i];
    }
    if (data == display) return window;
    Image image(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height));
    for (std::int64_t y = std::max(data.min.y, display.min.y); y <= std::min(data.max.y, display.max.y); ++y) {
      for (std::int64_t x = std::max(data.min.x, display.min.x); x <= std::min(data.max.x, display.max.x); ++x) {
        image.set(std::uint32_t(x - display.min.x), std::uint32_t(y - display.min.y),
                  window.at(std::uint32_t(x - data.min.x), std::uint32_t(y - data.min.y)));
      }
    }
    return image;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    // OpenEXR names an in-memory stream "(string)": the label already names the file.
    std::string why = e.what();
    for (const std::string noise : {" image file \"(string)\"", " \"(string)\""}) {
      for (std::size_t at; (at = why.find(noise)) != std::string::npos;) why.erase(at, noise.size());
    }
    throw Error(label + ": cannot read OpenEXR file (truncated or damaged): " + why);
  }
}

}  // namespace raylab
