#pragma once
// Poses kept by lidar name where the app keeps them: settings.ini's `source = NAME; X,Y,YAW; ...`
// lines (ui/view/settings), which the app reads when a lidar of that name starts and which
// `ydscope-cli align --apply` writes, and the `unit = SERIAL; NAME` lines that bind a name to a
// unit's serial. One place, so the CLI and the app never disagree.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/frame/pose.h"

namespace ydscope::cli {

struct NamedPose {
  std::string name;
  Pose pose;
  std::string serial = {};  // the unit's serial, read while aligning; empty: bound by name only
};

// settings.ini in the app's config folder; empty when there is none (no HOME, no XDG_CONFIG_HOME).
std::filesystem::path remembered_poses_file();

// The pose remembered for `name`, if any.
std::optional<Pose> remembered_pose(const std::filesystem::path& file, const std::string& name);

// The serial remembered for `name`'s unit; empty when none.
std::string remembered_serial(const std::filesystem::path& file, const std::string& name);

// Each name's pose replaced (or added, in a colour no other remembered lidar has); the rest of
// the file as it was. A name given a serial is bound to that unit, and no other name is. False, with one sentence in `error`, when the file cannot be written.
bool remember_poses(const std::filesystem::path& file, const std::vector<NamedPose>& poses, std::string& error);

}  // namespace ydscope::cli
