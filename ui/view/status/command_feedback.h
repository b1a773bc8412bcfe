#pragma once
// The outcome of a device command, kept for the control that issued it: the panel shows it beside
// that control ("set scan frequency to 8 Hz: read back 8.00 Hz") and lets it go after a while.
// The session reports outcomes on its I/O thread, so finished() may be called from any thread;
// everything else is for the UI thread.
#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

namespace ydscope::ui {

enum class CommandControl : std::size_t { ScanFrequency, RangingFrequency, Health, Recording, kCount };

class CommandFeedback {
 public:
  static constexpr double kShowSeconds = 8.0;

  struct Shown {
    bool pending = false;  // issued, no outcome yet
    bool ok = false;
    std::string text;
  };

  // Returns the ticket finished() must bring back: an outcome for an older ticket (a command of a
  // source that was since replaced, or one issued again) is dropped.
  std::uint64_t issued(CommandControl control);
  void finished(CommandControl control, std::uint64_t ticket, bool ok, std::string text);
  // What to show beside `control` now; empty once the outcome is kShowSeconds old. The clock
  // starts when the UI first sees the outcome, so a slow frame does not shorten it.
  std::optional<Shown> shown(CommandControl control, double now_s);
  void clear();

 private:
  struct Slot {
    std::uint64_t ticket = 0;
    bool pending = false;
    bool has_outcome = false;
    bool ok = false;
    std::string text;
    std::optional<double> seen_s;
  };
  std::mutex mutex_;
  std::uint64_t next_ticket_ = 1;
  std::array<Slot, static_cast<std::size_t>(CommandControl::kCount)> slots_;
};

}  // namespace ydscope::ui
