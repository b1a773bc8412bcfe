// App, the source list: several lidars at once, each with its own session, panels and look, one
// selected for the panels; started from the command line, added, removed and posed while running,
// and drawn together in the common frame.
#include <algorithm>
#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/gui/app.h"
#include "ui/panels/panels.h"
#include "ui/view/remembered_sources.h"

namespace ydscope::gui {

SourceSlot& App::add_slot(ui::SourceLook look) {
  std::vector<std::string> names;
  std::vector<ui::Rgba8> colours;
  for (const auto& slot : sources_) {
    names.push_back(slot->look.name);
    colours.push_back(slot->look.colour);
  }
  look.name = ui::unique_source_name(look.name, names);
  if (look.colour == ui::Rgba8{}) look.colour = ui::unused_source_colour(colours);
  auto slot = std::make_unique<SourceSlot>(std::move(look), [] { glfwPostEmptyEvent(); });
  slot->history.set_depth(static_cast<std::size_t>(settings_.persistence_laps));
  sources_.push_back(std::move(slot));
  return *sources_.back();
}

std::vector<ui::SourceLook> App::looks() const {
  std::vector<ui::SourceLook> looks;
  for (const auto& slot : sources_) looks.push_back(slot->look);
  return looks;
}

ui::ConnectRequest App::connect_request_for(const SourceChoice& choice) const {
  ui::ConnectRequest request;
  request.kind = choice.kind == SourceKind::Sim ? ui::ConnectRequest::Kind::Sim : ui::ConnectRequest::Kind::Port;
  request.address = choice.port;
  request.model = choice.model;
  request.baud = choice.baud;
  request.scene = choice.scene.empty() ? options_.scene : choice.scene;
  return request;
}

std::string App::start_several() {
  const std::vector<Pose> spread = ui::spread_poses(options_.sources.size());
  // Several lidars are told apart by colour first; by-range stays one click away. (One port
  // given a --name or --pose is still one lidar, drawn as always.)
  if (options_.sources.size() > 1) settings_.colours.mode = ui::ColourMode::Source;
  std::string first_error;
  for (std::size_t i = 0; i < options_.sources.size(); ++i) {
    const SourceChoice& choice = options_.sources[i];
    ui::SourceLook look;
    look.name = choice.name.empty() ? choice.model.value_or("lidar") : choice.name;
    look.pose = choice.pose.value_or(spread[i]);
    ui::recall_look(settings_, looks(), look, choice.pose.has_value());
    if (i == 0) {
      look.colour = look.colour == ui::Rgba8{} ? sel().look.colour : look.colour;
      sel().look = look;
    } else {
      add_slot(std::move(look));
    }
    selected_ = i;  // start() fills the selected source's panels
    const std::string error = start(connect_request_for(choice));
    if (!error.empty()) {
      std::fprintf(stderr, "ydscope: %s: %s\n", sel().look.name.c_str(), error.c_str());
      if (first_error.empty()) first_error = sel().look.name + ": " + error;
    }
  }
  selected_ = 0;
  sync_sectors();  // several: the first source's sectors are no longer outlined round the origin
  return first_error;
}

void App::select_source(std::size_t index) {
  if (index >= sources_.size() || index == selected_) return;
  // Share and recordings follow one session; they end rather than silently follow another.
  if (model().recording()) outputs_.stop_recording(sel(), " (another source was selected)");
  if (outputs_.sharing()) outputs_.stop_share(sel());
  selected_ = index;
  shown_banner_ = model().banner;
  sync_sectors();
  view_->invalidate();
}

void App::change_sources(const ui::SelectSource& request) { select_source(request.index); }

void App::change_sources(const ui::SetSourceLook& request) {
  if (request.index >= sources_.size()) return;
  SourceSlot& slot = *sources_[request.index];
  slot.look = request.look;
  slot.model.paused_view = request.look.paused;
  view_->invalidate();
}

void App::change_sources(const ui::AddSource& request) {
  ui::SourceLook look;
  look.name = request.name.empty() ? request.request.model.value_or("lidar") : request.name;
  // Beside the others, not on top of them.
  std::vector<Pose> taken;
  for (const auto& slot : sources_) taken.push_back(slot->look.pose);
  look.pose = ui::free_spread_pose(taken);
  ui::recall_look(settings_, looks(), look, false);
  add_slot(std::move(look));
  const std::size_t previous = selected_;
  selected_ = sources_.size() - 1;
  const std::string error = start(request.request);
  selected_ = previous;
  if (!error.empty()) model().status_message = sources_.back()->look.name + ": " + error;
  select_source(sources_.size() - 1);
  if (settings_.colours.mode != ui::ColourMode::Source && sources_.size() == 2)
    settings_.colours.mode = ui::ColourMode::Source;
}

void App::change_sources(const ui::RemoveSource& request) {
  if (request.index >= sources_.size() || sources_.size() < 2) return;  // the list is never empty
  if (request.index == selected_) select_source(request.index == 0 ? 1 : 0);
  sources_[request.index]->source.stop();
  sources_.erase(sources_.begin() + static_cast<std::ptrdiff_t>(request.index));
  if (selected_ > request.index) --selected_;
  sync_sectors();  // back to one lidar: its sectors are outlined again
  view_->invalidate();
}

void App::fill_source_rows() {
  const auto now = std::chrono::steady_clock::now();
  std::vector<ui::SourceRow> rows;
  rows.reserve(sources_.size());
  for (const auto& slot : sources_) {
    ui::SourceRow row;
    row.look = slot->look;
    row.look.paused = slot->model.paused_view;  // P freezes the selected source as the checkbox does
    row.dim = slot->model.view_state.dim;
    row.legend = ui::source_legend_line(slot->look.name, slot->model.view_state, slot->seconds_since_lap(now));
    rows.push_back(std::move(row));
  }
  model().sources = std::move(rows);
  model().selected_source = selected_;
}

std::vector<std::string> App::summary() const {
  std::vector<std::string> lines;
  if (sources_.size() < 2) return lines;  // one source's run says what it always said
  for (const auto& slot : sources_) {
    const SessionSnapshot s = slot->session.snapshot();
    std::uint64_t lost = 0;  // laps one of the app's rings could not take
    for (const LapConsumerStats& consumer : s.consumers) lost += consumer.dropped;
    char line[256];
    std::snprintf(line, sizeof line, "%s: %llu laps from the device, %llu drawn, %llu lost", slot->look.name.c_str(),
                  static_cast<unsigned long long>(s.counters.laps),
                  static_cast<unsigned long long>(slot->model.laps_shown), static_cast<unsigned long long>(lost));
    lines.emplace_back(line);
    if (s.scan_hz) {  // what the device was last set to: each source's own commands
      std::snprintf(line, sizeof line, ", scan rate set to %.1f Hz", *s.scan_hz);
      lines.back() += line;
    }
  }
  char frames[128];
  std::snprintf(frames, sizeof frames, "frame work %.1f ms (mean of the last 60 frames; the slowest %.1f ms)",
                model().frame_ms.mean(), model().frame_ms.max());
  lines.emplace_back(frames);
  return lines;
}

std::span<const ui::SourceLayer> App::source_layers() {
  const bool several = sources_.size() > 1;
  layers_.clear();
  marks_.clear();
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    const SourceSlot& slot = *sources_[i];
    if (slot.look.hidden) continue;
    ui::SourceLayer layer;
    layer.history = &slot.history;
    layer.pose = several ? slot.look.pose : Pose{};  // a lone lidar is drawn around itself
    layer.colour = slot.look.colour;
    layer.dim = several && slot.model.view_state.dim;  // a lone one says so over the whole view
    layer.motion = &slot.motion;
    layers_.push_back(layer);
    if (several) marks_.push_back({slot.look.pose, slot.look.colour, i == selected_});
  }
  // Moving, hiding or dimming a source changes the picture without a new lap.
  std::vector<std::pair<Pose, bool>> key;
  for (const ui::SourceLayer& layer : layers_) key.emplace_back(layer.pose, layer.dim);
  if (key != drawn_layers_key_) {
    drawn_layers_key_ = std::move(key);
    view_->invalidate();
  }
  return layers_;
}

}  // namespace ydscope::gui
