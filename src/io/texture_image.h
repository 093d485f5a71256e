// Texture images (lpfg: .rgb and .png; cpfg: the same), read with
// GraphicsMagick (in its plugin, texture_plugin.h), which also reads SGI's RGB
// format.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sylva::io {

struct TextureImage {
  int width = 0, height = 0;
  // RGBA, 4 bytes a pixel, the bottom row first (as lpfg hands texture
  // rows to OpenGL: texture coordinate v = 0 is the image's bottom).
  std::vector<std::uint8_t> rgba;
};

// Throws ModelError naming the file when it cannot be read as an image.
TextureImage read_texture_image(const std::string& path);

// The image as PNG bytes, top row first (for embedding in glTF files).
std::string encode_texture_png(const TextureImage& image);

}  // namespace sylva::io
