// The turtle's orientation: heading H, left L and up U, orthonormal with
// U = H x L. The initial frame H = (0,1,0), L = (-1,0,0), U = (0,0,1) makes
// models grow up the screen (CPFG manual, chapter 6).
#pragma once

#include "geometry/vec3.h"

namespace sylva::turtle {

using geometry::Vec3;

// Points closer than this are the same point, and vectors shorter than it
// have no direction (LPFG manual 5.1).
inline constexpr float kEpsilon = 1e-5f;

// Cosine and sine of an angle in degrees, computed once for repeated angles
// (a model turns by the same few angles millions of times).
class AngleCache {
 public:
  void get(float degrees, float* c, float* s);

 private:
  float degrees_ = 0, cos_ = 1, sin_ = 0;
};

// Rodrigues' rotation of v around the unit axis k by the angle of (c, s).
inline Vec3 rotated(Vec3 v, Vec3 k, float c, float s) { return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c)); }

struct Frame {
  Vec3 heading{0, 1, 0};
  Vec3 left{-1, 0, 0};
  Vec3 up{0, 0, 1};

  // Right-handed rotations of the frame by the angle of (c, s):
  // around U (positive turns H toward L), around L (positive turns H toward
  // -U) and around H (positive turns U toward -L).
  void rotate_up(float c, float s);
  void rotate_left(float c, float s);
  void rotate_heading(float c, float s);
  // Around any unit axis, right-handed.
  void rotate(Vec3 axis, float c, float s);

  // SetHead: H and U given (any length), L = U x H; false (and unchanged)
  // when either is shorter than `epsilon` or they are parallel.
  bool set_head_up(Vec3 h, Vec3 u, float epsilon);
  // SetHead3f: the smallest rotation taking H to h (parallel transport).
  bool set_heading(Vec3 h, float epsilon);
  // RollToVert: roll around H so that U lies in the vertical plane through H,
  // on the upper side: L = V x H / |V x H|, U = H x L. `vertical` is world up.
  bool roll_to_vertical(Vec3 vertical, float epsilon);
  // Removes the drift of many rotations in float.
  void orthonormalize();
};

}  // namespace sylva::turtle
