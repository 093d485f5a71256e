#include "env/programs/light_columns.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sylva::env::light {

namespace {

Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

}  // namespace

int LightColumns::cell_index(double u, double v) const {
  double column = std::clamp(std::floor((u - low_u_) / cell_), 0.0, static_cast<double>(columns_ - 1));
  double row = std::clamp(std::floor((v - low_v_) / cell_), 0.0, static_cast<double>(rows_ - 1));
  return static_cast<int>(row) * columns_ + static_cast<int>(column);
}

void LightColumns::build(std::span<const Sphere> spheres, Vec3 direction, double margin) {
  project(spheres, direction);
  lay_out_grid(spheres, margin);
  order_by_home_cell();
  fill_cells(spheres, margin);
}

void LightColumns::project(std::span<const Sphere> spheres, Vec3 direction) {
  Vec3 helper = std::abs(direction.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  across_u_ = normalized(helper - dot(helper, direction) * direction);
  across_v_ = cross(direction, across_u_);
  projected_.resize(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    Vec3 c = spheres[i].centre;
    projected_[i] = {dot(c, across_u_), dot(c, across_v_), dot(c, direction), 0};
  }
}

void LightColumns::lay_out_grid(std::span<const Sphere> spheres, double margin) {
  double low_u = std::numeric_limits<double>::max(), low_v = low_u;
  double high_u = std::numeric_limits<double>::lowest(), high_v = high_u;
  double reach_sum = 0;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Projected& p = projected_[i];
    double reach = spheres[i].radius + margin;
    low_u = std::min(low_u, p.u - reach), high_u = std::max(high_u, p.u + reach);
    low_v = std::min(low_v, p.v - reach), high_v = std::max(high_v, p.v + reach);
    reach_sum += reach;
  }
  if (spheres.empty()) low_u = low_v = 0, high_u = high_v = 1;

  // Cells about as wide as a typical sphere's reach keep both the number of
  // cells a sphere enters and the spheres per cell small; at most about four
  // cells per sphere when the spheres are sparse.
  double width = std::max(high_u - low_u, 1e-9), height = std::max(high_v - low_v, 1e-9);
  double count = static_cast<double>(std::max<std::size_t>(1, spheres.size()));
  double cell = reach_sum / count;
  cell = std::max({cell, std::sqrt(width * height / (4 * count)), std::max(width, height) / 16384});
  low_u_ = low_u, low_v_ = low_v, cell_ = cell;
  columns_ = std::max(1, static_cast<int>(std::ceil(width / cell)));
  rows_ = std::max(1, static_cast<int>(std::ceil(height / cell)));
  for (Projected& p : projected_) p.cell = static_cast<std::uint32_t>(cell_index(p.u, p.v));
}

// A counting sort of the spheres by the cell under their centre.
void LightColumns::order_by_home_cell() {
  first_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (const Projected& p : projected_) ++first_[p.cell + 1];
  for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
  casting_order_.resize(projected_.size());
  fill_.assign(first_.begin(), first_.end() - 1);
  for (std::uint32_t i = 0; i < projected_.size(); ++i) casting_order_[fill_[projected_[i].cell]++] = i;
}

// Entered in casting order, so that neighbouring spheres write to
// neighbouring cells.
void LightColumns::fill_cells(std::span<const Sphere> spheres, double margin) {
  covered_.resize(spheres.size());
  std::fill(first_.begin(), first_.end(), 0);
  for (std::uint32_t i = 0; i < spheres.size(); ++i) {
    const Projected& p = projected_[i];
    double reach = spheres[i].radius + margin;
    int from = cell_index(p.u - reach, p.v - reach), to = cell_index(p.u + reach, p.v + reach);
    covered_[i] = {from % columns_, to % columns_, from / columns_, to / columns_};
  }
  auto for_each_cell = [&](std::uint32_t i, auto&& action) {
    const CellRange& r = covered_[i];
    for (int row = r.first_row; row <= r.last_row; ++row)
      for (int column = r.first_column; column <= r.last_column; ++column) action(row * columns_ + column);
  };
  // Two passes: count the entries of each cell, then fill them in.
  for (std::uint32_t i : casting_order_) for_each_cell(i, [&](int c) { ++first_[c + 1]; });
  for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
  entries_.resize(first_.back());
  fill_.assign(first_.begin(), first_.end() - 1);
  for (std::uint32_t i : casting_order_) {
    const Projected& p = projected_[i];
    Entry entry{p.u, p.v, p.along, spheres[i].radius, i};
    for_each_cell(i, [&](int c) { entries_[fill_[c]++] = entry; });
  }
}

}  // namespace sylva::env::light
