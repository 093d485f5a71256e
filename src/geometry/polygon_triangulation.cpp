#include "geometry/polygon_triangulation.h"

#include <algorithm>
#include <cmath>

namespace sylva::geometry {
namespace {

struct Projected {
  double a = 0, b = 0;
};

// Coordinates in the plane of the two axes other than `drop`, taken in cyclic
// order so that the projection keeps the orientation seen from +drop.
Projected project(Vec3 p, int drop) {
  switch (drop) {
    case 0: return {p.y, p.z};
    case 1: return {p.z, p.x};
    default: return {p.x, p.y};
  }
}

double cross2(Projected o, Projected p, Projected q) { return (p.a - o.a) * (q.b - o.b) - (p.b - o.b) * (q.a - o.a); }

}  // namespace

Vec3 newell_normal(const Vec3* points, std::size_t count) {
  double x = 0, y = 0, z = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 p = points[i], q = points[(i + 1) % count];
    x += (static_cast<double>(p.y) - q.y) * (static_cast<double>(p.z) + q.z);
    y += (static_cast<double>(p.z) - q.z) * (static_cast<double>(p.x) + q.x);
    z += (static_cast<double>(p.x) - q.x) * (static_cast<double>(p.y) + q.y);
  }
  return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}

std::size_t triangulate_polygon(const Vec3* points, std::size_t count, std::uint32_t base,
                                std::vector<std::uint32_t>& triangles, std::vector<std::uint32_t>& work) {
  if (count < 3) return 0;
  const Vec3 normal = newell_normal(points, count);
  const float ax = std::fabs(normal.x), ay = std::fabs(normal.y), az = std::fabs(normal.z);
  if (ax == 0 && ay == 0 && az == 0) return 0;
  const int drop = az >= ax && az >= ay ? 2 : (ay >= ax ? 1 : 0);
  const double sign = (drop == 0 ? normal.x : drop == 1 ? normal.y : normal.z) > 0 ? 1.0 : -1.0;

  double extent = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const Projected p = project(points[i] - points[0], drop);
    extent = std::max({extent, std::fabs(p.a), std::fabs(p.b)});
  }
  // Points the turtle reaches by different turns carry float noise: a polygon
  // closed on its first point ends a hair away from it. Such points are one
  // point, and the slivers between them no triangles.
  const float same = static_cast<float>(1e-6 * extent);
  const double eps = 1e-8 * extent * extent;
  auto coincide = [&](std::uint32_t i, std::uint32_t j) { return length(points[i] - points[j]) <= same; };

  work.clear();
  for (std::size_t i = 0; i < count; ++i)
    if (work.empty() || !coincide(static_cast<std::uint32_t>(i), work.back()))
      work.push_back(static_cast<std::uint32_t>(i));
  while (work.size() > 1 && coincide(work.back(), work.front())) work.pop_back();
  if (work.size() < 3) return 0;

  auto at = [&](std::uint32_t i) { return project(points[i], drop); };

  std::size_t made = 0;
  auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    triangles.insert(triangles.end(), {base + a, base + b, base + c});
    ++made;
  };
  auto inside = [&](Projected p, Projected a, Projected b, Projected c) {
    return sign * cross2(a, b, p) >= -eps && sign * cross2(b, c, p) >= -eps && sign * cross2(c, a, p) >= -eps;
  };

  std::size_t i = 0, misses = 0;
  while (work.size() > 3) {
    const std::size_t n = work.size();
    const std::uint32_t prev = work[(i + n - 1) % n], cur = work[i], next = work[(i + 1) % n];
    const Projected p = at(prev), c = at(cur), q = at(next);
    const double turn = sign * cross2(p, c, q);
    bool clip = std::fabs(turn) <= eps;  // collinear: the vertex adds nothing
    if (!clip && turn > 0) {
      clip = true;
      for (std::size_t k = 0; k < n && clip; ++k) {
        const std::uint32_t other = work[k];
        if (other == prev || other == cur || other == next) continue;
        if (coincide(other, prev) || coincide(other, cur) || coincide(other, next)) continue;
        if (inside(at(other), p, c, q)) clip = false;
      }
      if (clip) emit(prev, cur, next);
    }
    if (clip) {
      work.erase(work.begin() + static_cast<std::ptrdiff_t>(i));
      if (i >= work.size()) i = 0;
      misses = 0;
      continue;
    }
    i = (i + 1) % n;
    if (++misses > n) {
      // No ear left: the polygon crosses itself. Fan what remains.
      for (std::size_t k = 1; k + 1 < work.size(); ++k) emit(work[0], work[k], work[k + 1]);
      return made;
    }
  }
  if (std::fabs(cross2(at(work[0]), at(work[1]), at(work[2]))) > eps) emit(work[0], work[1], work[2]);
  return made;
}

}  // namespace sylva::geometry
