#pragma once
// The device details a recording's metadata carries, so a replay shows the model, firmware,
// hardware and serial of the lidar it was recorded from rather than blanks.
#include "core/session/session.h"
#include "core/record/recording_metadata.h"

namespace ydscope {

// `profile` is the model the replay decodes with; fields the recording lacks stay zero or empty.
DeviceDetails recorded_device(const RecordingMetadata& metadata, const ModelProfile& profile);

}  // namespace ydscope
