// A uniform grid over balls (disks in 2D) for finding which ones are near a
// point quickly: the collision programs ask it, for each of up to hundreds of
// thousands of objects per step, for the few objects close enough to touch.
//
// The grid tightly fits the objects' bounding boxes and is rebuilt for every
// environmental pass (EnviroManual 3.1.2). Each object is entered in every
// cell its bounding box overlaps, so an object with a radius may be visited
// more than once by one search; objects of radius 0 are in exactly one cell.
// The grid only narrows the search: callers still test the exact distance, so
// the cell size never changes an answer.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sylva::env::collision {

using Point3 = std::array<float, 3>;

class UniformGrid {
 public:
  // `dimensions` is 2 (z ignored) or 3. `cell_hint` is the smallest useful
  // cell edge, typically the distance at which objects interact; cells may be
  // larger so that there are not many more cells than objects. `min_cells`
  // asks for at least that many cells along each axis (a program's "grid
  // size"), within the same limit.
  UniformGrid(std::span<const Point3> centres, std::span<const float> radii, int dimensions, float cell_hint,
              std::array<int, 3> min_cells = {1, 1, 1});

  // Calls visit(j) for every object whose cells overlap the box around
  // `centre` of half-size `reach`, until visit returns true (then returns true).
  template <class Visit>
  bool visit_near(const Point3& centre, float reach, Visit&& visit) const {
    if (objects_ == 0) return false;
    std::array<int, 3> lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      lo[a] = cell_of(a, centre[a] - reach);
      hi[a] = cell_of(a, centre[a] + reach);
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          std::size_t cell = index(x, y, z);
          for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k)
            if (visit(static_cast<std::size_t>(entries_[k]))) return true;
        }
    return false;
  }

  std::array<int, 3> cells() const { return cells_; }

 private:
  int cell_of(int axis, float coordinate) const {
    float offset = (coordinate - origin_[axis]) * inverse_size_[axis];
    if (!(offset > 0)) return 0;  // also NaN
    if (offset >= static_cast<float>(cells_[axis])) return cells_[axis] - 1;
    return static_cast<int>(offset);
  }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * cells_[1] + y) * cells_[0] + x;
  }

  std::size_t objects_ = 0;
  Point3 origin_{};
  Point3 inverse_size_{};
  std::array<int, 3> cells_{1, 1, 1};
  std::vector<std::uint32_t> cell_start_;  // cells + 1 offsets into entries_
  std::vector<std::uint32_t> entries_;     // object indices, cell by cell
};

}  // namespace sylva::env::collision
