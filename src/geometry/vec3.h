// Small fixed-size vector math for geometry: positions, directions, colours.
#pragma once

#include <cmath>

namespace sylva::geometry {

struct Vec3 {
  float x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}

  constexpr Vec3 operator+(Vec3 o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(Vec3 o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(float k) const { return {x * k, y * k, z * k}; }
  constexpr Vec3 operator/(float k) const { return {x / k, y / k, z / k}; }
  Vec3& operator+=(Vec3 o) { return *this = *this + o; }
  Vec3& operator-=(Vec3 o) { return *this = *this - o; }
  Vec3& operator*=(float k) { return *this = *this * k; }
  constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator*(float k, Vec3 v) { return v * k; }
constexpr float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline float length(Vec3 v) { return std::sqrt(dot(v, v)); }
inline Vec3 normalized(Vec3 v) {
  float l = length(v);
  return l > 0 ? v / l : v;
}

struct Vec2 {
  float x = 0, y = 0;
  constexpr bool operator==(const Vec2&) const = default;
};

// An axis-aligned box; empty until a point is added.
struct Box {
  Vec3 min{INFINITY, INFINITY, INFINITY};
  Vec3 max{-INFINITY, -INFINITY, -INFINITY};

  bool empty() const { return min.x > max.x; }
  void add(Vec3 p) {
    min = {std::fmin(min.x, p.x), std::fmin(min.y, p.y), std::fmin(min.z, p.z)};
    max = {std::fmax(max.x, p.x), std::fmax(max.y, p.y), std::fmax(max.z, p.z)};
  }
  void add(const Box& b) {
    if (!b.empty()) {
      add(b.min);
      add(b.max);
    }
  }
  Vec3 center() const { return (min + max) * 0.5f; }
  Vec3 size() const { return max - min; }
};

}  // namespace sylva::geometry
