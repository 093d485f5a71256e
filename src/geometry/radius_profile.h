// cpfg's @Gr (CPFG manual 6.7.3): the radius of a generalized cylinder along
// a stretch between two control points as a cubic Hermite curve in the plane
// (distance along the stretch, radius), from (0, r0) to (X, r1), with start
// tangent length1 (cos angle1, sin angle1) and end tangent length2 (cos
// angle2, sin angle2); angles in degrees, both measured from the direction of
// travel toward larger radii. With the adjustment on (@Gr(1)), the curve is
// laid out on a stretch of unit length (X = 1) and stretched onto the real
// one, so the angles are those before stretching; with it off (@Gr(0)) X is
// the stretch's real length and the angles are the real ones.
#pragma once

namespace sylva::geometry {

struct RadiusTangents {
  bool given = false;  // no @Gr(a1,l1,a2,l2) yet: the radius goes linearly
  float angle1 = 0, length1 = 1, angle2 = 0, length2 = 1;
  bool adjust = true;  // @Gr(flag)
};

// The radius at fraction t (0..1) of the way along a stretch of length
// `distance` from radius r0 to r1: the Hermite curve's radius where its first
// coordinate is t X.
float stretch_radius(const RadiusTangents& tangents, float r0, float r1, float distance, float t);

}  // namespace sylva::geometry
