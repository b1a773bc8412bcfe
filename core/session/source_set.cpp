#include "core/session/source_set.h"

#include <algorithm>
#include <stdexcept>

#include "core/record/recording_source.h"

namespace ydscope {
namespace {

bool laps_flow(LinkState state) { return state == LinkState::Scanning || state == LinkState::CommandInProgress; }

bool in_trouble(LinkState state) {
  return state == LinkState::Stalled || state == LinkState::Reconnecting || state == LinkState::Failed;
}

}  // namespace

SourceSet::SourceSet(std::vector<SourceSpec> specs, std::size_t lap_queue) {
  if (specs.empty()) throw std::invalid_argument("a set of lidars holds at least one");
  for (SourceSpec& spec : specs) {
    infos_.push_back(std::move(spec.info));
    configs_.push_back(std::move(spec.config));
    sessions_.push_back(std::make_unique<Session>(lap_queue));
  }
  ever_scanned_.assign(sessions_.size(), false);
}

std::unique_ptr<SourcesRecording> record_sessions(const std::string& path, const std::vector<Session*>& sessions,
                                                  std::vector<RecordingMetadata> entries, std::string& error) {
  auto recording = SourcesRecording::create(path, std::move(entries), error);
  if (!recording) return nullptr;
  for (std::size_t id = 0; id < sessions.size(); ++id) {
    std::promise<CommandResult> tapped;
    auto done = tapped.get_future();
    sessions[id]->start_tap(recording->tap(id), [&tapped](const CommandResult& r) { tapped.set_value(r); });
    if (const CommandResult result = done.get(); !result.ok) {
      error = result.message;
      return nullptr;
    }
  }
  return recording;
}

std::vector<SessionTap> recording_taps(const std::vector<Session*>& sessions, const SourcesRecording& recording) {
  std::vector<SessionTap> taps;
  for (std::size_t id = 0; id < sessions.size(); ++id) taps.push_back({sessions[id], recording.tap(id)});
  return taps;
}

std::vector<std::future<CommandResult>> close_taps_together(const std::vector<SessionTap>& taps) {
  std::vector<Session*> sessions;
  for (const SessionTap& t : taps)
    if (std::find(sessions.begin(), sessions.end(), t.session) == sessions.end()) sessions.push_back(t.session);
  std::vector<std::future<CommandResult>> closed;
  for (Session* session : sessions) {
    std::vector<std::shared_ptr<RecordTap>> its_taps;
    for (const SessionTap& t : taps)
      if (t.session == session) its_taps.push_back(t.tap);
    auto promise = std::make_shared<std::promise<CommandResult>>();
    closed.push_back(promise->get_future());
    session->stop_taps(std::move(its_taps), [promise](const CommandResult& r) { promise->set_value(r); });
  }
  return closed;
}

std::vector<Session*> SourceSet::sessions() const {
  std::vector<Session*> all;
  for (const auto& session : sessions_) all.push_back(session.get());
  return all;
}

std::unique_ptr<SourcesRecording> SourceSet::record(const std::string& path, std::string& error) {
  std::vector<RecordingMetadata> entries;
  for (std::size_t id = 0; id < size(); ++id) {
    entries.push_back(source_entry_of(infos_, id));
    entries.back().port = configs_[id].address;
  }
  return record_sessions(path, sessions(), std::move(entries), error);
}

void SourceSet::connect_all() {
  for (std::size_t id = 0; id < size(); ++id) sessions_[id]->connect(configs_[id]);
}

void SourceSet::disconnect_all(std::chrono::milliseconds wait) {
  for (const auto& session : sessions_) session->disconnect();
  for (const auto& session : sessions_)
    session->wait_until(
        [](const SessionSnapshot& s) { return s.state == LinkState::Idle || s.state == LinkState::Failed; }, wait);
}

SetStart SourceSet::start_state() {
  SetStart start;
  start.settled = true;
  for (std::size_t id = 0; id < size(); ++id) {
    const SessionSnapshot s = sessions_[id]->snapshot();
    if (laps_flow(s.state)) ever_scanned_[id] = true;
    const bool trouble = in_trouble(s.state);
    if (trouble && !ever_scanned_[id] && start.failure.empty())
      start.failure = s.message.empty() ? std::string(link_state_name(s.state)) : s.message;
    start.any_scanned = start.any_scanned || ever_scanned_[id];
    start.settled = start.settled && (ever_scanned_[id] || trouble);
  }
  return start;
}

}  // namespace ydscope
