#include "geometry/generalized_cylinder.h"

namespace sylva::geometry {

void place_ring(const Vec3* contour, int sides, Vec3 origin, Vec3 heading, Vec3 left, Vec3 up, float scale_left,
                float scale_up, std::vector<Vec3>& positions) {
  const Vec3 l = left * scale_left, u = up * scale_up, h = heading * scale_up;
  for (int i = 0; i < sides; ++i) {
    const Vec3 c = contour[i];
    positions.push_back(origin + l * c.x + u * c.y + h * c.z);
  }
}

void join_rings(std::uint32_t a, std::uint32_t b, int sides, bool closed, bool reverse,
                std::vector<std::uint32_t>& indices) {
  const int bands = closed ? sides : sides - 1;
  for (int i = 0; i < bands; ++i) {
    const auto i0 = static_cast<std::uint32_t>(i);
    const auto i1 = static_cast<std::uint32_t>((i + 1) % sides);
    const std::uint32_t p = a + i0, q = a + i1, r = b + i1, s = b + i0;
    if (reverse) indices.insert(indices.end(), {p, r, q, p, s, r});
    else indices.insert(indices.end(), {p, q, r, p, r, s});
  }
}

Vec3 HermiteSegment::at(float t) const {
  const float t2 = t * t, t3 = t2 * t;
  return p0 * (2 * t3 - 3 * t2 + 1) + m0 * (t3 - 2 * t2 + t) + p1 * (-2 * t3 + 3 * t2) + m1 * (t3 - t2);
}

Vec3 HermiteSegment::derivative(float t) const {
  const float t2 = t * t;
  return p0 * (6 * t2 - 6 * t) + m0 * (3 * t2 - 4 * t + 1) + p1 * (-6 * t2 + 6 * t) + m1 * (3 * t2 - 2 * t);
}

Vec3 BSplineSegment::at(float t) const {
  const float t2 = t * t, t3 = t2 * t, u = 1 - t;
  return (q0 * (u * u * u) + q1 * (3 * t3 - 6 * t2 + 4) + q2 * (-3 * t3 + 3 * t2 + 3 * t + 1) + q3 * t3) / 6.0f;
}

Vec3 BSplineSegment::derivative(float t) const {
  const float t2 = t * t, u = 1 - t;
  return (q0 * (-3 * u * u) + q1 * (9 * t2 - 12 * t) + q2 * (-9 * t2 + 6 * t + 3) + q3 * (3 * t2)) / 6.0f;
}

float contour_orientation(const Vec3* contour, int sides) {
  float twice_area = 0;
  for (int i = 0; i < sides; ++i) {
    const Vec3 p = contour[i], q = contour[(i + 1) % sides];
    twice_area += p.x * q.y - q.x * p.y;
  }
  return twice_area;
}

}  // namespace sylva::geometry
