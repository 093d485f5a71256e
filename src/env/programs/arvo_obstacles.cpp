#include "env/programs/arvo_obstacles.h"

#include <algorithm>
#include <limits>

namespace sylva::env::arvo {
namespace {

// Voxels beyond this many are merged: a grid far finer than the objects
// costs memory without saving time.
constexpr double kMaxVoxels = 1 << 21;

Vec3 facing(Vec3 normal, const Vec3& direction) {
  normal = normalized(normal);
  return dot(normal, direction) > 0 ? normal * -1.0 : normal;
}

std::optional<Hit> intersect_triangle(const Obstacle& o, const Vec3& origin, const Vec3& direction, double t_min,
                                      double t_max) {
  // Möller–Trumbore.
  Vec3 e1 = o.b - o.a, e2 = o.c - o.a;
  Vec3 p = cross(direction, e2);
  double det = dot(e1, p);
  if (std::abs(det) < 1e-14) return std::nullopt;
  double inv = 1.0 / det;
  Vec3 s = origin - o.a;
  double u = dot(s, p) * inv;
  if (u < 0 || u > 1) return std::nullopt;
  Vec3 q = cross(s, e1);
  double v = dot(direction, q) * inv;
  if (v < 0 || u + v > 1) return std::nullopt;
  double t = dot(e2, q) * inv;
  if (t <= t_min || t > t_max) return std::nullopt;
  return Hit{t, facing(cross(e1, e2), direction)};
}

// Local-frame intersections: the ray is already in the object's frame.
void consider(double t, const Vec3& local_normal, double t_min, double t_max, std::optional<Hit>& best,
              Vec3& best_local_normal) {
  if (t <= t_min || t > t_max || (best && t >= best->t)) return;
  best = Hit{t, {}};
  best_local_normal = local_normal;
}

void sphere_hits(const Obstacle& o, const Vec3& p, const Vec3& d, double t_min, double t_max,
                 std::optional<Hit>& best, Vec3& normal) {
  double a = dot(d, d), b = 2 * dot(p, d), c = dot(p, p) - o.r1 * o.r1;
  double disc = b * b - 4 * a * c;
  if (a <= 0 || disc < 0) return;
  double root = std::sqrt(disc);
  for (double t : {(-b - root) / (2 * a), (-b + root) / (2 * a)}) consider(t, p + d * t, t_min, t_max, best, normal);
}

void frustum_hits(const Obstacle& o, const Vec3& p, const Vec3& d, double t_min, double t_max,
                  std::optional<Hit>& best, Vec3& normal) {
  // Side: x^2 + z^2 = (r1 + k y)^2 for 0 <= y <= h.
  double k = (o.r2 - o.r1) / o.h;
  double base = o.r1 + k * p[1];
  double a = d[0] * d[0] + d[2] * d[2] - k * k * d[1] * d[1];
  double b = 2 * (p[0] * d[0] + p[2] * d[2] - k * base * d[1]);
  double c = p[0] * p[0] + p[2] * p[2] - base * base;
  auto side = [&](double t) {
    Vec3 x = p + d * t;
    double r = o.r1 + k * x[1];
    if (x[1] < 0 || x[1] > o.h || r < 0) return;
    consider(t, {x[0], -k * r, x[2]}, t_min, t_max, best, normal);
  };
  if (std::abs(a) > 1e-14) {
    double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      double root = std::sqrt(disc);
      side((-b - root) / (2 * a));
      side((-b + root) / (2 * a));
    }
  } else if (std::abs(b) > 1e-14) {
    side(-c / b);
  }
  // Caps: the discs y = 0 (radius r1) and y = h (radius r2).
  if (std::abs(d[1]) > 1e-14) {
    for (auto [y, r, ny] : {std::array<double, 3>{0, o.r1, -1}, std::array<double, 3>{o.h, o.r2, 1}}) {
      double t = (y - p[1]) / d[1];
      Vec3 x = p + d * t;
      if (x[0] * x[0] + x[2] * x[2] <= r * r) consider(t, {0, ny, 0}, t_min, t_max, best, normal);
    }
  }
}

}  // namespace

std::optional<Hit> intersect(const Obstacle& obstacle, const Vec3& origin, const Vec3& direction, double t_min,
                             double t_max) {
  if (obstacle.kind == Obstacle::Kind::triangle) return intersect_triangle(obstacle, origin, direction, t_min, t_max);
  // The same t in both frames: the direction is mapped without normalising.
  Vec3 p = obstacle.to_local.point(origin), d = obstacle.to_local.vector(direction);
  std::optional<Hit> best;
  Vec3 local_normal{};
  if (obstacle.kind == Obstacle::Kind::sphere)
    sphere_hits(obstacle, p, d, t_min, t_max, best, local_normal);
  else
    frustum_hits(obstacle, p, d, t_min, t_max, best, local_normal);
  if (best) best->normal = facing(obstacle.to_local.transposed_vector(local_normal), direction);
  return best;
}

void ObstacleScene::set_domain(const Domain& domain) {
  domain_ = domain;
  for (int a = 0; a < 3; ++a) domain_.cells[a] = std::max(domain_.cells[a], 1);
  double total = 1;
  for (int a = 0; a < 3; ++a) total *= domain_.cells[a];
  while (total > kMaxVoxels) {
    total = 1;
    for (int a = 0; a < 3; ++a) total *= (domain_.cells[a] = std::max(1, (domain_.cells[a] + 1) / 2));
  }
  grid_stale_ = true;
}

void ObstacleScene::add_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  Obstacle o;
  o.kind = Obstacle::Kind::triangle;
  o.a = a;
  o.b = b;
  o.c = c;
  obstacles_.push_back(o);
  grid_stale_ = true;
}

void ObstacleScene::add_sphere(const Mat4& to_world, double radius) {
  Obstacle o;
  o.kind = Obstacle::Kind::sphere;
  o.r1 = radius;
  o.to_world = to_world;
  if (radius <= 0 || !affine_inverse(to_world, o.to_local)) return;
  obstacles_.push_back(o);
  grid_stale_ = true;
}

void ObstacleScene::add_frustum(const Mat4& to_world, double r1, double r2, double h) {
  Obstacle o;
  o.kind = Obstacle::Kind::frustum;
  o.r1 = r1;
  o.r2 = r2;
  o.h = h;
  o.to_world = to_world;
  if (h <= 0 || (r1 <= 0 && r2 <= 0) || r1 < 0 || r2 < 0 || !affine_inverse(to_world, o.to_local)) return;
  obstacles_.push_back(o);
  grid_stale_ = true;
}

void ObstacleScene::truncate(std::size_t count) {
  if (count >= obstacles_.size()) return;
  obstacles_.resize(count);
  grid_stale_ = true;
}

ObstacleScene::Box ObstacleScene::bounds_of(const Obstacle& o) const {
  Box box{{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()},
          {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(),
           std::numeric_limits<double>::lowest()}};
  auto add = [&](const Vec3& p) {
    for (int a = 0; a < 3; ++a) {
      box.lo[a] = std::min(box.lo[a], p[a]);
      box.hi[a] = std::max(box.hi[a], p[a]);
    }
  };
  if (o.kind == Obstacle::Kind::triangle) {
    add(o.a);
    add(o.b);
    add(o.c);
    return box;
  }
  double r = std::max(o.r1, o.r2);
  Vec3 lo = o.kind == Obstacle::Kind::sphere ? Vec3{-r, -r, -r} : Vec3{-r, 0, -r};
  Vec3 hi = o.kind == Obstacle::Kind::sphere ? Vec3{r, r, r} : Vec3{r, o.h, r};
  for (int corner = 0; corner < 8; ++corner)
    add(o.to_world.point({corner & 1 ? hi[0] : lo[0], corner & 2 ? hi[1] : lo[1], corner & 4 ? hi[2] : lo[2]}));
  return box;
}

int ObstacleScene::cell_of(int axis, double coordinate) const {
  double offset = (coordinate - domain_.position[axis]) / domain_.size[axis] * domain_.cells[axis];
  if (!(offset > 0) || domain_.size[axis] <= 0) return 0;
  if (offset >= domain_.cells[axis]) return domain_.cells[axis] - 1;
  return static_cast<int>(offset);
}

void ObstacleScene::build_grid() const {
  const auto& n = domain_.cells;
  voxels_.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], {});
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    Box box = bounds_of(obstacles_[i]);
    for (int z = cell_of(2, box.lo[2]); z <= cell_of(2, box.hi[2]); ++z)
      for (int y = cell_of(1, box.lo[1]); y <= cell_of(1, box.hi[1]); ++y)
        for (int x = cell_of(0, box.lo[0]); x <= cell_of(0, box.hi[0]); ++x)
          voxels_[(static_cast<std::size_t>(z) * n[1] + y) * n[0] + x].push_back(static_cast<std::uint32_t>(i));
  }
  seen_.assign(obstacles_.size(), 0);
  ray_ = 0;
  grid_stale_ = false;
}

std::optional<Hit> ObstacleScene::closest(const Vec3& origin, const Vec3& direction, double t_min,
                                          double t_max) const {
  if (obstacles_.empty()) return std::nullopt;
  if (grid_stale_) build_grid();
  if (++ray_ == 0) {  // the stamps wrapped around
    std::fill(seen_.begin(), seen_.end(), 0);
    ray_ = 1;
  }
  Vec3 from = origin + direction * t_min, to = origin + direction * t_max;
  std::array<int, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = cell_of(a, std::min(from[a], to[a]));
    hi[a] = cell_of(a, std::max(from[a], to[a]));
  }
  const auto& n = domain_.cells;
  std::optional<Hit> best;
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x)
        for (std::uint32_t i : voxels_[(static_cast<std::size_t>(z) * n[1] + y) * n[0] + x]) {
          if (seen_[i] == ray_) continue;
          seen_[i] = ray_;
          auto hit = intersect(obstacles_[i], origin, direction, t_min, best ? best->t : t_max);
          if (hit && (!best || hit->t < best->t)) best = hit;
        }
  return best;
}

}  // namespace sylva::env::arvo
