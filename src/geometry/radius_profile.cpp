#include "geometry/radius_profile.h"

#include <cmath>

namespace sylva::geometry {

float stretch_radius(const RadiusTangents& tangents, float r0, float r1, float distance, float t) {
  if (!tangents.given) return r0 * (1 - t) + r1 * t;
  const double kDegree = 3.14159265358979323846 / 180;
  const double extent = tangents.adjust || distance <= 0 ? 1.0 : distance;
  const double m0x = tangents.length1 * std::cos(tangents.angle1 * kDegree);
  const double m0y = tangents.length1 * std::sin(tangents.angle1 * kDegree);
  const double m1x = tangents.length2 * std::cos(tangents.angle2 * kDegree);
  const double m1y = tangents.length2 * std::sin(tangents.angle2 * kDegree);
  auto x_at = [&](double u) {
    const double u2 = u * u, u3 = u2 * u;
    return (u3 - 2 * u2 + u) * m0x + (-2 * u3 + 3 * u2) * extent + (u3 - u2) * m1x;
  };
  // x(0) = 0 and x(1) = extent, so bisection finds a parameter where the
  // curve is t of the way along, whatever the tangents.
  const double target = t * extent;
  double lo = 0, hi = 1;
  for (int k = 0; k < 50; ++k) {
    const double mid = (lo + hi) / 2;
    (x_at(mid) < target ? lo : hi) = mid;
  }
  const double u = (lo + hi) / 2, u2 = u * u, u3 = u2 * u;
  return static_cast<float>((2 * u3 - 3 * u2 + 1) * r0 + (u3 - 2 * u2 + u) * m0y + (-2 * u3 + 3 * u2) * r1 +
                            (u3 - u2) * m1y);
}

}  // namespace sylva::geometry
