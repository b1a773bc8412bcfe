#include "ui/render/gl_program.h"

#include <stdexcept>
#include <utility>
#include <vector>

namespace ydscope::ui {
namespace {

GLuint compile(const char* name, GLenum stage, const char* source) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint size = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &size);
    std::vector<char> log(static_cast<std::size_t>(size) + 1, '\0');
    glGetShaderInfoLog(shader, size, nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error(std::string("the ") + name + (stage == GL_VERTEX_SHADER ? " vertex" : " fragment") +
                             " shader does not compile on this OpenGL driver: " + log.data());
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
    GLint size = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &size);
    std::vector<char> log(static_cast<std::size_t>(size) + 1, '\0');
    glGetProgramInfoLog(id_, size, nullptr, log.data());
    glDeleteProgram(id_);
    id_ = 0;
    throw std::runtime_error(std::string("the ") + name + " shaders do not link: " + log.data());
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
