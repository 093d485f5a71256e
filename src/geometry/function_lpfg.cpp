// lpfg's evaluation of a graphically defined function (see function.h), in
// float and in lpfg's order of operations, so the values agree to the bit.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "geometry/function.h"

namespace sylva::geometry {
namespace {

constexpr std::size_t kOrder = 4;  // cubic

// The cubic B-spline over `points` with knots 0,0,0,0, 1, 2, ..., m,m,m,m
// (m = points - 3), evaluated by the Cox-de Boor recursion on a parameter
// u = d m for d in [0,1], all in float.
class LpfgSpline {
 public:
  explicit LpfgSpline(const std::vector<Vec2>& points) : p_(points), last_(points.size() - 1) {}

  Vec2 point(float d) const {
    const float u = d * static_cast<float>(last_ - kOrder + 2);
    Vec2 sum;
    for (std::size_t k = 0; k <= last_; ++k) {
      const float n = basis(k, kOrder, u);
      sum.x += p_[k].x * n;
      sum.y += p_[k].y * n;
    }
    return sum;
  }

  // The derivative by u: each basis function's derivative is a difference
  // of two of order 3, weighted as lpfg weighs them (in double).
  Vec2 derivative(float d) const {
    const float u = d * static_cast<float>(last_ - kOrder + 2);
    Vec2 sum;
    for (std::size_t k = 0; k <= last_; ++k) {
      float n = 0;
      int span = static_cast<int>(knot(k + kOrder - 1) - knot(k));
      if (span > 0) n += ((kOrder - 1.0) / span) * basis(k, kOrder - 1, u);
      span = static_cast<int>(knot(k + kOrder) - knot(k + 1));
      if (span > 0) n -= ((kOrder - 1.0) / span) * basis(k + 1, kOrder - 1, u);
      sum.x += p_[k].x * n;
      sum.y += p_[k].y * n;
    }
    return sum;
  }

 private:
  std::size_t knot(std::size_t j) const {
    if (j < kOrder) return 0;
    if (j > last_) return last_ - kOrder + 2;
    return j - kOrder + 1;
  }

  float basis(std::size_t k, std::size_t order, float u) const {
    if (order == 1) return static_cast<float>(knot(k)) <= u && u < static_cast<float>(knot(k + 1)) ? 1.0f : 0.0f;
    float sum = 0.0f;
    const std::size_t start = knot(k);
    std::size_t span = knot(k + order - 1) - start;
    if (span != 0) sum = (u - static_cast<float>(start)) / static_cast<float>(span) * basis(k, order - 1, u);
    const std::size_t end = knot(k + order);
    span = end - knot(k + 1);
    if (span != 0) sum += (static_cast<float>(end) - u) / static_cast<float>(span) * basis(k + 1, order - 1, u);
    return sum;
  }

  const std::vector<Vec2>& p_;
  std::size_t last_;
};

// The spline parameter whose point has x within `tolerance` of x, by
// bisection of [0,1] (lpfg returns the last midpoint tried). A curve that
// never reaches x (its points end short of it) stops where bisection can go
// no further.
float parameter_at(const LpfgSpline& spline, float x, float tolerance) {
  float low = 0.0f, high = 1.0f, middle = 0.5f;
  for (int step = 0; step < 200; ++step) {
    middle = (low + high) / 2.0f;
    const float found = spline.point(middle).x;
    if (found > x) high = middle;
    else low = middle;
    if (!(std::fabs(found - x) > tolerance)) break;
  }
  return middle;
}

// Linear interpolation in a table of `n` values at v (0 <= v <= 1), as lpfg
// computes it.
template <class T, class Mix>
T interpolate(const std::vector<T>& table, float v, Mix mix) {
  const std::size_t n = table.size();
  const float index = v * static_cast<float>(n - 1);
  const std::size_t i = static_cast<std::size_t>(std::floor(index));
  const float w1 = 1 - index + static_cast<float>(i);
  const float w2 = index - static_cast<float>(i);
  if (i >= n - 1) return table[n - 1];
  return mix(w1, table[i], w2, table[i + 1]);
}

float clamped(float v) { return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v == v ? v : 0.0f; }

}  // namespace

LpfgFunction::LpfgFunction(const Function& f) : points_(f.points) {
  if (points_.size() < kOrder) return;
  const int samples = std::clamp(f.samples, kMinSamples, kMaxSamples);
  const LpfgSpline spline(points_);
  const float tolerance = 0.01f / static_cast<float>(samples);
  values_.resize(static_cast<std::size_t>(samples));
  tangents_.resize(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) {
    const float t = parameter_at(spline, static_cast<float>(i) / static_cast<float>(samples - 1), tolerance);
    values_[static_cast<std::size_t>(i)] = spline.point(t).y;
    tangents_[static_cast<std::size_t>(i)] = spline.derivative(t);
  }
}

float LpfgFunction::value(float v) const {
  if (values_.empty()) return 0.0f;
  return interpolate(values_, clamped(v), [](float w1, float a, float w2, float b) { return w1 * a + w2 * b; });
}

Vec2 LpfgFunction::tangent(float v) const {
  if (tangents_.empty()) return {};
  return interpolate(tangents_, clamped(v), [](float w1, Vec2 a, float w2, Vec2 b) {
    return Vec2{w1 * a.x + w2 * b.x, w1 * a.y + w2 * b.y};
  });
}

}  // namespace sylva::geometry
