#pragma once
// The GL side of the points drawn on the CPU (sprite_splat.h): the picture painted again when the
// points, their framing or what they are painted over changed, the tiles that changed uploaded to
// a texture that keeps the picture whole, and laid over the view. Painted over nothing, it is laid
// in the tiles drawn, premultiplied over what lies under. Painted over the view's backdrop, it
// stands in for the backdrop: laid without a blend into a frame's boxes, the backdrop and the
// sprites go through llvmpipe in one pass instead of two.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "ui/render/backdrop_picture.h"
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
  // The same, painted over `backdrop`'s pixels under the viewport, laid into `boxes` (pixels of the
  // viewport, inside it) in place of what the framebuffer holds there. No blend, no scissor.
  void lay_over(const BackdropPicture& backdrop, std::span<const PixelBox> boxes, std::span<const PointVertex> points,
                std::uint64_t points_generation, const SplatFrame& frame, int x, int y);

 private:
  // The picture brought up to date, and the texture with it.
  void paint(std::span<const PointVertex> points, std::uint64_t points_generation, const SplatFrame& frame,
             const SplatGround& ground);
  void upload_changed();

  SpriteSplat splat_;
  PictureLayer layer_;
  GLuint texture_ = 0;
  int texture_width_ = 0, texture_height_ = 0;
  struct Painted {
    std::uint64_t points_generation = 0;
    SplatFrame frame;
    std::optional<std::uint64_t> ground_generation;  // painted over nothing, or over this ground
    friend bool operator==(const Painted&, const Painted&) = default;
  };
  std::optional<Painted> painted_;
  // The backdrop's pixels under the viewport, as last read, and which drawing of it and where.
  std::vector<std::uint8_t> ground_;
  std::uint64_t ground_generation_ = 0;
  struct GroundRead {
    std::uint64_t backdrop_generation = 0;
    PixelBox place;
    friend bool operator==(const GroundRead&, const GroundRead&) = default;
  };
  std::optional<GroundRead> ground_read_;
};

}  // namespace ydscope::ui
