#include "env/programs/clover_leaf_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sylva::env {

LeafGrid::LeafGrid(const CloverParameters& p)
    : position_(p.position), range_(p.range), size_(p.size), cells_(load_clover_ground(p.image, p.size)) {
  powers_[0] = 1.0f;
  for (std::size_t n = 1; n < powers_.size(); ++n) powers_[n] = p.transmittance * powers_[n - 1];
}

std::array<long long, 2> LeafGrid::node(float u, float v) const {
  const float point[2] = {u, v};
  std::array<long long, 2> node{};
  for (int c = 0; c < 2; ++c) {
    const double cell = std::floor((point[c] - position_[c]) / range_[c] * static_cast<float>(size_[c]));
    // Far outside (or NaN): a cell number far off the grid.
    node[c] = std::isfinite(cell) ? static_cast<long long>(std::clamp(cell, -1e15, 1e15)) : -(1LL << 50);
  }
  return node;
}

std::optional<std::size_t> LeafGrid::cell_at(float u, float v) const {
  const std::array<long long, 2> n = node(u, v);
  if (n[0] < 0 || n[0] >= size_[0] || n[1] < 0 || n[1] >= size_[1]) return std::nullopt;
  return static_cast<std::size_t>(n[1]) * size_[0] + n[0];
}

float LeafGrid::light(std::size_t cell) const {
  return static_cast<float>(static_cast<float>(cells_[cell].light) / 255.0 * powers_[cells_[cell].objects]);
}

float LeafGrid::second_value(std::size_t cell) const {
  return static_cast<float>(static_cast<float>(cells_[cell].ratio) / 128.0);
}

void LeafGrid::change_leaf(float u, float v, float area, int count) {
  if (area < 0.0000001f) return;
  const float radius = static_cast<float>(std::sqrt(area / std::numbers::pi));
  const std::array<long long, 2> centre = node(u, v);
  std::array<long long, 2> reach{};
  for (int c = 0; c < 2; ++c) {
    const float cells = radius / range_[c] * static_cast<float>(size_[c]) + 1;
    reach[c] = std::isfinite(cells) ? static_cast<long long>(std::min(cells, 1e15f)) : 1LL << 50;
  }
  // Only the offsets that land on the grid are visited; the others would
  // change nothing.
  const long long y_from = std::max(-reach[1], -centre[1]), y_to = std::min(reach[1], size_[1] - centre[1]);
  const long long x_from = std::max(-reach[0], -centre[0]), x_to = std::min(reach[0], size_[0] - centre[0]);
  const float rx2 = static_cast<float>(reach[0] * reach[0]), ry2 = static_cast<float>(reach[1] * reach[1]);
  for (long long y = y_from; y < y_to; ++y)
    for (long long x = x_from; x < x_to; ++x) {
      if (static_cast<float>(x * x) / rx2 + static_cast<float>(y * y) / ry2 > 1) continue;
      CloverCell& cell = cells_[static_cast<std::size_t>(centre[1] + y) * size_[0] + static_cast<std::size_t>(centre[0] + x)];
      if (count > 0 && cell.objects < 255) ++cell.objects;
      else if (count < 0 && cell.objects > 0) --cell.objects;
    }
}

void LeafGrid::remove_all_leaves() {
  for (CloverCell& cell : cells_) cell.objects = 0;
}

}  // namespace sylva::env
