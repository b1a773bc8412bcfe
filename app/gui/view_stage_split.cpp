// ViewStage, the split view: two to four sources side by side, each drawn around itself in a view
// of its own (zoom, pan, hover and its own "No data" overlay), for comparing units; View > split.
#include <algorithm>

#include <imgui.h>

#include "app/gui/view_stage.h"
#include "ui/panels/panels.h"

namespace ydscope::gui {

void ViewStage::lay_out_split(SourceList& sources, ui::ViewSettings& settings, const ViewFrame& frame) {
  // The first four shown sources: two side by side, three or four in a 2 x 2 grid.
  std::vector<SourceSlot*> shown;
  for (const auto& slot : sources.slots())
    if (!slot->look.hidden && shown.size() < 4) shown.push_back(slot.get());
  while (tiles_.size() < shown.size()) tiles_.push_back(std::make_unique<ui::PolarView>(interactive_));
  tiles_.resize(shown.size());
  const std::size_t columns = shown.size() <= 2 ? shown.size() : 2;
  const std::size_t rows = shown.size() <= 2 ? 1 : 2;
  const float tile_w = frame.width / static_cast<float>(std::max<std::size_t>(columns, 1));
  const float tile_h = frame.height / static_cast<float>(rows);
  const auto now = std::chrono::steady_clock::now();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  std::size_t points = 0;
  for (std::size_t i = 0; i < shown.size(); ++i) {
    SourceSlot& slot = *shown[i];
    ui::PolarView& tile = *tiles_[i];
    const float x = frame.left + tile_w * static_cast<float>(i % columns);
    const float y = tile_h * static_cast<float>(i / columns);
    tile.set_viewport({x, y}, {tile_w, tile_h});
    tile.set_status_band(i / columns == rows - 1 ? ui::status_band_height() : 0.0f);
    tile.handle_input(settings, frame.hovered, frame.now_s);
    // Its own frame, in its own colour when the view colours by source.
    const ui::SourceLayer layer{&slot.history, Pose{}, slot.look.colour, false, &slot.motion};
    tile.auto_range(std::span(&layer, 1), settings);
    tile.update_cloud(std::span(&layer, 1), settings, frame.phase);
    points += tile.points_shown();
    tile.lay_out(slot.history, settings);
    ui::draw_view_overlay(slot.model, x, tile_w, tile_h, y);
    ui::draw_source_label(source_row(slot, now), {x, y}, &slot == &sources.selected());
    if (i % columns > 0) draw->AddLine({x, y}, {x, y + tile_h}, IM_COL32(90, 100, 120, 255), 2.0f);
    if (i / columns > 0) draw->AddLine({x, y}, {x + tile_w, y}, IM_COL32(90, 100, 120, 255), 2.0f);
  }
  ui::UiModel& model = sources.selected().model;
  model.laps_on_screen = sources.selected().history.size();
  model.points_drawn_total = points;
}

}  // namespace ydscope::gui
