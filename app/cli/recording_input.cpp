#include "app/cli/recording_input.h"

#include <cstdio>
#include <stdexcept>

#include "app/common/arguments.h"

namespace ydscope::cli {

RecordingPlan recording_plan_or_throw(const std::string& path, RecordingUse use,
                                      const std::optional<std::string>& model_option,
                                      const std::optional<double>& scale_option,
                                      std::optional<Reading> reading_option) {
  RecordingPlan plan = plan_recording(path, use, model_option, scale_option, reading_option);
  switch (plan.refusal) {
    case RecordingRefusal::None: return plan;
    case RecordingRefusal::Unsupported:
    case RecordingRefusal::NeedsModel: throw UsageError(plan.refusal_text);
    case RecordingRefusal::Unreadable:
    case RecordingRefusal::NotARecording:
    case RecordingRefusal::NothingToPlay:
    case RecordingRefusal::Damaged: break;
  }
  throw std::runtime_error(plan.refusal_text);
}

void print_recording_warnings(const char* program, const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) std::fprintf(stderr, "%s: warning: %s\n", program, warning.c_str());
}

void print_gap(const char* program, const RecordingGap& gap, bool skipped) {
  std::fprintf(stderr, "%s: %s (%s)\n", program, gap_sentence(gap, skipped).c_str(),
               skipped ? "--keep-gaps waits gaps out" : "skipped without --keep-gaps");
}

void read_recording_device_bytes(const std::string& path,
                                 FunctionRef<void(std::span<const std::uint8_t>, std::int64_t t_ns)> on_chunk) {
  std::string error;
  auto reader = RecordingReader::open(path, error);
  if (!reader) throw std::runtime_error(error);
  RecordView record;
  while (reader->next(record))
    if (record.type == RecordType::DeviceToHost) on_chunk(record.payload, record.t_ns);
}

}  // namespace ydscope::cli
