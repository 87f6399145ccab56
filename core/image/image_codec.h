#pragma once
// The image codec: OpenImageIO, in a module of its own (probeproxy_image_codec) that is loaded
// on the first image read or written. OpenImageIO brings 260 shared libraries with it (OpenCV,
// FFmpeg, DCMTK, OpenVDB, ...) whose loading took half a second of every run of the command
// line, where most runs (validate, layout, survey without pictures) touch no image. Only this
// header and the module see the codec; the rest of core reads and writes through
// core/image/rgb_image.h, write_exr.h and write_png.h.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace probeproxy {

// What the file's header says, before any pixel is decoded.
struct ImageHeader {
  int width = 0, height = 0, depth = 1;  // pixels; depth > 1: a volume image
  int channels = 0;
  bool floating = false;  // stored as floats (EXR, HDR): linear by definition
  bool srgb = false;      // 8/16-bit values OpenImageIO reports as sRGB-encoded (PNG, JPEG)
};

// Where to decode: the first `channels` channels, interleaved, row 0 at the top, as float.
struct PixelDestination {
  int channels = 0;
  float* pixels = nullptr;  // width * height * channels floats, owned by the caller
};

struct ImageCodec {
  // Reads `file`'s header, asks `destination` where its pixels go (it may throw to refuse the
  // image), decodes them. Throws std::runtime_error with OpenImageIO's message when the file
  // cannot be opened or decoded.
  void (*read)(const std::filesystem::path& file,
               const std::function<PixelDestination(const ImageHeader&)>& destination);
  // Writes `pixels` (`channelNames.size()` interleaved channels, row 0 at the top; float when
  // `floating`, else 8-bit) to `file` in `format` ("exr": zip-compressed with a fixed date, so
  // the same pixels give the same bytes; "png"). Throws std::runtime_error with OpenImageIO's
  // message.
  void (*write)(const std::filesystem::path& file, const std::string& format, int width, int height,
                const std::vector<std::string>& channelNames, bool floating, const void* pixels);
};

// The codec, its module loaded on the first call (thread-safe). Throws std::runtime_error
// naming the module when it cannot be loaded: an installation fault, not a bad input.
const ImageCodec& imageCodec();

// The codec's write, into a temporary file renamed to `file` once written (core/io/
// atomic_write.h). Throws InputError naming `file` when it cannot be written.
void writeImageAtomically(const std::filesystem::path& file, const std::string& format, int width,
                          int height, const std::vector<std::string>& channelNames, bool floating,
                          const void* pixels);

}  // namespace probeproxy

// The module's one entry point.
extern "C" const probeproxy::ImageCodec* probeproxy_image_codec();
