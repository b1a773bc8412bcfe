#pragma once
// Where the app keeps what it remembers between runs: settings.ini (ui/view/settings/settings.h) and
// ImGui's imgui.ini (the panels' layout), both in the user's config directory; or nowhere, for
// runs that must not depend on a user's layout or change it (screenshots, tests).
#include <string>

#include "ui/view/settings/settings.h"

namespace ydscope::gui {

class SettingsStore {
 public:
  // Tells ImGui where its file is (or that there is none); ImGui must be set up.
  explicit SettingsStore(bool persist);
  ~SettingsStore();  // ImGui saves its layout and forgets the path it only pointed to
  SettingsStore(const SettingsStore&) = delete;
  SettingsStore& operator=(const SettingsStore&) = delete;

  // The remembered settings, or the defaults; what could not be read goes to stderr, a line each.
  ui::ViewSettings load() const;
  void save(const ui::ViewSettings& settings) const;

 private:
  std::string settings_path_;  // empty: nothing is remembered
  std::string imgui_ini_path_;
};

}  // namespace ydscope::gui
