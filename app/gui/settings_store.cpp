#include "app/gui/settings_store.h"

#include <cstdio>
#include <filesystem>
#include <system_error>
#include <vector>

#include <imgui.h>

namespace ydscope::gui {

SettingsStore::SettingsStore(bool persist) {
  const auto dir = ui::config_directory();
  if (!persist || dir.empty()) {
    ImGui::GetIO().IniFilename = nullptr;  // screenshot runs must not depend on a user's layout
    return;
  }
  settings_path_ = (dir / "settings.ini").string();
  imgui_ini_path_ = (dir / "imgui.ini").string();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  ImGui::GetIO().IniFilename = imgui_ini_path_.c_str();
}

SettingsStore::~SettingsStore() {
  if (!imgui_ini_path_.empty()) ImGui::SaveIniSettingsToDisk(imgui_ini_path_.c_str());
  ImGui::GetIO().IniFilename = nullptr;
}

ui::ViewSettings SettingsStore::load() const {
  if (settings_path_.empty()) return {};
  std::vector<std::string> notes;
  ui::ViewSettings settings = ui::load_settings(settings_path_, &notes);
  for (const auto& note : notes) std::fprintf(stderr, "ydscope: %s: %s\n", settings_path_.c_str(), note.c_str());
  return settings;
}

void SettingsStore::save(const ui::ViewSettings& settings) const {
  if (!settings_path_.empty()) ui::save_settings(settings_path_, settings);
}

}  // namespace ydscope::gui
