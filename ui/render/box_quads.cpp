#include "ui/render/box_quads.h"

namespace ydscope::ui {

BoxQuads::BoxQuads() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

BoxQuads::~BoxQuads() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void BoxQuads::draw(std::span<const PixelBox> boxes) {
  corners_.clear();
  for (const PixelBox& b : boxes) {
    if (b.empty()) continue;
    const auto x0 = static_cast<float>(b.x), y0 = static_cast<float>(b.y);
    const auto x1 = static_cast<float>(b.x + b.width), y1 = static_cast<float>(b.y + b.height);
    corners_.insert(corners_.end(), {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
  }
  if (corners_.empty()) return;
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners_.size() * sizeof(float)), corners_.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners_.size() / 2));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
}

}  // namespace ydscope::ui
