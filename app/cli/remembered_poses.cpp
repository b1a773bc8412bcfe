#include "app/cli/remembered_poses.h"

#include <algorithm>

#include "ui/view/scene/source_set.h"
#include "ui/view/settings/remembered_sources.h"
#include "ui/view/settings/settings.h"

namespace ydscope::cli {

std::filesystem::path remembered_poses_file() {
  const std::filesystem::path dir = ui::config_directory();
  return dir.empty() ? dir : dir / "settings.ini";
}

std::optional<Pose> remembered_pose(const std::filesystem::path& file, const std::string& name) {
  if (file.empty()) return std::nullopt;
  const ui::ViewSettings settings = ui::load_settings(file);
  for (const ui::SourceLook& look : settings.sources)
    if (look.name == name) return look.pose;
  return std::nullopt;
}

std::string remembered_serial(const std::filesystem::path& file, const std::string& name) {
  if (file.empty()) return {};
  for (const ui::SourceLook& look : ui::load_settings(file).sources)
    if (look.name == name) return look.serial;
  return {};
}

bool remember_poses(const std::filesystem::path& file, const std::vector<NamedPose>& poses, std::string& error) {
  if (file.empty()) {
    error = "there is no config folder to keep poses in (set HOME or XDG_CONFIG_HOME)";
    return false;
  }
  ui::ViewSettings settings = ui::load_settings(file);
  for (const NamedPose& named : poses) {
    auto it = std::find_if(settings.sources.begin(), settings.sources.end(),
                           [&](const ui::SourceLook& look) { return look.name == named.name; });
    if (it == settings.sources.end()) {
      std::vector<ui::Rgba8> taken;
      for (const ui::SourceLook& look : settings.sources) taken.push_back(look.colour);
      ui::SourceLook look;
      look.name = named.name;
      look.colour = ui::unused_source_colour(taken);
      settings.sources.push_back(look);
      it = settings.sources.end() - 1;
    }
    it->pose = named.pose;
    if (!named.serial.empty()) ui::bind_serial(settings.sources, named.name, named.serial);
  }
  if (!ui::save_settings(file, settings)) {
    error = "could not write " + file.string() + "; check that its folder is writable";
    return false;
  }
  return true;
}

}  // namespace ydscope::cli
