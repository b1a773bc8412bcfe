#include "app/cli/recording_input.h"

#include <cstdio>
#include <stdexcept>

#include "app/common/arguments.h"

namespace ydscope::cli {

const ModelProfile& recording_profile(const std::optional<std::string>& model_option,
                                      const RecordingMetadata& metadata, const std::string& path) {
  if (model_option) {
    const ModelProfile* profile = find_profile(*model_option);
    if (!profile)
      throw UsageError("unknown model '" + *model_option + "'; valid models are " + std::string(model_names()));
    return *profile;
  }
  if (!metadata.model)
    throw UsageError(path + " does not say which lidar made it; pass --model (" + std::string(model_names()) + ")");
  const ModelProfile* profile = find_profile(*metadata.model);
  if (!profile)
    throw UsageError(path + " was made with model '" + *metadata.model + "', which this ydscope does not know; pass --model (" +
                     std::string(model_names()) + ")");
  return *profile;
}

void throw_open_failure(const std::string& error, RecordingOpenFailure failure) {
  if (failure == RecordingOpenFailure::Unsupported) throw UsageError(error);
  throw std::runtime_error(error);
}

std::optional<double> recording_distance_scale(const std::optional<double>& scale_option, bool model_forced,
                                               const RecordingMetadata& metadata) {
  if (scale_option) return scale_option;
  if (model_forced) return std::nullopt;  // the recorded scale belonged to the recorded model
  return metadata.distance_scale;
}

std::optional<RecordingMetadata> recording_metadata_of(const std::string& path) {
  if (path == "-" || !is_recording_file(path)) return std::nullopt;
  std::string error;
  auto failure = RecordingOpenFailure::Unreadable;
  const auto summary = summarize_recording(path, error, &failure);
  if (!summary) throw_open_failure(error, failure);
  return summary->metadata;
}

std::optional<RecordingMetadata> read_recording_device_bytes(
    const std::string& path, FunctionRef<void(std::span<const std::uint8_t>)> on_chunk) {
  if (path == "-" || !is_recording_file(path)) return std::nullopt;
  std::string error;
  auto failure = RecordingOpenFailure::Unreadable;
  auto reader = RecordingReader::open(path, error, &failure);
  if (!reader) throw_open_failure(error, failure);
  RecordView record;
  while (reader->next(record))
    if (record.type == RecordType::DeviceToHost) on_chunk(record.payload);
  if (reader->corrupt() || reader->truncated())
    std::fprintf(stderr, "ydscope-cli: warning: %s\n", (reader->corrupt() ? reader->error() : reader->warning()).c_str());
  if (reader->time_corrections() > 0)
    std::fprintf(stderr, "ydscope-cli: warning: %s\n", reader->time_warning().c_str());
  for (const std::string& warning : reader->metadata_warnings())
    std::fprintf(stderr, "ydscope-cli: warning: %s: %s\n", path.c_str(), warning.c_str());
  return reader->metadata();
}

}  // namespace ydscope::cli
