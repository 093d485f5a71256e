#include "env/programs/arvo_geometry.h"

#include <numbers>

namespace sylva::env::arvo {

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 product;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += a.at(r, k) * b.at(k, c);
      product.at(r, c) = sum;
    }
  return product;
}

Mat4 translation(const Vec3& t) {
  Mat4 m;
  for (int r = 0; r < 3; ++r) m.at(r, 3) = t[r];
  return m;
}

Mat4 scaling(const Vec3& s) {
  Mat4 m;
  for (int r = 0; r < 3; ++r) m.at(r, r) = s[r];
  return m;
}

Mat4 rotation(double degrees, const Vec3& axis) {
  Vec3 u = normalized(axis);
  double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a), t = 1 - c;
  Mat4 m;
  m.at(0, 0) = t * u[0] * u[0] + c;
  m.at(0, 1) = t * u[0] * u[1] - s * u[2];
  m.at(0, 2) = t * u[0] * u[2] + s * u[1];
  m.at(1, 0) = t * u[0] * u[1] + s * u[2];
  m.at(1, 1) = t * u[1] * u[1] + c;
  m.at(1, 2) = t * u[1] * u[2] - s * u[0];
  m.at(2, 0) = t * u[0] * u[2] - s * u[1];
  m.at(2, 1) = t * u[1] * u[2] + s * u[0];
  m.at(2, 2) = t * u[2] * u[2] + c;
  return m;
}

bool affine_inverse(const Mat4& a, Mat4& inverse) {
  // Inverse of the 3x3 part by cofactors, then the translation.
  auto e = [&](int r, int c) { return a.at(r, c); };
  double c00 = e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1);
  double c01 = e(1, 2) * e(2, 0) - e(1, 0) * e(2, 2);
  double c02 = e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0);
  double det = e(0, 0) * c00 + e(0, 1) * c01 + e(0, 2) * c02;
  if (std::abs(det) < 1e-300) return false;
  double inv = 1.0 / det;
  Mat4 m;
  m.at(0, 0) = c00 * inv;
  m.at(0, 1) = (e(0, 2) * e(2, 1) - e(0, 1) * e(2, 2)) * inv;
  m.at(0, 2) = (e(0, 1) * e(1, 2) - e(0, 2) * e(1, 1)) * inv;
  m.at(1, 0) = c01 * inv;
  m.at(1, 1) = (e(0, 0) * e(2, 2) - e(0, 2) * e(2, 0)) * inv;
  m.at(1, 2) = (e(0, 2) * e(1, 0) - e(0, 0) * e(1, 2)) * inv;
  m.at(2, 0) = c02 * inv;
  m.at(2, 1) = (e(0, 1) * e(2, 0) - e(0, 0) * e(2, 1)) * inv;
  m.at(2, 2) = (e(0, 0) * e(1, 1) - e(0, 1) * e(1, 0)) * inv;
  Vec3 t{e(0, 3), e(1, 3), e(2, 3)};
  Vec3 moved = m.vector(t);
  for (int r = 0; r < 3; ++r) m.at(r, 3) = -moved[r];
  inverse = m;
  return true;
}

Mat4 frame(const Vec3& origin, const Vec3& axis_y, const Vec3& toward_z) {
  Vec3 y = normalized(axis_y);
  Vec3 z = toward_z - y * dot(toward_z, y);
  if (length(z) < 1e-9) z = std::abs(y[0]) < 0.9 ? Vec3{1, 0, 0} - y * y[0] : Vec3{0, 0, 1} - y * y[2];
  z = normalized(z);
  Vec3 x = cross(y, z);
  Mat4 m;
  for (int r = 0; r < 3; ++r) {
    m.at(r, 0) = x[r];
    m.at(r, 1) = y[r];
    m.at(r, 2) = z[r];
    m.at(r, 3) = origin[r];
  }
  return m;
}

}  // namespace sylva::env::arvo
