#include "render/gl_passes.h"

#include <algorithm>

#include "support/diagnostic.h"

namespace sylva::gpu {

GLuint compile_fragment_program(const std::string& source, const std::vector<std::pair<GLuint, const char*>>& outputs,
                                const std::string& what) {
  const GLuint shader = glCreateShader(GL_FRAGMENT_SHADER);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::string log(8192, '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteShader(shader);
    throw ModelError("--gpu: " + what + " does not compile: " + log.c_str());
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  for (const auto& [location, name] : outputs) glBindFragDataLocation(program, location, name);
  glLinkProgram(program);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::string log(8192, '\0');
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteProgram(program);
    throw ModelError("--gpu: " + what + " does not link: " + log.c_str());
  }
  return program;
}

TexelRows texel_rows(long count, int widest, int max_size, const char* things) {
  TexelRows l;
  l.count = count;
  l.width = static_cast<int>(std::max<long>(1, std::min<long>(count, std::min(widest, max_size))));
  l.rows = static_cast<int>(std::max<long>(1, (count + l.width - 1) / l.width));
  if (l.rows > max_size)
    throw ModelError("--gpu: " + std::to_string(count) + " " + things + " do not fit a texture of at most " +
                     std::to_string(max_size) + " x " + std::to_string(max_size) + " texels");
  return l;
}

}  // namespace sylva::gpu
