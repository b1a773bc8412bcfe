#include "ui/render/splat_picture.h"

namespace ydscope::ui {

SplatPicture::SplatPicture() { glGenTextures(1, &texture_); }

SplatPicture::~SplatPicture() { glDeleteTextures(1, &texture_); }

void SplatPicture::upload_changed() {
  glBindTexture(GL_TEXTURE_2D, texture_);
  if (splat_.width() != texture_width_ || splat_.height() != texture_height_) {
    texture_width_ = splat_.width();
    texture_height_ = splat_.height();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, texture_width_, texture_height_, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  // A new texture's size comes with a paint that changed every tile (sprite_splat.h).
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, splat_.width());
  for (const PixelBox& run : splat_.changed()) {
    const std::uint8_t* first =
        splat_.pixels() +
        (static_cast<std::size_t>(run.y) * static_cast<std::size_t>(splat_.width()) + static_cast<std::size_t>(run.x)) *
            4;
    glTexSubImage2D(GL_TEXTURE_2D, 0, run.x, run.y, run.width, run.height, GL_RGBA, GL_UNSIGNED_BYTE, first);
  }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void SplatPicture::paint(std::span<const PointVertex> points, std::uint64_t points_generation, const SplatFrame& frame,
                         const SplatGround& ground) {
  const Painted now{points_generation, frame,
                    ground.pixels.empty() ? std::nullopt : std::optional<std::uint64_t>(ground.generation)};
  if (painted_ == now) return;
  splat_.paint(points, frame, ground);
  upload_changed();
  painted_ = now;
}

void SplatPicture::draw(std::span<const PointVertex> points, std::uint64_t points_generation, const SplatFrame& frame,
                        int x, int y) {
  if (frame.width <= 0 || frame.height <= 0) return;
  paint(points, points_generation, frame, {});
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // the picture is premultiplied
  layer_.lay(texture_, {x, y, frame.width, frame.height}, splat_.drawn());
}

void SplatPicture::lay_over(const BackdropPicture& backdrop, std::span<const PixelBox> boxes,
                            std::span<const PointVertex> points, std::uint64_t points_generation,
                            const SplatFrame& frame, int x, int y) {
  if (frame.width <= 0 || frame.height <= 0) return;
  // Read back only when the backdrop was drawn again (a zoom, a resize) or the view moved on it.
  const PixelBox place{x, y, frame.width, frame.height};
  if (const GroundRead now{backdrop.generation(), place}; !(ground_read_ == now)) {
    backdrop.read(place, ground_);
    ++ground_generation_;
    ground_read_ = now;
  }
  paint(points, points_generation, frame, {ground_, ground_generation_});
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  layer_.lay(texture_, place, boxes);
}

}  // namespace ydscope::ui
