#include "geometry/function.h"

#include <algorithm>
#include <array>
#include <cstddef>

namespace sylva::geometry {
namespace {

struct Point2 {
  double x = 0, y = 0;
};

// The function editor's curve: a B-spline of degree min(3, n - 1) with
// uniform interior knots and end knots repeated so the curve starts at the
// first control point (x = 0) and ends at the last (x = 1).
class ClampedBSpline {
 public:
  explicit ClampedBSpline(const std::vector<Vec2>& points)
      : p_(points), n_(static_cast<int>(points.size())), degree_(std::min(3, n_ - 1)) {}

  double domain_end() const { return n_ - degree_; }

  Point2 at(double s) const {
    const int p = degree_;
    int span = std::clamp(static_cast<int>(s) + p, p, n_ - 1);
    std::array<Point2, 4> d;
    for (int j = 0; j <= p; ++j) {
      const Vec2& c = p_[static_cast<std::size_t>(j + span - p)];
      d[static_cast<std::size_t>(j)] = {c.x, c.y};
    }
    for (int r = 1; r <= p; ++r) {
      for (int j = p; j >= r; --j) {
        const double lo = knot(j + span - p), hi = knot(j + 1 + span - r);
        const double alpha = hi > lo ? (s - lo) / (hi - lo) : 0.0;
        Point2& a = d[static_cast<std::size_t>(j)];
        const Point2& b = d[static_cast<std::size_t>(j - 1)];
        a = {(1 - alpha) * b.x + alpha * a.x, (1 - alpha) * b.y + alpha * a.y};
      }
    }
    return d[static_cast<std::size_t>(p)];
  }

 private:
  double knot(int i) const { return std::clamp(i - degree_, 0, n_ - degree_); }

  const std::vector<Vec2>& p_;
  int n_;
  int degree_;
};

}  // namespace

float Function::operator()(float x) const {
  if (points.empty()) return 0;
  if (points.size() == 1) return points[0].y;
  const double lo_x = points.front().x, hi_x = points.back().x;
  const double target = std::clamp(static_cast<double>(x), std::min(lo_x, hi_x), std::max(lo_x, hi_x));
  const ClampedBSpline curve(points);
  // x(s) does not decrease (the editor keeps the control points' x in order),
  // so the parameter reaching x is found by bisection.
  double lo = 0, hi = curve.domain_end();
  for (int k = 0; k < 60 && hi - lo > 1e-12; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (curve.at(mid).x < target) lo = mid;
    else hi = mid;
  }
  return static_cast<float>(curve.at(0.5 * (lo + hi)).y);
}

}  // namespace sylva::geometry
