#pragma once
// A picture kept in a texture laid, pixel for pixel, into boxes of the framebuffer (two triangles a
// box, one draw call, shaders/laid_picture.*): the backdrop into a frame's boxes, the sprites drawn
// on the CPU over their tiles. How it mixes with what lies under is the caller's blend state.
#include <span>
#include <vector>

#include "ui/render/gl.h"
#include "ui/render/gl_program.h"
#include "ui/render/screen_boxes.h"

namespace ydscope::ui {

class PictureLayer {
 public:
  PictureLayer();  // needs a current GL 3.3 core context
  ~PictureLayer();
  PictureLayer(const PictureLayer&) = delete;
  PictureLayer& operator=(const PictureLayer&) = delete;

  // Lays `texture`, whose pixel (0, 0) sits at framebuffer pixel (`place.x`, `place.y`) and which is
  // `place`'s size, in `boxes` (pixels of the texture; empty ones left out). Sets the viewport to
  // `place`; leaves blend and scissor as they are.
  void lay(GLuint texture, const PixelBox& place, std::span<const PixelBox> boxes);

 private:
  GlProgram program_;
  GLuint vao_ = 0, vbo_ = 0;
  std::vector<float> corners_;  // reused
};

}  // namespace ydscope::ui
