#include "ui/render/backdrop_picture.h"

#include <vector>

#include "ui/embedded_shaders.h"

namespace ydscope::ui {

BackdropPicture::BackdropPicture() : program_("backdrop", shaders::k_backdrop_vert, shaders::k_backdrop_frag) {
  glGenTextures(1, &texture_);
  glGenFramebuffers(1, &framebuffer_);
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

BackdropPicture::~BackdropPicture() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &texture_);
}

void BackdropPicture::begin(int width, int height) {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawing_to_);
  if (width != width_ || height != height_) {
    width_ = width;
    height_ = height;
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
}

void BackdropPicture::end() { glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(drawing_to_)); }

void BackdropPicture::lay(std::span<const PixelBox> boxes) const {
  std::vector<float> corners;
  corners.reserve(boxes.size() * 12);
  for (const PixelBox& b : boxes) {
    if (b.empty()) continue;
    const auto x0 = static_cast<float>(b.x), y0 = static_cast<float>(b.y);
    const auto x1 = static_cast<float>(b.x + b.width), y1 = static_cast<float>(b.y + b.height);
    corners.insert(corners.end(), {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
  }
  if (corners.empty()) return;
  glViewport(0, 0, width_, height_);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  program_.use();
  glUniform2f(program_.uniform("u_framebuffer_size"), static_cast<float>(width_), static_cast<float>(height_));
  glUniform1i(program_.uniform("u_picture"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners.size() * sizeof(float)), corners.data(),
               GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners.size() / 2));
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
}

}  // namespace ydscope::ui
