#include "ui/render/backdrop_picture.h"

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

void BackdropPicture::end() { glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(drawing_to_)); }

void BackdropPicture::lay(std::span<const PixelBox> boxes) {
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  layer_.lay(texture_, {0, 0, width_, height_}, boxes);
}

}  // namespace ydscope::ui
