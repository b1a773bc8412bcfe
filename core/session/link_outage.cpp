#include "core/session/link_outage.h"

#include "core/session/recording_control.h"

namespace ydscope {

void LinkOutage::down(const std::string& fault) {
  if (fault.empty() || fault == fault_) return;
  fault_ = fault;
  record();
}

void LinkOutage::up() {
  if (fault_.empty()) return;
  fault_.clear();
  record();  // the empty value ends the outage
}

void LinkOutage::add_to(RecordingMetadata& metadata) const {
  if (is_down()) metadata.extra[kLinkFaultKey] = fault_;
}

void LinkOutage::record() {
  if (!recording_.capturing()) return;
  RecordingMetadata change;
  change.extra[kLinkFaultKey] = fault_;
  recording_.record_metadata(change);
}

}  // namespace ydscope
