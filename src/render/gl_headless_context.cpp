// The GPU derivers' OpenGL context (gl_headless_context.h): EGL, a device
// (a GPU) or Mesa's surfaceless platform, else OSMesa.
#include "render/gl_headless_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "support/diagnostic.h"

namespace sylva::gpu {
namespace {

std::string egl_error(EGLint code) {
  static const char* const kNames[] = {
      "EGL_SUCCESS",       "EGL_NOT_INITIALIZED", "EGL_BAD_ACCESS",          "EGL_BAD_ALLOC",
      "EGL_BAD_ATTRIBUTE", "EGL_BAD_CONFIG",      "EGL_BAD_CONTEXT",         "EGL_BAD_CURRENT_SURFACE",
      "EGL_BAD_DISPLAY",   "EGL_BAD_MATCH",       "EGL_BAD_NATIVE_PIXMAP",   "EGL_BAD_NATIVE_WINDOW",
      "EGL_BAD_PARAMETER", "EGL_BAD_SURFACE",     "EGL_CONTEXT_LOST"};
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04X", static_cast<unsigned>(code));
  if (code >= EGL_SUCCESS && code <= EGL_CONTEXT_LOST) return std::string(kNames[code - EGL_SUCCESS]) + " (" + hex + ")";
  return hex;
}

std::string last_egl_error() { return egl_error(eglGetError()); }

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t length = std::strlen(name);
  for (const char* at = list; (at = std::strstr(at, name)) != nullptr; at += length) {
    const bool starts = at == list || at[-1] == ' ';
    const bool ends = at[length] == '\0' || at[length] == ' ';
    if (starts && ends) return true;
  }
  return false;
}

// An initialised EGL display on which a desktop OpenGL context of 3.0 or
// later was made once: chosen once a process.
struct EglDisplay {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;  // EGL_NO_CONFIG_KHR where the display has no pbuffer config for OpenGL
  bool surfaceless = false;    // EGL_KHR_surfaceless_context: no pbuffer needed
  bool create_context = false; // EGL 1.5 or EGL_KHR_create_context: versions and profiles
  std::string name;            // "device /dev/dri/renderD128", "surfaceless"
  std::string failure;         // why there is none, where there is none
};

// A context on `d`: a compatibility one of 3.3 or later, else whatever the
// display gives for no attributes (also a compatibility one, checked later).
EGLContext create_context(const EglDisplay& d, std::string& why) {
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why = "eglBindAPI(EGL_OPENGL_API): " + last_egl_error();
    return EGL_NO_CONTEXT;
  }
  if (d.create_context) {
    const EGLint compatibility_3_3[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
    if (EGLContext c = eglCreateContext(d.display, d.config, EGL_NO_CONTEXT, compatibility_3_3)) return c;
    why = "eglCreateContext (OpenGL 3.3, compatibility profile): " + last_egl_error();
  }
  if (EGLContext c = eglCreateContext(d.display, d.config, EGL_NO_CONTEXT, nullptr)) return c;
  why += std::string(why.empty() ? "" : "; ") + "eglCreateContext: " + last_egl_error();
  return EGL_NO_CONTEXT;
}

// Initialises `display` and makes a context on it once; on failure says why
// (appended to `why`) and terminates it.
bool try_display(EGLDisplay display, const std::string& name, EglDisplay& chosen, std::vector<std::string>& why) {
  if (display == EGL_NO_DISPLAY) {
    why.push_back(name + ": eglGetPlatformDisplayEXT: " + last_egl_error());
    return false;
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    why.push_back(name + ": eglInitialize: " + last_egl_error());
    return false;
  }
  EglDisplay d;
  d.display = display;
  d.name = name;
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  d.surfaceless = has_extension(extensions, "EGL_KHR_surfaceless_context");
  d.create_context = major > 1 || minor >= 5 || has_extension(extensions, "EGL_KHR_create_context");
  const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EGLint configs = 0;
  if (!eglChooseConfig(display, wanted, &d.config, 1, &configs) || configs < 1) {
    d.config = EGL_NO_CONFIG_KHR;
    if (!d.surfaceless || !has_extension(extensions, "EGL_KHR_no_config_context")) {
      why.push_back(name + ": no EGL config for OpenGL with pbuffers, nor surfaceless contexts without one");
      eglTerminate(display);
      return false;
    }
  }
  std::string failure;
  const EGLContext context = create_context(d, failure);
  if (context == EGL_NO_CONTEXT) {
    why.push_back(name + ": " + failure);
    eglTerminate(display);
    return false;
  }
  eglDestroyContext(display, context);
  chosen = d;
  return true;
}

EglDisplay choose_egl_display() {
  EglDisplay chosen;
  std::vector<std::string> why;
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const auto get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!client || !has_extension(client, "EGL_EXT_platform_base") || !get_platform_display) {
    chosen.failure = "no EGL_EXT_platform_base (" + (client ? std::string("client extensions: ") + client
                                                            : "eglQueryString: " + last_egl_error()) + ")";
    return chosen;
  }
  // 1. A device that is not Mesa's software one: a GPU.
  const auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  const auto query_device_string =
      reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  if (has_extension(client, "EGL_EXT_platform_device") && query_devices && query_device_string) {
    EGLint count = 0;
    std::vector<EGLDeviceEXT> devices;
    if (query_devices(0, nullptr, &count) && count > 0) {
      devices.resize(static_cast<std::size_t>(count));
      if (!query_devices(count, devices.data(), &count)) count = 0;
      devices.resize(static_cast<std::size_t>(std::max(count, 0)));
    }
    for (std::size_t i = 0; i < devices.size(); ++i) {
      const char* extensions = query_device_string(devices[i], EGL_EXTENSIONS);
      if (has_extension(extensions, "EGL_MESA_device_software")) continue;
      std::string name = "device " + std::to_string(i);
      if (has_extension(extensions, "EGL_EXT_device_drm")) {
        if (const char* file = query_device_string(devices[i], EGL_DRM_DEVICE_FILE_EXT)) name = "device " + std::string(file);
      }
      if (try_display(get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr), name, chosen, why))
        return chosen;
    }
    if (why.empty()) why.push_back("no EGL device but Mesa's software one");
  } else {
    why.push_back("no EGL_EXT_platform_device");
  }
  // 2. Mesa's surfaceless platform: a render node where Mesa drives one, else llvmpipe.
  if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
    if (try_display(get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), "surfaceless",
                    chosen, why))
      return chosen;
  } else {
    why.push_back("no EGL_MESA_platform_surfaceless");
  }
  for (std::size_t i = 0; i < why.size(); ++i) chosen.failure += (i ? "; " : "") + why[i];
  return chosen;
}

const EglDisplay& egl_display() {
  static const EglDisplay chosen = choose_egl_display();  // the display stays initialised for the process
  return chosen;
}

enum class Backend { automatic, egl, osmesa };

Backend requested_backend() {
  const char* value = std::getenv("SYLVA_GL");
  if (!value || !*value) return Backend::automatic;
  if (std::strcmp(value, "egl") == 0) return Backend::egl;
  if (std::strcmp(value, "osmesa") == 0) return Backend::osmesa;
  throw ModelError(std::string("--gpu: SYLVA_GL=") + value +
                   " names no OpenGL: SYLVA_GL=egl (EGL: a GPU, else Mesa's surfaceless platform) or SYLVA_GL=osmesa "
                   "(Mesa's software rasteriser); unset, EGL where it makes a context, else OSMesa");
}

// Sets the functions of gl_headless_context.h from `get`; returns the first
// one missing, nullptr when none is.
template <typename Get>
const char* load_functions(Get get) {
  const char* missing = nullptr;
#define SYLVA_GL_LOAD_1_1(name)                           \
  name = reinterpret_cast<decltype(&::name)>(get(#name)); \
  if (!name && !missing) missing = #name;
#define SYLVA_GL_LOAD_LATER(type, name)      \
  name = reinterpret_cast<type>(get(#name)); \
  if (!name && !missing) missing = #name;
  SYLVA_GL_1_1_FUNCTIONS(SYLVA_GL_LOAD_1_1)
  SYLVA_GL_LATER_FUNCTIONS(SYLVA_GL_LOAD_LATER)
#undef SYLVA_GL_LOAD_1_1
#undef SYLVA_GL_LOAD_LATER
  return missing;
}

std::string gl_string(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "?";
}

}  // namespace

HeadlessGlContext::HeadlessGlContext() {
  const Backend backend = requested_backend();
  if (backend != Backend::osmesa) {
    std::string why;
    if (make_egl(why)) return;
    if (backend == Backend::egl)
      throw ModelError("--gpu: SYLVA_GL=egl: cannot make an OpenGL context through EGL: " + why);
  }
  make_osmesa();
}

bool HeadlessGlContext::make_egl(std::string& why) {
  const EglDisplay& d = egl_display();
  if (d.display == EGL_NO_DISPLAY) {
    why = d.failure;
    return false;
  }
  const EGLContext context = create_context(d, why);
  if (context == EGL_NO_CONTEXT) {
    why = d.name + ": " + why;
    return false;
  }
  why.clear();
  EGLSurface surface = EGL_NO_SURFACE;
  if (!d.surfaceless) {
    const EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface = eglCreatePbufferSurface(d.display, d.config, size);
    if (surface == EGL_NO_SURFACE) {
      why = d.name + ": eglCreatePbufferSurface: " + last_egl_error();
      eglDestroyContext(d.display, context);
      return false;
    }
  }
  if (!eglMakeCurrent(d.display, surface, surface, context)) {
    why = d.name + ": eglMakeCurrent: " + last_egl_error();
    if (surface != EGL_NO_SURFACE) eglDestroySurface(d.display, surface);
    eglDestroyContext(d.display, context);
    return false;
  }
  if (const char* missing =
          load_functions([](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); })) {
    why = d.name + ": eglGetProcAddress gives no " + missing;
  } else {
    GLint major = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    if (major < 3) why = d.name + ": OpenGL 3.0 or later is needed, the context is " + gl_string(GL_VERSION);
  }
  if (!why.empty()) {
    eglMakeCurrent(d.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface != EGL_NO_SURFACE) eglDestroySurface(d.display, surface);
    eglDestroyContext(d.display, context);
    return false;
  }
  egl_context_ = context;
  egl_surface_ = surface;
  description_ = "EGL " + d.name + ": " + gl_string(GL_RENDERER) + ", OpenGL " + gl_string(GL_VERSION);
  return true;
}

void HeadlessGlContext::make_osmesa() {
  osmesa_ = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  if (!osmesa_) throw ModelError("--gpu: cannot create an OpenGL context (OSMesa)");
  if (!OSMesaMakeCurrent(osmesa_, pixel_, GL_UNSIGNED_BYTE, 1, 1)) {
    OSMesaDestroyContext(osmesa_);
    throw ModelError("--gpu: cannot make the OpenGL context current (OSMesa)");
  }
  if (const char* missing =
          load_functions([](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); })) {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(osmesa_);
    osmesa_ = nullptr;
    throw ModelError(std::string("--gpu: OSMesa gives no ") + missing);
  }
  description_ = "OSMesa: " + gl_string(GL_RENDERER) + ", OpenGL " + gl_string(GL_VERSION);
}

HeadlessGlContext::~HeadlessGlContext() {
  if (egl_context_) {
    const EGLDisplay display = egl_display().display;
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (egl_surface_) eglDestroySurface(display, egl_surface_);
    eglDestroyContext(display, egl_context_);
  }
  if (osmesa_) {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(osmesa_);
  }
}

}  // namespace sylva::gpu
