#pragma once
// A bounded log of health changes with timestamps: a change is recorded only when a source's value
// differs from the last one seen, so a steady device writes nothing.
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

namespace ydscope::ui {

struct HealthEvent {
  double time_s;       // seconds since the app started
  std::string source;  // "CT health", "A5 92", "A5 91", "link"
  std::uint32_t value;
  std::string text;  // what it means now
};

class HealthTimeline {
 public:
  static constexpr std::size_t kMaxEvents = 200;

  // Returns true when the value changed (or is the first for that source) and was recorded.
  bool observe(std::string_view source, std::uint32_t value, double time_s, std::string text);
  const std::deque<HealthEvent>& events() const { return events_; }
  void clear();

 private:
  struct Last {
    std::string source;
    std::uint32_t value;
  };
  std::vector<Last> last_;
  std::deque<HealthEvent> events_;
};

}  // namespace ydscope::ui
