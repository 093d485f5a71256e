// The ground of clover: a grid of cells, each with the light that falls on
// it from above, a second value the image gives (answered as p2), and the
// number of leaves over it. Filled from the input image as the real clover
// fills it (ENVIRO/clover), by file name:
//  - ending in "tga": a 24-bit Targa image with its origin at the top left
//    (nothing else); light from its red channel (blue in run-length packets,
//    which clover's reader turns around), the second value from green; the
//    file's first row is the grid's top row;
//  - ending in "rgb": an SGI image; light from channel 1 (green), the second
//    value from channel 0 (red); the image's bottom row is the grid's row 0;
//  - anything else: a PNG image; light from green, the second value from red,
//    the bottom row at row 0. The real clover never copies the image's last
//    row and column (its copying loop stops one short), so cells that sample
//    them get 0.
// Cell (x, y) samples pixel ((int)(x * (w-1)/(X-1)), (int)(y * (h-1)/(Y-1)))
// for an image of w x h pixels and a grid of X x Y cells, in float as clover
// computes it. Without an image every cell has light 255 and second value 0.
// An image that cannot be read is a warning: its cells get 0, as the real
// clover's never-filled grid memory reads on a fresh process.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sylva::env {

struct CloverCell {
  std::uint8_t objects = 0;  // leaves over the cell, at most 255
  std::uint8_t light = 255;
  std::uint8_t ratio = 0;
};

// The cells of a grid of size[0] x size[1], row by row from y = 0.
std::vector<CloverCell> load_clover_ground(const std::filesystem::path& image, std::array<int, 2> size);

}  // namespace sylva::env
