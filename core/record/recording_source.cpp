#include "core/record/recording_source.h"

namespace ydscope {

SourceInfo source_info_of(const RecordingMetadata& metadata, std::size_t id) {
  SourceInfo source;
  source.name = source_label(metadata, id);
  source.pose = metadata.pose.value_or(Pose{});
  if (metadata.model)
    if (const ModelProfile* profile = find_profile(*metadata.model)) source.model = profile->model;
  source.serial = metadata.serial.value_or("");
  return source;
}

RecordingMetadata source_entry_of(std::span<const SourceInfo> sources, std::size_t id) {
  const SourceInfo& source = sources[id];
  RecordingMetadata metadata;
  if (named_apart(sources)) {
    metadata.name = source.name;
    metadata.pose = source.pose;
  }
  if (source.model) metadata.model = std::string(profile_for(*source.model).name);
  if (!source.serial.empty()) metadata.serial = source.serial;
  return metadata;
}

}  // namespace ydscope
