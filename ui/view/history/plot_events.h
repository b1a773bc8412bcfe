#pragma once
// What happened on the plots' time axis: stalls, reconnects, scan-rate changes and health changes,
// each with its time, so a step or a gap in a line is read beside its cause. A fixed ring: the
// newest kCapacity events are kept, nothing allocates once built.
#include <array>
#include <cstddef>

namespace ydscope::ui {

enum class PlotEventKind { Stall, Reconnect, RateChange, HealthChange };

// "stall", "reconnect", "scan rate set", "health changed"
const char* plot_event_name(PlotEventKind kind);

struct PlotEvent {
  PlotEventKind kind = PlotEventKind::Stall;
  double time_s = 0.0;  // the app's seconds, as the plots' sample times
};

class PlotEvents {
 public:
  static constexpr std::size_t kCapacity = 64;

  void add(PlotEventKind kind, double time_s);
  void clear() { count_ = next_ = 0; }
  std::size_t size() const { return count_; }
  // Event i, oldest first.
  const PlotEvent& at(std::size_t i) const { return events_[(next_ + kCapacity - count_ + i) % kCapacity]; }

 private:
  std::array<PlotEvent, kCapacity> events_{};
  std::size_t next_ = 0;
  std::size_t count_ = 0;
};

}  // namespace ydscope::ui
