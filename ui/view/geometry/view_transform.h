#pragma once
// Where the polar view's world (millimetres around the lidar) lands on the screen: zoom about the
// cursor, drag to pan, reset and auto-range. Pure math so it is tested without a GL context.
#include "ui/view/geometry/geometry.h"

namespace ydscope::ui {

// ndc = world * scale + offset, per axis: what the point shader needs as two uniforms.
struct NdcTransform {
  float scale_x, scale_y, offset_x, offset_y;
};

class ViewTransform {
 public:
  static constexpr float kMinPxPerMm = 1e-4f;  // ~1 km across a 200 px window
  static constexpr float kMaxPxPerMm = 50.0f;  // 1 mm = 50 px

  // The screen rectangle the view draws into, in pixels (top-left origin, y down).
  void set_viewport(Vec2 origin_px, Vec2 size_px);
  Vec2 viewport_origin() const { return origin_; }
  Vec2 viewport_size() const { return size_; }
  Vec2 viewport_centre() const { return origin_ + size_ * 0.5f; }

  Vec2 world_to_screen(Vec2 world_mm) const;
  Vec2 screen_to_world(Vec2 screen_px) const;
  NdcTransform ndc_transform() const;
  float px_per_mm() const { return px_per_mm_; }
  Vec2 centre_world() const { return centre_mm_; }

  // Keeps the world point under `screen_px` fixed while scaling by `factor` (> 1 zooms in).
  void zoom_about(Vec2 screen_px, float factor);
  void pan_by_pixels(Vec2 delta_px);
  // Centres the lidar and fits a circle of `range_mm` into the shorter side of the viewport.
  void fit_range(float range_mm);
  // Largest distance from the lidar to any visible pixel, so rings are laid out only where seen.
  float visible_radius_mm() const;
  bool contains_screen(Vec2 screen_px) const;
  // The same framing: where on the screen, how large, centred where, at what zoom. What is drawn
  // from the view (its grid, its merged points, their cover) is kept until it changes.
  friend bool operator==(const ViewTransform&, const ViewTransform&) = default;

 private:
  Vec2 origin_{0.0f, 0.0f};
  Vec2 size_{800.0f, 600.0f};
  Vec2 centre_mm_{0.0f, 0.0f};  // world point at the viewport centre
  float px_per_mm_ = 0.05f;
};

}  // namespace ydscope::ui
