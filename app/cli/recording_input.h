#pragma once
// Recordings (.ydrec) as input to the commands that decode bytes (decode, replay, export): the
// shared plan (core/record/recording_plan.h) turned into the CLI's exit codes and warning lines,
// and the device->host bytes in order.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/protocol/function_ref.h"
#include "core/record/recording_gap.h"
#include "core/record/recording_plan.h"

namespace ydscope::cli {

// plan_recording(), or its refusal thrown: UsageError (exit 2) for a recording this ydscope cannot
// read or that needs --model, std::runtime_error (exit 1) otherwise.
RecordingPlan recording_plan_or_throw(const std::string& path, RecordingUse use,
                                      const std::optional<std::string>& model_option,
                                      const std::optional<double>& scale_option = std::nullopt,
                                      std::optional<Reading> reading_option = std::nullopt);

// Each of `warnings` on stderr: "PROGRAM: warning: SENTENCE".
void print_recording_warnings(const char* program, const std::vector<std::string>& warnings);

// A long gap that playback reached, on stderr: "PROGRAM: SENTENCE" (core/record/recording_gap.h),
// with the option that does the other thing.
void print_gap(const char* program, const RecordingGap& gap, bool skipped);

// Calls on_chunk with every device->host record's bytes and recorded time, in order (damage is
// the plan's to tell). Throws std::runtime_error when the file cannot be read.
void read_recording_device_bytes(const std::string& path,
                                 FunctionRef<void(std::span<const std::uint8_t>, std::int64_t t_ns)> on_chunk);

}  // namespace ydscope::cli
