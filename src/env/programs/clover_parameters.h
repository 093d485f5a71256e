// The clover specification file, read as the Virtual Laboratory's clover
// reads it (ENVIRO/clover; vlab_spec_file.h for the reading rules):
//
//   grid size: 512 x 512       cells along x and y (default 512 x 512)
//   grid position: -1 -1      the grid's lower left corner (default -1 -1)
//   grid range: 2 x 2         its size in world units (default 2 x 2)
//   transmittance: 0.6        light let through by one leaf (default 0.6; 0 reads 0.0001)
//   input image: light.rgb    light from above (green; red for an image ending in
//                             "tga") and a second answer (red; green for "tga")
//   remove old leaves: on     leaves last one pass only (on or yes)
//   z is up: no               the ground is x z instead of x y (no or off)
//   verbose: on
#pragma once

#include <array>
#include <filesystem>
#include <string>

namespace sylva::env {

struct CloverParameters {
  std::array<int, 2> size{512, 512};
  std::array<float, 2> position{-1, -1};
  std::array<float, 2> range{2, 2};
  float transmittance = 0.6f;
  std::filesystem::path image;  // empty: full light everywhere
  bool remove_old_leaves = false;
  bool z_is_up = true;
  bool verbose = false;
};

// Never fails on what the real clover accepts; a grid size below 1 cell,
// which the real clover cannot allocate, is a ModelError at its line. The
// image is found relative to `directory`, the folder clover runs in.
CloverParameters read_clover_parameters(const std::filesystem::path& path, const std::filesystem::path& directory);

}  // namespace sylva::env
