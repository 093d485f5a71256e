#include "env/programs/clover_leaf_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace sylva::env {

namespace {

// Voxels [first, last] along one axis whose centres lie in [from, to]
// (world coordinates); empty when first > last.
std::pair<int, int> voxels_between(double from, double to, double low, double voxel, int count) {
  double first = std::ceil((from - low) / voxel - 0.5);
  double last = std::floor((to - low) / voxel - 0.5);
  first = std::clamp(first, 0.0, static_cast<double>(count));
  last = std::clamp(last, -1.0, static_cast<double>(count - 1));
  return {static_cast<int>(first), static_cast<int>(last)};
}

}  // namespace

LeafGrid::LeafGrid(const CloverParameters& p)
    : low_(p.position),
      voxel_{p.range[0] / p.size[0], p.range[1] / p.size[1]},
      size_(p.size),
      transmittance_(p.transmittance),
      initial_(static_cast<std::size_t>(p.size[0]) * p.size[1], 1.0f),
      leaves_(initial_.size(), 0) {
  if (!p.image) return;
  // The image is stretched over the grid, its top row at the far (high v)
  // edge as it appears when the ground is seen from above; each voxel takes
  // the pixel under its centre.
  const GreenChannel& image = *p.image;
  for (int j = 0; j < size_[1]; ++j) {
    int row = image.height - 1 - static_cast<int>((j + 0.5) * image.height / size_[1]);
    for (int i = 0; i < size_[0]; ++i) {
      int column = static_cast<int>((i + 0.5) * image.width / size_[0]);
      initial_[index(i, j)] = image.at(column, row);
    }
  }
}

void LeafGrid::change_leaf(double u, double v, double area, int count) {
  if (!(area > 0)) return;
  double radius = std::sqrt(area / std::numbers::pi);
  auto [j_first, j_last] = voxels_between(v - radius, v + radius, low_[1], voxel_[1], size_[1]);
  for (int j = j_first; j <= j_last; ++j) {
    // The disk's chord along this row of voxel centres.
    double dv = low_[1] + (j + 0.5) * voxel_[1] - v;
    double half = std::sqrt(std::max(0.0, radius * radius - dv * dv));
    auto [i_first, i_last] = voxels_between(u - half, u + half, low_[0], voxel_[0], size_[0]);
    for (int i = i_first; i <= i_last; ++i) {
      std::uint32_t& n = leaves_[index(i, j)];
      if (count > 0) {
        ++n;
      } else if (n > 0) {
        --n;
      }
    }
  }
}

double LeafGrid::light_at(double u, double v) const {
  double fi = std::floor((u - low_[0]) / voxel_[0]);
  double fj = std::floor((v - low_[1]) / voxel_[1]);
  if (!(fi >= 0 && fi < size_[0] && fj >= 0 && fj < size_[1])) return 0;
  std::size_t k = index(static_cast<int>(fi), static_cast<int>(fj));
  return initial_[k] * std::pow(transmittance_, static_cast<double>(leaves_[k]));
}

void LeafGrid::remove_all_leaves() { std::fill(leaves_.begin(), leaves_.end(), 0); }

}  // namespace sylva::env
