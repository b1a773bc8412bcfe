#pragma once
// RecordingControl: the session's recording part, on the I/O thread. It owns the recorder (a
// file, live taps for MCAP and the bridge, any of them), points the link's wire hook at it
// while anything captures (so every byte is recorded as it crosses the link, whatever the UI
// does), carries out the four recording intents, and says what the session knows as recording
// metadata.
#include <memory>
#include <optional>
#include <string>

#include "core/session/session_recorder.h"
#include "core/snapshot/session_snapshot.h"
#include "core/record/recording_metadata.h"

namespace ydscope {

class RecordTap;
class SessionIo;

class RecordingControl {
 public:
  explicit RecordingControl(SessionIo& link) : link_(link) {}

  // `start` is the metadata a recording begins with (start time, software, port).
  CommandResult start_file(const std::string& path, const RecordingMetadata& start);
  CommandResult stop_file();
  CommandResult start_tap(std::shared_ptr<RecordTap> tap, const RecordingMetadata& start);
  CommandResult stop_tap(const std::shared_ptr<RecordTap>& tap);

  // Once a second while a file records: hands its bytes to the kernel. Empty, or the sentence
  // saying why the file stopped (a write error).
  std::optional<std::string> flush_file();

  bool file_active() const { return recorder_.active(); }
  const std::string& file_path() const { return recorder_.path(); }
  // Adds a metadata record to whatever captures (SessionRecorder skips what is not open).
  void record_metadata(const RecordingMetadata& metadata);
  bool capturing() const { return recorder_.capturing(); }

 private:
  void update_wire_hook();

  SessionIo& link_;
  SessionRecorder recorder_;
};

// What a session knows, as a recording's metadata: the port, the line rate, the scale in use, the
// device's identity and its settings as last read back (so a recording, and its MCAP, can say them).
RecordingMetadata recording_metadata_of(const SessionSnapshot& snapshot, const std::optional<std::string>& port,
                                        std::optional<double> distance_scale);

}  // namespace ydscope
