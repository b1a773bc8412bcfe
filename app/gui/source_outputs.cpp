#include "app/gui/source_outputs.h"

#include <cstdio>

#include "ui/panels/panels.h"
#include "ui/view/export/file_names.h"

namespace ydscope::gui {

void SourceOutputs::start_share(SourceSlot& slot) {
  ui::UiModel& m = slot.model;
  if (share_) return;
  ShareOptions options;
  options.server.port = share_port_;
  options.server.port_option = "--share-port";
  options.server.name = "ydscope" + (m.source_text.empty() ? std::string() : " on " + m.source_text);
  std::string error;
  share_ = SessionShare::start(slot.session, std::move(options), error);
  if (!share_) {
    // One sentence where the user looks; the toggle stays off.
    m.share = {};
    m.share.error = "Share did not start: " + error + ".";
    m.status_message = m.share.error;
    m.show_source_tab = static_cast<int>(ui::SourceTab::Share);
    std::fprintf(stderr, "ydscope: %s\n", m.share.error.c_str());
    return;
  }
  m.share.on = true;
  m.share.error.clear();
  m.share.address = share_->address();
  m.share.clients = 0;
  m.show_source_tab = static_cast<int>(ui::SourceTab::Share);  // where the address is
  m.status_message = "sharing on " + m.share.address + " (Foxglove: Open connection > Foxglove WebSocket)";
  // Scripts and tests read where to connect from here, as from `ydscope-cli serve`.
  std::printf("sharing %s\n", m.share.address.c_str());
  std::fflush(stdout);
}

void SourceOutputs::stop_share(SourceSlot& slot) {
  if (!share_) return;
  share_->stop();
  share_.reset();
  slot.model.share = {};
  slot.model.status_message = "sharing stopped";
}

void SourceOutputs::start_recording(SourceSlot& slot, const ui::StartRecording& request) {
  ui::UiModel& m = slot.model;
  using ui::CommandControl;
  if (!request.path.empty())
    slot.session.start_recording(request.path, ui::track_command(m, CommandControl::Recording));
  if (request.mcap_path.empty()) return;
  LiveTopicsOptions options;
  options.mcap_path = request.mcap_path;
  std::string error;
  mcap_recording_ = LiveTopics::start(slot.session, std::move(options), error);
  if (!mcap_recording_) {
    const std::uint64_t ticket = m.feedback->issued(CommandControl::Recording);
    m.feedback->finished(CommandControl::Recording, ticket, false, error);
    return;
  }
  m.mcap_recording = {true, request.mcap_path, 0, 0};
  if (request.path.empty()) {  // else the .ydrec's outcome is the one shown
    const std::uint64_t ticket = m.feedback->issued(CommandControl::Recording);
    m.feedback->finished(CommandControl::Recording, ticket, true, "recording ROS 2 topics to " + request.mcap_path);
  }
}

void SourceOutputs::stop_recording(SourceSlot& slot, const std::string& why) {
  ui::UiModel& m = slot.model;
  using ui::CommandControl;
  if (m.snap.recording) slot.session.stop_recording(ui::track_command(m, CommandControl::Recording));
  if (!mcap_recording_) return;
  const bool written = mcap_recording_->stop();
  const std::string said = written ? mcap_recording_->file_summary() + why : mcap_recording_->error();
  mcap_recording_.reset();
  m.mcap_recording = {};
  const std::uint64_t ticket = m.feedback->issued(CommandControl::Recording);
  m.feedback->finished(CommandControl::Recording, ticket, written, said);
  m.status_message = said;
}

void SourceOutputs::leave_source(SourceSlot& slot) {
  if (slot.model.recording()) stop_recording(slot, " (the source changed)");
  if (share_) share_->topics().detach();
}

void SourceOutputs::follow(SourceSlot& slot) {
  ui::UiModel& m = slot.model;
  if (!record_at_start_.empty() && link_state_connected(m.snap.state)) {
    // --record: as the Record tab's Start with an empty name, once there is something to record.
    const auto format = record_at_start_ == "mcap"   ? ui::RecordFormat::Mcap
                        : record_at_start_ == "both" ? ui::RecordFormat::Both
                                                     : ui::RecordFormat::Ydrec;
    record_at_start_.clear();
    slot.edits.record_format = static_cast<int>(format);
    const ui::RecordingPaths paths = ui::recording_paths(format, "");
    m.record_started_s = m.now_s;
    m.show_source_tab = static_cast<int>(ui::SourceTab::Record);
    start_recording(slot, {paths.ydrec, paths.mcap});
  }
  if (mcap_recording_) {
    m.mcap_recording.bytes = mcap_recording_->bytes_written();
    m.mcap_recording.laps = mcap_recording_->laps();
    if (!mcap_recording_->error().empty()) stop_recording(slot);
  }
  if (!share_) return;
  // The new source is served once it scans, so its model and times start the new topics.
  if (!share_->topics().attached() && slot.has_source && m.snap.state == LinkState::Scanning) share_->topics().attach();
  const auto now = std::chrono::steady_clock::now();
  if (now - share_polled_ >= std::chrono::milliseconds(500)) {
    share_polled_ = now;
    m.share.clients = share_->clients().size();
  }
}

}  // namespace ydscope::gui
