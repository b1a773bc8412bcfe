#pragma once
// The view's background and grid kept as a picture, to lay into the boxes of a frame drawn in
// parts. Between two laps only the boxes round the points are drawn again; rastering the grid's
// lines once a box sent every line through llvmpipe's pipeline once a box, which cost more than
// the boxes saved. The picture is drawn once when the grid changes (its caller draws it between
// begin and end, exactly as into the window) and then laid, pixel for pixel, into every box in
// one pass, which replaces both the box's clear and its grid.
#include <cstdint>
#include <span>
#include <vector>

#include "ui/render/picture_layer.h"
#include "ui/render/screen_boxes.h"

namespace ydscope::ui {

class BackdropPicture {
 public:
  BackdropPicture();  // needs a current GL 3.3 core context
  ~BackdropPicture();
  BackdropPicture(const BackdropPicture&) = delete;
  BackdropPicture& operator=(const BackdropPicture&) = delete;

  // Draws go to the picture, `width` x `height` like the framebuffer it stands in for, until end.
  void begin(int width, int height);
  void end();
  // Copies the picture's pixels in `boxes` (framebuffer pixels) to the framebuffer bound, as they
  // are: no blend, no scissor.
  void lay(std::span<const PixelBox> boxes);
  // The picture's pixels in `part` (framebuffer pixels, inside the picture) into `pixels`: RGBA,
  // bottom row first. For the sprites drawn on the CPU over it (splat_picture.h).
  void read(const PixelBox& part, std::vector<std::uint8_t>& pixels) const;
  // Changes each time the picture is drawn.
  std::uint64_t generation() const { return generation_; }

 private:
  PictureLayer layer_;
  GLuint texture_ = 0, framebuffer_ = 0;
  int width_ = 0, height_ = 0;
  GLint drawing_to_ = 0;  // the framebuffer that was bound at begin
  std::uint64_t generation_ = 0;
};

}  // namespace ydscope::ui
