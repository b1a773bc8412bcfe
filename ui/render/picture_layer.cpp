#include "ui/render/picture_layer.h"

#include "ui/embedded_shaders.h"

namespace ydscope::ui {

PictureLayer::PictureLayer() : program_("laid picture", shaders::k_laid_picture_vert, shaders::k_laid_picture_frag) {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

PictureLayer::~PictureLayer() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void PictureLayer::lay(GLuint texture, const PixelBox& place, std::span<const PixelBox> boxes) {
  corners_.clear();
  for (const PixelBox& b : boxes) {
    if (b.empty()) continue;
    const auto x0 = static_cast<float>(b.x), y0 = static_cast<float>(b.y);
    const auto x1 = static_cast<float>(b.x + b.width), y1 = static_cast<float>(b.y + b.height);
    corners_.insert(corners_.end(), {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
  }
  if (corners_.empty()) return;
  glViewport(place.x, place.y, place.width, place.height);
  program_.use();
  glUniform2f(program_.uniform("u_framebuffer_size"), static_cast<float>(place.width),
              static_cast<float>(place.height));
  glUniform2i(program_.uniform("u_origin"), place.x, place.y);
  glUniform1i(program_.uniform("u_picture"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners_.size() * sizeof(float)), corners_.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners_.size() / 2));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
}

}  // namespace ydscope::ui
