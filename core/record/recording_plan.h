#pragma once
// A recording as something to decode or play: which model and scale to decode it with, what is
// wrong with it but still plays, and, when it cannot give a single lap, the one sentence that says
// why and what to try. Both programs ask here (ydscope-cli decode, replay and export; the app's
// Replay), so they say the same words about the same file.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/protocol/model_profile.h"
#include "core/protocol/unit_conventions.h"
#include "core/record/recording_metadata.h"
#include "core/record/recording_reader.h"

namespace ydscope {

enum class RecordingUse : std::uint8_t {
  Decode,  // every byte once: a recording without device bytes decodes to no laps, and says so by that
  Replay,  // played with its timing: a recording without device bytes would wait forever; refused
};

// Why a recording cannot be used. The CLI exits 2 (usage) for Unsupported and NeedsModel, whose fix
// is another ydscope or a --model, and 1 for the others.
enum class RecordingRefusal : std::uint8_t {
  None,
  Unreadable,     // missing, no permission, a folder, a read error
  NotARecording,  // no magic, or cut off inside the file header
  Unsupported,    // a version or header size this ydscope cannot read
  NothingToPlay,  // Replay: not one byte from a device
  NeedsModel,     // no model recorded, an unknown one, or an unknown --model
  Damaged,        // corrupt or cut off before it says which lidar made it, with no device byte before
};

// How one source of the recording decodes (version 2 has several; version 1 one).
struct SourcePlan {
  std::string name;  // source_label(): what its laps are tagged with
  const ModelProfile* profile = nullptr;
  std::optional<double> distance_scale;          // empty: the conventions' own
  const UnitConventions* conventions = nullptr;  // how its bytes are read (recorded_conventions)
};

struct RecordingPlan {
  RecordingRefusal refusal = RecordingRefusal::None;
  std::string refusal_text;               // one sentence; empty when usable
  RecordingSummary summary;               // when the file opened
  const ModelProfile* profile = nullptr;  // the model to decode with, when usable
  std::optional<double> distance_scale;   // empty: the conventions' own
  const UnitConventions* conventions = nullptr;
  // Every source, by id; sources[0] is profile, distance_scale and conventions above. Set when usable.
  std::vector<SourcePlan> sources;
  // A version-2 recording of several lidars: its laps are tagged with their source.
  bool several_sources() const { return summary.version >= kMultiSourceVersion; }
  bool usable() const { return refusal == RecordingRefusal::None; }
  // What is wrong but still plays (summary.damage): a cut-off tail, damaged times or fields.
  const std::vector<std::string>& warnings() const { return summary.damage; }
};

// One pass over the file. model_option: a model name the user chose instead of the recording's;
// scale_option: a distance scale (mm per count) the user chose; reading_option: field or manual
// conventions instead of those the recording was made with.
RecordingPlan plan_recording(const std::string& path, RecordingUse use, const std::optional<std::string>& model_option,
                             const std::optional<double>& scale_option,
                             std::optional<Reading> reading_option = std::nullopt);

// The model to decode with: model_option when given, else the recording's. Null plus one sentence
// in `error` when model_option is unknown, or the recording names no model or an unknown one.
const ModelProfile* recording_model(const std::optional<std::string>& model_option, const RecordingMetadata& metadata,
                                    const std::string& path, std::string& error);

// The scale to decode with, the same in decode and replay: scale_option when given; else the
// recording's own (held to kMin/kMaxDistanceScale when its metadata was read) unless another
// model was chosen; else empty (the model's).
std::optional<double> recording_distance_scale(const std::optional<double>& scale_option, bool model_chosen,
                                               const RecordingMetadata& metadata);

// "PATH holds no bytes from a device; nothing to replay", or empty when it holds some. When damage
// stopped the reading, the sentence is the damage's: that is the cause, not an empty recording.
std::string nothing_to_replay(const RecordingSummary& summary, const std::string& path);

}  // namespace ydscope
