// cpfg's camera, as cpfg's SetView and CalculateWindow set up OpenGL:
//   eye = vrp + (viewpoint - vrp) / scale, looking at vrp, up = view_up;
//   parallel: glOrtho around the box's corners as seen from the eye, the
//   larger of their width and height (for the image's shape) filling the
//   image, divided by scale, centred on them;
//   perspective: gluPerspective(viewing angle, width / height).
// Both clip at front and back distance from the eye.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/camera.h"
#include "geometry/camera_matrices.h"

namespace sylva::geometry {

namespace {

constexpr float kDegrees = std::numbers::pi_v<float> / 180;

bool usable(const Box& b) {
  return !b.empty() && std::isfinite(b.min.x) && std::isfinite(b.min.y) && std::isfinite(b.min.z) &&
         std::isfinite(b.max.x) && std::isfinite(b.max.y) && std::isfinite(b.max.z);
}

// cpfg measures the model as it draws it, starting from a minimum of 1 and
// a maximum of 0 on each axis: the box it frames always reaches down to 1 at
// least and up to 0 at least. Without anything drawn it is the unit cube.
Box cpfg_view_volume(const Box& drawn) {
  if (!usable(drawn)) return Box{{0, 0, 0}, {1, 1, 1}};
  Box b = drawn;
  b.min = {std::fmin(b.min.x, 1.0f), std::fmin(b.min.y, 1.0f), std::fmin(b.min.z, 1.0f)};
  b.max = {std::fmax(b.max.x, 0.0f), std::fmax(b.max.y, 0.0f), std::fmax(b.max.z, 0.0f)};
  return b;
}

// Rotation of v about the unit axis n by `angle` radians, counterclockwise
// as seen from where n points.
Vec3 rotate_about(Vec3 v, Vec3 n, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(n, v) * s + n * (dot(n, v) * (1 - c));
}

}  // namespace

Vec3 cpfg_view_up(const CpfgView& view) {
  Vec3 normal = view.viewpoint - view.reference_point;
  if (length(normal) == 0) normal = {0, 0, -1};  // cpfg's fallback
  normal = normalized(normal);
  Vec3 across = cross(normal, Vec3{0, 1, 0});
  across = length(across) == 0 ? Vec3{-1, 0, 0} : normalized(across);
  // cpfg turns `across` by the quaternion q(-twist/2) as q^-1 v q: a turn of
  // +twist about the normal.
  if (view.twist != 0) across = rotate_about(across, normal, static_cast<float>(view.twist) * 0.1f * kDegrees);
  return cross(across, normal);
}

void Camera::frame_cpfg(const ViewParameters& params, const Box& scene_bounds) {
  const CpfgView& v = *params.cpfg;
  Vec3 viewpoint = v.viewpoint, reference = v.reference_point;
  if (length(viewpoint - reference) == 0) viewpoint = {0, 0, -1}, reference = {0, 0, 0};
  const float scale = v.scale != 0 ? v.scale : 1;
  eye_ = reference + (viewpoint - reference) / scale;
  const Vec3 f = normalized(reference - eye_);
  const Vec3 r = normalized(cross(f, cpfg_view_up(v)));
  const Vec3 u = cross(r, f);
  direction_ = f, up_ = u, right_ = r;
  view_ = look_at(eye_, f, u, r);
  target_distance_ = length(reference - eye_);

  // Only where the model is can anything be clipped: clipping planes closer
  // together than cpfg's (+-100000 by default) give the same picture and a
  // finer depth buffer.
  Box drawn = usable(scene_bounds) ? scene_bounds : Box{{0, 0, 0}, {1, 1, 1}};
  if (v.box) drawn.add(*v.box);
  float zmin = INFINITY, zmax = -INFINITY;
  for (Vec3 c : corners(drawn)) {
    const float z = dot(c - eye_, f);
    zmin = std::min(zmin, z), zmax = std::max(zmax, z);
  }
  // glOrtho takes the planes in either order (front 1000, back -1000 is
  // common): the same slab, only its depth order reversed, which is not
  // reproduced.
  const float front = std::min(v.front_distance, v.back_distance), back = std::max(v.front_distance, v.back_distance);
  const float margin = std::max({(zmax - zmin) * 0.01f, length(drawn.size()) * 0.01f, 1e-4f});
  near_ = std::max(front, zmin - margin);
  far_ = std::min(back, zmax + margin);
  if (!(far_ > near_)) near_ = front, far_ = back;
  if (!(far_ > near_)) far_ = near_ + 1;

  const float w = static_cast<float>(width_), h = static_cast<float>(height_);
  if (!perspective_) {
    const Box box = v.box ? *v.box : cpfg_view_volume(params.box ? *params.box : scene_bounds);
    float minx = INFINITY, maxx = -INFINITY, miny = INFINITY, maxy = -INFINITY;
    for (Vec3 c : corners(box)) {
      const float x = dot(c - eye_, r), y = dot(c - eye_, u);
      minx = std::min(minx, x), maxx = std::max(maxx, x), miny = std::min(miny, y), maxy = std::max(maxy, y);
    }
    const float aspect = h / w;  // cpfg's aspect ratio: height over width
    const float cx = (minx + maxx) / 2, cy = (miny + maxy) / 2;
    float span = std::max((maxx - minx) / 2, (maxy - miny) / 2 / aspect) / scale;
    if (!(span > 0)) span = 1;  // cpfg: "view volume is zero"
    projection_ = ortho(cx - span, cx + span, cy - span * aspect, cy + span * aspect, near_, far_);
    pixels_per_unit_ = h / (2 * span * aspect);
  } else {
    if (near_ <= 0) near_ = std::max(far_ * 1e-4f, 1e-4f);
    const float ty = std::tan(std::clamp(v.viewing_angle, 0.1f, 179.0f) * kDegrees / 2), tx = ty * w / h;
    projection_ = frustum(-near_ * tx, near_ * tx, -near_ * ty, near_ * ty, near_, far_);
    pixels_per_unit_ = h / (2 * std::max(target_distance_, 1e-6f) * ty);
  }
}

}  // namespace sylva::geometry
