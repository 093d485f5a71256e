// Shadow mapping for render mode "shadows" (LPFG manual 8.1.2) with OpenGL's
// fixed-function pipeline: the scene's depth seen from the first directional
// or spot light goes into a depth texture; the visible surfaces are then
// drawn once more, projecting that texture onto them, and whatever lies
// behind something nearer the light is multiplied by the shadow colour.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "geometry/camera.h"
#include "geometry/material.h"
#include "geometry/vec3.h"
#include "render/png_renderer.h"

namespace sylva::io::gl {

// World to the shadow-casting light's clip space.
struct LightCamera {
  geometry::Mat4 view{}, projection{};
};

// The first directional or spot light of `lights` looking at `bounds`; none
// when there is no such light or a spot light faces away from everything.
// Lights that are not stationary are in the eye coordinates of `camera`.
std::optional<LightCamera> shadow_light_camera(const std::vector<geometry::Light>& lights, bool stationary,
                                               const geometry::Camera& camera, const geometry::Box& bounds);

// A depth texture with the framebuffer that renders into it. Needs the
// OpenGL context current for its whole life.
class ShadowMapTexture {
 public:
  explicit ShadowMapTexture(int size);
  ~ShadowMapTexture();
  ShadowMapTexture(const ShadowMapTexture&) = delete;
  ShadowMapTexture& operator=(const ShadowMapTexture&) = delete;

  // Records the depth of the triangles `draw_triangles` draws (positions
  // only), as `light` sees them. Restores the default framebuffer, but not
  // the viewport or the matrices.
  void render(const LightCamera& light, const geometry::ShadowMap& settings, const std::function<void()>& draw_triangles);

  // Multiplies the shadowed parts of the image by `color`; `draw_triangles`
  // must draw the same triangles as the pass that made the image, with the
  // same depth. Leaves the modelview matrix at `camera_view`.
  void darken(const LightCamera& light, const geometry::Mat4& camera_view, const geometry::Rgb& color,
              const std::function<void()>& draw_triangles);

 private:
  int size_;
  unsigned texture_ = 0, framebuffer_ = 0;
};

}  // namespace sylva::io::gl
