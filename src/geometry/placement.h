// An affine placement of local coordinates in the world: where the turtle
// puts a surface, a mesh or a dynamic surface. Normals go through the inverse
// transpose so that non-uniform scaling keeps them perpendicular.
#pragma once

#include "geometry/vec3.h"

namespace sylva::geometry {

struct Placement {
  Vec3 origin;
  // Images of the local x, y and z axes (scale included).
  Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  // Images of the local axes for normals (the inverse transpose of x, y, z).
  Vec3 normal_x{1, 0, 0}, normal_y{0, 1, 0}, normal_z{0, 0, 1};

  Vec3 point(Vec3 p) const { return origin + x * p.x + y * p.y + z * p.z; }
  Vec3 normal(Vec3 n) const { return normalized(normal_x * n.x + normal_y * n.y + normal_z * n.z); }

  // Local axes mapped to the orthonormal world directions ax, ay, az, each
  // scaled by its factor (a zero factor flattens that axis; normals then
  // ignore it).
  static Placement from_frame(Vec3 origin, Vec3 ax, Vec3 ay, Vec3 az, Vec3 scale) {
    Placement p;
    p.origin = origin;
    p.x = ax * scale.x;
    p.y = ay * scale.y;
    p.z = az * scale.z;
    p.normal_x = scale.x != 0 ? ax / scale.x : Vec3{};
    p.normal_y = scale.y != 0 ? ay / scale.y : Vec3{};
    p.normal_z = scale.z != 0 ? az / scale.z : Vec3{};
    return p;
  }
};

}  // namespace sylva::geometry
