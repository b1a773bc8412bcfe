#pragma once
// Recordings (.ydrec) as input to the commands that decode bytes (decode, replay): which model
// and scale they were made with, and their device->host bytes in order.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "core/protocol/function_ref.h"
#include "core/protocol/model_profile.h"
#include "core/record/recording_metadata.h"
#include "core/record/recording_reader.h"

namespace ydscope::cli {

// The profile to decode with: --model when given (UsageError if unknown), else the recording's
// model (UsageError naming the file when it has none or an unknown one).
const ModelProfile& recording_profile(const std::optional<std::string>& model_option,
                                      const RecordingMetadata& metadata, const std::string& path);

// The scale to decode a recording with, the same in decode and replay: --distance-scale when
// given; else the recording's own (already held to kMin/kMaxDistanceScale when its metadata was
// read) unless --model forced another model; else empty (the model's).
std::optional<double> recording_distance_scale(const std::optional<double>& scale_option, bool model_forced,
                                               const RecordingMetadata& metadata);

// Throws the sentence of a recording that did not open: UsageError (exit 2) for a recording of a
// version or header this ydscope cannot read, std::runtime_error (exit 1) otherwise.
[[noreturn]] void throw_open_failure(const std::string& error, RecordingOpenFailure failure);

// The metadata of the recording at `path`, every metadata record merged (one pass over the
// file); empty when `path` is not a recording (or "-"). Throws std::runtime_error if unreadable.
std::optional<RecordingMetadata> recording_metadata_of(const std::string& path);

// If `path` is a recording: calls on_chunk with every device->host record's bytes, in order,
// prints a truncated or corrupt tail as a warning on stderr, and returns the merged metadata.
// Empty when `path` is not a recording (or "-"). Throws std::runtime_error when it cannot be read.
std::optional<RecordingMetadata> read_recording_device_bytes(
    const std::string& path, FunctionRef<void(std::span<const std::uint8_t>)> on_chunk);

}  // namespace ydscope::cli
