// The spheres as seen along one light direction, for casting the rays of all
// spheres towards that source at once (chiba, takenaka). The sphere centres
// are projected onto the plane across the direction and entered in a regular
// 2D grid there: each sphere in every cell its disk, grown by a margin,
// touches. A ray from a sphere's centre along the direction can only meet the
// spheres entered in the cell under that centre, so each ray tests a short
// list instead of every sphere; the answers are those of testing every pair.
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

  // Calls visit(Neighbour) for the spheres other than `self` that may touch
  // the ray from the centre of sphere `self` (some may not), whose centres
  // lie no further than `behind` behind its origin.
  template <class Visit>
  void for_each_near(std::uint32_t self, double behind, Visit&& visit) const;

 private:
  struct Entry {
    double u, v, along;
    std::uint32_t sphere;
  };
  struct Projected {
    double u, v, along;
  };
  int cell_index(double u, double v) const;

  Vec3 across_u_, across_v_;
  double low_u_ = 0, low_v_ = 0, cell_ = 1;
  int columns_ = 1, rows_ = 1;
  std::vector<Projected> projected_;  // per sphere
  std::vector<std::uint32_t> first_;  // entries of cell c: entries_[first_[c] .. first_[c + 1])
  std::vector<Entry> entries_;
};

template <class Visit>
void LightColumns::for_each_near(std::uint32_t self, double behind, Visit&& visit) const {
  const Projected& p = projected_[self];
  int c = cell_index(p.u, p.v);
  for (std::uint32_t e = first_[c]; e < first_[c + 1]; ++e) {
    const Entry& entry = entries_[e];
    double along = entry.along - p.along;
    if (along < -behind || entry.sphere == self) continue;
    double du = entry.u - p.u, dv = entry.v - p.v;
    visit(Neighbour{entry.sphere, along, du * du + dv * dv});
  }
}

}  // namespace sylva::env::light
