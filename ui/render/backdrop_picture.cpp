#include "ui/render/backdrop_picture.h"

#include <algorithm>

namespace ydscope::ui {

BackdropPicture::BackdropPicture() {
  glGenTextures(1, &texture_);
  glGenFramebuffers(1, &framebuffer_);
}

BackdropPicture::~BackdropPicture() {
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

void BackdropPicture::end() {
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(drawing_to_));
  ++generation_;
}

void BackdropPicture::read(const PixelBox& part, std::vector<std::uint8_t>& pixels) const {
  pixels.resize(static_cast<std::size_t>(std::max(part.width, 0)) * static_cast<std::size_t>(std::max(part.height, 0)) *
                4);
  if (part.empty()) return;
  GLint reading_from = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &reading_from);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(part.x, part.y, part.width, part.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(reading_from));
}

void BackdropPicture::lay(std::span<const PixelBox> boxes) {
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  layer_.lay(texture_, {0, 0, width_, height_}, boxes);
}

}  // namespace ydscope::ui
