// The ground of clover: a regular 2D grid whose voxels hold the light coming
// from above (1, or the input image's green channel) and the number of leaves
// over them (EnviroManual 3.2.1).
#pragma once

#include <cstdint>
#include <vector>

#include "env/programs/clover_parameters.h"

namespace sylva::env {

class LeafGrid {
 public:
  explicit LeafGrid(const CloverParameters& parameters);

  // Adds (count +1) or removes (count -1) a leaf: a disk of `area` centred at
  // ground point (u, v). It covers the voxels whose centres lie in the disk.
  // A voxel's count never goes below 0.
  void change_leaf(double u, double v, double area, int count);

  // The light reaching ground point (u, v): the voxel's initial intensity
  // times t^n for the n leaves over it; 0 outside the grid.
  double light_at(double u, double v) const;

  void remove_all_leaves();

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * size_[0] + i; }

  std::array<double, 2> low_{};
  std::array<double, 2> voxel_{};  // world size of one voxel
  std::array<int, 2> size_{};
  double transmittance_ = 0;
  std::vector<float> initial_;
  std::vector<std::uint32_t> leaves_;
};

}  // namespace sylva::env
