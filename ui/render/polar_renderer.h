#pragma once
// Draws the polar view with our own shaders: the analytic ring/spoke grid as one full-viewport
// triangle, then every point of the persistence as round sprites from one vertex buffer in one
// draw call. Text labels and markers are left to ImGui's draw lists (see polar_overlay.h).
#include <cstddef>
#include <span>

#include "ui/render/gl_program.h"
#include "ui/view/grid_layout.h"
#include "ui/view/point_cloud.h"
#include "ui/view/view_transform.h"

namespace ydscope::ui {

struct PolarStyle {
  float point_size_px = 3.0f;
  bool show_grid = true;
  float ring_rgba[4] = {0.55f, 0.65f, 0.80f, 0.30f};
  float spoke_rgba[4] = {0.55f, 0.65f, 0.80f, 0.14f};
  float glow_rgba[4] = {0.20f, 0.35f, 0.60f, 0.18f};
};

class PolarRenderer {
 public:
  PolarRenderer();  // needs a current GL 3.3 core context
  ~PolarRenderer();
  PolarRenderer(const PolarRenderer&) = delete;
  PolarRenderer& operator=(const PolarRenderer&) = delete;

  // Replaces the point buffer's contents; call only when the cloud changed.
  void upload_points(std::span<const PointVertex> points);
  std::size_t uploaded_points() const { return count_; }

  // `framebuffer_scale` = framebuffer pixels per window pixel (HiDPI); `framebuffer_height` for
  // GL's bottom-up viewport.
  void draw(const ViewTransform& view, const GridLayout& grid, const PolarStyle& style, float framebuffer_scale,
            int framebuffer_height) const;

 private:
  GlProgram points_;
  GlProgram grid_;
  GLuint points_vao_ = 0;
  GLuint points_vbo_ = 0;
  GLuint empty_vao_ = 0;  // core profile needs a VAO bound even for attribute-less draws
  std::size_t capacity_bytes_ = 0;
  std::size_t count_ = 0;
};

}  // namespace ydscope::ui
