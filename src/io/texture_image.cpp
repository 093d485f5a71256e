#include "io/texture_image.h"

#include "io/texture_plugin.h"

namespace sylva::io {

namespace {

TextureCodec& codec() {
  static TextureCodec& plugin =
      plugin_object<TextureCodec>("libsylva_textures.so", "sylva_texture_codec", "reads texture images");
  return plugin;
}

}  // namespace

TextureImage read_texture_image(const std::string& path) { return codec().read(path); }

std::string encode_texture_png(const TextureImage& image) { return codec().encode_png(image); }

}  // namespace sylva::io
