// libOSMesa exports OpenGL's later entry points (shaders, framebuffers)
// directly: declared, they need no glXGetProcAddress-style lookup.
#define GL_GLEXT_PROTOTYPES
#include "render/gl_shadows.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/diagnostic.h"

namespace sylva::io::gl {

namespace {

using geometry::Mat4;
using geometry::Vec3;

Mat4 look_along(Vec3 eye, Vec3 f) {
  Vec3 hint = std::fabs(f.y) < 0.9f ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  Vec3 r = geometry::normalized(geometry::cross(f, hint));
  Vec3 u = geometry::cross(r, f);
  Mat4 m{};
  m[0] = r.x, m[4] = r.y, m[8] = r.z, m[12] = -geometry::dot(r, eye);
  m[1] = u.x, m[5] = u.y, m[9] = u.z, m[13] = -geometry::dot(u, eye);
  m[2] = -f.x, m[6] = -f.y, m[10] = -f.z, m[14] = geometry::dot(f, eye);
  m[15] = 1;
  return m;
}

Mat4 frustum(float half_width, float near, float far, bool perspective) {
  Mat4 m{};
  if (perspective) {
    m[0] = m[5] = near / half_width;
    m[10] = -(far + near) / (far - near);
    m[11] = -1;
    m[14] = -2 * far * near / (far - near);
  } else {
    m[0] = m[5] = 1 / half_width;
    m[10] = -2 / (far - near);
    m[14] = -(far + near) / (far - near);
    m[15] = 1;
  }
  return m;
}

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

std::optional<LightCamera> shadow_light_camera(const std::vector<geometry::Light>& lights, bool stationary,
                                               const geometry::Camera& camera, const geometry::Box& bounds) {
  auto found = std::find_if(lights.begin(), lights.end(), [](const geometry::Light& l) { return l.kind != geometry::Light::Kind::Point; });
  if (found == lights.end() || bounds.empty()) return std::nullopt;
  const geometry::Light& light = *found;
  // Eye coordinates: x right, y up, z toward the viewer, origin at the eye.
  auto to_world_direction = [&](Vec3 d) {
    return stationary ? d : camera.right() * d.x + camera.up() * d.y - camera.direction() * d.z;
  };
  auto to_world_point = [&](Vec3 p) { return stationary ? p : camera.eye() + to_world_direction(p); };

  const Vec3 centre = bounds.center();
  const float radius = std::max(geometry::length(bounds.size()) * 0.5f, 1e-6f);
  LightCamera result;
  if (light.kind == geometry::Light::Kind::Directional) {
    Vec3 toward = geometry::normalized(to_world_direction(light.direction));
    if (geometry::length(toward) == 0 || !finite(toward)) return std::nullopt;
    result.view = look_along(centre + toward * (2 * radius), -toward);
    result.projection = frustum(radius, 0.5f * radius, 3.5f * radius, false);
    return result;
  }
  const Vec3 eye = to_world_point(light.position);
  const Vec3 f = geometry::normalized(to_world_direction(light.direction));
  if (geometry::length(f) == 0 || !finite(f) || !finite(eye)) return std::nullopt;
  float near = INFINITY, far = -INFINITY;
  for (int i = 0; i < 8; ++i) {
    Vec3 corner{(i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                (i & 4) ? bounds.max.z : bounds.min.z};
    float z = geometry::dot(corner - eye, f);
    near = std::min(near, z), far = std::max(far, z);
  }
  if (far <= 0) return std::nullopt;
  near = std::max(near, far * 1e-3f);
  // A cone wider than this has no useful perspective map; what it lights
  // beyond the map is left unshadowed.
  const float half_angle = std::min(light.spot_cutoff, 80.0f) * std::numbers::pi_v<float> / 180;
  result.view = look_along(eye, f);
  result.projection = frustum(near * std::tan(half_angle), near, far, true);
  return result;
}

ShadowMapTexture::ShadowMapTexture(int size) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  size_ = std::clamp(size, 16, std::max(16, static_cast<int>(max_size)));
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size_, size_, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  // Linear filtering of a compared depth texture averages four comparisons:
  // shadow edges a texel soft instead of stair-stepped.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Beyond the map nothing was seen by the light, so nothing is shadowed.
  const GLfloat lit[4] = {1, 1, 1, 1};
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, lit);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
  glBindTexture(GL_TEXTURE_2D, 0);

  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture_, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
    throw ModelError("cannot make a shadow map of " + std::to_string(size_) + " x " + std::to_string(size_) +
                     " texels");
  }
}

ShadowMapTexture::~ShadowMapTexture() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &texture_);
}

void ShadowMapTexture::render(const LightCamera& light, const geometry::ShadowMap& settings,
                              const std::function<void()>& draw_triangles) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, size_, size_);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glClear(GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(light.projection.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(light.view.data());
  // Pushing the recorded depth back keeps lit surfaces from shadowing
  // themselves (shadow acne).
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(settings.offset_factor, settings.offset_units);
  draw_triangles();
  glDisable(GL_POLYGON_OFFSET_FILL);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowMapTexture::darken(const LightCamera& light, const geometry::Mat4& camera_view, const geometry::Rgb& color,
                              const std::function<void()>& draw_triangles) {
  glBindTexture(GL_TEXTURE_2D, texture_);
  glEnable(GL_TEXTURE_2D);
  // Eye-linear planes given under the camera's view produce world
  // coordinates; the texture matrix takes them into the light's map.
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(camera_view.data());
  const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
  const GLenum enables[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q};
  for (int i = 0; i < 4; ++i) {
    GLfloat plane[4] = {0, 0, 0, 0};
    plane[i] = 1;
    glTexGeni(coords[i], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(coords[i], GL_EYE_PLANE, plane);
    glEnable(enables[i]);
  }
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glTranslatef(0.5f, 0.5f, 0.5f);
  glScalef(0.5f, 0.5f, 0.5f);
  glMultMatrixf(light.projection.data());
  glMultMatrixf(light.view.data());
  glMatrixMode(GL_MODELVIEW);

  // The comparison gives 1 where lit and 0 in shadow: interpolating white and
  // the shadow colour by it, then multiplying into the image, darkens only
  // the shadow.
  const GLfloat white[4] = {1, 1, 1, 1};
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_CONSTANT);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_SRC_COLOR);
  glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_TEXTURE);
  glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_COLOR);
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, white);
  glDisable(GL_LIGHTING);
  glColor3f(color.r, color.g, color.b);
  glEnable(GL_BLEND);
  glBlendFunc(GL_DST_COLOR, GL_ZERO);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_LEQUAL);
  // Drawn a hair nearer, so every visible fragment passes the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1, -1);

  draw_triangles();

  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  for (GLenum e : enables) glDisable(e);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

}  // namespace sylva::io::gl
