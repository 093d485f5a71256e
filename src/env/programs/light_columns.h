// The spheres as seen along one light direction, for casting the rays of all
// spheres towards that source at once (chiba, takenaka). The sphere centres
// are projected onto the plane across the direction and entered in a regular
// 2D grid there: each sphere in every cell its disk, grown by a margin,
// touches. A ray from a sphere's centre along the direction can only meet the
// spheres entered in the cell under that centre, so each ray tests a short
// list instead of every sphere; the answers are those of testing every pair.
//
// Rays are best cast in casting_order(): the spheres grouped by the cell
// under their centre, so consecutive rays read the same short list while it
// is in cache.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "env/programs/light_geometry.h"

namespace sylva::env::light {

class LightColumns {
 public:
  // Where a sphere lies relative to the ray of another: how far along the
  // ray (negative behind its origin), and the squared distance from the ray.
  struct Neighbour {
    std::uint32_t sphere;
    double along;
    double distance_squared;
  };

  // Rebuilds for `direction` (unit length). A ray then finds every sphere
  // whose radius plus `margin` reaches it.
  void build(std::span<const Sphere> spheres, Vec3 direction, double margin);

  // Every sphere once, those whose centres share a cell next to each other.
  std::span<const std::uint32_t> casting_order() const { return casting_order_; }

  // Calls visit(Neighbour) for the spheres other than `self` whose disks,
  // grown by `widen`, the ray from the centre of sphere `self` passes through,
  // and whose centres lie no further than `behind` behind its origin.
  template <class Visit>
  void for_each_near(std::uint32_t self, double behind, double widen, Visit&& visit) const;

 private:
  struct Entry {
    double u, v, along, radius;
    std::uint32_t sphere;
  };
  struct Projected {
    double u, v, along;
    std::uint32_t cell;  // the cell under the centre
  };
  struct CellRange {
    int first_column, last_column, first_row, last_row;
  };
  int cell_index(double u, double v) const;
  void project(std::span<const Sphere> spheres, Vec3 direction);
  void lay_out_grid(std::span<const Sphere> spheres, double margin);
  void order_by_home_cell();
  void fill_cells(std::span<const Sphere> spheres, double margin);

  Vec3 across_u_, across_v_;
  double low_u_ = 0, low_v_ = 0, cell_ = 1;
  int columns_ = 1, rows_ = 1;
  std::vector<Projected> projected_;  // per sphere
  std::vector<CellRange> covered_;    // per sphere: the cells its disk and margin touch
  std::vector<std::uint32_t> casting_order_;  // sphere indices by the cell under their centre
  std::vector<std::uint32_t> first_;  // entries of cell c: entries_[first_[c] .. first_[c + 1])
  std::vector<std::uint32_t> fill_;   // scratch: the next free slot of each cell
  std::vector<Entry> entries_;
};

template <class Visit>
void LightColumns::for_each_near(std::uint32_t self, double behind, double widen, Visit&& visit) const {
  const Projected& p = projected_[self];
  const Entry* end = entries_.data() + first_[p.cell + 1];
  for (const Entry* entry = entries_.data() + first_[p.cell]; entry != end; ++entry) {
    double along = entry->along - p.along;
    double du = entry->u - p.u, dv = entry->v - p.v;
    double distance_squared = du * du + dv * dv, reach = entry->radius + widen;
    // Tested together: most entries fail one of these, and which one is
    // unpredictable.
    bool near = (along >= -behind) & (distance_squared < reach * reach) & (entry->sphere != self);
    if (near) visit(Neighbour{entry->sphere, along, distance_squared});
  }
}

}  // namespace sylva::env::light
