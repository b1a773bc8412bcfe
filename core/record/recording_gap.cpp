#include "core/record/recording_gap.h"

#include <cstdio>

namespace ydscope {
namespace {

std::string seconds(std::int64_t ns, const char* format) {
  char text[48];
  std::snprintf(text, sizeof text, format, static_cast<double>(ns) / 1e9);
  return text;
}

}  // namespace

std::optional<RecordingGap> long_gap(std::int64_t previous_t_ns, std::int64_t next_t_ns) {
  // The reader keeps record times sound (never back, never more than kMaxRecordGapNs ahead).
  if (next_t_ns - previous_t_ns <= kLongGapNs) return std::nullopt;
  return RecordingGap{previous_t_ns, next_t_ns - previous_t_ns};
}

std::string gap_sentence(const RecordingGap& gap, bool skipped) {
  return "the recording has a gap of " + seconds(gap.length_ns, "%.1f s") + " at " + seconds(gap.at_ns, "%.1f s") +
         " without a byte from the lidar; " + (skipped ? "skipped to " : "waiting it out, playing on at ") +
         seconds(gap.end_ns(), "%.1f s");
}

std::string gap_notice(const RecordingGap& gap, bool skipped, std::int64_t position_ns) {
  if (gap.length_ns <= 0 || position_ns < gap.at_ns || position_ns > gap.end_ns() + kGapNoticeNs) return {};
  return "gap in recording: " + seconds(gap.length_ns, "%.0f s") + " at " + seconds(gap.at_ns, "%.0f s") +
         (skipped ? ", skipped" : ", waiting it out");
}

}  // namespace ydscope
