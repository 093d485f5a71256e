// What the GPU derivers (render/gl_stencil.cpp, render/gl_lsystem.cpp) share:
// fragment programs compiled and linked, and strings laid out as texels
// wrapped into rows. Calls OpenGL through the functions a HeadlessGlContext
// sets (render/gl_headless_context.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "render/gl_headless_context.h"

namespace sylva::gpu {

// A program of one fragment shader, its outputs bound to their locations.
// Throws ModelError saying that `what` does not compile or link, with the
// driver's log.
GLuint compile_fragment_program(const std::string& source, const std::vector<std::pair<GLuint, const char*>>& outputs,
                                const std::string& what);

// `count` texels in rows of at most `widest` (and at least one texel, one row).
struct TexelRows {
  long count = 0;
  int width = 1, rows = 1;
};
// Throws ModelError naming `things` ("points", "modules") when they need more
// than `max_size` rows.
TexelRows texel_rows(long count, int widest, int max_size, const char* things);

}  // namespace sylva::gpu
