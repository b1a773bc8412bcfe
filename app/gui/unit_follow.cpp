#include "app/gui/unit_follow.h"

#include <algorithm>

#include "app/gui/source_list.h"
#include "core/frame/unit_identity.h"

namespace ydscope::gui {
namespace {

// It has said its serial, or will not for now (failed, waiting to reconnect, a replay).
bool settled(const SessionSnapshot& s) {
  return s.device || (s.state != LinkState::Connecting && s.state != LinkState::Probing);
}

}  // namespace

std::vector<std::string> UnitFollow::follow(SourceList& sources) {
  if (!sources.several()) return {};
  std::vector<std::string> serials;
  std::vector<UnitSeen> seen;
  std::vector<SourceInfo> given;
  for (const auto& slot : sources.slots()) {
    const SessionSnapshot& s = slot->model.snap;
    if (!settled(s)) return {};
    serials.push_back(s.device ? s.device->serial : std::string());
    seen.push_back({slot->source.description(), serials.back()});  // the port as given, without its baud
    given.push_back({slot->look.name, slot->look.pose, std::nullopt, "", slot->look.serial});
  }
  if (serials == last_serials_) return {};
  last_serials_ = serials;
  const UnitIdentity identity = identify_units(given, seen);
  std::vector<ui::SourceLook> looks;
  for (const auto& slot : sources.slots()) looks.push_back(slot->look);
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const auto from = std::find_if(looks.begin(), looks.end(),
                                   [&](const ui::SourceLook& l) { return l.name == identity.sources[i].name; });
    ui::SourceLook look = from == looks.end() ? looks[i] : *from;  // the whole look goes with the unit ...
    look.origin = looks[i].origin;                                 // ... but how to start it is the port's
    // Remembered at exit, so the next run binds it; a serial two units share binds nothing.
    if (!serials[i].empty() && std::count(serials.begin(), serials.end(), serials[i]) == 1) look.serial = serials[i];
    sources[i].look = std::move(look);
  }
  return identity.notes;
}

}  // namespace ydscope::gui
