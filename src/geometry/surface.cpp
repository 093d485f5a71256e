#include "geometry/surface.h"

#include <array>
#include <cstddef>

namespace sylva::geometry {
namespace {

std::array<float, 4> bernstein(float t) {
  const float s = 1 - t;
  return {s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t};
}

std::array<float, 4> bernstein_derivative(float t) {
  const float s = 1 - t;
  return {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t};
}

// u runs along a row (the column index), v down the rows.
Vec3 combine(const BezierPatch& patch, const std::array<float, 4>& bu, const std::array<float, 4>& bv) {
  Vec3 p;
  for (std::size_t row = 0; row < 4; ++row)
    for (std::size_t col = 0; col < 4; ++col) p += patch.points[4 * row + col] * (bv[row] * bu[col]);
  return p;
}

Vec3 raw_normal(const BezierPatch& patch, float u, float v) {
  const Vec3 du = combine(patch, bernstein_derivative(u), bernstein(v));
  const Vec3 dv = combine(patch, bernstein(u), bernstein_derivative(v));
  return cross(du, dv);
}

}  // namespace

Vec3 evaluate_patch(const BezierPatch& patch, float u, float v) { return combine(patch, bernstein(u), bernstein(v)); }

Vec3 patch_normal(const BezierPatch& patch, float u, float v) {
  Vec3 n = raw_normal(patch, u, v);
  // Where a row or column of control points collapses (a leaf's tip) the
  // derivative vanishes; the normal there is the limit from inside the patch.
  for (float step = 1e-3f; dot(n, n) < 1e-20f && step <= 0.25f; step *= 4) {
    const float uu = u + (u < 0.5f ? step : -step);
    const float vv = v + (v < 0.5f ? step : -step);
    n = raw_normal(patch, uu, vv);
  }
  return dot(n, n) > 0 ? normalized(n) : Vec3{0, 0, 1};
}

}  // namespace sylva::geometry
