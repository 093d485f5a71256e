// The vector types of lpfg (LPFG manual 6.3.1, A.6.13): V2f V2d V3f V3d.
//
// They come in two layers, so that models written for lpfg compile unchanged:
//   - the coordinates V2tf V2td V3tf V3td: x, y (, z) with the arithmetic and
//     no constructors, so they are aggregates and can be module parameters;
//   - V2f V2d V3f V3d, derived from them, adding the constructors. Each
//     converts implicitly from every coordinate type of its dimension (a V3d
//     from a V3f, a V3f from the V3tf a sum returns) and a V3 from a V2 (z = 0).
// The operators are friends of the coordinates, so arguments convert as in
// a call of an ordinary function (v * 2, 2.0 * v); a + b returns coordinates,
// which convert back on assignment. Normalize() divides by the length, as
// lpfg does, whatever the length.
//
// With NOAUTOOVERLOAD defined before lpfgall.h, a model gets plain structs
// with constructors and no operators (it defines its own), and V3tf is V3f.
// Both layers are trivially copyable, so modules carry them.
#pragma once

#include <cmath>

#ifndef NOAUTOOVERLOAD

namespace sylva::rt {

template <class S>
struct Coords2 {
  S x = 0, y = 0;

  void Set(S nx, S ny) { x = nx; y = ny; }
  S Length() const { return std::sqrt(x * x + y * y); }
  Coords2& Normalize() { return *this /= Length(); }
  Coords2 Normalized() const { Coords2 v = *this; return v /= Length(); }

  Coords2& operator+=(Coords2 o) { x += o.x; y += o.y; return *this; }
  Coords2& operator-=(Coords2 o) { x -= o.x; y -= o.y; return *this; }
  Coords2& operator*=(S k) { x *= k; y *= k; return *this; }
  Coords2& operator/=(S k) { x /= k; y /= k; return *this; }

  friend Coords2 operator-(Coords2 a) { return {-a.x, -a.y}; }
  friend Coords2 operator+(Coords2 a, Coords2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Coords2 operator-(Coords2 a, Coords2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Coords2 operator*(Coords2 a, S k) { return {a.x * k, a.y * k}; }
  friend Coords2 operator*(S k, Coords2 a) { return a * k; }
  friend Coords2 operator/(Coords2 a, S k) { return {a.x / k, a.y / k}; }
  // The dot product.
  friend S operator*(Coords2 a, Coords2 b) { return a.x * b.x + a.y * b.y; }
};

template <class S>
struct Coords3 {
  S x = 0, y = 0, z = 0;

  void Set(S nx, S ny, S nz) { x = nx; y = ny; z = nz; }
  S Length() const { return std::sqrt(x * x + y * y + z * z); }
  Coords3& Normalize() { return *this /= Length(); }
  Coords3 Normalized() const { Coords3 v = *this; return v /= Length(); }
  // A coordinate by number (0, 1, else 2), as a double as in lpfg.
  double operator[](int c) const { return c == 0 ? x : c == 1 ? y : z; }

  Coords3& operator+=(Coords3 o) { x += o.x; y += o.y; z += o.z; return *this; }
  Coords3& operator-=(Coords3 o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  Coords3& operator*=(S k) { x *= k; y *= k; z *= k; return *this; }
  Coords3& operator/=(S k) { x /= k; y /= k; z /= k; return *this; }

  friend Coords3 operator-(Coords3 a) { return {-a.x, -a.y, -a.z}; }
  friend Coords3 operator+(Coords3 a, Coords3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Coords3 operator-(Coords3 a, Coords3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Coords3 operator*(Coords3 a, S k) { return {a.x * k, a.y * k, a.z * k}; }
  friend Coords3 operator*(S k, Coords3 a) { return a * k; }
  friend Coords3 operator/(Coords3 a, S k) { return {a.x / k, a.y / k, a.z / k}; }
  // The dot product, and the cross product.
  friend S operator*(Coords3 a, Coords3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
  friend Coords3 operator%(Coords3 a, Coords3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  }
};

template <class S>
struct Vector2 : Coords2<S> {
  Vector2() = default;
  Vector2(S nx, S ny) : Coords2<S>{nx, ny} {}
  Vector2(const Coords2<float>& v) : Coords2<S>{static_cast<S>(v.x), static_cast<S>(v.y)} {}
  Vector2(const Coords2<double>& v) : Coords2<S>{static_cast<S>(v.x), static_cast<S>(v.y)} {}
};

template <class S>
struct Vector3 : Coords3<S> {
  Vector3() = default;
  Vector3(S nx, S ny, S nz) : Coords3<S>{nx, ny, nz} {}
  Vector3(const Coords3<float>& v) : Coords3<S>{static_cast<S>(v.x), static_cast<S>(v.y), static_cast<S>(v.z)} {}
  Vector3(const Coords3<double>& v) : Coords3<S>{static_cast<S>(v.x), static_cast<S>(v.y), static_cast<S>(v.z)} {}
  Vector3(const Coords2<float>& v) : Coords3<S>{static_cast<S>(v.x), static_cast<S>(v.y), 0} {}
  Vector3(const Coords2<double>& v) : Coords3<S>{static_cast<S>(v.x), static_cast<S>(v.y), 0} {}
};

}  // namespace sylva::rt

using V2tf = sylva::rt::Coords2<float>;
using V2td = sylva::rt::Coords2<double>;
using V3tf = sylva::rt::Coords3<float>;
using V3td = sylva::rt::Coords3<double>;
using V2f = sylva::rt::Vector2<float>;
using V2d = sylva::rt::Vector2<double>;
using V3f = sylva::rt::Vector3<float>;
using V3d = sylva::rt::Vector3<double>;

template <class Vector>
Vector Normalize(Vector v) {
  return v.Normalize();
}

#else  // NOAUTOOVERLOAD

namespace sylva::rt {

template <class S>
struct Vector2 {
  S x = 0, y = 0;
  Vector2() = default;
  Vector2(S nx, S ny) : x(nx), y(ny) {}
};

template <class S>
struct Vector3 {
  S x = 0, y = 0, z = 0;
  Vector3() = default;
  Vector3(S nx, S ny, S nz) : x(nx), y(ny), z(nz) {}
};

}  // namespace sylva::rt

using V2f = sylva::rt::Vector2<float>;
using V2d = sylva::rt::Vector2<double>;
using V3f = sylva::rt::Vector3<float>;
using V3d = sylva::rt::Vector3<double>;
using V2tf = V2f;
using V2td = V2d;
using V3tf = V3f;
using V3td = V3d;

inline V2f Normalize(V2f v) {
  const float l = std::sqrt(v.x * v.x + v.y * v.y);
  return V2f(v.x / l, v.y / l);
}
inline V2d Normalize(V2d v) {
  const double l = std::sqrt(v.x * v.x + v.y * v.y);
  return V2d(v.x / l, v.y / l);
}
inline V3f Normalize(V3f v) {
  const float l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return V3f(v.x / l, v.y / l, v.z / l);
}
inline V3d Normalize(V3d v) {
  const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return V3d(v.x / l, v.y / l, v.z / l);
}

#endif  // NOAUTOOVERLOAD

// lpfg's names of the plain structs its functions return (curveXYZ ...
// return V2f and V3f here, which convert to these).
using __lc_V2f = V2tf;
using __lc_V3f = V3tf;
using __lc_V2d = V2td;
using __lc_V3d = V3td;

namespace sylva::rt {
// How many coordinates a vector type has: 2 or 3, or 0 for any other type.
template <class T> inline constexpr int vector_size = 0;
template <> inline constexpr int vector_size<V2f> = 2;
template <> inline constexpr int vector_size<V2d> = 2;
template <> inline constexpr int vector_size<V3f> = 3;
template <> inline constexpr int vector_size<V3d> = 3;
#ifndef NOAUTOOVERLOAD
template <> inline constexpr int vector_size<V2tf> = 2;
template <> inline constexpr int vector_size<V2td> = 2;
template <> inline constexpr int vector_size<V3tf> = 3;
template <> inline constexpr int vector_size<V3td> = 3;
#endif
}  // namespace sylva::rt
