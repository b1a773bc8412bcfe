#include "ui/render/polar_renderer.h"

#include <algorithm>
#include <cmath>

#include "ui/embedded_shaders.h"

namespace ydscope::ui {

PolarRenderer::PolarRenderer()
    : points_("point", shaders::k_points_vert, shaders::k_points_frag),
      grid_("grid", shaders::k_grid_vert, shaders::k_grid_frag) {
  glGenVertexArrays(1, &points_vao_);
  glGenBuffers(1, &points_vbo_);
  glBindVertexArray(points_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, points_vbo_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(PointVertex), nullptr);
  glEnableVertexAttribArray(1);
  // The colour follows the two floats; GL takes the offset as a pointer by its API's convention.
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(PointVertex),
                        reinterpret_cast<const void*>(offsetof(PointVertex, colour)));
  glBindVertexArray(0);
  glGenVertexArrays(1, &empty_vao_);
}

PolarRenderer::~PolarRenderer() {
  glDeleteBuffers(1, &points_vbo_);
  glDeleteVertexArrays(1, &points_vao_);
  glDeleteVertexArrays(1, &empty_vao_);
}

void PolarRenderer::upload_points(std::span<const PointVertex> points) {
  glBindBuffer(GL_ARRAY_BUFFER, points_vbo_);
  const std::size_t bytes = points.size_bytes();
  if (bytes > capacity_bytes_) {
    capacity_bytes_ = std::max(bytes, capacity_bytes_ * 2);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_bytes_), nullptr, GL_STREAM_DRAW);
  } else {
    // Orphan the old storage so the driver need not wait for the previous frame's draw.
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_bytes_), nullptr, GL_STREAM_DRAW);
  }
  if (bytes > 0) glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), points.data());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  count_ = points.size();
}

void PolarRenderer::draw(const ViewTransform& view, const GridLayout& grid, const PolarStyle& style,
                         float framebuffer_scale, int framebuffer_height) const {
  const Vec2 origin = view.viewport_origin() * framebuffer_scale;
  const Vec2 size = view.viewport_size() * framebuffer_scale;
  const auto x = static_cast<GLint>(std::lround(origin.x));
  const auto w = static_cast<GLsizei>(std::lround(size.x));
  const auto h = static_cast<GLsizei>(std::lround(size.y));
  const auto y = static_cast<GLint>(framebuffer_height - std::lround(origin.y) - h);
  glViewport(x, y, w, h);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);

  if (style.show_grid) {
    grid_.use();
    const Vec2 centre_fb{static_cast<float>(x) + 0.5f * static_cast<float>(w),
                         static_cast<float>(y) + 0.5f * static_cast<float>(h)};
    glUniform2f(grid_.uniform("u_centre_px"), centre_fb.x, centre_fb.y);
    glUniform2f(grid_.uniform("u_centre_world"), view.centre_world().x, view.centre_world().y);
    glUniform1f(grid_.uniform("u_px_per_mm"), view.px_per_mm() * framebuffer_scale);
    glUniform1f(grid_.uniform("u_ring_step_mm"), grid.ring_step_mm);
    glUniform1f(grid_.uniform("u_spoke_step_deg"),
                grid.spoke_angles_deg.size() > 1 ? grid.spoke_angles_deg[1] - grid.spoke_angles_deg[0] : 30.0f);
    glUniform1f(grid_.uniform("u_max_ring_mm"), grid.ring_radii_mm.empty() ? 0.0f : grid.ring_radii_mm.back());
    glUniform4fv(grid_.uniform("u_ring_colour"), 1, style.ring_rgba);
    glUniform4fv(grid_.uniform("u_spoke_colour"), 1, style.spoke_rgba);
    glUniform4fv(grid_.uniform("u_glow_colour"), 1, style.glow_rgba);
    glBindVertexArray(empty_vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  if (count_ > 0) {
    glEnable(GL_PROGRAM_POINT_SIZE);
    points_.use();
    const NdcTransform ndc = view.ndc_transform();
    glUniform4f(points_.uniform("u_ndc"), ndc.scale_x, ndc.scale_y, ndc.offset_x, ndc.offset_y);
    glUniform1f(points_.uniform("u_point_size"), style.point_size_px * framebuffer_scale);
    glBindVertexArray(points_vao_);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count_));
  }
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace ydscope::ui
