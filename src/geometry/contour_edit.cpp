#include "geometry/contour_edit.h"

namespace sylva::geometry {

void scale_contour(Contour& contour, Vec3 factors) {
  for (Vec3& p : contour.points) p = Vec3{p.x * factors.x, p.y * factors.y, p.z * factors.z};
}

bool set_contour_point(Contour& contour, int index, Vec3 position) {
  if (index < 0) return false;
  if (contour.multiplicities.empty()) {
    if (static_cast<std::size_t>(index) >= contour.points.size()) return false;
    contour.points[static_cast<std::size_t>(index)] = position;
    return true;
  }
  if (static_cast<std::size_t>(index) >= contour.multiplicities.size()) return false;
  std::size_t first = 0;
  for (int k = 0; k < index; ++k) first += static_cast<std::size_t>(contour.multiplicities[static_cast<std::size_t>(k)]);
  const auto copies = static_cast<std::size_t>(contour.multiplicities[static_cast<std::size_t>(index)]);
  for (std::size_t k = first; k < first + copies && k < contour.points.size(); ++k) contour.points[k] = position;
  return true;
}

}  // namespace sylva::geometry
