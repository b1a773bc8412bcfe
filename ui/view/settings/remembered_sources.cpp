#include "ui/view/settings/remembered_sources.h"

#include <algorithm>

namespace ydscope::ui {

namespace {
constexpr std::size_t kRememberedLooks = 32;
}  // namespace

void recall_look(const ViewSettings& settings, const std::vector<SourceLook>& others, SourceLook& look,
                 bool pose_given) {
  for (const SourceLook& remembered : settings.sources) {
    if (remembered.name != look.name) continue;
    if (!pose_given) look.pose = remembered.pose;
    const bool colour_taken = std::any_of(others.begin(), others.end(), [&](const SourceLook& other) {
      return other.name != look.name && other.colour == remembered.colour;
    });
    if (!colour_taken) look.colour = remembered.colour;
    if (look.serial.empty()) look.serial = remembered.serial;
  }
}

void remember_looks(ViewSettings& settings, const std::vector<SourceLook>& looks) {
  settings.last_sources.clear();
  if (looks.size() < 2) return;
  for (const SourceLook& look : looks) settings.last_sources.push_back(look.name);
  for (SourceLook look : looks) {
    look.hidden = look.paused = false;  // a new run shows everything live
    std::erase_if(settings.sources, [&](const SourceLook& l) { return l.name == look.name; });
    const std::string name = look.name, serial = look.serial;
    settings.sources.push_back(std::move(look));
    if (!serial.empty()) bind_serial(settings.sources, name, serial);
    if (settings.sources.size() > kRememberedLooks) settings.sources.erase(settings.sources.begin());
  }
}

void bind_serial(std::vector<SourceLook>& remembered, const std::string& name, const std::string& serial) {
  for (SourceLook& look : remembered) {
    if (look.name == name)
      look.serial = serial;
    else if (look.serial == serial)
      look.serial.clear();
  }
}

}  // namespace ydscope::ui
