// The camera of a view file (LPFG manual 8.1.1): projection, view direction,
// up, pan, field of view, scale, and the box to frame. Vector drawings and
// images project the Scene through the same Camera.
#pragma once

#include <array>
#include <optional>

#include "geometry/vec3.h"

namespace sylva::geometry {

// cpfg's view (CPFG manual 8.1.2), framed as cpfg frames it (its SetView and
// CalculateWindow): the eye on the line from the view reference point through
// the viewpoint, at 1/scale of their distance; up is world y as seen along
// that line, turned by `twist`. In parallel projection the box (or the
// model's bounds) fills the image, centred, times `scale`; in perspective
// only the viewing angle and the eye's place set the size.
struct CpfgView {
  Vec3 viewpoint{0, 0, 1};
  Vec3 reference_point{0, 0, 0};
  int twist = 0;              // tenths of a degree
  float viewing_angle = 45;   // degrees, in y; perspective only
  float scale = 1;            // "scale factor:"
  // Distances from the eye along the view to the clipping planes.
  float front_distance = -100000, back_distance = 100000;
  std::optional<Box> box;     // "box: x: ... y: ... z: ..."; else the model's bounds
};

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
  // Both or neither (8.1.1). lpfg makes of them a slab |back - front| deep
  // centred on the point looked at, in both projections.
  std::optional<float> front_distance, back_distance;
  // A cpfg model's view: when set, the Camera frames as cpfg does and the
  // fields above other than `perspective` and `box` (the model's bounds to
  // frame when cpfg has no box) are not used.
  std::optional<CpfgView> cpfg;
};

// cpfg's screen up (its view_up): world y made square to the line from the
// view reference point to the viewpoint (world -x instead when that line is
// along y), then turned by twist/10 degrees about that line, counterclockwise
// as seen from the viewpoint.
Vec3 cpfg_view_up(const CpfgView& view);

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
  // cpfg's framing of params.cpfg (camera_cpfg.cpp).
  void frame_cpfg(const ViewParameters& params, const Box& scene_bounds);

  int width_, height_;
  bool perspective_ = false;
  Mat4 view_{}, projection_{};
  Vec3 eye_, direction_, up_, right_;
  float near_ = 0, far_ = 1;
  float target_distance_ = 1;
  float pixels_per_unit_ = 1;
};

}  // namespace sylva::geometry
