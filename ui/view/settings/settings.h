#pragma once
// What the app remembers between runs besides ImGui's window layout (imgui.ini): view and filter
// choices, as `key = value` lines in $XDG_CONFIG_HOME/ydscope/settings.ini (or ~/.config/ydscope).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ui/view/scene/booth_figure.h"
#include "ui/view/scene/colour_map.h"
#include "ui/view/scene/point_cloud.h"
#include "ui/view/scene/source_set.h"
#include "ui/view/settings/sidebar_tab.h"

namespace ydscope::ui {

// The ranges a hand-edited settings.ini is held to (the panels' sliders stay inside them).
inline constexpr double kMaxColourRangeMm = 100'000.0;  // beyond any supported lidar's reach
inline constexpr double kMinPointSizePx = 1.0;
inline constexpr double kMaxPointSizePx = 20.0;
inline constexpr double kMaxPersistenceLaps = 60.0;

struct ViewSettings {
  ColourParams colours;
  bool auto_range = true;
  float point_size_px = 3.0f;
  int persistence_laps = 10;
  InterferenceSettings interference;
  bool show_panels = true;
  bool show_grid = true;
  // Draw at the display's rate so persistence fades between laps; off, the view redraws once a
  // lap (cheaper with software rendering).
  bool smooth = true;
  // Several sources: two to four side by side, each around itself, instead of one common view.
  bool split_view = false;
  std::string last_replay_file;
  std::vector<std::string> sectors;  // SectorWatch::spec() of each watched sector
  std::vector<std::string> zones;    // zone_spec() of each zone (core/analysis/zone.h)
  bool zone_beep = false;            // ring the bell when a zone's rule is raised
  // The booth view's own line for visitors (empty: none) and its large live figure.
  std::string booth_title;
  BoothFigureKind booth_figure = BoothFigureKind::None;
  SidebarTab sidebar_tab = SidebarTab::Lidar;  // the tab the sidebar was left on
  // Sources by name: a source of a remembered name gets its pose and colour back.
  std::vector<SourceLook> sources;
  // The last run's lidars, by name, when it had several: a run with no source named starts them
  // again (their `origin`). Empty after a run of one.
  std::vector<std::string> last_sources;

  friend bool operator==(const ViewSettings&, const ViewSettings&) = default;
};

// Folder for settings.ini and imgui.ini; empty when neither XDG_CONFIG_HOME nor HOME is set.
std::filesystem::path config_directory();

// Unknown keys and bad values are ignored, so an older or hand-edited file never stops the app.
// A numeric value that is not a number or out of its range keeps the default, and one sentence
// per such line goes to `notes` (when given) for the app to show.
ViewSettings parse_settings(const std::string& text, std::vector<std::string>* notes = nullptr);
std::string format_settings(const ViewSettings& settings);

ViewSettings load_settings(const std::filesystem::path& file, std::vector<std::string>* notes = nullptr);
// False when the file cannot be written (the app then just does not remember).
bool save_settings(const std::filesystem::path& file, const ViewSettings& settings);

}  // namespace ydscope::ui
