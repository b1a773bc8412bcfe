#pragma once
// A hidden window's GL 3.3 core context and an offscreen RGBA picture of a given size bound as the
// framebuffer to draw into, for the tests that compare what the app's GL code draws pixel by
// pixel. Needs a display (CTest runs the suite under xvfb-run); false when none would open.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstddef>
#include <vector>

#include "ui/render/gl.h"

namespace ydscope::ui {

class OffscreenGl {
 public:
  OffscreenGl(int width, int height) : width_(width), height_(height) {
    if (!glfwInit()) return;
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    window_ = glfwCreateWindow(32, 32, "offscreen", nullptr, nullptr);
    if (!window_) return;
    glfwMakeContextCurrent(window_);
    glGenFramebuffers(1, &framebuffer_);
    glGenRenderbuffers(1, &colour_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    complete_ = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  }
  ~OffscreenGl() {
    if (window_) {
      glDeleteRenderbuffers(1, &colour_);
      glDeleteFramebuffers(1, &framebuffer_);
      glfwDestroyWindow(window_);
    }
    glfwTerminate();
  }
  OffscreenGl(const OffscreenGl&) = delete;
  OffscreenGl& operator=(const OffscreenGl&) = delete;
  explicit operator bool() const { return complete_; }

  // The picture as drawn so far, bottom row first, RGBA.
  std::vector<unsigned char> picture() const {
    std::vector<unsigned char> pixels(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;
  }

 private:
  int width_, height_;
  GLFWwindow* window_ = nullptr;
  GLuint framebuffer_ = 0;
  GLuint colour_ = 0;
  bool complete_ = false;
};

}  // namespace ydscope::ui
