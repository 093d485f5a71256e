// cpfg's curve files (the "curve:" command of a cpfg view file, CPFG
// manual 8.1.5; the curves of curveX ... curveGAL): "version: 1.x", the
// curve's placement (contact:, end:, heading:, up:, size:), "points: n",
// "range:", "dimension: d", "type: t", then n lines of d numbers (x y [z
// [multiplicity]]). cuspy's contour files ("cver ...") serve as curves too.
#pragma once

#include <string>

#include "geometry/contour.h"

namespace sylva::io {

// The curve as a contour: "bspline" (the default) an open uniform cubic
// B-spline of the points, each repeated by its multiplicity; "bspline-closed"
// a closed one; "bspline-phantom" an open one with a phantom point mirrored
// beyond each end, as cpfg adds them. Other types (bspline-endpoint, bezier,
// bezier-surface) and curves within curves are a ModelError: not supported.
geometry::Contour read_curve_file(const std::string& path);

}  // namespace sylva::io
