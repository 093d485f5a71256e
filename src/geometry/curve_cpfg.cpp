#include "geometry/curve_cpfg.h"

#include <algorithm>
#include <cmath>

namespace sylva::geometry {

CpfgCurve::CpfgCurve(const Contour& curve, int samples) : curve_(curve) {
  const int n = std::max(samples, 2);
  arc_.resize(static_cast<std::size_t>(n), 0.0);
  Vec3 previous = curve.at_parameter(0);
  for (int i = 1; i < n; ++i) {
    const Vec3 p = curve.at_parameter(static_cast<double>(i) / (n - 1));
    const double dx = static_cast<double>(p.x) - previous.x, dy = static_cast<double>(p.y) - previous.y,
                 dz = static_cast<double>(p.z) - previous.z;
    length_ += std::sqrt(dx * dx + dy * dy + dz * dz);
    arc_[static_cast<std::size_t>(i)] = length_;
    previous = p;
  }
  if (length_ > 0)
    for (double& l : arc_) l /= length_;
}

Vec3 CpfgCurve::at(double t) const {
  t = std::clamp(t, 0.0, 1.0);
  // The last sample at or before t, by bisection as cpfg finds it.
  std::size_t low = 0, high = arc_.size() - 1;
  while (high - low > 1) {
    const std::size_t middle = (low + high) / 2;
    if (arc_[middle] > t) high = middle;
    else low = middle;
  }
  const double span = arc_[high] - arc_[low];
  const double fraction = span > 0 ? (t - arc_[low]) / span : 0.0;
  return curve_.at_parameter((static_cast<double>(low) + fraction) / static_cast<double>(arc_.size() - 1));
}

}  // namespace sylva::geometry
