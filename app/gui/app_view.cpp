// App, the view of a frame: one lidar drawn around itself as always, or several in the common
// frame (source_cloud), with the mouse on it (pan, zoom, sectors, and posing the selected source).
#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/gui/app.h"
#include "ui/panels/panels.h"

namespace ydscope::gui {

void App::lay_out_common_view(float left, float width, float height) {
  view_->set_viewport({left, 0.0f}, {width, height});
  view_->set_status_band(ui::status_band_height());
  view_->enable_pose_drag(sources_.size() > 1);
  view_->handle_input(settings_, glfwGetWindowAttrib(window_, GLFW_HOVERED) == GLFW_TRUE,
                      seconds_since_start(last_frame_));
  if (const auto drag = view_->take_pose_drag()) {  // Alt/Ctrl+drag: the selected source's pose
    ui::SourceLook look = sel().look;
    look.pose = ui::dragged_pose(look.pose, *drag);
    look.paused = model().paused_view;
    model().requests.push_back(ui::SetSourceLook{selected_, look});
  }
  if (const auto swept = view_->take_swept_sector()) {  // Shift+drag on the view
    char spec[48];
    std::snprintf(spec, sizeof spec, "%.0f:%.0f", static_cast<double>(swept->first),
                  static_cast<double>(swept->second));
    model().requests.push_back(ui::WatchSector{spec});
  }
  // One lidar is drawn as always; several (or one in its source colour) go through the layers.
  const bool several = sources_.size() > 1;
  const bool layered = several || settings_.colours.mode == ui::ColourMode::Source;
  const auto layers = layered ? source_layers() : std::span<const ui::SourceLayer>();
  view_->set_source_marks(marks_);
  if (layered)
    view_->auto_range_to(ui::robust_extent_mm(layers, 0.93f) * 1.1f, settings_);
  else
    view_->auto_range(history(), settings_);
  model().cloud = layered ? view_->update_cloud(layers, settings_, shown_phase_)
                          : view_->update_cloud(history(), settings_, &sel().motion, shown_phase_);
  model().laps_on_screen = history().size();
  model().points_drawn_total = view_->vertex_count();

  // The hover box reads one lidar's own frame, which several do not share.
  static const ui::LapHistory no_laps;
  view_->lay_out(several ? no_laps : history(), settings_);
  // Each source's state in its own line; the booth view's large legend says it there instead.
  if (several && !(booth_.on() && settings_.colours.mode == ui::ColourMode::Source))
    ui::draw_source_legend(model(), left, width);
  else
    ui::draw_view_overlay(model(), left, width, height);
}

std::uint64_t App::gl_generation() const {
  if (!split_active()) return view_->gl_generation();
  std::uint64_t generation = tiles_.size();
  for (const auto& tile : tiles_) generation = generation * 1'000'003u + tile->gl_generation();
  return generation;
}

}  // namespace ydscope::gui
