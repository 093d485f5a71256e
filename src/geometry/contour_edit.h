// Changing a contour's control points while a model runs (lpfg's curveScale
// and curveSetPoint, LPFG manual 6.2.3).
#pragma once

#include "geometry/contour.h"

namespace sylva::geometry {

// Multiplies every control point by `factors`, coordinate by coordinate.
void scale_contour(Contour& contour, Vec3 factors);

// Moves control point `index` (counted from 0 as the file lists them) to
// `position`; a point of multiplicity m moves as one, all m copies together.
// False, changing nothing, when there is no such point.
bool set_contour_point(Contour& contour, int index, Vec3 position);

}  // namespace sylva::geometry
