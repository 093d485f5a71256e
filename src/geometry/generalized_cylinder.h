// Generalized cylinders (LPFG manual 5.8, CPFG manual 6.7.3): a contour swept
// along the turtle's path. The turtle places a ring of contour points at each
// control point, and in cpfg models `strips - 1` more between two control
// points along the Hermite curve through them; consecutive rings are joined
// by a band of triangles.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/vec3.h"

namespace sylva::geometry {

// The ring of a contour at a control point: contour point (x, y, z) goes to
// origin + left * (x * scale_left) + up * (y * scale_up) + heading * (z * scale_up).
void place_ring(const Vec3* contour, int sides, Vec3 origin, Vec3 heading, Vec3 left, Vec3 up, float scale_left,
                float scale_up, std::vector<Vec3>& positions);

// Appends the triangles joining ring `a` to ring `b` (each `sides` vertices
// from those first indices). A closed contour also joins its last point to
// its first. The triangles face outward for a contour running
// counter-clockwise in its (left, up) plane; `reverse` flips them.
void join_rings(std::uint32_t a, std::uint32_t b, int sides, bool closed, bool reverse,
                std::vector<std::uint32_t>& indices);

// A cubic Hermite segment from p0 to p1 with tangents m0 and m1:
// p(t) = h00(t) p0 + h10(t) m0 + h01(t) p1 + h11(t) m1, with
// h00 = 2t^3 - 3t^2 + 1, h10 = t^3 - 2t^2 + t, h01 = -2t^3 + 3t^2, h11 = t^3 - t^2.
struct HermiteSegment {
  Vec3 p0, m0, p1, m1;
  Vec3 at(float t) const;
  Vec3 derivative(float t) const;  // dp/dt
};

// A uniform cubic B-spline segment with control points q0..q3:
// p(t) = ((1-t)^3 q0 + (3t^3 - 6t^2 + 4) q1 + (-3t^3 + 3t^2 + 3t + 1) q2 + t^3 q3) / 6.
// It starts at (q0 + 4 q1 + q2) / 6 and ends at (q1 + 4 q2 + q3) / 6.
struct BSplineSegment {
  Vec3 q0, q1, q2, q3;
  Vec3 at(float t) const;
  Vec3 derivative(float t) const;  // dp/dt
};

// Twice the signed area of a contour in its plane: positive when it runs
// counter-clockwise.
float contour_orientation(const Vec3* contour, int sides);

}  // namespace sylva::geometry
