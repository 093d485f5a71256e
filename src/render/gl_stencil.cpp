// The GPU stencil deriver (gpu/stencil_deriver.h): point-subdivision
// L-systems derived in fragment shaders, as in "Generating subdivision curves
// with L-systems on a GPU" (algorithm 1). The points lie in a float texture
// (R32F, RG32F or RGBA32F by dimension), one texel per point, wrapped into rows; each step renders a
// framebuffer texture of k·n texels, texel o = q·k + i computing
// sum_j c[i][j] · p[(q + j - left) mod n]; the two textures ping-pong and the
// last is read back. OpenGL through EGL (a GPU where there is one) or OSMesa
// (Mesa's software rasteriser): gl_headless_context.h.
#include <algorithm>
#include <string>
#include <vector>

#include "gpu/stencil_deriver.h"
#include "render/gl_headless_context.h"
#include "render/gl_passes.h"
#include "support/diagnostic.h"
#include "support/plugin_library.h"

namespace sylva::gpu {
namespace {

constexpr int kMaxCoefficients = 128;

const char* const kFragmentSource = R"(#version 130
uniform sampler2D points;
uniform int n;          // points in the source
uniform int src_width;  // texels per row of the source
uniform int out_width;  // texels per row of the output
uniform int k;
uniform int left;
uniform int span;
uniform float c[128];
// Open curves: rows of their own at the ends (Stencil::open).
uniform bool open;
uniform int head_points, tail_points, head_rows, tail_rows, end_width;
uniform float head[64];
uniform float tail[64];
out vec4 result;
vec4 point(int at) { return texelFetch(points, ivec2(at % src_width, at / src_width), 0); }
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  int o = pixel.y * out_width + pixel.x;
  if (open) {
    vec4 sum = vec4(0.0);
    int inner = n - head_points - tail_points;
    if (o < head_rows) {
      for (int j = 0; j < end_width; ++j) sum += head[o * end_width + j] * point(j);
    } else if (o >= head_rows + k * inner) {
      int r = min(o - (head_rows + k * inner), max(tail_rows - 1, 0));
      for (int j = 0; j < end_width; ++j) sum += tail[r * end_width + j] * point(n - end_width + j);
    } else {
      int m = (o - head_rows) / k;
      int i = (o - head_rows) - m * k;
      int q = head_points + m;
      for (int j = 0; j < span; ++j) sum += c[i * span + j] * point(q + j - left);
    }
    result = sum;
    return;
  }
  int q = min(o / k, n - 1);
  int i = o - (o / k) * k;
  if (i >= k) i = k - 1;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < span; ++j) {
    int at = q + j - left;
    if (at < 0) at += n;
    if (at >= n) at -= n;
    sum += c[i * span + j] * texelFetch(points, ivec2(at % src_width, at / src_width), 0);
  }
  result = sum;
}
)";

// Texels of 1, 2 or 4 floats: R32F for scalars, RG32F for 2D points (half the
// memory of RGBA32F, so twice the points fit llvmpipe's texture limit), RGBA32F
// for 3D and 4D points.
struct TexelFormat {
  int channels;
  GLenum internal, format;
};

TexelFormat texel_format(int dim) {
  if (dim == 1) return {1, GL_R32F, GL_RED};
  if (dim == 2) return {2, GL_RG32F, GL_RG};
  return {4, GL_RGBA32F, GL_RGBA};
}

GLuint make_texture(const TexelRows& l, const TexelFormat& f, const float* data) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, f.internal, l.width, l.rows, 0, f.format, GL_FLOAT, data);
  return texture;
}

class GlStencilDeriver : public StencilDeriver {
 public:
  std::vector<double> derive(const std::vector<double>& points, int dim, const Stencil& s, int steps) override {
    if (dim < 1 || dim > 4) throw ModelError("--gpu: points of 1 to 4 coordinates only");
    if (s.k * s.width() > kMaxCoefficients)
      throw ModelError("--gpu: a stencil of more than " + std::to_string(kMaxCoefficients) + " weights");
    const long n0 = static_cast<long>(points.size()) / dim;
    if (steps == 0 || n0 == 0) return points;
    HeadlessGlContext context;
    context_ = context.description();
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    GLint max_viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
    max_size = std::min({max_size, max_viewport[0], max_viewport[1]});

    const TexelFormat f = texel_format(dim);
    TexelRows src = texel_rows(n0, max_size, max_size, "points");
    std::vector<float> texels(static_cast<std::size_t>(src.width) * src.rows * f.channels, 0.0f);
    for (long q = 0; q < n0; ++q)
      for (int d = 0; d < dim; ++d) texels[q * f.channels + d] = static_cast<float>(points[q * dim + d]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLuint from = make_texture(src, f, texels.data());
    texels = {};

    const GLuint program = compile_fragment_program(kFragmentSource, {{0, "result"}}, "the stencil shader");
    glUseProgram(program);
    std::vector<float> weights(kMaxCoefficients, 0.0f);
    for (std::size_t i = 0; i < s.c.size(); ++i) weights[i] = static_cast<float>(s.c[i]);
    glUniform1fv(glGetUniformLocation(program, "c"), kMaxCoefficients, weights.data());
    glUniform1i(glGetUniformLocation(program, "points"), 0);
    glUniform1i(glGetUniformLocation(program, "k"), s.k);
    glUniform1i(glGetUniformLocation(program, "left"), s.left);
    glUniform1i(glGetUniformLocation(program, "span"), s.width());
    glUniform1i(glGetUniformLocation(program, "open"), s.open ? 1 : 0);
    if (s.open) {
      if (s.head_rows * s.end_width > 64 || s.tail_rows * s.end_width > 64)
        throw ModelError("--gpu: end rules of more than 64 weights");
      std::vector<float> head(64, 0.0f), tail(64, 0.0f);
      std::copy(s.head.begin(), s.head.end(), head.begin());
      std::copy(s.tail.begin(), s.tail.end(), tail.begin());
      glUniform1fv(glGetUniformLocation(program, "head"), 64, head.data());
      glUniform1fv(glGetUniformLocation(program, "tail"), 64, tail.data());
      glUniform1i(glGetUniformLocation(program, "head_points"), s.head_points);
      glUniform1i(glGetUniformLocation(program, "tail_points"), s.tail_points);
      glUniform1i(glGetUniformLocation(program, "head_rows"), s.head_rows);
      glUniform1i(glGetUniformLocation(program, "tail_rows"), s.tail_rows);
      glUniform1i(glGetUniformLocation(program, "end_width"), s.end_width);
    }
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);

    for (int step = 0; step < steps; ++step) {
      const TexelRows out = texel_rows(s.successors(src.count), max_size, max_size, "points");
      const GLuint to = make_texture(out, f, nullptr);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, to, 0);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw ModelError("--gpu: cannot render " + std::to_string(out.count) + " points into a float texture of " +
                         std::to_string(out.width) + " x " + std::to_string(out.rows) + " texels (" +
                         std::to_string(static_cast<long long>(out.width) * out.rows * f.channels * 4 >> 20) +
                         " MiB): framebuffer incomplete, the texture is too large for this OpenGL");
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, from);
      glUniform1i(glGetUniformLocation(program, "n"), static_cast<GLint>(src.count));
      glUniform1i(glGetUniformLocation(program, "src_width"), src.width);
      glUniform1i(glGetUniformLocation(program, "out_width"), out.width);
      glViewport(0, 0, out.width, out.rows);
      glRectf(-1, -1, 1, 1);
      glDeleteTextures(1, &from);
      from = to;
      src = out;
    }

    std::vector<float> result(static_cast<std::size_t>(src.width) * src.rows * f.channels);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, src.width, src.rows, f.format, GL_FLOAT, result.data());
    const GLenum error = glGetError();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &from);
    glUseProgram(0);
    glDeleteProgram(program);
    if (error != GL_NO_ERROR) throw ModelError("--gpu: OpenGL error " + std::to_string(error));

    std::vector<double> derived(static_cast<std::size_t>(src.count) * dim);
    for (long q = 0; q < src.count; ++q)
      for (int d = 0; d < dim; ++d) derived[q * dim + d] = result[q * f.channels + d];
    return derived;
  }
  // "gl", and after a derivation the OpenGL it ran on (HeadlessGlContext::description).
  std::string name() const override { return context_.empty() ? "OpenGL" : "OpenGL on " + context_; }

 private:
  std::string context_;
};

}  // namespace
}  // namespace sylva::gpu

extern "C" SYLVA_PLUGIN_EXPORT sylva::gpu::StencilDeriver* sylva_gl_stencil_deriver() {
  static sylva::gpu::GlStencilDeriver deriver;
  return &deriver;
}
