#pragma once
// How a recording's bytes are read back: the conventions it was recorded with, so it replays as
// it was seen; the manual's for a recording from before they were written down (ydscope then read
// every unit as its manual says); or the reading the user asks for now.
#include <optional>

#include "core/protocol/model_profile.h"
#include "core/protocol/unit_conventions.h"
#include "core/record/recording_metadata.h"

namespace ydscope {

const UnitConventions& recorded_conventions(const RecordingMetadata& metadata, const ModelProfile& profile,
                                            std::optional<Reading> asked);

// The recorded firmware ("major.minor": the A5 90 bytes in the manuals' order), if it parses.
std::optional<FirmwareVersion> recorded_firmware(const RecordingMetadata& metadata);
// The same bytes as the vendor SDK reads them (firmware_as_sdk_reads).
std::optional<FirmwareVersion> recorded_sdk_firmware(const RecordingMetadata& metadata);

}  // namespace ydscope
