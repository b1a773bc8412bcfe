#include "ui/render/gl_program.h"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ydscope::ui {
namespace {

// What the driver said about a shader or a program that failed, read with that object's own pair
// of calls (glGetShaderiv and glGetShaderInfoLog, or the program's).
template <typename GetParameter, typename GetLog>
std::string info_log(GLuint id, GetParameter get_parameter, GetLog get_log) {
  GLint size = 0;
  get_parameter(id, GL_INFO_LOG_LENGTH, &size);
  std::vector<char> log(static_cast<std::size_t>(size) + 1, '\0');
  get_log(id, size, nullptr, log.data());
  return log.data();
}

GLuint compile(const char* name, GLenum stage, const char* source) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(shader, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("the ") + name + (stage == GL_VERTEX_SHADER ? " vertex" : " fragment") +
                             " shader does not compile on this OpenGL driver: " + log);
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(const char* name, const char* vertex_source, const char* fragment_source) {
  const GLuint vs = compile(name, GL_VERTEX_SHADER, vertex_source);
  const GLuint fs = compile(name, GL_FRAGMENT_SHADER, fragment_source);
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = info_log(id_, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(id_);
    id_ = 0;
    throw std::runtime_error(std::string("the ") + name + " shaders do not link: " + log);
  }
}

GlProgram::~GlProgram() {
  if (id_ != 0) glDeleteProgram(id_);
}

GlProgram::GlProgram(GlProgram&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

GlProgram& GlProgram::operator=(GlProgram&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

void GlProgram::use() const { glUseProgram(id_); }

GLint GlProgram::uniform(const char* name) const { return glGetUniformLocation(id_, name); }

}  // namespace ydscope::ui
