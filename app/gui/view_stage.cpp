#include "app/gui/view_stage.h"

#include <array>
#include <cmath>
#include <cstdio>

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include "ui/panels/panels.h"
#include "ui/render/imgui_within.h"
#include "ui/render/gl.h"
#include "ui/render/theme.h"
#include "ui/view/geometry/forward_click.h"
#include "ui/view/geometry/view_frame.h"
#include "ui/view/scene/booth_framing.h"

namespace ydscope::gui {

void ViewStage::lay_out(SourceList& sources, ui::ViewSettings& settings, const ViewFrame& frame) {
  split_ = settings.split_view && sources.several();
  sidebar_px_ = frame.left;
  if (split_)
    lay_out_split(sources, settings, frame);
  else
    lay_out_common(sources, settings, frame);
}

void ViewStage::lay_out_common(SourceList& sources, ui::ViewSettings& settings, const ViewFrame& frame) {
  SourceSlot& selected = sources.selected();
  ui::UiModel& model = selected.model;
  view_->set_viewport({frame.left, 0.0f}, {frame.width, frame.height});
  view_->set_status_band(ui::status_band_height());
  view_->enable_pose_drag(sources.several());
  view_->arm_forward_click(selected.edits.forward_click_armed);
  view_->handle_input(settings, frame.hovered, frame.now_s);
  if (const auto clicked = view_->take_forward_click()) {  // the Sources tab's "straight ahead" tool
    selected.edits.forward_click_armed = false;
    // Several are drawn where their poses put them; a lone lidar round itself, in its laser frame.
    const CommonPoint at = ui::common_of(*clicked);
    ui::SourceLook look = selected.look;
    if (const auto facing = ui::facing_forward(look.pose, sources.several() ? look.pose.to_laser(at) : at)) {
      look.pose = *facing;
      look.paused = model.paused_view;
      model.requests.push_back(ui::SetSourceLook{sources.selected_index(), look});
    }
  }
  if (const auto drag = view_->take_pose_drag()) {  // Alt/Ctrl+drag: the selected source's pose
    ui::SourceLook look = selected.look;
    look.pose = ui::dragged_pose(look.pose, *drag);
    look.paused = model.paused_view;
    model.requests.push_back(ui::SetSourceLook{sources.selected_index(), look});
  }
  if (const auto swept = view_->take_swept_sector()) {  // Shift+drag on the view
    char spec[48];
    std::snprintf(spec, sizeof spec, "%.0f:%.0f", static_cast<double>(swept->first),
                  static_cast<double>(swept->second));
    model.requests.push_back(ui::WatchSector{spec});
  }
  // One lidar is a layer at the identity pose, drawn round itself; several each at its pose.
  const bool several = sources.several();
  const auto layers = layers_of(sources);
  view_->set_source_marks(marks_);
  if (!model.zones.zones().empty())
    view_->set_zones(ui::ZoneShapes{several ? selected.look.pose : Pose{}, model.zones.zones(), model.zones.states()});
  else
    view_->set_zones(std::nullopt);
  view_->set_dropout_ring(ui::DropoutRingShape{several ? selected.look.pose : Pose{}, model.dropouts.no_return_share(),
                                               model.dropouts.blocked()});
  // The booth frames a lone lidar's room by what it has learned of it (booth_framing.h).
  const float framed =
      frame.booth && !several ? ui::booth_frame_range_mm(selected.motion, view_->transform().viewport_size()) : 0.0f;
  if (framed > 0.0f)
    view_->auto_range_to(framed, settings);
  else
    view_->auto_range(layers, settings);
  model.cloud = view_->update_cloud(layers, settings, frame.phase);
  model.laps_on_screen = selected.history.size();
  model.points_drawn_total = view_->points_shown();

  // The hover box reads one lidar's own frame, which several do not share.
  static const ui::LapHistory no_laps;
  view_->lay_out(several ? no_laps : selected.history, settings);
  // Each source's state in its own line; the booth view's large legend says it there instead.
  if (several && !frame.legend_in_booth)
    ui::draw_source_legend(model, frame.left, frame.width);
  else
    ui::draw_view_overlay(model, frame.left, frame.width, frame.height);
}

std::span<const ui::SourceLayer> ViewStage::layers_of(const SourceList& sources) {
  const bool several = sources.several();
  layers_.clear();
  marks_.clear();
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const SourceSlot& slot = sources[i];
    if (slot.look.hidden) continue;
    ui::SourceLayer layer;
    layer.history = &slot.history;
    layer.pose = several ? slot.look.pose : Pose{};  // a lone lidar is drawn around itself
    layer.colour = slot.look.colour;
    layer.dim = several && slot.model.view_state.dim;  // a lone one says so over the whole view
    layer.motion = &slot.motion;
    layers_.push_back(layer);
    if (several) marks_.push_back({slot.look.pose, slot.look.colour, i == sources.selected_index()});
  }
  return layers_;
}

std::uint64_t ViewStage::gl_generation() const {
  if (!split_) return view_->gl_generation();
  std::uint64_t generation = tiles_.size();
  for (const auto& tile : tiles_) generation = generation * 1'000'003u + tile->gl_generation();
  return generation;
}

bool ViewStage::DrawnGl::points_only_changed_to(const DrawnGl& now) const {
  return !split && !now.split && grid_generation == now.grid_generation && grid == now.grid &&
         point_size_px == now.point_size_px;
}

std::vector<ui::DisplayBox> ViewStage::points_changed_in(const ui::DisplayBox& view, float point_size_px) {
  // Past this many boxes the tiles are made coarser: each box is a clear and a scissor for every
  // ImGui command reaching it, and the grid's picture is laid in all of them in one pass.
  constexpr std::size_t kMaxBoxes = 32;
  ui::TileCover both = view_->sprite_cover(point_size_px);
  if (!both.unite(drawn_cover_)) return {view};
  std::vector<ui::DisplayBox> boxes = ui::covering_boxes(both, kMaxBoxes);
  for (ui::DisplayBox& box : boxes) box = box.intersected(view);
  return boxes;
}

ui::DrawnFrame ViewStage::render_if_changed(const ui::ViewSettings& settings, float fb_scale, int fb_w, int fb_h,
                                            bool must_draw, bool partial) {
  ImDrawData& data = *ImGui::GetDrawData();
  const std::optional<std::vector<ui::DisplayBox>> imgui_changed = damage_.update(data);
  const DrawnLayout layout{fb_w, fb_h, fb_scale, sidebar_px_};
  const DrawnGl gl{gl_generation(), view_->grid_generation(), split_, settings.show_grid, settings.point_size_px};
  const bool relaid = !(layout == drawn_layout_);
  const bool gl_changed = !(gl == drawn_gl_);
  const bool points_only = gl_changed && drawn_gl_.points_only_changed_to(gl);
  drawn_layout_ = layout;
  drawn_gl_ = gl;
  const ui::DisplayBox window{0.0f, 0.0f, static_cast<float>(fb_w) / fb_scale, static_cast<float>(fb_h) / fb_scale};
  const ui::DisplayBox view{std::floor(sidebar_px_), 0.0f, window.x1, window.y1};
  // Where the view changed: where its points were and are when only they changed (their fade, a
  // lap), else all of it. Either holds every point drawn now or last time.
  std::vector<ui::DisplayBox> view_changed;
  if (points_only)
    view_changed = points_changed_in(view, settings.point_size_px);
  else if (gl_changed)
    view_changed.push_back(view);
  // The split view's tiles are drawn whole; the common view's cover is what the next frame joins.
  drawn_cover_ = split_ ? ui::TileCover{} : view_->sprite_cover(settings.point_size_px);
  // The whole window when it cannot be drawn in parts: a swap, a new layout, a frame that cannot
  // be compared with the last, a scale whose pixels the backend's scissors would round past.
  std::vector<ui::DisplayBox> boxes;
  if (must_draw || relaid || !imgui_changed || !partial || fb_scale != 1.0f) {
    if (must_draw || relaid || !imgui_changed || gl_changed || !imgui_changed->empty()) boxes.push_back(window);
  } else {
    boxes = std::move(view_changed);
    for (const ui::DisplayBox& box : *imgui_changed) boxes.push_back(box.intersected(window));
    boxes = ui::merged_boxes(std::move(boxes));
    float area = 0.0f;
    for (const ui::DisplayBox& box : boxes) area += box.area();
    // Several passes each take every vertex of ImGui's draw data through the pipeline; when they
    // would clear nearly all of the window anyway, one pass of all of it is no dearer.
    if (area > 0.9f * window.area()) boxes.assign(1, window);
  }
  ui::DrawnFrame drawn;
  drawn.whole = boxes.size() == 1 && boxes.front() == window;
  BoxPlan plan;
  plan.points_once = drawn.whole || gl_changed;
  // The grid's picture is drawn again only for a frame of points; a zoom draws its grid whole.
  plan.backdrop =
      !drawn.whole && !split_ && (points_only || backdrop_holds_ == backdrop_key(settings, view, fb_w, fb_h));
  std::vector<ui::PixelBox> pixels = draw_boxes(boxes, view, plan, settings, fb_scale, fb_w, fb_h);
  if (!drawn.whole) drawn.boxes = std::move(pixels);
  return drawn;
}

ViewStage::BackdropKey ViewStage::backdrop_key(const ui::ViewSettings& settings, const ui::DisplayBox& view, int fb_w,
                                               int fb_h) const {
  return {view_->grid_generation(), settings.show_grid, fb_w, fb_h, view};
}

std::vector<ui::PixelBox> ViewStage::draw_boxes(std::span<const ui::DisplayBox> boxes, const ui::DisplayBox& view,
                                                const BoxPlan& plan, const ui::ViewSettings& settings, float fb_scale,
                                                int fb_w, int fb_h) {
  const auto scissor = [](const ui::PixelBox& p) { glScissor(p.x, p.y, p.width, p.height); };
  const auto draw_gl = [&](ui::GlLayer layer) {
    if (split_) {
      for (const auto& tile : tiles_) tile->draw_gl(settings, fb_scale, fb_h, layer);
    } else {
      view_->draw_gl(settings, fb_scale, fb_h, layer);
    }
  };
  const auto clear = [&](const ui::PixelBox& p, const std::array<float, 4>& colour) {
    scissor(p);
    glClearColor(colour[0], colour[1], colour[2], colour[3]);
    glClear(GL_COLOR_BUFFER_BIT);
  };
  const std::array<float, 4> background{ui::kBackground[0], ui::kBackground[1], ui::kBackground[2], ui::kBackground[3]};
  if (plan.backdrop) {
    if (!backdrop_) backdrop_ = std::make_unique<ui::BackdropPicture>();
    if (const BackdropKey key = backdrop_key(settings, view, fb_w, fb_h); !(backdrop_holds_ == key)) {
      backdrop_->begin(fb_w, fb_h);
      glEnable(GL_SCISSOR_TEST);
      clear(ui::to_pixels(view, fb_scale, fb_h), background);
      draw_gl(ui::GlLayer::grid);
      glDisable(GL_SCISSOR_TEST);
      backdrop_->end();
      backdrop_holds_ = key;
    }
  }
  std::vector<ui::PixelBox> pixels, in_view;
  for (const ui::DisplayBox& box : boxes) {
    pixels.push_back(ui::to_pixels(box, fb_scale, fb_h));
    in_view.push_back(ui::to_pixels(box.intersected(view), fb_scale, fb_h));
  }
  glEnable(GL_SCISSOR_TEST);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    // The view's part of a box is the backdrop's, when it is laid.
    if (!plan.backdrop || !(pixels[i] == in_view[i])) clear(pixels[i], background);
    // The sidebar's background, cleared rather than blended by ImGui: far cheaper in software.
    if (const ui::PixelBox sidebar =
            ui::to_pixels(boxes[i].intersected({0.0f, 0.0f, view.x0, view.y1}), fb_scale, fb_h);
        !sidebar.empty())
      clear(sidebar, ui::sidebar_background());
  }
  // The GL layer stays in the view: a point at its edge does not spill onto the panels.
  bool points_drawn = false;
  if (plan.backdrop) {
    // Sprites drawn on the CPU come painted over the backdrop: one pass lays both.
    points_drawn = view_->lay_gl_over(*backdrop_, in_view, settings, fb_scale, fb_h);
    if (!points_drawn) backdrop_->lay(in_view);
    glEnable(GL_SCISSOR_TEST);
  } else {
    for (const ui::PixelBox& part : in_view)
      if (!part.empty()) {
        scissor(part);
        draw_gl(ui::GlLayer::grid);
      }
  }
  if (points_drawn) {
    // laid with the backdrop
  } else if (plan.points_once && !boxes.empty()) {
    // Every point lies in the boxes, so one pass over the view draws each box's and nothing
    // else: the points go through the pipeline once, not once a box.
    scissor(ui::to_pixels(view, fb_scale, fb_h));
    draw_gl(ui::GlLayer::points);
  } else {
    for (const ui::PixelBox& part : in_view)
      if (!part.empty()) {
        scissor(part);
        draw_gl(ui::GlLayer::points);
      }
  }
  glDisable(GL_SCISSOR_TEST);
  ui::render_imgui_within(*ImGui::GetDrawData(), boxes);
  return pixels;
}

}  // namespace ydscope::gui
