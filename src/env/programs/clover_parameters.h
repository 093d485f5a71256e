// The clover parameter file (EnviroManual 3.2.1).
#pragma once

#include <array>
#include <filesystem>
#include <optional>

#include "env/programs/clover_image.h"

namespace sylva::env {

struct CloverParameters {
  std::array<double, 2> range{};     // world size of the grid
  std::array<double, 2> position{};  // its lower left corner
  std::array<int, 2> size{};         // voxels
  double transmittance = 0;
  std::optional<GreenChannel> image;  // "input image:", light from above
  bool remove_old_leaves = false;
  bool z_is_up = true;  // ground coordinates x, y; otherwise x, z
  bool verbose = false;
};

// Throws ModelError with the file, line and column of what is wrong. The
// image is read relative to the parameter file's folder.
CloverParameters read_clover_parameters(const std::filesystem::path& path);

}  // namespace sylva::env
