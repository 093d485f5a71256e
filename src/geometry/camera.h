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
  float shift = 1;
  float scale = 0.9f;  // fraction of the image the model fills
  std::optional<Box> box;  // the box to frame; the Scene's bounds when absent
  std::optional<float> front_distance, back_distance;
};

// A 4x4 matrix, column-major as OpenGL takes it.
using Mat4 = std::array<float, 16>;

class Camera {
 public:
  // Frames `scene_bounds` (or params.box) in an image of width x height pixels.
  Camera(const ViewParameters& params, const Box& scene_bounds, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  const Mat4& view() const { return view_; }
  const Mat4& projection() const { return projection_; }
  Vec3 eye() const { return eye_; }
  Vec3 direction() const { return direction_; }

  // Pixel coordinates (x right, y down, origin top-left) and depth in [0,1]
  // (0 nearest) of a point.
  Vec3 to_pixels(Vec3 world) const;
  // World units per pixel at the centre of the view (for widths in drawings).
  float pixels_per_unit() const { return pixels_per_unit_; }

 private:
  int width_, height_;
  Mat4 view_{}, projection_{};
  Vec3 eye_, direction_;
  float pixels_per_unit_ = 1;
};

}  // namespace sylva::geometry
