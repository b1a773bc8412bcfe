#include "ui/view/history/health_timeline.h"

#include <utility>

namespace ydscope::ui {

bool HealthTimeline::observe(std::string_view source, std::uint32_t value, double time_s, std::string text) {
  for (Last& last : last_) {
    if (last.source == source) {
      if (last.value == value) return false;
      last.value = value;
      events_.push_back({time_s, std::string(source), value, std::move(text)});
      if (events_.size() > kMaxEvents) events_.pop_front();
      return true;
    }
  }
  last_.push_back({std::string(source), value});
  events_.push_back({time_s, std::string(source), value, std::move(text)});
  if (events_.size() > kMaxEvents) events_.pop_front();
  return true;
}

void HealthTimeline::clear() {
  last_.clear();
  events_.clear();
}

}  // namespace ydscope::ui
