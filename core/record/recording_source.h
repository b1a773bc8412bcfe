#pragma once
// A recording's source entry (its metadata's name, pose, model and serial) as the SourceInfo
// every other part of ydscope carries, and back: the file format stays as it is, the rest of the
// program knows one kind of "one lidar of several".
#include <cstddef>

#include "core/frame/source_info.h"
#include "core/record/recording_metadata.h"

namespace ydscope {

// What source `id` of a recording is: its name (else "source<id>"), pose (else the identity),
// model (when the metadata names one ydscope knows) and serial.
SourceInfo source_info_of(const RecordingMetadata& metadata, std::size_t id);

// The metadata a recording of `sources` begins with for source `id`: a set of one writes what a
// one-lidar recording always held (version 1 has no name or pose); several name and place each.
RecordingMetadata source_entry_of(std::span<const SourceInfo> sources, std::size_t id);

}  // namespace ydscope
