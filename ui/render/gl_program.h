#pragma once
// A linked GLSL program with its uniform lookups; compile and link errors become exceptions with
// the driver's log, thrown at start-up where main turns them into one sentence.
#include <string>

#include "ui/render/gl.h"

namespace ydscope::ui {

class GlProgram {
 public:
  GlProgram() = default;
  GlProgram(const char* name, const char* vertex_source, const char* fragment_source);
  ~GlProgram();
  GlProgram(GlProgram&& other) noexcept;
  GlProgram& operator=(GlProgram&& other) noexcept;
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const;
  GLint uniform(const char* name) const;  // -1 when the shader has no such active uniform
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

}  // namespace ydscope::ui
