#include "app/cli/units_by_serial.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "app/cli/remembered_poses.h"
#include "core/frame/unit_identity.h"
#include "core/session/session.h"

namespace ydscope::cli {
namespace {

// A unit that answers at all answers A5 90 within a second or two (a baud probe takes longer).
constexpr std::chrono::seconds kSerialPatience{8};

}  // namespace

void recall_serials(std::vector<SourceInfo>& infos) {
  if (!named_apart(infos)) return;
  const std::filesystem::path file = remembered_poses_file();
  for (SourceInfo& info : infos)
    if (info.serial.empty()) info.serial = remembered_serial(file, info.name);
}

std::vector<std::string> ask_serials(const std::vector<SessionConfig>& configs) {
  std::vector<std::unique_ptr<Session>> sessions;
  for (SessionConfig config : configs) {
    config.scan = false;  // A5 90 is all it needs; the set starts the scan afterwards
    config.reconnect = false;
    sessions.push_back(std::make_unique<Session>(1));
    sessions.back()->connect(std::move(config));
  }
  std::vector<std::string> serials;
  for (const auto& session : sessions) {
    const SessionSnapshot s = session->wait_until(
        [](const SessionSnapshot& x) {
          return x.device || x.state == LinkState::Failed || x.state == LinkState::Ready;
        },
        kSerialPatience);
    serials.push_back(s.device ? s.device->serial : std::string());
  }
  for (const auto& session : sessions) session->disconnect();
  for (const auto& session : sessions)
    session->wait_until(
        [](const SessionSnapshot& x) { return x.state == LinkState::Idle || x.state == LinkState::Failed; },
        std::chrono::seconds(3));
  return serials;
}

void bind_units_by_serial(std::vector<SourceSpec>& specs) {
  std::vector<SourceInfo> given;
  for (const SourceSpec& spec : specs) given.push_back(spec.info);
  recall_serials(given);
  const bool any_bound = std::any_of(given.begin(), given.end(), [](const SourceInfo& i) { return !i.serial.empty(); });
  if (!named_apart(given) || !any_bound) return;
  std::vector<SessionConfig> configs;
  for (const SourceSpec& spec : specs) configs.push_back(spec.config);
  const std::vector<std::string> serials = ask_serials(configs);
  std::vector<UnitSeen> seen;
  for (std::size_t id = 0; id < specs.size(); ++id) seen.push_back({specs[id].config.address, serials[id]});
  const UnitIdentity identity = identify_units(given, seen);
  for (std::size_t id = 0; id < specs.size(); ++id) specs[id].info = identity.sources[id];
  for (const std::string& note : identity.notes) std::fprintf(stderr, "ydscope-cli: %s\n", note.c_str());
}

}  // namespace ydscope::cli
