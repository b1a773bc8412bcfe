#pragma once
// A long gap in a recording: a legal stretch without a byte from the lidar (a pulled cable the
// recorder waited out, a unit that stopped), up to kMaxRecordGapNs. Played as recorded it froze a
// replay for up to a minute without a word, so replays find such gaps here, say so in these
// words, and skip them unless asked to wait them out. Plain C++, like the rest of core/record.
#include <cstdint>
#include <optional>
#include <string>

namespace ydscope {

// Longer than any pause a working session makes in its stream (a command stops the scan for a
// second or two), so only an outage counts as a gap.
inline constexpr std::int64_t kLongGapNs = 5'000'000'000;
// How long after a gap the app still shows it (recording time).
inline constexpr std::int64_t kGapNoticeNs = 10'000'000'000;

struct RecordingGap {
  std::int64_t at_ns = 0;      // recording time of the last device byte before it (0 at the start)
  std::int64_t length_ns = 0;  // to the next device byte
  std::int64_t end_ns() const { return at_ns + length_ns; }
};

// The gap between device bytes at previous_t_ns and next_t_ns, when longer than kLongGapNs.
std::optional<RecordingGap> long_gap(std::int64_t previous_t_ns, std::int64_t next_t_ns);

// "the recording has a gap of 59.0 s at 12.3 s without a byte from the lidar; skipped to 71.3 s"
// or, when waited out, "...; waiting it out, playing on at 71.3 s".
std::string gap_sentence(const RecordingGap& gap, bool skipped);

// For a view beside the playback point: "gap in recording: 59 s at 12 s, skipped" while
// position_ns is within kGapNoticeNs after the gap ends (or in it), else empty.
std::string gap_notice(const RecordingGap& gap, bool skipped, std::int64_t position_ns);

}  // namespace ydscope
