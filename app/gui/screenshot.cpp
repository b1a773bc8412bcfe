#include "app/gui/screenshot.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <vector>

#include <stb_image_write.h>

#include "ui/render/gl.h"
#include "ui/view/export/whole_file.h"

namespace ydscope::gui {

std::string save_framebuffer_png(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) return "the window has no pixels to save (minimised?).";
  const auto w = static_cast<std::size_t>(width);
  const auto h = static_cast<std::size_t>(height);
  std::vector<unsigned char> pixels(w * h * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  // GL rows run bottom-up; PNG rows top-down.
  std::vector<unsigned char> flipped(pixels.size());
  for (std::size_t row = 0; row < h; ++row) {
    std::memcpy(&flipped[row * w * 3], &pixels[(h - 1 - row) * w * 3], w * 3);
  }
  std::string error;
  if (!stbi_write_png(ui::part_name(path).c_str(), width, height, 3, flipped.data(), width * 3))
    error = "could not write " + path + ": " + std::strerror(errno) + "; is the folder writable?";
  return ui::finish_whole_file(path, error);
}

std::string save_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(ui::part_name(path));
  if (!out) return "could not create " + path + ": " + std::strerror(errno) + ".";
  out << text;
  out.close();
  return ui::finish_whole_file(path,
                               out ? std::string() : "writing " + path + " failed: " + std::strerror(errno) + ".");
}

}  // namespace ydscope::gui
