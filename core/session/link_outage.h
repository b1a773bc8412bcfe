#pragma once
// LinkOutage: what a session's records say while its link is down. A metadata record
// `link_fault=<sentence>` when the link goes down (and when the sentence changes), and
// `link_fault=` (empty) once the device is back, so a recording marks its gaps and /diagnostics,
// made from the same records (core/export/ros_topic_encoder.h), reports the outage. I/O thread only.
#include <string>

#include "core/record/recording_metadata.h"

namespace ydscope {

class RecordingControl;

// The metadata key (an extra key of a .ydrec, see core/record/recording_format.h).
inline constexpr const char* kLinkFaultKey = "link_fault";

class LinkOutage {
 public:
  explicit LinkOutage(RecordingControl& recording) : recording_(recording) {}

  // The link is down: `fault` says why and what the session does about it.
  void down(const std::string& fault);
  // The device answers again.
  void up();
  bool is_down() const { return !fault_.empty(); }
  // A capture that starts mid-outage is told in its first metadata.
  void add_to(RecordingMetadata& metadata) const;

 private:
  void record();

  RecordingControl& recording_;
  std::string fault_;  // empty while the link is up
};

}  // namespace ydscope
