#include "geometry/contour.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace sylva::geometry {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
// Dense samples per curve segment for measuring arc length. The returned
// points are evaluated on the curve itself; only their spacing is approximate.
constexpr int kSamplesPerSegment = 64;

Vec3 uniform_bspline(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3, float t) {
  const float s = 1 - t;
  const float b0 = s * s * s / 6;
  const float b1 = (3 * t * t * t - 6 * t * t + 4) / 6;
  const float b2 = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6;
  const float b3 = t * t * t / 6;
  return p0 * b0 + p1 * b1 + p2 * b2 + p3 * b3;
}

// The curve as segments over a parameter s in [0, segments()].
class Path {
 public:
  Path(const std::vector<Vec3>& points, bool closed, bool spline) : p_(points), closed_(closed), spline_(spline) {
    const int n = static_cast<int>(p_.size());
    if (spline_ && (closed_ ? n < 3 : n < 4)) spline_ = false;  // too few points for a cubic
    if (spline_) segments_ = closed_ ? n : n - 3;
    else segments_ = closed_ ? n : n - 1;
  }

  int segments() const { return segments_; }

  Vec3 at(double s) const {
    // Clamped before the conversion: points far enough apart make the arc
    // length, and so s, infinite or NaN.
    const double whole = std::isnan(s) ? 0.0 : std::clamp(std::floor(s), 0.0, static_cast<double>(segments_ - 1));
    const int seg = static_cast<int>(whole);
    const float t = static_cast<float>(s - seg);
    const int n = static_cast<int>(p_.size());
    if (!spline_) return p_[seg] * (1 - t) + p_[(seg + 1) % n] * t;
    // Closed: segment i runs near P[i] .. P[i+1]; open: over P[i] .. P[i+3].
    if (closed_) return uniform_bspline(point(seg - 1), point(seg), point(seg + 1), point(seg + 2), t);
    return uniform_bspline(p_[seg], p_[seg + 1], p_[seg + 2], p_[seg + 3], t);
  }

 private:
  Vec3 point(int i) const {
    const int n = static_cast<int>(p_.size());
    return p_[static_cast<std::size_t>(((i % n) + n) % n)];
  }

  const std::vector<Vec3>& p_;
  bool closed_;
  bool spline_;
  int segments_ = 0;
};

std::vector<Vec3> circle_points(int sides) {
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(sides));
  for (int k = 0; k < sides; ++k) {
    const double a = kTwoPi * k / sides;
    out.push_back({static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0});
  }
  return out;
}

}  // namespace

std::vector<Vec3> Contour::resample(int sides) const {
  if (sides < 1) sides = 1;
  if (curve == Curve::Circle) return circle_points(sides);
  if (points.empty()) return std::vector<Vec3>(static_cast<std::size_t>(sides), Vec3{});
  if (points.size() == 1) return std::vector<Vec3>(static_cast<std::size_t>(sides), points[0]);

  const Path c(points, closed, curve == Curve::BSpline);
  const int dense = c.segments() * kSamplesPerSegment;
  std::vector<double> arc(static_cast<std::size_t>(dense) + 1, 0.0);
  Vec3 previous = c.at(0);
  for (int k = 1; k <= dense; ++k) {
    Vec3 p = c.at(static_cast<double>(k) / kSamplesPerSegment);
    arc[static_cast<std::size_t>(k)] = arc[static_cast<std::size_t>(k) - 1] + length(p - previous);
    previous = p;
  }
  const double total = arc.back();

  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(sides));
  // A closed curve's last point would repeat its first; an open one ends at its end.
  const int intervals = closed ? sides : std::max(sides - 1, 1);
  std::size_t j = 0;
  for (int k = 0; k < sides; ++k) {
    const double target = total * k / intervals;
    while (j + 1 < static_cast<std::size_t>(dense) && arc[j + 1] < target) ++j;
    const double span = arc[j + 1] - arc[j];
    const double frac = span > 0 ? std::clamp((target - arc[j]) / span, 0.0, 1.0) : 0.0;
    out.push_back(c.at((static_cast<double>(j) + frac) / kSamplesPerSegment));
  }
  return out;
}

Vec3 Contour::at_parameter(double t) const {
  if (curve == Curve::Circle) {
    const double a = kTwoPi * t;
    return {static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0};
  }
  if (points.empty()) return {};
  if (points.size() == 1) return points[0];
  t = std::clamp(t, 0.0, 1.0);
  const std::size_t n = points.size();
  if (curve == Curve::BSpline && !closed && n >= 4) {
    // In double, with cpfg's slightly short parameter range, so that t = 1
    // stays in the last segment.
    const double u = t * (static_cast<double>(n) - 3.000001);
    const std::size_t seg = std::min(static_cast<std::size_t>(u), n - 4);
    const double f = u - static_cast<double>(seg), g = 1 - f;
    const double b[4] = {g * g * g / 6, (3 * f * f * f - 6 * f * f + 4) / 6, (-3 * f * f * f + 3 * f * f + 3 * f + 1) / 6,
                         f * f * f / 6};
    double x = 0, y = 0, z = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      x += b[k] * points[seg + k].x;
      y += b[k] * points[seg + k].y;
      z += b[k] * points[seg + k].z;
    }
    return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
  }
  const Path c(points, closed, curve == Curve::BSpline);
  return c.at(t * c.segments());
}

Contour Contour::circle() {
  Contour c;
  c.name = "circle";
  c.closed = true;
  c.curve = Curve::Circle;
  c.points = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  return c;
}

}  // namespace sylva::geometry
