#include "ui/render/polar_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <string_view>

#include "ui/embedded_shaders.h"
#include "ui/view/window/frame_pacing.h"

namespace ydscope::ui {
namespace {

// GL takes attribute offsets as pointers by its API's convention.
const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(bytes)); }

// One attribute of a vertex: how many components of which type, whether integers read as 0..1,
// and where in the vertex it sits.
struct Attribute {
  GLint components;
  GLenum type;
  GLboolean normalized;
  std::size_t at;
};

// A vertex array over a buffer of its own, attribute i read as `layout[i]` says; left bound.
void create_vertex_array(GLuint& vao, GLuint& vbo, GLsizei stride, std::initializer_list<Attribute> layout) {
  glGenVertexArrays(1, &vao);
  glGenBuffers(1, &vbo);
  glBindVertexArray(vao);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  GLuint index = 0;
  for (const Attribute& attribute : layout) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, attribute.components, attribute.type, attribute.normalized, stride,
                          offset(attribute.at));
    ++index;
  }
}

// llvmpipe spends about four times the CPU on the sprites that sprite_splat.h does (bench_frame's
// BM_PointsOnly); a GPU is the other way round.
bool draws_points_on_cpu(PointDrawing drawing) {
  if (drawing != PointDrawing::suited) return drawing == PointDrawing::cpu;
  if (const char* asked = std::getenv("YDSCOPE_POINTS"); asked != nullptr) {
    if (std::string_view(asked) == "cpu") return true;
    if (std::string_view(asked) == "gl") return false;
  }
  return is_software_renderer(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
}

}  // namespace

PolarRenderer::PolarRenderer(PointDrawing drawing)
    : line_program_("grid line", shaders::k_lines_vert, shaders::k_lines_frag) {
  // One way of drawing the sprites is made, not both: a program is a compile at start-up.
  if (draws_points_on_cpu(drawing)) {
    splat_ = std::make_unique<SplatPicture>();
  } else {
    point_program_ = GlProgram("point", shaders::k_points_vert, shaders::k_points_frag);
    create_vertex_array(points_.vao, points_.vbo, sizeof(PointVertex),
                        {{2, GL_FLOAT, GL_FALSE, offsetof(PointVertex, x)},
                         {4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(PointVertex, colour)},
                         {1, GL_FLOAT, GL_FALSE, offsetof(PointVertex, half_clear)}});
  }
  create_vertex_array(lines_.vao, lines_.vbo, sizeof(LineVertex),
                      {{2, GL_FLOAT, GL_FALSE, offsetof(LineVertex, x)},
                       {1, GL_FLOAT, GL_FALSE, offsetof(LineVertex, edge_px)},
                       {4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(LineVertex, colour)}});
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

PolarRenderer::~PolarRenderer() {
  for (Buffer* b : {&points_, &lines_}) {
    glDeleteBuffers(1, &b->vbo);
    glDeleteVertexArrays(1, &b->vao);
  }
}

void PolarRenderer::upload(Buffer& buffer, const void* data, std::size_t bytes, std::size_t count) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.vbo);
  if (bytes > buffer.capacity_bytes) buffer.capacity_bytes = std::max(bytes, buffer.capacity_bytes * 2);
  // Orphan the old storage so the driver need not wait for the previous frame's draw.
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(buffer.capacity_bytes), nullptr, GL_STREAM_DRAW);
  if (bytes > 0) glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  buffer.count = count;
}

void PolarRenderer::upload_points(std::span<const PointVertex> points) {
  if (splat_) {
    cpu_points_.assign(points.begin(), points.end());
    points_.count = points.size();
    ++uploads_;
    return;
  }
  upload(points_, points.data(), points.size_bytes(), points.size());
}

void PolarRenderer::upload_grid(std::span<const LineVertex> lines) {
  upload(lines_, lines.data(), lines.size_bytes(), lines.size());
}

PixelBox PolarRenderer::viewport_of(const ViewTransform& view, float framebuffer_scale, int framebuffer_height) {
  const Vec2 origin = view.viewport_origin() * framebuffer_scale;
  const Vec2 size = view.viewport_size() * framebuffer_scale;
  const auto width = static_cast<int>(std::lround(size.x)), height = static_cast<int>(std::lround(size.y));
  return {static_cast<int>(std::lround(origin.x)),
          framebuffer_height - static_cast<int>(std::lround(origin.y)) - height, width, height};
}

SplatFrame PolarRenderer::splat_frame(const ViewTransform& view, const PolarStyle& style, float framebuffer_scale,
                                      const PixelBox& pixels) {
  const NdcTransform ndc = view.ndc_transform();
  return {ndc.scale_x,
          ndc.scale_y,
          ndc.offset_x,
          ndc.offset_y,
          pixels.width,
          pixels.height,
          style.point_size_px * framebuffer_scale};
}

bool PolarRenderer::lay_points_over(const BackdropPicture& backdrop, std::span<const PixelBox> boxes,
                                    const ViewTransform& view, const PolarStyle& style, float framebuffer_scale,
                                    int framebuffer_height) const {
  if (!splat_) return false;
  const PixelBox pixels = viewport_of(view, framebuffer_scale, framebuffer_height);
  std::vector<PixelBox> in_picture;
  for (const PixelBox& box : boxes) {
    if (box.empty()) continue;
    if (box.x < pixels.x || box.y < pixels.y || box.x + box.width > pixels.x + pixels.width ||
        box.y + box.height > pixels.y + pixels.height)
      return false;
    in_picture.push_back({box.x - pixels.x, box.y - pixels.y, box.width, box.height});
  }
  splat_->lay_over(backdrop, in_picture, cpu_points_, uploads_, splat_frame(view, style, framebuffer_scale, pixels),
                   pixels.x, pixels.y);
  return true;
}

void PolarRenderer::draw(const ViewTransform& view, const PolarStyle& style, float framebuffer_scale,
                         int framebuffer_height, GlLayer layer) const {
  const PixelBox pixels = viewport_of(view, framebuffer_scale, framebuffer_height);
  const GLint x = pixels.x, y = pixels.y;
  const GLsizei w = pixels.width, h = pixels.height;
  glViewport(x, y, w, h);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_DEPTH_TEST);
  // The scissor is the caller's: a frame drawn in parts keeps the layer to the part being drawn.
  const NdcTransform ndc = view.ndc_transform();

  if (layer == GlLayer::grid && style.show_grid && lines_.count > 0) {
    line_program_.use();
    glUniform4f(line_program_.uniform("u_ndc"), ndc.scale_x, ndc.scale_y, ndc.offset_x, ndc.offset_y);
    glUniform1f(line_program_.uniform("u_half_width_px"),
                0.5f * style.grid.line_width_px);  // edge_px is in window pixels too
    glBindVertexArray(lines_.vao);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(lines_.count));
  }

  if (layer == GlLayer::points && splat_) {
    splat_->draw(cpu_points_, uploads_, splat_frame(view, style, framebuffer_scale, pixels), x, y);
  } else if (layer == GlLayer::points && points_.count > 0) {
    // The viewport grows by a sprite's reach on each side, and the transform shrinks to match.
    const auto margin = static_cast<GLint>(std::ceil(sprite_reach_px(style.point_size_px) * framebuffer_scale)) + 1;
    glViewport(x - margin, y - margin, w + 2 * margin, h + 2 * margin);
    const float kx = static_cast<float>(w) / static_cast<float>(w + 2 * margin);
    const float ky = static_cast<float>(h) / static_cast<float>(h + 2 * margin);
    glEnable(GL_PROGRAM_POINT_SIZE);
    point_program_.use();
    glUniform4f(point_program_.uniform("u_ndc"), ndc.scale_x * kx, ndc.scale_y * ky, ndc.offset_x * kx,
                ndc.offset_y * ky);
    glUniform1f(point_program_.uniform("u_point_size"), style.point_size_px * framebuffer_scale);
    glBindVertexArray(points_.vao);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(points_.count));
  }
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace ydscope::ui
