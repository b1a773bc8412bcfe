#include "ui/view/settings/settings.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <type_traits>

#include "core/frame/pose_convention.h"
#include "core/analysis/zone.h"
#include "ui/view/history/sector_watch.h"

namespace ydscope::ui {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::optional<double> to_number(const std::string& v) {
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0' || !std::isfinite(d)) return std::nullopt;
  return d;
}

std::string shortest(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// A numeric setting outside [min, max] (or not a number, or not whole where a count is meant)
// keeps its default and leaves a note: casting an absurd value such as 3e38 to int is undefined.
template <typename T>
void take_number(const std::string& key, const std::string& value, double min, double max, T& field,
                 std::vector<std::string>* notes) {
  const auto number = to_number(value);
  const bool whole = !std::is_integral_v<T> || (number && std::floor(*number) == *number);
  if (number && whole && *number >= min && *number <= max) {
    field = static_cast<T>(*number);
    return;
  }
  if (!notes) return;
  const char* kind = std::is_integral_v<T> ? "a whole number" : "a number";
  notes->push_back(key + " = " + value + " is not " + kind + " from " + shortest(min) + " to " + shortest(max) +
                   "; using the default, " + shortest(static_cast<double>(field)));
}

std::optional<bool> to_bool(const std::string& v) {
  if (v == "true" || v == "1") return true;
  if (v == "false" || v == "0") return false;
  return std::nullopt;
}

// Each `unit = SERIAL; NAME` line binds the remembered source of that name to the unit's serial.
void bind_units(const std::vector<std::string>& units, std::vector<SourceLook>& sources,
                std::vector<std::string>* notes) {
  for (const std::string& value : units) {
    const auto semicolon = value.find(';');
    const std::string serial = trim(value.substr(0, semicolon));
    const std::string name = semicolon == std::string::npos ? std::string() : trim(value.substr(semicolon + 1));
    auto look = std::find_if(sources.begin(), sources.end(), [&](const SourceLook& l) { return l.name == name; });
    if (serial.empty() || serial.find(' ') != std::string::npos || look == sources.end()) {
      if (notes)
        notes->push_back("unit = " + value + " is left out: " +
                         (look == sources.end() ? "no source = line has the name '" + name + "'"
                                                : std::string("expected SERIAL; NAME")));
      continue;
    }
    look->serial = serial;
  }
}

}  // namespace

std::filesystem::path config_directory() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "ydscope";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".config" / "ydscope";
  return {};
}

ViewSettings parse_settings(const std::string& text, std::vector<std::string>* notes) {
  ViewSettings s;
  bool poses_in_rep103 = false;
  std::vector<std::string> units;  // `unit = SERIAL; NAME`, bound once every source line is read
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find('=');
    if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
    const std::string key = trim(line.substr(0, eq));
    const std::string value = trim(line.substr(eq + 1));
    const auto b = to_bool(value);
    if (key == "colour_mode") {
      if (value == "range")
        s.colours.mode = ColourMode::Range;
      else if (value == "flag")
        s.colours.mode = ColourMode::Flag;
      else if (value == "age")
        s.colours.mode = ColourMode::LapAge;
      else if (value == "motion")
        s.colours.mode = ColourMode::Motion;
      else if (value == "source")
        s.colours.mode = ColourMode::Source;
    } else if (key == "palette") {
      if (value == "turbo")
        s.colours.palette = Palette::Turbo;
      else if (value == "viridis")
        s.colours.palette = Palette::Viridis;
    } else if (key == "near_mm") {
      take_number(key, value, 0.0, kMaxColourRangeMm, s.colours.near_mm, notes);
    } else if (key == "far_mm") {
      take_number(key, value, 1.0, kMaxColourRangeMm, s.colours.far_mm, notes);
    } else if (key == "fade_old_laps" && b) {
      s.colours.fade_old_laps = *b;
    } else if (key == "auto_range" && b) {
      s.auto_range = *b;
    } else if (key == "point_size_px") {
      take_number(key, value, kMinPointSizePx, kMaxPointSizePx, s.point_size_px, notes);
    } else if (key == "persistence_laps") {
      take_number(key, value, 1, kMaxPersistenceLaps, s.persistence_laps, notes);
    } else if (key == "drop_specular" && b) {
      s.interference.drop_specular = *b;
    } else if (key == "drop_ambient" && b) {
      s.interference.drop_ambient = *b;
    } else if (key == "show_ghosts" && b) {
      s.interference.show_ghosts = *b;
    } else if (key == "show_panels" && b) {
      s.show_panels = *b;
    } else if (key == "show_grid" && b) {
      s.show_grid = *b;
    } else if (key == "smooth" && b) {
      s.smooth = *b;
    } else if (key == "split_view" && b) {
      s.split_view = *b;
    } else if (key == "zone_beep" && b) {
      s.zone_beep = *b;
    } else if (key == "zone") {
      std::string error;
      if (parse_zone(value, error))
        s.zones.push_back(value);
      else if (notes)
        notes->push_back("zone = " + value + " is left out: " + error);
    } else if (key == "booth_title") {
      s.booth_title = value;
    } else if (key == "booth_figure") {
      if (const auto kind = booth_figure_from_word(value))
        s.booth_figure = *kind;
      else if (notes)
        notes->push_back("booth_figure = " + value + " is left out: it takes none, visitors or nearest");
    } else if (key == "sidebar_tab") {
      if (const auto tab = sidebar_tab_from_word(value))
        s.sidebar_tab = *tab;
      else if (notes)
        notes->push_back("sidebar_tab = " + value + " is left out: it takes lidar, view, statistics or sources");
    } else if (key == "last_replay_file") {
      s.last_replay_file = value;
    } else if (key == "last_sources") {
      s.last_sources.clear();
      std::size_t at = 0;
      while (at <= value.size()) {
        const std::size_t comma = std::min(value.find(',', at), value.size());
        // Trimmed as a whole line's value is: written back as "a, b", the list then reads the same.
        std::string name = trim(value.substr(at, comma - at));
        if (!name.empty()) s.last_sources.push_back(std::move(name));
        at = comma + 1;
      }
    } else if (key == kPoseConventionKey) {
      poses_in_rep103 = value == kPoseConvention;
    } else if (key == "unit") {
      units.push_back(value);
    } else if (key == "source") {
      std::string error;
      if (auto look = parse_source_line(value, error))
        s.sources.push_back(std::move(*look));
      else if (notes)
        notes->push_back("source = " + value + " is left out: " + error);
    } else if (key == "sector") {
      std::string error;
      if (s.sectors.size() >= kMaxWatchedSectors) {
        if (notes)
          notes->push_back("sector = " + value + " is left out: at most " + std::to_string(kMaxWatchedSectors) +
                           " sectors");
      } else if (parse_sector_spec(value, error)) {
        s.sectors.push_back(value);
      } else if (notes) {
        notes->push_back("sector = " + value + " is left out: " + error);
      }
    }
  }
  bind_units(units, s.sources, notes);
  if (!poses_in_rep103 && !s.sources.empty()) {
    for (SourceLook& look : s.sources) look.pose = pose_from_pre_rep103(look.pose);
    if (notes) notes->push_back(std::string(kPreRep103Note));
  }
  return s;
}

std::string format_settings(const ViewSettings& s) {
  std::ostringstream out;
  const char* mode = s.colours.mode == ColourMode::Range    ? "range"
                     : s.colours.mode == ColourMode::Flag   ? "flag"
                     : s.colours.mode == ColourMode::Motion ? "motion"
                     : s.colours.mode == ColourMode::Source ? "source"
                                                            : "age";
  auto yes = [](bool v) { return v ? "true" : "false"; };
  out << "# ydscope view settings; written on exit\n"
      << "colour_mode = " << mode << "\n"
      << "palette = " << palette_name(s.colours.palette) << "\n"
      << "near_mm = " << s.colours.near_mm << "\n"
      << "far_mm = " << s.colours.far_mm << "\n"
      << "fade_old_laps = " << yes(s.colours.fade_old_laps) << "\n"
      << "auto_range = " << yes(s.auto_range) << "\n"
      << "point_size_px = " << s.point_size_px << "\n"
      << "persistence_laps = " << s.persistence_laps << "\n"
      << "drop_specular = " << yes(s.interference.drop_specular) << "\n"
      << "drop_ambient = " << yes(s.interference.drop_ambient) << "\n"
      << "show_ghosts = " << yes(s.interference.show_ghosts) << "\n"
      << "show_panels = " << yes(s.show_panels) << "\n"
      << "show_grid = " << yes(s.show_grid) << "\n"
      << "smooth = " << yes(s.smooth) << "\n"
      << "split_view = " << yes(s.split_view) << "\n"
      << "zone_beep = " << yes(s.zone_beep) << "\n"
      << "booth_title = " << s.booth_title << "\n"
      << "booth_figure = " << booth_figure_word(s.booth_figure) << "\n"
      << "sidebar_tab = " << sidebar_tab_word(s.sidebar_tab) << "\n"
      << "last_replay_file = " << s.last_replay_file << "\n"
      << kPoseConventionKey << " = " << kPoseConvention << "\n";
  for (const std::string& sector : s.sectors) out << "sector = " << sector << "\n";
  for (const std::string& zone : s.zones) out << "zone = " << zone << "\n";
  for (const SourceLook& source : s.sources) out << "source = " << format_source_line(source) << "\n";
  for (const SourceLook& source : s.sources)
    if (!source.serial.empty()) out << "unit = " << source.serial << "; " << source.name << "\n";
  if (!s.last_sources.empty()) {
    out << "last_sources = ";
    for (std::size_t i = 0; i < s.last_sources.size(); ++i) out << (i ? ", " : "") << s.last_sources[i];
    out << "\n";
  }
  return out.str();
}

ViewSettings load_settings(const std::filesystem::path& file, std::vector<std::string>* notes) {
  std::ifstream in(file);
  if (!in) return {};
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_settings(buffer.str(), notes);
}

bool save_settings(const std::filesystem::path& file, const ViewSettings& settings) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  std::ofstream out(file);
  if (!out) return false;
  out << format_settings(settings);
  return static_cast<bool>(out);
}

}  // namespace ydscope::ui
