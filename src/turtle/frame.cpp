#include "turtle/frame.h"

#include <cmath>

namespace sylva::turtle {

void AngleCache::get(float degrees, float* c, float* s) {
  if (degrees != degrees_) {
    const double radians = static_cast<double>(degrees) * (3.14159265358979323846 / 180.0);
    degrees_ = degrees;
    cos_ = static_cast<float>(std::cos(radians));
    sin_ = static_cast<float>(std::sin(radians));
  }
  *c = cos_;
  *s = sin_;
}

void Frame::rotate_up(float c, float s) {
  const Vec3 h = heading * c + left * s;
  left = left * c - heading * s;
  heading = h;
}

void Frame::rotate_left(float c, float s) {
  const Vec3 h = heading * c - up * s;
  up = up * c + heading * s;
  heading = h;
}

void Frame::rotate_heading(float c, float s) {
  const Vec3 l = left * c + up * s;
  up = up * c - left * s;
  left = l;
}

void Frame::rotate(Vec3 axis, float c, float s) {
  heading = rotated(heading, axis, c, s);
  left = rotated(left, axis, c, s);
  up = rotated(up, axis, c, s);
}

bool Frame::set_head_up(Vec3 h, Vec3 u, float epsilon) {
  if (length(h) < epsilon || length(u) < epsilon) return false;
  const Vec3 hn = normalized(h), un = normalized(u);
  const Vec3 l = cross(un, hn);
  if (length(l) < epsilon) return false;
  heading = hn;
  left = normalized(l);
  up = cross(heading, left);  // U exactly perpendicular to H even when u was not
  return true;
}

bool Frame::set_heading(Vec3 h, float epsilon) {
  if (length(h) < epsilon) return false;
  const Vec3 target = normalized(h);
  const Vec3 axis = cross(heading, target);
  const float s = length(axis);
  const float c = dot(heading, target);
  if (s < 1e-7f) {
    // Parallel: nothing to do. Opposite: any half turn will do; around U
    // keeps the up vector, as TurnAround does.
    if (c < 0) rotate_up(-1, 0);
    return true;
  }
  rotate(axis / s, c, s);
  heading = target;
  return true;
}

bool Frame::roll_to_vertical(Vec3 vertical, float epsilon) {
  const Vec3 l = cross(vertical, heading);
  if (length(l) < epsilon) return false;  // heading vertical: every roll qualifies
  left = normalized(l);
  up = cross(heading, left);
  return true;
}

void Frame::orthonormalize() {
  heading = normalized(heading);
  left = normalized(left - heading * dot(left, heading));
  up = cross(heading, left);
}

}  // namespace sylva::turtle
