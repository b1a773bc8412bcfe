#pragma once
// Draws the polar view with our own shaders: the ring/spoke grid as antialiased line quads, then
// every point of the persistence as round sprites from one vertex buffer in one draw call; on a
// software renderer the sprites are drawn on the CPU instead (sprite_splat.h) and laid as a
// picture. Text labels and markers are left to ImGui's draw lists (see polar_overlay.h).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "ui/render/backdrop_picture.h"
#include "ui/render/gl_program.h"
#include "ui/render/screen_boxes.h"
#include "ui/render/splat_picture.h"
#include "ui/view/geometry/grid_geometry.h"
#include "ui/view/scene/point_cloud.h"
#include "ui/view/geometry/view_transform.h"

namespace ydscope::ui {

// The two things the view draws with GL, in the order a pixel must get them.
enum class GlLayer { grid, points };

struct PolarStyle {
  float point_size_px = 3.0f;
  bool show_grid = true;
  GridStyle grid;
};

// Where the sprites are drawn: as GL points, or on the CPU and laid as a picture (sprite_splat.h).
// `suited`: on the CPU when the context's GL_RENDERER is a software one, unless YDSCOPE_POINTS in
// the environment says "gl" or "cpu".
enum class PointDrawing { suited, gl, cpu };

class PolarRenderer {
 public:
  explicit PolarRenderer(PointDrawing drawing = PointDrawing::suited);  // needs a current GL 3.3 core context
  ~PolarRenderer();
  PolarRenderer(const PolarRenderer&) = delete;
  PolarRenderer& operator=(const PolarRenderer&) = delete;

  // Replace a buffer's contents; call only when the cloud or the grid changed.
  void upload_points(std::span<const PointVertex> points);
  void upload_grid(std::span<const LineVertex> lines);
  std::size_t uploaded_points() const { return points_.count; }
  // How far outside the view (window pixels) a sprite `point_size_px` across may have its centre
  // and still reach into it: the points are drawn in a viewport this much larger than the view
  // (the scissor keeps them to it), so none that shows needs clipping, and a caller may leave out
  // those further out. llvmpipe sends a draw with a point to clip down a slower path that walks
  // all its vertices again.
  static float sprite_reach_px(float point_size_px) { return 0.5f * point_size_px + 1.0f; }

  // `framebuffer_scale` = framebuffer pixels per window pixel (HiDPI); `framebuffer_height` for
  // GL's bottom-up viewport. The grid goes under the points: a pixel's grid is drawn before its
  // points, though a frame drawn in parts may draw every part's grid and then the points once.
  void draw(const ViewTransform& view, const PolarStyle& style, float framebuffer_scale, int framebuffer_height,
            GlLayer layer) const;
  // With the sprites drawn on the CPU: lays `backdrop` (the framebuffer's picture, the grid and
  // what lies under it) with the points over it into `boxes` (framebuffer pixels) in one pass, in
  // place of what they held, and returns true. False, having drawn nothing, when the sprites are
  // GL points or a box reaches outside the view's pixels: the caller then lays the backdrop and
  // draws the points.
  bool lay_points_over(const BackdropPicture& backdrop, std::span<const PixelBox> boxes, const ViewTransform& view,
                       const PolarStyle& style, float framebuffer_scale, int framebuffer_height) const;

 private:
  struct Buffer {
    GLuint vao = 0;
    GLuint vbo = 0;
    std::size_t capacity_bytes = 0;
    std::size_t count = 0;
  };
  static void upload(Buffer& buffer, const void* data, std::size_t bytes, std::size_t count);
  // The view's framebuffer pixels, as its viewport.
  static PixelBox viewport_of(const ViewTransform& view, float framebuffer_scale, int framebuffer_height);
  // The CPU's sprites framed for the view, its viewport `pixels`.
  static SplatFrame splat_frame(const ViewTransform& view, const PolarStyle& style, float framebuffer_scale,
                                const PixelBox& pixels);

  GlProgram point_program_;  // drawing GL points only
  GlProgram line_program_;
  Buffer points_;
  Buffer lines_;
  // Drawing on the CPU: the points as uploaded, and their picture (painted again when drawn after
  // an upload, which a const draw may do: the picture is held by pointer).
  std::unique_ptr<SplatPicture> splat_;
  std::vector<PointVertex> cpu_points_;
  std::uint64_t uploads_ = 0;
};

}  // namespace ydscope::ui
