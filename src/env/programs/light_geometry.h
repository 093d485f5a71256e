// Small vector and intersection helpers shared by chiba and takenaka.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace sylva::env::light {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

inline Vec3 to_vec3(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(Vec3 a) {
  double l = length(a);
  return l > 0 ? (1.0 / l) * a : a;
}

struct Sphere {
  Vec3 centre;
  double radius = 0;
};

// Where a ray from `origin` along the unit vector `direction` passes a point:
// how far along the ray (negative behind the origin) and how far from it.
struct RayOffset {
  double along = 0;
  double distance_squared = 0;
};

// Length of the part of the ray (from the origin on) inside a sphere of
// `radius` at the point described by `offset`; 0 when the ray misses it.
inline double chord_ahead(RayOffset offset, double radius) {
  double r2 = radius * radius;
  if (offset.distance_squared >= r2) return 0;
  double half = std::sqrt(r2 - offset.distance_squared);
  double exit = offset.along + half;
  if (exit <= 0) return 0;
  return exit - std::max(offset.along - half, 0.0);
}

// Area of the intersection of two disks of radii a and b whose centres are
// `d` apart.
inline double disk_overlap_area(double a, double b, double d) {
  if (a <= 0 || b <= 0 || d >= a + b) return 0;
  double small = std::min(a, b);
  if (d <= std::abs(a - b)) return std::numbers::pi * small * small;
  // The lens: two circular sectors less the kite between the two centres and
  // the two crossing points. Heron's formula gives the kite's area without
  // the sines of the sector angles.
  double kite = 0.5 * std::sqrt(std::max(0.0, (-d + a + b) * (d + a - b) * (d - a + b) * (d + a + b)));
  if (a == b) {  // both sectors alike: one acos
    return 2 * a * a * std::acos(std::clamp(d / (2 * a), -1.0, 1.0)) - kite;
  }
  double alpha = std::acos(std::clamp((d * d + a * a - b * b) / (2 * d * a), -1.0, 1.0));
  double beta = std::acos(std::clamp((d * d + b * b - a * a) / (2 * d * b), -1.0, 1.0));
  return a * a * alpha + b * b * beta - kite;
}

}  // namespace sylva::env::light
