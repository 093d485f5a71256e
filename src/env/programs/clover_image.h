// The input image of clover: light intensities from its green channel.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sylva::env {

struct GreenChannel {
  int width = 0;
  int height = 0;
  std::vector<float> values;  // row by row from the top row, 0..1

  float at(int column, int row) const { return values[static_cast<std::size_t>(row) * width + column]; }
};

// Reads PNG, BMP, TGA, JPEG, GIF, PNM, PSD or HDR. Throws std::runtime_error
// with the reason when the file cannot be read or decoded.
GreenChannel read_green_channel(const std::filesystem::path& path);

}  // namespace sylva::env
