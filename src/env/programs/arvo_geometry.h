// Small vector and matrix helpers for arvo's obstacles and rays.
#pragma once

#include <array>
#include <cmath>

namespace sylva::env::arvo {

using Vec3 = std::array<double, 3>;

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator*(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
// `a` of unit length; the zero vector stays zero.
inline Vec3 normalized(const Vec3& a) {
  double l = length(a);
  return l > 0 ? a * (1.0 / l) : a;
}

// A 4x4 affine matrix, column-major as the background file's loadmatrix
// writes it: m[c * 4 + r].
struct Mat4 {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  double at(int row, int column) const { return m[column * 4 + row]; }
  double& at(int row, int column) { return m[column * 4 + row]; }

  Vec3 point(const Vec3& p) const {
    return {at(0, 0) * p[0] + at(0, 1) * p[1] + at(0, 2) * p[2] + at(0, 3),
            at(1, 0) * p[0] + at(1, 1) * p[1] + at(1, 2) * p[2] + at(1, 3),
            at(2, 0) * p[0] + at(2, 1) * p[1] + at(2, 2) * p[2] + at(2, 3)};
  }
  Vec3 vector(const Vec3& v) const {
    return {at(0, 0) * v[0] + at(0, 1) * v[1] + at(0, 2) * v[2], at(1, 0) * v[0] + at(1, 1) * v[1] + at(1, 2) * v[2],
            at(2, 0) * v[0] + at(2, 1) * v[1] + at(2, 2) * v[2]};
  }
  // The transpose of the 3x3 part applied to v: normals go through the
  // transpose of the inverse.
  Vec3 transposed_vector(const Vec3& v) const {
    return {at(0, 0) * v[0] + at(1, 0) * v[1] + at(2, 0) * v[2], at(0, 1) * v[0] + at(1, 1) * v[1] + at(2, 1) * v[2],
            at(0, 2) * v[0] + at(1, 2) * v[1] + at(2, 2) * v[2]};
  }
};

Mat4 operator*(const Mat4& a, const Mat4& b);
Mat4 translation(const Vec3& t);
Mat4 scaling(const Vec3& s);
Mat4 rotation(double degrees, const Vec3& axis);
// The inverse of an affine matrix; false if it is singular.
bool affine_inverse(const Mat4& a, Mat4& inverse);
// The frame whose y axis is `axis_y` and whose z axis is as close to `toward_z`
// as can be, placed at `origin`: how an object made by a module sits on the
// turtle (cpfg draws cylinders along the turtle's heading, its local y).
Mat4 frame(const Vec3& origin, const Vec3& axis_y, const Vec3& toward_z);

}  // namespace sylva::env::arvo
