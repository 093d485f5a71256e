// The door to the texture plugin, libsylva_textures.so: texture images read
// and encoded with GraphicsMagick, which with its image format libraries is
// kept out of the program until a model names a texture
// (support/plugin_library.h).
#pragma once

#include <string>

#include "io/texture_image.h"
#include "support/plugin_library.h"

namespace sylva::io {

class TextureCodec {
 public:
  // See read_texture_image and encode_texture_png.
  virtual TextureImage read(const std::string& path) = 0;
  virtual std::string encode_png(const TextureImage& image) = 0;

 protected:
  ~TextureCodec() = default;
};

}  // namespace sylva::io

// The plugin's one codec.
extern "C" SYLVA_PLUGIN_EXPORT sylva::io::TextureCodec* sylva_texture_codec();
