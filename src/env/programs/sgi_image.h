// SGI image files (.rgb, .bw, .sgi): the Virtual Laboratory's light maps and
// textures come in this format. Read as the Virtual Laboratory's own reader
// (libs/image) reads them: a 512-byte header whose magic number also tells
// the byte order, then rows verbatim or run-length encoded, one byte per
// value; row 0 is the bottom row.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sylva::env {

struct SgiImage {
  int width = 0;
  int height = 0;
  int channels = 0;
  // Channel c, row y (0 = bottom), column x at (c * height + y) * width + x.
  std::vector<std::uint8_t> values;

  std::uint8_t at(int channel, int row, int column) const {
    return values[(static_cast<std::size_t>(channel) * height + row) * width + column];
  }
};

// Whether `bytes` start with an SGI image's magic number.
bool looks_like_sgi_image(const std::vector<std::uint8_t>& bytes);

// Decodes an SGI image; throws std::runtime_error saying what is wrong.
SgiImage decode_sgi_image(const std::vector<std::uint8_t>& bytes);

}  // namespace sylva::env
