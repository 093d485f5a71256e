// cpfg's evaluation of a graphically defined function (see function.h), in
// double and in cpfg's order of operations.
#include <cmath>

#include "geometry/function.h"

namespace sylva::geometry {
namespace {

constexpr int kOrder = 4;  // cubic

// The cubic B-spline over the points with knots 0,0,0,0, 1, ..., m,m,m,m,
// by the Cox-de Boor recursion, in double.
class CpfgSpline {
 public:
  explicit CpfgSpline(const std::vector<Vec2>& points) : p_(points), last_(static_cast<int>(points.size()) - 1) {}

  // The point at d in [0,1] (x, y).
  void point(double d, double& x, double& y) const {
    const double u = d * (last_ - kOrder + 2);
    x = y = 0;
    for (int k = 0; k <= last_; ++k) {
      const double n = basis(k, kOrder, u);
      x += p_[static_cast<std::size_t>(k)].x * n;
      y += p_[static_cast<std::size_t>(k)].y * n;
    }
  }

 private:
  int knot(int j) const {
    if (j < kOrder) return 0;
    if (j > last_) return last_ - kOrder + 2;
    return j - kOrder + 1;
  }
  double basis(int k, int order, double u) const {
    if (order == 1) return knot(k) <= u && u < knot(k + 1) ? 1.0 : 0.0;
    double sum = 0.0;
    int span = knot(k + order - 1) - knot(k);
    if (span != 0) sum = (u - knot(k)) / span * basis(k, order - 1, u);
    span = knot(k + order) - knot(k + 1);
    if (span != 0) sum += (knot(k + order) - u) / span * basis(k + 1, order - 1, u);
    return sum;
  }

  const std::vector<Vec2>& p_;
  int last_;
};

double clamped(double v) { return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v == v ? v : 0.0; }

}  // namespace

CpfgFunction::CpfgFunction(const Function& f) : points_(f.points) {
  // The table holds bisected values; with two samples or fewer there is none.
  if (f.samples > 2 && points_.size() >= kOrder) {
    values_.resize(static_cast<std::size_t>(f.samples));
    for (int i = 0; i < f.samples; ++i) values_[static_cast<std::size_t>(i)] = bisect(double(i) / double(f.samples - 1));
  }
}

// The y of the last point tried by bisecting the spline parameter until the
// point's x is within 0.001 of v.
double CpfgFunction::bisect(double v) const {
  if (points_.size() < kOrder) return 0;
  const CpfgSpline spline(points_);
  double low = 0.0, high = 1.0, x = 0, y = 0;
  for (int step = 0; step < 200; ++step) {
    const double middle = (low + high) / 2.0;
    spline.point(middle, x, y);
    if (x > v) high = middle;
    else low = middle;
    if (!(std::fabs(x - v) > 0.001)) break;
  }
  return y;
}

double CpfgFunction::value(double v) const {
  v = clamped(v);
  if (values_.empty()) return bisect(v);
  const int n = static_cast<int>(values_.size());
  const double index = v * (n - 1);
  const int i = static_cast<int>(std::floor(index));
  const double w1 = 1 - index + i;
  const double w2 = index - i;
  if (i >= n - 1) return values_[static_cast<std::size_t>(n - 1)];
  return w1 * values_[static_cast<std::size_t>(i)] + w2 * values_[static_cast<std::size_t>(i + 1)];
}

}  // namespace sylva::geometry
