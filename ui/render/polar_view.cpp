#include "ui/render/polar_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include <imgui.h>

#include "ui/render/polar_overlay.h"
#include "ui/view/geometry/grid_layout.h"

namespace ydscope::ui {
namespace {

// Small enough that a wall's tiles leave most of the view out, large enough that a cover is a
// few boxes (covering_boxes makes them larger where it is not).
constexpr float kCoverTilePx = 16.0f;

}  // namespace

void PolarView::set_viewport(Vec2 origin, Vec2 size) {
  const Vec2 old_size = view_.viewport_size();
  view_.set_viewport(origin, size);
  if (std::fabs(old_size.x - size.x) > 0.5f || std::fabs(old_size.y - size.y) > 0.5f) {
    fit_.forget();  // refit on resize when auto-range is on
  }
}

void PolarView::reset(ViewSettings& settings) {
  settings.auto_range = true;
  fit_.forget();
  view_.fit_range(fit_.fitted_mm() > 0.0f ? fit_.fitted_mm() : 8000.0f);
}

void PolarView::handle_input(ViewSettings& settings, bool pointer_in_window, double now_s) {
  const ImGuiIO& io = ImGui::GetIO();
  const Vec2 mouse{io.MousePos.x, io.MousePos.y};
  const bool inside = pointer_in_window && view_.contains_screen(mouse) && !io.WantCaptureMouse;
  hover_gate_.update(inside, io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f, now_s);
  hover_cursor_.reset();
  cursor_world_.reset();
  if (!inside) {
    if (sweep_from_deg_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) sweep_from_deg_.reset();  // let go outside
    return;
  }
  if (hover_gate_.visible()) hover_cursor_ = mouse;
  cursor_world_ = view_.screen_to_world(mouse);
  if (io.MouseWheel != 0.0f) {
    view_.zoom_about(mouse, std::pow(1.15f, io.MouseWheel));
    settings.auto_range = false;
  }
  const float angle = world_angle_deg(*cursor_world_);
  if (forward_click_armed_ && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    forward_click_ = *cursor_world_;
    forward_click_armed_ = false;
    return;
  }
  if (io.KeyShift && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    sweep_from_deg_ = sweep_last_deg_ = angle;
    sweep_turned_deg_ = 0.0f;
  }
  if (sweep_from_deg_) {
    // Wrapped step since the last frame: the sweep follows the cursor round, either way.
    float step = angle - sweep_last_deg_;
    if (step > 180.0f) step -= 360.0f;
    if (step < -180.0f) step += 360.0f;
    sweep_turned_deg_ = std::clamp(sweep_turned_deg_ + step, -359.0f, 359.0f);
    sweep_last_deg_ = angle;
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
      if (const auto shape = sweep_shape(); shape && shape->width_deg >= 1.0f)
        swept_ = {shape->from_deg, std::fmod(shape->from_deg + shape->width_deg, 360.0f)};
      sweep_from_deg_.reset();
    }
  } else if (pose_drag_enabled_ && (io.KeyAlt || io.KeyCtrl) && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2.0f)) {
    // The selected source's cloud follows the pointer (Alt) or turns with it (Ctrl).
    const Vec2 before = view_.screen_to_world(mouse - Vec2{io.MouseDelta.x, io.MouseDelta.y});
    pose_drag_ = PoseDrag{pose_drag_ ? pose_drag_->from_world : before, *cursor_world_, io.KeyCtrl};
    settings.auto_range = false;  // a view that refits mid-drag would pull the cloud from under the pointer
  } else if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    reset(settings);
  } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2.0f)) {
    view_.pan_by_pixels({io.MouseDelta.x, io.MouseDelta.y});
    settings.auto_range = false;
  }
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) ruler_.click(*cursor_world_);
}

std::optional<SectorShape> PolarView::sweep_shape() const {
  if (!sweep_from_deg_) return std::nullopt;
  SectorShape shape;
  shape.from_deg =
      sweep_turned_deg_ >= 0.0f ? *sweep_from_deg_ : std::fmod(*sweep_from_deg_ + sweep_turned_deg_ + 360.0f, 360.0f);
  shape.width_deg = std::fabs(sweep_turned_deg_);
  char label[32];
  std::snprintf(label, sizeof label, "%.0f\xC2\xB0", static_cast<double>(shape.width_deg));
  shape.label = label;
  return shape;
}

std::optional<PoseDrag> PolarView::take_pose_drag() {
  auto drag = pose_drag_;
  pose_drag_.reset();
  return drag;
}

std::optional<Vec2> PolarView::take_forward_click() {
  auto clicked = forward_click_;
  forward_click_.reset();
  return clicked;
}

std::optional<std::pair<float, float>> PolarView::take_swept_sector() {
  auto swept = swept_;
  swept_.reset();
  return swept;
}

bool PolarView::layers_changed(std::span<const SourceLayer> layers, std::vector<SourceLayerKey>& last) {
  layer_keys_.clear();
  for (const SourceLayer& layer : layers) layer_keys_.emplace_back(layer);
  if (layer_keys_ == last) return false;
  last.swap(layer_keys_);
  return true;
}

void PolarView::auto_range(std::span<const SourceLayer> layers, const ViewSettings& settings) {
  // A partial sort of the newest lap's ranges: once a lap, not at every frame.
  if (layers_changed(layers, extent_from_)) extent_mm_ = robust_extent_mm(layers, 0.93f) * 1.1f;
  auto_range_to(extent_mm_, settings);
}

void PolarView::auto_range_to(float extent_mm, const ViewSettings& settings) {
  // Asked every frame, lap or not, so turning auto-range back on is seen the frame it happens.
  if (const auto range = fit_.update(settings.auto_range, extent_mm)) view_.fit_range(*range);
}

ColourParams PolarView::colours_for(const ViewSettings& settings, float phase, bool several_laps) {
  // With auto-range the range palette spans what is shown, so a 30 m TG scan and a 3 m room both
  // use all of it; a manual view keeps the panel's near/far.
  ColourParams colours = settings.colours;
  if (settings.auto_range && fit_.fitted_mm() > 0.0f) {
    colours.near_mm = 0.0f;
    colours.far_mm = fit_.fitted_mm();
  }
  if (!(colours == last_colours_) || !(settings.interference == last_settings_.interference)) shape_dirty_ = true;
  if (phase != last_phase_ && several_laps) dirty_ = true;  // one lap alone does not fade
  last_settings_ = settings;
  last_colours_ = colours;
  return colours;
}

void PolarView::upload_if_dirty(float phase) {
  renderer_.upload_points(vertices_);
  ++gl_generation_;
  dirty_ = false;
  last_phase_ = phase;
}

const PointCloudStats& PolarView::update_cloud(std::span<const SourceLayer> layers, const ViewSettings& settings,
                                               float phase) {
  const bool several_laps = std::any_of(layers.begin(), layers.end(),
                                        [](const SourceLayer& l) { return l.history && l.history->size() > 1; });
  const ColourParams colours = colours_for(settings, phase, several_laps);
  // Points are merged per pixel, so a zoom changes what is drawn; those outside the view are left
  // out, so a pan does too.
  if (!(merged_for_ == view_)) dirty_ = true;
  // New laps, a source moved, recoloured or dimmed: those layers are built again.
  if (clouds_.update(layers, colours, settings.interference, shape_dirty_)) {
    stats_ = clouds_.stats();
    points_shown_ = clouds_.cloud().vertices.size();
    dirty_ = true;
    ++sprites_moved_;
  }
  shape_dirty_ = false;
  if (dirty_) {
    fade_cloud(clouds_.cloud(), colours, phase);
    // The merge replaces what it is given; the cloud is kept for the next fade.
    copy_seen(clouds_.cloud().vertices, settings.point_size_px);
    if (!merged_for_ || merged_for_->px_per_mm() != view_.px_per_mm()) ++sprites_moved_;
    merger_.merge(vertices_, 1.0f / view_.px_per_mm());
    merged_for_ = view_;
    upload_if_dirty(phase);
  }
  return stats_;
}

void PolarView::copy_seen(const std::vector<PointVertex>& cloud, float point_size_px) {
  // In world millimetres, so a point is one comparison away from being left out.
  const float reach_mm = PolarRenderer::sprite_reach_px(point_size_px) / view_.px_per_mm();
  const Vec2 origin = view_.viewport_origin(), size = view_.viewport_size();
  const Vec2 corner = view_.screen_to_world(origin), far_corner = view_.screen_to_world(origin + size);
  const float left = std::min(corner.x, far_corner.x) - reach_mm, right = std::max(corner.x, far_corner.x) + reach_mm;
  const float bottom = std::min(corner.y, far_corner.y) - reach_mm, top = std::max(corner.y, far_corner.y) + reach_mm;
  vertices_.clear();
  std::copy_if(cloud.begin(), cloud.end(), std::back_inserter(vertices_),
               [&](const PointVertex& v) { return v.x >= left && v.x <= right && v.y >= bottom && v.y <= top; });
}

const TileCover& PolarView::sprite_cover(float point_size_px) {
  const CoverKey key{sprites_moved_, view_, point_size_px};
  if (key == cover_key_) return cover_;
  cover_key_ = key;
  const Vec2 origin = view_.viewport_origin(), size = view_.viewport_size();
  cover_ = TileCover({origin.x, origin.y, origin.x + size.x, origin.y + size.y}, kCoverTilePx);
  // And half a pixel for where GL rounds a sprite's centre.
  const float reach = PolarRenderer::sprite_reach_px(point_size_px) + 0.5f;
  for (const PointVertex& v : vertices_) {
    const Vec2 at = view_.world_to_screen({v.x, v.y});
    cover_.mark({at.x - reach, at.y - reach, at.x + reach, at.y + reach});
  }
  return cover_;
}

void PolarView::lay_out(const LapHistory& history, const ViewSettings& settings) {
  if (const GridKey key{view_, status_band_px_}; !(key == grid_key_)) {
    grid_key_ = key;
    grid_ = layout_grid(view_, ring_spacing_px(view_.viewport_size()), 30.0f, 225.0f, 18.0f, status_band_px_);
    build_grid_geometry(view_, grid_, PolarStyle{}.grid, grid_lines_);
    renderer_.upload_grid(grid_lines_);
    ++gl_generation_;
    ++grid_generation_;
  }
  const GridLayout& grid = grid_;

  OverlayInput overlay;
  overlay.view = &view_;
  overlay.grid = &grid;
  overlay.show_grid_labels = settings.show_grid;
  overlay.ruler = &ruler_;
  overlay.ruler_cursor_world = cursor_world_;
  overlay.sectors = sectors_;
  overlay.sweep = sweep_shape();
  overlay.marks = marks_;
  overlay.dropouts = dropouts_;
  overlay.zones = zones_;
  if (hover_cursor_ && !history.empty())
    overlay.hover = nearest_point(history.newest().points, view_, *hover_cursor_, 12.0f);
  draw_polar_overlay(ImGui::GetBackgroundDrawList(), overlay);
}

PolarStyle PolarView::style_of(const ViewSettings& settings) {
  PolarStyle style;
  style.point_size_px = settings.point_size_px;
  style.show_grid = settings.show_grid;
  return style;
}

void PolarView::draw_gl(const ViewSettings& settings, float framebuffer_scale, int framebuffer_height,
                        GlLayer layer) const {
  renderer_.draw(view_, style_of(settings), framebuffer_scale, framebuffer_height, layer);
}

bool PolarView::lay_gl_over(const BackdropPicture& backdrop, std::span<const PixelBox> boxes,
                            const ViewSettings& settings, float framebuffer_scale, int framebuffer_height) const {
  return renderer_.lay_points_over(backdrop, boxes, view_, style_of(settings), framebuffer_scale, framebuffer_height);
}

}  // namespace ydscope::ui
