// The vector types of lpfg (LPFG manual 6.3.1): V2f, V2d, V3f, V3d.
//
// They are plain trivially copyable structs so they can be module parameters.
// Operators are defined unless NOAUTOOVERLOAD is defined before lpfgall.h.
#pragma once

#include <cmath>
#include <type_traits>

namespace sylva::rt {

template <class Scalar>
struct Vec2 {
  Scalar x = 0, y = 0;
  constexpr Vec2() = default;
  constexpr Vec2(Scalar x_, Scalar y_) : x(x_), y(y_) {}
  template <class Other>
  constexpr explicit Vec2(const Vec2<Other>& o) : x(Scalar(o.x)), y(Scalar(o.y)) {}
  void Set(Scalar x_, Scalar y_) { x = x_; y = y_; }
  Scalar Length() const { return std::sqrt(x * x + y * y); }
  Vec2& Normalize() {
    Scalar l = Length();
    if (l > 0) { x /= l; y /= l; }
    return *this;
  }
  Vec2 Normalized() const { Vec2 v = *this; return v.Normalize(); }
};

template <class Scalar>
struct Vec3 {
  Scalar x = 0, y = 0, z = 0;
  constexpr Vec3() = default;
  constexpr Vec3(Scalar x_, Scalar y_, Scalar z_) : x(x_), y(y_), z(z_) {}
  template <class Other>
  constexpr explicit Vec3(const Vec3<Other>& o) : x(Scalar(o.x)), y(Scalar(o.y)), z(Scalar(o.z)) {}
  void Set(Scalar x_, Scalar y_, Scalar z_) { x = x_; y = y_; z = z_; }
  Scalar Length() const { return std::sqrt(x * x + y * y + z * z); }
  Vec3& Normalize() {
    Scalar l = Length();
    if (l > 0) { x /= l; y /= l; z /= l; }
    return *this;
  }
  Vec3 Normalized() const { Vec3 v = *this; return v.Normalize(); }
};

}  // namespace sylva::rt

using V2f = sylva::rt::Vec2<float>;
using V2d = sylva::rt::Vec2<double>;
using V3f = sylva::rt::Vec3<float>;
using V3d = sylva::rt::Vec3<double>;

inline V2f Normalize(V2f v) { return v.Normalize(); }
inline V2d Normalize(V2d v) { return v.Normalize(); }
inline V3f Normalize(V3f v) { return v.Normalize(); }
inline V3d Normalize(V3d v) { return v.Normalize(); }

#ifndef NOAUTOOVERLOAD
namespace sylva::rt {

template <class S> Vec2<S> operator+(Vec2<S> a, Vec2<S> b) { return {S(a.x + b.x), S(a.y + b.y)}; }
template <class S> Vec2<S> operator-(Vec2<S> a, Vec2<S> b) { return {S(a.x - b.x), S(a.y - b.y)}; }
template <class S> Vec2<S> operator-(Vec2<S> a) { return {-a.x, -a.y}; }
template <class S> Vec2<S> operator*(Vec2<S> a, S k) { return {S(a.x * k), S(a.y * k)}; }
template <class S> Vec2<S> operator*(S k, Vec2<S> a) { return a * k; }
template <class S> Vec2<S> operator/(Vec2<S> a, S k) { return {S(a.x / k), S(a.y / k)}; }
template <class S> S operator*(Vec2<S> a, Vec2<S> b) { return a.x * b.x + a.y * b.y; }
template <class S> Vec2<S>& operator+=(Vec2<S>& a, Vec2<S> b) { return a = a + b; }
template <class S> Vec2<S>& operator-=(Vec2<S>& a, Vec2<S> b) { return a = a - b; }
template <class S> Vec2<S>& operator*=(Vec2<S>& a, S k) { return a = a * k; }
template <class S> Vec2<S>& operator/=(Vec2<S>& a, S k) { return a = a / k; }
template <class S> bool operator==(Vec2<S> a, Vec2<S> b) { return a.x == b.x && a.y == b.y; }

template <class S> Vec3<S> operator+(Vec3<S> a, Vec3<S> b) { return {S(a.x + b.x), S(a.y + b.y), S(a.z + b.z)}; }
template <class S> Vec3<S> operator-(Vec3<S> a, Vec3<S> b) { return {S(a.x - b.x), S(a.y - b.y), S(a.z - b.z)}; }
template <class S> Vec3<S> operator-(Vec3<S> a) { return {-a.x, -a.y, -a.z}; }
template <class S> Vec3<S> operator*(Vec3<S> a, S k) { return {S(a.x * k), S(a.y * k), S(a.z * k)}; }
template <class S> Vec3<S> operator*(S k, Vec3<S> a) { return a * k; }
template <class S> Vec3<S> operator/(Vec3<S> a, S k) { return {S(a.x / k), S(a.y / k), S(a.z / k)}; }
template <class S> S operator*(Vec3<S> a, Vec3<S> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class S> Vec3<S> operator%(Vec3<S> a, Vec3<S> b) {
  return {S(a.y * b.z - a.z * b.y), S(a.z * b.x - a.x * b.z), S(a.x * b.y - a.y * b.x)};
}
template <class S> Vec3<S>& operator+=(Vec3<S>& a, Vec3<S> b) { return a = a + b; }
template <class S> Vec3<S>& operator-=(Vec3<S>& a, Vec3<S> b) { return a = a - b; }
template <class S> Vec3<S>& operator*=(Vec3<S>& a, S k) { return a = a * k; }
template <class S> Vec3<S>& operator/=(Vec3<S>& a, S k) { return a = a / k; }
template <class S> bool operator==(Vec3<S> a, Vec3<S> b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// Scalars of another arithmetic type (a V3f times a double literal) convert
// to the vector's scalar type, as lpfg's non-template overloads do.
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec2<S> operator*(Vec2<S> a, K k) { return a * S(k); }
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec2<S> operator*(K k, Vec2<S> a) { return a * S(k); }
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec2<S> operator/(Vec2<S> a, K k) { return a / S(k); }
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec2<S>& operator*=(Vec2<S>& a, K k) { return a *= S(k); }
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec2<S>& operator/=(Vec2<S>& a, K k) { return a /= S(k); }
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec3<S> operator*(Vec3<S> a, K k) { return a * S(k); }
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec3<S> operator*(K k, Vec3<S> a) { return a * S(k); }
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec3<S> operator/(Vec3<S> a, K k) { return a / S(k); }
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec3<S>& operator*=(Vec3<S>& a, K k) { return a *= S(k); }
template <class S, class K, class = std::enable_if_t<std::is_arithmetic_v<K> && !std::is_same_v<S, K>>>
Vec3<S>& operator/=(Vec3<S>& a, K k) { return a /= S(k); }

}  // namespace sylva::rt
#endif
