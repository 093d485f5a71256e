#include "env/programs/grid_uniform.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sylva::env::collision {
namespace {

// About two cells per object keeps cells nearly empty without the grid
// outgrowing the objects; the floor serves small scenes.
constexpr double kCellsPerObject = 2.0;
constexpr double kMinCellBudget = 64.0;

}  // namespace

UniformGrid::UniformGrid(std::span<const Point3> centres, std::span<const float> radii, int dimensions,
                         float cell_hint, std::array<int, 3> min_cells)
    : objects_(centres.size()) {
  if (objects_ == 0) {
    cell_start_.assign(2, 0);
    return;
  }
  Point3 lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<float>::max();
    hi[a] = std::numeric_limits<float>::lowest();
  }
  for (std::size_t i = 0; i < objects_; ++i)
    for (int a = 0; a < dimensions; ++a) {
      lo[a] = std::min(lo[a], centres[i][a] - radii[i]);
      hi[a] = std::max(hi[a], centres[i][a] + radii[i]);
    }
  for (int a = dimensions; a < 3; ++a) lo[a] = hi[a] = 0;

  // The cell edge: at least the hint, and large enough that the cell count
  // stays within the budget.
  double budget = std::max(kMinCellBudget, kCellsPerObject * static_cast<double>(objects_));
  double volume = 1;
  int spread_axes = 0;
  for (int a = 0; a < dimensions; ++a)
    if (hi[a] > lo[a]) {
      volume *= static_cast<double>(hi[a]) - lo[a];
      ++spread_axes;
    }
  double edge = spread_axes > 0 ? std::pow(volume / budget, 1.0 / spread_axes) : 1.0;
  edge = std::max(edge, static_cast<double>(cell_hint));
  double total = 1;
  for (int a = 0; a < 3; ++a) {
    double extent = static_cast<double>(hi[a]) - lo[a];
    double count = a < dimensions && extent > 0 && edge > 0 ? std::ceil(extent / edge) : 1.0;
    count = std::max(count, static_cast<double>(a < dimensions ? std::max(min_cells[a], 1) : 1));
    // A requested grid finer than the budget is coarsened to it.
    count = std::clamp(count, 1.0, std::max(1.0, budget));
    cells_[a] = static_cast<int>(count);
    total *= count;
  }
  while (total > 4 * budget) {  // only when the requested grid was very fine
    total = 1;
    for (int a = 0; a < 3; ++a) {
      cells_[a] = std::max(1, (cells_[a] + 1) / 2);
      total *= cells_[a];
    }
  }
  for (int a = 0; a < 3; ++a) {
    origin_[a] = lo[a];
    double extent = static_cast<double>(hi[a]) - lo[a];
    inverse_size_[a] = extent > 0 ? static_cast<float>(cells_[a] / extent) : 0.0f;
  }

  // Counting sort of (cell, object) pairs into cell_start_/entries_.
  std::size_t cell_count = static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2];
  cell_start_.assign(cell_count + 1, 0);
  auto for_cells_of = [&](std::size_t i, auto&& action) {
    std::array<int, 3> from{}, to{};
    for (int a = 0; a < 3; ++a) {
      from[a] = cell_of(a, centres[i][a] - radii[i]);
      to[a] = cell_of(a, centres[i][a] + radii[i]);
    }
    if (dimensions < 3) from[2] = to[2] = 0;
    for (int z = from[2]; z <= to[2]; ++z)
      for (int y = from[1]; y <= to[1]; ++y)
        for (int x = from[0]; x <= to[0]; ++x) action(index(x, y, z));
  };
  for (std::size_t i = 0; i < objects_; ++i) for_cells_of(i, [&](std::size_t cell) { ++cell_start_[cell + 1]; });
  for (std::size_t c = 0; c < cell_count; ++c) cell_start_[c + 1] += cell_start_[c];
  entries_.resize(cell_start_[cell_count]);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < objects_; ++i)
    for_cells_of(i, [&](std::size_t cell) { entries_[fill[cell]++] = static_cast<std::uint32_t>(i); });
}

}  // namespace sylva::env::collision
