#include "core/record/recording_plan.h"

#include "core/record/recorded_conventions.h"
#include "core/text/quoted_text.h"

namespace ydscope {
namespace {

RecordingRefusal refusal_of(RecordingOpenFailure failure) {
  switch (failure) {
    case RecordingOpenFailure::Unreadable: return RecordingRefusal::Unreadable;
    case RecordingOpenFailure::NotARecording: return RecordingRefusal::NotARecording;
    case RecordingOpenFailure::Unsupported: return RecordingRefusal::Unsupported;
  }
  return RecordingRefusal::Unreadable;
}

// The sentence of the damage that ended the reading (a corrupt record, a cut-off tail), or empty:
// "PATH is corrupt at byte N (...); the K records before it are intact".
const std::string& damage_that_stopped(const RecordingSummary& summary) {
  return summary.error.empty() ? summary.warning : summary.error;
}

}  // namespace

const ModelProfile* recording_model(const std::optional<std::string>& model_option, const RecordingMetadata& metadata,
                                    const std::string& path, std::string& error) {
  const std::string choices(model_names());
  if (model_option) {
    const ModelProfile* profile = find_profile(*model_option);
    if (!profile) error = "unknown model " + quote_file_text(*model_option) + "; valid models are " + choices;
    return profile;
  }
  if (!metadata.model) {
    error = path + " does not say which lidar made it; pass --model (" + choices + ")";
    return nullptr;
  }
  const ModelProfile* profile = find_profile(*metadata.model);
  if (!profile)
    error = path + " was made with model " + quote_file_text(*metadata.model) +
            ", which this ydscope does not know; pass --model (" + choices + ")";
  return profile;
}

std::optional<double> recording_distance_scale(const std::optional<double>& scale_option, bool model_chosen,
                                               const RecordingMetadata& metadata) {
  if (scale_option) return scale_option;
  if (model_chosen) return std::nullopt;  // the recorded scale belonged to the recorded model
  return metadata.distance_scale;
}

std::string nothing_to_replay(const RecordingSummary& summary, const std::string& path) {
  if (summary.device_bytes > 0) return {};
  if (const std::string& damage = damage_that_stopped(summary); !damage.empty())
    return damage + ", and none of them holds bytes from a device: nothing to replay";
  return path + " holds no bytes from a device; nothing to replay";
}

RecordingPlan plan_recording(const std::string& path, RecordingUse use, const std::optional<std::string>& model_option,
                             const std::optional<double>& scale_option, std::optional<Reading> reading_option) {
  RecordingPlan plan;
  auto failure = RecordingOpenFailure::Unreadable;
  auto summary = summarize_recording(path, plan.refusal_text, &failure);
  if (!summary) {
    plan.refusal = refusal_of(failure);
    return plan;
  }
  plan.summary = std::move(*summary);
  if (use == RecordingUse::Replay) {
    plan.refusal_text = nothing_to_replay(plan.summary, path);
    if (!plan.refusal_text.empty()) {
      plan.refusal = RecordingRefusal::NothingToPlay;
      return plan;
    }
  }
  // Each source decodes with its own model and scale; --model and --distance-scale set them all.
  for (std::size_t id = 0; id < plan.summary.sources.size(); ++id) {
    const RecordingMetadata& metadata = plan.summary.sources[id].metadata;
    SourcePlan source{source_label(metadata, id), nullptr, std::nullopt};
    const std::string named = plan.several_sources() ? path + "'s source " + source.name : path;
    source.profile = recording_model(model_option, metadata, named, plan.refusal_text);
    if (!source.profile) {
      plan.refusal = RecordingRefusal::NeedsModel;
      plan.sources.clear();
      // Damage before the model record is the cause: "does not say which lidar" would hide it.
      if (const std::string& damage = damage_that_stopped(plan.summary);
          !model_option && !metadata.model && !damage.empty()) {
        const std::uint64_t bytes = plan.summary.sources[id].device_bytes;
        if (bytes == 0) plan.refusal = RecordingRefusal::Damaged;
        plan.refusal_text = damage + ", and none of them says which lidar made it: " +
                            (bytes == 0 ? std::string("nothing to decode")
                                        : "pass --model (" + std::string(model_names()) + ") to decode the " +
                                              std::to_string(bytes) + " bytes from the device before it");
      }
      return plan;
    }
    source.distance_scale = recording_distance_scale(scale_option, model_option.has_value(), metadata);
    source.conventions = &recorded_conventions(metadata, *source.profile, reading_option);
    plan.sources.push_back(std::move(source));
  }
  plan.profile = plan.sources.front().profile;
  plan.distance_scale = plan.sources.front().distance_scale;
  plan.conventions = plan.sources.front().conventions;
  return plan;
}

}  // namespace ydscope
