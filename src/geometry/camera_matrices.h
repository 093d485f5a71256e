// The OpenGL matrices the cameras are made of, column-major as OpenGL takes
// them: gluLookAt (with its basis already worked out), glOrtho, glFrustum;
// and the corners of a box, which cameras frame.
#pragma once

#include <array>

#include "geometry/camera.h"

namespace sylva::geometry {

inline Mat4 look_at(Vec3 eye, Vec3 f, Vec3 u, Vec3 r) {
  Mat4 m{};
  m[0] = r.x, m[4] = r.y, m[8] = r.z, m[12] = -dot(r, eye);
  m[1] = u.x, m[5] = u.y, m[9] = u.z, m[13] = -dot(u, eye);
  m[2] = -f.x, m[6] = -f.y, m[10] = -f.z, m[14] = dot(f, eye);
  m[15] = 1;
  return m;
}

inline Mat4 ortho(float l, float r, float b, float t, float n, float f) {
  Mat4 m{};
  m[0] = 2 / (r - l);
  m[5] = 2 / (t - b);
  m[10] = -2 / (f - n);
  m[12] = -(r + l) / (r - l);
  m[13] = -(t + b) / (t - b);
  m[14] = -(f + n) / (f - n);
  m[15] = 1;
  return m;
}

inline Mat4 frustum(float l, float r, float b, float t, float n, float f) {
  Mat4 m{};
  m[0] = 2 * n / (r - l);
  m[5] = 2 * n / (t - b);
  m[8] = (r + l) / (r - l);
  m[9] = (t + b) / (t - b);
  m[10] = -(f + n) / (f - n);
  m[11] = -1;
  m[14] = -2 * f * n / (f - n);
  return m;
}

inline std::array<Vec3, 8> corners(const Box& b) {
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i)
    c[i] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
  return c;
}

}  // namespace sylva::geometry
