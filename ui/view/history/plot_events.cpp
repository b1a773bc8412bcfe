#include "ui/view/history/plot_events.h"

#include <algorithm>

namespace ydscope::ui {

const char* plot_event_name(PlotEventKind kind) {
  switch (kind) {
    case PlotEventKind::Stall: return "stall";
    case PlotEventKind::Reconnect: return "reconnect";
    case PlotEventKind::RateChange: return "scan rate set";
    case PlotEventKind::HealthChange: return "health changed";
  }
  return "event";
}

void PlotEvents::add(PlotEventKind kind, double time_s) {
  events_[next_] = {kind, time_s};
  next_ = (next_ + 1) % kCapacity;
  count_ = std::min(count_ + 1, kCapacity);
}

}  // namespace ydscope::ui
