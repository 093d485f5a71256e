// The OpenGL context of the GPU derivers (gl_stencil.cpp, gl_lsystem.cpp):
// headless, rendering into framebuffer objects only, made through
//   EGL   a GPU where there is one (EGL_EXT_platform_device: the first device
//         that is not Mesa's software one, e.g. NVIDIA's or a DRM render
//         node), else Mesa's surfaceless platform (llvmpipe on a machine
//         without one); desktop OpenGL, a compatibility context of 3.3 or
//         later (the shaders are GLSL 1.30 and are drawn by glRectf, with no
//         vertex shader), or
//   OSMesa  Mesa's software rasteriser, as the raster renderer.
// SYLVA_GL=egl or SYLVA_GL=osmesa chooses; unset, EGL where it makes a
// context, else OSMesa, silently. Anything else is an error.
//
// The derivers call OpenGL by its usual names, but those names are the
// function pointers below (sylva::gpu's, hiding the global ones of <GL/gl.h>),
// set for the calling thread by the context from the backend's
// GetProcAddress. The plugin does not link libGL or libOpenGL: under glvnd
// their entry points would clash with libOSMesa's, which the raster renderer
// calls directly.
#pragma once

#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

struct osmesa_context;

namespace sylva::gpu {

// OpenGL 1.0 and 1.1, declared by <GL/gl.h>.
#define SYLVA_GL_1_1_FUNCTIONS(X)                                                                                    \
  X(glBindTexture)                                                                                                   \
  X(glDeleteTextures)                                                                                                \
  X(glDisable)                                                                                                       \
  X(glGenTextures)                                                                                                   \
  X(glGetError)                                                                                                      \
  X(glGetIntegerv)                                                                                                   \
  X(glGetString)                                                                                                     \
  X(glPixelStorei)                                                                                                   \
  X(glReadBuffer)                                                                                                    \
  X(glReadPixels)                                                                                                    \
  X(glRectf)                                                                                                         \
  X(glTexImage2D)                                                                                                    \
  X(glTexParameteri)                                                                                                 \
  X(glViewport)

// Later ones, by their <GL/glext.h> pointer types.
#define SYLVA_GL_LATER_FUNCTIONS(X)                                 \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                        \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                          \
  X(PFNGLBINDFRAGDATALOCATIONPROC, glBindFragDataLocation)          \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                    \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)      \
  X(PFNGLCLAMPCOLORPROC, glClampColor)                              \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                        \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                        \
  X(PFNGLCREATESHADERPROC, glCreateShader)                          \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)              \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                        \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                          \
  X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                            \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)          \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                    \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                          \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                  \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                            \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)              \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                            \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                          \
  X(PFNGLUNIFORM1FVPROC, glUniform1fv)                              \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)

#define SYLVA_GL_DECLARE_1_1(name) inline thread_local decltype(&::name) name = nullptr;
#define SYLVA_GL_DECLARE_LATER(type, name) inline thread_local type name = nullptr;
SYLVA_GL_1_1_FUNCTIONS(SYLVA_GL_DECLARE_1_1)
SYLVA_GL_LATER_FUNCTIONS(SYLVA_GL_DECLARE_LATER)
#undef SYLVA_GL_DECLARE_1_1
#undef SYLVA_GL_DECLARE_LATER

// An OpenGL context current on this thread for the object's lifetime, the
// functions above set. Throws ModelError when none can be made (with the EGL
// error codes) or SYLVA_GL names no backend.
class HeadlessGlContext {
 public:
  HeadlessGlContext();
  ~HeadlessGlContext();
  HeadlessGlContext(const HeadlessGlContext&) = delete;
  HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

  // Which: "EGL device /dev/dri/renderD128: <GL_RENDERER>, OpenGL <GL_VERSION>",
  // "EGL surfaceless: ...", "OSMesa: ...".
  const std::string& description() const { return description_; }

 private:
  bool make_egl(std::string& why);
  void make_osmesa();

  osmesa_context* osmesa_ = nullptr;
  void* egl_context_ = nullptr;  // EGLContext
  void* egl_surface_ = nullptr;  // EGLSurface: a 1x1 pbuffer where surfaceless contexts are not supported
  unsigned char pixel_[4] = {};
  std::string description_;
};

}  // namespace sylva::gpu
