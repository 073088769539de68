// OpenEXR files through the OpenEXR library: linear float32 RGBA.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfPartType.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfVersion.h>
#include <openexr.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <map>
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
// The same bound on what raylab allocates (float RGBA, 16 bytes a pixel, for the data window and the display
// window alike): four times the ratio, for half-float channels widened to float and absent ones filled. A
// display window far larger than the data window costs memory too, though the file holds nothing of it.
constexpr std::uint64_t kMaxExpansion = 4 * kMaxCompressionRatio;

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

// OpenEXR's C++ classes allocate what a header states before reading it (an attribute of 1.9 GB in a file of
// 900 bytes, or 2^28 one-pixel tiles' offsets). Its core library (OpenEXRCore) parses headers strictly and takes
// an allocator: the header is parsed there first, from memory, with every allocation bounded by the file's size,
// and only a file that passes reaches the C++ classes.
thread_local std::size_t coreAllocationLimit = 0;
thread_local std::string coreError;

void* boundedAllocation(std::size_t bytes) { return bytes > coreAllocationLimit ? nullptr : std::malloc(bytes); }

std::int64_t readFromMemory(exr_const_context_t, void* user, void* buffer, std::uint64_t size, std::uint64_t offset,
                            exr_stream_error_func_ptr_t) {
  const std::string& bytes = *static_cast<const std::string*>(user);
  if (offset >= bytes.size()) return 0;
  const std::size_t count = std::size_t(std::min<std::uint64_t>(size, bytes.size() - offset));
  std::memcpy(buffer, bytes.data() + offset, count);
  return std::int64_t(count);
}

std::int64_t sizeInMemory(exr_const_context_t, void* user) {
  return std::int64_t(static_cast<const std::string*>(user)->size());
}

void keepError(exr_const_context_t, exr_result_t, const char* message) {
  if (coreError.empty() && message != nullptr) coreError = message;
}

// Walks the headers as OpenEXR 3.1's C++ Header::readFrom reads them, which is not always as OpenEXRCore does:
// the C++ reader takes a known type's value by its layout and ignores the stated size (a channel list runs to its
// empty name), takes names of up to 33 bytes without a terminator, and allocates an unknown type's stated size, or
// a preview's width x height x 4, before reading. Throws when such an allocation would exceed what is left of the
// file. (Fuzzing found files that OpenEXRCore accepts and the C++ reader misreads into a 1.8 GB attribute.)
void checkCxxHeaderWalk(const std::string& bytes, const std::string& label) {
  std::int32_t version = 0;
  std::memcpy(&version, bytes.data() + 4, 4);
  const std::size_t n = (version & Imf::LONG_NAMES_FLAG) ? 255 : 31;
  std::size_t at = 8;
  const auto damaged = [&]() { return Error(label + ": damaged OpenEXR header (raylab's walk of it)"); };
  const auto need = [&](std::uint64_t count) {
    if (count > bytes.size() - std::min(at, bytes.size())) throw damaged();
  };
  const auto name = [&]() {  // Xdr::read(is, n + 1, c): up to n + 2 bytes, stopping after a NUL
    std::string text;
    for (std::size_t read = 0; read <= n + 1; ++read) {
      need(1);
      const char c = bytes[at++];
      if (c == '\0') break;
      text += c;
    }
    return text;
  };
  const auto int32 = [&]() {
    need(4);
    std::int32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4);
    at += 4;
    return value;
  };
  // Fixed layouts of the C++ library's attribute types; the others are read by their stated size or specially.
  static const std::map<std::string, std::size_t> kFixed = {
      {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"double", 8}, {"envmap", 1},
      {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64},
      {"m44d", 128}, {"rational", 8}, {"tiledesc", 9}, {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16},
      {"v3i", 12}, {"v3f", 12}, {"v3d", 24}, {"deepImageState", 1}};
  for (int part = 0; part < 64; ++part) {
    for (int attributes = 0;; ++attributes) {
      if (attributes > 10000) throw damaged();
      const std::string attribute = name();
      if (attribute.empty()) break;
      const std::string type = name();
      const std::int32_t size = int32();
      if (size < 0) throw damaged();
      if (const auto fixed = kFixed.find(type); fixed != kFixed.end()) {
        need(fixed->second);
        at += fixed->second;
      } else if (type == "chlist") {
        for (int channels = 0;; ++channels) {
          if (channels > 100000) throw damaged();
          if (name().empty()) break;
          need(16);  // pixel type, pLinear and reserved, x and y sampling
          at += 16;
        }
      } else if (type == "preview") {
        const std::uint64_t width = std::uint32_t(int32()), height = std::uint32_t(int32());
        need(width * height * 4);
        at += std::size_t(width * height * 4);
      } else {
        need(std::uint64_t(size));  // string, stringvector, floatvector, opaque types: allocated, then read
        at += std::size_t(size);
      }
    }
    if (!(version & Imf::MULTI_PART_FILE_FLAG) || at >= bytes.size() || bytes[at] == '\0') return;
  }
}

// How many of the data window's rows the file's chunks hold: every chunk of the first level is found through the
// offset table and decompressed by the core library. OpenEXR's C++ classes fill rows whose chunk is missing, or
// decompresses short (a header whose windows were enlarged past the stored rows), with whatever their buffers held:
// heap memory, NaN or finite. A chunk that fails counts the rows its data does hold where that is known (stored
// uncompressed: its size), else none.
// The bytes of pixels a chunk holds once decompressed, where that can be told without decoding it: its size stored
// uncompressed, the length of its zlib stream (ZIP, ZIPS: raylab's own files), else 0.
std::uint64_t storedBytes(exr_context_t context, const exr_chunk_info_t& chunk) {
  if (chunk.compression == EXR_COMPRESSION_NONE) return chunk.packed_size;
  if (chunk.compression != EXR_COMPRESSION_ZIP && chunk.compression != EXR_COMPRESSION_ZIPS) return 0;
  std::vector<unsigned char> packed(chunk.packed_size), out(1 << 16);
  if (exr_read_chunk(context, 0, &chunk, packed.data()) != EXR_ERR_SUCCESS) return 0;
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK) return 0;
  stream.next_in = packed.data();
  stream.avail_in = uInt(packed.size());
  std::uint64_t total = 0;
  int status = Z_OK;
  while (status == Z_OK && total <= chunk.unpacked_size) {  // never more than the chunk claims
    stream.next_out = out.data();
    stream.avail_out = uInt(out.size());
    status = inflate(&stream, Z_NO_FLUSH);
    total += out.size() - stream.avail_out;
  }
  inflateEnd(&stream);
  return total;
}

std::int64_t rowsHeld(exr_context_t context, exr_storage_t storage, const exr_attr_box2i_t& window) {
  std::int64_t held = 0;
  exr_decode_pipeline_t decoder = EXR_DECODE_PIPELINE_INITIALIZER;
  bool started = false;
  const auto decodes = [&](const exr_chunk_info_t& chunk) {
    exr_result_t result = started ? exr_decoding_update(context, 0, &chunk, &decoder)
                                  : exr_decoding_initialize(context, 0, &chunk, &decoder);
    if (!started && result == EXR_ERR_SUCCESS) result = exr_decoding_choose_default_routines(context, 0, &decoder);
    started = started || result == EXR_ERR_SUCCESS;
    if (result == EXR_ERR_SUCCESS) result = exr_decoding_run(context, 0, &decoder);  // read and decompress
    // The core library of OpenEXR 3.1 does not decompress DWAA/DWAB: such a chunk is counted as found, and the
    // C++ classes, which do, report what they cannot decode.
    return result == EXR_ERR_SUCCESS || result == EXR_ERR_FEATURE_NOT_IMPLEMENTED;
  };
  const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
  if (storage == EXR_STORAGE_SCANLINE) {
    std::int32_t lines = 0;
    if (exr_get_scanlines_per_chunk(context, 0, &lines) != EXR_ERR_SUCCESS || lines <= 0) return 0;
    std::uint64_t rowBytes = 0;
    const exr_attr_chlist_t* channels = nullptr;
    if (exr_get_channels(context, 0, &channels) == EXR_ERR_SUCCESS && channels != nullptr) {
      for (int c = 0; c < channels->num_channels; ++c) {
        rowBytes += std::uint64_t(width / channels->entries[c].x_sampling) *
                    (channels->entries[c].pixel_type == EXR_PIXEL_HALF ? 2 : 4);
      }
    }
    for (std::int64_t y = window.min.y; y <= window.max.y; y += lines) {
      exr_chunk_info_t chunk{};
      if (exr_read_scanline_chunk_info(context, 0, int(y), &chunk) != EXR_ERR_SUCCESS) continue;
      if (decodes(chunk)) {
        held += chunk.height;
      } else if (rowBytes > 0) {
        held += std::min<std::int64_t>(chunk.height, std::int64_t(storedBytes(context, chunk) / rowBytes));
      }
    }
  } else {
    // Tiles: the first level's, each holding its rows for its columns; counted as whole rows of the window when
    // every tile of a row of tiles decodes.
    std::uint32_t tileWidth = 0, tileHeight = 0;
    exr_tile_level_mode_t levelMode{};
    exr_tile_round_mode_t roundMode{};
    if (exr_get_tile_descriptor(context, 0, &tileWidth, &tileHeight, &levelMode, &roundMode) != EXR_ERR_SUCCESS ||
        tileWidth == 0 || tileHeight == 0) {
      return 0;
    }
    const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
    const auto tilesX = std::int32_t((width + tileWidth - 1) / tileWidth);
    const auto tilesY = std::int32_t((height + tileHeight - 1) / tileHeight);
    for (std::int32_t ty = 0; ty < tilesY; ++ty) {
      bool whole = true;
      std::int64_t rows = 0;
      for (std::int32_t tx = 0; tx < tilesX && whole; ++tx) {
        exr_chunk_info_t chunk{};
        whole = exr_read_tile_chunk_info(context, 0, tx, ty, 0, 0, &chunk) == EXR_ERR_SUCCESS && decodes(chunk);
        rows = chunk.height;
      }
      if (whole) held += rows;
    }
  }
  if (started) exr_decoding_destroy(context, &decoder);
  return held;
}

// Refuses, before OpenEXR's C++ classes see the file: a header the core library does not accept, several parts
// (which would be read as the first, silently), deep data, and more chunks than the file has room for offsets of
// (each chunk needs 8 bytes in the file's offset table).
void checkHeaderAgainstContent(const std::string& bytes, const std::string& label) {
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = &keepError;
  init.alloc_fn = &boundedAllocation;
  init.free_fn = &std::free;
  init.user_data = const_cast<std::string*>(&bytes);
  init.read_fn = &readFromMemory;
  init.size_fn = &sizeInMemory;
  init.flags = EXR_CONTEXT_FLAG_STRICT_HEADER;
  coreAllocationLimit = (std::size_t(16) << 20) + bytes.size();  // the context and tables, and a header's copy
  coreError.clear();
  exr_context_t context = nullptr;
  if (exr_start_read(&context, label.c_str(), &init) != EXR_ERR_SUCCESS) {
    if (context != nullptr) exr_finish(&context);
    throw Error(label + ": not a readable OpenEXR file (" + (coreError.empty() ? "damaged header" : coreError) + ")");
  }
  std::string problem;
  int parts = 0;
  exr_get_count(context, &parts);
  exr_storage_t storage = EXR_STORAGE_SCANLINE;
  std::int32_t chunks = 0;
  if (parts != 1) {
    std::string names;
    for (int i = 0; i < parts; ++i) {
      const char* name = nullptr;
      const bool named = exr_get_name(context, i, &name) == EXR_ERR_SUCCESS && name != nullptr;
      names += (i ? ", " : "") + (named ? "'" + std::string(name) + "'" : "#" + std::to_string(i));
    }
    problem = "OpenEXR file of " + std::to_string(parts) + " parts (" + names + "); raylab reads single-part files";
  } else if (exr_get_storage(context, 0, &storage) != EXR_ERR_SUCCESS || storage == EXR_STORAGE_DEEP_SCANLINE ||
             storage == EXR_STORAGE_DEEP_TILED) {
    problem = "a deep OpenEXR file; raylab reads flat images";
  } else if (exr_get_chunk_count(context, 0, &chunks) != EXR_ERR_SUCCESS || chunks < 0 ||
             std::uint64_t(chunks) * 8 > bytes.size()) {
    problem = "OpenEXR header promises " + std::to_string(chunks) + " chunks of pixels in a file of " +
              std::to_string(bytes.size()) + " bytes, which cannot even hold their offsets: the file is damaged";
  }
  // The pixels the header claims, in the file's own channel types, within what the file's content can fill; and
  // the buffer of one chunk, which the C++ classes allocate at once whatever the image's height (a 1-pixel-tall
  // image of 256-line chunks), within that and a fixed 256 MiB of slack.
  exr_attr_box2i_t window{};
  const exr_attr_chlist_t* channels = nullptr;
  if (problem.empty() && exr_get_data_window(context, 0, &window) == EXR_ERR_SUCCESS &&
      exr_get_channels(context, 0, &channels) == EXR_ERR_SUCCESS && channels != nullptr) {
    std::uint64_t pixelBytes = 0;
    for (int c = 0; c < channels->num_channels; ++c) pixelBytes += channels->entries[c].pixel_type == EXR_PIXEL_HALF ? 2 : 4;
    const std::uint64_t width = std::uint64_t(std::max<std::int64_t>(0, std::int64_t(window.max.x) - window.min.x + 1));
    const std::uint64_t height = std::uint64_t(std::max<std::int64_t>(0, std::int64_t(window.max.y) - window.min.y + 1));
    const std::uint64_t bound = kMaxCompressionRatio * std::max<std::uint64_t>(bytes.size(), 1);
    if (width > kMaxImageSide || height > kMaxImageSide) {
      problem = "OpenEXR data window of " + std::to_string(width) + "x" + std::to_string(height) +
                " pixels; raylab reads at most " + std::to_string(kMaxImageSide) + " a side";
    } else if (std::uint64_t chunkBytes = 0;
               width * height * pixelBytes > bound ||
               exr_get_chunk_unpacked_size(context, 0, &chunkBytes) != EXR_ERR_SUCCESS ||
               chunkBytes > bound + (std::uint64_t(256) << 20)) {
      problem = "OpenEXR header claims " + std::to_string(width) + "x" + std::to_string(height) + " pixels of " +
                std::to_string(channels->num_channels) + " channels in a file of " + std::to_string(bytes.size()) +
                " bytes, more than any compression holds: the file is damaged";
    }
  }
  if (problem.empty() && channels != nullptr) {
    const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
    // Decompression buffers: a chunk's unpacked size was bounded above.
    coreAllocationLimit = (std::size_t(16) << 20) + 2 * bytes.size() + (std::size_t(512) << 20);
    const std::int64_t held = rowsHeld(context, storage, window);
    if (held < height) {
      problem = "OpenEXR file holds " + std::to_string(held) + " of its " + std::to_string(height) +
                " rows (truncated, or a header that declares more than was stored)";
    }
  }
  exr_finish(&context);
  if (!problem.empty()) throw Error(label + ": " + problem);
  checkCxxHeaderWalk(bytes, label);
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
    // Multi-part files (which would be read as their first part, silently), deep files and headers that promise
    // more than the file holds are refused before OpenEXR's file classes allocate anything.
    checkHeaderAgainstContent(bytes, label);
    Imf::StdISStream input;
    input.str(bytes);
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
    // The pixels the file claims were checked against its size with its header (checkHeaderAgainstContent); what
    // raylab allocates, float RGBA for both windows, is checked here.
    for (const auto& [w, h, what] : {std::tuple{width, height, "display window"}, std::tuple{dataWidth, dataHeight, "data window"}}) {
      if (std::uint64_t(w) * std::uint64_t(h) * 16 > kMaxExpansion * std::max<std::uint64_t>(bytes.size(), 1)) {
        throw Error(label + ": OpenEXR " + what + " of " + std::to_string(w) + "x" + std::to_string(h) +
                    " pixels in a file of " + std::to_string(bytes.size()) + " bytes: more than its content can " +
                    "fill (the file is damaged)");
      }
    }
    if (!file.isComplete()) {
      throw Error(label + ": OpenEXR file does not hold every pixel its header declares (truncated or damaged)");
    }
    // Read the data window, then place it in the display window; pixels outside the data window are 0.
    Image window(static_cast<std::uint32_t>(dataWidth), static_cast<std::uint32_t>(dataHeight));
    Imf::FrameBuffer frameBuffer;
    for (int c = 0; c < 4; ++c) {
      // Absent alpha is 1 (below); a channel read twice (Y as grey) is copied after the read. Slice::Make offsets
      // the base by the data window's origin without forming an out-of-range pointer.
      if (channels[c].empty() || frameBuffer.findSlice(channels[c]) != nullptr) continue;
      frameBuffer.insert(channels[c], Imf::Slice::Make(Imf::FLOAT, window.rgba.data() + c, data, 4 * sizeof(float),
                                                       4 * sizeof(float) * window.width));
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
