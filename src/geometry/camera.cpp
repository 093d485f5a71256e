#include "geometry/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/camera_matrices.h"

namespace sylva::geometry {

namespace {

std::array<float, 4> transform(const Mat4& m, std::array<float, 4> v) {
  std::array<float, 4> out{};
  for (int row = 0; row < 4; ++row)
    out[row] = m[row] * v[0] + m[4 + row] * v[1] + m[8 + row] * v[2] + m[12 + row] * v[3];
  return out;
}

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

Camera::Camera(const ViewParameters& params, const Box& scene_bounds, int width, int height)
    : width_(std::max(width, 1)), height_(std::max(height, 1)), perspective_(params.perspective) {
  if (params.cpfg) {
    frame_cpfg(params, scene_bounds);
    return;
  }
  Box box = params.box ? *params.box : scene_bounds;
  if (box.empty() || !finite(box.min) || !finite(box.max)) box = Box{{-1, -1, -1}, {1, 1, 1}};

  Vec3 f = normalized(params.dir);
  if (length(f) == 0 || !finite(f)) f = {0, 0, -1};
  Vec3 r = cross(f, params.up);
  if (length(r) < 1e-6f * length(params.up) || length(r) == 0) {
    // `up` along `dir`: any screen orientation is as good as another, so take
    // the world axis least aligned with the view.
    Vec3 axis = std::fabs(f.y) < 0.9f ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    r = cross(f, axis);
  }
  r = normalized(r);
  Vec3 u = cross(r, f);
  direction_ = f, up_ = u, right_ = r;

  const Vec3 centre = box.center();
  const auto box_corners = corners(box);
  float radius = length(box.size()) * 0.5f;
  float hx = 0, hy = 0;
  for (Vec3 c : box_corners) {
    hx = std::max(hx, std::fabs(dot(c - centre, r)));
    hy = std::max(hy, std::fabs(dot(c - centre, u)));
  }
  if (radius <= 0) radius = 1;
  if (hx <= 0 && hy <= 0) hx = hy = radius;  // a box seen end-on: frame its depth instead

  const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
  const float fov = std::clamp(params.fov, 0.1f, 179.0f) * std::numbers::pi_v<float> / 180;
  const float ty = std::tan(fov / 2), tx = ty * aspect;
  const float half_angle = std::min(std::atan(tx), std::atan(ty));
  const float shift = params.shift > 0 ? params.shift : 1;
  const float distance = shift * radius / std::sin(half_angle);
  const float scale = params.scale > 0 ? params.scale : 0.9f;
  target_distance_ = distance;

  const Vec3 target = centre + params.pan;
  eye_ = target - f * distance;
  view_ = look_at(eye_, f, u, r);

  float zmin = INFINITY, zmax = -INFINITY;
  for (Vec3 c : box_corners) {
    float z = dot(c - eye_, f);
    zmin = std::min(zmin, z), zmax = std::max(zmax, z);
  }
  if (params.front_distance && params.back_distance) {
    // lpfg keeps only the distance between the two planes: its clipping slab
    // is centred on the point looked at, |back - front| / 2 deep either way
    // (Projection::SetVolume), whichever the order of the two.
    const float half = std::fabs(*params.back_distance - *params.front_distance) / 2;
    near_ = distance - half, far_ = distance + half;
  } else {
    // A flat model has no depth of its own: keep a sliver around it.
    float margin = std::max((zmax - zmin) * 0.01f, radius * 0.01f);
    near_ = zmin - margin, far_ = zmax + margin;
  }
  if (perspective_) near_ = std::max(near_, distance * 1e-3f);
  if (!(far_ > near_)) far_ = near_ + radius;

  if (!perspective_) {
    float fit_x = hx > 0 ? static_cast<float>(width_) / (2 * hx) : INFINITY;
    float fit_y = hy > 0 ? static_cast<float>(height_) / (2 * hy) : INFINITY;
    pixels_per_unit_ = scale * std::min(fit_x, fit_y);
    float hw = static_cast<float>(width_) / (2 * pixels_per_unit_);
    float hh = static_cast<float>(height_) / (2 * pixels_per_unit_);
    projection_ = ortho(-hw, hw, -hh, hh, near_, far_);
  } else {
    // Zoom so the corners, seen from the un-panned camera, fill `scale` of the
    // image; corners behind the eye (shift < 1) cannot be framed and are left out.
    float extent = 0;
    for (Vec3 c : box_corners) {
      Vec3 v = c - centre;
      float z = distance + dot(v, f);
      if (z <= distance * 1e-3f) continue;
      extent = std::max({extent, std::fabs(dot(v, r)) / (z * tx), std::fabs(dot(v, u)) / (z * ty)});
    }
    float zoom = scale / (extent > 0 ? extent : 1);
    projection_ = frustum(-near_ * tx / zoom, near_ * tx / zoom, -near_ * ty / zoom, near_ * ty / zoom, near_, far_);
    pixels_per_unit_ = static_cast<float>(height_) * 0.5f * zoom / (distance * ty);
  }
}

Vec3 Camera::to_pixels(Vec3 world) const {
  auto eye_space = transform(view_, {world.x, world.y, world.z, 1});
  auto clip = transform(projection_, eye_space);
  float w = clip[3];
  if (std::fabs(w) < 1e-30f) w = w < 0 ? -1e-30f : 1e-30f;
  float x = clip[0] / w, y = clip[1] / w, z = clip[2] / w;
  return {(x + 1) * 0.5f * static_cast<float>(width_), (1 - y) * 0.5f * static_cast<float>(height_), (z + 1) * 0.5f};
}

float Camera::pixels_per_unit_at(Vec3 world) const {
  if (!perspective_) return pixels_per_unit_;
  float z = std::max(view_distance(world), near_);
  return pixels_per_unit_ * target_distance_ / z;
}

}  // namespace sylva::geometry
