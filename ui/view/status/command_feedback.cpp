#include "ui/view/status/command_feedback.h"

namespace ydscope::ui {

std::uint64_t CommandFeedback::issued(CommandControl control) {
  std::lock_guard lock(mutex_);
  Slot& slot = slots_[static_cast<std::size_t>(control)];
  slot = Slot{};
  slot.ticket = next_ticket_++;
  slot.pending = true;
  return slot.ticket;
}

void CommandFeedback::finished(CommandControl control, std::uint64_t ticket, bool ok, std::string text) {
  std::lock_guard lock(mutex_);
  Slot& slot = slots_[static_cast<std::size_t>(control)];
  if (slot.ticket != ticket) return;
  slot.pending = false;
  slot.has_outcome = true;
  slot.ok = ok;
  slot.text = std::move(text);
  slot.seen_s.reset();
}

std::optional<CommandFeedback::Shown> CommandFeedback::shown(CommandControl control, double now_s) {
  std::lock_guard lock(mutex_);
  Slot& slot = slots_[static_cast<std::size_t>(control)];
  if (slot.pending) return Shown{true, false, {}};
  if (!slot.has_outcome) return std::nullopt;
  if (!slot.seen_s) slot.seen_s = now_s;
  if (now_s - *slot.seen_s > kShowSeconds) {
    slot.has_outcome = false;
    return std::nullopt;
  }
  return Shown{false, slot.ok, slot.text};
}

void CommandFeedback::clear() {
  std::lock_guard lock(mutex_);
  slots_.fill(Slot{});  // tickets restart at none, so late outcomes find no match
}

}  // namespace ydscope::ui
