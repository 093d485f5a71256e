// The GPU L-system deriver (gpu/lsystem_glsl.h): algorithm 2 of "Generating
// subdivision curves with L-systems on a GPU", in fragment shaders through
// OpenGL through EGL or OSMesa (gl_headless_context.h), as gl_stencil.cpp.
//
// A string of n modules lies in two textures wrapped into rows of W texels:
// RGBA32F the parameters (4 floats), R32I the module's type. Each step:
//   1. fragment program 1, per module: the productions in order (the
//      model's translated GLSL), writing (successor length, production) into
//      an RG32I texture;
//   2. the scan-add: Hillis-Steele passes over RG32I textures, ping-pong,
//      `radix` values per pass (the paper's footnote 7), the first reading
//      the lengths shifted by one, so that after ⌈log_radix n⌉ passes texel
//      i holds (exclusive prefix sum, own length); its last texel, read back
//      alone, gives the new string's length;
//   3. fragment program 3, per output texel j: a binary search in the sums
//      finds the module i whose successor holds j (the largest i whose sum
//      is at most j), and production[i]'s body, run again, gives module
//      j - sum[i] of it. The paper draws line segments built on the CPU from
//      the sums read back; the search keeps the sums on the GPU and needs no
//      readback but the total.
// The final string is read back once.
#include <algorithm>
#include <string>
#include <vector>

#include "gpu/lsystem_glsl.h"
#include "render/gl_headless_context.h"
#include "render/gl_passes.h"
#include "support/diagnostic.h"
#include "support/plugin_library.h"

namespace sylva::gpu {
namespace {

const char* const kPrelude = R"(#version 130
uniform isampler2D sylva_types;
uniform sampler2D sylva_values;
uniform int sylva_n;
uniform int sylva_width;
uniform bool sylva_ring;
uniform int sylva_out_width;
ivec2 sylva_texel(int i) { return ivec2(i % sylva_width, i / sylva_width); }
bool sylva_module(int i, out int type, out vec4 params) {
  if (i < 0 || i >= sylva_n) {
    if (!sylva_ring) { type = -1; params = vec4(0.0); return false; }
    i = i < 0 ? sylva_n - 1 - (-i - 1) % sylva_n : i % sylva_n;  // % of non-negative numbers only
  }
  type = texelFetch(sylva_types, sylva_texel(i), 0).r;
  params = texelFetch(sylva_values, sylva_texel(i), 0);
  return true;
}
int sylva_here() { ivec2 p = ivec2(gl_FragCoord.xy); return p.y * sylva_out_width + p.x; }
)";

// Fragment program 1.
const char* const kMatchMain = R"(
out ivec2 sylva_result;
void main() {
  int i = sylva_here();
  if (i >= sylva_n) { sylva_result = ivec2(0, -1); return; }
  int len;
  int p = sylva_match(i, len);
  sylva_result = ivec2(len, p);
}
)";

// Fragment program 2: one pass of the scan-add.
const char* const kScanSource = R"(#version 130
uniform isampler2D sylva_from;
uniform bool sylva_first;   // sylva_from holds (length, production): sum the lengths shifted by one
uniform int sylva_n;
uniform int sylva_width;
uniform int sylva_stride;
uniform int sylva_radix;
out ivec2 sylva_result;
ivec2 at(int i) { return ivec2(i % sylva_width, i / sylva_width); }
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int i = p.y * sylva_width + p.x;
  if (i >= sylva_n) { sylva_result = ivec2(0); return; }
  int sum = 0;
  for (int m = 0; m < sylva_radix; ++m) {
    int j = i - m * sylva_stride;
    if (sylva_first) j -= 1;
    if (j < 0) break;
    sum += texelFetch(sylva_from, at(j), 0).x;
  }
  ivec2 own = texelFetch(sylva_from, at(i), 0).xy;
  sylva_result = ivec2(sum, sylva_first ? own.x : own.y);
}
)";

// Fragment program 3.
const char* const kApplyMain = R"(
uniform isampler2D sylva_sums;     // (exclusive sum, length)
uniform isampler2D sylva_matched;  // (length, production)
uniform int sylva_total;
out vec4 sylva_out_values;
out int sylva_out_type;
void main() {
  int j = sylva_here();
  if (j >= sylva_total) { sylva_out_values = vec4(0.0); sylva_out_type = -1; return; }
  int lo = 0, hi = sylva_n - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (texelFetch(sylva_sums, sylva_texel(mid), 0).x <= j) lo = mid; else hi = mid - 1;
  }
  int want = j - texelFetch(sylva_sums, sylva_texel(lo), 0).x;
  int p = texelFetch(sylva_matched, sylva_texel(lo), 0).y;
  int type; vec4 values;
  if (p < 0) sylva_module(lo, type, values);
  else sylva_apply(p, lo, want, type, values);
  sylva_out_values = values;
  sylva_out_type = type;
}
)";

GLuint make_texture(const TexelRows& l, GLenum internal, GLenum format, GLenum type, const void* data) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), l.width, l.rows, 0, format, type, data);
  return texture;
}

void bind(GLuint program, const char* sampler, int unit, GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D, texture);
  glUniform1i(glGetUniformLocation(program, sampler), unit);
}

void set_int(GLuint program, const char* name, long value) {
  glUniform1i(glGetUniformLocation(program, name), static_cast<GLint>(value));
}

class Gl : public GlLsystemDeriver {
 public:
  void set_layout(int row_width, int radix) override {
    row_width_ = row_width;
    radix_ = std::max(2, radix);
  }

  GpuString derive(const LsystemProgram& program, const GpuString& string, int steps) override {
    if (steps <= 0 || string.size() == 0) return string;
    HeadlessGlContext context;
    context_ = context.description();
    setup();
    TexelRows src = layout_for(static_cast<long>(string.size()));
    std::vector<float> values(static_cast<std::size_t>(src.width) * src.rows * 4, 0.0f);
    std::vector<GLint> types(static_cast<std::size_t>(src.width) * src.rows, -1);
    for (std::size_t i = 0; i < string.size(); ++i) {
      types[i] = string.types[i];
      for (int c = 0; c < 4; ++c) values[4 * i + c] = static_cast<float>(string.params[4 * i + c]);
    }
    GLuint from_values = make_texture(src, GL_RGBA32F, GL_RGBA, GL_FLOAT, values.data());
    GLuint from_types = make_texture(src, GL_R32I, GL_RED_INTEGER, GL_INT, types.data());
    values = {};
    types = {};

    const std::string prelude = std::string(kPrelude) + program.glsl;
    const GLuint match =
        compile_fragment_program(prelude + kMatchMain, {{0, "sylva_result"}}, "fragment program 1 (the productions)");
    const GLuint scan = compile_fragment_program(kScanSource, {{0, "sylva_result"}}, "fragment program 2 (the scan-add)");
    const GLuint apply = compile_fragment_program(
        prelude + kApplyMain, {{0, "sylva_out_values"}, {1, "sylva_out_type"}}, "fragment program 3 (the successors)");

    for (int step = 0; step < steps && src.count > 0; ++step) {
      // 1: production and successor length per module.
      const GLuint matched = make_texture(src, GL_RG32I, GL_RG_INTEGER, GL_INT, nullptr);
      target({matched}, src);
      glUseProgram(match);
      string_uniforms(match, program, src, from_types, from_values);
      set_int(match, "sylva_out_width", src.width);
      glRectf(-1, -1, 1, 1);
      // 2: the scan-add.
      const GLuint sums = scan_passes(scan, matched, src);
      glReadBuffer(GL_COLOR_ATTACHMENT0);
      GLint last[2] = {0, 0};
      const long n1 = src.count - 1;
      glReadPixels(static_cast<GLint>(n1 % src.width), static_cast<GLint>(n1 / src.width), 1, 1, GL_RG_INTEGER, GL_INT,
                   last);
      const long total = static_cast<long>(last[0]) + last[1];
      check("the scan-add");
      // 3: the successors.
      const TexelRows out = layout_for(total);
      const GLuint to_values = make_texture(out, GL_RGBA32F, GL_RGBA, GL_FLOAT, nullptr);
      const GLuint to_types = make_texture(out, GL_R32I, GL_RED_INTEGER, GL_INT, nullptr);
      if (total > 0) {
        target({to_values, to_types}, out);
        glUseProgram(apply);
        string_uniforms(apply, program, src, from_types, from_values);
        set_int(apply, "sylva_out_width", out.width);
        set_int(apply, "sylva_total", total);
        bind(apply, "sylva_sums", 2, sums);
        bind(apply, "sylva_matched", 3, matched);
        glRectf(-1, -1, 1, 1);
      }
      glDeleteTextures(1, &matched);
      glDeleteTextures(1, &sums);
      glDeleteTextures(1, &from_values);
      glDeleteTextures(1, &from_types);
      from_values = to_values;
      from_types = to_types;
      src = out;
      check("a derivation step");
    }

    GpuString result;
    if (src.count > 0) {
      std::vector<float> got(static_cast<std::size_t>(src.width) * src.rows * 4);
      std::vector<GLint> got_types(static_cast<std::size_t>(src.width) * src.rows);
      target({from_values, from_types}, src);
      glReadBuffer(GL_COLOR_ATTACHMENT0);
      glReadPixels(0, 0, src.width, src.rows, GL_RGBA, GL_FLOAT, got.data());
      glReadBuffer(GL_COLOR_ATTACHMENT1);
      glReadPixels(0, 0, src.width, src.rows, GL_RED_INTEGER, GL_INT, got_types.data());
      check("reading the string back");
      result.types.assign(got_types.begin(), got_types.begin() + src.count);
      result.params.assign(got.begin(), got.begin() + 4 * src.count);
    }
    glDeleteTextures(1, &from_values);
    glDeleteTextures(1, &from_types);
    finish({match, scan, apply});
    return result;
  }

  std::vector<std::int64_t> scan_add(const std::vector<std::int32_t>& lengths) override {
    if (lengths.empty()) return {};
    HeadlessGlContext context;
    context_ = context.description();
    setup();
    const TexelRows l = layout_for(static_cast<long>(lengths.size()));
    // What fragment program 1 writes: (length, production).
    std::vector<GLint> texels(static_cast<std::size_t>(l.width) * l.rows * 2, 0);
    for (std::size_t i = 0; i < lengths.size(); ++i) texels[2 * i] = lengths[i];
    const GLuint matched = make_texture(l, GL_RG32I, GL_RG_INTEGER, GL_INT, texels.data());
    const GLuint scan = compile_fragment_program(kScanSource, {{0, "sylva_result"}}, "fragment program 2 (the scan-add)");
    const GLuint sums = scan_passes(scan, matched, l);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, l.width, l.rows, GL_RG_INTEGER, GL_INT, texels.data());
    check("the scan-add");
    std::vector<std::int64_t> result(lengths.size());
    for (std::size_t i = 0; i < lengths.size(); ++i) result[i] = texels[2 * i];
    glDeleteTextures(1, &matched);
    glDeleteTextures(1, &sums);
    finish({scan});
    return result;
  }

  // "gl", and after a derivation the OpenGL it ran on (HeadlessGlContext::description).
  std::string name() const override { return context_.empty() ? "OpenGL" : "OpenGL on " + context_; }

 private:
  void setup() {
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    GLint max_viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
    max_size_ = std::min({max_size, max_viewport[0], max_viewport[1]});
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glClampColor(GL_CLAMP_FRAGMENT_COLOR, GL_FALSE);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_DITHER);
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  }

  void finish(const std::vector<GLuint>& programs) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer_);
    glUseProgram(0);
    for (GLuint p : programs) glDeleteProgram(p);
  }

  TexelRows layout_for(long count) const {
    return texel_rows(count, row_width_ > 0 ? row_width_ : max_size_, max_size_, "modules");
  }

  void target(const std::vector<GLuint>& textures, const TexelRows& l) {
    std::vector<GLenum> buffers;
    for (std::size_t k = 0; k < textures.size(); ++k) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k), GL_TEXTURE_2D,
                             textures[k], 0);
      buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k));
    }
    for (std::size_t k = textures.size(); k < 2; ++k)
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k), GL_TEXTURE_2D, 0, 0);
    glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw ModelError("--gpu: cannot render " + std::to_string(l.count) + " modules into textures of " +
                       std::to_string(l.width) + " x " + std::to_string(l.rows) +
                       " texels: framebuffer incomplete, the texture is too large for this OpenGL");
    glViewport(0, 0, l.width, l.rows);
  }

  void string_uniforms(GLuint p, const LsystemProgram& program, const TexelRows& src, GLuint types, GLuint values) {
    bind(p, "sylva_types", 0, types);
    bind(p, "sylva_values", 1, values);
    set_int(p, "sylva_n", src.count);
    set_int(p, "sylva_width", src.width);
    set_int(p, "sylva_ring", program.ring ? 1 : 0);
  }

  // The Hillis-Steele passes from the (length, production) texture `matched`:
  // returns the texture of (exclusive sum, length), bound as the target.
  GLuint scan_passes(GLuint scan, GLuint matched, const TexelRows& l) {
    glUseProgram(scan);
    set_int(scan, "sylva_n", l.count);
    set_int(scan, "sylva_width", l.width);
    set_int(scan, "sylva_radix", radix_);
    GLuint from = matched, to = 0, spare = 0;
    bool first = true;
    long stride = 1;
    while (true) {
      if (!to) to = make_texture(l, GL_RG32I, GL_RG_INTEGER, GL_INT, nullptr);
      target({to}, l);
      bind(scan, "sylva_from", 0, from);
      set_int(scan, "sylva_first", first ? 1 : 0);
      set_int(scan, "sylva_stride", stride);
      glRectf(-1, -1, 1, 1);
      const long covered = stride * radix_;
      if (!first) spare = from;
      from = to;
      to = spare;
      spare = 0;
      first = false;
      stride = covered;
      if (covered >= l.count) break;
    }
    if (to) glDeleteTextures(1, &to);
    target({from}, l);
    return from;
  }

  static void check(const char* what) {
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR) throw ModelError(std::string("--gpu: OpenGL error ") + std::to_string(error) + " in " + what);
  }

  std::string context_;
  int row_width_ = 0;
  int radix_ = 2;
  int max_size_ = 4096;
  GLuint framebuffer_ = 0;
};

}  // namespace
}  // namespace sylva::gpu

extern "C" SYLVA_PLUGIN_EXPORT sylva::gpu::GlLsystemDeriver* sylva_gl_lsystem_deriver() {
  static sylva::gpu::Gl deriver;
  return &deriver;
}
