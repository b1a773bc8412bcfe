#pragma once
// decode and replay of a recording of several lidars (format version 2): each source decoded with
// its own model (core/record/source_decoders.h), its laps printed tagged with the source's name,
// then one summary line per source. A version-1 recording never comes here: it prints as ever.
#include <atomic>
#include <string>

#include "app/cli/lap_output.h"
#include "core/protocol/interference_filter.h"
#include "core/record/recording_plan.h"

namespace ydscope::cli {

struct Pacing {
  // 0: as fast as the file reads (decode); otherwise the records are paced by their recorded
  // times (replay: 1 as recorded, 2 twice as fast).
  double speed = 0;
  // Paced: a gap longer than kLongGapNs is waited out instead of skipped (said on stderr either way).
  bool keep_gaps = false;
};

// `stop` (Ctrl-C) ends early; the summaries of what was played are still printed. Throws
// std::runtime_error when the file cannot be read.
void print_source_laps(const std::string& path, const RecordingPlan& plan, LapFormat format, Pacing pacing,
                       InterferenceFilter filter, const std::atomic<bool>& stop);

}  // namespace ydscope::cli
