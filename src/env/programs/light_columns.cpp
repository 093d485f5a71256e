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
  Vec3 helper = std::abs(direction.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  across_u_ = normalized(helper - dot(helper, direction) * direction);
  across_v_ = cross(direction, across_u_);

  projected_.resize(spheres.size());
  double low_u = std::numeric_limits<double>::max(), low_v = low_u;
  double high_u = std::numeric_limits<double>::lowest(), high_v = high_u;
  double reach_sum = 0;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Sphere& s = spheres[i];
    Projected& p = projected_[i];
    p = {dot(s.centre, across_u_), dot(s.centre, across_v_), dot(s.centre, direction)};
    double reach = s.radius + margin;
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

  // Two passes: count the entries of each cell, then fill them in.
  first_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  auto for_each_cell = [&](std::size_t i, auto&& action) {
    const Projected& p = projected_[i];
    double reach = spheres[i].radius + margin;
    int from = cell_index(p.u - reach, p.v - reach), to = cell_index(p.u + reach, p.v + reach);
    int first_column = from % columns_, last_column = to % columns_;
    for (int row = from / columns_; row <= to / columns_; ++row)
      for (int column = first_column; column <= last_column; ++column) action(row * columns_ + column);
  };
  for (std::size_t i = 0; i < spheres.size(); ++i) for_each_cell(i, [&](int c) { ++first_[c + 1]; });
  for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
  entries_.resize(first_.back());
  std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Projected& p = projected_[i];
    Entry entry{p.u, p.v, p.along, static_cast<std::uint32_t>(i)};
    for_each_cell(i, [&](int c) { entries_[fill[c]++] = entry; });
  }
}

}  // namespace sylva::env::light
