#include "app/gui/source_outputs.h"

#include <cstdio>
#include <future>

#include "core/session/source_set.h"
#include "core/record/recording_source.h"
#include "ui/panels/panels.h"
#include "ui/view/export/file_names.h"

namespace ydscope::gui {
namespace {

// What the outputs call a source: its name and pose as the view shows it; its model is what its
// device or recording says.
SourceInfo info_of(const SourceSlot& slot) { return {slot.look.name, slot.look.pose, {}, {}, {}}; }

std::vector<SourceInfo> infos_of(const SourceList& sources) {
  std::vector<SourceInfo> infos;
  for (const auto& slot : sources.slots()) infos.push_back(info_of(*slot));
  return infos;
}

std::vector<Session*> sessions_of(const SourceList& sources) {
  std::vector<Session*> sessions;
  for (const auto& slot : sources.slots()) sessions.push_back(&slot->session);
  return sessions;
}

// The outcome of a recording's start or stop, beside the Record tab's controls.
void tell_outcome(ui::UiModel& m, bool ok, const std::string& said) {
  const std::uint64_t ticket = m.feedback->issued(ui::CommandControl::Recording);
  m.feedback->finished(ui::CommandControl::Recording, ticket, ok, said);
}

}  // namespace

SourceOutputs::~SourceOutputs() {
  if (ydrec_) stop_ydrec();
}

void SourceOutputs::start_share(SourceList& sources) {
  ui::UiModel& m = sources.selected().model;
  if (share_) return;
  ShareOptions options;
  options.server.port = share_port_;
  options.server.port_option = "--share-port";
  options.server.name = "ydscope" + (sources.several()       ? " on " + std::to_string(sources.size()) + " lidars"
                                     : m.source_text.empty() ? std::string()
                                                             : " on " + m.source_text);
  std::vector<SessionShare::Source> shared;
  for (const auto& slot : sources.slots()) shared.push_back({&slot->session, info_of(*slot)});
  std::string error;
  share_ = SessionShare::start(shared, std::move(options), error);
  if (!share_) {
    // One sentence where the user looks; the toggle stays off.
    m.share = {};
    m.share.error = "Share did not start: " + error + ".";
    m.status_message = m.share.error;
    m.show_source_tab = static_cast<int>(ui::SourceTab::Share);
    std::fprintf(stderr, "ydscope: %s\n", m.share.error.c_str());
    return;
  }
  rejoining_.assign(sources.size(), false);
  share_clients_ = 0;
  tell_models(sources);
  m.show_source_tab = static_cast<int>(ui::SourceTab::Share);  // where the address is
  m.status_message = "sharing on " + share_->address() + " (Foxglove: Open connection > Foxglove WebSocket)";
  // Scripts and tests read where to connect from here, as from `ydscope-cli serve`.
  std::printf("sharing %s\n", share_->address().c_str());
  std::fflush(stdout);
}

void SourceOutputs::stop_share(SourceList& sources) {
  if (!share_) return;
  share_->stop();
  share_.reset();
  tell_models(sources);
  sources.selected().model.status_message = "sharing stopped";
}

void SourceOutputs::start_recording(SourceList& sources, const ui::StartRecording& request) {
  ui::UiModel& m = sources.selected().model;
  if (recording()) return;
  const std::vector<SourceInfo> infos = infos_of(sources);
  std::string error;
  if (!request.path.empty()) {
    std::vector<RecordingMetadata> entries;
    for (std::size_t id = 0; id < infos.size(); ++id) entries.push_back(source_entry_of(infos, id));
    ydrec_sessions_ = sessions_of(sources);
    ydrec_ = record_sessions(request.path, ydrec_sessions_, std::move(entries), error);
    if (!ydrec_) return tell_outcome(m, false, error);
    ydrec_stopping_.store(false);
    ydrec_failed_.store(false);
    // Written off the window's thread, as the sessions' own files were.
    ydrec_pump_ = std::thread([this] {
      while (!ydrec_stopping_.load())
        if (!ydrec_->pump(std::chrono::milliseconds(50))) {
          ydrec_failed_.store(true);
          return;
        }
    });
    ydrec_state_ = {true, request.path, 0, 0};
  }
  if (!request.mcap_path.empty()) {
    LiveTopicsOptions options;
    options.mcap_path = request.mcap_path;
    std::vector<LiveSource> live;
    for (const auto& slot : sources.slots()) live.push_back({&slot->session, info_of(*slot), nullptr});
    mcap_recording_ = LiveTopics::start(std::move(live), std::move(options), error);
    if (!mcap_recording_) {
      if (ydrec_) stop_recording(sources);
      return tell_outcome(m, false, error);
    }
    mcap_state_ = {true, request.mcap_path, 0, 0};
  }
  record_started_s_ = m.now_s;
  tell_models(sources);
  const std::string what = sources.several() ? std::to_string(sources.size()) + " lidars" : "every byte";
  tell_outcome(m, true,
               !request.path.empty() ? "recording " + what + " to " + request.path
                                     : "recording ROS 2 topics to " + request.mcap_path);
}

void SourceOutputs::stop_ydrec() {
  ydrec_stopping_.store(true);
  if (ydrec_pump_.joinable()) ydrec_pump_.join();
}

void SourceOutputs::stop_recording(SourceList& sources, const std::string& why) {
  if (!recording()) return;
  ui::UiModel& m = sources.selected().model;
  // Each lidar's taps close together, so both files end at the same byte of it.
  std::vector<std::future<CommandResult>> closed = close_run_taps(ydrec_sessions_, ydrec_.get(), mcap_recording_.get());
  bool written = true;
  std::string said;
  if (mcap_recording_) {
    written = mcap_recording_->stop();
    said = written ? mcap_recording_->file_summary() : mcap_recording_->error();
    mcap_recording_.reset();
  }
  if (ydrec_) {
    stop_ydrec();
    for (auto& tap_closed : closed) tap_closed.wait_for(std::chrono::seconds(3));
    const bool saved = ydrec_->finish() && !ydrec_failed_.load();
    written = written && saved;
    const std::string ydrec_said = saved ? "recording saved to " + ydrec_->path() : ydrec_->error();
    said = said.empty() ? ydrec_said : ydrec_said + "; " + said;
    ydrec_.reset();
    ydrec_sessions_.clear();
  }
  ydrec_state_ = {};
  mcap_state_ = {};
  tell_models(sources);
  tell_outcome(m, written, said + why);
  m.status_message = said + why;
}

void SourceOutputs::leave_source(SourceList& sources, std::size_t index) {
  if (recording()) stop_recording(sources, " (the source changed)");
  if (!share_ || index >= rejoining_.size()) return;
  share_->topics().detach_source(index);
  rejoining_[index] = true;
}

void SourceOutputs::before_change(SourceList& sources) {
  if (recording()) stop_recording(sources, " (the sources changed)");
  share_again_ = sharing();
  stop_share(sources);
}

void SourceOutputs::after_change(SourceList& sources) {
  if (share_again_) start_share(sources);
  share_again_ = false;
}

void SourceOutputs::tell_models(SourceList& sources) {
  for (const auto& slot : sources.slots()) {
    ui::UiModel& m = slot->model;
    const std::string error = m.share.error;
    m.share = {};
    if (share_)
      m.share = {true, share_->address(), share_clients_, {}};
    else
      m.share.error = error;
    m.ydrec_recording = ydrec_state_;
    m.mcap_recording = mcap_state_;
    if (recording()) m.record_started_s = record_started_s_;
  }
}

void SourceOutputs::follow(SourceList& sources) {
  SourceSlot& selected = sources.selected();
  ui::UiModel& m = selected.model;
  if (!record_at_start_.empty() && link_state_connected(m.snap.state)) {
    // --record: as the Record tab's Start with an empty name, once there is something to record.
    const auto format = record_at_start_ == "mcap"   ? ui::RecordFormat::Mcap
                        : record_at_start_ == "both" ? ui::RecordFormat::Both
                                                     : ui::RecordFormat::Ydrec;
    record_at_start_.clear();
    selected.edits.record_format = static_cast<int>(format);
    const ui::RecordingPaths paths = ui::recording_paths(format, "");
    m.show_source_tab = static_cast<int>(ui::SourceTab::Record);
    start_recording(sources, {paths.ydrec, paths.mcap});
  }
  if (mcap_recording_) {
    mcap_state_.bytes = mcap_recording_->bytes_written();
    mcap_state_.laps = mcap_recording_->laps();
    if (!mcap_recording_->error().empty()) stop_recording(sources);
  }
  if (ydrec_ && ydrec_failed_.load()) stop_recording(sources);
  if (share_) {
    // A changed source is served again once it scans, so its model and times start its new topics.
    for (std::size_t id = 0; id < rejoining_.size() && id < sources.size(); ++id) {
      const SourceSlot& slot = sources[id];
      if (rejoining_[id] && slot.has_source && slot.model.snap.state == LinkState::Scanning) {
        share_->topics().attach_source(id);
        rejoining_[id] = false;
      }
    }
    const auto now = std::chrono::steady_clock::now();
    if (now - share_polled_ >= std::chrono::milliseconds(500)) {
      share_polled_ = now;
      share_clients_ = share_->clients().size();
    }
  }
  tell_models(sources);
}

}  // namespace ydscope::gui
