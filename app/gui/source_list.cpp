#include "app/gui/source_list.h"

#include <algorithm>
#include <cstdio>

namespace ydscope::gui {

SourceSlot& SourceList::add(ui::SourceLook look, std::size_t persistence_laps) {
  std::vector<std::string> names;
  std::vector<ui::Rgba8> colours;
  for (const auto& slot : slots_) {
    names.push_back(slot->look.name);
    colours.push_back(slot->look.colour);
  }
  look.name = ui::unique_source_name(look.name, names);
  if (look.colour == ui::Rgba8{}) look.colour = ui::unused_source_colour(colours);
  auto slot = std::make_unique<SourceSlot>(std::move(look), wake_);
  slot->history.set_depth(persistence_laps);
  slots_.push_back(std::move(slot));
  return *slots_.back();
}

void SourceList::remove(std::size_t index) {
  if (index >= slots_.size() || index == selected_ || slots_.size() < 2) return;
  slots_[index]->source.stop();
  slots_.erase(slots_.begin() + static_cast<std::ptrdiff_t>(index));
  if (selected_ > index) --selected_;
}

std::vector<ui::SourceLook> SourceList::looks() const {
  std::vector<ui::SourceLook> looks;
  for (const auto& slot : slots_) looks.push_back(slot->look);
  return looks;
}

std::vector<Pose> SourceList::poses() const {
  std::vector<Pose> poses;
  for (const auto& slot : slots_) poses.push_back(slot->look.pose);
  return poses;
}

ui::SourceRow source_row(const SourceSlot& slot, std::chrono::steady_clock::time_point now) {
  ui::SourceRow row;
  row.look = slot.look;
  row.look.paused = slot.model.paused_view;  // P freezes the selected source as the checkbox does
  row.dim = slot.model.view_state.dim;
  row.legend = ui::source_legend_line(slot.look.name, slot.model.view_state, slot.seconds_since_lap(now));
  return row;
}

std::vector<ui::SourceRow> SourceList::rows(std::chrono::steady_clock::time_point now) const {
  std::vector<ui::SourceRow> rows;
  rows.reserve(slots_.size());
  for (const auto& slot : slots_) rows.push_back(source_row(*slot, now));
  return rows;
}

std::vector<std::string> SourceList::summary() const {
  std::vector<std::string> lines;
  if (!several()) return lines;  // one source's run says what it always said
  for (const auto& slot : slots_) {
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
  const ui::UiModel& model = selected().model;
  char frames[128];
  std::snprintf(frames, sizeof frames, "frame work %.1f ms (mean of the last 60 frames; the slowest %.1f ms)",
                model.frame_ms.mean(), model.frame_ms.max());
  lines.emplace_back(frames);
  return lines;
}

bool SourceList::any_scanning() const {
  return std::any_of(slots_.begin(), slots_.end(),
                     [](const auto& slot) { return slot->model.snap.state == LinkState::Scanning; });
}

const SourceSlot* SourceList::pacing_fade(bool smooth) const {
  const auto fading = [&](const SourceSlot& s) {
    return smooth && s.model.snap.state == LinkState::Scanning && !s.model.paused_view && s.history.size() > 1;
  };
  if (fading(selected())) return &selected();
  for (const auto& slot : slots_)
    if (fading(*slot)) return slot.get();
  return nullptr;
}

}  // namespace ydscope::gui
