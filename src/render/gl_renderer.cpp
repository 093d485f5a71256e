// libOSMesa exports OpenGL's later entry points (shaders, framebuffers)
// directly: declared, they need no glXGetProcAddress-style lookup.
#define GL_GLEXT_PROTOTYPES
#include "render/gl_renderer.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "render/gl_batches.h"
#include "render/gl_meshes.h"
#include "render/gl_shadows.h"
#include "render/raster_labels.h"
#include "render/raster_plugin.h"
#include "support/diagnostic.h"

namespace sylva::io {

namespace {

using geometry::Rgb;
using geometry::Vec3;

constexpr int kMaxLights = 8;
constexpr int kMaxSupersampling = 4;

// An OSMesa context rendering into memory of its own; made current on
// construction, released and destroyed with the object, so nothing of one
// render survives into the next.
class OffscreenContext {
 public:
  OffscreenContext(int width, int height)
      : width_(width),
        height_(height),
        pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!context_) throw ModelError("cannot create an offscreen OpenGL context (OSMesa)");
    if (!OSMesaMakeCurrent(context_, pixels_.data(), GL_UNSIGNED_BYTE, width, height)) {
      OSMesaDestroyContext(context_);
      throw ModelError("cannot render an image of " + std::to_string(width) + " x " + std::to_string(height) +
                       " pixels with OSMesa");
    }
  }
  ~OffscreenContext() {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
  }
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  // RGBA, bottom row first (OpenGL's origin), once glFinish has returned.
  const std::uint8_t* pixels() const { return pixels_.data(); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  std::vector<std::uint8_t> pixels_;
  OSMesaContext context_ = nullptr;
};

int supersampling(int antialiasing, int width, int height, int max_size) {
  int factor = antialiasing > 1 ? static_cast<int>(std::ceil(std::sqrt(static_cast<double>(antialiasing)))) : 1;
  factor = std::min(factor, kMaxSupersampling);
  while (factor > 1 && (width * factor > max_size || height * factor > max_size)) --factor;
  return factor;
}

void set_lights(const std::vector<geometry::Light>& given, bool stationary, const geometry::Mat4& view) {
  const std::vector<geometry::Light> fallback(1);
  const std::vector<geometry::Light>& lights = given.empty() ? fallback : given;
  glMatrixMode(GL_MODELVIEW);
  // glLight positions are taken through the current modelview matrix: the
  // camera's for lights fixed in the scene, none for lights in eye space.
  if (stationary)
    glLoadMatrixf(view.data());
  else
    glLoadIdentity();
  // Each lpfg light brings its own ambient term (A:), so OpenGL's global one
  // would only brighten everything twice.
  const GLfloat none[4] = {0, 0, 0, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, none);
  // Leaves and other flat shapes are seen from both sides, and lit on both.
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const int count = std::min(static_cast<int>(lights.size()), kMaxLights);
  for (int i = 0; i < count; ++i) {
    const geometry::Light& l = lights[static_cast<std::size_t>(i)];
    const GLenum id = GL_LIGHT0 + static_cast<GLenum>(i);
    auto rgba = [](const Rgb& c) { return std::array<GLfloat, 4>{c.r, c.g, c.b, 1}; };
    glEnable(id);
    const std::array<GLfloat, 4> position = l.kind == geometry::Light::Kind::Directional
                                                ? std::array<GLfloat, 4>{l.direction.x, l.direction.y, l.direction.z, 0}
                                                : std::array<GLfloat, 4>{l.position.x, l.position.y, l.position.z, 1};
    glLightfv(id, GL_POSITION, position.data());
    glLightfv(id, GL_AMBIENT, rgba(l.ambient).data());
    glLightfv(id, GL_DIFFUSE, rgba(l.diffuse).data());
    glLightfv(id, GL_SPECULAR, rgba(l.specular).data());
    glLightf(id, GL_CONSTANT_ATTENUATION, std::max(0.0f, l.constant_attenuation));
    glLightf(id, GL_LINEAR_ATTENUATION, std::max(0.0f, l.linear_attenuation));
    glLightf(id, GL_QUADRATIC_ATTENUATION, std::max(0.0f, l.quadratic_attenuation));
    if (l.kind == geometry::Light::Kind::Spot) {
      const GLfloat direction[3] = {l.direction.x, l.direction.y, l.direction.z};
      glLightfv(id, GL_SPOT_DIRECTION, direction);
      glLightf(id, GL_SPOT_EXPONENT, std::clamp(l.spot_exponent, 0.0f, 128.0f));
      glLightf(id, GL_SPOT_CUTOFF, l.spot_cutoff >= 180 ? 180.0f : std::clamp(l.spot_cutoff, 0.0f, 90.0f));
    }
  }
  glLoadMatrixf(view.data());
}

// The material of colour index `index` on the sides `face` (GL_FRONT,
// GL_BACK or GL_FRONT_AND_BACK).
void set_material(const geometry::Palette& palette, int index, GLenum face) {
  const geometry::Material& m = palette.at(index);
  const float alpha = 1 - m.transparency;
  auto rgba = [alpha](const Rgb& c) { return std::array<GLfloat, 4>{c.r, c.g, c.b, alpha}; };
  const Rgb black{0, 0, 0};
  // A colormap gives one colour per index: lit, it keeps OpenGL's default
  // ratio of ambient to diffuse reflection (0.2 : 0.8), so the unlit side of
  // a shape is a darker shade of its colour rather than as bright as the lit one.
  const bool full = palette.from_materials;
  const Rgb ambient = full ? m.ambient : Rgb{m.diffuse.r * 0.25f, m.diffuse.g * 0.25f, m.diffuse.b * 0.25f};
  glMaterialfv(face, GL_AMBIENT, rgba(ambient).data());
  glMaterialfv(face, GL_DIFFUSE, rgba(m.diffuse).data());
  glMaterialfv(face, GL_SPECULAR, rgba(full ? m.specular : black).data());
  glMaterialfv(face, GL_EMISSION, rgba(full ? m.emission : black).data());
  glMaterialf(face, GL_SHININESS, std::clamp(m.shininess, 0.0f, 128.0f));
}

// Both sides in `front`, or (cpfg's @; @,) the back in `back`: two-sided
// lighting lights the side facing away from the normals with GL_BACK.
void set_materials(const geometry::Palette& palette, int front, int back) {
  if (back < 0 || back == front) {
    set_material(palette, front, GL_FRONT_AND_BACK);
    return;
  }
  set_material(palette, front, GL_FRONT);
  set_material(palette, back, GL_BACK);
}

// Without a z buffer lpfg draws the string in order, later modules over
// earlier ones. Drawing in that order would take a draw call wherever lines
// and triangles alternate; instead every vertex carries its module's rank as
// its depth (see Batches), and the depth test does the rest. The camera's
// near and far planes still cut as they would.
class StringOrderProgram {
 public:
  static constexpr GLuint kDepthAttribute = 7;

  StringOrderProgram() {
    static const char* const source = R"(#version 130
in float depth;
void main() {
  vec4 clip = gl_ModelViewProjectionMatrix * gl_Vertex;
  gl_ClipDistance[0] = clip.w + clip.z;
  gl_ClipDistance[1] = clip.w - clip.z;
  clip.z = depth * clip.w;
  gl_Position = clip;
  gl_FrontColor = gl_Color;
  gl_TexCoord[0] = gl_MultiTexCoord0;  // fixed-function texturing reads it
}
)";
    const GLuint shader = glCreateShader(GL_VERTEX_SHADER);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    program_ = glCreateProgram();
    glAttachShader(program_, shader);
    glBindAttribLocation(program_, kDepthAttribute, "depth");
    glLinkProgram(program_);
    glDeleteShader(shader);
    GLint linked = GL_FALSE;
    glGetProgramiv(program_, GL_LINK_STATUS, &linked);
    if (!linked) {
      char log[1024] = "";
      glGetProgramInfoLog(program_, sizeof log, nullptr, log);
      glDeleteProgram(program_);
      throw ModelError(std::string("cannot set up OpenGL for drawing in the string's order: ") + log);
    }
  }
  ~StringOrderProgram() {
    glUseProgram(0);
    glDeleteProgram(program_);
  }
  StringOrderProgram(const StringOrderProgram&) = delete;
  StringOrderProgram& operator=(const StringOrderProgram&) = delete;

  void use() const {
    glUseProgram(program_);
    glEnable(GL_CLIP_DISTANCE0);
    glEnable(GL_CLIP_DISTANCE1);
    glEnableVertexAttribArray(kDepthAttribute);
  }

 private:
  GLuint program_ = 0;
};

// Issues the draw calls of `batches`, or just every triangle with no colour
// (for the shadow passes). The arrays stay in client memory: llvmpipe reads
// them where they are, where buffer objects would be copies.
class SceneDrawer {
 public:
  SceneDrawer(const gl::Batches& batches, const geometry::Palette& palette, bool lit, bool string_order,
              float polygon_line_width, const std::vector<GLuint>& textures)
      : batches_(batches),
        palette_(palette),
        lit_(lit),
        string_order_(string_order),
        polygon_line_width_(polygon_line_width),
        textures_(textures) {}

  void draw() const {
    constexpr std::uint32_t kLines = ~0u;  // bound: the lines rather than a mesh
    std::uint32_t bound = kLines - 1;
    int material = -1, back_material = -1;
    float line_width = -1;
    auto set_line_width = [&](float width) {
      if (width != line_width) glLineWidth(line_width = width);
    };
    glEnableClientState(GL_VERTEX_ARRAY);
    for (const gl::Draw& d : batches_.draws()) {
      if (d.kind == gl::Draw::Kind::Triangles) {
        const gl::MeshBatch& mesh = batches_.meshes()[d.mesh];
        if (bound != d.mesh) {
          bind(mesh);
          if (lit_) glEnable(GL_LIGHTING);
          set_line_width(polygon_line_width_);
          bound = d.mesh;
        }
        if (lit_ && (d.material != material || d.back_material != back_material))
          set_materials(palette_, material = d.material, back_material = d.back_material);
        const bool textured = d.texture >= 0 && static_cast<std::size_t>(d.texture) < textures_.size() &&
                              !mesh.mesh->texcoords.empty();
        if (textured) {
          glEnable(GL_TEXTURE_2D);
          glBindTexture(GL_TEXTURE_2D, textures_[static_cast<std::size_t>(d.texture)]);
          glEnableClientState(GL_TEXTURE_COORD_ARRAY);
          glTexCoordPointer(2, GL_FLOAT, sizeof(geometry::TexCoord), mesh.mesh->texcoords.data());
        }
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(d.count), GL_UNSIGNED_INT, mesh.indices.data() + d.first);
        if (textured) {
          glDisableClientState(GL_TEXTURE_COORD_ARRAY);
          glDisable(GL_TEXTURE_2D);
        }
      } else {
        if (bound != kLines) {
          // Pixel lines have no surface to light: they keep their flat colour.
          glDisable(GL_LIGHTING);
          glDisableClientState(GL_NORMAL_ARRAY);
          glEnableClientState(GL_COLOR_ARRAY);
          glVertexPointer(3, GL_FLOAT, sizeof(Vec3), batches_.line_positions().data());
          glColorPointer(4, GL_UNSIGNED_BYTE, 0, batches_.line_colors().data());
          if (string_order_)
            glVertexAttribPointer(StringOrderProgram::kDepthAttribute, 1, GL_FLOAT, GL_FALSE, 0,
                                  batches_.line_depths().data());
          bound = kLines;
        }
        set_line_width(d.width);
        glDrawArrays(GL_LINES, static_cast<GLint>(d.first), static_cast<GLsizei>(d.count));
      }
    }
    glDisable(GL_LIGHTING);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
  }

  void draw_positions_only() const {
    glEnableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    std::uint32_t bound = ~0u;
    for (const gl::Draw& d : batches_.draws()) {
      if (d.kind != gl::Draw::Kind::Triangles) continue;
      const gl::MeshBatch& mesh = batches_.meshes()[d.mesh];
      if (bound != d.mesh) glVertexPointer(3, GL_FLOAT, sizeof(Vec3), mesh.mesh->positions.data());
      bound = d.mesh;
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(d.count), GL_UNSIGNED_INT, mesh.indices.data() + d.first);
    }
  }

 private:
  void bind(const gl::MeshBatch& mesh) const {
    glVertexPointer(3, GL_FLOAT, sizeof(Vec3), mesh.mesh->positions.data());
    if (lit_) {
      glDisableClientState(GL_COLOR_ARRAY);
      glEnableClientState(GL_NORMAL_ARRAY);
      glNormalPointer(GL_FLOAT, sizeof(Vec3), mesh.mesh->normals.data());
    } else {
      glEnableClientState(GL_COLOR_ARRAY);
      glColorPointer(4, GL_UNSIGNED_BYTE, 0, mesh.colors.data());
    }
    if (string_order_)
      glVertexAttribPointer(StringOrderProgram::kDepthAttribute, 1, GL_FLOAT, GL_FALSE, 0, mesh.depths.data());
  }

  const gl::Batches& batches_;
  const geometry::Palette& palette_;
  bool lit_, string_order_;
  float polygon_line_width_;
  const std::vector<GLuint>& textures_;
};

// The textures as OpenGL textures (0 for an empty image), deleted with the object.
class GlTextures {
 public:
  explicit GlTextures(const std::vector<TextureImage>& images) : names_(images.size(), 0) {
    for (std::size_t i = 0; i < images.size(); ++i) {
      const TextureImage& image = images[i];
      if (image.width <= 0 || image.height <= 0) continue;
      glGenTextures(1, &names_[i]);
      glBindTexture(GL_TEXTURE_2D, names_[i]);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    }
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  ~GlTextures() {
    for (GLuint n : names_)
      if (n) glDeleteTextures(1, &n);
  }
  GlTextures(const GlTextures&) = delete;
  GlTextures& operator=(const GlTextures&) = delete;
  const std::vector<GLuint>& names() const { return names_; }

 private:
  std::vector<GLuint> names_;
};

// The camera's image, box-filtered down by `factor` and turned top row first.
Image read_image(const OffscreenContext& context, int factor) {
  Image image;
  image.width = context.width() / factor;
  image.height = context.height() / factor;
  image.rgb.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
  const std::uint8_t* pixels = context.pixels();
  const auto stride = static_cast<std::size_t>(context.width()) * 4;
  const int samples = factor * factor;
  std::uint8_t* out = image.rgb.data();
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      unsigned sum[3] = {0, 0, 0};
      for (int j = 0; j < factor; ++j) {
        const std::uint8_t* row = pixels + static_cast<std::size_t>(context.height() - 1 - (y * factor + j)) * stride;
        for (int i = 0; i < factor; ++i) {
          const std::uint8_t* p = row + static_cast<std::size_t>(x * factor + i) * 4;
          sum[0] += p[0], sum[1] += p[1], sum[2] += p[2];
        }
      }
      for (unsigned s : sum)
        *out++ = static_cast<std::uint8_t>((s + static_cast<unsigned>(samples) / 2) / static_cast<unsigned>(samples));
    }
  }
  return image;
}

}  // namespace

Image gl::draw_image(const geometry::Scene& scene, const geometry::Palette& palette, const geometry::ViewParameters& view,
                   const ImageSettings& settings, int width, int height) {
  // Lower than any OpenGL implementation's limit, so the check can come
  // before a context exists.
  constexpr int kMaxSize = 16384;
  if (width <= 0 || height <= 0 || width > kMaxSize || height > kMaxSize)
    throw ModelError("cannot render an image of " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels (1 to " + std::to_string(kMaxSize) + " each way)");
  using Mode = geometry::RenderMode;
  const geometry::RenderSettings& render = settings.render;
  const bool lit = render.mode == Mode::Shaded || render.mode == Mode::Shadows;
  const bool string_order = !render.z_buffer && !lit;
  const bool pixel_lines = render.line_style == geometry::LineStyle::Pixel;
  const int factor = supersampling(render.antialiasing, width, height, kMaxSize);

  const geometry::Box bounds = gl::drawn_bounds(scene, render.line_style);
  const geometry::Camera camera(view, bounds, width, height);
  std::vector<geometry::TriangleMesh> meshes =
      gl::tessellate_for_view(scene, camera, {render.line_style, settings.contour_sides}, static_cast<float>(factor),
                              render.mode == Mode::Wireframe);
  if (!lit)
    for (auto& mesh : meshes) mesh.normals = {};
  const gl::Batches batches(scene, meshes, palette, {lit, string_order, pixel_lines, static_cast<float>(factor)});

  OffscreenContext context(width * factor, height * factor);
  const float polygon_line_width =
      render.mode == Mode::Wireframe ? std::max(render.wireframe_line_width, 1e-3f) * static_cast<float>(factor) : 1;
  const GlTextures textures(settings.textures);
  const SceneDrawer drawer(batches, palette, lit, string_order, polygon_line_width, textures.names());

  std::optional<gl::LightCamera> shadow_light;
  std::optional<gl::ShadowMapTexture> shadow_map;
  if (render.mode == Mode::Shadows) {
    const std::vector<geometry::Light> default_lights(1);
    shadow_light = gl::shadow_light_camera(settings.lights.empty() ? default_lights : settings.lights,
                                           render.stationary_lights, camera, bounds);
    if (shadow_light) {
      shadow_map.emplace(render.shadow_map.size);
      shadow_map->render(*shadow_light, render.shadow_map, [&] { drawer.draw_positions_only(); });
    }
  }

  glViewport(0, 0, context.width(), context.height());
  const Rgb background = palette.background();
  glClearColor(background.r, background.g, background.b, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(camera.projection().data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(camera.view().data());
  // Where two surfaces meet at the same depth the later module shows, as it
  // does without the z buffer.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  std::optional<StringOrderProgram> string_order_program;
  if (string_order) string_order_program.emplace().use();
  if (batches.transparent()) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }
  if (render.backface_culling) glEnable(GL_CULL_FACE);
  if (render.mode == Mode::Wireframe) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  if (lit) {
    set_lights(settings.lights, render.stationary_lights, camera.view());
    glEnable(GL_NORMALIZE);
    glShadeModel(GL_SMOOTH);
  }

  drawer.draw();
  glDisable(GL_BLEND);
  if (shadow_map)
    shadow_map->darken(*shadow_light, camera.view(), render.shadow_map.color, [&] { drawer.draw_positions_only(); });

  glFinish();
  const GLenum error = glGetError();
  if (error == GL_OUT_OF_MEMORY) throw ModelError("out of memory rendering the image");
  Image image = read_image(context, factor);
  draw_labels(image, scene.labels, palette, camera, settings.label_font);
  return image;
}

namespace {

class GlRenderer final : public RasterRenderer {
 public:
  Image render(const geometry::Scene& scene, const geometry::Palette& palette, const geometry::ViewParameters& view,
               const ImageSettings& settings, int width, int height) override {
    return gl::draw_image(scene, palette, view, settings, width, height);
  }
  std::string encode_png(const std::string& path, const Image& image, const std::string& provenance) override {
    return gl::encode_png(path, image, provenance);
  }
};

}  // namespace

}  // namespace sylva::io

extern "C" SYLVA_PLUGIN_EXPORT sylva::io::RasterRenderer* sylva_raster_renderer() {
  static sylva::io::GlRenderer renderer;
  return &renderer;
}
