#include "ui/view/geometry/view_transform.h"

#include <algorithm>
#include <cmath>

namespace ydscope::ui {

void ViewTransform::set_viewport(Vec2 origin_px, Vec2 size_px) {
  origin_ = origin_px;
  size_ = {std::max(size_px.x, 1.0f), std::max(size_px.y, 1.0f)};
}

Vec2 ViewTransform::world_to_screen(Vec2 world_mm) const {
  const Vec2 c = viewport_centre();
  return {c.x + (world_mm.x - centre_mm_.x) * px_per_mm_, c.y - (world_mm.y - centre_mm_.y) * px_per_mm_};
}

Vec2 ViewTransform::screen_to_world(Vec2 screen_px) const {
  const Vec2 c = viewport_centre();
  return {centre_mm_.x + (screen_px.x - c.x) / px_per_mm_, centre_mm_.y - (screen_px.y - c.y) / px_per_mm_};
}

NdcTransform ViewTransform::ndc_transform() const {
  // The GL viewport is set to this rectangle, so NDC spans exactly size_ pixels.
  const float sx = 2.0f * px_per_mm_ / size_.x;
  const float sy = 2.0f * px_per_mm_ / size_.y;
  return {sx, sy, -centre_mm_.x * sx, -centre_mm_.y * sy};
}

void ViewTransform::zoom_about(Vec2 screen_px, float factor) {
  if (!(factor > 0.0f)) return;
  const Vec2 anchor = screen_to_world(screen_px);
  px_per_mm_ = std::clamp(px_per_mm_ * factor, kMinPxPerMm, kMaxPxPerMm);
  // Move the centre so the anchor maps back to the same pixel.
  const Vec2 c = viewport_centre();
  centre_mm_ = {anchor.x - (screen_px.x - c.x) / px_per_mm_, anchor.y + (screen_px.y - c.y) / px_per_mm_};
}

void ViewTransform::pan_by_pixels(Vec2 delta_px) {
  centre_mm_.x -= delta_px.x / px_per_mm_;
  centre_mm_.y += delta_px.y / px_per_mm_;
}

void ViewTransform::fit_range(float range_mm) {
  const float r = std::max(range_mm, 100.0f);
  const float half = 0.5f * std::min(size_.x, size_.y);
  centre_mm_ = {0.0f, 0.0f};
  px_per_mm_ = std::clamp(half * 0.92f / r, kMinPxPerMm, kMaxPxPerMm);
}

float ViewTransform::visible_radius_mm() const {
  float best = 0.0f;
  const Vec2 corners[4] = {
      origin_, {origin_.x + size_.x, origin_.y}, {origin_.x, origin_.y + size_.y}, origin_ + size_};
  for (const Vec2& corner : corners) best = std::max(best, length(screen_to_world(corner)));
  return best;
}

bool ViewTransform::contains_screen(Vec2 p) const {
  return p.x >= origin_.x && p.y >= origin_.y && p.x <= origin_.x + size_.x && p.y <= origin_.y + size_.y;
}

}  // namespace ydscope::ui
