// The surfaces arvo's segments climb around: the obstacles of the background
// file and the objects the model adds, kept in a regular grid of voxels over
// the parameter file's domain so that a short ray tests only the objects in
// the voxels it passes. Objects reaching outside the domain are entered in
// its border voxels, so the grid never hides one; it only saves time.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "env/programs/arvo_geometry.h"

namespace sylva::env::arvo {

struct Hit {
  double t = 0;   // distance along the ray, in units of the direction's length
  Vec3 normal{};  // unit surface normal facing the ray's origin
};

// A triangle in world coordinates, or a sphere or capped cone frustum in a
// local frame: sphere of radius r1 at the origin; frustum along +y from y = 0
// (radius r1) to y = h (radius r2), a cylinder when r1 == r2.
struct Obstacle {
  enum class Kind { triangle, sphere, frustum };
  Kind kind = Kind::triangle;
  Vec3 a{}, b{}, c{};
  double r1 = 0, r2 = 0, h = 0;
  Mat4 to_world, to_local;
};

std::optional<Hit> intersect(const Obstacle& obstacle, const Vec3& origin, const Vec3& direction, double t_min,
                             double t_max);

struct Domain {
  Vec3 position{};             // the lower front left corner
  Vec3 size{1, 1, 1};          // extent along x, y, z
  std::array<int, 3> cells{1, 1, 1};
};

class ObstacleScene {
 public:
  void set_domain(const Domain& domain);

  void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c);
  // Singular transforms (a zero scale) make flat objects nothing can hit;
  // they are left out.
  void add_sphere(const Mat4& to_world, double radius);
  void add_frustum(const Mat4& to_world, double r1, double r2, double h);

  std::size_t size() const { return obstacles_.size(); }
  // Forgets the objects added after the first `count`.
  void truncate(std::size_t count);

  // The nearest surface the ray origin + t * direction meets with
  // t_min < t <= t_max.
  std::optional<Hit> closest(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const;

 private:
  struct Box {
    Vec3 lo, hi;
  };
  Box bounds_of(const Obstacle& obstacle) const;
  void build_grid() const;
  int cell_of(int axis, double coordinate) const;

  Domain domain_;
  std::vector<Obstacle> obstacles_;
  // The grid is rebuilt on the first ray after the objects change.
  mutable bool grid_stale_ = true;
  mutable std::vector<std::vector<std::uint32_t>> voxels_;
  mutable std::vector<std::uint32_t> seen_;  // per obstacle: the last ray that tested it
  mutable std::uint32_t ray_ = 0;
};

}  // namespace sylva::env::arvo
