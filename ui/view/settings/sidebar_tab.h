#pragma once
// The sidebar's tabs, and settings.ini's word for each: the app opens on the tab it was left on.
#include <optional>
#include <string_view>

namespace ydscope::ui {

enum class SidebarTab { Lidar, View, Statistics, Sources };

// "lidar", "view", "statistics", "sources", and back; nullopt for another word.
std::string_view sidebar_tab_word(SidebarTab tab);
std::optional<SidebarTab> sidebar_tab_from_word(std::string_view word);

}  // namespace ydscope::ui
