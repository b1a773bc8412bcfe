#pragma once
// The GL side of the points drawn on the CPU (sprite_splat.h): the picture painted again when the
// points or their framing changed, its drawn tiles uploaded to a texture, and laid over the view
// in those tiles, premultiplied over what lies under.
#include <cstdint>
#include <optional>
#include <span>

#include "ui/render/picture_layer.h"
#include "ui/render/sprite_splat.h"

namespace ydscope::ui {

class SplatPicture {
 public:
  SplatPicture();  // needs a current GL 3.3 core context
  ~SplatPicture();
  SplatPicture(const SplatPicture&) = delete;
  SplatPicture& operator=(const SplatPicture&) = delete;

  // Draws `points` framed by `frame` into the viewport at framebuffer pixel (`x`, `y`), `frame`'s
  // size. `points_generation` changes whenever the points do: the same points in the same frame
  // are laid again without painting. The scissor is the caller's.
  void draw(std::span<const PointVertex> points, std::uint64_t points_generation, const SplatFrame& frame, int x,
            int y);

 private:
  void upload_drawn();

  SpriteSplat splat_;
  PictureLayer layer_;
  GLuint texture_ = 0;
  int texture_width_ = 0, texture_height_ = 0;
  struct Painted {
    std::uint64_t points_generation = 0;
    SplatFrame frame;
    friend bool operator==(const Painted&, const Painted&) = default;
  };
  std::optional<Painted> painted_;
};

}  // namespace ydscope::ui
