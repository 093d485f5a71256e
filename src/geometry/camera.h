// The camera of a view file (LPFG manual 8.1.1): projection, view direction,
// up, pan, field of view, scale, and the box to frame. Vector drawings and
// images project the Scene through the same Camera.
#pragma once

#include <array>
#include <optional>

#include "geometry/vec3.h"

namespace sylva::geometry {

struct ViewParameters {
  bool perspective = false;
  Vec3 dir{0, 0, -1};
  Vec3 up{0, 1, 0};
  Vec3 pan{0, 0, 0};   // centre of the view, relative to the centre of the box
  float fov = 45;      // degrees, in y
  // The camera's distance from the point looked at, as a multiple of the
  // distance at which the box's bounding sphere just fits the field of view
  // (an absolute distance would need changing with every model's size).
  float shift = 1;
  float scale = 0.9f;  // fraction of the image the model fills
  std::optional<Box> box;  // the box to frame; the Scene's bounds when absent
  // Both or neither (8.1.1): from the viewer in perspective, from the box's
  // centre along the view direction in parallel projection.
  std::optional<float> front_distance, back_distance;
};

// A 4x4 matrix, column-major as OpenGL takes it (glLoadMatrixf).
using Mat4 = std::array<float, 16>;

// The box (or the Scene's bounds) is framed so that its outline as seen along
// `dir` fills `scale` of the image in the limiting dimension, centred on the
// box's centre plus `pan`, with square pixels. In perspective the camera sits
// `shift` times the bounding-sphere distance away, and the image is zoomed so
// that the box's projected corners fill `scale` of it: `fov` sets how strong
// the perspective is, not how big the model appears.
class Camera {
 public:
  // Frames `scene_bounds` (or params.box) in an image of width x height pixels.
  Camera(const ViewParameters& params, const Box& scene_bounds, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  bool perspective() const { return perspective_; }
  const Mat4& view() const { return view_; }
  const Mat4& projection() const { return projection_; }
  Vec3 eye() const { return eye_; }
  Vec3 direction() const { return direction_; }  // unit, from the eye into the scene
  Vec3 up() const { return up_; }                // unit, screen up
  Vec3 right() const { return right_; }          // unit, screen right
  // Clipping planes: distances from the eye along direction().
  float near_plane() const { return near_; }
  float far_plane() const { return far_; }

  // Pixel coordinates (x right, y down, origin top-left) and depth in [0,1]
  // (0 nearest) of a point. In perspective, only points beyond the near plane
  // have a meaningful projection.
  Vec3 to_pixels(Vec3 world) const;
  // Distance of a point from the eye along the view direction.
  float view_distance(Vec3 world) const { return dot(world - eye_, direction_); }
  // Pixels per world unit in the plane through the point looked at.
  float pixels_per_unit() const { return pixels_per_unit_; }
  // Pixels per world unit at the depth of `world` (differs in perspective).
  float pixels_per_unit_at(Vec3 world) const;

 private:
  int width_, height_;
  bool perspective_ = false;
  Mat4 view_{}, projection_{};
  Vec3 eye_, direction_, up_, right_;
  float near_ = 0, far_ = 1;
  float target_distance_ = 1;
  float pixels_per_unit_ = 1;
};

}  // namespace sylva::geometry
