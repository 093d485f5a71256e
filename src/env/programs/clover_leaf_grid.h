// The grid of clover (ENVIRO/clover): cells over the ground with the light
// from above and the leaves over them, computed as the real clover computes
// them, in float where it uses float.
//  - The cell of a ground point (u, v): floor((u - x0) / range * size) along
//    each axis; a point outside the grid has no cell.
//  - A leaf of area a at (u, v): the cells (cx + i, cy + j) of the ellipse
//    i^2/rx^2 + j^2/ry^2 <= 1, -rx <= i < rx, -ry <= j < ry, around the
//    point's cell (cx, cy), where r = sqrt(a / pi) and rx = (int)(r / range *
//    size + 1) (the same for y). Each cell counts at most 255 leaves, and
//    removing never goes below 0. An area below 1e-7 changes nothing.
//  - The light of a cell: light / 255 * t^n for its n leaves, t^n taken from
//    a table of float powers; 0 outside the grid. The second value:
//    ratio / 128.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "env/programs/clover_image.h"
#include "env/programs/clover_parameters.h"

namespace sylva::env {

class LeafGrid {
 public:
  explicit LeafGrid(const CloverParameters& parameters);

  // Adds (count +1) or removes (count -1) a leaf of `area` at ground point (u, v).
  void change_leaf(float u, float v, float area, int count);

  // The cell under ground point (u, v), or nullopt outside the grid.
  std::optional<std::size_t> cell_at(float u, float v) const;
  float light(std::size_t cell) const;
  float second_value(std::size_t cell) const;

  void remove_all_leaves();

 private:
  std::array<long long, 2> node(float u, float v) const;

  std::array<float, 2> position_;
  std::array<float, 2> range_;
  std::array<int, 2> size_;
  std::array<float, 256> powers_{};  // transmittance^n
  std::vector<CloverCell> cells_;
};

}  // namespace sylva::env
