#pragma once
// The app's lidars: never empty, one of them selected, which the panels show and command. Each
// SourceSlot has its own session, laps, look and panel model; the list keeps their names unique
// and their colours apart, and says for all of them what the Sources panel, the legend and the
// end of a run say.
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/gui/source_slot.h"

namespace ydscope::gui {

class SourceList {
 public:
  // `wake` runs on a source's I/O thread after each of its laps.
  explicit SourceList(std::function<void()> wake) : wake_(std::move(wake)) {}

  // A new source at the end, its name made unique and, where `look` leaves it empty, the first
  // palette colour no source has; its view keeps `persistence_laps` laps.
  SourceSlot& add(ui::SourceLook look, std::size_t persistence_laps);
  // Stops source `index` and takes it out; the selection stays on the source it was on. Neither
  // the selected source nor the last one (the caller selects another first).
  void remove(std::size_t index);

  std::size_t size() const { return slots_.size(); }
  bool several() const { return slots_.size() > 1; }
  SourceSlot& operator[](std::size_t index) { return *slots_[index]; }
  const SourceSlot& operator[](std::size_t index) const { return *slots_[index]; }
  const std::vector<std::unique_ptr<SourceSlot>>& slots() const { return slots_; }
  SourceSlot& selected() { return *slots_[selected_]; }
  const SourceSlot& selected() const { return *slots_[selected_]; }
  std::size_t selected_index() const { return selected_; }
  void select(std::size_t index) { selected_ = index; }

  // Every source's look (settings.ini's memory of them, remembered_sources.h) and pose, in order.
  std::vector<ui::SourceLook> looks() const;
  std::vector<Pose> poses() const;
  // The Sources panel's rows and the legend's lines.
  std::vector<ui::SourceRow> rows(std::chrono::steady_clock::time_point now) const;
  // With several sources, a line per source (laps from the device, drawn, lost) and the frame
  // work of the selected one, for the end of a run; nothing with one.
  std::vector<std::string> summary() const;
  bool any_scanning() const;
  // The source whose laps pace the fading persistence (`smooth`): the selected one while it
  // streams, else another that does (one lidar unplugged must not stop the others' smooth
  // drawing); or none.
  const SourceSlot* pacing_fade(bool smooth) const;

 private:
  std::function<void()> wake_;
  std::vector<std::unique_ptr<SourceSlot>> slots_;
  std::size_t selected_ = 0;
};

// One source's row: its look, whether it is dimmed, and its legend line ("G6: no data 5 s, reconnecting").
ui::SourceRow source_row(const SourceSlot& slot, std::chrono::steady_clock::time_point now);

}  // namespace ydscope::gui
