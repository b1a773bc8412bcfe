#pragma once
// UnitFollow: identity by serial in the window. Once every lidar shown has answered A5 90 (or
// given up), each name, pose and colour follows its unit's serial to the port it came up on
// (core/frame/unit_identity.h): from --serial, or settings.ini's `unit = SERIAL; NAME` lines,
// which the app writes at exit for every lidar of several whose serial it read. A unit moved or
// two swapped are said in one sentence; lidars with no serial bound stay bound by their port.
#include <string>
#include <vector>

namespace ydscope::gui {

class SourceList;

class UnitFollow {
 public:
  // Call once a frame after every slot's model is refreshed. Does its work when every source has
  // settled and the serials read differ from the last time; returns what to say (often nothing).
  std::vector<std::string> follow(SourceList& sources);

 private:
  std::vector<std::string> last_serials_;
};

}  // namespace ydscope::gui
