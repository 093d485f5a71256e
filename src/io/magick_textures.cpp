// The texture plugin (texture_plugin.h): images read and written with
// GraphicsMagick.
#include <magick/api.h>

#include <cstring>
#include <memory>
#include <mutex>

#include "io/texture_plugin.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

void initialize_magick() {
  static std::once_flag once;
  std::call_once(once, [] { InitializeMagick(nullptr); });
}

struct Exception {
  ExceptionInfo info;
  Exception() { GetExceptionInfo(&info); }
  ~Exception() { DestroyExceptionInfo(&info); }
  std::string reason() const {
    std::string text = info.reason ? info.reason : "not an image it can read";
    if (info.description) text += std::string(" (") + info.description + ")";
    return text;
  }
};

using ImageInfoPtr = std::unique_ptr<ImageInfo, decltype(&DestroyImageInfo)>;
using ImagePtr = std::unique_ptr<::Image, decltype(&DestroyImage)>;

TextureImage read_with_magick(const std::string& path) {
  initialize_magick();
  ImageInfoPtr info(CloneImageInfo(nullptr), DestroyImageInfo);
  std::strncpy(info->filename, path.c_str(), MaxTextExtent - 1);
  Exception error;
  ImagePtr image(ReadImage(info.get(), &error.info), DestroyImage);
  if (!image) throw ModelError(SourceLocation{path, 0, 0}, "cannot read the texture image: " + error.reason());
  TextureImage out;
  out.width = static_cast<int>(image->columns);
  out.height = static_cast<int>(image->rows);
  std::vector<std::uint8_t> top_first(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4);
  if (DispatchImage(image.get(), 0, 0, image->columns, image->rows, "RGBA", CharPixel, top_first.data(), &error.info) !=
      MagickPass)
    throw ModelError(SourceLocation{path, 0, 0}, "cannot read the texture image's pixels: " + error.reason());
  const std::size_t row = static_cast<std::size_t>(out.width) * 4;
  out.rgba.resize(top_first.size());
  for (int y = 0; y < out.height; ++y)
    std::memcpy(out.rgba.data() + static_cast<std::size_t>(y) * row,
                top_first.data() + static_cast<std::size_t>(out.height - 1 - y) * row, row);
  return out;
}

std::string encode_png_with_magick(const TextureImage& image) {
  initialize_magick();
  const std::size_t row = static_cast<std::size_t>(image.width) * 4;
  std::vector<std::uint8_t> top_first(image.rgba.size());
  for (int y = 0; y < image.height; ++y)
    std::memcpy(top_first.data() + static_cast<std::size_t>(y) * row,
                image.rgba.data() + static_cast<std::size_t>(image.height - 1 - y) * row, row);
  Exception error;
  ImagePtr img(ConstituteImage(static_cast<unsigned long>(image.width), static_cast<unsigned long>(image.height), "RGBA",
                               CharPixel, top_first.data(), &error.info),
               DestroyImage);
  if (!img) throw ModelError("cannot encode a texture as PNG: " + error.reason());
  ImageInfoPtr info(CloneImageInfo(nullptr), DestroyImageInfo);
  std::strncpy(info->magick, "PNG", MaxTextExtent - 1);
  std::strncpy(img->magick, "PNG", MaxTextExtent - 1);
  std::size_t length = 0;
  void* blob = ImageToBlob(info.get(), img.get(), &length, &error.info);
  if (!blob) throw ModelError("cannot encode a texture as PNG: " + error.reason());
  std::string bytes(static_cast<const char*>(blob), length);
  MagickFree(blob);
  return bytes;
}

class MagickTextures final : public TextureCodec {
 public:
  TextureImage read(const std::string& path) override { return read_with_magick(path); }
  std::string encode_png(const TextureImage& image) override { return encode_png_with_magick(image); }
};

}  // namespace

}  // namespace sylva::io

extern "C" SYLVA_PLUGIN_EXPORT sylva::io::TextureCodec* sylva_texture_codec() {
  static sylva::io::MagickTextures codec;
  return &codec;
}
