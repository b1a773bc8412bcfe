#pragma once
// Boxes of pixels drawn as two triangles each, in one draw call, with whatever program is in use:
// the way a picture kept in a texture is laid into the boxes of a frame. The program's vertex
// shader reads attribute 0 as a box corner in the viewport's pixels (shaders/laid_picture.vert).
#include <span>
#include <vector>

#include "ui/render/gl.h"
#include "ui/render/screen_boxes.h"

namespace ydscope::ui {

class BoxQuads {
 public:
  BoxQuads();  // needs a current GL 3.3 core context
  ~BoxQuads();
  BoxQuads(const BoxQuads&) = delete;
  BoxQuads& operator=(const BoxQuads&) = delete;

  // Draws `boxes` (empty ones left out) with the program and state in use.
  void draw(std::span<const PixelBox> boxes);

 private:
  GLuint vao_ = 0, vbo_ = 0;
  std::vector<float> corners_;  // reused
};

}  // namespace ydscope::ui
